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

struct type_34 {
    member: u32,
    member_1: u32,
}

struct type_45 {
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
var<storage, read_write> global_9: type_45;
var<workgroup> global_10: array<u32, 384>;
var<private> global_11: u32;
var<private> global_12: u32;
var<private> global_13: u32;
var<private> global_14: u32;
var<private> global_15: u32 = 2143289344u;

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
    var local_16: bool;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: bool;
    var local_24: f32;
    var local_25: u32;
    var local_26: array<f32, 4>;
    var local_27: array<f32, 3>;
    var local_28: f32;
    var local_29: array<f32, 4>;
    var local_30: f32;
    var local_31: f32;
    var local_32: array<f32, 3>;
    var local_33: array<f32, 2>;
    var local_34: u32;
    var local_35: f32;
    var local_36: bool;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: f32;
    var local_42: u32;
    var local_43: f32;
    var local_44: u32;
    var local_45: f32;
    var local_46: f32;
    var local_47: f32;
    var local_48: f32;
    var local_49: array<f32, 3>;
    var local_50: f32;
    var local_51: u32;
    var local_52: bool;
    var local_53: type_23;
    var local_54: array<f32, 3>;
    var local_55: f32;
    var local_56: u32;
    var local_57: f32;
    var local_58: f32;
    var local_59: f32;
    var local_60: u32;
    var local_61: bool;
    var local_62: f32;
    var local_63: f32;
    var local_64: f32;
    var local_65: f32;
    var local_66: f32;
    var local_67: array<f32, 3>;
    var local_68: f32;
    var local_69: f32;
    var local_70: f32;
    var local_71: bool;
    var local_72: bool;
    var local_73: f32;
    var local_74: bool;
    var local_75: array<f32, 3>;
    var local_76: array<f32, 3>;
    var local_77: f32;
    var local_78: f32;
    var local_79: f32;
    var local_80: f32;
    var local_81: f32;
    var local_82: f32;
    var local_83: u32;
    var local_84: f32;
    var local_85: bool;
    var local_86: f32;
    var local_87: f32;
    var local_88: type_30;
    var local_89: u32;
    var local_90: f32;
    var local_91: f32;
    var local_92: u32;
    var local_93: bool;
    var local_94: u32;
    var local_95: u32;
    var local_96: u32;
    var local_97: u32;
    var local_98: array<f32, 3>;
    var local_99: f32;
    var local_100: bool;
    var local_101: f32;
    var local_102: u32;
    var local_103: u32;
    var local_104: array<f32, 3>;
    var local_105: f32;
    var local_106: bool;
    var local_107: u32;
    var local_108: u32;
    var local_109: i32;
    var local_110: i32;
    var local_111: u32;
    var local_112: u32;
    var local_113: u32;
    var local_114: u32;
    var local_115: f32;
    var local_116: u32;
    var local_117: f32;
    var local_118: u32;
    var local_119: f32;
    var local_120: f32;
    var local_121: f32;
    var local_122: f32;
    var local_123: array<f32, 3>;
    var local_124: f32;
    var local_125: u32;
    var local_126: bool;
    var local_127: type_23;
    var local_128: f32;
    var local_129: f32;
    var local_130: f32;
    var local_131: f32;
    var local_132: f32;
    var local_133: f32;
    var local_134: f32;
    var local_135: f32;
    var local_136: u32;
    var local_137: bool;
    var local_138: u32;
    var local_139: u32;
    var local_140: u32;
    var local_141: u32;
    var local_142: f32;
    var local_143: u32;
    var local_144: f32;
    var local_145: u32;
    var local_146: f32;
    var local_147: f32;
    var local_148: f32;
    var local_149: f32;
    var local_150: array<f32, 3>;
    var local_151: f32;
    var local_152: u32;
    var local_153: bool;
    var local_154: type_23;
    var local_155: array<f32, 3>;
    var local_156: f32;
    var local_157: u32;
    var local_158: f32;
    var local_159: f32;
    var local_160: f32;
    var local_161: f32;
    var local_162: f32;
    var local_163: f32;
    var local_164: f32;
    var local_165: f32;
    var local_166: u32;
    var local_167: array<f32, 4>;
    var local_168: array<f32, 3>;
    var local_169: f32;
    var local_170: array<f32, 4>;
    var local_171: f32;
    var local_172: f32;
    var local_173: array<f32, 3>;
    var local_174: array<f32, 2>;
    var local_175: u32;
    var local_176: f32;
    var local_177: bool;
    var local_178: u32;
    var local_179: u32;
    var local_180: u32;
    var local_181: u32;
    var local_182: f32;
    var local_183: u32;
    var local_184: f32;
    var local_185: u32;
    var local_186: f32;
    var local_187: f32;
    var local_188: f32;
    var local_189: f32;
    var local_190: array<f32, 3>;
    var local_191: f32;
    var local_192: u32;
    var local_193: bool;
    var local_194: type_23;
    var local_195: array<f32, 3>;
    var local_196: f32;
    var local_197: u32;
    var local_198: f32;
    var local_199: f32;
    var local_200: f32;
    var local_201: u32;
    var local_202: bool;
    var local_203: f32;
    var local_204: f32;
    var local_205: f32;
    var local_206: f32;
    var local_207: f32;
    var local_208: array<f32, 3>;
    var local_209: f32;
    var local_210: f32;
    var local_211: f32;
    var local_212: bool;
    var local_213: bool;
    var local_214: f32;
    var local_215: bool;
    var local_216: array<f32, 3>;
    var local_217: array<f32, 3>;
    var local_218: f32;
    var local_219: f32;
    var local_220: f32;
    var local_221: f32;
    var local_222: f32;
    var local_223: f32;
    var local_224: u32;
    var local_225: f32;
    var local_226: bool;
    var local_227: f32;
    var local_228: f32;
    var local_229: type_30;
    var local_230: f32;
    var local_231: f32;
    var local_232: f32;
    var local_233: f32;
    var local_234: u32;
    var local_235: u32;
    var local_236: u32;
    var local_237: u32;
    var local_238: u32;
    var local_239: bool;
    var local_240: bool;
    var local_241: u32;
    var local_242: u32;
    var local_243: u32;
    var local_244: u32;
    var local_245: u32;
    var local_246: u32;
    var local_247: u32;
    var local_248: u32;
    var local_249: u32;
    var local_250: bool;
    var local_251: u32;
    var local_252: u32;
    var local_253: bool;
    var local_254: u32;
    var local_255: u32;
    var local_256: u32;
    var local_257: u32;
    var local_258: u32;
    var local_259: u32;
    var local_260: bool;
    var local_261: u32;
    var local_262: u32;
    var local_263: u32;
    var local_264: u32;
    var local_265: u32;
    var local_266: u32;
    var local_267: bool;
    var local_268: u32;
    var local_269: u32;
    var local_270: u32;
    var local_271: bool;
    var local_272: u32;
    var local_273: u32;
    var local_274: u32;
    var local_275: u32;
    var local_276: u32;
    var local_277: u32;
    var local_278: bool;
    var local_279: u32;
    var local_280: u32;
    var local_281: u32;
    var local_282: u32;
    var local_283: u32;
    var local_284: u32;
    var local_285: bool;
    var local_286: u32;
    var local_287: u32;
    var local_288: u32;
    var local_289: u32;
    var local_290: u32;
    var local_291: u32;
    var local_292: bool;
    var local_293: u32;
    var local_294: u32;
    var local_295: bool;
    var local_296: u32;
    var local_297: u32;
    var local_298: u32;
    var local_299: bool;
    var local_300: u32;
    var local_301: u32;
    var local_302: u32;
    var local_303: u32;
    var local_304: u32;
    var local_305: bool;
    var local_306: u32;
    var local_307: u32;
    var local_308: u32;
    var local_309: u32;
    var local_310: u32;
    var local_311: u32;
    var local_312: bool;
    var local_313: u32;
    var local_314: u32;
    var local_315: bool;
    var local_316: u32;
    var local_317: u32;
    var local_318: u32;
    var local_319: u32;
    var local_320: u32;
    var local_321: u32;
    var local_322: bool;
    var local_323: u32;
    var local_324: u32;
    var local_325: u32;
    var local_326: u32;
    var local_327: u32;
    var local_328: u32;
    var local_329: bool;
    var local_330: u32;
    var local_331: u32;
    var local_332: u32;
    var local_333: u32;
    var local_334: u32;
    var local_335: u32;
    var local_336: bool;
    var local_337: u32;
    var local_338: u32;
    var local_339: bool;
    var local_340: u32;
    var local_341: u32;
    var local_342: u32;
    var local_343: bool;
    var local_344: u32;
    var local_345: u32;
    var local_346: u32;
    var local_347: u32;
    var local_348: u32;
    var local_349: bool;
    var local_350: u32;
    var local_351: u32;
    var local_352: u32;
    var local_353: u32;
    var local_354: u32;
    var local_355: u32;
    var local_356: bool;
    var local_357: u32;
    var local_358: u32;
    var local_359: bool;
    var local_360: u32;
    var local_361: u32;
    var local_362: u32;
    var local_363: u32;
    var local_364: u32;
    var local_365: u32;
    var local_366: u32;
    var local_367: u32;
    var local_368: u32;
    var local_369: u32;
    var local_370: u32;
    var local_371: u32;
    var local_372: u32;
    var local_373: array<f32, 3>;
    var local_374: f32;
    var local_375: bool;
    var local_376: f32;
    var local_377: u32;
    var local_378: u32;
    var local_379: array<f32, 3>;
    var local_380: f32;
    var local_381: bool;
    var local_382: u32;
    var local_383: u32;
    var local_384: i32;
    var local_385: i32;
    var local_386: u32;
    var local_387: u32;
    var local_388: u32;
    var local_389: u32;
    var local_390: f32;
    var local_391: u32;
    var local_392: f32;
    var local_393: u32;
    var local_394: f32;
    var local_395: f32;
    var local_396: f32;
    var local_397: f32;
    var local_398: array<f32, 3>;
    var local_399: f32;
    var local_400: u32;
    var local_401: bool;
    var local_402: type_23;
    var local_403: f32;
    var local_404: f32;
    var local_405: f32;
    var local_406: f32;
    var local_407: f32;
    var local_408: f32;
    var local_409: f32;
    var local_410: f32;
    var local_411: u32;
    var local_412: bool;
    var local_413: u32;
    var local_414: u32;
    var local_415: u32;
    var local_416: u32;
    var local_417: f32;
    var local_418: u32;
    var local_419: f32;
    var local_420: u32;
    var local_421: f32;
    var local_422: f32;
    var local_423: f32;
    var local_424: f32;
    var local_425: array<f32, 3>;
    var local_426: f32;
    var local_427: u32;
    var local_428: bool;
    var local_429: type_23;
    var local_430: array<f32, 3>;
    var local_431: f32;
    var local_432: f32;
    var local_433: u32;
    var local_434: f32;
    var local_435: f32;
    var local_436: f32;
    var local_437: f32;
    var local_438: f32;
    var local_439: f32;
    var local_440: u32;
    var local_441: array<f32, 4>;
    var local_442: array<f32, 3>;
    var local_443: f32;
    var local_444: array<f32, 4>;
    var local_445: f32;
    var local_446: f32;
    var local_447: array<f32, 3>;
    var local_448: array<f32, 2>;
    var local_449: u32;
    var local_450: f32;
    var local_451: bool;
    var local_452: u32;
    var local_453: u32;
    var local_454: u32;
    var local_455: u32;
    var local_456: f32;
    var local_457: u32;
    var local_458: f32;
    var local_459: u32;
    var local_460: f32;
    var local_461: f32;
    var local_462: f32;
    var local_463: f32;
    var local_464: array<f32, 3>;
    var local_465: f32;
    var local_466: u32;
    var local_467: bool;
    var local_468: type_23;
    var local_469: array<f32, 3>;
    var local_470: f32;
    var local_471: u32;
    var local_472: f32;
    var local_473: f32;
    var local_474: f32;
    var local_475: u32;
    var local_476: bool;
    var local_477: f32;
    var local_478: f32;
    var local_479: f32;
    var local_480: f32;
    var local_481: f32;
    var local_482: array<f32, 3>;
    var local_483: f32;
    var local_484: f32;
    var local_485: f32;
    var local_486: bool;
    var local_487: bool;
    var local_488: f32;
    var local_489: bool;
    var local_490: array<f32, 3>;
    var local_491: array<f32, 3>;
    var local_492: f32;
    var local_493: f32;
    var local_494: f32;
    var local_495: f32;
    var local_496: f32;
    var local_497: f32;
    var local_498: u32;
    var local_499: f32;
    var local_500: bool;
    var local_501: f32;
    var local_502: f32;
    var local_503: type_30;
    var local_504: u32;
    var local_505: u32;
    var local_506: bool;
    var local_507: u32;
    var local_508: u32;
    var local_509: f32;
    var local_510: f32;
    var local_511: f32;
    var local_512: f32;
    var local_513: f32;
    var local_514: f32;
    var local_515: u32;
    var local_516: u32;
    var local_517: u32;
    var local_518: u32;
    var local_519: u32;
    var local_520: u32;
    var local_521: u32;
    var local_522: u32;
    var local_523: u32;
    var local_524: u32;
    var local_525: u32;
    var local_526: u32;
    var local_527: u32;
    var local_528: u32;
    var local_529: u32;
    var local_530: type_31;
    var local_531: array<f32, 4>;
    var local_532: u32;
    var local_533: bool;
    var local_534: u32;
    var local_535: u32;
    var local_536: u32;
    var local_537: u32;
    var local_538: bool;
    var local_539: u32;
    var local_540: u32;
    var local_541: bool;
    var local_542: u32;
    var local_543: u32;
    var local_544: bool;
    var local_545: u32;
    var local_546: f32;
    var local_547: f32;
    var local_548: f32;
    var local_549: f32;
    var local_550: f32;
    var local_551: f32;
    var local_552: array<f32, 3>;
    var local_553: f32;
    var local_554: u32;
    var local_555: bool;
    var local_556: type_23;
    var local_557: f32;
    var local_558: u32;
    var local_559: bool;
    var local_560: f32;
    var local_561: f32;
    var local_562: f32;
    var local_563: f32;
    var local_564: f32;
    var local_565: array<u32, 3>;
    var local_566: u32;
    var local_567: u32;
    var local_568: u32;
    var local_569: u32;
    var local_570: u32;
    var local_571: u32;
    var local_572: u32;
    var local_573: u32;
    var local_574: u32;
    var local_575: u32;
    var local_576: u32;
    var local_577: u32;
    var local_578: u32;
    var local_579: f32;
    var local_580: f32;
    var local_581: f32;
    var local_582: f32;
    var local_583: f32;
    var local_584: bool;
    var local_585: f32;
    var local_586: f32;
    var local_587: f32;
    var local_588: f32;
    var local_589: f32;
    var local_590: f32;
    var local_591: f32;
    var local_592: f32;
    var local_593: f32;
    var local_594: bool;
    var local_595: array<f32, 4>;
    var local_596: array<f32, 4>;
    var local_597: f32;
    var local_598: f32;
    var local_599: f32;
    var local_600: f32;
    var local_601: f32;
    var local_602: f32;
    var local_603: f32;
    var local_604: f32;
    var local_605: f32;
    var local_606: f32;
    var local_607: f32;
    var local_608: bool;
    var local_609: f32;
    var local_610: f32;
    var local_611: u32;
    var local_612: u32;
    var local_613: u32;
    var local_614: u32;
    var local_615: u32;
    var local_616: f32;
    var local_617: f32;
    var local_618: f32;
    var local_619: f32;
    var local_620: f32;
    var local_621: u32;
    var local_622: f32;
    var local_623: array<f32, 3>;
    var local_624: array<f32, 4>;
    var local_625: array<f32, 4>;
    var local_626: array<f32, 3>;
    var local_627: array<f32, 4>;
    var local_628: array<f32, 4>;
    var local_629: array<f32, 3>;
    var local_630: array<f32, 4>;
    var local_631: array<f32, 4>;
    var local_632: array<f32, 3>;
    var local_633: array<f32, 4>;
    var local_634: array<f32, 3>;
    var local_635: array<f32, 3>;
    var local_636: array<f32, 3>;
    var local_637: array<f32, 9>;
    var local_638: array<f32, 3>;
    var local_639: array<f32, 3>;
    var local_640: array<f32, 3>;
    var local_641: array<f32, 4>;
    var local_642: array<f32, 3>;
    var local_643: array<f32, 3>;
    var local_644: array<f32, 3>;
    var local_645: array<f32, 4>;
    var local_646: array<f32, 9>;
    var local_647: array<f32, 3>;
    var local_648: array<f32, 3>;
    var local_649: array<f32, 3>;
    var local_650: array<f32, 4>;
    var phi_330_: u32;
    var phi_348_: u32;
    var phi_5944_: bool;
    var phi_367_: u32;
    var phi_370_: array<f32, 4>;
    var phi_372_: array<f32, 3>;
    var phi_374_: f32;
    var phi_376_: array<f32, 4>;
    var phi_378_: f32;
    var phi_380_: f32;
    var phi_382_: array<f32, 3>;
    var phi_384_: array<f32, 2>;
    var phi_386_: u32;
    var phi_388_: f32;
    var phi_456_: bool;
    var phi_470_: bool;
    var phi_475_: f32;
    var phi_485_: bool;
    var phi_499_: bool;
    var phi_504_: f32;
    var phi_514_: bool;
    var phi_528_: bool;
    var phi_533_: f32;
    var phi_567_: bool;
    var phi_573_: type_23;
    var phi_575_: type_23;
    var phi_576_: bool;
    var phi_577_: type_23;
    var phi_578_: bool;
    var phi_579_: type_23;
    var phi_580_: bool;
    var phi_585_: type_23;
    var phi_622_: bool;
    var phi_650_: f32;
    var phi_651_: f32;
    var phi_653_: f32;
    var phi_687_: u32;
    var phi_688_: u32;
    var phi_5928_: bool;
    var phi_5975_: bool;
    var phi_759_: type_25;
    var phi_5969_: bool;
    var phi_879_: array<f32, 4>;
    var phi_880_: array<f32, 3>;
    var phi_881_: f32;
    var phi_882_: array<f32, 4>;
    var phi_883_: f32;
    var phi_884_: f32;
    var phi_885_: array<f32, 3>;
    var phi_886_: array<f32, 2>;
    var phi_887_: u32;
    var phi_888_: f32;
    var phi_5968_: bool;
    var phi_889_: array<f32, 4>;
    var phi_890_: array<f32, 3>;
    var phi_891_: f32;
    var phi_892_: array<f32, 4>;
    var phi_893_: f32;
    var phi_894_: f32;
    var phi_895_: array<f32, 3>;
    var phi_896_: array<f32, 2>;
    var phi_897_: u32;
    var phi_898_: f32;
    var phi_5967_: bool;
    var phi_899_: array<f32, 4>;
    var phi_900_: array<f32, 3>;
    var phi_901_: f32;
    var phi_902_: array<f32, 4>;
    var phi_903_: f32;
    var phi_904_: f32;
    var phi_905_: array<f32, 3>;
    var phi_906_: array<f32, 2>;
    var phi_907_: u32;
    var phi_908_: f32;
    var phi_5966_: bool;
    var phi_368_: u32;
    var phi_371_: array<f32, 4>;
    var phi_373_: array<f32, 3>;
    var phi_375_: f32;
    var phi_377_: array<f32, 4>;
    var phi_379_: f32;
    var phi_381_: f32;
    var phi_383_: array<f32, 3>;
    var phi_385_: array<f32, 2>;
    var phi_387_: u32;
    var phi_389_: f32;
    var phi_5965_: bool;
    var phi_939_: array<f32, 3>;
    var phi_940_: f32;
    var phi_942_: array<f32, 3>;
    var phi_943_: f32;
    var phi_944_: bool;
    var phi_948_: array<f32, 3>;
    var phi_964_: array<f32, 3>;
    var phi_965_: f32;
    var phi_971_: f32;
    var phi_990_: u32;
    var phi_993_: f32;
    var phi_1037_: f32;
    var phi_991_: u32;
    var phi_994_: f32;
    var phi_5976_: bool;
    var phi_5989_: bool;
    var phi_1043_: f32;
    var phi_1044_: f32;
    var phi_1045_: array<f32, 2>;
    var phi_5988_: bool;
    var phi_1047_: type_30;
    var phi_1070_: u32;
    var phi_1071_: u32;
    var phi_5985_: bool;
    var phi_5994_: bool;
    var phi_1115_: u32;
    var phi_1118_: u32;
    var phi_1120_: array<f32, 3>;
    var phi_1122_: f32;
    var phi_1137_: u32;
    var phi_1140_: u32;
    var phi_1142_: array<f32, 3>;
    var phi_1144_: f32;
    var phi_1172_: i32;
    var phi_1173_: i32;
    var phi_1174_: i32;
    var phi_1175_: i32;
    var phi_1176_: bool;
    var phi_1199_: i32;
    var phi_1200_: i32;
    var phi_1201_: bool;
    var phi_1202_: i32;
    var phi_1203_: i32;
    var phi_1204_: bool;
    var phi_1274_: bool;
    var phi_1288_: bool;
    var phi_1293_: f32;
    var phi_1303_: bool;
    var phi_1317_: bool;
    var phi_1322_: f32;
    var phi_1332_: bool;
    var phi_1346_: bool;
    var phi_1351_: f32;
    var phi_1385_: bool;
    var phi_1391_: type_23;
    var phi_1393_: type_23;
    var phi_1394_: bool;
    var phi_1395_: type_23;
    var phi_1396_: bool;
    var phi_1397_: type_23;
    var phi_1398_: bool;
    var phi_1403_: type_23;
    var phi_1443_: u32;
    var phi_1444_: array<f32, 3>;
    var phi_1445_: u32;
    var phi_1446_: array<f32, 3>;
    var phi_1447_: f32;
    var phi_1448_: u32;
    var phi_1449_: array<f32, 3>;
    var phi_1450_: f32;
    var phi_1451_: u32;
    var phi_1452_: array<f32, 3>;
    var phi_1453_: f32;
    var phi_1454_: u32;
    var phi_1455_: array<f32, 3>;
    var phi_1456_: f32;
    var phi_1457_: u32;
    var phi_1458_: array<f32, 3>;
    var phi_1459_: f32;
    var phi_1460_: u32;
    var phi_1461_: array<f32, 3>;
    var phi_1462_: f32;
    var phi_1463_: u32;
    var phi_1464_: array<f32, 3>;
    var phi_1465_: f32;
    var phi_1138_: u32;
    var phi_1141_: u32;
    var phi_1143_: array<f32, 3>;
    var phi_1145_: f32;
    var phi_5990_: bool;
    var phi_6036_: bool;
    var phi_1116_: u32;
    var phi_1119_: u32;
    var phi_1121_: array<f32, 3>;
    var phi_1123_: f32;
    var phi_6035_: bool;
    var phi_1493_: u32;
    var phi_1562_: bool;
    var phi_1576_: bool;
    var phi_1581_: f32;
    var phi_1591_: bool;
    var phi_1605_: bool;
    var phi_1610_: f32;
    var phi_1620_: bool;
    var phi_1634_: bool;
    var phi_1639_: f32;
    var phi_1673_: bool;
    var phi_1679_: type_23;
    var phi_1681_: type_23;
    var phi_1682_: bool;
    var phi_1683_: type_23;
    var phi_1684_: bool;
    var phi_1685_: type_23;
    var phi_1686_: bool;
    var phi_1691_: type_23;
    var phi_1731_: bool;
    var phi_1759_: f32;
    var phi_1760_: f32;
    var phi_1762_: f32;
    var phi_1779_: f32;
    var phi_1846_: f32;
    var phi_1494_: u32;
    var phi_6037_: bool;
    var phi_6249_: bool;
    var phi_6180_: f32;
    var phi_6132_: f32;
    var phi_6084_: f32;
    var phi_1898_: bool;
    var phi_1899_: bool;
    var phi_1900_: bool;
    var phi_1901_: bool;
    var phi_1902_: bool;
    var phi_6244_: bool;
    var phi_1914_: u32;
    var phi_1917_: array<f32, 4>;
    var phi_1919_: array<f32, 3>;
    var phi_1921_: f32;
    var phi_1923_: array<f32, 4>;
    var phi_1925_: f32;
    var phi_1927_: f32;
    var phi_1929_: array<f32, 3>;
    var phi_1931_: array<f32, 2>;
    var phi_1933_: u32;
    var phi_1935_: f32;
    var phi_2003_: bool;
    var phi_2017_: bool;
    var phi_2022_: f32;
    var phi_2032_: bool;
    var phi_2046_: bool;
    var phi_2051_: f32;
    var phi_2061_: bool;
    var phi_2075_: bool;
    var phi_2080_: f32;
    var phi_2114_: bool;
    var phi_2120_: type_23;
    var phi_2122_: type_23;
    var phi_2123_: bool;
    var phi_2124_: type_23;
    var phi_2125_: bool;
    var phi_2126_: type_23;
    var phi_2127_: bool;
    var phi_2132_: type_23;
    var phi_2169_: bool;
    var phi_2197_: f32;
    var phi_2198_: f32;
    var phi_2200_: f32;
    var phi_2246_: u32;
    var phi_2247_: u32;
    var phi_6228_: bool;
    var phi_6278_: bool;
    var phi_2318_: type_25;
    var phi_6272_: bool;
    var phi_2438_: array<f32, 4>;
    var phi_2439_: array<f32, 3>;
    var phi_2440_: f32;
    var phi_2441_: array<f32, 4>;
    var phi_2442_: f32;
    var phi_2443_: f32;
    var phi_2444_: array<f32, 3>;
    var phi_2445_: array<f32, 2>;
    var phi_2446_: u32;
    var phi_2447_: f32;
    var phi_6271_: bool;
    var phi_2448_: array<f32, 4>;
    var phi_2449_: array<f32, 3>;
    var phi_2450_: f32;
    var phi_2451_: array<f32, 4>;
    var phi_2452_: f32;
    var phi_2453_: f32;
    var phi_2454_: array<f32, 3>;
    var phi_2455_: array<f32, 2>;
    var phi_2456_: u32;
    var phi_2457_: f32;
    var phi_6270_: bool;
    var phi_2458_: array<f32, 4>;
    var phi_2459_: array<f32, 3>;
    var phi_2460_: f32;
    var phi_2461_: array<f32, 4>;
    var phi_2462_: f32;
    var phi_2463_: f32;
    var phi_2464_: array<f32, 3>;
    var phi_2465_: array<f32, 2>;
    var phi_2466_: u32;
    var phi_2467_: f32;
    var phi_6269_: bool;
    var phi_1915_: u32;
    var phi_1918_: array<f32, 4>;
    var phi_1920_: array<f32, 3>;
    var phi_1922_: f32;
    var phi_1924_: array<f32, 4>;
    var phi_1926_: f32;
    var phi_1928_: f32;
    var phi_1930_: array<f32, 3>;
    var phi_1932_: array<f32, 2>;
    var phi_1934_: u32;
    var phi_1936_: f32;
    var phi_6268_: bool;
    var phi_2498_: array<f32, 3>;
    var phi_2499_: f32;
    var phi_2501_: array<f32, 3>;
    var phi_2502_: f32;
    var phi_2503_: bool;
    var phi_2507_: array<f32, 3>;
    var phi_2523_: array<f32, 3>;
    var phi_2524_: f32;
    var phi_2530_: f32;
    var phi_2549_: u32;
    var phi_2552_: f32;
    var phi_2596_: f32;
    var phi_2550_: u32;
    var phi_2553_: f32;
    var phi_6279_: bool;
    var phi_6301_: bool;
    var phi_2602_: f32;
    var phi_2603_: f32;
    var phi_2604_: array<f32, 2>;
    var phi_6300_: bool;
    var phi_2606_: type_30;
    var phi_2622_: f32;
    var phi_2628_: f32;
    var phi_6296_: bool;
    var phi_2631_: f32;
    var phi_6295_: bool;
    var phi_2633_: f32;
    var phi_2634_: f32;
    var phi_2635_: u32;
    var phi_6294_: bool;
    var phi_2636_: f32;
    var phi_2637_: f32;
    var phi_2638_: u32;
    var phi_6293_: bool;
    var phi_2639_: f32;
    var phi_2640_: f32;
    var phi_2641_: u32;
    var phi_2680_: type_34;
    var phi_2682_: type_34;
    var phi_2683_: bool;
    var phi_2684_: type_34;
    var phi_2685_: bool;
    var phi_2690_: type_34;
    var phi_2840_: u32;
    var phi_2843_: u32;
    var phi_2879_: u32;
    var phi_2841_: u32;
    var phi_2844_: u32;
    var phi_6288_: bool;
    var phi_2727_: u32;
    var phi_2730_: u32;
    var phi_2731_: u32;
    var phi_2733_: u32;
    var phi_2761_: u32;
    var phi_2728_: u32;
    var phi_2732_: u32;
    var phi_2734_: u32;
    var phi_6308_: bool;
    var phi_2783_: u32;
    var phi_2786_: u32;
    var phi_2788_: u32;
    var phi_2803_: u32;
    var phi_2784_: u32;
    var phi_2787_: u32;
    var phi_2789_: u32;
    var phi_6313_: bool;
    var phi_6324_: bool;
    var phi_2894_: u32;
    var phi_2911_: type_34;
    var phi_2913_: type_34;
    var phi_2914_: bool;
    var phi_2915_: type_34;
    var phi_2916_: bool;
    var phi_2921_: type_34;
    var phi_3121_: u32;
    var phi_3124_: u32;
    var phi_3164_: u32;
    var phi_3122_: u32;
    var phi_3125_: u32;
    var phi_6319_: bool;
    var phi_2948_: u32;
    var phi_2951_: u32;
    var phi_2969_: u32;
    var phi_2949_: u32;
    var phi_2952_: u32;
    var phi_2981_: u32;
    var phi_2984_: u32;
    var phi_2985_: u32;
    var phi_2987_: u32;
    var phi_3015_: u32;
    var phi_3021_: u32;
    var phi_3024_: u32;
    var phi_3042_: u32;
    var phi_3022_: u32;
    var phi_3025_: u32;
    var phi_2982_: u32;
    var phi_2986_: u32;
    var phi_2988_: u32;
    var phi_6331_: bool;
    var phi_3060_: u32;
    var phi_3063_: u32;
    var phi_3065_: u32;
    var phi_3080_: u32;
    var phi_3061_: u32;
    var phi_3064_: u32;
    var phi_3066_: u32;
    var phi_6344_: bool;
    var phi_6356_: bool;
    var phi_3179_: u32;
    var phi_3196_: type_34;
    var phi_3198_: type_34;
    var phi_3199_: bool;
    var phi_3200_: type_34;
    var phi_3201_: bool;
    var phi_3206_: type_34;
    var phi_3406_: u32;
    var phi_3409_: u32;
    var phi_3449_: u32;
    var phi_3407_: u32;
    var phi_3410_: u32;
    var phi_6351_: bool;
    var phi_3233_: u32;
    var phi_3236_: u32;
    var phi_3254_: u32;
    var phi_3234_: u32;
    var phi_3237_: u32;
    var phi_3266_: u32;
    var phi_3269_: u32;
    var phi_3270_: u32;
    var phi_3272_: u32;
    var phi_3300_: u32;
    var phi_3306_: u32;
    var phi_3309_: u32;
    var phi_3327_: u32;
    var phi_3307_: u32;
    var phi_3310_: u32;
    var phi_3267_: u32;
    var phi_3271_: u32;
    var phi_3273_: u32;
    var phi_6363_: bool;
    var phi_3345_: u32;
    var phi_3348_: u32;
    var phi_3350_: u32;
    var phi_3365_: u32;
    var phi_3346_: u32;
    var phi_3349_: u32;
    var phi_3351_: u32;
    var phi_6376_: bool;
    var phi_6391_: bool;
    var phi_3464_: u32;
    var phi_3482_: u32;
    var phi_3498_: u32;
    var phi_3524_: u32;
    var phi_6387_: bool;
    var phi_3540_: u32;
    var phi_3543_: u32;
    var phi_3545_: array<f32, 3>;
    var phi_3547_: f32;
    var phi_3562_: u32;
    var phi_3565_: u32;
    var phi_3567_: array<f32, 3>;
    var phi_3569_: f32;
    var phi_3597_: i32;
    var phi_3598_: i32;
    var phi_3599_: i32;
    var phi_3600_: i32;
    var phi_3601_: bool;
    var phi_3624_: i32;
    var phi_3625_: i32;
    var phi_3626_: bool;
    var phi_3627_: i32;
    var phi_3628_: i32;
    var phi_3629_: bool;
    var phi_3699_: bool;
    var phi_3713_: bool;
    var phi_3718_: f32;
    var phi_3728_: bool;
    var phi_3742_: bool;
    var phi_3747_: f32;
    var phi_3757_: bool;
    var phi_3771_: bool;
    var phi_3776_: f32;
    var phi_3810_: bool;
    var phi_3816_: type_23;
    var phi_3818_: type_23;
    var phi_3819_: bool;
    var phi_3820_: type_23;
    var phi_3821_: bool;
    var phi_3822_: type_23;
    var phi_3823_: bool;
    var phi_3828_: type_23;
    var phi_3868_: u32;
    var phi_3869_: array<f32, 3>;
    var phi_3870_: u32;
    var phi_3871_: array<f32, 3>;
    var phi_3872_: f32;
    var phi_3873_: u32;
    var phi_3874_: array<f32, 3>;
    var phi_3875_: f32;
    var phi_3876_: u32;
    var phi_3877_: array<f32, 3>;
    var phi_3878_: f32;
    var phi_3879_: u32;
    var phi_3880_: array<f32, 3>;
    var phi_3881_: f32;
    var phi_3882_: u32;
    var phi_3883_: array<f32, 3>;
    var phi_3884_: f32;
    var phi_3885_: u32;
    var phi_3886_: array<f32, 3>;
    var phi_3887_: f32;
    var phi_3888_: u32;
    var phi_3889_: array<f32, 3>;
    var phi_3890_: f32;
    var phi_3563_: u32;
    var phi_3566_: u32;
    var phi_3568_: array<f32, 3>;
    var phi_3570_: f32;
    var phi_6383_: bool;
    var phi_6431_: bool;
    var phi_3541_: u32;
    var phi_3544_: u32;
    var phi_3546_: array<f32, 3>;
    var phi_3548_: f32;
    var phi_6430_: bool;
    var phi_3918_: u32;
    var phi_3987_: bool;
    var phi_4001_: bool;
    var phi_4006_: f32;
    var phi_4016_: bool;
    var phi_4030_: bool;
    var phi_4035_: f32;
    var phi_4045_: bool;
    var phi_4059_: bool;
    var phi_4064_: f32;
    var phi_4098_: bool;
    var phi_4104_: type_23;
    var phi_4106_: type_23;
    var phi_4107_: bool;
    var phi_4108_: type_23;
    var phi_4109_: bool;
    var phi_4110_: type_23;
    var phi_4111_: bool;
    var phi_4116_: type_23;
    var phi_4156_: bool;
    var phi_4184_: f32;
    var phi_4185_: f32;
    var phi_4187_: f32;
    var phi_4204_: f32;
    var phi_4271_: f32;
    var phi_3919_: u32;
    var phi_6432_: bool;
    var phi_6640_: bool;
    var phi_6575_: f32;
    var phi_6527_: f32;
    var phi_6479_: f32;
    var phi_6639_: bool;
    var phi_4310_: u32;
    var phi_4313_: array<f32, 4>;
    var phi_4315_: array<f32, 3>;
    var phi_4317_: f32;
    var phi_4319_: array<f32, 4>;
    var phi_4321_: f32;
    var phi_4323_: f32;
    var phi_4325_: array<f32, 3>;
    var phi_4327_: array<f32, 2>;
    var phi_4329_: u32;
    var phi_4331_: f32;
    var phi_4399_: bool;
    var phi_4413_: bool;
    var phi_4418_: f32;
    var phi_4428_: bool;
    var phi_4442_: bool;
    var phi_4447_: f32;
    var phi_4457_: bool;
    var phi_4471_: bool;
    var phi_4476_: f32;
    var phi_4510_: bool;
    var phi_4516_: type_23;
    var phi_4518_: type_23;
    var phi_4519_: bool;
    var phi_4520_: type_23;
    var phi_4521_: bool;
    var phi_4522_: type_23;
    var phi_4523_: bool;
    var phi_4528_: type_23;
    var phi_4565_: bool;
    var phi_4593_: f32;
    var phi_4594_: f32;
    var phi_4596_: f32;
    var phi_4642_: u32;
    var phi_4643_: u32;
    var phi_6623_: bool;
    var phi_6669_: bool;
    var phi_4714_: type_25;
    var phi_6663_: bool;
    var phi_4834_: array<f32, 4>;
    var phi_4835_: array<f32, 3>;
    var phi_4836_: f32;
    var phi_4837_: array<f32, 4>;
    var phi_4838_: f32;
    var phi_4839_: f32;
    var phi_4840_: array<f32, 3>;
    var phi_4841_: array<f32, 2>;
    var phi_4842_: u32;
    var phi_4843_: f32;
    var phi_6662_: bool;
    var phi_4844_: array<f32, 4>;
    var phi_4845_: array<f32, 3>;
    var phi_4846_: f32;
    var phi_4847_: array<f32, 4>;
    var phi_4848_: f32;
    var phi_4849_: f32;
    var phi_4850_: array<f32, 3>;
    var phi_4851_: array<f32, 2>;
    var phi_4852_: u32;
    var phi_4853_: f32;
    var phi_6661_: bool;
    var phi_4854_: array<f32, 4>;
    var phi_4855_: array<f32, 3>;
    var phi_4856_: f32;
    var phi_4857_: array<f32, 4>;
    var phi_4858_: f32;
    var phi_4859_: f32;
    var phi_4860_: array<f32, 3>;
    var phi_4861_: array<f32, 2>;
    var phi_4862_: u32;
    var phi_4863_: f32;
    var phi_6660_: bool;
    var phi_4311_: u32;
    var phi_4314_: array<f32, 4>;
    var phi_4316_: array<f32, 3>;
    var phi_4318_: f32;
    var phi_4320_: array<f32, 4>;
    var phi_4322_: f32;
    var phi_4324_: f32;
    var phi_4326_: array<f32, 3>;
    var phi_4328_: array<f32, 2>;
    var phi_4330_: u32;
    var phi_4332_: f32;
    var phi_6659_: bool;
    var phi_4894_: array<f32, 3>;
    var phi_4895_: f32;
    var phi_4897_: array<f32, 3>;
    var phi_4898_: f32;
    var phi_4899_: bool;
    var phi_4903_: array<f32, 3>;
    var phi_4919_: array<f32, 3>;
    var phi_4920_: f32;
    var phi_4926_: f32;
    var phi_4945_: u32;
    var phi_4948_: f32;
    var phi_4992_: f32;
    var phi_4946_: u32;
    var phi_4949_: f32;
    var phi_6670_: bool;
    var phi_6683_: bool;
    var phi_4998_: f32;
    var phi_4999_: f32;
    var phi_5000_: array<f32, 2>;
    var phi_6682_: bool;
    var phi_5002_: type_30;
    var phi_5025_: u32;
    var phi_5026_: u32;
    var phi_6679_: bool;
    var phi_5065_: f32;
    var phi_5073_: f32;
    var phi_5755_: f32;
    var phi_5756_: f32;
    var phi_5777_: f32;
    var phi_5789_: f32;
    var phi_5790_: f32;
    var phi_5798_: f32;
    var phi_5806_: f32;
    var phi_5807_: f32;
    var phi_5820_: bool;
    var phi_5847_: f32;
    var phi_5850_: f32;
    var phi_5851_: f32;
    var phi_5855_: f32;
    var phi_5858_: f32;
    var phi_5859_: f32;
    var phi_6697_: bool;
    var phi_5150_: type_31;
    var phi_6696_: bool;
    var phi_5151_: type_31;
    var phi_6695_: bool;
    var phi_5173_: u32;
    var phi_5280_: bool;
    var phi_5294_: bool;
    var phi_5299_: f32;
    var phi_5309_: bool;
    var phi_5323_: bool;
    var phi_5328_: f32;
    var phi_5338_: bool;
    var phi_5352_: bool;
    var phi_5357_: f32;
    var phi_5391_: bool;
    var phi_5397_: type_23;
    var phi_5399_: type_23;
    var phi_5400_: bool;
    var phi_5401_: type_23;
    var phi_5402_: bool;
    var phi_5403_: type_23;
    var phi_5404_: bool;
    var phi_5409_: type_23;
    var phi_5464_: u32;
    var phi_5465_: u32;
    var phi_6684_: bool;
    var phi_6737_: bool;
    var phi_5536_: type_25;
    var phi_6736_: bool;
    var phi_5545_: array<u32, 3>;
    var phi_6735_: bool;
    var phi_5546_: array<u32, 3>;
    var phi_6734_: bool;
    var phi_6733_: bool;
    var phi_6732_: bool;
    var phi_5174_: u32;
    var phi_6731_: bool;
    var phi_5595_: u32;
    var phi_5611_: u32;
    var local_651: u32;
    var local_652: array<f32, 3>;
    var local_653: f32;
    var local_654: u32;
    var local_655: u32;
    var local_656: u32;
    var local_657: u32;
    var local_658: u32;
    var local_659: u32;
    var local_660: u32;
    var local_661: u32;
    var local_662: u32;
    var local_663: u32;
    var local_664: u32;
    var local_665: u32;
    var local_666: u32;
    var local_667: array<f32, 3>;
    var local_668: f32;
    var local_669: f32;

    let _e728 = global_15;
    let _e729 = bitcast<f32>(_e728);
    local_622 = _e729;
    switch bitcast<i32>(0u) {
        default: {
            let _e731 = global;
            local = _e731;
            let _e732 = global_1;
            let _e733 = global_11;
            local_1 = _e733;
            let _e734 = global_12;
            local_2 = _e734;
            let _e735 = global_13;
            local_3 = _e735;
            let _e736 = global_14;
            local_4 = _e736;
            local_5 = arrayLength((&global_4.member));
            local_6 = arrayLength((&global_3.member));
            local_7 = arrayLength((&global_5.member));
            local_8 = arrayLength((&global_6.member));
            local_9 = arrayLength((&global_7.member));
            local_10 = arrayLength((&global_8.member));
            local_11 = arrayLength((&global_9.member));
            local_12 = _e732.x;
            local_13 = _e732.y;
            let _e755 = global_2.member.member;
            local_14 = _e755;
            let _e756 = (_e755 / 2u);
            local_15 = _e756;
            let _e758 = ((_e755 % 2u) > 0u);
            local_16 = _e758;
            if _e758 {
                let _e759 = local_15;
                phi_330_ = (_e759 + 1u);
            } else {
                phi_330_ = _e756;
            }
            let _e762 = phi_330_;
            local_17 = _e762;
            let _e765 = global_2.member.member_1;
            local_18 = _e765;
            let _e766 = (_e765 / 2u);
            local_19 = _e766;
            if ((_e765 % 2u) > 0u) {
                let _e769 = local_19;
                phi_348_ = (_e769 + 1u);
            } else {
                phi_348_ = _e766;
            }
            let _e772 = phi_348_;
            local_20 = _e772;
            let _e773 = local_12;
            let _e775 = local;
            let _e777 = ((_e773 * 8u) + (_e775 % 8u));
            local_21 = _e777;
            let _e778 = local_13;
            let _e780 = local;
            local_22 = ((_e778 * 8u) + (_e780 / 8u));
            let _e783 = local_17;
            let _e784 = (_e777 < _e783);
            local_23 = _e784;
            if _e784 {
                let _e785 = local_22;
                let _e786 = local_20;
                if (_e785 < _e786) {
                    let _e790 = global_2.member.member_3;
                    local_24 = f32(_e790);
                    local_650 = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_5944_ = false;
                    phi_367_ = 0u;
                    phi_370_ = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_372_ = array<f32, 3>(0f, 0f, 0f);
                    phi_374_ = 0f;
                    phi_376_ = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_378_ = 0f;
                    phi_380_ = 0f;
                    phi_382_ = array<f32, 3>(0f, 0f, 0f);
                    phi_384_ = array<f32, 2>(0f, 0f);
                    phi_386_ = 0u;
                    phi_388_ = 0f;
                    loop {
                        let _e793 = phi_5944_;
                        let _e795 = phi_367_;
                        let _e797 = phi_370_;
                        let _e799 = phi_372_;
                        let _e801 = phi_374_;
                        let _e803 = phi_376_;
                        let _e805 = phi_378_;
                        let _e807 = phi_380_;
                        let _e809 = phi_382_;
                        let _e811 = phi_384_;
                        let _e813 = phi_386_;
                        let _e815 = phi_388_;
                        local_25 = _e795;
                        local_26 = _e797;
                        local_27 = _e799;
                        local_28 = _e801;
                        local_29 = _e803;
                        local_30 = _e805;
                        local_31 = _e807;
                        local_32 = _e809;
                        local_33 = _e811;
                        local_34 = _e813;
                        local_35 = _e815;
                        let _e816 = local_25;
                        let _e817 = (_e816 < 4u);
                        local_36 = _e817;
                        if _e817 {
                            let _e818 = local_21;
                            let _e820 = local_25;
                            let _e822 = ((2u * _e818) + (_e820 % 2u));
                            local_37 = _e822;
                            let _e823 = local_22;
                            let _e825 = local_25;
                            local_38 = ((2u * _e823) + (_e825 / 2u));
                            let _e828 = local_14;
                            if (_e822 < _e828) {
                                let _e830 = local_38;
                                let _e831 = local_18;
                                if (_e830 < _e831) {
                                    let _e833 = local_38;
                                    let _e834 = local_14;
                                    let _e836 = local_37;
                                    let _e837 = ((_e833 * _e834) + _e836);
                                    local_39 = _e837;
                                    let _e838 = (3u * _e837);
                                    local_40 = _e838;
                                    let _e839 = local_5;
                                    if (_e838 < _e839) {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e841 = local_40;
                                    let _e844 = global_4.member[_e841];
                                    local_41 = bitcast<f32>(_e844);
                                    let _e846 = local_40;
                                    let _e847 = (_e846 + 1u);
                                    local_42 = _e847;
                                    let _e848 = local_5;
                                    if (_e847 < _e848) {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e850 = local_42;
                                    let _e853 = global_4.member[_e850];
                                    local_43 = bitcast<f32>(_e853);
                                    let _e855 = local_40;
                                    let _e856 = (_e855 + 2u);
                                    local_44 = _e856;
                                    let _e857 = local_5;
                                    if (_e856 < _e857) {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e859 = local_44;
                                    let _e862 = global_4.member[_e859];
                                    local_45 = bitcast<f32>(_e862);
                                    let _e864 = local_41;
                                    if (_e864 > 1267650600000000000000000000000f) {
                                        let _e866 = local_41;
                                        phi_456_ = select(true, false, (_e866 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_456_ = true;
                                    }
                                    let _e870 = phi_456_;
                                    if _e870 {
                                        let _e871 = local_41;
                                        if (_e871 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e873 = local_41;
                                            phi_470_ = select(true, false, (_e873 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_470_ = true;
                                        }
                                        let _e877 = phi_470_;
                                        let _e878 = local_41;
                                        phi_475_ = select(0f, _e878, _e877);
                                    } else {
                                        phi_475_ = 1267650600000000000000000000000f;
                                    }
                                    let _e881 = phi_475_;
                                    local_46 = _e881;
                                    let _e882 = local_43;
                                    if (_e882 > 1267650600000000000000000000000f) {
                                        let _e884 = local_43;
                                        phi_485_ = select(true, false, (_e884 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_485_ = true;
                                    }
                                    let _e888 = phi_485_;
                                    if _e888 {
                                        let _e889 = local_43;
                                        if (_e889 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e891 = local_43;
                                            phi_499_ = select(true, false, (_e891 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_499_ = true;
                                        }
                                        let _e895 = phi_499_;
                                        let _e896 = local_43;
                                        phi_504_ = select(0f, _e896, _e895);
                                    } else {
                                        phi_504_ = 1267650600000000000000000000000f;
                                    }
                                    let _e899 = phi_504_;
                                    local_47 = _e899;
                                    let _e900 = local_45;
                                    if (_e900 > 1267650600000000000000000000000f) {
                                        let _e902 = local_45;
                                        phi_514_ = select(true, false, (_e902 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_514_ = true;
                                    }
                                    let _e906 = phi_514_;
                                    if _e906 {
                                        let _e907 = local_45;
                                        if (_e907 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e909 = local_45;
                                            phi_528_ = select(true, false, (_e909 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_528_ = true;
                                        }
                                        let _e913 = phi_528_;
                                        let _e914 = local_45;
                                        phi_533_ = select(0f, _e914, _e913);
                                    } else {
                                        phi_533_ = 1267650600000000000000000000000f;
                                    }
                                    let _e917 = phi_533_;
                                    local_48 = _e917;
                                    let _e918 = local_46;
                                    let _e919 = local_47;
                                    local_49 = array<f32, 3>(_e918, _e919, _e917);
                                    let _e921 = local_39;
                                    let _e922 = local_6;
                                    if (_e921 < _e922) {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e924 = local_39;
                                    let _e927 = global_3.member[_e924];
                                    local_50 = bitcast<f32>(_e927);
                                    let _e929 = local_46;
                                    if ((bitcast<u32>(_e929) & 2139095040u) != 2139095040u) {
                                        let _e933 = local_47;
                                        if ((bitcast<u32>(_e933) & 2139095040u) != 2139095040u) {
                                            let _e937 = local_48;
                                            if ((bitcast<u32>(_e937) & 2139095040u) != 2139095040u) {
                                                let _e941 = local_50;
                                                let _e942 = bitcast<u32>(_e941);
                                                local_51 = _e942;
                                                if (_e942 == 0u) {
                                                    phi_567_ = false;
                                                } else {
                                                    let _e944 = local_51;
                                                    phi_567_ = (_e944 <= 2139095040u);
                                                }
                                                let _e947 = phi_567_;
                                                local_52 = _e947;
                                                if _e947 {
                                                    let _e948 = local_49;
                                                    let _e949 = local_50;
                                                    phi_573_ = type_23(1u, type_22(_e948, _e949));
                                                } else {
                                                    phi_573_ = type_23();
                                                }
                                                let _e953 = phi_573_;
                                                let _e954 = local_52;
                                                phi_575_ = _e953;
                                                phi_576_ = select(true, false, _e954);
                                            } else {
                                                phi_575_ = type_23();
                                                phi_576_ = true;
                                            }
                                            let _e957 = phi_575_;
                                            let _e959 = phi_576_;
                                            phi_577_ = _e957;
                                            phi_578_ = _e959;
                                        } else {
                                            phi_577_ = type_23();
                                            phi_578_ = true;
                                        }
                                        let _e961 = phi_577_;
                                        let _e963 = phi_578_;
                                        phi_579_ = _e961;
                                        phi_580_ = _e963;
                                    } else {
                                        phi_579_ = type_23();
                                        phi_580_ = true;
                                    }
                                    let _e965 = phi_579_;
                                    let _e967 = phi_580_;
                                    if _e967 {
                                        phi_585_ = type_23(0u, type_23().member_1);
                                    } else {
                                        phi_585_ = _e965;
                                    }
                                    let _e972 = phi_585_;
                                    local_53 = _e972;
                                    if (bitcast<i32>(_e972.member) != 0i) {
                                        let _e976 = local_53;
                                        local_54 = _e976.member_1.member;
                                        let _e979 = local_53;
                                        local_55 = _e979.member_1.member_1;
                                        let _e982 = bitcast<u32>(_e979.member_1.member_1);
                                        local_56 = _e982;
                                        if (_e982 == 2139095040u) {
                                            let _e1026 = global_2.member.member_4.member_1;
                                            let _e1031 = global_2.member.member_4.member;
                                            let _e1036 = global_2.member.member_4.member_2;
                                            let _e1042 = global_2.member.member_4.member_3;
                                            phi_653_ = (0.5f * ((((2f * _e1026) * _e1031) / (_e1036 - _e1031)) * _e1042));
                                        } else {
                                            let _e984 = local_56;
                                            if (_e984 == 0u) {
                                                phi_622_ = false;
                                            } else {
                                                let _e986 = local_56;
                                                phi_622_ = (_e986 <= 2139095040u);
                                            }
                                            let _e989 = phi_622_;
                                            if _e989 {
                                                let _e993 = global_2.member.member_4.member_1;
                                                let _e998 = global_2.member.member_4.member;
                                                let _e1003 = global_2.member.member_4.member_2;
                                                local_57 = _e1003;
                                                let _e1009 = global_2.member.member_4.member_3;
                                                let _e1010 = ((((2f * _e993) * _e998) / (_e1003 - _e998)) * _e1009);
                                                local_58 = _e1010;
                                                if (_e1010 == 0f) {
                                                    phi_650_ = 0f;
                                                } else {
                                                    let _e1012 = local_57;
                                                    let _e1013 = local_55;
                                                    let _e1016 = local_58;
                                                    phi_650_ = (_e1016 * (1f - (_e1012 / _e1013)));
                                                }
                                                let _e1019 = phi_650_;
                                                phi_651_ = _e1019;
                                            } else {
                                                phi_651_ = _e729;
                                            }
                                            let _e1021 = phi_651_;
                                            phi_653_ = (0.5f * _e1021);
                                        }
                                        let _e1046 = phi_653_;
                                        let _e1047 = local_24;
                                        let _e1049 = local_24;
                                        let _e1050 = select(_e1049, _e1046, (_e1046 < _e1047));
                                        let _e1051 = local_24;
                                        let _e1052 = -(_e1051);
                                        local_603 = select(_e1052, _e1050, (_e1050 > _e1052));
                                        let _e1055 = local_54;
                                        let _e1057 = local_54;
                                        let _e1059 = local_54;
                                        local_647 = array<f32, 3>(_e1055[0], _e1057[1], _e1059[2]);
                                        local_624 = array<f32, 4>(0f, 0f, 0f, 0f);
                                        local_623 = array<f32, 3>(0f, 0f, 0f);
                                        let _e1062 = local_36;
                                        if _e1062 {
                                        } else {
                                            phi_5965_ = true;
                                            break;
                                        }
                                        let _e1063 = local_25;
                                        let _e1065 = local_624[_e1063];
                                        local_59 = _e1065;
                                        if (_e1065 <= 0f) {
                                            let _e1126 = local_647;
                                            phi_5975_ = _e793;
                                            phi_759_ = type_25(array<f32, 3>(_e1126[0], _e1126[1], _e1126[2]), array<f32, 3>(0f, 0f, 0f));
                                        } else {
                                            let _e1067 = local_647;
                                            local_648 = _e1067;
                                            local_649 = array<f32, 3>(0f, 0f, 0f);
                                            phi_687_ = 0u;
                                            loop {
                                                let _e1069 = phi_687_;
                                                local_60 = _e1069;
                                                let _e1070 = local_60;
                                                let _e1071 = (_e1070 < 3u);
                                                local_61 = _e1071;
                                                if _e1071 {
                                                    let _e1072 = local_61;
                                                    if _e1072 {
                                                    } else {
                                                        phi_5928_ = true;
                                                        break;
                                                    }
                                                    let _e1073 = local_60;
                                                    let _e1075 = local_623[_e1073];
                                                    local_62 = _e1075;
                                                    let _e1076 = local_61;
                                                    if _e1076 {
                                                    } else {
                                                        phi_5928_ = true;
                                                        break;
                                                    }
                                                    let _e1077 = local_60;
                                                    let _e1079 = local_647[_e1077];
                                                    let _e1080 = local_62;
                                                    if (_e1079 > _e1080) {
                                                        let _e1082 = local_61;
                                                        if _e1082 {
                                                        } else {
                                                            phi_5928_ = true;
                                                            break;
                                                        }
                                                        let _e1083 = local_647[_e1077];
                                                        let _e1084 = local_62;
                                                        local_63 = (_e1083 - _e1084);
                                                        let _e1086 = local_61;
                                                        if _e1086 {
                                                        } else {
                                                            phi_5928_ = true;
                                                            break;
                                                        }
                                                        let _e1087 = local_60;
                                                        let _e1089 = local_59;
                                                        let _e1090 = local_63;
                                                        local_649[_e1087] = (_e1089 * _e1090);
                                                        let _e1092 = local_59;
                                                        local_64 = (1f - _e1092);
                                                        let _e1094 = local_61;
                                                        if _e1094 {
                                                        } else {
                                                            phi_5928_ = true;
                                                            break;
                                                        }
                                                        let _e1095 = local_647[_e1077];
                                                        let _e1096 = local_64;
                                                        local_65 = (_e1096 * _e1095);
                                                        let _e1098 = local_59;
                                                        let _e1099 = local_62;
                                                        local_66 = (_e1098 * _e1099);
                                                        let _e1101 = local_61;
                                                        if _e1101 {
                                                        } else {
                                                            phi_5928_ = true;
                                                            break;
                                                        }
                                                        let _e1102 = local_60;
                                                        let _e1104 = local_65;
                                                        let _e1105 = local_66;
                                                        local_648[_e1102] = (_e1104 + _e1105);
                                                    }
                                                    let _e1107 = local_60;
                                                    phi_688_ = (_e1107 + 1u);
                                                } else {
                                                    phi_688_ = u32();
                                                }
                                                let _e1110 = phi_688_;
                                                continue;
                                                continuing {
                                                    let _e1111 = local_61;
                                                    phi_687_ = _e1110;
                                                    phi_5928_ = _e793;
                                                    break if !(_e1111);
                                                }
                                            }
                                            let _e1114 = phi_5928_;
                                            phi_5965_ = _e1114;
                                            if _e1114 {
                                                break;
                                            }
                                            let _e1115 = local_648;
                                            let _e1120 = local_649;
                                            phi_5975_ = _e1114;
                                            phi_759_ = type_25(array<f32, 3>(_e1115[0], _e1115[1], _e1115[2]), array<f32, 3>(_e1120[0], _e1120[1], _e1120[2]));
                                        }
                                        let _e1133 = phi_5975_;
                                        let _e1135 = phi_759_;
                                        local_67 = _e1135.member;
                                        let _e1138 = local_27;
                                        let _e1142 = local_27;
                                        let _e1146 = local_27;
                                        local_68 = (((0.2126f * _e1135.member_1[0]) + (0.7152f * _e1135.member_1[1])) + (0.0722f * _e1135.member_1[2]));
                                        let _e1156 = local_36;
                                        if _e1156 {
                                        } else {
                                            phi_5965_ = true;
                                            break;
                                        }
                                        let _e1157 = local_25;
                                        let _e1159 = local_68;
                                        local_650[_e1157] = _e1159;
                                        let _e1160 = local_26;
                                        let _e1162 = local_37;
                                        let _e1163 = f32(_e1162);
                                        let _e1165 = local_68;
                                        let _e1168 = local_26;
                                        let _e1170 = local_38;
                                        let _e1171 = f32(_e1170);
                                        let _e1173 = local_68;
                                        let _e1176 = local_26;
                                        let _e1178 = local_68;
                                        let _e1179 = local_603;
                                        let _e1182 = local_26;
                                        let _e1184 = local_68;
                                        let _e1187 = local_35;
                                        let _e1188 = local_603;
                                        let _e1190 = local_33;
                                        let _e1194 = local_33;
                                        let _e1199 = local_34;
                                        let _e1201 = local_603;
                                        let _e1203 = local_603;
                                        let _e1205 = ((-1f - _e1203) * 0.5f);
                                        let _e1207 = select(0f, _e1205, (_e1205 > 0f));
                                        let _e1209 = select(1f, _e1207, (_e1207 < 1f));
                                        let _e1210 = local_32;
                                        let _e1212 = local_67;
                                        let _e1216 = local_32;
                                        let _e1218 = local_67;
                                        let _e1222 = local_32;
                                        let _e1224 = local_67;
                                        let _e1229 = local_603;
                                        let _e1231 = local_31;
                                        let _e1233 = local_30;
                                        let _e1236 = local_603;
                                        let _e1238 = local_603;
                                        let _e1240 = (select(_e1238, -(_e1201), (_e1236 < 0f)) - 1f);
                                        let _e1242 = select(0f, _e1240, (_e1240 > 0f));
                                        let _e1246 = ((1f - _e1209) * (select(1f, _e1242, (_e1242 < 1f)) + 0.001f));
                                        let _e1247 = local_29;
                                        let _e1251 = local_29;
                                        let _e1255 = local_29;
                                        let _e1259 = local_29;
                                        let _e1261 = local_603;
                                        let _e1265 = local_28;
                                        phi_5969_ = _e1133;
                                        phi_879_ = array<f32, 4>((_e1160[0] + (_e1165 * (_e1163 + 0.5f))), (_e1168[1] + (_e1173 * (_e1171 + 0.5f))), (_e1176[2] + (_e1178 * _e1179)), (_e1182[3] + _e1184));
                                        phi_880_ = array<f32, 3>((_e1138[0] + _e1135.member_1[0]), (_e1142[1] + _e1135.member_1[1]), (_e1146[2] + _e1135.member_1[2]));
                                        phi_881_ = (_e1265 + _e1246);
                                        phi_882_ = array<f32, 4>((_e1247[0] + (_e1246 * _e1212[0])), (_e1251[1] + (_e1246 * _e1218[1])), (_e1255[2] + (_e1246 * _e1224[2])), (_e1259[3] + (_e1246 * _e1261)));
                                        phi_883_ = (_e1233 + _e1209);
                                        phi_884_ = (_e1231 + (_e1209 * _e1229));
                                        phi_885_ = array<f32, 3>((_e1210[0] + (_e1209 * _e1212[0])), (_e1216[1] + (_e1209 * _e1218[1])), (_e1222[2] + (_e1209 * _e1224[2])));
                                        phi_886_ = array<f32, 2>(((_e1190[0] + _e1163) + 0.5f), ((_e1194[1] + _e1171) + 0.5f));
                                        phi_887_ = (_e1199 + 1u);
                                        phi_888_ = (_e1187 + _e1188);
                                    } else {
                                        phi_5969_ = _e793;
                                        phi_879_ = _e797;
                                        phi_880_ = _e799;
                                        phi_881_ = _e801;
                                        phi_882_ = _e803;
                                        phi_883_ = _e805;
                                        phi_884_ = _e807;
                                        phi_885_ = _e809;
                                        phi_886_ = _e811;
                                        phi_887_ = _e813;
                                        phi_888_ = _e815;
                                    }
                                    let _e1268 = phi_5969_;
                                    let _e1270 = phi_879_;
                                    let _e1272 = phi_880_;
                                    let _e1274 = phi_881_;
                                    let _e1276 = phi_882_;
                                    let _e1278 = phi_883_;
                                    let _e1280 = phi_884_;
                                    let _e1282 = phi_885_;
                                    let _e1284 = phi_886_;
                                    let _e1286 = phi_887_;
                                    let _e1288 = phi_888_;
                                    phi_5968_ = _e1268;
                                    phi_889_ = _e1270;
                                    phi_890_ = _e1272;
                                    phi_891_ = _e1274;
                                    phi_892_ = _e1276;
                                    phi_893_ = _e1278;
                                    phi_894_ = _e1280;
                                    phi_895_ = _e1282;
                                    phi_896_ = _e1284;
                                    phi_897_ = _e1286;
                                    phi_898_ = _e1288;
                                } else {
                                    phi_5968_ = _e793;
                                    phi_889_ = _e797;
                                    phi_890_ = _e799;
                                    phi_891_ = _e801;
                                    phi_892_ = _e803;
                                    phi_893_ = _e805;
                                    phi_894_ = _e807;
                                    phi_895_ = _e809;
                                    phi_896_ = _e811;
                                    phi_897_ = _e813;
                                    phi_898_ = _e815;
                                }
                                let _e1290 = phi_5968_;
                                let _e1292 = phi_889_;
                                let _e1294 = phi_890_;
                                let _e1296 = phi_891_;
                                let _e1298 = phi_892_;
                                let _e1300 = phi_893_;
                                let _e1302 = phi_894_;
                                let _e1304 = phi_895_;
                                let _e1306 = phi_896_;
                                let _e1308 = phi_897_;
                                let _e1310 = phi_898_;
                                phi_5967_ = _e1290;
                                phi_899_ = _e1292;
                                phi_900_ = _e1294;
                                phi_901_ = _e1296;
                                phi_902_ = _e1298;
                                phi_903_ = _e1300;
                                phi_904_ = _e1302;
                                phi_905_ = _e1304;
                                phi_906_ = _e1306;
                                phi_907_ = _e1308;
                                phi_908_ = _e1310;
                            } else {
                                phi_5967_ = _e793;
                                phi_899_ = _e797;
                                phi_900_ = _e799;
                                phi_901_ = _e801;
                                phi_902_ = _e803;
                                phi_903_ = _e805;
                                phi_904_ = _e807;
                                phi_905_ = _e809;
                                phi_906_ = _e811;
                                phi_907_ = _e813;
                                phi_908_ = _e815;
                            }
                            let _e1312 = phi_5967_;
                            let _e1314 = phi_899_;
                            let _e1316 = phi_900_;
                            let _e1318 = phi_901_;
                            let _e1320 = phi_902_;
                            let _e1322 = phi_903_;
                            let _e1324 = phi_904_;
                            let _e1326 = phi_905_;
                            let _e1328 = phi_906_;
                            let _e1330 = phi_907_;
                            let _e1332 = phi_908_;
                            let _e1333 = local_25;
                            phi_5966_ = _e1312;
                            phi_368_ = (_e1333 + 1u);
                            phi_371_ = _e1314;
                            phi_373_ = _e1316;
                            phi_375_ = _e1318;
                            phi_377_ = _e1320;
                            phi_379_ = _e1322;
                            phi_381_ = _e1324;
                            phi_383_ = _e1326;
                            phi_385_ = _e1328;
                            phi_387_ = _e1330;
                            phi_389_ = _e1332;
                        } else {
                            phi_5966_ = _e793;
                            phi_368_ = u32();
                            phi_371_ = array<f32, 4>();
                            phi_373_ = array<f32, 3>();
                            phi_375_ = f32();
                            phi_377_ = array<f32, 4>();
                            phi_379_ = f32();
                            phi_381_ = f32();
                            phi_383_ = array<f32, 3>();
                            phi_385_ = array<f32, 2>();
                            phi_387_ = u32();
                            phi_389_ = f32();
                        }
                        let _e1336 = phi_5966_;
                        let _e1338 = phi_368_;
                        let _e1340 = phi_371_;
                        let _e1342 = phi_373_;
                        let _e1344 = phi_375_;
                        let _e1346 = phi_377_;
                        let _e1348 = phi_379_;
                        let _e1350 = phi_381_;
                        let _e1352 = phi_383_;
                        let _e1354 = phi_385_;
                        let _e1356 = phi_387_;
                        let _e1358 = phi_389_;
                        continue;
                        continuing {
                            let _e1359 = local_36;
                            phi_5944_ = _e1336;
                            phi_367_ = _e1338;
                            phi_370_ = _e1340;
                            phi_372_ = _e1342;
                            phi_374_ = _e1344;
                            phi_376_ = _e1346;
                            phi_378_ = _e1348;
                            phi_380_ = _e1350;
                            phi_382_ = _e1352;
                            phi_384_ = _e1354;
                            phi_386_ = _e1356;
                            phi_388_ = _e1358;
                            phi_5965_ = _e1336;
                            break if !(_e1359);
                        }
                    }
                    let _e1362 = phi_5965_;
                    if _e1362 {
                        break;
                    }
                    let _e1363 = local_34;
                    if (_e1363 == 0u) {
                        let _e1537 = local_622;
                        let _e1538 = local_34;
                        phi_5988_ = _e1362;
                        phi_1047_ = type_30(array<f32, 2>(0f, 0f), array<f32, 3>(0f, 0f, 0f), 0f, 0f, array<f32, 3>(0f, 0f, 0f), _e1537, _e1538, array<f32, 3>(0f, 0f, 0f), 0f, 0f);
                    } else {
                        let _e1365 = local_34;
                        let _e1366 = f32(_e1365);
                        let _e1367 = (1f / _e1366);
                        local_69 = _e1367;
                        let _e1368 = local_35;
                        let _e1370 = ((0.5f * _e1368) * _e1367);
                        local_70 = _e1370;
                        let _e1371 = local_30;
                        let _e1373 = ((_e1366 - _e1371) > 0f);
                        local_71 = _e1373;
                        if _e1373 {
                            let _e1374 = local_28;
                            let _e1375 = (_e1374 > 0f);
                            local_72 = _e1375;
                            if _e1375 {
                                let _e1376 = local_28;
                                let _e1377 = (1f / _e1376);
                                let _e1378 = local_29;
                                let _e1381 = local_29;
                                let _e1384 = local_29;
                                let _e1388 = local_29;
                                phi_939_ = array<f32, 3>((_e1378[0] * _e1377), (_e1381[1] * _e1377), (_e1384[2] * _e1377));
                                phi_940_ = ((0.5f * _e1388[3]) * _e1377);
                            } else {
                                phi_939_ = array<f32, 3>();
                                phi_940_ = f32();
                            }
                            let _e1393 = phi_939_;
                            let _e1395 = phi_940_;
                            let _e1396 = local_72;
                            phi_942_ = _e1393;
                            phi_943_ = _e1395;
                            phi_944_ = select(true, false, _e1396);
                        } else {
                            phi_942_ = array<f32, 3>();
                            phi_943_ = f32();
                            phi_944_ = true;
                        }
                        let _e1399 = phi_942_;
                        let _e1401 = phi_943_;
                        let _e1403 = phi_944_;
                        local_73 = _e1401;
                        local_74 = _e1403;
                        if _e1403 {
                            phi_948_ = array<f32, 3>(0f, 0f, 0f);
                        } else {
                            phi_948_ = _e1399;
                        }
                        let _e1405 = phi_948_;
                        local_75 = _e1405;
                        let _e1406 = local_74;
                        let _e1407 = local_70;
                        let _e1408 = local_73;
                        local_604 = select(_e1408, _e1407, _e1406);
                        let _e1410 = local_30;
                        if (_e1410 > 0f) {
                            let _e1412 = local_30;
                            let _e1413 = (1f / _e1412);
                            let _e1414 = local_32;
                            let _e1417 = local_32;
                            let _e1420 = local_32;
                            let _e1424 = local_31;
                            phi_964_ = array<f32, 3>((_e1414[0] * _e1413), (_e1417[1] * _e1413), (_e1420[2] * _e1413));
                            phi_965_ = ((0.5f * _e1424) * _e1413);
                        } else {
                            phi_964_ = array<f32, 3>(0f, 0f, 0f);
                            phi_965_ = _e1370;
                        }
                        let _e1428 = phi_964_;
                        let _e1430 = phi_965_;
                        local_76 = _e1428;
                        local_77 = _e1430;
                        let _e1431 = local_71;
                        if _e1431 {
                            let _e1432 = local_30;
                            let _e1433 = local_69;
                            phi_971_ = (_e1432 * _e1433);
                        } else {
                            phi_971_ = 1f;
                        }
                        let _e1436 = phi_971_;
                        local_78 = _e1436;
                        let _e1437 = local_33;
                        let _e1439 = local_69;
                        let _e1441 = local_33;
                        let _e1443 = local_69;
                        let _e1446 = local_26;
                        local_79 = _e1446[3];
                        if (_e1446[3] > 0f) {
                            let _e1451 = local_79;
                            let _e1452 = (1f / _e1451);
                            local_80 = _e1452;
                            let _e1453 = local_26;
                            let _e1455 = (_e1453[0] * _e1452);
                            local_81 = _e1455;
                            let _e1456 = local_26;
                            let _e1458 = (_e1456[1] * _e1452);
                            local_82 = _e1458;
                            phi_990_ = 0u;
                            phi_993_ = 0f;
                            loop {
                                let _e1461 = phi_990_;
                                let _e1463 = phi_993_;
                                local_83 = _e1461;
                                local_84 = _e1463;
                                let _e1464 = local_83;
                                let _e1465 = (_e1464 < 4u);
                                local_85 = _e1465;
                                if _e1465 {
                                    let _e1466 = local_85;
                                    if _e1466 {
                                    } else {
                                        phi_5976_ = true;
                                        break;
                                    }
                                    let _e1467 = local_83;
                                    let _e1469 = local_650[_e1467];
                                    if (_e1469 > 0f) {
                                        let _e1471 = local_21;
                                        let _e1473 = local_83;
                                        let _e1478 = local_81;
                                        local_86 = ((f32(((2u * _e1471) + (_e1473 % 2u))) + 0.5f) - _e1478);
                                        let _e1480 = local_22;
                                        let _e1482 = local_83;
                                        let _e1487 = local_82;
                                        local_87 = ((f32(((2u * _e1480) + (_e1482 / 2u))) + 0.5f) - _e1487);
                                        let _e1489 = local_85;
                                        if _e1489 {
                                        } else {
                                            phi_5976_ = true;
                                            break;
                                        }
                                        let _e1490 = local_650[_e1467];
                                        let _e1491 = local_86;
                                        let _e1492 = local_86;
                                        let _e1494 = local_87;
                                        let _e1495 = local_87;
                                        let _e1500 = local_84;
                                        phi_1037_ = (_e1500 + (_e1490 * sqrt(((_e1491 * _e1492) + (_e1494 * _e1495)))));
                                    } else {
                                        phi_1037_ = _e1463;
                                    }
                                    let _e1503 = phi_1037_;
                                    let _e1504 = local_83;
                                    phi_991_ = (_e1504 + 1u);
                                    phi_994_ = _e1503;
                                } else {
                                    phi_991_ = u32();
                                    phi_994_ = f32();
                                }
                                let _e1507 = phi_991_;
                                let _e1509 = phi_994_;
                                continue;
                                continuing {
                                    let _e1510 = local_85;
                                    phi_990_ = _e1507;
                                    phi_993_ = _e1509;
                                    phi_5976_ = _e1362;
                                    break if !(_e1510);
                                }
                            }
                            let _e1513 = phi_5976_;
                            if _e1513 {
                                break;
                            }
                            let _e1514 = local_26;
                            let _e1516 = local_80;
                            let _e1518 = local_84;
                            let _e1519 = local_80;
                            phi_5989_ = _e1513;
                            phi_1043_ = (_e1514[2] * _e1516);
                            phi_1044_ = (_e1518 * _e1519);
                            phi_1045_ = array<f32, 2>(_e1455, _e1458);
                        } else {
                            let _e1449 = local_70;
                            phi_5989_ = _e1362;
                            phi_1043_ = (2f * _e1449);
                            phi_1044_ = 0f;
                            phi_1045_ = array<f32, 2>((_e1437[0] * _e1439), (_e1441[1] * _e1443));
                        }
                        let _e1522 = phi_5989_;
                        let _e1524 = phi_1043_;
                        let _e1526 = phi_1044_;
                        let _e1528 = phi_1045_;
                        let _e1529 = local_76;
                        let _e1530 = local_78;
                        let _e1531 = local_77;
                        let _e1532 = local_75;
                        let _e1533 = local_604;
                        let _e1534 = local_34;
                        let _e1535 = local_27;
                        phi_5988_ = _e1522;
                        phi_1047_ = type_30(_e1528, _e1529, _e1530, _e1531, _e1532, _e1533, _e1534, _e1535, _e1524, _e1526);
                    }
                    let _e1541 = phi_5988_;
                    let _e1543 = phi_1047_;
                    local_88 = _e1543;
                    let _e1544 = local_22;
                    let _e1545 = local_17;
                    let _e1547 = local_21;
                    local_89 = (9u * ((_e1544 * _e1545) + _e1547));
                    local_90 = _e1543.member_3;
                    local_91 = _e1543.member_5;
                    local_646[0u] = _e1543.member_1[0];
                    local_646[1u] = _e1543.member_1[1];
                    local_646[2u] = _e1543.member_1[2];
                    local_646[3u] = _e1543.member_2;
                    local_646[4u] = _e1543.member_4[0];
                    local_646[5u] = _e1543.member_4[1];
                    local_646[6u] = _e1543.member_4[2];
                    local_646[7u] = _e1543.member_3;
                    local_646[8u] = _e1543.member_5;
                    phi_1070_ = 0u;
                    loop {
                        let _e1575 = phi_1070_;
                        local_92 = _e1575;
                        let _e1576 = local_92;
                        let _e1577 = (_e1576 < 9u);
                        local_93 = _e1577;
                        if _e1577 {
                            let _e1578 = local_89;
                            let _e1579 = local_92;
                            local_94 = (_e1578 + _e1579);
                            let _e1581 = local_93;
                            if _e1581 {
                            } else {
                                phi_5985_ = true;
                                break;
                            }
                            let _e1582 = local_92;
                            let _e1584 = local_646[_e1582];
                            local_95 = bitcast<u32>(_e1584);
                            let _e1586 = local_94;
                            let _e1587 = local_7;
                            if (_e1586 < _e1587) {
                            } else {
                                phi_5985_ = true;
                                break;
                            }
                            let _e1589 = local_94;
                            let _e1592 = local_95;
                            global_5.member[_e1589] = _e1592;
                            let _e1593 = local_92;
                            phi_1071_ = (_e1593 + 1u);
                        } else {
                            phi_1071_ = u32();
                        }
                        let _e1596 = phi_1071_;
                        continue;
                        continuing {
                            let _e1597 = local_93;
                            phi_1070_ = _e1596;
                            phi_5985_ = _e1541;
                            break if !(_e1597);
                        }
                    }
                    let _e1600 = phi_5985_;
                    if _e1600 {
                        break;
                    }
                    let _e1601 = local_88;
                    if (_e1601.member_6 > 0u) {
                        let _e1604 = local_90;
                        let _e1605 = -(_e1604);
                        let _e1606 = local_91;
                        let _e1607 = -(_e1606);
                        let _e1609 = select(_e1607, _e1605, (_e1605 > _e1607));
                        phi_5994_ = _e1600;
                        phi_1115_ = 0u;
                        phi_1118_ = 0u;
                        phi_1120_ = array<f32, 3>(0f, 0f, 0f);
                        phi_1122_ = 340282350000000000000000000000000000000f;
                        loop {
                            let _e1613 = phi_5994_;
                            let _e1615 = phi_1115_;
                            let _e1617 = phi_1118_;
                            let _e1619 = phi_1120_;
                            let _e1621 = phi_1122_;
                            local_96 = _e1615;
                            local_97 = _e1617;
                            local_98 = _e1619;
                            local_99 = _e1621;
                            let _e1622 = local_96;
                            let _e1623 = (_e1622 < 2u);
                            local_100 = _e1623;
                            if _e1623 {
                                let _e1624 = local_99;
                                let _e1626 = local_99;
                                local_101 = (4f * select(0.25f, _e1626, (_e1624 > 0.25f)));
                                phi_1137_ = 0u;
                                phi_1140_ = _e1617;
                                phi_1142_ = _e1619;
                                phi_1144_ = _e1621;
                                loop {
                                    let _e1630 = phi_1137_;
                                    let _e1632 = phi_1140_;
                                    let _e1634 = phi_1142_;
                                    let _e1636 = phi_1144_;
                                    local_102 = _e1630;
                                    local_103 = _e1632;
                                    local_104 = _e1634;
                                    local_105 = _e1636;
                                    local_651 = _e1632;
                                    local_652 = _e1634;
                                    local_653 = _e1636;
                                    let _e1637 = local_102;
                                    let _e1638 = (_e1637 < 16u);
                                    local_106 = _e1638;
                                    if _e1638 {
                                        let _e1639 = local_102;
                                        let _e1640 = (_e1639 % 4u);
                                        local_107 = _e1640;
                                        let _e1641 = local_102;
                                        local_108 = (_e1641 / 4u);
                                        if (_e1640 == 1u) {
                                            phi_1174_ = i32();
                                            phi_1175_ = i32();
                                            phi_1176_ = true;
                                        } else {
                                            let _e1644 = local_107;
                                            let _e1645 = (_e1644 == 2u);
                                            if _e1645 {
                                                phi_1172_ = i32();
                                                phi_1173_ = i32();
                                            } else {
                                                let _e1646 = local_21;
                                                let _e1650 = local_107;
                                                let _e1653 = local_22;
                                                let _e1657 = local_108;
                                                phi_1172_ = (((2i * bitcast<i32>(_e1653)) - 1i) + bitcast<i32>(_e1657));
                                                phi_1173_ = (((2i * bitcast<i32>(_e1646)) - 1i) + bitcast<i32>(_e1650));
                                            }
                                            let _e1661 = phi_1172_;
                                            let _e1663 = phi_1173_;
                                            phi_1174_ = _e1661;
                                            phi_1175_ = _e1663;
                                            phi_1176_ = _e1645;
                                        }
                                        let _e1665 = phi_1174_;
                                        let _e1667 = phi_1175_;
                                        let _e1669 = phi_1176_;
                                        if _e1669 {
                                            let _e1670 = local_108;
                                            if (_e1670 == 1u) {
                                                phi_1199_ = i32();
                                                phi_1200_ = i32();
                                                phi_1201_ = false;
                                            } else {
                                                let _e1672 = local_108;
                                                let _e1674 = local_21;
                                                let _e1678 = local_107;
                                                let _e1681 = local_22;
                                                let _e1685 = local_108;
                                                phi_1199_ = (((2i * bitcast<i32>(_e1681)) - 1i) + bitcast<i32>(_e1685));
                                                phi_1200_ = (((2i * bitcast<i32>(_e1674)) - 1i) + bitcast<i32>(_e1678));
                                                phi_1201_ = select(true, false, (_e1672 == 2u));
                                            }
                                            let _e1690 = phi_1199_;
                                            let _e1692 = phi_1200_;
                                            let _e1694 = phi_1201_;
                                            phi_1202_ = _e1690;
                                            phi_1203_ = _e1692;
                                            phi_1204_ = _e1694;
                                        } else {
                                            phi_1202_ = _e1665;
                                            phi_1203_ = _e1667;
                                            phi_1204_ = true;
                                        }
                                        let _e1696 = phi_1202_;
                                        let _e1698 = phi_1203_;
                                        let _e1700 = phi_1204_;
                                        local_109 = _e1696;
                                        local_110 = _e1698;
                                        if _e1700 {
                                            let _e1701 = local_110;
                                            if (_e1701 >= 0i) {
                                                let _e1703 = local_109;
                                                if (_e1703 >= 0i) {
                                                    let _e1705 = local_110;
                                                    let _e1706 = bitcast<u32>(_e1705);
                                                    local_111 = _e1706;
                                                    let _e1707 = local_14;
                                                    if (_e1706 < _e1707) {
                                                        let _e1709 = local_109;
                                                        let _e1710 = bitcast<u32>(_e1709);
                                                        local_112 = _e1710;
                                                        let _e1711 = local_18;
                                                        if (_e1710 < _e1711) {
                                                            let _e1713 = local_112;
                                                            let _e1714 = local_14;
                                                            let _e1716 = local_111;
                                                            let _e1717 = ((_e1713 * _e1714) + _e1716);
                                                            local_113 = _e1717;
                                                            let _e1718 = (3u * _e1717);
                                                            local_114 = _e1718;
                                                            let _e1719 = local_5;
                                                            if (_e1718 < _e1719) {
                                                            } else {
                                                                phi_5990_ = true;
                                                                break;
                                                            }
                                                            let _e1721 = local_114;
                                                            let _e1724 = global_4.member[_e1721];
                                                            local_115 = bitcast<f32>(_e1724);
                                                            let _e1726 = local_114;
                                                            let _e1727 = (_e1726 + 1u);
                                                            local_116 = _e1727;
                                                            let _e1728 = local_5;
                                                            if (_e1727 < _e1728) {
                                                            } else {
                                                                phi_5990_ = true;
                                                                break;
                                                            }
                                                            let _e1730 = local_116;
                                                            let _e1733 = global_4.member[_e1730];
                                                            local_117 = bitcast<f32>(_e1733);
                                                            let _e1735 = local_114;
                                                            let _e1736 = (_e1735 + 2u);
                                                            local_118 = _e1736;
                                                            let _e1737 = local_5;
                                                            if (_e1736 < _e1737) {
                                                            } else {
                                                                phi_5990_ = true;
                                                                break;
                                                            }
                                                            let _e1739 = local_118;
                                                            let _e1742 = global_4.member[_e1739];
                                                            local_119 = bitcast<f32>(_e1742);
                                                            let _e1744 = local_115;
                                                            if (_e1744 > 1267650600000000000000000000000f) {
                                                                let _e1746 = local_115;
                                                                phi_1274_ = select(true, false, (_e1746 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_1274_ = true;
                                                            }
                                                            let _e1750 = phi_1274_;
                                                            if _e1750 {
                                                                let _e1751 = local_115;
                                                                if (_e1751 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e1753 = local_115;
                                                                    phi_1288_ = select(true, false, (_e1753 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_1288_ = true;
                                                                }
                                                                let _e1757 = phi_1288_;
                                                                let _e1758 = local_115;
                                                                phi_1293_ = select(0f, _e1758, _e1757);
                                                            } else {
                                                                phi_1293_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e1761 = phi_1293_;
                                                            local_120 = _e1761;
                                                            let _e1762 = local_117;
                                                            if (_e1762 > 1267650600000000000000000000000f) {
                                                                let _e1764 = local_117;
                                                                phi_1303_ = select(true, false, (_e1764 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_1303_ = true;
                                                            }
                                                            let _e1768 = phi_1303_;
                                                            if _e1768 {
                                                                let _e1769 = local_117;
                                                                if (_e1769 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e1771 = local_117;
                                                                    phi_1317_ = select(true, false, (_e1771 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_1317_ = true;
                                                                }
                                                                let _e1775 = phi_1317_;
                                                                let _e1776 = local_117;
                                                                phi_1322_ = select(0f, _e1776, _e1775);
                                                            } else {
                                                                phi_1322_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e1779 = phi_1322_;
                                                            local_121 = _e1779;
                                                            let _e1780 = local_119;
                                                            if (_e1780 > 1267650600000000000000000000000f) {
                                                                let _e1782 = local_119;
                                                                phi_1332_ = select(true, false, (_e1782 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_1332_ = true;
                                                            }
                                                            let _e1786 = phi_1332_;
                                                            if _e1786 {
                                                                let _e1787 = local_119;
                                                                if (_e1787 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e1789 = local_119;
                                                                    phi_1346_ = select(true, false, (_e1789 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_1346_ = true;
                                                                }
                                                                let _e1793 = phi_1346_;
                                                                let _e1794 = local_119;
                                                                phi_1351_ = select(0f, _e1794, _e1793);
                                                            } else {
                                                                phi_1351_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e1797 = phi_1351_;
                                                            local_122 = _e1797;
                                                            let _e1798 = local_120;
                                                            let _e1799 = local_121;
                                                            local_123 = array<f32, 3>(_e1798, _e1799, _e1797);
                                                            let _e1801 = local_113;
                                                            let _e1802 = local_6;
                                                            if (_e1801 < _e1802) {
                                                            } else {
                                                                phi_5990_ = true;
                                                                break;
                                                            }
                                                            let _e1804 = local_113;
                                                            let _e1807 = global_3.member[_e1804];
                                                            local_124 = bitcast<f32>(_e1807);
                                                            let _e1809 = local_120;
                                                            if ((bitcast<u32>(_e1809) & 2139095040u) != 2139095040u) {
                                                                let _e1813 = local_121;
                                                                if ((bitcast<u32>(_e1813) & 2139095040u) != 2139095040u) {
                                                                    let _e1817 = local_122;
                                                                    if ((bitcast<u32>(_e1817) & 2139095040u) != 2139095040u) {
                                                                        let _e1821 = local_124;
                                                                        let _e1822 = bitcast<u32>(_e1821);
                                                                        local_125 = _e1822;
                                                                        if (_e1822 == 0u) {
                                                                            phi_1385_ = false;
                                                                        } else {
                                                                            let _e1824 = local_125;
                                                                            phi_1385_ = (_e1824 <= 2139095040u);
                                                                        }
                                                                        let _e1827 = phi_1385_;
                                                                        local_126 = _e1827;
                                                                        if _e1827 {
                                                                            let _e1828 = local_123;
                                                                            let _e1829 = local_124;
                                                                            phi_1391_ = type_23(1u, type_22(_e1828, _e1829));
                                                                        } else {
                                                                            phi_1391_ = type_23();
                                                                        }
                                                                        let _e1833 = phi_1391_;
                                                                        let _e1834 = local_126;
                                                                        phi_1393_ = _e1833;
                                                                        phi_1394_ = select(true, false, _e1834);
                                                                    } else {
                                                                        phi_1393_ = type_23();
                                                                        phi_1394_ = true;
                                                                    }
                                                                    let _e1837 = phi_1393_;
                                                                    let _e1839 = phi_1394_;
                                                                    phi_1395_ = _e1837;
                                                                    phi_1396_ = _e1839;
                                                                } else {
                                                                    phi_1395_ = type_23();
                                                                    phi_1396_ = true;
                                                                }
                                                                let _e1841 = phi_1395_;
                                                                let _e1843 = phi_1396_;
                                                                phi_1397_ = _e1841;
                                                                phi_1398_ = _e1843;
                                                            } else {
                                                                phi_1397_ = type_23();
                                                                phi_1398_ = true;
                                                            }
                                                            let _e1845 = phi_1397_;
                                                            let _e1847 = phi_1398_;
                                                            if _e1847 {
                                                                phi_1403_ = type_23(0u, type_23().member_1);
                                                            } else {
                                                                phi_1403_ = _e1845;
                                                            }
                                                            let _e1852 = phi_1403_;
                                                            local_127 = _e1852;
                                                            if (bitcast<i32>(_e1852.member) != 0i) {
                                                                let _e1856 = local_127;
                                                                local_128 = _e1856.member_1.member[0];
                                                                local_129 = _e1856.member_1.member[1];
                                                                local_130 = _e1856.member_1.member[2];
                                                                local_131 = (((0.2126f * _e1856.member_1.member[0]) + (0.7152f * _e1856.member_1.member[1])) + (0.0722f * _e1856.member_1.member[2]));
                                                                let _e1867 = local_96;
                                                                if (_e1867 == 0u) {
                                                                    let _e1891 = local_105;
                                                                    let _e1892 = local_131;
                                                                    let _e1894 = local_105;
                                                                    let _e1895 = local_131;
                                                                    phi_1445_ = _e1632;
                                                                    phi_1446_ = _e1634;
                                                                    phi_1447_ = select(_e1895, _e1894, (_e1891 < _e1892));
                                                                } else {
                                                                    let _e1869 = local_131;
                                                                    let _e1870 = local_101;
                                                                    if (_e1869 <= _e1870) {
                                                                        let _e1872 = local_104;
                                                                        let _e1874 = local_128;
                                                                        let _e1876 = local_104;
                                                                        let _e1878 = local_129;
                                                                        let _e1880 = local_104;
                                                                        let _e1882 = local_130;
                                                                        let _e1885 = local_103;
                                                                        phi_1443_ = (_e1885 + 1u);
                                                                        phi_1444_ = array<f32, 3>((_e1872[0] + _e1874), (_e1876[1] + _e1878), (_e1880[2] + _e1882));
                                                                    } else {
                                                                        phi_1443_ = _e1632;
                                                                        phi_1444_ = _e1634;
                                                                    }
                                                                    let _e1888 = phi_1443_;
                                                                    let _e1890 = phi_1444_;
                                                                    phi_1445_ = _e1888;
                                                                    phi_1446_ = _e1890;
                                                                    phi_1447_ = _e1636;
                                                                }
                                                                let _e1898 = phi_1445_;
                                                                let _e1900 = phi_1446_;
                                                                let _e1902 = phi_1447_;
                                                                phi_1448_ = _e1898;
                                                                phi_1449_ = _e1900;
                                                                phi_1450_ = _e1902;
                                                            } else {
                                                                phi_1448_ = _e1632;
                                                                phi_1449_ = _e1634;
                                                                phi_1450_ = _e1636;
                                                            }
                                                            let _e1904 = phi_1448_;
                                                            let _e1906 = phi_1449_;
                                                            let _e1908 = phi_1450_;
                                                            phi_1451_ = _e1904;
                                                            phi_1452_ = _e1906;
                                                            phi_1453_ = _e1908;
                                                        } else {
                                                            phi_1451_ = _e1632;
                                                            phi_1452_ = _e1634;
                                                            phi_1453_ = _e1636;
                                                        }
                                                        let _e1910 = phi_1451_;
                                                        let _e1912 = phi_1452_;
                                                        let _e1914 = phi_1453_;
                                                        phi_1454_ = _e1910;
                                                        phi_1455_ = _e1912;
                                                        phi_1456_ = _e1914;
                                                    } else {
                                                        phi_1454_ = _e1632;
                                                        phi_1455_ = _e1634;
                                                        phi_1456_ = _e1636;
                                                    }
                                                    let _e1916 = phi_1454_;
                                                    let _e1918 = phi_1455_;
                                                    let _e1920 = phi_1456_;
                                                    phi_1457_ = _e1916;
                                                    phi_1458_ = _e1918;
                                                    phi_1459_ = _e1920;
                                                } else {
                                                    phi_1457_ = _e1632;
                                                    phi_1458_ = _e1634;
                                                    phi_1459_ = _e1636;
                                                }
                                                let _e1922 = phi_1457_;
                                                let _e1924 = phi_1458_;
                                                let _e1926 = phi_1459_;
                                                phi_1460_ = _e1922;
                                                phi_1461_ = _e1924;
                                                phi_1462_ = _e1926;
                                            } else {
                                                phi_1460_ = _e1632;
                                                phi_1461_ = _e1634;
                                                phi_1462_ = _e1636;
                                            }
                                            let _e1928 = phi_1460_;
                                            let _e1930 = phi_1461_;
                                            let _e1932 = phi_1462_;
                                            phi_1463_ = _e1928;
                                            phi_1464_ = _e1930;
                                            phi_1465_ = _e1932;
                                        } else {
                                            phi_1463_ = _e1632;
                                            phi_1464_ = _e1634;
                                            phi_1465_ = _e1636;
                                        }
                                        let _e1934 = phi_1463_;
                                        let _e1936 = phi_1464_;
                                        let _e1938 = phi_1465_;
                                        let _e1939 = local_102;
                                        phi_1138_ = (_e1939 + 1u);
                                        phi_1141_ = _e1934;
                                        phi_1143_ = _e1936;
                                        phi_1145_ = _e1938;
                                    } else {
                                        phi_1138_ = u32();
                                        phi_1141_ = u32();
                                        phi_1143_ = array<f32, 3>();
                                        phi_1145_ = f32();
                                    }
                                    let _e1942 = phi_1138_;
                                    let _e1944 = phi_1141_;
                                    let _e1946 = phi_1143_;
                                    let _e1948 = phi_1145_;
                                    continue;
                                    continuing {
                                        let _e1949 = local_106;
                                        phi_1137_ = _e1942;
                                        phi_1140_ = _e1944;
                                        phi_1142_ = _e1946;
                                        phi_1144_ = _e1948;
                                        phi_5990_ = _e1613;
                                        break if !(_e1949);
                                    }
                                }
                                let _e1952 = phi_5990_;
                                phi_6035_ = _e1952;
                                if _e1952 {
                                    break;
                                }
                                let _e1953 = local_96;
                                phi_6036_ = _e1952;
                                phi_1116_ = (_e1953 + 1u);
                                let _e6370 = local_651;
                                phi_1119_ = _e6370;
                                let _e6373 = local_652;
                                phi_1121_ = _e6373;
                                let _e6376 = local_653;
                                phi_1123_ = _e6376;
                            } else {
                                phi_6036_ = _e1613;
                                phi_1116_ = u32();
                                phi_1119_ = u32();
                                phi_1121_ = array<f32, 3>();
                                phi_1123_ = f32();
                            }
                            let _e1956 = phi_6036_;
                            let _e1958 = phi_1116_;
                            let _e1960 = phi_1119_;
                            let _e1962 = phi_1121_;
                            let _e1964 = phi_1123_;
                            continue;
                            continuing {
                                let _e1965 = local_100;
                                phi_5994_ = _e1956;
                                phi_1115_ = _e1958;
                                phi_1118_ = _e1960;
                                phi_1120_ = _e1962;
                                phi_1122_ = _e1964;
                                phi_6035_ = _e1956;
                                break if !(_e1965);
                            }
                        }
                        let _e1968 = phi_6035_;
                        if _e1968 {
                            break;
                        }
                        let _e1969 = local_97;
                        if (_e1969 == 0u) {
                            local_625 = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_6249_ = _e1968;
                            phi_6180_ = 0f;
                            phi_6132_ = 0f;
                            phi_6084_ = 0f;
                        } else {
                            let _e1971 = local_97;
                            let _e1973 = (1f / f32(_e1971));
                            let _e1974 = local_98;
                            let _e1976 = (_e1974[0] * _e1973);
                            local_132 = _e1976;
                            let _e1977 = local_98;
                            let _e1979 = (_e1977[1] * _e1973);
                            local_133 = _e1979;
                            let _e1980 = local_98;
                            let _e1982 = (_e1980[2] * _e1973);
                            local_134 = _e1982;
                            local_135 = (((0.2126f * _e1976) + (0.7152f * _e1979)) + (0.0722f * _e1982));
                            local_625 = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_1493_ = 0u;
                            loop {
                                let _e1989 = phi_1493_;
                                local_136 = _e1989;
                                let _e1990 = local_136;
                                let _e1991 = (_e1990 < 4u);
                                local_137 = _e1991;
                                if _e1991 {
                                    let _e1992 = local_21;
                                    let _e1994 = local_136;
                                    let _e1996 = ((2u * _e1992) + (_e1994 % 2u));
                                    local_138 = _e1996;
                                    let _e1997 = local_22;
                                    let _e1999 = local_136;
                                    local_139 = ((2u * _e1997) + (_e1999 / 2u));
                                    let _e2002 = local_14;
                                    if (_e1996 < _e2002) {
                                        let _e2004 = local_139;
                                        let _e2005 = local_18;
                                        if (_e2004 < _e2005) {
                                            let _e2007 = local_139;
                                            let _e2008 = local_14;
                                            let _e2010 = local_138;
                                            let _e2011 = ((_e2007 * _e2008) + _e2010);
                                            local_140 = _e2011;
                                            let _e2012 = (3u * _e2011);
                                            local_141 = _e2012;
                                            let _e2013 = local_5;
                                            if (_e2012 < _e2013) {
                                            } else {
                                                phi_6037_ = true;
                                                break;
                                            }
                                            let _e2015 = local_141;
                                            let _e2018 = global_4.member[_e2015];
                                            local_142 = bitcast<f32>(_e2018);
                                            let _e2020 = local_141;
                                            let _e2021 = (_e2020 + 1u);
                                            local_143 = _e2021;
                                            let _e2022 = local_5;
                                            if (_e2021 < _e2022) {
                                            } else {
                                                phi_6037_ = true;
                                                break;
                                            }
                                            let _e2024 = local_143;
                                            let _e2027 = global_4.member[_e2024];
                                            local_144 = bitcast<f32>(_e2027);
                                            let _e2029 = local_141;
                                            let _e2030 = (_e2029 + 2u);
                                            local_145 = _e2030;
                                            let _e2031 = local_5;
                                            if (_e2030 < _e2031) {
                                            } else {
                                                phi_6037_ = true;
                                                break;
                                            }
                                            let _e2033 = local_145;
                                            let _e2036 = global_4.member[_e2033];
                                            local_146 = bitcast<f32>(_e2036);
                                            let _e2038 = local_142;
                                            if (_e2038 > 1267650600000000000000000000000f) {
                                                let _e2040 = local_142;
                                                phi_1562_ = select(true, false, (_e2040 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_1562_ = true;
                                            }
                                            let _e2044 = phi_1562_;
                                            if _e2044 {
                                                let _e2045 = local_142;
                                                if (_e2045 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e2047 = local_142;
                                                    phi_1576_ = select(true, false, (_e2047 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1576_ = true;
                                                }
                                                let _e2051 = phi_1576_;
                                                let _e2052 = local_142;
                                                phi_1581_ = select(0f, _e2052, _e2051);
                                            } else {
                                                phi_1581_ = 1267650600000000000000000000000f;
                                            }
                                            let _e2055 = phi_1581_;
                                            local_147 = _e2055;
                                            let _e2056 = local_144;
                                            if (_e2056 > 1267650600000000000000000000000f) {
                                                let _e2058 = local_144;
                                                phi_1591_ = select(true, false, (_e2058 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_1591_ = true;
                                            }
                                            let _e2062 = phi_1591_;
                                            if _e2062 {
                                                let _e2063 = local_144;
                                                if (_e2063 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e2065 = local_144;
                                                    phi_1605_ = select(true, false, (_e2065 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1605_ = true;
                                                }
                                                let _e2069 = phi_1605_;
                                                let _e2070 = local_144;
                                                phi_1610_ = select(0f, _e2070, _e2069);
                                            } else {
                                                phi_1610_ = 1267650600000000000000000000000f;
                                            }
                                            let _e2073 = phi_1610_;
                                            local_148 = _e2073;
                                            let _e2074 = local_146;
                                            if (_e2074 > 1267650600000000000000000000000f) {
                                                let _e2076 = local_146;
                                                phi_1620_ = select(true, false, (_e2076 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_1620_ = true;
                                            }
                                            let _e2080 = phi_1620_;
                                            if _e2080 {
                                                let _e2081 = local_146;
                                                if (_e2081 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e2083 = local_146;
                                                    phi_1634_ = select(true, false, (_e2083 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1634_ = true;
                                                }
                                                let _e2087 = phi_1634_;
                                                let _e2088 = local_146;
                                                phi_1639_ = select(0f, _e2088, _e2087);
                                            } else {
                                                phi_1639_ = 1267650600000000000000000000000f;
                                            }
                                            let _e2091 = phi_1639_;
                                            local_149 = _e2091;
                                            let _e2092 = local_147;
                                            let _e2093 = local_148;
                                            local_150 = array<f32, 3>(_e2092, _e2093, _e2091);
                                            let _e2095 = local_140;
                                            let _e2096 = local_6;
                                            if (_e2095 < _e2096) {
                                            } else {
                                                phi_6037_ = true;
                                                break;
                                            }
                                            let _e2098 = local_140;
                                            let _e2101 = global_3.member[_e2098];
                                            local_151 = bitcast<f32>(_e2101);
                                            let _e2103 = local_147;
                                            if ((bitcast<u32>(_e2103) & 2139095040u) != 2139095040u) {
                                                let _e2107 = local_148;
                                                if ((bitcast<u32>(_e2107) & 2139095040u) != 2139095040u) {
                                                    let _e2111 = local_149;
                                                    if ((bitcast<u32>(_e2111) & 2139095040u) != 2139095040u) {
                                                        let _e2115 = local_151;
                                                        let _e2116 = bitcast<u32>(_e2115);
                                                        local_152 = _e2116;
                                                        if (_e2116 == 0u) {
                                                            phi_1673_ = false;
                                                        } else {
                                                            let _e2118 = local_152;
                                                            phi_1673_ = (_e2118 <= 2139095040u);
                                                        }
                                                        let _e2121 = phi_1673_;
                                                        local_153 = _e2121;
                                                        if _e2121 {
                                                            let _e2122 = local_150;
                                                            let _e2123 = local_151;
                                                            phi_1679_ = type_23(1u, type_22(_e2122, _e2123));
                                                        } else {
                                                            phi_1679_ = type_23();
                                                        }
                                                        let _e2127 = phi_1679_;
                                                        let _e2128 = local_153;
                                                        phi_1681_ = _e2127;
                                                        phi_1682_ = select(true, false, _e2128);
                                                    } else {
                                                        phi_1681_ = type_23();
                                                        phi_1682_ = true;
                                                    }
                                                    let _e2131 = phi_1681_;
                                                    let _e2133 = phi_1682_;
                                                    phi_1683_ = _e2131;
                                                    phi_1684_ = _e2133;
                                                } else {
                                                    phi_1683_ = type_23();
                                                    phi_1684_ = true;
                                                }
                                                let _e2135 = phi_1683_;
                                                let _e2137 = phi_1684_;
                                                phi_1685_ = _e2135;
                                                phi_1686_ = _e2137;
                                            } else {
                                                phi_1685_ = type_23();
                                                phi_1686_ = true;
                                            }
                                            let _e2139 = phi_1685_;
                                            let _e2141 = phi_1686_;
                                            if _e2141 {
                                                phi_1691_ = type_23(0u, type_23().member_1);
                                            } else {
                                                phi_1691_ = _e2139;
                                            }
                                            let _e2146 = phi_1691_;
                                            local_154 = _e2146;
                                            if (bitcast<i32>(_e2146.member) != 0i) {
                                                let _e2150 = local_154;
                                                local_155 = _e2150.member_1.member;
                                                let _e2153 = local_154;
                                                local_156 = _e2153.member_1.member_1;
                                                let _e2156 = bitcast<u32>(_e2153.member_1.member_1);
                                                local_157 = _e2156;
                                                if (_e2156 == 2139095040u) {
                                                    let _e2200 = global_2.member.member_4.member_1;
                                                    let _e2205 = global_2.member.member_4.member;
                                                    let _e2210 = global_2.member.member_4.member_2;
                                                    let _e2216 = global_2.member.member_4.member_3;
                                                    phi_1762_ = (0.5f * ((((2f * _e2200) * _e2205) / (_e2210 - _e2205)) * _e2216));
                                                } else {
                                                    let _e2158 = local_157;
                                                    if (_e2158 == 0u) {
                                                        phi_1731_ = false;
                                                    } else {
                                                        let _e2160 = local_157;
                                                        phi_1731_ = (_e2160 <= 2139095040u);
                                                    }
                                                    let _e2163 = phi_1731_;
                                                    if _e2163 {
                                                        let _e2167 = global_2.member.member_4.member_1;
                                                        let _e2172 = global_2.member.member_4.member;
                                                        let _e2177 = global_2.member.member_4.member_2;
                                                        local_158 = _e2177;
                                                        let _e2183 = global_2.member.member_4.member_3;
                                                        let _e2184 = ((((2f * _e2167) * _e2172) / (_e2177 - _e2172)) * _e2183);
                                                        local_159 = _e2184;
                                                        if (_e2184 == 0f) {
                                                            phi_1759_ = 0f;
                                                        } else {
                                                            let _e2186 = local_158;
                                                            let _e2187 = local_156;
                                                            let _e2190 = local_159;
                                                            phi_1759_ = (_e2190 * (1f - (_e2186 / _e2187)));
                                                        }
                                                        let _e2193 = phi_1759_;
                                                        phi_1760_ = _e2193;
                                                    } else {
                                                        phi_1760_ = _e729;
                                                    }
                                                    let _e2195 = phi_1760_;
                                                    phi_1762_ = (0.5f * _e2195);
                                                }
                                                let _e2220 = phi_1762_;
                                                let _e2221 = local_24;
                                                let _e2223 = local_24;
                                                let _e2224 = select(_e2223, _e2220, (_e2220 < _e2221));
                                                let _e2225 = local_24;
                                                let _e2226 = -(_e2225);
                                                let _e2228 = select(_e2226, _e2224, (_e2224 > _e2226));
                                                local_605 = _e2228;
                                                if (_e2228 < 0f) {
                                                    let _e2230 = local_605;
                                                    phi_1779_ = -(_e2230);
                                                } else {
                                                    phi_1779_ = _e2228;
                                                }
                                                let _e2233 = phi_1779_;
                                                let _e2235 = ((_e2233 - 0.25f) * 4f);
                                                let _e2237 = select(0f, _e2235, (_e2235 > 0f));
                                                local_606 = select(1f, _e2237, (_e2237 < 1f));
                                                let _e2240 = local_155;
                                                let _e2242 = local_132;
                                                let _e2243 = (_e2240[0] - _e2242);
                                                let _e2246 = local_155;
                                                let _e2248 = local_133;
                                                let _e2249 = (_e2246[1] - _e2248);
                                                let _e2252 = local_155;
                                                let _e2254 = local_134;
                                                let _e2255 = (_e2252[2] - _e2254);
                                                let _e2262 = (((0.2126f * _e2240[0]) + (0.7152f * _e2246[1])) + (0.0722f * _e2252[2]));
                                                local_160 = _e2262;
                                                local_161 = (((0.2126f * select(0f, _e2243, (_e2243 > 0f))) + (0.7152f * select(0f, _e2249, (_e2249 > 0f)))) + (0.0722f * select(0f, _e2255, (_e2255 > 0f))));
                                                let _e2268 = local_135;
                                                if (_e2262 >= (8f * _e2268)) {
                                                    phi_1846_ = 1f;
                                                } else {
                                                    let _e2271 = local_135;
                                                    let _e2272 = (4f * _e2271);
                                                    let _e2273 = local_160;
                                                    let _e2275 = ((_e2273 - _e2272) / _e2272);
                                                    let _e2277 = select(0f, _e2275, (_e2275 > 0f));
                                                    phi_1846_ = select(1f, _e2277, (_e2277 < 1f));
                                                }
                                                let _e2281 = phi_1846_;
                                                let _e2282 = local_161;
                                                let _e2284 = ((_e2282 - 0.25f) * 4f);
                                                let _e2286 = select(0f, _e2284, (_e2284 > 0f));
                                                local_607 = select(1f, _e2286, (_e2286 < 1f));
                                                let _e2289 = local_606;
                                                local_162 = (_e2289 * _e2281);
                                                let _e2291 = local_137;
                                                if _e2291 {
                                                } else {
                                                    phi_6037_ = true;
                                                    break;
                                                }
                                                let _e2292 = local_136;
                                                let _e2294 = local_162;
                                                let _e2295 = local_607;
                                                local_625[_e2292] = (_e2294 * _e2295);
                                            }
                                        }
                                    }
                                    let _e2297 = local_136;
                                    phi_1494_ = (_e2297 + 1u);
                                } else {
                                    phi_1494_ = u32();
                                }
                                let _e2300 = phi_1494_;
                                continue;
                                continuing {
                                    let _e2301 = local_137;
                                    phi_1493_ = _e2300;
                                    phi_6037_ = _e1968;
                                    break if !(_e2301);
                                }
                            }
                            let _e2304 = phi_6037_;
                            if _e2304 {
                                break;
                            }
                            phi_6249_ = _e2304;
                            phi_6180_ = _e1976;
                            phi_6132_ = _e1979;
                            phi_6084_ = _e1982;
                        }
                        let _e2306 = phi_6249_;
                        let _e2308 = phi_6180_;
                        let _e2310 = phi_6132_;
                        let _e2312 = phi_6084_;
                        local_599 = _e2308;
                        local_598 = _e2310;
                        local_597 = _e2312;
                        let _e2313 = local_625;
                        local_596 = _e2313;
                        local_163 = _e2313[1];
                        local_164 = _e2313[2];
                        local_165 = _e2313[3];
                        if (_e2313[0] > 0f) {
                            phi_1901_ = bool();
                            phi_1902_ = true;
                        } else {
                            let _e2319 = local_163;
                            if (_e2319 > 0f) {
                                phi_1899_ = bool();
                                phi_1900_ = true;
                            } else {
                                let _e2321 = local_164;
                                let _e2322 = (_e2321 > 0f);
                                if _e2322 {
                                    phi_1898_ = bool();
                                } else {
                                    let _e2323 = local_165;
                                    phi_1898_ = (_e2323 > 0f);
                                }
                                let _e2326 = phi_1898_;
                                phi_1899_ = _e2326;
                                phi_1900_ = _e2322;
                            }
                            let _e2328 = phi_1899_;
                            let _e2330 = phi_1900_;
                            phi_1901_ = _e2328;
                            phi_1902_ = _e2330;
                        }
                        let _e2332 = phi_1901_;
                        let _e2334 = phi_1902_;
                        let _e2335 = select(_e2332, true, _e2334);
                        local_608 = _e2335;
                        if _e2335 {
                            local_645 = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_6244_ = _e2306;
                            phi_1914_ = 0u;
                            phi_1917_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_1919_ = array<f32, 3>(0f, 0f, 0f);
                            phi_1921_ = 0f;
                            phi_1923_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            phi_1925_ = 0f;
                            phi_1927_ = 0f;
                            phi_1929_ = array<f32, 3>(0f, 0f, 0f);
                            phi_1931_ = array<f32, 2>(0f, 0f);
                            phi_1933_ = 0u;
                            phi_1935_ = 0f;
                            loop {
                                let _e2337 = phi_6244_;
                                let _e2339 = phi_1914_;
                                let _e2341 = phi_1917_;
                                let _e2343 = phi_1919_;
                                let _e2345 = phi_1921_;
                                let _e2347 = phi_1923_;
                                let _e2349 = phi_1925_;
                                let _e2351 = phi_1927_;
                                let _e2353 = phi_1929_;
                                let _e2355 = phi_1931_;
                                let _e2357 = phi_1933_;
                                let _e2359 = phi_1935_;
                                local_166 = _e2339;
                                local_167 = _e2341;
                                local_168 = _e2343;
                                local_169 = _e2345;
                                local_170 = _e2347;
                                local_171 = _e2349;
                                local_172 = _e2351;
                                local_173 = _e2353;
                                local_174 = _e2355;
                                local_175 = _e2357;
                                local_176 = _e2359;
                                let _e2360 = local_166;
                                let _e2361 = (_e2360 < 4u);
                                local_177 = _e2361;
                                if _e2361 {
                                    let _e2362 = local_21;
                                    let _e2364 = local_166;
                                    let _e2366 = ((2u * _e2362) + (_e2364 % 2u));
                                    local_178 = _e2366;
                                    let _e2367 = local_22;
                                    let _e2369 = local_166;
                                    local_179 = ((2u * _e2367) + (_e2369 / 2u));
                                    let _e2372 = local_14;
                                    if (_e2366 < _e2372) {
                                        let _e2374 = local_179;
                                        let _e2375 = local_18;
                                        if (_e2374 < _e2375) {
                                            let _e2377 = local_179;
                                            let _e2378 = local_14;
                                            let _e2380 = local_178;
                                            let _e2381 = ((_e2377 * _e2378) + _e2380);
                                            local_180 = _e2381;
                                            let _e2382 = (3u * _e2381);
                                            local_181 = _e2382;
                                            let _e2383 = local_5;
                                            if (_e2382 < _e2383) {
                                            } else {
                                                phi_6268_ = true;
                                                break;
                                            }
                                            let _e2385 = local_181;
                                            let _e2388 = global_4.member[_e2385];
                                            local_182 = bitcast<f32>(_e2388);
                                            let _e2390 = local_181;
                                            let _e2391 = (_e2390 + 1u);
                                            local_183 = _e2391;
                                            let _e2392 = local_5;
                                            if (_e2391 < _e2392) {
                                            } else {
                                                phi_6268_ = true;
                                                break;
                                            }
                                            let _e2394 = local_183;
                                            let _e2397 = global_4.member[_e2394];
                                            local_184 = bitcast<f32>(_e2397);
                                            let _e2399 = local_181;
                                            let _e2400 = (_e2399 + 2u);
                                            local_185 = _e2400;
                                            let _e2401 = local_5;
                                            if (_e2400 < _e2401) {
                                            } else {
                                                phi_6268_ = true;
                                                break;
                                            }
                                            let _e2403 = local_185;
                                            let _e2406 = global_4.member[_e2403];
                                            local_186 = bitcast<f32>(_e2406);
                                            let _e2408 = local_182;
                                            if (_e2408 > 1267650600000000000000000000000f) {
                                                let _e2410 = local_182;
                                                phi_2003_ = select(true, false, (_e2410 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_2003_ = true;
                                            }
                                            let _e2414 = phi_2003_;
                                            if _e2414 {
                                                let _e2415 = local_182;
                                                if (_e2415 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e2417 = local_182;
                                                    phi_2017_ = select(true, false, (_e2417 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_2017_ = true;
                                                }
                                                let _e2421 = phi_2017_;
                                                let _e2422 = local_182;
                                                phi_2022_ = select(0f, _e2422, _e2421);
                                            } else {
                                                phi_2022_ = 1267650600000000000000000000000f;
                                            }
                                            let _e2425 = phi_2022_;
                                            local_187 = _e2425;
                                            let _e2426 = local_184;
                                            if (_e2426 > 1267650600000000000000000000000f) {
                                                let _e2428 = local_184;
                                                phi_2032_ = select(true, false, (_e2428 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_2032_ = true;
                                            }
                                            let _e2432 = phi_2032_;
                                            if _e2432 {
                                                let _e2433 = local_184;
                                                if (_e2433 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e2435 = local_184;
                                                    phi_2046_ = select(true, false, (_e2435 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_2046_ = true;
                                                }
                                                let _e2439 = phi_2046_;
                                                let _e2440 = local_184;
                                                phi_2051_ = select(0f, _e2440, _e2439);
                                            } else {
                                                phi_2051_ = 1267650600000000000000000000000f;
                                            }
                                            let _e2443 = phi_2051_;
                                            local_188 = _e2443;
                                            let _e2444 = local_186;
                                            if (_e2444 > 1267650600000000000000000000000f) {
                                                let _e2446 = local_186;
                                                phi_2061_ = select(true, false, (_e2446 <= 340282350000000000000000000000000000000f));
                                            } else {
                                                phi_2061_ = true;
                                            }
                                            let _e2450 = phi_2061_;
                                            if _e2450 {
                                                let _e2451 = local_186;
                                                if (_e2451 < 0.000000000000000000000000000000000000011754944f) {
                                                    let _e2453 = local_186;
                                                    phi_2075_ = select(true, false, (_e2453 >= -340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_2075_ = true;
                                                }
                                                let _e2457 = phi_2075_;
                                                let _e2458 = local_186;
                                                phi_2080_ = select(0f, _e2458, _e2457);
                                            } else {
                                                phi_2080_ = 1267650600000000000000000000000f;
                                            }
                                            let _e2461 = phi_2080_;
                                            local_189 = _e2461;
                                            let _e2462 = local_187;
                                            let _e2463 = local_188;
                                            local_190 = array<f32, 3>(_e2462, _e2463, _e2461);
                                            let _e2465 = local_180;
                                            let _e2466 = local_6;
                                            if (_e2465 < _e2466) {
                                            } else {
                                                phi_6268_ = true;
                                                break;
                                            }
                                            let _e2468 = local_180;
                                            let _e2471 = global_3.member[_e2468];
                                            local_191 = bitcast<f32>(_e2471);
                                            let _e2473 = local_187;
                                            if ((bitcast<u32>(_e2473) & 2139095040u) != 2139095040u) {
                                                let _e2477 = local_188;
                                                if ((bitcast<u32>(_e2477) & 2139095040u) != 2139095040u) {
                                                    let _e2481 = local_189;
                                                    if ((bitcast<u32>(_e2481) & 2139095040u) != 2139095040u) {
                                                        let _e2485 = local_191;
                                                        let _e2486 = bitcast<u32>(_e2485);
                                                        local_192 = _e2486;
                                                        if (_e2486 == 0u) {
                                                            phi_2114_ = false;
                                                        } else {
                                                            let _e2488 = local_192;
                                                            phi_2114_ = (_e2488 <= 2139095040u);
                                                        }
                                                        let _e2491 = phi_2114_;
                                                        local_193 = _e2491;
                                                        if _e2491 {
                                                            let _e2492 = local_190;
                                                            let _e2493 = local_191;
                                                            phi_2120_ = type_23(1u, type_22(_e2492, _e2493));
                                                        } else {
                                                            phi_2120_ = type_23();
                                                        }
                                                        let _e2497 = phi_2120_;
                                                        let _e2498 = local_193;
                                                        phi_2122_ = _e2497;
                                                        phi_2123_ = select(true, false, _e2498);
                                                    } else {
                                                        phi_2122_ = type_23();
                                                        phi_2123_ = true;
                                                    }
                                                    let _e2501 = phi_2122_;
                                                    let _e2503 = phi_2123_;
                                                    phi_2124_ = _e2501;
                                                    phi_2125_ = _e2503;
                                                } else {
                                                    phi_2124_ = type_23();
                                                    phi_2125_ = true;
                                                }
                                                let _e2505 = phi_2124_;
                                                let _e2507 = phi_2125_;
                                                phi_2126_ = _e2505;
                                                phi_2127_ = _e2507;
                                            } else {
                                                phi_2126_ = type_23();
                                                phi_2127_ = true;
                                            }
                                            let _e2509 = phi_2126_;
                                            let _e2511 = phi_2127_;
                                            if _e2511 {
                                                phi_2132_ = type_23(0u, type_23().member_1);
                                            } else {
                                                phi_2132_ = _e2509;
                                            }
                                            let _e2516 = phi_2132_;
                                            local_194 = _e2516;
                                            if (bitcast<i32>(_e2516.member) != 0i) {
                                                let _e2520 = local_194;
                                                local_195 = _e2520.member_1.member;
                                                let _e2523 = local_194;
                                                local_196 = _e2523.member_1.member_1;
                                                let _e2526 = bitcast<u32>(_e2523.member_1.member_1);
                                                local_197 = _e2526;
                                                if (_e2526 == 2139095040u) {
                                                    let _e2570 = global_2.member.member_4.member_1;
                                                    let _e2575 = global_2.member.member_4.member;
                                                    let _e2580 = global_2.member.member_4.member_2;
                                                    let _e2586 = global_2.member.member_4.member_3;
                                                    phi_2200_ = (0.5f * ((((2f * _e2570) * _e2575) / (_e2580 - _e2575)) * _e2586));
                                                } else {
                                                    let _e2528 = local_197;
                                                    if (_e2528 == 0u) {
                                                        phi_2169_ = false;
                                                    } else {
                                                        let _e2530 = local_197;
                                                        phi_2169_ = (_e2530 <= 2139095040u);
                                                    }
                                                    let _e2533 = phi_2169_;
                                                    if _e2533 {
                                                        let _e2537 = global_2.member.member_4.member_1;
                                                        let _e2542 = global_2.member.member_4.member;
                                                        let _e2547 = global_2.member.member_4.member_2;
                                                        local_198 = _e2547;
                                                        let _e2553 = global_2.member.member_4.member_3;
                                                        let _e2554 = ((((2f * _e2537) * _e2542) / (_e2547 - _e2542)) * _e2553);
                                                        local_199 = _e2554;
                                                        if (_e2554 == 0f) {
                                                            phi_2197_ = 0f;
                                                        } else {
                                                            let _e2556 = local_198;
                                                            let _e2557 = local_196;
                                                            let _e2560 = local_199;
                                                            phi_2197_ = (_e2560 * (1f - (_e2556 / _e2557)));
                                                        }
                                                        let _e2563 = phi_2197_;
                                                        phi_2198_ = _e2563;
                                                    } else {
                                                        phi_2198_ = _e729;
                                                    }
                                                    let _e2565 = phi_2198_;
                                                    phi_2200_ = (0.5f * _e2565);
                                                }
                                                let _e2590 = phi_2200_;
                                                let _e2591 = local_24;
                                                let _e2593 = local_24;
                                                let _e2594 = select(_e2593, _e2590, (_e2590 < _e2591));
                                                let _e2595 = local_24;
                                                let _e2596 = -(_e2595);
                                                local_609 = select(_e2596, _e2594, (_e2594 > _e2596));
                                                let _e2599 = local_195;
                                                let _e2601 = local_195;
                                                let _e2603 = local_195;
                                                local_642 = array<f32, 3>(_e2599[0], _e2601[1], _e2603[2]);
                                                let _e2606 = local_599;
                                                let _e2607 = local_598;
                                                let _e2608 = local_597;
                                                let _e2610 = local_596;
                                                local_627 = _e2610;
                                                local_626 = array<f32, 3>(_e2606, _e2607, _e2608);
                                                let _e2611 = local_177;
                                                if _e2611 {
                                                } else {
                                                    phi_6268_ = true;
                                                    break;
                                                }
                                                let _e2612 = local_166;
                                                let _e2614 = local_627[_e2612];
                                                local_200 = _e2614;
                                                if (_e2614 <= 0f) {
                                                    let _e2675 = local_642;
                                                    phi_6278_ = _e2337;
                                                    phi_2318_ = type_25(array<f32, 3>(_e2675[0], _e2675[1], _e2675[2]), array<f32, 3>(0f, 0f, 0f));
                                                } else {
                                                    let _e2616 = local_642;
                                                    local_643 = _e2616;
                                                    local_644 = array<f32, 3>(0f, 0f, 0f);
                                                    phi_2246_ = 0u;
                                                    loop {
                                                        let _e2618 = phi_2246_;
                                                        local_201 = _e2618;
                                                        let _e2619 = local_201;
                                                        let _e2620 = (_e2619 < 3u);
                                                        local_202 = _e2620;
                                                        if _e2620 {
                                                            let _e2621 = local_202;
                                                            if _e2621 {
                                                            } else {
                                                                phi_6228_ = true;
                                                                break;
                                                            }
                                                            let _e2622 = local_201;
                                                            let _e2624 = local_626[_e2622];
                                                            local_203 = _e2624;
                                                            let _e2625 = local_202;
                                                            if _e2625 {
                                                            } else {
                                                                phi_6228_ = true;
                                                                break;
                                                            }
                                                            let _e2626 = local_201;
                                                            let _e2628 = local_642[_e2626];
                                                            let _e2629 = local_203;
                                                            if (_e2628 > _e2629) {
                                                                let _e2631 = local_202;
                                                                if _e2631 {
                                                                } else {
                                                                    phi_6228_ = true;
                                                                    break;
                                                                }
                                                                let _e2632 = local_642[_e2626];
                                                                let _e2633 = local_203;
                                                                local_204 = (_e2632 - _e2633);
                                                                let _e2635 = local_202;
                                                                if _e2635 {
                                                                } else {
                                                                    phi_6228_ = true;
                                                                    break;
                                                                }
                                                                let _e2636 = local_201;
                                                                let _e2638 = local_200;
                                                                let _e2639 = local_204;
                                                                local_644[_e2636] = (_e2638 * _e2639);
                                                                let _e2641 = local_200;
                                                                local_205 = (1f - _e2641);
                                                                let _e2643 = local_202;
                                                                if _e2643 {
                                                                } else {
                                                                    phi_6228_ = true;
                                                                    break;
                                                                }
                                                                let _e2644 = local_642[_e2626];
                                                                let _e2645 = local_205;
                                                                local_206 = (_e2645 * _e2644);
                                                                let _e2647 = local_200;
                                                                let _e2648 = local_203;
                                                                local_207 = (_e2647 * _e2648);
                                                                let _e2650 = local_202;
                                                                if _e2650 {
                                                                } else {
                                                                    phi_6228_ = true;
                                                                    break;
                                                                }
                                                                let _e2651 = local_201;
                                                                let _e2653 = local_206;
                                                                let _e2654 = local_207;
                                                                local_643[_e2651] = (_e2653 + _e2654);
                                                            }
                                                            let _e2656 = local_201;
                                                            phi_2247_ = (_e2656 + 1u);
                                                        } else {
                                                            phi_2247_ = u32();
                                                        }
                                                        let _e2659 = phi_2247_;
                                                        continue;
                                                        continuing {
                                                            let _e2660 = local_202;
                                                            phi_2246_ = _e2659;
                                                            phi_6228_ = _e2337;
                                                            break if !(_e2660);
                                                        }
                                                    }
                                                    let _e2663 = phi_6228_;
                                                    phi_6268_ = _e2663;
                                                    if _e2663 {
                                                        break;
                                                    }
                                                    let _e2664 = local_643;
                                                    let _e2669 = local_644;
                                                    phi_6278_ = _e2663;
                                                    phi_2318_ = type_25(array<f32, 3>(_e2664[0], _e2664[1], _e2664[2]), array<f32, 3>(_e2669[0], _e2669[1], _e2669[2]));
                                                }
                                                let _e2682 = phi_6278_;
                                                let _e2684 = phi_2318_;
                                                local_208 = _e2684.member;
                                                let _e2687 = local_168;
                                                let _e2691 = local_168;
                                                let _e2695 = local_168;
                                                local_209 = (((0.2126f * _e2684.member_1[0]) + (0.7152f * _e2684.member_1[1])) + (0.0722f * _e2684.member_1[2]));
                                                let _e2705 = local_177;
                                                if _e2705 {
                                                } else {
                                                    phi_6268_ = true;
                                                    break;
                                                }
                                                let _e2706 = local_166;
                                                let _e2708 = local_209;
                                                local_645[_e2706] = _e2708;
                                                let _e2709 = local_167;
                                                let _e2711 = local_178;
                                                let _e2712 = f32(_e2711);
                                                let _e2714 = local_209;
                                                let _e2717 = local_167;
                                                let _e2719 = local_179;
                                                let _e2720 = f32(_e2719);
                                                let _e2722 = local_209;
                                                let _e2725 = local_167;
                                                let _e2727 = local_209;
                                                let _e2728 = local_609;
                                                let _e2731 = local_167;
                                                let _e2733 = local_209;
                                                let _e2736 = local_176;
                                                let _e2737 = local_609;
                                                let _e2739 = local_174;
                                                let _e2743 = local_174;
                                                let _e2748 = local_175;
                                                let _e2750 = local_609;
                                                let _e2752 = local_609;
                                                let _e2754 = ((-1f - _e2752) * 0.5f);
                                                let _e2756 = select(0f, _e2754, (_e2754 > 0f));
                                                let _e2758 = select(1f, _e2756, (_e2756 < 1f));
                                                let _e2759 = local_173;
                                                let _e2761 = local_208;
                                                let _e2765 = local_173;
                                                let _e2767 = local_208;
                                                let _e2771 = local_173;
                                                let _e2773 = local_208;
                                                let _e2778 = local_609;
                                                let _e2780 = local_172;
                                                let _e2782 = local_171;
                                                let _e2785 = local_609;
                                                let _e2787 = local_609;
                                                let _e2789 = (select(_e2787, -(_e2750), (_e2785 < 0f)) - 1f);
                                                let _e2791 = select(0f, _e2789, (_e2789 > 0f));
                                                let _e2795 = ((1f - _e2758) * (select(1f, _e2791, (_e2791 < 1f)) + 0.001f));
                                                let _e2796 = local_170;
                                                let _e2800 = local_170;
                                                let _e2804 = local_170;
                                                let _e2808 = local_170;
                                                let _e2810 = local_609;
                                                let _e2814 = local_169;
                                                phi_6272_ = _e2682;
                                                phi_2438_ = array<f32, 4>((_e2709[0] + (_e2714 * (_e2712 + 0.5f))), (_e2717[1] + (_e2722 * (_e2720 + 0.5f))), (_e2725[2] + (_e2727 * _e2728)), (_e2731[3] + _e2733));
                                                phi_2439_ = array<f32, 3>((_e2687[0] + _e2684.member_1[0]), (_e2691[1] + _e2684.member_1[1]), (_e2695[2] + _e2684.member_1[2]));
                                                phi_2440_ = (_e2814 + _e2795);
                                                phi_2441_ = array<f32, 4>((_e2796[0] + (_e2795 * _e2761[0])), (_e2800[1] + (_e2795 * _e2767[1])), (_e2804[2] + (_e2795 * _e2773[2])), (_e2808[3] + (_e2795 * _e2810)));
                                                phi_2442_ = (_e2782 + _e2758);
                                                phi_2443_ = (_e2780 + (_e2758 * _e2778));
                                                phi_2444_ = array<f32, 3>((_e2759[0] + (_e2758 * _e2761[0])), (_e2765[1] + (_e2758 * _e2767[1])), (_e2771[2] + (_e2758 * _e2773[2])));
                                                phi_2445_ = array<f32, 2>(((_e2739[0] + _e2712) + 0.5f), ((_e2743[1] + _e2720) + 0.5f));
                                                phi_2446_ = (_e2748 + 1u);
                                                phi_2447_ = (_e2736 + _e2737);
                                            } else {
                                                phi_6272_ = _e2337;
                                                phi_2438_ = _e2341;
                                                phi_2439_ = _e2343;
                                                phi_2440_ = _e2345;
                                                phi_2441_ = _e2347;
                                                phi_2442_ = _e2349;
                                                phi_2443_ = _e2351;
                                                phi_2444_ = _e2353;
                                                phi_2445_ = _e2355;
                                                phi_2446_ = _e2357;
                                                phi_2447_ = _e2359;
                                            }
                                            let _e2817 = phi_6272_;
                                            let _e2819 = phi_2438_;
                                            let _e2821 = phi_2439_;
                                            let _e2823 = phi_2440_;
                                            let _e2825 = phi_2441_;
                                            let _e2827 = phi_2442_;
                                            let _e2829 = phi_2443_;
                                            let _e2831 = phi_2444_;
                                            let _e2833 = phi_2445_;
                                            let _e2835 = phi_2446_;
                                            let _e2837 = phi_2447_;
                                            phi_6271_ = _e2817;
                                            phi_2448_ = _e2819;
                                            phi_2449_ = _e2821;
                                            phi_2450_ = _e2823;
                                            phi_2451_ = _e2825;
                                            phi_2452_ = _e2827;
                                            phi_2453_ = _e2829;
                                            phi_2454_ = _e2831;
                                            phi_2455_ = _e2833;
                                            phi_2456_ = _e2835;
                                            phi_2457_ = _e2837;
                                        } else {
                                            phi_6271_ = _e2337;
                                            phi_2448_ = _e2341;
                                            phi_2449_ = _e2343;
                                            phi_2450_ = _e2345;
                                            phi_2451_ = _e2347;
                                            phi_2452_ = _e2349;
                                            phi_2453_ = _e2351;
                                            phi_2454_ = _e2353;
                                            phi_2455_ = _e2355;
                                            phi_2456_ = _e2357;
                                            phi_2457_ = _e2359;
                                        }
                                        let _e2839 = phi_6271_;
                                        let _e2841 = phi_2448_;
                                        let _e2843 = phi_2449_;
                                        let _e2845 = phi_2450_;
                                        let _e2847 = phi_2451_;
                                        let _e2849 = phi_2452_;
                                        let _e2851 = phi_2453_;
                                        let _e2853 = phi_2454_;
                                        let _e2855 = phi_2455_;
                                        let _e2857 = phi_2456_;
                                        let _e2859 = phi_2457_;
                                        phi_6270_ = _e2839;
                                        phi_2458_ = _e2841;
                                        phi_2459_ = _e2843;
                                        phi_2460_ = _e2845;
                                        phi_2461_ = _e2847;
                                        phi_2462_ = _e2849;
                                        phi_2463_ = _e2851;
                                        phi_2464_ = _e2853;
                                        phi_2465_ = _e2855;
                                        phi_2466_ = _e2857;
                                        phi_2467_ = _e2859;
                                    } else {
                                        phi_6270_ = _e2337;
                                        phi_2458_ = _e2341;
                                        phi_2459_ = _e2343;
                                        phi_2460_ = _e2345;
                                        phi_2461_ = _e2347;
                                        phi_2462_ = _e2349;
                                        phi_2463_ = _e2351;
                                        phi_2464_ = _e2353;
                                        phi_2465_ = _e2355;
                                        phi_2466_ = _e2357;
                                        phi_2467_ = _e2359;
                                    }
                                    let _e2861 = phi_6270_;
                                    let _e2863 = phi_2458_;
                                    let _e2865 = phi_2459_;
                                    let _e2867 = phi_2460_;
                                    let _e2869 = phi_2461_;
                                    let _e2871 = phi_2462_;
                                    let _e2873 = phi_2463_;
                                    let _e2875 = phi_2464_;
                                    let _e2877 = phi_2465_;
                                    let _e2879 = phi_2466_;
                                    let _e2881 = phi_2467_;
                                    let _e2882 = local_166;
                                    phi_6269_ = _e2861;
                                    phi_1915_ = (_e2882 + 1u);
                                    phi_1918_ = _e2863;
                                    phi_1920_ = _e2865;
                                    phi_1922_ = _e2867;
                                    phi_1924_ = _e2869;
                                    phi_1926_ = _e2871;
                                    phi_1928_ = _e2873;
                                    phi_1930_ = _e2875;
                                    phi_1932_ = _e2877;
                                    phi_1934_ = _e2879;
                                    phi_1936_ = _e2881;
                                } else {
                                    phi_6269_ = _e2337;
                                    phi_1915_ = u32();
                                    phi_1918_ = array<f32, 4>();
                                    phi_1920_ = array<f32, 3>();
                                    phi_1922_ = f32();
                                    phi_1924_ = array<f32, 4>();
                                    phi_1926_ = f32();
                                    phi_1928_ = f32();
                                    phi_1930_ = array<f32, 3>();
                                    phi_1932_ = array<f32, 2>();
                                    phi_1934_ = u32();
                                    phi_1936_ = f32();
                                }
                                let _e2885 = phi_6269_;
                                let _e2887 = phi_1915_;
                                let _e2889 = phi_1918_;
                                let _e2891 = phi_1920_;
                                let _e2893 = phi_1922_;
                                let _e2895 = phi_1924_;
                                let _e2897 = phi_1926_;
                                let _e2899 = phi_1928_;
                                let _e2901 = phi_1930_;
                                let _e2903 = phi_1932_;
                                let _e2905 = phi_1934_;
                                let _e2907 = phi_1936_;
                                continue;
                                continuing {
                                    let _e2908 = local_177;
                                    phi_6244_ = _e2885;
                                    phi_1914_ = _e2887;
                                    phi_1917_ = _e2889;
                                    phi_1919_ = _e2891;
                                    phi_1921_ = _e2893;
                                    phi_1923_ = _e2895;
                                    phi_1925_ = _e2897;
                                    phi_1927_ = _e2899;
                                    phi_1929_ = _e2901;
                                    phi_1931_ = _e2903;
                                    phi_1933_ = _e2905;
                                    phi_1935_ = _e2907;
                                    phi_6268_ = _e2885;
                                    break if !(_e2908);
                                }
                            }
                            let _e2911 = phi_6268_;
                            if _e2911 {
                                break;
                            }
                            let _e2912 = local_175;
                            if (_e2912 == 0u) {
                                let _e3086 = local_622;
                                let _e3087 = local_175;
                                phi_6300_ = _e2911;
                                phi_2606_ = type_30(array<f32, 2>(0f, 0f), array<f32, 3>(0f, 0f, 0f), 0f, 0f, array<f32, 3>(0f, 0f, 0f), _e3086, _e3087, array<f32, 3>(0f, 0f, 0f), 0f, 0f);
                            } else {
                                let _e2914 = local_175;
                                let _e2915 = f32(_e2914);
                                let _e2916 = (1f / _e2915);
                                local_210 = _e2916;
                                let _e2917 = local_176;
                                let _e2919 = ((0.5f * _e2917) * _e2916);
                                local_211 = _e2919;
                                let _e2920 = local_171;
                                let _e2922 = ((_e2915 - _e2920) > 0f);
                                local_212 = _e2922;
                                if _e2922 {
                                    let _e2923 = local_169;
                                    let _e2924 = (_e2923 > 0f);
                                    local_213 = _e2924;
                                    if _e2924 {
                                        let _e2925 = local_169;
                                        let _e2926 = (1f / _e2925);
                                        let _e2927 = local_170;
                                        let _e2930 = local_170;
                                        let _e2933 = local_170;
                                        let _e2937 = local_170;
                                        phi_2498_ = array<f32, 3>((_e2927[0] * _e2926), (_e2930[1] * _e2926), (_e2933[2] * _e2926));
                                        phi_2499_ = ((0.5f * _e2937[3]) * _e2926);
                                    } else {
                                        phi_2498_ = array<f32, 3>();
                                        phi_2499_ = f32();
                                    }
                                    let _e2942 = phi_2498_;
                                    let _e2944 = phi_2499_;
                                    let _e2945 = local_213;
                                    phi_2501_ = _e2942;
                                    phi_2502_ = _e2944;
                                    phi_2503_ = select(true, false, _e2945);
                                } else {
                                    phi_2501_ = array<f32, 3>();
                                    phi_2502_ = f32();
                                    phi_2503_ = true;
                                }
                                let _e2948 = phi_2501_;
                                let _e2950 = phi_2502_;
                                let _e2952 = phi_2503_;
                                local_214 = _e2950;
                                local_215 = _e2952;
                                if _e2952 {
                                    phi_2507_ = array<f32, 3>(0f, 0f, 0f);
                                } else {
                                    phi_2507_ = _e2948;
                                }
                                let _e2954 = phi_2507_;
                                local_216 = _e2954;
                                let _e2955 = local_215;
                                let _e2956 = local_211;
                                let _e2957 = local_214;
                                local_610 = select(_e2957, _e2956, _e2955);
                                let _e2959 = local_171;
                                if (_e2959 > 0f) {
                                    let _e2961 = local_171;
                                    let _e2962 = (1f / _e2961);
                                    let _e2963 = local_173;
                                    let _e2966 = local_173;
                                    let _e2969 = local_173;
                                    let _e2973 = local_172;
                                    phi_2523_ = array<f32, 3>((_e2963[0] * _e2962), (_e2966[1] * _e2962), (_e2969[2] * _e2962));
                                    phi_2524_ = ((0.5f * _e2973) * _e2962);
                                } else {
                                    phi_2523_ = array<f32, 3>(0f, 0f, 0f);
                                    phi_2524_ = _e2919;
                                }
                                let _e2977 = phi_2523_;
                                let _e2979 = phi_2524_;
                                local_217 = _e2977;
                                local_218 = _e2979;
                                let _e2980 = local_212;
                                if _e2980 {
                                    let _e2981 = local_171;
                                    let _e2982 = local_210;
                                    phi_2530_ = (_e2981 * _e2982);
                                } else {
                                    phi_2530_ = 1f;
                                }
                                let _e2985 = phi_2530_;
                                local_219 = _e2985;
                                let _e2986 = local_174;
                                let _e2988 = local_210;
                                let _e2990 = local_174;
                                let _e2992 = local_210;
                                let _e2995 = local_167;
                                local_220 = _e2995[3];
                                if (_e2995[3] > 0f) {
                                    let _e3000 = local_220;
                                    let _e3001 = (1f / _e3000);
                                    local_221 = _e3001;
                                    let _e3002 = local_167;
                                    let _e3004 = (_e3002[0] * _e3001);
                                    local_222 = _e3004;
                                    let _e3005 = local_167;
                                    let _e3007 = (_e3005[1] * _e3001);
                                    local_223 = _e3007;
                                    phi_2549_ = 0u;
                                    phi_2552_ = 0f;
                                    loop {
                                        let _e3010 = phi_2549_;
                                        let _e3012 = phi_2552_;
                                        local_224 = _e3010;
                                        local_225 = _e3012;
                                        let _e3013 = local_224;
                                        let _e3014 = (_e3013 < 4u);
                                        local_226 = _e3014;
                                        if _e3014 {
                                            let _e3015 = local_226;
                                            if _e3015 {
                                            } else {
                                                phi_6279_ = true;
                                                break;
                                            }
                                            let _e3016 = local_224;
                                            let _e3018 = local_645[_e3016];
                                            if (_e3018 > 0f) {
                                                let _e3020 = local_21;
                                                let _e3022 = local_224;
                                                let _e3027 = local_222;
                                                local_227 = ((f32(((2u * _e3020) + (_e3022 % 2u))) + 0.5f) - _e3027);
                                                let _e3029 = local_22;
                                                let _e3031 = local_224;
                                                let _e3036 = local_223;
                                                local_228 = ((f32(((2u * _e3029) + (_e3031 / 2u))) + 0.5f) - _e3036);
                                                let _e3038 = local_226;
                                                if _e3038 {
                                                } else {
                                                    phi_6279_ = true;
                                                    break;
                                                }
                                                let _e3039 = local_645[_e3016];
                                                let _e3040 = local_227;
                                                let _e3041 = local_227;
                                                let _e3043 = local_228;
                                                let _e3044 = local_228;
                                                let _e3049 = local_225;
                                                phi_2596_ = (_e3049 + (_e3039 * sqrt(((_e3040 * _e3041) + (_e3043 * _e3044)))));
                                            } else {
                                                phi_2596_ = _e3012;
                                            }
                                            let _e3052 = phi_2596_;
                                            let _e3053 = local_224;
                                            phi_2550_ = (_e3053 + 1u);
                                            phi_2553_ = _e3052;
                                        } else {
                                            phi_2550_ = u32();
                                            phi_2553_ = f32();
                                        }
                                        let _e3056 = phi_2550_;
                                        let _e3058 = phi_2553_;
                                        continue;
                                        continuing {
                                            let _e3059 = local_226;
                                            phi_2549_ = _e3056;
                                            phi_2552_ = _e3058;
                                            phi_6279_ = _e2911;
                                            break if !(_e3059);
                                        }
                                    }
                                    let _e3062 = phi_6279_;
                                    if _e3062 {
                                        break;
                                    }
                                    let _e3063 = local_167;
                                    let _e3065 = local_221;
                                    let _e3067 = local_225;
                                    let _e3068 = local_221;
                                    phi_6301_ = _e3062;
                                    phi_2602_ = (_e3063[2] * _e3065);
                                    phi_2603_ = (_e3067 * _e3068);
                                    phi_2604_ = array<f32, 2>(_e3004, _e3007);
                                } else {
                                    let _e2998 = local_211;
                                    phi_6301_ = _e2911;
                                    phi_2602_ = (2f * _e2998);
                                    phi_2603_ = 0f;
                                    phi_2604_ = array<f32, 2>((_e2986[0] * _e2988), (_e2990[1] * _e2992));
                                }
                                let _e3071 = phi_6301_;
                                let _e3073 = phi_2602_;
                                let _e3075 = phi_2603_;
                                let _e3077 = phi_2604_;
                                let _e3078 = local_217;
                                let _e3079 = local_219;
                                let _e3080 = local_218;
                                let _e3081 = local_216;
                                let _e3082 = local_610;
                                let _e3083 = local_175;
                                let _e3084 = local_168;
                                phi_6300_ = _e3071;
                                phi_2606_ = type_30(_e3077, _e3078, _e3079, _e3080, _e3081, _e3082, _e3083, _e3084, _e3073, _e3075);
                            }
                            let _e3090 = phi_6300_;
                            let _e3092 = phi_2606_;
                            local_229 = _e3092;
                            local_230 = _e3092.member_8;
                            if (_e3092.member_8 < 0f) {
                                let _e3099 = local_230;
                                let _e3101 = local_230;
                                phi_2622_ = select(-0.5f, _e3101, (_e3099 < -0.5f));
                            } else {
                                let _e3095 = local_230;
                                let _e3097 = local_230;
                                phi_2622_ = select(0.5f, _e3097, (_e3095 > 0.5f));
                            }
                            let _e3104 = phi_2622_;
                            local_231 = _e3104;
                            if (_e3104 < 0f) {
                                let _e3106 = local_231;
                                phi_2628_ = -(_e3106);
                            } else {
                                phi_2628_ = _e3104;
                            }
                            let _e3109 = phi_2628_;
                            let _e3110 = local_229;
                            phi_6296_ = _e3090;
                            phi_2631_ = (_e3109 + _e3110.member_9);
                        } else {
                            phi_6296_ = _e2306;
                            phi_2631_ = 0f;
                        }
                        let _e3114 = phi_6296_;
                        let _e3116 = phi_2631_;
                        let _e3117 = local_608;
                        phi_6295_ = _e3114;
                        phi_2633_ = select(0f, _e1609, (_e1609 > 0f));
                        phi_2634_ = _e3116;
                        phi_2635_ = select(0u, 1u, _e3117);
                    } else {
                        phi_6295_ = _e1600;
                        phi_2633_ = 0f;
                        phi_2634_ = 0f;
                        phi_2635_ = 0u;
                    }
                    let _e3120 = phi_6295_;
                    let _e3122 = phi_2633_;
                    let _e3124 = phi_2634_;
                    let _e3126 = phi_2635_;
                    phi_6294_ = _e3120;
                    phi_2636_ = _e3122;
                    phi_2637_ = _e3124;
                    phi_2638_ = _e3126;
                } else {
                    phi_6294_ = false;
                    phi_2636_ = 0f;
                    phi_2637_ = 0f;
                    phi_2638_ = 0u;
                }
                let _e3128 = phi_6294_;
                let _e3130 = phi_2636_;
                let _e3132 = phi_2637_;
                let _e3134 = phi_2638_;
                phi_6293_ = _e3128;
                phi_2639_ = _e3130;
                phi_2640_ = _e3132;
                phi_2641_ = _e3134;
            } else {
                phi_6293_ = false;
                phi_2639_ = 0f;
                phi_2640_ = 0f;
                phi_2641_ = 0u;
            }
            let _e3136 = phi_6293_;
            let _e3138 = phi_2639_;
            let _e3140 = phi_2640_;
            let _e3142 = phi_2641_;
            local_232 = _e3138;
            local_233 = _e3140;
            local_234 = _e3142;
            let _e3143 = local;
            if (_e3143 < 384u) {
            } else {
                break;
            }
            let _e3145 = local;
            let _e3147 = local_234;
            global_10[_e3145] = _e3147;
            let _e3148 = local_232;
            local_235 = bitcast<u32>(_e3148);
            let _e3150 = local;
            let _e3151 = (128u + _e3150);
            local_236 = _e3151;
            if (_e3151 < 384u) {
            } else {
                break;
            }
            let _e3153 = local_236;
            let _e3155 = local_235;
            global_10[_e3153] = _e3155;
            let _e3156 = local_233;
            local_237 = bitcast<u32>(_e3156);
            let _e3158 = local;
            let _e3159 = (256u + _e3158);
            local_238 = _e3159;
            if (_e3159 < 384u) {
            } else {
                break;
            }
            let _e3161 = local_238;
            let _e3163 = local_237;
            global_10[_e3161] = _e3163;
            storageBarrier();
            workgroupBarrier();
            let _e3164 = local_1;
            let _e3165 = (_e3164 >= 2u);
            local_239 = _e3165;
            if _e3165 {
                let _e3166 = local_1;
                let _e3168 = local_1;
                if ((_e3168 & (_e3166 - 1u)) == 0u) {
                    let _e3171 = local_2;
                    let _e3172 = local_1;
                    let _e3174 = ((_e3171 * _e3172) == 64u);
                    local_240 = _e3174;
                    if _e3174 {
                        let _e3175 = local_1;
                        phi_2680_ = type_34(1u, _e3175);
                    } else {
                        phi_2680_ = type_34();
                    }
                    let _e3178 = phi_2680_;
                    let _e3179 = local_240;
                    phi_2682_ = _e3178;
                    phi_2683_ = select(true, false, _e3179);
                } else {
                    phi_2682_ = type_34();
                    phi_2683_ = true;
                }
                let _e3182 = phi_2682_;
                let _e3184 = phi_2683_;
                phi_2684_ = _e3182;
                phi_2685_ = _e3184;
            } else {
                phi_2684_ = type_34();
                phi_2685_ = true;
            }
            let _e3186 = phi_2684_;
            let _e3188 = phi_2685_;
            if _e3188 {
                phi_2690_ = type_34(0u, type_34().member_1);
            } else {
                phi_2690_ = _e3186;
            }
            let _e3193 = phi_2690_;
            local_241 = _e3193.member_1;
            if (bitcast<i32>(_e3193.member) != 0i) {
                let _e3247 = local_241;
                let _e3249 = local_241;
                local_242 = select(firstTrailingBit(_e3247), 32u, (_e3249 == 0u));
                let _e3252 = local_3;
                let _e3253 = local_1;
                let _e3255 = local_4;
                let _e3256 = ((_e3252 * _e3253) + _e3255);
                local_243 = _e3256;
                if (_e3256 < 384u) {
                } else {
                    break;
                }
                let _e3258 = local_243;
                let _e3260 = global_10[_e3258];
                let _e3261 = subgroupInclusiveAdd(_e3260);
                local_244 = _e3261;
                let _e3262 = local_243;
                let _e3263 = (64u + _e3262);
                local_245 = _e3263;
                if (_e3263 < 384u) {
                } else {
                    break;
                }
                let _e3265 = local_245;
                let _e3267 = local_244;
                global_10[_e3265] = _e3267;
                storageBarrier();
                workgroupBarrier();
                phi_2727_ = 0u;
                phi_2730_ = 64u;
                phi_2731_ = 64u;
                phi_2733_ = 0u;
                loop {
                    let _e3269 = phi_2727_;
                    let _e3271 = phi_2730_;
                    let _e3273 = phi_2731_;
                    let _e3275 = phi_2733_;
                    local_246 = _e3269;
                    local_247 = _e3271;
                    local_248 = _e3273;
                    local_249 = _e3275;
                    local_654 = _e3271;
                    local_655 = _e3273;
                    local_656 = _e3275;
                    let _e3276 = local_248;
                    let _e3277 = local_241;
                    let _e3278 = (_e3276 > _e3277);
                    local_250 = _e3278;
                    if _e3278 {
                        let _e3279 = local_242;
                        let _e3280 = (_e3279 & 31u);
                        local_251 = _e3280;
                        let _e3281 = local_248;
                        let _e3283 = (_e3281 >> bitcast<u32>(_e3280));
                        local_252 = _e3283;
                        let _e3284 = local_243;
                        let _e3285 = (_e3284 < _e3283);
                        local_253 = _e3285;
                        if _e3285 {
                            let _e3286 = local_243;
                            let _e3288 = local_251;
                            let _e3291 = local_247;
                            let _e3293 = ((_e3291 + ((_e3286 + 1u) << bitcast<u32>(_e3288))) - 1u);
                            local_254 = _e3293;
                            if (_e3293 < 384u) {
                            } else {
                                phi_6308_ = true;
                                break;
                            }
                            let _e3295 = local_254;
                            let _e3297 = global_10[_e3295];
                            phi_2761_ = _e3297;
                        } else {
                            phi_2761_ = 0u;
                        }
                        let _e3299 = phi_2761_;
                        let _e3300 = subgroupInclusiveAdd(_e3299);
                        local_255 = _e3300;
                        let _e3301 = local_253;
                        if _e3301 {
                            let _e3302 = local_246;
                            let _e3303 = local_243;
                            let _e3304 = (_e3302 + _e3303);
                            local_256 = _e3304;
                            if (_e3304 < 384u) {
                            } else {
                                phi_6308_ = true;
                                break;
                            }
                            let _e3306 = local_256;
                            let _e3308 = local_255;
                            global_10[_e3306] = _e3308;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e3309 = local_246;
                        let _e3310 = local_252;
                        let _e3312 = local_249;
                        phi_2728_ = (_e3309 + _e3310);
                        phi_2732_ = _e3283;
                        phi_2734_ = (_e3312 + 1u);
                    } else {
                        phi_2728_ = u32();
                        phi_2732_ = u32();
                        phi_2734_ = u32();
                    }
                    let _e3315 = phi_2728_;
                    let _e3317 = phi_2732_;
                    let _e3319 = phi_2734_;
                    continue;
                    continuing {
                        let _e3320 = local_250;
                        phi_2727_ = _e3315;
                        phi_2730_ = _e3269;
                        phi_2731_ = _e3317;
                        phi_2733_ = _e3319;
                        phi_6308_ = _e3136;
                        break if !(_e3320);
                    }
                }
                let _e3323 = phi_6308_;
                if _e3323 {
                    break;
                }
                let _e6559 = local_654;
                phi_2783_ = _e6559;
                let _e6562 = local_655;
                phi_2786_ = _e6562;
                let _e6565 = local_656;
                phi_2788_ = _e6565;
                loop {
                    let _e3325 = phi_2783_;
                    let _e3327 = phi_2786_;
                    let _e3329 = phi_2788_;
                    local_257 = _e3325;
                    local_258 = _e3327;
                    local_259 = _e3329;
                    let _e3330 = local_259;
                    let _e3331 = (_e3330 > 0u);
                    local_260 = _e3331;
                    if _e3331 {
                        let _e3332 = local_242;
                        let _e3333 = (_e3332 & 31u);
                        local_261 = _e3333;
                        let _e3334 = local_258;
                        let _e3336 = (_e3334 << bitcast<u32>(_e3333));
                        local_262 = _e3336;
                        let _e3337 = local_259;
                        if (_e3337 == 1u) {
                            phi_2803_ = 64u;
                        } else {
                            let _e3339 = local_257;
                            let _e3340 = local_262;
                            phi_2803_ = (_e3339 - _e3340);
                        }
                        let _e3343 = phi_2803_;
                        local_263 = _e3343;
                        let _e3344 = local;
                        let _e3345 = local_241;
                        if (_e3344 >= _e3345) {
                            let _e3347 = local;
                            let _e3348 = local_262;
                            if (_e3347 < _e3348) {
                                let _e3350 = local_263;
                                let _e3351 = local;
                                local_264 = (_e3350 + _e3351);
                                let _e3353 = local;
                                let _e3354 = local_261;
                                let _e3357 = local_257;
                                let _e3359 = ((_e3357 + (_e3353 >> bitcast<u32>(_e3354))) - 1u);
                                local_265 = _e3359;
                                if (_e3359 < 384u) {
                                } else {
                                    phi_6313_ = true;
                                    break;
                                }
                                let _e3361 = local_265;
                                let _e3363 = global_10[_e3361];
                                local_266 = _e3363;
                                let _e3364 = local_264;
                                let _e3365 = (_e3364 < 384u);
                                local_267 = _e3365;
                                if _e3365 {
                                } else {
                                    phi_6313_ = true;
                                    break;
                                }
                                let _e3366 = local_264;
                                let _e3368 = global_10[_e3366];
                                let _e3369 = local_266;
                                local_268 = (_e3369 + _e3368);
                                let _e3371 = local_267;
                                if _e3371 {
                                } else {
                                    phi_6313_ = true;
                                    break;
                                }
                                let _e3372 = local_268;
                                global_10[_e3366] = _e3372;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e3373 = local_259;
                        phi_2784_ = _e3343;
                        phi_2787_ = _e3336;
                        phi_2789_ = (_e3373 - 1u);
                    } else {
                        phi_2784_ = u32();
                        phi_2787_ = u32();
                        phi_2789_ = u32();
                    }
                    let _e3376 = phi_2784_;
                    let _e3378 = phi_2787_;
                    let _e3380 = phi_2789_;
                    continue;
                    continuing {
                        let _e3381 = local_260;
                        phi_2783_ = _e3376;
                        phi_2786_ = _e3378;
                        phi_2788_ = _e3380;
                        phi_6313_ = _e3323;
                        break if !(_e3381);
                    }
                }
                let _e3384 = phi_6313_;
                if _e3384 {
                    break;
                }
                phi_6324_ = _e3384;
                phi_2894_ = 64u;
            } else {
                phi_2840_ = 1u;
                phi_2843_ = 0u;
                loop {
                    let _e3199 = phi_2840_;
                    let _e3201 = phi_2843_;
                    local_269 = _e3199;
                    local_270 = _e3201;
                    local_657 = _e3201;
                    let _e3202 = local_269;
                    let _e3203 = (_e3202 < 64u);
                    local_271 = _e3203;
                    if _e3203 {
                        let _e3204 = local_270;
                        let _e3206 = select(0u, 64u, (_e3204 == 0u));
                        local_611 = _e3206;
                        let _e3207 = local_270;
                        let _e3208 = local;
                        let _e3209 = (_e3207 + _e3208);
                        local_272 = _e3209;
                        if (_e3209 < 384u) {
                        } else {
                            phi_6288_ = true;
                            break;
                        }
                        let _e3211 = local_272;
                        let _e3213 = global_10[_e3211];
                        local_273 = _e3213;
                        let _e3214 = local;
                        let _e3215 = local_269;
                        if (_e3214 >= _e3215) {
                            let _e3217 = local;
                            let _e3218 = local_269;
                            let _e3220 = local_270;
                            let _e3221 = (_e3220 + (_e3217 - _e3218));
                            local_274 = _e3221;
                            if (_e3221 < 384u) {
                            } else {
                                phi_6288_ = true;
                                break;
                            }
                            let _e3223 = local_274;
                            let _e3225 = global_10[_e3223];
                            let _e3226 = local_273;
                            phi_2879_ = (_e3225 + _e3226);
                        } else {
                            phi_2879_ = _e3213;
                        }
                        let _e3229 = phi_2879_;
                        local_275 = _e3229;
                        let _e3230 = local_611;
                        let _e3231 = local;
                        let _e3232 = (_e3230 + _e3231);
                        local_276 = _e3232;
                        if (_e3232 < 384u) {
                        } else {
                            phi_6288_ = true;
                            break;
                        }
                        let _e3234 = local_276;
                        let _e3236 = local_275;
                        global_10[_e3234] = _e3236;
                        storageBarrier();
                        workgroupBarrier();
                        let _e3237 = local_269;
                        phi_2841_ = (_e3237 * 2u);
                        phi_2844_ = _e3206;
                    } else {
                        phi_2841_ = u32();
                        phi_2844_ = u32();
                    }
                    let _e3240 = phi_2841_;
                    let _e3242 = phi_2844_;
                    continue;
                    continuing {
                        let _e3243 = local_271;
                        phi_2840_ = _e3240;
                        phi_2843_ = _e3242;
                        phi_6288_ = _e3136;
                        break if !(_e3243);
                    }
                }
                let _e3246 = phi_6288_;
                if _e3246 {
                    break;
                }
                phi_6324_ = _e3246;
                let _e6574 = local_657;
                phi_2894_ = _e6574;
            }
            let _e3386 = phi_6324_;
            let _e3388 = phi_2894_;
            local_277 = _e3388;
            let _e3389 = local_239;
            if _e3389 {
                let _e3390 = local_1;
                let _e3392 = local_1;
                if ((_e3392 & (_e3390 - 1u)) == 0u) {
                    let _e3395 = local_2;
                    let _e3396 = local_1;
                    let _e3398 = ((_e3395 * _e3396) == 64u);
                    local_278 = _e3398;
                    if _e3398 {
                        let _e3399 = local_1;
                        phi_2911_ = type_34(1u, _e3399);
                    } else {
                        phi_2911_ = type_34();
                    }
                    let _e3402 = phi_2911_;
                    let _e3403 = local_278;
                    phi_2913_ = _e3402;
                    phi_2914_ = select(true, false, _e3403);
                } else {
                    phi_2913_ = type_34();
                    phi_2914_ = true;
                }
                let _e3406 = phi_2913_;
                let _e3408 = phi_2914_;
                phi_2915_ = _e3406;
                phi_2916_ = _e3408;
            } else {
                phi_2915_ = type_34();
                phi_2916_ = true;
            }
            let _e3410 = phi_2915_;
            let _e3412 = phi_2916_;
            if _e3412 {
                phi_2921_ = type_34(0u, type_34().member_1);
            } else {
                phi_2921_ = _e3410;
            }
            let _e3417 = phi_2921_;
            local_279 = _e3417.member_1;
            if (bitcast<i32>(_e3417.member) != 0i) {
                let _e3473 = local_279;
                let _e3475 = local_279;
                local_280 = select(firstTrailingBit(_e3473), 32u, (_e3475 == 0u));
                let _e3478 = local_3;
                let _e3479 = local_1;
                let _e3481 = local_4;
                let _e3482 = ((_e3478 * _e3479) + _e3481);
                local_281 = _e3482;
                let _e3483 = (128u + _e3482);
                local_282 = _e3483;
                if (_e3483 < 384u) {
                } else {
                    break;
                }
                let _e3485 = local_282;
                let _e3487 = global_10[_e3485];
                phi_2948_ = 1u;
                phi_2951_ = _e3487;
                loop {
                    let _e3489 = phi_2948_;
                    let _e3491 = phi_2951_;
                    local_283 = _e3489;
                    local_284 = _e3491;
                    let _e3492 = local_283;
                    let _e3493 = local_1;
                    let _e3494 = (_e3492 < _e3493);
                    local_285 = _e3494;
                    if _e3494 {
                        let _e3495 = local_284;
                        let _e3496 = local_283;
                        let _e3497 = subgroupShuffleUp(_e3495, _e3496);
                        local_286 = _e3497;
                        let _e3498 = local_4;
                        let _e3499 = local_283;
                        if (_e3498 >= _e3499) {
                            let _e3501 = local_286;
                            let _e3502 = local_284;
                            let _e3504 = local_286;
                            let _e3505 = local_284;
                            phi_2969_ = select(_e3505, _e3504, (_e3501 > _e3502));
                        } else {
                            phi_2969_ = _e3491;
                        }
                        let _e3508 = phi_2969_;
                        let _e3509 = local_283;
                        phi_2949_ = (_e3509 * 2u);
                        phi_2952_ = _e3508;
                    } else {
                        phi_2949_ = u32();
                        phi_2952_ = u32();
                    }
                    let _e3512 = phi_2949_;
                    let _e3514 = phi_2952_;
                    continue;
                    continuing {
                        let _e3515 = local_285;
                        phi_2948_ = _e3512;
                        phi_2951_ = _e3514;
                        break if !(_e3515);
                    }
                }
                let _e3517 = local_281;
                let _e3518 = (192u + _e3517);
                local_287 = _e3518;
                if (_e3518 < 384u) {
                } else {
                    break;
                }
                let _e3520 = local_287;
                let _e3522 = local_284;
                global_10[_e3520] = _e3522;
                storageBarrier();
                workgroupBarrier();
                phi_2981_ = 128u;
                phi_2984_ = 192u;
                phi_2985_ = 64u;
                phi_2987_ = 0u;
                loop {
                    let _e3524 = phi_2981_;
                    let _e3526 = phi_2984_;
                    let _e3528 = phi_2985_;
                    let _e3530 = phi_2987_;
                    local_288 = _e3524;
                    local_289 = _e3526;
                    local_290 = _e3528;
                    local_291 = _e3530;
                    local_658 = _e3526;
                    local_659 = _e3528;
                    local_660 = _e3530;
                    let _e3531 = local_290;
                    let _e3532 = local_279;
                    let _e3533 = (_e3531 > _e3532);
                    local_292 = _e3533;
                    if _e3533 {
                        let _e3534 = local_280;
                        let _e3535 = (_e3534 & 31u);
                        local_293 = _e3535;
                        let _e3536 = local_290;
                        let _e3538 = (_e3536 >> bitcast<u32>(_e3535));
                        local_294 = _e3538;
                        let _e3539 = local_281;
                        let _e3540 = (_e3539 < _e3538);
                        local_295 = _e3540;
                        if _e3540 {
                            let _e3541 = local_281;
                            let _e3543 = local_293;
                            let _e3546 = local_289;
                            let _e3548 = ((_e3546 + ((_e3541 + 1u) << bitcast<u32>(_e3543))) - 1u);
                            local_296 = _e3548;
                            if (_e3548 < 384u) {
                            } else {
                                phi_6331_ = true;
                                break;
                            }
                            let _e3550 = local_296;
                            let _e3552 = global_10[_e3550];
                            phi_3015_ = _e3552;
                        } else {
                            phi_3015_ = 0u;
                        }
                        let _e3554 = phi_3015_;
                        phi_3021_ = 1u;
                        phi_3024_ = _e3554;
                        loop {
                            let _e3556 = phi_3021_;
                            let _e3558 = phi_3024_;
                            local_297 = _e3556;
                            local_298 = _e3558;
                            let _e3559 = local_297;
                            let _e3560 = local_1;
                            let _e3561 = (_e3559 < _e3560);
                            local_299 = _e3561;
                            if _e3561 {
                                let _e3562 = local_298;
                                let _e3563 = local_297;
                                let _e3564 = subgroupShuffleUp(_e3562, _e3563);
                                local_300 = _e3564;
                                let _e3565 = local_4;
                                let _e3566 = local_297;
                                if (_e3565 >= _e3566) {
                                    let _e3568 = local_300;
                                    let _e3569 = local_298;
                                    let _e3571 = local_300;
                                    let _e3572 = local_298;
                                    phi_3042_ = select(_e3572, _e3571, (_e3568 > _e3569));
                                } else {
                                    phi_3042_ = _e3558;
                                }
                                let _e3575 = phi_3042_;
                                let _e3576 = local_297;
                                phi_3022_ = (_e3576 * 2u);
                                phi_3025_ = _e3575;
                            } else {
                                phi_3022_ = u32();
                                phi_3025_ = u32();
                            }
                            let _e3579 = phi_3022_;
                            let _e3581 = phi_3025_;
                            continue;
                            continuing {
                                let _e3582 = local_299;
                                phi_3021_ = _e3579;
                                phi_3024_ = _e3581;
                                break if !(_e3582);
                            }
                        }
                        let _e3584 = local_295;
                        if _e3584 {
                            let _e3585 = local_288;
                            let _e3586 = local_281;
                            let _e3587 = (_e3585 + _e3586);
                            local_301 = _e3587;
                            if (_e3587 < 384u) {
                            } else {
                                phi_6331_ = true;
                                break;
                            }
                            let _e3589 = local_301;
                            let _e3591 = local_298;
                            global_10[_e3589] = _e3591;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e3592 = local_288;
                        let _e3593 = local_294;
                        let _e3595 = local_291;
                        phi_2982_ = (_e3592 + _e3593);
                        phi_2986_ = _e3538;
                        phi_2988_ = (_e3595 + 1u);
                    } else {
                        phi_2982_ = u32();
                        phi_2986_ = u32();
                        phi_2988_ = u32();
                    }
                    let _e3598 = phi_2982_;
                    let _e3600 = phi_2986_;
                    let _e3602 = phi_2988_;
                    continue;
                    continuing {
                        let _e3603 = local_292;
                        phi_2981_ = _e3598;
                        phi_2984_ = _e3524;
                        phi_2985_ = _e3600;
                        phi_2987_ = _e3602;
                        phi_6331_ = _e3386;
                        break if !(_e3603);
                    }
                }
                let _e3606 = phi_6331_;
                if _e3606 {
                    break;
                }
                let _e6608 = local_658;
                phi_3060_ = _e6608;
                let _e6611 = local_659;
                phi_3063_ = _e6611;
                let _e6614 = local_660;
                phi_3065_ = _e6614;
                loop {
                    let _e3608 = phi_3060_;
                    let _e3610 = phi_3063_;
                    let _e3612 = phi_3065_;
                    local_302 = _e3608;
                    local_303 = _e3610;
                    local_304 = _e3612;
                    let _e3613 = local_304;
                    let _e3614 = (_e3613 > 0u);
                    local_305 = _e3614;
                    if _e3614 {
                        let _e3615 = local_280;
                        let _e3616 = (_e3615 & 31u);
                        local_306 = _e3616;
                        let _e3617 = local_303;
                        let _e3619 = (_e3617 << bitcast<u32>(_e3616));
                        local_307 = _e3619;
                        let _e3620 = local_304;
                        if (_e3620 == 1u) {
                            phi_3080_ = 192u;
                        } else {
                            let _e3622 = local_302;
                            let _e3623 = local_307;
                            phi_3080_ = (_e3622 - _e3623);
                        }
                        let _e3626 = phi_3080_;
                        local_308 = _e3626;
                        let _e3627 = local;
                        let _e3628 = local_279;
                        if (_e3627 >= _e3628) {
                            let _e3630 = local;
                            let _e3631 = local_307;
                            if (_e3630 < _e3631) {
                                let _e3633 = local_308;
                                let _e3634 = local;
                                local_309 = (_e3633 + _e3634);
                                let _e3636 = local;
                                let _e3637 = local_306;
                                let _e3640 = local_302;
                                let _e3642 = ((_e3640 + (_e3636 >> bitcast<u32>(_e3637))) - 1u);
                                local_310 = _e3642;
                                if (_e3642 < 384u) {
                                } else {
                                    phi_6344_ = true;
                                    break;
                                }
                                let _e3644 = local_310;
                                let _e3646 = global_10[_e3644];
                                local_311 = _e3646;
                                let _e3647 = local_309;
                                let _e3648 = (_e3647 < 384u);
                                local_312 = _e3648;
                                if _e3648 {
                                } else {
                                    phi_6344_ = true;
                                    break;
                                }
                                let _e3649 = local_309;
                                let _e3651 = global_10[_e3649];
                                let _e3652 = local_311;
                                let _e3654 = local_311;
                                local_613 = select(_e3651, _e3654, (_e3652 > _e3651));
                                let _e3656 = local_312;
                                if _e3656 {
                                } else {
                                    phi_6344_ = true;
                                    break;
                                }
                                let _e3657 = local_613;
                                global_10[_e3649] = _e3657;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e3658 = local_304;
                        phi_3061_ = _e3626;
                        phi_3064_ = _e3619;
                        phi_3066_ = (_e3658 - 1u);
                    } else {
                        phi_3061_ = u32();
                        phi_3064_ = u32();
                        phi_3066_ = u32();
                    }
                    let _e3661 = phi_3061_;
                    let _e3663 = phi_3064_;
                    let _e3665 = phi_3066_;
                    continue;
                    continuing {
                        let _e3666 = local_305;
                        phi_3060_ = _e3661;
                        phi_3063_ = _e3663;
                        phi_3065_ = _e3665;
                        phi_6344_ = _e3606;
                        break if !(_e3666);
                    }
                }
                let _e3669 = phi_6344_;
                if _e3669 {
                    break;
                }
                phi_6356_ = _e3669;
                phi_3179_ = 192u;
            } else {
                phi_3121_ = 1u;
                phi_3124_ = 128u;
                loop {
                    let _e3423 = phi_3121_;
                    let _e3425 = phi_3124_;
                    local_313 = _e3423;
                    local_314 = _e3425;
                    local_661 = _e3425;
                    let _e3426 = local_313;
                    let _e3427 = (_e3426 < 64u);
                    local_315 = _e3427;
                    if _e3427 {
                        let _e3428 = local_314;
                        let _e3430 = select(128u, 192u, (_e3428 == 128u));
                        local_612 = _e3430;
                        let _e3431 = local_314;
                        let _e3432 = local;
                        let _e3433 = (_e3431 + _e3432);
                        local_316 = _e3433;
                        if (_e3433 < 384u) {
                        } else {
                            phi_6319_ = true;
                            break;
                        }
                        let _e3435 = local_316;
                        let _e3437 = global_10[_e3435];
                        local_317 = _e3437;
                        let _e3438 = local;
                        let _e3439 = local_313;
                        if (_e3438 >= _e3439) {
                            let _e3441 = local;
                            let _e3442 = local_313;
                            let _e3444 = local_314;
                            let _e3445 = (_e3444 + (_e3441 - _e3442));
                            local_318 = _e3445;
                            if (_e3445 < 384u) {
                            } else {
                                phi_6319_ = true;
                                break;
                            }
                            let _e3447 = local_318;
                            let _e3449 = global_10[_e3447];
                            let _e3450 = local_317;
                            let _e3452 = local_317;
                            phi_3164_ = select(_e3452, _e3449, (_e3449 > _e3450));
                        } else {
                            phi_3164_ = _e3437;
                        }
                        let _e3455 = phi_3164_;
                        local_319 = _e3455;
                        let _e3456 = local_612;
                        let _e3457 = local;
                        let _e3458 = (_e3456 + _e3457);
                        local_320 = _e3458;
                        if (_e3458 < 384u) {
                        } else {
                            phi_6319_ = true;
                            break;
                        }
                        let _e3460 = local_320;
                        let _e3462 = local_319;
                        global_10[_e3460] = _e3462;
                        storageBarrier();
                        workgroupBarrier();
                        let _e3463 = local_313;
                        phi_3122_ = (_e3463 * 2u);
                        phi_3125_ = _e3430;
                    } else {
                        phi_3122_ = u32();
                        phi_3125_ = u32();
                    }
                    let _e3466 = phi_3122_;
                    let _e3468 = phi_3125_;
                    continue;
                    continuing {
                        let _e3469 = local_315;
                        phi_3121_ = _e3466;
                        phi_3124_ = _e3468;
                        phi_6319_ = _e3386;
                        break if !(_e3469);
                    }
                }
                let _e3472 = phi_6319_;
                if _e3472 {
                    break;
                }
                phi_6356_ = _e3472;
                let _e6623 = local_661;
                phi_3179_ = _e6623;
            }
            let _e3671 = phi_6356_;
            let _e3673 = phi_3179_;
            local_321 = _e3673;
            let _e3674 = local_239;
            if _e3674 {
                let _e3675 = local_1;
                let _e3677 = local_1;
                if ((_e3677 & (_e3675 - 1u)) == 0u) {
                    let _e3680 = local_2;
                    let _e3681 = local_1;
                    let _e3683 = ((_e3680 * _e3681) == 64u);
                    local_322 = _e3683;
                    if _e3683 {
                        let _e3684 = local_1;
                        phi_3196_ = type_34(1u, _e3684);
                    } else {
                        phi_3196_ = type_34();
                    }
                    let _e3687 = phi_3196_;
                    let _e3688 = local_322;
                    phi_3198_ = _e3687;
                    phi_3199_ = select(true, false, _e3688);
                } else {
                    phi_3198_ = type_34();
                    phi_3199_ = true;
                }
                let _e3691 = phi_3198_;
                let _e3693 = phi_3199_;
                phi_3200_ = _e3691;
                phi_3201_ = _e3693;
            } else {
                phi_3200_ = type_34();
                phi_3201_ = true;
            }
            let _e3695 = phi_3200_;
            let _e3697 = phi_3201_;
            if _e3697 {
                phi_3206_ = type_34(0u, type_34().member_1);
            } else {
                phi_3206_ = _e3695;
            }
            let _e3702 = phi_3206_;
            local_323 = _e3702.member_1;
            if (bitcast<i32>(_e3702.member) != 0i) {
                let _e3758 = local_323;
                let _e3760 = local_323;
                local_324 = select(firstTrailingBit(_e3758), 32u, (_e3760 == 0u));
                let _e3763 = local_3;
                let _e3764 = local_1;
                let _e3766 = local_4;
                let _e3767 = ((_e3763 * _e3764) + _e3766);
                local_325 = _e3767;
                let _e3768 = (256u + _e3767);
                local_326 = _e3768;
                if (_e3768 < 384u) {
                } else {
                    break;
                }
                let _e3770 = local_326;
                let _e3772 = global_10[_e3770];
                phi_3233_ = 1u;
                phi_3236_ = _e3772;
                loop {
                    let _e3774 = phi_3233_;
                    let _e3776 = phi_3236_;
                    local_327 = _e3774;
                    local_328 = _e3776;
                    let _e3777 = local_327;
                    let _e3778 = local_1;
                    let _e3779 = (_e3777 < _e3778);
                    local_329 = _e3779;
                    if _e3779 {
                        let _e3780 = local_328;
                        let _e3781 = local_327;
                        let _e3782 = subgroupShuffleUp(_e3780, _e3781);
                        local_330 = _e3782;
                        let _e3783 = local_4;
                        let _e3784 = local_327;
                        if (_e3783 >= _e3784) {
                            let _e3786 = local_330;
                            let _e3787 = local_328;
                            let _e3789 = local_330;
                            let _e3790 = local_328;
                            phi_3254_ = select(_e3790, _e3789, (_e3786 > _e3787));
                        } else {
                            phi_3254_ = _e3776;
                        }
                        let _e3793 = phi_3254_;
                        let _e3794 = local_327;
                        phi_3234_ = (_e3794 * 2u);
                        phi_3237_ = _e3793;
                    } else {
                        phi_3234_ = u32();
                        phi_3237_ = u32();
                    }
                    let _e3797 = phi_3234_;
                    let _e3799 = phi_3237_;
                    continue;
                    continuing {
                        let _e3800 = local_329;
                        phi_3233_ = _e3797;
                        phi_3236_ = _e3799;
                        break if !(_e3800);
                    }
                }
                let _e3802 = local_325;
                let _e3803 = (320u + _e3802);
                local_331 = _e3803;
                if (_e3803 < 384u) {
                } else {
                    break;
                }
                let _e3805 = local_331;
                let _e3807 = local_328;
                global_10[_e3805] = _e3807;
                storageBarrier();
                workgroupBarrier();
                phi_3266_ = 256u;
                phi_3269_ = 320u;
                phi_3270_ = 64u;
                phi_3272_ = 0u;
                loop {
                    let _e3809 = phi_3266_;
                    let _e3811 = phi_3269_;
                    let _e3813 = phi_3270_;
                    let _e3815 = phi_3272_;
                    local_332 = _e3809;
                    local_333 = _e3811;
                    local_334 = _e3813;
                    local_335 = _e3815;
                    local_662 = _e3811;
                    local_663 = _e3813;
                    local_664 = _e3815;
                    let _e3816 = local_334;
                    let _e3817 = local_323;
                    let _e3818 = (_e3816 > _e3817);
                    local_336 = _e3818;
                    if _e3818 {
                        let _e3819 = local_324;
                        let _e3820 = (_e3819 & 31u);
                        local_337 = _e3820;
                        let _e3821 = local_334;
                        let _e3823 = (_e3821 >> bitcast<u32>(_e3820));
                        local_338 = _e3823;
                        let _e3824 = local_325;
                        let _e3825 = (_e3824 < _e3823);
                        local_339 = _e3825;
                        if _e3825 {
                            let _e3826 = local_325;
                            let _e3828 = local_337;
                            let _e3831 = local_333;
                            let _e3833 = ((_e3831 + ((_e3826 + 1u) << bitcast<u32>(_e3828))) - 1u);
                            local_340 = _e3833;
                            if (_e3833 < 384u) {
                            } else {
                                phi_6363_ = true;
                                break;
                            }
                            let _e3835 = local_340;
                            let _e3837 = global_10[_e3835];
                            phi_3300_ = _e3837;
                        } else {
                            phi_3300_ = 0u;
                        }
                        let _e3839 = phi_3300_;
                        phi_3306_ = 1u;
                        phi_3309_ = _e3839;
                        loop {
                            let _e3841 = phi_3306_;
                            let _e3843 = phi_3309_;
                            local_341 = _e3841;
                            local_342 = _e3843;
                            let _e3844 = local_341;
                            let _e3845 = local_1;
                            let _e3846 = (_e3844 < _e3845);
                            local_343 = _e3846;
                            if _e3846 {
                                let _e3847 = local_342;
                                let _e3848 = local_341;
                                let _e3849 = subgroupShuffleUp(_e3847, _e3848);
                                local_344 = _e3849;
                                let _e3850 = local_4;
                                let _e3851 = local_341;
                                if (_e3850 >= _e3851) {
                                    let _e3853 = local_344;
                                    let _e3854 = local_342;
                                    let _e3856 = local_344;
                                    let _e3857 = local_342;
                                    phi_3327_ = select(_e3857, _e3856, (_e3853 > _e3854));
                                } else {
                                    phi_3327_ = _e3843;
                                }
                                let _e3860 = phi_3327_;
                                let _e3861 = local_341;
                                phi_3307_ = (_e3861 * 2u);
                                phi_3310_ = _e3860;
                            } else {
                                phi_3307_ = u32();
                                phi_3310_ = u32();
                            }
                            let _e3864 = phi_3307_;
                            let _e3866 = phi_3310_;
                            continue;
                            continuing {
                                let _e3867 = local_343;
                                phi_3306_ = _e3864;
                                phi_3309_ = _e3866;
                                break if !(_e3867);
                            }
                        }
                        let _e3869 = local_339;
                        if _e3869 {
                            let _e3870 = local_332;
                            let _e3871 = local_325;
                            let _e3872 = (_e3870 + _e3871);
                            local_345 = _e3872;
                            if (_e3872 < 384u) {
                            } else {
                                phi_6363_ = true;
                                break;
                            }
                            let _e3874 = local_345;
                            let _e3876 = local_342;
                            global_10[_e3874] = _e3876;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e3877 = local_332;
                        let _e3878 = local_338;
                        let _e3880 = local_335;
                        phi_3267_ = (_e3877 + _e3878);
                        phi_3271_ = _e3823;
                        phi_3273_ = (_e3880 + 1u);
                    } else {
                        phi_3267_ = u32();
                        phi_3271_ = u32();
                        phi_3273_ = u32();
                    }
                    let _e3883 = phi_3267_;
                    let _e3885 = phi_3271_;
                    let _e3887 = phi_3273_;
                    continue;
                    continuing {
                        let _e3888 = local_336;
                        phi_3266_ = _e3883;
                        phi_3269_ = _e3809;
                        phi_3270_ = _e3885;
                        phi_3272_ = _e3887;
                        phi_6363_ = _e3671;
                        break if !(_e3888);
                    }
                }
                let _e3891 = phi_6363_;
                if _e3891 {
                    break;
                }
                let _e6657 = local_662;
                phi_3345_ = _e6657;
                let _e6660 = local_663;
                phi_3348_ = _e6660;
                let _e6663 = local_664;
                phi_3350_ = _e6663;
                loop {
                    let _e3893 = phi_3345_;
                    let _e3895 = phi_3348_;
                    let _e3897 = phi_3350_;
                    local_346 = _e3893;
                    local_347 = _e3895;
                    local_348 = _e3897;
                    let _e3898 = local_348;
                    let _e3899 = (_e3898 > 0u);
                    local_349 = _e3899;
                    if _e3899 {
                        let _e3900 = local_324;
                        let _e3901 = (_e3900 & 31u);
                        local_350 = _e3901;
                        let _e3902 = local_347;
                        let _e3904 = (_e3902 << bitcast<u32>(_e3901));
                        local_351 = _e3904;
                        let _e3905 = local_348;
                        if (_e3905 == 1u) {
                            phi_3365_ = 320u;
                        } else {
                            let _e3907 = local_346;
                            let _e3908 = local_351;
                            phi_3365_ = (_e3907 - _e3908);
                        }
                        let _e3911 = phi_3365_;
                        local_352 = _e3911;
                        let _e3912 = local;
                        let _e3913 = local_323;
                        if (_e3912 >= _e3913) {
                            let _e3915 = local;
                            let _e3916 = local_351;
                            if (_e3915 < _e3916) {
                                let _e3918 = local_352;
                                let _e3919 = local;
                                local_353 = (_e3918 + _e3919);
                                let _e3921 = local;
                                let _e3922 = local_350;
                                let _e3925 = local_346;
                                let _e3927 = ((_e3925 + (_e3921 >> bitcast<u32>(_e3922))) - 1u);
                                local_354 = _e3927;
                                if (_e3927 < 384u) {
                                } else {
                                    phi_6376_ = true;
                                    break;
                                }
                                let _e3929 = local_354;
                                let _e3931 = global_10[_e3929];
                                local_355 = _e3931;
                                let _e3932 = local_353;
                                let _e3933 = (_e3932 < 384u);
                                local_356 = _e3933;
                                if _e3933 {
                                } else {
                                    phi_6376_ = true;
                                    break;
                                }
                                let _e3934 = local_353;
                                let _e3936 = global_10[_e3934];
                                let _e3937 = local_355;
                                let _e3939 = local_355;
                                local_615 = select(_e3936, _e3939, (_e3937 > _e3936));
                                let _e3941 = local_356;
                                if _e3941 {
                                } else {
                                    phi_6376_ = true;
                                    break;
                                }
                                let _e3942 = local_615;
                                global_10[_e3934] = _e3942;
                            }
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e3943 = local_348;
                        phi_3346_ = _e3911;
                        phi_3349_ = _e3904;
                        phi_3351_ = (_e3943 - 1u);
                    } else {
                        phi_3346_ = u32();
                        phi_3349_ = u32();
                        phi_3351_ = u32();
                    }
                    let _e3946 = phi_3346_;
                    let _e3948 = phi_3349_;
                    let _e3950 = phi_3351_;
                    continue;
                    continuing {
                        let _e3951 = local_349;
                        phi_3345_ = _e3946;
                        phi_3348_ = _e3948;
                        phi_3350_ = _e3950;
                        phi_6376_ = _e3891;
                        break if !(_e3951);
                    }
                }
                let _e3954 = phi_6376_;
                if _e3954 {
                    break;
                }
                phi_6391_ = _e3954;
                phi_3464_ = 320u;
            } else {
                phi_3406_ = 1u;
                phi_3409_ = 256u;
                loop {
                    let _e3708 = phi_3406_;
                    let _e3710 = phi_3409_;
                    local_357 = _e3708;
                    local_358 = _e3710;
                    local_665 = _e3710;
                    let _e3711 = local_357;
                    let _e3712 = (_e3711 < 64u);
                    local_359 = _e3712;
                    if _e3712 {
                        let _e3713 = local_358;
                        let _e3715 = select(256u, 320u, (_e3713 == 256u));
                        local_614 = _e3715;
                        let _e3716 = local_358;
                        let _e3717 = local;
                        let _e3718 = (_e3716 + _e3717);
                        local_360 = _e3718;
                        if (_e3718 < 384u) {
                        } else {
                            phi_6351_ = true;
                            break;
                        }
                        let _e3720 = local_360;
                        let _e3722 = global_10[_e3720];
                        local_361 = _e3722;
                        let _e3723 = local;
                        let _e3724 = local_357;
                        if (_e3723 >= _e3724) {
                            let _e3726 = local;
                            let _e3727 = local_357;
                            let _e3729 = local_358;
                            let _e3730 = (_e3729 + (_e3726 - _e3727));
                            local_362 = _e3730;
                            if (_e3730 < 384u) {
                            } else {
                                phi_6351_ = true;
                                break;
                            }
                            let _e3732 = local_362;
                            let _e3734 = global_10[_e3732];
                            let _e3735 = local_361;
                            let _e3737 = local_361;
                            phi_3449_ = select(_e3737, _e3734, (_e3734 > _e3735));
                        } else {
                            phi_3449_ = _e3722;
                        }
                        let _e3740 = phi_3449_;
                        local_363 = _e3740;
                        let _e3741 = local_614;
                        let _e3742 = local;
                        let _e3743 = (_e3741 + _e3742);
                        local_364 = _e3743;
                        if (_e3743 < 384u) {
                        } else {
                            phi_6351_ = true;
                            break;
                        }
                        let _e3745 = local_364;
                        let _e3747 = local_363;
                        global_10[_e3745] = _e3747;
                        storageBarrier();
                        workgroupBarrier();
                        let _e3748 = local_357;
                        phi_3407_ = (_e3748 * 2u);
                        phi_3410_ = _e3715;
                    } else {
                        phi_3407_ = u32();
                        phi_3410_ = u32();
                    }
                    let _e3751 = phi_3407_;
                    let _e3753 = phi_3410_;
                    continue;
                    continuing {
                        let _e3754 = local_359;
                        phi_3406_ = _e3751;
                        phi_3409_ = _e3753;
                        phi_6351_ = _e3671;
                        break if !(_e3754);
                    }
                }
                let _e3757 = phi_6351_;
                if _e3757 {
                    break;
                }
                phi_6391_ = _e3757;
                let _e6672 = local_665;
                phi_3464_ = _e6672;
            }
            let _e3956 = phi_6391_;
            let _e3958 = phi_3464_;
            local_365 = _e3958;
            let _e3959 = local_16;
            if _e3959 {
                let _e3960 = local_15;
                phi_3482_ = (_e3960 + 1u);
            } else {
                phi_3482_ = _e756;
            }
            let _e3963 = phi_3482_;
            let _e3964 = (_e3963 / 8u);
            local_366 = _e3964;
            if ((_e3963 % 8u) > 0u) {
                let _e3967 = local_366;
                phi_3498_ = (_e3967 + 1u);
            } else {
                phi_3498_ = _e3964;
            }
            let _e3970 = phi_3498_;
            let _e3971 = local_13;
            let _e3973 = local_12;
            local_367 = (66u * ((_e3971 * _e3970) + _e3973));
            let _e3976 = local_277;
            let _e3977 = local;
            let _e3978 = (_e3976 + _e3977);
            local_368 = _e3978;
            if (_e3978 < 384u) {
            } else {
                break;
            }
            let _e3980 = local_368;
            let _e3982 = global_10[_e3980];
            local_369 = _e3982;
            let _e3983 = local;
            if (_e3983 == 0u) {
                phi_3524_ = _e3982;
            } else {
                let _e3985 = local_368;
                let _e3986 = (_e3985 - 1u);
                local_370 = _e3986;
                if (_e3986 < 384u) {
                } else {
                    break;
                }
                let _e3988 = local_370;
                let _e3990 = global_10[_e3988];
                let _e3991 = local_369;
                phi_3524_ = (_e3991 - _e3990);
            }
            let _e3994 = phi_3524_;
            if (_e3994 == 1u) {
                let _e3996 = local_369;
                if (_e3996 <= 8u) {
                    phi_6387_ = _e3956;
                    phi_3540_ = 0u;
                    phi_3543_ = 0u;
                    phi_3545_ = array<f32, 3>(0f, 0f, 0f);
                    phi_3547_ = 340282350000000000000000000000000000000f;
                    loop {
                        let _e3999 = phi_6387_;
                        let _e4001 = phi_3540_;
                        let _e4003 = phi_3543_;
                        let _e4005 = phi_3545_;
                        let _e4007 = phi_3547_;
                        local_371 = _e4001;
                        local_372 = _e4003;
                        local_373 = _e4005;
                        local_374 = _e4007;
                        let _e4008 = local_371;
                        let _e4009 = (_e4008 < 2u);
                        local_375 = _e4009;
                        if _e4009 {
                            let _e4010 = local_374;
                            let _e4012 = local_374;
                            local_376 = (4f * select(0.25f, _e4012, (_e4010 > 0.25f)));
                            phi_3562_ = 0u;
                            phi_3565_ = _e4003;
                            phi_3567_ = _e4005;
                            phi_3569_ = _e4007;
                            loop {
                                let _e4016 = phi_3562_;
                                let _e4018 = phi_3565_;
                                let _e4020 = phi_3567_;
                                let _e4022 = phi_3569_;
                                local_377 = _e4016;
                                local_378 = _e4018;
                                local_379 = _e4020;
                                local_380 = _e4022;
                                local_666 = _e4018;
                                local_667 = _e4020;
                                local_668 = _e4022;
                                let _e4023 = local_377;
                                let _e4024 = (_e4023 < 16u);
                                local_381 = _e4024;
                                if _e4024 {
                                    let _e4025 = local_377;
                                    let _e4026 = (_e4025 % 4u);
                                    local_382 = _e4026;
                                    let _e4027 = local_377;
                                    local_383 = (_e4027 / 4u);
                                    if (_e4026 == 1u) {
                                        phi_3599_ = i32();
                                        phi_3600_ = i32();
                                        phi_3601_ = true;
                                    } else {
                                        let _e4030 = local_382;
                                        let _e4031 = (_e4030 == 2u);
                                        if _e4031 {
                                            phi_3597_ = i32();
                                            phi_3598_ = i32();
                                        } else {
                                            let _e4032 = local_21;
                                            let _e4036 = local_382;
                                            let _e4039 = local_22;
                                            let _e4043 = local_383;
                                            phi_3597_ = (((2i * bitcast<i32>(_e4039)) - 1i) + bitcast<i32>(_e4043));
                                            phi_3598_ = (((2i * bitcast<i32>(_e4032)) - 1i) + bitcast<i32>(_e4036));
                                        }
                                        let _e4047 = phi_3597_;
                                        let _e4049 = phi_3598_;
                                        phi_3599_ = _e4047;
                                        phi_3600_ = _e4049;
                                        phi_3601_ = _e4031;
                                    }
                                    let _e4051 = phi_3599_;
                                    let _e4053 = phi_3600_;
                                    let _e4055 = phi_3601_;
                                    if _e4055 {
                                        let _e4056 = local_383;
                                        if (_e4056 == 1u) {
                                            phi_3624_ = i32();
                                            phi_3625_ = i32();
                                            phi_3626_ = false;
                                        } else {
                                            let _e4058 = local_383;
                                            let _e4060 = local_21;
                                            let _e4064 = local_382;
                                            let _e4067 = local_22;
                                            let _e4071 = local_383;
                                            phi_3624_ = (((2i * bitcast<i32>(_e4067)) - 1i) + bitcast<i32>(_e4071));
                                            phi_3625_ = (((2i * bitcast<i32>(_e4060)) - 1i) + bitcast<i32>(_e4064));
                                            phi_3626_ = select(true, false, (_e4058 == 2u));
                                        }
                                        let _e4076 = phi_3624_;
                                        let _e4078 = phi_3625_;
                                        let _e4080 = phi_3626_;
                                        phi_3627_ = _e4076;
                                        phi_3628_ = _e4078;
                                        phi_3629_ = _e4080;
                                    } else {
                                        phi_3627_ = _e4051;
                                        phi_3628_ = _e4053;
                                        phi_3629_ = true;
                                    }
                                    let _e4082 = phi_3627_;
                                    let _e4084 = phi_3628_;
                                    let _e4086 = phi_3629_;
                                    local_384 = _e4082;
                                    local_385 = _e4084;
                                    if _e4086 {
                                        let _e4087 = local_385;
                                        if (_e4087 >= 0i) {
                                            let _e4089 = local_384;
                                            if (_e4089 >= 0i) {
                                                let _e4091 = local_385;
                                                let _e4092 = bitcast<u32>(_e4091);
                                                local_386 = _e4092;
                                                let _e4093 = local_14;
                                                if (_e4092 < _e4093) {
                                                    let _e4095 = local_384;
                                                    let _e4096 = bitcast<u32>(_e4095);
                                                    local_387 = _e4096;
                                                    let _e4097 = local_18;
                                                    if (_e4096 < _e4097) {
                                                        let _e4099 = local_387;
                                                        let _e4100 = local_14;
                                                        let _e4102 = local_386;
                                                        let _e4103 = ((_e4099 * _e4100) + _e4102);
                                                        local_388 = _e4103;
                                                        let _e4104 = (3u * _e4103);
                                                        local_389 = _e4104;
                                                        let _e4105 = local_5;
                                                        if (_e4104 < _e4105) {
                                                        } else {
                                                            phi_6383_ = true;
                                                            break;
                                                        }
                                                        let _e4107 = local_389;
                                                        let _e4110 = global_4.member[_e4107];
                                                        local_390 = bitcast<f32>(_e4110);
                                                        let _e4112 = local_389;
                                                        let _e4113 = (_e4112 + 1u);
                                                        local_391 = _e4113;
                                                        let _e4114 = local_5;
                                                        if (_e4113 < _e4114) {
                                                        } else {
                                                            phi_6383_ = true;
                                                            break;
                                                        }
                                                        let _e4116 = local_391;
                                                        let _e4119 = global_4.member[_e4116];
                                                        local_392 = bitcast<f32>(_e4119);
                                                        let _e4121 = local_389;
                                                        let _e4122 = (_e4121 + 2u);
                                                        local_393 = _e4122;
                                                        let _e4123 = local_5;
                                                        if (_e4122 < _e4123) {
                                                        } else {
                                                            phi_6383_ = true;
                                                            break;
                                                        }
                                                        let _e4125 = local_393;
                                                        let _e4128 = global_4.member[_e4125];
                                                        local_394 = bitcast<f32>(_e4128);
                                                        let _e4130 = local_390;
                                                        if (_e4130 > 1267650600000000000000000000000f) {
                                                            let _e4132 = local_390;
                                                            phi_3699_ = select(true, false, (_e4132 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_3699_ = true;
                                                        }
                                                        let _e4136 = phi_3699_;
                                                        if _e4136 {
                                                            let _e4137 = local_390;
                                                            if (_e4137 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e4139 = local_390;
                                                                phi_3713_ = select(true, false, (_e4139 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_3713_ = true;
                                                            }
                                                            let _e4143 = phi_3713_;
                                                            let _e4144 = local_390;
                                                            phi_3718_ = select(0f, _e4144, _e4143);
                                                        } else {
                                                            phi_3718_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e4147 = phi_3718_;
                                                        local_395 = _e4147;
                                                        let _e4148 = local_392;
                                                        if (_e4148 > 1267650600000000000000000000000f) {
                                                            let _e4150 = local_392;
                                                            phi_3728_ = select(true, false, (_e4150 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_3728_ = true;
                                                        }
                                                        let _e4154 = phi_3728_;
                                                        if _e4154 {
                                                            let _e4155 = local_392;
                                                            if (_e4155 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e4157 = local_392;
                                                                phi_3742_ = select(true, false, (_e4157 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_3742_ = true;
                                                            }
                                                            let _e4161 = phi_3742_;
                                                            let _e4162 = local_392;
                                                            phi_3747_ = select(0f, _e4162, _e4161);
                                                        } else {
                                                            phi_3747_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e4165 = phi_3747_;
                                                        local_396 = _e4165;
                                                        let _e4166 = local_394;
                                                        if (_e4166 > 1267650600000000000000000000000f) {
                                                            let _e4168 = local_394;
                                                            phi_3757_ = select(true, false, (_e4168 <= 340282350000000000000000000000000000000f));
                                                        } else {
                                                            phi_3757_ = true;
                                                        }
                                                        let _e4172 = phi_3757_;
                                                        if _e4172 {
                                                            let _e4173 = local_394;
                                                            if (_e4173 < 0.000000000000000000000000000000000000011754944f) {
                                                                let _e4175 = local_394;
                                                                phi_3771_ = select(true, false, (_e4175 >= -340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_3771_ = true;
                                                            }
                                                            let _e4179 = phi_3771_;
                                                            let _e4180 = local_394;
                                                            phi_3776_ = select(0f, _e4180, _e4179);
                                                        } else {
                                                            phi_3776_ = 1267650600000000000000000000000f;
                                                        }
                                                        let _e4183 = phi_3776_;
                                                        local_397 = _e4183;
                                                        let _e4184 = local_395;
                                                        let _e4185 = local_396;
                                                        local_398 = array<f32, 3>(_e4184, _e4185, _e4183);
                                                        let _e4187 = local_388;
                                                        let _e4188 = local_6;
                                                        if (_e4187 < _e4188) {
                                                        } else {
                                                            phi_6383_ = true;
                                                            break;
                                                        }
                                                        let _e4190 = local_388;
                                                        let _e4193 = global_3.member[_e4190];
                                                        local_399 = bitcast<f32>(_e4193);
                                                        let _e4195 = local_395;
                                                        if ((bitcast<u32>(_e4195) & 2139095040u) != 2139095040u) {
                                                            let _e4199 = local_396;
                                                            if ((bitcast<u32>(_e4199) & 2139095040u) != 2139095040u) {
                                                                let _e4203 = local_397;
                                                                if ((bitcast<u32>(_e4203) & 2139095040u) != 2139095040u) {
                                                                    let _e4207 = local_399;
                                                                    let _e4208 = bitcast<u32>(_e4207);
                                                                    local_400 = _e4208;
                                                                    if (_e4208 == 0u) {
                                                                        phi_3810_ = false;
                                                                    } else {
                                                                        let _e4210 = local_400;
                                                                        phi_3810_ = (_e4210 <= 2139095040u);
                                                                    }
                                                                    let _e4213 = phi_3810_;
                                                                    local_401 = _e4213;
                                                                    if _e4213 {
                                                                        let _e4214 = local_398;
                                                                        let _e4215 = local_399;
                                                                        phi_3816_ = type_23(1u, type_22(_e4214, _e4215));
                                                                    } else {
                                                                        phi_3816_ = type_23();
                                                                    }
                                                                    let _e4219 = phi_3816_;
                                                                    let _e4220 = local_401;
                                                                    phi_3818_ = _e4219;
                                                                    phi_3819_ = select(true, false, _e4220);
                                                                } else {
                                                                    phi_3818_ = type_23();
                                                                    phi_3819_ = true;
                                                                }
                                                                let _e4223 = phi_3818_;
                                                                let _e4225 = phi_3819_;
                                                                phi_3820_ = _e4223;
                                                                phi_3821_ = _e4225;
                                                            } else {
                                                                phi_3820_ = type_23();
                                                                phi_3821_ = true;
                                                            }
                                                            let _e4227 = phi_3820_;
                                                            let _e4229 = phi_3821_;
                                                            phi_3822_ = _e4227;
                                                            phi_3823_ = _e4229;
                                                        } else {
                                                            phi_3822_ = type_23();
                                                            phi_3823_ = true;
                                                        }
                                                        let _e4231 = phi_3822_;
                                                        let _e4233 = phi_3823_;
                                                        if _e4233 {
                                                            phi_3828_ = type_23(0u, type_23().member_1);
                                                        } else {
                                                            phi_3828_ = _e4231;
                                                        }
                                                        let _e4238 = phi_3828_;
                                                        local_402 = _e4238;
                                                        if (bitcast<i32>(_e4238.member) != 0i) {
                                                            let _e4242 = local_402;
                                                            local_403 = _e4242.member_1.member[0];
                                                            local_404 = _e4242.member_1.member[1];
                                                            local_405 = _e4242.member_1.member[2];
                                                            local_406 = (((0.2126f * _e4242.member_1.member[0]) + (0.7152f * _e4242.member_1.member[1])) + (0.0722f * _e4242.member_1.member[2]));
                                                            let _e4253 = local_371;
                                                            if (_e4253 == 0u) {
                                                                let _e4277 = local_380;
                                                                let _e4278 = local_406;
                                                                let _e4280 = local_380;
                                                                let _e4281 = local_406;
                                                                phi_3870_ = _e4018;
                                                                phi_3871_ = _e4020;
                                                                phi_3872_ = select(_e4281, _e4280, (_e4277 < _e4278));
                                                            } else {
                                                                let _e4255 = local_406;
                                                                let _e4256 = local_376;
                                                                if (_e4255 <= _e4256) {
                                                                    let _e4258 = local_379;
                                                                    let _e4260 = local_403;
                                                                    let _e4262 = local_379;
                                                                    let _e4264 = local_404;
                                                                    let _e4266 = local_379;
                                                                    let _e4268 = local_405;
                                                                    let _e4271 = local_378;
                                                                    phi_3868_ = (_e4271 + 1u);
                                                                    phi_3869_ = array<f32, 3>((_e4258[0] + _e4260), (_e4262[1] + _e4264), (_e4266[2] + _e4268));
                                                                } else {
                                                                    phi_3868_ = _e4018;
                                                                    phi_3869_ = _e4020;
                                                                }
                                                                let _e4274 = phi_3868_;
                                                                let _e4276 = phi_3869_;
                                                                phi_3870_ = _e4274;
                                                                phi_3871_ = _e4276;
                                                                phi_3872_ = _e4022;
                                                            }
                                                            let _e4284 = phi_3870_;
                                                            let _e4286 = phi_3871_;
                                                            let _e4288 = phi_3872_;
                                                            phi_3873_ = _e4284;
                                                            phi_3874_ = _e4286;
                                                            phi_3875_ = _e4288;
                                                        } else {
                                                            phi_3873_ = _e4018;
                                                            phi_3874_ = _e4020;
                                                            phi_3875_ = _e4022;
                                                        }
                                                        let _e4290 = phi_3873_;
                                                        let _e4292 = phi_3874_;
                                                        let _e4294 = phi_3875_;
                                                        phi_3876_ = _e4290;
                                                        phi_3877_ = _e4292;
                                                        phi_3878_ = _e4294;
                                                    } else {
                                                        phi_3876_ = _e4018;
                                                        phi_3877_ = _e4020;
                                                        phi_3878_ = _e4022;
                                                    }
                                                    let _e4296 = phi_3876_;
                                                    let _e4298 = phi_3877_;
                                                    let _e4300 = phi_3878_;
                                                    phi_3879_ = _e4296;
                                                    phi_3880_ = _e4298;
                                                    phi_3881_ = _e4300;
                                                } else {
                                                    phi_3879_ = _e4018;
                                                    phi_3880_ = _e4020;
                                                    phi_3881_ = _e4022;
                                                }
                                                let _e4302 = phi_3879_;
                                                let _e4304 = phi_3880_;
                                                let _e4306 = phi_3881_;
                                                phi_3882_ = _e4302;
                                                phi_3883_ = _e4304;
                                                phi_3884_ = _e4306;
                                            } else {
                                                phi_3882_ = _e4018;
                                                phi_3883_ = _e4020;
                                                phi_3884_ = _e4022;
                                            }
                                            let _e4308 = phi_3882_;
                                            let _e4310 = phi_3883_;
                                            let _e4312 = phi_3884_;
                                            phi_3885_ = _e4308;
                                            phi_3886_ = _e4310;
                                            phi_3887_ = _e4312;
                                        } else {
                                            phi_3885_ = _e4018;
                                            phi_3886_ = _e4020;
                                            phi_3887_ = _e4022;
                                        }
                                        let _e4314 = phi_3885_;
                                        let _e4316 = phi_3886_;
                                        let _e4318 = phi_3887_;
                                        phi_3888_ = _e4314;
                                        phi_3889_ = _e4316;
                                        phi_3890_ = _e4318;
                                    } else {
                                        phi_3888_ = _e4018;
                                        phi_3889_ = _e4020;
                                        phi_3890_ = _e4022;
                                    }
                                    let _e4320 = phi_3888_;
                                    let _e4322 = phi_3889_;
                                    let _e4324 = phi_3890_;
                                    let _e4325 = local_377;
                                    phi_3563_ = (_e4325 + 1u);
                                    phi_3566_ = _e4320;
                                    phi_3568_ = _e4322;
                                    phi_3570_ = _e4324;
                                } else {
                                    phi_3563_ = u32();
                                    phi_3566_ = u32();
                                    phi_3568_ = array<f32, 3>();
                                    phi_3570_ = f32();
                                }
                                let _e4328 = phi_3563_;
                                let _e4330 = phi_3566_;
                                let _e4332 = phi_3568_;
                                let _e4334 = phi_3570_;
                                continue;
                                continuing {
                                    let _e4335 = local_381;
                                    phi_3562_ = _e4328;
                                    phi_3565_ = _e4330;
                                    phi_3567_ = _e4332;
                                    phi_3569_ = _e4334;
                                    phi_6383_ = _e3999;
                                    break if !(_e4335);
                                }
                            }
                            let _e4338 = phi_6383_;
                            phi_6430_ = _e4338;
                            if _e4338 {
                                break;
                            }
                            let _e4339 = local_371;
                            phi_6431_ = _e4338;
                            phi_3541_ = (_e4339 + 1u);
                            let _e6746 = local_666;
                            phi_3544_ = _e6746;
                            let _e6749 = local_667;
                            phi_3546_ = _e6749;
                            let _e6752 = local_668;
                            phi_3548_ = _e6752;
                        } else {
                            phi_6431_ = _e3999;
                            phi_3541_ = u32();
                            phi_3544_ = u32();
                            phi_3546_ = array<f32, 3>();
                            phi_3548_ = f32();
                        }
                        let _e4342 = phi_6431_;
                        let _e4344 = phi_3541_;
                        let _e4346 = phi_3544_;
                        let _e4348 = phi_3546_;
                        let _e4350 = phi_3548_;
                        continue;
                        continuing {
                            let _e4351 = local_375;
                            phi_6387_ = _e4342;
                            phi_3540_ = _e4344;
                            phi_3543_ = _e4346;
                            phi_3545_ = _e4348;
                            phi_3547_ = _e4350;
                            phi_6430_ = _e4342;
                            break if !(_e4351);
                        }
                    }
                    let _e4354 = phi_6430_;
                    if _e4354 {
                        break;
                    }
                    let _e4355 = local_372;
                    if (_e4355 == 0u) {
                        local_628 = array<f32, 4>(0f, 0f, 0f, 0f);
                        phi_6640_ = _e4354;
                        phi_6575_ = 0f;
                        phi_6527_ = 0f;
                        phi_6479_ = 0f;
                    } else {
                        let _e4357 = local_372;
                        let _e4359 = (1f / f32(_e4357));
                        let _e4360 = local_373;
                        let _e4362 = (_e4360[0] * _e4359);
                        local_407 = _e4362;
                        let _e4363 = local_373;
                        let _e4365 = (_e4363[1] * _e4359);
                        local_408 = _e4365;
                        let _e4366 = local_373;
                        let _e4368 = (_e4366[2] * _e4359);
                        local_409 = _e4368;
                        local_410 = (((0.2126f * _e4362) + (0.7152f * _e4365)) + (0.0722f * _e4368));
                        local_628 = array<f32, 4>(0f, 0f, 0f, 0f);
                        phi_3918_ = 0u;
                        loop {
                            let _e4375 = phi_3918_;
                            local_411 = _e4375;
                            let _e4376 = local_411;
                            let _e4377 = (_e4376 < 4u);
                            local_412 = _e4377;
                            if _e4377 {
                                let _e4378 = local_21;
                                let _e4380 = local_411;
                                let _e4382 = ((2u * _e4378) + (_e4380 % 2u));
                                local_413 = _e4382;
                                let _e4383 = local_22;
                                let _e4385 = local_411;
                                local_414 = ((2u * _e4383) + (_e4385 / 2u));
                                let _e4388 = local_14;
                                if (_e4382 < _e4388) {
                                    let _e4390 = local_414;
                                    let _e4391 = local_18;
                                    if (_e4390 < _e4391) {
                                        let _e4393 = local_414;
                                        let _e4394 = local_14;
                                        let _e4396 = local_413;
                                        let _e4397 = ((_e4393 * _e4394) + _e4396);
                                        local_415 = _e4397;
                                        let _e4398 = (3u * _e4397);
                                        local_416 = _e4398;
                                        let _e4399 = local_5;
                                        if (_e4398 < _e4399) {
                                        } else {
                                            phi_6432_ = true;
                                            break;
                                        }
                                        let _e4401 = local_416;
                                        let _e4404 = global_4.member[_e4401];
                                        local_417 = bitcast<f32>(_e4404);
                                        let _e4406 = local_416;
                                        let _e4407 = (_e4406 + 1u);
                                        local_418 = _e4407;
                                        let _e4408 = local_5;
                                        if (_e4407 < _e4408) {
                                        } else {
                                            phi_6432_ = true;
                                            break;
                                        }
                                        let _e4410 = local_418;
                                        let _e4413 = global_4.member[_e4410];
                                        local_419 = bitcast<f32>(_e4413);
                                        let _e4415 = local_416;
                                        let _e4416 = (_e4415 + 2u);
                                        local_420 = _e4416;
                                        let _e4417 = local_5;
                                        if (_e4416 < _e4417) {
                                        } else {
                                            phi_6432_ = true;
                                            break;
                                        }
                                        let _e4419 = local_420;
                                        let _e4422 = global_4.member[_e4419];
                                        local_421 = bitcast<f32>(_e4422);
                                        let _e4424 = local_417;
                                        if (_e4424 > 1267650600000000000000000000000f) {
                                            let _e4426 = local_417;
                                            phi_3987_ = select(true, false, (_e4426 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_3987_ = true;
                                        }
                                        let _e4430 = phi_3987_;
                                        if _e4430 {
                                            let _e4431 = local_417;
                                            if (_e4431 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e4433 = local_417;
                                                phi_4001_ = select(true, false, (_e4433 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_4001_ = true;
                                            }
                                            let _e4437 = phi_4001_;
                                            let _e4438 = local_417;
                                            phi_4006_ = select(0f, _e4438, _e4437);
                                        } else {
                                            phi_4006_ = 1267650600000000000000000000000f;
                                        }
                                        let _e4441 = phi_4006_;
                                        local_422 = _e4441;
                                        let _e4442 = local_419;
                                        if (_e4442 > 1267650600000000000000000000000f) {
                                            let _e4444 = local_419;
                                            phi_4016_ = select(true, false, (_e4444 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4016_ = true;
                                        }
                                        let _e4448 = phi_4016_;
                                        if _e4448 {
                                            let _e4449 = local_419;
                                            if (_e4449 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e4451 = local_419;
                                                phi_4030_ = select(true, false, (_e4451 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_4030_ = true;
                                            }
                                            let _e4455 = phi_4030_;
                                            let _e4456 = local_419;
                                            phi_4035_ = select(0f, _e4456, _e4455);
                                        } else {
                                            phi_4035_ = 1267650600000000000000000000000f;
                                        }
                                        let _e4459 = phi_4035_;
                                        local_423 = _e4459;
                                        let _e4460 = local_421;
                                        if (_e4460 > 1267650600000000000000000000000f) {
                                            let _e4462 = local_421;
                                            phi_4045_ = select(true, false, (_e4462 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4045_ = true;
                                        }
                                        let _e4466 = phi_4045_;
                                        if _e4466 {
                                            let _e4467 = local_421;
                                            if (_e4467 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e4469 = local_421;
                                                phi_4059_ = select(true, false, (_e4469 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_4059_ = true;
                                            }
                                            let _e4473 = phi_4059_;
                                            let _e4474 = local_421;
                                            phi_4064_ = select(0f, _e4474, _e4473);
                                        } else {
                                            phi_4064_ = 1267650600000000000000000000000f;
                                        }
                                        let _e4477 = phi_4064_;
                                        local_424 = _e4477;
                                        let _e4478 = local_422;
                                        let _e4479 = local_423;
                                        local_425 = array<f32, 3>(_e4478, _e4479, _e4477);
                                        let _e4481 = local_415;
                                        let _e4482 = local_6;
                                        if (_e4481 < _e4482) {
                                        } else {
                                            phi_6432_ = true;
                                            break;
                                        }
                                        let _e4484 = local_415;
                                        let _e4487 = global_3.member[_e4484];
                                        local_426 = bitcast<f32>(_e4487);
                                        let _e4489 = local_422;
                                        if ((bitcast<u32>(_e4489) & 2139095040u) != 2139095040u) {
                                            let _e4493 = local_423;
                                            if ((bitcast<u32>(_e4493) & 2139095040u) != 2139095040u) {
                                                let _e4497 = local_424;
                                                if ((bitcast<u32>(_e4497) & 2139095040u) != 2139095040u) {
                                                    let _e4501 = local_426;
                                                    let _e4502 = bitcast<u32>(_e4501);
                                                    local_427 = _e4502;
                                                    if (_e4502 == 0u) {
                                                        phi_4098_ = false;
                                                    } else {
                                                        let _e4504 = local_427;
                                                        phi_4098_ = (_e4504 <= 2139095040u);
                                                    }
                                                    let _e4507 = phi_4098_;
                                                    local_428 = _e4507;
                                                    if _e4507 {
                                                        let _e4508 = local_425;
                                                        let _e4509 = local_426;
                                                        phi_4104_ = type_23(1u, type_22(_e4508, _e4509));
                                                    } else {
                                                        phi_4104_ = type_23();
                                                    }
                                                    let _e4513 = phi_4104_;
                                                    let _e4514 = local_428;
                                                    phi_4106_ = _e4513;
                                                    phi_4107_ = select(true, false, _e4514);
                                                } else {
                                                    phi_4106_ = type_23();
                                                    phi_4107_ = true;
                                                }
                                                let _e4517 = phi_4106_;
                                                let _e4519 = phi_4107_;
                                                phi_4108_ = _e4517;
                                                phi_4109_ = _e4519;
                                            } else {
                                                phi_4108_ = type_23();
                                                phi_4109_ = true;
                                            }
                                            let _e4521 = phi_4108_;
                                            let _e4523 = phi_4109_;
                                            phi_4110_ = _e4521;
                                            phi_4111_ = _e4523;
                                        } else {
                                            phi_4110_ = type_23();
                                            phi_4111_ = true;
                                        }
                                        let _e4525 = phi_4110_;
                                        let _e4527 = phi_4111_;
                                        if _e4527 {
                                            phi_4116_ = type_23(0u, type_23().member_1);
                                        } else {
                                            phi_4116_ = _e4525;
                                        }
                                        let _e4532 = phi_4116_;
                                        local_429 = _e4532;
                                        if (bitcast<i32>(_e4532.member) != 0i) {
                                            let _e4536 = local_429;
                                            local_430 = _e4536.member_1.member;
                                            let _e4539 = local_429;
                                            local_431 = _e4539.member_1.member_1;
                                            let _e4544 = global_2.member.member_3;
                                            local_432 = f32(_e4544);
                                            let _e4546 = bitcast<u32>(_e4539.member_1.member_1);
                                            local_433 = _e4546;
                                            if (_e4546 == 2139095040u) {
                                                let _e4590 = global_2.member.member_4.member_1;
                                                let _e4595 = global_2.member.member_4.member;
                                                let _e4600 = global_2.member.member_4.member_2;
                                                let _e4606 = global_2.member.member_4.member_3;
                                                phi_4187_ = (0.5f * ((((2f * _e4590) * _e4595) / (_e4600 - _e4595)) * _e4606));
                                            } else {
                                                let _e4548 = local_433;
                                                if (_e4548 == 0u) {
                                                    phi_4156_ = false;
                                                } else {
                                                    let _e4550 = local_433;
                                                    phi_4156_ = (_e4550 <= 2139095040u);
                                                }
                                                let _e4553 = phi_4156_;
                                                if _e4553 {
                                                    let _e4557 = global_2.member.member_4.member_1;
                                                    let _e4562 = global_2.member.member_4.member;
                                                    let _e4567 = global_2.member.member_4.member_2;
                                                    local_434 = _e4567;
                                                    let _e4573 = global_2.member.member_4.member_3;
                                                    let _e4574 = ((((2f * _e4557) * _e4562) / (_e4567 - _e4562)) * _e4573);
                                                    local_435 = _e4574;
                                                    if (_e4574 == 0f) {
                                                        phi_4184_ = 0f;
                                                    } else {
                                                        let _e4576 = local_434;
                                                        let _e4577 = local_431;
                                                        let _e4580 = local_435;
                                                        phi_4184_ = (_e4580 * (1f - (_e4576 / _e4577)));
                                                    }
                                                    let _e4583 = phi_4184_;
                                                    phi_4185_ = _e4583;
                                                } else {
                                                    phi_4185_ = _e729;
                                                }
                                                let _e4585 = phi_4185_;
                                                phi_4187_ = (0.5f * _e4585);
                                            }
                                            let _e4610 = phi_4187_;
                                            let _e4611 = local_432;
                                            let _e4613 = local_432;
                                            let _e4614 = select(_e4613, _e4610, (_e4610 < _e4611));
                                            let _e4615 = local_432;
                                            let _e4616 = -(_e4615);
                                            let _e4618 = select(_e4616, _e4614, (_e4614 > _e4616));
                                            local_616 = _e4618;
                                            if (_e4618 < 0f) {
                                                let _e4620 = local_616;
                                                phi_4204_ = -(_e4620);
                                            } else {
                                                phi_4204_ = _e4618;
                                            }
                                            let _e4623 = phi_4204_;
                                            let _e4625 = ((_e4623 - 0.25f) * 4f);
                                            let _e4627 = select(0f, _e4625, (_e4625 > 0f));
                                            local_617 = select(1f, _e4627, (_e4627 < 1f));
                                            let _e4630 = local_430;
                                            let _e4632 = local_407;
                                            let _e4633 = (_e4630[0] - _e4632);
                                            let _e4636 = local_430;
                                            let _e4638 = local_408;
                                            let _e4639 = (_e4636[1] - _e4638);
                                            let _e4642 = local_430;
                                            let _e4644 = local_409;
                                            let _e4645 = (_e4642[2] - _e4644);
                                            let _e4652 = (((0.2126f * _e4630[0]) + (0.7152f * _e4636[1])) + (0.0722f * _e4642[2]));
                                            local_436 = _e4652;
                                            local_437 = (((0.2126f * select(0f, _e4633, (_e4633 > 0f))) + (0.7152f * select(0f, _e4639, (_e4639 > 0f)))) + (0.0722f * select(0f, _e4645, (_e4645 > 0f))));
                                            let _e4658 = local_410;
                                            if (_e4652 >= (8f * _e4658)) {
                                                phi_4271_ = 1f;
                                            } else {
                                                let _e4661 = local_410;
                                                let _e4662 = (4f * _e4661);
                                                let _e4663 = local_436;
                                                let _e4665 = ((_e4663 - _e4662) / _e4662);
                                                let _e4667 = select(0f, _e4665, (_e4665 > 0f));
                                                phi_4271_ = select(1f, _e4667, (_e4667 < 1f));
                                            }
                                            let _e4671 = phi_4271_;
                                            let _e4672 = local_437;
                                            let _e4674 = ((_e4672 - 0.25f) * 4f);
                                            let _e4676 = select(0f, _e4674, (_e4674 > 0f));
                                            local_618 = select(1f, _e4676, (_e4676 < 1f));
                                            let _e4679 = local_617;
                                            local_438 = (_e4679 * _e4671);
                                            let _e4681 = local_412;
                                            if _e4681 {
                                            } else {
                                                phi_6432_ = true;
                                                break;
                                            }
                                            let _e4682 = local_411;
                                            let _e4684 = local_438;
                                            let _e4685 = local_618;
                                            local_628[_e4682] = (_e4684 * _e4685);
                                        }
                                    }
                                }
                                let _e4687 = local_411;
                                phi_3919_ = (_e4687 + 1u);
                            } else {
                                phi_3919_ = u32();
                            }
                            let _e4690 = phi_3919_;
                            continue;
                            continuing {
                                let _e4691 = local_412;
                                phi_3918_ = _e4690;
                                phi_6432_ = _e4354;
                                break if !(_e4691);
                            }
                        }
                        let _e4694 = phi_6432_;
                        if _e4694 {
                            break;
                        }
                        phi_6640_ = _e4694;
                        phi_6575_ = _e4362;
                        phi_6527_ = _e4365;
                        phi_6479_ = _e4368;
                    }
                    let _e4696 = phi_6640_;
                    let _e4698 = phi_6575_;
                    let _e4700 = phi_6527_;
                    let _e4702 = phi_6479_;
                    local_602 = _e4698;
                    local_601 = _e4700;
                    local_600 = _e4702;
                    let _e4703 = local_628;
                    local_595 = _e4703;
                    let _e4713 = global_2.member.member_3;
                    local_439 = f32(_e4713);
                    local_641 = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_6639_ = _e4696;
                    phi_4310_ = 0u;
                    phi_4313_ = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_4315_ = array<f32, 3>(0f, 0f, 0f);
                    phi_4317_ = 0f;
                    phi_4319_ = array<f32, 4>(0f, 0f, 0f, 0f);
                    phi_4321_ = 0f;
                    phi_4323_ = 0f;
                    phi_4325_ = array<f32, 3>(0f, 0f, 0f);
                    phi_4327_ = array<f32, 2>(0f, 0f);
                    phi_4329_ = 0u;
                    phi_4331_ = 0f;
                    loop {
                        let _e4716 = phi_6639_;
                        let _e4718 = phi_4310_;
                        let _e4720 = phi_4313_;
                        let _e4722 = phi_4315_;
                        let _e4724 = phi_4317_;
                        let _e4726 = phi_4319_;
                        let _e4728 = phi_4321_;
                        let _e4730 = phi_4323_;
                        let _e4732 = phi_4325_;
                        let _e4734 = phi_4327_;
                        let _e4736 = phi_4329_;
                        let _e4738 = phi_4331_;
                        local_440 = _e4718;
                        local_441 = _e4720;
                        local_442 = _e4722;
                        local_443 = _e4724;
                        local_444 = _e4726;
                        local_445 = _e4728;
                        local_446 = _e4730;
                        local_447 = _e4732;
                        local_448 = _e4734;
                        local_449 = _e4736;
                        local_450 = _e4738;
                        let _e4739 = local_440;
                        let _e4740 = (_e4739 < 4u);
                        local_451 = _e4740;
                        if _e4740 {
                            let _e4741 = local_21;
                            let _e4743 = local_440;
                            let _e4745 = ((2u * _e4741) + (_e4743 % 2u));
                            local_452 = _e4745;
                            let _e4746 = local_22;
                            let _e4748 = local_440;
                            local_453 = ((2u * _e4746) + (_e4748 / 2u));
                            let _e4751 = local_14;
                            if (_e4745 < _e4751) {
                                let _e4753 = local_453;
                                let _e4754 = local_18;
                                if (_e4753 < _e4754) {
                                    let _e4756 = local_453;
                                    let _e4757 = local_14;
                                    let _e4759 = local_452;
                                    let _e4760 = ((_e4756 * _e4757) + _e4759);
                                    local_454 = _e4760;
                                    let _e4761 = (3u * _e4760);
                                    local_455 = _e4761;
                                    let _e4762 = local_5;
                                    if (_e4761 < _e4762) {
                                    } else {
                                        phi_6659_ = true;
                                        break;
                                    }
                                    let _e4764 = local_455;
                                    let _e4767 = global_4.member[_e4764];
                                    local_456 = bitcast<f32>(_e4767);
                                    let _e4769 = local_455;
                                    let _e4770 = (_e4769 + 1u);
                                    local_457 = _e4770;
                                    let _e4771 = local_5;
                                    if (_e4770 < _e4771) {
                                    } else {
                                        phi_6659_ = true;
                                        break;
                                    }
                                    let _e4773 = local_457;
                                    let _e4776 = global_4.member[_e4773];
                                    local_458 = bitcast<f32>(_e4776);
                                    let _e4778 = local_455;
                                    let _e4779 = (_e4778 + 2u);
                                    local_459 = _e4779;
                                    let _e4780 = local_5;
                                    if (_e4779 < _e4780) {
                                    } else {
                                        phi_6659_ = true;
                                        break;
                                    }
                                    let _e4782 = local_459;
                                    let _e4785 = global_4.member[_e4782];
                                    local_460 = bitcast<f32>(_e4785);
                                    let _e4787 = local_456;
                                    if (_e4787 > 1267650600000000000000000000000f) {
                                        let _e4789 = local_456;
                                        phi_4399_ = select(true, false, (_e4789 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_4399_ = true;
                                    }
                                    let _e4793 = phi_4399_;
                                    if _e4793 {
                                        let _e4794 = local_456;
                                        if (_e4794 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e4796 = local_456;
                                            phi_4413_ = select(true, false, (_e4796 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4413_ = true;
                                        }
                                        let _e4800 = phi_4413_;
                                        let _e4801 = local_456;
                                        phi_4418_ = select(0f, _e4801, _e4800);
                                    } else {
                                        phi_4418_ = 1267650600000000000000000000000f;
                                    }
                                    let _e4804 = phi_4418_;
                                    local_461 = _e4804;
                                    let _e4805 = local_458;
                                    if (_e4805 > 1267650600000000000000000000000f) {
                                        let _e4807 = local_458;
                                        phi_4428_ = select(true, false, (_e4807 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_4428_ = true;
                                    }
                                    let _e4811 = phi_4428_;
                                    if _e4811 {
                                        let _e4812 = local_458;
                                        if (_e4812 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e4814 = local_458;
                                            phi_4442_ = select(true, false, (_e4814 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4442_ = true;
                                        }
                                        let _e4818 = phi_4442_;
                                        let _e4819 = local_458;
                                        phi_4447_ = select(0f, _e4819, _e4818);
                                    } else {
                                        phi_4447_ = 1267650600000000000000000000000f;
                                    }
                                    let _e4822 = phi_4447_;
                                    local_462 = _e4822;
                                    let _e4823 = local_460;
                                    if (_e4823 > 1267650600000000000000000000000f) {
                                        let _e4825 = local_460;
                                        phi_4457_ = select(true, false, (_e4825 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_4457_ = true;
                                    }
                                    let _e4829 = phi_4457_;
                                    if _e4829 {
                                        let _e4830 = local_460;
                                        if (_e4830 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e4832 = local_460;
                                            phi_4471_ = select(true, false, (_e4832 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_4471_ = true;
                                        }
                                        let _e4836 = phi_4471_;
                                        let _e4837 = local_460;
                                        phi_4476_ = select(0f, _e4837, _e4836);
                                    } else {
                                        phi_4476_ = 1267650600000000000000000000000f;
                                    }
                                    let _e4840 = phi_4476_;
                                    local_463 = _e4840;
                                    let _e4841 = local_461;
                                    let _e4842 = local_462;
                                    local_464 = array<f32, 3>(_e4841, _e4842, _e4840);
                                    let _e4844 = local_454;
                                    let _e4845 = local_6;
                                    if (_e4844 < _e4845) {
                                    } else {
                                        phi_6659_ = true;
                                        break;
                                    }
                                    let _e4847 = local_454;
                                    let _e4850 = global_3.member[_e4847];
                                    local_465 = bitcast<f32>(_e4850);
                                    let _e4852 = local_461;
                                    if ((bitcast<u32>(_e4852) & 2139095040u) != 2139095040u) {
                                        let _e4856 = local_462;
                                        if ((bitcast<u32>(_e4856) & 2139095040u) != 2139095040u) {
                                            let _e4860 = local_463;
                                            if ((bitcast<u32>(_e4860) & 2139095040u) != 2139095040u) {
                                                let _e4864 = local_465;
                                                let _e4865 = bitcast<u32>(_e4864);
                                                local_466 = _e4865;
                                                if (_e4865 == 0u) {
                                                    phi_4510_ = false;
                                                } else {
                                                    let _e4867 = local_466;
                                                    phi_4510_ = (_e4867 <= 2139095040u);
                                                }
                                                let _e4870 = phi_4510_;
                                                local_467 = _e4870;
                                                if _e4870 {
                                                    let _e4871 = local_464;
                                                    let _e4872 = local_465;
                                                    phi_4516_ = type_23(1u, type_22(_e4871, _e4872));
                                                } else {
                                                    phi_4516_ = type_23();
                                                }
                                                let _e4876 = phi_4516_;
                                                let _e4877 = local_467;
                                                phi_4518_ = _e4876;
                                                phi_4519_ = select(true, false, _e4877);
                                            } else {
                                                phi_4518_ = type_23();
                                                phi_4519_ = true;
                                            }
                                            let _e4880 = phi_4518_;
                                            let _e4882 = phi_4519_;
                                            phi_4520_ = _e4880;
                                            phi_4521_ = _e4882;
                                        } else {
                                            phi_4520_ = type_23();
                                            phi_4521_ = true;
                                        }
                                        let _e4884 = phi_4520_;
                                        let _e4886 = phi_4521_;
                                        phi_4522_ = _e4884;
                                        phi_4523_ = _e4886;
                                    } else {
                                        phi_4522_ = type_23();
                                        phi_4523_ = true;
                                    }
                                    let _e4888 = phi_4522_;
                                    let _e4890 = phi_4523_;
                                    if _e4890 {
                                        phi_4528_ = type_23(0u, type_23().member_1);
                                    } else {
                                        phi_4528_ = _e4888;
                                    }
                                    let _e4895 = phi_4528_;
                                    local_468 = _e4895;
                                    if (bitcast<i32>(_e4895.member) != 0i) {
                                        let _e4899 = local_468;
                                        local_469 = _e4899.member_1.member;
                                        let _e4902 = local_468;
                                        local_470 = _e4902.member_1.member_1;
                                        let _e4905 = bitcast<u32>(_e4902.member_1.member_1);
                                        local_471 = _e4905;
                                        if (_e4905 == 2139095040u) {
                                            let _e4949 = global_2.member.member_4.member_1;
                                            let _e4954 = global_2.member.member_4.member;
                                            let _e4959 = global_2.member.member_4.member_2;
                                            let _e4965 = global_2.member.member_4.member_3;
                                            phi_4596_ = (0.5f * ((((2f * _e4949) * _e4954) / (_e4959 - _e4954)) * _e4965));
                                        } else {
                                            let _e4907 = local_471;
                                            if (_e4907 == 0u) {
                                                phi_4565_ = false;
                                            } else {
                                                let _e4909 = local_471;
                                                phi_4565_ = (_e4909 <= 2139095040u);
                                            }
                                            let _e4912 = phi_4565_;
                                            if _e4912 {
                                                let _e4916 = global_2.member.member_4.member_1;
                                                let _e4921 = global_2.member.member_4.member;
                                                let _e4926 = global_2.member.member_4.member_2;
                                                local_472 = _e4926;
                                                let _e4932 = global_2.member.member_4.member_3;
                                                let _e4933 = ((((2f * _e4916) * _e4921) / (_e4926 - _e4921)) * _e4932);
                                                local_473 = _e4933;
                                                if (_e4933 == 0f) {
                                                    phi_4593_ = 0f;
                                                } else {
                                                    let _e4935 = local_472;
                                                    let _e4936 = local_470;
                                                    let _e4939 = local_473;
                                                    phi_4593_ = (_e4939 * (1f - (_e4935 / _e4936)));
                                                }
                                                let _e4942 = phi_4593_;
                                                phi_4594_ = _e4942;
                                            } else {
                                                phi_4594_ = _e729;
                                            }
                                            let _e4944 = phi_4594_;
                                            phi_4596_ = (0.5f * _e4944);
                                        }
                                        let _e4969 = phi_4596_;
                                        let _e4970 = local_439;
                                        let _e4972 = local_439;
                                        let _e4973 = select(_e4972, _e4969, (_e4969 < _e4970));
                                        let _e4974 = local_439;
                                        let _e4975 = -(_e4974);
                                        local_619 = select(_e4975, _e4973, (_e4973 > _e4975));
                                        let _e4978 = local_469;
                                        let _e4980 = local_469;
                                        let _e4982 = local_469;
                                        local_638 = array<f32, 3>(_e4978[0], _e4980[1], _e4982[2]);
                                        let _e4985 = local_602;
                                        let _e4986 = local_601;
                                        let _e4987 = local_600;
                                        let _e4989 = local_595;
                                        local_630 = _e4989;
                                        local_629 = array<f32, 3>(_e4985, _e4986, _e4987);
                                        let _e4990 = local_451;
                                        if _e4990 {
                                        } else {
                                            phi_6659_ = true;
                                            break;
                                        }
                                        let _e4991 = local_440;
                                        let _e4993 = local_630[_e4991];
                                        local_474 = _e4993;
                                        if (_e4993 <= 0f) {
                                            let _e5054 = local_638;
                                            phi_6669_ = _e4716;
                                            phi_4714_ = type_25(array<f32, 3>(_e5054[0], _e5054[1], _e5054[2]), array<f32, 3>(0f, 0f, 0f));
                                        } else {
                                            let _e4995 = local_638;
                                            local_639 = _e4995;
                                            local_640 = array<f32, 3>(0f, 0f, 0f);
                                            phi_4642_ = 0u;
                                            loop {
                                                let _e4997 = phi_4642_;
                                                local_475 = _e4997;
                                                let _e4998 = local_475;
                                                let _e4999 = (_e4998 < 3u);
                                                local_476 = _e4999;
                                                if _e4999 {
                                                    let _e5000 = local_476;
                                                    if _e5000 {
                                                    } else {
                                                        phi_6623_ = true;
                                                        break;
                                                    }
                                                    let _e5001 = local_475;
                                                    let _e5003 = local_629[_e5001];
                                                    local_477 = _e5003;
                                                    let _e5004 = local_476;
                                                    if _e5004 {
                                                    } else {
                                                        phi_6623_ = true;
                                                        break;
                                                    }
                                                    let _e5005 = local_475;
                                                    let _e5007 = local_638[_e5005];
                                                    let _e5008 = local_477;
                                                    if (_e5007 > _e5008) {
                                                        let _e5010 = local_476;
                                                        if _e5010 {
                                                        } else {
                                                            phi_6623_ = true;
                                                            break;
                                                        }
                                                        let _e5011 = local_638[_e5005];
                                                        let _e5012 = local_477;
                                                        local_478 = (_e5011 - _e5012);
                                                        let _e5014 = local_476;
                                                        if _e5014 {
                                                        } else {
                                                            phi_6623_ = true;
                                                            break;
                                                        }
                                                        let _e5015 = local_475;
                                                        let _e5017 = local_474;
                                                        let _e5018 = local_478;
                                                        local_640[_e5015] = (_e5017 * _e5018);
                                                        let _e5020 = local_474;
                                                        local_479 = (1f - _e5020);
                                                        let _e5022 = local_476;
                                                        if _e5022 {
                                                        } else {
                                                            phi_6623_ = true;
                                                            break;
                                                        }
                                                        let _e5023 = local_638[_e5005];
                                                        let _e5024 = local_479;
                                                        local_480 = (_e5024 * _e5023);
                                                        let _e5026 = local_474;
                                                        let _e5027 = local_477;
                                                        local_481 = (_e5026 * _e5027);
                                                        let _e5029 = local_476;
                                                        if _e5029 {
                                                        } else {
                                                            phi_6623_ = true;
                                                            break;
                                                        }
                                                        let _e5030 = local_475;
                                                        let _e5032 = local_480;
                                                        let _e5033 = local_481;
                                                        local_639[_e5030] = (_e5032 + _e5033);
                                                    }
                                                    let _e5035 = local_475;
                                                    phi_4643_ = (_e5035 + 1u);
                                                } else {
                                                    phi_4643_ = u32();
                                                }
                                                let _e5038 = phi_4643_;
                                                continue;
                                                continuing {
                                                    let _e5039 = local_476;
                                                    phi_4642_ = _e5038;
                                                    phi_6623_ = _e4716;
                                                    break if !(_e5039);
                                                }
                                            }
                                            let _e5042 = phi_6623_;
                                            phi_6659_ = _e5042;
                                            if _e5042 {
                                                break;
                                            }
                                            let _e5043 = local_639;
                                            let _e5048 = local_640;
                                            phi_6669_ = _e5042;
                                            phi_4714_ = type_25(array<f32, 3>(_e5043[0], _e5043[1], _e5043[2]), array<f32, 3>(_e5048[0], _e5048[1], _e5048[2]));
                                        }
                                        let _e5061 = phi_6669_;
                                        let _e5063 = phi_4714_;
                                        local_482 = _e5063.member;
                                        let _e5066 = local_442;
                                        let _e5070 = local_442;
                                        let _e5074 = local_442;
                                        local_483 = (((0.2126f * _e5063.member_1[0]) + (0.7152f * _e5063.member_1[1])) + (0.0722f * _e5063.member_1[2]));
                                        let _e5084 = local_451;
                                        if _e5084 {
                                        } else {
                                            phi_6659_ = true;
                                            break;
                                        }
                                        let _e5085 = local_440;
                                        let _e5087 = local_483;
                                        local_641[_e5085] = _e5087;
                                        let _e5088 = local_441;
                                        let _e5090 = local_452;
                                        let _e5091 = f32(_e5090);
                                        let _e5093 = local_483;
                                        let _e5096 = local_441;
                                        let _e5098 = local_453;
                                        let _e5099 = f32(_e5098);
                                        let _e5101 = local_483;
                                        let _e5104 = local_441;
                                        let _e5106 = local_483;
                                        let _e5107 = local_619;
                                        let _e5110 = local_441;
                                        let _e5112 = local_483;
                                        let _e5115 = local_450;
                                        let _e5116 = local_619;
                                        let _e5118 = local_448;
                                        let _e5122 = local_448;
                                        let _e5127 = local_449;
                                        let _e5129 = local_619;
                                        let _e5131 = local_619;
                                        let _e5133 = ((-1f - _e5131) * 0.5f);
                                        let _e5135 = select(0f, _e5133, (_e5133 > 0f));
                                        let _e5137 = select(1f, _e5135, (_e5135 < 1f));
                                        let _e5138 = local_447;
                                        let _e5140 = local_482;
                                        let _e5144 = local_447;
                                        let _e5146 = local_482;
                                        let _e5150 = local_447;
                                        let _e5152 = local_482;
                                        let _e5157 = local_619;
                                        let _e5159 = local_446;
                                        let _e5161 = local_445;
                                        let _e5164 = local_619;
                                        let _e5166 = local_619;
                                        let _e5168 = (select(_e5166, -(_e5129), (_e5164 < 0f)) - 1f);
                                        let _e5170 = select(0f, _e5168, (_e5168 > 0f));
                                        let _e5174 = ((1f - _e5137) * (select(1f, _e5170, (_e5170 < 1f)) + 0.001f));
                                        let _e5175 = local_444;
                                        let _e5179 = local_444;
                                        let _e5183 = local_444;
                                        let _e5187 = local_444;
                                        let _e5189 = local_619;
                                        let _e5193 = local_443;
                                        phi_6663_ = _e5061;
                                        phi_4834_ = array<f32, 4>((_e5088[0] + (_e5093 * (_e5091 + 0.5f))), (_e5096[1] + (_e5101 * (_e5099 + 0.5f))), (_e5104[2] + (_e5106 * _e5107)), (_e5110[3] + _e5112));
                                        phi_4835_ = array<f32, 3>((_e5066[0] + _e5063.member_1[0]), (_e5070[1] + _e5063.member_1[1]), (_e5074[2] + _e5063.member_1[2]));
                                        phi_4836_ = (_e5193 + _e5174);
                                        phi_4837_ = array<f32, 4>((_e5175[0] + (_e5174 * _e5140[0])), (_e5179[1] + (_e5174 * _e5146[1])), (_e5183[2] + (_e5174 * _e5152[2])), (_e5187[3] + (_e5174 * _e5189)));
                                        phi_4838_ = (_e5161 + _e5137);
                                        phi_4839_ = (_e5159 + (_e5137 * _e5157));
                                        phi_4840_ = array<f32, 3>((_e5138[0] + (_e5137 * _e5140[0])), (_e5144[1] + (_e5137 * _e5146[1])), (_e5150[2] + (_e5137 * _e5152[2])));
                                        phi_4841_ = array<f32, 2>(((_e5118[0] + _e5091) + 0.5f), ((_e5122[1] + _e5099) + 0.5f));
                                        phi_4842_ = (_e5127 + 1u);
                                        phi_4843_ = (_e5115 + _e5116);
                                    } else {
                                        phi_6663_ = _e4716;
                                        phi_4834_ = _e4720;
                                        phi_4835_ = _e4722;
                                        phi_4836_ = _e4724;
                                        phi_4837_ = _e4726;
                                        phi_4838_ = _e4728;
                                        phi_4839_ = _e4730;
                                        phi_4840_ = _e4732;
                                        phi_4841_ = _e4734;
                                        phi_4842_ = _e4736;
                                        phi_4843_ = _e4738;
                                    }
                                    let _e5196 = phi_6663_;
                                    let _e5198 = phi_4834_;
                                    let _e5200 = phi_4835_;
                                    let _e5202 = phi_4836_;
                                    let _e5204 = phi_4837_;
                                    let _e5206 = phi_4838_;
                                    let _e5208 = phi_4839_;
                                    let _e5210 = phi_4840_;
                                    let _e5212 = phi_4841_;
                                    let _e5214 = phi_4842_;
                                    let _e5216 = phi_4843_;
                                    phi_6662_ = _e5196;
                                    phi_4844_ = _e5198;
                                    phi_4845_ = _e5200;
                                    phi_4846_ = _e5202;
                                    phi_4847_ = _e5204;
                                    phi_4848_ = _e5206;
                                    phi_4849_ = _e5208;
                                    phi_4850_ = _e5210;
                                    phi_4851_ = _e5212;
                                    phi_4852_ = _e5214;
                                    phi_4853_ = _e5216;
                                } else {
                                    phi_6662_ = _e4716;
                                    phi_4844_ = _e4720;
                                    phi_4845_ = _e4722;
                                    phi_4846_ = _e4724;
                                    phi_4847_ = _e4726;
                                    phi_4848_ = _e4728;
                                    phi_4849_ = _e4730;
                                    phi_4850_ = _e4732;
                                    phi_4851_ = _e4734;
                                    phi_4852_ = _e4736;
                                    phi_4853_ = _e4738;
                                }
                                let _e5218 = phi_6662_;
                                let _e5220 = phi_4844_;
                                let _e5222 = phi_4845_;
                                let _e5224 = phi_4846_;
                                let _e5226 = phi_4847_;
                                let _e5228 = phi_4848_;
                                let _e5230 = phi_4849_;
                                let _e5232 = phi_4850_;
                                let _e5234 = phi_4851_;
                                let _e5236 = phi_4852_;
                                let _e5238 = phi_4853_;
                                phi_6661_ = _e5218;
                                phi_4854_ = _e5220;
                                phi_4855_ = _e5222;
                                phi_4856_ = _e5224;
                                phi_4857_ = _e5226;
                                phi_4858_ = _e5228;
                                phi_4859_ = _e5230;
                                phi_4860_ = _e5232;
                                phi_4861_ = _e5234;
                                phi_4862_ = _e5236;
                                phi_4863_ = _e5238;
                            } else {
                                phi_6661_ = _e4716;
                                phi_4854_ = _e4720;
                                phi_4855_ = _e4722;
                                phi_4856_ = _e4724;
                                phi_4857_ = _e4726;
                                phi_4858_ = _e4728;
                                phi_4859_ = _e4730;
                                phi_4860_ = _e4732;
                                phi_4861_ = _e4734;
                                phi_4862_ = _e4736;
                                phi_4863_ = _e4738;
                            }
                            let _e5240 = phi_6661_;
                            let _e5242 = phi_4854_;
                            let _e5244 = phi_4855_;
                            let _e5246 = phi_4856_;
                            let _e5248 = phi_4857_;
                            let _e5250 = phi_4858_;
                            let _e5252 = phi_4859_;
                            let _e5254 = phi_4860_;
                            let _e5256 = phi_4861_;
                            let _e5258 = phi_4862_;
                            let _e5260 = phi_4863_;
                            let _e5261 = local_440;
                            phi_6660_ = _e5240;
                            phi_4311_ = (_e5261 + 1u);
                            phi_4314_ = _e5242;
                            phi_4316_ = _e5244;
                            phi_4318_ = _e5246;
                            phi_4320_ = _e5248;
                            phi_4322_ = _e5250;
                            phi_4324_ = _e5252;
                            phi_4326_ = _e5254;
                            phi_4328_ = _e5256;
                            phi_4330_ = _e5258;
                            phi_4332_ = _e5260;
                        } else {
                            phi_6660_ = _e4716;
                            phi_4311_ = u32();
                            phi_4314_ = array<f32, 4>();
                            phi_4316_ = array<f32, 3>();
                            phi_4318_ = f32();
                            phi_4320_ = array<f32, 4>();
                            phi_4322_ = f32();
                            phi_4324_ = f32();
                            phi_4326_ = array<f32, 3>();
                            phi_4328_ = array<f32, 2>();
                            phi_4330_ = u32();
                            phi_4332_ = f32();
                        }
                        let _e5264 = phi_6660_;
                        let _e5266 = phi_4311_;
                        let _e5268 = phi_4314_;
                        let _e5270 = phi_4316_;
                        let _e5272 = phi_4318_;
                        let _e5274 = phi_4320_;
                        let _e5276 = phi_4322_;
                        let _e5278 = phi_4324_;
                        let _e5280 = phi_4326_;
                        let _e5282 = phi_4328_;
                        let _e5284 = phi_4330_;
                        let _e5286 = phi_4332_;
                        continue;
                        continuing {
                            let _e5287 = local_451;
                            phi_6639_ = _e5264;
                            phi_4310_ = _e5266;
                            phi_4313_ = _e5268;
                            phi_4315_ = _e5270;
                            phi_4317_ = _e5272;
                            phi_4319_ = _e5274;
                            phi_4321_ = _e5276;
                            phi_4323_ = _e5278;
                            phi_4325_ = _e5280;
                            phi_4327_ = _e5282;
                            phi_4329_ = _e5284;
                            phi_4331_ = _e5286;
                            phi_6659_ = _e5264;
                            break if !(_e5287);
                        }
                    }
                    let _e5290 = phi_6659_;
                    if _e5290 {
                        break;
                    }
                    let _e5291 = local_449;
                    if (_e5291 == 0u) {
                        let _e5465 = local_622;
                        let _e5466 = local_449;
                        phi_6682_ = _e5290;
                        phi_5002_ = type_30(array<f32, 2>(0f, 0f), array<f32, 3>(0f, 0f, 0f), 0f, 0f, array<f32, 3>(0f, 0f, 0f), _e5465, _e5466, array<f32, 3>(0f, 0f, 0f), 0f, 0f);
                    } else {
                        let _e5293 = local_449;
                        let _e5294 = f32(_e5293);
                        let _e5295 = (1f / _e5294);
                        local_484 = _e5295;
                        let _e5296 = local_450;
                        let _e5298 = ((0.5f * _e5296) * _e5295);
                        local_485 = _e5298;
                        let _e5299 = local_445;
                        let _e5301 = ((_e5294 - _e5299) > 0f);
                        local_486 = _e5301;
                        if _e5301 {
                            let _e5302 = local_443;
                            let _e5303 = (_e5302 > 0f);
                            local_487 = _e5303;
                            if _e5303 {
                                let _e5304 = local_443;
                                let _e5305 = (1f / _e5304);
                                let _e5306 = local_444;
                                let _e5309 = local_444;
                                let _e5312 = local_444;
                                let _e5316 = local_444;
                                phi_4894_ = array<f32, 3>((_e5306[0] * _e5305), (_e5309[1] * _e5305), (_e5312[2] * _e5305));
                                phi_4895_ = ((0.5f * _e5316[3]) * _e5305);
                            } else {
                                phi_4894_ = array<f32, 3>();
                                phi_4895_ = f32();
                            }
                            let _e5321 = phi_4894_;
                            let _e5323 = phi_4895_;
                            let _e5324 = local_487;
                            phi_4897_ = _e5321;
                            phi_4898_ = _e5323;
                            phi_4899_ = select(true, false, _e5324);
                        } else {
                            phi_4897_ = array<f32, 3>();
                            phi_4898_ = f32();
                            phi_4899_ = true;
                        }
                        let _e5327 = phi_4897_;
                        let _e5329 = phi_4898_;
                        let _e5331 = phi_4899_;
                        local_488 = _e5329;
                        local_489 = _e5331;
                        if _e5331 {
                            phi_4903_ = array<f32, 3>(0f, 0f, 0f);
                        } else {
                            phi_4903_ = _e5327;
                        }
                        let _e5333 = phi_4903_;
                        local_490 = _e5333;
                        let _e5334 = local_489;
                        let _e5335 = local_485;
                        let _e5336 = local_488;
                        local_620 = select(_e5336, _e5335, _e5334);
                        let _e5338 = local_445;
                        if (_e5338 > 0f) {
                            let _e5340 = local_445;
                            let _e5341 = (1f / _e5340);
                            let _e5342 = local_447;
                            let _e5345 = local_447;
                            let _e5348 = local_447;
                            let _e5352 = local_446;
                            phi_4919_ = array<f32, 3>((_e5342[0] * _e5341), (_e5345[1] * _e5341), (_e5348[2] * _e5341));
                            phi_4920_ = ((0.5f * _e5352) * _e5341);
                        } else {
                            phi_4919_ = array<f32, 3>(0f, 0f, 0f);
                            phi_4920_ = _e5298;
                        }
                        let _e5356 = phi_4919_;
                        let _e5358 = phi_4920_;
                        local_491 = _e5356;
                        local_492 = _e5358;
                        let _e5359 = local_486;
                        if _e5359 {
                            let _e5360 = local_445;
                            let _e5361 = local_484;
                            phi_4926_ = (_e5360 * _e5361);
                        } else {
                            phi_4926_ = 1f;
                        }
                        let _e5364 = phi_4926_;
                        local_493 = _e5364;
                        let _e5365 = local_448;
                        let _e5367 = local_484;
                        let _e5369 = local_448;
                        let _e5371 = local_484;
                        let _e5374 = local_441;
                        local_494 = _e5374[3];
                        if (_e5374[3] > 0f) {
                            let _e5379 = local_494;
                            let _e5380 = (1f / _e5379);
                            local_495 = _e5380;
                            let _e5381 = local_441;
                            let _e5383 = (_e5381[0] * _e5380);
                            local_496 = _e5383;
                            let _e5384 = local_441;
                            let _e5386 = (_e5384[1] * _e5380);
                            local_497 = _e5386;
                            phi_4945_ = 0u;
                            phi_4948_ = 0f;
                            loop {
                                let _e5389 = phi_4945_;
                                let _e5391 = phi_4948_;
                                local_498 = _e5389;
                                local_499 = _e5391;
                                let _e5392 = local_498;
                                let _e5393 = (_e5392 < 4u);
                                local_500 = _e5393;
                                if _e5393 {
                                    let _e5394 = local_500;
                                    if _e5394 {
                                    } else {
                                        phi_6670_ = true;
                                        break;
                                    }
                                    let _e5395 = local_498;
                                    let _e5397 = local_641[_e5395];
                                    if (_e5397 > 0f) {
                                        let _e5399 = local_21;
                                        let _e5401 = local_498;
                                        let _e5406 = local_496;
                                        local_501 = ((f32(((2u * _e5399) + (_e5401 % 2u))) + 0.5f) - _e5406);
                                        let _e5408 = local_22;
                                        let _e5410 = local_498;
                                        let _e5415 = local_497;
                                        local_502 = ((f32(((2u * _e5408) + (_e5410 / 2u))) + 0.5f) - _e5415);
                                        let _e5417 = local_500;
                                        if _e5417 {
                                        } else {
                                            phi_6670_ = true;
                                            break;
                                        }
                                        let _e5418 = local_641[_e5395];
                                        let _e5419 = local_501;
                                        let _e5420 = local_501;
                                        let _e5422 = local_502;
                                        let _e5423 = local_502;
                                        let _e5428 = local_499;
                                        phi_4992_ = (_e5428 + (_e5418 * sqrt(((_e5419 * _e5420) + (_e5422 * _e5423)))));
                                    } else {
                                        phi_4992_ = _e5391;
                                    }
                                    let _e5431 = phi_4992_;
                                    let _e5432 = local_498;
                                    phi_4946_ = (_e5432 + 1u);
                                    phi_4949_ = _e5431;
                                } else {
                                    phi_4946_ = u32();
                                    phi_4949_ = f32();
                                }
                                let _e5435 = phi_4946_;
                                let _e5437 = phi_4949_;
                                continue;
                                continuing {
                                    let _e5438 = local_500;
                                    phi_4945_ = _e5435;
                                    phi_4948_ = _e5437;
                                    phi_6670_ = _e5290;
                                    break if !(_e5438);
                                }
                            }
                            let _e5441 = phi_6670_;
                            if _e5441 {
                                break;
                            }
                            let _e5442 = local_441;
                            let _e5444 = local_495;
                            let _e5446 = local_499;
                            let _e5447 = local_495;
                            phi_6683_ = _e5441;
                            phi_4998_ = (_e5442[2] * _e5444);
                            phi_4999_ = (_e5446 * _e5447);
                            phi_5000_ = array<f32, 2>(_e5383, _e5386);
                        } else {
                            let _e5377 = local_485;
                            phi_6683_ = _e5290;
                            phi_4998_ = (2f * _e5377);
                            phi_4999_ = 0f;
                            phi_5000_ = array<f32, 2>((_e5365[0] * _e5367), (_e5369[1] * _e5371));
                        }
                        let _e5450 = phi_6683_;
                        let _e5452 = phi_4998_;
                        let _e5454 = phi_4999_;
                        let _e5456 = phi_5000_;
                        let _e5457 = local_491;
                        let _e5458 = local_493;
                        let _e5459 = local_492;
                        let _e5460 = local_490;
                        let _e5461 = local_620;
                        let _e5462 = local_449;
                        let _e5463 = local_442;
                        phi_6682_ = _e5450;
                        phi_5002_ = type_30(_e5456, _e5457, _e5458, _e5459, _e5460, _e5461, _e5462, _e5463, _e5452, _e5454);
                    }
                    let _e5469 = phi_6682_;
                    let _e5471 = phi_5002_;
                    local_503 = _e5471;
                    let _e5472 = local_22;
                    let _e5473 = local_17;
                    let _e5475 = local_21;
                    local_504 = (9u * ((_e5472 * _e5473) + _e5475));
                    local_637[0u] = _e5471.member_1[0];
                    local_637[1u] = _e5471.member_1[1];
                    local_637[2u] = _e5471.member_1[2];
                    local_637[3u] = _e5471.member_2;
                    local_637[4u] = _e5471.member_4[0];
                    local_637[5u] = _e5471.member_4[1];
                    local_637[6u] = _e5471.member_4[2];
                    local_637[7u] = _e5471.member_3;
                    local_637[8u] = _e5471.member_5;
                    phi_5025_ = 0u;
                    loop {
                        let _e5503 = phi_5025_;
                        local_505 = _e5503;
                        let _e5504 = local_505;
                        let _e5505 = (_e5504 < 9u);
                        local_506 = _e5505;
                        if _e5505 {
                            let _e5506 = local_504;
                            let _e5507 = local_505;
                            local_507 = (_e5506 + _e5507);
                            let _e5509 = local_506;
                            if _e5509 {
                            } else {
                                phi_6679_ = true;
                                break;
                            }
                            let _e5510 = local_505;
                            let _e5512 = local_637[_e5510];
                            local_508 = bitcast<u32>(_e5512);
                            let _e5514 = local_507;
                            let _e5515 = local_7;
                            if (_e5514 < _e5515) {
                            } else {
                                phi_6679_ = true;
                                break;
                            }
                            let _e5517 = local_507;
                            let _e5520 = local_508;
                            global_5.member[_e5517] = _e5520;
                            let _e5521 = local_505;
                            phi_5026_ = (_e5521 + 1u);
                        } else {
                            phi_5026_ = u32();
                        }
                        let _e5524 = phi_5026_;
                        continue;
                        continuing {
                            let _e5525 = local_506;
                            phi_5025_ = _e5524;
                            phi_6679_ = _e5469;
                            break if !(_e5525);
                        }
                    }
                    let _e5528 = phi_6679_;
                    if _e5528 {
                        break;
                    }
                    let _e5529 = local_503;
                    local_509 = _e5529.member_8;
                    if (_e5529.member_8 < 0f) {
                        let _e5536 = local_509;
                        let _e5538 = local_509;
                        phi_5065_ = select(-0.5f, _e5538, (_e5536 < -0.5f));
                    } else {
                        let _e5532 = local_509;
                        let _e5534 = local_509;
                        phi_5065_ = select(0.5f, _e5534, (_e5532 > 0.5f));
                    }
                    let _e5541 = phi_5065_;
                    local_510 = _e5541;
                    let _e5542 = local_503;
                    local_511 = _e5542.member[0];
                    let _e5545 = local_503;
                    local_512 = _e5545.member[1];
                    if (_e5541 < 0f) {
                        let _e5549 = local_510;
                        phi_5073_ = -(_e5549);
                    } else {
                        phi_5073_ = _e5541;
                    }
                    let _e5552 = phi_5073_;
                    let _e5553 = local_503;
                    local_513 = _e5553.member_9;
                    let _e5556 = ((_e5552 + 0.5f) + _e5553.member_9);
                    local_579 = _e5556;
                    local_580 = ((_e5552 - 0.5f) - _e5553.member_9);
                    let _e5559 = local_512;
                    let _e5562 = local_512;
                    local_581 = floor((_e5562 + _e5556));
                    phi_5755_ = floor((_e5559 - _e5556));
                    phi_5756_ = 0f;
                    loop {
                        let _e5566 = phi_5755_;
                        let _e5568 = phi_5756_;
                        local_582 = _e5566;
                        local_583 = _e5568;
                        let _e5569 = local_582;
                        let _e5570 = local_581;
                        let _e5571 = (_e5569 <= _e5570);
                        local_584 = _e5571;
                        if _e5571 {
                            let _e5572 = local_582;
                            let _e5574 = local_512;
                            let _e5575 = ((_e5572 + 0.5f) - _e5574);
                            let _e5576 = local_579;
                            let _e5577 = local_579;
                            let _e5579 = (_e5575 * _e5575);
                            local_585 = _e5579;
                            let _e5580 = ((_e5576 * _e5577) - _e5579);
                            local_586 = _e5580;
                            if (_e5580 > 0f) {
                                let _e5582 = local_586;
                                local_587 = sqrt(_e5582);
                                let _e5584 = local_580;
                                if (_e5584 > 0f) {
                                    let _e5586 = local_580;
                                    let _e5587 = local_580;
                                    let _e5589 = local_585;
                                    phi_5777_ = ((_e5586 * _e5587) - _e5589);
                                } else {
                                    phi_5777_ = -1f;
                                }
                                let _e5592 = phi_5777_;
                                local_588 = _e5592;
                                if (_e5592 > 0f) {
                                    let _e5594 = local_588;
                                    let _e5595 = sqrt(_e5594);
                                    let _e5596 = local_511;
                                    let _e5600 = local_511;
                                    phi_5789_ = floor(((_e5600 + _e5595) - 0.5f));
                                    phi_5790_ = ceil(((_e5596 - _e5595) - 0.5f));
                                } else {
                                    phi_5789_ = 0f;
                                    phi_5790_ = 1f;
                                }
                                let _e5605 = phi_5789_;
                                let _e5607 = phi_5790_;
                                local_589 = _e5605;
                                local_590 = _e5607;
                                if (_e5605 >= _e5607) {
                                    let _e5609 = local_589;
                                    let _e5610 = local_590;
                                    let _e5613 = local_583;
                                    phi_5798_ = (_e5613 + ((_e5609 - _e5610) + 1f));
                                } else {
                                    phi_5798_ = _e5568;
                                }
                                let _e5616 = phi_5798_;
                                let _e5617 = local_511;
                                let _e5618 = local_587;
                                let _e5622 = local_511;
                                let _e5623 = local_587;
                                local_591 = ceil(((_e5622 + _e5623) - 0.5f));
                                phi_5806_ = floor(((_e5617 - _e5618) - 0.5f));
                                phi_5807_ = _e5616;
                                loop {
                                    let _e5628 = phi_5806_;
                                    let _e5630 = phi_5807_;
                                    local_592 = _e5628;
                                    local_593 = _e5630;
                                    local_669 = _e5630;
                                    let _e5631 = local_592;
                                    let _e5632 = local_591;
                                    let _e5633 = (_e5631 <= _e5632);
                                    local_594 = _e5633;
                                    if _e5633 {
                                        let _e5634 = local_592;
                                        let _e5635 = local_590;
                                        if (_e5634 < _e5635) {
                                            phi_5820_ = true;
                                        } else {
                                            let _e5637 = local_592;
                                            let _e5638 = local_589;
                                            phi_5820_ = (_e5637 > _e5638);
                                        }
                                        let _e5641 = phi_5820_;
                                        if _e5641 {
                                            let _e5642 = local_592;
                                            let _e5644 = local_511;
                                            let _e5645 = ((_e5642 + 0.5f) - _e5644);
                                            let _e5647 = local_585;
                                            let _e5650 = local_513;
                                            let _e5653 = local_579;
                                            let _e5655 = ((_e5653 - sqrt(((_e5645 * _e5645) + _e5647))) / (1f + (2f * _e5650)));
                                            let _e5660 = local_593;
                                            phi_5847_ = (_e5660 + select(0f, select(1f, _e5655, (_e5655 < 1f)), (0f < _e5655)));
                                        } else {
                                            phi_5847_ = _e5630;
                                        }
                                        let _e5663 = phi_5847_;
                                        let _e5664 = local_592;
                                        phi_5850_ = (_e5664 + 1f);
                                        phi_5851_ = _e5663;
                                    } else {
                                        phi_5850_ = f32();
                                        phi_5851_ = f32();
                                    }
                                    let _e5667 = phi_5850_;
                                    let _e5669 = phi_5851_;
                                    continue;
                                    continuing {
                                        let _e5670 = local_594;
                                        phi_5806_ = _e5667;
                                        phi_5807_ = _e5669;
                                        break if !(_e5670);
                                    }
                                }
                                let _e6910 = local_669;
                                phi_5855_ = _e6910;
                            } else {
                                phi_5855_ = _e5568;
                            }
                            let _e5673 = phi_5855_;
                            let _e5674 = local_582;
                            phi_5858_ = (_e5674 + 1f);
                            phi_5859_ = _e5673;
                        } else {
                            phi_5858_ = f32();
                            phi_5859_ = f32();
                        }
                        let _e5677 = phi_5858_;
                        let _e5679 = phi_5859_;
                        continue;
                        continuing {
                            let _e5680 = local_584;
                            phi_5755_ = _e5677;
                            phi_5756_ = _e5679;
                            break if !(_e5680);
                        }
                    }
                    let _e5682 = local_583;
                    local_514 = (1f / _e5682);
                    let _e5684 = local_367;
                    let _e5686 = local_369;
                    let _e5689 = ((_e5684 + 2u) + (8u * (_e5686 - 1u)));
                    local_515 = _e5689;
                    let _e5690 = local_511;
                    local_516 = bitcast<u32>(_e5690);
                    let _e5692 = local_9;
                    if (_e5689 < _e5692) {
                    } else {
                        break;
                    }
                    let _e5694 = local_515;
                    let _e5697 = local_516;
                    global_7.member[_e5694] = _e5697;
                    let _e5698 = local_515;
                    let _e5699 = (_e5698 + 1u);
                    local_517 = _e5699;
                    let _e5700 = local_512;
                    local_518 = bitcast<u32>(_e5700);
                    let _e5702 = local_9;
                    if (_e5699 < _e5702) {
                    } else {
                        break;
                    }
                    let _e5704 = local_517;
                    let _e5707 = local_518;
                    global_7.member[_e5704] = _e5707;
                    let _e5708 = local_515;
                    let _e5709 = (_e5708 + 2u);
                    local_519 = _e5709;
                    let _e5710 = local_510;
                    local_520 = bitcast<u32>(_e5710);
                    let _e5712 = local_9;
                    if (_e5709 < _e5712) {
                    } else {
                        break;
                    }
                    let _e5714 = local_519;
                    let _e5717 = local_520;
                    global_7.member[_e5714] = _e5717;
                    let _e5718 = local_515;
                    let _e5719 = (_e5718 + 3u);
                    local_521 = _e5719;
                    let _e5720 = local_503;
                    let _e5723 = local_514;
                    local_522 = bitcast<u32>((_e5720.member_7[0] * _e5723));
                    let _e5726 = local_9;
                    if (_e5719 < _e5726) {
                    } else {
                        break;
                    }
                    let _e5728 = local_521;
                    let _e5731 = local_522;
                    global_7.member[_e5728] = _e5731;
                    let _e5732 = local_515;
                    let _e5733 = (_e5732 + 4u);
                    local_523 = _e5733;
                    let _e5734 = local_503;
                    let _e5737 = local_514;
                    local_524 = bitcast<u32>((_e5734.member_7[1] * _e5737));
                    let _e5740 = local_9;
                    if (_e5733 < _e5740) {
                    } else {
                        break;
                    }
                    let _e5742 = local_523;
                    let _e5745 = local_524;
                    global_7.member[_e5742] = _e5745;
                    let _e5746 = local_515;
                    let _e5747 = (_e5746 + 5u);
                    local_525 = _e5747;
                    let _e5748 = local_503;
                    let _e5751 = local_514;
                    local_526 = bitcast<u32>((_e5748.member_7[2] * _e5751));
                    let _e5754 = local_9;
                    if (_e5747 < _e5754) {
                    } else {
                        break;
                    }
                    let _e5756 = local_525;
                    let _e5759 = local_526;
                    global_7.member[_e5756] = _e5759;
                    let _e5760 = local_515;
                    let _e5761 = (_e5760 + 6u);
                    local_527 = _e5761;
                    let _e5762 = local_513;
                    local_528 = bitcast<u32>(_e5762);
                    let _e5764 = local_9;
                    if (_e5761 < _e5764) {
                    } else {
                        break;
                    }
                    let _e5766 = local_527;
                    let _e5769 = local_528;
                    global_7.member[_e5766] = _e5769;
                    let _e5770 = local_515;
                    let _e5771 = (_e5770 + 7u);
                    local_529 = _e5771;
                    let _e5772 = local_9;
                    if (_e5771 < _e5772) {
                    } else {
                        break;
                    }
                    let _e5774 = local_529;
                    global_7.member[_e5774] = 0u;
                    phi_6697_ = _e5528;
                    phi_5150_ = type_31(array<f32, 4>(_e4703[0], _e4703[1], _e4703[2], _e4703[3]), array<f32, 3>(_e4698, _e4700, _e4702));
                } else {
                    phi_6697_ = _e3956;
                    phi_5150_ = type_31(array<f32, 4>(0f, 0f, 0f, 0f), array<f32, 3>(0f, 0f, 0f));
                }
                let _e5778 = phi_6697_;
                let _e5780 = phi_5150_;
                phi_6696_ = _e5778;
                phi_5151_ = _e5780;
            } else {
                phi_6696_ = _e3956;
                phi_5151_ = type_31(array<f32, 4>(0f, 0f, 0f, 0f), array<f32, 3>(0f, 0f, 0f));
            }
            let _e5782 = phi_6696_;
            let _e5784 = phi_5151_;
            local_530 = _e5784;
            let _e5785 = local_23;
            if _e5785 {
                let _e5786 = local_22;
                let _e5787 = local_20;
                if (_e5786 < _e5787) {
                    let _e5789 = local_530;
                    let _e5795 = array<f32, 4>(_e5789.member[0], _e5789.member[1], _e5789.member[2], _e5789.member[3]);
                    local_531 = _e5795;
                    local_631 = _e5795;
                    phi_6695_ = _e5782;
                    phi_5173_ = 0u;
                    loop {
                        let _e5797 = phi_6695_;
                        let _e5799 = phi_5173_;
                        local_532 = _e5799;
                        let _e5800 = local_532;
                        let _e5801 = (_e5800 < 4u);
                        local_533 = _e5801;
                        if _e5801 {
                            let _e5802 = local_21;
                            let _e5804 = local_532;
                            let _e5806 = ((2u * _e5802) + (_e5804 % 2u));
                            local_534 = _e5806;
                            let _e5807 = local_22;
                            let _e5809 = local_532;
                            local_535 = ((2u * _e5807) + (_e5809 / 2u));
                            let _e5812 = local_14;
                            if (_e5806 < _e5812) {
                                let _e5814 = local_535;
                                let _e5815 = local_18;
                                if (_e5814 < _e5815) {
                                    let _e5817 = local_535;
                                    let _e5818 = local_14;
                                    let _e5820 = local_534;
                                    let _e5821 = ((_e5817 * _e5818) + _e5820);
                                    local_536 = _e5821;
                                    let _e5822 = (3u * _e5821);
                                    local_537 = _e5822;
                                    let _e5823 = local_5;
                                    let _e5824 = (_e5822 < _e5823);
                                    local_538 = _e5824;
                                    if _e5824 {
                                    } else {
                                        phi_6731_ = true;
                                        break;
                                    }
                                    let _e5825 = local_537;
                                    let _e5828 = global_4.member[_e5825];
                                    local_539 = _e5828;
                                    let _e5829 = local_537;
                                    let _e5830 = (_e5829 + 1u);
                                    local_540 = _e5830;
                                    let _e5831 = local_5;
                                    let _e5832 = (_e5830 < _e5831);
                                    local_541 = _e5832;
                                    if _e5832 {
                                    } else {
                                        phi_6731_ = true;
                                        break;
                                    }
                                    let _e5833 = local_540;
                                    let _e5836 = global_4.member[_e5833];
                                    local_542 = _e5836;
                                    let _e5837 = local_537;
                                    let _e5838 = (_e5837 + 2u);
                                    local_543 = _e5838;
                                    let _e5839 = local_5;
                                    let _e5840 = (_e5838 < _e5839);
                                    local_544 = _e5840;
                                    if _e5840 {
                                    } else {
                                        phi_6731_ = true;
                                        break;
                                    }
                                    let _e5841 = local_543;
                                    let _e5844 = global_4.member[_e5841];
                                    local_545 = _e5844;
                                    let _e5845 = local_539;
                                    let _e5846 = local_542;
                                    let _e5847 = array<u32, 3>(_e5845, _e5846, _e5844);
                                    let _e5848 = local_533;
                                    if _e5848 {
                                    } else {
                                        phi_6731_ = true;
                                        break;
                                    }
                                    let _e5849 = local_532;
                                    let _e5851 = local_631[_e5849];
                                    if (_e5851 > 0f) {
                                        let _e5853 = local_538;
                                        if _e5853 {
                                        } else {
                                            phi_6731_ = true;
                                            break;
                                        }
                                        let _e5854 = local_539;
                                        local_546 = bitcast<f32>(_e5854);
                                        let _e5856 = local_541;
                                        if _e5856 {
                                        } else {
                                            phi_6731_ = true;
                                            break;
                                        }
                                        let _e5857 = local_542;
                                        local_547 = bitcast<f32>(_e5857);
                                        let _e5859 = local_544;
                                        if _e5859 {
                                        } else {
                                            phi_6731_ = true;
                                            break;
                                        }
                                        let _e5860 = local_545;
                                        local_548 = bitcast<f32>(_e5860);
                                        let _e5862 = local_546;
                                        if (_e5862 > 1267650600000000000000000000000f) {
                                            let _e5864 = local_546;
                                            phi_5280_ = select(true, false, (_e5864 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_5280_ = true;
                                        }
                                        let _e5868 = phi_5280_;
                                        if _e5868 {
                                            let _e5869 = local_546;
                                            if (_e5869 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e5871 = local_546;
                                                phi_5294_ = select(true, false, (_e5871 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_5294_ = true;
                                            }
                                            let _e5875 = phi_5294_;
                                            let _e5876 = local_546;
                                            phi_5299_ = select(0f, _e5876, _e5875);
                                        } else {
                                            phi_5299_ = 1267650600000000000000000000000f;
                                        }
                                        let _e5879 = phi_5299_;
                                        local_549 = _e5879;
                                        let _e5880 = local_547;
                                        if (_e5880 > 1267650600000000000000000000000f) {
                                            let _e5882 = local_547;
                                            phi_5309_ = select(true, false, (_e5882 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_5309_ = true;
                                        }
                                        let _e5886 = phi_5309_;
                                        if _e5886 {
                                            let _e5887 = local_547;
                                            if (_e5887 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e5889 = local_547;
                                                phi_5323_ = select(true, false, (_e5889 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_5323_ = true;
                                            }
                                            let _e5893 = phi_5323_;
                                            let _e5894 = local_547;
                                            phi_5328_ = select(0f, _e5894, _e5893);
                                        } else {
                                            phi_5328_ = 1267650600000000000000000000000f;
                                        }
                                        let _e5897 = phi_5328_;
                                        local_550 = _e5897;
                                        let _e5898 = local_548;
                                        if (_e5898 > 1267650600000000000000000000000f) {
                                            let _e5900 = local_548;
                                            phi_5338_ = select(true, false, (_e5900 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_5338_ = true;
                                        }
                                        let _e5904 = phi_5338_;
                                        if _e5904 {
                                            let _e5905 = local_548;
                                            if (_e5905 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e5907 = local_548;
                                                phi_5352_ = select(true, false, (_e5907 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_5352_ = true;
                                            }
                                            let _e5911 = phi_5352_;
                                            let _e5912 = local_548;
                                            phi_5357_ = select(0f, _e5912, _e5911);
                                        } else {
                                            phi_5357_ = 1267650600000000000000000000000f;
                                        }
                                        let _e5915 = phi_5357_;
                                        local_551 = _e5915;
                                        let _e5916 = local_549;
                                        let _e5917 = local_550;
                                        local_552 = array<f32, 3>(_e5916, _e5917, _e5915);
                                        let _e5919 = local_536;
                                        let _e5920 = local_6;
                                        if (_e5919 < _e5920) {
                                        } else {
                                            phi_6731_ = true;
                                            break;
                                        }
                                        let _e5922 = local_536;
                                        let _e5925 = global_3.member[_e5922];
                                        local_553 = bitcast<f32>(_e5925);
                                        let _e5927 = local_549;
                                        if ((bitcast<u32>(_e5927) & 2139095040u) != 2139095040u) {
                                            let _e5931 = local_550;
                                            if ((bitcast<u32>(_e5931) & 2139095040u) != 2139095040u) {
                                                let _e5935 = local_551;
                                                if ((bitcast<u32>(_e5935) & 2139095040u) != 2139095040u) {
                                                    let _e5939 = local_553;
                                                    let _e5940 = bitcast<u32>(_e5939);
                                                    local_554 = _e5940;
                                                    if (_e5940 == 0u) {
                                                        phi_5391_ = false;
                                                    } else {
                                                        let _e5942 = local_554;
                                                        phi_5391_ = (_e5942 <= 2139095040u);
                                                    }
                                                    let _e5945 = phi_5391_;
                                                    local_555 = _e5945;
                                                    if _e5945 {
                                                        let _e5946 = local_552;
                                                        let _e5947 = local_553;
                                                        phi_5397_ = type_23(1u, type_22(_e5946, _e5947));
                                                    } else {
                                                        phi_5397_ = type_23();
                                                    }
                                                    let _e5951 = phi_5397_;
                                                    let _e5952 = local_555;
                                                    phi_5399_ = _e5951;
                                                    phi_5400_ = select(true, false, _e5952);
                                                } else {
                                                    phi_5399_ = type_23();
                                                    phi_5400_ = true;
                                                }
                                                let _e5955 = phi_5399_;
                                                let _e5957 = phi_5400_;
                                                phi_5401_ = _e5955;
                                                phi_5402_ = _e5957;
                                            } else {
                                                phi_5401_ = type_23();
                                                phi_5402_ = true;
                                            }
                                            let _e5959 = phi_5401_;
                                            let _e5961 = phi_5402_;
                                            phi_5403_ = _e5959;
                                            phi_5404_ = _e5961;
                                        } else {
                                            phi_5403_ = type_23();
                                            phi_5404_ = true;
                                        }
                                        let _e5963 = phi_5403_;
                                        let _e5965 = phi_5404_;
                                        if _e5965 {
                                            phi_5409_ = type_23(0u, type_23().member_1);
                                        } else {
                                            phi_5409_ = _e5963;
                                        }
                                        let _e5970 = phi_5409_;
                                        local_556 = _e5970;
                                        if (bitcast<i32>(_e5970.member) != 0i) {
                                            let _e5974 = local_556;
                                            local_634 = array<f32, 3>(_e5974.member_1.member[0], _e5974.member_1.member[1], _e5974.member_1.member[2]);
                                            let _e5981 = local_530;
                                            let _e5987 = local_531;
                                            local_633 = _e5987;
                                            local_632 = array<f32, 3>(_e5981.member_1[0], _e5981.member_1[1], _e5981.member_1[2]);
                                            let _e5988 = local_533;
                                            if _e5988 {
                                            } else {
                                                phi_6731_ = true;
                                                break;
                                            }
                                            let _e5989 = local_532;
                                            let _e5991 = local_633[_e5989];
                                            local_557 = _e5991;
                                            if (_e5991 <= 0f) {
                                                let _e6052 = local_634;
                                                phi_6737_ = _e5797;
                                                phi_5536_ = type_25(array<f32, 3>(_e6052[0], _e6052[1], _e6052[2]), array<f32, 3>(0f, 0f, 0f));
                                            } else {
                                                let _e5993 = local_634;
                                                local_635 = _e5993;
                                                local_636 = array<f32, 3>(0f, 0f, 0f);
                                                phi_5464_ = 0u;
                                                loop {
                                                    let _e5995 = phi_5464_;
                                                    local_558 = _e5995;
                                                    let _e5996 = local_558;
                                                    let _e5997 = (_e5996 < 3u);
                                                    local_559 = _e5997;
                                                    if _e5997 {
                                                        let _e5998 = local_559;
                                                        if _e5998 {
                                                        } else {
                                                            phi_6684_ = true;
                                                            break;
                                                        }
                                                        let _e5999 = local_558;
                                                        let _e6001 = local_632[_e5999];
                                                        local_560 = _e6001;
                                                        let _e6002 = local_559;
                                                        if _e6002 {
                                                        } else {
                                                            phi_6684_ = true;
                                                            break;
                                                        }
                                                        let _e6003 = local_558;
                                                        let _e6005 = local_634[_e6003];
                                                        let _e6006 = local_560;
                                                        if (_e6005 > _e6006) {
                                                            let _e6008 = local_559;
                                                            if _e6008 {
                                                            } else {
                                                                phi_6684_ = true;
                                                                break;
                                                            }
                                                            let _e6009 = local_634[_e6003];
                                                            let _e6010 = local_560;
                                                            local_561 = (_e6009 - _e6010);
                                                            let _e6012 = local_559;
                                                            if _e6012 {
                                                            } else {
                                                                phi_6684_ = true;
                                                                break;
                                                            }
                                                            let _e6013 = local_558;
                                                            let _e6015 = local_557;
                                                            let _e6016 = local_561;
                                                            local_636[_e6013] = (_e6015 * _e6016);
                                                            let _e6018 = local_557;
                                                            local_562 = (1f - _e6018);
                                                            let _e6020 = local_559;
                                                            if _e6020 {
                                                            } else {
                                                                phi_6684_ = true;
                                                                break;
                                                            }
                                                            let _e6021 = local_634[_e6003];
                                                            let _e6022 = local_562;
                                                            local_563 = (_e6022 * _e6021);
                                                            let _e6024 = local_557;
                                                            let _e6025 = local_560;
                                                            local_564 = (_e6024 * _e6025);
                                                            let _e6027 = local_559;
                                                            if _e6027 {
                                                            } else {
                                                                phi_6684_ = true;
                                                                break;
                                                            }
                                                            let _e6028 = local_558;
                                                            let _e6030 = local_563;
                                                            let _e6031 = local_564;
                                                            local_635[_e6028] = (_e6030 + _e6031);
                                                        }
                                                        let _e6033 = local_558;
                                                        phi_5465_ = (_e6033 + 1u);
                                                    } else {
                                                        phi_5465_ = u32();
                                                    }
                                                    let _e6036 = phi_5465_;
                                                    continue;
                                                    continuing {
                                                        let _e6037 = local_559;
                                                        phi_5464_ = _e6036;
                                                        phi_6684_ = _e5797;
                                                        break if !(_e6037);
                                                    }
                                                }
                                                let _e6040 = phi_6684_;
                                                phi_6731_ = _e6040;
                                                if _e6040 {
                                                    break;
                                                }
                                                let _e6041 = local_635;
                                                let _e6046 = local_636;
                                                phi_6737_ = _e6040;
                                                phi_5536_ = type_25(array<f32, 3>(_e6041[0], _e6041[1], _e6041[2]), array<f32, 3>(_e6046[0], _e6046[1], _e6046[2]));
                                            }
                                            let _e6059 = phi_6737_;
                                            let _e6061 = phi_5536_;
                                            phi_6736_ = _e6059;
                                            phi_5545_ = array<u32, 3>(bitcast<u32>(_e6061.member[0]), bitcast<u32>(_e6061.member[1]), bitcast<u32>(_e6061.member[2]));
                                        } else {
                                            phi_6736_ = _e5797;
                                            phi_5545_ = _e5847;
                                        }
                                        let _e6071 = phi_6736_;
                                        let _e6073 = phi_5545_;
                                        phi_6735_ = _e6071;
                                        phi_5546_ = _e6073;
                                    } else {
                                        phi_6735_ = _e5797;
                                        phi_5546_ = _e5847;
                                    }
                                    let _e6075 = phi_6735_;
                                    let _e6077 = phi_5546_;
                                    local_565 = _e6077;
                                    local_566 = _e6077[0];
                                    let _e6079 = local_537;
                                    let _e6080 = local_10;
                                    if (_e6079 < _e6080) {
                                    } else {
                                        phi_6731_ = true;
                                        break;
                                    }
                                    let _e6082 = local_537;
                                    let _e6085 = local_566;
                                    global_8.member[_e6082] = _e6085;
                                    let _e6086 = local_565;
                                    local_567 = _e6086[1];
                                    let _e6088 = local_540;
                                    let _e6089 = local_10;
                                    if (_e6088 < _e6089) {
                                    } else {
                                        phi_6731_ = true;
                                        break;
                                    }
                                    let _e6091 = local_540;
                                    let _e6094 = local_567;
                                    global_8.member[_e6091] = _e6094;
                                    let _e6095 = local_565;
                                    local_568 = _e6095[2];
                                    let _e6097 = local_543;
                                    let _e6098 = local_10;
                                    if (_e6097 < _e6098) {
                                    } else {
                                        phi_6731_ = true;
                                        break;
                                    }
                                    let _e6100 = local_543;
                                    let _e6103 = local_568;
                                    global_8.member[_e6100] = _e6103;
                                    phi_6734_ = _e6075;
                                } else {
                                    phi_6734_ = _e5797;
                                }
                                let _e6105 = phi_6734_;
                                phi_6733_ = _e6105;
                            } else {
                                phi_6733_ = _e5797;
                            }
                            let _e6107 = phi_6733_;
                            let _e6108 = local_532;
                            phi_6732_ = _e6107;
                            phi_5174_ = (_e6108 + 1u);
                        } else {
                            phi_6732_ = _e5797;
                            phi_5174_ = u32();
                        }
                        let _e6111 = phi_6732_;
                        let _e6113 = phi_5174_;
                        continue;
                        continuing {
                            let _e6114 = local_533;
                            phi_6695_ = _e6111;
                            phi_5173_ = _e6113;
                            phi_6731_ = _e6111;
                            break if !(_e6114);
                        }
                    }
                    let _e6117 = phi_6731_;
                    if _e6117 {
                        break;
                    }
                }
            }
            let _e6118 = local;
            if (_e6118 == 63u) {
                let _e6120 = local_16;
                if _e6120 {
                    let _e6121 = local_15;
                    phi_5595_ = (_e6121 + 1u);
                } else {
                    phi_5595_ = _e756;
                }
                let _e6124 = phi_5595_;
                let _e6125 = (_e6124 / 8u);
                local_569 = _e6125;
                if ((_e6124 % 8u) > 0u) {
                    let _e6128 = local_569;
                    phi_5611_ = (_e6128 + 1u);
                } else {
                    phi_5611_ = _e6125;
                }
                let _e6131 = phi_5611_;
                let _e6132 = local_13;
                let _e6134 = local_12;
                local_570 = ((_e6132 * _e6131) + _e6134);
                let _e6136 = local_321;
                let _e6137 = (_e6136 + 63u);
                local_571 = _e6137;
                if (_e6137 < 384u) {
                } else {
                    break;
                }
                let _e6139 = local_571;
                let _e6141 = global_10[_e6139];
                local_572 = _e6141;
                let _e6142 = local_570;
                let _e6143 = local_8;
                if (_e6142 < _e6143) {
                } else {
                    break;
                }
                let _e6145 = local_570;
                let _e6148 = local_572;
                global_6.member[_e6145] = _e6148;
                let _e6149 = local_277;
                let _e6150 = (_e6149 + 63u);
                local_573 = _e6150;
                if (_e6150 < 384u) {
                } else {
                    break;
                }
                let _e6152 = local_573;
                let _e6154 = global_10[_e6152];
                local_574 = _e6154;
                local_621 = select(8u, _e6154, (_e6154 < 8u));
                let _e6157 = local_367;
                let _e6158 = local_9;
                if (_e6157 < _e6158) {
                } else {
                    break;
                }
                let _e6160 = local_367;
                let _e6163 = local_621;
                global_7.member[_e6160] = _e6163;
                let _e6164 = local_367;
                local_575 = (_e6164 + 1u);
                let _e6166 = local_365;
                let _e6167 = (_e6166 + 63u);
                local_576 = _e6167;
                if (_e6167 < 384u) {
                } else {
                    break;
                }
                let _e6169 = local_576;
                let _e6171 = global_10[_e6169];
                local_577 = _e6171;
                let _e6172 = local_575;
                let _e6173 = local_9;
                if (_e6172 < _e6173) {
                } else {
                    break;
                }
                let _e6175 = local_575;
                let _e6178 = local_577;
                global_7.member[_e6175] = _e6178;
                let _e6179 = local_574;
                if (_e6179 > 8u) {
                    let _e6181 = local_574;
                    local_578 = (_e6181 - 8u);
                    let _e6183 = local_11;
                    if (1u < _e6183) {
                    } else {
                        break;
                    }
                    let _e6187 = local_578;
                    let _e6188 = atomicAdd((&global_9.member[1u]), _e6187);
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
fn subgroups(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(subgroup_size) param_2: u32, @builtin(num_subgroups) param_3: u32, @builtin(subgroup_id) param_4: u32, @builtin(subgroup_invocation_id) param_5: u32) {
    global = param;
    global_1 = param_1;
    global_11 = param_2;
    global_12 = param_3;
    global_13 = param_4;
    global_14 = param_5;
    function_();
}
