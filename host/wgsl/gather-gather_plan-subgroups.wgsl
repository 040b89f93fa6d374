struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_6 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: type_5,
}

struct type_7 {
    member: type_6,
}

struct type_10 {
    member: array<u32>,
}

struct type_20 {
    member: u32,
    member_1: u32,
}

struct type_26 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_10;
var<workgroup> global_5: array<u32, 512>;
@group(0) @binding(1) 
var<storage, read_write> global_6: type_26;
var<private> global_7: u32;
var<private> global_8: u32;
var<private> global_9: u32;
var<private> global_10: u32;
var<private> global_11: u32 = 2143289344u;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: u32;
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: bool;
    var local_12: f32;
    var local_13: u32;
    var local_14: bool;
    var local_15: f32;
    var local_16: f32;
    var local_17: f32;
    var local_18: f32;
    var local_19: bool;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: bool;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: bool;
    var local_33: u32;
    var local_34: u32;
    var local_35: bool;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: bool;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: bool;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: bool;
    var local_53: u32;
    var local_54: u32;
    var local_55: bool;
    var local_56: u32;
    var local_57: u32;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: u32;
    var local_62: u32;
    var local_63: u32;
    var local_64: f32;
    var local_65: u32;
    var local_66: u32;
    var phi_121_: u32;
    var phi_124_: u32;
    var phi_146_: bool;
    var phi_181_: bool;
    var phi_209_: f32;
    var phi_210_: f32;
    var phi_216_: f32;
    var phi_218_: f32;
    var phi_590_: bool;
    var phi_253_: u32;
    var phi_122_: u32;
    var phi_125_: u32;
    var phi_597_: bool;
    var phi_277_: type_20;
    var phi_279_: type_20;
    var phi_280_: bool;
    var phi_281_: type_20;
    var phi_282_: bool;
    var phi_287_: type_20;
    var phi_487_: u32;
    var phi_490_: u32;
    var phi_530_: u32;
    var phi_488_: u32;
    var phi_491_: u32;
    var phi_612_: bool;
    var phi_314_: u32;
    var phi_317_: u32;
    var phi_335_: u32;
    var phi_315_: u32;
    var phi_318_: u32;
    var phi_347_: u32;
    var phi_350_: u32;
    var phi_351_: u32;
    var phi_353_: u32;
    var phi_381_: u32;
    var phi_387_: u32;
    var phi_390_: u32;
    var phi_408_: u32;
    var phi_388_: u32;
    var phi_391_: u32;
    var phi_348_: u32;
    var phi_352_: u32;
    var phi_354_: u32;
    var phi_623_: bool;
    var phi_426_: u32;
    var phi_429_: u32;
    var phi_431_: u32;
    var phi_446_: u32;
    var phi_427_: u32;
    var phi_430_: u32;
    var phi_432_: u32;
    var phi_636_: bool;
    var phi_545_: u32;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;

    let _e105 = global_11;
    switch bitcast<i32>(0u) {
        default: {
            let _e108 = global;
            local = _e108;
            let _e109 = global_1;
            let _e110 = global_2;
            let _e111 = global_7;
            local_1 = _e111;
            let _e112 = global_8;
            local_2 = _e112;
            let _e113 = global_9;
            local_3 = _e113;
            let _e114 = global_10;
            local_4 = _e114;
            local_5 = arrayLength((&global_4.member));
            local_6 = arrayLength((&global_6.member));
            local_7 = (_e110.x * 256u);
            let _e125 = global_3.member.member;
            let _e128 = global_3.member.member_1;
            local_8 = (_e125 * _e128);
            phi_121_ = ((_e109.x * 256u) + _e108);
            phi_124_ = 0u;
            loop {
                let _e132 = phi_121_;
                let _e134 = phi_124_;
                local_9 = _e132;
                local_10 = _e134;
                let _e135 = local_9;
                let _e136 = local_8;
                let _e137 = (_e135 < _e136);
                local_11 = _e137;
                if _e137 {
                    let _e138 = local_9;
                    let _e139 = local_5;
                    if (_e138 < _e139) {
                    } else {
                        phi_597_ = true;
                        break;
                    }
                    let _e141 = local_9;
                    let _e144 = global_4.member[_e141];
                    let _e145 = bitcast<f32>(_e144);
                    local_12 = _e145;
                    let _e146 = bitcast<u32>(_e145);
                    local_13 = _e146;
                    let _e147 = (_e146 == 0u);
                    local_14 = _e147;
                    if _e147 {
                        phi_146_ = false;
                    } else {
                        let _e148 = local_13;
                        phi_146_ = (_e148 <= 2139095040u);
                    }
                    let _e151 = phi_146_;
                    if _e151 {
                        let _e154 = global_3.member.member_2;
                        local_15 = f32(_e154);
                        let _e156 = local_13;
                        if (_e156 == 2139095040u) {
                            let _e204 = global_3.member.member_4.member_1;
                            let _e209 = global_3.member.member_4.member;
                            let _e214 = global_3.member.member_4.member_2;
                            let _e220 = global_3.member.member_4.member_3;
                            phi_218_ = (0.5f * ((((2f * _e204) * _e209) / (_e214 - _e209)) * _e220));
                        } else {
                            let _e158 = local_14;
                            if _e158 {
                                phi_181_ = false;
                            } else {
                                let _e159 = local_13;
                                phi_181_ = (_e159 <= 2139095040u);
                            }
                            let _e162 = phi_181_;
                            if _e162 {
                                let _e166 = global_3.member.member_4.member_1;
                                let _e171 = global_3.member.member_4.member;
                                let _e176 = global_3.member.member_4.member_2;
                                local_16 = _e176;
                                let _e182 = global_3.member.member_4.member_3;
                                let _e183 = ((((2f * _e166) * _e171) / (_e176 - _e171)) * _e182);
                                local_17 = _e183;
                                if (_e183 == 0f) {
                                    phi_209_ = 0f;
                                } else {
                                    let _e185 = local_16;
                                    let _e186 = local_12;
                                    let _e189 = local_17;
                                    phi_209_ = (_e189 * (1f - (_e185 / _e186)));
                                }
                                let _e192 = phi_209_;
                                phi_210_ = _e192;
                            } else {
                                phi_210_ = bitcast<f32>(_e105);
                            }
                            let _e194 = phi_210_;
                            local_18 = _e194;
                            if (_e194 < 0f) {
                                let _e196 = local_18;
                                phi_216_ = -(_e196);
                            } else {
                                phi_216_ = _e194;
                            }
                            let _e199 = phi_216_;
                            phi_218_ = (0.5f * _e199);
                        }
                        let _e224 = phi_218_;
                        let _e228 = select(_e224, 0f, ((bitcast<u32>(_e224) & 2147483647u) > 2139095040u));
                        local_64 = _e228;
                        if !((_e228 == _e228)) {
                            phi_590_ = true;
                        } else {
                            let _e231 = local_15;
                            let _e232 = local_64;
                            phi_590_ = (_e231 <= _e232);
                        }
                        let _e235 = phi_590_;
                        let _e236 = local_15;
                        let _e237 = local_64;
                        let _e238 = select(_e237, _e236, _e235);
                        let _e244 = select(select(u32(_e238), 0u, !((_e238 >= 0f))), 4294967295u, (_e238 > 4294967000f));
                        let _e248 = (_e244 + select(1u, 0u, (f32(_e244) == _e238)));
                        let _e249 = local_10;
                        let _e251 = local_10;
                        phi_253_ = select(_e251, _e248, (_e248 > _e249));
                    } else {
                        phi_253_ = _e134;
                    }
                    let _e254 = phi_253_;
                    let _e255 = local_9;
                    let _e256 = local_7;
                    phi_122_ = (_e255 + _e256);
                    phi_125_ = _e254;
                } else {
                    phi_122_ = u32();
                    phi_125_ = u32();
                }
                let _e259 = phi_122_;
                let _e261 = phi_125_;
                continue;
                continuing {
                    let _e262 = local_11;
                    phi_121_ = _e259;
                    phi_124_ = _e261;
                    phi_597_ = false;
                    break if !(_e262);
                }
            }
            let _e265 = phi_597_;
            if _e265 {
                break;
            }
            let _e266 = local;
            if (_e266 < 512u) {
            } else {
                break;
            }
            let _e268 = local;
            let _e270 = local_10;
            global_5[_e268] = _e270;
            storageBarrier();
            workgroupBarrier();
            let _e271 = local_1;
            if (_e271 >= 2u) {
                let _e273 = local_1;
                let _e275 = local_1;
                if ((_e275 & (_e273 - 1u)) == 0u) {
                    let _e278 = local_2;
                    let _e279 = local_1;
                    let _e281 = ((_e278 * _e279) == 256u);
                    local_19 = _e281;
                    if _e281 {
                        let _e282 = local_1;
                        phi_277_ = type_20(1u, _e282);
                    } else {
                        phi_277_ = type_20();
                    }
                    let _e285 = phi_277_;
                    let _e286 = local_19;
                    phi_279_ = _e285;
                    phi_280_ = select(true, false, _e286);
                } else {
                    phi_279_ = type_20();
                    phi_280_ = true;
                }
                let _e289 = phi_279_;
                let _e291 = phi_280_;
                phi_281_ = _e289;
                phi_282_ = _e291;
            } else {
                phi_281_ = type_20();
                phi_282_ = true;
            }
            let _e293 = phi_281_;
            let _e295 = phi_282_;
            if _e295 {
                phi_287_ = type_20(0u, type_20().member_1);
            } else {
                phi_287_ = _e293;
            }
            let _e300 = phi_287_;
            local_20 = _e300.member_1;
            if (bitcast<i32>(_e300.member) != 0i) {
                let _e356 = local_20;
                let _e358 = local_20;
                local_21 = select(firstTrailingBit(_e356), 32u, (_e358 == 0u));
                let _e361 = local_3;
                let _e362 = local_1;
                let _e364 = local_4;
                let _e365 = ((_e361 * _e362) + _e364);
                local_22 = _e365;
                if (_e365 < 512u) {
                } else {
                    break;
                }
                let _e367 = local_22;
                let _e369 = global_5[_e367];
                phi_314_ = 1u;
                phi_317_ = _e369;
                loop {
                    let _e371 = phi_314_;
                    let _e373 = phi_317_;
                    local_23 = _e371;
                    local_24 = _e373;
                    let _e374 = local_23;
                    let _e375 = local_1;
                    let _e376 = (_e374 < _e375);
                    local_25 = _e376;
                    if _e376 {
                        let _e377 = local_24;
                        let _e378 = local_23;
                        let _e379 = subgroupShuffleUp(_e377, _e378);
                        local_26 = _e379;
                        let _e380 = local_4;
                        let _e381 = local_23;
                        if (_e380 >= _e381) {
                            let _e383 = local_26;
                            let _e384 = local_24;
                            let _e386 = local_26;
                            let _e387 = local_24;
                            phi_335_ = select(_e387, _e386, (_e383 > _e384));
                        } else {
                            phi_335_ = _e373;
                        }
                        let _e390 = phi_335_;
                        let _e391 = local_23;
                        phi_315_ = (_e391 * 2u);
                        phi_318_ = _e390;
                    } else {
                        phi_315_ = u32();
                        phi_318_ = u32();
                    }
                    let _e394 = phi_315_;
                    let _e396 = phi_318_;
                    continue;
                    continuing {
                        let _e397 = local_25;
                        phi_314_ = _e394;
                        phi_317_ = _e396;
                        break if !(_e397);
                    }
                }
                let _e399 = local_22;
                let _e400 = (256u + _e399);
                local_27 = _e400;
                if (_e400 < 512u) {
                } else {
                    break;
                }
                let _e402 = local_27;
                let _e404 = local_24;
                global_5[_e402] = _e404;
                storageBarrier();
                workgroupBarrier();
                phi_347_ = 0u;
                phi_350_ = 256u;
                phi_351_ = 256u;
                phi_353_ = 0u;
                loop {
                    let _e406 = phi_347_;
                    let _e408 = phi_350_;
                    let _e410 = phi_351_;
                    let _e412 = phi_353_;
                    local_28 = _e406;
                    local_29 = _e408;
                    local_30 = _e410;
                    local_31 = _e412;
                    local_67 = _e408;
                    local_68 = _e410;
                    local_69 = _e412;
                    let _e413 = local_30;
                    let _e414 = local_20;
                    let _e415 = (_e413 > _e414);
                    local_32 = _e415;
                    if _e415 {
                        let _e416 = local_21;
                        let _e417 = (_e416 & 31u);
                        local_33 = _e417;
                        let _e418 = local_30;
                        let _e420 = (_e418 >> bitcast<u32>(_e417));
                        local_34 = _e420;
                        let _e421 = local_22;
                        let _e422 = (_e421 < _e420);
                        local_35 = _e422;
                        if _e422 {
                            let _e423 = local_22;
                            let _e425 = local_33;
                            let _e428 = local_29;
                            let _e430 = ((_e428 + ((_e423 + 1u) << bitcast<u32>(_e425))) - 1u);
                            local_36 = _e430;
                            if (_e430 < 512u) {
                            } else {
                                phi_623_ = true;
                                break;
                            }
                            let _e432 = local_36;
                            let _e434 = global_5[_e432];
                            phi_381_ = _e434;
                        } else {
                            phi_381_ = 0u;
                        }
                        let _e436 = phi_381_;
                        phi_387_ = 1u;
                        phi_390_ = _e436;
                        loop {
                            let _e438 = phi_387_;
                            let _e440 = phi_390_;
                            local_37 = _e438;
                            local_38 = _e440;
                            let _e441 = local_37;
                            let _e442 = local_1;
                            let _e443 = (_e441 < _e442);
                            local_39 = _e443;
                            if _e443 {
                                let _e444 = local_38;
                                let _e445 = local_37;
                                let _e446 = subgroupShuffleUp(_e444, _e445);
                                local_40 = _e446;
                                let _e447 = local_4;
                                let _e448 = local_37;
                                if (_e447 >= _e448) {
                                    let _e450 = local_40;
                                    let _e451 = local_38;
                                    let _e453 = local_40;
                                    let _e454 = local_38;
                                    phi_408_ = select(_e454, _e453, (_e450 > _e451));
                                } else {
                                    phi_408_ = _e440;
                                }
                                let _e457 = phi_408_;
                                let _e458 = local_37;
                                phi_388_ = (_e458 * 2u);
                                phi_391_ = _e457;
                            } else {
                                phi_388_ = u32();
                                phi_391_ = u32();
                            }
                            let _e461 = phi_388_;
                            let _e463 = phi_391_;
                            continue;
                            continuing {
                                let _e464 = local_39;
                                phi_387_ = _e461;
                                phi_390_ = _e463;
                                break if !(_e464);
                            }
                        }
                        let _e466 = local_35;
                        if _e466 {
                            let _e467 = local_28;
                            let _e468 = local_22;
                            let _e469 = (_e467 + _e468);
                            local_41 = _e469;
                            if (_e469 < 512u) {
                            } else {
                                phi_623_ = true;
                                break;
                            }
                            let _e471 = local_41;
                            let _e473 = local_38;
                            global_5[_e471] = _e473;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e474 = local_28;
                        let _e475 = local_34;
                        let _e477 = local_31;
                        phi_348_ = (_e474 + _e475);
                        phi_352_ = _e420;
                        phi_354_ = (_e477 + 1u);
                    } else {
                        phi_348_ = u32();
                        phi_352_ = u32();
                        phi_354_ = u32();
                    }
                    let _e480 = phi_348_;
                    let _e482 = phi_352_;
                    let _e484 = phi_354_;
                    continue;
                    continuing {
                        let _e485 = local_32;
                        phi_347_ = _e480;
                        phi_350_ = _e406;
                        phi_351_ = _e482;
                        phi_353_ = _e484;
                        phi_623_ = _e265;
                        break if !(_e485);
                    }
                }
                let _e488 = phi_623_;
                if _e488 {
                    break;
                }
                let _e615 = local_67;
                phi_426_ = _e615;
                let _e618 = local_68;
                phi_429_ = _e618;
                let _e621 = local_69;
                phi_431_ = _e621;
                loop {
                    let _e490 = phi_426_;
                    let _e492 = phi_429_;
                    let _e494 = phi_431_;
                    local_42 = _e490;
                    local_43 = _e492;
                    local_44 = _e494;
                    let _e495 = local_44;
                    let _e496 = (_e495 > 0u);
                    local_45 = _e496;
                    if _e496 {
                        let _e497 = local_21;
                        let _e498 = (_e497 & 31u);
                        local_46 = _e498;
                        let _e499 = local_43;
                        let _e501 = (_e499 << bitcast<u32>(_e498));
                        local_47 = _e501;
                        let _e502 = local_44;
                        if (_e502 == 1u) {
                            phi_446_ = 256u;
                        } else {
                            let _e504 = local_42;
                            let _e505 = local_47;
                            phi_446_ = (_e504 - _e505);
                        }
                        let _e508 = phi_446_;
                        local_48 = _e508;
                        let _e509 = local;
                        let _e510 = local_20;
                        if (_e509 >= _e510) {
                            let _e512 = local;
                            let _e513 = local_47;
                            if (_e512 < _e513) {
                                let _e515 = local_48;
                                let _e516 = local;
                                local_49 = (_e515 + _e516);
                                let _e518 = local;
                                let _e519 = local_46;
                                let _e522 = local_42;
                                let _e524 = ((_e522 + (_e518 >> bitcast<u32>(_e519))) - 1u);
                                local_50 = _e524;
                                if (_e524 < 512u) {
                                } else {
                                    phi_636_ = true;
                                    break;
                                }
                                let _e526 = local_50;
                                let _e528 = global_5[_e526];
                                local_51 = _e528;
                                let _e529 = local_49;
                                let _e530 = (_e529 < 512u);
                                local_52 = _e530;
                                if _e530 {
                                } else {
                                    phi_636_ = true;
                                    break;
                                }
                                let _e531 = local_49;
                                let _e533 = global_5[_e531];
                                let _e534 = local_51;
                                let _e536 = local_51;
                                local_66 = select(_e533, _e536, (_e534 > _e533));
                                let _e538 = local_52;
                                if _e538 {
                                } else {
                                    phi_636_ = true;
                                    break;
                                }
                                let _e539 = local_66;
                                global_5[_e531] = _e539;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e540 = local_44;
                        phi_427_ = _e508;
                        phi_430_ = _e501;
                        phi_432_ = (_e540 - 1u);
                    } else {
                        phi_427_ = u32();
                        phi_430_ = u32();
                        phi_432_ = u32();
                    }
                    let _e543 = phi_427_;
                    let _e545 = phi_430_;
                    let _e547 = phi_432_;
                    continue;
                    continuing {
                        let _e548 = local_45;
                        phi_426_ = _e543;
                        phi_429_ = _e545;
                        phi_431_ = _e547;
                        phi_636_ = _e488;
                        break if !(_e548);
                    }
                }
                let _e551 = phi_636_;
                if _e551 {
                    break;
                }
                phi_545_ = 256u;
            } else {
                phi_487_ = 1u;
                phi_490_ = 0u;
                loop {
                    let _e306 = phi_487_;
                    let _e308 = phi_490_;
                    local_53 = _e306;
                    local_54 = _e308;
                    local_70 = _e308;
                    let _e309 = local_53;
                    let _e310 = (_e309 < 256u);
                    local_55 = _e310;
                    if _e310 {
                        let _e311 = local_54;
                        let _e313 = select(0u, 256u, (_e311 == 0u));
                        local_65 = _e313;
                        let _e314 = local_54;
                        let _e315 = local;
                        let _e316 = (_e314 + _e315);
                        local_56 = _e316;
                        if (_e316 < 512u) {
                        } else {
                            phi_612_ = true;
                            break;
                        }
                        let _e318 = local_56;
                        let _e320 = global_5[_e318];
                        local_57 = _e320;
                        let _e321 = local;
                        let _e322 = local_53;
                        if (_e321 >= _e322) {
                            let _e324 = local;
                            let _e325 = local_53;
                            let _e327 = local_54;
                            let _e328 = (_e327 + (_e324 - _e325));
                            local_58 = _e328;
                            if (_e328 < 512u) {
                            } else {
                                phi_612_ = true;
                                break;
                            }
                            let _e330 = local_58;
                            let _e332 = global_5[_e330];
                            let _e333 = local_57;
                            let _e335 = local_57;
                            phi_530_ = select(_e335, _e332, (_e332 > _e333));
                        } else {
                            phi_530_ = _e320;
                        }
                        let _e338 = phi_530_;
                        local_59 = _e338;
                        let _e339 = local_65;
                        let _e340 = local;
                        let _e341 = (_e339 + _e340);
                        local_60 = _e341;
                        if (_e341 < 512u) {
                        } else {
                            phi_612_ = true;
                            break;
                        }
                        let _e343 = local_60;
                        let _e345 = local_59;
                        global_5[_e343] = _e345;
                        storageBarrier();
                        workgroupBarrier();
                        let _e346 = local_53;
                        phi_488_ = (_e346 * 2u);
                        phi_491_ = _e313;
                    } else {
                        phi_488_ = u32();
                        phi_491_ = u32();
                    }
                    let _e349 = phi_488_;
                    let _e351 = phi_491_;
                    continue;
                    continuing {
                        let _e352 = local_55;
                        phi_487_ = _e349;
                        phi_490_ = _e351;
                        phi_612_ = _e265;
                        break if !(_e352);
                    }
                }
                let _e355 = phi_612_;
                if _e355 {
                    break;
                }
                let _e629 = local_70;
                phi_545_ = _e629;
            }
            let _e553 = phi_545_;
            local_61 = _e553;
            let _e554 = local;
            if (_e554 == 255u) {
                let _e556 = local_61;
                let _e557 = local;
                let _e558 = (_e556 + _e557);
                local_62 = _e558;
                if (_e558 < 512u) {
                } else {
                    break;
                }
                let _e560 = local_62;
                let _e562 = global_5[_e560];
                local_63 = _e562;
                let _e563 = local_6;
                if (0u < _e563) {
                } else {
                    break;
                }
                let _e567 = local_63;
                let _e568 = atomicMax((&global_6.member[0u]), _e567);
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn subgroups(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>, @builtin(subgroup_size) param_3: u32, @builtin(num_subgroups) param_4: u32, @builtin(subgroup_id) param_5: u32, @builtin(subgroup_invocation_id) param_6: u32) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    global_7 = param_3;
    global_8 = param_4;
    global_9 = param_5;
    global_10 = param_6;
    function_();
}
