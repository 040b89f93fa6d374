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
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: f32,
    member_6: array<u32, 2>,
    member_7: type_5,
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
@group(0) @binding(1) 
var<storage> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_7;
var<immediate> global_5: type_16;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_24;
var<private> global_7: u32 = 2143289344u;
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
    var local_8: bool;
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: bool;
    var local_15: u32;
    var local_16: u32;
    var local_17: bool;
    var local_18: u32;
    var local_19: bool;
    var local_20: i32;
    var local_21: u32;
    var local_22: u32;
    var local_23: i32;
    var local_24: i32;
    var local_25: u32;
    var local_26: u32;
    var local_27: f32;
    var local_28: i32;
    var local_29: u32;
    var local_30: u32;
    var local_31: f32;
    var local_32: u32;
    var local_33: u32;
    var local_34: f32;
    var local_35: i32;
    var local_36: u32;
    var local_37: bool;
    var local_38: u32;
    var local_39: bool;
    var local_40: u32;
    var local_41: u32;
    var local_42: bool;
    var local_43: f32;
    var local_44: bool;
    var local_45: u32;
    var local_46: f32;
    var local_47: u32;
    var local_48: f32;
    var local_49: u32;
    var local_50: f32;
    var local_51: u32;
    var local_52: f32;
    var local_53: u32;
    var local_54: f32;
    var local_55: bool;
    var local_56: u32;
    var local_57: f32;
    var local_58: f32;
    var local_59: bool;
    var local_60: u32;
    var local_61: u32;
    var local_62: u32;
    var local_63: bool;
    var local_64: u32;
    var local_65: u32;
    var local_66: bool;
    var local_67: u32;
    var local_68: bool;
    var local_69: i32;
    var local_70: u32;
    var local_71: u32;
    var local_72: i32;
    var local_73: i32;
    var local_74: u32;
    var local_75: u32;
    var local_76: f32;
    var local_77: i32;
    var local_78: u32;
    var local_79: u32;
    var local_80: f32;
    var local_81: u32;
    var local_82: u32;
    var local_83: f32;
    var local_84: i32;
    var local_85: u32;
    var local_86: bool;
    var local_87: u32;
    var local_88: bool;
    var local_89: u32;
    var local_90: bool;
    var local_91: f32;
    var local_92: u32;
    var local_93: f32;
    var local_94: bool;
    var local_95: u32;
    var local_96: f32;
    var local_97: u32;
    var local_98: f32;
    var local_99: u32;
    var local_100: f32;
    var local_101: u32;
    var local_102: f32;
    var local_103: bool;
    var local_104: u32;
    var local_105: u32;
    var local_106: f32;
    var local_107: f32;
    var local_108: f32;
    var local_109: f32;
    var local_110: bool;
    var local_111: u32;
    var local_112: u32;
    var local_113: u32;
    var local_114: bool;
    var local_115: u32;
    var local_116: u32;
    var local_117: bool;
    var local_118: u32;
    var local_119: bool;
    var local_120: i32;
    var local_121: u32;
    var local_122: u32;
    var local_123: i32;
    var local_124: i32;
    var local_125: u32;
    var local_126: u32;
    var local_127: f32;
    var local_128: i32;
    var local_129: u32;
    var local_130: u32;
    var local_131: f32;
    var local_132: u32;
    var local_133: u32;
    var local_134: f32;
    var local_135: i32;
    var local_136: u32;
    var local_137: u32;
    var local_138: f32;
    var local_139: bool;
    var local_140: bool;
    var local_141: bool;
    var local_142: u32;
    var local_143: bool;
    var local_144: u32;
    var local_145: u32;
    var local_146: u32;
    var local_147: u32;
    var local_148: u32;
    var local_149: u32;
    var local_150: bool;
    var local_151: bool;
    var local_152: u32;
    var local_153: u32;
    var local_154: bool;
    var local_155: u32;
    var local_156: bool;
    var local_157: u32;
    var local_158: f32;
    var phi_1896_: bool;
    var phi_110_: u32;
    var phi_187_: u32;
    var phi_190_: u32;
    var phi_223_: u32;
    var phi_188_: u32;
    var phi_191_: u32;
    var phi_1890_: bool;
    var phi_229_: u32;
    var phi_239_: u32;
    var phi_282_: f32;
    var phi_283_: f32;
    var phi_287_: bool;
    var phi_321_: f32;
    var phi_322_: f32;
    var phi_352_: f32;
    var phi_353_: f32;
    var phi_382_: f32;
    var phi_383_: f32;
    var phi_487_: bool;
    var phi_502_: f32;
    var phi_504_: f32;
    var phi_505_: bool;
    var phi_510_: f32;
    var phi_240_: u32;
    var phi_1898_: bool;
    var phi_1926_: bool;
    var phi_552_: f32;
    var phi_553_: u32;
    var phi_555_: u32;
    var phi_558_: bool;
    var phi_560_: f32;
    var phi_681_: bool;
    var phi_682_: bool;
    var phi_684_: bool;
    var phi_685_: bool;
    var phi_686_: bool;
    var phi_687_: bool;
    var phi_704_: f32;
    var phi_708_: f32;
    var phi_556_: u32;
    var phi_559_: bool;
    var phi_561_: f32;
    var phi_1923_: bool;
    var phi_714_: bool;
    var phi_741_: u32;
    var phi_754_: u32;
    var phi_757_: u32;
    var phi_790_: u32;
    var phi_755_: u32;
    var phi_758_: u32;
    var phi_1935_: bool;
    var phi_796_: u32;
    var phi_806_: u32;
    var phi_849_: f32;
    var phi_850_: f32;
    var phi_854_: bool;
    var phi_888_: f32;
    var phi_889_: f32;
    var phi_919_: f32;
    var phi_920_: f32;
    var phi_949_: f32;
    var phi_950_: f32;
    var phi_1054_: bool;
    var phi_1069_: f32;
    var phi_1071_: f32;
    var phi_1072_: bool;
    var phi_1077_: f32;
    var phi_807_: u32;
    var phi_1942_: bool;
    var phi_1976_: bool;
    var phi_1119_: f32;
    var phi_1120_: u32;
    var phi_1975_: bool;
    var phi_1122_: u32;
    var phi_1125_: bool;
    var phi_1127_: f32;
    var phi_1129_: u32;
    var phi_1131_: f32;
    var phi_1251_: bool;
    var phi_1252_: bool;
    var phi_1254_: bool;
    var phi_1255_: bool;
    var phi_1256_: bool;
    var phi_1257_: bool;
    var phi_1272_: bool;
    var phi_1300_: f32;
    var phi_1301_: f32;
    var phi_1321_: bool;
    var phi_1326_: u32;
    var phi_1346_: f32;
    var phi_1357_: f32;
    var phi_1358_: u32;
    var phi_1359_: f32;
    var phi_1363_: u32;
    var phi_1366_: u32;
    var phi_1399_: u32;
    var phi_1364_: u32;
    var phi_1367_: u32;
    var phi_1967_: bool;
    var phi_1405_: u32;
    var phi_1415_: u32;
    var phi_1458_: f32;
    var phi_1459_: f32;
    var phi_1463_: bool;
    var phi_1497_: f32;
    var phi_1498_: f32;
    var phi_1528_: f32;
    var phi_1529_: f32;
    var phi_1558_: f32;
    var phi_1559_: f32;
    var phi_1589_: f32;
    var phi_1590_: f32;
    var phi_1663_: bool;
    var phi_1678_: f32;
    var phi_1680_: f32;
    var phi_1681_: bool;
    var phi_1686_: f32;
    var phi_1611_: f32;
    var phi_1613_: f32;
    var phi_1614_: bool;
    var phi_1615_: f32;
    var phi_1616_: bool;
    var phi_1629_: bool;
    var phi_1644_: f32;
    var phi_1646_: f32;
    var phi_1647_: bool;
    var phi_1652_: f32;
    var phi_1653_: f32;
    var phi_1687_: f32;
    var phi_1416_: u32;
    var phi_1988_: bool;
    var phi_2026_: bool;
    var phi_1729_: f32;
    var phi_1730_: u32;
    var phi_1731_: f32;
    var phi_2025_: bool;
    var phi_1123_: u32;
    var phi_1126_: bool;
    var phi_1128_: f32;
    var phi_1130_: u32;
    var phi_1132_: f32;
    var phi_2024_: bool;
    var phi_1751_: u32;
    var phi_1752_: u32;
    var phi_1753_: u32;
    var phi_1771_: u32;
    var phi_1772_: u32;
    var phi_1773_: u32;
    var phi_2029_: bool;
    var phi_2028_: bool;
    var phi_111_: u32;
    var phi_2027_: bool;

    let _e198 = global_7;
    let _e200 = global_8;
    let _e201 = bitcast<f32>(_e200);
    local_158 = _e201;
    switch bitcast<i32>(0u) {
        default: {
            let _e203 = global;
            local = _e203;
            let _e204 = global_1;
            let _e205 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            let _e216 = global_5.member.member_3;
            local_4 = _e216;
            let _e219 = global_5.member.member;
            let _e222 = global_5.member.member_1;
            local_5 = (_e219 * _e222);
            local_6 = (_e205.x * 256u);
            phi_1896_ = false;
            phi_110_ = (_e204.x * 256u);
            loop {
                let _e227 = phi_1896_;
                let _e229 = phi_110_;
                local_7 = _e229;
                let _e230 = local_7;
                let _e231 = local_5;
                let _e232 = (_e230 < _e231);
                local_8 = _e232;
                if _e232 {
                    let _e233 = local_7;
                    let _e234 = local;
                    let _e235 = (_e233 + _e234);
                    local_9 = _e235;
                    let _e236 = local_5;
                    if (_e235 < _e236) {
                        let _e238 = local_9;
                        let _e239 = local_2;
                        if (_e238 < _e239) {
                        } else {
                            phi_2027_ = true;
                            break;
                        }
                        let _e241 = local_9;
                        let _e244 = global_3.member[_e241];
                        let _e247 = global_5.member.member_2;
                        local_10 = _e247;
                        let _e249 = select(_e244, _e247, (_e247 < _e244));
                        local_152 = _e249;
                        if (_e249 == 0u) {
                            let _e254 = global_5.member.member_7.member_1;
                            let _e259 = global_5.member.member_7.member;
                            let _e264 = global_5.member.member_7.member_2;
                            let _e270 = global_5.member.member_7.member_3;
                            let _e271 = ((((2f * _e254) * _e259) / (_e264 - _e259)) * _e270);
                            let _e274 = global_5.member.member_5;
                            let _e275 = (_e271 > _e274);
                            let _e278 = local_4;
                            let _e279 = (_e278 - 1u);
                            local_11 = _e279;
                            phi_187_ = _e279;
                            phi_190_ = 0u;
                            loop {
                                let _e281 = phi_187_;
                                let _e283 = phi_190_;
                                local_12 = _e281;
                                local_13 = _e283;
                                let _e284 = local_13;
                                let _e285 = local_12;
                                let _e286 = (_e284 < _e285);
                                local_14 = _e286;
                                if _e286 {
                                    let _e287 = local_13;
                                    let _e288 = local_12;
                                    let _e290 = ((_e287 + _e288) / 2u);
                                    local_15 = _e290;
                                    let _e291 = (128u + _e290);
                                    local_16 = _e291;
                                    let _e292 = local_3;
                                    if (_e291 < _e292) {
                                    } else {
                                        phi_1890_ = true;
                                        break;
                                    }
                                    let _e294 = local_16;
                                    let _e297 = atomicLoad((&global_6.member[_e294]));
                                    let _e299 = local_158;
                                    let _e300 = (bitcast<f32>(_e297) < _e299);
                                    local_17 = _e300;
                                    if _e300 {
                                        let _e301 = local_15;
                                        phi_223_ = (_e301 + 1u);
                                    } else {
                                        phi_223_ = _e283;
                                    }
                                    let _e304 = phi_223_;
                                    let _e305 = local_17;
                                    let _e306 = local_12;
                                    let _e307 = local_15;
                                    phi_188_ = select(_e307, _e306, _e305);
                                    phi_191_ = _e304;
                                } else {
                                    phi_188_ = u32();
                                    phi_191_ = u32();
                                }
                                let _e310 = phi_188_;
                                let _e312 = phi_191_;
                                continue;
                                continuing {
                                    let _e313 = local_14;
                                    phi_187_ = _e310;
                                    phi_190_ = _e312;
                                    phi_1890_ = _e227;
                                    break if !(_e313);
                                }
                            }
                            let _e316 = phi_1890_;
                            phi_2027_ = _e316;
                            if _e316 {
                                break;
                            }
                            let _e317 = local_13;
                            if (_e317 > 0u) {
                                let _e319 = local_13;
                                phi_229_ = (_e319 - 1u);
                            } else {
                                phi_229_ = 0u;
                            }
                            let _e322 = phi_229_;
                            let _e323 = local_13;
                            let _e324 = (_e323 + 1u);
                            let _e325 = local_4;
                            let _e327 = local_11;
                            local_153 = select(_e327, _e324, (_e324 < _e325));
                            phi_239_ = _e322;
                            loop {
                                let _e330 = phi_239_;
                                local_18 = _e330;
                                let _e331 = local_18;
                                let _e332 = local_153;
                                let _e333 = (_e331 <= _e332);
                                local_19 = _e333;
                                if _e333 {
                                    let _e334 = local_18;
                                    if (_e334 == 0u) {
                                        phi_287_ = true;
                                    } else {
                                        let _e336 = local_18;
                                        let _e338 = (bitcast<i32>(_e336) - 1i);
                                        local_20 = _e338;
                                        if (_e338 < 0i) {
                                            phi_283_ = 0f;
                                        } else {
                                            let _e340 = local_20;
                                            let _e341 = bitcast<u32>(_e340);
                                            local_21 = _e341;
                                            let _e343 = local_4;
                                            if ((_e341 + 1u) >= _e343) {
                                                phi_282_ = _e201;
                                            } else {
                                                let _e345 = local_21;
                                                let _e346 = (128u + _e345);
                                                local_22 = _e346;
                                                let _e347 = local_3;
                                                if (_e346 < _e347) {
                                                } else {
                                                    phi_1898_ = true;
                                                    break;
                                                }
                                                let _e349 = local_22;
                                                let _e352 = atomicLoad((&global_6.member[_e349]));
                                                phi_282_ = bitcast<f32>(_e352);
                                            }
                                            let _e355 = phi_282_;
                                            phi_283_ = _e355;
                                        }
                                        let _e357 = phi_283_;
                                        phi_287_ = !((bitcast<u32>(_e357) == 2139095040u));
                                    }
                                    let _e362 = phi_287_;
                                    if _e362 {
                                        let _e363 = local_18;
                                        let _e364 = bitcast<i32>(_e363);
                                        local_23 = _e364;
                                        let _e365 = (_e364 - 2i);
                                        local_24 = _e365;
                                        if (_e365 < 0i) {
                                            phi_322_ = 0f;
                                        } else {
                                            let _e367 = local_24;
                                            let _e368 = bitcast<u32>(_e367);
                                            local_25 = _e368;
                                            let _e370 = local_4;
                                            if ((_e368 + 1u) >= _e370) {
                                                phi_321_ = _e201;
                                            } else {
                                                let _e372 = local_25;
                                                let _e373 = (128u + _e372);
                                                local_26 = _e373;
                                                let _e374 = local_3;
                                                if (_e373 < _e374) {
                                                } else {
                                                    phi_1898_ = true;
                                                    break;
                                                }
                                                let _e376 = local_26;
                                                let _e379 = atomicLoad((&global_6.member[_e376]));
                                                phi_321_ = bitcast<f32>(_e379);
                                            }
                                            let _e382 = phi_321_;
                                            phi_322_ = _e382;
                                        }
                                        let _e384 = phi_322_;
                                        local_27 = _e384;
                                        let _e385 = local_23;
                                        let _e386 = (_e385 - 1i);
                                        local_28 = _e386;
                                        if (_e386 < 0i) {
                                            phi_353_ = 0f;
                                        } else {
                                            let _e388 = local_28;
                                            let _e389 = bitcast<u32>(_e388);
                                            local_29 = _e389;
                                            let _e391 = local_4;
                                            if ((_e389 + 1u) >= _e391) {
                                                phi_352_ = _e201;
                                            } else {
                                                let _e393 = local_29;
                                                let _e394 = (128u + _e393);
                                                local_30 = _e394;
                                                let _e395 = local_3;
                                                if (_e394 < _e395) {
                                                } else {
                                                    phi_1898_ = true;
                                                    break;
                                                }
                                                let _e397 = local_30;
                                                let _e400 = atomicLoad((&global_6.member[_e397]));
                                                phi_352_ = bitcast<f32>(_e400);
                                            }
                                            let _e403 = phi_352_;
                                            phi_353_ = _e403;
                                        }
                                        let _e405 = phi_353_;
                                        local_31 = _e405;
                                        let _e406 = local_23;
                                        if (_e406 < 0i) {
                                            phi_383_ = 0f;
                                        } else {
                                            let _e408 = local_23;
                                            let _e409 = bitcast<u32>(_e408);
                                            local_32 = _e409;
                                            let _e411 = local_4;
                                            if ((_e409 + 1u) >= _e411) {
                                                phi_382_ = _e201;
                                            } else {
                                                let _e413 = local_32;
                                                let _e414 = (128u + _e413);
                                                local_33 = _e414;
                                                let _e415 = local_3;
                                                if (_e414 < _e415) {
                                                } else {
                                                    phi_1898_ = true;
                                                    break;
                                                }
                                                let _e417 = local_33;
                                                let _e420 = atomicLoad((&global_6.member[_e417]));
                                                phi_382_ = bitcast<f32>(_e420);
                                            }
                                            let _e423 = phi_382_;
                                            phi_383_ = _e423;
                                        }
                                        let _e425 = phi_383_;
                                        local_34 = _e425;
                                        let _e426 = local_23;
                                        let _e427 = (_e426 + 1i);
                                        local_35 = _e427;
                                        if (_e427 < 0i) {
                                        } else {
                                            let _e429 = local_35;
                                            let _e430 = bitcast<u32>(_e429);
                                            local_36 = _e430;
                                            let _e432 = local_4;
                                            if ((_e430 + 1u) >= _e432) {
                                            } else {
                                                let _e434 = local_36;
                                                let _e436 = local_3;
                                                if ((128u + _e434) < _e436) {
                                                } else {
                                                    phi_1898_ = true;
                                                    break;
                                                }
                                            }
                                        }
                                        let _e438 = local_158;
                                        let _e439 = local_31;
                                        if (_e438 >= _e439) {
                                            let _e441 = local_158;
                                            let _e442 = local_34;
                                            phi_487_ = select(true, false, (_e441 <= _e442));
                                        } else {
                                            phi_487_ = true;
                                        }
                                        let _e446 = phi_487_;
                                        if _e446 {
                                            let _e447 = local_158;
                                            let _e448 = local_27;
                                            if (_e447 > _e448) {
                                                let _e450 = local_158;
                                                let _e451 = local_31;
                                                let _e452 = (_e450 < _e451);
                                                local_37 = _e452;
                                                if _e452 {
                                                    let _e453 = local_158;
                                                    let _e454 = local_27;
                                                    let _e456 = local_31;
                                                    let _e457 = local_27;
                                                    phi_502_ = ((_e453 - _e454) / (_e456 - _e457));
                                                } else {
                                                    phi_502_ = f32();
                                                }
                                                let _e461 = phi_502_;
                                                let _e462 = local_37;
                                                phi_504_ = _e461;
                                                phi_505_ = select(true, false, _e462);
                                            } else {
                                                phi_504_ = f32();
                                                phi_505_ = true;
                                            }
                                            let _e465 = phi_504_;
                                            let _e467 = phi_505_;
                                            phi_510_ = select(_e465, 0f, _e467);
                                        } else {
                                            phi_510_ = 1f;
                                        }
                                        let _e470 = phi_510_;
                                        if (_e470 > 0f) {
                                            let _e472 = local_18;
                                            let _e473 = (256u + _e472);
                                            local_38 = _e473;
                                            let _e474 = local_3;
                                            let _e475 = (_e473 < _e474);
                                            local_39 = _e475;
                                            if _e475 {
                                            } else {
                                                phi_1898_ = true;
                                                break;
                                            }
                                            let _e476 = local_38;
                                            let _e479 = atomicLoad((&global_6.member[_e476]));
                                            if (_e479 == 0u) {
                                                let _e481 = local_39;
                                                if _e481 {
                                                } else {
                                                    phi_1898_ = true;
                                                    break;
                                                }
                                                atomicStore((&global_6.member[_e476]), 1u);
                                            }
                                        }
                                    }
                                    let _e482 = local_18;
                                    phi_240_ = (_e482 + 1u);
                                } else {
                                    phi_240_ = u32();
                                }
                                let _e485 = phi_240_;
                                continue;
                                continuing {
                                    let _e486 = local_19;
                                    phi_239_ = _e485;
                                    phi_1898_ = _e316;
                                    break if !(_e486);
                                }
                            }
                            let _e489 = phi_1898_;
                            phi_2027_ = _e489;
                            if _e489 {
                                break;
                            }
                            phi_1926_ = _e489;
                            phi_552_ = select(_e271, _e274, _e275);
                            phi_553_ = select(0u, 1u, _e275);
                        } else {
                            phi_1926_ = _e227;
                            phi_552_ = 0f;
                            phi_553_ = 0u;
                        }
                        let _e491 = phi_1926_;
                        let _e493 = phi_552_;
                        let _e495 = phi_553_;
                        local_40 = _e495;
                        phi_555_ = 0u;
                        phi_558_ = false;
                        phi_560_ = 1f;
                        loop {
                            let _e497 = phi_555_;
                            let _e499 = phi_558_;
                            let _e501 = phi_560_;
                            local_41 = _e497;
                            local_42 = _e499;
                            local_43 = _e501;
                            let _e502 = local_41;
                            let _e503 = local_152;
                            let _e504 = (_e502 < _e503);
                            local_44 = _e504;
                            if _e504 {
                                let _e505 = local_9;
                                let _e506 = local_10;
                                let _e508 = local_41;
                                let _e510 = (5u * ((_e505 * _e506) + _e508));
                                local_45 = _e510;
                                let _e511 = local_1;
                                if (_e510 < _e511) {
                                } else {
                                    phi_1923_ = true;
                                    break;
                                }
                                let _e513 = local_45;
                                let _e516 = global_4.member[_e513];
                                local_46 = bitcast<f32>(_e516);
                                let _e518 = local_45;
                                let _e519 = (_e518 + 1u);
                                local_47 = _e519;
                                let _e520 = local_1;
                                if (_e519 < _e520) {
                                } else {
                                    phi_1923_ = true;
                                    break;
                                }
                                let _e522 = local_47;
                                let _e525 = global_4.member[_e522];
                                local_48 = bitcast<f32>(_e525);
                                let _e527 = local_45;
                                let _e528 = (_e527 + 2u);
                                local_49 = _e528;
                                let _e529 = local_1;
                                if (_e528 < _e529) {
                                } else {
                                    phi_1923_ = true;
                                    break;
                                }
                                let _e531 = local_49;
                                let _e534 = global_4.member[_e531];
                                local_50 = bitcast<f32>(_e534);
                                let _e536 = local_45;
                                let _e537 = (_e536 + 3u);
                                local_51 = _e537;
                                let _e538 = local_1;
                                if (_e537 < _e538) {
                                } else {
                                    phi_1923_ = true;
                                    break;
                                }
                                let _e540 = local_51;
                                let _e543 = global_4.member[_e540];
                                local_52 = bitcast<f32>(_e543);
                                let _e545 = local_45;
                                let _e546 = (_e545 + 4u);
                                local_53 = _e546;
                                let _e547 = local_1;
                                if (_e546 < _e547) {
                                } else {
                                    phi_1923_ = true;
                                    break;
                                }
                                let _e549 = local_53;
                                let _e552 = global_4.member[_e549];
                                local_54 = bitcast<f32>(_e552);
                                let _e554 = local_46;
                                if ((bitcast<u32>(_e554) & 2139095040u) != 2139095040u) {
                                    let _e558 = local_48;
                                    if ((bitcast<u32>(_e558) & 2139095040u) != 2139095040u) {
                                        let _e562 = local_50;
                                        let _e565 = ((bitcast<u32>(_e562) & 2139095040u) != 2139095040u);
                                        local_55 = _e565;
                                        if _e565 {
                                            let _e566 = local_52;
                                            let _e567 = bitcast<u32>(_e566);
                                            local_56 = _e567;
                                            if (_e567 == 0u) {
                                                phi_681_ = false;
                                            } else {
                                                let _e569 = local_56;
                                                phi_681_ = (_e569 <= 2139095040u);
                                            }
                                            let _e572 = phi_681_;
                                            phi_682_ = _e572;
                                        } else {
                                            phi_682_ = bool();
                                        }
                                        let _e574 = phi_682_;
                                        let _e575 = local_55;
                                        phi_684_ = _e574;
                                        phi_685_ = select(true, false, _e575);
                                    } else {
                                        phi_684_ = bool();
                                        phi_685_ = true;
                                    }
                                    let _e578 = phi_684_;
                                    let _e580 = phi_685_;
                                    phi_686_ = _e578;
                                    phi_687_ = _e580;
                                } else {
                                    phi_686_ = bool();
                                    phi_687_ = true;
                                }
                                let _e582 = phi_686_;
                                let _e584 = phi_687_;
                                let _e585 = select(_e582, false, _e584);
                                local_154 = _e585;
                                if _e585 {
                                    let _e586 = local_54;
                                    if (_e586 > 1f) {
                                        phi_704_ = 1f;
                                    } else {
                                        let _e588 = local_54;
                                        let _e590 = local_54;
                                        phi_704_ = select(0f, _e590, (_e588 >= 0f));
                                    }
                                    let _e593 = phi_704_;
                                    let _e595 = local_43;
                                    phi_708_ = (_e595 * (1f - _e593));
                                } else {
                                    phi_708_ = _e501;
                                }
                                let _e598 = phi_708_;
                                let _e599 = local_154;
                                let _e600 = local_42;
                                let _e602 = local_41;
                                phi_556_ = (_e602 + 1u);
                                phi_559_ = select(_e600, true, _e599);
                                phi_561_ = _e598;
                            } else {
                                phi_556_ = u32();
                                phi_559_ = bool();
                                phi_561_ = f32();
                            }
                            let _e605 = phi_556_;
                            let _e607 = phi_559_;
                            let _e609 = phi_561_;
                            continue;
                            continuing {
                                let _e610 = local_44;
                                phi_555_ = _e605;
                                phi_558_ = _e607;
                                phi_560_ = _e609;
                                phi_1923_ = _e491;
                                break if !(_e610);
                            }
                        }
                        let _e613 = phi_1923_;
                        phi_2027_ = _e613;
                        if _e613 {
                            break;
                        }
                        let _e614 = local_42;
                        if _e614 {
                            let _e615 = local_43;
                            phi_714_ = (_e615 > 0f);
                        } else {
                            phi_714_ = false;
                        }
                        let _e618 = phi_714_;
                        if _e618 {
                            let _e622 = global_5.member.member_7.member_1;
                            let _e627 = global_5.member.member_7.member;
                            let _e632 = global_5.member.member_7.member_2;
                            let _e638 = global_5.member.member_7.member_3;
                            let _e639 = ((((2f * _e622) * _e627) / (_e632 - _e627)) * _e638);
                            local_57 = _e639;
                            let _e642 = global_5.member.member_5;
                            local_58 = _e642;
                            let _e643 = (_e639 > _e642);
                            local_59 = _e643;
                            if _e643 {
                                let _e644 = local_40;
                                phi_741_ = (_e644 + 1u);
                            } else {
                                phi_741_ = _e495;
                            }
                            let _e647 = phi_741_;
                            let _e648 = local_59;
                            let _e649 = local_58;
                            let _e650 = local_57;
                            let _e652 = local_4;
                            let _e653 = (_e652 - 1u);
                            local_60 = _e653;
                            phi_754_ = _e653;
                            phi_757_ = 0u;
                            loop {
                                let _e655 = phi_754_;
                                let _e657 = phi_757_;
                                local_61 = _e655;
                                local_62 = _e657;
                                let _e658 = local_62;
                                let _e659 = local_61;
                                let _e660 = (_e658 < _e659);
                                local_63 = _e660;
                                if _e660 {
                                    let _e661 = local_62;
                                    let _e662 = local_61;
                                    let _e664 = ((_e661 + _e662) / 2u);
                                    local_64 = _e664;
                                    let _e665 = (128u + _e664);
                                    local_65 = _e665;
                                    let _e666 = local_3;
                                    if (_e665 < _e666) {
                                    } else {
                                        phi_1935_ = true;
                                        break;
                                    }
                                    let _e668 = local_65;
                                    let _e671 = atomicLoad((&global_6.member[_e668]));
                                    let _e673 = local_158;
                                    let _e674 = (bitcast<f32>(_e671) < _e673);
                                    local_66 = _e674;
                                    if _e674 {
                                        let _e675 = local_64;
                                        phi_790_ = (_e675 + 1u);
                                    } else {
                                        phi_790_ = _e657;
                                    }
                                    let _e678 = phi_790_;
                                    let _e679 = local_66;
                                    let _e680 = local_61;
                                    let _e681 = local_64;
                                    phi_755_ = select(_e681, _e680, _e679);
                                    phi_758_ = _e678;
                                } else {
                                    phi_755_ = u32();
                                    phi_758_ = u32();
                                }
                                let _e684 = phi_755_;
                                let _e686 = phi_758_;
                                continue;
                                continuing {
                                    let _e687 = local_63;
                                    phi_754_ = _e684;
                                    phi_757_ = _e686;
                                    phi_1935_ = _e613;
                                    break if !(_e687);
                                }
                            }
                            let _e690 = phi_1935_;
                            phi_2027_ = _e690;
                            if _e690 {
                                break;
                            }
                            let _e691 = local_62;
                            if (_e691 > 0u) {
                                let _e693 = local_62;
                                phi_796_ = (_e693 - 1u);
                            } else {
                                phi_796_ = 0u;
                            }
                            let _e696 = phi_796_;
                            let _e697 = local_62;
                            let _e698 = (_e697 + 1u);
                            let _e699 = local_4;
                            let _e701 = local_60;
                            local_155 = select(_e701, _e698, (_e698 < _e699));
                            phi_806_ = _e696;
                            loop {
                                let _e704 = phi_806_;
                                local_67 = _e704;
                                let _e705 = local_67;
                                let _e706 = local_155;
                                let _e707 = (_e705 <= _e706);
                                local_68 = _e707;
                                if _e707 {
                                    let _e708 = local_67;
                                    if (_e708 == 0u) {
                                        phi_854_ = true;
                                    } else {
                                        let _e710 = local_67;
                                        let _e712 = (bitcast<i32>(_e710) - 1i);
                                        local_69 = _e712;
                                        if (_e712 < 0i) {
                                            phi_850_ = 0f;
                                        } else {
                                            let _e714 = local_69;
                                            let _e715 = bitcast<u32>(_e714);
                                            local_70 = _e715;
                                            let _e717 = local_4;
                                            if ((_e715 + 1u) >= _e717) {
                                                phi_849_ = _e201;
                                            } else {
                                                let _e719 = local_70;
                                                let _e720 = (128u + _e719);
                                                local_71 = _e720;
                                                let _e721 = local_3;
                                                if (_e720 < _e721) {
                                                } else {
                                                    phi_1942_ = true;
                                                    break;
                                                }
                                                let _e723 = local_71;
                                                let _e726 = atomicLoad((&global_6.member[_e723]));
                                                phi_849_ = bitcast<f32>(_e726);
                                            }
                                            let _e729 = phi_849_;
                                            phi_850_ = _e729;
                                        }
                                        let _e731 = phi_850_;
                                        phi_854_ = !((bitcast<u32>(_e731) == 2139095040u));
                                    }
                                    let _e736 = phi_854_;
                                    if _e736 {
                                        let _e737 = local_67;
                                        let _e738 = bitcast<i32>(_e737);
                                        local_72 = _e738;
                                        let _e739 = (_e738 - 2i);
                                        local_73 = _e739;
                                        if (_e739 < 0i) {
                                            phi_889_ = 0f;
                                        } else {
                                            let _e741 = local_73;
                                            let _e742 = bitcast<u32>(_e741);
                                            local_74 = _e742;
                                            let _e744 = local_4;
                                            if ((_e742 + 1u) >= _e744) {
                                                phi_888_ = _e201;
                                            } else {
                                                let _e746 = local_74;
                                                let _e747 = (128u + _e746);
                                                local_75 = _e747;
                                                let _e748 = local_3;
                                                if (_e747 < _e748) {
                                                } else {
                                                    phi_1942_ = true;
                                                    break;
                                                }
                                                let _e750 = local_75;
                                                let _e753 = atomicLoad((&global_6.member[_e750]));
                                                phi_888_ = bitcast<f32>(_e753);
                                            }
                                            let _e756 = phi_888_;
                                            phi_889_ = _e756;
                                        }
                                        let _e758 = phi_889_;
                                        local_76 = _e758;
                                        let _e759 = local_72;
                                        let _e760 = (_e759 - 1i);
                                        local_77 = _e760;
                                        if (_e760 < 0i) {
                                            phi_920_ = 0f;
                                        } else {
                                            let _e762 = local_77;
                                            let _e763 = bitcast<u32>(_e762);
                                            local_78 = _e763;
                                            let _e765 = local_4;
                                            if ((_e763 + 1u) >= _e765) {
                                                phi_919_ = _e201;
                                            } else {
                                                let _e767 = local_78;
                                                let _e768 = (128u + _e767);
                                                local_79 = _e768;
                                                let _e769 = local_3;
                                                if (_e768 < _e769) {
                                                } else {
                                                    phi_1942_ = true;
                                                    break;
                                                }
                                                let _e771 = local_79;
                                                let _e774 = atomicLoad((&global_6.member[_e771]));
                                                phi_919_ = bitcast<f32>(_e774);
                                            }
                                            let _e777 = phi_919_;
                                            phi_920_ = _e777;
                                        }
                                        let _e779 = phi_920_;
                                        local_80 = _e779;
                                        let _e780 = local_72;
                                        if (_e780 < 0i) {
                                            phi_950_ = 0f;
                                        } else {
                                            let _e782 = local_72;
                                            let _e783 = bitcast<u32>(_e782);
                                            local_81 = _e783;
                                            let _e785 = local_4;
                                            if ((_e783 + 1u) >= _e785) {
                                                phi_949_ = _e201;
                                            } else {
                                                let _e787 = local_81;
                                                let _e788 = (128u + _e787);
                                                local_82 = _e788;
                                                let _e789 = local_3;
                                                if (_e788 < _e789) {
                                                } else {
                                                    phi_1942_ = true;
                                                    break;
                                                }
                                                let _e791 = local_82;
                                                let _e794 = atomicLoad((&global_6.member[_e791]));
                                                phi_949_ = bitcast<f32>(_e794);
                                            }
                                            let _e797 = phi_949_;
                                            phi_950_ = _e797;
                                        }
                                        let _e799 = phi_950_;
                                        local_83 = _e799;
                                        let _e800 = local_72;
                                        let _e801 = (_e800 + 1i);
                                        local_84 = _e801;
                                        if (_e801 < 0i) {
                                        } else {
                                            let _e803 = local_84;
                                            let _e804 = bitcast<u32>(_e803);
                                            local_85 = _e804;
                                            let _e806 = local_4;
                                            if ((_e804 + 1u) >= _e806) {
                                            } else {
                                                let _e808 = local_85;
                                                let _e810 = local_3;
                                                if ((128u + _e808) < _e810) {
                                                } else {
                                                    phi_1942_ = true;
                                                    break;
                                                }
                                            }
                                        }
                                        let _e812 = local_158;
                                        let _e813 = local_80;
                                        if (_e812 >= _e813) {
                                            let _e815 = local_158;
                                            let _e816 = local_83;
                                            phi_1054_ = select(true, false, (_e815 <= _e816));
                                        } else {
                                            phi_1054_ = true;
                                        }
                                        let _e820 = phi_1054_;
                                        if _e820 {
                                            let _e821 = local_158;
                                            let _e822 = local_76;
                                            if (_e821 > _e822) {
                                                let _e824 = local_158;
                                                let _e825 = local_80;
                                                let _e826 = (_e824 < _e825);
                                                local_86 = _e826;
                                                if _e826 {
                                                    let _e827 = local_158;
                                                    let _e828 = local_76;
                                                    let _e830 = local_80;
                                                    let _e831 = local_76;
                                                    phi_1069_ = ((_e827 - _e828) / (_e830 - _e831));
                                                } else {
                                                    phi_1069_ = f32();
                                                }
                                                let _e835 = phi_1069_;
                                                let _e836 = local_86;
                                                phi_1071_ = _e835;
                                                phi_1072_ = select(true, false, _e836);
                                            } else {
                                                phi_1071_ = f32();
                                                phi_1072_ = true;
                                            }
                                            let _e839 = phi_1071_;
                                            let _e841 = phi_1072_;
                                            phi_1077_ = select(_e839, 0f, _e841);
                                        } else {
                                            phi_1077_ = 1f;
                                        }
                                        let _e844 = phi_1077_;
                                        if (_e844 > 0f) {
                                            let _e846 = local_67;
                                            let _e847 = (256u + _e846);
                                            local_87 = _e847;
                                            let _e848 = local_3;
                                            let _e849 = (_e847 < _e848);
                                            local_88 = _e849;
                                            if _e849 {
                                            } else {
                                                phi_1942_ = true;
                                                break;
                                            }
                                            let _e850 = local_87;
                                            let _e853 = atomicLoad((&global_6.member[_e850]));
                                            if (_e853 == 0u) {
                                                let _e855 = local_88;
                                                if _e855 {
                                                } else {
                                                    phi_1942_ = true;
                                                    break;
                                                }
                                                atomicStore((&global_6.member[_e850]), 1u);
                                            }
                                        }
                                    }
                                    let _e856 = local_67;
                                    phi_807_ = (_e856 + 1u);
                                } else {
                                    phi_807_ = u32();
                                }
                                let _e859 = phi_807_;
                                continue;
                                continuing {
                                    let _e860 = local_68;
                                    phi_806_ = _e859;
                                    phi_1942_ = _e690;
                                    break if !(_e860);
                                }
                            }
                            let _e863 = phi_1942_;
                            phi_2027_ = _e863;
                            if _e863 {
                                break;
                            }
                            phi_1976_ = _e863;
                            phi_1119_ = select(_e650, _e649, _e648);
                            phi_1120_ = _e647;
                        } else {
                            phi_1976_ = _e613;
                            phi_1119_ = _e493;
                            phi_1120_ = _e495;
                        }
                        let _e865 = phi_1976_;
                        let _e867 = phi_1119_;
                        let _e869 = phi_1120_;
                        phi_1975_ = _e865;
                        phi_1122_ = 0u;
                        phi_1125_ = true;
                        phi_1127_ = _e867;
                        phi_1129_ = _e869;
                        phi_1131_ = 0f;
                        loop {
                            let _e871 = phi_1975_;
                            let _e873 = phi_1122_;
                            let _e875 = phi_1125_;
                            let _e877 = phi_1127_;
                            let _e879 = phi_1129_;
                            let _e881 = phi_1131_;
                            local_89 = _e873;
                            local_90 = _e875;
                            local_91 = _e877;
                            local_92 = _e879;
                            local_93 = _e881;
                            let _e882 = local_89;
                            let _e883 = local_152;
                            let _e884 = (_e882 < _e883);
                            local_94 = _e884;
                            if _e884 {
                                let _e885 = local_9;
                                let _e886 = local_10;
                                let _e888 = local_89;
                                let _e890 = (5u * ((_e885 * _e886) + _e888));
                                local_95 = _e890;
                                let _e891 = local_1;
                                if (_e890 < _e891) {
                                } else {
                                    phi_2024_ = true;
                                    break;
                                }
                                let _e893 = local_95;
                                let _e896 = global_4.member[_e893];
                                local_96 = bitcast<f32>(_e896);
                                let _e898 = local_95;
                                let _e899 = (_e898 + 1u);
                                local_97 = _e899;
                                let _e900 = local_1;
                                if (_e899 < _e900) {
                                } else {
                                    phi_2024_ = true;
                                    break;
                                }
                                let _e902 = local_97;
                                let _e905 = global_4.member[_e902];
                                local_98 = bitcast<f32>(_e905);
                                let _e907 = local_95;
                                let _e908 = (_e907 + 2u);
                                local_99 = _e908;
                                let _e909 = local_1;
                                if (_e908 < _e909) {
                                } else {
                                    phi_2024_ = true;
                                    break;
                                }
                                let _e911 = local_99;
                                let _e914 = global_4.member[_e911];
                                local_100 = bitcast<f32>(_e914);
                                let _e916 = local_95;
                                let _e917 = (_e916 + 3u);
                                local_101 = _e917;
                                let _e918 = local_1;
                                if (_e917 < _e918) {
                                } else {
                                    phi_2024_ = true;
                                    break;
                                }
                                let _e920 = local_101;
                                let _e923 = global_4.member[_e920];
                                local_102 = bitcast<f32>(_e923);
                                let _e925 = local_95;
                                let _e927 = local_1;
                                if ((_e925 + 4u) < _e927) {
                                } else {
                                    phi_2024_ = true;
                                    break;
                                }
                                let _e929 = local_96;
                                if ((bitcast<u32>(_e929) & 2139095040u) != 2139095040u) {
                                    let _e933 = local_98;
                                    if ((bitcast<u32>(_e933) & 2139095040u) != 2139095040u) {
                                        let _e937 = local_100;
                                        let _e940 = ((bitcast<u32>(_e937) & 2139095040u) != 2139095040u);
                                        local_103 = _e940;
                                        if _e940 {
                                            let _e941 = local_102;
                                            let _e942 = bitcast<u32>(_e941);
                                            local_104 = _e942;
                                            if (_e942 == 0u) {
                                                phi_1251_ = false;
                                            } else {
                                                let _e944 = local_104;
                                                phi_1251_ = (_e944 <= 2139095040u);
                                            }
                                            let _e947 = phi_1251_;
                                            phi_1252_ = _e947;
                                        } else {
                                            phi_1252_ = bool();
                                        }
                                        let _e949 = phi_1252_;
                                        let _e950 = local_103;
                                        phi_1254_ = _e949;
                                        phi_1255_ = select(true, false, _e950);
                                    } else {
                                        phi_1254_ = bool();
                                        phi_1255_ = true;
                                    }
                                    let _e953 = phi_1254_;
                                    let _e955 = phi_1255_;
                                    phi_1256_ = _e953;
                                    phi_1257_ = _e955;
                                } else {
                                    phi_1256_ = bool();
                                    phi_1257_ = true;
                                }
                                let _e957 = phi_1256_;
                                let _e959 = phi_1257_;
                                let _e960 = select(_e957, false, _e959);
                                local_156 = _e960;
                                if _e960 {
                                    let _e961 = local_102;
                                    let _e962 = bitcast<u32>(_e961);
                                    local_105 = _e962;
                                    if (_e962 == 0u) {
                                        phi_1272_ = false;
                                    } else {
                                        let _e964 = local_105;
                                        phi_1272_ = (_e964 <= 2139095040u);
                                    }
                                    let _e967 = phi_1272_;
                                    if _e967 {
                                        let _e971 = global_5.member.member_7.member_1;
                                        let _e976 = global_5.member.member_7.member;
                                        let _e981 = global_5.member.member_7.member_2;
                                        local_106 = _e981;
                                        let _e987 = global_5.member.member_7.member_3;
                                        let _e988 = ((((2f * _e971) * _e976) / (_e981 - _e976)) * _e987);
                                        local_107 = _e988;
                                        if (_e988 == 0f) {
                                            phi_1300_ = 0f;
                                        } else {
                                            let _e990 = local_106;
                                            let _e991 = local_102;
                                            let _e994 = local_107;
                                            phi_1300_ = (_e994 * (1f - (_e990 / _e991)));
                                        }
                                        let _e997 = phi_1300_;
                                        phi_1301_ = _e997;
                                    } else {
                                        phi_1301_ = bitcast<f32>(_e198);
                                    }
                                    let _e999 = phi_1301_;
                                    local_108 = _e999;
                                    if ((bitcast<u32>(_e999) & 2139095040u) != 2139095040u) {
                                        let _e1005 = global_5.member.member_5;
                                        local_109 = _e1005;
                                        let _e1006 = local_108;
                                        let _e1007 = (_e1006 > _e1005);
                                        local_110 = _e1007;
                                        if _e1007 {
                                            phi_1321_ = true;
                                        } else {
                                            let _e1008 = local_109;
                                            let _e1010 = local_108;
                                            phi_1321_ = (_e1010 < -(_e1008));
                                        }
                                        let _e1013 = phi_1321_;
                                        if _e1013 {
                                            let _e1014 = local_92;
                                            phi_1326_ = (_e1014 + 1u);
                                        } else {
                                            phi_1326_ = _e879;
                                        }
                                        let _e1017 = phi_1326_;
                                        let _e1018 = local_110;
                                        if _e1018 {
                                            phi_1346_ = _e1005;
                                        } else {
                                            let _e1019 = local_109;
                                            let _e1020 = -(_e1019);
                                            let _e1021 = local_108;
                                            let _e1023 = local_108;
                                            phi_1346_ = select(_e1023, _e1020, (_e1021 < _e1020));
                                        }
                                        let _e1026 = phi_1346_;
                                        let _e1027 = local_93;
                                        let _e1029 = local_93;
                                        let _e1031 = local_91;
                                        let _e1033 = local_91;
                                        phi_1357_ = select(_e1033, _e1026, (_e1026 > _e1031));
                                        phi_1358_ = _e1017;
                                        phi_1359_ = select(_e1029, _e1026, (_e1026 < _e1027));
                                    } else {
                                        phi_1357_ = _e877;
                                        phi_1358_ = _e879;
                                        phi_1359_ = _e881;
                                    }
                                    let _e1036 = phi_1357_;
                                    let _e1038 = phi_1358_;
                                    let _e1040 = phi_1359_;
                                    let _e1041 = local_4;
                                    let _e1042 = (_e1041 - 1u);
                                    local_111 = _e1042;
                                    phi_1363_ = _e1042;
                                    phi_1366_ = 0u;
                                    loop {
                                        let _e1044 = phi_1363_;
                                        let _e1046 = phi_1366_;
                                        local_112 = _e1044;
                                        local_113 = _e1046;
                                        let _e1047 = local_113;
                                        let _e1048 = local_112;
                                        let _e1049 = (_e1047 < _e1048);
                                        local_114 = _e1049;
                                        if _e1049 {
                                            let _e1050 = local_113;
                                            let _e1051 = local_112;
                                            let _e1053 = ((_e1050 + _e1051) / 2u);
                                            local_115 = _e1053;
                                            let _e1054 = (128u + _e1053);
                                            local_116 = _e1054;
                                            let _e1055 = local_3;
                                            if (_e1054 < _e1055) {
                                            } else {
                                                phi_1967_ = true;
                                                break;
                                            }
                                            let _e1057 = local_116;
                                            let _e1060 = atomicLoad((&global_6.member[_e1057]));
                                            let _e1062 = local_102;
                                            let _e1063 = (bitcast<f32>(_e1060) < _e1062);
                                            local_117 = _e1063;
                                            if _e1063 {
                                                let _e1064 = local_115;
                                                phi_1399_ = (_e1064 + 1u);
                                            } else {
                                                phi_1399_ = _e1046;
                                            }
                                            let _e1067 = phi_1399_;
                                            let _e1068 = local_117;
                                            let _e1069 = local_112;
                                            let _e1070 = local_115;
                                            phi_1364_ = select(_e1070, _e1069, _e1068);
                                            phi_1367_ = _e1067;
                                        } else {
                                            phi_1364_ = u32();
                                            phi_1367_ = u32();
                                        }
                                        let _e1073 = phi_1364_;
                                        let _e1075 = phi_1367_;
                                        continue;
                                        continuing {
                                            let _e1076 = local_114;
                                            phi_1363_ = _e1073;
                                            phi_1366_ = _e1075;
                                            phi_1967_ = _e871;
                                            break if !(_e1076);
                                        }
                                    }
                                    let _e1079 = phi_1967_;
                                    phi_2024_ = _e1079;
                                    if _e1079 {
                                        break;
                                    }
                                    let _e1080 = local_113;
                                    if (_e1080 > 0u) {
                                        let _e1082 = local_113;
                                        phi_1405_ = (_e1082 - 1u);
                                    } else {
                                        phi_1405_ = 0u;
                                    }
                                    let _e1085 = phi_1405_;
                                    let _e1086 = local_113;
                                    let _e1087 = (_e1086 + 1u);
                                    let _e1088 = local_4;
                                    let _e1090 = local_111;
                                    local_157 = select(_e1090, _e1087, (_e1087 < _e1088));
                                    phi_1415_ = _e1085;
                                    loop {
                                        let _e1093 = phi_1415_;
                                        local_118 = _e1093;
                                        let _e1094 = local_118;
                                        let _e1095 = local_157;
                                        let _e1096 = (_e1094 <= _e1095);
                                        local_119 = _e1096;
                                        if _e1096 {
                                            let _e1097 = local_118;
                                            if (_e1097 == 0u) {
                                                phi_1463_ = true;
                                            } else {
                                                let _e1099 = local_118;
                                                let _e1101 = (bitcast<i32>(_e1099) - 1i);
                                                local_120 = _e1101;
                                                if (_e1101 < 0i) {
                                                    phi_1459_ = 0f;
                                                } else {
                                                    let _e1103 = local_120;
                                                    let _e1104 = bitcast<u32>(_e1103);
                                                    local_121 = _e1104;
                                                    let _e1106 = local_4;
                                                    if ((_e1104 + 1u) >= _e1106) {
                                                        phi_1458_ = _e201;
                                                    } else {
                                                        let _e1108 = local_121;
                                                        let _e1109 = (128u + _e1108);
                                                        local_122 = _e1109;
                                                        let _e1110 = local_3;
                                                        if (_e1109 < _e1110) {
                                                        } else {
                                                            phi_1988_ = true;
                                                            break;
                                                        }
                                                        let _e1112 = local_122;
                                                        let _e1115 = atomicLoad((&global_6.member[_e1112]));
                                                        phi_1458_ = bitcast<f32>(_e1115);
                                                    }
                                                    let _e1118 = phi_1458_;
                                                    phi_1459_ = _e1118;
                                                }
                                                let _e1120 = phi_1459_;
                                                phi_1463_ = !((bitcast<u32>(_e1120) == 2139095040u));
                                            }
                                            let _e1125 = phi_1463_;
                                            if _e1125 {
                                                let _e1126 = local_118;
                                                let _e1127 = bitcast<i32>(_e1126);
                                                local_123 = _e1127;
                                                let _e1128 = (_e1127 - 2i);
                                                local_124 = _e1128;
                                                if (_e1128 < 0i) {
                                                    phi_1498_ = 0f;
                                                } else {
                                                    let _e1130 = local_124;
                                                    let _e1131 = bitcast<u32>(_e1130);
                                                    local_125 = _e1131;
                                                    let _e1133 = local_4;
                                                    if ((_e1131 + 1u) >= _e1133) {
                                                        phi_1497_ = _e201;
                                                    } else {
                                                        let _e1135 = local_125;
                                                        let _e1136 = (128u + _e1135);
                                                        local_126 = _e1136;
                                                        let _e1137 = local_3;
                                                        if (_e1136 < _e1137) {
                                                        } else {
                                                            phi_1988_ = true;
                                                            break;
                                                        }
                                                        let _e1139 = local_126;
                                                        let _e1142 = atomicLoad((&global_6.member[_e1139]));
                                                        phi_1497_ = bitcast<f32>(_e1142);
                                                    }
                                                    let _e1145 = phi_1497_;
                                                    phi_1498_ = _e1145;
                                                }
                                                let _e1147 = phi_1498_;
                                                local_127 = _e1147;
                                                let _e1148 = local_123;
                                                let _e1149 = (_e1148 - 1i);
                                                local_128 = _e1149;
                                                if (_e1149 < 0i) {
                                                    phi_1529_ = 0f;
                                                } else {
                                                    let _e1151 = local_128;
                                                    let _e1152 = bitcast<u32>(_e1151);
                                                    local_129 = _e1152;
                                                    let _e1154 = local_4;
                                                    if ((_e1152 + 1u) >= _e1154) {
                                                        phi_1528_ = _e201;
                                                    } else {
                                                        let _e1156 = local_129;
                                                        let _e1157 = (128u + _e1156);
                                                        local_130 = _e1157;
                                                        let _e1158 = local_3;
                                                        if (_e1157 < _e1158) {
                                                        } else {
                                                            phi_1988_ = true;
                                                            break;
                                                        }
                                                        let _e1160 = local_130;
                                                        let _e1163 = atomicLoad((&global_6.member[_e1160]));
                                                        phi_1528_ = bitcast<f32>(_e1163);
                                                    }
                                                    let _e1166 = phi_1528_;
                                                    phi_1529_ = _e1166;
                                                }
                                                let _e1168 = phi_1529_;
                                                local_131 = _e1168;
                                                let _e1169 = local_123;
                                                if (_e1169 < 0i) {
                                                    phi_1559_ = 0f;
                                                } else {
                                                    let _e1171 = local_123;
                                                    let _e1172 = bitcast<u32>(_e1171);
                                                    local_132 = _e1172;
                                                    let _e1174 = local_4;
                                                    if ((_e1172 + 1u) >= _e1174) {
                                                        phi_1558_ = _e201;
                                                    } else {
                                                        let _e1176 = local_132;
                                                        let _e1177 = (128u + _e1176);
                                                        local_133 = _e1177;
                                                        let _e1178 = local_3;
                                                        if (_e1177 < _e1178) {
                                                        } else {
                                                            phi_1988_ = true;
                                                            break;
                                                        }
                                                        let _e1180 = local_133;
                                                        let _e1183 = atomicLoad((&global_6.member[_e1180]));
                                                        phi_1558_ = bitcast<f32>(_e1183);
                                                    }
                                                    let _e1186 = phi_1558_;
                                                    phi_1559_ = _e1186;
                                                }
                                                let _e1188 = phi_1559_;
                                                local_134 = _e1188;
                                                let _e1189 = local_123;
                                                let _e1190 = (_e1189 + 1i);
                                                local_135 = _e1190;
                                                if (_e1190 < 0i) {
                                                    phi_1590_ = 0f;
                                                } else {
                                                    let _e1192 = local_135;
                                                    let _e1193 = bitcast<u32>(_e1192);
                                                    local_136 = _e1193;
                                                    let _e1195 = local_4;
                                                    if ((_e1193 + 1u) >= _e1195) {
                                                        phi_1589_ = _e201;
                                                    } else {
                                                        let _e1197 = local_136;
                                                        let _e1198 = (128u + _e1197);
                                                        local_137 = _e1198;
                                                        let _e1199 = local_3;
                                                        if (_e1198 < _e1199) {
                                                        } else {
                                                            phi_1988_ = true;
                                                            break;
                                                        }
                                                        let _e1201 = local_137;
                                                        let _e1204 = atomicLoad((&global_6.member[_e1201]));
                                                        phi_1589_ = bitcast<f32>(_e1204);
                                                    }
                                                    let _e1207 = phi_1589_;
                                                    phi_1590_ = _e1207;
                                                }
                                                let _e1209 = phi_1590_;
                                                local_138 = _e1209;
                                                let _e1210 = local_90;
                                                if _e1210 {
                                                    let _e1244 = local_102;
                                                    let _e1245 = local_134;
                                                    if (_e1244 > _e1245) {
                                                        let _e1247 = local_102;
                                                        let _e1248 = local_138;
                                                        if (_e1247 < _e1248) {
                                                            let _e1250 = local_138;
                                                            let _e1253 = ((bitcast<u32>(_e1250) & 2139095040u) != 2139095040u);
                                                            local_139 = _e1253;
                                                            if _e1253 {
                                                                let _e1254 = local_138;
                                                                let _e1255 = local_102;
                                                                let _e1257 = local_138;
                                                                let _e1258 = local_134;
                                                                phi_1611_ = ((_e1254 - _e1255) / (_e1257 - _e1258));
                                                            } else {
                                                                phi_1611_ = f32();
                                                            }
                                                            let _e1262 = phi_1611_;
                                                            let _e1263 = local_139;
                                                            phi_1613_ = _e1262;
                                                            phi_1614_ = select(true, false, _e1263);
                                                        } else {
                                                            phi_1613_ = f32();
                                                            phi_1614_ = true;
                                                        }
                                                        let _e1266 = phi_1613_;
                                                        let _e1268 = phi_1614_;
                                                        phi_1615_ = _e1266;
                                                        phi_1616_ = _e1268;
                                                    } else {
                                                        phi_1615_ = f32();
                                                        phi_1616_ = true;
                                                    }
                                                    let _e1270 = phi_1615_;
                                                    let _e1272 = phi_1616_;
                                                    if _e1272 {
                                                        let _e1273 = local_102;
                                                        let _e1274 = local_131;
                                                        if (_e1273 >= _e1274) {
                                                            let _e1276 = local_102;
                                                            let _e1277 = local_134;
                                                            phi_1629_ = select(true, false, (_e1276 <= _e1277));
                                                        } else {
                                                            phi_1629_ = true;
                                                        }
                                                        let _e1281 = phi_1629_;
                                                        if _e1281 {
                                                            let _e1282 = local_102;
                                                            let _e1283 = local_127;
                                                            if (_e1282 > _e1283) {
                                                                let _e1285 = local_102;
                                                                let _e1286 = local_131;
                                                                let _e1287 = (_e1285 < _e1286);
                                                                local_140 = _e1287;
                                                                if _e1287 {
                                                                    let _e1288 = local_102;
                                                                    let _e1289 = local_127;
                                                                    let _e1291 = local_131;
                                                                    let _e1292 = local_127;
                                                                    phi_1644_ = ((_e1288 - _e1289) / (_e1291 - _e1292));
                                                                } else {
                                                                    phi_1644_ = f32();
                                                                }
                                                                let _e1296 = phi_1644_;
                                                                let _e1297 = local_140;
                                                                phi_1646_ = _e1296;
                                                                phi_1647_ = select(true, false, _e1297);
                                                            } else {
                                                                phi_1646_ = f32();
                                                                phi_1647_ = true;
                                                            }
                                                            let _e1300 = phi_1646_;
                                                            let _e1302 = phi_1647_;
                                                            phi_1652_ = select(_e1300, 0f, _e1302);
                                                        } else {
                                                            phi_1652_ = 1f;
                                                        }
                                                        let _e1305 = phi_1652_;
                                                        phi_1653_ = _e1305;
                                                    } else {
                                                        phi_1653_ = _e1270;
                                                    }
                                                    let _e1307 = phi_1653_;
                                                    phi_1687_ = _e1307;
                                                } else {
                                                    let _e1211 = local_102;
                                                    let _e1212 = local_131;
                                                    if (_e1211 >= _e1212) {
                                                        let _e1214 = local_102;
                                                        let _e1215 = local_134;
                                                        phi_1663_ = select(true, false, (_e1214 <= _e1215));
                                                    } else {
                                                        phi_1663_ = true;
                                                    }
                                                    let _e1219 = phi_1663_;
                                                    if _e1219 {
                                                        let _e1220 = local_102;
                                                        let _e1221 = local_127;
                                                        if (_e1220 > _e1221) {
                                                            let _e1223 = local_102;
                                                            let _e1224 = local_131;
                                                            let _e1225 = (_e1223 < _e1224);
                                                            local_141 = _e1225;
                                                            if _e1225 {
                                                                let _e1226 = local_102;
                                                                let _e1227 = local_127;
                                                                let _e1229 = local_131;
                                                                let _e1230 = local_127;
                                                                phi_1678_ = ((_e1226 - _e1227) / (_e1229 - _e1230));
                                                            } else {
                                                                phi_1678_ = f32();
                                                            }
                                                            let _e1234 = phi_1678_;
                                                            let _e1235 = local_141;
                                                            phi_1680_ = _e1234;
                                                            phi_1681_ = select(true, false, _e1235);
                                                        } else {
                                                            phi_1680_ = f32();
                                                            phi_1681_ = true;
                                                        }
                                                        let _e1238 = phi_1680_;
                                                        let _e1240 = phi_1681_;
                                                        phi_1686_ = select(_e1238, 0f, _e1240);
                                                    } else {
                                                        phi_1686_ = 1f;
                                                    }
                                                    let _e1243 = phi_1686_;
                                                    phi_1687_ = _e1243;
                                                }
                                                let _e1309 = phi_1687_;
                                                if (_e1309 > 0f) {
                                                    let _e1311 = local_118;
                                                    let _e1312 = (256u + _e1311);
                                                    local_142 = _e1312;
                                                    let _e1313 = local_3;
                                                    let _e1314 = (_e1312 < _e1313);
                                                    local_143 = _e1314;
                                                    if _e1314 {
                                                    } else {
                                                        phi_1988_ = true;
                                                        break;
                                                    }
                                                    let _e1315 = local_142;
                                                    let _e1318 = atomicLoad((&global_6.member[_e1315]));
                                                    if (_e1318 == 0u) {
                                                        let _e1320 = local_143;
                                                        if _e1320 {
                                                        } else {
                                                            phi_1988_ = true;
                                                            break;
                                                        }
                                                        atomicStore((&global_6.member[_e1315]), 1u);
                                                    }
                                                }
                                            }
                                            let _e1321 = local_118;
                                            phi_1416_ = (_e1321 + 1u);
                                        } else {
                                            phi_1416_ = u32();
                                        }
                                        let _e1324 = phi_1416_;
                                        continue;
                                        continuing {
                                            let _e1325 = local_119;
                                            phi_1415_ = _e1324;
                                            phi_1988_ = _e1079;
                                            break if !(_e1325);
                                        }
                                    }
                                    let _e1328 = phi_1988_;
                                    phi_2024_ = _e1328;
                                    if _e1328 {
                                        break;
                                    }
                                    phi_2026_ = _e1328;
                                    phi_1729_ = _e1036;
                                    phi_1730_ = _e1038;
                                    phi_1731_ = _e1040;
                                } else {
                                    phi_2026_ = _e871;
                                    phi_1729_ = _e877;
                                    phi_1730_ = _e879;
                                    phi_1731_ = _e881;
                                }
                                let _e1330 = phi_2026_;
                                let _e1332 = phi_1729_;
                                let _e1334 = phi_1730_;
                                let _e1336 = phi_1731_;
                                let _e1337 = local_156;
                                let _e1338 = local_90;
                                let _e1340 = local_89;
                                phi_2025_ = _e1330;
                                phi_1123_ = (_e1340 + 1u);
                                phi_1126_ = select(_e1338, false, _e1337);
                                phi_1128_ = _e1332;
                                phi_1130_ = _e1334;
                                phi_1132_ = _e1336;
                            } else {
                                phi_2025_ = _e871;
                                phi_1123_ = u32();
                                phi_1126_ = bool();
                                phi_1128_ = f32();
                                phi_1130_ = u32();
                                phi_1132_ = f32();
                            }
                            let _e1343 = phi_2025_;
                            let _e1345 = phi_1123_;
                            let _e1347 = phi_1126_;
                            let _e1349 = phi_1128_;
                            let _e1351 = phi_1130_;
                            let _e1353 = phi_1132_;
                            continue;
                            continuing {
                                let _e1354 = local_94;
                                phi_1975_ = _e1343;
                                phi_1122_ = _e1345;
                                phi_1125_ = _e1347;
                                phi_1127_ = _e1349;
                                phi_1129_ = _e1351;
                                phi_1131_ = _e1353;
                                phi_2024_ = _e1343;
                                break if !(_e1354);
                            }
                        }
                        let _e1357 = phi_2024_;
                        phi_2027_ = _e1357;
                        if _e1357 {
                            break;
                        }
                        let _e1358 = local_93;
                        let _e1360 = bitcast<u32>(-(_e1358));
                        local_144 = _e1360;
                        let _e1361 = (_e1360 & 2147483647u);
                        local_145 = _e1361;
                        if (_e1361 > 2139095040u) {
                            phi_1753_ = 4294967295u;
                        } else {
                            let _e1363 = local_145;
                            if (_e1363 == 0u) {
                                phi_1752_ = 2147483648u;
                            } else {
                                let _e1365 = local_144;
                                if ((_e1365 & 2147483648u) == 0u) {
                                    let _e1370 = local_144;
                                    phi_1751_ = (_e1370 | 2147483648u);
                                } else {
                                    let _e1368 = local_144;
                                    phi_1751_ = ~(_e1368);
                                }
                                let _e1373 = phi_1751_;
                                phi_1752_ = _e1373;
                            }
                            let _e1375 = phi_1752_;
                            phi_1753_ = _e1375;
                        }
                        let _e1377 = phi_1753_;
                        local_146 = _e1377;
                        let _e1378 = local_91;
                        let _e1379 = bitcast<u32>(_e1378);
                        local_147 = _e1379;
                        let _e1380 = (_e1379 & 2147483647u);
                        local_148 = _e1380;
                        if (_e1380 > 2139095040u) {
                            phi_1773_ = 4294967295u;
                        } else {
                            let _e1382 = local_148;
                            if (_e1382 == 0u) {
                                phi_1772_ = 2147483648u;
                            } else {
                                let _e1384 = local_147;
                                if ((_e1384 & 2147483648u) == 0u) {
                                    let _e1389 = local_147;
                                    phi_1771_ = (_e1389 | 2147483648u);
                                } else {
                                    let _e1387 = local_147;
                                    phi_1771_ = ~(_e1387);
                                }
                                let _e1392 = phi_1771_;
                                phi_1772_ = _e1392;
                            }
                            let _e1394 = phi_1772_;
                            phi_1773_ = _e1394;
                        }
                        let _e1396 = phi_1773_;
                        local_149 = _e1396;
                        let _e1397 = local_3;
                        let _e1398 = (640u < _e1397);
                        local_150 = _e1398;
                        if _e1398 {
                        } else {
                            phi_2027_ = true;
                            break;
                        }
                        let _e1401 = atomicLoad((&global_6.member[640u]));
                        let _e1402 = local_146;
                        if (_e1402 > _e1401) {
                            let _e1404 = local_150;
                            if _e1404 {
                            } else {
                                phi_2027_ = true;
                                break;
                            }
                            let _e1405 = local_146;
                            let _e1406 = atomicMax((&global_6.member[640u]), _e1405);
                        }
                        let _e1407 = local_3;
                        let _e1408 = (641u < _e1407);
                        local_151 = _e1408;
                        if _e1408 {
                        } else {
                            phi_2027_ = true;
                            break;
                        }
                        let _e1411 = atomicLoad((&global_6.member[641u]));
                        let _e1412 = local_149;
                        if (_e1412 > _e1411) {
                            let _e1414 = local_151;
                            if _e1414 {
                            } else {
                                phi_2027_ = true;
                                break;
                            }
                            let _e1415 = local_149;
                            let _e1416 = atomicMax((&global_6.member[641u]), _e1415);
                        }
                        let _e1417 = local_92;
                        if (_e1417 > 0u) {
                            let _e1419 = local_3;
                            if (642u < _e1419) {
                            } else {
                                phi_2027_ = true;
                                break;
                            }
                            let _e1423 = local_92;
                            let _e1424 = atomicAdd((&global_6.member[642u]), _e1423);
                        }
                        phi_2029_ = _e1357;
                    } else {
                        phi_2029_ = _e227;
                    }
                    let _e1426 = phi_2029_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e1427 = local_7;
                    let _e1428 = local_6;
                    phi_2028_ = _e1426;
                    phi_111_ = (_e1427 + _e1428);
                } else {
                    phi_2028_ = _e227;
                    phi_111_ = u32();
                }
                let _e1431 = phi_2028_;
                let _e1433 = phi_111_;
                continue;
                continuing {
                    let _e1434 = local_8;
                    phi_1896_ = _e1431;
                    phi_110_ = _e1433;
                    phi_2027_ = _e1431;
                    break if !(_e1434);
                }
            }
            let _e1437 = phi_2027_;
            if _e1437 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn layered_plan_reach(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
