struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_15 {
    member: type_5,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: array<u32, 2>,
}

struct type_16 {
    member: type_15,
}

struct type_24 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_16;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_24;
var<private> global_8: u32 = 2143289344u;
var<private> global_9: u32 = 2139095040u;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: i32;
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: bool;
    var local_12: u32;
    var local_13: bool;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: f32;
    var local_19: u32;
    var local_20: u32;
    var local_21: f32;
    var local_22: f32;
    var local_23: u32;
    var local_24: u32;
    var local_25: bool;
    var local_26: f32;
    var local_27: f32;
    var local_28: f32;
    var local_29: f32;
    var local_30: f32;
    var local_31: f32;
    var local_32: f32;
    var local_33: f32;
    var local_34: f32;
    var local_35: f32;
    var local_36: bool;
    var local_37: i32;
    var local_38: u32;
    var local_39: u32;
    var local_40: f32;
    var local_41: f32;
    var local_42: u32;
    var local_43: u32;
    var local_44: bool;
    var local_45: f32;
    var local_46: f32;
    var local_47: f32;
    var local_48: f32;
    var local_49: f32;
    var local_50: f32;
    var local_51: f32;
    var local_52: f32;
    var local_53: f32;
    var local_54: f32;
    var local_55: bool;
    var local_56: i32;
    var local_57: u32;
    var local_58: u32;
    var local_59: f32;
    var local_60: f32;
    var local_61: u32;
    var local_62: u32;
    var local_63: bool;
    var local_64: f32;
    var local_65: f32;
    var local_66: f32;
    var local_67: f32;
    var local_68: f32;
    var local_69: f32;
    var local_70: f32;
    var local_71: f32;
    var local_72: f32;
    var local_73: f32;
    var local_74: bool;
    var local_75: i32;
    var local_76: u32;
    var local_77: u32;
    var local_78: f32;
    var local_79: f32;
    var local_80: u32;
    var local_81: u32;
    var local_82: bool;
    var local_83: f32;
    var local_84: f32;
    var local_85: f32;
    var local_86: f32;
    var local_87: f32;
    var local_88: f32;
    var local_89: f32;
    var local_90: f32;
    var local_91: f32;
    var local_92: f32;
    var local_93: bool;
    var local_94: u32;
    var phi_126_: u32;
    var phi_193_: f32;
    var phi_241_: f32;
    var phi_267_: f32;
    var phi_275_: bool;
    var phi_277_: bool;
    var phi_287_: bool;
    var phi_315_: f32;
    var phi_316_: f32;
    var phi_322_: f32;
    var phi_329_: bool;
    var phi_357_: f32;
    var phi_358_: f32;
    var phi_364_: f32;
    var phi_381_: bool;
    var phi_386_: f32;
    var phi_413_: i32;
    var phi_414_: i32;
    var phi_416_: i32;
    var phi_417_: bool;
    var phi_422_: i32;
    var phi_607_: i32;
    var phi_653_: f32;
    var phi_857_: f32;
    var phi_865_: bool;
    var phi_867_: bool;
    var phi_877_: bool;
    var phi_905_: f32;
    var phi_906_: f32;
    var phi_912_: f32;
    var phi_919_: bool;
    var phi_947_: f32;
    var phi_948_: f32;
    var phi_954_: f32;
    var phi_971_: bool;
    var phi_976_: f32;
    var phi_1003_: i32;
    var phi_1004_: i32;
    var phi_1006_: i32;
    var phi_1007_: bool;
    var phi_1012_: i32;
    var phi_1019_: i32;
    var phi_1068_: f32;
    var phi_1094_: f32;
    var phi_1102_: bool;
    var phi_1104_: bool;
    var phi_1114_: bool;
    var phi_1142_: f32;
    var phi_1143_: f32;
    var phi_1149_: f32;
    var phi_1156_: bool;
    var phi_1184_: f32;
    var phi_1185_: f32;
    var phi_1191_: f32;
    var phi_1208_: bool;
    var phi_1213_: f32;
    var phi_1240_: i32;
    var phi_1241_: i32;
    var phi_1243_: i32;
    var phi_1244_: bool;
    var phi_1249_: i32;
    var phi_1434_: i32;
    var phi_1481_: f32;
    var phi_1685_: f32;
    var phi_1693_: bool;
    var phi_1695_: bool;
    var phi_1705_: bool;
    var phi_1733_: f32;
    var phi_1734_: f32;
    var phi_1740_: f32;
    var phi_1747_: bool;
    var phi_1775_: f32;
    var phi_1776_: f32;
    var phi_1782_: f32;
    var phi_1799_: bool;
    var phi_1804_: f32;
    var phi_1831_: i32;
    var phi_1832_: i32;
    var phi_1834_: i32;
    var phi_1835_: bool;
    var phi_1840_: i32;
    var phi_1847_: i32;
    var phi_127_: u32;
    var phi_1898_: bool;

    let _e131 = global_8;
    let _e132 = bitcast<f32>(_e131);
    let _e133 = global_9;
    let _e134 = bitcast<f32>(_e133);
    switch bitcast<i32>(0u) {
        default: {
            let _e136 = global;
            local = _e136;
            let _e137 = global_1;
            let _e138 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e151 = global_3.member.member_1;
            local_5 = _e151;
            let _e154 = global_3.member.member_2;
            local_6 = _e154;
            local_7 = bitcast<i32>(select(_e154, _e151, (_e151 > _e154)));
            local_8 = (_e151 * _e154);
            local_9 = (_e138.x * 256u);
            phi_126_ = (_e137.x * 256u);
            loop {
                let _e162 = phi_126_;
                local_10 = _e162;
                let _e163 = local_10;
                let _e164 = local_8;
                let _e165 = (_e163 < _e164);
                local_11 = _e165;
                if _e165 {
                    let _e166 = local_10;
                    let _e167 = local;
                    let _e168 = (_e166 + _e167);
                    local_12 = _e168;
                    let _e169 = local_8;
                    if (_e168 < _e169) {
                        let _e171 = local_5;
                        let _e172 = (_e171 == 0u);
                        local_13 = _e172;
                        if _e172 {
                            phi_1898_ = true;
                            break;
                        }
                        let _e173 = local_12;
                        let _e174 = local_5;
                        local_14 = (_e173 % _e174);
                        let _e176 = local_13;
                        if _e176 {
                            phi_1898_ = true;
                            break;
                        }
                        let _e177 = local_12;
                        let _e178 = local_5;
                        local_15 = (_e177 / _e178);
                        let _e182 = global_3.member.member_3;
                        local_16 = _e182;
                        let _e183 = local_12;
                        let _e184 = local_2;
                        if (_e183 < _e184) {
                        } else {
                            phi_1898_ = true;
                            break;
                        }
                        let _e186 = local_12;
                        let _e189 = global_5.member[_e186];
                        if (_e189 > 0u) {
                            let _e191 = local_12;
                            let _e192 = local_16;
                            let _e195 = ((5u * (_e191 * _e192)) + 3u);
                            local_17 = _e195;
                            let _e196 = local_1;
                            if (_e195 < _e196) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e198 = local_17;
                            let _e201 = global_4.member[_e198];
                            phi_193_ = bitcast<f32>(_e201);
                        } else {
                            phi_193_ = _e134;
                        }
                        let _e204 = phi_193_;
                        local_18 = _e204;
                        let _e205 = local_14;
                        let _e207 = local_5;
                        if ((_e205 + 1u) < _e207) {
                            let _e209 = local_12;
                            let _e210 = (_e209 + 1u);
                            local_19 = _e210;
                            let _e211 = local_2;
                            if (_e210 < _e211) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e213 = local_19;
                            let _e216 = global_5.member[_e213];
                            if (_e216 > 0u) {
                                let _e218 = local_19;
                                let _e219 = local_16;
                                let _e222 = ((5u * (_e218 * _e219)) + 3u);
                                local_20 = _e222;
                                let _e223 = local_1;
                                if (_e222 < _e223) {
                                } else {
                                    phi_1898_ = true;
                                    break;
                                }
                                let _e225 = local_20;
                                let _e228 = global_4.member[_e225];
                                phi_241_ = bitcast<f32>(_e228);
                            } else {
                                phi_241_ = _e134;
                            }
                            let _e231 = phi_241_;
                            local_21 = _e231;
                            let _e234 = global_3.member.member_5;
                            local_22 = _e234;
                            let _e235 = local_18;
                            let _e236 = bitcast<u32>(_e235);
                            local_23 = _e236;
                            let _e239 = bitcast<u32>(_e231);
                            local_24 = _e239;
                            local_25 = ((_e239 & 2139095040u) != 2139095040u);
                            if ((_e236 & 2139095040u) != 2139095040u) {
                                let _e244 = local_25;
                                if _e244 {
                                    let _e245 = local_18;
                                    let _e246 = local_21;
                                    let _e247 = (_e245 - _e246);
                                    local_26 = _e247;
                                    if (_e247 < 0f) {
                                        let _e249 = local_26;
                                        phi_267_ = -(_e249);
                                    } else {
                                        phi_267_ = _e247;
                                    }
                                    let _e252 = phi_267_;
                                    let _e253 = local_18;
                                    let _e254 = local_21;
                                    let _e256 = local_18;
                                    let _e257 = local_21;
                                    let _e259 = local_22;
                                    phi_275_ = (_e252 > (_e259 * select(_e257, _e256, (_e253 < _e254))));
                                } else {
                                    phi_275_ = true;
                                }
                                let _e263 = phi_275_;
                                phi_277_ = _e263;
                            } else {
                                let _e242 = local_25;
                                phi_277_ = (_e242 != false);
                            }
                            let _e265 = phi_277_;
                            if _e265 {
                                let _e266 = local_23;
                                if (_e266 == 0u) {
                                    phi_287_ = false;
                                } else {
                                    let _e268 = local_23;
                                    phi_287_ = (_e268 <= 2139095040u);
                                }
                                let _e271 = phi_287_;
                                if _e271 {
                                    let _e275 = global_3.member.member.member_1;
                                    let _e280 = global_3.member.member.member;
                                    let _e285 = global_3.member.member.member_2;
                                    local_27 = _e285;
                                    let _e291 = global_3.member.member.member_3;
                                    let _e292 = ((((2f * _e275) * _e280) / (_e285 - _e280)) * _e291);
                                    local_28 = _e292;
                                    if (_e292 == 0f) {
                                        phi_315_ = 0f;
                                    } else {
                                        let _e294 = local_27;
                                        let _e295 = local_18;
                                        let _e298 = local_28;
                                        phi_315_ = (_e298 * (1f - (_e294 / _e295)));
                                    }
                                    let _e301 = phi_315_;
                                    phi_316_ = _e301;
                                } else {
                                    phi_316_ = _e132;
                                }
                                let _e303 = phi_316_;
                                local_29 = _e303;
                                if (_e303 < 0f) {
                                    let _e305 = local_29;
                                    phi_322_ = -(_e305);
                                } else {
                                    phi_322_ = _e303;
                                }
                                let _e308 = phi_322_;
                                local_30 = _e308;
                                let _e309 = local_24;
                                if (_e309 == 0u) {
                                    phi_329_ = false;
                                } else {
                                    let _e311 = local_24;
                                    phi_329_ = (_e311 <= 2139095040u);
                                }
                                let _e314 = phi_329_;
                                if _e314 {
                                    let _e318 = global_3.member.member.member_1;
                                    let _e323 = global_3.member.member.member;
                                    let _e328 = global_3.member.member.member_2;
                                    local_31 = _e328;
                                    let _e334 = global_3.member.member.member_3;
                                    let _e335 = ((((2f * _e318) * _e323) / (_e328 - _e323)) * _e334);
                                    local_32 = _e335;
                                    if (_e335 == 0f) {
                                        phi_357_ = 0f;
                                    } else {
                                        let _e337 = local_31;
                                        let _e338 = local_21;
                                        let _e341 = local_32;
                                        phi_357_ = (_e341 * (1f - (_e337 / _e338)));
                                    }
                                    let _e344 = phi_357_;
                                    phi_358_ = _e344;
                                } else {
                                    phi_358_ = _e132;
                                }
                                let _e346 = phi_358_;
                                local_33 = _e346;
                                if (_e346 < 0f) {
                                    let _e348 = local_33;
                                    phi_364_ = -(_e348);
                                } else {
                                    phi_364_ = _e346;
                                }
                                let _e351 = phi_364_;
                                local_34 = _e351;
                                let _e352 = local_30;
                                if ((bitcast<u32>(_e352) & 2147483647u) > 2139095040u) {
                                    phi_386_ = _e351;
                                } else {
                                    let _e356 = local_34;
                                    if ((bitcast<u32>(_e356) & 2147483647u) > 2139095040u) {
                                        phi_381_ = true;
                                    } else {
                                        let _e360 = local_30;
                                        let _e361 = local_34;
                                        phi_381_ = (_e360 > _e361);
                                    }
                                    let _e364 = phi_381_;
                                    let _e365 = local_30;
                                    let _e366 = local_34;
                                    phi_386_ = select(_e366, _e365, _e364);
                                }
                                let _e369 = phi_386_;
                                let _e371 = ceil((_e369 * 0.5f));
                                local_35 = _e371;
                                if ((bitcast<u32>(_e371) & 2139095040u) != 2139095040u) {
                                    let _e375 = local_7;
                                    let _e377 = local_35;
                                    let _e378 = (_e377 < f32(_e375));
                                    local_36 = _e378;
                                    if _e378 {
                                        let _e379 = local_35;
                                        if (_e379 < 0f) {
                                            phi_413_ = 0i;
                                        } else {
                                            let _e381 = local_35;
                                            let _e383 = local_35;
                                            let _e386 = local_35;
                                            let _e390 = local_35;
                                            let _e391 = local_35;
                                            phi_413_ = select(0i, select(select(i32(_e381), i32(-2147483648), !((_e383 >= -2147483600f))), 2147483647i, (_e386 > 2147483500f)), (_e390 == _e391));
                                        }
                                        let _e395 = phi_413_;
                                        phi_414_ = _e395;
                                    } else {
                                        phi_414_ = i32();
                                    }
                                    let _e397 = phi_414_;
                                    let _e398 = local_36;
                                    phi_416_ = _e397;
                                    phi_417_ = select(true, false, _e398);
                                } else {
                                    phi_416_ = i32();
                                    phi_417_ = true;
                                }
                                let _e401 = phi_416_;
                                let _e403 = phi_417_;
                                let _e404 = local_7;
                                phi_422_ = select(_e401, _e404, _e403);
                            } else {
                                phi_422_ = -1i;
                            }
                            let _e407 = phi_422_;
                            phi_607_ = select(_e407, -1i, (_e407 < -1i));
                        } else {
                            phi_607_ = -1i;
                        }
                        let _e411 = phi_607_;
                        local_37 = _e411;
                        let _e412 = local_14;
                        if (_e412 > 0u) {
                            let _e414 = local_12;
                            let _e415 = (_e414 - 1u);
                            local_38 = _e415;
                            let _e416 = local_2;
                            if (_e415 < _e416) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e418 = local_38;
                            let _e421 = global_5.member[_e418];
                            if (_e421 > 0u) {
                                let _e423 = local_38;
                                let _e424 = local_16;
                                let _e427 = ((5u * (_e423 * _e424)) + 3u);
                                local_39 = _e427;
                                let _e428 = local_1;
                                if (_e427 < _e428) {
                                } else {
                                    phi_1898_ = true;
                                    break;
                                }
                                let _e430 = local_39;
                                let _e433 = global_4.member[_e430];
                                phi_653_ = bitcast<f32>(_e433);
                            } else {
                                phi_653_ = _e134;
                            }
                            let _e436 = phi_653_;
                            local_40 = _e436;
                            let _e439 = global_3.member.member_5;
                            local_41 = _e439;
                            let _e440 = bitcast<u32>(_e436);
                            local_42 = _e440;
                            let _e443 = local_18;
                            let _e444 = bitcast<u32>(_e443);
                            local_43 = _e444;
                            local_44 = ((_e444 & 2139095040u) != 2139095040u);
                            if ((_e440 & 2139095040u) != 2139095040u) {
                                let _e449 = local_44;
                                if _e449 {
                                    let _e450 = local_40;
                                    let _e451 = local_18;
                                    let _e452 = (_e450 - _e451);
                                    local_45 = _e452;
                                    if (_e452 < 0f) {
                                        let _e454 = local_45;
                                        phi_857_ = -(_e454);
                                    } else {
                                        phi_857_ = _e452;
                                    }
                                    let _e457 = phi_857_;
                                    let _e458 = local_40;
                                    let _e459 = local_18;
                                    let _e461 = local_40;
                                    let _e462 = local_18;
                                    let _e464 = local_41;
                                    phi_865_ = (_e457 > (_e464 * select(_e462, _e461, (_e458 < _e459))));
                                } else {
                                    phi_865_ = true;
                                }
                                let _e468 = phi_865_;
                                phi_867_ = _e468;
                            } else {
                                let _e447 = local_44;
                                phi_867_ = (_e447 != false);
                            }
                            let _e470 = phi_867_;
                            if _e470 {
                                let _e471 = local_42;
                                if (_e471 == 0u) {
                                    phi_877_ = false;
                                } else {
                                    let _e473 = local_42;
                                    phi_877_ = (_e473 <= 2139095040u);
                                }
                                let _e476 = phi_877_;
                                if _e476 {
                                    let _e480 = global_3.member.member.member_1;
                                    let _e485 = global_3.member.member.member;
                                    let _e490 = global_3.member.member.member_2;
                                    local_46 = _e490;
                                    let _e496 = global_3.member.member.member_3;
                                    let _e497 = ((((2f * _e480) * _e485) / (_e490 - _e485)) * _e496);
                                    local_47 = _e497;
                                    if (_e497 == 0f) {
                                        phi_905_ = 0f;
                                    } else {
                                        let _e499 = local_46;
                                        let _e500 = local_40;
                                        let _e503 = local_47;
                                        phi_905_ = (_e503 * (1f - (_e499 / _e500)));
                                    }
                                    let _e506 = phi_905_;
                                    phi_906_ = _e506;
                                } else {
                                    phi_906_ = _e132;
                                }
                                let _e508 = phi_906_;
                                local_48 = _e508;
                                if (_e508 < 0f) {
                                    let _e510 = local_48;
                                    phi_912_ = -(_e510);
                                } else {
                                    phi_912_ = _e508;
                                }
                                let _e513 = phi_912_;
                                local_49 = _e513;
                                let _e514 = local_43;
                                if (_e514 == 0u) {
                                    phi_919_ = false;
                                } else {
                                    let _e516 = local_43;
                                    phi_919_ = (_e516 <= 2139095040u);
                                }
                                let _e519 = phi_919_;
                                if _e519 {
                                    let _e523 = global_3.member.member.member_1;
                                    let _e528 = global_3.member.member.member;
                                    let _e533 = global_3.member.member.member_2;
                                    local_50 = _e533;
                                    let _e539 = global_3.member.member.member_3;
                                    let _e540 = ((((2f * _e523) * _e528) / (_e533 - _e528)) * _e539);
                                    local_51 = _e540;
                                    if (_e540 == 0f) {
                                        phi_947_ = 0f;
                                    } else {
                                        let _e542 = local_50;
                                        let _e543 = local_18;
                                        let _e546 = local_51;
                                        phi_947_ = (_e546 * (1f - (_e542 / _e543)));
                                    }
                                    let _e549 = phi_947_;
                                    phi_948_ = _e549;
                                } else {
                                    phi_948_ = _e132;
                                }
                                let _e551 = phi_948_;
                                local_52 = _e551;
                                if (_e551 < 0f) {
                                    let _e553 = local_52;
                                    phi_954_ = -(_e553);
                                } else {
                                    phi_954_ = _e551;
                                }
                                let _e556 = phi_954_;
                                local_53 = _e556;
                                let _e557 = local_49;
                                if ((bitcast<u32>(_e557) & 2147483647u) > 2139095040u) {
                                    phi_976_ = _e556;
                                } else {
                                    let _e561 = local_53;
                                    if ((bitcast<u32>(_e561) & 2147483647u) > 2139095040u) {
                                        phi_971_ = true;
                                    } else {
                                        let _e565 = local_49;
                                        let _e566 = local_53;
                                        phi_971_ = (_e565 > _e566);
                                    }
                                    let _e569 = phi_971_;
                                    let _e570 = local_49;
                                    let _e571 = local_53;
                                    phi_976_ = select(_e571, _e570, _e569);
                                }
                                let _e574 = phi_976_;
                                let _e576 = ceil((_e574 * 0.5f));
                                local_54 = _e576;
                                if ((bitcast<u32>(_e576) & 2139095040u) != 2139095040u) {
                                    let _e580 = local_7;
                                    let _e582 = local_54;
                                    let _e583 = (_e582 < f32(_e580));
                                    local_55 = _e583;
                                    if _e583 {
                                        let _e584 = local_54;
                                        if (_e584 < 0f) {
                                            phi_1003_ = 0i;
                                        } else {
                                            let _e586 = local_54;
                                            let _e588 = local_54;
                                            let _e591 = local_54;
                                            let _e595 = local_54;
                                            let _e596 = local_54;
                                            phi_1003_ = select(0i, select(select(i32(_e586), i32(-2147483648), !((_e588 >= -2147483600f))), 2147483647i, (_e591 > 2147483500f)), (_e595 == _e596));
                                        }
                                        let _e600 = phi_1003_;
                                        phi_1004_ = _e600;
                                    } else {
                                        phi_1004_ = i32();
                                    }
                                    let _e602 = phi_1004_;
                                    let _e603 = local_55;
                                    phi_1006_ = _e602;
                                    phi_1007_ = select(true, false, _e603);
                                } else {
                                    phi_1006_ = i32();
                                    phi_1007_ = true;
                                }
                                let _e606 = phi_1006_;
                                let _e608 = phi_1007_;
                                let _e609 = local_7;
                                phi_1012_ = select(_e606, _e609, _e608);
                            } else {
                                phi_1012_ = -1i;
                            }
                            let _e612 = phi_1012_;
                            let _e613 = local_37;
                            let _e615 = local_37;
                            phi_1019_ = select(_e612, _e615, (_e612 < _e613));
                        } else {
                            phi_1019_ = _e411;
                        }
                        let _e618 = phi_1019_;
                        local_56 = _e618;
                        let _e619 = local_15;
                        let _e621 = local_6;
                        if ((_e619 + 1u) < _e621) {
                            let _e623 = local_12;
                            let _e624 = local_5;
                            let _e625 = (_e623 + _e624);
                            local_57 = _e625;
                            let _e626 = local_2;
                            if (_e625 < _e626) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e628 = local_57;
                            let _e631 = global_5.member[_e628];
                            if (_e631 > 0u) {
                                let _e633 = local_57;
                                let _e634 = local_16;
                                let _e637 = ((5u * (_e633 * _e634)) + 3u);
                                local_58 = _e637;
                                let _e638 = local_1;
                                if (_e637 < _e638) {
                                } else {
                                    phi_1898_ = true;
                                    break;
                                }
                                let _e640 = local_58;
                                let _e643 = global_4.member[_e640];
                                phi_1068_ = bitcast<f32>(_e643);
                            } else {
                                phi_1068_ = _e134;
                            }
                            let _e646 = phi_1068_;
                            local_59 = _e646;
                            let _e649 = global_3.member.member_5;
                            local_60 = _e649;
                            let _e650 = local_18;
                            let _e651 = bitcast<u32>(_e650);
                            local_61 = _e651;
                            let _e654 = bitcast<u32>(_e646);
                            local_62 = _e654;
                            local_63 = ((_e654 & 2139095040u) != 2139095040u);
                            if ((_e651 & 2139095040u) != 2139095040u) {
                                let _e659 = local_63;
                                if _e659 {
                                    let _e660 = local_18;
                                    let _e661 = local_59;
                                    let _e662 = (_e660 - _e661);
                                    local_64 = _e662;
                                    if (_e662 < 0f) {
                                        let _e664 = local_64;
                                        phi_1094_ = -(_e664);
                                    } else {
                                        phi_1094_ = _e662;
                                    }
                                    let _e667 = phi_1094_;
                                    let _e668 = local_18;
                                    let _e669 = local_59;
                                    let _e671 = local_18;
                                    let _e672 = local_59;
                                    let _e674 = local_60;
                                    phi_1102_ = (_e667 > (_e674 * select(_e672, _e671, (_e668 < _e669))));
                                } else {
                                    phi_1102_ = true;
                                }
                                let _e678 = phi_1102_;
                                phi_1104_ = _e678;
                            } else {
                                let _e657 = local_63;
                                phi_1104_ = (_e657 != false);
                            }
                            let _e680 = phi_1104_;
                            if _e680 {
                                let _e681 = local_61;
                                if (_e681 == 0u) {
                                    phi_1114_ = false;
                                } else {
                                    let _e683 = local_61;
                                    phi_1114_ = (_e683 <= 2139095040u);
                                }
                                let _e686 = phi_1114_;
                                if _e686 {
                                    let _e690 = global_3.member.member.member_1;
                                    let _e695 = global_3.member.member.member;
                                    let _e700 = global_3.member.member.member_2;
                                    local_65 = _e700;
                                    let _e706 = global_3.member.member.member_3;
                                    let _e707 = ((((2f * _e690) * _e695) / (_e700 - _e695)) * _e706);
                                    local_66 = _e707;
                                    if (_e707 == 0f) {
                                        phi_1142_ = 0f;
                                    } else {
                                        let _e709 = local_65;
                                        let _e710 = local_18;
                                        let _e713 = local_66;
                                        phi_1142_ = (_e713 * (1f - (_e709 / _e710)));
                                    }
                                    let _e716 = phi_1142_;
                                    phi_1143_ = _e716;
                                } else {
                                    phi_1143_ = _e132;
                                }
                                let _e718 = phi_1143_;
                                local_67 = _e718;
                                if (_e718 < 0f) {
                                    let _e720 = local_67;
                                    phi_1149_ = -(_e720);
                                } else {
                                    phi_1149_ = _e718;
                                }
                                let _e723 = phi_1149_;
                                local_68 = _e723;
                                let _e724 = local_62;
                                if (_e724 == 0u) {
                                    phi_1156_ = false;
                                } else {
                                    let _e726 = local_62;
                                    phi_1156_ = (_e726 <= 2139095040u);
                                }
                                let _e729 = phi_1156_;
                                if _e729 {
                                    let _e733 = global_3.member.member.member_1;
                                    let _e738 = global_3.member.member.member;
                                    let _e743 = global_3.member.member.member_2;
                                    local_69 = _e743;
                                    let _e749 = global_3.member.member.member_3;
                                    let _e750 = ((((2f * _e733) * _e738) / (_e743 - _e738)) * _e749);
                                    local_70 = _e750;
                                    if (_e750 == 0f) {
                                        phi_1184_ = 0f;
                                    } else {
                                        let _e752 = local_69;
                                        let _e753 = local_59;
                                        let _e756 = local_70;
                                        phi_1184_ = (_e756 * (1f - (_e752 / _e753)));
                                    }
                                    let _e759 = phi_1184_;
                                    phi_1185_ = _e759;
                                } else {
                                    phi_1185_ = _e132;
                                }
                                let _e761 = phi_1185_;
                                local_71 = _e761;
                                if (_e761 < 0f) {
                                    let _e763 = local_71;
                                    phi_1191_ = -(_e763);
                                } else {
                                    phi_1191_ = _e761;
                                }
                                let _e766 = phi_1191_;
                                local_72 = _e766;
                                let _e767 = local_68;
                                if ((bitcast<u32>(_e767) & 2147483647u) > 2139095040u) {
                                    phi_1213_ = _e766;
                                } else {
                                    let _e771 = local_72;
                                    if ((bitcast<u32>(_e771) & 2147483647u) > 2139095040u) {
                                        phi_1208_ = true;
                                    } else {
                                        let _e775 = local_68;
                                        let _e776 = local_72;
                                        phi_1208_ = (_e775 > _e776);
                                    }
                                    let _e779 = phi_1208_;
                                    let _e780 = local_68;
                                    let _e781 = local_72;
                                    phi_1213_ = select(_e781, _e780, _e779);
                                }
                                let _e784 = phi_1213_;
                                let _e786 = ceil((_e784 * 0.5f));
                                local_73 = _e786;
                                if ((bitcast<u32>(_e786) & 2139095040u) != 2139095040u) {
                                    let _e790 = local_7;
                                    let _e792 = local_73;
                                    let _e793 = (_e792 < f32(_e790));
                                    local_74 = _e793;
                                    if _e793 {
                                        let _e794 = local_73;
                                        if (_e794 < 0f) {
                                            phi_1240_ = 0i;
                                        } else {
                                            let _e796 = local_73;
                                            let _e798 = local_73;
                                            let _e801 = local_73;
                                            let _e805 = local_73;
                                            let _e806 = local_73;
                                            phi_1240_ = select(0i, select(select(i32(_e796), i32(-2147483648), !((_e798 >= -2147483600f))), 2147483647i, (_e801 > 2147483500f)), (_e805 == _e806));
                                        }
                                        let _e810 = phi_1240_;
                                        phi_1241_ = _e810;
                                    } else {
                                        phi_1241_ = i32();
                                    }
                                    let _e812 = phi_1241_;
                                    let _e813 = local_74;
                                    phi_1243_ = _e812;
                                    phi_1244_ = select(true, false, _e813);
                                } else {
                                    phi_1243_ = i32();
                                    phi_1244_ = true;
                                }
                                let _e816 = phi_1243_;
                                let _e818 = phi_1244_;
                                let _e819 = local_7;
                                phi_1249_ = select(_e816, _e819, _e818);
                            } else {
                                phi_1249_ = -1i;
                            }
                            let _e822 = phi_1249_;
                            let _e823 = local_56;
                            let _e825 = local_56;
                            phi_1434_ = select(_e822, _e825, (_e822 < _e823));
                        } else {
                            phi_1434_ = _e618;
                        }
                        let _e828 = phi_1434_;
                        local_75 = _e828;
                        let _e829 = local_15;
                        if (_e829 > 0u) {
                            let _e831 = local_12;
                            let _e832 = local_5;
                            let _e833 = (_e831 - _e832);
                            local_76 = _e833;
                            let _e834 = local_2;
                            if (_e833 < _e834) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e836 = local_76;
                            let _e839 = global_5.member[_e836];
                            if (_e839 > 0u) {
                                let _e841 = local_76;
                                let _e842 = local_16;
                                let _e845 = ((5u * (_e841 * _e842)) + 3u);
                                local_77 = _e845;
                                let _e846 = local_1;
                                if (_e845 < _e846) {
                                } else {
                                    phi_1898_ = true;
                                    break;
                                }
                                let _e848 = local_77;
                                let _e851 = global_4.member[_e848];
                                phi_1481_ = bitcast<f32>(_e851);
                            } else {
                                phi_1481_ = _e134;
                            }
                            let _e854 = phi_1481_;
                            local_78 = _e854;
                            let _e857 = global_3.member.member_5;
                            local_79 = _e857;
                            let _e858 = bitcast<u32>(_e854);
                            local_80 = _e858;
                            let _e861 = local_18;
                            let _e862 = bitcast<u32>(_e861);
                            local_81 = _e862;
                            local_82 = ((_e862 & 2139095040u) != 2139095040u);
                            if ((_e858 & 2139095040u) != 2139095040u) {
                                let _e867 = local_82;
                                if _e867 {
                                    let _e868 = local_78;
                                    let _e869 = local_18;
                                    let _e870 = (_e868 - _e869);
                                    local_83 = _e870;
                                    if (_e870 < 0f) {
                                        let _e872 = local_83;
                                        phi_1685_ = -(_e872);
                                    } else {
                                        phi_1685_ = _e870;
                                    }
                                    let _e875 = phi_1685_;
                                    let _e876 = local_78;
                                    let _e877 = local_18;
                                    let _e879 = local_78;
                                    let _e880 = local_18;
                                    let _e882 = local_79;
                                    phi_1693_ = (_e875 > (_e882 * select(_e880, _e879, (_e876 < _e877))));
                                } else {
                                    phi_1693_ = true;
                                }
                                let _e886 = phi_1693_;
                                phi_1695_ = _e886;
                            } else {
                                let _e865 = local_82;
                                phi_1695_ = (_e865 != false);
                            }
                            let _e888 = phi_1695_;
                            if _e888 {
                                let _e889 = local_80;
                                if (_e889 == 0u) {
                                    phi_1705_ = false;
                                } else {
                                    let _e891 = local_80;
                                    phi_1705_ = (_e891 <= 2139095040u);
                                }
                                let _e894 = phi_1705_;
                                if _e894 {
                                    let _e898 = global_3.member.member.member_1;
                                    let _e903 = global_3.member.member.member;
                                    let _e908 = global_3.member.member.member_2;
                                    local_84 = _e908;
                                    let _e914 = global_3.member.member.member_3;
                                    let _e915 = ((((2f * _e898) * _e903) / (_e908 - _e903)) * _e914);
                                    local_85 = _e915;
                                    if (_e915 == 0f) {
                                        phi_1733_ = 0f;
                                    } else {
                                        let _e917 = local_84;
                                        let _e918 = local_78;
                                        let _e921 = local_85;
                                        phi_1733_ = (_e921 * (1f - (_e917 / _e918)));
                                    }
                                    let _e924 = phi_1733_;
                                    phi_1734_ = _e924;
                                } else {
                                    phi_1734_ = _e132;
                                }
                                let _e926 = phi_1734_;
                                local_86 = _e926;
                                if (_e926 < 0f) {
                                    let _e928 = local_86;
                                    phi_1740_ = -(_e928);
                                } else {
                                    phi_1740_ = _e926;
                                }
                                let _e931 = phi_1740_;
                                local_87 = _e931;
                                let _e932 = local_81;
                                if (_e932 == 0u) {
                                    phi_1747_ = false;
                                } else {
                                    let _e934 = local_81;
                                    phi_1747_ = (_e934 <= 2139095040u);
                                }
                                let _e937 = phi_1747_;
                                if _e937 {
                                    let _e941 = global_3.member.member.member_1;
                                    let _e946 = global_3.member.member.member;
                                    let _e951 = global_3.member.member.member_2;
                                    local_88 = _e951;
                                    let _e957 = global_3.member.member.member_3;
                                    let _e958 = ((((2f * _e941) * _e946) / (_e951 - _e946)) * _e957);
                                    local_89 = _e958;
                                    if (_e958 == 0f) {
                                        phi_1775_ = 0f;
                                    } else {
                                        let _e960 = local_88;
                                        let _e961 = local_18;
                                        let _e964 = local_89;
                                        phi_1775_ = (_e964 * (1f - (_e960 / _e961)));
                                    }
                                    let _e967 = phi_1775_;
                                    phi_1776_ = _e967;
                                } else {
                                    phi_1776_ = _e132;
                                }
                                let _e969 = phi_1776_;
                                local_90 = _e969;
                                if (_e969 < 0f) {
                                    let _e971 = local_90;
                                    phi_1782_ = -(_e971);
                                } else {
                                    phi_1782_ = _e969;
                                }
                                let _e974 = phi_1782_;
                                local_91 = _e974;
                                let _e975 = local_87;
                                if ((bitcast<u32>(_e975) & 2147483647u) > 2139095040u) {
                                    phi_1804_ = _e974;
                                } else {
                                    let _e979 = local_91;
                                    if ((bitcast<u32>(_e979) & 2147483647u) > 2139095040u) {
                                        phi_1799_ = true;
                                    } else {
                                        let _e983 = local_87;
                                        let _e984 = local_91;
                                        phi_1799_ = (_e983 > _e984);
                                    }
                                    let _e987 = phi_1799_;
                                    let _e988 = local_87;
                                    let _e989 = local_91;
                                    phi_1804_ = select(_e989, _e988, _e987);
                                }
                                let _e992 = phi_1804_;
                                let _e994 = ceil((_e992 * 0.5f));
                                local_92 = _e994;
                                if ((bitcast<u32>(_e994) & 2139095040u) != 2139095040u) {
                                    let _e998 = local_7;
                                    let _e1000 = local_92;
                                    let _e1001 = (_e1000 < f32(_e998));
                                    local_93 = _e1001;
                                    if _e1001 {
                                        let _e1002 = local_92;
                                        if (_e1002 < 0f) {
                                            phi_1831_ = 0i;
                                        } else {
                                            let _e1004 = local_92;
                                            let _e1006 = local_92;
                                            let _e1009 = local_92;
                                            let _e1013 = local_92;
                                            let _e1014 = local_92;
                                            phi_1831_ = select(0i, select(select(i32(_e1004), i32(-2147483648), !((_e1006 >= -2147483600f))), 2147483647i, (_e1009 > 2147483500f)), (_e1013 == _e1014));
                                        }
                                        let _e1018 = phi_1831_;
                                        phi_1832_ = _e1018;
                                    } else {
                                        phi_1832_ = i32();
                                    }
                                    let _e1020 = phi_1832_;
                                    let _e1021 = local_93;
                                    phi_1834_ = _e1020;
                                    phi_1835_ = select(true, false, _e1021);
                                } else {
                                    phi_1834_ = i32();
                                    phi_1835_ = true;
                                }
                                let _e1024 = phi_1834_;
                                let _e1026 = phi_1835_;
                                let _e1027 = local_7;
                                phi_1840_ = select(_e1024, _e1027, _e1026);
                            } else {
                                phi_1840_ = -1i;
                            }
                            let _e1030 = phi_1840_;
                            let _e1031 = local_75;
                            let _e1033 = local_75;
                            phi_1847_ = select(_e1030, _e1033, (_e1030 < _e1031));
                        } else {
                            phi_1847_ = _e828;
                        }
                        let _e1036 = phi_1847_;
                        local_94 = bitcast<u32>((_e1036 + 1i));
                        let _e1039 = local_12;
                        let _e1040 = local_3;
                        if (_e1039 < _e1040) {
                        } else {
                            phi_1898_ = true;
                            break;
                        }
                        let _e1042 = local_12;
                        let _e1045 = local_94;
                        global_6.member[_e1042] = _e1045;
                        let _e1046 = local_94;
                        if (_e1046 > 0u) {
                            let _e1048 = local_4;
                            if (0u < _e1048) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e1052 = local_94;
                            let _e1053 = atomicMax((&global_7.member[0u]), _e1052);
                        }
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e1054 = local_10;
                    let _e1055 = local_9;
                    phi_127_ = (_e1054 + _e1055);
                } else {
                    phi_127_ = u32();
                }
                let _e1058 = phi_127_;
                continue;
                continuing {
                    let _e1059 = local_11;
                    phi_126_ = _e1058;
                    phi_1898_ = false;
                    break if !(_e1059);
                }
            }
            let _e1062 = phi_1898_;
            if _e1062 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn peel_edges(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
