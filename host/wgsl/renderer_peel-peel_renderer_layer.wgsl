struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_16 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_17 {
    member: type_16,
    member_1: type_5,
    member_2: f32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
}

struct type_18 {
    member: type_17,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_7;
var<immediate> global_5: type_18;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_7;
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
    var local_7: u32;
    var local_8: bool;
    var local_9: u32;
    var local_10: u32;
    var local_11: f32;
    var local_12: u32;
    var local_13: bool;
    var local_14: f32;
    var local_15: bool;
    var local_16: f32;
    var local_17: f32;
    var local_18: f32;
    var local_19: bool;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: f32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: f32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: f32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: f32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: f32;
    var local_51: u32;
    var local_52: f32;
    var local_53: u32;
    var local_54: f32;
    var local_55: u32;
    var local_56: array<f32, 4>;
    var local_57: u32;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: u32;
    var local_62: u32;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: f32;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: f32;
    var local_71: u32;
    var local_72: u32;
    var local_73: u32;
    var local_74: f32;
    var local_75: u32;
    var local_76: u32;
    var local_77: u32;
    var local_78: f32;
    var local_79: u32;
    var local_80: u32;
    var local_81: u32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: f32;
    var local_88: u32;
    var local_89: f32;
    var local_90: u32;
    var local_91: f32;
    var local_92: u32;
    var local_93: bool;
    var local_94: array<f32, 4>;
    var local_95: bool;
    var local_96: bool;
    var local_97: bool;
    var local_98: array<f32, 3>;
    var local_99: f32;
    var local_100: u32;
    var local_101: u32;
    var local_102: u32;
    var local_103: u32;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: f32;
    var local_111: f32;
    var local_112: bool;
    var local_113: f32;
    var local_114: u32;
    var local_115: f32;
    var local_116: f32;
    var local_117: f32;
    var local_118: f32;
    var local_119: f32;
    var local_120: f32;
    var local_121: f32;
    var local_122: f32;
    var local_123: f32;
    var local_124: f32;
    var local_125: bool;
    var local_126: f32;
    var local_127: f32;
    var local_128: f32;
    var phi_126_: u32;
    var phi_172_: f32;
    var phi_217_: f32;
    var phi_218_: f32;
    var phi_238_: f32;
    var phi_239_: f32;
    var phi_240_: f32;
    var phi_241_: f32;
    var phi_247_: f32;
    var phi_248_: f32;
    var phi_250_: f32;
    var phi_251_: bool;
    var phi_256_: f32;
    var phi_266_: bool;
    var phi_287_: u32;
    var phi_342_: f32;
    var phi_357_: f32;
    var phi_358_: f32;
    var phi_359_: f32;
    var phi_360_: f32;
    var phi_361_: bool;
    var phi_383_: f32;
    var phi_398_: f32;
    var phi_399_: f32;
    var phi_400_: f32;
    var phi_401_: f32;
    var phi_402_: bool;
    var phi_424_: f32;
    var phi_439_: f32;
    var phi_440_: f32;
    var phi_441_: f32;
    var phi_442_: f32;
    var phi_443_: bool;
    var phi_465_: f32;
    var phi_480_: f32;
    var phi_481_: f32;
    var phi_482_: f32;
    var phi_483_: f32;
    var phi_484_: bool;
    var phi_542_: f32;
    var phi_543_: f32;
    var phi_544_: f32;
    var phi_545_: f32;
    var phi_546_: bool;
    var phi_585_: f32;
    var phi_586_: f32;
    var phi_587_: f32;
    var phi_588_: f32;
    var phi_589_: bool;
    var phi_627_: f32;
    var phi_628_: f32;
    var phi_629_: f32;
    var phi_630_: f32;
    var phi_631_: bool;
    var phi_710_: array<f32, 4>;
    var phi_711_: array<f32, 4>;
    var phi_720_: array<f32, 3>;
    var phi_721_: f32;
    var phi_737_: u32;
    var phi_792_: f32;
    var phi_807_: f32;
    var phi_808_: f32;
    var phi_809_: f32;
    var phi_810_: f32;
    var phi_811_: bool;
    var phi_833_: f32;
    var phi_848_: f32;
    var phi_849_: f32;
    var phi_850_: f32;
    var phi_851_: f32;
    var phi_852_: bool;
    var phi_874_: f32;
    var phi_889_: f32;
    var phi_890_: f32;
    var phi_891_: f32;
    var phi_892_: f32;
    var phi_893_: bool;
    var phi_915_: f32;
    var phi_930_: f32;
    var phi_931_: f32;
    var phi_932_: f32;
    var phi_933_: f32;
    var phi_934_: bool;
    var phi_992_: f32;
    var phi_993_: f32;
    var phi_994_: f32;
    var phi_995_: f32;
    var phi_996_: bool;
    var phi_1035_: f32;
    var phi_1036_: f32;
    var phi_1037_: f32;
    var phi_1038_: f32;
    var phi_1039_: bool;
    var phi_1077_: f32;
    var phi_1078_: f32;
    var phi_1079_: f32;
    var phi_1080_: f32;
    var phi_1081_: bool;
    var phi_1160_: array<f32, 4>;
    var phi_1161_: array<f32, 4>;
    var phi_1162_: array<f32, 3>;
    var phi_1163_: f32;
    var phi_1164_: bool;
    var phi_1165_: array<f32, 4>;
    var phi_1166_: bool;
    var phi_1167_: bool;
    var phi_1197_: array<f32, 3>;
    var phi_1199_: array<f32, 3>;
    var phi_1200_: f32;
    var phi_1303_: bool;
    var phi_1330_: f32;
    var phi_1332_: f32;
    var phi_1333_: bool;
    var phi_1334_: f32;
    var phi_1335_: f32;
    var phi_1336_: bool;
    var phi_1337_: f32;
    var phi_1338_: f32;
    var phi_1339_: bool;
    var phi_1340_: bool;
    var phi_1341_: f32;
    var phi_1342_: f32;
    var phi_1343_: bool;
    var phi_1344_: bool;
    var phi_1362_: f32;
    var phi_1363_: f32;
    var phi_127_: u32;
    var phi_1394_: bool;

    let _e183 = global_8;
    local_127 = bitcast<f32>(_e183);
    let _e185 = global_9;
    let _e186 = bitcast<f32>(_e185);
    local_128 = _e186;
    switch bitcast<i32>(0u) {
        default: {
            let _e188 = global;
            local = _e188;
            let _e189 = global_1;
            let _e190 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e204 = global_5.member.member.member;
            let _e208 = global_5.member.member.member_1;
            local_5 = (_e204 * _e208);
            local_6 = (_e190.x * 256u);
            phi_126_ = (_e189.x * 256u);
            loop {
                let _e213 = phi_126_;
                local_7 = _e213;
                let _e214 = local_7;
                let _e215 = local_5;
                let _e216 = (_e214 < _e215);
                local_8 = _e216;
                if _e216 {
                    let _e217 = local_7;
                    let _e218 = local;
                    let _e219 = (_e217 + _e218);
                    local_9 = _e219;
                    let _e220 = local_5;
                    if (_e219 < _e220) {
                        let _e222 = local_9;
                        let _e223 = local_2;
                        if (_e222 < _e223) {
                        } else {
                            phi_1394_ = true;
                            break;
                        }
                        let _e225 = local_9;
                        let _e228 = global_3.member[_e225];
                        local_10 = _e228;
                        let _e232 = global_5.member.member.member_7;
                        if (select(3u, 4u, (_e232 == 1u)) == 4u) {
                            let _e236 = local_10;
                            phi_172_ = (f32((_e236 & 16777215u)) * 0.00000005960465f);
                        } else {
                            let _e240 = local_10;
                            phi_172_ = bitcast<f32>(_e240);
                        }
                        let _e243 = phi_172_;
                        local_11 = _e243;
                        let _e247 = global_5.member.member.member_3;
                        local_12 = _e247;
                        if (_e247 == 0u) {
                            phi_256_ = _e243;
                        } else {
                            let _e249 = local_11;
                            if (_e249 >= 0f) {
                                let _e251 = local_11;
                                let _e252 = (_e251 <= 1f);
                                local_13 = _e252;
                                if _e252 {
                                    let _e256 = global_5.member.member.member_5;
                                    local_14 = _e256;
                                    let _e257 = local_128;
                                    local_15 = (_e256 == _e257);
                                    let _e259 = local_12;
                                    if (_e259 == 1u) {
                                        let _e261 = local_15;
                                        if _e261 {
                                            let _e265 = global_5.member.member.member_4;
                                            let _e266 = local_11;
                                            phi_217_ = (1f - _e266);
                                            phi_218_ = _e265;
                                        } else {
                                            let _e271 = global_5.member.member.member_4;
                                            let _e272 = local_14;
                                            let _e274 = local_14;
                                            let _e276 = local_11;
                                            let _e278 = local_14;
                                            phi_217_ = (_e278 - (_e276 * (_e274 - _e271)));
                                            phi_218_ = (_e271 * _e272);
                                        }
                                        let _e281 = phi_217_;
                                        let _e283 = phi_218_;
                                        phi_240_ = _e281;
                                        phi_241_ = _e283;
                                    } else {
                                        let _e284 = local_15;
                                        if _e284 {
                                            let _e288 = global_5.member.member.member_4;
                                            phi_238_ = _e243;
                                            phi_239_ = _e288;
                                        } else {
                                            let _e292 = global_5.member.member.member_4;
                                            let _e293 = local_14;
                                            let _e295 = local_14;
                                            let _e297 = local_11;
                                            phi_238_ = (_e292 + (_e297 * (_e295 - _e292)));
                                            phi_239_ = (_e292 * _e293);
                                        }
                                        let _e301 = phi_238_;
                                        let _e303 = phi_239_;
                                        phi_240_ = _e301;
                                        phi_241_ = _e303;
                                    }
                                    let _e305 = phi_240_;
                                    let _e307 = phi_241_;
                                    local_16 = _e305;
                                    local_17 = _e307;
                                    if (_e305 <= 0f) {
                                        phi_247_ = _e186;
                                    } else {
                                        let _e309 = local_17;
                                        let _e310 = local_16;
                                        phi_247_ = (_e309 / _e310);
                                    }
                                    let _e313 = phi_247_;
                                    phi_248_ = _e313;
                                } else {
                                    phi_248_ = f32();
                                }
                                let _e315 = phi_248_;
                                let _e316 = local_13;
                                phi_250_ = _e315;
                                phi_251_ = select(true, false, _e316);
                            } else {
                                phi_250_ = f32();
                                phi_251_ = true;
                            }
                            let _e319 = phi_250_;
                            let _e321 = phi_251_;
                            let _e322 = local_127;
                            phi_256_ = select(_e319, _e322, _e321);
                        }
                        let _e325 = phi_256_;
                        local_18 = _e325;
                        let _e326 = local_12;
                        if (_e326 == 2u) {
                            let _e328 = local_11;
                            phi_266_ = (_e328 > 0f);
                        } else {
                            let _e330 = local_11;
                            phi_266_ = (_e330 < 1f);
                        }
                        let _e333 = phi_266_;
                        if _e333 {
                            let _e334 = local_18;
                            let _e337 = ((bitcast<u32>(_e334) & 2139095040u) != 2139095040u);
                            local_19 = _e337;
                            let _e341 = global_5.member.member.member_2;
                            local_20 = _e341;
                            if (_e341 == 1u) {
                                phi_287_ = 2u;
                            } else {
                                let _e343 = local_20;
                                phi_287_ = select(0u, 1u, (_e343 == 2u));
                            }
                            let _e347 = phi_287_;
                            local_21 = _e347;
                            if (_e347 == 1u) {
                                let _e349 = local_9;
                                let _e350 = (2u * _e349);
                                local_22 = _e350;
                                let _e351 = local_1;
                                if (_e350 < _e351) {
                                } else {
                                    phi_1394_ = true;
                                    break;
                                }
                                let _e353 = local_22;
                                let _e356 = global_4.member[_e353];
                                local_23 = _e356;
                                let _e357 = local_22;
                                let _e358 = (_e357 + 1u);
                                local_24 = _e358;
                                let _e359 = local_1;
                                if (_e358 < _e359) {
                                } else {
                                    phi_1394_ = true;
                                    break;
                                }
                                let _e361 = local_24;
                                let _e364 = global_4.member[_e361];
                                local_25 = _e364;
                                let _e365 = local_23;
                                let _e366 = (_e365 & 65535u);
                                local_26 = ((_e366 & 32768u) << bitcast<u32>(16i));
                                let _e372 = ((_e366 >> bitcast<u32>(10i)) & 31u);
                                local_27 = _e372;
                                local_28 = (_e366 & 1023u);
                                if (_e372 == 0u) {
                                    let _e375 = local_28;
                                    let _e376 = f32(_e375);
                                    local_29 = _e376;
                                    let _e378 = local_26;
                                    if (_e378 == 0u) {
                                        phi_342_ = (_e376 * 0.000000059604645f);
                                    } else {
                                        let _e380 = local_29;
                                        phi_342_ = (_e380 * -0.000000059604645f);
                                    }
                                    let _e383 = phi_342_;
                                    phi_359_ = _e383;
                                    phi_360_ = f32();
                                    phi_361_ = true;
                                } else {
                                    let _e384 = local_27;
                                    let _e385 = (_e384 == 31u);
                                    if _e385 {
                                        let _e386 = local_26;
                                        let _e388 = local_28;
                                        phi_357_ = bitcast<f32>(((_e386 | 2139095040u) | (_e388 << bitcast<u32>(13i))));
                                        phi_358_ = f32();
                                    } else {
                                        let _e393 = local_27;
                                        let _e397 = local_26;
                                        let _e399 = local_28;
                                        phi_357_ = f32();
                                        phi_358_ = bitcast<f32>(((_e397 | ((_e393 + 112u) << bitcast<u32>(23i))) | (_e399 << bitcast<u32>(13i))));
                                    }
                                    let _e405 = phi_357_;
                                    let _e407 = phi_358_;
                                    phi_359_ = _e405;
                                    phi_360_ = _e407;
                                    phi_361_ = _e385;
                                }
                                let _e409 = phi_359_;
                                let _e411 = phi_360_;
                                let _e413 = phi_361_;
                                local_115 = select(_e411, _e409, _e413);
                                let _e415 = local_23;
                                let _e417 = (_e415 >> bitcast<u32>(16i));
                                local_30 = ((_e417 & 32768u) << bitcast<u32>(16i));
                                let _e423 = ((_e417 >> bitcast<u32>(10i)) & 31u);
                                local_31 = _e423;
                                local_32 = (_e417 & 1023u);
                                if (_e423 == 0u) {
                                    let _e426 = local_32;
                                    let _e427 = f32(_e426);
                                    local_33 = _e427;
                                    let _e429 = local_30;
                                    if (_e429 == 0u) {
                                        phi_383_ = (_e427 * 0.000000059604645f);
                                    } else {
                                        let _e431 = local_33;
                                        phi_383_ = (_e431 * -0.000000059604645f);
                                    }
                                    let _e434 = phi_383_;
                                    phi_400_ = _e434;
                                    phi_401_ = f32();
                                    phi_402_ = true;
                                } else {
                                    let _e435 = local_31;
                                    let _e436 = (_e435 == 31u);
                                    if _e436 {
                                        let _e437 = local_30;
                                        let _e439 = local_32;
                                        phi_398_ = bitcast<f32>(((_e437 | 2139095040u) | (_e439 << bitcast<u32>(13i))));
                                        phi_399_ = f32();
                                    } else {
                                        let _e444 = local_31;
                                        let _e448 = local_30;
                                        let _e450 = local_32;
                                        phi_398_ = f32();
                                        phi_399_ = bitcast<f32>(((_e448 | ((_e444 + 112u) << bitcast<u32>(23i))) | (_e450 << bitcast<u32>(13i))));
                                    }
                                    let _e456 = phi_398_;
                                    let _e458 = phi_399_;
                                    phi_400_ = _e456;
                                    phi_401_ = _e458;
                                    phi_402_ = _e436;
                                }
                                let _e460 = phi_400_;
                                let _e462 = phi_401_;
                                let _e464 = phi_402_;
                                local_116 = select(_e462, _e460, _e464);
                                let _e466 = local_25;
                                let _e467 = (_e466 & 65535u);
                                local_34 = ((_e467 & 32768u) << bitcast<u32>(16i));
                                let _e473 = ((_e467 >> bitcast<u32>(10i)) & 31u);
                                local_35 = _e473;
                                local_36 = (_e467 & 1023u);
                                if (_e473 == 0u) {
                                    let _e476 = local_36;
                                    let _e477 = f32(_e476);
                                    local_37 = _e477;
                                    let _e479 = local_34;
                                    if (_e479 == 0u) {
                                        phi_424_ = (_e477 * 0.000000059604645f);
                                    } else {
                                        let _e481 = local_37;
                                        phi_424_ = (_e481 * -0.000000059604645f);
                                    }
                                    let _e484 = phi_424_;
                                    phi_441_ = _e484;
                                    phi_442_ = f32();
                                    phi_443_ = true;
                                } else {
                                    let _e485 = local_35;
                                    let _e486 = (_e485 == 31u);
                                    if _e486 {
                                        let _e487 = local_34;
                                        let _e489 = local_36;
                                        phi_439_ = bitcast<f32>(((_e487 | 2139095040u) | (_e489 << bitcast<u32>(13i))));
                                        phi_440_ = f32();
                                    } else {
                                        let _e494 = local_35;
                                        let _e498 = local_34;
                                        let _e500 = local_36;
                                        phi_439_ = f32();
                                        phi_440_ = bitcast<f32>(((_e498 | ((_e494 + 112u) << bitcast<u32>(23i))) | (_e500 << bitcast<u32>(13i))));
                                    }
                                    let _e506 = phi_439_;
                                    let _e508 = phi_440_;
                                    phi_441_ = _e506;
                                    phi_442_ = _e508;
                                    phi_443_ = _e486;
                                }
                                let _e510 = phi_441_;
                                let _e512 = phi_442_;
                                let _e514 = phi_443_;
                                local_117 = select(_e512, _e510, _e514);
                                let _e516 = local_25;
                                let _e518 = (_e516 >> bitcast<u32>(16i));
                                local_38 = ((_e518 & 32768u) << bitcast<u32>(16i));
                                let _e524 = ((_e518 >> bitcast<u32>(10i)) & 31u);
                                local_39 = _e524;
                                local_40 = (_e518 & 1023u);
                                if (_e524 == 0u) {
                                    let _e527 = local_40;
                                    let _e528 = f32(_e527);
                                    local_41 = _e528;
                                    let _e530 = local_38;
                                    if (_e530 == 0u) {
                                        phi_465_ = (_e528 * 0.000000059604645f);
                                    } else {
                                        let _e532 = local_41;
                                        phi_465_ = (_e532 * -0.000000059604645f);
                                    }
                                    let _e535 = phi_465_;
                                    phi_482_ = _e535;
                                    phi_483_ = f32();
                                    phi_484_ = true;
                                } else {
                                    let _e536 = local_39;
                                    let _e537 = (_e536 == 31u);
                                    if _e537 {
                                        let _e538 = local_38;
                                        let _e540 = local_40;
                                        phi_480_ = bitcast<f32>(((_e538 | 2139095040u) | (_e540 << bitcast<u32>(13i))));
                                        phi_481_ = f32();
                                    } else {
                                        let _e545 = local_39;
                                        let _e549 = local_38;
                                        let _e551 = local_40;
                                        phi_480_ = f32();
                                        phi_481_ = bitcast<f32>(((_e549 | ((_e545 + 112u) << bitcast<u32>(23i))) | (_e551 << bitcast<u32>(13i))));
                                    }
                                    let _e557 = phi_480_;
                                    let _e559 = phi_481_;
                                    phi_482_ = _e557;
                                    phi_483_ = _e559;
                                    phi_484_ = _e537;
                                }
                                let _e561 = phi_482_;
                                let _e563 = phi_483_;
                                let _e565 = phi_484_;
                                let _e567 = local_115;
                                let _e568 = local_116;
                                let _e569 = local_117;
                                phi_711_ = array<f32, 4>(_e567, _e568, _e569, select(_e563, _e561, _e565));
                            } else {
                                let _e571 = local_21;
                                if (_e571 == 2u) {
                                    let _e573 = local_9;
                                    let _e574 = local_1;
                                    if (_e573 < _e574) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e576 = local_9;
                                    let _e579 = global_4.member[_e576];
                                    local_42 = _e579;
                                    let _e580 = (_e579 & 2047u);
                                    let _e583 = ((_e580 >> bitcast<u32>(6u)) & 31u);
                                    local_43 = _e583;
                                    local_44 = (_e580 & 63u);
                                    if (_e583 == 0u) {
                                        let _e586 = local_44;
                                        phi_544_ = (f32(_e586) * 0.0000009536743f);
                                        phi_545_ = f32();
                                        phi_546_ = true;
                                    } else {
                                        let _e589 = local_43;
                                        let _e590 = (_e589 == 31u);
                                        if _e590 {
                                            let _e591 = local_44;
                                            phi_542_ = bitcast<f32>((2139095040u | (_e591 << bitcast<u32>(17u))));
                                            phi_543_ = f32();
                                        } else {
                                            let _e596 = local_43;
                                            let _e600 = local_44;
                                            phi_542_ = f32();
                                            phi_543_ = bitcast<f32>((((_e596 + 112u) << bitcast<u32>(23i)) | (_e600 << bitcast<u32>(17u))));
                                        }
                                        let _e606 = phi_542_;
                                        let _e608 = phi_543_;
                                        phi_544_ = _e606;
                                        phi_545_ = _e608;
                                        phi_546_ = _e590;
                                    }
                                    let _e610 = phi_544_;
                                    let _e612 = phi_545_;
                                    let _e614 = phi_546_;
                                    local_118 = select(_e612, _e610, _e614);
                                    let _e616 = local_42;
                                    let _e619 = ((_e616 >> bitcast<u32>(11i)) & 2047u);
                                    let _e622 = ((_e619 >> bitcast<u32>(6u)) & 31u);
                                    local_45 = _e622;
                                    local_46 = (_e619 & 63u);
                                    if (_e622 == 0u) {
                                        let _e625 = local_46;
                                        phi_587_ = (f32(_e625) * 0.0000009536743f);
                                        phi_588_ = f32();
                                        phi_589_ = true;
                                    } else {
                                        let _e628 = local_45;
                                        let _e629 = (_e628 == 31u);
                                        if _e629 {
                                            let _e630 = local_46;
                                            phi_585_ = bitcast<f32>((2139095040u | (_e630 << bitcast<u32>(17u))));
                                            phi_586_ = f32();
                                        } else {
                                            let _e635 = local_45;
                                            let _e639 = local_46;
                                            phi_585_ = f32();
                                            phi_586_ = bitcast<f32>((((_e635 + 112u) << bitcast<u32>(23i)) | (_e639 << bitcast<u32>(17u))));
                                        }
                                        let _e645 = phi_585_;
                                        let _e647 = phi_586_;
                                        phi_587_ = _e645;
                                        phi_588_ = _e647;
                                        phi_589_ = _e629;
                                    }
                                    let _e649 = phi_587_;
                                    let _e651 = phi_588_;
                                    let _e653 = phi_589_;
                                    local_119 = select(_e651, _e649, _e653);
                                    let _e655 = local_42;
                                    let _e657 = (_e655 >> bitcast<u32>(22i));
                                    let _e660 = ((_e657 >> bitcast<u32>(5u)) & 31u);
                                    local_47 = _e660;
                                    local_48 = (_e657 & 31u);
                                    if (_e660 == 0u) {
                                        let _e663 = local_48;
                                        phi_629_ = (f32(_e663) * 0.0000019073486f);
                                        phi_630_ = f32();
                                        phi_631_ = true;
                                    } else {
                                        let _e666 = local_47;
                                        let _e667 = (_e666 == 31u);
                                        if _e667 {
                                            let _e668 = local_48;
                                            phi_627_ = bitcast<f32>((2139095040u | (_e668 << bitcast<u32>(18u))));
                                            phi_628_ = f32();
                                        } else {
                                            let _e673 = local_47;
                                            let _e677 = local_48;
                                            phi_627_ = f32();
                                            phi_628_ = bitcast<f32>((((_e673 + 112u) << bitcast<u32>(23i)) | (_e677 << bitcast<u32>(18u))));
                                        }
                                        let _e683 = phi_627_;
                                        let _e685 = phi_628_;
                                        phi_629_ = _e683;
                                        phi_630_ = _e685;
                                        phi_631_ = _e667;
                                    }
                                    let _e687 = phi_629_;
                                    let _e689 = phi_630_;
                                    let _e691 = phi_631_;
                                    let _e693 = local_118;
                                    let _e694 = local_119;
                                    phi_710_ = array<f32, 4>(_e693, _e694, select(_e689, _e687, _e691), 1f);
                                } else {
                                    let _e696 = local_9;
                                    let _e697 = (4u * _e696);
                                    local_49 = _e697;
                                    let _e698 = local_1;
                                    if (_e697 < _e698) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e700 = local_49;
                                    let _e703 = global_4.member[_e700];
                                    local_50 = bitcast<f32>(_e703);
                                    let _e705 = local_49;
                                    let _e706 = (_e705 + 1u);
                                    local_51 = _e706;
                                    let _e707 = local_1;
                                    if (_e706 < _e707) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e709 = local_51;
                                    let _e712 = global_4.member[_e709];
                                    local_52 = bitcast<f32>(_e712);
                                    let _e714 = local_49;
                                    let _e715 = (_e714 + 2u);
                                    local_53 = _e715;
                                    let _e716 = local_1;
                                    if (_e715 < _e716) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e718 = local_53;
                                    let _e721 = global_4.member[_e718];
                                    local_54 = bitcast<f32>(_e721);
                                    let _e723 = local_49;
                                    let _e724 = (_e723 + 3u);
                                    local_55 = _e724;
                                    let _e725 = local_1;
                                    if (_e724 < _e725) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e727 = local_55;
                                    let _e730 = global_4.member[_e727];
                                    let _e732 = local_50;
                                    let _e733 = local_52;
                                    let _e734 = local_54;
                                    phi_710_ = array<f32, 4>(_e732, _e733, _e734, bitcast<f32>(_e730));
                                }
                                let _e737 = phi_710_;
                                phi_711_ = _e737;
                            }
                            let _e739 = phi_711_;
                            local_56 = _e739;
                            let _e740 = local_19;
                            if _e740 {
                                let _e741 = local_56;
                                let _e743 = local_56;
                                let _e745 = local_56;
                                let _e748 = local_56;
                                phi_720_ = array<f32, 3>(_e741[0], _e743[1], _e745[2]);
                                phi_721_ = _e748[3];
                            } else {
                                phi_720_ = array<f32, 3>();
                                phi_721_ = f32();
                            }
                            let _e751 = phi_720_;
                            let _e753 = phi_721_;
                            let _e754 = local_19;
                            phi_1162_ = _e751;
                            phi_1163_ = _e753;
                            phi_1164_ = _e337;
                            phi_1165_ = _e739;
                            phi_1166_ = _e337;
                            phi_1167_ = select(true, false, _e754);
                        } else {
                            let _e759 = global_5.member.member.member_2;
                            local_57 = _e759;
                            if (_e759 == 1u) {
                                phi_737_ = 2u;
                            } else {
                                let _e761 = local_57;
                                phi_737_ = select(0u, 1u, (_e761 == 2u));
                            }
                            let _e765 = phi_737_;
                            local_58 = _e765;
                            if (_e765 == 1u) {
                                let _e767 = local_9;
                                let _e768 = (2u * _e767);
                                local_59 = _e768;
                                let _e769 = local_1;
                                if (_e768 < _e769) {
                                } else {
                                    phi_1394_ = true;
                                    break;
                                }
                                let _e771 = local_59;
                                let _e774 = global_4.member[_e771];
                                local_60 = _e774;
                                let _e775 = local_59;
                                let _e776 = (_e775 + 1u);
                                local_61 = _e776;
                                let _e777 = local_1;
                                if (_e776 < _e777) {
                                } else {
                                    phi_1394_ = true;
                                    break;
                                }
                                let _e779 = local_61;
                                let _e782 = global_4.member[_e779];
                                local_62 = _e782;
                                let _e783 = local_60;
                                let _e784 = (_e783 & 65535u);
                                local_63 = ((_e784 & 32768u) << bitcast<u32>(16i));
                                let _e790 = ((_e784 >> bitcast<u32>(10i)) & 31u);
                                local_64 = _e790;
                                local_65 = (_e784 & 1023u);
                                if (_e790 == 0u) {
                                    let _e793 = local_65;
                                    let _e794 = f32(_e793);
                                    local_66 = _e794;
                                    let _e796 = local_63;
                                    if (_e796 == 0u) {
                                        phi_792_ = (_e794 * 0.000000059604645f);
                                    } else {
                                        let _e798 = local_66;
                                        phi_792_ = (_e798 * -0.000000059604645f);
                                    }
                                    let _e801 = phi_792_;
                                    phi_809_ = _e801;
                                    phi_810_ = f32();
                                    phi_811_ = true;
                                } else {
                                    let _e802 = local_64;
                                    let _e803 = (_e802 == 31u);
                                    if _e803 {
                                        let _e804 = local_63;
                                        let _e806 = local_65;
                                        phi_807_ = bitcast<f32>(((_e804 | 2139095040u) | (_e806 << bitcast<u32>(13i))));
                                        phi_808_ = f32();
                                    } else {
                                        let _e811 = local_64;
                                        let _e815 = local_63;
                                        let _e817 = local_65;
                                        phi_807_ = f32();
                                        phi_808_ = bitcast<f32>(((_e815 | ((_e811 + 112u) << bitcast<u32>(23i))) | (_e817 << bitcast<u32>(13i))));
                                    }
                                    let _e823 = phi_807_;
                                    let _e825 = phi_808_;
                                    phi_809_ = _e823;
                                    phi_810_ = _e825;
                                    phi_811_ = _e803;
                                }
                                let _e827 = phi_809_;
                                let _e829 = phi_810_;
                                let _e831 = phi_811_;
                                local_120 = select(_e829, _e827, _e831);
                                let _e833 = local_60;
                                let _e835 = (_e833 >> bitcast<u32>(16i));
                                local_67 = ((_e835 & 32768u) << bitcast<u32>(16i));
                                let _e841 = ((_e835 >> bitcast<u32>(10i)) & 31u);
                                local_68 = _e841;
                                local_69 = (_e835 & 1023u);
                                if (_e841 == 0u) {
                                    let _e844 = local_69;
                                    let _e845 = f32(_e844);
                                    local_70 = _e845;
                                    let _e847 = local_67;
                                    if (_e847 == 0u) {
                                        phi_833_ = (_e845 * 0.000000059604645f);
                                    } else {
                                        let _e849 = local_70;
                                        phi_833_ = (_e849 * -0.000000059604645f);
                                    }
                                    let _e852 = phi_833_;
                                    phi_850_ = _e852;
                                    phi_851_ = f32();
                                    phi_852_ = true;
                                } else {
                                    let _e853 = local_68;
                                    let _e854 = (_e853 == 31u);
                                    if _e854 {
                                        let _e855 = local_67;
                                        let _e857 = local_69;
                                        phi_848_ = bitcast<f32>(((_e855 | 2139095040u) | (_e857 << bitcast<u32>(13i))));
                                        phi_849_ = f32();
                                    } else {
                                        let _e862 = local_68;
                                        let _e866 = local_67;
                                        let _e868 = local_69;
                                        phi_848_ = f32();
                                        phi_849_ = bitcast<f32>(((_e866 | ((_e862 + 112u) << bitcast<u32>(23i))) | (_e868 << bitcast<u32>(13i))));
                                    }
                                    let _e874 = phi_848_;
                                    let _e876 = phi_849_;
                                    phi_850_ = _e874;
                                    phi_851_ = _e876;
                                    phi_852_ = _e854;
                                }
                                let _e878 = phi_850_;
                                let _e880 = phi_851_;
                                let _e882 = phi_852_;
                                local_121 = select(_e880, _e878, _e882);
                                let _e884 = local_62;
                                let _e885 = (_e884 & 65535u);
                                local_71 = ((_e885 & 32768u) << bitcast<u32>(16i));
                                let _e891 = ((_e885 >> bitcast<u32>(10i)) & 31u);
                                local_72 = _e891;
                                local_73 = (_e885 & 1023u);
                                if (_e891 == 0u) {
                                    let _e894 = local_73;
                                    let _e895 = f32(_e894);
                                    local_74 = _e895;
                                    let _e897 = local_71;
                                    if (_e897 == 0u) {
                                        phi_874_ = (_e895 * 0.000000059604645f);
                                    } else {
                                        let _e899 = local_74;
                                        phi_874_ = (_e899 * -0.000000059604645f);
                                    }
                                    let _e902 = phi_874_;
                                    phi_891_ = _e902;
                                    phi_892_ = f32();
                                    phi_893_ = true;
                                } else {
                                    let _e903 = local_72;
                                    let _e904 = (_e903 == 31u);
                                    if _e904 {
                                        let _e905 = local_71;
                                        let _e907 = local_73;
                                        phi_889_ = bitcast<f32>(((_e905 | 2139095040u) | (_e907 << bitcast<u32>(13i))));
                                        phi_890_ = f32();
                                    } else {
                                        let _e912 = local_72;
                                        let _e916 = local_71;
                                        let _e918 = local_73;
                                        phi_889_ = f32();
                                        phi_890_ = bitcast<f32>(((_e916 | ((_e912 + 112u) << bitcast<u32>(23i))) | (_e918 << bitcast<u32>(13i))));
                                    }
                                    let _e924 = phi_889_;
                                    let _e926 = phi_890_;
                                    phi_891_ = _e924;
                                    phi_892_ = _e926;
                                    phi_893_ = _e904;
                                }
                                let _e928 = phi_891_;
                                let _e930 = phi_892_;
                                let _e932 = phi_893_;
                                local_122 = select(_e930, _e928, _e932);
                                let _e934 = local_62;
                                let _e936 = (_e934 >> bitcast<u32>(16i));
                                local_75 = ((_e936 & 32768u) << bitcast<u32>(16i));
                                let _e942 = ((_e936 >> bitcast<u32>(10i)) & 31u);
                                local_76 = _e942;
                                local_77 = (_e936 & 1023u);
                                if (_e942 == 0u) {
                                    let _e945 = local_77;
                                    let _e946 = f32(_e945);
                                    local_78 = _e946;
                                    let _e948 = local_75;
                                    if (_e948 == 0u) {
                                        phi_915_ = (_e946 * 0.000000059604645f);
                                    } else {
                                        let _e950 = local_78;
                                        phi_915_ = (_e950 * -0.000000059604645f);
                                    }
                                    let _e953 = phi_915_;
                                    phi_932_ = _e953;
                                    phi_933_ = f32();
                                    phi_934_ = true;
                                } else {
                                    let _e954 = local_76;
                                    let _e955 = (_e954 == 31u);
                                    if _e955 {
                                        let _e956 = local_75;
                                        let _e958 = local_77;
                                        phi_930_ = bitcast<f32>(((_e956 | 2139095040u) | (_e958 << bitcast<u32>(13i))));
                                        phi_931_ = f32();
                                    } else {
                                        let _e963 = local_76;
                                        let _e967 = local_75;
                                        let _e969 = local_77;
                                        phi_930_ = f32();
                                        phi_931_ = bitcast<f32>(((_e967 | ((_e963 + 112u) << bitcast<u32>(23i))) | (_e969 << bitcast<u32>(13i))));
                                    }
                                    let _e975 = phi_930_;
                                    let _e977 = phi_931_;
                                    phi_932_ = _e975;
                                    phi_933_ = _e977;
                                    phi_934_ = _e955;
                                }
                                let _e979 = phi_932_;
                                let _e981 = phi_933_;
                                let _e983 = phi_934_;
                                let _e985 = local_120;
                                let _e986 = local_121;
                                let _e987 = local_122;
                                phi_1161_ = array<f32, 4>(_e985, _e986, _e987, select(_e981, _e979, _e983));
                            } else {
                                let _e989 = local_58;
                                if (_e989 == 2u) {
                                    let _e991 = local_9;
                                    let _e992 = local_1;
                                    if (_e991 < _e992) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e994 = local_9;
                                    let _e997 = global_4.member[_e994];
                                    local_79 = _e997;
                                    let _e998 = (_e997 & 2047u);
                                    let _e1001 = ((_e998 >> bitcast<u32>(6u)) & 31u);
                                    local_80 = _e1001;
                                    local_81 = (_e998 & 63u);
                                    if (_e1001 == 0u) {
                                        let _e1004 = local_81;
                                        phi_994_ = (f32(_e1004) * 0.0000009536743f);
                                        phi_995_ = f32();
                                        phi_996_ = true;
                                    } else {
                                        let _e1007 = local_80;
                                        let _e1008 = (_e1007 == 31u);
                                        if _e1008 {
                                            let _e1009 = local_81;
                                            phi_992_ = bitcast<f32>((2139095040u | (_e1009 << bitcast<u32>(17u))));
                                            phi_993_ = f32();
                                        } else {
                                            let _e1014 = local_80;
                                            let _e1018 = local_81;
                                            phi_992_ = f32();
                                            phi_993_ = bitcast<f32>((((_e1014 + 112u) << bitcast<u32>(23i)) | (_e1018 << bitcast<u32>(17u))));
                                        }
                                        let _e1024 = phi_992_;
                                        let _e1026 = phi_993_;
                                        phi_994_ = _e1024;
                                        phi_995_ = _e1026;
                                        phi_996_ = _e1008;
                                    }
                                    let _e1028 = phi_994_;
                                    let _e1030 = phi_995_;
                                    let _e1032 = phi_996_;
                                    local_123 = select(_e1030, _e1028, _e1032);
                                    let _e1034 = local_79;
                                    let _e1037 = ((_e1034 >> bitcast<u32>(11i)) & 2047u);
                                    let _e1040 = ((_e1037 >> bitcast<u32>(6u)) & 31u);
                                    local_82 = _e1040;
                                    local_83 = (_e1037 & 63u);
                                    if (_e1040 == 0u) {
                                        let _e1043 = local_83;
                                        phi_1037_ = (f32(_e1043) * 0.0000009536743f);
                                        phi_1038_ = f32();
                                        phi_1039_ = true;
                                    } else {
                                        let _e1046 = local_82;
                                        let _e1047 = (_e1046 == 31u);
                                        if _e1047 {
                                            let _e1048 = local_83;
                                            phi_1035_ = bitcast<f32>((2139095040u | (_e1048 << bitcast<u32>(17u))));
                                            phi_1036_ = f32();
                                        } else {
                                            let _e1053 = local_82;
                                            let _e1057 = local_83;
                                            phi_1035_ = f32();
                                            phi_1036_ = bitcast<f32>((((_e1053 + 112u) << bitcast<u32>(23i)) | (_e1057 << bitcast<u32>(17u))));
                                        }
                                        let _e1063 = phi_1035_;
                                        let _e1065 = phi_1036_;
                                        phi_1037_ = _e1063;
                                        phi_1038_ = _e1065;
                                        phi_1039_ = _e1047;
                                    }
                                    let _e1067 = phi_1037_;
                                    let _e1069 = phi_1038_;
                                    let _e1071 = phi_1039_;
                                    local_124 = select(_e1069, _e1067, _e1071);
                                    let _e1073 = local_79;
                                    let _e1075 = (_e1073 >> bitcast<u32>(22i));
                                    let _e1078 = ((_e1075 >> bitcast<u32>(5u)) & 31u);
                                    local_84 = _e1078;
                                    local_85 = (_e1075 & 31u);
                                    if (_e1078 == 0u) {
                                        let _e1081 = local_85;
                                        phi_1079_ = (f32(_e1081) * 0.0000019073486f);
                                        phi_1080_ = f32();
                                        phi_1081_ = true;
                                    } else {
                                        let _e1084 = local_84;
                                        let _e1085 = (_e1084 == 31u);
                                        if _e1085 {
                                            let _e1086 = local_85;
                                            phi_1077_ = bitcast<f32>((2139095040u | (_e1086 << bitcast<u32>(18u))));
                                            phi_1078_ = f32();
                                        } else {
                                            let _e1091 = local_84;
                                            let _e1095 = local_85;
                                            phi_1077_ = f32();
                                            phi_1078_ = bitcast<f32>((((_e1091 + 112u) << bitcast<u32>(23i)) | (_e1095 << bitcast<u32>(18u))));
                                        }
                                        let _e1101 = phi_1077_;
                                        let _e1103 = phi_1078_;
                                        phi_1079_ = _e1101;
                                        phi_1080_ = _e1103;
                                        phi_1081_ = _e1085;
                                    }
                                    let _e1105 = phi_1079_;
                                    let _e1107 = phi_1080_;
                                    let _e1109 = phi_1081_;
                                    let _e1111 = local_123;
                                    let _e1112 = local_124;
                                    phi_1160_ = array<f32, 4>(_e1111, _e1112, select(_e1107, _e1105, _e1109), 1f);
                                } else {
                                    let _e1114 = local_9;
                                    let _e1115 = (4u * _e1114);
                                    local_86 = _e1115;
                                    let _e1116 = local_1;
                                    if (_e1115 < _e1116) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e1118 = local_86;
                                    let _e1121 = global_4.member[_e1118];
                                    local_87 = bitcast<f32>(_e1121);
                                    let _e1123 = local_86;
                                    let _e1124 = (_e1123 + 1u);
                                    local_88 = _e1124;
                                    let _e1125 = local_1;
                                    if (_e1124 < _e1125) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e1127 = local_88;
                                    let _e1130 = global_4.member[_e1127];
                                    local_89 = bitcast<f32>(_e1130);
                                    let _e1132 = local_86;
                                    let _e1133 = (_e1132 + 2u);
                                    local_90 = _e1133;
                                    let _e1134 = local_1;
                                    if (_e1133 < _e1134) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e1136 = local_90;
                                    let _e1139 = global_4.member[_e1136];
                                    local_91 = bitcast<f32>(_e1139);
                                    let _e1141 = local_86;
                                    let _e1142 = (_e1141 + 3u);
                                    local_92 = _e1142;
                                    let _e1143 = local_1;
                                    if (_e1142 < _e1143) {
                                    } else {
                                        phi_1394_ = true;
                                        break;
                                    }
                                    let _e1145 = local_92;
                                    let _e1148 = global_4.member[_e1145];
                                    let _e1150 = local_87;
                                    let _e1151 = local_89;
                                    let _e1152 = local_91;
                                    phi_1160_ = array<f32, 4>(_e1150, _e1151, _e1152, bitcast<f32>(_e1148));
                                }
                                let _e1155 = phi_1160_;
                                phi_1161_ = _e1155;
                            }
                            let _e1157 = phi_1161_;
                            phi_1162_ = array<f32, 3>();
                            phi_1163_ = f32();
                            phi_1164_ = bool();
                            phi_1165_ = _e1157;
                            phi_1166_ = false;
                            phi_1167_ = true;
                        }
                        let _e1159 = phi_1162_;
                        let _e1161 = phi_1163_;
                        let _e1163 = phi_1164_;
                        let _e1165 = phi_1165_;
                        let _e1167 = phi_1166_;
                        let _e1169 = phi_1167_;
                        local_93 = _e1163;
                        local_94 = _e1165;
                        local_95 = _e1167;
                        local_96 = _e1169;
                        if _e1169 {
                            let _e1170 = local_9;
                            let _e1171 = local_3;
                            if (_e1170 < _e1171) {
                            } else {
                                phi_1394_ = true;
                                break;
                            }
                            let _e1173 = local_9;
                            let _e1176 = global_6.member[_e1173];
                            let _e1180 = ((bitcast<u32>(bitcast<f32>(_e1176)) & 2139095040u) != 2139095040u);
                            local_97 = _e1180;
                            if _e1180 {
                                let _e1181 = local_94;
                                let _e1183 = local_94;
                                let _e1185 = local_94;
                                phi_1197_ = array<f32, 3>(_e1181[0], _e1183[1], _e1185[2]);
                            } else {
                                phi_1197_ = array<f32, 3>(0f, 0f, 0f);
                            }
                            let _e1189 = phi_1197_;
                            let _e1190 = local_97;
                            phi_1199_ = _e1189;
                            phi_1200_ = select(0f, 1f, _e1190);
                        } else {
                            phi_1199_ = _e1159;
                            phi_1200_ = _e1161;
                        }
                        let _e1193 = phi_1199_;
                        let _e1195 = phi_1200_;
                        local_98 = _e1193;
                        local_99 = _e1195;
                        let _e1196 = local_96;
                        let _e1197 = local_95;
                        let _e1198 = local_93;
                        local_125 = select(_e1198, _e1197, _e1196);
                        let _e1200 = local_96;
                        let _e1201 = local_128;
                        let _e1202 = local_18;
                        let _e1203 = select(_e1202, _e1201, _e1200);
                        local_126 = _e1203;
                        let _e1204 = local_9;
                        let _e1205 = (5u * _e1204);
                        local_100 = _e1205;
                        local_101 = bitcast<u32>(_e1193[0]);
                        let _e1208 = local_4;
                        if (_e1205 < _e1208) {
                        } else {
                            phi_1394_ = true;
                            break;
                        }
                        let _e1210 = local_100;
                        let _e1213 = local_101;
                        global_7.member[_e1210] = _e1213;
                        let _e1214 = local_100;
                        let _e1215 = (_e1214 + 1u);
                        local_102 = _e1215;
                        let _e1216 = local_98;
                        local_103 = bitcast<u32>(_e1216[1]);
                        let _e1219 = local_4;
                        if (_e1215 < _e1219) {
                        } else {
                            phi_1394_ = true;
                            break;
                        }
                        let _e1221 = local_102;
                        let _e1224 = local_103;
                        global_7.member[_e1221] = _e1224;
                        let _e1225 = local_100;
                        let _e1226 = (_e1225 + 2u);
                        local_104 = _e1226;
                        let _e1227 = local_98;
                        local_105 = bitcast<u32>(_e1227[2]);
                        let _e1230 = local_4;
                        if (_e1226 < _e1230) {
                        } else {
                            phi_1394_ = true;
                            break;
                        }
                        let _e1232 = local_104;
                        let _e1235 = local_105;
                        global_7.member[_e1232] = _e1235;
                        let _e1236 = local_100;
                        let _e1237 = (_e1236 + 3u);
                        local_106 = _e1237;
                        let _e1238 = local_99;
                        local_107 = bitcast<u32>(_e1238);
                        let _e1240 = local_4;
                        if (_e1237 < _e1240) {
                        } else {
                            phi_1394_ = true;
                            break;
                        }
                        let _e1242 = local_106;
                        let _e1245 = local_107;
                        global_7.member[_e1242] = _e1245;
                        let _e1246 = local_100;
                        let _e1247 = (_e1246 + 4u);
                        local_108 = _e1247;
                        let _e1248 = local_126;
                        local_109 = bitcast<u32>(_e1248);
                        let _e1250 = local_4;
                        if (_e1247 < _e1250) {
                        } else {
                            phi_1394_ = true;
                            break;
                        }
                        let _e1252 = local_108;
                        let _e1255 = local_109;
                        global_7.member[_e1252] = _e1255;
                        let _e1258 = global_5.member.member_2;
                        local_110 = _e1258;
                        let _e1259 = local_125;
                        if _e1259 {
                            let _e1260 = local_99;
                            if (_e1260 < 1f) {
                                phi_1362_ = _e1203;
                            } else {
                                let _e1262 = local_126;
                                let _e1263 = local_110;
                                local_111 = (_e1262 * _e1263);
                                let _e1265 = local_109;
                                if (_e1265 == 0u) {
                                    phi_1303_ = false;
                                } else {
                                    let _e1267 = local_109;
                                    phi_1303_ = (_e1267 <= 2139095040u);
                                }
                                let _e1270 = phi_1303_;
                                if _e1270 {
                                    let _e1271 = local_111;
                                    if (_e1271 >= 0f) {
                                        let _e1273 = local_111;
                                        let _e1276 = ((bitcast<u32>(_e1273) & 2147483647u) > 2139095040u);
                                        if _e1276 {
                                            phi_1334_ = f32();
                                            phi_1335_ = f32();
                                            phi_1336_ = false;
                                        } else {
                                            let _e1277 = local_111;
                                            let _e1278 = (_e1277 == 0f);
                                            local_112 = _e1278;
                                            if _e1278 {
                                                phi_1332_ = f32();
                                                phi_1333_ = true;
                                            } else {
                                                let _e1282 = global_5.member.member_1.member_1;
                                                local_113 = _e1282;
                                                let _e1283 = local_111;
                                                let _e1284 = (_e1283 >= _e1282);
                                                if _e1284 {
                                                    phi_1330_ = f32();
                                                } else {
                                                    let _e1285 = local_111;
                                                    let _e1286 = local_126;
                                                    let _e1288 = local_113;
                                                    let _e1289 = local_111;
                                                    phi_1330_ = ((_e1285 * _e1286) / (_e1288 - _e1289));
                                                }
                                                let _e1293 = phi_1330_;
                                                phi_1332_ = _e1293;
                                                phi_1333_ = _e1284;
                                            }
                                            let _e1295 = phi_1332_;
                                            let _e1297 = phi_1333_;
                                            let _e1298 = local_112;
                                            let _e1299 = local_128;
                                            phi_1334_ = select(_e1299, 0f, _e1298);
                                            phi_1335_ = _e1295;
                                            phi_1336_ = _e1297;
                                        }
                                        let _e1302 = phi_1334_;
                                        let _e1304 = phi_1335_;
                                        let _e1306 = phi_1336_;
                                        phi_1337_ = _e1302;
                                        phi_1338_ = _e1304;
                                        phi_1339_ = _e1276;
                                        phi_1340_ = _e1306;
                                    } else {
                                        phi_1337_ = f32();
                                        phi_1338_ = f32();
                                        phi_1339_ = true;
                                        phi_1340_ = false;
                                    }
                                    let _e1308 = phi_1337_;
                                    let _e1310 = phi_1338_;
                                    let _e1312 = phi_1339_;
                                    let _e1314 = phi_1340_;
                                    phi_1341_ = _e1308;
                                    phi_1342_ = _e1310;
                                    phi_1343_ = _e1312;
                                    phi_1344_ = _e1314;
                                } else {
                                    phi_1341_ = f32();
                                    phi_1342_ = f32();
                                    phi_1343_ = true;
                                    phi_1344_ = false;
                                }
                                let _e1316 = phi_1341_;
                                let _e1318 = phi_1342_;
                                let _e1320 = phi_1343_;
                                let _e1322 = phi_1344_;
                                let _e1323 = local_127;
                                let _e1327 = local_126;
                                let _e1328 = (_e1327 + select(_e1318, select(_e1316, _e1323, _e1320), select(_e1322, true, _e1320)));
                                let _e1332 = local_128;
                                phi_1362_ = select(_e1332, _e1328, ((bitcast<u32>(_e1328) & 2139095040u) != 2139095040u));
                            }
                            let _e1335 = phi_1362_;
                            phi_1363_ = _e1335;
                        } else {
                            phi_1363_ = _e186;
                        }
                        let _e1337 = phi_1363_;
                        local_114 = bitcast<u32>(_e1337);
                        let _e1339 = local_9;
                        let _e1340 = local_3;
                        if (_e1339 < _e1340) {
                        } else {
                            phi_1394_ = true;
                            break;
                        }
                        let _e1342 = local_9;
                        let _e1345 = local_114;
                        global_6.member[_e1342] = _e1345;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e1346 = local_7;
                    let _e1347 = local_6;
                    phi_127_ = (_e1346 + _e1347);
                } else {
                    phi_127_ = u32();
                }
                let _e1350 = phi_127_;
                continue;
                continuing {
                    let _e1351 = local_8;
                    phi_126_ = _e1350;
                    phi_1394_ = false;
                    break if !(_e1351);
                }
            }
            let _e1354 = phi_1394_;
            if _e1354 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn peel_renderer_layer(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
