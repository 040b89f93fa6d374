struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_18 {
    member: u32,
    member_1: u32,
}

struct type_19 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_20 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: f32,
    member_12: f32,
    member_13: f32,
    member_14: f32,
    member_15: type_5,
    member_16: type_19,
    member_17: u32,
    member_18: u32,
}

struct type_21 {
    member: type_20,
}

struct type_28 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<workgroup> global_3: array<u32, 512>;
@group(0) @binding(1) 
var<storage> global_4: type_7;
var<private> global_5: u32;
var<private> global_6: u32;
var<private> global_7: u32;
var<private> global_8: u32;
var<immediate> global_9: type_21;
@group(0) @binding(0) 
var<storage> global_10: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_11: type_28;
var<private> global_12: u32 = 2143289344u;

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
    var local_11: f32;
    var local_12: bool;
    var local_13: u32;
    var local_14: u32;
    var local_15: bool;
    var local_16: f32;
    var local_17: f32;
    var local_18: bool;
    var local_19: u32;
    var local_20: f32;
    var local_21: u32;
    var local_22: f32;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: u32;
    var local_28: f32;
    var local_29: bool;
    var local_30: u32;
    var local_31: u32;
    var local_32: f32;
    var local_33: f32;
    var local_34: f32;
    var local_35: u32;
    var local_36: bool;
    var local_37: bool;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: bool;
    var local_43: u32;
    var local_44: bool;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: bool;
    var local_52: u32;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: bool;
    var local_57: u32;
    var phi_687_: bool;
    var phi_111_: u32;
    var phi_114_: f32;
    var phi_139_: u32;
    var phi_142_: bool;
    var phi_144_: f32;
    var phi_146_: f32;
    var phi_228_: bool;
    var phi_229_: bool;
    var phi_231_: bool;
    var phi_232_: bool;
    var phi_233_: bool;
    var phi_234_: bool;
    var phi_251_: f32;
    var phi_282_: bool;
    var phi_310_: f32;
    var phi_311_: f32;
    var phi_317_: f32;
    var phi_319_: f32;
    var phi_333_: f32;
    var phi_334_: f32;
    var phi_140_: u32;
    var phi_143_: bool;
    var phi_145_: f32;
    var phi_147_: f32;
    var phi_683_: bool;
    var phi_346_: bool;
    var phi_347_: bool;
    var phi_429_: f32;
    var phi_704_: bool;
    var phi_112_: u32;
    var phi_115_: f32;
    var phi_703_: bool;
    var phi_454_: type_18;
    var phi_456_: type_18;
    var phi_457_: bool;
    var phi_458_: type_18;
    var phi_459_: bool;
    var phi_464_: type_18;
    var phi_607_: u32;
    var phi_608_: u32;
    var phi_715_: bool;
    var phi_476_: u32;
    var phi_479_: u32;
    var phi_503_: u32;
    var phi_477_: u32;
    var phi_480_: u32;
    var phi_724_: bool;
    var phi_574_: u32;
    var phi_655_: u32;
    var local_58: f32;

    let _e99 = global_12;
    switch bitcast<i32>(0u) {
        default: {
            let _e102 = global;
            local = _e102;
            let _e103 = global_1;
            let _e104 = global_2;
            let _e105 = global_5;
            local_1 = _e105;
            let _e106 = global_6;
            local_2 = _e106;
            let _e107 = global_7;
            local_3 = _e107;
            let _e108 = global_8;
            local_4 = _e108;
            local_5 = arrayLength((&global_10.member));
            local_6 = arrayLength((&global_4.member));
            local_7 = arrayLength((&global_11.member));
            let _e119 = global_9.member.member;
            let _e122 = global_9.member.member_1;
            local_8 = (_e119 * _e122);
            local_9 = (_e104.x * 256u);
            phi_687_ = false;
            phi_111_ = ((_e103.x * 256u) + _e102);
            phi_114_ = 0f;
            loop {
                let _e128 = phi_687_;
                let _e130 = phi_111_;
                let _e132 = phi_114_;
                local_10 = _e130;
                local_11 = _e132;
                let _e133 = local_10;
                let _e134 = local_8;
                let _e135 = (_e133 < _e134);
                local_12 = _e135;
                if _e135 {
                    let _e136 = local_10;
                    let _e137 = local_6;
                    if (_e136 < _e137) {
                    } else {
                        phi_703_ = true;
                        break;
                    }
                    let _e139 = local_10;
                    let _e142 = global_4.member[_e139];
                    let _e145 = global_9.member.member_2;
                    local_13 = _e145;
                    local_55 = select(_e145, _e142, (_e142 < _e145));
                    phi_139_ = 0u;
                    phi_142_ = false;
                    phi_144_ = 1f;
                    phi_146_ = _e132;
                    loop {
                        let _e149 = phi_139_;
                        let _e151 = phi_142_;
                        let _e153 = phi_144_;
                        let _e155 = phi_146_;
                        local_14 = _e149;
                        local_15 = _e151;
                        local_16 = _e153;
                        local_17 = _e155;
                        local_58 = _e155;
                        let _e156 = local_14;
                        let _e157 = local_55;
                        let _e158 = (_e156 < _e157);
                        local_18 = _e158;
                        if _e158 {
                            let _e159 = local_10;
                            let _e160 = local_13;
                            let _e162 = local_14;
                            let _e164 = (5u * ((_e159 * _e160) + _e162));
                            local_19 = _e164;
                            let _e165 = local_5;
                            if (_e164 < _e165) {
                            } else {
                                phi_683_ = true;
                                break;
                            }
                            let _e167 = local_19;
                            let _e170 = global_10.member[_e167];
                            local_20 = bitcast<f32>(_e170);
                            let _e172 = local_19;
                            let _e173 = (_e172 + 1u);
                            local_21 = _e173;
                            let _e174 = local_5;
                            if (_e173 < _e174) {
                            } else {
                                phi_683_ = true;
                                break;
                            }
                            let _e176 = local_21;
                            let _e179 = global_10.member[_e176];
                            local_22 = bitcast<f32>(_e179);
                            let _e181 = local_19;
                            let _e182 = (_e181 + 2u);
                            local_23 = _e182;
                            let _e183 = local_5;
                            if (_e182 < _e183) {
                            } else {
                                phi_683_ = true;
                                break;
                            }
                            let _e185 = local_23;
                            let _e188 = global_10.member[_e185];
                            local_24 = bitcast<f32>(_e188);
                            let _e190 = local_19;
                            let _e191 = (_e190 + 3u);
                            local_25 = _e191;
                            let _e192 = local_5;
                            if (_e191 < _e192) {
                            } else {
                                phi_683_ = true;
                                break;
                            }
                            let _e194 = local_25;
                            let _e197 = global_10.member[_e194];
                            local_26 = bitcast<f32>(_e197);
                            let _e199 = local_19;
                            let _e200 = (_e199 + 4u);
                            local_27 = _e200;
                            let _e201 = local_5;
                            if (_e200 < _e201) {
                            } else {
                                phi_683_ = true;
                                break;
                            }
                            let _e203 = local_27;
                            let _e206 = global_10.member[_e203];
                            local_28 = bitcast<f32>(_e206);
                            let _e208 = local_14;
                            let _e210 = local_20;
                            if ((bitcast<u32>(_e210) & 2139095040u) != 2139095040u) {
                                let _e214 = local_22;
                                if ((bitcast<u32>(_e214) & 2139095040u) != 2139095040u) {
                                    let _e218 = local_24;
                                    let _e221 = ((bitcast<u32>(_e218) & 2139095040u) != 2139095040u);
                                    local_29 = _e221;
                                    if _e221 {
                                        let _e222 = local_26;
                                        let _e223 = bitcast<u32>(_e222);
                                        local_30 = _e223;
                                        if (_e223 == 0u) {
                                            phi_228_ = false;
                                        } else {
                                            let _e225 = local_30;
                                            phi_228_ = (_e225 <= 2139095040u);
                                        }
                                        let _e228 = phi_228_;
                                        phi_229_ = _e228;
                                    } else {
                                        phi_229_ = bool();
                                    }
                                    let _e230 = phi_229_;
                                    let _e231 = local_29;
                                    phi_231_ = _e230;
                                    phi_232_ = select(true, false, _e231);
                                } else {
                                    phi_231_ = bool();
                                    phi_232_ = true;
                                }
                                let _e234 = phi_231_;
                                let _e236 = phi_232_;
                                phi_233_ = _e234;
                                phi_234_ = _e236;
                            } else {
                                phi_233_ = bool();
                                phi_234_ = true;
                            }
                            let _e238 = phi_233_;
                            let _e240 = phi_234_;
                            let _e241 = select(_e238, false, _e240);
                            local_56 = _e241;
                            if _e241 {
                                let _e242 = local_28;
                                if (_e242 > 1f) {
                                    phi_251_ = 1f;
                                } else {
                                    let _e244 = local_28;
                                    let _e246 = local_28;
                                    phi_251_ = select(0f, _e246, (_e244 >= 0f));
                                }
                                let _e249 = phi_251_;
                                let _e251 = local_16;
                                let _e253 = local_26;
                                let _e254 = bitcast<u32>(_e253);
                                local_31 = _e254;
                                if (_e254 == 2139095040u) {
                                    let _e303 = global_9.member.member_15.member_1;
                                    let _e308 = global_9.member.member_15.member;
                                    let _e313 = global_9.member.member_15.member_2;
                                    let _e319 = global_9.member.member_15.member_3;
                                    phi_319_ = (0.5f * ((((2f * _e303) * _e308) / (_e313 - _e308)) * _e319));
                                } else {
                                    let _e256 = local_31;
                                    if (_e256 == 0u) {
                                        phi_282_ = false;
                                    } else {
                                        let _e258 = local_31;
                                        phi_282_ = (_e258 <= 2139095040u);
                                    }
                                    let _e261 = phi_282_;
                                    if _e261 {
                                        let _e265 = global_9.member.member_15.member_1;
                                        let _e270 = global_9.member.member_15.member;
                                        let _e275 = global_9.member.member_15.member_2;
                                        local_32 = _e275;
                                        let _e281 = global_9.member.member_15.member_3;
                                        let _e282 = ((((2f * _e265) * _e270) / (_e275 - _e270)) * _e281);
                                        local_33 = _e282;
                                        if (_e282 == 0f) {
                                            phi_310_ = 0f;
                                        } else {
                                            let _e284 = local_32;
                                            let _e285 = local_26;
                                            let _e288 = local_33;
                                            phi_310_ = (_e288 * (1f - (_e284 / _e285)));
                                        }
                                        let _e291 = phi_310_;
                                        phi_311_ = _e291;
                                    } else {
                                        phi_311_ = bitcast<f32>(_e99);
                                    }
                                    let _e293 = phi_311_;
                                    local_34 = _e293;
                                    if (_e293 < 0f) {
                                        let _e295 = local_34;
                                        phi_317_ = -(_e295);
                                    } else {
                                        phi_317_ = _e293;
                                    }
                                    let _e298 = phi_317_;
                                    phi_319_ = (0.5f * _e298);
                                }
                                let _e323 = phi_319_;
                                let _e327 = select(_e323, 0f, ((bitcast<u32>(_e323) & 2147483647u) > 2139095040u));
                                let _e328 = local_17;
                                let _e330 = local_17;
                                phi_333_ = (_e251 * (1f - _e249));
                                phi_334_ = select(_e330, _e327, (_e327 > _e328));
                            } else {
                                phi_333_ = _e153;
                                phi_334_ = _e155;
                            }
                            let _e333 = phi_333_;
                            let _e335 = phi_334_;
                            let _e336 = local_56;
                            let _e337 = local_15;
                            phi_140_ = (_e208 + 1u);
                            phi_143_ = select(_e337, true, _e336);
                            phi_145_ = _e333;
                            phi_147_ = _e335;
                        } else {
                            phi_140_ = u32();
                            phi_143_ = bool();
                            phi_145_ = f32();
                            phi_147_ = f32();
                        }
                        let _e340 = phi_140_;
                        let _e342 = phi_143_;
                        let _e344 = phi_145_;
                        let _e346 = phi_147_;
                        continue;
                        continuing {
                            let _e347 = local_18;
                            phi_139_ = _e340;
                            phi_142_ = _e342;
                            phi_144_ = _e344;
                            phi_146_ = _e346;
                            phi_683_ = _e128;
                            break if !(_e347);
                        }
                    }
                    let _e350 = phi_683_;
                    phi_703_ = _e350;
                    if _e350 {
                        break;
                    }
                    let _e351 = local_55;
                    if (_e351 == 0u) {
                        phi_347_ = true;
                    } else {
                        let _e353 = local_15;
                        if _e353 {
                            let _e354 = local_16;
                            phi_346_ = (_e354 > 0f);
                        } else {
                            phi_346_ = false;
                        }
                        let _e357 = phi_346_;
                        phi_347_ = _e357;
                    }
                    let _e359 = phi_347_;
                    if _e359 {
                        let _e363 = global_9.member.member_15.member_1;
                        let _e368 = global_9.member.member_15.member;
                        let _e373 = global_9.member.member_15.member_2;
                        let _e379 = global_9.member.member_15.member_3;
                        let _e381 = (0.5f * ((((2f * _e363) * _e368) / (_e373 - _e368)) * _e379));
                        let _e385 = select(_e381, 0f, ((bitcast<u32>(_e381) & 2147483647u) > 2139095040u));
                        let _e386 = local_17;
                        let _e388 = local_17;
                        phi_429_ = select(_e388, _e385, (_e385 > _e386));
                    } else {
                        let _e602 = local_58;
                        phi_429_ = _e602;
                    }
                    let _e391 = phi_429_;
                    let _e392 = local_10;
                    let _e393 = local_9;
                    phi_704_ = _e350;
                    phi_112_ = (_e392 + _e393);
                    phi_115_ = _e391;
                } else {
                    phi_704_ = _e128;
                    phi_112_ = u32();
                    phi_115_ = f32();
                }
                let _e396 = phi_704_;
                let _e398 = phi_112_;
                let _e400 = phi_115_;
                continue;
                continuing {
                    let _e401 = local_12;
                    phi_687_ = _e396;
                    phi_111_ = _e398;
                    phi_114_ = _e400;
                    phi_703_ = _e396;
                    break if !(_e401);
                }
            }
            let _e404 = phi_703_;
            if _e404 {
                break;
            }
            let _e405 = local_11;
            local_35 = bitcast<u32>(_e405);
            let _e407 = local;
            let _e408 = (_e407 < 512u);
            local_36 = _e408;
            if _e408 {
            } else {
                break;
            }
            let _e409 = local;
            let _e411 = local_35;
            global_3[_e409] = _e411;
            storageBarrier();
            workgroupBarrier();
            let _e412 = local_1;
            if (_e412 >= 2u) {
                let _e414 = local_1;
                let _e416 = local_1;
                if ((_e416 & (_e414 - 1u)) == 0u) {
                    let _e419 = local_2;
                    let _e420 = local_1;
                    let _e422 = ((_e419 * _e420) == 256u);
                    local_37 = _e422;
                    if _e422 {
                        let _e423 = local_1;
                        phi_454_ = type_18(1u, _e423);
                    } else {
                        phi_454_ = type_18();
                    }
                    let _e426 = phi_454_;
                    let _e427 = local_37;
                    phi_456_ = _e426;
                    phi_457_ = select(true, false, _e427);
                } else {
                    phi_456_ = type_18();
                    phi_457_ = true;
                }
                let _e430 = phi_456_;
                let _e432 = phi_457_;
                phi_458_ = _e430;
                phi_459_ = _e432;
            } else {
                phi_458_ = type_18();
                phi_459_ = true;
            }
            let _e434 = phi_458_;
            let _e436 = phi_459_;
            if _e436 {
                phi_464_ = type_18(0u, type_18().member_1);
            } else {
                phi_464_ = _e434;
            }
            let _e441 = phi_464_;
            local_38 = _e441.member_1;
            if (bitcast<i32>(_e441.member) != 0i) {
                let _e478 = local_38;
                let _e480 = local_38;
                local_39 = select(firstTrailingBit(_e478), 32u, (_e480 == 0u));
                phi_476_ = 0u;
                phi_479_ = 256u;
                loop {
                    let _e484 = phi_476_;
                    let _e486 = phi_479_;
                    local_40 = _e484;
                    local_41 = _e486;
                    let _e487 = local_41;
                    let _e488 = local_38;
                    let _e489 = (_e487 > _e488);
                    local_42 = _e489;
                    if _e489 {
                        let _e490 = local_3;
                        let _e491 = local_1;
                        let _e493 = local_4;
                        let _e494 = ((_e490 * _e491) + _e493);
                        local_43 = _e494;
                        let _e495 = local_41;
                        let _e496 = (_e494 < _e495);
                        local_44 = _e496;
                        if _e496 {
                            let _e497 = local_40;
                            let _e499 = local_43;
                            let _e501 = (_e499 << bitcast<u32>((_e497 & 31u)));
                            local_45 = _e501;
                            if (_e501 < 512u) {
                            } else {
                                phi_724_ = true;
                                break;
                            }
                            let _e503 = local_45;
                            let _e505 = global_3[_e503];
                            phi_503_ = _e505;
                        } else {
                            phi_503_ = 0u;
                        }
                        let _e507 = phi_503_;
                        let _e508 = subgroupMax(_e507);
                        local_46 = _e508;
                        let _e509 = local_44;
                        if _e509 {
                            let _e510 = local_38;
                            let _e512 = local_43;
                            if ((_e512 & (_e510 - 1u)) == 0u) {
                                let _e515 = local_40;
                                let _e517 = local_43;
                                let _e519 = (_e517 << bitcast<u32>((_e515 & 31u)));
                                local_47 = _e519;
                                if (_e519 < 512u) {
                                } else {
                                    phi_724_ = true;
                                    break;
                                }
                                let _e521 = local_47;
                                let _e523 = local_46;
                                global_3[_e521] = _e523;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e524 = local_39;
                        let _e526 = local_41;
                        let _e529 = local_40;
                        let _e530 = local_39;
                        phi_477_ = (_e529 + _e530);
                        phi_480_ = (_e526 >> bitcast<u32>((_e524 & 31u)));
                    } else {
                        phi_477_ = u32();
                        phi_480_ = u32();
                    }
                    let _e533 = phi_477_;
                    let _e535 = phi_480_;
                    continue;
                    continuing {
                        let _e536 = local_42;
                        phi_476_ = _e533;
                        phi_479_ = _e535;
                        phi_724_ = _e404;
                        break if !(_e536);
                    }
                }
                let _e539 = phi_724_;
                if _e539 {
                    break;
                }
                let _e540 = local_3;
                let _e541 = local_1;
                let _e543 = local_4;
                let _e545 = local_38;
                let _e547 = (((_e540 * _e541) + _e543) & (_e545 - 1u));
                local_48 = _e547;
                let _e548 = local_41;
                if (_e547 < _e548) {
                    let _e550 = local_40;
                    let _e552 = local_48;
                    let _e554 = (_e552 << bitcast<u32>((_e550 & 31u)));
                    local_49 = _e554;
                    if (_e554 < 512u) {
                    } else {
                        break;
                    }
                    let _e556 = local_49;
                    let _e558 = global_3[_e556];
                    phi_574_ = _e558;
                } else {
                    phi_574_ = 0u;
                }
                let _e560 = phi_574_;
                let _e561 = subgroupMax(_e560);
                storageBarrier();
                workgroupBarrier();
                phi_655_ = _e561;
            } else {
                phi_607_ = 128u;
                loop {
                    let _e447 = phi_607_;
                    local_50 = _e447;
                    let _e448 = local_50;
                    let _e449 = (_e448 > 0u);
                    local_51 = _e449;
                    if _e449 {
                        let _e450 = local;
                        let _e451 = local_50;
                        if (_e450 < _e451) {
                            let _e453 = local_36;
                            if _e453 {
                            } else {
                                phi_715_ = true;
                                break;
                            }
                            let _e454 = global_3[_e409];
                            local_52 = _e454;
                            let _e455 = local;
                            let _e456 = local_50;
                            let _e457 = (_e455 + _e456);
                            local_53 = _e457;
                            if (_e457 < 512u) {
                            } else {
                                phi_715_ = true;
                                break;
                            }
                            let _e459 = local_53;
                            let _e461 = global_3[_e459];
                            let _e462 = local_52;
                            let _e464 = local_52;
                            local_57 = select(_e461, _e464, (_e462 > _e461));
                            let _e466 = local_36;
                            if _e466 {
                            } else {
                                phi_715_ = true;
                                break;
                            }
                            let _e467 = local_57;
                            global_3[_e409] = _e467;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e468 = local_50;
                        phi_608_ = (_e468 / 2u);
                    } else {
                        phi_608_ = u32();
                    }
                    let _e471 = phi_608_;
                    continue;
                    continuing {
                        let _e472 = local_51;
                        phi_607_ = _e471;
                        phi_715_ = _e404;
                        break if !(_e472);
                    }
                }
                let _e475 = phi_715_;
                if _e475 {
                    break;
                }
                let _e477 = global_3[0u];
                storageBarrier();
                workgroupBarrier();
                phi_655_ = _e477;
            }
            let _e563 = phi_655_;
            local_54 = _e563;
            let _e564 = local;
            if (_e564 == 0u) {
                let _e566 = local_7;
                if (17u < _e566) {
                } else {
                    break;
                }
                let _e570 = local_54;
                let _e571 = atomicMax((&global_11.member[17u]), _e570);
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
    global_5 = param_3;
    global_6 = param_4;
    global_7 = param_5;
    global_8 = param_6;
    function_();
}
