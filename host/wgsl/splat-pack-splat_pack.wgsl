struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_17 {
    member: array<f32, 3>,
    member_1: f32,
}

struct type_20 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: f32,
}

struct type_21 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_22 {
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
    member_16: type_21,
    member_17: u32,
    member_18: u32,
}

struct type_23 {
    member: type_22,
}

struct type_26 {
    member: array<u32, 2>,
    member_1: array<f32, 3>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_28 {
    member: type_17,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
    member_6: f32,
    member_7: f32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: type_26,
    member_12: type_26,
    member_13: u32,
    member_14: u32,
    member_15: u32,
    member_16: u32,
    member_17: u32,
}

struct type_29 {
    member: array<u32, 3>,
    member_1: u32,
}

struct type_39 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_3: type_7;
var<immediate> global_4: type_23;
@group(0) @binding(0) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_7;
@group(0) @binding(4) 
var<storage, read_write> global_8: type_39;
@group(0) @binding(5) 
var<storage, read_write> global_9: type_39;
var<private> global_10: u32 = 2143289344u;
var<private> global_11: u32 = 2139095040u;

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
    var local_9: type_22;
    var local_10: f32;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
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
    var local_26: bool;
    var local_27: u32;
    var local_28: bool;
    var local_29: u32;
    var local_30: bool;
    var local_31: u32;
    var local_32: u32;
    var local_33: bool;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: type_28;
    var local_40: type_28;
    var local_41: f32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: bool;
    var local_46: u32;
    var local_47: u32;
    var local_48: type_28;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: f32;
    var local_53: u32;
    var local_54: f32;
    var local_55: u32;
    var local_56: array<f32, 3>;
    var local_57: u32;
    var local_58: f32;
    var local_59: u32;
    var local_60: type_20;
    var local_61: u32;
    var local_62: type_28;
    var local_63: array<f32, 3>;
    var local_64: f32;
    var local_65: f32;
    var local_66: u32;
    var local_67: bool;
    var local_68: u32;
    var local_69: f32;
    var local_70: bool;
    var local_71: type_28;
    var local_72: f32;
    var local_73: bool;
    var local_74: f32;
    var local_75: f32;
    var local_76: bool;
    var local_77: f32;
    var local_78: f32;
    var local_79: bool;
    var local_80: f32;
    var local_81: type_28;
    var local_82: f32;
    var local_83: f32;
    var local_84: f32;
    var local_85: array<f32, 3>;
    var local_86: f32;
    var local_87: type_28;
    var local_88: array<u32, 2>;
    var local_89: u32;
    var local_90: f32;
    var local_91: f32;
    var local_92: bool;
    var local_93: u32;
    var local_94: u32;
    var local_95: u32;
    var local_96: u32;
    var local_97: u32;
    var local_98: type_26;
    var local_99: bool;
    var local_100: f32;
    var local_101: bool;
    var local_102: bool;
    var local_103: f32;
    var local_104: bool;
    var local_105: bool;
    var local_106: bool;
    var local_107: type_28;
    var local_108: type_28;
    var local_109: type_28;
    var local_110: bool;
    var local_111: u32;
    var local_112: type_28;
    var local_113: type_28;
    var local_114: u32;
    var local_115: u32;
    var local_116: u32;
    var local_117: bool;
    var local_118: bool;
    var local_119: u32;
    var local_120: array<f32, 3>;
    var local_121: f32;
    var local_122: f32;
    var local_123: f32;
    var local_124: f32;
    var local_125: f32;
    var local_126: f32;
    var local_127: i32;
    var local_128: i32;
    var local_129: f32;
    var local_130: u32;
    var local_131: u32;
    var local_132: bool;
    var local_133: f32;
    var local_134: bool;
    var local_135: bool;
    var local_136: u32;
    var local_137: u32;
    var local_138: u32;
    var local_139: u32;
    var local_140: f32;
    var local_141: u32;
    var local_142: f32;
    var local_143: u32;
    var local_144: u32;
    var local_145: u32;
    var local_146: u32;
    var local_147: u32;
    var local_148: u32;
    var local_149: u32;
    var local_150: u32;
    var local_151: u32;
    var local_152: u32;
    var local_153: u32;
    var local_154: u32;
    var local_155: u32;
    var local_156: bool;
    var local_157: u32;
    var local_158: u32;
    var local_159: f32;
    var local_160: f32;
    var local_161: f32;
    var local_162: u32;
    var local_163: bool;
    var local_164: array<f32, 3>;
    var local_165: f32;
    var local_166: u32;
    var local_167: u32;
    var local_168: u32;
    var local_169: u32;
    var local_170: u32;
    var local_171: u32;
    var local_172: u32;
    var local_173: u32;
    var local_174: u32;
    var local_175: u32;
    var local_176: u32;
    var local_177: u32;
    var local_178: u32;
    var local_179: u32;
    var local_180: u32;
    var local_181: u32;
    var local_182: u32;
    var local_183: u32;
    var local_184: bool;
    var local_185: type_28;
    var local_186: bool;
    var local_187: u32;
    var local_188: bool;
    var local_189: bool;
    var local_190: f32;
    var local_191: array<f32, 3>;
    var local_192: array<u32, 3>;
    var phi_2430_: bool;
    var phi_270_: u32;
    var phi_2427_: bool;
    var phi_400_: type_28;
    var phi_403_: f32;
    var phi_405_: u32;
    var phi_407_: u32;
    var phi_433_: type_28;
    var phi_544_: type_20;
    var phi_577_: bool;
    var phi_578_: bool;
    var phi_580_: bool;
    var phi_581_: bool;
    var phi_582_: bool;
    var phi_583_: bool;
    var phi_597_: bool;
    var phi_613_: f32;
    var phi_624_: bool;
    var phi_638_: bool;
    var phi_643_: f32;
    var phi_654_: bool;
    var phi_668_: bool;
    var phi_673_: f32;
    var phi_684_: bool;
    var phi_698_: bool;
    var phi_703_: f32;
    var phi_2265_: bool;
    var phi_2275_: bool;
    var phi_2285_: bool;
    var phi_716_: bool;
    var phi_718_: bool;
    var phi_719_: bool;
    var phi_739_: bool;
    var phi_753_: bool;
    var phi_758_: f32;
    var phi_769_: bool;
    var phi_783_: bool;
    var phi_788_: f32;
    var phi_799_: bool;
    var phi_813_: bool;
    var phi_818_: f32;
    var phi_872_: bool;
    var phi_900_: f32;
    var phi_901_: f32;
    var phi_907_: f32;
    var phi_909_: f32;
    var phi_956_: u32;
    var phi_992_: u32;
    var phi_994_: type_26;
    var phi_1021_: bool;
    var phi_1023_: bool;
    var phi_1024_: bool;
    var phi_1025_: bool;
    var phi_1026_: bool;
    var phi_1056_: type_28;
    var phi_1057_: type_28;
    var phi_1065_: type_28;
    var phi_1067_: type_28;
    var phi_1068_: bool;
    var phi_1098_: bool;
    var phi_1100_: bool;
    var phi_1101_: bool;
    var phi_1102_: bool;
    var phi_1103_: bool;
    var phi_1133_: type_28;
    var phi_1134_: type_28;
    var phi_1142_: type_28;
    var phi_1144_: type_28;
    var phi_1145_: bool;
    var phi_1160_: type_28;
    var phi_1162_: type_28;
    var phi_1163_: bool;
    var phi_1204_: type_28;
    var phi_1195_: type_28;
    var phi_1205_: type_28;
    var phi_1207_: type_28;
    var phi_1209_: bool;
    var phi_1217_: type_28;
    var phi_1218_: u32;
    var phi_1278_: type_28;
    var phi_1281_: type_28;
    var phi_1283_: type_28;
    var phi_1284_: u32;
    var phi_1285_: type_28;
    var phi_1286_: u32;
    var phi_1287_: type_28;
    var phi_1288_: u32;
    var phi_1292_: type_28;
    var phi_1293_: u32;
    var phi_1325_: type_28;
    var phi_1326_: type_28;
    var phi_1327_: type_28;
    var phi_1328_: type_28;
    var phi_1329_: type_28;
    var phi_1335_: type_28;
    var phi_1336_: bool;
    var phi_1337_: bool;
    var phi_2331_: bool;
    var phi_2253_: bool;
    var phi_2251_: type_28;
    var phi_1345_: type_28;
    var phi_2468_: bool;
    var phi_401_: type_28;
    var phi_1350_: bool;
    var phi_1372_: bool;
    var phi_1386_: bool;
    var phi_1391_: f32;
    var phi_1402_: bool;
    var phi_1416_: bool;
    var phi_1421_: f32;
    var phi_1432_: bool;
    var phi_1446_: bool;
    var phi_1451_: f32;
    var phi_1469_: f32;
    var phi_1478_: f32;
    var phi_2447_: bool;
    var phi_1493_: i32;
    var phi_1496_: i32;
    var phi_1510_: u32;
    var phi_1513_: u32;
    var phi_1561_: u32;
    var phi_1511_: u32;
    var phi_1514_: u32;
    var phi_2443_: bool;
    var phi_1569_: i32;
    var phi_1570_: i32;
    var phi_2472_: bool;
    var phi_1494_: i32;
    var phi_1497_: i32;
    var phi_1572_: bool;
    var phi_2471_: bool;
    var phi_2488_: bool;
    var phi_1586_: type_29;
    var phi_1608_: f32;
    var phi_1713_: u32;
    var phi_1726_: u32;
    var phi_1786_: f32;
    var phi_1815_: bool;
    var phi_1843_: f32;
    var phi_1844_: f32;
    var phi_1850_: f32;
    var phi_1852_: f32;
    var phi_2476_: bool;
    var phi_1879_: f32;
    var phi_1880_: u32;
    var phi_2475_: bool;
    var phi_404_: f32;
    var phi_406_: u32;
    var phi_408_: u32;
    var phi_2474_: bool;
    var phi_2255_: type_28;
    var phi_1889_: bool;
    var phi_2112_: bool;
    var phi_2497_: bool;
    var phi_2496_: bool;
    var phi_271_: u32;
    var phi_2495_: bool;
    var local_193: type_28;

    let _e272 = global_10;
    let _e273 = bitcast<f32>(_e272);
    local_190 = _e273;
    let _e274 = global_11;
    switch bitcast<i32>(0u) {
        default: {
            let _e278 = global;
            local = _e278;
            let _e279 = global_1;
            let _e280 = global_2;
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            let _e293 = arrayLength((&global_9.member));
            local_6 = _e293;
            local_7 = _e279.x;
            local_8 = _e280.x;
            let _e296 = global_4.member;
            local_9 = _e296;
            if (18u < _e293) {
            } else {
                break;
            }
            let _e298 = local_6;
            if (19u < _e298) {
            } else {
                break;
            }
            let _e302 = atomicLoad((&global_9.member[19u]));
            local_10 = bitcast<f32>(_e302);
            let _e304 = local_9;
            local_11 = _e304.member;
            let _e306 = local_9;
            let _e308 = local_9;
            local_12 = _e308.member_2;
            let _e310 = local_9;
            local_13 = _e310.member_3;
            let _e312 = local_9;
            local_14 = _e312.member_4;
            let _e314 = local_9;
            local_15 = _e314.member_6;
            let _e316 = local_9;
            local_16 = _e316.member_7;
            let _e318 = local_9;
            local_17 = _e318.member_8;
            let _e320 = local_9;
            local_18 = _e320.member_10;
            let _e322 = local_9;
            local_19 = _e322.member_15.member;
            local_20 = _e322.member_15.member_1;
            local_21 = _e322.member_15.member_2;
            local_22 = _e322.member_15.member_3;
            local_23 = (_e304.member * _e306.member_1);
            let _e329 = local_8;
            local_24 = (_e329 * 256u);
            let _e331 = local_7;
            phi_2430_ = false;
            phi_270_ = (_e331 * 256u);
            loop {
                let _e334 = phi_2430_;
                let _e336 = phi_270_;
                local_25 = _e336;
                let _e337 = local_25;
                let _e338 = local_23;
                let _e339 = (_e337 < _e338);
                local_26 = _e339;
                if _e339 {
                    let _e340 = local_25;
                    let _e341 = local;
                    let _e342 = (_e340 + _e341);
                    local_27 = _e342;
                    let _e343 = local_23;
                    if (_e342 < _e343) {
                        let _e345 = local_27;
                        let _e346 = local_2;
                        if (_e345 < _e346) {
                        } else {
                            phi_2495_ = true;
                            break;
                        }
                        let _e348 = local_27;
                        let _e351 = global_3.member[_e348];
                        let _e352 = local_12;
                        let _e354 = local_12;
                        let _e355 = select(_e354, _e351, (_e351 < _e352));
                        let _e358 = local_27;
                        let _e359 = local_190;
                        let _e361 = local_13;
                        let _e362 = (_e361 == 0u);
                        local_28 = _e362;
                        if _e362 {
                            phi_2495_ = true;
                            break;
                        }
                        let _e363 = local_15;
                        let _e364 = local_13;
                        local_29 = (_e363 / _e364);
                        let _e366 = local_14;
                        let _e367 = (_e366 == 0u);
                        local_30 = _e367;
                        if _e367 {
                            phi_2495_ = true;
                            break;
                        }
                        let _e368 = local_27;
                        let _e369 = local_14;
                        local_31 = (_e368 % _e369);
                        let _e371 = local_30;
                        if _e371 {
                            phi_2495_ = true;
                            break;
                        }
                        let _e372 = local_27;
                        let _e373 = local_14;
                        local_32 = (_e372 / _e373);
                        let _e375 = local_29;
                        let _e376 = (_e375 == 0u);
                        local_33 = _e376;
                        if _e376 {
                            phi_2495_ = true;
                            break;
                        }
                        let _e377 = local_32;
                        let _e378 = local_29;
                        let _e380 = local_16;
                        local_34 = ((_e377 / _e378) * _e380);
                        let _e382 = local_33;
                        if _e382 {
                            phi_2495_ = true;
                            break;
                        }
                        let _e383 = local_31;
                        let _e384 = local_29;
                        let _e386 = local_34;
                        local_35 = (_e386 + (_e383 / _e384));
                        let _e388 = local_33;
                        if _e388 {
                            phi_2495_ = true;
                            break;
                        }
                        let _e389 = local_31;
                        let _e390 = local_29;
                        local_36 = (_e389 % _e390);
                        let _e392 = local_33;
                        if _e392 {
                            phi_2495_ = true;
                            break;
                        }
                        let _e393 = local_32;
                        let _e394 = local_29;
                        local_37 = (_e393 % _e394);
                        let _e396 = local_28;
                        if _e396 {
                            phi_2495_ = true;
                            break;
                        }
                        let _e397 = local_35;
                        let _e398 = local_29;
                        let _e400 = local_37;
                        let _e402 = local_29;
                        let _e404 = local_36;
                        let _e406 = local_12;
                        let _e407 = local_13;
                        let _e409 = local_13;
                        local_38 = (((((_e397 * _e398) + _e400) * _e402) + _e404) * ((_e406 * _e407) * _e409));
                        phi_2427_ = _e334;
                        phi_400_ = type_28(type_17(array<f32, 3>(0f, 0f, 0f), 1f), _e358, _e355, select(_e355, 1u, (_e355 == 0u)), 0u, 0u, _e359, 1f, 0u, 0u, 0u, type_26(array<u32, 2>(0u, 0u), array<f32, 3>(0f, 0f, 0f), 1f, 0f, 0u, 0u), type_26(array<u32, 2>(0u, 0u), array<f32, 3>(0f, 0f, 0f), 1f, 0f, 0u, 0u), 0u, 0u, 0u, 0u, 0u);
                        phi_403_ = 0f;
                        phi_405_ = 0u;
                        phi_407_ = 0u;
                        loop {
                            let _e413 = phi_2427_;
                            let _e415 = phi_400_;
                            let _e417 = phi_403_;
                            let _e419 = phi_405_;
                            let _e421 = phi_407_;
                            local_39 = _e415;
                            local_41 = _e417;
                            local_42 = _e419;
                            local_43 = _e421;
                            let _e422 = local_39;
                            if (_e422.member_10 == 0u) {
                                let _e466 = local_39;
                                local_44 = _e466.member_1;
                                let _e468 = local_11;
                                let _e469 = (_e468 == 0u);
                                local_45 = _e469;
                                if _e469 {
                                    phi_2474_ = true;
                                    phi_2255_ = type_28();
                                    break;
                                }
                                let _e470 = local_44;
                                let _e471 = local_11;
                                local_46 = (_e470 % _e471);
                                let _e473 = local_45;
                                if _e473 {
                                    phi_2474_ = true;
                                    phi_2255_ = type_28();
                                    break;
                                }
                                let _e474 = local_44;
                                let _e475 = local_11;
                                local_47 = (_e474 / _e475);
                                phi_433_ = _e415;
                                loop {
                                    let _e478 = phi_433_;
                                    local_48 = _e478;
                                    local_193 = _e478;
                                    let _e479 = local_48;
                                    local_49 = _e479.member_4;
                                    let _e481 = local_48;
                                    if (_e479.member_4 < _e481.member_3) {
                                        let _e484 = local_48;
                                        local_50 = _e484.member_2;
                                        let _e486 = local_49;
                                        if (_e486 >= _e484.member_2) {
                                            phi_544_ = type_20(array<f32, 3>(0f, 0f, 0f), bitcast<f32>(_e274), 1f);
                                        } else {
                                            let _e488 = local_48;
                                            let _e490 = local_12;
                                            let _e492 = local_49;
                                            let _e494 = (5u * ((_e488.member_1 * _e490) + _e492));
                                            local_51 = _e494;
                                            let _e495 = local_1;
                                            if (_e494 < _e495) {
                                            } else {
                                                phi_2331_ = true;
                                                phi_2253_ = bool();
                                                phi_2251_ = type_28();
                                                break;
                                            }
                                            let _e497 = local_51;
                                            let _e500 = global_5.member[_e497];
                                            local_52 = bitcast<f32>(_e500);
                                            let _e502 = local_51;
                                            let _e503 = (_e502 + 1u);
                                            local_53 = _e503;
                                            let _e504 = local_1;
                                            if (_e503 < _e504) {
                                            } else {
                                                phi_2331_ = true;
                                                phi_2253_ = bool();
                                                phi_2251_ = type_28();
                                                break;
                                            }
                                            let _e506 = local_53;
                                            let _e509 = global_5.member[_e506];
                                            local_54 = bitcast<f32>(_e509);
                                            let _e511 = local_51;
                                            let _e512 = (_e511 + 2u);
                                            local_55 = _e512;
                                            let _e513 = local_1;
                                            if (_e512 < _e513) {
                                            } else {
                                                phi_2331_ = true;
                                                phi_2253_ = bool();
                                                phi_2251_ = type_28();
                                                break;
                                            }
                                            let _e515 = local_55;
                                            let _e518 = global_5.member[_e515];
                                            let _e520 = local_52;
                                            let _e521 = local_54;
                                            local_56 = array<f32, 3>(_e520, _e521, bitcast<f32>(_e518));
                                            let _e523 = local_51;
                                            let _e524 = (_e523 + 3u);
                                            local_57 = _e524;
                                            let _e525 = local_1;
                                            if (_e524 < _e525) {
                                            } else {
                                                phi_2331_ = true;
                                                phi_2253_ = bool();
                                                phi_2251_ = type_28();
                                                break;
                                            }
                                            let _e527 = local_57;
                                            let _e530 = global_5.member[_e527];
                                            local_58 = bitcast<f32>(_e530);
                                            let _e532 = local_51;
                                            let _e533 = (_e532 + 4u);
                                            local_59 = _e533;
                                            let _e534 = local_1;
                                            if (_e533 < _e534) {
                                            } else {
                                                phi_2331_ = true;
                                                phi_2253_ = bool();
                                                phi_2251_ = type_28();
                                                break;
                                            }
                                            let _e536 = local_59;
                                            let _e539 = global_5.member[_e536];
                                            let _e541 = local_56;
                                            let _e542 = local_58;
                                            phi_544_ = type_20(_e541, _e542, bitcast<f32>(_e539));
                                        }
                                        let _e545 = phi_544_;
                                        local_60 = _e545;
                                        let _e546 = local_49;
                                        let _e547 = (_e546 + 1u);
                                        local_61 = _e547;
                                        let _e548 = local_48;
                                        local_62 = type_28(_e548.member, _e548.member_1, _e548.member_2, _e548.member_3, _e547, _e548.member_5, _e548.member_6, _e548.member_7, _e548.member_8, _e548.member_9, _e548.member_10, _e548.member_11, _e548.member_12, _e548.member_13, _e548.member_14, _e548.member_15, _e548.member_16, _e548.member_17);
                                        local_63 = _e545.member;
                                        local_64 = _e545.member_1;
                                        local_65 = _e545.member[0];
                                        let _e571 = bitcast<u32>(_e545.member[0]);
                                        local_66 = _e571;
                                        if ((_e571 & 2139095040u) != 2139095040u) {
                                            let _e574 = local_63;
                                            if ((bitcast<u32>(_e574[1]) & 2139095040u) != 2139095040u) {
                                                let _e579 = local_63;
                                                let _e583 = ((bitcast<u32>(_e579[2]) & 2139095040u) != 2139095040u);
                                                local_67 = _e583;
                                                if _e583 {
                                                    let _e584 = local_64;
                                                    let _e585 = bitcast<u32>(_e584);
                                                    local_68 = _e585;
                                                    if (_e585 == 0u) {
                                                        phi_577_ = false;
                                                    } else {
                                                        let _e587 = local_68;
                                                        phi_577_ = (_e587 <= 2139095040u);
                                                    }
                                                    let _e590 = phi_577_;
                                                    phi_578_ = _e590;
                                                } else {
                                                    phi_578_ = bool();
                                                }
                                                let _e592 = phi_578_;
                                                let _e593 = local_67;
                                                phi_580_ = _e592;
                                                phi_581_ = select(true, false, _e593);
                                            } else {
                                                phi_580_ = bool();
                                                phi_581_ = true;
                                            }
                                            let _e596 = phi_580_;
                                            let _e598 = phi_581_;
                                            phi_582_ = _e596;
                                            phi_583_ = _e598;
                                        } else {
                                            phi_582_ = bool();
                                            phi_583_ = true;
                                        }
                                        let _e600 = phi_582_;
                                        let _e602 = phi_583_;
                                        if select(_e600, false, _e602) {
                                            let _e627 = local_60;
                                            local_69 = _e627.member_2;
                                            let _e629 = (_e627.member_2 >= 0f);
                                            local_70 = _e629;
                                            if _e629 {
                                                let _e630 = local_69;
                                                phi_597_ = (_e630 <= 1f);
                                            } else {
                                                phi_597_ = false;
                                            }
                                            let _e633 = phi_597_;
                                            let _e636 = local_48;
                                            let _e639 = local_62;
                                            local_71 = type_28(_e639.member, _e639.member_1, _e639.member_2, _e639.member_3, _e639.member_4, _e639.member_5, _e639.member_6, _e639.member_7, _e639.member_8, _e639.member_9, _e639.member_10, _e639.member_11, _e639.member_12, _e639.member_13, _e639.member_14, (_e636.member_15 + select(0u, 1u, !(_e633))), _e639.member_16, _e639.member_17);
                                            let _e659 = local_69;
                                            if (_e659 > 1f) {
                                                phi_613_ = 1f;
                                            } else {
                                                let _e661 = local_70;
                                                let _e662 = local_69;
                                                phi_613_ = select(0f, _e662, _e661);
                                            }
                                            let _e665 = phi_613_;
                                            local_72 = _e665;
                                            let _e666 = local_65;
                                            let _e667 = (_e666 > 1267650600000000000000000000000f);
                                            local_73 = _e667;
                                            if _e667 {
                                                let _e668 = local_65;
                                                phi_624_ = select(true, false, (_e668 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_624_ = true;
                                            }
                                            let _e672 = phi_624_;
                                            if _e672 {
                                                let _e673 = local_65;
                                                if (_e673 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e675 = local_65;
                                                    phi_638_ = select(true, false, (_e675 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_638_ = true;
                                                }
                                                let _e679 = phi_638_;
                                                let _e680 = local_65;
                                                phi_643_ = select(0f, _e680, _e679);
                                            } else {
                                                phi_643_ = 1267650600000000000000000000000f;
                                            }
                                            let _e683 = phi_643_;
                                            local_74 = _e683;
                                            let _e684 = local_63;
                                            local_75 = _e684[1];
                                            let _e686 = (_e684[1] > 1267650600000000000000000000000f);
                                            local_76 = _e686;
                                            if _e686 {
                                                let _e687 = local_75;
                                                phi_654_ = select(true, false, (_e687 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_654_ = true;
                                            }
                                            let _e691 = phi_654_;
                                            if _e691 {
                                                let _e692 = local_75;
                                                if (_e692 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e694 = local_75;
                                                    phi_668_ = select(true, false, (_e694 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_668_ = true;
                                                }
                                                let _e698 = phi_668_;
                                                let _e699 = local_75;
                                                phi_673_ = select(0f, _e699, _e698);
                                            } else {
                                                phi_673_ = 1267650600000000000000000000000f;
                                            }
                                            let _e702 = phi_673_;
                                            local_77 = _e702;
                                            let _e703 = local_63;
                                            local_78 = _e703[2];
                                            let _e705 = (_e703[2] > 1267650600000000000000000000000f);
                                            local_79 = _e705;
                                            if _e705 {
                                                let _e706 = local_78;
                                                phi_684_ = select(true, false, (_e706 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_684_ = true;
                                            }
                                            let _e710 = phi_684_;
                                            if _e710 {
                                                let _e711 = local_78;
                                                if (_e711 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e713 = local_78;
                                                    phi_698_ = select(true, false, (_e713 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_698_ = true;
                                                }
                                                let _e717 = phi_698_;
                                                let _e718 = local_78;
                                                phi_703_ = select(0f, _e718, _e717);
                                            } else {
                                                phi_703_ = 1267650600000000000000000000000f;
                                            }
                                            let _e721 = phi_703_;
                                            local_80 = _e721;
                                            let _e722 = local_65;
                                            let _e723 = local_74;
                                            if (_e722 == _e723) {
                                                phi_2265_ = true;
                                            } else {
                                                let _e725 = local_66;
                                                phi_2265_ = ((_e725 & 2147483647u) > 2139095040u);
                                            }
                                            let _e729 = phi_2265_;
                                            if _e729 {
                                                let _e730 = local_75;
                                                let _e731 = local_77;
                                                if (_e730 == _e731) {
                                                    phi_2275_ = true;
                                                } else {
                                                    let _e733 = local_75;
                                                    phi_2275_ = ((bitcast<u32>(_e733) & 2147483647u) > 2139095040u);
                                                }
                                                let _e738 = phi_2275_;
                                                local_186 = _e738;
                                                if _e738 {
                                                    let _e739 = local_78;
                                                    let _e740 = local_80;
                                                    if (_e739 == _e740) {
                                                        phi_2285_ = true;
                                                    } else {
                                                        let _e742 = local_78;
                                                        phi_2285_ = ((bitcast<u32>(_e742) & 2147483647u) > 2139095040u);
                                                    }
                                                    let _e747 = phi_2285_;
                                                    phi_716_ = _e747;
                                                } else {
                                                    phi_716_ = bool();
                                                }
                                                let _e749 = phi_716_;
                                                let _e750 = local_186;
                                                phi_718_ = _e749;
                                                phi_719_ = select(true, false, _e750);
                                            } else {
                                                phi_718_ = bool();
                                                phi_719_ = true;
                                            }
                                            let _e753 = phi_718_;
                                            let _e755 = phi_719_;
                                            let _e759 = local_48;
                                            let _e762 = local_71;
                                            local_81 = type_28(_e762.member, _e762.member_1, _e762.member_2, _e762.member_3, _e762.member_4, _e762.member_5, _e762.member_6, _e762.member_7, _e762.member_8, _e762.member_9, _e762.member_10, _e762.member_11, _e762.member_12, _e762.member_13, (_e759.member_14 + select(0u, 1u, !(select(_e753, false, _e755)))), _e762.member_15, _e762.member_16, _e762.member_17);
                                            let _e782 = local_73;
                                            if _e782 {
                                                let _e783 = local_65;
                                                phi_739_ = select(true, false, (_e783 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_739_ = true;
                                            }
                                            let _e787 = phi_739_;
                                            if _e787 {
                                                let _e788 = local_65;
                                                if (_e788 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e790 = local_65;
                                                    phi_753_ = select(true, false, (_e790 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_753_ = true;
                                                }
                                                let _e794 = phi_753_;
                                                let _e795 = local_65;
                                                phi_758_ = select(0f, _e795, _e794);
                                            } else {
                                                phi_758_ = 1267650600000000000000000000000f;
                                            }
                                            let _e798 = phi_758_;
                                            local_82 = _e798;
                                            let _e799 = local_76;
                                            if _e799 {
                                                let _e800 = local_75;
                                                phi_769_ = select(true, false, (_e800 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_769_ = true;
                                            }
                                            let _e804 = phi_769_;
                                            if _e804 {
                                                let _e805 = local_75;
                                                if (_e805 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e807 = local_75;
                                                    phi_783_ = select(true, false, (_e807 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_783_ = true;
                                                }
                                                let _e811 = phi_783_;
                                                let _e812 = local_75;
                                                phi_788_ = select(0f, _e812, _e811);
                                            } else {
                                                phi_788_ = 1267650600000000000000000000000f;
                                            }
                                            let _e815 = phi_788_;
                                            local_83 = _e815;
                                            let _e816 = local_79;
                                            if _e816 {
                                                let _e817 = local_78;
                                                phi_799_ = select(true, false, (_e817 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_799_ = true;
                                            }
                                            let _e821 = phi_799_;
                                            if _e821 {
                                                let _e822 = local_78;
                                                if (_e822 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e824 = local_78;
                                                    phi_813_ = select(true, false, (_e824 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_813_ = true;
                                                }
                                                let _e828 = phi_813_;
                                                let _e829 = local_78;
                                                phi_818_ = select(0f, _e829, _e828);
                                            } else {
                                                phi_818_ = 1267650600000000000000000000000f;
                                            }
                                            let _e832 = phi_818_;
                                            local_84 = _e832;
                                            let _e833 = local_82;
                                            let _e834 = local_83;
                                            let _e835 = array<f32, 3>(_e833, _e834, _e832);
                                            local_85 = _e835;
                                            let _e836 = local_48;
                                            let _e839 = local_81;
                                            let _e858 = type_28(_e839.member, _e839.member_1, _e839.member_2, _e839.member_3, _e839.member_4, _e839.member_5, _e839.member_6, _e839.member_7, (_e836.member_8 + 1u), _e839.member_9, _e839.member_10, _e839.member_11, _e839.member_12, _e839.member_13, _e839.member_14, _e839.member_15, _e839.member_16, _e839.member_17);
                                            let _e859 = local_72;
                                            let _e860 = (1f - _e859);
                                            local_86 = _e860;
                                            let _e861 = local_48;
                                            let _e882 = type_28(_e858.member, _e858.member_1, _e858.member_2, _e858.member_3, _e858.member_4, _e858.member_5, _e858.member_6, (_e861.member_7 * _e860), _e858.member_8, _e858.member_9, _e858.member_10, _e858.member_11, _e858.member_12, _e858.member_13, _e858.member_14, _e858.member_15, _e858.member_16, _e858.member_17);
                                            local_87 = _e882;
                                            let _e883 = local_46;
                                            let _e886 = local_47;
                                            let _e889 = array<u32, 2>(((2u * _e883) + 1u), ((2u * _e886) + 1u));
                                            local_88 = _e889;
                                            let _e890 = local_72;
                                            let _e891 = local_64;
                                            let _e893 = local_64;
                                            let _e894 = bitcast<u32>(_e893);
                                            local_89 = _e894;
                                            if (_e894 == 2139095040u) {
                                                let _e929 = local_20;
                                                let _e931 = local_19;
                                                let _e933 = local_21;
                                                let _e934 = local_19;
                                                let _e937 = local_22;
                                                phi_909_ = (0.5f * ((((2f * _e929) * _e931) / (_e933 - _e934)) * _e937));
                                            } else {
                                                let _e896 = local_89;
                                                if (_e896 == 0u) {
                                                    phi_872_ = false;
                                                } else {
                                                    let _e898 = local_89;
                                                    phi_872_ = (_e898 <= 2139095040u);
                                                }
                                                let _e901 = phi_872_;
                                                if _e901 {
                                                    let _e902 = local_20;
                                                    let _e904 = local_19;
                                                    let _e906 = local_21;
                                                    let _e907 = local_19;
                                                    let _e910 = local_22;
                                                    let _e911 = ((((2f * _e902) * _e904) / (_e906 - _e907)) * _e910);
                                                    local_90 = _e911;
                                                    if (_e911 == 0f) {
                                                        phi_900_ = 0f;
                                                    } else {
                                                        let _e913 = local_21;
                                                        let _e914 = local_64;
                                                        let _e917 = local_90;
                                                        phi_900_ = (_e917 * (1f - (_e913 / _e914)));
                                                    }
                                                    let _e920 = phi_900_;
                                                    phi_901_ = _e920;
                                                } else {
                                                    phi_901_ = _e273;
                                                }
                                                let _e922 = phi_901_;
                                                local_91 = _e922;
                                                if (_e922 < 0f) {
                                                    let _e924 = local_91;
                                                    phi_907_ = -(_e924);
                                                } else {
                                                    phi_907_ = _e922;
                                                }
                                                let _e927 = phi_907_;
                                                phi_909_ = (0.5f * _e927);
                                            }
                                            let _e941 = phi_909_;
                                            let _e946 = (select(_e941, 0f, ((bitcast<u32>(_e941) & 2147483647u) > 2139095040u)) + 0.5f);
                                            let _e947 = local_10;
                                            let _e949 = local_10;
                                            let _e950 = select(_e949, _e946, (_e946 < _e947));
                                            local_92 = (select(0.5f, _e950, (_e950 > 0.5f)) <= 1f);
                                            let _e954 = local_61;
                                            let _e955 = local_50;
                                            if (_e954 > _e955) {
                                                phi_994_ = type_26(_e889, _e835, _e890, _e891, 0u, 0u);
                                            } else {
                                                let _e957 = local_48;
                                                local_93 = _e957.member_1;
                                                let _e959 = local_18;
                                                let _e962 = ((_e959 >> bitcast<u32>(8u)) & 7u);
                                                local_94 = _e962;
                                                if (_e962 == 0u) {
                                                    phi_992_ = 0u;
                                                } else {
                                                    let _e964 = local_94;
                                                    let _e965 = local_94;
                                                    let _e966 = (_e964 * _e965);
                                                    local_95 = _e966;
                                                    if (_e966 >= 32u) {
                                                        phi_956_ = 4294967295u;
                                                    } else {
                                                        let _e968 = local_95;
                                                        phi_956_ = ((1u << bitcast<u32>((_e968 & 31u))) - 1u);
                                                    }
                                                    let _e974 = phi_956_;
                                                    local_96 = _e974;
                                                    let _e975 = local_23;
                                                    let _e976 = local_12;
                                                    let _e978 = local_93;
                                                    let _e979 = local_12;
                                                    let _e981 = local_49;
                                                    let _e984 = ((5u * (_e975 * _e976)) + ((_e978 * _e979) + _e981));
                                                    local_97 = _e984;
                                                    let _e985 = local_1;
                                                    if (_e984 < _e985) {
                                                    } else {
                                                        phi_2331_ = true;
                                                        phi_2253_ = bool();
                                                        phi_2251_ = type_28();
                                                        break;
                                                    }
                                                    let _e987 = local_97;
                                                    let _e990 = global_5.member[_e987];
                                                    let _e991 = local_96;
                                                    let _e992 = (_e990 & _e991);
                                                    let _e993 = local_96;
                                                    phi_992_ = select(_e992, 0u, (_e992 == _e993));
                                                }
                                                let _e997 = phi_992_;
                                                let _e998 = local_88;
                                                let _e999 = local_85;
                                                let _e1000 = local_72;
                                                let _e1001 = local_64;
                                                phi_994_ = type_26(_e998, _e999, _e1000, _e1001, 0u, _e997);
                                            }
                                            let _e1004 = phi_994_;
                                            local_98 = _e1004;
                                            let _e1005 = local_92;
                                            if _e1005 {
                                                let _e1006 = local_48;
                                                let _e1008 = (_e1006.member_5 == 0u);
                                                local_99 = _e1008;
                                                if _e1008 {
                                                    let _e1009 = local_48;
                                                    local_100 = _e1009.member.member_1;
                                                    if (_e1009.member.member_1 >= 1f) {
                                                        let _e1013 = local_48;
                                                        if (_e1013.member.member[0] == 0f) {
                                                            let _e1018 = local_48;
                                                            let _e1022 = (_e1018.member.member[1] == 0f);
                                                            local_101 = _e1022;
                                                            if _e1022 {
                                                                let _e1023 = local_48;
                                                                phi_1021_ = (_e1023.member.member[2] == 0f);
                                                            } else {
                                                                phi_1021_ = bool();
                                                            }
                                                            let _e1029 = phi_1021_;
                                                            let _e1030 = local_101;
                                                            phi_1023_ = _e1029;
                                                            phi_1024_ = select(true, false, _e1030);
                                                        } else {
                                                            phi_1023_ = bool();
                                                            phi_1024_ = true;
                                                        }
                                                        let _e1033 = phi_1023_;
                                                        let _e1035 = phi_1024_;
                                                        phi_1025_ = _e1033;
                                                        phi_1026_ = _e1035;
                                                    } else {
                                                        phi_1025_ = bool();
                                                        phi_1026_ = true;
                                                    }
                                                    let _e1037 = phi_1025_;
                                                    let _e1039 = phi_1026_;
                                                    if select(_e1037, false, _e1039) {
                                                        let _e1094 = local_85;
                                                        let _e1095 = local_86;
                                                        let _e1097 = local_87;
                                                        phi_1057_ = type_28(type_17(_e1094, _e1095), _e1097.member_1, _e1097.member_2, _e1097.member_3, _e1097.member_4, _e1097.member_5, _e1097.member_6, _e1097.member_7, _e1097.member_8, _e1097.member_9, _e1097.member_10, _e1097.member_11, _e1097.member_12, _e1097.member_13, _e1097.member_14, _e1097.member_15, _e1097.member_16, _e1097.member_17);
                                                    } else {
                                                        let _e1041 = local_100;
                                                        if (_e1041 > 0f) {
                                                            let _e1043 = local_48;
                                                            let _e1047 = local_100;
                                                            let _e1048 = local_82;
                                                            let _e1051 = local_48;
                                                            let _e1055 = local_100;
                                                            let _e1056 = local_83;
                                                            let _e1059 = local_48;
                                                            let _e1063 = local_100;
                                                            let _e1064 = local_84;
                                                            let _e1068 = local_100;
                                                            let _e1069 = local_86;
                                                            let _e1072 = local_87;
                                                            phi_1056_ = type_28(type_17(array<f32, 3>((_e1043.member.member[0] + (_e1047 * _e1048)), (_e1051.member.member[1] + (_e1055 * _e1056)), (_e1059.member.member[2] + (_e1063 * _e1064))), (_e1068 * _e1069)), _e1072.member_1, _e1072.member_2, _e1072.member_3, _e1072.member_4, _e1072.member_5, _e1072.member_6, _e1072.member_7, _e1072.member_8, _e1072.member_9, _e1072.member_10, _e1072.member_11, _e1072.member_12, _e1072.member_13, _e1072.member_14, _e1072.member_15, _e1072.member_16, _e1072.member_17);
                                                        } else {
                                                            phi_1056_ = _e882;
                                                        }
                                                        let _e1093 = phi_1056_;
                                                        phi_1057_ = _e1093;
                                                    }
                                                    let _e1118 = phi_1057_;
                                                    let _e1119 = local_64;
                                                    let _e1138 = type_28(_e1118.member, _e1118.member_1, _e1118.member_2, _e1118.member_3, _e1118.member_4, _e1118.member_5, _e1119, _e1118.member_7, _e1118.member_8, _e1118.member_9, _e1118.member_10, _e1118.member_11, _e1118.member_12, _e1118.member_13, _e1118.member_14, _e1118.member_15, _e1118.member_16, _e1118.member_17);
                                                    let _e1139 = local_72;
                                                    phi_1065_ = type_28(_e1138.member, _e1138.member_1, _e1138.member_2, _e1138.member_3, _e1138.member_4, select(1u, 2u, (_e1139 >= 1f)), _e1138.member_6, _e1138.member_7, _e1138.member_8, _e1138.member_9, _e1138.member_10, _e1138.member_11, _e1138.member_12, _e1138.member_13, _e1138.member_14, _e1138.member_15, _e1138.member_16, _e1138.member_17);
                                                } else {
                                                    phi_1065_ = type_28();
                                                }
                                                let _e1162 = phi_1065_;
                                                let _e1163 = local_99;
                                                phi_1067_ = _e1162;
                                                phi_1068_ = select(true, false, _e1163);
                                            } else {
                                                phi_1067_ = type_28();
                                                phi_1068_ = true;
                                            }
                                            let _e1166 = phi_1067_;
                                            let _e1168 = phi_1068_;
                                            if _e1168 {
                                                let _e1169 = local_92;
                                                if _e1169 {
                                                    let _e1170 = local_48;
                                                    let _e1172 = (_e1170.member_5 == 1u);
                                                    local_102 = _e1172;
                                                    if _e1172 {
                                                        let _e1173 = local_48;
                                                        local_103 = _e1173.member.member_1;
                                                        if (_e1173.member.member_1 >= 1f) {
                                                            let _e1177 = local_48;
                                                            if (_e1177.member.member[0] == 0f) {
                                                                let _e1182 = local_48;
                                                                let _e1186 = (_e1182.member.member[1] == 0f);
                                                                local_104 = _e1186;
                                                                if _e1186 {
                                                                    let _e1187 = local_48;
                                                                    phi_1098_ = (_e1187.member.member[2] == 0f);
                                                                } else {
                                                                    phi_1098_ = bool();
                                                                }
                                                                let _e1193 = phi_1098_;
                                                                let _e1194 = local_104;
                                                                phi_1100_ = _e1193;
                                                                phi_1101_ = select(true, false, _e1194);
                                                            } else {
                                                                phi_1100_ = bool();
                                                                phi_1101_ = true;
                                                            }
                                                            let _e1197 = phi_1100_;
                                                            let _e1199 = phi_1101_;
                                                            phi_1102_ = _e1197;
                                                            phi_1103_ = _e1199;
                                                        } else {
                                                            phi_1102_ = bool();
                                                            phi_1103_ = true;
                                                        }
                                                        let _e1201 = phi_1102_;
                                                        let _e1203 = phi_1103_;
                                                        if select(_e1201, false, _e1203) {
                                                            let _e1258 = local_85;
                                                            let _e1259 = local_86;
                                                            let _e1261 = local_87;
                                                            phi_1134_ = type_28(type_17(_e1258, _e1259), _e1261.member_1, _e1261.member_2, _e1261.member_3, _e1261.member_4, _e1261.member_5, _e1261.member_6, _e1261.member_7, _e1261.member_8, _e1261.member_9, _e1261.member_10, _e1261.member_11, _e1261.member_12, _e1261.member_13, _e1261.member_14, _e1261.member_15, _e1261.member_16, _e1261.member_17);
                                                        } else {
                                                            let _e1205 = local_103;
                                                            if (_e1205 > 0f) {
                                                                let _e1207 = local_48;
                                                                let _e1211 = local_103;
                                                                let _e1212 = local_82;
                                                                let _e1215 = local_48;
                                                                let _e1219 = local_103;
                                                                let _e1220 = local_83;
                                                                let _e1223 = local_48;
                                                                let _e1227 = local_103;
                                                                let _e1228 = local_84;
                                                                let _e1232 = local_103;
                                                                let _e1233 = local_86;
                                                                let _e1236 = local_87;
                                                                phi_1133_ = type_28(type_17(array<f32, 3>((_e1207.member.member[0] + (_e1211 * _e1212)), (_e1215.member.member[1] + (_e1219 * _e1220)), (_e1223.member.member[2] + (_e1227 * _e1228))), (_e1232 * _e1233)), _e1236.member_1, _e1236.member_2, _e1236.member_3, _e1236.member_4, _e1236.member_5, _e1236.member_6, _e1236.member_7, _e1236.member_8, _e1236.member_9, _e1236.member_10, _e1236.member_11, _e1236.member_12, _e1236.member_13, _e1236.member_14, _e1236.member_15, _e1236.member_16, _e1236.member_17);
                                                            } else {
                                                                phi_1133_ = _e882;
                                                            }
                                                            let _e1257 = phi_1133_;
                                                            phi_1134_ = _e1257;
                                                        }
                                                        let _e1282 = phi_1134_;
                                                        phi_1142_ = type_28(_e1282.member, _e1282.member_1, _e1282.member_2, _e1282.member_3, _e1282.member_4, select(2u, 1u, (_e1282.member.member_1 > 0f)), _e1282.member_6, _e1282.member_7, _e1282.member_8, _e1282.member_9, _e1282.member_10, _e1282.member_11, _e1282.member_12, _e1282.member_13, _e1282.member_14, _e1282.member_15, _e1282.member_16, _e1282.member_17);
                                                    } else {
                                                        phi_1142_ = type_28();
                                                    }
                                                    let _e1307 = phi_1142_;
                                                    let _e1308 = local_102;
                                                    phi_1144_ = _e1307;
                                                    phi_1145_ = select(true, false, _e1308);
                                                } else {
                                                    phi_1144_ = type_28();
                                                    phi_1145_ = true;
                                                }
                                                let _e1311 = phi_1144_;
                                                let _e1313 = phi_1145_;
                                                if _e1313 {
                                                    let _e1314 = local_92;
                                                    if _e1314 {
                                                        let _e1315 = local_48;
                                                        let _e1317 = (_e1315.member_5 == 2u);
                                                        local_105 = _e1317;
                                                        if _e1317 {
                                                            let _e1318 = local_48;
                                                            let _e1321 = local_87;
                                                            phi_1160_ = type_28(_e1321.member, _e1321.member_1, _e1321.member_2, _e1321.member_3, _e1321.member_4, _e1321.member_5, _e1321.member_6, _e1321.member_7, _e1321.member_8, _e1321.member_9, _e1321.member_10, _e1321.member_11, _e1321.member_12, _e1321.member_13, _e1321.member_14, _e1321.member_15, (_e1318.member_16 + 1u), _e1321.member_17);
                                                        } else {
                                                            phi_1160_ = type_28();
                                                        }
                                                        let _e1342 = phi_1160_;
                                                        let _e1343 = local_105;
                                                        phi_1162_ = _e1342;
                                                        phi_1163_ = select(true, false, _e1343);
                                                    } else {
                                                        phi_1162_ = type_28();
                                                        phi_1163_ = true;
                                                    }
                                                    let _e1346 = phi_1162_;
                                                    let _e1348 = phi_1163_;
                                                    if _e1348 {
                                                        let _e1349 = local_48;
                                                        let _e1351 = (_e1349.member_5 == 1u);
                                                        local_106 = _e1351;
                                                        if _e1351 {
                                                            let _e1379 = local_48;
                                                            let _e1382 = local_48;
                                                            let _e1384 = local_48;
                                                            let _e1388 = local_88;
                                                            let _e1390 = local_87;
                                                            let _e1409 = type_28(_e1390.member, _e1390.member_1, _e1390.member_2, _e1390.member_3, _e1390.member_4, _e1390.member_5, _e1390.member_6, _e1390.member_7, _e1390.member_8, _e1390.member_9, _e1390.member_10, _e1390.member_11, type_26(_e1388, _e1379.member.member, (1f - _e1384.member.member_1), _e1382.member_6, 0u, 0u), _e1390.member_13, _e1390.member_14, _e1390.member_15, _e1390.member_16, _e1390.member_17);
                                                            let _e1410 = local_48;
                                                            let _e1412 = (_e1410.member_9 + 1u);
                                                            let _e1431 = type_28(_e1409.member, _e1409.member_1, _e1409.member_2, _e1409.member_3, _e1409.member_4, _e1409.member_5, _e1409.member_6, _e1409.member_7, _e1409.member_8, _e1412, _e1409.member_10, _e1409.member_11, _e1409.member_12, _e1409.member_13, _e1409.member_14, _e1409.member_15, _e1409.member_16, _e1409.member_17);
                                                            let _e1450 = type_28(_e1431.member, _e1431.member_1, _e1431.member_2, _e1431.member_3, _e1431.member_4, 3u, _e1431.member_6, _e1431.member_7, _e1431.member_8, _e1431.member_9, _e1431.member_10, _e1431.member_11, _e1431.member_12, _e1431.member_13, _e1431.member_14, _e1431.member_15, _e1431.member_16, _e1431.member_17);
                                                            local_107 = _e1450;
                                                            let _e1451 = local_12;
                                                            let _e1452 = (_e1412 < _e1451);
                                                            if _e1452 {
                                                                let _e1453 = local_98;
                                                                let _e1454 = local_107;
                                                                let _e1473 = type_28(_e1454.member, _e1454.member_1, _e1454.member_2, _e1454.member_3, _e1454.member_4, _e1454.member_5, _e1454.member_6, _e1454.member_7, _e1454.member_8, _e1454.member_9, _e1454.member_10, _e1453, _e1454.member_12, _e1454.member_13, _e1454.member_14, _e1454.member_15, _e1454.member_16, _e1454.member_17);
                                                                phi_1195_ = type_28(_e1473.member, _e1473.member_1, _e1473.member_2, _e1473.member_3, _e1473.member_4, _e1473.member_5, _e1473.member_6, _e1473.member_7, _e1473.member_8, _e1473.member_9, 1u, _e1473.member_11, _e1473.member_12, _e1473.member_13, _e1473.member_14, _e1473.member_15, _e1473.member_16, _e1473.member_17);
                                                            } else {
                                                                phi_1195_ = type_28();
                                                            }
                                                            let _e1494 = phi_1195_;
                                                            phi_1205_ = _e1494;
                                                            phi_1207_ = _e1450;
                                                            phi_1209_ = _e1452;
                                                        } else {
                                                            let _e1352 = local_48;
                                                            let _e1354 = local_12;
                                                            let _e1355 = (_e1352.member_9 < _e1354);
                                                            if _e1355 {
                                                                let _e1356 = local_98;
                                                                let _e1357 = local_87;
                                                                phi_1204_ = type_28(_e1357.member, _e1357.member_1, _e1357.member_2, _e1357.member_3, _e1357.member_4, _e1357.member_5, _e1357.member_6, _e1357.member_7, _e1357.member_8, _e1357.member_9, _e1357.member_10, _e1357.member_11, _e1356, _e1357.member_13, _e1357.member_14, _e1357.member_15, _e1357.member_16, _e1357.member_17);
                                                            } else {
                                                                phi_1204_ = type_28();
                                                            }
                                                            let _e1378 = phi_1204_;
                                                            phi_1205_ = _e1378;
                                                            phi_1207_ = _e882;
                                                            phi_1209_ = _e1355;
                                                        }
                                                        let _e1496 = phi_1205_;
                                                        let _e1498 = phi_1207_;
                                                        let _e1500 = phi_1209_;
                                                        local_108 = _e1496;
                                                        local_109 = _e1498;
                                                        local_110 = _e1500;
                                                        let _e1501 = local_106;
                                                        local_187 = select(0u, 1u, _e1501);
                                                        if _e1500 {
                                                            let _e1503 = local_108;
                                                            let _e1506 = local_108;
                                                            let _e1526 = local_187;
                                                            phi_1217_ = type_28(_e1506.member, _e1506.member_1, _e1506.member_2, _e1506.member_3, _e1506.member_4, _e1506.member_5, _e1506.member_6, _e1506.member_7, _e1506.member_8, (_e1503.member_9 + 1u), _e1506.member_10, _e1506.member_11, _e1506.member_12, _e1506.member_13, _e1506.member_14, _e1506.member_15, _e1506.member_16, _e1506.member_17);
                                                            phi_1218_ = (_e1526 + 1u);
                                                        } else {
                                                            phi_1217_ = type_28();
                                                            phi_1218_ = u32();
                                                        }
                                                        let _e1529 = phi_1217_;
                                                        let _e1531 = phi_1218_;
                                                        local_111 = _e1531;
                                                        let _e1532 = local_110;
                                                        let _e1533 = select(true, false, _e1532);
                                                        local_188 = _e1533;
                                                        if _e1533 {
                                                            let _e1534 = local_109;
                                                            local_112 = type_28(type_17(array<f32, 3>(0f, 0f, 0f), 1f), _e1534.member_1, _e1534.member_2, _e1534.member_3, _e1534.member_4, _e1534.member_5, _e1534.member_6, _e1534.member_7, _e1534.member_8, _e1534.member_9, _e1534.member_10, _e1534.member_11, _e1534.member_12, _e1534.member_13, _e1534.member_14, _e1534.member_15, _e1534.member_16, _e1534.member_17);
                                                            if true {
                                                                let _e1577 = local_85;
                                                                let _e1578 = local_86;
                                                                let _e1580 = local_112;
                                                                phi_1278_ = type_28(type_17(_e1577, _e1578), _e1580.member_1, _e1580.member_2, _e1580.member_3, _e1580.member_4, _e1580.member_5, _e1580.member_6, _e1580.member_7, _e1580.member_8, _e1580.member_9, _e1580.member_10, _e1580.member_11, _e1580.member_12, _e1580.member_13, _e1580.member_14, _e1580.member_15, _e1580.member_16, _e1580.member_17);
                                                            } else {
                                                                let _e1554 = local_85;
                                                                let _e1555 = local_86;
                                                                let _e1557 = local_112;
                                                                phi_1278_ = type_28(type_17(_e1554, _e1555), _e1557.member_1, _e1557.member_2, _e1557.member_3, _e1557.member_4, _e1557.member_5, _e1557.member_6, _e1557.member_7, _e1557.member_8, _e1557.member_9, _e1557.member_10, _e1557.member_11, _e1557.member_12, _e1557.member_13, _e1557.member_14, _e1557.member_15, _e1557.member_16, _e1557.member_17);
                                                            }
                                                            let _e1601 = phi_1278_;
                                                            let _e1602 = local_64;
                                                            let _e1621 = type_28(_e1601.member, _e1601.member_1, _e1601.member_2, _e1601.member_3, _e1601.member_4, _e1601.member_5, _e1602, _e1601.member_7, _e1601.member_8, _e1601.member_9, _e1601.member_10, _e1601.member_11, _e1601.member_12, _e1601.member_13, _e1601.member_14, _e1601.member_15, _e1601.member_16, _e1601.member_17);
                                                            phi_1281_ = type_28(_e1621.member, _e1621.member_1, _e1621.member_2, _e1621.member_3, _e1621.member_4, 2u, _e1621.member_6, _e1621.member_7, _e1621.member_8, _e1621.member_9, _e1621.member_10, _e1621.member_11, _e1621.member_12, _e1621.member_13, _e1621.member_14, _e1621.member_15, _e1621.member_16, _e1621.member_17);
                                                        } else {
                                                            phi_1281_ = _e1529;
                                                        }
                                                        let _e1642 = phi_1281_;
                                                        let _e1643 = local_188;
                                                        let _e1644 = local_187;
                                                        let _e1645 = local_111;
                                                        phi_1283_ = _e1642;
                                                        phi_1284_ = select(_e1645, _e1644, _e1643);
                                                    } else {
                                                        phi_1283_ = _e1346;
                                                        phi_1284_ = 0u;
                                                    }
                                                    let _e1648 = phi_1283_;
                                                    let _e1650 = phi_1284_;
                                                    phi_1285_ = _e1648;
                                                    phi_1286_ = _e1650;
                                                } else {
                                                    phi_1285_ = _e1311;
                                                    phi_1286_ = 0u;
                                                }
                                                let _e1652 = phi_1285_;
                                                let _e1654 = phi_1286_;
                                                phi_1287_ = _e1652;
                                                phi_1288_ = _e1654;
                                            } else {
                                                phi_1287_ = _e1166;
                                                phi_1288_ = 0u;
                                            }
                                            let _e1656 = phi_1287_;
                                            let _e1658 = phi_1288_;
                                            phi_1292_ = _e1656;
                                            phi_1293_ = _e1658;
                                        } else {
                                            let _e604 = local_48;
                                            let _e607 = local_62;
                                            phi_1292_ = type_28(_e607.member, _e607.member_1, _e607.member_2, _e607.member_3, _e607.member_4, _e607.member_5, _e607.member_6, _e607.member_7, _e607.member_8, _e607.member_9, _e607.member_10, _e607.member_11, _e607.member_12, (_e604.member_13 + 1u), _e607.member_14, _e607.member_15, _e607.member_16, _e607.member_17);
                                            phi_1293_ = 0u;
                                        }
                                        let _e1660 = phi_1292_;
                                        let _e1662 = phi_1293_;
                                        local_113 = _e1660;
                                        local_114 = _e1662;
                                        local_115 = _e1660.member_4;
                                        local_116 = _e1660.member_3;
                                        if (_e1660.member_4 == _e1660.member_3) {
                                            let _e1666 = local_113;
                                            let _e1668 = local_115;
                                            if (_e1668 == _e1666.member_2) {
                                                let _e1670 = local_113;
                                                if (_e1670.member_8 > 0u) {
                                                    let _e1673 = local_113;
                                                    if (_e1673.member_7 > 0f) {
                                                        let _e1676 = local_113;
                                                        if (_e1676.member_5 != 1u) {
                                                            let _e1679 = local_116;
                                                            let _e1681 = local_113;
                                                            let _e1700 = type_28(_e1681.member, _e1681.member_1, _e1681.member_2, (_e1679 + 1u), _e1681.member_4, _e1681.member_5, _e1681.member_6, _e1681.member_7, _e1681.member_8, _e1681.member_9, _e1681.member_10, _e1681.member_11, _e1681.member_12, _e1681.member_13, _e1681.member_14, _e1681.member_15, _e1681.member_16, _e1681.member_17);
                                                            phi_1325_ = type_28(_e1700.member, _e1700.member_1, _e1700.member_2, _e1700.member_3, _e1700.member_4, _e1700.member_5, _e1700.member_6, _e1700.member_7, _e1700.member_8, _e1700.member_9, _e1700.member_10, _e1700.member_11, _e1700.member_12, _e1700.member_13, _e1700.member_14, _e1700.member_15, _e1700.member_16, 1u);
                                                        } else {
                                                            phi_1325_ = _e1660;
                                                        }
                                                        let _e1721 = phi_1325_;
                                                        phi_1326_ = _e1721;
                                                    } else {
                                                        phi_1326_ = _e1660;
                                                    }
                                                    let _e1723 = phi_1326_;
                                                    phi_1327_ = _e1723;
                                                } else {
                                                    phi_1327_ = _e1660;
                                                }
                                                let _e1725 = phi_1327_;
                                                phi_1328_ = _e1725;
                                            } else {
                                                phi_1328_ = _e1660;
                                            }
                                            let _e1727 = phi_1328_;
                                            phi_1329_ = _e1727;
                                        } else {
                                            phi_1329_ = _e1660;
                                        }
                                        let _e1729 = phi_1329_;
                                        let _e1730 = local_114;
                                        let _e1731 = (_e1730 > 0u);
                                        phi_1335_ = _e1729;
                                        phi_1336_ = select(true, false, _e1731);
                                        phi_1337_ = _e1731;
                                    } else {
                                        phi_1335_ = type_28();
                                        phi_1336_ = false;
                                        phi_1337_ = false;
                                    }
                                    let _e1734 = phi_1335_;
                                    let _e1736 = phi_1336_;
                                    let _e1738 = phi_1337_;
                                    local_117 = _e1736;
                                    continue;
                                    continuing {
                                        let _e1739 = local_117;
                                        phi_433_ = _e1734;
                                        phi_2331_ = _e413;
                                        phi_2253_ = _e1738;
                                        phi_2251_ = _e1734;
                                        break if !(_e1739);
                                    }
                                }
                                let _e1742 = phi_2331_;
                                let _e1744 = phi_2253_;
                                let _e1746 = phi_2251_;
                                local_184 = _e1744;
                                phi_2474_ = _e1742;
                                phi_2255_ = type_28();
                                if _e1742 {
                                    break;
                                }
                                let _e1747 = local_184;
                                let _e1748 = select(true, false, _e1747);
                                local_189 = _e1748;
                                if _e1748 {
                                    let _e2489 = local_193;
                                    phi_1345_ = _e2489;
                                } else {
                                    phi_1345_ = _e1746;
                                }
                                let _e1750 = phi_1345_;
                                let _e1751 = local_189;
                                phi_2468_ = _e1742;
                                phi_401_ = _e1750;
                                phi_1350_ = select(true, false, _e1751);
                            } else {
                                let _e425 = local_39;
                                let _e444 = type_28(_e425.member, _e425.member_1, _e425.member_2, _e425.member_3, _e425.member_4, _e425.member_5, _e425.member_6, _e425.member_7, _e425.member_8, _e425.member_9, 0u, _e425.member_11, _e425.member_12, _e425.member_13, _e425.member_14, _e425.member_15, _e425.member_16, _e425.member_17);
                                let _e445 = local_39;
                                phi_2468_ = _e413;
                                phi_401_ = type_28(_e444.member, _e444.member_1, _e444.member_2, _e444.member_3, _e444.member_4, _e444.member_5, _e444.member_6, _e444.member_7, _e444.member_8, _e444.member_9, _e444.member_10, _e444.member_11, _e445.member_11, _e444.member_13, _e444.member_14, _e444.member_15, _e444.member_16, _e444.member_17);
                                phi_1350_ = true;
                            }
                            let _e1754 = phi_2468_;
                            let _e1756 = phi_401_;
                            let _e1758 = phi_1350_;
                            local_40 = _e1756;
                            local_118 = _e1758;
                            if _e1758 {
                                let _e1759 = local_13;
                                if (_e1759 == 1u) {
                                    let _e1761 = local_38;
                                    let _e1762 = local_43;
                                    local_119 = (_e1761 + _e1762);
                                    let _e1764 = local_40;
                                    local_120 = _e1764.member_12.member_1;
                                    local_121 = _e1764.member_12.member_1[0];
                                    if (_e1764.member_12.member_1[0] > 1267650600000000000000000000000f) {
                                        let _e1769 = local_121;
                                        phi_1372_ = select(true, false, (_e1769 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_1372_ = true;
                                    }
                                    let _e1773 = phi_1372_;
                                    if _e1773 {
                                        let _e1774 = local_121;
                                        if (_e1774 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e1776 = local_121;
                                            phi_1386_ = select(true, false, (_e1776 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_1386_ = true;
                                        }
                                        let _e1780 = phi_1386_;
                                        let _e1781 = local_121;
                                        phi_1391_ = select(0f, _e1781, _e1780);
                                    } else {
                                        phi_1391_ = 1267650600000000000000000000000f;
                                    }
                                    let _e1784 = phi_1391_;
                                    local_122 = _e1784;
                                    let _e1785 = local_120;
                                    local_123 = _e1785[1];
                                    if (_e1785[1] > 1267650600000000000000000000000f) {
                                        let _e1788 = local_123;
                                        phi_1402_ = select(true, false, (_e1788 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_1402_ = true;
                                    }
                                    let _e1792 = phi_1402_;
                                    if _e1792 {
                                        let _e1793 = local_123;
                                        if (_e1793 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e1795 = local_123;
                                            phi_1416_ = select(true, false, (_e1795 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_1416_ = true;
                                        }
                                        let _e1799 = phi_1416_;
                                        let _e1800 = local_123;
                                        phi_1421_ = select(0f, _e1800, _e1799);
                                    } else {
                                        phi_1421_ = 1267650600000000000000000000000f;
                                    }
                                    let _e1803 = phi_1421_;
                                    local_124 = _e1803;
                                    let _e1804 = local_120;
                                    local_125 = _e1804[2];
                                    if (_e1804[2] > 1267650600000000000000000000000f) {
                                        let _e1807 = local_125;
                                        phi_1432_ = select(true, false, (_e1807 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_1432_ = true;
                                    }
                                    let _e1811 = phi_1432_;
                                    if _e1811 {
                                        let _e1812 = local_125;
                                        if (_e1812 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e1814 = local_125;
                                            phi_1446_ = select(true, false, (_e1814 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_1446_ = true;
                                        }
                                        let _e1818 = phi_1446_;
                                        let _e1819 = local_125;
                                        phi_1451_ = select(0f, _e1819, _e1818);
                                    } else {
                                        phi_1451_ = 1267650600000000000000000000000f;
                                    }
                                    let _e1822 = phi_1451_;
                                    let _e1823 = local_122;
                                    let _e1824 = local_124;
                                    local_191 = array<f32, 3>(_e1823, _e1824, _e1822);
                                    let _e1827 = local_191[0u];
                                    let _e1829 = local_191[1u];
                                    if (_e1827 > _e1829) {
                                        let _e1832 = local_191[0u];
                                        phi_1469_ = _e1832;
                                    } else {
                                        let _e1831 = local_191[1u];
                                        phi_1469_ = _e1831;
                                    }
                                    let _e1834 = phi_1469_;
                                    let _e1836 = local_191[2u];
                                    if (_e1834 > _e1836) {
                                        phi_1478_ = _e1834;
                                    } else {
                                        let _e1838 = local_191[2u];
                                        phi_1478_ = _e1838;
                                    }
                                    let _e1840 = phi_1478_;
                                    local_126 = _e1840;
                                    if (_e1840 >= 0.0000000000000000000000000000000000962965f) {
                                        let _e1842 = local_126;
                                        local_192 = array<u32, 3>(0u, 0u, 0u);
                                        phi_2447_ = _e1754;
                                        phi_1493_ = 0i;
                                        phi_1496_ = (bitcast<i32>(((bitcast<u32>(_e1842) >> bitcast<u32>(23i)) & 255u)) - 127i);
                                        loop {
                                            let _e1850 = phi_2447_;
                                            let _e1852 = phi_1493_;
                                            let _e1854 = phi_1496_;
                                            local_127 = _e1852;
                                            local_128 = _e1854;
                                            let _e1855 = local_127;
                                            if (_e1855 < 2i) {
                                                let _e1857 = local_128;
                                                local_129 = bitcast<f32>((bitcast<u32>((140i - _e1857)) << bitcast<u32>(23i)));
                                                phi_1510_ = 0u;
                                                phi_1513_ = 0u;
                                                loop {
                                                    let _e1864 = phi_1510_;
                                                    let _e1866 = phi_1513_;
                                                    local_130 = _e1864;
                                                    local_131 = _e1866;
                                                    let _e1867 = local_130;
                                                    let _e1868 = (_e1867 < 3u);
                                                    local_132 = _e1868;
                                                    if _e1868 {
                                                        let _e1869 = local_132;
                                                        if _e1869 {
                                                        } else {
                                                            phi_2443_ = true;
                                                            break;
                                                        }
                                                        let _e1870 = local_130;
                                                        let _e1872 = local_191[_e1870];
                                                        let _e1873 = local_129;
                                                        local_133 = ((_e1872 * _e1873) + 0.5f);
                                                        let _e1876 = local_132;
                                                        if _e1876 {
                                                        } else {
                                                            phi_2443_ = true;
                                                            break;
                                                        }
                                                        let _e1877 = local_130;
                                                        let _e1879 = local_133;
                                                        let _e1881 = local_133;
                                                        let _e1884 = local_133;
                                                        local_192[_e1877] = select(select(u32(_e1879), 0u, !((_e1881 >= 0f))), 4294967295u, (_e1884 > 4294967000f));
                                                        let _e1888 = local_132;
                                                        if _e1888 {
                                                        } else {
                                                            phi_2443_ = true;
                                                            break;
                                                        }
                                                        let _e1889 = local_192[_e1877];
                                                        let _e1890 = local_131;
                                                        if (_e1889 > _e1890) {
                                                            let _e1892 = local_132;
                                                            if _e1892 {
                                                            } else {
                                                                phi_2443_ = true;
                                                                break;
                                                            }
                                                            let _e1893 = local_192[_e1877];
                                                            phi_1561_ = _e1893;
                                                        } else {
                                                            phi_1561_ = _e1866;
                                                        }
                                                        let _e1895 = phi_1561_;
                                                        let _e1896 = local_130;
                                                        phi_1511_ = (_e1896 + 1u);
                                                        phi_1514_ = _e1895;
                                                    } else {
                                                        phi_1511_ = u32();
                                                        phi_1514_ = u32();
                                                    }
                                                    let _e1899 = phi_1511_;
                                                    let _e1901 = phi_1514_;
                                                    continue;
                                                    continuing {
                                                        let _e1902 = local_132;
                                                        phi_1510_ = _e1899;
                                                        phi_1513_ = _e1901;
                                                        phi_2443_ = _e1850;
                                                        break if !(_e1902);
                                                    }
                                                }
                                                let _e1905 = phi_2443_;
                                                phi_2471_ = _e1905;
                                                if _e1905 {
                                                    break;
                                                }
                                                let _e1906 = local_131;
                                                let _e1907 = (_e1906 <= 16383u);
                                                local_134 = _e1907;
                                                if _e1907 {
                                                    phi_1569_ = i32();
                                                    phi_1570_ = i32();
                                                } else {
                                                    let _e1908 = local_128;
                                                    let _e1910 = local_127;
                                                    phi_1569_ = (_e1910 + 1i);
                                                    phi_1570_ = (_e1908 + 1i);
                                                }
                                                let _e1913 = phi_1569_;
                                                let _e1915 = phi_1570_;
                                                let _e1916 = local_134;
                                                phi_2472_ = _e1905;
                                                phi_1494_ = _e1913;
                                                phi_1497_ = _e1915;
                                                phi_1572_ = select(true, false, _e1916);
                                            } else {
                                                phi_2472_ = _e1850;
                                                phi_1494_ = i32();
                                                phi_1497_ = i32();
                                                phi_1572_ = false;
                                            }
                                            let _e1919 = phi_2472_;
                                            let _e1921 = phi_1494_;
                                            let _e1923 = phi_1497_;
                                            let _e1925 = phi_1572_;
                                            local_135 = _e1925;
                                            continue;
                                            continuing {
                                                let _e1926 = local_135;
                                                phi_2447_ = _e1919;
                                                phi_1493_ = _e1921;
                                                phi_1496_ = _e1923;
                                                phi_2471_ = _e1919;
                                                break if !(_e1926);
                                            }
                                        }
                                        let _e1929 = phi_2471_;
                                        phi_2474_ = _e1929;
                                        phi_2255_ = type_28();
                                        if _e1929 {
                                            break;
                                        }
                                        let _e1930 = local_128;
                                        let _e1933 = local_192;
                                        phi_2488_ = _e1929;
                                        phi_1586_ = type_29(array<u32, 3>(_e1933[0], _e1933[1], _e1933[2]), bitcast<u32>((_e1930 + 127i)));
                                    } else {
                                        phi_2488_ = _e1754;
                                        phi_1586_ = type_29(array<u32, 3>(0u, 0u, 0u), 0u);
                                    }
                                    let _e1940 = phi_2488_;
                                    let _e1942 = phi_1586_;
                                    local_136 = _e1942.member_1;
                                    let _e1950 = local_40;
                                    local_137 = _e1950.member_12.member_4;
                                    local_138 = ((_e1942.member[0] | (_e1942.member[1] << bitcast<u32>(14u))) | ((_e1950.member_12.member_4 & 3u) << bitcast<u32>(28i)));
                                    local_139 = _e1942.member[2];
                                    let _e1958 = local_40;
                                    local_140 = _e1958.member_12.member_2;
                                    if (_e1958.member_12.member_2 > 1f) {
                                        phi_1608_ = 1f;
                                    } else {
                                        let _e1962 = local_140;
                                        let _e1964 = local_140;
                                        phi_1608_ = select(0f, _e1964, (_e1962 > 0f));
                                    }
                                    let _e1967 = phi_1608_;
                                    let _e1969 = ((_e1967 * 1023f) + 0.5f);
                                    let _e1978 = local_139;
                                    let _e1980 = local_136;
                                    local_141 = ((_e1978 | (select(select(u32(_e1969), 0u, !((_e1969 >= 0f))), 4294967295u, (_e1969 > 4294967000f)) << bitcast<u32>(14u))) | (_e1980 << bitcast<u32>(24i)));
                                    let _e1984 = local_40;
                                    local_142 = _e1984.member_12.member_3;
                                    local_143 = bitcast<u32>(_e1984.member_12.member_3);
                                    let _e1988 = local_40;
                                    let _e1993 = local_40;
                                    local_144 = ((_e1988.member_12.member[0] & 65535u) | (_e1993.member_12.member[1] << bitcast<u32>(16i)));
                                    let _e2000 = local_119;
                                    let _e2001 = (4u * _e2000);
                                    local_145 = _e2001;
                                    let _e2002 = local_5;
                                    if (_e2001 < _e2002) {
                                    } else {
                                        phi_2474_ = true;
                                        phi_2255_ = type_28();
                                        break;
                                    }
                                    let _e2004 = local_145;
                                    let _e2007 = local_138;
                                    atomicStore((&global_8.member[_e2004]), _e2007);
                                    let _e2008 = local_145;
                                    let _e2009 = (_e2008 + 1u);
                                    local_146 = _e2009;
                                    let _e2010 = local_5;
                                    if (_e2009 < _e2010) {
                                    } else {
                                        phi_2474_ = true;
                                        phi_2255_ = type_28();
                                        break;
                                    }
                                    let _e2012 = local_146;
                                    let _e2015 = local_141;
                                    atomicStore((&global_8.member[_e2012]), _e2015);
                                    let _e2016 = local_145;
                                    let _e2017 = (_e2016 + 2u);
                                    local_147 = _e2017;
                                    let _e2018 = local_5;
                                    if (_e2017 < _e2018) {
                                    } else {
                                        phi_2474_ = true;
                                        phi_2255_ = type_28();
                                        break;
                                    }
                                    let _e2020 = local_147;
                                    let _e2023 = local_143;
                                    atomicStore((&global_8.member[_e2020]), _e2023);
                                    let _e2024 = local_145;
                                    let _e2025 = (_e2024 + 3u);
                                    local_148 = _e2025;
                                    let _e2026 = local_5;
                                    if (_e2025 < _e2026) {
                                    } else {
                                        phi_2474_ = true;
                                        phi_2255_ = type_28();
                                        break;
                                    }
                                    let _e2028 = local_148;
                                    let _e2031 = local_144;
                                    atomicStore((&global_8.member[_e2028]), _e2031);
                                    let _e2032 = local_18;
                                    let _e2035 = ((_e2032 >> bitcast<u32>(8u)) & 7u);
                                    local_149 = _e2035;
                                    if (_e2035 > 0u) {
                                        let _e2037 = local_40;
                                        local_150 = _e2037.member_12.member_5;
                                        if (_e2037.member_12.member_5 != 0u) {
                                            let _e2041 = local_149;
                                            let _e2042 = local_149;
                                            let _e2043 = (_e2041 * _e2042);
                                            local_151 = _e2043;
                                            if (_e2043 <= 1u) {
                                                phi_1713_ = 1u;
                                            } else {
                                                let _e2045 = local_151;
                                                phi_1713_ = select(16u, 4u, (_e2045 <= 4u));
                                            }
                                            let _e2049 = phi_1713_;
                                            local_152 = _e2049;
                                            if (_e2049 == 0u) {
                                                phi_2474_ = true;
                                                phi_2255_ = type_28();
                                                break;
                                            }
                                            let _e2051 = local_152;
                                            local_153 = (32u / _e2051);
                                            let _e2053 = local_152;
                                            if (_e2053 >= 32u) {
                                                phi_1726_ = 4294967295u;
                                            } else {
                                                let _e2055 = local_152;
                                                phi_1726_ = ((1u << bitcast<u32>((_e2055 & 31u))) - 1u);
                                            }
                                            let _e2061 = phi_1726_;
                                            local_154 = _e2061;
                                            let _e2062 = local_16;
                                            let _e2063 = local_17;
                                            let _e2065 = local_15;
                                            let _e2067 = local_15;
                                            let _e2069 = local_12;
                                            local_155 = (4u * ((((_e2062 * _e2063) * _e2065) * _e2067) * _e2069));
                                            let _e2072 = local_153;
                                            let _e2073 = (_e2072 == 0u);
                                            local_156 = _e2073;
                                            if _e2073 {
                                                phi_2474_ = true;
                                                phi_2255_ = type_28();
                                                break;
                                            }
                                            let _e2074 = local_119;
                                            let _e2075 = local_153;
                                            let _e2077 = local_155;
                                            local_157 = (_e2077 + (_e2074 / _e2075));
                                            let _e2079 = local_156;
                                            if _e2079 {
                                                phi_2474_ = true;
                                                phi_2255_ = type_28();
                                                break;
                                            }
                                            let _e2080 = local_119;
                                            let _e2081 = local_153;
                                            let _e2083 = local_152;
                                            let _e2085 = local_150;
                                            let _e2086 = local_154;
                                            local_158 = ((_e2085 & _e2086) << bitcast<u32>((((_e2080 % _e2081) * _e2083) & 31u)));
                                            let _e2091 = local_157;
                                            let _e2092 = local_5;
                                            if (_e2091 < _e2092) {
                                            } else {
                                                phi_2474_ = true;
                                                phi_2255_ = type_28();
                                                break;
                                            }
                                            let _e2094 = local_157;
                                            let _e2097 = local_158;
                                            let _e2098 = atomicAdd((&global_8.member[_e2094]), _e2097);
                                        }
                                    }
                                    let _e2099 = local_40;
                                    if (_e2099.member_12.member_5 != 0u) {
                                        phi_1786_ = 1.4142135f;
                                    } else {
                                        let _e2103 = local_137;
                                        phi_1786_ = (0.5f * f32((1u << bitcast<u32>((_e2103 & 31u)))));
                                    }
                                    let _e2110 = phi_1786_;
                                    local_159 = _e2110;
                                    let _e2111 = local_143;
                                    if (_e2111 == 2139095040u) {
                                        let _e2146 = local_20;
                                        let _e2148 = local_19;
                                        let _e2150 = local_21;
                                        let _e2151 = local_19;
                                        let _e2154 = local_22;
                                        phi_1852_ = (0.5f * ((((2f * _e2146) * _e2148) / (_e2150 - _e2151)) * _e2154));
                                    } else {
                                        let _e2113 = local_143;
                                        if (_e2113 == 0u) {
                                            phi_1815_ = false;
                                        } else {
                                            let _e2115 = local_143;
                                            phi_1815_ = (_e2115 <= 2139095040u);
                                        }
                                        let _e2118 = phi_1815_;
                                        if _e2118 {
                                            let _e2119 = local_20;
                                            let _e2121 = local_19;
                                            let _e2123 = local_21;
                                            let _e2124 = local_19;
                                            let _e2127 = local_22;
                                            let _e2128 = ((((2f * _e2119) * _e2121) / (_e2123 - _e2124)) * _e2127);
                                            local_160 = _e2128;
                                            if (_e2128 == 0f) {
                                                phi_1843_ = 0f;
                                            } else {
                                                let _e2130 = local_21;
                                                let _e2131 = local_142;
                                                let _e2134 = local_160;
                                                phi_1843_ = (_e2134 * (1f - (_e2130 / _e2131)));
                                            }
                                            let _e2137 = phi_1843_;
                                            phi_1844_ = _e2137;
                                        } else {
                                            phi_1844_ = _e273;
                                        }
                                        let _e2139 = phi_1844_;
                                        local_161 = _e2139;
                                        if (_e2139 < 0f) {
                                            let _e2141 = local_161;
                                            phi_1850_ = -(_e2141);
                                        } else {
                                            phi_1850_ = _e2139;
                                        }
                                        let _e2144 = phi_1850_;
                                        phi_1852_ = (0.5f * _e2144);
                                    }
                                    let _e2158 = phi_1852_;
                                    let _e2163 = local_159;
                                    let _e2164 = (select(_e2158, 0f, ((bitcast<u32>(_e2158) & 2147483647u) > 2139095040u)) + _e2163);
                                    let _e2165 = local_10;
                                    let _e2167 = local_10;
                                    let _e2169 = local_10;
                                    let _e2170 = select(_e2169, _e2164, (_e2164 < _e2167));
                                    let _e2172 = select(0.5f, _e2170, (_e2170 > 0.5f));
                                    let _e2173 = local_41;
                                    let _e2175 = local_41;
                                    let _e2178 = local_42;
                                    phi_2476_ = _e1940;
                                    phi_1879_ = select(_e2175, _e2172, (_e2172 > _e2173));
                                    phi_1880_ = (_e2178 + select(0u, 1u, (_e2164 > _e2165)));
                                } else {
                                    phi_2476_ = _e1754;
                                    phi_1879_ = _e417;
                                    phi_1880_ = _e419;
                                }
                                let _e2181 = phi_2476_;
                                let _e2183 = phi_1879_;
                                let _e2185 = phi_1880_;
                                let _e2186 = local_43;
                                phi_2475_ = _e2181;
                                phi_404_ = _e2183;
                                phi_406_ = _e2185;
                                phi_408_ = (_e2186 + 1u);
                            } else {
                                phi_2475_ = _e1754;
                                phi_404_ = f32();
                                phi_406_ = u32();
                                phi_408_ = u32();
                            }
                            let _e2189 = phi_2475_;
                            let _e2191 = phi_404_;
                            let _e2193 = phi_406_;
                            let _e2195 = phi_408_;
                            continue;
                            continuing {
                                let _e2196 = local_118;
                                phi_2427_ = _e2189;
                                phi_400_ = _e1756;
                                phi_403_ = _e2191;
                                phi_405_ = _e2193;
                                phi_407_ = _e2195;
                                phi_2474_ = _e2189;
                                phi_2255_ = _e1756;
                                break if !(_e2196);
                            }
                        }
                        let _e2199 = phi_2474_;
                        let _e2201 = phi_2255_;
                        local_185 = _e2201;
                        phi_2495_ = _e2199;
                        if _e2199 {
                            break;
                        }
                        let _e2202 = local_185;
                        local_162 = _e2202.member_5;
                        let _e2204 = (_e2202.member_5 == 1u);
                        local_163 = _e2204;
                        if _e2204 {
                            phi_1889_ = true;
                        } else {
                            let _e2205 = local_162;
                            phi_1889_ = (_e2205 == 2u);
                        }
                        let _e2208 = phi_1889_;
                        if _e2208 {
                            let _e2237 = local_185;
                            local_164 = _e2237.member.member;
                            let _e2240 = local_185;
                            local_165 = _e2240.member_6;
                            let _e2242 = local_27;
                            let _e2243 = (4u * _e2242);
                            local_166 = _e2243;
                            local_167 = bitcast<u32>(_e2237.member.member[0]);
                            let _e2246 = local_4;
                            if (_e2243 < _e2246) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2248 = local_166;
                            let _e2251 = local_167;
                            global_7.member[_e2248] = _e2251;
                            let _e2252 = local_166;
                            let _e2253 = (_e2252 + 1u);
                            local_168 = _e2253;
                            let _e2254 = local_164;
                            local_169 = bitcast<u32>(_e2254[1]);
                            let _e2257 = local_4;
                            if (_e2253 < _e2257) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2259 = local_168;
                            let _e2262 = local_169;
                            global_7.member[_e2259] = _e2262;
                            let _e2263 = local_166;
                            let _e2264 = (_e2263 + 2u);
                            local_170 = _e2264;
                            let _e2265 = local_164;
                            local_171 = bitcast<u32>(_e2265[2]);
                            let _e2268 = local_4;
                            if (_e2264 < _e2268) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2270 = local_170;
                            let _e2273 = local_171;
                            global_7.member[_e2270] = _e2273;
                            let _e2274 = local_166;
                            let _e2275 = (_e2274 + 3u);
                            local_172 = _e2275;
                            let _e2276 = local_165;
                            local_173 = bitcast<u32>(_e2276);
                            let _e2278 = local_4;
                            if (_e2275 < _e2278) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2280 = local_172;
                            let _e2283 = local_173;
                            global_7.member[_e2280] = _e2283;
                        } else {
                            let _e2209 = local_27;
                            let _e2210 = (4u * _e2209);
                            local_174 = _e2210;
                            let _e2211 = local_4;
                            if (_e2210 < _e2211) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2213 = local_174;
                            global_7.member[_e2213] = 0u;
                            let _e2216 = local_174;
                            let _e2217 = (_e2216 + 1u);
                            local_175 = _e2217;
                            let _e2218 = local_4;
                            if (_e2217 < _e2218) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2220 = local_175;
                            global_7.member[_e2220] = 0u;
                            let _e2223 = local_174;
                            let _e2224 = (_e2223 + 2u);
                            local_176 = _e2224;
                            let _e2225 = local_4;
                            if (_e2224 < _e2225) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2227 = local_176;
                            global_7.member[_e2227] = 0u;
                            let _e2230 = local_174;
                            let _e2231 = (_e2230 + 3u);
                            local_177 = _e2231;
                            let _e2232 = local_4;
                            if (_e2231 < _e2232) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2234 = local_177;
                            global_7.member[_e2234] = 2143289344u;
                        }
                        let _e2284 = local_13;
                        if (_e2284 == 1u) {
                            let _e2286 = local_27;
                            let _e2287 = local_3;
                            if (_e2286 < _e2287) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2289 = local_27;
                            let _e2292 = local_43;
                            global_6.member[_e2289] = _e2292;
                            let _e2293 = local_23;
                            let _e2294 = local_27;
                            let _e2295 = (_e2293 + _e2294);
                            local_178 = _e2295;
                            let _e2296 = local_41;
                            local_179 = bitcast<u32>(_e2296);
                            let _e2298 = local_3;
                            if (_e2295 < _e2298) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2300 = local_178;
                            let _e2303 = local_179;
                            global_6.member[_e2300] = _e2303;
                            let _e2304 = local_42;
                            if (_e2304 > 0u) {
                                let _e2306 = local_6;
                                if (6u < _e2306) {
                                } else {
                                    phi_2495_ = true;
                                    break;
                                }
                                let _e2310 = local_42;
                                let _e2311 = atomicAdd((&global_9.member[6u]), _e2310);
                            }
                        }
                        let _e2312 = local_185;
                        if (_e2312.member_2 == 0u) {
                            let _e2315 = local_6;
                            if (2u < _e2315) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2319 = atomicAdd((&global_9.member[2u]), 1u);
                        }
                        let _e2320 = local_163;
                        if _e2320 {
                            phi_2112_ = true;
                        } else {
                            let _e2321 = local_162;
                            phi_2112_ = (_e2321 == 2u);
                        }
                        let _e2324 = phi_2112_;
                        if _e2324 {
                            let _e2325 = local_6;
                            if (11u < _e2325) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2329 = atomicAdd((&global_9.member[11u]), 1u);
                        }
                        let _e2330 = local_185;
                        if (_e2330.member_17 > 0u) {
                            let _e2333 = local_6;
                            if (21u < _e2333) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2337 = atomicAdd((&global_9.member[21u]), 1u);
                        }
                        let _e2338 = local_185;
                        local_180 = _e2338.member_16;
                        if (_e2338.member_16 > 0u) {
                            let _e2341 = local_6;
                            if (12u < _e2341) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2345 = local_180;
                            let _e2346 = atomicAdd((&global_9.member[12u]), _e2345);
                        }
                        let _e2347 = local_185;
                        local_181 = _e2347.member_13;
                        if (_e2347.member_13 > 0u) {
                            let _e2350 = local_6;
                            if (0u < _e2350) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2354 = local_181;
                            let _e2355 = atomicAdd((&global_9.member[0u]), _e2354);
                        }
                        let _e2356 = local_185;
                        local_182 = _e2356.member_14;
                        if (_e2356.member_14 > 0u) {
                            let _e2359 = local_6;
                            if (1u < _e2359) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2363 = local_182;
                            let _e2364 = atomicAdd((&global_9.member[1u]), _e2363);
                        }
                        let _e2365 = local_185;
                        local_183 = _e2365.member_15;
                        if (_e2365.member_15 > 0u) {
                            let _e2368 = local_6;
                            if (20u < _e2368) {
                            } else {
                                phi_2495_ = true;
                                break;
                            }
                            let _e2372 = local_183;
                            let _e2373 = atomicAdd((&global_9.member[20u]), _e2372);
                        }
                        phi_2497_ = _e2199;
                    } else {
                        phi_2497_ = _e334;
                    }
                    let _e2375 = phi_2497_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e2376 = local_25;
                    let _e2377 = local_24;
                    phi_2496_ = _e2375;
                    phi_271_ = (_e2376 + _e2377);
                } else {
                    phi_2496_ = _e334;
                    phi_271_ = u32();
                }
                let _e2380 = phi_2496_;
                let _e2382 = phi_271_;
                continue;
                continuing {
                    let _e2383 = local_26;
                    phi_2430_ = _e2380;
                    phi_270_ = _e2382;
                    phi_2495_ = _e2380;
                    break if !(_e2383);
                }
            }
            let _e2386 = phi_2495_;
            if _e2386 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn splat_pack(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
