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
                                                                                let _e1560 = select(select(u32(_e1555), 0u, (_e1555 < 0f)), 4294967295u, (_e1555 > 4294967000f));
                                                                                local_134 = _e1560;
                                                                                let _e1561 = (_e1560 >= _e1554);
                                                                                local_135 = _e1561;
                                                                                if _e1561 {
                                                                                    phi_1383_ = 0f;
                                                                                } else {
                                                                                    let _e1562 = local_134;
                                                                                    phi_1383_ = -(f32(_e1562));
                                                                                }
                                                                                let _e1566 = phi_1383_;
                                                                                local_136 = _e1566;
                                                                                let _e1567 = local_135;
                                                                                let _e1568 = local_133;
                                                                                let _e1569 = local_134;
                                                                                local_307 = select(_e1569, _e1568, _e1567);
                                                                                local_308 = select(1u, 2u, (_e1566 > 0f));
                                                                                phi_3041_ = 0u;
                                                                                phi_3042_ = _e1531;
                                                                                loop {
                                                                                    let _e1574 = phi_3041_;
                                                                                    let _e1576 = phi_3042_;
                                                                                    local_283 = _e1574;
                                                                                    local_284 = _e1576;
                                                                                    local_329 = _e1576;
                                                                                    let _e1577 = local_283;
                                                                                    let _e1578 = local_307;
                                                                                    let _e1579 = (_e1577 < _e1578);
                                                                                    local_285 = _e1579;
                                                                                    if _e1579 {
                                                                                        let _e1580 = local_284;
                                                                                        local_286 = _e1580.member_1;
                                                                                        let _e1582 = local_284;
                                                                                        local_287 = _e1582.member_2;
                                                                                        let _e1585 = local_284;
                                                                                        let _e1588 = local_284;
                                                                                        local_288 = type_22((_e1585.member + (_e1580.member_1 * _e1582.member_2)), _e1588.member_1, _e1588.member_2, _e1588.member_3, _e1588.member_4);
                                                                                        if (_e1580.member_1 > 1u) {
                                                                                            let _e1596 = local_286;
                                                                                            phi_3059_ = (_e1596 >> bitcast<u32>(1i));
                                                                                        } else {
                                                                                            phi_3059_ = 1u;
                                                                                        }
                                                                                        let _e1600 = phi_3059_;
                                                                                        let _e1601 = local_288;
                                                                                        local_289 = type_22(_e1601.member, _e1600, _e1601.member_2, _e1601.member_3, _e1601.member_4);
                                                                                        let _e1608 = local_287;
                                                                                        if (_e1608 > 1u) {
                                                                                            let _e1610 = local_287;
                                                                                            phi_3068_ = (_e1610 >> bitcast<u32>(1i));
                                                                                        } else {
                                                                                            phi_3068_ = 1u;
                                                                                        }
                                                                                        let _e1614 = phi_3068_;
                                                                                        let _e1615 = local_289;
                                                                                        let _e1622 = local_283;
                                                                                        phi_3073_ = (_e1622 + 1u);
                                                                                        phi_3074_ = type_22(_e1615.member, _e1615.member_1, _e1614, _e1615.member_3, _e1615.member_4);
                                                                                    } else {
                                                                                        phi_3073_ = u32();
                                                                                        phi_3074_ = type_22();
                                                                                    }
                                                                                    let _e1625 = phi_3073_;
                                                                                    let _e1627 = phi_3074_;
                                                                                    continue;
                                                                                    continuing {
                                                                                        let _e1628 = local_285;
                                                                                        phi_3041_ = _e1625;
                                                                                        phi_3042_ = _e1627;
                                                                                        break if !(_e1628);
                                                                                    }
                                                                                }
                                                                                let _e1630 = local_307;
                                                                                let _e1631 = local_308;
                                                                                local_137 = ((_e1630 + _e1631) - 1u);
                                                                                phi_3080_ = 0u;
                                                                                phi_3081_ = _e1531;
                                                                                loop {
                                                                                    let _e1635 = phi_3080_;
                                                                                    let _e1637 = phi_3081_;
                                                                                    local_290 = _e1635;
                                                                                    local_291 = _e1637;
                                                                                    local_330 = _e1637;
                                                                                    let _e1638 = local_290;
                                                                                    let _e1639 = local_137;
                                                                                    let _e1640 = (_e1638 < _e1639);
                                                                                    local_292 = _e1640;
                                                                                    if _e1640 {
                                                                                        let _e1641 = local_291;
                                                                                        local_293 = _e1641.member_1;
                                                                                        let _e1643 = local_291;
                                                                                        local_294 = _e1643.member_2;
                                                                                        let _e1646 = local_291;
                                                                                        let _e1649 = local_291;
                                                                                        local_295 = type_22((_e1646.member + (_e1641.member_1 * _e1643.member_2)), _e1649.member_1, _e1649.member_2, _e1649.member_3, _e1649.member_4);
                                                                                        if (_e1641.member_1 > 1u) {
                                                                                            let _e1657 = local_293;
                                                                                            phi_3098_ = (_e1657 >> bitcast<u32>(1i));
                                                                                        } else {
                                                                                            phi_3098_ = 1u;
                                                                                        }
                                                                                        let _e1661 = phi_3098_;
                                                                                        let _e1662 = local_295;
                                                                                        local_296 = type_22(_e1662.member, _e1661, _e1662.member_2, _e1662.member_3, _e1662.member_4);
                                                                                        let _e1669 = local_294;
                                                                                        if (_e1669 > 1u) {
                                                                                            let _e1671 = local_294;
                                                                                            phi_3107_ = (_e1671 >> bitcast<u32>(1i));
                                                                                        } else {
                                                                                            phi_3107_ = 1u;
                                                                                        }
                                                                                        let _e1675 = phi_3107_;
                                                                                        let _e1676 = local_296;
                                                                                        let _e1683 = local_290;
                                                                                        phi_3112_ = (_e1683 + 1u);
                                                                                        phi_3113_ = type_22(_e1676.member, _e1676.member_1, _e1675, _e1676.member_3, _e1676.member_4);
                                                                                    } else {
                                                                                        phi_3112_ = u32();
                                                                                        phi_3113_ = type_22();
                                                                                    }
                                                                                    let _e1686 = phi_3112_;
                                                                                    let _e1688 = phi_3113_;
                                                                                    continue;
                                                                                    continuing {
                                                                                        let _e1689 = local_292;
                                                                                        phi_3080_ = _e1686;
                                                                                        phi_3081_ = _e1688;
                                                                                        break if !(_e1689);
                                                                                    }
                                                                                }
                                                                                let _e1691 = local_132;
                                                                                local_138 = ((_e1691 & 1u) != 0u);
                                                                                phi_3257_ = _e1452;
                                                                                phi_1402_ = 0u;
                                                                                phi_1405_ = type_5(0f, 0f, 0f, 0f);
                                                                                loop {
                                                                                    let _e1695 = phi_3257_;
                                                                                    let _e1697 = phi_1402_;
                                                                                    let _e1699 = phi_1405_;
                                                                                    local_139 = _e1697;
                                                                                    local_140 = _e1699;
                                                                                    local_333 = _e1699;
                                                                                    let _e1700 = local_139;
                                                                                    let _e1701 = (_e1700 < 1u);
                                                                                    local_141 = _e1701;
                                                                                    if _e1701 {
                                                                                        phi_3256_ = _e1695;
                                                                                        phi_1419_ = 0u;
                                                                                        phi_1422_ = _e1699;
                                                                                        loop {
                                                                                            let _e1703 = phi_3256_;
                                                                                            let _e1705 = phi_1419_;
                                                                                            let _e1707 = phi_1422_;
                                                                                            local_142 = _e1705;
                                                                                            local_332 = _e1707;
                                                                                            let _e1708 = local_142;
                                                                                            let _e1709 = (_e1708 < 1u);
                                                                                            local_143 = _e1709;
                                                                                            if _e1709 {
                                                                                                phi_1448_ = 0u;
                                                                                                phi_1451_ = _e1707;
                                                                                                loop {
                                                                                                    let _e1711 = phi_1448_;
                                                                                                    let _e1713 = phi_1451_;
                                                                                                    local_144 = _e1711;
                                                                                                    local_145 = _e1713;
                                                                                                    local_331 = _e1713;
                                                                                                    let _e1714 = local_144;
                                                                                                    let _e1715 = local_308;
                                                                                                    let _e1716 = (_e1714 < _e1715);
                                                                                                    local_146 = _e1716;
                                                                                                    if _e1716 {
                                                                                                        let _e1717 = local_144;
                                                                                                        if (_e1717 == 0u) {
                                                                                                            let _e1719 = local_136;
                                                                                                            let _e3065 = local_329;
                                                                                                            phi_1464_ = _e3065;
                                                                                                            phi_1465_ = (1f - _e1719);
                                                                                                        } else {
                                                                                                            let _e3067 = local_330;
                                                                                                            phi_1464_ = _e3067;
                                                                                                            phi_1465_ = _e1566;
                                                                                                        }
                                                                                                        let _e1722 = phi_1464_;
                                                                                                        let _e1724 = phi_1465_;
                                                                                                        local_147 = _e1722;
                                                                                                        local_148 = _e1724;
                                                                                                        let _e1725 = local_138;
                                                                                                        let _e1726 = select(0.5f, 0f, _e1725);
                                                                                                        local_149 = _e1722.member_1;
                                                                                                        let _e1729 = local_306;
                                                                                                        let _e1731 = ((_e1729 * f32(_e1722.member_1)) - _e1726);
                                                                                                        local_150 = _e1731;
                                                                                                        local_151 = _e1722.member_2;
                                                                                                        let _e1734 = local_305;
                                                                                                        let _e1736 = ((_e1734 * f32(_e1722.member_2)) - _e1726);
                                                                                                        local_152 = _e1736;
                                                                                                        local_153 = floor(_e1731);
                                                                                                        local_154 = floor(_e1736);
                                                                                                        let _e1739 = local_138;
                                                                                                        if _e1739 {
                                                                                                            phi_1485_ = 0f;
                                                                                                            phi_1486_ = 0f;
                                                                                                        } else {
                                                                                                            let _e1740 = local_150;
                                                                                                            let _e1741 = local_153;
                                                                                                            let _e1743 = local_152;
                                                                                                            let _e1744 = local_154;
                                                                                                            phi_1485_ = (_e1743 - _e1744);
                                                                                                            phi_1486_ = (_e1740 - _e1741);
                                                                                                        }
                                                                                                        let _e1747 = phi_1485_;
                                                                                                        let _e1749 = phi_1486_;
                                                                                                        local_155 = _e1747;
                                                                                                        local_156 = _e1749;
                                                                                                        let _e1750 = local_153;
                                                                                                        let _e1752 = local_153;
                                                                                                        let _e1754 = local_153;
                                                                                                        let _e1758 = local_153;
                                                                                                        let _e1759 = local_153;
                                                                                                        let _e1761 = select(0i, select(select(i32(_e1750), i32(-2147483648), (_e1752 < -2147483600f)), 2147483647i, (_e1754 > 2147483500f)), (_e1758 == _e1759));
                                                                                                        local_157 = _e1761;
                                                                                                        let _e1762 = local_154;
                                                                                                        let _e1764 = local_154;
                                                                                                        let _e1766 = local_154;
                                                                                                        let _e1770 = local_154;
                                                                                                        let _e1771 = local_154;
                                                                                                        let _e1773 = select(0i, select(select(i32(_e1762), i32(-2147483648), (_e1764 < -2147483600f)), 2147483647i, (_e1766 > 2147483500f)), (_e1770 == _e1771));
                                                                                                        local_158 = _e1773;
                                                                                                        let _e1774 = local_147;
                                                                                                        local_159 = _e1774.member_3;
                                                                                                        let _e1776 = local_149;
                                                                                                        local_160 = bitcast<i32>(_e1776);
                                                                                                        let _e1778 = (_e1774.member_3 == 1u);
                                                                                                        local_161 = _e1778;
                                                                                                        if _e1778 {
                                                                                                            let _e1832 = local_157;
                                                                                                            if (_e1832 < 0i) {
                                                                                                                phi_1522_ = 0i;
                                                                                                            } else {
                                                                                                                let _e1834 = local_157;
                                                                                                                let _e1835 = local_160;
                                                                                                                if (_e1834 >= _e1835) {
                                                                                                                    let _e1837 = local_160;
                                                                                                                    phi_1521_ = (_e1837 - 1i);
                                                                                                                } else {
                                                                                                                    phi_1521_ = _e1761;
                                                                                                                }
                                                                                                                let _e1840 = phi_1521_;
                                                                                                                phi_1522_ = _e1840;
                                                                                                            }
                                                                                                            let _e1842 = phi_1522_;
                                                                                                            phi_1582_ = _e1842;
                                                                                                        } else {
                                                                                                            let _e1779 = local_159;
                                                                                                            if (_e1779 == 2u) {
                                                                                                                let _e1801 = local_160;
                                                                                                                let _e1802 = (2i * _e1801);
                                                                                                                local_162 = _e1802;
                                                                                                                let _e1803 = (_e1802 == 0i);
                                                                                                                local_163 = _e1803;
                                                                                                                if _e1803 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1804 = local_162;
                                                                                                                let _e1805 = (_e1804 == -1i);
                                                                                                                local_164 = _e1805;
                                                                                                                let _e1806 = local_157;
                                                                                                                if (_e1805 && (_e1806 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1809 = local_157;
                                                                                                                let _e1810 = local_162;
                                                                                                                let _e1812 = local_162;
                                                                                                                local_165 = ((_e1809 % _e1810) + _e1812);
                                                                                                                let _e1814 = local_163;
                                                                                                                if _e1814 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1815 = local_165;
                                                                                                                let _e1817 = local_164;
                                                                                                                if (_e1817 && (_e1815 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1819 = local_165;
                                                                                                                let _e1820 = local_162;
                                                                                                                let _e1821 = (_e1819 % _e1820);
                                                                                                                local_166 = _e1821;
                                                                                                                let _e1822 = local_160;
                                                                                                                if (_e1821 < _e1822) {
                                                                                                                    phi_1557_ = _e1821;
                                                                                                                } else {
                                                                                                                    let _e1824 = local_162;
                                                                                                                    let _e1826 = local_166;
                                                                                                                    phi_1557_ = ((_e1824 - 1i) - _e1826);
                                                                                                                }
                                                                                                                let _e1829 = phi_1557_;
                                                                                                                phi_1581_ = _e1829;
                                                                                                            } else {
                                                                                                                let _e1781 = local_160;
                                                                                                                let _e1782 = (_e1781 == 0i);
                                                                                                                local_167 = _e1782;
                                                                                                                if _e1782 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1783 = local_160;
                                                                                                                let _e1784 = (_e1783 == -1i);
                                                                                                                local_168 = _e1784;
                                                                                                                let _e1785 = local_157;
                                                                                                                if (_e1784 && (_e1785 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1788 = local_157;
                                                                                                                let _e1789 = local_160;
                                                                                                                let _e1791 = local_160;
                                                                                                                local_169 = ((_e1788 % _e1789) + _e1791);
                                                                                                                let _e1793 = local_167;
                                                                                                                if _e1793 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1794 = local_169;
                                                                                                                let _e1796 = local_168;
                                                                                                                if (_e1796 && (_e1794 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1798 = local_169;
                                                                                                                let _e1799 = local_160;
                                                                                                                phi_1581_ = (_e1798 % _e1799);
                                                                                                            }
                                                                                                            let _e1831 = phi_1581_;
                                                                                                            phi_1582_ = _e1831;
                                                                                                        }
                                                                                                        let _e1844 = phi_1582_;
                                                                                                        local_170 = bitcast<u32>(_e1844);
                                                                                                        let _e1846 = local_157;
                                                                                                        let _e1847 = (_e1846 + 1i);
                                                                                                        local_171 = _e1847;
                                                                                                        let _e1848 = local_161;
                                                                                                        if _e1848 {
                                                                                                            let _e1902 = local_171;
                                                                                                            if (_e1902 < 0i) {
                                                                                                                phi_1602_ = 0i;
                                                                                                            } else {
                                                                                                                let _e1904 = local_171;
                                                                                                                let _e1905 = local_160;
                                                                                                                if (_e1904 >= _e1905) {
                                                                                                                    let _e1907 = local_160;
                                                                                                                    phi_1601_ = (_e1907 - 1i);
                                                                                                                } else {
                                                                                                                    phi_1601_ = _e1847;
                                                                                                                }
                                                                                                                let _e1910 = phi_1601_;
                                                                                                                phi_1602_ = _e1910;
                                                                                                            }
                                                                                                            let _e1912 = phi_1602_;
                                                                                                            phi_1662_ = _e1912;
                                                                                                        } else {
                                                                                                            let _e1849 = local_159;
                                                                                                            if (_e1849 == 2u) {
                                                                                                                let _e1871 = local_160;
                                                                                                                let _e1872 = (2i * _e1871);
                                                                                                                local_172 = _e1872;
                                                                                                                let _e1873 = (_e1872 == 0i);
                                                                                                                local_173 = _e1873;
                                                                                                                if _e1873 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1874 = local_172;
                                                                                                                let _e1875 = (_e1874 == -1i);
                                                                                                                local_174 = _e1875;
                                                                                                                let _e1876 = local_171;
                                                                                                                if (_e1875 && (_e1876 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1879 = local_171;
                                                                                                                let _e1880 = local_172;
                                                                                                                let _e1882 = local_172;
                                                                                                                local_175 = ((_e1879 % _e1880) + _e1882);
                                                                                                                let _e1884 = local_173;
                                                                                                                if _e1884 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1885 = local_175;
                                                                                                                let _e1887 = local_174;
                                                                                                                if (_e1887 && (_e1885 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1889 = local_175;
                                                                                                                let _e1890 = local_172;
                                                                                                                let _e1891 = (_e1889 % _e1890);
                                                                                                                local_176 = _e1891;
                                                                                                                let _e1892 = local_160;
                                                                                                                if (_e1891 < _e1892) {
                                                                                                                    phi_1637_ = _e1891;
                                                                                                                } else {
                                                                                                                    let _e1894 = local_172;
                                                                                                                    let _e1896 = local_176;
                                                                                                                    phi_1637_ = ((_e1894 - 1i) - _e1896);
                                                                                                                }
                                                                                                                let _e1899 = phi_1637_;
                                                                                                                phi_1661_ = _e1899;
                                                                                                            } else {
                                                                                                                let _e1851 = local_160;
                                                                                                                let _e1852 = (_e1851 == 0i);
                                                                                                                local_177 = _e1852;
                                                                                                                if _e1852 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1853 = local_160;
                                                                                                                let _e1854 = (_e1853 == -1i);
                                                                                                                local_178 = _e1854;
                                                                                                                let _e1855 = local_171;
                                                                                                                if (_e1854 && (_e1855 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1858 = local_171;
                                                                                                                let _e1859 = local_160;
                                                                                                                let _e1861 = local_160;
                                                                                                                local_179 = ((_e1858 % _e1859) + _e1861);
                                                                                                                let _e1863 = local_177;
                                                                                                                if _e1863 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1864 = local_179;
                                                                                                                let _e1866 = local_178;
                                                                                                                if (_e1866 && (_e1864 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1868 = local_179;
                                                                                                                let _e1869 = local_160;
                                                                                                                phi_1661_ = (_e1868 % _e1869);
                                                                                                            }
                                                                                                            let _e1901 = phi_1661_;
                                                                                                            phi_1662_ = _e1901;
                                                                                                        }
                                                                                                        let _e1914 = phi_1662_;
                                                                                                        local_180 = bitcast<u32>(_e1914);
                                                                                                        let _e1916 = local_147;
                                                                                                        local_181 = _e1916.member_4;
                                                                                                        let _e1918 = local_151;
                                                                                                        local_182 = bitcast<i32>(_e1918);
                                                                                                        let _e1920 = (_e1916.member_4 == 1u);
                                                                                                        local_183 = _e1920;
                                                                                                        if _e1920 {
                                                                                                            let _e1974 = local_158;
                                                                                                            if (_e1974 < 0i) {
                                                                                                                phi_1681_ = 0i;
                                                                                                            } else {
                                                                                                                let _e1976 = local_158;
                                                                                                                let _e1977 = local_182;
                                                                                                                if (_e1976 >= _e1977) {
                                                                                                                    let _e1979 = local_182;
                                                                                                                    phi_1680_ = (_e1979 - 1i);
                                                                                                                } else {
                                                                                                                    phi_1680_ = _e1773;
                                                                                                                }
                                                                                                                let _e1982 = phi_1680_;
                                                                                                                phi_1681_ = _e1982;
                                                                                                            }
                                                                                                            let _e1984 = phi_1681_;
                                                                                                            phi_1741_ = _e1984;
                                                                                                        } else {
                                                                                                            let _e1921 = local_181;
                                                                                                            if (_e1921 == 2u) {
                                                                                                                let _e1943 = local_182;
                                                                                                                let _e1944 = (2i * _e1943);
                                                                                                                local_184 = _e1944;
                                                                                                                let _e1945 = (_e1944 == 0i);
                                                                                                                local_185 = _e1945;
                                                                                                                if _e1945 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1946 = local_184;
                                                                                                                let _e1947 = (_e1946 == -1i);
                                                                                                                local_186 = _e1947;
                                                                                                                let _e1948 = local_158;
                                                                                                                if (_e1947 && (_e1948 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1951 = local_158;
                                                                                                                let _e1952 = local_184;
                                                                                                                let _e1954 = local_184;
                                                                                                                local_187 = ((_e1951 % _e1952) + _e1954);
                                                                                                                let _e1956 = local_185;
                                                                                                                if _e1956 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1957 = local_187;
                                                                                                                let _e1959 = local_186;
                                                                                                                if (_e1959 && (_e1957 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1961 = local_187;
                                                                                                                let _e1962 = local_184;
                                                                                                                let _e1963 = (_e1961 % _e1962);
                                                                                                                local_188 = _e1963;
                                                                                                                let _e1964 = local_182;
                                                                                                                if (_e1963 < _e1964) {
                                                                                                                    phi_1716_ = _e1963;
                                                                                                                } else {
                                                                                                                    let _e1966 = local_184;
                                                                                                                    let _e1968 = local_188;
                                                                                                                    phi_1716_ = ((_e1966 - 1i) - _e1968);
                                                                                                                }
                                                                                                                let _e1971 = phi_1716_;
                                                                                                                phi_1740_ = _e1971;
                                                                                                            } else {
                                                                                                                let _e1923 = local_182;
                                                                                                                let _e1924 = (_e1923 == 0i);
                                                                                                                local_189 = _e1924;
                                                                                                                if _e1924 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1925 = local_182;
                                                                                                                let _e1926 = (_e1925 == -1i);
                                                                                                                local_190 = _e1926;
                                                                                                                let _e1927 = local_158;
                                                                                                                if (_e1926 && (_e1927 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1930 = local_158;
                                                                                                                let _e1931 = local_182;
                                                                                                                let _e1933 = local_182;
                                                                                                                local_191 = ((_e1930 % _e1931) + _e1933);
                                                                                                                let _e1935 = local_189;
                                                                                                                if _e1935 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1936 = local_191;
                                                                                                                let _e1938 = local_190;
                                                                                                                if (_e1938 && (_e1936 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1940 = local_191;
                                                                                                                let _e1941 = local_182;
                                                                                                                phi_1740_ = (_e1940 % _e1941);
                                                                                                            }
                                                                                                            let _e1973 = phi_1740_;
                                                                                                            phi_1741_ = _e1973;
                                                                                                        }
                                                                                                        let _e1986 = phi_1741_;
                                                                                                        local_192 = bitcast<u32>(_e1986);
                                                                                                        let _e1988 = local_158;
                                                                                                        let _e1989 = (_e1988 + 1i);
                                                                                                        local_193 = _e1989;
                                                                                                        let _e1990 = local_183;
                                                                                                        if _e1990 {
                                                                                                            let _e2044 = local_193;
                                                                                                            if (_e2044 < 0i) {
                                                                                                                phi_1761_ = 0i;
                                                                                                            } else {
                                                                                                                let _e2046 = local_193;
                                                                                                                let _e2047 = local_182;
                                                                                                                if (_e2046 >= _e2047) {
                                                                                                                    let _e2049 = local_182;
                                                                                                                    phi_1760_ = (_e2049 - 1i);
                                                                                                                } else {
                                                                                                                    phi_1760_ = _e1989;
                                                                                                                }
                                                                                                                let _e2052 = phi_1760_;
                                                                                                                phi_1761_ = _e2052;
                                                                                                            }
                                                                                                            let _e2054 = phi_1761_;
                                                                                                            phi_1821_ = _e2054;
                                                                                                        } else {
                                                                                                            let _e1991 = local_181;
                                                                                                            if (_e1991 == 2u) {
                                                                                                                let _e2013 = local_182;
                                                                                                                let _e2014 = (2i * _e2013);
                                                                                                                local_194 = _e2014;
                                                                                                                let _e2015 = (_e2014 == 0i);
                                                                                                                local_195 = _e2015;
                                                                                                                if _e2015 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2016 = local_194;
                                                                                                                let _e2017 = (_e2016 == -1i);
                                                                                                                local_196 = _e2017;
                                                                                                                let _e2018 = local_193;
                                                                                                                if (_e2017 && (_e2018 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2021 = local_193;
                                                                                                                let _e2022 = local_194;
                                                                                                                let _e2024 = local_194;
                                                                                                                local_197 = ((_e2021 % _e2022) + _e2024);
                                                                                                                let _e2026 = local_195;
                                                                                                                if _e2026 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2027 = local_197;
                                                                                                                let _e2029 = local_196;
                                                                                                                if (_e2029 && (_e2027 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2031 = local_197;
                                                                                                                let _e2032 = local_194;
                                                                                                                let _e2033 = (_e2031 % _e2032);
                                                                                                                local_198 = _e2033;
                                                                                                                let _e2034 = local_182;
                                                                                                                if (_e2033 < _e2034) {
                                                                                                                    phi_1796_ = _e2033;
                                                                                                                } else {
                                                                                                                    let _e2036 = local_194;
                                                                                                                    let _e2038 = local_198;
                                                                                                                    phi_1796_ = ((_e2036 - 1i) - _e2038);
                                                                                                                }
                                                                                                                let _e2041 = phi_1796_;
                                                                                                                phi_1820_ = _e2041;
                                                                                                            } else {
                                                                                                                let _e1993 = local_182;
                                                                                                                let _e1994 = (_e1993 == 0i);
                                                                                                                local_199 = _e1994;
                                                                                                                if _e1994 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e1995 = local_182;
                                                                                                                let _e1996 = (_e1995 == -1i);
                                                                                                                local_200 = _e1996;
                                                                                                                let _e1997 = local_193;
                                                                                                                if (_e1996 && (_e1997 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2000 = local_193;
                                                                                                                let _e2001 = local_182;
                                                                                                                let _e2003 = local_182;
                                                                                                                local_201 = ((_e2000 % _e2001) + _e2003);
                                                                                                                let _e2005 = local_199;
                                                                                                                if _e2005 {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2006 = local_201;
                                                                                                                let _e2008 = local_200;
                                                                                                                if (_e2008 && (_e2006 == i32(-2147483648))) {
                                                                                                                    phi_3210_ = true;
                                                                                                                    break;
                                                                                                                }
                                                                                                                let _e2010 = local_201;
                                                                                                                let _e2011 = local_182;
                                                                                                                phi_1820_ = (_e2010 % _e2011);
                                                                                                            }
                                                                                                            let _e2043 = phi_1820_;
                                                                                                            phi_1821_ = _e2043;
                                                                                                        }
                                                                                                        let _e2056 = phi_1821_;
                                                                                                        local_202 = bitcast<u32>(_e2056);
                                                                                                        let _e2058 = local_147;
                                                                                                        local_203 = _e2058.member;
                                                                                                        let _e2060 = local_192;
                                                                                                        let _e2061 = local_149;
                                                                                                        let _e2063 = (_e2058.member + (_e2060 * _e2061));
                                                                                                        local_204 = _e2063;
                                                                                                        let _e2064 = local_170;
                                                                                                        let _e2066 = ((_e2063 + _e2064) * 2u);
                                                                                                        local_205 = _e2066;
                                                                                                        let _e2067 = local_5;
                                                                                                        if (_e2066 < _e2067) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2069 = local_205;
                                                                                                        let _e2072 = global_8.member[_e2069];
                                                                                                        local_206 = _e2072;
                                                                                                        let _e2073 = local_205;
                                                                                                        let _e2074 = (_e2073 + 1u);
                                                                                                        local_207 = _e2074;
                                                                                                        let _e2075 = local_5;
                                                                                                        if (_e2074 < _e2075) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2077 = local_207;
                                                                                                        let _e2080 = global_8.member[_e2077];
                                                                                                        local_208 = _e2080;
                                                                                                        let _e2081 = local_206;
                                                                                                        let _e2082 = (_e2081 & 65535u);
                                                                                                        local_309 = select(-1f, 1f, ((_e2082 & 32768u) == 0u));
                                                                                                        let _e2088 = ((_e2082 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_209 = _e2088;
                                                                                                        local_210 = (_e2082 & 1023u);
                                                                                                        if (_e2088 == 0u) {
                                                                                                            let _e2110 = local_210;
                                                                                                            let _e2112 = local_309;
                                                                                                            phi_1875_ = ((_e2112 * f32(_e2110)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2091 = local_209;
                                                                                                            if (_e2091 == 31u) {
                                                                                                                let _e2101 = local_210;
                                                                                                                phi_1872_ = (2139095040u | (_e2101 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2093 = local_209;
                                                                                                                let _e2097 = local_210;
                                                                                                                phi_1872_ = (((_e2093 + 112u) << bitcast<u32>(23i)) | (_e2097 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2106 = phi_1872_;
                                                                                                            let _e2108 = local_309;
                                                                                                            phi_1875_ = (_e2108 * bitcast<f32>(_e2106));
                                                                                                        }
                                                                                                        let _e2116 = phi_1875_;
                                                                                                        local_211 = _e2116;
                                                                                                        let _e2117 = local_206;
                                                                                                        let _e2119 = (_e2117 >> bitcast<u32>(16i));
                                                                                                        local_310 = select(-1f, 1f, ((_e2119 & 32768u) == 0u));
                                                                                                        let _e2125 = ((_e2119 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_212 = _e2125;
                                                                                                        local_213 = (_e2119 & 1023u);
                                                                                                        if (_e2125 == 0u) {
                                                                                                            let _e2147 = local_213;
                                                                                                            let _e2149 = local_310;
                                                                                                            phi_1907_ = ((_e2149 * f32(_e2147)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2128 = local_212;
                                                                                                            if (_e2128 == 31u) {
                                                                                                                let _e2138 = local_213;
                                                                                                                phi_1904_ = (2139095040u | (_e2138 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2130 = local_212;
                                                                                                                let _e2134 = local_213;
                                                                                                                phi_1904_ = (((_e2130 + 112u) << bitcast<u32>(23i)) | (_e2134 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2143 = phi_1904_;
                                                                                                            let _e2145 = local_310;
                                                                                                            phi_1907_ = (_e2145 * bitcast<f32>(_e2143));
                                                                                                        }
                                                                                                        let _e2153 = phi_1907_;
                                                                                                        local_214 = _e2153;
                                                                                                        let _e2154 = local_208;
                                                                                                        let _e2155 = (_e2154 & 65535u);
                                                                                                        local_311 = select(-1f, 1f, ((_e2155 & 32768u) == 0u));
                                                                                                        let _e2161 = ((_e2155 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_215 = _e2161;
                                                                                                        local_216 = (_e2155 & 1023u);
                                                                                                        if (_e2161 == 0u) {
                                                                                                            let _e2183 = local_216;
                                                                                                            let _e2185 = local_311;
                                                                                                            phi_1939_ = ((_e2185 * f32(_e2183)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2164 = local_215;
                                                                                                            if (_e2164 == 31u) {
                                                                                                                let _e2174 = local_216;
                                                                                                                phi_1936_ = (2139095040u | (_e2174 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2166 = local_215;
                                                                                                                let _e2170 = local_216;
                                                                                                                phi_1936_ = (((_e2166 + 112u) << bitcast<u32>(23i)) | (_e2170 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2179 = phi_1936_;
                                                                                                            let _e2181 = local_311;
                                                                                                            phi_1939_ = (_e2181 * bitcast<f32>(_e2179));
                                                                                                        }
                                                                                                        let _e2189 = phi_1939_;
                                                                                                        local_217 = _e2189;
                                                                                                        let _e2190 = local_208;
                                                                                                        let _e2192 = (_e2190 >> bitcast<u32>(16i));
                                                                                                        local_312 = select(-1f, 1f, ((_e2192 & 32768u) == 0u));
                                                                                                        let _e2198 = ((_e2192 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_218 = _e2198;
                                                                                                        local_219 = (_e2192 & 1023u);
                                                                                                        if (_e2198 == 0u) {
                                                                                                            let _e2220 = local_219;
                                                                                                            let _e2222 = local_312;
                                                                                                            phi_1971_ = ((_e2222 * f32(_e2220)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2201 = local_218;
                                                                                                            if (_e2201 == 31u) {
                                                                                                                let _e2211 = local_219;
                                                                                                                phi_1968_ = (2139095040u | (_e2211 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2203 = local_218;
                                                                                                                let _e2207 = local_219;
                                                                                                                phi_1968_ = (((_e2203 + 112u) << bitcast<u32>(23i)) | (_e2207 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2216 = phi_1968_;
                                                                                                            let _e2218 = local_312;
                                                                                                            phi_1971_ = (_e2218 * bitcast<f32>(_e2216));
                                                                                                        }
                                                                                                        let _e2226 = phi_1971_;
                                                                                                        local_220 = _e2226;
                                                                                                        let _e2227 = local_204;
                                                                                                        let _e2228 = local_180;
                                                                                                        let _e2230 = ((_e2227 + _e2228) * 2u);
                                                                                                        local_221 = _e2230;
                                                                                                        let _e2231 = local_5;
                                                                                                        if (_e2230 < _e2231) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2233 = local_221;
                                                                                                        let _e2236 = global_8.member[_e2233];
                                                                                                        local_222 = _e2236;
                                                                                                        let _e2237 = local_221;
                                                                                                        let _e2238 = (_e2237 + 1u);
                                                                                                        local_223 = _e2238;
                                                                                                        let _e2239 = local_5;
                                                                                                        if (_e2238 < _e2239) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2241 = local_223;
                                                                                                        let _e2244 = global_8.member[_e2241];
                                                                                                        local_224 = _e2244;
                                                                                                        let _e2245 = local_222;
                                                                                                        let _e2246 = (_e2245 & 65535u);
                                                                                                        local_313 = select(-1f, 1f, ((_e2246 & 32768u) == 0u));
                                                                                                        let _e2252 = ((_e2246 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_225 = _e2252;
                                                                                                        local_226 = (_e2246 & 1023u);
                                                                                                        if (_e2252 == 0u) {
                                                                                                            let _e2274 = local_226;
                                                                                                            let _e2276 = local_313;
                                                                                                            phi_2024_ = ((_e2276 * f32(_e2274)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2255 = local_225;
                                                                                                            if (_e2255 == 31u) {
                                                                                                                let _e2265 = local_226;
                                                                                                                phi_2021_ = (2139095040u | (_e2265 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2257 = local_225;
                                                                                                                let _e2261 = local_226;
                                                                                                                phi_2021_ = (((_e2257 + 112u) << bitcast<u32>(23i)) | (_e2261 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2270 = phi_2021_;
                                                                                                            let _e2272 = local_313;
                                                                                                            phi_2024_ = (_e2272 * bitcast<f32>(_e2270));
                                                                                                        }
                                                                                                        let _e2280 = phi_2024_;
                                                                                                        local_227 = _e2280;
                                                                                                        let _e2281 = local_222;
                                                                                                        let _e2283 = (_e2281 >> bitcast<u32>(16i));
                                                                                                        local_314 = select(-1f, 1f, ((_e2283 & 32768u) == 0u));
                                                                                                        let _e2289 = ((_e2283 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_228 = _e2289;
                                                                                                        local_229 = (_e2283 & 1023u);
                                                                                                        if (_e2289 == 0u) {
                                                                                                            let _e2311 = local_229;
                                                                                                            let _e2313 = local_314;
                                                                                                            phi_2056_ = ((_e2313 * f32(_e2311)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2292 = local_228;
                                                                                                            if (_e2292 == 31u) {
                                                                                                                let _e2302 = local_229;
                                                                                                                phi_2053_ = (2139095040u | (_e2302 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2294 = local_228;
                                                                                                                let _e2298 = local_229;
                                                                                                                phi_2053_ = (((_e2294 + 112u) << bitcast<u32>(23i)) | (_e2298 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2307 = phi_2053_;
                                                                                                            let _e2309 = local_314;
                                                                                                            phi_2056_ = (_e2309 * bitcast<f32>(_e2307));
                                                                                                        }
                                                                                                        let _e2317 = phi_2056_;
                                                                                                        local_230 = _e2317;
                                                                                                        let _e2318 = local_224;
                                                                                                        let _e2319 = (_e2318 & 65535u);
                                                                                                        local_315 = select(-1f, 1f, ((_e2319 & 32768u) == 0u));
                                                                                                        let _e2325 = ((_e2319 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_231 = _e2325;
                                                                                                        local_232 = (_e2319 & 1023u);
                                                                                                        if (_e2325 == 0u) {
                                                                                                            let _e2347 = local_232;
                                                                                                            let _e2349 = local_315;
                                                                                                            phi_2088_ = ((_e2349 * f32(_e2347)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2328 = local_231;
                                                                                                            if (_e2328 == 31u) {
                                                                                                                let _e2338 = local_232;
                                                                                                                phi_2085_ = (2139095040u | (_e2338 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2330 = local_231;
                                                                                                                let _e2334 = local_232;
                                                                                                                phi_2085_ = (((_e2330 + 112u) << bitcast<u32>(23i)) | (_e2334 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2343 = phi_2085_;
                                                                                                            let _e2345 = local_315;
                                                                                                            phi_2088_ = (_e2345 * bitcast<f32>(_e2343));
                                                                                                        }
                                                                                                        let _e2353 = phi_2088_;
                                                                                                        local_233 = _e2353;
                                                                                                        let _e2354 = local_224;
                                                                                                        let _e2356 = (_e2354 >> bitcast<u32>(16i));
                                                                                                        local_316 = select(-1f, 1f, ((_e2356 & 32768u) == 0u));
                                                                                                        let _e2362 = ((_e2356 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_234 = _e2362;
                                                                                                        local_235 = (_e2356 & 1023u);
                                                                                                        if (_e2362 == 0u) {
                                                                                                            let _e2384 = local_235;
                                                                                                            let _e2386 = local_316;
                                                                                                            phi_2120_ = ((_e2386 * f32(_e2384)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2365 = local_234;
                                                                                                            if (_e2365 == 31u) {
                                                                                                                let _e2375 = local_235;
                                                                                                                phi_2117_ = (2139095040u | (_e2375 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2367 = local_234;
                                                                                                                let _e2371 = local_235;
                                                                                                                phi_2117_ = (((_e2367 + 112u) << bitcast<u32>(23i)) | (_e2371 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2380 = phi_2117_;
                                                                                                            let _e2382 = local_316;
                                                                                                            phi_2120_ = (_e2382 * bitcast<f32>(_e2380));
                                                                                                        }
                                                                                                        let _e2390 = phi_2120_;
                                                                                                        let _e2391 = local_227;
                                                                                                        let _e2392 = local_211;
                                                                                                        let _e2394 = local_156;
                                                                                                        let _e2396 = local_211;
                                                                                                        local_236 = (_e2396 + ((_e2391 - _e2392) * _e2394));
                                                                                                        let _e2398 = local_230;
                                                                                                        let _e2399 = local_214;
                                                                                                        let _e2401 = local_156;
                                                                                                        let _e2403 = local_214;
                                                                                                        local_237 = (_e2403 + ((_e2398 - _e2399) * _e2401));
                                                                                                        let _e2405 = local_233;
                                                                                                        let _e2406 = local_217;
                                                                                                        let _e2408 = local_156;
                                                                                                        let _e2410 = local_217;
                                                                                                        local_238 = (_e2410 + ((_e2405 - _e2406) * _e2408));
                                                                                                        let _e2412 = local_220;
                                                                                                        let _e2414 = local_156;
                                                                                                        let _e2416 = local_220;
                                                                                                        local_239 = (_e2416 + ((_e2390 - _e2412) * _e2414));
                                                                                                        let _e2418 = local_202;
                                                                                                        let _e2419 = local_149;
                                                                                                        let _e2421 = local_203;
                                                                                                        let _e2422 = (_e2421 + (_e2418 * _e2419));
                                                                                                        local_240 = _e2422;
                                                                                                        let _e2423 = local_170;
                                                                                                        let _e2425 = ((_e2422 + _e2423) * 2u);
                                                                                                        local_241 = _e2425;
                                                                                                        let _e2426 = local_5;
                                                                                                        if (_e2425 < _e2426) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2428 = local_241;
                                                                                                        let _e2431 = global_8.member[_e2428];
                                                                                                        local_242 = _e2431;
                                                                                                        let _e2432 = local_241;
                                                                                                        let _e2433 = (_e2432 + 1u);
                                                                                                        local_243 = _e2433;
                                                                                                        let _e2434 = local_5;
                                                                                                        if (_e2433 < _e2434) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2436 = local_243;
                                                                                                        let _e2439 = global_8.member[_e2436];
                                                                                                        local_244 = _e2439;
                                                                                                        let _e2440 = local_242;
                                                                                                        let _e2441 = (_e2440 & 65535u);
                                                                                                        local_317 = select(-1f, 1f, ((_e2441 & 32768u) == 0u));
                                                                                                        let _e2447 = ((_e2441 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_245 = _e2447;
                                                                                                        local_246 = (_e2441 & 1023u);
                                                                                                        if (_e2447 == 0u) {
                                                                                                            let _e2469 = local_246;
                                                                                                            let _e2471 = local_317;
                                                                                                            phi_2185_ = ((_e2471 * f32(_e2469)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2450 = local_245;
                                                                                                            if (_e2450 == 31u) {
                                                                                                                let _e2460 = local_246;
                                                                                                                phi_2182_ = (2139095040u | (_e2460 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2452 = local_245;
                                                                                                                let _e2456 = local_246;
                                                                                                                phi_2182_ = (((_e2452 + 112u) << bitcast<u32>(23i)) | (_e2456 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2465 = phi_2182_;
                                                                                                            let _e2467 = local_317;
                                                                                                            phi_2185_ = (_e2467 * bitcast<f32>(_e2465));
                                                                                                        }
                                                                                                        let _e2475 = phi_2185_;
                                                                                                        local_247 = _e2475;
                                                                                                        let _e2476 = local_242;
                                                                                                        let _e2478 = (_e2476 >> bitcast<u32>(16i));
                                                                                                        local_318 = select(-1f, 1f, ((_e2478 & 32768u) == 0u));
                                                                                                        let _e2484 = ((_e2478 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_248 = _e2484;
                                                                                                        local_249 = (_e2478 & 1023u);
                                                                                                        if (_e2484 == 0u) {
                                                                                                            let _e2506 = local_249;
                                                                                                            let _e2508 = local_318;
                                                                                                            phi_2217_ = ((_e2508 * f32(_e2506)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2487 = local_248;
                                                                                                            if (_e2487 == 31u) {
                                                                                                                let _e2497 = local_249;
                                                                                                                phi_2214_ = (2139095040u | (_e2497 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2489 = local_248;
                                                                                                                let _e2493 = local_249;
                                                                                                                phi_2214_ = (((_e2489 + 112u) << bitcast<u32>(23i)) | (_e2493 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2502 = phi_2214_;
                                                                                                            let _e2504 = local_318;
                                                                                                            phi_2217_ = (_e2504 * bitcast<f32>(_e2502));
                                                                                                        }
                                                                                                        let _e2512 = phi_2217_;
                                                                                                        local_250 = _e2512;
                                                                                                        let _e2513 = local_244;
                                                                                                        let _e2514 = (_e2513 & 65535u);
                                                                                                        local_319 = select(-1f, 1f, ((_e2514 & 32768u) == 0u));
                                                                                                        let _e2520 = ((_e2514 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_251 = _e2520;
                                                                                                        local_252 = (_e2514 & 1023u);
                                                                                                        if (_e2520 == 0u) {
                                                                                                            let _e2542 = local_252;
                                                                                                            let _e2544 = local_319;
                                                                                                            phi_2249_ = ((_e2544 * f32(_e2542)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2523 = local_251;
                                                                                                            if (_e2523 == 31u) {
                                                                                                                let _e2533 = local_252;
                                                                                                                phi_2246_ = (2139095040u | (_e2533 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2525 = local_251;
                                                                                                                let _e2529 = local_252;
                                                                                                                phi_2246_ = (((_e2525 + 112u) << bitcast<u32>(23i)) | (_e2529 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2538 = phi_2246_;
                                                                                                            let _e2540 = local_319;
                                                                                                            phi_2249_ = (_e2540 * bitcast<f32>(_e2538));
                                                                                                        }
                                                                                                        let _e2548 = phi_2249_;
                                                                                                        local_253 = _e2548;
                                                                                                        let _e2549 = local_244;
                                                                                                        let _e2551 = (_e2549 >> bitcast<u32>(16i));
                                                                                                        local_320 = select(-1f, 1f, ((_e2551 & 32768u) == 0u));
                                                                                                        let _e2557 = ((_e2551 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_254 = _e2557;
                                                                                                        local_255 = (_e2551 & 1023u);
                                                                                                        if (_e2557 == 0u) {
                                                                                                            let _e2579 = local_255;
                                                                                                            let _e2581 = local_320;
                                                                                                            phi_2281_ = ((_e2581 * f32(_e2579)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2560 = local_254;
                                                                                                            if (_e2560 == 31u) {
                                                                                                                let _e2570 = local_255;
                                                                                                                phi_2278_ = (2139095040u | (_e2570 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2562 = local_254;
                                                                                                                let _e2566 = local_255;
                                                                                                                phi_2278_ = (((_e2562 + 112u) << bitcast<u32>(23i)) | (_e2566 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2575 = phi_2278_;
                                                                                                            let _e2577 = local_320;
                                                                                                            phi_2281_ = (_e2577 * bitcast<f32>(_e2575));
                                                                                                        }
                                                                                                        let _e2585 = phi_2281_;
                                                                                                        local_256 = _e2585;
                                                                                                        let _e2586 = local_240;
                                                                                                        let _e2587 = local_180;
                                                                                                        let _e2589 = ((_e2586 + _e2587) * 2u);
                                                                                                        local_257 = _e2589;
                                                                                                        let _e2590 = local_5;
                                                                                                        if (_e2589 < _e2590) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2592 = local_257;
                                                                                                        let _e2595 = global_8.member[_e2592];
                                                                                                        local_258 = _e2595;
                                                                                                        let _e2596 = local_257;
                                                                                                        let _e2597 = (_e2596 + 1u);
                                                                                                        local_259 = _e2597;
                                                                                                        let _e2598 = local_5;
                                                                                                        if (_e2597 < _e2598) {
                                                                                                        } else {
                                                                                                            phi_3210_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e2600 = local_259;
                                                                                                        let _e2603 = global_8.member[_e2600];
                                                                                                        local_260 = _e2603;
                                                                                                        let _e2604 = local_258;
                                                                                                        let _e2605 = (_e2604 & 65535u);
                                                                                                        local_321 = select(-1f, 1f, ((_e2605 & 32768u) == 0u));
                                                                                                        let _e2611 = ((_e2605 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_261 = _e2611;
                                                                                                        local_262 = (_e2605 & 1023u);
                                                                                                        if (_e2611 == 0u) {
                                                                                                            let _e2633 = local_262;
                                                                                                            let _e2635 = local_321;
                                                                                                            phi_2334_ = ((_e2635 * f32(_e2633)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2614 = local_261;
                                                                                                            if (_e2614 == 31u) {
                                                                                                                let _e2624 = local_262;
                                                                                                                phi_2331_ = (2139095040u | (_e2624 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2616 = local_261;
                                                                                                                let _e2620 = local_262;
                                                                                                                phi_2331_ = (((_e2616 + 112u) << bitcast<u32>(23i)) | (_e2620 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2629 = phi_2331_;
                                                                                                            let _e2631 = local_321;
                                                                                                            phi_2334_ = (_e2631 * bitcast<f32>(_e2629));
                                                                                                        }
                                                                                                        let _e2639 = phi_2334_;
                                                                                                        local_263 = _e2639;
                                                                                                        let _e2640 = local_258;
                                                                                                        let _e2642 = (_e2640 >> bitcast<u32>(16i));
                                                                                                        local_322 = select(-1f, 1f, ((_e2642 & 32768u) == 0u));
                                                                                                        let _e2648 = ((_e2642 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_264 = _e2648;
                                                                                                        local_265 = (_e2642 & 1023u);
                                                                                                        if (_e2648 == 0u) {
                                                                                                            let _e2670 = local_265;
                                                                                                            let _e2672 = local_322;
                                                                                                            phi_2366_ = ((_e2672 * f32(_e2670)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2651 = local_264;
                                                                                                            if (_e2651 == 31u) {
                                                                                                                let _e2661 = local_265;
                                                                                                                phi_2363_ = (2139095040u | (_e2661 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2653 = local_264;
                                                                                                                let _e2657 = local_265;
                                                                                                                phi_2363_ = (((_e2653 + 112u) << bitcast<u32>(23i)) | (_e2657 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2666 = phi_2363_;
                                                                                                            let _e2668 = local_322;
                                                                                                            phi_2366_ = (_e2668 * bitcast<f32>(_e2666));
                                                                                                        }
                                                                                                        let _e2676 = phi_2366_;
                                                                                                        local_266 = _e2676;
                                                                                                        let _e2677 = local_260;
                                                                                                        let _e2678 = (_e2677 & 65535u);
                                                                                                        local_323 = select(-1f, 1f, ((_e2678 & 32768u) == 0u));
                                                                                                        let _e2684 = ((_e2678 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_267 = _e2684;
                                                                                                        local_268 = (_e2678 & 1023u);
                                                                                                        if (_e2684 == 0u) {
                                                                                                            let _e2706 = local_268;
                                                                                                            let _e2708 = local_323;
                                                                                                            phi_2398_ = ((_e2708 * f32(_e2706)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2687 = local_267;
                                                                                                            if (_e2687 == 31u) {
                                                                                                                let _e2697 = local_268;
                                                                                                                phi_2395_ = (2139095040u | (_e2697 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2689 = local_267;
                                                                                                                let _e2693 = local_268;
                                                                                                                phi_2395_ = (((_e2689 + 112u) << bitcast<u32>(23i)) | (_e2693 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2702 = phi_2395_;
                                                                                                            let _e2704 = local_323;
                                                                                                            phi_2398_ = (_e2704 * bitcast<f32>(_e2702));
                                                                                                        }
                                                                                                        let _e2712 = phi_2398_;
                                                                                                        local_269 = _e2712;
                                                                                                        let _e2713 = local_260;
                                                                                                        let _e2715 = (_e2713 >> bitcast<u32>(16i));
                                                                                                        local_324 = select(-1f, 1f, ((_e2715 & 32768u) == 0u));
                                                                                                        let _e2721 = ((_e2715 >> bitcast<u32>(10i)) & 31u);
                                                                                                        local_270 = _e2721;
                                                                                                        local_271 = (_e2715 & 1023u);
                                                                                                        if (_e2721 == 0u) {
                                                                                                            let _e2743 = local_271;
                                                                                                            let _e2745 = local_324;
                                                                                                            phi_2430_ = ((_e2745 * f32(_e2743)) * 0.000000059604645f);
                                                                                                        } else {
                                                                                                            let _e2724 = local_270;
                                                                                                            if (_e2724 == 31u) {
                                                                                                                let _e2734 = local_271;
                                                                                                                phi_2427_ = (2139095040u | (_e2734 << bitcast<u32>(13i)));
                                                                                                            } else {
                                                                                                                let _e2726 = local_270;
                                                                                                                let _e2730 = local_271;
                                                                                                                phi_2427_ = (((_e2726 + 112u) << bitcast<u32>(23i)) | (_e2730 << bitcast<u32>(13i)));
                                                                                                            }
                                                                                                            let _e2739 = phi_2427_;
                                                                                                            let _e2741 = local_324;
                                                                                                            phi_2430_ = (_e2741 * bitcast<f32>(_e2739));
                                                                                                        }
                                                                                                        let _e2749 = phi_2430_;
                                                                                                        let _e2750 = local_263;
                                                                                                        let _e2751 = local_247;
                                                                                                        let _e2753 = local_156;
                                                                                                        let _e2755 = local_247;
                                                                                                        let _e2757 = local_266;
                                                                                                        let _e2758 = local_250;
                                                                                                        let _e2760 = local_156;
                                                                                                        let _e2762 = local_250;
                                                                                                        let _e2764 = local_269;
                                                                                                        let _e2765 = local_253;
                                                                                                        let _e2767 = local_156;
                                                                                                        let _e2769 = local_253;
                                                                                                        let _e2771 = local_256;
                                                                                                        let _e2773 = local_156;
                                                                                                        let _e2775 = local_256;
                                                                                                        let _e2777 = local_236;
                                                                                                        let _e2779 = local_155;
                                                                                                        let _e2781 = local_236;
                                                                                                        let _e2783 = local_237;
                                                                                                        let _e2785 = local_155;
                                                                                                        let _e2787 = local_237;
                                                                                                        let _e2789 = local_238;
                                                                                                        let _e2791 = local_155;
                                                                                                        let _e2793 = local_238;
                                                                                                        let _e2795 = local_239;
                                                                                                        let _e2797 = local_155;
                                                                                                        let _e2799 = local_239;
                                                                                                        let _e2801 = local_148;
                                                                                                        let _e2803 = local_148;
                                                                                                        let _e2805 = local_148;
                                                                                                        let _e2807 = local_148;
                                                                                                        let _e2809 = local_145;
                                                                                                        let _e2812 = local_145;
                                                                                                        let _e2815 = local_145;
                                                                                                        let _e2818 = local_145;
                                                                                                        let _e2822 = local_144;
                                                                                                        phi_1449_ = (_e2822 + 1u);
                                                                                                        phi_1452_ = type_5((_e2809.member + ((_e2781 + (((_e2755 + ((_e2750 - _e2751) * _e2753)) - _e2777) * _e2779)) * _e2801)), (_e2812.member_1 + ((_e2787 + (((_e2762 + ((_e2757 - _e2758) * _e2760)) - _e2783) * _e2785)) * _e2803)), (_e2815.member_2 + ((_e2793 + (((_e2769 + ((_e2764 - _e2765) * _e2767)) - _e2789) * _e2791)) * _e2805)), (_e2818.member_3 + ((_e2799 + (((_e2775 + ((_e2749 - _e2771) * _e2773)) - _e2795) * _e2797)) * _e2807)));
                                                                                                    } else {
                                                                                                        phi_1449_ = u32();
                                                                                                        phi_1452_ = type_5();
                                                                                                    }
                                                                                                    let _e2825 = phi_1449_;
                                                                                                    let _e2827 = phi_1452_;
                                                                                                    continue;
                                                                                                    continuing {
                                                                                                        let _e2828 = local_146;
                                                                                                        phi_1448_ = _e2825;
                                                                                                        phi_1451_ = _e2827;
                                                                                                        phi_3210_ = _e1703;
                                                                                                        break if !(_e2828);
                                                                                                    }
                                                                                                }
                                                                                                let _e2831 = phi_3210_;
                                                                                                phi_3316_ = _e2831;
                                                                                                if _e2831 {
                                                                                                    break;
                                                                                                }
                                                                                                let _e2832 = local_142;
                                                                                                phi_3317_ = _e2831;
                                                                                                phi_1420_ = (_e2832 + 1u);
                                                                                                let _e3130 = local_331;
                                                                                                phi_1423_ = _e3130;
                                                                                            } else {
                                                                                                phi_3317_ = _e1703;
                                                                                                phi_1420_ = u32();
                                                                                                phi_1423_ = type_5();
                                                                                            }
                                                                                            let _e2835 = phi_3317_;
                                                                                            let _e2837 = phi_1420_;
                                                                                            let _e2839 = phi_1423_;
                                                                                            continue;
                                                                                            continuing {
                                                                                                let _e2840 = local_143;
                                                                                                phi_3256_ = _e2835;
                                                                                                phi_1419_ = _e2837;
                                                                                                phi_1422_ = _e2839;
                                                                                                phi_3316_ = _e2835;
                                                                                                break if !(_e2840);
                                                                                            }
                                                                                        }
                                                                                        let _e2843 = phi_3316_;
                                                                                        phi_3318_ = _e2843;
                                                                                        if _e2843 {
                                                                                            break;
                                                                                        }
                                                                                        let _e2844 = local_139;
                                                                                        phi_3319_ = _e2843;
                                                                                        phi_1403_ = (_e2844 + 1u);
                                                                                        let _e3136 = local_332;
                                                                                        phi_1406_ = _e3136;
                                                                                    } else {
                                                                                        phi_3319_ = _e1695;
                                                                                        phi_1403_ = u32();
                                                                                        phi_1406_ = type_5();
                                                                                    }
                                                                                    let _e2847 = phi_3319_;
                                                                                    let _e2849 = phi_1403_;
                                                                                    let _e2851 = phi_1406_;
                                                                                    continue;
                                                                                    continuing {
                                                                                        let _e2852 = local_141;
                                                                                        phi_3257_ = _e2847;
                                                                                        phi_1402_ = _e2849;
                                                                                        phi_1405_ = _e2851;
                                                                                        phi_3318_ = _e2847;
                                                                                        break if !(_e2852);
                                                                                    }
                                                                                }
                                                                                let _e2855 = phi_3318_;
                                                                                phi_3320_ = _e2855;
                                                                                if _e2855 {
                                                                                    break;
                                                                                }
                                                                                let _e2856 = local_140;
                                                                                let _e2858 = local_140;
                                                                                let _e2860 = local_140;
                                                                                let _e2862 = local_140;
                                                                                phi_3341_ = _e2855;
                                                                                let _e3141 = local_333;
                                                                                phi_2483_ = _e3141;
                                                                            }
                                                                            let _e2865 = phi_3341_;
                                                                            let _e2867 = phi_2483_;
                                                                            phi_3340_ = _e2865;
                                                                            phi_2484_ = _e2867;
                                                                            phi_2485_ = _e1513;
                                                                        }
                                                                        let _e2869 = phi_3340_;
                                                                        let _e2871 = phi_2484_;
                                                                        let _e2873 = phi_2485_;
                                                                        if _e2873 {
                                                                            phi_2489_ = type_5(1f, 1f, 1f, 1f);
                                                                        } else {
                                                                            phi_2489_ = _e2871;
                                                                        }
                                                                        let _e2875 = phi_2489_;
                                                                        phi_3338_ = _e2869;
                                                                        phi_2490_ = _e2875;
                                                                    }
                                                                    let _e2877 = phi_3338_;
                                                                    let _e2879 = phi_2490_;
                                                                    phi_3337_ = _e2877;
                                                                    phi_2491_ = _e2879;
                                                                    phi_2492_ = _e1477;
                                                                }
                                                                let _e2881 = phi_3337_;
                                                                let _e2883 = phi_2491_;
                                                                let _e2885 = phi_2492_;
                                                                if _e2885 {
                                                                    phi_2496_ = type_5(1f, 1f, 1f, 1f);
                                                                } else {
                                                                    phi_2496_ = _e2883;
                                                                }
                                                                let _e2887 = phi_2496_;
                                                                let _e2889 = local_123;
                                                                let _e2891 = local_110;
                                                                local_272 = ((_e2889 * _e2887.member_3) * _e2891);
                                                                let _e2893 = local_84;
                                                                if ((_e2893 & 4u) == 0u) {
                                                                    let _e2907 = local_272;
                                                                    phi_2517_ = (_e2907 > 0f);
                                                                } else {
                                                                    let _e2896 = local_82;
                                                                    let _e2897 = (_e2896 + 7u);
                                                                    local_273 = _e2897;
                                                                    let _e2898 = local_3;
                                                                    if (_e2897 < _e2898) {
                                                                    } else {
                                                                        phi_3320_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2900 = local_273;
                                                                    let _e2903 = global_5.member[_e2900];
                                                                    let _e2905 = local_272;
                                                                    phi_2517_ = (_e2905 >= bitcast<f32>(_e2903));
                                                                }
                                                                let _e2910 = phi_2517_;
                                                                phi_3334_ = _e2881;
                                                                phi_2518_ = _e2910;
                                                            }
                                                            let _e2912 = phi_3334_;
                                                            let _e2914 = phi_2518_;
                                                            phi_3333_ = _e2912;
                                                            phi_2519_ = _e2914;
                                                        } else {
                                                            phi_3333_ = _e434;
                                                            phi_2519_ = bool();
                                                        }
                                                        let _e2916 = phi_3333_;
                                                        let _e2918 = phi_2519_;
                                                        let _e2919 = local_81;
                                                        phi_3332_ = _e2916;
                                                        phi_2521_ = _e2918;
                                                        phi_2522_ = select(true, false, _e2919);
                                                    } else {
                                                        phi_3332_ = _e434;
                                                        phi_2521_ = bool();
                                                        phi_2522_ = true;
                                                    }
                                                    let _e2922 = phi_3332_;
                                                    let _e2924 = phi_2521_;
                                                    let _e2926 = phi_2522_;
                                                    if select(_e2924, false, _e2926) {
                                                        let _e2928 = local_13;
                                                        local_274 = bitcast<u32>(f32((_e2928 + 1u)));
                                                        let _e2932 = local_79;
                                                        if _e2932 {
                                                        } else {
                                                            phi_3320_ = true;
                                                            break;
                                                        }
                                                        let _e2933 = local_274;
                                                        global_11.member[_e1103] = _e2933;
                                                        let _e2934 = local_78;
                                                        let _e2935 = (_e2934 + 1u);
                                                        local_275 = _e2935;
                                                        let _e2936 = local_76;
                                                        local_276 = bitcast<u32>(_e2936);
                                                        let _e2938 = local_8;
                                                        if (_e2935 < _e2938) {
                                                        } else {
                                                            phi_3320_ = true;
                                                            break;
                                                        }
                                                        let _e2940 = local_275;
                                                        let _e2943 = local_276;
                                                        global_11.member[_e2940] = _e2943;
                                                        let _e2944 = local_78;
                                                        let _e2945 = (_e2944 + 2u);
                                                        local_277 = _e2945;
                                                        let _e2946 = local_74;
                                                        local_278 = bitcast<u32>(_e2946);
                                                        let _e2948 = local_8;
                                                        if (_e2945 < _e2948) {
                                                        } else {
                                                            phi_3320_ = true;
                                                            break;
                                                        }
                                                        let _e2950 = local_277;
                                                        let _e2953 = local_278;
                                                        global_11.member[_e2950] = _e2953;
                                                        let _e2954 = local_78;
                                                        let _e2955 = (_e2954 + 3u);
                                                        local_279 = _e2955;
                                                        let _e2956 = local_75;
                                                        local_280 = bitcast<u32>(_e2956);
                                                        let _e2958 = local_8;
                                                        if (_e2955 < _e2958) {
                                                        } else {
                                                            phi_3320_ = true;
                                                            break;
                                                        }
                                                        let _e2960 = local_279;
                                                        let _e2963 = local_280;
                                                        global_11.member[_e2960] = _e2963;
                                                    }
                                                    phi_3329_ = _e2922;
                                                } else {
                                                    phi_3329_ = _e434;
                                                }
                                                let _e2965 = phi_3329_;
                                                phi_3328_ = _e2965;
                                            }
                                            let _e2967 = phi_3328_;
                                            phi_3327_ = _e2967;
                                        }
                                        let _e2969 = phi_3327_;
                                        phi_3326_ = _e2969;
                                    }
                                    let _e2971 = phi_3326_;
                                    storageBarrier();
                                    workgroupBarrier();
                                    phi_3325_ = _e2971;
                                } else {
                                    phi_3325_ = _e434;
                                }
                                let _e2973 = phi_3325_;
                                phi_3324_ = _e2973;
                            } else {
                                phi_3324_ = _e434;
                            }
                            let _e2975 = phi_3324_;
                            phi_3323_ = _e2975;
                        } else {
                            phi_3323_ = _e434;
                        }
                        let _e2977 = phi_3323_;
                        phi_3322_ = _e2977;
                    } else {
                        phi_3322_ = _e434;
                    }
                    let _e2979 = phi_3322_;
                    let _e2980 = local_13;
                    phi_3321_ = _e2979;
                    phi_184_ = (_e2980 + 1u);
                } else {
                    phi_3321_ = _e434;
                    phi_184_ = u32();
                }
                let _e2983 = phi_3321_;
                let _e2985 = phi_184_;
                continue;
                continuing {
                    let _e2986 = local_14;
                    phi_3190_ = _e2983;
                    phi_183_ = _e2985;
                    phi_3320_ = _e2983;
                    break if !(_e2986);
                }
            }
            let _e2989 = phi_3320_;
            if _e2989 {
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
