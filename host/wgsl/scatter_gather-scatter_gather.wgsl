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

struct type_16 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: array<f32, 3>,
    member_3: f32,
    member_4: f32,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<immediate> global_2: type_7;
@group(0) @binding(1) 
var<storage> global_3: type_10;
@group(0) @binding(0) 
var<storage> global_4: type_10;
@group(0) @binding(2) 
var<storage> global_5: type_10;
@group(0) @binding(3) 
var<storage> global_6: type_10;
@group(0) @binding(4) 
var<storage, read_write> global_7: type_10;

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
    var local_11: u32;
    var local_12: f32;
    var local_13: u32;
    var local_14: f32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: bool;
    var local_20: f32;
    var local_21: bool;
    var local_22: bool;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: u32;
    var local_28: f32;
    var local_29: f32;
    var local_30: f32;
    var local_31: array<f32, 3>;
    var local_32: f32;
    var local_33: f32;
    var local_34: type_16;
    var local_35: f32;
    var local_36: f32;
    var local_37: u32;
    var local_38: f32;
    var local_39: u32;
    var local_40: f32;
    var local_41: u32;
    var local_42: f32;
    var local_43: f32;
    var local_44: f32;
    var local_45: f32;
    var local_46: u32;
    var local_47: f32;
    var local_48: f32;
    var local_49: f32;
    var local_50: f32;
    var local_51: f32;
    var local_52: f32;
    var local_53: f32;
    var local_54: type_16;
    var local_55: u32;
    var local_56: bool;
    var local_57: u32;
    var local_58: f32;
    var local_59: f32;
    var local_60: f32;
    var local_61: type_16;
    var local_62: u32;
    var local_63: f32;
    var local_64: f32;
    var local_65: bool;
    var local_66: f32;
    var local_67: u32;
    var local_68: bool;
    var local_69: f32;
    var local_70: f32;
    var local_71: f32;
    var local_72: f32;
    var local_73: bool;
    var local_74: f32;
    var local_75: u32;
    var local_76: f32;
    var local_77: u32;
    var local_78: f32;
    var local_79: u32;
    var local_80: f32;
    var local_81: f32;
    var local_82: f32;
    var local_83: f32;
    var local_84: u32;
    var local_85: array<f32, 3>;
    var local_86: f32;
    var local_87: array<f32, 3>;
    var local_88: array<f32, 3>;
    var local_89: f32;
    var local_90: array<f32, 3>;
    var local_91: f32;
    var local_92: f32;
    var local_93: array<f32, 3>;
    var local_94: u32;
    var local_95: u32;
    var local_96: u32;
    var local_97: u32;
    var local_98: u32;
    var local_99: u32;
    var local_100: u32;
    var local_101: f32;
    var local_102: f32;
    var phi_114_: u32;
    var phi_211_: bool;
    var phi_225_: bool;
    var phi_230_: f32;
    var phi_240_: bool;
    var phi_254_: bool;
    var phi_259_: f32;
    var phi_269_: bool;
    var phi_283_: bool;
    var phi_288_: f32;
    var phi_290_: array<f32, 3>;
    var phi_302_: f32;
    var phi_367_: f32;
    var phi_467_: bool;
    var phi_481_: bool;
    var phi_486_: f32;
    var phi_496_: bool;
    var phi_510_: bool;
    var phi_515_: f32;
    var phi_525_: bool;
    var phi_539_: bool;
    var phi_544_: f32;
    var phi_573_: f32;
    var phi_574_: f32;
    var phi_614_: type_16;
    var phi_615_: type_16;
    var phi_1238_: bool;
    var phi_640_: type_16;
    var phi_643_: u32;
    var phi_693_: type_16;
    var phi_696_: u32;
    var phi_698_: f32;
    var phi_700_: f32;
    var phi_785_: f32;
    var phi_817_: f32;
    var phi_840_: f32;
    var phi_841_: f32;
    var phi_843_: f32;
    var phi_844_: bool;
    var phi_865_: f32;
    var phi_917_: bool;
    var phi_931_: bool;
    var phi_936_: f32;
    var phi_946_: bool;
    var phi_960_: bool;
    var phi_965_: f32;
    var phi_975_: bool;
    var phi_989_: bool;
    var phi_994_: f32;
    var phi_1023_: f32;
    var phi_1024_: f32;
    var phi_1064_: type_16;
    var phi_1065_: type_16;
    var phi_694_: type_16;
    var phi_697_: u32;
    var phi_699_: f32;
    var phi_701_: f32;
    var phi_1228_: bool;
    var phi_1335_: bool;
    var phi_641_: type_16;
    var phi_644_: u32;
    var phi_1334_: bool;
    var phi_1094_: array<f32, 3>;
    var phi_1115_: array<f32, 3>;
    var phi_1167_: array<f32, 3>;
    var phi_1168_: array<f32, 3>;
    var phi_1169_: array<f32, 3>;
    var phi_1170_: bool;
    var phi_1174_: array<f32, 3>;
    var phi_1175_: array<f32, 3>;
    var local_103: type_16;

    switch bitcast<i32>(0u) {
        default: {
            let _e147 = global;
            local = _e147;
            let _e148 = global_1;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = arrayLength((&global_6.member));
            local_5 = arrayLength((&global_7.member));
            local_6 = _e148.x;
            local_7 = _e148.y;
            local_8 = (_e148.y / 2u);
            let _e164 = global_2.member.member;
            local_9 = _e164;
            let _e165 = (_e164 / 16u);
            local_10 = _e165;
            if ((_e164 % 16u) > 0u) {
                let _e168 = local_10;
                phi_114_ = (_e168 + 1u);
            } else {
                phi_114_ = _e165;
            }
            let _e171 = phi_114_;
            let _e172 = local_8;
            let _e174 = local_6;
            let _e177 = (2u * ((_e172 * _e171) + (_e174 / 2u)));
            local_11 = _e177;
            let _e178 = local_4;
            if (_e177 < _e178) {
            } else {
                break;
            }
            let _e180 = local_11;
            let _e183 = global_6.member[_e180];
            local_12 = bitcast<f32>(_e183);
            let _e185 = local_11;
            let _e186 = (_e185 + 1u);
            local_13 = _e186;
            let _e187 = local_4;
            if (_e186 < _e187) {
            } else {
                break;
            }
            let _e189 = local_13;
            let _e192 = global_6.member[_e189];
            local_14 = bitcast<f32>(_e192);
            let _e194 = local_6;
            let _e196 = local;
            let _e198 = ((_e194 * 8u) + (_e196 % 8u));
            local_15 = _e198;
            let _e199 = local_7;
            let _e201 = local;
            local_16 = ((_e199 * 8u) + (_e201 / 8u));
            let _e204 = local_9;
            if (_e198 >= _e204) {
            } else {
                let _e208 = global_2.member.member_1;
                local_17 = _e208;
                let _e209 = local_16;
                if (_e209 >= _e208) {
                } else {
                    let _e211 = local_16;
                    let _e212 = local_9;
                    let _e214 = local_15;
                    let _e215 = ((_e211 * _e212) + _e214);
                    local_18 = _e215;
                    let _e216 = local_3;
                    let _e217 = (_e215 < _e216);
                    local_19 = _e217;
                    if _e217 {
                    } else {
                        break;
                    }
                    let _e218 = local_18;
                    let _e221 = global_5.member[_e218];
                    let _e222 = bitcast<f32>(_e221);
                    local_20 = _e222;
                    let _e225 = ((bitcast<u32>(_e222) & 2147483647u) > 2139095040u);
                    local_21 = _e225;
                    let _e226 = !(_e225);
                    local_22 = _e226;
                    if _e226 {
                        let _e227 = local_18;
                        let _e228 = (3u * _e227);
                        local_23 = _e228;
                        let _e229 = local_1;
                        if (_e228 < _e229) {
                        } else {
                            break;
                        }
                        let _e231 = local_23;
                        let _e234 = global_4.member[_e231];
                        local_24 = bitcast<f32>(_e234);
                        let _e236 = local_23;
                        let _e237 = (_e236 + 1u);
                        local_25 = _e237;
                        let _e238 = local_1;
                        if (_e237 < _e238) {
                        } else {
                            break;
                        }
                        let _e240 = local_25;
                        let _e243 = global_4.member[_e240];
                        local_26 = bitcast<f32>(_e243);
                        let _e245 = local_23;
                        let _e246 = (_e245 + 2u);
                        local_27 = _e246;
                        let _e247 = local_1;
                        if (_e246 < _e247) {
                        } else {
                            break;
                        }
                        let _e249 = local_27;
                        let _e252 = global_4.member[_e249];
                        local_28 = bitcast<f32>(_e252);
                        let _e254 = local_24;
                        if (_e254 > 1267650600000000000000000000000f) {
                            let _e256 = local_24;
                            phi_211_ = select(true, false, (_e256 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_211_ = true;
                        }
                        let _e260 = phi_211_;
                        if _e260 {
                            let _e261 = local_24;
                            if (_e261 < 0.000000000000000000000000000000000000011754944f) {
                                let _e263 = local_24;
                                phi_225_ = select(true, false, (_e263 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_225_ = true;
                            }
                            let _e267 = phi_225_;
                            let _e268 = local_24;
                            phi_230_ = select(0f, _e268, _e267);
                        } else {
                            phi_230_ = 1267650600000000000000000000000f;
                        }
                        let _e271 = phi_230_;
                        local_29 = _e271;
                        let _e272 = local_26;
                        if (_e272 > 1267650600000000000000000000000f) {
                            let _e274 = local_26;
                            phi_240_ = select(true, false, (_e274 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_240_ = true;
                        }
                        let _e278 = phi_240_;
                        if _e278 {
                            let _e279 = local_26;
                            if (_e279 < 0.000000000000000000000000000000000000011754944f) {
                                let _e281 = local_26;
                                phi_254_ = select(true, false, (_e281 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_254_ = true;
                            }
                            let _e285 = phi_254_;
                            let _e286 = local_26;
                            phi_259_ = select(0f, _e286, _e285);
                        } else {
                            phi_259_ = 1267650600000000000000000000000f;
                        }
                        let _e289 = phi_259_;
                        local_30 = _e289;
                        let _e290 = local_28;
                        if (_e290 > 1267650600000000000000000000000f) {
                            let _e292 = local_28;
                            phi_269_ = select(true, false, (_e292 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_269_ = true;
                        }
                        let _e296 = phi_269_;
                        if _e296 {
                            let _e297 = local_28;
                            if (_e297 < 0.000000000000000000000000000000000000011754944f) {
                                let _e299 = local_28;
                                phi_283_ = select(true, false, (_e299 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_283_ = true;
                            }
                            let _e303 = phi_283_;
                            let _e304 = local_28;
                            phi_288_ = select(0f, _e304, _e303);
                        } else {
                            phi_288_ = 1267650600000000000000000000000f;
                        }
                        let _e307 = phi_288_;
                        let _e308 = local_29;
                        let _e309 = local_30;
                        phi_290_ = array<f32, 3>(_e308, _e309, _e307);
                    } else {
                        phi_290_ = array<f32, 3>(0f, 0f, 0f);
                    }
                    let _e312 = phi_290_;
                    local_31 = _e312;
                    let _e313 = local_22;
                    if _e313 {
                        let _e314 = local_18;
                        let _e315 = local_2;
                        if (_e314 < _e315) {
                        } else {
                            break;
                        }
                        let _e317 = local_18;
                        let _e320 = global_3.member[_e317];
                        phi_302_ = bitcast<f32>(_e320);
                    } else {
                        phi_302_ = 0f;
                    }
                    let _e323 = phi_302_;
                    local_32 = _e323;
                    let _e324 = local_12;
                    if (_e324 < 0.5f) {
                        phi_1175_ = _e312;
                    } else {
                        let _e326 = local_12;
                        let _e328 = local_12;
                        let _e329 = select(0.5f, _e328, (_e326 > 0.5f));
                        let _e332 = (1f / ((3.1415927f * _e329) * _e329));
                        local_33 = _e332;
                        let _e333 = type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, _e332);
                        local_34 = _e333;
                        let _e334 = local_19;
                        if _e334 {
                        } else {
                            break;
                        }
                        let _e335 = local_21;
                        if _e335 {
                            phi_615_ = _e333;
                        } else {
                            let _e336 = local_18;
                            let _e337 = local_2;
                            if (_e336 < _e337) {
                            } else {
                                break;
                            }
                            let _e339 = local_18;
                            let _e342 = global_3.member[_e339];
                            local_35 = bitcast<f32>(_e342);
                            let _e344 = local_20;
                            if (_e344 < 0f) {
                                let _e346 = local_20;
                                phi_367_ = -(_e346);
                            } else {
                                phi_367_ = _e222;
                            }
                            let _e349 = phi_367_;
                            let _e351 = select(0.5f, _e349, (_e349 > 0.5f));
                            let _e354 = (1f / ((3.1415927f * _e351) * _e351));
                            local_36 = _e354;
                            if (_e354 > 0f) {
                                let _e356 = local_18;
                                let _e357 = (3u * _e356);
                                local_37 = _e357;
                                let _e358 = local_1;
                                if (_e357 < _e358) {
                                } else {
                                    break;
                                }
                                let _e360 = local_37;
                                let _e363 = global_4.member[_e360];
                                local_38 = bitcast<f32>(_e363);
                                let _e365 = local_37;
                                let _e366 = (_e365 + 1u);
                                local_39 = _e366;
                                let _e367 = local_1;
                                if (_e366 < _e367) {
                                } else {
                                    break;
                                }
                                let _e369 = local_39;
                                let _e372 = global_4.member[_e369];
                                local_40 = bitcast<f32>(_e372);
                                let _e374 = local_37;
                                let _e375 = (_e374 + 2u);
                                local_41 = _e375;
                                let _e376 = local_1;
                                if (_e375 < _e376) {
                                } else {
                                    break;
                                }
                                let _e378 = local_41;
                                let _e381 = global_4.member[_e378];
                                local_42 = bitcast<f32>(_e381);
                                let _e383 = local_38;
                                if (_e383 > 1267650600000000000000000000000f) {
                                    let _e385 = local_38;
                                    phi_467_ = select(true, false, (_e385 <= 340282350000000000000000000000000000000f));
                                } else {
                                    phi_467_ = true;
                                }
                                let _e389 = phi_467_;
                                if _e389 {
                                    let _e390 = local_38;
                                    if (_e390 < 0.000000000000000000000000000000000000011754944f) {
                                        let _e392 = local_38;
                                        phi_481_ = select(true, false, (_e392 >= -340282350000000000000000000000000000000f));
                                    } else {
                                        phi_481_ = true;
                                    }
                                    let _e396 = phi_481_;
                                    let _e397 = local_38;
                                    phi_486_ = select(0f, _e397, _e396);
                                } else {
                                    phi_486_ = 1267650600000000000000000000000f;
                                }
                                let _e400 = phi_486_;
                                local_43 = _e400;
                                let _e401 = local_40;
                                if (_e401 > 1267650600000000000000000000000f) {
                                    let _e403 = local_40;
                                    phi_496_ = select(true, false, (_e403 <= 340282350000000000000000000000000000000f));
                                } else {
                                    phi_496_ = true;
                                }
                                let _e407 = phi_496_;
                                if _e407 {
                                    let _e408 = local_40;
                                    if (_e408 < 0.000000000000000000000000000000000000011754944f) {
                                        let _e410 = local_40;
                                        phi_510_ = select(true, false, (_e410 >= -340282350000000000000000000000000000000f));
                                    } else {
                                        phi_510_ = true;
                                    }
                                    let _e414 = phi_510_;
                                    let _e415 = local_40;
                                    phi_515_ = select(0f, _e415, _e414);
                                } else {
                                    phi_515_ = 1267650600000000000000000000000f;
                                }
                                let _e418 = phi_515_;
                                local_44 = _e418;
                                let _e419 = local_42;
                                if (_e419 > 1267650600000000000000000000000f) {
                                    let _e421 = local_42;
                                    phi_525_ = select(true, false, (_e421 <= 340282350000000000000000000000000000000f));
                                } else {
                                    phi_525_ = true;
                                }
                                let _e425 = phi_525_;
                                if _e425 {
                                    let _e426 = local_42;
                                    if (_e426 < 0.000000000000000000000000000000000000011754944f) {
                                        let _e428 = local_42;
                                        phi_539_ = select(true, false, (_e428 >= -340282350000000000000000000000000000000f));
                                    } else {
                                        phi_539_ = true;
                                    }
                                    let _e432 = phi_539_;
                                    let _e433 = local_42;
                                    phi_544_ = select(0f, _e433, _e432);
                                } else {
                                    phi_544_ = 1267650600000000000000000000000f;
                                }
                                let _e436 = phi_544_;
                                local_45 = _e436;
                                let _e437 = local_35;
                                let _e438 = bitcast<u32>(_e437);
                                local_46 = _e438;
                                let _e439 = local_14;
                                if (_e438 <= bitcast<u32>(_e439)) {
                                    phi_574_ = 0f;
                                } else {
                                    let _e442 = local_46;
                                    if (_e442 == 2139095040u) {
                                        phi_573_ = 1f;
                                    } else {
                                        let _e444 = local_35;
                                        let _e445 = local_14;
                                        let _e447 = local_14;
                                        let _e449 = ((_e444 - _e445) / (0.05f * _e447));
                                        let _e451 = select(0f, _e449, (_e449 > 0f));
                                        let _e453 = select(1f, _e451, (_e451 < 1f));
                                        phi_573_ = ((_e453 * _e453) * (3f - (2f * _e453)));
                                    }
                                    let _e459 = phi_573_;
                                    phi_574_ = _e459;
                                }
                                let _e461 = phi_574_;
                                let _e463 = local_36;
                                let _e464 = (_e463 * (1f - _e461));
                                let _e465 = local_36;
                                let _e466 = (_e465 * _e461);
                                let _e467 = local_31;
                                let _e469 = local_43;
                                let _e470 = (_e469 - _e467[0]);
                                let _e471 = local_31;
                                let _e473 = local_44;
                                let _e474 = (_e473 - _e471[1]);
                                let _e475 = local_31;
                                let _e477 = local_45;
                                let _e478 = (_e477 - _e475[2]);
                                let _e483 = local_34;
                                let _e489 = type_16(array<f32, 3>((_e464 * _e470), (_e464 * _e474), (_e464 * _e478)), _e483.member_1, _e483.member_2, _e483.member_3, _e483.member_4);
                                let _e495 = type_16(_e489.member, _e464, _e489.member_2, _e489.member_3, _e489.member_4);
                                let _e505 = type_16(_e495.member, _e495.member_1, array<f32, 3>((_e466 * _e470), (_e466 * _e474), (_e466 * _e478)), _e495.member_3, _e495.member_4);
                                phi_614_ = type_16(_e505.member, _e505.member_1, _e505.member_2, _e466, _e505.member_4);
                            } else {
                                phi_614_ = _e333;
                            }
                            let _e513 = phi_614_;
                            phi_615_ = _e513;
                        }
                        let _e515 = phi_615_;
                        let _e518 = global_2.member.member_2;
                        let _e520 = select(_e518, 1u, (_e518 == 0u));
                        local_100 = _e520;
                        let _e522 = local_12;
                        local_47 = (_e522 / f32(_e520));
                        let _e524 = local_15;
                        let _e525 = f32(_e524);
                        local_48 = _e525;
                        local_49 = (_e525 + 0.5f);
                        let _e527 = local_16;
                        let _e528 = f32(_e527);
                        local_50 = _e528;
                        local_51 = (_e528 + 0.5f);
                        let _e530 = local_9;
                        local_52 = f32((_e530 - 1u));
                        let _e533 = local_17;
                        local_53 = f32((_e533 - 1u));
                        phi_1238_ = false;
                        phi_640_ = _e515;
                        phi_643_ = 1u;
                        loop {
                            let _e537 = phi_1238_;
                            let _e539 = phi_640_;
                            let _e541 = phi_643_;
                            local_54 = _e539;
                            local_55 = _e541;
                            let _e542 = local_55;
                            let _e543 = local_100;
                            let _e544 = (_e542 <= _e543);
                            local_56 = _e544;
                            if _e544 {
                                let _e545 = local_55;
                                let _e546 = (8u * _e545);
                                local_57 = _e546;
                                let _e548 = (3.1415927f / f32(_e546));
                                let _e549 = (_e548 * _e548);
                                let _e561 = (_e548 * (1f - ((_e549 * 0.16666667f) * (1f - ((_e549 * 0.05f) * (1f - ((_e549 * 0.023809524f) * (1f - (_e549 * 0.013888889f)))))))));
                                let _e572 = (1f - ((_e549 * 0.5f) * (1f - ((_e549 * 0.083333336f) * (1f - ((_e549 * 0.033333335f) * (1f - (_e549 * 0.017857144f))))))));
                                local_58 = ((_e572 * _e572) - (_e561 * _e561));
                                local_59 = ((2f * _e572) * _e561);
                                let _e578 = local_55;
                                let _e580 = local_47;
                                local_60 = (_e580 * f32(_e578));
                                phi_693_ = _e539;
                                phi_696_ = 0u;
                                phi_698_ = _e561;
                                phi_700_ = _e572;
                                loop {
                                    let _e583 = phi_693_;
                                    let _e585 = phi_696_;
                                    let _e587 = phi_698_;
                                    let _e589 = phi_700_;
                                    local_61 = _e583;
                                    local_62 = _e585;
                                    local_63 = _e587;
                                    local_64 = _e589;
                                    local_103 = _e583;
                                    let _e590 = local_62;
                                    let _e591 = local_57;
                                    let _e592 = (_e590 < _e591);
                                    local_65 = _e592;
                                    if _e592 {
                                        let _e593 = local_60;
                                        let _e594 = local_64;
                                        let _e596 = local_49;
                                        let _e598 = floor((_e596 + (_e593 * _e594)));
                                        let _e600 = select(0f, _e598, (_e598 > 0f));
                                        let _e601 = local_52;
                                        let _e603 = local_52;
                                        let _e604 = select(_e603, _e600, (_e600 < _e601));
                                        let _e605 = local_60;
                                        let _e606 = local_63;
                                        let _e608 = local_51;
                                        let _e610 = floor((_e608 + (_e605 * _e606)));
                                        let _e612 = select(0f, _e610, (_e610 > 0f));
                                        let _e613 = local_53;
                                        let _e615 = local_53;
                                        let _e616 = select(_e615, _e612, (_e612 < _e613));
                                        let _e617 = local_48;
                                        let _e618 = (_e604 - _e617);
                                        let _e619 = local_50;
                                        let _e620 = (_e616 - _e619);
                                        let _e624 = sqrt(((_e618 * _e618) + (_e620 * _e620)));
                                        local_66 = _e624;
                                        let _e631 = local_9;
                                        local_67 = ((select(select(u32(_e616), 0u, !((_e616 >= 0f))), 4294967295u, (_e616 > 4294967000f)) * _e631) + select(select(u32(_e604), 0u, !((_e604 >= 0f))), 4294967295u, (_e604 > 4294967000f)));
                                        let _e640 = (_e624 == 0f);
                                        local_68 = _e640;
                                        if _e640 {
                                            phi_785_ = 1f;
                                        } else {
                                            let _e641 = local_12;
                                            let _e642 = local_66;
                                            let _e644 = ((_e641 - _e642) + 0.5f);
                                            let _e646 = select(0f, _e644, (_e644 > 0f));
                                            phi_785_ = select(1f, _e646, (_e646 < 1f));
                                        }
                                        let _e650 = phi_785_;
                                        let _e651 = local_33;
                                        let _e653 = local_61;
                                        let _e655 = (_e653.member_4 + (_e651 * _e650));
                                        local_69 = _e655;
                                        let _e656 = local_61;
                                        let _e662 = type_16(_e656.member, _e656.member_1, _e656.member_2, _e656.member_3, _e655);
                                        let _e663 = local_67;
                                        let _e664 = local_3;
                                        if (_e663 < _e664) {
                                        } else {
                                            phi_1228_ = true;
                                            break;
                                        }
                                        let _e666 = local_67;
                                        let _e669 = global_5.member[_e666];
                                        let _e670 = bitcast<f32>(_e669);
                                        local_70 = _e670;
                                        if ((bitcast<u32>(_e670) & 2147483647u) > 2139095040u) {
                                            phi_1065_ = _e662;
                                        } else {
                                            let _e674 = local_67;
                                            let _e675 = local_2;
                                            if (_e674 < _e675) {
                                            } else {
                                                phi_1228_ = true;
                                                break;
                                            }
                                            let _e677 = local_67;
                                            let _e680 = global_3.member[_e677];
                                            local_71 = bitcast<f32>(_e680);
                                            let _e682 = local_70;
                                            if (_e682 < 0f) {
                                                let _e684 = local_70;
                                                phi_817_ = -(_e684);
                                            } else {
                                                phi_817_ = _e670;
                                            }
                                            let _e687 = phi_817_;
                                            local_72 = _e687;
                                            let _e688 = local_21;
                                            if _e688 {
                                                phi_843_ = f32();
                                                phi_844_ = true;
                                            } else {
                                                let _e689 = local_71;
                                                let _e691 = local_32;
                                                let _e693 = (bitcast<u32>(_e689) > bitcast<u32>(_e691));
                                                local_73 = _e693;
                                                if _e693 {
                                                    let _e694 = local_20;
                                                    if (_e694 >= 0f) {
                                                        let _e698 = local_72;
                                                        let _e699 = local_20;
                                                        let _e701 = local_72;
                                                        let _e702 = local_20;
                                                        phi_840_ = select(_e702, _e701, (_e698 < _e699));
                                                    } else {
                                                        let _e696 = local_20;
                                                        phi_840_ = -(_e696);
                                                    }
                                                    let _e705 = phi_840_;
                                                    phi_841_ = _e705;
                                                } else {
                                                    phi_841_ = f32();
                                                }
                                                let _e707 = phi_841_;
                                                let _e708 = local_73;
                                                phi_843_ = _e707;
                                                phi_844_ = select(true, false, _e708);
                                            }
                                            let _e711 = phi_843_;
                                            let _e713 = phi_844_;
                                            let _e714 = local_72;
                                            local_101 = select(_e711, _e714, _e713);
                                            let _e716 = local_68;
                                            if _e716 {
                                                phi_865_ = 1f;
                                            } else {
                                                let _e717 = local_101;
                                                let _e718 = local_66;
                                                let _e720 = ((_e717 - _e718) + 0.5f);
                                                let _e722 = select(0f, _e720, (_e720 > 0f));
                                                phi_865_ = select(1f, _e722, (_e722 < 1f));
                                            }
                                            let _e726 = phi_865_;
                                            let _e727 = local_72;
                                            let _e729 = local_72;
                                            let _e730 = select(0.5f, _e729, (_e727 > 0.5f));
                                            let _e734 = (_e726 * (1f / ((3.1415927f * _e730) * _e730)));
                                            local_74 = _e734;
                                            if (_e734 > 0f) {
                                                let _e736 = local_67;
                                                let _e737 = (3u * _e736);
                                                local_75 = _e737;
                                                let _e738 = local_1;
                                                if (_e737 < _e738) {
                                                } else {
                                                    phi_1228_ = true;
                                                    break;
                                                }
                                                let _e740 = local_75;
                                                let _e743 = global_4.member[_e740];
                                                local_76 = bitcast<f32>(_e743);
                                                let _e745 = local_75;
                                                let _e746 = (_e745 + 1u);
                                                local_77 = _e746;
                                                let _e747 = local_1;
                                                if (_e746 < _e747) {
                                                } else {
                                                    phi_1228_ = true;
                                                    break;
                                                }
                                                let _e749 = local_77;
                                                let _e752 = global_4.member[_e749];
                                                local_78 = bitcast<f32>(_e752);
                                                let _e754 = local_75;
                                                let _e755 = (_e754 + 2u);
                                                local_79 = _e755;
                                                let _e756 = local_1;
                                                if (_e755 < _e756) {
                                                } else {
                                                    phi_1228_ = true;
                                                    break;
                                                }
                                                let _e758 = local_79;
                                                let _e761 = global_4.member[_e758];
                                                local_80 = bitcast<f32>(_e761);
                                                let _e763 = local_76;
                                                if (_e763 > 1267650600000000000000000000000f) {
                                                    let _e765 = local_76;
                                                    phi_917_ = select(true, false, (_e765 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_917_ = true;
                                                }
                                                let _e769 = phi_917_;
                                                if _e769 {
                                                    let _e770 = local_76;
                                                    if (_e770 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e772 = local_76;
                                                        phi_931_ = select(true, false, (_e772 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_931_ = true;
                                                    }
                                                    let _e776 = phi_931_;
                                                    let _e777 = local_76;
                                                    phi_936_ = select(0f, _e777, _e776);
                                                } else {
                                                    phi_936_ = 1267650600000000000000000000000f;
                                                }
                                                let _e780 = phi_936_;
                                                local_81 = _e780;
                                                let _e781 = local_78;
                                                if (_e781 > 1267650600000000000000000000000f) {
                                                    let _e783 = local_78;
                                                    phi_946_ = select(true, false, (_e783 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_946_ = true;
                                                }
                                                let _e787 = phi_946_;
                                                if _e787 {
                                                    let _e788 = local_78;
                                                    if (_e788 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e790 = local_78;
                                                        phi_960_ = select(true, false, (_e790 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_960_ = true;
                                                    }
                                                    let _e794 = phi_960_;
                                                    let _e795 = local_78;
                                                    phi_965_ = select(0f, _e795, _e794);
                                                } else {
                                                    phi_965_ = 1267650600000000000000000000000f;
                                                }
                                                let _e798 = phi_965_;
                                                local_82 = _e798;
                                                let _e799 = local_80;
                                                if (_e799 > 1267650600000000000000000000000f) {
                                                    let _e801 = local_80;
                                                    phi_975_ = select(true, false, (_e801 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_975_ = true;
                                                }
                                                let _e805 = phi_975_;
                                                if _e805 {
                                                    let _e806 = local_80;
                                                    if (_e806 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e808 = local_80;
                                                        phi_989_ = select(true, false, (_e808 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_989_ = true;
                                                    }
                                                    let _e812 = phi_989_;
                                                    let _e813 = local_80;
                                                    phi_994_ = select(0f, _e813, _e812);
                                                } else {
                                                    phi_994_ = 1267650600000000000000000000000f;
                                                }
                                                let _e816 = phi_994_;
                                                local_83 = _e816;
                                                let _e817 = local_71;
                                                let _e818 = bitcast<u32>(_e817);
                                                local_84 = _e818;
                                                let _e819 = local_14;
                                                if (_e818 <= bitcast<u32>(_e819)) {
                                                    phi_1024_ = 0f;
                                                } else {
                                                    let _e822 = local_84;
                                                    if (_e822 == 2139095040u) {
                                                        phi_1023_ = 1f;
                                                    } else {
                                                        let _e824 = local_71;
                                                        let _e825 = local_14;
                                                        let _e827 = local_14;
                                                        let _e829 = ((_e824 - _e825) / (0.05f * _e827));
                                                        let _e831 = select(0f, _e829, (_e829 > 0f));
                                                        let _e833 = select(1f, _e831, (_e831 < 1f));
                                                        phi_1023_ = ((_e833 * _e833) * (3f - (2f * _e833)));
                                                    }
                                                    let _e839 = phi_1023_;
                                                    phi_1024_ = _e839;
                                                }
                                                let _e841 = phi_1024_;
                                                let _e843 = local_74;
                                                let _e844 = (_e843 * (1f - _e841));
                                                let _e845 = local_74;
                                                let _e846 = (_e845 * _e841);
                                                let _e847 = local_31;
                                                let _e849 = local_81;
                                                let _e850 = (_e849 - _e847[0]);
                                                let _e851 = local_31;
                                                let _e853 = local_82;
                                                let _e854 = (_e853 - _e851[1]);
                                                let _e855 = local_31;
                                                let _e857 = local_83;
                                                let _e858 = (_e857 - _e855[2]);
                                                let _e859 = local_61;
                                                let _e864 = local_61;
                                                let _e869 = local_61;
                                                let _e875 = local_61;
                                                let _e878 = local_61;
                                                let _e883 = local_61;
                                                let _e888 = local_61;
                                                let _e894 = local_61;
                                                let _e897 = local_69;
                                                phi_1064_ = type_16(array<f32, 3>((_e859.member[0] + (_e844 * _e850)), (_e864.member[1] + (_e844 * _e854)), (_e869.member[2] + (_e844 * _e858))), (_e875.member_1 + _e844), array<f32, 3>((_e878.member_2[0] + (_e846 * _e850)), (_e883.member_2[1] + (_e846 * _e854)), (_e888.member_2[2] + (_e846 * _e858))), (_e894.member_3 + _e846), _e897);
                                            } else {
                                                phi_1064_ = _e662;
                                            }
                                            let _e900 = phi_1064_;
                                            phi_1065_ = _e900;
                                        }
                                        let _e902 = phi_1065_;
                                        let _e903 = local_64;
                                        let _e904 = local_58;
                                        let _e906 = local_63;
                                        let _e907 = local_59;
                                        let _e910 = local_64;
                                        let _e911 = local_59;
                                        let _e913 = local_63;
                                        let _e914 = local_58;
                                        let _e917 = local_62;
                                        phi_694_ = _e902;
                                        phi_697_ = (_e917 + 1u);
                                        phi_699_ = ((_e910 * _e911) + (_e913 * _e914));
                                        phi_701_ = ((_e903 * _e904) - (_e906 * _e907));
                                    } else {
                                        phi_694_ = type_16();
                                        phi_697_ = u32();
                                        phi_699_ = f32();
                                        phi_701_ = f32();
                                    }
                                    let _e920 = phi_694_;
                                    let _e922 = phi_697_;
                                    let _e924 = phi_699_;
                                    let _e926 = phi_701_;
                                    continue;
                                    continuing {
                                        let _e927 = local_65;
                                        phi_693_ = _e920;
                                        phi_696_ = _e922;
                                        phi_698_ = _e924;
                                        phi_700_ = _e926;
                                        phi_1228_ = _e537;
                                        break if !(_e927);
                                    }
                                }
                                let _e930 = phi_1228_;
                                phi_1334_ = _e930;
                                if _e930 {
                                    break;
                                }
                                let _e931 = local_55;
                                phi_1335_ = _e930;
                                let _e1155 = local_103;
                                phi_641_ = _e1155;
                                phi_644_ = (_e931 + 1u);
                            } else {
                                phi_1335_ = _e537;
                                phi_641_ = type_16();
                                phi_644_ = u32();
                            }
                            let _e934 = phi_1335_;
                            let _e936 = phi_641_;
                            let _e938 = phi_644_;
                            continue;
                            continuing {
                                let _e939 = local_56;
                                phi_1238_ = _e934;
                                phi_640_ = _e936;
                                phi_643_ = _e938;
                                phi_1334_ = _e934;
                                break if !(_e939);
                            }
                        }
                        let _e942 = phi_1334_;
                        if _e942 {
                            break;
                        }
                        let _e943 = local_54;
                        local_85 = _e943.member;
                        let _e945 = local_54;
                        local_86 = _e945.member_1;
                        if (_e945.member_1 > 0f) {
                            let _e948 = local_86;
                            let _e949 = (1f / _e948);
                            let _e950 = local_31;
                            let _e952 = local_85;
                            let _e956 = local_31;
                            let _e958 = local_85;
                            let _e962 = local_31;
                            let _e964 = local_85;
                            phi_1094_ = array<f32, 3>((_e950[0] + (_e952[0] * _e949)), (_e956[1] + (_e958[1] * _e949)), (_e962[2] + (_e964[2] * _e949)));
                        } else {
                            phi_1094_ = _e312;
                        }
                        let _e970 = phi_1094_;
                        local_87 = _e970;
                        let _e971 = local_54;
                        local_88 = _e971.member_2;
                        let _e973 = local_54;
                        local_89 = _e973.member_3;
                        if (_e973.member_3 > 0f) {
                            let _e976 = local_89;
                            let _e977 = (1f / _e976);
                            let _e978 = local_31;
                            let _e980 = local_88;
                            let _e984 = local_31;
                            let _e986 = local_88;
                            let _e990 = local_31;
                            let _e992 = local_88;
                            phi_1115_ = array<f32, 3>((_e978[0] + (_e980[0] * _e977)), (_e984[1] + (_e986[1] * _e977)), (_e990[2] + (_e992[2] * _e977)));
                        } else {
                            phi_1115_ = _e312;
                        }
                        let _e998 = phi_1115_;
                        local_90 = _e998;
                        let _e999 = local_54;
                        let _e1001 = (1f / _e999.member_4);
                        let _e1002 = local_86;
                        let _e1003 = (_e1002 * _e1001);
                        let _e1005 = select(0f, _e1003, (_e1003 > 0f));
                        let _e1007 = select(1f, _e1005, (_e1005 < 1f));
                        let _e1008 = (1f - _e1007);
                        let _e1009 = local_89;
                        let _e1010 = (_e1009 * _e1001);
                        let _e1012 = select(_e1010, _e1008, (_e1008 < _e1010));
                        local_102 = _e1012;
                        let _e1013 = (_e1007 + _e1012);
                        local_91 = _e1013;
                        if (_e1013 > 0f) {
                            let _e1015 = local_102;
                            let _e1016 = local_91;
                            let _e1017 = (_e1015 / _e1016);
                            local_92 = _e1017;
                            let _e1018 = (_e1017 >= 1f);
                            if _e1018 {
                                phi_1167_ = array<f32, 3>();
                            } else {
                                let _e1019 = local_87;
                                let _e1021 = local_90;
                                let _e1024 = local_92;
                                let _e1027 = local_87;
                                let _e1029 = local_90;
                                let _e1032 = local_92;
                                let _e1035 = local_87;
                                let _e1037 = local_90;
                                let _e1040 = local_92;
                                phi_1167_ = array<f32, 3>((_e1019[0] + (_e1024 * (_e1021[0] - _e1019[0]))), (_e1027[1] + (_e1032 * (_e1029[1] - _e1027[1]))), (_e1035[2] + (_e1040 * (_e1037[2] - _e1035[2]))));
                            }
                            let _e1045 = phi_1167_;
                            phi_1168_ = _e998;
                            phi_1169_ = _e1045;
                            phi_1170_ = _e1018;
                        } else {
                            phi_1168_ = _e970;
                            phi_1169_ = array<f32, 3>();
                            phi_1170_ = true;
                        }
                        let _e1047 = phi_1168_;
                        let _e1049 = phi_1169_;
                        let _e1051 = phi_1170_;
                        if _e1051 {
                            phi_1174_ = _e1047;
                        } else {
                            phi_1174_ = _e1049;
                        }
                        let _e1053 = phi_1174_;
                        phi_1175_ = _e1053;
                    }
                    let _e1055 = phi_1175_;
                    local_93 = _e1055;
                    let _e1056 = local_18;
                    let _e1057 = (3u * _e1056);
                    local_94 = _e1057;
                    local_95 = bitcast<u32>(select(0f, _e1055[0], (_e1055[0] > 0f)));
                    let _e1062 = local_5;
                    if (_e1057 < _e1062) {
                    } else {
                        break;
                    }
                    let _e1064 = local_94;
                    let _e1067 = local_95;
                    global_7.member[_e1064] = _e1067;
                    let _e1068 = local_94;
                    let _e1069 = (_e1068 + 1u);
                    local_96 = _e1069;
                    let _e1070 = local_93;
                    local_97 = bitcast<u32>(select(0f, _e1070[1], (_e1070[1] > 0f)));
                    let _e1075 = local_5;
                    if (_e1069 < _e1075) {
                    } else {
                        break;
                    }
                    let _e1077 = local_96;
                    let _e1080 = local_97;
                    global_7.member[_e1077] = _e1080;
                    let _e1081 = local_94;
                    let _e1082 = (_e1081 + 2u);
                    local_98 = _e1082;
                    let _e1083 = local_93;
                    local_99 = bitcast<u32>(select(0f, _e1083[2], (_e1083[2] > 0f)));
                    let _e1088 = local_5;
                    if (_e1082 < _e1088) {
                    } else {
                        break;
                    }
                    let _e1090 = local_98;
                    let _e1093 = local_99;
                    global_7.member[_e1090] = _e1093;
                }
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn scatter_gather(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
