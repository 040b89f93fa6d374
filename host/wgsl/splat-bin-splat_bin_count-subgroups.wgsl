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
@group(0) @binding(5) 
var<storage, read_write> global_12: type_7;
@group(0) @binding(6) 
var<storage, read_write> global_13: type_7;
@group(0) @binding(7) 
var<storage> global_14: type_7;
var<workgroup> global_15: array<u32, 1792>;
var<private> global_16: u32 = 2143289344u;

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
    var local_15: type_18;
    var local_16: u32;
    var local_17: f32;
    var local_18: u32;
    var local_19: u32;
    var local_20: bool;
    var local_21: u32;
    var local_22: i32;
    var local_23: bool;
    var local_24: i32;
    var local_25: i32;
    var local_26: i32;
    var local_27: i32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: f32;
    var local_32: bool;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: bool;
    var local_38: bool;
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
    var local_49: bool;
    var local_50: u32;
    var local_51: u32;
    var local_52: bool;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: u32;
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
    var local_70: bool;
    var local_71: u32;
    var local_72: u32;
    var local_73: u32;
    var local_74: u32;
    var local_75: u32;
    var local_76: u32;
    var local_77: u32;
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
    var local_89: bool;
    var local_90: u32;
    var local_91: u32;
    var local_92: bool;
    var local_93: u32;
    var local_94: u32;
    var local_95: bool;
    var local_96: u32;
    var local_97: u32;
    var local_98: u32;
    var local_99: u32;
    var local_100: u32;
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
    var local_209: bool;
    var local_210: u32;
    var local_211: bool;
    var local_212: u32;
    var local_213: bool;
    var local_214: u32;
    var local_215: u32;
    var local_216: u32;
    var local_217: u32;
    var local_218: bool;
    var local_219: u32;
    var local_220: bool;
    var local_221: u32;
    var local_222: bool;
    var local_223: u32;
    var local_224: bool;
    var local_225: u32;
    var local_226: bool;
    var local_227: u32;
    var local_228: bool;
    var local_229: bool;
    var local_230: u32;
    var local_231: u32;
    var local_232: u32;
    var local_233: u32;
    var local_234: bool;
    var local_235: u32;
    var local_236: bool;
    var local_237: u32;
    var local_238: u32;
    var local_239: u32;
    var local_240: u32;
    var local_241: u32;
    var local_242: u32;
    var local_243: bool;
    var local_244: u32;
    var local_245: u32;
    var local_246: u32;
    var local_247: u32;
    var local_248: bool;
    var local_249: u32;
    var local_250: u32;
    var local_251: u32;
    var local_252: u32;
    var local_253: bool;
    var local_254: u32;
    var local_255: bool;
    var local_256: u32;
    var local_257: u32;
    var local_258: u32;
    var local_259: u32;
    var local_260: u32;
    var local_261: u32;
    var local_262: bool;
    var local_263: u32;
    var local_264: u32;
    var local_265: u32;
    var local_266: u32;
    var local_267: bool;
    var local_268: u32;
    var local_269: u32;
    var local_270: u32;
    var local_271: u32;
    var local_272: bool;
    var local_273: u32;
    var local_274: bool;
    var local_275: u32;
    var local_276: u32;
    var local_277: u32;
    var local_278: u32;
    var local_279: u32;
    var local_280: u32;
    var local_281: bool;
    var local_282: u32;
    var local_283: u32;
    var local_284: u32;
    var local_285: u32;
    var local_286: bool;
    var local_287: u32;
    var local_288: u32;
    var local_289: u32;
    var local_290: u32;
    var local_291: bool;
    var local_292: u32;
    var local_293: bool;
    var local_294: u32;
    var local_295: u32;
    var local_296: u32;
    var local_297: u32;
    var local_298: u32;
    var local_299: u32;
    var local_300: bool;
    var local_301: u32;
    var local_302: u32;
    var local_303: u32;
    var local_304: u32;
    var local_305: bool;
    var local_306: u32;
    var local_307: u32;
    var local_308: u32;
    var local_309: u32;
    var local_310: bool;
    var local_311: u32;
    var local_312: bool;
    var local_313: u32;
    var local_314: u32;
    var local_315: u32;
    var local_316: u32;
    var local_317: u32;
    var local_318: u32;
    var local_319: bool;
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
    var local_335: f32;
    var phi_332_: bool;
    var phi_343_: u32;
    var phi_345_: u32;
    var phi_346_: u32;
    var phi_347_: u32;
    var phi_348_: u32;
    var phi_349_: u32;
    var phi_350_: u32;
    var phi_351_: u32;
    var phi_352_: u32;
    var phi_353_: u32;
    var phi_354_: u32;
    var phi_355_: u32;
    var phi_356_: u32;
    var phi_387_: type_16;
    var phi_389_: type_16;
    var phi_390_: bool;
    var phi_391_: type_16;
    var phi_392_: bool;
    var phi_397_: type_16;
    var phi_547_: u32;
    var phi_550_: u32;
    var phi_586_: u32;
    var phi_548_: u32;
    var phi_551_: u32;
    var phi_2839_: bool;
    var phi_434_: u32;
    var phi_437_: u32;
    var phi_438_: u32;
    var phi_440_: u32;
    var phi_468_: u32;
    var phi_435_: u32;
    var phi_439_: u32;
    var phi_441_: u32;
    var phi_2865_: bool;
    var phi_490_: u32;
    var phi_493_: u32;
    var phi_495_: u32;
    var phi_510_: u32;
    var phi_491_: u32;
    var phi_494_: u32;
    var phi_496_: u32;
    var phi_2870_: bool;
    var phi_2882_: bool;
    var phi_601_: u32;
    var phi_2879_: bool;
    var phi_630_: u32;
    var phi_633_: u32;
    var phi_635_: u32;
    var phi_637_: u32;
    var phi_639_: u32;
    var phi_641_: u32;
    var phi_643_: u32;
    var phi_645_: u32;
    var phi_654_: u32;
    var phi_657_: u32;
    var phi_681_: u32;
    var phi_655_: u32;
    var phi_658_: u32;
    var phi_2876_: bool;
    var phi_2887_: bool;
    var phi_684_: u32;
    var phi_687_: u32;
    var phi_689_: u32;
    var phi_691_: u32;
    var phi_693_: u32;
    var phi_695_: u32;
    var phi_697_: type_25;
    var phi_699_: u32;
    var phi_714_: type_25;
    var phi_740_: type_25;
    var phi_715_: type_25;
    var phi_741_: bool;
    var phi_2884_: bool;
    var phi_761_: u32;
    var phi_830_: u32;
    var phi_833_: u32;
    var phi_857_: u32;
    var phi_873_: u32;
    var phi_879_: u32;
    var phi_831_: u32;
    var phi_834_: u32;
    var phi_2889_: bool;
    var phi_883_: u32;
    var phi_886_: u32;
    var phi_910_: u32;
    var phi_926_: u32;
    var phi_932_: u32;
    var phi_884_: u32;
    var phi_887_: u32;
    var phi_2898_: bool;
    var phi_951_: u32;
    var phi_991_: u32;
    var phi_974_: u32;
    var phi_992_: u32;
    var phi_2907_: bool;
    var phi_1104_: type_25;
    var phi_1106_: type_25;
    var phi_1128_: u32;
    var phi_1149_: u32;
    var phi_1194_: u32;
    var phi_1175_: u32;
    var phi_1195_: u32;
    var phi_1107_: type_25;
    var phi_2904_: bool;
    var phi_1802_: u32;
    var phi_1820_: u32;
    var phi_1392_: array<f32, 3>;
    var phi_1403_: f32;
    var phi_1428_: u32;
    var phi_1441_: u32;
    var phi_1475_: type_22;
    var phi_1486_: f32;
    var phi_1510_: bool;
    var phi_1532_: f32;
    var phi_1533_: f32;
    var phi_1539_: f32;
    var phi_1541_: f32;
    var phi_1642_: u32;
    var phi_1643_: u32;
    var phi_1663_: bool;
    var phi_1677_: u32;
    var phi_1678_: u32;
    var phi_1698_: bool;
    var phi_1712_: u32;
    var phi_1713_: u32;
    var phi_1733_: bool;
    var phi_1747_: u32;
    var phi_1748_: u32;
    var phi_1768_: bool;
    var phi_1780_: u32;
    var phi_1781_: u32;
    var phi_1782_: u32;
    var phi_1783_: u32;
    var phi_1784_: u32;
    var phi_1785_: u32;
    var phi_1822_: u32;
    var phi_1823_: u32;
    var phi_1824_: u32;
    var phi_1825_: u32;
    var phi_1826_: u32;
    var phi_1827_: u32;
    var phi_1828_: u32;
    var phi_2935_: bool;
    var phi_1829_: u32;
    var phi_1830_: u32;
    var phi_1831_: u32;
    var phi_1832_: u32;
    var phi_1833_: u32;
    var phi_1834_: u32;
    var phi_1835_: type_25;
    var phi_1836_: u32;
    var phi_2934_: bool;
    var phi_685_: u32;
    var phi_688_: u32;
    var phi_690_: u32;
    var phi_692_: u32;
    var phi_694_: u32;
    var phi_696_: u32;
    var phi_698_: type_25;
    var phi_700_: u32;
    var phi_1837_: bool;
    var phi_2933_: bool;
    var phi_1850_: u32;
    var phi_2974_: bool;
    var phi_631_: u32;
    var phi_634_: u32;
    var phi_636_: u32;
    var phi_638_: u32;
    var phi_640_: u32;
    var phi_642_: u32;
    var phi_644_: u32;
    var phi_646_: u32;
    var phi_2973_: bool;
    var phi_1913_: type_16;
    var phi_1915_: type_16;
    var phi_1916_: bool;
    var phi_1917_: type_16;
    var phi_1918_: bool;
    var phi_1923_: type_16;
    var phi_2020_: u32;
    var phi_2021_: u32;
    var phi_2976_: bool;
    var phi_1935_: u32;
    var phi_1938_: u32;
    var phi_1962_: u32;
    var phi_1936_: u32;
    var phi_1939_: u32;
    var phi_2984_: bool;
    var phi_2010_: u32;
    var phi_2995_: bool;
    var phi_2064_: u32;
    var phi_2081_: type_16;
    var phi_2083_: type_16;
    var phi_2084_: bool;
    var phi_2085_: type_16;
    var phi_2086_: bool;
    var phi_2091_: type_16;
    var phi_2188_: u32;
    var phi_2189_: u32;
    var phi_2990_: bool;
    var phi_2103_: u32;
    var phi_2106_: u32;
    var phi_2130_: u32;
    var phi_2104_: u32;
    var phi_2107_: u32;
    var phi_3000_: bool;
    var phi_2178_: u32;
    var phi_3011_: bool;
    var phi_2232_: u32;
    var phi_2249_: type_16;
    var phi_2251_: type_16;
    var phi_2252_: bool;
    var phi_2253_: type_16;
    var phi_2254_: bool;
    var phi_2259_: type_16;
    var phi_2356_: u32;
    var phi_2357_: u32;
    var phi_3006_: bool;
    var phi_2271_: u32;
    var phi_2274_: u32;
    var phi_2298_: u32;
    var phi_2272_: u32;
    var phi_2275_: u32;
    var phi_3016_: bool;
    var phi_2346_: u32;
    var phi_3027_: bool;
    var phi_2400_: u32;
    var phi_2417_: type_16;
    var phi_2419_: type_16;
    var phi_2420_: bool;
    var phi_2421_: type_16;
    var phi_2422_: bool;
    var phi_2427_: type_16;
    var phi_2524_: u32;
    var phi_2525_: u32;
    var phi_3022_: bool;
    var phi_2439_: u32;
    var phi_2442_: u32;
    var phi_2466_: u32;
    var phi_2440_: u32;
    var phi_2443_: u32;
    var phi_3032_: bool;
    var phi_2514_: u32;
    var phi_3043_: bool;
    var phi_2568_: u32;
    var phi_2585_: type_16;
    var phi_2587_: type_16;
    var phi_2588_: bool;
    var phi_2589_: type_16;
    var phi_2590_: bool;
    var phi_2595_: type_16;
    var phi_2692_: u32;
    var phi_2693_: u32;
    var phi_3038_: bool;
    var phi_2607_: u32;
    var phi_2610_: u32;
    var phi_2634_: u32;
    var phi_2608_: u32;
    var phi_2611_: u32;
    var phi_3048_: bool;
    var phi_2682_: u32;
    var phi_2736_: u32;
    var local_336: u32;
    var local_337: u32;
    var local_338: u32;
    var local_339: u32;
    var local_340: type_25;
    var local_341: type_25;
    var local_342: u32;
    var local_343: u32;
    var local_344: u32;
    var local_345: u32;
    var local_346: u32;

    let _e402 = global_16;
    switch bitcast<i32>(0u) {
        default: {
            let _e405 = global;
            local = _e405;
            let _e406 = global_1;
            let _e407 = global_2;
            local_1 = _e407;
            let _e408 = global_3;
            local_2 = _e408;
            let _e409 = global_4;
            local_3 = _e409;
            let _e410 = global_5;
            local_4 = _e410;
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_9.member));
            local_7 = arrayLength((&global_10.member));
            local_8 = arrayLength((&global_11.member));
            local_9 = arrayLength((&global_7.member));
            local_10 = arrayLength((&global_12.member));
            local_11 = arrayLength((&global_13.member));
            let _e427 = arrayLength((&global_14.member));
            local_12 = _e427;
            local_13 = _e406.x;
            local_14 = _e406.y;
            let _e430 = global_6.member;
            local_15 = _e430;
            if (18u < _e427) {
            } else {
                break;
            }
            let _e434 = global_14.member[18u];
            local_16 = _e434;
            let _e435 = local_12;
            if (19u < _e435) {
            } else {
                break;
            }
            let _e439 = global_14.member[19u];
            local_17 = bitcast<f32>(_e439);
            let _e441 = local_15;
            local_18 = _e441.member_7;
            let _e443 = local_14;
            let _e445 = local_13;
            let _e446 = ((_e443 * _e441.member_7) + _e445);
            local_19 = _e446;
            let _e447 = local_9;
            if (_e446 < _e447) {
            } else {
                break;
            }
            let _e449 = local_19;
            let _e452 = global_7.member[_e449];
            local_20 = (_e452 != 0u);
            let _e454 = local_16;
            let _e456 = ((2u * _e454) + 1u);
            local_21 = _e456;
            let _e458 = local;
            if (_e458 < (_e456 * _e456)) {
                let _e460 = local_20;
                if _e460 {
                    phi_353_ = 0u;
                    phi_354_ = 0u;
                } else {
                    let _e461 = local_13;
                    local_22 = bitcast<i32>(_e461);
                    let _e463 = local_21;
                    let _e464 = (_e463 == 0u);
                    local_23 = _e464;
                    if _e464 {
                        break;
                    }
                    let _e465 = local;
                    let _e466 = local_21;
                    let _e469 = local_22;
                    let _e471 = local_16;
                    let _e472 = bitcast<i32>(_e471);
                    local_24 = _e472;
                    local_25 = ((_e469 + bitcast<i32>((_e465 % _e466))) - _e472);
                    let _e474 = local_14;
                    local_26 = bitcast<i32>(_e474);
                    let _e476 = local_23;
                    if _e476 {
                        break;
                    }
                    let _e477 = local;
                    let _e478 = local_21;
                    let _e481 = local_26;
                    let _e483 = local_24;
                    local_27 = ((_e481 + bitcast<i32>((_e477 / _e478))) - _e483);
                    let _e485 = local_25;
                    if (_e485 >= 0i) {
                        let _e487 = local_27;
                        if (_e487 >= 0i) {
                            let _e489 = local_18;
                            let _e491 = local_25;
                            if (_e491 < bitcast<i32>(_e489)) {
                                let _e493 = local_15;
                                let _e496 = local_27;
                                if (_e496 < bitcast<i32>(_e493.member_8)) {
                                    let _e498 = local_27;
                                    let _e499 = bitcast<u32>(_e498);
                                    local_28 = _e499;
                                    let _e500 = local_18;
                                    let _e502 = local_25;
                                    let _e503 = bitcast<u32>(_e502);
                                    local_29 = _e503;
                                    let _e504 = ((_e499 * _e500) + _e503);
                                    local_30 = _e504;
                                    let _e505 = local_8;
                                    if (_e504 < _e505) {
                                    } else {
                                        break;
                                    }
                                    let _e507 = local_30;
                                    let _e510 = global_11.member[_e507];
                                    local_31 = bitcast<f32>(_e510);
                                    let _e512 = local_30;
                                    let _e513 = local_19;
                                    if (_e512 == _e513) {
                                        phi_332_ = true;
                                    } else {
                                        let _e515 = local_15;
                                        let _e517 = local_15;
                                        let _e519 = local_29;
                                        let _e521 = ((_e519 + 1u) * _e515.member_6);
                                        let _e524 = local_29;
                                        let _e528 = local_15;
                                        let _e530 = local_28;
                                        let _e532 = ((_e530 + 1u) * _e515.member_6);
                                        let _e535 = local_28;
                                        let _e539 = local_13;
                                        let _e541 = ((_e539 + 1u) * _e515.member_6);
                                        let _e544 = local_13;
                                        let _e548 = local_14;
                                        let _e550 = ((_e548 + 1u) * _e515.member_6);
                                        let _e553 = local_14;
                                        let _e559 = ((f32((_e544 * _e515.member_6)) + 0.5f) - f32(select(_e517.member, _e521, (_e521 < _e517.member))));
                                        let _e560 = (f32((_e524 * _e515.member_6)) - (f32(select(_e517.member, _e541, (_e541 < _e517.member))) - 0.5f));
                                        let _e562 = select(_e560, _e559, (_e559 > _e560));
                                        let _e564 = select(0f, _e562, (_e562 > 0f));
                                        let _e567 = ((f32((_e553 * _e515.member_6)) + 0.5f) - f32(select(_e528.member_1, _e532, (_e532 < _e528.member_1))));
                                        let _e568 = (f32((_e535 * _e515.member_6)) - (f32(select(_e528.member_1, _e550, (_e550 < _e528.member_1))) - 0.5f));
                                        let _e570 = select(_e568, _e567, (_e567 > _e568));
                                        let _e572 = select(0f, _e570, (_e570 > 0f));
                                        let _e576 = local_31;
                                        let _e577 = local_31;
                                        phi_332_ = (((_e564 * _e564) + (_e572 * _e572)) <= (_e576 * _e577));
                                    }
                                    let _e581 = phi_332_;
                                    local_32 = _e581;
                                    if _e581 {
                                        let _e582 = local_30;
                                        let _e583 = local_6;
                                        if (_e582 < _e583) {
                                        } else {
                                            break;
                                        }
                                        let _e585 = local_30;
                                        let _e588 = global_9.member[_e585];
                                        phi_343_ = _e588;
                                    } else {
                                        phi_343_ = 0u;
                                    }
                                    let _e590 = phi_343_;
                                    let _e591 = local_32;
                                    let _e592 = local_30;
                                    phi_345_ = _e590;
                                    phi_346_ = select(0u, _e592, _e591);
                                } else {
                                    phi_345_ = 0u;
                                    phi_346_ = 0u;
                                }
                                let _e595 = phi_345_;
                                let _e597 = phi_346_;
                                phi_347_ = _e595;
                                phi_348_ = _e597;
                            } else {
                                phi_347_ = 0u;
                                phi_348_ = 0u;
                            }
                            let _e599 = phi_347_;
                            let _e601 = phi_348_;
                            phi_349_ = _e599;
                            phi_350_ = _e601;
                        } else {
                            phi_349_ = 0u;
                            phi_350_ = 0u;
                        }
                        let _e603 = phi_349_;
                        let _e605 = phi_350_;
                        phi_351_ = _e603;
                        phi_352_ = _e605;
                    } else {
                        phi_351_ = 0u;
                        phi_352_ = 0u;
                    }
                    let _e607 = phi_351_;
                    let _e609 = phi_352_;
                    phi_353_ = _e607;
                    phi_354_ = _e609;
                }
                let _e611 = phi_353_;
                let _e613 = phi_354_;
                phi_355_ = _e611;
                phi_356_ = _e613;
            } else {
                phi_355_ = 0u;
                phi_356_ = 0u;
            }
            let _e615 = phi_355_;
            let _e617 = phi_356_;
            local_33 = _e615;
            local_34 = _e617;
            let _e618 = local;
            let _e619 = (768u + _e618);
            local_35 = _e619;
            if (_e619 < 1792u) {
            } else {
                break;
            }
            let _e621 = local_35;
            let _e623 = local_33;
            global_15[_e621] = _e623;
            let _e624 = local;
            let _e625 = (1280u + _e624);
            local_36 = _e625;
            if (_e625 < 1792u) {
            } else {
                break;
            }
            let _e627 = local_36;
            let _e629 = local_34;
            global_15[_e627] = _e629;
            storageBarrier();
            workgroupBarrier();
            let _e630 = local_1;
            let _e631 = (_e630 >= 2u);
            local_37 = _e631;
            if _e631 {
                let _e632 = local_1;
                let _e634 = local_1;
                if ((_e634 & (_e632 - 1u)) == 0u) {
                    let _e637 = local_2;
                    let _e638 = local_1;
                    let _e640 = ((_e637 * _e638) == 256u);
                    local_38 = _e640;
                    if _e640 {
                        let _e641 = local_1;
                        phi_387_ = type_16(1u, _e641);
                    } else {
                        phi_387_ = type_16();
                    }
                    let _e644 = phi_387_;
                    let _e645 = local_38;
                    phi_389_ = _e644;
                    phi_390_ = select(true, false, _e645);
                } else {
                    phi_389_ = type_16();
                    phi_390_ = true;
                }
                let _e648 = phi_389_;
                let _e650 = phi_390_;
                phi_391_ = _e648;
                phi_392_ = _e650;
            } else {
                phi_391_ = type_16();
                phi_392_ = true;
            }
            let _e652 = phi_391_;
            let _e654 = phi_392_;
            if _e654 {
                phi_397_ = type_16(0u, type_16().member_1);
            } else {
                phi_397_ = _e652;
            }
            let _e659 = phi_397_;
            local_39 = _e659.member_1;
            if (bitcast<i32>(_e659.member) != 0i) {
                let _e713 = local_39;
                let _e715 = local_39;
                local_40 = select(firstTrailingBit(_e713), 32u, (_e715 == 0u));
                let _e718 = local_3;
                let _e719 = local_1;
                let _e721 = local_4;
                let _e722 = ((_e718 * _e719) + _e721);
                local_41 = _e722;
                let _e723 = (768u + _e722);
                local_42 = _e723;
                if (_e723 < 1792u) {
                } else {
                    break;
                }
                let _e725 = local_42;
                let _e727 = global_15[_e725];
                let _e728 = subgroupInclusiveAdd(_e727);
                local_43 = _e728;
                let _e729 = local_41;
                let _e730 = (1024u + _e729);
                local_44 = _e730;
                if (_e730 < 1792u) {
                } else {
                    break;
                }
                let _e732 = local_44;
                let _e734 = local_43;
                global_15[_e732] = _e734;
                storageBarrier();
                workgroupBarrier();
                phi_434_ = 768u;
                phi_437_ = 1024u;
                phi_438_ = 256u;
                phi_440_ = 0u;
                loop {
                    let _e736 = phi_434_;
                    let _e738 = phi_437_;
                    let _e740 = phi_438_;
                    let _e742 = phi_440_;
                    local_45 = _e736;
                    local_46 = _e738;
                    local_47 = _e740;
                    local_48 = _e742;
                    local_336 = _e738;
                    local_337 = _e740;
                    local_338 = _e742;
                    let _e743 = local_47;
                    let _e744 = local_39;
                    let _e745 = (_e743 > _e744);
                    local_49 = _e745;
                    if _e745 {
                        let _e746 = local_40;
                        let _e747 = (_e746 & 31u);
                        local_50 = _e747;
                        let _e748 = local_47;
                        let _e750 = (_e748 >> bitcast<u32>(_e747));
                        local_51 = _e750;
                        let _e751 = local_41;
                        let _e752 = (_e751 < _e750);
                        local_52 = _e752;
                        if _e752 {
                            let _e753 = local_41;
                            let _e755 = local_50;
                            let _e758 = local_46;
                            let _e760 = ((_e758 + ((_e753 + 1u) << bitcast<u32>(_e755))) - 1u);
                            local_53 = _e760;
                            if (_e760 < 1792u) {
                            } else {
                                phi_2865_ = true;
                                break;
                            }
                            let _e762 = local_53;
                            let _e764 = global_15[_e762];
                            phi_468_ = _e764;
                        } else {
                            phi_468_ = 0u;
                        }
                        let _e766 = phi_468_;
                        let _e767 = subgroupInclusiveAdd(_e766);
                        local_54 = _e767;
                        let _e768 = local_52;
                        if _e768 {
                            let _e769 = local_45;
                            let _e770 = local_41;
                            let _e771 = (_e769 + _e770);
                            local_55 = _e771;
                            if (_e771 < 1792u) {
                            } else {
                                phi_2865_ = true;
                                break;
                            }
                            let _e773 = local_55;
                            let _e775 = local_54;
                            global_15[_e773] = _e775;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e776 = local_45;
                        let _e777 = local_51;
                        let _e779 = local_48;
                        phi_435_ = (_e776 + _e777);
                        phi_439_ = _e750;
                        phi_441_ = (_e779 + 1u);
                    } else {
                        phi_435_ = u32();
                        phi_439_ = u32();
                        phi_441_ = u32();
                    }
                    let _e782 = phi_435_;
                    let _e784 = phi_439_;
                    let _e786 = phi_441_;
                    continue;
                    continuing {
                        let _e787 = local_49;
                        phi_434_ = _e782;
                        phi_437_ = _e736;
                        phi_438_ = _e784;
                        phi_440_ = _e786;
                        phi_2865_ = false;
                        break if !(_e787);
                    }
                }
                let _e790 = phi_2865_;
                if _e790 {
                    break;
                }
                let _e3306 = local_336;
                phi_490_ = _e3306;
                let _e3309 = local_337;
                phi_493_ = _e3309;
                let _e3312 = local_338;
                phi_495_ = _e3312;
                loop {
                    let _e792 = phi_490_;
                    let _e794 = phi_493_;
                    let _e796 = phi_495_;
                    local_56 = _e792;
                    local_57 = _e794;
                    local_58 = _e796;
                    let _e797 = local_58;
                    let _e798 = (_e797 > 0u);
                    local_59 = _e798;
                    if _e798 {
                        let _e799 = local_40;
                        let _e800 = (_e799 & 31u);
                        local_60 = _e800;
                        let _e801 = local_57;
                        let _e803 = (_e801 << bitcast<u32>(_e800));
                        local_61 = _e803;
                        let _e804 = local_58;
                        if (_e804 == 1u) {
                            phi_510_ = 1024u;
                        } else {
                            let _e806 = local_56;
                            let _e807 = local_61;
                            phi_510_ = (_e806 - _e807);
                        }
                        let _e810 = phi_510_;
                        local_62 = _e810;
                        let _e811 = local;
                        let _e812 = local_39;
                        if (_e811 >= _e812) {
                            let _e814 = local;
                            let _e815 = local_61;
                            if (_e814 < _e815) {
                                let _e817 = local_62;
                                let _e818 = local;
                                local_63 = (_e817 + _e818);
                                let _e820 = local;
                                let _e821 = local_60;
                                let _e824 = local_56;
                                let _e826 = ((_e824 + (_e820 >> bitcast<u32>(_e821))) - 1u);
                                local_64 = _e826;
                                if (_e826 < 1792u) {
                                } else {
                                    phi_2870_ = true;
                                    break;
                                }
                                let _e828 = local_64;
                                let _e830 = global_15[_e828];
                                local_65 = _e830;
                                let _e831 = local_63;
                                let _e832 = (_e831 < 1792u);
                                local_66 = _e832;
                                if _e832 {
                                } else {
                                    phi_2870_ = true;
                                    break;
                                }
                                let _e833 = local_63;
                                let _e835 = global_15[_e833];
                                let _e836 = local_65;
                                local_67 = (_e836 + _e835);
                                let _e838 = local_66;
                                if _e838 {
                                } else {
                                    phi_2870_ = true;
                                    break;
                                }
                                let _e839 = local_67;
                                global_15[_e833] = _e839;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e840 = local_58;
                        phi_491_ = _e810;
                        phi_494_ = _e803;
                        phi_496_ = (_e840 - 1u);
                    } else {
                        phi_491_ = u32();
                        phi_494_ = u32();
                        phi_496_ = u32();
                    }
                    let _e843 = phi_491_;
                    let _e845 = phi_494_;
                    let _e847 = phi_496_;
                    continue;
                    continuing {
                        let _e848 = local_59;
                        phi_490_ = _e843;
                        phi_493_ = _e845;
                        phi_495_ = _e847;
                        phi_2870_ = _e790;
                        break if !(_e848);
                    }
                }
                let _e851 = phi_2870_;
                if _e851 {
                    break;
                }
                phi_2882_ = _e851;
                phi_601_ = 1024u;
            } else {
                phi_547_ = 1u;
                phi_550_ = 768u;
                loop {
                    let _e665 = phi_547_;
                    let _e667 = phi_550_;
                    local_68 = _e665;
                    local_69 = _e667;
                    local_339 = _e667;
                    let _e668 = local_68;
                    let _e669 = (_e668 < 256u);
                    local_70 = _e669;
                    if _e669 {
                        let _e670 = local_69;
                        let _e672 = select(768u, 1024u, (_e670 == 768u));
                        local_329 = _e672;
                        let _e673 = local_69;
                        let _e674 = local;
                        let _e675 = (_e673 + _e674);
                        local_71 = _e675;
                        if (_e675 < 1792u) {
                        } else {
                            phi_2839_ = true;
                            break;
                        }
                        let _e677 = local_71;
                        let _e679 = global_15[_e677];
                        local_72 = _e679;
                        let _e680 = local;
                        let _e681 = local_68;
                        if (_e680 >= _e681) {
                            let _e683 = local;
                            let _e684 = local_68;
                            let _e686 = local_69;
                            let _e687 = (_e686 + (_e683 - _e684));
                            local_73 = _e687;
                            if (_e687 < 1792u) {
                            } else {
                                phi_2839_ = true;
                                break;
                            }
                            let _e689 = local_73;
                            let _e691 = global_15[_e689];
                            let _e692 = local_72;
                            phi_586_ = (_e691 + _e692);
                        } else {
                            phi_586_ = _e679;
                        }
                        let _e695 = phi_586_;
                        local_74 = _e695;
                        let _e696 = local_329;
                        let _e697 = local;
                        let _e698 = (_e696 + _e697);
                        local_75 = _e698;
                        if (_e698 < 1792u) {
                        } else {
                            phi_2839_ = true;
                            break;
                        }
                        let _e700 = local_75;
                        let _e702 = local_74;
                        global_15[_e700] = _e702;
                        storageBarrier();
                        workgroupBarrier();
                        let _e703 = local_68;
                        phi_548_ = (_e703 * 2u);
                        phi_551_ = _e672;
                    } else {
                        phi_548_ = u32();
                        phi_551_ = u32();
                    }
                    let _e706 = phi_548_;
                    let _e708 = phi_551_;
                    continue;
                    continuing {
                        let _e709 = local_70;
                        phi_547_ = _e706;
                        phi_550_ = _e708;
                        phi_2839_ = false;
                        break if !(_e709);
                    }
                }
                let _e712 = phi_2839_;
                if _e712 {
                    break;
                }
                phi_2882_ = _e712;
                let _e3321 = local_339;
                phi_601_ = _e3321;
            }
            let _e853 = phi_2882_;
            let _e855 = phi_601_;
            local_76 = _e855;
            let _e856 = (_e855 + 255u);
            local_77 = _e856;
            if (_e856 < 1792u) {
            } else {
                break;
            }
            let _e858 = local_77;
            let _e860 = global_15[_e858];
            local_78 = _e860;
            let _e861 = local_15;
            local_79 = _e861.member_10;
            let _e865 = select(16u, 1u, ((_e861.member_10 & 2u) == 0u));
            local_330 = _e865;
            local_80 = (32u >> bitcast<u32>((select(firstTrailingBit(_e865), 32u, (_e865 == 0u)) & 31u)));
            let _e872 = local_76;
            local_331 = select(768u, 1024u, (_e872 == 768u));
            let _e875 = local;
            phi_2879_ = _e853;
            phi_630_ = 0u;
            phi_633_ = 0u;
            phi_635_ = 0u;
            phi_637_ = 0u;
            phi_639_ = 0u;
            phi_641_ = (_e875 * _e865);
            phi_643_ = 0u;
            phi_645_ = 0u;
            loop {
                let _e878 = phi_2879_;
                let _e880 = phi_630_;
                let _e882 = phi_633_;
                let _e884 = phi_635_;
                let _e886 = phi_637_;
                let _e888 = phi_639_;
                let _e890 = phi_641_;
                let _e892 = phi_643_;
                let _e894 = phi_645_;
                local_81 = _e880;
                local_82 = _e882;
                local_83 = _e884;
                local_84 = _e886;
                local_85 = _e888;
                local_86 = _e890;
                local_87 = _e892;
                local_88 = _e894;
                let _e895 = local_86;
                let _e896 = local_78;
                let _e897 = (_e895 < _e896);
                local_89 = _e897;
                if _e897 {
                    phi_654_ = 255u;
                    phi_657_ = 0u;
                    loop {
                        let _e899 = phi_654_;
                        let _e901 = phi_657_;
                        local_90 = _e899;
                        local_91 = _e901;
                        let _e902 = local_91;
                        let _e903 = local_90;
                        let _e904 = (_e902 < _e903);
                        local_92 = _e904;
                        if _e904 {
                            let _e905 = local_91;
                            let _e906 = local_90;
                            let _e908 = ((_e905 + _e906) / 2u);
                            local_93 = _e908;
                            let _e909 = local_76;
                            let _e910 = (_e909 + _e908);
                            local_94 = _e910;
                            if (_e910 < 1792u) {
                            } else {
                                phi_2876_ = true;
                                break;
                            }
                            let _e912 = local_94;
                            let _e914 = global_15[_e912];
                            let _e915 = local_86;
                            let _e916 = (_e914 > _e915);
                            local_95 = _e916;
                            if _e916 {
                                phi_681_ = _e901;
                            } else {
                                let _e917 = local_93;
                                phi_681_ = (_e917 + 1u);
                            }
                            let _e920 = phi_681_;
                            let _e921 = local_95;
                            let _e922 = local_93;
                            let _e923 = local_90;
                            phi_655_ = select(_e923, _e922, _e921);
                            phi_658_ = _e920;
                        } else {
                            phi_655_ = u32();
                            phi_658_ = u32();
                        }
                        let _e926 = phi_655_;
                        let _e928 = phi_658_;
                        continue;
                        continuing {
                            let _e929 = local_92;
                            phi_654_ = _e926;
                            phi_657_ = _e928;
                            phi_2876_ = _e878;
                            break if !(_e929);
                        }
                    }
                    let _e932 = phi_2876_;
                    phi_2973_ = _e932;
                    if _e932 {
                        break;
                    }
                    let _e933 = local_91;
                    let _e934 = local_13;
                    let _e935 = local_14;
                    phi_2887_ = _e932;
                    phi_684_ = 0u;
                    phi_687_ = _e880;
                    phi_689_ = _e882;
                    phi_691_ = _e884;
                    phi_693_ = _e886;
                    phi_695_ = _e888;
                    phi_697_ = type_25(_e933, 4294967295u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, _e934, _e935, false);
                    phi_699_ = 0u;
                    loop {
                        let _e938 = phi_2887_;
                        let _e940 = phi_684_;
                        let _e942 = phi_687_;
                        let _e944 = phi_689_;
                        let _e946 = phi_691_;
                        let _e948 = phi_693_;
                        let _e950 = phi_695_;
                        let _e952 = phi_697_;
                        let _e954 = phi_699_;
                        local_96 = _e940;
                        local_97 = _e942;
                        local_98 = _e944;
                        local_99 = _e946;
                        local_100 = _e948;
                        local_101 = _e950;
                        local_102 = _e954;
                        local_342 = _e942;
                        local_343 = _e944;
                        local_344 = _e946;
                        local_345 = _e948;
                        local_346 = _e950;
                        let _e955 = local_102;
                        let _e956 = local_330;
                        if (_e955 < _e956) {
                            let _e958 = local_86;
                            let _e959 = local_102;
                            let _e960 = (_e958 + _e959);
                            local_103 = _e960;
                            let _e961 = local_78;
                            let _e962 = (_e960 < _e961);
                            if _e962 {
                                phi_714_ = _e952;
                                loop {
                                    let _e964 = phi_714_;
                                    local_104 = _e964;
                                    local_340 = _e964;
                                    let _e965 = local_104;
                                    local_105 = _e965.member;
                                    if (_e965.member < 255u) {
                                        let _e968 = local_76;
                                        let _e969 = local_105;
                                        let _e970 = (_e968 + _e969);
                                        local_106 = _e970;
                                        if (_e970 < 1792u) {
                                        } else {
                                            phi_2884_ = true;
                                            break;
                                        }
                                        let _e972 = local_106;
                                        let _e974 = global_15[_e972];
                                        let _e975 = local_103;
                                        let _e976 = (_e974 <= _e975);
                                        if _e976 {
                                            let _e977 = local_105;
                                            let _e979 = local_104;
                                            phi_740_ = type_25((_e977 + 1u), _e979.member_1, _e979.member_2, _e979.member_3, _e979.member_4, _e979.member_5, _e979.member_6, _e979.member_7, _e979.member_8, _e979.member_9, _e979.member_10, _e979.member_11, _e979.member_12, _e979.member_13, _e979.member_14);
                                        } else {
                                            phi_740_ = type_25();
                                        }
                                        let _e997 = phi_740_;
                                        phi_715_ = _e997;
                                        phi_741_ = _e976;
                                    } else {
                                        phi_715_ = type_25();
                                        phi_741_ = false;
                                    }
                                    let _e999 = phi_715_;
                                    let _e1001 = phi_741_;
                                    local_107 = _e1001;
                                    continue;
                                    continuing {
                                        let _e1002 = local_107;
                                        phi_714_ = _e999;
                                        phi_2884_ = _e938;
                                        break if !(_e1002);
                                    }
                                }
                                let _e1005 = phi_2884_;
                                phi_2933_ = _e1005;
                                if _e1005 {
                                    break;
                                }
                                let _e1006 = local_105;
                                if (_e1006 == 0u) {
                                    phi_761_ = 0u;
                                } else {
                                    let _e1008 = local_76;
                                    let _e1009 = local_105;
                                    let _e1011 = ((_e1008 + _e1009) - 1u);
                                    local_108 = _e1011;
                                    if (_e1011 < 1792u) {
                                    } else {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1013 = local_108;
                                    let _e1015 = global_15[_e1013];
                                    phi_761_ = _e1015;
                                }
                                let _e1017 = phi_761_;
                                let _e1018 = local_103;
                                local_109 = (_e1018 - _e1017);
                                let _e1020 = local_104;
                                let _e1022 = local_105;
                                if (_e1020.member_1 != _e1022) {
                                    let _e1024 = local_15;
                                    local_110 = _e1024.member_6;
                                    let _e1026 = local_15;
                                    local_111 = _e1026.member_3;
                                    if (_e1026.member_3 == 0u) {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1029 = local_110;
                                    let _e1030 = local_111;
                                    local_112 = (_e1029 / _e1030);
                                    let _e1032 = local_105;
                                    let _e1033 = (1280u + _e1032);
                                    local_113 = _e1033;
                                    if (_e1033 < 1792u) {
                                    } else {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1035 = local_113;
                                    let _e1037 = global_15[_e1035];
                                    local_114 = _e1037;
                                    let _e1038 = local_18;
                                    let _e1039 = (_e1038 == 0u);
                                    local_115 = _e1039;
                                    if _e1039 {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1040 = local_114;
                                    let _e1041 = local_18;
                                    let _e1043 = local_112;
                                    local_116 = ((_e1040 % _e1041) * _e1043);
                                    let _e1045 = local_115;
                                    if _e1045 {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1046 = local_114;
                                    let _e1047 = local_18;
                                    let _e1049 = local_112;
                                    let _e1050 = ((_e1046 / _e1047) * _e1049);
                                    local_117 = _e1050;
                                    let _e1051 = local_105;
                                    let _e1052 = local_104;
                                    let _e1068 = type_25(_e1052.member, _e1051, _e1052.member_2, _e1052.member_3, _e1052.member_4, _e1052.member_5, _e1052.member_6, _e1052.member_7, _e1052.member_8, _e1052.member_9, _e1052.member_10, _e1052.member_11, _e1052.member_12, _e1052.member_13, _e1052.member_14);
                                    let _e1069 = local_114;
                                    let _e1085 = type_25(_e1068.member, _e1068.member_1, _e1069, _e1068.member_3, _e1068.member_4, _e1068.member_5, _e1068.member_6, _e1068.member_7, _e1068.member_8, _e1068.member_9, _e1068.member_10, _e1068.member_11, _e1068.member_12, _e1068.member_13, _e1068.member_14);
                                    let _e1086 = local_15;
                                    local_118 = _e1086.member_4;
                                    let _e1089 = local_116;
                                    let _e1090 = ((_e1050 * _e1086.member_4) + _e1089);
                                    local_119 = _e1090;
                                    let _e1106 = type_25(_e1085.member, _e1085.member_1, _e1085.member_2, _e1090, _e1085.member_4, _e1085.member_5, _e1085.member_6, _e1085.member_7, _e1085.member_8, _e1085.member_9, _e1085.member_10, _e1085.member_11, _e1085.member_12, _e1085.member_13, _e1085.member_14);
                                    let _e1107 = local_116;
                                    let _e1123 = type_25(_e1106.member, _e1106.member_1, _e1106.member_2, _e1106.member_3, _e1107, _e1106.member_5, _e1106.member_6, _e1106.member_7, _e1106.member_8, _e1106.member_9, _e1106.member_10, _e1106.member_11, _e1106.member_12, _e1106.member_13, _e1106.member_14);
                                    let _e1139 = type_25(_e1123.member, _e1123.member_1, _e1123.member_2, _e1123.member_3, _e1123.member_4, _e1050, _e1123.member_6, _e1123.member_7, _e1123.member_8, _e1123.member_9, _e1123.member_10, _e1123.member_11, _e1123.member_12, _e1123.member_13, _e1123.member_14);
                                    let _e1140 = local_116;
                                    let _e1141 = (_e1086.member_4 - _e1140);
                                    let _e1142 = local_112;
                                    let _e1144 = local_112;
                                    let _e1145 = select(_e1144, _e1141, (_e1141 < _e1142));
                                    local_332 = _e1145;
                                    let _e1161 = type_25(_e1139.member, _e1139.member_1, _e1139.member_2, _e1139.member_3, _e1139.member_4, _e1139.member_5, _e1145, _e1139.member_7, _e1139.member_8, _e1139.member_9, _e1139.member_10, _e1139.member_11, _e1139.member_12, _e1139.member_13, _e1139.member_14);
                                    let _e1162 = local_15;
                                    local_120 = _e1162.member_5;
                                    let _e1164 = (_e1162.member_5 - _e1050);
                                    let _e1165 = local_112;
                                    let _e1167 = local_112;
                                    let _e1168 = select(_e1167, _e1164, (_e1164 < _e1165));
                                    local_333 = _e1168;
                                    local_121 = type_25(_e1161.member, _e1161.member_1, _e1161.member_2, _e1161.member_3, _e1161.member_4, _e1161.member_5, _e1161.member_6, _e1168, _e1161.member_8, _e1161.member_9, _e1161.member_10, _e1161.member_11, _e1161.member_12, _e1161.member_13, _e1161.member_14);
                                    phi_830_ = (_e1168 - 1u);
                                    phi_833_ = 0u;
                                    loop {
                                        let _e1187 = phi_830_;
                                        let _e1189 = phi_833_;
                                        local_122 = _e1187;
                                        local_123 = _e1189;
                                        let _e1190 = local_123;
                                        let _e1191 = local_122;
                                        let _e1192 = (_e1190 < _e1191);
                                        local_124 = _e1192;
                                        if _e1192 {
                                            let _e1193 = local_123;
                                            let _e1194 = local_122;
                                            let _e1195 = (_e1193 + _e1194);
                                            let _e1196 = (_e1195 / 2u);
                                            local_125 = _e1196;
                                            if ((_e1195 % 2u) > 0u) {
                                                let _e1199 = local_125;
                                                phi_857_ = (_e1199 + 1u);
                                            } else {
                                                phi_857_ = _e1196;
                                            }
                                            let _e1202 = phi_857_;
                                            local_126 = _e1202;
                                            let _e1203 = local_333;
                                            if (_e1202 < _e1203) {
                                                let _e1205 = local_126;
                                                let _e1206 = local_118;
                                                let _e1208 = local_119;
                                                let _e1209 = (_e1208 + (_e1205 * _e1206));
                                                local_127 = _e1209;
                                                let _e1210 = local_7;
                                                if (_e1209 < _e1210) {
                                                } else {
                                                    phi_2889_ = true;
                                                    break;
                                                }
                                                let _e1212 = local_127;
                                                let _e1215 = global_10.member[_e1212];
                                                phi_873_ = _e1215;
                                            } else {
                                                phi_873_ = 4294967295u;
                                            }
                                            let _e1217 = phi_873_;
                                            let _e1218 = local_109;
                                            let _e1219 = (_e1217 <= _e1218);
                                            local_128 = _e1219;
                                            if _e1219 {
                                                phi_879_ = _e1187;
                                            } else {
                                                let _e1220 = local_126;
                                                phi_879_ = (_e1220 - 1u);
                                            }
                                            let _e1223 = phi_879_;
                                            let _e1224 = local_128;
                                            let _e1225 = local_126;
                                            let _e1226 = local_123;
                                            phi_831_ = _e1223;
                                            phi_834_ = select(_e1226, _e1225, _e1224);
                                        } else {
                                            phi_831_ = u32();
                                            phi_834_ = u32();
                                        }
                                        let _e1229 = phi_831_;
                                        let _e1231 = phi_834_;
                                        continue;
                                        continuing {
                                            let _e1232 = local_124;
                                            phi_830_ = _e1229;
                                            phi_833_ = _e1231;
                                            phi_2889_ = _e1005;
                                            break if !(_e1232);
                                        }
                                    }
                                    let _e1235 = phi_2889_;
                                    phi_2933_ = _e1235;
                                    if _e1235 {
                                        break;
                                    }
                                    let _e1236 = local_332;
                                    phi_883_ = (_e1236 - 1u);
                                    phi_886_ = 0u;
                                    loop {
                                        let _e1239 = phi_883_;
                                        let _e1241 = phi_886_;
                                        local_129 = _e1239;
                                        local_130 = _e1241;
                                        let _e1242 = local_130;
                                        let _e1243 = local_129;
                                        let _e1244 = (_e1242 < _e1243);
                                        local_131 = _e1244;
                                        if _e1244 {
                                            let _e1245 = local_130;
                                            let _e1246 = local_129;
                                            let _e1247 = (_e1245 + _e1246);
                                            let _e1248 = (_e1247 / 2u);
                                            local_132 = _e1248;
                                            if ((_e1247 % 2u) > 0u) {
                                                let _e1251 = local_132;
                                                phi_910_ = (_e1251 + 1u);
                                            } else {
                                                phi_910_ = _e1248;
                                            }
                                            let _e1254 = phi_910_;
                                            local_133 = _e1254;
                                            let _e1255 = local_123;
                                            let _e1256 = local_333;
                                            if (_e1255 < _e1256) {
                                                let _e1258 = local_123;
                                                let _e1259 = local_118;
                                                let _e1261 = local_119;
                                                let _e1263 = local_133;
                                                let _e1264 = ((_e1261 + (_e1258 * _e1259)) + _e1263);
                                                local_134 = _e1264;
                                                let _e1265 = local_7;
                                                if (_e1264 < _e1265) {
                                                } else {
                                                    phi_2898_ = true;
                                                    break;
                                                }
                                                let _e1267 = local_134;
                                                let _e1270 = global_10.member[_e1267];
                                                phi_926_ = _e1270;
                                            } else {
                                                phi_926_ = 4294967295u;
                                            }
                                            let _e1272 = phi_926_;
                                            let _e1273 = local_109;
                                            let _e1274 = (_e1272 <= _e1273);
                                            local_135 = _e1274;
                                            if _e1274 {
                                                phi_932_ = _e1239;
                                            } else {
                                                let _e1275 = local_133;
                                                phi_932_ = (_e1275 - 1u);
                                            }
                                            let _e1278 = phi_932_;
                                            let _e1279 = local_135;
                                            let _e1280 = local_133;
                                            let _e1281 = local_130;
                                            phi_884_ = _e1278;
                                            phi_887_ = select(_e1281, _e1280, _e1279);
                                        } else {
                                            phi_884_ = u32();
                                            phi_887_ = u32();
                                        }
                                        let _e1284 = phi_884_;
                                        let _e1286 = phi_887_;
                                        continue;
                                        continuing {
                                            let _e1287 = local_131;
                                            phi_883_ = _e1284;
                                            phi_886_ = _e1286;
                                            phi_2898_ = _e1235;
                                            break if !(_e1287);
                                        }
                                    }
                                    let _e1290 = phi_2898_;
                                    phi_2933_ = _e1290;
                                    if _e1290 {
                                        break;
                                    }
                                    let _e1291 = local_130;
                                    let _e1292 = local_121;
                                    let _e1308 = type_25(_e1292.member, _e1292.member_1, _e1292.member_2, _e1292.member_3, _e1292.member_4, _e1292.member_5, _e1292.member_6, _e1292.member_7, _e1291, _e1292.member_9, _e1292.member_10, _e1292.member_11, _e1292.member_12, _e1292.member_13, _e1292.member_14);
                                    let _e1309 = local_123;
                                    local_136 = type_25(_e1308.member, _e1308.member_1, _e1308.member_2, _e1308.member_3, _e1308.member_4, _e1308.member_5, _e1308.member_6, _e1308.member_7, _e1308.member_8, _e1309, _e1308.member_10, _e1308.member_11, _e1308.member_12, _e1308.member_13, _e1308.member_14);
                                    let _e1326 = local_123;
                                    let _e1327 = local_333;
                                    let _e1328 = (_e1326 < _e1327);
                                    local_137 = _e1328;
                                    if _e1328 {
                                        let _e1329 = local_123;
                                        let _e1330 = local_118;
                                        let _e1332 = local_119;
                                        let _e1334 = local_130;
                                        let _e1335 = ((_e1332 + (_e1329 * _e1330)) + _e1334);
                                        local_138 = _e1335;
                                        let _e1336 = local_7;
                                        if (_e1335 < _e1336) {
                                        } else {
                                            phi_2933_ = true;
                                            break;
                                        }
                                        let _e1338 = local_138;
                                        let _e1341 = global_10.member[_e1338];
                                        phi_951_ = _e1341;
                                    } else {
                                        phi_951_ = 4294967295u;
                                    }
                                    let _e1343 = phi_951_;
                                    let _e1344 = local_136;
                                    local_139 = type_25(_e1344.member, _e1344.member_1, _e1344.member_2, _e1344.member_3, _e1344.member_4, _e1344.member_5, _e1344.member_6, _e1344.member_7, _e1344.member_8, _e1344.member_9, _e1343, _e1344.member_11, _e1344.member_12, _e1344.member_13, _e1344.member_14);
                                    let _e1361 = local_130;
                                    let _e1362 = (_e1361 + 1u);
                                    local_140 = _e1362;
                                    let _e1363 = local_332;
                                    if (_e1362 < _e1363) {
                                        let _e1382 = local_137;
                                        if _e1382 {
                                            let _e1383 = local_123;
                                            let _e1384 = local_118;
                                            let _e1386 = local_119;
                                            let _e1388 = local_140;
                                            let _e1389 = ((_e1386 + (_e1383 * _e1384)) + _e1388);
                                            local_141 = _e1389;
                                            let _e1390 = local_7;
                                            if (_e1389 < _e1390) {
                                            } else {
                                                phi_2933_ = true;
                                                break;
                                            }
                                            let _e1392 = local_141;
                                            let _e1395 = global_10.member[_e1392];
                                            phi_974_ = _e1395;
                                        } else {
                                            phi_974_ = 4294967295u;
                                        }
                                        let _e1397 = phi_974_;
                                        phi_992_ = _e1397;
                                    } else {
                                        let _e1365 = local_123;
                                        let _e1366 = (_e1365 + 1u);
                                        local_142 = _e1366;
                                        let _e1367 = local_333;
                                        if (_e1366 < _e1367) {
                                            let _e1369 = local_142;
                                            let _e1370 = local_118;
                                            let _e1372 = local_119;
                                            let _e1373 = (_e1372 + (_e1369 * _e1370));
                                            local_143 = _e1373;
                                            let _e1374 = local_7;
                                            if (_e1373 < _e1374) {
                                            } else {
                                                phi_2933_ = true;
                                                break;
                                            }
                                            let _e1376 = local_143;
                                            let _e1379 = global_10.member[_e1376];
                                            phi_991_ = _e1379;
                                        } else {
                                            phi_991_ = 4294967295u;
                                        }
                                        let _e1381 = phi_991_;
                                        phi_992_ = _e1381;
                                    }
                                    let _e1399 = phi_992_;
                                    let _e1400 = local_139;
                                    local_144 = type_25(_e1400.member, _e1400.member_1, _e1400.member_2, _e1400.member_3, _e1400.member_4, _e1400.member_5, _e1400.member_6, _e1400.member_7, _e1400.member_8, _e1400.member_9, _e1400.member_10, _e1399, _e1400.member_12, _e1400.member_13, _e1400.member_14);
                                    let _e1417 = local_118;
                                    let _e1418 = local_120;
                                    let _e1420 = local_123;
                                    let _e1421 = local_118;
                                    let _e1423 = local_119;
                                    let _e1425 = local_130;
                                    let _e1427 = ((_e1417 * _e1418) + ((_e1423 + (_e1420 * _e1421)) + _e1425));
                                    local_145 = _e1427;
                                    let _e1428 = local_7;
                                    if (_e1427 < _e1428) {
                                    } else {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1430 = local_145;
                                    let _e1433 = global_10.member[_e1430];
                                    let _e1434 = bitcast<f32>(_e1433);
                                    let _e1435 = local_116;
                                    let _e1436 = local_130;
                                    let _e1437 = (_e1435 + _e1436);
                                    let _e1438 = local_15;
                                    let _e1441 = local_111;
                                    let _e1442 = ((_e1437 + 1u) * _e1441);
                                    let _e1445 = local_111;
                                    let _e1449 = local_117;
                                    let _e1450 = local_123;
                                    let _e1451 = (_e1449 + _e1450);
                                    let _e1452 = local_15;
                                    let _e1455 = local_111;
                                    let _e1456 = ((_e1451 + 1u) * _e1455);
                                    let _e1459 = local_111;
                                    let _e1463 = local_104;
                                    let _e1465 = local_104;
                                    let _e1468 = local_110;
                                    let _e1469 = ((_e1463.member_12 + 1u) * _e1468);
                                    let _e1472 = local_110;
                                    let _e1477 = local_110;
                                    let _e1478 = ((_e1465.member_13 + 1u) * _e1477);
                                    let _e1481 = local_110;
                                    let _e1487 = ((f32((_e1463.member_12 * _e1472)) + 0.5f) - f32(select(_e1438.member, _e1442, (_e1442 < _e1438.member))));
                                    let _e1488 = (f32((_e1437 * _e1445)) - (f32(select(_e1438.member, _e1469, (_e1469 < _e1438.member))) - 0.5f));
                                    let _e1490 = select(_e1488, _e1487, (_e1487 > _e1488));
                                    let _e1492 = select(0f, _e1490, (_e1490 > 0f));
                                    let _e1495 = ((f32((_e1465.member_13 * _e1481)) + 0.5f) - f32(select(_e1452.member_1, _e1456, (_e1456 < _e1452.member_1))));
                                    let _e1496 = (f32((_e1451 * _e1459)) - (f32(select(_e1452.member_1, _e1478, (_e1478 < _e1452.member_1))) - 0.5f));
                                    let _e1498 = select(_e1496, _e1495, (_e1495 > _e1496));
                                    let _e1500 = select(0f, _e1498, (_e1498 > 0f));
                                    let _e1506 = local_144;
                                    phi_2907_ = _e1290;
                                    phi_1104_ = type_25(_e1506.member, _e1506.member_1, _e1506.member_2, _e1506.member_3, _e1506.member_4, _e1506.member_5, _e1506.member_6, _e1506.member_7, _e1506.member_8, _e1506.member_9, _e1506.member_10, _e1506.member_11, _e1506.member_12, _e1506.member_13, (((_e1492 * _e1492) + (_e1500 * _e1500)) <= (_e1434 * _e1434)));
                                } else {
                                    phi_2907_ = _e1005;
                                    let _e3375 = local_340;
                                    phi_1104_ = _e3375;
                                }
                                let _e1524 = phi_2907_;
                                let _e1526 = phi_1104_;
                                phi_1106_ = _e1526;
                                loop {
                                    let _e1528 = phi_1106_;
                                    local_146 = _e1528;
                                    local_341 = _e1528;
                                    let _e1529 = local_146;
                                    local_147 = _e1529.member_11;
                                    let _e1531 = local_109;
                                    let _e1532 = (_e1529.member_11 <= _e1531);
                                    local_148 = _e1532;
                                    if _e1532 {
                                        let _e1533 = local_146;
                                        let _e1535 = (_e1533.member_8 + 1u);
                                        local_149 = _e1535;
                                        let _e1536 = local_146;
                                        local_150 = _e1536.member_6;
                                        let _e1538 = (_e1535 < _e1536.member_6);
                                        local_151 = _e1538;
                                        if _e1538 {
                                            let _e1542 = local_146;
                                            phi_1128_ = _e1542.member_9;
                                        } else {
                                            let _e1539 = local_146;
                                            phi_1128_ = (_e1539.member_9 + 1u);
                                        }
                                        let _e1545 = phi_1128_;
                                        local_152 = _e1545;
                                        let _e1546 = local_151;
                                        let _e1547 = local_149;
                                        let _e1548 = select(0u, _e1547, _e1546);
                                        local_334 = _e1548;
                                        let _e1549 = local_146;
                                        let _e1565 = type_25(_e1549.member, _e1549.member_1, _e1549.member_2, _e1549.member_3, _e1549.member_4, _e1549.member_5, _e1549.member_6, _e1549.member_7, _e1548, _e1549.member_9, _e1549.member_10, _e1549.member_11, _e1549.member_12, _e1549.member_13, _e1549.member_14);
                                        local_153 = type_25(_e1565.member, _e1565.member_1, _e1565.member_2, _e1565.member_3, _e1565.member_4, _e1565.member_5, _e1565.member_6, _e1565.member_7, _e1565.member_8, _e1545, _e1565.member_10, _e1565.member_11, _e1565.member_12, _e1565.member_13, _e1565.member_14);
                                        let _e1582 = local_146;
                                        local_154 = _e1582.member_7;
                                        let _e1584 = (_e1545 < _e1582.member_7);
                                        local_155 = _e1584;
                                        if _e1584 {
                                            let _e1585 = local_146;
                                            let _e1587 = local_15;
                                            let _e1589 = local_152;
                                            let _e1592 = local_334;
                                            let _e1593 = ((_e1585.member_3 + (_e1589 * _e1587.member_4)) + _e1592);
                                            local_156 = _e1593;
                                            let _e1594 = local_7;
                                            if (_e1593 < _e1594) {
                                            } else {
                                                phi_2904_ = true;
                                                break;
                                            }
                                            let _e1596 = local_156;
                                            let _e1599 = global_10.member[_e1596];
                                            phi_1149_ = _e1599;
                                        } else {
                                            phi_1149_ = 4294967295u;
                                        }
                                        let _e1601 = phi_1149_;
                                        let _e1602 = local_153;
                                        local_157 = type_25(_e1602.member, _e1602.member_1, _e1602.member_2, _e1602.member_3, _e1602.member_4, _e1602.member_5, _e1602.member_6, _e1602.member_7, _e1602.member_8, _e1602.member_9, _e1601, _e1602.member_11, _e1602.member_12, _e1602.member_13, _e1602.member_14);
                                        let _e1619 = local_334;
                                        let _e1620 = (_e1619 + 1u);
                                        local_158 = _e1620;
                                        let _e1621 = local_150;
                                        if (_e1620 < _e1621) {
                                            let _e1642 = local_155;
                                            if _e1642 {
                                                let _e1643 = local_146;
                                                let _e1645 = local_15;
                                                let _e1647 = local_152;
                                                let _e1650 = local_158;
                                                let _e1651 = ((_e1643.member_3 + (_e1647 * _e1645.member_4)) + _e1650);
                                                local_159 = _e1651;
                                                let _e1652 = local_7;
                                                if (_e1651 < _e1652) {
                                                } else {
                                                    phi_2904_ = true;
                                                    break;
                                                }
                                                let _e1654 = local_159;
                                                let _e1657 = global_10.member[_e1654];
                                                phi_1175_ = _e1657;
                                            } else {
                                                phi_1175_ = 4294967295u;
                                            }
                                            let _e1659 = phi_1175_;
                                            phi_1195_ = _e1659;
                                        } else {
                                            let _e1623 = local_152;
                                            let _e1624 = (_e1623 + 1u);
                                            local_160 = _e1624;
                                            let _e1625 = local_154;
                                            if (_e1624 < _e1625) {
                                                let _e1627 = local_146;
                                                let _e1629 = local_15;
                                                let _e1631 = local_160;
                                                let _e1633 = (_e1627.member_3 + (_e1631 * _e1629.member_4));
                                                local_161 = _e1633;
                                                let _e1634 = local_7;
                                                if (_e1633 < _e1634) {
                                                } else {
                                                    phi_2904_ = true;
                                                    break;
                                                }
                                                let _e1636 = local_161;
                                                let _e1639 = global_10.member[_e1636];
                                                phi_1194_ = _e1639;
                                            } else {
                                                phi_1194_ = 4294967295u;
                                            }
                                            let _e1641 = phi_1194_;
                                            phi_1195_ = _e1641;
                                        }
                                        let _e1661 = phi_1195_;
                                        let _e1662 = local_157;
                                        local_162 = type_25(_e1662.member, _e1662.member_1, _e1662.member_2, _e1662.member_3, _e1662.member_4, _e1662.member_5, _e1662.member_6, _e1662.member_7, _e1662.member_8, _e1662.member_9, _e1662.member_10, _e1661, _e1662.member_12, _e1662.member_13, _e1662.member_14);
                                        let _e1679 = local_15;
                                        let _e1681 = local_15;
                                        let _e1684 = local_146;
                                        let _e1686 = local_152;
                                        let _e1689 = local_334;
                                        let _e1691 = ((_e1679.member_4 * _e1681.member_5) + ((_e1684.member_3 + (_e1686 * _e1679.member_4)) + _e1689));
                                        local_163 = _e1691;
                                        let _e1692 = local_7;
                                        if (_e1691 < _e1692) {
                                        } else {
                                            phi_2904_ = true;
                                            break;
                                        }
                                        let _e1694 = local_163;
                                        let _e1697 = global_10.member[_e1694];
                                        let _e1698 = bitcast<f32>(_e1697);
                                        let _e1699 = local_146;
                                        let _e1701 = local_334;
                                        let _e1702 = (_e1699.member_4 + _e1701);
                                        let _e1703 = local_15;
                                        let _e1705 = local_15;
                                        let _e1708 = ((_e1702 + 1u) * _e1703.member_3);
                                        let _e1714 = local_146;
                                        let _e1716 = local_152;
                                        let _e1717 = (_e1714.member_5 + _e1716);
                                        let _e1718 = local_15;
                                        let _e1721 = ((_e1717 + 1u) * _e1703.member_3);
                                        let _e1727 = local_146;
                                        let _e1729 = local_146;
                                        let _e1731 = local_15;
                                        let _e1734 = ((_e1727.member_12 + 1u) * _e1731.member_6);
                                        let _e1741 = ((_e1729.member_13 + 1u) * _e1731.member_6);
                                        let _e1749 = ((f32((_e1727.member_12 * _e1731.member_6)) + 0.5f) - f32(select(_e1705.member, _e1708, (_e1708 < _e1705.member))));
                                        let _e1750 = (f32((_e1702 * _e1703.member_3)) - (f32(select(_e1705.member, _e1734, (_e1734 < _e1705.member))) - 0.5f));
                                        let _e1752 = select(_e1750, _e1749, (_e1749 > _e1750));
                                        let _e1754 = select(0f, _e1752, (_e1752 > 0f));
                                        let _e1757 = ((f32((_e1729.member_13 * _e1731.member_6)) + 0.5f) - f32(select(_e1718.member_1, _e1721, (_e1721 < _e1718.member_1))));
                                        let _e1758 = (f32((_e1717 * _e1703.member_3)) - (f32(select(_e1718.member_1, _e1741, (_e1741 < _e1718.member_1))) - 0.5f));
                                        let _e1760 = select(_e1758, _e1757, (_e1757 > _e1758));
                                        let _e1762 = select(0f, _e1760, (_e1760 > 0f));
                                        let _e1768 = local_162;
                                        phi_1107_ = type_25(_e1768.member, _e1768.member_1, _e1768.member_2, _e1768.member_3, _e1768.member_4, _e1768.member_5, _e1768.member_6, _e1768.member_7, _e1768.member_8, _e1768.member_9, _e1768.member_10, _e1768.member_11, _e1768.member_12, _e1768.member_13, (((_e1754 * _e1754) + (_e1762 * _e1762)) <= (_e1698 * _e1698)));
                                    } else {
                                        phi_1107_ = type_25();
                                    }
                                    let _e1786 = phi_1107_;
                                    continue;
                                    continuing {
                                        let _e1787 = local_148;
                                        phi_1106_ = _e1786;
                                        phi_2904_ = _e1524;
                                        break if !(_e1787);
                                    }
                                }
                                let _e1790 = phi_2904_;
                                phi_2933_ = _e1790;
                                if _e1790 {
                                    break;
                                }
                                let _e1791 = local_146;
                                local_164 = _e1791.member_2;
                                let _e1793 = local_146;
                                local_165 = _e1793.member_8;
                                let _e1795 = local_146;
                                local_166 = _e1795.member_9;
                                let _e1797 = local_15;
                                local_167 = _e1797.member_6;
                                let _e1799 = local_15;
                                local_168 = _e1799.member_3;
                                if (_e1799.member_3 == 0u) {
                                    phi_2933_ = true;
                                    break;
                                }
                                let _e1802 = local_167;
                                let _e1803 = local_168;
                                let _e1804 = (_e1802 / _e1803);
                                let _e1805 = local_164;
                                let _e1807 = local_166;
                                let _e1810 = local_165;
                                let _e1812 = local_15;
                                local_169 = _e1812.member_2;
                                let _e1814 = local_168;
                                let _e1816 = local_168;
                                let _e1819 = local_146;
                                let _e1821 = local_109;
                                local_170 = ((((((_e1805 * _e1804) + _e1807) * _e1804) + _e1810) * ((_e1812.member_2 * _e1814) * _e1816)) + (_e1821 - _e1819.member_10));
                                let _e1824 = local_146;
                                if _e1824.member_14 {
                                    let _e1857 = local_170;
                                    let _e1858 = (4u * _e1857);
                                    local_171 = _e1858;
                                    let _e1859 = local_5;
                                    if (_e1858 < _e1859) {
                                    } else {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1861 = local_171;
                                    let _e1864 = global_8.member[_e1861];
                                    local_172 = _e1864;
                                    let _e1865 = local_171;
                                    let _e1866 = (_e1865 + 1u);
                                    local_173 = _e1866;
                                    let _e1867 = local_5;
                                    if (_e1866 < _e1867) {
                                    } else {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1869 = local_173;
                                    let _e1872 = global_8.member[_e1869];
                                    local_174 = _e1872;
                                    let _e1873 = local_171;
                                    let _e1874 = (_e1873 + 2u);
                                    local_175 = _e1874;
                                    let _e1875 = local_5;
                                    if (_e1874 < _e1875) {
                                    } else {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1877 = local_175;
                                    let _e1880 = global_8.member[_e1877];
                                    local_176 = _e1880;
                                    let _e1881 = local_171;
                                    let _e1882 = (_e1881 + 3u);
                                    local_177 = _e1882;
                                    let _e1883 = local_5;
                                    if (_e1882 < _e1883) {
                                    } else {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1885 = local_177;
                                    let _e1888 = global_8.member[_e1885];
                                    local_178 = _e1888;
                                    let _e1889 = local_172;
                                    local_179 = (_e1889 & 16383u);
                                    let _e1891 = local_172;
                                    local_180 = ((_e1891 >> bitcast<u32>(14u)) & 16383u);
                                    let _e1895 = local_174;
                                    local_181 = (_e1895 & 16383u);
                                    let _e1897 = local_174;
                                    let _e1899 = (_e1897 >> bitcast<u32>(24i));
                                    local_182 = _e1899;
                                    if (_e1899 == 0u) {
                                        phi_1392_ = array<f32, 3>(0f, 0f, 0f);
                                    } else {
                                        let _e1901 = local_182;
                                        let _e1907 = bitcast<f32>((bitcast<u32>((bitcast<i32>(_e1901) + -13i)) << bitcast<u32>(23i)));
                                        let _e1908 = local_179;
                                        let _e1911 = local_180;
                                        let _e1914 = local_181;
                                        phi_1392_ = array<f32, 3>((f32(_e1908) * _e1907), (f32(_e1911) * _e1907), (f32(_e1914) * _e1907));
                                    }
                                    let _e1919 = phi_1392_;
                                    local_183 = _e1919;
                                    let _e1920 = local_174;
                                    let _e1923 = ((_e1920 >> bitcast<u32>(14u)) & 1023u);
                                    local_184 = _e1923;
                                    if (_e1923 >= 1023u) {
                                        phi_1403_ = 1f;
                                    } else {
                                        let _e1925 = local_184;
                                        phi_1403_ = (f32(_e1925) * 0.0009775171f);
                                    }
                                    let _e1929 = phi_1403_;
                                    local_185 = _e1929;
                                    let _e1930 = local_176;
                                    let _e1931 = bitcast<f32>(_e1930);
                                    local_186 = _e1931;
                                    let _e1932 = local_172;
                                    let _e1935 = ((_e1932 >> bitcast<u32>(28i)) & 3u);
                                    local_187 = _e1935;
                                    let _e1936 = local_178;
                                    let _e1938 = local_178;
                                    let _e1941 = array<u32, 2>((_e1936 & 65535u), (_e1938 >> bitcast<u32>(16i)));
                                    local_188 = _e1941;
                                    let _e1942 = local_183;
                                    let _e1944 = local_79;
                                    let _e1947 = ((_e1944 >> bitcast<u32>(8u)) & 7u);
                                    local_189 = _e1947;
                                    if (_e1947 == 0u) {
                                        phi_1475_ = type_22(_e1941, _e1942, _e1929, _e1931, _e1935, 0u);
                                    } else {
                                        let _e1949 = local_189;
                                        let _e1950 = local_189;
                                        let _e1951 = (_e1949 * _e1950);
                                        local_190 = _e1951;
                                        if (_e1951 <= 1u) {
                                            phi_1428_ = 1u;
                                        } else {
                                            let _e1953 = local_190;
                                            phi_1428_ = select(16u, 4u, (_e1953 <= 4u));
                                        }
                                        let _e1957 = phi_1428_;
                                        local_191 = _e1957;
                                        if (_e1957 == 0u) {
                                            phi_2933_ = true;
                                            break;
                                        }
                                        let _e1959 = local_191;
                                        local_192 = (32u / _e1959);
                                        let _e1961 = local_191;
                                        if (_e1961 >= 32u) {
                                            phi_1441_ = 4294967295u;
                                        } else {
                                            let _e1963 = local_191;
                                            phi_1441_ = ((1u << bitcast<u32>((_e1963 & 31u))) - 1u);
                                        }
                                        let _e1969 = phi_1441_;
                                        local_193 = _e1969;
                                        let _e1970 = local_15;
                                        let _e1972 = local_18;
                                        let _e1974 = local_167;
                                        let _e1976 = local_167;
                                        let _e1978 = local_169;
                                        local_194 = (4u * ((((_e1972 * _e1970.member_8) * _e1974) * _e1976) * _e1978));
                                        let _e1981 = local_192;
                                        let _e1982 = (_e1981 == 0u);
                                        local_195 = _e1982;
                                        if _e1982 {
                                            phi_2933_ = true;
                                            break;
                                        }
                                        let _e1983 = local_170;
                                        let _e1984 = local_192;
                                        let _e1986 = local_194;
                                        local_196 = (_e1986 + (_e1983 / _e1984));
                                        let _e1988 = local_195;
                                        if _e1988 {
                                            phi_2933_ = true;
                                            break;
                                        }
                                        let _e1989 = local_170;
                                        let _e1990 = local_192;
                                        let _e1992 = local_191;
                                        local_197 = ((_e1989 % _e1990) * _e1992);
                                        let _e1994 = local_196;
                                        let _e1995 = local_5;
                                        if (_e1994 < _e1995) {
                                        } else {
                                            phi_2933_ = true;
                                            break;
                                        }
                                        let _e1997 = local_196;
                                        let _e2000 = global_8.member[_e1997];
                                        let _e2001 = local_197;
                                        let _e2005 = local_193;
                                        let _e2007 = local_188;
                                        let _e2008 = local_183;
                                        let _e2009 = local_185;
                                        let _e2010 = local_186;
                                        let _e2011 = local_187;
                                        phi_1475_ = type_22(_e2007, _e2008, _e2009, _e2010, _e2011, ((_e2000 >> bitcast<u32>((_e2001 & 31u))) & _e2005));
                                    }
                                    let _e2014 = phi_1475_;
                                    local_198 = _e2014;
                                    if (_e2014.member_5 != 0u) {
                                        phi_1486_ = 1.4142135f;
                                    } else {
                                        let _e2017 = local_198;
                                        phi_1486_ = (0.5f * f32((1u << bitcast<u32>((_e2017.member_4 & 31u)))));
                                    }
                                    let _e2025 = phi_1486_;
                                    local_199 = _e2025;
                                    let _e2026 = local_198;
                                    local_200 = _e2026.member_3;
                                    let _e2028 = bitcast<u32>(_e2026.member_3);
                                    local_201 = _e2028;
                                    if (_e2028 == 2139095040u) {
                                        let _e2070 = local_15;
                                        let _e2074 = local_15;
                                        let _e2078 = local_15;
                                        let _e2083 = local_15;
                                        phi_1541_ = (0.5f * ((((2f * _e2070.member_15.member_1) * _e2074.member_15.member) / (_e2078.member_15.member_2 - _e2074.member_15.member)) * _e2083.member_15.member_3));
                                    } else {
                                        let _e2030 = local_201;
                                        if (_e2030 == 0u) {
                                            phi_1510_ = false;
                                        } else {
                                            let _e2032 = local_201;
                                            phi_1510_ = (_e2032 <= 2139095040u);
                                        }
                                        let _e2035 = phi_1510_;
                                        if _e2035 {
                                            let _e2036 = local_15;
                                            let _e2040 = local_15;
                                            let _e2044 = local_15;
                                            local_202 = _e2044.member_15.member_2;
                                            let _e2049 = local_15;
                                            let _e2052 = ((((2f * _e2036.member_15.member_1) * _e2040.member_15.member) / (_e2044.member_15.member_2 - _e2040.member_15.member)) * _e2049.member_15.member_3);
                                            local_203 = _e2052;
                                            if (_e2052 == 0f) {
                                                phi_1532_ = 0f;
                                            } else {
                                                let _e2054 = local_202;
                                                let _e2055 = local_200;
                                                let _e2058 = local_203;
                                                phi_1532_ = (_e2058 * (1f - (_e2054 / _e2055)));
                                            }
                                            let _e2061 = phi_1532_;
                                            phi_1533_ = _e2061;
                                        } else {
                                            phi_1533_ = bitcast<f32>(_e402);
                                        }
                                        let _e2063 = phi_1533_;
                                        local_204 = _e2063;
                                        if (_e2063 < 0f) {
                                            let _e2065 = local_204;
                                            phi_1539_ = -(_e2065);
                                        } else {
                                            phi_1539_ = _e2063;
                                        }
                                        let _e2068 = phi_1539_;
                                        phi_1541_ = (0.5f * _e2068);
                                    }
                                    let _e2089 = phi_1541_;
                                    let _e2094 = local_199;
                                    let _e2095 = (select(_e2089, 0f, ((bitcast<u32>(_e2089) & 2147483647u) > 2139095040u)) + _e2094);
                                    let _e2096 = local_17;
                                    let _e2098 = local_17;
                                    let _e2099 = select(_e2098, _e2095, (_e2095 < _e2096));
                                    let _e2101 = select(0.5f, _e2099, (_e2099 > 0.5f));
                                    local_335 = _e2101;
                                    let _e2102 = local_198;
                                    let _e2106 = (f32(_e2102.member[0]) * 0.5f);
                                    let _e2107 = local_198;
                                    let _e2111 = (f32(_e2107.member[1]) * 0.5f);
                                    let _e2112 = local_15;
                                    let _e2114 = local_13;
                                    let _e2116 = local_167;
                                    let _e2117 = ((_e2114 + 1u) * _e2116);
                                    let _e2120 = local_13;
                                    let _e2121 = local_167;
                                    let _e2125 = local_15;
                                    let _e2127 = local_14;
                                    let _e2129 = local_167;
                                    let _e2130 = ((_e2127 + 1u) * _e2129);
                                    let _e2133 = local_14;
                                    let _e2134 = local_167;
                                    let _e2140 = ((f32((_e2120 * _e2121)) + 0.5f) - _e2106);
                                    let _e2141 = (_e2106 - (f32(select(_e2112.member, _e2117, (_e2117 < _e2112.member))) - 0.5f));
                                    let _e2143 = select(_e2141, _e2140, (_e2140 > _e2141));
                                    let _e2145 = select(0f, _e2143, (_e2143 > 0f));
                                    let _e2148 = ((f32((_e2133 * _e2134)) + 0.5f) - _e2111);
                                    let _e2149 = (_e2111 - (f32(select(_e2125.member_1, _e2130, (_e2130 < _e2125.member_1))) - 0.5f));
                                    let _e2151 = select(_e2149, _e2148, (_e2148 > _e2149));
                                    let _e2153 = select(0f, _e2151, (_e2151 > 0f));
                                    if (((_e2145 * _e2145) + (_e2153 * _e2153)) <= (_e2101 * _e2101)) {
                                        let _e2159 = local_146;
                                        let _e2161 = local_165;
                                        let _e2163 = local_146;
                                        let _e2165 = local_166;
                                        let _e2167 = local_102;
                                        let _e2171 = local_96;
                                        let _e2173 = local_101;
                                        local_205 = ((_e2159.member_4 + _e2161) | (_e2163.member_5 + _e2165));
                                        phi_1642_ = 0u;
                                        loop {
                                            let _e2177 = phi_1642_;
                                            local_206 = _e2177;
                                            let _e2178 = local_206;
                                            if (_e2178 < 1u) {
                                                let _e2180 = local_206;
                                                let _e2181 = (_e2180 + 1u);
                                                let _e2183 = local_168;
                                                let _e2188 = local_335;
                                                let _e2189 = (_e2188 >= f32((2u * (_e2183 << bitcast<u32>((_e2181 & 31u))))));
                                                phi_1643_ = select(u32(), _e2181, _e2189);
                                                phi_1663_ = _e2189;
                                            } else {
                                                phi_1643_ = u32();
                                                phi_1663_ = false;
                                            }
                                            let _e2192 = phi_1643_;
                                            let _e2194 = phi_1663_;
                                            local_207 = _e2194;
                                            continue;
                                            continuing {
                                                let _e2195 = local_207;
                                                phi_1642_ = _e2192;
                                                break if !(_e2195);
                                            }
                                        }
                                        let _e2197 = local_206;
                                        let _e2202 = local_205;
                                        let _e2206 = local_100;
                                        phi_1677_ = 0u;
                                        loop {
                                            let _e2209 = phi_1677_;
                                            local_208 = _e2209;
                                            let _e2210 = local_208;
                                            if (_e2210 < 2u) {
                                                let _e2212 = local_208;
                                                let _e2213 = (_e2212 + 1u);
                                                let _e2215 = local_168;
                                                let _e2220 = local_335;
                                                let _e2221 = (_e2220 >= f32((2u * (_e2215 << bitcast<u32>((_e2213 & 31u))))));
                                                phi_1678_ = select(u32(), _e2213, _e2221);
                                                phi_1698_ = _e2221;
                                            } else {
                                                phi_1678_ = u32();
                                                phi_1698_ = false;
                                            }
                                            let _e2224 = phi_1678_;
                                            let _e2226 = phi_1698_;
                                            local_209 = _e2226;
                                            continue;
                                            continuing {
                                                let _e2227 = local_209;
                                                phi_1677_ = _e2224;
                                                break if !(_e2227);
                                            }
                                        }
                                        let _e2229 = local_208;
                                        let _e2234 = local_205;
                                        let _e2238 = local_99;
                                        phi_1712_ = 0u;
                                        loop {
                                            let _e2241 = phi_1712_;
                                            local_210 = _e2241;
                                            let _e2242 = local_210;
                                            if (_e2242 < 3u) {
                                                let _e2244 = local_210;
                                                let _e2245 = (_e2244 + 1u);
                                                let _e2247 = local_168;
                                                let _e2252 = local_335;
                                                let _e2253 = (_e2252 >= f32((2u * (_e2247 << bitcast<u32>((_e2245 & 31u))))));
                                                phi_1713_ = select(u32(), _e2245, _e2253);
                                                phi_1733_ = _e2253;
                                            } else {
                                                phi_1713_ = u32();
                                                phi_1733_ = false;
                                            }
                                            let _e2256 = phi_1713_;
                                            let _e2258 = phi_1733_;
                                            local_211 = _e2258;
                                            continue;
                                            continuing {
                                                let _e2259 = local_211;
                                                phi_1712_ = _e2256;
                                                break if !(_e2259);
                                            }
                                        }
                                        let _e2261 = local_210;
                                        let _e2266 = local_205;
                                        let _e2270 = local_98;
                                        phi_1747_ = 0u;
                                        loop {
                                            let _e2273 = phi_1747_;
                                            local_212 = _e2273;
                                            let _e2274 = local_212;
                                            if (_e2274 < 4u) {
                                                let _e2276 = local_212;
                                                let _e2277 = (_e2276 + 1u);
                                                let _e2279 = local_168;
                                                let _e2284 = local_335;
                                                let _e2285 = (_e2284 >= f32((2u * (_e2279 << bitcast<u32>((_e2277 & 31u))))));
                                                phi_1748_ = select(u32(), _e2277, _e2285);
                                                phi_1768_ = _e2285;
                                            } else {
                                                phi_1748_ = u32();
                                                phi_1768_ = false;
                                            }
                                            let _e2288 = phi_1748_;
                                            let _e2290 = phi_1768_;
                                            local_213 = _e2290;
                                            continue;
                                            continuing {
                                                let _e2291 = local_213;
                                                phi_1747_ = _e2288;
                                                break if !(_e2291);
                                            }
                                        }
                                        let _e2293 = local_212;
                                        let _e2298 = local_205;
                                        let _e2302 = local_97;
                                        phi_1780_ = (_e2171 | (1u << bitcast<u32>((_e2167 & 31u))));
                                        phi_1781_ = (_e2302 + select(0u, 1u, ((_e2298 & ((1u << bitcast<u32>((_e2293 & 31u))) - 1u)) == 0u)));
                                        phi_1782_ = (_e2270 + select(0u, 1u, ((_e2266 & ((1u << bitcast<u32>((_e2261 & 31u))) - 1u)) == 0u)));
                                        phi_1783_ = (_e2238 + select(0u, 1u, ((_e2234 & ((1u << bitcast<u32>((_e2229 & 31u))) - 1u)) == 0u)));
                                        phi_1784_ = (_e2206 + select(0u, 1u, ((_e2202 & ((1u << bitcast<u32>((_e2197 & 31u))) - 1u)) == 0u)));
                                        phi_1785_ = (_e2173 + 1u);
                                    } else {
                                        phi_1780_ = _e940;
                                        phi_1781_ = _e942;
                                        phi_1782_ = _e944;
                                        phi_1783_ = _e946;
                                        phi_1784_ = _e948;
                                        phi_1785_ = _e950;
                                    }
                                    let _e2305 = phi_1780_;
                                    let _e2307 = phi_1781_;
                                    let _e2309 = phi_1782_;
                                    let _e2311 = phi_1783_;
                                    let _e2313 = phi_1784_;
                                    let _e2315 = phi_1785_;
                                    let _e2316 = local_102;
                                    phi_1822_ = _e2305;
                                    phi_1823_ = _e2307;
                                    phi_1824_ = _e2309;
                                    phi_1825_ = _e2311;
                                    phi_1826_ = _e2313;
                                    phi_1827_ = _e2315;
                                    phi_1828_ = (_e2316 + 1u);
                                } else {
                                    let _e1826 = local_146;
                                    local_214 = _e1826.member;
                                    if (_e1826.member == 0u) {
                                        phi_1802_ = 0u;
                                    } else {
                                        let _e1829 = local_76;
                                        let _e1830 = local_214;
                                        let _e1832 = ((_e1829 + _e1830) - 1u);
                                        local_215 = _e1832;
                                        if (_e1832 < 1792u) {
                                        } else {
                                            phi_2933_ = true;
                                            break;
                                        }
                                        let _e1834 = local_215;
                                        let _e1836 = global_15[_e1834];
                                        phi_1802_ = _e1836;
                                    }
                                    let _e1838 = phi_1802_;
                                    local_216 = _e1838;
                                    let _e1839 = local_76;
                                    let _e1840 = local_214;
                                    let _e1841 = (_e1839 + _e1840);
                                    local_217 = _e1841;
                                    if (_e1841 < 1792u) {
                                    } else {
                                        phi_2933_ = true;
                                        break;
                                    }
                                    let _e1843 = local_217;
                                    let _e1845 = global_15[_e1843];
                                    let _e1846 = local_216;
                                    let _e1848 = local_147;
                                    if (_e1848 < (_e1845 - _e1846)) {
                                        let _e1850 = local_216;
                                        let _e1851 = local_147;
                                        phi_1820_ = (_e1850 + _e1851);
                                    } else {
                                        phi_1820_ = _e1845;
                                    }
                                    let _e1854 = phi_1820_;
                                    let _e1855 = local_86;
                                    phi_1822_ = _e940;
                                    phi_1823_ = _e942;
                                    phi_1824_ = _e944;
                                    phi_1825_ = _e946;
                                    phi_1826_ = _e948;
                                    phi_1827_ = _e950;
                                    phi_1828_ = (_e1854 - _e1855);
                                }
                                let _e2319 = phi_1822_;
                                let _e2321 = phi_1823_;
                                let _e2323 = phi_1824_;
                                let _e2325 = phi_1825_;
                                let _e2327 = phi_1826_;
                                let _e2329 = phi_1827_;
                                let _e2331 = phi_1828_;
                                phi_2935_ = _e1790;
                                phi_1829_ = _e2319;
                                phi_1830_ = _e2321;
                                phi_1831_ = _e2323;
                                phi_1832_ = _e2325;
                                phi_1833_ = _e2327;
                                phi_1834_ = _e2329;
                                let _e3431 = local_341;
                                phi_1835_ = _e3431;
                                phi_1836_ = _e2331;
                            } else {
                                phi_2935_ = _e938;
                                phi_1829_ = u32();
                                phi_1830_ = u32();
                                phi_1831_ = u32();
                                phi_1832_ = u32();
                                phi_1833_ = u32();
                                phi_1834_ = u32();
                                phi_1835_ = type_25();
                                phi_1836_ = u32();
                            }
                            let _e2333 = phi_2935_;
                            let _e2335 = phi_1829_;
                            let _e2337 = phi_1830_;
                            let _e2339 = phi_1831_;
                            let _e2341 = phi_1832_;
                            let _e2343 = phi_1833_;
                            let _e2345 = phi_1834_;
                            let _e2347 = phi_1835_;
                            let _e2349 = phi_1836_;
                            phi_2934_ = _e2333;
                            phi_685_ = _e2335;
                            phi_688_ = _e2337;
                            phi_690_ = _e2339;
                            phi_692_ = _e2341;
                            phi_694_ = _e2343;
                            phi_696_ = _e2345;
                            phi_698_ = _e2347;
                            phi_700_ = _e2349;
                            phi_1837_ = _e962;
                        } else {
                            phi_2934_ = _e938;
                            phi_685_ = u32();
                            phi_688_ = u32();
                            phi_690_ = u32();
                            phi_692_ = u32();
                            phi_694_ = u32();
                            phi_696_ = u32();
                            phi_698_ = type_25();
                            phi_700_ = u32();
                            phi_1837_ = false;
                        }
                        let _e2351 = phi_2934_;
                        let _e2353 = phi_685_;
                        let _e2355 = phi_688_;
                        let _e2357 = phi_690_;
                        let _e2359 = phi_692_;
                        let _e2361 = phi_694_;
                        let _e2363 = phi_696_;
                        let _e2365 = phi_698_;
                        let _e2367 = phi_700_;
                        let _e2369 = phi_1837_;
                        local_218 = _e2369;
                        continue;
                        continuing {
                            let _e2370 = local_218;
                            phi_2887_ = _e2351;
                            phi_684_ = _e2353;
                            phi_687_ = _e2355;
                            phi_689_ = _e2357;
                            phi_691_ = _e2359;
                            phi_693_ = _e2361;
                            phi_695_ = _e2363;
                            phi_697_ = _e2365;
                            phi_699_ = _e2367;
                            phi_2933_ = _e2351;
                            break if !(_e2370);
                        }
                    }
                    let _e2373 = phi_2933_;
                    phi_2973_ = _e2373;
                    if _e2373 {
                        break;
                    }
                    let _e2374 = local_87;
                    let _e2375 = local_80;
                    if (_e2374 < _e2375) {
                        let _e2377 = local_87;
                        let _e2378 = local_330;
                        let _e2381 = local_96;
                        let _e2384 = local_88;
                        phi_1850_ = (_e2384 | (_e2381 << bitcast<u32>(((_e2377 * _e2378) & 31u))));
                    } else {
                        phi_1850_ = _e894;
                    }
                    let _e2387 = phi_1850_;
                    let _e2388 = local_330;
                    let _e2390 = local_86;
                    let _e2392 = local_87;
                    phi_2974_ = _e2373;
                    let _e3448 = local_342;
                    phi_631_ = _e3448;
                    let _e3451 = local_343;
                    phi_634_ = _e3451;
                    let _e3454 = local_344;
                    phi_636_ = _e3454;
                    let _e3457 = local_345;
                    phi_638_ = _e3457;
                    let _e3460 = local_346;
                    phi_640_ = _e3460;
                    phi_642_ = (_e2390 + (256u * _e2388));
                    phi_644_ = (_e2392 + 1u);
                    phi_646_ = _e2387;
                } else {
                    phi_2974_ = _e878;
                    phi_631_ = u32();
                    phi_634_ = u32();
                    phi_636_ = u32();
                    phi_638_ = u32();
                    phi_640_ = u32();
                    phi_642_ = u32();
                    phi_644_ = u32();
                    phi_646_ = u32();
                }
                let _e2395 = phi_2974_;
                let _e2397 = phi_631_;
                let _e2399 = phi_634_;
                let _e2401 = phi_636_;
                let _e2403 = phi_638_;
                let _e2405 = phi_640_;
                let _e2407 = phi_642_;
                let _e2409 = phi_644_;
                let _e2411 = phi_646_;
                continue;
                continuing {
                    let _e2412 = local_89;
                    phi_2879_ = _e2395;
                    phi_630_ = _e2397;
                    phi_633_ = _e2399;
                    phi_635_ = _e2401;
                    phi_637_ = _e2403;
                    phi_639_ = _e2405;
                    phi_641_ = _e2407;
                    phi_643_ = _e2409;
                    phi_645_ = _e2411;
                    phi_2973_ = _e2395;
                    break if !(_e2412);
                }
            }
            let _e2415 = phi_2973_;
            if _e2415 {
                break;
            }
            let _e2416 = local_19;
            let _e2418 = local;
            let _e2419 = ((_e2416 * 256u) + _e2418);
            local_219 = _e2419;
            let _e2420 = local_11;
            if (_e2419 < _e2420) {
            } else {
                break;
            }
            let _e2422 = local_219;
            let _e2425 = local_88;
            global_13.member[_e2422] = _e2425;
            let _e2426 = local;
            let _e2427 = (_e2426 < 1792u);
            local_220 = _e2427;
            if _e2427 {
            } else {
                break;
            }
            let _e2428 = local;
            let _e2430 = local_85;
            global_15[_e2428] = _e2430;
            let _e2431 = local;
            let _e2432 = (256u + _e2431);
            local_221 = _e2432;
            let _e2433 = (_e2432 < 1792u);
            local_222 = _e2433;
            if _e2433 {
            } else {
                break;
            }
            let _e2434 = local_221;
            let _e2436 = local_84;
            global_15[_e2434] = _e2436;
            let _e2437 = local;
            let _e2438 = (512u + _e2437);
            local_223 = _e2438;
            let _e2439 = (_e2438 < 1792u);
            local_224 = _e2439;
            if _e2439 {
            } else {
                break;
            }
            let _e2440 = local_223;
            let _e2442 = local_83;
            global_15[_e2440] = _e2442;
            let _e2443 = local_331;
            let _e2444 = local;
            let _e2445 = (_e2443 + _e2444);
            local_225 = _e2445;
            let _e2446 = (_e2445 < 1792u);
            local_226 = _e2446;
            if _e2446 {
            } else {
                break;
            }
            let _e2447 = local_225;
            let _e2449 = local_82;
            global_15[_e2447] = _e2449;
            let _e2450 = local;
            let _e2451 = (1536u + _e2450);
            local_227 = _e2451;
            let _e2452 = (_e2451 < 1792u);
            local_228 = _e2452;
            if _e2452 {
            } else {
                break;
            }
            let _e2453 = local_227;
            let _e2455 = local_81;
            global_15[_e2453] = _e2455;
            storageBarrier();
            workgroupBarrier();
            let _e2456 = local_37;
            if _e2456 {
                let _e2457 = local_1;
                let _e2459 = local_1;
                if ((_e2459 & (_e2457 - 1u)) == 0u) {
                    let _e2462 = local_2;
                    let _e2463 = local_1;
                    let _e2465 = ((_e2462 * _e2463) == 256u);
                    local_229 = _e2465;
                    if _e2465 {
                        let _e2466 = local_1;
                        phi_1913_ = type_16(1u, _e2466);
                    } else {
                        phi_1913_ = type_16();
                    }
                    let _e2469 = phi_1913_;
                    let _e2470 = local_229;
                    phi_1915_ = _e2469;
                    phi_1916_ = select(true, false, _e2470);
                } else {
                    phi_1915_ = type_16();
                    phi_1916_ = true;
                }
                let _e2473 = phi_1915_;
                let _e2475 = phi_1916_;
                phi_1917_ = _e2473;
                phi_1918_ = _e2475;
            } else {
                phi_1917_ = type_16();
                phi_1918_ = true;
            }
            let _e2477 = phi_1917_;
            let _e2479 = phi_1918_;
            if _e2479 {
                phi_1923_ = type_16(0u, type_16().member_1);
            } else {
                phi_1923_ = _e2477;
            }
            let _e2484 = phi_1923_;
            local_230 = _e2484.member_1;
            if (bitcast<i32>(_e2484.member) != 0i) {
                let _e2519 = local_230;
                let _e2521 = local_230;
                local_231 = select(firstTrailingBit(_e2519), 32u, (_e2521 == 0u));
                phi_1935_ = 0u;
                phi_1938_ = 256u;
                loop {
                    let _e2525 = phi_1935_;
                    let _e2527 = phi_1938_;
                    local_232 = _e2525;
                    local_233 = _e2527;
                    let _e2528 = local_233;
                    let _e2529 = local_230;
                    let _e2530 = (_e2528 > _e2529);
                    local_234 = _e2530;
                    if _e2530 {
                        let _e2531 = local_3;
                        let _e2532 = local_1;
                        let _e2534 = local_4;
                        let _e2535 = ((_e2531 * _e2532) + _e2534);
                        local_235 = _e2535;
                        let _e2536 = local_233;
                        let _e2537 = (_e2535 < _e2536);
                        local_236 = _e2537;
                        if _e2537 {
                            let _e2538 = local_232;
                            let _e2540 = local_235;
                            let _e2542 = (_e2540 << bitcast<u32>((_e2538 & 31u)));
                            local_237 = _e2542;
                            if (_e2542 < 1792u) {
                            } else {
                                phi_2984_ = true;
                                break;
                            }
                            let _e2544 = local_237;
                            let _e2546 = global_15[_e2544];
                            phi_1962_ = _e2546;
                        } else {
                            phi_1962_ = 0u;
                        }
                        let _e2548 = phi_1962_;
                        let _e2549 = subgroupAdd(_e2548);
                        local_238 = _e2549;
                        let _e2550 = local_236;
                        if _e2550 {
                            let _e2551 = local_230;
                            let _e2553 = local_235;
                            if ((_e2553 & (_e2551 - 1u)) == 0u) {
                                let _e2556 = local_232;
                                let _e2558 = local_235;
                                let _e2560 = (_e2558 << bitcast<u32>((_e2556 & 31u)));
                                local_239 = _e2560;
                                if (_e2560 < 1792u) {
                                } else {
                                    phi_2984_ = true;
                                    break;
                                }
                                let _e2562 = local_239;
                                let _e2564 = local_238;
                                global_15[_e2562] = _e2564;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e2565 = local_231;
                        let _e2567 = local_233;
                        let _e2570 = local_232;
                        let _e2571 = local_231;
                        phi_1936_ = (_e2570 + _e2571);
                        phi_1939_ = (_e2567 >> bitcast<u32>((_e2565 & 31u)));
                    } else {
                        phi_1936_ = u32();
                        phi_1939_ = u32();
                    }
                    let _e2574 = phi_1936_;
                    let _e2576 = phi_1939_;
                    continue;
                    continuing {
                        let _e2577 = local_234;
                        phi_1935_ = _e2574;
                        phi_1938_ = _e2576;
                        phi_2984_ = _e2415;
                        break if !(_e2577);
                    }
                }
                let _e2580 = phi_2984_;
                if _e2580 {
                    break;
                }
                let _e2581 = local_3;
                let _e2582 = local_1;
                let _e2584 = local_4;
                let _e2586 = local_230;
                let _e2588 = (((_e2581 * _e2582) + _e2584) & (_e2586 - 1u));
                local_240 = _e2588;
                let _e2589 = local_233;
                if (_e2588 < _e2589) {
                    let _e2591 = local_232;
                    let _e2593 = local_240;
                    let _e2595 = (_e2593 << bitcast<u32>((_e2591 & 31u)));
                    local_241 = _e2595;
                    if (_e2595 < 1792u) {
                    } else {
                        break;
                    }
                    let _e2597 = local_241;
                    let _e2599 = global_15[_e2597];
                    phi_2010_ = _e2599;
                } else {
                    phi_2010_ = 0u;
                }
                let _e2601 = phi_2010_;
                let _e2602 = subgroupAdd(_e2601);
                storageBarrier();
                workgroupBarrier();
                phi_2995_ = _e2580;
                phi_2064_ = _e2602;
            } else {
                phi_2020_ = 128u;
                loop {
                    let _e2490 = phi_2020_;
                    local_242 = _e2490;
                    let _e2491 = local_242;
                    let _e2492 = (_e2491 > 0u);
                    local_243 = _e2492;
                    if _e2492 {
                        let _e2493 = local;
                        let _e2494 = local_242;
                        if (_e2493 < _e2494) {
                            let _e2496 = local_220;
                            if _e2496 {
                            } else {
                                phi_2976_ = true;
                                break;
                            }
                            let _e2497 = global_15[_e2428];
                            local_244 = _e2497;
                            let _e2498 = local;
                            let _e2499 = local_242;
                            let _e2500 = (_e2498 + _e2499);
                            local_245 = _e2500;
                            if (_e2500 < 1792u) {
                            } else {
                                phi_2976_ = true;
                                break;
                            }
                            let _e2502 = local_245;
                            let _e2504 = global_15[_e2502];
                            let _e2505 = local_244;
                            local_246 = (_e2505 + _e2504);
                            let _e2507 = local_220;
                            if _e2507 {
                            } else {
                                phi_2976_ = true;
                                break;
                            }
                            let _e2508 = local_246;
                            global_15[_e2428] = _e2508;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e2509 = local_242;
                        phi_2021_ = (_e2509 / 2u);
                    } else {
                        phi_2021_ = u32();
                    }
                    let _e2512 = phi_2021_;
                    continue;
                    continuing {
                        let _e2513 = local_243;
                        phi_2020_ = _e2512;
                        phi_2976_ = _e2415;
                        break if !(_e2513);
                    }
                }
                let _e2516 = phi_2976_;
                if _e2516 {
                    break;
                }
                let _e2518 = global_15[0u];
                storageBarrier();
                workgroupBarrier();
                phi_2995_ = _e2516;
                phi_2064_ = _e2518;
            }
            let _e2604 = phi_2995_;
            let _e2606 = phi_2064_;
            local_247 = _e2606;
            let _e2607 = local_37;
            if _e2607 {
                let _e2608 = local_1;
                let _e2610 = local_1;
                if ((_e2610 & (_e2608 - 1u)) == 0u) {
                    let _e2613 = local_2;
                    let _e2614 = local_1;
                    let _e2616 = ((_e2613 * _e2614) == 256u);
                    local_248 = _e2616;
                    if _e2616 {
                        let _e2617 = local_1;
                        phi_2081_ = type_16(1u, _e2617);
                    } else {
                        phi_2081_ = type_16();
                    }
                    let _e2620 = phi_2081_;
                    let _e2621 = local_248;
                    phi_2083_ = _e2620;
                    phi_2084_ = select(true, false, _e2621);
                } else {
                    phi_2083_ = type_16();
                    phi_2084_ = true;
                }
                let _e2624 = phi_2083_;
                let _e2626 = phi_2084_;
                phi_2085_ = _e2624;
                phi_2086_ = _e2626;
            } else {
                phi_2085_ = type_16();
                phi_2086_ = true;
            }
            let _e2628 = phi_2085_;
            let _e2630 = phi_2086_;
            if _e2630 {
                phi_2091_ = type_16(0u, type_16().member_1);
            } else {
                phi_2091_ = _e2628;
            }
            let _e2635 = phi_2091_;
            local_249 = _e2635.member_1;
            if (bitcast<i32>(_e2635.member) != 0i) {
                let _e2670 = local_249;
                let _e2672 = local_249;
                local_250 = select(firstTrailingBit(_e2670), 32u, (_e2672 == 0u));
                phi_2103_ = 0u;
                phi_2106_ = 256u;
                loop {
                    let _e2676 = phi_2103_;
                    let _e2678 = phi_2106_;
                    local_251 = _e2676;
                    local_252 = _e2678;
                    let _e2679 = local_252;
                    let _e2680 = local_249;
                    let _e2681 = (_e2679 > _e2680);
                    local_253 = _e2681;
                    if _e2681 {
                        let _e2682 = local_3;
                        let _e2683 = local_1;
                        let _e2685 = local_4;
                        let _e2686 = ((_e2682 * _e2683) + _e2685);
                        local_254 = _e2686;
                        let _e2687 = local_252;
                        let _e2688 = (_e2686 < _e2687);
                        local_255 = _e2688;
                        if _e2688 {
                            let _e2689 = local_251;
                            let _e2691 = local_254;
                            let _e2694 = (256u + (_e2691 << bitcast<u32>((_e2689 & 31u))));
                            local_256 = _e2694;
                            if (_e2694 < 1792u) {
                            } else {
                                phi_3000_ = true;
                                break;
                            }
                            let _e2696 = local_256;
                            let _e2698 = global_15[_e2696];
                            phi_2130_ = _e2698;
                        } else {
                            phi_2130_ = 0u;
                        }
                        let _e2700 = phi_2130_;
                        let _e2701 = subgroupAdd(_e2700);
                        local_257 = _e2701;
                        let _e2702 = local_255;
                        if _e2702 {
                            let _e2703 = local_249;
                            let _e2705 = local_254;
                            if ((_e2705 & (_e2703 - 1u)) == 0u) {
                                let _e2708 = local_251;
                                let _e2710 = local_254;
                                let _e2713 = (256u + (_e2710 << bitcast<u32>((_e2708 & 31u))));
                                local_258 = _e2713;
                                if (_e2713 < 1792u) {
                                } else {
                                    phi_3000_ = true;
                                    break;
                                }
                                let _e2715 = local_258;
                                let _e2717 = local_257;
                                global_15[_e2715] = _e2717;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e2718 = local_250;
                        let _e2720 = local_252;
                        let _e2723 = local_251;
                        let _e2724 = local_250;
                        phi_2104_ = (_e2723 + _e2724);
                        phi_2107_ = (_e2720 >> bitcast<u32>((_e2718 & 31u)));
                    } else {
                        phi_2104_ = u32();
                        phi_2107_ = u32();
                    }
                    let _e2727 = phi_2104_;
                    let _e2729 = phi_2107_;
                    continue;
                    continuing {
                        let _e2730 = local_253;
                        phi_2103_ = _e2727;
                        phi_2106_ = _e2729;
                        phi_3000_ = _e2604;
                        break if !(_e2730);
                    }
                }
                let _e2733 = phi_3000_;
                if _e2733 {
                    break;
                }
                let _e2734 = local_3;
                let _e2735 = local_1;
                let _e2737 = local_4;
                let _e2739 = local_249;
                let _e2741 = (((_e2734 * _e2735) + _e2737) & (_e2739 - 1u));
                local_259 = _e2741;
                let _e2742 = local_252;
                if (_e2741 < _e2742) {
                    let _e2744 = local_251;
                    let _e2746 = local_259;
                    let _e2749 = (256u + (_e2746 << bitcast<u32>((_e2744 & 31u))));
                    local_260 = _e2749;
                    if (_e2749 < 1792u) {
                    } else {
                        break;
                    }
                    let _e2751 = local_260;
                    let _e2753 = global_15[_e2751];
                    phi_2178_ = _e2753;
                } else {
                    phi_2178_ = 0u;
                }
                let _e2755 = phi_2178_;
                let _e2756 = subgroupAdd(_e2755);
                storageBarrier();
                workgroupBarrier();
                phi_3011_ = _e2733;
                phi_2232_ = _e2756;
            } else {
                phi_2188_ = 128u;
                loop {
                    let _e2641 = phi_2188_;
                    local_261 = _e2641;
                    let _e2642 = local_261;
                    let _e2643 = (_e2642 > 0u);
                    local_262 = _e2643;
                    if _e2643 {
                        let _e2644 = local;
                        let _e2645 = local_261;
                        if (_e2644 < _e2645) {
                            let _e2647 = local_222;
                            if _e2647 {
                            } else {
                                phi_2990_ = true;
                                break;
                            }
                            let _e2648 = global_15[_e2434];
                            local_263 = _e2648;
                            let _e2649 = local_221;
                            let _e2650 = local_261;
                            let _e2651 = (_e2649 + _e2650);
                            local_264 = _e2651;
                            if (_e2651 < 1792u) {
                            } else {
                                phi_2990_ = true;
                                break;
                            }
                            let _e2653 = local_264;
                            let _e2655 = global_15[_e2653];
                            let _e2656 = local_263;
                            local_265 = (_e2656 + _e2655);
                            let _e2658 = local_222;
                            if _e2658 {
                            } else {
                                phi_2990_ = true;
                                break;
                            }
                            let _e2659 = local_265;
                            global_15[_e2434] = _e2659;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e2660 = local_261;
                        phi_2189_ = (_e2660 / 2u);
                    } else {
                        phi_2189_ = u32();
                    }
                    let _e2663 = phi_2189_;
                    continue;
                    continuing {
                        let _e2664 = local_262;
                        phi_2188_ = _e2663;
                        phi_2990_ = _e2604;
                        break if !(_e2664);
                    }
                }
                let _e2667 = phi_2990_;
                if _e2667 {
                    break;
                }
                let _e2669 = global_15[256u];
                storageBarrier();
                workgroupBarrier();
                phi_3011_ = _e2667;
                phi_2232_ = _e2669;
            }
            let _e2758 = phi_3011_;
            let _e2760 = phi_2232_;
            local_266 = _e2760;
            let _e2761 = local_37;
            if _e2761 {
                let _e2762 = local_1;
                let _e2764 = local_1;
                if ((_e2764 & (_e2762 - 1u)) == 0u) {
                    let _e2767 = local_2;
                    let _e2768 = local_1;
                    let _e2770 = ((_e2767 * _e2768) == 256u);
                    local_267 = _e2770;
                    if _e2770 {
                        let _e2771 = local_1;
                        phi_2249_ = type_16(1u, _e2771);
                    } else {
                        phi_2249_ = type_16();
                    }
                    let _e2774 = phi_2249_;
                    let _e2775 = local_267;
                    phi_2251_ = _e2774;
                    phi_2252_ = select(true, false, _e2775);
                } else {
                    phi_2251_ = type_16();
                    phi_2252_ = true;
                }
                let _e2778 = phi_2251_;
                let _e2780 = phi_2252_;
                phi_2253_ = _e2778;
                phi_2254_ = _e2780;
            } else {
                phi_2253_ = type_16();
                phi_2254_ = true;
            }
            let _e2782 = phi_2253_;
            let _e2784 = phi_2254_;
            if _e2784 {
                phi_2259_ = type_16(0u, type_16().member_1);
            } else {
                phi_2259_ = _e2782;
            }
            let _e2789 = phi_2259_;
            local_268 = _e2789.member_1;
            if (bitcast<i32>(_e2789.member) != 0i) {
                let _e2824 = local_268;
                let _e2826 = local_268;
                local_269 = select(firstTrailingBit(_e2824), 32u, (_e2826 == 0u));
                phi_2271_ = 0u;
                phi_2274_ = 256u;
                loop {
                    let _e2830 = phi_2271_;
                    let _e2832 = phi_2274_;
                    local_270 = _e2830;
                    local_271 = _e2832;
                    let _e2833 = local_271;
                    let _e2834 = local_268;
                    let _e2835 = (_e2833 > _e2834);
                    local_272 = _e2835;
                    if _e2835 {
                        let _e2836 = local_3;
                        let _e2837 = local_1;
                        let _e2839 = local_4;
                        let _e2840 = ((_e2836 * _e2837) + _e2839);
                        local_273 = _e2840;
                        let _e2841 = local_271;
                        let _e2842 = (_e2840 < _e2841);
                        local_274 = _e2842;
                        if _e2842 {
                            let _e2843 = local_270;
                            let _e2845 = local_273;
                            let _e2848 = (512u + (_e2845 << bitcast<u32>((_e2843 & 31u))));
                            local_275 = _e2848;
                            if (_e2848 < 1792u) {
                            } else {
                                phi_3016_ = true;
                                break;
                            }
                            let _e2850 = local_275;
                            let _e2852 = global_15[_e2850];
                            phi_2298_ = _e2852;
                        } else {
                            phi_2298_ = 0u;
                        }
                        let _e2854 = phi_2298_;
                        let _e2855 = subgroupAdd(_e2854);
                        local_276 = _e2855;
                        let _e2856 = local_274;
                        if _e2856 {
                            let _e2857 = local_268;
                            let _e2859 = local_273;
                            if ((_e2859 & (_e2857 - 1u)) == 0u) {
                                let _e2862 = local_270;
                                let _e2864 = local_273;
                                let _e2867 = (512u + (_e2864 << bitcast<u32>((_e2862 & 31u))));
                                local_277 = _e2867;
                                if (_e2867 < 1792u) {
                                } else {
                                    phi_3016_ = true;
                                    break;
                                }
                                let _e2869 = local_277;
                                let _e2871 = local_276;
                                global_15[_e2869] = _e2871;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e2872 = local_269;
                        let _e2874 = local_271;
                        let _e2877 = local_270;
                        let _e2878 = local_269;
                        phi_2272_ = (_e2877 + _e2878);
                        phi_2275_ = (_e2874 >> bitcast<u32>((_e2872 & 31u)));
                    } else {
                        phi_2272_ = u32();
                        phi_2275_ = u32();
                    }
                    let _e2881 = phi_2272_;
                    let _e2883 = phi_2275_;
                    continue;
                    continuing {
                        let _e2884 = local_272;
                        phi_2271_ = _e2881;
                        phi_2274_ = _e2883;
                        phi_3016_ = _e2758;
                        break if !(_e2884);
                    }
                }
                let _e2887 = phi_3016_;
                if _e2887 {
                    break;
                }
                let _e2888 = local_3;
                let _e2889 = local_1;
                let _e2891 = local_4;
                let _e2893 = local_268;
                let _e2895 = (((_e2888 * _e2889) + _e2891) & (_e2893 - 1u));
                local_278 = _e2895;
                let _e2896 = local_271;
                if (_e2895 < _e2896) {
                    let _e2898 = local_270;
                    let _e2900 = local_278;
                    let _e2903 = (512u + (_e2900 << bitcast<u32>((_e2898 & 31u))));
                    local_279 = _e2903;
                    if (_e2903 < 1792u) {
                    } else {
                        break;
                    }
                    let _e2905 = local_279;
                    let _e2907 = global_15[_e2905];
                    phi_2346_ = _e2907;
                } else {
                    phi_2346_ = 0u;
                }
                let _e2909 = phi_2346_;
                let _e2910 = subgroupAdd(_e2909);
                storageBarrier();
                workgroupBarrier();
                phi_3027_ = _e2887;
                phi_2400_ = _e2910;
            } else {
                phi_2356_ = 128u;
                loop {
                    let _e2795 = phi_2356_;
                    local_280 = _e2795;
                    let _e2796 = local_280;
                    let _e2797 = (_e2796 > 0u);
                    local_281 = _e2797;
                    if _e2797 {
                        let _e2798 = local;
                        let _e2799 = local_280;
                        if (_e2798 < _e2799) {
                            let _e2801 = local_224;
                            if _e2801 {
                            } else {
                                phi_3006_ = true;
                                break;
                            }
                            let _e2802 = global_15[_e2440];
                            local_282 = _e2802;
                            let _e2803 = local_223;
                            let _e2804 = local_280;
                            let _e2805 = (_e2803 + _e2804);
                            local_283 = _e2805;
                            if (_e2805 < 1792u) {
                            } else {
                                phi_3006_ = true;
                                break;
                            }
                            let _e2807 = local_283;
                            let _e2809 = global_15[_e2807];
                            let _e2810 = local_282;
                            local_284 = (_e2810 + _e2809);
                            let _e2812 = local_224;
                            if _e2812 {
                            } else {
                                phi_3006_ = true;
                                break;
                            }
                            let _e2813 = local_284;
                            global_15[_e2440] = _e2813;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e2814 = local_280;
                        phi_2357_ = (_e2814 / 2u);
                    } else {
                        phi_2357_ = u32();
                    }
                    let _e2817 = phi_2357_;
                    continue;
                    continuing {
                        let _e2818 = local_281;
                        phi_2356_ = _e2817;
                        phi_3006_ = _e2758;
                        break if !(_e2818);
                    }
                }
                let _e2821 = phi_3006_;
                if _e2821 {
                    break;
                }
                let _e2823 = global_15[512u];
                storageBarrier();
                workgroupBarrier();
                phi_3027_ = _e2821;
                phi_2400_ = _e2823;
            }
            let _e2912 = phi_3027_;
            let _e2914 = phi_2400_;
            local_285 = _e2914;
            let _e2915 = local_37;
            if _e2915 {
                let _e2916 = local_1;
                let _e2918 = local_1;
                if ((_e2918 & (_e2916 - 1u)) == 0u) {
                    let _e2921 = local_2;
                    let _e2922 = local_1;
                    let _e2924 = ((_e2921 * _e2922) == 256u);
                    local_286 = _e2924;
                    if _e2924 {
                        let _e2925 = local_1;
                        phi_2417_ = type_16(1u, _e2925);
                    } else {
                        phi_2417_ = type_16();
                    }
                    let _e2928 = phi_2417_;
                    let _e2929 = local_286;
                    phi_2419_ = _e2928;
                    phi_2420_ = select(true, false, _e2929);
                } else {
                    phi_2419_ = type_16();
                    phi_2420_ = true;
                }
                let _e2932 = phi_2419_;
                let _e2934 = phi_2420_;
                phi_2421_ = _e2932;
                phi_2422_ = _e2934;
            } else {
                phi_2421_ = type_16();
                phi_2422_ = true;
            }
            let _e2936 = phi_2421_;
            let _e2938 = phi_2422_;
            if _e2938 {
                phi_2427_ = type_16(0u, type_16().member_1);
            } else {
                phi_2427_ = _e2936;
            }
            let _e2943 = phi_2427_;
            local_287 = _e2943.member_1;
            if (bitcast<i32>(_e2943.member) != 0i) {
                let _e2981 = local_287;
                let _e2983 = local_287;
                local_288 = select(firstTrailingBit(_e2981), 32u, (_e2983 == 0u));
                phi_2439_ = 0u;
                phi_2442_ = 256u;
                loop {
                    let _e2987 = phi_2439_;
                    let _e2989 = phi_2442_;
                    local_289 = _e2987;
                    local_290 = _e2989;
                    let _e2990 = local_290;
                    let _e2991 = local_287;
                    let _e2992 = (_e2990 > _e2991);
                    local_291 = _e2992;
                    if _e2992 {
                        let _e2993 = local_3;
                        let _e2994 = local_1;
                        let _e2996 = local_4;
                        let _e2997 = ((_e2993 * _e2994) + _e2996);
                        local_292 = _e2997;
                        let _e2998 = local_290;
                        let _e2999 = (_e2997 < _e2998);
                        local_293 = _e2999;
                        if _e2999 {
                            let _e3000 = local_289;
                            let _e3002 = local_292;
                            let _e3005 = local_331;
                            let _e3006 = (_e3005 + (_e3002 << bitcast<u32>((_e3000 & 31u))));
                            local_294 = _e3006;
                            if (_e3006 < 1792u) {
                            } else {
                                phi_3032_ = true;
                                break;
                            }
                            let _e3008 = local_294;
                            let _e3010 = global_15[_e3008];
                            phi_2466_ = _e3010;
                        } else {
                            phi_2466_ = 0u;
                        }
                        let _e3012 = phi_2466_;
                        let _e3013 = subgroupAdd(_e3012);
                        local_295 = _e3013;
                        let _e3014 = local_293;
                        if _e3014 {
                            let _e3015 = local_287;
                            let _e3017 = local_292;
                            if ((_e3017 & (_e3015 - 1u)) == 0u) {
                                let _e3020 = local_289;
                                let _e3022 = local_292;
                                let _e3025 = local_331;
                                let _e3026 = (_e3025 + (_e3022 << bitcast<u32>((_e3020 & 31u))));
                                local_296 = _e3026;
                                if (_e3026 < 1792u) {
                                } else {
                                    phi_3032_ = true;
                                    break;
                                }
                                let _e3028 = local_296;
                                let _e3030 = local_295;
                                global_15[_e3028] = _e3030;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e3031 = local_288;
                        let _e3033 = local_290;
                        let _e3036 = local_289;
                        let _e3037 = local_288;
                        phi_2440_ = (_e3036 + _e3037);
                        phi_2443_ = (_e3033 >> bitcast<u32>((_e3031 & 31u)));
                    } else {
                        phi_2440_ = u32();
                        phi_2443_ = u32();
                    }
                    let _e3040 = phi_2440_;
                    let _e3042 = phi_2443_;
                    continue;
                    continuing {
                        let _e3043 = local_291;
                        phi_2439_ = _e3040;
                        phi_2442_ = _e3042;
                        phi_3032_ = _e2912;
                        break if !(_e3043);
                    }
                }
                let _e3046 = phi_3032_;
                if _e3046 {
                    break;
                }
                let _e3047 = local_3;
                let _e3048 = local_1;
                let _e3050 = local_4;
                let _e3052 = local_287;
                let _e3054 = (((_e3047 * _e3048) + _e3050) & (_e3052 - 1u));
                local_297 = _e3054;
                let _e3055 = local_290;
                if (_e3054 < _e3055) {
                    let _e3057 = local_289;
                    let _e3059 = local_297;
                    let _e3062 = local_331;
                    let _e3063 = (_e3062 + (_e3059 << bitcast<u32>((_e3057 & 31u))));
                    local_298 = _e3063;
                    if (_e3063 < 1792u) {
                    } else {
                        break;
                    }
                    let _e3065 = local_298;
                    let _e3067 = global_15[_e3065];
                    phi_2514_ = _e3067;
                } else {
                    phi_2514_ = 0u;
                }
                let _e3069 = phi_2514_;
                let _e3070 = subgroupAdd(_e3069);
                storageBarrier();
                workgroupBarrier();
                phi_3043_ = _e3046;
                phi_2568_ = _e3070;
            } else {
                phi_2524_ = 128u;
                loop {
                    let _e2949 = phi_2524_;
                    local_299 = _e2949;
                    let _e2950 = local_299;
                    let _e2951 = (_e2950 > 0u);
                    local_300 = _e2951;
                    if _e2951 {
                        let _e2952 = local;
                        let _e2953 = local_299;
                        if (_e2952 < _e2953) {
                            let _e2955 = local_226;
                            if _e2955 {
                            } else {
                                phi_3022_ = true;
                                break;
                            }
                            let _e2956 = global_15[_e2447];
                            local_301 = _e2956;
                            let _e2957 = local_225;
                            let _e2958 = local_299;
                            let _e2959 = (_e2957 + _e2958);
                            local_302 = _e2959;
                            if (_e2959 < 1792u) {
                            } else {
                                phi_3022_ = true;
                                break;
                            }
                            let _e2961 = local_302;
                            let _e2963 = global_15[_e2961];
                            let _e2964 = local_301;
                            local_303 = (_e2964 + _e2963);
                            let _e2966 = local_226;
                            if _e2966 {
                            } else {
                                phi_3022_ = true;
                                break;
                            }
                            let _e2967 = local_303;
                            global_15[_e2447] = _e2967;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e2968 = local_299;
                        phi_2525_ = (_e2968 / 2u);
                    } else {
                        phi_2525_ = u32();
                    }
                    let _e2971 = phi_2525_;
                    continue;
                    continuing {
                        let _e2972 = local_300;
                        phi_2524_ = _e2971;
                        phi_3022_ = _e2912;
                        break if !(_e2972);
                    }
                }
                let _e2975 = phi_3022_;
                if _e2975 {
                    break;
                }
                let _e2976 = local_331;
                if (_e2976 < 1792u) {
                } else {
                    break;
                }
                let _e2978 = local_331;
                let _e2980 = global_15[_e2978];
                storageBarrier();
                workgroupBarrier();
                phi_3043_ = _e2975;
                phi_2568_ = _e2980;
            }
            let _e3072 = phi_3043_;
            let _e3074 = phi_2568_;
            local_304 = _e3074;
            let _e3075 = local_37;
            if _e3075 {
                let _e3076 = local_1;
                let _e3078 = local_1;
                if ((_e3078 & (_e3076 - 1u)) == 0u) {
                    let _e3081 = local_2;
                    let _e3082 = local_1;
                    let _e3084 = ((_e3081 * _e3082) == 256u);
                    local_305 = _e3084;
                    if _e3084 {
                        let _e3085 = local_1;
                        phi_2585_ = type_16(1u, _e3085);
                    } else {
                        phi_2585_ = type_16();
                    }
                    let _e3088 = phi_2585_;
                    let _e3089 = local_305;
                    phi_2587_ = _e3088;
                    phi_2588_ = select(true, false, _e3089);
                } else {
                    phi_2587_ = type_16();
                    phi_2588_ = true;
                }
                let _e3092 = phi_2587_;
                let _e3094 = phi_2588_;
                phi_2589_ = _e3092;
                phi_2590_ = _e3094;
            } else {
                phi_2589_ = type_16();
                phi_2590_ = true;
            }
            let _e3096 = phi_2589_;
            let _e3098 = phi_2590_;
            if _e3098 {
                phi_2595_ = type_16(0u, type_16().member_1);
            } else {
                phi_2595_ = _e3096;
            }
            let _e3103 = phi_2595_;
            local_306 = _e3103.member_1;
            if (bitcast<i32>(_e3103.member) != 0i) {
                let _e3138 = local_306;
                let _e3140 = local_306;
                local_307 = select(firstTrailingBit(_e3138), 32u, (_e3140 == 0u));
                phi_2607_ = 0u;
                phi_2610_ = 256u;
                loop {
                    let _e3144 = phi_2607_;
                    let _e3146 = phi_2610_;
                    local_308 = _e3144;
                    local_309 = _e3146;
                    let _e3147 = local_309;
                    let _e3148 = local_306;
                    let _e3149 = (_e3147 > _e3148);
                    local_310 = _e3149;
                    if _e3149 {
                        let _e3150 = local_3;
                        let _e3151 = local_1;
                        let _e3153 = local_4;
                        let _e3154 = ((_e3150 * _e3151) + _e3153);
                        local_311 = _e3154;
                        let _e3155 = local_309;
                        let _e3156 = (_e3154 < _e3155);
                        local_312 = _e3156;
                        if _e3156 {
                            let _e3157 = local_308;
                            let _e3159 = local_311;
                            let _e3162 = (1536u + (_e3159 << bitcast<u32>((_e3157 & 31u))));
                            local_313 = _e3162;
                            if (_e3162 < 1792u) {
                            } else {
                                phi_3048_ = true;
                                break;
                            }
                            let _e3164 = local_313;
                            let _e3166 = global_15[_e3164];
                            phi_2634_ = _e3166;
                        } else {
                            phi_2634_ = 0u;
                        }
                        let _e3168 = phi_2634_;
                        let _e3169 = subgroupAdd(_e3168);
                        local_314 = _e3169;
                        let _e3170 = local_312;
                        if _e3170 {
                            let _e3171 = local_306;
                            let _e3173 = local_311;
                            if ((_e3173 & (_e3171 - 1u)) == 0u) {
                                let _e3176 = local_308;
                                let _e3178 = local_311;
                                let _e3181 = (1536u + (_e3178 << bitcast<u32>((_e3176 & 31u))));
                                local_315 = _e3181;
                                if (_e3181 < 1792u) {
                                } else {
                                    phi_3048_ = true;
                                    break;
                                }
                                let _e3183 = local_315;
                                let _e3185 = local_314;
                                global_15[_e3183] = _e3185;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e3186 = local_307;
                        let _e3188 = local_309;
                        let _e3191 = local_308;
                        let _e3192 = local_307;
                        phi_2608_ = (_e3191 + _e3192);
                        phi_2611_ = (_e3188 >> bitcast<u32>((_e3186 & 31u)));
                    } else {
                        phi_2608_ = u32();
                        phi_2611_ = u32();
                    }
                    let _e3195 = phi_2608_;
                    let _e3197 = phi_2611_;
                    continue;
                    continuing {
                        let _e3198 = local_310;
                        phi_2607_ = _e3195;
                        phi_2610_ = _e3197;
                        phi_3048_ = _e3072;
                        break if !(_e3198);
                    }
                }
                let _e3201 = phi_3048_;
                if _e3201 {
                    break;
                }
                let _e3202 = local_3;
                let _e3203 = local_1;
                let _e3205 = local_4;
                let _e3207 = local_306;
                let _e3209 = (((_e3202 * _e3203) + _e3205) & (_e3207 - 1u));
                local_316 = _e3209;
                let _e3210 = local_309;
                if (_e3209 < _e3210) {
                    let _e3212 = local_308;
                    let _e3214 = local_316;
                    let _e3217 = (1536u + (_e3214 << bitcast<u32>((_e3212 & 31u))));
                    local_317 = _e3217;
                    if (_e3217 < 1792u) {
                    } else {
                        break;
                    }
                    let _e3219 = local_317;
                    let _e3221 = global_15[_e3219];
                    phi_2682_ = _e3221;
                } else {
                    phi_2682_ = 0u;
                }
                let _e3223 = phi_2682_;
                let _e3224 = subgroupAdd(_e3223);
                storageBarrier();
                workgroupBarrier();
                phi_2736_ = _e3224;
            } else {
                phi_2692_ = 128u;
                loop {
                    let _e3109 = phi_2692_;
                    local_318 = _e3109;
                    let _e3110 = local_318;
                    let _e3111 = (_e3110 > 0u);
                    local_319 = _e3111;
                    if _e3111 {
                        let _e3112 = local;
                        let _e3113 = local_318;
                        if (_e3112 < _e3113) {
                            let _e3115 = local_228;
                            if _e3115 {
                            } else {
                                phi_3038_ = true;
                                break;
                            }
                            let _e3116 = global_15[_e2453];
                            local_320 = _e3116;
                            let _e3117 = local_227;
                            let _e3118 = local_318;
                            let _e3119 = (_e3117 + _e3118);
                            local_321 = _e3119;
                            if (_e3119 < 1792u) {
                            } else {
                                phi_3038_ = true;
                                break;
                            }
                            let _e3121 = local_321;
                            let _e3123 = global_15[_e3121];
                            let _e3124 = local_320;
                            local_322 = (_e3124 + _e3123);
                            let _e3126 = local_228;
                            if _e3126 {
                            } else {
                                phi_3038_ = true;
                                break;
                            }
                            let _e3127 = local_322;
                            global_15[_e2453] = _e3127;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e3128 = local_318;
                        phi_2693_ = (_e3128 / 2u);
                    } else {
                        phi_2693_ = u32();
                    }
                    let _e3131 = phi_2693_;
                    continue;
                    continuing {
                        let _e3132 = local_319;
                        phi_2692_ = _e3131;
                        phi_3038_ = _e3072;
                        break if !(_e3132);
                    }
                }
                let _e3135 = phi_3038_;
                if _e3135 {
                    break;
                }
                let _e3137 = global_15[1536u];
                storageBarrier();
                workgroupBarrier();
                phi_2736_ = _e3137;
            }
            let _e3226 = phi_2736_;
            local_323 = _e3226;
            let _e3227 = local;
            if (_e3227 == 0u) {
                let _e3229 = local_19;
                let _e3230 = (_e3229 * 5u);
                local_324 = _e3230;
                let _e3231 = local_10;
                if (_e3230 < _e3231) {
                } else {
                    break;
                }
                let _e3233 = local_324;
                let _e3236 = local_247;
                global_12.member[_e3233] = _e3236;
                let _e3237 = local_324;
                let _e3238 = (_e3237 + 1u);
                local_325 = _e3238;
                let _e3239 = local_10;
                if (_e3238 < _e3239) {
                } else {
                    break;
                }
                let _e3241 = local_325;
                let _e3244 = local_266;
                global_12.member[_e3241] = _e3244;
                let _e3245 = local_324;
                let _e3246 = (_e3245 + 2u);
                local_326 = _e3246;
                let _e3247 = local_10;
                if (_e3246 < _e3247) {
                } else {
                    break;
                }
                let _e3249 = local_326;
                let _e3252 = local_285;
                global_12.member[_e3249] = _e3252;
                let _e3253 = local_324;
                let _e3254 = (_e3253 + 3u);
                local_327 = _e3254;
                let _e3255 = local_10;
                if (_e3254 < _e3255) {
                } else {
                    break;
                }
                let _e3257 = local_327;
                let _e3260 = local_304;
                global_12.member[_e3257] = _e3260;
                let _e3261 = local_324;
                let _e3262 = (_e3261 + 4u);
                local_328 = _e3262;
                let _e3263 = local_10;
                if (_e3262 < _e3263) {
                } else {
                    break;
                }
                let _e3265 = local_328;
                let _e3268 = local_323;
                global_12.member[_e3265] = _e3268;
            }
            storageBarrier();
            workgroupBarrier();
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
