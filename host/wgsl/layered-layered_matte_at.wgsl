struct type_6 {
    member: array<u32>,
}

struct type_15 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: f32,
}

struct type_16 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: array<f32, 4>,
    member_9: u32,
    member_10: array<u32, 3>,
}

struct type_17 {
    member: type_16,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(3) 
var<storage, read_write> global_3: type_6;
@group(0) @binding(1) 
var<storage> global_4: type_6;
var<immediate> global_5: type_17;
@group(0) @binding(0) 
var<storage> global_6: type_6;
@group(0) @binding(2) 
var<storage> global_7: type_6;
var<private> global_8: u32 = 2139095040u;

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
    var local_9: i32;
    var local_10: i32;
    var local_11: u32;
    var local_12: u32;
    var local_13: f32;
    var local_14: i32;
    var local_15: u32;
    var local_16: u32;
    var local_17: f32;
    var local_18: u32;
    var local_19: u32;
    var local_20: f32;
    var local_21: i32;
    var local_22: u32;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: bool;
    var local_29: u32;
    var local_30: u32;
    var local_31: bool;
    var local_32: u32;
    var local_33: bool;
    var local_34: f32;
    var local_35: bool;
    var local_36: u32;
    var local_37: f32;
    var local_38: u32;
    var local_39: f32;
    var local_40: u32;
    var local_41: f32;
    var local_42: u32;
    var local_43: f32;
    var local_44: u32;
    var local_45: f32;
    var local_46: bool;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: bool;
    var local_51: array<f32, 4>;
    var local_52: bool;
    var local_53: u32;
    var local_54: f32;
    var local_55: u32;
    var local_56: f32;
    var local_57: u32;
    var local_58: array<f32, 3>;
    var local_59: u32;
    var local_60: f32;
    var local_61: u32;
    var local_62: type_15;
    var local_63: bool;
    var local_64: u32;
    var local_65: array<f32, 3>;
    var local_66: f32;
    var local_67: f32;
    var local_68: f32;
    var local_69: f32;
    var local_70: f32;
    var local_71: f32;
    var local_72: f32;
    var local_73: f32;
    var local_74: f32;
    var local_75: bool;
    var local_76: bool;
    var local_77: bool;
    var local_78: f32;
    var local_79: f32;
    var local_80: f32;
    var local_81: u32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: bool;
    var local_91: bool;
    var local_92: f32;
    var phi_139_: bool;
    var phi_169_: f32;
    var phi_170_: f32;
    var phi_192_: f32;
    var phi_193_: f32;
    var phi_214_: f32;
    var phi_215_: f32;
    var phi_237_: f32;
    var phi_238_: f32;
    var phi_1080_: bool;
    var phi_253_: u32;
    var phi_307_: bool;
    var phi_332_: f32;
    var phi_334_: f32;
    var phi_335_: bool;
    var phi_340_: f32;
    var phi_342_: array<f32, 4>;
    var phi_344_: u32;
    var phi_347_: bool;
    var phi_349_: f32;
    var phi_470_: bool;
    var phi_471_: bool;
    var phi_473_: bool;
    var phi_474_: bool;
    var phi_475_: bool;
    var phi_476_: bool;
    var phi_493_: f32;
    var phi_497_: f32;
    var phi_345_: u32;
    var phi_348_: bool;
    var phi_350_: f32;
    var phi_1062_: bool;
    var phi_503_: bool;
    var phi_508_: u32;
    var phi_510_: u32;
    var phi_513_: bool;
    var phi_515_: array<f32, 4>;
    var phi_619_: type_15;
    var phi_648_: bool;
    var phi_649_: bool;
    var phi_651_: bool;
    var phi_652_: bool;
    var phi_653_: bool;
    var phi_654_: bool;
    var phi_673_: bool;
    var phi_687_: bool;
    var phi_692_: f32;
    var phi_703_: bool;
    var phi_717_: bool;
    var phi_722_: f32;
    var phi_733_: bool;
    var phi_747_: bool;
    var phi_752_: f32;
    var phi_764_: f32;
    var phi_782_: bool;
    var phi_819_: f32;
    var phi_821_: f32;
    var phi_822_: bool;
    var phi_823_: f32;
    var phi_824_: bool;
    var phi_841_: bool;
    var phi_866_: f32;
    var phi_868_: f32;
    var phi_869_: bool;
    var phi_874_: f32;
    var phi_875_: f32;
    var phi_889_: bool;
    var phi_914_: f32;
    var phi_916_: f32;
    var phi_917_: bool;
    var phi_922_: f32;
    var phi_923_: f32;
    var phi_924_: f32;
    var phi_1043_: bool;
    var phi_949_: array<f32, 4>;
    var phi_511_: u32;
    var phi_514_: bool;
    var phi_516_: array<f32, 4>;
    var phi_1091_: bool;
    var phi_1148_: bool;
    var phi_1147_: bool;
    var phi_254_: u32;
    var phi_1146_: bool;

    let _e134 = global_8;
    let _e135 = bitcast<f32>(_e134);
    local_92 = _e135;
    switch bitcast<i32>(0u) {
        default: {
            let _e138 = global;
            local = _e138;
            let _e139 = global_1;
            let _e140 = global_2;
            local_1 = arrayLength((&global_6.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = arrayLength((&global_7.member));
            local_4 = arrayLength((&global_3.member));
            local_5 = _e139.x;
            local_6 = _e140.x;
            let _e153 = global_5.member.member_7;
            local_7 = _e153;
            if (_e153 == 4294967295u) {
                phi_139_ = true;
            } else {
                let _e155 = local_7;
                let _e156 = local_3;
                if (_e155 < _e156) {
                } else {
                    break;
                }
                let _e158 = local_7;
                let _e161 = global_7.member[_e158];
                phi_139_ = (_e161 != 0u);
            }
            let _e164 = phi_139_;
            if _e164 {
                let _e167 = global_5.member.member_9;
                local_8 = _e167;
                let _e170 = global_5.member.member_6;
                let _e171 = bitcast<i32>(_e170);
                local_9 = _e171;
                let _e172 = (_e171 - 2i);
                local_10 = _e172;
                if (_e172 < 0i) {
                    phi_170_ = 0f;
                } else {
                    let _e174 = local_10;
                    let _e175 = bitcast<u32>(_e174);
                    local_11 = _e175;
                    let _e177 = local_8;
                    if ((_e175 + 1u) >= _e177) {
                        phi_169_ = _e135;
                    } else {
                        let _e179 = local_11;
                        let _e180 = (128u + _e179);
                        local_12 = _e180;
                        let _e181 = local_3;
                        if (_e180 < _e181) {
                        } else {
                            break;
                        }
                        let _e183 = local_12;
                        let _e186 = global_7.member[_e183];
                        phi_169_ = bitcast<f32>(_e186);
                    }
                    let _e189 = phi_169_;
                    phi_170_ = _e189;
                }
                let _e191 = phi_170_;
                local_13 = _e191;
                let _e192 = local_9;
                let _e193 = (_e192 - 1i);
                local_14 = _e193;
                if (_e193 < 0i) {
                    phi_193_ = 0f;
                } else {
                    let _e195 = local_14;
                    let _e196 = bitcast<u32>(_e195);
                    local_15 = _e196;
                    let _e198 = local_8;
                    if ((_e196 + 1u) >= _e198) {
                        phi_192_ = _e135;
                    } else {
                        let _e200 = local_15;
                        let _e201 = (128u + _e200);
                        local_16 = _e201;
                        let _e202 = local_3;
                        if (_e201 < _e202) {
                        } else {
                            break;
                        }
                        let _e204 = local_16;
                        let _e207 = global_7.member[_e204];
                        phi_192_ = bitcast<f32>(_e207);
                    }
                    let _e210 = phi_192_;
                    phi_193_ = _e210;
                }
                let _e212 = phi_193_;
                local_17 = _e212;
                let _e213 = local_9;
                if (_e213 < 0i) {
                    phi_215_ = 0f;
                } else {
                    let _e215 = local_9;
                    let _e216 = bitcast<u32>(_e215);
                    local_18 = _e216;
                    let _e218 = local_8;
                    if ((_e216 + 1u) >= _e218) {
                        phi_214_ = _e135;
                    } else {
                        let _e220 = local_18;
                        let _e221 = (128u + _e220);
                        local_19 = _e221;
                        let _e222 = local_3;
                        if (_e221 < _e222) {
                        } else {
                            break;
                        }
                        let _e224 = local_19;
                        let _e227 = global_7.member[_e224];
                        phi_214_ = bitcast<f32>(_e227);
                    }
                    let _e230 = phi_214_;
                    phi_215_ = _e230;
                }
                let _e232 = phi_215_;
                local_20 = _e232;
                let _e233 = local_9;
                let _e234 = (_e233 + 1i);
                local_21 = _e234;
                if (_e234 < 0i) {
                    phi_238_ = 0f;
                } else {
                    let _e236 = local_21;
                    let _e237 = bitcast<u32>(_e236);
                    local_22 = _e237;
                    let _e239 = local_8;
                    if ((_e237 + 1u) >= _e239) {
                        phi_237_ = _e135;
                    } else {
                        let _e241 = local_22;
                        let _e242 = (128u + _e241);
                        local_23 = _e242;
                        let _e243 = local_3;
                        if (_e242 < _e243) {
                        } else {
                            break;
                        }
                        let _e245 = local_23;
                        let _e248 = global_7.member[_e245];
                        phi_237_ = bitcast<f32>(_e248);
                    }
                    let _e251 = phi_237_;
                    phi_238_ = _e251;
                }
                let _e253 = phi_238_;
                local_24 = _e253;
                let _e256 = global_5.member.member;
                let _e259 = global_5.member.member_1;
                local_25 = (_e256 * _e259);
                let _e261 = local_6;
                local_26 = (_e261 * 256u);
                let _e263 = local_5;
                phi_1080_ = false;
                phi_253_ = (_e263 * 256u);
                loop {
                    let _e266 = phi_1080_;
                    let _e268 = phi_253_;
                    local_27 = _e268;
                    let _e269 = local_27;
                    let _e270 = local_25;
                    let _e271 = (_e269 < _e270);
                    local_28 = _e271;
                    if _e271 {
                        let _e272 = local_27;
                        let _e273 = local;
                        let _e274 = (_e272 + _e273);
                        local_29 = _e274;
                        let _e275 = local_25;
                        if (_e274 < _e275) {
                            let _e277 = local_29;
                            let _e278 = local_2;
                            if (_e277 < _e278) {
                            } else {
                                phi_1146_ = true;
                                break;
                            }
                            let _e280 = local_29;
                            let _e283 = global_4.member[_e280];
                            let _e286 = global_5.member.member_2;
                            local_30 = _e286;
                            let _e288 = select(_e283, _e286, (_e286 < _e283));
                            local_89 = _e288;
                            if (_e288 == 0u) {
                                let _e290 = local_92;
                                let _e291 = local_17;
                                if (_e290 >= _e291) {
                                    let _e293 = local_92;
                                    let _e294 = local_20;
                                    phi_307_ = select(true, false, (_e293 <= _e294));
                                } else {
                                    phi_307_ = true;
                                }
                                let _e298 = phi_307_;
                                if _e298 {
                                    let _e299 = local_92;
                                    let _e300 = local_13;
                                    if (_e299 > _e300) {
                                        let _e302 = local_92;
                                        let _e303 = local_17;
                                        let _e304 = (_e302 < _e303);
                                        local_31 = _e304;
                                        if _e304 {
                                            let _e305 = local_92;
                                            let _e306 = local_13;
                                            let _e308 = local_17;
                                            let _e309 = local_13;
                                            phi_332_ = ((_e305 - _e306) / (_e308 - _e309));
                                        } else {
                                            phi_332_ = f32();
                                        }
                                        let _e313 = phi_332_;
                                        let _e314 = local_31;
                                        phi_334_ = _e313;
                                        phi_335_ = select(true, false, _e314);
                                    } else {
                                        phi_334_ = f32();
                                        phi_335_ = true;
                                    }
                                    let _e317 = phi_334_;
                                    let _e319 = phi_335_;
                                    phi_340_ = select(_e317, 0f, _e319);
                                } else {
                                    phi_340_ = 1f;
                                }
                                let _e322 = phi_340_;
                                phi_342_ = array<f32, 4>(array<f32, 4>(0f, 0f, 0f, 0f)[0], array<f32, 4>(0f, 0f, 0f, 0f)[1], array<f32, 4>(0f, 0f, 0f, 0f)[2], _e322);
                            } else {
                                phi_342_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            }
                            let _e329 = phi_342_;
                            phi_344_ = 0u;
                            phi_347_ = false;
                            phi_349_ = 1f;
                            loop {
                                let _e331 = phi_344_;
                                let _e333 = phi_347_;
                                let _e335 = phi_349_;
                                local_32 = _e331;
                                local_33 = _e333;
                                local_34 = _e335;
                                let _e336 = local_32;
                                let _e337 = local_89;
                                let _e338 = (_e336 < _e337);
                                local_35 = _e338;
                                if _e338 {
                                    let _e339 = local_29;
                                    let _e340 = local_30;
                                    let _e342 = local_32;
                                    let _e344 = (5u * ((_e339 * _e340) + _e342));
                                    local_36 = _e344;
                                    let _e345 = local_1;
                                    if (_e344 < _e345) {
                                    } else {
                                        phi_1062_ = true;
                                        break;
                                    }
                                    let _e347 = local_36;
                                    let _e350 = global_6.member[_e347];
                                    local_37 = bitcast<f32>(_e350);
                                    let _e352 = local_36;
                                    let _e353 = (_e352 + 1u);
                                    local_38 = _e353;
                                    let _e354 = local_1;
                                    if (_e353 < _e354) {
                                    } else {
                                        phi_1062_ = true;
                                        break;
                                    }
                                    let _e356 = local_38;
                                    let _e359 = global_6.member[_e356];
                                    local_39 = bitcast<f32>(_e359);
                                    let _e361 = local_36;
                                    let _e362 = (_e361 + 2u);
                                    local_40 = _e362;
                                    let _e363 = local_1;
                                    if (_e362 < _e363) {
                                    } else {
                                        phi_1062_ = true;
                                        break;
                                    }
                                    let _e365 = local_40;
                                    let _e368 = global_6.member[_e365];
                                    local_41 = bitcast<f32>(_e368);
                                    let _e370 = local_36;
                                    let _e371 = (_e370 + 3u);
                                    local_42 = _e371;
                                    let _e372 = local_1;
                                    if (_e371 < _e372) {
                                    } else {
                                        phi_1062_ = true;
                                        break;
                                    }
                                    let _e374 = local_42;
                                    let _e377 = global_6.member[_e374];
                                    local_43 = bitcast<f32>(_e377);
                                    let _e379 = local_36;
                                    let _e380 = (_e379 + 4u);
                                    local_44 = _e380;
                                    let _e381 = local_1;
                                    if (_e380 < _e381) {
                                    } else {
                                        phi_1062_ = true;
                                        break;
                                    }
                                    let _e383 = local_44;
                                    let _e386 = global_6.member[_e383];
                                    local_45 = bitcast<f32>(_e386);
                                    let _e388 = local_37;
                                    if ((bitcast<u32>(_e388) & 2139095040u) != 2139095040u) {
                                        let _e392 = local_39;
                                        if ((bitcast<u32>(_e392) & 2139095040u) != 2139095040u) {
                                            let _e396 = local_41;
                                            let _e399 = ((bitcast<u32>(_e396) & 2139095040u) != 2139095040u);
                                            local_46 = _e399;
                                            if _e399 {
                                                let _e400 = local_43;
                                                let _e401 = bitcast<u32>(_e400);
                                                local_47 = _e401;
                                                if (_e401 == 0u) {
                                                    phi_470_ = false;
                                                } else {
                                                    let _e403 = local_47;
                                                    phi_470_ = (_e403 <= 2139095040u);
                                                }
                                                let _e406 = phi_470_;
                                                phi_471_ = _e406;
                                            } else {
                                                phi_471_ = bool();
                                            }
                                            let _e408 = phi_471_;
                                            let _e409 = local_46;
                                            phi_473_ = _e408;
                                            phi_474_ = select(true, false, _e409);
                                        } else {
                                            phi_473_ = bool();
                                            phi_474_ = true;
                                        }
                                        let _e412 = phi_473_;
                                        let _e414 = phi_474_;
                                        phi_475_ = _e412;
                                        phi_476_ = _e414;
                                    } else {
                                        phi_475_ = bool();
                                        phi_476_ = true;
                                    }
                                    let _e416 = phi_475_;
                                    let _e418 = phi_476_;
                                    let _e419 = select(_e416, false, _e418);
                                    local_90 = _e419;
                                    if _e419 {
                                        let _e420 = local_45;
                                        if (_e420 > 1f) {
                                            phi_493_ = 1f;
                                        } else {
                                            let _e422 = local_45;
                                            let _e424 = local_45;
                                            phi_493_ = select(0f, _e424, (_e422 >= 0f));
                                        }
                                        let _e427 = phi_493_;
                                        let _e429 = local_34;
                                        phi_497_ = (_e429 * (1f - _e427));
                                    } else {
                                        phi_497_ = _e335;
                                    }
                                    let _e432 = phi_497_;
                                    let _e433 = local_90;
                                    let _e434 = local_33;
                                    let _e436 = local_32;
                                    phi_345_ = (_e436 + 1u);
                                    phi_348_ = select(_e434, true, _e433);
                                    phi_350_ = _e432;
                                } else {
                                    phi_345_ = u32();
                                    phi_348_ = bool();
                                    phi_350_ = f32();
                                }
                                let _e439 = phi_345_;
                                let _e441 = phi_348_;
                                let _e443 = phi_350_;
                                continue;
                                continuing {
                                    let _e444 = local_35;
                                    phi_344_ = _e439;
                                    phi_347_ = _e441;
                                    phi_349_ = _e443;
                                    phi_1062_ = _e266;
                                    break if !(_e444);
                                }
                            }
                            let _e447 = phi_1062_;
                            phi_1146_ = _e447;
                            if _e447 {
                                break;
                            }
                            let _e448 = local_33;
                            if _e448 {
                                let _e449 = local_34;
                                phi_503_ = (_e449 > 0f);
                            } else {
                                phi_503_ = false;
                            }
                            let _e452 = phi_503_;
                            if _e452 {
                                let _e453 = local_89;
                                phi_508_ = (_e453 + 1u);
                            } else {
                                phi_508_ = _e288;
                            }
                            let _e456 = phi_508_;
                            local_48 = _e456;
                            phi_510_ = 0u;
                            phi_513_ = true;
                            phi_515_ = _e329;
                            loop {
                                let _e458 = phi_510_;
                                let _e460 = phi_513_;
                                let _e462 = phi_515_;
                                local_49 = _e458;
                                local_50 = _e460;
                                local_51 = _e462;
                                let _e463 = local_49;
                                let _e464 = local_48;
                                let _e465 = (_e463 < _e464);
                                local_52 = _e465;
                                if _e465 {
                                    let _e466 = local_49;
                                    let _e467 = local_89;
                                    if (_e466 < _e467) {
                                        let _e469 = local_29;
                                        let _e470 = local_30;
                                        let _e472 = local_49;
                                        let _e474 = (5u * ((_e469 * _e470) + _e472));
                                        local_53 = _e474;
                                        let _e475 = local_1;
                                        if (_e474 < _e475) {
                                        } else {
                                            phi_1091_ = true;
                                            break;
                                        }
                                        let _e477 = local_53;
                                        let _e480 = global_6.member[_e477];
                                        local_54 = bitcast<f32>(_e480);
                                        let _e482 = local_53;
                                        let _e483 = (_e482 + 1u);
                                        local_55 = _e483;
                                        let _e484 = local_1;
                                        if (_e483 < _e484) {
                                        } else {
                                            phi_1091_ = true;
                                            break;
                                        }
                                        let _e486 = local_55;
                                        let _e489 = global_6.member[_e486];
                                        local_56 = bitcast<f32>(_e489);
                                        let _e491 = local_53;
                                        let _e492 = (_e491 + 2u);
                                        local_57 = _e492;
                                        let _e493 = local_1;
                                        if (_e492 < _e493) {
                                        } else {
                                            phi_1091_ = true;
                                            break;
                                        }
                                        let _e495 = local_57;
                                        let _e498 = global_6.member[_e495];
                                        let _e500 = local_54;
                                        let _e501 = local_56;
                                        local_58 = array<f32, 3>(_e500, _e501, bitcast<f32>(_e498));
                                        let _e503 = local_53;
                                        let _e504 = (_e503 + 3u);
                                        local_59 = _e504;
                                        let _e505 = local_1;
                                        if (_e504 < _e505) {
                                        } else {
                                            phi_1091_ = true;
                                            break;
                                        }
                                        let _e507 = local_59;
                                        let _e510 = global_6.member[_e507];
                                        local_60 = bitcast<f32>(_e510);
                                        let _e512 = local_53;
                                        let _e513 = (_e512 + 4u);
                                        local_61 = _e513;
                                        let _e514 = local_1;
                                        if (_e513 < _e514) {
                                        } else {
                                            phi_1091_ = true;
                                            break;
                                        }
                                        let _e516 = local_61;
                                        let _e519 = global_6.member[_e516];
                                        let _e521 = local_58;
                                        let _e522 = local_60;
                                        phi_619_ = type_15(_e521, _e522, bitcast<f32>(_e519));
                                    } else {
                                        phi_619_ = type_15(array<f32, 3>(0f, 0f, 0f), _e135, 1f);
                                    }
                                    let _e525 = phi_619_;
                                    local_62 = _e525;
                                    if ((bitcast<u32>(_e525.member[0]) & 2139095040u) != 2139095040u) {
                                        let _e531 = local_62;
                                        if ((bitcast<u32>(_e531.member[1]) & 2139095040u) != 2139095040u) {
                                            let _e537 = local_62;
                                            let _e542 = ((bitcast<u32>(_e537.member[2]) & 2139095040u) != 2139095040u);
                                            local_63 = _e542;
                                            if _e542 {
                                                let _e543 = local_62;
                                                let _e545 = bitcast<u32>(_e543.member_1);
                                                local_64 = _e545;
                                                if (_e545 == 0u) {
                                                    phi_648_ = false;
                                                } else {
                                                    let _e547 = local_64;
                                                    phi_648_ = (_e547 <= 2139095040u);
                                                }
                                                let _e550 = phi_648_;
                                                phi_649_ = _e550;
                                            } else {
                                                phi_649_ = bool();
                                            }
                                            let _e552 = phi_649_;
                                            let _e553 = local_63;
                                            phi_651_ = _e552;
                                            phi_652_ = select(true, false, _e553);
                                        } else {
                                            phi_651_ = bool();
                                            phi_652_ = true;
                                        }
                                        let _e556 = phi_651_;
                                        let _e558 = phi_652_;
                                        phi_653_ = _e556;
                                        phi_654_ = _e558;
                                    } else {
                                        phi_653_ = bool();
                                        phi_654_ = true;
                                    }
                                    let _e560 = phi_653_;
                                    let _e562 = phi_654_;
                                    let _e563 = select(_e560, false, _e562);
                                    local_91 = _e563;
                                    if _e563 {
                                        let _e564 = local_62;
                                        local_65 = _e564.member;
                                        local_66 = _e564.member[0];
                                        if (_e564.member[0] > 1267650600000000000000000000000f) {
                                            let _e568 = local_66;
                                            phi_673_ = select(true, false, (_e568 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_673_ = true;
                                        }
                                        let _e572 = phi_673_;
                                        if _e572 {
                                            let _e573 = local_66;
                                            if (_e573 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e575 = local_66;
                                                phi_687_ = select(true, false, (_e575 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_687_ = true;
                                            }
                                            let _e579 = phi_687_;
                                            let _e580 = local_66;
                                            phi_692_ = select(0f, _e580, _e579);
                                        } else {
                                            phi_692_ = 1267650600000000000000000000000f;
                                        }
                                        let _e583 = phi_692_;
                                        local_67 = _e583;
                                        let _e584 = local_65;
                                        local_68 = _e584[1];
                                        if (_e584[1] > 1267650600000000000000000000000f) {
                                            let _e587 = local_68;
                                            phi_703_ = select(true, false, (_e587 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_703_ = true;
                                        }
                                        let _e591 = phi_703_;
                                        if _e591 {
                                            let _e592 = local_68;
                                            if (_e592 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e594 = local_68;
                                                phi_717_ = select(true, false, (_e594 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_717_ = true;
                                            }
                                            let _e598 = phi_717_;
                                            let _e599 = local_68;
                                            phi_722_ = select(0f, _e599, _e598);
                                        } else {
                                            phi_722_ = 1267650600000000000000000000000f;
                                        }
                                        let _e602 = phi_722_;
                                        local_69 = _e602;
                                        let _e603 = local_65;
                                        local_70 = _e603[2];
                                        if (_e603[2] > 1267650600000000000000000000000f) {
                                            let _e606 = local_70;
                                            phi_733_ = select(true, false, (_e606 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_733_ = true;
                                        }
                                        let _e610 = phi_733_;
                                        if _e610 {
                                            let _e611 = local_70;
                                            if (_e611 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e613 = local_70;
                                                phi_747_ = select(true, false, (_e613 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_747_ = true;
                                            }
                                            let _e617 = phi_747_;
                                            let _e618 = local_70;
                                            phi_752_ = select(0f, _e618, _e617);
                                        } else {
                                            phi_752_ = 1267650600000000000000000000000f;
                                        }
                                        let _e621 = phi_752_;
                                        local_71 = _e621;
                                        let _e622 = local_62;
                                        local_72 = _e622.member_1;
                                        let _e624 = local_62;
                                        local_73 = _e624.member_2;
                                        if (_e624.member_2 > 1f) {
                                            phi_764_ = 1f;
                                        } else {
                                            let _e627 = local_73;
                                            let _e629 = local_73;
                                            phi_764_ = select(0f, _e629, (_e627 >= 0f));
                                        }
                                        let _e632 = phi_764_;
                                        local_74 = _e632;
                                        if (_e632 < 1f) {
                                            let _e634 = local_72;
                                            let _e635 = local_17;
                                            if (_e634 > _e635) {
                                                let _e637 = local_72;
                                                let _e638 = local_20;
                                                phi_782_ = select(true, false, (_e637 <= _e638));
                                            } else {
                                                phi_782_ = true;
                                            }
                                            let _e642 = phi_782_;
                                            phi_924_ = select(1f, 0f, _e642);
                                        } else {
                                            let _e644 = local_50;
                                            if _e644 {
                                                let _e645 = local_72;
                                                let _e646 = local_20;
                                                if (_e645 > _e646) {
                                                    let _e648 = local_72;
                                                    let _e649 = local_24;
                                                    if (_e648 < _e649) {
                                                        let _e651 = local_24;
                                                        let _e654 = ((bitcast<u32>(_e651) & 2139095040u) != 2139095040u);
                                                        local_75 = _e654;
                                                        if _e654 {
                                                            let _e655 = local_24;
                                                            let _e656 = local_72;
                                                            let _e658 = local_24;
                                                            let _e659 = local_20;
                                                            phi_819_ = ((_e655 - _e656) / (_e658 - _e659));
                                                        } else {
                                                            phi_819_ = f32();
                                                        }
                                                        let _e663 = phi_819_;
                                                        let _e664 = local_75;
                                                        phi_821_ = _e663;
                                                        phi_822_ = select(true, false, _e664);
                                                    } else {
                                                        phi_821_ = f32();
                                                        phi_822_ = true;
                                                    }
                                                    let _e667 = phi_821_;
                                                    let _e669 = phi_822_;
                                                    phi_823_ = _e667;
                                                    phi_824_ = _e669;
                                                } else {
                                                    phi_823_ = f32();
                                                    phi_824_ = true;
                                                }
                                                let _e671 = phi_823_;
                                                let _e673 = phi_824_;
                                                if _e673 {
                                                    let _e674 = local_72;
                                                    let _e675 = local_17;
                                                    if (_e674 >= _e675) {
                                                        let _e677 = local_72;
                                                        let _e678 = local_20;
                                                        phi_841_ = select(true, false, (_e677 <= _e678));
                                                    } else {
                                                        phi_841_ = true;
                                                    }
                                                    let _e682 = phi_841_;
                                                    if _e682 {
                                                        let _e683 = local_72;
                                                        let _e684 = local_13;
                                                        if (_e683 > _e684) {
                                                            let _e686 = local_72;
                                                            let _e687 = local_17;
                                                            let _e688 = (_e686 < _e687);
                                                            local_76 = _e688;
                                                            if _e688 {
                                                                let _e689 = local_72;
                                                                let _e690 = local_13;
                                                                let _e692 = local_17;
                                                                let _e693 = local_13;
                                                                phi_866_ = ((_e689 - _e690) / (_e692 - _e693));
                                                            } else {
                                                                phi_866_ = f32();
                                                            }
                                                            let _e697 = phi_866_;
                                                            let _e698 = local_76;
                                                            phi_868_ = _e697;
                                                            phi_869_ = select(true, false, _e698);
                                                        } else {
                                                            phi_868_ = f32();
                                                            phi_869_ = true;
                                                        }
                                                        let _e701 = phi_868_;
                                                        let _e703 = phi_869_;
                                                        phi_874_ = select(_e701, 0f, _e703);
                                                    } else {
                                                        phi_874_ = 1f;
                                                    }
                                                    let _e706 = phi_874_;
                                                    phi_875_ = _e706;
                                                } else {
                                                    phi_875_ = _e671;
                                                }
                                                let _e708 = phi_875_;
                                                phi_923_ = _e708;
                                            } else {
                                                let _e709 = local_72;
                                                let _e710 = local_17;
                                                if (_e709 >= _e710) {
                                                    let _e712 = local_72;
                                                    let _e713 = local_20;
                                                    phi_889_ = select(true, false, (_e712 <= _e713));
                                                } else {
                                                    phi_889_ = true;
                                                }
                                                let _e717 = phi_889_;
                                                if _e717 {
                                                    let _e718 = local_72;
                                                    let _e719 = local_13;
                                                    if (_e718 > _e719) {
                                                        let _e721 = local_72;
                                                        let _e722 = local_17;
                                                        let _e723 = (_e721 < _e722);
                                                        local_77 = _e723;
                                                        if _e723 {
                                                            let _e724 = local_72;
                                                            let _e725 = local_13;
                                                            let _e727 = local_17;
                                                            let _e728 = local_13;
                                                            phi_914_ = ((_e724 - _e725) / (_e727 - _e728));
                                                        } else {
                                                            phi_914_ = f32();
                                                        }
                                                        let _e732 = phi_914_;
                                                        let _e733 = local_77;
                                                        phi_916_ = _e732;
                                                        phi_917_ = select(true, false, _e733);
                                                    } else {
                                                        phi_916_ = f32();
                                                        phi_917_ = true;
                                                    }
                                                    let _e736 = phi_916_;
                                                    let _e738 = phi_917_;
                                                    phi_922_ = select(_e736, 0f, _e738);
                                                } else {
                                                    phi_922_ = 1f;
                                                }
                                                let _e741 = phi_922_;
                                                phi_923_ = _e741;
                                            }
                                            let _e743 = phi_923_;
                                            phi_924_ = _e743;
                                        }
                                        let _e745 = phi_924_;
                                        local_78 = _e745;
                                        let _e746 = local_51;
                                        local_79 = _e746[3];
                                        let _e748 = (1f - _e746[3]);
                                        local_80 = _e748;
                                        if !((_e748 == _e748)) {
                                            phi_1043_ = true;
                                        } else {
                                            let _e751 = local_80;
                                            phi_1043_ = (0f >= _e751);
                                        }
                                        let _e754 = phi_1043_;
                                        let _e755 = local_80;
                                        let _e757 = local_78;
                                        let _e758 = (select(_e755, 0f, _e754) * _e757);
                                        let _e759 = local_67;
                                        let _e761 = local_51;
                                        let _e764 = local_69;
                                        let _e766 = local_51;
                                        let _e769 = local_71;
                                        let _e771 = local_51;
                                        let _e774 = local_74;
                                        let _e776 = local_79;
                                        phi_949_ = array<f32, 4>((_e761[0] + (_e758 * _e759)), (_e766[1] + (_e758 * _e764)), (_e771[2] + (_e758 * _e769)), (_e776 + (_e758 * _e774)));
                                    } else {
                                        phi_949_ = _e462;
                                    }
                                    let _e780 = phi_949_;
                                    let _e781 = local_91;
                                    let _e782 = local_50;
                                    let _e784 = local_49;
                                    phi_511_ = (_e784 + 1u);
                                    phi_514_ = select(_e782, false, _e781);
                                    phi_516_ = _e780;
                                } else {
                                    phi_511_ = u32();
                                    phi_514_ = bool();
                                    phi_516_ = array<f32, 4>();
                                }
                                let _e787 = phi_511_;
                                let _e789 = phi_514_;
                                let _e791 = phi_516_;
                                continue;
                                continuing {
                                    let _e792 = local_52;
                                    phi_510_ = _e787;
                                    phi_513_ = _e789;
                                    phi_515_ = _e791;
                                    phi_1091_ = _e447;
                                    break if !(_e792);
                                }
                            }
                            let _e795 = phi_1091_;
                            phi_1146_ = _e795;
                            if _e795 {
                                break;
                            }
                            let _e796 = local_29;
                            let _e797 = (4u * _e796);
                            local_81 = _e797;
                            let _e798 = local_51;
                            local_82 = bitcast<u32>(_e798[0]);
                            let _e801 = local_4;
                            if (_e797 < _e801) {
                            } else {
                                phi_1146_ = true;
                                break;
                            }
                            let _e803 = local_81;
                            let _e806 = local_82;
                            global_3.member[_e803] = _e806;
                            let _e807 = local_81;
                            let _e808 = (_e807 + 1u);
                            local_83 = _e808;
                            let _e809 = local_51;
                            local_84 = bitcast<u32>(_e809[1]);
                            let _e812 = local_4;
                            if (_e808 < _e812) {
                            } else {
                                phi_1146_ = true;
                                break;
                            }
                            let _e814 = local_83;
                            let _e817 = local_84;
                            global_3.member[_e814] = _e817;
                            let _e818 = local_81;
                            let _e819 = (_e818 + 2u);
                            local_85 = _e819;
                            let _e820 = local_51;
                            local_86 = bitcast<u32>(_e820[2]);
                            let _e823 = local_4;
                            if (_e819 < _e823) {
                            } else {
                                phi_1146_ = true;
                                break;
                            }
                            let _e825 = local_85;
                            let _e828 = local_86;
                            global_3.member[_e825] = _e828;
                            let _e829 = local_81;
                            let _e830 = (_e829 + 3u);
                            local_87 = _e830;
                            let _e831 = local_51;
                            local_88 = bitcast<u32>(_e831[3]);
                            let _e834 = local_4;
                            if (_e830 < _e834) {
                            } else {
                                phi_1146_ = true;
                                break;
                            }
                            let _e836 = local_87;
                            let _e839 = local_88;
                            global_3.member[_e836] = _e839;
                            phi_1148_ = _e795;
                        } else {
                            phi_1148_ = _e266;
                        }
                        let _e841 = phi_1148_;
                        storageBarrier();
                        workgroupBarrier();
                        let _e842 = local_27;
                        let _e843 = local_26;
                        phi_1147_ = _e841;
                        phi_254_ = (_e842 + _e843);
                    } else {
                        phi_1147_ = _e266;
                        phi_254_ = u32();
                    }
                    let _e846 = phi_1147_;
                    let _e848 = phi_254_;
                    continue;
                    continuing {
                        let _e849 = local_28;
                        phi_1080_ = _e846;
                        phi_253_ = _e848;
                        phi_1146_ = _e846;
                        break if !(_e849);
                    }
                }
                let _e852 = phi_1146_;
                if _e852 {
                    break;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn layered_matte_at(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
