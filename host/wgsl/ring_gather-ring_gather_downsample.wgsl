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

struct type_22 {
    member: array<f32, 3>,
    member_1: f32,
}

struct type_23 {
    member: u32,
    member_1: type_22,
}

struct type_25 {
    member: array<f32, 3>,
    member_1: array<f32, 3>,
}

struct type_30 {
    member: array<f32, 2>,
    member_1: array<f32, 3>,
    member_2: f32,
    member_3: f32,
    member_4: array<f32, 3>,
    member_5: f32,
    member_6: u32,
    member_7: array<f32, 3>,
    member_8: f32,
    member_9: f32,
}

struct type_31 {
    member: array<f32, 4>,
    member_1: array<f32, 3>,
}

struct type_44 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<immediate> global_2: type_7;
@group(0) @binding(1) 
var<storage> global_3: type_10;
@group(0) @binding(0) 
var<storage> global_4: type_10;
@group(0) @binding(2) 
var<storage, read_write> global_5: type_10;
@group(0) @binding(3) 
var<storage, read_write> global_6: type_10;
@group(0) @binding(4) 
var<storage, read_write> global_7: type_10;
@group(0) @binding(5) 
var<storage, read_write> global_8: type_10;
@group(0) @binding(6) 
var<storage, read_write> global_9: type_44;
var<workgroup> global_10: array<u32, 384>;
var<private> global_11: u32 = 2143289344u;

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
    var local_12: bool;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: bool;
    var local_20: f32;
    var local_21: u32;
    var local_22: array<f32, 4>;
    var local_23: array<f32, 3>;
    var local_24: f32;
    var local_25: array<f32, 4>;
    var local_26: f32;
    var local_27: f32;
    var local_28: array<f32, 3>;
    var local_29: array<f32, 2>;
    var local_30: u32;
    var local_31: f32;
    var local_32: bool;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: f32;
    var local_38: u32;
    var local_39: f32;
    var local_40: u32;
    var local_41: f32;
    var local_42: f32;
    var local_43: f32;
    var local_44: f32;
    var local_45: array<f32, 3>;
    var local_46: f32;
    var local_47: u32;
    var local_48: bool;
    var local_49: type_23;
    var local_50: array<f32, 3>;
    var local_51: f32;
    var local_52: u32;
    var local_53: f32;
    var local_54: f32;
    var local_55: f32;
    var local_56: u32;
    var local_57: bool;
    var local_58: f32;
    var local_59: f32;
    var local_60: f32;
    var local_61: f32;
    var local_62: f32;
    var local_63: array<f32, 3>;
    var local_64: f32;
    var local_65: f32;
    var local_66: f32;
    var local_67: bool;
    var local_68: bool;
    var local_69: f32;
    var local_70: bool;
    var local_71: array<f32, 3>;
    var local_72: array<f32, 3>;
    var local_73: f32;
    var local_74: f32;
    var local_75: f32;
    var local_76: f32;
    var local_77: f32;
    var local_78: f32;
    var local_79: u32;
    var local_80: f32;
    var local_81: bool;
    var local_82: f32;
    var local_83: f32;
    var local_84: type_30;
    var local_85: u32;
    var local_86: f32;
    var local_87: f32;
    var local_88: u32;
    var local_89: bool;
    var local_90: u32;
    var local_91: u32;
    var local_92: u32;
    var local_93: u32;
    var local_94: array<f32, 3>;
    var local_95: f32;
    var local_96: bool;
    var local_97: f32;
    var local_98: u32;
    var local_99: u32;
    var local_100: array<f32, 3>;
    var local_101: f32;
    var local_102: bool;
    var local_103: u32;
    var local_104: u32;
    var local_105: i32;
    var local_106: i32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: f32;
    var local_112: u32;
    var local_113: f32;
    var local_114: u32;
    var local_115: f32;
    var local_116: f32;
    var local_117: f32;
    var local_118: f32;
    var local_119: array<f32, 3>;
    var local_120: f32;
    var local_121: u32;
    var local_122: bool;
    var local_123: type_23;
    var local_124: f32;
    var local_125: f32;
    var local_126: f32;
    var local_127: f32;
    var local_128: f32;
    var local_129: f32;
    var local_130: f32;
    var local_131: f32;
    var local_132: u32;
    var local_133: bool;
    var local_134: u32;
    var local_135: u32;
    var local_136: u32;
    var local_137: u32;
    var local_138: f32;
    var local_139: u32;
    var local_140: f32;
    var local_141: u32;
    var local_142: f32;
    var local_143: f32;
    var local_144: f32;
    var local_145: f32;
    var local_146: array<f32, 3>;
    var local_147: f32;
    var local_148: u32;
    var local_149: bool;
    var local_150: type_23;
    var local_151: array<f32, 3>;
    var local_152: f32;
    var local_153: u32;
    var local_154: f32;
    var local_155: f32;
    var local_156: f32;
    var local_157: f32;
    var local_158: f32;
    var local_159: f32;
    var local_160: f32;
    var local_161: f32;
    var local_162: u32;
    var local_163: array<f32, 4>;
    var local_164: array<f32, 3>;
    var local_165: f32;
    var local_166: array<f32, 4>;
    var local_167: f32;
    var local_168: f32;
    var local_169: array<f32, 3>;
    var local_170: array<f32, 2>;
    var local_171: u32;
    var local_172: f32;
    var local_173: bool;
    var local_174: u32;
    var local_175: u32;
    var local_176: u32;
    var local_177: u32;
    var local_178: f32;
    var local_179: u32;
    var local_180: f32;
    var local_181: u32;
    var local_182: f32;
    var local_183: f32;
    var local_184: f32;
    var local_185: f32;
    var local_186: array<f32, 3>;
    var local_187: f32;
    var local_188: u32;
    var local_189: bool;
    var local_190: type_23;
    var local_191: array<f32, 3>;
    var local_192: f32;
    var local_193: u32;
    var local_194: f32;
    var local_195: f32;
    var local_196: f32;
    var local_197: u32;
    var local_198: bool;
    var local_199: f32;
    var local_200: f32;
    var local_201: f32;
    var local_202: f32;
    var local_203: f32;
    var local_204: array<f32, 3>;
    var local_205: f32;
    var local_206: f32;
    var local_207: f32;
    var local_208: bool;
    var local_209: bool;
    var local_210: f32;
    var local_211: bool;
    var local_212: array<f32, 3>;
    var local_213: array<f32, 3>;
    var local_214: f32;
    var local_215: f32;
    var local_216: f32;
    var local_217: f32;
    var local_218: f32;
    var local_219: f32;
    var local_220: u32;
    var local_221: f32;
    var local_222: bool;
    var local_223: f32;
    var local_224: f32;
    var local_225: type_30;
    var local_226: f32;
    var local_227: f32;
    var local_228: f32;
    var local_229: f32;
    var local_230: u32;
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
    var local_244: u32;
    var local_245: bool;
    var local_246: u32;
    var local_247: u32;
    var local_248: u32;
    var local_249: u32;
    var local_250: u32;
    var local_251: u32;
    var local_252: u32;
    var local_253: bool;
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
    var local_266: array<f32, 3>;
    var local_267: f32;
    var local_268: bool;
    var local_269: f32;
    var local_270: u32;
    var local_271: u32;
    var local_272: array<f32, 3>;
    var local_273: f32;
    var local_274: bool;
    var local_275: u32;
    var local_276: u32;
    var local_277: i32;
    var local_278: i32;
    var local_279: u32;
    var local_280: u32;
    var local_281: u32;
    var local_282: u32;
    var local_283: f32;
    var local_284: u32;
    var local_285: f32;
    var local_286: u32;
    var local_287: f32;
    var local_288: f32;
    var local_289: f32;
    var local_290: f32;
    var local_291: array<f32, 3>;
    var local_292: f32;
    var local_293: u32;
    var local_294: bool;
    var local_295: type_23;
    var local_296: f32;
    var local_297: f32;
    var local_298: f32;
    var local_299: f32;
    var local_300: f32;
    var local_301: f32;
    var local_302: f32;
    var local_303: f32;
    var local_304: u32;
    var local_305: bool;
    var local_306: u32;
    var local_307: u32;
    var local_308: u32;
    var local_309: u32;
    var local_310: f32;
    var local_311: u32;
    var local_312: f32;
    var local_313: u32;
    var local_314: f32;
    var local_315: f32;
    var local_316: f32;
    var local_317: f32;
    var local_318: array<f32, 3>;
    var local_319: f32;
    var local_320: u32;
    var local_321: bool;
    var local_322: type_23;
    var local_323: array<f32, 3>;
    var local_324: f32;
    var local_325: f32;
    var local_326: u32;
    var local_327: f32;
    var local_328: f32;
    var local_329: f32;
    var local_330: f32;
    var local_331: f32;
    var local_332: f32;
    var local_333: u32;
    var local_334: array<f32, 4>;
    var local_335: array<f32, 3>;
    var local_336: f32;
    var local_337: array<f32, 4>;
    var local_338: f32;
    var local_339: f32;
    var local_340: array<f32, 3>;
    var local_341: array<f32, 2>;
    var local_342: u32;
    var local_343: f32;
    var local_344: bool;
    var local_345: u32;
    var local_346: u32;
    var local_347: u32;
    var local_348: u32;
    var local_349: f32;
    var local_350: u32;
    var local_351: f32;
    var local_352: u32;
    var local_353: f32;
    var local_354: f32;
    var local_355: f32;
    var local_356: f32;
    var local_357: array<f32, 3>;
    var local_358: f32;
    var local_359: u32;
    var local_360: bool;
    var local_361: type_23;
    var local_362: array<f32, 3>;
    var local_363: f32;
    var local_364: u32;
    var local_365: f32;
    var local_366: f32;
    var local_367: f32;
    var local_368: u32;
    var local_369: bool;
    var local_370: f32;
    var local_371: f32;
    var local_372: f32;
    var local_373: f32;
    var local_374: f32;
    var local_375: array<f32, 3>;
    var local_376: f32;
    var local_377: f32;
    var local_378: f32;
    var local_379: bool;
    var local_380: bool;
    var local_381: f32;
    var local_382: bool;
    var local_383: array<f32, 3>;
    var local_384: array<f32, 3>;
    var local_385: f32;
    var local_386: f32;
    var local_387: f32;
    var local_388: f32;
    var local_389: f32;
    var local_390: f32;
    var local_391: u32;
    var local_392: f32;
    var local_393: bool;
    var local_394: f32;
    var local_395: f32;
    var local_396: type_30;
    var local_397: u32;
    var local_398: u32;
    var local_399: bool;
    var local_400: u32;
    var local_401: u32;
    var local_402: f32;
    var local_403: f32;
    var local_404: f32;
    var local_405: f32;
    var local_406: f32;
    var local_407: f32;
    var local_408: u32;
    var local_409: u32;
    var local_410: u32;
    var local_411: u32;
    var local_412: u32;
    var local_413: u32;
    var local_414: u32;
    var local_415: u32;
    var local_416: u32;
    var local_417: u32;
    var local_418: u32;
    var local_419: u32;
    var local_420: u32;
    var local_421: u32;
    var local_422: u32;
    var local_423: type_31;
    var local_424: array<f32, 4>;
    var local_425: u32;
    var local_426: bool;
    var local_427: u32;
    var local_428: u32;
    var local_429: u32;
    var local_430: u32;
    var local_431: bool;
    var local_432: u32;
    var local_433: u32;
    var local_434: bool;
    var local_435: u32;
    var local_436: u32;
    var local_437: bool;
    var local_438: u32;
    var local_439: f32;
    var local_440: f32;
    var local_441: f32;
    var local_442: f32;
    var local_443: f32;
    var local_444: f32;
    var local_445: array<f32, 3>;
    var local_446: f32;
    var local_447: u32;
    var local_448: bool;
    var local_449: type_23;
    var local_450: f32;
    var local_451: u32;
    var local_452: bool;
    var local_453: f32;
    var local_454: f32;
    var local_455: f32;
    var local_456: f32;
    var local_457: f32;
    var local_458: array<u32, 3>;
    var local_459: u32;
    var local_460: u32;
    var local_461: u32;
    var local_462: u32;
    var local_463: u32;
    var local_464: u32;
    var local_465: u32;
    var local_466: u32;
    var local_467: u32;
    var local_468: u32;
    var local_469: u32;
    var local_470: u32;
    var local_471: u32;
    var local_472: f32;
    var local_473: f32;
    var local_474: f32;
    var local_475: f32;
    var local_476: f32;
    var local_477: bool;
    var local_478: f32;
    var local_479: f32;
    var local_480: f32;
    var local_481: f32;
    var local_482: f32;
    var local_483: f32;
    var local_484: f32;
    var local_485: f32;
    var local_486: f32;
    var local_487: bool;
    var local_488: array<f32, 4>;
    var local_489: array<f32, 4>;
    var local_490: f32;
    var local_491: f32;
    var local_492: f32;
    var local_493: f32;
    var local_494: f32;
    var local_495: f32;
    var local_496: f32;
    var local_497: f32;
    var local_498: f32;
    var local_499: f32;
    var local_500: f32;
    var local_501: bool;
    var local_502: f32;
    var local_503: f32;
    var local_504: u32;
    var local_505: u32;
    var local_506: u32;
    var local_507: f32;
    var local_508: f32;
    var local_509: f32;
    var local_510: f32;
    var local_511: f32;
    var local_512: u32;
    var local_513: f32;
    var local_514: array<f32, 3>;
    var local_515: array<f32, 4>;
    var local_516: array<f32, 4>;
    var local_517: array<f32, 3>;
    var local_518: array<f32, 4>;
    var local_519: array<f32, 4>;
    var local_520: array<f32, 3>;
    var local_521: array<f32, 4>;
    var local_522: array<f32, 4>;
    var local_523: array<f32, 3>;
    var local_524: array<f32, 4>;
    var local_525: array<f32, 3>;
    var local_526: array<f32, 3>;
    var local_527: array<f32, 3>;
    var local_528: array<f32, 9>;
    var local_529: array<f32, 3>;
    var local_530: array<f32, 3>;
    var local_531: array<f32, 3>;
    var local_532: array<f32, 4>;
    var local_533: array<f32, 3>;
    var local_534: array<f32, 3>;
    var local_535: array<f32, 3>;
    var local_536: array<f32, 4>;
    var local_537: array<f32, 9>;
    var local_538: array<f32, 3>;
    var local_539: array<f32, 3>;
    var local_540: array<f32, 3>;
    var local_541: array<f32, 4>;
    var phi_207_: u32;
    var phi_225_: u32;
    var phi_5744_: bool;
    var phi_244_: u32;
    var phi_247_: array<f32, 4>;
    var phi_249_: array<f32, 3>;
    var phi_251_: f32;
    var phi_253_: array<f32, 4>;
    var phi_255_: f32;
    var phi_257_: f32;
    var phi_259_: array<f32, 3>;
    var phi_261_: array<f32, 2>;
    var phi_263_: u32;
    var phi_265_: f32;
    var phi_333_: bool;
    var phi_347_: bool;
    var phi_352_: f32;
    var phi_362_: bool;
    var phi_376_: bool;
    var phi_381_: f32;
    var phi_391_: bool;
    var phi_405_: bool;
    var phi_410_: f32;
    var phi_444_: bool;
    var phi_450_: type_23;
    var phi_452_: type_23;
    var phi_453_: bool;
    var phi_454_: type_23;
    var phi_455_: bool;
    var phi_456_: type_23;
    var phi_457_: bool;
    var phi_462_: type_23;
    var phi_499_: bool;
    var phi_527_: f32;
    var phi_528_: f32;
    var phi_530_: f32;
    var phi_564_: u32;
    var phi_565_: u32;
    var phi_5713_: bool;
    var phi_5760_: bool;
    var phi_636_: type_25;
    var phi_5754_: bool;
    var phi_756_: array<f32, 4>;
    var phi_757_: array<f32, 3>;
    var phi_758_: f32;
    var phi_759_: array<f32, 4>;
    var phi_760_: f32;
    var phi_761_: f32;
    var phi_762_: array<f32, 3>;
    var phi_763_: array<f32, 2>;
    var phi_764_: u32;
    var phi_765_: f32;
    var phi_5753_: bool;
    var phi_766_: array<f32, 4>;
    var phi_767_: array<f32, 3>;
    var phi_768_: f32;
    var phi_769_: array<f32, 4>;
    var phi_770_: f32;
    var phi_771_: f32;
    var phi_772_: array<f32, 3>;
    var phi_773_: array<f32, 2>;
    var phi_774_: u32;
    var phi_775_: f32;
    var phi_5752_: bool;
    var phi_776_: array<f32, 4>;
    var phi_777_: array<f32, 3>;
    var phi_778_: f32;
    var phi_779_: array<f32, 4>;
    var phi_780_: f32;
    var phi_781_: f32;
    var phi_782_: array<f32, 3>;
    var phi_783_: array<f32, 2>;
    var phi_784_: u32;
    var phi_785_: f32;
    var phi_5751_: bool;
    var phi_245_: u32;
    var phi_248_: array<f32, 4>;
    var phi_250_: array<f32, 3>;
    var phi_252_: f32;
    var phi_254_: array<f32, 4>;
    var phi_256_: f32;
    var phi_258_: f32;
    var phi_260_: array<f32, 3>;
    var phi_262_: array<f32, 2>;
    var phi_264_: u32;
    var phi_266_: f32;
    var phi_5750_: bool;
    var phi_816_: array<f32, 3>;
    var phi_817_: f32;
    var phi_819_: array<f32, 3>;
    var phi_820_: f32;
    var phi_821_: bool;
    var phi_825_: array<f32, 3>;
    var phi_841_: array<f32, 3>;
    var phi_842_: f32;
    var phi_848_: f32;
    var phi_867_: u32;
    var phi_870_: f32;
    var phi_914_: f32;
    var phi_868_: u32;
    var phi_871_: f32;
    var phi_5761_: bool;
    var phi_5774_: bool;
    var phi_920_: f32;
    var phi_921_: f32;
    var phi_922_: array<f32, 2>;
    var phi_5773_: bool;
    var phi_924_: type_30;
    var phi_947_: u32;
    var phi_948_: u32;
    var phi_5770_: bool;
    var phi_5814_: bool;
    var phi_992_: u32;
    var phi_995_: u32;
    var phi_997_: array<f32, 3>;
    var phi_999_: f32;
    var phi_1014_: u32;
    var phi_1017_: u32;
    var phi_1019_: array<f32, 3>;
    var phi_1021_: f32;
    var phi_1049_: i32;
    var phi_1050_: i32;
    var phi_1051_: i32;
    var phi_1052_: i32;
    var phi_1053_: bool;
    var phi_1076_: i32;
    var phi_1077_: i32;
    var phi_1078_: bool;
    var phi_1079_: i32;
    var phi_1080_: i32;
    var phi_1081_: bool;
    var phi_1151_: bool;
    var phi_1165_: bool;
    var phi_1170_: f32;
    var phi_1180_: bool;
    var phi_1194_: bool;
    var phi_1199_: f32;
    var phi_1209_: bool;
    var phi_1223_: bool;
    var phi_1228_: f32;
    var phi_1262_: bool;
    var phi_1268_: type_23;
    var phi_1270_: type_23;
    var phi_1271_: bool;
    var phi_1272_: type_23;
    var phi_1273_: bool;
    var phi_1274_: type_23;
    var phi_1275_: bool;
    var phi_1280_: type_23;
    var phi_1320_: u32;
    var phi_1321_: array<f32, 3>;
    var phi_1322_: u32;
    var phi_1323_: array<f32, 3>;
    var phi_1324_: f32;
    var phi_1325_: u32;
    var phi_1326_: array<f32, 3>;
    var phi_1327_: f32;
    var phi_1328_: u32;
    var phi_1329_: array<f32, 3>;
    var phi_1330_: f32;
    var phi_1331_: u32;
    var phi_1332_: array<f32, 3>;
    var phi_1333_: f32;
    var phi_1334_: u32;
    var phi_1335_: array<f32, 3>;
    var phi_1336_: f32;
    var phi_1337_: u32;
    var phi_1338_: array<f32, 3>;
    var phi_1339_: f32;
    var phi_1340_: u32;
    var phi_1341_: array<f32, 3>;
    var phi_1342_: f32;
    var phi_1015_: u32;
    var phi_1018_: u32;
    var phi_1020_: array<f32, 3>;
    var phi_1022_: f32;
    var phi_5775_: bool;
    var phi_5821_: bool;
    var phi_993_: u32;
    var phi_996_: u32;
    var phi_998_: array<f32, 3>;
    var phi_1000_: f32;
    var phi_5820_: bool;
    var phi_1370_: u32;
    var phi_1439_: bool;
    var phi_1453_: bool;
    var phi_1458_: f32;
    var phi_1468_: bool;
    var phi_1482_: bool;
    var phi_1487_: f32;
    var phi_1497_: bool;
    var phi_1511_: bool;
    var phi_1516_: f32;
    var phi_1550_: bool;
    var phi_1556_: type_23;
    var phi_1558_: type_23;
    var phi_1559_: bool;
    var phi_1560_: type_23;
    var phi_1561_: bool;
    var phi_1562_: type_23;
    var phi_1563_: bool;
    var phi_1568_: type_23;
    var phi_1608_: bool;
    var phi_1636_: f32;
    var phi_1637_: f32;
    var phi_1639_: f32;
    var phi_1656_: f32;
    var phi_1723_: f32;
    var phi_1371_: u32;
    var phi_5822_: bool;
    var phi_6047_: bool;
    var phi_5965_: f32;
    var phi_5917_: f32;
    var phi_5869_: f32;
    var phi_1775_: bool;
    var phi_1776_: bool;
    var phi_1777_: bool;
    var phi_1778_: bool;
    var phi_1779_: bool;
    var phi_6044_: bool;
    var phi_1791_: u32;
    var phi_1794_: array<f32, 4>;
    var phi_1796_: array<f32, 3>;
    var phi_1798_: f32;
    var phi_1800_: array<f32, 4>;
    var phi_1802_: f32;
    var phi_1804_: f32;
    var phi_1806_: array<f32, 3>;
    var phi_1808_: array<f32, 2>;
    var phi_1810_: u32;
    var phi_1812_: f32;
    var phi_1880_: bool;
    var phi_1894_: bool;
    var phi_1899_: f32;
    var phi_1909_: bool;
    var phi_1923_: bool;
    var phi_1928_: f32;
    var phi_1938_: bool;
    var phi_1952_: bool;
    var phi_1957_: f32;
    var phi_1991_: bool;
    var phi_1997_: type_23;
    var phi_1999_: type_23;
    var phi_2000_: bool;
    var phi_2001_: type_23;
    var phi_2002_: bool;
    var phi_2003_: type_23;
    var phi_2004_: bool;
    var phi_2009_: type_23;
    var phi_2046_: bool;
    var phi_2074_: f32;
    var phi_2075_: f32;
    var phi_2077_: f32;
    var phi_2123_: u32;
    var phi_2124_: u32;
    var phi_6013_: bool;
    var phi_6063_: bool;
    var phi_2195_: type_25;
    var phi_6057_: bool;
    var phi_2315_: array<f32, 4>;
    var phi_2316_: array<f32, 3>;
    var phi_2317_: f32;
    var phi_2318_: array<f32, 4>;
    var phi_2319_: f32;
    var phi_2320_: f32;
    var phi_2321_: array<f32, 3>;
    var phi_2322_: array<f32, 2>;
    var phi_2323_: u32;
    var phi_2324_: f32;
    var phi_6056_: bool;
    var phi_2325_: array<f32, 4>;
    var phi_2326_: array<f32, 3>;
    var phi_2327_: f32;
    var phi_2328_: array<f32, 4>;
    var phi_2329_: f32;
    var phi_2330_: f32;
    var phi_2331_: array<f32, 3>;
    var phi_2332_: array<f32, 2>;
    var phi_2333_: u32;
    var phi_2334_: f32;
    var phi_6055_: bool;
    var phi_2335_: array<f32, 4>;
    var phi_2336_: array<f32, 3>;
    var phi_2337_: f32;
    var phi_2338_: array<f32, 4>;
    var phi_2339_: f32;
    var phi_2340_: f32;
    var phi_2341_: array<f32, 3>;
    var phi_2342_: array<f32, 2>;
    var phi_2343_: u32;
    var phi_2344_: f32;
    var phi_6054_: bool;
    var phi_1792_: u32;
    var phi_1795_: array<f32, 4>;
    var phi_1797_: array<f32, 3>;
    var phi_1799_: f32;
    var phi_1801_: array<f32, 4>;
    var phi_1803_: f32;
    var phi_1805_: f32;
    var phi_1807_: array<f32, 3>;
    var phi_1809_: array<f32, 2>;
    var phi_1811_: u32;
    var phi_1813_: f32;
    var phi_6053_: bool;
    var phi_2375_: array<f32, 3>;
    var phi_2376_: f32;
    var phi_2378_: array<f32, 3>;
    var phi_2379_: f32;
    var phi_2380_: bool;
    var phi_2384_: array<f32, 3>;
    var phi_2400_: array<f32, 3>;
    var phi_2401_: f32;
    var phi_2407_: f32;
    var phi_2426_: u32;
    var phi_2429_: f32;
    var phi_2473_: f32;
    var phi_2427_: u32;
    var phi_2430_: f32;
    var phi_6064_: bool;
    var phi_6087_: bool;
    var phi_2479_: f32;
    var phi_2480_: f32;
    var phi_2481_: array<f32, 2>;
    var phi_6086_: bool;
    var phi_2483_: type_30;
    var phi_2499_: f32;
    var phi_2505_: f32;
    var phi_6082_: bool;
    var phi_2508_: f32;
    var phi_6081_: bool;
    var phi_2510_: f32;
    var phi_2511_: f32;
    var phi_2512_: u32;
    var phi_6080_: bool;
    var phi_2513_: f32;
    var phi_2514_: f32;
    var phi_2515_: u32;
    var phi_6079_: bool;
    var phi_2516_: f32;
    var phi_2517_: f32;
    var phi_2518_: u32;
    var phi_2680_: u32;
    var phi_2683_: u32;
    var phi_2719_: u32;
    var phi_2681_: u32;
    var phi_2684_: u32;
    var phi_6073_: bool;
    var phi_2878_: u32;
    var phi_2881_: u32;
    var phi_2921_: u32;
    var phi_2879_: u32;
    var phi_2882_: u32;
    var phi_6107_: bool;
    var phi_3080_: u32;
    var phi_3083_: u32;
    var phi_3123_: u32;
    var phi_3081_: u32;
    var phi_3084_: u32;
    var phi_6134_: bool;
    var phi_3156_: u32;
    var phi_3172_: u32;
    var phi_3198_: u32;
    var phi_6200_: bool;
    var phi_3214_: u32;
    var phi_3217_: u32;
    var phi_3219_: array<f32, 3>;
    var phi_3221_: f32;
    var phi_3236_: u32;
    var phi_3239_: u32;
    var phi_3241_: array<f32, 3>;
    var phi_3243_: f32;
    var phi_3271_: i32;
    var phi_3272_: i32;
    var phi_3273_: i32;
    var phi_3274_: i32;
    var phi_3275_: bool;
    var phi_3298_: i32;
    var phi_3299_: i32;
    var phi_3300_: bool;
    var phi_3301_: i32;
    var phi_3302_: i32;
    var phi_3303_: bool;
    var phi_3373_: bool;
    var phi_3387_: bool;
    var phi_3392_: f32;
    var phi_3402_: bool;
    var phi_3416_: bool;
    var phi_3421_: f32;
    var phi_3431_: bool;
    var phi_3445_: bool;
    var phi_3450_: f32;
    var phi_3484_: bool;
    var phi_3490_: type_23;
    var phi_3492_: type_23;
    var phi_3493_: bool;
    var phi_3494_: type_23;
    var phi_3495_: bool;
    var phi_3496_: type_23;
    var phi_3497_: bool;
    var phi_3502_: type_23;
    var phi_3542_: u32;
    var phi_3543_: array<f32, 3>;
    var phi_3544_: u32;
    var phi_3545_: array<f32, 3>;
    var phi_3546_: f32;
    var phi_3547_: u32;
    var phi_3548_: array<f32, 3>;
    var phi_3549_: f32;
    var phi_3550_: u32;
    var phi_3551_: array<f32, 3>;
    var phi_3552_: f32;
    var phi_3553_: u32;
    var phi_3554_: array<f32, 3>;
    var phi_3555_: f32;
    var phi_3556_: u32;
    var phi_3557_: array<f32, 3>;
    var phi_3558_: f32;
    var phi_3559_: u32;
    var phi_3560_: array<f32, 3>;
    var phi_3561_: f32;
    var phi_3562_: u32;
    var phi_3563_: array<f32, 3>;
    var phi_3564_: f32;
    var phi_3237_: u32;
    var phi_3240_: u32;
    var phi_3242_: array<f32, 3>;
    var phi_3244_: f32;
    var phi_6161_: bool;
    var phi_6209_: bool;
    var phi_3215_: u32;
    var phi_3218_: u32;
    var phi_3220_: array<f32, 3>;
    var phi_3222_: f32;
    var phi_6208_: bool;
    var phi_3592_: u32;
    var phi_3661_: bool;
    var phi_3675_: bool;
    var phi_3680_: f32;
    var phi_3690_: bool;
    var phi_3704_: bool;
    var phi_3709_: f32;
    var phi_3719_: bool;
    var phi_3733_: bool;
    var phi_3738_: f32;
    var phi_3772_: bool;
    var phi_3778_: type_23;
    var phi_3780_: type_23;
    var phi_3781_: bool;
    var phi_3782_: type_23;
    var phi_3783_: bool;
    var phi_3784_: type_23;
    var phi_3785_: bool;
    var phi_3790_: type_23;
    var phi_3830_: bool;
    var phi_3858_: f32;
    var phi_3859_: f32;
    var phi_3861_: f32;
    var phi_3878_: f32;
    var phi_3945_: f32;
    var phi_3593_: u32;
    var phi_6210_: bool;
    var phi_6433_: bool;
    var phi_6353_: f32;
    var phi_6305_: f32;
    var phi_6257_: f32;
    var phi_6432_: bool;
    var phi_3984_: u32;
    var phi_3987_: array<f32, 4>;
    var phi_3989_: array<f32, 3>;
    var phi_3991_: f32;
    var phi_3993_: array<f32, 4>;
    var phi_3995_: f32;
    var phi_3997_: f32;
    var phi_3999_: array<f32, 3>;
    var phi_4001_: array<f32, 2>;
    var phi_4003_: u32;
    var phi_4005_: f32;
    var phi_4073_: bool;
    var phi_4087_: bool;
    var phi_4092_: f32;
    var phi_4102_: bool;
    var phi_4116_: bool;
    var phi_4121_: f32;
    var phi_4131_: bool;
    var phi_4145_: bool;
    var phi_4150_: f32;
    var phi_4184_: bool;
    var phi_4190_: type_23;
    var phi_4192_: type_23;
    var phi_4193_: bool;
    var phi_4194_: type_23;
    var phi_4195_: bool;
    var phi_4196_: type_23;
    var phi_4197_: bool;
    var phi_4202_: type_23;
    var phi_4239_: bool;
    var phi_4267_: f32;
    var phi_4268_: f32;
    var phi_4270_: f32;
    var phi_4316_: u32;
    var phi_4317_: u32;
    var phi_6401_: bool;
    var phi_6447_: bool;
    var phi_4388_: type_25;
    var phi_6441_: bool;
    var phi_4508_: array<f32, 4>;
    var phi_4509_: array<f32, 3>;
    var phi_4510_: f32;
    var phi_4511_: array<f32, 4>;
    var phi_4512_: f32;
    var phi_4513_: f32;
    var phi_4514_: array<f32, 3>;
    var phi_4515_: array<f32, 2>;
    var phi_4516_: u32;
    var phi_4517_: f32;
    var phi_6440_: bool;
    var phi_4518_: array<f32, 4>;
    var phi_4519_: array<f32, 3>;
    var phi_4520_: f32;
    var phi_4521_: array<f32, 4>;
    var phi_4522_: f32;
    var phi_4523_: f32;
    var phi_4524_: array<f32, 3>;
    var phi_4525_: array<f32, 2>;
    var phi_4526_: u32;
    var phi_4527_: f32;
    var phi_6439_: bool;
    var phi_4528_: array<f32, 4>;
    var phi_4529_: array<f32, 3>;
    var phi_4530_: f32;
    var phi_4531_: array<f32, 4>;
    var phi_4532_: f32;
    var phi_4533_: f32;
    var phi_4534_: array<f32, 3>;
    var phi_4535_: array<f32, 2>;
    var phi_4536_: u32;
    var phi_4537_: f32;
    var phi_6438_: bool;
    var phi_3985_: u32;
    var phi_3988_: array<f32, 4>;
    var phi_3990_: array<f32, 3>;
    var phi_3992_: f32;
    var phi_3994_: array<f32, 4>;
    var phi_3996_: f32;
    var phi_3998_: f32;
    var phi_4000_: array<f32, 3>;
    var phi_4002_: array<f32, 2>;
    var phi_4004_: u32;
    var phi_4006_: f32;
    var phi_6437_: bool;
    var phi_4568_: array<f32, 3>;
    var phi_4569_: f32;
    var phi_4571_: array<f32, 3>;
    var phi_4572_: f32;
    var phi_4573_: bool;
    var phi_4577_: array<f32, 3>;
    var phi_4593_: array<f32, 3>;
    var phi_4594_: f32;
    var phi_4600_: f32;
    var phi_4619_: u32;
    var phi_4622_: f32;
    var phi_4666_: f32;
    var phi_4620_: u32;
    var phi_4623_: f32;
    var phi_6448_: bool;
    var phi_6461_: bool;
    var phi_4672_: f32;
    var phi_4673_: f32;
    var phi_4674_: array<f32, 2>;
    var phi_6460_: bool;
    var phi_4676_: type_30;
    var phi_4699_: u32;
    var phi_4700_: u32;
    var phi_6457_: bool;
    var phi_4739_: f32;
    var phi_4747_: f32;
    var phi_5540_: f32;
    var phi_5541_: f32;
    var phi_5560_: f32;
    var phi_5572_: f32;
    var phi_5573_: f32;
    var phi_5581_: f32;
    var phi_5589_: f32;
    var phi_5590_: f32;
    var phi_5602_: bool;
    var phi_5629_: f32;
    var phi_5633_: f32;
    var phi_5634_: f32;
    var phi_5639_: f32;
    var phi_5643_: f32;
    var phi_5644_: f32;
    var phi_6492_: bool;
    var phi_4824_: type_31;
    var phi_6491_: bool;
    var phi_4825_: type_31;
    var phi_6490_: bool;
    var phi_4847_: u32;
    var phi_4954_: bool;
    var phi_4968_: bool;
    var phi_4973_: f32;
    var phi_4983_: bool;
    var phi_4997_: bool;
    var phi_5002_: f32;
    var phi_5012_: bool;
    var phi_5026_: bool;
    var phi_5031_: f32;
    var phi_5065_: bool;
    var phi_5071_: type_23;
    var phi_5073_: type_23;
    var phi_5074_: bool;
    var phi_5075_: type_23;
    var phi_5076_: bool;
    var phi_5077_: type_23;
    var phi_5078_: bool;
    var phi_5083_: type_23;
    var phi_5138_: u32;
    var phi_5139_: u32;
    var phi_6462_: bool;
    var phi_6515_: bool;
    var phi_5210_: type_25;
    var phi_6514_: bool;
    var phi_5219_: array<u32, 3>;
    var phi_6513_: bool;
    var phi_5220_: array<u32, 3>;
    var phi_6512_: bool;
    var phi_6511_: bool;
    var phi_6510_: bool;
    var phi_4848_: u32;
    var phi_6509_: bool;
    var phi_5269_: u32;
    var phi_5285_: u32;
    var local_542: u32;
    var local_543: array<f32, 3>;
    var local_544: f32;
    var local_545: u32;
    var local_546: array<f32, 3>;
    var local_547: f32;
    var local_548: f32;

    let _e612 = global_11;
    let _e613 = bitcast<f32>(_e612);
    local_513 = _e613;
    switch bitcast<i32>(0u) {
        default: {
            let _e615 = global;
            local = _e615;
            let _e616 = global_1;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = arrayLength((&global_6.member));
            local_5 = arrayLength((&global_7.member));
            local_6 = arrayLength((&global_8.member));
            local_7 = arrayLength((&global_9.member));
            local_8 = _e616.x;
            local_9 = _e616.y;
            let _e635 = global_2.member.member;
            local_10 = _e635;
            let _e636 = (_e635 / 2u);
            local_11 = _e636;
            let _e638 = ((_e635 % 2u) > 0u);
            local_12 = _e638;
            if _e638 {
                let _e639 = local_11;
                phi_207_ = (_e639 + 1u);
            } else {
                phi_207_ = _e636;
            }
            let _e642 = phi_207_;
            local_13 = _e642;
            let _e645 = global_2.member.member_1;
            local_14 = _e645;
            let _e646 = (_e645 / 2u);
            local_15 = _e646;
            if ((_e645 % 2u) > 0u) {
                let _e649 = local_15;
                phi_225_ = (_e649 + 1u);
            } else {
                phi_225_ = _e646;
            }
            let _e652 = phi_225_;
            local_16 = _e652;
            let _e653 = local_8;
            let _e655 = local;
            let _e657 = ((_e653 * 8u) + (_e655 % 8u));
            local_17 = _e657;
            let _e658 = local_9;
            let _e660 = local;
            local_18 = ((_e658 * 8u) + (_e660 / 8u));
            let _e663 = local_13;
            let _e664 = (_e657 < _e663);
            local_19 = _e664;
            if _e664 {
                let _e665 = local_18;
                let _e666 = local_16;
                if (_e665 < _e666) {
                    let _e670 = global_2.member.member_3;
                    local_20 = f32(_e670);
                    local_541 = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_5744_ = false;
                    phi_244_ = 0u;
                    phi_247_ = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_249_ = array<f32, 3>(0f, 0f, 0f);
                    phi_251_ = 0f;
                    phi_253_ = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_255_ = 0f;
                    phi_257_ = 0f;
                    phi_259_ = array<f32, 3>(0f, 0f, 0f);
                    phi_261_ = array<f32, 2>(0f, 0f);
                    phi_263_ = 0u;
                    phi_265_ = 0f;
                    loop {
                        let _e673 = phi_5744_;
                        let _e675 = phi_244_;
                        let _e677 = phi_247_;
                        let _e679 = phi_249_;
                        let _e681 = phi_251_;
                        let _e683 = phi_253_;
                        let _e685 = phi_255_;
                        let _e687 = phi_257_;
                        let _e689 = phi_259_;
                        let _e691 = phi_261_;
                        let _e693 = phi_263_;
                        let _e695 = phi_265_;
                        local_21 = _e675;
                        local_22 = _e677;
                        local_23 = _e679;
                        local_24 = _e681;
                        local_25 = _e683;
                        local_26 = _e685;
                        local_27 = _e687;
                        local_28 = _e689;
                        local_29 = _e691;
                        local_30 = _e693;
                        local_31 = _e695;
                        let _e696 = local_21;
                        let _e697 = (_e696 < 4u);
                        local_32 = _e697;
                        if _e697 {
                            let _e698 = local_17;
                            let _e700 = local_21;
                            let _e702 = ((2u * _e698) + (_e700 % 2u));
                            local_33 = _e702;
                            let _e703 = local_18;
                            let _e705 = local_21;
                            local_34 = ((2u * _e703) + (_e705 / 2u));
                            let _e708 = local_10;
                            if (_e702 < _e708) {
                                let _e710 = local_34;
                                let _e711 = local_14;
                                if (_e710 < _e711) {
                                    let _e713 = local_34;
                                    let _e714 = local_10;
                                    let _e716 = local_33;
                                    let _e717 = ((_e713 * _e714) + _e716);
                                    local_35 = _e717;
                                    let _e718 = (3u * _e717);
                                    local_36 = _e718;
                                    let _e719 = local_1;
                                    if (_e718 < _e719) {
                                    } else {
                                        phi_5750_ = true;
                                        break;
                                    }
                                    let _e721 = local_36;
                                    let _e724 = global_4.member[_e721];
                                    local_37 = bitcast<f32>(_e724);
                                    let _e726 = local_36;
                                    let _e727 = (_e726 + 1u);
                                    local_38 = _e727;
                                    let _e728 = local_1;
                                    if (_e727 < _e728) {
                                    } else {
                                        phi_5750_ = true;
                                        break;
                                    }
                                    let _e730 = local_38;
                                    let _e733 = global_4.member[_e730];
                                    local_39 = bitcast<f32>(_e733);
                                    let _e735 = local_36;
                                    let _e736 = (_e735 + 2u);
                                    local_40 = _e736;
                                    let _e737 = local_1;
                                    if (_e736 < _e737) {
                                    } else {
                                        phi_5750_ = true;
                                        break;
                                    }
                                    let _e739 = local_40;
                                    let _e742 = global_4.member[_e739];
                                    local_41 = bitcast<f32>(_e742);
                                    let _e744 = local_37;
                                    if (_e744 > 1267650600000000000000000000000f) {
                                        let _e746 = local_37;
                                        phi_333_ = select(true, false, (_e746 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_333_ = true;
                                    }
                                    let _e750 = phi_333_;
                                    if _e750 {
                                        let _e751 = local_37;
                                        if (_e751 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e753 = local_37;
                                            phi_347_ = select(true, false, (_e753 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_347_ = true;
                                        }
                                        let _e757 = phi_347_;
                                        let _e758 = local_37;
                                        phi_352_ = select(0f, _e758, _e757);
                                    } else {
                                        phi_352_ = 1267650600000000000000000000000f;
                                    }
                                    let _e761 = phi_352_;
                                    local_42 = _e761;
                                    let _e762 = local_39;
                                    if (_e762 > 1267650600000000000000000000000f) {
                                        let _e764 = local_39;
                                        phi_362_ = select(true, false, (_e764 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_362_ = true;
                                    }
                                    let _e768 = phi_362_;
                                    if _e768 {
                                        let _e769 = local_39;
                                        if (_e769 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e771 = local_39;
                                            phi_376_ = select(true, false, (_e771 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_376_ = true;
                                        }
                                        let _e775 = phi_376_;
                                        let _e776 = local_39;
                                        phi_381_ = select(0f, _e776, _e775);
                                    } else {
                                        phi_381_ = 1267650600000000000000000000000f;
                                    }
                                    let _e779 = phi_381_;
                                    local_43 = _e779;
                                    let _e780 = local_41;
                                    if (_e780 > 1267650600000000000000000000000f) {
                                        let _e782 = local_41;
                                        phi_391_ = select(true, false, (_e782 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_391_ = true;
                                    }
                                    let _e786 = phi_391_;
                                    if _e786 {
                                        let _e787 = local_41;
                                        if (_e787 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e789 = local_41;
                                            phi_405_ = select(true, false, (_e789 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_405_ = true;
                                        }
                                        let _e793 = phi_405_;
                                        let _e794 = local_41;
                                        phi_410_ = select(0f, _e794, _e793);
                                    } else {
                                        phi_410_ = 1267650600000000000000000000000f;
                                    }
                                    let _e797 = phi_410_;
                                    local_44 = _e797;
                                    let _e798 = local_42;
                                    let _e799 = local_43;
                                    local_45 = array<f32, 3>(_e798, _e799, _e797);
                                    let _e801 = local_35;
                                    let _e802 = local_2;
                                    if (_e801 < _e802) {
                                    } else {
                                        phi_5750_ = true;
                                        break;
                                    }
                                    let _e804 = local_35;
                                    let _e807 = global_3.member[_e804];
                                    local_46 = bitcast<f32>(_e807);
                                    let _e809 = local_42;
                                    if ((bitcast<u32>(_e809) & 2139095040u) != 2139095040u) {
                                        let _e813 = local_43;
                                        if ((bitcast<u32>(_e813) & 2139095040u) != 2139095040u) {
                                            let _e817 = local_44;
                                            if ((bitcast<u32>(_e817) & 2139095040u) != 2139095040u) {
                                                let _e821 = local_46;
                                                let _e822 = bitcast<u32>(_e821);
                                                local_47 = _e822;
                                                if (_e822 == 0u) {
                                                    phi_444_ = false;
                                                } else {
                                                    let _e824 = local_47;
                                                    phi_444_ = (_e824 <= 2139095040u);
                                                }
                                                let _e827 = phi_444_;
                                                local_48 = _e827;
                                                if _e827 {
                                                    let _e828 = local_45;
                                                    let _e829 = local_46;
                                                    phi_450_ = type_23(1u, type_22(_e828, _e829));
                                                } else {
                                                    phi_450_ = type_23();
                                                }
                                                let _e833 = phi_450_;
                                                let _e834 = local_48;
                                                phi_452_ = _e833;
                                                phi_453_ = select(true, false, _e834);
                                            } else {
                                                phi_452_ = type_23();
                                                phi_453_ = true;
                                            }
                                            let _e837 = phi_452_;
                                            let _e839 = phi_453_;
                                            phi_454_ = _e837;
                                            phi_455_ = _e839;
                                        } else {
                                            phi_454_ = type_23();
                                            phi_455_ = true;
                                        }
                                        let _e841 = phi_454_;
                                        let _e843 = phi_455_;
                                        phi_456_ = _e841;
                                        phi_457_ = _e843;
                                    } else {
                                        phi_456_ = type_23();
                                        phi_457_ = true;
                                    }
                                    let _e845 = phi_456_;
                                    let _e847 = phi_457_;
                                    if _e847 {
                                        phi_462_ = type_23(0u, type_23().member_1);
                                    } else {
                                        phi_462_ = _e845;
                                    }
                                    let _e852 = phi_462_;
                                    local_49 = _e852;
                                    if (bitcast<i32>(_e852.member) != 0i) {
                                        let _e856 = local_49;
                                        local_50 = _e856.member_1.member;
                                        let _e859 = local_49;
                                        local_51 = _e859.member_1.member_1;
                                        let _e862 = bitcast<u32>(_e859.member_1.member_1);
                                        local_52 = _e862;
                                        if (_e862 == 2139095040u) {
                                            let _e906 = global_2.member.member_4.member_1;
                                            let _e911 = global_2.member.member_4.member;
                                            let _e916 = global_2.member.member_4.member_2;
                                            let _e922 = global_2.member.member_4.member_3;
                                            phi_530_ = (0.5f * ((((2f * _e906) * _e911) / (_e916 - _e911)) * _e922));
                                        } else {
                                            let _e864 = local_52;
                                            if (_e864 == 0u) {
                                                phi_499_ = false;
                                            } else {
                                                let _e866 = local_52;
                                                phi_499_ = (_e866 <= 2139095040u);
                                            }
                                            let _e869 = phi_499_;
                                            if _e869 {
                                                let _e873 = global_2.member.member_4.member_1;
                                                let _e878 = global_2.member.member_4.member;
                                                let _e883 = global_2.member.member_4.member_2;
                                                local_53 = _e883;
                                                let _e889 = global_2.member.member_4.member_3;
                                                let _e890 = ((((2f * _e873) * _e878) / (_e883 - _e878)) * _e889);
                                                local_54 = _e890;
                                                if (_e890 == 0f) {
                                                    phi_527_ = 0f;
                                                } else {
                                                    let _e892 = local_53;
                                                    let _e893 = local_51;
                                                    let _e896 = local_54;
                                                    phi_527_ = (_e896 * (1f - (_e892 / _e893)));
                                                }
                                                let _e899 = phi_527_;
                                                phi_528_ = _e899;
                                            } else {
                                                phi_528_ = _e613;
                                            }
                                            let _e901 = phi_528_;
                                            phi_530_ = (0.5f * _e901);
                                        }
                                        let _e926 = phi_530_;
                                        let _e927 = local_20;
                                        let _e929 = local_20;
                                        let _e930 = select(_e929, _e926, (_e926 < _e927));
                                        let _e931 = local_20;
                                        let _e932 = -(_e931);
                                        local_496 = select(_e932, _e930, (_e930 > _e932));
                                        let _e935 = local_50;
                                        let _e937 = local_50;
                                        let _e939 = local_50;
                                        local_538 = array<f32, 3>(_e935[0], _e937[1], _e939[2]);
                                        local_515 = array<f32, 4>(0f, 0f, 0f, 0f);
                                        local_514 = array<f32, 3>(0f, 0f, 0f);
                                        let _e942 = local_32;
                                        if _e942 {
                                        } else {
                                            phi_5750_ = true;
                                            break;
                                        }
                                        let _e943 = local_21;
                                        let _e945 = local_515[_e943];
                                        local_55 = _e945;
                                        if (_e945 <= 0f) {
                                            let _e1006 = local_538;
                                            phi_5760_ = _e673;
                                            phi_636_ = type_25(array<f32, 3>(_e1006[0], _e1006[1], _e1006[2]), array<f32, 3>(0f, 0f, 0f));
                                        } else {
                                            let _e947 = local_538;
                                            local_539 = _e947;
                                            local_540 = array<f32, 3>(0f, 0f, 0f);
                                            phi_564_ = 0u;
                                            loop {
                                                let _e949 = phi_564_;
                                                local_56 = _e949;
                                                let _e950 = local_56;
                                                let _e951 = (_e950 < 3u);
                                                local_57 = _e951;
                                                if _e951 {
                                                    let _e952 = local_57;
                                                    if _e952 {
                                                    } else {
                                                        phi_5713_ = true;
                                                        break;
                                                    }
                                                    let _e953 = local_56;
                                                    let _e955 = local_514[_e953];
                                                    local_58 = _e955;
                                                    let _e956 = local_57;
                                                    if _e956 {
                                                    } else {
                                                        phi_5713_ = true;
                                                        break;
                                                    }
                                                    let _e957 = local_56;
                                                    let _e959 = local_538[_e957];
                                                    let _e960 = local_58;
                                                    if (_e959 > _e960) {
                                                        let _e962 = local_57;
                                                        if _e962 {
                                                        } else {
                                                            phi_5713_ = true;
                                                            break;
                                                        }
                                                        let _e963 = local_538[_e957];
                                                        let _e964 = local_58;
                                                        local_59 = (_e963 - _e964);
                                                        let _e966 = local_57;
                                                        if _e966 {
                                                        } else {
                                                            phi_5713_ = true;
                                                            break;
                                                        }
                                                        let _e967 = local_56;
                                                        let _e969 = local_55;
                                                        let _e970 = local_59;
                                                        local_540[_e967] = (_e969 * _e970);
                                                        let _e972 = local_55;
                                                        local_60 = (1f - _e972);
                                                        let _e974 = local_57;
                                                        if _e974 {
                                                        } else {
                                                            phi_5713_ = true;
                                                            break;
                                                        }
                                                        let _e975 = local_538[_e957];
                                                        let _e976 = local_60;
                                                        local_61 = (_e976 * _e975);
                                                        let _e978 = local_55;
                                                        let _e979 = local_58;
                                                        local_62 = (_e978 * _e979);
                                                        let _e981 = local_57;
                                                        if _e981 {
                                                        } else {
                                                            phi_5713_ = true;
                                                            break;
                                                        }
                                                        let _e982 = local_56;
                                                        let _e984 = local_61;
                                                        let _e985 = local_62;
                                                        local_539[_e982] = (_e984 + _e985);
                                                    }
                                                    let _e987 = local_56;
                                                    phi_565_ = (_e987 + 1u);
                                                } else {
                                                    phi_565_ = u32();
                                                }
                                                let _e990 = phi_565_;
                                                continue;
                                                continuing {
                                                    let _e991 = local_57;
                                                    phi_564_ = _e990;
                                                    phi_5713_ = _e673;
                                                    break if !(_e991);
                                                }
                                            }
                                            let _e994 = phi_5713_;
                                            phi_5750_ = _e994;
                                            if _e994 {
                                                break;
                                            }
                                            let _e995 = local_539;
                                            let _e1000 = local_540;
                                            phi_5760_ = _e994;
                                            phi_636_ = type_25(array<f32, 3>(_e995[0], _e995[1], _e995[2]), array<f32, 3>(_e1000[0], _e1000[1], _e1000[2]));
                                        }
                                        let _e1013 = phi_5760_;
                                        let _e1015 = phi_636_;
                                        local_63 = _e1015.member;
                                        let _e1018 = local_23;
                                        let _e1022 = local_23;
                                        let _e1026 = local_23;
                                        local_64 = (((0.2126f * _e1015.member_1[0]) + (0.7152f * _e1015.member_1[1])) + (0.0722f * _e1015.member_1[2]));
                                        let _e1036 = local_32;
                                        if _e1036 {
                                        } else {
                                            phi_5750_ = true;
                                            break;
                                        }
                                        let _e1037 = local_21;
                                        let _e1039 = local_64;
                                        local_541[_e1037] = _e1039;
                                        let _e1040 = local_22;
                                        let _e1042 = local_33;
                                        let _e1043 = f32(_e1042);
                                        let _e1045 = local_64;
                                        let _e1048 = local_22;
                                        let _e1050 = local_34;
                                        let _e1051 = f32(_e1050);
                                        let _e1053 = local_64;
                                        let _e1056 = local_22;
                                        let _e1058 = local_64;
                                        let _e1059 = local_496;
                                        let _e1062 = local_22;
                                        let _e1064 = local_64;
                                        let _e1067 = local_31;
                                        let _e1068 = local_496;
                                        let _e1070 = local_29;
                                        let _e1074 = local_29;
                                        let _e1079 = local_30;
                                        let _e1081 = local_496;
                                        let _e1083 = local_496;
                                        let _e1085 = ((-1f - _e1083) * 0.5f);
                                        let _e1087 = select(0f, _e1085, (_e1085 > 0f));
                                        let _e1089 = select(1f, _e1087, (_e1087 < 1f));
                                        let _e1090 = local_28;
                                        let _e1092 = local_63;
                                        let _e1096 = local_28;
                                        let _e1098 = local_63;
                                        let _e1102 = local_28;
                                        let _e1104 = local_63;
                                        let _e1109 = local_496;
                                        let _e1111 = local_27;
                                        let _e1113 = local_26;
                                        let _e1116 = local_496;
                                        let _e1118 = local_496;
                                        let _e1120 = (select(_e1118, -(_e1081), (_e1116 < 0f)) - 1f);
                                        let _e1122 = select(0f, _e1120, (_e1120 > 0f));
                                        let _e1126 = ((1f - _e1089) * (select(1f, _e1122, (_e1122 < 1f)) + 0.001f));
                                        let _e1127 = local_25;
                                        let _e1131 = local_25;
                                        let _e1135 = local_25;
                                        let _e1139 = local_25;
                                        let _e1141 = local_496;
                                        let _e1145 = local_24;
                                        phi_5754_ = _e1013;
                                        phi_756_ = array<f32, 4>((_e1040[0] + (_e1045 * (_e1043 + 0.5f))), (_e1048[1] + (_e1053 * (_e1051 + 0.5f))), (_e1056[2] + (_e1058 * _e1059)), (_e1062[3] + _e1064));
                                        phi_757_ = array<f32, 3>((_e1018[0] + _e1015.member_1[0]), (_e1022[1] + _e1015.member_1[1]), (_e1026[2] + _e1015.member_1[2]));
                                        phi_758_ = (_e1145 + _e1126);
                                        phi_759_ = array<f32, 4>((_e1127[0] + (_e1126 * _e1092[0])), (_e1131[1] + (_e1126 * _e1098[1])), (_e1135[2] + (_e1126 * _e1104[2])), (_e1139[3] + (_e1126 * _e1141)));
                                        phi_760_ = (_e1113 + _e1089);
                                        phi_761_ = (_e1111 + (_e1089 * _e1109));
                                        phi_762_ = array<f32, 3>((_e1090[0] + (_e1089 * _e1092[0])), (_e1096[1] + (_e1089 * _e1098[1])), (_e1102[2] + (_e1089 * _e1104[2])));
                                        phi_763_ = array<f32, 2>(((_e1070[0] + _e1043) + 0.5f), ((_e1074[1] + _e1051) + 0.5f));
                                        phi_764_ = (_e1079 + 1u);
                                        phi_765_ = (_e1067 + _e1068);
                                    } else {
                                        phi_5754_ = _e673;
                                        phi_756_ = _e677;
                                        phi_757_ = _e679;
                                        phi_758_ = _e681;
                                        phi_759_ = _e683;
                                        phi_760_ = _e685;
                                        phi_761_ = _e687;
                                        phi_762_ = _e689;
                                        phi_763_ = _e691;
                                        phi_764_ = _e693;
                                        phi_765_ = _e695;
                                    }
                                    let _e1148 = phi_5754_;
                                    let _e1150 = phi_756_;
                                    let _e1152 = phi_757_;
                                    let _e1154 = phi_758_;
                                    let _e1156 = phi_759_;
                                    let _e1158 = phi_760_;
                                    let _e1160 = phi_761_;
                                    let _e1162 = phi_762_;
                                    let _e1164 = phi_763_;
                                    let _e1166 = phi_764_;
                                    let _e1168 = phi_765_;
                                    phi_5753_ = _e1148;
                                    phi_766_ = _e1150;
                                    phi_767_ = _e1152;
                                    phi_768_ = _e1154;
                                    phi_769_ = _e1156;
                                    phi_770_ = _e1158;
                                    phi_771_ = _e1160;
                                    phi_772_ = _e1162;
                                    phi_773_ = _e1164;
                                    phi_774_ = _e1166;
                                    phi_775_ = _e1168;
                                } else {
                                    phi_5753_ = _e673;
                                    phi_766_ = _e677;
                                    phi_767_ = _e679;
                                    phi_768_ = _e681;
                                    phi_769_ = _e683;
                                    phi_770_ = _e685;
                                    phi_771_ = _e687;
                                    phi_772_ = _e689;
                                    phi_773_ = _e691;
                                    phi_774_ = _e693;
                                    phi_775_ = _e695;
                                }
                                let _e1170 = phi_5753_;
                                let _e1172 = phi_766_;
                                let _e1174 = phi_767_;
                                let _e1176 = phi_768_;
                                let _e1178 = phi_769_;
                                let _e1180 = phi_770_;
                                let _e1182 = phi_771_;
                                let _e1184 = phi_772_;
                                let _e1186 = phi_773_;
                                let _e1188 = phi_774_;
                                let _e1190 = phi_775_;
                                phi_5752_ = _e1170;
                                phi_776_ = _e1172;
                                phi_777_ = _e1174;
                                phi_778_ = _e1176;
                                phi_779_ = _e1178;
                                phi_780_ = _e1180;
                                phi_781_ = _e1182;
                                phi_782_ = _e1184;
                                phi_783_ = _e1186;
                                phi_784_ = _e1188;
                                phi_785_ = _e1190;
                            } else {
                                phi_5752_ = _e673;
                                phi_776_ = _e677;
                                phi_777_ = _e679;
                                phi_778_ = _e681;
                                phi_779_ = _e683;
                                phi_780_ = _e685;
                                phi_781_ = _e687;
                                phi_782_ = _e689;
                                phi_783_ = _e691;
                                phi_784_ = _e693;
                                phi_785_ = _e695;
                            }
                            let _e1192 = phi_5752_;
                            let _e1194 = phi_776_;
                            let _e1196 = phi_777_;
                            let _e1198 = phi_778_;
                            let _e1200 = phi_779_;
                            let _e1202 = phi_780_;
                            let _e1204 = phi_781_;
                            let _e1206 = phi_782_;
                            let _e1208 = phi_783_;
                            let _e1210 = phi_784_;
                            let _e1212 = phi_785_;
                            let _e1213 = local_21;
                            phi_5751_ = _e1192;
                            phi_245_ = (_e1213 + 1u);
                            phi_248_ = _e1194;
                            phi_250_ = _e1196;
                            phi_252_ = _e1198;
                            phi_254_ = _e1200;
                            phi_256_ = _e1202;
                            phi_258_ = _e1204;
                            phi_260_ = _e1206;
                            phi_262_ = _e1208;
                            phi_264_ = _e1210;
                            phi_266_ = _e1212;
                        } else {
                            phi_5751_ = _e673;
                            phi_245_ = u32();
                            phi_248_ = array<f32, 4>();
                            phi_250_ = array<f32, 3>();
                            phi_252_ = f32();
                            phi_254_ = array<f32, 4>();
                            phi_256_ = f32();
                            phi_258_ = f32();
                            phi_260_ = array<f32, 3>();
                            phi_262_ = array<f32, 2>();
                            phi_264_ = u32();
                            phi_266_ = f32();
                        }
                        let _e1216 = phi_5751_;
                        let _e1218 = phi_245_;
                        let _e1220 = phi_248_;
                        let _e1222 = phi_250_;
                        let _e1224 = phi_252_;
                        let _e1226 = phi_254_;
                        let _e1228 = phi_256_;
                        let _e1230 = phi_258_;
                        let _e1232 = phi_260_;
                        let _e1234 = phi_262_;
                        let _e1236 = phi_264_;
                        let _e1238 = phi_266_;
                        continue;
                        continuing {
                            let _e1239 = local_32;
                            phi_5744_ = _e1216;
                            phi_244_ = _e1218;
                            phi_247_ = _e1220;
                            phi_249_ = _e1222;
                            phi_251_ = _e1224;
                            phi_253_ = _e1226;
                            phi_255_ = _e1228;
                            phi_257_ = _e1230;
                            phi_259_ = _e1232;
                            phi_261_ = _e1234;
                            phi_263_ = _e1236;
                            phi_265_ = _e1238;
                            phi_5750_ = _e1216;
                            break if !(_e1239);
                        }
                    }
                    let _e1242 = phi_5750_;
                    if _e1242 {
                        break;
                    }
                    let _e1243 = local_30;
                    if (_e1243 == 0u) {
                        let _e1417 = local_513;
                        let _e1418 = local_30;
                        phi_5773_ = _e1242;
                        phi_924_ = type_30(array<f32, 2>(0f, 0f), array<f32, 3>(0f, 0f, 0f), 0f, 0f, array<f32, 3>(0f, 0f, 0f), _e1417, _e1418, array<f32, 3>(0f, 0f, 0f), 0f, 0f);
                    } else {
                        let _e1245 = local_30;
                        let _e1246 = f32(_e1245);
                        let _e1247 = (1f / _e1246);
                        local_65 = _e1247;
                        let _e1248 = local_31;
                        let _e1250 = ((0.5f * _e1248) * _e1247);
                        local_66 = _e1250;
                        let _e1251 = local_26;
                        let _e1253 = ((_e1246 - _e1251) > 0f);
                        local_67 = _e1253;
                        if _e1253 {
                            let _e1254 = local_24;
                            let _e1255 = (_e1254 > 0f);
                            local_68 = _e1255;
                            if _e1255 {
                                let _e1256 = local_24;
                                let _e1257 = (1f / _e1256);
                                let _e1258 = local_25;
                                let _e1261 = local_25;
                                let _e1264 = local_25;
                                let _e1268 = local_25;
                                phi_816_ = array<f32, 3>((_e1258[0] * _e1257), (_e1261[1] * _e1257), (_e1264[2] * _e1257));
                                phi_817_ = ((0.5f * _e1268[3]) * _e1257);
                            } else {
                                phi_816_ = array<f32, 3>();
                                phi_817_ = f32();
                            }
                            let _e1273 = phi_816_;
                            let _e1275 = phi_817_;
                            let _e1276 = local_68;
                            phi_819_ = _e1273;
                            phi_820_ = _e1275;
                            phi_821_ = select(true, false, _e1276);
                        } else {
                            phi_819_ = array<f32, 3>();
                            phi_820_ = f32();
                            phi_821_ = true;
                        }
                        let _e1279 = phi_819_;
                        let _e1281 = phi_820_;
                        let _e1283 = phi_821_;
                        local_69 = _e1281;
                        local_70 = _e1283;
                        if _e1283 {
                            phi_825_ = array<f32, 3>(0f, 0f, 0f);
                        } else {
                            phi_825_ = _e1279;
                        }
                        let _e1285 = phi_825_;
                        local_71 = _e1285;
                        let _e1286 = local_70;
                        let _e1287 = local_66;
                        let _e1288 = local_69;
                        local_497 = select(_e1288, _e1287, _e1286);
                        let _e1290 = local_26;
                        if (_e1290 > 0f) {
                            let _e1292 = local_26;
                            let _e1293 = (1f / _e1292);
                            let _e1294 = local_28;
                            let _e1297 = local_28;
                            let _e1300 = local_28;
                            let _e1304 = local_27;
                            phi_841_ = array<f32, 3>((_e1294[0] * _e1293), (_e1297[1] * _e1293), (_e1300[2] * _e1293));
                            phi_842_ = ((0.5f * _e1304) * _e1293);
                        } else {
                            phi_841_ = array<f32, 3>(0f, 0f, 0f);
                            phi_842_ = _e1250;
                        }
                        let _e1308 = phi_841_;
                        let _e1310 = phi_842_;
                        local_72 = _e1308;
                        local_73 = _e1310;
                        let _e1311 = local_67;
                        if _e1311 {
                            let _e1312 = local_26;
                            let _e1313 = local_65;
                            phi_848_ = (_e1312 * _e1313);
                        } else {
                            phi_848_ = 1f;
                        }
                        let _e1316 = phi_848_;
                        local_74 = _e1316;
                        let _e1317 = local_29;
                        let _e1319 = local_65;
                        let _e1321 = local_29;
                        let _e1323 = local_65;
                        let _e1326 = local_22;
                        local_75 = _e1326[3];
                        if (_e1326[3] > 0f) {
                            let _e1331 = local_75;
                            let _e1332 = (1f / _e1331);
                            local_76 = _e1332;
                            let _e1333 = local_22;
                            let _e1335 = (_e1333[0] * _e1332);
                            local_77 = _e1335;
                            let _e1336 = local_22;
                            let _e1338 = (_e1336[1] * _e1332);
                            local_78 = _e1338;
                            phi_867_ = 0u;
                            phi_870_ = 0f;
                            loop {
                                let _e1341 = phi_867_;
                                let _e1343 = phi_870_;
                                local_79 = _e1341;
                                local_80 = _e1343;
                                let _e1344 = local_79;
                                let _e1345 = (_e1344 < 4u);
                                local_81 = _e1345;
                                if _e1345 {
                                    let _e1346 = local_81;
                                    if _e1346 {
                                    } else {
                                        phi_5761_ = true;
                                        break;
                                    }
                                    let _e1347 = local_79;
                                    let _e1349 = local_541[_e1347];
                                    if (_e1349 > 0f) {
                                        let _e1351 = local_17;
                                        let _e1353 = local_79;
                                        let _e1358 = local_77;
                                        local_82 = ((f32(((2u * _e1351) + (_e1353 % 2u))) + 0.5f) - _e1358);
                                        let _e1360 = local_18;
                                        let _e1362 = local_79;
                                        let _e1367 = local_78;
                                        local_83 = ((f32(((2u * _e1360) + (_e1362 / 2u))) + 0.5f) - _e1367);
                                        let _e1369 = local_81;
                                        if _e1369 {
                                        } else {
                                            phi_5761_ = true;
                                            break;
                                        }
                                        let _e1370 = local_541[_e1347];
                                        let _e1371 = local_82;
                                        let _e1372 = local_82;
                                        let _e1374 = local_83;
                                        let _e1375 = local_83;
                                        let _e1380 = local_80;
                                        phi_914_ = (_e1380 + (_e1370 * sqrt(((_e1371 * _e1372) + (_e1374 * _e1375)))));
                                    } else {
                                        phi_914_ = _e1343;
                                    }
                                    let _e1383 = phi_914_;
                                    let _e1384 = local_79;
                                    phi_868_ = (_e1384 + 1u);
                                    phi_871_ = _e1383;
                                } else {
                                    phi_868_ = u32();
                                    phi_871_ = f32();
                                }
                                let _e1387 = phi_868_;
                                let _e1389 = phi_871_;
                                continue;
                                continuing {
                                    let _e1390 = local_81;
                                    phi_867_ = _e1387;
                                    phi_870_ = _e1389;
                                    phi_5761_ = _e1242;
                                    break if !(_e1390);
                                }
                            }
                            let _e1393 = phi_5761_;
                            if _e1393 {
                                break;
                            }
                            let _e1394 = local_22;
                            let _e1396 = local_76;
                            let _e1398 = local_80;
                            let _e1399 = local_76;
                            phi_5774_ = _e1393;
                            phi_920_ = (_e1394[2] * _e1396);
                            phi_921_ = (_e1398 * _e1399);
                            phi_922_ = array<f32, 2>(_e1335, _e1338);
                        } else {
                            let _e1329 = local_66;
                            phi_5774_ = _e1242;
                            phi_920_ = (2f * _e1329);
                            phi_921_ = 0f;
                            phi_922_ = array<f32, 2>((_e1317[0] * _e1319), (_e1321[1] * _e1323));
                        }
                        let _e1402 = phi_5774_;
                        let _e1404 = phi_920_;
                        let _e1406 = phi_921_;
                        let _e1408 = phi_922_;
                        let _e1409 = local_72;
                        let _e1410 = local_74;
                        let _e1411 = local_73;
                        let _e1412 = local_71;
                        let _e1413 = local_497;
                        let _e1414 = local_30;
                        let _e1415 = local_23;
                        phi_5773_ = _e1402;
                        phi_924_ = type_30(_e1408, _e1409, _e1410, _e1411, _e1412, _e1413, _e1414, _e1415, _e1404, _e1406);
                    }
                    let _e1421 = phi_5773_;
                    let _e1423 = phi_924_;
                    local_84 = _e1423;
                    let _e1424 = local_18;
                    let _e1425 = local_13;
                    let _e1427 = local_17;
                    local_85 = (9u * ((_e1424 * _e1425) + _e1427));
                    local_86 = _e1423.member_3;
                    local_87 = _e1423.member_5;
                    local_537[0u] = _e1423.member_1[0];
                    local_537[1u] = _e1423.member_1[1];
                    local_537[2u] = _e1423.member_1[2];
                    local_537[3u] = _e1423.member_2;
                    local_537[4u] = _e1423.member_4[0];
                    local_537[5u] = _e1423.member_4[1];
                    local_537[6u] = _e1423.member_4[2];
                    local_537[7u] = _e1423.member_3;
                    local_537[8u] = _e1423.member_5;
                    phi_947_ = 0u;
                    loop {
                        let _e1455 = phi_947_;
                        local_88 = _e1455;
                        let _e1456 = local_88;
                        let _e1457 = (_e1456 < 9u);
                        local_89 = _e1457;
                        if _e1457 {
                            let _e1458 = local_85;
                            let _e1459 = local_88;
                            local_90 = (_e1458 + _e1459);
                            let _e1461 = local_89;
                            if _e1461 {
                            } else {
                                phi_5770_ = true;
                                break;
                            }
                            let _e1462 = local_88;
                            let _e1464 = local_537[_e1462];
                            local_91 = bitcast<u32>(_e1464);
                            let _e1466 = local_90;
                            let _e1467 = local_3;
                            if (_e1466 < _e1467) {
                            } else {
                                phi_5770_ = true;
                                break;
                            }
                            let _e1469 = local_90;
                            let _e1472 = local_91;
                            global_5.member[_e1469] = _e1472;
                            let _e1473 = local_88;
                            phi_948_ = (_e1473 + 1u);
                        } else {
                            phi_948_ = u32();
                        }
                        let _e1476 = phi_948_;
                        continue;
                        continuing {
                            let _e1477 = local_89;
                            phi_947_ = _e1476;
                            phi_5770_ = _e1421;
                            break if !(_e1477);
                        }
                    }
                    let _e1480 = phi_5770_;
                    if _e1480 {
                        break;
                    }
                    let _e1481 = local_84;
                    if (_e1481.member_6 > 0u) {
                        let _e1484 = local_86;
                        let _e1485 = -(_e1484);
                        let _e1486 = local_87;
                        let _e1487 = -(_e1486);
                        let _e1489 = select(_e1487, _e1485, (_e1485 > _e1487));
                        phi_5814_ = _e1480;
                        phi_992_ = 0u;
                        phi_995_ = 0u;
                        phi_997_ = array<f32, 3>(0f, 0f, 0f);
                        phi_999_ = 340282350000000000000000000000000000000f;
                        loop {
                            let _e1493 = phi_5814_;
                            let _e1495 = phi_992_;
                            let _e1497 = phi_995_;
                            let _e1499 = phi_997_;
                            let _e1501 = phi_999_;
                            local_92 = _e1495;
                            local_93 = _e1497;
                            local_94 = _e1499;
                            local_95 = _e1501;
                            let _e1502 = local_92;
                            let _e1503 = (_e1502 < 2u);
                            local_96 = _e1503;
                            if _e1503 {
                                let _e1504 = local_95;
                                let _e1506 = local_95;
                                local_97 = (4f * select(0.25f, _e1506, (_e1504 > 0.25f)));
                                phi_1014_ = 0u;
                                phi_1017_ = _e1497;
                                phi_1019_ = _e1499;
                                phi_1021_ = _e1501;
                                loop {
                                    let _e1510 = phi_1014_;
                                    let _e1512 = phi_1017_;
                                    let _e1514 = phi_1019_;
                                    let _e1516 = phi_1021_;
                                    local_98 = _e1510;
                                    local_99 = _e1512;
                                    local_100 = _e1514;
                                    local_101 = _e1516;
                                    local_542 = _e1512;
                                    local_543 = _e1514;
                                    local_544 = _e1516;
                                    let _e1517 = local_98;
                                    let _e1518 = (_e1517 < 16u);
                                    local_102 = _e1518;
                                    if _e1518 {
                                        let _e1519 = local_98;
                                        let _e1520 = (_e1519 % 4u);
                                        local_103 = _e1520;
                                        let _e1521 = local_98;
                                        local_104 = (_e1521 / 4u);
                                        if (_e1520 == 1u) {
                                            phi_1051_ = i32();
                                            phi_1052_ = i32();
                                            phi_1053_ = true;
                                        } else {
                                            let _e1524 = local_103;
                                            let _e1525 = (_e1524 == 2u);
                                            if _e1525 {
                                                phi_1049_ = i32();
                                                phi_1050_ = i32();
                                            } else {
                                                let _e1526 = local_17;
                                                let _e1530 = local_103;
                                                let _e1533 = local_18;
                                                let _e1537 = local_104;
                                                phi_1049_ = (((2i * bitcast<i32>(_e1533)) - 1i) + bitcast<i32>(_e1537));
                                                phi_1050_ = (((2i * bitcast<i32>(_e1526)) - 1i) + bitcast<i32>(_e1530));
                                            }
                                            let _e1541 = phi_1049_;
                                            let _e1543 = phi_1050_;
                                            phi_1051_ = _e1541;
                                            phi_1052_ = _e1543;
                                            phi_1053_ = _e1525;
                                        }
                                        let _e1545 = phi_1051_;
                                        let _e1547 = phi_1052_;
                                        let _e1549 = phi_1053_;
                                        if _e1549 {
                                            let _e1550 = local_104;
                                            if (_e1550 == 1u) {
                                                phi_1076_ = i32();
                                                phi_1077_ = i32();
                                                phi_1078_ = false;
                                            } else {
                                                let _e1552 = local_104;
                                                let _e1554 = local_17;
                                                let _e1558 = local_103;
                                                let _e1561 = local_18;
                                                let _e1565 = local_104;
                                                phi_1076_ = (((2i * bitcast<i32>(_e1561)) - 1i) + bitcast<i32>(_e1565));
                                                phi_1077_ = (((2i * bitcast<i32>(_e1554)) - 1i) + bitcast<i32>(_e1558));
                                                phi_1078_ = select(true, false, (_e1552 == 2u));
                                            }
                                            let _e1570 = phi_1076_;
                                            let _e1572 = phi_1077_;
                                            let _e1574 = phi_1078_;
                                            phi_1079_ = _e1570;
                                            phi_1080_ = _e1572;
                                            phi_1081_ = _e1574;
                                        } else {
                                            phi_1079_ = _e1545;
                                            phi_1080_ = _e1547;
                                            phi_1081_ = true;
                                        }
                                        let _e1576 = phi_1079_;
                                        let _e1578 = phi_1080_;
                                        let _e1580 = phi_1081_;
                                        local_105 = _e1576;
                                        local_106 = _e1578;
                                        if _e1580 {
                                            let _e1581 = local_106;
                                            if (_e1581 >= 0i) {
                                                let _e1583 = local_105;
                                                if (_e1583 >= 0i) {
                                                    let _e1585 = local_106;
                                                    let _e1586 = bitcast<u32>(_e1585);
                                                    local_107 = _e1586;
                                                    let _e1587 = local_10;
                                                    if (_e1586 < _e1587) {
                                                        let _e1589 = local_105;
                                                        let _e1590 = bitcast<u32>(_e1589);
                                                        local_108 = _e1590;
                                                        let _e1591 = local_14;
                                                        if (_e1590 < _e1591) {
                                                            let _e1593 = local_108;
                                                            let _e1594 = local_10;
                                                            let _e1596 = local_107;
                                                            let _e1597 = ((_e1593 * _e1594) + _e1596);
                                                            local_109 = _e1597;
                                                            let _e1598 = (3u * _e1597);
                                                            local_110 = _e1598;
                                                            let _e1599 = local_1;
                                                            if (_e1598 < _e1599) {
                                                            } else {
                                                                phi_5775_ = true;
                                                                break;
                                                            }
                                                            let _e1601 = local_110;
                                                            let _e1604 = global_4.member[_e1601];
                                                            local_111 = bitcast<f32>(_e1604);
                                                            let _e1606 = local_110;
                                                            let _e1607 = (_e1606 + 1u);
                                                            local_112 = _e1607;
                                                            let _e1608 = local_1;
                                                            if (_e1607 < _e1608) {
                                                            } else {
                                                                phi_5775_ = true;
                                                                break;
                                                            }
                                                            let _e1610 = local_112;
                                                            let _e1613 = global_4.member[_e1610];
                                                            local_113 = bitcast<f32>(_e1613);
                                                            let _e1615 = local_110;
                                                            let _e1616 = (_e1615 + 2u);
                                                            local_114 = _e1616;
                                                            let _e1617 = local_1;
                                                            if (_e1616 < _e1617) {
                                                            } else {
                                                                phi_5775_ = true;
                                                                break;
                                                            }
                                                            let _e1619 = local_114;
                                                            let _e1622 = global_4.member[_e1619];
                                                            local_115 = bitcast<f32>(_e1622);
                                                            let _e1624 = local_111;
                                                            if (_e1624 > 1267650600000000000000000000000f) {
                                                                let _e1626 = local_111;
                                                                phi_1151_ = select(true, false, (_e1626 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_1151_ = true;
                                                            }
                                                            let _e1630 = phi_1151_;
                                                            if _e1630 {
                                                                let _e1631 = local_111;
                                                                if (_e1631 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e1633 = local_111;
                                                                    phi_1165_ = select(true, false, (_e1633 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_1165_ = true;
                                                                }
                                                                let _e1637 = phi_1165_;
                                                                let _e1638 = local_111;
                                                                phi_1170_ = select(0f, _e1638, _e1637);
                                                            } else {
                                                                phi_1170_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e1641 = phi_1170_;
                                                            local_116 = _e1641;
                                                            let _e1642 = local_113;
                                                            if (_e1642 > 1267650600000000000000000000000f) {
                                                                let _e1644 = local_113;
                                                                phi_1180_ = select(true, false, (_e1644 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_1180_ = true;
                                                            }
                                                            let _e1648 = phi_1180_;
                                                            if _e1648 {
                                                                let _e1649 = local_113;
                                                                if (_e1649 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e1651 = local_113;
                                                                    phi_1194_ = select(true, false, (_e1651 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_1194_ = true;
                                                                }
                                                                let _e1655 = phi_1194_;
                                                                let _e1656 = local_113;
                                                                phi_1199_ = select(0f, _e1656, _e1655);
                                                            } else {
                                                                phi_1199_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e1659 = phi_1199_;
                                                            local_117 = _e1659;
                                                            let _e1660 = local_115;
                                                            if (_e1660 > 1267650600000000000000000000000f) {
                                                                let _e1662 = local_115;
                                                                phi_1209_ = select(true, false, (_e1662 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_1209_ = true;
                                                            }
                                                            let _e1666 = phi_1209_;
                                                            if _e1666 {
                                                                let _e1667 = local_115;
                                                                if (_e1667 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e1669 = local_115;
                                                                    phi_1223_ = select(true, false, (_e1669 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_1223_ = true;
                                                                }
                                                                let _e1673 = phi_1223_;
                                                                let _e1674 = local_115;
                                                                phi_1228_ = select(0f, _e1674, _e1673);
                                                            } else {
                                                                phi_1228_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e1677 = phi_1228_;
                                                            local_118 = _e1677;
                                                            let _e1678 = local_116;
                                                            let _e1679 = local_117;
                                                            local_119 = array<f32, 3>(_e1678, _e1679, _e1677);
                                                            let _e1681 = local_109;
                                                            let _e1682 = local_2;
                                                            if (_e1681 < _e1682) {
                                                            } else {
                                                                phi_5775_ = true;
                                                                break;
                                                            }
                                                            let _e1684 = local_109;
                                                            let _e1687 = global_3.member[_e1684];
                                                            local_120 = bitcast<f32>(_e1687);
                                                            let _e1689 = local_116;
                                                            if ((bitcast<u32>(_e1689) & 2139095040u) != 2139095040u) {
                                                                let _e1693 = local_117;
                                                                if ((bitcast<u32>(_e1693) & 2139095040u) != 2139095040u) {
                                                                    let _e1697 = local_118;
                                                                    if ((bitcast<u32>(_e1697) & 2139095040u) != 2139095040u) {
                                                                        let _e1701 = local_120;
                                                                        let _e1702 = bitcast<u32>(_e1701);
                                                                        local_121 = _e1702;
                                                                        if (_e1702 == 0u) {
                                                                            phi_1262_ = false;
                                                                        } else {
                                                                            let _e1704 = local_121;
                                                                            phi_1262_ = (_e1704 <= 2139095040u);
                                                                        }
                                                                        let _e1707 = phi_1262_;
                                                                        local_122 = _e1707;
                                                                        if _e1707 {
                                                                            let _e1708 = local_119;
                                                                            let _e1709 = local_120;
                                                                            phi_1268_ = type_23(1u, type_22(_e1708, _e1709));
                                                                        } else {
                                                                            phi_1268_ = type_23();
                                                                        }
                                                                        let _e1713 = phi_1268_;
                                                                        let _e1714 = local_122;
                                                                        phi_1270_ = _e1713;
                                                                        phi_1271_ = select(true, false, _e1714);
                                                                    } else {
                                                                        phi_1270_ = type_23();
                                                                        phi_1271_ = true;
                                                                    }
                                                                    let _e1717 = phi_1270_;
                                                                    let _e1719 = phi_1271_;
                                                                    phi_1272_ = _e1717;
                                                                    phi_1273_ = _e1719;
                                                                } else {
                                                                    phi_1272_ = type_23();
                                                                    phi_1273_ = true;
                                                                }
                                                                let _e1721 = phi_1272_;
                                                                let _e1723 = phi_1273_;
                                                                phi_1274_ = _e1721;
                                                                phi_1275_ = _e1723;
                                                            } else {
                                                                phi_1274_ = type_23();
                                                                phi_1275_ = true;
                                                            }
                                                            let _e1725 = phi_1274_;
                                                            let _e1727 = phi_1275_;
                                                            if _e1727 {
                                                                phi_1280_ = type_23(0u, type_23().member_1);
                                                            } else {
                                                                phi_1280_ = _e1725;
                                                            }
                                                            let _e1732 = phi_1280_;
                                                            local_123 = _e1732;
                                                            if (bitcast<i32>(_e1732.member) != 0i) {
                                                                let _e1736 = local_123;
                                                                local_124 = _e1736.member_1.member[0];
                                                                local_125 = _e1736.member_1.member[1];
                                                                local_126 = _e1736.member_1.member[2];
                                                                local_127 = (((0.2126f * _e1736.member_1.member[0]) + (0.7152f * _e1736.member_1.member[1])) + (0.0722f * _e1736.member_1.member[2]));
                                                                let _e1747 = local_92;
                                                                if (_e1747 == 0u) {
                                                                    let _e1771 = local_101;
                                                                    let _e1772 = local_127;
                                                                    let _e1774 = local_101;
                                                                    let _e1775 = local_127;
                                                                    phi_1322_ = _e1512;
                                                                    phi_1323_ = _e1514;
                                                                    phi_1324_ = select(_e1775, _e1774, (_e1771 < _e1772));
                                                                } else {
                                                                    let _e1749 = local_127;
                                                                    let _e1750 = local_97;
                                                                    if (_e1749 <= _e1750) {
                                                                        let _e1752 = local_100;
                                                                        let _e1754 = local_124;
                                                                        let _e1756 = local_100;
                                                                        let _e1758 = local_125;
                                                                        let _e1760 = local_100;
                                                                        let _e1762 = local_126;
                                                                        let _e1765 = local_99;
                                                                        phi_1320_ = (_e1765 + 1u);
                                                                        phi_1321_ = array<f32, 3>((_e1752[0] + _e1754), (_e1756[1] + _e1758), (_e1760[2] + _e1762));
                                                                    } else {
                                                                        phi_1320_ = _e1512;
                                                                        phi_1321_ = _e1514;
                                                                    }
                                                                    let _e1768 = phi_1320_;
                                                                    let _e1770 = phi_1321_;
                                                                    phi_1322_ = _e1768;
                                                                    phi_1323_ = _e1770;
                                                                    phi_1324_ = _e1516;
                                                                }
                                                                let _e1778 = phi_1322_;
                                                                let _e1780 = phi_1323_;
                                                                let _e1782 = phi_1324_;
                                                                phi_1325_ = _e1778;
                                                                phi_1326_ = _e1780;
                                                                phi_1327_ = _e1782;
                                                            } else {
                                                                phi_1325_ = _e1512;
                                                                phi_1326_ = _e1514;
                                                                phi_1327_ = _e1516;
                                                            }
                                                            let _e1784 = phi_1325_;
                                                            let _e1786 = phi_1326_;
                                                            let _e1788 = phi_1327_;
                                                            phi_1328_ = _e1784;
                                                            phi_1329_ = _e1786;
                                                            phi_1330_ = _e1788;
                                                        } else {
                                                            phi_1328_ = _e1512;
                                                            phi_1329_ = _e1514;
                                                            phi_1330_ = _e1516;
                                                        }
                                                        let _e1790 = phi_1328_;
                                                        let _e1792 = phi_1329_;
                                                        let _e1794 = phi_1330_;
                                                        phi_1331_ = _e1790;
                                                        phi_1332_ = _e1792;
                                                        phi_1333_ = _e1794;
                                                    } else {
                                                        phi_1331_ = _e1512;
                                                        phi_1332_ = _e1514;
                                                        phi_1333_ = _e1516;
                                                    }
                                                    let _e1796 = phi_1331_;
                                                    let _e1798 = phi_1332_;
                                                    let _e1800 = phi_1333_;
                                                    phi_1334_ = _e1796;
                                                    phi_1335_ = _e1798;
                                                    phi_1336_ = _e1800;
                                                } else {
                                                    phi_1334_ = _e1512;
                                                    phi_1335_ = _e1514;
                                                    phi_1336_ = _e1516;
                                                }
                                                let _e1802 = phi_1334_;
                                                let _e1804 = phi_1335_;
                                                let _e1806 = phi_1336_;
                                                phi_1337_ = _e1802;
                                                phi_1338_ = _e1804;
                                                phi_1339_ = _e1806;
                                            } else {
                                                phi_1337_ = _e1512;
                                                phi_1338_ = _e1514;
                                                phi_1339_ = _e1516;
                                            }
                                            let _e1808 = phi_1337_;
                                            let _e1810 = phi_1338_;
                                            let _e1812 = phi_1339_;
                                            phi_1340_ = _e1808;
                                            phi_1341_ = _e1810;
                                            phi_1342_ = _e1812;
                                        } else {
                                            phi_1340_ = _e1512;
                                            phi_1341_ = _e1514;
                                            phi_1342_ = _e1516;
                                        }
                                        let _e1814 = phi_1340_;
                                        let _e1816 = phi_1341_;
                                        let _e1818 = phi_1342_;
                                        let _e1819 = local_98;
                                        phi_1015_ = (_e1819 + 1u);
                                        phi_1018_ = _e1814;
                                        phi_1020_ = _e1816;
                                        phi_1022_ = _e1818;
                                    } else {
                                        phi_1015_ = u32();
                                        phi_1018_ = u32();
                                        phi_1020_ = array<f32, 3>();
                                        phi_1022_ = f32();
                                    }
                                    let _e1822 = phi_1015_;
                                    let _e1824 = phi_1018_;
                                    let _e1826 = phi_1020_;
                                    let _e1828 = phi_1022_;
                                    continue;
                                    continuing {
                                        let _e1829 = local_102;
                                        phi_1014_ = _e1822;
                                        phi_1017_ = _e1824;
                                        phi_1019_ = _e1826;
                                        phi_1021_ = _e1828;
                                        phi_5775_ = _e1493;
                                        break if !(_e1829);
                                    }
                                }
                                let _e1832 = phi_5775_;
                                phi_5820_ = _e1832;
                                if _e1832 {
                                    break;
                                }
                                let _e1833 = local_92;
                                phi_5821_ = _e1832;
                                phi_993_ = (_e1833 + 1u);
                                let _e5606 = local_542;
                                phi_996_ = _e5606;
                                let _e5609 = local_543;
                                phi_998_ = _e5609;
                                let _e5612 = local_544;
                                phi_1000_ = _e5612;
                            } else {
                                phi_5821_ = _e1493;
                                phi_993_ = u32();
                                phi_996_ = u32();
                                phi_998_ = array<f32, 3>();
                                phi_1000_ = f32();
                            }
                            let _e1836 = phi_5821_;
                            let _e1838 = phi_993_;
                            let _e1840 = phi_996_;
                            let _e1842 = phi_998_;
                            let _e1844 = phi_1000_;
                            continue;
                            continuing {
                                let _e1845 = local_96;
                                phi_5814_ = _e1836;
                                phi_992_ = _e1838;
                                phi_995_ = _e1840;
                                phi_997_ = _e1842;
                                phi_999_ = _e1844;
                                phi_5820_ = _e1836;
                                break if !(_e1845);
                            }
                        }
                        let _e1848 = phi_5820_;
                        if _e1848 {
                            break;
                        }
                        let _e1849 = local_93;
                        if (_e1849 == 0u) {
                            local_516 = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_6047_ = _e1848;
                            phi_5965_ = 0f;
                            phi_5917_ = 0f;
                            phi_5869_ = 0f;
                        } else {
                            let _e1851 = local_93;
                            let _e1853 = (1f / f32(_e1851));
                            let _e1854 = local_94;
                            let _e1856 = (_e1854[0] * _e1853);
                            local_128 = _e1856;
                            let _e1857 = local_94;
                            let _e1859 = (_e1857[1] * _e1853);
                            local_129 = _e1859;
                            let _e1860 = local_94;
                            let _e1862 = (_e1860[2] * _e1853);
                            local_130 = _e1862;
                            local_131 = (((0.2126f * _e1856) + (0.7152f * _e1859)) + (0.0722f * _e1862));
                            local_516 = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_1370_ = 0u;
                            loop {
                                let _e1869 = phi_1370_;
                                local_132 = _e1869;
                                let _e1870 = local_132;
                                let _e1871 = (_e1870 < 4u);
                                local_133 = _e1871;
                                if _e1871 {
                                    let _e1872 = local_17;
                                    let _e1874 = local_132;
                                    let _e1876 = ((2u * _e1872) + (_e1874 % 2u));
                                    local_134 = _e1876;
                                    let _e1877 = local_18;
                                    let _e1879 = local_132;
                                    local_135 = ((2u * _e1877) + (_e1879 / 2u));
                                    let _e1882 = local_10;
                                    if (_e1876 < _e1882) {
                                        let _e1884 = local_135;
                                        let _e1885 = local_14;
                                        if (_e1884 < _e1885) {
                                            let _e1887 = local_135;
                                            let _e1888 = local_10;
                                            let _e1890 = local_134;
                                            let _e1891 = ((_e1887 * _e1888) + _e1890);
                                            local_136 = _e1891;
                                            let _e1892 = (3u * _e1891);
                                            local_137 = _e1892;
                                            let _e1893 = local_1;
                                            if (_e1892 < _e1893) {
                                            } else {
                                                phi_5822_ = true;
                                                break;
                                            }
                                            let _e1895 = local_137;
                                            let _e1898 = global_4.member[_e1895];
                                            local_138 = bitcast<f32>(_e1898);
                                            let _e1900 = local_137;
                                            let _e1901 = (_e1900 + 1u);
                                            local_139 = _e1901;
                                            let _e1902 = local_1;
                                            if (_e1901 < _e1902) {
                                            } else {
                                                phi_5822_ = true;
                                                break;
                                            }
                                            let _e1904 = local_139;
                                            let _e1907 = global_4.member[_e1904];
                                            local_140 = bitcast<f32>(_e1907);
                                            let _e1909 = local_137;
                                            let _e1910 = (_e1909 + 2u);
                                            local_141 = _e1910;
                                            let _e1911 = local_1;
                                            if (_e1910 < _e1911) {
                                            } else {
                                                phi_5822_ = true;
                                                break;
                                            }
                                            let _e1913 = local_141;
                                            let _e1916 = global_4.member[_e1913];
                                            local_142 = bitcast<f32>(_e1916);
                                            let _e1918 = local_138;
                                            if (_e1918 > 1267650600000000000000000000000f) {
                                                let _e1920 = local_138;
                                                phi_1439_ = select(true, false, (_e1920 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_1439_ = true;
                                            }
                                            let _e1924 = phi_1439_;
                                            if _e1924 {
                                                let _e1925 = local_138;
                                                if (_e1925 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e1927 = local_138;
                                                    phi_1453_ = select(true, false, (_e1927 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1453_ = true;
                                                }
                                                let _e1931 = phi_1453_;
                                                let _e1932 = local_138;
                                                phi_1458_ = select(0f, _e1932, _e1931);
                                            } else {
                                                phi_1458_ = 1267650600000000000000000000000f;
                                            }
                                            let _e1935 = phi_1458_;
                                            local_143 = _e1935;
                                            let _e1936 = local_140;
                                            if (_e1936 > 1267650600000000000000000000000f) {
                                                let _e1938 = local_140;
                                                phi_1468_ = select(true, false, (_e1938 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_1468_ = true;
                                            }
                                            let _e1942 = phi_1468_;
                                            if _e1942 {
                                                let _e1943 = local_140;
                                                if (_e1943 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e1945 = local_140;
                                                    phi_1482_ = select(true, false, (_e1945 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1482_ = true;
                                                }
                                                let _e1949 = phi_1482_;
                                                let _e1950 = local_140;
                                                phi_1487_ = select(0f, _e1950, _e1949);
                                            } else {
                                                phi_1487_ = 1267650600000000000000000000000f;
                                            }
                                            let _e1953 = phi_1487_;
                                            local_144 = _e1953;
                                            let _e1954 = local_142;
                                            if (_e1954 > 1267650600000000000000000000000f) {
                                                let _e1956 = local_142;
                                                phi_1497_ = select(true, false, (_e1956 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_1497_ = true;
                                            }
                                            let _e1960 = phi_1497_;
                                            if _e1960 {
                                                let _e1961 = local_142;
                                                if (_e1961 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e1963 = local_142;
                                                    phi_1511_ = select(true, false, (_e1963 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1511_ = true;
                                                }
                                                let _e1967 = phi_1511_;
                                                let _e1968 = local_142;
                                                phi_1516_ = select(0f, _e1968, _e1967);
                                            } else {
                                                phi_1516_ = 1267650600000000000000000000000f;
                                            }
                                            let _e1971 = phi_1516_;
                                            local_145 = _e1971;
                                            let _e1972 = local_143;
                                            let _e1973 = local_144;
                                            local_146 = array<f32, 3>(_e1972, _e1973, _e1971);
                                            let _e1975 = local_136;
                                            let _e1976 = local_2;
                                            if (_e1975 < _e1976) {
                                            } else {
                                                phi_5822_ = true;
                                                break;
                                            }
                                            let _e1978 = local_136;
                                            let _e1981 = global_3.member[_e1978];
                                            local_147 = bitcast<f32>(_e1981);
                                            let _e1983 = local_143;
                                            if ((bitcast<u32>(_e1983) & 2139095040u) != 2139095040u) {
                                                let _e1987 = local_144;
                                                if ((bitcast<u32>(_e1987) & 2139095040u) != 2139095040u) {
                                                    let _e1991 = local_145;
                                                    if ((bitcast<u32>(_e1991) & 2139095040u) != 2139095040u) {
                                                        let _e1995 = local_147;
                                                        let _e1996 = bitcast<u32>(_e1995);
                                                        local_148 = _e1996;
                                                        if (_e1996 == 0u) {
                                                            phi_1550_ = false;
                                                        } else {
                                                            let _e1998 = local_148;
                                                            phi_1550_ = (_e1998 <= 2139095040u);
                                                        }
                                                        let _e2001 = phi_1550_;
                                                        local_149 = _e2001;
                                                        if _e2001 {
                                                            let _e2002 = local_146;
                                                            let _e2003 = local_147;
                                                            phi_1556_ = type_23(1u, type_22(_e2002, _e2003));
                                                        } else {
                                                            phi_1556_ = type_23();
                                                        }
                                                        let _e2007 = phi_1556_;
                                                        let _e2008 = local_149;
                                                        phi_1558_ = _e2007;
                                                        phi_1559_ = select(true, false, _e2008);
                                                    } else {
                                                        phi_1558_ = type_23();
                                                        phi_1559_ = true;
                                                    }
                                                    let _e2011 = phi_1558_;
                                                    let _e2013 = phi_1559_;
                                                    phi_1560_ = _e2011;
                                                    phi_1561_ = _e2013;
                                                } else {
                                                    phi_1560_ = type_23();
                                                    phi_1561_ = true;
                                                }
                                                let _e2015 = phi_1560_;
                                                let _e2017 = phi_1561_;
                                                phi_1562_ = _e2015;
                                                phi_1563_ = _e2017;
                                            } else {
                                                phi_1562_ = type_23();
                                                phi_1563_ = true;
                                            }
                                            let _e2019 = phi_1562_;
                                            let _e2021 = phi_1563_;
                                            if _e2021 {
                                                phi_1568_ = type_23(0u, type_23().member_1);
                                            } else {
                                                phi_1568_ = _e2019;
                                            }
                                            let _e2026 = phi_1568_;
                                            local_150 = _e2026;
                                            if (bitcast<i32>(_e2026.member) != 0i) {
                                                let _e2030 = local_150;
                                                local_151 = _e2030.member_1.member;
                                                let _e2033 = local_150;
                                                local_152 = _e2033.member_1.member_1;
                                                let _e2036 = bitcast<u32>(_e2033.member_1.member_1);
                                                local_153 = _e2036;
                                                if (_e2036 == 2139095040u) {
                                                    let _e2080 = global_2.member.member_4.member_1;
                                                    let _e2085 = global_2.member.member_4.member;
                                                    let _e2090 = global_2.member.member_4.member_2;
                                                    let _e2096 = global_2.member.member_4.member_3;
                                                    phi_1639_ = (0.5f * ((((2f * _e2080) * _e2085) / (_e2090 - _e2085)) * _e2096));
                                                } else {
                                                    let _e2038 = local_153;
                                                    if (_e2038 == 0u) {
                                                        phi_1608_ = false;
                                                    } else {
                                                        let _e2040 = local_153;
                                                        phi_1608_ = (_e2040 <= 2139095040u);
                                                    }
                                                    let _e2043 = phi_1608_;
                                                    if _e2043 {
                                                        let _e2047 = global_2.member.member_4.member_1;
                                                        let _e2052 = global_2.member.member_4.member;
                                                        let _e2057 = global_2.member.member_4.member_2;
                                                        local_154 = _e2057;
                                                        let _e2063 = global_2.member.member_4.member_3;
                                                        let _e2064 = ((((2f * _e2047) * _e2052) / (_e2057 - _e2052)) * _e2063);
                                                        local_155 = _e2064;
                                                        if (_e2064 == 0f) {
                                                            phi_1636_ = 0f;
                                                        } else {
                                                            let _e2066 = local_154;
                                                            let _e2067 = local_152;
                                                            let _e2070 = local_155;
                                                            phi_1636_ = (_e2070 * (1f - (_e2066 / _e2067)));
                                                        }
                                                        let _e2073 = phi_1636_;
                                                        phi_1637_ = _e2073;
                                                    } else {
                                                        phi_1637_ = _e613;
                                                    }
                                                    let _e2075 = phi_1637_;
                                                    phi_1639_ = (0.5f * _e2075);
                                                }
                                                let _e2100 = phi_1639_;
                                                let _e2101 = local_20;
                                                let _e2103 = local_20;
                                                let _e2104 = select(_e2103, _e2100, (_e2100 < _e2101));
                                                let _e2105 = local_20;
                                                let _e2106 = -(_e2105);
                                                let _e2108 = select(_e2106, _e2104, (_e2104 > _e2106));
                                                local_498 = _e2108;
                                                if (_e2108 < 0f) {
                                                    let _e2110 = local_498;
                                                    phi_1656_ = -(_e2110);
                                                } else {
                                                    phi_1656_ = _e2108;
                                                }
                                                let _e2113 = phi_1656_;
                                                let _e2115 = ((_e2113 - 0.25f) * 4f);
                                                let _e2117 = select(0f, _e2115, (_e2115 > 0f));
                                                local_499 = select(1f, _e2117, (_e2117 < 1f));
                                                let _e2120 = local_151;
                                                let _e2122 = local_128;
                                                let _e2123 = (_e2120[0] - _e2122);
                                                let _e2126 = local_151;
                                                let _e2128 = local_129;
                                                let _e2129 = (_e2126[1] - _e2128);
                                                let _e2132 = local_151;
                                                let _e2134 = local_130;
                                                let _e2135 = (_e2132[2] - _e2134);
                                                let _e2142 = (((0.2126f * _e2120[0]) + (0.7152f * _e2126[1])) + (0.0722f * _e2132[2]));
                                                local_156 = _e2142;
                                                local_157 = (((0.2126f * select(0f, _e2123, (_e2123 > 0f))) + (0.7152f * select(0f, _e2129, (_e2129 > 0f)))) + (0.0722f * select(0f, _e2135, (_e2135 > 0f))));
                                                let _e2148 = local_131;
                                                if (_e2142 >= (8f * _e2148)) {
                                                    phi_1723_ = 1f;
                                                } else {
                                                    let _e2151 = local_131;
                                                    let _e2152 = (4f * _e2151);
                                                    let _e2153 = local_156;
                                                    let _e2155 = ((_e2153 - _e2152) / _e2152);
                                                    let _e2157 = select(0f, _e2155, (_e2155 > 0f));
                                                    phi_1723_ = select(1f, _e2157, (_e2157 < 1f));
                                                }
                                                let _e2161 = phi_1723_;
                                                let _e2162 = local_157;
                                                let _e2164 = ((_e2162 - 0.25f) * 4f);
                                                let _e2166 = select(0f, _e2164, (_e2164 > 0f));
                                                local_500 = select(1f, _e2166, (_e2166 < 1f));
                                                let _e2169 = local_499;
                                                local_158 = (_e2169 * _e2161);
                                                let _e2171 = local_133;
                                                if _e2171 {
                                                } else {
                                                    phi_5822_ = true;
                                                    break;
                                                }
                                                let _e2172 = local_132;
                                                let _e2174 = local_158;
                                                let _e2175 = local_500;
                                                local_516[_e2172] = (_e2174 * _e2175);
                                            }
                                        }
                                    }
                                    let _e2177 = local_132;
                                    phi_1371_ = (_e2177 + 1u);
                                } else {
                                    phi_1371_ = u32();
                                }
                                let _e2180 = phi_1371_;
                                continue;
                                continuing {
                                    let _e2181 = local_133;
                                    phi_1370_ = _e2180;
                                    phi_5822_ = _e1848;
                                    break if !(_e2181);
                                }
                            }
                            let _e2184 = phi_5822_;
                            if _e2184 {
                                break;
                            }
                            phi_6047_ = _e2184;
                            phi_5965_ = _e1856;
                            phi_5917_ = _e1859;
                            phi_5869_ = _e1862;
                        }
                        let _e2186 = phi_6047_;
                        let _e2188 = phi_5965_;
                        let _e2190 = phi_5917_;
                        let _e2192 = phi_5869_;
                        local_492 = _e2188;
                        local_491 = _e2190;
                        local_490 = _e2192;
                        let _e2193 = local_516;
                        local_489 = _e2193;
                        local_159 = _e2193[1];
                        local_160 = _e2193[2];
                        local_161 = _e2193[3];
                        if (_e2193[0] > 0f) {
                            phi_1778_ = bool();
                            phi_1779_ = true;
                        } else {
                            let _e2199 = local_159;
                            if (_e2199 > 0f) {
                                phi_1776_ = bool();
                                phi_1777_ = true;
                            } else {
                                let _e2201 = local_160;
                                let _e2202 = (_e2201 > 0f);
                                if _e2202 {
                                    phi_1775_ = bool();
                                } else {
                                    let _e2203 = local_161;
                                    phi_1775_ = (_e2203 > 0f);
                                }
                                let _e2206 = phi_1775_;
                                phi_1776_ = _e2206;
                                phi_1777_ = _e2202;
                            }
                            let _e2208 = phi_1776_;
                            let _e2210 = phi_1777_;
                            phi_1778_ = _e2208;
                            phi_1779_ = _e2210;
                        }
                        let _e2212 = phi_1778_;
                        let _e2214 = phi_1779_;
                        let _e2215 = select(_e2212, true, _e2214);
                        local_501 = _e2215;
                        if _e2215 {
                            local_536 = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_6044_ = _e2186;
                            phi_1791_ = 0u;
                            phi_1794_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_1796_ = array<f32, 3>(0f, 0f, 0f);
                            phi_1798_ = 0f;
                            phi_1800_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_1802_ = 0f;
                            phi_1804_ = 0f;
                            phi_1806_ = array<f32, 3>(0f, 0f, 0f);
                            phi_1808_ = array<f32, 2>(0f, 0f);
                            phi_1810_ = 0u;
                            phi_1812_ = 0f;
                            loop {
                                let _e2217 = phi_6044_;
                                let _e2219 = phi_1791_;
                                let _e2221 = phi_1794_;
                                let _e2223 = phi_1796_;
                                let _e2225 = phi_1798_;
                                let _e2227 = phi_1800_;
                                let _e2229 = phi_1802_;
                                let _e2231 = phi_1804_;
                                let _e2233 = phi_1806_;
                                let _e2235 = phi_1808_;
                                let _e2237 = phi_1810_;
                                let _e2239 = phi_1812_;
                                local_162 = _e2219;
                                local_163 = _e2221;
                                local_164 = _e2223;
                                local_165 = _e2225;
                                local_166 = _e2227;
                                local_167 = _e2229;
                                local_168 = _e2231;
                                local_169 = _e2233;
                                local_170 = _e2235;
                                local_171 = _e2237;
                                local_172 = _e2239;
                                let _e2240 = local_162;
                                let _e2241 = (_e2240 < 4u);
                                local_173 = _e2241;
                                if _e2241 {
                                    let _e2242 = local_17;
                                    let _e2244 = local_162;
                                    let _e2246 = ((2u * _e2242) + (_e2244 % 2u));
                                    local_174 = _e2246;
                                    let _e2247 = local_18;
                                    let _e2249 = local_162;
                                    local_175 = ((2u * _e2247) + (_e2249 / 2u));
                                    let _e2252 = local_10;
                                    if (_e2246 < _e2252) {
                                        let _e2254 = local_175;
                                        let _e2255 = local_14;
                                        if (_e2254 < _e2255) {
                                            let _e2257 = local_175;
                                            let _e2258 = local_10;
                                            let _e2260 = local_174;
                                            let _e2261 = ((_e2257 * _e2258) + _e2260);
                                            local_176 = _e2261;
                                            let _e2262 = (3u * _e2261);
                                            local_177 = _e2262;
                                            let _e2263 = local_1;
                                            if (_e2262 < _e2263) {
                                            } else {
                                                phi_6053_ = true;
                                                break;
                                            }
                                            let _e2265 = local_177;
                                            let _e2268 = global_4.member[_e2265];
                                            local_178 = bitcast<f32>(_e2268);
                                            let _e2270 = local_177;
                                            let _e2271 = (_e2270 + 1u);
                                            local_179 = _e2271;
                                            let _e2272 = local_1;
                                            if (_e2271 < _e2272) {
                                            } else {
                                                phi_6053_ = true;
                                                break;
                                            }
                                            let _e2274 = local_179;
                                            let _e2277 = global_4.member[_e2274];
                                            local_180 = bitcast<f32>(_e2277);
                                            let _e2279 = local_177;
                                            let _e2280 = (_e2279 + 2u);
                                            local_181 = _e2280;
                                            let _e2281 = local_1;
                                            if (_e2280 < _e2281) {
                                            } else {
                                                phi_6053_ = true;
                                                break;
                                            }
                                            let _e2283 = local_181;
                                            let _e2286 = global_4.member[_e2283];
                                            local_182 = bitcast<f32>(_e2286);
                                            let _e2288 = local_178;
                                            if (_e2288 > 1267650600000000000000000000000f) {
                                                let _e2290 = local_178;
                                                phi_1880_ = select(true, false, (_e2290 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_1880_ = true;
                                            }
                                            let _e2294 = phi_1880_;
                                            if _e2294 {
                                                let _e2295 = local_178;
                                                if (_e2295 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e2297 = local_178;
                                                    phi_1894_ = select(true, false, (_e2297 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1894_ = true;
                                                }
                                                let _e2301 = phi_1894_;
                                                let _e2302 = local_178;
                                                phi_1899_ = select(0f, _e2302, _e2301);
                                            } else {
                                                phi_1899_ = 1267650600000000000000000000000f;
                                            }
                                            let _e2305 = phi_1899_;
                                            local_183 = _e2305;
                                            let _e2306 = local_180;
                                            if (_e2306 > 1267650600000000000000000000000f) {
                                                let _e2308 = local_180;
                                                phi_1909_ = select(true, false, (_e2308 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_1909_ = true;
                                            }
                                            let _e2312 = phi_1909_;
                                            if _e2312 {
                                                let _e2313 = local_180;
                                                if (_e2313 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e2315 = local_180;
                                                    phi_1923_ = select(true, false, (_e2315 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1923_ = true;
                                                }
                                                let _e2319 = phi_1923_;
                                                let _e2320 = local_180;
                                                phi_1928_ = select(0f, _e2320, _e2319);
                                            } else {
                                                phi_1928_ = 1267650600000000000000000000000f;
                                            }
                                            let _e2323 = phi_1928_;
                                            local_184 = _e2323;
                                            let _e2324 = local_182;
                                            if (_e2324 > 1267650600000000000000000000000f) {
                                                let _e2326 = local_182;
                                                phi_1938_ = select(true, false, (_e2326 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_1938_ = true;
                                            }
                                            let _e2330 = phi_1938_;
                                            if _e2330 {
                                                let _e2331 = local_182;
                                                if (_e2331 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e2333 = local_182;
                                                    phi_1952_ = select(true, false, (_e2333 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1952_ = true;
                                                }
                                                let _e2337 = phi_1952_;
                                                let _e2338 = local_182;
                                                phi_1957_ = select(0f, _e2338, _e2337);
                                            } else {
                                                phi_1957_ = 1267650600000000000000000000000f;
                                            }
                                            let _e2341 = phi_1957_;
                                            local_185 = _e2341;
                                            let _e2342 = local_183;
                                            let _e2343 = local_184;
                                            local_186 = array<f32, 3>(_e2342, _e2343, _e2341);
                                            let _e2345 = local_176;
                                            let _e2346 = local_2;
                                            if (_e2345 < _e2346) {
                                            } else {
                                                phi_6053_ = true;
                                                break;
                                            }
                                            let _e2348 = local_176;
                                            let _e2351 = global_3.member[_e2348];
                                            local_187 = bitcast<f32>(_e2351);
                                            let _e2353 = local_183;
                                            if ((bitcast<u32>(_e2353) & 2139095040u) != 2139095040u) {
                                                let _e2357 = local_184;
                                                if ((bitcast<u32>(_e2357) & 2139095040u) != 2139095040u) {
                                                    let _e2361 = local_185;
                                                    if ((bitcast<u32>(_e2361) & 2139095040u) != 2139095040u) {
                                                        let _e2365 = local_187;
                                                        let _e2366 = bitcast<u32>(_e2365);
                                                        local_188 = _e2366;
                                                        if (_e2366 == 0u) {
                                                            phi_1991_ = false;
                                                        } else {
                                                            let _e2368 = local_188;
                                                            phi_1991_ = (_e2368 <= 2139095040u);
                                                        }
                                                        let _e2371 = phi_1991_;
                                                        local_189 = _e2371;
                                                        if _e2371 {
                                                            let _e2372 = local_186;
                                                            let _e2373 = local_187;
                                                            phi_1997_ = type_23(1u, type_22(_e2372, _e2373));
                                                        } else {
                                                            phi_1997_ = type_23();
                                                        }
                                                        let _e2377 = phi_1997_;
                                                        let _e2378 = local_189;
                                                        phi_1999_ = _e2377;
                                                        phi_2000_ = select(true, false, _e2378);
                                                    } else {
                                                        phi_1999_ = type_23();
                                                        phi_2000_ = true;
                                                    }
                                                    let _e2381 = phi_1999_;
                                                    let _e2383 = phi_2000_;
                                                    phi_2001_ = _e2381;
                                                    phi_2002_ = _e2383;
                                                } else {
                                                    phi_2001_ = type_23();
                                                    phi_2002_ = true;
                                                }
                                                let _e2385 = phi_2001_;
                                                let _e2387 = phi_2002_;
                                                phi_2003_ = _e2385;
                                                phi_2004_ = _e2387;
                                            } else {
                                                phi_2003_ = type_23();
                                                phi_2004_ = true;
                                            }
                                            let _e2389 = phi_2003_;
                                            let _e2391 = phi_2004_;
                                            if _e2391 {
                                                phi_2009_ = type_23(0u, type_23().member_1);
                                            } else {
                                                phi_2009_ = _e2389;
                                            }
                                            let _e2396 = phi_2009_;
                                            local_190 = _e2396;
                                            if (bitcast<i32>(_e2396.member) != 0i) {
                                                let _e2400 = local_190;
                                                local_191 = _e2400.member_1.member;
                                                let _e2403 = local_190;
                                                local_192 = _e2403.member_1.member_1;
                                                let _e2406 = bitcast<u32>(_e2403.member_1.member_1);
                                                local_193 = _e2406;
                                                if (_e2406 == 2139095040u) {
                                                    let _e2450 = global_2.member.member_4.member_1;
                                                    let _e2455 = global_2.member.member_4.member;
                                                    let _e2460 = global_2.member.member_4.member_2;
                                                    let _e2466 = global_2.member.member_4.member_3;
                                                    phi_2077_ = (0.5f * ((((2f * _e2450) * _e2455) / (_e2460 - _e2455)) * _e2466));
                                                } else {
                                                    let _e2408 = local_193;
                                                    if (_e2408 == 0u) {
                                                        phi_2046_ = false;
                                                    } else {
                                                        let _e2410 = local_193;
                                                        phi_2046_ = (_e2410 <= 2139095040u);
                                                    }
                                                    let _e2413 = phi_2046_;
                                                    if _e2413 {
                                                        let _e2417 = global_2.member.member_4.member_1;
                                                        let _e2422 = global_2.member.member_4.member;
                                                        let _e2427 = global_2.member.member_4.member_2;
                                                        local_194 = _e2427;
                                                        let _e2433 = global_2.member.member_4.member_3;
                                                        let _e2434 = ((((2f * _e2417) * _e2422) / (_e2427 - _e2422)) * _e2433);
                                                        local_195 = _e2434;
                                                        if (_e2434 == 0f) {
                                                            phi_2074_ = 0f;
                                                        } else {
                                                            let _e2436 = local_194;
                                                            let _e2437 = local_192;
                                                            let _e2440 = local_195;
                                                            phi_2074_ = (_e2440 * (1f - (_e2436 / _e2437)));
                                                        }
                                                        let _e2443 = phi_2074_;
                                                        phi_2075_ = _e2443;
                                                    } else {
                                                        phi_2075_ = _e613;
                                                    }
                                                    let _e2445 = phi_2075_;
                                                    phi_2077_ = (0.5f * _e2445);
                                                }
                                                let _e2470 = phi_2077_;
                                                let _e2471 = local_20;
                                                let _e2473 = local_20;
                                                let _e2474 = select(_e2473, _e2470, (_e2470 < _e2471));
                                                let _e2475 = local_20;
                                                let _e2476 = -(_e2475);
                                                local_502 = select(_e2476, _e2474, (_e2474 > _e2476));
                                                let _e2479 = local_191;
                                                let _e2481 = local_191;
                                                let _e2483 = local_191;
                                                local_533 = array<f32, 3>(_e2479[0], _e2481[1], _e2483[2]);
                                                let _e2486 = local_492;
                                                let _e2487 = local_491;
                                                let _e2488 = local_490;
                                                let _e2490 = local_489;
                                                local_518 = _e2490;
                                                local_517 = array<f32, 3>(_e2486, _e2487, _e2488);
                                                let _e2491 = local_173;
                                                if _e2491 {
                                                } else {
                                                    phi_6053_ = true;
                                                    break;
                                                }
                                                let _e2492 = local_162;
                                                let _e2494 = local_518[_e2492];
                                                local_196 = _e2494;
                                                if (_e2494 <= 0f) {
                                                    let _e2555 = local_533;
                                                    phi_6063_ = _e2217;
                                                    phi_2195_ = type_25(array<f32, 3>(_e2555[0], _e2555[1], _e2555[2]), array<f32, 3>(0f, 0f, 0f));
                                                } else {
                                                    let _e2496 = local_533;
                                                    local_534 = _e2496;
                                                    local_535 = array<f32, 3>(0f, 0f, 0f);
                                                    phi_2123_ = 0u;
                                                    loop {
                                                        let _e2498 = phi_2123_;
                                                        local_197 = _e2498;
                                                        let _e2499 = local_197;
                                                        let _e2500 = (_e2499 < 3u);
                                                        local_198 = _e2500;
                                                        if _e2500 {
                                                            let _e2501 = local_198;
                                                            if _e2501 {
                                                            } else {
                                                                phi_6013_ = true;
                                                                break;
                                                            }
                                                            let _e2502 = local_197;
                                                            let _e2504 = local_517[_e2502];
                                                            local_199 = _e2504;
                                                            let _e2505 = local_198;
                                                            if _e2505 {
                                                            } else {
                                                                phi_6013_ = true;
                                                                break;
                                                            }
                                                            let _e2506 = local_197;
                                                            let _e2508 = local_533[_e2506];
                                                            let _e2509 = local_199;
                                                            if (_e2508 > _e2509) {
                                                                let _e2511 = local_198;
                                                                if _e2511 {
                                                                } else {
                                                                    phi_6013_ = true;
                                                                    break;
                                                                }
                                                                let _e2512 = local_533[_e2506];
                                                                let _e2513 = local_199;
                                                                local_200 = (_e2512 - _e2513);
                                                                let _e2515 = local_198;
                                                                if _e2515 {
                                                                } else {
                                                                    phi_6013_ = true;
                                                                    break;
                                                                }
                                                                let _e2516 = local_197;
                                                                let _e2518 = local_196;
                                                                let _e2519 = local_200;
                                                                local_535[_e2516] = (_e2518 * _e2519);
                                                                let _e2521 = local_196;
                                                                local_201 = (1f - _e2521);
                                                                let _e2523 = local_198;
                                                                if _e2523 {
                                                                } else {
                                                                    phi_6013_ = true;
                                                                    break;
                                                                }
                                                                let _e2524 = local_533[_e2506];
                                                                let _e2525 = local_201;
                                                                local_202 = (_e2525 * _e2524);
                                                                let _e2527 = local_196;
                                                                let _e2528 = local_199;
                                                                local_203 = (_e2527 * _e2528);
                                                                let _e2530 = local_198;
                                                                if _e2530 {
                                                                } else {
                                                                    phi_6013_ = true;
                                                                    break;
                                                                }
                                                                let _e2531 = local_197;
                                                                let _e2533 = local_202;
                                                                let _e2534 = local_203;
                                                                local_534[_e2531] = (_e2533 + _e2534);
                                                            }
                                                            let _e2536 = local_197;
                                                            phi_2124_ = (_e2536 + 1u);
                                                        } else {
                                                            phi_2124_ = u32();
                                                        }
                                                        let _e2539 = phi_2124_;
                                                        continue;
                                                        continuing {
                                                            let _e2540 = local_198;
                                                            phi_2123_ = _e2539;
                                                            phi_6013_ = _e2217;
                                                            break if !(_e2540);
                                                        }
                                                    }
                                                    let _e2543 = phi_6013_;
                                                    phi_6053_ = _e2543;
                                                    if _e2543 {
                                                        break;
                                                    }
                                                    let _e2544 = local_534;
                                                    let _e2549 = local_535;
                                                    phi_6063_ = _e2543;
                                                    phi_2195_ = type_25(array<f32, 3>(_e2544[0], _e2544[1], _e2544[2]), array<f32, 3>(_e2549[0], _e2549[1], _e2549[2]));
                                                }
                                                let _e2562 = phi_6063_;
                                                let _e2564 = phi_2195_;
                                                local_204 = _e2564.member;
                                                let _e2567 = local_164;
                                                let _e2571 = local_164;
                                                let _e2575 = local_164;
                                                local_205 = (((0.2126f * _e2564.member_1[0]) + (0.7152f * _e2564.member_1[1])) + (0.0722f * _e2564.member_1[2]));
                                                let _e2585 = local_173;
                                                if _e2585 {
                                                } else {
                                                    phi_6053_ = true;
                                                    break;
                                                }
                                                let _e2586 = local_162;
                                                let _e2588 = local_205;
                                                local_536[_e2586] = _e2588;
                                                let _e2589 = local_163;
                                                let _e2591 = local_174;
                                                let _e2592 = f32(_e2591);
                                                let _e2594 = local_205;
                                                let _e2597 = local_163;
                                                let _e2599 = local_175;
                                                let _e2600 = f32(_e2599);
                                                let _e2602 = local_205;
                                                let _e2605 = local_163;
                                                let _e2607 = local_205;
                                                let _e2608 = local_502;
                                                let _e2611 = local_163;
                                                let _e2613 = local_205;
                                                let _e2616 = local_172;
                                                let _e2617 = local_502;
                                                let _e2619 = local_170;
                                                let _e2623 = local_170;
                                                let _e2628 = local_171;
                                                let _e2630 = local_502;
                                                let _e2632 = local_502;
                                                let _e2634 = ((-1f - _e2632) * 0.5f);
                                                let _e2636 = select(0f, _e2634, (_e2634 > 0f));
                                                let _e2638 = select(1f, _e2636, (_e2636 < 1f));
                                                let _e2639 = local_169;
                                                let _e2641 = local_204;
                                                let _e2645 = local_169;
                                                let _e2647 = local_204;
                                                let _e2651 = local_169;
                                                let _e2653 = local_204;
                                                let _e2658 = local_502;
                                                let _e2660 = local_168;
                                                let _e2662 = local_167;
                                                let _e2665 = local_502;
                                                let _e2667 = local_502;
                                                let _e2669 = (select(_e2667, -(_e2630), (_e2665 < 0f)) - 1f);
                                                let _e2671 = select(0f, _e2669, (_e2669 > 0f));
                                                let _e2675 = ((1f - _e2638) * (select(1f, _e2671, (_e2671 < 1f)) + 0.001f));
                                                let _e2676 = local_166;
                                                let _e2680 = local_166;
                                                let _e2684 = local_166;
                                                let _e2688 = local_166;
                                                let _e2690 = local_502;
                                                let _e2694 = local_165;
                                                phi_6057_ = _e2562;
                                                phi_2315_ = array<f32, 4>((_e2589[0] + (_e2594 * (_e2592 + 0.5f))), (_e2597[1] + (_e2602 * (_e2600 + 0.5f))), (_e2605[2] + (_e2607 * _e2608)), (_e2611[3] + _e2613));
                                                phi_2316_ = array<f32, 3>((_e2567[0] + _e2564.member_1[0]), (_e2571[1] + _e2564.member_1[1]), (_e2575[2] + _e2564.member_1[2]));
                                                phi_2317_ = (_e2694 + _e2675);
                                                phi_2318_ = array<f32, 4>((_e2676[0] + (_e2675 * _e2641[0])), (_e2680[1] + (_e2675 * _e2647[1])), (_e2684[2] + (_e2675 * _e2653[2])), (_e2688[3] + (_e2675 * _e2690)));
                                                phi_2319_ = (_e2662 + _e2638);
                                                phi_2320_ = (_e2660 + (_e2638 * _e2658));
                                                phi_2321_ = array<f32, 3>((_e2639[0] + (_e2638 * _e2641[0])), (_e2645[1] + (_e2638 * _e2647[1])), (_e2651[2] + (_e2638 * _e2653[2])));
                                                phi_2322_ = array<f32, 2>(((_e2619[0] + _e2592) + 0.5f), ((_e2623[1] + _e2600) + 0.5f));
                                                phi_2323_ = (_e2628 + 1u);
                                                phi_2324_ = (_e2616 + _e2617);
                                            } else {
                                                phi_6057_ = _e2217;
                                                phi_2315_ = _e2221;
                                                phi_2316_ = _e2223;
                                                phi_2317_ = _e2225;
                                                phi_2318_ = _e2227;
                                                phi_2319_ = _e2229;
                                                phi_2320_ = _e2231;
                                                phi_2321_ = _e2233;
                                                phi_2322_ = _e2235;
                                                phi_2323_ = _e2237;
                                                phi_2324_ = _e2239;
                                            }
                                            let _e2697 = phi_6057_;
                                            let _e2699 = phi_2315_;
                                            let _e2701 = phi_2316_;
                                            let _e2703 = phi_2317_;
                                            let _e2705 = phi_2318_;
                                            let _e2707 = phi_2319_;
                                            let _e2709 = phi_2320_;
                                            let _e2711 = phi_2321_;
                                            let _e2713 = phi_2322_;
                                            let _e2715 = phi_2323_;
                                            let _e2717 = phi_2324_;
                                            phi_6056_ = _e2697;
                                            phi_2325_ = _e2699;
                                            phi_2326_ = _e2701;
                                            phi_2327_ = _e2703;
                                            phi_2328_ = _e2705;
                                            phi_2329_ = _e2707;
                                            phi_2330_ = _e2709;
                                            phi_2331_ = _e2711;
                                            phi_2332_ = _e2713;
                                            phi_2333_ = _e2715;
                                            phi_2334_ = _e2717;
                                        } else {
                                            phi_6056_ = _e2217;
                                            phi_2325_ = _e2221;
                                            phi_2326_ = _e2223;
                                            phi_2327_ = _e2225;
                                            phi_2328_ = _e2227;
                                            phi_2329_ = _e2229;
                                            phi_2330_ = _e2231;
                                            phi_2331_ = _e2233;
                                            phi_2332_ = _e2235;
                                            phi_2333_ = _e2237;
                                            phi_2334_ = _e2239;
                                        }
                                        let _e2719 = phi_6056_;
                                        let _e2721 = phi_2325_;
                                        let _e2723 = phi_2326_;
                                        let _e2725 = phi_2327_;
                                        let _e2727 = phi_2328_;
                                        let _e2729 = phi_2329_;
                                        let _e2731 = phi_2330_;
                                        let _e2733 = phi_2331_;
                                        let _e2735 = phi_2332_;
                                        let _e2737 = phi_2333_;
                                        let _e2739 = phi_2334_;
                                        phi_6055_ = _e2719;
                                        phi_2335_ = _e2721;
                                        phi_2336_ = _e2723;
                                        phi_2337_ = _e2725;
                                        phi_2338_ = _e2727;
                                        phi_2339_ = _e2729;
                                        phi_2340_ = _e2731;
                                        phi_2341_ = _e2733;
                                        phi_2342_ = _e2735;
                                        phi_2343_ = _e2737;
                                        phi_2344_ = _e2739;
                                    } else {
                                        phi_6055_ = _e2217;
                                        phi_2335_ = _e2221;
                                        phi_2336_ = _e2223;
                                        phi_2337_ = _e2225;
                                        phi_2338_ = _e2227;
                                        phi_2339_ = _e2229;
                                        phi_2340_ = _e2231;
                                        phi_2341_ = _e2233;
                                        phi_2342_ = _e2235;
                                        phi_2343_ = _e2237;
                                        phi_2344_ = _e2239;
                                    }
                                    let _e2741 = phi_6055_;
                                    let _e2743 = phi_2335_;
                                    let _e2745 = phi_2336_;
                                    let _e2747 = phi_2337_;
                                    let _e2749 = phi_2338_;
                                    let _e2751 = phi_2339_;
                                    let _e2753 = phi_2340_;
                                    let _e2755 = phi_2341_;
                                    let _e2757 = phi_2342_;
                                    let _e2759 = phi_2343_;
                                    let _e2761 = phi_2344_;
                                    let _e2762 = local_162;
                                    phi_6054_ = _e2741;
                                    phi_1792_ = (_e2762 + 1u);
                                    phi_1795_ = _e2743;
                                    phi_1797_ = _e2745;
                                    phi_1799_ = _e2747;
                                    phi_1801_ = _e2749;
                                    phi_1803_ = _e2751;
                                    phi_1805_ = _e2753;
                                    phi_1807_ = _e2755;
                                    phi_1809_ = _e2757;
                                    phi_1811_ = _e2759;
                                    phi_1813_ = _e2761;
                                } else {
                                    phi_6054_ = _e2217;
                                    phi_1792_ = u32();
                                    phi_1795_ = array<f32, 4>();
                                    phi_1797_ = array<f32, 3>();
                                    phi_1799_ = f32();
                                    phi_1801_ = array<f32, 4>();
                                    phi_1803_ = f32();
                                    phi_1805_ = f32();
                                    phi_1807_ = array<f32, 3>();
                                    phi_1809_ = array<f32, 2>();
                                    phi_1811_ = u32();
                                    phi_1813_ = f32();
                                }
                                let _e2765 = phi_6054_;
                                let _e2767 = phi_1792_;
                                let _e2769 = phi_1795_;
                                let _e2771 = phi_1797_;
                                let _e2773 = phi_1799_;
                                let _e2775 = phi_1801_;
                                let _e2777 = phi_1803_;
                                let _e2779 = phi_1805_;
                                let _e2781 = phi_1807_;
                                let _e2783 = phi_1809_;
                                let _e2785 = phi_1811_;
                                let _e2787 = phi_1813_;
                                continue;
                                continuing {
                                    let _e2788 = local_173;
                                    phi_6044_ = _e2765;
                                    phi_1791_ = _e2767;
                                    phi_1794_ = _e2769;
                                    phi_1796_ = _e2771;
                                    phi_1798_ = _e2773;
                                    phi_1800_ = _e2775;
                                    phi_1802_ = _e2777;
                                    phi_1804_ = _e2779;
                                    phi_1806_ = _e2781;
                                    phi_1808_ = _e2783;
                                    phi_1810_ = _e2785;
                                    phi_1812_ = _e2787;
                                    phi_6053_ = _e2765;
                                    break if !(_e2788);
                                }
                            }
                            let _e2791 = phi_6053_;
                            if _e2791 {
                                break;
                            }
                            let _e2792 = local_171;
                            if (_e2792 == 0u) {
                                let _e2966 = local_513;
                                let _e2967 = local_171;
                                phi_6086_ = _e2791;
                                phi_2483_ = type_30(array<f32, 2>(0f, 0f), array<f32, 3>(0f, 0f, 0f), 0f, 0f, array<f32, 3>(0f, 0f, 0f), _e2966, _e2967, array<f32, 3>(0f, 0f, 0f), 0f, 0f);
                            } else {
                                let _e2794 = local_171;
                                let _e2795 = f32(_e2794);
                                let _e2796 = (1f / _e2795);
                                local_206 = _e2796;
                                let _e2797 = local_172;
                                let _e2799 = ((0.5f * _e2797) * _e2796);
                                local_207 = _e2799;
                                let _e2800 = local_167;
                                let _e2802 = ((_e2795 - _e2800) > 0f);
                                local_208 = _e2802;
                                if _e2802 {
                                    let _e2803 = local_165;
                                    let _e2804 = (_e2803 > 0f);
                                    local_209 = _e2804;
                                    if _e2804 {
                                        let _e2805 = local_165;
                                        let _e2806 = (1f / _e2805);
                                        let _e2807 = local_166;
                                        let _e2810 = local_166;
                                        let _e2813 = local_166;
                                        let _e2817 = local_166;
                                        phi_2375_ = array<f32, 3>((_e2807[0] * _e2806), (_e2810[1] * _e2806), (_e2813[2] * _e2806));
                                        phi_2376_ = ((0.5f * _e2817[3]) * _e2806);
                                    } else {
                                        phi_2375_ = array<f32, 3>();
                                        phi_2376_ = f32();
                                    }
                                    let _e2822 = phi_2375_;
                                    let _e2824 = phi_2376_;
                                    let _e2825 = local_209;
                                    phi_2378_ = _e2822;
                                    phi_2379_ = _e2824;
                                    phi_2380_ = select(true, false, _e2825);
                                } else {
                                    phi_2378_ = array<f32, 3>();
                                    phi_2379_ = f32();
                                    phi_2380_ = true;
                                }
                                let _e2828 = phi_2378_;
                                let _e2830 = phi_2379_;
                                let _e2832 = phi_2380_;
                                local_210 = _e2830;
                                local_211 = _e2832;
                                if _e2832 {
                                    phi_2384_ = array<f32, 3>(0f, 0f, 0f);
                                } else {
                                    phi_2384_ = _e2828;
                                }
                                let _e2834 = phi_2384_;
                                local_212 = _e2834;
                                let _e2835 = local_211;
                                let _e2836 = local_207;
                                let _e2837 = local_210;
                                local_503 = select(_e2837, _e2836, _e2835);
                                let _e2839 = local_167;
                                if (_e2839 > 0f) {
                                    let _e2841 = local_167;
                                    let _e2842 = (1f / _e2841);
                                    let _e2843 = local_169;
                                    let _e2846 = local_169;
                                    let _e2849 = local_169;
                                    let _e2853 = local_168;
                                    phi_2400_ = array<f32, 3>((_e2843[0] * _e2842), (_e2846[1] * _e2842), (_e2849[2] * _e2842));
                                    phi_2401_ = ((0.5f * _e2853) * _e2842);
                                } else {
                                    phi_2400_ = array<f32, 3>(0f, 0f, 0f);
                                    phi_2401_ = _e2799;
                                }
                                let _e2857 = phi_2400_;
                                let _e2859 = phi_2401_;
                                local_213 = _e2857;
                                local_214 = _e2859;
                                let _e2860 = local_208;
                                if _e2860 {
                                    let _e2861 = local_167;
                                    let _e2862 = local_206;
                                    phi_2407_ = (_e2861 * _e2862);
                                } else {
                                    phi_2407_ = 1f;
                                }
                                let _e2865 = phi_2407_;
                                local_215 = _e2865;
                                let _e2866 = local_170;
                                let _e2868 = local_206;
                                let _e2870 = local_170;
                                let _e2872 = local_206;
                                let _e2875 = local_163;
                                local_216 = _e2875[3];
                                if (_e2875[3] > 0f) {
                                    let _e2880 = local_216;
                                    let _e2881 = (1f / _e2880);
                                    local_217 = _e2881;
                                    let _e2882 = local_163;
                                    let _e2884 = (_e2882[0] * _e2881);
                                    local_218 = _e2884;
                                    let _e2885 = local_163;
                                    let _e2887 = (_e2885[1] * _e2881);
                                    local_219 = _e2887;
                                    phi_2426_ = 0u;
                                    phi_2429_ = 0f;
                                    loop {
                                        let _e2890 = phi_2426_;
                                        let _e2892 = phi_2429_;
                                        local_220 = _e2890;
                                        local_221 = _e2892;
                                        let _e2893 = local_220;
                                        let _e2894 = (_e2893 < 4u);
                                        local_222 = _e2894;
                                        if _e2894 {
                                            let _e2895 = local_222;
                                            if _e2895 {
                                            } else {
                                                phi_6064_ = true;
                                                break;
                                            }
                                            let _e2896 = local_220;
                                            let _e2898 = local_536[_e2896];
                                            if (_e2898 > 0f) {
                                                let _e2900 = local_17;
                                                let _e2902 = local_220;
                                                let _e2907 = local_218;
                                                local_223 = ((f32(((2u * _e2900) + (_e2902 % 2u))) + 0.5f) - _e2907);
                                                let _e2909 = local_18;
                                                let _e2911 = local_220;
                                                let _e2916 = local_219;
                                                local_224 = ((f32(((2u * _e2909) + (_e2911 / 2u))) + 0.5f) - _e2916);
                                                let _e2918 = local_222;
                                                if _e2918 {
                                                } else {
                                                    phi_6064_ = true;
                                                    break;
                                                }
                                                let _e2919 = local_536[_e2896];
                                                let _e2920 = local_223;
                                                let _e2921 = local_223;
                                                let _e2923 = local_224;
                                                let _e2924 = local_224;
                                                let _e2929 = local_221;
                                                phi_2473_ = (_e2929 + (_e2919 * sqrt(((_e2920 * _e2921) + (_e2923 * _e2924)))));
                                            } else {
                                                phi_2473_ = _e2892;
                                            }
                                            let _e2932 = phi_2473_;
                                            let _e2933 = local_220;
                                            phi_2427_ = (_e2933 + 1u);
                                            phi_2430_ = _e2932;
                                        } else {
                                            phi_2427_ = u32();
                                            phi_2430_ = f32();
                                        }
                                        let _e2936 = phi_2427_;
                                        let _e2938 = phi_2430_;
                                        continue;
                                        continuing {
                                            let _e2939 = local_222;
                                            phi_2426_ = _e2936;
                                            phi_2429_ = _e2938;
                                            phi_6064_ = _e2791;
                                            break if !(_e2939);
                                        }
                                    }
                                    let _e2942 = phi_6064_;
                                    if _e2942 {
                                        break;
                                    }
                                    let _e2943 = local_163;
                                    let _e2945 = local_217;
                                    let _e2947 = local_221;
                                    let _e2948 = local_217;
                                    phi_6087_ = _e2942;
                                    phi_2479_ = (_e2943[2] * _e2945);
                                    phi_2480_ = (_e2947 * _e2948);
                                    phi_2481_ = array<f32, 2>(_e2884, _e2887);
                                } else {
                                    let _e2878 = local_207;
                                    phi_6087_ = _e2791;
                                    phi_2479_ = (2f * _e2878);
                                    phi_2480_ = 0f;
                                    phi_2481_ = array<f32, 2>((_e2866[0] * _e2868), (_e2870[1] * _e2872));
                                }
                                let _e2951 = phi_6087_;
                                let _e2953 = phi_2479_;
                                let _e2955 = phi_2480_;
                                let _e2957 = phi_2481_;
                                let _e2958 = local_213;
                                let _e2959 = local_215;
                                let _e2960 = local_214;
                                let _e2961 = local_212;
                                let _e2962 = local_503;
                                let _e2963 = local_171;
                                let _e2964 = local_164;
                                phi_6086_ = _e2951;
                                phi_2483_ = type_30(_e2957, _e2958, _e2959, _e2960, _e2961, _e2962, _e2963, _e2964, _e2953, _e2955);
                            }
                            let _e2970 = phi_6086_;
                            let _e2972 = phi_2483_;
                            local_225 = _e2972;
                            local_226 = _e2972.member_8;
                            if (_e2972.member_8 < 0f) {
                                let _e2979 = local_226;
                                let _e2981 = local_226;
                                phi_2499_ = select(-0.5f, _e2981, (_e2979 < -0.5f));
                            } else {
                                let _e2975 = local_226;
                                let _e2977 = local_226;
                                phi_2499_ = select(0.5f, _e2977, (_e2975 > 0.5f));
                            }
                            let _e2984 = phi_2499_;
                            local_227 = _e2984;
                            if (_e2984 < 0f) {
                                let _e2986 = local_227;
                                phi_2505_ = -(_e2986);
                            } else {
                                phi_2505_ = _e2984;
                            }
                            let _e2989 = phi_2505_;
                            let _e2990 = local_225;
                            phi_6082_ = _e2970;
                            phi_2508_ = (_e2989 + _e2990.member_9);
                        } else {
                            phi_6082_ = _e2186;
                            phi_2508_ = 0f;
                        }
                        let _e2994 = phi_6082_;
                        let _e2996 = phi_2508_;
                        let _e2997 = local_501;
                        phi_6081_ = _e2994;
                        phi_2510_ = select(0f, _e1489, (_e1489 > 0f));
                        phi_2511_ = _e2996;
                        phi_2512_ = select(0u, 1u, _e2997);
                    } else {
                        phi_6081_ = _e1480;
                        phi_2510_ = 0f;
                        phi_2511_ = 0f;
                        phi_2512_ = 0u;
                    }
                    let _e3000 = phi_6081_;
                    let _e3002 = phi_2510_;
                    let _e3004 = phi_2511_;
                    let _e3006 = phi_2512_;
                    phi_6080_ = _e3000;
                    phi_2513_ = _e3002;
                    phi_2514_ = _e3004;
                    phi_2515_ = _e3006;
                } else {
                    phi_6080_ = false;
                    phi_2513_ = 0f;
                    phi_2514_ = 0f;
                    phi_2515_ = 0u;
                }
                let _e3008 = phi_6080_;
                let _e3010 = phi_2513_;
                let _e3012 = phi_2514_;
                let _e3014 = phi_2515_;
                phi_6079_ = _e3008;
                phi_2516_ = _e3010;
                phi_2517_ = _e3012;
                phi_2518_ = _e3014;
            } else {
                phi_6079_ = false;
                phi_2516_ = 0f;
                phi_2517_ = 0f;
                phi_2518_ = 0u;
            }
            let _e3016 = phi_6079_;
            let _e3018 = phi_2516_;
            let _e3020 = phi_2517_;
            let _e3022 = phi_2518_;
            local_228 = _e3018;
            local_229 = _e3020;
            local_230 = _e3022;
            let _e3023 = local;
            if (_e3023 < 384u) {
            } else {
                break;
            }
            let _e3025 = local;
            let _e3027 = local_230;
            global_10[_e3025] = _e3027;
            let _e3028 = local_228;
            local_231 = bitcast<u32>(_e3028);
            let _e3030 = local;
            let _e3031 = (128u + _e3030);
            local_232 = _e3031;
            if (_e3031 < 384u) {
            } else {
                break;
            }
            let _e3033 = local_232;
            let _e3035 = local_231;
            global_10[_e3033] = _e3035;
            let _e3036 = local_229;
            local_233 = bitcast<u32>(_e3036);
            let _e3038 = local;
            let _e3039 = (256u + _e3038);
            local_234 = _e3039;
            if (_e3039 < 384u) {
            } else {
                break;
            }
            let _e3041 = local_234;
            let _e3043 = local_233;
            global_10[_e3041] = _e3043;
            storageBarrier();
            workgroupBarrier();
            phi_2680_ = 1u;
            phi_2683_ = 0u;
            loop {
                let _e3045 = phi_2680_;
                let _e3047 = phi_2683_;
                local_235 = _e3045;
                local_236 = _e3047;
                let _e3048 = local_235;
                let _e3049 = (_e3048 < 64u);
                local_237 = _e3049;
                if _e3049 {
                    let _e3050 = local_236;
                    let _e3052 = select(0u, 64u, (_e3050 == 0u));
                    local_504 = _e3052;
                    let _e3053 = local_236;
                    let _e3054 = local;
                    let _e3055 = (_e3053 + _e3054);
                    local_238 = _e3055;
                    if (_e3055 < 384u) {
                    } else {
                        phi_6073_ = true;
                        break;
                    }
                    let _e3057 = local_238;
                    let _e3059 = global_10[_e3057];
                    local_239 = _e3059;
                    let _e3060 = local;
                    let _e3061 = local_235;
                    if (_e3060 >= _e3061) {
                        let _e3063 = local;
                        let _e3064 = local_235;
                        let _e3066 = local_236;
                        let _e3067 = (_e3066 + (_e3063 - _e3064));
                        local_240 = _e3067;
                        if (_e3067 < 384u) {
                        } else {
                            phi_6073_ = true;
                            break;
                        }
                        let _e3069 = local_240;
                        let _e3071 = global_10[_e3069];
                        let _e3072 = local_239;
                        phi_2719_ = (_e3071 + _e3072);
                    } else {
                        phi_2719_ = _e3059;
                    }
                    let _e3075 = phi_2719_;
                    local_241 = _e3075;
                    let _e3076 = local_504;
                    let _e3077 = local;
                    let _e3078 = (_e3076 + _e3077);
                    local_242 = _e3078;
                    if (_e3078 < 384u) {
                    } else {
                        phi_6073_ = true;
                        break;
                    }
                    let _e3080 = local_242;
                    let _e3082 = local_241;
                    global_10[_e3080] = _e3082;
                    storageBarrier();
                    workgroupBarrier();
                    let _e3083 = local_235;
                    phi_2681_ = (_e3083 * 2u);
                    phi_2684_ = _e3052;
                } else {
                    phi_2681_ = u32();
                    phi_2684_ = u32();
                }
                let _e3086 = phi_2681_;
                let _e3088 = phi_2684_;
                continue;
                continuing {
                    let _e3089 = local_237;
                    phi_2680_ = _e3086;
                    phi_2683_ = _e3088;
                    phi_6073_ = _e3016;
                    break if !(_e3089);
                }
            }
            let _e3092 = phi_6073_;
            if _e3092 {
                break;
            }
            phi_2878_ = 1u;
            phi_2881_ = 128u;
            loop {
                let _e3094 = phi_2878_;
                let _e3096 = phi_2881_;
                local_243 = _e3094;
                local_244 = _e3096;
                let _e3097 = local_243;
                let _e3098 = (_e3097 < 64u);
                local_245 = _e3098;
                if _e3098 {
                    let _e3099 = local_244;
                    let _e3101 = select(128u, 192u, (_e3099 == 128u));
                    local_505 = _e3101;
                    let _e3102 = local_244;
                    let _e3103 = local;
                    let _e3104 = (_e3102 + _e3103);
                    local_246 = _e3104;
                    if (_e3104 < 384u) {
                    } else {
                        phi_6107_ = true;
                        break;
                    }
                    let _e3106 = local_246;
                    let _e3108 = global_10[_e3106];
                    local_247 = _e3108;
                    let _e3109 = local;
                    let _e3110 = local_243;
                    if (_e3109 >= _e3110) {
                        let _e3112 = local;
                        let _e3113 = local_243;
                        let _e3115 = local_244;
                        let _e3116 = (_e3115 + (_e3112 - _e3113));
                        local_248 = _e3116;
                        if (_e3116 < 384u) {
                        } else {
                            phi_6107_ = true;
                            break;
                        }
                        let _e3118 = local_248;
                        let _e3120 = global_10[_e3118];
                        let _e3121 = local_247;
                        let _e3123 = local_247;
                        phi_2921_ = select(_e3123, _e3120, (_e3120 > _e3121));
                    } else {
                        phi_2921_ = _e3108;
                    }
                    let _e3126 = phi_2921_;
                    local_249 = _e3126;
                    let _e3127 = local_505;
                    let _e3128 = local;
                    let _e3129 = (_e3127 + _e3128);
                    local_250 = _e3129;
                    if (_e3129 < 384u) {
                    } else {
                        phi_6107_ = true;
                        break;
                    }
                    let _e3131 = local_250;
                    let _e3133 = local_249;
                    global_10[_e3131] = _e3133;
                    storageBarrier();
                    workgroupBarrier();
                    let _e3134 = local_243;
                    phi_2879_ = (_e3134 * 2u);
                    phi_2882_ = _e3101;
                } else {
                    phi_2879_ = u32();
                    phi_2882_ = u32();
                }
                let _e3137 = phi_2879_;
                let _e3139 = phi_2882_;
                continue;
                continuing {
                    let _e3140 = local_245;
                    phi_2878_ = _e3137;
                    phi_2881_ = _e3139;
                    phi_6107_ = _e3092;
                    break if !(_e3140);
                }
            }
            let _e3143 = phi_6107_;
            if _e3143 {
                break;
            }
            phi_3080_ = 1u;
            phi_3083_ = 256u;
            loop {
                let _e3145 = phi_3080_;
                let _e3147 = phi_3083_;
                local_251 = _e3145;
                local_252 = _e3147;
                let _e3148 = local_251;
                let _e3149 = (_e3148 < 64u);
                local_253 = _e3149;
                if _e3149 {
                    let _e3150 = local_252;
                    let _e3152 = select(256u, 320u, (_e3150 == 256u));
                    local_506 = _e3152;
                    let _e3153 = local_252;
                    let _e3154 = local;
                    let _e3155 = (_e3153 + _e3154);
                    local_254 = _e3155;
                    if (_e3155 < 384u) {
                    } else {
                        phi_6134_ = true;
                        break;
                    }
                    let _e3157 = local_254;
                    let _e3159 = global_10[_e3157];
                    local_255 = _e3159;
                    let _e3160 = local;
                    let _e3161 = local_251;
                    if (_e3160 >= _e3161) {
                        let _e3163 = local;
                        let _e3164 = local_251;
                        let _e3166 = local_252;
                        let _e3167 = (_e3166 + (_e3163 - _e3164));
                        local_256 = _e3167;
                        if (_e3167 < 384u) {
                        } else {
                            phi_6134_ = true;
                            break;
                        }
                        let _e3169 = local_256;
                        let _e3171 = global_10[_e3169];
                        let _e3172 = local_255;
                        let _e3174 = local_255;
                        phi_3123_ = select(_e3174, _e3171, (_e3171 > _e3172));
                    } else {
                        phi_3123_ = _e3159;
                    }
                    let _e3177 = phi_3123_;
                    local_257 = _e3177;
                    let _e3178 = local_506;
                    let _e3179 = local;
                    let _e3180 = (_e3178 + _e3179);
                    local_258 = _e3180;
                    if (_e3180 < 384u) {
                    } else {
                        phi_6134_ = true;
                        break;
                    }
                    let _e3182 = local_258;
                    let _e3184 = local_257;
                    global_10[_e3182] = _e3184;
                    storageBarrier();
                    workgroupBarrier();
                    let _e3185 = local_251;
                    phi_3081_ = (_e3185 * 2u);
                    phi_3084_ = _e3152;
                } else {
                    phi_3081_ = u32();
                    phi_3084_ = u32();
                }
                let _e3188 = phi_3081_;
                let _e3190 = phi_3084_;
                continue;
                continuing {
                    let _e3191 = local_253;
                    phi_3080_ = _e3188;
                    phi_3083_ = _e3190;
                    phi_6134_ = _e3143;
                    break if !(_e3191);
                }
            }
            let _e3194 = phi_6134_;
            if _e3194 {
                break;
            }
            let _e3195 = local_12;
            if _e3195 {
                let _e3196 = local_11;
                phi_3156_ = (_e3196 + 1u);
            } else {
                phi_3156_ = _e636;
            }
            let _e3199 = phi_3156_;
            let _e3200 = (_e3199 / 8u);
            local_259 = _e3200;
            if ((_e3199 % 8u) > 0u) {
                let _e3203 = local_259;
                phi_3172_ = (_e3203 + 1u);
            } else {
                phi_3172_ = _e3200;
            }
            let _e3206 = phi_3172_;
            let _e3207 = local_9;
            let _e3209 = local_8;
            local_260 = (66u * ((_e3207 * _e3206) + _e3209));
            let _e3212 = local_236;
            let _e3213 = local;
            let _e3214 = (_e3212 + _e3213);
            local_261 = _e3214;
            if (_e3214 < 384u) {
            } else {
                break;
            }
            let _e3216 = local_261;
            let _e3218 = global_10[_e3216];
            local_262 = _e3218;
            let _e3219 = local;
            if (_e3219 == 0u) {
                phi_3198_ = _e3218;
            } else {
                let _e3221 = local_261;
                let _e3222 = (_e3221 - 1u);
                local_263 = _e3222;
                if (_e3222 < 384u) {
                } else {
                    break;
                }
                let _e3224 = local_263;
                let _e3226 = global_10[_e3224];
                let _e3227 = local_262;
                phi_3198_ = (_e3227 - _e3226);
            }
            let _e3230 = phi_3198_;
            if (_e3230 == 1u) {
                let _e3232 = local_262;
                if (_e3232 <= 8u) {
                    phi_6200_ = _e3194;
                    phi_3214_ = 0u;
                    phi_3217_ = 0u;
                    phi_3219_ = array<f32, 3>(0f, 0f, 0f);
                    phi_3221_ = 340282350000000000000000000000000000000f;
                    loop {
                        let _e3235 = phi_6200_;
                        let _e3237 = phi_3214_;
                        let _e3239 = phi_3217_;
                        let _e3241 = phi_3219_;
                        let _e3243 = phi_3221_;
                        local_264 = _e3237;
                        local_265 = _e3239;
                        local_266 = _e3241;
                        local_267 = _e3243;
                        let _e3244 = local_264;
                        let _e3245 = (_e3244 < 2u);
                        local_268 = _e3245;
                        if _e3245 {
                            let _e3246 = local_267;
                            let _e3248 = local_267;
                            local_269 = (4f * select(0.25f, _e3248, (_e3246 > 0.25f)));
                            phi_3236_ = 0u;
                            phi_3239_ = _e3239;
                            phi_3241_ = _e3241;
                            phi_3243_ = _e3243;
                            loop {
                                let _e3252 = phi_3236_;
                                let _e3254 = phi_3239_;
                                let _e3256 = phi_3241_;
                                let _e3258 = phi_3243_;
                                local_270 = _e3252;
                                local_271 = _e3254;
                                local_272 = _e3256;
                                local_273 = _e3258;
                                local_545 = _e3254;
                                local_546 = _e3256;
                                local_547 = _e3258;
                                let _e3259 = local_270;
                                let _e3260 = (_e3259 < 16u);
                                local_274 = _e3260;
                                if _e3260 {
                                    let _e3261 = local_270;
                                    let _e3262 = (_e3261 % 4u);
                                    local_275 = _e3262;
                                    let _e3263 = local_270;
                                    local_276 = (_e3263 / 4u);
                                    if (_e3262 == 1u) {
                                        phi_3273_ = i32();
                                        phi_3274_ = i32();
                                        phi_3275_ = true;
                                    } else {
                                        let _e3266 = local_275;
                                        let _e3267 = (_e3266 == 2u);
                                        if _e3267 {
                                            phi_3271_ = i32();
                                            phi_3272_ = i32();
                                        } else {
                                            let _e3268 = local_17;
                                            let _e3272 = local_275;
                                            let _e3275 = local_18;
                                            let _e3279 = local_276;
                                            phi_3271_ = (((2i * bitcast<i32>(_e3275)) - 1i) + bitcast<i32>(_e3279));
                                            phi_3272_ = (((2i * bitcast<i32>(_e3268)) - 1i) + bitcast<i32>(_e3272));
                                        }
                                        let _e3283 = phi_3271_;
                                        let _e3285 = phi_3272_;
                                        phi_3273_ = _e3283;
                                        phi_3274_ = _e3285;
                                        phi_3275_ = _e3267;
                                    }
                                    let _e3287 = phi_3273_;
                                    let _e3289 = phi_3274_;
                                    let _e3291 = phi_3275_;
                                    if _e3291 {
                                        let _e3292 = local_276;
                                        if (_e3292 == 1u) {
                                            phi_3298_ = i32();
                                            phi_3299_ = i32();
                                            phi_3300_ = false;
                                        } else {
                                            let _e3294 = local_276;
                                            let _e3296 = local_17;
                                            let _e3300 = local_275;
                                            let _e3303 = local_18;
                                            let _e3307 = local_276;
                                            phi_3298_ = (((2i * bitcast<i32>(_e3303)) - 1i) + bitcast<i32>(_e3307));
                                            phi_3299_ = (((2i * bitcast<i32>(_e3296)) - 1i) + bitcast<i32>(_e3300));
                                            phi_3300_ = select(true, false, (_e3294 == 2u));
                                        }
                                        let _e3312 = phi_3298_;
                                        let _e3314 = phi_3299_;
                                        let _e3316 = phi_3300_;
                                        phi_3301_ = _e3312;
                                        phi_3302_ = _e3314;
                                        phi_3303_ = _e3316;
                                    } else {
                                        phi_3301_ = _e3287;
                                        phi_3302_ = _e3289;
                                        phi_3303_ = true;
                                    }
                                    let _e3318 = phi_3301_;
                                    let _e3320 = phi_3302_;
                                    let _e3322 = phi_3303_;
                                    local_277 = _e3318;
                                    local_278 = _e3320;
                                    if _e3322 {
                                        let _e3323 = local_278;
                                        if (_e3323 >= 0i) {
                                            let _e3325 = local_277;
                                            if (_e3325 >= 0i) {
                                                let _e3327 = local_278;
                                                let _e3328 = bitcast<u32>(_e3327);
                                                local_279 = _e3328;
                                                let _e3329 = local_10;
                                                if (_e3328 < _e3329) {
                                                    let _e3331 = local_277;
                                                    let _e3332 = bitcast<u32>(_e3331);
                                                    local_280 = _e3332;
                                                    let _e3333 = local_14;
                                                    if (_e3332 < _e3333) {
                                                        let _e3335 = local_280;
                                                        let _e3336 = local_10;
                                                        let _e3338 = local_279;
                                                        let _e3339 = ((_e3335 * _e3336) + _e3338);
                                                        local_281 = _e3339;
                                                        let _e3340 = (3u * _e3339);
                                                        local_282 = _e3340;
                                                        let _e3341 = local_1;
                                                        if (_e3340 < _e3341) {
                                                        } else {
                                                            phi_6161_ = true;
                                                            break;
                                                        }
                                                        let _e3343 = local_282;
                                                        let _e3346 = global_4.member[_e3343];
                                                        local_283 = bitcast<f32>(_e3346);
                                                        let _e3348 = local_282;
                                                        let _e3349 = (_e3348 + 1u);
                                                        local_284 = _e3349;
                                                        let _e3350 = local_1;
                                                        if (_e3349 < _e3350) {
                                                        } else {
                                                            phi_6161_ = true;
                                                            break;
                                                        }
                                                        let _e3352 = local_284;
                                                        let _e3355 = global_4.member[_e3352];
                                                        local_285 = bitcast<f32>(_e3355);
                                                        let _e3357 = local_282;
                                                        let _e3358 = (_e3357 + 2u);
                                                        local_286 = _e3358;
                                                        let _e3359 = local_1;
                                                        if (_e3358 < _e3359) {
                                                        } else {
                                                            phi_6161_ = true;
                                                            break;
                                                        }
                                                        let _e3361 = local_286;
                                                        let _e3364 = global_4.member[_e3361];
                                                        local_287 = bitcast<f32>(_e3364);
                                                        let _e3366 = local_283;
                                                        if (_e3366 > 1267650600000000000000000000000f) {
                                                            let _e3368 = local_283;
                                                            phi_3373_ = select(true, false, (_e3368 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_3373_ = true;
                                                        }
                                                        let _e3372 = phi_3373_;
                                                        if _e3372 {
                                                            let _e3373 = local_283;
                                                            if (_e3373 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e3375 = local_283;
                                                                phi_3387_ = select(true, false, (_e3375 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_3387_ = true;
                                                            }
                                                            let _e3379 = phi_3387_;
                                                            let _e3380 = local_283;
                                                            phi_3392_ = select(0f, _e3380, _e3379);
                                                        } else {
                                                            phi_3392_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e3383 = phi_3392_;
                                                        local_288 = _e3383;
                                                        let _e3384 = local_285;
                                                        if (_e3384 > 1267650600000000000000000000000f) {
                                                            let _e3386 = local_285;
                                                            phi_3402_ = select(true, false, (_e3386 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_3402_ = true;
                                                        }
                                                        let _e3390 = phi_3402_;
                                                        if _e3390 {
                                                            let _e3391 = local_285;
                                                            if (_e3391 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e3393 = local_285;
                                                                phi_3416_ = select(true, false, (_e3393 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_3416_ = true;
                                                            }
                                                            let _e3397 = phi_3416_;
                                                            let _e3398 = local_285;
                                                            phi_3421_ = select(0f, _e3398, _e3397);
                                                        } else {
                                                            phi_3421_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e3401 = phi_3421_;
                                                        local_289 = _e3401;
                                                        let _e3402 = local_287;
                                                        if (_e3402 > 1267650600000000000000000000000f) {
                                                            let _e3404 = local_287;
                                                            phi_3431_ = select(true, false, (_e3404 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_3431_ = true;
                                                        }
                                                        let _e3408 = phi_3431_;
                                                        if _e3408 {
                                                            let _e3409 = local_287;
                                                            if (_e3409 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e3411 = local_287;
                                                                phi_3445_ = select(true, false, (_e3411 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_3445_ = true;
                                                            }
                                                            let _e3415 = phi_3445_;
                                                            let _e3416 = local_287;
                                                            phi_3450_ = select(0f, _e3416, _e3415);
                                                        } else {
                                                            phi_3450_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e3419 = phi_3450_;
                                                        local_290 = _e3419;
                                                        let _e3420 = local_288;
                                                        let _e3421 = local_289;
                                                        local_291 = array<f32, 3>(_e3420, _e3421, _e3419);
                                                        let _e3423 = local_281;
                                                        let _e3424 = local_2;
                                                        if (_e3423 < _e3424) {
                                                        } else {
                                                            phi_6161_ = true;
                                                            break;
                                                        }
                                                        let _e3426 = local_281;
                                                        let _e3429 = global_3.member[_e3426];
                                                        local_292 = bitcast<f32>(_e3429);
                                                        let _e3431 = local_288;
                                                        if ((bitcast<u32>(_e3431) & 2139095040u) != 2139095040u) {
                                                            let _e3435 = local_289;
                                                            if ((bitcast<u32>(_e3435) & 2139095040u) != 2139095040u) {
                                                                let _e3439 = local_290;
                                                                if ((bitcast<u32>(_e3439) & 2139095040u) != 2139095040u) {
                                                                    let _e3443 = local_292;
                                                                    let _e3444 = bitcast<u32>(_e3443);
                                                                    local_293 = _e3444;
                                                                    if (_e3444 == 0u) {
                                                                        phi_3484_ = false;
                                                                    } else {
                                                                        let _e3446 = local_293;
                                                                        phi_3484_ = (_e3446 <= 2139095040u);
                                                                    }
                                                                    let _e3449 = phi_3484_;
                                                                    local_294 = _e3449;
                                                                    if _e3449 {
                                                                        let _e3450 = local_291;
                                                                        let _e3451 = local_292;
                                                                        phi_3490_ = type_23(1u, type_22(_e3450, _e3451));
                                                                    } else {
                                                                        phi_3490_ = type_23();
                                                                    }
                                                                    let _e3455 = phi_3490_;
                                                                    let _e3456 = local_294;
                                                                    phi_3492_ = _e3455;
                                                                    phi_3493_ = select(true, false, _e3456);
                                                                } else {
                                                                    phi_3492_ = type_23();
                                                                    phi_3493_ = true;
                                                                }
                                                                let _e3459 = phi_3492_;
                                                                let _e3461 = phi_3493_;
                                                                phi_3494_ = _e3459;
                                                                phi_3495_ = _e3461;
                                                            } else {
                                                                phi_3494_ = type_23();
                                                                phi_3495_ = true;
                                                            }
                                                            let _e3463 = phi_3494_;
                                                            let _e3465 = phi_3495_;
                                                            phi_3496_ = _e3463;
                                                            phi_3497_ = _e3465;
                                                        } else {
                                                            phi_3496_ = type_23();
                                                            phi_3497_ = true;
                                                        }
                                                        let _e3467 = phi_3496_;
                                                        let _e3469 = phi_3497_;
                                                        if _e3469 {
                                                            phi_3502_ = type_23(0u, type_23().member_1);
                                                        } else {
                                                            phi_3502_ = _e3467;
                                                        }
                                                        let _e3474 = phi_3502_;
                                                        local_295 = _e3474;
                                                        if (bitcast<i32>(_e3474.member) != 0i) {
                                                            let _e3478 = local_295;
                                                            local_296 = _e3478.member_1.member[0];
                                                            local_297 = _e3478.member_1.member[1];
                                                            local_298 = _e3478.member_1.member[2];
                                                            local_299 = (((0.2126f * _e3478.member_1.member[0]) + (0.7152f * _e3478.member_1.member[1])) + (0.0722f * _e3478.member_1.member[2]));
                                                            let _e3489 = local_264;
                                                            if (_e3489 == 0u) {
                                                                let _e3513 = local_273;
                                                                let _e3514 = local_299;
                                                                let _e3516 = local_273;
                                                                let _e3517 = local_299;
                                                                phi_3544_ = _e3254;
                                                                phi_3545_ = _e3256;
                                                                phi_3546_ = select(_e3517, _e3516, (_e3513 < _e3514));
                                                            } else {
                                                                let _e3491 = local_299;
                                                                let _e3492 = local_269;
                                                                if (_e3491 <= _e3492) {
                                                                    let _e3494 = local_272;
                                                                    let _e3496 = local_296;
                                                                    let _e3498 = local_272;
                                                                    let _e3500 = local_297;
                                                                    let _e3502 = local_272;
                                                                    let _e3504 = local_298;
                                                                    let _e3507 = local_271;
                                                                    phi_3542_ = (_e3507 + 1u);
                                                                    phi_3543_ = array<f32, 3>((_e3494[0] + _e3496), (_e3498[1] + _e3500), (_e3502[2] + _e3504));
                                                                } else {
                                                                    phi_3542_ = _e3254;
                                                                    phi_3543_ = _e3256;
                                                                }
                                                                let _e3510 = phi_3542_;
                                                                let _e3512 = phi_3543_;
                                                                phi_3544_ = _e3510;
                                                                phi_3545_ = _e3512;
                                                                phi_3546_ = _e3258;
                                                            }
                                                            let _e3520 = phi_3544_;
                                                            let _e3522 = phi_3545_;
                                                            let _e3524 = phi_3546_;
                                                            phi_3547_ = _e3520;
                                                            phi_3548_ = _e3522;
                                                            phi_3549_ = _e3524;
                                                        } else {
                                                            phi_3547_ = _e3254;
                                                            phi_3548_ = _e3256;
                                                            phi_3549_ = _e3258;
                                                        }
                                                        let _e3526 = phi_3547_;
                                                        let _e3528 = phi_3548_;
                                                        let _e3530 = phi_3549_;
                                                        phi_3550_ = _e3526;
                                                        phi_3551_ = _e3528;
                                                        phi_3552_ = _e3530;
                                                    } else {
                                                        phi_3550_ = _e3254;
                                                        phi_3551_ = _e3256;
                                                        phi_3552_ = _e3258;
                                                    }
                                                    let _e3532 = phi_3550_;
                                                    let _e3534 = phi_3551_;
                                                    let _e3536 = phi_3552_;
                                                    phi_3553_ = _e3532;
                                                    phi_3554_ = _e3534;
                                                    phi_3555_ = _e3536;
                                                } else {
                                                    phi_3553_ = _e3254;
                                                    phi_3554_ = _e3256;
                                                    phi_3555_ = _e3258;
                                                }
                                                let _e3538 = phi_3553_;
                                                let _e3540 = phi_3554_;
                                                let _e3542 = phi_3555_;
                                                phi_3556_ = _e3538;
                                                phi_3557_ = _e3540;
                                                phi_3558_ = _e3542;
                                            } else {
                                                phi_3556_ = _e3254;
                                                phi_3557_ = _e3256;
                                                phi_3558_ = _e3258;
                                            }
                                            let _e3544 = phi_3556_;
                                            let _e3546 = phi_3557_;
                                            let _e3548 = phi_3558_;
                                            phi_3559_ = _e3544;
                                            phi_3560_ = _e3546;
                                            phi_3561_ = _e3548;
                                        } else {
                                            phi_3559_ = _e3254;
                                            phi_3560_ = _e3256;
                                            phi_3561_ = _e3258;
                                        }
                                        let _e3550 = phi_3559_;
                                        let _e3552 = phi_3560_;
                                        let _e3554 = phi_3561_;
                                        phi_3562_ = _e3550;
                                        phi_3563_ = _e3552;
                                        phi_3564_ = _e3554;
                                    } else {
                                        phi_3562_ = _e3254;
                                        phi_3563_ = _e3256;
                                        phi_3564_ = _e3258;
                                    }
                                    let _e3556 = phi_3562_;
                                    let _e3558 = phi_3563_;
                                    let _e3560 = phi_3564_;
                                    let _e3561 = local_270;
                                    phi_3237_ = (_e3561 + 1u);
                                    phi_3240_ = _e3556;
                                    phi_3242_ = _e3558;
                                    phi_3244_ = _e3560;
                                } else {
                                    phi_3237_ = u32();
                                    phi_3240_ = u32();
                                    phi_3242_ = array<f32, 3>();
                                    phi_3244_ = f32();
                                }
                                let _e3564 = phi_3237_;
                                let _e3566 = phi_3240_;
                                let _e3568 = phi_3242_;
                                let _e3570 = phi_3244_;
                                continue;
                                continuing {
                                    let _e3571 = local_274;
                                    phi_3236_ = _e3564;
                                    phi_3239_ = _e3566;
                                    phi_3241_ = _e3568;
                                    phi_3243_ = _e3570;
                                    phi_6161_ = _e3235;
                                    break if !(_e3571);
                                }
                            }
                            let _e3574 = phi_6161_;
                            phi_6208_ = _e3574;
                            if _e3574 {
                                break;
                            }
                            let _e3575 = local_264;
                            phi_6209_ = _e3574;
                            phi_3215_ = (_e3575 + 1u);
                            let _e5863 = local_545;
                            phi_3218_ = _e5863;
                            let _e5866 = local_546;
                            phi_3220_ = _e5866;
                            let _e5869 = local_547;
                            phi_3222_ = _e5869;
                        } else {
                            phi_6209_ = _e3235;
                            phi_3215_ = u32();
                            phi_3218_ = u32();
                            phi_3220_ = array<f32, 3>();
                            phi_3222_ = f32();
                        }
                        let _e3578 = phi_6209_;
                        let _e3580 = phi_3215_;
                        let _e3582 = phi_3218_;
                        let _e3584 = phi_3220_;
                        let _e3586 = phi_3222_;
                        continue;
                        continuing {
                            let _e3587 = local_268;
                            phi_6200_ = _e3578;
                            phi_3214_ = _e3580;
                            phi_3217_ = _e3582;
                            phi_3219_ = _e3584;
                            phi_3221_ = _e3586;
                            phi_6208_ = _e3578;
                            break if !(_e3587);
                        }
                    }
                    let _e3590 = phi_6208_;
                    if _e3590 {
                        break;
                    }
                    let _e3591 = local_265;
                    if (_e3591 == 0u) {
                        local_519 = array<f32, 4>(0f, 0f, 0f, 0f);
                        phi_6433_ = _e3590;
                        phi_6353_ = 0f;
                        phi_6305_ = 0f;
                        phi_6257_ = 0f;
                    } else {
                        let _e3593 = local_265;
                        let _e3595 = (1f / f32(_e3593));
                        let _e3596 = local_266;
                        let _e3598 = (_e3596[0] * _e3595);
                        local_300 = _e3598;
                        let _e3599 = local_266;
                        let _e3601 = (_e3599[1] * _e3595);
                        local_301 = _e3601;
                        let _e3602 = local_266;
                        let _e3604 = (_e3602[2] * _e3595);
                        local_302 = _e3604;
                        local_303 = (((0.2126f * _e3598) + (0.7152f * _e3601)) + (0.0722f * _e3604));
                        local_519 = array<f32, 4>(0f, 0f, 0f, 0f);
                        phi_3592_ = 0u;
                        loop {
                            let _e3611 = phi_3592_;
                            local_304 = _e3611;
                            let _e3612 = local_304;
                            let _e3613 = (_e3612 < 4u);
                            local_305 = _e3613;
                            if _e3613 {
                                let _e3614 = local_17;
                                let _e3616 = local_304;
                                let _e3618 = ((2u * _e3614) + (_e3616 % 2u));
                                local_306 = _e3618;
                                let _e3619 = local_18;
                                let _e3621 = local_304;
                                local_307 = ((2u * _e3619) + (_e3621 / 2u));
                                let _e3624 = local_10;
                                if (_e3618 < _e3624) {
                                    let _e3626 = local_307;
                                    let _e3627 = local_14;
                                    if (_e3626 < _e3627) {
                                        let _e3629 = local_307;
                                        let _e3630 = local_10;
                                        let _e3632 = local_306;
                                        let _e3633 = ((_e3629 * _e3630) + _e3632);
                                        local_308 = _e3633;
                                        let _e3634 = (3u * _e3633);
                                        local_309 = _e3634;
                                        let _e3635 = local_1;
                                        if (_e3634 < _e3635) {
                                        } else {
                                            phi_6210_ = true;
                                            break;
                                        }
                                        let _e3637 = local_309;
                                        let _e3640 = global_4.member[_e3637];
                                        local_310 = bitcast<f32>(_e3640);
                                        let _e3642 = local_309;
                                        let _e3643 = (_e3642 + 1u);
                                        local_311 = _e3643;
                                        let _e3644 = local_1;
                                        if (_e3643 < _e3644) {
                                        } else {
                                            phi_6210_ = true;
                                            break;
                                        }
                                        let _e3646 = local_311;
                                        let _e3649 = global_4.member[_e3646];
                                        local_312 = bitcast<f32>(_e3649);
                                        let _e3651 = local_309;
                                        let _e3652 = (_e3651 + 2u);
                                        local_313 = _e3652;
                                        let _e3653 = local_1;
                                        if (_e3652 < _e3653) {
                                        } else {
                                            phi_6210_ = true;
                                            break;
                                        }
                                        let _e3655 = local_313;
                                        let _e3658 = global_4.member[_e3655];
                                        local_314 = bitcast<f32>(_e3658);
                                        let _e3660 = local_310;
                                        if (_e3660 > 1267650600000000000000000000000f) {
                                            let _e3662 = local_310;
                                            phi_3661_ = select(true, false, (_e3662 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_3661_ = true;
                                        }
                                        let _e3666 = phi_3661_;
                                        if _e3666 {
                                            let _e3667 = local_310;
                                            if (_e3667 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e3669 = local_310;
                                                phi_3675_ = select(true, false, (_e3669 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_3675_ = true;
                                            }
                                            let _e3673 = phi_3675_;
                                            let _e3674 = local_310;
                                            phi_3680_ = select(0f, _e3674, _e3673);
                                        } else {
                                            phi_3680_ = 1267650600000000000000000000000f;
                                        }
                                        let _e3677 = phi_3680_;
                                        local_315 = _e3677;
                                        let _e3678 = local_312;
                                        if (_e3678 > 1267650600000000000000000000000f) {
                                            let _e3680 = local_312;
                                            phi_3690_ = select(true, false, (_e3680 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_3690_ = true;
                                        }
                                        let _e3684 = phi_3690_;
                                        if _e3684 {
                                            let _e3685 = local_312;
                                            if (_e3685 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e3687 = local_312;
                                                phi_3704_ = select(true, false, (_e3687 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_3704_ = true;
                                            }
                                            let _e3691 = phi_3704_;
                                            let _e3692 = local_312;
                                            phi_3709_ = select(0f, _e3692, _e3691);
                                        } else {
                                            phi_3709_ = 1267650600000000000000000000000f;
                                        }
                                        let _e3695 = phi_3709_;
                                        local_316 = _e3695;
                                        let _e3696 = local_314;
                                        if (_e3696 > 1267650600000000000000000000000f) {
                                            let _e3698 = local_314;
                                            phi_3719_ = select(true, false, (_e3698 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_3719_ = true;
                                        }
                                        let _e3702 = phi_3719_;
                                        if _e3702 {
                                            let _e3703 = local_314;
                                            if (_e3703 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e3705 = local_314;
                                                phi_3733_ = select(true, false, (_e3705 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_3733_ = true;
                                            }
                                            let _e3709 = phi_3733_;
                                            let _e3710 = local_314;
                                            phi_3738_ = select(0f, _e3710, _e3709);
                                        } else {
                                            phi_3738_ = 1267650600000000000000000000000f;
                                        }
                                        let _e3713 = phi_3738_;
                                        local_317 = _e3713;
                                        let _e3714 = local_315;
                                        let _e3715 = local_316;
                                        local_318 = array<f32, 3>(_e3714, _e3715, _e3713);
                                        let _e3717 = local_308;
                                        let _e3718 = local_2;
                                        if (_e3717 < _e3718) {
                                        } else {
                                            phi_6210_ = true;
                                            break;
                                        }
                                        let _e3720 = local_308;
                                        let _e3723 = global_3.member[_e3720];
                                        local_319 = bitcast<f32>(_e3723);
                                        let _e3725 = local_315;
                                        if ((bitcast<u32>(_e3725) & 2139095040u) != 2139095040u) {
                                            let _e3729 = local_316;
                                            if ((bitcast<u32>(_e3729) & 2139095040u) != 2139095040u) {
                                                let _e3733 = local_317;
                                                if ((bitcast<u32>(_e3733) & 2139095040u) != 2139095040u) {
                                                    let _e3737 = local_319;
                                                    let _e3738 = bitcast<u32>(_e3737);
                                                    local_320 = _e3738;
                                                    if (_e3738 == 0u) {
                                                        phi_3772_ = false;
                                                    } else {
                                                        let _e3740 = local_320;
                                                        phi_3772_ = (_e3740 <= 2139095040u);
                                                    }
                                                    let _e3743 = phi_3772_;
                                                    local_321 = _e3743;
                                                    if _e3743 {
                                                        let _e3744 = local_318;
                                                        let _e3745 = local_319;
                                                        phi_3778_ = type_23(1u, type_22(_e3744, _e3745));
                                                    } else {
                                                        phi_3778_ = type_23();
                                                    }
                                                    let _e3749 = phi_3778_;
                                                    let _e3750 = local_321;
                                                    phi_3780_ = _e3749;
                                                    phi_3781_ = select(true, false, _e3750);
                                                } else {
                                                    phi_3780_ = type_23();
                                                    phi_3781_ = true;
                                                }
                                                let _e3753 = phi_3780_;
                                                let _e3755 = phi_3781_;
                                                phi_3782_ = _e3753;
                                                phi_3783_ = _e3755;
                                            } else {
                                                phi_3782_ = type_23();
                                                phi_3783_ = true;
                                            }
                                            let _e3757 = phi_3782_;
                                            let _e3759 = phi_3783_;
                                            phi_3784_ = _e3757;
                                            phi_3785_ = _e3759;
                                        } else {
                                            phi_3784_ = type_23();
                                            phi_3785_ = true;
                                        }
                                        let _e3761 = phi_3784_;
                                        let _e3763 = phi_3785_;
                                        if _e3763 {
                                            phi_3790_ = type_23(0u, type_23().member_1);
                                        } else {
                                            phi_3790_ = _e3761;
                                        }
                                        let _e3768 = phi_3790_;
                                        local_322 = _e3768;
                                        if (bitcast<i32>(_e3768.member) != 0i) {
                                            let _e3772 = local_322;
                                            local_323 = _e3772.member_1.member;
                                            let _e3775 = local_322;
                                            local_324 = _e3775.member_1.member_1;
                                            let _e3780 = global_2.member.member_3;
                                            local_325 = f32(_e3780);
                                            let _e3782 = bitcast<u32>(_e3775.member_1.member_1);
                                            local_326 = _e3782;
                                            if (_e3782 == 2139095040u) {
                                                let _e3826 = global_2.member.member_4.member_1;
                                                let _e3831 = global_2.member.member_4.member;
                                                let _e3836 = global_2.member.member_4.member_2;
                                                let _e3842 = global_2.member.member_4.member_3;
                                                phi_3861_ = (0.5f * ((((2f * _e3826) * _e3831) / (_e3836 - _e3831)) * _e3842));
                                            } else {
                                                let _e3784 = local_326;
                                                if (_e3784 == 0u) {
                                                    phi_3830_ = false;
                                                } else {
                                                    let _e3786 = local_326;
                                                    phi_3830_ = (_e3786 <= 2139095040u);
                                                }
                                                let _e3789 = phi_3830_;
                                                if _e3789 {
                                                    let _e3793 = global_2.member.member_4.member_1;
                                                    let _e3798 = global_2.member.member_4.member;
                                                    let _e3803 = global_2.member.member_4.member_2;
                                                    local_327 = _e3803;
                                                    let _e3809 = global_2.member.member_4.member_3;
                                                    let _e3810 = ((((2f * _e3793) * _e3798) / (_e3803 - _e3798)) * _e3809);
                                                    local_328 = _e3810;
                                                    if (_e3810 == 0f) {
                                                        phi_3858_ = 0f;
                                                    } else {
                                                        let _e3812 = local_327;
                                                        let _e3813 = local_324;
                                                        let _e3816 = local_328;
                                                        phi_3858_ = (_e3816 * (1f - (_e3812 / _e3813)));
                                                    }
                                                    let _e3819 = phi_3858_;
                                                    phi_3859_ = _e3819;
                                                } else {
                                                    phi_3859_ = _e613;
                                                }
                                                let _e3821 = phi_3859_;
                                                phi_3861_ = (0.5f * _e3821);
                                            }
                                            let _e3846 = phi_3861_;
                                            let _e3847 = local_325;
                                            let _e3849 = local_325;
                                            let _e3850 = select(_e3849, _e3846, (_e3846 < _e3847));
                                            let _e3851 = local_325;
                                            let _e3852 = -(_e3851);
                                            let _e3854 = select(_e3852, _e3850, (_e3850 > _e3852));
                                            local_507 = _e3854;
                                            if (_e3854 < 0f) {
                                                let _e3856 = local_507;
                                                phi_3878_ = -(_e3856);
                                            } else {
                                                phi_3878_ = _e3854;
                                            }
                                            let _e3859 = phi_3878_;
                                            let _e3861 = ((_e3859 - 0.25f) * 4f);
                                            let _e3863 = select(0f, _e3861, (_e3861 > 0f));
                                            local_508 = select(1f, _e3863, (_e3863 < 1f));
                                            let _e3866 = local_323;
                                            let _e3868 = local_300;
                                            let _e3869 = (_e3866[0] - _e3868);
                                            let _e3872 = local_323;
                                            let _e3874 = local_301;
                                            let _e3875 = (_e3872[1] - _e3874);
                                            let _e3878 = local_323;
                                            let _e3880 = local_302;
                                            let _e3881 = (_e3878[2] - _e3880);
                                            let _e3888 = (((0.2126f * _e3866[0]) + (0.7152f * _e3872[1])) + (0.0722f * _e3878[2]));
                                            local_329 = _e3888;
                                            local_330 = (((0.2126f * select(0f, _e3869, (_e3869 > 0f))) + (0.7152f * select(0f, _e3875, (_e3875 > 0f)))) + (0.0722f * select(0f, _e3881, (_e3881 > 0f))));
                                            let _e3894 = local_303;
                                            if (_e3888 >= (8f * _e3894)) {
                                                phi_3945_ = 1f;
                                            } else {
                                                let _e3897 = local_303;
                                                let _e3898 = (4f * _e3897);
                                                let _e3899 = local_329;
                                                let _e3901 = ((_e3899 - _e3898) / _e3898);
                                                let _e3903 = select(0f, _e3901, (_e3901 > 0f));
                                                phi_3945_ = select(1f, _e3903, (_e3903 < 1f));
                                            }
                                            let _e3907 = phi_3945_;
                                            let _e3908 = local_330;
                                            let _e3910 = ((_e3908 - 0.25f) * 4f);
                                            let _e3912 = select(0f, _e3910, (_e3910 > 0f));
                                            local_509 = select(1f, _e3912, (_e3912 < 1f));
                                            let _e3915 = local_508;
                                            local_331 = (_e3915 * _e3907);
                                            let _e3917 = local_305;
                                            if _e3917 {
                                            } else {
                                                phi_6210_ = true;
                                                break;
                                            }
                                            let _e3918 = local_304;
                                            let _e3920 = local_331;
                                            let _e3921 = local_509;
                                            local_519[_e3918] = (_e3920 * _e3921);
                                        }
                                    }
                                }
                                let _e3923 = local_304;
                                phi_3593_ = (_e3923 + 1u);
                            } else {
                                phi_3593_ = u32();
                            }
                            let _e3926 = phi_3593_;
                            continue;
                            continuing {
                                let _e3927 = local_305;
                                phi_3592_ = _e3926;
                                phi_6210_ = _e3590;
                                break if !(_e3927);
                            }
                        }
                        let _e3930 = phi_6210_;
                        if _e3930 {
                            break;
                        }
                        phi_6433_ = _e3930;
                        phi_6353_ = _e3598;
                        phi_6305_ = _e3601;
                        phi_6257_ = _e3604;
                    }
                    let _e3932 = phi_6433_;
                    let _e3934 = phi_6353_;
                    let _e3936 = phi_6305_;
                    let _e3938 = phi_6257_;
                    local_495 = _e3934;
                    local_494 = _e3936;
                    local_493 = _e3938;
                    let _e3939 = local_519;
                    local_488 = _e3939;
                    let _e3949 = global_2.member.member_3;
                    local_332 = f32(_e3949);
                    local_532 = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_6432_ = _e3932;
                    phi_3984_ = 0u;
                    phi_3987_ = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_3989_ = array<f32, 3>(0f, 0f, 0f);
                    phi_3991_ = 0f;
                    phi_3993_ = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_3995_ = 0f;
                    phi_3997_ = 0f;
                    phi_3999_ = array<f32, 3>(0f, 0f, 0f);
                    phi_4001_ = array<f32, 2>(0f, 0f);
                    phi_4003_ = 0u;
                    phi_4005_ = 0f;
                    loop {
                        let _e3952 = phi_6432_;
                        let _e3954 = phi_3984_;
                        let _e3956 = phi_3987_;
                        let _e3958 = phi_3989_;
                        let _e3960 = phi_3991_;
                        let _e3962 = phi_3993_;
                        let _e3964 = phi_3995_;
                        let _e3966 = phi_3997_;
                        let _e3968 = phi_3999_;
                        let _e3970 = phi_4001_;
                        let _e3972 = phi_4003_;
                        let _e3974 = phi_4005_;
                        local_333 = _e3954;
                        local_334 = _e3956;
                        local_335 = _e3958;
                        local_336 = _e3960;
                        local_337 = _e3962;
                        local_338 = _e3964;
                        local_339 = _e3966;
                        local_340 = _e3968;
                        local_341 = _e3970;
                        local_342 = _e3972;
                        local_343 = _e3974;
                        let _e3975 = local_333;
                        let _e3976 = (_e3975 < 4u);
                        local_344 = _e3976;
                        if _e3976 {
                            let _e3977 = local_17;
                            let _e3979 = local_333;
                            let _e3981 = ((2u * _e3977) + (_e3979 % 2u));
                            local_345 = _e3981;
                            let _e3982 = local_18;
                            let _e3984 = local_333;
                            local_346 = ((2u * _e3982) + (_e3984 / 2u));
                            let _e3987 = local_10;
                            if (_e3981 < _e3987) {
                                let _e3989 = local_346;
                                let _e3990 = local_14;
                                if (_e3989 < _e3990) {
                                    let _e3992 = local_346;
                                    let _e3993 = local_10;
                                    let _e3995 = local_345;
                                    let _e3996 = ((_e3992 * _e3993) + _e3995);
                                    local_347 = _e3996;
                                    let _e3997 = (3u * _e3996);
                                    local_348 = _e3997;
                                    let _e3998 = local_1;
                                    if (_e3997 < _e3998) {
                                    } else {
                                        phi_6437_ = true;
                                        break;
                                    }
                                    let _e4000 = local_348;
                                    let _e4003 = global_4.member[_e4000];
                                    local_349 = bitcast<f32>(_e4003);
                                    let _e4005 = local_348;
                                    let _e4006 = (_e4005 + 1u);
                                    local_350 = _e4006;
                                    let _e4007 = local_1;
                                    if (_e4006 < _e4007) {
                                    } else {
                                        phi_6437_ = true;
                                        break;
                                    }
                                    let _e4009 = local_350;
                                    let _e4012 = global_4.member[_e4009];
                                    local_351 = bitcast<f32>(_e4012);
                                    let _e4014 = local_348;
                                    let _e4015 = (_e4014 + 2u);
                                    local_352 = _e4015;
                                    let _e4016 = local_1;
                                    if (_e4015 < _e4016) {
                                    } else {
                                        phi_6437_ = true;
                                        break;
                                    }
                                    let _e4018 = local_352;
                                    let _e4021 = global_4.member[_e4018];
                                    local_353 = bitcast<f32>(_e4021);
                                    let _e4023 = local_349;
                                    if (_e4023 > 1267650600000000000000000000000f) {
                                        let _e4025 = local_349;
                                        phi_4073_ = select(true, false, (_e4025 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_4073_ = true;
                                    }
                                    let _e4029 = phi_4073_;
                                    if _e4029 {
                                        let _e4030 = local_349;
                                        if (_e4030 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e4032 = local_349;
                                            phi_4087_ = select(true, false, (_e4032 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4087_ = true;
                                        }
                                        let _e4036 = phi_4087_;
                                        let _e4037 = local_349;
                                        phi_4092_ = select(0f, _e4037, _e4036);
                                    } else {
                                        phi_4092_ = 1267650600000000000000000000000f;
                                    }
                                    let _e4040 = phi_4092_;
                                    local_354 = _e4040;
                                    let _e4041 = local_351;
                                    if (_e4041 > 1267650600000000000000000000000f) {
                                        let _e4043 = local_351;
                                        phi_4102_ = select(true, false, (_e4043 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_4102_ = true;
                                    }
                                    let _e4047 = phi_4102_;
                                    if _e4047 {
                                        let _e4048 = local_351;
                                        if (_e4048 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e4050 = local_351;
                                            phi_4116_ = select(true, false, (_e4050 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4116_ = true;
                                        }
                                        let _e4054 = phi_4116_;
                                        let _e4055 = local_351;
                                        phi_4121_ = select(0f, _e4055, _e4054);
                                    } else {
                                        phi_4121_ = 1267650600000000000000000000000f;
                                    }
                                    let _e4058 = phi_4121_;
                                    local_355 = _e4058;
                                    let _e4059 = local_353;
                                    if (_e4059 > 1267650600000000000000000000000f) {
                                        let _e4061 = local_353;
                                        phi_4131_ = select(true, false, (_e4061 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_4131_ = true;
                                    }
                                    let _e4065 = phi_4131_;
                                    if _e4065 {
                                        let _e4066 = local_353;
                                        if (_e4066 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e4068 = local_353;
                                            phi_4145_ = select(true, false, (_e4068 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4145_ = true;
                                        }
                                        let _e4072 = phi_4145_;
                                        let _e4073 = local_353;
                                        phi_4150_ = select(0f, _e4073, _e4072);
                                    } else {
                                        phi_4150_ = 1267650600000000000000000000000f;
                                    }
                                    let _e4076 = phi_4150_;
                                    local_356 = _e4076;
                                    let _e4077 = local_354;
                                    let _e4078 = local_355;
                                    local_357 = array<f32, 3>(_e4077, _e4078, _e4076);
                                    let _e4080 = local_347;
                                    let _e4081 = local_2;
                                    if (_e4080 < _e4081) {
                                    } else {
                                        phi_6437_ = true;
                                        break;
                                    }
                                    let _e4083 = local_347;
                                    let _e4086 = global_3.member[_e4083];
                                    local_358 = bitcast<f32>(_e4086);
                                    let _e4088 = local_354;
                                    if ((bitcast<u32>(_e4088) & 2139095040u) != 2139095040u) {
                                        let _e4092 = local_355;
                                        if ((bitcast<u32>(_e4092) & 2139095040u) != 2139095040u) {
                                            let _e4096 = local_356;
                                            if ((bitcast<u32>(_e4096) & 2139095040u) != 2139095040u) {
                                                let _e4100 = local_358;
                                                let _e4101 = bitcast<u32>(_e4100);
                                                local_359 = _e4101;
                                                if (_e4101 == 0u) {
                                                    phi_4184_ = false;
                                                } else {
                                                    let _e4103 = local_359;
                                                    phi_4184_ = (_e4103 <= 2139095040u);
                                                }
                                                let _e4106 = phi_4184_;
                                                local_360 = _e4106;
                                                if _e4106 {
                                                    let _e4107 = local_357;
                                                    let _e4108 = local_358;
                                                    phi_4190_ = type_23(1u, type_22(_e4107, _e4108));
                                                } else {
                                                    phi_4190_ = type_23();
                                                }
                                                let _e4112 = phi_4190_;
                                                let _e4113 = local_360;
                                                phi_4192_ = _e4112;
                                                phi_4193_ = select(true, false, _e4113);
                                            } else {
                                                phi_4192_ = type_23();
                                                phi_4193_ = true;
                                            }
                                            let _e4116 = phi_4192_;
                                            let _e4118 = phi_4193_;
                                            phi_4194_ = _e4116;
                                            phi_4195_ = _e4118;
                                        } else {
                                            phi_4194_ = type_23();
                                            phi_4195_ = true;
                                        }
                                        let _e4120 = phi_4194_;
                                        let _e4122 = phi_4195_;
                                        phi_4196_ = _e4120;
                                        phi_4197_ = _e4122;
                                    } else {
                                        phi_4196_ = type_23();
                                        phi_4197_ = true;
                                    }
                                    let _e4124 = phi_4196_;
                                    let _e4126 = phi_4197_;
                                    if _e4126 {
                                        phi_4202_ = type_23(0u, type_23().member_1);
                                    } else {
                                        phi_4202_ = _e4124;
                                    }
                                    let _e4131 = phi_4202_;
                                    local_361 = _e4131;
                                    if (bitcast<i32>(_e4131.member) != 0i) {
                                        let _e4135 = local_361;
                                        local_362 = _e4135.member_1.member;
                                        let _e4138 = local_361;
                                        local_363 = _e4138.member_1.member_1;
                                        let _e4141 = bitcast<u32>(_e4138.member_1.member_1);
                                        local_364 = _e4141;
                                        if (_e4141 == 2139095040u) {
                                            let _e4185 = global_2.member.member_4.member_1;
                                            let _e4190 = global_2.member.member_4.member;
                                            let _e4195 = global_2.member.member_4.member_2;
                                            let _e4201 = global_2.member.member_4.member_3;
                                            phi_4270_ = (0.5f * ((((2f * _e4185) * _e4190) / (_e4195 - _e4190)) * _e4201));
                                        } else {
                                            let _e4143 = local_364;
                                            if (_e4143 == 0u) {
                                                phi_4239_ = false;
                                            } else {
                                                let _e4145 = local_364;
                                                phi_4239_ = (_e4145 <= 2139095040u);
                                            }
                                            let _e4148 = phi_4239_;
                                            if _e4148 {
                                                let _e4152 = global_2.member.member_4.member_1;
                                                let _e4157 = global_2.member.member_4.member;
                                                let _e4162 = global_2.member.member_4.member_2;
                                                local_365 = _e4162;
                                                let _e4168 = global_2.member.member_4.member_3;
                                                let _e4169 = ((((2f * _e4152) * _e4157) / (_e4162 - _e4157)) * _e4168);
                                                local_366 = _e4169;
                                                if (_e4169 == 0f) {
                                                    phi_4267_ = 0f;
                                                } else {
                                                    let _e4171 = local_365;
                                                    let _e4172 = local_363;
                                                    let _e4175 = local_366;
                                                    phi_4267_ = (_e4175 * (1f - (_e4171 / _e4172)));
                                                }
                                                let _e4178 = phi_4267_;
                                                phi_4268_ = _e4178;
                                            } else {
                                                phi_4268_ = _e613;
                                            }
                                            let _e4180 = phi_4268_;
                                            phi_4270_ = (0.5f * _e4180);
                                        }
                                        let _e4205 = phi_4270_;
                                        let _e4206 = local_332;
                                        let _e4208 = local_332;
                                        let _e4209 = select(_e4208, _e4205, (_e4205 < _e4206));
                                        let _e4210 = local_332;
                                        let _e4211 = -(_e4210);
                                        local_510 = select(_e4211, _e4209, (_e4209 > _e4211));
                                        let _e4214 = local_362;
                                        let _e4216 = local_362;
                                        let _e4218 = local_362;
                                        local_529 = array<f32, 3>(_e4214[0], _e4216[1], _e4218[2]);
                                        let _e4221 = local_495;
                                        let _e4222 = local_494;
                                        let _e4223 = local_493;
                                        let _e4225 = local_488;
                                        local_521 = _e4225;
                                        local_520 = array<f32, 3>(_e4221, _e4222, _e4223);
                                        let _e4226 = local_344;
                                        if _e4226 {
                                        } else {
                                            phi_6437_ = true;
                                            break;
                                        }
                                        let _e4227 = local_333;
                                        let _e4229 = local_521[_e4227];
                                        local_367 = _e4229;
                                        if (_e4229 <= 0f) {
                                            let _e4290 = local_529;
                                            phi_6447_ = _e3952;
                                            phi_4388_ = type_25(array<f32, 3>(_e4290[0], _e4290[1], _e4290[2]), array<f32, 3>(0f, 0f, 0f));
                                        } else {
                                            let _e4231 = local_529;
                                            local_530 = _e4231;
                                            local_531 = array<f32, 3>(0f, 0f, 0f);
                                            phi_4316_ = 0u;
                                            loop {
                                                let _e4233 = phi_4316_;
                                                local_368 = _e4233;
                                                let _e4234 = local_368;
                                                let _e4235 = (_e4234 < 3u);
                                                local_369 = _e4235;
                                                if _e4235 {
                                                    let _e4236 = local_369;
                                                    if _e4236 {
                                                    } else {
                                                        phi_6401_ = true;
                                                        break;
                                                    }
                                                    let _e4237 = local_368;
                                                    let _e4239 = local_520[_e4237];
                                                    local_370 = _e4239;
                                                    let _e4240 = local_369;
                                                    if _e4240 {
                                                    } else {
                                                        phi_6401_ = true;
                                                        break;
                                                    }
                                                    let _e4241 = local_368;
                                                    let _e4243 = local_529[_e4241];
                                                    let _e4244 = local_370;
                                                    if (_e4243 > _e4244) {
                                                        let _e4246 = local_369;
                                                        if _e4246 {
                                                        } else {
                                                            phi_6401_ = true;
                                                            break;
                                                        }
                                                        let _e4247 = local_529[_e4241];
                                                        let _e4248 = local_370;
                                                        local_371 = (_e4247 - _e4248);
                                                        let _e4250 = local_369;
                                                        if _e4250 {
                                                        } else {
                                                            phi_6401_ = true;
                                                            break;
                                                        }
                                                        let _e4251 = local_368;
                                                        let _e4253 = local_367;
                                                        let _e4254 = local_371;
                                                        local_531[_e4251] = (_e4253 * _e4254);
                                                        let _e4256 = local_367;
                                                        local_372 = (1f - _e4256);
                                                        let _e4258 = local_369;
                                                        if _e4258 {
                                                        } else {
                                                            phi_6401_ = true;
                                                            break;
                                                        }
                                                        let _e4259 = local_529[_e4241];
                                                        let _e4260 = local_372;
                                                        local_373 = (_e4260 * _e4259);
                                                        let _e4262 = local_367;
                                                        let _e4263 = local_370;
                                                        local_374 = (_e4262 * _e4263);
                                                        let _e4265 = local_369;
                                                        if _e4265 {
                                                        } else {
                                                            phi_6401_ = true;
                                                            break;
                                                        }
                                                        let _e4266 = local_368;
                                                        let _e4268 = local_373;
                                                        let _e4269 = local_374;
                                                        local_530[_e4266] = (_e4268 + _e4269);
                                                    }
                                                    let _e4271 = local_368;
                                                    phi_4317_ = (_e4271 + 1u);
                                                } else {
                                                    phi_4317_ = u32();
                                                }
                                                let _e4274 = phi_4317_;
                                                continue;
                                                continuing {
                                                    let _e4275 = local_369;
                                                    phi_4316_ = _e4274;
                                                    phi_6401_ = _e3952;
                                                    break if !(_e4275);
                                                }
                                            }
                                            let _e4278 = phi_6401_;
                                            phi_6437_ = _e4278;
                                            if _e4278 {
                                                break;
                                            }
                                            let _e4279 = local_530;
                                            let _e4284 = local_531;
                                            phi_6447_ = _e4278;
                                            phi_4388_ = type_25(array<f32, 3>(_e4279[0], _e4279[1], _e4279[2]), array<f32, 3>(_e4284[0], _e4284[1], _e4284[2]));
                                        }
                                        let _e4297 = phi_6447_;
                                        let _e4299 = phi_4388_;
                                        local_375 = _e4299.member;
                                        let _e4302 = local_335;
                                        let _e4306 = local_335;
                                        let _e4310 = local_335;
                                        local_376 = (((0.2126f * _e4299.member_1[0]) + (0.7152f * _e4299.member_1[1])) + (0.0722f * _e4299.member_1[2]));
                                        let _e4320 = local_344;
                                        if _e4320 {
                                        } else {
                                            phi_6437_ = true;
                                            break;
                                        }
                                        let _e4321 = local_333;
                                        let _e4323 = local_376;
                                        local_532[_e4321] = _e4323;
                                        let _e4324 = local_334;
                                        let _e4326 = local_345;
                                        let _e4327 = f32(_e4326);
                                        let _e4329 = local_376;
                                        let _e4332 = local_334;
                                        let _e4334 = local_346;
                                        let _e4335 = f32(_e4334);
                                        let _e4337 = local_376;
                                        let _e4340 = local_334;
                                        let _e4342 = local_376;
                                        let _e4343 = local_510;
                                        let _e4346 = local_334;
                                        let _e4348 = local_376;
                                        let _e4351 = local_343;
                                        let _e4352 = local_510;
                                        let _e4354 = local_341;
                                        let _e4358 = local_341;
                                        let _e4363 = local_342;
                                        let _e4365 = local_510;
                                        let _e4367 = local_510;
                                        let _e4369 = ((-1f - _e4367) * 0.5f);
                                        let _e4371 = select(0f, _e4369, (_e4369 > 0f));
                                        let _e4373 = select(1f, _e4371, (_e4371 < 1f));
                                        let _e4374 = local_340;
                                        let _e4376 = local_375;
                                        let _e4380 = local_340;
                                        let _e4382 = local_375;
                                        let _e4386 = local_340;
                                        let _e4388 = local_375;
                                        let _e4393 = local_510;
                                        let _e4395 = local_339;
                                        let _e4397 = local_338;
                                        let _e4400 = local_510;
                                        let _e4402 = local_510;
                                        let _e4404 = (select(_e4402, -(_e4365), (_e4400 < 0f)) - 1f);
                                        let _e4406 = select(0f, _e4404, (_e4404 > 0f));
                                        let _e4410 = ((1f - _e4373) * (select(1f, _e4406, (_e4406 < 1f)) + 0.001f));
                                        let _e4411 = local_337;
                                        let _e4415 = local_337;
                                        let _e4419 = local_337;
                                        let _e4423 = local_337;
                                        let _e4425 = local_510;
                                        let _e4429 = local_336;
                                        phi_6441_ = _e4297;
                                        phi_4508_ = array<f32, 4>((_e4324[0] + (_e4329 * (_e4327 + 0.5f))), (_e4332[1] + (_e4337 * (_e4335 + 0.5f))), (_e4340[2] + (_e4342 * _e4343)), (_e4346[3] + _e4348));
                                        phi_4509_ = array<f32, 3>((_e4302[0] + _e4299.member_1[0]), (_e4306[1] + _e4299.member_1[1]), (_e4310[2] + _e4299.member_1[2]));
                                        phi_4510_ = (_e4429 + _e4410);
                                        phi_4511_ = array<f32, 4>((_e4411[0] + (_e4410 * _e4376[0])), (_e4415[1] + (_e4410 * _e4382[1])), (_e4419[2] + (_e4410 * _e4388[2])), (_e4423[3] + (_e4410 * _e4425)));
                                        phi_4512_ = (_e4397 + _e4373);
                                        phi_4513_ = (_e4395 + (_e4373 * _e4393));
                                        phi_4514_ = array<f32, 3>((_e4374[0] + (_e4373 * _e4376[0])), (_e4380[1] + (_e4373 * _e4382[1])), (_e4386[2] + (_e4373 * _e4388[2])));
                                        phi_4515_ = array<f32, 2>(((_e4354[0] + _e4327) + 0.5f), ((_e4358[1] + _e4335) + 0.5f));
                                        phi_4516_ = (_e4363 + 1u);
                                        phi_4517_ = (_e4351 + _e4352);
                                    } else {
                                        phi_6441_ = _e3952;
                                        phi_4508_ = _e3956;
                                        phi_4509_ = _e3958;
                                        phi_4510_ = _e3960;
                                        phi_4511_ = _e3962;
                                        phi_4512_ = _e3964;
                                        phi_4513_ = _e3966;
                                        phi_4514_ = _e3968;
                                        phi_4515_ = _e3970;
                                        phi_4516_ = _e3972;
                                        phi_4517_ = _e3974;
                                    }
                                    let _e4432 = phi_6441_;
                                    let _e4434 = phi_4508_;
                                    let _e4436 = phi_4509_;
                                    let _e4438 = phi_4510_;
                                    let _e4440 = phi_4511_;
                                    let _e4442 = phi_4512_;
                                    let _e4444 = phi_4513_;
                                    let _e4446 = phi_4514_;
                                    let _e4448 = phi_4515_;
                                    let _e4450 = phi_4516_;
                                    let _e4452 = phi_4517_;
                                    phi_6440_ = _e4432;
                                    phi_4518_ = _e4434;
                                    phi_4519_ = _e4436;
                                    phi_4520_ = _e4438;
                                    phi_4521_ = _e4440;
                                    phi_4522_ = _e4442;
                                    phi_4523_ = _e4444;
                                    phi_4524_ = _e4446;
                                    phi_4525_ = _e4448;
                                    phi_4526_ = _e4450;
                                    phi_4527_ = _e4452;
                                } else {
                                    phi_6440_ = _e3952;
                                    phi_4518_ = _e3956;
                                    phi_4519_ = _e3958;
                                    phi_4520_ = _e3960;
                                    phi_4521_ = _e3962;
                                    phi_4522_ = _e3964;
                                    phi_4523_ = _e3966;
                                    phi_4524_ = _e3968;
                                    phi_4525_ = _e3970;
                                    phi_4526_ = _e3972;
                                    phi_4527_ = _e3974;
                                }
                                let _e4454 = phi_6440_;
                                let _e4456 = phi_4518_;
                                let _e4458 = phi_4519_;
                                let _e4460 = phi_4520_;
                                let _e4462 = phi_4521_;
                                let _e4464 = phi_4522_;
                                let _e4466 = phi_4523_;
                                let _e4468 = phi_4524_;
                                let _e4470 = phi_4525_;
                                let _e4472 = phi_4526_;
                                let _e4474 = phi_4527_;
                                phi_6439_ = _e4454;
                                phi_4528_ = _e4456;
                                phi_4529_ = _e4458;
                                phi_4530_ = _e4460;
                                phi_4531_ = _e4462;
                                phi_4532_ = _e4464;
                                phi_4533_ = _e4466;
                                phi_4534_ = _e4468;
                                phi_4535_ = _e4470;
                                phi_4536_ = _e4472;
                                phi_4537_ = _e4474;
                            } else {
                                phi_6439_ = _e3952;
                                phi_4528_ = _e3956;
                                phi_4529_ = _e3958;
                                phi_4530_ = _e3960;
                                phi_4531_ = _e3962;
                                phi_4532_ = _e3964;
                                phi_4533_ = _e3966;
                                phi_4534_ = _e3968;
                                phi_4535_ = _e3970;
                                phi_4536_ = _e3972;
                                phi_4537_ = _e3974;
                            }
                            let _e4476 = phi_6439_;
                            let _e4478 = phi_4528_;
                            let _e4480 = phi_4529_;
                            let _e4482 = phi_4530_;
                            let _e4484 = phi_4531_;
                            let _e4486 = phi_4532_;
                            let _e4488 = phi_4533_;
                            let _e4490 = phi_4534_;
                            let _e4492 = phi_4535_;
                            let _e4494 = phi_4536_;
                            let _e4496 = phi_4537_;
                            let _e4497 = local_333;
                            phi_6438_ = _e4476;
                            phi_3985_ = (_e4497 + 1u);
                            phi_3988_ = _e4478;
                            phi_3990_ = _e4480;
                            phi_3992_ = _e4482;
                            phi_3994_ = _e4484;
                            phi_3996_ = _e4486;
                            phi_3998_ = _e4488;
                            phi_4000_ = _e4490;
                            phi_4002_ = _e4492;
                            phi_4004_ = _e4494;
                            phi_4006_ = _e4496;
                        } else {
                            phi_6438_ = _e3952;
                            phi_3985_ = u32();
                            phi_3988_ = array<f32, 4>();
                            phi_3990_ = array<f32, 3>();
                            phi_3992_ = f32();
                            phi_3994_ = array<f32, 4>();
                            phi_3996_ = f32();
                            phi_3998_ = f32();
                            phi_4000_ = array<f32, 3>();
                            phi_4002_ = array<f32, 2>();
                            phi_4004_ = u32();
                            phi_4006_ = f32();
                        }
                        let _e4500 = phi_6438_;
                        let _e4502 = phi_3985_;
                        let _e4504 = phi_3988_;
                        let _e4506 = phi_3990_;
                        let _e4508 = phi_3992_;
                        let _e4510 = phi_3994_;
                        let _e4512 = phi_3996_;
                        let _e4514 = phi_3998_;
                        let _e4516 = phi_4000_;
                        let _e4518 = phi_4002_;
                        let _e4520 = phi_4004_;
                        let _e4522 = phi_4006_;
                        continue;
                        continuing {
                            let _e4523 = local_344;
                            phi_6432_ = _e4500;
                            phi_3984_ = _e4502;
                            phi_3987_ = _e4504;
                            phi_3989_ = _e4506;
                            phi_3991_ = _e4508;
                            phi_3993_ = _e4510;
                            phi_3995_ = _e4512;
                            phi_3997_ = _e4514;
                            phi_3999_ = _e4516;
                            phi_4001_ = _e4518;
                            phi_4003_ = _e4520;
                            phi_4005_ = _e4522;
                            phi_6437_ = _e4500;
                            break if !(_e4523);
                        }
                    }
                    let _e4526 = phi_6437_;
                    if _e4526 {
                        break;
                    }
                    let _e4527 = local_342;
                    if (_e4527 == 0u) {
                        let _e4701 = local_513;
                        let _e4702 = local_342;
                        phi_6460_ = _e4526;
                        phi_4676_ = type_30(array<f32, 2>(0f, 0f), array<f32, 3>(0f, 0f, 0f), 0f, 0f, array<f32, 3>(0f, 0f, 0f), _e4701, _e4702, array<f32, 3>(0f, 0f, 0f), 0f, 0f);
                    } else {
                        let _e4529 = local_342;
                        let _e4530 = f32(_e4529);
                        let _e4531 = (1f / _e4530);
                        local_377 = _e4531;
                        let _e4532 = local_343;
                        let _e4534 = ((0.5f * _e4532) * _e4531);
                        local_378 = _e4534;
                        let _e4535 = local_338;
                        let _e4537 = ((_e4530 - _e4535) > 0f);
                        local_379 = _e4537;
                        if _e4537 {
                            let _e4538 = local_336;
                            let _e4539 = (_e4538 > 0f);
                            local_380 = _e4539;
                            if _e4539 {
                                let _e4540 = local_336;
                                let _e4541 = (1f / _e4540);
                                let _e4542 = local_337;
                                let _e4545 = local_337;
                                let _e4548 = local_337;
                                let _e4552 = local_337;
                                phi_4568_ = array<f32, 3>((_e4542[0] * _e4541), (_e4545[1] * _e4541), (_e4548[2] * _e4541));
                                phi_4569_ = ((0.5f * _e4552[3]) * _e4541);
                            } else {
                                phi_4568_ = array<f32, 3>();
                                phi_4569_ = f32();
                            }
                            let _e4557 = phi_4568_;
                            let _e4559 = phi_4569_;
                            let _e4560 = local_380;
                            phi_4571_ = _e4557;
                            phi_4572_ = _e4559;
                            phi_4573_ = select(true, false, _e4560);
                        } else {
                            phi_4571_ = array<f32, 3>();
                            phi_4572_ = f32();
                            phi_4573_ = true;
                        }
                        let _e4563 = phi_4571_;
                        let _e4565 = phi_4572_;
                        let _e4567 = phi_4573_;
                        local_381 = _e4565;
                        local_382 = _e4567;
                        if _e4567 {
                            phi_4577_ = array<f32, 3>(0f, 0f, 0f);
                        } else {
                            phi_4577_ = _e4563;
                        }
                        let _e4569 = phi_4577_;
                        local_383 = _e4569;
                        let _e4570 = local_382;
                        let _e4571 = local_378;
                        let _e4572 = local_381;
                        local_511 = select(_e4572, _e4571, _e4570);
                        let _e4574 = local_338;
                        if (_e4574 > 0f) {
                            let _e4576 = local_338;
                            let _e4577 = (1f / _e4576);
                            let _e4578 = local_340;
                            let _e4581 = local_340;
                            let _e4584 = local_340;
                            let _e4588 = local_339;
                            phi_4593_ = array<f32, 3>((_e4578[0] * _e4577), (_e4581[1] * _e4577), (_e4584[2] * _e4577));
                            phi_4594_ = ((0.5f * _e4588) * _e4577);
                        } else {
                            phi_4593_ = array<f32, 3>(0f, 0f, 0f);
                            phi_4594_ = _e4534;
                        }
                        let _e4592 = phi_4593_;
                        let _e4594 = phi_4594_;
                        local_384 = _e4592;
                        local_385 = _e4594;
                        let _e4595 = local_379;
                        if _e4595 {
                            let _e4596 = local_338;
                            let _e4597 = local_377;
                            phi_4600_ = (_e4596 * _e4597);
                        } else {
                            phi_4600_ = 1f;
                        }
                        let _e4600 = phi_4600_;
                        local_386 = _e4600;
                        let _e4601 = local_341;
                        let _e4603 = local_377;
                        let _e4605 = local_341;
                        let _e4607 = local_377;
                        let _e4610 = local_334;
                        local_387 = _e4610[3];
                        if (_e4610[3] > 0f) {
                            let _e4615 = local_387;
                            let _e4616 = (1f / _e4615);
                            local_388 = _e4616;
                            let _e4617 = local_334;
                            let _e4619 = (_e4617[0] * _e4616);
                            local_389 = _e4619;
                            let _e4620 = local_334;
                            let _e4622 = (_e4620[1] * _e4616);
                            local_390 = _e4622;
                            phi_4619_ = 0u;
                            phi_4622_ = 0f;
                            loop {
                                let _e4625 = phi_4619_;
                                let _e4627 = phi_4622_;
                                local_391 = _e4625;
                                local_392 = _e4627;
                                let _e4628 = local_391;
                                let _e4629 = (_e4628 < 4u);
                                local_393 = _e4629;
                                if _e4629 {
                                    let _e4630 = local_393;
                                    if _e4630 {
                                    } else {
                                        phi_6448_ = true;
                                        break;
                                    }
                                    let _e4631 = local_391;
                                    let _e4633 = local_532[_e4631];
                                    if (_e4633 > 0f) {
                                        let _e4635 = local_17;
                                        let _e4637 = local_391;
                                        let _e4642 = local_389;
                                        local_394 = ((f32(((2u * _e4635) + (_e4637 % 2u))) + 0.5f) - _e4642);
                                        let _e4644 = local_18;
                                        let _e4646 = local_391;
                                        let _e4651 = local_390;
                                        local_395 = ((f32(((2u * _e4644) + (_e4646 / 2u))) + 0.5f) - _e4651);
                                        let _e4653 = local_393;
                                        if _e4653 {
                                        } else {
                                            phi_6448_ = true;
                                            break;
                                        }
                                        let _e4654 = local_532[_e4631];
                                        let _e4655 = local_394;
                                        let _e4656 = local_394;
                                        let _e4658 = local_395;
                                        let _e4659 = local_395;
                                        let _e4664 = local_392;
                                        phi_4666_ = (_e4664 + (_e4654 * sqrt(((_e4655 * _e4656) + (_e4658 * _e4659)))));
                                    } else {
                                        phi_4666_ = _e4627;
                                    }
                                    let _e4667 = phi_4666_;
                                    let _e4668 = local_391;
                                    phi_4620_ = (_e4668 + 1u);
                                    phi_4623_ = _e4667;
                                } else {
                                    phi_4620_ = u32();
                                    phi_4623_ = f32();
                                }
                                let _e4671 = phi_4620_;
                                let _e4673 = phi_4623_;
                                continue;
                                continuing {
                                    let _e4674 = local_393;
                                    phi_4619_ = _e4671;
                                    phi_4622_ = _e4673;
                                    phi_6448_ = _e4526;
                                    break if !(_e4674);
                                }
                            }
                            let _e4677 = phi_6448_;
                            if _e4677 {
                                break;
                            }
                            let _e4678 = local_334;
                            let _e4680 = local_388;
                            let _e4682 = local_392;
                            let _e4683 = local_388;
                            phi_6461_ = _e4677;
                            phi_4672_ = (_e4678[2] * _e4680);
                            phi_4673_ = (_e4682 * _e4683);
                            phi_4674_ = array<f32, 2>(_e4619, _e4622);
                        } else {
                            let _e4613 = local_378;
                            phi_6461_ = _e4526;
                            phi_4672_ = (2f * _e4613);
                            phi_4673_ = 0f;
                            phi_4674_ = array<f32, 2>((_e4601[0] * _e4603), (_e4605[1] * _e4607));
                        }
                        let _e4686 = phi_6461_;
                        let _e4688 = phi_4672_;
                        let _e4690 = phi_4673_;
                        let _e4692 = phi_4674_;
                        let _e4693 = local_384;
                        let _e4694 = local_386;
                        let _e4695 = local_385;
                        let _e4696 = local_383;
                        let _e4697 = local_511;
                        let _e4698 = local_342;
                        let _e4699 = local_335;
                        phi_6460_ = _e4686;
                        phi_4676_ = type_30(_e4692, _e4693, _e4694, _e4695, _e4696, _e4697, _e4698, _e4699, _e4688, _e4690);
                    }
                    let _e4705 = phi_6460_;
                    let _e4707 = phi_4676_;
                    local_396 = _e4707;
                    let _e4708 = local_18;
                    let _e4709 = local_13;
                    let _e4711 = local_17;
                    local_397 = (9u * ((_e4708 * _e4709) + _e4711));
                    local_528[0u] = _e4707.member_1[0];
                    local_528[1u] = _e4707.member_1[1];
                    local_528[2u] = _e4707.member_1[2];
                    local_528[3u] = _e4707.member_2;
                    local_528[4u] = _e4707.member_4[0];
                    local_528[5u] = _e4707.member_4[1];
                    local_528[6u] = _e4707.member_4[2];
                    local_528[7u] = _e4707.member_3;
                    local_528[8u] = _e4707.member_5;
                    phi_4699_ = 0u;
                    loop {
                        let _e4739 = phi_4699_;
                        local_398 = _e4739;
                        let _e4740 = local_398;
                        let _e4741 = (_e4740 < 9u);
                        local_399 = _e4741;
                        if _e4741 {
                            let _e4742 = local_397;
                            let _e4743 = local_398;
                            local_400 = (_e4742 + _e4743);
                            let _e4745 = local_399;
                            if _e4745 {
                            } else {
                                phi_6457_ = true;
                                break;
                            }
                            let _e4746 = local_398;
                            let _e4748 = local_528[_e4746];
                            local_401 = bitcast<u32>(_e4748);
                            let _e4750 = local_400;
                            let _e4751 = local_3;
                            if (_e4750 < _e4751) {
                            } else {
                                phi_6457_ = true;
                                break;
                            }
                            let _e4753 = local_400;
                            let _e4756 = local_401;
                            global_5.member[_e4753] = _e4756;
                            let _e4757 = local_398;
                            phi_4700_ = (_e4757 + 1u);
                        } else {
                            phi_4700_ = u32();
                        }
                        let _e4760 = phi_4700_;
                        continue;
                        continuing {
                            let _e4761 = local_399;
                            phi_4699_ = _e4760;
                            phi_6457_ = _e4705;
                            break if !(_e4761);
                        }
                    }
                    let _e4764 = phi_6457_;
                    if _e4764 {
                        break;
                    }
                    let _e4765 = local_396;
                    local_402 = _e4765.member_8;
                    if (_e4765.member_8 < 0f) {
                        let _e4772 = local_402;
                        let _e4774 = local_402;
                        phi_4739_ = select(-0.5f, _e4774, (_e4772 < -0.5f));
                    } else {
                        let _e4768 = local_402;
                        let _e4770 = local_402;
                        phi_4739_ = select(0.5f, _e4770, (_e4768 > 0.5f));
                    }
                    let _e4777 = phi_4739_;
                    local_403 = _e4777;
                    let _e4778 = local_396;
                    local_404 = _e4778.member[0];
                    let _e4781 = local_396;
                    local_405 = _e4781.member[1];
                    if (_e4777 < 0f) {
                        let _e4785 = local_403;
                        phi_4747_ = -(_e4785);
                    } else {
                        phi_4747_ = _e4777;
                    }
                    let _e4788 = phi_4747_;
                    let _e4789 = local_396;
                    local_406 = _e4789.member_9;
                    let _e4792 = ((_e4788 + 0.5f) + _e4789.member_9);
                    local_472 = _e4792;
                    local_473 = ((_e4788 - 0.5f) - _e4789.member_9);
                    let _e4795 = local_405;
                    let _e4798 = local_405;
                    local_474 = floor((_e4798 + _e4792));
                    phi_5540_ = floor((_e4795 - _e4792));
                    phi_5541_ = 0f;
                    loop {
                        let _e4802 = phi_5540_;
                        let _e4804 = phi_5541_;
                        local_475 = _e4802;
                        local_476 = _e4804;
                        let _e4805 = local_475;
                        let _e4806 = local_474;
                        let _e4807 = (_e4805 <= _e4806);
                        local_477 = _e4807;
                        if _e4807 {
                            let _e4808 = local_475;
                            let _e4810 = local_405;
                            let _e4811 = ((_e4808 + 0.5f) - _e4810);
                            let _e4812 = local_472;
                            let _e4813 = local_472;
                            let _e4815 = (_e4811 * _e4811);
                            local_478 = _e4815;
                            let _e4816 = ((_e4812 * _e4813) - _e4815);
                            local_479 = _e4816;
                            if (_e4816 > 0f) {
                                let _e4818 = local_479;
                                local_480 = sqrt(_e4818);
                                let _e4820 = local_473;
                                if (_e4820 > 0f) {
                                    let _e4822 = local_473;
                                    let _e4823 = local_473;
                                    let _e4825 = local_478;
                                    phi_5560_ = ((_e4822 * _e4823) - _e4825);
                                } else {
                                    phi_5560_ = -1f;
                                }
                                let _e4828 = phi_5560_;
                                local_481 = _e4828;
                                if (_e4828 > 0f) {
                                    let _e4830 = local_481;
                                    let _e4831 = sqrt(_e4830);
                                    let _e4832 = local_404;
                                    let _e4836 = local_404;
                                    phi_5572_ = floor(((_e4836 + _e4831) - 0.5f));
                                    phi_5573_ = ceil(((_e4832 - _e4831) - 0.5f));
                                } else {
                                    phi_5572_ = 0f;
                                    phi_5573_ = 1f;
                                }
                                let _e4841 = phi_5572_;
                                let _e4843 = phi_5573_;
                                local_482 = _e4841;
                                local_483 = _e4843;
                                if (_e4841 >= _e4843) {
                                    let _e4845 = local_482;
                                    let _e4846 = local_483;
                                    let _e4849 = local_476;
                                    phi_5581_ = (_e4849 + ((_e4845 - _e4846) + 1f));
                                } else {
                                    phi_5581_ = _e4804;
                                }
                                let _e4852 = phi_5581_;
                                let _e4853 = local_404;
                                let _e4854 = local_480;
                                let _e4858 = local_404;
                                let _e4859 = local_480;
                                local_484 = ceil(((_e4858 + _e4859) - 0.5f));
                                phi_5589_ = floor(((_e4853 - _e4854) - 0.5f));
                                phi_5590_ = _e4852;
                                loop {
                                    let _e4864 = phi_5589_;
                                    let _e4866 = phi_5590_;
                                    local_485 = _e4864;
                                    local_486 = _e4866;
                                    local_548 = _e4866;
                                    let _e4867 = local_485;
                                    let _e4868 = local_484;
                                    let _e4869 = (_e4867 <= _e4868);
                                    local_487 = _e4869;
                                    if _e4869 {
                                        let _e4870 = local_485;
                                        let _e4871 = local_483;
                                        if (_e4870 < _e4871) {
                                            phi_5602_ = true;
                                        } else {
                                            let _e4873 = local_485;
                                            let _e4874 = local_482;
                                            phi_5602_ = (_e4873 > _e4874);
                                        }
                                        let _e4877 = phi_5602_;
                                        if _e4877 {
                                            let _e4878 = local_485;
                                            let _e4880 = local_404;
                                            let _e4881 = ((_e4878 + 0.5f) - _e4880);
                                            let _e4883 = local_478;
                                            let _e4886 = local_406;
                                            let _e4889 = local_472;
                                            let _e4891 = ((_e4889 - sqrt(((_e4881 * _e4881) + _e4883))) / (1f + (2f * _e4886)));
                                            let _e4896 = local_486;
                                            phi_5629_ = (_e4896 + select(0f, select(1f, _e4891, (_e4891 < 1f)), (0f < _e4891)));
                                        } else {
                                            phi_5629_ = _e4866;
                                        }
                                        let _e4899 = phi_5629_;
                                        let _e4900 = local_485;
                                        phi_5633_ = (_e4900 + 1f);
                                        phi_5634_ = _e4899;
                                    } else {
                                        phi_5633_ = f32();
                                        phi_5634_ = f32();
                                    }
                                    let _e4903 = phi_5633_;
                                    let _e4905 = phi_5634_;
                                    continue;
                                    continuing {
                                        let _e4906 = local_487;
                                        phi_5589_ = _e4903;
                                        phi_5590_ = _e4905;
                                        break if !(_e4906);
                                    }
                                }
                                let _e6027 = local_548;
                                phi_5639_ = _e6027;
                            } else {
                                phi_5639_ = _e4804;
                            }
                            let _e4909 = phi_5639_;
                            let _e4910 = local_475;
                            phi_5643_ = (_e4910 + 1f);
                            phi_5644_ = _e4909;
                        } else {
                            phi_5643_ = f32();
                            phi_5644_ = f32();
                        }
                        let _e4913 = phi_5643_;
                        let _e4915 = phi_5644_;
                        continue;
                        continuing {
                            let _e4916 = local_477;
                            phi_5540_ = _e4913;
                            phi_5541_ = _e4915;
                            break if !(_e4916);
                        }
                    }
                    let _e4918 = local_476;
                    local_407 = (1f / _e4918);
                    let _e4920 = local_260;
                    let _e4922 = local_262;
                    let _e4925 = ((_e4920 + 2u) + (8u * (_e4922 - 1u)));
                    local_408 = _e4925;
                    let _e4926 = local_404;
                    local_409 = bitcast<u32>(_e4926);
                    let _e4928 = local_5;
                    if (_e4925 < _e4928) {
                    } else {
                        break;
                    }
                    let _e4930 = local_408;
                    let _e4933 = local_409;
                    global_7.member[_e4930] = _e4933;
                    let _e4934 = local_408;
                    let _e4935 = (_e4934 + 1u);
                    local_410 = _e4935;
                    let _e4936 = local_405;
                    local_411 = bitcast<u32>(_e4936);
                    let _e4938 = local_5;
                    if (_e4935 < _e4938) {
                    } else {
                        break;
                    }
                    let _e4940 = local_410;
                    let _e4943 = local_411;
                    global_7.member[_e4940] = _e4943;
                    let _e4944 = local_408;
                    let _e4945 = (_e4944 + 2u);
                    local_412 = _e4945;
                    let _e4946 = local_403;
                    local_413 = bitcast<u32>(_e4946);
                    let _e4948 = local_5;
                    if (_e4945 < _e4948) {
                    } else {
                        break;
                    }
                    let _e4950 = local_412;
                    let _e4953 = local_413;
                    global_7.member[_e4950] = _e4953;
                    let _e4954 = local_408;
                    let _e4955 = (_e4954 + 3u);
                    local_414 = _e4955;
                    let _e4956 = local_396;
                    let _e4959 = local_407;
                    local_415 = bitcast<u32>((_e4956.member_7[0] * _e4959));
                    let _e4962 = local_5;
                    if (_e4955 < _e4962) {
                    } else {
                        break;
                    }
                    let _e4964 = local_414;
                    let _e4967 = local_415;
                    global_7.member[_e4964] = _e4967;
                    let _e4968 = local_408;
                    let _e4969 = (_e4968 + 4u);
                    local_416 = _e4969;
                    let _e4970 = local_396;
                    let _e4973 = local_407;
                    local_417 = bitcast<u32>((_e4970.member_7[1] * _e4973));
                    let _e4976 = local_5;
                    if (_e4969 < _e4976) {
                    } else {
                        break;
                    }
                    let _e4978 = local_416;
                    let _e4981 = local_417;
                    global_7.member[_e4978] = _e4981;
                    let _e4982 = local_408;
                    let _e4983 = (_e4982 + 5u);
                    local_418 = _e4983;
                    let _e4984 = local_396;
                    let _e4987 = local_407;
                    local_419 = bitcast<u32>((_e4984.member_7[2] * _e4987));
                    let _e4990 = local_5;
                    if (_e4983 < _e4990) {
                    } else {
                        break;
                    }
                    let _e4992 = local_418;
                    let _e4995 = local_419;
                    global_7.member[_e4992] = _e4995;
                    let _e4996 = local_408;
                    let _e4997 = (_e4996 + 6u);
                    local_420 = _e4997;
                    let _e4998 = local_406;
                    local_421 = bitcast<u32>(_e4998);
                    let _e5000 = local_5;
                    if (_e4997 < _e5000) {
                    } else {
                        break;
                    }
                    let _e5002 = local_420;
                    let _e5005 = local_421;
                    global_7.member[_e5002] = _e5005;
                    let _e5006 = local_408;
                    let _e5007 = (_e5006 + 7u);
                    local_422 = _e5007;
                    let _e5008 = local_5;
                    if (_e5007 < _e5008) {
                    } else {
                        break;
                    }
                    let _e5010 = local_422;
                    global_7.member[_e5010] = 0u;
                    phi_6492_ = _e4764;
                    phi_4824_ = type_31(array<f32, 4>(_e3939[0], _e3939[1], _e3939[2], _e3939[3]), array<f32, 3>(_e3934, _e3936, _e3938));
                } else {
                    phi_6492_ = _e3194;
                    phi_4824_ = type_31(array<f32, 4>(0f, 0f, 0f, 0f), array<f32, 3>(0f, 0f, 0f));
                }
                let _e5014 = phi_6492_;
                let _e5016 = phi_4824_;
                phi_6491_ = _e5014;
                phi_4825_ = _e5016;
            } else {
                phi_6491_ = _e3194;
                phi_4825_ = type_31(array<f32, 4>(0f, 0f, 0f, 0f), array<f32, 3>(0f, 0f, 0f));
            }
            let _e5018 = phi_6491_;
            let _e5020 = phi_4825_;
            local_423 = _e5020;
            let _e5021 = local_19;
            if _e5021 {
                let _e5022 = local_18;
                let _e5023 = local_16;
                if (_e5022 < _e5023) {
                    let _e5025 = local_423;
                    let _e5031 = array<f32, 4>(_e5025.member[0], _e5025.member[1], _e5025.member[2], _e5025.member[3]);
                    local_424 = _e5031;
                    local_522 = _e5031;
                    phi_6490_ = _e5018;
                    phi_4847_ = 0u;
                    loop {
                        let _e5033 = phi_6490_;
                        let _e5035 = phi_4847_;
                        local_425 = _e5035;
                        let _e5036 = local_425;
                        let _e5037 = (_e5036 < 4u);
                        local_426 = _e5037;
                        if _e5037 {
                            let _e5038 = local_17;
                            let _e5040 = local_425;
                            let _e5042 = ((2u * _e5038) + (_e5040 % 2u));
                            local_427 = _e5042;
                            let _e5043 = local_18;
                            let _e5045 = local_425;
                            local_428 = ((2u * _e5043) + (_e5045 / 2u));
                            let _e5048 = local_10;
                            if (_e5042 < _e5048) {
                                let _e5050 = local_428;
                                let _e5051 = local_14;
                                if (_e5050 < _e5051) {
                                    let _e5053 = local_428;
                                    let _e5054 = local_10;
                                    let _e5056 = local_427;
                                    let _e5057 = ((_e5053 * _e5054) + _e5056);
                                    local_429 = _e5057;
                                    let _e5058 = (3u * _e5057);
                                    local_430 = _e5058;
                                    let _e5059 = local_1;
                                    let _e5060 = (_e5058 < _e5059);
                                    local_431 = _e5060;
                                    if _e5060 {
                                    } else {
                                        phi_6509_ = true;
                                        break;
                                    }
                                    let _e5061 = local_430;
                                    let _e5064 = global_4.member[_e5061];
                                    local_432 = _e5064;
                                    let _e5065 = local_430;
                                    let _e5066 = (_e5065 + 1u);
                                    local_433 = _e5066;
                                    let _e5067 = local_1;
                                    let _e5068 = (_e5066 < _e5067);
                                    local_434 = _e5068;
                                    if _e5068 {
                                    } else {
                                        phi_6509_ = true;
                                        break;
                                    }
                                    let _e5069 = local_433;
                                    let _e5072 = global_4.member[_e5069];
                                    local_435 = _e5072;
                                    let _e5073 = local_430;
                                    let _e5074 = (_e5073 + 2u);
                                    local_436 = _e5074;
                                    let _e5075 = local_1;
                                    let _e5076 = (_e5074 < _e5075);
                                    local_437 = _e5076;
                                    if _e5076 {
                                    } else {
                                        phi_6509_ = true;
                                        break;
                                    }
                                    let _e5077 = local_436;
                                    let _e5080 = global_4.member[_e5077];
                                    local_438 = _e5080;
                                    let _e5081 = local_432;
                                    let _e5082 = local_435;
                                    let _e5083 = array<u32, 3>(_e5081, _e5082, _e5080);
                                    let _e5084 = local_426;
                                    if _e5084 {
                                    } else {
                                        phi_6509_ = true;
                                        break;
                                    }
                                    let _e5085 = local_425;
                                    let _e5087 = local_522[_e5085];
                                    if (_e5087 > 0f) {
                                        let _e5089 = local_431;
                                        if _e5089 {
                                        } else {
                                            phi_6509_ = true;
                                            break;
                                        }
                                        let _e5090 = local_432;
                                        local_439 = bitcast<f32>(_e5090);
                                        let _e5092 = local_434;
                                        if _e5092 {
                                        } else {
                                            phi_6509_ = true;
                                            break;
                                        }
                                        let _e5093 = local_435;
                                        local_440 = bitcast<f32>(_e5093);
                                        let _e5095 = local_437;
                                        if _e5095 {
                                        } else {
                                            phi_6509_ = true;
                                            break;
                                        }
                                        let _e5096 = local_438;
                                        local_441 = bitcast<f32>(_e5096);
                                        let _e5098 = local_439;
                                        if (_e5098 > 1267650600000000000000000000000f) {
                                            let _e5100 = local_439;
                                            phi_4954_ = select(true, false, (_e5100 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4954_ = true;
                                        }
                                        let _e5104 = phi_4954_;
                                        if _e5104 {
                                            let _e5105 = local_439;
                                            if (_e5105 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e5107 = local_439;
                                                phi_4968_ = select(true, false, (_e5107 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_4968_ = true;
                                            }
                                            let _e5111 = phi_4968_;
                                            let _e5112 = local_439;
                                            phi_4973_ = select(0f, _e5112, _e5111);
                                        } else {
                                            phi_4973_ = 1267650600000000000000000000000f;
                                        }
                                        let _e5115 = phi_4973_;
                                        local_442 = _e5115;
                                        let _e5116 = local_440;
                                        if (_e5116 > 1267650600000000000000000000000f) {
                                            let _e5118 = local_440;
                                            phi_4983_ = select(true, false, (_e5118 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4983_ = true;
                                        }
                                        let _e5122 = phi_4983_;
                                        if _e5122 {
                                            let _e5123 = local_440;
                                            if (_e5123 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e5125 = local_440;
                                                phi_4997_ = select(true, false, (_e5125 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_4997_ = true;
                                            }
                                            let _e5129 = phi_4997_;
                                            let _e5130 = local_440;
                                            phi_5002_ = select(0f, _e5130, _e5129);
                                        } else {
                                            phi_5002_ = 1267650600000000000000000000000f;
                                        }
                                        let _e5133 = phi_5002_;
                                        local_443 = _e5133;
                                        let _e5134 = local_441;
                                        if (_e5134 > 1267650600000000000000000000000f) {
                                            let _e5136 = local_441;
                                            phi_5012_ = select(true, false, (_e5136 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_5012_ = true;
                                        }
                                        let _e5140 = phi_5012_;
                                        if _e5140 {
                                            let _e5141 = local_441;
                                            if (_e5141 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e5143 = local_441;
                                                phi_5026_ = select(true, false, (_e5143 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_5026_ = true;
                                            }
                                            let _e5147 = phi_5026_;
                                            let _e5148 = local_441;
                                            phi_5031_ = select(0f, _e5148, _e5147);
                                        } else {
                                            phi_5031_ = 1267650600000000000000000000000f;
                                        }
                                        let _e5151 = phi_5031_;
                                        local_444 = _e5151;
                                        let _e5152 = local_442;
                                        let _e5153 = local_443;
                                        local_445 = array<f32, 3>(_e5152, _e5153, _e5151);
                                        let _e5155 = local_429;
                                        let _e5156 = local_2;
                                        if (_e5155 < _e5156) {
                                        } else {
                                            phi_6509_ = true;
                                            break;
                                        }
                                        let _e5158 = local_429;
                                        let _e5161 = global_3.member[_e5158];
                                        local_446 = bitcast<f32>(_e5161);
                                        let _e5163 = local_442;
                                        if ((bitcast<u32>(_e5163) & 2139095040u) != 2139095040u) {
                                            let _e5167 = local_443;
                                            if ((bitcast<u32>(_e5167) & 2139095040u) != 2139095040u) {
                                                let _e5171 = local_444;
                                                if ((bitcast<u32>(_e5171) & 2139095040u) != 2139095040u) {
                                                    let _e5175 = local_446;
                                                    let _e5176 = bitcast<u32>(_e5175);
                                                    local_447 = _e5176;
                                                    if (_e5176 == 0u) {
                                                        phi_5065_ = false;
                                                    } else {
                                                        let _e5178 = local_447;
                                                        phi_5065_ = (_e5178 <= 2139095040u);
                                                    }
                                                    let _e5181 = phi_5065_;
                                                    local_448 = _e5181;
                                                    if _e5181 {
                                                        let _e5182 = local_445;
                                                        let _e5183 = local_446;
                                                        phi_5071_ = type_23(1u, type_22(_e5182, _e5183));
                                                    } else {
                                                        phi_5071_ = type_23();
                                                    }
                                                    let _e5187 = phi_5071_;
                                                    let _e5188 = local_448;
                                                    phi_5073_ = _e5187;
                                                    phi_5074_ = select(true, false, _e5188);
                                                } else {
                                                    phi_5073_ = type_23();
                                                    phi_5074_ = true;
                                                }
                                                let _e5191 = phi_5073_;
                                                let _e5193 = phi_5074_;
                                                phi_5075_ = _e5191;
                                                phi_5076_ = _e5193;
                                            } else {
                                                phi_5075_ = type_23();
                                                phi_5076_ = true;
                                            }
                                            let _e5195 = phi_5075_;
                                            let _e5197 = phi_5076_;
                                            phi_5077_ = _e5195;
                                            phi_5078_ = _e5197;
                                        } else {
                                            phi_5077_ = type_23();
                                            phi_5078_ = true;
                                        }
                                        let _e5199 = phi_5077_;
                                        let _e5201 = phi_5078_;
                                        if _e5201 {
                                            phi_5083_ = type_23(0u, type_23().member_1);
                                        } else {
                                            phi_5083_ = _e5199;
                                        }
                                        let _e5206 = phi_5083_;
                                        local_449 = _e5206;
                                        if (bitcast<i32>(_e5206.member) != 0i) {
                                            let _e5210 = local_449;
                                            local_525 = array<f32, 3>(_e5210.member_1.member[0], _e5210.member_1.member[1], _e5210.member_1.member[2]);
                                            let _e5217 = local_423;
                                            let _e5223 = local_424;
                                            local_524 = _e5223;
                                            local_523 = array<f32, 3>(_e5217.member_1[0], _e5217.member_1[1], _e5217.member_1[2]);
                                            let _e5224 = local_426;
                                            if _e5224 {
                                            } else {
                                                phi_6509_ = true;
                                                break;
                                            }
                                            let _e5225 = local_425;
                                            let _e5227 = local_524[_e5225];
                                            local_450 = _e5227;
                                            if (_e5227 <= 0f) {
                                                let _e5288 = local_525;
                                                phi_6515_ = _e5033;
                                                phi_5210_ = type_25(array<f32, 3>(_e5288[0], _e5288[1], _e5288[2]), array<f32, 3>(0f, 0f, 0f));
                                            } else {
                                                let _e5229 = local_525;
                                                local_526 = _e5229;
                                                local_527 = array<f32, 3>(0f, 0f, 0f);
                                                phi_5138_ = 0u;
                                                loop {
                                                    let _e5231 = phi_5138_;
                                                    local_451 = _e5231;
                                                    let _e5232 = local_451;
                                                    let _e5233 = (_e5232 < 3u);
                                                    local_452 = _e5233;
                                                    if _e5233 {
                                                        let _e5234 = local_452;
                                                        if _e5234 {
                                                        } else {
                                                            phi_6462_ = true;
                                                            break;
                                                        }
                                                        let _e5235 = local_451;
                                                        let _e5237 = local_523[_e5235];
                                                        local_453 = _e5237;
                                                        let _e5238 = local_452;
                                                        if _e5238 {
                                                        } else {
                                                            phi_6462_ = true;
                                                            break;
                                                        }
                                                        let _e5239 = local_451;
                                                        let _e5241 = local_525[_e5239];
                                                        let _e5242 = local_453;
                                                        if (_e5241 > _e5242) {
                                                            let _e5244 = local_452;
                                                            if _e5244 {
                                                            } else {
                                                                phi_6462_ = true;
                                                                break;
                                                            }
                                                            let _e5245 = local_525[_e5239];
                                                            let _e5246 = local_453;
                                                            local_454 = (_e5245 - _e5246);
                                                            let _e5248 = local_452;
                                                            if _e5248 {
                                                            } else {
                                                                phi_6462_ = true;
                                                                break;
                                                            }
                                                            let _e5249 = local_451;
                                                            let _e5251 = local_450;
                                                            let _e5252 = local_454;
                                                            local_527[_e5249] = (_e5251 * _e5252);
                                                            let _e5254 = local_450;
                                                            local_455 = (1f - _e5254);
                                                            let _e5256 = local_452;
                                                            if _e5256 {
                                                            } else {
                                                                phi_6462_ = true;
                                                                break;
                                                            }
                                                            let _e5257 = local_525[_e5239];
                                                            let _e5258 = local_455;
                                                            local_456 = (_e5258 * _e5257);
                                                            let _e5260 = local_450;
                                                            let _e5261 = local_453;
                                                            local_457 = (_e5260 * _e5261);
                                                            let _e5263 = local_452;
                                                            if _e5263 {
                                                            } else {
                                                                phi_6462_ = true;
                                                                break;
                                                            }
                                                            let _e5264 = local_451;
                                                            let _e5266 = local_456;
                                                            let _e5267 = local_457;
                                                            local_526[_e5264] = (_e5266 + _e5267);
                                                        }
                                                        let _e5269 = local_451;
                                                        phi_5139_ = (_e5269 + 1u);
                                                    } else {
                                                        phi_5139_ = u32();
                                                    }
                                                    let _e5272 = phi_5139_;
                                                    continue;
                                                    continuing {
                                                        let _e5273 = local_452;
                                                        phi_5138_ = _e5272;
                                                        phi_6462_ = _e5033;
                                                        break if !(_e5273);
                                                    }
                                                }
                                                let _e5276 = phi_6462_;
                                                phi_6509_ = _e5276;
                                                if _e5276 {
                                                    break;
                                                }
                                                let _e5277 = local_526;
                                                let _e5282 = local_527;
                                                phi_6515_ = _e5276;
                                                phi_5210_ = type_25(array<f32, 3>(_e5277[0], _e5277[1], _e5277[2]), array<f32, 3>(_e5282[0], _e5282[1], _e5282[2]));
                                            }
                                            let _e5295 = phi_6515_;
                                            let _e5297 = phi_5210_;
                                            phi_6514_ = _e5295;
                                            phi_5219_ = array<u32, 3>(bitcast<u32>(_e5297.member[0]), bitcast<u32>(_e5297.member[1]), bitcast<u32>(_e5297.member[2]));
                                        } else {
                                            phi_6514_ = _e5033;
                                            phi_5219_ = _e5083;
                                        }
                                        let _e5307 = phi_6514_;
                                        let _e5309 = phi_5219_;
                                        phi_6513_ = _e5307;
                                        phi_5220_ = _e5309;
                                    } else {
                                        phi_6513_ = _e5033;
                                        phi_5220_ = _e5083;
                                    }
                                    let _e5311 = phi_6513_;
                                    let _e5313 = phi_5220_;
                                    local_458 = _e5313;
                                    local_459 = _e5313[0];
                                    let _e5315 = local_430;
                                    let _e5316 = local_6;
                                    if (_e5315 < _e5316) {
                                    } else {
                                        phi_6509_ = true;
                                        break;
                                    }
                                    let _e5318 = local_430;
                                    let _e5321 = local_459;
                                    global_8.member[_e5318] = _e5321;
                                    let _e5322 = local_458;
                                    local_460 = _e5322[1];
                                    let _e5324 = local_433;
                                    let _e5325 = local_6;
                                    if (_e5324 < _e5325) {
                                    } else {
                                        phi_6509_ = true;
                                        break;
                                    }
                                    let _e5327 = local_433;
                                    let _e5330 = local_460;
                                    global_8.member[_e5327] = _e5330;
                                    let _e5331 = local_458;
                                    local_461 = _e5331[2];
                                    let _e5333 = local_436;
                                    let _e5334 = local_6;
                                    if (_e5333 < _e5334) {
                                    } else {
                                        phi_6509_ = true;
                                        break;
                                    }
                                    let _e5336 = local_436;
                                    let _e5339 = local_461;
                                    global_8.member[_e5336] = _e5339;
                                    phi_6512_ = _e5311;
                                } else {
                                    phi_6512_ = _e5033;
                                }
                                let _e5341 = phi_6512_;
                                phi_6511_ = _e5341;
                            } else {
                                phi_6511_ = _e5033;
                            }
                            let _e5343 = phi_6511_;
                            let _e5344 = local_425;
                            phi_6510_ = _e5343;
                            phi_4848_ = (_e5344 + 1u);
                        } else {
                            phi_6510_ = _e5033;
                            phi_4848_ = u32();
                        }
                        let _e5347 = phi_6510_;
                        let _e5349 = phi_4848_;
                        continue;
                        continuing {
                            let _e5350 = local_426;
                            phi_6490_ = _e5347;
                            phi_4847_ = _e5349;
                            phi_6509_ = _e5347;
                            break if !(_e5350);
                        }
                    }
                    let _e5353 = phi_6509_;
                    if _e5353 {
                        break;
                    }
                }
            }
            let _e5354 = local;
            if (_e5354 == 63u) {
                let _e5356 = local_12;
                if _e5356 {
                    let _e5357 = local_11;
                    phi_5269_ = (_e5357 + 1u);
                } else {
                    phi_5269_ = _e636;
                }
                let _e5360 = phi_5269_;
                let _e5361 = (_e5360 / 8u);
                local_462 = _e5361;
                if ((_e5360 % 8u) > 0u) {
                    let _e5364 = local_462;
                    phi_5285_ = (_e5364 + 1u);
                } else {
                    phi_5285_ = _e5361;
                }
                let _e5367 = phi_5285_;
                let _e5368 = local_9;
                let _e5370 = local_8;
                local_463 = ((_e5368 * _e5367) + _e5370);
                let _e5372 = local_244;
                let _e5373 = (_e5372 + 63u);
                local_464 = _e5373;
                if (_e5373 < 384u) {
                } else {
                    break;
                }
                let _e5375 = local_464;
                let _e5377 = global_10[_e5375];
                local_465 = _e5377;
                let _e5378 = local_463;
                let _e5379 = local_4;
                if (_e5378 < _e5379) {
                } else {
                    break;
                }
                let _e5381 = local_463;
                let _e5384 = local_465;
                global_6.member[_e5381] = _e5384;
                let _e5385 = local_236;
                let _e5386 = (_e5385 + 63u);
                local_466 = _e5386;
                if (_e5386 < 384u) {
                } else {
                    break;
                }
                let _e5388 = local_466;
                let _e5390 = global_10[_e5388];
                local_467 = _e5390;
                local_512 = select(8u, _e5390, (_e5390 < 8u));
                let _e5393 = local_260;
                let _e5394 = local_5;
                if (_e5393 < _e5394) {
                } else {
                    break;
                }
                let _e5396 = local_260;
                let _e5399 = local_512;
                global_7.member[_e5396] = _e5399;
                let _e5400 = local_260;
                local_468 = (_e5400 + 1u);
                let _e5402 = local_252;
                let _e5403 = (_e5402 + 63u);
                local_469 = _e5403;
                if (_e5403 < 384u) {
                } else {
                    break;
                }
                let _e5405 = local_469;
                let _e5407 = global_10[_e5405];
                local_470 = _e5407;
                let _e5408 = local_468;
                let _e5409 = local_5;
                if (_e5408 < _e5409) {
                } else {
                    break;
                }
                let _e5411 = local_468;
                let _e5414 = local_470;
                global_7.member[_e5411] = _e5414;
                let _e5415 = local_467;
                if (_e5415 > 8u) {
                    let _e5417 = local_467;
                    local_471 = (_e5417 - 8u);
                    let _e5419 = local_7;
                    if (1u < _e5419) {
                    } else {
                        break;
                    }
                    let _e5423 = local_471;
                    let _e5424 = atomicAdd((&global_9.member[1u]), _e5423);
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
fn ring_gather_downsample(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
