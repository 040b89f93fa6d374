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
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: bool;
    var local_15: f32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: bool;
    var local_20: f32;
    var local_21: f32;
    var local_22: f32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: f32;
    var local_30: u32;
    var local_31: bool;
    var local_32: f32;
    var local_33: bool;
    var local_34: f32;
    var local_35: f32;
    var local_36: f32;
    var local_37: bool;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: f32;
    var local_42: u32;
    var local_43: f32;
    var local_44: u32;
    var local_45: f32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
    var local_54: f32;
    var local_55: u32;
    var local_56: u32;
    var local_57: u32;
    var local_58: f32;
    var local_59: u32;
    var local_60: u32;
    var local_61: u32;
    var local_62: f32;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: f32;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: u32;
    var local_72: u32;
    var local_73: u32;
    var local_74: array<f32, 4>;
    var local_75: u32;
    var local_76: u32;
    var local_77: u32;
    var local_78: f32;
    var local_79: u32;
    var local_80: f32;
    var local_81: u32;
    var local_82: f32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: u32;
    var local_91: f32;
    var local_92: u32;
    var local_93: u32;
    var local_94: u32;
    var local_95: f32;
    var local_96: u32;
    var local_97: u32;
    var local_98: u32;
    var local_99: f32;
    var local_100: u32;
    var local_101: u32;
    var local_102: u32;
    var local_103: f32;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: bool;
    var local_112: array<f32, 4>;
    var local_113: bool;
    var local_114: bool;
    var local_115: bool;
    var local_116: array<f32, 3>;
    var local_117: f32;
    var local_118: u32;
    var local_119: u32;
    var local_120: u32;
    var local_121: u32;
    var local_122: u32;
    var local_123: u32;
    var local_124: u32;
    var local_125: u32;
    var local_126: u32;
    var local_127: u32;
    var local_128: f32;
    var local_129: f32;
    var local_130: bool;
    var local_131: f32;
    var local_132: u32;
    var local_133: u32;
    var local_134: f32;
    var local_135: f32;
    var local_136: f32;
    var local_137: f32;
    var local_138: f32;
    var local_139: f32;
    var local_140: f32;
    var local_141: f32;
    var local_142: f32;
    var local_143: f32;
    var local_144: f32;
    var local_145: f32;
    var local_146: f32;
    var local_147: f32;
    var local_148: f32;
    var local_149: bool;
    var local_150: f32;
    var local_151: f32;
    var local_152: f32;
    var phi_126_: u32;
    var phi_194_: f32;
    var phi_209_: f32;
    var phi_210_: f32;
    var phi_211_: f32;
    var phi_212_: f32;
    var phi_213_: bool;
    var phi_235_: f32;
    var phi_250_: f32;
    var phi_251_: f32;
    var phi_252_: f32;
    var phi_253_: f32;
    var phi_254_: bool;
    var phi_276_: f32;
    var phi_291_: f32;
    var phi_292_: f32;
    var phi_293_: f32;
    var phi_294_: f32;
    var phi_295_: bool;
    var phi_317_: f32;
    var phi_332_: f32;
    var phi_333_: f32;
    var phi_334_: f32;
    var phi_335_: f32;
    var phi_336_: bool;
    var phi_379_: f32;
    var phi_380_: f32;
    var phi_381_: f32;
    var phi_382_: f32;
    var phi_383_: bool;
    var phi_422_: f32;
    var phi_423_: f32;
    var phi_424_: f32;
    var phi_425_: f32;
    var phi_426_: bool;
    var phi_464_: f32;
    var phi_465_: f32;
    var phi_466_: f32;
    var phi_467_: f32;
    var phi_468_: bool;
    var phi_484_: array<f32, 4>;
    var phi_485_: array<f32, 4>;
    var phi_486_: array<f32, 4>;
    var phi_487_: array<f32, 4>;
    var phi_533_: f32;
    var phi_534_: f32;
    var phi_554_: f32;
    var phi_555_: f32;
    var phi_556_: f32;
    var phi_557_: f32;
    var phi_563_: f32;
    var phi_564_: f32;
    var phi_566_: f32;
    var phi_567_: bool;
    var phi_572_: f32;
    var phi_582_: bool;
    var phi_603_: u32;
    var phi_735_: f32;
    var phi_750_: f32;
    var phi_751_: f32;
    var phi_752_: f32;
    var phi_753_: f32;
    var phi_754_: bool;
    var phi_776_: f32;
    var phi_791_: f32;
    var phi_792_: f32;
    var phi_793_: f32;
    var phi_794_: f32;
    var phi_795_: bool;
    var phi_817_: f32;
    var phi_832_: f32;
    var phi_833_: f32;
    var phi_834_: f32;
    var phi_835_: f32;
    var phi_836_: bool;
    var phi_858_: f32;
    var phi_873_: f32;
    var phi_874_: f32;
    var phi_875_: f32;
    var phi_876_: f32;
    var phi_877_: bool;
    var phi_935_: f32;
    var phi_936_: f32;
    var phi_937_: f32;
    var phi_938_: f32;
    var phi_939_: bool;
    var phi_978_: f32;
    var phi_979_: f32;
    var phi_980_: f32;
    var phi_981_: f32;
    var phi_982_: bool;
    var phi_1020_: f32;
    var phi_1021_: f32;
    var phi_1022_: f32;
    var phi_1023_: f32;
    var phi_1024_: bool;
    var phi_1070_: array<f32, 4>;
    var phi_1071_: array<f32, 4>;
    var phi_1072_: array<f32, 4>;
    var phi_1073_: array<f32, 4>;
    var phi_1082_: array<f32, 3>;
    var phi_1083_: f32;
    var phi_1099_: u32;
    var phi_1231_: f32;
    var phi_1246_: f32;
    var phi_1247_: f32;
    var phi_1248_: f32;
    var phi_1249_: f32;
    var phi_1250_: bool;
    var phi_1272_: f32;
    var phi_1287_: f32;
    var phi_1288_: f32;
    var phi_1289_: f32;
    var phi_1290_: f32;
    var phi_1291_: bool;
    var phi_1313_: f32;
    var phi_1328_: f32;
    var phi_1329_: f32;
    var phi_1330_: f32;
    var phi_1331_: f32;
    var phi_1332_: bool;
    var phi_1354_: f32;
    var phi_1369_: f32;
    var phi_1370_: f32;
    var phi_1371_: f32;
    var phi_1372_: f32;
    var phi_1373_: bool;
    var phi_1431_: f32;
    var phi_1432_: f32;
    var phi_1433_: f32;
    var phi_1434_: f32;
    var phi_1435_: bool;
    var phi_1474_: f32;
    var phi_1475_: f32;
    var phi_1476_: f32;
    var phi_1477_: f32;
    var phi_1478_: bool;
    var phi_1516_: f32;
    var phi_1517_: f32;
    var phi_1518_: f32;
    var phi_1519_: f32;
    var phi_1520_: bool;
    var phi_1566_: array<f32, 4>;
    var phi_1567_: array<f32, 4>;
    var phi_1568_: array<f32, 4>;
    var phi_1569_: array<f32, 4>;
    var phi_1570_: array<f32, 3>;
    var phi_1571_: f32;
    var phi_1572_: bool;
    var phi_1573_: array<f32, 4>;
    var phi_1574_: bool;
    var phi_1575_: bool;
    var phi_1605_: array<f32, 3>;
    var phi_1607_: array<f32, 3>;
    var phi_1608_: f32;
    var phi_1711_: bool;
    var phi_1738_: f32;
    var phi_1740_: f32;
    var phi_1741_: bool;
    var phi_1742_: f32;
    var phi_1743_: f32;
    var phi_1744_: bool;
    var phi_1745_: f32;
    var phi_1746_: f32;
    var phi_1747_: bool;
    var phi_1748_: bool;
    var phi_1749_: f32;
    var phi_1750_: f32;
    var phi_1751_: bool;
    var phi_1752_: bool;
    var phi_1770_: f32;
    var phi_1771_: f32;
    var phi_127_: u32;
    var phi_1802_: bool;

    let _e207 = global_8;
    local_151 = bitcast<f32>(_e207);
    let _e209 = global_9;
    let _e210 = bitcast<f32>(_e209);
    local_152 = _e210;
    switch bitcast<i32>(0u) {
        default: {
            let _e212 = global;
            local = _e212;
            let _e213 = global_1;
            let _e214 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e228 = global_5.member.member.member;
            let _e232 = global_5.member.member.member_1;
            local_5 = (_e228 * _e232);
            local_6 = (_e214.x * 256u);
            phi_126_ = (_e213.x * 256u);
            loop {
                let _e237 = phi_126_;
                local_7 = _e237;
                let _e238 = local_7;
                let _e239 = local_5;
                let _e240 = (_e238 < _e239);
                local_8 = _e240;
                if _e240 {
                    let _e241 = local_7;
                    let _e242 = local;
                    let _e243 = (_e241 + _e242);
                    local_9 = _e243;
                    let _e244 = local_5;
                    if (_e243 < _e244) {
                        let _e246 = local_9;
                        let _e247 = local_2;
                        if (_e246 < _e247) {
                        } else {
                            phi_1802_ = true;
                            break;
                        }
                        let _e249 = local_9;
                        let _e252 = global_3.member[_e249];
                        local_10 = _e252;
                        let _e256 = global_5.member.member.member_7;
                        let _e258 = select(3u, 4u, (_e256 == 1u));
                        local_133 = _e258;
                        if (_e258 == 0u) {
                            let _e260 = local_10;
                            let _e261 = bitcast<f32>(_e260);
                            phi_487_ = array<f32, 4>(_e261, _e261, _e261, _e261);
                        } else {
                            let _e263 = local_133;
                            if (_e263 == 1u) {
                                let _e265 = local_10;
                                let _e266 = (_e265 & 65535u);
                                local_11 = ((_e266 & 32768u) << bitcast<u32>(16i));
                                let _e272 = ((_e266 >> bitcast<u32>(10i)) & 31u);
                                local_12 = _e272;
                                local_13 = (_e266 & 1023u);
                                let _e274 = (_e272 == 0u);
                                local_14 = _e274;
                                if _e274 {
                                    let _e275 = local_13;
                                    let _e276 = f32(_e275);
                                    local_15 = _e276;
                                    let _e278 = local_11;
                                    if (_e278 == 0u) {
                                        phi_194_ = (_e276 * 0.000000059604645f);
                                    } else {
                                        let _e280 = local_15;
                                        phi_194_ = (_e280 * -0.000000059604645f);
                                    }
                                    let _e283 = phi_194_;
                                    phi_211_ = _e283;
                                    phi_212_ = f32();
                                    phi_213_ = true;
                                } else {
                                    let _e284 = local_12;
                                    let _e285 = (_e284 == 31u);
                                    if _e285 {
                                        let _e286 = local_11;
                                        let _e288 = local_13;
                                        phi_209_ = bitcast<f32>(((_e286 | 2139095040u) | (_e288 << bitcast<u32>(13i))));
                                        phi_210_ = f32();
                                    } else {
                                        let _e293 = local_12;
                                        let _e297 = local_11;
                                        let _e299 = local_13;
                                        phi_209_ = f32();
                                        phi_210_ = bitcast<f32>(((_e297 | ((_e293 + 112u) << bitcast<u32>(23i))) | (_e299 << bitcast<u32>(13i))));
                                    }
                                    let _e305 = phi_209_;
                                    let _e307 = phi_210_;
                                    phi_211_ = _e305;
                                    phi_212_ = _e307;
                                    phi_213_ = _e285;
                                }
                                let _e309 = phi_211_;
                                let _e311 = phi_212_;
                                let _e313 = phi_213_;
                                local_134 = select(_e311, _e309, _e313);
                                let _e315 = local_10;
                                let _e317 = (_e315 >> bitcast<u32>(16i));
                                local_16 = ((_e317 & 32768u) << bitcast<u32>(16i));
                                let _e323 = ((_e317 >> bitcast<u32>(10i)) & 31u);
                                local_17 = _e323;
                                local_18 = (_e317 & 1023u);
                                let _e325 = (_e323 == 0u);
                                local_19 = _e325;
                                if _e325 {
                                    let _e326 = local_18;
                                    let _e327 = f32(_e326);
                                    local_20 = _e327;
                                    let _e329 = local_16;
                                    if (_e329 == 0u) {
                                        phi_235_ = (_e327 * 0.000000059604645f);
                                    } else {
                                        let _e331 = local_20;
                                        phi_235_ = (_e331 * -0.000000059604645f);
                                    }
                                    let _e334 = phi_235_;
                                    phi_252_ = _e334;
                                    phi_253_ = f32();
                                    phi_254_ = true;
                                } else {
                                    let _e335 = local_17;
                                    let _e336 = (_e335 == 31u);
                                    if _e336 {
                                        let _e337 = local_16;
                                        let _e339 = local_18;
                                        phi_250_ = bitcast<f32>(((_e337 | 2139095040u) | (_e339 << bitcast<u32>(13i))));
                                        phi_251_ = f32();
                                    } else {
                                        let _e344 = local_17;
                                        let _e348 = local_16;
                                        let _e350 = local_18;
                                        phi_250_ = f32();
                                        phi_251_ = bitcast<f32>(((_e348 | ((_e344 + 112u) << bitcast<u32>(23i))) | (_e350 << bitcast<u32>(13i))));
                                    }
                                    let _e356 = phi_250_;
                                    let _e358 = phi_251_;
                                    phi_252_ = _e356;
                                    phi_253_ = _e358;
                                    phi_254_ = _e336;
                                }
                                let _e360 = phi_252_;
                                let _e362 = phi_253_;
                                let _e364 = phi_254_;
                                local_135 = select(_e362, _e360, _e364);
                                let _e366 = local_14;
                                if _e366 {
                                    let _e367 = local_13;
                                    let _e368 = f32(_e367);
                                    local_21 = _e368;
                                    let _e370 = local_11;
                                    if (_e370 == 0u) {
                                        phi_276_ = (_e368 * 0.000000059604645f);
                                    } else {
                                        let _e372 = local_21;
                                        phi_276_ = (_e372 * -0.000000059604645f);
                                    }
                                    let _e375 = phi_276_;
                                    phi_293_ = _e375;
                                    phi_294_ = f32();
                                    phi_295_ = true;
                                } else {
                                    let _e376 = local_12;
                                    let _e377 = (_e376 == 31u);
                                    if _e377 {
                                        let _e378 = local_11;
                                        let _e380 = local_13;
                                        phi_291_ = bitcast<f32>(((_e378 | 2139095040u) | (_e380 << bitcast<u32>(13i))));
                                        phi_292_ = f32();
                                    } else {
                                        let _e385 = local_12;
                                        let _e389 = local_11;
                                        let _e391 = local_13;
                                        phi_291_ = f32();
                                        phi_292_ = bitcast<f32>(((_e389 | ((_e385 + 112u) << bitcast<u32>(23i))) | (_e391 << bitcast<u32>(13i))));
                                    }
                                    let _e397 = phi_291_;
                                    let _e399 = phi_292_;
                                    phi_293_ = _e397;
                                    phi_294_ = _e399;
                                    phi_295_ = _e377;
                                }
                                let _e401 = phi_293_;
                                let _e403 = phi_294_;
                                let _e405 = phi_295_;
                                local_136 = select(_e403, _e401, _e405);
                                let _e407 = local_19;
                                if _e407 {
                                    let _e408 = local_18;
                                    let _e409 = f32(_e408);
                                    local_22 = _e409;
                                    let _e411 = local_16;
                                    if (_e411 == 0u) {
                                        phi_317_ = (_e409 * 0.000000059604645f);
                                    } else {
                                        let _e413 = local_22;
                                        phi_317_ = (_e413 * -0.000000059604645f);
                                    }
                                    let _e416 = phi_317_;
                                    phi_334_ = _e416;
                                    phi_335_ = f32();
                                    phi_336_ = true;
                                } else {
                                    let _e417 = local_17;
                                    let _e418 = (_e417 == 31u);
                                    if _e418 {
                                        let _e419 = local_16;
                                        let _e421 = local_18;
                                        phi_332_ = bitcast<f32>(((_e419 | 2139095040u) | (_e421 << bitcast<u32>(13i))));
                                        phi_333_ = f32();
                                    } else {
                                        let _e426 = local_17;
                                        let _e430 = local_16;
                                        let _e432 = local_18;
                                        phi_332_ = f32();
                                        phi_333_ = bitcast<f32>(((_e430 | ((_e426 + 112u) << bitcast<u32>(23i))) | (_e432 << bitcast<u32>(13i))));
                                    }
                                    let _e438 = phi_332_;
                                    let _e440 = phi_333_;
                                    phi_334_ = _e438;
                                    phi_335_ = _e440;
                                    phi_336_ = _e418;
                                }
                                let _e442 = phi_334_;
                                let _e444 = phi_335_;
                                let _e446 = phi_336_;
                                let _e448 = local_134;
                                let _e449 = local_135;
                                let _e450 = local_136;
                                phi_486_ = array<f32, 4>(_e448, _e449, _e450, select(_e444, _e442, _e446));
                            } else {
                                let _e452 = local_133;
                                if (_e452 == 2u) {
                                    let _e454 = local_10;
                                    let _e455 = (_e454 & 2047u);
                                    let _e458 = ((_e455 >> bitcast<u32>(6u)) & 31u);
                                    local_23 = _e458;
                                    local_24 = (_e455 & 63u);
                                    if (_e458 == 0u) {
                                        let _e461 = local_24;
                                        phi_381_ = (f32(_e461) * 0.0000009536743f);
                                        phi_382_ = f32();
                                        phi_383_ = true;
                                    } else {
                                        let _e464 = local_23;
                                        let _e465 = (_e464 == 31u);
                                        if _e465 {
                                            let _e466 = local_24;
                                            phi_379_ = bitcast<f32>((2139095040u | (_e466 << bitcast<u32>(17u))));
                                            phi_380_ = f32();
                                        } else {
                                            let _e471 = local_23;
                                            let _e475 = local_24;
                                            phi_379_ = f32();
                                            phi_380_ = bitcast<f32>((((_e471 + 112u) << bitcast<u32>(23i)) | (_e475 << bitcast<u32>(17u))));
                                        }
                                        let _e481 = phi_379_;
                                        let _e483 = phi_380_;
                                        phi_381_ = _e481;
                                        phi_382_ = _e483;
                                        phi_383_ = _e465;
                                    }
                                    let _e485 = phi_381_;
                                    let _e487 = phi_382_;
                                    let _e489 = phi_383_;
                                    local_137 = select(_e487, _e485, _e489);
                                    let _e491 = local_10;
                                    let _e494 = ((_e491 >> bitcast<u32>(11i)) & 2047u);
                                    let _e497 = ((_e494 >> bitcast<u32>(6u)) & 31u);
                                    local_25 = _e497;
                                    local_26 = (_e494 & 63u);
                                    if (_e497 == 0u) {
                                        let _e500 = local_26;
                                        phi_424_ = (f32(_e500) * 0.0000009536743f);
                                        phi_425_ = f32();
                                        phi_426_ = true;
                                    } else {
                                        let _e503 = local_25;
                                        let _e504 = (_e503 == 31u);
                                        if _e504 {
                                            let _e505 = local_26;
                                            phi_422_ = bitcast<f32>((2139095040u | (_e505 << bitcast<u32>(17u))));
                                            phi_423_ = f32();
                                        } else {
                                            let _e510 = local_25;
                                            let _e514 = local_26;
                                            phi_422_ = f32();
                                            phi_423_ = bitcast<f32>((((_e510 + 112u) << bitcast<u32>(23i)) | (_e514 << bitcast<u32>(17u))));
                                        }
                                        let _e520 = phi_422_;
                                        let _e522 = phi_423_;
                                        phi_424_ = _e520;
                                        phi_425_ = _e522;
                                        phi_426_ = _e504;
                                    }
                                    let _e524 = phi_424_;
                                    let _e526 = phi_425_;
                                    let _e528 = phi_426_;
                                    local_138 = select(_e526, _e524, _e528);
                                    let _e530 = local_10;
                                    let _e532 = (_e530 >> bitcast<u32>(22i));
                                    let _e535 = ((_e532 >> bitcast<u32>(5u)) & 31u);
                                    local_27 = _e535;
                                    local_28 = (_e532 & 31u);
                                    if (_e535 == 0u) {
                                        let _e538 = local_28;
                                        phi_466_ = (f32(_e538) * 0.0000019073486f);
                                        phi_467_ = f32();
                                        phi_468_ = true;
                                    } else {
                                        let _e541 = local_27;
                                        let _e542 = (_e541 == 31u);
                                        if _e542 {
                                            let _e543 = local_28;
                                            phi_464_ = bitcast<f32>((2139095040u | (_e543 << bitcast<u32>(18u))));
                                            phi_465_ = f32();
                                        } else {
                                            let _e548 = local_27;
                                            let _e552 = local_28;
                                            phi_464_ = f32();
                                            phi_465_ = bitcast<f32>((((_e548 + 112u) << bitcast<u32>(23i)) | (_e552 << bitcast<u32>(18u))));
                                        }
                                        let _e558 = phi_464_;
                                        let _e560 = phi_465_;
                                        phi_466_ = _e558;
                                        phi_467_ = _e560;
                                        phi_468_ = _e542;
                                    }
                                    let _e562 = phi_466_;
                                    let _e564 = phi_467_;
                                    let _e566 = phi_468_;
                                    let _e568 = local_137;
                                    let _e569 = local_138;
                                    phi_485_ = array<f32, 4>(_e568, _e569, select(_e564, _e562, _e566), 1f);
                                } else {
                                    let _e571 = local_133;
                                    if (_e571 == 4u) {
                                        let _e573 = local_10;
                                        phi_484_ = array<f32, 4>((f32((_e573 & 16777215u)) * 0.00000005960465f), 0f, 0f, 1f);
                                    } else {
                                        let _e578 = local_10;
                                        phi_484_ = array<f32, 4>(bitcast<f32>(_e578), 0f, 0f, 1f);
                                    }
                                    let _e582 = phi_484_;
                                    phi_485_ = _e582;
                                }
                                let _e584 = phi_485_;
                                phi_486_ = _e584;
                            }
                            let _e586 = phi_486_;
                            phi_487_ = _e586;
                        }
                        let _e588 = phi_487_;
                        local_29 = _e588[0];
                        let _e593 = global_5.member.member.member_3;
                        local_30 = _e593;
                        if (_e593 == 0u) {
                            phi_572_ = _e588[0];
                        } else {
                            let _e595 = local_29;
                            if (_e595 >= 0f) {
                                let _e597 = local_29;
                                let _e598 = (_e597 <= 1f);
                                local_31 = _e598;
                                if _e598 {
                                    let _e602 = global_5.member.member.member_5;
                                    local_32 = _e602;
                                    let _e603 = local_152;
                                    local_33 = (_e602 == _e603);
                                    let _e605 = local_30;
                                    if (_e605 == 1u) {
                                        let _e607 = local_33;
                                        if _e607 {
                                            let _e611 = global_5.member.member.member_4;
                                            let _e612 = local_29;
                                            phi_533_ = (1f - _e612);
                                            phi_534_ = _e611;
                                        } else {
                                            let _e617 = global_5.member.member.member_4;
                                            let _e618 = local_32;
                                            let _e620 = local_32;
                                            let _e622 = local_29;
                                            let _e624 = local_32;
                                            phi_533_ = (_e624 - (_e622 * (_e620 - _e617)));
                                            phi_534_ = (_e617 * _e618);
                                        }
                                        let _e627 = phi_533_;
                                        let _e629 = phi_534_;
                                        phi_556_ = _e627;
                                        phi_557_ = _e629;
                                    } else {
                                        let _e630 = local_33;
                                        if _e630 {
                                            let _e634 = global_5.member.member.member_4;
                                            phi_554_ = _e588[0];
                                            phi_555_ = _e634;
                                        } else {
                                            let _e638 = global_5.member.member.member_4;
                                            let _e639 = local_32;
                                            let _e641 = local_32;
                                            let _e643 = local_29;
                                            phi_554_ = (_e638 + (_e643 * (_e641 - _e638)));
                                            phi_555_ = (_e638 * _e639);
                                        }
                                        let _e647 = phi_554_;
                                        let _e649 = phi_555_;
                                        phi_556_ = _e647;
                                        phi_557_ = _e649;
                                    }
                                    let _e651 = phi_556_;
                                    let _e653 = phi_557_;
                                    local_34 = _e651;
                                    local_35 = _e653;
                                    if (_e651 <= 0f) {
                                        phi_563_ = _e210;
                                    } else {
                                        let _e655 = local_35;
                                        let _e656 = local_34;
                                        phi_563_ = (_e655 / _e656);
                                    }
                                    let _e659 = phi_563_;
                                    phi_564_ = _e659;
                                } else {
                                    phi_564_ = f32();
                                }
                                let _e661 = phi_564_;
                                let _e662 = local_31;
                                phi_566_ = _e661;
                                phi_567_ = select(true, false, _e662);
                            } else {
                                phi_566_ = f32();
                                phi_567_ = true;
                            }
                            let _e665 = phi_566_;
                            let _e667 = phi_567_;
                            let _e668 = local_151;
                            phi_572_ = select(_e665, _e668, _e667);
                        }
                        let _e671 = phi_572_;
                        local_36 = _e671;
                        let _e672 = local_30;
                        if (_e672 == 2u) {
                            let _e674 = local_29;
                            phi_582_ = (_e674 > 0f);
                        } else {
                            let _e676 = local_29;
                            phi_582_ = (_e676 < 1f);
                        }
                        let _e679 = phi_582_;
                        if _e679 {
                            let _e680 = local_36;
                            let _e683 = ((bitcast<u32>(_e680) & 2139095040u) != 2139095040u);
                            local_37 = _e683;
                            let _e687 = global_5.member.member.member_2;
                            local_38 = _e687;
                            if (_e687 == 1u) {
                                phi_603_ = 2u;
                            } else {
                                let _e689 = local_38;
                                phi_603_ = select(0u, 1u, (_e689 == 2u));
                            }
                            let _e693 = phi_603_;
                            local_39 = _e693;
                            if (_e693 == 0u) {
                                let _e695 = local_9;
                                let _e696 = (4u * _e695);
                                local_40 = _e696;
                                let _e697 = local_1;
                                if (_e696 < _e697) {
                                } else {
                                    phi_1802_ = true;
                                    break;
                                }
                                let _e699 = local_40;
                                let _e702 = global_4.member[_e699];
                                local_41 = bitcast<f32>(_e702);
                                let _e704 = local_40;
                                let _e705 = (_e704 + 1u);
                                local_42 = _e705;
                                let _e706 = local_1;
                                if (_e705 < _e706) {
                                } else {
                                    phi_1802_ = true;
                                    break;
                                }
                                let _e708 = local_42;
                                let _e711 = global_4.member[_e708];
                                local_43 = bitcast<f32>(_e711);
                                let _e713 = local_40;
                                let _e714 = (_e713 + 2u);
                                local_44 = _e714;
                                let _e715 = local_1;
                                if (_e714 < _e715) {
                                } else {
                                    phi_1802_ = true;
                                    break;
                                }
                                let _e717 = local_44;
                                let _e720 = global_4.member[_e717];
                                local_45 = bitcast<f32>(_e720);
                                let _e722 = local_40;
                                let _e723 = (_e722 + 3u);
                                local_46 = _e723;
                                let _e724 = local_1;
                                if (_e723 < _e724) {
                                } else {
                                    phi_1802_ = true;
                                    break;
                                }
                                let _e726 = local_46;
                                let _e729 = global_4.member[_e726];
                                let _e731 = local_41;
                                let _e732 = local_43;
                                let _e733 = local_45;
                                phi_1073_ = array<f32, 4>(_e731, _e732, _e733, bitcast<f32>(_e729));
                            } else {
                                let _e735 = local_39;
                                if (_e735 == 1u) {
                                    let _e737 = local_9;
                                    let _e738 = (2u * _e737);
                                    local_47 = _e738;
                                    let _e739 = local_1;
                                    if (_e738 < _e739) {
                                    } else {
                                        phi_1802_ = true;
                                        break;
                                    }
                                    let _e741 = local_47;
                                    let _e744 = global_4.member[_e741];
                                    local_48 = _e744;
                                    let _e745 = local_47;
                                    let _e746 = (_e745 + 1u);
                                    local_49 = _e746;
                                    let _e747 = local_1;
                                    if (_e746 < _e747) {
                                    } else {
                                        phi_1802_ = true;
                                        break;
                                    }
                                    let _e749 = local_49;
                                    let _e752 = global_4.member[_e749];
                                    local_50 = _e752;
                                    let _e753 = local_48;
                                    let _e754 = (_e753 & 65535u);
                                    local_51 = ((_e754 & 32768u) << bitcast<u32>(16i));
                                    let _e760 = ((_e754 >> bitcast<u32>(10i)) & 31u);
                                    local_52 = _e760;
                                    local_53 = (_e754 & 1023u);
                                    if (_e760 == 0u) {
                                        let _e763 = local_53;
                                        let _e764 = f32(_e763);
                                        local_54 = _e764;
                                        let _e766 = local_51;
                                        if (_e766 == 0u) {
                                            phi_735_ = (_e764 * 0.000000059604645f);
                                        } else {
                                            let _e768 = local_54;
                                            phi_735_ = (_e768 * -0.000000059604645f);
                                        }
                                        let _e771 = phi_735_;
                                        phi_752_ = _e771;
                                        phi_753_ = f32();
                                        phi_754_ = true;
                                    } else {
                                        let _e772 = local_52;
                                        let _e773 = (_e772 == 31u);
                                        if _e773 {
                                            let _e774 = local_51;
                                            let _e776 = local_53;
                                            phi_750_ = bitcast<f32>(((_e774 | 2139095040u) | (_e776 << bitcast<u32>(13i))));
                                            phi_751_ = f32();
                                        } else {
                                            let _e781 = local_52;
                                            let _e785 = local_51;
                                            let _e787 = local_53;
                                            phi_750_ = f32();
                                            phi_751_ = bitcast<f32>(((_e785 | ((_e781 + 112u) << bitcast<u32>(23i))) | (_e787 << bitcast<u32>(13i))));
                                        }
                                        let _e793 = phi_750_;
                                        let _e795 = phi_751_;
                                        phi_752_ = _e793;
                                        phi_753_ = _e795;
                                        phi_754_ = _e773;
                                    }
                                    let _e797 = phi_752_;
                                    let _e799 = phi_753_;
                                    let _e801 = phi_754_;
                                    local_139 = select(_e799, _e797, _e801);
                                    let _e803 = local_48;
                                    let _e805 = (_e803 >> bitcast<u32>(16i));
                                    local_55 = ((_e805 & 32768u) << bitcast<u32>(16i));
                                    let _e811 = ((_e805 >> bitcast<u32>(10i)) & 31u);
                                    local_56 = _e811;
                                    local_57 = (_e805 & 1023u);
                                    if (_e811 == 0u) {
                                        let _e814 = local_57;
                                        let _e815 = f32(_e814);
                                        local_58 = _e815;
                                        let _e817 = local_55;
                                        if (_e817 == 0u) {
                                            phi_776_ = (_e815 * 0.000000059604645f);
                                        } else {
                                            let _e819 = local_58;
                                            phi_776_ = (_e819 * -0.000000059604645f);
                                        }
                                        let _e822 = phi_776_;
                                        phi_793_ = _e822;
                                        phi_794_ = f32();
                                        phi_795_ = true;
                                    } else {
                                        let _e823 = local_56;
                                        let _e824 = (_e823 == 31u);
                                        if _e824 {
                                            let _e825 = local_55;
                                            let _e827 = local_57;
                                            phi_791_ = bitcast<f32>(((_e825 | 2139095040u) | (_e827 << bitcast<u32>(13i))));
                                            phi_792_ = f32();
                                        } else {
                                            let _e832 = local_56;
                                            let _e836 = local_55;
                                            let _e838 = local_57;
                                            phi_791_ = f32();
                                            phi_792_ = bitcast<f32>(((_e836 | ((_e832 + 112u) << bitcast<u32>(23i))) | (_e838 << bitcast<u32>(13i))));
                                        }
                                        let _e844 = phi_791_;
                                        let _e846 = phi_792_;
                                        phi_793_ = _e844;
                                        phi_794_ = _e846;
                                        phi_795_ = _e824;
                                    }
                                    let _e848 = phi_793_;
                                    let _e850 = phi_794_;
                                    let _e852 = phi_795_;
                                    local_140 = select(_e850, _e848, _e852);
                                    let _e854 = local_50;
                                    let _e855 = (_e854 & 65535u);
                                    local_59 = ((_e855 & 32768u) << bitcast<u32>(16i));
                                    let _e861 = ((_e855 >> bitcast<u32>(10i)) & 31u);
                                    local_60 = _e861;
                                    local_61 = (_e855 & 1023u);
                                    if (_e861 == 0u) {
                                        let _e864 = local_61;
                                        let _e865 = f32(_e864);
                                        local_62 = _e865;
                                        let _e867 = local_59;
                                        if (_e867 == 0u) {
                                            phi_817_ = (_e865 * 0.000000059604645f);
                                        } else {
                                            let _e869 = local_62;
                                            phi_817_ = (_e869 * -0.000000059604645f);
                                        }
                                        let _e872 = phi_817_;
                                        phi_834_ = _e872;
                                        phi_835_ = f32();
                                        phi_836_ = true;
                                    } else {
                                        let _e873 = local_60;
                                        let _e874 = (_e873 == 31u);
                                        if _e874 {
                                            let _e875 = local_59;
                                            let _e877 = local_61;
                                            phi_832_ = bitcast<f32>(((_e875 | 2139095040u) | (_e877 << bitcast<u32>(13i))));
                                            phi_833_ = f32();
                                        } else {
                                            let _e882 = local_60;
                                            let _e886 = local_59;
                                            let _e888 = local_61;
                                            phi_832_ = f32();
                                            phi_833_ = bitcast<f32>(((_e886 | ((_e882 + 112u) << bitcast<u32>(23i))) | (_e888 << bitcast<u32>(13i))));
                                        }
                                        let _e894 = phi_832_;
                                        let _e896 = phi_833_;
                                        phi_834_ = _e894;
                                        phi_835_ = _e896;
                                        phi_836_ = _e874;
                                    }
                                    let _e898 = phi_834_;
                                    let _e900 = phi_835_;
                                    let _e902 = phi_836_;
                                    local_141 = select(_e900, _e898, _e902);
                                    let _e904 = local_50;
                                    let _e906 = (_e904 >> bitcast<u32>(16i));
                                    local_63 = ((_e906 & 32768u) << bitcast<u32>(16i));
                                    let _e912 = ((_e906 >> bitcast<u32>(10i)) & 31u);
                                    local_64 = _e912;
                                    local_65 = (_e906 & 1023u);
                                    if (_e912 == 0u) {
                                        let _e915 = local_65;
                                        let _e916 = f32(_e915);
                                        local_66 = _e916;
                                        let _e918 = local_63;
                                        if (_e918 == 0u) {
                                            phi_858_ = (_e916 * 0.000000059604645f);
                                        } else {
                                            let _e920 = local_66;
                                            phi_858_ = (_e920 * -0.000000059604645f);
                                        }
                                        let _e923 = phi_858_;
                                        phi_875_ = _e923;
                                        phi_876_ = f32();
                                        phi_877_ = true;
                                    } else {
                                        let _e924 = local_64;
                                        let _e925 = (_e924 == 31u);
                                        if _e925 {
                                            let _e926 = local_63;
                                            let _e928 = local_65;
                                            phi_873_ = bitcast<f32>(((_e926 | 2139095040u) | (_e928 << bitcast<u32>(13i))));
                                            phi_874_ = f32();
                                        } else {
                                            let _e933 = local_64;
                                            let _e937 = local_63;
                                            let _e939 = local_65;
                                            phi_873_ = f32();
                                            phi_874_ = bitcast<f32>(((_e937 | ((_e933 + 112u) << bitcast<u32>(23i))) | (_e939 << bitcast<u32>(13i))));
                                        }
                                        let _e945 = phi_873_;
                                        let _e947 = phi_874_;
                                        phi_875_ = _e945;
                                        phi_876_ = _e947;
                                        phi_877_ = _e925;
                                    }
                                    let _e949 = phi_875_;
                                    let _e951 = phi_876_;
                                    let _e953 = phi_877_;
                                    let _e955 = local_139;
                                    let _e956 = local_140;
                                    let _e957 = local_141;
                                    phi_1072_ = array<f32, 4>(_e955, _e956, _e957, select(_e951, _e949, _e953));
                                } else {
                                    let _e959 = local_39;
                                    if (_e959 == 2u) {
                                        let _e961 = local_9;
                                        let _e962 = local_1;
                                        if (_e961 < _e962) {
                                        } else {
                                            phi_1802_ = true;
                                            break;
                                        }
                                        let _e964 = local_9;
                                        let _e967 = global_4.member[_e964];
                                        local_67 = _e967;
                                        let _e968 = (_e967 & 2047u);
                                        let _e971 = ((_e968 >> bitcast<u32>(6u)) & 31u);
                                        local_68 = _e971;
                                        local_69 = (_e968 & 63u);
                                        if (_e971 == 0u) {
                                            let _e974 = local_69;
                                            phi_937_ = (f32(_e974) * 0.0000009536743f);
                                            phi_938_ = f32();
                                            phi_939_ = true;
                                        } else {
                                            let _e977 = local_68;
                                            let _e978 = (_e977 == 31u);
                                            if _e978 {
                                                let _e979 = local_69;
                                                phi_935_ = bitcast<f32>((2139095040u | (_e979 << bitcast<u32>(17u))));
                                                phi_936_ = f32();
                                            } else {
                                                let _e984 = local_68;
                                                let _e988 = local_69;
                                                phi_935_ = f32();
                                                phi_936_ = bitcast<f32>((((_e984 + 112u) << bitcast<u32>(23i)) | (_e988 << bitcast<u32>(17u))));
                                            }
                                            let _e994 = phi_935_;
                                            let _e996 = phi_936_;
                                            phi_937_ = _e994;
                                            phi_938_ = _e996;
                                            phi_939_ = _e978;
                                        }
                                        let _e998 = phi_937_;
                                        let _e1000 = phi_938_;
                                        let _e1002 = phi_939_;
                                        local_142 = select(_e1000, _e998, _e1002);
                                        let _e1004 = local_67;
                                        let _e1007 = ((_e1004 >> bitcast<u32>(11i)) & 2047u);
                                        let _e1010 = ((_e1007 >> bitcast<u32>(6u)) & 31u);
                                        local_70 = _e1010;
                                        local_71 = (_e1007 & 63u);
                                        if (_e1010 == 0u) {
                                            let _e1013 = local_71;
                                            phi_980_ = (f32(_e1013) * 0.0000009536743f);
                                            phi_981_ = f32();
                                            phi_982_ = true;
                                        } else {
                                            let _e1016 = local_70;
                                            let _e1017 = (_e1016 == 31u);
                                            if _e1017 {
                                                let _e1018 = local_71;
                                                phi_978_ = bitcast<f32>((2139095040u | (_e1018 << bitcast<u32>(17u))));
                                                phi_979_ = f32();
                                            } else {
                                                let _e1023 = local_70;
                                                let _e1027 = local_71;
                                                phi_978_ = f32();
                                                phi_979_ = bitcast<f32>((((_e1023 + 112u) << bitcast<u32>(23i)) | (_e1027 << bitcast<u32>(17u))));
                                            }
                                            let _e1033 = phi_978_;
                                            let _e1035 = phi_979_;
                                            phi_980_ = _e1033;
                                            phi_981_ = _e1035;
                                            phi_982_ = _e1017;
                                        }
                                        let _e1037 = phi_980_;
                                        let _e1039 = phi_981_;
                                        let _e1041 = phi_982_;
                                        local_143 = select(_e1039, _e1037, _e1041);
                                        let _e1043 = local_67;
                                        let _e1045 = (_e1043 >> bitcast<u32>(22i));
                                        let _e1048 = ((_e1045 >> bitcast<u32>(5u)) & 31u);
                                        local_72 = _e1048;
                                        local_73 = (_e1045 & 31u);
                                        if (_e1048 == 0u) {
                                            let _e1051 = local_73;
                                            phi_1022_ = (f32(_e1051) * 0.0000019073486f);
                                            phi_1023_ = f32();
                                            phi_1024_ = true;
                                        } else {
                                            let _e1054 = local_72;
                                            let _e1055 = (_e1054 == 31u);
                                            if _e1055 {
                                                let _e1056 = local_73;
                                                phi_1020_ = bitcast<f32>((2139095040u | (_e1056 << bitcast<u32>(18u))));
                                                phi_1021_ = f32();
                                            } else {
                                                let _e1061 = local_72;
                                                let _e1065 = local_73;
                                                phi_1020_ = f32();
                                                phi_1021_ = bitcast<f32>((((_e1061 + 112u) << bitcast<u32>(23i)) | (_e1065 << bitcast<u32>(18u))));
                                            }
                                            let _e1071 = phi_1020_;
                                            let _e1073 = phi_1021_;
                                            phi_1022_ = _e1071;
                                            phi_1023_ = _e1073;
                                            phi_1024_ = _e1055;
                                        }
                                        let _e1075 = phi_1022_;
                                        let _e1077 = phi_1023_;
                                        let _e1079 = phi_1024_;
                                        let _e1081 = local_142;
                                        let _e1082 = local_143;
                                        phi_1071_ = array<f32, 4>(_e1081, _e1082, select(_e1077, _e1075, _e1079), 1f);
                                    } else {
                                        let _e1084 = local_39;
                                        if (_e1084 == 4u) {
                                            let _e1086 = local_9;
                                            let _e1087 = local_1;
                                            if (_e1086 < _e1087) {
                                            } else {
                                                phi_1802_ = true;
                                                break;
                                            }
                                            let _e1089 = local_9;
                                            let _e1092 = global_4.member[_e1089];
                                            phi_1070_ = array<f32, 4>((f32((_e1092 & 16777215u)) * 0.00000005960465f), 0f, 0f, 1f);
                                        } else {
                                            let _e1097 = local_9;
                                            let _e1098 = local_1;
                                            if (_e1097 < _e1098) {
                                            } else {
                                                phi_1802_ = true;
                                                break;
                                            }
                                            let _e1100 = local_9;
                                            let _e1103 = global_4.member[_e1100];
                                            phi_1070_ = array<f32, 4>(bitcast<f32>(_e1103), 0f, 0f, 1f);
                                        }
                                        let _e1107 = phi_1070_;
                                        phi_1071_ = _e1107;
                                    }
                                    let _e1109 = phi_1071_;
                                    phi_1072_ = _e1109;
                                }
                                let _e1111 = phi_1072_;
                                phi_1073_ = _e1111;
                            }
                            let _e1113 = phi_1073_;
                            local_74 = _e1113;
                            let _e1114 = local_37;
                            if _e1114 {
                                let _e1115 = local_74;
                                let _e1117 = local_74;
                                let _e1119 = local_74;
                                let _e1122 = local_74;
                                phi_1082_ = array<f32, 3>(_e1115[0], _e1117[1], _e1119[2]);
                                phi_1083_ = _e1122[3];
                            } else {
                                phi_1082_ = array<f32, 3>();
                                phi_1083_ = f32();
                            }
                            let _e1125 = phi_1082_;
                            let _e1127 = phi_1083_;
                            let _e1128 = local_37;
                            phi_1570_ = _e1125;
                            phi_1571_ = _e1127;
                            phi_1572_ = _e683;
                            phi_1573_ = _e1113;
                            phi_1574_ = _e683;
                            phi_1575_ = select(true, false, _e1128);
                        } else {
                            let _e1133 = global_5.member.member.member_2;
                            local_75 = _e1133;
                            if (_e1133 == 1u) {
                                phi_1099_ = 2u;
                            } else {
                                let _e1135 = local_75;
                                phi_1099_ = select(0u, 1u, (_e1135 == 2u));
                            }
                            let _e1139 = phi_1099_;
                            local_76 = _e1139;
                            if (_e1139 == 0u) {
                                let _e1141 = local_9;
                                let _e1142 = (4u * _e1141);
                                local_77 = _e1142;
                                let _e1143 = local_1;
                                if (_e1142 < _e1143) {
                                } else {
                                    phi_1802_ = true;
                                    break;
                                }
                                let _e1145 = local_77;
                                let _e1148 = global_4.member[_e1145];
                                local_78 = bitcast<f32>(_e1148);
                                let _e1150 = local_77;
                                let _e1151 = (_e1150 + 1u);
                                local_79 = _e1151;
                                let _e1152 = local_1;
                                if (_e1151 < _e1152) {
                                } else {
                                    phi_1802_ = true;
                                    break;
                                }
                                let _e1154 = local_79;
                                let _e1157 = global_4.member[_e1154];
                                local_80 = bitcast<f32>(_e1157);
                                let _e1159 = local_77;
                                let _e1160 = (_e1159 + 2u);
                                local_81 = _e1160;
                                let _e1161 = local_1;
                                if (_e1160 < _e1161) {
                                } else {
                                    phi_1802_ = true;
                                    break;
                                }
                                let _e1163 = local_81;
                                let _e1166 = global_4.member[_e1163];
                                local_82 = bitcast<f32>(_e1166);
                                let _e1168 = local_77;
                                let _e1169 = (_e1168 + 3u);
                                local_83 = _e1169;
                                let _e1170 = local_1;
                                if (_e1169 < _e1170) {
                                } else {
                                    phi_1802_ = true;
                                    break;
                                }
                                let _e1172 = local_83;
                                let _e1175 = global_4.member[_e1172];
                                let _e1177 = local_78;
                                let _e1178 = local_80;
                                let _e1179 = local_82;
                                phi_1569_ = array<f32, 4>(_e1177, _e1178, _e1179, bitcast<f32>(_e1175));
                            } else {
                                let _e1181 = local_76;
                                if (_e1181 == 1u) {
                                    let _e1183 = local_9;
                                    let _e1184 = (2u * _e1183);
                                    local_84 = _e1184;
                                    let _e1185 = local_1;
                                    if (_e1184 < _e1185) {
                                    } else {
                                        phi_1802_ = true;
                                        break;
                                    }
                                    let _e1187 = local_84;
                                    let _e1190 = global_4.member[_e1187];
                                    local_85 = _e1190;
                                    let _e1191 = local_84;
                                    let _e1192 = (_e1191 + 1u);
                                    local_86 = _e1192;
                                    let _e1193 = local_1;
                                    if (_e1192 < _e1193) {
                                    } else {
                                        phi_1802_ = true;
                                        break;
                                    }
                                    let _e1195 = local_86;
                                    let _e1198 = global_4.member[_e1195];
                                    local_87 = _e1198;
                                    let _e1199 = local_85;
                                    let _e1200 = (_e1199 & 65535u);
                                    local_88 = ((_e1200 & 32768u) << bitcast<u32>(16i));
                                    let _e1206 = ((_e1200 >> bitcast<u32>(10i)) & 31u);
                                    local_89 = _e1206;
                                    local_90 = (_e1200 & 1023u);
                                    if (_e1206 == 0u) {
                                        let _e1209 = local_90;
                                        let _e1210 = f32(_e1209);
                                        local_91 = _e1210;
                                        let _e1212 = local_88;
                                        if (_e1212 == 0u) {
                                            phi_1231_ = (_e1210 * 0.000000059604645f);
                                        } else {
                                            let _e1214 = local_91;
                                            phi_1231_ = (_e1214 * -0.000000059604645f);
                                        }
                                        let _e1217 = phi_1231_;
                                        phi_1248_ = _e1217;
                                        phi_1249_ = f32();
                                        phi_1250_ = true;
                                    } else {
                                        let _e1218 = local_89;
                                        let _e1219 = (_e1218 == 31u);
                                        if _e1219 {
                                            let _e1220 = local_88;
                                            let _e1222 = local_90;
                                            phi_1246_ = bitcast<f32>(((_e1220 | 2139095040u) | (_e1222 << bitcast<u32>(13i))));
                                            phi_1247_ = f32();
                                        } else {
                                            let _e1227 = local_89;
                                            let _e1231 = local_88;
                                            let _e1233 = local_90;
                                            phi_1246_ = f32();
                                            phi_1247_ = bitcast<f32>(((_e1231 | ((_e1227 + 112u) << bitcast<u32>(23i))) | (_e1233 << bitcast<u32>(13i))));
                                        }
                                        let _e1239 = phi_1246_;
                                        let _e1241 = phi_1247_;
                                        phi_1248_ = _e1239;
                                        phi_1249_ = _e1241;
                                        phi_1250_ = _e1219;
                                    }
                                    let _e1243 = phi_1248_;
                                    let _e1245 = phi_1249_;
                                    let _e1247 = phi_1250_;
                                    local_144 = select(_e1245, _e1243, _e1247);
                                    let _e1249 = local_85;
                                    let _e1251 = (_e1249 >> bitcast<u32>(16i));
                                    local_92 = ((_e1251 & 32768u) << bitcast<u32>(16i));
                                    let _e1257 = ((_e1251 >> bitcast<u32>(10i)) & 31u);
                                    local_93 = _e1257;
                                    local_94 = (_e1251 & 1023u);
                                    if (_e1257 == 0u) {
                                        let _e1260 = local_94;
                                        let _e1261 = f32(_e1260);
                                        local_95 = _e1261;
                                        let _e1263 = local_92;
                                        if (_e1263 == 0u) {
                                            phi_1272_ = (_e1261 * 0.000000059604645f);
                                        } else {
                                            let _e1265 = local_95;
                                            phi_1272_ = (_e1265 * -0.000000059604645f);
                                        }
                                        let _e1268 = phi_1272_;
                                        phi_1289_ = _e1268;
                                        phi_1290_ = f32();
                                        phi_1291_ = true;
                                    } else {
                                        let _e1269 = local_93;
                                        let _e1270 = (_e1269 == 31u);
                                        if _e1270 {
                                            let _e1271 = local_92;
                                            let _e1273 = local_94;
                                            phi_1287_ = bitcast<f32>(((_e1271 | 2139095040u) | (_e1273 << bitcast<u32>(13i))));
                                            phi_1288_ = f32();
                                        } else {
                                            let _e1278 = local_93;
                                            let _e1282 = local_92;
                                            let _e1284 = local_94;
                                            phi_1287_ = f32();
                                            phi_1288_ = bitcast<f32>(((_e1282 | ((_e1278 + 112u) << bitcast<u32>(23i))) | (_e1284 << bitcast<u32>(13i))));
                                        }
                                        let _e1290 = phi_1287_;
                                        let _e1292 = phi_1288_;
                                        phi_1289_ = _e1290;
                                        phi_1290_ = _e1292;
                                        phi_1291_ = _e1270;
                                    }
                                    let _e1294 = phi_1289_;
                                    let _e1296 = phi_1290_;
                                    let _e1298 = phi_1291_;
                                    local_145 = select(_e1296, _e1294, _e1298);
                                    let _e1300 = local_87;
                                    let _e1301 = (_e1300 & 65535u);
                                    local_96 = ((_e1301 & 32768u) << bitcast<u32>(16i));
                                    let _e1307 = ((_e1301 >> bitcast<u32>(10i)) & 31u);
                                    local_97 = _e1307;
                                    local_98 = (_e1301 & 1023u);
                                    if (_e1307 == 0u) {
                                        let _e1310 = local_98;
                                        let _e1311 = f32(_e1310);
                                        local_99 = _e1311;
                                        let _e1313 = local_96;
                                        if (_e1313 == 0u) {
                                            phi_1313_ = (_e1311 * 0.000000059604645f);
                                        } else {
                                            let _e1315 = local_99;
                                            phi_1313_ = (_e1315 * -0.000000059604645f);
                                        }
                                        let _e1318 = phi_1313_;
                                        phi_1330_ = _e1318;
                                        phi_1331_ = f32();
                                        phi_1332_ = true;
                                    } else {
                                        let _e1319 = local_97;
                                        let _e1320 = (_e1319 == 31u);
                                        if _e1320 {
                                            let _e1321 = local_96;
                                            let _e1323 = local_98;
                                            phi_1328_ = bitcast<f32>(((_e1321 | 2139095040u) | (_e1323 << bitcast<u32>(13i))));
                                            phi_1329_ = f32();
                                        } else {
                                            let _e1328 = local_97;
                                            let _e1332 = local_96;
                                            let _e1334 = local_98;
                                            phi_1328_ = f32();
                                            phi_1329_ = bitcast<f32>(((_e1332 | ((_e1328 + 112u) << bitcast<u32>(23i))) | (_e1334 << bitcast<u32>(13i))));
                                        }
                                        let _e1340 = phi_1328_;
                                        let _e1342 = phi_1329_;
                                        phi_1330_ = _e1340;
                                        phi_1331_ = _e1342;
                                        phi_1332_ = _e1320;
                                    }
                                    let _e1344 = phi_1330_;
                                    let _e1346 = phi_1331_;
                                    let _e1348 = phi_1332_;
                                    local_146 = select(_e1346, _e1344, _e1348);
                                    let _e1350 = local_87;
                                    let _e1352 = (_e1350 >> bitcast<u32>(16i));
                                    local_100 = ((_e1352 & 32768u) << bitcast<u32>(16i));
                                    let _e1358 = ((_e1352 >> bitcast<u32>(10i)) & 31u);
                                    local_101 = _e1358;
                                    local_102 = (_e1352 & 1023u);
                                    if (_e1358 == 0u) {
                                        let _e1361 = local_102;
                                        let _e1362 = f32(_e1361);
                                        local_103 = _e1362;
                                        let _e1364 = local_100;
                                        if (_e1364 == 0u) {
                                            phi_1354_ = (_e1362 * 0.000000059604645f);
                                        } else {
                                            let _e1366 = local_103;
                                            phi_1354_ = (_e1366 * -0.000000059604645f);
                                        }
                                        let _e1369 = phi_1354_;
                                        phi_1371_ = _e1369;
                                        phi_1372_ = f32();
                                        phi_1373_ = true;
                                    } else {
                                        let _e1370 = local_101;
                                        let _e1371 = (_e1370 == 31u);
                                        if _e1371 {
                                            let _e1372 = local_100;
                                            let _e1374 = local_102;
                                            phi_1369_ = bitcast<f32>(((_e1372 | 2139095040u) | (_e1374 << bitcast<u32>(13i))));
                                            phi_1370_ = f32();
                                        } else {
                                            let _e1379 = local_101;
                                            let _e1383 = local_100;
                                            let _e1385 = local_102;
                                            phi_1369_ = f32();
                                            phi_1370_ = bitcast<f32>(((_e1383 | ((_e1379 + 112u) << bitcast<u32>(23i))) | (_e1385 << bitcast<u32>(13i))));
                                        }
                                        let _e1391 = phi_1369_;
                                        let _e1393 = phi_1370_;
                                        phi_1371_ = _e1391;
                                        phi_1372_ = _e1393;
                                        phi_1373_ = _e1371;
                                    }
                                    let _e1395 = phi_1371_;
                                    let _e1397 = phi_1372_;
                                    let _e1399 = phi_1373_;
                                    let _e1401 = local_144;
                                    let _e1402 = local_145;
                                    let _e1403 = local_146;
                                    phi_1568_ = array<f32, 4>(_e1401, _e1402, _e1403, select(_e1397, _e1395, _e1399));
                                } else {
                                    let _e1405 = local_76;
                                    if (_e1405 == 2u) {
                                        let _e1407 = local_9;
                                        let _e1408 = local_1;
                                        if (_e1407 < _e1408) {
                                        } else {
                                            phi_1802_ = true;
                                            break;
                                        }
                                        let _e1410 = local_9;
                                        let _e1413 = global_4.member[_e1410];
                                        local_104 = _e1413;
                                        let _e1414 = (_e1413 & 2047u);
                                        let _e1417 = ((_e1414 >> bitcast<u32>(6u)) & 31u);
                                        local_105 = _e1417;
                                        local_106 = (_e1414 & 63u);
                                        if (_e1417 == 0u) {
                                            let _e1420 = local_106;
                                            phi_1433_ = (f32(_e1420) * 0.0000009536743f);
                                            phi_1434_ = f32();
                                            phi_1435_ = true;
                                        } else {
                                            let _e1423 = local_105;
                                            let _e1424 = (_e1423 == 31u);
                                            if _e1424 {
                                                let _e1425 = local_106;
                                                phi_1431_ = bitcast<f32>((2139095040u | (_e1425 << bitcast<u32>(17u))));
                                                phi_1432_ = f32();
                                            } else {
                                                let _e1430 = local_105;
                                                let _e1434 = local_106;
                                                phi_1431_ = f32();
                                                phi_1432_ = bitcast<f32>((((_e1430 + 112u) << bitcast<u32>(23i)) | (_e1434 << bitcast<u32>(17u))));
                                            }
                                            let _e1440 = phi_1431_;
                                            let _e1442 = phi_1432_;
                                            phi_1433_ = _e1440;
                                            phi_1434_ = _e1442;
                                            phi_1435_ = _e1424;
                                        }
                                        let _e1444 = phi_1433_;
                                        let _e1446 = phi_1434_;
                                        let _e1448 = phi_1435_;
                                        local_147 = select(_e1446, _e1444, _e1448);
                                        let _e1450 = local_104;
                                        let _e1453 = ((_e1450 >> bitcast<u32>(11i)) & 2047u);
                                        let _e1456 = ((_e1453 >> bitcast<u32>(6u)) & 31u);
                                        local_107 = _e1456;
                                        local_108 = (_e1453 & 63u);
                                        if (_e1456 == 0u) {
                                            let _e1459 = local_108;
                                            phi_1476_ = (f32(_e1459) * 0.0000009536743f);
                                            phi_1477_ = f32();
                                            phi_1478_ = true;
                                        } else {
                                            let _e1462 = local_107;
                                            let _e1463 = (_e1462 == 31u);
                                            if _e1463 {
                                                let _e1464 = local_108;
                                                phi_1474_ = bitcast<f32>((2139095040u | (_e1464 << bitcast<u32>(17u))));
                                                phi_1475_ = f32();
                                            } else {
                                                let _e1469 = local_107;
                                                let _e1473 = local_108;
                                                phi_1474_ = f32();
                                                phi_1475_ = bitcast<f32>((((_e1469 + 112u) << bitcast<u32>(23i)) | (_e1473 << bitcast<u32>(17u))));
                                            }
                                            let _e1479 = phi_1474_;
                                            let _e1481 = phi_1475_;
                                            phi_1476_ = _e1479;
                                            phi_1477_ = _e1481;
                                            phi_1478_ = _e1463;
                                        }
                                        let _e1483 = phi_1476_;
                                        let _e1485 = phi_1477_;
                                        let _e1487 = phi_1478_;
                                        local_148 = select(_e1485, _e1483, _e1487);
                                        let _e1489 = local_104;
                                        let _e1491 = (_e1489 >> bitcast<u32>(22i));
                                        let _e1494 = ((_e1491 >> bitcast<u32>(5u)) & 31u);
                                        local_109 = _e1494;
                                        local_110 = (_e1491 & 31u);
                                        if (_e1494 == 0u) {
                                            let _e1497 = local_110;
                                            phi_1518_ = (f32(_e1497) * 0.0000019073486f);
                                            phi_1519_ = f32();
                                            phi_1520_ = true;
                                        } else {
                                            let _e1500 = local_109;
                                            let _e1501 = (_e1500 == 31u);
                                            if _e1501 {
                                                let _e1502 = local_110;
                                                phi_1516_ = bitcast<f32>((2139095040u | (_e1502 << bitcast<u32>(18u))));
                                                phi_1517_ = f32();
                                            } else {
                                                let _e1507 = local_109;
                                                let _e1511 = local_110;
                                                phi_1516_ = f32();
                                                phi_1517_ = bitcast<f32>((((_e1507 + 112u) << bitcast<u32>(23i)) | (_e1511 << bitcast<u32>(18u))));
                                            }
                                            let _e1517 = phi_1516_;
                                            let _e1519 = phi_1517_;
                                            phi_1518_ = _e1517;
                                            phi_1519_ = _e1519;
                                            phi_1520_ = _e1501;
                                        }
                                        let _e1521 = phi_1518_;
                                        let _e1523 = phi_1519_;
                                        let _e1525 = phi_1520_;
                                        let _e1527 = local_147;
                                        let _e1528 = local_148;
                                        phi_1567_ = array<f32, 4>(_e1527, _e1528, select(_e1523, _e1521, _e1525), 1f);
                                    } else {
                                        let _e1530 = local_76;
                                        if (_e1530 == 4u) {
                                            let _e1532 = local_9;
                                            let _e1533 = local_1;
                                            if (_e1532 < _e1533) {
                                            } else {
                                                phi_1802_ = true;
                                                break;
                                            }
                                            let _e1535 = local_9;
                                            let _e1538 = global_4.member[_e1535];
                                            phi_1566_ = array<f32, 4>((f32((_e1538 & 16777215u)) * 0.00000005960465f), 0f, 0f, 1f);
                                        } else {
                                            let _e1543 = local_9;
                                            let _e1544 = local_1;
                                            if (_e1543 < _e1544) {
                                            } else {
                                                phi_1802_ = true;
                                                break;
                                            }
                                            let _e1546 = local_9;
                                            let _e1549 = global_4.member[_e1546];
                                            phi_1566_ = array<f32, 4>(bitcast<f32>(_e1549), 0f, 0f, 1f);
                                        }
                                        let _e1553 = phi_1566_;
                                        phi_1567_ = _e1553;
                                    }
                                    let _e1555 = phi_1567_;
                                    phi_1568_ = _e1555;
                                }
                                let _e1557 = phi_1568_;
                                phi_1569_ = _e1557;
                            }
                            let _e1559 = phi_1569_;
                            phi_1570_ = array<f32, 3>();
                            phi_1571_ = f32();
                            phi_1572_ = bool();
                            phi_1573_ = _e1559;
                            phi_1574_ = false;
                            phi_1575_ = true;
                        }
                        let _e1561 = phi_1570_;
                        let _e1563 = phi_1571_;
                        let _e1565 = phi_1572_;
                        let _e1567 = phi_1573_;
                        let _e1569 = phi_1574_;
                        let _e1571 = phi_1575_;
                        local_111 = _e1565;
                        local_112 = _e1567;
                        local_113 = _e1569;
                        local_114 = _e1571;
                        if _e1571 {
                            let _e1572 = local_9;
                            let _e1573 = local_3;
                            if (_e1572 < _e1573) {
                            } else {
                                phi_1802_ = true;
                                break;
                            }
                            let _e1575 = local_9;
                            let _e1578 = global_6.member[_e1575];
                            let _e1582 = ((bitcast<u32>(bitcast<f32>(_e1578)) & 2139095040u) != 2139095040u);
                            local_115 = _e1582;
                            if _e1582 {
                                let _e1583 = local_112;
                                let _e1585 = local_112;
                                let _e1587 = local_112;
                                phi_1605_ = array<f32, 3>(_e1583[0], _e1585[1], _e1587[2]);
                            } else {
                                phi_1605_ = array<f32, 3>(0f, 0f, 0f);
                            }
                            let _e1591 = phi_1605_;
                            let _e1592 = local_115;
                            phi_1607_ = _e1591;
                            phi_1608_ = select(0f, 1f, _e1592);
                        } else {
                            phi_1607_ = _e1561;
                            phi_1608_ = _e1563;
                        }
                        let _e1595 = phi_1607_;
                        let _e1597 = phi_1608_;
                        local_116 = _e1595;
                        local_117 = _e1597;
                        let _e1598 = local_114;
                        let _e1599 = local_113;
                        let _e1600 = local_111;
                        local_149 = select(_e1600, _e1599, _e1598);
                        let _e1602 = local_114;
                        let _e1603 = local_152;
                        let _e1604 = local_36;
                        let _e1605 = select(_e1604, _e1603, _e1602);
                        local_150 = _e1605;
                        let _e1606 = local_9;
                        let _e1607 = (5u * _e1606);
                        local_118 = _e1607;
                        local_119 = bitcast<u32>(_e1595[0]);
                        let _e1610 = local_4;
                        if (_e1607 < _e1610) {
                        } else {
                            phi_1802_ = true;
                            break;
                        }
                        let _e1612 = local_118;
                        let _e1615 = local_119;
                        global_7.member[_e1612] = _e1615;
                        let _e1616 = local_118;
                        let _e1617 = (_e1616 + 1u);
                        local_120 = _e1617;
                        let _e1618 = local_116;
                        local_121 = bitcast<u32>(_e1618[1]);
                        let _e1621 = local_4;
                        if (_e1617 < _e1621) {
                        } else {
                            phi_1802_ = true;
                            break;
                        }
                        let _e1623 = local_120;
                        let _e1626 = local_121;
                        global_7.member[_e1623] = _e1626;
                        let _e1627 = local_118;
                        let _e1628 = (_e1627 + 2u);
                        local_122 = _e1628;
                        let _e1629 = local_116;
                        local_123 = bitcast<u32>(_e1629[2]);
                        let _e1632 = local_4;
                        if (_e1628 < _e1632) {
                        } else {
                            phi_1802_ = true;
                            break;
                        }
                        let _e1634 = local_122;
                        let _e1637 = local_123;
                        global_7.member[_e1634] = _e1637;
                        let _e1638 = local_118;
                        let _e1639 = (_e1638 + 3u);
                        local_124 = _e1639;
                        let _e1640 = local_117;
                        local_125 = bitcast<u32>(_e1640);
                        let _e1642 = local_4;
                        if (_e1639 < _e1642) {
                        } else {
                            phi_1802_ = true;
                            break;
                        }
                        let _e1644 = local_124;
                        let _e1647 = local_125;
                        global_7.member[_e1644] = _e1647;
                        let _e1648 = local_118;
                        let _e1649 = (_e1648 + 4u);
                        local_126 = _e1649;
                        let _e1650 = local_150;
                        local_127 = bitcast<u32>(_e1650);
                        let _e1652 = local_4;
                        if (_e1649 < _e1652) {
                        } else {
                            phi_1802_ = true;
                            break;
                        }
                        let _e1654 = local_126;
                        let _e1657 = local_127;
                        global_7.member[_e1654] = _e1657;
                        let _e1660 = global_5.member.member_2;
                        local_128 = _e1660;
                        let _e1661 = local_149;
                        if _e1661 {
                            let _e1662 = local_117;
                            if (_e1662 < 1f) {
                                phi_1770_ = _e1605;
                            } else {
                                let _e1664 = local_150;
                                let _e1665 = local_128;
                                local_129 = (_e1664 * _e1665);
                                let _e1667 = local_127;
                                if (_e1667 == 0u) {
                                    phi_1711_ = false;
                                } else {
                                    let _e1669 = local_127;
                                    phi_1711_ = (_e1669 <= 2139095040u);
                                }
                                let _e1672 = phi_1711_;
                                if _e1672 {
                                    let _e1673 = local_129;
                                    if (_e1673 >= 0f) {
                                        let _e1675 = local_129;
                                        let _e1678 = ((bitcast<u32>(_e1675) & 2147483647u) > 2139095040u);
                                        if _e1678 {
                                            phi_1742_ = f32();
                                            phi_1743_ = f32();
                                            phi_1744_ = false;
                                        } else {
                                            let _e1679 = local_129;
                                            let _e1680 = (_e1679 == 0f);
                                            local_130 = _e1680;
                                            if _e1680 {
                                                phi_1740_ = f32();
                                                phi_1741_ = true;
                                            } else {
                                                let _e1684 = global_5.member.member_1.member_1;
                                                local_131 = _e1684;
                                                let _e1685 = local_129;
                                                let _e1686 = (_e1685 >= _e1684);
                                                if _e1686 {
                                                    phi_1738_ = f32();
                                                } else {
                                                    let _e1687 = local_129;
                                                    let _e1688 = local_150;
                                                    let _e1690 = local_131;
                                                    let _e1691 = local_129;
                                                    phi_1738_ = ((_e1687 * _e1688) / (_e1690 - _e1691));
                                                }
                                                let _e1695 = phi_1738_;
                                                phi_1740_ = _e1695;
                                                phi_1741_ = _e1686;
                                            }
                                            let _e1697 = phi_1740_;
                                            let _e1699 = phi_1741_;
                                            let _e1700 = local_130;
                                            let _e1701 = local_152;
                                            phi_1742_ = select(_e1701, 0f, _e1700);
                                            phi_1743_ = _e1697;
                                            phi_1744_ = _e1699;
                                        }
                                        let _e1704 = phi_1742_;
                                        let _e1706 = phi_1743_;
                                        let _e1708 = phi_1744_;
                                        phi_1745_ = _e1704;
                                        phi_1746_ = _e1706;
                                        phi_1747_ = _e1678;
                                        phi_1748_ = _e1708;
                                    } else {
                                        phi_1745_ = f32();
                                        phi_1746_ = f32();
                                        phi_1747_ = true;
                                        phi_1748_ = false;
                                    }
                                    let _e1710 = phi_1745_;
                                    let _e1712 = phi_1746_;
                                    let _e1714 = phi_1747_;
                                    let _e1716 = phi_1748_;
                                    phi_1749_ = _e1710;
                                    phi_1750_ = _e1712;
                                    phi_1751_ = _e1714;
                                    phi_1752_ = _e1716;
                                } else {
                                    phi_1749_ = f32();
                                    phi_1750_ = f32();
                                    phi_1751_ = true;
                                    phi_1752_ = false;
                                }
                                let _e1718 = phi_1749_;
                                let _e1720 = phi_1750_;
                                let _e1722 = phi_1751_;
                                let _e1724 = phi_1752_;
                                let _e1725 = local_151;
                                let _e1729 = local_150;
                                let _e1730 = (_e1729 + select(_e1720, select(_e1718, _e1725, _e1722), select(_e1724, true, _e1722)));
                                let _e1734 = local_152;
                                phi_1770_ = select(_e1734, _e1730, ((bitcast<u32>(_e1730) & 2139095040u) != 2139095040u));
                            }
                            let _e1737 = phi_1770_;
                            phi_1771_ = _e1737;
                        } else {
                            phi_1771_ = _e210;
                        }
                        let _e1739 = phi_1771_;
                        local_132 = bitcast<u32>(_e1739);
                        let _e1741 = local_9;
                        let _e1742 = local_3;
                        if (_e1741 < _e1742) {
                        } else {
                            phi_1802_ = true;
                            break;
                        }
                        let _e1744 = local_9;
                        let _e1747 = local_132;
                        global_6.member[_e1744] = _e1747;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e1748 = local_7;
                    let _e1749 = local_6;
                    phi_127_ = (_e1748 + _e1749);
                } else {
                    phi_127_ = u32();
                }
                let _e1752 = phi_127_;
                continue;
                continuing {
                    let _e1753 = local_8;
                    phi_126_ = _e1752;
                    phi_1802_ = false;
                    break if !(_e1753);
                }
            }
            let _e1756 = phi_1802_;
            if _e1756 {
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
