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
    member_10: array<u32, 3>,
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
                                            let _e385 = local_35;
                                            let _e389 = local_35;
                                            let _e390 = local_35;
                                            phi_413_ = select(0i, select(select(i32(_e381), i32(-2147483648), (_e383 < -2147483600f)), 2147483647i, (_e385 > 2147483500f)), (_e389 == _e390));
                                        }
                                        let _e394 = phi_413_;
                                        phi_414_ = _e394;
                                    } else {
                                        phi_414_ = i32();
                                    }
                                    let _e396 = phi_414_;
                                    let _e397 = local_36;
                                    phi_416_ = _e396;
                                    phi_417_ = select(true, false, _e397);
                                } else {
                                    phi_416_ = i32();
                                    phi_417_ = true;
                                }
                                let _e400 = phi_416_;
                                let _e402 = phi_417_;
                                let _e403 = local_7;
                                phi_422_ = select(_e400, _e403, _e402);
                            } else {
                                phi_422_ = -1i;
                            }
                            let _e406 = phi_422_;
                            phi_607_ = select(_e406, -1i, (_e406 < -1i));
                        } else {
                            phi_607_ = -1i;
                        }
                        let _e410 = phi_607_;
                        local_37 = _e410;
                        let _e411 = local_14;
                        if (_e411 > 0u) {
                            let _e413 = local_12;
                            let _e414 = (_e413 - 1u);
                            local_38 = _e414;
                            let _e415 = local_2;
                            if (_e414 < _e415) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e417 = local_38;
                            let _e420 = global_5.member[_e417];
                            if (_e420 > 0u) {
                                let _e422 = local_38;
                                let _e423 = local_16;
                                let _e426 = ((5u * (_e422 * _e423)) + 3u);
                                local_39 = _e426;
                                let _e427 = local_1;
                                if (_e426 < _e427) {
                                } else {
                                    phi_1898_ = true;
                                    break;
                                }
                                let _e429 = local_39;
                                let _e432 = global_4.member[_e429];
                                phi_653_ = bitcast<f32>(_e432);
                            } else {
                                phi_653_ = _e134;
                            }
                            let _e435 = phi_653_;
                            local_40 = _e435;
                            let _e438 = global_3.member.member_5;
                            local_41 = _e438;
                            let _e439 = bitcast<u32>(_e435);
                            local_42 = _e439;
                            let _e442 = local_18;
                            let _e443 = bitcast<u32>(_e442);
                            local_43 = _e443;
                            local_44 = ((_e443 & 2139095040u) != 2139095040u);
                            if ((_e439 & 2139095040u) != 2139095040u) {
                                let _e448 = local_44;
                                if _e448 {
                                    let _e449 = local_40;
                                    let _e450 = local_18;
                                    let _e451 = (_e449 - _e450);
                                    local_45 = _e451;
                                    if (_e451 < 0f) {
                                        let _e453 = local_45;
                                        phi_857_ = -(_e453);
                                    } else {
                                        phi_857_ = _e451;
                                    }
                                    let _e456 = phi_857_;
                                    let _e457 = local_40;
                                    let _e458 = local_18;
                                    let _e460 = local_40;
                                    let _e461 = local_18;
                                    let _e463 = local_41;
                                    phi_865_ = (_e456 > (_e463 * select(_e461, _e460, (_e457 < _e458))));
                                } else {
                                    phi_865_ = true;
                                }
                                let _e467 = phi_865_;
                                phi_867_ = _e467;
                            } else {
                                let _e446 = local_44;
                                phi_867_ = (_e446 != false);
                            }
                            let _e469 = phi_867_;
                            if _e469 {
                                let _e470 = local_42;
                                if (_e470 == 0u) {
                                    phi_877_ = false;
                                } else {
                                    let _e472 = local_42;
                                    phi_877_ = (_e472 <= 2139095040u);
                                }
                                let _e475 = phi_877_;
                                if _e475 {
                                    let _e479 = global_3.member.member.member_1;
                                    let _e484 = global_3.member.member.member;
                                    let _e489 = global_3.member.member.member_2;
                                    local_46 = _e489;
                                    let _e495 = global_3.member.member.member_3;
                                    let _e496 = ((((2f * _e479) * _e484) / (_e489 - _e484)) * _e495);
                                    local_47 = _e496;
                                    if (_e496 == 0f) {
                                        phi_905_ = 0f;
                                    } else {
                                        let _e498 = local_46;
                                        let _e499 = local_40;
                                        let _e502 = local_47;
                                        phi_905_ = (_e502 * (1f - (_e498 / _e499)));
                                    }
                                    let _e505 = phi_905_;
                                    phi_906_ = _e505;
                                } else {
                                    phi_906_ = _e132;
                                }
                                let _e507 = phi_906_;
                                local_48 = _e507;
                                if (_e507 < 0f) {
                                    let _e509 = local_48;
                                    phi_912_ = -(_e509);
                                } else {
                                    phi_912_ = _e507;
                                }
                                let _e512 = phi_912_;
                                local_49 = _e512;
                                let _e513 = local_43;
                                if (_e513 == 0u) {
                                    phi_919_ = false;
                                } else {
                                    let _e515 = local_43;
                                    phi_919_ = (_e515 <= 2139095040u);
                                }
                                let _e518 = phi_919_;
                                if _e518 {
                                    let _e522 = global_3.member.member.member_1;
                                    let _e527 = global_3.member.member.member;
                                    let _e532 = global_3.member.member.member_2;
                                    local_50 = _e532;
                                    let _e538 = global_3.member.member.member_3;
                                    let _e539 = ((((2f * _e522) * _e527) / (_e532 - _e527)) * _e538);
                                    local_51 = _e539;
                                    if (_e539 == 0f) {
                                        phi_947_ = 0f;
                                    } else {
                                        let _e541 = local_50;
                                        let _e542 = local_18;
                                        let _e545 = local_51;
                                        phi_947_ = (_e545 * (1f - (_e541 / _e542)));
                                    }
                                    let _e548 = phi_947_;
                                    phi_948_ = _e548;
                                } else {
                                    phi_948_ = _e132;
                                }
                                let _e550 = phi_948_;
                                local_52 = _e550;
                                if (_e550 < 0f) {
                                    let _e552 = local_52;
                                    phi_954_ = -(_e552);
                                } else {
                                    phi_954_ = _e550;
                                }
                                let _e555 = phi_954_;
                                local_53 = _e555;
                                let _e556 = local_49;
                                if ((bitcast<u32>(_e556) & 2147483647u) > 2139095040u) {
                                    phi_976_ = _e555;
                                } else {
                                    let _e560 = local_53;
                                    if ((bitcast<u32>(_e560) & 2147483647u) > 2139095040u) {
                                        phi_971_ = true;
                                    } else {
                                        let _e564 = local_49;
                                        let _e565 = local_53;
                                        phi_971_ = (_e564 > _e565);
                                    }
                                    let _e568 = phi_971_;
                                    let _e569 = local_49;
                                    let _e570 = local_53;
                                    phi_976_ = select(_e570, _e569, _e568);
                                }
                                let _e573 = phi_976_;
                                let _e575 = ceil((_e573 * 0.5f));
                                local_54 = _e575;
                                if ((bitcast<u32>(_e575) & 2139095040u) != 2139095040u) {
                                    let _e579 = local_7;
                                    let _e581 = local_54;
                                    let _e582 = (_e581 < f32(_e579));
                                    local_55 = _e582;
                                    if _e582 {
                                        let _e583 = local_54;
                                        if (_e583 < 0f) {
                                            phi_1003_ = 0i;
                                        } else {
                                            let _e585 = local_54;
                                            let _e587 = local_54;
                                            let _e589 = local_54;
                                            let _e593 = local_54;
                                            let _e594 = local_54;
                                            phi_1003_ = select(0i, select(select(i32(_e585), i32(-2147483648), (_e587 < -2147483600f)), 2147483647i, (_e589 > 2147483500f)), (_e593 == _e594));
                                        }
                                        let _e598 = phi_1003_;
                                        phi_1004_ = _e598;
                                    } else {
                                        phi_1004_ = i32();
                                    }
                                    let _e600 = phi_1004_;
                                    let _e601 = local_55;
                                    phi_1006_ = _e600;
                                    phi_1007_ = select(true, false, _e601);
                                } else {
                                    phi_1006_ = i32();
                                    phi_1007_ = true;
                                }
                                let _e604 = phi_1006_;
                                let _e606 = phi_1007_;
                                let _e607 = local_7;
                                phi_1012_ = select(_e604, _e607, _e606);
                            } else {
                                phi_1012_ = -1i;
                            }
                            let _e610 = phi_1012_;
                            let _e611 = local_37;
                            let _e613 = local_37;
                            phi_1019_ = select(_e610, _e613, (_e610 < _e611));
                        } else {
                            phi_1019_ = _e410;
                        }
                        let _e616 = phi_1019_;
                        local_56 = _e616;
                        let _e617 = local_15;
                        let _e619 = local_6;
                        if ((_e617 + 1u) < _e619) {
                            let _e621 = local_12;
                            let _e622 = local_5;
                            let _e623 = (_e621 + _e622);
                            local_57 = _e623;
                            let _e624 = local_2;
                            if (_e623 < _e624) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e626 = local_57;
                            let _e629 = global_5.member[_e626];
                            if (_e629 > 0u) {
                                let _e631 = local_57;
                                let _e632 = local_16;
                                let _e635 = ((5u * (_e631 * _e632)) + 3u);
                                local_58 = _e635;
                                let _e636 = local_1;
                                if (_e635 < _e636) {
                                } else {
                                    phi_1898_ = true;
                                    break;
                                }
                                let _e638 = local_58;
                                let _e641 = global_4.member[_e638];
                                phi_1068_ = bitcast<f32>(_e641);
                            } else {
                                phi_1068_ = _e134;
                            }
                            let _e644 = phi_1068_;
                            local_59 = _e644;
                            let _e647 = global_3.member.member_5;
                            local_60 = _e647;
                            let _e648 = local_18;
                            let _e649 = bitcast<u32>(_e648);
                            local_61 = _e649;
                            let _e652 = bitcast<u32>(_e644);
                            local_62 = _e652;
                            local_63 = ((_e652 & 2139095040u) != 2139095040u);
                            if ((_e649 & 2139095040u) != 2139095040u) {
                                let _e657 = local_63;
                                if _e657 {
                                    let _e658 = local_18;
                                    let _e659 = local_59;
                                    let _e660 = (_e658 - _e659);
                                    local_64 = _e660;
                                    if (_e660 < 0f) {
                                        let _e662 = local_64;
                                        phi_1094_ = -(_e662);
                                    } else {
                                        phi_1094_ = _e660;
                                    }
                                    let _e665 = phi_1094_;
                                    let _e666 = local_18;
                                    let _e667 = local_59;
                                    let _e669 = local_18;
                                    let _e670 = local_59;
                                    let _e672 = local_60;
                                    phi_1102_ = (_e665 > (_e672 * select(_e670, _e669, (_e666 < _e667))));
                                } else {
                                    phi_1102_ = true;
                                }
                                let _e676 = phi_1102_;
                                phi_1104_ = _e676;
                            } else {
                                let _e655 = local_63;
                                phi_1104_ = (_e655 != false);
                            }
                            let _e678 = phi_1104_;
                            if _e678 {
                                let _e679 = local_61;
                                if (_e679 == 0u) {
                                    phi_1114_ = false;
                                } else {
                                    let _e681 = local_61;
                                    phi_1114_ = (_e681 <= 2139095040u);
                                }
                                let _e684 = phi_1114_;
                                if _e684 {
                                    let _e688 = global_3.member.member.member_1;
                                    let _e693 = global_3.member.member.member;
                                    let _e698 = global_3.member.member.member_2;
                                    local_65 = _e698;
                                    let _e704 = global_3.member.member.member_3;
                                    let _e705 = ((((2f * _e688) * _e693) / (_e698 - _e693)) * _e704);
                                    local_66 = _e705;
                                    if (_e705 == 0f) {
                                        phi_1142_ = 0f;
                                    } else {
                                        let _e707 = local_65;
                                        let _e708 = local_18;
                                        let _e711 = local_66;
                                        phi_1142_ = (_e711 * (1f - (_e707 / _e708)));
                                    }
                                    let _e714 = phi_1142_;
                                    phi_1143_ = _e714;
                                } else {
                                    phi_1143_ = _e132;
                                }
                                let _e716 = phi_1143_;
                                local_67 = _e716;
                                if (_e716 < 0f) {
                                    let _e718 = local_67;
                                    phi_1149_ = -(_e718);
                                } else {
                                    phi_1149_ = _e716;
                                }
                                let _e721 = phi_1149_;
                                local_68 = _e721;
                                let _e722 = local_62;
                                if (_e722 == 0u) {
                                    phi_1156_ = false;
                                } else {
                                    let _e724 = local_62;
                                    phi_1156_ = (_e724 <= 2139095040u);
                                }
                                let _e727 = phi_1156_;
                                if _e727 {
                                    let _e731 = global_3.member.member.member_1;
                                    let _e736 = global_3.member.member.member;
                                    let _e741 = global_3.member.member.member_2;
                                    local_69 = _e741;
                                    let _e747 = global_3.member.member.member_3;
                                    let _e748 = ((((2f * _e731) * _e736) / (_e741 - _e736)) * _e747);
                                    local_70 = _e748;
                                    if (_e748 == 0f) {
                                        phi_1184_ = 0f;
                                    } else {
                                        let _e750 = local_69;
                                        let _e751 = local_59;
                                        let _e754 = local_70;
                                        phi_1184_ = (_e754 * (1f - (_e750 / _e751)));
                                    }
                                    let _e757 = phi_1184_;
                                    phi_1185_ = _e757;
                                } else {
                                    phi_1185_ = _e132;
                                }
                                let _e759 = phi_1185_;
                                local_71 = _e759;
                                if (_e759 < 0f) {
                                    let _e761 = local_71;
                                    phi_1191_ = -(_e761);
                                } else {
                                    phi_1191_ = _e759;
                                }
                                let _e764 = phi_1191_;
                                local_72 = _e764;
                                let _e765 = local_68;
                                if ((bitcast<u32>(_e765) & 2147483647u) > 2139095040u) {
                                    phi_1213_ = _e764;
                                } else {
                                    let _e769 = local_72;
                                    if ((bitcast<u32>(_e769) & 2147483647u) > 2139095040u) {
                                        phi_1208_ = true;
                                    } else {
                                        let _e773 = local_68;
                                        let _e774 = local_72;
                                        phi_1208_ = (_e773 > _e774);
                                    }
                                    let _e777 = phi_1208_;
                                    let _e778 = local_68;
                                    let _e779 = local_72;
                                    phi_1213_ = select(_e779, _e778, _e777);
                                }
                                let _e782 = phi_1213_;
                                let _e784 = ceil((_e782 * 0.5f));
                                local_73 = _e784;
                                if ((bitcast<u32>(_e784) & 2139095040u) != 2139095040u) {
                                    let _e788 = local_7;
                                    let _e790 = local_73;
                                    let _e791 = (_e790 < f32(_e788));
                                    local_74 = _e791;
                                    if _e791 {
                                        let _e792 = local_73;
                                        if (_e792 < 0f) {
                                            phi_1240_ = 0i;
                                        } else {
                                            let _e794 = local_73;
                                            let _e796 = local_73;
                                            let _e798 = local_73;
                                            let _e802 = local_73;
                                            let _e803 = local_73;
                                            phi_1240_ = select(0i, select(select(i32(_e794), i32(-2147483648), (_e796 < -2147483600f)), 2147483647i, (_e798 > 2147483500f)), (_e802 == _e803));
                                        }
                                        let _e807 = phi_1240_;
                                        phi_1241_ = _e807;
                                    } else {
                                        phi_1241_ = i32();
                                    }
                                    let _e809 = phi_1241_;
                                    let _e810 = local_74;
                                    phi_1243_ = _e809;
                                    phi_1244_ = select(true, false, _e810);
                                } else {
                                    phi_1243_ = i32();
                                    phi_1244_ = true;
                                }
                                let _e813 = phi_1243_;
                                let _e815 = phi_1244_;
                                let _e816 = local_7;
                                phi_1249_ = select(_e813, _e816, _e815);
                            } else {
                                phi_1249_ = -1i;
                            }
                            let _e819 = phi_1249_;
                            let _e820 = local_56;
                            let _e822 = local_56;
                            phi_1434_ = select(_e819, _e822, (_e819 < _e820));
                        } else {
                            phi_1434_ = _e616;
                        }
                        let _e825 = phi_1434_;
                        local_75 = _e825;
                        let _e826 = local_15;
                        if (_e826 > 0u) {
                            let _e828 = local_12;
                            let _e829 = local_5;
                            let _e830 = (_e828 - _e829);
                            local_76 = _e830;
                            let _e831 = local_2;
                            if (_e830 < _e831) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e833 = local_76;
                            let _e836 = global_5.member[_e833];
                            if (_e836 > 0u) {
                                let _e838 = local_76;
                                let _e839 = local_16;
                                let _e842 = ((5u * (_e838 * _e839)) + 3u);
                                local_77 = _e842;
                                let _e843 = local_1;
                                if (_e842 < _e843) {
                                } else {
                                    phi_1898_ = true;
                                    break;
                                }
                                let _e845 = local_77;
                                let _e848 = global_4.member[_e845];
                                phi_1481_ = bitcast<f32>(_e848);
                            } else {
                                phi_1481_ = _e134;
                            }
                            let _e851 = phi_1481_;
                            local_78 = _e851;
                            let _e854 = global_3.member.member_5;
                            local_79 = _e854;
                            let _e855 = bitcast<u32>(_e851);
                            local_80 = _e855;
                            let _e858 = local_18;
                            let _e859 = bitcast<u32>(_e858);
                            local_81 = _e859;
                            local_82 = ((_e859 & 2139095040u) != 2139095040u);
                            if ((_e855 & 2139095040u) != 2139095040u) {
                                let _e864 = local_82;
                                if _e864 {
                                    let _e865 = local_78;
                                    let _e866 = local_18;
                                    let _e867 = (_e865 - _e866);
                                    local_83 = _e867;
                                    if (_e867 < 0f) {
                                        let _e869 = local_83;
                                        phi_1685_ = -(_e869);
                                    } else {
                                        phi_1685_ = _e867;
                                    }
                                    let _e872 = phi_1685_;
                                    let _e873 = local_78;
                                    let _e874 = local_18;
                                    let _e876 = local_78;
                                    let _e877 = local_18;
                                    let _e879 = local_79;
                                    phi_1693_ = (_e872 > (_e879 * select(_e877, _e876, (_e873 < _e874))));
                                } else {
                                    phi_1693_ = true;
                                }
                                let _e883 = phi_1693_;
                                phi_1695_ = _e883;
                            } else {
                                let _e862 = local_82;
                                phi_1695_ = (_e862 != false);
                            }
                            let _e885 = phi_1695_;
                            if _e885 {
                                let _e886 = local_80;
                                if (_e886 == 0u) {
                                    phi_1705_ = false;
                                } else {
                                    let _e888 = local_80;
                                    phi_1705_ = (_e888 <= 2139095040u);
                                }
                                let _e891 = phi_1705_;
                                if _e891 {
                                    let _e895 = global_3.member.member.member_1;
                                    let _e900 = global_3.member.member.member;
                                    let _e905 = global_3.member.member.member_2;
                                    local_84 = _e905;
                                    let _e911 = global_3.member.member.member_3;
                                    let _e912 = ((((2f * _e895) * _e900) / (_e905 - _e900)) * _e911);
                                    local_85 = _e912;
                                    if (_e912 == 0f) {
                                        phi_1733_ = 0f;
                                    } else {
                                        let _e914 = local_84;
                                        let _e915 = local_78;
                                        let _e918 = local_85;
                                        phi_1733_ = (_e918 * (1f - (_e914 / _e915)));
                                    }
                                    let _e921 = phi_1733_;
                                    phi_1734_ = _e921;
                                } else {
                                    phi_1734_ = _e132;
                                }
                                let _e923 = phi_1734_;
                                local_86 = _e923;
                                if (_e923 < 0f) {
                                    let _e925 = local_86;
                                    phi_1740_ = -(_e925);
                                } else {
                                    phi_1740_ = _e923;
                                }
                                let _e928 = phi_1740_;
                                local_87 = _e928;
                                let _e929 = local_81;
                                if (_e929 == 0u) {
                                    phi_1747_ = false;
                                } else {
                                    let _e931 = local_81;
                                    phi_1747_ = (_e931 <= 2139095040u);
                                }
                                let _e934 = phi_1747_;
                                if _e934 {
                                    let _e938 = global_3.member.member.member_1;
                                    let _e943 = global_3.member.member.member;
                                    let _e948 = global_3.member.member.member_2;
                                    local_88 = _e948;
                                    let _e954 = global_3.member.member.member_3;
                                    let _e955 = ((((2f * _e938) * _e943) / (_e948 - _e943)) * _e954);
                                    local_89 = _e955;
                                    if (_e955 == 0f) {
                                        phi_1775_ = 0f;
                                    } else {
                                        let _e957 = local_88;
                                        let _e958 = local_18;
                                        let _e961 = local_89;
                                        phi_1775_ = (_e961 * (1f - (_e957 / _e958)));
                                    }
                                    let _e964 = phi_1775_;
                                    phi_1776_ = _e964;
                                } else {
                                    phi_1776_ = _e132;
                                }
                                let _e966 = phi_1776_;
                                local_90 = _e966;
                                if (_e966 < 0f) {
                                    let _e968 = local_90;
                                    phi_1782_ = -(_e968);
                                } else {
                                    phi_1782_ = _e966;
                                }
                                let _e971 = phi_1782_;
                                local_91 = _e971;
                                let _e972 = local_87;
                                if ((bitcast<u32>(_e972) & 2147483647u) > 2139095040u) {
                                    phi_1804_ = _e971;
                                } else {
                                    let _e976 = local_91;
                                    if ((bitcast<u32>(_e976) & 2147483647u) > 2139095040u) {
                                        phi_1799_ = true;
                                    } else {
                                        let _e980 = local_87;
                                        let _e981 = local_91;
                                        phi_1799_ = (_e980 > _e981);
                                    }
                                    let _e984 = phi_1799_;
                                    let _e985 = local_87;
                                    let _e986 = local_91;
                                    phi_1804_ = select(_e986, _e985, _e984);
                                }
                                let _e989 = phi_1804_;
                                let _e991 = ceil((_e989 * 0.5f));
                                local_92 = _e991;
                                if ((bitcast<u32>(_e991) & 2139095040u) != 2139095040u) {
                                    let _e995 = local_7;
                                    let _e997 = local_92;
                                    let _e998 = (_e997 < f32(_e995));
                                    local_93 = _e998;
                                    if _e998 {
                                        let _e999 = local_92;
                                        if (_e999 < 0f) {
                                            phi_1831_ = 0i;
                                        } else {
                                            let _e1001 = local_92;
                                            let _e1003 = local_92;
                                            let _e1005 = local_92;
                                            let _e1009 = local_92;
                                            let _e1010 = local_92;
                                            phi_1831_ = select(0i, select(select(i32(_e1001), i32(-2147483648), (_e1003 < -2147483600f)), 2147483647i, (_e1005 > 2147483500f)), (_e1009 == _e1010));
                                        }
                                        let _e1014 = phi_1831_;
                                        phi_1832_ = _e1014;
                                    } else {
                                        phi_1832_ = i32();
                                    }
                                    let _e1016 = phi_1832_;
                                    let _e1017 = local_93;
                                    phi_1834_ = _e1016;
                                    phi_1835_ = select(true, false, _e1017);
                                } else {
                                    phi_1834_ = i32();
                                    phi_1835_ = true;
                                }
                                let _e1020 = phi_1834_;
                                let _e1022 = phi_1835_;
                                let _e1023 = local_7;
                                phi_1840_ = select(_e1020, _e1023, _e1022);
                            } else {
                                phi_1840_ = -1i;
                            }
                            let _e1026 = phi_1840_;
                            let _e1027 = local_75;
                            let _e1029 = local_75;
                            phi_1847_ = select(_e1026, _e1029, (_e1026 < _e1027));
                        } else {
                            phi_1847_ = _e825;
                        }
                        let _e1032 = phi_1847_;
                        local_94 = bitcast<u32>((_e1032 + 1i));
                        let _e1035 = local_12;
                        let _e1036 = local_3;
                        if (_e1035 < _e1036) {
                        } else {
                            phi_1898_ = true;
                            break;
                        }
                        let _e1038 = local_12;
                        let _e1041 = local_94;
                        global_6.member[_e1038] = _e1041;
                        let _e1042 = local_94;
                        if (_e1042 > 0u) {
                            let _e1044 = local_4;
                            if (0u < _e1044) {
                            } else {
                                phi_1898_ = true;
                                break;
                            }
                            let _e1048 = local_94;
                            let _e1049 = atomicMax((&global_7.member[0u]), _e1048);
                        }
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e1050 = local_10;
                    let _e1051 = local_9;
                    phi_127_ = (_e1050 + _e1051);
                } else {
                    phi_127_ = u32();
                }
                let _e1054 = phi_127_;
                continue;
                continuing {
                    let _e1055 = local_11;
                    phi_126_ = _e1054;
                    phi_1898_ = false;
                    break if !(_e1055);
                }
            }
            let _e1058 = phi_1898_;
            if _e1058 {
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
