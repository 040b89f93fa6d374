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
var<workgroup> global_8: array<u32, 1792>;
@group(0) @binding(5) 
var<storage> global_9: type_7;
@group(0) @binding(6) 
var<storage> global_10: type_7;
@group(0) @binding(7) 
var<storage, read_write> global_11: type_7;
@group(0) @binding(8) 
var<storage, read_write> global_12: type_7;
@group(0) @binding(9) 
var<storage> global_13: type_7;
var<private> global_14: u32 = 2143289344u;

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
    var local_13: type_17;
    var local_14: u32;
    var local_15: f32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: i32;
    var local_26: bool;
    var local_27: i32;
    var local_28: i32;
    var local_29: i32;
    var local_30: i32;
    var local_31: u32;
    var local_32: u32;
    var local_33: u32;
    var local_34: f32;
    var local_35: bool;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: bool;
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
    var local_53: u32;
    var local_54: u32;
    var local_55: bool;
    var local_56: u32;
    var local_57: bool;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: bool;
    var local_62: u32;
    var local_63: u32;
    var local_64: bool;
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
    var local_173: u32;
    var local_174: u32;
    var local_175: u32;
    var local_176: bool;
    var local_177: u32;
    var local_178: u32;
    var local_179: u32;
    var local_180: bool;
    var local_181: u32;
    var local_182: u32;
    var local_183: bool;
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
    var local_194: bool;
    var local_195: u32;
    var local_196: u32;
    var local_197: bool;
    var local_198: u32;
    var local_199: u32;
    var local_200: bool;
    var local_201: u32;
    var local_202: type_24;
    var local_203: u32;
    var local_204: u32;
    var local_205: bool;
    var local_206: u32;
    var local_207: u32;
    var local_208: u32;
    var local_209: u32;
    var local_210: u32;
    var local_211: u32;
    var local_212: u32;
    var local_213: bool;
    var local_214: u32;
    var local_215: u32;
    var local_216: u32;
    var local_217: u32;
    var local_218: type_24;
    var local_219: u32;
    var local_220: u32;
    var local_221: bool;
    var local_222: u32;
    var local_223: u32;
    var local_224: u32;
    var local_225: bool;
    var local_226: u32;
    var local_227: u32;
    var local_228: bool;
    var local_229: u32;
    var local_230: u32;
    var local_231: u32;
    var local_232: bool;
    var local_233: type_24;
    var local_234: bool;
    var local_235: u32;
    var local_236: type_24;
    var local_237: u32;
    var local_238: u32;
    var local_239: u32;
    var local_240: u32;
    var local_241: type_24;
    var local_242: bool;
    var local_243: u32;
    var local_244: u32;
    var local_245: bool;
    var local_246: u32;
    var local_247: type_24;
    var local_248: u32;
    var local_249: bool;
    var local_250: u32;
    var local_251: type_24;
    var local_252: u32;
    var local_253: u32;
    var local_254: u32;
    var local_255: u32;
    var local_256: u32;
    var local_257: u32;
    var local_258: u32;
    var local_259: u32;
    var local_260: u32;
    var local_261: u32;
    var local_262: u32;
    var local_263: u32;
    var local_264: u32;
    var local_265: u32;
    var local_266: u32;
    var local_267: u32;
    var local_268: u32;
    var local_269: u32;
    var local_270: f32;
    var local_271: u32;
    var local_272: u32;
    var local_273: u32;
    var local_274: u32;
    var phi_355_: bool;
    var phi_366_: u32;
    var phi_368_: u32;
    var phi_369_: u32;
    var phi_370_: u32;
    var phi_371_: u32;
    var phi_372_: u32;
    var phi_373_: u32;
    var phi_374_: u32;
    var phi_375_: u32;
    var phi_378_: u32;
    var phi_379_: u32;
    var phi_533_: u32;
    var phi_536_: u32;
    var phi_572_: u32;
    var phi_534_: u32;
    var phi_537_: u32;
    var phi_2713_: bool;
    var phi_2756_: bool;
    var phi_610_: u32;
    var phi_613_: u32;
    var phi_615_: u32;
    var phi_649_: u32;
    var phi_651_: u32;
    var phi_652_: bool;
    var phi_657_: u32;
    var phi_660_: u32;
    var phi_684_: u32;
    var phi_658_: u32;
    var phi_661_: u32;
    var phi_2752_: bool;
    var phi_2764_: bool;
    var phi_687_: u32;
    var phi_690_: type_24;
    var phi_692_: u32;
    var phi_707_: type_24;
    var phi_733_: type_24;
    var phi_708_: type_24;
    var phi_734_: bool;
    var phi_2761_: bool;
    var phi_754_: u32;
    var phi_823_: u32;
    var phi_826_: u32;
    var phi_850_: u32;
    var phi_866_: u32;
    var phi_872_: u32;
    var phi_824_: u32;
    var phi_827_: u32;
    var phi_2766_: bool;
    var phi_876_: u32;
    var phi_879_: u32;
    var phi_903_: u32;
    var phi_919_: u32;
    var phi_925_: u32;
    var phi_877_: u32;
    var phi_880_: u32;
    var phi_2775_: bool;
    var phi_944_: u32;
    var phi_984_: u32;
    var phi_967_: u32;
    var phi_985_: u32;
    var phi_2784_: bool;
    var phi_1097_: type_24;
    var phi_1099_: type_24;
    var phi_1121_: u32;
    var phi_1142_: u32;
    var phi_1187_: u32;
    var phi_1168_: u32;
    var phi_1188_: u32;
    var phi_1100_: type_24;
    var phi_2781_: bool;
    var phi_1686_: u32;
    var phi_1704_: u32;
    var phi_1385_: array<f32, 3>;
    var phi_1396_: f32;
    var phi_1421_: u32;
    var phi_1434_: u32;
    var phi_1468_: type_21;
    var phi_1479_: f32;
    var phi_1503_: bool;
    var phi_1525_: f32;
    var phi_1526_: f32;
    var phi_1532_: f32;
    var phi_1534_: f32;
    var phi_1631_: u32;
    var phi_1632_: u32;
    var phi_1652_: bool;
    var phi_1668_: u32;
    var phi_1669_: u32;
    var phi_1706_: u32;
    var phi_1707_: u32;
    var phi_2812_: bool;
    var phi_1708_: u32;
    var phi_1709_: type_24;
    var phi_1710_: u32;
    var phi_2811_: bool;
    var phi_688_: u32;
    var phi_691_: type_24;
    var phi_693_: u32;
    var phi_1711_: bool;
    var phi_2810_: bool;
    var phi_2845_: bool;
    var phi_1716_: u32;
    var phi_1871_: u32;
    var phi_1874_: u32;
    var phi_1910_: u32;
    var phi_1872_: u32;
    var phi_1875_: u32;
    var phi_2842_: bool;
    var phi_1940_: u32;
    var phi_1957_: u32;
    var phi_1960_: u32;
    var phi_1984_: u32;
    var phi_1958_: u32;
    var phi_1961_: u32;
    var phi_2867_: bool;
    var phi_2877_: bool;
    var phi_1985_: u32;
    var phi_2876_: bool;
    var phi_1988_: type_24;
    var phi_1991_: u32;
    var phi_1993_: u32;
    var phi_2010_: type_24;
    var phi_2036_: type_24;
    var phi_2011_: type_24;
    var phi_2037_: bool;
    var phi_2873_: bool;
    var phi_2057_: u32;
    var phi_2126_: u32;
    var phi_2129_: u32;
    var phi_2153_: u32;
    var phi_2169_: u32;
    var phi_2175_: u32;
    var phi_2127_: u32;
    var phi_2130_: u32;
    var phi_2879_: bool;
    var phi_2179_: u32;
    var phi_2182_: u32;
    var phi_2206_: u32;
    var phi_2222_: u32;
    var phi_2228_: u32;
    var phi_2180_: u32;
    var phi_2183_: u32;
    var phi_2888_: bool;
    var phi_2247_: u32;
    var phi_2287_: u32;
    var phi_2270_: u32;
    var phi_2288_: u32;
    var phi_2897_: bool;
    var phi_2400_: type_24;
    var phi_2402_: type_24;
    var phi_2424_: u32;
    var phi_2445_: u32;
    var phi_2490_: u32;
    var phi_2471_: u32;
    var phi_2491_: u32;
    var phi_2403_: type_24;
    var phi_2894_: bool;
    var phi_2925_: bool;
    var phi_2651_: type_24;
    var phi_2652_: u32;
    var phi_2924_: bool;
    var phi_1989_: type_24;
    var phi_1992_: u32;
    var phi_1994_: u32;
    var phi_2923_: bool;
    var phi_2927_: bool;
    var phi_611_: u32;
    var phi_614_: u32;
    var phi_616_: u32;
    var phi_2926_: bool;
    var local_275: type_24;
    var local_276: type_24;
    var local_277: u32;
    var local_278: u32;
    var local_279: type_24;
    var local_280: type_24;

    let _e335 = global_14;
    switch bitcast<i32>(0u) {
        default: {
            let _e338 = global;
            local = _e338;
            let _e339 = global_1;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_3.member));
            local_6 = arrayLength((&global_9.member));
            local_7 = arrayLength((&global_10.member));
            local_8 = arrayLength((&global_11.member));
            local_9 = arrayLength((&global_12.member));
            let _e360 = arrayLength((&global_13.member));
            local_10 = _e360;
            local_11 = _e339.x;
            local_12 = _e339.y;
            let _e363 = global_2.member;
            local_13 = _e363;
            if (18u < _e360) {
            } else {
                break;
            }
            let _e367 = global_13.member[18u];
            local_14 = _e367;
            let _e368 = local_10;
            if (19u < _e368) {
            } else {
                break;
            }
            let _e372 = global_13.member[19u];
            local_15 = bitcast<f32>(_e372);
            let _e374 = local_13;
            local_16 = _e374.member_7;
            let _e376 = local_12;
            let _e378 = local_11;
            let _e379 = ((_e376 * _e374.member_7) + _e378);
            local_17 = _e379;
            let _e380 = local_5;
            if (_e379 < _e380) {
            } else {
                break;
            }
            let _e382 = local_17;
            let _e385 = global_3.member[_e382];
            local_18 = _e385;
            let _e386 = local_17;
            let _e387 = (2u * _e386);
            local_19 = _e387;
            let _e388 = local_6;
            if (_e387 < _e388) {
            } else {
                break;
            }
            let _e390 = local_19;
            let _e393 = global_9.member[_e390];
            local_20 = _e393;
            let _e394 = local_19;
            let _e395 = (_e394 + 1u);
            local_21 = _e395;
            let _e396 = local_6;
            if (_e395 < _e396) {
            } else {
                break;
            }
            let _e398 = local_21;
            let _e401 = global_9.member[_e398];
            local_22 = _e401;
            let _e402 = local_18;
            if ((_e402 & 1u) == 0u) {
                let _e405 = local_22;
                if (_e405 == 0u) {
                } else {
                    let _e407 = local_18;
                    local_23 = (_e407 >> bitcast<u32>(1u));
                    let _e410 = local_14;
                    let _e412 = ((2u * _e410) + 1u);
                    local_24 = _e412;
                    let _e414 = local;
                    if (_e414 < (_e412 * _e412)) {
                        let _e416 = local_11;
                        local_25 = bitcast<i32>(_e416);
                        let _e418 = local_24;
                        let _e419 = (_e418 == 0u);
                        local_26 = _e419;
                        if _e419 {
                            break;
                        }
                        let _e420 = local;
                        let _e421 = local_24;
                        let _e424 = local_25;
                        let _e426 = local_14;
                        let _e427 = bitcast<i32>(_e426);
                        local_27 = _e427;
                        local_28 = ((_e424 + bitcast<i32>((_e420 % _e421))) - _e427);
                        let _e429 = local_12;
                        local_29 = bitcast<i32>(_e429);
                        let _e431 = local_26;
                        if _e431 {
                            break;
                        }
                        let _e432 = local;
                        let _e433 = local_24;
                        let _e436 = local_29;
                        let _e438 = local_27;
                        local_30 = ((_e436 + bitcast<i32>((_e432 / _e433))) - _e438);
                        let _e440 = local_28;
                        if (_e440 >= 0i) {
                            let _e442 = local_30;
                            if (_e442 >= 0i) {
                                let _e444 = local_16;
                                let _e446 = local_28;
                                if (_e446 < bitcast<i32>(_e444)) {
                                    let _e448 = local_13;
                                    let _e451 = local_30;
                                    if (_e451 < bitcast<i32>(_e448.member_8)) {
                                        let _e453 = local_30;
                                        let _e454 = bitcast<u32>(_e453);
                                        local_31 = _e454;
                                        let _e455 = local_16;
                                        let _e457 = local_28;
                                        let _e458 = bitcast<u32>(_e457);
                                        local_32 = _e458;
                                        let _e459 = ((_e454 * _e455) + _e458);
                                        local_33 = _e459;
                                        let _e460 = local_4;
                                        if (_e459 < _e460) {
                                        } else {
                                            break;
                                        }
                                        let _e462 = local_33;
                                        let _e465 = global_7.member[_e462];
                                        local_34 = bitcast<f32>(_e465);
                                        let _e467 = local_33;
                                        let _e468 = local_17;
                                        if (_e467 == _e468) {
                                            phi_355_ = true;
                                        } else {
                                            let _e470 = local_13;
                                            let _e472 = local_13;
                                            let _e474 = local_32;
                                            let _e476 = ((_e474 + 1u) * _e470.member_6);
                                            let _e479 = local_32;
                                            let _e483 = local_13;
                                            let _e485 = local_31;
                                            let _e487 = ((_e485 + 1u) * _e470.member_6);
                                            let _e490 = local_31;
                                            let _e494 = local_11;
                                            let _e496 = ((_e494 + 1u) * _e470.member_6);
                                            let _e499 = local_11;
                                            let _e503 = local_12;
                                            let _e505 = ((_e503 + 1u) * _e470.member_6);
                                            let _e508 = local_12;
                                            let _e514 = ((f32((_e499 * _e470.member_6)) + 0.5f) - f32(select(_e472.member, _e476, (_e476 < _e472.member))));
                                            let _e515 = (f32((_e479 * _e470.member_6)) - (f32(select(_e472.member, _e496, (_e496 < _e472.member))) - 0.5f));
                                            let _e517 = select(_e515, _e514, (_e514 > _e515));
                                            let _e519 = select(0f, _e517, (_e517 > 0f));
                                            let _e522 = ((f32((_e508 * _e470.member_6)) + 0.5f) - f32(select(_e483.member_1, _e487, (_e487 < _e483.member_1))));
                                            let _e523 = (f32((_e490 * _e470.member_6)) - (f32(select(_e483.member_1, _e505, (_e505 < _e483.member_1))) - 0.5f));
                                            let _e525 = select(_e523, _e522, (_e522 > _e523));
                                            let _e527 = select(0f, _e525, (_e525 > 0f));
                                            let _e531 = local_34;
                                            let _e532 = local_34;
                                            phi_355_ = (((_e519 * _e519) + (_e527 * _e527)) <= (_e531 * _e532));
                                        }
                                        let _e536 = phi_355_;
                                        local_35 = _e536;
                                        if _e536 {
                                            let _e537 = local_33;
                                            let _e538 = local_2;
                                            if (_e537 < _e538) {
                                            } else {
                                                break;
                                            }
                                            let _e540 = local_33;
                                            let _e543 = global_5.member[_e540];
                                            phi_366_ = _e543;
                                        } else {
                                            phi_366_ = 0u;
                                        }
                                        let _e545 = phi_366_;
                                        let _e546 = local_35;
                                        let _e547 = local_33;
                                        phi_368_ = _e545;
                                        phi_369_ = select(0u, _e547, _e546);
                                    } else {
                                        phi_368_ = 0u;
                                        phi_369_ = 0u;
                                    }
                                    let _e550 = phi_368_;
                                    let _e552 = phi_369_;
                                    phi_370_ = _e550;
                                    phi_371_ = _e552;
                                } else {
                                    phi_370_ = 0u;
                                    phi_371_ = 0u;
                                }
                                let _e554 = phi_370_;
                                let _e556 = phi_371_;
                                phi_372_ = _e554;
                                phi_373_ = _e556;
                            } else {
                                phi_372_ = 0u;
                                phi_373_ = 0u;
                            }
                            let _e558 = phi_372_;
                            let _e560 = phi_373_;
                            phi_374_ = _e558;
                            phi_375_ = _e560;
                        } else {
                            phi_374_ = 0u;
                            phi_375_ = 0u;
                        }
                        let _e562 = phi_374_;
                        let _e564 = phi_375_;
                        phi_378_ = _e562;
                        phi_379_ = _e564;
                    } else {
                        phi_378_ = 0u;
                        phi_379_ = 0u;
                    }
                    let _e566 = phi_378_;
                    let _e568 = phi_379_;
                    local_36 = _e566;
                    local_37 = _e568;
                    let _e569 = local;
                    let _e570 = (768u + _e569);
                    local_38 = _e570;
                    if (_e570 < 1792u) {
                    } else {
                        break;
                    }
                    let _e572 = local_38;
                    let _e574 = local_36;
                    global_8[_e572] = _e574;
                    let _e575 = local;
                    let _e576 = (1280u + _e575);
                    local_39 = _e576;
                    if (_e576 < 1792u) {
                    } else {
                        break;
                    }
                    let _e578 = local_39;
                    let _e580 = local_37;
                    global_8[_e578] = _e580;
                    storageBarrier();
                    workgroupBarrier();
                    phi_533_ = 1u;
                    phi_536_ = 768u;
                    loop {
                        let _e582 = phi_533_;
                        let _e584 = phi_536_;
                        local_40 = _e582;
                        local_41 = _e584;
                        let _e585 = local_40;
                        let _e586 = (_e585 < 256u);
                        local_42 = _e586;
                        if _e586 {
                            let _e587 = local_41;
                            let _e589 = select(768u, 1024u, (_e587 == 768u));
                            local_265 = _e589;
                            let _e590 = local_41;
                            let _e591 = local;
                            let _e592 = (_e590 + _e591);
                            local_43 = _e592;
                            if (_e592 < 1792u) {
                            } else {
                                phi_2713_ = true;
                                break;
                            }
                            let _e594 = local_43;
                            let _e596 = global_8[_e594];
                            local_44 = _e596;
                            let _e597 = local;
                            let _e598 = local_40;
                            if (_e597 >= _e598) {
                                let _e600 = local;
                                let _e601 = local_40;
                                let _e603 = local_41;
                                let _e604 = (_e603 + (_e600 - _e601));
                                local_45 = _e604;
                                if (_e604 < 1792u) {
                                } else {
                                    phi_2713_ = true;
                                    break;
                                }
                                let _e606 = local_45;
                                let _e608 = global_8[_e606];
                                let _e609 = local_44;
                                phi_572_ = (_e608 + _e609);
                            } else {
                                phi_572_ = _e596;
                            }
                            let _e612 = phi_572_;
                            local_46 = _e612;
                            let _e613 = local_265;
                            let _e614 = local;
                            let _e615 = (_e613 + _e614);
                            local_47 = _e615;
                            if (_e615 < 1792u) {
                            } else {
                                phi_2713_ = true;
                                break;
                            }
                            let _e617 = local_47;
                            let _e619 = local_46;
                            global_8[_e617] = _e619;
                            storageBarrier();
                            workgroupBarrier();
                            let _e620 = local_40;
                            phi_534_ = (_e620 * 2u);
                            phi_537_ = _e589;
                        } else {
                            phi_534_ = u32();
                            phi_537_ = u32();
                        }
                        let _e623 = phi_534_;
                        let _e625 = phi_537_;
                        continue;
                        continuing {
                            let _e626 = local_42;
                            phi_533_ = _e623;
                            phi_536_ = _e625;
                            phi_2713_ = false;
                            break if !(_e626);
                        }
                    }
                    let _e629 = phi_2713_;
                    if _e629 {
                        break;
                    }
                    let _e630 = local_41;
                    let _e631 = (_e630 + 255u);
                    local_48 = _e631;
                    if (_e631 < 1792u) {
                    } else {
                        break;
                    }
                    let _e633 = local_48;
                    let _e635 = global_8[_e633];
                    local_49 = _e635;
                    let _e636 = local_13;
                    local_50 = _e636.member_10;
                    let _e640 = select(16u, 1u, ((_e636.member_10 & 2u) == 0u));
                    local_266 = _e640;
                    local_51 = (32u >> bitcast<u32>((select(firstTrailingBit(_e640), 32u, (_e640 == 0u)) & 31u)));
                    phi_2756_ = _e629;
                    phi_610_ = 0u;
                    phi_613_ = 0u;
                    phi_615_ = 0u;
                    loop {
                        let _e648 = phi_2756_;
                        let _e650 = phi_610_;
                        let _e652 = phi_613_;
                        let _e654 = phi_615_;
                        local_52 = _e650;
                        local_53 = _e652;
                        local_54 = _e654;
                        let _e655 = local_53;
                        let _e656 = local_49;
                        let _e657 = (_e655 < _e656);
                        local_55 = _e657;
                        if _e657 {
                            let _e658 = local;
                            let _e659 = local_266;
                            let _e661 = local_53;
                            local_56 = (_e661 + (_e658 * _e659));
                            let _e663 = local_52;
                            let _e664 = local_51;
                            if (_e663 < _e664) {
                                let _e666 = local_23;
                                let _e667 = (_e666 == 0u);
                                local_57 = _e667;
                                if _e667 {
                                    let _e668 = local_17;
                                    let _e670 = local;
                                    let _e671 = ((_e668 * 256u) + _e670);
                                    local_58 = _e671;
                                    let _e672 = local_7;
                                    if (_e671 < _e672) {
                                    } else {
                                        phi_2926_ = true;
                                        break;
                                    }
                                    let _e674 = local_58;
                                    let _e677 = global_10.member[_e674];
                                    let _e678 = local_52;
                                    let _e679 = local_266;
                                    let _e684 = local_266;
                                    phi_649_ = ((_e677 >> bitcast<u32>(((_e678 * _e679) & 31u))) & (4294967295u >> bitcast<u32>(((32u - _e684) & 31u))));
                                } else {
                                    phi_649_ = u32();
                                }
                                let _e691 = phi_649_;
                                let _e692 = local_57;
                                phi_651_ = _e691;
                                phi_652_ = select(true, false, _e692);
                            } else {
                                phi_651_ = u32();
                                phi_652_ = true;
                            }
                            let _e695 = phi_651_;
                            let _e697 = phi_652_;
                            if _e697 {
                                phi_657_ = 255u;
                                phi_660_ = 0u;
                                loop {
                                    let _e699 = phi_657_;
                                    let _e701 = phi_660_;
                                    local_59 = _e699;
                                    local_60 = _e701;
                                    let _e702 = local_60;
                                    let _e703 = local_59;
                                    let _e704 = (_e702 < _e703);
                                    local_61 = _e704;
                                    if _e704 {
                                        let _e705 = local_60;
                                        let _e706 = local_59;
                                        let _e708 = ((_e705 + _e706) / 2u);
                                        local_62 = _e708;
                                        let _e709 = local_41;
                                        let _e710 = (_e709 + _e708);
                                        local_63 = _e710;
                                        if (_e710 < 1792u) {
                                        } else {
                                            phi_2752_ = true;
                                            break;
                                        }
                                        let _e712 = local_63;
                                        let _e714 = global_8[_e712];
                                        let _e715 = local_56;
                                        let _e716 = (_e714 > _e715);
                                        local_64 = _e716;
                                        if _e716 {
                                            phi_684_ = _e701;
                                        } else {
                                            let _e717 = local_62;
                                            phi_684_ = (_e717 + 1u);
                                        }
                                        let _e720 = phi_684_;
                                        let _e721 = local_64;
                                        let _e722 = local_62;
                                        let _e723 = local_59;
                                        phi_658_ = select(_e723, _e722, _e721);
                                        phi_661_ = _e720;
                                    } else {
                                        phi_658_ = u32();
                                        phi_661_ = u32();
                                    }
                                    let _e726 = phi_658_;
                                    let _e728 = phi_661_;
                                    continue;
                                    continuing {
                                        let _e729 = local_61;
                                        phi_657_ = _e726;
                                        phi_660_ = _e728;
                                        phi_2752_ = _e648;
                                        break if !(_e729);
                                    }
                                }
                                let _e732 = phi_2752_;
                                phi_2926_ = _e732;
                                if _e732 {
                                    break;
                                }
                                let _e733 = local_60;
                                let _e734 = local_11;
                                let _e735 = local_12;
                                phi_2764_ = _e732;
                                phi_687_ = 0u;
                                phi_690_ = type_24(_e733, 4294967295u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, _e734, _e735, false);
                                phi_692_ = 0u;
                                loop {
                                    let _e738 = phi_2764_;
                                    let _e740 = phi_687_;
                                    let _e742 = phi_690_;
                                    let _e744 = phi_692_;
                                    local_65 = _e740;
                                    local_66 = _e744;
                                    local_277 = _e740;
                                    let _e745 = local_66;
                                    let _e746 = local_266;
                                    if (_e745 < _e746) {
                                        let _e748 = local_56;
                                        let _e749 = local_66;
                                        let _e750 = (_e748 + _e749);
                                        local_67 = _e750;
                                        let _e751 = local_49;
                                        let _e752 = (_e750 < _e751);
                                        if _e752 {
                                            phi_707_ = _e742;
                                            loop {
                                                let _e754 = phi_707_;
                                                local_68 = _e754;
                                                local_275 = _e754;
                                                let _e755 = local_68;
                                                local_69 = _e755.member;
                                                if (_e755.member < 255u) {
                                                    let _e758 = local_41;
                                                    let _e759 = local_69;
                                                    let _e760 = (_e758 + _e759);
                                                    local_70 = _e760;
                                                    if (_e760 < 1792u) {
                                                    } else {
                                                        phi_2761_ = true;
                                                        break;
                                                    }
                                                    let _e762 = local_70;
                                                    let _e764 = global_8[_e762];
                                                    let _e765 = local_67;
                                                    let _e766 = (_e764 <= _e765);
                                                    if _e766 {
                                                        let _e767 = local_69;
                                                        let _e769 = local_68;
                                                        phi_733_ = type_24((_e767 + 1u), _e769.member_1, _e769.member_2, _e769.member_3, _e769.member_4, _e769.member_5, _e769.member_6, _e769.member_7, _e769.member_8, _e769.member_9, _e769.member_10, _e769.member_11, _e769.member_12, _e769.member_13, _e769.member_14);
                                                    } else {
                                                        phi_733_ = type_24();
                                                    }
                                                    let _e787 = phi_733_;
                                                    phi_708_ = _e787;
                                                    phi_734_ = _e766;
                                                } else {
                                                    phi_708_ = type_24();
                                                    phi_734_ = false;
                                                }
                                                let _e789 = phi_708_;
                                                let _e791 = phi_734_;
                                                local_71 = _e791;
                                                continue;
                                                continuing {
                                                    let _e792 = local_71;
                                                    phi_707_ = _e789;
                                                    phi_2761_ = _e738;
                                                    break if !(_e792);
                                                }
                                            }
                                            let _e795 = phi_2761_;
                                            phi_2810_ = _e795;
                                            if _e795 {
                                                break;
                                            }
                                            let _e796 = local_69;
                                            if (_e796 == 0u) {
                                                phi_754_ = 0u;
                                            } else {
                                                let _e798 = local_41;
                                                let _e799 = local_69;
                                                let _e801 = ((_e798 + _e799) - 1u);
                                                local_72 = _e801;
                                                if (_e801 < 1792u) {
                                                } else {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e803 = local_72;
                                                let _e805 = global_8[_e803];
                                                phi_754_ = _e805;
                                            }
                                            let _e807 = phi_754_;
                                            let _e808 = local_67;
                                            local_73 = (_e808 - _e807);
                                            let _e810 = local_68;
                                            let _e812 = local_69;
                                            if (_e810.member_1 != _e812) {
                                                let _e814 = local_13;
                                                local_74 = _e814.member_6;
                                                let _e816 = local_13;
                                                local_75 = _e816.member_3;
                                                if (_e816.member_3 == 0u) {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e819 = local_74;
                                                let _e820 = local_75;
                                                local_76 = (_e819 / _e820);
                                                let _e822 = local_69;
                                                let _e823 = (1280u + _e822);
                                                local_77 = _e823;
                                                if (_e823 < 1792u) {
                                                } else {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e825 = local_77;
                                                let _e827 = global_8[_e825];
                                                local_78 = _e827;
                                                let _e828 = local_16;
                                                let _e829 = (_e828 == 0u);
                                                local_79 = _e829;
                                                if _e829 {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e830 = local_78;
                                                let _e831 = local_16;
                                                let _e833 = local_76;
                                                local_80 = ((_e830 % _e831) * _e833);
                                                let _e835 = local_79;
                                                if _e835 {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e836 = local_78;
                                                let _e837 = local_16;
                                                let _e839 = local_76;
                                                let _e840 = ((_e836 / _e837) * _e839);
                                                local_81 = _e840;
                                                let _e841 = local_69;
                                                let _e842 = local_68;
                                                let _e858 = type_24(_e842.member, _e841, _e842.member_2, _e842.member_3, _e842.member_4, _e842.member_5, _e842.member_6, _e842.member_7, _e842.member_8, _e842.member_9, _e842.member_10, _e842.member_11, _e842.member_12, _e842.member_13, _e842.member_14);
                                                let _e859 = local_78;
                                                let _e875 = type_24(_e858.member, _e858.member_1, _e859, _e858.member_3, _e858.member_4, _e858.member_5, _e858.member_6, _e858.member_7, _e858.member_8, _e858.member_9, _e858.member_10, _e858.member_11, _e858.member_12, _e858.member_13, _e858.member_14);
                                                let _e876 = local_13;
                                                local_82 = _e876.member_4;
                                                let _e879 = local_80;
                                                let _e880 = ((_e840 * _e876.member_4) + _e879);
                                                local_83 = _e880;
                                                let _e896 = type_24(_e875.member, _e875.member_1, _e875.member_2, _e880, _e875.member_4, _e875.member_5, _e875.member_6, _e875.member_7, _e875.member_8, _e875.member_9, _e875.member_10, _e875.member_11, _e875.member_12, _e875.member_13, _e875.member_14);
                                                let _e897 = local_80;
                                                let _e913 = type_24(_e896.member, _e896.member_1, _e896.member_2, _e896.member_3, _e897, _e896.member_5, _e896.member_6, _e896.member_7, _e896.member_8, _e896.member_9, _e896.member_10, _e896.member_11, _e896.member_12, _e896.member_13, _e896.member_14);
                                                let _e929 = type_24(_e913.member, _e913.member_1, _e913.member_2, _e913.member_3, _e913.member_4, _e840, _e913.member_6, _e913.member_7, _e913.member_8, _e913.member_9, _e913.member_10, _e913.member_11, _e913.member_12, _e913.member_13, _e913.member_14);
                                                let _e930 = local_80;
                                                let _e931 = (_e876.member_4 - _e930);
                                                let _e932 = local_76;
                                                let _e934 = local_76;
                                                let _e935 = select(_e934, _e931, (_e931 < _e932));
                                                local_267 = _e935;
                                                let _e951 = type_24(_e929.member, _e929.member_1, _e929.member_2, _e929.member_3, _e929.member_4, _e929.member_5, _e935, _e929.member_7, _e929.member_8, _e929.member_9, _e929.member_10, _e929.member_11, _e929.member_12, _e929.member_13, _e929.member_14);
                                                let _e952 = local_13;
                                                local_84 = _e952.member_5;
                                                let _e954 = (_e952.member_5 - _e840);
                                                let _e955 = local_76;
                                                let _e957 = local_76;
                                                let _e958 = select(_e957, _e954, (_e954 < _e955));
                                                local_268 = _e958;
                                                local_85 = type_24(_e951.member, _e951.member_1, _e951.member_2, _e951.member_3, _e951.member_4, _e951.member_5, _e951.member_6, _e958, _e951.member_8, _e951.member_9, _e951.member_10, _e951.member_11, _e951.member_12, _e951.member_13, _e951.member_14);
                                                phi_823_ = (_e958 - 1u);
                                                phi_826_ = 0u;
                                                loop {
                                                    let _e977 = phi_823_;
                                                    let _e979 = phi_826_;
                                                    local_86 = _e977;
                                                    local_87 = _e979;
                                                    let _e980 = local_87;
                                                    let _e981 = local_86;
                                                    let _e982 = (_e980 < _e981);
                                                    local_88 = _e982;
                                                    if _e982 {
                                                        let _e983 = local_87;
                                                        let _e984 = local_86;
                                                        let _e985 = (_e983 + _e984);
                                                        let _e986 = (_e985 / 2u);
                                                        local_89 = _e986;
                                                        if ((_e985 % 2u) > 0u) {
                                                            let _e989 = local_89;
                                                            phi_850_ = (_e989 + 1u);
                                                        } else {
                                                            phi_850_ = _e986;
                                                        }
                                                        let _e992 = phi_850_;
                                                        local_90 = _e992;
                                                        let _e993 = local_268;
                                                        if (_e992 < _e993) {
                                                            let _e995 = local_90;
                                                            let _e996 = local_82;
                                                            let _e998 = local_83;
                                                            let _e999 = (_e998 + (_e995 * _e996));
                                                            local_91 = _e999;
                                                            let _e1000 = local_3;
                                                            if (_e999 < _e1000) {
                                                            } else {
                                                                phi_2766_ = true;
                                                                break;
                                                            }
                                                            let _e1002 = local_91;
                                                            let _e1005 = global_6.member[_e1002];
                                                            phi_866_ = _e1005;
                                                        } else {
                                                            phi_866_ = 4294967295u;
                                                        }
                                                        let _e1007 = phi_866_;
                                                        let _e1008 = local_73;
                                                        let _e1009 = (_e1007 <= _e1008);
                                                        local_92 = _e1009;
                                                        if _e1009 {
                                                            phi_872_ = _e977;
                                                        } else {
                                                            let _e1010 = local_90;
                                                            phi_872_ = (_e1010 - 1u);
                                                        }
                                                        let _e1013 = phi_872_;
                                                        let _e1014 = local_92;
                                                        let _e1015 = local_90;
                                                        let _e1016 = local_87;
                                                        phi_824_ = _e1013;
                                                        phi_827_ = select(_e1016, _e1015, _e1014);
                                                    } else {
                                                        phi_824_ = u32();
                                                        phi_827_ = u32();
                                                    }
                                                    let _e1019 = phi_824_;
                                                    let _e1021 = phi_827_;
                                                    continue;
                                                    continuing {
                                                        let _e1022 = local_88;
                                                        phi_823_ = _e1019;
                                                        phi_826_ = _e1021;
                                                        phi_2766_ = _e795;
                                                        break if !(_e1022);
                                                    }
                                                }
                                                let _e1025 = phi_2766_;
                                                phi_2810_ = _e1025;
                                                if _e1025 {
                                                    break;
                                                }
                                                let _e1026 = local_267;
                                                phi_876_ = (_e1026 - 1u);
                                                phi_879_ = 0u;
                                                loop {
                                                    let _e1029 = phi_876_;
                                                    let _e1031 = phi_879_;
                                                    local_93 = _e1029;
                                                    local_94 = _e1031;
                                                    let _e1032 = local_94;
                                                    let _e1033 = local_93;
                                                    let _e1034 = (_e1032 < _e1033);
                                                    local_95 = _e1034;
                                                    if _e1034 {
                                                        let _e1035 = local_94;
                                                        let _e1036 = local_93;
                                                        let _e1037 = (_e1035 + _e1036);
                                                        let _e1038 = (_e1037 / 2u);
                                                        local_96 = _e1038;
                                                        if ((_e1037 % 2u) > 0u) {
                                                            let _e1041 = local_96;
                                                            phi_903_ = (_e1041 + 1u);
                                                        } else {
                                                            phi_903_ = _e1038;
                                                        }
                                                        let _e1044 = phi_903_;
                                                        local_97 = _e1044;
                                                        let _e1045 = local_87;
                                                        let _e1046 = local_268;
                                                        if (_e1045 < _e1046) {
                                                            let _e1048 = local_87;
                                                            let _e1049 = local_82;
                                                            let _e1051 = local_83;
                                                            let _e1053 = local_97;
                                                            let _e1054 = ((_e1051 + (_e1048 * _e1049)) + _e1053);
                                                            local_98 = _e1054;
                                                            let _e1055 = local_3;
                                                            if (_e1054 < _e1055) {
                                                            } else {
                                                                phi_2775_ = true;
                                                                break;
                                                            }
                                                            let _e1057 = local_98;
                                                            let _e1060 = global_6.member[_e1057];
                                                            phi_919_ = _e1060;
                                                        } else {
                                                            phi_919_ = 4294967295u;
                                                        }
                                                        let _e1062 = phi_919_;
                                                        let _e1063 = local_73;
                                                        let _e1064 = (_e1062 <= _e1063);
                                                        local_99 = _e1064;
                                                        if _e1064 {
                                                            phi_925_ = _e1029;
                                                        } else {
                                                            let _e1065 = local_97;
                                                            phi_925_ = (_e1065 - 1u);
                                                        }
                                                        let _e1068 = phi_925_;
                                                        let _e1069 = local_99;
                                                        let _e1070 = local_97;
                                                        let _e1071 = local_94;
                                                        phi_877_ = _e1068;
                                                        phi_880_ = select(_e1071, _e1070, _e1069);
                                                    } else {
                                                        phi_877_ = u32();
                                                        phi_880_ = u32();
                                                    }
                                                    let _e1074 = phi_877_;
                                                    let _e1076 = phi_880_;
                                                    continue;
                                                    continuing {
                                                        let _e1077 = local_95;
                                                        phi_876_ = _e1074;
                                                        phi_879_ = _e1076;
                                                        phi_2775_ = _e1025;
                                                        break if !(_e1077);
                                                    }
                                                }
                                                let _e1080 = phi_2775_;
                                                phi_2810_ = _e1080;
                                                if _e1080 {
                                                    break;
                                                }
                                                let _e1081 = local_94;
                                                let _e1082 = local_85;
                                                let _e1098 = type_24(_e1082.member, _e1082.member_1, _e1082.member_2, _e1082.member_3, _e1082.member_4, _e1082.member_5, _e1082.member_6, _e1082.member_7, _e1081, _e1082.member_9, _e1082.member_10, _e1082.member_11, _e1082.member_12, _e1082.member_13, _e1082.member_14);
                                                let _e1099 = local_87;
                                                local_100 = type_24(_e1098.member, _e1098.member_1, _e1098.member_2, _e1098.member_3, _e1098.member_4, _e1098.member_5, _e1098.member_6, _e1098.member_7, _e1098.member_8, _e1099, _e1098.member_10, _e1098.member_11, _e1098.member_12, _e1098.member_13, _e1098.member_14);
                                                let _e1116 = local_87;
                                                let _e1117 = local_268;
                                                let _e1118 = (_e1116 < _e1117);
                                                local_101 = _e1118;
                                                if _e1118 {
                                                    let _e1119 = local_87;
                                                    let _e1120 = local_82;
                                                    let _e1122 = local_83;
                                                    let _e1124 = local_94;
                                                    let _e1125 = ((_e1122 + (_e1119 * _e1120)) + _e1124);
                                                    local_102 = _e1125;
                                                    let _e1126 = local_3;
                                                    if (_e1125 < _e1126) {
                                                    } else {
                                                        phi_2810_ = true;
                                                        break;
                                                    }
                                                    let _e1128 = local_102;
                                                    let _e1131 = global_6.member[_e1128];
                                                    phi_944_ = _e1131;
                                                } else {
                                                    phi_944_ = 4294967295u;
                                                }
                                                let _e1133 = phi_944_;
                                                let _e1134 = local_100;
                                                local_103 = type_24(_e1134.member, _e1134.member_1, _e1134.member_2, _e1134.member_3, _e1134.member_4, _e1134.member_5, _e1134.member_6, _e1134.member_7, _e1134.member_8, _e1134.member_9, _e1133, _e1134.member_11, _e1134.member_12, _e1134.member_13, _e1134.member_14);
                                                let _e1151 = local_94;
                                                let _e1152 = (_e1151 + 1u);
                                                local_104 = _e1152;
                                                let _e1153 = local_267;
                                                if (_e1152 < _e1153) {
                                                    let _e1172 = local_101;
                                                    if _e1172 {
                                                        let _e1173 = local_87;
                                                        let _e1174 = local_82;
                                                        let _e1176 = local_83;
                                                        let _e1178 = local_104;
                                                        let _e1179 = ((_e1176 + (_e1173 * _e1174)) + _e1178);
                                                        local_105 = _e1179;
                                                        let _e1180 = local_3;
                                                        if (_e1179 < _e1180) {
                                                        } else {
                                                            phi_2810_ = true;
                                                            break;
                                                        }
                                                        let _e1182 = local_105;
                                                        let _e1185 = global_6.member[_e1182];
                                                        phi_967_ = _e1185;
                                                    } else {
                                                        phi_967_ = 4294967295u;
                                                    }
                                                    let _e1187 = phi_967_;
                                                    phi_985_ = _e1187;
                                                } else {
                                                    let _e1155 = local_87;
                                                    let _e1156 = (_e1155 + 1u);
                                                    local_106 = _e1156;
                                                    let _e1157 = local_268;
                                                    if (_e1156 < _e1157) {
                                                        let _e1159 = local_106;
                                                        let _e1160 = local_82;
                                                        let _e1162 = local_83;
                                                        let _e1163 = (_e1162 + (_e1159 * _e1160));
                                                        local_107 = _e1163;
                                                        let _e1164 = local_3;
                                                        if (_e1163 < _e1164) {
                                                        } else {
                                                            phi_2810_ = true;
                                                            break;
                                                        }
                                                        let _e1166 = local_107;
                                                        let _e1169 = global_6.member[_e1166];
                                                        phi_984_ = _e1169;
                                                    } else {
                                                        phi_984_ = 4294967295u;
                                                    }
                                                    let _e1171 = phi_984_;
                                                    phi_985_ = _e1171;
                                                }
                                                let _e1189 = phi_985_;
                                                let _e1190 = local_103;
                                                local_108 = type_24(_e1190.member, _e1190.member_1, _e1190.member_2, _e1190.member_3, _e1190.member_4, _e1190.member_5, _e1190.member_6, _e1190.member_7, _e1190.member_8, _e1190.member_9, _e1190.member_10, _e1189, _e1190.member_12, _e1190.member_13, _e1190.member_14);
                                                let _e1207 = local_82;
                                                let _e1208 = local_84;
                                                let _e1210 = local_87;
                                                let _e1211 = local_82;
                                                let _e1213 = local_83;
                                                let _e1215 = local_94;
                                                let _e1217 = ((_e1207 * _e1208) + ((_e1213 + (_e1210 * _e1211)) + _e1215));
                                                local_109 = _e1217;
                                                let _e1218 = local_3;
                                                if (_e1217 < _e1218) {
                                                } else {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e1220 = local_109;
                                                let _e1223 = global_6.member[_e1220];
                                                let _e1224 = bitcast<f32>(_e1223);
                                                let _e1225 = local_80;
                                                let _e1226 = local_94;
                                                let _e1227 = (_e1225 + _e1226);
                                                let _e1228 = local_13;
                                                let _e1231 = local_75;
                                                let _e1232 = ((_e1227 + 1u) * _e1231);
                                                let _e1235 = local_75;
                                                let _e1239 = local_81;
                                                let _e1240 = local_87;
                                                let _e1241 = (_e1239 + _e1240);
                                                let _e1242 = local_13;
                                                let _e1245 = local_75;
                                                let _e1246 = ((_e1241 + 1u) * _e1245);
                                                let _e1249 = local_75;
                                                let _e1253 = local_68;
                                                let _e1255 = local_68;
                                                let _e1258 = local_74;
                                                let _e1259 = ((_e1253.member_12 + 1u) * _e1258);
                                                let _e1262 = local_74;
                                                let _e1267 = local_74;
                                                let _e1268 = ((_e1255.member_13 + 1u) * _e1267);
                                                let _e1271 = local_74;
                                                let _e1277 = ((f32((_e1253.member_12 * _e1262)) + 0.5f) - f32(select(_e1228.member, _e1232, (_e1232 < _e1228.member))));
                                                let _e1278 = (f32((_e1227 * _e1235)) - (f32(select(_e1228.member, _e1259, (_e1259 < _e1228.member))) - 0.5f));
                                                let _e1280 = select(_e1278, _e1277, (_e1277 > _e1278));
                                                let _e1282 = select(0f, _e1280, (_e1280 > 0f));
                                                let _e1285 = ((f32((_e1255.member_13 * _e1271)) + 0.5f) - f32(select(_e1242.member_1, _e1246, (_e1246 < _e1242.member_1))));
                                                let _e1286 = (f32((_e1241 * _e1249)) - (f32(select(_e1242.member_1, _e1268, (_e1268 < _e1242.member_1))) - 0.5f));
                                                let _e1288 = select(_e1286, _e1285, (_e1285 > _e1286));
                                                let _e1290 = select(0f, _e1288, (_e1288 > 0f));
                                                let _e1296 = local_108;
                                                phi_2784_ = _e1080;
                                                phi_1097_ = type_24(_e1296.member, _e1296.member_1, _e1296.member_2, _e1296.member_3, _e1296.member_4, _e1296.member_5, _e1296.member_6, _e1296.member_7, _e1296.member_8, _e1296.member_9, _e1296.member_10, _e1296.member_11, _e1296.member_12, _e1296.member_13, (((_e1282 * _e1282) + (_e1290 * _e1290)) <= (_e1224 * _e1224)));
                                            } else {
                                                phi_2784_ = _e795;
                                                let _e2985 = local_275;
                                                phi_1097_ = _e2985;
                                            }
                                            let _e1314 = phi_2784_;
                                            let _e1316 = phi_1097_;
                                            phi_1099_ = _e1316;
                                            loop {
                                                let _e1318 = phi_1099_;
                                                local_110 = _e1318;
                                                local_276 = _e1318;
                                                let _e1319 = local_110;
                                                local_111 = _e1319.member_11;
                                                let _e1321 = local_73;
                                                let _e1322 = (_e1319.member_11 <= _e1321);
                                                local_112 = _e1322;
                                                if _e1322 {
                                                    let _e1323 = local_110;
                                                    let _e1325 = (_e1323.member_8 + 1u);
                                                    local_113 = _e1325;
                                                    let _e1326 = local_110;
                                                    local_114 = _e1326.member_6;
                                                    let _e1328 = (_e1325 < _e1326.member_6);
                                                    local_115 = _e1328;
                                                    if _e1328 {
                                                        let _e1332 = local_110;
                                                        phi_1121_ = _e1332.member_9;
                                                    } else {
                                                        let _e1329 = local_110;
                                                        phi_1121_ = (_e1329.member_9 + 1u);
                                                    }
                                                    let _e1335 = phi_1121_;
                                                    local_116 = _e1335;
                                                    let _e1336 = local_115;
                                                    let _e1337 = local_113;
                                                    let _e1338 = select(0u, _e1337, _e1336);
                                                    local_269 = _e1338;
                                                    let _e1339 = local_110;
                                                    let _e1355 = type_24(_e1339.member, _e1339.member_1, _e1339.member_2, _e1339.member_3, _e1339.member_4, _e1339.member_5, _e1339.member_6, _e1339.member_7, _e1338, _e1339.member_9, _e1339.member_10, _e1339.member_11, _e1339.member_12, _e1339.member_13, _e1339.member_14);
                                                    local_117 = type_24(_e1355.member, _e1355.member_1, _e1355.member_2, _e1355.member_3, _e1355.member_4, _e1355.member_5, _e1355.member_6, _e1355.member_7, _e1355.member_8, _e1335, _e1355.member_10, _e1355.member_11, _e1355.member_12, _e1355.member_13, _e1355.member_14);
                                                    let _e1372 = local_110;
                                                    local_118 = _e1372.member_7;
                                                    let _e1374 = (_e1335 < _e1372.member_7);
                                                    local_119 = _e1374;
                                                    if _e1374 {
                                                        let _e1375 = local_110;
                                                        let _e1377 = local_13;
                                                        let _e1379 = local_116;
                                                        let _e1382 = local_269;
                                                        let _e1383 = ((_e1375.member_3 + (_e1379 * _e1377.member_4)) + _e1382);
                                                        local_120 = _e1383;
                                                        let _e1384 = local_3;
                                                        if (_e1383 < _e1384) {
                                                        } else {
                                                            phi_2781_ = true;
                                                            break;
                                                        }
                                                        let _e1386 = local_120;
                                                        let _e1389 = global_6.member[_e1386];
                                                        phi_1142_ = _e1389;
                                                    } else {
                                                        phi_1142_ = 4294967295u;
                                                    }
                                                    let _e1391 = phi_1142_;
                                                    let _e1392 = local_117;
                                                    local_121 = type_24(_e1392.member, _e1392.member_1, _e1392.member_2, _e1392.member_3, _e1392.member_4, _e1392.member_5, _e1392.member_6, _e1392.member_7, _e1392.member_8, _e1392.member_9, _e1391, _e1392.member_11, _e1392.member_12, _e1392.member_13, _e1392.member_14);
                                                    let _e1409 = local_269;
                                                    let _e1410 = (_e1409 + 1u);
                                                    local_122 = _e1410;
                                                    let _e1411 = local_114;
                                                    if (_e1410 < _e1411) {
                                                        let _e1432 = local_119;
                                                        if _e1432 {
                                                            let _e1433 = local_110;
                                                            let _e1435 = local_13;
                                                            let _e1437 = local_116;
                                                            let _e1440 = local_122;
                                                            let _e1441 = ((_e1433.member_3 + (_e1437 * _e1435.member_4)) + _e1440);
                                                            local_123 = _e1441;
                                                            let _e1442 = local_3;
                                                            if (_e1441 < _e1442) {
                                                            } else {
                                                                phi_2781_ = true;
                                                                break;
                                                            }
                                                            let _e1444 = local_123;
                                                            let _e1447 = global_6.member[_e1444];
                                                            phi_1168_ = _e1447;
                                                        } else {
                                                            phi_1168_ = 4294967295u;
                                                        }
                                                        let _e1449 = phi_1168_;
                                                        phi_1188_ = _e1449;
                                                    } else {
                                                        let _e1413 = local_116;
                                                        let _e1414 = (_e1413 + 1u);
                                                        local_124 = _e1414;
                                                        let _e1415 = local_118;
                                                        if (_e1414 < _e1415) {
                                                            let _e1417 = local_110;
                                                            let _e1419 = local_13;
                                                            let _e1421 = local_124;
                                                            let _e1423 = (_e1417.member_3 + (_e1421 * _e1419.member_4));
                                                            local_125 = _e1423;
                                                            let _e1424 = local_3;
                                                            if (_e1423 < _e1424) {
                                                            } else {
                                                                phi_2781_ = true;
                                                                break;
                                                            }
                                                            let _e1426 = local_125;
                                                            let _e1429 = global_6.member[_e1426];
                                                            phi_1187_ = _e1429;
                                                        } else {
                                                            phi_1187_ = 4294967295u;
                                                        }
                                                        let _e1431 = phi_1187_;
                                                        phi_1188_ = _e1431;
                                                    }
                                                    let _e1451 = phi_1188_;
                                                    let _e1452 = local_121;
                                                    local_126 = type_24(_e1452.member, _e1452.member_1, _e1452.member_2, _e1452.member_3, _e1452.member_4, _e1452.member_5, _e1452.member_6, _e1452.member_7, _e1452.member_8, _e1452.member_9, _e1452.member_10, _e1451, _e1452.member_12, _e1452.member_13, _e1452.member_14);
                                                    let _e1469 = local_13;
                                                    let _e1471 = local_13;
                                                    let _e1474 = local_110;
                                                    let _e1476 = local_116;
                                                    let _e1479 = local_269;
                                                    let _e1481 = ((_e1469.member_4 * _e1471.member_5) + ((_e1474.member_3 + (_e1476 * _e1469.member_4)) + _e1479));
                                                    local_127 = _e1481;
                                                    let _e1482 = local_3;
                                                    if (_e1481 < _e1482) {
                                                    } else {
                                                        phi_2781_ = true;
                                                        break;
                                                    }
                                                    let _e1484 = local_127;
                                                    let _e1487 = global_6.member[_e1484];
                                                    let _e1488 = bitcast<f32>(_e1487);
                                                    let _e1489 = local_110;
                                                    let _e1491 = local_269;
                                                    let _e1492 = (_e1489.member_4 + _e1491);
                                                    let _e1493 = local_13;
                                                    let _e1495 = local_13;
                                                    let _e1498 = ((_e1492 + 1u) * _e1493.member_3);
                                                    let _e1504 = local_110;
                                                    let _e1506 = local_116;
                                                    let _e1507 = (_e1504.member_5 + _e1506);
                                                    let _e1508 = local_13;
                                                    let _e1511 = ((_e1507 + 1u) * _e1493.member_3);
                                                    let _e1517 = local_110;
                                                    let _e1519 = local_110;
                                                    let _e1521 = local_13;
                                                    let _e1524 = ((_e1517.member_12 + 1u) * _e1521.member_6);
                                                    let _e1531 = ((_e1519.member_13 + 1u) * _e1521.member_6);
                                                    let _e1539 = ((f32((_e1517.member_12 * _e1521.member_6)) + 0.5f) - f32(select(_e1495.member, _e1498, (_e1498 < _e1495.member))));
                                                    let _e1540 = (f32((_e1492 * _e1493.member_3)) - (f32(select(_e1495.member, _e1524, (_e1524 < _e1495.member))) - 0.5f));
                                                    let _e1542 = select(_e1540, _e1539, (_e1539 > _e1540));
                                                    let _e1544 = select(0f, _e1542, (_e1542 > 0f));
                                                    let _e1547 = ((f32((_e1519.member_13 * _e1521.member_6)) + 0.5f) - f32(select(_e1508.member_1, _e1511, (_e1511 < _e1508.member_1))));
                                                    let _e1548 = (f32((_e1507 * _e1493.member_3)) - (f32(select(_e1508.member_1, _e1531, (_e1531 < _e1508.member_1))) - 0.5f));
                                                    let _e1550 = select(_e1548, _e1547, (_e1547 > _e1548));
                                                    let _e1552 = select(0f, _e1550, (_e1550 > 0f));
                                                    let _e1558 = local_126;
                                                    phi_1100_ = type_24(_e1558.member, _e1558.member_1, _e1558.member_2, _e1558.member_3, _e1558.member_4, _e1558.member_5, _e1558.member_6, _e1558.member_7, _e1558.member_8, _e1558.member_9, _e1558.member_10, _e1558.member_11, _e1558.member_12, _e1558.member_13, (((_e1544 * _e1544) + (_e1552 * _e1552)) <= (_e1488 * _e1488)));
                                                } else {
                                                    phi_1100_ = type_24();
                                                }
                                                let _e1576 = phi_1100_;
                                                continue;
                                                continuing {
                                                    let _e1577 = local_112;
                                                    phi_1099_ = _e1576;
                                                    phi_2781_ = _e1314;
                                                    break if !(_e1577);
                                                }
                                            }
                                            let _e1580 = phi_2781_;
                                            phi_2810_ = _e1580;
                                            if _e1580 {
                                                break;
                                            }
                                            let _e1581 = local_110;
                                            local_128 = _e1581.member_2;
                                            let _e1583 = local_110;
                                            local_129 = _e1583.member_8;
                                            let _e1585 = local_110;
                                            local_130 = _e1585.member_9;
                                            let _e1587 = local_13;
                                            local_131 = _e1587.member_6;
                                            let _e1589 = local_13;
                                            local_132 = _e1589.member_3;
                                            if (_e1589.member_3 == 0u) {
                                                phi_2810_ = true;
                                                break;
                                            }
                                            let _e1592 = local_131;
                                            let _e1593 = local_132;
                                            let _e1594 = (_e1592 / _e1593);
                                            let _e1595 = local_128;
                                            let _e1597 = local_130;
                                            let _e1600 = local_129;
                                            let _e1602 = local_13;
                                            local_133 = _e1602.member_2;
                                            let _e1604 = local_132;
                                            let _e1606 = local_132;
                                            let _e1609 = local_110;
                                            let _e1611 = local_73;
                                            local_134 = ((((((_e1595 * _e1594) + _e1597) * _e1594) + _e1600) * ((_e1602.member_2 * _e1604) * _e1606)) + (_e1611 - _e1609.member_10));
                                            let _e1614 = local_110;
                                            if _e1614.member_14 {
                                                let _e1647 = local_134;
                                                let _e1648 = (4u * _e1647);
                                                local_135 = _e1648;
                                                let _e1649 = local_1;
                                                if (_e1648 < _e1649) {
                                                } else {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e1651 = local_135;
                                                let _e1654 = global_4.member[_e1651];
                                                local_136 = _e1654;
                                                let _e1655 = local_135;
                                                let _e1656 = (_e1655 + 1u);
                                                local_137 = _e1656;
                                                let _e1657 = local_1;
                                                if (_e1656 < _e1657) {
                                                } else {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e1659 = local_137;
                                                let _e1662 = global_4.member[_e1659];
                                                local_138 = _e1662;
                                                let _e1663 = local_135;
                                                let _e1664 = (_e1663 + 2u);
                                                local_139 = _e1664;
                                                let _e1665 = local_1;
                                                if (_e1664 < _e1665) {
                                                } else {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e1667 = local_139;
                                                let _e1670 = global_4.member[_e1667];
                                                local_140 = _e1670;
                                                let _e1671 = local_135;
                                                let _e1672 = (_e1671 + 3u);
                                                local_141 = _e1672;
                                                let _e1673 = local_1;
                                                if (_e1672 < _e1673) {
                                                } else {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e1675 = local_141;
                                                let _e1678 = global_4.member[_e1675];
                                                local_142 = _e1678;
                                                let _e1679 = local_136;
                                                local_143 = (_e1679 & 16383u);
                                                let _e1681 = local_136;
                                                local_144 = ((_e1681 >> bitcast<u32>(14u)) & 16383u);
                                                let _e1685 = local_138;
                                                local_145 = (_e1685 & 16383u);
                                                let _e1687 = local_138;
                                                let _e1689 = (_e1687 >> bitcast<u32>(24i));
                                                local_146 = _e1689;
                                                if (_e1689 == 0u) {
                                                    phi_1385_ = array<f32, 3>(0f, 0f, 0f);
                                                } else {
                                                    let _e1691 = local_146;
                                                    let _e1697 = bitcast<f32>((bitcast<u32>((bitcast<i32>(_e1691) + -13i)) << bitcast<u32>(23i)));
                                                    let _e1698 = local_143;
                                                    let _e1701 = local_144;
                                                    let _e1704 = local_145;
                                                    phi_1385_ = array<f32, 3>((f32(_e1698) * _e1697), (f32(_e1701) * _e1697), (f32(_e1704) * _e1697));
                                                }
                                                let _e1709 = phi_1385_;
                                                local_147 = _e1709;
                                                let _e1710 = local_138;
                                                let _e1713 = ((_e1710 >> bitcast<u32>(14u)) & 1023u);
                                                local_148 = _e1713;
                                                if (_e1713 >= 1023u) {
                                                    phi_1396_ = 1f;
                                                } else {
                                                    let _e1715 = local_148;
                                                    phi_1396_ = (f32(_e1715) * 0.0009775171f);
                                                }
                                                let _e1719 = phi_1396_;
                                                local_149 = _e1719;
                                                let _e1720 = local_140;
                                                let _e1721 = bitcast<f32>(_e1720);
                                                local_150 = _e1721;
                                                let _e1722 = local_136;
                                                let _e1725 = ((_e1722 >> bitcast<u32>(28i)) & 3u);
                                                local_151 = _e1725;
                                                let _e1726 = local_142;
                                                let _e1728 = local_142;
                                                let _e1731 = array<u32, 2>((_e1726 & 65535u), (_e1728 >> bitcast<u32>(16i)));
                                                local_152 = _e1731;
                                                let _e1732 = local_147;
                                                let _e1734 = local_50;
                                                let _e1737 = ((_e1734 >> bitcast<u32>(8u)) & 7u);
                                                local_153 = _e1737;
                                                if (_e1737 == 0u) {
                                                    phi_1468_ = type_21(_e1731, _e1732, _e1719, _e1721, _e1725, 0u);
                                                } else {
                                                    let _e1739 = local_153;
                                                    let _e1740 = local_153;
                                                    let _e1741 = (_e1739 * _e1740);
                                                    local_154 = _e1741;
                                                    if (_e1741 <= 1u) {
                                                        phi_1421_ = 1u;
                                                    } else {
                                                        let _e1743 = local_154;
                                                        phi_1421_ = select(16u, 4u, (_e1743 <= 4u));
                                                    }
                                                    let _e1747 = phi_1421_;
                                                    local_155 = _e1747;
                                                    if (_e1747 == 0u) {
                                                        phi_2810_ = true;
                                                        break;
                                                    }
                                                    let _e1749 = local_155;
                                                    local_156 = (32u / _e1749);
                                                    let _e1751 = local_155;
                                                    if (_e1751 >= 32u) {
                                                        phi_1434_ = 4294967295u;
                                                    } else {
                                                        let _e1753 = local_155;
                                                        phi_1434_ = ((1u << bitcast<u32>((_e1753 & 31u))) - 1u);
                                                    }
                                                    let _e1759 = phi_1434_;
                                                    local_157 = _e1759;
                                                    let _e1760 = local_13;
                                                    let _e1762 = local_16;
                                                    let _e1764 = local_131;
                                                    let _e1766 = local_131;
                                                    let _e1768 = local_133;
                                                    local_158 = (4u * ((((_e1762 * _e1760.member_8) * _e1764) * _e1766) * _e1768));
                                                    let _e1771 = local_156;
                                                    let _e1772 = (_e1771 == 0u);
                                                    local_159 = _e1772;
                                                    if _e1772 {
                                                        phi_2810_ = true;
                                                        break;
                                                    }
                                                    let _e1773 = local_134;
                                                    let _e1774 = local_156;
                                                    let _e1776 = local_158;
                                                    local_160 = (_e1776 + (_e1773 / _e1774));
                                                    let _e1778 = local_159;
                                                    if _e1778 {
                                                        phi_2810_ = true;
                                                        break;
                                                    }
                                                    let _e1779 = local_134;
                                                    let _e1780 = local_156;
                                                    let _e1782 = local_155;
                                                    local_161 = ((_e1779 % _e1780) * _e1782);
                                                    let _e1784 = local_160;
                                                    let _e1785 = local_1;
                                                    if (_e1784 < _e1785) {
                                                    } else {
                                                        phi_2810_ = true;
                                                        break;
                                                    }
                                                    let _e1787 = local_160;
                                                    let _e1790 = global_4.member[_e1787];
                                                    let _e1791 = local_161;
                                                    let _e1795 = local_157;
                                                    let _e1797 = local_152;
                                                    let _e1798 = local_147;
                                                    let _e1799 = local_149;
                                                    let _e1800 = local_150;
                                                    let _e1801 = local_151;
                                                    phi_1468_ = type_21(_e1797, _e1798, _e1799, _e1800, _e1801, ((_e1790 >> bitcast<u32>((_e1791 & 31u))) & _e1795));
                                                }
                                                let _e1804 = phi_1468_;
                                                local_162 = _e1804;
                                                if (_e1804.member_5 != 0u) {
                                                    phi_1479_ = 1.4142135f;
                                                } else {
                                                    let _e1807 = local_162;
                                                    phi_1479_ = (0.5f * f32((1u << bitcast<u32>((_e1807.member_4 & 31u)))));
                                                }
                                                let _e1815 = phi_1479_;
                                                local_163 = _e1815;
                                                let _e1816 = local_162;
                                                local_164 = _e1816.member_3;
                                                let _e1818 = bitcast<u32>(_e1816.member_3);
                                                local_165 = _e1818;
                                                if (_e1818 == 2139095040u) {
                                                    let _e1860 = local_13;
                                                    let _e1864 = local_13;
                                                    let _e1868 = local_13;
                                                    let _e1873 = local_13;
                                                    phi_1534_ = (0.5f * ((((2f * _e1860.member_15.member_1) * _e1864.member_15.member) / (_e1868.member_15.member_2 - _e1864.member_15.member)) * _e1873.member_15.member_3));
                                                } else {
                                                    let _e1820 = local_165;
                                                    if (_e1820 == 0u) {
                                                        phi_1503_ = false;
                                                    } else {
                                                        let _e1822 = local_165;
                                                        phi_1503_ = (_e1822 <= 2139095040u);
                                                    }
                                                    let _e1825 = phi_1503_;
                                                    if _e1825 {
                                                        let _e1826 = local_13;
                                                        let _e1830 = local_13;
                                                        let _e1834 = local_13;
                                                        local_166 = _e1834.member_15.member_2;
                                                        let _e1839 = local_13;
                                                        let _e1842 = ((((2f * _e1826.member_15.member_1) * _e1830.member_15.member) / (_e1834.member_15.member_2 - _e1830.member_15.member)) * _e1839.member_15.member_3);
                                                        local_167 = _e1842;
                                                        if (_e1842 == 0f) {
                                                            phi_1525_ = 0f;
                                                        } else {
                                                            let _e1844 = local_166;
                                                            let _e1845 = local_164;
                                                            let _e1848 = local_167;
                                                            phi_1525_ = (_e1848 * (1f - (_e1844 / _e1845)));
                                                        }
                                                        let _e1851 = phi_1525_;
                                                        phi_1526_ = _e1851;
                                                    } else {
                                                        phi_1526_ = bitcast<f32>(_e335);
                                                    }
                                                    let _e1853 = phi_1526_;
                                                    local_168 = _e1853;
                                                    if (_e1853 < 0f) {
                                                        let _e1855 = local_168;
                                                        phi_1532_ = -(_e1855);
                                                    } else {
                                                        phi_1532_ = _e1853;
                                                    }
                                                    let _e1858 = phi_1532_;
                                                    phi_1534_ = (0.5f * _e1858);
                                                }
                                                let _e1879 = phi_1534_;
                                                let _e1884 = local_163;
                                                let _e1885 = (select(_e1879, 0f, ((bitcast<u32>(_e1879) & 2147483647u) > 2139095040u)) + _e1884);
                                                let _e1886 = local_15;
                                                let _e1888 = local_15;
                                                let _e1889 = select(_e1888, _e1885, (_e1885 < _e1886));
                                                let _e1891 = select(0.5f, _e1889, (_e1889 > 0.5f));
                                                local_270 = _e1891;
                                                let _e1892 = local_162;
                                                let _e1896 = (f32(_e1892.member[0]) * 0.5f);
                                                let _e1897 = local_162;
                                                let _e1901 = (f32(_e1897.member[1]) * 0.5f);
                                                let _e1902 = local_13;
                                                let _e1904 = local_11;
                                                let _e1906 = local_131;
                                                let _e1907 = ((_e1904 + 1u) * _e1906);
                                                let _e1910 = local_11;
                                                let _e1911 = local_131;
                                                let _e1915 = local_13;
                                                let _e1917 = local_12;
                                                let _e1919 = local_131;
                                                let _e1920 = ((_e1917 + 1u) * _e1919);
                                                let _e1923 = local_12;
                                                let _e1924 = local_131;
                                                let _e1930 = ((f32((_e1910 * _e1911)) + 0.5f) - _e1896);
                                                let _e1931 = (_e1896 - (f32(select(_e1902.member, _e1907, (_e1907 < _e1902.member))) - 0.5f));
                                                let _e1933 = select(_e1931, _e1930, (_e1930 > _e1931));
                                                let _e1935 = select(0f, _e1933, (_e1933 > 0f));
                                                let _e1938 = ((f32((_e1923 * _e1924)) + 0.5f) - _e1901);
                                                let _e1939 = (_e1901 - (f32(select(_e1915.member_1, _e1920, (_e1920 < _e1915.member_1))) - 0.5f));
                                                let _e1941 = select(_e1939, _e1938, (_e1938 > _e1939));
                                                let _e1943 = select(0f, _e1941, (_e1941 > 0f));
                                                if (((_e1935 * _e1935) + (_e1943 * _e1943)) <= (_e1891 * _e1891)) {
                                                    let _e1949 = local_110;
                                                    let _e1951 = local_129;
                                                    let _e1953 = local_110;
                                                    let _e1955 = local_130;
                                                    local_169 = ((_e1949.member_4 + _e1951) | (_e1953.member_5 + _e1955));
                                                    phi_1631_ = 0u;
                                                    loop {
                                                        let _e1959 = phi_1631_;
                                                        local_170 = _e1959;
                                                        let _e1960 = local_170;
                                                        let _e1961 = local_23;
                                                        if (_e1960 < _e1961) {
                                                            let _e1963 = local_170;
                                                            let _e1964 = (_e1963 + 1u);
                                                            let _e1966 = local_132;
                                                            let _e1971 = local_270;
                                                            let _e1972 = (_e1971 >= f32((2u * (_e1966 << bitcast<u32>((_e1964 & 31u))))));
                                                            phi_1632_ = select(u32(), _e1964, _e1972);
                                                            phi_1652_ = _e1972;
                                                        } else {
                                                            phi_1632_ = u32();
                                                            phi_1652_ = false;
                                                        }
                                                        let _e1975 = phi_1632_;
                                                        let _e1977 = phi_1652_;
                                                        local_171 = _e1977;
                                                        continue;
                                                        continuing {
                                                            let _e1978 = local_171;
                                                            phi_1631_ = _e1975;
                                                            break if !(_e1978);
                                                        }
                                                    }
                                                    let _e1980 = local_170;
                                                    let _e1985 = local_169;
                                                    if ((_e1985 & ((1u << bitcast<u32>((_e1980 & 31u))) - 1u)) == 0u) {
                                                        let _e1988 = local_66;
                                                        let _e1992 = local_65;
                                                        phi_1668_ = (_e1992 | (1u << bitcast<u32>((_e1988 & 31u))));
                                                    } else {
                                                        phi_1668_ = _e740;
                                                    }
                                                    let _e1995 = phi_1668_;
                                                    phi_1669_ = _e1995;
                                                } else {
                                                    phi_1669_ = _e740;
                                                }
                                                let _e1997 = phi_1669_;
                                                let _e1998 = local_66;
                                                phi_1706_ = _e1997;
                                                phi_1707_ = (_e1998 + 1u);
                                            } else {
                                                let _e1616 = local_110;
                                                local_172 = _e1616.member;
                                                if (_e1616.member == 0u) {
                                                    phi_1686_ = 0u;
                                                } else {
                                                    let _e1619 = local_41;
                                                    let _e1620 = local_172;
                                                    let _e1622 = ((_e1619 + _e1620) - 1u);
                                                    local_173 = _e1622;
                                                    if (_e1622 < 1792u) {
                                                    } else {
                                                        phi_2810_ = true;
                                                        break;
                                                    }
                                                    let _e1624 = local_173;
                                                    let _e1626 = global_8[_e1624];
                                                    phi_1686_ = _e1626;
                                                }
                                                let _e1628 = phi_1686_;
                                                local_174 = _e1628;
                                                let _e1629 = local_41;
                                                let _e1630 = local_172;
                                                let _e1631 = (_e1629 + _e1630);
                                                local_175 = _e1631;
                                                if (_e1631 < 1792u) {
                                                } else {
                                                    phi_2810_ = true;
                                                    break;
                                                }
                                                let _e1633 = local_175;
                                                let _e1635 = global_8[_e1633];
                                                let _e1636 = local_174;
                                                let _e1638 = local_111;
                                                if (_e1638 < (_e1635 - _e1636)) {
                                                    let _e1640 = local_174;
                                                    let _e1641 = local_111;
                                                    phi_1704_ = (_e1640 + _e1641);
                                                } else {
                                                    phi_1704_ = _e1635;
                                                }
                                                let _e1644 = phi_1704_;
                                                let _e1645 = local_56;
                                                phi_1706_ = _e740;
                                                phi_1707_ = (_e1644 - _e1645);
                                            }
                                            let _e2001 = phi_1706_;
                                            let _e2003 = phi_1707_;
                                            phi_2812_ = _e1580;
                                            phi_1708_ = _e2001;
                                            let _e3018 = local_276;
                                            phi_1709_ = _e3018;
                                            phi_1710_ = _e2003;
                                        } else {
                                            phi_2812_ = _e738;
                                            phi_1708_ = u32();
                                            phi_1709_ = type_24();
                                            phi_1710_ = u32();
                                        }
                                        let _e2005 = phi_2812_;
                                        let _e2007 = phi_1708_;
                                        let _e2009 = phi_1709_;
                                        let _e2011 = phi_1710_;
                                        phi_2811_ = _e2005;
                                        phi_688_ = _e2007;
                                        phi_691_ = _e2009;
                                        phi_693_ = _e2011;
                                        phi_1711_ = _e752;
                                    } else {
                                        phi_2811_ = _e738;
                                        phi_688_ = u32();
                                        phi_691_ = type_24();
                                        phi_693_ = u32();
                                        phi_1711_ = false;
                                    }
                                    let _e2013 = phi_2811_;
                                    let _e2015 = phi_688_;
                                    let _e2017 = phi_691_;
                                    let _e2019 = phi_693_;
                                    let _e2021 = phi_1711_;
                                    local_176 = _e2021;
                                    continue;
                                    continuing {
                                        let _e2022 = local_176;
                                        phi_2764_ = _e2013;
                                        phi_687_ = _e2015;
                                        phi_690_ = _e2017;
                                        phi_692_ = _e2019;
                                        phi_2810_ = _e2013;
                                        break if !(_e2022);
                                    }
                                }
                                let _e2025 = phi_2810_;
                                phi_2926_ = _e2025;
                                if _e2025 {
                                    break;
                                }
                                phi_2845_ = _e2025;
                                let _e3029 = local_277;
                                phi_1716_ = _e3029;
                            } else {
                                phi_2845_ = _e648;
                                phi_1716_ = _e695;
                            }
                            let _e2027 = phi_2845_;
                            let _e2029 = phi_1716_;
                            local_177 = _e2029;
                            local_178 = countOneBits(_e2029);
                            let _e2031 = local;
                            if (_e2031 < 1792u) {
                            } else {
                                phi_2926_ = true;
                                break;
                            }
                            let _e2033 = local;
                            let _e2035 = local_178;
                            global_8[_e2033] = _e2035;
                            let _e2036 = local;
                            let _e2037 = (512u + _e2036);
                            local_179 = _e2037;
                            let _e2038 = (_e2037 < 1792u);
                            local_180 = _e2038;
                            if _e2038 {
                            } else {
                                phi_2926_ = true;
                                break;
                            }
                            let _e2039 = local_179;
                            let _e2041 = local_177;
                            global_8[_e2039] = _e2041;
                            storageBarrier();
                            workgroupBarrier();
                            phi_1871_ = 1u;
                            phi_1874_ = 0u;
                            loop {
                                let _e2043 = phi_1871_;
                                let _e2045 = phi_1874_;
                                local_181 = _e2043;
                                local_182 = _e2045;
                                let _e2046 = local_181;
                                let _e2047 = (_e2046 < 256u);
                                local_183 = _e2047;
                                if _e2047 {
                                    let _e2048 = local_182;
                                    let _e2050 = select(0u, 256u, (_e2048 == 0u));
                                    local_271 = _e2050;
                                    let _e2051 = local_182;
                                    let _e2052 = local;
                                    let _e2053 = (_e2051 + _e2052);
                                    local_184 = _e2053;
                                    if (_e2053 < 1792u) {
                                    } else {
                                        phi_2842_ = true;
                                        break;
                                    }
                                    let _e2055 = local_184;
                                    let _e2057 = global_8[_e2055];
                                    local_185 = _e2057;
                                    let _e2058 = local;
                                    let _e2059 = local_181;
                                    if (_e2058 >= _e2059) {
                                        let _e2061 = local;
                                        let _e2062 = local_181;
                                        let _e2064 = local_182;
                                        let _e2065 = (_e2064 + (_e2061 - _e2062));
                                        local_186 = _e2065;
                                        if (_e2065 < 1792u) {
                                        } else {
                                            phi_2842_ = true;
                                            break;
                                        }
                                        let _e2067 = local_186;
                                        let _e2069 = global_8[_e2067];
                                        let _e2070 = local_185;
                                        phi_1910_ = (_e2069 + _e2070);
                                    } else {
                                        phi_1910_ = _e2057;
                                    }
                                    let _e2073 = phi_1910_;
                                    local_187 = _e2073;
                                    let _e2074 = local_271;
                                    let _e2075 = local;
                                    let _e2076 = (_e2074 + _e2075);
                                    local_188 = _e2076;
                                    if (_e2076 < 1792u) {
                                    } else {
                                        phi_2842_ = true;
                                        break;
                                    }
                                    let _e2078 = local_188;
                                    let _e2080 = local_187;
                                    global_8[_e2078] = _e2080;
                                    storageBarrier();
                                    workgroupBarrier();
                                    let _e2081 = local_181;
                                    phi_1872_ = (_e2081 * 2u);
                                    phi_1875_ = _e2050;
                                } else {
                                    phi_1872_ = u32();
                                    phi_1875_ = u32();
                                }
                                let _e2084 = phi_1872_;
                                let _e2086 = phi_1875_;
                                continue;
                                continuing {
                                    let _e2087 = local_183;
                                    phi_1871_ = _e2084;
                                    phi_1874_ = _e2086;
                                    phi_2842_ = _e2027;
                                    break if !(_e2087);
                                }
                            }
                            let _e2090 = phi_2842_;
                            phi_2926_ = _e2090;
                            if _e2090 {
                                break;
                            }
                            let _e2091 = local_20;
                            let _e2092 = local_54;
                            local_189 = (_e2091 + _e2092);
                            let _e2094 = local;
                            if (_e2094 == 0u) {
                                phi_1940_ = 0u;
                            } else {
                                let _e2096 = local_182;
                                let _e2097 = local;
                                let _e2099 = ((_e2096 + _e2097) - 1u);
                                local_190 = _e2099;
                                if (_e2099 < 1792u) {
                                } else {
                                    phi_2926_ = true;
                                    break;
                                }
                                let _e2101 = local_190;
                                let _e2103 = global_8[_e2101];
                                phi_1940_ = _e2103;
                            }
                            let _e2105 = phi_1940_;
                            let _e2106 = local_189;
                            let _e2108 = local_180;
                            if _e2108 {
                            } else {
                                phi_2926_ = true;
                                break;
                            }
                            let _e2109 = global_8[_e2039];
                            local_191 = _e2109;
                            if (_e2109 == 0u) {
                                phi_2877_ = _e2090;
                                phi_1985_ = 0u;
                            } else {
                                phi_1957_ = 255u;
                                phi_1960_ = 0u;
                                loop {
                                    let _e2112 = phi_1957_;
                                    let _e2114 = phi_1960_;
                                    local_192 = _e2112;
                                    local_193 = _e2114;
                                    local_278 = _e2114;
                                    let _e2115 = local_193;
                                    let _e2116 = local_192;
                                    let _e2117 = (_e2115 < _e2116);
                                    local_194 = _e2117;
                                    if _e2117 {
                                        let _e2118 = local_193;
                                        let _e2119 = local_192;
                                        let _e2121 = ((_e2118 + _e2119) / 2u);
                                        local_195 = _e2121;
                                        let _e2122 = local_41;
                                        let _e2123 = (_e2122 + _e2121);
                                        local_196 = _e2123;
                                        if (_e2123 < 1792u) {
                                        } else {
                                            phi_2867_ = true;
                                            break;
                                        }
                                        let _e2125 = local_196;
                                        let _e2127 = global_8[_e2125];
                                        let _e2128 = local_56;
                                        let _e2129 = (_e2127 > _e2128);
                                        local_197 = _e2129;
                                        if _e2129 {
                                            phi_1984_ = _e2114;
                                        } else {
                                            let _e2130 = local_195;
                                            phi_1984_ = (_e2130 + 1u);
                                        }
                                        let _e2133 = phi_1984_;
                                        let _e2134 = local_197;
                                        let _e2135 = local_195;
                                        let _e2136 = local_192;
                                        phi_1958_ = select(_e2136, _e2135, _e2134);
                                        phi_1961_ = _e2133;
                                    } else {
                                        phi_1958_ = u32();
                                        phi_1961_ = u32();
                                    }
                                    let _e2139 = phi_1958_;
                                    let _e2141 = phi_1961_;
                                    continue;
                                    continuing {
                                        let _e2142 = local_194;
                                        phi_1957_ = _e2139;
                                        phi_1960_ = _e2141;
                                        phi_2867_ = _e2090;
                                        break if !(_e2142);
                                    }
                                }
                                let _e2145 = phi_2867_;
                                phi_2926_ = _e2145;
                                if _e2145 {
                                    break;
                                }
                                phi_2877_ = _e2145;
                                let _e3046 = local_278;
                                phi_1985_ = _e3046;
                            }
                            let _e2147 = phi_2877_;
                            let _e2149 = phi_1985_;
                            let _e2150 = local_11;
                            let _e2151 = local_12;
                            phi_2876_ = _e2147;
                            phi_1988_ = type_24(_e2149, 4294967295u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, _e2150, _e2151, false);
                            phi_1991_ = 0u;
                            phi_1993_ = (_e2106 + _e2105);
                            loop {
                                let _e2154 = phi_2876_;
                                let _e2156 = phi_1988_;
                                let _e2158 = phi_1991_;
                                let _e2160 = phi_1993_;
                                local_198 = _e2158;
                                local_199 = _e2160;
                                let _e2161 = local_198;
                                let _e2162 = local_266;
                                let _e2163 = (_e2161 < _e2162);
                                local_200 = _e2163;
                                if _e2163 {
                                    let _e2164 = local_198;
                                    let _e2168 = local_191;
                                    if ((_e2168 & (1u << bitcast<u32>((_e2164 & 31u)))) == 0u) {
                                        phi_2925_ = _e2154;
                                        phi_2651_ = _e2156;
                                        phi_2652_ = _e2160;
                                    } else {
                                        let _e2171 = local_56;
                                        let _e2172 = local_198;
                                        local_201 = (_e2171 + _e2172);
                                        phi_2010_ = _e2156;
                                        loop {
                                            let _e2175 = phi_2010_;
                                            local_202 = _e2175;
                                            local_279 = _e2175;
                                            let _e2176 = local_202;
                                            local_203 = _e2176.member;
                                            if (_e2176.member < 255u) {
                                                let _e2179 = local_41;
                                                let _e2180 = local_203;
                                                let _e2181 = (_e2179 + _e2180);
                                                local_204 = _e2181;
                                                if (_e2181 < 1792u) {
                                                } else {
                                                    phi_2873_ = true;
                                                    break;
                                                }
                                                let _e2183 = local_204;
                                                let _e2185 = global_8[_e2183];
                                                let _e2186 = local_201;
                                                let _e2187 = (_e2185 <= _e2186);
                                                if _e2187 {
                                                    let _e2188 = local_203;
                                                    let _e2190 = local_202;
                                                    phi_2036_ = type_24((_e2188 + 1u), _e2190.member_1, _e2190.member_2, _e2190.member_3, _e2190.member_4, _e2190.member_5, _e2190.member_6, _e2190.member_7, _e2190.member_8, _e2190.member_9, _e2190.member_10, _e2190.member_11, _e2190.member_12, _e2190.member_13, _e2190.member_14);
                                                } else {
                                                    phi_2036_ = type_24();
                                                }
                                                let _e2208 = phi_2036_;
                                                phi_2011_ = _e2208;
                                                phi_2037_ = _e2187;
                                            } else {
                                                phi_2011_ = type_24();
                                                phi_2037_ = false;
                                            }
                                            let _e2210 = phi_2011_;
                                            let _e2212 = phi_2037_;
                                            local_205 = _e2212;
                                            continue;
                                            continuing {
                                                let _e2213 = local_205;
                                                phi_2010_ = _e2210;
                                                phi_2873_ = _e2154;
                                                break if !(_e2213);
                                            }
                                        }
                                        let _e2216 = phi_2873_;
                                        phi_2923_ = _e2216;
                                        if _e2216 {
                                            break;
                                        }
                                        let _e2217 = local_203;
                                        if (_e2217 == 0u) {
                                            phi_2057_ = 0u;
                                        } else {
                                            let _e2219 = local_41;
                                            let _e2220 = local_203;
                                            let _e2222 = ((_e2219 + _e2220) - 1u);
                                            local_206 = _e2222;
                                            if (_e2222 < 1792u) {
                                            } else {
                                                phi_2923_ = true;
                                                break;
                                            }
                                            let _e2224 = local_206;
                                            let _e2226 = global_8[_e2224];
                                            phi_2057_ = _e2226;
                                        }
                                        let _e2228 = phi_2057_;
                                        let _e2229 = local_201;
                                        local_207 = (_e2229 - _e2228);
                                        let _e2231 = local_202;
                                        let _e2233 = local_203;
                                        if (_e2231.member_1 != _e2233) {
                                            let _e2235 = local_13;
                                            local_208 = _e2235.member_6;
                                            let _e2237 = local_13;
                                            local_209 = _e2237.member_3;
                                            if (_e2237.member_3 == 0u) {
                                                phi_2923_ = true;
                                                break;
                                            }
                                            let _e2240 = local_208;
                                            let _e2241 = local_209;
                                            local_210 = (_e2240 / _e2241);
                                            let _e2243 = local_203;
                                            let _e2244 = (1280u + _e2243);
                                            local_211 = _e2244;
                                            if (_e2244 < 1792u) {
                                            } else {
                                                phi_2923_ = true;
                                                break;
                                            }
                                            let _e2246 = local_211;
                                            let _e2248 = global_8[_e2246];
                                            local_212 = _e2248;
                                            let _e2249 = local_16;
                                            let _e2250 = (_e2249 == 0u);
                                            local_213 = _e2250;
                                            if _e2250 {
                                                phi_2923_ = true;
                                                break;
                                            }
                                            let _e2251 = local_212;
                                            let _e2252 = local_16;
                                            let _e2254 = local_210;
                                            local_214 = ((_e2251 % _e2252) * _e2254);
                                            let _e2256 = local_213;
                                            if _e2256 {
                                                phi_2923_ = true;
                                                break;
                                            }
                                            let _e2257 = local_212;
                                            let _e2258 = local_16;
                                            let _e2260 = local_210;
                                            let _e2261 = ((_e2257 / _e2258) * _e2260);
                                            let _e2262 = local_203;
                                            let _e2263 = local_202;
                                            let _e2279 = type_24(_e2263.member, _e2262, _e2263.member_2, _e2263.member_3, _e2263.member_4, _e2263.member_5, _e2263.member_6, _e2263.member_7, _e2263.member_8, _e2263.member_9, _e2263.member_10, _e2263.member_11, _e2263.member_12, _e2263.member_13, _e2263.member_14);
                                            let _e2280 = local_212;
                                            let _e2296 = type_24(_e2279.member, _e2279.member_1, _e2280, _e2279.member_3, _e2279.member_4, _e2279.member_5, _e2279.member_6, _e2279.member_7, _e2279.member_8, _e2279.member_9, _e2279.member_10, _e2279.member_11, _e2279.member_12, _e2279.member_13, _e2279.member_14);
                                            let _e2297 = local_13;
                                            local_215 = _e2297.member_4;
                                            let _e2300 = local_214;
                                            let _e2301 = ((_e2261 * _e2297.member_4) + _e2300);
                                            local_216 = _e2301;
                                            let _e2317 = type_24(_e2296.member, _e2296.member_1, _e2296.member_2, _e2301, _e2296.member_4, _e2296.member_5, _e2296.member_6, _e2296.member_7, _e2296.member_8, _e2296.member_9, _e2296.member_10, _e2296.member_11, _e2296.member_12, _e2296.member_13, _e2296.member_14);
                                            let _e2318 = local_214;
                                            let _e2334 = type_24(_e2317.member, _e2317.member_1, _e2317.member_2, _e2317.member_3, _e2318, _e2317.member_5, _e2317.member_6, _e2317.member_7, _e2317.member_8, _e2317.member_9, _e2317.member_10, _e2317.member_11, _e2317.member_12, _e2317.member_13, _e2317.member_14);
                                            let _e2350 = type_24(_e2334.member, _e2334.member_1, _e2334.member_2, _e2334.member_3, _e2334.member_4, _e2261, _e2334.member_6, _e2334.member_7, _e2334.member_8, _e2334.member_9, _e2334.member_10, _e2334.member_11, _e2334.member_12, _e2334.member_13, _e2334.member_14);
                                            let _e2351 = local_214;
                                            let _e2352 = (_e2297.member_4 - _e2351);
                                            let _e2353 = local_210;
                                            let _e2355 = local_210;
                                            let _e2356 = select(_e2355, _e2352, (_e2352 < _e2353));
                                            local_272 = _e2356;
                                            let _e2372 = type_24(_e2350.member, _e2350.member_1, _e2350.member_2, _e2350.member_3, _e2350.member_4, _e2350.member_5, _e2356, _e2350.member_7, _e2350.member_8, _e2350.member_9, _e2350.member_10, _e2350.member_11, _e2350.member_12, _e2350.member_13, _e2350.member_14);
                                            let _e2373 = local_13;
                                            local_217 = _e2373.member_5;
                                            let _e2375 = (_e2373.member_5 - _e2261);
                                            let _e2376 = local_210;
                                            let _e2378 = local_210;
                                            let _e2379 = select(_e2378, _e2375, (_e2375 < _e2376));
                                            local_273 = _e2379;
                                            local_218 = type_24(_e2372.member, _e2372.member_1, _e2372.member_2, _e2372.member_3, _e2372.member_4, _e2372.member_5, _e2372.member_6, _e2379, _e2372.member_8, _e2372.member_9, _e2372.member_10, _e2372.member_11, _e2372.member_12, _e2372.member_13, _e2372.member_14);
                                            phi_2126_ = (_e2379 - 1u);
                                            phi_2129_ = 0u;
                                            loop {
                                                let _e2398 = phi_2126_;
                                                let _e2400 = phi_2129_;
                                                local_219 = _e2398;
                                                local_220 = _e2400;
                                                let _e2401 = local_220;
                                                let _e2402 = local_219;
                                                let _e2403 = (_e2401 < _e2402);
                                                local_221 = _e2403;
                                                if _e2403 {
                                                    let _e2404 = local_220;
                                                    let _e2405 = local_219;
                                                    let _e2406 = (_e2404 + _e2405);
                                                    let _e2407 = (_e2406 / 2u);
                                                    local_222 = _e2407;
                                                    if ((_e2406 % 2u) > 0u) {
                                                        let _e2410 = local_222;
                                                        phi_2153_ = (_e2410 + 1u);
                                                    } else {
                                                        phi_2153_ = _e2407;
                                                    }
                                                    let _e2413 = phi_2153_;
                                                    local_223 = _e2413;
                                                    let _e2414 = local_273;
                                                    if (_e2413 < _e2414) {
                                                        let _e2416 = local_223;
                                                        let _e2417 = local_215;
                                                        let _e2419 = local_216;
                                                        let _e2420 = (_e2419 + (_e2416 * _e2417));
                                                        local_224 = _e2420;
                                                        let _e2421 = local_3;
                                                        if (_e2420 < _e2421) {
                                                        } else {
                                                            phi_2879_ = true;
                                                            break;
                                                        }
                                                        let _e2423 = local_224;
                                                        let _e2426 = global_6.member[_e2423];
                                                        phi_2169_ = _e2426;
                                                    } else {
                                                        phi_2169_ = 4294967295u;
                                                    }
                                                    let _e2428 = phi_2169_;
                                                    let _e2429 = local_207;
                                                    let _e2430 = (_e2428 <= _e2429);
                                                    local_225 = _e2430;
                                                    if _e2430 {
                                                        phi_2175_ = _e2398;
                                                    } else {
                                                        let _e2431 = local_223;
                                                        phi_2175_ = (_e2431 - 1u);
                                                    }
                                                    let _e2434 = phi_2175_;
                                                    let _e2435 = local_225;
                                                    let _e2436 = local_223;
                                                    let _e2437 = local_220;
                                                    phi_2127_ = _e2434;
                                                    phi_2130_ = select(_e2437, _e2436, _e2435);
                                                } else {
                                                    phi_2127_ = u32();
                                                    phi_2130_ = u32();
                                                }
                                                let _e2440 = phi_2127_;
                                                let _e2442 = phi_2130_;
                                                continue;
                                                continuing {
                                                    let _e2443 = local_221;
                                                    phi_2126_ = _e2440;
                                                    phi_2129_ = _e2442;
                                                    phi_2879_ = _e2216;
                                                    break if !(_e2443);
                                                }
                                            }
                                            let _e2446 = phi_2879_;
                                            phi_2923_ = _e2446;
                                            if _e2446 {
                                                break;
                                            }
                                            let _e2447 = local_272;
                                            phi_2179_ = (_e2447 - 1u);
                                            phi_2182_ = 0u;
                                            loop {
                                                let _e2450 = phi_2179_;
                                                let _e2452 = phi_2182_;
                                                local_226 = _e2450;
                                                local_227 = _e2452;
                                                let _e2453 = local_227;
                                                let _e2454 = local_226;
                                                let _e2455 = (_e2453 < _e2454);
                                                local_228 = _e2455;
                                                if _e2455 {
                                                    let _e2456 = local_227;
                                                    let _e2457 = local_226;
                                                    let _e2458 = (_e2456 + _e2457);
                                                    let _e2459 = (_e2458 / 2u);
                                                    local_229 = _e2459;
                                                    if ((_e2458 % 2u) > 0u) {
                                                        let _e2462 = local_229;
                                                        phi_2206_ = (_e2462 + 1u);
                                                    } else {
                                                        phi_2206_ = _e2459;
                                                    }
                                                    let _e2465 = phi_2206_;
                                                    local_230 = _e2465;
                                                    let _e2466 = local_220;
                                                    let _e2467 = local_273;
                                                    if (_e2466 < _e2467) {
                                                        let _e2469 = local_220;
                                                        let _e2470 = local_215;
                                                        let _e2472 = local_216;
                                                        let _e2474 = local_230;
                                                        let _e2475 = ((_e2472 + (_e2469 * _e2470)) + _e2474);
                                                        local_231 = _e2475;
                                                        let _e2476 = local_3;
                                                        if (_e2475 < _e2476) {
                                                        } else {
                                                            phi_2888_ = true;
                                                            break;
                                                        }
                                                        let _e2478 = local_231;
                                                        let _e2481 = global_6.member[_e2478];
                                                        phi_2222_ = _e2481;
                                                    } else {
                                                        phi_2222_ = 4294967295u;
                                                    }
                                                    let _e2483 = phi_2222_;
                                                    let _e2484 = local_207;
                                                    let _e2485 = (_e2483 <= _e2484);
                                                    local_232 = _e2485;
                                                    if _e2485 {
                                                        phi_2228_ = _e2450;
                                                    } else {
                                                        let _e2486 = local_230;
                                                        phi_2228_ = (_e2486 - 1u);
                                                    }
                                                    let _e2489 = phi_2228_;
                                                    let _e2490 = local_232;
                                                    let _e2491 = local_230;
                                                    let _e2492 = local_227;
                                                    phi_2180_ = _e2489;
                                                    phi_2183_ = select(_e2492, _e2491, _e2490);
                                                } else {
                                                    phi_2180_ = u32();
                                                    phi_2183_ = u32();
                                                }
                                                let _e2495 = phi_2180_;
                                                let _e2497 = phi_2183_;
                                                continue;
                                                continuing {
                                                    let _e2498 = local_228;
                                                    phi_2179_ = _e2495;
                                                    phi_2182_ = _e2497;
                                                    phi_2888_ = _e2446;
                                                    break if !(_e2498);
                                                }
                                            }
                                            let _e2501 = phi_2888_;
                                            phi_2923_ = _e2501;
                                            if _e2501 {
                                                break;
                                            }
                                            let _e2502 = local_227;
                                            let _e2503 = local_218;
                                            let _e2519 = type_24(_e2503.member, _e2503.member_1, _e2503.member_2, _e2503.member_3, _e2503.member_4, _e2503.member_5, _e2503.member_6, _e2503.member_7, _e2502, _e2503.member_9, _e2503.member_10, _e2503.member_11, _e2503.member_12, _e2503.member_13, _e2503.member_14);
                                            let _e2520 = local_220;
                                            local_233 = type_24(_e2519.member, _e2519.member_1, _e2519.member_2, _e2519.member_3, _e2519.member_4, _e2519.member_5, _e2519.member_6, _e2519.member_7, _e2519.member_8, _e2520, _e2519.member_10, _e2519.member_11, _e2519.member_12, _e2519.member_13, _e2519.member_14);
                                            let _e2537 = local_220;
                                            let _e2538 = local_273;
                                            let _e2539 = (_e2537 < _e2538);
                                            local_234 = _e2539;
                                            if _e2539 {
                                                let _e2540 = local_220;
                                                let _e2541 = local_215;
                                                let _e2543 = local_216;
                                                let _e2545 = local_227;
                                                let _e2546 = ((_e2543 + (_e2540 * _e2541)) + _e2545);
                                                local_235 = _e2546;
                                                let _e2547 = local_3;
                                                if (_e2546 < _e2547) {
                                                } else {
                                                    phi_2923_ = true;
                                                    break;
                                                }
                                                let _e2549 = local_235;
                                                let _e2552 = global_6.member[_e2549];
                                                phi_2247_ = _e2552;
                                            } else {
                                                phi_2247_ = 4294967295u;
                                            }
                                            let _e2554 = phi_2247_;
                                            let _e2555 = local_233;
                                            local_236 = type_24(_e2555.member, _e2555.member_1, _e2555.member_2, _e2555.member_3, _e2555.member_4, _e2555.member_5, _e2555.member_6, _e2555.member_7, _e2555.member_8, _e2555.member_9, _e2554, _e2555.member_11, _e2555.member_12, _e2555.member_13, _e2555.member_14);
                                            let _e2572 = local_227;
                                            let _e2573 = (_e2572 + 1u);
                                            local_237 = _e2573;
                                            let _e2574 = local_272;
                                            if (_e2573 < _e2574) {
                                                let _e2593 = local_234;
                                                if _e2593 {
                                                    let _e2594 = local_220;
                                                    let _e2595 = local_215;
                                                    let _e2597 = local_216;
                                                    let _e2599 = local_237;
                                                    let _e2600 = ((_e2597 + (_e2594 * _e2595)) + _e2599);
                                                    local_238 = _e2600;
                                                    let _e2601 = local_3;
                                                    if (_e2600 < _e2601) {
                                                    } else {
                                                        phi_2923_ = true;
                                                        break;
                                                    }
                                                    let _e2603 = local_238;
                                                    let _e2606 = global_6.member[_e2603];
                                                    phi_2270_ = _e2606;
                                                } else {
                                                    phi_2270_ = 4294967295u;
                                                }
                                                let _e2608 = phi_2270_;
                                                phi_2288_ = _e2608;
                                            } else {
                                                let _e2576 = local_220;
                                                let _e2577 = (_e2576 + 1u);
                                                local_239 = _e2577;
                                                let _e2578 = local_273;
                                                if (_e2577 < _e2578) {
                                                    let _e2580 = local_239;
                                                    let _e2581 = local_215;
                                                    let _e2583 = local_216;
                                                    let _e2584 = (_e2583 + (_e2580 * _e2581));
                                                    local_240 = _e2584;
                                                    let _e2585 = local_3;
                                                    if (_e2584 < _e2585) {
                                                    } else {
                                                        phi_2923_ = true;
                                                        break;
                                                    }
                                                    let _e2587 = local_240;
                                                    let _e2590 = global_6.member[_e2587];
                                                    phi_2287_ = _e2590;
                                                } else {
                                                    phi_2287_ = 4294967295u;
                                                }
                                                let _e2592 = phi_2287_;
                                                phi_2288_ = _e2592;
                                            }
                                            let _e2610 = phi_2288_;
                                            let _e2611 = local_236;
                                            let _e2628 = local_215;
                                            let _e2629 = local_217;
                                            let _e2631 = local_220;
                                            let _e2632 = local_215;
                                            let _e2634 = local_216;
                                            let _e2636 = local_227;
                                            let _e2639 = local_3;
                                            if (((_e2628 * _e2629) + ((_e2634 + (_e2631 * _e2632)) + _e2636)) < _e2639) {
                                            } else {
                                                phi_2923_ = true;
                                                break;
                                            }
                                            phi_2897_ = _e2501;
                                            phi_2400_ = type_24(_e2611.member, _e2611.member_1, _e2611.member_2, _e2611.member_3, _e2611.member_4, _e2611.member_5, _e2611.member_6, _e2611.member_7, _e2611.member_8, _e2611.member_9, _e2611.member_10, _e2610, _e2611.member_12, _e2611.member_13, _e2611.member_14);
                                        } else {
                                            phi_2897_ = _e2216;
                                            let _e3080 = local_279;
                                            phi_2400_ = _e3080;
                                        }
                                        let _e2642 = phi_2897_;
                                        let _e2644 = phi_2400_;
                                        phi_2402_ = _e2644;
                                        loop {
                                            let _e2646 = phi_2402_;
                                            local_241 = _e2646;
                                            local_280 = _e2646;
                                            let _e2647 = local_241;
                                            let _e2649 = local_207;
                                            let _e2650 = (_e2647.member_11 <= _e2649);
                                            local_242 = _e2650;
                                            if _e2650 {
                                                let _e2651 = local_241;
                                                let _e2653 = (_e2651.member_8 + 1u);
                                                local_243 = _e2653;
                                                let _e2654 = local_241;
                                                local_244 = _e2654.member_6;
                                                let _e2656 = (_e2653 < _e2654.member_6);
                                                local_245 = _e2656;
                                                if _e2656 {
                                                    let _e2660 = local_241;
                                                    phi_2424_ = _e2660.member_9;
                                                } else {
                                                    let _e2657 = local_241;
                                                    phi_2424_ = (_e2657.member_9 + 1u);
                                                }
                                                let _e2663 = phi_2424_;
                                                local_246 = _e2663;
                                                let _e2664 = local_245;
                                                let _e2665 = local_243;
                                                let _e2666 = select(0u, _e2665, _e2664);
                                                local_274 = _e2666;
                                                let _e2667 = local_241;
                                                let _e2683 = type_24(_e2667.member, _e2667.member_1, _e2667.member_2, _e2667.member_3, _e2667.member_4, _e2667.member_5, _e2667.member_6, _e2667.member_7, _e2666, _e2667.member_9, _e2667.member_10, _e2667.member_11, _e2667.member_12, _e2667.member_13, _e2667.member_14);
                                                local_247 = type_24(_e2683.member, _e2683.member_1, _e2683.member_2, _e2683.member_3, _e2683.member_4, _e2683.member_5, _e2683.member_6, _e2683.member_7, _e2683.member_8, _e2663, _e2683.member_10, _e2683.member_11, _e2683.member_12, _e2683.member_13, _e2683.member_14);
                                                let _e2700 = local_241;
                                                local_248 = _e2700.member_7;
                                                let _e2702 = (_e2663 < _e2700.member_7);
                                                local_249 = _e2702;
                                                if _e2702 {
                                                    let _e2703 = local_241;
                                                    let _e2705 = local_13;
                                                    let _e2707 = local_246;
                                                    let _e2710 = local_274;
                                                    let _e2711 = ((_e2703.member_3 + (_e2707 * _e2705.member_4)) + _e2710);
                                                    local_250 = _e2711;
                                                    let _e2712 = local_3;
                                                    if (_e2711 < _e2712) {
                                                    } else {
                                                        phi_2894_ = true;
                                                        break;
                                                    }
                                                    let _e2714 = local_250;
                                                    let _e2717 = global_6.member[_e2714];
                                                    phi_2445_ = _e2717;
                                                } else {
                                                    phi_2445_ = 4294967295u;
                                                }
                                                let _e2719 = phi_2445_;
                                                let _e2720 = local_247;
                                                local_251 = type_24(_e2720.member, _e2720.member_1, _e2720.member_2, _e2720.member_3, _e2720.member_4, _e2720.member_5, _e2720.member_6, _e2720.member_7, _e2720.member_8, _e2720.member_9, _e2719, _e2720.member_11, _e2720.member_12, _e2720.member_13, _e2720.member_14);
                                                let _e2737 = local_274;
                                                let _e2738 = (_e2737 + 1u);
                                                local_252 = _e2738;
                                                let _e2739 = local_244;
                                                if (_e2738 < _e2739) {
                                                    let _e2760 = local_249;
                                                    if _e2760 {
                                                        let _e2761 = local_241;
                                                        let _e2763 = local_13;
                                                        let _e2765 = local_246;
                                                        let _e2768 = local_252;
                                                        let _e2769 = ((_e2761.member_3 + (_e2765 * _e2763.member_4)) + _e2768);
                                                        local_253 = _e2769;
                                                        let _e2770 = local_3;
                                                        if (_e2769 < _e2770) {
                                                        } else {
                                                            phi_2894_ = true;
                                                            break;
                                                        }
                                                        let _e2772 = local_253;
                                                        let _e2775 = global_6.member[_e2772];
                                                        phi_2471_ = _e2775;
                                                    } else {
                                                        phi_2471_ = 4294967295u;
                                                    }
                                                    let _e2777 = phi_2471_;
                                                    phi_2491_ = _e2777;
                                                } else {
                                                    let _e2741 = local_246;
                                                    let _e2742 = (_e2741 + 1u);
                                                    local_254 = _e2742;
                                                    let _e2743 = local_248;
                                                    if (_e2742 < _e2743) {
                                                        let _e2745 = local_241;
                                                        let _e2747 = local_13;
                                                        let _e2749 = local_254;
                                                        let _e2751 = (_e2745.member_3 + (_e2749 * _e2747.member_4));
                                                        local_255 = _e2751;
                                                        let _e2752 = local_3;
                                                        if (_e2751 < _e2752) {
                                                        } else {
                                                            phi_2894_ = true;
                                                            break;
                                                        }
                                                        let _e2754 = local_255;
                                                        let _e2757 = global_6.member[_e2754];
                                                        phi_2490_ = _e2757;
                                                    } else {
                                                        phi_2490_ = 4294967295u;
                                                    }
                                                    let _e2759 = phi_2490_;
                                                    phi_2491_ = _e2759;
                                                }
                                                let _e2779 = phi_2491_;
                                                let _e2780 = local_251;
                                                let _e2797 = local_13;
                                                let _e2799 = local_13;
                                                let _e2802 = local_241;
                                                let _e2804 = local_246;
                                                let _e2807 = local_274;
                                                let _e2810 = local_3;
                                                if (((_e2797.member_4 * _e2799.member_5) + ((_e2802.member_3 + (_e2804 * _e2797.member_4)) + _e2807)) < _e2810) {
                                                } else {
                                                    phi_2894_ = true;
                                                    break;
                                                }
                                                phi_2403_ = type_24(_e2780.member, _e2780.member_1, _e2780.member_2, _e2780.member_3, _e2780.member_4, _e2780.member_5, _e2780.member_6, _e2780.member_7, _e2780.member_8, _e2780.member_9, _e2780.member_10, _e2779, _e2780.member_12, _e2780.member_13, _e2780.member_14);
                                            } else {
                                                phi_2403_ = type_24();
                                            }
                                            let _e2813 = phi_2403_;
                                            continue;
                                            continuing {
                                                let _e2814 = local_242;
                                                phi_2402_ = _e2813;
                                                phi_2894_ = _e2642;
                                                break if !(_e2814);
                                            }
                                        }
                                        let _e2817 = phi_2894_;
                                        phi_2923_ = _e2817;
                                        if _e2817 {
                                            break;
                                        }
                                        let _e2818 = local_241;
                                        local_256 = _e2818.member_2;
                                        let _e2820 = local_241;
                                        local_257 = _e2820.member_8;
                                        let _e2822 = local_241;
                                        local_258 = _e2822.member_9;
                                        let _e2824 = local_13;
                                        local_259 = _e2824.member_6;
                                        let _e2826 = local_13;
                                        local_260 = _e2826.member_3;
                                        if (_e2826.member_3 == 0u) {
                                            phi_2923_ = true;
                                            break;
                                        }
                                        let _e2829 = local_259;
                                        let _e2830 = local_260;
                                        let _e2831 = (_e2829 / _e2830);
                                        let _e2832 = local_256;
                                        let _e2834 = local_258;
                                        let _e2837 = local_257;
                                        let _e2839 = local_13;
                                        let _e2841 = local_260;
                                        let _e2843 = local_260;
                                        let _e2846 = local_241;
                                        let _e2848 = local_207;
                                        let _e2850 = ((((((_e2832 * _e2831) + _e2834) * _e2831) + _e2837) * ((_e2839.member_2 * _e2841) * _e2843)) + (_e2848 - _e2846.member_10));
                                        local_261 = _e2850;
                                        let _e2852 = ((4u * _e2850) + 2u);
                                        local_262 = _e2852;
                                        let _e2853 = local_1;
                                        if (_e2852 < _e2853) {
                                        } else {
                                            phi_2923_ = true;
                                            break;
                                        }
                                        let _e2855 = local_262;
                                        let _e2858 = global_4.member[_e2855];
                                        local_263 = _e2858;
                                        let _e2859 = local_199;
                                        let _e2860 = local_8;
                                        if (_e2859 < _e2860) {
                                        } else {
                                            phi_2923_ = true;
                                            break;
                                        }
                                        let _e2862 = local_199;
                                        let _e2865 = local_263;
                                        global_11.member[_e2862] = _e2865;
                                        let _e2866 = local_199;
                                        let _e2867 = local_9;
                                        if (_e2866 < _e2867) {
                                        } else {
                                            phi_2923_ = true;
                                            break;
                                        }
                                        let _e2869 = local_199;
                                        let _e2872 = local_261;
                                        global_12.member[_e2869] = _e2872;
                                        let _e2873 = local_199;
                                        phi_2925_ = _e2817;
                                        let _e3092 = local_280;
                                        phi_2651_ = _e3092;
                                        phi_2652_ = (_e2873 + 1u);
                                    }
                                    let _e2876 = phi_2925_;
                                    let _e2878 = phi_2651_;
                                    let _e2880 = phi_2652_;
                                    let _e2881 = local_198;
                                    phi_2924_ = _e2876;
                                    phi_1989_ = _e2878;
                                    phi_1992_ = (_e2881 + 1u);
                                    phi_1994_ = _e2880;
                                } else {
                                    phi_2924_ = _e2154;
                                    phi_1989_ = type_24();
                                    phi_1992_ = u32();
                                    phi_1994_ = u32();
                                }
                                let _e2884 = phi_2924_;
                                let _e2886 = phi_1989_;
                                let _e2888 = phi_1992_;
                                let _e2890 = phi_1994_;
                                continue;
                                continuing {
                                    let _e2891 = local_200;
                                    phi_2876_ = _e2884;
                                    phi_1988_ = _e2886;
                                    phi_1991_ = _e2888;
                                    phi_1993_ = _e2890;
                                    phi_2923_ = _e2884;
                                    break if !(_e2891);
                                }
                            }
                            let _e2894 = phi_2923_;
                            phi_2926_ = _e2894;
                            if _e2894 {
                                break;
                            }
                            let _e2895 = local_182;
                            let _e2896 = (_e2895 + 255u);
                            local_264 = _e2896;
                            if (_e2896 < 1792u) {
                            } else {
                                phi_2926_ = true;
                                break;
                            }
                            let _e2898 = local_264;
                            let _e2900 = global_8[_e2898];
                            storageBarrier();
                            workgroupBarrier();
                            let _e2901 = local_54;
                            let _e2903 = local_266;
                            let _e2905 = local_53;
                            let _e2907 = local_52;
                            phi_2927_ = _e2894;
                            phi_611_ = (_e2907 + 1u);
                            phi_614_ = (_e2905 + (256u * _e2903));
                            phi_616_ = (_e2901 + _e2900);
                        } else {
                            phi_2927_ = _e648;
                            phi_611_ = u32();
                            phi_614_ = u32();
                            phi_616_ = u32();
                        }
                        let _e2910 = phi_2927_;
                        let _e2912 = phi_611_;
                        let _e2914 = phi_614_;
                        let _e2916 = phi_616_;
                        continue;
                        continuing {
                            let _e2917 = local_55;
                            phi_2756_ = _e2910;
                            phi_610_ = _e2912;
                            phi_613_ = _e2914;
                            phi_615_ = _e2916;
                            phi_2926_ = _e2910;
                            break if !(_e2917);
                        }
                    }
                    let _e2920 = phi_2926_;
                    if _e2920 {
                        break;
                    }
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn splat_bin(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
