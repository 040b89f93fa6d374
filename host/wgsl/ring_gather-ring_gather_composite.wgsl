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

struct type_21 {
    member: array<f32, 3>,
    member_1: f32,
}

struct type_22 {
    member: u32,
    member_1: type_21,
}

struct type_24 {
    member: array<f32, 3>,
    member_1: array<f32, 3>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<immediate> global_2: type_7;
@group(0) @binding(0) 
var<storage> global_3: type_10;
@group(0) @binding(1) 
var<storage> global_4: type_10;
@group(0) @binding(2) 
var<storage> global_5: type_10;
@group(0) @binding(3) 
var<storage> global_6: type_10;
@group(0) @binding(4) 
var<storage> global_7: type_10;
@group(0) @binding(5) 
var<storage, read_write> global_8: type_10;
var<private> global_9: u32 = 2143289344u;

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
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: bool;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: f32;
    var local_20: f32;
    var local_21: f32;
    var local_22: f32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: f32;
    var local_27: bool;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: f32;
    var local_33: f32;
    var local_34: u32;
    var local_35: u32;
    var local_36: f32;
    var local_37: u32;
    var local_38: bool;
    var local_39: u32;
    var local_40: f32;
    var local_41: u32;
    var local_42: bool;
    var local_43: u32;
    var local_44: f32;
    var local_45: u32;
    var local_46: u32;
    var local_47: f32;
    var local_48: u32;
    var local_49: f32;
    var local_50: u32;
    var local_51: f32;
    var local_52: f32;
    var local_53: f32;
    var local_54: f32;
    var local_55: array<f32, 3>;
    var local_56: f32;
    var local_57: u32;
    var local_58: bool;
    var local_59: type_22;
    var local_60: array<f32, 3>;
    var local_61: f32;
    var local_62: f32;
    var local_63: u32;
    var local_64: f32;
    var local_65: f32;
    var local_66: f32;
    var local_67: bool;
    var local_68: u32;
    var local_69: f32;
    var local_70: array<f32, 3>;
    var local_71: bool;
    var local_72: i32;
    var local_73: i32;
    var local_74: i32;
    var local_75: i32;
    var local_76: u32;
    var local_77: u32;
    var local_78: u32;
    var local_79: u32;
    var local_80: f32;
    var local_81: u32;
    var local_82: f32;
    var local_83: u32;
    var local_84: f32;
    var local_85: f32;
    var local_86: f32;
    var local_87: f32;
    var local_88: array<f32, 3>;
    var local_89: f32;
    var local_90: u32;
    var local_91: bool;
    var local_92: type_22;
    var local_93: array<f32, 3>;
    var local_94: f32;
    var local_95: u32;
    var local_96: f32;
    var local_97: f32;
    var local_98: f32;
    var local_99: f32;
    var local_100: u32;
    var local_101: bool;
    var local_102: f32;
    var local_103: f32;
    var local_104: f32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: u32;
    var local_112: u32;
    var local_113: i32;
    var local_114: bool;
    var local_115: f32;
    var local_116: f32;
    var local_117: i32;
    var local_118: array<f32, 3>;
    var local_119: array<f32, 3>;
    var local_120: bool;
    var local_121: i32;
    var local_122: i32;
    var local_123: i32;
    var local_124: u32;
    var local_125: u32;
    var local_126: u32;
    var local_127: array<f32, 3>;
    var local_128: array<f32, 3>;
    var local_129: bool;
    var local_130: u32;
    var local_131: f32;
    var local_132: u32;
    var local_133: f32;
    var local_134: u32;
    var local_135: f32;
    var local_136: f32;
    var local_137: bool;
    var local_138: f32;
    var local_139: f32;
    var local_140: u32;
    var local_141: f32;
    var local_142: f32;
    var local_143: u32;
    var local_144: f32;
    var local_145: u32;
    var local_146: f32;
    var local_147: u32;
    var local_148: f32;
    var local_149: bool;
    var local_150: array<f32, 3>;
    var local_151: f32;
    var local_152: u32;
    var local_153: u32;
    var local_154: u32;
    var local_155: f32;
    var local_156: f32;
    var local_157: f32;
    var local_158: f32;
    var local_159: f32;
    var local_160: array<f32, 3>;
    var local_161: array<f32, 4>;
    var local_162: array<f32, 3>;
    var phi_134_: u32;
    var phi_152_: u32;
    var phi_1631_: bool;
    var phi_208_: u32;
    var phi_211_: f32;
    var phi_228_: u32;
    var phi_238_: u32;
    var phi_245_: f32;
    var phi_252_: f32;
    var phi_268_: u32;
    var phi_269_: u32;
    var phi_1624_: bool;
    var phi_300_: u32;
    var phi_301_: u32;
    var phi_1636_: bool;
    var phi_1640_: bool;
    var phi_209_: u32;
    var phi_212_: f32;
    var phi_1639_: bool;
    var phi_374_: bool;
    var phi_388_: bool;
    var phi_393_: f32;
    var phi_403_: bool;
    var phi_417_: bool;
    var phi_422_: f32;
    var phi_432_: bool;
    var phi_446_: bool;
    var phi_451_: f32;
    var phi_485_: bool;
    var phi_491_: type_22;
    var phi_493_: type_22;
    var phi_494_: bool;
    var phi_495_: type_22;
    var phi_496_: bool;
    var phi_497_: type_22;
    var phi_498_: bool;
    var phi_503_: type_22;
    var phi_543_: bool;
    var phi_571_: f32;
    var phi_572_: f32;
    var phi_574_: f32;
    var phi_591_: f32;
    var phi_617_: f32;
    var phi_642_: u32;
    var phi_645_: f32;
    var phi_647_: array<f32, 3>;
    var phi_735_: bool;
    var phi_749_: bool;
    var phi_754_: f32;
    var phi_764_: bool;
    var phi_778_: bool;
    var phi_783_: f32;
    var phi_793_: bool;
    var phi_807_: bool;
    var phi_812_: f32;
    var phi_846_: bool;
    var phi_852_: type_22;
    var phi_854_: type_22;
    var phi_855_: bool;
    var phi_856_: type_22;
    var phi_857_: bool;
    var phi_858_: type_22;
    var phi_859_: bool;
    var phi_864_: type_22;
    var phi_904_: bool;
    var phi_932_: f32;
    var phi_933_: f32;
    var phi_935_: f32;
    var phi_967_: f32;
    var phi_956_: f32;
    var phi_968_: f32;
    var phi_1038_: f32;
    var phi_1039_: array<f32, 3>;
    var phi_1040_: f32;
    var phi_1041_: array<f32, 3>;
    var phi_1042_: f32;
    var phi_1043_: array<f32, 3>;
    var phi_1044_: f32;
    var phi_1045_: array<f32, 3>;
    var phi_1046_: f32;
    var phi_1047_: array<f32, 3>;
    var phi_1048_: f32;
    var phi_1049_: array<f32, 3>;
    var phi_1050_: f32;
    var phi_1051_: array<f32, 3>;
    var phi_643_: u32;
    var phi_646_: f32;
    var phi_648_: array<f32, 3>;
    var phi_1641_: bool;
    var phi_1733_: bool;
    var phi_1085_: u32;
    var phi_1086_: u32;
    var phi_1730_: bool;
    var phi_1756_: bool;
    var phi_1755_: bool;
    var phi_1754_: bool;
    var phi_1139_: f32;
    var phi_1157_: u32;
    var phi_1173_: u32;
    var phi_1191_: u32;
    var phi_1207_: u32;
    var phi_1244_: f32;
    var phi_1262_: f32;
    var phi_1744_: bool;
    var phi_1265_: i32;
    var phi_1268_: array<f32, 3>;
    var phi_1270_: array<f32, 3>;
    var phi_1743_: bool;
    var phi_1282_: i32;
    var phi_1285_: array<f32, 3>;
    var phi_1287_: array<f32, 3>;
    var phi_1328_: u32;
    var phi_1331_: array<f32, 3>;
    var phi_1333_: array<f32, 3>;
    var phi_1381_: f32;
    var phi_1394_: f32;
    var phi_1477_: array<f32, 3>;
    var phi_1478_: array<f32, 3>;
    var phi_1479_: array<f32, 3>;
    var phi_1480_: array<f32, 3>;
    var phi_1329_: u32;
    var phi_1332_: array<f32, 3>;
    var phi_1334_: array<f32, 3>;
    var phi_1734_: bool;
    var phi_1764_: bool;
    var phi_1482_: array<f32, 3>;
    var phi_1483_: array<f32, 3>;
    var phi_1763_: bool;
    var phi_1484_: array<f32, 3>;
    var phi_1485_: array<f32, 3>;
    var phi_1762_: bool;
    var phi_1487_: i32;
    var phi_1488_: array<f32, 3>;
    var phi_1489_: array<f32, 3>;
    var phi_1761_: bool;
    var phi_1491_: i32;
    var phi_1492_: array<f32, 3>;
    var phi_1493_: array<f32, 3>;
    var phi_1494_: bool;
    var phi_1760_: bool;
    var phi_1283_: i32;
    var phi_1286_: array<f32, 3>;
    var phi_1288_: array<f32, 3>;
    var phi_1496_: bool;
    var phi_1759_: bool;
    var phi_1766_: bool;
    var phi_1266_: i32;
    var phi_1269_: array<f32, 3>;
    var phi_1271_: array<f32, 3>;
    var phi_1765_: bool;
    var phi_1508_: type_24;
    var local_163: array<f32, 3>;
    var local_164: array<f32, 3>;
    var local_165: array<f32, 3>;
    var local_166: array<f32, 3>;

    let _e215 = global_9;
    let _e216 = bitcast<f32>(_e215);
    switch bitcast<i32>(0u) {
        default: {
            let _e218 = global;
            local = _e218;
            let _e219 = global_1;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = arrayLength((&global_6.member));
            local_5 = arrayLength((&global_7.member));
            local_6 = arrayLength((&global_8.member));
            local_7 = _e219.x;
            local_8 = _e219.y;
            let _e236 = global_2.member.member;
            local_9 = _e236;
            let _e237 = (_e236 / 2u);
            local_10 = _e237;
            let _e239 = ((_e236 % 2u) > 0u);
            local_11 = _e239;
            if _e239 {
                let _e240 = local_10;
                phi_134_ = (_e240 + 1u);
            } else {
                phi_134_ = _e237;
            }
            let _e243 = phi_134_;
            local_12 = _e243;
            let _e246 = global_2.member.member_1;
            local_13 = _e246;
            let _e247 = (_e246 / 2u);
            local_14 = _e247;
            let _e249 = ((_e246 % 2u) > 0u);
            local_15 = _e249;
            if _e249 {
                let _e250 = local_14;
                phi_152_ = (_e250 + 1u);
            } else {
                phi_152_ = _e247;
            }
            let _e253 = phi_152_;
            local_16 = _e253;
            let _e254 = local_7;
            let _e256 = local;
            let _e258 = ((_e254 * 8u) + (_e256 % 8u));
            local_17 = _e258;
            let _e259 = local_8;
            let _e261 = local;
            local_18 = ((_e259 * 8u) + (_e261 / 8u));
            let _e264 = local_9;
            if (_e258 >= _e264) {
            } else {
                let _e266 = local_18;
                let _e267 = local_13;
                if (_e266 >= _e267) {
                } else {
                    let _e269 = local_17;
                    let _e271 = (f32(_e269) + 0.5f);
                    local_19 = _e271;
                    let _e273 = ((_e271 * 0.5f) - 0.5f);
                    let _e275 = select(0f, _e273, (_e273 > 0f));
                    let _e276 = local_18;
                    let _e278 = (f32(_e276) + 0.5f);
                    local_20 = _e278;
                    let _e280 = ((_e278 * 0.5f) - 0.5f);
                    let _e282 = select(0f, _e280, (_e280 > 0f));
                    let _e283 = floor(_e275);
                    let _e284 = floor(_e282);
                    let _e285 = (_e275 - _e283);
                    local_21 = _e285;
                    let _e286 = (_e282 - _e284);
                    local_22 = _e286;
                    local_23 = select(select(u32(_e283), 0u, !((_e283 >= 0f))), 4294967295u, (_e283 > 4294967000f));
                    local_24 = select(select(u32(_e284), 0u, !((_e284 >= 0f))), 4294967295u, (_e284 > 4294967000f));
                    local_160 = array<f32, 3>(0f, 0f, 0f);
                    local_161 = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_1631_ = false;
                    phi_208_ = 0u;
                    phi_211_ = 0f;
                    loop {
                        let _e300 = phi_1631_;
                        let _e302 = phi_208_;
                        let _e304 = phi_211_;
                        local_25 = _e302;
                        local_26 = _e304;
                        let _e305 = local_25;
                        let _e306 = (_e305 < 4u);
                        local_27 = _e306;
                        if _e306 {
                            let _e307 = local_25;
                            let _e308 = (_e307 % 2u);
                            local_28 = _e308;
                            let _e309 = local_23;
                            let _e310 = (_e309 + _e308);
                            let _e311 = local_12;
                            if (_e310 < _e311) {
                                phi_228_ = _e310;
                            } else {
                                let _e313 = local_12;
                                phi_228_ = (_e313 - 1u);
                            }
                            let _e316 = phi_228_;
                            local_29 = _e316;
                            let _e317 = local_25;
                            let _e318 = (_e317 / 2u);
                            local_30 = _e318;
                            let _e319 = local_24;
                            let _e320 = (_e319 + _e318);
                            let _e321 = local_16;
                            if (_e320 < _e321) {
                                phi_238_ = _e320;
                            } else {
                                let _e323 = local_16;
                                phi_238_ = (_e323 - 1u);
                            }
                            let _e326 = phi_238_;
                            local_31 = _e326;
                            let _e327 = local_28;
                            if (_e327 == 0u) {
                                let _e329 = local_21;
                                phi_245_ = (1f - _e329);
                            } else {
                                phi_245_ = _e285;
                            }
                            let _e332 = phi_245_;
                            local_32 = _e332;
                            let _e333 = local_30;
                            if (_e333 == 0u) {
                                let _e335 = local_22;
                                phi_252_ = (1f - _e335);
                            } else {
                                phi_252_ = _e286;
                            }
                            let _e338 = phi_252_;
                            let _e339 = local_32;
                            local_33 = (_e339 * _e338);
                            let _e341 = local_31;
                            let _e342 = local_12;
                            let _e344 = local_29;
                            let _e346 = (8u * ((_e341 * _e342) + _e344));
                            local_34 = _e346;
                            let _e347 = (_e346 + 3u);
                            local_35 = _e347;
                            let _e348 = local_3;
                            if (_e347 < _e348) {
                            } else {
                                phi_1639_ = true;
                                break;
                            }
                            let _e350 = local_35;
                            let _e353 = global_5.member[_e350];
                            let _e355 = local_33;
                            local_36 = (_e355 * bitcast<f32>(_e353));
                            phi_268_ = 0u;
                            loop {
                                let _e358 = phi_268_;
                                local_37 = _e358;
                                let _e359 = local_37;
                                let _e360 = (_e359 < 3u);
                                local_38 = _e360;
                                if _e360 {
                                    let _e361 = local_34;
                                    let _e362 = local_37;
                                    let _e363 = (_e361 + _e362);
                                    local_39 = _e363;
                                    let _e364 = local_3;
                                    if (_e363 < _e364) {
                                    } else {
                                        phi_1624_ = true;
                                        break;
                                    }
                                    let _e366 = local_39;
                                    let _e369 = global_5.member[_e366];
                                    let _e371 = local_36;
                                    local_40 = (_e371 * bitcast<f32>(_e369));
                                    let _e373 = local_38;
                                    if _e373 {
                                    } else {
                                        phi_1624_ = true;
                                        break;
                                    }
                                    let _e374 = local_37;
                                    let _e376 = local_160[_e374];
                                    let _e377 = local_40;
                                    local_160[_e374] = (_e376 + _e377);
                                    let _e379 = local_37;
                                    phi_269_ = (_e379 + 1u);
                                } else {
                                    phi_269_ = u32();
                                }
                                let _e382 = phi_269_;
                                continue;
                                continuing {
                                    let _e383 = local_38;
                                    phi_268_ = _e382;
                                    phi_1624_ = _e300;
                                    break if !(_e383);
                                }
                            }
                            let _e386 = phi_1624_;
                            phi_1639_ = _e386;
                            if _e386 {
                                break;
                            }
                            let _e387 = local_26;
                            let _e388 = local_36;
                            phi_300_ = 0u;
                            loop {
                                let _e391 = phi_300_;
                                local_41 = _e391;
                                let _e392 = local_41;
                                let _e393 = (_e392 < 4u);
                                local_42 = _e393;
                                if _e393 {
                                    let _e394 = local_34;
                                    let _e396 = local_41;
                                    let _e397 = ((_e394 + 4u) + _e396);
                                    local_43 = _e397;
                                    let _e398 = local_3;
                                    if (_e397 < _e398) {
                                    } else {
                                        phi_1636_ = true;
                                        break;
                                    }
                                    let _e400 = local_43;
                                    let _e403 = global_5.member[_e400];
                                    let _e405 = local_33;
                                    local_44 = (_e405 * bitcast<f32>(_e403));
                                    let _e407 = local_42;
                                    if _e407 {
                                    } else {
                                        phi_1636_ = true;
                                        break;
                                    }
                                    let _e408 = local_41;
                                    let _e410 = local_161[_e408];
                                    let _e411 = local_44;
                                    local_161[_e408] = (_e410 + _e411);
                                    let _e413 = local_41;
                                    phi_301_ = (_e413 + 1u);
                                } else {
                                    phi_301_ = u32();
                                }
                                let _e416 = phi_301_;
                                continue;
                                continuing {
                                    let _e417 = local_42;
                                    phi_300_ = _e416;
                                    phi_1636_ = _e386;
                                    break if !(_e417);
                                }
                            }
                            let _e420 = phi_1636_;
                            phi_1639_ = _e420;
                            if _e420 {
                                break;
                            }
                            let _e421 = local_25;
                            phi_1640_ = _e420;
                            phi_209_ = (_e421 + 1u);
                            phi_212_ = (_e387 + _e388);
                        } else {
                            phi_1640_ = _e300;
                            phi_209_ = u32();
                            phi_212_ = f32();
                        }
                        let _e424 = phi_1640_;
                        let _e426 = phi_209_;
                        let _e428 = phi_212_;
                        continue;
                        continuing {
                            let _e429 = local_27;
                            phi_1631_ = _e424;
                            phi_208_ = _e426;
                            phi_211_ = _e428;
                            phi_1639_ = _e424;
                            break if !(_e429);
                        }
                    }
                    let _e432 = phi_1639_;
                    if _e432 {
                        break;
                    }
                    let _e433 = local_18;
                    let _e434 = local_9;
                    let _e436 = local_17;
                    let _e437 = ((_e433 * _e434) + _e436);
                    local_45 = _e437;
                    local_162 = array<f32, 3>(0f, 0f, 0f);
                    let _e438 = (3u * _e437);
                    local_46 = _e438;
                    let _e439 = local_1;
                    if (_e438 < _e439) {
                    } else {
                        break;
                    }
                    let _e441 = local_46;
                    let _e444 = global_3.member[_e441];
                    local_47 = bitcast<f32>(_e444);
                    let _e446 = local_46;
                    let _e447 = (_e446 + 1u);
                    local_48 = _e447;
                    let _e448 = local_1;
                    if (_e447 < _e448) {
                    } else {
                        break;
                    }
                    let _e450 = local_48;
                    let _e453 = global_3.member[_e450];
                    local_49 = bitcast<f32>(_e453);
                    let _e455 = local_46;
                    let _e456 = (_e455 + 2u);
                    local_50 = _e456;
                    let _e457 = local_1;
                    if (_e456 < _e457) {
                    } else {
                        break;
                    }
                    let _e459 = local_50;
                    let _e462 = global_3.member[_e459];
                    local_51 = bitcast<f32>(_e462);
                    let _e464 = local_47;
                    if (_e464 > 1267650600000000000000000000000f) {
                        let _e466 = local_47;
                        phi_374_ = select(true, false, (_e466 <= 340282350000000000000000000000000000000f));
                    } else {
                        phi_374_ = true;
                    }
                    let _e470 = phi_374_;
                    if _e470 {
                        let _e471 = local_47;
                        if (_e471 < 0.000000000000000000000000000000000000011754944f) {
                            let _e473 = local_47;
                            phi_388_ = select(true, false, (_e473 >= -340282350000000000000000000000000000000f));
                        } else {
                            phi_388_ = true;
                        }
                        let _e477 = phi_388_;
                        let _e478 = local_47;
                        phi_393_ = select(0f, _e478, _e477);
                    } else {
                        phi_393_ = 1267650600000000000000000000000f;
                    }
                    let _e481 = phi_393_;
                    local_52 = _e481;
                    let _e482 = local_49;
                    if (_e482 > 1267650600000000000000000000000f) {
                        let _e484 = local_49;
                        phi_403_ = select(true, false, (_e484 <= 340282350000000000000000000000000000000f));
                    } else {
                        phi_403_ = true;
                    }
                    let _e488 = phi_403_;
                    if _e488 {
                        let _e489 = local_49;
                        if (_e489 < 0.000000000000000000000000000000000000011754944f) {
                            let _e491 = local_49;
                            phi_417_ = select(true, false, (_e491 >= -340282350000000000000000000000000000000f));
                        } else {
                            phi_417_ = true;
                        }
                        let _e495 = phi_417_;
                        let _e496 = local_49;
                        phi_422_ = select(0f, _e496, _e495);
                    } else {
                        phi_422_ = 1267650600000000000000000000000f;
                    }
                    let _e499 = phi_422_;
                    local_53 = _e499;
                    let _e500 = local_51;
                    if (_e500 > 1267650600000000000000000000000f) {
                        let _e502 = local_51;
                        phi_432_ = select(true, false, (_e502 <= 340282350000000000000000000000000000000f));
                    } else {
                        phi_432_ = true;
                    }
                    let _e506 = phi_432_;
                    if _e506 {
                        let _e507 = local_51;
                        if (_e507 < 0.000000000000000000000000000000000000011754944f) {
                            let _e509 = local_51;
                            phi_446_ = select(true, false, (_e509 >= -340282350000000000000000000000000000000f));
                        } else {
                            phi_446_ = true;
                        }
                        let _e513 = phi_446_;
                        let _e514 = local_51;
                        phi_451_ = select(0f, _e514, _e513);
                    } else {
                        phi_451_ = 1267650600000000000000000000000f;
                    }
                    let _e517 = phi_451_;
                    local_54 = _e517;
                    let _e518 = local_52;
                    let _e519 = local_53;
                    local_55 = array<f32, 3>(_e518, _e519, _e517);
                    let _e521 = local_45;
                    let _e522 = local_2;
                    if (_e521 < _e522) {
                    } else {
                        break;
                    }
                    let _e524 = local_45;
                    let _e527 = global_4.member[_e524];
                    local_56 = bitcast<f32>(_e527);
                    let _e529 = local_52;
                    if ((bitcast<u32>(_e529) & 2139095040u) != 2139095040u) {
                        let _e533 = local_53;
                        if ((bitcast<u32>(_e533) & 2139095040u) != 2139095040u) {
                            let _e537 = local_54;
                            if ((bitcast<u32>(_e537) & 2139095040u) != 2139095040u) {
                                let _e541 = local_56;
                                let _e542 = bitcast<u32>(_e541);
                                local_57 = _e542;
                                if (_e542 == 0u) {
                                    phi_485_ = false;
                                } else {
                                    let _e544 = local_57;
                                    phi_485_ = (_e544 <= 2139095040u);
                                }
                                let _e547 = phi_485_;
                                local_58 = _e547;
                                if _e547 {
                                    let _e548 = local_55;
                                    let _e549 = local_56;
                                    phi_491_ = type_22(1u, type_21(_e548, _e549));
                                } else {
                                    phi_491_ = type_22();
                                }
                                let _e553 = phi_491_;
                                let _e554 = local_58;
                                phi_493_ = _e553;
                                phi_494_ = select(true, false, _e554);
                            } else {
                                phi_493_ = type_22();
                                phi_494_ = true;
                            }
                            let _e557 = phi_493_;
                            let _e559 = phi_494_;
                            phi_495_ = _e557;
                            phi_496_ = _e559;
                        } else {
                            phi_495_ = type_22();
                            phi_496_ = true;
                        }
                        let _e561 = phi_495_;
                        let _e563 = phi_496_;
                        phi_497_ = _e561;
                        phi_498_ = _e563;
                    } else {
                        phi_497_ = type_22();
                        phi_498_ = true;
                    }
                    let _e565 = phi_497_;
                    let _e567 = phi_498_;
                    if _e567 {
                        phi_503_ = type_22(0u, type_22().member_1);
                    } else {
                        phi_503_ = _e565;
                    }
                    let _e572 = phi_503_;
                    local_59 = _e572;
                    if (bitcast<i32>(_e572.member) != 0i) {
                        let _e592 = local_59;
                        local_60 = _e592.member_1.member;
                        let _e595 = local_59;
                        local_61 = _e595.member_1.member_1;
                        let _e600 = global_2.member.member_3;
                        local_62 = f32(_e600);
                        let _e602 = bitcast<u32>(_e595.member_1.member_1);
                        local_63 = _e602;
                        if (_e602 == 2139095040u) {
                            let _e646 = global_2.member.member_4.member_1;
                            let _e651 = global_2.member.member_4.member;
                            let _e656 = global_2.member.member_4.member_2;
                            let _e662 = global_2.member.member_4.member_3;
                            phi_574_ = (0.5f * ((((2f * _e646) * _e651) / (_e656 - _e651)) * _e662));
                        } else {
                            let _e604 = local_63;
                            if (_e604 == 0u) {
                                phi_543_ = false;
                            } else {
                                let _e606 = local_63;
                                phi_543_ = (_e606 <= 2139095040u);
                            }
                            let _e609 = phi_543_;
                            if _e609 {
                                let _e613 = global_2.member.member_4.member_1;
                                let _e618 = global_2.member.member_4.member;
                                let _e623 = global_2.member.member_4.member_2;
                                local_64 = _e623;
                                let _e629 = global_2.member.member_4.member_3;
                                let _e630 = ((((2f * _e613) * _e618) / (_e623 - _e618)) * _e629);
                                local_65 = _e630;
                                if (_e630 == 0f) {
                                    phi_571_ = 0f;
                                } else {
                                    let _e632 = local_64;
                                    let _e633 = local_61;
                                    let _e636 = local_65;
                                    phi_571_ = (_e636 * (1f - (_e632 / _e633)));
                                }
                                let _e639 = phi_571_;
                                phi_572_ = _e639;
                            } else {
                                phi_572_ = _e216;
                            }
                            let _e641 = phi_572_;
                            phi_574_ = (0.5f * _e641);
                        }
                        let _e666 = phi_574_;
                        let _e667 = local_62;
                        let _e669 = local_62;
                        let _e670 = select(_e669, _e666, (_e666 < _e667));
                        let _e671 = local_62;
                        let _e672 = -(_e671);
                        local_66 = _e672;
                        let _e674 = select(_e672, _e670, (_e670 > _e672));
                        local_155 = _e674;
                        let _e675 = (_e674 < 0f);
                        local_67 = _e675;
                        if _e675 {
                            let _e676 = local_155;
                            phi_591_ = -(_e676);
                        } else {
                            phi_591_ = _e674;
                        }
                        let _e679 = phi_591_;
                        let _e680 = (_e679 - 1f);
                        let _e682 = select(0f, _e680, (_e680 > 0f));
                        let _e684 = select(1f, _e682, (_e682 < 1f));
                        local_156 = _e684;
                        if (_e684 < 1f) {
                            let _e693 = local_155;
                            let _e695 = local_155;
                            local_157 = select(0f, _e695, (_e693 > 0f));
                            let _e697 = local_67;
                            if _e697 {
                                let _e698 = local_155;
                                phi_617_ = -(_e698);
                            } else {
                                phi_617_ = _e674;
                            }
                            let _e701 = phi_617_;
                            let _e703 = select(1.5f, _e701, (_e701 < 1.5f));
                            let _e704 = (_e703 + 0.5f);
                            let _e706 = select(0f, _e704, (_e704 > 0f));
                            let _e709 = (_e703 * _e703);
                            phi_642_ = 0u;
                            phi_645_ = (select(1f, _e706, (_e706 < 1f)) / select(0.25f, _e709, (_e709 > 0.25f)));
                            phi_647_ = array<f32, 3>(0f, 0f, 0f);
                            loop {
                                let _e714 = phi_642_;
                                let _e716 = phi_645_;
                                let _e718 = phi_647_;
                                local_68 = _e714;
                                local_69 = _e716;
                                local_70 = _e718;
                                let _e719 = local_68;
                                let _e720 = (_e719 < 9u);
                                local_71 = _e720;
                                if _e720 {
                                    let _e721 = local_68;
                                    let _e724 = (bitcast<i32>((_e721 % 3u)) - 1i);
                                    local_72 = _e724;
                                    let _e725 = local_68;
                                    let _e728 = (bitcast<i32>((_e725 / 3u)) - 1i);
                                    local_73 = _e728;
                                    let _e729 = local_17;
                                    local_74 = (bitcast<i32>(_e729) + _e724);
                                    let _e732 = local_18;
                                    local_75 = (bitcast<i32>(_e732) + _e728);
                                    let _e735 = local_68;
                                    if (_e735 == 4u) {
                                        phi_1050_ = _e716;
                                        phi_1051_ = _e718;
                                    } else {
                                        let _e737 = local_74;
                                        if (_e737 >= 0i) {
                                            let _e739 = local_75;
                                            if (_e739 >= 0i) {
                                                let _e741 = local_74;
                                                let _e742 = bitcast<u32>(_e741);
                                                local_76 = _e742;
                                                let _e743 = local_9;
                                                if (_e742 < _e743) {
                                                    let _e745 = local_75;
                                                    let _e746 = bitcast<u32>(_e745);
                                                    local_77 = _e746;
                                                    let _e747 = local_13;
                                                    if (_e746 < _e747) {
                                                        let _e749 = local_77;
                                                        let _e750 = local_9;
                                                        let _e752 = local_76;
                                                        let _e753 = ((_e749 * _e750) + _e752);
                                                        local_78 = _e753;
                                                        let _e754 = (3u * _e753);
                                                        local_79 = _e754;
                                                        let _e755 = local_1;
                                                        if (_e754 < _e755) {
                                                        } else {
                                                            phi_1641_ = true;
                                                            break;
                                                        }
                                                        let _e757 = local_79;
                                                        let _e760 = global_3.member[_e757];
                                                        local_80 = bitcast<f32>(_e760);
                                                        let _e762 = local_79;
                                                        let _e763 = (_e762 + 1u);
                                                        local_81 = _e763;
                                                        let _e764 = local_1;
                                                        if (_e763 < _e764) {
                                                        } else {
                                                            phi_1641_ = true;
                                                            break;
                                                        }
                                                        let _e766 = local_81;
                                                        let _e769 = global_3.member[_e766];
                                                        local_82 = bitcast<f32>(_e769);
                                                        let _e771 = local_79;
                                                        let _e772 = (_e771 + 2u);
                                                        local_83 = _e772;
                                                        let _e773 = local_1;
                                                        if (_e772 < _e773) {
                                                        } else {
                                                            phi_1641_ = true;
                                                            break;
                                                        }
                                                        let _e775 = local_83;
                                                        let _e778 = global_3.member[_e775];
                                                        local_84 = bitcast<f32>(_e778);
                                                        let _e780 = local_80;
                                                        if (_e780 > 1267650600000000000000000000000f) {
                                                            let _e782 = local_80;
                                                            phi_735_ = select(true, false, (_e782 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_735_ = true;
                                                        }
                                                        let _e786 = phi_735_;
                                                        if _e786 {
                                                            let _e787 = local_80;
                                                            if (_e787 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e789 = local_80;
                                                                phi_749_ = select(true, false, (_e789 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_749_ = true;
                                                            }
                                                            let _e793 = phi_749_;
                                                            let _e794 = local_80;
                                                            phi_754_ = select(0f, _e794, _e793);
                                                        } else {
                                                            phi_754_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e797 = phi_754_;
                                                        local_85 = _e797;
                                                        let _e798 = local_82;
                                                        if (_e798 > 1267650600000000000000000000000f) {
                                                            let _e800 = local_82;
                                                            phi_764_ = select(true, false, (_e800 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_764_ = true;
                                                        }
                                                        let _e804 = phi_764_;
                                                        if _e804 {
                                                            let _e805 = local_82;
                                                            if (_e805 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e807 = local_82;
                                                                phi_778_ = select(true, false, (_e807 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_778_ = true;
                                                            }
                                                            let _e811 = phi_778_;
                                                            let _e812 = local_82;
                                                            phi_783_ = select(0f, _e812, _e811);
                                                        } else {
                                                            phi_783_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e815 = phi_783_;
                                                        local_86 = _e815;
                                                        let _e816 = local_84;
                                                        if (_e816 > 1267650600000000000000000000000f) {
                                                            let _e818 = local_84;
                                                            phi_793_ = select(true, false, (_e818 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_793_ = true;
                                                        }
                                                        let _e822 = phi_793_;
                                                        if _e822 {
                                                            let _e823 = local_84;
                                                            if (_e823 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e825 = local_84;
                                                                phi_807_ = select(true, false, (_e825 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_807_ = true;
                                                            }
                                                            let _e829 = phi_807_;
                                                            let _e830 = local_84;
                                                            phi_812_ = select(0f, _e830, _e829);
                                                        } else {
                                                            phi_812_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e833 = phi_812_;
                                                        local_87 = _e833;
                                                        let _e834 = local_85;
                                                        let _e835 = local_86;
                                                        local_88 = array<f32, 3>(_e834, _e835, _e833);
                                                        let _e837 = local_78;
                                                        let _e838 = local_2;
                                                        if (_e837 < _e838) {
                                                        } else {
                                                            phi_1641_ = true;
                                                            break;
                                                        }
                                                        let _e840 = local_78;
                                                        let _e843 = global_4.member[_e840];
                                                        local_89 = bitcast<f32>(_e843);
                                                        let _e845 = local_85;
                                                        if ((bitcast<u32>(_e845) & 2139095040u) != 2139095040u) {
                                                            let _e849 = local_86;
                                                            if ((bitcast<u32>(_e849) & 2139095040u) != 2139095040u) {
                                                                let _e853 = local_87;
                                                                if ((bitcast<u32>(_e853) & 2139095040u) != 2139095040u) {
                                                                    let _e857 = local_89;
                                                                    let _e858 = bitcast<u32>(_e857);
                                                                    local_90 = _e858;
                                                                    if (_e858 == 0u) {
                                                                        phi_846_ = false;
                                                                    } else {
                                                                        let _e860 = local_90;
                                                                        phi_846_ = (_e860 <= 2139095040u);
                                                                    }
                                                                    let _e863 = phi_846_;
                                                                    local_91 = _e863;
                                                                    if _e863 {
                                                                        let _e864 = local_88;
                                                                        let _e865 = local_89;
                                                                        phi_852_ = type_22(1u, type_21(_e864, _e865));
                                                                    } else {
                                                                        phi_852_ = type_22();
                                                                    }
                                                                    let _e869 = phi_852_;
                                                                    let _e870 = local_91;
                                                                    phi_854_ = _e869;
                                                                    phi_855_ = select(true, false, _e870);
                                                                } else {
                                                                    phi_854_ = type_22();
                                                                    phi_855_ = true;
                                                                }
                                                                let _e873 = phi_854_;
                                                                let _e875 = phi_855_;
                                                                phi_856_ = _e873;
                                                                phi_857_ = _e875;
                                                            } else {
                                                                phi_856_ = type_22();
                                                                phi_857_ = true;
                                                            }
                                                            let _e877 = phi_856_;
                                                            let _e879 = phi_857_;
                                                            phi_858_ = _e877;
                                                            phi_859_ = _e879;
                                                        } else {
                                                            phi_858_ = type_22();
                                                            phi_859_ = true;
                                                        }
                                                        let _e881 = phi_858_;
                                                        let _e883 = phi_859_;
                                                        if _e883 {
                                                            phi_864_ = type_22(0u, type_22().member_1);
                                                        } else {
                                                            phi_864_ = _e881;
                                                        }
                                                        let _e888 = phi_864_;
                                                        local_92 = _e888;
                                                        if (bitcast<i32>(_e888.member) != 0i) {
                                                            let _e892 = local_92;
                                                            local_93 = _e892.member_1.member;
                                                            let _e895 = local_92;
                                                            local_94 = _e895.member_1.member_1;
                                                            let _e898 = bitcast<u32>(_e895.member_1.member_1);
                                                            local_95 = _e898;
                                                            if (_e898 == 2139095040u) {
                                                                let _e942 = global_2.member.member_4.member_1;
                                                                let _e947 = global_2.member.member_4.member;
                                                                let _e952 = global_2.member.member_4.member_2;
                                                                let _e958 = global_2.member.member_4.member_3;
                                                                phi_935_ = (0.5f * ((((2f * _e942) * _e947) / (_e952 - _e947)) * _e958));
                                                            } else {
                                                                let _e900 = local_95;
                                                                if (_e900 == 0u) {
                                                                    phi_904_ = false;
                                                                } else {
                                                                    let _e902 = local_95;
                                                                    phi_904_ = (_e902 <= 2139095040u);
                                                                }
                                                                let _e905 = phi_904_;
                                                                if _e905 {
                                                                    let _e909 = global_2.member.member_4.member_1;
                                                                    let _e914 = global_2.member.member_4.member;
                                                                    let _e919 = global_2.member.member_4.member_2;
                                                                    local_96 = _e919;
                                                                    let _e925 = global_2.member.member_4.member_3;
                                                                    let _e926 = ((((2f * _e909) * _e914) / (_e919 - _e914)) * _e925);
                                                                    local_97 = _e926;
                                                                    if (_e926 == 0f) {
                                                                        phi_932_ = 0f;
                                                                    } else {
                                                                        let _e928 = local_96;
                                                                        let _e929 = local_94;
                                                                        let _e932 = local_97;
                                                                        phi_932_ = (_e932 * (1f - (_e928 / _e929)));
                                                                    }
                                                                    let _e935 = phi_932_;
                                                                    phi_933_ = _e935;
                                                                } else {
                                                                    phi_933_ = _e216;
                                                                }
                                                                let _e937 = phi_933_;
                                                                phi_935_ = (0.5f * _e937);
                                                            }
                                                            let _e962 = phi_935_;
                                                            let _e963 = local_62;
                                                            let _e965 = local_62;
                                                            let _e966 = select(_e965, _e962, (_e962 < _e963));
                                                            let _e967 = local_66;
                                                            let _e969 = local_66;
                                                            let _e970 = select(_e969, _e966, (_e966 > _e967));
                                                            local_158 = _e970;
                                                            let _e971 = local_155;
                                                            if (_e970 > _e971) {
                                                                let _e979 = local_158;
                                                                if (_e979 < 0f) {
                                                                    let _e981 = local_158;
                                                                    phi_956_ = -(_e981);
                                                                } else {
                                                                    phi_956_ = _e970;
                                                                }
                                                                let _e984 = phi_956_;
                                                                let _e985 = local_157;
                                                                let _e987 = local_157;
                                                                phi_968_ = select(_e987, _e984, (_e984 < _e985));
                                                            } else {
                                                                let _e973 = local_158;
                                                                if (_e973 < 0f) {
                                                                    let _e975 = local_158;
                                                                    phi_967_ = -(_e975);
                                                                } else {
                                                                    phi_967_ = _e970;
                                                                }
                                                                let _e978 = phi_967_;
                                                                phi_968_ = _e978;
                                                            }
                                                            let _e990 = phi_968_;
                                                            let _e992 = select(1.5f, _e990, (_e990 < 1.5f));
                                                            let _e993 = local_72;
                                                            let _e994 = local_72;
                                                            let _e996 = local_73;
                                                            let _e997 = local_73;
                                                            let _e1003 = ((_e992 - sqrt(f32(((_e993 * _e994) + (_e996 * _e997))))) + 0.5f);
                                                            let _e1005 = select(0f, _e1003, (_e1003 > 0f));
                                                            let _e1007 = select(1f, _e1005, (_e1005 < 1f));
                                                            let _e1008 = local_158;
                                                            let _e1010 = ((-1f - _e1008) * 0.5f);
                                                            let _e1012 = select(0f, _e1010, (_e1010 > 0f));
                                                            let _e1018 = (_e992 * _e992);
                                                            let _e1021 = ((((1f - select(1f, _e1012, (_e1012 < 1f))) * _e1007) * _e1007) / select(0.25f, _e1018, (_e1018 > 0.25f)));
                                                            local_98 = _e1021;
                                                            if (_e1021 > 0f) {
                                                                let _e1023 = local_70;
                                                                let _e1025 = local_93;
                                                                let _e1027 = local_60;
                                                                let _e1030 = local_98;
                                                                let _e1033 = local_70;
                                                                let _e1035 = local_93;
                                                                let _e1037 = local_60;
                                                                let _e1040 = local_98;
                                                                let _e1043 = local_70;
                                                                let _e1045 = local_93;
                                                                let _e1047 = local_60;
                                                                let _e1050 = local_98;
                                                                let _e1054 = local_69;
                                                                let _e1055 = local_98;
                                                                phi_1038_ = (_e1054 + _e1055);
                                                                phi_1039_ = array<f32, 3>((_e1023[0] + (_e1030 * (_e1025[0] - _e1027[0]))), (_e1033[1] + (_e1040 * (_e1035[1] - _e1037[1]))), (_e1043[2] + (_e1050 * (_e1045[2] - _e1047[2]))));
                                                            } else {
                                                                phi_1038_ = _e716;
                                                                phi_1039_ = _e718;
                                                            }
                                                            let _e1058 = phi_1038_;
                                                            let _e1060 = phi_1039_;
                                                            phi_1040_ = _e1058;
                                                            phi_1041_ = _e1060;
                                                        } else {
                                                            phi_1040_ = _e716;
                                                            phi_1041_ = _e718;
                                                        }
                                                        let _e1062 = phi_1040_;
                                                        let _e1064 = phi_1041_;
                                                        phi_1042_ = _e1062;
                                                        phi_1043_ = _e1064;
                                                    } else {
                                                        phi_1042_ = _e716;
                                                        phi_1043_ = _e718;
                                                    }
                                                    let _e1066 = phi_1042_;
                                                    let _e1068 = phi_1043_;
                                                    phi_1044_ = _e1066;
                                                    phi_1045_ = _e1068;
                                                } else {
                                                    phi_1044_ = _e716;
                                                    phi_1045_ = _e718;
                                                }
                                                let _e1070 = phi_1044_;
                                                let _e1072 = phi_1045_;
                                                phi_1046_ = _e1070;
                                                phi_1047_ = _e1072;
                                            } else {
                                                phi_1046_ = _e716;
                                                phi_1047_ = _e718;
                                            }
                                            let _e1074 = phi_1046_;
                                            let _e1076 = phi_1047_;
                                            phi_1048_ = _e1074;
                                            phi_1049_ = _e1076;
                                        } else {
                                            phi_1048_ = _e716;
                                            phi_1049_ = _e718;
                                        }
                                        let _e1078 = phi_1048_;
                                        let _e1080 = phi_1049_;
                                        phi_1050_ = _e1078;
                                        phi_1051_ = _e1080;
                                    }
                                    let _e1082 = phi_1050_;
                                    let _e1084 = phi_1051_;
                                    let _e1085 = local_68;
                                    phi_643_ = (_e1085 + 1u);
                                    phi_646_ = _e1082;
                                    phi_648_ = _e1084;
                                } else {
                                    phi_643_ = u32();
                                    phi_646_ = f32();
                                    phi_648_ = array<f32, 3>();
                                }
                                let _e1088 = phi_643_;
                                let _e1090 = phi_646_;
                                let _e1092 = phi_648_;
                                continue;
                                continuing {
                                    let _e1093 = local_71;
                                    phi_642_ = _e1088;
                                    phi_645_ = _e1090;
                                    phi_647_ = _e1092;
                                    phi_1641_ = _e432;
                                    break if !(_e1093);
                                }
                            }
                            let _e1096 = phi_1641_;
                            if _e1096 {
                                break;
                            }
                            let _e1097 = local_69;
                            let _e1098 = (1f / _e1097);
                            let _e1099 = local_60;
                            let _e1101 = local_70;
                            let _e1105 = local_60;
                            let _e1107 = local_70;
                            let _e1111 = local_60;
                            let _e1113 = local_70;
                            local_162 = array<f32, 3>((_e1099[0] + (_e1101[0] * _e1098)), (_e1105[1] + (_e1107[1] * _e1098)), (_e1111[2] + (_e1113[2] * _e1098)));
                            phi_1733_ = _e1096;
                        } else {
                            let _e686 = local_60;
                            let _e688 = local_60;
                            let _e690 = local_60;
                            local_162 = array<f32, 3>(_e686[0], _e688[1], _e690[2]);
                            phi_1733_ = _e432;
                        }
                        let _e1119 = phi_1733_;
                        let _e1120 = local_156;
                        if (_e1120 > 0f) {
                            let _e1122 = local_26;
                            if (_e1122 > 0f) {
                                let _e1124 = local_26;
                                local_99 = (1f / _e1124);
                                phi_1085_ = 0u;
                                loop {
                                    let _e1127 = phi_1085_;
                                    local_100 = _e1127;
                                    let _e1128 = local_100;
                                    let _e1129 = (_e1128 < 3u);
                                    local_101 = _e1129;
                                    if _e1129 {
                                        let _e1130 = local_101;
                                        if _e1130 {
                                        } else {
                                            phi_1730_ = true;
                                            break;
                                        }
                                        let _e1131 = local_100;
                                        let _e1133 = local_160[_e1131];
                                        let _e1134 = local_99;
                                        local_102 = (_e1133 * _e1134);
                                        let _e1136 = local_101;
                                        if _e1136 {
                                        } else {
                                            phi_1730_ = true;
                                            break;
                                        }
                                        let _e1137 = local_100;
                                        let _e1139 = local_162[_e1137];
                                        let _e1140 = local_102;
                                        let _e1142 = local_156;
                                        local_103 = (_e1142 * (_e1140 - _e1139));
                                        let _e1144 = local_101;
                                        if _e1144 {
                                        } else {
                                            phi_1730_ = true;
                                            break;
                                        }
                                        let _e1145 = local_162[_e1137];
                                        let _e1146 = local_103;
                                        local_162[_e1137] = (_e1145 + _e1146);
                                        let _e1148 = local_100;
                                        phi_1086_ = (_e1148 + 1u);
                                    } else {
                                        phi_1086_ = u32();
                                    }
                                    let _e1151 = phi_1086_;
                                    continue;
                                    continuing {
                                        let _e1152 = local_101;
                                        phi_1085_ = _e1151;
                                        phi_1730_ = _e1119;
                                        break if !(_e1152);
                                    }
                                }
                                let _e1155 = phi_1730_;
                                if _e1155 {
                                    break;
                                }
                                phi_1756_ = _e1155;
                            } else {
                                phi_1756_ = _e1119;
                            }
                            let _e1157 = phi_1756_;
                            phi_1755_ = _e1157;
                        } else {
                            phi_1755_ = _e1119;
                        }
                        let _e1159 = phi_1755_;
                        phi_1754_ = _e1159;
                        phi_1139_ = _e674;
                    } else {
                        let _e576 = local_26;
                        if (_e576 > 0f) {
                            let _e578 = local_26;
                            let _e579 = (1f / _e578);
                            let _e581 = local_160[0u];
                            let _e584 = local_160[1u];
                            let _e587 = local_160[2u];
                            local_162[0u] = (_e581 * _e579);
                            local_162[1u] = (_e584 * _e579);
                            local_162[2u] = (_e587 * _e579);
                        }
                        phi_1754_ = _e432;
                        phi_1139_ = _e216;
                    }
                    let _e1161 = phi_1754_;
                    let _e1163 = phi_1139_;
                    local_104 = _e1163;
                    let _e1164 = local_11;
                    if _e1164 {
                        let _e1165 = local_10;
                        phi_1157_ = (_e1165 + 1u);
                    } else {
                        phi_1157_ = _e237;
                    }
                    let _e1168 = phi_1157_;
                    let _e1169 = (_e1168 / 8u);
                    local_105 = _e1169;
                    if ((_e1168 % 8u) > 0u) {
                        let _e1172 = local_105;
                        phi_1173_ = (_e1172 + 1u);
                    } else {
                        phi_1173_ = _e1169;
                    }
                    let _e1175 = phi_1173_;
                    local_106 = _e1175;
                    let _e1176 = local_15;
                    if _e1176 {
                        let _e1177 = local_14;
                        phi_1191_ = (_e1177 + 1u);
                    } else {
                        phi_1191_ = _e247;
                    }
                    let _e1180 = phi_1191_;
                    let _e1181 = (_e1180 / 8u);
                    local_107 = _e1181;
                    if ((_e1180 % 8u) > 0u) {
                        let _e1184 = local_107;
                        phi_1207_ = (_e1184 + 1u);
                    } else {
                        phi_1207_ = _e1181;
                    }
                    let _e1187 = phi_1207_;
                    local_108 = _e1187;
                    let _e1188 = local_17;
                    let _e1189 = (_e1188 / 16u);
                    local_109 = _e1189;
                    let _e1190 = local_18;
                    let _e1191 = (_e1190 / 16u);
                    local_110 = _e1191;
                    let _e1192 = local_106;
                    let _e1196 = ((2u * ((_e1191 * _e1192) + _e1189)) + 1u);
                    local_111 = _e1196;
                    let _e1197 = local_5;
                    if (_e1196 < _e1197) {
                    } else {
                        break;
                    }
                    let _e1199 = local_111;
                    let _e1202 = global_7.member[_e1199];
                    local_112 = _e1202;
                    if (_e1202 == 0u) {
                        phi_1508_ = type_24(array<f32, 3>(0f, 0f, 0f), array<f32, 3>(0f, 0f, 0f));
                    } else {
                        let _e1204 = local_112;
                        local_113 = bitcast<i32>((_e1204 - 1u));
                        let _e1207 = local_104;
                        let _e1211 = !(((bitcast<u32>(_e1207) & 2147483647u) > 2139095040u));
                        local_114 = _e1211;
                        if _e1211 {
                            let _e1212 = local_104;
                            let _e1214 = local_104;
                            phi_1244_ = select(0f, _e1214, (_e1212 > 0f));
                        } else {
                            phi_1244_ = 0f;
                        }
                        let _e1217 = phi_1244_;
                        local_115 = _e1217;
                        let _e1218 = local_114;
                        if _e1218 {
                            let _e1219 = local_104;
                            let _e1221 = ((_e1219 * -0.5f) - 0.5f);
                            let _e1223 = select(0f, _e1221, (_e1221 > 0f));
                            phi_1262_ = select(1f, _e1223, (_e1223 < 1f));
                        } else {
                            phi_1262_ = 1f;
                        }
                        let _e1227 = phi_1262_;
                        local_116 = _e1227;
                        let _e1228 = local_113;
                        let _e1229 = -(_e1228);
                        phi_1744_ = _e1161;
                        phi_1265_ = _e1229;
                        phi_1268_ = array<f32, 3>(0f, 0f, 0f);
                        phi_1270_ = array<f32, 3>(0f, 0f, 0f);
                        loop {
                            let _e1231 = phi_1744_;
                            let _e1233 = phi_1265_;
                            let _e1235 = phi_1268_;
                            let _e1237 = phi_1270_;
                            local_117 = _e1233;
                            local_118 = _e1235;
                            local_119 = _e1237;
                            let _e1238 = local_117;
                            let _e1239 = local_113;
                            let _e1240 = (_e1238 <= _e1239);
                            local_120 = _e1240;
                            if _e1240 {
                                let _e1241 = local_110;
                                let _e1243 = local_117;
                                local_121 = (bitcast<i32>(_e1241) + _e1243);
                                phi_1743_ = _e1231;
                                phi_1282_ = _e1229;
                                phi_1285_ = _e1235;
                                phi_1287_ = _e1237;
                                loop {
                                    let _e1246 = phi_1743_;
                                    let _e1248 = phi_1282_;
                                    let _e1250 = phi_1285_;
                                    let _e1252 = phi_1287_;
                                    local_122 = _e1248;
                                    local_165 = _e1250;
                                    local_166 = _e1252;
                                    let _e1253 = local_121;
                                    if (_e1253 >= 0i) {
                                        let _e1255 = local_108;
                                        let _e1257 = local_121;
                                        if (_e1257 < bitcast<i32>(_e1255)) {
                                            let _e1259 = local_122;
                                            let _e1260 = local_113;
                                            let _e1261 = (_e1259 <= _e1260);
                                            if _e1261 {
                                                let _e1262 = local_109;
                                                let _e1264 = local_122;
                                                let _e1265 = (bitcast<i32>(_e1262) + _e1264);
                                                local_123 = _e1265;
                                                if (_e1265 >= 0i) {
                                                    let _e1267 = local_106;
                                                    let _e1269 = local_123;
                                                    if (_e1269 < bitcast<i32>(_e1267)) {
                                                        let _e1271 = local_121;
                                                        let _e1273 = local_106;
                                                        let _e1275 = local_123;
                                                        let _e1278 = (66u * ((bitcast<u32>(_e1271) * _e1273) + bitcast<u32>(_e1275)));
                                                        local_124 = _e1278;
                                                        let _e1279 = local_4;
                                                        if (_e1278 < _e1279) {
                                                        } else {
                                                            phi_1759_ = true;
                                                            break;
                                                        }
                                                        let _e1281 = local_124;
                                                        let _e1284 = global_6.member[_e1281];
                                                        local_125 = _e1284;
                                                        phi_1328_ = 0u;
                                                        phi_1331_ = _e1250;
                                                        phi_1333_ = _e1252;
                                                        loop {
                                                            let _e1286 = phi_1328_;
                                                            let _e1288 = phi_1331_;
                                                            let _e1290 = phi_1333_;
                                                            local_126 = _e1286;
                                                            local_127 = _e1288;
                                                            local_128 = _e1290;
                                                            local_163 = _e1288;
                                                            local_164 = _e1290;
                                                            let _e1291 = local_126;
                                                            let _e1292 = local_125;
                                                            let _e1293 = (_e1291 < _e1292);
                                                            local_129 = _e1293;
                                                            if _e1293 {
                                                                let _e1294 = local_124;
                                                                let _e1296 = local_126;
                                                                let _e1298 = ((_e1294 + 2u) + (8u * _e1296));
                                                                local_130 = _e1298;
                                                                let _e1299 = local_4;
                                                                if (_e1298 < _e1299) {
                                                                } else {
                                                                    phi_1734_ = true;
                                                                    break;
                                                                }
                                                                let _e1301 = local_130;
                                                                let _e1304 = global_6.member[_e1301];
                                                                local_131 = bitcast<f32>(_e1304);
                                                                let _e1306 = local_130;
                                                                let _e1307 = (_e1306 + 1u);
                                                                local_132 = _e1307;
                                                                let _e1308 = local_4;
                                                                if (_e1307 < _e1308) {
                                                                } else {
                                                                    phi_1734_ = true;
                                                                    break;
                                                                }
                                                                let _e1310 = local_132;
                                                                let _e1313 = global_6.member[_e1310];
                                                                local_133 = bitcast<f32>(_e1313);
                                                                let _e1315 = local_130;
                                                                let _e1316 = (_e1315 + 2u);
                                                                local_134 = _e1316;
                                                                let _e1317 = local_4;
                                                                if (_e1316 < _e1317) {
                                                                } else {
                                                                    phi_1734_ = true;
                                                                    break;
                                                                }
                                                                let _e1319 = local_134;
                                                                let _e1322 = global_6.member[_e1319];
                                                                let _e1323 = bitcast<f32>(_e1322);
                                                                local_135 = _e1323;
                                                                let _e1324 = local_19;
                                                                let _e1325 = local_131;
                                                                let _e1326 = (_e1324 - _e1325);
                                                                let _e1327 = local_20;
                                                                let _e1328 = local_133;
                                                                let _e1329 = (_e1327 - _e1328);
                                                                local_136 = sqrt(((_e1326 * _e1326) + (_e1329 * _e1329)));
                                                                let _e1334 = (_e1323 < 0f);
                                                                local_137 = _e1334;
                                                                if _e1334 {
                                                                    let _e1335 = local_135;
                                                                    phi_1381_ = -(_e1335);
                                                                } else {
                                                                    phi_1381_ = _e1323;
                                                                }
                                                                let _e1338 = phi_1381_;
                                                                local_138 = _e1338;
                                                                let _e1339 = local_137;
                                                                if _e1339 {
                                                                    phi_1394_ = _e1338;
                                                                } else {
                                                                    let _e1340 = local_138;
                                                                    let _e1341 = local_115;
                                                                    let _e1343 = local_138;
                                                                    let _e1344 = local_115;
                                                                    let _e1345 = select(_e1344, _e1343, (_e1340 < _e1341));
                                                                    let _e1346 = local_138;
                                                                    let _e1348 = local_116;
                                                                    phi_1394_ = (_e1345 + (_e1348 * (_e1346 - _e1345)));
                                                                }
                                                                let _e1352 = phi_1394_;
                                                                local_139 = _e1352;
                                                                let _e1353 = local_130;
                                                                let _e1354 = (_e1353 + 6u);
                                                                local_140 = _e1354;
                                                                let _e1355 = local_4;
                                                                if (_e1354 < _e1355) {
                                                                } else {
                                                                    phi_1734_ = true;
                                                                    break;
                                                                }
                                                                let _e1357 = local_140;
                                                                let _e1360 = global_6.member[_e1357];
                                                                let _e1361 = bitcast<f32>(_e1360);
                                                                local_141 = _e1361;
                                                                let _e1362 = local_139;
                                                                let _e1364 = ((_e1362 + 0.5f) + _e1361);
                                                                local_142 = _e1364;
                                                                let _e1365 = local_136;
                                                                if (_e1365 < _e1364) {
                                                                    let _e1367 = local_141;
                                                                    let _e1370 = local_142;
                                                                    let _e1371 = local_136;
                                                                    let _e1373 = ((_e1370 - _e1371) / (1f + (2f * _e1367)));
                                                                    local_159 = select(0f, select(1f, _e1373, (_e1373 < 1f)), (0f < _e1373));
                                                                    let _e1378 = local_130;
                                                                    let _e1379 = (_e1378 + 3u);
                                                                    local_143 = _e1379;
                                                                    let _e1380 = local_4;
                                                                    if (_e1379 < _e1380) {
                                                                    } else {
                                                                        phi_1734_ = true;
                                                                        break;
                                                                    }
                                                                    let _e1382 = local_143;
                                                                    let _e1385 = global_6.member[_e1382];
                                                                    local_144 = bitcast<f32>(_e1385);
                                                                    let _e1387 = local_130;
                                                                    let _e1388 = (_e1387 + 4u);
                                                                    local_145 = _e1388;
                                                                    let _e1389 = local_4;
                                                                    if (_e1388 < _e1389) {
                                                                    } else {
                                                                        phi_1734_ = true;
                                                                        break;
                                                                    }
                                                                    let _e1391 = local_145;
                                                                    let _e1394 = global_6.member[_e1391];
                                                                    local_146 = bitcast<f32>(_e1394);
                                                                    let _e1396 = local_130;
                                                                    let _e1397 = (_e1396 + 5u);
                                                                    local_147 = _e1397;
                                                                    let _e1398 = local_4;
                                                                    if (_e1397 < _e1398) {
                                                                    } else {
                                                                        phi_1734_ = true;
                                                                        break;
                                                                    }
                                                                    let _e1400 = local_147;
                                                                    let _e1403 = global_6.member[_e1400];
                                                                    local_148 = bitcast<f32>(_e1403);
                                                                    let _e1405 = local_137;
                                                                    if _e1405 {
                                                                        let _e1425 = local_127;
                                                                        let _e1427 = local_159;
                                                                        let _e1428 = local_144;
                                                                        let _e1431 = local_127;
                                                                        let _e1433 = local_159;
                                                                        let _e1434 = local_146;
                                                                        let _e1437 = local_127;
                                                                        let _e1439 = local_159;
                                                                        let _e1440 = local_148;
                                                                        phi_1477_ = array<f32, 3>((_e1425[0] + (_e1427 * _e1428)), (_e1431[1] + (_e1433 * _e1434)), (_e1437[2] + (_e1439 * _e1440)));
                                                                        phi_1478_ = _e1290;
                                                                    } else {
                                                                        let _e1406 = local_128;
                                                                        let _e1408 = local_159;
                                                                        let _e1409 = local_144;
                                                                        let _e1412 = local_128;
                                                                        let _e1414 = local_159;
                                                                        let _e1415 = local_146;
                                                                        let _e1418 = local_128;
                                                                        let _e1420 = local_159;
                                                                        let _e1421 = local_148;
                                                                        phi_1477_ = _e1288;
                                                                        phi_1478_ = array<f32, 3>((_e1406[0] + (_e1408 * _e1409)), (_e1412[1] + (_e1414 * _e1415)), (_e1418[2] + (_e1420 * _e1421)));
                                                                    }
                                                                    let _e1445 = phi_1477_;
                                                                    let _e1447 = phi_1478_;
                                                                    phi_1479_ = _e1445;
                                                                    phi_1480_ = _e1447;
                                                                } else {
                                                                    phi_1479_ = _e1288;
                                                                    phi_1480_ = _e1290;
                                                                }
                                                                let _e1449 = phi_1479_;
                                                                let _e1451 = phi_1480_;
                                                                let _e1452 = local_126;
                                                                phi_1329_ = (_e1452 + 1u);
                                                                phi_1332_ = _e1449;
                                                                phi_1334_ = _e1451;
                                                            } else {
                                                                phi_1329_ = u32();
                                                                phi_1332_ = array<f32, 3>();
                                                                phi_1334_ = array<f32, 3>();
                                                            }
                                                            let _e1455 = phi_1329_;
                                                            let _e1457 = phi_1332_;
                                                            let _e1459 = phi_1334_;
                                                            continue;
                                                            continuing {
                                                                let _e1460 = local_129;
                                                                phi_1328_ = _e1455;
                                                                phi_1331_ = _e1457;
                                                                phi_1333_ = _e1459;
                                                                phi_1734_ = _e1246;
                                                                break if !(_e1460);
                                                            }
                                                        }
                                                        let _e1463 = phi_1734_;
                                                        phi_1759_ = _e1463;
                                                        if _e1463 {
                                                            break;
                                                        }
                                                        phi_1764_ = _e1463;
                                                        let _e1729 = local_163;
                                                        phi_1482_ = _e1729;
                                                        let _e1732 = local_164;
                                                        phi_1483_ = _e1732;
                                                    } else {
                                                        phi_1764_ = _e1246;
                                                        phi_1482_ = _e1250;
                                                        phi_1483_ = _e1252;
                                                    }
                                                    let _e1465 = phi_1764_;
                                                    let _e1467 = phi_1482_;
                                                    let _e1469 = phi_1483_;
                                                    phi_1763_ = _e1465;
                                                    phi_1484_ = _e1467;
                                                    phi_1485_ = _e1469;
                                                } else {
                                                    phi_1763_ = _e1246;
                                                    phi_1484_ = _e1250;
                                                    phi_1485_ = _e1252;
                                                }
                                                let _e1471 = phi_1763_;
                                                let _e1473 = phi_1484_;
                                                let _e1475 = phi_1485_;
                                                let _e1476 = local_122;
                                                phi_1762_ = _e1471;
                                                phi_1487_ = (_e1476 + 1i);
                                                phi_1488_ = _e1473;
                                                phi_1489_ = _e1475;
                                            } else {
                                                phi_1762_ = _e1246;
                                                phi_1487_ = i32();
                                                phi_1488_ = array<f32, 3>();
                                                phi_1489_ = array<f32, 3>();
                                            }
                                            let _e1479 = phi_1762_;
                                            let _e1481 = phi_1487_;
                                            let _e1483 = phi_1488_;
                                            let _e1485 = phi_1489_;
                                            phi_1761_ = _e1479;
                                            phi_1491_ = _e1481;
                                            phi_1492_ = _e1483;
                                            phi_1493_ = _e1485;
                                            phi_1494_ = _e1261;
                                        } else {
                                            phi_1761_ = _e1246;
                                            phi_1491_ = i32();
                                            phi_1492_ = array<f32, 3>();
                                            phi_1493_ = array<f32, 3>();
                                            phi_1494_ = false;
                                        }
                                        let _e1487 = phi_1761_;
                                        let _e1489 = phi_1491_;
                                        let _e1491 = phi_1492_;
                                        let _e1493 = phi_1493_;
                                        let _e1495 = phi_1494_;
                                        phi_1760_ = _e1487;
                                        phi_1283_ = _e1489;
                                        phi_1286_ = _e1491;
                                        phi_1288_ = _e1493;
                                        phi_1496_ = _e1495;
                                    } else {
                                        phi_1760_ = _e1246;
                                        phi_1283_ = i32();
                                        phi_1286_ = array<f32, 3>();
                                        phi_1288_ = array<f32, 3>();
                                        phi_1496_ = false;
                                    }
                                    let _e1497 = phi_1760_;
                                    let _e1499 = phi_1283_;
                                    let _e1501 = phi_1286_;
                                    let _e1503 = phi_1288_;
                                    let _e1505 = phi_1496_;
                                    local_149 = _e1505;
                                    continue;
                                    continuing {
                                        let _e1506 = local_149;
                                        phi_1743_ = _e1497;
                                        phi_1282_ = _e1499;
                                        phi_1285_ = _e1501;
                                        phi_1287_ = _e1503;
                                        phi_1759_ = _e1497;
                                        break if !(_e1506);
                                    }
                                }
                                let _e1509 = phi_1759_;
                                phi_1765_ = _e1509;
                                if _e1509 {
                                    break;
                                }
                                let _e1510 = local_117;
                                phi_1766_ = _e1509;
                                phi_1266_ = (_e1510 + 1i);
                                let _e1755 = local_165;
                                phi_1269_ = _e1755;
                                let _e1758 = local_166;
                                phi_1271_ = _e1758;
                            } else {
                                phi_1766_ = _e1231;
                                phi_1266_ = i32();
                                phi_1269_ = array<f32, 3>();
                                phi_1271_ = array<f32, 3>();
                            }
                            let _e1513 = phi_1766_;
                            let _e1515 = phi_1266_;
                            let _e1517 = phi_1269_;
                            let _e1519 = phi_1271_;
                            continue;
                            continuing {
                                let _e1520 = local_120;
                                phi_1744_ = _e1513;
                                phi_1265_ = _e1515;
                                phi_1268_ = _e1517;
                                phi_1270_ = _e1519;
                                phi_1765_ = _e1513;
                                break if !(_e1520);
                            }
                        }
                        let _e1523 = phi_1765_;
                        if _e1523 {
                            break;
                        }
                        let _e1524 = local_119;
                        let _e1525 = local_118;
                        phi_1508_ = type_24(_e1524, _e1525);
                    }
                    let _e1528 = phi_1508_;
                    local_150 = _e1528.member_1;
                    let _e1532 = local_162[0u];
                    let _e1536 = local_162[1u];
                    let _e1540 = local_162[2u];
                    local_162[0u] = (_e1532 + _e1528.member[0]);
                    local_162[1u] = (_e1536 + _e1528.member[1]);
                    local_162[2u] = (_e1540 + _e1528.member[2]);
                    let _e1544 = local_161[3u];
                    local_151 = _e1544;
                    if (_e1544 > 0f) {
                        let _e1546 = local_151;
                        let _e1547 = (1f - _e1546);
                        let _e1548 = local_162[0u];
                        let _e1551 = local_161[0u];
                        let _e1553 = local_162[1u];
                        let _e1556 = local_161[1u];
                        let _e1558 = local_162[2u];
                        let _e1561 = local_161[2u];
                        local_162[0u] = ((_e1548 * _e1547) + _e1551);
                        local_162[1u] = ((_e1553 * _e1547) + _e1556);
                        local_162[2u] = ((_e1558 * _e1547) + _e1561);
                    }
                    let _e1563 = local_162[0u];
                    let _e1564 = local_150;
                    let _e1567 = local_162[1u];
                    let _e1568 = local_150;
                    let _e1571 = local_162[2u];
                    let _e1572 = local_150;
                    local_162[0u] = (_e1563 + _e1564[0]);
                    local_162[1u] = (_e1567 + _e1568[1]);
                    local_162[2u] = (_e1571 + _e1572[2]);
                    let _e1575 = local_162[0u];
                    local_152 = bitcast<u32>(_e1575);
                    let _e1577 = local_46;
                    let _e1578 = local_6;
                    if (_e1577 < _e1578) {
                    } else {
                        break;
                    }
                    let _e1580 = local_46;
                    let _e1583 = local_152;
                    global_8.member[_e1580] = _e1583;
                    let _e1584 = local_162[1u];
                    local_153 = bitcast<u32>(_e1584);
                    let _e1586 = local_48;
                    let _e1587 = local_6;
                    if (_e1586 < _e1587) {
                    } else {
                        break;
                    }
                    let _e1589 = local_48;
                    let _e1592 = local_153;
                    global_8.member[_e1589] = _e1592;
                    let _e1593 = local_162[2u];
                    local_154 = bitcast<u32>(_e1593);
                    let _e1595 = local_50;
                    let _e1596 = local_6;
                    if (_e1595 < _e1596) {
                    } else {
                        break;
                    }
                    let _e1598 = local_50;
                    let _e1601 = local_154;
                    global_8.member[_e1598] = _e1601;
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
fn ring_gather_composite(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
