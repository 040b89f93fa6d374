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

struct type_16 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: array<f32, 3>,
    member_3: f32,
    member_4: array<f32, 3>,
    member_5: f32,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<immediate> global_2: type_7;
@group(0) @binding(0) 
var<storage> global_3: type_10;
@group(0) @binding(1) 
var<storage> global_4: type_10;
@group(0) @binding(2) 
var<storage, read_write> global_5: type_10;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: bool;
    var local_8: u32;
    var local_9: u32;
    var local_10: bool;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: bool;
    var local_18: f32;
    var local_19: u32;
    var local_20: bool;
    var local_21: f32;
    var local_22: u32;
    var local_23: bool;
    var local_24: f32;
    var local_25: f32;
    var local_26: u32;
    var local_27: u32;
    var local_28: f32;
    var local_29: bool;
    var local_30: f32;
    var local_31: bool;
    var local_32: f32;
    var local_33: u32;
    var local_34: f32;
    var local_35: u32;
    var local_36: f32;
    var local_37: f32;
    var local_38: f32;
    var local_39: bool;
    var local_40: type_16;
    var local_41: type_16;
    var local_42: u32;
    var local_43: f32;
    var local_44: u32;
    var local_45: f32;
    var local_46: u32;
    var local_47: f32;
    var local_48: f32;
    var local_49: f32;
    var local_50: bool;
    var local_51: type_16;
    var local_52: type_16;
    var local_53: f32;
    var local_54: u32;
    var local_55: f32;
    var local_56: u32;
    var local_57: f32;
    var local_58: f32;
    var local_59: f32;
    var local_60: type_16;
    var local_61: u32;
    var local_62: f32;
    var local_63: u32;
    var local_64: f32;
    var local_65: u32;
    var local_66: f32;
    var local_67: f32;
    var local_68: f32;
    var local_69: bool;
    var local_70: bool;
    var local_71: bool;
    var local_72: u32;
    var local_73: u32;
    var local_74: f32;
    var local_75: f32;
    var local_76: u32;
    var local_77: u32;
    var local_78: bool;
    var local_79: type_16;
    var local_80: u32;
    var local_81: bool;
    var local_82: bool;
    var local_83: u32;
    var local_84: f32;
    var local_85: array<f32, 2>;
    var local_86: u32;
    var local_87: u32;
    var local_88: f32;
    var local_89: u32;
    var local_90: f32;
    var local_91: u32;
    var local_92: f32;
    var local_93: f32;
    var local_94: u32;
    var local_95: f32;
    var local_96: u32;
    var local_97: f32;
    var local_98: u32;
    var local_99: f32;
    var local_100: f32;
    var local_101: f32;
    var local_102: bool;
    var local_103: f32;
    var local_104: type_16;
    var local_105: type_16;
    var local_106: f32;
    var local_107: type_16;
    var local_108: u32;
    var local_109: f32;
    var local_110: u32;
    var local_111: f32;
    var local_112: u32;
    var local_113: f32;
    var local_114: f32;
    var local_115: f32;
    var local_116: f32;
    var local_117: bool;
    var local_118: f32;
    var local_119: type_16;
    var local_120: type_16;
    var local_121: f32;
    var local_122: u32;
    var local_123: u32;
    var local_124: f32;
    var local_125: f32;
    var local_126: u32;
    var local_127: u32;
    var local_128: bool;
    var local_129: type_16;
    var local_130: u32;
    var local_131: bool;
    var local_132: bool;
    var local_133: u32;
    var local_134: f32;
    var local_135: array<f32, 2>;
    var local_136: u32;
    var local_137: u32;
    var local_138: f32;
    var local_139: u32;
    var local_140: f32;
    var local_141: u32;
    var local_142: f32;
    var local_143: f32;
    var local_144: u32;
    var local_145: f32;
    var local_146: u32;
    var local_147: f32;
    var local_148: u32;
    var local_149: f32;
    var local_150: f32;
    var local_151: f32;
    var local_152: bool;
    var local_153: f32;
    var local_154: type_16;
    var local_155: type_16;
    var local_156: u32;
    var local_157: f32;
    var local_158: u32;
    var local_159: f32;
    var local_160: u32;
    var local_161: f32;
    var local_162: f32;
    var local_163: f32;
    var local_164: bool;
    var local_165: f32;
    var local_166: type_16;
    var local_167: u32;
    var local_168: u32;
    var local_169: f32;
    var local_170: f32;
    var local_171: u32;
    var local_172: u32;
    var local_173: bool;
    var local_174: type_16;
    var local_175: u32;
    var local_176: bool;
    var local_177: bool;
    var local_178: u32;
    var local_179: f32;
    var local_180: array<f32, 2>;
    var local_181: u32;
    var local_182: u32;
    var local_183: f32;
    var local_184: u32;
    var local_185: f32;
    var local_186: u32;
    var local_187: f32;
    var local_188: f32;
    var local_189: u32;
    var local_190: f32;
    var local_191: u32;
    var local_192: f32;
    var local_193: u32;
    var local_194: f32;
    var local_195: f32;
    var local_196: f32;
    var local_197: type_16;
    var local_198: u32;
    var local_199: f32;
    var local_200: u32;
    var local_201: f32;
    var local_202: u32;
    var local_203: f32;
    var local_204: f32;
    var local_205: f32;
    var local_206: type_16;
    var local_207: u32;
    var local_208: f32;
    var local_209: bool;
    var local_210: array<f32, 3>;
    var local_211: f32;
    var local_212: f32;
    var local_213: f32;
    var local_214: f32;
    var local_215: f32;
    var local_216: array<f32, 3>;
    var local_217: f32;
    var local_218: f32;
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
    var local_235: f32;
    var local_236: f32;
    var local_237: f32;
    var local_238: f32;
    var local_239: f32;
    var local_240: f32;
    var local_241: f32;
    var local_242: f32;
    var local_243: f32;
    var local_244: f32;
    var local_245: f32;
    var local_246: f32;
    var local_247: f32;
    var local_248: f32;
    var phi_100_: u32;
    var phi_118_: u32;
    var phi_184_: u32;
    var phi_200_: u32;
    var phi_225_: f32;
    var phi_367_: f32;
    var phi_466_: type_16;
    var phi_467_: type_16;
    var phi_468_: type_16;
    var phi_536_: type_16;
    var phi_621_: f32;
    var phi_720_: type_16;
    var phi_721_: type_16;
    var phi_722_: type_16;
    var phi_791_: type_16;
    var phi_792_: type_16;
    var phi_1104_: type_16;
    var phi_1106_: type_16;
    var phi_1359_: type_16;
    var phi_1361_: type_16;
    var phi_1362_: type_16;
    var phi_1363_: type_16;
    var phi_1393_: u32;
    var phi_1411_: u32;
    var phi_1447_: u32;
    var phi_1448_: u32;
    var phi_3954_: bool;
    var phi_1450_: type_16;
    var phi_1453_: u32;
    var phi_1462_: type_16;
    var phi_1465_: u32;
    var phi_1513_: array<f32, 2>;
    var phi_1514_: array<f32, 2>;
    var phi_1515_: array<f32, 2>;
    var phi_1516_: array<f32, 2>;
    var phi_1517_: array<f32, 2>;
    var phi_1548_: array<f32, 2>;
    var phi_1549_: array<f32, 2>;
    var phi_1550_: array<f32, 2>;
    var phi_1551_: array<f32, 2>;
    var phi_1552_: array<f32, 2>;
    var phi_1739_: f32;
    var phi_1757_: f32;
    var phi_1838_: type_16;
    var phi_1839_: type_16;
    var phi_1840_: type_16;
    var phi_1906_: type_16;
    var phi_1908_: type_16;
    var phi_1993_: f32;
    var phi_2011_: f32;
    var phi_2092_: type_16;
    var phi_2093_: type_16;
    var phi_2094_: type_16;
    var phi_2161_: type_16;
    var phi_2163_: type_16;
    var phi_2164_: type_16;
    var phi_1463_: type_16;
    var phi_1466_: u32;
    var phi_3944_: bool;
    var phi_4152_: bool;
    var phi_1451_: type_16;
    var phi_1454_: u32;
    var phi_4151_: bool;
    var phi_4171_: bool;
    var phi_2167_: type_16;
    var phi_4170_: bool;
    var phi_2169_: type_16;
    var phi_2170_: bool;
    var phi_4169_: bool;
    var phi_2171_: type_16;
    var phi_2172_: bool;
    var phi_2196_: u32;
    var phi_2214_: u32;
    var phi_2250_: u32;
    var phi_2251_: u32;
    var phi_4163_: bool;
    var phi_2253_: type_16;
    var phi_2256_: u32;
    var phi_2265_: type_16;
    var phi_2268_: u32;
    var phi_2316_: array<f32, 2>;
    var phi_2317_: array<f32, 2>;
    var phi_2318_: array<f32, 2>;
    var phi_2319_: array<f32, 2>;
    var phi_2320_: array<f32, 2>;
    var phi_2351_: array<f32, 2>;
    var phi_2352_: array<f32, 2>;
    var phi_2353_: array<f32, 2>;
    var phi_2354_: array<f32, 2>;
    var phi_2355_: array<f32, 2>;
    var phi_2542_: f32;
    var phi_2560_: f32;
    var phi_2641_: type_16;
    var phi_2642_: type_16;
    var phi_2643_: type_16;
    var phi_2711_: type_16;
    var phi_2796_: f32;
    var phi_2814_: f32;
    var phi_2895_: type_16;
    var phi_2896_: type_16;
    var phi_2897_: type_16;
    var phi_2966_: type_16;
    var phi_2967_: type_16;
    var phi_2266_: type_16;
    var phi_2269_: u32;
    var phi_4153_: bool;
    var phi_4238_: bool;
    var phi_2254_: type_16;
    var phi_2257_: u32;
    var phi_4237_: bool;
    var phi_4255_: bool;
    var phi_2970_: type_16;
    var phi_2991_: u32;
    var phi_3009_: u32;
    var phi_3045_: u32;
    var phi_3046_: u32;
    var phi_4249_: bool;
    var phi_3048_: type_16;
    var phi_3051_: u32;
    var phi_3060_: type_16;
    var phi_3063_: u32;
    var phi_3111_: array<f32, 2>;
    var phi_3112_: array<f32, 2>;
    var phi_3113_: array<f32, 2>;
    var phi_3114_: array<f32, 2>;
    var phi_3115_: array<f32, 2>;
    var phi_3146_: array<f32, 2>;
    var phi_3147_: array<f32, 2>;
    var phi_3148_: array<f32, 2>;
    var phi_3149_: array<f32, 2>;
    var phi_3150_: array<f32, 2>;
    var phi_3504_: type_16;
    var phi_3506_: type_16;
    var phi_3759_: type_16;
    var phi_3761_: type_16;
    var phi_3762_: type_16;
    var phi_3061_: type_16;
    var phi_3064_: u32;
    var phi_4239_: bool;
    var phi_4322_: bool;
    var phi_3049_: type_16;
    var phi_3052_: u32;
    var phi_4321_: bool;
    var phi_3765_: type_16;
    var phi_3766_: type_16;
    var phi_3784_: array<f32, 3>;
    var phi_3839_: array<f32, 3>;
    var phi_3816_: f32;
    var phi_3840_: f32;
    var phi_3841_: array<f32, 3>;
    var phi_3855_: f32;
    var local_249: type_16;
    var local_250: type_16;
    var local_251: type_16;
    var local_252: type_16;
    var local_253: type_16;
    var local_254: type_16;

    switch bitcast<i32>(0u) {
        default: {
            let _e292 = global;
            local = _e292;
            let _e293 = global_1;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = _e293.x;
            local_5 = _e293.y;
            let _e304 = global_2.member.member;
            let _e305 = (_e304 / 2u);
            local_6 = _e305;
            let _e307 = ((_e304 % 2u) > 0u);
            local_7 = _e307;
            if _e307 {
                let _e308 = local_6;
                phi_100_ = (_e308 + 1u);
            } else {
                phi_100_ = _e305;
            }
            let _e311 = phi_100_;
            local_8 = _e311;
            let _e314 = global_2.member.member_1;
            let _e315 = (_e314 / 2u);
            local_9 = _e315;
            let _e317 = ((_e314 % 2u) > 0u);
            local_10 = _e317;
            if _e317 {
                let _e318 = local_9;
                phi_118_ = (_e318 + 1u);
            } else {
                phi_118_ = _e315;
            }
            let _e321 = phi_118_;
            local_11 = _e321;
            let _e322 = local_4;
            let _e324 = local;
            let _e326 = ((_e322 * 8u) + (_e324 % 8u));
            local_12 = _e326;
            let _e327 = local_5;
            let _e329 = local;
            local_13 = ((_e327 * 8u) + (_e329 / 8u));
            let _e332 = local_8;
            if (_e326 >= _e332) {
            } else {
                let _e334 = local_13;
                let _e335 = local_11;
                if (_e334 >= _e335) {
                } else {
                    let _e337 = local_13;
                    let _e338 = local_8;
                    let _e340 = local_12;
                    let _e341 = ((_e337 * _e338) + _e340);
                    local_14 = _e341;
                    let _e342 = (9u * _e341);
                    local_15 = _e342;
                    let _e343 = (_e342 + 3u);
                    local_16 = _e343;
                    let _e344 = local_1;
                    let _e345 = (_e343 < _e344);
                    local_17 = _e345;
                    if _e345 {
                    } else {
                        break;
                    }
                    let _e346 = local_16;
                    let _e349 = global_3.member[_e346];
                    local_18 = bitcast<f32>(_e349);
                    let _e351 = local_15;
                    let _e352 = (_e351 + 8u);
                    local_19 = _e352;
                    let _e353 = local_1;
                    let _e354 = (_e352 < _e353);
                    local_20 = _e354;
                    if _e354 {
                    } else {
                        break;
                    }
                    let _e355 = local_19;
                    let _e358 = global_3.member[_e355];
                    local_21 = bitcast<f32>(_e358);
                    let _e360 = local_15;
                    let _e361 = (_e360 + 7u);
                    local_22 = _e361;
                    let _e362 = local_1;
                    let _e363 = (_e361 < _e362);
                    local_23 = _e363;
                    if _e363 {
                    } else {
                        break;
                    }
                    let _e364 = local_22;
                    let _e367 = global_3.member[_e364];
                    let _e368 = bitcast<f32>(_e367);
                    local_24 = _e368;
                    let _e369 = local_21;
                    let _e371 = local_18;
                    let _e373 = local_21;
                    local_25 = (_e373 + (_e371 * (_e368 - _e369)));
                    let _e375 = local_7;
                    if _e375 {
                        let _e376 = local_6;
                        phi_184_ = (_e376 + 1u);
                    } else {
                        phi_184_ = _e305;
                    }
                    let _e379 = phi_184_;
                    let _e380 = (_e379 / 8u);
                    local_26 = _e380;
                    if ((_e379 % 8u) > 0u) {
                        let _e383 = local_26;
                        phi_200_ = (_e383 + 1u);
                    } else {
                        phi_200_ = _e380;
                    }
                    let _e386 = phi_200_;
                    let _e387 = local_5;
                    let _e389 = local_4;
                    let _e391 = (2u * ((_e387 * _e386) + _e389));
                    local_27 = _e391;
                    let _e392 = local_2;
                    if (_e391 < _e392) {
                    } else {
                        break;
                    }
                    let _e394 = local_27;
                    let _e397 = global_4.member[_e394];
                    local_28 = bitcast<f32>(_e397);
                    let _e399 = local_25;
                    let _e403 = !(((bitcast<u32>(_e399) & 2147483647u) > 2139095040u));
                    local_29 = _e403;
                    let _e404 = local_25;
                    let _e405 = select(0f, _e404, _e403);
                    local_234 = _e405;
                    if (_e405 < 0f) {
                        let _e407 = local_234;
                        phi_225_ = -(_e407);
                    } else {
                        phi_225_ = _e405;
                    }
                    let _e410 = phi_225_;
                    let _e411 = local_234;
                    let _e412 = (-0.5f - _e411);
                    let _e414 = select(0f, _e412, (_e412 > 0f));
                    let _e416 = select(1f, _e414, (_e414 < 1f));
                    local_235 = _e416;
                    let _e419 = local_28;
                    let _e421 = local_28;
                    local_30 = (((1f - _e416) * _e410) + (_e416 * select(_e410, _e421, (_e419 > _e410))));
                    let _e425 = local_29;
                    if _e425 {
                        let _e426 = local_20;
                        if _e426 {
                        } else {
                            break;
                        }
                        let _e427 = local_21;
                        let _e430 = ((bitcast<u32>(_e427) & 2147483647u) > 2139095040u);
                        local_31 = _e430;
                        if _e430 {
                            phi_792_ = type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f);
                        } else {
                            let _e431 = local_17;
                            if _e431 {
                            } else {
                                break;
                            }
                            let _e432 = local_18;
                            if (_e432 > 0f) {
                                let _e434 = local_15;
                                let _e435 = local_1;
                                if (_e434 < _e435) {
                                } else {
                                    break;
                                }
                                let _e437 = local_15;
                                let _e440 = global_3.member[_e437];
                                local_32 = bitcast<f32>(_e440);
                                let _e442 = local_15;
                                let _e443 = (_e442 + 1u);
                                local_33 = _e443;
                                let _e444 = local_1;
                                if (_e443 < _e444) {
                                } else {
                                    break;
                                }
                                let _e446 = local_33;
                                let _e449 = global_3.member[_e446];
                                local_34 = bitcast<f32>(_e449);
                                let _e451 = local_15;
                                let _e452 = (_e451 + 2u);
                                local_35 = _e452;
                                let _e453 = local_1;
                                if (_e452 < _e453) {
                                } else {
                                    break;
                                }
                                let _e455 = local_35;
                                let _e458 = global_3.member[_e455];
                                local_36 = bitcast<f32>(_e458);
                                let _e460 = local_23;
                                if _e460 {
                                } else {
                                    break;
                                }
                                let _e461 = local_24;
                                local_37 = -(_e461);
                                let _e463 = local_24;
                                let _e464 = (-0.5f - _e463);
                                let _e466 = select(0f, _e464, (_e464 > 0f));
                                let _e470 = local_18;
                                let _e471 = (_e470 * (1f - select(1f, _e466, (_e466 < 1f))));
                                local_38 = _e471;
                                if (_e471 <= 0f) {
                                    phi_468_ = type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f);
                                } else {
                                    let _e473 = local_234;
                                    let _e475 = local_234;
                                    local_236 = select(0f, _e475, (_e473 > 0f));
                                    let _e477 = local_24;
                                    let _e478 = local_234;
                                    let _e479 = (_e477 > _e478);
                                    local_39 = _e479;
                                    if _e479 {
                                        let _e485 = local_24;
                                        let _e487 = local_37;
                                        let _e488 = local_24;
                                        let _e489 = select(_e488, _e487, (_e485 < 0f));
                                        let _e490 = local_236;
                                        let _e492 = local_236;
                                        phi_367_ = select(_e492, _e489, (_e489 < _e490));
                                    } else {
                                        let _e480 = local_24;
                                        let _e482 = local_37;
                                        let _e483 = local_24;
                                        phi_367_ = select(_e483, _e482, (_e480 < 0f));
                                    }
                                    let _e495 = phi_367_;
                                    let _e496 = (_e495 * _e495);
                                    let _e499 = local_38;
                                    let _e500 = (_e499 / select(0.25f, _e496, (_e496 > 0.25f)));
                                    let _e501 = local_32;
                                    let _e503 = local_34;
                                    let _e505 = local_36;
                                    let _e514 = type_16(array<f32, 3>((_e500 * _e501), (_e500 * _e503), (_e500 * _e505)), type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f).member_1, type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f).member_2, type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f).member_3, type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f).member_4, type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f).member_5);
                                    let _e521 = type_16(_e514.member, _e500, _e514.member_2, _e514.member_3, _e514.member_4, _e514.member_5);
                                    local_40 = _e521;
                                    let _e522 = local_39;
                                    if _e522 {
                                        let _e523 = local_235;
                                        if (_e523 > 0f) {
                                            let _e525 = local_30;
                                            let _e526 = (_e525 + 0.5f);
                                            let _e528 = select(0f, _e526, (_e526 > 0f));
                                            let _e531 = local_38;
                                            let _e533 = local_30;
                                            let _e534 = local_30;
                                            let _e535 = (_e533 * _e534);
                                            let _e538 = ((_e531 * select(1f, _e528, (_e528 < 1f))) / select(0.25f, _e535, (_e535 > 0.25f)));
                                            let _e539 = local_32;
                                            let _e541 = local_34;
                                            let _e543 = local_36;
                                            let _e546 = local_40;
                                            let _e553 = type_16(_e546.member, _e546.member_1, array<f32, 3>((_e538 * _e539), (_e538 * _e541), (_e538 * _e543)), _e546.member_3, _e546.member_4, _e546.member_5);
                                            phi_466_ = type_16(_e553.member, _e553.member_1, _e553.member_2, _e538, _e553.member_4, _e553.member_5);
                                        } else {
                                            phi_466_ = _e521;
                                        }
                                        let _e562 = phi_466_;
                                        phi_467_ = _e562;
                                    } else {
                                        phi_467_ = _e521;
                                    }
                                    let _e564 = phi_467_;
                                    phi_468_ = _e564;
                                }
                                let _e566 = phi_468_;
                                phi_536_ = _e566;
                            } else {
                                phi_536_ = type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f);
                            }
                            let _e568 = phi_536_;
                            local_41 = _e568;
                            let _e569 = local_18;
                            if (_e569 < 1f) {
                                let _e571 = local_15;
                                let _e572 = (_e571 + 4u);
                                local_42 = _e572;
                                let _e573 = local_1;
                                if (_e572 < _e573) {
                                } else {
                                    break;
                                }
                                let _e575 = local_42;
                                let _e578 = global_3.member[_e575];
                                local_43 = bitcast<f32>(_e578);
                                let _e580 = local_15;
                                let _e581 = (_e580 + 5u);
                                local_44 = _e581;
                                let _e582 = local_1;
                                if (_e581 < _e582) {
                                } else {
                                    break;
                                }
                                let _e584 = local_44;
                                let _e587 = global_3.member[_e584];
                                local_45 = bitcast<f32>(_e587);
                                let _e589 = local_15;
                                let _e590 = (_e589 + 6u);
                                local_46 = _e590;
                                let _e591 = local_1;
                                if (_e590 < _e591) {
                                } else {
                                    break;
                                }
                                let _e593 = local_46;
                                let _e596 = global_3.member[_e593];
                                local_47 = bitcast<f32>(_e596);
                                let _e598 = local_18;
                                let _e600 = local_21;
                                local_48 = -(_e600);
                                let _e602 = local_21;
                                let _e603 = (-0.5f - _e602);
                                let _e605 = select(0f, _e603, (_e603 > 0f));
                                let _e609 = ((1f - _e598) * (1f - select(1f, _e605, (_e605 < 1f))));
                                local_49 = _e609;
                                if (_e609 <= 0f) {
                                    phi_722_ = _e568;
                                } else {
                                    let _e611 = local_234;
                                    let _e613 = local_234;
                                    local_237 = select(0f, _e613, (_e611 > 0f));
                                    let _e615 = local_21;
                                    let _e616 = local_234;
                                    let _e617 = (_e615 > _e616);
                                    local_50 = _e617;
                                    if _e617 {
                                        let _e623 = local_21;
                                        let _e625 = local_48;
                                        let _e626 = local_21;
                                        let _e627 = select(_e626, _e625, (_e623 < 0f));
                                        let _e628 = local_237;
                                        let _e630 = local_237;
                                        phi_621_ = select(_e630, _e627, (_e627 < _e628));
                                    } else {
                                        let _e618 = local_21;
                                        let _e620 = local_48;
                                        let _e621 = local_21;
                                        phi_621_ = select(_e621, _e620, (_e618 < 0f));
                                    }
                                    let _e633 = phi_621_;
                                    let _e634 = (_e633 * _e633);
                                    let _e637 = local_49;
                                    let _e638 = (_e637 / select(0.25f, _e634, (_e634 > 0.25f)));
                                    let _e639 = local_41;
                                    let _e642 = local_43;
                                    let _e645 = local_41;
                                    let _e648 = local_45;
                                    let _e651 = local_41;
                                    let _e654 = local_47;
                                    let _e658 = local_41;
                                    let _e665 = type_16(array<f32, 3>((_e639.member[0] + (_e638 * _e642)), (_e645.member[1] + (_e638 * _e648)), (_e651.member[2] + (_e638 * _e654))), _e658.member_1, _e658.member_2, _e658.member_3, _e658.member_4, _e658.member_5);
                                    let _e666 = local_41;
                                    let _e675 = type_16(_e665.member, (_e666.member_1 + _e638), _e665.member_2, _e665.member_3, _e665.member_4, _e665.member_5);
                                    local_51 = _e675;
                                    let _e676 = local_50;
                                    if _e676 {
                                        let _e677 = local_235;
                                        if (_e677 > 0f) {
                                            let _e679 = local_30;
                                            let _e680 = (_e679 + 0.5f);
                                            let _e682 = select(0f, _e680, (_e680 > 0f));
                                            let _e685 = local_49;
                                            let _e687 = local_30;
                                            let _e688 = local_30;
                                            let _e689 = (_e687 * _e688);
                                            let _e692 = ((_e685 * select(1f, _e682, (_e682 < 1f))) / select(0.25f, _e689, (_e689 > 0.25f)));
                                            let _e693 = local_41;
                                            let _e696 = local_43;
                                            let _e699 = local_41;
                                            let _e702 = local_45;
                                            let _e705 = local_41;
                                            let _e708 = local_47;
                                            let _e712 = local_51;
                                            let _e719 = type_16(_e712.member, _e712.member_1, array<f32, 3>((_e693.member_2[0] + (_e692 * _e696)), (_e699.member_2[1] + (_e692 * _e702)), (_e705.member_2[2] + (_e692 * _e708))), _e712.member_3, _e712.member_4, _e712.member_5);
                                            let _e720 = local_41;
                                            phi_720_ = type_16(_e719.member, _e719.member_1, _e719.member_2, (_e720.member_3 + _e692), _e719.member_4, _e719.member_5);
                                        } else {
                                            phi_720_ = _e675;
                                        }
                                        let _e731 = phi_720_;
                                        phi_721_ = _e731;
                                    } else {
                                        phi_721_ = _e675;
                                    }
                                    let _e733 = phi_721_;
                                    phi_722_ = _e733;
                                }
                                let _e735 = phi_722_;
                                phi_791_ = _e735;
                            } else {
                                phi_791_ = _e568;
                            }
                            let _e737 = phi_791_;
                            phi_792_ = _e737;
                        }
                        let _e739 = phi_792_;
                        local_52 = _e739;
                        let _e742 = global_2.member.member_2;
                        let _e746 = local_28;
                        let _e747 = (_e746 / f32(select(_e742, 1u, (_e742 == 0u))));
                        local_238 = select(1f, _e747, (_e747 > 1f));
                        let _e750 = local_20;
                        if _e750 {
                        } else {
                            break;
                        }
                        let _e751 = local_31;
                        if _e751 {
                            phi_1362_ = _e739;
                        } else {
                            let _e752 = local_17;
                            if _e752 {
                            } else {
                                break;
                            }
                            let _e753 = local_18;
                            if (_e753 > 0f) {
                                let _e755 = local_15;
                                let _e756 = local_1;
                                if (_e755 < _e756) {
                                } else {
                                    break;
                                }
                                let _e758 = local_15;
                                let _e761 = global_3.member[_e758];
                                local_53 = bitcast<f32>(_e761);
                                let _e763 = local_15;
                                let _e764 = (_e763 + 1u);
                                local_54 = _e764;
                                let _e765 = local_1;
                                if (_e764 < _e765) {
                                } else {
                                    break;
                                }
                                let _e767 = local_54;
                                let _e770 = global_3.member[_e767];
                                local_55 = bitcast<f32>(_e770);
                                let _e772 = local_15;
                                let _e773 = (_e772 + 2u);
                                local_56 = _e773;
                                let _e774 = local_1;
                                if (_e773 < _e774) {
                                } else {
                                    break;
                                }
                                let _e776 = local_56;
                                let _e779 = global_3.member[_e776];
                                local_57 = bitcast<f32>(_e779);
                                let _e781 = local_23;
                                if _e781 {
                                } else {
                                    break;
                                }
                                let _e782 = local_24;
                                local_58 = -(_e782);
                                let _e784 = local_24;
                                let _e785 = (-0.5f - _e784);
                                let _e787 = select(0f, _e785, (_e785 > 0f));
                                let _e790 = local_18;
                                let _e791 = (_e790 * select(1f, _e787, (_e787 < 1f)));
                                local_59 = _e791;
                                if (_e791 <= 0f) {
                                    phi_1104_ = _e739;
                                } else {
                                    let _e793 = local_238;
                                    let _e795 = local_238;
                                    let _e797 = local_24;
                                    let _e799 = local_58;
                                    let _e801 = (((0.8660254f * _e793) * _e795) / ((_e797 * -3.1415927f) * _e799));
                                    let _e804 = local_238;
                                    let _e806 = local_58;
                                    let _e807 = (_e806 + (0.5f * _e804));
                                    let _e809 = select(0f, _e807, (_e807 > 0f));
                                    let _e812 = local_59;
                                    let _e814 = ((_e812 * select(1f, _e809, (_e809 < 1f))) * select(1f, _e801, (_e801 < 1f)));
                                    let _e815 = local_52;
                                    let _e818 = local_53;
                                    let _e821 = local_52;
                                    let _e824 = local_55;
                                    let _e827 = local_52;
                                    let _e830 = local_57;
                                    let _e834 = local_52;
                                    let _e841 = type_16(_e834.member, _e834.member_1, _e834.member_2, _e834.member_3, array<f32, 3>((_e815.member_4[0] + (_e814 * _e818)), (_e821.member_4[1] + (_e814 * _e824)), (_e827.member_4[2] + (_e814 * _e830))), _e834.member_5);
                                    let _e842 = local_52;
                                    phi_1104_ = type_16(_e841.member, _e841.member_1, _e841.member_2, _e841.member_3, _e841.member_4, (_e842.member_5 + _e814));
                                }
                                let _e853 = phi_1104_;
                                phi_1106_ = _e853;
                            } else {
                                phi_1106_ = _e739;
                            }
                            let _e855 = phi_1106_;
                            local_60 = _e855;
                            let _e856 = local_18;
                            if (_e856 < 1f) {
                                let _e858 = local_15;
                                let _e859 = (_e858 + 4u);
                                local_61 = _e859;
                                let _e860 = local_1;
                                if (_e859 < _e860) {
                                } else {
                                    break;
                                }
                                let _e862 = local_61;
                                let _e865 = global_3.member[_e862];
                                local_62 = bitcast<f32>(_e865);
                                let _e867 = local_15;
                                let _e868 = (_e867 + 5u);
                                local_63 = _e868;
                                let _e869 = local_1;
                                if (_e868 < _e869) {
                                } else {
                                    break;
                                }
                                let _e871 = local_63;
                                let _e874 = global_3.member[_e871];
                                local_64 = bitcast<f32>(_e874);
                                let _e876 = local_15;
                                let _e877 = (_e876 + 6u);
                                local_65 = _e877;
                                let _e878 = local_1;
                                if (_e877 < _e878) {
                                } else {
                                    break;
                                }
                                let _e880 = local_65;
                                let _e883 = global_3.member[_e880];
                                local_66 = bitcast<f32>(_e883);
                                let _e885 = local_18;
                                let _e887 = local_21;
                                local_67 = -(_e887);
                                let _e889 = local_21;
                                let _e890 = (-0.5f - _e889);
                                let _e892 = select(0f, _e890, (_e890 > 0f));
                                let _e895 = ((1f - _e885) * select(1f, _e892, (_e892 < 1f)));
                                local_68 = _e895;
                                if (_e895 <= 0f) {
                                    phi_1359_ = _e855;
                                } else {
                                    let _e897 = local_238;
                                    let _e899 = local_238;
                                    let _e901 = local_21;
                                    let _e903 = local_67;
                                    let _e905 = (((0.8660254f * _e897) * _e899) / ((_e901 * -3.1415927f) * _e903));
                                    let _e908 = local_238;
                                    let _e910 = local_67;
                                    let _e911 = (_e910 + (0.5f * _e908));
                                    let _e913 = select(0f, _e911, (_e911 > 0f));
                                    let _e916 = local_68;
                                    let _e918 = ((_e916 * select(1f, _e913, (_e913 < 1f))) * select(1f, _e905, (_e905 < 1f)));
                                    let _e919 = local_60;
                                    let _e922 = local_62;
                                    let _e925 = local_60;
                                    let _e928 = local_64;
                                    let _e931 = local_60;
                                    let _e934 = local_66;
                                    let _e938 = local_60;
                                    let _e945 = type_16(_e938.member, _e938.member_1, _e938.member_2, _e938.member_3, array<f32, 3>((_e919.member_4[0] + (_e918 * _e922)), (_e925.member_4[1] + (_e918 * _e928)), (_e931.member_4[2] + (_e918 * _e934))), _e938.member_5);
                                    let _e946 = local_60;
                                    phi_1359_ = type_16(_e945.member, _e945.member_1, _e945.member_2, _e945.member_3, _e945.member_4, (_e946.member_5 + _e918));
                                }
                                let _e957 = phi_1359_;
                                phi_1361_ = _e957;
                            } else {
                                phi_1361_ = _e855;
                            }
                            let _e959 = phi_1361_;
                            phi_1362_ = _e959;
                        }
                        let _e961 = phi_1362_;
                        phi_1363_ = _e961;
                    } else {
                        phi_1363_ = type_16(array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), 0f);
                    }
                    let _e963 = phi_1363_;
                    let _e964 = local_30;
                    let _e965 = (_e964 >= 0.5f);
                    local_69 = _e965;
                    let _e966 = local_28;
                    local_70 = (_e966 >= 0.5f);
                    if _e965 {
                        let _e968 = local_70;
                        if _e968 {
                            let _e969 = local_30;
                            let _e970 = local_28;
                            let _e971 = (_e969 == _e970);
                            local_71 = _e971;
                            if _e971 {
                                let _e972 = local_7;
                                if _e972 {
                                    let _e973 = local_6;
                                    phi_1393_ = (_e973 + 1u);
                                } else {
                                    phi_1393_ = _e305;
                                }
                                let _e976 = phi_1393_;
                                local_72 = _e976;
                                let _e977 = local_10;
                                if _e977 {
                                    let _e978 = local_9;
                                    phi_1411_ = (_e978 + 1u);
                                } else {
                                    phi_1411_ = _e315;
                                }
                                let _e981 = phi_1411_;
                                local_73 = _e981;
                                let _e984 = global_2.member.member_2;
                                let _e986 = select(_e984, 1u, (_e984 == 0u));
                                let _e987 = f32(_e986);
                                local_74 = _e987;
                                let _e988 = local_30;
                                let _e989 = (_e988 / _e987);
                                let _e991 = select(1f, _e989, (_e989 > 1f));
                                local_239 = _e991;
                                let _e992 = local_30;
                                let _e995 = ceil(((_e992 / _e991) + 0.5f));
                                local_75 = _e995;
                                if (_e995 < 1f) {
                                    phi_1448_ = 1u;
                                } else {
                                    let _e997 = local_75;
                                    let _e998 = local_74;
                                    if (_e997 < _e998) {
                                        let _e1000 = local_75;
                                        let _e1002 = local_75;
                                        let _e1004 = local_75;
                                        phi_1447_ = select(select(u32(_e1000), 0u, (_e1002 < 0f)), 4294967295u, (_e1004 > 4294967000f));
                                    } else {
                                        phi_1447_ = _e986;
                                    }
                                    let _e1009 = phi_1447_;
                                    phi_1448_ = _e1009;
                                }
                                let _e1011 = phi_1448_;
                                local_76 = _e1011;
                                phi_3954_ = false;
                                phi_1450_ = _e963;
                                phi_1453_ = 1u;
                                loop {
                                    let _e1013 = phi_3954_;
                                    let _e1015 = phi_1450_;
                                    let _e1017 = phi_1453_;
                                    local_77 = _e1017;
                                    local_250 = _e1015;
                                    let _e1018 = local_77;
                                    let _e1019 = local_76;
                                    let _e1020 = (_e1018 <= _e1019);
                                    local_78 = _e1020;
                                    if _e1020 {
                                        phi_1462_ = _e1015;
                                        phi_1465_ = 0u;
                                        loop {
                                            let _e1022 = phi_1462_;
                                            let _e1024 = phi_1465_;
                                            local_79 = _e1022;
                                            local_80 = _e1024;
                                            local_249 = _e1022;
                                            let _e1025 = local_77;
                                            let _e1027 = local_80;
                                            let _e1028 = (_e1027 < (6u * _e1025));
                                            local_81 = _e1028;
                                            if _e1028 {
                                                let _e1029 = local_77;
                                                let _e1030 = (_e1029 == 0u);
                                                local_82 = _e1030;
                                                if _e1030 {
                                                    phi_3944_ = true;
                                                    break;
                                                }
                                                let _e1031 = local_80;
                                                let _e1032 = local_77;
                                                local_83 = (_e1031 / _e1032);
                                                let _e1034 = local_82;
                                                if _e1034 {
                                                    phi_3944_ = true;
                                                    break;
                                                }
                                                let _e1035 = local_80;
                                                let _e1036 = local_77;
                                                local_84 = f32((_e1035 % _e1036));
                                                let _e1039 = local_83;
                                                if (_e1039 == 0u) {
                                                    phi_1517_ = array<f32, 2>(1f, 0f);
                                                } else {
                                                    let _e1041 = local_83;
                                                    if (_e1041 == 1u) {
                                                        phi_1516_ = array<f32, 2>(0.5f, 0.8660254f);
                                                    } else {
                                                        let _e1043 = local_83;
                                                        if (_e1043 == 2u) {
                                                            phi_1515_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                        } else {
                                                            let _e1045 = local_83;
                                                            if (_e1045 == 3u) {
                                                                phi_1514_ = array<f32, 2>(-1f, 0f);
                                                            } else {
                                                                let _e1047 = local_83;
                                                                if (_e1047 == 4u) {
                                                                    phi_1513_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                                } else {
                                                                    phi_1513_ = array<f32, 2>(0.5f, -0.8660254f);
                                                                }
                                                                let _e1050 = phi_1513_;
                                                                phi_1514_ = _e1050;
                                                            }
                                                            let _e1052 = phi_1514_;
                                                            phi_1515_ = _e1052;
                                                        }
                                                        let _e1054 = phi_1515_;
                                                        phi_1516_ = _e1054;
                                                    }
                                                    let _e1056 = phi_1516_;
                                                    phi_1517_ = _e1056;
                                                }
                                                let _e1058 = phi_1517_;
                                                local_85 = _e1058;
                                                let _e1059 = local_83;
                                                let _e1061 = ((_e1059 + 1u) % 6u);
                                                local_86 = _e1061;
                                                if (_e1061 == 0u) {
                                                    phi_1552_ = array<f32, 2>(1f, 0f);
                                                } else {
                                                    let _e1063 = local_86;
                                                    if (_e1063 == 1u) {
                                                        phi_1551_ = array<f32, 2>(0.5f, 0.8660254f);
                                                    } else {
                                                        let _e1065 = local_86;
                                                        if (_e1065 == 2u) {
                                                            phi_1550_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                        } else {
                                                            let _e1067 = local_86;
                                                            if (_e1067 == 3u) {
                                                                phi_1549_ = array<f32, 2>(-1f, 0f);
                                                            } else {
                                                                let _e1069 = local_86;
                                                                if (_e1069 == 4u) {
                                                                    phi_1548_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                                } else {
                                                                    phi_1548_ = array<f32, 2>(0.5f, -0.8660254f);
                                                                }
                                                                let _e1072 = phi_1548_;
                                                                phi_1549_ = _e1072;
                                                            }
                                                            let _e1074 = phi_1549_;
                                                            phi_1550_ = _e1074;
                                                        }
                                                        let _e1076 = phi_1550_;
                                                        phi_1551_ = _e1076;
                                                    }
                                                    let _e1078 = phi_1551_;
                                                    phi_1552_ = _e1078;
                                                }
                                                let _e1080 = phi_1552_;
                                                let _e1081 = local_77;
                                                let _e1082 = f32(_e1081);
                                                let _e1083 = local_85;
                                                let _e1088 = local_84;
                                                let _e1091 = local_85;
                                                let _e1096 = local_84;
                                                let _e1099 = local_239;
                                                let _e1100 = (((_e1083[0] * _e1082) + ((_e1080[0] - _e1083[0]) * _e1088)) * _e1099);
                                                let _e1101 = local_239;
                                                let _e1102 = (((_e1091[1] * _e1082) + ((_e1080[1] - _e1091[1]) * _e1096)) * _e1101);
                                                let _e1103 = local_12;
                                                let _e1107 = floor(((f32(_e1103) + 0.5f) + _e1100));
                                                let _e1108 = local_13;
                                                let _e1112 = floor(((f32(_e1108) + 0.5f) + _e1102));
                                                let _e1114 = select(0f, _e1107, (_e1107 > 0f));
                                                let _e1115 = local_72;
                                                let _e1117 = f32((_e1115 - 1u));
                                                let _e1119 = select(_e1117, _e1114, (_e1114 < _e1117));
                                                let _e1126 = select(0f, _e1112, (_e1112 > 0f));
                                                let _e1127 = local_73;
                                                let _e1129 = f32((_e1127 - 1u));
                                                let _e1131 = select(_e1129, _e1126, (_e1126 < _e1129));
                                                let _e1137 = local_72;
                                                let _e1140 = (9u * ((select(select(u32(_e1131), 0u, (_e1131 < 0f)), 4294967295u, (_e1131 > 4294967000f)) * _e1137) + select(select(u32(_e1119), 0u, (_e1119 < 0f)), 4294967295u, (_e1119 > 4294967000f))));
                                                local_87 = _e1140;
                                                local_88 = sqrt(((_e1100 * _e1100) + (_e1102 * _e1102)));
                                                let _e1145 = (_e1140 + 8u);
                                                local_89 = _e1145;
                                                let _e1146 = local_1;
                                                if (_e1145 < _e1146) {
                                                } else {
                                                    phi_3944_ = true;
                                                    break;
                                                }
                                                let _e1148 = local_89;
                                                let _e1151 = global_3.member[_e1148];
                                                let _e1152 = bitcast<f32>(_e1151);
                                                local_90 = _e1152;
                                                if ((bitcast<u32>(_e1152) & 2147483647u) > 2139095040u) {
                                                    phi_2164_ = _e1022;
                                                } else {
                                                    let _e1156 = local_87;
                                                    let _e1157 = (_e1156 + 3u);
                                                    local_91 = _e1157;
                                                    let _e1158 = local_1;
                                                    if (_e1157 < _e1158) {
                                                    } else {
                                                        phi_3944_ = true;
                                                        break;
                                                    }
                                                    let _e1160 = local_91;
                                                    let _e1163 = global_3.member[_e1160];
                                                    let _e1164 = bitcast<f32>(_e1163);
                                                    local_92 = _e1164;
                                                    if (_e1164 > 0f) {
                                                        let _e1166 = local_87;
                                                        let _e1167 = local_1;
                                                        if (_e1166 < _e1167) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1169 = local_87;
                                                        let _e1172 = global_3.member[_e1169];
                                                        local_93 = bitcast<f32>(_e1172);
                                                        let _e1174 = local_87;
                                                        let _e1175 = (_e1174 + 1u);
                                                        local_94 = _e1175;
                                                        let _e1176 = local_1;
                                                        if (_e1175 < _e1176) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1178 = local_94;
                                                        let _e1181 = global_3.member[_e1178];
                                                        local_95 = bitcast<f32>(_e1181);
                                                        let _e1183 = local_87;
                                                        let _e1184 = (_e1183 + 2u);
                                                        local_96 = _e1184;
                                                        let _e1185 = local_1;
                                                        if (_e1184 < _e1185) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1187 = local_96;
                                                        let _e1190 = global_3.member[_e1187];
                                                        local_97 = bitcast<f32>(_e1190);
                                                        let _e1192 = local_87;
                                                        let _e1193 = (_e1192 + 7u);
                                                        local_98 = _e1193;
                                                        let _e1194 = local_1;
                                                        if (_e1193 < _e1194) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1196 = local_98;
                                                        let _e1199 = global_3.member[_e1196];
                                                        let _e1200 = bitcast<f32>(_e1199);
                                                        local_99 = _e1200;
                                                        local_100 = -(_e1200);
                                                        let _e1202 = (-0.5f - _e1200);
                                                        let _e1204 = select(0f, _e1202, (_e1202 > 0f));
                                                        let _e1206 = select(1f, _e1204, (_e1204 < 1f));
                                                        local_240 = _e1206;
                                                        let _e1208 = local_92;
                                                        let _e1209 = (_e1208 * (1f - _e1206));
                                                        local_101 = _e1209;
                                                        if (_e1209 <= 0f) {
                                                            phi_1840_ = _e1022;
                                                        } else {
                                                            let _e1211 = local_234;
                                                            let _e1213 = local_234;
                                                            local_241 = select(0f, _e1213, (_e1211 > 0f));
                                                            let _e1215 = local_99;
                                                            let _e1216 = local_234;
                                                            let _e1217 = (_e1215 > _e1216);
                                                            local_102 = _e1217;
                                                            if _e1217 {
                                                                let _e1223 = local_99;
                                                                let _e1225 = local_100;
                                                                let _e1226 = local_99;
                                                                let _e1227 = select(_e1226, _e1225, (_e1223 < 0f));
                                                                let _e1228 = local_241;
                                                                let _e1230 = local_241;
                                                                phi_1739_ = select(_e1230, _e1227, (_e1227 < _e1228));
                                                            } else {
                                                                let _e1218 = local_99;
                                                                let _e1220 = local_100;
                                                                let _e1221 = local_99;
                                                                phi_1739_ = select(_e1221, _e1220, (_e1218 < 0f));
                                                            }
                                                            let _e1233 = phi_1739_;
                                                            local_103 = _e1233;
                                                            let _e1234 = local_88;
                                                            if (_e1234 == 0f) {
                                                                phi_1757_ = 1f;
                                                            } else {
                                                                let _e1236 = local_103;
                                                                let _e1237 = local_88;
                                                                let _e1239 = local_239;
                                                                let _e1241 = ((_e1236 - _e1237) + (0.5f * _e1239));
                                                                let _e1243 = select(0f, _e1241, (_e1241 > 0f));
                                                                phi_1757_ = select(1f, _e1243, (_e1243 < 1f));
                                                            }
                                                            let _e1247 = phi_1757_;
                                                            let _e1248 = local_101;
                                                            let _e1250 = local_103;
                                                            let _e1251 = local_103;
                                                            let _e1252 = (_e1250 * _e1251);
                                                            let _e1255 = ((_e1248 * _e1247) / select(0.25f, _e1252, (_e1252 > 0.25f)));
                                                            let _e1256 = local_79;
                                                            let _e1259 = local_93;
                                                            let _e1262 = local_79;
                                                            let _e1265 = local_95;
                                                            let _e1268 = local_79;
                                                            let _e1271 = local_97;
                                                            let _e1275 = local_79;
                                                            let _e1282 = type_16(array<f32, 3>((_e1256.member[0] + (_e1255 * _e1259)), (_e1262.member[1] + (_e1255 * _e1265)), (_e1268.member[2] + (_e1255 * _e1271))), _e1275.member_1, _e1275.member_2, _e1275.member_3, _e1275.member_4, _e1275.member_5);
                                                            let _e1283 = local_79;
                                                            let _e1292 = type_16(_e1282.member, (_e1283.member_1 + _e1255), _e1282.member_2, _e1282.member_3, _e1282.member_4, _e1282.member_5);
                                                            local_104 = _e1292;
                                                            let _e1293 = local_102;
                                                            if _e1293 {
                                                                let _e1294 = local_235;
                                                                if (_e1294 > 0f) {
                                                                    let _e1296 = local_30;
                                                                    let _e1297 = local_88;
                                                                    let _e1299 = local_239;
                                                                    let _e1301 = ((_e1296 - _e1297) + (0.5f * _e1299));
                                                                    let _e1303 = select(0f, _e1301, (_e1301 > 0f));
                                                                    let _e1306 = local_101;
                                                                    let _e1308 = local_30;
                                                                    let _e1309 = local_30;
                                                                    let _e1310 = (_e1308 * _e1309);
                                                                    let _e1313 = ((_e1306 * select(1f, _e1303, (_e1303 < 1f))) / select(0.25f, _e1310, (_e1310 > 0.25f)));
                                                                    let _e1314 = local_79;
                                                                    let _e1317 = local_93;
                                                                    let _e1320 = local_79;
                                                                    let _e1323 = local_95;
                                                                    let _e1326 = local_79;
                                                                    let _e1329 = local_97;
                                                                    let _e1333 = local_104;
                                                                    let _e1340 = type_16(_e1333.member, _e1333.member_1, array<f32, 3>((_e1314.member_2[0] + (_e1313 * _e1317)), (_e1320.member_2[1] + (_e1313 * _e1323)), (_e1326.member_2[2] + (_e1313 * _e1329))), _e1333.member_3, _e1333.member_4, _e1333.member_5);
                                                                    let _e1341 = local_79;
                                                                    phi_1838_ = type_16(_e1340.member, _e1340.member_1, _e1340.member_2, (_e1341.member_3 + _e1313), _e1340.member_4, _e1340.member_5);
                                                                } else {
                                                                    phi_1838_ = _e1292;
                                                                }
                                                                let _e1352 = phi_1838_;
                                                                phi_1839_ = _e1352;
                                                            } else {
                                                                phi_1839_ = _e1292;
                                                            }
                                                            let _e1354 = phi_1839_;
                                                            phi_1840_ = _e1354;
                                                        }
                                                        let _e1356 = phi_1840_;
                                                        local_105 = _e1356;
                                                        let _e1357 = local_92;
                                                        let _e1358 = local_240;
                                                        let _e1359 = (_e1357 * _e1358);
                                                        local_106 = _e1359;
                                                        if (_e1359 <= 0f) {
                                                            phi_1906_ = _e1356;
                                                        } else {
                                                            let _e1361 = local_239;
                                                            let _e1363 = local_239;
                                                            let _e1365 = local_99;
                                                            let _e1367 = local_100;
                                                            let _e1369 = (((0.8660254f * _e1361) * _e1363) / ((_e1365 * -3.1415927f) * _e1367));
                                                            let _e1372 = local_100;
                                                            let _e1373 = local_88;
                                                            let _e1375 = local_239;
                                                            let _e1377 = ((_e1372 - _e1373) + (0.5f * _e1375));
                                                            let _e1379 = select(0f, _e1377, (_e1377 > 0f));
                                                            let _e1382 = local_106;
                                                            let _e1384 = ((_e1382 * select(1f, _e1379, (_e1379 < 1f))) * select(1f, _e1369, (_e1369 < 1f)));
                                                            let _e1385 = local_105;
                                                            let _e1388 = local_93;
                                                            let _e1391 = local_105;
                                                            let _e1394 = local_95;
                                                            let _e1397 = local_105;
                                                            let _e1400 = local_97;
                                                            let _e1404 = local_105;
                                                            let _e1411 = type_16(_e1404.member, _e1404.member_1, _e1404.member_2, _e1404.member_3, array<f32, 3>((_e1385.member_4[0] + (_e1384 * _e1388)), (_e1391.member_4[1] + (_e1384 * _e1394)), (_e1397.member_4[2] + (_e1384 * _e1400))), _e1404.member_5);
                                                            let _e1412 = local_105;
                                                            phi_1906_ = type_16(_e1411.member, _e1411.member_1, _e1411.member_2, _e1411.member_3, _e1411.member_4, (_e1412.member_5 + _e1384));
                                                        }
                                                        let _e1423 = phi_1906_;
                                                        phi_1908_ = _e1423;
                                                    } else {
                                                        phi_1908_ = _e1022;
                                                    }
                                                    let _e1425 = phi_1908_;
                                                    local_107 = _e1425;
                                                    let _e1426 = local_92;
                                                    if (_e1426 < 1f) {
                                                        let _e1428 = local_87;
                                                        let _e1429 = (_e1428 + 4u);
                                                        local_108 = _e1429;
                                                        let _e1430 = local_1;
                                                        if (_e1429 < _e1430) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1432 = local_108;
                                                        let _e1435 = global_3.member[_e1432];
                                                        local_109 = bitcast<f32>(_e1435);
                                                        let _e1437 = local_87;
                                                        let _e1438 = (_e1437 + 5u);
                                                        local_110 = _e1438;
                                                        let _e1439 = local_1;
                                                        if (_e1438 < _e1439) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1441 = local_110;
                                                        let _e1444 = global_3.member[_e1441];
                                                        local_111 = bitcast<f32>(_e1444);
                                                        let _e1446 = local_87;
                                                        let _e1447 = (_e1446 + 6u);
                                                        local_112 = _e1447;
                                                        let _e1448 = local_1;
                                                        if (_e1447 < _e1448) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1450 = local_112;
                                                        let _e1453 = global_3.member[_e1450];
                                                        local_113 = bitcast<f32>(_e1453);
                                                        let _e1455 = local_92;
                                                        let _e1456 = (1f - _e1455);
                                                        local_114 = _e1456;
                                                        let _e1457 = local_90;
                                                        local_115 = -(_e1457);
                                                        let _e1459 = local_90;
                                                        let _e1460 = (-0.5f - _e1459);
                                                        let _e1462 = select(0f, _e1460, (_e1460 > 0f));
                                                        let _e1464 = select(1f, _e1462, (_e1462 < 1f));
                                                        local_242 = _e1464;
                                                        let _e1466 = (_e1456 * (1f - _e1464));
                                                        local_116 = _e1466;
                                                        if (_e1466 <= 0f) {
                                                            phi_2094_ = _e1425;
                                                        } else {
                                                            let _e1468 = local_234;
                                                            let _e1470 = local_234;
                                                            local_243 = select(0f, _e1470, (_e1468 > 0f));
                                                            let _e1472 = local_90;
                                                            let _e1473 = local_234;
                                                            let _e1474 = (_e1472 > _e1473);
                                                            local_117 = _e1474;
                                                            if _e1474 {
                                                                let _e1480 = local_90;
                                                                let _e1482 = local_115;
                                                                let _e1483 = local_90;
                                                                let _e1484 = select(_e1483, _e1482, (_e1480 < 0f));
                                                                let _e1485 = local_243;
                                                                let _e1487 = local_243;
                                                                phi_1993_ = select(_e1487, _e1484, (_e1484 < _e1485));
                                                            } else {
                                                                let _e1475 = local_90;
                                                                let _e1477 = local_115;
                                                                let _e1478 = local_90;
                                                                phi_1993_ = select(_e1478, _e1477, (_e1475 < 0f));
                                                            }
                                                            let _e1490 = phi_1993_;
                                                            local_118 = _e1490;
                                                            let _e1491 = local_88;
                                                            if (_e1491 == 0f) {
                                                                phi_2011_ = 1f;
                                                            } else {
                                                                let _e1493 = local_118;
                                                                let _e1494 = local_88;
                                                                let _e1496 = local_239;
                                                                let _e1498 = ((_e1493 - _e1494) + (0.5f * _e1496));
                                                                let _e1500 = select(0f, _e1498, (_e1498 > 0f));
                                                                phi_2011_ = select(1f, _e1500, (_e1500 < 1f));
                                                            }
                                                            let _e1504 = phi_2011_;
                                                            let _e1505 = local_116;
                                                            let _e1507 = local_118;
                                                            let _e1508 = local_118;
                                                            let _e1509 = (_e1507 * _e1508);
                                                            let _e1512 = ((_e1505 * _e1504) / select(0.25f, _e1509, (_e1509 > 0.25f)));
                                                            let _e1513 = local_107;
                                                            let _e1516 = local_109;
                                                            let _e1519 = local_107;
                                                            let _e1522 = local_111;
                                                            let _e1525 = local_107;
                                                            let _e1528 = local_113;
                                                            let _e1532 = local_107;
                                                            let _e1539 = type_16(array<f32, 3>((_e1513.member[0] + (_e1512 * _e1516)), (_e1519.member[1] + (_e1512 * _e1522)), (_e1525.member[2] + (_e1512 * _e1528))), _e1532.member_1, _e1532.member_2, _e1532.member_3, _e1532.member_4, _e1532.member_5);
                                                            let _e1540 = local_107;
                                                            let _e1549 = type_16(_e1539.member, (_e1540.member_1 + _e1512), _e1539.member_2, _e1539.member_3, _e1539.member_4, _e1539.member_5);
                                                            local_119 = _e1549;
                                                            let _e1550 = local_117;
                                                            if _e1550 {
                                                                let _e1551 = local_235;
                                                                if (_e1551 > 0f) {
                                                                    let _e1553 = local_30;
                                                                    let _e1554 = local_88;
                                                                    let _e1556 = local_239;
                                                                    let _e1558 = ((_e1553 - _e1554) + (0.5f * _e1556));
                                                                    let _e1560 = select(0f, _e1558, (_e1558 > 0f));
                                                                    let _e1563 = local_116;
                                                                    let _e1565 = local_30;
                                                                    let _e1566 = local_30;
                                                                    let _e1567 = (_e1565 * _e1566);
                                                                    let _e1570 = ((_e1563 * select(1f, _e1560, (_e1560 < 1f))) / select(0.25f, _e1567, (_e1567 > 0.25f)));
                                                                    let _e1571 = local_107;
                                                                    let _e1574 = local_109;
                                                                    let _e1577 = local_107;
                                                                    let _e1580 = local_111;
                                                                    let _e1583 = local_107;
                                                                    let _e1586 = local_113;
                                                                    let _e1590 = local_119;
                                                                    let _e1597 = type_16(_e1590.member, _e1590.member_1, array<f32, 3>((_e1571.member_2[0] + (_e1570 * _e1574)), (_e1577.member_2[1] + (_e1570 * _e1580)), (_e1583.member_2[2] + (_e1570 * _e1586))), _e1590.member_3, _e1590.member_4, _e1590.member_5);
                                                                    let _e1598 = local_107;
                                                                    phi_2092_ = type_16(_e1597.member, _e1597.member_1, _e1597.member_2, (_e1598.member_3 + _e1570), _e1597.member_4, _e1597.member_5);
                                                                } else {
                                                                    phi_2092_ = _e1549;
                                                                }
                                                                let _e1609 = phi_2092_;
                                                                phi_2093_ = _e1609;
                                                            } else {
                                                                phi_2093_ = _e1549;
                                                            }
                                                            let _e1611 = phi_2093_;
                                                            phi_2094_ = _e1611;
                                                        }
                                                        let _e1613 = phi_2094_;
                                                        local_120 = _e1613;
                                                        let _e1614 = local_114;
                                                        let _e1615 = local_242;
                                                        let _e1616 = (_e1614 * _e1615);
                                                        local_121 = _e1616;
                                                        if (_e1616 <= 0f) {
                                                            phi_2161_ = _e1613;
                                                        } else {
                                                            let _e1618 = local_239;
                                                            let _e1620 = local_239;
                                                            let _e1622 = local_90;
                                                            let _e1624 = local_115;
                                                            let _e1626 = (((0.8660254f * _e1618) * _e1620) / ((_e1622 * -3.1415927f) * _e1624));
                                                            let _e1629 = local_115;
                                                            let _e1630 = local_88;
                                                            let _e1632 = local_239;
                                                            let _e1634 = ((_e1629 - _e1630) + (0.5f * _e1632));
                                                            let _e1636 = select(0f, _e1634, (_e1634 > 0f));
                                                            let _e1639 = local_121;
                                                            let _e1641 = ((_e1639 * select(1f, _e1636, (_e1636 < 1f))) * select(1f, _e1626, (_e1626 < 1f)));
                                                            let _e1642 = local_120;
                                                            let _e1645 = local_109;
                                                            let _e1648 = local_120;
                                                            let _e1651 = local_111;
                                                            let _e1654 = local_120;
                                                            let _e1657 = local_113;
                                                            let _e1661 = local_120;
                                                            let _e1668 = type_16(_e1661.member, _e1661.member_1, _e1661.member_2, _e1661.member_3, array<f32, 3>((_e1642.member_4[0] + (_e1641 * _e1645)), (_e1648.member_4[1] + (_e1641 * _e1651)), (_e1654.member_4[2] + (_e1641 * _e1657))), _e1661.member_5);
                                                            let _e1669 = local_120;
                                                            phi_2161_ = type_16(_e1668.member, _e1668.member_1, _e1668.member_2, _e1668.member_3, _e1668.member_4, (_e1669.member_5 + _e1641));
                                                        }
                                                        let _e1680 = phi_2161_;
                                                        phi_2163_ = _e1680;
                                                    } else {
                                                        phi_2163_ = _e1425;
                                                    }
                                                    let _e1682 = phi_2163_;
                                                    phi_2164_ = _e1682;
                                                }
                                                let _e1684 = phi_2164_;
                                                let _e1685 = local_80;
                                                phi_1463_ = _e1684;
                                                phi_1466_ = (_e1685 + 1u);
                                            } else {
                                                phi_1463_ = type_16();
                                                phi_1466_ = u32();
                                            }
                                            let _e1688 = phi_1463_;
                                            let _e1690 = phi_1466_;
                                            continue;
                                            continuing {
                                                let _e1691 = local_81;
                                                phi_1462_ = _e1688;
                                                phi_1465_ = _e1690;
                                                phi_3944_ = _e1013;
                                                break if !(_e1691);
                                            }
                                        }
                                        let _e1694 = phi_3944_;
                                        phi_4151_ = _e1694;
                                        if _e1694 {
                                            break;
                                        }
                                        let _e1695 = local_77;
                                        phi_4152_ = _e1694;
                                        let _e3004 = local_249;
                                        phi_1451_ = _e3004;
                                        phi_1454_ = (_e1695 + 1u);
                                    } else {
                                        phi_4152_ = _e1013;
                                        phi_1451_ = type_16();
                                        phi_1454_ = u32();
                                    }
                                    let _e1698 = phi_4152_;
                                    let _e1700 = phi_1451_;
                                    let _e1702 = phi_1454_;
                                    continue;
                                    continuing {
                                        let _e1703 = local_78;
                                        phi_3954_ = _e1698;
                                        phi_1450_ = _e1700;
                                        phi_1453_ = _e1702;
                                        phi_4151_ = _e1698;
                                        break if !(_e1703);
                                    }
                                }
                                let _e1706 = phi_4151_;
                                if _e1706 {
                                    break;
                                }
                                phi_4171_ = _e1706;
                                let _e3010 = local_250;
                                phi_2167_ = _e3010;
                            } else {
                                phi_4171_ = false;
                                phi_2167_ = type_16();
                            }
                            let _e1708 = phi_4171_;
                            let _e1710 = phi_2167_;
                            let _e1711 = local_71;
                            phi_4170_ = _e1708;
                            phi_2169_ = _e1710;
                            phi_2170_ = select(true, false, _e1711);
                        } else {
                            phi_4170_ = false;
                            phi_2169_ = type_16();
                            phi_2170_ = true;
                        }
                        let _e1714 = phi_4170_;
                        let _e1716 = phi_2169_;
                        let _e1718 = phi_2170_;
                        phi_4169_ = _e1714;
                        phi_2171_ = _e1716;
                        phi_2172_ = _e1718;
                    } else {
                        phi_4169_ = false;
                        phi_2171_ = type_16();
                        phi_2172_ = true;
                    }
                    let _e1720 = phi_4169_;
                    let _e1722 = phi_2171_;
                    let _e1724 = phi_2172_;
                    if _e1724 {
                        let _e1725 = local_69;
                        if _e1725 {
                            let _e1726 = local_7;
                            if _e1726 {
                                let _e1727 = local_6;
                                phi_2196_ = (_e1727 + 1u);
                            } else {
                                phi_2196_ = _e305;
                            }
                            let _e1730 = phi_2196_;
                            local_122 = _e1730;
                            let _e1731 = local_10;
                            if _e1731 {
                                let _e1732 = local_9;
                                phi_2214_ = (_e1732 + 1u);
                            } else {
                                phi_2214_ = _e315;
                            }
                            let _e1735 = phi_2214_;
                            local_123 = _e1735;
                            let _e1738 = global_2.member.member_2;
                            let _e1740 = select(_e1738, 1u, (_e1738 == 0u));
                            let _e1741 = f32(_e1740);
                            local_124 = _e1741;
                            let _e1742 = local_30;
                            let _e1743 = (_e1742 / _e1741);
                            let _e1745 = select(1f, _e1743, (_e1743 > 1f));
                            local_244 = _e1745;
                            let _e1746 = local_30;
                            let _e1749 = ceil(((_e1746 / _e1745) + 0.5f));
                            local_125 = _e1749;
                            if (_e1749 < 1f) {
                                phi_2251_ = 1u;
                            } else {
                                let _e1751 = local_125;
                                let _e1752 = local_124;
                                if (_e1751 < _e1752) {
                                    let _e1754 = local_125;
                                    let _e1756 = local_125;
                                    let _e1758 = local_125;
                                    phi_2250_ = select(select(u32(_e1754), 0u, (_e1756 < 0f)), 4294967295u, (_e1758 > 4294967000f));
                                } else {
                                    phi_2250_ = _e1740;
                                }
                                let _e1763 = phi_2250_;
                                phi_2251_ = _e1763;
                            }
                            let _e1765 = phi_2251_;
                            local_126 = _e1765;
                            phi_4163_ = _e1720;
                            phi_2253_ = _e963;
                            phi_2256_ = 1u;
                            loop {
                                let _e1767 = phi_4163_;
                                let _e1769 = phi_2253_;
                                let _e1771 = phi_2256_;
                                local_127 = _e1771;
                                local_252 = _e1769;
                                let _e1772 = local_127;
                                let _e1773 = local_126;
                                let _e1774 = (_e1772 <= _e1773);
                                local_128 = _e1774;
                                if _e1774 {
                                    phi_2265_ = _e1769;
                                    phi_2268_ = 0u;
                                    loop {
                                        let _e1776 = phi_2265_;
                                        let _e1778 = phi_2268_;
                                        local_129 = _e1776;
                                        local_130 = _e1778;
                                        local_251 = _e1776;
                                        let _e1779 = local_127;
                                        let _e1781 = local_130;
                                        let _e1782 = (_e1781 < (6u * _e1779));
                                        local_131 = _e1782;
                                        if _e1782 {
                                            let _e1783 = local_127;
                                            let _e1784 = (_e1783 == 0u);
                                            local_132 = _e1784;
                                            if _e1784 {
                                                phi_4153_ = true;
                                                break;
                                            }
                                            let _e1785 = local_130;
                                            let _e1786 = local_127;
                                            local_133 = (_e1785 / _e1786);
                                            let _e1788 = local_132;
                                            if _e1788 {
                                                phi_4153_ = true;
                                                break;
                                            }
                                            let _e1789 = local_130;
                                            let _e1790 = local_127;
                                            local_134 = f32((_e1789 % _e1790));
                                            let _e1793 = local_133;
                                            if (_e1793 == 0u) {
                                                phi_2320_ = array<f32, 2>(1f, 0f);
                                            } else {
                                                let _e1795 = local_133;
                                                if (_e1795 == 1u) {
                                                    phi_2319_ = array<f32, 2>(0.5f, 0.8660254f);
                                                } else {
                                                    let _e1797 = local_133;
                                                    if (_e1797 == 2u) {
                                                        phi_2318_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                    } else {
                                                        let _e1799 = local_133;
                                                        if (_e1799 == 3u) {
                                                            phi_2317_ = array<f32, 2>(-1f, 0f);
                                                        } else {
                                                            let _e1801 = local_133;
                                                            if (_e1801 == 4u) {
                                                                phi_2316_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                            } else {
                                                                phi_2316_ = array<f32, 2>(0.5f, -0.8660254f);
                                                            }
                                                            let _e1804 = phi_2316_;
                                                            phi_2317_ = _e1804;
                                                        }
                                                        let _e1806 = phi_2317_;
                                                        phi_2318_ = _e1806;
                                                    }
                                                    let _e1808 = phi_2318_;
                                                    phi_2319_ = _e1808;
                                                }
                                                let _e1810 = phi_2319_;
                                                phi_2320_ = _e1810;
                                            }
                                            let _e1812 = phi_2320_;
                                            local_135 = _e1812;
                                            let _e1813 = local_133;
                                            let _e1815 = ((_e1813 + 1u) % 6u);
                                            local_136 = _e1815;
                                            if (_e1815 == 0u) {
                                                phi_2355_ = array<f32, 2>(1f, 0f);
                                            } else {
                                                let _e1817 = local_136;
                                                if (_e1817 == 1u) {
                                                    phi_2354_ = array<f32, 2>(0.5f, 0.8660254f);
                                                } else {
                                                    let _e1819 = local_136;
                                                    if (_e1819 == 2u) {
                                                        phi_2353_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                    } else {
                                                        let _e1821 = local_136;
                                                        if (_e1821 == 3u) {
                                                            phi_2352_ = array<f32, 2>(-1f, 0f);
                                                        } else {
                                                            let _e1823 = local_136;
                                                            if (_e1823 == 4u) {
                                                                phi_2351_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                            } else {
                                                                phi_2351_ = array<f32, 2>(0.5f, -0.8660254f);
                                                            }
                                                            let _e1826 = phi_2351_;
                                                            phi_2352_ = _e1826;
                                                        }
                                                        let _e1828 = phi_2352_;
                                                        phi_2353_ = _e1828;
                                                    }
                                                    let _e1830 = phi_2353_;
                                                    phi_2354_ = _e1830;
                                                }
                                                let _e1832 = phi_2354_;
                                                phi_2355_ = _e1832;
                                            }
                                            let _e1834 = phi_2355_;
                                            let _e1835 = local_127;
                                            let _e1836 = f32(_e1835);
                                            let _e1837 = local_135;
                                            let _e1842 = local_134;
                                            let _e1845 = local_135;
                                            let _e1850 = local_134;
                                            let _e1853 = local_244;
                                            let _e1854 = (((_e1837[0] * _e1836) + ((_e1834[0] - _e1837[0]) * _e1842)) * _e1853);
                                            let _e1855 = local_244;
                                            let _e1856 = (((_e1845[1] * _e1836) + ((_e1834[1] - _e1845[1]) * _e1850)) * _e1855);
                                            let _e1857 = local_12;
                                            let _e1861 = floor(((f32(_e1857) + 0.5f) + _e1854));
                                            let _e1862 = local_13;
                                            let _e1866 = floor(((f32(_e1862) + 0.5f) + _e1856));
                                            let _e1868 = select(0f, _e1861, (_e1861 > 0f));
                                            let _e1869 = local_122;
                                            let _e1871 = f32((_e1869 - 1u));
                                            let _e1873 = select(_e1871, _e1868, (_e1868 < _e1871));
                                            let _e1880 = select(0f, _e1866, (_e1866 > 0f));
                                            let _e1881 = local_123;
                                            let _e1883 = f32((_e1881 - 1u));
                                            let _e1885 = select(_e1883, _e1880, (_e1880 < _e1883));
                                            let _e1891 = local_122;
                                            let _e1894 = (9u * ((select(select(u32(_e1885), 0u, (_e1885 < 0f)), 4294967295u, (_e1885 > 4294967000f)) * _e1891) + select(select(u32(_e1873), 0u, (_e1873 < 0f)), 4294967295u, (_e1873 > 4294967000f))));
                                            local_137 = _e1894;
                                            local_138 = sqrt(((_e1854 * _e1854) + (_e1856 * _e1856)));
                                            let _e1899 = (_e1894 + 8u);
                                            local_139 = _e1899;
                                            let _e1900 = local_1;
                                            if (_e1899 < _e1900) {
                                            } else {
                                                phi_4153_ = true;
                                                break;
                                            }
                                            let _e1902 = local_139;
                                            let _e1905 = global_3.member[_e1902];
                                            let _e1906 = bitcast<f32>(_e1905);
                                            local_140 = _e1906;
                                            if ((bitcast<u32>(_e1906) & 2147483647u) > 2139095040u) {
                                                phi_2967_ = _e1776;
                                            } else {
                                                let _e1910 = local_137;
                                                let _e1911 = (_e1910 + 3u);
                                                local_141 = _e1911;
                                                let _e1912 = local_1;
                                                if (_e1911 < _e1912) {
                                                } else {
                                                    phi_4153_ = true;
                                                    break;
                                                }
                                                let _e1914 = local_141;
                                                let _e1917 = global_3.member[_e1914];
                                                let _e1918 = bitcast<f32>(_e1917);
                                                local_142 = _e1918;
                                                if (_e1918 > 0f) {
                                                    let _e1920 = local_137;
                                                    let _e1921 = local_1;
                                                    if (_e1920 < _e1921) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e1923 = local_137;
                                                    let _e1926 = global_3.member[_e1923];
                                                    local_143 = bitcast<f32>(_e1926);
                                                    let _e1928 = local_137;
                                                    let _e1929 = (_e1928 + 1u);
                                                    local_144 = _e1929;
                                                    let _e1930 = local_1;
                                                    if (_e1929 < _e1930) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e1932 = local_144;
                                                    let _e1935 = global_3.member[_e1932];
                                                    local_145 = bitcast<f32>(_e1935);
                                                    let _e1937 = local_137;
                                                    let _e1938 = (_e1937 + 2u);
                                                    local_146 = _e1938;
                                                    let _e1939 = local_1;
                                                    if (_e1938 < _e1939) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e1941 = local_146;
                                                    let _e1944 = global_3.member[_e1941];
                                                    local_147 = bitcast<f32>(_e1944);
                                                    let _e1946 = local_137;
                                                    let _e1947 = (_e1946 + 7u);
                                                    local_148 = _e1947;
                                                    let _e1948 = local_1;
                                                    if (_e1947 < _e1948) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e1950 = local_148;
                                                    let _e1953 = global_3.member[_e1950];
                                                    let _e1954 = bitcast<f32>(_e1953);
                                                    local_149 = _e1954;
                                                    local_150 = -(_e1954);
                                                    let _e1956 = (-0.5f - _e1954);
                                                    let _e1958 = select(0f, _e1956, (_e1956 > 0f));
                                                    let _e1962 = local_142;
                                                    let _e1963 = (_e1962 * (1f - select(1f, _e1958, (_e1958 < 1f))));
                                                    local_151 = _e1963;
                                                    if (_e1963 <= 0f) {
                                                        phi_2643_ = _e1776;
                                                    } else {
                                                        let _e1965 = local_234;
                                                        let _e1967 = local_234;
                                                        local_245 = select(0f, _e1967, (_e1965 > 0f));
                                                        let _e1969 = local_149;
                                                        let _e1970 = local_234;
                                                        let _e1971 = (_e1969 > _e1970);
                                                        local_152 = _e1971;
                                                        if _e1971 {
                                                            let _e1977 = local_149;
                                                            let _e1979 = local_150;
                                                            let _e1980 = local_149;
                                                            let _e1981 = select(_e1980, _e1979, (_e1977 < 0f));
                                                            let _e1982 = local_245;
                                                            let _e1984 = local_245;
                                                            phi_2542_ = select(_e1984, _e1981, (_e1981 < _e1982));
                                                        } else {
                                                            let _e1972 = local_149;
                                                            let _e1974 = local_150;
                                                            let _e1975 = local_149;
                                                            phi_2542_ = select(_e1975, _e1974, (_e1972 < 0f));
                                                        }
                                                        let _e1987 = phi_2542_;
                                                        local_153 = _e1987;
                                                        let _e1988 = local_138;
                                                        if (_e1988 == 0f) {
                                                            phi_2560_ = 1f;
                                                        } else {
                                                            let _e1990 = local_153;
                                                            let _e1991 = local_138;
                                                            let _e1993 = local_244;
                                                            let _e1995 = ((_e1990 - _e1991) + (0.5f * _e1993));
                                                            let _e1997 = select(0f, _e1995, (_e1995 > 0f));
                                                            phi_2560_ = select(1f, _e1997, (_e1997 < 1f));
                                                        }
                                                        let _e2001 = phi_2560_;
                                                        let _e2002 = local_151;
                                                        let _e2004 = local_153;
                                                        let _e2005 = local_153;
                                                        let _e2006 = (_e2004 * _e2005);
                                                        let _e2009 = ((_e2002 * _e2001) / select(0.25f, _e2006, (_e2006 > 0.25f)));
                                                        let _e2010 = local_129;
                                                        let _e2013 = local_143;
                                                        let _e2016 = local_129;
                                                        let _e2019 = local_145;
                                                        let _e2022 = local_129;
                                                        let _e2025 = local_147;
                                                        let _e2029 = local_129;
                                                        let _e2036 = type_16(array<f32, 3>((_e2010.member[0] + (_e2009 * _e2013)), (_e2016.member[1] + (_e2009 * _e2019)), (_e2022.member[2] + (_e2009 * _e2025))), _e2029.member_1, _e2029.member_2, _e2029.member_3, _e2029.member_4, _e2029.member_5);
                                                        let _e2037 = local_129;
                                                        let _e2046 = type_16(_e2036.member, (_e2037.member_1 + _e2009), _e2036.member_2, _e2036.member_3, _e2036.member_4, _e2036.member_5);
                                                        local_154 = _e2046;
                                                        let _e2047 = local_152;
                                                        if _e2047 {
                                                            let _e2048 = local_235;
                                                            if (_e2048 > 0f) {
                                                                let _e2050 = local_30;
                                                                let _e2051 = local_138;
                                                                let _e2053 = local_244;
                                                                let _e2055 = ((_e2050 - _e2051) + (0.5f * _e2053));
                                                                let _e2057 = select(0f, _e2055, (_e2055 > 0f));
                                                                let _e2060 = local_151;
                                                                let _e2062 = local_30;
                                                                let _e2063 = local_30;
                                                                let _e2064 = (_e2062 * _e2063);
                                                                let _e2067 = ((_e2060 * select(1f, _e2057, (_e2057 < 1f))) / select(0.25f, _e2064, (_e2064 > 0.25f)));
                                                                let _e2068 = local_129;
                                                                let _e2071 = local_143;
                                                                let _e2074 = local_129;
                                                                let _e2077 = local_145;
                                                                let _e2080 = local_129;
                                                                let _e2083 = local_147;
                                                                let _e2087 = local_154;
                                                                let _e2094 = type_16(_e2087.member, _e2087.member_1, array<f32, 3>((_e2068.member_2[0] + (_e2067 * _e2071)), (_e2074.member_2[1] + (_e2067 * _e2077)), (_e2080.member_2[2] + (_e2067 * _e2083))), _e2087.member_3, _e2087.member_4, _e2087.member_5);
                                                                let _e2095 = local_129;
                                                                phi_2641_ = type_16(_e2094.member, _e2094.member_1, _e2094.member_2, (_e2095.member_3 + _e2067), _e2094.member_4, _e2094.member_5);
                                                            } else {
                                                                phi_2641_ = _e2046;
                                                            }
                                                            let _e2106 = phi_2641_;
                                                            phi_2642_ = _e2106;
                                                        } else {
                                                            phi_2642_ = _e2046;
                                                        }
                                                        let _e2108 = phi_2642_;
                                                        phi_2643_ = _e2108;
                                                    }
                                                    let _e2110 = phi_2643_;
                                                    phi_2711_ = _e2110;
                                                } else {
                                                    phi_2711_ = _e1776;
                                                }
                                                let _e2112 = phi_2711_;
                                                local_155 = _e2112;
                                                let _e2113 = local_142;
                                                if (_e2113 < 1f) {
                                                    let _e2115 = local_137;
                                                    let _e2116 = (_e2115 + 4u);
                                                    local_156 = _e2116;
                                                    let _e2117 = local_1;
                                                    if (_e2116 < _e2117) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e2119 = local_156;
                                                    let _e2122 = global_3.member[_e2119];
                                                    local_157 = bitcast<f32>(_e2122);
                                                    let _e2124 = local_137;
                                                    let _e2125 = (_e2124 + 5u);
                                                    local_158 = _e2125;
                                                    let _e2126 = local_1;
                                                    if (_e2125 < _e2126) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e2128 = local_158;
                                                    let _e2131 = global_3.member[_e2128];
                                                    local_159 = bitcast<f32>(_e2131);
                                                    let _e2133 = local_137;
                                                    let _e2134 = (_e2133 + 6u);
                                                    local_160 = _e2134;
                                                    let _e2135 = local_1;
                                                    if (_e2134 < _e2135) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e2137 = local_160;
                                                    let _e2140 = global_3.member[_e2137];
                                                    local_161 = bitcast<f32>(_e2140);
                                                    let _e2142 = local_142;
                                                    let _e2144 = local_140;
                                                    local_162 = -(_e2144);
                                                    let _e2146 = local_140;
                                                    let _e2147 = (-0.5f - _e2146);
                                                    let _e2149 = select(0f, _e2147, (_e2147 > 0f));
                                                    let _e2153 = ((1f - _e2142) * (1f - select(1f, _e2149, (_e2149 < 1f))));
                                                    local_163 = _e2153;
                                                    if (_e2153 <= 0f) {
                                                        phi_2897_ = _e2112;
                                                    } else {
                                                        let _e2155 = local_234;
                                                        let _e2157 = local_234;
                                                        local_246 = select(0f, _e2157, (_e2155 > 0f));
                                                        let _e2159 = local_140;
                                                        let _e2160 = local_234;
                                                        let _e2161 = (_e2159 > _e2160);
                                                        local_164 = _e2161;
                                                        if _e2161 {
                                                            let _e2167 = local_140;
                                                            let _e2169 = local_162;
                                                            let _e2170 = local_140;
                                                            let _e2171 = select(_e2170, _e2169, (_e2167 < 0f));
                                                            let _e2172 = local_246;
                                                            let _e2174 = local_246;
                                                            phi_2796_ = select(_e2174, _e2171, (_e2171 < _e2172));
                                                        } else {
                                                            let _e2162 = local_140;
                                                            let _e2164 = local_162;
                                                            let _e2165 = local_140;
                                                            phi_2796_ = select(_e2165, _e2164, (_e2162 < 0f));
                                                        }
                                                        let _e2177 = phi_2796_;
                                                        local_165 = _e2177;
                                                        let _e2178 = local_138;
                                                        if (_e2178 == 0f) {
                                                            phi_2814_ = 1f;
                                                        } else {
                                                            let _e2180 = local_165;
                                                            let _e2181 = local_138;
                                                            let _e2183 = local_244;
                                                            let _e2185 = ((_e2180 - _e2181) + (0.5f * _e2183));
                                                            let _e2187 = select(0f, _e2185, (_e2185 > 0f));
                                                            phi_2814_ = select(1f, _e2187, (_e2187 < 1f));
                                                        }
                                                        let _e2191 = phi_2814_;
                                                        let _e2192 = local_163;
                                                        let _e2194 = local_165;
                                                        let _e2195 = local_165;
                                                        let _e2196 = (_e2194 * _e2195);
                                                        let _e2199 = ((_e2192 * _e2191) / select(0.25f, _e2196, (_e2196 > 0.25f)));
                                                        let _e2200 = local_155;
                                                        let _e2203 = local_157;
                                                        let _e2206 = local_155;
                                                        let _e2209 = local_159;
                                                        let _e2212 = local_155;
                                                        let _e2215 = local_161;
                                                        let _e2219 = local_155;
                                                        let _e2226 = type_16(array<f32, 3>((_e2200.member[0] + (_e2199 * _e2203)), (_e2206.member[1] + (_e2199 * _e2209)), (_e2212.member[2] + (_e2199 * _e2215))), _e2219.member_1, _e2219.member_2, _e2219.member_3, _e2219.member_4, _e2219.member_5);
                                                        let _e2227 = local_155;
                                                        let _e2236 = type_16(_e2226.member, (_e2227.member_1 + _e2199), _e2226.member_2, _e2226.member_3, _e2226.member_4, _e2226.member_5);
                                                        local_166 = _e2236;
                                                        let _e2237 = local_164;
                                                        if _e2237 {
                                                            let _e2238 = local_235;
                                                            if (_e2238 > 0f) {
                                                                let _e2240 = local_30;
                                                                let _e2241 = local_138;
                                                                let _e2243 = local_244;
                                                                let _e2245 = ((_e2240 - _e2241) + (0.5f * _e2243));
                                                                let _e2247 = select(0f, _e2245, (_e2245 > 0f));
                                                                let _e2250 = local_163;
                                                                let _e2252 = local_30;
                                                                let _e2253 = local_30;
                                                                let _e2254 = (_e2252 * _e2253);
                                                                let _e2257 = ((_e2250 * select(1f, _e2247, (_e2247 < 1f))) / select(0.25f, _e2254, (_e2254 > 0.25f)));
                                                                let _e2258 = local_155;
                                                                let _e2261 = local_157;
                                                                let _e2264 = local_155;
                                                                let _e2267 = local_159;
                                                                let _e2270 = local_155;
                                                                let _e2273 = local_161;
                                                                let _e2277 = local_166;
                                                                let _e2284 = type_16(_e2277.member, _e2277.member_1, array<f32, 3>((_e2258.member_2[0] + (_e2257 * _e2261)), (_e2264.member_2[1] + (_e2257 * _e2267)), (_e2270.member_2[2] + (_e2257 * _e2273))), _e2277.member_3, _e2277.member_4, _e2277.member_5);
                                                                let _e2285 = local_155;
                                                                phi_2895_ = type_16(_e2284.member, _e2284.member_1, _e2284.member_2, (_e2285.member_3 + _e2257), _e2284.member_4, _e2284.member_5);
                                                            } else {
                                                                phi_2895_ = _e2236;
                                                            }
                                                            let _e2296 = phi_2895_;
                                                            phi_2896_ = _e2296;
                                                        } else {
                                                            phi_2896_ = _e2236;
                                                        }
                                                        let _e2298 = phi_2896_;
                                                        phi_2897_ = _e2298;
                                                    }
                                                    let _e2300 = phi_2897_;
                                                    phi_2966_ = _e2300;
                                                } else {
                                                    phi_2966_ = _e2112;
                                                }
                                                let _e2302 = phi_2966_;
                                                phi_2967_ = _e2302;
                                            }
                                            let _e2304 = phi_2967_;
                                            let _e2305 = local_130;
                                            phi_2266_ = _e2304;
                                            phi_2269_ = (_e2305 + 1u);
                                        } else {
                                            phi_2266_ = type_16();
                                            phi_2269_ = u32();
                                        }
                                        let _e2308 = phi_2266_;
                                        let _e2310 = phi_2269_;
                                        continue;
                                        continuing {
                                            let _e2311 = local_131;
                                            phi_2265_ = _e2308;
                                            phi_2268_ = _e2310;
                                            phi_4153_ = _e1767;
                                            break if !(_e2311);
                                        }
                                    }
                                    let _e2314 = phi_4153_;
                                    phi_4237_ = _e2314;
                                    if _e2314 {
                                        break;
                                    }
                                    let _e2315 = local_127;
                                    phi_4238_ = _e2314;
                                    let _e3055 = local_251;
                                    phi_2254_ = _e3055;
                                    phi_2257_ = (_e2315 + 1u);
                                } else {
                                    phi_4238_ = _e1767;
                                    phi_2254_ = type_16();
                                    phi_2257_ = u32();
                                }
                                let _e2318 = phi_4238_;
                                let _e2320 = phi_2254_;
                                let _e2322 = phi_2257_;
                                continue;
                                continuing {
                                    let _e2323 = local_128;
                                    phi_4163_ = _e2318;
                                    phi_2253_ = _e2320;
                                    phi_2256_ = _e2322;
                                    phi_4237_ = _e2318;
                                    break if !(_e2323);
                                }
                            }
                            let _e2326 = phi_4237_;
                            if _e2326 {
                                break;
                            }
                            phi_4255_ = _e2326;
                            let _e3061 = local_252;
                            phi_2970_ = _e3061;
                        } else {
                            phi_4255_ = _e1720;
                            phi_2970_ = _e963;
                        }
                        let _e2328 = phi_4255_;
                        let _e2330 = phi_2970_;
                        let _e2331 = local_70;
                        if _e2331 {
                            let _e2332 = local_7;
                            if _e2332 {
                                let _e2333 = local_6;
                                phi_2991_ = (_e2333 + 1u);
                            } else {
                                phi_2991_ = _e305;
                            }
                            let _e2336 = phi_2991_;
                            local_167 = _e2336;
                            let _e2337 = local_10;
                            if _e2337 {
                                let _e2338 = local_9;
                                phi_3009_ = (_e2338 + 1u);
                            } else {
                                phi_3009_ = _e315;
                            }
                            let _e2341 = phi_3009_;
                            local_168 = _e2341;
                            let _e2344 = global_2.member.member_2;
                            let _e2346 = select(_e2344, 1u, (_e2344 == 0u));
                            let _e2347 = f32(_e2346);
                            local_169 = _e2347;
                            let _e2348 = local_28;
                            let _e2349 = (_e2348 / _e2347);
                            let _e2351 = select(1f, _e2349, (_e2349 > 1f));
                            local_247 = _e2351;
                            let _e2352 = local_28;
                            let _e2355 = ceil(((_e2352 / _e2351) + 0.5f));
                            local_170 = _e2355;
                            if (_e2355 < 1f) {
                                phi_3046_ = 1u;
                            } else {
                                let _e2357 = local_170;
                                let _e2358 = local_169;
                                if (_e2357 < _e2358) {
                                    let _e2360 = local_170;
                                    let _e2362 = local_170;
                                    let _e2364 = local_170;
                                    phi_3045_ = select(select(u32(_e2360), 0u, (_e2362 < 0f)), 4294967295u, (_e2364 > 4294967000f));
                                } else {
                                    phi_3045_ = _e2346;
                                }
                                let _e2369 = phi_3045_;
                                phi_3046_ = _e2369;
                            }
                            let _e2371 = phi_3046_;
                            local_171 = _e2371;
                            phi_4249_ = _e2328;
                            phi_3048_ = _e2330;
                            phi_3051_ = 1u;
                            loop {
                                let _e2373 = phi_4249_;
                                let _e2375 = phi_3048_;
                                let _e2377 = phi_3051_;
                                local_172 = _e2377;
                                local_254 = _e2375;
                                let _e2378 = local_172;
                                let _e2379 = local_171;
                                let _e2380 = (_e2378 <= _e2379);
                                local_173 = _e2380;
                                if _e2380 {
                                    phi_3060_ = _e2375;
                                    phi_3063_ = 0u;
                                    loop {
                                        let _e2382 = phi_3060_;
                                        let _e2384 = phi_3063_;
                                        local_174 = _e2382;
                                        local_175 = _e2384;
                                        local_253 = _e2382;
                                        let _e2385 = local_172;
                                        let _e2387 = local_175;
                                        let _e2388 = (_e2387 < (6u * _e2385));
                                        local_176 = _e2388;
                                        if _e2388 {
                                            let _e2389 = local_172;
                                            let _e2390 = (_e2389 == 0u);
                                            local_177 = _e2390;
                                            if _e2390 {
                                                phi_4239_ = true;
                                                break;
                                            }
                                            let _e2391 = local_175;
                                            let _e2392 = local_172;
                                            local_178 = (_e2391 / _e2392);
                                            let _e2394 = local_177;
                                            if _e2394 {
                                                phi_4239_ = true;
                                                break;
                                            }
                                            let _e2395 = local_175;
                                            let _e2396 = local_172;
                                            local_179 = f32((_e2395 % _e2396));
                                            let _e2399 = local_178;
                                            if (_e2399 == 0u) {
                                                phi_3115_ = array<f32, 2>(1f, 0f);
                                            } else {
                                                let _e2401 = local_178;
                                                if (_e2401 == 1u) {
                                                    phi_3114_ = array<f32, 2>(0.5f, 0.8660254f);
                                                } else {
                                                    let _e2403 = local_178;
                                                    if (_e2403 == 2u) {
                                                        phi_3113_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                    } else {
                                                        let _e2405 = local_178;
                                                        if (_e2405 == 3u) {
                                                            phi_3112_ = array<f32, 2>(-1f, 0f);
                                                        } else {
                                                            let _e2407 = local_178;
                                                            if (_e2407 == 4u) {
                                                                phi_3111_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                            } else {
                                                                phi_3111_ = array<f32, 2>(0.5f, -0.8660254f);
                                                            }
                                                            let _e2410 = phi_3111_;
                                                            phi_3112_ = _e2410;
                                                        }
                                                        let _e2412 = phi_3112_;
                                                        phi_3113_ = _e2412;
                                                    }
                                                    let _e2414 = phi_3113_;
                                                    phi_3114_ = _e2414;
                                                }
                                                let _e2416 = phi_3114_;
                                                phi_3115_ = _e2416;
                                            }
                                            let _e2418 = phi_3115_;
                                            local_180 = _e2418;
                                            let _e2419 = local_178;
                                            let _e2421 = ((_e2419 + 1u) % 6u);
                                            local_181 = _e2421;
                                            if (_e2421 == 0u) {
                                                phi_3150_ = array<f32, 2>(1f, 0f);
                                            } else {
                                                let _e2423 = local_181;
                                                if (_e2423 == 1u) {
                                                    phi_3149_ = array<f32, 2>(0.5f, 0.8660254f);
                                                } else {
                                                    let _e2425 = local_181;
                                                    if (_e2425 == 2u) {
                                                        phi_3148_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                    } else {
                                                        let _e2427 = local_181;
                                                        if (_e2427 == 3u) {
                                                            phi_3147_ = array<f32, 2>(-1f, 0f);
                                                        } else {
                                                            let _e2429 = local_181;
                                                            if (_e2429 == 4u) {
                                                                phi_3146_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                            } else {
                                                                phi_3146_ = array<f32, 2>(0.5f, -0.8660254f);
                                                            }
                                                            let _e2432 = phi_3146_;
                                                            phi_3147_ = _e2432;
                                                        }
                                                        let _e2434 = phi_3147_;
                                                        phi_3148_ = _e2434;
                                                    }
                                                    let _e2436 = phi_3148_;
                                                    phi_3149_ = _e2436;
                                                }
                                                let _e2438 = phi_3149_;
                                                phi_3150_ = _e2438;
                                            }
                                            let _e2440 = phi_3150_;
                                            let _e2441 = local_172;
                                            let _e2442 = f32(_e2441);
                                            let _e2443 = local_180;
                                            let _e2448 = local_179;
                                            let _e2451 = local_180;
                                            let _e2456 = local_179;
                                            let _e2459 = local_247;
                                            let _e2460 = (((_e2443[0] * _e2442) + ((_e2440[0] - _e2443[0]) * _e2448)) * _e2459);
                                            let _e2461 = local_247;
                                            let _e2462 = (((_e2451[1] * _e2442) + ((_e2440[1] - _e2451[1]) * _e2456)) * _e2461);
                                            let _e2463 = local_12;
                                            let _e2467 = floor(((f32(_e2463) + 0.5f) + _e2460));
                                            let _e2468 = local_13;
                                            let _e2472 = floor(((f32(_e2468) + 0.5f) + _e2462));
                                            let _e2474 = select(0f, _e2467, (_e2467 > 0f));
                                            let _e2475 = local_167;
                                            let _e2477 = f32((_e2475 - 1u));
                                            let _e2479 = select(_e2477, _e2474, (_e2474 < _e2477));
                                            let _e2486 = select(0f, _e2472, (_e2472 > 0f));
                                            let _e2487 = local_168;
                                            let _e2489 = f32((_e2487 - 1u));
                                            let _e2491 = select(_e2489, _e2486, (_e2486 < _e2489));
                                            let _e2497 = local_167;
                                            let _e2500 = (9u * ((select(select(u32(_e2491), 0u, (_e2491 < 0f)), 4294967295u, (_e2491 > 4294967000f)) * _e2497) + select(select(u32(_e2479), 0u, (_e2479 < 0f)), 4294967295u, (_e2479 > 4294967000f))));
                                            local_182 = _e2500;
                                            local_183 = sqrt(((_e2460 * _e2460) + (_e2462 * _e2462)));
                                            let _e2505 = (_e2500 + 8u);
                                            local_184 = _e2505;
                                            let _e2506 = local_1;
                                            if (_e2505 < _e2506) {
                                            } else {
                                                phi_4239_ = true;
                                                break;
                                            }
                                            let _e2508 = local_184;
                                            let _e2511 = global_3.member[_e2508];
                                            let _e2512 = bitcast<f32>(_e2511);
                                            local_185 = _e2512;
                                            if ((bitcast<u32>(_e2512) & 2147483647u) > 2139095040u) {
                                                phi_3762_ = _e2382;
                                            } else {
                                                let _e2516 = local_182;
                                                let _e2517 = (_e2516 + 3u);
                                                local_186 = _e2517;
                                                let _e2518 = local_1;
                                                if (_e2517 < _e2518) {
                                                } else {
                                                    phi_4239_ = true;
                                                    break;
                                                }
                                                let _e2520 = local_186;
                                                let _e2523 = global_3.member[_e2520];
                                                let _e2524 = bitcast<f32>(_e2523);
                                                local_187 = _e2524;
                                                if (_e2524 > 0f) {
                                                    let _e2526 = local_182;
                                                    let _e2527 = local_1;
                                                    if (_e2526 < _e2527) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2529 = local_182;
                                                    let _e2532 = global_3.member[_e2529];
                                                    local_188 = bitcast<f32>(_e2532);
                                                    let _e2534 = local_182;
                                                    let _e2535 = (_e2534 + 1u);
                                                    local_189 = _e2535;
                                                    let _e2536 = local_1;
                                                    if (_e2535 < _e2536) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2538 = local_189;
                                                    let _e2541 = global_3.member[_e2538];
                                                    local_190 = bitcast<f32>(_e2541);
                                                    let _e2543 = local_182;
                                                    let _e2544 = (_e2543 + 2u);
                                                    local_191 = _e2544;
                                                    let _e2545 = local_1;
                                                    if (_e2544 < _e2545) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2547 = local_191;
                                                    let _e2550 = global_3.member[_e2547];
                                                    local_192 = bitcast<f32>(_e2550);
                                                    let _e2552 = local_182;
                                                    let _e2553 = (_e2552 + 7u);
                                                    local_193 = _e2553;
                                                    let _e2554 = local_1;
                                                    if (_e2553 < _e2554) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2556 = local_193;
                                                    let _e2559 = global_3.member[_e2556];
                                                    let _e2560 = bitcast<f32>(_e2559);
                                                    local_194 = _e2560;
                                                    local_195 = -(_e2560);
                                                    let _e2562 = (-0.5f - _e2560);
                                                    let _e2564 = select(0f, _e2562, (_e2562 > 0f));
                                                    let _e2567 = local_187;
                                                    let _e2568 = (_e2567 * select(1f, _e2564, (_e2564 < 1f)));
                                                    local_196 = _e2568;
                                                    if (_e2568 <= 0f) {
                                                        phi_3504_ = _e2382;
                                                    } else {
                                                        let _e2570 = local_247;
                                                        let _e2572 = local_247;
                                                        let _e2574 = local_194;
                                                        let _e2576 = local_195;
                                                        let _e2578 = (((0.8660254f * _e2570) * _e2572) / ((_e2574 * -3.1415927f) * _e2576));
                                                        let _e2581 = local_195;
                                                        let _e2582 = local_183;
                                                        let _e2584 = local_247;
                                                        let _e2586 = ((_e2581 - _e2582) + (0.5f * _e2584));
                                                        let _e2588 = select(0f, _e2586, (_e2586 > 0f));
                                                        let _e2591 = local_196;
                                                        let _e2593 = ((_e2591 * select(1f, _e2588, (_e2588 < 1f))) * select(1f, _e2578, (_e2578 < 1f)));
                                                        let _e2594 = local_174;
                                                        let _e2597 = local_188;
                                                        let _e2600 = local_174;
                                                        let _e2603 = local_190;
                                                        let _e2606 = local_174;
                                                        let _e2609 = local_192;
                                                        let _e2613 = local_174;
                                                        let _e2620 = type_16(_e2613.member, _e2613.member_1, _e2613.member_2, _e2613.member_3, array<f32, 3>((_e2594.member_4[0] + (_e2593 * _e2597)), (_e2600.member_4[1] + (_e2593 * _e2603)), (_e2606.member_4[2] + (_e2593 * _e2609))), _e2613.member_5);
                                                        let _e2621 = local_174;
                                                        phi_3504_ = type_16(_e2620.member, _e2620.member_1, _e2620.member_2, _e2620.member_3, _e2620.member_4, (_e2621.member_5 + _e2593));
                                                    }
                                                    let _e2632 = phi_3504_;
                                                    phi_3506_ = _e2632;
                                                } else {
                                                    phi_3506_ = _e2382;
                                                }
                                                let _e2634 = phi_3506_;
                                                local_197 = _e2634;
                                                let _e2635 = local_187;
                                                if (_e2635 < 1f) {
                                                    let _e2637 = local_182;
                                                    let _e2638 = (_e2637 + 4u);
                                                    local_198 = _e2638;
                                                    let _e2639 = local_1;
                                                    if (_e2638 < _e2639) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2641 = local_198;
                                                    let _e2644 = global_3.member[_e2641];
                                                    local_199 = bitcast<f32>(_e2644);
                                                    let _e2646 = local_182;
                                                    let _e2647 = (_e2646 + 5u);
                                                    local_200 = _e2647;
                                                    let _e2648 = local_1;
                                                    if (_e2647 < _e2648) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2650 = local_200;
                                                    let _e2653 = global_3.member[_e2650];
                                                    local_201 = bitcast<f32>(_e2653);
                                                    let _e2655 = local_182;
                                                    let _e2656 = (_e2655 + 6u);
                                                    local_202 = _e2656;
                                                    let _e2657 = local_1;
                                                    if (_e2656 < _e2657) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2659 = local_202;
                                                    let _e2662 = global_3.member[_e2659];
                                                    local_203 = bitcast<f32>(_e2662);
                                                    let _e2664 = local_187;
                                                    let _e2666 = local_185;
                                                    local_204 = -(_e2666);
                                                    let _e2668 = local_185;
                                                    let _e2669 = (-0.5f - _e2668);
                                                    let _e2671 = select(0f, _e2669, (_e2669 > 0f));
                                                    let _e2674 = ((1f - _e2664) * select(1f, _e2671, (_e2671 < 1f)));
                                                    local_205 = _e2674;
                                                    if (_e2674 <= 0f) {
                                                        phi_3759_ = _e2634;
                                                    } else {
                                                        let _e2676 = local_247;
                                                        let _e2678 = local_247;
                                                        let _e2680 = local_185;
                                                        let _e2682 = local_204;
                                                        let _e2684 = (((0.8660254f * _e2676) * _e2678) / ((_e2680 * -3.1415927f) * _e2682));
                                                        let _e2687 = local_204;
                                                        let _e2688 = local_183;
                                                        let _e2690 = local_247;
                                                        let _e2692 = ((_e2687 - _e2688) + (0.5f * _e2690));
                                                        let _e2694 = select(0f, _e2692, (_e2692 > 0f));
                                                        let _e2697 = local_205;
                                                        let _e2699 = ((_e2697 * select(1f, _e2694, (_e2694 < 1f))) * select(1f, _e2684, (_e2684 < 1f)));
                                                        let _e2700 = local_197;
                                                        let _e2703 = local_199;
                                                        let _e2706 = local_197;
                                                        let _e2709 = local_201;
                                                        let _e2712 = local_197;
                                                        let _e2715 = local_203;
                                                        let _e2719 = local_197;
                                                        let _e2726 = type_16(_e2719.member, _e2719.member_1, _e2719.member_2, _e2719.member_3, array<f32, 3>((_e2700.member_4[0] + (_e2699 * _e2703)), (_e2706.member_4[1] + (_e2699 * _e2709)), (_e2712.member_4[2] + (_e2699 * _e2715))), _e2719.member_5);
                                                        let _e2727 = local_197;
                                                        phi_3759_ = type_16(_e2726.member, _e2726.member_1, _e2726.member_2, _e2726.member_3, _e2726.member_4, (_e2727.member_5 + _e2699));
                                                    }
                                                    let _e2738 = phi_3759_;
                                                    phi_3761_ = _e2738;
                                                } else {
                                                    phi_3761_ = _e2634;
                                                }
                                                let _e2740 = phi_3761_;
                                                phi_3762_ = _e2740;
                                            }
                                            let _e2742 = phi_3762_;
                                            let _e2743 = local_175;
                                            phi_3061_ = _e2742;
                                            phi_3064_ = (_e2743 + 1u);
                                        } else {
                                            phi_3061_ = type_16();
                                            phi_3064_ = u32();
                                        }
                                        let _e2746 = phi_3061_;
                                        let _e2748 = phi_3064_;
                                        continue;
                                        continuing {
                                            let _e2749 = local_176;
                                            phi_3060_ = _e2746;
                                            phi_3063_ = _e2748;
                                            phi_4239_ = _e2373;
                                            break if !(_e2749);
                                        }
                                    }
                                    let _e2752 = phi_4239_;
                                    phi_4321_ = _e2752;
                                    if _e2752 {
                                        break;
                                    }
                                    let _e2753 = local_172;
                                    phi_4322_ = _e2752;
                                    let _e3092 = local_253;
                                    phi_3049_ = _e3092;
                                    phi_3052_ = (_e2753 + 1u);
                                } else {
                                    phi_4322_ = _e2373;
                                    phi_3049_ = type_16();
                                    phi_3052_ = u32();
                                }
                                let _e2756 = phi_4322_;
                                let _e2758 = phi_3049_;
                                let _e2760 = phi_3052_;
                                continue;
                                continuing {
                                    let _e2761 = local_173;
                                    phi_4249_ = _e2756;
                                    phi_3048_ = _e2758;
                                    phi_3051_ = _e2760;
                                    phi_4321_ = _e2756;
                                    break if !(_e2761);
                                }
                            }
                            let _e2764 = phi_4321_;
                            if _e2764 {
                                break;
                            }
                            let _e3097 = local_254;
                            phi_3765_ = _e3097;
                        } else {
                            phi_3765_ = _e2330;
                        }
                        let _e2766 = phi_3765_;
                        phi_3766_ = _e2766;
                    } else {
                        phi_3766_ = _e1722;
                    }
                    let _e2768 = phi_3766_;
                    local_206 = _e2768;
                    let _e2769 = local_14;
                    local_207 = (8u * _e2769);
                    local_208 = _e2768.member_1;
                    let _e2772 = (_e2768.member_1 > 0f);
                    local_209 = _e2772;
                    if _e2772 {
                        let _e2773 = local_208;
                        let _e2774 = (1f / _e2773);
                        let _e2775 = local_206;
                        let _e2779 = local_206;
                        let _e2783 = local_206;
                        phi_3784_ = array<f32, 3>((_e2775.member[0] * _e2774), (_e2779.member[1] * _e2774), (_e2783.member[2] * _e2774));
                    } else {
                        phi_3784_ = array<f32, 3>(0f, 0f, 0f);
                    }
                    let _e2789 = phi_3784_;
                    local_210 = _e2789;
                    let _e2790 = local_206;
                    local_211 = _e2790.member_3;
                    if (_e2790.member_3 > 0f) {
                        let _e2798 = local_211;
                        let _e2799 = (1f / _e2798);
                        let _e2800 = local_206;
                        local_212 = (_e2800.member_2[0] * _e2799);
                        let _e2804 = local_206;
                        local_213 = (_e2804.member_2[1] * _e2799);
                        let _e2808 = local_206;
                        local_214 = (_e2808.member_2[2] * _e2799);
                        let _e2812 = local_209;
                        if _e2812 {
                            phi_3816_ = _e416;
                        } else {
                            phi_3816_ = 1f;
                        }
                        let _e2814 = phi_3816_;
                        let _e2815 = local_210;
                        let _e2817 = local_212;
                        let _e2821 = local_210;
                        let _e2823 = local_213;
                        let _e2827 = local_210;
                        let _e2829 = local_214;
                        phi_3840_ = 1f;
                        phi_3841_ = array<f32, 3>((_e2815[0] + (_e2814 * (_e2817 - _e2815[0]))), (_e2821[1] + (_e2814 * (_e2823 - _e2821[1]))), (_e2827[2] + (_e2814 * (_e2829 - _e2827[2]))));
                    } else {
                        let _e2793 = local_209;
                        if _e2793 {
                            phi_3839_ = _e2789;
                        } else {
                            phi_3839_ = array<f32, 3>(0f, 0f, 0f);
                        }
                        let _e2795 = phi_3839_;
                        let _e2796 = local_209;
                        phi_3840_ = select(0f, 1f, _e2796);
                        phi_3841_ = _e2795;
                    }
                    let _e2835 = phi_3840_;
                    let _e2837 = phi_3841_;
                    local_215 = _e2835;
                    local_216 = _e2837;
                    let _e2838 = local_206;
                    local_217 = _e2838.member_5;
                    local_248 = select(1f, _e2838.member_5, (_e2838.member_5 < 1f));
                    if (_e2838.member_5 > 0f) {
                        let _e2843 = local_248;
                        let _e2844 = local_217;
                        phi_3855_ = (_e2843 / _e2844);
                    } else {
                        phi_3855_ = 0f;
                    }
                    let _e2847 = phi_3855_;
                    local_218 = _e2847;
                    let _e2848 = local_216;
                    local_219 = bitcast<u32>(_e2848[0]);
                    let _e2851 = local_207;
                    let _e2852 = local_3;
                    if (_e2851 < _e2852) {
                    } else {
                        break;
                    }
                    let _e2854 = local_207;
                    let _e2857 = local_219;
                    global_5.member[_e2854] = _e2857;
                    let _e2858 = local_207;
                    let _e2859 = (_e2858 + 1u);
                    local_220 = _e2859;
                    let _e2860 = local_216;
                    local_221 = bitcast<u32>(_e2860[1]);
                    let _e2863 = local_3;
                    if (_e2859 < _e2863) {
                    } else {
                        break;
                    }
                    let _e2865 = local_220;
                    let _e2868 = local_221;
                    global_5.member[_e2865] = _e2868;
                    let _e2869 = local_207;
                    let _e2870 = (_e2869 + 2u);
                    local_222 = _e2870;
                    let _e2871 = local_216;
                    local_223 = bitcast<u32>(_e2871[2]);
                    let _e2874 = local_3;
                    if (_e2870 < _e2874) {
                    } else {
                        break;
                    }
                    let _e2876 = local_222;
                    let _e2879 = local_223;
                    global_5.member[_e2876] = _e2879;
                    let _e2880 = local_207;
                    let _e2881 = (_e2880 + 3u);
                    local_224 = _e2881;
                    let _e2882 = local_215;
                    local_225 = bitcast<u32>(_e2882);
                    let _e2884 = local_3;
                    if (_e2881 < _e2884) {
                    } else {
                        break;
                    }
                    let _e2886 = local_224;
                    let _e2889 = local_225;
                    global_5.member[_e2886] = _e2889;
                    let _e2890 = local_207;
                    let _e2891 = (_e2890 + 4u);
                    local_226 = _e2891;
                    let _e2892 = local_206;
                    let _e2895 = local_218;
                    local_227 = bitcast<u32>((_e2892.member_4[0] * _e2895));
                    let _e2898 = local_3;
                    if (_e2891 < _e2898) {
                    } else {
                        break;
                    }
                    let _e2900 = local_226;
                    let _e2903 = local_227;
                    global_5.member[_e2900] = _e2903;
                    let _e2904 = local_207;
                    let _e2905 = (_e2904 + 5u);
                    local_228 = _e2905;
                    let _e2906 = local_206;
                    let _e2909 = local_218;
                    local_229 = bitcast<u32>((_e2906.member_4[1] * _e2909));
                    let _e2912 = local_3;
                    if (_e2905 < _e2912) {
                    } else {
                        break;
                    }
                    let _e2914 = local_228;
                    let _e2917 = local_229;
                    global_5.member[_e2914] = _e2917;
                    let _e2918 = local_207;
                    let _e2919 = (_e2918 + 6u);
                    local_230 = _e2919;
                    let _e2920 = local_206;
                    let _e2923 = local_218;
                    local_231 = bitcast<u32>((_e2920.member_4[2] * _e2923));
                    let _e2926 = local_3;
                    if (_e2919 < _e2926) {
                    } else {
                        break;
                    }
                    let _e2928 = local_230;
                    let _e2931 = local_231;
                    global_5.member[_e2928] = _e2931;
                    let _e2932 = local_207;
                    let _e2933 = (_e2932 + 7u);
                    local_232 = _e2933;
                    let _e2934 = local_248;
                    local_233 = bitcast<u32>(_e2934);
                    let _e2936 = local_3;
                    if (_e2933 < _e2936) {
                    } else {
                        break;
                    }
                    let _e2938 = local_232;
                    let _e2941 = local_233;
                    global_5.member[_e2938] = _e2941;
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
fn ring_gather(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
