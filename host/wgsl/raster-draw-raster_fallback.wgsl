struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_22 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
}

struct type_23 {
    member: array<f32, 4>,
    member_1: array<f32, 4>,
    member_2: array<f32, 4>,
    member_3: array<f32, 3>,
    member_4: f32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: array<u32, 3>,
}

struct type_24 {
    member: type_23,
}

struct type_29 {
    member: array<array<f32, 3>, 3>,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: array<f32, 2>,
    member_5: f32,
    member_6: array<f32, 3>,
    member_7: bool,
}

struct type_30 {
    member: f32,
    member_1: f32,
    member_2: f32,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_2: type_7;
@group(0) @binding(1) 
var<storage> global_3: type_7;
var<immediate> global_4: type_24;
@group(0) @binding(2) 
var<storage> global_5: type_7;
@group(0) @binding(7) 
var<storage> global_6: type_7;
@group(0) @binding(3) 
var<storage> global_7: type_7;
@group(0) @binding(4) 
var<storage> global_8: type_7;
@group(0) @binding(5) 
var<storage> global_9: type_7;
@group(0) @binding(6) 
var<storage> global_10: type_7;
@group(0) @binding(8) 
var<storage, read_write> global_11: type_7;

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
    var local_14: bool;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: bool;
    var local_21: u32;
    var local_22: u32;
    var local_23: bool;
    var local_24: u32;
    var local_25: u32;
    var local_26: bool;
    var local_27: u32;
    var local_28: u32;
    var local_29: bool;
    var local_30: u32;
    var local_31: u32;
    var local_32: f32;
    var local_33: u32;
    var local_34: f32;
    var local_35: u32;
    var local_36: f32;
    var local_37: u32;
    var local_38: f32;
    var local_39: u32;
    var local_40: f32;
    var local_41: u32;
    var local_42: f32;
    var local_43: u32;
    var local_44: f32;
    var local_45: u32;
    var local_46: f32;
    var local_47: u32;
    var local_48: f32;
    var local_49: f32;
    var local_50: f32;
    var local_51: f32;
    var local_52: f32;
    var local_53: f32;
    var local_54: f32;
    var local_55: f32;
    var local_56: f32;
    var local_57: f32;
    var local_58: f32;
    var local_59: u32;
    var local_60: u32;
    var local_61: u32;
    var local_62: u32;
    var local_63: f32;
    var local_64: f32;
    var local_65: f32;
    var local_66: f32;
    var local_67: f32;
    var local_68: f32;
    var local_69: f32;
    var local_70: f32;
    var local_71: f32;
    var local_72: f32;
    var local_73: f32;
    var local_74: f32;
    var local_75: f32;
    var local_76: f32;
    var local_77: u32;
    var local_78: u32;
    var local_79: bool;
    var local_80: u32;
    var local_81: bool;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: array<u32, 4>;
    var local_86: f32;
    var local_87: u32;
    var local_88: array<f32, 4>;
    var local_89: bool;
    var local_90: u32;
    var local_91: u32;
    var local_92: u32;
    var local_93: u32;
    var local_94: u32;
    var local_95: f32;
    var local_96: u32;
    var local_97: u32;
    var local_98: f32;
    var local_99: f32;
    var local_100: u32;
    var local_101: u32;
    var local_102: f32;
    var local_103: f32;
    var local_104: u32;
    var local_105: u32;
    var local_106: f32;
    var local_107: f32;
    var local_108: u32;
    var local_109: u32;
    var local_110: f32;
    var local_111: u32;
    var local_112: f32;
    var local_113: f32;
    var local_114: bool;
    var local_115: u32;
    var local_116: f32;
    var local_117: u32;
    var local_118: f32;
    var local_119: u32;
    var local_120: u32;
    var local_121: u32;
    var local_122: u32;
    var local_123: f32;
    var local_124: u32;
    var local_125: u32;
    var local_126: u32;
    var local_127: u32;
    var local_128: u32;
    var local_129: u32;
    var local_130: u32;
    var local_131: u32;
    var local_132: u32;
    var local_133: u32;
    var local_134: u32;
    var local_135: bool;
    var local_136: f32;
    var local_137: u32;
    var local_138: bool;
    var local_139: u32;
    var local_140: type_5;
    var local_141: bool;
    var local_142: u32;
    var local_143: bool;
    var local_144: u32;
    var local_145: type_5;
    var local_146: bool;
    var local_147: type_22;
    var local_148: f32;
    var local_149: u32;
    var local_150: f32;
    var local_151: u32;
    var local_152: f32;
    var local_153: f32;
    var local_154: f32;
    var local_155: f32;
    var local_156: f32;
    var local_157: i32;
    var local_158: i32;
    var local_159: u32;
    var local_160: i32;
    var local_161: bool;
    var local_162: i32;
    var local_163: bool;
    var local_164: bool;
    var local_165: i32;
    var local_166: i32;
    var local_167: bool;
    var local_168: bool;
    var local_169: i32;
    var local_170: u32;
    var local_171: i32;
    var local_172: i32;
    var local_173: bool;
    var local_174: bool;
    var local_175: i32;
    var local_176: i32;
    var local_177: bool;
    var local_178: bool;
    var local_179: i32;
    var local_180: u32;
    var local_181: u32;
    var local_182: i32;
    var local_183: bool;
    var local_184: i32;
    var local_185: bool;
    var local_186: bool;
    var local_187: i32;
    var local_188: i32;
    var local_189: bool;
    var local_190: bool;
    var local_191: i32;
    var local_192: u32;
    var local_193: i32;
    var local_194: i32;
    var local_195: bool;
    var local_196: bool;
    var local_197: i32;
    var local_198: i32;
    var local_199: bool;
    var local_200: bool;
    var local_201: i32;
    var local_202: u32;
    var local_203: u32;
    var local_204: u32;
    var local_205: u32;
    var local_206: u32;
    var local_207: u32;
    var local_208: u32;
    var local_209: u32;
    var local_210: u32;
    var local_211: f32;
    var local_212: u32;
    var local_213: u32;
    var local_214: f32;
    var local_215: u32;
    var local_216: u32;
    var local_217: f32;
    var local_218: u32;
    var local_219: u32;
    var local_220: f32;
    var local_221: u32;
    var local_222: u32;
    var local_223: u32;
    var local_224: u32;
    var local_225: u32;
    var local_226: u32;
    var local_227: f32;
    var local_228: u32;
    var local_229: u32;
    var local_230: f32;
    var local_231: u32;
    var local_232: u32;
    var local_233: f32;
    var local_234: u32;
    var local_235: u32;
    var local_236: f32;
    var local_237: f32;
    var local_238: f32;
    var local_239: f32;
    var local_240: u32;
    var local_241: u32;
    var local_242: u32;
    var local_243: u32;
    var local_244: u32;
    var local_245: u32;
    var local_246: u32;
    var local_247: f32;
    var local_248: u32;
    var local_249: u32;
    var local_250: f32;
    var local_251: u32;
    var local_252: u32;
    var local_253: f32;
    var local_254: u32;
    var local_255: u32;
    var local_256: f32;
    var local_257: u32;
    var local_258: u32;
    var local_259: u32;
    var local_260: u32;
    var local_261: u32;
    var local_262: u32;
    var local_263: f32;
    var local_264: u32;
    var local_265: u32;
    var local_266: f32;
    var local_267: u32;
    var local_268: u32;
    var local_269: f32;
    var local_270: u32;
    var local_271: u32;
    var local_272: f32;
    var local_273: u32;
    var local_274: u32;
    var local_275: u32;
    var local_276: u32;
    var local_277: u32;
    var local_278: u32;
    var local_279: u32;
    var local_280: u32;
    var local_281: bool;
    var local_282: type_29;
    var local_283: u32;
    var local_284: type_22;
    var local_285: bool;
    var local_286: u32;
    var local_287: u32;
    var local_288: type_22;
    var local_289: type_22;
    var local_290: u32;
    var local_291: type_22;
    var local_292: bool;
    var local_293: u32;
    var local_294: u32;
    var local_295: type_22;
    var local_296: type_22;
    var local_297: u32;
    var local_298: bool;
    var local_299: f32;
    var local_300: f32;
    var local_301: f32;
    var local_302: f32;
    var local_303: f32;
    var local_304: u32;
    var local_305: f32;
    var local_306: f32;
    var local_307: u32;
    var local_308: u32;
    var local_309: f32;
    var local_310: f32;
    var local_311: f32;
    var local_312: f32;
    var local_313: f32;
    var local_314: f32;
    var local_315: f32;
    var local_316: f32;
    var local_317: f32;
    var local_318: f32;
    var local_319: f32;
    var local_320: f32;
    var local_321: f32;
    var local_322: f32;
    var local_323: f32;
    var local_324: f32;
    var local_325: array<u32, 4>;
    var local_326: array<f32, 3>;
    var local_327: array<u32, 4>;
    var local_328: array<f32, 3>;
    var phi_3190_: bool;
    var phi_183_: u32;
    var phi_2900_: type_29;
    var phi_2902_: bool;
    var phi_2903_: type_29;
    var phi_2904_: bool;
    var phi_2906_: bool;
    var phi_2907_: type_29;
    var phi_2908_: bool;
    var phi_2909_: bool;
    var phi_3036_: type_29;
    var phi_684_: type_30;
    var phi_685_: type_30;
    var phi_686_: bool;
    var phi_687_: type_30;
    var phi_688_: bool;
    var phi_693_: type_30;
    var phi_694_: type_30;
    var phi_620_: type_30;
    var phi_621_: type_30;
    var phi_622_: bool;
    var phi_623_: type_30;
    var phi_624_: bool;
    var phi_625_: type_30;
    var phi_626_: bool;
    var phi_627_: type_30;
    var phi_628_: bool;
    var phi_633_: type_30;
    var phi_695_: type_30;
    var phi_732_: bool;
    var phi_760_: bool;
    var phi_822_: u32;
    var phi_825_: array<f32, 4>;
    var phi_892_: u32;
    var phi_895_: f32;
    var phi_935_: u32;
    var phi_938_: f32;
    var phi_978_: u32;
    var phi_981_: f32;
    var phi_1021_: u32;
    var phi_1024_: f32;
    var phi_823_: u32;
    var phi_826_: array<f32, 4>;
    var phi_3169_: bool;
    var phi_1042_: u32;
    var phi_1045_: f32;
    var phi_1047_: f32;
    var phi_1043_: u32;
    var phi_1046_: f32;
    var phi_1048_: f32;
    var phi_3207_: bool;
    var phi_1197_: bool;
    var phi_1383_: f32;
    var phi_3041_: u32;
    var phi_3042_: type_22;
    var phi_3059_: u32;
    var phi_3068_: u32;
    var phi_3073_: u32;
    var phi_3074_: type_22;
    var phi_3080_: u32;
    var phi_3081_: type_22;
    var phi_3098_: u32;
    var phi_3107_: u32;
    var phi_3112_: u32;
    var phi_3113_: type_22;
    var phi_3257_: bool;
    var phi_1402_: u32;
    var phi_1405_: type_5;
    var phi_3256_: bool;
    var phi_1419_: u32;
    var phi_1422_: type_5;
    var phi_1448_: u32;
    var phi_1451_: type_5;
    var phi_1464_: type_22;
    var phi_1465_: f32;
    var phi_1485_: f32;
    var phi_1486_: f32;
    var phi_1557_: i32;
    var phi_1581_: i32;
    var phi_1521_: i32;
    var phi_1522_: i32;
    var phi_1582_: i32;
    var phi_1637_: i32;
    var phi_1661_: i32;
    var phi_1601_: i32;
    var phi_1602_: i32;
    var phi_1662_: i32;
    var phi_1716_: i32;
    var phi_1740_: i32;
    var phi_1680_: i32;
    var phi_1681_: i32;
    var phi_1741_: i32;
    var phi_1796_: i32;
    var phi_1820_: i32;
    var phi_1760_: i32;
    var phi_1761_: i32;
    var phi_1821_: i32;
    var phi_1872_: u32;
    var phi_1875_: f32;
    var phi_1904_: u32;
    var phi_1907_: f32;
    var phi_1936_: u32;
    var phi_1939_: f32;
    var phi_1968_: u32;
    var phi_1971_: f32;
    var phi_2021_: u32;
    var phi_2024_: f32;
    var phi_2053_: u32;
    var phi_2056_: f32;
    var phi_2085_: u32;
    var phi_2088_: f32;
    var phi_2117_: u32;
    var phi_2120_: f32;
    var phi_2182_: u32;
    var phi_2185_: f32;
    var phi_2214_: u32;
    var phi_2217_: f32;
    var phi_2246_: u32;
    var phi_2249_: f32;
    var phi_2278_: u32;
    var phi_2281_: f32;
    var phi_2331_: u32;
    var phi_2334_: f32;
    var phi_2363_: u32;
    var phi_2366_: f32;
    var phi_2395_: u32;
    var phi_2398_: f32;
    var phi_2427_: u32;
    var phi_2430_: f32;
    var phi_1449_: u32;
    var phi_1452_: type_5;
    var phi_3210_: bool;
    var phi_3317_: bool;
    var phi_1420_: u32;
    var phi_1423_: type_5;
    var phi_3316_: bool;
    var phi_3319_: bool;
    var phi_1403_: u32;
    var phi_1406_: type_5;
    var phi_3318_: bool;
    var phi_3341_: bool;
    var phi_2483_: type_5;
    var phi_3340_: bool;
    var phi_2484_: type_5;
    var phi_2485_: bool;
    var phi_2489_: type_5;
    var phi_3338_: bool;
    var phi_2490_: type_5;
    var phi_3337_: bool;
    var phi_2491_: type_5;
    var phi_2492_: bool;
    var phi_2496_: type_5;
    var phi_2517_: bool;
    var phi_3334_: bool;
    var phi_2518_: bool;
    var phi_3333_: bool;
    var phi_2519_: bool;
    var phi_3332_: bool;
    var phi_2521_: bool;
    var phi_2522_: bool;
    var phi_3329_: bool;
    var phi_3328_: bool;
    var phi_3327_: bool;
    var phi_3326_: bool;
    var phi_3325_: bool;
    var phi_3324_: bool;
    var phi_3323_: bool;
    var phi_3322_: bool;
    var phi_3321_: bool;
    var phi_184_: u32;
    var phi_3320_: bool;
    var local_329: type_22;
    var local_330: type_22;
    var local_331: type_5;
    var local_332: type_5;
    var local_333: type_5;

    switch bitcast<i32>(0u) {
        default: {
            let _e399 = global;
            local = _e399;
            let _e400 = global_1;
            local_1 = arrayLength((&global_2.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_9.member));
            local_7 = arrayLength((&global_10.member));
            local_8 = arrayLength((&global_11.member));
            local_9 = _e400.x;
            local_10 = _e400.y;
            local_11 = (_e400.x * 16u);
            local_12 = (_e400.y * 16u);
            if (0u < arrayLength((&global_6.member))) {
            } else {
                break;
            }
            let _e426 = global_6.member[0u];
            let _e427 = (_e426 / 3u);
            let _e430 = global_4.member.member_7;
            local_297 = select(_e430, _e427, (_e427 < _e430));
            phi_3190_ = false;
            phi_183_ = 0u;
            loop {
                let _e434 = phi_3190_;
                let _e436 = phi_183_;
                local_13 = _e436;
                let _e437 = local_13;
                let _e438 = local_297;
                let _e439 = (_e437 < _e438);
                local_14 = _e439;
                if _e439 {
                    let _e440 = local_13;
                    let _e441 = (4u * _e440);
                    local_15 = _e441;
                    let _e442 = local_7;
                    if (_e441 < _e442) {
                    } else {
                        phi_3320_ = true;
                        break;
                    }
                    let _e444 = local_15;
                    let _e447 = global_10.member[_e444];
                    let _e448 = local_9;
                    if (_e448 >= _e447) {
                        let _e450 = local_15;
                        let _e451 = (_e450 + 1u);
                        local_16 = _e451;
                        let _e452 = local_7;
                        if (_e451 < _e452) {
                        } else {
                            phi_3320_ = true;
                            break;
                        }
                        let _e454 = local_16;
                        let _e457 = global_10.member[_e454];
                        let _e458 = local_10;
                        if (_e458 >= _e457) {
                            let _e460 = local_15;
                            let _e461 = (_e460 + 2u);
                            local_17 = _e461;
                            let _e462 = local_7;
                            if (_e461 < _e462) {
                            } else {
                                phi_3320_ = true;
                                break;
                            }
                            let _e464 = local_17;
                            let _e467 = global_10.member[_e464];
                            let _e468 = local_9;
                            if (_e468 <= _e467) {
                                let _e470 = local_15;
                                let _e471 = (_e470 + 3u);
                                local_18 = _e471;
                                let _e472 = local_7;
                                if (_e471 < _e472) {
                                } else {
                                    phi_3320_ = true;
                                    break;
                                }
                                let _e474 = local_18;
                                let _e477 = global_10.member[_e474];
                                let _e478 = local_10;
                                if (_e478 <= _e477) {
                                    let _e480 = local_13;
                                    let _e481 = (_e480 * 4u);
                                    local_19 = _e481;
                                    let _e482 = local_2;
                                    let _e483 = (_e481 < _e482);
                                    local_20 = _e483;
                                    if _e483 {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e484 = local_19;
                                    let _e487 = global_3.member[_e484];
                                    local_21 = _e487;
                                    let _e488 = local_19;
                                    let _e489 = (_e488 + 1u);
                                    local_22 = _e489;
                                    let _e490 = local_2;
                                    let _e491 = (_e489 < _e490);
                                    local_23 = _e491;
                                    if _e491 {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e492 = local_22;
                                    let _e495 = global_3.member[_e492];
                                    local_24 = _e495;
                                    let _e496 = local_19;
                                    let _e497 = (_e496 + 2u);
                                    local_25 = _e497;
                                    let _e498 = local_2;
                                    let _e499 = (_e497 < _e498);
                                    local_26 = _e499;
                                    if _e499 {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e500 = local_25;
                                    let _e503 = global_3.member[_e500];
                                    local_27 = _e503;
                                    let _e504 = local_19;
                                    let _e505 = (_e504 + 3u);
                                    local_28 = _e505;
                                    let _e506 = local_2;
                                    let _e507 = (_e505 < _e506);
                                    local_29 = _e507;
                                    if _e507 {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e508 = local_28;
                                    let _e511 = global_3.member[_e508];
                                    local_30 = _e511;
                                    let _e512 = local_21;
                                    let _e513 = (_e512 * 10u);
                                    local_31 = _e513;
                                    let _e514 = local_1;
                                    if (_e513 < _e514) {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e516 = local_31;
                                    let _e519 = global_2.member[_e516];
                                    local_32 = bitcast<f32>(_e519);
                                    let _e521 = local_31;
                                    let _e522 = (_e521 + 1u);
                                    local_33 = _e522;
                                    let _e523 = local_1;
                                    if (_e522 < _e523) {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e525 = local_33;
                                    let _e528 = global_2.member[_e525];
                                    local_34 = bitcast<f32>(_e528);
                                    let _e530 = local_31;
                                    let _e531 = (_e530 + 2u);
                                    local_35 = _e531;
                                    let _e532 = local_1;
                                    if (_e531 < _e532) {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e534 = local_35;
                                    let _e537 = global_2.member[_e534];
                                    local_36 = bitcast<f32>(_e537);
                                    let _e539 = local_24;
                                    let _e540 = (_e539 * 10u);
                                    local_37 = _e540;
                                    let _e541 = local_1;
                                    if (_e540 < _e541) {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e543 = local_37;
                                    let _e546 = global_2.member[_e543];
                                    local_38 = bitcast<f32>(_e546);
                                    let _e548 = local_37;
                                    let _e549 = (_e548 + 1u);
                                    local_39 = _e549;
                                    let _e550 = local_1;
                                    if (_e549 < _e550) {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e552 = local_39;
                                    let _e555 = global_2.member[_e552];
                                    local_40 = bitcast<f32>(_e555);
                                    let _e557 = local_37;
                                    let _e558 = (_e557 + 2u);
                                    local_41 = _e558;
                                    let _e559 = local_1;
                                    if (_e558 < _e559) {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e561 = local_41;
                                    let _e564 = global_2.member[_e561];
                                    local_42 = bitcast<f32>(_e564);
                                    let _e566 = local_27;
                                    let _e567 = (_e566 * 10u);
                                    local_43 = _e567;
                                    let _e568 = local_1;
                                    if (_e567 < _e568) {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e570 = local_43;
                                    let _e573 = global_2.member[_e570];
                                    local_44 = bitcast<f32>(_e573);
                                    let _e575 = local_43;
                                    let _e576 = (_e575 + 1u);
                                    local_45 = _e576;
                                    let _e577 = local_1;
                                    if (_e576 < _e577) {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e579 = local_45;
                                    let _e582 = global_2.member[_e579];
                                    local_46 = bitcast<f32>(_e582);
                                    let _e584 = local_43;
                                    let _e585 = (_e584 + 2u);
                                    local_47 = _e585;
                                    let _e586 = local_1;
                                    if (_e585 < _e586) {
                                    } else {
                                        phi_3320_ = true;
                                        break;
                                    }
                                    let _e588 = local_47;
                                    let _e591 = global_2.member[_e588];
                                    let _e592 = bitcast<f32>(_e591);
                                    local_48 = _e592;
                                    let _e593 = local_38;
                                    let _e594 = local_32;
                                    let _e595 = (_e593 - _e594);
                                    let _e596 = local_40;
                                    let _e597 = local_34;
                                    let _e598 = (_e596 - _e597);
                                    let _e599 = local_42;
                                    let _e600 = local_36;
                                    let _e601 = (_e599 - _e600);
                                    let _e602 = local_44;
                                    let _e603 = local_32;
                                    let _e604 = (_e602 - _e603);
                                    let _e605 = local_46;
                                    let _e606 = local_34;
                                    let _e607 = (_e605 - _e606);
                                    let _e608 = local_36;
                                    let _e609 = (_e592 - _e608);
                                    let _e612 = ((_e598 * _e609) - (_e601 * _e607));
                                    let _e615 = ((_e601 * _e604) - (_e595 * _e609));
                                    let _e618 = ((_e595 * _e607) - (_e598 * _e604));
                                    if ((((_e612 * _e612) + (_e615 * _e615)) + (_e618 * _e618)) == 0f) {
                                    } else {
                                        let _e625 = local_30;
                                        let _e628 = local_3;
                                        if (((_e625 * 16u) + 10u) < _e628) {
                                        } else {
                                            phi_3320_ = true;
                                            break;
                                        }
                                    }
                                    let _e632 = global_4.member.member;
                                    let _e634 = local_32;
                                    let _e637 = local_34;
                                    let _e641 = local_36;
                                    local_49 = ((((_e632[0] * _e634) + (_e632[1] * _e637)) + (_e632[2] * _e641)) + _e632[3]);
                                    let _e648 = global_4.member.member_1;
                                    let _e650 = local_32;
                                    let _e653 = local_34;
                                    let _e657 = local_36;
                                    local_50 = ((((_e648[0] * _e650) + (_e648[1] * _e653)) + (_e648[2] * _e657)) + _e648[3]);
                                    let _e664 = global_4.member.member_2;
                                    let _e666 = local_32;
                                    let _e669 = local_34;
                                    let _e673 = local_36;
                                    let _e677 = ((((_e664[0] * _e666) + (_e664[1] * _e669)) + (_e664[2] * _e673)) + _e664[3]);
                                    local_51 = _e677;
                                    let _e678 = local_38;
                                    let _e680 = local_40;
                                    let _e683 = local_42;
                                    local_52 = ((((_e632[0] * _e678) + (_e632[1] * _e680)) + (_e632[2] * _e683)) + _e632[3]);
                                    let _e687 = local_38;
                                    let _e689 = local_40;
                                    let _e692 = local_42;
                                    local_53 = ((((_e648[0] * _e687) + (_e648[1] * _e689)) + (_e648[2] * _e692)) + _e648[3]);
                                    let _e696 = local_38;
                                    let _e698 = local_40;
                                    let _e701 = local_42;
                                    local_54 = ((((_e664[0] * _e696) + (_e664[1] * _e698)) + (_e664[2] * _e701)) + _e664[3]);
                                    let _e705 = local_44;
                                    let _e707 = local_46;
                                    let _e710 = local_48;
                                    local_55 = ((((_e632[0] * _e705) + (_e632[1] * _e707)) + (_e632[2] * _e710)) + _e632[3]);
                                    let _e714 = local_44;
                                    let _e716 = local_46;
                                    let _e719 = local_48;
                                    local_56 = ((((_e648[0] * _e714) + (_e648[1] * _e716)) + (_e648[2] * _e719)) + _e648[3]);
                                    let _e723 = local_44;
                                    let _e725 = local_46;
                                    let _e728 = local_48;
                                    local_57 = ((((_e664[0] * _e723) + (_e664[1] * _e725)) + (_e664[2] * _e728)) + _e664[3]);
                                    let _e734 = global_4.member.member_4;
                                    local_58 = _e734;
                                    if (_e677 < _e734) {
                                        phi_2906_ = bool();
                                        phi_2907_ = type_29();
                                        phi_2908_ = true;
                                        phi_2909_ = false;
                                    } else {
                                        let _e736 = local_54;
                                        let _e737 = local_58;
                                        let _e738 = (_e736 < _e737);
                                        if _e738 {
                                            phi_2902_ = bool();
                                            phi_2903_ = type_29();
                                            phi_2904_ = false;
                                        } else {
                                            let _e739 = local_57;
                                            let _e740 = local_58;
                                            let _e741 = (_e739 < _e740);
                                            local_281 = _e741;
                                            if _e741 {
                                                phi_2900_ = type_29();
                                            } else {
                                                let _e742 = local_51;
                                                let _e743 = (1f / _e742);
                                                let _e744 = local_54;
                                                let _e745 = (1f / _e744);
                                                let _e746 = local_57;
                                                let _e747 = (1f / _e746);
                                                let _e749 = local_49;
                                                let _e750 = (_e749 * _e743);
                                                let _e751 = local_50;
                                                let _e752 = (_e751 * _e743);
                                                let _e754 = local_52;
                                                let _e756 = local_53;
                                                let _e758 = local_55;
                                                let _e760 = local_56;
                                                let _e762 = ((_e754 * _e745) - _e750);
                                                let _e763 = ((_e756 * _e745) - _e752);
                                                let _e765 = ((_e758 * _e747) - _e750);
                                                let _e766 = ((_e760 * _e747) - _e752);
                                                let _e771 = local_281;
                                                phi_2900_ = type_29(array<array<f32, 3>, 3>(array<f32, 3>(0f, 0f, 0f), array<f32, 3>(0f, 0f, 0f), array<f32, 3>(0f, 0f, 0f)), 0f, array<f32, 2>(_e750, _e752), array<f32, 2>(_e762, _e763), array<f32, 2>(_e765, _e766), ((_e762 * _e766) - (_e763 * _e765)), array<f32, 3>(_e743, _e745, _e747), _e771);
                                            }
                                            let _e774 = phi_2900_;
                                            phi_2902_ = _e741;
                                            phi_2903_ = _e774;
                                            phi_2904_ = _e741;
                                        }
                                        let _e776 = phi_2902_;
                                        let _e778 = phi_2903_;
                                        let _e780 = phi_2904_;
                                        phi_2906_ = _e776;
                                        phi_2907_ = _e778;
                                        phi_2908_ = _e738;
                                        phi_2909_ = _e780;
                                    }
                                    let _e782 = phi_2906_;
                                    let _e784 = phi_2907_;
                                    let _e786 = phi_2908_;
                                    let _e788 = phi_2909_;
                                    local_298 = select(_e782, true, _e786);
                                    if select(_e788, true, _e786) {
                                        let _e791 = local_53;
                                        let _e792 = local_57;
                                        let _e794 = local_54;
                                        let _e795 = local_56;
                                        let _e797 = ((_e791 * _e792) - (_e794 * _e795));
                                        let _e798 = local_54;
                                        let _e799 = local_55;
                                        let _e801 = local_52;
                                        let _e802 = local_57;
                                        let _e804 = ((_e798 * _e799) - (_e801 * _e802));
                                        let _e805 = local_52;
                                        let _e806 = local_56;
                                        let _e808 = local_53;
                                        let _e809 = local_55;
                                        let _e811 = ((_e805 * _e806) - (_e808 * _e809));
                                        let _e813 = local_56;
                                        let _e814 = local_51;
                                        let _e816 = local_57;
                                        let _e817 = local_50;
                                        let _e820 = local_57;
                                        let _e821 = local_49;
                                        let _e823 = local_55;
                                        let _e824 = local_51;
                                        let _e827 = local_55;
                                        let _e828 = local_50;
                                        let _e830 = local_56;
                                        let _e831 = local_49;
                                        let _e835 = local_50;
                                        let _e836 = local_54;
                                        let _e838 = local_51;
                                        let _e839 = local_53;
                                        let _e842 = local_51;
                                        let _e843 = local_52;
                                        let _e845 = local_49;
                                        let _e846 = local_54;
                                        let _e849 = local_49;
                                        let _e850 = local_53;
                                        let _e852 = local_50;
                                        let _e853 = local_52;
                                        let _e857 = local_49;
                                        let _e859 = local_50;
                                        let _e862 = local_51;
                                        let _e866 = local_298;
                                        phi_3036_ = type_29(array<array<f32, 3>, 3>(array<f32, 3>(_e797, _e804, _e811), array<f32, 3>(((_e813 * _e814) - (_e816 * _e817)), ((_e820 * _e821) - (_e823 * _e824)), ((_e827 * _e828) - (_e830 * _e831))), array<f32, 3>(((_e835 * _e836) - (_e838 * _e839)), ((_e842 * _e843) - (_e845 * _e846)), ((_e849 * _e850) - (_e852 * _e853)))), (((_e857 * _e797) + (_e859 * _e804)) + (_e862 * _e811)), array<f32, 2>(0f, 0f), array<f32, 2>(0f, 0f), array<f32, 2>(0f, 0f), 0f, array<f32, 3>(0f, 0f, 0f), _e866);
                                    } else {
                                        phi_3036_ = _e784;
                                    }
                                    let _e869 = phi_3036_;
                                    local_282 = _e869;
                                    let _e870 = local;
                                    let _e872 = local_11;
                                    let _e873 = (_e872 + (_e870 % 16u));
                                    local_59 = _e873;
                                    let _e874 = local;
                                    let _e876 = local_12;
                                    local_60 = (_e876 + (_e874 / 16u));
                                    let _e880 = global_4.member.member_5;
                                    local_61 = _e880;
                                    if (_e873 >= _e880) {
                                        phi_3326_ = _e434;
                                    } else {
                                        let _e884 = global_4.member.member_6;
                                        local_62 = _e884;
                                        let _e885 = local_60;
                                        if (_e885 >= _e884) {
                                            phi_3327_ = _e434;
                                        } else {
                                            let _e887 = local_59;
                                            let _e891 = local_61;
                                            local_63 = (((2f * (f32(_e887) + 0.5f)) / f32(_e891)) - 1f);
                                            let _e895 = local_60;
                                            let _e899 = local_62;
                                            local_64 = (((2f * (f32(_e895) + 0.5f)) / f32(_e899)) - 1f);
                                            let _e903 = local_282;
                                            if _e903.member_7 {
                                                let _e982 = local_282;
                                                let _e986 = local_63;
                                                let _e988 = local_282;
                                                let _e992 = local_64;
                                                let _e995 = local_282;
                                                let _e999 = (((_e982.member[0][0] * _e986) + (_e988.member[0][1] * _e992)) + _e995.member[0][2]);
                                                local_65 = _e999;
                                                let _e1000 = local_282;
                                                let _e1004 = local_63;
                                                let _e1006 = local_282;
                                                let _e1010 = local_64;
                                                let _e1013 = local_282;
                                                let _e1017 = (((_e1000.member[1][0] * _e1004) + (_e1006.member[1][1] * _e1010)) + _e1013.member[1][2]);
                                                local_66 = _e1017;
                                                let _e1018 = local_282;
                                                let _e1022 = local_63;
                                                let _e1024 = local_282;
                                                let _e1028 = local_64;
                                                let _e1031 = local_282;
                                                let _e1035 = (((_e1018.member[2][0] * _e1022) + (_e1024.member[2][1] * _e1028)) + _e1031.member[2][2]);
                                                local_67 = _e1035;
                                                let _e1036 = local_282;
                                                local_68 = _e1036.member_1;
                                                local_299 = select(-1f, 1f, (_e1036.member_1 > 0f));
                                                local_69 = ((_e999 + _e1017) + _e1035);
                                                if (_e1036.member_1 == 0f) {
                                                    phi_627_ = type_30();
                                                    phi_628_ = true;
                                                } else {
                                                    let _e1043 = local_65;
                                                    let _e1044 = local_299;
                                                    if ((_e1043 * _e1044) < 0f) {
                                                        phi_625_ = type_30();
                                                        phi_626_ = true;
                                                    } else {
                                                        let _e1047 = local_66;
                                                        let _e1048 = local_299;
                                                        if ((_e1047 * _e1048) < 0f) {
                                                            phi_623_ = type_30();
                                                            phi_624_ = true;
                                                        } else {
                                                            let _e1051 = local_67;
                                                            let _e1052 = local_299;
                                                            if ((_e1051 * _e1052) < 0f) {
                                                                phi_621_ = type_30();
                                                                phi_622_ = true;
                                                            } else {
                                                                let _e1055 = local_69;
                                                                let _e1056 = local_299;
                                                                let _e1058 = ((_e1055 * _e1056) <= 0f);
                                                                if _e1058 {
                                                                    phi_620_ = type_30();
                                                                } else {
                                                                    let _e1059 = local_65;
                                                                    let _e1060 = local_69;
                                                                    let _e1062 = local_66;
                                                                    let _e1063 = local_69;
                                                                    let _e1065 = local_68;
                                                                    let _e1066 = local_69;
                                                                    phi_620_ = type_30((_e1059 / _e1060), (_e1062 / _e1063), (_e1065 / _e1066));
                                                                }
                                                                let _e1070 = phi_620_;
                                                                phi_621_ = _e1070;
                                                                phi_622_ = _e1058;
                                                            }
                                                            let _e1072 = phi_621_;
                                                            let _e1074 = phi_622_;
                                                            phi_623_ = _e1072;
                                                            phi_624_ = _e1074;
                                                        }
                                                        let _e1076 = phi_623_;
                                                        let _e1078 = phi_624_;
                                                        phi_625_ = _e1076;
                                                        phi_626_ = _e1078;
                                                    }
                                                    let _e1080 = phi_625_;
                                                    let _e1082 = phi_626_;
                                                    phi_627_ = _e1080;
                                                    phi_628_ = _e1082;
                                                }
                                                let _e1084 = phi_627_;
                                                let _e1086 = phi_628_;
                                                if _e1086 {
                                                    phi_633_ = type_30(0f, 0f, 0f);
                                                } else {
                                                    phi_633_ = _e1084;
                                                }
                                                let _e1088 = phi_633_;
                                                phi_695_ = _e1088;
                                            } else {
                                                let _e905 = local_282;
                                                local_70 = _e905.member_5;
                                                if (_e905.member_5 == 0f) {
                                                    phi_694_ = type_30(0f, 0f, 0f);
                                                } else {
                                                    let _e908 = local_282;
                                                    let _e911 = local_63;
                                                    let _e912 = (_e911 - _e908.member_2[0]);
                                                    let _e913 = local_282;
                                                    let _e916 = local_64;
                                                    let _e917 = (_e916 - _e913.member_2[1]);
                                                    let _e918 = local_282;
                                                    let _e922 = local_282;
                                                    let _e927 = local_70;
                                                    let _e928 = (((_e912 * _e918.member_4[1]) - (_e917 * _e922.member_4[0])) / _e927);
                                                    local_71 = _e928;
                                                    let _e929 = local_282;
                                                    let _e933 = local_282;
                                                    let _e938 = local_70;
                                                    let _e939 = (((_e929.member_3[0] * _e917) - (_e933.member_3[1] * _e912)) / _e938);
                                                    local_72 = _e939;
                                                    let _e941 = ((1f - _e928) - _e939);
                                                    local_73 = _e941;
                                                    if (_e941 < 0f) {
                                                        phi_687_ = type_30();
                                                        phi_688_ = true;
                                                    } else {
                                                        let _e943 = local_71;
                                                        if (_e943 < 0f) {
                                                            phi_685_ = type_30();
                                                            phi_686_ = true;
                                                        } else {
                                                            let _e945 = local_72;
                                                            let _e946 = (_e945 < 0f);
                                                            if _e946 {
                                                                phi_684_ = type_30();
                                                            } else {
                                                                let _e947 = local_282;
                                                                let _e950 = local_73;
                                                                let _e951 = (_e950 * _e947.member_6[0]);
                                                                let _e952 = local_282;
                                                                let _e955 = local_71;
                                                                let _e956 = (_e955 * _e952.member_6[1]);
                                                                let _e957 = local_282;
                                                                let _e960 = local_72;
                                                                let _e963 = ((_e951 + _e956) + (_e960 * _e957.member_6[2]));
                                                                phi_684_ = type_30((_e951 / _e963), (_e956 / _e963), (1f / _e963));
                                                            }
                                                            let _e969 = phi_684_;
                                                            phi_685_ = _e969;
                                                            phi_686_ = _e946;
                                                        }
                                                        let _e971 = phi_685_;
                                                        let _e973 = phi_686_;
                                                        phi_687_ = _e971;
                                                        phi_688_ = _e973;
                                                    }
                                                    let _e975 = phi_687_;
                                                    let _e977 = phi_688_;
                                                    if _e977 {
                                                        phi_693_ = type_30(0f, 0f, 0f);
                                                    } else {
                                                        phi_693_ = _e975;
                                                    }
                                                    let _e979 = phi_693_;
                                                    phi_694_ = _e979;
                                                }
                                                let _e981 = phi_694_;
                                                phi_695_ = _e981;
                                            }
                                            let _e1090 = phi_695_;
                                            local_74 = _e1090.member;
                                            local_75 = _e1090.member_1;
                                            local_76 = _e1090.member_2;
                                            if (_e1090.member_2 <= 0f) {
                                                phi_3328_ = _e434;
                                            } else {
                                                let _e1095 = local_60;
                                                let _e1096 = local_61;
                                                let _e1098 = local_59;
                                                let _e1099 = ((_e1095 * _e1096) + _e1098);
                                                local_77 = _e1099;
                                                let _e1100 = (_e1099 * 4u);
                                                local_78 = _e1100;
                                                let _e1101 = local_8;
                                                let _e1102 = (_e1100 < _e1101);
                                                local_79 = _e1102;
                                                if _e1102 {
                                                } else {
                                                    phi_3320_ = true;
                                                    break;
                                                }
                                                let _e1103 = local_78;
                                                let _e1106 = global_11.member[_e1103];
                                                if (_e1106 == 0u) {
                                                    phi_732_ = true;
                                                } else {
                                                    let _e1108 = local_78;
                                                    let _e1109 = (_e1108 + 1u);
                                                    local_80 = _e1109;
                                                    let _e1110 = local_8;
                                                    if (_e1109 < _e1110) {
                                                    } else {
                                                        phi_3320_ = true;
                                                        break;
                                                    }
                                                    let _e1112 = local_80;
                                                    let _e1115 = global_11.member[_e1112];
                                                    let _e1117 = local_76;
                                                    phi_732_ = (_e1117 < bitcast<f32>(_e1115));
                                                }
                                                let _e1120 = phi_732_;
                                                if _e1120 {
                                                    let _e1121 = local_76;
                                                    let _e1122 = local_58;
                                                    if (_e1121 >= _e1122) {
                                                        let _e1126 = global_4.member.member_9;
                                                        if (_e1126 == 0u) {
                                                            phi_760_ = true;
                                                        } else {
                                                            let _e1128 = local_77;
                                                            let _e1129 = local_6;
                                                            if (_e1128 < _e1129) {
                                                            } else {
                                                                phi_3320_ = true;
                                                                break;
                                                            }
                                                            let _e1131 = local_77;
                                                            let _e1134 = global_9.member[_e1131];
                                                            let _e1136 = local_76;
                                                            phi_760_ = (_e1136 > bitcast<f32>(_e1134));
                                                        }
                                                        let _e1139 = phi_760_;
                                                        local_81 = _e1139;
                                                        if _e1139 {
                                                            let _e1140 = local_20;
                                                            if _e1140 {
                                                            } else {
                                                                phi_3320_ = true;
                                                                break;
                                                            }
                                                            let _e1141 = local_23;
                                                            if _e1141 {
                                                            } else {
                                                                phi_3320_ = true;
                                                                break;
                                                            }
                                                            let _e1142 = local_26;
                                                            if _e1142 {
                                                            } else {
                                                                phi_3320_ = true;
                                                                break;
                                                            }
                                                            let _e1143 = local_29;
                                                            if _e1143 {
                                                            } else {
                                                                phi_3320_ = true;
                                                                break;
                                                            }
                                                            let _e1144 = local_30;
                                                            let _e1145 = (_e1144 * 16u);
                                                            local_82 = _e1145;
                                                            let _e1146 = (_e1145 + 10u);
                                                            local_83 = _e1146;
                                                            let _e1147 = local_3;
                                                            if (_e1146 < _e1147) {
                                                            } else {
                                                                phi_3320_ = true;
                                                                break;
                                                            }
                                                            let _e1149 = local_83;
                                                            let _e1152 = global_5.member[_e1149];
                                                            local_84 = _e1152;
                                                            if ((_e1152 & 12u) == 0u) {
                                                                phi_3334_ = _e434;
                                                                phi_2518_ = true;
                                                            } else {
                                                                let _e1155 = local_21;
                                                                let _e1156 = local_24;
                                                                let _e1157 = local_27;
                                                                let _e1158 = local_30;
                                                                let _e1159 = array<u32, 4>(_e1155, _e1156, _e1157, _e1158);
                                                                local_85 = _e1159;
                                                                local_327 = _e1159;
                                                                let _e1160 = local_74;
                                                                let _e1162 = local_75;
                                                                let _e1163 = ((1f - _e1160) - _e1162);
                                                                local_86 = _e1163;
                                                                let _e1165 = local_74;
                                                                local_328[0u] = _e1165;
                                                                let _e1167 = local_75;
                                                                local_328[1u] = _e1167;
                                                                local_328[2u] = _e1163;
                                                                phi_822_ = 0u;
                                                                phi_825_ = array<f32, 4>(0f, 0f, 0f, 0f);
                                                                loop {
                                                                    let _e1170 = phi_822_;
                                                                    let _e1172 = phi_825_;
                                                                    local_87 = _e1170;
                                                                    local_88 = _e1172;
                                                                    let _e1173 = local_87;
                                                                    let _e1174 = (_e1173 < 3u);
                                                                    local_89 = _e1174;
                                                                    if _e1174 {
                                                                        let _e1175 = local_87;
                                                                        if (_e1175 < 4u) {
                                                                        } else {
                                                                            phi_3169_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1177 = local_87;
                                                                        let _e1179 = local_327[_e1177];
                                                                        let _e1180 = (_e1179 * 10u);
                                                                        local_90 = _e1180;
                                                                        let _e1181 = (_e1180 + 8u);
                                                                        local_91 = _e1181;
                                                                        let _e1182 = local_1;
                                                                        if (_e1181 < _e1182) {
                                                                        } else {
                                                                            phi_3169_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1184 = local_91;
                                                                        let _e1187 = global_2.member[_e1184];
                                                                        local_92 = _e1187;
                                                                        let _e1188 = local_90;
                                                                        let _e1189 = (_e1188 + 9u);
                                                                        local_93 = _e1189;
                                                                        let _e1190 = local_1;
                                                                        if (_e1189 < _e1190) {
                                                                        } else {
                                                                            phi_3169_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1192 = local_93;
                                                                        let _e1195 = global_2.member[_e1192];
                                                                        local_94 = _e1195;
                                                                        let _e1196 = local_89;
                                                                        if _e1196 {
                                                                        } else {
                                                                            phi_3169_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1197 = local_87;
                                                                        let _e1199 = local_328[_e1197];
                                                                        local_95 = _e1199;
                                                                        let _e1200 = local_92;
                                                                        let _e1201 = (_e1200 & 65535u);
                                                                        local_300 = select(-1f, 1f, ((_e1201 & 32768u) == 0u));
                                                                        let _e1207 = ((_e1201 >> bitcast<u32>(10i)) & 31u);
                                                                        local_96 = _e1207;
                                                                        local_97 = (_e1201 & 1023u);
                                                                        if (_e1207 == 0u) {
                                                                            let _e1229 = local_97;
                                                                            let _e1231 = local_300;
                                                                            phi_895_ = ((_e1231 * f32(_e1229)) * 0.000000059604645f);
                                                                        } else {
                                                                            let _e1210 = local_96;
                                                                            if (_e1210 == 31u) {
                                                                                let _e1220 = local_97;
                                                                                phi_892_ = (2139095040u | (_e1220 << bitcast<u32>(13i)));
                                                                            } else {
                                                                                let _e1212 = local_96;
                                                                                let _e1216 = local_97;
                                                                                phi_892_ = (((_e1212 + 112u) << bitcast<u32>(23i)) | (_e1216 << bitcast<u32>(13i)));
                                                                            }
                                                                            let _e1225 = phi_892_;
                                                                            let _e1227 = local_300;
                                                                            phi_895_ = (_e1227 * bitcast<f32>(_e1225));
                                                                        }
                                                                        let _e1235 = phi_895_;
                                                                        let _e1236 = local_95;
                                                                        let _e1238 = local_88;
                                                                        local_98 = (_e1238[0] + (_e1236 * _e1235));
                                                                        let _e1241 = local_89;
                                                                        if _e1241 {
                                                                        } else {
                                                                            phi_3169_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1242 = local_328[_e1197];
                                                                        local_99 = _e1242;
                                                                        let _e1243 = local_92;
                                                                        let _e1245 = (_e1243 >> bitcast<u32>(16i));
                                                                        local_301 = select(-1f, 1f, ((_e1245 & 32768u) == 0u));
                                                                        let _e1251 = ((_e1245 >> bitcast<u32>(10i)) & 31u);
                                                                        local_100 = _e1251;
                                                                        local_101 = (_e1245 & 1023u);
                                                                        if (_e1251 == 0u) {
                                                                            let _e1273 = local_101;
                                                                            let _e1275 = local_301;
                                                                            phi_938_ = ((_e1275 * f32(_e1273)) * 0.000000059604645f);
                                                                        } else {
                                                                            let _e1254 = local_100;
                                                                            if (_e1254 == 31u) {
                                                                                let _e1264 = local_101;
                                                                                phi_935_ = (2139095040u | (_e1264 << bitcast<u32>(13i)));
                                                                            } else {
                                                                                let _e1256 = local_100;
                                                                                let _e1260 = local_101;
                                                                                phi_935_ = (((_e1256 + 112u) << bitcast<u32>(23i)) | (_e1260 << bitcast<u32>(13i)));
                                                                            }
                                                                            let _e1269 = phi_935_;
                                                                            let _e1271 = local_301;
                                                                            phi_938_ = (_e1271 * bitcast<f32>(_e1269));
                                                                        }
                                                                        let _e1279 = phi_938_;
                                                                        let _e1280 = local_99;
                                                                        let _e1282 = local_88;
                                                                        local_102 = (_e1282[1] + (_e1280 * _e1279));
                                                                        let _e1285 = local_89;
                                                                        if _e1285 {
                                                                        } else {
                                                                            phi_3169_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1286 = local_328[_e1197];
                                                                        local_103 = _e1286;
                                                                        let _e1287 = local_94;
                                                                        let _e1288 = (_e1287 & 65535u);
                                                                        local_302 = select(-1f, 1f, ((_e1288 & 32768u) == 0u));
                                                                        let _e1294 = ((_e1288 >> bitcast<u32>(10i)) & 31u);
                                                                        local_104 = _e1294;
                                                                        local_105 = (_e1288 & 1023u);
                                                                        if (_e1294 == 0u) {
                                                                            let _e1316 = local_105;
                                                                            let _e1318 = local_302;
                                                                            phi_981_ = ((_e1318 * f32(_e1316)) * 0.000000059604645f);
                                                                        } else {
                                                                            let _e1297 = local_104;
                                                                            if (_e1297 == 31u) {
                                                                                let _e1307 = local_105;
                                                                                phi_978_ = (2139095040u | (_e1307 << bitcast<u32>(13i)));
                                                                            } else {
                                                                                let _e1299 = local_104;
                                                                                let _e1303 = local_105;
                                                                                phi_978_ = (((_e1299 + 112u) << bitcast<u32>(23i)) | (_e1303 << bitcast<u32>(13i)));
                                                                            }
                                                                            let _e1312 = phi_978_;
                                                                            let _e1314 = local_302;
                                                                            phi_981_ = (_e1314 * bitcast<f32>(_e1312));
                                                                        }
                                                                        let _e1322 = phi_981_;
                                                                        let _e1323 = local_103;
                                                                        let _e1325 = local_88;
                                                                        local_106 = (_e1325[2] + (_e1323 * _e1322));
                                                                        let _e1328 = local_89;
                                                                        if _e1328 {
                                                                        } else {
                                                                            phi_3169_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1329 = local_328[_e1197];
                                                                        local_107 = _e1329;
                                                                        let _e1330 = local_94;
                                                                        let _e1332 = (_e1330 >> bitcast<u32>(16i));
                                                                        local_303 = select(-1f, 1f, ((_e1332 & 32768u) == 0u));
                                                                        let _e1338 = ((_e1332 >> bitcast<u32>(10i)) & 31u);
                                                                        local_108 = _e1338;
                                                                        local_109 = (_e1332 & 1023u);
                                                                        if (_e1338 == 0u) {
                                                                            let _e1360 = local_109;
                                                                            let _e1362 = local_303;
                                                                            phi_1024_ = ((_e1362 * f32(_e1360)) * 0.000000059604645f);
                                                                        } else {
                                                                            let _e1341 = local_108;
                                                                            if (_e1341 == 31u) {
                                                                                let _e1351 = local_109;
                                                                                phi_1021_ = (2139095040u | (_e1351 << bitcast<u32>(13i)));
                                                                            } else {
                                                                                let _e1343 = local_108;
                                                                                let _e1347 = local_109;
                                                                                phi_1021_ = (((_e1343 + 112u) << bitcast<u32>(23i)) | (_e1347 << bitcast<u32>(13i)));
                                                                            }
                                                                            let _e1356 = phi_1021_;
                                                                            let _e1358 = local_303;
                                                                            phi_1024_ = (_e1358 * bitcast<f32>(_e1356));
                                                                        }
                                                                        let _e1366 = phi_1024_;
                                                                        let _e1367 = local_107;
                                                                        let _e1369 = local_88;
                                                                        let _e1372 = local_98;
                                                                        let _e1373 = local_102;
                                                                        let _e1374 = local_106;
                                                                        let _e1376 = local_87;
                                                                        phi_823_ = (_e1376 + 1u);
                                                                        phi_826_ = array<f32, 4>(_e1372, _e1373, _e1374, (_e1369[3] + (_e1367 * _e1366)));
                                                                    } else {
                                                                        phi_823_ = u32();
                                                                        phi_826_ = array<f32, 4>();
                                                                    }
                                                                    let _e1379 = phi_823_;
                                                                    let _e1381 = phi_826_;
                                                                    continue;
                                                                    continuing {
                                                                        let _e1382 = local_89;
                                                                        phi_822_ = _e1379;
                                                                        phi_825_ = _e1381;
                                                                        phi_3169_ = _e434;
                                                                        break if !(_e1382);
                                                                    }
                                                                }
                                                                let _e1385 = phi_3169_;
                                                                phi_3320_ = _e1385;
                                                                if _e1385 {
                                                                    break;
                                                                }
                                                                let _e1386 = local_88;
                                                                local_110 = _e1386[3];
                                                                let _e1388 = local_85;
                                                                local_325 = _e1388;
                                                                let _e1390 = local_74;
                                                                local_326[0u] = _e1390;
                                                                let _e1392 = local_75;
                                                                local_326[1u] = _e1392;
                                                                let _e1394 = local_86;
                                                                local_326[2u] = _e1394;
                                                                phi_1042_ = 0u;
                                                                phi_1045_ = 0f;
                                                                phi_1047_ = 0f;
                                                                loop {
                                                                    let _e1396 = phi_1042_;
                                                                    let _e1398 = phi_1045_;
                                                                    let _e1400 = phi_1047_;
                                                                    local_111 = _e1396;
                                                                    local_112 = _e1398;
                                                                    local_113 = _e1400;
                                                                    let _e1401 = local_111;
                                                                    let _e1402 = (_e1401 < 3u);
                                                                    local_114 = _e1402;
                                                                    if _e1402 {
                                                                        let _e1403 = local_111;
                                                                        if (_e1403 < 4u) {
                                                                        } else {
                                                                            phi_3207_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1405 = local_111;
                                                                        let _e1407 = local_325[_e1405];
                                                                        local_115 = (_e1407 * 10u);
                                                                        let _e1409 = local_114;
                                                                        if _e1409 {
                                                                        } else {
                                                                            phi_3207_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1410 = local_111;
                                                                        let _e1412 = local_326[_e1410];
                                                                        local_116 = _e1412;
                                                                        let _e1413 = local_115;
                                                                        let _e1414 = (_e1413 + 3u);
                                                                        local_117 = _e1414;
                                                                        let _e1415 = local_1;
                                                                        if (_e1414 < _e1415) {
                                                                        } else {
                                                                            phi_3207_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1417 = local_117;
                                                                        let _e1420 = global_2.member[_e1417];
                                                                        let _e1422 = local_116;
                                                                        let _e1424 = local_113;
                                                                        let _e1426 = local_114;
                                                                        if _e1426 {
                                                                        } else {
                                                                            phi_3207_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1427 = local_326[_e1410];
                                                                        local_118 = _e1427;
                                                                        let _e1428 = local_115;
                                                                        let _e1429 = (_e1428 + 7u);
                                                                        local_119 = _e1429;
                                                                        let _e1430 = local_1;
                                                                        if (_e1429 < _e1430) {
                                                                        } else {
                                                                            phi_3207_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1432 = local_119;
                                                                        let _e1435 = global_2.member[_e1432];
                                                                        let _e1437 = local_118;
                                                                        let _e1439 = local_112;
                                                                        let _e1441 = local_111;
                                                                        phi_1043_ = (_e1441 + 1u);
                                                                        phi_1046_ = (_e1439 + (_e1437 * bitcast<f32>(_e1435)));
                                                                        phi_1048_ = (_e1424 + (_e1422 * bitcast<f32>(_e1420)));
                                                                    } else {
                                                                        phi_1043_ = u32();
                                                                        phi_1046_ = f32();
                                                                        phi_1048_ = f32();
                                                                    }
                                                                    let _e1444 = phi_1043_;
                                                                    let _e1446 = phi_1046_;
                                                                    let _e1448 = phi_1048_;
                                                                    continue;
                                                                    continuing {
                                                                        let _e1449 = local_114;
                                                                        phi_1042_ = _e1444;
                                                                        phi_1045_ = _e1446;
                                                                        phi_1047_ = _e1448;
                                                                        phi_3207_ = _e1385;
                                                                        break if !(_e1449);
                                                                    }
                                                                }
                                                                let _e1452 = phi_3207_;
                                                                phi_3320_ = _e1452;
                                                                if _e1452 {
                                                                    break;
                                                                }
                                                                let _e1453 = local_82;
                                                                let _e1454 = (_e1453 + 8u);
                                                                local_120 = _e1454;
                                                                let _e1455 = local_3;
                                                                if (_e1454 < _e1455) {
                                                                } else {
                                                                    phi_3320_ = true;
                                                                    break;
                                                                }
                                                                let _e1457 = local_120;
                                                                let _e1460 = global_5.member[_e1457];
                                                                local_121 = _e1460;
                                                                let _e1461 = local_82;
                                                                let _e1462 = (_e1461 + 3u);
                                                                local_122 = _e1462;
                                                                let _e1463 = local_3;
                                                                if (_e1462 < _e1463) {
                                                                } else {
                                                                    phi_3320_ = true;
                                                                    break;
                                                                }
                                                                let _e1465 = local_122;
                                                                let _e1468 = global_5.member[_e1465];
                                                                local_123 = bitcast<f32>(_e1468);
                                                                let _e1472 = global_4.member.member_8;
                                                                local_124 = _e1472;
                                                                let _e1473 = local_121;
                                                                if (_e1473 == 4294967295u) {
                                                                    phi_3337_ = _e1452;
                                                                    phi_2491_ = type_5();
                                                                    phi_2492_ = true;
                                                                } else {
                                                                    let _e1475 = local_121;
                                                                    let _e1476 = local_124;
                                                                    let _e1477 = (_e1475 >= _e1476);
                                                                    if _e1477 {
                                                                        phi_3338_ = _e1452;
                                                                        phi_2490_ = type_5();
                                                                    } else {
                                                                        let _e1478 = local_121;
                                                                        let _e1479 = (_e1478 * 4u);
                                                                        local_125 = _e1479;
                                                                        let _e1480 = local_4;
                                                                        if (_e1479 < _e1480) {
                                                                        } else {
                                                                            phi_3320_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1482 = local_125;
                                                                        let _e1485 = global_7.member[_e1482];
                                                                        local_126 = _e1485;
                                                                        let _e1486 = local_125;
                                                                        let _e1487 = (_e1486 + 1u);
                                                                        local_127 = _e1487;
                                                                        let _e1488 = local_4;
                                                                        if (_e1487 < _e1488) {
                                                                        } else {
                                                                            phi_3320_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1490 = local_127;
                                                                        let _e1493 = global_7.member[_e1490];
                                                                        local_128 = _e1493;
                                                                        let _e1494 = local_125;
                                                                        let _e1495 = (_e1494 + 2u);
                                                                        local_129 = _e1495;
                                                                        let _e1496 = local_4;
                                                                        if (_e1495 < _e1496) {
                                                                        } else {
                                                                            phi_3320_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1498 = local_129;
                                                                        let _e1501 = global_7.member[_e1498];
                                                                        local_130 = _e1501;
                                                                        let _e1502 = local_125;
                                                                        let _e1503 = (_e1502 + 3u);
                                                                        local_131 = _e1503;
                                                                        let _e1504 = local_4;
                                                                        if (_e1503 < _e1504) {
                                                                        } else {
                                                                            phi_3320_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1506 = local_131;
                                                                        let _e1509 = global_7.member[_e1506];
                                                                        local_132 = _e1509;
                                                                        let _e1510 = local_128;
                                                                        if (_e1510 == 0u) {
                                                                            phi_3340_ = _e1452;
                                                                            phi_2484_ = type_5();
                                                                            phi_2485_ = true;
                                                                        } else {
                                                                            let _e1512 = local_130;
                                                                            let _e1513 = (_e1512 == 0u);
                                                                            if _e1513 {
                                                                                phi_3341_ = _e1452;
                                                                                phi_2483_ = type_5();
                                                                            } else {
                                                                                let _e1514 = local_132;
                                                                                let _e1517 = ((_e1514 >> bitcast<u32>(8u)) & 31u);
                                                                                local_304 = select(_e1517, 1u, (_e1517 == 0u));
                                                                                let _e1520 = local_132;
                                                                                let _e1524 = local_132;
                                                                                let _e1528 = local_126;
                                                                                let _e1529 = local_128;
                                                                                let _e1530 = local_130;
                                                                                let _e1531 = type_22(_e1528, _e1529, _e1530, ((_e1520 >> bitcast<u32>(1u)) & 3u), ((_e1524 >> bitcast<u32>(3u)) & 3u));
                                                                                let _e1532 = local_128;
                                                                                let _e1534 = local_113;
                                                                                if ((bitcast<u32>((_e1534 * f32(_e1532))) & 2139095040u) != 2139095040u) {
                                                                                    let _e1539 = local_130;
                                                                                    let _e1541 = local_112;
                                                                                    phi_1197_ = select(true, false, ((bitcast<u32>((_e1541 * f32(_e1539))) & 2139095040u) != 2139095040u));
                                                                                } else {
                                                                                    phi_1197_ = true;
                                                                                }
                                                                                let _e1548 = phi_1197_;
                                                                                let _e1549 = local_112;
                                                                                local_305 = select(_e1549, 0f, _e1548);
                                                                                let _e1551 = local_113;
                                                                                local_306 = select(_e1551, 0f, _e1548);
                                                                                if false {
                                                                                }
                                                                                let _e1553 = local_304;
                                                                                let _e1554 = (_e1553 - 1u);
                                                                                local_133 = _e1554;
                                                                                let _e1555 = floor(0f);
                                                                                let _e1561 = select(select(u32(_e1555), 0u, !((_e1555 >= 0f))), 4294967295u, (_e1555 > 4294967000f));
                                                                                local_134 = _e1561;
                                                                                let _e1562 = (_e1561 >= _e1554);
                                                                                local_135 = _e1562;
                                                                                if _e1562 {
                                                                                    phi_1383_ = 0f;
                                                                                } else {
                                                                                    let _e1563 = local_134;
                                                                                    phi_1383_ = -(f32(_e1563));
                                                                                }
                                                                                let _e1567 = phi_1383_;
                                                                                local_136 = _e1567;
                                                                                let _e1568 = local_135;
                                                                                let _e1569 = local_133;
                                                                                let _e1570 = local_134;
                                                                                local_307 = select(_e1570, _e1569, _e1568);
                                                                                local_308 = select(1u, 2u, (_e1567 > 0f));
                                                                                phi_3041_ = 0u;
                                                                                phi_3042_ = _e1531;
                                                                                loop {
                                                                                    let _e1575 = phi_3041_;
                                                                                    let _e1577 = phi_3042_;
                                                                                    local_283 = _e1575;
                                                                                    local_284 = _e1577;
                                                                                    local_329 = _e1577;
                                                                                    let _e1578 = local_283;
                                                                                    let _e1579 = local_307;
                                                                                    let _e1580 = (_e1578 < _e1579);
                                                                                    local_285 = _e1580;
                                                                                    if _e1580 {
                                                                                        let _e1581 = local_284;
                                                                                        local_286 = _e1581.member_1;
                                                                                        let _e1583 = local_284;
                                                                                        local_287 = _e1583.member_2;
                                                                                        let _e1586 = local_284;
                                                                                        let _e1589 = local_284;
                                                                                        local_288 = type_22((_e1586.member + (_e1581.member_1 * _e1583.member_2)), _e1589.member_1, _e1589.member_2, _e1589.member_3, _e1589.member_4);
                                                                                        if (_e1581.member_1 > 1u) {
                                                                                            let _e1597 = local_286;
                                                                                            phi_3059_ = (_e1597 >> bitcast<u32>(1i));
                                                                                        } else {
                                                                                            phi_3059_ = 1u;
                                                                                        }
                                                                                        let _e1601 = phi_3059_;
                                                                                        let _e1602 = local_288;
                                                                                        local_289 = type_22(_e1602.member, _e1601, _e1602.member_2, _e1602.member_3, _e1602.member_4);
                                                                                        let _e1609 = local_287;
                                                                                        if (_e1609 > 1u) {
                                                                                            let _e1611 = local_287;
                                                                                            phi_3068_ = (_e1611 >> bitcast<u32>(1i));
                                                                                        } else {
                                                                                            phi_3068_ = 1u;
                                                                                        }
                                                                                        let _e1615 = phi_3068_;
                                                                                        let _e1616 = local_289;
                                                                                        let _e1623 = local_283;
                                                                                        phi_3073_ = (_e1623 + 1u);
                                                                                        phi_3074_ = type_22(_e1616.member, _e1616.member_1, _e1615, _e1616.member_3, _e1616.member_4);
                                                                                    } else {
                                                                                        phi_3073_ = u32();
                                                                                        phi_3074_ = type_22();
                                                                                    }
                                                                                    let _e1626 = phi_3073_;
                                                                                    let _e1628 = phi_3074_;
                                                                                    continue;
                                                                                    continuing {
                                                                                        let _e1629 = local_285;
                                                                                        phi_3041_ = _e1626;
                                                                                        phi_3042_ = _e1628;
                                                                                        break if !(_e1629);
                                                                                    }
                                                                                }
                                                                                let _e1631 = local_307;
                                                                                let _e1632 = local_308;
                                                                                local_137 = ((_e1631 + _e1632) - 1u);
                                                                                phi_3080_ = 0u;
                                                                                phi_3081_ = _e1531;
                                                                                loop {
                                                                                    let _e1636 = phi_3080_;
                                                                                    let _e1638 = phi_3081_;
                                                                                    local_290 = _e1636;
                                                                                    local_291 = _e1638;
                                                                                    local_330 = _e1638;
                                                                                    let _e1639 = local_290;
                                                                                    let _e1640 = local_137;
                                                                                    let _e1641 = (_e1639 < _e1640);
                                                                                    local_292 = _e1641;
                                                                                    if _e1641 {
                                                                                        let _e1642 = local_291;
                                                                                        local_293 = _e1642.member_1;
                                                                                        let _e1644 = local_291;
                                                                                        local_294 = _e1644.member_2;
                                                                                        let _e1647 = local_291;
                                                                                        let _e1650 = local_291;
                                                                                        local_295 = type_22((_e1647.member + (_e1642.member_1 * _e1644.member_2)), _e1650.member_1, _e1650.member_2, _e1650.member_3, _e1650.member_4);
                                                                                        if (_e1642.member_1 > 1u) {
                                                                                            let _e1658 = local_293;
                                                                                            phi_3098_ = (_e1658 >> bitcast<u32>(1i));
                                                                                        } else {
                                                                                            phi_3098_ = 1u;
                                                                                        }
                                                                                        let _e1662 = phi_3098_;
                                                                                        let _e1663 = local_295;
                                                                                        local_296 = type_22(_e1663.member, _e1662, _e1663.member_2, _e1663.member_3, _e1663.member_4);
                                                                                        let _e1670 = local_294;
                                                                                        if (_e1670 > 1u) {
                                                                                            let _e1672 = local_294;
                                                                                            phi_3107_ = (_e1672 >> bitcast<u32>(1i));
                                                                                        } else {
                                                                                            phi_3107_ = 1u;
                                                                                        }
                                                                                        let _e1676 = phi_3107_;
                                                                                        let _e1677 = local_296;
                                                                                        let _e1684 = local_290;
                                                                                        phi_3112_ = (_e1684 + 1u);
                                                                                        phi_3113_ = type_22(_e1677.member, _e1677.member_1, _e1676, _e1677.member_3, _e1677.member_4);
                                                                                    } else {
                                                                                        phi_3112_ = u32();
                                                                                        phi_3113_ = type_22();
                                                                                    }
                                                                                    let _e1687 = phi_3112_;
                                                                                    let _e1689 = phi_3113_;
                                                                                    continue;
                                                                                    continuing {
                                                                                        let _e1690 = local_292;
                                                                                        phi_3080_ = _e1687;
                                                                                        phi_3081_ = _e1689;
                                                                                        break if !(_e1690);
                                                                                    }
                                                                                }
                                                                                let _e1692 = local_132;
                                                                                local_138 = ((_e1692 & 1u) != 0u);
                                                                                phi_3257_ = _e1452;
                                                                                phi_1402_ = 0u;
                                                                                phi_1405_ = type_5(0f, 0f, 0f, 0f);
                                                                                loop {
                                                                                    let _e1696 = phi_3257_;
                                                                                    let _e1698 = phi_1402_;
                                                                                    let _e1700 = phi_1405_;
                                                                                    local_139 = _e1698;
                                                                                    local_140 = _e1700;
                                                                                    local_333 = _e1700;
                                                                                    let _e1701 = local_139;
                                                                                    let _e1702 = (_e1701 < 1u);
                                                                                    local_141 = _e1702;
                                                                                    if _e1702 {
                                                                                        phi_3256_ = _e1696;
                                                                                        phi_1419_ = 0u;
                                                                                        phi_1422_ = _e1700;
                                                                                        loop {
                                                                                            let _e1704 = phi_3256_;
                                                                                            let _e1706 = phi_1419_;
                                                                                            let _e1708 = phi_1422_;
                                                                                            local_142 = _e1706;
                                                                                            local_332 = _e1708;
                                                                                            let _e1709 = local_142;
                                                                                            let _e1710 = (_e1709 < 1u);
                                                                                            local_143 = _e1710;
                                                                                            if _e1710 {
                                                                                                phi_1448_ = 0u;
                                                                                                phi_1451_ = _e1708;
                                                                                                loop {
                                                                                                    let _e1712 = phi_1448_;
                                                                                                    let _e1714 = phi_1451_;
                                                                                                    local_144 = _e1712;
                                                                                                    local_145 = _e1714;
                                                                                                    local_331 = _e1714;
                                                                                                    let _e1715 = local_144;
                                                                                                    let _e1716 = local_308;
                                                                                                    let _e1717 = (_e1715 < _e1716);
                                                                                                    local_146 = _e1717;
                                                                                                    if _e1717 {
                                                                                                        let _e1718 = local_144;
                                                                                                        if (_e1718 == 0u) {
                                                                                                            let _e1720 = local_136;
                                                                                                            let _e3068 = local_329;
                                                                                                            phi_1464_ = _e3068;
                                                                                                            phi_1465_ = (1f - _e1720);
                                                                                                        } else {
                                                                                                            let _e3070 = local_330;
                                                                                                            phi_1464_ = _e3070;
                                                                                                            phi_1465_ = _e1567;
                                                                                                        }
                                                                                                        let _e1723 = phi_1464_;
                                                                                                        let _e1725 = phi_1465_;
                                                                                                        local_147 = _e1723;
                                                                                                        local_148 = _e1725;
                                                                                                        let _e1726 = local_138;
                                                                                                        let _e1727 = select(0.5f, 0f, _e1726);
                                                                                                        local_149 = _e1723.member_1;
                                                                                                        let _e1730 = local_306;
                                                                                                        let _e1732 = ((_e1730 * f32(_e1723.member_1)) - _e1727);
                                                                                                        local_150 = _e1732;
                                                                                                        local_151 = _e1723.member_2;
                                                                                                        let _e1735 = local_305;
                                                                                                        let _e1737 = ((_e1735 * f32(_e1723.member_2)) - _e1727);
                                                                                                        local_152 = _e1737;
                                                                                                        local_153 = floor(_e1732);
                                                                                                        local_154 = floor(_e1737);
                                                                                                        let _e1740 = local_138;
                                                                                                        if _e1740 {
                                                                                                            phi_1485_ = 0f;
                                                                                                            phi_1486_ = 0f;
                                                                                                        } else {
                                                                                                            let _e1741 = local_150;
                                                                                                            let _e1742 = local_153;
                                                                                                            let _e1744 = local_152;
                                                                                                            let _e1745 = local_154;
                                                                                                            phi_1485_ = (_e1744 - _e1745);
                                                                                                            phi_1486_ = (_e1741 - _e1742);
                                                                                                        }
                                                                                                        let _e1748 = phi_1485_;
                                                                                                        let _e1750 = phi_1486_;
                                                                                                        local_155 = _e1748;
                                                                                                        local_156 = _e1750;
                                                                                                        let _e1751 = local_153;
                                                                                                        let _e1753 = local_153;
                                                                                                        let _e1756 = local_153;
                                                                                                        let _e1760 = local_153;
                                                                                                        let _e1761 = local_153;
                                                                                                        let _e1763 = select(0i, select(select(i32(_e1751), i32(-2147483648), !((_e1753 >= -2147483600f))), 2147483647i, (_e1756 > 2147483500f)), (_e1760 == _e1761));
                                                                                                        local_157 = _e1763;
                                                                                                        let _e1764 = local_154;
                                                                                                        let _e1766 = local_154;
                                                                                                        let _e1769 = local_154;
                                                                                                        let _e1773 = local_154;
                                                                                                        let _e1774 = local_154;
                                                                                                        let _e1776 = select(0i, select(select(i32(_e1764), i32(-2147483648), !((_e1766 >= -2147483600f))), 2147483647i, (_e1769 > 2147483500f)), (_e1773 == _e1774));
                                                                                                        local_158 = _e1776;
                                                                                                        let _e1777 = local_147;
                                                                                                        local_159 = _e1777.member_3;
                                                                                                        let _e1779 = local_149;
                                                                                                        local_160 = bitcast<i32>(_e1779);
                                                                                                        let _e1781 = (_e1777.member_3 == 1u);
                                                                                                        local_161 = _e1781;
                                                                                                        if _e1781 {
                                                                                                            let _e1835 = local_157;
                                                                                                            if (_e1835 < 0i) {
                                                                                                                phi_1522_ = 0i;
                                                                                                            } else {
                                                                                                                let _e1837 = local_157;
                                                                                                                let _e1838 = local_160;
                                                                                                                if (_e1837 >= _e1838) {
                                                                                                                    let _e1840 = local_160;
                                                                                                                    phi_1521_ = (_e1840 - 1i);
                                                                                                                } else {
                                                                                                                    phi_1521_ = _e1763;
                                                                                                                }
                                                                                                                let _e1843 = phi_1521_;
                                                                                                                phi_1522_ = _e1843;
                                                                                                            }
                                                                                                            let _e1845 = phi_1522_;
                                                                                                            phi_1582_ = _e1845;
                                                                                                        } else {
                                                                                                            let _e1782 = local_159;
                                                                                                            if (_e1782 == 2u) {
                                                                                                                let _e1804 = local_160;
                                                                                                                let _e1805 = (2i * _e1804);
                                                                                                                local_162 = _e1805;
                                                                                                                let _e1806 = (_e1805 == 0i);
                                                                                                                local_163 = _e1806;
                                                                                                                if _e1806 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1807 = local_162;
                                                                                                                let _e1808 = (_e1807 == -1i);
                                                                                                                local_164 = _e1808;
                                                                                                                let _e1809 = local_157;
                                                                                                                if (_e1808 && (_e1809 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1812 = local_157;
                                                                                                                let _e1813 = local_162;
                                                                                                                let _e1815 = local_162;
                                                                                                                local_165 = ((_e1812 % _e1813) + _e1815);
                                                                                                                let _e1817 = local_163;
                                                                                                                if _e1817 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1818 = local_165;
                                                                                                                let _e1820 = local_164;
                                                                                                                if (_e1820 && (_e1818 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1822 = local_165;
                                                                                                                let _e1823 = local_162;
                                                                                                                let _e1824 = (_e1822 % _e1823);
                                                                                                                local_166 = _e1824;
                                                                                                                let _e1825 = local_160;
                                                                                                                if (_e1824 < _e1825) {
                                                                                                                    phi_1557_ = _e1824;
                                                                                                                } else {
                                                                                                                    let _e1827 = local_162;
                                                                                                                    let _e1829 = local_166;
                                                                                                                    phi_1557_ = ((_e1827 - 1i) - _e1829);
                                                                                                                }
                                                                                                                let _e1832 = phi_1557_;
                                                                                                                phi_1581_ = _e1832;
                                                                                                            } else {
                                                                                                                let _e1784 = local_160;
                                                                                                                let _e1785 = (_e1784 == 0i);
                                                                                                                local_167 = _e1785;
                                                                                                                if _e1785 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1786 = local_160;
                                                                                                                let _e1787 = (_e1786 == -1i);
                                                                                                                local_168 = _e1787;
                                                                                                                let _e1788 = local_157;
                                                                                                                if (_e1787 && (_e1788 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1791 = local_157;
                                                                                                                let _e1792 = local_160;
                                                                                                                let _e1794 = local_160;
                                                                                                                local_169 = ((_e1791 % _e1792) + _e1794);
                                                                                                                let _e1796 = local_167;
                                                                                                                if _e1796 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1797 = local_169;
                                                                                                                let _e1799 = local_168;
                                                                                                                if (_e1799 && (_e1797 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1801 = local_169;
                                                                                                                let _e1802 = local_160;
                                                                                                                phi_1581_ = (_e1801 % _e1802);
                                                                                                            }
                                                                                                            let _e1834 = phi_1581_;
                                                                                                            phi_1582_ = _e1834;
                                                                                                        }
                                                                                                        let _e1847 = phi_1582_;
                                                                                                        local_170 = bitcast<u32>(_e1847);
                                                                                                        let _e1849 = local_157;
                                                                                                        let _e1850 = (_e1849 + 1i);
                                                                                                        local_171 = _e1850;
                                                                                                        let _e1851 = local_161;
                                                                                                        if _e1851 {
                                                                                                            let _e1905 = local_171;
                                                                                                            if (_e1905 < 0i) {
                                                                                                                phi_1602_ = 0i;
                                                                                                            } else {
                                                                                                                let _e1907 = local_171;
                                                                                                                let _e1908 = local_160;
                                                                                                                if (_e1907 >= _e1908) {
                                                                                                                    let _e1910 = local_160;
                                                                                                                    phi_1601_ = (_e1910 - 1i);
                                                                                                                } else {
                                                                                                                    phi_1601_ = _e1850;
                                                                                                                }
                                                                                                                let _e1913 = phi_1601_;
                                                                                                                phi_1602_ = _e1913;
                                                                                                            }
                                                                                                            let _e1915 = phi_1602_;
                                                                                                            phi_1662_ = _e1915;
                                                                                                        } else {
                                                                                                            let _e1852 = local_159;
                                                                                                            if (_e1852 == 2u) {
                                                                                                                let _e1874 = local_160;
                                                                                                                let _e1875 = (2i * _e1874);
                                                                                                                local_172 = _e1875;
                                                                                                                let _e1876 = (_e1875 == 0i);
                                                                                                                local_173 = _e1876;
                                                                                                                if _e1876 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1877 = local_172;
                                                                                                                let _e1878 = (_e1877 == -1i);
                                                                                                                local_174 = _e1878;
                                                                                                                let _e1879 = local_171;
                                                                                                                if (_e1878 && (_e1879 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1882 = local_171;
                                                                                                                let _e1883 = local_172;
                                                                                                                let _e1885 = local_172;
                                                                                                                local_175 = ((_e1882 % _e1883) + _e1885);
                                                                                                                let _e1887 = local_173;
                                                                                                                if _e1887 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1888 = local_175;
                                                                                                                let _e1890 = local_174;
                                                                                                                if (_e1890 && (_e1888 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1892 = local_175;
                                                                                                                let _e1893 = local_172;
                                                                                                                let _e1894 = (_e1892 % _e1893);
                                                                                                                local_176 = _e1894;
                                                                                                                let _e1895 = local_160;
                                                                                                                if (_e1894 < _e1895) {
                                                                                                                    phi_1637_ = _e1894;
                                                                                                                } else {
                                                                                                                    let _e1897 = local_172;
                                                                                                                    let _e1899 = local_176;
                                                                                                                    phi_1637_ = ((_e1897 - 1i) - _e1899);
                                                                                                                }
                                                                                                                let _e1902 = phi_1637_;
                                                                                                                phi_1661_ = _e1902;
                                                                                                            } else {
                                                                                                                let _e1854 = local_160;
                                                                                                                let _e1855 = (_e1854 == 0i);
                                                                                                                local_177 = _e1855;
                                                                                                                if _e1855 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1856 = local_160;
                                                                                                                let _e1857 = (_e1856 == -1i);
                                                                                                                local_178 = _e1857;
                                                                                                                let _e1858 = local_171;
                                                                                                                if (_e1857 && (_e1858 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1861 = local_171;
                                                                                                                let _e1862 = local_160;
                                                                                                                let _e1864 = local_160;
                                                                                                                local_179 = ((_e1861 % _e1862) + _e1864);
                                                                                                                let _e1866 = local_177;
                                                                                                                if _e1866 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1867 = local_179;
                                                                                                                let _e1869 = local_178;
                                                                                                                if (_e1869 && (_e1867 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1871 = local_179;
                                                                                                                let _e1872 = local_160;
                                                                                                                phi_1661_ = (_e1871 % _e1872);
                                                                                                            }
                                                                                                            let _e1904 = phi_1661_;
                                                                                                            phi_1662_ = _e1904;
                                                                                                        }
                                                                                                        let _e1917 = phi_1662_;
                                                                                                        local_180 = bitcast<u32>(_e1917);
                                                                                                        let _e1919 = local_147;
                                                                                                        local_181 = _e1919.member_4;
                                                                                                        let _e1921 = local_151;
                                                                                                        local_182 = bitcast<i32>(_e1921);
                                                                                                        let _e1923 = (_e1919.member_4 == 1u);
                                                                                                        local_183 = _e1923;
                                                                                                        if _e1923 {
                                                                                                            let _e1977 = local_158;
                                                                                                            if (_e1977 < 0i) {
                                                                                                                phi_1681_ = 0i;
                                                                                                            } else {
                                                                                                                let _e1979 = local_158;
                                                                                                                let _e1980 = local_182;
                                                                                                                if (_e1979 >= _e1980) {
                                                                                                                    let _e1982 = local_182;
                                                                                                                    phi_1680_ = (_e1982 - 1i);
                                                                                                                } else {
                                                                                                                    phi_1680_ = _e1776;
                                                                                                                }
                                                                                                                let _e1985 = phi_1680_;
                                                                                                                phi_1681_ = _e1985;
                                                                                                            }
                                                                                                            let _e1987 = phi_1681_;
                                                                                                            phi_1741_ = _e1987;
                                                                                                        } else {
                                                                                                            let _e1924 = local_181;
                                                                                                            if (_e1924 == 2u) {
                                                                                                                let _e1946 = local_182;
                                                                                                                let _e1947 = (2i * _e1946);
                                                                                                                local_184 = _e1947;
                                                                                                                let _e1948 = (_e1947 == 0i);
                                                                                                                local_185 = _e1948;
                                                                                                                if _e1948 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1949 = local_184;
                                                                                                                let _e1950 = (_e1949 == -1i);
                                                                                                                local_186 = _e1950;
                                                                                                                let _e1951 = local_158;
                                                                                                                if (_e1950 && (_e1951 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1954 = local_158;
                                                                                                                let _e1955 = local_184;
                                                                                                                let _e1957 = local_184;
                                                                                                                local_187 = ((_e1954 % _e1955) + _e1957);
                                                                                                                let _e1959 = local_185;
                                                                                                                if _e1959 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1960 = local_187;
                                                                                                                let _e1962 = local_186;
                                                                                                                if (_e1962 && (_e1960 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1964 = local_187;
                                                                                                                let _e1965 = local_184;
                                                                                                                let _e1966 = (_e1964 % _e1965);
                                                                                                                local_188 = _e1966;
                                                                                                                let _e1967 = local_182;
                                                                                                                if (_e1966 < _e1967) {
                                                                                                                    phi_1716_ = _e1966;
                                                                                                                } else {
                                                                                                                    let _e1969 = local_184;
                                                                                                                    let _e1971 = local_188;
                                                                                                                    phi_1716_ = ((_e1969 - 1i) - _e1971);
                                                                                                                }
                                                                                                                let _e1974 = phi_1716_;
                                                                                                                phi_1740_ = _e1974;
                                                                                                            } else {
                                                                                                                let _e1926 = local_182;
                                                                                                                let _e1927 = (_e1926 == 0i);
                                                                                                                local_189 = _e1927;
                                                                                                                if _e1927 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1928 = local_182;
                                                                                                                let _e1929 = (_e1928 == -1i);
                                                                                                                local_190 = _e1929;
                                                                                                                let _e1930 = local_158;
                                                                                                                if (_e1929 && (_e1930 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1933 = local_158;
                                                                                                                let _e1934 = local_182;
                                                                                                                let _e1936 = local_182;
                                                                                                                local_191 = ((_e1933 % _e1934) + _e1936);
                                                                                                                let _e1938 = local_189;
                                                                                                                if _e1938 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1939 = local_191;
                                                                                                                let _e1941 = local_190;
                                                                                                                if (_e1941 && (_e1939 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1943 = local_191;
                                                                                                                let _e1944 = local_182;
                                                                                                                phi_1740_ = (_e1943 % _e1944);
                                                                                                            }
                                                                                                            let _e1976 = phi_1740_;
                                                                                                            phi_1741_ = _e1976;
                                                                                                        }
                                                                                                        let _e1989 = phi_1741_;
                                                                                                        local_192 = bitcast<u32>(_e1989);
                                                                                                        let _e1991 = local_158;
                                                                                                        let _e1992 = (_e1991 + 1i);
                                                                                                        local_193 = _e1992;
                                                                                                        let _e1993 = local_183;
                                                                                                        if _e1993 {
                                                                                                            let _e2047 = local_193;
                                                                                                            if (_e2047 < 0i) {
                                                                                                                phi_1761_ = 0i;
                                                                                                            } else {
                                                                                                                let _e2049 = local_193;
                                                                                                                let _e2050 = local_182;
                                                                                                                if (_e2049 >= _e2050) {
                                                                                                                    let _e2052 = local_182;
                                                                                                                    phi_1760_ = (_e2052 - 1i);
                                                                                                                } else {
                                                                                                                    phi_1760_ = _e1992;
                                                                                                                }
                                                                                                                let _e2055 = phi_1760_;
                                                                                                                phi_1761_ = _e2055;
                                                                                                            }
                                                                                                            let _e2057 = phi_1761_;
                                                                                                            phi_1821_ = _e2057;
                                                                                                        } else {
                                                                                                            let _e1994 = local_181;
                                                                                                            if (_e1994 == 2u) {
                                                                                                                let _e2016 = local_182;
                                                                                                                let _e2017 = (2i * _e2016);
                                                                                                                local_194 = _e2017;
                                                                                                                let _e2018 = (_e2017 == 0i);
                                                                                                                local_195 = _e2018;
                                                                                                                if _e2018 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2019 = local_194;
                                                                                                                let _e2020 = (_e2019 == -1i);
                                                                                                                local_196 = _e2020;
                                                                                                                let _e2021 = local_193;
                                                                                                                if (_e2020 && (_e2021 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2024 = local_193;
                                                                                                                let _e2025 = local_194;
                                                                                                                let _e2027 = local_194;
                                                                                                                local_197 = ((_e2024 % _e2025) + _e2027);
                                                                                                                let _e2029 = local_195;
                                                                                                                if _e2029 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2030 = local_197;
                                                                                                                let _e2032 = local_196;
                                                                                                                if (_e2032 && (_e2030 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2034 = local_197;
                                                                                                                let _e2035 = local_194;
                                                                                                                let _e2036 = (_e2034 % _e2035);
                                                                                                                local_198 = _e2036;
                                                                                                                let _e2037 = local_182;
                                                                                                                if (_e2036 < _e2037) {
                                                                                                                    phi_1796_ = _e2036;
                                                                                                                } else {
                                                                                                                    let _e2039 = local_194;
                                                                                                                    let _e2041 = local_198;
                                                                                                                    phi_1796_ = ((_e2039 - 1i) - _e2041);
                                                                                                                }
                                                                                                                let _e2044 = phi_1796_;
                                                                                                                phi_1820_ = _e2044;
                                                                                                            } else {
                                                                                                                let _e1996 = local_182;
                                                                                                                let _e1997 = (_e1996 == 0i);
                                                                                                                local_199 = _e1997;
                                                                                                                if _e1997 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1998 = local_182;
                                                                                                                let _e1999 = (_e1998 == -1i);
                                                                                                                local_200 = _e1999;
                                                                                                                let _e2000 = local_193;
                                                                                                                if (_e1999 && (_e2000 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2003 = local_193;
                                                                                                                let _e2004 = local_182;
                                                                                                                let _e2006 = local_182;
                                                                                                                local_201 = ((_e2003 % _e2004) + _e2006);
                                                                                                                let _e2008 = local_199;
                                                                                                                if _e2008 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2009 = local_201;
                                                                                                                let _e2011 = local_200;
                                                                                                                if (_e2011 && (_e2009 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2013 = local_201;
                                                                                                                let _e2014 = local_182;
                                                                                                                phi_1820_ = (_e2013 % _e2014);
                                                                                                            }
                                                                                                            let _e2046 = phi_1820_;
                                                                                                            phi_1821_ = _e2046;
                                                                                                        }
                                                                                                        let _e2059 = phi_1821_;
                                                                                                        local_202 = bitcast<u32>(_e2059);
                                                                                                        let _e2061 = local_147;
                                                                                                        local_203 = _e2061.member;
                                                                                                        let _e2063 = local_192;
                                                                                                        let _e2064 = local_149;
                                                                                                        let _e2066 = (_e2061.member + (_e2063 * _e2064));
                                                                                                        local_204 = _e2066;
                                                                                                        let _e2067 = local_170;
                                                                                                        let _e2069 = ((_e2066 + _e2067) * 2u);
                                                                                                        local_205 = _e2069;
                                                                                                        let _e2070 = local_5;
                                                                                                        if (_e2069 < _e2070) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2072 = local_205;
                                                                                                        let _e2075 = global_8.member[_e2072];
                                                                                                        local_206 = _e2075;
                                                                                                        let _e2076 = local_205;
                                                                                                        let _e2077 = (_e2076 + 1u);
                                                                                                        local_207 = _e2077;
                                                                                                        let _e2078 = local_5;
                                                                                                        if (_e2077 < _e2078) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2080 = local_207;
                                                                                                        let _e2083 = global_8.member[_e2080];
                                                                                                        local_208 = _e2083;
                                                                                                        let _e2084 = local_206;
                                                                                                        let _e2085 = (_e2084 & 65535u);
                                                                                                        local_309 = select(-1f, 1f, ((_e2085 & 32768u) == 0u));
                                                                                                        let _e2091 = ((_e2085 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_209 = _e2091;
                                                                                                        local_210 = (_e2085 & 1023u);
                                                                                                        if (_e2091 == 0u) {
                                                                                                            let _e2113 = local_210;
                                                                                                            let _e2115 = local_309;
                                                                                                            phi_1875_ = ((_e2115 * f32(_e2113)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2094 = local_209;
                                                                                                            if (_e2094 == 31u) {
                                                                                                                let _e2104 = local_210;
                                                                                                                phi_1872_ = (2139095040u | (_e2104 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2096 = local_209;
                                                                                                                let _e2100 = local_210;
                                                                                                                phi_1872_ = (((_e2096 + 112u) << bitcast<u32>(23i)) | (_e2100 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2109 = phi_1872_;
                                                                                                            let _e2111 = local_309;
                                                                                                            phi_1875_ = (_e2111 * bitcast<f32>(_e2109));
                                                                                                        }
                                                                                                        let _e2119 = phi_1875_;
                                                                                                        local_211 = _e2119;
                                                                                                        let _e2120 = local_206;
                                                                                                        let _e2122 = (_e2120 >> bitcast<u32>(16i));
                                                                                                        local_310 = select(-1f, 1f, ((_e2122 & 32768u) == 0u));
                                                                                                        let _e2128 = ((_e2122 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_212 = _e2128;
                                                                                                        local_213 = (_e2122 & 1023u);
                                                                                                        if (_e2128 == 0u) {
                                                                                                            let _e2150 = local_213;
                                                                                                            let _e2152 = local_310;
                                                                                                            phi_1907_ = ((_e2152 * f32(_e2150)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2131 = local_212;
                                                                                                            if (_e2131 == 31u) {
                                                                                                                let _e2141 = local_213;
                                                                                                                phi_1904_ = (2139095040u | (_e2141 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2133 = local_212;
                                                                                                                let _e2137 = local_213;
                                                                                                                phi_1904_ = (((_e2133 + 112u) << bitcast<u32>(23i)) | (_e2137 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2146 = phi_1904_;
                                                                                                            let _e2148 = local_310;
                                                                                                            phi_1907_ = (_e2148 * bitcast<f32>(_e2146));
                                                                                                        }
                                                                                                        let _e2156 = phi_1907_;
                                                                                                        local_214 = _e2156;
                                                                                                        let _e2157 = local_208;
                                                                                                        let _e2158 = (_e2157 & 65535u);
                                                                                                        local_311 = select(-1f, 1f, ((_e2158 & 32768u) == 0u));
                                                                                                        let _e2164 = ((_e2158 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_215 = _e2164;
                                                                                                        local_216 = (_e2158 & 1023u);
                                                                                                        if (_e2164 == 0u) {
                                                                                                            let _e2186 = local_216;
                                                                                                            let _e2188 = local_311;
                                                                                                            phi_1939_ = ((_e2188 * f32(_e2186)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2167 = local_215;
                                                                                                            if (_e2167 == 31u) {
                                                                                                                let _e2177 = local_216;
                                                                                                                phi_1936_ = (2139095040u | (_e2177 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2169 = local_215;
                                                                                                                let _e2173 = local_216;
                                                                                                                phi_1936_ = (((_e2169 + 112u) << bitcast<u32>(23i)) | (_e2173 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2182 = phi_1936_;
                                                                                                            let _e2184 = local_311;
                                                                                                            phi_1939_ = (_e2184 * bitcast<f32>(_e2182));
                                                                                                        }
                                                                                                        let _e2192 = phi_1939_;
                                                                                                        local_217 = _e2192;
                                                                                                        let _e2193 = local_208;
                                                                                                        let _e2195 = (_e2193 >> bitcast<u32>(16i));
                                                                                                        local_312 = select(-1f, 1f, ((_e2195 & 32768u) == 0u));
                                                                                                        let _e2201 = ((_e2195 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_218 = _e2201;
                                                                                                        local_219 = (_e2195 & 1023u);
                                                                                                        if (_e2201 == 0u) {
                                                                                                            let _e2223 = local_219;
                                                                                                            let _e2225 = local_312;
                                                                                                            phi_1971_ = ((_e2225 * f32(_e2223)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2204 = local_218;
                                                                                                            if (_e2204 == 31u) {
                                                                                                                let _e2214 = local_219;
                                                                                                                phi_1968_ = (2139095040u | (_e2214 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2206 = local_218;
                                                                                                                let _e2210 = local_219;
                                                                                                                phi_1968_ = (((_e2206 + 112u) << bitcast<u32>(23i)) | (_e2210 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2219 = phi_1968_;
                                                                                                            let _e2221 = local_312;
                                                                                                            phi_1971_ = (_e2221 * bitcast<f32>(_e2219));
                                                                                                        }
                                                                                                        let _e2229 = phi_1971_;
                                                                                                        local_220 = _e2229;
                                                                                                        let _e2230 = local_204;
                                                                                                        let _e2231 = local_180;
                                                                                                        let _e2233 = ((_e2230 + _e2231) * 2u);
                                                                                                        local_221 = _e2233;
                                                                                                        let _e2234 = local_5;
                                                                                                        if (_e2233 < _e2234) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2236 = local_221;
                                                                                                        let _e2239 = global_8.member[_e2236];
                                                                                                        local_222 = _e2239;
                                                                                                        let _e2240 = local_221;
                                                                                                        let _e2241 = (_e2240 + 1u);
                                                                                                        local_223 = _e2241;
                                                                                                        let _e2242 = local_5;
                                                                                                        if (_e2241 < _e2242) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2244 = local_223;
                                                                                                        let _e2247 = global_8.member[_e2244];
                                                                                                        local_224 = _e2247;
                                                                                                        let _e2248 = local_222;
                                                                                                        let _e2249 = (_e2248 & 65535u);
                                                                                                        local_313 = select(-1f, 1f, ((_e2249 & 32768u) == 0u));
                                                                                                        let _e2255 = ((_e2249 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_225 = _e2255;
                                                                                                        local_226 = (_e2249 & 1023u);
                                                                                                        if (_e2255 == 0u) {
                                                                                                            let _e2277 = local_226;
                                                                                                            let _e2279 = local_313;
                                                                                                            phi_2024_ = ((_e2279 * f32(_e2277)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2258 = local_225;
                                                                                                            if (_e2258 == 31u) {
                                                                                                                let _e2268 = local_226;
                                                                                                                phi_2021_ = (2139095040u | (_e2268 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2260 = local_225;
                                                                                                                let _e2264 = local_226;
                                                                                                                phi_2021_ = (((_e2260 + 112u) << bitcast<u32>(23i)) | (_e2264 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2273 = phi_2021_;
                                                                                                            let _e2275 = local_313;
                                                                                                            phi_2024_ = (_e2275 * bitcast<f32>(_e2273));
                                                                                                        }
                                                                                                        let _e2283 = phi_2024_;
                                                                                                        local_227 = _e2283;
                                                                                                        let _e2284 = local_222;
                                                                                                        let _e2286 = (_e2284 >> bitcast<u32>(16i));
                                                                                                        local_314 = select(-1f, 1f, ((_e2286 & 32768u) == 0u));
                                                                                                        let _e2292 = ((_e2286 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_228 = _e2292;
                                                                                                        local_229 = (_e2286 & 1023u);
                                                                                                        if (_e2292 == 0u) {
                                                                                                            let _e2314 = local_229;
                                                                                                            let _e2316 = local_314;
                                                                                                            phi_2056_ = ((_e2316 * f32(_e2314)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2295 = local_228;
                                                                                                            if (_e2295 == 31u) {
                                                                                                                let _e2305 = local_229;
                                                                                                                phi_2053_ = (2139095040u | (_e2305 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2297 = local_228;
                                                                                                                let _e2301 = local_229;
                                                                                                                phi_2053_ = (((_e2297 + 112u) << bitcast<u32>(23i)) | (_e2301 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2310 = phi_2053_;
                                                                                                            let _e2312 = local_314;
                                                                                                            phi_2056_ = (_e2312 * bitcast<f32>(_e2310));
                                                                                                        }
                                                                                                        let _e2320 = phi_2056_;
                                                                                                        local_230 = _e2320;
                                                                                                        let _e2321 = local_224;
                                                                                                        let _e2322 = (_e2321 & 65535u);
                                                                                                        local_315 = select(-1f, 1f, ((_e2322 & 32768u) == 0u));
                                                                                                        let _e2328 = ((_e2322 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_231 = _e2328;
                                                                                                        local_232 = (_e2322 & 1023u);
                                                                                                        if (_e2328 == 0u) {
                                                                                                            let _e2350 = local_232;
                                                                                                            let _e2352 = local_315;
                                                                                                            phi_2088_ = ((_e2352 * f32(_e2350)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2331 = local_231;
                                                                                                            if (_e2331 == 31u) {
                                                                                                                let _e2341 = local_232;
                                                                                                                phi_2085_ = (2139095040u | (_e2341 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2333 = local_231;
                                                                                                                let _e2337 = local_232;
                                                                                                                phi_2085_ = (((_e2333 + 112u) << bitcast<u32>(23i)) | (_e2337 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2346 = phi_2085_;
                                                                                                            let _e2348 = local_315;
                                                                                                            phi_2088_ = (_e2348 * bitcast<f32>(_e2346));
                                                                                                        }
                                                                                                        let _e2356 = phi_2088_;
                                                                                                        local_233 = _e2356;
                                                                                                        let _e2357 = local_224;
                                                                                                        let _e2359 = (_e2357 >> bitcast<u32>(16i));
                                                                                                        local_316 = select(-1f, 1f, ((_e2359 & 32768u) == 0u));
                                                                                                        let _e2365 = ((_e2359 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_234 = _e2365;
                                                                                                        local_235 = (_e2359 & 1023u);
                                                                                                        if (_e2365 == 0u) {
                                                                                                            let _e2387 = local_235;
                                                                                                            let _e2389 = local_316;
                                                                                                            phi_2120_ = ((_e2389 * f32(_e2387)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2368 = local_234;
                                                                                                            if (_e2368 == 31u) {
                                                                                                                let _e2378 = local_235;
                                                                                                                phi_2117_ = (2139095040u | (_e2378 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2370 = local_234;
                                                                                                                let _e2374 = local_235;
                                                                                                                phi_2117_ = (((_e2370 + 112u) << bitcast<u32>(23i)) | (_e2374 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2383 = phi_2117_;
                                                                                                            let _e2385 = local_316;
                                                                                                            phi_2120_ = (_e2385 * bitcast<f32>(_e2383));
                                                                                                        }
                                                                                                        let _e2393 = phi_2120_;
                                                                                                        let _e2394 = local_227;
                                                                                                        let _e2395 = local_211;
                                                                                                        let _e2397 = local_156;
                                                                                                        let _e2399 = local_211;
                                                                                                        local_236 = (_e2399 + ((_e2394 - _e2395) * _e2397));
                                                                                                        let _e2401 = local_230;
                                                                                                        let _e2402 = local_214;
                                                                                                        let _e2404 = local_156;
                                                                                                        let _e2406 = local_214;
                                                                                                        local_237 = (_e2406 + ((_e2401 - _e2402) * _e2404));
                                                                                                        let _e2408 = local_233;
                                                                                                        let _e2409 = local_217;
                                                                                                        let _e2411 = local_156;
                                                                                                        let _e2413 = local_217;
                                                                                                        local_238 = (_e2413 + ((_e2408 - _e2409) * _e2411));
                                                                                                        let _e2415 = local_220;
                                                                                                        let _e2417 = local_156;
                                                                                                        let _e2419 = local_220;
                                                                                                        local_239 = (_e2419 + ((_e2393 - _e2415) * _e2417));
                                                                                                        let _e2421 = local_202;
                                                                                                        let _e2422 = local_149;
                                                                                                        let _e2424 = local_203;
                                                                                                        let _e2425 = (_e2424 + (_e2421 * _e2422));
                                                                                                        local_240 = _e2425;
                                                                                                        let _e2426 = local_170;
                                                                                                        let _e2428 = ((_e2425 + _e2426) * 2u);
                                                                                                        local_241 = _e2428;
                                                                                                        let _e2429 = local_5;
                                                                                                        if (_e2428 < _e2429) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2431 = local_241;
                                                                                                        let _e2434 = global_8.member[_e2431];
                                                                                                        local_242 = _e2434;
                                                                                                        let _e2435 = local_241;
                                                                                                        let _e2436 = (_e2435 + 1u);
                                                                                                        local_243 = _e2436;
                                                                                                        let _e2437 = local_5;
                                                                                                        if (_e2436 < _e2437) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2439 = local_243;
                                                                                                        let _e2442 = global_8.member[_e2439];
                                                                                                        local_244 = _e2442;
                                                                                                        let _e2443 = local_242;
                                                                                                        let _e2444 = (_e2443 & 65535u);
                                                                                                        local_317 = select(-1f, 1f, ((_e2444 & 32768u) == 0u));
                                                                                                        let _e2450 = ((_e2444 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_245 = _e2450;
                                                                                                        local_246 = (_e2444 & 1023u);
                                                                                                        if (_e2450 == 0u) {
                                                                                                            let _e2472 = local_246;
                                                                                                            let _e2474 = local_317;
                                                                                                            phi_2185_ = ((_e2474 * f32(_e2472)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2453 = local_245;
                                                                                                            if (_e2453 == 31u) {
                                                                                                                let _e2463 = local_246;
                                                                                                                phi_2182_ = (2139095040u | (_e2463 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2455 = local_245;
                                                                                                                let _e2459 = local_246;
                                                                                                                phi_2182_ = (((_e2455 + 112u) << bitcast<u32>(23i)) | (_e2459 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2468 = phi_2182_;
                                                                                                            let _e2470 = local_317;
                                                                                                            phi_2185_ = (_e2470 * bitcast<f32>(_e2468));
                                                                                                        }
                                                                                                        let _e2478 = phi_2185_;
                                                                                                        local_247 = _e2478;
                                                                                                        let _e2479 = local_242;
                                                                                                        let _e2481 = (_e2479 >> bitcast<u32>(16i));
                                                                                                        local_318 = select(-1f, 1f, ((_e2481 & 32768u) == 0u));
                                                                                                        let _e2487 = ((_e2481 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_248 = _e2487;
                                                                                                        local_249 = (_e2481 & 1023u);
                                                                                                        if (_e2487 == 0u) {
                                                                                                            let _e2509 = local_249;
                                                                                                            let _e2511 = local_318;
                                                                                                            phi_2217_ = ((_e2511 * f32(_e2509)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2490 = local_248;
                                                                                                            if (_e2490 == 31u) {
                                                                                                                let _e2500 = local_249;
                                                                                                                phi_2214_ = (2139095040u | (_e2500 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2492 = local_248;
                                                                                                                let _e2496 = local_249;
                                                                                                                phi_2214_ = (((_e2492 + 112u) << bitcast<u32>(23i)) | (_e2496 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2505 = phi_2214_;
                                                                                                            let _e2507 = local_318;
                                                                                                            phi_2217_ = (_e2507 * bitcast<f32>(_e2505));
                                                                                                        }
                                                                                                        let _e2515 = phi_2217_;
                                                                                                        local_250 = _e2515;
                                                                                                        let _e2516 = local_244;
                                                                                                        let _e2517 = (_e2516 & 65535u);
                                                                                                        local_319 = select(-1f, 1f, ((_e2517 & 32768u) == 0u));
                                                                                                        let _e2523 = ((_e2517 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_251 = _e2523;
                                                                                                        local_252 = (_e2517 & 1023u);
                                                                                                        if (_e2523 == 0u) {
                                                                                                            let _e2545 = local_252;
                                                                                                            let _e2547 = local_319;
                                                                                                            phi_2249_ = ((_e2547 * f32(_e2545)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2526 = local_251;
                                                                                                            if (_e2526 == 31u) {
                                                                                                                let _e2536 = local_252;
                                                                                                                phi_2246_ = (2139095040u | (_e2536 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2528 = local_251;
                                                                                                                let _e2532 = local_252;
                                                                                                                phi_2246_ = (((_e2528 + 112u) << bitcast<u32>(23i)) | (_e2532 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2541 = phi_2246_;
                                                                                                            let _e2543 = local_319;
                                                                                                            phi_2249_ = (_e2543 * bitcast<f32>(_e2541));
                                                                                                        }
                                                                                                        let _e2551 = phi_2249_;
                                                                                                        local_253 = _e2551;
                                                                                                        let _e2552 = local_244;
                                                                                                        let _e2554 = (_e2552 >> bitcast<u32>(16i));
                                                                                                        local_320 = select(-1f, 1f, ((_e2554 & 32768u) == 0u));
                                                                                                        let _e2560 = ((_e2554 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_254 = _e2560;
                                                                                                        local_255 = (_e2554 & 1023u);
                                                                                                        if (_e2560 == 0u) {
                                                                                                            let _e2582 = local_255;
                                                                                                            let _e2584 = local_320;
                                                                                                            phi_2281_ = ((_e2584 * f32(_e2582)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2563 = local_254;
                                                                                                            if (_e2563 == 31u) {
                                                                                                                let _e2573 = local_255;
                                                                                                                phi_2278_ = (2139095040u | (_e2573 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2565 = local_254;
                                                                                                                let _e2569 = local_255;
                                                                                                                phi_2278_ = (((_e2565 + 112u) << bitcast<u32>(23i)) | (_e2569 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2578 = phi_2278_;
                                                                                                            let _e2580 = local_320;
                                                                                                            phi_2281_ = (_e2580 * bitcast<f32>(_e2578));
                                                                                                        }
                                                                                                        let _e2588 = phi_2281_;
                                                                                                        local_256 = _e2588;
                                                                                                        let _e2589 = local_240;
                                                                                                        let _e2590 = local_180;
                                                                                                        let _e2592 = ((_e2589 + _e2590) * 2u);
                                                                                                        local_257 = _e2592;
                                                                                                        let _e2593 = local_5;
                                                                                                        if (_e2592 < _e2593) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2595 = local_257;
                                                                                                        let _e2598 = global_8.member[_e2595];
                                                                                                        local_258 = _e2598;
                                                                                                        let _e2599 = local_257;
                                                                                                        let _e2600 = (_e2599 + 1u);
                                                                                                        local_259 = _e2600;
                                                                                                        let _e2601 = local_5;
                                                                                                        if (_e2600 < _e2601) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2603 = local_259;
                                                                                                        let _e2606 = global_8.member[_e2603];
                                                                                                        local_260 = _e2606;
                                                                                                        let _e2607 = local_258;
                                                                                                        let _e2608 = (_e2607 & 65535u);
                                                                                                        local_321 = select(-1f, 1f, ((_e2608 & 32768u) == 0u));
                                                                                                        let _e2614 = ((_e2608 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_261 = _e2614;
                                                                                                        local_262 = (_e2608 & 1023u);
                                                                                                        if (_e2614 == 0u) {
                                                                                                            let _e2636 = local_262;
                                                                                                            let _e2638 = local_321;
                                                                                                            phi_2334_ = ((_e2638 * f32(_e2636)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2617 = local_261;
                                                                                                            if (_e2617 == 31u) {
                                                                                                                let _e2627 = local_262;
                                                                                                                phi_2331_ = (2139095040u | (_e2627 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2619 = local_261;
                                                                                                                let _e2623 = local_262;
                                                                                                                phi_2331_ = (((_e2619 + 112u) << bitcast<u32>(23i)) | (_e2623 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2632 = phi_2331_;
                                                                                                            let _e2634 = local_321;
                                                                                                            phi_2334_ = (_e2634 * bitcast<f32>(_e2632));
                                                                                                        }
                                                                                                        let _e2642 = phi_2334_;
                                                                                                        local_263 = _e2642;
                                                                                                        let _e2643 = local_258;
                                                                                                        let _e2645 = (_e2643 >> bitcast<u32>(16i));
                                                                                                        local_322 = select(-1f, 1f, ((_e2645 & 32768u) == 0u));
                                                                                                        let _e2651 = ((_e2645 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_264 = _e2651;
                                                                                                        local_265 = (_e2645 & 1023u);
                                                                                                        if (_e2651 == 0u) {
                                                                                                            let _e2673 = local_265;
                                                                                                            let _e2675 = local_322;
                                                                                                            phi_2366_ = ((_e2675 * f32(_e2673)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2654 = local_264;
                                                                                                            if (_e2654 == 31u) {
                                                                                                                let _e2664 = local_265;
                                                                                                                phi_2363_ = (2139095040u | (_e2664 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2656 = local_264;
                                                                                                                let _e2660 = local_265;
                                                                                                                phi_2363_ = (((_e2656 + 112u) << bitcast<u32>(23i)) | (_e2660 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2669 = phi_2363_;
                                                                                                            let _e2671 = local_322;
                                                                                                            phi_2366_ = (_e2671 * bitcast<f32>(_e2669));
                                                                                                        }
                                                                                                        let _e2679 = phi_2366_;
                                                                                                        local_266 = _e2679;
                                                                                                        let _e2680 = local_260;
                                                                                                        let _e2681 = (_e2680 & 65535u);
                                                                                                        local_323 = select(-1f, 1f, ((_e2681 & 32768u) == 0u));
                                                                                                        let _e2687 = ((_e2681 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_267 = _e2687;
                                                                                                        local_268 = (_e2681 & 1023u);
                                                                                                        if (_e2687 == 0u) {
                                                                                                            let _e2709 = local_268;
                                                                                                            let _e2711 = local_323;
                                                                                                            phi_2398_ = ((_e2711 * f32(_e2709)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2690 = local_267;
                                                                                                            if (_e2690 == 31u) {
                                                                                                                let _e2700 = local_268;
                                                                                                                phi_2395_ = (2139095040u | (_e2700 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2692 = local_267;
                                                                                                                let _e2696 = local_268;
                                                                                                                phi_2395_ = (((_e2692 + 112u) << bitcast<u32>(23i)) | (_e2696 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2705 = phi_2395_;
                                                                                                            let _e2707 = local_323;
                                                                                                            phi_2398_ = (_e2707 * bitcast<f32>(_e2705));
                                                                                                        }
                                                                                                        let _e2715 = phi_2398_;
                                                                                                        local_269 = _e2715;
                                                                                                        let _e2716 = local_260;
                                                                                                        let _e2718 = (_e2716 >> bitcast<u32>(16i));
                                                                                                        local_324 = select(-1f, 1f, ((_e2718 & 32768u) == 0u));
                                                                                                        let _e2724 = ((_e2718 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_270 = _e2724;
                                                                                                        local_271 = (_e2718 & 1023u);
                                                                                                        if (_e2724 == 0u) {
                                                                                                            let _e2746 = local_271;
                                                                                                            let _e2748 = local_324;
                                                                                                            phi_2430_ = ((_e2748 * f32(_e2746)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2727 = local_270;
                                                                                                            if (_e2727 == 31u) {
                                                                                                                let _e2737 = local_271;
                                                                                                                phi_2427_ = (2139095040u | (_e2737 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2729 = local_270;
                                                                                                                let _e2733 = local_271;
                                                                                                                phi_2427_ = (((_e2729 + 112u) << bitcast<u32>(23i)) | (_e2733 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2742 = phi_2427_;
                                                                                                            let _e2744 = local_324;
                                                                                                            phi_2430_ = (_e2744 * bitcast<f32>(_e2742));
                                                                                                        }
                                                                                                        let _e2752 = phi_2430_;
                                                                                                        let _e2753 = local_263;
                                                                                                        let _e2754 = local_247;
                                                                                                        let _e2756 = local_156;
                                                                                                        let _e2758 = local_247;
                                                                                                        let _e2760 = local_266;
                                                                                                        let _e2761 = local_250;
                                                                                                        let _e2763 = local_156;
                                                                                                        let _e2765 = local_250;
                                                                                                        let _e2767 = local_269;
                                                                                                        let _e2768 = local_253;
                                                                                                        let _e2770 = local_156;
                                                                                                        let _e2772 = local_253;
                                                                                                        let _e2774 = local_256;
                                                                                                        let _e2776 = local_156;
                                                                                                        let _e2778 = local_256;
                                                                                                        let _e2780 = local_236;
                                                                                                        let _e2782 = local_155;
                                                                                                        let _e2784 = local_236;
                                                                                                        let _e2786 = local_237;
                                                                                                        let _e2788 = local_155;
                                                                                                        let _e2790 = local_237;
                                                                                                        let _e2792 = local_238;
                                                                                                        let _e2794 = local_155;
                                                                                                        let _e2796 = local_238;
                                                                                                        let _e2798 = local_239;
                                                                                                        let _e2800 = local_155;
                                                                                                        let _e2802 = local_239;
                                                                                                        let _e2804 = local_148;
                                                                                                        let _e2806 = local_148;
                                                                                                        let _e2808 = local_148;
                                                                                                        let _e2810 = local_148;
                                                                                                        let _e2812 = local_145;
                                                                                                        let _e2815 = local_145;
                                                                                                        let _e2818 = local_145;
                                                                                                        let _e2821 = local_145;
                                                                                                        let _e2825 = local_144;
                                                                                                        phi_1449_ = (_e2825 + 1u);
                                                                                                        phi_1452_ = type_5((_e2812.member + ((_e2784 + (((_e2758 + ((_e2753 - _e2754) * _e2756)) - _e2780) * _e2782)) * _e2804)), (_e2815.member_1 + ((_e2790 + (((_e2765 + ((_e2760 - _e2761) * _e2763)) - _e2786) * _e2788)) * _e2806)), (_e2818.member_2 + ((_e2796 + (((_e2772 + ((_e2767 - _e2768) * _e2770)) - _e2792) * _e2794)) * _e2808)), (_e2821.member_3 + ((_e2802 + (((_e2778 + ((_e2752 - _e2774) * _e2776)) - _e2798) * _e2800)) * _e2810)));
                                                                                                    } else {
                                                                                                        phi_1449_ = u32();
                                                                                                        phi_1452_ = type_5();
                                                                                                    }
                                                                                                    let _e2828 = phi_1449_;
                                                                                                    let _e2830 = phi_1452_;
                                                                                                    continue;
                                                                                                    continuing {
                                                                                                        let _e2831 = local_146;
                                                                                                        phi_1448_ = _e2828;
                                                                                                        phi_1451_ = _e2830;
                                                                                                        phi_3210_ = _e1704;
                                                                                                        break if !(_e2831);
                                                                                                    }
                                                                                                }
                                                                                                let _e2834 = phi_3210_;
                                                                                                phi_3316_ = _e2834;
                                                                                                if _e2834 {
                                                                                                    break;
                                                                                                }
                                                                                                let _e2835 = local_142;
                                                                                                phi_3317_ = _e2834;
                                                                                                phi_1420_ = (_e2835 + 1u);
                                                                                                let _e3133 = local_331;
                                                                                                phi_1423_ = _e3133;
                                                                                            } else {
                                                                                                phi_3317_ = _e1704;
                                                                                                phi_1420_ = u32();
                                                                                                phi_1423_ = type_5();
                                                                                            }
                                                                                            let _e2838 = phi_3317_;
                                                                                            let _e2840 = phi_1420_;
                                                                                            let _e2842 = phi_1423_;
                                                                                            continue;
                                                                                            continuing {
                                                                                                let _e2843 = local_143;
                                                                                                phi_3256_ = _e2838;
                                                                                                phi_1419_ = _e2840;
                                                                                                phi_1422_ = _e2842;
                                                                                                phi_3316_ = _e2838;
                                                                                                break if !(_e2843);
                                                                                            }
                                                                                        }
                                                                                        let _e2846 = phi_3316_;
                                                                                        phi_3318_ = _e2846;
                                                                                        if _e2846 {
                                                                                            break;
                                                                                        }
                                                                                        let _e2847 = local_139;
                                                                                        phi_3319_ = _e2846;
                                                                                        phi_1403_ = (_e2847 + 1u);
                                                                                        let _e3139 = local_332;
                                                                                        phi_1406_ = _e3139;
                                                                                    } else {
                                                                                        phi_3319_ = _e1696;
                                                                                        phi_1403_ = u32();
                                                                                        phi_1406_ = type_5();
                                                                                    }
                                                                                    let _e2850 = phi_3319_;
                                                                                    let _e2852 = phi_1403_;
                                                                                    let _e2854 = phi_1406_;
                                                                                    continue;
                                                                                    continuing {
                                                                                        let _e2855 = local_141;
                                                                                        phi_3257_ = _e2850;
                                                                                        phi_1402_ = _e2852;
                                                                                        phi_1405_ = _e2854;
                                                                                        phi_3318_ = _e2850;
                                                                                        break if !(_e2855);
                                                                                    }
                                                                                }
                                                                                let _e2858 = phi_3318_;
                                                                                phi_3320_ = _e2858;
                                                                                if _e2858 {
                                                                                    break;
                                                                                }
                                                                                let _e2859 = local_140;
                                                                                let _e2861 = local_140;
                                                                                let _e2863 = local_140;
                                                                                let _e2865 = local_140;
                                                                                phi_3341_ = _e2858;
                                                                                let _e3144 = local_333;
                                                                                phi_2483_ = _e3144;
                                                                            }
                                                                            let _e2868 = phi_3341_;
                                                                            let _e2870 = phi_2483_;
                                                                            phi_3340_ = _e2868;
                                                                            phi_2484_ = _e2870;
                                                                            phi_2485_ = _e1513;
                                                                        }
                                                                        let _e2872 = phi_3340_;
                                                                        let _e2874 = phi_2484_;
                                                                        let _e2876 = phi_2485_;
                                                                        if _e2876 {
                                                                            phi_2489_ = type_5(1f, 1f, 1f, 1f);
                                                                        } else {
                                                                            phi_2489_ = _e2874;
                                                                        }
                                                                        let _e2878 = phi_2489_;
                                                                        phi_3338_ = _e2872;
                                                                        phi_2490_ = _e2878;
                                                                    }
                                                                    let _e2880 = phi_3338_;
                                                                    let _e2882 = phi_2490_;
                                                                    phi_3337_ = _e2880;
                                                                    phi_2491_ = _e2882;
                                                                    phi_2492_ = _e1477;
                                                                }
                                                                let _e2884 = phi_3337_;
                                                                let _e2886 = phi_2491_;
                                                                let _e2888 = phi_2492_;
                                                                if _e2888 {
                                                                    phi_2496_ = type_5(1f, 1f, 1f, 1f);
                                                                } else {
                                                                    phi_2496_ = _e2886;
                                                                }
                                                                let _e2890 = phi_2496_;
                                                                let _e2892 = local_123;
                                                                let _e2894 = local_110;
                                                                local_272 = ((_e2892 * _e2890.member_3) * _e2894);
                                                                let _e2896 = local_84;
                                                                if ((_e2896 & 4u) == 0u) {
                                                                    let _e2910 = local_272;
                                                                    phi_2517_ = (_e2910 > 0f);
                                                                } else {
                                                                    let _e2899 = local_82;
                                                                    let _e2900 = (_e2899 + 7u);
                                                                    local_273 = _e2900;
                                                                    let _e2901 = local_3;
                                                                    if (_e2900 < _e2901) {
                                                                    } else {
                                                                        phi_3320_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2903 = local_273;
                                                                    let _e2906 = global_5.member[_e2903];
                                                                    let _e2908 = local_272;
                                                                    phi_2517_ = (_e2908 >= bitcast<f32>(_e2906));
                                                                }
                                                                let _e2913 = phi_2517_;
                                                                phi_3334_ = _e2884;
                                                                phi_2518_ = _e2913;
                                                            }
                                                            let _e2915 = phi_3334_;
                                                            let _e2917 = phi_2518_;
                                                            phi_3333_ = _e2915;
                                                            phi_2519_ = _e2917;
                                                        } else {
                                                            phi_3333_ = _e434;
                                                            phi_2519_ = bool();
                                                        }
                                                        let _e2919 = phi_3333_;
                                                        let _e2921 = phi_2519_;
                                                        let _e2922 = local_81;
                                                        phi_3332_ = _e2919;
                                                        phi_2521_ = _e2921;
                                                        phi_2522_ = select(true, false, _e2922);
                                                    } else {
                                                        phi_3332_ = _e434;
                                                        phi_2521_ = bool();
                                                        phi_2522_ = true;
                                                    }
                                                    let _e2925 = phi_3332_;
                                                    let _e2927 = phi_2521_;
                                                    let _e2929 = phi_2522_;
                                                    if select(_e2927, false, _e2929) {
                                                        let _e2931 = local_13;
                                                        local_274 = bitcast<u32>(f32((_e2931 + 1u)));
                                                        let _e2935 = local_79;
                                                        if _e2935 {
                                                        } else {
                                                            phi_3320_ = true;
                                                            break;
                                                        }
                                                        let _e2936 = local_274;
                                                        global_11.member[_e1103] = _e2936;
                                                        let _e2937 = local_78;
                                                        let _e2938 = (_e2937 + 1u);
                                                        local_275 = _e2938;
                                                        let _e2939 = local_76;
                                                        local_276 = bitcast<u32>(_e2939);
                                                        let _e2941 = local_8;
                                                        if (_e2938 < _e2941) {
                                                        } else {
                                                            phi_3320_ = true;
                                                            break;
                                                        }
                                                        let _e2943 = local_275;
                                                        let _e2946 = local_276;
                                                        global_11.member[_e2943] = _e2946;
                                                        let _e2947 = local_78;
                                                        let _e2948 = (_e2947 + 2u);
                                                        local_277 = _e2948;
                                                        let _e2949 = local_74;
                                                        local_278 = bitcast<u32>(_e2949);
                                                        let _e2951 = local_8;
                                                        if (_e2948 < _e2951) {
                                                        } else {
                                                            phi_3320_ = true;
                                                            break;
                                                        }
                                                        let _e2953 = local_277;
                                                        let _e2956 = local_278;
                                                        global_11.member[_e2953] = _e2956;
                                                        let _e2957 = local_78;
                                                        let _e2958 = (_e2957 + 3u);
                                                        local_279 = _e2958;
                                                        let _e2959 = local_75;
                                                        local_280 = bitcast<u32>(_e2959);
                                                        let _e2961 = local_8;
                                                        if (_e2958 < _e2961) {
                                                        } else {
                                                            phi_3320_ = true;
                                                            break;
                                                        }
                                                        let _e2963 = local_279;
                                                        let _e2966 = local_280;
                                                        global_11.member[_e2963] = _e2966;
                                                    }
                                                    phi_3329_ = _e2925;
                                                } else {
                                                    phi_3329_ = _e434;
                                                }
                                                let _e2968 = phi_3329_;
                                                phi_3328_ = _e2968;
                                            }
                                            let _e2970 = phi_3328_;
                                            phi_3327_ = _e2970;
                                        }
                                        let _e2972 = phi_3327_;
                                        phi_3326_ = _e2972;
                                    }
                                    let _e2974 = phi_3326_;
                                    storageBarrier();
                                    workgroupBarrier();
                                    phi_3325_ = _e2974;
                                } else {
                                    phi_3325_ = _e434;
                                }
                                let _e2976 = phi_3325_;
                                phi_3324_ = _e2976;
                            } else {
                                phi_3324_ = _e434;
                            }
                            let _e2978 = phi_3324_;
                            phi_3323_ = _e2978;
                        } else {
                            phi_3323_ = _e434;
                        }
                        let _e2980 = phi_3323_;
                        phi_3322_ = _e2980;
                    } else {
                        phi_3322_ = _e434;
                    }
                    let _e2982 = phi_3322_;
                    let _e2983 = local_13;
                    phi_3321_ = _e2982;
                    phi_184_ = (_e2983 + 1u);
                } else {
                    phi_3321_ = _e434;
                    phi_184_ = u32();
                }
                let _e2986 = phi_3321_;
                let _e2988 = phi_184_;
                continue;
                continuing {
                    let _e2989 = local_14;
                    phi_3190_ = _e2986;
                    phi_183_ = _e2988;
                    phi_3320_ = _e2986;
                    break if !(_e2989);
                }
            }
            let _e2992 = phi_3320_;
            if _e2992 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn raster_fallback(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
