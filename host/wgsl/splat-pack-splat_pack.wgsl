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
    member_11: u32,
    member_12: type_26,
    member_13: type_26,
    member_14: u32,
    member_15: u32,
    member_16: u32,
    member_17: u32,
    member_18: u32,
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
    var local_86: type_28;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: u32;
    var local_91: u32;
    var local_92: u32;
    var local_93: f32;
    var local_94: u32;
    var local_95: f32;
    var local_96: bool;
    var local_97: bool;
    var local_98: bool;
    var local_99: f32;
    var local_100: u32;
    var local_101: u32;
    var local_102: f32;
    var local_103: bool;
    var local_104: f32;
    var local_105: type_28;
    var local_106: array<u32, 2>;
    var local_107: type_26;
    var local_108: u32;
    var local_109: f32;
    var local_110: f32;
    var local_111: bool;
    var local_112: bool;
    var local_113: f32;
    var local_114: bool;
    var local_115: bool;
    var local_116: f32;
    var local_117: bool;
    var local_118: bool;
    var local_119: bool;
    var local_120: type_28;
    var local_121: type_28;
    var local_122: type_28;
    var local_123: bool;
    var local_124: u32;
    var local_125: type_28;
    var local_126: type_28;
    var local_127: u32;
    var local_128: u32;
    var local_129: u32;
    var local_130: bool;
    var local_131: bool;
    var local_132: u32;
    var local_133: array<f32, 3>;
    var local_134: f32;
    var local_135: f32;
    var local_136: f32;
    var local_137: f32;
    var local_138: f32;
    var local_139: f32;
    var local_140: i32;
    var local_141: i32;
    var local_142: f32;
    var local_143: u32;
    var local_144: u32;
    var local_145: bool;
    var local_146: f32;
    var local_147: bool;
    var local_148: bool;
    var local_149: u32;
    var local_150: u32;
    var local_151: u32;
    var local_152: u32;
    var local_153: f32;
    var local_154: u32;
    var local_155: f32;
    var local_156: u32;
    var local_157: u32;
    var local_158: u32;
    var local_159: u32;
    var local_160: u32;
    var local_161: u32;
    var local_162: u32;
    var local_163: u32;
    var local_164: u32;
    var local_165: u32;
    var local_166: u32;
    var local_167: u32;
    var local_168: u32;
    var local_169: bool;
    var local_170: u32;
    var local_171: u32;
    var local_172: f32;
    var local_173: f32;
    var local_174: f32;
    var local_175: u32;
    var local_176: bool;
    var local_177: array<f32, 3>;
    var local_178: f32;
    var local_179: u32;
    var local_180: u32;
    var local_181: u32;
    var local_182: u32;
    var local_183: u32;
    var local_184: u32;
    var local_185: u32;
    var local_186: u32;
    var local_187: u32;
    var local_188: u32;
    var local_189: u32;
    var local_190: u32;
    var local_191: u32;
    var local_192: u32;
    var local_193: u32;
    var local_194: u32;
    var local_195: u32;
    var local_196: u32;
    var local_197: bool;
    var local_198: type_28;
    var local_199: bool;
    var local_200: f32;
    var local_201: u32;
    var local_202: bool;
    var local_203: bool;
    var local_204: f32;
    var local_205: array<f32, 3>;
    var local_206: array<u32, 3>;
    var phi_2562_: bool;
    var phi_273_: u32;
    var phi_2559_: bool;
    var phi_404_: type_28;
    var phi_407_: f32;
    var phi_409_: u32;
    var phi_411_: u32;
    var phi_437_: type_28;
    var phi_548_: type_20;
    var phi_581_: bool;
    var phi_582_: bool;
    var phi_584_: bool;
    var phi_585_: bool;
    var phi_586_: bool;
    var phi_587_: bool;
    var phi_601_: bool;
    var phi_617_: f32;
    var phi_628_: bool;
    var phi_642_: bool;
    var phi_647_: f32;
    var phi_658_: bool;
    var phi_672_: bool;
    var phi_677_: f32;
    var phi_688_: bool;
    var phi_702_: bool;
    var phi_707_: f32;
    var phi_2393_: bool;
    var phi_2403_: bool;
    var phi_2413_: bool;
    var phi_720_: bool;
    var phi_722_: bool;
    var phi_723_: bool;
    var phi_743_: bool;
    var phi_757_: bool;
    var phi_762_: f32;
    var phi_773_: bool;
    var phi_787_: bool;
    var phi_792_: f32;
    var phi_803_: bool;
    var phi_817_: bool;
    var phi_822_: f32;
    var phi_906_: u32;
    var phi_942_: u32;
    var phi_973_: type_17;
    var phi_974_: type_17;
    var phi_976_: type_17;
    var phi_977_: type_17;
    var phi_978_: bool;
    var phi_979_: type_17;
    var phi_980_: type_17;
    var phi_981_: bool;
    var phi_982_: bool;
    var phi_987_: type_17;
    var phi_992_: type_17;
    var phi_999_: f32;
    var phi_1000_: array<f32, 3>;
    var phi_1001_: u32;
    var phi_1002_: u32;
    var phi_1003_: f32;
    var phi_1004_: array<f32, 3>;
    var phi_1006_: bool;
    var phi_1012_: array<f32, 3>;
    var phi_1066_: bool;
    var phi_1094_: f32;
    var phi_1095_: f32;
    var phi_1101_: f32;
    var phi_1103_: f32;
    var phi_1149_: bool;
    var phi_1151_: bool;
    var phi_1152_: bool;
    var phi_1153_: bool;
    var phi_1154_: bool;
    var phi_1184_: type_28;
    var phi_1185_: type_28;
    var phi_1193_: type_28;
    var phi_1195_: type_28;
    var phi_1196_: bool;
    var phi_1226_: bool;
    var phi_1228_: bool;
    var phi_1229_: bool;
    var phi_1230_: bool;
    var phi_1231_: bool;
    var phi_1261_: type_28;
    var phi_1262_: type_28;
    var phi_1270_: type_28;
    var phi_1272_: type_28;
    var phi_1273_: bool;
    var phi_1288_: type_28;
    var phi_1290_: type_28;
    var phi_1291_: bool;
    var phi_1332_: type_28;
    var phi_1323_: type_28;
    var phi_1333_: type_28;
    var phi_1335_: type_28;
    var phi_1337_: bool;
    var phi_1345_: type_28;
    var phi_1346_: u32;
    var phi_1406_: type_28;
    var phi_1409_: type_28;
    var phi_1411_: type_28;
    var phi_1412_: u32;
    var phi_1413_: type_28;
    var phi_1414_: u32;
    var phi_1415_: type_28;
    var phi_1416_: u32;
    var phi_1420_: type_28;
    var phi_1421_: u32;
    var phi_1453_: type_28;
    var phi_1454_: type_28;
    var phi_1455_: type_28;
    var phi_1456_: type_28;
    var phi_1457_: type_28;
    var phi_1463_: type_28;
    var phi_1464_: bool;
    var phi_1465_: bool;
    var phi_2459_: bool;
    var phi_2381_: bool;
    var phi_2379_: type_28;
    var phi_1473_: type_28;
    var phi_2607_: bool;
    var phi_405_: type_28;
    var phi_1478_: bool;
    var phi_1500_: bool;
    var phi_1514_: bool;
    var phi_1519_: f32;
    var phi_1530_: bool;
    var phi_1544_: bool;
    var phi_1549_: f32;
    var phi_1560_: bool;
    var phi_1574_: bool;
    var phi_1579_: f32;
    var phi_1597_: f32;
    var phi_1606_: f32;
    var phi_2586_: bool;
    var phi_1621_: i32;
    var phi_1624_: i32;
    var phi_1638_: u32;
    var phi_1641_: u32;
    var phi_1689_: u32;
    var phi_1639_: u32;
    var phi_1642_: u32;
    var phi_2582_: bool;
    var phi_1697_: i32;
    var phi_1698_: i32;
    var phi_2611_: bool;
    var phi_1622_: i32;
    var phi_1625_: i32;
    var phi_1700_: bool;
    var phi_2610_: bool;
    var phi_2627_: bool;
    var phi_1714_: type_29;
    var phi_1736_: f32;
    var phi_1841_: u32;
    var phi_1854_: u32;
    var phi_1914_: f32;
    var phi_1943_: bool;
    var phi_1971_: f32;
    var phi_1972_: f32;
    var phi_1978_: f32;
    var phi_1980_: f32;
    var phi_2615_: bool;
    var phi_2007_: f32;
    var phi_2008_: u32;
    var phi_2614_: bool;
    var phi_408_: f32;
    var phi_410_: u32;
    var phi_412_: u32;
    var phi_2613_: bool;
    var phi_2383_: type_28;
    var phi_2017_: bool;
    var phi_2240_: bool;
    var phi_2636_: bool;
    var phi_2635_: bool;
    var phi_274_: u32;
    var phi_2634_: bool;
    var local_207: type_28;

    let _e288 = global_10;
    let _e289 = bitcast<f32>(_e288);
    local_204 = _e289;
    let _e290 = global_11;
    switch bitcast<i32>(0u) {
        default: {
            let _e294 = global;
            local = _e294;
            let _e295 = global_1;
            let _e296 = global_2;
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            let _e309 = arrayLength((&global_9.member));
            local_6 = _e309;
            local_7 = _e295.x;
            local_8 = _e296.x;
            let _e312 = global_4.member;
            local_9 = _e312;
            if (18u < _e309) {
            } else {
                break;
            }
            let _e314 = local_6;
            if (19u < _e314) {
            } else {
                break;
            }
            let _e318 = atomicLoad((&global_9.member[19u]));
            local_10 = bitcast<f32>(_e318);
            let _e320 = local_9;
            local_11 = _e320.member;
            let _e322 = local_9;
            let _e324 = local_9;
            local_12 = _e324.member_2;
            let _e326 = local_9;
            local_13 = _e326.member_3;
            let _e328 = local_9;
            local_14 = _e328.member_4;
            let _e330 = local_9;
            local_15 = _e330.member_6;
            let _e332 = local_9;
            local_16 = _e332.member_7;
            let _e334 = local_9;
            local_17 = _e334.member_8;
            let _e336 = local_9;
            local_18 = _e336.member_10;
            let _e338 = local_9;
            local_19 = _e338.member_15.member;
            local_20 = _e338.member_15.member_1;
            local_21 = _e338.member_15.member_2;
            local_22 = _e338.member_15.member_3;
            local_23 = (_e320.member * _e322.member_1);
            let _e345 = local_8;
            local_24 = (_e345 * 256u);
            let _e347 = local_7;
            phi_2562_ = false;
            phi_273_ = (_e347 * 256u);
            loop {
                let _e350 = phi_2562_;
                let _e352 = phi_273_;
                local_25 = _e352;
                let _e353 = local_25;
                let _e354 = local_23;
                let _e355 = (_e353 < _e354);
                local_26 = _e355;
                if _e355 {
                    let _e356 = local_25;
                    let _e357 = local;
                    let _e358 = (_e356 + _e357);
                    local_27 = _e358;
                    let _e359 = local_23;
                    if (_e358 < _e359) {
                        let _e361 = local_27;
                        let _e362 = local_2;
                        if (_e361 < _e362) {
                        } else {
                            phi_2634_ = true;
                            break;
                        }
                        let _e364 = local_27;
                        let _e367 = global_3.member[_e364];
                        let _e368 = local_12;
                        let _e370 = local_12;
                        let _e371 = select(_e370, _e367, (_e367 < _e368));
                        let _e374 = local_27;
                        let _e375 = local_204;
                        let _e377 = local_13;
                        let _e378 = (_e377 == 0u);
                        local_28 = _e378;
                        if _e378 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e379 = local_15;
                        let _e380 = local_13;
                        local_29 = (_e379 / _e380);
                        let _e382 = local_14;
                        let _e383 = (_e382 == 0u);
                        local_30 = _e383;
                        if _e383 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e384 = local_27;
                        let _e385 = local_14;
                        local_31 = (_e384 % _e385);
                        let _e387 = local_30;
                        if _e387 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e388 = local_27;
                        let _e389 = local_14;
                        local_32 = (_e388 / _e389);
                        let _e391 = local_29;
                        let _e392 = (_e391 == 0u);
                        local_33 = _e392;
                        if _e392 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e393 = local_32;
                        let _e394 = local_29;
                        let _e396 = local_16;
                        local_34 = ((_e393 / _e394) * _e396);
                        let _e398 = local_33;
                        if _e398 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e399 = local_31;
                        let _e400 = local_29;
                        let _e402 = local_34;
                        local_35 = (_e402 + (_e399 / _e400));
                        let _e404 = local_33;
                        if _e404 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e405 = local_31;
                        let _e406 = local_29;
                        local_36 = (_e405 % _e406);
                        let _e408 = local_33;
                        if _e408 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e409 = local_32;
                        let _e410 = local_29;
                        local_37 = (_e409 % _e410);
                        let _e412 = local_28;
                        if _e412 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e413 = local_35;
                        let _e414 = local_29;
                        let _e416 = local_37;
                        let _e418 = local_29;
                        let _e420 = local_36;
                        let _e422 = local_12;
                        let _e423 = local_13;
                        let _e425 = local_13;
                        local_38 = (((((_e413 * _e414) + _e416) * _e418) + _e420) * ((_e422 * _e423) * _e425));
                        phi_2559_ = _e350;
                        phi_404_ = type_28(type_17(array<f32, 3>(0f, 0f, 0f), 1f), _e374, _e371, select(_e371, 1u, (_e371 == 0u)), 0u, 0u, _e375, 1f, 0u, 0u, 0u, 0u, type_26(array<u32, 2>(0u, 0u), array<f32, 3>(0f, 0f, 0f), 1f, 0f, 0u, 0u), type_26(array<u32, 2>(0u, 0u), array<f32, 3>(0f, 0f, 0f), 1f, 0f, 0u, 0u), 0u, 0u, 0u, 0u, 0u);
                        phi_407_ = 0f;
                        phi_409_ = 0u;
                        phi_411_ = 0u;
                        loop {
                            let _e429 = phi_2559_;
                            let _e431 = phi_404_;
                            let _e433 = phi_407_;
                            let _e435 = phi_409_;
                            let _e437 = phi_411_;
                            local_39 = _e431;
                            local_41 = _e433;
                            local_42 = _e435;
                            local_43 = _e437;
                            let _e438 = local_39;
                            if (_e438.member_11 == 0u) {
                                let _e484 = local_39;
                                local_44 = _e484.member_1;
                                let _e486 = local_11;
                                let _e487 = (_e486 == 0u);
                                local_45 = _e487;
                                if _e487 {
                                    phi_2613_ = true;
                                    phi_2383_ = type_28();
                                    break;
                                }
                                let _e488 = local_44;
                                let _e489 = local_11;
                                local_46 = (_e488 % _e489);
                                let _e491 = local_45;
                                if _e491 {
                                    phi_2613_ = true;
                                    phi_2383_ = type_28();
                                    break;
                                }
                                let _e492 = local_44;
                                let _e493 = local_11;
                                local_47 = (_e492 / _e493);
                                phi_437_ = _e431;
                                loop {
                                    let _e496 = phi_437_;
                                    local_48 = _e496;
                                    local_207 = _e496;
                                    let _e497 = local_48;
                                    local_49 = _e497.member_4;
                                    let _e499 = local_48;
                                    if (_e497.member_4 < _e499.member_3) {
                                        let _e502 = local_48;
                                        local_50 = _e502.member_2;
                                        let _e504 = local_49;
                                        if (_e504 >= _e502.member_2) {
                                            phi_548_ = type_20(array<f32, 3>(0f, 0f, 0f), bitcast<f32>(_e290), 1f);
                                        } else {
                                            let _e506 = local_48;
                                            let _e508 = local_12;
                                            let _e510 = local_49;
                                            let _e512 = (5u * ((_e506.member_1 * _e508) + _e510));
                                            local_51 = _e512;
                                            let _e513 = local_1;
                                            if (_e512 < _e513) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e515 = local_51;
                                            let _e518 = global_5.member[_e515];
                                            local_52 = bitcast<f32>(_e518);
                                            let _e520 = local_51;
                                            let _e521 = (_e520 + 1u);
                                            local_53 = _e521;
                                            let _e522 = local_1;
                                            if (_e521 < _e522) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e524 = local_53;
                                            let _e527 = global_5.member[_e524];
                                            local_54 = bitcast<f32>(_e527);
                                            let _e529 = local_51;
                                            let _e530 = (_e529 + 2u);
                                            local_55 = _e530;
                                            let _e531 = local_1;
                                            if (_e530 < _e531) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e533 = local_55;
                                            let _e536 = global_5.member[_e533];
                                            let _e538 = local_52;
                                            let _e539 = local_54;
                                            local_56 = array<f32, 3>(_e538, _e539, bitcast<f32>(_e536));
                                            let _e541 = local_51;
                                            let _e542 = (_e541 + 3u);
                                            local_57 = _e542;
                                            let _e543 = local_1;
                                            if (_e542 < _e543) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e545 = local_57;
                                            let _e548 = global_5.member[_e545];
                                            local_58 = bitcast<f32>(_e548);
                                            let _e550 = local_51;
                                            let _e551 = (_e550 + 4u);
                                            local_59 = _e551;
                                            let _e552 = local_1;
                                            if (_e551 < _e552) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e554 = local_59;
                                            let _e557 = global_5.member[_e554];
                                            let _e559 = local_56;
                                            let _e560 = local_58;
                                            phi_548_ = type_20(_e559, _e560, bitcast<f32>(_e557));
                                        }
                                        let _e563 = phi_548_;
                                        local_60 = _e563;
                                        let _e564 = local_49;
                                        let _e565 = (_e564 + 1u);
                                        local_61 = _e565;
                                        let _e566 = local_48;
                                        local_62 = type_28(_e566.member, _e566.member_1, _e566.member_2, _e566.member_3, _e565, _e566.member_5, _e566.member_6, _e566.member_7, _e566.member_8, _e566.member_9, _e566.member_10, _e566.member_11, _e566.member_12, _e566.member_13, _e566.member_14, _e566.member_15, _e566.member_16, _e566.member_17, _e566.member_18);
                                        local_63 = _e563.member;
                                        local_64 = _e563.member_1;
                                        local_65 = _e563.member[0];
                                        let _e590 = bitcast<u32>(_e563.member[0]);
                                        local_66 = _e590;
                                        if ((_e590 & 2139095040u) != 2139095040u) {
                                            let _e593 = local_63;
                                            if ((bitcast<u32>(_e593[1]) & 2139095040u) != 2139095040u) {
                                                let _e598 = local_63;
                                                let _e602 = ((bitcast<u32>(_e598[2]) & 2139095040u) != 2139095040u);
                                                local_67 = _e602;
                                                if _e602 {
                                                    let _e603 = local_64;
                                                    let _e604 = bitcast<u32>(_e603);
                                                    local_68 = _e604;
                                                    if (_e604 == 0u) {
                                                        phi_581_ = false;
                                                    } else {
                                                        let _e606 = local_68;
                                                        phi_581_ = (_e606 <= 2139095040u);
                                                    }
                                                    let _e609 = phi_581_;
                                                    phi_582_ = _e609;
                                                } else {
                                                    phi_582_ = bool();
                                                }
                                                let _e611 = phi_582_;
                                                let _e612 = local_67;
                                                phi_584_ = _e611;
                                                phi_585_ = select(true, false, _e612);
                                            } else {
                                                phi_584_ = bool();
                                                phi_585_ = true;
                                            }
                                            let _e615 = phi_584_;
                                            let _e617 = phi_585_;
                                            phi_586_ = _e615;
                                            phi_587_ = _e617;
                                        } else {
                                            phi_586_ = bool();
                                            phi_587_ = true;
                                        }
                                        let _e619 = phi_586_;
                                        let _e621 = phi_587_;
                                        if select(_e619, false, _e621) {
                                            let _e647 = local_60;
                                            local_69 = _e647.member_2;
                                            let _e649 = (_e647.member_2 >= 0f);
                                            local_70 = _e649;
                                            if _e649 {
                                                let _e650 = local_69;
                                                phi_601_ = (_e650 <= 1f);
                                            } else {
                                                phi_601_ = false;
                                            }
                                            let _e653 = phi_601_;
                                            let _e656 = local_48;
                                            let _e659 = local_62;
                                            local_71 = type_28(_e659.member, _e659.member_1, _e659.member_2, _e659.member_3, _e659.member_4, _e659.member_5, _e659.member_6, _e659.member_7, _e659.member_8, _e659.member_9, _e659.member_10, _e659.member_11, _e659.member_12, _e659.member_13, _e659.member_14, _e659.member_15, (_e656.member_16 + select(0u, 1u, !(_e653))), _e659.member_17, _e659.member_18);
                                            let _e680 = local_69;
                                            if (_e680 > 1f) {
                                                phi_617_ = 1f;
                                            } else {
                                                let _e682 = local_70;
                                                let _e683 = local_69;
                                                phi_617_ = select(0f, _e683, _e682);
                                            }
                                            let _e686 = phi_617_;
                                            local_72 = _e686;
                                            let _e687 = local_65;
                                            let _e688 = (_e687 > 1267650600000000000000000000000f);
                                            local_73 = _e688;
                                            if _e688 {
                                                let _e689 = local_65;
                                                phi_628_ = select(true, false, (_e689 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_628_ = true;
                                            }
                                            let _e693 = phi_628_;
                                            if _e693 {
                                                let _e694 = local_65;
                                                if (_e694 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e696 = local_65;
                                                    phi_642_ = select(true, false, (_e696 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_642_ = true;
                                                }
                                                let _e700 = phi_642_;
                                                let _e701 = local_65;
                                                phi_647_ = select(0f, _e701, _e700);
                                            } else {
                                                phi_647_ = 1267650600000000000000000000000f;
                                            }
                                            let _e704 = phi_647_;
                                            local_74 = _e704;
                                            let _e705 = local_63;
                                            local_75 = _e705[1];
                                            let _e707 = (_e705[1] > 1267650600000000000000000000000f);
                                            local_76 = _e707;
                                            if _e707 {
                                                let _e708 = local_75;
                                                phi_658_ = select(true, false, (_e708 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_658_ = true;
                                            }
                                            let _e712 = phi_658_;
                                            if _e712 {
                                                let _e713 = local_75;
                                                if (_e713 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e715 = local_75;
                                                    phi_672_ = select(true, false, (_e715 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_672_ = true;
                                                }
                                                let _e719 = phi_672_;
                                                let _e720 = local_75;
                                                phi_677_ = select(0f, _e720, _e719);
                                            } else {
                                                phi_677_ = 1267650600000000000000000000000f;
                                            }
                                            let _e723 = phi_677_;
                                            local_77 = _e723;
                                            let _e724 = local_63;
                                            local_78 = _e724[2];
                                            let _e726 = (_e724[2] > 1267650600000000000000000000000f);
                                            local_79 = _e726;
                                            if _e726 {
                                                let _e727 = local_78;
                                                phi_688_ = select(true, false, (_e727 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_688_ = true;
                                            }
                                            let _e731 = phi_688_;
                                            if _e731 {
                                                let _e732 = local_78;
                                                if (_e732 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e734 = local_78;
                                                    phi_702_ = select(true, false, (_e734 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_702_ = true;
                                                }
                                                let _e738 = phi_702_;
                                                let _e739 = local_78;
                                                phi_707_ = select(0f, _e739, _e738);
                                            } else {
                                                phi_707_ = 1267650600000000000000000000000f;
                                            }
                                            let _e742 = phi_707_;
                                            local_80 = _e742;
                                            let _e743 = local_65;
                                            let _e744 = local_74;
                                            if (_e743 == _e744) {
                                                phi_2393_ = true;
                                            } else {
                                                let _e746 = local_66;
                                                phi_2393_ = ((_e746 & 2147483647u) > 2139095040u);
                                            }
                                            let _e750 = phi_2393_;
                                            if _e750 {
                                                let _e751 = local_75;
                                                let _e752 = local_77;
                                                if (_e751 == _e752) {
                                                    phi_2403_ = true;
                                                } else {
                                                    let _e754 = local_75;
                                                    phi_2403_ = ((bitcast<u32>(_e754) & 2147483647u) > 2139095040u);
                                                }
                                                let _e759 = phi_2403_;
                                                local_199 = _e759;
                                                if _e759 {
                                                    let _e760 = local_78;
                                                    let _e761 = local_80;
                                                    if (_e760 == _e761) {
                                                        phi_2413_ = true;
                                                    } else {
                                                        let _e763 = local_78;
                                                        phi_2413_ = ((bitcast<u32>(_e763) & 2147483647u) > 2139095040u);
                                                    }
                                                    let _e768 = phi_2413_;
                                                    phi_720_ = _e768;
                                                } else {
                                                    phi_720_ = bool();
                                                }
                                                let _e770 = phi_720_;
                                                let _e771 = local_199;
                                                phi_722_ = _e770;
                                                phi_723_ = select(true, false, _e771);
                                            } else {
                                                phi_722_ = bool();
                                                phi_723_ = true;
                                            }
                                            let _e774 = phi_722_;
                                            let _e776 = phi_723_;
                                            let _e780 = local_48;
                                            let _e783 = local_71;
                                            local_81 = type_28(_e783.member, _e783.member_1, _e783.member_2, _e783.member_3, _e783.member_4, _e783.member_5, _e783.member_6, _e783.member_7, _e783.member_8, _e783.member_9, _e783.member_10, _e783.member_11, _e783.member_12, _e783.member_13, _e783.member_14, (_e780.member_15 + select(0u, 1u, !(select(_e774, false, _e776)))), _e783.member_16, _e783.member_17, _e783.member_18);
                                            let _e804 = local_73;
                                            if _e804 {
                                                let _e805 = local_65;
                                                phi_743_ = select(true, false, (_e805 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_743_ = true;
                                            }
                                            let _e809 = phi_743_;
                                            if _e809 {
                                                let _e810 = local_65;
                                                if (_e810 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e812 = local_65;
                                                    phi_757_ = select(true, false, (_e812 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_757_ = true;
                                                }
                                                let _e816 = phi_757_;
                                                let _e817 = local_65;
                                                phi_762_ = select(0f, _e817, _e816);
                                            } else {
                                                phi_762_ = 1267650600000000000000000000000f;
                                            }
                                            let _e820 = phi_762_;
                                            local_82 = _e820;
                                            let _e821 = local_76;
                                            if _e821 {
                                                let _e822 = local_75;
                                                phi_773_ = select(true, false, (_e822 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_773_ = true;
                                            }
                                            let _e826 = phi_773_;
                                            if _e826 {
                                                let _e827 = local_75;
                                                if (_e827 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e829 = local_75;
                                                    phi_787_ = select(true, false, (_e829 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_787_ = true;
                                                }
                                                let _e833 = phi_787_;
                                                let _e834 = local_75;
                                                phi_792_ = select(0f, _e834, _e833);
                                            } else {
                                                phi_792_ = 1267650600000000000000000000000f;
                                            }
                                            let _e837 = phi_792_;
                                            local_83 = _e837;
                                            let _e838 = local_79;
                                            if _e838 {
                                                let _e839 = local_78;
                                                phi_803_ = select(true, false, (_e839 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_803_ = true;
                                            }
                                            let _e843 = phi_803_;
                                            if _e843 {
                                                let _e844 = local_78;
                                                if (_e844 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e846 = local_78;
                                                    phi_817_ = select(true, false, (_e846 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_817_ = true;
                                                }
                                                let _e850 = phi_817_;
                                                let _e851 = local_78;
                                                phi_822_ = select(0f, _e851, _e850);
                                            } else {
                                                phi_822_ = 1267650600000000000000000000000f;
                                            }
                                            let _e854 = phi_822_;
                                            local_84 = _e854;
                                            let _e855 = local_82;
                                            let _e856 = local_83;
                                            let _e857 = array<f32, 3>(_e855, _e856, _e854);
                                            local_85 = _e857;
                                            let _e858 = local_48;
                                            let _e861 = local_81;
                                            local_86 = type_28(_e861.member, _e861.member_1, _e861.member_2, _e861.member_3, _e861.member_4, _e861.member_5, _e861.member_6, _e861.member_7, (_e858.member_8 + 1u), _e861.member_9, _e861.member_10, _e861.member_11, _e861.member_12, _e861.member_13, _e861.member_14, _e861.member_15, _e861.member_16, _e861.member_17, _e861.member_18);
                                            let _e882 = local_61;
                                            let _e883 = local_50;
                                            if (_e882 > _e883) {
                                                phi_999_ = _e686;
                                                phi_1000_ = _e857;
                                                phi_1001_ = 0u;
                                                phi_1002_ = u32();
                                                phi_1003_ = f32();
                                                phi_1004_ = array<f32, 3>();
                                                phi_1006_ = true;
                                            } else {
                                                let _e885 = local_48;
                                                local_87 = _e885.member_1;
                                                let _e887 = local_18;
                                                let _e890 = ((_e887 >> bitcast<u32>(8u)) & 7u);
                                                local_88 = _e890;
                                                if (_e890 == 0u) {
                                                    phi_942_ = 0u;
                                                } else {
                                                    let _e892 = local_88;
                                                    let _e893 = local_88;
                                                    let _e894 = (_e892 * _e893);
                                                    local_89 = _e894;
                                                    if (_e894 >= 32u) {
                                                        phi_906_ = 4294967295u;
                                                    } else {
                                                        let _e896 = local_89;
                                                        phi_906_ = ((1u << bitcast<u32>((_e896 & 31u))) - 1u);
                                                    }
                                                    let _e902 = phi_906_;
                                                    local_90 = _e902;
                                                    let _e903 = local_23;
                                                    let _e904 = local_12;
                                                    let _e906 = local_87;
                                                    let _e907 = local_12;
                                                    let _e909 = local_49;
                                                    let _e912 = ((5u * (_e903 * _e904)) + ((_e906 * _e907) + _e909));
                                                    local_91 = _e912;
                                                    let _e913 = local_1;
                                                    if (_e912 < _e913) {
                                                    } else {
                                                        phi_2459_ = true;
                                                        phi_2381_ = bool();
                                                        phi_2379_ = type_28();
                                                        break;
                                                    }
                                                    let _e915 = local_91;
                                                    let _e918 = global_5.member[_e915];
                                                    let _e919 = local_90;
                                                    let _e920 = (_e918 & _e919);
                                                    let _e921 = local_90;
                                                    phi_942_ = select(_e920, 0u, (_e920 == _e921));
                                                }
                                                let _e925 = phi_942_;
                                                local_92 = _e925;
                                                let _e926 = local_48;
                                                local_93 = _e926.member_7;
                                                let _e928 = local_48;
                                                local_94 = (_e925 & ~(_e928.member_9));
                                                let _e932 = (_e925 == 0u);
                                                if _e932 {
                                                    phi_979_ = type_17();
                                                    phi_980_ = type_17();
                                                    phi_981_ = true;
                                                    phi_982_ = false;
                                                } else {
                                                    let _e933 = local_94;
                                                    let _e934 = (_e933 == 0u);
                                                    if _e934 {
                                                        phi_976_ = type_17();
                                                        phi_977_ = type_17();
                                                        phi_978_ = false;
                                                    } else {
                                                        let _e935 = local_93;
                                                        let _e936 = local_72;
                                                        let _e938 = local_92;
                                                        let _e942 = local_94;
                                                        let _e945 = (((_e935 * _e936) * f32(countOneBits(_e938))) / f32(countOneBits(_e942)));
                                                        local_95 = _e945;
                                                        let _e946 = local_72;
                                                        let _e947 = (_e945 < _e946);
                                                        local_96 = _e947;
                                                        if _e947 {
                                                            let _e951 = local_95;
                                                            let _e952 = local_72;
                                                            let _e953 = (_e951 / _e952);
                                                            let _e954 = local_82;
                                                            let _e956 = local_83;
                                                            let _e958 = local_84;
                                                            let _e961 = local_95;
                                                            phi_973_ = type_17(array<f32, 3>((_e954 * _e953), (_e956 * _e953), (_e958 * _e953)), _e961);
                                                            phi_974_ = type_17();
                                                        } else {
                                                            let _e948 = local_85;
                                                            let _e949 = local_72;
                                                            phi_973_ = type_17();
                                                            phi_974_ = type_17(_e948, _e949);
                                                        }
                                                        let _e964 = phi_973_;
                                                        let _e966 = phi_974_;
                                                        let _e967 = local_96;
                                                        phi_976_ = _e964;
                                                        phi_977_ = _e966;
                                                        phi_978_ = select(true, false, _e967);
                                                    }
                                                    let _e970 = phi_976_;
                                                    let _e972 = phi_977_;
                                                    let _e974 = phi_978_;
                                                    phi_979_ = _e970;
                                                    phi_980_ = _e972;
                                                    phi_981_ = _e934;
                                                    phi_982_ = _e974;
                                                }
                                                let _e976 = phi_979_;
                                                let _e978 = phi_980_;
                                                let _e980 = phi_981_;
                                                let _e982 = phi_982_;
                                                local_97 = _e980;
                                                local_98 = _e982;
                                                if _e980 {
                                                    let _e983 = local_85;
                                                    let _e984 = local_72;
                                                    phi_987_ = type_17(_e983, _e984);
                                                } else {
                                                    phi_987_ = _e978;
                                                }
                                                let _e987 = phi_987_;
                                                let _e988 = local_97;
                                                let _e989 = local_98;
                                                if select(_e989, true, _e988) {
                                                    phi_992_ = _e987;
                                                } else {
                                                    phi_992_ = _e976;
                                                }
                                                let _e992 = phi_992_;
                                                phi_999_ = _e992.member_1;
                                                phi_1000_ = _e992.member;
                                                phi_1001_ = _e925;
                                                phi_1002_ = _e925;
                                                phi_1003_ = _e992.member_1;
                                                phi_1004_ = _e992.member;
                                                phi_1006_ = _e932;
                                            }
                                            let _e996 = phi_999_;
                                            let _e998 = phi_1000_;
                                            let _e1000 = phi_1001_;
                                            let _e1002 = phi_1002_;
                                            let _e1004 = phi_1003_;
                                            let _e1006 = phi_1004_;
                                            let _e1008 = phi_1006_;
                                            local_99 = _e996;
                                            local_100 = _e1000;
                                            local_101 = _e1002;
                                            local_102 = _e1004;
                                            local_103 = _e1008;
                                            if _e1008 {
                                                phi_1012_ = _e998;
                                            } else {
                                                phi_1012_ = _e1006;
                                            }
                                            let _e1010 = phi_1012_;
                                            let _e1011 = local_103;
                                            let _e1012 = local_101;
                                            let _e1014 = local_103;
                                            let _e1015 = local_99;
                                            let _e1016 = local_102;
                                            let _e1018 = local_103;
                                            let _e1019 = local_100;
                                            let _e1020 = local_101;
                                            let _e1021 = select(_e1020, _e1019, _e1018);
                                            let _e1022 = local_48;
                                            let _e1025 = local_86;
                                            let _e1045 = type_28(_e1025.member, _e1025.member_1, _e1025.member_2, _e1025.member_3, _e1025.member_4, _e1025.member_5, _e1025.member_6, _e1025.member_7, _e1025.member_8, (_e1022.member_9 | select(_e1012, 4294967295u, _e1011)), _e1025.member_10, _e1025.member_11, _e1025.member_12, _e1025.member_13, _e1025.member_14, _e1025.member_15, _e1025.member_16, _e1025.member_17, _e1025.member_18);
                                            let _e1046 = local_72;
                                            let _e1047 = (1f - _e1046);
                                            local_104 = _e1047;
                                            let _e1048 = local_48;
                                            let _e1070 = type_28(_e1045.member, _e1045.member_1, _e1045.member_2, _e1045.member_3, _e1045.member_4, _e1045.member_5, _e1045.member_6, (_e1048.member_7 * _e1047), _e1045.member_8, _e1045.member_9, _e1045.member_10, _e1045.member_11, _e1045.member_12, _e1045.member_13, _e1045.member_14, _e1045.member_15, _e1045.member_16, _e1045.member_17, _e1045.member_18);
                                            local_105 = _e1070;
                                            let _e1071 = local_46;
                                            let _e1074 = local_47;
                                            let _e1077 = array<u32, 2>(((2u * _e1071) + 1u), ((2u * _e1074) + 1u));
                                            local_106 = _e1077;
                                            let _e1078 = local_64;
                                            local_107 = type_26(_e1077, _e1010, select(_e1016, _e1015, _e1014), _e1078, 0u, _e1021);
                                            local_200 = select(0.5f, 1.4142135f, (_e1021 != 0u));
                                            let _e1082 = local_64;
                                            let _e1083 = bitcast<u32>(_e1082);
                                            local_108 = _e1083;
                                            if (_e1083 == 2139095040u) {
                                                let _e1118 = local_20;
                                                let _e1120 = local_19;
                                                let _e1122 = local_21;
                                                let _e1123 = local_19;
                                                let _e1126 = local_22;
                                                phi_1103_ = (0.5f * ((((2f * _e1118) * _e1120) / (_e1122 - _e1123)) * _e1126));
                                            } else {
                                                let _e1085 = local_108;
                                                if (_e1085 == 0u) {
                                                    phi_1066_ = false;
                                                } else {
                                                    let _e1087 = local_108;
                                                    phi_1066_ = (_e1087 <= 2139095040u);
                                                }
                                                let _e1090 = phi_1066_;
                                                if _e1090 {
                                                    let _e1091 = local_20;
                                                    let _e1093 = local_19;
                                                    let _e1095 = local_21;
                                                    let _e1096 = local_19;
                                                    let _e1099 = local_22;
                                                    let _e1100 = ((((2f * _e1091) * _e1093) / (_e1095 - _e1096)) * _e1099);
                                                    local_109 = _e1100;
                                                    if (_e1100 == 0f) {
                                                        phi_1094_ = 0f;
                                                    } else {
                                                        let _e1102 = local_21;
                                                        let _e1103 = local_64;
                                                        let _e1106 = local_109;
                                                        phi_1094_ = (_e1106 * (1f - (_e1102 / _e1103)));
                                                    }
                                                    let _e1109 = phi_1094_;
                                                    phi_1095_ = _e1109;
                                                } else {
                                                    phi_1095_ = _e289;
                                                }
                                                let _e1111 = phi_1095_;
                                                local_110 = _e1111;
                                                if (_e1111 < 0f) {
                                                    let _e1113 = local_110;
                                                    phi_1101_ = -(_e1113);
                                                } else {
                                                    phi_1101_ = _e1111;
                                                }
                                                let _e1116 = phi_1101_;
                                                phi_1103_ = (0.5f * _e1116);
                                            }
                                            let _e1130 = phi_1103_;
                                            let _e1135 = local_200;
                                            let _e1136 = (select(_e1130, 0f, ((bitcast<u32>(_e1130) & 2147483647u) > 2139095040u)) + _e1135);
                                            let _e1137 = local_10;
                                            let _e1139 = local_10;
                                            let _e1140 = select(_e1139, _e1136, (_e1136 < _e1137));
                                            let _e1143 = (select(0.5f, _e1140, (_e1140 > 0.5f)) <= 1f);
                                            local_111 = _e1143;
                                            if _e1143 {
                                                let _e1144 = local_48;
                                                let _e1146 = (_e1144.member_5 == 0u);
                                                local_112 = _e1146;
                                                if _e1146 {
                                                    let _e1147 = local_48;
                                                    local_113 = _e1147.member.member_1;
                                                    if (_e1147.member.member_1 >= 1f) {
                                                        let _e1151 = local_48;
                                                        if (_e1151.member.member[0] == 0f) {
                                                            let _e1156 = local_48;
                                                            let _e1160 = (_e1156.member.member[1] == 0f);
                                                            local_114 = _e1160;
                                                            if _e1160 {
                                                                let _e1161 = local_48;
                                                                phi_1149_ = (_e1161.member.member[2] == 0f);
                                                            } else {
                                                                phi_1149_ = bool();
                                                            }
                                                            let _e1167 = phi_1149_;
                                                            let _e1168 = local_114;
                                                            phi_1151_ = _e1167;
                                                            phi_1152_ = select(true, false, _e1168);
                                                        } else {
                                                            phi_1151_ = bool();
                                                            phi_1152_ = true;
                                                        }
                                                        let _e1171 = phi_1151_;
                                                        let _e1173 = phi_1152_;
                                                        phi_1153_ = _e1171;
                                                        phi_1154_ = _e1173;
                                                    } else {
                                                        phi_1153_ = bool();
                                                        phi_1154_ = true;
                                                    }
                                                    let _e1175 = phi_1153_;
                                                    let _e1177 = phi_1154_;
                                                    if select(_e1175, false, _e1177) {
                                                        let _e1233 = local_85;
                                                        let _e1234 = local_104;
                                                        let _e1236 = local_105;
                                                        phi_1185_ = type_28(type_17(_e1233, _e1234), _e1236.member_1, _e1236.member_2, _e1236.member_3, _e1236.member_4, _e1236.member_5, _e1236.member_6, _e1236.member_7, _e1236.member_8, _e1236.member_9, _e1236.member_10, _e1236.member_11, _e1236.member_12, _e1236.member_13, _e1236.member_14, _e1236.member_15, _e1236.member_16, _e1236.member_17, _e1236.member_18);
                                                    } else {
                                                        let _e1179 = local_113;
                                                        if (_e1179 > 0f) {
                                                            let _e1181 = local_48;
                                                            let _e1185 = local_113;
                                                            let _e1186 = local_82;
                                                            let _e1189 = local_48;
                                                            let _e1193 = local_113;
                                                            let _e1194 = local_83;
                                                            let _e1197 = local_48;
                                                            let _e1201 = local_113;
                                                            let _e1202 = local_84;
                                                            let _e1206 = local_113;
                                                            let _e1207 = local_104;
                                                            let _e1210 = local_105;
                                                            phi_1184_ = type_28(type_17(array<f32, 3>((_e1181.member.member[0] + (_e1185 * _e1186)), (_e1189.member.member[1] + (_e1193 * _e1194)), (_e1197.member.member[2] + (_e1201 * _e1202))), (_e1206 * _e1207)), _e1210.member_1, _e1210.member_2, _e1210.member_3, _e1210.member_4, _e1210.member_5, _e1210.member_6, _e1210.member_7, _e1210.member_8, _e1210.member_9, _e1210.member_10, _e1210.member_11, _e1210.member_12, _e1210.member_13, _e1210.member_14, _e1210.member_15, _e1210.member_16, _e1210.member_17, _e1210.member_18);
                                                        } else {
                                                            phi_1184_ = _e1070;
                                                        }
                                                        let _e1232 = phi_1184_;
                                                        phi_1185_ = _e1232;
                                                    }
                                                    let _e1258 = phi_1185_;
                                                    let _e1259 = local_64;
                                                    let _e1279 = type_28(_e1258.member, _e1258.member_1, _e1258.member_2, _e1258.member_3, _e1258.member_4, _e1258.member_5, _e1259, _e1258.member_7, _e1258.member_8, _e1258.member_9, _e1258.member_10, _e1258.member_11, _e1258.member_12, _e1258.member_13, _e1258.member_14, _e1258.member_15, _e1258.member_16, _e1258.member_17, _e1258.member_18);
                                                    let _e1280 = local_72;
                                                    phi_1193_ = type_28(_e1279.member, _e1279.member_1, _e1279.member_2, _e1279.member_3, _e1279.member_4, select(1u, 2u, (_e1280 >= 1f)), _e1279.member_6, _e1279.member_7, _e1279.member_8, _e1279.member_9, _e1279.member_10, _e1279.member_11, _e1279.member_12, _e1279.member_13, _e1279.member_14, _e1279.member_15, _e1279.member_16, _e1279.member_17, _e1279.member_18);
                                                } else {
                                                    phi_1193_ = type_28();
                                                }
                                                let _e1304 = phi_1193_;
                                                let _e1305 = local_112;
                                                phi_1195_ = _e1304;
                                                phi_1196_ = select(true, false, _e1305);
                                            } else {
                                                phi_1195_ = type_28();
                                                phi_1196_ = true;
                                            }
                                            let _e1308 = phi_1195_;
                                            let _e1310 = phi_1196_;
                                            if _e1310 {
                                                let _e1311 = local_111;
                                                if _e1311 {
                                                    let _e1312 = local_48;
                                                    let _e1314 = (_e1312.member_5 == 1u);
                                                    local_115 = _e1314;
                                                    if _e1314 {
                                                        let _e1315 = local_48;
                                                        local_116 = _e1315.member.member_1;
                                                        if (_e1315.member.member_1 >= 1f) {
                                                            let _e1319 = local_48;
                                                            if (_e1319.member.member[0] == 0f) {
                                                                let _e1324 = local_48;
                                                                let _e1328 = (_e1324.member.member[1] == 0f);
                                                                local_117 = _e1328;
                                                                if _e1328 {
                                                                    let _e1329 = local_48;
                                                                    phi_1226_ = (_e1329.member.member[2] == 0f);
                                                                } else {
                                                                    phi_1226_ = bool();
                                                                }
                                                                let _e1335 = phi_1226_;
                                                                let _e1336 = local_117;
                                                                phi_1228_ = _e1335;
                                                                phi_1229_ = select(true, false, _e1336);
                                                            } else {
                                                                phi_1228_ = bool();
                                                                phi_1229_ = true;
                                                            }
                                                            let _e1339 = phi_1228_;
                                                            let _e1341 = phi_1229_;
                                                            phi_1230_ = _e1339;
                                                            phi_1231_ = _e1341;
                                                        } else {
                                                            phi_1230_ = bool();
                                                            phi_1231_ = true;
                                                        }
                                                        let _e1343 = phi_1230_;
                                                        let _e1345 = phi_1231_;
                                                        if select(_e1343, false, _e1345) {
                                                            let _e1401 = local_85;
                                                            let _e1402 = local_104;
                                                            let _e1404 = local_105;
                                                            phi_1262_ = type_28(type_17(_e1401, _e1402), _e1404.member_1, _e1404.member_2, _e1404.member_3, _e1404.member_4, _e1404.member_5, _e1404.member_6, _e1404.member_7, _e1404.member_8, _e1404.member_9, _e1404.member_10, _e1404.member_11, _e1404.member_12, _e1404.member_13, _e1404.member_14, _e1404.member_15, _e1404.member_16, _e1404.member_17, _e1404.member_18);
                                                        } else {
                                                            let _e1347 = local_116;
                                                            if (_e1347 > 0f) {
                                                                let _e1349 = local_48;
                                                                let _e1353 = local_116;
                                                                let _e1354 = local_82;
                                                                let _e1357 = local_48;
                                                                let _e1361 = local_116;
                                                                let _e1362 = local_83;
                                                                let _e1365 = local_48;
                                                                let _e1369 = local_116;
                                                                let _e1370 = local_84;
                                                                let _e1374 = local_116;
                                                                let _e1375 = local_104;
                                                                let _e1378 = local_105;
                                                                phi_1261_ = type_28(type_17(array<f32, 3>((_e1349.member.member[0] + (_e1353 * _e1354)), (_e1357.member.member[1] + (_e1361 * _e1362)), (_e1365.member.member[2] + (_e1369 * _e1370))), (_e1374 * _e1375)), _e1378.member_1, _e1378.member_2, _e1378.member_3, _e1378.member_4, _e1378.member_5, _e1378.member_6, _e1378.member_7, _e1378.member_8, _e1378.member_9, _e1378.member_10, _e1378.member_11, _e1378.member_12, _e1378.member_13, _e1378.member_14, _e1378.member_15, _e1378.member_16, _e1378.member_17, _e1378.member_18);
                                                            } else {
                                                                phi_1261_ = _e1070;
                                                            }
                                                            let _e1400 = phi_1261_;
                                                            phi_1262_ = _e1400;
                                                        }
                                                        let _e1426 = phi_1262_;
                                                        phi_1270_ = type_28(_e1426.member, _e1426.member_1, _e1426.member_2, _e1426.member_3, _e1426.member_4, select(2u, 1u, (_e1426.member.member_1 > 0f)), _e1426.member_6, _e1426.member_7, _e1426.member_8, _e1426.member_9, _e1426.member_10, _e1426.member_11, _e1426.member_12, _e1426.member_13, _e1426.member_14, _e1426.member_15, _e1426.member_16, _e1426.member_17, _e1426.member_18);
                                                    } else {
                                                        phi_1270_ = type_28();
                                                    }
                                                    let _e1452 = phi_1270_;
                                                    let _e1453 = local_115;
                                                    phi_1272_ = _e1452;
                                                    phi_1273_ = select(true, false, _e1453);
                                                } else {
                                                    phi_1272_ = type_28();
                                                    phi_1273_ = true;
                                                }
                                                let _e1456 = phi_1272_;
                                                let _e1458 = phi_1273_;
                                                if _e1458 {
                                                    let _e1459 = local_111;
                                                    if _e1459 {
                                                        let _e1460 = local_48;
                                                        let _e1462 = (_e1460.member_5 == 2u);
                                                        local_118 = _e1462;
                                                        if _e1462 {
                                                            let _e1463 = local_48;
                                                            let _e1466 = local_105;
                                                            phi_1288_ = type_28(_e1466.member, _e1466.member_1, _e1466.member_2, _e1466.member_3, _e1466.member_4, _e1466.member_5, _e1466.member_6, _e1466.member_7, _e1466.member_8, _e1466.member_9, _e1466.member_10, _e1466.member_11, _e1466.member_12, _e1466.member_13, _e1466.member_14, _e1466.member_15, _e1466.member_16, (_e1463.member_17 + 1u), _e1466.member_18);
                                                        } else {
                                                            phi_1288_ = type_28();
                                                        }
                                                        let _e1488 = phi_1288_;
                                                        let _e1489 = local_118;
                                                        phi_1290_ = _e1488;
                                                        phi_1291_ = select(true, false, _e1489);
                                                    } else {
                                                        phi_1290_ = type_28();
                                                        phi_1291_ = true;
                                                    }
                                                    let _e1492 = phi_1290_;
                                                    let _e1494 = phi_1291_;
                                                    if _e1494 {
                                                        let _e1495 = local_48;
                                                        let _e1497 = (_e1495.member_5 == 1u);
                                                        local_119 = _e1497;
                                                        if _e1497 {
                                                            let _e1526 = local_48;
                                                            let _e1529 = local_48;
                                                            let _e1531 = local_48;
                                                            let _e1535 = local_106;
                                                            let _e1537 = local_105;
                                                            let _e1557 = type_28(_e1537.member, _e1537.member_1, _e1537.member_2, _e1537.member_3, _e1537.member_4, _e1537.member_5, _e1537.member_6, _e1537.member_7, _e1537.member_8, _e1537.member_9, _e1537.member_10, _e1537.member_11, _e1537.member_12, type_26(_e1535, _e1526.member.member, (1f - _e1531.member.member_1), _e1529.member_6, 0u, 0u), _e1537.member_14, _e1537.member_15, _e1537.member_16, _e1537.member_17, _e1537.member_18);
                                                            let _e1558 = local_48;
                                                            let _e1560 = (_e1558.member_10 + 1u);
                                                            let _e1580 = type_28(_e1557.member, _e1557.member_1, _e1557.member_2, _e1557.member_3, _e1557.member_4, _e1557.member_5, _e1557.member_6, _e1557.member_7, _e1557.member_8, _e1557.member_9, _e1560, _e1557.member_11, _e1557.member_12, _e1557.member_13, _e1557.member_14, _e1557.member_15, _e1557.member_16, _e1557.member_17, _e1557.member_18);
                                                            let _e1600 = type_28(_e1580.member, _e1580.member_1, _e1580.member_2, _e1580.member_3, _e1580.member_4, 3u, _e1580.member_6, _e1580.member_7, _e1580.member_8, _e1580.member_9, _e1580.member_10, _e1580.member_11, _e1580.member_12, _e1580.member_13, _e1580.member_14, _e1580.member_15, _e1580.member_16, _e1580.member_17, _e1580.member_18);
                                                            local_120 = _e1600;
                                                            let _e1601 = local_12;
                                                            let _e1602 = (_e1560 < _e1601);
                                                            if _e1602 {
                                                                let _e1603 = local_107;
                                                                let _e1604 = local_120;
                                                                let _e1624 = type_28(_e1604.member, _e1604.member_1, _e1604.member_2, _e1604.member_3, _e1604.member_4, _e1604.member_5, _e1604.member_6, _e1604.member_7, _e1604.member_8, _e1604.member_9, _e1604.member_10, _e1604.member_11, _e1603, _e1604.member_13, _e1604.member_14, _e1604.member_15, _e1604.member_16, _e1604.member_17, _e1604.member_18);
                                                                phi_1323_ = type_28(_e1624.member, _e1624.member_1, _e1624.member_2, _e1624.member_3, _e1624.member_4, _e1624.member_5, _e1624.member_6, _e1624.member_7, _e1624.member_8, _e1624.member_9, _e1624.member_10, 1u, _e1624.member_12, _e1624.member_13, _e1624.member_14, _e1624.member_15, _e1624.member_16, _e1624.member_17, _e1624.member_18);
                                                            } else {
                                                                phi_1323_ = type_28();
                                                            }
                                                            let _e1646 = phi_1323_;
                                                            phi_1333_ = _e1646;
                                                            phi_1335_ = _e1600;
                                                            phi_1337_ = _e1602;
                                                        } else {
                                                            let _e1498 = local_48;
                                                            let _e1500 = local_12;
                                                            let _e1501 = (_e1498.member_10 < _e1500);
                                                            if _e1501 {
                                                                let _e1502 = local_107;
                                                                let _e1503 = local_105;
                                                                phi_1332_ = type_28(_e1503.member, _e1503.member_1, _e1503.member_2, _e1503.member_3, _e1503.member_4, _e1503.member_5, _e1503.member_6, _e1503.member_7, _e1503.member_8, _e1503.member_9, _e1503.member_10, _e1503.member_11, _e1503.member_12, _e1502, _e1503.member_14, _e1503.member_15, _e1503.member_16, _e1503.member_17, _e1503.member_18);
                                                            } else {
                                                                phi_1332_ = type_28();
                                                            }
                                                            let _e1525 = phi_1332_;
                                                            phi_1333_ = _e1525;
                                                            phi_1335_ = _e1070;
                                                            phi_1337_ = _e1501;
                                                        }
                                                        let _e1648 = phi_1333_;
                                                        let _e1650 = phi_1335_;
                                                        let _e1652 = phi_1337_;
                                                        local_121 = _e1648;
                                                        local_122 = _e1650;
                                                        local_123 = _e1652;
                                                        let _e1653 = local_119;
                                                        local_201 = select(0u, 1u, _e1653);
                                                        if _e1652 {
                                                            let _e1655 = local_121;
                                                            let _e1658 = local_121;
                                                            let _e1679 = local_201;
                                                            phi_1345_ = type_28(_e1658.member, _e1658.member_1, _e1658.member_2, _e1658.member_3, _e1658.member_4, _e1658.member_5, _e1658.member_6, _e1658.member_7, _e1658.member_8, _e1658.member_9, (_e1655.member_10 + 1u), _e1658.member_11, _e1658.member_12, _e1658.member_13, _e1658.member_14, _e1658.member_15, _e1658.member_16, _e1658.member_17, _e1658.member_18);
                                                            phi_1346_ = (_e1679 + 1u);
                                                        } else {
                                                            phi_1345_ = type_28();
                                                            phi_1346_ = u32();
                                                        }
                                                        let _e1682 = phi_1345_;
                                                        let _e1684 = phi_1346_;
                                                        local_124 = _e1684;
                                                        let _e1685 = local_123;
                                                        let _e1686 = select(true, false, _e1685);
                                                        local_202 = _e1686;
                                                        if _e1686 {
                                                            let _e1687 = local_122;
                                                            local_125 = type_28(type_17(array<f32, 3>(0f, 0f, 0f), 1f), _e1687.member_1, _e1687.member_2, _e1687.member_3, _e1687.member_4, _e1687.member_5, _e1687.member_6, _e1687.member_7, _e1687.member_8, _e1687.member_9, _e1687.member_10, _e1687.member_11, _e1687.member_12, _e1687.member_13, _e1687.member_14, _e1687.member_15, _e1687.member_16, _e1687.member_17, _e1687.member_18);
                                                            if true {
                                                                let _e1732 = local_85;
                                                                let _e1733 = local_104;
                                                                let _e1735 = local_125;
                                                                phi_1406_ = type_28(type_17(_e1732, _e1733), _e1735.member_1, _e1735.member_2, _e1735.member_3, _e1735.member_4, _e1735.member_5, _e1735.member_6, _e1735.member_7, _e1735.member_8, _e1735.member_9, _e1735.member_10, _e1735.member_11, _e1735.member_12, _e1735.member_13, _e1735.member_14, _e1735.member_15, _e1735.member_16, _e1735.member_17, _e1735.member_18);
                                                            } else {
                                                                let _e1708 = local_85;
                                                                let _e1709 = local_104;
                                                                let _e1711 = local_125;
                                                                phi_1406_ = type_28(type_17(_e1708, _e1709), _e1711.member_1, _e1711.member_2, _e1711.member_3, _e1711.member_4, _e1711.member_5, _e1711.member_6, _e1711.member_7, _e1711.member_8, _e1711.member_9, _e1711.member_10, _e1711.member_11, _e1711.member_12, _e1711.member_13, _e1711.member_14, _e1711.member_15, _e1711.member_16, _e1711.member_17, _e1711.member_18);
                                                            }
                                                            let _e1757 = phi_1406_;
                                                            let _e1758 = local_64;
                                                            let _e1778 = type_28(_e1757.member, _e1757.member_1, _e1757.member_2, _e1757.member_3, _e1757.member_4, _e1757.member_5, _e1758, _e1757.member_7, _e1757.member_8, _e1757.member_9, _e1757.member_10, _e1757.member_11, _e1757.member_12, _e1757.member_13, _e1757.member_14, _e1757.member_15, _e1757.member_16, _e1757.member_17, _e1757.member_18);
                                                            phi_1409_ = type_28(_e1778.member, _e1778.member_1, _e1778.member_2, _e1778.member_3, _e1778.member_4, 2u, _e1778.member_6, _e1778.member_7, _e1778.member_8, _e1778.member_9, _e1778.member_10, _e1778.member_11, _e1778.member_12, _e1778.member_13, _e1778.member_14, _e1778.member_15, _e1778.member_16, _e1778.member_17, _e1778.member_18);
                                                        } else {
                                                            phi_1409_ = _e1682;
                                                        }
                                                        let _e1800 = phi_1409_;
                                                        let _e1801 = local_202;
                                                        let _e1802 = local_201;
                                                        let _e1803 = local_124;
                                                        phi_1411_ = _e1800;
                                                        phi_1412_ = select(_e1803, _e1802, _e1801);
                                                    } else {
                                                        phi_1411_ = _e1492;
                                                        phi_1412_ = 0u;
                                                    }
                                                    let _e1806 = phi_1411_;
                                                    let _e1808 = phi_1412_;
                                                    phi_1413_ = _e1806;
                                                    phi_1414_ = _e1808;
                                                } else {
                                                    phi_1413_ = _e1456;
                                                    phi_1414_ = 0u;
                                                }
                                                let _e1810 = phi_1413_;
                                                let _e1812 = phi_1414_;
                                                phi_1415_ = _e1810;
                                                phi_1416_ = _e1812;
                                            } else {
                                                phi_1415_ = _e1308;
                                                phi_1416_ = 0u;
                                            }
                                            let _e1814 = phi_1415_;
                                            let _e1816 = phi_1416_;
                                            phi_1420_ = _e1814;
                                            phi_1421_ = _e1816;
                                        } else {
                                            let _e623 = local_48;
                                            let _e626 = local_62;
                                            phi_1420_ = type_28(_e626.member, _e626.member_1, _e626.member_2, _e626.member_3, _e626.member_4, _e626.member_5, _e626.member_6, _e626.member_7, _e626.member_8, _e626.member_9, _e626.member_10, _e626.member_11, _e626.member_12, _e626.member_13, (_e623.member_14 + 1u), _e626.member_15, _e626.member_16, _e626.member_17, _e626.member_18);
                                            phi_1421_ = 0u;
                                        }
                                        let _e1818 = phi_1420_;
                                        let _e1820 = phi_1421_;
                                        local_126 = _e1818;
                                        local_127 = _e1820;
                                        local_128 = _e1818.member_4;
                                        local_129 = _e1818.member_3;
                                        if (_e1818.member_4 == _e1818.member_3) {
                                            let _e1824 = local_126;
                                            let _e1826 = local_128;
                                            if (_e1826 == _e1824.member_2) {
                                                let _e1828 = local_126;
                                                if (_e1828.member_8 > 0u) {
                                                    let _e1831 = local_126;
                                                    if (_e1831.member_7 > 0f) {
                                                        let _e1834 = local_126;
                                                        if (_e1834.member_5 != 1u) {
                                                            let _e1837 = local_129;
                                                            let _e1839 = local_126;
                                                            let _e1859 = type_28(_e1839.member, _e1839.member_1, _e1839.member_2, (_e1837 + 1u), _e1839.member_4, _e1839.member_5, _e1839.member_6, _e1839.member_7, _e1839.member_8, _e1839.member_9, _e1839.member_10, _e1839.member_11, _e1839.member_12, _e1839.member_13, _e1839.member_14, _e1839.member_15, _e1839.member_16, _e1839.member_17, _e1839.member_18);
                                                            phi_1453_ = type_28(_e1859.member, _e1859.member_1, _e1859.member_2, _e1859.member_3, _e1859.member_4, _e1859.member_5, _e1859.member_6, _e1859.member_7, _e1859.member_8, _e1859.member_9, _e1859.member_10, _e1859.member_11, _e1859.member_12, _e1859.member_13, _e1859.member_14, _e1859.member_15, _e1859.member_16, _e1859.member_17, 1u);
                                                        } else {
                                                            phi_1453_ = _e1818;
                                                        }
                                                        let _e1881 = phi_1453_;
                                                        phi_1454_ = _e1881;
                                                    } else {
                                                        phi_1454_ = _e1818;
                                                    }
                                                    let _e1883 = phi_1454_;
                                                    phi_1455_ = _e1883;
                                                } else {
                                                    phi_1455_ = _e1818;
                                                }
                                                let _e1885 = phi_1455_;
                                                phi_1456_ = _e1885;
                                            } else {
                                                phi_1456_ = _e1818;
                                            }
                                            let _e1887 = phi_1456_;
                                            phi_1457_ = _e1887;
                                        } else {
                                            phi_1457_ = _e1818;
                                        }
                                        let _e1889 = phi_1457_;
                                        let _e1890 = local_127;
                                        let _e1891 = (_e1890 > 0u);
                                        phi_1463_ = _e1889;
                                        phi_1464_ = select(true, false, _e1891);
                                        phi_1465_ = _e1891;
                                    } else {
                                        phi_1463_ = type_28();
                                        phi_1464_ = false;
                                        phi_1465_ = false;
                                    }
                                    let _e1894 = phi_1463_;
                                    let _e1896 = phi_1464_;
                                    let _e1898 = phi_1465_;
                                    local_130 = _e1896;
                                    continue;
                                    continuing {
                                        let _e1899 = local_130;
                                        phi_437_ = _e1894;
                                        phi_2459_ = _e429;
                                        phi_2381_ = _e1898;
                                        phi_2379_ = _e1894;
                                        break if !(_e1899);
                                    }
                                }
                                let _e1902 = phi_2459_;
                                let _e1904 = phi_2381_;
                                let _e1906 = phi_2379_;
                                local_197 = _e1904;
                                phi_2613_ = _e1902;
                                phi_2383_ = type_28();
                                if _e1902 {
                                    break;
                                }
                                let _e1907 = local_197;
                                let _e1908 = select(true, false, _e1907);
                                local_203 = _e1908;
                                if _e1908 {
                                    let _e2667 = local_207;
                                    phi_1473_ = _e2667;
                                } else {
                                    phi_1473_ = _e1906;
                                }
                                let _e1910 = phi_1473_;
                                let _e1911 = local_203;
                                phi_2607_ = _e1902;
                                phi_405_ = _e1910;
                                phi_1478_ = select(true, false, _e1911);
                            } else {
                                let _e441 = local_39;
                                let _e461 = type_28(_e441.member, _e441.member_1, _e441.member_2, _e441.member_3, _e441.member_4, _e441.member_5, _e441.member_6, _e441.member_7, _e441.member_8, _e441.member_9, _e441.member_10, 0u, _e441.member_12, _e441.member_13, _e441.member_14, _e441.member_15, _e441.member_16, _e441.member_17, _e441.member_18);
                                let _e462 = local_39;
                                phi_2607_ = _e429;
                                phi_405_ = type_28(_e461.member, _e461.member_1, _e461.member_2, _e461.member_3, _e461.member_4, _e461.member_5, _e461.member_6, _e461.member_7, _e461.member_8, _e461.member_9, _e461.member_10, _e461.member_11, _e461.member_12, _e462.member_12, _e461.member_14, _e461.member_15, _e461.member_16, _e461.member_17, _e461.member_18);
                                phi_1478_ = true;
                            }
                            let _e1914 = phi_2607_;
                            let _e1916 = phi_405_;
                            let _e1918 = phi_1478_;
                            local_40 = _e1916;
                            local_131 = _e1918;
                            if _e1918 {
                                let _e1919 = local_13;
                                if (_e1919 == 1u) {
                                    let _e1921 = local_38;
                                    let _e1922 = local_43;
                                    local_132 = (_e1921 + _e1922);
                                    let _e1924 = local_40;
                                    local_133 = _e1924.member_13.member_1;
                                    local_134 = _e1924.member_13.member_1[0];
                                    if (_e1924.member_13.member_1[0] > 1267650600000000000000000000000f) {
                                        let _e1929 = local_134;
                                        phi_1500_ = select(true, false, (_e1929 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_1500_ = true;
                                    }
                                    let _e1933 = phi_1500_;
                                    if _e1933 {
                                        let _e1934 = local_134;
                                        if (_e1934 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e1936 = local_134;
                                            phi_1514_ = select(true, false, (_e1936 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_1514_ = true;
                                        }
                                        let _e1940 = phi_1514_;
                                        let _e1941 = local_134;
                                        phi_1519_ = select(0f, _e1941, _e1940);
                                    } else {
                                        phi_1519_ = 1267650600000000000000000000000f;
                                    }
                                    let _e1944 = phi_1519_;
                                    local_135 = _e1944;
                                    let _e1945 = local_133;
                                    local_136 = _e1945[1];
                                    if (_e1945[1] > 1267650600000000000000000000000f) {
                                        let _e1948 = local_136;
                                        phi_1530_ = select(true, false, (_e1948 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_1530_ = true;
                                    }
                                    let _e1952 = phi_1530_;
                                    if _e1952 {
                                        let _e1953 = local_136;
                                        if (_e1953 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e1955 = local_136;
                                            phi_1544_ = select(true, false, (_e1955 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_1544_ = true;
                                        }
                                        let _e1959 = phi_1544_;
                                        let _e1960 = local_136;
                                        phi_1549_ = select(0f, _e1960, _e1959);
                                    } else {
                                        phi_1549_ = 1267650600000000000000000000000f;
                                    }
                                    let _e1963 = phi_1549_;
                                    local_137 = _e1963;
                                    let _e1964 = local_133;
                                    local_138 = _e1964[2];
                                    if (_e1964[2] > 1267650600000000000000000000000f) {
                                        let _e1967 = local_138;
                                        phi_1560_ = select(true, false, (_e1967 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_1560_ = true;
                                    }
                                    let _e1971 = phi_1560_;
                                    if _e1971 {
                                        let _e1972 = local_138;
                                        if (_e1972 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e1974 = local_138;
                                            phi_1574_ = select(true, false, (_e1974 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_1574_ = true;
                                        }
                                        let _e1978 = phi_1574_;
                                        let _e1979 = local_138;
                                        phi_1579_ = select(0f, _e1979, _e1978);
                                    } else {
                                        phi_1579_ = 1267650600000000000000000000000f;
                                    }
                                    let _e1982 = phi_1579_;
                                    let _e1983 = local_135;
                                    let _e1984 = local_137;
                                    local_205 = array<f32, 3>(_e1983, _e1984, _e1982);
                                    let _e1987 = local_205[0u];
                                    let _e1989 = local_205[1u];
                                    if (_e1987 > _e1989) {
                                        let _e1992 = local_205[0u];
                                        phi_1597_ = _e1992;
                                    } else {
                                        let _e1991 = local_205[1u];
                                        phi_1597_ = _e1991;
                                    }
                                    let _e1994 = phi_1597_;
                                    let _e1996 = local_205[2u];
                                    if (_e1994 > _e1996) {
                                        phi_1606_ = _e1994;
                                    } else {
                                        let _e1998 = local_205[2u];
                                        phi_1606_ = _e1998;
                                    }
                                    let _e2000 = phi_1606_;
                                    local_139 = _e2000;
                                    if (_e2000 >= 0.0000000000000000000000000000000000962965f) {
                                        let _e2002 = local_139;
                                        local_206 = array<u32, 3>(0u, 0u, 0u);
                                        phi_2586_ = _e1914;
                                        phi_1621_ = 0i;
                                        phi_1624_ = (bitcast<i32>(((bitcast<u32>(_e2002) >> bitcast<u32>(23i)) & 255u)) - 127i);
                                        loop {
                                            let _e2010 = phi_2586_;
                                            let _e2012 = phi_1621_;
                                            let _e2014 = phi_1624_;
                                            local_140 = _e2012;
                                            local_141 = _e2014;
                                            let _e2015 = local_140;
                                            if (_e2015 < 2i) {
                                                let _e2017 = local_141;
                                                local_142 = bitcast<f32>((bitcast<u32>((140i - _e2017)) << bitcast<u32>(23i)));
                                                phi_1638_ = 0u;
                                                phi_1641_ = 0u;
                                                loop {
                                                    let _e2024 = phi_1638_;
                                                    let _e2026 = phi_1641_;
                                                    local_143 = _e2024;
                                                    local_144 = _e2026;
                                                    let _e2027 = local_143;
                                                    let _e2028 = (_e2027 < 3u);
                                                    local_145 = _e2028;
                                                    if _e2028 {
                                                        let _e2029 = local_145;
                                                        if _e2029 {
                                                        } else {
                                                            phi_2582_ = true;
                                                            break;
                                                        }
                                                        let _e2030 = local_143;
                                                        let _e2032 = local_205[_e2030];
                                                        let _e2033 = local_142;
                                                        local_146 = ((_e2032 * _e2033) + 0.5f);
                                                        let _e2036 = local_145;
                                                        if _e2036 {
                                                        } else {
                                                            phi_2582_ = true;
                                                            break;
                                                        }
                                                        let _e2037 = local_143;
                                                        let _e2039 = local_146;
                                                        let _e2041 = local_146;
                                                        let _e2044 = local_146;
                                                        local_206[_e2037] = select(select(u32(_e2039), 0u, !((_e2041 >= 0f))), 4294967295u, (_e2044 > 4294967000f));
                                                        let _e2048 = local_145;
                                                        if _e2048 {
                                                        } else {
                                                            phi_2582_ = true;
                                                            break;
                                                        }
                                                        let _e2049 = local_206[_e2037];
                                                        let _e2050 = local_144;
                                                        if (_e2049 > _e2050) {
                                                            let _e2052 = local_145;
                                                            if _e2052 {
                                                            } else {
                                                                phi_2582_ = true;
                                                                break;
                                                            }
                                                            let _e2053 = local_206[_e2037];
                                                            phi_1689_ = _e2053;
                                                        } else {
                                                            phi_1689_ = _e2026;
                                                        }
                                                        let _e2055 = phi_1689_;
                                                        let _e2056 = local_143;
                                                        phi_1639_ = (_e2056 + 1u);
                                                        phi_1642_ = _e2055;
                                                    } else {
                                                        phi_1639_ = u32();
                                                        phi_1642_ = u32();
                                                    }
                                                    let _e2059 = phi_1639_;
                                                    let _e2061 = phi_1642_;
                                                    continue;
                                                    continuing {
                                                        let _e2062 = local_145;
                                                        phi_1638_ = _e2059;
                                                        phi_1641_ = _e2061;
                                                        phi_2582_ = _e2010;
                                                        break if !(_e2062);
                                                    }
                                                }
                                                let _e2065 = phi_2582_;
                                                phi_2610_ = _e2065;
                                                if _e2065 {
                                                    break;
                                                }
                                                let _e2066 = local_144;
                                                let _e2067 = (_e2066 <= 16383u);
                                                local_147 = _e2067;
                                                if _e2067 {
                                                    phi_1697_ = i32();
                                                    phi_1698_ = i32();
                                                } else {
                                                    let _e2068 = local_141;
                                                    let _e2070 = local_140;
                                                    phi_1697_ = (_e2070 + 1i);
                                                    phi_1698_ = (_e2068 + 1i);
                                                }
                                                let _e2073 = phi_1697_;
                                                let _e2075 = phi_1698_;
                                                let _e2076 = local_147;
                                                phi_2611_ = _e2065;
                                                phi_1622_ = _e2073;
                                                phi_1625_ = _e2075;
                                                phi_1700_ = select(true, false, _e2076);
                                            } else {
                                                phi_2611_ = _e2010;
                                                phi_1622_ = i32();
                                                phi_1625_ = i32();
                                                phi_1700_ = false;
                                            }
                                            let _e2079 = phi_2611_;
                                            let _e2081 = phi_1622_;
                                            let _e2083 = phi_1625_;
                                            let _e2085 = phi_1700_;
                                            local_148 = _e2085;
                                            continue;
                                            continuing {
                                                let _e2086 = local_148;
                                                phi_2586_ = _e2079;
                                                phi_1621_ = _e2081;
                                                phi_1624_ = _e2083;
                                                phi_2610_ = _e2079;
                                                break if !(_e2086);
                                            }
                                        }
                                        let _e2089 = phi_2610_;
                                        phi_2613_ = _e2089;
                                        phi_2383_ = type_28();
                                        if _e2089 {
                                            break;
                                        }
                                        let _e2090 = local_141;
                                        let _e2093 = local_206;
                                        phi_2627_ = _e2089;
                                        phi_1714_ = type_29(array<u32, 3>(_e2093[0], _e2093[1], _e2093[2]), bitcast<u32>((_e2090 + 127i)));
                                    } else {
                                        phi_2627_ = _e1914;
                                        phi_1714_ = type_29(array<u32, 3>(0u, 0u, 0u), 0u);
                                    }
                                    let _e2100 = phi_2627_;
                                    let _e2102 = phi_1714_;
                                    local_149 = _e2102.member_1;
                                    let _e2110 = local_40;
                                    local_150 = _e2110.member_13.member_4;
                                    local_151 = ((_e2102.member[0] | (_e2102.member[1] << bitcast<u32>(14u))) | ((_e2110.member_13.member_4 & 3u) << bitcast<u32>(28i)));
                                    local_152 = _e2102.member[2];
                                    let _e2118 = local_40;
                                    local_153 = _e2118.member_13.member_2;
                                    if (_e2118.member_13.member_2 > 1f) {
                                        phi_1736_ = 1f;
                                    } else {
                                        let _e2122 = local_153;
                                        let _e2124 = local_153;
                                        phi_1736_ = select(0f, _e2124, (_e2122 > 0f));
                                    }
                                    let _e2127 = phi_1736_;
                                    let _e2129 = ((_e2127 * 1023f) + 0.5f);
                                    let _e2138 = local_152;
                                    let _e2140 = local_149;
                                    local_154 = ((_e2138 | (select(select(u32(_e2129), 0u, !((_e2129 >= 0f))), 4294967295u, (_e2129 > 4294967000f)) << bitcast<u32>(14u))) | (_e2140 << bitcast<u32>(24i)));
                                    let _e2144 = local_40;
                                    local_155 = _e2144.member_13.member_3;
                                    local_156 = bitcast<u32>(_e2144.member_13.member_3);
                                    let _e2148 = local_40;
                                    let _e2153 = local_40;
                                    local_157 = ((_e2148.member_13.member[0] & 65535u) | (_e2153.member_13.member[1] << bitcast<u32>(16i)));
                                    let _e2160 = local_132;
                                    let _e2161 = (4u * _e2160);
                                    local_158 = _e2161;
                                    let _e2162 = local_5;
                                    if (_e2161 < _e2162) {
                                    } else {
                                        phi_2613_ = true;
                                        phi_2383_ = type_28();
                                        break;
                                    }
                                    let _e2164 = local_158;
                                    let _e2167 = local_151;
                                    atomicStore((&global_8.member[_e2164]), _e2167);
                                    let _e2168 = local_158;
                                    let _e2169 = (_e2168 + 1u);
                                    local_159 = _e2169;
                                    let _e2170 = local_5;
                                    if (_e2169 < _e2170) {
                                    } else {
                                        phi_2613_ = true;
                                        phi_2383_ = type_28();
                                        break;
                                    }
                                    let _e2172 = local_159;
                                    let _e2175 = local_154;
                                    atomicStore((&global_8.member[_e2172]), _e2175);
                                    let _e2176 = local_158;
                                    let _e2177 = (_e2176 + 2u);
                                    local_160 = _e2177;
                                    let _e2178 = local_5;
                                    if (_e2177 < _e2178) {
                                    } else {
                                        phi_2613_ = true;
                                        phi_2383_ = type_28();
                                        break;
                                    }
                                    let _e2180 = local_160;
                                    let _e2183 = local_156;
                                    atomicStore((&global_8.member[_e2180]), _e2183);
                                    let _e2184 = local_158;
                                    let _e2185 = (_e2184 + 3u);
                                    local_161 = _e2185;
                                    let _e2186 = local_5;
                                    if (_e2185 < _e2186) {
                                    } else {
                                        phi_2613_ = true;
                                        phi_2383_ = type_28();
                                        break;
                                    }
                                    let _e2188 = local_161;
                                    let _e2191 = local_157;
                                    atomicStore((&global_8.member[_e2188]), _e2191);
                                    let _e2192 = local_18;
                                    let _e2195 = ((_e2192 >> bitcast<u32>(8u)) & 7u);
                                    local_162 = _e2195;
                                    if (_e2195 > 0u) {
                                        let _e2197 = local_40;
                                        local_163 = _e2197.member_13.member_5;
                                        if (_e2197.member_13.member_5 != 0u) {
                                            let _e2201 = local_162;
                                            let _e2202 = local_162;
                                            let _e2203 = (_e2201 * _e2202);
                                            local_164 = _e2203;
                                            if (_e2203 <= 1u) {
                                                phi_1841_ = 1u;
                                            } else {
                                                let _e2205 = local_164;
                                                phi_1841_ = select(16u, 4u, (_e2205 <= 4u));
                                            }
                                            let _e2209 = phi_1841_;
                                            local_165 = _e2209;
                                            if (_e2209 == 0u) {
                                                phi_2613_ = true;
                                                phi_2383_ = type_28();
                                                break;
                                            }
                                            let _e2211 = local_165;
                                            local_166 = (32u / _e2211);
                                            let _e2213 = local_165;
                                            if (_e2213 >= 32u) {
                                                phi_1854_ = 4294967295u;
                                            } else {
                                                let _e2215 = local_165;
                                                phi_1854_ = ((1u << bitcast<u32>((_e2215 & 31u))) - 1u);
                                            }
                                            let _e2221 = phi_1854_;
                                            local_167 = _e2221;
                                            let _e2222 = local_16;
                                            let _e2223 = local_17;
                                            let _e2225 = local_15;
                                            let _e2227 = local_15;
                                            let _e2229 = local_12;
                                            local_168 = (4u * ((((_e2222 * _e2223) * _e2225) * _e2227) * _e2229));
                                            let _e2232 = local_166;
                                            let _e2233 = (_e2232 == 0u);
                                            local_169 = _e2233;
                                            if _e2233 {
                                                phi_2613_ = true;
                                                phi_2383_ = type_28();
                                                break;
                                            }
                                            let _e2234 = local_132;
                                            let _e2235 = local_166;
                                            let _e2237 = local_168;
                                            local_170 = (_e2237 + (_e2234 / _e2235));
                                            let _e2239 = local_169;
                                            if _e2239 {
                                                phi_2613_ = true;
                                                phi_2383_ = type_28();
                                                break;
                                            }
                                            let _e2240 = local_132;
                                            let _e2241 = local_166;
                                            let _e2243 = local_165;
                                            let _e2245 = local_163;
                                            let _e2246 = local_167;
                                            local_171 = ((_e2245 & _e2246) << bitcast<u32>((((_e2240 % _e2241) * _e2243) & 31u)));
                                            let _e2251 = local_170;
                                            let _e2252 = local_5;
                                            if (_e2251 < _e2252) {
                                            } else {
                                                phi_2613_ = true;
                                                phi_2383_ = type_28();
                                                break;
                                            }
                                            let _e2254 = local_170;
                                            let _e2257 = local_171;
                                            let _e2258 = atomicAdd((&global_8.member[_e2254]), _e2257);
                                        }
                                    }
                                    let _e2259 = local_40;
                                    if (_e2259.member_13.member_5 != 0u) {
                                        phi_1914_ = 1.4142135f;
                                    } else {
                                        let _e2263 = local_150;
                                        phi_1914_ = (0.5f * f32((1u << bitcast<u32>((_e2263 & 31u)))));
                                    }
                                    let _e2270 = phi_1914_;
                                    local_172 = _e2270;
                                    let _e2271 = local_156;
                                    if (_e2271 == 2139095040u) {
                                        let _e2306 = local_20;
                                        let _e2308 = local_19;
                                        let _e2310 = local_21;
                                        let _e2311 = local_19;
                                        let _e2314 = local_22;
                                        phi_1980_ = (0.5f * ((((2f * _e2306) * _e2308) / (_e2310 - _e2311)) * _e2314));
                                    } else {
                                        let _e2273 = local_156;
                                        if (_e2273 == 0u) {
                                            phi_1943_ = false;
                                        } else {
                                            let _e2275 = local_156;
                                            phi_1943_ = (_e2275 <= 2139095040u);
                                        }
                                        let _e2278 = phi_1943_;
                                        if _e2278 {
                                            let _e2279 = local_20;
                                            let _e2281 = local_19;
                                            let _e2283 = local_21;
                                            let _e2284 = local_19;
                                            let _e2287 = local_22;
                                            let _e2288 = ((((2f * _e2279) * _e2281) / (_e2283 - _e2284)) * _e2287);
                                            local_173 = _e2288;
                                            if (_e2288 == 0f) {
                                                phi_1971_ = 0f;
                                            } else {
                                                let _e2290 = local_21;
                                                let _e2291 = local_155;
                                                let _e2294 = local_173;
                                                phi_1971_ = (_e2294 * (1f - (_e2290 / _e2291)));
                                            }
                                            let _e2297 = phi_1971_;
                                            phi_1972_ = _e2297;
                                        } else {
                                            phi_1972_ = _e289;
                                        }
                                        let _e2299 = phi_1972_;
                                        local_174 = _e2299;
                                        if (_e2299 < 0f) {
                                            let _e2301 = local_174;
                                            phi_1978_ = -(_e2301);
                                        } else {
                                            phi_1978_ = _e2299;
                                        }
                                        let _e2304 = phi_1978_;
                                        phi_1980_ = (0.5f * _e2304);
                                    }
                                    let _e2318 = phi_1980_;
                                    let _e2323 = local_172;
                                    let _e2324 = (select(_e2318, 0f, ((bitcast<u32>(_e2318) & 2147483647u) > 2139095040u)) + _e2323);
                                    let _e2325 = local_10;
                                    let _e2327 = local_10;
                                    let _e2329 = local_10;
                                    let _e2330 = select(_e2329, _e2324, (_e2324 < _e2327));
                                    let _e2332 = select(0.5f, _e2330, (_e2330 > 0.5f));
                                    let _e2333 = local_41;
                                    let _e2335 = local_41;
                                    let _e2338 = local_42;
                                    phi_2615_ = _e2100;
                                    phi_2007_ = select(_e2335, _e2332, (_e2332 > _e2333));
                                    phi_2008_ = (_e2338 + select(0u, 1u, (_e2324 > _e2325)));
                                } else {
                                    phi_2615_ = _e1914;
                                    phi_2007_ = _e433;
                                    phi_2008_ = _e435;
                                }
                                let _e2341 = phi_2615_;
                                let _e2343 = phi_2007_;
                                let _e2345 = phi_2008_;
                                let _e2346 = local_43;
                                phi_2614_ = _e2341;
                                phi_408_ = _e2343;
                                phi_410_ = _e2345;
                                phi_412_ = (_e2346 + 1u);
                            } else {
                                phi_2614_ = _e1914;
                                phi_408_ = f32();
                                phi_410_ = u32();
                                phi_412_ = u32();
                            }
                            let _e2349 = phi_2614_;
                            let _e2351 = phi_408_;
                            let _e2353 = phi_410_;
                            let _e2355 = phi_412_;
                            continue;
                            continuing {
                                let _e2356 = local_131;
                                phi_2559_ = _e2349;
                                phi_404_ = _e1916;
                                phi_407_ = _e2351;
                                phi_409_ = _e2353;
                                phi_411_ = _e2355;
                                phi_2613_ = _e2349;
                                phi_2383_ = _e1916;
                                break if !(_e2356);
                            }
                        }
                        let _e2359 = phi_2613_;
                        let _e2361 = phi_2383_;
                        local_198 = _e2361;
                        phi_2634_ = _e2359;
                        if _e2359 {
                            break;
                        }
                        let _e2362 = local_198;
                        local_175 = _e2362.member_5;
                        let _e2364 = (_e2362.member_5 == 1u);
                        local_176 = _e2364;
                        if _e2364 {
                            phi_2017_ = true;
                        } else {
                            let _e2365 = local_175;
                            phi_2017_ = (_e2365 == 2u);
                        }
                        let _e2368 = phi_2017_;
                        if _e2368 {
                            let _e2397 = local_198;
                            local_177 = _e2397.member.member;
                            let _e2400 = local_198;
                            local_178 = _e2400.member_6;
                            let _e2402 = local_27;
                            let _e2403 = (4u * _e2402);
                            local_179 = _e2403;
                            local_180 = bitcast<u32>(_e2397.member.member[0]);
                            let _e2406 = local_4;
                            if (_e2403 < _e2406) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2408 = local_179;
                            let _e2411 = local_180;
                            global_7.member[_e2408] = _e2411;
                            let _e2412 = local_179;
                            let _e2413 = (_e2412 + 1u);
                            local_181 = _e2413;
                            let _e2414 = local_177;
                            local_182 = bitcast<u32>(_e2414[1]);
                            let _e2417 = local_4;
                            if (_e2413 < _e2417) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2419 = local_181;
                            let _e2422 = local_182;
                            global_7.member[_e2419] = _e2422;
                            let _e2423 = local_179;
                            let _e2424 = (_e2423 + 2u);
                            local_183 = _e2424;
                            let _e2425 = local_177;
                            local_184 = bitcast<u32>(_e2425[2]);
                            let _e2428 = local_4;
                            if (_e2424 < _e2428) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2430 = local_183;
                            let _e2433 = local_184;
                            global_7.member[_e2430] = _e2433;
                            let _e2434 = local_179;
                            let _e2435 = (_e2434 + 3u);
                            local_185 = _e2435;
                            let _e2436 = local_178;
                            local_186 = bitcast<u32>(_e2436);
                            let _e2438 = local_4;
                            if (_e2435 < _e2438) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2440 = local_185;
                            let _e2443 = local_186;
                            global_7.member[_e2440] = _e2443;
                        } else {
                            let _e2369 = local_27;
                            let _e2370 = (4u * _e2369);
                            local_187 = _e2370;
                            let _e2371 = local_4;
                            if (_e2370 < _e2371) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2373 = local_187;
                            global_7.member[_e2373] = 0u;
                            let _e2376 = local_187;
                            let _e2377 = (_e2376 + 1u);
                            local_188 = _e2377;
                            let _e2378 = local_4;
                            if (_e2377 < _e2378) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2380 = local_188;
                            global_7.member[_e2380] = 0u;
                            let _e2383 = local_187;
                            let _e2384 = (_e2383 + 2u);
                            local_189 = _e2384;
                            let _e2385 = local_4;
                            if (_e2384 < _e2385) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2387 = local_189;
                            global_7.member[_e2387] = 0u;
                            let _e2390 = local_187;
                            let _e2391 = (_e2390 + 3u);
                            local_190 = _e2391;
                            let _e2392 = local_4;
                            if (_e2391 < _e2392) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2394 = local_190;
                            global_7.member[_e2394] = 2143289344u;
                        }
                        let _e2444 = local_13;
                        if (_e2444 == 1u) {
                            let _e2446 = local_27;
                            let _e2447 = local_3;
                            if (_e2446 < _e2447) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2449 = local_27;
                            let _e2452 = local_43;
                            global_6.member[_e2449] = _e2452;
                            let _e2453 = local_23;
                            let _e2454 = local_27;
                            let _e2455 = (_e2453 + _e2454);
                            local_191 = _e2455;
                            let _e2456 = local_41;
                            local_192 = bitcast<u32>(_e2456);
                            let _e2458 = local_3;
                            if (_e2455 < _e2458) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2460 = local_191;
                            let _e2463 = local_192;
                            global_6.member[_e2460] = _e2463;
                            let _e2464 = local_42;
                            if (_e2464 > 0u) {
                                let _e2466 = local_6;
                                if (6u < _e2466) {
                                } else {
                                    phi_2634_ = true;
                                    break;
                                }
                                let _e2470 = local_42;
                                let _e2471 = atomicAdd((&global_9.member[6u]), _e2470);
                            }
                        }
                        let _e2472 = local_198;
                        if (_e2472.member_2 == 0u) {
                            let _e2475 = local_6;
                            if (2u < _e2475) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2479 = atomicAdd((&global_9.member[2u]), 1u);
                        }
                        let _e2480 = local_176;
                        if _e2480 {
                            phi_2240_ = true;
                        } else {
                            let _e2481 = local_175;
                            phi_2240_ = (_e2481 == 2u);
                        }
                        let _e2484 = phi_2240_;
                        if _e2484 {
                            let _e2485 = local_6;
                            if (11u < _e2485) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2489 = atomicAdd((&global_9.member[11u]), 1u);
                        }
                        let _e2490 = local_198;
                        if (_e2490.member_18 > 0u) {
                            let _e2493 = local_6;
                            if (21u < _e2493) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2497 = atomicAdd((&global_9.member[21u]), 1u);
                        }
                        let _e2498 = local_198;
                        local_193 = _e2498.member_17;
                        if (_e2498.member_17 > 0u) {
                            let _e2501 = local_6;
                            if (12u < _e2501) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2505 = local_193;
                            let _e2506 = atomicAdd((&global_9.member[12u]), _e2505);
                        }
                        let _e2507 = local_198;
                        local_194 = _e2507.member_14;
                        if (_e2507.member_14 > 0u) {
                            let _e2510 = local_6;
                            if (0u < _e2510) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2514 = local_194;
                            let _e2515 = atomicAdd((&global_9.member[0u]), _e2514);
                        }
                        let _e2516 = local_198;
                        local_195 = _e2516.member_15;
                        if (_e2516.member_15 > 0u) {
                            let _e2519 = local_6;
                            if (1u < _e2519) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2523 = local_195;
                            let _e2524 = atomicAdd((&global_9.member[1u]), _e2523);
                        }
                        let _e2525 = local_198;
                        local_196 = _e2525.member_16;
                        if (_e2525.member_16 > 0u) {
                            let _e2528 = local_6;
                            if (20u < _e2528) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2532 = local_196;
                            let _e2533 = atomicAdd((&global_9.member[20u]), _e2532);
                        }
                        phi_2636_ = _e2359;
                    } else {
                        phi_2636_ = _e350;
                    }
                    let _e2535 = phi_2636_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e2536 = local_25;
                    let _e2537 = local_24;
                    phi_2635_ = _e2535;
                    phi_274_ = (_e2536 + _e2537);
                } else {
                    phi_2635_ = _e350;
                    phi_274_ = u32();
                }
                let _e2540 = phi_2635_;
                let _e2542 = phi_274_;
                continue;
                continuing {
                    let _e2543 = local_26;
                    phi_2562_ = _e2540;
                    phi_273_ = _e2542;
                    phi_2634_ = _e2540;
                    break if !(_e2543);
                }
            }
            let _e2546 = phi_2634_;
            if _e2546 {
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
