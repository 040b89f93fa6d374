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
                                        let _e1005 = local_75;
                                        phi_1447_ = select(select(u32(_e1000), 0u, !((_e1002 >= 0f))), 4294967295u, (_e1005 > 4294967000f));
                                    } else {
                                        phi_1447_ = _e986;
                                    }
                                    let _e1010 = phi_1447_;
                                    phi_1448_ = _e1010;
                                }
                                let _e1012 = phi_1448_;
                                local_76 = _e1012;
                                phi_3954_ = false;
                                phi_1450_ = _e963;
                                phi_1453_ = 1u;
                                loop {
                                    let _e1014 = phi_3954_;
                                    let _e1016 = phi_1450_;
                                    let _e1018 = phi_1453_;
                                    local_77 = _e1018;
                                    local_250 = _e1016;
                                    let _e1019 = local_77;
                                    let _e1020 = local_76;
                                    let _e1021 = (_e1019 <= _e1020);
                                    local_78 = _e1021;
                                    if _e1021 {
                                        phi_1462_ = _e1016;
                                        phi_1465_ = 0u;
                                        loop {
                                            let _e1023 = phi_1462_;
                                            let _e1025 = phi_1465_;
                                            local_79 = _e1023;
                                            local_80 = _e1025;
                                            local_249 = _e1023;
                                            let _e1026 = local_77;
                                            let _e1028 = local_80;
                                            let _e1029 = (_e1028 < (6u * _e1026));
                                            local_81 = _e1029;
                                            if _e1029 {
                                                let _e1030 = local_77;
                                                let _e1031 = (_e1030 == 0u);
                                                local_82 = _e1031;
                                                if _e1031 {
                                                    phi_3944_ = true;
                                                    break;
                                                }
                                                let _e1032 = local_80;
                                                let _e1033 = local_77;
                                                local_83 = (_e1032 / _e1033);
                                                let _e1035 = local_82;
                                                if _e1035 {
                                                    phi_3944_ = true;
                                                    break;
                                                }
                                                let _e1036 = local_80;
                                                let _e1037 = local_77;
                                                local_84 = f32((_e1036 % _e1037));
                                                let _e1040 = local_83;
                                                if (_e1040 == 0u) {
                                                    phi_1517_ = array<f32, 2>(1f, 0f);
                                                } else {
                                                    let _e1042 = local_83;
                                                    if (_e1042 == 1u) {
                                                        phi_1516_ = array<f32, 2>(0.5f, 0.8660254f);
                                                    } else {
                                                        let _e1044 = local_83;
                                                        if (_e1044 == 2u) {
                                                            phi_1515_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                        } else {
                                                            let _e1046 = local_83;
                                                            if (_e1046 == 3u) {
                                                                phi_1514_ = array<f32, 2>(-1f, 0f);
                                                            } else {
                                                                let _e1048 = local_83;
                                                                if (_e1048 == 4u) {
                                                                    phi_1513_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                                } else {
                                                                    phi_1513_ = array<f32, 2>(0.5f, -0.8660254f);
                                                                }
                                                                let _e1051 = phi_1513_;
                                                                phi_1514_ = _e1051;
                                                            }
                                                            let _e1053 = phi_1514_;
                                                            phi_1515_ = _e1053;
                                                        }
                                                        let _e1055 = phi_1515_;
                                                        phi_1516_ = _e1055;
                                                    }
                                                    let _e1057 = phi_1516_;
                                                    phi_1517_ = _e1057;
                                                }
                                                let _e1059 = phi_1517_;
                                                local_85 = _e1059;
                                                let _e1060 = local_83;
                                                let _e1062 = ((_e1060 + 1u) % 6u);
                                                local_86 = _e1062;
                                                if (_e1062 == 0u) {
                                                    phi_1552_ = array<f32, 2>(1f, 0f);
                                                } else {
                                                    let _e1064 = local_86;
                                                    if (_e1064 == 1u) {
                                                        phi_1551_ = array<f32, 2>(0.5f, 0.8660254f);
                                                    } else {
                                                        let _e1066 = local_86;
                                                        if (_e1066 == 2u) {
                                                            phi_1550_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                        } else {
                                                            let _e1068 = local_86;
                                                            if (_e1068 == 3u) {
                                                                phi_1549_ = array<f32, 2>(-1f, 0f);
                                                            } else {
                                                                let _e1070 = local_86;
                                                                if (_e1070 == 4u) {
                                                                    phi_1548_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                                } else {
                                                                    phi_1548_ = array<f32, 2>(0.5f, -0.8660254f);
                                                                }
                                                                let _e1073 = phi_1548_;
                                                                phi_1549_ = _e1073;
                                                            }
                                                            let _e1075 = phi_1549_;
                                                            phi_1550_ = _e1075;
                                                        }
                                                        let _e1077 = phi_1550_;
                                                        phi_1551_ = _e1077;
                                                    }
                                                    let _e1079 = phi_1551_;
                                                    phi_1552_ = _e1079;
                                                }
                                                let _e1081 = phi_1552_;
                                                let _e1082 = local_77;
                                                let _e1083 = f32(_e1082);
                                                let _e1084 = local_85;
                                                let _e1089 = local_84;
                                                let _e1092 = local_85;
                                                let _e1097 = local_84;
                                                let _e1100 = local_239;
                                                let _e1101 = (((_e1084[0] * _e1083) + ((_e1081[0] - _e1084[0]) * _e1089)) * _e1100);
                                                let _e1102 = local_239;
                                                let _e1103 = (((_e1092[1] * _e1083) + ((_e1081[1] - _e1092[1]) * _e1097)) * _e1102);
                                                let _e1104 = local_12;
                                                let _e1108 = floor(((f32(_e1104) + 0.5f) + _e1101));
                                                let _e1109 = local_13;
                                                let _e1113 = floor(((f32(_e1109) + 0.5f) + _e1103));
                                                let _e1115 = select(0f, _e1108, (_e1108 > 0f));
                                                let _e1116 = local_72;
                                                let _e1118 = f32((_e1116 - 1u));
                                                let _e1120 = select(_e1118, _e1115, (_e1115 < _e1118));
                                                let _e1128 = select(0f, _e1113, (_e1113 > 0f));
                                                let _e1129 = local_73;
                                                let _e1131 = f32((_e1129 - 1u));
                                                let _e1133 = select(_e1131, _e1128, (_e1128 < _e1131));
                                                let _e1140 = local_72;
                                                let _e1143 = (9u * ((select(select(u32(_e1133), 0u, !((_e1133 >= 0f))), 4294967295u, (_e1133 > 4294967000f)) * _e1140) + select(select(u32(_e1120), 0u, !((_e1120 >= 0f))), 4294967295u, (_e1120 > 4294967000f))));
                                                local_87 = _e1143;
                                                local_88 = sqrt(((_e1101 * _e1101) + (_e1103 * _e1103)));
                                                let _e1148 = (_e1143 + 8u);
                                                local_89 = _e1148;
                                                let _e1149 = local_1;
                                                if (_e1148 < _e1149) {
                                                } else {
                                                    phi_3944_ = true;
                                                    break;
                                                }
                                                let _e1151 = local_89;
                                                let _e1154 = global_3.member[_e1151];
                                                let _e1155 = bitcast<f32>(_e1154);
                                                local_90 = _e1155;
                                                if ((bitcast<u32>(_e1155) & 2147483647u) > 2139095040u) {
                                                    phi_2164_ = _e1023;
                                                } else {
                                                    let _e1159 = local_87;
                                                    let _e1160 = (_e1159 + 3u);
                                                    local_91 = _e1160;
                                                    let _e1161 = local_1;
                                                    if (_e1160 < _e1161) {
                                                    } else {
                                                        phi_3944_ = true;
                                                        break;
                                                    }
                                                    let _e1163 = local_91;
                                                    let _e1166 = global_3.member[_e1163];
                                                    let _e1167 = bitcast<f32>(_e1166);
                                                    local_92 = _e1167;
                                                    if (_e1167 > 0f) {
                                                        let _e1169 = local_87;
                                                        let _e1170 = local_1;
                                                        if (_e1169 < _e1170) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1172 = local_87;
                                                        let _e1175 = global_3.member[_e1172];
                                                        local_93 = bitcast<f32>(_e1175);
                                                        let _e1177 = local_87;
                                                        let _e1178 = (_e1177 + 1u);
                                                        local_94 = _e1178;
                                                        let _e1179 = local_1;
                                                        if (_e1178 < _e1179) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1181 = local_94;
                                                        let _e1184 = global_3.member[_e1181];
                                                        local_95 = bitcast<f32>(_e1184);
                                                        let _e1186 = local_87;
                                                        let _e1187 = (_e1186 + 2u);
                                                        local_96 = _e1187;
                                                        let _e1188 = local_1;
                                                        if (_e1187 < _e1188) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1190 = local_96;
                                                        let _e1193 = global_3.member[_e1190];
                                                        local_97 = bitcast<f32>(_e1193);
                                                        let _e1195 = local_87;
                                                        let _e1196 = (_e1195 + 7u);
                                                        local_98 = _e1196;
                                                        let _e1197 = local_1;
                                                        if (_e1196 < _e1197) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1199 = local_98;
                                                        let _e1202 = global_3.member[_e1199];
                                                        let _e1203 = bitcast<f32>(_e1202);
                                                        local_99 = _e1203;
                                                        local_100 = -(_e1203);
                                                        let _e1205 = (-0.5f - _e1203);
                                                        let _e1207 = select(0f, _e1205, (_e1205 > 0f));
                                                        let _e1209 = select(1f, _e1207, (_e1207 < 1f));
                                                        local_240 = _e1209;
                                                        let _e1211 = local_92;
                                                        let _e1212 = (_e1211 * (1f - _e1209));
                                                        local_101 = _e1212;
                                                        if (_e1212 <= 0f) {
                                                            phi_1840_ = _e1023;
                                                        } else {
                                                            let _e1214 = local_234;
                                                            let _e1216 = local_234;
                                                            local_241 = select(0f, _e1216, (_e1214 > 0f));
                                                            let _e1218 = local_99;
                                                            let _e1219 = local_234;
                                                            let _e1220 = (_e1218 > _e1219);
                                                            local_102 = _e1220;
                                                            if _e1220 {
                                                                let _e1226 = local_99;
                                                                let _e1228 = local_100;
                                                                let _e1229 = local_99;
                                                                let _e1230 = select(_e1229, _e1228, (_e1226 < 0f));
                                                                let _e1231 = local_241;
                                                                let _e1233 = local_241;
                                                                phi_1739_ = select(_e1233, _e1230, (_e1230 < _e1231));
                                                            } else {
                                                                let _e1221 = local_99;
                                                                let _e1223 = local_100;
                                                                let _e1224 = local_99;
                                                                phi_1739_ = select(_e1224, _e1223, (_e1221 < 0f));
                                                            }
                                                            let _e1236 = phi_1739_;
                                                            local_103 = _e1236;
                                                            let _e1237 = local_88;
                                                            if (_e1237 == 0f) {
                                                                phi_1757_ = 1f;
                                                            } else {
                                                                let _e1239 = local_103;
                                                                let _e1240 = local_88;
                                                                let _e1242 = local_239;
                                                                let _e1244 = ((_e1239 - _e1240) + (0.5f * _e1242));
                                                                let _e1246 = select(0f, _e1244, (_e1244 > 0f));
                                                                phi_1757_ = select(1f, _e1246, (_e1246 < 1f));
                                                            }
                                                            let _e1250 = phi_1757_;
                                                            let _e1251 = local_101;
                                                            let _e1253 = local_103;
                                                            let _e1254 = local_103;
                                                            let _e1255 = (_e1253 * _e1254);
                                                            let _e1258 = ((_e1251 * _e1250) / select(0.25f, _e1255, (_e1255 > 0.25f)));
                                                            let _e1259 = local_79;
                                                            let _e1262 = local_93;
                                                            let _e1265 = local_79;
                                                            let _e1268 = local_95;
                                                            let _e1271 = local_79;
                                                            let _e1274 = local_97;
                                                            let _e1278 = local_79;
                                                            let _e1285 = type_16(array<f32, 3>((_e1259.member[0] + (_e1258 * _e1262)), (_e1265.member[1] + (_e1258 * _e1268)), (_e1271.member[2] + (_e1258 * _e1274))), _e1278.member_1, _e1278.member_2, _e1278.member_3, _e1278.member_4, _e1278.member_5);
                                                            let _e1286 = local_79;
                                                            let _e1295 = type_16(_e1285.member, (_e1286.member_1 + _e1258), _e1285.member_2, _e1285.member_3, _e1285.member_4, _e1285.member_5);
                                                            local_104 = _e1295;
                                                            let _e1296 = local_102;
                                                            if _e1296 {
                                                                let _e1297 = local_235;
                                                                if (_e1297 > 0f) {
                                                                    let _e1299 = local_30;
                                                                    let _e1300 = local_88;
                                                                    let _e1302 = local_239;
                                                                    let _e1304 = ((_e1299 - _e1300) + (0.5f * _e1302));
                                                                    let _e1306 = select(0f, _e1304, (_e1304 > 0f));
                                                                    let _e1309 = local_101;
                                                                    let _e1311 = local_30;
                                                                    let _e1312 = local_30;
                                                                    let _e1313 = (_e1311 * _e1312);
                                                                    let _e1316 = ((_e1309 * select(1f, _e1306, (_e1306 < 1f))) / select(0.25f, _e1313, (_e1313 > 0.25f)));
                                                                    let _e1317 = local_79;
                                                                    let _e1320 = local_93;
                                                                    let _e1323 = local_79;
                                                                    let _e1326 = local_95;
                                                                    let _e1329 = local_79;
                                                                    let _e1332 = local_97;
                                                                    let _e1336 = local_104;
                                                                    let _e1343 = type_16(_e1336.member, _e1336.member_1, array<f32, 3>((_e1317.member_2[0] + (_e1316 * _e1320)), (_e1323.member_2[1] + (_e1316 * _e1326)), (_e1329.member_2[2] + (_e1316 * _e1332))), _e1336.member_3, _e1336.member_4, _e1336.member_5);
                                                                    let _e1344 = local_79;
                                                                    phi_1838_ = type_16(_e1343.member, _e1343.member_1, _e1343.member_2, (_e1344.member_3 + _e1316), _e1343.member_4, _e1343.member_5);
                                                                } else {
                                                                    phi_1838_ = _e1295;
                                                                }
                                                                let _e1355 = phi_1838_;
                                                                phi_1839_ = _e1355;
                                                            } else {
                                                                phi_1839_ = _e1295;
                                                            }
                                                            let _e1357 = phi_1839_;
                                                            phi_1840_ = _e1357;
                                                        }
                                                        let _e1359 = phi_1840_;
                                                        local_105 = _e1359;
                                                        let _e1360 = local_92;
                                                        let _e1361 = local_240;
                                                        let _e1362 = (_e1360 * _e1361);
                                                        local_106 = _e1362;
                                                        if (_e1362 <= 0f) {
                                                            phi_1906_ = _e1359;
                                                        } else {
                                                            let _e1364 = local_239;
                                                            let _e1366 = local_239;
                                                            let _e1368 = local_99;
                                                            let _e1370 = local_100;
                                                            let _e1372 = (((0.8660254f * _e1364) * _e1366) / ((_e1368 * -3.1415927f) * _e1370));
                                                            let _e1375 = local_100;
                                                            let _e1376 = local_88;
                                                            let _e1378 = local_239;
                                                            let _e1380 = ((_e1375 - _e1376) + (0.5f * _e1378));
                                                            let _e1382 = select(0f, _e1380, (_e1380 > 0f));
                                                            let _e1385 = local_106;
                                                            let _e1387 = ((_e1385 * select(1f, _e1382, (_e1382 < 1f))) * select(1f, _e1372, (_e1372 < 1f)));
                                                            let _e1388 = local_105;
                                                            let _e1391 = local_93;
                                                            let _e1394 = local_105;
                                                            let _e1397 = local_95;
                                                            let _e1400 = local_105;
                                                            let _e1403 = local_97;
                                                            let _e1407 = local_105;
                                                            let _e1414 = type_16(_e1407.member, _e1407.member_1, _e1407.member_2, _e1407.member_3, array<f32, 3>((_e1388.member_4[0] + (_e1387 * _e1391)), (_e1394.member_4[1] + (_e1387 * _e1397)), (_e1400.member_4[2] + (_e1387 * _e1403))), _e1407.member_5);
                                                            let _e1415 = local_105;
                                                            phi_1906_ = type_16(_e1414.member, _e1414.member_1, _e1414.member_2, _e1414.member_3, _e1414.member_4, (_e1415.member_5 + _e1387));
                                                        }
                                                        let _e1426 = phi_1906_;
                                                        phi_1908_ = _e1426;
                                                    } else {
                                                        phi_1908_ = _e1023;
                                                    }
                                                    let _e1428 = phi_1908_;
                                                    local_107 = _e1428;
                                                    let _e1429 = local_92;
                                                    if (_e1429 < 1f) {
                                                        let _e1431 = local_87;
                                                        let _e1432 = (_e1431 + 4u);
                                                        local_108 = _e1432;
                                                        let _e1433 = local_1;
                                                        if (_e1432 < _e1433) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1435 = local_108;
                                                        let _e1438 = global_3.member[_e1435];
                                                        local_109 = bitcast<f32>(_e1438);
                                                        let _e1440 = local_87;
                                                        let _e1441 = (_e1440 + 5u);
                                                        local_110 = _e1441;
                                                        let _e1442 = local_1;
                                                        if (_e1441 < _e1442) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1444 = local_110;
                                                        let _e1447 = global_3.member[_e1444];
                                                        local_111 = bitcast<f32>(_e1447);
                                                        let _e1449 = local_87;
                                                        let _e1450 = (_e1449 + 6u);
                                                        local_112 = _e1450;
                                                        let _e1451 = local_1;
                                                        if (_e1450 < _e1451) {
                                                        } else {
                                                            phi_3944_ = true;
                                                            break;
                                                        }
                                                        let _e1453 = local_112;
                                                        let _e1456 = global_3.member[_e1453];
                                                        local_113 = bitcast<f32>(_e1456);
                                                        let _e1458 = local_92;
                                                        let _e1459 = (1f - _e1458);
                                                        local_114 = _e1459;
                                                        let _e1460 = local_90;
                                                        local_115 = -(_e1460);
                                                        let _e1462 = local_90;
                                                        let _e1463 = (-0.5f - _e1462);
                                                        let _e1465 = select(0f, _e1463, (_e1463 > 0f));
                                                        let _e1467 = select(1f, _e1465, (_e1465 < 1f));
                                                        local_242 = _e1467;
                                                        let _e1469 = (_e1459 * (1f - _e1467));
                                                        local_116 = _e1469;
                                                        if (_e1469 <= 0f) {
                                                            phi_2094_ = _e1428;
                                                        } else {
                                                            let _e1471 = local_234;
                                                            let _e1473 = local_234;
                                                            local_243 = select(0f, _e1473, (_e1471 > 0f));
                                                            let _e1475 = local_90;
                                                            let _e1476 = local_234;
                                                            let _e1477 = (_e1475 > _e1476);
                                                            local_117 = _e1477;
                                                            if _e1477 {
                                                                let _e1483 = local_90;
                                                                let _e1485 = local_115;
                                                                let _e1486 = local_90;
                                                                let _e1487 = select(_e1486, _e1485, (_e1483 < 0f));
                                                                let _e1488 = local_243;
                                                                let _e1490 = local_243;
                                                                phi_1993_ = select(_e1490, _e1487, (_e1487 < _e1488));
                                                            } else {
                                                                let _e1478 = local_90;
                                                                let _e1480 = local_115;
                                                                let _e1481 = local_90;
                                                                phi_1993_ = select(_e1481, _e1480, (_e1478 < 0f));
                                                            }
                                                            let _e1493 = phi_1993_;
                                                            local_118 = _e1493;
                                                            let _e1494 = local_88;
                                                            if (_e1494 == 0f) {
                                                                phi_2011_ = 1f;
                                                            } else {
                                                                let _e1496 = local_118;
                                                                let _e1497 = local_88;
                                                                let _e1499 = local_239;
                                                                let _e1501 = ((_e1496 - _e1497) + (0.5f * _e1499));
                                                                let _e1503 = select(0f, _e1501, (_e1501 > 0f));
                                                                phi_2011_ = select(1f, _e1503, (_e1503 < 1f));
                                                            }
                                                            let _e1507 = phi_2011_;
                                                            let _e1508 = local_116;
                                                            let _e1510 = local_118;
                                                            let _e1511 = local_118;
                                                            let _e1512 = (_e1510 * _e1511);
                                                            let _e1515 = ((_e1508 * _e1507) / select(0.25f, _e1512, (_e1512 > 0.25f)));
                                                            let _e1516 = local_107;
                                                            let _e1519 = local_109;
                                                            let _e1522 = local_107;
                                                            let _e1525 = local_111;
                                                            let _e1528 = local_107;
                                                            let _e1531 = local_113;
                                                            let _e1535 = local_107;
                                                            let _e1542 = type_16(array<f32, 3>((_e1516.member[0] + (_e1515 * _e1519)), (_e1522.member[1] + (_e1515 * _e1525)), (_e1528.member[2] + (_e1515 * _e1531))), _e1535.member_1, _e1535.member_2, _e1535.member_3, _e1535.member_4, _e1535.member_5);
                                                            let _e1543 = local_107;
                                                            let _e1552 = type_16(_e1542.member, (_e1543.member_1 + _e1515), _e1542.member_2, _e1542.member_3, _e1542.member_4, _e1542.member_5);
                                                            local_119 = _e1552;
                                                            let _e1553 = local_117;
                                                            if _e1553 {
                                                                let _e1554 = local_235;
                                                                if (_e1554 > 0f) {
                                                                    let _e1556 = local_30;
                                                                    let _e1557 = local_88;
                                                                    let _e1559 = local_239;
                                                                    let _e1561 = ((_e1556 - _e1557) + (0.5f * _e1559));
                                                                    let _e1563 = select(0f, _e1561, (_e1561 > 0f));
                                                                    let _e1566 = local_116;
                                                                    let _e1568 = local_30;
                                                                    let _e1569 = local_30;
                                                                    let _e1570 = (_e1568 * _e1569);
                                                                    let _e1573 = ((_e1566 * select(1f, _e1563, (_e1563 < 1f))) / select(0.25f, _e1570, (_e1570 > 0.25f)));
                                                                    let _e1574 = local_107;
                                                                    let _e1577 = local_109;
                                                                    let _e1580 = local_107;
                                                                    let _e1583 = local_111;
                                                                    let _e1586 = local_107;
                                                                    let _e1589 = local_113;
                                                                    let _e1593 = local_119;
                                                                    let _e1600 = type_16(_e1593.member, _e1593.member_1, array<f32, 3>((_e1574.member_2[0] + (_e1573 * _e1577)), (_e1580.member_2[1] + (_e1573 * _e1583)), (_e1586.member_2[2] + (_e1573 * _e1589))), _e1593.member_3, _e1593.member_4, _e1593.member_5);
                                                                    let _e1601 = local_107;
                                                                    phi_2092_ = type_16(_e1600.member, _e1600.member_1, _e1600.member_2, (_e1601.member_3 + _e1573), _e1600.member_4, _e1600.member_5);
                                                                } else {
                                                                    phi_2092_ = _e1552;
                                                                }
                                                                let _e1612 = phi_2092_;
                                                                phi_2093_ = _e1612;
                                                            } else {
                                                                phi_2093_ = _e1552;
                                                            }
                                                            let _e1614 = phi_2093_;
                                                            phi_2094_ = _e1614;
                                                        }
                                                        let _e1616 = phi_2094_;
                                                        local_120 = _e1616;
                                                        let _e1617 = local_114;
                                                        let _e1618 = local_242;
                                                        let _e1619 = (_e1617 * _e1618);
                                                        local_121 = _e1619;
                                                        if (_e1619 <= 0f) {
                                                            phi_2161_ = _e1616;
                                                        } else {
                                                            let _e1621 = local_239;
                                                            let _e1623 = local_239;
                                                            let _e1625 = local_90;
                                                            let _e1627 = local_115;
                                                            let _e1629 = (((0.8660254f * _e1621) * _e1623) / ((_e1625 * -3.1415927f) * _e1627));
                                                            let _e1632 = local_115;
                                                            let _e1633 = local_88;
                                                            let _e1635 = local_239;
                                                            let _e1637 = ((_e1632 - _e1633) + (0.5f * _e1635));
                                                            let _e1639 = select(0f, _e1637, (_e1637 > 0f));
                                                            let _e1642 = local_121;
                                                            let _e1644 = ((_e1642 * select(1f, _e1639, (_e1639 < 1f))) * select(1f, _e1629, (_e1629 < 1f)));
                                                            let _e1645 = local_120;
                                                            let _e1648 = local_109;
                                                            let _e1651 = local_120;
                                                            let _e1654 = local_111;
                                                            let _e1657 = local_120;
                                                            let _e1660 = local_113;
                                                            let _e1664 = local_120;
                                                            let _e1671 = type_16(_e1664.member, _e1664.member_1, _e1664.member_2, _e1664.member_3, array<f32, 3>((_e1645.member_4[0] + (_e1644 * _e1648)), (_e1651.member_4[1] + (_e1644 * _e1654)), (_e1657.member_4[2] + (_e1644 * _e1660))), _e1664.member_5);
                                                            let _e1672 = local_120;
                                                            phi_2161_ = type_16(_e1671.member, _e1671.member_1, _e1671.member_2, _e1671.member_3, _e1671.member_4, (_e1672.member_5 + _e1644));
                                                        }
                                                        let _e1683 = phi_2161_;
                                                        phi_2163_ = _e1683;
                                                    } else {
                                                        phi_2163_ = _e1428;
                                                    }
                                                    let _e1685 = phi_2163_;
                                                    phi_2164_ = _e1685;
                                                }
                                                let _e1687 = phi_2164_;
                                                let _e1688 = local_80;
                                                phi_1463_ = _e1687;
                                                phi_1466_ = (_e1688 + 1u);
                                            } else {
                                                phi_1463_ = type_16();
                                                phi_1466_ = u32();
                                            }
                                            let _e1691 = phi_1463_;
                                            let _e1693 = phi_1466_;
                                            continue;
                                            continuing {
                                                let _e1694 = local_81;
                                                phi_1462_ = _e1691;
                                                phi_1465_ = _e1693;
                                                phi_3944_ = _e1014;
                                                break if !(_e1694);
                                            }
                                        }
                                        let _e1697 = phi_3944_;
                                        phi_4151_ = _e1697;
                                        if _e1697 {
                                            break;
                                        }
                                        let _e1698 = local_77;
                                        phi_4152_ = _e1697;
                                        let _e3013 = local_249;
                                        phi_1451_ = _e3013;
                                        phi_1454_ = (_e1698 + 1u);
                                    } else {
                                        phi_4152_ = _e1014;
                                        phi_1451_ = type_16();
                                        phi_1454_ = u32();
                                    }
                                    let _e1701 = phi_4152_;
                                    let _e1703 = phi_1451_;
                                    let _e1705 = phi_1454_;
                                    continue;
                                    continuing {
                                        let _e1706 = local_78;
                                        phi_3954_ = _e1701;
                                        phi_1450_ = _e1703;
                                        phi_1453_ = _e1705;
                                        phi_4151_ = _e1701;
                                        break if !(_e1706);
                                    }
                                }
                                let _e1709 = phi_4151_;
                                if _e1709 {
                                    break;
                                }
                                phi_4171_ = _e1709;
                                let _e3019 = local_250;
                                phi_2167_ = _e3019;
                            } else {
                                phi_4171_ = false;
                                phi_2167_ = type_16();
                            }
                            let _e1711 = phi_4171_;
                            let _e1713 = phi_2167_;
                            let _e1714 = local_71;
                            phi_4170_ = _e1711;
                            phi_2169_ = _e1713;
                            phi_2170_ = select(true, false, _e1714);
                        } else {
                            phi_4170_ = false;
                            phi_2169_ = type_16();
                            phi_2170_ = true;
                        }
                        let _e1717 = phi_4170_;
                        let _e1719 = phi_2169_;
                        let _e1721 = phi_2170_;
                        phi_4169_ = _e1717;
                        phi_2171_ = _e1719;
                        phi_2172_ = _e1721;
                    } else {
                        phi_4169_ = false;
                        phi_2171_ = type_16();
                        phi_2172_ = true;
                    }
                    let _e1723 = phi_4169_;
                    let _e1725 = phi_2171_;
                    let _e1727 = phi_2172_;
                    if _e1727 {
                        let _e1728 = local_69;
                        if _e1728 {
                            let _e1729 = local_7;
                            if _e1729 {
                                let _e1730 = local_6;
                                phi_2196_ = (_e1730 + 1u);
                            } else {
                                phi_2196_ = _e305;
                            }
                            let _e1733 = phi_2196_;
                            local_122 = _e1733;
                            let _e1734 = local_10;
                            if _e1734 {
                                let _e1735 = local_9;
                                phi_2214_ = (_e1735 + 1u);
                            } else {
                                phi_2214_ = _e315;
                            }
                            let _e1738 = phi_2214_;
                            local_123 = _e1738;
                            let _e1741 = global_2.member.member_2;
                            let _e1743 = select(_e1741, 1u, (_e1741 == 0u));
                            let _e1744 = f32(_e1743);
                            local_124 = _e1744;
                            let _e1745 = local_30;
                            let _e1746 = (_e1745 / _e1744);
                            let _e1748 = select(1f, _e1746, (_e1746 > 1f));
                            local_244 = _e1748;
                            let _e1749 = local_30;
                            let _e1752 = ceil(((_e1749 / _e1748) + 0.5f));
                            local_125 = _e1752;
                            if (_e1752 < 1f) {
                                phi_2251_ = 1u;
                            } else {
                                let _e1754 = local_125;
                                let _e1755 = local_124;
                                if (_e1754 < _e1755) {
                                    let _e1757 = local_125;
                                    let _e1759 = local_125;
                                    let _e1762 = local_125;
                                    phi_2250_ = select(select(u32(_e1757), 0u, !((_e1759 >= 0f))), 4294967295u, (_e1762 > 4294967000f));
                                } else {
                                    phi_2250_ = _e1743;
                                }
                                let _e1767 = phi_2250_;
                                phi_2251_ = _e1767;
                            }
                            let _e1769 = phi_2251_;
                            local_126 = _e1769;
                            phi_4163_ = _e1723;
                            phi_2253_ = _e963;
                            phi_2256_ = 1u;
                            loop {
                                let _e1771 = phi_4163_;
                                let _e1773 = phi_2253_;
                                let _e1775 = phi_2256_;
                                local_127 = _e1775;
                                local_252 = _e1773;
                                let _e1776 = local_127;
                                let _e1777 = local_126;
                                let _e1778 = (_e1776 <= _e1777);
                                local_128 = _e1778;
                                if _e1778 {
                                    phi_2265_ = _e1773;
                                    phi_2268_ = 0u;
                                    loop {
                                        let _e1780 = phi_2265_;
                                        let _e1782 = phi_2268_;
                                        local_129 = _e1780;
                                        local_130 = _e1782;
                                        local_251 = _e1780;
                                        let _e1783 = local_127;
                                        let _e1785 = local_130;
                                        let _e1786 = (_e1785 < (6u * _e1783));
                                        local_131 = _e1786;
                                        if _e1786 {
                                            let _e1787 = local_127;
                                            let _e1788 = (_e1787 == 0u);
                                            local_132 = _e1788;
                                            if _e1788 {
                                                phi_4153_ = true;
                                                break;
                                            }
                                            let _e1789 = local_130;
                                            let _e1790 = local_127;
                                            local_133 = (_e1789 / _e1790);
                                            let _e1792 = local_132;
                                            if _e1792 {
                                                phi_4153_ = true;
                                                break;
                                            }
                                            let _e1793 = local_130;
                                            let _e1794 = local_127;
                                            local_134 = f32((_e1793 % _e1794));
                                            let _e1797 = local_133;
                                            if (_e1797 == 0u) {
                                                phi_2320_ = array<f32, 2>(1f, 0f);
                                            } else {
                                                let _e1799 = local_133;
                                                if (_e1799 == 1u) {
                                                    phi_2319_ = array<f32, 2>(0.5f, 0.8660254f);
                                                } else {
                                                    let _e1801 = local_133;
                                                    if (_e1801 == 2u) {
                                                        phi_2318_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                    } else {
                                                        let _e1803 = local_133;
                                                        if (_e1803 == 3u) {
                                                            phi_2317_ = array<f32, 2>(-1f, 0f);
                                                        } else {
                                                            let _e1805 = local_133;
                                                            if (_e1805 == 4u) {
                                                                phi_2316_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                            } else {
                                                                phi_2316_ = array<f32, 2>(0.5f, -0.8660254f);
                                                            }
                                                            let _e1808 = phi_2316_;
                                                            phi_2317_ = _e1808;
                                                        }
                                                        let _e1810 = phi_2317_;
                                                        phi_2318_ = _e1810;
                                                    }
                                                    let _e1812 = phi_2318_;
                                                    phi_2319_ = _e1812;
                                                }
                                                let _e1814 = phi_2319_;
                                                phi_2320_ = _e1814;
                                            }
                                            let _e1816 = phi_2320_;
                                            local_135 = _e1816;
                                            let _e1817 = local_133;
                                            let _e1819 = ((_e1817 + 1u) % 6u);
                                            local_136 = _e1819;
                                            if (_e1819 == 0u) {
                                                phi_2355_ = array<f32, 2>(1f, 0f);
                                            } else {
                                                let _e1821 = local_136;
                                                if (_e1821 == 1u) {
                                                    phi_2354_ = array<f32, 2>(0.5f, 0.8660254f);
                                                } else {
                                                    let _e1823 = local_136;
                                                    if (_e1823 == 2u) {
                                                        phi_2353_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                    } else {
                                                        let _e1825 = local_136;
                                                        if (_e1825 == 3u) {
                                                            phi_2352_ = array<f32, 2>(-1f, 0f);
                                                        } else {
                                                            let _e1827 = local_136;
                                                            if (_e1827 == 4u) {
                                                                phi_2351_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                            } else {
                                                                phi_2351_ = array<f32, 2>(0.5f, -0.8660254f);
                                                            }
                                                            let _e1830 = phi_2351_;
                                                            phi_2352_ = _e1830;
                                                        }
                                                        let _e1832 = phi_2352_;
                                                        phi_2353_ = _e1832;
                                                    }
                                                    let _e1834 = phi_2353_;
                                                    phi_2354_ = _e1834;
                                                }
                                                let _e1836 = phi_2354_;
                                                phi_2355_ = _e1836;
                                            }
                                            let _e1838 = phi_2355_;
                                            let _e1839 = local_127;
                                            let _e1840 = f32(_e1839);
                                            let _e1841 = local_135;
                                            let _e1846 = local_134;
                                            let _e1849 = local_135;
                                            let _e1854 = local_134;
                                            let _e1857 = local_244;
                                            let _e1858 = (((_e1841[0] * _e1840) + ((_e1838[0] - _e1841[0]) * _e1846)) * _e1857);
                                            let _e1859 = local_244;
                                            let _e1860 = (((_e1849[1] * _e1840) + ((_e1838[1] - _e1849[1]) * _e1854)) * _e1859);
                                            let _e1861 = local_12;
                                            let _e1865 = floor(((f32(_e1861) + 0.5f) + _e1858));
                                            let _e1866 = local_13;
                                            let _e1870 = floor(((f32(_e1866) + 0.5f) + _e1860));
                                            let _e1872 = select(0f, _e1865, (_e1865 > 0f));
                                            let _e1873 = local_122;
                                            let _e1875 = f32((_e1873 - 1u));
                                            let _e1877 = select(_e1875, _e1872, (_e1872 < _e1875));
                                            let _e1885 = select(0f, _e1870, (_e1870 > 0f));
                                            let _e1886 = local_123;
                                            let _e1888 = f32((_e1886 - 1u));
                                            let _e1890 = select(_e1888, _e1885, (_e1885 < _e1888));
                                            let _e1897 = local_122;
                                            let _e1900 = (9u * ((select(select(u32(_e1890), 0u, !((_e1890 >= 0f))), 4294967295u, (_e1890 > 4294967000f)) * _e1897) + select(select(u32(_e1877), 0u, !((_e1877 >= 0f))), 4294967295u, (_e1877 > 4294967000f))));
                                            local_137 = _e1900;
                                            local_138 = sqrt(((_e1858 * _e1858) + (_e1860 * _e1860)));
                                            let _e1905 = (_e1900 + 8u);
                                            local_139 = _e1905;
                                            let _e1906 = local_1;
                                            if (_e1905 < _e1906) {
                                            } else {
                                                phi_4153_ = true;
                                                break;
                                            }
                                            let _e1908 = local_139;
                                            let _e1911 = global_3.member[_e1908];
                                            let _e1912 = bitcast<f32>(_e1911);
                                            local_140 = _e1912;
                                            if ((bitcast<u32>(_e1912) & 2147483647u) > 2139095040u) {
                                                phi_2967_ = _e1780;
                                            } else {
                                                let _e1916 = local_137;
                                                let _e1917 = (_e1916 + 3u);
                                                local_141 = _e1917;
                                                let _e1918 = local_1;
                                                if (_e1917 < _e1918) {
                                                } else {
                                                    phi_4153_ = true;
                                                    break;
                                                }
                                                let _e1920 = local_141;
                                                let _e1923 = global_3.member[_e1920];
                                                let _e1924 = bitcast<f32>(_e1923);
                                                local_142 = _e1924;
                                                if (_e1924 > 0f) {
                                                    let _e1926 = local_137;
                                                    let _e1927 = local_1;
                                                    if (_e1926 < _e1927) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e1929 = local_137;
                                                    let _e1932 = global_3.member[_e1929];
                                                    local_143 = bitcast<f32>(_e1932);
                                                    let _e1934 = local_137;
                                                    let _e1935 = (_e1934 + 1u);
                                                    local_144 = _e1935;
                                                    let _e1936 = local_1;
                                                    if (_e1935 < _e1936) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e1938 = local_144;
                                                    let _e1941 = global_3.member[_e1938];
                                                    local_145 = bitcast<f32>(_e1941);
                                                    let _e1943 = local_137;
                                                    let _e1944 = (_e1943 + 2u);
                                                    local_146 = _e1944;
                                                    let _e1945 = local_1;
                                                    if (_e1944 < _e1945) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e1947 = local_146;
                                                    let _e1950 = global_3.member[_e1947];
                                                    local_147 = bitcast<f32>(_e1950);
                                                    let _e1952 = local_137;
                                                    let _e1953 = (_e1952 + 7u);
                                                    local_148 = _e1953;
                                                    let _e1954 = local_1;
                                                    if (_e1953 < _e1954) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e1956 = local_148;
                                                    let _e1959 = global_3.member[_e1956];
                                                    let _e1960 = bitcast<f32>(_e1959);
                                                    local_149 = _e1960;
                                                    local_150 = -(_e1960);
                                                    let _e1962 = (-0.5f - _e1960);
                                                    let _e1964 = select(0f, _e1962, (_e1962 > 0f));
                                                    let _e1968 = local_142;
                                                    let _e1969 = (_e1968 * (1f - select(1f, _e1964, (_e1964 < 1f))));
                                                    local_151 = _e1969;
                                                    if (_e1969 <= 0f) {
                                                        phi_2643_ = _e1780;
                                                    } else {
                                                        let _e1971 = local_234;
                                                        let _e1973 = local_234;
                                                        local_245 = select(0f, _e1973, (_e1971 > 0f));
                                                        let _e1975 = local_149;
                                                        let _e1976 = local_234;
                                                        let _e1977 = (_e1975 > _e1976);
                                                        local_152 = _e1977;
                                                        if _e1977 {
                                                            let _e1983 = local_149;
                                                            let _e1985 = local_150;
                                                            let _e1986 = local_149;
                                                            let _e1987 = select(_e1986, _e1985, (_e1983 < 0f));
                                                            let _e1988 = local_245;
                                                            let _e1990 = local_245;
                                                            phi_2542_ = select(_e1990, _e1987, (_e1987 < _e1988));
                                                        } else {
                                                            let _e1978 = local_149;
                                                            let _e1980 = local_150;
                                                            let _e1981 = local_149;
                                                            phi_2542_ = select(_e1981, _e1980, (_e1978 < 0f));
                                                        }
                                                        let _e1993 = phi_2542_;
                                                        local_153 = _e1993;
                                                        let _e1994 = local_138;
                                                        if (_e1994 == 0f) {
                                                            phi_2560_ = 1f;
                                                        } else {
                                                            let _e1996 = local_153;
                                                            let _e1997 = local_138;
                                                            let _e1999 = local_244;
                                                            let _e2001 = ((_e1996 - _e1997) + (0.5f * _e1999));
                                                            let _e2003 = select(0f, _e2001, (_e2001 > 0f));
                                                            phi_2560_ = select(1f, _e2003, (_e2003 < 1f));
                                                        }
                                                        let _e2007 = phi_2560_;
                                                        let _e2008 = local_151;
                                                        let _e2010 = local_153;
                                                        let _e2011 = local_153;
                                                        let _e2012 = (_e2010 * _e2011);
                                                        let _e2015 = ((_e2008 * _e2007) / select(0.25f, _e2012, (_e2012 > 0.25f)));
                                                        let _e2016 = local_129;
                                                        let _e2019 = local_143;
                                                        let _e2022 = local_129;
                                                        let _e2025 = local_145;
                                                        let _e2028 = local_129;
                                                        let _e2031 = local_147;
                                                        let _e2035 = local_129;
                                                        let _e2042 = type_16(array<f32, 3>((_e2016.member[0] + (_e2015 * _e2019)), (_e2022.member[1] + (_e2015 * _e2025)), (_e2028.member[2] + (_e2015 * _e2031))), _e2035.member_1, _e2035.member_2, _e2035.member_3, _e2035.member_4, _e2035.member_5);
                                                        let _e2043 = local_129;
                                                        let _e2052 = type_16(_e2042.member, (_e2043.member_1 + _e2015), _e2042.member_2, _e2042.member_3, _e2042.member_4, _e2042.member_5);
                                                        local_154 = _e2052;
                                                        let _e2053 = local_152;
                                                        if _e2053 {
                                                            let _e2054 = local_235;
                                                            if (_e2054 > 0f) {
                                                                let _e2056 = local_30;
                                                                let _e2057 = local_138;
                                                                let _e2059 = local_244;
                                                                let _e2061 = ((_e2056 - _e2057) + (0.5f * _e2059));
                                                                let _e2063 = select(0f, _e2061, (_e2061 > 0f));
                                                                let _e2066 = local_151;
                                                                let _e2068 = local_30;
                                                                let _e2069 = local_30;
                                                                let _e2070 = (_e2068 * _e2069);
                                                                let _e2073 = ((_e2066 * select(1f, _e2063, (_e2063 < 1f))) / select(0.25f, _e2070, (_e2070 > 0.25f)));
                                                                let _e2074 = local_129;
                                                                let _e2077 = local_143;
                                                                let _e2080 = local_129;
                                                                let _e2083 = local_145;
                                                                let _e2086 = local_129;
                                                                let _e2089 = local_147;
                                                                let _e2093 = local_154;
                                                                let _e2100 = type_16(_e2093.member, _e2093.member_1, array<f32, 3>((_e2074.member_2[0] + (_e2073 * _e2077)), (_e2080.member_2[1] + (_e2073 * _e2083)), (_e2086.member_2[2] + (_e2073 * _e2089))), _e2093.member_3, _e2093.member_4, _e2093.member_5);
                                                                let _e2101 = local_129;
                                                                phi_2641_ = type_16(_e2100.member, _e2100.member_1, _e2100.member_2, (_e2101.member_3 + _e2073), _e2100.member_4, _e2100.member_5);
                                                            } else {
                                                                phi_2641_ = _e2052;
                                                            }
                                                            let _e2112 = phi_2641_;
                                                            phi_2642_ = _e2112;
                                                        } else {
                                                            phi_2642_ = _e2052;
                                                        }
                                                        let _e2114 = phi_2642_;
                                                        phi_2643_ = _e2114;
                                                    }
                                                    let _e2116 = phi_2643_;
                                                    phi_2711_ = _e2116;
                                                } else {
                                                    phi_2711_ = _e1780;
                                                }
                                                let _e2118 = phi_2711_;
                                                local_155 = _e2118;
                                                let _e2119 = local_142;
                                                if (_e2119 < 1f) {
                                                    let _e2121 = local_137;
                                                    let _e2122 = (_e2121 + 4u);
                                                    local_156 = _e2122;
                                                    let _e2123 = local_1;
                                                    if (_e2122 < _e2123) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e2125 = local_156;
                                                    let _e2128 = global_3.member[_e2125];
                                                    local_157 = bitcast<f32>(_e2128);
                                                    let _e2130 = local_137;
                                                    let _e2131 = (_e2130 + 5u);
                                                    local_158 = _e2131;
                                                    let _e2132 = local_1;
                                                    if (_e2131 < _e2132) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e2134 = local_158;
                                                    let _e2137 = global_3.member[_e2134];
                                                    local_159 = bitcast<f32>(_e2137);
                                                    let _e2139 = local_137;
                                                    let _e2140 = (_e2139 + 6u);
                                                    local_160 = _e2140;
                                                    let _e2141 = local_1;
                                                    if (_e2140 < _e2141) {
                                                    } else {
                                                        phi_4153_ = true;
                                                        break;
                                                    }
                                                    let _e2143 = local_160;
                                                    let _e2146 = global_3.member[_e2143];
                                                    local_161 = bitcast<f32>(_e2146);
                                                    let _e2148 = local_142;
                                                    let _e2150 = local_140;
                                                    local_162 = -(_e2150);
                                                    let _e2152 = local_140;
                                                    let _e2153 = (-0.5f - _e2152);
                                                    let _e2155 = select(0f, _e2153, (_e2153 > 0f));
                                                    let _e2159 = ((1f - _e2148) * (1f - select(1f, _e2155, (_e2155 < 1f))));
                                                    local_163 = _e2159;
                                                    if (_e2159 <= 0f) {
                                                        phi_2897_ = _e2118;
                                                    } else {
                                                        let _e2161 = local_234;
                                                        let _e2163 = local_234;
                                                        local_246 = select(0f, _e2163, (_e2161 > 0f));
                                                        let _e2165 = local_140;
                                                        let _e2166 = local_234;
                                                        let _e2167 = (_e2165 > _e2166);
                                                        local_164 = _e2167;
                                                        if _e2167 {
                                                            let _e2173 = local_140;
                                                            let _e2175 = local_162;
                                                            let _e2176 = local_140;
                                                            let _e2177 = select(_e2176, _e2175, (_e2173 < 0f));
                                                            let _e2178 = local_246;
                                                            let _e2180 = local_246;
                                                            phi_2796_ = select(_e2180, _e2177, (_e2177 < _e2178));
                                                        } else {
                                                            let _e2168 = local_140;
                                                            let _e2170 = local_162;
                                                            let _e2171 = local_140;
                                                            phi_2796_ = select(_e2171, _e2170, (_e2168 < 0f));
                                                        }
                                                        let _e2183 = phi_2796_;
                                                        local_165 = _e2183;
                                                        let _e2184 = local_138;
                                                        if (_e2184 == 0f) {
                                                            phi_2814_ = 1f;
                                                        } else {
                                                            let _e2186 = local_165;
                                                            let _e2187 = local_138;
                                                            let _e2189 = local_244;
                                                            let _e2191 = ((_e2186 - _e2187) + (0.5f * _e2189));
                                                            let _e2193 = select(0f, _e2191, (_e2191 > 0f));
                                                            phi_2814_ = select(1f, _e2193, (_e2193 < 1f));
                                                        }
                                                        let _e2197 = phi_2814_;
                                                        let _e2198 = local_163;
                                                        let _e2200 = local_165;
                                                        let _e2201 = local_165;
                                                        let _e2202 = (_e2200 * _e2201);
                                                        let _e2205 = ((_e2198 * _e2197) / select(0.25f, _e2202, (_e2202 > 0.25f)));
                                                        let _e2206 = local_155;
                                                        let _e2209 = local_157;
                                                        let _e2212 = local_155;
                                                        let _e2215 = local_159;
                                                        let _e2218 = local_155;
                                                        let _e2221 = local_161;
                                                        let _e2225 = local_155;
                                                        let _e2232 = type_16(array<f32, 3>((_e2206.member[0] + (_e2205 * _e2209)), (_e2212.member[1] + (_e2205 * _e2215)), (_e2218.member[2] + (_e2205 * _e2221))), _e2225.member_1, _e2225.member_2, _e2225.member_3, _e2225.member_4, _e2225.member_5);
                                                        let _e2233 = local_155;
                                                        let _e2242 = type_16(_e2232.member, (_e2233.member_1 + _e2205), _e2232.member_2, _e2232.member_3, _e2232.member_4, _e2232.member_5);
                                                        local_166 = _e2242;
                                                        let _e2243 = local_164;
                                                        if _e2243 {
                                                            let _e2244 = local_235;
                                                            if (_e2244 > 0f) {
                                                                let _e2246 = local_30;
                                                                let _e2247 = local_138;
                                                                let _e2249 = local_244;
                                                                let _e2251 = ((_e2246 - _e2247) + (0.5f * _e2249));
                                                                let _e2253 = select(0f, _e2251, (_e2251 > 0f));
                                                                let _e2256 = local_163;
                                                                let _e2258 = local_30;
                                                                let _e2259 = local_30;
                                                                let _e2260 = (_e2258 * _e2259);
                                                                let _e2263 = ((_e2256 * select(1f, _e2253, (_e2253 < 1f))) / select(0.25f, _e2260, (_e2260 > 0.25f)));
                                                                let _e2264 = local_155;
                                                                let _e2267 = local_157;
                                                                let _e2270 = local_155;
                                                                let _e2273 = local_159;
                                                                let _e2276 = local_155;
                                                                let _e2279 = local_161;
                                                                let _e2283 = local_166;
                                                                let _e2290 = type_16(_e2283.member, _e2283.member_1, array<f32, 3>((_e2264.member_2[0] + (_e2263 * _e2267)), (_e2270.member_2[1] + (_e2263 * _e2273)), (_e2276.member_2[2] + (_e2263 * _e2279))), _e2283.member_3, _e2283.member_4, _e2283.member_5);
                                                                let _e2291 = local_155;
                                                                phi_2895_ = type_16(_e2290.member, _e2290.member_1, _e2290.member_2, (_e2291.member_3 + _e2263), _e2290.member_4, _e2290.member_5);
                                                            } else {
                                                                phi_2895_ = _e2242;
                                                            }
                                                            let _e2302 = phi_2895_;
                                                            phi_2896_ = _e2302;
                                                        } else {
                                                            phi_2896_ = _e2242;
                                                        }
                                                        let _e2304 = phi_2896_;
                                                        phi_2897_ = _e2304;
                                                    }
                                                    let _e2306 = phi_2897_;
                                                    phi_2966_ = _e2306;
                                                } else {
                                                    phi_2966_ = _e2118;
                                                }
                                                let _e2308 = phi_2966_;
                                                phi_2967_ = _e2308;
                                            }
                                            let _e2310 = phi_2967_;
                                            let _e2311 = local_130;
                                            phi_2266_ = _e2310;
                                            phi_2269_ = (_e2311 + 1u);
                                        } else {
                                            phi_2266_ = type_16();
                                            phi_2269_ = u32();
                                        }
                                        let _e2314 = phi_2266_;
                                        let _e2316 = phi_2269_;
                                        continue;
                                        continuing {
                                            let _e2317 = local_131;
                                            phi_2265_ = _e2314;
                                            phi_2268_ = _e2316;
                                            phi_4153_ = _e1771;
                                            break if !(_e2317);
                                        }
                                    }
                                    let _e2320 = phi_4153_;
                                    phi_4237_ = _e2320;
                                    if _e2320 {
                                        break;
                                    }
                                    let _e2321 = local_127;
                                    phi_4238_ = _e2320;
                                    let _e3064 = local_251;
                                    phi_2254_ = _e3064;
                                    phi_2257_ = (_e2321 + 1u);
                                } else {
                                    phi_4238_ = _e1771;
                                    phi_2254_ = type_16();
                                    phi_2257_ = u32();
                                }
                                let _e2324 = phi_4238_;
                                let _e2326 = phi_2254_;
                                let _e2328 = phi_2257_;
                                continue;
                                continuing {
                                    let _e2329 = local_128;
                                    phi_4163_ = _e2324;
                                    phi_2253_ = _e2326;
                                    phi_2256_ = _e2328;
                                    phi_4237_ = _e2324;
                                    break if !(_e2329);
                                }
                            }
                            let _e2332 = phi_4237_;
                            if _e2332 {
                                break;
                            }
                            phi_4255_ = _e2332;
                            let _e3070 = local_252;
                            phi_2970_ = _e3070;
                        } else {
                            phi_4255_ = _e1723;
                            phi_2970_ = _e963;
                        }
                        let _e2334 = phi_4255_;
                        let _e2336 = phi_2970_;
                        let _e2337 = local_70;
                        if _e2337 {
                            let _e2338 = local_7;
                            if _e2338 {
                                let _e2339 = local_6;
                                phi_2991_ = (_e2339 + 1u);
                            } else {
                                phi_2991_ = _e305;
                            }
                            let _e2342 = phi_2991_;
                            local_167 = _e2342;
                            let _e2343 = local_10;
                            if _e2343 {
                                let _e2344 = local_9;
                                phi_3009_ = (_e2344 + 1u);
                            } else {
                                phi_3009_ = _e315;
                            }
                            let _e2347 = phi_3009_;
                            local_168 = _e2347;
                            let _e2350 = global_2.member.member_2;
                            let _e2352 = select(_e2350, 1u, (_e2350 == 0u));
                            let _e2353 = f32(_e2352);
                            local_169 = _e2353;
                            let _e2354 = local_28;
                            let _e2355 = (_e2354 / _e2353);
                            let _e2357 = select(1f, _e2355, (_e2355 > 1f));
                            local_247 = _e2357;
                            let _e2358 = local_28;
                            let _e2361 = ceil(((_e2358 / _e2357) + 0.5f));
                            local_170 = _e2361;
                            if (_e2361 < 1f) {
                                phi_3046_ = 1u;
                            } else {
                                let _e2363 = local_170;
                                let _e2364 = local_169;
                                if (_e2363 < _e2364) {
                                    let _e2366 = local_170;
                                    let _e2368 = local_170;
                                    let _e2371 = local_170;
                                    phi_3045_ = select(select(u32(_e2366), 0u, !((_e2368 >= 0f))), 4294967295u, (_e2371 > 4294967000f));
                                } else {
                                    phi_3045_ = _e2352;
                                }
                                let _e2376 = phi_3045_;
                                phi_3046_ = _e2376;
                            }
                            let _e2378 = phi_3046_;
                            local_171 = _e2378;
                            phi_4249_ = _e2334;
                            phi_3048_ = _e2336;
                            phi_3051_ = 1u;
                            loop {
                                let _e2380 = phi_4249_;
                                let _e2382 = phi_3048_;
                                let _e2384 = phi_3051_;
                                local_172 = _e2384;
                                local_254 = _e2382;
                                let _e2385 = local_172;
                                let _e2386 = local_171;
                                let _e2387 = (_e2385 <= _e2386);
                                local_173 = _e2387;
                                if _e2387 {
                                    phi_3060_ = _e2382;
                                    phi_3063_ = 0u;
                                    loop {
                                        let _e2389 = phi_3060_;
                                        let _e2391 = phi_3063_;
                                        local_174 = _e2389;
                                        local_175 = _e2391;
                                        local_253 = _e2389;
                                        let _e2392 = local_172;
                                        let _e2394 = local_175;
                                        let _e2395 = (_e2394 < (6u * _e2392));
                                        local_176 = _e2395;
                                        if _e2395 {
                                            let _e2396 = local_172;
                                            let _e2397 = (_e2396 == 0u);
                                            local_177 = _e2397;
                                            if _e2397 {
                                                phi_4239_ = true;
                                                break;
                                            }
                                            let _e2398 = local_175;
                                            let _e2399 = local_172;
                                            local_178 = (_e2398 / _e2399);
                                            let _e2401 = local_177;
                                            if _e2401 {
                                                phi_4239_ = true;
                                                break;
                                            }
                                            let _e2402 = local_175;
                                            let _e2403 = local_172;
                                            local_179 = f32((_e2402 % _e2403));
                                            let _e2406 = local_178;
                                            if (_e2406 == 0u) {
                                                phi_3115_ = array<f32, 2>(1f, 0f);
                                            } else {
                                                let _e2408 = local_178;
                                                if (_e2408 == 1u) {
                                                    phi_3114_ = array<f32, 2>(0.5f, 0.8660254f);
                                                } else {
                                                    let _e2410 = local_178;
                                                    if (_e2410 == 2u) {
                                                        phi_3113_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                    } else {
                                                        let _e2412 = local_178;
                                                        if (_e2412 == 3u) {
                                                            phi_3112_ = array<f32, 2>(-1f, 0f);
                                                        } else {
                                                            let _e2414 = local_178;
                                                            if (_e2414 == 4u) {
                                                                phi_3111_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                            } else {
                                                                phi_3111_ = array<f32, 2>(0.5f, -0.8660254f);
                                                            }
                                                            let _e2417 = phi_3111_;
                                                            phi_3112_ = _e2417;
                                                        }
                                                        let _e2419 = phi_3112_;
                                                        phi_3113_ = _e2419;
                                                    }
                                                    let _e2421 = phi_3113_;
                                                    phi_3114_ = _e2421;
                                                }
                                                let _e2423 = phi_3114_;
                                                phi_3115_ = _e2423;
                                            }
                                            let _e2425 = phi_3115_;
                                            local_180 = _e2425;
                                            let _e2426 = local_178;
                                            let _e2428 = ((_e2426 + 1u) % 6u);
                                            local_181 = _e2428;
                                            if (_e2428 == 0u) {
                                                phi_3150_ = array<f32, 2>(1f, 0f);
                                            } else {
                                                let _e2430 = local_181;
                                                if (_e2430 == 1u) {
                                                    phi_3149_ = array<f32, 2>(0.5f, 0.8660254f);
                                                } else {
                                                    let _e2432 = local_181;
                                                    if (_e2432 == 2u) {
                                                        phi_3148_ = array<f32, 2>(-0.5f, 0.8660254f);
                                                    } else {
                                                        let _e2434 = local_181;
                                                        if (_e2434 == 3u) {
                                                            phi_3147_ = array<f32, 2>(-1f, 0f);
                                                        } else {
                                                            let _e2436 = local_181;
                                                            if (_e2436 == 4u) {
                                                                phi_3146_ = array<f32, 2>(-0.5f, -0.8660254f);
                                                            } else {
                                                                phi_3146_ = array<f32, 2>(0.5f, -0.8660254f);
                                                            }
                                                            let _e2439 = phi_3146_;
                                                            phi_3147_ = _e2439;
                                                        }
                                                        let _e2441 = phi_3147_;
                                                        phi_3148_ = _e2441;
                                                    }
                                                    let _e2443 = phi_3148_;
                                                    phi_3149_ = _e2443;
                                                }
                                                let _e2445 = phi_3149_;
                                                phi_3150_ = _e2445;
                                            }
                                            let _e2447 = phi_3150_;
                                            let _e2448 = local_172;
                                            let _e2449 = f32(_e2448);
                                            let _e2450 = local_180;
                                            let _e2455 = local_179;
                                            let _e2458 = local_180;
                                            let _e2463 = local_179;
                                            let _e2466 = local_247;
                                            let _e2467 = (((_e2450[0] * _e2449) + ((_e2447[0] - _e2450[0]) * _e2455)) * _e2466);
                                            let _e2468 = local_247;
                                            let _e2469 = (((_e2458[1] * _e2449) + ((_e2447[1] - _e2458[1]) * _e2463)) * _e2468);
                                            let _e2470 = local_12;
                                            let _e2474 = floor(((f32(_e2470) + 0.5f) + _e2467));
                                            let _e2475 = local_13;
                                            let _e2479 = floor(((f32(_e2475) + 0.5f) + _e2469));
                                            let _e2481 = select(0f, _e2474, (_e2474 > 0f));
                                            let _e2482 = local_167;
                                            let _e2484 = f32((_e2482 - 1u));
                                            let _e2486 = select(_e2484, _e2481, (_e2481 < _e2484));
                                            let _e2494 = select(0f, _e2479, (_e2479 > 0f));
                                            let _e2495 = local_168;
                                            let _e2497 = f32((_e2495 - 1u));
                                            let _e2499 = select(_e2497, _e2494, (_e2494 < _e2497));
                                            let _e2506 = local_167;
                                            let _e2509 = (9u * ((select(select(u32(_e2499), 0u, !((_e2499 >= 0f))), 4294967295u, (_e2499 > 4294967000f)) * _e2506) + select(select(u32(_e2486), 0u, !((_e2486 >= 0f))), 4294967295u, (_e2486 > 4294967000f))));
                                            local_182 = _e2509;
                                            local_183 = sqrt(((_e2467 * _e2467) + (_e2469 * _e2469)));
                                            let _e2514 = (_e2509 + 8u);
                                            local_184 = _e2514;
                                            let _e2515 = local_1;
                                            if (_e2514 < _e2515) {
                                            } else {
                                                phi_4239_ = true;
                                                break;
                                            }
                                            let _e2517 = local_184;
                                            let _e2520 = global_3.member[_e2517];
                                            let _e2521 = bitcast<f32>(_e2520);
                                            local_185 = _e2521;
                                            if ((bitcast<u32>(_e2521) & 2147483647u) > 2139095040u) {
                                                phi_3762_ = _e2389;
                                            } else {
                                                let _e2525 = local_182;
                                                let _e2526 = (_e2525 + 3u);
                                                local_186 = _e2526;
                                                let _e2527 = local_1;
                                                if (_e2526 < _e2527) {
                                                } else {
                                                    phi_4239_ = true;
                                                    break;
                                                }
                                                let _e2529 = local_186;
                                                let _e2532 = global_3.member[_e2529];
                                                let _e2533 = bitcast<f32>(_e2532);
                                                local_187 = _e2533;
                                                if (_e2533 > 0f) {
                                                    let _e2535 = local_182;
                                                    let _e2536 = local_1;
                                                    if (_e2535 < _e2536) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2538 = local_182;
                                                    let _e2541 = global_3.member[_e2538];
                                                    local_188 = bitcast<f32>(_e2541);
                                                    let _e2543 = local_182;
                                                    let _e2544 = (_e2543 + 1u);
                                                    local_189 = _e2544;
                                                    let _e2545 = local_1;
                                                    if (_e2544 < _e2545) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2547 = local_189;
                                                    let _e2550 = global_3.member[_e2547];
                                                    local_190 = bitcast<f32>(_e2550);
                                                    let _e2552 = local_182;
                                                    let _e2553 = (_e2552 + 2u);
                                                    local_191 = _e2553;
                                                    let _e2554 = local_1;
                                                    if (_e2553 < _e2554) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2556 = local_191;
                                                    let _e2559 = global_3.member[_e2556];
                                                    local_192 = bitcast<f32>(_e2559);
                                                    let _e2561 = local_182;
                                                    let _e2562 = (_e2561 + 7u);
                                                    local_193 = _e2562;
                                                    let _e2563 = local_1;
                                                    if (_e2562 < _e2563) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2565 = local_193;
                                                    let _e2568 = global_3.member[_e2565];
                                                    let _e2569 = bitcast<f32>(_e2568);
                                                    local_194 = _e2569;
                                                    local_195 = -(_e2569);
                                                    let _e2571 = (-0.5f - _e2569);
                                                    let _e2573 = select(0f, _e2571, (_e2571 > 0f));
                                                    let _e2576 = local_187;
                                                    let _e2577 = (_e2576 * select(1f, _e2573, (_e2573 < 1f)));
                                                    local_196 = _e2577;
                                                    if (_e2577 <= 0f) {
                                                        phi_3504_ = _e2389;
                                                    } else {
                                                        let _e2579 = local_247;
                                                        let _e2581 = local_247;
                                                        let _e2583 = local_194;
                                                        let _e2585 = local_195;
                                                        let _e2587 = (((0.8660254f * _e2579) * _e2581) / ((_e2583 * -3.1415927f) * _e2585));
                                                        let _e2590 = local_195;
                                                        let _e2591 = local_183;
                                                        let _e2593 = local_247;
                                                        let _e2595 = ((_e2590 - _e2591) + (0.5f * _e2593));
                                                        let _e2597 = select(0f, _e2595, (_e2595 > 0f));
                                                        let _e2600 = local_196;
                                                        let _e2602 = ((_e2600 * select(1f, _e2597, (_e2597 < 1f))) * select(1f, _e2587, (_e2587 < 1f)));
                                                        let _e2603 = local_174;
                                                        let _e2606 = local_188;
                                                        let _e2609 = local_174;
                                                        let _e2612 = local_190;
                                                        let _e2615 = local_174;
                                                        let _e2618 = local_192;
                                                        let _e2622 = local_174;
                                                        let _e2629 = type_16(_e2622.member, _e2622.member_1, _e2622.member_2, _e2622.member_3, array<f32, 3>((_e2603.member_4[0] + (_e2602 * _e2606)), (_e2609.member_4[1] + (_e2602 * _e2612)), (_e2615.member_4[2] + (_e2602 * _e2618))), _e2622.member_5);
                                                        let _e2630 = local_174;
                                                        phi_3504_ = type_16(_e2629.member, _e2629.member_1, _e2629.member_2, _e2629.member_3, _e2629.member_4, (_e2630.member_5 + _e2602));
                                                    }
                                                    let _e2641 = phi_3504_;
                                                    phi_3506_ = _e2641;
                                                } else {
                                                    phi_3506_ = _e2389;
                                                }
                                                let _e2643 = phi_3506_;
                                                local_197 = _e2643;
                                                let _e2644 = local_187;
                                                if (_e2644 < 1f) {
                                                    let _e2646 = local_182;
                                                    let _e2647 = (_e2646 + 4u);
                                                    local_198 = _e2647;
                                                    let _e2648 = local_1;
                                                    if (_e2647 < _e2648) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2650 = local_198;
                                                    let _e2653 = global_3.member[_e2650];
                                                    local_199 = bitcast<f32>(_e2653);
                                                    let _e2655 = local_182;
                                                    let _e2656 = (_e2655 + 5u);
                                                    local_200 = _e2656;
                                                    let _e2657 = local_1;
                                                    if (_e2656 < _e2657) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2659 = local_200;
                                                    let _e2662 = global_3.member[_e2659];
                                                    local_201 = bitcast<f32>(_e2662);
                                                    let _e2664 = local_182;
                                                    let _e2665 = (_e2664 + 6u);
                                                    local_202 = _e2665;
                                                    let _e2666 = local_1;
                                                    if (_e2665 < _e2666) {
                                                    } else {
                                                        phi_4239_ = true;
                                                        break;
                                                    }
                                                    let _e2668 = local_202;
                                                    let _e2671 = global_3.member[_e2668];
                                                    local_203 = bitcast<f32>(_e2671);
                                                    let _e2673 = local_187;
                                                    let _e2675 = local_185;
                                                    local_204 = -(_e2675);
                                                    let _e2677 = local_185;
                                                    let _e2678 = (-0.5f - _e2677);
                                                    let _e2680 = select(0f, _e2678, (_e2678 > 0f));
                                                    let _e2683 = ((1f - _e2673) * select(1f, _e2680, (_e2680 < 1f)));
                                                    local_205 = _e2683;
                                                    if (_e2683 <= 0f) {
                                                        phi_3759_ = _e2643;
                                                    } else {
                                                        let _e2685 = local_247;
                                                        let _e2687 = local_247;
                                                        let _e2689 = local_185;
                                                        let _e2691 = local_204;
                                                        let _e2693 = (((0.8660254f * _e2685) * _e2687) / ((_e2689 * -3.1415927f) * _e2691));
                                                        let _e2696 = local_204;
                                                        let _e2697 = local_183;
                                                        let _e2699 = local_247;
                                                        let _e2701 = ((_e2696 - _e2697) + (0.5f * _e2699));
                                                        let _e2703 = select(0f, _e2701, (_e2701 > 0f));
                                                        let _e2706 = local_205;
                                                        let _e2708 = ((_e2706 * select(1f, _e2703, (_e2703 < 1f))) * select(1f, _e2693, (_e2693 < 1f)));
                                                        let _e2709 = local_197;
                                                        let _e2712 = local_199;
                                                        let _e2715 = local_197;
                                                        let _e2718 = local_201;
                                                        let _e2721 = local_197;
                                                        let _e2724 = local_203;
                                                        let _e2728 = local_197;
                                                        let _e2735 = type_16(_e2728.member, _e2728.member_1, _e2728.member_2, _e2728.member_3, array<f32, 3>((_e2709.member_4[0] + (_e2708 * _e2712)), (_e2715.member_4[1] + (_e2708 * _e2718)), (_e2721.member_4[2] + (_e2708 * _e2724))), _e2728.member_5);
                                                        let _e2736 = local_197;
                                                        phi_3759_ = type_16(_e2735.member, _e2735.member_1, _e2735.member_2, _e2735.member_3, _e2735.member_4, (_e2736.member_5 + _e2708));
                                                    }
                                                    let _e2747 = phi_3759_;
                                                    phi_3761_ = _e2747;
                                                } else {
                                                    phi_3761_ = _e2643;
                                                }
                                                let _e2749 = phi_3761_;
                                                phi_3762_ = _e2749;
                                            }
                                            let _e2751 = phi_3762_;
                                            let _e2752 = local_175;
                                            phi_3061_ = _e2751;
                                            phi_3064_ = (_e2752 + 1u);
                                        } else {
                                            phi_3061_ = type_16();
                                            phi_3064_ = u32();
                                        }
                                        let _e2755 = phi_3061_;
                                        let _e2757 = phi_3064_;
                                        continue;
                                        continuing {
                                            let _e2758 = local_176;
                                            phi_3060_ = _e2755;
                                            phi_3063_ = _e2757;
                                            phi_4239_ = _e2380;
                                            break if !(_e2758);
                                        }
                                    }
                                    let _e2761 = phi_4239_;
                                    phi_4321_ = _e2761;
                                    if _e2761 {
                                        break;
                                    }
                                    let _e2762 = local_172;
                                    phi_4322_ = _e2761;
                                    let _e3101 = local_253;
                                    phi_3049_ = _e3101;
                                    phi_3052_ = (_e2762 + 1u);
                                } else {
                                    phi_4322_ = _e2380;
                                    phi_3049_ = type_16();
                                    phi_3052_ = u32();
                                }
                                let _e2765 = phi_4322_;
                                let _e2767 = phi_3049_;
                                let _e2769 = phi_3052_;
                                continue;
                                continuing {
                                    let _e2770 = local_173;
                                    phi_4249_ = _e2765;
                                    phi_3048_ = _e2767;
                                    phi_3051_ = _e2769;
                                    phi_4321_ = _e2765;
                                    break if !(_e2770);
                                }
                            }
                            let _e2773 = phi_4321_;
                            if _e2773 {
                                break;
                            }
                            let _e3106 = local_254;
                            phi_3765_ = _e3106;
                        } else {
                            phi_3765_ = _e2336;
                        }
                        let _e2775 = phi_3765_;
                        phi_3766_ = _e2775;
                    } else {
                        phi_3766_ = _e1725;
                    }
                    let _e2777 = phi_3766_;
                    local_206 = _e2777;
                    let _e2778 = local_14;
                    local_207 = (8u * _e2778);
                    local_208 = _e2777.member_1;
                    let _e2781 = (_e2777.member_1 > 0f);
                    local_209 = _e2781;
                    if _e2781 {
                        let _e2782 = local_208;
                        let _e2783 = (1f / _e2782);
                        let _e2784 = local_206;
                        let _e2788 = local_206;
                        let _e2792 = local_206;
                        phi_3784_ = array<f32, 3>((_e2784.member[0] * _e2783), (_e2788.member[1] * _e2783), (_e2792.member[2] * _e2783));
                    } else {
                        phi_3784_ = array<f32, 3>(0f, 0f, 0f);
                    }
                    let _e2798 = phi_3784_;
                    local_210 = _e2798;
                    let _e2799 = local_206;
                    local_211 = _e2799.member_3;
                    if (_e2799.member_3 > 0f) {
                        let _e2807 = local_211;
                        let _e2808 = (1f / _e2807);
                        let _e2809 = local_206;
                        local_212 = (_e2809.member_2[0] * _e2808);
                        let _e2813 = local_206;
                        local_213 = (_e2813.member_2[1] * _e2808);
                        let _e2817 = local_206;
                        local_214 = (_e2817.member_2[2] * _e2808);
                        let _e2821 = local_209;
                        if _e2821 {
                            phi_3816_ = _e416;
                        } else {
                            phi_3816_ = 1f;
                        }
                        let _e2823 = phi_3816_;
                        let _e2824 = local_210;
                        let _e2826 = local_212;
                        let _e2830 = local_210;
                        let _e2832 = local_213;
                        let _e2836 = local_210;
                        let _e2838 = local_214;
                        phi_3840_ = 1f;
                        phi_3841_ = array<f32, 3>((_e2824[0] + (_e2823 * (_e2826 - _e2824[0]))), (_e2830[1] + (_e2823 * (_e2832 - _e2830[1]))), (_e2836[2] + (_e2823 * (_e2838 - _e2836[2]))));
                    } else {
                        let _e2802 = local_209;
                        if _e2802 {
                            phi_3839_ = _e2798;
                        } else {
                            phi_3839_ = array<f32, 3>(0f, 0f, 0f);
                        }
                        let _e2804 = phi_3839_;
                        let _e2805 = local_209;
                        phi_3840_ = select(0f, 1f, _e2805);
                        phi_3841_ = _e2804;
                    }
                    let _e2844 = phi_3840_;
                    let _e2846 = phi_3841_;
                    local_215 = _e2844;
                    local_216 = _e2846;
                    let _e2847 = local_206;
                    local_217 = _e2847.member_5;
                    local_248 = select(1f, _e2847.member_5, (_e2847.member_5 < 1f));
                    if (_e2847.member_5 > 0f) {
                        let _e2852 = local_248;
                        let _e2853 = local_217;
                        phi_3855_ = (_e2852 / _e2853);
                    } else {
                        phi_3855_ = 0f;
                    }
                    let _e2856 = phi_3855_;
                    local_218 = _e2856;
                    let _e2857 = local_216;
                    local_219 = bitcast<u32>(_e2857[0]);
                    let _e2860 = local_207;
                    let _e2861 = local_3;
                    if (_e2860 < _e2861) {
                    } else {
                        break;
                    }
                    let _e2863 = local_207;
                    let _e2866 = local_219;
                    global_5.member[_e2863] = _e2866;
                    let _e2867 = local_207;
                    let _e2868 = (_e2867 + 1u);
                    local_220 = _e2868;
                    let _e2869 = local_216;
                    local_221 = bitcast<u32>(_e2869[1]);
                    let _e2872 = local_3;
                    if (_e2868 < _e2872) {
                    } else {
                        break;
                    }
                    let _e2874 = local_220;
                    let _e2877 = local_221;
                    global_5.member[_e2874] = _e2877;
                    let _e2878 = local_207;
                    let _e2879 = (_e2878 + 2u);
                    local_222 = _e2879;
                    let _e2880 = local_216;
                    local_223 = bitcast<u32>(_e2880[2]);
                    let _e2883 = local_3;
                    if (_e2879 < _e2883) {
                    } else {
                        break;
                    }
                    let _e2885 = local_222;
                    let _e2888 = local_223;
                    global_5.member[_e2885] = _e2888;
                    let _e2889 = local_207;
                    let _e2890 = (_e2889 + 3u);
                    local_224 = _e2890;
                    let _e2891 = local_215;
                    local_225 = bitcast<u32>(_e2891);
                    let _e2893 = local_3;
                    if (_e2890 < _e2893) {
                    } else {
                        break;
                    }
                    let _e2895 = local_224;
                    let _e2898 = local_225;
                    global_5.member[_e2895] = _e2898;
                    let _e2899 = local_207;
                    let _e2900 = (_e2899 + 4u);
                    local_226 = _e2900;
                    let _e2901 = local_206;
                    let _e2904 = local_218;
                    local_227 = bitcast<u32>((_e2901.member_4[0] * _e2904));
                    let _e2907 = local_3;
                    if (_e2900 < _e2907) {
                    } else {
                        break;
                    }
                    let _e2909 = local_226;
                    let _e2912 = local_227;
                    global_5.member[_e2909] = _e2912;
                    let _e2913 = local_207;
                    let _e2914 = (_e2913 + 5u);
                    local_228 = _e2914;
                    let _e2915 = local_206;
                    let _e2918 = local_218;
                    local_229 = bitcast<u32>((_e2915.member_4[1] * _e2918));
                    let _e2921 = local_3;
                    if (_e2914 < _e2921) {
                    } else {
                        break;
                    }
                    let _e2923 = local_228;
                    let _e2926 = local_229;
                    global_5.member[_e2923] = _e2926;
                    let _e2927 = local_207;
                    let _e2928 = (_e2927 + 6u);
                    local_230 = _e2928;
                    let _e2929 = local_206;
                    let _e2932 = local_218;
                    local_231 = bitcast<u32>((_e2929.member_4[2] * _e2932));
                    let _e2935 = local_3;
                    if (_e2928 < _e2935) {
                    } else {
                        break;
                    }
                    let _e2937 = local_230;
                    let _e2940 = local_231;
                    global_5.member[_e2937] = _e2940;
                    let _e2941 = local_207;
                    let _e2942 = (_e2941 + 7u);
                    local_232 = _e2942;
                    let _e2943 = local_248;
                    local_233 = bitcast<u32>(_e2943);
                    let _e2945 = local_3;
                    if (_e2942 < _e2945) {
                    } else {
                        break;
                    }
                    let _e2947 = local_232;
                    let _e2950 = local_233;
                    global_5.member[_e2947] = _e2950;
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
