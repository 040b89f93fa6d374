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
}

struct type_17 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_18 {
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
    member_16: type_17,
    member_17: u32,
    member_18: u32,
}

struct type_19 {
    member: type_18,
}

struct type_22 {
    member: array<u32, 2>,
    member_1: array<f32, 3>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_25 {
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
var<private> global_2: u32;
var<private> global_3: u32;
var<private> global_4: u32;
var<private> global_5: u32;
var<immediate> global_6: type_19;
@group(0) @binding(4) 
var<storage> global_7: type_7;
@group(0) @binding(0) 
var<storage> global_8: type_7;
@group(0) @binding(1) 
var<storage> global_9: type_7;
@group(0) @binding(2) 
var<storage> global_10: type_7;
@group(0) @binding(3) 
var<storage> global_11: type_7;
var<workgroup> global_12: array<u32, 1792>;
@group(0) @binding(5) 
var<storage> global_13: type_7;
@group(0) @binding(6) 
var<storage> global_14: type_7;
@group(0) @binding(7) 
var<storage, read_write> global_15: type_7;
@group(0) @binding(8) 
var<storage, read_write> global_16: type_7;
@group(0) @binding(9) 
var<storage> global_17: type_7;
var<private> global_18: u32 = 2143289344u;

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
    var local_17: type_18;
    var local_18: u32;
    var local_19: f32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: i32;
    var local_30: bool;
    var local_31: i32;
    var local_32: i32;
    var local_33: i32;
    var local_34: i32;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: f32;
    var local_39: bool;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: bool;
    var local_45: bool;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
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
    var local_66: bool;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: u32;
    var local_72: u32;
    var local_73: bool;
    var local_74: u32;
    var local_75: u32;
    var local_76: u32;
    var local_77: bool;
    var local_78: u32;
    var local_79: u32;
    var local_80: u32;
    var local_81: u32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: u32;
    var local_91: bool;
    var local_92: u32;
    var local_93: bool;
    var local_94: u32;
    var local_95: u32;
    var local_96: u32;
    var local_97: bool;
    var local_98: u32;
    var local_99: u32;
    var local_100: bool;
    var local_101: u32;
    var local_102: u32;
    var local_103: u32;
    var local_104: type_25;
    var local_105: u32;
    var local_106: u32;
    var local_107: bool;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: u32;
    var local_112: u32;
    var local_113: u32;
    var local_114: u32;
    var local_115: bool;
    var local_116: u32;
    var local_117: u32;
    var local_118: u32;
    var local_119: u32;
    var local_120: u32;
    var local_121: type_25;
    var local_122: u32;
    var local_123: u32;
    var local_124: bool;
    var local_125: u32;
    var local_126: u32;
    var local_127: u32;
    var local_128: bool;
    var local_129: u32;
    var local_130: u32;
    var local_131: bool;
    var local_132: u32;
    var local_133: u32;
    var local_134: u32;
    var local_135: bool;
    var local_136: type_25;
    var local_137: bool;
    var local_138: u32;
    var local_139: type_25;
    var local_140: u32;
    var local_141: u32;
    var local_142: u32;
    var local_143: u32;
    var local_144: type_25;
    var local_145: u32;
    var local_146: type_25;
    var local_147: u32;
    var local_148: bool;
    var local_149: u32;
    var local_150: u32;
    var local_151: bool;
    var local_152: u32;
    var local_153: type_25;
    var local_154: u32;
    var local_155: bool;
    var local_156: u32;
    var local_157: type_25;
    var local_158: u32;
    var local_159: u32;
    var local_160: u32;
    var local_161: u32;
    var local_162: type_25;
    var local_163: u32;
    var local_164: u32;
    var local_165: u32;
    var local_166: u32;
    var local_167: u32;
    var local_168: u32;
    var local_169: u32;
    var local_170: u32;
    var local_171: u32;
    var local_172: u32;
    var local_173: u32;
    var local_174: u32;
    var local_175: u32;
    var local_176: u32;
    var local_177: u32;
    var local_178: u32;
    var local_179: u32;
    var local_180: u32;
    var local_181: u32;
    var local_182: u32;
    var local_183: array<f32, 3>;
    var local_184: u32;
    var local_185: f32;
    var local_186: f32;
    var local_187: u32;
    var local_188: array<u32, 2>;
    var local_189: u32;
    var local_190: u32;
    var local_191: u32;
    var local_192: u32;
    var local_193: u32;
    var local_194: u32;
    var local_195: bool;
    var local_196: u32;
    var local_197: u32;
    var local_198: type_22;
    var local_199: f32;
    var local_200: f32;
    var local_201: u32;
    var local_202: f32;
    var local_203: f32;
    var local_204: f32;
    var local_205: u32;
    var local_206: u32;
    var local_207: bool;
    var local_208: u32;
    var local_209: u32;
    var local_210: u32;
    var local_211: u32;
    var local_212: bool;
    var local_213: u32;
    var local_214: u32;
    var local_215: u32;
    var local_216: bool;
    var local_217: bool;
    var local_218: u32;
    var local_219: u32;
    var local_220: u32;
    var local_221: u32;
    var local_222: u32;
    var local_223: u32;
    var local_224: u32;
    var local_225: u32;
    var local_226: u32;
    var local_227: bool;
    var local_228: u32;
    var local_229: u32;
    var local_230: bool;
    var local_231: u32;
    var local_232: u32;
    var local_233: u32;
    var local_234: u32;
    var local_235: u32;
    var local_236: u32;
    var local_237: bool;
    var local_238: u32;
    var local_239: u32;
    var local_240: u32;
    var local_241: u32;
    var local_242: u32;
    var local_243: u32;
    var local_244: bool;
    var local_245: u32;
    var local_246: u32;
    var local_247: u32;
    var local_248: bool;
    var local_249: u32;
    var local_250: u32;
    var local_251: u32;
    var local_252: u32;
    var local_253: u32;
    var local_254: u32;
    var local_255: u32;
    var local_256: u32;
    var local_257: u32;
    var local_258: u32;
    var local_259: u32;
    var local_260: bool;
    var local_261: u32;
    var local_262: u32;
    var local_263: bool;
    var local_264: u32;
    var local_265: u32;
    var local_266: bool;
    var local_267: u32;
    var local_268: type_25;
    var local_269: u32;
    var local_270: u32;
    var local_271: bool;
    var local_272: u32;
    var local_273: u32;
    var local_274: u32;
    var local_275: u32;
    var local_276: u32;
    var local_277: u32;
    var local_278: u32;
    var local_279: bool;
    var local_280: u32;
    var local_281: u32;
    var local_282: u32;
    var local_283: u32;
    var local_284: type_25;
    var local_285: u32;
    var local_286: u32;
    var local_287: bool;
    var local_288: u32;
    var local_289: u32;
    var local_290: u32;
    var local_291: bool;
    var local_292: u32;
    var local_293: u32;
    var local_294: bool;
    var local_295: u32;
    var local_296: u32;
    var local_297: u32;
    var local_298: bool;
    var local_299: type_25;
    var local_300: bool;
    var local_301: u32;
    var local_302: type_25;
    var local_303: u32;
    var local_304: u32;
    var local_305: u32;
    var local_306: u32;
    var local_307: type_25;
    var local_308: bool;
    var local_309: u32;
    var local_310: u32;
    var local_311: bool;
    var local_312: u32;
    var local_313: type_25;
    var local_314: u32;
    var local_315: bool;
    var local_316: u32;
    var local_317: type_25;
    var local_318: u32;
    var local_319: u32;
    var local_320: u32;
    var local_321: u32;
    var local_322: u32;
    var local_323: u32;
    var local_324: u32;
    var local_325: u32;
    var local_326: u32;
    var local_327: u32;
    var local_328: u32;
    var local_329: u32;
    var local_330: u32;
    var local_331: u32;
    var local_332: u32;
    var local_333: u32;
    var local_334: u32;
    var local_335: u32;
    var local_336: f32;
    var local_337: u32;
    var local_338: u32;
    var local_339: u32;
    var local_340: u32;
    var phi_361_: bool;
    var phi_372_: u32;
    var phi_374_: u32;
    var phi_375_: u32;
    var phi_376_: u32;
    var phi_377_: u32;
    var phi_378_: u32;
    var phi_379_: u32;
    var phi_380_: u32;
    var phi_381_: u32;
    var phi_384_: u32;
    var phi_385_: u32;
    var phi_416_: type_16;
    var phi_418_: type_16;
    var phi_419_: bool;
    var phi_420_: type_16;
    var phi_421_: bool;
    var phi_426_: type_16;
    var phi_576_: u32;
    var phi_579_: u32;
    var phi_615_: u32;
    var phi_577_: u32;
    var phi_580_: u32;
    var phi_2797_: bool;
    var phi_463_: u32;
    var phi_466_: u32;
    var phi_467_: u32;
    var phi_469_: u32;
    var phi_497_: u32;
    var phi_464_: u32;
    var phi_468_: u32;
    var phi_470_: u32;
    var phi_2822_: bool;
    var phi_519_: u32;
    var phi_522_: u32;
    var phi_524_: u32;
    var phi_539_: u32;
    var phi_520_: u32;
    var phi_523_: u32;
    var phi_525_: u32;
    var phi_2827_: bool;
    var phi_2839_: bool;
    var phi_630_: u32;
    var phi_2837_: bool;
    var phi_653_: u32;
    var phi_656_: u32;
    var phi_658_: u32;
    var phi_692_: u32;
    var phi_694_: u32;
    var phi_695_: bool;
    var phi_700_: u32;
    var phi_703_: u32;
    var phi_727_: u32;
    var phi_701_: u32;
    var phi_704_: u32;
    var phi_2833_: bool;
    var phi_2845_: bool;
    var phi_730_: u32;
    var phi_733_: type_25;
    var phi_735_: u32;
    var phi_750_: type_25;
    var phi_776_: type_25;
    var phi_751_: type_25;
    var phi_777_: bool;
    var phi_2842_: bool;
    var phi_797_: u32;
    var phi_866_: u32;
    var phi_869_: u32;
    var phi_893_: u32;
    var phi_909_: u32;
    var phi_915_: u32;
    var phi_867_: u32;
    var phi_870_: u32;
    var phi_2847_: bool;
    var phi_919_: u32;
    var phi_922_: u32;
    var phi_946_: u32;
    var phi_962_: u32;
    var phi_968_: u32;
    var phi_920_: u32;
    var phi_923_: u32;
    var phi_2856_: bool;
    var phi_987_: u32;
    var phi_1027_: u32;
    var phi_1010_: u32;
    var phi_1028_: u32;
    var phi_2865_: bool;
    var phi_1140_: type_25;
    var phi_1142_: type_25;
    var phi_1164_: u32;
    var phi_1185_: u32;
    var phi_1230_: u32;
    var phi_1211_: u32;
    var phi_1231_: u32;
    var phi_1143_: type_25;
    var phi_2862_: bool;
    var phi_1729_: u32;
    var phi_1747_: u32;
    var phi_1428_: array<f32, 3>;
    var phi_1439_: f32;
    var phi_1464_: u32;
    var phi_1477_: u32;
    var phi_1511_: type_22;
    var phi_1522_: f32;
    var phi_1546_: bool;
    var phi_1568_: f32;
    var phi_1569_: f32;
    var phi_1575_: f32;
    var phi_1577_: f32;
    var phi_1674_: u32;
    var phi_1675_: u32;
    var phi_1695_: bool;
    var phi_1711_: u32;
    var phi_1712_: u32;
    var phi_1749_: u32;
    var phi_1750_: u32;
    var phi_2893_: bool;
    var phi_1751_: u32;
    var phi_1752_: type_25;
    var phi_1753_: u32;
    var phi_2892_: bool;
    var phi_731_: u32;
    var phi_734_: type_25;
    var phi_736_: u32;
    var phi_1754_: bool;
    var phi_2891_: bool;
    var phi_2928_: bool;
    var phi_1759_: u32;
    var phi_1791_: type_16;
    var phi_1793_: type_16;
    var phi_1794_: bool;
    var phi_1795_: type_16;
    var phi_1796_: bool;
    var phi_1801_: type_16;
    var phi_1951_: u32;
    var phi_1954_: u32;
    var phi_1990_: u32;
    var phi_1952_: u32;
    var phi_1955_: u32;
    var phi_2923_: bool;
    var phi_1838_: u32;
    var phi_1841_: u32;
    var phi_1842_: u32;
    var phi_1844_: u32;
    var phi_1872_: u32;
    var phi_1839_: u32;
    var phi_1843_: u32;
    var phi_1845_: u32;
    var phi_2934_: bool;
    var phi_1894_: u32;
    var phi_1897_: u32;
    var phi_1899_: u32;
    var phi_1914_: u32;
    var phi_1895_: u32;
    var phi_1898_: u32;
    var phi_1900_: u32;
    var phi_2939_: bool;
    var phi_2949_: bool;
    var phi_2005_: u32;
    var phi_2020_: u32;
    var phi_2037_: u32;
    var phi_2040_: u32;
    var phi_2064_: u32;
    var phi_2038_: u32;
    var phi_2041_: u32;
    var phi_2945_: bool;
    var phi_2955_: bool;
    var phi_2065_: u32;
    var phi_2954_: bool;
    var phi_2068_: type_25;
    var phi_2071_: u32;
    var phi_2073_: u32;
    var phi_2090_: type_25;
    var phi_2116_: type_25;
    var phi_2091_: type_25;
    var phi_2117_: bool;
    var phi_2951_: bool;
    var phi_2137_: u32;
    var phi_2206_: u32;
    var phi_2209_: u32;
    var phi_2233_: u32;
    var phi_2249_: u32;
    var phi_2255_: u32;
    var phi_2207_: u32;
    var phi_2210_: u32;
    var phi_2957_: bool;
    var phi_2259_: u32;
    var phi_2262_: u32;
    var phi_2286_: u32;
    var phi_2302_: u32;
    var phi_2308_: u32;
    var phi_2260_: u32;
    var phi_2263_: u32;
    var phi_2966_: bool;
    var phi_2327_: u32;
    var phi_2367_: u32;
    var phi_2350_: u32;
    var phi_2368_: u32;
    var phi_2975_: bool;
    var phi_2480_: type_25;
    var phi_2482_: type_25;
    var phi_2504_: u32;
    var phi_2525_: u32;
    var phi_2570_: u32;
    var phi_2551_: u32;
    var phi_2571_: u32;
    var phi_2483_: type_25;
    var phi_2972_: bool;
    var phi_3003_: bool;
    var phi_2731_: type_25;
    var phi_2732_: u32;
    var phi_3002_: bool;
    var phi_2069_: type_25;
    var phi_2072_: u32;
    var phi_2074_: u32;
    var phi_3001_: bool;
    var phi_3005_: bool;
    var phi_654_: u32;
    var phi_657_: u32;
    var phi_659_: u32;
    var phi_3004_: bool;
    var local_341: u32;
    var local_342: u32;
    var local_343: u32;
    var local_344: u32;
    var local_345: type_25;
    var local_346: type_25;
    var local_347: u32;
    var local_348: u32;
    var local_349: u32;
    var local_350: u32;
    var local_351: u32;
    var local_352: u32;
    var local_353: type_25;
    var local_354: type_25;

    let _e406 = global_18;
    switch bitcast<i32>(0u) {
        default: {
            let _e409 = global;
            local = _e409;
            let _e410 = global_1;
            let _e411 = global_2;
            local_1 = _e411;
            let _e412 = global_3;
            local_2 = _e412;
            let _e413 = global_4;
            local_3 = _e413;
            let _e414 = global_5;
            local_4 = _e414;
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_9.member));
            local_7 = arrayLength((&global_10.member));
            local_8 = arrayLength((&global_11.member));
            local_9 = arrayLength((&global_7.member));
            local_10 = arrayLength((&global_13.member));
            local_11 = arrayLength((&global_14.member));
            local_12 = arrayLength((&global_15.member));
            local_13 = arrayLength((&global_16.member));
            let _e435 = arrayLength((&global_17.member));
            local_14 = _e435;
            local_15 = _e410.x;
            local_16 = _e410.y;
            let _e438 = global_6.member;
            local_17 = _e438;
            if (18u < _e435) {
            } else {
                break;
            }
            let _e442 = global_17.member[18u];
            local_18 = _e442;
            let _e443 = local_14;
            if (19u < _e443) {
            } else {
                break;
            }
            let _e447 = global_17.member[19u];
            local_19 = bitcast<f32>(_e447);
            let _e449 = local_17;
            local_20 = _e449.member_7;
            let _e451 = local_16;
            let _e453 = local_15;
            let _e454 = ((_e451 * _e449.member_7) + _e453);
            local_21 = _e454;
            let _e455 = local_9;
            if (_e454 < _e455) {
            } else {
                break;
            }
            let _e457 = local_21;
            let _e460 = global_7.member[_e457];
            local_22 = _e460;
            let _e461 = local_21;
            let _e462 = (2u * _e461);
            local_23 = _e462;
            let _e463 = local_10;
            if (_e462 < _e463) {
            } else {
                break;
            }
            let _e465 = local_23;
            let _e468 = global_13.member[_e465];
            local_24 = _e468;
            let _e469 = local_23;
            let _e470 = (_e469 + 1u);
            local_25 = _e470;
            let _e471 = local_10;
            if (_e470 < _e471) {
            } else {
                break;
            }
            let _e473 = local_25;
            let _e476 = global_13.member[_e473];
            local_26 = _e476;
            let _e477 = local_22;
            if ((_e477 & 1u) == 0u) {
                let _e480 = local_26;
                if (_e480 == 0u) {
                } else {
                    let _e482 = local_22;
                    local_27 = (_e482 >> bitcast<u32>(1u));
                    let _e485 = local_18;
                    let _e487 = ((2u * _e485) + 1u);
                    local_28 = _e487;
                    let _e489 = local;
                    if (_e489 < (_e487 * _e487)) {
                        let _e491 = local_15;
                        local_29 = bitcast<i32>(_e491);
                        let _e493 = local_28;
                        let _e494 = (_e493 == 0u);
                        local_30 = _e494;
                        if _e494 {
                            break;
                        }
                        let _e495 = local;
                        let _e496 = local_28;
                        let _e499 = local_29;
                        let _e501 = local_18;
                        let _e502 = bitcast<i32>(_e501);
                        local_31 = _e502;
                        local_32 = ((_e499 + bitcast<i32>((_e495 % _e496))) - _e502);
                        let _e504 = local_16;
                        local_33 = bitcast<i32>(_e504);
                        let _e506 = local_30;
                        if _e506 {
                            break;
                        }
                        let _e507 = local;
                        let _e508 = local_28;
                        let _e511 = local_33;
                        let _e513 = local_31;
                        local_34 = ((_e511 + bitcast<i32>((_e507 / _e508))) - _e513);
                        let _e515 = local_32;
                        if (_e515 >= 0i) {
                            let _e517 = local_34;
                            if (_e517 >= 0i) {
                                let _e519 = local_20;
                                let _e521 = local_32;
                                if (_e521 < bitcast<i32>(_e519)) {
                                    let _e523 = local_17;
                                    let _e526 = local_34;
                                    if (_e526 < bitcast<i32>(_e523.member_8)) {
                                        let _e528 = local_34;
                                        let _e529 = bitcast<u32>(_e528);
                                        local_35 = _e529;
                                        let _e530 = local_20;
                                        let _e532 = local_32;
                                        let _e533 = bitcast<u32>(_e532);
                                        local_36 = _e533;
                                        let _e534 = ((_e529 * _e530) + _e533);
                                        local_37 = _e534;
                                        let _e535 = local_8;
                                        if (_e534 < _e535) {
                                        } else {
                                            break;
                                        }
                                        let _e537 = local_37;
                                        let _e540 = global_11.member[_e537];
                                        local_38 = bitcast<f32>(_e540);
                                        let _e542 = local_37;
                                        let _e543 = local_21;
                                        if (_e542 == _e543) {
                                            phi_361_ = true;
                                        } else {
                                            let _e545 = local_17;
                                            let _e547 = local_17;
                                            let _e549 = local_36;
                                            let _e551 = ((_e549 + 1u) * _e545.member_6);
                                            let _e554 = local_36;
                                            let _e558 = local_17;
                                            let _e560 = local_35;
                                            let _e562 = ((_e560 + 1u) * _e545.member_6);
                                            let _e565 = local_35;
                                            let _e569 = local_15;
                                            let _e571 = ((_e569 + 1u) * _e545.member_6);
                                            let _e574 = local_15;
                                            let _e578 = local_16;
                                            let _e580 = ((_e578 + 1u) * _e545.member_6);
                                            let _e583 = local_16;
                                            let _e589 = ((f32((_e574 * _e545.member_6)) + 0.5f) - f32(select(_e547.member, _e551, (_e551 < _e547.member))));
                                            let _e590 = (f32((_e554 * _e545.member_6)) - (f32(select(_e547.member, _e571, (_e571 < _e547.member))) - 0.5f));
                                            let _e592 = select(_e590, _e589, (_e589 > _e590));
                                            let _e594 = select(0f, _e592, (_e592 > 0f));
                                            let _e597 = ((f32((_e583 * _e545.member_6)) + 0.5f) - f32(select(_e558.member_1, _e562, (_e562 < _e558.member_1))));
                                            let _e598 = (f32((_e565 * _e545.member_6)) - (f32(select(_e558.member_1, _e580, (_e580 < _e558.member_1))) - 0.5f));
                                            let _e600 = select(_e598, _e597, (_e597 > _e598));
                                            let _e602 = select(0f, _e600, (_e600 > 0f));
                                            let _e606 = local_38;
                                            let _e607 = local_38;
                                            phi_361_ = (((_e594 * _e594) + (_e602 * _e602)) <= (_e606 * _e607));
                                        }
                                        let _e611 = phi_361_;
                                        local_39 = _e611;
                                        if _e611 {
                                            let _e612 = local_37;
                                            let _e613 = local_6;
                                            if (_e612 < _e613) {
                                            } else {
                                                break;
                                            }
                                            let _e615 = local_37;
                                            let _e618 = global_9.member[_e615];
                                            phi_372_ = _e618;
                                        } else {
                                            phi_372_ = 0u;
                                        }
                                        let _e620 = phi_372_;
                                        let _e621 = local_39;
                                        let _e622 = local_37;
                                        phi_374_ = _e620;
                                        phi_375_ = select(0u, _e622, _e621);
                                    } else {
                                        phi_374_ = 0u;
                                        phi_375_ = 0u;
                                    }
                                    let _e625 = phi_374_;
                                    let _e627 = phi_375_;
                                    phi_376_ = _e625;
                                    phi_377_ = _e627;
                                } else {
                                    phi_376_ = 0u;
                                    phi_377_ = 0u;
                                }
                                let _e629 = phi_376_;
                                let _e631 = phi_377_;
                                phi_378_ = _e629;
                                phi_379_ = _e631;
                            } else {
                                phi_378_ = 0u;
                                phi_379_ = 0u;
                            }
                            let _e633 = phi_378_;
                            let _e635 = phi_379_;
                            phi_380_ = _e633;
                            phi_381_ = _e635;
                        } else {
                            phi_380_ = 0u;
                            phi_381_ = 0u;
                        }
                        let _e637 = phi_380_;
                        let _e639 = phi_381_;
                        phi_384_ = _e637;
                        phi_385_ = _e639;
                    } else {
                        phi_384_ = 0u;
                        phi_385_ = 0u;
                    }
                    let _e641 = phi_384_;
                    let _e643 = phi_385_;
                    local_40 = _e641;
                    local_41 = _e643;
                    let _e644 = local;
                    let _e645 = (768u + _e644);
                    local_42 = _e645;
                    if (_e645 < 1792u) {
                    } else {
                        break;
                    }
                    let _e647 = local_42;
                    let _e649 = local_40;
                    global_12[_e647] = _e649;
                    let _e650 = local;
                    let _e651 = (1280u + _e650);
                    local_43 = _e651;
                    if (_e651 < 1792u) {
                    } else {
                        break;
                    }
                    let _e653 = local_43;
                    let _e655 = local_41;
                    global_12[_e653] = _e655;
                    storageBarrier();
                    workgroupBarrier();
                    let _e656 = local_1;
                    let _e657 = (_e656 >= 2u);
                    local_44 = _e657;
                    if _e657 {
                        let _e658 = local_1;
                        let _e660 = local_1;
                        if ((_e660 & (_e658 - 1u)) == 0u) {
                            let _e663 = local_2;
                            let _e664 = local_1;
                            let _e666 = ((_e663 * _e664) == 256u);
                            local_45 = _e666;
                            if _e666 {
                                let _e667 = local_1;
                                phi_416_ = type_16(1u, _e667);
                            } else {
                                phi_416_ = type_16();
                            }
                            let _e670 = phi_416_;
                            let _e671 = local_45;
                            phi_418_ = _e670;
                            phi_419_ = select(true, false, _e671);
                        } else {
                            phi_418_ = type_16();
                            phi_419_ = true;
                        }
                        let _e674 = phi_418_;
                        let _e676 = phi_419_;
                        phi_420_ = _e674;
                        phi_421_ = _e676;
                    } else {
                        phi_420_ = type_16();
                        phi_421_ = true;
                    }
                    let _e678 = phi_420_;
                    let _e680 = phi_421_;
                    if _e680 {
                        phi_426_ = type_16(0u, type_16().member_1);
                    } else {
                        phi_426_ = _e678;
                    }
                    let _e685 = phi_426_;
                    local_46 = _e685.member_1;
                    if (bitcast<i32>(_e685.member) != 0i) {
                        let _e739 = local_46;
                        let _e741 = local_46;
                        local_47 = select(firstTrailingBit(_e739), 32u, (_e741 == 0u));
                        let _e744 = local_3;
                        let _e745 = local_1;
                        let _e747 = local_4;
                        let _e748 = ((_e744 * _e745) + _e747);
                        local_48 = _e748;
                        let _e749 = (768u + _e748);
                        local_49 = _e749;
                        if (_e749 < 1792u) {
                        } else {
                            break;
                        }
                        let _e751 = local_49;
                        let _e753 = global_12[_e751];
                        let _e754 = subgroupInclusiveAdd(_e753);
                        local_50 = _e754;
                        let _e755 = local_48;
                        let _e756 = (1024u + _e755);
                        local_51 = _e756;
                        if (_e756 < 1792u) {
                        } else {
                            break;
                        }
                        let _e758 = local_51;
                        let _e760 = local_50;
                        global_12[_e758] = _e760;
                        storageBarrier();
                        workgroupBarrier();
                        phi_463_ = 768u;
                        phi_466_ = 1024u;
                        phi_467_ = 256u;
                        phi_469_ = 0u;
                        loop {
                            let _e762 = phi_463_;
                            let _e764 = phi_466_;
                            let _e766 = phi_467_;
                            let _e768 = phi_469_;
                            local_52 = _e762;
                            local_53 = _e764;
                            local_54 = _e766;
                            local_55 = _e768;
                            local_341 = _e764;
                            local_342 = _e766;
                            local_343 = _e768;
                            let _e769 = local_54;
                            let _e770 = local_46;
                            let _e771 = (_e769 > _e770);
                            local_56 = _e771;
                            if _e771 {
                                let _e772 = local_47;
                                let _e773 = (_e772 & 31u);
                                local_57 = _e773;
                                let _e774 = local_54;
                                let _e776 = (_e774 >> bitcast<u32>(_e773));
                                local_58 = _e776;
                                let _e777 = local_48;
                                let _e778 = (_e777 < _e776);
                                local_59 = _e778;
                                if _e778 {
                                    let _e779 = local_48;
                                    let _e781 = local_57;
                                    let _e784 = local_53;
                                    let _e786 = ((_e784 + ((_e779 + 1u) << bitcast<u32>(_e781))) - 1u);
                                    local_60 = _e786;
                                    if (_e786 < 1792u) {
                                    } else {
                                        phi_2822_ = true;
                                        break;
                                    }
                                    let _e788 = local_60;
                                    let _e790 = global_12[_e788];
                                    phi_497_ = _e790;
                                } else {
                                    phi_497_ = 0u;
                                }
                                let _e792 = phi_497_;
                                let _e793 = subgroupInclusiveAdd(_e792);
                                local_61 = _e793;
                                let _e794 = local_59;
                                if _e794 {
                                    let _e795 = local_52;
                                    let _e796 = local_48;
                                    let _e797 = (_e795 + _e796);
                                    local_62 = _e797;
                                    if (_e797 < 1792u) {
                                    } else {
                                        phi_2822_ = true;
                                        break;
                                    }
                                    let _e799 = local_62;
                                    let _e801 = local_61;
                                    global_12[_e799] = _e801;
                                }
                                storageBarrier();
                                workgroupBarrier();
                                let _e802 = local_52;
                                let _e803 = local_58;
                                let _e805 = local_55;
                                phi_464_ = (_e802 + _e803);
                                phi_468_ = _e776;
                                phi_470_ = (_e805 + 1u);
                            } else {
                                phi_464_ = u32();
                                phi_468_ = u32();
                                phi_470_ = u32();
                            }
                            let _e808 = phi_464_;
                            let _e810 = phi_468_;
                            let _e812 = phi_470_;
                            continue;
                            continuing {
                                let _e813 = local_56;
                                phi_463_ = _e808;
                                phi_466_ = _e762;
                                phi_467_ = _e810;
                                phi_469_ = _e812;
                                phi_2822_ = false;
                                break if !(_e813);
                            }
                        }
                        let _e816 = phi_2822_;
                        if _e816 {
                            break;
                        }
                        let _e3382 = local_341;
                        phi_519_ = _e3382;
                        let _e3385 = local_342;
                        phi_522_ = _e3385;
                        let _e3388 = local_343;
                        phi_524_ = _e3388;
                        loop {
                            let _e818 = phi_519_;
                            let _e820 = phi_522_;
                            let _e822 = phi_524_;
                            local_63 = _e818;
                            local_64 = _e820;
                            local_65 = _e822;
                            let _e823 = local_65;
                            let _e824 = (_e823 > 0u);
                            local_66 = _e824;
                            if _e824 {
                                let _e825 = local_47;
                                let _e826 = (_e825 & 31u);
                                local_67 = _e826;
                                let _e827 = local_64;
                                let _e829 = (_e827 << bitcast<u32>(_e826));
                                local_68 = _e829;
                                let _e830 = local_65;
                                if (_e830 == 1u) {
                                    phi_539_ = 1024u;
                                } else {
                                    let _e832 = local_63;
                                    let _e833 = local_68;
                                    phi_539_ = (_e832 - _e833);
                                }
                                let _e836 = phi_539_;
                                local_69 = _e836;
                                let _e837 = local;
                                let _e838 = local_46;
                                if (_e837 >= _e838) {
                                    let _e840 = local;
                                    let _e841 = local_68;
                                    if (_e840 < _e841) {
                                        let _e843 = local_69;
                                        let _e844 = local;
                                        local_70 = (_e843 + _e844);
                                        let _e846 = local;
                                        let _e847 = local_67;
                                        let _e850 = local_63;
                                        let _e852 = ((_e850 + (_e846 >> bitcast<u32>(_e847))) - 1u);
                                        local_71 = _e852;
                                        if (_e852 < 1792u) {
                                        } else {
                                            phi_2827_ = true;
                                            break;
                                        }
                                        let _e854 = local_71;
                                        let _e856 = global_12[_e854];
                                        local_72 = _e856;
                                        let _e857 = local_70;
                                        let _e858 = (_e857 < 1792u);
                                        local_73 = _e858;
                                        if _e858 {
                                        } else {
                                            phi_2827_ = true;
                                            break;
                                        }
                                        let _e859 = local_70;
                                        let _e861 = global_12[_e859];
                                        let _e862 = local_72;
                                        local_74 = (_e862 + _e861);
                                        let _e864 = local_73;
                                        if _e864 {
                                        } else {
                                            phi_2827_ = true;
                                            break;
                                        }
                                        let _e865 = local_74;
                                        global_12[_e859] = _e865;
                                    }
                                }
                                storageBarrier();
                                workgroupBarrier();
                                let _e866 = local_65;
                                phi_520_ = _e836;
                                phi_523_ = _e829;
                                phi_525_ = (_e866 - 1u);
                            } else {
                                phi_520_ = u32();
                                phi_523_ = u32();
                                phi_525_ = u32();
                            }
                            let _e869 = phi_520_;
                            let _e871 = phi_523_;
                            let _e873 = phi_525_;
                            continue;
                            continuing {
                                let _e874 = local_66;
                                phi_519_ = _e869;
                                phi_522_ = _e871;
                                phi_524_ = _e873;
                                phi_2827_ = _e816;
                                break if !(_e874);
                            }
                        }
                        let _e877 = phi_2827_;
                        if _e877 {
                            break;
                        }
                        phi_2839_ = _e877;
                        phi_630_ = 1024u;
                    } else {
                        phi_576_ = 1u;
                        phi_579_ = 768u;
                        loop {
                            let _e691 = phi_576_;
                            let _e693 = phi_579_;
                            local_75 = _e691;
                            local_76 = _e693;
                            local_344 = _e693;
                            let _e694 = local_75;
                            let _e695 = (_e694 < 256u);
                            local_77 = _e695;
                            if _e695 {
                                let _e696 = local_76;
                                let _e698 = select(768u, 1024u, (_e696 == 768u));
                                local_331 = _e698;
                                let _e699 = local_76;
                                let _e700 = local;
                                let _e701 = (_e699 + _e700);
                                local_78 = _e701;
                                if (_e701 < 1792u) {
                                } else {
                                    phi_2797_ = true;
                                    break;
                                }
                                let _e703 = local_78;
                                let _e705 = global_12[_e703];
                                local_79 = _e705;
                                let _e706 = local;
                                let _e707 = local_75;
                                if (_e706 >= _e707) {
                                    let _e709 = local;
                                    let _e710 = local_75;
                                    let _e712 = local_76;
                                    let _e713 = (_e712 + (_e709 - _e710));
                                    local_80 = _e713;
                                    if (_e713 < 1792u) {
                                    } else {
                                        phi_2797_ = true;
                                        break;
                                    }
                                    let _e715 = local_80;
                                    let _e717 = global_12[_e715];
                                    let _e718 = local_79;
                                    phi_615_ = (_e717 + _e718);
                                } else {
                                    phi_615_ = _e705;
                                }
                                let _e721 = phi_615_;
                                local_81 = _e721;
                                let _e722 = local_331;
                                let _e723 = local;
                                let _e724 = (_e722 + _e723);
                                local_82 = _e724;
                                if (_e724 < 1792u) {
                                } else {
                                    phi_2797_ = true;
                                    break;
                                }
                                let _e726 = local_82;
                                let _e728 = local_81;
                                global_12[_e726] = _e728;
                                storageBarrier();
                                workgroupBarrier();
                                let _e729 = local_75;
                                phi_577_ = (_e729 * 2u);
                                phi_580_ = _e698;
                            } else {
                                phi_577_ = u32();
                                phi_580_ = u32();
                            }
                            let _e732 = phi_577_;
                            let _e734 = phi_580_;
                            continue;
                            continuing {
                                let _e735 = local_77;
                                phi_576_ = _e732;
                                phi_579_ = _e734;
                                phi_2797_ = false;
                                break if !(_e735);
                            }
                        }
                        let _e738 = phi_2797_;
                        if _e738 {
                            break;
                        }
                        phi_2839_ = _e738;
                        let _e3397 = local_344;
                        phi_630_ = _e3397;
                    }
                    let _e879 = phi_2839_;
                    let _e881 = phi_630_;
                    local_83 = _e881;
                    let _e882 = (_e881 + 255u);
                    local_84 = _e882;
                    if (_e882 < 1792u) {
                    } else {
                        break;
                    }
                    let _e884 = local_84;
                    let _e886 = global_12[_e884];
                    local_85 = _e886;
                    let _e887 = local_17;
                    local_86 = _e887.member_10;
                    let _e891 = select(16u, 1u, ((_e887.member_10 & 2u) == 0u));
                    local_332 = _e891;
                    local_87 = (32u >> bitcast<u32>((select(firstTrailingBit(_e891), 32u, (_e891 == 0u)) & 31u)));
                    phi_2837_ = _e879;
                    phi_653_ = 0u;
                    phi_656_ = 0u;
                    phi_658_ = 0u;
                    loop {
                        let _e899 = phi_2837_;
                        let _e901 = phi_653_;
                        let _e903 = phi_656_;
                        let _e905 = phi_658_;
                        local_88 = _e901;
                        local_89 = _e903;
                        local_90 = _e905;
                        let _e906 = local_89;
                        let _e907 = local_85;
                        let _e908 = (_e906 < _e907);
                        local_91 = _e908;
                        if _e908 {
                            let _e909 = local;
                            let _e910 = local_332;
                            let _e912 = local_89;
                            local_92 = (_e912 + (_e909 * _e910));
                            let _e914 = local_88;
                            let _e915 = local_87;
                            if (_e914 < _e915) {
                                let _e917 = local_27;
                                let _e918 = (_e917 == 0u);
                                local_93 = _e918;
                                if _e918 {
                                    let _e919 = local_21;
                                    let _e921 = local;
                                    let _e922 = ((_e919 * 256u) + _e921);
                                    local_94 = _e922;
                                    let _e923 = local_11;
                                    if (_e922 < _e923) {
                                    } else {
                                        phi_3004_ = true;
                                        break;
                                    }
                                    let _e925 = local_94;
                                    let _e928 = global_14.member[_e925];
                                    let _e929 = local_88;
                                    let _e930 = local_332;
                                    let _e935 = local_332;
                                    phi_692_ = ((_e928 >> bitcast<u32>(((_e929 * _e930) & 31u))) & (4294967295u >> bitcast<u32>(((32u - _e935) & 31u))));
                                } else {
                                    phi_692_ = u32();
                                }
                                let _e942 = phi_692_;
                                let _e943 = local_93;
                                phi_694_ = _e942;
                                phi_695_ = select(true, false, _e943);
                            } else {
                                phi_694_ = u32();
                                phi_695_ = true;
                            }
                            let _e946 = phi_694_;
                            let _e948 = phi_695_;
                            if _e948 {
                                phi_700_ = 255u;
                                phi_703_ = 0u;
                                loop {
                                    let _e950 = phi_700_;
                                    let _e952 = phi_703_;
                                    local_95 = _e950;
                                    local_96 = _e952;
                                    let _e953 = local_96;
                                    let _e954 = local_95;
                                    let _e955 = (_e953 < _e954);
                                    local_97 = _e955;
                                    if _e955 {
                                        let _e956 = local_96;
                                        let _e957 = local_95;
                                        let _e959 = ((_e956 + _e957) / 2u);
                                        local_98 = _e959;
                                        let _e960 = local_83;
                                        let _e961 = (_e960 + _e959);
                                        local_99 = _e961;
                                        if (_e961 < 1792u) {
                                        } else {
                                            phi_2833_ = true;
                                            break;
                                        }
                                        let _e963 = local_99;
                                        let _e965 = global_12[_e963];
                                        let _e966 = local_92;
                                        let _e967 = (_e965 > _e966);
                                        local_100 = _e967;
                                        if _e967 {
                                            phi_727_ = _e952;
                                        } else {
                                            let _e968 = local_98;
                                            phi_727_ = (_e968 + 1u);
                                        }
                                        let _e971 = phi_727_;
                                        let _e972 = local_100;
                                        let _e973 = local_98;
                                        let _e974 = local_95;
                                        phi_701_ = select(_e974, _e973, _e972);
                                        phi_704_ = _e971;
                                    } else {
                                        phi_701_ = u32();
                                        phi_704_ = u32();
                                    }
                                    let _e977 = phi_701_;
                                    let _e979 = phi_704_;
                                    continue;
                                    continuing {
                                        let _e980 = local_97;
                                        phi_700_ = _e977;
                                        phi_703_ = _e979;
                                        phi_2833_ = _e899;
                                        break if !(_e980);
                                    }
                                }
                                let _e983 = phi_2833_;
                                phi_3004_ = _e983;
                                if _e983 {
                                    break;
                                }
                                let _e984 = local_96;
                                let _e985 = local_15;
                                let _e986 = local_16;
                                phi_2845_ = _e983;
                                phi_730_ = 0u;
                                phi_733_ = type_25(_e984, 4294967295u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, _e985, _e986, false);
                                phi_735_ = 0u;
                                loop {
                                    let _e989 = phi_2845_;
                                    let _e991 = phi_730_;
                                    let _e993 = phi_733_;
                                    let _e995 = phi_735_;
                                    local_101 = _e991;
                                    local_102 = _e995;
                                    local_347 = _e991;
                                    let _e996 = local_102;
                                    let _e997 = local_332;
                                    if (_e996 < _e997) {
                                        let _e999 = local_92;
                                        let _e1000 = local_102;
                                        let _e1001 = (_e999 + _e1000);
                                        local_103 = _e1001;
                                        let _e1002 = local_85;
                                        let _e1003 = (_e1001 < _e1002);
                                        if _e1003 {
                                            phi_750_ = _e993;
                                            loop {
                                                let _e1005 = phi_750_;
                                                local_104 = _e1005;
                                                local_345 = _e1005;
                                                let _e1006 = local_104;
                                                local_105 = _e1006.member;
                                                if (_e1006.member < 255u) {
                                                    let _e1009 = local_83;
                                                    let _e1010 = local_105;
                                                    let _e1011 = (_e1009 + _e1010);
                                                    local_106 = _e1011;
                                                    if (_e1011 < 1792u) {
                                                    } else {
                                                        phi_2842_ = true;
                                                        break;
                                                    }
                                                    let _e1013 = local_106;
                                                    let _e1015 = global_12[_e1013];
                                                    let _e1016 = local_103;
                                                    let _e1017 = (_e1015 <= _e1016);
                                                    if _e1017 {
                                                        let _e1018 = local_105;
                                                        let _e1020 = local_104;
                                                        phi_776_ = type_25((_e1018 + 1u), _e1020.member_1, _e1020.member_2, _e1020.member_3, _e1020.member_4, _e1020.member_5, _e1020.member_6, _e1020.member_7, _e1020.member_8, _e1020.member_9, _e1020.member_10, _e1020.member_11, _e1020.member_12, _e1020.member_13, _e1020.member_14);
                                                    } else {
                                                        phi_776_ = type_25();
                                                    }
                                                    let _e1038 = phi_776_;
                                                    phi_751_ = _e1038;
                                                    phi_777_ = _e1017;
                                                } else {
                                                    phi_751_ = type_25();
                                                    phi_777_ = false;
                                                }
                                                let _e1040 = phi_751_;
                                                let _e1042 = phi_777_;
                                                local_107 = _e1042;
                                                continue;
                                                continuing {
                                                    let _e1043 = local_107;
                                                    phi_750_ = _e1040;
                                                    phi_2842_ = _e989;
                                                    break if !(_e1043);
                                                }
                                            }
                                            let _e1046 = phi_2842_;
                                            phi_2891_ = _e1046;
                                            if _e1046 {
                                                break;
                                            }
                                            let _e1047 = local_105;
                                            if (_e1047 == 0u) {
                                                phi_797_ = 0u;
                                            } else {
                                                let _e1049 = local_83;
                                                let _e1050 = local_105;
                                                let _e1052 = ((_e1049 + _e1050) - 1u);
                                                local_108 = _e1052;
                                                if (_e1052 < 1792u) {
                                                } else {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1054 = local_108;
                                                let _e1056 = global_12[_e1054];
                                                phi_797_ = _e1056;
                                            }
                                            let _e1058 = phi_797_;
                                            let _e1059 = local_103;
                                            local_109 = (_e1059 - _e1058);
                                            let _e1061 = local_104;
                                            let _e1063 = local_105;
                                            if (_e1061.member_1 != _e1063) {
                                                let _e1065 = local_17;
                                                local_110 = _e1065.member_6;
                                                let _e1067 = local_17;
                                                local_111 = _e1067.member_3;
                                                if (_e1067.member_3 == 0u) {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1070 = local_110;
                                                let _e1071 = local_111;
                                                local_112 = (_e1070 / _e1071);
                                                let _e1073 = local_105;
                                                let _e1074 = (1280u + _e1073);
                                                local_113 = _e1074;
                                                if (_e1074 < 1792u) {
                                                } else {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1076 = local_113;
                                                let _e1078 = global_12[_e1076];
                                                local_114 = _e1078;
                                                let _e1079 = local_20;
                                                let _e1080 = (_e1079 == 0u);
                                                local_115 = _e1080;
                                                if _e1080 {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1081 = local_114;
                                                let _e1082 = local_20;
                                                let _e1084 = local_112;
                                                local_116 = ((_e1081 % _e1082) * _e1084);
                                                let _e1086 = local_115;
                                                if _e1086 {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1087 = local_114;
                                                let _e1088 = local_20;
                                                let _e1090 = local_112;
                                                let _e1091 = ((_e1087 / _e1088) * _e1090);
                                                local_117 = _e1091;
                                                let _e1092 = local_105;
                                                let _e1093 = local_104;
                                                let _e1109 = type_25(_e1093.member, _e1092, _e1093.member_2, _e1093.member_3, _e1093.member_4, _e1093.member_5, _e1093.member_6, _e1093.member_7, _e1093.member_8, _e1093.member_9, _e1093.member_10, _e1093.member_11, _e1093.member_12, _e1093.member_13, _e1093.member_14);
                                                let _e1110 = local_114;
                                                let _e1126 = type_25(_e1109.member, _e1109.member_1, _e1110, _e1109.member_3, _e1109.member_4, _e1109.member_5, _e1109.member_6, _e1109.member_7, _e1109.member_8, _e1109.member_9, _e1109.member_10, _e1109.member_11, _e1109.member_12, _e1109.member_13, _e1109.member_14);
                                                let _e1127 = local_17;
                                                local_118 = _e1127.member_4;
                                                let _e1130 = local_116;
                                                let _e1131 = ((_e1091 * _e1127.member_4) + _e1130);
                                                local_119 = _e1131;
                                                let _e1147 = type_25(_e1126.member, _e1126.member_1, _e1126.member_2, _e1131, _e1126.member_4, _e1126.member_5, _e1126.member_6, _e1126.member_7, _e1126.member_8, _e1126.member_9, _e1126.member_10, _e1126.member_11, _e1126.member_12, _e1126.member_13, _e1126.member_14);
                                                let _e1148 = local_116;
                                                let _e1164 = type_25(_e1147.member, _e1147.member_1, _e1147.member_2, _e1147.member_3, _e1148, _e1147.member_5, _e1147.member_6, _e1147.member_7, _e1147.member_8, _e1147.member_9, _e1147.member_10, _e1147.member_11, _e1147.member_12, _e1147.member_13, _e1147.member_14);
                                                let _e1180 = type_25(_e1164.member, _e1164.member_1, _e1164.member_2, _e1164.member_3, _e1164.member_4, _e1091, _e1164.member_6, _e1164.member_7, _e1164.member_8, _e1164.member_9, _e1164.member_10, _e1164.member_11, _e1164.member_12, _e1164.member_13, _e1164.member_14);
                                                let _e1181 = local_116;
                                                let _e1182 = (_e1127.member_4 - _e1181);
                                                let _e1183 = local_112;
                                                let _e1185 = local_112;
                                                let _e1186 = select(_e1185, _e1182, (_e1182 < _e1183));
                                                local_333 = _e1186;
                                                let _e1202 = type_25(_e1180.member, _e1180.member_1, _e1180.member_2, _e1180.member_3, _e1180.member_4, _e1180.member_5, _e1186, _e1180.member_7, _e1180.member_8, _e1180.member_9, _e1180.member_10, _e1180.member_11, _e1180.member_12, _e1180.member_13, _e1180.member_14);
                                                let _e1203 = local_17;
                                                local_120 = _e1203.member_5;
                                                let _e1205 = (_e1203.member_5 - _e1091);
                                                let _e1206 = local_112;
                                                let _e1208 = local_112;
                                                let _e1209 = select(_e1208, _e1205, (_e1205 < _e1206));
                                                local_334 = _e1209;
                                                local_121 = type_25(_e1202.member, _e1202.member_1, _e1202.member_2, _e1202.member_3, _e1202.member_4, _e1202.member_5, _e1202.member_6, _e1209, _e1202.member_8, _e1202.member_9, _e1202.member_10, _e1202.member_11, _e1202.member_12, _e1202.member_13, _e1202.member_14);
                                                phi_866_ = (_e1209 - 1u);
                                                phi_869_ = 0u;
                                                loop {
                                                    let _e1228 = phi_866_;
                                                    let _e1230 = phi_869_;
                                                    local_122 = _e1228;
                                                    local_123 = _e1230;
                                                    let _e1231 = local_123;
                                                    let _e1232 = local_122;
                                                    let _e1233 = (_e1231 < _e1232);
                                                    local_124 = _e1233;
                                                    if _e1233 {
                                                        let _e1234 = local_123;
                                                        let _e1235 = local_122;
                                                        let _e1236 = (_e1234 + _e1235);
                                                        let _e1237 = (_e1236 / 2u);
                                                        local_125 = _e1237;
                                                        if ((_e1236 % 2u) > 0u) {
                                                            let _e1240 = local_125;
                                                            phi_893_ = (_e1240 + 1u);
                                                        } else {
                                                            phi_893_ = _e1237;
                                                        }
                                                        let _e1243 = phi_893_;
                                                        local_126 = _e1243;
                                                        let _e1244 = local_334;
                                                        if (_e1243 < _e1244) {
                                                            let _e1246 = local_126;
                                                            let _e1247 = local_118;
                                                            let _e1249 = local_119;
                                                            let _e1250 = (_e1249 + (_e1246 * _e1247));
                                                            local_127 = _e1250;
                                                            let _e1251 = local_7;
                                                            if (_e1250 < _e1251) {
                                                            } else {
                                                                phi_2847_ = true;
                                                                break;
                                                            }
                                                            let _e1253 = local_127;
                                                            let _e1256 = global_10.member[_e1253];
                                                            phi_909_ = _e1256;
                                                        } else {
                                                            phi_909_ = 4294967295u;
                                                        }
                                                        let _e1258 = phi_909_;
                                                        let _e1259 = local_109;
                                                        let _e1260 = (_e1258 <= _e1259);
                                                        local_128 = _e1260;
                                                        if _e1260 {
                                                            phi_915_ = _e1228;
                                                        } else {
                                                            let _e1261 = local_126;
                                                            phi_915_ = (_e1261 - 1u);
                                                        }
                                                        let _e1264 = phi_915_;
                                                        let _e1265 = local_128;
                                                        let _e1266 = local_126;
                                                        let _e1267 = local_123;
                                                        phi_867_ = _e1264;
                                                        phi_870_ = select(_e1267, _e1266, _e1265);
                                                    } else {
                                                        phi_867_ = u32();
                                                        phi_870_ = u32();
                                                    }
                                                    let _e1270 = phi_867_;
                                                    let _e1272 = phi_870_;
                                                    continue;
                                                    continuing {
                                                        let _e1273 = local_124;
                                                        phi_866_ = _e1270;
                                                        phi_869_ = _e1272;
                                                        phi_2847_ = _e1046;
                                                        break if !(_e1273);
                                                    }
                                                }
                                                let _e1276 = phi_2847_;
                                                phi_2891_ = _e1276;
                                                if _e1276 {
                                                    break;
                                                }
                                                let _e1277 = local_333;
                                                phi_919_ = (_e1277 - 1u);
                                                phi_922_ = 0u;
                                                loop {
                                                    let _e1280 = phi_919_;
                                                    let _e1282 = phi_922_;
                                                    local_129 = _e1280;
                                                    local_130 = _e1282;
                                                    let _e1283 = local_130;
                                                    let _e1284 = local_129;
                                                    let _e1285 = (_e1283 < _e1284);
                                                    local_131 = _e1285;
                                                    if _e1285 {
                                                        let _e1286 = local_130;
                                                        let _e1287 = local_129;
                                                        let _e1288 = (_e1286 + _e1287);
                                                        let _e1289 = (_e1288 / 2u);
                                                        local_132 = _e1289;
                                                        if ((_e1288 % 2u) > 0u) {
                                                            let _e1292 = local_132;
                                                            phi_946_ = (_e1292 + 1u);
                                                        } else {
                                                            phi_946_ = _e1289;
                                                        }
                                                        let _e1295 = phi_946_;
                                                        local_133 = _e1295;
                                                        let _e1296 = local_123;
                                                        let _e1297 = local_334;
                                                        if (_e1296 < _e1297) {
                                                            let _e1299 = local_123;
                                                            let _e1300 = local_118;
                                                            let _e1302 = local_119;
                                                            let _e1304 = local_133;
                                                            let _e1305 = ((_e1302 + (_e1299 * _e1300)) + _e1304);
                                                            local_134 = _e1305;
                                                            let _e1306 = local_7;
                                                            if (_e1305 < _e1306) {
                                                            } else {
                                                                phi_2856_ = true;
                                                                break;
                                                            }
                                                            let _e1308 = local_134;
                                                            let _e1311 = global_10.member[_e1308];
                                                            phi_962_ = _e1311;
                                                        } else {
                                                            phi_962_ = 4294967295u;
                                                        }
                                                        let _e1313 = phi_962_;
                                                        let _e1314 = local_109;
                                                        let _e1315 = (_e1313 <= _e1314);
                                                        local_135 = _e1315;
                                                        if _e1315 {
                                                            phi_968_ = _e1280;
                                                        } else {
                                                            let _e1316 = local_133;
                                                            phi_968_ = (_e1316 - 1u);
                                                        }
                                                        let _e1319 = phi_968_;
                                                        let _e1320 = local_135;
                                                        let _e1321 = local_133;
                                                        let _e1322 = local_130;
                                                        phi_920_ = _e1319;
                                                        phi_923_ = select(_e1322, _e1321, _e1320);
                                                    } else {
                                                        phi_920_ = u32();
                                                        phi_923_ = u32();
                                                    }
                                                    let _e1325 = phi_920_;
                                                    let _e1327 = phi_923_;
                                                    continue;
                                                    continuing {
                                                        let _e1328 = local_131;
                                                        phi_919_ = _e1325;
                                                        phi_922_ = _e1327;
                                                        phi_2856_ = _e1276;
                                                        break if !(_e1328);
                                                    }
                                                }
                                                let _e1331 = phi_2856_;
                                                phi_2891_ = _e1331;
                                                if _e1331 {
                                                    break;
                                                }
                                                let _e1332 = local_130;
                                                let _e1333 = local_121;
                                                let _e1349 = type_25(_e1333.member, _e1333.member_1, _e1333.member_2, _e1333.member_3, _e1333.member_4, _e1333.member_5, _e1333.member_6, _e1333.member_7, _e1332, _e1333.member_9, _e1333.member_10, _e1333.member_11, _e1333.member_12, _e1333.member_13, _e1333.member_14);
                                                let _e1350 = local_123;
                                                local_136 = type_25(_e1349.member, _e1349.member_1, _e1349.member_2, _e1349.member_3, _e1349.member_4, _e1349.member_5, _e1349.member_6, _e1349.member_7, _e1349.member_8, _e1350, _e1349.member_10, _e1349.member_11, _e1349.member_12, _e1349.member_13, _e1349.member_14);
                                                let _e1367 = local_123;
                                                let _e1368 = local_334;
                                                let _e1369 = (_e1367 < _e1368);
                                                local_137 = _e1369;
                                                if _e1369 {
                                                    let _e1370 = local_123;
                                                    let _e1371 = local_118;
                                                    let _e1373 = local_119;
                                                    let _e1375 = local_130;
                                                    let _e1376 = ((_e1373 + (_e1370 * _e1371)) + _e1375);
                                                    local_138 = _e1376;
                                                    let _e1377 = local_7;
                                                    if (_e1376 < _e1377) {
                                                    } else {
                                                        phi_2891_ = true;
                                                        break;
                                                    }
                                                    let _e1379 = local_138;
                                                    let _e1382 = global_10.member[_e1379];
                                                    phi_987_ = _e1382;
                                                } else {
                                                    phi_987_ = 4294967295u;
                                                }
                                                let _e1384 = phi_987_;
                                                let _e1385 = local_136;
                                                local_139 = type_25(_e1385.member, _e1385.member_1, _e1385.member_2, _e1385.member_3, _e1385.member_4, _e1385.member_5, _e1385.member_6, _e1385.member_7, _e1385.member_8, _e1385.member_9, _e1384, _e1385.member_11, _e1385.member_12, _e1385.member_13, _e1385.member_14);
                                                let _e1402 = local_130;
                                                let _e1403 = (_e1402 + 1u);
                                                local_140 = _e1403;
                                                let _e1404 = local_333;
                                                if (_e1403 < _e1404) {
                                                    let _e1423 = local_137;
                                                    if _e1423 {
                                                        let _e1424 = local_123;
                                                        let _e1425 = local_118;
                                                        let _e1427 = local_119;
                                                        let _e1429 = local_140;
                                                        let _e1430 = ((_e1427 + (_e1424 * _e1425)) + _e1429);
                                                        local_141 = _e1430;
                                                        let _e1431 = local_7;
                                                        if (_e1430 < _e1431) {
                                                        } else {
                                                            phi_2891_ = true;
                                                            break;
                                                        }
                                                        let _e1433 = local_141;
                                                        let _e1436 = global_10.member[_e1433];
                                                        phi_1010_ = _e1436;
                                                    } else {
                                                        phi_1010_ = 4294967295u;
                                                    }
                                                    let _e1438 = phi_1010_;
                                                    phi_1028_ = _e1438;
                                                } else {
                                                    let _e1406 = local_123;
                                                    let _e1407 = (_e1406 + 1u);
                                                    local_142 = _e1407;
                                                    let _e1408 = local_334;
                                                    if (_e1407 < _e1408) {
                                                        let _e1410 = local_142;
                                                        let _e1411 = local_118;
                                                        let _e1413 = local_119;
                                                        let _e1414 = (_e1413 + (_e1410 * _e1411));
                                                        local_143 = _e1414;
                                                        let _e1415 = local_7;
                                                        if (_e1414 < _e1415) {
                                                        } else {
                                                            phi_2891_ = true;
                                                            break;
                                                        }
                                                        let _e1417 = local_143;
                                                        let _e1420 = global_10.member[_e1417];
                                                        phi_1027_ = _e1420;
                                                    } else {
                                                        phi_1027_ = 4294967295u;
                                                    }
                                                    let _e1422 = phi_1027_;
                                                    phi_1028_ = _e1422;
                                                }
                                                let _e1440 = phi_1028_;
                                                let _e1441 = local_139;
                                                local_144 = type_25(_e1441.member, _e1441.member_1, _e1441.member_2, _e1441.member_3, _e1441.member_4, _e1441.member_5, _e1441.member_6, _e1441.member_7, _e1441.member_8, _e1441.member_9, _e1441.member_10, _e1440, _e1441.member_12, _e1441.member_13, _e1441.member_14);
                                                let _e1458 = local_118;
                                                let _e1459 = local_120;
                                                let _e1461 = local_123;
                                                let _e1462 = local_118;
                                                let _e1464 = local_119;
                                                let _e1466 = local_130;
                                                let _e1468 = ((_e1458 * _e1459) + ((_e1464 + (_e1461 * _e1462)) + _e1466));
                                                local_145 = _e1468;
                                                let _e1469 = local_7;
                                                if (_e1468 < _e1469) {
                                                } else {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1471 = local_145;
                                                let _e1474 = global_10.member[_e1471];
                                                let _e1475 = bitcast<f32>(_e1474);
                                                let _e1476 = local_116;
                                                let _e1477 = local_130;
                                                let _e1478 = (_e1476 + _e1477);
                                                let _e1479 = local_17;
                                                let _e1482 = local_111;
                                                let _e1483 = ((_e1478 + 1u) * _e1482);
                                                let _e1486 = local_111;
                                                let _e1490 = local_117;
                                                let _e1491 = local_123;
                                                let _e1492 = (_e1490 + _e1491);
                                                let _e1493 = local_17;
                                                let _e1496 = local_111;
                                                let _e1497 = ((_e1492 + 1u) * _e1496);
                                                let _e1500 = local_111;
                                                let _e1504 = local_104;
                                                let _e1506 = local_104;
                                                let _e1509 = local_110;
                                                let _e1510 = ((_e1504.member_12 + 1u) * _e1509);
                                                let _e1513 = local_110;
                                                let _e1518 = local_110;
                                                let _e1519 = ((_e1506.member_13 + 1u) * _e1518);
                                                let _e1522 = local_110;
                                                let _e1528 = ((f32((_e1504.member_12 * _e1513)) + 0.5f) - f32(select(_e1479.member, _e1483, (_e1483 < _e1479.member))));
                                                let _e1529 = (f32((_e1478 * _e1486)) - (f32(select(_e1479.member, _e1510, (_e1510 < _e1479.member))) - 0.5f));
                                                let _e1531 = select(_e1529, _e1528, (_e1528 > _e1529));
                                                let _e1533 = select(0f, _e1531, (_e1531 > 0f));
                                                let _e1536 = ((f32((_e1506.member_13 * _e1522)) + 0.5f) - f32(select(_e1493.member_1, _e1497, (_e1497 < _e1493.member_1))));
                                                let _e1537 = (f32((_e1492 * _e1500)) - (f32(select(_e1493.member_1, _e1519, (_e1519 < _e1493.member_1))) - 0.5f));
                                                let _e1539 = select(_e1537, _e1536, (_e1536 > _e1537));
                                                let _e1541 = select(0f, _e1539, (_e1539 > 0f));
                                                let _e1547 = local_144;
                                                phi_2865_ = _e1331;
                                                phi_1140_ = type_25(_e1547.member, _e1547.member_1, _e1547.member_2, _e1547.member_3, _e1547.member_4, _e1547.member_5, _e1547.member_6, _e1547.member_7, _e1547.member_8, _e1547.member_9, _e1547.member_10, _e1547.member_11, _e1547.member_12, _e1547.member_13, (((_e1533 * _e1533) + (_e1541 * _e1541)) <= (_e1475 * _e1475)));
                                            } else {
                                                phi_2865_ = _e1046;
                                                let _e3444 = local_345;
                                                phi_1140_ = _e3444;
                                            }
                                            let _e1565 = phi_2865_;
                                            let _e1567 = phi_1140_;
                                            phi_1142_ = _e1567;
                                            loop {
                                                let _e1569 = phi_1142_;
                                                local_146 = _e1569;
                                                local_346 = _e1569;
                                                let _e1570 = local_146;
                                                local_147 = _e1570.member_11;
                                                let _e1572 = local_109;
                                                let _e1573 = (_e1570.member_11 <= _e1572);
                                                local_148 = _e1573;
                                                if _e1573 {
                                                    let _e1574 = local_146;
                                                    let _e1576 = (_e1574.member_8 + 1u);
                                                    local_149 = _e1576;
                                                    let _e1577 = local_146;
                                                    local_150 = _e1577.member_6;
                                                    let _e1579 = (_e1576 < _e1577.member_6);
                                                    local_151 = _e1579;
                                                    if _e1579 {
                                                        let _e1583 = local_146;
                                                        phi_1164_ = _e1583.member_9;
                                                    } else {
                                                        let _e1580 = local_146;
                                                        phi_1164_ = (_e1580.member_9 + 1u);
                                                    }
                                                    let _e1586 = phi_1164_;
                                                    local_152 = _e1586;
                                                    let _e1587 = local_151;
                                                    let _e1588 = local_149;
                                                    let _e1589 = select(0u, _e1588, _e1587);
                                                    local_335 = _e1589;
                                                    let _e1590 = local_146;
                                                    let _e1606 = type_25(_e1590.member, _e1590.member_1, _e1590.member_2, _e1590.member_3, _e1590.member_4, _e1590.member_5, _e1590.member_6, _e1590.member_7, _e1589, _e1590.member_9, _e1590.member_10, _e1590.member_11, _e1590.member_12, _e1590.member_13, _e1590.member_14);
                                                    local_153 = type_25(_e1606.member, _e1606.member_1, _e1606.member_2, _e1606.member_3, _e1606.member_4, _e1606.member_5, _e1606.member_6, _e1606.member_7, _e1606.member_8, _e1586, _e1606.member_10, _e1606.member_11, _e1606.member_12, _e1606.member_13, _e1606.member_14);
                                                    let _e1623 = local_146;
                                                    local_154 = _e1623.member_7;
                                                    let _e1625 = (_e1586 < _e1623.member_7);
                                                    local_155 = _e1625;
                                                    if _e1625 {
                                                        let _e1626 = local_146;
                                                        let _e1628 = local_17;
                                                        let _e1630 = local_152;
                                                        let _e1633 = local_335;
                                                        let _e1634 = ((_e1626.member_3 + (_e1630 * _e1628.member_4)) + _e1633);
                                                        local_156 = _e1634;
                                                        let _e1635 = local_7;
                                                        if (_e1634 < _e1635) {
                                                        } else {
                                                            phi_2862_ = true;
                                                            break;
                                                        }
                                                        let _e1637 = local_156;
                                                        let _e1640 = global_10.member[_e1637];
                                                        phi_1185_ = _e1640;
                                                    } else {
                                                        phi_1185_ = 4294967295u;
                                                    }
                                                    let _e1642 = phi_1185_;
                                                    let _e1643 = local_153;
                                                    local_157 = type_25(_e1643.member, _e1643.member_1, _e1643.member_2, _e1643.member_3, _e1643.member_4, _e1643.member_5, _e1643.member_6, _e1643.member_7, _e1643.member_8, _e1643.member_9, _e1642, _e1643.member_11, _e1643.member_12, _e1643.member_13, _e1643.member_14);
                                                    let _e1660 = local_335;
                                                    let _e1661 = (_e1660 + 1u);
                                                    local_158 = _e1661;
                                                    let _e1662 = local_150;
                                                    if (_e1661 < _e1662) {
                                                        let _e1683 = local_155;
                                                        if _e1683 {
                                                            let _e1684 = local_146;
                                                            let _e1686 = local_17;
                                                            let _e1688 = local_152;
                                                            let _e1691 = local_158;
                                                            let _e1692 = ((_e1684.member_3 + (_e1688 * _e1686.member_4)) + _e1691);
                                                            local_159 = _e1692;
                                                            let _e1693 = local_7;
                                                            if (_e1692 < _e1693) {
                                                            } else {
                                                                phi_2862_ = true;
                                                                break;
                                                            }
                                                            let _e1695 = local_159;
                                                            let _e1698 = global_10.member[_e1695];
                                                            phi_1211_ = _e1698;
                                                        } else {
                                                            phi_1211_ = 4294967295u;
                                                        }
                                                        let _e1700 = phi_1211_;
                                                        phi_1231_ = _e1700;
                                                    } else {
                                                        let _e1664 = local_152;
                                                        let _e1665 = (_e1664 + 1u);
                                                        local_160 = _e1665;
                                                        let _e1666 = local_154;
                                                        if (_e1665 < _e1666) {
                                                            let _e1668 = local_146;
                                                            let _e1670 = local_17;
                                                            let _e1672 = local_160;
                                                            let _e1674 = (_e1668.member_3 + (_e1672 * _e1670.member_4));
                                                            local_161 = _e1674;
                                                            let _e1675 = local_7;
                                                            if (_e1674 < _e1675) {
                                                            } else {
                                                                phi_2862_ = true;
                                                                break;
                                                            }
                                                            let _e1677 = local_161;
                                                            let _e1680 = global_10.member[_e1677];
                                                            phi_1230_ = _e1680;
                                                        } else {
                                                            phi_1230_ = 4294967295u;
                                                        }
                                                        let _e1682 = phi_1230_;
                                                        phi_1231_ = _e1682;
                                                    }
                                                    let _e1702 = phi_1231_;
                                                    let _e1703 = local_157;
                                                    local_162 = type_25(_e1703.member, _e1703.member_1, _e1703.member_2, _e1703.member_3, _e1703.member_4, _e1703.member_5, _e1703.member_6, _e1703.member_7, _e1703.member_8, _e1703.member_9, _e1703.member_10, _e1702, _e1703.member_12, _e1703.member_13, _e1703.member_14);
                                                    let _e1720 = local_17;
                                                    let _e1722 = local_17;
                                                    let _e1725 = local_146;
                                                    let _e1727 = local_152;
                                                    let _e1730 = local_335;
                                                    let _e1732 = ((_e1720.member_4 * _e1722.member_5) + ((_e1725.member_3 + (_e1727 * _e1720.member_4)) + _e1730));
                                                    local_163 = _e1732;
                                                    let _e1733 = local_7;
                                                    if (_e1732 < _e1733) {
                                                    } else {
                                                        phi_2862_ = true;
                                                        break;
                                                    }
                                                    let _e1735 = local_163;
                                                    let _e1738 = global_10.member[_e1735];
                                                    let _e1739 = bitcast<f32>(_e1738);
                                                    let _e1740 = local_146;
                                                    let _e1742 = local_335;
                                                    let _e1743 = (_e1740.member_4 + _e1742);
                                                    let _e1744 = local_17;
                                                    let _e1746 = local_17;
                                                    let _e1749 = ((_e1743 + 1u) * _e1744.member_3);
                                                    let _e1755 = local_146;
                                                    let _e1757 = local_152;
                                                    let _e1758 = (_e1755.member_5 + _e1757);
                                                    let _e1759 = local_17;
                                                    let _e1762 = ((_e1758 + 1u) * _e1744.member_3);
                                                    let _e1768 = local_146;
                                                    let _e1770 = local_146;
                                                    let _e1772 = local_17;
                                                    let _e1775 = ((_e1768.member_12 + 1u) * _e1772.member_6);
                                                    let _e1782 = ((_e1770.member_13 + 1u) * _e1772.member_6);
                                                    let _e1790 = ((f32((_e1768.member_12 * _e1772.member_6)) + 0.5f) - f32(select(_e1746.member, _e1749, (_e1749 < _e1746.member))));
                                                    let _e1791 = (f32((_e1743 * _e1744.member_3)) - (f32(select(_e1746.member, _e1775, (_e1775 < _e1746.member))) - 0.5f));
                                                    let _e1793 = select(_e1791, _e1790, (_e1790 > _e1791));
                                                    let _e1795 = select(0f, _e1793, (_e1793 > 0f));
                                                    let _e1798 = ((f32((_e1770.member_13 * _e1772.member_6)) + 0.5f) - f32(select(_e1759.member_1, _e1762, (_e1762 < _e1759.member_1))));
                                                    let _e1799 = (f32((_e1758 * _e1744.member_3)) - (f32(select(_e1759.member_1, _e1782, (_e1782 < _e1759.member_1))) - 0.5f));
                                                    let _e1801 = select(_e1799, _e1798, (_e1798 > _e1799));
                                                    let _e1803 = select(0f, _e1801, (_e1801 > 0f));
                                                    let _e1809 = local_162;
                                                    phi_1143_ = type_25(_e1809.member, _e1809.member_1, _e1809.member_2, _e1809.member_3, _e1809.member_4, _e1809.member_5, _e1809.member_6, _e1809.member_7, _e1809.member_8, _e1809.member_9, _e1809.member_10, _e1809.member_11, _e1809.member_12, _e1809.member_13, (((_e1795 * _e1795) + (_e1803 * _e1803)) <= (_e1739 * _e1739)));
                                                } else {
                                                    phi_1143_ = type_25();
                                                }
                                                let _e1827 = phi_1143_;
                                                continue;
                                                continuing {
                                                    let _e1828 = local_148;
                                                    phi_1142_ = _e1827;
                                                    phi_2862_ = _e1565;
                                                    break if !(_e1828);
                                                }
                                            }
                                            let _e1831 = phi_2862_;
                                            phi_2891_ = _e1831;
                                            if _e1831 {
                                                break;
                                            }
                                            let _e1832 = local_146;
                                            local_164 = _e1832.member_2;
                                            let _e1834 = local_146;
                                            local_165 = _e1834.member_8;
                                            let _e1836 = local_146;
                                            local_166 = _e1836.member_9;
                                            let _e1838 = local_17;
                                            local_167 = _e1838.member_6;
                                            let _e1840 = local_17;
                                            local_168 = _e1840.member_3;
                                            if (_e1840.member_3 == 0u) {
                                                phi_2891_ = true;
                                                break;
                                            }
                                            let _e1843 = local_167;
                                            let _e1844 = local_168;
                                            let _e1845 = (_e1843 / _e1844);
                                            let _e1846 = local_164;
                                            let _e1848 = local_166;
                                            let _e1851 = local_165;
                                            let _e1853 = local_17;
                                            local_169 = _e1853.member_2;
                                            let _e1855 = local_168;
                                            let _e1857 = local_168;
                                            let _e1860 = local_146;
                                            let _e1862 = local_109;
                                            local_170 = ((((((_e1846 * _e1845) + _e1848) * _e1845) + _e1851) * ((_e1853.member_2 * _e1855) * _e1857)) + (_e1862 - _e1860.member_10));
                                            let _e1865 = local_146;
                                            if _e1865.member_14 {
                                                let _e1898 = local_170;
                                                let _e1899 = (4u * _e1898);
                                                local_171 = _e1899;
                                                let _e1900 = local_5;
                                                if (_e1899 < _e1900) {
                                                } else {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1902 = local_171;
                                                let _e1905 = global_8.member[_e1902];
                                                local_172 = _e1905;
                                                let _e1906 = local_171;
                                                let _e1907 = (_e1906 + 1u);
                                                local_173 = _e1907;
                                                let _e1908 = local_5;
                                                if (_e1907 < _e1908) {
                                                } else {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1910 = local_173;
                                                let _e1913 = global_8.member[_e1910];
                                                local_174 = _e1913;
                                                let _e1914 = local_171;
                                                let _e1915 = (_e1914 + 2u);
                                                local_175 = _e1915;
                                                let _e1916 = local_5;
                                                if (_e1915 < _e1916) {
                                                } else {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1918 = local_175;
                                                let _e1921 = global_8.member[_e1918];
                                                local_176 = _e1921;
                                                let _e1922 = local_171;
                                                let _e1923 = (_e1922 + 3u);
                                                local_177 = _e1923;
                                                let _e1924 = local_5;
                                                if (_e1923 < _e1924) {
                                                } else {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1926 = local_177;
                                                let _e1929 = global_8.member[_e1926];
                                                local_178 = _e1929;
                                                let _e1930 = local_172;
                                                local_179 = (_e1930 & 16383u);
                                                let _e1932 = local_172;
                                                local_180 = ((_e1932 >> bitcast<u32>(14u)) & 16383u);
                                                let _e1936 = local_174;
                                                local_181 = (_e1936 & 16383u);
                                                let _e1938 = local_174;
                                                let _e1940 = (_e1938 >> bitcast<u32>(24i));
                                                local_182 = _e1940;
                                                if (_e1940 == 0u) {
                                                    phi_1428_ = array<f32, 3>(0f, 0f, 0f);
                                                } else {
                                                    let _e1942 = local_182;
                                                    let _e1948 = bitcast<f32>((bitcast<u32>((bitcast<i32>(_e1942) + -13i)) << bitcast<u32>(23i)));
                                                    let _e1949 = local_179;
                                                    let _e1952 = local_180;
                                                    let _e1955 = local_181;
                                                    phi_1428_ = array<f32, 3>((f32(_e1949) * _e1948), (f32(_e1952) * _e1948), (f32(_e1955) * _e1948));
                                                }
                                                let _e1960 = phi_1428_;
                                                local_183 = _e1960;
                                                let _e1961 = local_174;
                                                let _e1964 = ((_e1961 >> bitcast<u32>(14u)) & 1023u);
                                                local_184 = _e1964;
                                                if (_e1964 >= 1023u) {
                                                    phi_1439_ = 1f;
                                                } else {
                                                    let _e1966 = local_184;
                                                    phi_1439_ = (f32(_e1966) * 0.0009775171f);
                                                }
                                                let _e1970 = phi_1439_;
                                                local_185 = _e1970;
                                                let _e1971 = local_176;
                                                let _e1972 = bitcast<f32>(_e1971);
                                                local_186 = _e1972;
                                                let _e1973 = local_172;
                                                let _e1976 = ((_e1973 >> bitcast<u32>(28i)) & 3u);
                                                local_187 = _e1976;
                                                let _e1977 = local_178;
                                                let _e1979 = local_178;
                                                let _e1982 = array<u32, 2>((_e1977 & 65535u), (_e1979 >> bitcast<u32>(16i)));
                                                local_188 = _e1982;
                                                let _e1983 = local_183;
                                                let _e1985 = local_86;
                                                let _e1988 = ((_e1985 >> bitcast<u32>(8u)) & 7u);
                                                local_189 = _e1988;
                                                if (_e1988 == 0u) {
                                                    phi_1511_ = type_22(_e1982, _e1983, _e1970, _e1972, _e1976, 0u);
                                                } else {
                                                    let _e1990 = local_189;
                                                    let _e1991 = local_189;
                                                    let _e1992 = (_e1990 * _e1991);
                                                    local_190 = _e1992;
                                                    if (_e1992 <= 1u) {
                                                        phi_1464_ = 1u;
                                                    } else {
                                                        let _e1994 = local_190;
                                                        phi_1464_ = select(16u, 4u, (_e1994 <= 4u));
                                                    }
                                                    let _e1998 = phi_1464_;
                                                    local_191 = _e1998;
                                                    if (_e1998 == 0u) {
                                                        phi_2891_ = true;
                                                        break;
                                                    }
                                                    let _e2000 = local_191;
                                                    local_192 = (32u / _e2000);
                                                    let _e2002 = local_191;
                                                    if (_e2002 >= 32u) {
                                                        phi_1477_ = 4294967295u;
                                                    } else {
                                                        let _e2004 = local_191;
                                                        phi_1477_ = ((1u << bitcast<u32>((_e2004 & 31u))) - 1u);
                                                    }
                                                    let _e2010 = phi_1477_;
                                                    local_193 = _e2010;
                                                    let _e2011 = local_17;
                                                    let _e2013 = local_20;
                                                    let _e2015 = local_167;
                                                    let _e2017 = local_167;
                                                    let _e2019 = local_169;
                                                    local_194 = (4u * ((((_e2013 * _e2011.member_8) * _e2015) * _e2017) * _e2019));
                                                    let _e2022 = local_192;
                                                    let _e2023 = (_e2022 == 0u);
                                                    local_195 = _e2023;
                                                    if _e2023 {
                                                        phi_2891_ = true;
                                                        break;
                                                    }
                                                    let _e2024 = local_170;
                                                    let _e2025 = local_192;
                                                    let _e2027 = local_194;
                                                    local_196 = (_e2027 + (_e2024 / _e2025));
                                                    let _e2029 = local_195;
                                                    if _e2029 {
                                                        phi_2891_ = true;
                                                        break;
                                                    }
                                                    let _e2030 = local_170;
                                                    let _e2031 = local_192;
                                                    let _e2033 = local_191;
                                                    local_197 = ((_e2030 % _e2031) * _e2033);
                                                    let _e2035 = local_196;
                                                    let _e2036 = local_5;
                                                    if (_e2035 < _e2036) {
                                                    } else {
                                                        phi_2891_ = true;
                                                        break;
                                                    }
                                                    let _e2038 = local_196;
                                                    let _e2041 = global_8.member[_e2038];
                                                    let _e2042 = local_197;
                                                    let _e2046 = local_193;
                                                    let _e2048 = local_188;
                                                    let _e2049 = local_183;
                                                    let _e2050 = local_185;
                                                    let _e2051 = local_186;
                                                    let _e2052 = local_187;
                                                    phi_1511_ = type_22(_e2048, _e2049, _e2050, _e2051, _e2052, ((_e2041 >> bitcast<u32>((_e2042 & 31u))) & _e2046));
                                                }
                                                let _e2055 = phi_1511_;
                                                local_198 = _e2055;
                                                if (_e2055.member_5 != 0u) {
                                                    phi_1522_ = 1.4142135f;
                                                } else {
                                                    let _e2058 = local_198;
                                                    phi_1522_ = (0.5f * f32((1u << bitcast<u32>((_e2058.member_4 & 31u)))));
                                                }
                                                let _e2066 = phi_1522_;
                                                local_199 = _e2066;
                                                let _e2067 = local_198;
                                                local_200 = _e2067.member_3;
                                                let _e2069 = bitcast<u32>(_e2067.member_3);
                                                local_201 = _e2069;
                                                if (_e2069 == 2139095040u) {
                                                    let _e2111 = local_17;
                                                    let _e2115 = local_17;
                                                    let _e2119 = local_17;
                                                    let _e2124 = local_17;
                                                    phi_1577_ = (0.5f * ((((2f * _e2111.member_15.member_1) * _e2115.member_15.member) / (_e2119.member_15.member_2 - _e2115.member_15.member)) * _e2124.member_15.member_3));
                                                } else {
                                                    let _e2071 = local_201;
                                                    if (_e2071 == 0u) {
                                                        phi_1546_ = false;
                                                    } else {
                                                        let _e2073 = local_201;
                                                        phi_1546_ = (_e2073 <= 2139095040u);
                                                    }
                                                    let _e2076 = phi_1546_;
                                                    if _e2076 {
                                                        let _e2077 = local_17;
                                                        let _e2081 = local_17;
                                                        let _e2085 = local_17;
                                                        local_202 = _e2085.member_15.member_2;
                                                        let _e2090 = local_17;
                                                        let _e2093 = ((((2f * _e2077.member_15.member_1) * _e2081.member_15.member) / (_e2085.member_15.member_2 - _e2081.member_15.member)) * _e2090.member_15.member_3);
                                                        local_203 = _e2093;
                                                        if (_e2093 == 0f) {
                                                            phi_1568_ = 0f;
                                                        } else {
                                                            let _e2095 = local_202;
                                                            let _e2096 = local_200;
                                                            let _e2099 = local_203;
                                                            phi_1568_ = (_e2099 * (1f - (_e2095 / _e2096)));
                                                        }
                                                        let _e2102 = phi_1568_;
                                                        phi_1569_ = _e2102;
                                                    } else {
                                                        phi_1569_ = bitcast<f32>(_e406);
                                                    }
                                                    let _e2104 = phi_1569_;
                                                    local_204 = _e2104;
                                                    if (_e2104 < 0f) {
                                                        let _e2106 = local_204;
                                                        phi_1575_ = -(_e2106);
                                                    } else {
                                                        phi_1575_ = _e2104;
                                                    }
                                                    let _e2109 = phi_1575_;
                                                    phi_1577_ = (0.5f * _e2109);
                                                }
                                                let _e2130 = phi_1577_;
                                                let _e2135 = local_199;
                                                let _e2136 = (select(_e2130, 0f, ((bitcast<u32>(_e2130) & 2147483647u) > 2139095040u)) + _e2135);
                                                let _e2137 = local_19;
                                                let _e2139 = local_19;
                                                let _e2140 = select(_e2139, _e2136, (_e2136 < _e2137));
                                                let _e2142 = select(0.5f, _e2140, (_e2140 > 0.5f));
                                                local_336 = _e2142;
                                                let _e2143 = local_198;
                                                let _e2147 = (f32(_e2143.member[0]) * 0.5f);
                                                let _e2148 = local_198;
                                                let _e2152 = (f32(_e2148.member[1]) * 0.5f);
                                                let _e2153 = local_17;
                                                let _e2155 = local_15;
                                                let _e2157 = local_167;
                                                let _e2158 = ((_e2155 + 1u) * _e2157);
                                                let _e2161 = local_15;
                                                let _e2162 = local_167;
                                                let _e2166 = local_17;
                                                let _e2168 = local_16;
                                                let _e2170 = local_167;
                                                let _e2171 = ((_e2168 + 1u) * _e2170);
                                                let _e2174 = local_16;
                                                let _e2175 = local_167;
                                                let _e2181 = ((f32((_e2161 * _e2162)) + 0.5f) - _e2147);
                                                let _e2182 = (_e2147 - (f32(select(_e2153.member, _e2158, (_e2158 < _e2153.member))) - 0.5f));
                                                let _e2184 = select(_e2182, _e2181, (_e2181 > _e2182));
                                                let _e2186 = select(0f, _e2184, (_e2184 > 0f));
                                                let _e2189 = ((f32((_e2174 * _e2175)) + 0.5f) - _e2152);
                                                let _e2190 = (_e2152 - (f32(select(_e2166.member_1, _e2171, (_e2171 < _e2166.member_1))) - 0.5f));
                                                let _e2192 = select(_e2190, _e2189, (_e2189 > _e2190));
                                                let _e2194 = select(0f, _e2192, (_e2192 > 0f));
                                                if (((_e2186 * _e2186) + (_e2194 * _e2194)) <= (_e2142 * _e2142)) {
                                                    let _e2200 = local_146;
                                                    let _e2202 = local_165;
                                                    let _e2204 = local_146;
                                                    let _e2206 = local_166;
                                                    local_205 = ((_e2200.member_4 + _e2202) | (_e2204.member_5 + _e2206));
                                                    phi_1674_ = 0u;
                                                    loop {
                                                        let _e2210 = phi_1674_;
                                                        local_206 = _e2210;
                                                        let _e2211 = local_206;
                                                        let _e2212 = local_27;
                                                        if (_e2211 < _e2212) {
                                                            let _e2214 = local_206;
                                                            let _e2215 = (_e2214 + 1u);
                                                            let _e2217 = local_168;
                                                            let _e2222 = local_336;
                                                            let _e2223 = (_e2222 >= f32((2u * (_e2217 << bitcast<u32>((_e2215 & 31u))))));
                                                            phi_1675_ = select(u32(), _e2215, _e2223);
                                                            phi_1695_ = _e2223;
                                                        } else {
                                                            phi_1675_ = u32();
                                                            phi_1695_ = false;
                                                        }
                                                        let _e2226 = phi_1675_;
                                                        let _e2228 = phi_1695_;
                                                        local_207 = _e2228;
                                                        continue;
                                                        continuing {
                                                            let _e2229 = local_207;
                                                            phi_1674_ = _e2226;
                                                            break if !(_e2229);
                                                        }
                                                    }
                                                    let _e2231 = local_206;
                                                    let _e2236 = local_205;
                                                    if ((_e2236 & ((1u << bitcast<u32>((_e2231 & 31u))) - 1u)) == 0u) {
                                                        let _e2239 = local_102;
                                                        let _e2243 = local_101;
                                                        phi_1711_ = (_e2243 | (1u << bitcast<u32>((_e2239 & 31u))));
                                                    } else {
                                                        phi_1711_ = _e991;
                                                    }
                                                    let _e2246 = phi_1711_;
                                                    phi_1712_ = _e2246;
                                                } else {
                                                    phi_1712_ = _e991;
                                                }
                                                let _e2248 = phi_1712_;
                                                let _e2249 = local_102;
                                                phi_1749_ = _e2248;
                                                phi_1750_ = (_e2249 + 1u);
                                            } else {
                                                let _e1867 = local_146;
                                                local_208 = _e1867.member;
                                                if (_e1867.member == 0u) {
                                                    phi_1729_ = 0u;
                                                } else {
                                                    let _e1870 = local_83;
                                                    let _e1871 = local_208;
                                                    let _e1873 = ((_e1870 + _e1871) - 1u);
                                                    local_209 = _e1873;
                                                    if (_e1873 < 1792u) {
                                                    } else {
                                                        phi_2891_ = true;
                                                        break;
                                                    }
                                                    let _e1875 = local_209;
                                                    let _e1877 = global_12[_e1875];
                                                    phi_1729_ = _e1877;
                                                }
                                                let _e1879 = phi_1729_;
                                                local_210 = _e1879;
                                                let _e1880 = local_83;
                                                let _e1881 = local_208;
                                                let _e1882 = (_e1880 + _e1881);
                                                local_211 = _e1882;
                                                if (_e1882 < 1792u) {
                                                } else {
                                                    phi_2891_ = true;
                                                    break;
                                                }
                                                let _e1884 = local_211;
                                                let _e1886 = global_12[_e1884];
                                                let _e1887 = local_210;
                                                let _e1889 = local_147;
                                                if (_e1889 < (_e1886 - _e1887)) {
                                                    let _e1891 = local_210;
                                                    let _e1892 = local_147;
                                                    phi_1747_ = (_e1891 + _e1892);
                                                } else {
                                                    phi_1747_ = _e1886;
                                                }
                                                let _e1895 = phi_1747_;
                                                let _e1896 = local_92;
                                                phi_1749_ = _e991;
                                                phi_1750_ = (_e1895 - _e1896);
                                            }
                                            let _e2252 = phi_1749_;
                                            let _e2254 = phi_1750_;
                                            phi_2893_ = _e1831;
                                            phi_1751_ = _e2252;
                                            let _e3477 = local_346;
                                            phi_1752_ = _e3477;
                                            phi_1753_ = _e2254;
                                        } else {
                                            phi_2893_ = _e989;
                                            phi_1751_ = u32();
                                            phi_1752_ = type_25();
                                            phi_1753_ = u32();
                                        }
                                        let _e2256 = phi_2893_;
                                        let _e2258 = phi_1751_;
                                        let _e2260 = phi_1752_;
                                        let _e2262 = phi_1753_;
                                        phi_2892_ = _e2256;
                                        phi_731_ = _e2258;
                                        phi_734_ = _e2260;
                                        phi_736_ = _e2262;
                                        phi_1754_ = _e1003;
                                    } else {
                                        phi_2892_ = _e989;
                                        phi_731_ = u32();
                                        phi_734_ = type_25();
                                        phi_736_ = u32();
                                        phi_1754_ = false;
                                    }
                                    let _e2264 = phi_2892_;
                                    let _e2266 = phi_731_;
                                    let _e2268 = phi_734_;
                                    let _e2270 = phi_736_;
                                    let _e2272 = phi_1754_;
                                    local_212 = _e2272;
                                    continue;
                                    continuing {
                                        let _e2273 = local_212;
                                        phi_2845_ = _e2264;
                                        phi_730_ = _e2266;
                                        phi_733_ = _e2268;
                                        phi_735_ = _e2270;
                                        phi_2891_ = _e2264;
                                        break if !(_e2273);
                                    }
                                }
                                let _e2276 = phi_2891_;
                                phi_3004_ = _e2276;
                                if _e2276 {
                                    break;
                                }
                                phi_2928_ = _e2276;
                                let _e3488 = local_347;
                                phi_1759_ = _e3488;
                            } else {
                                phi_2928_ = _e899;
                                phi_1759_ = _e946;
                            }
                            let _e2278 = phi_2928_;
                            let _e2280 = phi_1759_;
                            local_213 = _e2280;
                            local_214 = countOneBits(_e2280);
                            let _e2282 = local;
                            if (_e2282 < 1792u) {
                            } else {
                                phi_3004_ = true;
                                break;
                            }
                            let _e2284 = local;
                            let _e2286 = local_214;
                            global_12[_e2284] = _e2286;
                            let _e2287 = local;
                            let _e2288 = (512u + _e2287);
                            local_215 = _e2288;
                            let _e2289 = (_e2288 < 1792u);
                            local_216 = _e2289;
                            if _e2289 {
                            } else {
                                phi_3004_ = true;
                                break;
                            }
                            let _e2290 = local_215;
                            let _e2292 = local_213;
                            global_12[_e2290] = _e2292;
                            storageBarrier();
                            workgroupBarrier();
                            let _e2293 = local_44;
                            if _e2293 {
                                let _e2294 = local_1;
                                let _e2296 = local_1;
                                if ((_e2296 & (_e2294 - 1u)) == 0u) {
                                    let _e2299 = local_2;
                                    let _e2300 = local_1;
                                    let _e2302 = ((_e2299 * _e2300) == 256u);
                                    local_217 = _e2302;
                                    if _e2302 {
                                        let _e2303 = local_1;
                                        phi_1791_ = type_16(1u, _e2303);
                                    } else {
                                        phi_1791_ = type_16();
                                    }
                                    let _e2306 = phi_1791_;
                                    let _e2307 = local_217;
                                    phi_1793_ = _e2306;
                                    phi_1794_ = select(true, false, _e2307);
                                } else {
                                    phi_1793_ = type_16();
                                    phi_1794_ = true;
                                }
                                let _e2310 = phi_1793_;
                                let _e2312 = phi_1794_;
                                phi_1795_ = _e2310;
                                phi_1796_ = _e2312;
                            } else {
                                phi_1795_ = type_16();
                                phi_1796_ = true;
                            }
                            let _e2314 = phi_1795_;
                            let _e2316 = phi_1796_;
                            if _e2316 {
                                phi_1801_ = type_16(0u, type_16().member_1);
                            } else {
                                phi_1801_ = _e2314;
                            }
                            let _e2321 = phi_1801_;
                            local_218 = _e2321.member_1;
                            if (bitcast<i32>(_e2321.member) != 0i) {
                                let _e2375 = local_218;
                                let _e2377 = local_218;
                                local_219 = select(firstTrailingBit(_e2375), 32u, (_e2377 == 0u));
                                let _e2380 = local_3;
                                let _e2381 = local_1;
                                let _e2383 = local_4;
                                let _e2384 = ((_e2380 * _e2381) + _e2383);
                                local_220 = _e2384;
                                if (_e2384 < 1792u) {
                                } else {
                                    phi_3004_ = true;
                                    break;
                                }
                                let _e2386 = local_220;
                                let _e2388 = global_12[_e2386];
                                let _e2389 = subgroupInclusiveAdd(_e2388);
                                local_221 = _e2389;
                                let _e2390 = local_220;
                                let _e2391 = (256u + _e2390);
                                local_222 = _e2391;
                                if (_e2391 < 1792u) {
                                } else {
                                    phi_3004_ = true;
                                    break;
                                }
                                let _e2393 = local_222;
                                let _e2395 = local_221;
                                global_12[_e2393] = _e2395;
                                storageBarrier();
                                workgroupBarrier();
                                phi_1838_ = 0u;
                                phi_1841_ = 256u;
                                phi_1842_ = 256u;
                                phi_1844_ = 0u;
                                loop {
                                    let _e2397 = phi_1838_;
                                    let _e2399 = phi_1841_;
                                    let _e2401 = phi_1842_;
                                    let _e2403 = phi_1844_;
                                    local_223 = _e2397;
                                    local_224 = _e2399;
                                    local_225 = _e2401;
                                    local_226 = _e2403;
                                    local_348 = _e2399;
                                    local_349 = _e2401;
                                    local_350 = _e2403;
                                    let _e2404 = local_225;
                                    let _e2405 = local_218;
                                    let _e2406 = (_e2404 > _e2405);
                                    local_227 = _e2406;
                                    if _e2406 {
                                        let _e2407 = local_219;
                                        let _e2408 = (_e2407 & 31u);
                                        local_228 = _e2408;
                                        let _e2409 = local_225;
                                        let _e2411 = (_e2409 >> bitcast<u32>(_e2408));
                                        local_229 = _e2411;
                                        let _e2412 = local_220;
                                        let _e2413 = (_e2412 < _e2411);
                                        local_230 = _e2413;
                                        if _e2413 {
                                            let _e2414 = local_220;
                                            let _e2416 = local_228;
                                            let _e2419 = local_224;
                                            let _e2421 = ((_e2419 + ((_e2414 + 1u) << bitcast<u32>(_e2416))) - 1u);
                                            local_231 = _e2421;
                                            if (_e2421 < 1792u) {
                                            } else {
                                                phi_2934_ = true;
                                                break;
                                            }
                                            let _e2423 = local_231;
                                            let _e2425 = global_12[_e2423];
                                            phi_1872_ = _e2425;
                                        } else {
                                            phi_1872_ = 0u;
                                        }
                                        let _e2427 = phi_1872_;
                                        let _e2428 = subgroupInclusiveAdd(_e2427);
                                        local_232 = _e2428;
                                        let _e2429 = local_230;
                                        if _e2429 {
                                            let _e2430 = local_223;
                                            let _e2431 = local_220;
                                            let _e2432 = (_e2430 + _e2431);
                                            local_233 = _e2432;
                                            if (_e2432 < 1792u) {
                                            } else {
                                                phi_2934_ = true;
                                                break;
                                            }
                                            let _e2434 = local_233;
                                            let _e2436 = local_232;
                                            global_12[_e2434] = _e2436;
                                        }
                                        storageBarrier();
                                        workgroupBarrier();
                                        let _e2437 = local_223;
                                        let _e2438 = local_229;
                                        let _e2440 = local_226;
                                        phi_1839_ = (_e2437 + _e2438);
                                        phi_1843_ = _e2411;
                                        phi_1845_ = (_e2440 + 1u);
                                    } else {
                                        phi_1839_ = u32();
                                        phi_1843_ = u32();
                                        phi_1845_ = u32();
                                    }
                                    let _e2443 = phi_1839_;
                                    let _e2445 = phi_1843_;
                                    let _e2447 = phi_1845_;
                                    continue;
                                    continuing {
                                        let _e2448 = local_227;
                                        phi_1838_ = _e2443;
                                        phi_1841_ = _e2397;
                                        phi_1842_ = _e2445;
                                        phi_1844_ = _e2447;
                                        phi_2934_ = _e2278;
                                        break if !(_e2448);
                                    }
                                }
                                let _e2451 = phi_2934_;
                                phi_3004_ = _e2451;
                                if _e2451 {
                                    break;
                                }
                                let _e3512 = local_348;
                                phi_1894_ = _e3512;
                                let _e3515 = local_349;
                                phi_1897_ = _e3515;
                                let _e3518 = local_350;
                                phi_1899_ = _e3518;
                                loop {
                                    let _e2453 = phi_1894_;
                                    let _e2455 = phi_1897_;
                                    let _e2457 = phi_1899_;
                                    local_234 = _e2453;
                                    local_235 = _e2455;
                                    local_236 = _e2457;
                                    let _e2458 = local_236;
                                    let _e2459 = (_e2458 > 0u);
                                    local_237 = _e2459;
                                    if _e2459 {
                                        let _e2460 = local_219;
                                        let _e2461 = (_e2460 & 31u);
                                        local_238 = _e2461;
                                        let _e2462 = local_235;
                                        let _e2464 = (_e2462 << bitcast<u32>(_e2461));
                                        local_239 = _e2464;
                                        let _e2465 = local_236;
                                        if (_e2465 == 1u) {
                                            phi_1914_ = 256u;
                                        } else {
                                            let _e2467 = local_234;
                                            let _e2468 = local_239;
                                            phi_1914_ = (_e2467 - _e2468);
                                        }
                                        let _e2471 = phi_1914_;
                                        local_240 = _e2471;
                                        let _e2472 = local;
                                        let _e2473 = local_218;
                                        if (_e2472 >= _e2473) {
                                            let _e2475 = local;
                                            let _e2476 = local_239;
                                            if (_e2475 < _e2476) {
                                                let _e2478 = local_240;
                                                let _e2479 = local;
                                                local_241 = (_e2478 + _e2479);
                                                let _e2481 = local;
                                                let _e2482 = local_238;
                                                let _e2485 = local_234;
                                                let _e2487 = ((_e2485 + (_e2481 >> bitcast<u32>(_e2482))) - 1u);
                                                local_242 = _e2487;
                                                if (_e2487 < 1792u) {
                                                } else {
                                                    phi_2939_ = true;
                                                    break;
                                                }
                                                let _e2489 = local_242;
                                                let _e2491 = global_12[_e2489];
                                                local_243 = _e2491;
                                                let _e2492 = local_241;
                                                let _e2493 = (_e2492 < 1792u);
                                                local_244 = _e2493;
                                                if _e2493 {
                                                } else {
                                                    phi_2939_ = true;
                                                    break;
                                                }
                                                let _e2494 = local_241;
                                                let _e2496 = global_12[_e2494];
                                                let _e2497 = local_243;
                                                local_245 = (_e2497 + _e2496);
                                                let _e2499 = local_244;
                                                if _e2499 {
                                                } else {
                                                    phi_2939_ = true;
                                                    break;
                                                }
                                                let _e2500 = local_245;
                                                global_12[_e2494] = _e2500;
                                            }
                                        }
                                        storageBarrier();
                                        workgroupBarrier();
                                        let _e2501 = local_236;
                                        phi_1895_ = _e2471;
                                        phi_1898_ = _e2464;
                                        phi_1900_ = (_e2501 - 1u);
                                    } else {
                                        phi_1895_ = u32();
                                        phi_1898_ = u32();
                                        phi_1900_ = u32();
                                    }
                                    let _e2504 = phi_1895_;
                                    let _e2506 = phi_1898_;
                                    let _e2508 = phi_1900_;
                                    continue;
                                    continuing {
                                        let _e2509 = local_237;
                                        phi_1894_ = _e2504;
                                        phi_1897_ = _e2506;
                                        phi_1899_ = _e2508;
                                        phi_2939_ = _e2451;
                                        break if !(_e2509);
                                    }
                                }
                                let _e2512 = phi_2939_;
                                phi_3004_ = _e2512;
                                if _e2512 {
                                    break;
                                }
                                phi_2949_ = _e2512;
                                phi_2005_ = 256u;
                            } else {
                                phi_1951_ = 1u;
                                phi_1954_ = 0u;
                                loop {
                                    let _e2327 = phi_1951_;
                                    let _e2329 = phi_1954_;
                                    local_246 = _e2327;
                                    local_247 = _e2329;
                                    local_351 = _e2329;
                                    let _e2330 = local_246;
                                    let _e2331 = (_e2330 < 256u);
                                    local_248 = _e2331;
                                    if _e2331 {
                                        let _e2332 = local_247;
                                        let _e2334 = select(0u, 256u, (_e2332 == 0u));
                                        local_337 = _e2334;
                                        let _e2335 = local_247;
                                        let _e2336 = local;
                                        let _e2337 = (_e2335 + _e2336);
                                        local_249 = _e2337;
                                        if (_e2337 < 1792u) {
                                        } else {
                                            phi_2923_ = true;
                                            break;
                                        }
                                        let _e2339 = local_249;
                                        let _e2341 = global_12[_e2339];
                                        local_250 = _e2341;
                                        let _e2342 = local;
                                        let _e2343 = local_246;
                                        if (_e2342 >= _e2343) {
                                            let _e2345 = local;
                                            let _e2346 = local_246;
                                            let _e2348 = local_247;
                                            let _e2349 = (_e2348 + (_e2345 - _e2346));
                                            local_251 = _e2349;
                                            if (_e2349 < 1792u) {
                                            } else {
                                                phi_2923_ = true;
                                                break;
                                            }
                                            let _e2351 = local_251;
                                            let _e2353 = global_12[_e2351];
                                            let _e2354 = local_250;
                                            phi_1990_ = (_e2353 + _e2354);
                                        } else {
                                            phi_1990_ = _e2341;
                                        }
                                        let _e2357 = phi_1990_;
                                        local_252 = _e2357;
                                        let _e2358 = local_337;
                                        let _e2359 = local;
                                        let _e2360 = (_e2358 + _e2359);
                                        local_253 = _e2360;
                                        if (_e2360 < 1792u) {
                                        } else {
                                            phi_2923_ = true;
                                            break;
                                        }
                                        let _e2362 = local_253;
                                        let _e2364 = local_252;
                                        global_12[_e2362] = _e2364;
                                        storageBarrier();
                                        workgroupBarrier();
                                        let _e2365 = local_246;
                                        phi_1952_ = (_e2365 * 2u);
                                        phi_1955_ = _e2334;
                                    } else {
                                        phi_1952_ = u32();
                                        phi_1955_ = u32();
                                    }
                                    let _e2368 = phi_1952_;
                                    let _e2370 = phi_1955_;
                                    continue;
                                    continuing {
                                        let _e2371 = local_248;
                                        phi_1951_ = _e2368;
                                        phi_1954_ = _e2370;
                                        phi_2923_ = _e2278;
                                        break if !(_e2371);
                                    }
                                }
                                let _e2374 = phi_2923_;
                                phi_3004_ = _e2374;
                                if _e2374 {
                                    break;
                                }
                                phi_2949_ = _e2374;
                                let _e3527 = local_351;
                                phi_2005_ = _e3527;
                            }
                            let _e2514 = phi_2949_;
                            let _e2516 = phi_2005_;
                            local_254 = _e2516;
                            let _e2517 = local_24;
                            let _e2518 = local_90;
                            local_255 = (_e2517 + _e2518);
                            let _e2520 = local;
                            if (_e2520 == 0u) {
                                phi_2020_ = 0u;
                            } else {
                                let _e2522 = local_254;
                                let _e2523 = local;
                                let _e2525 = ((_e2522 + _e2523) - 1u);
                                local_256 = _e2525;
                                if (_e2525 < 1792u) {
                                } else {
                                    phi_3004_ = true;
                                    break;
                                }
                                let _e2527 = local_256;
                                let _e2529 = global_12[_e2527];
                                phi_2020_ = _e2529;
                            }
                            let _e2531 = phi_2020_;
                            let _e2532 = local_255;
                            let _e2534 = local_216;
                            if _e2534 {
                            } else {
                                phi_3004_ = true;
                                break;
                            }
                            let _e2535 = global_12[_e2290];
                            local_257 = _e2535;
                            if (_e2535 == 0u) {
                                phi_2955_ = _e2514;
                                phi_2065_ = 0u;
                            } else {
                                phi_2037_ = 255u;
                                phi_2040_ = 0u;
                                loop {
                                    let _e2538 = phi_2037_;
                                    let _e2540 = phi_2040_;
                                    local_258 = _e2538;
                                    local_259 = _e2540;
                                    local_352 = _e2540;
                                    let _e2541 = local_259;
                                    let _e2542 = local_258;
                                    let _e2543 = (_e2541 < _e2542);
                                    local_260 = _e2543;
                                    if _e2543 {
                                        let _e2544 = local_259;
                                        let _e2545 = local_258;
                                        let _e2547 = ((_e2544 + _e2545) / 2u);
                                        local_261 = _e2547;
                                        let _e2548 = local_83;
                                        let _e2549 = (_e2548 + _e2547);
                                        local_262 = _e2549;
                                        if (_e2549 < 1792u) {
                                        } else {
                                            phi_2945_ = true;
                                            break;
                                        }
                                        let _e2551 = local_262;
                                        let _e2553 = global_12[_e2551];
                                        let _e2554 = local_92;
                                        let _e2555 = (_e2553 > _e2554);
                                        local_263 = _e2555;
                                        if _e2555 {
                                            phi_2064_ = _e2540;
                                        } else {
                                            let _e2556 = local_261;
                                            phi_2064_ = (_e2556 + 1u);
                                        }
                                        let _e2559 = phi_2064_;
                                        let _e2560 = local_263;
                                        let _e2561 = local_261;
                                        let _e2562 = local_258;
                                        phi_2038_ = select(_e2562, _e2561, _e2560);
                                        phi_2041_ = _e2559;
                                    } else {
                                        phi_2038_ = u32();
                                        phi_2041_ = u32();
                                    }
                                    let _e2565 = phi_2038_;
                                    let _e2567 = phi_2041_;
                                    continue;
                                    continuing {
                                        let _e2568 = local_260;
                                        phi_2037_ = _e2565;
                                        phi_2040_ = _e2567;
                                        phi_2945_ = _e2514;
                                        break if !(_e2568);
                                    }
                                }
                                let _e2571 = phi_2945_;
                                phi_3004_ = _e2571;
                                if _e2571 {
                                    break;
                                }
                                phi_2955_ = _e2571;
                                let _e3538 = local_352;
                                phi_2065_ = _e3538;
                            }
                            let _e2573 = phi_2955_;
                            let _e2575 = phi_2065_;
                            let _e2576 = local_15;
                            let _e2577 = local_16;
                            phi_2954_ = _e2573;
                            phi_2068_ = type_25(_e2575, 4294967295u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, _e2576, _e2577, false);
                            phi_2071_ = 0u;
                            phi_2073_ = (_e2532 + _e2531);
                            loop {
                                let _e2580 = phi_2954_;
                                let _e2582 = phi_2068_;
                                let _e2584 = phi_2071_;
                                let _e2586 = phi_2073_;
                                local_264 = _e2584;
                                local_265 = _e2586;
                                let _e2587 = local_264;
                                let _e2588 = local_332;
                                let _e2589 = (_e2587 < _e2588);
                                local_266 = _e2589;
                                if _e2589 {
                                    let _e2590 = local_264;
                                    let _e2594 = local_257;
                                    if ((_e2594 & (1u << bitcast<u32>((_e2590 & 31u)))) == 0u) {
                                        phi_3003_ = _e2580;
                                        phi_2731_ = _e2582;
                                        phi_2732_ = _e2586;
                                    } else {
                                        let _e2597 = local_92;
                                        let _e2598 = local_264;
                                        local_267 = (_e2597 + _e2598);
                                        phi_2090_ = _e2582;
                                        loop {
                                            let _e2601 = phi_2090_;
                                            local_268 = _e2601;
                                            local_353 = _e2601;
                                            let _e2602 = local_268;
                                            local_269 = _e2602.member;
                                            if (_e2602.member < 255u) {
                                                let _e2605 = local_83;
                                                let _e2606 = local_269;
                                                let _e2607 = (_e2605 + _e2606);
                                                local_270 = _e2607;
                                                if (_e2607 < 1792u) {
                                                } else {
                                                    phi_2951_ = true;
                                                    break;
                                                }
                                                let _e2609 = local_270;
                                                let _e2611 = global_12[_e2609];
                                                let _e2612 = local_267;
                                                let _e2613 = (_e2611 <= _e2612);
                                                if _e2613 {
                                                    let _e2614 = local_269;
                                                    let _e2616 = local_268;
                                                    phi_2116_ = type_25((_e2614 + 1u), _e2616.member_1, _e2616.member_2, _e2616.member_3, _e2616.member_4, _e2616.member_5, _e2616.member_6, _e2616.member_7, _e2616.member_8, _e2616.member_9, _e2616.member_10, _e2616.member_11, _e2616.member_12, _e2616.member_13, _e2616.member_14);
                                                } else {
                                                    phi_2116_ = type_25();
                                                }
                                                let _e2634 = phi_2116_;
                                                phi_2091_ = _e2634;
                                                phi_2117_ = _e2613;
                                            } else {
                                                phi_2091_ = type_25();
                                                phi_2117_ = false;
                                            }
                                            let _e2636 = phi_2091_;
                                            let _e2638 = phi_2117_;
                                            local_271 = _e2638;
                                            continue;
                                            continuing {
                                                let _e2639 = local_271;
                                                phi_2090_ = _e2636;
                                                phi_2951_ = _e2580;
                                                break if !(_e2639);
                                            }
                                        }
                                        let _e2642 = phi_2951_;
                                        phi_3001_ = _e2642;
                                        if _e2642 {
                                            break;
                                        }
                                        let _e2643 = local_269;
                                        if (_e2643 == 0u) {
                                            phi_2137_ = 0u;
                                        } else {
                                            let _e2645 = local_83;
                                            let _e2646 = local_269;
                                            let _e2648 = ((_e2645 + _e2646) - 1u);
                                            local_272 = _e2648;
                                            if (_e2648 < 1792u) {
                                            } else {
                                                phi_3001_ = true;
                                                break;
                                            }
                                            let _e2650 = local_272;
                                            let _e2652 = global_12[_e2650];
                                            phi_2137_ = _e2652;
                                        }
                                        let _e2654 = phi_2137_;
                                        let _e2655 = local_267;
                                        local_273 = (_e2655 - _e2654);
                                        let _e2657 = local_268;
                                        let _e2659 = local_269;
                                        if (_e2657.member_1 != _e2659) {
                                            let _e2661 = local_17;
                                            local_274 = _e2661.member_6;
                                            let _e2663 = local_17;
                                            local_275 = _e2663.member_3;
                                            if (_e2663.member_3 == 0u) {
                                                phi_3001_ = true;
                                                break;
                                            }
                                            let _e2666 = local_274;
                                            let _e2667 = local_275;
                                            local_276 = (_e2666 / _e2667);
                                            let _e2669 = local_269;
                                            let _e2670 = (1280u + _e2669);
                                            local_277 = _e2670;
                                            if (_e2670 < 1792u) {
                                            } else {
                                                phi_3001_ = true;
                                                break;
                                            }
                                            let _e2672 = local_277;
                                            let _e2674 = global_12[_e2672];
                                            local_278 = _e2674;
                                            let _e2675 = local_20;
                                            let _e2676 = (_e2675 == 0u);
                                            local_279 = _e2676;
                                            if _e2676 {
                                                phi_3001_ = true;
                                                break;
                                            }
                                            let _e2677 = local_278;
                                            let _e2678 = local_20;
                                            let _e2680 = local_276;
                                            local_280 = ((_e2677 % _e2678) * _e2680);
                                            let _e2682 = local_279;
                                            if _e2682 {
                                                phi_3001_ = true;
                                                break;
                                            }
                                            let _e2683 = local_278;
                                            let _e2684 = local_20;
                                            let _e2686 = local_276;
                                            let _e2687 = ((_e2683 / _e2684) * _e2686);
                                            let _e2688 = local_269;
                                            let _e2689 = local_268;
                                            let _e2705 = type_25(_e2689.member, _e2688, _e2689.member_2, _e2689.member_3, _e2689.member_4, _e2689.member_5, _e2689.member_6, _e2689.member_7, _e2689.member_8, _e2689.member_9, _e2689.member_10, _e2689.member_11, _e2689.member_12, _e2689.member_13, _e2689.member_14);
                                            let _e2706 = local_278;
                                            let _e2722 = type_25(_e2705.member, _e2705.member_1, _e2706, _e2705.member_3, _e2705.member_4, _e2705.member_5, _e2705.member_6, _e2705.member_7, _e2705.member_8, _e2705.member_9, _e2705.member_10, _e2705.member_11, _e2705.member_12, _e2705.member_13, _e2705.member_14);
                                            let _e2723 = local_17;
                                            local_281 = _e2723.member_4;
                                            let _e2726 = local_280;
                                            let _e2727 = ((_e2687 * _e2723.member_4) + _e2726);
                                            local_282 = _e2727;
                                            let _e2743 = type_25(_e2722.member, _e2722.member_1, _e2722.member_2, _e2727, _e2722.member_4, _e2722.member_5, _e2722.member_6, _e2722.member_7, _e2722.member_8, _e2722.member_9, _e2722.member_10, _e2722.member_11, _e2722.member_12, _e2722.member_13, _e2722.member_14);
                                            let _e2744 = local_280;
                                            let _e2760 = type_25(_e2743.member, _e2743.member_1, _e2743.member_2, _e2743.member_3, _e2744, _e2743.member_5, _e2743.member_6, _e2743.member_7, _e2743.member_8, _e2743.member_9, _e2743.member_10, _e2743.member_11, _e2743.member_12, _e2743.member_13, _e2743.member_14);
                                            let _e2776 = type_25(_e2760.member, _e2760.member_1, _e2760.member_2, _e2760.member_3, _e2760.member_4, _e2687, _e2760.member_6, _e2760.member_7, _e2760.member_8, _e2760.member_9, _e2760.member_10, _e2760.member_11, _e2760.member_12, _e2760.member_13, _e2760.member_14);
                                            let _e2777 = local_280;
                                            let _e2778 = (_e2723.member_4 - _e2777);
                                            let _e2779 = local_276;
                                            let _e2781 = local_276;
                                            let _e2782 = select(_e2781, _e2778, (_e2778 < _e2779));
                                            local_338 = _e2782;
                                            let _e2798 = type_25(_e2776.member, _e2776.member_1, _e2776.member_2, _e2776.member_3, _e2776.member_4, _e2776.member_5, _e2782, _e2776.member_7, _e2776.member_8, _e2776.member_9, _e2776.member_10, _e2776.member_11, _e2776.member_12, _e2776.member_13, _e2776.member_14);
                                            let _e2799 = local_17;
                                            local_283 = _e2799.member_5;
                                            let _e2801 = (_e2799.member_5 - _e2687);
                                            let _e2802 = local_276;
                                            let _e2804 = local_276;
                                            let _e2805 = select(_e2804, _e2801, (_e2801 < _e2802));
                                            local_339 = _e2805;
                                            local_284 = type_25(_e2798.member, _e2798.member_1, _e2798.member_2, _e2798.member_3, _e2798.member_4, _e2798.member_5, _e2798.member_6, _e2805, _e2798.member_8, _e2798.member_9, _e2798.member_10, _e2798.member_11, _e2798.member_12, _e2798.member_13, _e2798.member_14);
                                            phi_2206_ = (_e2805 - 1u);
                                            phi_2209_ = 0u;
                                            loop {
                                                let _e2824 = phi_2206_;
                                                let _e2826 = phi_2209_;
                                                local_285 = _e2824;
                                                local_286 = _e2826;
                                                let _e2827 = local_286;
                                                let _e2828 = local_285;
                                                let _e2829 = (_e2827 < _e2828);
                                                local_287 = _e2829;
                                                if _e2829 {
                                                    let _e2830 = local_286;
                                                    let _e2831 = local_285;
                                                    let _e2832 = (_e2830 + _e2831);
                                                    let _e2833 = (_e2832 / 2u);
                                                    local_288 = _e2833;
                                                    if ((_e2832 % 2u) > 0u) {
                                                        let _e2836 = local_288;
                                                        phi_2233_ = (_e2836 + 1u);
                                                    } else {
                                                        phi_2233_ = _e2833;
                                                    }
                                                    let _e2839 = phi_2233_;
                                                    local_289 = _e2839;
                                                    let _e2840 = local_339;
                                                    if (_e2839 < _e2840) {
                                                        let _e2842 = local_289;
                                                        let _e2843 = local_281;
                                                        let _e2845 = local_282;
                                                        let _e2846 = (_e2845 + (_e2842 * _e2843));
                                                        local_290 = _e2846;
                                                        let _e2847 = local_7;
                                                        if (_e2846 < _e2847) {
                                                        } else {
                                                            phi_2957_ = true;
                                                            break;
                                                        }
                                                        let _e2849 = local_290;
                                                        let _e2852 = global_10.member[_e2849];
                                                        phi_2249_ = _e2852;
                                                    } else {
                                                        phi_2249_ = 4294967295u;
                                                    }
                                                    let _e2854 = phi_2249_;
                                                    let _e2855 = local_273;
                                                    let _e2856 = (_e2854 <= _e2855);
                                                    local_291 = _e2856;
                                                    if _e2856 {
                                                        phi_2255_ = _e2824;
                                                    } else {
                                                        let _e2857 = local_289;
                                                        phi_2255_ = (_e2857 - 1u);
                                                    }
                                                    let _e2860 = phi_2255_;
                                                    let _e2861 = local_291;
                                                    let _e2862 = local_289;
                                                    let _e2863 = local_286;
                                                    phi_2207_ = _e2860;
                                                    phi_2210_ = select(_e2863, _e2862, _e2861);
                                                } else {
                                                    phi_2207_ = u32();
                                                    phi_2210_ = u32();
                                                }
                                                let _e2866 = phi_2207_;
                                                let _e2868 = phi_2210_;
                                                continue;
                                                continuing {
                                                    let _e2869 = local_287;
                                                    phi_2206_ = _e2866;
                                                    phi_2209_ = _e2868;
                                                    phi_2957_ = _e2642;
                                                    break if !(_e2869);
                                                }
                                            }
                                            let _e2872 = phi_2957_;
                                            phi_3001_ = _e2872;
                                            if _e2872 {
                                                break;
                                            }
                                            let _e2873 = local_338;
                                            phi_2259_ = (_e2873 - 1u);
                                            phi_2262_ = 0u;
                                            loop {
                                                let _e2876 = phi_2259_;
                                                let _e2878 = phi_2262_;
                                                local_292 = _e2876;
                                                local_293 = _e2878;
                                                let _e2879 = local_293;
                                                let _e2880 = local_292;
                                                let _e2881 = (_e2879 < _e2880);
                                                local_294 = _e2881;
                                                if _e2881 {
                                                    let _e2882 = local_293;
                                                    let _e2883 = local_292;
                                                    let _e2884 = (_e2882 + _e2883);
                                                    let _e2885 = (_e2884 / 2u);
                                                    local_295 = _e2885;
                                                    if ((_e2884 % 2u) > 0u) {
                                                        let _e2888 = local_295;
                                                        phi_2286_ = (_e2888 + 1u);
                                                    } else {
                                                        phi_2286_ = _e2885;
                                                    }
                                                    let _e2891 = phi_2286_;
                                                    local_296 = _e2891;
                                                    let _e2892 = local_286;
                                                    let _e2893 = local_339;
                                                    if (_e2892 < _e2893) {
                                                        let _e2895 = local_286;
                                                        let _e2896 = local_281;
                                                        let _e2898 = local_282;
                                                        let _e2900 = local_296;
                                                        let _e2901 = ((_e2898 + (_e2895 * _e2896)) + _e2900);
                                                        local_297 = _e2901;
                                                        let _e2902 = local_7;
                                                        if (_e2901 < _e2902) {
                                                        } else {
                                                            phi_2966_ = true;
                                                            break;
                                                        }
                                                        let _e2904 = local_297;
                                                        let _e2907 = global_10.member[_e2904];
                                                        phi_2302_ = _e2907;
                                                    } else {
                                                        phi_2302_ = 4294967295u;
                                                    }
                                                    let _e2909 = phi_2302_;
                                                    let _e2910 = local_273;
                                                    let _e2911 = (_e2909 <= _e2910);
                                                    local_298 = _e2911;
                                                    if _e2911 {
                                                        phi_2308_ = _e2876;
                                                    } else {
                                                        let _e2912 = local_296;
                                                        phi_2308_ = (_e2912 - 1u);
                                                    }
                                                    let _e2915 = phi_2308_;
                                                    let _e2916 = local_298;
                                                    let _e2917 = local_296;
                                                    let _e2918 = local_293;
                                                    phi_2260_ = _e2915;
                                                    phi_2263_ = select(_e2918, _e2917, _e2916);
                                                } else {
                                                    phi_2260_ = u32();
                                                    phi_2263_ = u32();
                                                }
                                                let _e2921 = phi_2260_;
                                                let _e2923 = phi_2263_;
                                                continue;
                                                continuing {
                                                    let _e2924 = local_294;
                                                    phi_2259_ = _e2921;
                                                    phi_2262_ = _e2923;
                                                    phi_2966_ = _e2872;
                                                    break if !(_e2924);
                                                }
                                            }
                                            let _e2927 = phi_2966_;
                                            phi_3001_ = _e2927;
                                            if _e2927 {
                                                break;
                                            }
                                            let _e2928 = local_293;
                                            let _e2929 = local_284;
                                            let _e2945 = type_25(_e2929.member, _e2929.member_1, _e2929.member_2, _e2929.member_3, _e2929.member_4, _e2929.member_5, _e2929.member_6, _e2929.member_7, _e2928, _e2929.member_9, _e2929.member_10, _e2929.member_11, _e2929.member_12, _e2929.member_13, _e2929.member_14);
                                            let _e2946 = local_286;
                                            local_299 = type_25(_e2945.member, _e2945.member_1, _e2945.member_2, _e2945.member_3, _e2945.member_4, _e2945.member_5, _e2945.member_6, _e2945.member_7, _e2945.member_8, _e2946, _e2945.member_10, _e2945.member_11, _e2945.member_12, _e2945.member_13, _e2945.member_14);
                                            let _e2963 = local_286;
                                            let _e2964 = local_339;
                                            let _e2965 = (_e2963 < _e2964);
                                            local_300 = _e2965;
                                            if _e2965 {
                                                let _e2966 = local_286;
                                                let _e2967 = local_281;
                                                let _e2969 = local_282;
                                                let _e2971 = local_293;
                                                let _e2972 = ((_e2969 + (_e2966 * _e2967)) + _e2971);
                                                local_301 = _e2972;
                                                let _e2973 = local_7;
                                                if (_e2972 < _e2973) {
                                                } else {
                                                    phi_3001_ = true;
                                                    break;
                                                }
                                                let _e2975 = local_301;
                                                let _e2978 = global_10.member[_e2975];
                                                phi_2327_ = _e2978;
                                            } else {
                                                phi_2327_ = 4294967295u;
                                            }
                                            let _e2980 = phi_2327_;
                                            let _e2981 = local_299;
                                            local_302 = type_25(_e2981.member, _e2981.member_1, _e2981.member_2, _e2981.member_3, _e2981.member_4, _e2981.member_5, _e2981.member_6, _e2981.member_7, _e2981.member_8, _e2981.member_9, _e2980, _e2981.member_11, _e2981.member_12, _e2981.member_13, _e2981.member_14);
                                            let _e2998 = local_293;
                                            let _e2999 = (_e2998 + 1u);
                                            local_303 = _e2999;
                                            let _e3000 = local_338;
                                            if (_e2999 < _e3000) {
                                                let _e3019 = local_300;
                                                if _e3019 {
                                                    let _e3020 = local_286;
                                                    let _e3021 = local_281;
                                                    let _e3023 = local_282;
                                                    let _e3025 = local_303;
                                                    let _e3026 = ((_e3023 + (_e3020 * _e3021)) + _e3025);
                                                    local_304 = _e3026;
                                                    let _e3027 = local_7;
                                                    if (_e3026 < _e3027) {
                                                    } else {
                                                        phi_3001_ = true;
                                                        break;
                                                    }
                                                    let _e3029 = local_304;
                                                    let _e3032 = global_10.member[_e3029];
                                                    phi_2350_ = _e3032;
                                                } else {
                                                    phi_2350_ = 4294967295u;
                                                }
                                                let _e3034 = phi_2350_;
                                                phi_2368_ = _e3034;
                                            } else {
                                                let _e3002 = local_286;
                                                let _e3003 = (_e3002 + 1u);
                                                local_305 = _e3003;
                                                let _e3004 = local_339;
                                                if (_e3003 < _e3004) {
                                                    let _e3006 = local_305;
                                                    let _e3007 = local_281;
                                                    let _e3009 = local_282;
                                                    let _e3010 = (_e3009 + (_e3006 * _e3007));
                                                    local_306 = _e3010;
                                                    let _e3011 = local_7;
                                                    if (_e3010 < _e3011) {
                                                    } else {
                                                        phi_3001_ = true;
                                                        break;
                                                    }
                                                    let _e3013 = local_306;
                                                    let _e3016 = global_10.member[_e3013];
                                                    phi_2367_ = _e3016;
                                                } else {
                                                    phi_2367_ = 4294967295u;
                                                }
                                                let _e3018 = phi_2367_;
                                                phi_2368_ = _e3018;
                                            }
                                            let _e3036 = phi_2368_;
                                            let _e3037 = local_302;
                                            let _e3054 = local_281;
                                            let _e3055 = local_283;
                                            let _e3057 = local_286;
                                            let _e3058 = local_281;
                                            let _e3060 = local_282;
                                            let _e3062 = local_293;
                                            let _e3065 = local_7;
                                            if (((_e3054 * _e3055) + ((_e3060 + (_e3057 * _e3058)) + _e3062)) < _e3065) {
                                            } else {
                                                phi_3001_ = true;
                                                break;
                                            }
                                            phi_2975_ = _e2927;
                                            phi_2480_ = type_25(_e3037.member, _e3037.member_1, _e3037.member_2, _e3037.member_3, _e3037.member_4, _e3037.member_5, _e3037.member_6, _e3037.member_7, _e3037.member_8, _e3037.member_9, _e3037.member_10, _e3036, _e3037.member_12, _e3037.member_13, _e3037.member_14);
                                        } else {
                                            phi_2975_ = _e2642;
                                            let _e3572 = local_353;
                                            phi_2480_ = _e3572;
                                        }
                                        let _e3068 = phi_2975_;
                                        let _e3070 = phi_2480_;
                                        phi_2482_ = _e3070;
                                        loop {
                                            let _e3072 = phi_2482_;
                                            local_307 = _e3072;
                                            local_354 = _e3072;
                                            let _e3073 = local_307;
                                            let _e3075 = local_273;
                                            let _e3076 = (_e3073.member_11 <= _e3075);
                                            local_308 = _e3076;
                                            if _e3076 {
                                                let _e3077 = local_307;
                                                let _e3079 = (_e3077.member_8 + 1u);
                                                local_309 = _e3079;
                                                let _e3080 = local_307;
                                                local_310 = _e3080.member_6;
                                                let _e3082 = (_e3079 < _e3080.member_6);
                                                local_311 = _e3082;
                                                if _e3082 {
                                                    let _e3086 = local_307;
                                                    phi_2504_ = _e3086.member_9;
                                                } else {
                                                    let _e3083 = local_307;
                                                    phi_2504_ = (_e3083.member_9 + 1u);
                                                }
                                                let _e3089 = phi_2504_;
                                                local_312 = _e3089;
                                                let _e3090 = local_311;
                                                let _e3091 = local_309;
                                                let _e3092 = select(0u, _e3091, _e3090);
                                                local_340 = _e3092;
                                                let _e3093 = local_307;
                                                let _e3109 = type_25(_e3093.member, _e3093.member_1, _e3093.member_2, _e3093.member_3, _e3093.member_4, _e3093.member_5, _e3093.member_6, _e3093.member_7, _e3092, _e3093.member_9, _e3093.member_10, _e3093.member_11, _e3093.member_12, _e3093.member_13, _e3093.member_14);
                                                local_313 = type_25(_e3109.member, _e3109.member_1, _e3109.member_2, _e3109.member_3, _e3109.member_4, _e3109.member_5, _e3109.member_6, _e3109.member_7, _e3109.member_8, _e3089, _e3109.member_10, _e3109.member_11, _e3109.member_12, _e3109.member_13, _e3109.member_14);
                                                let _e3126 = local_307;
                                                local_314 = _e3126.member_7;
                                                let _e3128 = (_e3089 < _e3126.member_7);
                                                local_315 = _e3128;
                                                if _e3128 {
                                                    let _e3129 = local_307;
                                                    let _e3131 = local_17;
                                                    let _e3133 = local_312;
                                                    let _e3136 = local_340;
                                                    let _e3137 = ((_e3129.member_3 + (_e3133 * _e3131.member_4)) + _e3136);
                                                    local_316 = _e3137;
                                                    let _e3138 = local_7;
                                                    if (_e3137 < _e3138) {
                                                    } else {
                                                        phi_2972_ = true;
                                                        break;
                                                    }
                                                    let _e3140 = local_316;
                                                    let _e3143 = global_10.member[_e3140];
                                                    phi_2525_ = _e3143;
                                                } else {
                                                    phi_2525_ = 4294967295u;
                                                }
                                                let _e3145 = phi_2525_;
                                                let _e3146 = local_313;
                                                local_317 = type_25(_e3146.member, _e3146.member_1, _e3146.member_2, _e3146.member_3, _e3146.member_4, _e3146.member_5, _e3146.member_6, _e3146.member_7, _e3146.member_8, _e3146.member_9, _e3145, _e3146.member_11, _e3146.member_12, _e3146.member_13, _e3146.member_14);
                                                let _e3163 = local_340;
                                                let _e3164 = (_e3163 + 1u);
                                                local_318 = _e3164;
                                                let _e3165 = local_310;
                                                if (_e3164 < _e3165) {
                                                    let _e3186 = local_315;
                                                    if _e3186 {
                                                        let _e3187 = local_307;
                                                        let _e3189 = local_17;
                                                        let _e3191 = local_312;
                                                        let _e3194 = local_318;
                                                        let _e3195 = ((_e3187.member_3 + (_e3191 * _e3189.member_4)) + _e3194);
                                                        local_319 = _e3195;
                                                        let _e3196 = local_7;
                                                        if (_e3195 < _e3196) {
                                                        } else {
                                                            phi_2972_ = true;
                                                            break;
                                                        }
                                                        let _e3198 = local_319;
                                                        let _e3201 = global_10.member[_e3198];
                                                        phi_2551_ = _e3201;
                                                    } else {
                                                        phi_2551_ = 4294967295u;
                                                    }
                                                    let _e3203 = phi_2551_;
                                                    phi_2571_ = _e3203;
                                                } else {
                                                    let _e3167 = local_312;
                                                    let _e3168 = (_e3167 + 1u);
                                                    local_320 = _e3168;
                                                    let _e3169 = local_314;
                                                    if (_e3168 < _e3169) {
                                                        let _e3171 = local_307;
                                                        let _e3173 = local_17;
                                                        let _e3175 = local_320;
                                                        let _e3177 = (_e3171.member_3 + (_e3175 * _e3173.member_4));
                                                        local_321 = _e3177;
                                                        let _e3178 = local_7;
                                                        if (_e3177 < _e3178) {
                                                        } else {
                                                            phi_2972_ = true;
                                                            break;
                                                        }
                                                        let _e3180 = local_321;
                                                        let _e3183 = global_10.member[_e3180];
                                                        phi_2570_ = _e3183;
                                                    } else {
                                                        phi_2570_ = 4294967295u;
                                                    }
                                                    let _e3185 = phi_2570_;
                                                    phi_2571_ = _e3185;
                                                }
                                                let _e3205 = phi_2571_;
                                                let _e3206 = local_317;
                                                let _e3223 = local_17;
                                                let _e3225 = local_17;
                                                let _e3228 = local_307;
                                                let _e3230 = local_312;
                                                let _e3233 = local_340;
                                                let _e3236 = local_7;
                                                if (((_e3223.member_4 * _e3225.member_5) + ((_e3228.member_3 + (_e3230 * _e3223.member_4)) + _e3233)) < _e3236) {
                                                } else {
                                                    phi_2972_ = true;
                                                    break;
                                                }
                                                phi_2483_ = type_25(_e3206.member, _e3206.member_1, _e3206.member_2, _e3206.member_3, _e3206.member_4, _e3206.member_5, _e3206.member_6, _e3206.member_7, _e3206.member_8, _e3206.member_9, _e3206.member_10, _e3205, _e3206.member_12, _e3206.member_13, _e3206.member_14);
                                            } else {
                                                phi_2483_ = type_25();
                                            }
                                            let _e3239 = phi_2483_;
                                            continue;
                                            continuing {
                                                let _e3240 = local_308;
                                                phi_2482_ = _e3239;
                                                phi_2972_ = _e3068;
                                                break if !(_e3240);
                                            }
                                        }
                                        let _e3243 = phi_2972_;
                                        phi_3001_ = _e3243;
                                        if _e3243 {
                                            break;
                                        }
                                        let _e3244 = local_307;
                                        local_322 = _e3244.member_2;
                                        let _e3246 = local_307;
                                        local_323 = _e3246.member_8;
                                        let _e3248 = local_307;
                                        local_324 = _e3248.member_9;
                                        let _e3250 = local_17;
                                        local_325 = _e3250.member_6;
                                        let _e3252 = local_17;
                                        local_326 = _e3252.member_3;
                                        if (_e3252.member_3 == 0u) {
                                            phi_3001_ = true;
                                            break;
                                        }
                                        let _e3255 = local_325;
                                        let _e3256 = local_326;
                                        let _e3257 = (_e3255 / _e3256);
                                        let _e3258 = local_322;
                                        let _e3260 = local_324;
                                        let _e3263 = local_323;
                                        let _e3265 = local_17;
                                        let _e3267 = local_326;
                                        let _e3269 = local_326;
                                        let _e3272 = local_307;
                                        let _e3274 = local_273;
                                        let _e3276 = ((((((_e3258 * _e3257) + _e3260) * _e3257) + _e3263) * ((_e3265.member_2 * _e3267) * _e3269)) + (_e3274 - _e3272.member_10));
                                        local_327 = _e3276;
                                        let _e3278 = ((4u * _e3276) + 2u);
                                        local_328 = _e3278;
                                        let _e3279 = local_5;
                                        if (_e3278 < _e3279) {
                                        } else {
                                            phi_3001_ = true;
                                            break;
                                        }
                                        let _e3281 = local_328;
                                        let _e3284 = global_8.member[_e3281];
                                        local_329 = _e3284;
                                        let _e3285 = local_265;
                                        let _e3286 = local_12;
                                        if (_e3285 < _e3286) {
                                        } else {
                                            phi_3001_ = true;
                                            break;
                                        }
                                        let _e3288 = local_265;
                                        let _e3291 = local_329;
                                        global_15.member[_e3288] = _e3291;
                                        let _e3292 = local_265;
                                        let _e3293 = local_13;
                                        if (_e3292 < _e3293) {
                                        } else {
                                            phi_3001_ = true;
                                            break;
                                        }
                                        let _e3295 = local_265;
                                        let _e3298 = local_327;
                                        global_16.member[_e3295] = _e3298;
                                        let _e3299 = local_265;
                                        phi_3003_ = _e3243;
                                        let _e3584 = local_354;
                                        phi_2731_ = _e3584;
                                        phi_2732_ = (_e3299 + 1u);
                                    }
                                    let _e3302 = phi_3003_;
                                    let _e3304 = phi_2731_;
                                    let _e3306 = phi_2732_;
                                    let _e3307 = local_264;
                                    phi_3002_ = _e3302;
                                    phi_2069_ = _e3304;
                                    phi_2072_ = (_e3307 + 1u);
                                    phi_2074_ = _e3306;
                                } else {
                                    phi_3002_ = _e2580;
                                    phi_2069_ = type_25();
                                    phi_2072_ = u32();
                                    phi_2074_ = u32();
                                }
                                let _e3310 = phi_3002_;
                                let _e3312 = phi_2069_;
                                let _e3314 = phi_2072_;
                                let _e3316 = phi_2074_;
                                continue;
                                continuing {
                                    let _e3317 = local_266;
                                    phi_2954_ = _e3310;
                                    phi_2068_ = _e3312;
                                    phi_2071_ = _e3314;
                                    phi_2073_ = _e3316;
                                    phi_3001_ = _e3310;
                                    break if !(_e3317);
                                }
                            }
                            let _e3320 = phi_3001_;
                            phi_3004_ = _e3320;
                            if _e3320 {
                                break;
                            }
                            let _e3321 = local_254;
                            let _e3322 = (_e3321 + 255u);
                            local_330 = _e3322;
                            if (_e3322 < 1792u) {
                            } else {
                                phi_3004_ = true;
                                break;
                            }
                            let _e3324 = local_330;
                            let _e3326 = global_12[_e3324];
                            storageBarrier();
                            workgroupBarrier();
                            let _e3327 = local_90;
                            let _e3329 = local_332;
                            let _e3331 = local_89;
                            let _e3333 = local_88;
                            phi_3005_ = _e3320;
                            phi_654_ = (_e3333 + 1u);
                            phi_657_ = (_e3331 + (256u * _e3329));
                            phi_659_ = (_e3327 + _e3326);
                        } else {
                            phi_3005_ = _e899;
                            phi_654_ = u32();
                            phi_657_ = u32();
                            phi_659_ = u32();
                        }
                        let _e3336 = phi_3005_;
                        let _e3338 = phi_654_;
                        let _e3340 = phi_657_;
                        let _e3342 = phi_659_;
                        continue;
                        continuing {
                            let _e3343 = local_91;
                            phi_2837_ = _e3336;
                            phi_653_ = _e3338;
                            phi_656_ = _e3340;
                            phi_658_ = _e3342;
                            phi_3004_ = _e3336;
                            break if !(_e3343);
                        }
                    }
                    let _e3346 = phi_3004_;
                    if _e3346 {
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
fn subgroups(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(subgroup_size) param_2: u32, @builtin(num_subgroups) param_3: u32, @builtin(subgroup_id) param_4: u32, @builtin(subgroup_invocation_id) param_5: u32) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    global_3 = param_3;
    global_4 = param_4;
    global_5 = param_5;
    function_();
}
