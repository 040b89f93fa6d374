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
                    local_23 = select(select(u32(_e283), 0u, (_e283 < 0f)), 4294967295u, (_e283 > 4294967000f));
                    local_24 = select(select(u32(_e284), 0u, (_e284 < 0f)), 4294967295u, (_e284 > 4294967000f));
                    local_160 = array<f32, 3>(0f, 0f, 0f);
                    local_161 = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_1631_ = false;
                    phi_208_ = 0u;
                    phi_211_ = 0f;
                    loop {
                        let _e298 = phi_1631_;
                        let _e300 = phi_208_;
                        let _e302 = phi_211_;
                        local_25 = _e300;
                        local_26 = _e302;
                        let _e303 = local_25;
                        let _e304 = (_e303 < 4u);
                        local_27 = _e304;
                        if _e304 {
                            let _e305 = local_25;
                            let _e306 = (_e305 % 2u);
                            local_28 = _e306;
                            let _e307 = local_23;
                            let _e308 = (_e307 + _e306);
                            let _e309 = local_12;
                            if (_e308 < _e309) {
                                phi_228_ = _e308;
                            } else {
                                let _e311 = local_12;
                                phi_228_ = (_e311 - 1u);
                            }
                            let _e314 = phi_228_;
                            local_29 = _e314;
                            let _e315 = local_25;
                            let _e316 = (_e315 / 2u);
                            local_30 = _e316;
                            let _e317 = local_24;
                            let _e318 = (_e317 + _e316);
                            let _e319 = local_16;
                            if (_e318 < _e319) {
                                phi_238_ = _e318;
                            } else {
                                let _e321 = local_16;
                                phi_238_ = (_e321 - 1u);
                            }
                            let _e324 = phi_238_;
                            local_31 = _e324;
                            let _e325 = local_28;
                            if (_e325 == 0u) {
                                let _e327 = local_21;
                                phi_245_ = (1f - _e327);
                            } else {
                                phi_245_ = _e285;
                            }
                            let _e330 = phi_245_;
                            local_32 = _e330;
                            let _e331 = local_30;
                            if (_e331 == 0u) {
                                let _e333 = local_22;
                                phi_252_ = (1f - _e333);
                            } else {
                                phi_252_ = _e286;
                            }
                            let _e336 = phi_252_;
                            let _e337 = local_32;
                            local_33 = (_e337 * _e336);
                            let _e339 = local_31;
                            let _e340 = local_12;
                            let _e342 = local_29;
                            let _e344 = (8u * ((_e339 * _e340) + _e342));
                            local_34 = _e344;
                            let _e345 = (_e344 + 3u);
                            local_35 = _e345;
                            let _e346 = local_3;
                            if (_e345 < _e346) {
                            } else {
                                phi_1639_ = true;
                                break;
                            }
                            let _e348 = local_35;
                            let _e351 = global_5.member[_e348];
                            let _e353 = local_33;
                            local_36 = (_e353 * bitcast<f32>(_e351));
                            phi_268_ = 0u;
                            loop {
                                let _e356 = phi_268_;
                                local_37 = _e356;
                                let _e357 = local_37;
                                let _e358 = (_e357 < 3u);
                                local_38 = _e358;
                                if _e358 {
                                    let _e359 = local_34;
                                    let _e360 = local_37;
                                    let _e361 = (_e359 + _e360);
                                    local_39 = _e361;
                                    let _e362 = local_3;
                                    if (_e361 < _e362) {
                                    } else {
                                        phi_1624_ = true;
                                        break;
                                    }
                                    let _e364 = local_39;
                                    let _e367 = global_5.member[_e364];
                                    let _e369 = local_36;
                                    local_40 = (_e369 * bitcast<f32>(_e367));
                                    let _e371 = local_38;
                                    if _e371 {
                                    } else {
                                        phi_1624_ = true;
                                        break;
                                    }
                                    let _e372 = local_37;
                                    let _e374 = local_160[_e372];
                                    let _e375 = local_40;
                                    local_160[_e372] = (_e374 + _e375);
                                    let _e377 = local_37;
                                    phi_269_ = (_e377 + 1u);
                                } else {
                                    phi_269_ = u32();
                                }
                                let _e380 = phi_269_;
                                continue;
                                continuing {
                                    let _e381 = local_38;
                                    phi_268_ = _e380;
                                    phi_1624_ = _e298;
                                    break if !(_e381);
                                }
                            }
                            let _e384 = phi_1624_;
                            phi_1639_ = _e384;
                            if _e384 {
                                break;
                            }
                            let _e385 = local_26;
                            let _e386 = local_36;
                            phi_300_ = 0u;
                            loop {
                                let _e389 = phi_300_;
                                local_41 = _e389;
                                let _e390 = local_41;
                                let _e391 = (_e390 < 4u);
                                local_42 = _e391;
                                if _e391 {
                                    let _e392 = local_34;
                                    let _e394 = local_41;
                                    let _e395 = ((_e392 + 4u) + _e394);
                                    local_43 = _e395;
                                    let _e396 = local_3;
                                    if (_e395 < _e396) {
                                    } else {
                                        phi_1636_ = true;
                                        break;
                                    }
                                    let _e398 = local_43;
                                    let _e401 = global_5.member[_e398];
                                    let _e403 = local_33;
                                    local_44 = (_e403 * bitcast<f32>(_e401));
                                    let _e405 = local_42;
                                    if _e405 {
                                    } else {
                                        phi_1636_ = true;
                                        break;
                                    }
                                    let _e406 = local_41;
                                    let _e408 = local_161[_e406];
                                    let _e409 = local_44;
                                    local_161[_e406] = (_e408 + _e409);
                                    let _e411 = local_41;
                                    phi_301_ = (_e411 + 1u);
                                } else {
                                    phi_301_ = u32();
                                }
                                let _e414 = phi_301_;
                                continue;
                                continuing {
                                    let _e415 = local_42;
                                    phi_300_ = _e414;
                                    phi_1636_ = _e384;
                                    break if !(_e415);
                                }
                            }
                            let _e418 = phi_1636_;
                            phi_1639_ = _e418;
                            if _e418 {
                                break;
                            }
                            let _e419 = local_25;
                            phi_1640_ = _e418;
                            phi_209_ = (_e419 + 1u);
                            phi_212_ = (_e385 + _e386);
                        } else {
                            phi_1640_ = _e298;
                            phi_209_ = u32();
                            phi_212_ = f32();
                        }
                        let _e422 = phi_1640_;
                        let _e424 = phi_209_;
                        let _e426 = phi_212_;
                        continue;
                        continuing {
                            let _e427 = local_27;
                            phi_1631_ = _e422;
                            phi_208_ = _e424;
                            phi_211_ = _e426;
                            phi_1639_ = _e422;
                            break if !(_e427);
                        }
                    }
                    let _e430 = phi_1639_;
                    if _e430 {
                        break;
                    }
                    let _e431 = local_18;
                    let _e432 = local_9;
                    let _e434 = local_17;
                    let _e435 = ((_e431 * _e432) + _e434);
                    local_45 = _e435;
                    local_162 = array<f32, 3>(0f, 0f, 0f);
                    let _e436 = (3u * _e435);
                    local_46 = _e436;
                    let _e437 = local_1;
                    if (_e436 < _e437) {
                    } else {
                        break;
                    }
                    let _e439 = local_46;
                    let _e442 = global_3.member[_e439];
                    local_47 = bitcast<f32>(_e442);
                    let _e444 = local_46;
                    let _e445 = (_e444 + 1u);
                    local_48 = _e445;
                    let _e446 = local_1;
                    if (_e445 < _e446) {
                    } else {
                        break;
                    }
                    let _e448 = local_48;
                    let _e451 = global_3.member[_e448];
                    local_49 = bitcast<f32>(_e451);
                    let _e453 = local_46;
                    let _e454 = (_e453 + 2u);
                    local_50 = _e454;
                    let _e455 = local_1;
                    if (_e454 < _e455) {
                    } else {
                        break;
                    }
                    let _e457 = local_50;
                    let _e460 = global_3.member[_e457];
                    local_51 = bitcast<f32>(_e460);
                    let _e462 = local_47;
                    if (_e462 > 1267650600000000000000000000000f) {
                        let _e464 = local_47;
                        phi_374_ = select(true, false, (_e464 <= 340282350000000000000000000000000000000f));
                    } else {
                        phi_374_ = true;
                    }
                    let _e468 = phi_374_;
                    if _e468 {
                        let _e469 = local_47;
                        if (_e469 < 0.000000000000000000000000000000000000011754944f) {
                            let _e471 = local_47;
                            phi_388_ = select(true, false, (_e471 >= -340282350000000000000000000000000000000f));
                        } else {
                            phi_388_ = true;
                        }
                        let _e475 = phi_388_;
                        let _e476 = local_47;
                        phi_393_ = select(0f, _e476, _e475);
                    } else {
                        phi_393_ = 1267650600000000000000000000000f;
                    }
                    let _e479 = phi_393_;
                    local_52 = _e479;
                    let _e480 = local_49;
                    if (_e480 > 1267650600000000000000000000000f) {
                        let _e482 = local_49;
                        phi_403_ = select(true, false, (_e482 <= 340282350000000000000000000000000000000f));
                    } else {
                        phi_403_ = true;
                    }
                    let _e486 = phi_403_;
                    if _e486 {
                        let _e487 = local_49;
                        if (_e487 < 0.000000000000000000000000000000000000011754944f) {
                            let _e489 = local_49;
                            phi_417_ = select(true, false, (_e489 >= -340282350000000000000000000000000000000f));
                        } else {
                            phi_417_ = true;
                        }
                        let _e493 = phi_417_;
                        let _e494 = local_49;
                        phi_422_ = select(0f, _e494, _e493);
                    } else {
                        phi_422_ = 1267650600000000000000000000000f;
                    }
                    let _e497 = phi_422_;
                    local_53 = _e497;
                    let _e498 = local_51;
                    if (_e498 > 1267650600000000000000000000000f) {
                        let _e500 = local_51;
                        phi_432_ = select(true, false, (_e500 <= 340282350000000000000000000000000000000f));
                    } else {
                        phi_432_ = true;
                    }
                    let _e504 = phi_432_;
                    if _e504 {
                        let _e505 = local_51;
                        if (_e505 < 0.000000000000000000000000000000000000011754944f) {
                            let _e507 = local_51;
                            phi_446_ = select(true, false, (_e507 >= -340282350000000000000000000000000000000f));
                        } else {
                            phi_446_ = true;
                        }
                        let _e511 = phi_446_;
                        let _e512 = local_51;
                        phi_451_ = select(0f, _e512, _e511);
                    } else {
                        phi_451_ = 1267650600000000000000000000000f;
                    }
                    let _e515 = phi_451_;
                    local_54 = _e515;
                    let _e516 = local_52;
                    let _e517 = local_53;
                    local_55 = array<f32, 3>(_e516, _e517, _e515);
                    let _e519 = local_45;
                    let _e520 = local_2;
                    if (_e519 < _e520) {
                    } else {
                        break;
                    }
                    let _e522 = local_45;
                    let _e525 = global_4.member[_e522];
                    local_56 = bitcast<f32>(_e525);
                    let _e527 = local_52;
                    if ((bitcast<u32>(_e527) & 2139095040u) != 2139095040u) {
                        let _e531 = local_53;
                        if ((bitcast<u32>(_e531) & 2139095040u) != 2139095040u) {
                            let _e535 = local_54;
                            if ((bitcast<u32>(_e535) & 2139095040u) != 2139095040u) {
                                let _e539 = local_56;
                                let _e540 = bitcast<u32>(_e539);
                                local_57 = _e540;
                                if (_e540 == 0u) {
                                    phi_485_ = false;
                                } else {
                                    let _e542 = local_57;
                                    phi_485_ = (_e542 <= 2139095040u);
                                }
                                let _e545 = phi_485_;
                                local_58 = _e545;
                                if _e545 {
                                    let _e546 = local_55;
                                    let _e547 = local_56;
                                    phi_491_ = type_22(1u, type_21(_e546, _e547));
                                } else {
                                    phi_491_ = type_22();
                                }
                                let _e551 = phi_491_;
                                let _e552 = local_58;
                                phi_493_ = _e551;
                                phi_494_ = select(true, false, _e552);
                            } else {
                                phi_493_ = type_22();
                                phi_494_ = true;
                            }
                            let _e555 = phi_493_;
                            let _e557 = phi_494_;
                            phi_495_ = _e555;
                            phi_496_ = _e557;
                        } else {
                            phi_495_ = type_22();
                            phi_496_ = true;
                        }
                        let _e559 = phi_495_;
                        let _e561 = phi_496_;
                        phi_497_ = _e559;
                        phi_498_ = _e561;
                    } else {
                        phi_497_ = type_22();
                        phi_498_ = true;
                    }
                    let _e563 = phi_497_;
                    let _e565 = phi_498_;
                    if _e565 {
                        phi_503_ = type_22(0u, type_22().member_1);
                    } else {
                        phi_503_ = _e563;
                    }
                    let _e570 = phi_503_;
                    local_59 = _e570;
                    if (bitcast<i32>(_e570.member) != 0i) {
                        let _e590 = local_59;
                        local_60 = _e590.member_1.member;
                        let _e593 = local_59;
                        local_61 = _e593.member_1.member_1;
                        let _e598 = global_2.member.member_3;
                        local_62 = f32(_e598);
                        let _e600 = bitcast<u32>(_e593.member_1.member_1);
                        local_63 = _e600;
                        if (_e600 == 2139095040u) {
                            let _e644 = global_2.member.member_4.member_1;
                            let _e649 = global_2.member.member_4.member;
                            let _e654 = global_2.member.member_4.member_2;
                            let _e660 = global_2.member.member_4.member_3;
                            phi_574_ = (0.5f * ((((2f * _e644) * _e649) / (_e654 - _e649)) * _e660));
                        } else {
                            let _e602 = local_63;
                            if (_e602 == 0u) {
                                phi_543_ = false;
                            } else {
                                let _e604 = local_63;
                                phi_543_ = (_e604 <= 2139095040u);
                            }
                            let _e607 = phi_543_;
                            if _e607 {
                                let _e611 = global_2.member.member_4.member_1;
                                let _e616 = global_2.member.member_4.member;
                                let _e621 = global_2.member.member_4.member_2;
                                local_64 = _e621;
                                let _e627 = global_2.member.member_4.member_3;
                                let _e628 = ((((2f * _e611) * _e616) / (_e621 - _e616)) * _e627);
                                local_65 = _e628;
                                if (_e628 == 0f) {
                                    phi_571_ = 0f;
                                } else {
                                    let _e630 = local_64;
                                    let _e631 = local_61;
                                    let _e634 = local_65;
                                    phi_571_ = (_e634 * (1f - (_e630 / _e631)));
                                }
                                let _e637 = phi_571_;
                                phi_572_ = _e637;
                            } else {
                                phi_572_ = _e216;
                            }
                            let _e639 = phi_572_;
                            phi_574_ = (0.5f * _e639);
                        }
                        let _e664 = phi_574_;
                        let _e665 = local_62;
                        let _e667 = local_62;
                        let _e668 = select(_e667, _e664, (_e664 < _e665));
                        let _e669 = local_62;
                        let _e670 = -(_e669);
                        local_66 = _e670;
                        let _e672 = select(_e670, _e668, (_e668 > _e670));
                        local_155 = _e672;
                        let _e673 = (_e672 < 0f);
                        local_67 = _e673;
                        if _e673 {
                            let _e674 = local_155;
                            phi_591_ = -(_e674);
                        } else {
                            phi_591_ = _e672;
                        }
                        let _e677 = phi_591_;
                        let _e678 = (_e677 - 1f);
                        let _e680 = select(0f, _e678, (_e678 > 0f));
                        let _e682 = select(1f, _e680, (_e680 < 1f));
                        local_156 = _e682;
                        if (_e682 < 1f) {
                            let _e691 = local_155;
                            let _e693 = local_155;
                            local_157 = select(0f, _e693, (_e691 > 0f));
                            let _e695 = local_67;
                            if _e695 {
                                let _e696 = local_155;
                                phi_617_ = -(_e696);
                            } else {
                                phi_617_ = _e672;
                            }
                            let _e699 = phi_617_;
                            let _e701 = select(1.5f, _e699, (_e699 < 1.5f));
                            let _e702 = (_e701 + 0.5f);
                            let _e704 = select(0f, _e702, (_e702 > 0f));
                            let _e707 = (_e701 * _e701);
                            phi_642_ = 0u;
                            phi_645_ = (select(1f, _e704, (_e704 < 1f)) / select(0.25f, _e707, (_e707 > 0.25f)));
                            phi_647_ = array<f32, 3>(0f, 0f, 0f);
                            loop {
                                let _e712 = phi_642_;
                                let _e714 = phi_645_;
                                let _e716 = phi_647_;
                                local_68 = _e712;
                                local_69 = _e714;
                                local_70 = _e716;
                                let _e717 = local_68;
                                let _e718 = (_e717 < 9u);
                                local_71 = _e718;
                                if _e718 {
                                    let _e719 = local_68;
                                    let _e722 = (bitcast<i32>((_e719 % 3u)) - 1i);
                                    local_72 = _e722;
                                    let _e723 = local_68;
                                    let _e726 = (bitcast<i32>((_e723 / 3u)) - 1i);
                                    local_73 = _e726;
                                    let _e727 = local_17;
                                    local_74 = (bitcast<i32>(_e727) + _e722);
                                    let _e730 = local_18;
                                    local_75 = (bitcast<i32>(_e730) + _e726);
                                    let _e733 = local_68;
                                    if (_e733 == 4u) {
                                        phi_1050_ = _e714;
                                        phi_1051_ = _e716;
                                    } else {
                                        let _e735 = local_74;
                                        if (_e735 >= 0i) {
                                            let _e737 = local_75;
                                            if (_e737 >= 0i) {
                                                let _e739 = local_74;
                                                let _e740 = bitcast<u32>(_e739);
                                                local_76 = _e740;
                                                let _e741 = local_9;
                                                if (_e740 < _e741) {
                                                    let _e743 = local_75;
                                                    let _e744 = bitcast<u32>(_e743);
                                                    local_77 = _e744;
                                                    let _e745 = local_13;
                                                    if (_e744 < _e745) {
                                                        let _e747 = local_77;
                                                        let _e748 = local_9;
                                                        let _e750 = local_76;
                                                        let _e751 = ((_e747 * _e748) + _e750);
                                                        local_78 = _e751;
                                                        let _e752 = (3u * _e751);
                                                        local_79 = _e752;
                                                        let _e753 = local_1;
                                                        if (_e752 < _e753) {
                                                        } else {
                                                            phi_1641_ = true;
                                                            break;
                                                        }
                                                        let _e755 = local_79;
                                                        let _e758 = global_3.member[_e755];
                                                        local_80 = bitcast<f32>(_e758);
                                                        let _e760 = local_79;
                                                        let _e761 = (_e760 + 1u);
                                                        local_81 = _e761;
                                                        let _e762 = local_1;
                                                        if (_e761 < _e762) {
                                                        } else {
                                                            phi_1641_ = true;
                                                            break;
                                                        }
                                                        let _e764 = local_81;
                                                        let _e767 = global_3.member[_e764];
                                                        local_82 = bitcast<f32>(_e767);
                                                        let _e769 = local_79;
                                                        let _e770 = (_e769 + 2u);
                                                        local_83 = _e770;
                                                        let _e771 = local_1;
                                                        if (_e770 < _e771) {
                                                        } else {
                                                            phi_1641_ = true;
                                                            break;
                                                        }
                                                        let _e773 = local_83;
                                                        let _e776 = global_3.member[_e773];
                                                        local_84 = bitcast<f32>(_e776);
                                                        let _e778 = local_80;
                                                        if (_e778 > 1267650600000000000000000000000f) {
                                                            let _e780 = local_80;
                                                            phi_735_ = select(true, false, (_e780 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_735_ = true;
                                                        }
                                                        let _e784 = phi_735_;
                                                        if _e784 {
                                                            let _e785 = local_80;
                                                            if (_e785 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e787 = local_80;
                                                                phi_749_ = select(true, false, (_e787 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_749_ = true;
                                                            }
                                                            let _e791 = phi_749_;
                                                            let _e792 = local_80;
                                                            phi_754_ = select(0f, _e792, _e791);
                                                        } else {
                                                            phi_754_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e795 = phi_754_;
                                                        local_85 = _e795;
                                                        let _e796 = local_82;
                                                        if (_e796 > 1267650600000000000000000000000f) {
                                                            let _e798 = local_82;
                                                            phi_764_ = select(true, false, (_e798 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_764_ = true;
                                                        }
                                                        let _e802 = phi_764_;
                                                        if _e802 {
                                                            let _e803 = local_82;
                                                            if (_e803 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e805 = local_82;
                                                                phi_778_ = select(true, false, (_e805 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_778_ = true;
                                                            }
                                                            let _e809 = phi_778_;
                                                            let _e810 = local_82;
                                                            phi_783_ = select(0f, _e810, _e809);
                                                        } else {
                                                            phi_783_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e813 = phi_783_;
                                                        local_86 = _e813;
                                                        let _e814 = local_84;
                                                        if (_e814 > 1267650600000000000000000000000f) {
                                                            let _e816 = local_84;
                                                            phi_793_ = select(true, false, (_e816 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_793_ = true;
                                                        }
                                                        let _e820 = phi_793_;
                                                        if _e820 {
                                                            let _e821 = local_84;
                                                            if (_e821 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e823 = local_84;
                                                                phi_807_ = select(true, false, (_e823 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_807_ = true;
                                                            }
                                                            let _e827 = phi_807_;
                                                            let _e828 = local_84;
                                                            phi_812_ = select(0f, _e828, _e827);
                                                        } else {
                                                            phi_812_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e831 = phi_812_;
                                                        local_87 = _e831;
                                                        let _e832 = local_85;
                                                        let _e833 = local_86;
                                                        local_88 = array<f32, 3>(_e832, _e833, _e831);
                                                        let _e835 = local_78;
                                                        let _e836 = local_2;
                                                        if (_e835 < _e836) {
                                                        } else {
                                                            phi_1641_ = true;
                                                            break;
                                                        }
                                                        let _e838 = local_78;
                                                        let _e841 = global_4.member[_e838];
                                                        local_89 = bitcast<f32>(_e841);
                                                        let _e843 = local_85;
                                                        if ((bitcast<u32>(_e843) & 2139095040u) != 2139095040u) {
                                                            let _e847 = local_86;
                                                            if ((bitcast<u32>(_e847) & 2139095040u) != 2139095040u) {
                                                                let _e851 = local_87;
                                                                if ((bitcast<u32>(_e851) & 2139095040u) != 2139095040u) {
                                                                    let _e855 = local_89;
                                                                    let _e856 = bitcast<u32>(_e855);
                                                                    local_90 = _e856;
                                                                    if (_e856 == 0u) {
                                                                        phi_846_ = false;
                                                                    } else {
                                                                        let _e858 = local_90;
                                                                        phi_846_ = (_e858 <= 2139095040u);
                                                                    }
                                                                    let _e861 = phi_846_;
                                                                    local_91 = _e861;
                                                                    if _e861 {
                                                                        let _e862 = local_88;
                                                                        let _e863 = local_89;
                                                                        phi_852_ = type_22(1u, type_21(_e862, _e863));
                                                                    } else {
                                                                        phi_852_ = type_22();
                                                                    }
                                                                    let _e867 = phi_852_;
                                                                    let _e868 = local_91;
                                                                    phi_854_ = _e867;
                                                                    phi_855_ = select(true, false, _e868);
                                                                } else {
                                                                    phi_854_ = type_22();
                                                                    phi_855_ = true;
                                                                }
                                                                let _e871 = phi_854_;
                                                                let _e873 = phi_855_;
                                                                phi_856_ = _e871;
                                                                phi_857_ = _e873;
                                                            } else {
                                                                phi_856_ = type_22();
                                                                phi_857_ = true;
                                                            }
                                                            let _e875 = phi_856_;
                                                            let _e877 = phi_857_;
                                                            phi_858_ = _e875;
                                                            phi_859_ = _e877;
                                                        } else {
                                                            phi_858_ = type_22();
                                                            phi_859_ = true;
                                                        }
                                                        let _e879 = phi_858_;
                                                        let _e881 = phi_859_;
                                                        if _e881 {
                                                            phi_864_ = type_22(0u, type_22().member_1);
                                                        } else {
                                                            phi_864_ = _e879;
                                                        }
                                                        let _e886 = phi_864_;
                                                        local_92 = _e886;
                                                        if (bitcast<i32>(_e886.member) != 0i) {
                                                            let _e890 = local_92;
                                                            local_93 = _e890.member_1.member;
                                                            let _e893 = local_92;
                                                            local_94 = _e893.member_1.member_1;
                                                            let _e896 = bitcast<u32>(_e893.member_1.member_1);
                                                            local_95 = _e896;
                                                            if (_e896 == 2139095040u) {
                                                                let _e940 = global_2.member.member_4.member_1;
                                                                let _e945 = global_2.member.member_4.member;
                                                                let _e950 = global_2.member.member_4.member_2;
                                                                let _e956 = global_2.member.member_4.member_3;
                                                                phi_935_ = (0.5f * ((((2f * _e940) * _e945) / (_e950 - _e945)) * _e956));
                                                            } else {
                                                                let _e898 = local_95;
                                                                if (_e898 == 0u) {
                                                                    phi_904_ = false;
                                                                } else {
                                                                    let _e900 = local_95;
                                                                    phi_904_ = (_e900 <= 2139095040u);
                                                                }
                                                                let _e903 = phi_904_;
                                                                if _e903 {
                                                                    let _e907 = global_2.member.member_4.member_1;
                                                                    let _e912 = global_2.member.member_4.member;
                                                                    let _e917 = global_2.member.member_4.member_2;
                                                                    local_96 = _e917;
                                                                    let _e923 = global_2.member.member_4.member_3;
                                                                    let _e924 = ((((2f * _e907) * _e912) / (_e917 - _e912)) * _e923);
                                                                    local_97 = _e924;
                                                                    if (_e924 == 0f) {
                                                                        phi_932_ = 0f;
                                                                    } else {
                                                                        let _e926 = local_96;
                                                                        let _e927 = local_94;
                                                                        let _e930 = local_97;
                                                                        phi_932_ = (_e930 * (1f - (_e926 / _e927)));
                                                                    }
                                                                    let _e933 = phi_932_;
                                                                    phi_933_ = _e933;
                                                                } else {
                                                                    phi_933_ = _e216;
                                                                }
                                                                let _e935 = phi_933_;
                                                                phi_935_ = (0.5f * _e935);
                                                            }
                                                            let _e960 = phi_935_;
                                                            let _e961 = local_62;
                                                            let _e963 = local_62;
                                                            let _e964 = select(_e963, _e960, (_e960 < _e961));
                                                            let _e965 = local_66;
                                                            let _e967 = local_66;
                                                            let _e968 = select(_e967, _e964, (_e964 > _e965));
                                                            local_158 = _e968;
                                                            let _e969 = local_155;
                                                            if (_e968 > _e969) {
                                                                let _e977 = local_158;
                                                                if (_e977 < 0f) {
                                                                    let _e979 = local_158;
                                                                    phi_956_ = -(_e979);
                                                                } else {
                                                                    phi_956_ = _e968;
                                                                }
                                                                let _e982 = phi_956_;
                                                                let _e983 = local_157;
                                                                let _e985 = local_157;
                                                                phi_968_ = select(_e985, _e982, (_e982 < _e983));
                                                            } else {
                                                                let _e971 = local_158;
                                                                if (_e971 < 0f) {
                                                                    let _e973 = local_158;
                                                                    phi_967_ = -(_e973);
                                                                } else {
                                                                    phi_967_ = _e968;
                                                                }
                                                                let _e976 = phi_967_;
                                                                phi_968_ = _e976;
                                                            }
                                                            let _e988 = phi_968_;
                                                            let _e990 = select(1.5f, _e988, (_e988 < 1.5f));
                                                            let _e991 = local_72;
                                                            let _e992 = local_72;
                                                            let _e994 = local_73;
                                                            let _e995 = local_73;
                                                            let _e1001 = ((_e990 - sqrt(f32(((_e991 * _e992) + (_e994 * _e995))))) + 0.5f);
                                                            let _e1003 = select(0f, _e1001, (_e1001 > 0f));
                                                            let _e1005 = select(1f, _e1003, (_e1003 < 1f));
                                                            let _e1006 = local_158;
                                                            let _e1008 = ((-1f - _e1006) * 0.5f);
                                                            let _e1010 = select(0f, _e1008, (_e1008 > 0f));
                                                            let _e1016 = (_e990 * _e990);
                                                            let _e1019 = ((((1f - select(1f, _e1010, (_e1010 < 1f))) * _e1005) * _e1005) / select(0.25f, _e1016, (_e1016 > 0.25f)));
                                                            local_98 = _e1019;
                                                            if (_e1019 > 0f) {
                                                                let _e1021 = local_70;
                                                                let _e1023 = local_93;
                                                                let _e1025 = local_60;
                                                                let _e1028 = local_98;
                                                                let _e1031 = local_70;
                                                                let _e1033 = local_93;
                                                                let _e1035 = local_60;
                                                                let _e1038 = local_98;
                                                                let _e1041 = local_70;
                                                                let _e1043 = local_93;
                                                                let _e1045 = local_60;
                                                                let _e1048 = local_98;
                                                                let _e1052 = local_69;
                                                                let _e1053 = local_98;
                                                                phi_1038_ = (_e1052 + _e1053);
                                                                phi_1039_ = array<f32, 3>((_e1021[0] + (_e1028 * (_e1023[0] - _e1025[0]))), (_e1031[1] + (_e1038 * (_e1033[1] - _e1035[1]))), (_e1041[2] + (_e1048 * (_e1043[2] - _e1045[2]))));
                                                            } else {
                                                                phi_1038_ = _e714;
                                                                phi_1039_ = _e716;
                                                            }
                                                            let _e1056 = phi_1038_;
                                                            let _e1058 = phi_1039_;
                                                            phi_1040_ = _e1056;
                                                            phi_1041_ = _e1058;
                                                        } else {
                                                            phi_1040_ = _e714;
                                                            phi_1041_ = _e716;
                                                        }
                                                        let _e1060 = phi_1040_;
                                                        let _e1062 = phi_1041_;
                                                        phi_1042_ = _e1060;
                                                        phi_1043_ = _e1062;
                                                    } else {
                                                        phi_1042_ = _e714;
                                                        phi_1043_ = _e716;
                                                    }
                                                    let _e1064 = phi_1042_;
                                                    let _e1066 = phi_1043_;
                                                    phi_1044_ = _e1064;
                                                    phi_1045_ = _e1066;
                                                } else {
                                                    phi_1044_ = _e714;
                                                    phi_1045_ = _e716;
                                                }
                                                let _e1068 = phi_1044_;
                                                let _e1070 = phi_1045_;
                                                phi_1046_ = _e1068;
                                                phi_1047_ = _e1070;
                                            } else {
                                                phi_1046_ = _e714;
                                                phi_1047_ = _e716;
                                            }
                                            let _e1072 = phi_1046_;
                                            let _e1074 = phi_1047_;
                                            phi_1048_ = _e1072;
                                            phi_1049_ = _e1074;
                                        } else {
                                            phi_1048_ = _e714;
                                            phi_1049_ = _e716;
                                        }
                                        let _e1076 = phi_1048_;
                                        let _e1078 = phi_1049_;
                                        phi_1050_ = _e1076;
                                        phi_1051_ = _e1078;
                                    }
                                    let _e1080 = phi_1050_;
                                    let _e1082 = phi_1051_;
                                    let _e1083 = local_68;
                                    phi_643_ = (_e1083 + 1u);
                                    phi_646_ = _e1080;
                                    phi_648_ = _e1082;
                                } else {
                                    phi_643_ = u32();
                                    phi_646_ = f32();
                                    phi_648_ = array<f32, 3>();
                                }
                                let _e1086 = phi_643_;
                                let _e1088 = phi_646_;
                                let _e1090 = phi_648_;
                                continue;
                                continuing {
                                    let _e1091 = local_71;
                                    phi_642_ = _e1086;
                                    phi_645_ = _e1088;
                                    phi_647_ = _e1090;
                                    phi_1641_ = _e430;
                                    break if !(_e1091);
                                }
                            }
                            let _e1094 = phi_1641_;
                            if _e1094 {
                                break;
                            }
                            let _e1095 = local_69;
                            let _e1096 = (1f / _e1095);
                            let _e1097 = local_60;
                            let _e1099 = local_70;
                            let _e1103 = local_60;
                            let _e1105 = local_70;
                            let _e1109 = local_60;
                            let _e1111 = local_70;
                            local_162 = array<f32, 3>((_e1097[0] + (_e1099[0] * _e1096)), (_e1103[1] + (_e1105[1] * _e1096)), (_e1109[2] + (_e1111[2] * _e1096)));
                            phi_1733_ = _e1094;
                        } else {
                            let _e684 = local_60;
                            let _e686 = local_60;
                            let _e688 = local_60;
                            local_162 = array<f32, 3>(_e684[0], _e686[1], _e688[2]);
                            phi_1733_ = _e430;
                        }
                        let _e1117 = phi_1733_;
                        let _e1118 = local_156;
                        if (_e1118 > 0f) {
                            let _e1120 = local_26;
                            if (_e1120 > 0f) {
                                let _e1122 = local_26;
                                local_99 = (1f / _e1122);
                                phi_1085_ = 0u;
                                loop {
                                    let _e1125 = phi_1085_;
                                    local_100 = _e1125;
                                    let _e1126 = local_100;
                                    let _e1127 = (_e1126 < 3u);
                                    local_101 = _e1127;
                                    if _e1127 {
                                        let _e1128 = local_101;
                                        if _e1128 {
                                        } else {
                                            phi_1730_ = true;
                                            break;
                                        }
                                        let _e1129 = local_100;
                                        let _e1131 = local_160[_e1129];
                                        let _e1132 = local_99;
                                        local_102 = (_e1131 * _e1132);
                                        let _e1134 = local_101;
                                        if _e1134 {
                                        } else {
                                            phi_1730_ = true;
                                            break;
                                        }
                                        let _e1135 = local_100;
                                        let _e1137 = local_162[_e1135];
                                        let _e1138 = local_102;
                                        let _e1140 = local_156;
                                        local_103 = (_e1140 * (_e1138 - _e1137));
                                        let _e1142 = local_101;
                                        if _e1142 {
                                        } else {
                                            phi_1730_ = true;
                                            break;
                                        }
                                        let _e1143 = local_162[_e1135];
                                        let _e1144 = local_103;
                                        local_162[_e1135] = (_e1143 + _e1144);
                                        let _e1146 = local_100;
                                        phi_1086_ = (_e1146 + 1u);
                                    } else {
                                        phi_1086_ = u32();
                                    }
                                    let _e1149 = phi_1086_;
                                    continue;
                                    continuing {
                                        let _e1150 = local_101;
                                        phi_1085_ = _e1149;
                                        phi_1730_ = _e1117;
                                        break if !(_e1150);
                                    }
                                }
                                let _e1153 = phi_1730_;
                                if _e1153 {
                                    break;
                                }
                                phi_1756_ = _e1153;
                            } else {
                                phi_1756_ = _e1117;
                            }
                            let _e1155 = phi_1756_;
                            phi_1755_ = _e1155;
                        } else {
                            phi_1755_ = _e1117;
                        }
                        let _e1157 = phi_1755_;
                        phi_1754_ = _e1157;
                        phi_1139_ = _e672;
                    } else {
                        let _e574 = local_26;
                        if (_e574 > 0f) {
                            let _e576 = local_26;
                            let _e577 = (1f / _e576);
                            let _e579 = local_160[0u];
                            let _e582 = local_160[1u];
                            let _e585 = local_160[2u];
                            local_162[0u] = (_e579 * _e577);
                            local_162[1u] = (_e582 * _e577);
                            local_162[2u] = (_e585 * _e577);
                        }
                        phi_1754_ = _e430;
                        phi_1139_ = _e216;
                    }
                    let _e1159 = phi_1754_;
                    let _e1161 = phi_1139_;
                    local_104 = _e1161;
                    let _e1162 = local_11;
                    if _e1162 {
                        let _e1163 = local_10;
                        phi_1157_ = (_e1163 + 1u);
                    } else {
                        phi_1157_ = _e237;
                    }
                    let _e1166 = phi_1157_;
                    let _e1167 = (_e1166 / 8u);
                    local_105 = _e1167;
                    if ((_e1166 % 8u) > 0u) {
                        let _e1170 = local_105;
                        phi_1173_ = (_e1170 + 1u);
                    } else {
                        phi_1173_ = _e1167;
                    }
                    let _e1173 = phi_1173_;
                    local_106 = _e1173;
                    let _e1174 = local_15;
                    if _e1174 {
                        let _e1175 = local_14;
                        phi_1191_ = (_e1175 + 1u);
                    } else {
                        phi_1191_ = _e247;
                    }
                    let _e1178 = phi_1191_;
                    let _e1179 = (_e1178 / 8u);
                    local_107 = _e1179;
                    if ((_e1178 % 8u) > 0u) {
                        let _e1182 = local_107;
                        phi_1207_ = (_e1182 + 1u);
                    } else {
                        phi_1207_ = _e1179;
                    }
                    let _e1185 = phi_1207_;
                    local_108 = _e1185;
                    let _e1186 = local_17;
                    let _e1187 = (_e1186 / 16u);
                    local_109 = _e1187;
                    let _e1188 = local_18;
                    let _e1189 = (_e1188 / 16u);
                    local_110 = _e1189;
                    let _e1190 = local_106;
                    let _e1194 = ((2u * ((_e1189 * _e1190) + _e1187)) + 1u);
                    local_111 = _e1194;
                    let _e1195 = local_5;
                    if (_e1194 < _e1195) {
                    } else {
                        break;
                    }
                    let _e1197 = local_111;
                    let _e1200 = global_7.member[_e1197];
                    local_112 = _e1200;
                    if (_e1200 == 0u) {
                        phi_1508_ = type_24(array<f32, 3>(0f, 0f, 0f), array<f32, 3>(0f, 0f, 0f));
                    } else {
                        let _e1202 = local_112;
                        local_113 = bitcast<i32>((_e1202 - 1u));
                        let _e1205 = local_104;
                        let _e1209 = !(((bitcast<u32>(_e1205) & 2147483647u) > 2139095040u));
                        local_114 = _e1209;
                        if _e1209 {
                            let _e1210 = local_104;
                            let _e1212 = local_104;
                            phi_1244_ = select(0f, _e1212, (_e1210 > 0f));
                        } else {
                            phi_1244_ = 0f;
                        }
                        let _e1215 = phi_1244_;
                        local_115 = _e1215;
                        let _e1216 = local_114;
                        if _e1216 {
                            let _e1217 = local_104;
                            let _e1219 = ((_e1217 * -0.5f) - 0.5f);
                            let _e1221 = select(0f, _e1219, (_e1219 > 0f));
                            phi_1262_ = select(1f, _e1221, (_e1221 < 1f));
                        } else {
                            phi_1262_ = 1f;
                        }
                        let _e1225 = phi_1262_;
                        local_116 = _e1225;
                        let _e1226 = local_113;
                        let _e1227 = -(_e1226);
                        phi_1744_ = _e1159;
                        phi_1265_ = _e1227;
                        phi_1268_ = array<f32, 3>(0f, 0f, 0f);
                        phi_1270_ = array<f32, 3>(0f, 0f, 0f);
                        loop {
                            let _e1229 = phi_1744_;
                            let _e1231 = phi_1265_;
                            let _e1233 = phi_1268_;
                            let _e1235 = phi_1270_;
                            local_117 = _e1231;
                            local_118 = _e1233;
                            local_119 = _e1235;
                            let _e1236 = local_117;
                            let _e1237 = local_113;
                            let _e1238 = (_e1236 <= _e1237);
                            local_120 = _e1238;
                            if _e1238 {
                                let _e1239 = local_110;
                                let _e1241 = local_117;
                                local_121 = (bitcast<i32>(_e1239) + _e1241);
                                phi_1743_ = _e1229;
                                phi_1282_ = _e1227;
                                phi_1285_ = _e1233;
                                phi_1287_ = _e1235;
                                loop {
                                    let _e1244 = phi_1743_;
                                    let _e1246 = phi_1282_;
                                    let _e1248 = phi_1285_;
                                    let _e1250 = phi_1287_;
                                    local_122 = _e1246;
                                    local_165 = _e1248;
                                    local_166 = _e1250;
                                    let _e1251 = local_121;
                                    if (_e1251 >= 0i) {
                                        let _e1253 = local_108;
                                        let _e1255 = local_121;
                                        if (_e1255 < bitcast<i32>(_e1253)) {
                                            let _e1257 = local_122;
                                            let _e1258 = local_113;
                                            let _e1259 = (_e1257 <= _e1258);
                                            if _e1259 {
                                                let _e1260 = local_109;
                                                let _e1262 = local_122;
                                                let _e1263 = (bitcast<i32>(_e1260) + _e1262);
                                                local_123 = _e1263;
                                                if (_e1263 >= 0i) {
                                                    let _e1265 = local_106;
                                                    let _e1267 = local_123;
                                                    if (_e1267 < bitcast<i32>(_e1265)) {
                                                        let _e1269 = local_121;
                                                        let _e1271 = local_106;
                                                        let _e1273 = local_123;
                                                        let _e1276 = (66u * ((bitcast<u32>(_e1269) * _e1271) + bitcast<u32>(_e1273)));
                                                        local_124 = _e1276;
                                                        let _e1277 = local_4;
                                                        if (_e1276 < _e1277) {
                                                        } else {
                                                            phi_1759_ = true;
                                                            break;
                                                        }
                                                        let _e1279 = local_124;
                                                        let _e1282 = global_6.member[_e1279];
                                                        local_125 = _e1282;
                                                        phi_1328_ = 0u;
                                                        phi_1331_ = _e1248;
                                                        phi_1333_ = _e1250;
                                                        loop {
                                                            let _e1284 = phi_1328_;
                                                            let _e1286 = phi_1331_;
                                                            let _e1288 = phi_1333_;
                                                            local_126 = _e1284;
                                                            local_127 = _e1286;
                                                            local_128 = _e1288;
                                                            local_163 = _e1286;
                                                            local_164 = _e1288;
                                                            let _e1289 = local_126;
                                                            let _e1290 = local_125;
                                                            let _e1291 = (_e1289 < _e1290);
                                                            local_129 = _e1291;
                                                            if _e1291 {
                                                                let _e1292 = local_124;
                                                                let _e1294 = local_126;
                                                                let _e1296 = ((_e1292 + 2u) + (8u * _e1294));
                                                                local_130 = _e1296;
                                                                let _e1297 = local_4;
                                                                if (_e1296 < _e1297) {
                                                                } else {
                                                                    phi_1734_ = true;
                                                                    break;
                                                                }
                                                                let _e1299 = local_130;
                                                                let _e1302 = global_6.member[_e1299];
                                                                local_131 = bitcast<f32>(_e1302);
                                                                let _e1304 = local_130;
                                                                let _e1305 = (_e1304 + 1u);
                                                                local_132 = _e1305;
                                                                let _e1306 = local_4;
                                                                if (_e1305 < _e1306) {
                                                                } else {
                                                                    phi_1734_ = true;
                                                                    break;
                                                                }
                                                                let _e1308 = local_132;
                                                                let _e1311 = global_6.member[_e1308];
                                                                local_133 = bitcast<f32>(_e1311);
                                                                let _e1313 = local_130;
                                                                let _e1314 = (_e1313 + 2u);
                                                                local_134 = _e1314;
                                                                let _e1315 = local_4;
                                                                if (_e1314 < _e1315) {
                                                                } else {
                                                                    phi_1734_ = true;
                                                                    break;
                                                                }
                                                                let _e1317 = local_134;
                                                                let _e1320 = global_6.member[_e1317];
                                                                let _e1321 = bitcast<f32>(_e1320);
                                                                local_135 = _e1321;
                                                                let _e1322 = local_19;
                                                                let _e1323 = local_131;
                                                                let _e1324 = (_e1322 - _e1323);
                                                                let _e1325 = local_20;
                                                                let _e1326 = local_133;
                                                                let _e1327 = (_e1325 - _e1326);
                                                                local_136 = sqrt(((_e1324 * _e1324) + (_e1327 * _e1327)));
                                                                let _e1332 = (_e1321 < 0f);
                                                                local_137 = _e1332;
                                                                if _e1332 {
                                                                    let _e1333 = local_135;
                                                                    phi_1381_ = -(_e1333);
                                                                } else {
                                                                    phi_1381_ = _e1321;
                                                                }
                                                                let _e1336 = phi_1381_;
                                                                local_138 = _e1336;
                                                                let _e1337 = local_137;
                                                                if _e1337 {
                                                                    phi_1394_ = _e1336;
                                                                } else {
                                                                    let _e1338 = local_138;
                                                                    let _e1339 = local_115;
                                                                    let _e1341 = local_138;
                                                                    let _e1342 = local_115;
                                                                    let _e1343 = select(_e1342, _e1341, (_e1338 < _e1339));
                                                                    let _e1344 = local_138;
                                                                    let _e1346 = local_116;
                                                                    phi_1394_ = (_e1343 + (_e1346 * (_e1344 - _e1343)));
                                                                }
                                                                let _e1350 = phi_1394_;
                                                                local_139 = _e1350;
                                                                let _e1351 = local_130;
                                                                let _e1352 = (_e1351 + 6u);
                                                                local_140 = _e1352;
                                                                let _e1353 = local_4;
                                                                if (_e1352 < _e1353) {
                                                                } else {
                                                                    phi_1734_ = true;
                                                                    break;
                                                                }
                                                                let _e1355 = local_140;
                                                                let _e1358 = global_6.member[_e1355];
                                                                let _e1359 = bitcast<f32>(_e1358);
                                                                local_141 = _e1359;
                                                                let _e1360 = local_139;
                                                                let _e1362 = ((_e1360 + 0.5f) + _e1359);
                                                                local_142 = _e1362;
                                                                let _e1363 = local_136;
                                                                if (_e1363 < _e1362) {
                                                                    let _e1365 = local_141;
                                                                    let _e1368 = local_142;
                                                                    let _e1369 = local_136;
                                                                    let _e1371 = ((_e1368 - _e1369) / (1f + (2f * _e1365)));
                                                                    local_159 = select(0f, select(1f, _e1371, (_e1371 < 1f)), (0f < _e1371));
                                                                    let _e1376 = local_130;
                                                                    let _e1377 = (_e1376 + 3u);
                                                                    local_143 = _e1377;
                                                                    let _e1378 = local_4;
                                                                    if (_e1377 < _e1378) {
                                                                    } else {
                                                                        phi_1734_ = true;
                                                                        break;
                                                                    }
                                                                    let _e1380 = local_143;
                                                                    let _e1383 = global_6.member[_e1380];
                                                                    local_144 = bitcast<f32>(_e1383);
                                                                    let _e1385 = local_130;
                                                                    let _e1386 = (_e1385 + 4u);
                                                                    local_145 = _e1386;
                                                                    let _e1387 = local_4;
                                                                    if (_e1386 < _e1387) {
                                                                    } else {
                                                                        phi_1734_ = true;
                                                                        break;
                                                                    }
                                                                    let _e1389 = local_145;
                                                                    let _e1392 = global_6.member[_e1389];
                                                                    local_146 = bitcast<f32>(_e1392);
                                                                    let _e1394 = local_130;
                                                                    let _e1395 = (_e1394 + 5u);
                                                                    local_147 = _e1395;
                                                                    let _e1396 = local_4;
                                                                    if (_e1395 < _e1396) {
                                                                    } else {
                                                                        phi_1734_ = true;
                                                                        break;
                                                                    }
                                                                    let _e1398 = local_147;
                                                                    let _e1401 = global_6.member[_e1398];
                                                                    local_148 = bitcast<f32>(_e1401);
                                                                    let _e1403 = local_137;
                                                                    if _e1403 {
                                                                        let _e1423 = local_127;
                                                                        let _e1425 = local_159;
                                                                        let _e1426 = local_144;
                                                                        let _e1429 = local_127;
                                                                        let _e1431 = local_159;
                                                                        let _e1432 = local_146;
                                                                        let _e1435 = local_127;
                                                                        let _e1437 = local_159;
                                                                        let _e1438 = local_148;
                                                                        phi_1477_ = array<f32, 3>((_e1423[0] + (_e1425 * _e1426)), (_e1429[1] + (_e1431 * _e1432)), (_e1435[2] + (_e1437 * _e1438)));
                                                                        phi_1478_ = _e1288;
                                                                    } else {
                                                                        let _e1404 = local_128;
                                                                        let _e1406 = local_159;
                                                                        let _e1407 = local_144;
                                                                        let _e1410 = local_128;
                                                                        let _e1412 = local_159;
                                                                        let _e1413 = local_146;
                                                                        let _e1416 = local_128;
                                                                        let _e1418 = local_159;
                                                                        let _e1419 = local_148;
                                                                        phi_1477_ = _e1286;
                                                                        phi_1478_ = array<f32, 3>((_e1404[0] + (_e1406 * _e1407)), (_e1410[1] + (_e1412 * _e1413)), (_e1416[2] + (_e1418 * _e1419)));
                                                                    }
                                                                    let _e1443 = phi_1477_;
                                                                    let _e1445 = phi_1478_;
                                                                    phi_1479_ = _e1443;
                                                                    phi_1480_ = _e1445;
                                                                } else {
                                                                    phi_1479_ = _e1286;
                                                                    phi_1480_ = _e1288;
                                                                }
                                                                let _e1447 = phi_1479_;
                                                                let _e1449 = phi_1480_;
                                                                let _e1450 = local_126;
                                                                phi_1329_ = (_e1450 + 1u);
                                                                phi_1332_ = _e1447;
                                                                phi_1334_ = _e1449;
                                                            } else {
                                                                phi_1329_ = u32();
                                                                phi_1332_ = array<f32, 3>();
                                                                phi_1334_ = array<f32, 3>();
                                                            }
                                                            let _e1453 = phi_1329_;
                                                            let _e1455 = phi_1332_;
                                                            let _e1457 = phi_1334_;
                                                            continue;
                                                            continuing {
                                                                let _e1458 = local_129;
                                                                phi_1328_ = _e1453;
                                                                phi_1331_ = _e1455;
                                                                phi_1333_ = _e1457;
                                                                phi_1734_ = _e1244;
                                                                break if !(_e1458);
                                                            }
                                                        }
                                                        let _e1461 = phi_1734_;
                                                        phi_1759_ = _e1461;
                                                        if _e1461 {
                                                            break;
                                                        }
                                                        phi_1764_ = _e1461;
                                                        let _e1727 = local_163;
                                                        phi_1482_ = _e1727;
                                                        let _e1730 = local_164;
                                                        phi_1483_ = _e1730;
                                                    } else {
                                                        phi_1764_ = _e1244;
                                                        phi_1482_ = _e1248;
                                                        phi_1483_ = _e1250;
                                                    }
                                                    let _e1463 = phi_1764_;
                                                    let _e1465 = phi_1482_;
                                                    let _e1467 = phi_1483_;
                                                    phi_1763_ = _e1463;
                                                    phi_1484_ = _e1465;
                                                    phi_1485_ = _e1467;
                                                } else {
                                                    phi_1763_ = _e1244;
                                                    phi_1484_ = _e1248;
                                                    phi_1485_ = _e1250;
                                                }
                                                let _e1469 = phi_1763_;
                                                let _e1471 = phi_1484_;
                                                let _e1473 = phi_1485_;
                                                let _e1474 = local_122;
                                                phi_1762_ = _e1469;
                                                phi_1487_ = (_e1474 + 1i);
                                                phi_1488_ = _e1471;
                                                phi_1489_ = _e1473;
                                            } else {
                                                phi_1762_ = _e1244;
                                                phi_1487_ = i32();
                                                phi_1488_ = array<f32, 3>();
                                                phi_1489_ = array<f32, 3>();
                                            }
                                            let _e1477 = phi_1762_;
                                            let _e1479 = phi_1487_;
                                            let _e1481 = phi_1488_;
                                            let _e1483 = phi_1489_;
                                            phi_1761_ = _e1477;
                                            phi_1491_ = _e1479;
                                            phi_1492_ = _e1481;
                                            phi_1493_ = _e1483;
                                            phi_1494_ = _e1259;
                                        } else {
                                            phi_1761_ = _e1244;
                                            phi_1491_ = i32();
                                            phi_1492_ = array<f32, 3>();
                                            phi_1493_ = array<f32, 3>();
                                            phi_1494_ = false;
                                        }
                                        let _e1485 = phi_1761_;
                                        let _e1487 = phi_1491_;
                                        let _e1489 = phi_1492_;
                                        let _e1491 = phi_1493_;
                                        let _e1493 = phi_1494_;
                                        phi_1760_ = _e1485;
                                        phi_1283_ = _e1487;
                                        phi_1286_ = _e1489;
                                        phi_1288_ = _e1491;
                                        phi_1496_ = _e1493;
                                    } else {
                                        phi_1760_ = _e1244;
                                        phi_1283_ = i32();
                                        phi_1286_ = array<f32, 3>();
                                        phi_1288_ = array<f32, 3>();
                                        phi_1496_ = false;
                                    }
                                    let _e1495 = phi_1760_;
                                    let _e1497 = phi_1283_;
                                    let _e1499 = phi_1286_;
                                    let _e1501 = phi_1288_;
                                    let _e1503 = phi_1496_;
                                    local_149 = _e1503;
                                    continue;
                                    continuing {
                                        let _e1504 = local_149;
                                        phi_1743_ = _e1495;
                                        phi_1282_ = _e1497;
                                        phi_1285_ = _e1499;
                                        phi_1287_ = _e1501;
                                        phi_1759_ = _e1495;
                                        break if !(_e1504);
                                    }
                                }
                                let _e1507 = phi_1759_;
                                phi_1765_ = _e1507;
                                if _e1507 {
                                    break;
                                }
                                let _e1508 = local_117;
                                phi_1766_ = _e1507;
                                phi_1266_ = (_e1508 + 1i);
                                let _e1753 = local_165;
                                phi_1269_ = _e1753;
                                let _e1756 = local_166;
                                phi_1271_ = _e1756;
                            } else {
                                phi_1766_ = _e1229;
                                phi_1266_ = i32();
                                phi_1269_ = array<f32, 3>();
                                phi_1271_ = array<f32, 3>();
                            }
                            let _e1511 = phi_1766_;
                            let _e1513 = phi_1266_;
                            let _e1515 = phi_1269_;
                            let _e1517 = phi_1271_;
                            continue;
                            continuing {
                                let _e1518 = local_120;
                                phi_1744_ = _e1511;
                                phi_1265_ = _e1513;
                                phi_1268_ = _e1515;
                                phi_1270_ = _e1517;
                                phi_1765_ = _e1511;
                                break if !(_e1518);
                            }
                        }
                        let _e1521 = phi_1765_;
                        if _e1521 {
                            break;
                        }
                        let _e1522 = local_119;
                        let _e1523 = local_118;
                        phi_1508_ = type_24(_e1522, _e1523);
                    }
                    let _e1526 = phi_1508_;
                    local_150 = _e1526.member_1;
                    let _e1530 = local_162[0u];
                    let _e1534 = local_162[1u];
                    let _e1538 = local_162[2u];
                    local_162[0u] = (_e1530 + _e1526.member[0]);
                    local_162[1u] = (_e1534 + _e1526.member[1]);
                    local_162[2u] = (_e1538 + _e1526.member[2]);
                    let _e1542 = local_161[3u];
                    local_151 = _e1542;
                    if (_e1542 > 0f) {
                        let _e1544 = local_151;
                        let _e1545 = (1f - _e1544);
                        let _e1546 = local_162[0u];
                        let _e1549 = local_161[0u];
                        let _e1551 = local_162[1u];
                        let _e1554 = local_161[1u];
                        let _e1556 = local_162[2u];
                        let _e1559 = local_161[2u];
                        local_162[0u] = ((_e1546 * _e1545) + _e1549);
                        local_162[1u] = ((_e1551 * _e1545) + _e1554);
                        local_162[2u] = ((_e1556 * _e1545) + _e1559);
                    }
                    let _e1561 = local_162[0u];
                    let _e1562 = local_150;
                    let _e1565 = local_162[1u];
                    let _e1566 = local_150;
                    let _e1569 = local_162[2u];
                    let _e1570 = local_150;
                    local_162[0u] = (_e1561 + _e1562[0]);
                    local_162[1u] = (_e1565 + _e1566[1]);
                    local_162[2u] = (_e1569 + _e1570[2]);
                    let _e1573 = local_162[0u];
                    local_152 = bitcast<u32>(_e1573);
                    let _e1575 = local_46;
                    let _e1576 = local_6;
                    if (_e1575 < _e1576) {
                    } else {
                        break;
                    }
                    let _e1578 = local_46;
                    let _e1581 = local_152;
                    global_8.member[_e1578] = _e1581;
                    let _e1582 = local_162[1u];
                    local_153 = bitcast<u32>(_e1582);
                    let _e1584 = local_48;
                    let _e1585 = local_6;
                    if (_e1584 < _e1585) {
                    } else {
                        break;
                    }
                    let _e1587 = local_48;
                    let _e1590 = local_153;
                    global_8.member[_e1587] = _e1590;
                    let _e1591 = local_162[2u];
                    local_154 = bitcast<u32>(_e1591);
                    let _e1593 = local_50;
                    let _e1594 = local_6;
                    if (_e1593 < _e1594) {
                    } else {
                        break;
                    }
                    let _e1596 = local_50;
                    let _e1599 = local_154;
                    global_8.member[_e1596] = _e1599;
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
