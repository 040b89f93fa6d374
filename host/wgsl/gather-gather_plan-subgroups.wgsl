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
    var phi_580_: bool;
    var phi_253_: u32;
    var phi_122_: u32;
    var phi_125_: u32;
    var phi_587_: bool;
    var phi_277_: type_20;
    var phi_279_: type_20;
    var phi_280_: bool;
    var phi_281_: type_20;
    var phi_282_: bool;
    var phi_287_: type_20;
    var phi_310_: u32;
    var phi_313_: u32;
    var phi_331_: u32;
    var phi_311_: u32;
    var phi_314_: u32;
    var phi_342_: u32;
    var phi_345_: u32;
    var phi_346_: u32;
    var phi_348_: u32;
    var phi_376_: u32;
    var phi_378_: u32;
    var phi_381_: u32;
    var phi_399_: u32;
    var phi_379_: u32;
    var phi_382_: u32;
    var phi_343_: u32;
    var phi_347_: u32;
    var phi_349_: u32;
    var phi_613_: bool;
    var phi_416_: u32;
    var phi_419_: u32;
    var phi_421_: u32;
    var phi_436_: u32;
    var phi_417_: u32;
    var phi_420_: u32;
    var phi_422_: u32;
    var phi_626_: bool;
    var phi_477_: u32;
    var phi_480_: u32;
    var phi_520_: u32;
    var phi_478_: u32;
    var phi_481_: u32;
    var phi_602_: bool;
    var phi_535_: u32;
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
                        phi_587_ = true;
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
                            let _e161 = global_3.member.member_4.member_1;
                            let _e166 = global_3.member.member_4.member;
                            let _e171 = global_3.member.member_4.member_2;
                            let _e177 = global_3.member.member_4.member_3;
                            phi_218_ = (0.5f * ((((2f * _e161) * _e166) / (_e171 - _e166)) * _e177));
                        } else {
                            let _e180 = local_14;
                            if _e180 {
                                phi_181_ = false;
                            } else {
                                let _e181 = local_13;
                                phi_181_ = (_e181 <= 2139095040u);
                            }
                            let _e184 = phi_181_;
                            if _e184 {
                                let _e188 = global_3.member.member_4.member_1;
                                let _e193 = global_3.member.member_4.member;
                                let _e198 = global_3.member.member_4.member_2;
                                local_16 = _e198;
                                let _e204 = global_3.member.member_4.member_3;
                                let _e205 = ((((2f * _e188) * _e193) / (_e198 - _e193)) * _e204);
                                local_17 = _e205;
                                if (_e205 == 0f) {
                                    phi_209_ = 0f;
                                } else {
                                    let _e207 = local_16;
                                    let _e208 = local_12;
                                    let _e211 = local_17;
                                    phi_209_ = (_e211 * (1f - (_e207 / _e208)));
                                }
                                let _e214 = phi_209_;
                                phi_210_ = _e214;
                            } else {
                                phi_210_ = bitcast<f32>(_e105);
                            }
                            let _e216 = phi_210_;
                            local_18 = _e216;
                            if (_e216 < 0f) {
                                let _e218 = local_18;
                                phi_216_ = -(_e218);
                            } else {
                                phi_216_ = _e216;
                            }
                            let _e221 = phi_216_;
                            phi_218_ = (0.5f * _e221);
                        }
                        let _e224 = phi_218_;
                        let _e228 = select(_e224, 0f, ((bitcast<u32>(_e224) & 2147483647u) > 2139095040u));
                        local_64 = _e228;
                        if !((_e228 == _e228)) {
                            phi_580_ = true;
                        } else {
                            let _e231 = local_15;
                            let _e232 = local_64;
                            phi_580_ = (_e231 <= _e232);
                        }
                        let _e235 = phi_580_;
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
                    phi_587_ = false;
                    break if !(_e262);
                }
            }
            let _e265 = phi_587_;
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
                let _e305 = local_20;
                let _e307 = local_20;
                local_21 = select(firstTrailingBit(_e305), 32u, (_e307 == 0u));
                let _e310 = local_3;
                let _e311 = local_1;
                let _e313 = local_4;
                let _e314 = ((_e310 * _e311) + _e313);
                local_22 = _e314;
                if (_e314 < 512u) {
                } else {
                    break;
                }
                let _e316 = local_22;
                let _e318 = global_5[_e316];
                phi_310_ = 1u;
                phi_313_ = _e318;
                loop {
                    let _e320 = phi_310_;
                    let _e322 = phi_313_;
                    local_23 = _e320;
                    local_24 = _e322;
                    let _e323 = local_23;
                    let _e324 = local_1;
                    let _e325 = (_e323 < _e324);
                    local_25 = _e325;
                    if _e325 {
                        let _e326 = local_24;
                        let _e327 = local_23;
                        let _e328 = subgroupShuffleUp(_e326, _e327);
                        local_26 = _e328;
                        let _e329 = local_4;
                        let _e330 = local_23;
                        if (_e329 >= _e330) {
                            let _e332 = local_26;
                            let _e333 = local_24;
                            let _e335 = local_26;
                            let _e336 = local_24;
                            phi_331_ = select(_e336, _e335, (_e332 > _e333));
                        } else {
                            phi_331_ = _e322;
                        }
                        let _e339 = phi_331_;
                        let _e340 = local_23;
                        phi_311_ = (_e340 * 2u);
                        phi_314_ = _e339;
                    } else {
                        phi_311_ = u32();
                        phi_314_ = u32();
                    }
                    let _e343 = phi_311_;
                    let _e345 = phi_314_;
                    continue;
                    continuing {
                        let _e346 = local_25;
                        phi_310_ = _e343;
                        phi_313_ = _e345;
                        break if !(_e346);
                    }
                }
                let _e348 = local_22;
                let _e349 = (256u + _e348);
                local_27 = _e349;
                if (_e349 < 512u) {
                } else {
                    break;
                }
                let _e351 = local_27;
                let _e353 = local_24;
                global_5[_e351] = _e353;
                storageBarrier();
                workgroupBarrier();
                phi_342_ = 0u;
                phi_345_ = 256u;
                phi_346_ = 256u;
                phi_348_ = 0u;
                loop {
                    let _e355 = phi_342_;
                    let _e357 = phi_345_;
                    let _e359 = phi_346_;
                    let _e361 = phi_348_;
                    local_28 = _e355;
                    local_29 = _e357;
                    local_30 = _e359;
                    local_31 = _e361;
                    local_67 = _e357;
                    local_68 = _e359;
                    local_69 = _e361;
                    let _e362 = local_30;
                    let _e363 = local_20;
                    let _e364 = (_e362 > _e363);
                    local_32 = _e364;
                    if _e364 {
                        let _e365 = local_21;
                        let _e366 = (_e365 & 31u);
                        local_33 = _e366;
                        let _e367 = local_30;
                        let _e369 = (_e367 >> bitcast<u32>(_e366));
                        local_34 = _e369;
                        let _e370 = local_22;
                        let _e371 = (_e370 < _e369);
                        local_35 = _e371;
                        if _e371 {
                            let _e372 = local_22;
                            let _e374 = local_33;
                            let _e377 = local_29;
                            let _e379 = ((_e377 + ((_e372 + 1u) << bitcast<u32>(_e374))) - 1u);
                            local_36 = _e379;
                            if (_e379 < 512u) {
                            } else {
                                phi_613_ = true;
                                break;
                            }
                            let _e381 = local_36;
                            let _e383 = global_5[_e381];
                            phi_376_ = _e383;
                        } else {
                            phi_376_ = 0u;
                        }
                        let _e385 = phi_376_;
                        phi_378_ = 1u;
                        phi_381_ = _e385;
                        loop {
                            let _e387 = phi_378_;
                            let _e389 = phi_381_;
                            local_37 = _e387;
                            local_38 = _e389;
                            let _e390 = local_37;
                            let _e391 = local_1;
                            let _e392 = (_e390 < _e391);
                            local_39 = _e392;
                            if _e392 {
                                let _e393 = local_38;
                                let _e394 = local_37;
                                let _e395 = subgroupShuffleUp(_e393, _e394);
                                local_40 = _e395;
                                let _e396 = local_4;
                                let _e397 = local_37;
                                if (_e396 >= _e397) {
                                    let _e399 = local_40;
                                    let _e400 = local_38;
                                    let _e402 = local_40;
                                    let _e403 = local_38;
                                    phi_399_ = select(_e403, _e402, (_e399 > _e400));
                                } else {
                                    phi_399_ = _e389;
                                }
                                let _e406 = phi_399_;
                                let _e407 = local_37;
                                phi_379_ = (_e407 * 2u);
                                phi_382_ = _e406;
                            } else {
                                phi_379_ = u32();
                                phi_382_ = u32();
                            }
                            let _e410 = phi_379_;
                            let _e412 = phi_382_;
                            continue;
                            continuing {
                                let _e413 = local_39;
                                phi_378_ = _e410;
                                phi_381_ = _e412;
                                break if !(_e413);
                            }
                        }
                        let _e415 = local_35;
                        if _e415 {
                            let _e416 = local_28;
                            let _e417 = local_22;
                            let _e418 = (_e416 + _e417);
                            local_41 = _e418;
                            if (_e418 < 512u) {
                            } else {
                                phi_613_ = true;
                                break;
                            }
                            let _e420 = local_41;
                            let _e422 = local_38;
                            global_5[_e420] = _e422;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e423 = local_28;
                        let _e424 = local_34;
                        let _e426 = local_31;
                        phi_343_ = (_e423 + _e424);
                        phi_347_ = _e369;
                        phi_349_ = (_e426 + 1u);
                    } else {
                        phi_343_ = u32();
                        phi_347_ = u32();
                        phi_349_ = u32();
                    }
                    let _e429 = phi_343_;
                    let _e431 = phi_347_;
                    let _e433 = phi_349_;
                    continue;
                    continuing {
                        let _e434 = local_32;
                        phi_342_ = _e429;
                        phi_345_ = _e355;
                        phi_346_ = _e431;
                        phi_348_ = _e433;
                        phi_613_ = _e265;
                        break if !(_e434);
                    }
                }
                let _e437 = phi_613_;
                if _e437 {
                    break;
                }
                let _e609 = local_67;
                phi_416_ = _e609;
                let _e612 = local_68;
                phi_419_ = _e612;
                let _e615 = local_69;
                phi_421_ = _e615;
                loop {
                    let _e439 = phi_416_;
                    let _e441 = phi_419_;
                    let _e443 = phi_421_;
                    local_42 = _e439;
                    local_43 = _e441;
                    local_44 = _e443;
                    let _e444 = local_44;
                    let _e445 = (_e444 > 0u);
                    local_45 = _e445;
                    if _e445 {
                        let _e446 = local_21;
                        let _e447 = (_e446 & 31u);
                        local_46 = _e447;
                        let _e448 = local_43;
                        let _e450 = (_e448 << bitcast<u32>(_e447));
                        local_47 = _e450;
                        let _e451 = local_44;
                        if (_e451 == 1u) {
                            phi_436_ = 256u;
                        } else {
                            let _e453 = local_42;
                            let _e454 = local_47;
                            phi_436_ = (_e453 - _e454);
                        }
                        let _e457 = phi_436_;
                        local_48 = _e457;
                        let _e458 = local;
                        let _e459 = local_20;
                        if (_e458 >= _e459) {
                            let _e461 = local;
                            let _e462 = local_47;
                            if (_e461 < _e462) {
                                let _e464 = local_48;
                                let _e465 = local;
                                local_49 = (_e464 + _e465);
                                let _e467 = local;
                                let _e468 = local_46;
                                let _e471 = local_42;
                                let _e473 = ((_e471 + (_e467 >> bitcast<u32>(_e468))) - 1u);
                                local_50 = _e473;
                                if (_e473 < 512u) {
                                } else {
                                    phi_626_ = true;
                                    break;
                                }
                                let _e475 = local_50;
                                let _e477 = global_5[_e475];
                                local_51 = _e477;
                                let _e478 = local_49;
                                let _e479 = (_e478 < 512u);
                                local_52 = _e479;
                                if _e479 {
                                } else {
                                    phi_626_ = true;
                                    break;
                                }
                                let _e480 = local_49;
                                let _e482 = global_5[_e480];
                                let _e483 = local_51;
                                let _e485 = local_51;
                                local_65 = select(_e482, _e485, (_e483 > _e482));
                                let _e487 = local_52;
                                if _e487 {
                                } else {
                                    phi_626_ = true;
                                    break;
                                }
                                let _e488 = local_65;
                                global_5[_e480] = _e488;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e489 = local_44;
                        phi_417_ = _e457;
                        phi_420_ = _e450;
                        phi_422_ = (_e489 - 1u);
                    } else {
                        phi_417_ = u32();
                        phi_420_ = u32();
                        phi_422_ = u32();
                    }
                    let _e492 = phi_417_;
                    let _e494 = phi_420_;
                    let _e496 = phi_422_;
                    continue;
                    continuing {
                        let _e497 = local_45;
                        phi_416_ = _e492;
                        phi_419_ = _e494;
                        phi_421_ = _e496;
                        phi_626_ = _e437;
                        break if !(_e497);
                    }
                }
                let _e500 = phi_626_;
                if _e500 {
                    break;
                }
                phi_535_ = 256u;
            } else {
                phi_477_ = 1u;
                phi_480_ = 0u;
                loop {
                    let _e502 = phi_477_;
                    let _e504 = phi_480_;
                    local_53 = _e502;
                    local_54 = _e504;
                    local_70 = _e504;
                    let _e505 = local_53;
                    let _e506 = (_e505 < 256u);
                    local_55 = _e506;
                    if _e506 {
                        let _e507 = local_54;
                        let _e509 = select(0u, 256u, (_e507 == 0u));
                        local_66 = _e509;
                        let _e510 = local_54;
                        let _e511 = local;
                        let _e512 = (_e510 + _e511);
                        local_56 = _e512;
                        if (_e512 < 512u) {
                        } else {
                            phi_602_ = true;
                            break;
                        }
                        let _e514 = local_56;
                        let _e516 = global_5[_e514];
                        local_57 = _e516;
                        let _e517 = local;
                        let _e518 = local_53;
                        if (_e517 >= _e518) {
                            let _e520 = local;
                            let _e521 = local_53;
                            let _e523 = local_54;
                            let _e524 = (_e523 + (_e520 - _e521));
                            local_58 = _e524;
                            if (_e524 < 512u) {
                            } else {
                                phi_602_ = true;
                                break;
                            }
                            let _e526 = local_58;
                            let _e528 = global_5[_e526];
                            let _e529 = local_57;
                            let _e531 = local_57;
                            phi_520_ = select(_e531, _e528, (_e528 > _e529));
                        } else {
                            phi_520_ = _e516;
                        }
                        let _e534 = phi_520_;
                        local_59 = _e534;
                        let _e535 = local_66;
                        let _e536 = local;
                        let _e537 = (_e535 + _e536);
                        local_60 = _e537;
                        if (_e537 < 512u) {
                        } else {
                            phi_602_ = true;
                            break;
                        }
                        let _e539 = local_60;
                        let _e541 = local_59;
                        global_5[_e539] = _e541;
                        storageBarrier();
                        workgroupBarrier();
                        let _e542 = local_53;
                        phi_478_ = (_e542 * 2u);
                        phi_481_ = _e509;
                    } else {
                        phi_478_ = u32();
                        phi_481_ = u32();
                    }
                    let _e545 = phi_478_;
                    let _e547 = phi_481_;
                    continue;
                    continuing {
                        let _e548 = local_55;
                        phi_477_ = _e545;
                        phi_480_ = _e547;
                        phi_602_ = _e265;
                        break if !(_e548);
                    }
                }
                let _e551 = phi_602_;
                if _e551 {
                    break;
                }
                let _e629 = local_70;
                phi_535_ = _e629;
            }
            let _e553 = phi_535_;
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
