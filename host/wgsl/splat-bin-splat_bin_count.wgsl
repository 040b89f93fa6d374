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
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_17 {
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
    member_16: type_16,
    member_17: u32,
    member_18: u32,
}

struct type_18 {
    member: type_17,
}

struct type_21 {
    member: array<u32, 2>,
    member_1: array<f32, 3>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_24 {
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
    member_11: u32,
    member_12: u32,
    member_13: u32,
    member_14: bool,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<immediate> global_2: type_18;
@group(0) @binding(4) 
var<storage> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage> global_6: type_7;
@group(0) @binding(3) 
var<storage> global_7: type_7;
@group(0) @binding(5) 
var<storage, read_write> global_8: type_7;
@group(0) @binding(6) 
var<storage, read_write> global_9: type_7;
@group(0) @binding(7) 
var<storage> global_10: type_7;
var<workgroup> global_11: array<u32, 1792>;
var<private> global_12: u32 = 2143289344u;

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
    var local_11: type_17;
    var local_12: u32;
    var local_13: f32;
    var local_14: u32;
    var local_15: u32;
    var local_16: bool;
    var local_17: u32;
    var local_18: i32;
    var local_19: bool;
    var local_20: i32;
    var local_21: i32;
    var local_22: i32;
    var local_23: i32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: f32;
    var local_28: bool;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: u32;
    var local_34: u32;
    var local_35: bool;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: bool;
    var local_54: u32;
    var local_55: u32;
    var local_56: bool;
    var local_57: u32;
    var local_58: u32;
    var local_59: bool;
    var local_60: u32;
    var local_61: u32;
    var local_62: u32;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: u32;
    var local_67: u32;
    var local_68: type_24;
    var local_69: u32;
    var local_70: u32;
    var local_71: bool;
    var local_72: u32;
    var local_73: u32;
    var local_74: u32;
    var local_75: u32;
    var local_76: u32;
    var local_77: u32;
    var local_78: u32;
    var local_79: bool;
    var local_80: u32;
    var local_81: u32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: type_24;
    var local_86: u32;
    var local_87: u32;
    var local_88: bool;
    var local_89: u32;
    var local_90: u32;
    var local_91: u32;
    var local_92: bool;
    var local_93: u32;
    var local_94: u32;
    var local_95: bool;
    var local_96: u32;
    var local_97: u32;
    var local_98: u32;
    var local_99: bool;
    var local_100: type_24;
    var local_101: bool;
    var local_102: u32;
    var local_103: type_24;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: type_24;
    var local_109: u32;
    var local_110: type_24;
    var local_111: u32;
    var local_112: bool;
    var local_113: u32;
    var local_114: u32;
    var local_115: bool;
    var local_116: u32;
    var local_117: type_24;
    var local_118: u32;
    var local_119: bool;
    var local_120: u32;
    var local_121: type_24;
    var local_122: u32;
    var local_123: u32;
    var local_124: u32;
    var local_125: u32;
    var local_126: type_24;
    var local_127: u32;
    var local_128: u32;
    var local_129: u32;
    var local_130: u32;
    var local_131: u32;
    var local_132: u32;
    var local_133: u32;
    var local_134: u32;
    var local_135: u32;
    var local_136: u32;
    var local_137: u32;
    var local_138: u32;
    var local_139: u32;
    var local_140: u32;
    var local_141: u32;
    var local_142: u32;
    var local_143: u32;
    var local_144: u32;
    var local_145: u32;
    var local_146: u32;
    var local_147: array<f32, 3>;
    var local_148: u32;
    var local_149: f32;
    var local_150: f32;
    var local_151: u32;
    var local_152: array<u32, 2>;
    var local_153: u32;
    var local_154: u32;
    var local_155: u32;
    var local_156: u32;
    var local_157: u32;
    var local_158: u32;
    var local_159: bool;
    var local_160: u32;
    var local_161: u32;
    var local_162: type_21;
    var local_163: f32;
    var local_164: f32;
    var local_165: u32;
    var local_166: f32;
    var local_167: f32;
    var local_168: f32;
    var local_169: u32;
    var local_170: u32;
    var local_171: bool;
    var local_172: u32;
    var local_173: bool;
    var local_174: u32;
    var local_175: bool;
    var local_176: u32;
    var local_177: bool;
    var local_178: u32;
    var local_179: u32;
    var local_180: u32;
    var local_181: u32;
    var local_182: bool;
    var local_183: u32;
    var local_184: bool;
    var local_185: u32;
    var local_186: bool;
    var local_187: u32;
    var local_188: bool;
    var local_189: u32;
    var local_190: bool;
    var local_191: u32;
    var local_192: bool;
    var local_193: u32;
    var local_194: bool;
    var local_195: u32;
    var local_196: u32;
    var local_197: u32;
    var local_198: u32;
    var local_199: u32;
    var local_200: bool;
    var local_201: u32;
    var local_202: u32;
    var local_203: u32;
    var local_204: u32;
    var local_205: u32;
    var local_206: bool;
    var local_207: u32;
    var local_208: u32;
    var local_209: u32;
    var local_210: u32;
    var local_211: u32;
    var local_212: bool;
    var local_213: u32;
    var local_214: u32;
    var local_215: u32;
    var local_216: u32;
    var local_217: u32;
    var local_218: bool;
    var local_219: u32;
    var local_220: u32;
    var local_221: u32;
    var local_222: u32;
    var local_223: u32;
    var local_224: u32;
    var local_225: u32;
    var local_226: u32;
    var local_227: u32;
    var local_228: u32;
    var local_229: u32;
    var local_230: u32;
    var local_231: u32;
    var local_232: u32;
    var local_233: u32;
    var local_234: f32;
    var phi_342_: bool;
    var phi_353_: u32;
    var phi_355_: u32;
    var phi_356_: u32;
    var phi_357_: u32;
    var phi_358_: u32;
    var phi_359_: u32;
    var phi_360_: u32;
    var phi_361_: u32;
    var phi_362_: u32;
    var phi_363_: u32;
    var phi_364_: u32;
    var phi_365_: u32;
    var phi_366_: u32;
    var phi_520_: u32;
    var phi_523_: u32;
    var phi_559_: u32;
    var phi_521_: u32;
    var phi_524_: u32;
    var phi_2621_: bool;
    var phi_2665_: bool;
    var phi_603_: u32;
    var phi_606_: u32;
    var phi_608_: u32;
    var phi_610_: u32;
    var phi_612_: u32;
    var phi_614_: u32;
    var phi_616_: u32;
    var phi_618_: u32;
    var phi_627_: u32;
    var phi_630_: u32;
    var phi_654_: u32;
    var phi_628_: u32;
    var phi_631_: u32;
    var phi_2661_: bool;
    var phi_2673_: bool;
    var phi_657_: u32;
    var phi_660_: u32;
    var phi_662_: u32;
    var phi_664_: u32;
    var phi_666_: u32;
    var phi_668_: u32;
    var phi_670_: type_24;
    var phi_672_: u32;
    var phi_687_: type_24;
    var phi_713_: type_24;
    var phi_688_: type_24;
    var phi_714_: bool;
    var phi_2669_: bool;
    var phi_734_: u32;
    var phi_803_: u32;
    var phi_806_: u32;
    var phi_830_: u32;
    var phi_846_: u32;
    var phi_852_: u32;
    var phi_804_: u32;
    var phi_807_: u32;
    var phi_2674_: bool;
    var phi_856_: u32;
    var phi_859_: u32;
    var phi_883_: u32;
    var phi_899_: u32;
    var phi_905_: u32;
    var phi_857_: u32;
    var phi_860_: u32;
    var phi_2683_: bool;
    var phi_924_: u32;
    var phi_964_: u32;
    var phi_947_: u32;
    var phi_965_: u32;
    var phi_2704_: bool;
    var phi_1077_: type_24;
    var phi_1079_: type_24;
    var phi_1101_: u32;
    var phi_1122_: u32;
    var phi_1167_: u32;
    var phi_1148_: u32;
    var phi_1168_: u32;
    var phi_1080_: type_24;
    var phi_2689_: bool;
    var phi_1775_: u32;
    var phi_1793_: u32;
    var phi_1365_: array<f32, 3>;
    var phi_1376_: f32;
    var phi_1401_: u32;
    var phi_1414_: u32;
    var phi_1448_: type_21;
    var phi_1459_: f32;
    var phi_1483_: bool;
    var phi_1505_: f32;
    var phi_1506_: f32;
    var phi_1512_: f32;
    var phi_1514_: f32;
    var phi_1615_: u32;
    var phi_1616_: u32;
    var phi_1636_: bool;
    var phi_1650_: u32;
    var phi_1651_: u32;
    var phi_1671_: bool;
    var phi_1685_: u32;
    var phi_1686_: u32;
    var phi_1706_: bool;
    var phi_1720_: u32;
    var phi_1721_: u32;
    var phi_1741_: bool;
    var phi_1753_: u32;
    var phi_1754_: u32;
    var phi_1755_: u32;
    var phi_1756_: u32;
    var phi_1757_: u32;
    var phi_1758_: u32;
    var phi_1795_: u32;
    var phi_1796_: u32;
    var phi_1797_: u32;
    var phi_1798_: u32;
    var phi_1799_: u32;
    var phi_1800_: u32;
    var phi_1801_: u32;
    var phi_2720_: bool;
    var phi_1802_: u32;
    var phi_1803_: u32;
    var phi_1804_: u32;
    var phi_1805_: u32;
    var phi_1806_: u32;
    var phi_1807_: u32;
    var phi_1808_: type_24;
    var phi_1809_: u32;
    var phi_2719_: bool;
    var phi_658_: u32;
    var phi_661_: u32;
    var phi_663_: u32;
    var phi_665_: u32;
    var phi_667_: u32;
    var phi_669_: u32;
    var phi_671_: type_24;
    var phi_673_: u32;
    var phi_1810_: bool;
    var phi_2718_: bool;
    var phi_1823_: u32;
    var phi_2759_: bool;
    var phi_604_: u32;
    var phi_607_: u32;
    var phi_609_: u32;
    var phi_611_: u32;
    var phi_613_: u32;
    var phi_615_: u32;
    var phi_617_: u32;
    var phi_619_: u32;
    var phi_2758_: bool;
    var phi_1958_: u32;
    var phi_1959_: u32;
    var phi_2761_: bool;
    var phi_2091_: u32;
    var phi_2092_: u32;
    var phi_2783_: bool;
    var phi_2224_: u32;
    var phi_2225_: u32;
    var phi_2807_: bool;
    var phi_2357_: u32;
    var phi_2358_: u32;
    var phi_2831_: bool;
    var phi_2490_: u32;
    var phi_2491_: u32;
    var phi_2855_: bool;
    var local_235: type_24;
    var local_236: type_24;
    var local_237: u32;
    var local_238: u32;
    var local_239: u32;
    var local_240: u32;
    var local_241: u32;

    let _e296 = global_12;
    switch bitcast<i32>(0u) {
        default: {
            let _e299 = global;
            local = _e299;
            let _e300 = global_1;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_3.member));
            local_6 = arrayLength((&global_8.member));
            local_7 = arrayLength((&global_9.member));
            let _e317 = arrayLength((&global_10.member));
            local_8 = _e317;
            local_9 = _e300.x;
            local_10 = _e300.y;
            let _e320 = global_2.member;
            local_11 = _e320;
            if (18u < _e317) {
            } else {
                break;
            }
            let _e324 = global_10.member[18u];
            local_12 = _e324;
            let _e325 = local_8;
            if (19u < _e325) {
            } else {
                break;
            }
            let _e329 = global_10.member[19u];
            local_13 = bitcast<f32>(_e329);
            let _e331 = local_11;
            local_14 = _e331.member_7;
            let _e333 = local_10;
            let _e335 = local_9;
            let _e336 = ((_e333 * _e331.member_7) + _e335);
            local_15 = _e336;
            let _e337 = local_5;
            if (_e336 < _e337) {
            } else {
                break;
            }
            let _e339 = local_15;
            let _e342 = global_3.member[_e339];
            local_16 = (_e342 != 0u);
            let _e344 = local_12;
            let _e346 = ((2u * _e344) + 1u);
            local_17 = _e346;
            let _e348 = local;
            if (_e348 < (_e346 * _e346)) {
                let _e350 = local_16;
                if _e350 {
                    phi_363_ = 0u;
                    phi_364_ = 0u;
                } else {
                    let _e351 = local_9;
                    local_18 = bitcast<i32>(_e351);
                    let _e353 = local_17;
                    let _e354 = (_e353 == 0u);
                    local_19 = _e354;
                    if _e354 {
                        break;
                    }
                    let _e355 = local;
                    let _e356 = local_17;
                    let _e359 = local_18;
                    let _e361 = local_12;
                    let _e362 = bitcast<i32>(_e361);
                    local_20 = _e362;
                    local_21 = ((_e359 + bitcast<i32>((_e355 % _e356))) - _e362);
                    let _e364 = local_10;
                    local_22 = bitcast<i32>(_e364);
                    let _e366 = local_19;
                    if _e366 {
                        break;
                    }
                    let _e367 = local;
                    let _e368 = local_17;
                    let _e371 = local_22;
                    let _e373 = local_20;
                    local_23 = ((_e371 + bitcast<i32>((_e367 / _e368))) - _e373);
                    let _e375 = local_21;
                    if (_e375 >= 0i) {
                        let _e377 = local_23;
                        if (_e377 >= 0i) {
                            let _e379 = local_14;
                            let _e381 = local_21;
                            if (_e381 < bitcast<i32>(_e379)) {
                                let _e383 = local_11;
                                let _e386 = local_23;
                                if (_e386 < bitcast<i32>(_e383.member_8)) {
                                    let _e388 = local_23;
                                    let _e389 = bitcast<u32>(_e388);
                                    local_24 = _e389;
                                    let _e390 = local_14;
                                    let _e392 = local_21;
                                    let _e393 = bitcast<u32>(_e392);
                                    local_25 = _e393;
                                    let _e394 = ((_e389 * _e390) + _e393);
                                    local_26 = _e394;
                                    let _e395 = local_4;
                                    if (_e394 < _e395) {
                                    } else {
                                        break;
                                    }
                                    let _e397 = local_26;
                                    let _e400 = global_7.member[_e397];
                                    local_27 = bitcast<f32>(_e400);
                                    let _e402 = local_26;
                                    let _e403 = local_15;
                                    if (_e402 == _e403) {
                                        phi_342_ = true;
                                    } else {
                                        let _e405 = local_11;
                                        let _e407 = local_11;
                                        let _e409 = local_25;
                                        let _e411 = ((_e409 + 1u) * _e405.member_6);
                                        let _e414 = local_25;
                                        let _e418 = local_11;
                                        let _e420 = local_24;
                                        let _e422 = ((_e420 + 1u) * _e405.member_6);
                                        let _e425 = local_24;
                                        let _e429 = local_9;
                                        let _e431 = ((_e429 + 1u) * _e405.member_6);
                                        let _e434 = local_9;
                                        let _e438 = local_10;
                                        let _e440 = ((_e438 + 1u) * _e405.member_6);
                                        let _e443 = local_10;
                                        let _e449 = ((f32((_e434 * _e405.member_6)) + 0.5f) - f32(select(_e407.member, _e411, (_e411 < _e407.member))));
                                        let _e450 = (f32((_e414 * _e405.member_6)) - (f32(select(_e407.member, _e431, (_e431 < _e407.member))) - 0.5f));
                                        let _e452 = select(_e450, _e449, (_e449 > _e450));
                                        let _e454 = select(0f, _e452, (_e452 > 0f));
                                        let _e457 = ((f32((_e443 * _e405.member_6)) + 0.5f) - f32(select(_e418.member_1, _e422, (_e422 < _e418.member_1))));
                                        let _e458 = (f32((_e425 * _e405.member_6)) - (f32(select(_e418.member_1, _e440, (_e440 < _e418.member_1))) - 0.5f));
                                        let _e460 = select(_e458, _e457, (_e457 > _e458));
                                        let _e462 = select(0f, _e460, (_e460 > 0f));
                                        let _e466 = local_27;
                                        let _e467 = local_27;
                                        phi_342_ = (((_e454 * _e454) + (_e462 * _e462)) <= (_e466 * _e467));
                                    }
                                    let _e471 = phi_342_;
                                    local_28 = _e471;
                                    if _e471 {
                                        let _e472 = local_26;
                                        let _e473 = local_2;
                                        if (_e472 < _e473) {
                                        } else {
                                            break;
                                        }
                                        let _e475 = local_26;
                                        let _e478 = global_5.member[_e475];
                                        phi_353_ = _e478;
                                    } else {
                                        phi_353_ = 0u;
                                    }
                                    let _e480 = phi_353_;
                                    let _e481 = local_28;
                                    let _e482 = local_26;
                                    phi_355_ = _e480;
                                    phi_356_ = select(0u, _e482, _e481);
                                } else {
                                    phi_355_ = 0u;
                                    phi_356_ = 0u;
                                }
                                let _e485 = phi_355_;
                                let _e487 = phi_356_;
                                phi_357_ = _e485;
                                phi_358_ = _e487;
                            } else {
                                phi_357_ = 0u;
                                phi_358_ = 0u;
                            }
                            let _e489 = phi_357_;
                            let _e491 = phi_358_;
                            phi_359_ = _e489;
                            phi_360_ = _e491;
                        } else {
                            phi_359_ = 0u;
                            phi_360_ = 0u;
                        }
                        let _e493 = phi_359_;
                        let _e495 = phi_360_;
                        phi_361_ = _e493;
                        phi_362_ = _e495;
                    } else {
                        phi_361_ = 0u;
                        phi_362_ = 0u;
                    }
                    let _e497 = phi_361_;
                    let _e499 = phi_362_;
                    phi_363_ = _e497;
                    phi_364_ = _e499;
                }
                let _e501 = phi_363_;
                let _e503 = phi_364_;
                phi_365_ = _e501;
                phi_366_ = _e503;
            } else {
                phi_365_ = 0u;
                phi_366_ = 0u;
            }
            let _e505 = phi_365_;
            let _e507 = phi_366_;
            local_29 = _e505;
            local_30 = _e507;
            let _e508 = local;
            let _e509 = (768u + _e508);
            local_31 = _e509;
            if (_e509 < 1792u) {
            } else {
                break;
            }
            let _e511 = local_31;
            let _e513 = local_29;
            global_11[_e511] = _e513;
            let _e514 = local;
            let _e515 = (1280u + _e514);
            local_32 = _e515;
            if (_e515 < 1792u) {
            } else {
                break;
            }
            let _e517 = local_32;
            let _e519 = local_30;
            global_11[_e517] = _e519;
            storageBarrier();
            workgroupBarrier();
            phi_520_ = 1u;
            phi_523_ = 768u;
            loop {
                let _e521 = phi_520_;
                let _e523 = phi_523_;
                local_33 = _e521;
                local_34 = _e523;
                let _e524 = local_33;
                let _e525 = (_e524 < 256u);
                local_35 = _e525;
                if _e525 {
                    let _e526 = local_34;
                    let _e528 = select(768u, 1024u, (_e526 == 768u));
                    local_228 = _e528;
                    let _e529 = local_34;
                    let _e530 = local;
                    let _e531 = (_e529 + _e530);
                    local_36 = _e531;
                    if (_e531 < 1792u) {
                    } else {
                        phi_2621_ = true;
                        break;
                    }
                    let _e533 = local_36;
                    let _e535 = global_11[_e533];
                    local_37 = _e535;
                    let _e536 = local;
                    let _e537 = local_33;
                    if (_e536 >= _e537) {
                        let _e539 = local;
                        let _e540 = local_33;
                        let _e542 = local_34;
                        let _e543 = (_e542 + (_e539 - _e540));
                        local_38 = _e543;
                        if (_e543 < 1792u) {
                        } else {
                            phi_2621_ = true;
                            break;
                        }
                        let _e545 = local_38;
                        let _e547 = global_11[_e545];
                        let _e548 = local_37;
                        phi_559_ = (_e547 + _e548);
                    } else {
                        phi_559_ = _e535;
                    }
                    let _e551 = phi_559_;
                    local_39 = _e551;
                    let _e552 = local_228;
                    let _e553 = local;
                    let _e554 = (_e552 + _e553);
                    local_40 = _e554;
                    if (_e554 < 1792u) {
                    } else {
                        phi_2621_ = true;
                        break;
                    }
                    let _e556 = local_40;
                    let _e558 = local_39;
                    global_11[_e556] = _e558;
                    storageBarrier();
                    workgroupBarrier();
                    let _e559 = local_33;
                    phi_521_ = (_e559 * 2u);
                    phi_524_ = _e528;
                } else {
                    phi_521_ = u32();
                    phi_524_ = u32();
                }
                let _e562 = phi_521_;
                let _e564 = phi_524_;
                continue;
                continuing {
                    let _e565 = local_35;
                    phi_520_ = _e562;
                    phi_523_ = _e564;
                    phi_2621_ = false;
                    break if !(_e565);
                }
            }
            let _e568 = phi_2621_;
            if _e568 {
                break;
            }
            let _e569 = local_34;
            let _e570 = (_e569 + 255u);
            local_41 = _e570;
            if (_e570 < 1792u) {
            } else {
                break;
            }
            let _e572 = local_41;
            let _e574 = global_11[_e572];
            local_42 = _e574;
            let _e575 = local_11;
            local_43 = _e575.member_10;
            let _e579 = select(16u, 1u, ((_e575.member_10 & 2u) == 0u));
            local_229 = _e579;
            local_44 = (32u >> bitcast<u32>((select(firstTrailingBit(_e579), 32u, (_e579 == 0u)) & 31u)));
            let _e586 = local_34;
            local_230 = select(768u, 1024u, (_e586 == 768u));
            let _e589 = local;
            phi_2665_ = _e568;
            phi_603_ = 0u;
            phi_606_ = 0u;
            phi_608_ = 0u;
            phi_610_ = 0u;
            phi_612_ = 0u;
            phi_614_ = (_e589 * _e579);
            phi_616_ = 0u;
            phi_618_ = 0u;
            loop {
                let _e592 = phi_2665_;
                let _e594 = phi_603_;
                let _e596 = phi_606_;
                let _e598 = phi_608_;
                let _e600 = phi_610_;
                let _e602 = phi_612_;
                let _e604 = phi_614_;
                let _e606 = phi_616_;
                let _e608 = phi_618_;
                local_45 = _e594;
                local_46 = _e596;
                local_47 = _e598;
                local_48 = _e600;
                local_49 = _e602;
                local_50 = _e604;
                local_51 = _e606;
                local_52 = _e608;
                let _e609 = local_50;
                let _e610 = local_42;
                let _e611 = (_e609 < _e610);
                local_53 = _e611;
                if _e611 {
                    phi_627_ = 255u;
                    phi_630_ = 0u;
                    loop {
                        let _e613 = phi_627_;
                        let _e615 = phi_630_;
                        local_54 = _e613;
                        local_55 = _e615;
                        let _e616 = local_55;
                        let _e617 = local_54;
                        let _e618 = (_e616 < _e617);
                        local_56 = _e618;
                        if _e618 {
                            let _e619 = local_55;
                            let _e620 = local_54;
                            let _e622 = ((_e619 + _e620) / 2u);
                            local_57 = _e622;
                            let _e623 = local_34;
                            let _e624 = (_e623 + _e622);
                            local_58 = _e624;
                            if (_e624 < 1792u) {
                            } else {
                                phi_2661_ = true;
                                break;
                            }
                            let _e626 = local_58;
                            let _e628 = global_11[_e626];
                            let _e629 = local_50;
                            let _e630 = (_e628 > _e629);
                            local_59 = _e630;
                            if _e630 {
                                phi_654_ = _e615;
                            } else {
                                let _e631 = local_57;
                                phi_654_ = (_e631 + 1u);
                            }
                            let _e634 = phi_654_;
                            let _e635 = local_59;
                            let _e636 = local_57;
                            let _e637 = local_54;
                            phi_628_ = select(_e637, _e636, _e635);
                            phi_631_ = _e634;
                        } else {
                            phi_628_ = u32();
                            phi_631_ = u32();
                        }
                        let _e640 = phi_628_;
                        let _e642 = phi_631_;
                        continue;
                        continuing {
                            let _e643 = local_56;
                            phi_627_ = _e640;
                            phi_630_ = _e642;
                            phi_2661_ = _e592;
                            break if !(_e643);
                        }
                    }
                    let _e646 = phi_2661_;
                    phi_2758_ = _e646;
                    if _e646 {
                        break;
                    }
                    let _e647 = local_55;
                    let _e648 = local_9;
                    let _e649 = local_10;
                    phi_2673_ = _e646;
                    phi_657_ = 0u;
                    phi_660_ = _e594;
                    phi_662_ = _e596;
                    phi_664_ = _e598;
                    phi_666_ = _e600;
                    phi_668_ = _e602;
                    phi_670_ = type_24(_e647, 4294967295u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, _e648, _e649, false);
                    phi_672_ = 0u;
                    loop {
                        let _e652 = phi_2673_;
                        let _e654 = phi_657_;
                        let _e656 = phi_660_;
                        let _e658 = phi_662_;
                        let _e660 = phi_664_;
                        let _e662 = phi_666_;
                        let _e664 = phi_668_;
                        let _e666 = phi_670_;
                        let _e668 = phi_672_;
                        local_60 = _e654;
                        local_61 = _e656;
                        local_62 = _e658;
                        local_63 = _e660;
                        local_64 = _e662;
                        local_65 = _e664;
                        local_66 = _e668;
                        local_237 = _e656;
                        local_238 = _e658;
                        local_239 = _e660;
                        local_240 = _e662;
                        local_241 = _e664;
                        let _e669 = local_66;
                        let _e670 = local_229;
                        if (_e669 < _e670) {
                            let _e672 = local_50;
                            let _e673 = local_66;
                            let _e674 = (_e672 + _e673);
                            local_67 = _e674;
                            let _e675 = local_42;
                            let _e676 = (_e674 < _e675);
                            if _e676 {
                                phi_687_ = _e666;
                                loop {
                                    let _e678 = phi_687_;
                                    local_68 = _e678;
                                    local_235 = _e678;
                                    let _e679 = local_68;
                                    local_69 = _e679.member;
                                    if (_e679.member < 255u) {
                                        let _e682 = local_34;
                                        let _e683 = local_69;
                                        let _e684 = (_e682 + _e683);
                                        local_70 = _e684;
                                        if (_e684 < 1792u) {
                                        } else {
                                            phi_2669_ = true;
                                            break;
                                        }
                                        let _e686 = local_70;
                                        let _e688 = global_11[_e686];
                                        let _e689 = local_67;
                                        let _e690 = (_e688 <= _e689);
                                        if _e690 {
                                            let _e691 = local_69;
                                            let _e693 = local_68;
                                            phi_713_ = type_24((_e691 + 1u), _e693.member_1, _e693.member_2, _e693.member_3, _e693.member_4, _e693.member_5, _e693.member_6, _e693.member_7, _e693.member_8, _e693.member_9, _e693.member_10, _e693.member_11, _e693.member_12, _e693.member_13, _e693.member_14);
                                        } else {
                                            phi_713_ = type_24();
                                        }
                                        let _e711 = phi_713_;
                                        phi_688_ = _e711;
                                        phi_714_ = _e690;
                                    } else {
                                        phi_688_ = type_24();
                                        phi_714_ = false;
                                    }
                                    let _e713 = phi_688_;
                                    let _e715 = phi_714_;
                                    local_71 = _e715;
                                    continue;
                                    continuing {
                                        let _e716 = local_71;
                                        phi_687_ = _e713;
                                        phi_2669_ = _e652;
                                        break if !(_e716);
                                    }
                                }
                                let _e719 = phi_2669_;
                                phi_2718_ = _e719;
                                if _e719 {
                                    break;
                                }
                                let _e720 = local_69;
                                if (_e720 == 0u) {
                                    phi_734_ = 0u;
                                } else {
                                    let _e722 = local_34;
                                    let _e723 = local_69;
                                    let _e725 = ((_e722 + _e723) - 1u);
                                    local_72 = _e725;
                                    if (_e725 < 1792u) {
                                    } else {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e727 = local_72;
                                    let _e729 = global_11[_e727];
                                    phi_734_ = _e729;
                                }
                                let _e731 = phi_734_;
                                let _e732 = local_67;
                                local_73 = (_e732 - _e731);
                                let _e734 = local_68;
                                let _e736 = local_69;
                                if (_e734.member_1 != _e736) {
                                    let _e738 = local_11;
                                    local_74 = _e738.member_6;
                                    let _e740 = local_11;
                                    local_75 = _e740.member_3;
                                    if (_e740.member_3 == 0u) {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e743 = local_74;
                                    let _e744 = local_75;
                                    local_76 = (_e743 / _e744);
                                    let _e746 = local_69;
                                    let _e747 = (1280u + _e746);
                                    local_77 = _e747;
                                    if (_e747 < 1792u) {
                                    } else {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e749 = local_77;
                                    let _e751 = global_11[_e749];
                                    local_78 = _e751;
                                    let _e752 = local_14;
                                    let _e753 = (_e752 == 0u);
                                    local_79 = _e753;
                                    if _e753 {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e754 = local_78;
                                    let _e755 = local_14;
                                    let _e757 = local_76;
                                    local_80 = ((_e754 % _e755) * _e757);
                                    let _e759 = local_79;
                                    if _e759 {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e760 = local_78;
                                    let _e761 = local_14;
                                    let _e763 = local_76;
                                    let _e764 = ((_e760 / _e761) * _e763);
                                    local_81 = _e764;
                                    let _e765 = local_69;
                                    let _e766 = local_68;
                                    let _e782 = type_24(_e766.member, _e765, _e766.member_2, _e766.member_3, _e766.member_4, _e766.member_5, _e766.member_6, _e766.member_7, _e766.member_8, _e766.member_9, _e766.member_10, _e766.member_11, _e766.member_12, _e766.member_13, _e766.member_14);
                                    let _e783 = local_78;
                                    let _e799 = type_24(_e782.member, _e782.member_1, _e783, _e782.member_3, _e782.member_4, _e782.member_5, _e782.member_6, _e782.member_7, _e782.member_8, _e782.member_9, _e782.member_10, _e782.member_11, _e782.member_12, _e782.member_13, _e782.member_14);
                                    let _e800 = local_11;
                                    local_82 = _e800.member_4;
                                    let _e803 = local_80;
                                    let _e804 = ((_e764 * _e800.member_4) + _e803);
                                    local_83 = _e804;
                                    let _e820 = type_24(_e799.member, _e799.member_1, _e799.member_2, _e804, _e799.member_4, _e799.member_5, _e799.member_6, _e799.member_7, _e799.member_8, _e799.member_9, _e799.member_10, _e799.member_11, _e799.member_12, _e799.member_13, _e799.member_14);
                                    let _e821 = local_80;
                                    let _e837 = type_24(_e820.member, _e820.member_1, _e820.member_2, _e820.member_3, _e821, _e820.member_5, _e820.member_6, _e820.member_7, _e820.member_8, _e820.member_9, _e820.member_10, _e820.member_11, _e820.member_12, _e820.member_13, _e820.member_14);
                                    let _e853 = type_24(_e837.member, _e837.member_1, _e837.member_2, _e837.member_3, _e837.member_4, _e764, _e837.member_6, _e837.member_7, _e837.member_8, _e837.member_9, _e837.member_10, _e837.member_11, _e837.member_12, _e837.member_13, _e837.member_14);
                                    let _e854 = local_80;
                                    let _e855 = (_e800.member_4 - _e854);
                                    let _e856 = local_76;
                                    let _e858 = local_76;
                                    let _e859 = select(_e858, _e855, (_e855 < _e856));
                                    local_231 = _e859;
                                    let _e875 = type_24(_e853.member, _e853.member_1, _e853.member_2, _e853.member_3, _e853.member_4, _e853.member_5, _e859, _e853.member_7, _e853.member_8, _e853.member_9, _e853.member_10, _e853.member_11, _e853.member_12, _e853.member_13, _e853.member_14);
                                    let _e876 = local_11;
                                    local_84 = _e876.member_5;
                                    let _e878 = (_e876.member_5 - _e764);
                                    let _e879 = local_76;
                                    let _e881 = local_76;
                                    let _e882 = select(_e881, _e878, (_e878 < _e879));
                                    local_232 = _e882;
                                    local_85 = type_24(_e875.member, _e875.member_1, _e875.member_2, _e875.member_3, _e875.member_4, _e875.member_5, _e875.member_6, _e882, _e875.member_8, _e875.member_9, _e875.member_10, _e875.member_11, _e875.member_12, _e875.member_13, _e875.member_14);
                                    phi_803_ = (_e882 - 1u);
                                    phi_806_ = 0u;
                                    loop {
                                        let _e901 = phi_803_;
                                        let _e903 = phi_806_;
                                        local_86 = _e901;
                                        local_87 = _e903;
                                        let _e904 = local_87;
                                        let _e905 = local_86;
                                        let _e906 = (_e904 < _e905);
                                        local_88 = _e906;
                                        if _e906 {
                                            let _e907 = local_87;
                                            let _e908 = local_86;
                                            let _e909 = (_e907 + _e908);
                                            let _e910 = (_e909 / 2u);
                                            local_89 = _e910;
                                            if ((_e909 % 2u) > 0u) {
                                                let _e913 = local_89;
                                                phi_830_ = (_e913 + 1u);
                                            } else {
                                                phi_830_ = _e910;
                                            }
                                            let _e916 = phi_830_;
                                            local_90 = _e916;
                                            let _e917 = local_232;
                                            if (_e916 < _e917) {
                                                let _e919 = local_90;
                                                let _e920 = local_82;
                                                let _e922 = local_83;
                                                let _e923 = (_e922 + (_e919 * _e920));
                                                local_91 = _e923;
                                                let _e924 = local_3;
                                                if (_e923 < _e924) {
                                                } else {
                                                    phi_2674_ = true;
                                                    break;
                                                }
                                                let _e926 = local_91;
                                                let _e929 = global_6.member[_e926];
                                                phi_846_ = _e929;
                                            } else {
                                                phi_846_ = 4294967295u;
                                            }
                                            let _e931 = phi_846_;
                                            let _e932 = local_73;
                                            let _e933 = (_e931 <= _e932);
                                            local_92 = _e933;
                                            if _e933 {
                                                phi_852_ = _e901;
                                            } else {
                                                let _e934 = local_90;
                                                phi_852_ = (_e934 - 1u);
                                            }
                                            let _e937 = phi_852_;
                                            let _e938 = local_92;
                                            let _e939 = local_90;
                                            let _e940 = local_87;
                                            phi_804_ = _e937;
                                            phi_807_ = select(_e940, _e939, _e938);
                                        } else {
                                            phi_804_ = u32();
                                            phi_807_ = u32();
                                        }
                                        let _e943 = phi_804_;
                                        let _e945 = phi_807_;
                                        continue;
                                        continuing {
                                            let _e946 = local_88;
                                            phi_803_ = _e943;
                                            phi_806_ = _e945;
                                            phi_2674_ = _e719;
                                            break if !(_e946);
                                        }
                                    }
                                    let _e949 = phi_2674_;
                                    phi_2718_ = _e949;
                                    if _e949 {
                                        break;
                                    }
                                    let _e950 = local_231;
                                    phi_856_ = (_e950 - 1u);
                                    phi_859_ = 0u;
                                    loop {
                                        let _e953 = phi_856_;
                                        let _e955 = phi_859_;
                                        local_93 = _e953;
                                        local_94 = _e955;
                                        let _e956 = local_94;
                                        let _e957 = local_93;
                                        let _e958 = (_e956 < _e957);
                                        local_95 = _e958;
                                        if _e958 {
                                            let _e959 = local_94;
                                            let _e960 = local_93;
                                            let _e961 = (_e959 + _e960);
                                            let _e962 = (_e961 / 2u);
                                            local_96 = _e962;
                                            if ((_e961 % 2u) > 0u) {
                                                let _e965 = local_96;
                                                phi_883_ = (_e965 + 1u);
                                            } else {
                                                phi_883_ = _e962;
                                            }
                                            let _e968 = phi_883_;
                                            local_97 = _e968;
                                            let _e969 = local_87;
                                            let _e970 = local_232;
                                            if (_e969 < _e970) {
                                                let _e972 = local_87;
                                                let _e973 = local_82;
                                                let _e975 = local_83;
                                                let _e977 = local_97;
                                                let _e978 = ((_e975 + (_e972 * _e973)) + _e977);
                                                local_98 = _e978;
                                                let _e979 = local_3;
                                                if (_e978 < _e979) {
                                                } else {
                                                    phi_2683_ = true;
                                                    break;
                                                }
                                                let _e981 = local_98;
                                                let _e984 = global_6.member[_e981];
                                                phi_899_ = _e984;
                                            } else {
                                                phi_899_ = 4294967295u;
                                            }
                                            let _e986 = phi_899_;
                                            let _e987 = local_73;
                                            let _e988 = (_e986 <= _e987);
                                            local_99 = _e988;
                                            if _e988 {
                                                phi_905_ = _e953;
                                            } else {
                                                let _e989 = local_97;
                                                phi_905_ = (_e989 - 1u);
                                            }
                                            let _e992 = phi_905_;
                                            let _e993 = local_99;
                                            let _e994 = local_97;
                                            let _e995 = local_94;
                                            phi_857_ = _e992;
                                            phi_860_ = select(_e995, _e994, _e993);
                                        } else {
                                            phi_857_ = u32();
                                            phi_860_ = u32();
                                        }
                                        let _e998 = phi_857_;
                                        let _e1000 = phi_860_;
                                        continue;
                                        continuing {
                                            let _e1001 = local_95;
                                            phi_856_ = _e998;
                                            phi_859_ = _e1000;
                                            phi_2683_ = _e949;
                                            break if !(_e1001);
                                        }
                                    }
                                    let _e1004 = phi_2683_;
                                    phi_2718_ = _e1004;
                                    if _e1004 {
                                        break;
                                    }
                                    let _e1005 = local_94;
                                    let _e1006 = local_85;
                                    let _e1022 = type_24(_e1006.member, _e1006.member_1, _e1006.member_2, _e1006.member_3, _e1006.member_4, _e1006.member_5, _e1006.member_6, _e1006.member_7, _e1005, _e1006.member_9, _e1006.member_10, _e1006.member_11, _e1006.member_12, _e1006.member_13, _e1006.member_14);
                                    let _e1023 = local_87;
                                    local_100 = type_24(_e1022.member, _e1022.member_1, _e1022.member_2, _e1022.member_3, _e1022.member_4, _e1022.member_5, _e1022.member_6, _e1022.member_7, _e1022.member_8, _e1023, _e1022.member_10, _e1022.member_11, _e1022.member_12, _e1022.member_13, _e1022.member_14);
                                    let _e1040 = local_87;
                                    let _e1041 = local_232;
                                    let _e1042 = (_e1040 < _e1041);
                                    local_101 = _e1042;
                                    if _e1042 {
                                        let _e1043 = local_87;
                                        let _e1044 = local_82;
                                        let _e1046 = local_83;
                                        let _e1048 = local_94;
                                        let _e1049 = ((_e1046 + (_e1043 * _e1044)) + _e1048);
                                        local_102 = _e1049;
                                        let _e1050 = local_3;
                                        if (_e1049 < _e1050) {
                                        } else {
                                            phi_2718_ = true;
                                            break;
                                        }
                                        let _e1052 = local_102;
                                        let _e1055 = global_6.member[_e1052];
                                        phi_924_ = _e1055;
                                    } else {
                                        phi_924_ = 4294967295u;
                                    }
                                    let _e1057 = phi_924_;
                                    let _e1058 = local_100;
                                    local_103 = type_24(_e1058.member, _e1058.member_1, _e1058.member_2, _e1058.member_3, _e1058.member_4, _e1058.member_5, _e1058.member_6, _e1058.member_7, _e1058.member_8, _e1058.member_9, _e1057, _e1058.member_11, _e1058.member_12, _e1058.member_13, _e1058.member_14);
                                    let _e1075 = local_94;
                                    let _e1076 = (_e1075 + 1u);
                                    local_104 = _e1076;
                                    let _e1077 = local_231;
                                    if (_e1076 < _e1077) {
                                        let _e1096 = local_101;
                                        if _e1096 {
                                            let _e1097 = local_87;
                                            let _e1098 = local_82;
                                            let _e1100 = local_83;
                                            let _e1102 = local_104;
                                            let _e1103 = ((_e1100 + (_e1097 * _e1098)) + _e1102);
                                            local_105 = _e1103;
                                            let _e1104 = local_3;
                                            if (_e1103 < _e1104) {
                                            } else {
                                                phi_2718_ = true;
                                                break;
                                            }
                                            let _e1106 = local_105;
                                            let _e1109 = global_6.member[_e1106];
                                            phi_947_ = _e1109;
                                        } else {
                                            phi_947_ = 4294967295u;
                                        }
                                        let _e1111 = phi_947_;
                                        phi_965_ = _e1111;
                                    } else {
                                        let _e1079 = local_87;
                                        let _e1080 = (_e1079 + 1u);
                                        local_106 = _e1080;
                                        let _e1081 = local_232;
                                        if (_e1080 < _e1081) {
                                            let _e1083 = local_106;
                                            let _e1084 = local_82;
                                            let _e1086 = local_83;
                                            let _e1087 = (_e1086 + (_e1083 * _e1084));
                                            local_107 = _e1087;
                                            let _e1088 = local_3;
                                            if (_e1087 < _e1088) {
                                            } else {
                                                phi_2718_ = true;
                                                break;
                                            }
                                            let _e1090 = local_107;
                                            let _e1093 = global_6.member[_e1090];
                                            phi_964_ = _e1093;
                                        } else {
                                            phi_964_ = 4294967295u;
                                        }
                                        let _e1095 = phi_964_;
                                        phi_965_ = _e1095;
                                    }
                                    let _e1113 = phi_965_;
                                    let _e1114 = local_103;
                                    local_108 = type_24(_e1114.member, _e1114.member_1, _e1114.member_2, _e1114.member_3, _e1114.member_4, _e1114.member_5, _e1114.member_6, _e1114.member_7, _e1114.member_8, _e1114.member_9, _e1114.member_10, _e1113, _e1114.member_12, _e1114.member_13, _e1114.member_14);
                                    let _e1131 = local_82;
                                    let _e1132 = local_84;
                                    let _e1134 = local_87;
                                    let _e1135 = local_82;
                                    let _e1137 = local_83;
                                    let _e1139 = local_94;
                                    let _e1141 = ((_e1131 * _e1132) + ((_e1137 + (_e1134 * _e1135)) + _e1139));
                                    local_109 = _e1141;
                                    let _e1142 = local_3;
                                    if (_e1141 < _e1142) {
                                    } else {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e1144 = local_109;
                                    let _e1147 = global_6.member[_e1144];
                                    let _e1148 = bitcast<f32>(_e1147);
                                    let _e1149 = local_80;
                                    let _e1150 = local_94;
                                    let _e1151 = (_e1149 + _e1150);
                                    let _e1152 = local_11;
                                    let _e1155 = local_75;
                                    let _e1156 = ((_e1151 + 1u) * _e1155);
                                    let _e1159 = local_75;
                                    let _e1163 = local_81;
                                    let _e1164 = local_87;
                                    let _e1165 = (_e1163 + _e1164);
                                    let _e1166 = local_11;
                                    let _e1169 = local_75;
                                    let _e1170 = ((_e1165 + 1u) * _e1169);
                                    let _e1173 = local_75;
                                    let _e1177 = local_68;
                                    let _e1179 = local_68;
                                    let _e1182 = local_74;
                                    let _e1183 = ((_e1177.member_12 + 1u) * _e1182);
                                    let _e1186 = local_74;
                                    let _e1191 = local_74;
                                    let _e1192 = ((_e1179.member_13 + 1u) * _e1191);
                                    let _e1195 = local_74;
                                    let _e1201 = ((f32((_e1177.member_12 * _e1186)) + 0.5f) - f32(select(_e1152.member, _e1156, (_e1156 < _e1152.member))));
                                    let _e1202 = (f32((_e1151 * _e1159)) - (f32(select(_e1152.member, _e1183, (_e1183 < _e1152.member))) - 0.5f));
                                    let _e1204 = select(_e1202, _e1201, (_e1201 > _e1202));
                                    let _e1206 = select(0f, _e1204, (_e1204 > 0f));
                                    let _e1209 = ((f32((_e1179.member_13 * _e1195)) + 0.5f) - f32(select(_e1166.member_1, _e1170, (_e1170 < _e1166.member_1))));
                                    let _e1210 = (f32((_e1165 * _e1173)) - (f32(select(_e1166.member_1, _e1192, (_e1192 < _e1166.member_1))) - 0.5f));
                                    let _e1212 = select(_e1210, _e1209, (_e1209 > _e1210));
                                    let _e1214 = select(0f, _e1212, (_e1212 > 0f));
                                    let _e1220 = local_108;
                                    phi_2704_ = _e1004;
                                    phi_1077_ = type_24(_e1220.member, _e1220.member_1, _e1220.member_2, _e1220.member_3, _e1220.member_4, _e1220.member_5, _e1220.member_6, _e1220.member_7, _e1220.member_8, _e1220.member_9, _e1220.member_10, _e1220.member_11, _e1220.member_12, _e1220.member_13, (((_e1206 * _e1206) + (_e1214 * _e1214)) <= (_e1148 * _e1148)));
                                } else {
                                    phi_2704_ = _e719;
                                    let _e2438 = local_235;
                                    phi_1077_ = _e2438;
                                }
                                let _e1238 = phi_2704_;
                                let _e1240 = phi_1077_;
                                phi_1079_ = _e1240;
                                loop {
                                    let _e1242 = phi_1079_;
                                    local_110 = _e1242;
                                    local_236 = _e1242;
                                    let _e1243 = local_110;
                                    local_111 = _e1243.member_11;
                                    let _e1245 = local_73;
                                    let _e1246 = (_e1243.member_11 <= _e1245);
                                    local_112 = _e1246;
                                    if _e1246 {
                                        let _e1247 = local_110;
                                        let _e1249 = (_e1247.member_8 + 1u);
                                        local_113 = _e1249;
                                        let _e1250 = local_110;
                                        local_114 = _e1250.member_6;
                                        let _e1252 = (_e1249 < _e1250.member_6);
                                        local_115 = _e1252;
                                        if _e1252 {
                                            let _e1256 = local_110;
                                            phi_1101_ = _e1256.member_9;
                                        } else {
                                            let _e1253 = local_110;
                                            phi_1101_ = (_e1253.member_9 + 1u);
                                        }
                                        let _e1259 = phi_1101_;
                                        local_116 = _e1259;
                                        let _e1260 = local_115;
                                        let _e1261 = local_113;
                                        let _e1262 = select(0u, _e1261, _e1260);
                                        local_233 = _e1262;
                                        let _e1263 = local_110;
                                        let _e1279 = type_24(_e1263.member, _e1263.member_1, _e1263.member_2, _e1263.member_3, _e1263.member_4, _e1263.member_5, _e1263.member_6, _e1263.member_7, _e1262, _e1263.member_9, _e1263.member_10, _e1263.member_11, _e1263.member_12, _e1263.member_13, _e1263.member_14);
                                        local_117 = type_24(_e1279.member, _e1279.member_1, _e1279.member_2, _e1279.member_3, _e1279.member_4, _e1279.member_5, _e1279.member_6, _e1279.member_7, _e1279.member_8, _e1259, _e1279.member_10, _e1279.member_11, _e1279.member_12, _e1279.member_13, _e1279.member_14);
                                        let _e1296 = local_110;
                                        local_118 = _e1296.member_7;
                                        let _e1298 = (_e1259 < _e1296.member_7);
                                        local_119 = _e1298;
                                        if _e1298 {
                                            let _e1299 = local_110;
                                            let _e1301 = local_11;
                                            let _e1303 = local_116;
                                            let _e1306 = local_233;
                                            let _e1307 = ((_e1299.member_3 + (_e1303 * _e1301.member_4)) + _e1306);
                                            local_120 = _e1307;
                                            let _e1308 = local_3;
                                            if (_e1307 < _e1308) {
                                            } else {
                                                phi_2689_ = true;
                                                break;
                                            }
                                            let _e1310 = local_120;
                                            let _e1313 = global_6.member[_e1310];
                                            phi_1122_ = _e1313;
                                        } else {
                                            phi_1122_ = 4294967295u;
                                        }
                                        let _e1315 = phi_1122_;
                                        let _e1316 = local_117;
                                        local_121 = type_24(_e1316.member, _e1316.member_1, _e1316.member_2, _e1316.member_3, _e1316.member_4, _e1316.member_5, _e1316.member_6, _e1316.member_7, _e1316.member_8, _e1316.member_9, _e1315, _e1316.member_11, _e1316.member_12, _e1316.member_13, _e1316.member_14);
                                        let _e1333 = local_233;
                                        let _e1334 = (_e1333 + 1u);
                                        local_122 = _e1334;
                                        let _e1335 = local_114;
                                        if (_e1334 < _e1335) {
                                            let _e1356 = local_119;
                                            if _e1356 {
                                                let _e1357 = local_110;
                                                let _e1359 = local_11;
                                                let _e1361 = local_116;
                                                let _e1364 = local_122;
                                                let _e1365 = ((_e1357.member_3 + (_e1361 * _e1359.member_4)) + _e1364);
                                                local_123 = _e1365;
                                                let _e1366 = local_3;
                                                if (_e1365 < _e1366) {
                                                } else {
                                                    phi_2689_ = true;
                                                    break;
                                                }
                                                let _e1368 = local_123;
                                                let _e1371 = global_6.member[_e1368];
                                                phi_1148_ = _e1371;
                                            } else {
                                                phi_1148_ = 4294967295u;
                                            }
                                            let _e1373 = phi_1148_;
                                            phi_1168_ = _e1373;
                                        } else {
                                            let _e1337 = local_116;
                                            let _e1338 = (_e1337 + 1u);
                                            local_124 = _e1338;
                                            let _e1339 = local_118;
                                            if (_e1338 < _e1339) {
                                                let _e1341 = local_110;
                                                let _e1343 = local_11;
                                                let _e1345 = local_124;
                                                let _e1347 = (_e1341.member_3 + (_e1345 * _e1343.member_4));
                                                local_125 = _e1347;
                                                let _e1348 = local_3;
                                                if (_e1347 < _e1348) {
                                                } else {
                                                    phi_2689_ = true;
                                                    break;
                                                }
                                                let _e1350 = local_125;
                                                let _e1353 = global_6.member[_e1350];
                                                phi_1167_ = _e1353;
                                            } else {
                                                phi_1167_ = 4294967295u;
                                            }
                                            let _e1355 = phi_1167_;
                                            phi_1168_ = _e1355;
                                        }
                                        let _e1375 = phi_1168_;
                                        let _e1376 = local_121;
                                        local_126 = type_24(_e1376.member, _e1376.member_1, _e1376.member_2, _e1376.member_3, _e1376.member_4, _e1376.member_5, _e1376.member_6, _e1376.member_7, _e1376.member_8, _e1376.member_9, _e1376.member_10, _e1375, _e1376.member_12, _e1376.member_13, _e1376.member_14);
                                        let _e1393 = local_11;
                                        let _e1395 = local_11;
                                        let _e1398 = local_110;
                                        let _e1400 = local_116;
                                        let _e1403 = local_233;
                                        let _e1405 = ((_e1393.member_4 * _e1395.member_5) + ((_e1398.member_3 + (_e1400 * _e1393.member_4)) + _e1403));
                                        local_127 = _e1405;
                                        let _e1406 = local_3;
                                        if (_e1405 < _e1406) {
                                        } else {
                                            phi_2689_ = true;
                                            break;
                                        }
                                        let _e1408 = local_127;
                                        let _e1411 = global_6.member[_e1408];
                                        let _e1412 = bitcast<f32>(_e1411);
                                        let _e1413 = local_110;
                                        let _e1415 = local_233;
                                        let _e1416 = (_e1413.member_4 + _e1415);
                                        let _e1417 = local_11;
                                        let _e1419 = local_11;
                                        let _e1422 = ((_e1416 + 1u) * _e1417.member_3);
                                        let _e1428 = local_110;
                                        let _e1430 = local_116;
                                        let _e1431 = (_e1428.member_5 + _e1430);
                                        let _e1432 = local_11;
                                        let _e1435 = ((_e1431 + 1u) * _e1417.member_3);
                                        let _e1441 = local_110;
                                        let _e1443 = local_110;
                                        let _e1445 = local_11;
                                        let _e1448 = ((_e1441.member_12 + 1u) * _e1445.member_6);
                                        let _e1455 = ((_e1443.member_13 + 1u) * _e1445.member_6);
                                        let _e1463 = ((f32((_e1441.member_12 * _e1445.member_6)) + 0.5f) - f32(select(_e1419.member, _e1422, (_e1422 < _e1419.member))));
                                        let _e1464 = (f32((_e1416 * _e1417.member_3)) - (f32(select(_e1419.member, _e1448, (_e1448 < _e1419.member))) - 0.5f));
                                        let _e1466 = select(_e1464, _e1463, (_e1463 > _e1464));
                                        let _e1468 = select(0f, _e1466, (_e1466 > 0f));
                                        let _e1471 = ((f32((_e1443.member_13 * _e1445.member_6)) + 0.5f) - f32(select(_e1432.member_1, _e1435, (_e1435 < _e1432.member_1))));
                                        let _e1472 = (f32((_e1431 * _e1417.member_3)) - (f32(select(_e1432.member_1, _e1455, (_e1455 < _e1432.member_1))) - 0.5f));
                                        let _e1474 = select(_e1472, _e1471, (_e1471 > _e1472));
                                        let _e1476 = select(0f, _e1474, (_e1474 > 0f));
                                        let _e1482 = local_126;
                                        phi_1080_ = type_24(_e1482.member, _e1482.member_1, _e1482.member_2, _e1482.member_3, _e1482.member_4, _e1482.member_5, _e1482.member_6, _e1482.member_7, _e1482.member_8, _e1482.member_9, _e1482.member_10, _e1482.member_11, _e1482.member_12, _e1482.member_13, (((_e1468 * _e1468) + (_e1476 * _e1476)) <= (_e1412 * _e1412)));
                                    } else {
                                        phi_1080_ = type_24();
                                    }
                                    let _e1500 = phi_1080_;
                                    continue;
                                    continuing {
                                        let _e1501 = local_112;
                                        phi_1079_ = _e1500;
                                        phi_2689_ = _e1238;
                                        break if !(_e1501);
                                    }
                                }
                                let _e1504 = phi_2689_;
                                phi_2718_ = _e1504;
                                if _e1504 {
                                    break;
                                }
                                let _e1505 = local_110;
                                local_128 = _e1505.member_2;
                                let _e1507 = local_110;
                                local_129 = _e1507.member_8;
                                let _e1509 = local_110;
                                local_130 = _e1509.member_9;
                                let _e1511 = local_11;
                                local_131 = _e1511.member_6;
                                let _e1513 = local_11;
                                local_132 = _e1513.member_3;
                                if (_e1513.member_3 == 0u) {
                                    phi_2718_ = true;
                                    break;
                                }
                                let _e1516 = local_131;
                                let _e1517 = local_132;
                                let _e1518 = (_e1516 / _e1517);
                                let _e1519 = local_128;
                                let _e1521 = local_130;
                                let _e1524 = local_129;
                                let _e1526 = local_11;
                                local_133 = _e1526.member_2;
                                let _e1528 = local_132;
                                let _e1530 = local_132;
                                let _e1533 = local_110;
                                let _e1535 = local_73;
                                local_134 = ((((((_e1519 * _e1518) + _e1521) * _e1518) + _e1524) * ((_e1526.member_2 * _e1528) * _e1530)) + (_e1535 - _e1533.member_10));
                                let _e1538 = local_110;
                                if _e1538.member_14 {
                                    let _e1571 = local_134;
                                    let _e1572 = (4u * _e1571);
                                    local_135 = _e1572;
                                    let _e1573 = local_1;
                                    if (_e1572 < _e1573) {
                                    } else {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e1575 = local_135;
                                    let _e1578 = global_4.member[_e1575];
                                    local_136 = _e1578;
                                    let _e1579 = local_135;
                                    let _e1580 = (_e1579 + 1u);
                                    local_137 = _e1580;
                                    let _e1581 = local_1;
                                    if (_e1580 < _e1581) {
                                    } else {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e1583 = local_137;
                                    let _e1586 = global_4.member[_e1583];
                                    local_138 = _e1586;
                                    let _e1587 = local_135;
                                    let _e1588 = (_e1587 + 2u);
                                    local_139 = _e1588;
                                    let _e1589 = local_1;
                                    if (_e1588 < _e1589) {
                                    } else {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e1591 = local_139;
                                    let _e1594 = global_4.member[_e1591];
                                    local_140 = _e1594;
                                    let _e1595 = local_135;
                                    let _e1596 = (_e1595 + 3u);
                                    local_141 = _e1596;
                                    let _e1597 = local_1;
                                    if (_e1596 < _e1597) {
                                    } else {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e1599 = local_141;
                                    let _e1602 = global_4.member[_e1599];
                                    local_142 = _e1602;
                                    let _e1603 = local_136;
                                    local_143 = (_e1603 & 16383u);
                                    let _e1605 = local_136;
                                    local_144 = ((_e1605 >> bitcast<u32>(14u)) & 16383u);
                                    let _e1609 = local_138;
                                    local_145 = (_e1609 & 16383u);
                                    let _e1611 = local_138;
                                    let _e1613 = (_e1611 >> bitcast<u32>(24i));
                                    local_146 = _e1613;
                                    if (_e1613 == 0u) {
                                        phi_1365_ = array<f32, 3>(0f, 0f, 0f);
                                    } else {
                                        let _e1615 = local_146;
                                        let _e1621 = bitcast<f32>((bitcast<u32>((bitcast<i32>(_e1615) + -13i)) << bitcast<u32>(23i)));
                                        let _e1622 = local_143;
                                        let _e1625 = local_144;
                                        let _e1628 = local_145;
                                        phi_1365_ = array<f32, 3>((f32(_e1622) * _e1621), (f32(_e1625) * _e1621), (f32(_e1628) * _e1621));
                                    }
                                    let _e1633 = phi_1365_;
                                    local_147 = _e1633;
                                    let _e1634 = local_138;
                                    let _e1637 = ((_e1634 >> bitcast<u32>(14u)) & 1023u);
                                    local_148 = _e1637;
                                    if (_e1637 >= 1023u) {
                                        phi_1376_ = 1f;
                                    } else {
                                        let _e1639 = local_148;
                                        phi_1376_ = (f32(_e1639) * 0.0009775171f);
                                    }
                                    let _e1643 = phi_1376_;
                                    local_149 = _e1643;
                                    let _e1644 = local_140;
                                    let _e1645 = bitcast<f32>(_e1644);
                                    local_150 = _e1645;
                                    let _e1646 = local_136;
                                    let _e1649 = ((_e1646 >> bitcast<u32>(28i)) & 3u);
                                    local_151 = _e1649;
                                    let _e1650 = local_142;
                                    let _e1652 = local_142;
                                    let _e1655 = array<u32, 2>((_e1650 & 65535u), (_e1652 >> bitcast<u32>(16i)));
                                    local_152 = _e1655;
                                    let _e1656 = local_147;
                                    let _e1658 = local_43;
                                    let _e1661 = ((_e1658 >> bitcast<u32>(8u)) & 7u);
                                    local_153 = _e1661;
                                    if (_e1661 == 0u) {
                                        phi_1448_ = type_21(_e1655, _e1656, _e1643, _e1645, _e1649, 0u);
                                    } else {
                                        let _e1663 = local_153;
                                        let _e1664 = local_153;
                                        let _e1665 = (_e1663 * _e1664);
                                        local_154 = _e1665;
                                        if (_e1665 <= 1u) {
                                            phi_1401_ = 1u;
                                        } else {
                                            let _e1667 = local_154;
                                            phi_1401_ = select(16u, 4u, (_e1667 <= 4u));
                                        }
                                        let _e1671 = phi_1401_;
                                        local_155 = _e1671;
                                        if (_e1671 == 0u) {
                                            phi_2718_ = true;
                                            break;
                                        }
                                        let _e1673 = local_155;
                                        local_156 = (32u / _e1673);
                                        let _e1675 = local_155;
                                        if (_e1675 >= 32u) {
                                            phi_1414_ = 4294967295u;
                                        } else {
                                            let _e1677 = local_155;
                                            phi_1414_ = ((1u << bitcast<u32>((_e1677 & 31u))) - 1u);
                                        }
                                        let _e1683 = phi_1414_;
                                        local_157 = _e1683;
                                        let _e1684 = local_11;
                                        let _e1686 = local_14;
                                        let _e1688 = local_131;
                                        let _e1690 = local_131;
                                        let _e1692 = local_133;
                                        local_158 = (4u * ((((_e1686 * _e1684.member_8) * _e1688) * _e1690) * _e1692));
                                        let _e1695 = local_156;
                                        let _e1696 = (_e1695 == 0u);
                                        local_159 = _e1696;
                                        if _e1696 {
                                            phi_2718_ = true;
                                            break;
                                        }
                                        let _e1697 = local_134;
                                        let _e1698 = local_156;
                                        let _e1700 = local_158;
                                        local_160 = (_e1700 + (_e1697 / _e1698));
                                        let _e1702 = local_159;
                                        if _e1702 {
                                            phi_2718_ = true;
                                            break;
                                        }
                                        let _e1703 = local_134;
                                        let _e1704 = local_156;
                                        let _e1706 = local_155;
                                        local_161 = ((_e1703 % _e1704) * _e1706);
                                        let _e1708 = local_160;
                                        let _e1709 = local_1;
                                        if (_e1708 < _e1709) {
                                        } else {
                                            phi_2718_ = true;
                                            break;
                                        }
                                        let _e1711 = local_160;
                                        let _e1714 = global_4.member[_e1711];
                                        let _e1715 = local_161;
                                        let _e1719 = local_157;
                                        let _e1721 = local_152;
                                        let _e1722 = local_147;
                                        let _e1723 = local_149;
                                        let _e1724 = local_150;
                                        let _e1725 = local_151;
                                        phi_1448_ = type_21(_e1721, _e1722, _e1723, _e1724, _e1725, ((_e1714 >> bitcast<u32>((_e1715 & 31u))) & _e1719));
                                    }
                                    let _e1728 = phi_1448_;
                                    local_162 = _e1728;
                                    if (_e1728.member_5 != 0u) {
                                        phi_1459_ = 1.4142135f;
                                    } else {
                                        let _e1731 = local_162;
                                        phi_1459_ = (0.5f * f32((1u << bitcast<u32>((_e1731.member_4 & 31u)))));
                                    }
                                    let _e1739 = phi_1459_;
                                    local_163 = _e1739;
                                    let _e1740 = local_162;
                                    local_164 = _e1740.member_3;
                                    let _e1742 = bitcast<u32>(_e1740.member_3);
                                    local_165 = _e1742;
                                    if (_e1742 == 2139095040u) {
                                        let _e1784 = local_11;
                                        let _e1788 = local_11;
                                        let _e1792 = local_11;
                                        let _e1797 = local_11;
                                        phi_1514_ = (0.5f * ((((2f * _e1784.member_15.member_1) * _e1788.member_15.member) / (_e1792.member_15.member_2 - _e1788.member_15.member)) * _e1797.member_15.member_3));
                                    } else {
                                        let _e1744 = local_165;
                                        if (_e1744 == 0u) {
                                            phi_1483_ = false;
                                        } else {
                                            let _e1746 = local_165;
                                            phi_1483_ = (_e1746 <= 2139095040u);
                                        }
                                        let _e1749 = phi_1483_;
                                        if _e1749 {
                                            let _e1750 = local_11;
                                            let _e1754 = local_11;
                                            let _e1758 = local_11;
                                            local_166 = _e1758.member_15.member_2;
                                            let _e1763 = local_11;
                                            let _e1766 = ((((2f * _e1750.member_15.member_1) * _e1754.member_15.member) / (_e1758.member_15.member_2 - _e1754.member_15.member)) * _e1763.member_15.member_3);
                                            local_167 = _e1766;
                                            if (_e1766 == 0f) {
                                                phi_1505_ = 0f;
                                            } else {
                                                let _e1768 = local_166;
                                                let _e1769 = local_164;
                                                let _e1772 = local_167;
                                                phi_1505_ = (_e1772 * (1f - (_e1768 / _e1769)));
                                            }
                                            let _e1775 = phi_1505_;
                                            phi_1506_ = _e1775;
                                        } else {
                                            phi_1506_ = bitcast<f32>(_e296);
                                        }
                                        let _e1777 = phi_1506_;
                                        local_168 = _e1777;
                                        if (_e1777 < 0f) {
                                            let _e1779 = local_168;
                                            phi_1512_ = -(_e1779);
                                        } else {
                                            phi_1512_ = _e1777;
                                        }
                                        let _e1782 = phi_1512_;
                                        phi_1514_ = (0.5f * _e1782);
                                    }
                                    let _e1803 = phi_1514_;
                                    let _e1808 = local_163;
                                    let _e1809 = (select(_e1803, 0f, ((bitcast<u32>(_e1803) & 2147483647u) > 2139095040u)) + _e1808);
                                    let _e1810 = local_13;
                                    let _e1812 = local_13;
                                    let _e1813 = select(_e1812, _e1809, (_e1809 < _e1810));
                                    let _e1815 = select(0.5f, _e1813, (_e1813 > 0.5f));
                                    local_234 = _e1815;
                                    let _e1816 = local_162;
                                    let _e1820 = (f32(_e1816.member[0]) * 0.5f);
                                    let _e1821 = local_162;
                                    let _e1825 = (f32(_e1821.member[1]) * 0.5f);
                                    let _e1826 = local_11;
                                    let _e1828 = local_9;
                                    let _e1830 = local_131;
                                    let _e1831 = ((_e1828 + 1u) * _e1830);
                                    let _e1834 = local_9;
                                    let _e1835 = local_131;
                                    let _e1839 = local_11;
                                    let _e1841 = local_10;
                                    let _e1843 = local_131;
                                    let _e1844 = ((_e1841 + 1u) * _e1843);
                                    let _e1847 = local_10;
                                    let _e1848 = local_131;
                                    let _e1854 = ((f32((_e1834 * _e1835)) + 0.5f) - _e1820);
                                    let _e1855 = (_e1820 - (f32(select(_e1826.member, _e1831, (_e1831 < _e1826.member))) - 0.5f));
                                    let _e1857 = select(_e1855, _e1854, (_e1854 > _e1855));
                                    let _e1859 = select(0f, _e1857, (_e1857 > 0f));
                                    let _e1862 = ((f32((_e1847 * _e1848)) + 0.5f) - _e1825);
                                    let _e1863 = (_e1825 - (f32(select(_e1839.member_1, _e1844, (_e1844 < _e1839.member_1))) - 0.5f));
                                    let _e1865 = select(_e1863, _e1862, (_e1862 > _e1863));
                                    let _e1867 = select(0f, _e1865, (_e1865 > 0f));
                                    if (((_e1859 * _e1859) + (_e1867 * _e1867)) <= (_e1815 * _e1815)) {
                                        let _e1873 = local_110;
                                        let _e1875 = local_129;
                                        let _e1877 = local_110;
                                        let _e1879 = local_130;
                                        let _e1881 = local_66;
                                        let _e1885 = local_60;
                                        let _e1887 = local_65;
                                        local_169 = ((_e1873.member_4 + _e1875) | (_e1877.member_5 + _e1879));
                                        phi_1615_ = 0u;
                                        loop {
                                            let _e1891 = phi_1615_;
                                            local_170 = _e1891;
                                            let _e1892 = local_170;
                                            if (_e1892 < 1u) {
                                                let _e1894 = local_170;
                                                let _e1895 = (_e1894 + 1u);
                                                let _e1897 = local_132;
                                                let _e1902 = local_234;
                                                let _e1903 = (_e1902 >= f32((2u * (_e1897 << bitcast<u32>((_e1895 & 31u))))));
                                                phi_1616_ = select(u32(), _e1895, _e1903);
                                                phi_1636_ = _e1903;
                                            } else {
                                                phi_1616_ = u32();
                                                phi_1636_ = false;
                                            }
                                            let _e1906 = phi_1616_;
                                            let _e1908 = phi_1636_;
                                            local_171 = _e1908;
                                            continue;
                                            continuing {
                                                let _e1909 = local_171;
                                                phi_1615_ = _e1906;
                                                break if !(_e1909);
                                            }
                                        }
                                        let _e1911 = local_170;
                                        let _e1916 = local_169;
                                        let _e1920 = local_64;
                                        phi_1650_ = 0u;
                                        loop {
                                            let _e1923 = phi_1650_;
                                            local_172 = _e1923;
                                            let _e1924 = local_172;
                                            if (_e1924 < 2u) {
                                                let _e1926 = local_172;
                                                let _e1927 = (_e1926 + 1u);
                                                let _e1929 = local_132;
                                                let _e1934 = local_234;
                                                let _e1935 = (_e1934 >= f32((2u * (_e1929 << bitcast<u32>((_e1927 & 31u))))));
                                                phi_1651_ = select(u32(), _e1927, _e1935);
                                                phi_1671_ = _e1935;
                                            } else {
                                                phi_1651_ = u32();
                                                phi_1671_ = false;
                                            }
                                            let _e1938 = phi_1651_;
                                            let _e1940 = phi_1671_;
                                            local_173 = _e1940;
                                            continue;
                                            continuing {
                                                let _e1941 = local_173;
                                                phi_1650_ = _e1938;
                                                break if !(_e1941);
                                            }
                                        }
                                        let _e1943 = local_172;
                                        let _e1948 = local_169;
                                        let _e1952 = local_63;
                                        phi_1685_ = 0u;
                                        loop {
                                            let _e1955 = phi_1685_;
                                            local_174 = _e1955;
                                            let _e1956 = local_174;
                                            if (_e1956 < 3u) {
                                                let _e1958 = local_174;
                                                let _e1959 = (_e1958 + 1u);
                                                let _e1961 = local_132;
                                                let _e1966 = local_234;
                                                let _e1967 = (_e1966 >= f32((2u * (_e1961 << bitcast<u32>((_e1959 & 31u))))));
                                                phi_1686_ = select(u32(), _e1959, _e1967);
                                                phi_1706_ = _e1967;
                                            } else {
                                                phi_1686_ = u32();
                                                phi_1706_ = false;
                                            }
                                            let _e1970 = phi_1686_;
                                            let _e1972 = phi_1706_;
                                            local_175 = _e1972;
                                            continue;
                                            continuing {
                                                let _e1973 = local_175;
                                                phi_1685_ = _e1970;
                                                break if !(_e1973);
                                            }
                                        }
                                        let _e1975 = local_174;
                                        let _e1980 = local_169;
                                        let _e1984 = local_62;
                                        phi_1720_ = 0u;
                                        loop {
                                            let _e1987 = phi_1720_;
                                            local_176 = _e1987;
                                            let _e1988 = local_176;
                                            if (_e1988 < 4u) {
                                                let _e1990 = local_176;
                                                let _e1991 = (_e1990 + 1u);
                                                let _e1993 = local_132;
                                                let _e1998 = local_234;
                                                let _e1999 = (_e1998 >= f32((2u * (_e1993 << bitcast<u32>((_e1991 & 31u))))));
                                                phi_1721_ = select(u32(), _e1991, _e1999);
                                                phi_1741_ = _e1999;
                                            } else {
                                                phi_1721_ = u32();
                                                phi_1741_ = false;
                                            }
                                            let _e2002 = phi_1721_;
                                            let _e2004 = phi_1741_;
                                            local_177 = _e2004;
                                            continue;
                                            continuing {
                                                let _e2005 = local_177;
                                                phi_1720_ = _e2002;
                                                break if !(_e2005);
                                            }
                                        }
                                        let _e2007 = local_176;
                                        let _e2012 = local_169;
                                        let _e2016 = local_61;
                                        phi_1753_ = (_e1885 | (1u << bitcast<u32>((_e1881 & 31u))));
                                        phi_1754_ = (_e2016 + select(0u, 1u, ((_e2012 & ((1u << bitcast<u32>((_e2007 & 31u))) - 1u)) == 0u)));
                                        phi_1755_ = (_e1984 + select(0u, 1u, ((_e1980 & ((1u << bitcast<u32>((_e1975 & 31u))) - 1u)) == 0u)));
                                        phi_1756_ = (_e1952 + select(0u, 1u, ((_e1948 & ((1u << bitcast<u32>((_e1943 & 31u))) - 1u)) == 0u)));
                                        phi_1757_ = (_e1920 + select(0u, 1u, ((_e1916 & ((1u << bitcast<u32>((_e1911 & 31u))) - 1u)) == 0u)));
                                        phi_1758_ = (_e1887 + 1u);
                                    } else {
                                        phi_1753_ = _e654;
                                        phi_1754_ = _e656;
                                        phi_1755_ = _e658;
                                        phi_1756_ = _e660;
                                        phi_1757_ = _e662;
                                        phi_1758_ = _e664;
                                    }
                                    let _e2019 = phi_1753_;
                                    let _e2021 = phi_1754_;
                                    let _e2023 = phi_1755_;
                                    let _e2025 = phi_1756_;
                                    let _e2027 = phi_1757_;
                                    let _e2029 = phi_1758_;
                                    let _e2030 = local_66;
                                    phi_1795_ = _e2019;
                                    phi_1796_ = _e2021;
                                    phi_1797_ = _e2023;
                                    phi_1798_ = _e2025;
                                    phi_1799_ = _e2027;
                                    phi_1800_ = _e2029;
                                    phi_1801_ = (_e2030 + 1u);
                                } else {
                                    let _e1540 = local_110;
                                    local_178 = _e1540.member;
                                    if (_e1540.member == 0u) {
                                        phi_1775_ = 0u;
                                    } else {
                                        let _e1543 = local_34;
                                        let _e1544 = local_178;
                                        let _e1546 = ((_e1543 + _e1544) - 1u);
                                        local_179 = _e1546;
                                        if (_e1546 < 1792u) {
                                        } else {
                                            phi_2718_ = true;
                                            break;
                                        }
                                        let _e1548 = local_179;
                                        let _e1550 = global_11[_e1548];
                                        phi_1775_ = _e1550;
                                    }
                                    let _e1552 = phi_1775_;
                                    local_180 = _e1552;
                                    let _e1553 = local_34;
                                    let _e1554 = local_178;
                                    let _e1555 = (_e1553 + _e1554);
                                    local_181 = _e1555;
                                    if (_e1555 < 1792u) {
                                    } else {
                                        phi_2718_ = true;
                                        break;
                                    }
                                    let _e1557 = local_181;
                                    let _e1559 = global_11[_e1557];
                                    let _e1560 = local_180;
                                    let _e1562 = local_111;
                                    if (_e1562 < (_e1559 - _e1560)) {
                                        let _e1564 = local_180;
                                        let _e1565 = local_111;
                                        phi_1793_ = (_e1564 + _e1565);
                                    } else {
                                        phi_1793_ = _e1559;
                                    }
                                    let _e1568 = phi_1793_;
                                    let _e1569 = local_50;
                                    phi_1795_ = _e654;
                                    phi_1796_ = _e656;
                                    phi_1797_ = _e658;
                                    phi_1798_ = _e660;
                                    phi_1799_ = _e662;
                                    phi_1800_ = _e664;
                                    phi_1801_ = (_e1568 - _e1569);
                                }
                                let _e2033 = phi_1795_;
                                let _e2035 = phi_1796_;
                                let _e2037 = phi_1797_;
                                let _e2039 = phi_1798_;
                                let _e2041 = phi_1799_;
                                let _e2043 = phi_1800_;
                                let _e2045 = phi_1801_;
                                phi_2720_ = _e1504;
                                phi_1802_ = _e2033;
                                phi_1803_ = _e2035;
                                phi_1804_ = _e2037;
                                phi_1805_ = _e2039;
                                phi_1806_ = _e2041;
                                phi_1807_ = _e2043;
                                let _e2494 = local_236;
                                phi_1808_ = _e2494;
                                phi_1809_ = _e2045;
                            } else {
                                phi_2720_ = _e652;
                                phi_1802_ = u32();
                                phi_1803_ = u32();
                                phi_1804_ = u32();
                                phi_1805_ = u32();
                                phi_1806_ = u32();
                                phi_1807_ = u32();
                                phi_1808_ = type_24();
                                phi_1809_ = u32();
                            }
                            let _e2047 = phi_2720_;
                            let _e2049 = phi_1802_;
                            let _e2051 = phi_1803_;
                            let _e2053 = phi_1804_;
                            let _e2055 = phi_1805_;
                            let _e2057 = phi_1806_;
                            let _e2059 = phi_1807_;
                            let _e2061 = phi_1808_;
                            let _e2063 = phi_1809_;
                            phi_2719_ = _e2047;
                            phi_658_ = _e2049;
                            phi_661_ = _e2051;
                            phi_663_ = _e2053;
                            phi_665_ = _e2055;
                            phi_667_ = _e2057;
                            phi_669_ = _e2059;
                            phi_671_ = _e2061;
                            phi_673_ = _e2063;
                            phi_1810_ = _e676;
                        } else {
                            phi_2719_ = _e652;
                            phi_658_ = u32();
                            phi_661_ = u32();
                            phi_663_ = u32();
                            phi_665_ = u32();
                            phi_667_ = u32();
                            phi_669_ = u32();
                            phi_671_ = type_24();
                            phi_673_ = u32();
                            phi_1810_ = false;
                        }
                        let _e2065 = phi_2719_;
                        let _e2067 = phi_658_;
                        let _e2069 = phi_661_;
                        let _e2071 = phi_663_;
                        let _e2073 = phi_665_;
                        let _e2075 = phi_667_;
                        let _e2077 = phi_669_;
                        let _e2079 = phi_671_;
                        let _e2081 = phi_673_;
                        let _e2083 = phi_1810_;
                        local_182 = _e2083;
                        continue;
                        continuing {
                            let _e2084 = local_182;
                            phi_2673_ = _e2065;
                            phi_657_ = _e2067;
                            phi_660_ = _e2069;
                            phi_662_ = _e2071;
                            phi_664_ = _e2073;
                            phi_666_ = _e2075;
                            phi_668_ = _e2077;
                            phi_670_ = _e2079;
                            phi_672_ = _e2081;
                            phi_2718_ = _e2065;
                            break if !(_e2084);
                        }
                    }
                    let _e2087 = phi_2718_;
                    phi_2758_ = _e2087;
                    if _e2087 {
                        break;
                    }
                    let _e2088 = local_51;
                    let _e2089 = local_44;
                    if (_e2088 < _e2089) {
                        let _e2091 = local_51;
                        let _e2092 = local_229;
                        let _e2095 = local_60;
                        let _e2098 = local_52;
                        phi_1823_ = (_e2098 | (_e2095 << bitcast<u32>(((_e2091 * _e2092) & 31u))));
                    } else {
                        phi_1823_ = _e608;
                    }
                    let _e2101 = phi_1823_;
                    let _e2102 = local_229;
                    let _e2104 = local_50;
                    let _e2106 = local_51;
                    phi_2759_ = _e2087;
                    let _e2511 = local_237;
                    phi_604_ = _e2511;
                    let _e2514 = local_238;
                    phi_607_ = _e2514;
                    let _e2517 = local_239;
                    phi_609_ = _e2517;
                    let _e2520 = local_240;
                    phi_611_ = _e2520;
                    let _e2523 = local_241;
                    phi_613_ = _e2523;
                    phi_615_ = (_e2104 + (256u * _e2102));
                    phi_617_ = (_e2106 + 1u);
                    phi_619_ = _e2101;
                } else {
                    phi_2759_ = _e592;
                    phi_604_ = u32();
                    phi_607_ = u32();
                    phi_609_ = u32();
                    phi_611_ = u32();
                    phi_613_ = u32();
                    phi_615_ = u32();
                    phi_617_ = u32();
                    phi_619_ = u32();
                }
                let _e2109 = phi_2759_;
                let _e2111 = phi_604_;
                let _e2113 = phi_607_;
                let _e2115 = phi_609_;
                let _e2117 = phi_611_;
                let _e2119 = phi_613_;
                let _e2121 = phi_615_;
                let _e2123 = phi_617_;
                let _e2125 = phi_619_;
                continue;
                continuing {
                    let _e2126 = local_53;
                    phi_2665_ = _e2109;
                    phi_603_ = _e2111;
                    phi_606_ = _e2113;
                    phi_608_ = _e2115;
                    phi_610_ = _e2117;
                    phi_612_ = _e2119;
                    phi_614_ = _e2121;
                    phi_616_ = _e2123;
                    phi_618_ = _e2125;
                    phi_2758_ = _e2109;
                    break if !(_e2126);
                }
            }
            let _e2129 = phi_2758_;
            if _e2129 {
                break;
            }
            let _e2130 = local_15;
            let _e2132 = local;
            let _e2133 = ((_e2130 * 256u) + _e2132);
            local_183 = _e2133;
            let _e2134 = local_7;
            if (_e2133 < _e2134) {
            } else {
                break;
            }
            let _e2136 = local_183;
            let _e2139 = local_52;
            global_9.member[_e2136] = _e2139;
            let _e2140 = local;
            let _e2141 = (_e2140 < 1792u);
            local_184 = _e2141;
            if _e2141 {
            } else {
                break;
            }
            let _e2142 = local;
            let _e2144 = local_49;
            global_11[_e2142] = _e2144;
            let _e2145 = local;
            let _e2146 = (256u + _e2145);
            local_185 = _e2146;
            let _e2147 = (_e2146 < 1792u);
            local_186 = _e2147;
            if _e2147 {
            } else {
                break;
            }
            let _e2148 = local_185;
            let _e2150 = local_48;
            global_11[_e2148] = _e2150;
            let _e2151 = local;
            let _e2152 = (512u + _e2151);
            local_187 = _e2152;
            let _e2153 = (_e2152 < 1792u);
            local_188 = _e2153;
            if _e2153 {
            } else {
                break;
            }
            let _e2154 = local_187;
            let _e2156 = local_47;
            global_11[_e2154] = _e2156;
            let _e2157 = local_230;
            let _e2158 = local;
            let _e2159 = (_e2157 + _e2158);
            local_189 = _e2159;
            let _e2160 = (_e2159 < 1792u);
            local_190 = _e2160;
            if _e2160 {
            } else {
                break;
            }
            let _e2161 = local_189;
            let _e2163 = local_46;
            global_11[_e2161] = _e2163;
            let _e2164 = local;
            let _e2165 = (1536u + _e2164);
            local_191 = _e2165;
            let _e2166 = (_e2165 < 1792u);
            local_192 = _e2166;
            if _e2166 {
            } else {
                break;
            }
            let _e2167 = local_191;
            let _e2169 = local_45;
            global_11[_e2167] = _e2169;
            storageBarrier();
            workgroupBarrier();
            phi_1958_ = 128u;
            loop {
                let _e2171 = phi_1958_;
                local_193 = _e2171;
                let _e2172 = local_193;
                let _e2173 = (_e2172 > 0u);
                local_194 = _e2173;
                if _e2173 {
                    let _e2174 = local;
                    let _e2175 = local_193;
                    if (_e2174 < _e2175) {
                        let _e2177 = local_184;
                        if _e2177 {
                        } else {
                            phi_2761_ = true;
                            break;
                        }
                        let _e2178 = global_11[_e2142];
                        local_195 = _e2178;
                        let _e2179 = local;
                        let _e2180 = local_193;
                        let _e2181 = (_e2179 + _e2180);
                        local_196 = _e2181;
                        if (_e2181 < 1792u) {
                        } else {
                            phi_2761_ = true;
                            break;
                        }
                        let _e2183 = local_196;
                        let _e2185 = global_11[_e2183];
                        let _e2186 = local_195;
                        local_197 = (_e2186 + _e2185);
                        let _e2188 = local_184;
                        if _e2188 {
                        } else {
                            phi_2761_ = true;
                            break;
                        }
                        let _e2189 = local_197;
                        global_11[_e2142] = _e2189;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e2190 = local_193;
                    phi_1959_ = (_e2190 / 2u);
                } else {
                    phi_1959_ = u32();
                }
                let _e2193 = phi_1959_;
                continue;
                continuing {
                    let _e2194 = local_194;
                    phi_1958_ = _e2193;
                    phi_2761_ = _e2129;
                    break if !(_e2194);
                }
            }
            let _e2197 = phi_2761_;
            if _e2197 {
                break;
            }
            let _e2199 = global_11[0u];
            local_198 = _e2199;
            storageBarrier();
            workgroupBarrier();
            phi_2091_ = 128u;
            loop {
                let _e2201 = phi_2091_;
                local_199 = _e2201;
                let _e2202 = local_199;
                let _e2203 = (_e2202 > 0u);
                local_200 = _e2203;
                if _e2203 {
                    let _e2204 = local;
                    let _e2205 = local_199;
                    if (_e2204 < _e2205) {
                        let _e2207 = local_186;
                        if _e2207 {
                        } else {
                            phi_2783_ = true;
                            break;
                        }
                        let _e2208 = global_11[_e2148];
                        local_201 = _e2208;
                        let _e2209 = local_185;
                        let _e2210 = local_199;
                        let _e2211 = (_e2209 + _e2210);
                        local_202 = _e2211;
                        if (_e2211 < 1792u) {
                        } else {
                            phi_2783_ = true;
                            break;
                        }
                        let _e2213 = local_202;
                        let _e2215 = global_11[_e2213];
                        let _e2216 = local_201;
                        local_203 = (_e2216 + _e2215);
                        let _e2218 = local_186;
                        if _e2218 {
                        } else {
                            phi_2783_ = true;
                            break;
                        }
                        let _e2219 = local_203;
                        global_11[_e2148] = _e2219;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e2220 = local_199;
                    phi_2092_ = (_e2220 / 2u);
                } else {
                    phi_2092_ = u32();
                }
                let _e2223 = phi_2092_;
                continue;
                continuing {
                    let _e2224 = local_200;
                    phi_2091_ = _e2223;
                    phi_2783_ = _e2197;
                    break if !(_e2224);
                }
            }
            let _e2227 = phi_2783_;
            if _e2227 {
                break;
            }
            let _e2229 = global_11[256u];
            local_204 = _e2229;
            storageBarrier();
            workgroupBarrier();
            phi_2224_ = 128u;
            loop {
                let _e2231 = phi_2224_;
                local_205 = _e2231;
                let _e2232 = local_205;
                let _e2233 = (_e2232 > 0u);
                local_206 = _e2233;
                if _e2233 {
                    let _e2234 = local;
                    let _e2235 = local_205;
                    if (_e2234 < _e2235) {
                        let _e2237 = local_188;
                        if _e2237 {
                        } else {
                            phi_2807_ = true;
                            break;
                        }
                        let _e2238 = global_11[_e2154];
                        local_207 = _e2238;
                        let _e2239 = local_187;
                        let _e2240 = local_205;
                        let _e2241 = (_e2239 + _e2240);
                        local_208 = _e2241;
                        if (_e2241 < 1792u) {
                        } else {
                            phi_2807_ = true;
                            break;
                        }
                        let _e2243 = local_208;
                        let _e2245 = global_11[_e2243];
                        let _e2246 = local_207;
                        local_209 = (_e2246 + _e2245);
                        let _e2248 = local_188;
                        if _e2248 {
                        } else {
                            phi_2807_ = true;
                            break;
                        }
                        let _e2249 = local_209;
                        global_11[_e2154] = _e2249;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e2250 = local_205;
                    phi_2225_ = (_e2250 / 2u);
                } else {
                    phi_2225_ = u32();
                }
                let _e2253 = phi_2225_;
                continue;
                continuing {
                    let _e2254 = local_206;
                    phi_2224_ = _e2253;
                    phi_2807_ = _e2227;
                    break if !(_e2254);
                }
            }
            let _e2257 = phi_2807_;
            if _e2257 {
                break;
            }
            let _e2259 = global_11[512u];
            local_210 = _e2259;
            storageBarrier();
            workgroupBarrier();
            phi_2357_ = 128u;
            loop {
                let _e2261 = phi_2357_;
                local_211 = _e2261;
                let _e2262 = local_211;
                let _e2263 = (_e2262 > 0u);
                local_212 = _e2263;
                if _e2263 {
                    let _e2264 = local;
                    let _e2265 = local_211;
                    if (_e2264 < _e2265) {
                        let _e2267 = local_190;
                        if _e2267 {
                        } else {
                            phi_2831_ = true;
                            break;
                        }
                        let _e2268 = global_11[_e2161];
                        local_213 = _e2268;
                        let _e2269 = local_189;
                        let _e2270 = local_211;
                        let _e2271 = (_e2269 + _e2270);
                        local_214 = _e2271;
                        if (_e2271 < 1792u) {
                        } else {
                            phi_2831_ = true;
                            break;
                        }
                        let _e2273 = local_214;
                        let _e2275 = global_11[_e2273];
                        let _e2276 = local_213;
                        local_215 = (_e2276 + _e2275);
                        let _e2278 = local_190;
                        if _e2278 {
                        } else {
                            phi_2831_ = true;
                            break;
                        }
                        let _e2279 = local_215;
                        global_11[_e2161] = _e2279;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e2280 = local_211;
                    phi_2358_ = (_e2280 / 2u);
                } else {
                    phi_2358_ = u32();
                }
                let _e2283 = phi_2358_;
                continue;
                continuing {
                    let _e2284 = local_212;
                    phi_2357_ = _e2283;
                    phi_2831_ = _e2257;
                    break if !(_e2284);
                }
            }
            let _e2287 = phi_2831_;
            if _e2287 {
                break;
            }
            let _e2288 = local_230;
            if (_e2288 < 1792u) {
            } else {
                break;
            }
            let _e2290 = local_230;
            let _e2292 = global_11[_e2290];
            local_216 = _e2292;
            storageBarrier();
            workgroupBarrier();
            phi_2490_ = 128u;
            loop {
                let _e2294 = phi_2490_;
                local_217 = _e2294;
                let _e2295 = local_217;
                let _e2296 = (_e2295 > 0u);
                local_218 = _e2296;
                if _e2296 {
                    let _e2297 = local;
                    let _e2298 = local_217;
                    if (_e2297 < _e2298) {
                        let _e2300 = local_192;
                        if _e2300 {
                        } else {
                            phi_2855_ = true;
                            break;
                        }
                        let _e2301 = global_11[_e2167];
                        local_219 = _e2301;
                        let _e2302 = local_191;
                        let _e2303 = local_217;
                        let _e2304 = (_e2302 + _e2303);
                        local_220 = _e2304;
                        if (_e2304 < 1792u) {
                        } else {
                            phi_2855_ = true;
                            break;
                        }
                        let _e2306 = local_220;
                        let _e2308 = global_11[_e2306];
                        let _e2309 = local_219;
                        local_221 = (_e2309 + _e2308);
                        let _e2311 = local_192;
                        if _e2311 {
                        } else {
                            phi_2855_ = true;
                            break;
                        }
                        let _e2312 = local_221;
                        global_11[_e2167] = _e2312;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e2313 = local_217;
                    phi_2491_ = (_e2313 / 2u);
                } else {
                    phi_2491_ = u32();
                }
                let _e2316 = phi_2491_;
                continue;
                continuing {
                    let _e2317 = local_218;
                    phi_2490_ = _e2316;
                    phi_2855_ = _e2287;
                    break if !(_e2317);
                }
            }
            let _e2320 = phi_2855_;
            if _e2320 {
                break;
            }
            let _e2322 = global_11[1536u];
            local_222 = _e2322;
            storageBarrier();
            workgroupBarrier();
            let _e2323 = local;
            if (_e2323 == 0u) {
                let _e2325 = local_15;
                let _e2326 = (_e2325 * 5u);
                local_223 = _e2326;
                let _e2327 = local_6;
                if (_e2326 < _e2327) {
                } else {
                    break;
                }
                let _e2329 = local_223;
                let _e2332 = local_198;
                global_8.member[_e2329] = _e2332;
                let _e2333 = local_223;
                let _e2334 = (_e2333 + 1u);
                local_224 = _e2334;
                let _e2335 = local_6;
                if (_e2334 < _e2335) {
                } else {
                    break;
                }
                let _e2337 = local_224;
                let _e2340 = local_204;
                global_8.member[_e2337] = _e2340;
                let _e2341 = local_223;
                let _e2342 = (_e2341 + 2u);
                local_225 = _e2342;
                let _e2343 = local_6;
                if (_e2342 < _e2343) {
                } else {
                    break;
                }
                let _e2345 = local_225;
                let _e2348 = local_210;
                global_8.member[_e2345] = _e2348;
                let _e2349 = local_223;
                let _e2350 = (_e2349 + 3u);
                local_226 = _e2350;
                let _e2351 = local_6;
                if (_e2350 < _e2351) {
                } else {
                    break;
                }
                let _e2353 = local_226;
                let _e2356 = local_216;
                global_8.member[_e2353] = _e2356;
                let _e2357 = local_223;
                let _e2358 = (_e2357 + 4u);
                local_227 = _e2358;
                let _e2359 = local_6;
                if (_e2358 < _e2359) {
                } else {
                    break;
                }
                let _e2361 = local_227;
                let _e2364 = local_222;
                global_8.member[_e2361] = _e2364;
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn splat_bin_count(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
