struct type_3 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_5 {
    member: array<u32>,
}

struct type_15 {
    member: u32,
    member_1: u32,
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
    member_15: type_3,
    member_16: type_16,
    member_17: u32,
    member_18: u32,
}

struct type_18 {
    member: type_17,
}

struct type_20 {
    member: u32,
    member_1: type_15,
}

struct type_26 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<workgroup> global_1: array<u32, 512>;
var<private> global_2: u32;
var<private> global_3: u32;
var<private> global_4: u32;
var<private> global_5: u32;
var<immediate> global_6: type_18;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_26;
@group(0) @binding(0) 
var<storage> global_8: type_5;
@group(0) @binding(1) 
var<storage, read_write> global_9: type_5;
@group(0) @binding(2) 
var<storage, read_write> global_10: type_5;

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
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: bool;
    var local_18: u32;
    var local_19: u32;
    var local_20: type_20;
    var local_21: bool;
    var local_22: bool;
    var local_23: bool;
    var local_24: bool;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: bool;
    var local_30: u32;
    var local_31: bool;
    var local_32: u32;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: bool;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: bool;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: bool;
    var local_53: u32;
    var local_54: u32;
    var local_55: type_20;
    var local_56: bool;
    var local_57: bool;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: u32;
    var local_62: bool;
    var local_63: u32;
    var local_64: bool;
    var local_65: u32;
    var local_66: u32;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: bool;
    var local_72: u32;
    var local_73: u32;
    var local_74: u32;
    var local_75: bool;
    var local_76: u32;
    var local_77: u32;
    var local_78: u32;
    var local_79: u32;
    var local_80: bool;
    var local_81: u32;
    var local_82: u32;
    var local_83: type_20;
    var local_84: bool;
    var local_85: bool;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: u32;
    var local_91: u32;
    var local_92: u32;
    var local_93: u32;
    var local_94: u32;
    var local_95: bool;
    var local_96: u32;
    var local_97: u32;
    var local_98: bool;
    var local_99: u32;
    var local_100: u32;
    var local_101: u32;
    var local_102: u32;
    var local_103: u32;
    var local_104: u32;
    var local_105: bool;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: u32;
    var local_112: bool;
    var local_113: u32;
    var local_114: u32;
    var local_115: u32;
    var local_116: bool;
    var local_117: u32;
    var local_118: u32;
    var local_119: u32;
    var local_120: u32;
    var local_121: u32;
    var local_122: u32;
    var local_123: u32;
    var local_124: u32;
    var local_125: type_20;
    var local_126: u32;
    var local_127: u32;
    var local_128: u32;
    var local_129: u32;
    var local_130: u32;
    var local_131: u32;
    var local_132: u32;
    var local_133: u32;
    var local_134: bool;
    var local_135: u32;
    var local_136: u32;
    var local_137: bool;
    var local_138: u32;
    var local_139: u32;
    var local_140: type_20;
    var local_141: type_20;
    var local_142: u32;
    var local_143: u32;
    var local_144: u32;
    var local_145: u32;
    var local_146: u32;
    var local_147: u32;
    var local_148: u32;
    var local_149: bool;
    var local_150: u32;
    var local_151: u32;
    var local_152: u32;
    var phi_135_: u32;
    var phi_1563_: bool;
    var phi_141_: u32;
    var phi_144_: u32;
    var phi_181_: u32;
    var phi_212_: u32;
    var phi_182_: u32;
    var phi_213_: bool;
    var phi_1560_: bool;
    var phi_245_: type_20;
    var phi_254_: u32;
    var phi_1569_: bool;
    var phi_255_: u32;
    var phi_1568_: bool;
    var phi_257_: u32;
    var phi_258_: u32;
    var phi_1567_: bool;
    var phi_142_: u32;
    var phi_145_: u32;
    var phi_259_: bool;
    var phi_1566_: bool;
    var phi_286_: type_15;
    var phi_288_: type_15;
    var phi_289_: bool;
    var phi_290_: type_15;
    var phi_291_: bool;
    var phi_296_: type_15;
    var phi_393_: u32;
    var phi_394_: u32;
    var phi_1572_: bool;
    var phi_308_: u32;
    var phi_311_: u32;
    var phi_335_: u32;
    var phi_309_: u32;
    var phi_312_: u32;
    var phi_1580_: bool;
    var phi_383_: u32;
    var phi_1593_: bool;
    var phi_437_: u32;
    var phi_1591_: bool;
    var phi_446_: u32;
    var phi_449_: u32;
    var phi_473_: u32;
    var phi_1589_: bool;
    var phi_478_: u32;
    var phi_481_: u32;
    var phi_518_: u32;
    var phi_549_: u32;
    var phi_519_: u32;
    var phi_550_: bool;
    var phi_1586_: bool;
    var phi_582_: type_20;
    var phi_591_: u32;
    var phi_1599_: bool;
    var phi_592_: u32;
    var phi_1598_: bool;
    var phi_594_: u32;
    var phi_595_: u32;
    var phi_1597_: bool;
    var phi_479_: u32;
    var phi_482_: u32;
    var phi_596_: bool;
    var phi_1596_: bool;
    var phi_623_: type_15;
    var phi_625_: type_15;
    var phi_626_: bool;
    var phi_627_: type_15;
    var phi_628_: bool;
    var phi_633_: type_15;
    var phi_730_: u32;
    var phi_731_: u32;
    var phi_1602_: bool;
    var phi_645_: u32;
    var phi_648_: u32;
    var phi_672_: u32;
    var phi_646_: u32;
    var phi_649_: u32;
    var phi_1610_: bool;
    var phi_720_: u32;
    var phi_1619_: bool;
    var phi_774_: u32;
    var phi_782_: u32;
    var phi_1617_: bool;
    var phi_447_: u32;
    var phi_450_: u32;
    var phi_1616_: bool;
    var phi_1624_: bool;
    var phi_787_: u32;
    var phi_790_: u32;
    var phi_827_: u32;
    var phi_858_: u32;
    var phi_828_: u32;
    var phi_859_: bool;
    var phi_1621_: bool;
    var phi_891_: type_20;
    var phi_900_: u32;
    var phi_1629_: bool;
    var phi_901_: u32;
    var phi_1628_: bool;
    var phi_903_: u32;
    var phi_904_: u32;
    var phi_1627_: bool;
    var phi_788_: u32;
    var phi_791_: u32;
    var phi_905_: bool;
    var phi_1626_: bool;
    var phi_932_: type_15;
    var phi_934_: type_15;
    var phi_935_: bool;
    var phi_936_: type_15;
    var phi_937_: bool;
    var phi_942_: type_15;
    var phi_1092_: u32;
    var phi_1095_: u32;
    var phi_1131_: u32;
    var phi_1093_: u32;
    var phi_1096_: u32;
    var phi_1632_: bool;
    var phi_979_: u32;
    var phi_982_: u32;
    var phi_983_: u32;
    var phi_985_: u32;
    var phi_1013_: u32;
    var phi_980_: u32;
    var phi_984_: u32;
    var phi_986_: u32;
    var phi_1642_: bool;
    var phi_1035_: u32;
    var phi_1038_: u32;
    var phi_1040_: u32;
    var phi_1055_: u32;
    var phi_1036_: u32;
    var phi_1039_: u32;
    var phi_1041_: u32;
    var phi_1647_: bool;
    var phi_1659_: bool;
    var phi_1146_: u32;
    var phi_1160_: u32;
    var phi_1657_: bool;
    var phi_1164_: u32;
    var phi_1167_: type_20;
    var phi_1169_: u32;
    var phi_1171_: u32;
    var phi_1173_: u32;
    var phi_1175_: u32;
    var phi_1177_: u32;
    var phi_1179_: u32;
    var phi_1237_: u32;
    var phi_1268_: u32;
    var phi_1238_: u32;
    var phi_1269_: bool;
    var phi_1653_: bool;
    var phi_1301_: type_20;
    var phi_1667_: bool;
    var phi_1303_: type_20;
    var phi_1330_: type_20;
    var phi_1332_: type_20;
    var phi_1416_: u32;
    var phi_1417_: u32;
    var phi_1378_: u32;
    var phi_1379_: u32;
    var phi_1418_: u32;
    var phi_1419_: u32;
    var phi_1420_: u32;
    var phi_1421_: u32;
    var phi_1422_: u32;
    var phi_1663_: bool;
    var phi_1424_: u32;
    var phi_1425_: type_20;
    var phi_1426_: u32;
    var phi_1427_: u32;
    var phi_1428_: u32;
    var phi_1429_: u32;
    var phi_1430_: u32;
    var phi_1431_: u32;
    var phi_1662_: bool;
    var phi_1165_: u32;
    var phi_1168_: type_20;
    var phi_1170_: u32;
    var phi_1172_: u32;
    var phi_1174_: u32;
    var phi_1176_: u32;
    var phi_1178_: u32;
    var phi_1180_: u32;
    var phi_1432_: bool;
    var phi_1661_: bool;
    var local_153: u32;
    var local_154: u32;
    var local_155: u32;
    var local_156: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e193 = global;
            local = _e193;
            let _e194 = global_2;
            local_1 = _e194;
            let _e195 = global_3;
            local_2 = _e195;
            let _e196 = global_4;
            local_3 = _e196;
            let _e197 = global_5;
            local_4 = _e197;
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_9.member));
            local_7 = arrayLength((&global_10.member));
            local_8 = arrayLength((&global_7.member));
            let _e208 = global_6.member.member_7;
            let _e211 = global_6.member.member_8;
            let _e212 = (_e208 * _e211);
            local_9 = _e212;
            let _e213 = (_e212 / 256u);
            local_10 = _e213;
            if ((_e212 % 256u) > 0u) {
                let _e216 = local_10;
                phi_135_ = (_e216 + 1u);
            } else {
                phi_135_ = _e213;
            }
            let _e219 = phi_135_;
            local_11 = _e219;
            let _e222 = global_6.member.member_18;
            local_12 = _e222;
            let _e223 = local;
            let _e224 = (_e223 * _e219);
            phi_1563_ = false;
            phi_141_ = _e224;
            phi_144_ = 0u;
            loop {
                let _e226 = phi_1563_;
                let _e228 = phi_141_;
                let _e230 = phi_144_;
                local_13 = _e228;
                local_14 = _e230;
                let _e231 = local_13;
                let _e232 = local_9;
                if (_e231 < _e232) {
                    let _e234 = local;
                    let _e236 = local_11;
                    let _e238 = local_13;
                    let _e239 = (_e238 < ((_e234 + 1u) * _e236));
                    if _e239 {
                        let _e240 = local_13;
                        let _e241 = local_6;
                        if (_e240 < _e241) {
                        } else {
                            phi_1566_ = true;
                            break;
                        }
                        let _e243 = local_13;
                        let _e246 = global_9.member[_e243];
                        if ((_e246 & 1u) == 0u) {
                            phi_181_ = 0u;
                            loop {
                                let _e250 = phi_181_;
                                local_15 = _e250;
                                let _e251 = local_15;
                                if (_e251 < 4u) {
                                    let _e253 = local_13;
                                    let _e255 = local_15;
                                    let _e256 = ((_e253 * 5u) + _e255);
                                    local_16 = _e256;
                                    let _e257 = local_5;
                                    if (_e256 < _e257) {
                                    } else {
                                        phi_1560_ = true;
                                        break;
                                    }
                                    let _e259 = local_16;
                                    let _e262 = global_8.member[_e259];
                                    let _e263 = local_12;
                                    let _e264 = (_e262 > _e263);
                                    if _e264 {
                                        let _e265 = local_15;
                                        phi_212_ = (_e265 + 1u);
                                    } else {
                                        phi_212_ = u32();
                                    }
                                    let _e268 = phi_212_;
                                    phi_182_ = _e268;
                                    phi_213_ = _e264;
                                } else {
                                    phi_182_ = u32();
                                    phi_213_ = false;
                                }
                                let _e270 = phi_182_;
                                let _e272 = phi_213_;
                                local_17 = _e272;
                                continue;
                                continuing {
                                    let _e273 = local_17;
                                    phi_181_ = _e270;
                                    phi_1560_ = _e226;
                                    break if !(_e273);
                                }
                            }
                            let _e276 = phi_1560_;
                            phi_1566_ = _e276;
                            if _e276 {
                                break;
                            }
                            let _e277 = local_13;
                            let _e279 = local_15;
                            let _e280 = ((_e277 * 5u) + _e279);
                            local_18 = _e280;
                            let _e281 = local_5;
                            if (_e280 < _e281) {
                            } else {
                                phi_1566_ = true;
                                break;
                            }
                            let _e283 = local_18;
                            let _e286 = global_8.member[_e283];
                            local_19 = _e286;
                            let _e287 = local_12;
                            if (_e286 <= _e287) {
                                let _e292 = local_15;
                                let _e293 = local_19;
                                phi_245_ = type_20(1u, type_15(_e292, _e293));
                            } else {
                                phi_245_ = type_20(0u, type_20().member_1);
                            }
                            let _e297 = phi_245_;
                            local_20 = _e297;
                            if (bitcast<i32>(_e297.member) != 0i) {
                                let _e301 = local_20;
                                let _e304 = local_14;
                                phi_254_ = (_e304 + _e301.member_1.member_1);
                            } else {
                                phi_254_ = _e230;
                            }
                            let _e307 = phi_254_;
                            phi_1569_ = _e276;
                            phi_255_ = _e307;
                        } else {
                            phi_1569_ = _e226;
                            phi_255_ = _e230;
                        }
                        let _e309 = phi_1569_;
                        let _e311 = phi_255_;
                        let _e312 = local_13;
                        phi_1568_ = _e309;
                        phi_257_ = (_e312 + 1u);
                        phi_258_ = _e311;
                    } else {
                        phi_1568_ = _e226;
                        phi_257_ = u32();
                        phi_258_ = u32();
                    }
                    let _e315 = phi_1568_;
                    let _e317 = phi_257_;
                    let _e319 = phi_258_;
                    phi_1567_ = _e315;
                    phi_142_ = _e317;
                    phi_145_ = _e319;
                    phi_259_ = _e239;
                } else {
                    phi_1567_ = _e226;
                    phi_142_ = u32();
                    phi_145_ = u32();
                    phi_259_ = false;
                }
                let _e321 = phi_1567_;
                let _e323 = phi_142_;
                let _e325 = phi_145_;
                let _e327 = phi_259_;
                local_21 = _e327;
                continue;
                continuing {
                    let _e328 = local_21;
                    phi_1563_ = _e321;
                    phi_141_ = _e323;
                    phi_144_ = _e325;
                    phi_1566_ = _e321;
                    break if !(_e328);
                }
            }
            let _e331 = phi_1566_;
            if _e331 {
                break;
            }
            let _e332 = local;
            let _e333 = (_e332 < 512u);
            local_22 = _e333;
            if _e333 {
            } else {
                break;
            }
            let _e334 = local;
            let _e336 = local_14;
            global_1[_e334] = _e336;
            storageBarrier();
            workgroupBarrier();
            let _e337 = local_1;
            let _e338 = (_e337 >= 2u);
            local_23 = _e338;
            if _e338 {
                let _e339 = local_1;
                let _e341 = local_1;
                if ((_e341 & (_e339 - 1u)) == 0u) {
                    let _e344 = local_2;
                    let _e345 = local_1;
                    let _e347 = ((_e344 * _e345) == 256u);
                    local_24 = _e347;
                    if _e347 {
                        let _e348 = local_1;
                        phi_286_ = type_15(1u, _e348);
                    } else {
                        phi_286_ = type_15();
                    }
                    let _e351 = phi_286_;
                    let _e352 = local_24;
                    phi_288_ = _e351;
                    phi_289_ = select(true, false, _e352);
                } else {
                    phi_288_ = type_15();
                    phi_289_ = true;
                }
                let _e355 = phi_288_;
                let _e357 = phi_289_;
                phi_290_ = _e355;
                phi_291_ = _e357;
            } else {
                phi_290_ = type_15();
                phi_291_ = true;
            }
            let _e359 = phi_290_;
            let _e361 = phi_291_;
            if _e361 {
                phi_296_ = type_15(0u, type_15().member_1);
            } else {
                phi_296_ = _e359;
            }
            let _e366 = phi_296_;
            local_25 = _e366.member_1;
            if (bitcast<i32>(_e366.member) != 0i) {
                let _e401 = local_25;
                let _e403 = local_25;
                local_26 = select(firstTrailingBit(_e401), 32u, (_e403 == 0u));
                phi_308_ = 0u;
                phi_311_ = 256u;
                loop {
                    let _e407 = phi_308_;
                    let _e409 = phi_311_;
                    local_27 = _e407;
                    local_28 = _e409;
                    let _e410 = local_28;
                    let _e411 = local_25;
                    let _e412 = (_e410 > _e411);
                    local_29 = _e412;
                    if _e412 {
                        let _e413 = local_3;
                        let _e414 = local_1;
                        let _e416 = local_4;
                        let _e417 = ((_e413 * _e414) + _e416);
                        local_30 = _e417;
                        let _e418 = local_28;
                        let _e419 = (_e417 < _e418);
                        local_31 = _e419;
                        if _e419 {
                            let _e420 = local_27;
                            let _e422 = local_30;
                            let _e424 = (_e422 << bitcast<u32>((_e420 & 31u)));
                            local_32 = _e424;
                            if (_e424 < 512u) {
                            } else {
                                phi_1580_ = true;
                                break;
                            }
                            let _e426 = local_32;
                            let _e428 = global_1[_e426];
                            phi_335_ = _e428;
                        } else {
                            phi_335_ = 0u;
                        }
                        let _e430 = phi_335_;
                        let _e431 = subgroupAdd(_e430);
                        local_33 = _e431;
                        let _e432 = local_31;
                        if _e432 {
                            let _e433 = local_25;
                            let _e435 = local_30;
                            if ((_e435 & (_e433 - 1u)) == 0u) {
                                let _e438 = local_27;
                                let _e440 = local_30;
                                let _e442 = (_e440 << bitcast<u32>((_e438 & 31u)));
                                local_34 = _e442;
                                if (_e442 < 512u) {
                                } else {
                                    phi_1580_ = true;
                                    break;
                                }
                                let _e444 = local_34;
                                let _e446 = local_33;
                                global_1[_e444] = _e446;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e447 = local_26;
                        let _e449 = local_28;
                        let _e452 = local_27;
                        let _e453 = local_26;
                        phi_309_ = (_e452 + _e453);
                        phi_312_ = (_e449 >> bitcast<u32>((_e447 & 31u)));
                    } else {
                        phi_309_ = u32();
                        phi_312_ = u32();
                    }
                    let _e456 = phi_309_;
                    let _e458 = phi_312_;
                    continue;
                    continuing {
                        let _e459 = local_29;
                        phi_308_ = _e456;
                        phi_311_ = _e458;
                        phi_1580_ = _e331;
                        break if !(_e459);
                    }
                }
                let _e462 = phi_1580_;
                if _e462 {
                    break;
                }
                let _e463 = local_3;
                let _e464 = local_1;
                let _e466 = local_4;
                let _e468 = local_25;
                let _e470 = (((_e463 * _e464) + _e466) & (_e468 - 1u));
                local_35 = _e470;
                let _e471 = local_28;
                if (_e470 < _e471) {
                    let _e473 = local_27;
                    let _e475 = local_35;
                    let _e477 = (_e475 << bitcast<u32>((_e473 & 31u)));
                    local_36 = _e477;
                    if (_e477 < 512u) {
                    } else {
                        break;
                    }
                    let _e479 = local_36;
                    let _e481 = global_1[_e479];
                    phi_383_ = _e481;
                } else {
                    phi_383_ = 0u;
                }
                let _e483 = phi_383_;
                let _e484 = subgroupAdd(_e483);
                storageBarrier();
                workgroupBarrier();
                phi_1593_ = _e462;
                phi_437_ = _e484;
            } else {
                phi_393_ = 128u;
                loop {
                    let _e372 = phi_393_;
                    local_37 = _e372;
                    let _e373 = local_37;
                    let _e374 = (_e373 > 0u);
                    local_38 = _e374;
                    if _e374 {
                        let _e375 = local;
                        let _e376 = local_37;
                        if (_e375 < _e376) {
                            let _e378 = local_22;
                            if _e378 {
                            } else {
                                phi_1572_ = true;
                                break;
                            }
                            let _e379 = global_1[_e334];
                            local_39 = _e379;
                            let _e380 = local;
                            let _e381 = local_37;
                            let _e382 = (_e380 + _e381);
                            local_40 = _e382;
                            if (_e382 < 512u) {
                            } else {
                                phi_1572_ = true;
                                break;
                            }
                            let _e384 = local_40;
                            let _e386 = global_1[_e384];
                            let _e387 = local_39;
                            local_41 = (_e387 + _e386);
                            let _e389 = local_22;
                            if _e389 {
                            } else {
                                phi_1572_ = true;
                                break;
                            }
                            let _e390 = local_41;
                            global_1[_e334] = _e390;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e391 = local_37;
                        phi_394_ = (_e391 / 2u);
                    } else {
                        phi_394_ = u32();
                    }
                    let _e394 = phi_394_;
                    continue;
                    continuing {
                        let _e395 = local_38;
                        phi_393_ = _e394;
                        phi_1572_ = _e331;
                        break if !(_e395);
                    }
                }
                let _e398 = phi_1572_;
                if _e398 {
                    break;
                }
                let _e400 = global_1[0u];
                storageBarrier();
                workgroupBarrier();
                phi_1593_ = _e398;
                phi_437_ = _e400;
            }
            let _e486 = phi_1593_;
            let _e488 = phi_437_;
            let _e491 = global_6.member.member_17;
            local_42 = _e491;
            let _e493 = local_12;
            phi_1591_ = _e486;
            phi_446_ = _e222;
            phi_449_ = select(0u, _e493, (_e488 <= _e491));
            loop {
                let _e496 = phi_1591_;
                let _e498 = phi_446_;
                let _e500 = phi_449_;
                local_43 = _e498;
                local_44 = _e500;
                let _e501 = local_44;
                let _e502 = local_43;
                let _e503 = (_e501 < _e502);
                local_45 = _e503;
                if _e503 {
                    let _e504 = local_43;
                    let _e505 = local_44;
                    let _e506 = (_e504 - _e505);
                    let _e507 = (_e506 / 2u);
                    local_46 = _e507;
                    if ((_e506 % 2u) > 0u) {
                        let _e510 = local_46;
                        phi_473_ = (_e510 + 1u);
                    } else {
                        phi_473_ = _e507;
                    }
                    let _e513 = phi_473_;
                    let _e514 = local_44;
                    local_47 = (_e514 + _e513);
                    phi_1589_ = _e496;
                    phi_478_ = _e224;
                    phi_481_ = 0u;
                    loop {
                        let _e517 = phi_1589_;
                        let _e519 = phi_478_;
                        let _e521 = phi_481_;
                        local_48 = _e519;
                        local_49 = _e521;
                        let _e522 = local_48;
                        let _e523 = local_9;
                        if (_e522 < _e523) {
                            let _e525 = local;
                            let _e527 = local_11;
                            let _e529 = local_48;
                            let _e530 = (_e529 < ((_e525 + 1u) * _e527));
                            if _e530 {
                                let _e531 = local_48;
                                let _e532 = local_6;
                                if (_e531 < _e532) {
                                } else {
                                    phi_1596_ = true;
                                    break;
                                }
                                let _e534 = local_48;
                                let _e537 = global_9.member[_e534];
                                if ((_e537 & 1u) == 0u) {
                                    phi_518_ = 0u;
                                    loop {
                                        let _e541 = phi_518_;
                                        local_50 = _e541;
                                        let _e542 = local_50;
                                        if (_e542 < 4u) {
                                            let _e544 = local_48;
                                            let _e546 = local_50;
                                            let _e547 = ((_e544 * 5u) + _e546);
                                            local_51 = _e547;
                                            let _e548 = local_5;
                                            if (_e547 < _e548) {
                                            } else {
                                                phi_1586_ = true;
                                                break;
                                            }
                                            let _e550 = local_51;
                                            let _e553 = global_8.member[_e550];
                                            let _e554 = local_47;
                                            let _e555 = (_e553 > _e554);
                                            if _e555 {
                                                let _e556 = local_50;
                                                phi_549_ = (_e556 + 1u);
                                            } else {
                                                phi_549_ = u32();
                                            }
                                            let _e559 = phi_549_;
                                            phi_519_ = _e559;
                                            phi_550_ = _e555;
                                        } else {
                                            phi_519_ = u32();
                                            phi_550_ = false;
                                        }
                                        let _e561 = phi_519_;
                                        let _e563 = phi_550_;
                                        local_52 = _e563;
                                        continue;
                                        continuing {
                                            let _e564 = local_52;
                                            phi_518_ = _e561;
                                            phi_1586_ = _e517;
                                            break if !(_e564);
                                        }
                                    }
                                    let _e567 = phi_1586_;
                                    phi_1596_ = _e567;
                                    if _e567 {
                                        break;
                                    }
                                    let _e568 = local_48;
                                    let _e570 = local_50;
                                    let _e571 = ((_e568 * 5u) + _e570);
                                    local_53 = _e571;
                                    let _e572 = local_5;
                                    if (_e571 < _e572) {
                                    } else {
                                        phi_1596_ = true;
                                        break;
                                    }
                                    let _e574 = local_53;
                                    let _e577 = global_8.member[_e574];
                                    local_54 = _e577;
                                    let _e578 = local_12;
                                    if (_e577 <= _e578) {
                                        let _e583 = local_50;
                                        let _e584 = local_54;
                                        phi_582_ = type_20(1u, type_15(_e583, _e584));
                                    } else {
                                        phi_582_ = type_20(0u, type_20().member_1);
                                    }
                                    let _e588 = phi_582_;
                                    local_55 = _e588;
                                    if (bitcast<i32>(_e588.member) != 0i) {
                                        let _e592 = local_55;
                                        let _e595 = local_49;
                                        phi_591_ = (_e595 + _e592.member_1.member_1);
                                    } else {
                                        phi_591_ = _e521;
                                    }
                                    let _e598 = phi_591_;
                                    phi_1599_ = _e567;
                                    phi_592_ = _e598;
                                } else {
                                    phi_1599_ = _e517;
                                    phi_592_ = _e521;
                                }
                                let _e600 = phi_1599_;
                                let _e602 = phi_592_;
                                let _e603 = local_48;
                                phi_1598_ = _e600;
                                phi_594_ = (_e603 + 1u);
                                phi_595_ = _e602;
                            } else {
                                phi_1598_ = _e517;
                                phi_594_ = u32();
                                phi_595_ = u32();
                            }
                            let _e606 = phi_1598_;
                            let _e608 = phi_594_;
                            let _e610 = phi_595_;
                            phi_1597_ = _e606;
                            phi_479_ = _e608;
                            phi_482_ = _e610;
                            phi_596_ = _e530;
                        } else {
                            phi_1597_ = _e517;
                            phi_479_ = u32();
                            phi_482_ = u32();
                            phi_596_ = false;
                        }
                        let _e612 = phi_1597_;
                        let _e614 = phi_479_;
                        let _e616 = phi_482_;
                        let _e618 = phi_596_;
                        local_56 = _e618;
                        continue;
                        continuing {
                            let _e619 = local_56;
                            phi_1589_ = _e612;
                            phi_478_ = _e614;
                            phi_481_ = _e616;
                            phi_1596_ = _e612;
                            break if !(_e619);
                        }
                    }
                    let _e622 = phi_1596_;
                    phi_1616_ = _e622;
                    if _e622 {
                        break;
                    }
                    let _e623 = local_22;
                    if _e623 {
                    } else {
                        phi_1616_ = true;
                        break;
                    }
                    let _e624 = local_49;
                    global_1[_e334] = _e624;
                    storageBarrier();
                    workgroupBarrier();
                    let _e625 = local_23;
                    if _e625 {
                        let _e626 = local_1;
                        let _e628 = local_1;
                        if ((_e628 & (_e626 - 1u)) == 0u) {
                            let _e631 = local_2;
                            let _e632 = local_1;
                            let _e634 = ((_e631 * _e632) == 256u);
                            local_57 = _e634;
                            if _e634 {
                                let _e635 = local_1;
                                phi_623_ = type_15(1u, _e635);
                            } else {
                                phi_623_ = type_15();
                            }
                            let _e638 = phi_623_;
                            let _e639 = local_57;
                            phi_625_ = _e638;
                            phi_626_ = select(true, false, _e639);
                        } else {
                            phi_625_ = type_15();
                            phi_626_ = true;
                        }
                        let _e642 = phi_625_;
                        let _e644 = phi_626_;
                        phi_627_ = _e642;
                        phi_628_ = _e644;
                    } else {
                        phi_627_ = type_15();
                        phi_628_ = true;
                    }
                    let _e646 = phi_627_;
                    let _e648 = phi_628_;
                    if _e648 {
                        phi_633_ = type_15(0u, type_15().member_1);
                    } else {
                        phi_633_ = _e646;
                    }
                    let _e653 = phi_633_;
                    local_58 = _e653.member_1;
                    if (bitcast<i32>(_e653.member) != 0i) {
                        let _e688 = local_58;
                        let _e690 = local_58;
                        local_59 = select(firstTrailingBit(_e688), 32u, (_e690 == 0u));
                        phi_645_ = 0u;
                        phi_648_ = 256u;
                        loop {
                            let _e694 = phi_645_;
                            let _e696 = phi_648_;
                            local_60 = _e694;
                            local_61 = _e696;
                            let _e697 = local_61;
                            let _e698 = local_58;
                            let _e699 = (_e697 > _e698);
                            local_62 = _e699;
                            if _e699 {
                                let _e700 = local_3;
                                let _e701 = local_1;
                                let _e703 = local_4;
                                let _e704 = ((_e700 * _e701) + _e703);
                                local_63 = _e704;
                                let _e705 = local_61;
                                let _e706 = (_e704 < _e705);
                                local_64 = _e706;
                                if _e706 {
                                    let _e707 = local_60;
                                    let _e709 = local_63;
                                    let _e711 = (_e709 << bitcast<u32>((_e707 & 31u)));
                                    local_65 = _e711;
                                    if (_e711 < 512u) {
                                    } else {
                                        phi_1610_ = true;
                                        break;
                                    }
                                    let _e713 = local_65;
                                    let _e715 = global_1[_e713];
                                    phi_672_ = _e715;
                                } else {
                                    phi_672_ = 0u;
                                }
                                let _e717 = phi_672_;
                                let _e718 = subgroupAdd(_e717);
                                local_66 = _e718;
                                let _e719 = local_64;
                                if _e719 {
                                    let _e720 = local_58;
                                    let _e722 = local_63;
                                    if ((_e722 & (_e720 - 1u)) == 0u) {
                                        let _e725 = local_60;
                                        let _e727 = local_63;
                                        let _e729 = (_e727 << bitcast<u32>((_e725 & 31u)));
                                        local_67 = _e729;
                                        if (_e729 < 512u) {
                                        } else {
                                            phi_1610_ = true;
                                            break;
                                        }
                                        let _e731 = local_67;
                                        let _e733 = local_66;
                                        global_1[_e731] = _e733;
                                    }
                                }
                                storageBarrier();
                                workgroupBarrier();
                                let _e734 = local_59;
                                let _e736 = local_61;
                                let _e739 = local_60;
                                let _e740 = local_59;
                                phi_646_ = (_e739 + _e740);
                                phi_649_ = (_e736 >> bitcast<u32>((_e734 & 31u)));
                            } else {
                                phi_646_ = u32();
                                phi_649_ = u32();
                            }
                            let _e743 = phi_646_;
                            let _e745 = phi_649_;
                            continue;
                            continuing {
                                let _e746 = local_62;
                                phi_645_ = _e743;
                                phi_648_ = _e745;
                                phi_1610_ = _e622;
                                break if !(_e746);
                            }
                        }
                        let _e749 = phi_1610_;
                        phi_1616_ = _e749;
                        if _e749 {
                            break;
                        }
                        let _e750 = local_3;
                        let _e751 = local_1;
                        let _e753 = local_4;
                        let _e755 = local_58;
                        let _e757 = (((_e750 * _e751) + _e753) & (_e755 - 1u));
                        local_68 = _e757;
                        let _e758 = local_61;
                        if (_e757 < _e758) {
                            let _e760 = local_60;
                            let _e762 = local_68;
                            let _e764 = (_e762 << bitcast<u32>((_e760 & 31u)));
                            local_69 = _e764;
                            if (_e764 < 512u) {
                            } else {
                                phi_1616_ = true;
                                break;
                            }
                            let _e766 = local_69;
                            let _e768 = global_1[_e766];
                            phi_720_ = _e768;
                        } else {
                            phi_720_ = 0u;
                        }
                        let _e770 = phi_720_;
                        let _e771 = subgroupAdd(_e770);
                        storageBarrier();
                        workgroupBarrier();
                        phi_1619_ = _e749;
                        phi_774_ = _e771;
                    } else {
                        phi_730_ = 128u;
                        loop {
                            let _e659 = phi_730_;
                            local_70 = _e659;
                            let _e660 = local_70;
                            let _e661 = (_e660 > 0u);
                            local_71 = _e661;
                            if _e661 {
                                let _e662 = local;
                                let _e663 = local_70;
                                if (_e662 < _e663) {
                                    let _e665 = local_22;
                                    if _e665 {
                                    } else {
                                        phi_1602_ = true;
                                        break;
                                    }
                                    let _e666 = global_1[_e334];
                                    local_72 = _e666;
                                    let _e667 = local;
                                    let _e668 = local_70;
                                    let _e669 = (_e667 + _e668);
                                    local_73 = _e669;
                                    if (_e669 < 512u) {
                                    } else {
                                        phi_1602_ = true;
                                        break;
                                    }
                                    let _e671 = local_73;
                                    let _e673 = global_1[_e671];
                                    let _e674 = local_72;
                                    local_74 = (_e674 + _e673);
                                    let _e676 = local_22;
                                    if _e676 {
                                    } else {
                                        phi_1602_ = true;
                                        break;
                                    }
                                    let _e677 = local_74;
                                    global_1[_e334] = _e677;
                                }
                                storageBarrier();
                                workgroupBarrier();
                                let _e678 = local_70;
                                phi_731_ = (_e678 / 2u);
                            } else {
                                phi_731_ = u32();
                            }
                            let _e681 = phi_731_;
                            continue;
                            continuing {
                                let _e682 = local_71;
                                phi_730_ = _e681;
                                phi_1602_ = _e622;
                                break if !(_e682);
                            }
                        }
                        let _e685 = phi_1602_;
                        phi_1616_ = _e685;
                        if _e685 {
                            break;
                        }
                        let _e687 = global_1[0u];
                        storageBarrier();
                        workgroupBarrier();
                        phi_1619_ = _e685;
                        phi_774_ = _e687;
                    }
                    let _e773 = phi_1619_;
                    let _e775 = phi_774_;
                    let _e776 = local_42;
                    let _e777 = (_e775 <= _e776);
                    local_75 = _e777;
                    if _e777 {
                        phi_782_ = _e498;
                    } else {
                        let _e778 = local_47;
                        phi_782_ = (_e778 - 1u);
                    }
                    let _e781 = phi_782_;
                    let _e782 = local_75;
                    let _e783 = local_47;
                    let _e784 = local_44;
                    phi_1617_ = _e773;
                    phi_447_ = _e781;
                    phi_450_ = select(_e784, _e783, _e782);
                } else {
                    phi_1617_ = _e496;
                    phi_447_ = u32();
                    phi_450_ = u32();
                }
                let _e787 = phi_1617_;
                let _e789 = phi_447_;
                let _e791 = phi_450_;
                continue;
                continuing {
                    let _e792 = local_45;
                    phi_1591_ = _e787;
                    phi_446_ = _e789;
                    phi_449_ = _e791;
                    phi_1616_ = _e787;
                    break if !(_e792);
                }
            }
            let _e795 = phi_1616_;
            if _e795 {
                break;
            }
            phi_1624_ = _e795;
            phi_787_ = _e224;
            phi_790_ = 0u;
            loop {
                let _e797 = phi_1624_;
                let _e799 = phi_787_;
                let _e801 = phi_790_;
                local_76 = _e799;
                local_77 = _e801;
                let _e802 = local_76;
                let _e803 = local_9;
                if (_e802 < _e803) {
                    let _e805 = local;
                    let _e807 = local_11;
                    let _e809 = local_76;
                    let _e810 = (_e809 < ((_e805 + 1u) * _e807));
                    if _e810 {
                        let _e811 = local_76;
                        let _e812 = local_6;
                        if (_e811 < _e812) {
                        } else {
                            phi_1626_ = true;
                            break;
                        }
                        let _e814 = local_76;
                        let _e817 = global_9.member[_e814];
                        if ((_e817 & 1u) == 0u) {
                            phi_827_ = 0u;
                            loop {
                                let _e821 = phi_827_;
                                local_78 = _e821;
                                let _e822 = local_78;
                                if (_e822 < 4u) {
                                    let _e824 = local_76;
                                    let _e826 = local_78;
                                    let _e827 = ((_e824 * 5u) + _e826);
                                    local_79 = _e827;
                                    let _e828 = local_5;
                                    if (_e827 < _e828) {
                                    } else {
                                        phi_1621_ = true;
                                        break;
                                    }
                                    let _e830 = local_79;
                                    let _e833 = global_8.member[_e830];
                                    let _e834 = local_44;
                                    let _e835 = (_e833 > _e834);
                                    if _e835 {
                                        let _e836 = local_78;
                                        phi_858_ = (_e836 + 1u);
                                    } else {
                                        phi_858_ = u32();
                                    }
                                    let _e839 = phi_858_;
                                    phi_828_ = _e839;
                                    phi_859_ = _e835;
                                } else {
                                    phi_828_ = u32();
                                    phi_859_ = false;
                                }
                                let _e841 = phi_828_;
                                let _e843 = phi_859_;
                                local_80 = _e843;
                                continue;
                                continuing {
                                    let _e844 = local_80;
                                    phi_827_ = _e841;
                                    phi_1621_ = _e797;
                                    break if !(_e844);
                                }
                            }
                            let _e847 = phi_1621_;
                            phi_1626_ = _e847;
                            if _e847 {
                                break;
                            }
                            let _e848 = local_76;
                            let _e850 = local_78;
                            let _e851 = ((_e848 * 5u) + _e850);
                            local_81 = _e851;
                            let _e852 = local_5;
                            if (_e851 < _e852) {
                            } else {
                                phi_1626_ = true;
                                break;
                            }
                            let _e854 = local_81;
                            let _e857 = global_8.member[_e854];
                            local_82 = _e857;
                            let _e858 = local_12;
                            if (_e857 <= _e858) {
                                let _e863 = local_78;
                                let _e864 = local_82;
                                phi_891_ = type_20(1u, type_15(_e863, _e864));
                            } else {
                                phi_891_ = type_20(0u, type_20().member_1);
                            }
                            let _e868 = phi_891_;
                            local_83 = _e868;
                            if (bitcast<i32>(_e868.member) != 0i) {
                                let _e872 = local_83;
                                let _e875 = local_77;
                                phi_900_ = (_e875 + _e872.member_1.member_1);
                            } else {
                                phi_900_ = _e801;
                            }
                            let _e878 = phi_900_;
                            phi_1629_ = _e847;
                            phi_901_ = _e878;
                        } else {
                            phi_1629_ = _e797;
                            phi_901_ = _e801;
                        }
                        let _e880 = phi_1629_;
                        let _e882 = phi_901_;
                        let _e883 = local_76;
                        phi_1628_ = _e880;
                        phi_903_ = (_e883 + 1u);
                        phi_904_ = _e882;
                    } else {
                        phi_1628_ = _e797;
                        phi_903_ = u32();
                        phi_904_ = u32();
                    }
                    let _e886 = phi_1628_;
                    let _e888 = phi_903_;
                    let _e890 = phi_904_;
                    phi_1627_ = _e886;
                    phi_788_ = _e888;
                    phi_791_ = _e890;
                    phi_905_ = _e810;
                } else {
                    phi_1627_ = _e797;
                    phi_788_ = u32();
                    phi_791_ = u32();
                    phi_905_ = false;
                }
                let _e892 = phi_1627_;
                let _e894 = phi_788_;
                let _e896 = phi_791_;
                let _e898 = phi_905_;
                local_84 = _e898;
                continue;
                continuing {
                    let _e899 = local_84;
                    phi_1624_ = _e892;
                    phi_787_ = _e894;
                    phi_790_ = _e896;
                    phi_1626_ = _e892;
                    break if !(_e899);
                }
            }
            let _e902 = phi_1626_;
            if _e902 {
                break;
            }
            let _e903 = local_22;
            if _e903 {
            } else {
                break;
            }
            let _e904 = local_77;
            global_1[_e334] = _e904;
            storageBarrier();
            workgroupBarrier();
            let _e905 = local_23;
            if _e905 {
                let _e906 = local_1;
                let _e908 = local_1;
                if ((_e908 & (_e906 - 1u)) == 0u) {
                    let _e911 = local_2;
                    let _e912 = local_1;
                    let _e914 = ((_e911 * _e912) == 256u);
                    local_85 = _e914;
                    if _e914 {
                        let _e915 = local_1;
                        phi_932_ = type_15(1u, _e915);
                    } else {
                        phi_932_ = type_15();
                    }
                    let _e918 = phi_932_;
                    let _e919 = local_85;
                    phi_934_ = _e918;
                    phi_935_ = select(true, false, _e919);
                } else {
                    phi_934_ = type_15();
                    phi_935_ = true;
                }
                let _e922 = phi_934_;
                let _e924 = phi_935_;
                phi_936_ = _e922;
                phi_937_ = _e924;
            } else {
                phi_936_ = type_15();
                phi_937_ = true;
            }
            let _e926 = phi_936_;
            let _e928 = phi_937_;
            if _e928 {
                phi_942_ = type_15(0u, type_15().member_1);
            } else {
                phi_942_ = _e926;
            }
            let _e933 = phi_942_;
            local_86 = _e933.member_1;
            if (bitcast<i32>(_e933.member) != 0i) {
                let _e987 = local_86;
                let _e989 = local_86;
                local_87 = select(firstTrailingBit(_e987), 32u, (_e989 == 0u));
                let _e992 = local_3;
                let _e993 = local_1;
                let _e995 = local_4;
                let _e996 = ((_e992 * _e993) + _e995);
                local_88 = _e996;
                if (_e996 < 512u) {
                } else {
                    break;
                }
                let _e998 = local_88;
                let _e1000 = global_1[_e998];
                let _e1001 = subgroupInclusiveAdd(_e1000);
                local_89 = _e1001;
                let _e1002 = local_88;
                let _e1003 = (256u + _e1002);
                local_90 = _e1003;
                if (_e1003 < 512u) {
                } else {
                    break;
                }
                let _e1005 = local_90;
                let _e1007 = local_89;
                global_1[_e1005] = _e1007;
                storageBarrier();
                workgroupBarrier();
                phi_979_ = 0u;
                phi_982_ = 256u;
                phi_983_ = 256u;
                phi_985_ = 0u;
                loop {
                    let _e1009 = phi_979_;
                    let _e1011 = phi_982_;
                    let _e1013 = phi_983_;
                    let _e1015 = phi_985_;
                    local_91 = _e1009;
                    local_92 = _e1011;
                    local_93 = _e1013;
                    local_94 = _e1015;
                    local_153 = _e1011;
                    local_154 = _e1013;
                    local_155 = _e1015;
                    let _e1016 = local_93;
                    let _e1017 = local_86;
                    let _e1018 = (_e1016 > _e1017);
                    local_95 = _e1018;
                    if _e1018 {
                        let _e1019 = local_87;
                        let _e1020 = (_e1019 & 31u);
                        local_96 = _e1020;
                        let _e1021 = local_93;
                        let _e1023 = (_e1021 >> bitcast<u32>(_e1020));
                        local_97 = _e1023;
                        let _e1024 = local_88;
                        let _e1025 = (_e1024 < _e1023);
                        local_98 = _e1025;
                        if _e1025 {
                            let _e1026 = local_88;
                            let _e1028 = local_96;
                            let _e1031 = local_92;
                            let _e1033 = ((_e1031 + ((_e1026 + 1u) << bitcast<u32>(_e1028))) - 1u);
                            local_99 = _e1033;
                            if (_e1033 < 512u) {
                            } else {
                                phi_1642_ = true;
                                break;
                            }
                            let _e1035 = local_99;
                            let _e1037 = global_1[_e1035];
                            phi_1013_ = _e1037;
                        } else {
                            phi_1013_ = 0u;
                        }
                        let _e1039 = phi_1013_;
                        let _e1040 = subgroupInclusiveAdd(_e1039);
                        local_100 = _e1040;
                        let _e1041 = local_98;
                        if _e1041 {
                            let _e1042 = local_91;
                            let _e1043 = local_88;
                            let _e1044 = (_e1042 + _e1043);
                            local_101 = _e1044;
                            if (_e1044 < 512u) {
                            } else {
                                phi_1642_ = true;
                                break;
                            }
                            let _e1046 = local_101;
                            let _e1048 = local_100;
                            global_1[_e1046] = _e1048;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e1049 = local_91;
                        let _e1050 = local_97;
                        let _e1052 = local_94;
                        phi_980_ = (_e1049 + _e1050);
                        phi_984_ = _e1023;
                        phi_986_ = (_e1052 + 1u);
                    } else {
                        phi_980_ = u32();
                        phi_984_ = u32();
                        phi_986_ = u32();
                    }
                    let _e1055 = phi_980_;
                    let _e1057 = phi_984_;
                    let _e1059 = phi_986_;
                    continue;
                    continuing {
                        let _e1060 = local_95;
                        phi_979_ = _e1055;
                        phi_982_ = _e1009;
                        phi_983_ = _e1057;
                        phi_985_ = _e1059;
                        phi_1642_ = _e902;
                        break if !(_e1060);
                    }
                }
                let _e1063 = phi_1642_;
                if _e1063 {
                    break;
                }
                let _e1578 = local_153;
                phi_1035_ = _e1578;
                let _e1581 = local_154;
                phi_1038_ = _e1581;
                let _e1584 = local_155;
                phi_1040_ = _e1584;
                loop {
                    let _e1065 = phi_1035_;
                    let _e1067 = phi_1038_;
                    let _e1069 = phi_1040_;
                    local_102 = _e1065;
                    local_103 = _e1067;
                    local_104 = _e1069;
                    let _e1070 = local_104;
                    let _e1071 = (_e1070 > 0u);
                    local_105 = _e1071;
                    if _e1071 {
                        let _e1072 = local_87;
                        let _e1073 = (_e1072 & 31u);
                        local_106 = _e1073;
                        let _e1074 = local_103;
                        let _e1076 = (_e1074 << bitcast<u32>(_e1073));
                        local_107 = _e1076;
                        let _e1077 = local_104;
                        if (_e1077 == 1u) {
                            phi_1055_ = 256u;
                        } else {
                            let _e1079 = local_102;
                            let _e1080 = local_107;
                            phi_1055_ = (_e1079 - _e1080);
                        }
                        let _e1083 = phi_1055_;
                        local_108 = _e1083;
                        let _e1084 = local;
                        let _e1085 = local_86;
                        if (_e1084 >= _e1085) {
                            let _e1087 = local;
                            let _e1088 = local_107;
                            if (_e1087 < _e1088) {
                                let _e1090 = local_108;
                                let _e1091 = local;
                                local_109 = (_e1090 + _e1091);
                                let _e1093 = local;
                                let _e1094 = local_106;
                                let _e1097 = local_102;
                                let _e1099 = ((_e1097 + (_e1093 >> bitcast<u32>(_e1094))) - 1u);
                                local_110 = _e1099;
                                if (_e1099 < 512u) {
                                } else {
                                    phi_1647_ = true;
                                    break;
                                }
                                let _e1101 = local_110;
                                let _e1103 = global_1[_e1101];
                                local_111 = _e1103;
                                let _e1104 = local_109;
                                let _e1105 = (_e1104 < 512u);
                                local_112 = _e1105;
                                if _e1105 {
                                } else {
                                    phi_1647_ = true;
                                    break;
                                }
                                let _e1106 = local_109;
                                let _e1108 = global_1[_e1106];
                                let _e1109 = local_111;
                                local_113 = (_e1109 + _e1108);
                                let _e1111 = local_112;
                                if _e1111 {
                                } else {
                                    phi_1647_ = true;
                                    break;
                                }
                                let _e1112 = local_113;
                                global_1[_e1106] = _e1112;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e1113 = local_104;
                        phi_1036_ = _e1083;
                        phi_1039_ = _e1076;
                        phi_1041_ = (_e1113 - 1u);
                    } else {
                        phi_1036_ = u32();
                        phi_1039_ = u32();
                        phi_1041_ = u32();
                    }
                    let _e1116 = phi_1036_;
                    let _e1118 = phi_1039_;
                    let _e1120 = phi_1041_;
                    continue;
                    continuing {
                        let _e1121 = local_105;
                        phi_1035_ = _e1116;
                        phi_1038_ = _e1118;
                        phi_1040_ = _e1120;
                        phi_1647_ = _e1063;
                        break if !(_e1121);
                    }
                }
                let _e1124 = phi_1647_;
                if _e1124 {
                    break;
                }
                phi_1659_ = _e1124;
                phi_1146_ = 256u;
            } else {
                phi_1092_ = 1u;
                phi_1095_ = 0u;
                loop {
                    let _e939 = phi_1092_;
                    let _e941 = phi_1095_;
                    local_114 = _e939;
                    local_115 = _e941;
                    local_156 = _e941;
                    let _e942 = local_114;
                    let _e943 = (_e942 < 256u);
                    local_116 = _e943;
                    if _e943 {
                        let _e944 = local_115;
                        let _e946 = select(0u, 256u, (_e944 == 0u));
                        local_152 = _e946;
                        let _e947 = local_115;
                        let _e948 = local;
                        let _e949 = (_e947 + _e948);
                        local_117 = _e949;
                        if (_e949 < 512u) {
                        } else {
                            phi_1632_ = true;
                            break;
                        }
                        let _e951 = local_117;
                        let _e953 = global_1[_e951];
                        local_118 = _e953;
                        let _e954 = local;
                        let _e955 = local_114;
                        if (_e954 >= _e955) {
                            let _e957 = local;
                            let _e958 = local_114;
                            let _e960 = local_115;
                            let _e961 = (_e960 + (_e957 - _e958));
                            local_119 = _e961;
                            if (_e961 < 512u) {
                            } else {
                                phi_1632_ = true;
                                break;
                            }
                            let _e963 = local_119;
                            let _e965 = global_1[_e963];
                            let _e966 = local_118;
                            phi_1131_ = (_e965 + _e966);
                        } else {
                            phi_1131_ = _e953;
                        }
                        let _e969 = phi_1131_;
                        local_120 = _e969;
                        let _e970 = local_152;
                        let _e971 = local;
                        let _e972 = (_e970 + _e971);
                        local_121 = _e972;
                        if (_e972 < 512u) {
                        } else {
                            phi_1632_ = true;
                            break;
                        }
                        let _e974 = local_121;
                        let _e976 = local_120;
                        global_1[_e974] = _e976;
                        storageBarrier();
                        workgroupBarrier();
                        let _e977 = local_114;
                        phi_1093_ = (_e977 * 2u);
                        phi_1096_ = _e946;
                    } else {
                        phi_1093_ = u32();
                        phi_1096_ = u32();
                    }
                    let _e980 = phi_1093_;
                    let _e982 = phi_1096_;
                    continue;
                    continuing {
                        let _e983 = local_116;
                        phi_1092_ = _e980;
                        phi_1095_ = _e982;
                        phi_1632_ = _e902;
                        break if !(_e983);
                    }
                }
                let _e986 = phi_1632_;
                if _e986 {
                    break;
                }
                phi_1659_ = _e986;
                let _e1593 = local_156;
                phi_1146_ = _e1593;
            }
            let _e1126 = phi_1659_;
            let _e1128 = phi_1146_;
            local_122 = _e1128;
            let _e1129 = local;
            if (_e1129 == 0u) {
                phi_1160_ = 0u;
            } else {
                let _e1131 = local_122;
                let _e1132 = local;
                let _e1134 = ((_e1131 + _e1132) - 1u);
                local_123 = _e1134;
                if (_e1134 < 512u) {
                } else {
                    break;
                }
                let _e1136 = local_123;
                let _e1138 = global_1[_e1136];
                phi_1160_ = _e1138;
            }
            let _e1140 = phi_1160_;
            phi_1657_ = _e1126;
            phi_1164_ = _e1140;
            phi_1167_ = type_20();
            phi_1169_ = _e224;
            phi_1171_ = 0u;
            phi_1173_ = 0u;
            phi_1175_ = 0u;
            phi_1177_ = 0u;
            phi_1179_ = 0u;
            loop {
                let _e1142 = phi_1657_;
                let _e1144 = phi_1164_;
                let _e1146 = phi_1167_;
                let _e1148 = phi_1169_;
                let _e1150 = phi_1171_;
                let _e1152 = phi_1173_;
                let _e1154 = phi_1175_;
                let _e1156 = phi_1177_;
                let _e1158 = phi_1179_;
                local_124 = _e1144;
                local_125 = _e1146;
                local_126 = _e1148;
                local_127 = _e1150;
                local_128 = _e1152;
                local_129 = _e1154;
                local_130 = _e1156;
                local_131 = _e1158;
                let _e1159 = local_126;
                let _e1160 = local_9;
                if (_e1159 < _e1160) {
                    let _e1162 = local;
                    let _e1164 = local_11;
                    let _e1166 = local_126;
                    let _e1167 = (_e1166 < ((_e1162 + 1u) * _e1164));
                    if _e1167 {
                        let _e1168 = local_126;
                        let _e1169 = (_e1168 * 5u);
                        local_132 = _e1169;
                        let _e1170 = local_5;
                        if (_e1169 < _e1170) {
                        } else {
                            phi_1661_ = true;
                            break;
                        }
                        let _e1172 = local_132;
                        let _e1175 = global_8.member[_e1172];
                        local_133 = _e1175;
                        let _e1176 = local_127;
                        let _e1178 = local_127;
                        let _e1180 = local_126;
                        let _e1181 = local_6;
                        let _e1182 = (_e1180 < _e1181);
                        local_134 = _e1182;
                        if _e1182 {
                        } else {
                            phi_1661_ = true;
                            break;
                        }
                        let _e1183 = local_126;
                        let _e1186 = global_9.member[_e1183];
                        if ((_e1186 & 1u) == 0u) {
                            phi_1237_ = 0u;
                            loop {
                                let _e1194 = phi_1237_;
                                local_135 = _e1194;
                                let _e1195 = local_135;
                                if (_e1195 < 4u) {
                                    let _e1197 = local_132;
                                    let _e1198 = local_135;
                                    let _e1199 = (_e1197 + _e1198);
                                    local_136 = _e1199;
                                    let _e1200 = local_5;
                                    if (_e1199 < _e1200) {
                                    } else {
                                        phi_1653_ = true;
                                        break;
                                    }
                                    let _e1202 = local_136;
                                    let _e1205 = global_8.member[_e1202];
                                    let _e1206 = local_44;
                                    let _e1207 = (_e1205 > _e1206);
                                    if _e1207 {
                                        let _e1208 = local_135;
                                        phi_1268_ = (_e1208 + 1u);
                                    } else {
                                        phi_1268_ = u32();
                                    }
                                    let _e1211 = phi_1268_;
                                    phi_1238_ = _e1211;
                                    phi_1269_ = _e1207;
                                } else {
                                    phi_1238_ = u32();
                                    phi_1269_ = false;
                                }
                                let _e1213 = phi_1238_;
                                let _e1215 = phi_1269_;
                                local_137 = _e1215;
                                continue;
                                continuing {
                                    let _e1216 = local_137;
                                    phi_1237_ = _e1213;
                                    phi_1653_ = _e1142;
                                    break if !(_e1216);
                                }
                            }
                            let _e1219 = phi_1653_;
                            phi_1661_ = _e1219;
                            if _e1219 {
                                break;
                            }
                            let _e1220 = local_132;
                            let _e1221 = local_135;
                            let _e1222 = (_e1220 + _e1221);
                            local_138 = _e1222;
                            let _e1223 = local_5;
                            if (_e1222 < _e1223) {
                            } else {
                                phi_1661_ = true;
                                break;
                            }
                            let _e1225 = local_138;
                            let _e1228 = global_8.member[_e1225];
                            local_139 = _e1228;
                            let _e1229 = local_12;
                            if (_e1228 <= _e1229) {
                                let _e1234 = local_135;
                                let _e1235 = local_139;
                                phi_1301_ = type_20(1u, type_15(_e1234, _e1235));
                            } else {
                                phi_1301_ = type_20(0u, type_20().member_1);
                            }
                            let _e1239 = phi_1301_;
                            phi_1667_ = _e1219;
                            phi_1303_ = _e1239;
                        } else {
                            let _e1189 = local_125;
                            phi_1667_ = _e1142;
                            phi_1303_ = type_20(0u, _e1189.member_1);
                        }
                        let _e1241 = phi_1667_;
                        let _e1243 = phi_1303_;
                        local_140 = _e1243;
                        if (bitcast<i32>(_e1243.member) != 0i) {
                            let _e1250 = local_140;
                            let _e1253 = local_42;
                            let _e1254 = local_124;
                            let _e1256 = local_42;
                            let _e1257 = local_124;
                            let _e1259 = local_42;
                            if (_e1250.member_1.member_1 <= (_e1259 - select(_e1257, _e1256, (_e1253 < _e1254)))) {
                                let _e1265 = local_140;
                                phi_1330_ = type_20(1u, _e1265.member_1);
                            } else {
                                phi_1330_ = type_20(0u, type_20().member_1);
                            }
                            let _e1269 = phi_1330_;
                            phi_1332_ = _e1269;
                        } else {
                            phi_1332_ = type_20(0u, type_20().member_1);
                        }
                        let _e1271 = phi_1332_;
                        local_141 = _e1271;
                        if (bitcast<i32>(_e1271.member) != 0i) {
                            let _e1301 = local_141;
                            local_142 = _e1301.member_1.member;
                            let _e1304 = local_141;
                            local_143 = _e1304.member_1.member_1;
                            let _e1307 = local_126;
                            let _e1308 = (2u * _e1307);
                            local_144 = _e1308;
                            let _e1309 = local_7;
                            if (_e1308 < _e1309) {
                            } else {
                                phi_1661_ = true;
                                break;
                            }
                            let _e1311 = local_144;
                            let _e1314 = local_124;
                            global_10.member[_e1311] = _e1314;
                            let _e1315 = local_144;
                            let _e1316 = (_e1315 + 1u);
                            local_145 = _e1316;
                            let _e1317 = local_7;
                            if (_e1316 < _e1317) {
                            } else {
                                phi_1661_ = true;
                                break;
                            }
                            let _e1319 = local_145;
                            let _e1322 = local_143;
                            global_10.member[_e1319] = _e1322;
                            let _e1323 = local_142;
                            local_146 = (_e1323 << bitcast<u32>(1u));
                            let _e1326 = local_134;
                            if _e1326 {
                            } else {
                                phi_1661_ = true;
                                break;
                            }
                            let _e1327 = local_146;
                            global_9.member[_e1183] = _e1327;
                            let _e1328 = local_142;
                            if (_e1328 > 0u) {
                                let _e1330 = local_131;
                                let _e1332 = local_133;
                                let _e1333 = local_143;
                                let _e1335 = local_130;
                                phi_1378_ = (_e1335 + (_e1332 - _e1333));
                                phi_1379_ = (_e1330 + 1u);
                            } else {
                                phi_1378_ = _e1156;
                                phi_1379_ = _e1158;
                            }
                            let _e1338 = phi_1378_;
                            let _e1340 = phi_1379_;
                            let _e1341 = local_124;
                            let _e1342 = local_143;
                            phi_1418_ = (_e1341 + _e1342);
                            phi_1419_ = _e1152;
                            phi_1420_ = _e1154;
                            phi_1421_ = _e1338;
                            phi_1422_ = _e1340;
                        } else {
                            let _e1275 = local_126;
                            let _e1276 = (2u * _e1275);
                            local_147 = _e1276;
                            let _e1277 = local_7;
                            if (_e1276 < _e1277) {
                            } else {
                                phi_1661_ = true;
                                break;
                            }
                            let _e1279 = local_147;
                            global_10.member[_e1279] = 0u;
                            let _e1282 = local_147;
                            let _e1283 = (_e1282 + 1u);
                            local_148 = _e1283;
                            let _e1284 = local_7;
                            if (_e1283 < _e1284) {
                            } else {
                                phi_1661_ = true;
                                break;
                            }
                            let _e1286 = local_148;
                            global_10.member[_e1286] = 0u;
                            let _e1289 = local_133;
                            if (_e1289 > 0u) {
                                let _e1291 = local_134;
                                if _e1291 {
                                } else {
                                    phi_1661_ = true;
                                    break;
                                }
                                global_9.member[_e1183] = 1u;
                                let _e1292 = local_129;
                                let _e1294 = local_128;
                                let _e1295 = local_133;
                                phi_1416_ = (_e1294 + _e1295);
                                phi_1417_ = (_e1292 + 1u);
                            } else {
                                phi_1416_ = _e1152;
                                phi_1417_ = _e1154;
                            }
                            let _e1298 = phi_1416_;
                            let _e1300 = phi_1417_;
                            phi_1418_ = _e1144;
                            phi_1419_ = _e1298;
                            phi_1420_ = _e1300;
                            phi_1421_ = _e1156;
                            phi_1422_ = _e1158;
                        }
                        let _e1345 = phi_1418_;
                        let _e1347 = phi_1419_;
                        let _e1349 = phi_1420_;
                        let _e1351 = phi_1421_;
                        let _e1353 = phi_1422_;
                        let _e1354 = local_126;
                        phi_1663_ = _e1241;
                        phi_1424_ = _e1345;
                        phi_1425_ = _e1243;
                        phi_1426_ = (_e1354 + 1u);
                        phi_1427_ = select(_e1178, _e1175, (_e1175 > _e1176));
                        phi_1428_ = _e1347;
                        phi_1429_ = _e1349;
                        phi_1430_ = _e1351;
                        phi_1431_ = _e1353;
                    } else {
                        phi_1663_ = _e1142;
                        phi_1424_ = u32();
                        phi_1425_ = type_20();
                        phi_1426_ = u32();
                        phi_1427_ = u32();
                        phi_1428_ = u32();
                        phi_1429_ = u32();
                        phi_1430_ = u32();
                        phi_1431_ = u32();
                    }
                    let _e1357 = phi_1663_;
                    let _e1359 = phi_1424_;
                    let _e1361 = phi_1425_;
                    let _e1363 = phi_1426_;
                    let _e1365 = phi_1427_;
                    let _e1367 = phi_1428_;
                    let _e1369 = phi_1429_;
                    let _e1371 = phi_1430_;
                    let _e1373 = phi_1431_;
                    phi_1662_ = _e1357;
                    phi_1165_ = _e1359;
                    phi_1168_ = _e1361;
                    phi_1170_ = _e1363;
                    phi_1172_ = _e1365;
                    phi_1174_ = _e1367;
                    phi_1176_ = _e1369;
                    phi_1178_ = _e1371;
                    phi_1180_ = _e1373;
                    phi_1432_ = _e1167;
                } else {
                    phi_1662_ = _e1142;
                    phi_1165_ = u32();
                    phi_1168_ = type_20();
                    phi_1170_ = u32();
                    phi_1172_ = u32();
                    phi_1174_ = u32();
                    phi_1176_ = u32();
                    phi_1178_ = u32();
                    phi_1180_ = u32();
                    phi_1432_ = false;
                }
                let _e1375 = phi_1662_;
                let _e1377 = phi_1165_;
                let _e1379 = phi_1168_;
                let _e1381 = phi_1170_;
                let _e1383 = phi_1172_;
                let _e1385 = phi_1174_;
                let _e1387 = phi_1176_;
                let _e1389 = phi_1178_;
                let _e1391 = phi_1180_;
                let _e1393 = phi_1432_;
                local_149 = _e1393;
                continue;
                continuing {
                    let _e1394 = local_149;
                    phi_1657_ = _e1375;
                    phi_1164_ = _e1377;
                    phi_1167_ = _e1379;
                    phi_1169_ = _e1381;
                    phi_1171_ = _e1383;
                    phi_1173_ = _e1385;
                    phi_1175_ = _e1387;
                    phi_1177_ = _e1389;
                    phi_1179_ = _e1391;
                    phi_1661_ = _e1375;
                    break if !(_e1394);
                }
            }
            let _e1397 = phi_1661_;
            if _e1397 {
                break;
            }
            let _e1398 = local_131;
            if (_e1398 > 0u) {
                let _e1400 = local_8;
                if (22u < _e1400) {
                } else {
                    break;
                }
                let _e1404 = local_131;
                let _e1405 = atomicAdd((&global_7.member[22u]), _e1404);
                let _e1406 = local_8;
                if (23u < _e1406) {
                } else {
                    break;
                }
                let _e1410 = local_130;
                let _e1411 = atomicAdd((&global_7.member[23u]), _e1410);
            }
            let _e1412 = local_129;
            if (_e1412 > 0u) {
                let _e1414 = local_8;
                if (14u < _e1414) {
                } else {
                    break;
                }
                let _e1418 = local_129;
                let _e1419 = atomicAdd((&global_7.member[14u]), _e1418);
                let _e1420 = local_8;
                if (15u < _e1420) {
                } else {
                    break;
                }
                let _e1424 = local_128;
                let _e1425 = atomicAdd((&global_7.member[15u]), _e1424);
            }
            let _e1426 = local_127;
            if (_e1426 > 0u) {
                let _e1428 = local_8;
                if (8u < _e1428) {
                } else {
                    break;
                }
                let _e1432 = local_127;
                let _e1433 = atomicMax((&global_7.member[8u]), _e1432);
            }
            let _e1434 = local;
            if (_e1434 == 255u) {
                let _e1436 = local_122;
                let _e1437 = local;
                let _e1438 = (_e1436 + _e1437);
                local_150 = _e1438;
                if (_e1438 < 512u) {
                } else {
                    break;
                }
                let _e1440 = local_150;
                let _e1442 = global_1[_e1440];
                local_151 = _e1442;
                let _e1443 = local_8;
                if (16u < _e1443) {
                } else {
                    break;
                }
                let _e1447 = local_151;
                let _e1448 = atomicAdd((&global_7.member[16u]), _e1447);
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn subgroups(@builtin(local_invocation_index) param: u32, @builtin(subgroup_size) param_1: u32, @builtin(num_subgroups) param_2: u32, @builtin(subgroup_id) param_3: u32, @builtin(subgroup_invocation_id) param_4: u32) {
    global = param;
    global_2 = param_1;
    global_3 = param_2;
    global_4 = param_3;
    global_5 = param_4;
    function_();
}
