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
    var local_104: array<f32, 3>;
    var local_105: f32;
    var local_106: type_28;
    var local_107: u32;
    var local_108: f32;
    var local_109: f32;
    var local_110: bool;
    var local_111: array<u32, 2>;
    var local_112: type_26;
    var local_113: bool;
    var local_114: f32;
    var local_115: bool;
    var local_116: bool;
    var local_117: f32;
    var local_118: bool;
    var local_119: bool;
    var local_120: bool;
    var local_121: type_28;
    var local_122: type_28;
    var local_123: type_28;
    var local_124: bool;
    var local_125: u32;
    var local_126: type_28;
    var local_127: type_28;
    var local_128: u32;
    var local_129: u32;
    var local_130: u32;
    var local_131: bool;
    var local_132: bool;
    var local_133: u32;
    var local_134: array<f32, 3>;
    var local_135: f32;
    var local_136: f32;
    var local_137: f32;
    var local_138: f32;
    var local_139: f32;
    var local_140: f32;
    var local_141: i32;
    var local_142: i32;
    var local_143: f32;
    var local_144: u32;
    var local_145: u32;
    var local_146: bool;
    var local_147: f32;
    var local_148: bool;
    var local_149: bool;
    var local_150: u32;
    var local_151: u32;
    var local_152: u32;
    var local_153: u32;
    var local_154: f32;
    var local_155: u32;
    var local_156: f32;
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
    var local_169: u32;
    var local_170: bool;
    var local_171: u32;
    var local_172: u32;
    var local_173: f32;
    var local_174: f32;
    var local_175: f32;
    var local_176: u32;
    var local_177: bool;
    var local_178: array<f32, 3>;
    var local_179: f32;
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
    var local_197: u32;
    var local_198: bool;
    var local_199: type_28;
    var local_200: bool;
    var local_201: f32;
    var local_202: u32;
    var local_203: u32;
    var local_204: bool;
    var local_205: bool;
    var local_206: f32;
    var local_207: array<f32, 3>;
    var local_208: array<u32, 3>;
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
    var phi_1060_: bool;
    var phi_1088_: f32;
    var phi_1089_: f32;
    var phi_1095_: f32;
    var phi_1097_: f32;
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
    var local_209: type_28;

    let _e290 = global_10;
    let _e291 = bitcast<f32>(_e290);
    local_206 = _e291;
    let _e292 = global_11;
    switch bitcast<i32>(0u) {
        default: {
            let _e296 = global;
            local = _e296;
            let _e297 = global_1;
            let _e298 = global_2;
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            let _e311 = arrayLength((&global_9.member));
            local_6 = _e311;
            local_7 = _e297.x;
            local_8 = _e298.x;
            let _e314 = global_4.member;
            local_9 = _e314;
            if (18u < _e311) {
            } else {
                break;
            }
            let _e316 = local_6;
            if (19u < _e316) {
            } else {
                break;
            }
            let _e320 = atomicLoad((&global_9.member[19u]));
            local_10 = bitcast<f32>(_e320);
            let _e322 = local_9;
            local_11 = _e322.member;
            let _e324 = local_9;
            let _e326 = local_9;
            local_12 = _e326.member_2;
            let _e328 = local_9;
            local_13 = _e328.member_3;
            let _e330 = local_9;
            local_14 = _e330.member_4;
            let _e332 = local_9;
            local_15 = _e332.member_6;
            let _e334 = local_9;
            local_16 = _e334.member_7;
            let _e336 = local_9;
            local_17 = _e336.member_8;
            let _e338 = local_9;
            local_18 = _e338.member_10;
            let _e340 = local_9;
            local_19 = _e340.member_15.member;
            local_20 = _e340.member_15.member_1;
            local_21 = _e340.member_15.member_2;
            local_22 = _e340.member_15.member_3;
            local_23 = (_e322.member * _e324.member_1);
            let _e347 = local_8;
            local_24 = (_e347 * 256u);
            let _e349 = local_7;
            phi_2562_ = false;
            phi_273_ = (_e349 * 256u);
            loop {
                let _e352 = phi_2562_;
                let _e354 = phi_273_;
                local_25 = _e354;
                let _e355 = local_25;
                let _e356 = local_23;
                let _e357 = (_e355 < _e356);
                local_26 = _e357;
                if _e357 {
                    let _e358 = local_25;
                    let _e359 = local;
                    let _e360 = (_e358 + _e359);
                    local_27 = _e360;
                    let _e361 = local_23;
                    if (_e360 < _e361) {
                        let _e363 = local_27;
                        let _e364 = local_2;
                        if (_e363 < _e364) {
                        } else {
                            phi_2634_ = true;
                            break;
                        }
                        let _e366 = local_27;
                        let _e369 = global_3.member[_e366];
                        let _e370 = local_12;
                        let _e372 = local_12;
                        let _e373 = select(_e372, _e369, (_e369 < _e370));
                        let _e376 = local_27;
                        let _e377 = local_206;
                        let _e379 = local_13;
                        let _e380 = (_e379 == 0u);
                        local_28 = _e380;
                        if _e380 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e381 = local_15;
                        let _e382 = local_13;
                        local_29 = (_e381 / _e382);
                        let _e384 = local_14;
                        let _e385 = (_e384 == 0u);
                        local_30 = _e385;
                        if _e385 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e386 = local_27;
                        let _e387 = local_14;
                        local_31 = (_e386 % _e387);
                        let _e389 = local_30;
                        if _e389 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e390 = local_27;
                        let _e391 = local_14;
                        local_32 = (_e390 / _e391);
                        let _e393 = local_29;
                        let _e394 = (_e393 == 0u);
                        local_33 = _e394;
                        if _e394 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e395 = local_32;
                        let _e396 = local_29;
                        let _e398 = local_16;
                        local_34 = ((_e395 / _e396) * _e398);
                        let _e400 = local_33;
                        if _e400 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e401 = local_31;
                        let _e402 = local_29;
                        let _e404 = local_34;
                        local_35 = (_e404 + (_e401 / _e402));
                        let _e406 = local_33;
                        if _e406 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e407 = local_31;
                        let _e408 = local_29;
                        local_36 = (_e407 % _e408);
                        let _e410 = local_33;
                        if _e410 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e411 = local_32;
                        let _e412 = local_29;
                        local_37 = (_e411 % _e412);
                        let _e414 = local_28;
                        if _e414 {
                            phi_2634_ = true;
                            break;
                        }
                        let _e415 = local_35;
                        let _e416 = local_29;
                        let _e418 = local_37;
                        let _e420 = local_29;
                        let _e422 = local_36;
                        let _e424 = local_12;
                        let _e425 = local_13;
                        let _e427 = local_13;
                        local_38 = (((((_e415 * _e416) + _e418) * _e420) + _e422) * ((_e424 * _e425) * _e427));
                        phi_2559_ = _e352;
                        phi_404_ = type_28(type_17(array<f32, 3>(0f, 0f, 0f), 1f), _e376, _e373, select(_e373, 1u, (_e373 == 0u)), 0u, 0u, _e377, 1f, 0u, 0u, 0u, 0u, type_26(array<u32, 2>(0u, 0u), array<f32, 3>(0f, 0f, 0f), 1f, 0f, 0u, 0u), type_26(array<u32, 2>(0u, 0u), array<f32, 3>(0f, 0f, 0f), 1f, 0f, 0u, 0u), 0u, 0u, 0u, 0u, 0u);
                        phi_407_ = 0f;
                        phi_409_ = 0u;
                        phi_411_ = 0u;
                        loop {
                            let _e431 = phi_2559_;
                            let _e433 = phi_404_;
                            let _e435 = phi_407_;
                            let _e437 = phi_409_;
                            let _e439 = phi_411_;
                            local_39 = _e433;
                            local_41 = _e435;
                            local_42 = _e437;
                            local_43 = _e439;
                            let _e440 = local_39;
                            if (_e440.member_11 == 0u) {
                                let _e486 = local_39;
                                local_44 = _e486.member_1;
                                let _e488 = local_11;
                                let _e489 = (_e488 == 0u);
                                local_45 = _e489;
                                if _e489 {
                                    phi_2613_ = true;
                                    phi_2383_ = type_28();
                                    break;
                                }
                                let _e490 = local_44;
                                let _e491 = local_11;
                                local_46 = (_e490 % _e491);
                                let _e493 = local_45;
                                if _e493 {
                                    phi_2613_ = true;
                                    phi_2383_ = type_28();
                                    break;
                                }
                                let _e494 = local_44;
                                let _e495 = local_11;
                                local_47 = (_e494 / _e495);
                                phi_437_ = _e433;
                                loop {
                                    let _e498 = phi_437_;
                                    local_48 = _e498;
                                    local_209 = _e498;
                                    let _e499 = local_48;
                                    local_49 = _e499.member_4;
                                    let _e501 = local_48;
                                    if (_e499.member_4 < _e501.member_3) {
                                        let _e504 = local_48;
                                        local_50 = _e504.member_2;
                                        let _e506 = local_49;
                                        if (_e506 >= _e504.member_2) {
                                            phi_548_ = type_20(array<f32, 3>(0f, 0f, 0f), bitcast<f32>(_e292), 1f);
                                        } else {
                                            let _e508 = local_48;
                                            let _e510 = local_12;
                                            let _e512 = local_49;
                                            let _e514 = (5u * ((_e508.member_1 * _e510) + _e512));
                                            local_51 = _e514;
                                            let _e515 = local_1;
                                            if (_e514 < _e515) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e517 = local_51;
                                            let _e520 = global_5.member[_e517];
                                            local_52 = bitcast<f32>(_e520);
                                            let _e522 = local_51;
                                            let _e523 = (_e522 + 1u);
                                            local_53 = _e523;
                                            let _e524 = local_1;
                                            if (_e523 < _e524) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e526 = local_53;
                                            let _e529 = global_5.member[_e526];
                                            local_54 = bitcast<f32>(_e529);
                                            let _e531 = local_51;
                                            let _e532 = (_e531 + 2u);
                                            local_55 = _e532;
                                            let _e533 = local_1;
                                            if (_e532 < _e533) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e535 = local_55;
                                            let _e538 = global_5.member[_e535];
                                            let _e540 = local_52;
                                            let _e541 = local_54;
                                            local_56 = array<f32, 3>(_e540, _e541, bitcast<f32>(_e538));
                                            let _e543 = local_51;
                                            let _e544 = (_e543 + 3u);
                                            local_57 = _e544;
                                            let _e545 = local_1;
                                            if (_e544 < _e545) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e547 = local_57;
                                            let _e550 = global_5.member[_e547];
                                            local_58 = bitcast<f32>(_e550);
                                            let _e552 = local_51;
                                            let _e553 = (_e552 + 4u);
                                            local_59 = _e553;
                                            let _e554 = local_1;
                                            if (_e553 < _e554) {
                                            } else {
                                                phi_2459_ = true;
                                                phi_2381_ = bool();
                                                phi_2379_ = type_28();
                                                break;
                                            }
                                            let _e556 = local_59;
                                            let _e559 = global_5.member[_e556];
                                            let _e561 = local_56;
                                            let _e562 = local_58;
                                            phi_548_ = type_20(_e561, _e562, bitcast<f32>(_e559));
                                        }
                                        let _e565 = phi_548_;
                                        local_60 = _e565;
                                        let _e566 = local_49;
                                        let _e567 = (_e566 + 1u);
                                        local_61 = _e567;
                                        let _e568 = local_48;
                                        local_62 = type_28(_e568.member, _e568.member_1, _e568.member_2, _e568.member_3, _e567, _e568.member_5, _e568.member_6, _e568.member_7, _e568.member_8, _e568.member_9, _e568.member_10, _e568.member_11, _e568.member_12, _e568.member_13, _e568.member_14, _e568.member_15, _e568.member_16, _e568.member_17, _e568.member_18);
                                        local_63 = _e565.member;
                                        local_64 = _e565.member_1;
                                        local_65 = _e565.member[0];
                                        let _e592 = bitcast<u32>(_e565.member[0]);
                                        local_66 = _e592;
                                        if ((_e592 & 2139095040u) != 2139095040u) {
                                            let _e595 = local_63;
                                            if ((bitcast<u32>(_e595[1]) & 2139095040u) != 2139095040u) {
                                                let _e600 = local_63;
                                                let _e604 = ((bitcast<u32>(_e600[2]) & 2139095040u) != 2139095040u);
                                                local_67 = _e604;
                                                if _e604 {
                                                    let _e605 = local_64;
                                                    let _e606 = bitcast<u32>(_e605);
                                                    local_68 = _e606;
                                                    if (_e606 == 0u) {
                                                        phi_581_ = false;
                                                    } else {
                                                        let _e608 = local_68;
                                                        phi_581_ = (_e608 <= 2139095040u);
                                                    }
                                                    let _e611 = phi_581_;
                                                    phi_582_ = _e611;
                                                } else {
                                                    phi_582_ = bool();
                                                }
                                                let _e613 = phi_582_;
                                                let _e614 = local_67;
                                                phi_584_ = _e613;
                                                phi_585_ = select(true, false, _e614);
                                            } else {
                                                phi_584_ = bool();
                                                phi_585_ = true;
                                            }
                                            let _e617 = phi_584_;
                                            let _e619 = phi_585_;
                                            phi_586_ = _e617;
                                            phi_587_ = _e619;
                                        } else {
                                            phi_586_ = bool();
                                            phi_587_ = true;
                                        }
                                        let _e621 = phi_586_;
                                        let _e623 = phi_587_;
                                        if select(_e621, false, _e623) {
                                            let _e649 = local_60;
                                            local_69 = _e649.member_2;
                                            let _e651 = (_e649.member_2 >= 0f);
                                            local_70 = _e651;
                                            if _e651 {
                                                let _e652 = local_69;
                                                phi_601_ = (_e652 <= 1f);
                                            } else {
                                                phi_601_ = false;
                                            }
                                            let _e655 = phi_601_;
                                            let _e658 = local_48;
                                            let _e661 = local_62;
                                            local_71 = type_28(_e661.member, _e661.member_1, _e661.member_2, _e661.member_3, _e661.member_4, _e661.member_5, _e661.member_6, _e661.member_7, _e661.member_8, _e661.member_9, _e661.member_10, _e661.member_11, _e661.member_12, _e661.member_13, _e661.member_14, _e661.member_15, (_e658.member_16 + select(0u, 1u, !(_e655))), _e661.member_17, _e661.member_18);
                                            let _e682 = local_69;
                                            if (_e682 > 1f) {
                                                phi_617_ = 1f;
                                            } else {
                                                let _e684 = local_70;
                                                let _e685 = local_69;
                                                phi_617_ = select(0f, _e685, _e684);
                                            }
                                            let _e688 = phi_617_;
                                            local_72 = _e688;
                                            let _e689 = local_65;
                                            let _e690 = (_e689 > 1267650600000000000000000000000f);
                                            local_73 = _e690;
                                            if _e690 {
                                                let _e691 = local_65;
                                                phi_628_ = select(true, false, (_e691 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_628_ = true;
                                            }
                                            let _e695 = phi_628_;
                                            if _e695 {
                                                let _e696 = local_65;
                                                if (_e696 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e698 = local_65;
                                                    phi_642_ = select(true, false, (_e698 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_642_ = true;
                                                }
                                                let _e702 = phi_642_;
                                                let _e703 = local_65;
                                                phi_647_ = select(0f, _e703, _e702);
                                            } else {
                                                phi_647_ = 1267650600000000000000000000000f;
                                            }
                                            let _e706 = phi_647_;
                                            local_74 = _e706;
                                            let _e707 = local_63;
                                            local_75 = _e707[1];
                                            let _e709 = (_e707[1] > 1267650600000000000000000000000f);
                                            local_76 = _e709;
                                            if _e709 {
                                                let _e710 = local_75;
                                                phi_658_ = select(true, false, (_e710 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_658_ = true;
                                            }
                                            let _e714 = phi_658_;
                                            if _e714 {
                                                let _e715 = local_75;
                                                if (_e715 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e717 = local_75;
                                                    phi_672_ = select(true, false, (_e717 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_672_ = true;
                                                }
                                                let _e721 = phi_672_;
                                                let _e722 = local_75;
                                                phi_677_ = select(0f, _e722, _e721);
                                            } else {
                                                phi_677_ = 1267650600000000000000000000000f;
                                            }
                                            let _e725 = phi_677_;
                                            local_77 = _e725;
                                            let _e726 = local_63;
                                            local_78 = _e726[2];
                                            let _e728 = (_e726[2] > 1267650600000000000000000000000f);
                                            local_79 = _e728;
                                            if _e728 {
                                                let _e729 = local_78;
                                                phi_688_ = select(true, false, (_e729 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_688_ = true;
                                            }
                                            let _e733 = phi_688_;
                                            if _e733 {
                                                let _e734 = local_78;
                                                if (_e734 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e736 = local_78;
                                                    phi_702_ = select(true, false, (_e736 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_702_ = true;
                                                }
                                                let _e740 = phi_702_;
                                                let _e741 = local_78;
                                                phi_707_ = select(0f, _e741, _e740);
                                            } else {
                                                phi_707_ = 1267650600000000000000000000000f;
                                            }
                                            let _e744 = phi_707_;
                                            local_80 = _e744;
                                            let _e745 = local_65;
                                            let _e746 = local_74;
                                            if (_e745 == _e746) {
                                                phi_2393_ = true;
                                            } else {
                                                let _e748 = local_66;
                                                phi_2393_ = ((_e748 & 2147483647u) > 2139095040u);
                                            }
                                            let _e752 = phi_2393_;
                                            if _e752 {
                                                let _e753 = local_75;
                                                let _e754 = local_77;
                                                if (_e753 == _e754) {
                                                    phi_2403_ = true;
                                                } else {
                                                    let _e756 = local_75;
                                                    phi_2403_ = ((bitcast<u32>(_e756) & 2147483647u) > 2139095040u);
                                                }
                                                let _e761 = phi_2403_;
                                                local_200 = _e761;
                                                if _e761 {
                                                    let _e762 = local_78;
                                                    let _e763 = local_80;
                                                    if (_e762 == _e763) {
                                                        phi_2413_ = true;
                                                    } else {
                                                        let _e765 = local_78;
                                                        phi_2413_ = ((bitcast<u32>(_e765) & 2147483647u) > 2139095040u);
                                                    }
                                                    let _e770 = phi_2413_;
                                                    phi_720_ = _e770;
                                                } else {
                                                    phi_720_ = bool();
                                                }
                                                let _e772 = phi_720_;
                                                let _e773 = local_200;
                                                phi_722_ = _e772;
                                                phi_723_ = select(true, false, _e773);
                                            } else {
                                                phi_722_ = bool();
                                                phi_723_ = true;
                                            }
                                            let _e776 = phi_722_;
                                            let _e778 = phi_723_;
                                            let _e782 = local_48;
                                            let _e785 = local_71;
                                            local_81 = type_28(_e785.member, _e785.member_1, _e785.member_2, _e785.member_3, _e785.member_4, _e785.member_5, _e785.member_6, _e785.member_7, _e785.member_8, _e785.member_9, _e785.member_10, _e785.member_11, _e785.member_12, _e785.member_13, _e785.member_14, (_e782.member_15 + select(0u, 1u, !(select(_e776, false, _e778)))), _e785.member_16, _e785.member_17, _e785.member_18);
                                            let _e806 = local_73;
                                            if _e806 {
                                                let _e807 = local_65;
                                                phi_743_ = select(true, false, (_e807 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_743_ = true;
                                            }
                                            let _e811 = phi_743_;
                                            if _e811 {
                                                let _e812 = local_65;
                                                if (_e812 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e814 = local_65;
                                                    phi_757_ = select(true, false, (_e814 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_757_ = true;
                                                }
                                                let _e818 = phi_757_;
                                                let _e819 = local_65;
                                                phi_762_ = select(0f, _e819, _e818);
                                            } else {
                                                phi_762_ = 1267650600000000000000000000000f;
                                            }
                                            let _e822 = phi_762_;
                                            local_82 = _e822;
                                            let _e823 = local_76;
                                            if _e823 {
                                                let _e824 = local_75;
                                                phi_773_ = select(true, false, (_e824 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_773_ = true;
                                            }
                                            let _e828 = phi_773_;
                                            if _e828 {
                                                let _e829 = local_75;
                                                if (_e829 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e831 = local_75;
                                                    phi_787_ = select(true, false, (_e831 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_787_ = true;
                                                }
                                                let _e835 = phi_787_;
                                                let _e836 = local_75;
                                                phi_792_ = select(0f, _e836, _e835);
                                            } else {
                                                phi_792_ = 1267650600000000000000000000000f;
                                            }
                                            let _e839 = phi_792_;
                                            local_83 = _e839;
                                            let _e840 = local_79;
                                            if _e840 {
                                                let _e841 = local_78;
                                                phi_803_ = select(true, false, (_e841 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_803_ = true;
                                            }
                                            let _e845 = phi_803_;
                                            if _e845 {
                                                let _e846 = local_78;
                                                if (_e846 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e848 = local_78;
                                                    phi_817_ = select(true, false, (_e848 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_817_ = true;
                                                }
                                                let _e852 = phi_817_;
                                                let _e853 = local_78;
                                                phi_822_ = select(0f, _e853, _e852);
                                            } else {
                                                phi_822_ = 1267650600000000000000000000000f;
                                            }
                                            let _e856 = phi_822_;
                                            local_84 = _e856;
                                            let _e857 = local_82;
                                            let _e858 = local_83;
                                            let _e859 = array<f32, 3>(_e857, _e858, _e856);
                                            local_85 = _e859;
                                            let _e860 = local_48;
                                            let _e863 = local_81;
                                            local_86 = type_28(_e863.member, _e863.member_1, _e863.member_2, _e863.member_3, _e863.member_4, _e863.member_5, _e863.member_6, _e863.member_7, (_e860.member_8 + 1u), _e863.member_9, _e863.member_10, _e863.member_11, _e863.member_12, _e863.member_13, _e863.member_14, _e863.member_15, _e863.member_16, _e863.member_17, _e863.member_18);
                                            let _e884 = local_61;
                                            let _e885 = local_50;
                                            if (_e884 > _e885) {
                                                phi_999_ = _e688;
                                                phi_1000_ = _e859;
                                                phi_1001_ = 0u;
                                                phi_1002_ = u32();
                                                phi_1003_ = f32();
                                                phi_1004_ = array<f32, 3>();
                                                phi_1006_ = true;
                                            } else {
                                                let _e887 = local_48;
                                                local_87 = _e887.member_1;
                                                let _e889 = local_18;
                                                let _e892 = ((_e889 >> bitcast<u32>(8u)) & 7u);
                                                local_88 = _e892;
                                                if (_e892 == 0u) {
                                                    phi_942_ = 0u;
                                                } else {
                                                    let _e894 = local_88;
                                                    let _e895 = local_88;
                                                    let _e896 = (_e894 * _e895);
                                                    local_89 = _e896;
                                                    if (_e896 >= 32u) {
                                                        phi_906_ = 4294967295u;
                                                    } else {
                                                        let _e898 = local_89;
                                                        phi_906_ = ((1u << bitcast<u32>((_e898 & 31u))) - 1u);
                                                    }
                                                    let _e904 = phi_906_;
                                                    local_90 = _e904;
                                                    let _e905 = local_23;
                                                    let _e906 = local_12;
                                                    let _e908 = local_87;
                                                    let _e909 = local_12;
                                                    let _e911 = local_49;
                                                    let _e914 = ((5u * (_e905 * _e906)) + ((_e908 * _e909) + _e911));
                                                    local_91 = _e914;
                                                    let _e915 = local_1;
                                                    if (_e914 < _e915) {
                                                    } else {
                                                        phi_2459_ = true;
                                                        phi_2381_ = bool();
                                                        phi_2379_ = type_28();
                                                        break;
                                                    }
                                                    let _e917 = local_91;
                                                    let _e920 = global_5.member[_e917];
                                                    let _e921 = local_90;
                                                    let _e922 = (_e920 & _e921);
                                                    let _e923 = local_90;
                                                    phi_942_ = select(_e922, 0u, (_e922 == _e923));
                                                }
                                                let _e927 = phi_942_;
                                                local_92 = _e927;
                                                let _e928 = local_48;
                                                local_93 = _e928.member_7;
                                                let _e930 = local_48;
                                                local_94 = (_e927 & ~(_e930.member_9));
                                                let _e934 = (_e927 == 0u);
                                                if _e934 {
                                                    phi_979_ = type_17();
                                                    phi_980_ = type_17();
                                                    phi_981_ = true;
                                                    phi_982_ = false;
                                                } else {
                                                    let _e935 = local_94;
                                                    let _e936 = (_e935 == 0u);
                                                    if _e936 {
                                                        phi_976_ = type_17();
                                                        phi_977_ = type_17();
                                                        phi_978_ = false;
                                                    } else {
                                                        let _e937 = local_93;
                                                        let _e938 = local_72;
                                                        let _e940 = local_92;
                                                        let _e944 = local_94;
                                                        let _e947 = (((_e937 * _e938) * f32(countOneBits(_e940))) / f32(countOneBits(_e944)));
                                                        local_95 = _e947;
                                                        let _e948 = local_72;
                                                        let _e949 = (_e947 < _e948);
                                                        local_96 = _e949;
                                                        if _e949 {
                                                            let _e953 = local_95;
                                                            let _e954 = local_72;
                                                            let _e955 = (_e953 / _e954);
                                                            let _e956 = local_82;
                                                            let _e958 = local_83;
                                                            let _e960 = local_84;
                                                            let _e963 = local_95;
                                                            phi_973_ = type_17(array<f32, 3>((_e956 * _e955), (_e958 * _e955), (_e960 * _e955)), _e963);
                                                            phi_974_ = type_17();
                                                        } else {
                                                            let _e950 = local_85;
                                                            let _e951 = local_72;
                                                            phi_973_ = type_17();
                                                            phi_974_ = type_17(_e950, _e951);
                                                        }
                                                        let _e966 = phi_973_;
                                                        let _e968 = phi_974_;
                                                        let _e969 = local_96;
                                                        phi_976_ = _e966;
                                                        phi_977_ = _e968;
                                                        phi_978_ = select(true, false, _e969);
                                                    }
                                                    let _e972 = phi_976_;
                                                    let _e974 = phi_977_;
                                                    let _e976 = phi_978_;
                                                    phi_979_ = _e972;
                                                    phi_980_ = _e974;
                                                    phi_981_ = _e936;
                                                    phi_982_ = _e976;
                                                }
                                                let _e978 = phi_979_;
                                                let _e980 = phi_980_;
                                                let _e982 = phi_981_;
                                                let _e984 = phi_982_;
                                                local_97 = _e982;
                                                local_98 = _e984;
                                                if _e982 {
                                                    let _e985 = local_85;
                                                    let _e986 = local_72;
                                                    phi_987_ = type_17(_e985, _e986);
                                                } else {
                                                    phi_987_ = _e980;
                                                }
                                                let _e989 = phi_987_;
                                                let _e990 = local_97;
                                                let _e991 = local_98;
                                                if select(_e991, true, _e990) {
                                                    phi_992_ = _e989;
                                                } else {
                                                    phi_992_ = _e978;
                                                }
                                                let _e994 = phi_992_;
                                                phi_999_ = _e994.member_1;
                                                phi_1000_ = _e994.member;
                                                phi_1001_ = _e927;
                                                phi_1002_ = _e927;
                                                phi_1003_ = _e994.member_1;
                                                phi_1004_ = _e994.member;
                                                phi_1006_ = _e934;
                                            }
                                            let _e998 = phi_999_;
                                            let _e1000 = phi_1000_;
                                            let _e1002 = phi_1001_;
                                            let _e1004 = phi_1002_;
                                            let _e1006 = phi_1003_;
                                            let _e1008 = phi_1004_;
                                            let _e1010 = phi_1006_;
                                            local_99 = _e998;
                                            local_100 = _e1002;
                                            local_101 = _e1004;
                                            local_102 = _e1006;
                                            local_103 = _e1010;
                                            if _e1010 {
                                                phi_1012_ = _e1000;
                                            } else {
                                                phi_1012_ = _e1008;
                                            }
                                            let _e1012 = phi_1012_;
                                            local_104 = _e1012;
                                            let _e1013 = local_103;
                                            let _e1014 = local_101;
                                            let _e1016 = local_103;
                                            let _e1017 = local_99;
                                            let _e1018 = local_102;
                                            local_201 = select(_e1018, _e1017, _e1016);
                                            let _e1020 = local_103;
                                            let _e1021 = local_100;
                                            let _e1022 = local_101;
                                            local_202 = select(_e1022, _e1021, _e1020);
                                            let _e1024 = local_48;
                                            let _e1027 = local_86;
                                            let _e1047 = type_28(_e1027.member, _e1027.member_1, _e1027.member_2, _e1027.member_3, _e1027.member_4, _e1027.member_5, _e1027.member_6, _e1027.member_7, _e1027.member_8, (_e1024.member_9 | select(_e1014, 4294967295u, _e1013)), _e1027.member_10, _e1027.member_11, _e1027.member_12, _e1027.member_13, _e1027.member_14, _e1027.member_15, _e1027.member_16, _e1027.member_17, _e1027.member_18);
                                            let _e1048 = local_72;
                                            let _e1049 = (1f - _e1048);
                                            local_105 = _e1049;
                                            let _e1050 = local_48;
                                            let _e1072 = type_28(_e1047.member, _e1047.member_1, _e1047.member_2, _e1047.member_3, _e1047.member_4, _e1047.member_5, _e1047.member_6, (_e1050.member_7 * _e1049), _e1047.member_8, _e1047.member_9, _e1047.member_10, _e1047.member_11, _e1047.member_12, _e1047.member_13, _e1047.member_14, _e1047.member_15, _e1047.member_16, _e1047.member_17, _e1047.member_18);
                                            local_106 = _e1072;
                                            let _e1073 = local_64;
                                            let _e1074 = bitcast<u32>(_e1073);
                                            local_107 = _e1074;
                                            if (_e1074 == 2139095040u) {
                                                let _e1109 = local_20;
                                                let _e1111 = local_19;
                                                let _e1113 = local_21;
                                                let _e1114 = local_19;
                                                let _e1117 = local_22;
                                                phi_1097_ = (0.5f * ((((2f * _e1109) * _e1111) / (_e1113 - _e1114)) * _e1117));
                                            } else {
                                                let _e1076 = local_107;
                                                if (_e1076 == 0u) {
                                                    phi_1060_ = false;
                                                } else {
                                                    let _e1078 = local_107;
                                                    phi_1060_ = (_e1078 <= 2139095040u);
                                                }
                                                let _e1081 = phi_1060_;
                                                if _e1081 {
                                                    let _e1082 = local_20;
                                                    let _e1084 = local_19;
                                                    let _e1086 = local_21;
                                                    let _e1087 = local_19;
                                                    let _e1090 = local_22;
                                                    let _e1091 = ((((2f * _e1082) * _e1084) / (_e1086 - _e1087)) * _e1090);
                                                    local_108 = _e1091;
                                                    if (_e1091 == 0f) {
                                                        phi_1088_ = 0f;
                                                    } else {
                                                        let _e1093 = local_21;
                                                        let _e1094 = local_64;
                                                        let _e1097 = local_108;
                                                        phi_1088_ = (_e1097 * (1f - (_e1093 / _e1094)));
                                                    }
                                                    let _e1100 = phi_1088_;
                                                    phi_1089_ = _e1100;
                                                } else {
                                                    phi_1089_ = _e291;
                                                }
                                                let _e1102 = phi_1089_;
                                                local_109 = _e1102;
                                                if (_e1102 < 0f) {
                                                    let _e1104 = local_109;
                                                    phi_1095_ = -(_e1104);
                                                } else {
                                                    phi_1095_ = _e1102;
                                                }
                                                let _e1107 = phi_1095_;
                                                phi_1097_ = (0.5f * _e1107);
                                            }
                                            let _e1121 = phi_1097_;
                                            let _e1126 = (select(_e1121, 0f, ((bitcast<u32>(_e1121) & 2147483647u) > 2139095040u)) + 0.5f);
                                            let _e1127 = local_10;
                                            let _e1129 = local_10;
                                            let _e1130 = select(_e1129, _e1126, (_e1126 < _e1127));
                                            let _e1133 = (select(0.5f, _e1130, (_e1130 > 0.5f)) <= 1f);
                                            local_110 = _e1133;
                                            let _e1134 = local_46;
                                            let _e1137 = local_47;
                                            let _e1140 = array<u32, 2>(((2u * _e1134) + 1u), ((2u * _e1137) + 1u));
                                            local_111 = _e1140;
                                            let _e1141 = local_104;
                                            let _e1142 = local_201;
                                            let _e1143 = local_64;
                                            let _e1144 = local_202;
                                            local_112 = type_26(_e1140, _e1141, _e1142, _e1143, 0u, _e1144);
                                            if _e1133 {
                                                let _e1146 = local_48;
                                                let _e1148 = (_e1146.member_5 == 0u);
                                                local_113 = _e1148;
                                                if _e1148 {
                                                    let _e1149 = local_48;
                                                    local_114 = _e1149.member.member_1;
                                                    if (_e1149.member.member_1 >= 1f) {
                                                        let _e1153 = local_48;
                                                        if (_e1153.member.member[0] == 0f) {
                                                            let _e1158 = local_48;
                                                            let _e1162 = (_e1158.member.member[1] == 0f);
                                                            local_115 = _e1162;
                                                            if _e1162 {
                                                                let _e1163 = local_48;
                                                                phi_1149_ = (_e1163.member.member[2] == 0f);
                                                            } else {
                                                                phi_1149_ = bool();
                                                            }
                                                            let _e1169 = phi_1149_;
                                                            let _e1170 = local_115;
                                                            phi_1151_ = _e1169;
                                                            phi_1152_ = select(true, false, _e1170);
                                                        } else {
                                                            phi_1151_ = bool();
                                                            phi_1152_ = true;
                                                        }
                                                        let _e1173 = phi_1151_;
                                                        let _e1175 = phi_1152_;
                                                        phi_1153_ = _e1173;
                                                        phi_1154_ = _e1175;
                                                    } else {
                                                        phi_1153_ = bool();
                                                        phi_1154_ = true;
                                                    }
                                                    let _e1177 = phi_1153_;
                                                    let _e1179 = phi_1154_;
                                                    if select(_e1177, false, _e1179) {
                                                        let _e1235 = local_85;
                                                        let _e1236 = local_105;
                                                        let _e1238 = local_106;
                                                        phi_1185_ = type_28(type_17(_e1235, _e1236), _e1238.member_1, _e1238.member_2, _e1238.member_3, _e1238.member_4, _e1238.member_5, _e1238.member_6, _e1238.member_7, _e1238.member_8, _e1238.member_9, _e1238.member_10, _e1238.member_11, _e1238.member_12, _e1238.member_13, _e1238.member_14, _e1238.member_15, _e1238.member_16, _e1238.member_17, _e1238.member_18);
                                                    } else {
                                                        let _e1181 = local_114;
                                                        if (_e1181 > 0f) {
                                                            let _e1183 = local_48;
                                                            let _e1187 = local_114;
                                                            let _e1188 = local_82;
                                                            let _e1191 = local_48;
                                                            let _e1195 = local_114;
                                                            let _e1196 = local_83;
                                                            let _e1199 = local_48;
                                                            let _e1203 = local_114;
                                                            let _e1204 = local_84;
                                                            let _e1208 = local_114;
                                                            let _e1209 = local_105;
                                                            let _e1212 = local_106;
                                                            phi_1184_ = type_28(type_17(array<f32, 3>((_e1183.member.member[0] + (_e1187 * _e1188)), (_e1191.member.member[1] + (_e1195 * _e1196)), (_e1199.member.member[2] + (_e1203 * _e1204))), (_e1208 * _e1209)), _e1212.member_1, _e1212.member_2, _e1212.member_3, _e1212.member_4, _e1212.member_5, _e1212.member_6, _e1212.member_7, _e1212.member_8, _e1212.member_9, _e1212.member_10, _e1212.member_11, _e1212.member_12, _e1212.member_13, _e1212.member_14, _e1212.member_15, _e1212.member_16, _e1212.member_17, _e1212.member_18);
                                                        } else {
                                                            phi_1184_ = _e1072;
                                                        }
                                                        let _e1234 = phi_1184_;
                                                        phi_1185_ = _e1234;
                                                    }
                                                    let _e1260 = phi_1185_;
                                                    let _e1261 = local_64;
                                                    let _e1281 = type_28(_e1260.member, _e1260.member_1, _e1260.member_2, _e1260.member_3, _e1260.member_4, _e1260.member_5, _e1261, _e1260.member_7, _e1260.member_8, _e1260.member_9, _e1260.member_10, _e1260.member_11, _e1260.member_12, _e1260.member_13, _e1260.member_14, _e1260.member_15, _e1260.member_16, _e1260.member_17, _e1260.member_18);
                                                    let _e1282 = local_72;
                                                    phi_1193_ = type_28(_e1281.member, _e1281.member_1, _e1281.member_2, _e1281.member_3, _e1281.member_4, select(1u, 2u, (_e1282 >= 1f)), _e1281.member_6, _e1281.member_7, _e1281.member_8, _e1281.member_9, _e1281.member_10, _e1281.member_11, _e1281.member_12, _e1281.member_13, _e1281.member_14, _e1281.member_15, _e1281.member_16, _e1281.member_17, _e1281.member_18);
                                                } else {
                                                    phi_1193_ = type_28();
                                                }
                                                let _e1306 = phi_1193_;
                                                let _e1307 = local_113;
                                                phi_1195_ = _e1306;
                                                phi_1196_ = select(true, false, _e1307);
                                            } else {
                                                phi_1195_ = type_28();
                                                phi_1196_ = true;
                                            }
                                            let _e1310 = phi_1195_;
                                            let _e1312 = phi_1196_;
                                            if _e1312 {
                                                let _e1313 = local_110;
                                                if _e1313 {
                                                    let _e1314 = local_48;
                                                    let _e1316 = (_e1314.member_5 == 1u);
                                                    local_116 = _e1316;
                                                    if _e1316 {
                                                        let _e1317 = local_48;
                                                        local_117 = _e1317.member.member_1;
                                                        if (_e1317.member.member_1 >= 1f) {
                                                            let _e1321 = local_48;
                                                            if (_e1321.member.member[0] == 0f) {
                                                                let _e1326 = local_48;
                                                                let _e1330 = (_e1326.member.member[1] == 0f);
                                                                local_118 = _e1330;
                                                                if _e1330 {
                                                                    let _e1331 = local_48;
                                                                    phi_1226_ = (_e1331.member.member[2] == 0f);
                                                                } else {
                                                                    phi_1226_ = bool();
                                                                }
                                                                let _e1337 = phi_1226_;
                                                                let _e1338 = local_118;
                                                                phi_1228_ = _e1337;
                                                                phi_1229_ = select(true, false, _e1338);
                                                            } else {
                                                                phi_1228_ = bool();
                                                                phi_1229_ = true;
                                                            }
                                                            let _e1341 = phi_1228_;
                                                            let _e1343 = phi_1229_;
                                                            phi_1230_ = _e1341;
                                                            phi_1231_ = _e1343;
                                                        } else {
                                                            phi_1230_ = bool();
                                                            phi_1231_ = true;
                                                        }
                                                        let _e1345 = phi_1230_;
                                                        let _e1347 = phi_1231_;
                                                        if select(_e1345, false, _e1347) {
                                                            let _e1403 = local_85;
                                                            let _e1404 = local_105;
                                                            let _e1406 = local_106;
                                                            phi_1262_ = type_28(type_17(_e1403, _e1404), _e1406.member_1, _e1406.member_2, _e1406.member_3, _e1406.member_4, _e1406.member_5, _e1406.member_6, _e1406.member_7, _e1406.member_8, _e1406.member_9, _e1406.member_10, _e1406.member_11, _e1406.member_12, _e1406.member_13, _e1406.member_14, _e1406.member_15, _e1406.member_16, _e1406.member_17, _e1406.member_18);
                                                        } else {
                                                            let _e1349 = local_117;
                                                            if (_e1349 > 0f) {
                                                                let _e1351 = local_48;
                                                                let _e1355 = local_117;
                                                                let _e1356 = local_82;
                                                                let _e1359 = local_48;
                                                                let _e1363 = local_117;
                                                                let _e1364 = local_83;
                                                                let _e1367 = local_48;
                                                                let _e1371 = local_117;
                                                                let _e1372 = local_84;
                                                                let _e1376 = local_117;
                                                                let _e1377 = local_105;
                                                                let _e1380 = local_106;
                                                                phi_1261_ = type_28(type_17(array<f32, 3>((_e1351.member.member[0] + (_e1355 * _e1356)), (_e1359.member.member[1] + (_e1363 * _e1364)), (_e1367.member.member[2] + (_e1371 * _e1372))), (_e1376 * _e1377)), _e1380.member_1, _e1380.member_2, _e1380.member_3, _e1380.member_4, _e1380.member_5, _e1380.member_6, _e1380.member_7, _e1380.member_8, _e1380.member_9, _e1380.member_10, _e1380.member_11, _e1380.member_12, _e1380.member_13, _e1380.member_14, _e1380.member_15, _e1380.member_16, _e1380.member_17, _e1380.member_18);
                                                            } else {
                                                                phi_1261_ = _e1072;
                                                            }
                                                            let _e1402 = phi_1261_;
                                                            phi_1262_ = _e1402;
                                                        }
                                                        let _e1428 = phi_1262_;
                                                        phi_1270_ = type_28(_e1428.member, _e1428.member_1, _e1428.member_2, _e1428.member_3, _e1428.member_4, select(2u, 1u, (_e1428.member.member_1 > 0f)), _e1428.member_6, _e1428.member_7, _e1428.member_8, _e1428.member_9, _e1428.member_10, _e1428.member_11, _e1428.member_12, _e1428.member_13, _e1428.member_14, _e1428.member_15, _e1428.member_16, _e1428.member_17, _e1428.member_18);
                                                    } else {
                                                        phi_1270_ = type_28();
                                                    }
                                                    let _e1454 = phi_1270_;
                                                    let _e1455 = local_116;
                                                    phi_1272_ = _e1454;
                                                    phi_1273_ = select(true, false, _e1455);
                                                } else {
                                                    phi_1272_ = type_28();
                                                    phi_1273_ = true;
                                                }
                                                let _e1458 = phi_1272_;
                                                let _e1460 = phi_1273_;
                                                if _e1460 {
                                                    let _e1461 = local_110;
                                                    if _e1461 {
                                                        let _e1462 = local_48;
                                                        let _e1464 = (_e1462.member_5 == 2u);
                                                        local_119 = _e1464;
                                                        if _e1464 {
                                                            let _e1465 = local_48;
                                                            let _e1468 = local_106;
                                                            phi_1288_ = type_28(_e1468.member, _e1468.member_1, _e1468.member_2, _e1468.member_3, _e1468.member_4, _e1468.member_5, _e1468.member_6, _e1468.member_7, _e1468.member_8, _e1468.member_9, _e1468.member_10, _e1468.member_11, _e1468.member_12, _e1468.member_13, _e1468.member_14, _e1468.member_15, _e1468.member_16, (_e1465.member_17 + 1u), _e1468.member_18);
                                                        } else {
                                                            phi_1288_ = type_28();
                                                        }
                                                        let _e1490 = phi_1288_;
                                                        let _e1491 = local_119;
                                                        phi_1290_ = _e1490;
                                                        phi_1291_ = select(true, false, _e1491);
                                                    } else {
                                                        phi_1290_ = type_28();
                                                        phi_1291_ = true;
                                                    }
                                                    let _e1494 = phi_1290_;
                                                    let _e1496 = phi_1291_;
                                                    if _e1496 {
                                                        let _e1497 = local_48;
                                                        let _e1499 = (_e1497.member_5 == 1u);
                                                        local_120 = _e1499;
                                                        if _e1499 {
                                                            let _e1528 = local_48;
                                                            let _e1531 = local_48;
                                                            let _e1533 = local_48;
                                                            let _e1537 = local_111;
                                                            let _e1539 = local_106;
                                                            let _e1559 = type_28(_e1539.member, _e1539.member_1, _e1539.member_2, _e1539.member_3, _e1539.member_4, _e1539.member_5, _e1539.member_6, _e1539.member_7, _e1539.member_8, _e1539.member_9, _e1539.member_10, _e1539.member_11, _e1539.member_12, type_26(_e1537, _e1528.member.member, (1f - _e1533.member.member_1), _e1531.member_6, 0u, 0u), _e1539.member_14, _e1539.member_15, _e1539.member_16, _e1539.member_17, _e1539.member_18);
                                                            let _e1560 = local_48;
                                                            let _e1562 = (_e1560.member_10 + 1u);
                                                            let _e1582 = type_28(_e1559.member, _e1559.member_1, _e1559.member_2, _e1559.member_3, _e1559.member_4, _e1559.member_5, _e1559.member_6, _e1559.member_7, _e1559.member_8, _e1559.member_9, _e1562, _e1559.member_11, _e1559.member_12, _e1559.member_13, _e1559.member_14, _e1559.member_15, _e1559.member_16, _e1559.member_17, _e1559.member_18);
                                                            let _e1602 = type_28(_e1582.member, _e1582.member_1, _e1582.member_2, _e1582.member_3, _e1582.member_4, 3u, _e1582.member_6, _e1582.member_7, _e1582.member_8, _e1582.member_9, _e1582.member_10, _e1582.member_11, _e1582.member_12, _e1582.member_13, _e1582.member_14, _e1582.member_15, _e1582.member_16, _e1582.member_17, _e1582.member_18);
                                                            local_121 = _e1602;
                                                            let _e1603 = local_12;
                                                            let _e1604 = (_e1562 < _e1603);
                                                            if _e1604 {
                                                                let _e1605 = local_112;
                                                                let _e1606 = local_121;
                                                                let _e1626 = type_28(_e1606.member, _e1606.member_1, _e1606.member_2, _e1606.member_3, _e1606.member_4, _e1606.member_5, _e1606.member_6, _e1606.member_7, _e1606.member_8, _e1606.member_9, _e1606.member_10, _e1606.member_11, _e1605, _e1606.member_13, _e1606.member_14, _e1606.member_15, _e1606.member_16, _e1606.member_17, _e1606.member_18);
                                                                phi_1323_ = type_28(_e1626.member, _e1626.member_1, _e1626.member_2, _e1626.member_3, _e1626.member_4, _e1626.member_5, _e1626.member_6, _e1626.member_7, _e1626.member_8, _e1626.member_9, _e1626.member_10, 1u, _e1626.member_12, _e1626.member_13, _e1626.member_14, _e1626.member_15, _e1626.member_16, _e1626.member_17, _e1626.member_18);
                                                            } else {
                                                                phi_1323_ = type_28();
                                                            }
                                                            let _e1648 = phi_1323_;
                                                            phi_1333_ = _e1648;
                                                            phi_1335_ = _e1602;
                                                            phi_1337_ = _e1604;
                                                        } else {
                                                            let _e1500 = local_48;
                                                            let _e1502 = local_12;
                                                            let _e1503 = (_e1500.member_10 < _e1502);
                                                            if _e1503 {
                                                                let _e1504 = local_112;
                                                                let _e1505 = local_106;
                                                                phi_1332_ = type_28(_e1505.member, _e1505.member_1, _e1505.member_2, _e1505.member_3, _e1505.member_4, _e1505.member_5, _e1505.member_6, _e1505.member_7, _e1505.member_8, _e1505.member_9, _e1505.member_10, _e1505.member_11, _e1505.member_12, _e1504, _e1505.member_14, _e1505.member_15, _e1505.member_16, _e1505.member_17, _e1505.member_18);
                                                            } else {
                                                                phi_1332_ = type_28();
                                                            }
                                                            let _e1527 = phi_1332_;
                                                            phi_1333_ = _e1527;
                                                            phi_1335_ = _e1072;
                                                            phi_1337_ = _e1503;
                                                        }
                                                        let _e1650 = phi_1333_;
                                                        let _e1652 = phi_1335_;
                                                        let _e1654 = phi_1337_;
                                                        local_122 = _e1650;
                                                        local_123 = _e1652;
                                                        local_124 = _e1654;
                                                        let _e1655 = local_120;
                                                        local_203 = select(0u, 1u, _e1655);
                                                        if _e1654 {
                                                            let _e1657 = local_122;
                                                            let _e1660 = local_122;
                                                            let _e1681 = local_203;
                                                            phi_1345_ = type_28(_e1660.member, _e1660.member_1, _e1660.member_2, _e1660.member_3, _e1660.member_4, _e1660.member_5, _e1660.member_6, _e1660.member_7, _e1660.member_8, _e1660.member_9, (_e1657.member_10 + 1u), _e1660.member_11, _e1660.member_12, _e1660.member_13, _e1660.member_14, _e1660.member_15, _e1660.member_16, _e1660.member_17, _e1660.member_18);
                                                            phi_1346_ = (_e1681 + 1u);
                                                        } else {
                                                            phi_1345_ = type_28();
                                                            phi_1346_ = u32();
                                                        }
                                                        let _e1684 = phi_1345_;
                                                        let _e1686 = phi_1346_;
                                                        local_125 = _e1686;
                                                        let _e1687 = local_124;
                                                        let _e1688 = select(true, false, _e1687);
                                                        local_204 = _e1688;
                                                        if _e1688 {
                                                            let _e1689 = local_123;
                                                            local_126 = type_28(type_17(array<f32, 3>(0f, 0f, 0f), 1f), _e1689.member_1, _e1689.member_2, _e1689.member_3, _e1689.member_4, _e1689.member_5, _e1689.member_6, _e1689.member_7, _e1689.member_8, _e1689.member_9, _e1689.member_10, _e1689.member_11, _e1689.member_12, _e1689.member_13, _e1689.member_14, _e1689.member_15, _e1689.member_16, _e1689.member_17, _e1689.member_18);
                                                            if true {
                                                                let _e1734 = local_85;
                                                                let _e1735 = local_105;
                                                                let _e1737 = local_126;
                                                                phi_1406_ = type_28(type_17(_e1734, _e1735), _e1737.member_1, _e1737.member_2, _e1737.member_3, _e1737.member_4, _e1737.member_5, _e1737.member_6, _e1737.member_7, _e1737.member_8, _e1737.member_9, _e1737.member_10, _e1737.member_11, _e1737.member_12, _e1737.member_13, _e1737.member_14, _e1737.member_15, _e1737.member_16, _e1737.member_17, _e1737.member_18);
                                                            } else {
                                                                let _e1710 = local_85;
                                                                let _e1711 = local_105;
                                                                let _e1713 = local_126;
                                                                phi_1406_ = type_28(type_17(_e1710, _e1711), _e1713.member_1, _e1713.member_2, _e1713.member_3, _e1713.member_4, _e1713.member_5, _e1713.member_6, _e1713.member_7, _e1713.member_8, _e1713.member_9, _e1713.member_10, _e1713.member_11, _e1713.member_12, _e1713.member_13, _e1713.member_14, _e1713.member_15, _e1713.member_16, _e1713.member_17, _e1713.member_18);
                                                            }
                                                            let _e1759 = phi_1406_;
                                                            let _e1760 = local_64;
                                                            let _e1780 = type_28(_e1759.member, _e1759.member_1, _e1759.member_2, _e1759.member_3, _e1759.member_4, _e1759.member_5, _e1760, _e1759.member_7, _e1759.member_8, _e1759.member_9, _e1759.member_10, _e1759.member_11, _e1759.member_12, _e1759.member_13, _e1759.member_14, _e1759.member_15, _e1759.member_16, _e1759.member_17, _e1759.member_18);
                                                            phi_1409_ = type_28(_e1780.member, _e1780.member_1, _e1780.member_2, _e1780.member_3, _e1780.member_4, 2u, _e1780.member_6, _e1780.member_7, _e1780.member_8, _e1780.member_9, _e1780.member_10, _e1780.member_11, _e1780.member_12, _e1780.member_13, _e1780.member_14, _e1780.member_15, _e1780.member_16, _e1780.member_17, _e1780.member_18);
                                                        } else {
                                                            phi_1409_ = _e1684;
                                                        }
                                                        let _e1802 = phi_1409_;
                                                        let _e1803 = local_204;
                                                        let _e1804 = local_203;
                                                        let _e1805 = local_125;
                                                        phi_1411_ = _e1802;
                                                        phi_1412_ = select(_e1805, _e1804, _e1803);
                                                    } else {
                                                        phi_1411_ = _e1494;
                                                        phi_1412_ = 0u;
                                                    }
                                                    let _e1808 = phi_1411_;
                                                    let _e1810 = phi_1412_;
                                                    phi_1413_ = _e1808;
                                                    phi_1414_ = _e1810;
                                                } else {
                                                    phi_1413_ = _e1458;
                                                    phi_1414_ = 0u;
                                                }
                                                let _e1812 = phi_1413_;
                                                let _e1814 = phi_1414_;
                                                phi_1415_ = _e1812;
                                                phi_1416_ = _e1814;
                                            } else {
                                                phi_1415_ = _e1310;
                                                phi_1416_ = 0u;
                                            }
                                            let _e1816 = phi_1415_;
                                            let _e1818 = phi_1416_;
                                            phi_1420_ = _e1816;
                                            phi_1421_ = _e1818;
                                        } else {
                                            let _e625 = local_48;
                                            let _e628 = local_62;
                                            phi_1420_ = type_28(_e628.member, _e628.member_1, _e628.member_2, _e628.member_3, _e628.member_4, _e628.member_5, _e628.member_6, _e628.member_7, _e628.member_8, _e628.member_9, _e628.member_10, _e628.member_11, _e628.member_12, _e628.member_13, (_e625.member_14 + 1u), _e628.member_15, _e628.member_16, _e628.member_17, _e628.member_18);
                                            phi_1421_ = 0u;
                                        }
                                        let _e1820 = phi_1420_;
                                        let _e1822 = phi_1421_;
                                        local_127 = _e1820;
                                        local_128 = _e1822;
                                        local_129 = _e1820.member_4;
                                        local_130 = _e1820.member_3;
                                        if (_e1820.member_4 == _e1820.member_3) {
                                            let _e1826 = local_127;
                                            let _e1828 = local_129;
                                            if (_e1828 == _e1826.member_2) {
                                                let _e1830 = local_127;
                                                if (_e1830.member_8 > 0u) {
                                                    let _e1833 = local_127;
                                                    if (_e1833.member_7 > 0f) {
                                                        let _e1836 = local_127;
                                                        if (_e1836.member_5 != 1u) {
                                                            let _e1839 = local_130;
                                                            let _e1841 = local_127;
                                                            let _e1861 = type_28(_e1841.member, _e1841.member_1, _e1841.member_2, (_e1839 + 1u), _e1841.member_4, _e1841.member_5, _e1841.member_6, _e1841.member_7, _e1841.member_8, _e1841.member_9, _e1841.member_10, _e1841.member_11, _e1841.member_12, _e1841.member_13, _e1841.member_14, _e1841.member_15, _e1841.member_16, _e1841.member_17, _e1841.member_18);
                                                            phi_1453_ = type_28(_e1861.member, _e1861.member_1, _e1861.member_2, _e1861.member_3, _e1861.member_4, _e1861.member_5, _e1861.member_6, _e1861.member_7, _e1861.member_8, _e1861.member_9, _e1861.member_10, _e1861.member_11, _e1861.member_12, _e1861.member_13, _e1861.member_14, _e1861.member_15, _e1861.member_16, _e1861.member_17, 1u);
                                                        } else {
                                                            phi_1453_ = _e1820;
                                                        }
                                                        let _e1883 = phi_1453_;
                                                        phi_1454_ = _e1883;
                                                    } else {
                                                        phi_1454_ = _e1820;
                                                    }
                                                    let _e1885 = phi_1454_;
                                                    phi_1455_ = _e1885;
                                                } else {
                                                    phi_1455_ = _e1820;
                                                }
                                                let _e1887 = phi_1455_;
                                                phi_1456_ = _e1887;
                                            } else {
                                                phi_1456_ = _e1820;
                                            }
                                            let _e1889 = phi_1456_;
                                            phi_1457_ = _e1889;
                                        } else {
                                            phi_1457_ = _e1820;
                                        }
                                        let _e1891 = phi_1457_;
                                        let _e1892 = local_128;
                                        let _e1893 = (_e1892 > 0u);
                                        phi_1463_ = _e1891;
                                        phi_1464_ = select(true, false, _e1893);
                                        phi_1465_ = _e1893;
                                    } else {
                                        phi_1463_ = type_28();
                                        phi_1464_ = false;
                                        phi_1465_ = false;
                                    }
                                    let _e1896 = phi_1463_;
                                    let _e1898 = phi_1464_;
                                    let _e1900 = phi_1465_;
                                    local_131 = _e1898;
                                    continue;
                                    continuing {
                                        let _e1901 = local_131;
                                        phi_437_ = _e1896;
                                        phi_2459_ = _e431;
                                        phi_2381_ = _e1900;
                                        phi_2379_ = _e1896;
                                        break if !(_e1901);
                                    }
                                }
                                let _e1904 = phi_2459_;
                                let _e1906 = phi_2381_;
                                let _e1908 = phi_2379_;
                                local_198 = _e1906;
                                phi_2613_ = _e1904;
                                phi_2383_ = type_28();
                                if _e1904 {
                                    break;
                                }
                                let _e1909 = local_198;
                                let _e1910 = select(true, false, _e1909);
                                local_205 = _e1910;
                                if _e1910 {
                                    let _e2669 = local_209;
                                    phi_1473_ = _e2669;
                                } else {
                                    phi_1473_ = _e1908;
                                }
                                let _e1912 = phi_1473_;
                                let _e1913 = local_205;
                                phi_2607_ = _e1904;
                                phi_405_ = _e1912;
                                phi_1478_ = select(true, false, _e1913);
                            } else {
                                let _e443 = local_39;
                                let _e463 = type_28(_e443.member, _e443.member_1, _e443.member_2, _e443.member_3, _e443.member_4, _e443.member_5, _e443.member_6, _e443.member_7, _e443.member_8, _e443.member_9, _e443.member_10, 0u, _e443.member_12, _e443.member_13, _e443.member_14, _e443.member_15, _e443.member_16, _e443.member_17, _e443.member_18);
                                let _e464 = local_39;
                                phi_2607_ = _e431;
                                phi_405_ = type_28(_e463.member, _e463.member_1, _e463.member_2, _e463.member_3, _e463.member_4, _e463.member_5, _e463.member_6, _e463.member_7, _e463.member_8, _e463.member_9, _e463.member_10, _e463.member_11, _e463.member_12, _e464.member_12, _e463.member_14, _e463.member_15, _e463.member_16, _e463.member_17, _e463.member_18);
                                phi_1478_ = true;
                            }
                            let _e1916 = phi_2607_;
                            let _e1918 = phi_405_;
                            let _e1920 = phi_1478_;
                            local_40 = _e1918;
                            local_132 = _e1920;
                            if _e1920 {
                                let _e1921 = local_13;
                                if (_e1921 == 1u) {
                                    let _e1923 = local_38;
                                    let _e1924 = local_43;
                                    local_133 = (_e1923 + _e1924);
                                    let _e1926 = local_40;
                                    local_134 = _e1926.member_13.member_1;
                                    local_135 = _e1926.member_13.member_1[0];
                                    if (_e1926.member_13.member_1[0] > 1267650600000000000000000000000f) {
                                        let _e1931 = local_135;
                                        phi_1500_ = select(true, false, (_e1931 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_1500_ = true;
                                    }
                                    let _e1935 = phi_1500_;
                                    if _e1935 {
                                        let _e1936 = local_135;
                                        if (_e1936 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e1938 = local_135;
                                            phi_1514_ = select(true, false, (_e1938 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_1514_ = true;
                                        }
                                        let _e1942 = phi_1514_;
                                        let _e1943 = local_135;
                                        phi_1519_ = select(0f, _e1943, _e1942);
                                    } else {
                                        phi_1519_ = 1267650600000000000000000000000f;
                                    }
                                    let _e1946 = phi_1519_;
                                    local_136 = _e1946;
                                    let _e1947 = local_134;
                                    local_137 = _e1947[1];
                                    if (_e1947[1] > 1267650600000000000000000000000f) {
                                        let _e1950 = local_137;
                                        phi_1530_ = select(true, false, (_e1950 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_1530_ = true;
                                    }
                                    let _e1954 = phi_1530_;
                                    if _e1954 {
                                        let _e1955 = local_137;
                                        if (_e1955 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e1957 = local_137;
                                            phi_1544_ = select(true, false, (_e1957 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_1544_ = true;
                                        }
                                        let _e1961 = phi_1544_;
                                        let _e1962 = local_137;
                                        phi_1549_ = select(0f, _e1962, _e1961);
                                    } else {
                                        phi_1549_ = 1267650600000000000000000000000f;
                                    }
                                    let _e1965 = phi_1549_;
                                    local_138 = _e1965;
                                    let _e1966 = local_134;
                                    local_139 = _e1966[2];
                                    if (_e1966[2] > 1267650600000000000000000000000f) {
                                        let _e1969 = local_139;
                                        phi_1560_ = select(true, false, (_e1969 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_1560_ = true;
                                    }
                                    let _e1973 = phi_1560_;
                                    if _e1973 {
                                        let _e1974 = local_139;
                                        if (_e1974 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e1976 = local_139;
                                            phi_1574_ = select(true, false, (_e1976 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_1574_ = true;
                                        }
                                        let _e1980 = phi_1574_;
                                        let _e1981 = local_139;
                                        phi_1579_ = select(0f, _e1981, _e1980);
                                    } else {
                                        phi_1579_ = 1267650600000000000000000000000f;
                                    }
                                    let _e1984 = phi_1579_;
                                    let _e1985 = local_136;
                                    let _e1986 = local_138;
                                    local_207 = array<f32, 3>(_e1985, _e1986, _e1984);
                                    let _e1989 = local_207[0u];
                                    let _e1991 = local_207[1u];
                                    if (_e1989 > _e1991) {
                                        let _e1994 = local_207[0u];
                                        phi_1597_ = _e1994;
                                    } else {
                                        let _e1993 = local_207[1u];
                                        phi_1597_ = _e1993;
                                    }
                                    let _e1996 = phi_1597_;
                                    let _e1998 = local_207[2u];
                                    if (_e1996 > _e1998) {
                                        phi_1606_ = _e1996;
                                    } else {
                                        let _e2000 = local_207[2u];
                                        phi_1606_ = _e2000;
                                    }
                                    let _e2002 = phi_1606_;
                                    local_140 = _e2002;
                                    if (_e2002 >= 0.0000000000000000000000000000000000962965f) {
                                        let _e2004 = local_140;
                                        local_208 = array<u32, 3>(0u, 0u, 0u);
                                        phi_2586_ = _e1916;
                                        phi_1621_ = 0i;
                                        phi_1624_ = (bitcast<i32>(((bitcast<u32>(_e2004) >> bitcast<u32>(23i)) & 255u)) - 127i);
                                        loop {
                                            let _e2012 = phi_2586_;
                                            let _e2014 = phi_1621_;
                                            let _e2016 = phi_1624_;
                                            local_141 = _e2014;
                                            local_142 = _e2016;
                                            let _e2017 = local_141;
                                            if (_e2017 < 2i) {
                                                let _e2019 = local_142;
                                                local_143 = bitcast<f32>((bitcast<u32>((140i - _e2019)) << bitcast<u32>(23i)));
                                                phi_1638_ = 0u;
                                                phi_1641_ = 0u;
                                                loop {
                                                    let _e2026 = phi_1638_;
                                                    let _e2028 = phi_1641_;
                                                    local_144 = _e2026;
                                                    local_145 = _e2028;
                                                    let _e2029 = local_144;
                                                    let _e2030 = (_e2029 < 3u);
                                                    local_146 = _e2030;
                                                    if _e2030 {
                                                        let _e2031 = local_146;
                                                        if _e2031 {
                                                        } else {
                                                            phi_2582_ = true;
                                                            break;
                                                        }
                                                        let _e2032 = local_144;
                                                        let _e2034 = local_207[_e2032];
                                                        let _e2035 = local_143;
                                                        local_147 = ((_e2034 * _e2035) + 0.5f);
                                                        let _e2038 = local_146;
                                                        if _e2038 {
                                                        } else {
                                                            phi_2582_ = true;
                                                            break;
                                                        }
                                                        let _e2039 = local_144;
                                                        let _e2041 = local_147;
                                                        let _e2043 = local_147;
                                                        let _e2046 = local_147;
                                                        local_208[_e2039] = select(select(u32(_e2041), 0u, !((_e2043 >= 0f))), 4294967295u, (_e2046 > 4294967000f));
                                                        let _e2050 = local_146;
                                                        if _e2050 {
                                                        } else {
                                                            phi_2582_ = true;
                                                            break;
                                                        }
                                                        let _e2051 = local_208[_e2039];
                                                        let _e2052 = local_145;
                                                        if (_e2051 > _e2052) {
                                                            let _e2054 = local_146;
                                                            if _e2054 {
                                                            } else {
                                                                phi_2582_ = true;
                                                                break;
                                                            }
                                                            let _e2055 = local_208[_e2039];
                                                            phi_1689_ = _e2055;
                                                        } else {
                                                            phi_1689_ = _e2028;
                                                        }
                                                        let _e2057 = phi_1689_;
                                                        let _e2058 = local_144;
                                                        phi_1639_ = (_e2058 + 1u);
                                                        phi_1642_ = _e2057;
                                                    } else {
                                                        phi_1639_ = u32();
                                                        phi_1642_ = u32();
                                                    }
                                                    let _e2061 = phi_1639_;
                                                    let _e2063 = phi_1642_;
                                                    continue;
                                                    continuing {
                                                        let _e2064 = local_146;
                                                        phi_1638_ = _e2061;
                                                        phi_1641_ = _e2063;
                                                        phi_2582_ = _e2012;
                                                        break if !(_e2064);
                                                    }
                                                }
                                                let _e2067 = phi_2582_;
                                                phi_2610_ = _e2067;
                                                if _e2067 {
                                                    break;
                                                }
                                                let _e2068 = local_145;
                                                let _e2069 = (_e2068 <= 16383u);
                                                local_148 = _e2069;
                                                if _e2069 {
                                                    phi_1697_ = i32();
                                                    phi_1698_ = i32();
                                                } else {
                                                    let _e2070 = local_142;
                                                    let _e2072 = local_141;
                                                    phi_1697_ = (_e2072 + 1i);
                                                    phi_1698_ = (_e2070 + 1i);
                                                }
                                                let _e2075 = phi_1697_;
                                                let _e2077 = phi_1698_;
                                                let _e2078 = local_148;
                                                phi_2611_ = _e2067;
                                                phi_1622_ = _e2075;
                                                phi_1625_ = _e2077;
                                                phi_1700_ = select(true, false, _e2078);
                                            } else {
                                                phi_2611_ = _e2012;
                                                phi_1622_ = i32();
                                                phi_1625_ = i32();
                                                phi_1700_ = false;
                                            }
                                            let _e2081 = phi_2611_;
                                            let _e2083 = phi_1622_;
                                            let _e2085 = phi_1625_;
                                            let _e2087 = phi_1700_;
                                            local_149 = _e2087;
                                            continue;
                                            continuing {
                                                let _e2088 = local_149;
                                                phi_2586_ = _e2081;
                                                phi_1621_ = _e2083;
                                                phi_1624_ = _e2085;
                                                phi_2610_ = _e2081;
                                                break if !(_e2088);
                                            }
                                        }
                                        let _e2091 = phi_2610_;
                                        phi_2613_ = _e2091;
                                        phi_2383_ = type_28();
                                        if _e2091 {
                                            break;
                                        }
                                        let _e2092 = local_142;
                                        let _e2095 = local_208;
                                        phi_2627_ = _e2091;
                                        phi_1714_ = type_29(array<u32, 3>(_e2095[0], _e2095[1], _e2095[2]), bitcast<u32>((_e2092 + 127i)));
                                    } else {
                                        phi_2627_ = _e1916;
                                        phi_1714_ = type_29(array<u32, 3>(0u, 0u, 0u), 0u);
                                    }
                                    let _e2102 = phi_2627_;
                                    let _e2104 = phi_1714_;
                                    local_150 = _e2104.member_1;
                                    let _e2112 = local_40;
                                    local_151 = _e2112.member_13.member_4;
                                    local_152 = ((_e2104.member[0] | (_e2104.member[1] << bitcast<u32>(14u))) | ((_e2112.member_13.member_4 & 3u) << bitcast<u32>(28i)));
                                    local_153 = _e2104.member[2];
                                    let _e2120 = local_40;
                                    local_154 = _e2120.member_13.member_2;
                                    if (_e2120.member_13.member_2 > 1f) {
                                        phi_1736_ = 1f;
                                    } else {
                                        let _e2124 = local_154;
                                        let _e2126 = local_154;
                                        phi_1736_ = select(0f, _e2126, (_e2124 > 0f));
                                    }
                                    let _e2129 = phi_1736_;
                                    let _e2131 = ((_e2129 * 1023f) + 0.5f);
                                    let _e2140 = local_153;
                                    let _e2142 = local_150;
                                    local_155 = ((_e2140 | (select(select(u32(_e2131), 0u, !((_e2131 >= 0f))), 4294967295u, (_e2131 > 4294967000f)) << bitcast<u32>(14u))) | (_e2142 << bitcast<u32>(24i)));
                                    let _e2146 = local_40;
                                    local_156 = _e2146.member_13.member_3;
                                    local_157 = bitcast<u32>(_e2146.member_13.member_3);
                                    let _e2150 = local_40;
                                    let _e2155 = local_40;
                                    local_158 = ((_e2150.member_13.member[0] & 65535u) | (_e2155.member_13.member[1] << bitcast<u32>(16i)));
                                    let _e2162 = local_133;
                                    let _e2163 = (4u * _e2162);
                                    local_159 = _e2163;
                                    let _e2164 = local_5;
                                    if (_e2163 < _e2164) {
                                    } else {
                                        phi_2613_ = true;
                                        phi_2383_ = type_28();
                                        break;
                                    }
                                    let _e2166 = local_159;
                                    let _e2169 = local_152;
                                    atomicStore((&global_8.member[_e2166]), _e2169);
                                    let _e2170 = local_159;
                                    let _e2171 = (_e2170 + 1u);
                                    local_160 = _e2171;
                                    let _e2172 = local_5;
                                    if (_e2171 < _e2172) {
                                    } else {
                                        phi_2613_ = true;
                                        phi_2383_ = type_28();
                                        break;
                                    }
                                    let _e2174 = local_160;
                                    let _e2177 = local_155;
                                    atomicStore((&global_8.member[_e2174]), _e2177);
                                    let _e2178 = local_159;
                                    let _e2179 = (_e2178 + 2u);
                                    local_161 = _e2179;
                                    let _e2180 = local_5;
                                    if (_e2179 < _e2180) {
                                    } else {
                                        phi_2613_ = true;
                                        phi_2383_ = type_28();
                                        break;
                                    }
                                    let _e2182 = local_161;
                                    let _e2185 = local_157;
                                    atomicStore((&global_8.member[_e2182]), _e2185);
                                    let _e2186 = local_159;
                                    let _e2187 = (_e2186 + 3u);
                                    local_162 = _e2187;
                                    let _e2188 = local_5;
                                    if (_e2187 < _e2188) {
                                    } else {
                                        phi_2613_ = true;
                                        phi_2383_ = type_28();
                                        break;
                                    }
                                    let _e2190 = local_162;
                                    let _e2193 = local_158;
                                    atomicStore((&global_8.member[_e2190]), _e2193);
                                    let _e2194 = local_18;
                                    let _e2197 = ((_e2194 >> bitcast<u32>(8u)) & 7u);
                                    local_163 = _e2197;
                                    if (_e2197 > 0u) {
                                        let _e2199 = local_40;
                                        local_164 = _e2199.member_13.member_5;
                                        if (_e2199.member_13.member_5 != 0u) {
                                            let _e2203 = local_163;
                                            let _e2204 = local_163;
                                            let _e2205 = (_e2203 * _e2204);
                                            local_165 = _e2205;
                                            if (_e2205 <= 1u) {
                                                phi_1841_ = 1u;
                                            } else {
                                                let _e2207 = local_165;
                                                phi_1841_ = select(16u, 4u, (_e2207 <= 4u));
                                            }
                                            let _e2211 = phi_1841_;
                                            local_166 = _e2211;
                                            if (_e2211 == 0u) {
                                                phi_2613_ = true;
                                                phi_2383_ = type_28();
                                                break;
                                            }
                                            let _e2213 = local_166;
                                            local_167 = (32u / _e2213);
                                            let _e2215 = local_166;
                                            if (_e2215 >= 32u) {
                                                phi_1854_ = 4294967295u;
                                            } else {
                                                let _e2217 = local_166;
                                                phi_1854_ = ((1u << bitcast<u32>((_e2217 & 31u))) - 1u);
                                            }
                                            let _e2223 = phi_1854_;
                                            local_168 = _e2223;
                                            let _e2224 = local_16;
                                            let _e2225 = local_17;
                                            let _e2227 = local_15;
                                            let _e2229 = local_15;
                                            let _e2231 = local_12;
                                            local_169 = (4u * ((((_e2224 * _e2225) * _e2227) * _e2229) * _e2231));
                                            let _e2234 = local_167;
                                            let _e2235 = (_e2234 == 0u);
                                            local_170 = _e2235;
                                            if _e2235 {
                                                phi_2613_ = true;
                                                phi_2383_ = type_28();
                                                break;
                                            }
                                            let _e2236 = local_133;
                                            let _e2237 = local_167;
                                            let _e2239 = local_169;
                                            local_171 = (_e2239 + (_e2236 / _e2237));
                                            let _e2241 = local_170;
                                            if _e2241 {
                                                phi_2613_ = true;
                                                phi_2383_ = type_28();
                                                break;
                                            }
                                            let _e2242 = local_133;
                                            let _e2243 = local_167;
                                            let _e2245 = local_166;
                                            let _e2247 = local_164;
                                            let _e2248 = local_168;
                                            local_172 = ((_e2247 & _e2248) << bitcast<u32>((((_e2242 % _e2243) * _e2245) & 31u)));
                                            let _e2253 = local_171;
                                            let _e2254 = local_5;
                                            if (_e2253 < _e2254) {
                                            } else {
                                                phi_2613_ = true;
                                                phi_2383_ = type_28();
                                                break;
                                            }
                                            let _e2256 = local_171;
                                            let _e2259 = local_172;
                                            let _e2260 = atomicAdd((&global_8.member[_e2256]), _e2259);
                                        }
                                    }
                                    let _e2261 = local_40;
                                    if (_e2261.member_13.member_5 != 0u) {
                                        phi_1914_ = 1.4142135f;
                                    } else {
                                        let _e2265 = local_151;
                                        phi_1914_ = (0.5f * f32((1u << bitcast<u32>((_e2265 & 31u)))));
                                    }
                                    let _e2272 = phi_1914_;
                                    local_173 = _e2272;
                                    let _e2273 = local_157;
                                    if (_e2273 == 2139095040u) {
                                        let _e2308 = local_20;
                                        let _e2310 = local_19;
                                        let _e2312 = local_21;
                                        let _e2313 = local_19;
                                        let _e2316 = local_22;
                                        phi_1980_ = (0.5f * ((((2f * _e2308) * _e2310) / (_e2312 - _e2313)) * _e2316));
                                    } else {
                                        let _e2275 = local_157;
                                        if (_e2275 == 0u) {
                                            phi_1943_ = false;
                                        } else {
                                            let _e2277 = local_157;
                                            phi_1943_ = (_e2277 <= 2139095040u);
                                        }
                                        let _e2280 = phi_1943_;
                                        if _e2280 {
                                            let _e2281 = local_20;
                                            let _e2283 = local_19;
                                            let _e2285 = local_21;
                                            let _e2286 = local_19;
                                            let _e2289 = local_22;
                                            let _e2290 = ((((2f * _e2281) * _e2283) / (_e2285 - _e2286)) * _e2289);
                                            local_174 = _e2290;
                                            if (_e2290 == 0f) {
                                                phi_1971_ = 0f;
                                            } else {
                                                let _e2292 = local_21;
                                                let _e2293 = local_156;
                                                let _e2296 = local_174;
                                                phi_1971_ = (_e2296 * (1f - (_e2292 / _e2293)));
                                            }
                                            let _e2299 = phi_1971_;
                                            phi_1972_ = _e2299;
                                        } else {
                                            phi_1972_ = _e291;
                                        }
                                        let _e2301 = phi_1972_;
                                        local_175 = _e2301;
                                        if (_e2301 < 0f) {
                                            let _e2303 = local_175;
                                            phi_1978_ = -(_e2303);
                                        } else {
                                            phi_1978_ = _e2301;
                                        }
                                        let _e2306 = phi_1978_;
                                        phi_1980_ = (0.5f * _e2306);
                                    }
                                    let _e2320 = phi_1980_;
                                    let _e2325 = local_173;
                                    let _e2326 = (select(_e2320, 0f, ((bitcast<u32>(_e2320) & 2147483647u) > 2139095040u)) + _e2325);
                                    let _e2327 = local_10;
                                    let _e2329 = local_10;
                                    let _e2331 = local_10;
                                    let _e2332 = select(_e2331, _e2326, (_e2326 < _e2329));
                                    let _e2334 = select(0.5f, _e2332, (_e2332 > 0.5f));
                                    let _e2335 = local_41;
                                    let _e2337 = local_41;
                                    let _e2340 = local_42;
                                    phi_2615_ = _e2102;
                                    phi_2007_ = select(_e2337, _e2334, (_e2334 > _e2335));
                                    phi_2008_ = (_e2340 + select(0u, 1u, (_e2326 > _e2327)));
                                } else {
                                    phi_2615_ = _e1916;
                                    phi_2007_ = _e435;
                                    phi_2008_ = _e437;
                                }
                                let _e2343 = phi_2615_;
                                let _e2345 = phi_2007_;
                                let _e2347 = phi_2008_;
                                let _e2348 = local_43;
                                phi_2614_ = _e2343;
                                phi_408_ = _e2345;
                                phi_410_ = _e2347;
                                phi_412_ = (_e2348 + 1u);
                            } else {
                                phi_2614_ = _e1916;
                                phi_408_ = f32();
                                phi_410_ = u32();
                                phi_412_ = u32();
                            }
                            let _e2351 = phi_2614_;
                            let _e2353 = phi_408_;
                            let _e2355 = phi_410_;
                            let _e2357 = phi_412_;
                            continue;
                            continuing {
                                let _e2358 = local_132;
                                phi_2559_ = _e2351;
                                phi_404_ = _e1918;
                                phi_407_ = _e2353;
                                phi_409_ = _e2355;
                                phi_411_ = _e2357;
                                phi_2613_ = _e2351;
                                phi_2383_ = _e1918;
                                break if !(_e2358);
                            }
                        }
                        let _e2361 = phi_2613_;
                        let _e2363 = phi_2383_;
                        local_199 = _e2363;
                        phi_2634_ = _e2361;
                        if _e2361 {
                            break;
                        }
                        let _e2364 = local_199;
                        local_176 = _e2364.member_5;
                        let _e2366 = (_e2364.member_5 == 1u);
                        local_177 = _e2366;
                        if _e2366 {
                            phi_2017_ = true;
                        } else {
                            let _e2367 = local_176;
                            phi_2017_ = (_e2367 == 2u);
                        }
                        let _e2370 = phi_2017_;
                        if _e2370 {
                            let _e2399 = local_199;
                            local_178 = _e2399.member.member;
                            let _e2402 = local_199;
                            local_179 = _e2402.member_6;
                            let _e2404 = local_27;
                            let _e2405 = (4u * _e2404);
                            local_180 = _e2405;
                            local_181 = bitcast<u32>(_e2399.member.member[0]);
                            let _e2408 = local_4;
                            if (_e2405 < _e2408) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2410 = local_180;
                            let _e2413 = local_181;
                            global_7.member[_e2410] = _e2413;
                            let _e2414 = local_180;
                            let _e2415 = (_e2414 + 1u);
                            local_182 = _e2415;
                            let _e2416 = local_178;
                            local_183 = bitcast<u32>(_e2416[1]);
                            let _e2419 = local_4;
                            if (_e2415 < _e2419) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2421 = local_182;
                            let _e2424 = local_183;
                            global_7.member[_e2421] = _e2424;
                            let _e2425 = local_180;
                            let _e2426 = (_e2425 + 2u);
                            local_184 = _e2426;
                            let _e2427 = local_178;
                            local_185 = bitcast<u32>(_e2427[2]);
                            let _e2430 = local_4;
                            if (_e2426 < _e2430) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2432 = local_184;
                            let _e2435 = local_185;
                            global_7.member[_e2432] = _e2435;
                            let _e2436 = local_180;
                            let _e2437 = (_e2436 + 3u);
                            local_186 = _e2437;
                            let _e2438 = local_179;
                            local_187 = bitcast<u32>(_e2438);
                            let _e2440 = local_4;
                            if (_e2437 < _e2440) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2442 = local_186;
                            let _e2445 = local_187;
                            global_7.member[_e2442] = _e2445;
                        } else {
                            let _e2371 = local_27;
                            let _e2372 = (4u * _e2371);
                            local_188 = _e2372;
                            let _e2373 = local_4;
                            if (_e2372 < _e2373) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2375 = local_188;
                            global_7.member[_e2375] = 0u;
                            let _e2378 = local_188;
                            let _e2379 = (_e2378 + 1u);
                            local_189 = _e2379;
                            let _e2380 = local_4;
                            if (_e2379 < _e2380) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2382 = local_189;
                            global_7.member[_e2382] = 0u;
                            let _e2385 = local_188;
                            let _e2386 = (_e2385 + 2u);
                            local_190 = _e2386;
                            let _e2387 = local_4;
                            if (_e2386 < _e2387) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2389 = local_190;
                            global_7.member[_e2389] = 0u;
                            let _e2392 = local_188;
                            let _e2393 = (_e2392 + 3u);
                            local_191 = _e2393;
                            let _e2394 = local_4;
                            if (_e2393 < _e2394) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2396 = local_191;
                            global_7.member[_e2396] = 2143289344u;
                        }
                        let _e2446 = local_13;
                        if (_e2446 == 1u) {
                            let _e2448 = local_27;
                            let _e2449 = local_3;
                            if (_e2448 < _e2449) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2451 = local_27;
                            let _e2454 = local_43;
                            global_6.member[_e2451] = _e2454;
                            let _e2455 = local_23;
                            let _e2456 = local_27;
                            let _e2457 = (_e2455 + _e2456);
                            local_192 = _e2457;
                            let _e2458 = local_41;
                            local_193 = bitcast<u32>(_e2458);
                            let _e2460 = local_3;
                            if (_e2457 < _e2460) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2462 = local_192;
                            let _e2465 = local_193;
                            global_6.member[_e2462] = _e2465;
                            let _e2466 = local_42;
                            if (_e2466 > 0u) {
                                let _e2468 = local_6;
                                if (6u < _e2468) {
                                } else {
                                    phi_2634_ = true;
                                    break;
                                }
                                let _e2472 = local_42;
                                let _e2473 = atomicAdd((&global_9.member[6u]), _e2472);
                            }
                        }
                        let _e2474 = local_199;
                        if (_e2474.member_2 == 0u) {
                            let _e2477 = local_6;
                            if (2u < _e2477) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2481 = atomicAdd((&global_9.member[2u]), 1u);
                        }
                        let _e2482 = local_177;
                        if _e2482 {
                            phi_2240_ = true;
                        } else {
                            let _e2483 = local_176;
                            phi_2240_ = (_e2483 == 2u);
                        }
                        let _e2486 = phi_2240_;
                        if _e2486 {
                            let _e2487 = local_6;
                            if (11u < _e2487) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2491 = atomicAdd((&global_9.member[11u]), 1u);
                        }
                        let _e2492 = local_199;
                        if (_e2492.member_18 > 0u) {
                            let _e2495 = local_6;
                            if (21u < _e2495) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2499 = atomicAdd((&global_9.member[21u]), 1u);
                        }
                        let _e2500 = local_199;
                        local_194 = _e2500.member_17;
                        if (_e2500.member_17 > 0u) {
                            let _e2503 = local_6;
                            if (12u < _e2503) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2507 = local_194;
                            let _e2508 = atomicAdd((&global_9.member[12u]), _e2507);
                        }
                        let _e2509 = local_199;
                        local_195 = _e2509.member_14;
                        if (_e2509.member_14 > 0u) {
                            let _e2512 = local_6;
                            if (0u < _e2512) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2516 = local_195;
                            let _e2517 = atomicAdd((&global_9.member[0u]), _e2516);
                        }
                        let _e2518 = local_199;
                        local_196 = _e2518.member_15;
                        if (_e2518.member_15 > 0u) {
                            let _e2521 = local_6;
                            if (1u < _e2521) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2525 = local_196;
                            let _e2526 = atomicAdd((&global_9.member[1u]), _e2525);
                        }
                        let _e2527 = local_199;
                        local_197 = _e2527.member_16;
                        if (_e2527.member_16 > 0u) {
                            let _e2530 = local_6;
                            if (20u < _e2530) {
                            } else {
                                phi_2634_ = true;
                                break;
                            }
                            let _e2534 = local_197;
                            let _e2535 = atomicAdd((&global_9.member[20u]), _e2534);
                        }
                        phi_2636_ = _e2361;
                    } else {
                        phi_2636_ = _e352;
                    }
                    let _e2537 = phi_2636_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e2538 = local_25;
                    let _e2539 = local_24;
                    phi_2635_ = _e2537;
                    phi_274_ = (_e2538 + _e2539);
                } else {
                    phi_2635_ = _e352;
                    phi_274_ = u32();
                }
                let _e2542 = phi_2635_;
                let _e2544 = phi_274_;
                continue;
                continuing {
                    let _e2545 = local_26;
                    phi_2562_ = _e2542;
                    phi_273_ = _e2544;
                    phi_2634_ = _e2542;
                    break if !(_e2545);
                }
            }
            let _e2548 = phi_2634_;
            if _e2548 {
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
