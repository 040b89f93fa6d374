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
}

struct type_23 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
}

struct type_28 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: array<f32, 3>,
    member_3: f32,
    member_4: array<f32, 3>,
    member_5: f32,
    member_6: array<f32, 3>,
    member_7: f32,
}

struct type_29 {
    member: type_28,
    member_1: array<f32, 3>,
    member_2: u32,
    member_3: type_5,
    member_4: f32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: array<f32, 4>,
}

struct type_30 {
    member: type_29,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_30;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage> global_6: type_7;
@group(0) @binding(3) 
var<storage> global_7: type_7;
@group(0) @binding(4) 
var<storage> global_8: type_7;
@group(0) @binding(5) 
var<storage> global_9: type_7;
@group(0) @binding(6) 
var<storage, read_write> global_10: type_7;
@group(0) @binding(7) 
var<storage, read_write> global_11: type_7;
var<private> global_12: u32 = 2143289344u;
var<private> global_13: u32 = 2139095040u;

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
    var local_16: bool;
    var local_17: u32;
    var local_18: f32;
    var local_19: u32;
    var local_20: f32;
    var local_21: u32;
    var local_22: f32;
    var local_23: array<f32, 3>;
    var local_24: array<f32, 4>;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: array<u32, 4>;
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
    var local_49: u32;
    var local_50: f32;
    var local_51: u32;
    var local_52: f32;
    var local_53: u32;
    var local_54: f32;
    var local_55: u32;
    var local_56: u32;
    var local_57: bool;
    var local_58: u32;
    var local_59: u32;
    var local_60: bool;
    var local_61: f32;
    var local_62: f32;
    var local_63: f32;
    var local_64: u32;
    var local_65: f32;
    var local_66: f32;
    var local_67: f32;
    var local_68: f32;
    var local_69: f32;
    var local_70: f32;
    var local_71: f32;
    var local_72: array<f32, 3>;
    var local_73: f32;
    var local_74: f32;
    var local_75: f32;
    var local_76: array<f32, 3>;
    var local_77: u32;
    var local_78: f32;
    var local_79: f32;
    var local_80: bool;
    var local_81: u32;
    var local_82: f32;
    var local_83: u32;
    var local_84: f32;
    var local_85: u32;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: u32;
    var local_91: u32;
    var local_92: u32;
    var local_93: f32;
    var local_94: u32;
    var local_95: f32;
    var local_96: u32;
    var local_97: u32;
    var local_98: f32;
    var local_99: u32;
    var local_100: f32;
    var local_101: u32;
    var local_102: u32;
    var local_103: f32;
    var local_104: u32;
    var local_105: f32;
    var local_106: type_5;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: u32;
    var local_112: u32;
    var local_113: u32;
    var local_114: u32;
    var local_115: f32;
    var local_116: f32;
    var local_117: f32;
    var local_118: f32;
    var local_119: f32;
    var local_120: f32;
    var local_121: f32;
    var local_122: bool;
    var local_123: f32;
    var local_124: u32;
    var local_125: f32;
    var local_126: f32;
    var local_127: u32;
    var local_128: f32;
    var local_129: u32;
    var local_130: u32;
    var local_131: f32;
    var local_132: f32;
    var local_133: u32;
    var local_134: u32;
    var local_135: bool;
    var local_136: f32;
    var local_137: u32;
    var local_138: bool;
    var local_139: u32;
    var local_140: type_5;
    var local_141: bool;
    var local_142: f32;
    var local_143: u32;
    var local_144: bool;
    var local_145: f32;
    var local_146: f32;
    var local_147: u32;
    var local_148: type_5;
    var local_149: bool;
    var local_150: type_23;
    var local_151: f32;
    var local_152: u32;
    var local_153: f32;
    var local_154: u32;
    var local_155: f32;
    var local_156: f32;
    var local_157: f32;
    var local_158: f32;
    var local_159: f32;
    var local_160: i32;
    var local_161: i32;
    var local_162: u32;
    var local_163: i32;
    var local_164: bool;
    var local_165: i32;
    var local_166: bool;
    var local_167: bool;
    var local_168: i32;
    var local_169: i32;
    var local_170: bool;
    var local_171: bool;
    var local_172: i32;
    var local_173: u32;
    var local_174: i32;
    var local_175: i32;
    var local_176: bool;
    var local_177: bool;
    var local_178: i32;
    var local_179: i32;
    var local_180: bool;
    var local_181: bool;
    var local_182: i32;
    var local_183: u32;
    var local_184: u32;
    var local_185: i32;
    var local_186: bool;
    var local_187: i32;
    var local_188: bool;
    var local_189: bool;
    var local_190: i32;
    var local_191: i32;
    var local_192: bool;
    var local_193: bool;
    var local_194: i32;
    var local_195: u32;
    var local_196: i32;
    var local_197: i32;
    var local_198: bool;
    var local_199: bool;
    var local_200: i32;
    var local_201: i32;
    var local_202: bool;
    var local_203: bool;
    var local_204: i32;
    var local_205: u32;
    var local_206: u32;
    var local_207: u32;
    var local_208: u32;
    var local_209: u32;
    var local_210: u32;
    var local_211: u32;
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
    var local_223: f32;
    var local_224: u32;
    var local_225: u32;
    var local_226: u32;
    var local_227: u32;
    var local_228: u32;
    var local_229: u32;
    var local_230: f32;
    var local_231: u32;
    var local_232: u32;
    var local_233: f32;
    var local_234: u32;
    var local_235: u32;
    var local_236: f32;
    var local_237: u32;
    var local_238: u32;
    var local_239: f32;
    var local_240: f32;
    var local_241: f32;
    var local_242: f32;
    var local_243: u32;
    var local_244: u32;
    var local_245: u32;
    var local_246: u32;
    var local_247: u32;
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
    var local_259: f32;
    var local_260: u32;
    var local_261: u32;
    var local_262: u32;
    var local_263: u32;
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
    var local_281: u32;
    var local_282: u32;
    var local_283: f32;
    var local_284: f32;
    var local_285: f32;
    var local_286: f32;
    var local_287: f32;
    var local_288: f32;
    var local_289: f32;
    var local_290: bool;
    var local_291: f32;
    var local_292: u32;
    var local_293: f32;
    var local_294: f32;
    var local_295: u32;
    var local_296: f32;
    var local_297: u32;
    var local_298: u32;
    var local_299: f32;
    var local_300: f32;
    var local_301: u32;
    var local_302: u32;
    var local_303: bool;
    var local_304: f32;
    var local_305: u32;
    var local_306: bool;
    var local_307: u32;
    var local_308: type_5;
    var local_309: bool;
    var local_310: f32;
    var local_311: u32;
    var local_312: bool;
    var local_313: f32;
    var local_314: f32;
    var local_315: u32;
    var local_316: type_5;
    var local_317: bool;
    var local_318: type_23;
    var local_319: f32;
    var local_320: u32;
    var local_321: f32;
    var local_322: u32;
    var local_323: f32;
    var local_324: f32;
    var local_325: f32;
    var local_326: f32;
    var local_327: f32;
    var local_328: i32;
    var local_329: i32;
    var local_330: u32;
    var local_331: i32;
    var local_332: bool;
    var local_333: i32;
    var local_334: bool;
    var local_335: bool;
    var local_336: i32;
    var local_337: i32;
    var local_338: bool;
    var local_339: bool;
    var local_340: i32;
    var local_341: u32;
    var local_342: i32;
    var local_343: i32;
    var local_344: bool;
    var local_345: bool;
    var local_346: i32;
    var local_347: i32;
    var local_348: bool;
    var local_349: bool;
    var local_350: i32;
    var local_351: u32;
    var local_352: u32;
    var local_353: i32;
    var local_354: bool;
    var local_355: i32;
    var local_356: bool;
    var local_357: bool;
    var local_358: i32;
    var local_359: i32;
    var local_360: bool;
    var local_361: bool;
    var local_362: i32;
    var local_363: u32;
    var local_364: i32;
    var local_365: i32;
    var local_366: bool;
    var local_367: bool;
    var local_368: i32;
    var local_369: i32;
    var local_370: bool;
    var local_371: bool;
    var local_372: i32;
    var local_373: u32;
    var local_374: u32;
    var local_375: u32;
    var local_376: u32;
    var local_377: u32;
    var local_378: u32;
    var local_379: u32;
    var local_380: u32;
    var local_381: u32;
    var local_382: f32;
    var local_383: u32;
    var local_384: u32;
    var local_385: f32;
    var local_386: u32;
    var local_387: u32;
    var local_388: f32;
    var local_389: u32;
    var local_390: u32;
    var local_391: f32;
    var local_392: u32;
    var local_393: u32;
    var local_394: u32;
    var local_395: u32;
    var local_396: u32;
    var local_397: u32;
    var local_398: f32;
    var local_399: u32;
    var local_400: u32;
    var local_401: f32;
    var local_402: u32;
    var local_403: u32;
    var local_404: f32;
    var local_405: u32;
    var local_406: u32;
    var local_407: f32;
    var local_408: f32;
    var local_409: f32;
    var local_410: f32;
    var local_411: u32;
    var local_412: u32;
    var local_413: u32;
    var local_414: u32;
    var local_415: u32;
    var local_416: u32;
    var local_417: u32;
    var local_418: f32;
    var local_419: u32;
    var local_420: u32;
    var local_421: f32;
    var local_422: u32;
    var local_423: u32;
    var local_424: f32;
    var local_425: u32;
    var local_426: u32;
    var local_427: f32;
    var local_428: u32;
    var local_429: u32;
    var local_430: u32;
    var local_431: u32;
    var local_432: u32;
    var local_433: u32;
    var local_434: f32;
    var local_435: u32;
    var local_436: u32;
    var local_437: f32;
    var local_438: u32;
    var local_439: u32;
    var local_440: f32;
    var local_441: u32;
    var local_442: u32;
    var local_443: u32;
    var local_444: array<f32, 4>;
    var local_445: bool;
    var local_446: u32;
    var local_447: u32;
    var local_448: u32;
    var local_449: u32;
    var local_450: u32;
    var local_451: f32;
    var local_452: u32;
    var local_453: u32;
    var local_454: f32;
    var local_455: f32;
    var local_456: u32;
    var local_457: u32;
    var local_458: f32;
    var local_459: f32;
    var local_460: u32;
    var local_461: u32;
    var local_462: f32;
    var local_463: f32;
    var local_464: u32;
    var local_465: u32;
    var local_466: u32;
    var local_467: u32;
    var local_468: f32;
    var local_469: u32;
    var local_470: bool;
    var local_471: u32;
    var local_472: f32;
    var local_473: bool;
    var local_474: f32;
    var local_475: f32;
    var local_476: f32;
    var local_477: f32;
    var local_478: u32;
    var local_479: f32;
    var local_480: f32;
    var local_481: u32;
    var local_482: bool;
    var local_483: f32;
    var local_484: f32;
    var local_485: u32;
    var local_486: bool;
    var local_487: u32;
    var local_488: bool;
    var local_489: f32;
    var local_490: u32;
    var local_491: u32;
    var local_492: u32;
    var local_493: u32;
    var local_494: u32;
    var local_495: u32;
    var local_496: u32;
    var local_497: u32;
    var local_498: u32;
    var local_499: u32;
    var local_500: u32;
    var local_501: f32;
    var local_502: f32;
    var local_503: bool;
    var local_504: f32;
    var local_505: u32;
    var local_506: f32;
    var local_507: f32;
    var local_508: f32;
    var local_509: f32;
    var local_510: f32;
    var local_511: f32;
    var local_512: f32;
    var local_513: f32;
    var local_514: f32;
    var local_515: f32;
    var local_516: f32;
    var local_517: f32;
    var local_518: f32;
    var local_519: f32;
    var local_520: f32;
    var local_521: f32;
    var local_522: f32;
    var local_523: f32;
    var local_524: bool;
    var local_525: f32;
    var local_526: f32;
    var local_527: f32;
    var local_528: bool;
    var local_529: f32;
    var local_530: f32;
    var local_531: f32;
    var local_532: f32;
    var local_533: f32;
    var local_534: f32;
    var local_535: u32;
    var local_536: type_23;
    var local_537: bool;
    var local_538: u32;
    var local_539: u32;
    var local_540: type_23;
    var local_541: type_23;
    var local_542: u32;
    var local_543: type_23;
    var local_544: bool;
    var local_545: u32;
    var local_546: u32;
    var local_547: type_23;
    var local_548: type_23;
    var local_549: u32;
    var local_550: type_23;
    var local_551: bool;
    var local_552: u32;
    var local_553: u32;
    var local_554: type_23;
    var local_555: type_23;
    var local_556: u32;
    var local_557: type_23;
    var local_558: bool;
    var local_559: u32;
    var local_560: u32;
    var local_561: type_23;
    var local_562: type_23;
    var local_563: u32;
    var local_564: f32;
    var local_565: f32;
    var local_566: f32;
    var local_567: u32;
    var local_568: u32;
    var local_569: f32;
    var local_570: f32;
    var local_571: f32;
    var local_572: f32;
    var local_573: f32;
    var local_574: f32;
    var local_575: f32;
    var local_576: f32;
    var local_577: f32;
    var local_578: f32;
    var local_579: f32;
    var local_580: f32;
    var local_581: f32;
    var local_582: f32;
    var local_583: f32;
    var local_584: f32;
    var local_585: u32;
    var local_586: f32;
    var local_587: f32;
    var local_588: f32;
    var local_589: u32;
    var local_590: u32;
    var local_591: f32;
    var local_592: f32;
    var local_593: f32;
    var local_594: f32;
    var local_595: f32;
    var local_596: f32;
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
    var local_608: f32;
    var local_609: f32;
    var local_610: f32;
    var local_611: f32;
    var local_612: f32;
    var local_613: f32;
    var local_614: array<u32, 4>;
    var local_615: array<f32, 3>;
    var local_616: array<u32, 4>;
    var local_617: array<f32, 3>;
    var local_618: array<u32, 4>;
    var local_619: array<f32, 3>;
    var local_620: array<array<f32, 3>, 3>;
    var local_621: array<f32, 3>;
    var local_622: array<f32, 3>;
    var local_623: array<f32, 4>;
    var local_624: array<f32, 4>;
    var local_625: array<f32, 4>;
    var local_626: array<f32, 3>;
    var local_627: array<f32, 3>;
    var phi_5740_: bool;
    var phi_279_: u32;
    var phi_4597_: bool;
    var phi_406_: type_22;
    var phi_407_: type_22;
    var phi_408_: bool;
    var phi_409_: type_22;
    var phi_410_: bool;
    var phi_411_: type_22;
    var phi_412_: bool;
    var phi_417_: type_22;
    var phi_5737_: bool;
    var phi_675_: u32;
    var phi_693_: u32;
    var phi_694_: u32;
    var phi_5734_: bool;
    var phi_5745_: bool;
    var phi_676_: u32;
    var phi_5744_: bool;
    var phi_5230_: array<f32, 3>;
    var phi_5204_: array<f32, 3>;
    var phi_855_: array<f32, 3>;
    var phi_886_: array<f32, 3>;
    var phi_904_: u32;
    var phi_907_: f32;
    var phi_909_: f32;
    var phi_905_: u32;
    var phi_908_: f32;
    var phi_910_: f32;
    var phi_5746_: bool;
    var phi_1021_: bool;
    var phi_5323_: f32;
    var phi_5332_: f32;
    var phi_5334_: f32;
    var phi_5440_: type_5;
    var phi_5444_: type_5;
    var phi_5445_: bool;
    var phi_5449_: type_5;
    var phi_1171_: type_5;
    var phi_1281_: bool;
    var phi_1320_: bool;
    var phi_1389_: u32;
    var phi_1413_: u32;
    var phi_1346_: u32;
    var phi_1370_: u32;
    var phi_1414_: u32;
    var phi_1415_: u32;
    var phi_1416_: u32;
    var phi_1417_: u32;
    var phi_1430_: f32;
    var phi_1451_: f32;
    var phi_1467_: f32;
    var phi_5550_: u32;
    var phi_5551_: type_23;
    var phi_5568_: u32;
    var phi_5577_: u32;
    var phi_5582_: u32;
    var phi_5583_: type_23;
    var phi_5589_: u32;
    var phi_5590_: type_23;
    var phi_5607_: u32;
    var phi_5616_: u32;
    var phi_5621_: u32;
    var phi_5622_: type_23;
    var phi_1483_: bool;
    var phi_5800_: bool;
    var phi_1486_: u32;
    var phi_1489_: type_5;
    var phi_5799_: bool;
    var phi_1503_: u32;
    var phi_1506_: type_5;
    var phi_1532_: u32;
    var phi_1535_: type_5;
    var phi_1548_: type_23;
    var phi_1549_: f32;
    var phi_1569_: f32;
    var phi_1570_: f32;
    var phi_1641_: i32;
    var phi_1665_: i32;
    var phi_1605_: i32;
    var phi_1606_: i32;
    var phi_1666_: i32;
    var phi_1721_: i32;
    var phi_1745_: i32;
    var phi_1685_: i32;
    var phi_1686_: i32;
    var phi_1746_: i32;
    var phi_1800_: i32;
    var phi_1824_: i32;
    var phi_1764_: i32;
    var phi_1765_: i32;
    var phi_1825_: i32;
    var phi_1880_: i32;
    var phi_1904_: i32;
    var phi_1844_: i32;
    var phi_1845_: i32;
    var phi_1905_: i32;
    var phi_1972_: u32;
    var phi_1975_: f32;
    var phi_2004_: u32;
    var phi_2007_: f32;
    var phi_2036_: u32;
    var phi_2039_: f32;
    var phi_2068_: u32;
    var phi_2071_: f32;
    var phi_2137_: u32;
    var phi_2140_: f32;
    var phi_2169_: u32;
    var phi_2172_: f32;
    var phi_2201_: u32;
    var phi_2204_: f32;
    var phi_2233_: u32;
    var phi_2236_: f32;
    var phi_2314_: u32;
    var phi_2317_: f32;
    var phi_2346_: u32;
    var phi_2349_: f32;
    var phi_2378_: u32;
    var phi_2381_: f32;
    var phi_2410_: u32;
    var phi_2413_: f32;
    var phi_2479_: u32;
    var phi_2482_: f32;
    var phi_2511_: u32;
    var phi_2514_: f32;
    var phi_2543_: u32;
    var phi_2546_: f32;
    var phi_2575_: u32;
    var phi_2578_: f32;
    var phi_1533_: u32;
    var phi_1536_: type_5;
    var phi_5753_: bool;
    var phi_5868_: bool;
    var phi_1504_: u32;
    var phi_1507_: type_5;
    var phi_5867_: bool;
    var phi_5870_: bool;
    var phi_1487_: u32;
    var phi_1490_: type_5;
    var phi_5869_: bool;
    var phi_5944_: bool;
    var phi_2631_: type_5;
    var phi_5943_: bool;
    var phi_2632_: type_5;
    var phi_2633_: bool;
    var phi_2637_: type_5;
    var phi_5941_: bool;
    var phi_2638_: type_5;
    var phi_5940_: bool;
    var phi_2639_: type_5;
    var phi_2640_: bool;
    var phi_2644_: type_5;
    var phi_2764_: bool;
    var phi_2803_: bool;
    var phi_2872_: u32;
    var phi_2896_: u32;
    var phi_2829_: u32;
    var phi_2853_: u32;
    var phi_2897_: u32;
    var phi_2898_: u32;
    var phi_2899_: u32;
    var phi_2900_: u32;
    var phi_2913_: f32;
    var phi_2934_: f32;
    var phi_2950_: f32;
    var phi_5628_: u32;
    var phi_5629_: type_23;
    var phi_5646_: u32;
    var phi_5655_: u32;
    var phi_5660_: u32;
    var phi_5661_: type_23;
    var phi_5667_: u32;
    var phi_5668_: type_23;
    var phi_5685_: u32;
    var phi_5694_: u32;
    var phi_5699_: u32;
    var phi_5700_: type_23;
    var phi_2966_: bool;
    var phi_5918_: bool;
    var phi_2969_: u32;
    var phi_2972_: type_5;
    var phi_5917_: bool;
    var phi_2986_: u32;
    var phi_2989_: type_5;
    var phi_3015_: u32;
    var phi_3018_: type_5;
    var phi_3031_: type_23;
    var phi_3032_: f32;
    var phi_3052_: f32;
    var phi_3053_: f32;
    var phi_3124_: i32;
    var phi_3148_: i32;
    var phi_3088_: i32;
    var phi_3089_: i32;
    var phi_3149_: i32;
    var phi_3204_: i32;
    var phi_3228_: i32;
    var phi_3168_: i32;
    var phi_3169_: i32;
    var phi_3229_: i32;
    var phi_3283_: i32;
    var phi_3307_: i32;
    var phi_3247_: i32;
    var phi_3248_: i32;
    var phi_3308_: i32;
    var phi_3363_: i32;
    var phi_3387_: i32;
    var phi_3327_: i32;
    var phi_3328_: i32;
    var phi_3388_: i32;
    var phi_3455_: u32;
    var phi_3458_: f32;
    var phi_3487_: u32;
    var phi_3490_: f32;
    var phi_3519_: u32;
    var phi_3522_: f32;
    var phi_3551_: u32;
    var phi_3554_: f32;
    var phi_3620_: u32;
    var phi_3623_: f32;
    var phi_3652_: u32;
    var phi_3655_: f32;
    var phi_3684_: u32;
    var phi_3687_: f32;
    var phi_3716_: u32;
    var phi_3719_: f32;
    var phi_3797_: u32;
    var phi_3800_: f32;
    var phi_3829_: u32;
    var phi_3832_: f32;
    var phi_3861_: u32;
    var phi_3864_: f32;
    var phi_3893_: u32;
    var phi_3896_: f32;
    var phi_3962_: u32;
    var phi_3965_: f32;
    var phi_3994_: u32;
    var phi_3997_: f32;
    var phi_4026_: u32;
    var phi_4029_: f32;
    var phi_4058_: u32;
    var phi_4061_: f32;
    var phi_3016_: u32;
    var phi_3019_: type_5;
    var phi_5871_: bool;
    var phi_5984_: bool;
    var phi_2987_: u32;
    var phi_2990_: type_5;
    var phi_5983_: bool;
    var phi_5986_: bool;
    var phi_2970_: u32;
    var phi_2973_: type_5;
    var phi_5985_: bool;
    var phi_6003_: bool;
    var phi_4114_: type_5;
    var phi_6002_: bool;
    var phi_4115_: type_5;
    var phi_4116_: bool;
    var phi_4120_: type_5;
    var phi_6000_: bool;
    var phi_4121_: type_5;
    var phi_5999_: bool;
    var phi_4122_: type_5;
    var phi_4123_: bool;
    var phi_4127_: type_5;
    var phi_4155_: u32;
    var phi_4158_: array<f32, 4>;
    var phi_4241_: u32;
    var phi_4244_: f32;
    var phi_4284_: u32;
    var phi_4287_: f32;
    var phi_4327_: u32;
    var phi_4330_: f32;
    var phi_4370_: u32;
    var phi_4373_: f32;
    var phi_4156_: u32;
    var phi_4159_: array<f32, 4>;
    var phi_5987_: bool;
    var phi_5713_: bool;
    var phi_4415_: u32;
    var phi_4481_: f32;
    var phi_4416_: u32;
    var phi_6008_: bool;
    var phi_4558_: f32;
    var phi_6017_: bool;
    var phi_4608_: f32;
    var phi_4609_: f32;
    var phi_4773_: bool;
    var phi_4800_: f32;
    var phi_4802_: f32;
    var phi_4803_: bool;
    var phi_4804_: f32;
    var phi_4805_: f32;
    var phi_4806_: bool;
    var phi_4807_: f32;
    var phi_4808_: f32;
    var phi_4809_: bool;
    var phi_4810_: bool;
    var phi_4811_: f32;
    var phi_4812_: f32;
    var phi_4813_: bool;
    var phi_4814_: bool;
    var phi_4832_: f32;
    var phi_4833_: f32;
    var phi_4618_: u32;
    var phi_4619_: u32;
    var phi_6014_: bool;
    var phi_6027_: bool;
    var phi_6026_: bool;
    var phi_6025_: bool;
    var phi_280_: u32;
    var phi_6024_: bool;
    var local_628: type_23;
    var local_629: type_23;
    var local_630: type_5;
    var local_631: type_5;
    var local_632: type_23;
    var local_633: type_23;
    var local_634: type_5;
    var local_635: type_5;

    let _e712 = global_12;
    local_612 = bitcast<f32>(_e712);
    let _e714 = global_13;
    let _e715 = bitcast<f32>(_e714);
    local_613 = _e715;
    switch bitcast<i32>(0u) {
        default: {
            let _e717 = global;
            local = _e717;
            let _e718 = global_1;
            let _e719 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_9.member));
            local_7 = arrayLength((&global_10.member));
            local_8 = arrayLength((&global_11.member));
            let _e740 = global_3.member.member_5;
            let _e743 = global_3.member.member_6;
            local_9 = (_e740 * _e743);
            local_10 = (_e719.x * 256u);
            phi_5740_ = false;
            phi_279_ = (_e718.x * 256u);
            loop {
                let _e748 = phi_5740_;
                let _e750 = phi_279_;
                local_11 = _e750;
                let _e751 = local_11;
                let _e752 = local_9;
                let _e753 = (_e751 < _e752);
                local_12 = _e753;
                if _e753 {
                    let _e754 = local_11;
                    let _e755 = local;
                    let _e756 = (_e754 + _e755);
                    local_13 = _e756;
                    let _e757 = local_9;
                    if (_e756 < _e757) {
                        let _e759 = local_13;
                        let _e760 = (_e759 * 4u);
                        local_14 = _e760;
                        let _e761 = local_1;
                        if (_e760 < _e761) {
                        } else {
                            phi_6024_ = true;
                            break;
                        }
                        let _e763 = local_14;
                        let _e766 = global_4.member[_e763];
                        let _e767 = bitcast<f32>(_e766);
                        let _e773 = select(select(u32(_e767), 0u, !((_e767 >= 0f))), 4294967295u, (_e767 > 4294967000f));
                        local_15 = _e773;
                        let _e774 = (_e773 > 0u);
                        local_16 = _e774;
                        if _e774 {
                            let _e803 = local_14;
                            let _e804 = (_e803 + 2u);
                            local_17 = _e804;
                            let _e805 = local_1;
                            if (_e804 < _e805) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e807 = local_17;
                            let _e810 = global_4.member[_e807];
                            local_18 = bitcast<f32>(_e810);
                            let _e812 = local_14;
                            let _e813 = (_e812 + 3u);
                            local_19 = _e813;
                            let _e814 = local_1;
                            if (_e813 < _e814) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e816 = local_19;
                            let _e819 = global_4.member[_e816];
                            local_20 = bitcast<f32>(_e819);
                            let _e821 = local_14;
                            let _e822 = (_e821 + 1u);
                            local_21 = _e822;
                            let _e823 = local_1;
                            if (_e822 < _e823) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e825 = local_21;
                            let _e828 = global_4.member[_e825];
                            let _e829 = bitcast<f32>(_e828);
                            let _e832 = global_3.member.member_4;
                            local_22 = ((2f * _e832) * _e829);
                            let _e837 = global_3.member.member_1;
                            local_23 = _e837;
                            let _e840 = global_3.member.member_8;
                            local_24 = _e840;
                            let _e843 = global_3.member.member_7;
                            local_25 = _e843;
                            let _e846 = global_3.member.member_2;
                            let _e848 = (_e846 >> bitcast<u32>(8u));
                            let _e849 = (_e848 & 127u);
                            local_26 = _e849;
                            local_27 = ((_e848 >> bitcast<u32>(7i)) & 15u);
                            if (_e849 == 0u) {
                                phi_411_ = type_22();
                                phi_412_ = true;
                            } else {
                                let _e854 = local_26;
                                if (_e854 > 64u) {
                                    phi_409_ = type_22();
                                    phi_410_ = true;
                                } else {
                                    let _e856 = local_27;
                                    if (_e856 == 0u) {
                                        phi_407_ = type_22();
                                        phi_408_ = true;
                                    } else {
                                        let _e858 = local_27;
                                        let _e859 = (_e858 > 8u);
                                        if _e859 {
                                            phi_406_ = type_22();
                                        } else {
                                            let _e860 = local_26;
                                            let _e861 = local_27;
                                            phi_406_ = type_22(_e860, _e861);
                                        }
                                        let _e864 = phi_406_;
                                        phi_407_ = _e864;
                                        phi_408_ = _e859;
                                    }
                                    let _e866 = phi_407_;
                                    let _e868 = phi_408_;
                                    phi_409_ = _e866;
                                    phi_410_ = _e868;
                                }
                                let _e870 = phi_409_;
                                let _e872 = phi_410_;
                                phi_411_ = _e870;
                                phi_412_ = _e872;
                            }
                            let _e874 = phi_411_;
                            let _e876 = phi_412_;
                            if _e876 {
                                phi_417_ = type_22(64u, 8u);
                            } else {
                                phi_417_ = _e874;
                            }
                            let _e878 = phi_417_;
                            local_28 = _e878.member;
                            local_29 = _e878.member_1;
                            let _e881 = local_15;
                            let _e883 = ((_e881 - 1u) * 4u);
                            local_30 = _e883;
                            let _e884 = local_3;
                            if (_e883 < _e884) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e886 = local_30;
                            let _e889 = global_6.member[_e886];
                            local_31 = _e889;
                            let _e890 = local_30;
                            let _e891 = (_e890 + 1u);
                            local_32 = _e891;
                            let _e892 = local_3;
                            if (_e891 < _e892) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e894 = local_32;
                            let _e897 = global_6.member[_e894];
                            local_33 = _e897;
                            let _e898 = local_30;
                            let _e899 = (_e898 + 2u);
                            local_34 = _e899;
                            let _e900 = local_3;
                            if (_e899 < _e900) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e902 = local_34;
                            let _e905 = global_6.member[_e902];
                            local_35 = _e905;
                            let _e906 = local_30;
                            let _e907 = (_e906 + 3u);
                            local_36 = _e907;
                            let _e908 = local_3;
                            if (_e907 < _e908) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e910 = local_36;
                            let _e913 = global_6.member[_e910];
                            let _e914 = local_31;
                            let _e915 = local_33;
                            let _e916 = local_35;
                            let _e917 = array<u32, 4>(_e914, _e915, _e916, _e913);
                            local_37 = _e917;
                            local_618 = _e917;
                            let _e918 = local_18;
                            let _e920 = local_20;
                            let _e921 = ((1f - _e918) - _e920);
                            local_38 = _e921;
                            let _e923 = local_18;
                            local_619[0u] = _e923;
                            let _e925 = local_20;
                            local_619[1u] = _e925;
                            local_619[2u] = _e921;
                            let _e928 = local_618[0u];
                            let _e929 = (_e928 * 10u);
                            local_39 = _e929;
                            let _e930 = local_2;
                            if (_e929 < _e930) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e932 = local_39;
                            let _e935 = global_5.member[_e932];
                            local_40 = bitcast<f32>(_e935);
                            let _e937 = local_39;
                            let _e938 = (_e937 + 1u);
                            local_41 = _e938;
                            let _e939 = local_2;
                            if (_e938 < _e939) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e941 = local_41;
                            let _e944 = global_5.member[_e941];
                            local_42 = bitcast<f32>(_e944);
                            let _e946 = local_39;
                            let _e947 = (_e946 + 2u);
                            local_43 = _e947;
                            let _e948 = local_2;
                            if (_e947 < _e948) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e950 = local_43;
                            let _e953 = global_5.member[_e950];
                            local_44 = bitcast<f32>(_e953);
                            let _e956 = local_618[1u];
                            let _e957 = (_e956 * 10u);
                            local_45 = _e957;
                            let _e958 = local_2;
                            if (_e957 < _e958) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e960 = local_45;
                            let _e963 = global_5.member[_e960];
                            local_46 = bitcast<f32>(_e963);
                            let _e965 = local_45;
                            let _e966 = (_e965 + 1u);
                            local_47 = _e966;
                            let _e967 = local_2;
                            if (_e966 < _e967) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e969 = local_47;
                            let _e972 = global_5.member[_e969];
                            local_48 = bitcast<f32>(_e972);
                            let _e974 = local_45;
                            let _e975 = (_e974 + 2u);
                            local_49 = _e975;
                            let _e976 = local_2;
                            if (_e975 < _e976) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e978 = local_49;
                            let _e981 = global_5.member[_e978];
                            local_50 = bitcast<f32>(_e981);
                            let _e984 = local_618[2u];
                            let _e985 = (_e984 * 10u);
                            local_51 = _e985;
                            let _e986 = local_2;
                            if (_e985 < _e986) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e988 = local_51;
                            let _e991 = global_5.member[_e988];
                            local_52 = bitcast<f32>(_e991);
                            let _e993 = local_51;
                            let _e994 = (_e993 + 1u);
                            local_53 = _e994;
                            let _e995 = local_2;
                            if (_e994 < _e995) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e997 = local_53;
                            let _e1000 = global_5.member[_e997];
                            local_54 = bitcast<f32>(_e1000);
                            let _e1002 = local_51;
                            let _e1003 = (_e1002 + 2u);
                            local_55 = _e1003;
                            let _e1004 = local_2;
                            if (_e1003 < _e1004) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e1006 = local_55;
                            let _e1009 = global_5.member[_e1006];
                            let _e1012 = local_40;
                            let _e1013 = local_42;
                            let _e1014 = local_44;
                            local_620[0u] = array<f32, 3>(_e1012, _e1013, _e1014);
                            let _e1017 = local_46;
                            let _e1018 = local_48;
                            let _e1019 = local_50;
                            local_620[1u] = array<f32, 3>(_e1017, _e1018, _e1019);
                            let _e1022 = local_52;
                            let _e1023 = local_54;
                            local_620[2u] = array<f32, 3>(_e1022, _e1023, bitcast<f32>(_e1009));
                            local_621 = array<f32, 3>(0f, 0f, 0f);
                            local_622 = array<f32, 3>(0f, 0f, 0f);
                            phi_5737_ = _e748;
                            phi_675_ = 0u;
                            loop {
                                let _e1026 = phi_5737_;
                                let _e1028 = phi_675_;
                                local_56 = _e1028;
                                let _e1029 = local_56;
                                let _e1030 = (_e1029 < 3u);
                                local_57 = _e1030;
                                if _e1030 {
                                    let _e1031 = local_56;
                                    if (_e1031 < 4u) {
                                    } else {
                                        phi_5744_ = true;
                                        break;
                                    }
                                    let _e1033 = local_56;
                                    let _e1035 = local_618[_e1033];
                                    local_58 = (_e1035 * 10u);
                                    phi_693_ = 0u;
                                    loop {
                                        let _e1038 = phi_693_;
                                        local_59 = _e1038;
                                        let _e1039 = local_59;
                                        let _e1040 = (_e1039 < 3u);
                                        local_60 = _e1040;
                                        if _e1040 {
                                            let _e1041 = local_57;
                                            if _e1041 {
                                            } else {
                                                phi_5734_ = true;
                                                break;
                                            }
                                            let _e1042 = local_56;
                                            let _e1044 = local_619[_e1042];
                                            local_61 = _e1044;
                                            let _e1045 = local_57;
                                            if _e1045 {
                                            } else {
                                                phi_5734_ = true;
                                                break;
                                            }
                                            let _e1046 = local_60;
                                            if _e1046 {
                                            } else {
                                                phi_5734_ = true;
                                                break;
                                            }
                                            let _e1047 = local_56;
                                            let _e1048 = local_59;
                                            let _e1051 = local_620[_e1047][_e1048];
                                            let _e1052 = local_61;
                                            local_62 = (_e1052 * _e1051);
                                            let _e1054 = local_60;
                                            if _e1054 {
                                            } else {
                                                phi_5734_ = true;
                                                break;
                                            }
                                            let _e1055 = local_59;
                                            let _e1057 = local_621[_e1055];
                                            let _e1058 = local_62;
                                            local_621[_e1055] = (_e1057 + _e1058);
                                            let _e1060 = local_57;
                                            if _e1060 {
                                            } else {
                                                phi_5734_ = true;
                                                break;
                                            }
                                            let _e1061 = local_619[_e1042];
                                            local_63 = _e1061;
                                            let _e1062 = local_58;
                                            let _e1064 = local_59;
                                            let _e1065 = ((_e1062 + 4u) + _e1064);
                                            local_64 = _e1065;
                                            let _e1066 = local_2;
                                            if (_e1065 < _e1066) {
                                            } else {
                                                phi_5734_ = true;
                                                break;
                                            }
                                            let _e1068 = local_64;
                                            let _e1071 = global_5.member[_e1068];
                                            let _e1073 = local_63;
                                            local_65 = (_e1073 * bitcast<f32>(_e1071));
                                            let _e1075 = local_60;
                                            if _e1075 {
                                            } else {
                                                phi_5734_ = true;
                                                break;
                                            }
                                            let _e1076 = local_59;
                                            let _e1078 = local_622[_e1076];
                                            let _e1079 = local_65;
                                            local_622[_e1076] = (_e1078 + _e1079);
                                            let _e1081 = local_59;
                                            phi_694_ = (_e1081 + 1u);
                                        } else {
                                            phi_694_ = u32();
                                        }
                                        let _e1084 = phi_694_;
                                        continue;
                                        continuing {
                                            let _e1085 = local_60;
                                            phi_693_ = _e1084;
                                            phi_5734_ = _e1026;
                                            break if !(_e1085);
                                        }
                                    }
                                    let _e1088 = phi_5734_;
                                    phi_5744_ = _e1088;
                                    if _e1088 {
                                        break;
                                    }
                                    let _e1089 = local_56;
                                    phi_5745_ = _e1088;
                                    phi_676_ = (_e1089 + 1u);
                                } else {
                                    phi_5745_ = _e1026;
                                    phi_676_ = u32();
                                }
                                let _e1092 = phi_5745_;
                                let _e1094 = phi_676_;
                                continue;
                                continuing {
                                    let _e1095 = local_57;
                                    phi_5737_ = _e1092;
                                    phi_675_ = _e1094;
                                    phi_5744_ = _e1092;
                                    break if !(_e1095);
                                }
                            }
                            let _e1098 = phi_5744_;
                            phi_6024_ = _e1098;
                            if _e1098 {
                                break;
                            }
                            let _e1099 = local_620[1u];
                            let _e1103 = local_620[0u];
                            let _e1107 = (_e1099[0] - _e1103[0]);
                            let _e1108 = (_e1099[1] - _e1103[1]);
                            let _e1109 = (_e1099[2] - _e1103[2]);
                            let _e1110 = local_620[2u];
                            let _e1114 = local_620[0u];
                            let _e1118 = (_e1110[0] - _e1114[0]);
                            let _e1119 = (_e1110[1] - _e1114[1]);
                            let _e1120 = (_e1110[2] - _e1114[2]);
                            let _e1123 = ((_e1108 * _e1120) - (_e1109 * _e1119));
                            local_66 = _e1123;
                            let _e1126 = ((_e1109 * _e1118) - (_e1107 * _e1120));
                            local_67 = _e1126;
                            let _e1129 = ((_e1107 * _e1119) - (_e1108 * _e1118));
                            local_68 = _e1129;
                            let _e1131 = local_622;
                            if ((((_e1131[0] * _e1131[0]) + (_e1131[1] * _e1131[1])) + (_e1131[2] * _e1131[2])) > 0f) {
                                let _e1166 = local_622;
                                local_69 = _e1166[0];
                                local_70 = _e1166[1];
                                local_71 = _e1166[2];
                                let _e1176 = sqrt((((_e1166[0] * _e1166[0]) + (_e1166[1] * _e1166[1])) + (_e1166[2] * _e1166[2])));
                                local_506 = _e1176;
                                if (_e1176 > 0f) {
                                    let _e1178 = local_69;
                                    let _e1179 = local_506;
                                    let _e1181 = local_70;
                                    let _e1182 = local_506;
                                    let _e1184 = local_71;
                                    let _e1185 = local_506;
                                    phi_5204_ = array<f32, 3>((_e1178 / _e1179), (_e1181 / _e1182), (_e1184 / _e1185));
                                } else {
                                    phi_5204_ = array<f32, 3>(_e1166[0], _e1166[1], _e1166[2]);
                                }
                                let _e1189 = phi_5204_;
                                phi_855_ = _e1189;
                            } else {
                                let _e1141 = local_66;
                                let _e1142 = local_66;
                                let _e1144 = local_67;
                                let _e1145 = local_67;
                                let _e1148 = local_68;
                                let _e1149 = local_68;
                                let _e1152 = sqrt((((_e1141 * _e1142) + (_e1144 * _e1145)) + (_e1148 * _e1149)));
                                local_507 = _e1152;
                                if (_e1152 > 0f) {
                                    let _e1154 = local_66;
                                    let _e1155 = local_507;
                                    let _e1157 = local_67;
                                    let _e1158 = local_507;
                                    let _e1160 = local_68;
                                    let _e1161 = local_507;
                                    phi_5230_ = array<f32, 3>((_e1154 / _e1155), (_e1157 / _e1158), (_e1160 / _e1161));
                                } else {
                                    phi_5230_ = array<f32, 3>(_e1123, _e1126, _e1129);
                                }
                                let _e1165 = phi_5230_;
                                phi_855_ = _e1165;
                            }
                            let _e1191 = phi_855_;
                            local_72 = _e1191;
                            let _e1192 = local_621;
                            let _e1196 = local_23;
                            local_73 = _e1196[0];
                            let _e1199 = local_23;
                            local_74 = _e1199[1];
                            let _e1202 = local_23;
                            local_75 = _e1202[2];
                            let _e1205 = local_66;
                            let _e1207 = local_67;
                            let _e1210 = local_68;
                            if ((((_e1205 * (_e1192[0] - _e1196[0])) + (_e1207 * (_e1192[1] - _e1199[1]))) + (_e1210 * (_e1192[2] - _e1202[2]))) > 0f) {
                                let _e1214 = local_72;
                                let _e1217 = local_72;
                                let _e1220 = local_72;
                                phi_886_ = array<f32, 3>(-(_e1214[0]), -(_e1217[1]), -(_e1220[2]));
                            } else {
                                phi_886_ = _e1191;
                            }
                            let _e1225 = phi_886_;
                            local_76 = _e1225;
                            let _e1226 = local_37;
                            local_616 = _e1226;
                            let _e1228 = local_18;
                            local_617[0u] = _e1228;
                            let _e1230 = local_20;
                            local_617[1u] = _e1230;
                            let _e1232 = local_38;
                            local_617[2u] = _e1232;
                            phi_904_ = 0u;
                            phi_907_ = 0f;
                            phi_909_ = 0f;
                            loop {
                                let _e1234 = phi_904_;
                                let _e1236 = phi_907_;
                                let _e1238 = phi_909_;
                                local_77 = _e1234;
                                local_78 = _e1236;
                                local_79 = _e1238;
                                let _e1239 = local_77;
                                let _e1240 = (_e1239 < 3u);
                                local_80 = _e1240;
                                if _e1240 {
                                    let _e1241 = local_77;
                                    if (_e1241 < 4u) {
                                    } else {
                                        phi_5746_ = true;
                                        break;
                                    }
                                    let _e1243 = local_77;
                                    let _e1245 = local_616[_e1243];
                                    local_81 = (_e1245 * 10u);
                                    let _e1247 = local_80;
                                    if _e1247 {
                                    } else {
                                        phi_5746_ = true;
                                        break;
                                    }
                                    let _e1248 = local_77;
                                    let _e1250 = local_617[_e1248];
                                    local_82 = _e1250;
                                    let _e1251 = local_81;
                                    let _e1252 = (_e1251 + 3u);
                                    local_83 = _e1252;
                                    let _e1253 = local_2;
                                    if (_e1252 < _e1253) {
                                    } else {
                                        phi_5746_ = true;
                                        break;
                                    }
                                    let _e1255 = local_83;
                                    let _e1258 = global_5.member[_e1255];
                                    let _e1260 = local_82;
                                    let _e1262 = local_79;
                                    let _e1264 = local_80;
                                    if _e1264 {
                                    } else {
                                        phi_5746_ = true;
                                        break;
                                    }
                                    let _e1265 = local_617[_e1248];
                                    local_84 = _e1265;
                                    let _e1266 = local_81;
                                    let _e1267 = (_e1266 + 7u);
                                    local_85 = _e1267;
                                    let _e1268 = local_2;
                                    if (_e1267 < _e1268) {
                                    } else {
                                        phi_5746_ = true;
                                        break;
                                    }
                                    let _e1270 = local_85;
                                    let _e1273 = global_5.member[_e1270];
                                    let _e1275 = local_84;
                                    let _e1277 = local_78;
                                    let _e1279 = local_77;
                                    phi_905_ = (_e1279 + 1u);
                                    phi_908_ = (_e1277 + (_e1275 * bitcast<f32>(_e1273)));
                                    phi_910_ = (_e1262 + (_e1260 * bitcast<f32>(_e1258)));
                                } else {
                                    phi_905_ = u32();
                                    phi_908_ = f32();
                                    phi_910_ = f32();
                                }
                                let _e1282 = phi_905_;
                                let _e1284 = phi_908_;
                                let _e1286 = phi_910_;
                                continue;
                                continuing {
                                    let _e1287 = local_80;
                                    phi_904_ = _e1282;
                                    phi_907_ = _e1284;
                                    phi_909_ = _e1286;
                                    phi_5746_ = _e1098;
                                    break if !(_e1287);
                                }
                            }
                            let _e1290 = phi_5746_;
                            phi_6024_ = _e1290;
                            if _e1290 {
                                break;
                            }
                            let _e1292 = local_618[3u];
                            let _e1293 = (_e1292 * 16u);
                            local_86 = _e1293;
                            let _e1294 = (_e1293 + 8u);
                            local_87 = _e1294;
                            let _e1295 = local_4;
                            if (_e1294 < _e1295) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e1297 = local_87;
                            let _e1300 = global_7.member[_e1297];
                            local_88 = _e1300;
                            let _e1301 = local_86;
                            let _e1302 = (_e1301 + 9u);
                            local_89 = _e1302;
                            let _e1303 = local_4;
                            if (_e1302 < _e1303) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e1305 = local_89;
                            let _e1308 = global_7.member[_e1305];
                            local_90 = _e1308;
                            let _e1309 = local_88;
                            let _e1310 = local_25;
                            if (_e1309 < _e1310) {
                                phi_1021_ = true;
                            } else {
                                let _e1312 = local_90;
                                let _e1313 = local_25;
                                phi_1021_ = (_e1312 < _e1313);
                            }
                            let _e1316 = phi_1021_;
                            if _e1316 {
                                let _e1317 = local_31;
                                let _e1318 = (_e1317 * 10u);
                                local_91 = _e1318;
                                let _e1319 = (_e1318 + 3u);
                                local_92 = _e1319;
                                let _e1320 = local_2;
                                if (_e1319 < _e1320) {
                                } else {
                                    phi_6024_ = true;
                                    break;
                                }
                                let _e1322 = local_92;
                                let _e1325 = global_5.member[_e1322];
                                local_93 = bitcast<f32>(_e1325);
                                let _e1327 = local_91;
                                let _e1328 = (_e1327 + 7u);
                                local_94 = _e1328;
                                let _e1329 = local_2;
                                if (_e1328 < _e1329) {
                                } else {
                                    phi_6024_ = true;
                                    break;
                                }
                                let _e1331 = local_94;
                                let _e1334 = global_5.member[_e1331];
                                local_95 = bitcast<f32>(_e1334);
                                let _e1336 = local_33;
                                let _e1337 = (_e1336 * 10u);
                                local_96 = _e1337;
                                let _e1338 = (_e1337 + 3u);
                                local_97 = _e1338;
                                let _e1339 = local_2;
                                if (_e1338 < _e1339) {
                                } else {
                                    phi_6024_ = true;
                                    break;
                                }
                                let _e1341 = local_97;
                                let _e1344 = global_5.member[_e1341];
                                local_98 = bitcast<f32>(_e1344);
                                let _e1346 = local_96;
                                let _e1347 = (_e1346 + 7u);
                                local_99 = _e1347;
                                let _e1348 = local_2;
                                if (_e1347 < _e1348) {
                                } else {
                                    phi_6024_ = true;
                                    break;
                                }
                                let _e1350 = local_99;
                                let _e1353 = global_5.member[_e1350];
                                local_100 = bitcast<f32>(_e1353);
                                let _e1355 = local_35;
                                let _e1356 = (_e1355 * 10u);
                                local_101 = _e1356;
                                let _e1357 = (_e1356 + 3u);
                                local_102 = _e1357;
                                let _e1358 = local_2;
                                if (_e1357 < _e1358) {
                                } else {
                                    phi_6024_ = true;
                                    break;
                                }
                                let _e1360 = local_102;
                                let _e1363 = global_5.member[_e1360];
                                local_103 = bitcast<f32>(_e1363);
                                let _e1365 = local_101;
                                let _e1366 = (_e1365 + 7u);
                                local_104 = _e1366;
                                let _e1367 = local_2;
                                if (_e1366 < _e1367) {
                                } else {
                                    phi_6024_ = true;
                                    break;
                                }
                                let _e1369 = local_104;
                                let _e1372 = global_5.member[_e1369];
                                local_105 = bitcast<f32>(_e1372);
                                let _e1374 = local_621;
                                let _e1378 = local_620;
                                let _e1391 = local_73;
                                local_508 = (_e1374[0] - _e1391);
                                let _e1393 = local_74;
                                local_509 = (_e1374[1] - _e1393);
                                let _e1395 = local_75;
                                local_510 = (_e1374[2] - _e1395);
                                let _e1397 = (_e1378[1][0] - _e1378[0][0]);
                                local_511 = _e1397;
                                let _e1398 = (_e1378[1][1] - _e1378[0][1]);
                                local_512 = _e1398;
                                let _e1399 = (_e1378[1][2] - _e1378[0][2]);
                                local_513 = _e1399;
                                let _e1400 = (_e1378[2][0] - _e1378[0][0]);
                                local_514 = _e1400;
                                let _e1401 = (_e1378[2][1] - _e1378[0][1]);
                                local_515 = _e1401;
                                let _e1402 = (_e1378[2][2] - _e1378[0][2]);
                                local_516 = _e1402;
                                local_517 = ((_e1398 * _e1402) - (_e1399 * _e1401));
                                local_518 = ((_e1399 * _e1400) - (_e1397 * _e1402));
                                local_519 = ((_e1397 * _e1401) - (_e1398 * _e1400));
                                let _e1416 = (((_e1397 * _e1397) + (_e1398 * _e1398)) + (_e1399 * _e1399));
                                local_520 = _e1416;
                                let _e1421 = (((_e1397 * _e1400) + (_e1398 * _e1401)) + (_e1399 * _e1402));
                                local_521 = _e1421;
                                let _e1426 = (((_e1400 * _e1400) + (_e1401 * _e1401)) + (_e1402 * _e1402));
                                local_522 = _e1426;
                                let _e1429 = ((_e1416 * _e1426) - (_e1421 * _e1421));
                                local_523 = _e1429;
                                if (_e1429 > 0f) {
                                    let _e1431 = local_22;
                                    let _e1432 = (_e1431 > 0f);
                                    local_524 = _e1432;
                                    if _e1432 {
                                        let _e1433 = local_24;
                                        let _e1435 = local_24;
                                        let _e1437 = local_24;
                                        let _e1439 = (2f * _e1437[2]);
                                        let _e1440 = (_e1435[1] * -2f);
                                        let _e1447 = local_24;
                                        local_529 = (1f + ((_e1435[1] * _e1440) - (_e1437[2] * _e1439)));
                                        local_530 = ((_e1447[3] * _e1439) + -((_e1433[0] * _e1440)));
                                        local_531 = ((_e1447[3] * _e1440) + (_e1433[0] * _e1439));
                                        let _e1454 = (_e1437[2] * -2f);
                                        let _e1455 = (2f * _e1433[0]);
                                        local_532 = ((_e1447[3] * _e1454) + (_e1435[1] * _e1455));
                                        local_533 = (1f + ((_e1437[2] * _e1454) - (_e1433[0] * _e1455)));
                                        local_534 = ((_e1447[3] * _e1455) + -((_e1435[1] * _e1454)));
                                        let _e1467 = local_508;
                                        let _e1468 = local_517;
                                        let _e1470 = local_509;
                                        let _e1471 = local_518;
                                        let _e1474 = local_510;
                                        let _e1475 = local_519;
                                        let _e1477 = (((_e1467 * _e1468) + (_e1470 * _e1471)) + (_e1474 * _e1475));
                                        local_525 = _e1477;
                                        let _e1478 = local_508;
                                        let _e1479 = local_508;
                                        let _e1481 = local_509;
                                        let _e1482 = local_509;
                                        let _e1485 = local_510;
                                        let _e1486 = local_510;
                                        let _e1489 = local_517;
                                        let _e1490 = local_517;
                                        let _e1492 = local_518;
                                        let _e1493 = local_518;
                                        let _e1496 = local_519;
                                        let _e1497 = local_519;
                                        let _e1501 = sqrt(((((_e1478 * _e1479) + (_e1481 * _e1482)) + (_e1485 * _e1486)) * (((_e1489 * _e1490) + (_e1492 * _e1493)) + (_e1496 * _e1497))));
                                        local_526 = _e1501;
                                        let _e1502 = (0.001f * _e1501);
                                        local_527 = _e1502;
                                        let _e1503 = (_e1477 < 0f);
                                        local_528 = _e1503;
                                        if _e1503 {
                                            let _e1504 = local_525;
                                            phi_5323_ = -(_e1504);
                                        } else {
                                            phi_5323_ = _e1477;
                                        }
                                        let _e1507 = phi_5323_;
                                        let _e1508 = local_527;
                                        if (_e1507 >= _e1508) {
                                            phi_5334_ = _e1477;
                                        } else {
                                            let _e1510 = local_528;
                                            if _e1510 {
                                                let _e1511 = local_526;
                                                phi_5332_ = (_e1511 * -0.001f);
                                            } else {
                                                phi_5332_ = _e1502;
                                            }
                                            let _e1514 = phi_5332_;
                                            phi_5334_ = _e1514;
                                        }
                                        let _e1516 = phi_5334_;
                                        let _e1517 = local_98;
                                        let _e1518 = local_93;
                                        let _e1519 = (_e1517 - _e1518);
                                        let _e1520 = local_100;
                                        let _e1521 = local_95;
                                        let _e1522 = (_e1520 - _e1521);
                                        let _e1523 = local_103;
                                        let _e1524 = local_93;
                                        let _e1525 = (_e1523 - _e1524);
                                        let _e1526 = local_105;
                                        let _e1527 = local_95;
                                        let _e1528 = (_e1526 - _e1527);
                                        let _e1529 = local_529;
                                        let _e1530 = local_517;
                                        let _e1532 = local_530;
                                        let _e1533 = local_518;
                                        let _e1536 = local_531;
                                        let _e1537 = local_519;
                                        let _e1540 = ((((_e1529 * _e1530) + (_e1532 * _e1533)) + (_e1536 * _e1537)) / _e1516);
                                        let _e1541 = local_508;
                                        let _e1543 = local_529;
                                        let _e1545 = local_22;
                                        let _e1546 = (_e1545 * (_e1543 - (_e1541 * _e1540)));
                                        let _e1547 = local_509;
                                        let _e1549 = local_530;
                                        let _e1551 = local_22;
                                        let _e1552 = (_e1551 * (_e1549 - (_e1547 * _e1540)));
                                        let _e1553 = local_510;
                                        let _e1555 = local_531;
                                        let _e1557 = local_22;
                                        let _e1558 = (_e1557 * (_e1555 - (_e1553 * _e1540)));
                                        let _e1559 = local_511;
                                        let _e1561 = local_512;
                                        let _e1564 = local_513;
                                        let _e1566 = (((_e1546 * _e1559) + (_e1552 * _e1561)) + (_e1558 * _e1564));
                                        let _e1567 = local_514;
                                        let _e1569 = local_515;
                                        let _e1572 = local_516;
                                        let _e1574 = (((_e1546 * _e1567) + (_e1552 * _e1569)) + (_e1558 * _e1572));
                                        let _e1575 = local_522;
                                        let _e1577 = local_521;
                                        let _e1580 = local_523;
                                        let _e1581 = (((_e1566 * _e1575) - (_e1574 * _e1577)) / _e1580);
                                        let _e1582 = local_520;
                                        let _e1584 = local_521;
                                        let _e1587 = local_523;
                                        let _e1588 = (((_e1574 * _e1582) - (_e1566 * _e1584)) / _e1587);
                                        let _e1595 = local_532;
                                        let _e1596 = local_517;
                                        let _e1598 = local_533;
                                        let _e1599 = local_518;
                                        let _e1602 = local_534;
                                        let _e1603 = local_519;
                                        let _e1606 = ((((_e1595 * _e1596) + (_e1598 * _e1599)) + (_e1602 * _e1603)) / _e1516);
                                        let _e1607 = local_508;
                                        let _e1609 = local_532;
                                        let _e1611 = local_22;
                                        let _e1612 = (_e1611 * (_e1609 - (_e1607 * _e1606)));
                                        let _e1613 = local_509;
                                        let _e1615 = local_533;
                                        let _e1617 = local_22;
                                        let _e1618 = (_e1617 * (_e1615 - (_e1613 * _e1606)));
                                        let _e1619 = local_510;
                                        let _e1621 = local_534;
                                        let _e1623 = local_22;
                                        let _e1624 = (_e1623 * (_e1621 - (_e1619 * _e1606)));
                                        let _e1625 = local_511;
                                        let _e1627 = local_512;
                                        let _e1630 = local_513;
                                        let _e1632 = (((_e1612 * _e1625) + (_e1618 * _e1627)) + (_e1624 * _e1630));
                                        let _e1633 = local_514;
                                        let _e1635 = local_515;
                                        let _e1638 = local_516;
                                        let _e1640 = (((_e1612 * _e1633) + (_e1618 * _e1635)) + (_e1624 * _e1638));
                                        let _e1641 = local_522;
                                        let _e1643 = local_521;
                                        let _e1646 = local_523;
                                        let _e1647 = (((_e1632 * _e1641) - (_e1640 * _e1643)) / _e1646);
                                        let _e1648 = local_520;
                                        let _e1650 = local_521;
                                        let _e1653 = local_523;
                                        let _e1654 = (((_e1640 * _e1648) - (_e1632 * _e1650)) / _e1653);
                                        phi_5440_ = type_5(((_e1581 * _e1519) + (_e1588 * _e1525)), ((_e1581 * _e1522) + (_e1588 * _e1528)), ((_e1647 * _e1519) + (_e1654 * _e1525)), ((_e1647 * _e1522) + (_e1654 * _e1528)));
                                    } else {
                                        phi_5440_ = type_5();
                                    }
                                    let _e1663 = phi_5440_;
                                    let _e1664 = local_524;
                                    phi_5444_ = _e1663;
                                    phi_5445_ = select(true, false, _e1664);
                                } else {
                                    phi_5444_ = type_5();
                                    phi_5445_ = true;
                                }
                                let _e1667 = phi_5444_;
                                let _e1669 = phi_5445_;
                                if _e1669 {
                                    phi_5449_ = type_5(0f, 0f, 0f, 0f);
                                } else {
                                    phi_5449_ = _e1667;
                                }
                                let _e1671 = phi_5449_;
                                phi_1171_ = _e1671;
                            } else {
                                phi_1171_ = type_5(0f, 0f, 0f, 0f);
                            }
                            let _e1673 = phi_1171_;
                            local_106 = _e1673;
                            let _e1674 = local_88;
                            if (_e1674 == 4294967295u) {
                                phi_5940_ = _e1290;
                                phi_2639_ = type_5();
                                phi_2640_ = true;
                            } else {
                                let _e1676 = local_88;
                                let _e1677 = local_25;
                                let _e1678 = (_e1676 >= _e1677);
                                if _e1678 {
                                    phi_5941_ = _e1290;
                                    phi_2638_ = type_5();
                                } else {
                                    let _e1679 = local_88;
                                    let _e1680 = (_e1679 * 4u);
                                    local_107 = _e1680;
                                    let _e1681 = local_5;
                                    if (_e1680 < _e1681) {
                                    } else {
                                        phi_6024_ = true;
                                        break;
                                    }
                                    let _e1683 = local_107;
                                    let _e1686 = global_8.member[_e1683];
                                    local_108 = _e1686;
                                    let _e1687 = local_107;
                                    let _e1688 = (_e1687 + 1u);
                                    local_109 = _e1688;
                                    let _e1689 = local_5;
                                    if (_e1688 < _e1689) {
                                    } else {
                                        phi_6024_ = true;
                                        break;
                                    }
                                    let _e1691 = local_109;
                                    let _e1694 = global_8.member[_e1691];
                                    local_110 = _e1694;
                                    let _e1695 = local_107;
                                    let _e1696 = (_e1695 + 2u);
                                    local_111 = _e1696;
                                    let _e1697 = local_5;
                                    if (_e1696 < _e1697) {
                                    } else {
                                        phi_6024_ = true;
                                        break;
                                    }
                                    let _e1699 = local_111;
                                    let _e1702 = global_8.member[_e1699];
                                    local_112 = _e1702;
                                    let _e1703 = local_107;
                                    let _e1704 = (_e1703 + 3u);
                                    local_113 = _e1704;
                                    let _e1705 = local_5;
                                    if (_e1704 < _e1705) {
                                    } else {
                                        phi_6024_ = true;
                                        break;
                                    }
                                    let _e1707 = local_113;
                                    let _e1710 = global_8.member[_e1707];
                                    local_114 = _e1710;
                                    let _e1711 = local_110;
                                    if (_e1711 == 0u) {
                                        phi_5943_ = _e1290;
                                        phi_2632_ = type_5();
                                        phi_2633_ = true;
                                    } else {
                                        let _e1713 = local_112;
                                        let _e1714 = (_e1713 == 0u);
                                        if _e1714 {
                                            phi_5944_ = _e1290;
                                            phi_2631_ = type_5();
                                        } else {
                                            let _e1715 = local_114;
                                            let _e1718 = ((_e1715 >> bitcast<u32>(8u)) & 31u);
                                            local_563 = select(_e1718, 1u, (_e1718 == 0u));
                                            let _e1721 = local_114;
                                            let _e1725 = local_114;
                                            let _e1729 = local_108;
                                            let _e1730 = local_110;
                                            let _e1731 = local_112;
                                            let _e1732 = type_23(_e1729, _e1730, _e1731, ((_e1721 >> bitcast<u32>(1u)) & 3u), ((_e1725 >> bitcast<u32>(3u)) & 3u));
                                            let _e1733 = local_110;
                                            let _e1734 = f32(_e1733);
                                            local_115 = _e1734;
                                            let _e1735 = local_79;
                                            if ((bitcast<u32>((_e1735 * _e1734)) & 2139095040u) != 2139095040u) {
                                                let _e1740 = local_112;
                                                let _e1742 = local_78;
                                                phi_1281_ = select(true, false, ((bitcast<u32>((_e1742 * f32(_e1740))) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_1281_ = true;
                                            }
                                            let _e1749 = phi_1281_;
                                            let _e1750 = local_78;
                                            local_564 = select(_e1750, 0f, _e1749);
                                            let _e1752 = local_79;
                                            local_565 = select(_e1752, 0f, _e1749);
                                            let _e1754 = local_106;
                                            local_116 = _e1754.member;
                                            let _e1756 = local_115;
                                            let _e1757 = (_e1754.member * _e1756);
                                            let _e1758 = local_106;
                                            local_117 = _e1758.member_1;
                                            let _e1760 = local_112;
                                            let _e1761 = f32(_e1760);
                                            let _e1762 = (_e1758.member_1 * _e1761);
                                            let _e1763 = local_106;
                                            local_118 = _e1763.member_2;
                                            let _e1765 = local_115;
                                            let _e1766 = (_e1763.member_2 * _e1765);
                                            let _e1767 = local_106;
                                            local_119 = _e1767.member_3;
                                            let _e1769 = (_e1767.member_3 * _e1761);
                                            let _e1773 = sqrt(((_e1757 * _e1757) + (_e1762 * _e1762)));
                                            local_120 = _e1773;
                                            let _e1777 = sqrt(((_e1766 * _e1766) + (_e1769 * _e1769)));
                                            local_121 = _e1777;
                                            let _e1779 = select(_e1777, _e1773, (_e1773 > _e1777));
                                            local_566 = _e1779;
                                            if (_e1779 > 1f) {
                                                let _e1781 = local_566;
                                                phi_1320_ = !(((bitcast<u32>(_e1781) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_1320_ = true;
                                            }
                                            let _e1787 = phi_1320_;
                                            local_122 = _e1787;
                                            if _e1787 {
                                                phi_1416_ = 1u;
                                                phi_1417_ = 1u;
                                            } else {
                                                let _e1788 = local_120;
                                                let _e1789 = local_121;
                                                if (_e1788 >= _e1789) {
                                                    let _e1832 = local_29;
                                                    let _e1833 = f32(_e1832);
                                                    let _e1834 = local_121;
                                                    let _e1836 = local_121;
                                                    let _e1838 = ceil(select(_e1833, _e1836, (_e1834 < _e1833)));
                                                    local_123 = _e1838;
                                                    if (_e1838 < 1f) {
                                                        phi_1346_ = 1u;
                                                    } else {
                                                        let _e1840 = local_123;
                                                        let _e1842 = local_123;
                                                        let _e1845 = local_123;
                                                        phi_1346_ = select(select(u32(_e1840), 0u, !((_e1842 >= 0f))), 4294967295u, (_e1845 > 4294967000f));
                                                    }
                                                    let _e1850 = phi_1346_;
                                                    local_124 = _e1850;
                                                    if (_e1850 == 0u) {
                                                        phi_6024_ = true;
                                                        break;
                                                    }
                                                    let _e1852 = local_28;
                                                    let _e1853 = local_124;
                                                    let _e1855 = f32((_e1852 / _e1853));
                                                    let _e1856 = local_120;
                                                    let _e1858 = local_120;
                                                    let _e1860 = ceil(select(_e1855, _e1858, (_e1856 < _e1855)));
                                                    local_125 = _e1860;
                                                    if (_e1860 < 1f) {
                                                        phi_1370_ = 1u;
                                                    } else {
                                                        let _e1862 = local_125;
                                                        let _e1864 = local_125;
                                                        let _e1867 = local_125;
                                                        phi_1370_ = select(select(u32(_e1862), 0u, !((_e1864 >= 0f))), 4294967295u, (_e1867 > 4294967000f));
                                                    }
                                                    let _e1872 = phi_1370_;
                                                    phi_1414_ = _e1850;
                                                    phi_1415_ = _e1872;
                                                } else {
                                                    let _e1791 = local_29;
                                                    let _e1792 = f32(_e1791);
                                                    let _e1793 = local_120;
                                                    let _e1795 = local_120;
                                                    let _e1797 = ceil(select(_e1792, _e1795, (_e1793 < _e1792)));
                                                    local_126 = _e1797;
                                                    if (_e1797 < 1f) {
                                                        phi_1389_ = 1u;
                                                    } else {
                                                        let _e1799 = local_126;
                                                        let _e1801 = local_126;
                                                        let _e1804 = local_126;
                                                        phi_1389_ = select(select(u32(_e1799), 0u, !((_e1801 >= 0f))), 4294967295u, (_e1804 > 4294967000f));
                                                    }
                                                    let _e1809 = phi_1389_;
                                                    local_127 = _e1809;
                                                    if (_e1809 == 0u) {
                                                        phi_6024_ = true;
                                                        break;
                                                    }
                                                    let _e1811 = local_28;
                                                    let _e1812 = local_127;
                                                    let _e1814 = f32((_e1811 / _e1812));
                                                    let _e1815 = local_121;
                                                    let _e1817 = local_121;
                                                    let _e1819 = ceil(select(_e1814, _e1817, (_e1815 < _e1814)));
                                                    local_128 = _e1819;
                                                    if (_e1819 < 1f) {
                                                        phi_1413_ = 1u;
                                                    } else {
                                                        let _e1821 = local_128;
                                                        let _e1823 = local_128;
                                                        let _e1826 = local_128;
                                                        phi_1413_ = select(select(u32(_e1821), 0u, !((_e1823 >= 0f))), 4294967295u, (_e1826 > 4294967000f));
                                                    }
                                                    let _e1831 = phi_1413_;
                                                    phi_1414_ = _e1831;
                                                    phi_1415_ = _e1809;
                                                }
                                                let _e1874 = phi_1414_;
                                                let _e1876 = phi_1415_;
                                                phi_1416_ = _e1874;
                                                phi_1417_ = _e1876;
                                            }
                                            let _e1878 = phi_1416_;
                                            let _e1880 = phi_1417_;
                                            local_129 = _e1878;
                                            local_130 = _e1880;
                                            let _e1881 = local_122;
                                            if _e1881 {
                                                phi_1430_ = 1f;
                                            } else {
                                                let _e1882 = local_130;
                                                let _e1884 = local_120;
                                                let _e1885 = (_e1884 / f32(_e1882));
                                                let _e1886 = local_129;
                                                let _e1888 = local_121;
                                                let _e1889 = (_e1888 / f32(_e1886));
                                                phi_1430_ = select(_e1889, _e1885, (_e1885 > _e1889));
                                            }
                                            let _e1893 = phi_1430_;
                                            local_131 = _e1893;
                                            if (_e1893 > 1f) {
                                                let _e1895 = local_131;
                                                let _e1896 = bitcast<u32>(_e1895);
                                                let _e1905 = (bitcast<f32>(((_e1896 & 8388607u) | 1065353216u)) - 1f);
                                                phi_1451_ = (f32((bitcast<i32>(((_e1896 >> bitcast<u32>(23i)) & 255u)) - 127i)) + (_e1905 * (1.4208645f + (_e1905 * (-0.5772506f + (_e1905 * 0.1563861f))))));
                                            } else {
                                                phi_1451_ = 0f;
                                            }
                                            let _e1914 = phi_1451_;
                                            local_132 = _e1914;
                                            let _e1915 = local_563;
                                            let _e1916 = (_e1915 - 1u);
                                            local_133 = _e1916;
                                            let _e1917 = floor(_e1914);
                                            let _e1923 = select(select(u32(_e1917), 0u, !((_e1917 >= 0f))), 4294967295u, (_e1917 > 4294967000f));
                                            local_134 = _e1923;
                                            let _e1924 = (_e1923 >= _e1916);
                                            local_135 = _e1924;
                                            if _e1924 {
                                                phi_1467_ = 0f;
                                            } else {
                                                let _e1925 = local_134;
                                                let _e1927 = local_132;
                                                phi_1467_ = (_e1927 - f32(_e1925));
                                            }
                                            let _e1930 = phi_1467_;
                                            local_136 = _e1930;
                                            let _e1931 = local_135;
                                            let _e1932 = local_133;
                                            let _e1933 = local_134;
                                            local_567 = select(_e1933, _e1932, _e1931);
                                            local_568 = select(1u, 2u, (_e1930 > 0f));
                                            phi_5550_ = 0u;
                                            phi_5551_ = _e1732;
                                            loop {
                                                let _e1938 = phi_5550_;
                                                let _e1940 = phi_5551_;
                                                local_535 = _e1938;
                                                local_536 = _e1940;
                                                local_628 = _e1940;
                                                let _e1941 = local_535;
                                                let _e1942 = local_567;
                                                let _e1943 = (_e1941 < _e1942);
                                                local_537 = _e1943;
                                                if _e1943 {
                                                    let _e1944 = local_536;
                                                    local_538 = _e1944.member_1;
                                                    let _e1946 = local_536;
                                                    local_539 = _e1946.member_2;
                                                    let _e1949 = local_536;
                                                    let _e1952 = local_536;
                                                    local_540 = type_23((_e1949.member + (_e1944.member_1 * _e1946.member_2)), _e1952.member_1, _e1952.member_2, _e1952.member_3, _e1952.member_4);
                                                    if (_e1944.member_1 > 1u) {
                                                        let _e1960 = local_538;
                                                        phi_5568_ = (_e1960 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5568_ = 1u;
                                                    }
                                                    let _e1964 = phi_5568_;
                                                    let _e1965 = local_540;
                                                    local_541 = type_23(_e1965.member, _e1964, _e1965.member_2, _e1965.member_3, _e1965.member_4);
                                                    let _e1972 = local_539;
                                                    if (_e1972 > 1u) {
                                                        let _e1974 = local_539;
                                                        phi_5577_ = (_e1974 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5577_ = 1u;
                                                    }
                                                    let _e1978 = phi_5577_;
                                                    let _e1979 = local_541;
                                                    let _e1986 = local_535;
                                                    phi_5582_ = (_e1986 + 1u);
                                                    phi_5583_ = type_23(_e1979.member, _e1979.member_1, _e1978, _e1979.member_3, _e1979.member_4);
                                                } else {
                                                    phi_5582_ = u32();
                                                    phi_5583_ = type_23();
                                                }
                                                let _e1989 = phi_5582_;
                                                let _e1991 = phi_5583_;
                                                continue;
                                                continuing {
                                                    let _e1992 = local_537;
                                                    phi_5550_ = _e1989;
                                                    phi_5551_ = _e1991;
                                                    break if !(_e1992);
                                                }
                                            }
                                            let _e1994 = local_567;
                                            let _e1995 = local_568;
                                            local_137 = ((_e1994 + _e1995) - 1u);
                                            phi_5589_ = 0u;
                                            phi_5590_ = _e1732;
                                            loop {
                                                let _e1999 = phi_5589_;
                                                let _e2001 = phi_5590_;
                                                local_542 = _e1999;
                                                local_543 = _e2001;
                                                local_629 = _e2001;
                                                let _e2002 = local_542;
                                                let _e2003 = local_137;
                                                let _e2004 = (_e2002 < _e2003);
                                                local_544 = _e2004;
                                                if _e2004 {
                                                    let _e2005 = local_543;
                                                    local_545 = _e2005.member_1;
                                                    let _e2007 = local_543;
                                                    local_546 = _e2007.member_2;
                                                    let _e2010 = local_543;
                                                    let _e2013 = local_543;
                                                    local_547 = type_23((_e2010.member + (_e2005.member_1 * _e2007.member_2)), _e2013.member_1, _e2013.member_2, _e2013.member_3, _e2013.member_4);
                                                    if (_e2005.member_1 > 1u) {
                                                        let _e2021 = local_545;
                                                        phi_5607_ = (_e2021 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5607_ = 1u;
                                                    }
                                                    let _e2025 = phi_5607_;
                                                    let _e2026 = local_547;
                                                    local_548 = type_23(_e2026.member, _e2025, _e2026.member_2, _e2026.member_3, _e2026.member_4);
                                                    let _e2033 = local_546;
                                                    if (_e2033 > 1u) {
                                                        let _e2035 = local_546;
                                                        phi_5616_ = (_e2035 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5616_ = 1u;
                                                    }
                                                    let _e2039 = phi_5616_;
                                                    let _e2040 = local_548;
                                                    let _e2047 = local_542;
                                                    phi_5621_ = (_e2047 + 1u);
                                                    phi_5622_ = type_23(_e2040.member, _e2040.member_1, _e2039, _e2040.member_3, _e2040.member_4);
                                                } else {
                                                    phi_5621_ = u32();
                                                    phi_5622_ = type_23();
                                                }
                                                let _e2050 = phi_5621_;
                                                let _e2052 = phi_5622_;
                                                continue;
                                                continuing {
                                                    let _e2053 = local_544;
                                                    phi_5589_ = _e2050;
                                                    phi_5590_ = _e2052;
                                                    break if !(_e2053);
                                                }
                                            }
                                            let _e2055 = local_122;
                                            if _e2055 {
                                                let _e2056 = local_114;
                                                phi_1483_ = ((_e2056 & 1u) != 0u);
                                            } else {
                                                phi_1483_ = false;
                                            }
                                            let _e2060 = phi_1483_;
                                            local_138 = _e2060;
                                            phi_5800_ = _e1290;
                                            phi_1486_ = 0u;
                                            phi_1489_ = type_5(0f, 0f, 0f, 0f);
                                            loop {
                                                let _e2062 = phi_5800_;
                                                let _e2064 = phi_1486_;
                                                let _e2066 = phi_1489_;
                                                local_139 = _e2064;
                                                local_140 = _e2066;
                                                let _e2067 = local_139;
                                                let _e2068 = local_130;
                                                let _e2069 = (_e2067 < _e2068);
                                                local_141 = _e2069;
                                                if _e2069 {
                                                    let _e2070 = local_139;
                                                    let _e2073 = local_130;
                                                    local_142 = (((f32(_e2070) + 0.5f) / f32(_e2073)) - 0.5f);
                                                    phi_5799_ = _e2062;
                                                    phi_1503_ = 0u;
                                                    phi_1506_ = _e2066;
                                                    loop {
                                                        let _e2078 = phi_5799_;
                                                        let _e2080 = phi_1503_;
                                                        let _e2082 = phi_1506_;
                                                        local_143 = _e2080;
                                                        local_631 = _e2082;
                                                        let _e2083 = local_143;
                                                        let _e2084 = local_129;
                                                        let _e2085 = (_e2083 < _e2084);
                                                        local_144 = _e2085;
                                                        if _e2085 {
                                                            let _e2086 = local_143;
                                                            let _e2089 = local_129;
                                                            let _e2092 = (((f32(_e2086) + 0.5f) / f32(_e2089)) - 0.5f);
                                                            let _e2093 = local_142;
                                                            let _e2094 = local_116;
                                                            let _e2096 = local_565;
                                                            let _e2098 = local_118;
                                                            local_145 = ((_e2096 + (_e2093 * _e2094)) + (_e2092 * _e2098));
                                                            let _e2101 = local_142;
                                                            let _e2102 = local_117;
                                                            let _e2104 = local_564;
                                                            let _e2106 = local_119;
                                                            local_146 = ((_e2104 + (_e2101 * _e2102)) + (_e2092 * _e2106));
                                                            phi_1532_ = 0u;
                                                            phi_1535_ = _e2082;
                                                            loop {
                                                                let _e2110 = phi_1532_;
                                                                let _e2112 = phi_1535_;
                                                                local_147 = _e2110;
                                                                local_148 = _e2112;
                                                                local_630 = _e2112;
                                                                let _e2113 = local_147;
                                                                let _e2114 = local_568;
                                                                let _e2115 = (_e2113 < _e2114);
                                                                local_149 = _e2115;
                                                                if _e2115 {
                                                                    let _e2116 = local_147;
                                                                    if (_e2116 == 0u) {
                                                                        let _e2118 = local_136;
                                                                        let _e5587 = local_628;
                                                                        phi_1548_ = _e5587;
                                                                        phi_1549_ = (1f - _e2118);
                                                                    } else {
                                                                        let _e5589 = local_629;
                                                                        phi_1548_ = _e5589;
                                                                        phi_1549_ = _e1930;
                                                                    }
                                                                    let _e2121 = phi_1548_;
                                                                    let _e2123 = phi_1549_;
                                                                    local_150 = _e2121;
                                                                    local_151 = _e2123;
                                                                    let _e2124 = local_138;
                                                                    let _e2125 = select(0.5f, 0f, _e2124);
                                                                    local_152 = _e2121.member_1;
                                                                    let _e2128 = local_145;
                                                                    let _e2130 = ((_e2128 * f32(_e2121.member_1)) - _e2125);
                                                                    local_153 = _e2130;
                                                                    local_154 = _e2121.member_2;
                                                                    let _e2133 = local_146;
                                                                    let _e2135 = ((_e2133 * f32(_e2121.member_2)) - _e2125);
                                                                    local_155 = _e2135;
                                                                    local_156 = floor(_e2130);
                                                                    local_157 = floor(_e2135);
                                                                    let _e2138 = local_138;
                                                                    if _e2138 {
                                                                        phi_1569_ = 0f;
                                                                        phi_1570_ = 0f;
                                                                    } else {
                                                                        let _e2139 = local_153;
                                                                        let _e2140 = local_156;
                                                                        let _e2142 = local_155;
                                                                        let _e2143 = local_157;
                                                                        phi_1569_ = (_e2142 - _e2143);
                                                                        phi_1570_ = (_e2139 - _e2140);
                                                                    }
                                                                    let _e2146 = phi_1569_;
                                                                    let _e2148 = phi_1570_;
                                                                    local_158 = _e2146;
                                                                    local_159 = _e2148;
                                                                    let _e2149 = local_156;
                                                                    let _e2151 = local_156;
                                                                    let _e2154 = local_156;
                                                                    let _e2158 = local_156;
                                                                    let _e2159 = local_156;
                                                                    let _e2161 = select(0i, select(select(i32(_e2149), i32(-2147483648), !((_e2151 >= -2147483600f))), 2147483647i, (_e2154 > 2147483500f)), (_e2158 == _e2159));
                                                                    local_160 = _e2161;
                                                                    let _e2162 = local_157;
                                                                    let _e2164 = local_157;
                                                                    let _e2167 = local_157;
                                                                    let _e2171 = local_157;
                                                                    let _e2172 = local_157;
                                                                    let _e2174 = select(0i, select(select(i32(_e2162), i32(-2147483648), !((_e2164 >= -2147483600f))), 2147483647i, (_e2167 > 2147483500f)), (_e2171 == _e2172));
                                                                    local_161 = _e2174;
                                                                    let _e2175 = local_150;
                                                                    local_162 = _e2175.member_3;
                                                                    let _e2177 = local_152;
                                                                    local_163 = bitcast<i32>(_e2177);
                                                                    let _e2179 = (_e2175.member_3 == 1u);
                                                                    local_164 = _e2179;
                                                                    if _e2179 {
                                                                        let _e2233 = local_160;
                                                                        if (_e2233 < 0i) {
                                                                            phi_1606_ = 0i;
                                                                        } else {
                                                                            let _e2235 = local_160;
                                                                            let _e2236 = local_163;
                                                                            if (_e2235 >= _e2236) {
                                                                                let _e2238 = local_163;
                                                                                phi_1605_ = (_e2238 - 1i);
                                                                            } else {
                                                                                phi_1605_ = _e2161;
                                                                            }
                                                                            let _e2241 = phi_1605_;
                                                                            phi_1606_ = _e2241;
                                                                        }
                                                                        let _e2243 = phi_1606_;
                                                                        phi_1666_ = _e2243;
                                                                    } else {
                                                                        let _e2180 = local_162;
                                                                        if (_e2180 == 2u) {
                                                                            let _e2202 = local_163;
                                                                            let _e2203 = (2i * _e2202);
                                                                            local_165 = _e2203;
                                                                            let _e2204 = (_e2203 == 0i);
                                                                            local_166 = _e2204;
                                                                            if _e2204 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2205 = local_165;
                                                                            let _e2206 = (_e2205 == -1i);
                                                                            local_167 = _e2206;
                                                                            let _e2207 = local_160;
                                                                            if (_e2206 && (_e2207 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2210 = local_160;
                                                                            let _e2211 = local_165;
                                                                            let _e2213 = local_165;
                                                                            local_168 = ((_e2210 % _e2211) + _e2213);
                                                                            let _e2215 = local_166;
                                                                            if _e2215 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2216 = local_168;
                                                                            let _e2218 = local_167;
                                                                            if (_e2218 && (_e2216 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2220 = local_168;
                                                                            let _e2221 = local_165;
                                                                            let _e2222 = (_e2220 % _e2221);
                                                                            local_169 = _e2222;
                                                                            let _e2223 = local_163;
                                                                            if (_e2222 < _e2223) {
                                                                                phi_1641_ = _e2222;
                                                                            } else {
                                                                                let _e2225 = local_165;
                                                                                let _e2227 = local_169;
                                                                                phi_1641_ = ((_e2225 - 1i) - _e2227);
                                                                            }
                                                                            let _e2230 = phi_1641_;
                                                                            phi_1665_ = _e2230;
                                                                        } else {
                                                                            let _e2182 = local_163;
                                                                            let _e2183 = (_e2182 == 0i);
                                                                            local_170 = _e2183;
                                                                            if _e2183 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2184 = local_163;
                                                                            let _e2185 = (_e2184 == -1i);
                                                                            local_171 = _e2185;
                                                                            let _e2186 = local_160;
                                                                            if (_e2185 && (_e2186 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2189 = local_160;
                                                                            let _e2190 = local_163;
                                                                            let _e2192 = local_163;
                                                                            local_172 = ((_e2189 % _e2190) + _e2192);
                                                                            let _e2194 = local_170;
                                                                            if _e2194 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2195 = local_172;
                                                                            let _e2197 = local_171;
                                                                            if (_e2197 && (_e2195 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2199 = local_172;
                                                                            let _e2200 = local_163;
                                                                            phi_1665_ = (_e2199 % _e2200);
                                                                        }
                                                                        let _e2232 = phi_1665_;
                                                                        phi_1666_ = _e2232;
                                                                    }
                                                                    let _e2245 = phi_1666_;
                                                                    local_173 = bitcast<u32>(_e2245);
                                                                    let _e2247 = local_160;
                                                                    let _e2248 = (_e2247 + 1i);
                                                                    local_174 = _e2248;
                                                                    let _e2249 = local_164;
                                                                    if _e2249 {
                                                                        let _e2303 = local_174;
                                                                        if (_e2303 < 0i) {
                                                                            phi_1686_ = 0i;
                                                                        } else {
                                                                            let _e2305 = local_174;
                                                                            let _e2306 = local_163;
                                                                            if (_e2305 >= _e2306) {
                                                                                let _e2308 = local_163;
                                                                                phi_1685_ = (_e2308 - 1i);
                                                                            } else {
                                                                                phi_1685_ = _e2248;
                                                                            }
                                                                            let _e2311 = phi_1685_;
                                                                            phi_1686_ = _e2311;
                                                                        }
                                                                        let _e2313 = phi_1686_;
                                                                        phi_1746_ = _e2313;
                                                                    } else {
                                                                        let _e2250 = local_162;
                                                                        if (_e2250 == 2u) {
                                                                            let _e2272 = local_163;
                                                                            let _e2273 = (2i * _e2272);
                                                                            local_175 = _e2273;
                                                                            let _e2274 = (_e2273 == 0i);
                                                                            local_176 = _e2274;
                                                                            if _e2274 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2275 = local_175;
                                                                            let _e2276 = (_e2275 == -1i);
                                                                            local_177 = _e2276;
                                                                            let _e2277 = local_174;
                                                                            if (_e2276 && (_e2277 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2280 = local_174;
                                                                            let _e2281 = local_175;
                                                                            let _e2283 = local_175;
                                                                            local_178 = ((_e2280 % _e2281) + _e2283);
                                                                            let _e2285 = local_176;
                                                                            if _e2285 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2286 = local_178;
                                                                            let _e2288 = local_177;
                                                                            if (_e2288 && (_e2286 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2290 = local_178;
                                                                            let _e2291 = local_175;
                                                                            let _e2292 = (_e2290 % _e2291);
                                                                            local_179 = _e2292;
                                                                            let _e2293 = local_163;
                                                                            if (_e2292 < _e2293) {
                                                                                phi_1721_ = _e2292;
                                                                            } else {
                                                                                let _e2295 = local_175;
                                                                                let _e2297 = local_179;
                                                                                phi_1721_ = ((_e2295 - 1i) - _e2297);
                                                                            }
                                                                            let _e2300 = phi_1721_;
                                                                            phi_1745_ = _e2300;
                                                                        } else {
                                                                            let _e2252 = local_163;
                                                                            let _e2253 = (_e2252 == 0i);
                                                                            local_180 = _e2253;
                                                                            if _e2253 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2254 = local_163;
                                                                            let _e2255 = (_e2254 == -1i);
                                                                            local_181 = _e2255;
                                                                            let _e2256 = local_174;
                                                                            if (_e2255 && (_e2256 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2259 = local_174;
                                                                            let _e2260 = local_163;
                                                                            let _e2262 = local_163;
                                                                            local_182 = ((_e2259 % _e2260) + _e2262);
                                                                            let _e2264 = local_180;
                                                                            if _e2264 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2265 = local_182;
                                                                            let _e2267 = local_181;
                                                                            if (_e2267 && (_e2265 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2269 = local_182;
                                                                            let _e2270 = local_163;
                                                                            phi_1745_ = (_e2269 % _e2270);
                                                                        }
                                                                        let _e2302 = phi_1745_;
                                                                        phi_1746_ = _e2302;
                                                                    }
                                                                    let _e2315 = phi_1746_;
                                                                    local_183 = bitcast<u32>(_e2315);
                                                                    let _e2317 = local_150;
                                                                    local_184 = _e2317.member_4;
                                                                    let _e2319 = local_154;
                                                                    local_185 = bitcast<i32>(_e2319);
                                                                    let _e2321 = (_e2317.member_4 == 1u);
                                                                    local_186 = _e2321;
                                                                    if _e2321 {
                                                                        let _e2375 = local_161;
                                                                        if (_e2375 < 0i) {
                                                                            phi_1765_ = 0i;
                                                                        } else {
                                                                            let _e2377 = local_161;
                                                                            let _e2378 = local_185;
                                                                            if (_e2377 >= _e2378) {
                                                                                let _e2380 = local_185;
                                                                                phi_1764_ = (_e2380 - 1i);
                                                                            } else {
                                                                                phi_1764_ = _e2174;
                                                                            }
                                                                            let _e2383 = phi_1764_;
                                                                            phi_1765_ = _e2383;
                                                                        }
                                                                        let _e2385 = phi_1765_;
                                                                        phi_1825_ = _e2385;
                                                                    } else {
                                                                        let _e2322 = local_184;
                                                                        if (_e2322 == 2u) {
                                                                            let _e2344 = local_185;
                                                                            let _e2345 = (2i * _e2344);
                                                                            local_187 = _e2345;
                                                                            let _e2346 = (_e2345 == 0i);
                                                                            local_188 = _e2346;
                                                                            if _e2346 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2347 = local_187;
                                                                            let _e2348 = (_e2347 == -1i);
                                                                            local_189 = _e2348;
                                                                            let _e2349 = local_161;
                                                                            if (_e2348 && (_e2349 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2352 = local_161;
                                                                            let _e2353 = local_187;
                                                                            let _e2355 = local_187;
                                                                            local_190 = ((_e2352 % _e2353) + _e2355);
                                                                            let _e2357 = local_188;
                                                                            if _e2357 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2358 = local_190;
                                                                            let _e2360 = local_189;
                                                                            if (_e2360 && (_e2358 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2362 = local_190;
                                                                            let _e2363 = local_187;
                                                                            let _e2364 = (_e2362 % _e2363);
                                                                            local_191 = _e2364;
                                                                            let _e2365 = local_185;
                                                                            if (_e2364 < _e2365) {
                                                                                phi_1800_ = _e2364;
                                                                            } else {
                                                                                let _e2367 = local_187;
                                                                                let _e2369 = local_191;
                                                                                phi_1800_ = ((_e2367 - 1i) - _e2369);
                                                                            }
                                                                            let _e2372 = phi_1800_;
                                                                            phi_1824_ = _e2372;
                                                                        } else {
                                                                            let _e2324 = local_185;
                                                                            let _e2325 = (_e2324 == 0i);
                                                                            local_192 = _e2325;
                                                                            if _e2325 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2326 = local_185;
                                                                            let _e2327 = (_e2326 == -1i);
                                                                            local_193 = _e2327;
                                                                            let _e2328 = local_161;
                                                                            if (_e2327 && (_e2328 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2331 = local_161;
                                                                            let _e2332 = local_185;
                                                                            let _e2334 = local_185;
                                                                            local_194 = ((_e2331 % _e2332) + _e2334);
                                                                            let _e2336 = local_192;
                                                                            if _e2336 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2337 = local_194;
                                                                            let _e2339 = local_193;
                                                                            if (_e2339 && (_e2337 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2341 = local_194;
                                                                            let _e2342 = local_185;
                                                                            phi_1824_ = (_e2341 % _e2342);
                                                                        }
                                                                        let _e2374 = phi_1824_;
                                                                        phi_1825_ = _e2374;
                                                                    }
                                                                    let _e2387 = phi_1825_;
                                                                    local_195 = bitcast<u32>(_e2387);
                                                                    let _e2389 = local_161;
                                                                    let _e2390 = (_e2389 + 1i);
                                                                    local_196 = _e2390;
                                                                    let _e2391 = local_186;
                                                                    if _e2391 {
                                                                        let _e2445 = local_196;
                                                                        if (_e2445 < 0i) {
                                                                            phi_1845_ = 0i;
                                                                        } else {
                                                                            let _e2447 = local_196;
                                                                            let _e2448 = local_185;
                                                                            if (_e2447 >= _e2448) {
                                                                                let _e2450 = local_185;
                                                                                phi_1844_ = (_e2450 - 1i);
                                                                            } else {
                                                                                phi_1844_ = _e2390;
                                                                            }
                                                                            let _e2453 = phi_1844_;
                                                                            phi_1845_ = _e2453;
                                                                        }
                                                                        let _e2455 = phi_1845_;
                                                                        phi_1905_ = _e2455;
                                                                    } else {
                                                                        let _e2392 = local_184;
                                                                        if (_e2392 == 2u) {
                                                                            let _e2414 = local_185;
                                                                            let _e2415 = (2i * _e2414);
                                                                            local_197 = _e2415;
                                                                            let _e2416 = (_e2415 == 0i);
                                                                            local_198 = _e2416;
                                                                            if _e2416 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2417 = local_197;
                                                                            let _e2418 = (_e2417 == -1i);
                                                                            local_199 = _e2418;
                                                                            let _e2419 = local_196;
                                                                            if (_e2418 && (_e2419 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2422 = local_196;
                                                                            let _e2423 = local_197;
                                                                            let _e2425 = local_197;
                                                                            local_200 = ((_e2422 % _e2423) + _e2425);
                                                                            let _e2427 = local_198;
                                                                            if _e2427 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2428 = local_200;
                                                                            let _e2430 = local_199;
                                                                            if (_e2430 && (_e2428 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2432 = local_200;
                                                                            let _e2433 = local_197;
                                                                            let _e2434 = (_e2432 % _e2433);
                                                                            local_201 = _e2434;
                                                                            let _e2435 = local_185;
                                                                            if (_e2434 < _e2435) {
                                                                                phi_1880_ = _e2434;
                                                                            } else {
                                                                                let _e2437 = local_197;
                                                                                let _e2439 = local_201;
                                                                                phi_1880_ = ((_e2437 - 1i) - _e2439);
                                                                            }
                                                                            let _e2442 = phi_1880_;
                                                                            phi_1904_ = _e2442;
                                                                        } else {
                                                                            let _e2394 = local_185;
                                                                            let _e2395 = (_e2394 == 0i);
                                                                            local_202 = _e2395;
                                                                            if _e2395 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2396 = local_185;
                                                                            let _e2397 = (_e2396 == -1i);
                                                                            local_203 = _e2397;
                                                                            let _e2398 = local_196;
                                                                            if (_e2397 && (_e2398 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2401 = local_196;
                                                                            let _e2402 = local_185;
                                                                            let _e2404 = local_185;
                                                                            local_204 = ((_e2401 % _e2402) + _e2404);
                                                                            let _e2406 = local_202;
                                                                            if _e2406 {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2407 = local_204;
                                                                            let _e2409 = local_203;
                                                                            if (_e2409 && (_e2407 == i32(-2147483648))) {
                                                                                phi_5753_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2411 = local_204;
                                                                            let _e2412 = local_185;
                                                                            phi_1904_ = (_e2411 % _e2412);
                                                                        }
                                                                        let _e2444 = phi_1904_;
                                                                        phi_1905_ = _e2444;
                                                                    }
                                                                    let _e2457 = phi_1905_;
                                                                    local_205 = bitcast<u32>(_e2457);
                                                                    let _e2459 = local_150;
                                                                    local_206 = _e2459.member;
                                                                    let _e2461 = local_195;
                                                                    let _e2462 = local_152;
                                                                    let _e2464 = (_e2459.member + (_e2461 * _e2462));
                                                                    local_207 = _e2464;
                                                                    let _e2465 = local_173;
                                                                    let _e2467 = ((_e2464 + _e2465) * 2u);
                                                                    local_208 = _e2467;
                                                                    let _e2468 = local_6;
                                                                    if (_e2467 < _e2468) {
                                                                    } else {
                                                                        phi_5753_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2470 = local_208;
                                                                    let _e2473 = global_9.member[_e2470];
                                                                    local_209 = _e2473;
                                                                    let _e2474 = local_208;
                                                                    let _e2475 = (_e2474 + 1u);
                                                                    local_210 = _e2475;
                                                                    let _e2476 = local_6;
                                                                    if (_e2475 < _e2476) {
                                                                    } else {
                                                                        phi_5753_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2478 = local_210;
                                                                    let _e2481 = global_9.member[_e2478];
                                                                    local_211 = _e2481;
                                                                    let _e2482 = local_209;
                                                                    let _e2483 = (_e2482 & 65535u);
                                                                    local_569 = select(-1f, 1f, ((_e2483 & 32768u) == 0u));
                                                                    let _e2489 = ((_e2483 >> bitcast<u32>(10i)) & 31u);
                                                                    local_212 = _e2489;
                                                                    local_213 = (_e2483 & 1023u);
                                                                    if (_e2489 == 0u) {
                                                                        let _e2511 = local_213;
                                                                        let _e2513 = local_569;
                                                                        phi_1975_ = ((_e2513 * f32(_e2511)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2492 = local_212;
                                                                        if (_e2492 == 31u) {
                                                                            let _e2502 = local_213;
                                                                            phi_1972_ = (2139095040u | (_e2502 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2494 = local_212;
                                                                            let _e2498 = local_213;
                                                                            phi_1972_ = (((_e2494 + 112u) << bitcast<u32>(23i)) | (_e2498 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2507 = phi_1972_;
                                                                        let _e2509 = local_569;
                                                                        phi_1975_ = (_e2509 * bitcast<f32>(_e2507));
                                                                    }
                                                                    let _e2517 = phi_1975_;
                                                                    local_214 = _e2517;
                                                                    let _e2518 = local_209;
                                                                    let _e2520 = (_e2518 >> bitcast<u32>(16i));
                                                                    local_570 = select(-1f, 1f, ((_e2520 & 32768u) == 0u));
                                                                    let _e2526 = ((_e2520 >> bitcast<u32>(10i)) & 31u);
                                                                    local_215 = _e2526;
                                                                    local_216 = (_e2520 & 1023u);
                                                                    if (_e2526 == 0u) {
                                                                        let _e2548 = local_216;
                                                                        let _e2550 = local_570;
                                                                        phi_2007_ = ((_e2550 * f32(_e2548)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2529 = local_215;
                                                                        if (_e2529 == 31u) {
                                                                            let _e2539 = local_216;
                                                                            phi_2004_ = (2139095040u | (_e2539 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2531 = local_215;
                                                                            let _e2535 = local_216;
                                                                            phi_2004_ = (((_e2531 + 112u) << bitcast<u32>(23i)) | (_e2535 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2544 = phi_2004_;
                                                                        let _e2546 = local_570;
                                                                        phi_2007_ = (_e2546 * bitcast<f32>(_e2544));
                                                                    }
                                                                    let _e2554 = phi_2007_;
                                                                    local_217 = _e2554;
                                                                    let _e2555 = local_211;
                                                                    let _e2556 = (_e2555 & 65535u);
                                                                    local_571 = select(-1f, 1f, ((_e2556 & 32768u) == 0u));
                                                                    let _e2562 = ((_e2556 >> bitcast<u32>(10i)) & 31u);
                                                                    local_218 = _e2562;
                                                                    local_219 = (_e2556 & 1023u);
                                                                    if (_e2562 == 0u) {
                                                                        let _e2584 = local_219;
                                                                        let _e2586 = local_571;
                                                                        phi_2039_ = ((_e2586 * f32(_e2584)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2565 = local_218;
                                                                        if (_e2565 == 31u) {
                                                                            let _e2575 = local_219;
                                                                            phi_2036_ = (2139095040u | (_e2575 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2567 = local_218;
                                                                            let _e2571 = local_219;
                                                                            phi_2036_ = (((_e2567 + 112u) << bitcast<u32>(23i)) | (_e2571 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2580 = phi_2036_;
                                                                        let _e2582 = local_571;
                                                                        phi_2039_ = (_e2582 * bitcast<f32>(_e2580));
                                                                    }
                                                                    let _e2590 = phi_2039_;
                                                                    local_220 = _e2590;
                                                                    let _e2591 = local_211;
                                                                    let _e2593 = (_e2591 >> bitcast<u32>(16i));
                                                                    local_572 = select(-1f, 1f, ((_e2593 & 32768u) == 0u));
                                                                    let _e2599 = ((_e2593 >> bitcast<u32>(10i)) & 31u);
                                                                    local_221 = _e2599;
                                                                    local_222 = (_e2593 & 1023u);
                                                                    if (_e2599 == 0u) {
                                                                        let _e2621 = local_222;
                                                                        let _e2623 = local_572;
                                                                        phi_2071_ = ((_e2623 * f32(_e2621)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2602 = local_221;
                                                                        if (_e2602 == 31u) {
                                                                            let _e2612 = local_222;
                                                                            phi_2068_ = (2139095040u | (_e2612 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2604 = local_221;
                                                                            let _e2608 = local_222;
                                                                            phi_2068_ = (((_e2604 + 112u) << bitcast<u32>(23i)) | (_e2608 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2617 = phi_2068_;
                                                                        let _e2619 = local_572;
                                                                        phi_2071_ = (_e2619 * bitcast<f32>(_e2617));
                                                                    }
                                                                    let _e2627 = phi_2071_;
                                                                    local_223 = _e2627;
                                                                    let _e2628 = local_207;
                                                                    let _e2629 = local_183;
                                                                    let _e2631 = ((_e2628 + _e2629) * 2u);
                                                                    local_224 = _e2631;
                                                                    let _e2632 = local_6;
                                                                    if (_e2631 < _e2632) {
                                                                    } else {
                                                                        phi_5753_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2634 = local_224;
                                                                    let _e2637 = global_9.member[_e2634];
                                                                    local_225 = _e2637;
                                                                    let _e2638 = local_224;
                                                                    let _e2639 = (_e2638 + 1u);
                                                                    local_226 = _e2639;
                                                                    let _e2640 = local_6;
                                                                    if (_e2639 < _e2640) {
                                                                    } else {
                                                                        phi_5753_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2642 = local_226;
                                                                    let _e2645 = global_9.member[_e2642];
                                                                    local_227 = _e2645;
                                                                    let _e2646 = local_225;
                                                                    let _e2647 = (_e2646 & 65535u);
                                                                    local_573 = select(-1f, 1f, ((_e2647 & 32768u) == 0u));
                                                                    let _e2653 = ((_e2647 >> bitcast<u32>(10i)) & 31u);
                                                                    local_228 = _e2653;
                                                                    local_229 = (_e2647 & 1023u);
                                                                    if (_e2653 == 0u) {
                                                                        let _e2675 = local_229;
                                                                        let _e2677 = local_573;
                                                                        phi_2140_ = ((_e2677 * f32(_e2675)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2656 = local_228;
                                                                        if (_e2656 == 31u) {
                                                                            let _e2666 = local_229;
                                                                            phi_2137_ = (2139095040u | (_e2666 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2658 = local_228;
                                                                            let _e2662 = local_229;
                                                                            phi_2137_ = (((_e2658 + 112u) << bitcast<u32>(23i)) | (_e2662 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2671 = phi_2137_;
                                                                        let _e2673 = local_573;
                                                                        phi_2140_ = (_e2673 * bitcast<f32>(_e2671));
                                                                    }
                                                                    let _e2681 = phi_2140_;
                                                                    local_230 = _e2681;
                                                                    let _e2682 = local_225;
                                                                    let _e2684 = (_e2682 >> bitcast<u32>(16i));
                                                                    local_574 = select(-1f, 1f, ((_e2684 & 32768u) == 0u));
                                                                    let _e2690 = ((_e2684 >> bitcast<u32>(10i)) & 31u);
                                                                    local_231 = _e2690;
                                                                    local_232 = (_e2684 & 1023u);
                                                                    if (_e2690 == 0u) {
                                                                        let _e2712 = local_232;
                                                                        let _e2714 = local_574;
                                                                        phi_2172_ = ((_e2714 * f32(_e2712)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2693 = local_231;
                                                                        if (_e2693 == 31u) {
                                                                            let _e2703 = local_232;
                                                                            phi_2169_ = (2139095040u | (_e2703 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2695 = local_231;
                                                                            let _e2699 = local_232;
                                                                            phi_2169_ = (((_e2695 + 112u) << bitcast<u32>(23i)) | (_e2699 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2708 = phi_2169_;
                                                                        let _e2710 = local_574;
                                                                        phi_2172_ = (_e2710 * bitcast<f32>(_e2708));
                                                                    }
                                                                    let _e2718 = phi_2172_;
                                                                    local_233 = _e2718;
                                                                    let _e2719 = local_227;
                                                                    let _e2720 = (_e2719 & 65535u);
                                                                    local_575 = select(-1f, 1f, ((_e2720 & 32768u) == 0u));
                                                                    let _e2726 = ((_e2720 >> bitcast<u32>(10i)) & 31u);
                                                                    local_234 = _e2726;
                                                                    local_235 = (_e2720 & 1023u);
                                                                    if (_e2726 == 0u) {
                                                                        let _e2748 = local_235;
                                                                        let _e2750 = local_575;
                                                                        phi_2204_ = ((_e2750 * f32(_e2748)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2729 = local_234;
                                                                        if (_e2729 == 31u) {
                                                                            let _e2739 = local_235;
                                                                            phi_2201_ = (2139095040u | (_e2739 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2731 = local_234;
                                                                            let _e2735 = local_235;
                                                                            phi_2201_ = (((_e2731 + 112u) << bitcast<u32>(23i)) | (_e2735 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2744 = phi_2201_;
                                                                        let _e2746 = local_575;
                                                                        phi_2204_ = (_e2746 * bitcast<f32>(_e2744));
                                                                    }
                                                                    let _e2754 = phi_2204_;
                                                                    local_236 = _e2754;
                                                                    let _e2755 = local_227;
                                                                    let _e2757 = (_e2755 >> bitcast<u32>(16i));
                                                                    local_576 = select(-1f, 1f, ((_e2757 & 32768u) == 0u));
                                                                    let _e2763 = ((_e2757 >> bitcast<u32>(10i)) & 31u);
                                                                    local_237 = _e2763;
                                                                    local_238 = (_e2757 & 1023u);
                                                                    if (_e2763 == 0u) {
                                                                        let _e2785 = local_238;
                                                                        let _e2787 = local_576;
                                                                        phi_2236_ = ((_e2787 * f32(_e2785)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2766 = local_237;
                                                                        if (_e2766 == 31u) {
                                                                            let _e2776 = local_238;
                                                                            phi_2233_ = (2139095040u | (_e2776 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2768 = local_237;
                                                                            let _e2772 = local_238;
                                                                            phi_2233_ = (((_e2768 + 112u) << bitcast<u32>(23i)) | (_e2772 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2781 = phi_2233_;
                                                                        let _e2783 = local_576;
                                                                        phi_2236_ = (_e2783 * bitcast<f32>(_e2781));
                                                                    }
                                                                    let _e2791 = phi_2236_;
                                                                    let _e2792 = local_230;
                                                                    let _e2793 = local_214;
                                                                    let _e2795 = local_159;
                                                                    let _e2797 = local_214;
                                                                    local_239 = (_e2797 + ((_e2792 - _e2793) * _e2795));
                                                                    let _e2799 = local_233;
                                                                    let _e2800 = local_217;
                                                                    let _e2802 = local_159;
                                                                    let _e2804 = local_217;
                                                                    local_240 = (_e2804 + ((_e2799 - _e2800) * _e2802));
                                                                    let _e2806 = local_236;
                                                                    let _e2807 = local_220;
                                                                    let _e2809 = local_159;
                                                                    let _e2811 = local_220;
                                                                    local_241 = (_e2811 + ((_e2806 - _e2807) * _e2809));
                                                                    let _e2813 = local_223;
                                                                    let _e2815 = local_159;
                                                                    let _e2817 = local_223;
                                                                    local_242 = (_e2817 + ((_e2791 - _e2813) * _e2815));
                                                                    let _e2819 = local_205;
                                                                    let _e2820 = local_152;
                                                                    let _e2822 = local_206;
                                                                    let _e2823 = (_e2822 + (_e2819 * _e2820));
                                                                    local_243 = _e2823;
                                                                    let _e2824 = local_173;
                                                                    let _e2826 = ((_e2823 + _e2824) * 2u);
                                                                    local_244 = _e2826;
                                                                    let _e2827 = local_6;
                                                                    if (_e2826 < _e2827) {
                                                                    } else {
                                                                        phi_5753_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2829 = local_244;
                                                                    let _e2832 = global_9.member[_e2829];
                                                                    local_245 = _e2832;
                                                                    let _e2833 = local_244;
                                                                    let _e2834 = (_e2833 + 1u);
                                                                    local_246 = _e2834;
                                                                    let _e2835 = local_6;
                                                                    if (_e2834 < _e2835) {
                                                                    } else {
                                                                        phi_5753_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2837 = local_246;
                                                                    let _e2840 = global_9.member[_e2837];
                                                                    local_247 = _e2840;
                                                                    let _e2841 = local_245;
                                                                    let _e2842 = (_e2841 & 65535u);
                                                                    local_577 = select(-1f, 1f, ((_e2842 & 32768u) == 0u));
                                                                    let _e2848 = ((_e2842 >> bitcast<u32>(10i)) & 31u);
                                                                    local_248 = _e2848;
                                                                    local_249 = (_e2842 & 1023u);
                                                                    if (_e2848 == 0u) {
                                                                        let _e2870 = local_249;
                                                                        let _e2872 = local_577;
                                                                        phi_2317_ = ((_e2872 * f32(_e2870)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2851 = local_248;
                                                                        if (_e2851 == 31u) {
                                                                            let _e2861 = local_249;
                                                                            phi_2314_ = (2139095040u | (_e2861 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2853 = local_248;
                                                                            let _e2857 = local_249;
                                                                            phi_2314_ = (((_e2853 + 112u) << bitcast<u32>(23i)) | (_e2857 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2866 = phi_2314_;
                                                                        let _e2868 = local_577;
                                                                        phi_2317_ = (_e2868 * bitcast<f32>(_e2866));
                                                                    }
                                                                    let _e2876 = phi_2317_;
                                                                    local_250 = _e2876;
                                                                    let _e2877 = local_245;
                                                                    let _e2879 = (_e2877 >> bitcast<u32>(16i));
                                                                    local_578 = select(-1f, 1f, ((_e2879 & 32768u) == 0u));
                                                                    let _e2885 = ((_e2879 >> bitcast<u32>(10i)) & 31u);
                                                                    local_251 = _e2885;
                                                                    local_252 = (_e2879 & 1023u);
                                                                    if (_e2885 == 0u) {
                                                                        let _e2907 = local_252;
                                                                        let _e2909 = local_578;
                                                                        phi_2349_ = ((_e2909 * f32(_e2907)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2888 = local_251;
                                                                        if (_e2888 == 31u) {
                                                                            let _e2898 = local_252;
                                                                            phi_2346_ = (2139095040u | (_e2898 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2890 = local_251;
                                                                            let _e2894 = local_252;
                                                                            phi_2346_ = (((_e2890 + 112u) << bitcast<u32>(23i)) | (_e2894 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2903 = phi_2346_;
                                                                        let _e2905 = local_578;
                                                                        phi_2349_ = (_e2905 * bitcast<f32>(_e2903));
                                                                    }
                                                                    let _e2913 = phi_2349_;
                                                                    local_253 = _e2913;
                                                                    let _e2914 = local_247;
                                                                    let _e2915 = (_e2914 & 65535u);
                                                                    local_579 = select(-1f, 1f, ((_e2915 & 32768u) == 0u));
                                                                    let _e2921 = ((_e2915 >> bitcast<u32>(10i)) & 31u);
                                                                    local_254 = _e2921;
                                                                    local_255 = (_e2915 & 1023u);
                                                                    if (_e2921 == 0u) {
                                                                        let _e2943 = local_255;
                                                                        let _e2945 = local_579;
                                                                        phi_2381_ = ((_e2945 * f32(_e2943)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2924 = local_254;
                                                                        if (_e2924 == 31u) {
                                                                            let _e2934 = local_255;
                                                                            phi_2378_ = (2139095040u | (_e2934 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2926 = local_254;
                                                                            let _e2930 = local_255;
                                                                            phi_2378_ = (((_e2926 + 112u) << bitcast<u32>(23i)) | (_e2930 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2939 = phi_2378_;
                                                                        let _e2941 = local_579;
                                                                        phi_2381_ = (_e2941 * bitcast<f32>(_e2939));
                                                                    }
                                                                    let _e2949 = phi_2381_;
                                                                    local_256 = _e2949;
                                                                    let _e2950 = local_247;
                                                                    let _e2952 = (_e2950 >> bitcast<u32>(16i));
                                                                    local_580 = select(-1f, 1f, ((_e2952 & 32768u) == 0u));
                                                                    let _e2958 = ((_e2952 >> bitcast<u32>(10i)) & 31u);
                                                                    local_257 = _e2958;
                                                                    local_258 = (_e2952 & 1023u);
                                                                    if (_e2958 == 0u) {
                                                                        let _e2980 = local_258;
                                                                        let _e2982 = local_580;
                                                                        phi_2413_ = ((_e2982 * f32(_e2980)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2961 = local_257;
                                                                        if (_e2961 == 31u) {
                                                                            let _e2971 = local_258;
                                                                            phi_2410_ = (2139095040u | (_e2971 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2963 = local_257;
                                                                            let _e2967 = local_258;
                                                                            phi_2410_ = (((_e2963 + 112u) << bitcast<u32>(23i)) | (_e2967 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2976 = phi_2410_;
                                                                        let _e2978 = local_580;
                                                                        phi_2413_ = (_e2978 * bitcast<f32>(_e2976));
                                                                    }
                                                                    let _e2986 = phi_2413_;
                                                                    local_259 = _e2986;
                                                                    let _e2987 = local_243;
                                                                    let _e2988 = local_183;
                                                                    let _e2990 = ((_e2987 + _e2988) * 2u);
                                                                    local_260 = _e2990;
                                                                    let _e2991 = local_6;
                                                                    if (_e2990 < _e2991) {
                                                                    } else {
                                                                        phi_5753_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2993 = local_260;
                                                                    let _e2996 = global_9.member[_e2993];
                                                                    local_261 = _e2996;
                                                                    let _e2997 = local_260;
                                                                    let _e2998 = (_e2997 + 1u);
                                                                    local_262 = _e2998;
                                                                    let _e2999 = local_6;
                                                                    if (_e2998 < _e2999) {
                                                                    } else {
                                                                        phi_5753_ = true;
                                                                        break;
                                                                    }
                                                                    let _e3001 = local_262;
                                                                    let _e3004 = global_9.member[_e3001];
                                                                    local_263 = _e3004;
                                                                    let _e3005 = local_261;
                                                                    let _e3006 = (_e3005 & 65535u);
                                                                    local_581 = select(-1f, 1f, ((_e3006 & 32768u) == 0u));
                                                                    let _e3012 = ((_e3006 >> bitcast<u32>(10i)) & 31u);
                                                                    local_264 = _e3012;
                                                                    local_265 = (_e3006 & 1023u);
                                                                    if (_e3012 == 0u) {
                                                                        let _e3034 = local_265;
                                                                        let _e3036 = local_581;
                                                                        phi_2482_ = ((_e3036 * f32(_e3034)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3015 = local_264;
                                                                        if (_e3015 == 31u) {
                                                                            let _e3025 = local_265;
                                                                            phi_2479_ = (2139095040u | (_e3025 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3017 = local_264;
                                                                            let _e3021 = local_265;
                                                                            phi_2479_ = (((_e3017 + 112u) << bitcast<u32>(23i)) | (_e3021 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3030 = phi_2479_;
                                                                        let _e3032 = local_581;
                                                                        phi_2482_ = (_e3032 * bitcast<f32>(_e3030));
                                                                    }
                                                                    let _e3040 = phi_2482_;
                                                                    local_266 = _e3040;
                                                                    let _e3041 = local_261;
                                                                    let _e3043 = (_e3041 >> bitcast<u32>(16i));
                                                                    local_582 = select(-1f, 1f, ((_e3043 & 32768u) == 0u));
                                                                    let _e3049 = ((_e3043 >> bitcast<u32>(10i)) & 31u);
                                                                    local_267 = _e3049;
                                                                    local_268 = (_e3043 & 1023u);
                                                                    if (_e3049 == 0u) {
                                                                        let _e3071 = local_268;
                                                                        let _e3073 = local_582;
                                                                        phi_2514_ = ((_e3073 * f32(_e3071)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3052 = local_267;
                                                                        if (_e3052 == 31u) {
                                                                            let _e3062 = local_268;
                                                                            phi_2511_ = (2139095040u | (_e3062 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3054 = local_267;
                                                                            let _e3058 = local_268;
                                                                            phi_2511_ = (((_e3054 + 112u) << bitcast<u32>(23i)) | (_e3058 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3067 = phi_2511_;
                                                                        let _e3069 = local_582;
                                                                        phi_2514_ = (_e3069 * bitcast<f32>(_e3067));
                                                                    }
                                                                    let _e3077 = phi_2514_;
                                                                    local_269 = _e3077;
                                                                    let _e3078 = local_263;
                                                                    let _e3079 = (_e3078 & 65535u);
                                                                    local_583 = select(-1f, 1f, ((_e3079 & 32768u) == 0u));
                                                                    let _e3085 = ((_e3079 >> bitcast<u32>(10i)) & 31u);
                                                                    local_270 = _e3085;
                                                                    local_271 = (_e3079 & 1023u);
                                                                    if (_e3085 == 0u) {
                                                                        let _e3107 = local_271;
                                                                        let _e3109 = local_583;
                                                                        phi_2546_ = ((_e3109 * f32(_e3107)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3088 = local_270;
                                                                        if (_e3088 == 31u) {
                                                                            let _e3098 = local_271;
                                                                            phi_2543_ = (2139095040u | (_e3098 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3090 = local_270;
                                                                            let _e3094 = local_271;
                                                                            phi_2543_ = (((_e3090 + 112u) << bitcast<u32>(23i)) | (_e3094 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3103 = phi_2543_;
                                                                        let _e3105 = local_583;
                                                                        phi_2546_ = (_e3105 * bitcast<f32>(_e3103));
                                                                    }
                                                                    let _e3113 = phi_2546_;
                                                                    local_272 = _e3113;
                                                                    let _e3114 = local_263;
                                                                    let _e3116 = (_e3114 >> bitcast<u32>(16i));
                                                                    local_584 = select(-1f, 1f, ((_e3116 & 32768u) == 0u));
                                                                    let _e3122 = ((_e3116 >> bitcast<u32>(10i)) & 31u);
                                                                    local_273 = _e3122;
                                                                    local_274 = (_e3116 & 1023u);
                                                                    if (_e3122 == 0u) {
                                                                        let _e3144 = local_274;
                                                                        let _e3146 = local_584;
                                                                        phi_2578_ = ((_e3146 * f32(_e3144)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3125 = local_273;
                                                                        if (_e3125 == 31u) {
                                                                            let _e3135 = local_274;
                                                                            phi_2575_ = (2139095040u | (_e3135 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3127 = local_273;
                                                                            let _e3131 = local_274;
                                                                            phi_2575_ = (((_e3127 + 112u) << bitcast<u32>(23i)) | (_e3131 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3140 = phi_2575_;
                                                                        let _e3142 = local_584;
                                                                        phi_2578_ = (_e3142 * bitcast<f32>(_e3140));
                                                                    }
                                                                    let _e3150 = phi_2578_;
                                                                    let _e3151 = local_266;
                                                                    let _e3152 = local_250;
                                                                    let _e3154 = local_159;
                                                                    let _e3156 = local_250;
                                                                    let _e3158 = local_269;
                                                                    let _e3159 = local_253;
                                                                    let _e3161 = local_159;
                                                                    let _e3163 = local_253;
                                                                    let _e3165 = local_272;
                                                                    let _e3166 = local_256;
                                                                    let _e3168 = local_159;
                                                                    let _e3170 = local_256;
                                                                    let _e3172 = local_259;
                                                                    let _e3174 = local_159;
                                                                    let _e3176 = local_259;
                                                                    let _e3178 = local_239;
                                                                    let _e3180 = local_158;
                                                                    let _e3182 = local_239;
                                                                    let _e3184 = local_240;
                                                                    let _e3186 = local_158;
                                                                    let _e3188 = local_240;
                                                                    let _e3190 = local_241;
                                                                    let _e3192 = local_158;
                                                                    let _e3194 = local_241;
                                                                    let _e3196 = local_242;
                                                                    let _e3198 = local_158;
                                                                    let _e3200 = local_242;
                                                                    let _e3202 = local_151;
                                                                    let _e3204 = local_151;
                                                                    let _e3206 = local_151;
                                                                    let _e3208 = local_151;
                                                                    let _e3210 = local_148;
                                                                    let _e3213 = local_148;
                                                                    let _e3216 = local_148;
                                                                    let _e3219 = local_148;
                                                                    let _e3223 = local_147;
                                                                    phi_1533_ = (_e3223 + 1u);
                                                                    phi_1536_ = type_5((_e3210.member + ((_e3182 + (((_e3156 + ((_e3151 - _e3152) * _e3154)) - _e3178) * _e3180)) * _e3202)), (_e3213.member_1 + ((_e3188 + (((_e3163 + ((_e3158 - _e3159) * _e3161)) - _e3184) * _e3186)) * _e3204)), (_e3216.member_2 + ((_e3194 + (((_e3170 + ((_e3165 - _e3166) * _e3168)) - _e3190) * _e3192)) * _e3206)), (_e3219.member_3 + ((_e3200 + (((_e3176 + ((_e3150 - _e3172) * _e3174)) - _e3196) * _e3198)) * _e3208)));
                                                                } else {
                                                                    phi_1533_ = u32();
                                                                    phi_1536_ = type_5();
                                                                }
                                                                let _e3226 = phi_1533_;
                                                                let _e3228 = phi_1536_;
                                                                continue;
                                                                continuing {
                                                                    let _e3229 = local_149;
                                                                    phi_1532_ = _e3226;
                                                                    phi_1535_ = _e3228;
                                                                    phi_5753_ = _e2078;
                                                                    break if !(_e3229);
                                                                }
                                                            }
                                                            let _e3232 = phi_5753_;
                                                            phi_5867_ = _e3232;
                                                            if _e3232 {
                                                                break;
                                                            }
                                                            let _e3233 = local_143;
                                                            phi_5868_ = _e3232;
                                                            phi_1504_ = (_e3233 + 1u);
                                                            let _e5652 = local_630;
                                                            phi_1507_ = _e5652;
                                                        } else {
                                                            phi_5868_ = _e2078;
                                                            phi_1504_ = u32();
                                                            phi_1507_ = type_5();
                                                        }
                                                        let _e3236 = phi_5868_;
                                                        let _e3238 = phi_1504_;
                                                        let _e3240 = phi_1507_;
                                                        continue;
                                                        continuing {
                                                            let _e3241 = local_144;
                                                            phi_5799_ = _e3236;
                                                            phi_1503_ = _e3238;
                                                            phi_1506_ = _e3240;
                                                            phi_5867_ = _e3236;
                                                            break if !(_e3241);
                                                        }
                                                    }
                                                    let _e3244 = phi_5867_;
                                                    phi_5869_ = _e3244;
                                                    if _e3244 {
                                                        break;
                                                    }
                                                    let _e3245 = local_139;
                                                    phi_5870_ = _e3244;
                                                    phi_1487_ = (_e3245 + 1u);
                                                    let _e5658 = local_631;
                                                    phi_1490_ = _e5658;
                                                } else {
                                                    phi_5870_ = _e2062;
                                                    phi_1487_ = u32();
                                                    phi_1490_ = type_5();
                                                }
                                                let _e3248 = phi_5870_;
                                                let _e3250 = phi_1487_;
                                                let _e3252 = phi_1490_;
                                                continue;
                                                continuing {
                                                    let _e3253 = local_141;
                                                    phi_5800_ = _e3248;
                                                    phi_1486_ = _e3250;
                                                    phi_1489_ = _e3252;
                                                    phi_5869_ = _e3248;
                                                    break if !(_e3253);
                                                }
                                            }
                                            let _e3256 = phi_5869_;
                                            phi_6024_ = _e3256;
                                            if _e3256 {
                                                break;
                                            }
                                            let _e3257 = local_130;
                                            let _e3258 = local_129;
                                            let _e3261 = (1f / f32((_e3257 * _e3258)));
                                            let _e3262 = local_140;
                                            let _e3265 = local_140;
                                            let _e3268 = local_140;
                                            let _e3271 = local_140;
                                            phi_5944_ = _e3256;
                                            phi_2631_ = type_5((_e3262.member * _e3261), (_e3265.member_1 * _e3261), (_e3268.member_2 * _e3261), (_e3271.member_3 * _e3261));
                                        }
                                        let _e3276 = phi_5944_;
                                        let _e3278 = phi_2631_;
                                        phi_5943_ = _e3276;
                                        phi_2632_ = _e3278;
                                        phi_2633_ = _e1714;
                                    }
                                    let _e3280 = phi_5943_;
                                    let _e3282 = phi_2632_;
                                    let _e3284 = phi_2633_;
                                    if _e3284 {
                                        phi_2637_ = type_5(1f, 1f, 1f, 1f);
                                    } else {
                                        phi_2637_ = _e3282;
                                    }
                                    let _e3286 = phi_2637_;
                                    phi_5941_ = _e3280;
                                    phi_2638_ = _e3286;
                                }
                                let _e3288 = phi_5941_;
                                let _e3290 = phi_2638_;
                                phi_5940_ = _e3288;
                                phi_2639_ = _e3290;
                                phi_2640_ = _e1678;
                            }
                            let _e3292 = phi_5940_;
                            let _e3294 = phi_2639_;
                            let _e3296 = phi_2640_;
                            if _e3296 {
                                phi_2644_ = type_5(1f, 1f, 1f, 1f);
                            } else {
                                phi_2644_ = _e3294;
                            }
                            let _e3298 = phi_2644_;
                            local_623 = array<f32, 4>(_e3298.member, _e3298.member_1, _e3298.member_2, _e3298.member_3);
                            let _e3304 = local_90;
                            if (_e3304 == 4294967295u) {
                                phi_5999_ = _e3292;
                                phi_4122_ = type_5();
                                phi_4123_ = true;
                            } else {
                                let _e3306 = local_90;
                                let _e3307 = local_25;
                                let _e3308 = (_e3306 >= _e3307);
                                if _e3308 {
                                    phi_6000_ = _e3292;
                                    phi_4121_ = type_5();
                                } else {
                                    let _e3309 = local_90;
                                    let _e3310 = (_e3309 * 4u);
                                    local_275 = _e3310;
                                    let _e3311 = local_5;
                                    if (_e3310 < _e3311) {
                                    } else {
                                        phi_6024_ = true;
                                        break;
                                    }
                                    let _e3313 = local_275;
                                    let _e3316 = global_8.member[_e3313];
                                    local_276 = _e3316;
                                    let _e3317 = local_275;
                                    let _e3318 = (_e3317 + 1u);
                                    local_277 = _e3318;
                                    let _e3319 = local_5;
                                    if (_e3318 < _e3319) {
                                    } else {
                                        phi_6024_ = true;
                                        break;
                                    }
                                    let _e3321 = local_277;
                                    let _e3324 = global_8.member[_e3321];
                                    local_278 = _e3324;
                                    let _e3325 = local_275;
                                    let _e3326 = (_e3325 + 2u);
                                    local_279 = _e3326;
                                    let _e3327 = local_5;
                                    if (_e3326 < _e3327) {
                                    } else {
                                        phi_6024_ = true;
                                        break;
                                    }
                                    let _e3329 = local_279;
                                    let _e3332 = global_8.member[_e3329];
                                    local_280 = _e3332;
                                    let _e3333 = local_275;
                                    let _e3334 = (_e3333 + 3u);
                                    local_281 = _e3334;
                                    let _e3335 = local_5;
                                    if (_e3334 < _e3335) {
                                    } else {
                                        phi_6024_ = true;
                                        break;
                                    }
                                    let _e3337 = local_281;
                                    let _e3340 = global_8.member[_e3337];
                                    local_282 = _e3340;
                                    let _e3341 = local_278;
                                    if (_e3341 == 0u) {
                                        phi_6002_ = _e3292;
                                        phi_4115_ = type_5();
                                        phi_4116_ = true;
                                    } else {
                                        let _e3343 = local_280;
                                        let _e3344 = (_e3343 == 0u);
                                        if _e3344 {
                                            phi_6003_ = _e3292;
                                            phi_4114_ = type_5();
                                        } else {
                                            let _e3345 = local_282;
                                            let _e3348 = ((_e3345 >> bitcast<u32>(8u)) & 31u);
                                            local_585 = select(_e3348, 1u, (_e3348 == 0u));
                                            let _e3351 = local_282;
                                            let _e3355 = local_282;
                                            let _e3359 = local_276;
                                            let _e3360 = local_278;
                                            let _e3361 = local_280;
                                            let _e3362 = type_23(_e3359, _e3360, _e3361, ((_e3351 >> bitcast<u32>(1u)) & 3u), ((_e3355 >> bitcast<u32>(3u)) & 3u));
                                            let _e3363 = local_278;
                                            let _e3364 = f32(_e3363);
                                            local_283 = _e3364;
                                            let _e3365 = local_79;
                                            if ((bitcast<u32>((_e3365 * _e3364)) & 2139095040u) != 2139095040u) {
                                                let _e3370 = local_280;
                                                let _e3372 = local_78;
                                                phi_2764_ = select(true, false, ((bitcast<u32>((_e3372 * f32(_e3370))) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_2764_ = true;
                                            }
                                            let _e3379 = phi_2764_;
                                            let _e3380 = local_78;
                                            local_586 = select(_e3380, 0f, _e3379);
                                            let _e3382 = local_79;
                                            local_587 = select(_e3382, 0f, _e3379);
                                            let _e3384 = local_106;
                                            local_284 = _e3384.member;
                                            let _e3386 = local_283;
                                            let _e3387 = (_e3384.member * _e3386);
                                            let _e3388 = local_106;
                                            local_285 = _e3388.member_1;
                                            let _e3390 = local_280;
                                            let _e3391 = f32(_e3390);
                                            let _e3392 = (_e3388.member_1 * _e3391);
                                            let _e3393 = local_106;
                                            local_286 = _e3393.member_2;
                                            let _e3395 = local_283;
                                            let _e3396 = (_e3393.member_2 * _e3395);
                                            let _e3397 = local_106;
                                            local_287 = _e3397.member_3;
                                            let _e3399 = (_e3397.member_3 * _e3391);
                                            let _e3403 = sqrt(((_e3387 * _e3387) + (_e3392 * _e3392)));
                                            local_288 = _e3403;
                                            let _e3407 = sqrt(((_e3396 * _e3396) + (_e3399 * _e3399)));
                                            local_289 = _e3407;
                                            let _e3409 = select(_e3407, _e3403, (_e3403 > _e3407));
                                            local_588 = _e3409;
                                            if (_e3409 > 1f) {
                                                let _e3411 = local_588;
                                                phi_2803_ = !(((bitcast<u32>(_e3411) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_2803_ = true;
                                            }
                                            let _e3417 = phi_2803_;
                                            local_290 = _e3417;
                                            if _e3417 {
                                                phi_2899_ = 1u;
                                                phi_2900_ = 1u;
                                            } else {
                                                let _e3418 = local_288;
                                                let _e3419 = local_289;
                                                if (_e3418 >= _e3419) {
                                                    let _e3462 = local_29;
                                                    let _e3463 = f32(_e3462);
                                                    let _e3464 = local_289;
                                                    let _e3466 = local_289;
                                                    let _e3468 = ceil(select(_e3463, _e3466, (_e3464 < _e3463)));
                                                    local_291 = _e3468;
                                                    if (_e3468 < 1f) {
                                                        phi_2829_ = 1u;
                                                    } else {
                                                        let _e3470 = local_291;
                                                        let _e3472 = local_291;
                                                        let _e3475 = local_291;
                                                        phi_2829_ = select(select(u32(_e3470), 0u, !((_e3472 >= 0f))), 4294967295u, (_e3475 > 4294967000f));
                                                    }
                                                    let _e3480 = phi_2829_;
                                                    local_292 = _e3480;
                                                    if (_e3480 == 0u) {
                                                        phi_6024_ = true;
                                                        break;
                                                    }
                                                    let _e3482 = local_28;
                                                    let _e3483 = local_292;
                                                    let _e3485 = f32((_e3482 / _e3483));
                                                    let _e3486 = local_288;
                                                    let _e3488 = local_288;
                                                    let _e3490 = ceil(select(_e3485, _e3488, (_e3486 < _e3485)));
                                                    local_293 = _e3490;
                                                    if (_e3490 < 1f) {
                                                        phi_2853_ = 1u;
                                                    } else {
                                                        let _e3492 = local_293;
                                                        let _e3494 = local_293;
                                                        let _e3497 = local_293;
                                                        phi_2853_ = select(select(u32(_e3492), 0u, !((_e3494 >= 0f))), 4294967295u, (_e3497 > 4294967000f));
                                                    }
                                                    let _e3502 = phi_2853_;
                                                    phi_2897_ = _e3480;
                                                    phi_2898_ = _e3502;
                                                } else {
                                                    let _e3421 = local_29;
                                                    let _e3422 = f32(_e3421);
                                                    let _e3423 = local_288;
                                                    let _e3425 = local_288;
                                                    let _e3427 = ceil(select(_e3422, _e3425, (_e3423 < _e3422)));
                                                    local_294 = _e3427;
                                                    if (_e3427 < 1f) {
                                                        phi_2872_ = 1u;
                                                    } else {
                                                        let _e3429 = local_294;
                                                        let _e3431 = local_294;
                                                        let _e3434 = local_294;
                                                        phi_2872_ = select(select(u32(_e3429), 0u, !((_e3431 >= 0f))), 4294967295u, (_e3434 > 4294967000f));
                                                    }
                                                    let _e3439 = phi_2872_;
                                                    local_295 = _e3439;
                                                    if (_e3439 == 0u) {
                                                        phi_6024_ = true;
                                                        break;
                                                    }
                                                    let _e3441 = local_28;
                                                    let _e3442 = local_295;
                                                    let _e3444 = f32((_e3441 / _e3442));
                                                    let _e3445 = local_289;
                                                    let _e3447 = local_289;
                                                    let _e3449 = ceil(select(_e3444, _e3447, (_e3445 < _e3444)));
                                                    local_296 = _e3449;
                                                    if (_e3449 < 1f) {
                                                        phi_2896_ = 1u;
                                                    } else {
                                                        let _e3451 = local_296;
                                                        let _e3453 = local_296;
                                                        let _e3456 = local_296;
                                                        phi_2896_ = select(select(u32(_e3451), 0u, !((_e3453 >= 0f))), 4294967295u, (_e3456 > 4294967000f));
                                                    }
                                                    let _e3461 = phi_2896_;
                                                    phi_2897_ = _e3461;
                                                    phi_2898_ = _e3439;
                                                }
                                                let _e3504 = phi_2897_;
                                                let _e3506 = phi_2898_;
                                                phi_2899_ = _e3504;
                                                phi_2900_ = _e3506;
                                            }
                                            let _e3508 = phi_2899_;
                                            let _e3510 = phi_2900_;
                                            local_297 = _e3508;
                                            local_298 = _e3510;
                                            let _e3511 = local_290;
                                            if _e3511 {
                                                phi_2913_ = 1f;
                                            } else {
                                                let _e3512 = local_298;
                                                let _e3514 = local_288;
                                                let _e3515 = (_e3514 / f32(_e3512));
                                                let _e3516 = local_297;
                                                let _e3518 = local_289;
                                                let _e3519 = (_e3518 / f32(_e3516));
                                                phi_2913_ = select(_e3519, _e3515, (_e3515 > _e3519));
                                            }
                                            let _e3523 = phi_2913_;
                                            local_299 = _e3523;
                                            if (_e3523 > 1f) {
                                                let _e3525 = local_299;
                                                let _e3526 = bitcast<u32>(_e3525);
                                                let _e3535 = (bitcast<f32>(((_e3526 & 8388607u) | 1065353216u)) - 1f);
                                                phi_2934_ = (f32((bitcast<i32>(((_e3526 >> bitcast<u32>(23i)) & 255u)) - 127i)) + (_e3535 * (1.4208645f + (_e3535 * (-0.5772506f + (_e3535 * 0.1563861f))))));
                                            } else {
                                                phi_2934_ = 0f;
                                            }
                                            let _e3544 = phi_2934_;
                                            local_300 = _e3544;
                                            let _e3545 = local_585;
                                            let _e3546 = (_e3545 - 1u);
                                            local_301 = _e3546;
                                            let _e3547 = floor(_e3544);
                                            let _e3553 = select(select(u32(_e3547), 0u, !((_e3547 >= 0f))), 4294967295u, (_e3547 > 4294967000f));
                                            local_302 = _e3553;
                                            let _e3554 = (_e3553 >= _e3546);
                                            local_303 = _e3554;
                                            if _e3554 {
                                                phi_2950_ = 0f;
                                            } else {
                                                let _e3555 = local_302;
                                                let _e3557 = local_300;
                                                phi_2950_ = (_e3557 - f32(_e3555));
                                            }
                                            let _e3560 = phi_2950_;
                                            local_304 = _e3560;
                                            let _e3561 = local_303;
                                            let _e3562 = local_301;
                                            let _e3563 = local_302;
                                            local_589 = select(_e3563, _e3562, _e3561);
                                            local_590 = select(1u, 2u, (_e3560 > 0f));
                                            phi_5628_ = 0u;
                                            phi_5629_ = _e3362;
                                            loop {
                                                let _e3568 = phi_5628_;
                                                let _e3570 = phi_5629_;
                                                local_549 = _e3568;
                                                local_550 = _e3570;
                                                local_632 = _e3570;
                                                let _e3571 = local_549;
                                                let _e3572 = local_589;
                                                let _e3573 = (_e3571 < _e3572);
                                                local_551 = _e3573;
                                                if _e3573 {
                                                    let _e3574 = local_550;
                                                    local_552 = _e3574.member_1;
                                                    let _e3576 = local_550;
                                                    local_553 = _e3576.member_2;
                                                    let _e3579 = local_550;
                                                    let _e3582 = local_550;
                                                    local_554 = type_23((_e3579.member + (_e3574.member_1 * _e3576.member_2)), _e3582.member_1, _e3582.member_2, _e3582.member_3, _e3582.member_4);
                                                    if (_e3574.member_1 > 1u) {
                                                        let _e3590 = local_552;
                                                        phi_5646_ = (_e3590 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5646_ = 1u;
                                                    }
                                                    let _e3594 = phi_5646_;
                                                    let _e3595 = local_554;
                                                    local_555 = type_23(_e3595.member, _e3594, _e3595.member_2, _e3595.member_3, _e3595.member_4);
                                                    let _e3602 = local_553;
                                                    if (_e3602 > 1u) {
                                                        let _e3604 = local_553;
                                                        phi_5655_ = (_e3604 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5655_ = 1u;
                                                    }
                                                    let _e3608 = phi_5655_;
                                                    let _e3609 = local_555;
                                                    let _e3616 = local_549;
                                                    phi_5660_ = (_e3616 + 1u);
                                                    phi_5661_ = type_23(_e3609.member, _e3609.member_1, _e3608, _e3609.member_3, _e3609.member_4);
                                                } else {
                                                    phi_5660_ = u32();
                                                    phi_5661_ = type_23();
                                                }
                                                let _e3619 = phi_5660_;
                                                let _e3621 = phi_5661_;
                                                continue;
                                                continuing {
                                                    let _e3622 = local_551;
                                                    phi_5628_ = _e3619;
                                                    phi_5629_ = _e3621;
                                                    break if !(_e3622);
                                                }
                                            }
                                            let _e3624 = local_589;
                                            let _e3625 = local_590;
                                            local_305 = ((_e3624 + _e3625) - 1u);
                                            phi_5667_ = 0u;
                                            phi_5668_ = _e3362;
                                            loop {
                                                let _e3629 = phi_5667_;
                                                let _e3631 = phi_5668_;
                                                local_556 = _e3629;
                                                local_557 = _e3631;
                                                local_633 = _e3631;
                                                let _e3632 = local_556;
                                                let _e3633 = local_305;
                                                let _e3634 = (_e3632 < _e3633);
                                                local_558 = _e3634;
                                                if _e3634 {
                                                    let _e3635 = local_557;
                                                    local_559 = _e3635.member_1;
                                                    let _e3637 = local_557;
                                                    local_560 = _e3637.member_2;
                                                    let _e3640 = local_557;
                                                    let _e3643 = local_557;
                                                    local_561 = type_23((_e3640.member + (_e3635.member_1 * _e3637.member_2)), _e3643.member_1, _e3643.member_2, _e3643.member_3, _e3643.member_4);
                                                    if (_e3635.member_1 > 1u) {
                                                        let _e3651 = local_559;
                                                        phi_5685_ = (_e3651 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5685_ = 1u;
                                                    }
                                                    let _e3655 = phi_5685_;
                                                    let _e3656 = local_561;
                                                    local_562 = type_23(_e3656.member, _e3655, _e3656.member_2, _e3656.member_3, _e3656.member_4);
                                                    let _e3663 = local_560;
                                                    if (_e3663 > 1u) {
                                                        let _e3665 = local_560;
                                                        phi_5694_ = (_e3665 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5694_ = 1u;
                                                    }
                                                    let _e3669 = phi_5694_;
                                                    let _e3670 = local_562;
                                                    let _e3677 = local_556;
                                                    phi_5699_ = (_e3677 + 1u);
                                                    phi_5700_ = type_23(_e3670.member, _e3670.member_1, _e3669, _e3670.member_3, _e3670.member_4);
                                                } else {
                                                    phi_5699_ = u32();
                                                    phi_5700_ = type_23();
                                                }
                                                let _e3680 = phi_5699_;
                                                let _e3682 = phi_5700_;
                                                continue;
                                                continuing {
                                                    let _e3683 = local_558;
                                                    phi_5667_ = _e3680;
                                                    phi_5668_ = _e3682;
                                                    break if !(_e3683);
                                                }
                                            }
                                            let _e3685 = local_290;
                                            if _e3685 {
                                                let _e3686 = local_282;
                                                phi_2966_ = ((_e3686 & 1u) != 0u);
                                            } else {
                                                phi_2966_ = false;
                                            }
                                            let _e3690 = phi_2966_;
                                            local_306 = _e3690;
                                            phi_5918_ = _e3292;
                                            phi_2969_ = 0u;
                                            phi_2972_ = type_5(0f, 0f, 0f, 0f);
                                            loop {
                                                let _e3692 = phi_5918_;
                                                let _e3694 = phi_2969_;
                                                let _e3696 = phi_2972_;
                                                local_307 = _e3694;
                                                local_308 = _e3696;
                                                let _e3697 = local_307;
                                                let _e3698 = local_298;
                                                let _e3699 = (_e3697 < _e3698);
                                                local_309 = _e3699;
                                                if _e3699 {
                                                    let _e3700 = local_307;
                                                    let _e3703 = local_298;
                                                    local_310 = (((f32(_e3700) + 0.5f) / f32(_e3703)) - 0.5f);
                                                    phi_5917_ = _e3692;
                                                    phi_2986_ = 0u;
                                                    phi_2989_ = _e3696;
                                                    loop {
                                                        let _e3708 = phi_5917_;
                                                        let _e3710 = phi_2986_;
                                                        let _e3712 = phi_2989_;
                                                        local_311 = _e3710;
                                                        local_635 = _e3712;
                                                        let _e3713 = local_311;
                                                        let _e3714 = local_297;
                                                        let _e3715 = (_e3713 < _e3714);
                                                        local_312 = _e3715;
                                                        if _e3715 {
                                                            let _e3716 = local_311;
                                                            let _e3719 = local_297;
                                                            let _e3722 = (((f32(_e3716) + 0.5f) / f32(_e3719)) - 0.5f);
                                                            let _e3723 = local_310;
                                                            let _e3724 = local_284;
                                                            let _e3726 = local_587;
                                                            let _e3728 = local_286;
                                                            local_313 = ((_e3726 + (_e3723 * _e3724)) + (_e3722 * _e3728));
                                                            let _e3731 = local_310;
                                                            let _e3732 = local_285;
                                                            let _e3734 = local_586;
                                                            let _e3736 = local_287;
                                                            local_314 = ((_e3734 + (_e3731 * _e3732)) + (_e3722 * _e3736));
                                                            phi_3015_ = 0u;
                                                            phi_3018_ = _e3712;
                                                            loop {
                                                                let _e3740 = phi_3015_;
                                                                let _e3742 = phi_3018_;
                                                                local_315 = _e3740;
                                                                local_316 = _e3742;
                                                                local_634 = _e3742;
                                                                let _e3743 = local_315;
                                                                let _e3744 = local_590;
                                                                let _e3745 = (_e3743 < _e3744);
                                                                local_317 = _e3745;
                                                                if _e3745 {
                                                                    let _e3746 = local_315;
                                                                    if (_e3746 == 0u) {
                                                                        let _e3748 = local_304;
                                                                        let _e5708 = local_632;
                                                                        phi_3031_ = _e5708;
                                                                        phi_3032_ = (1f - _e3748);
                                                                    } else {
                                                                        let _e5710 = local_633;
                                                                        phi_3031_ = _e5710;
                                                                        phi_3032_ = _e3560;
                                                                    }
                                                                    let _e3751 = phi_3031_;
                                                                    let _e3753 = phi_3032_;
                                                                    local_318 = _e3751;
                                                                    local_319 = _e3753;
                                                                    let _e3754 = local_306;
                                                                    let _e3755 = select(0.5f, 0f, _e3754);
                                                                    local_320 = _e3751.member_1;
                                                                    let _e3758 = local_313;
                                                                    let _e3760 = ((_e3758 * f32(_e3751.member_1)) - _e3755);
                                                                    local_321 = _e3760;
                                                                    local_322 = _e3751.member_2;
                                                                    let _e3763 = local_314;
                                                                    let _e3765 = ((_e3763 * f32(_e3751.member_2)) - _e3755);
                                                                    local_323 = _e3765;
                                                                    local_324 = floor(_e3760);
                                                                    local_325 = floor(_e3765);
                                                                    let _e3768 = local_306;
                                                                    if _e3768 {
                                                                        phi_3052_ = 0f;
                                                                        phi_3053_ = 0f;
                                                                    } else {
                                                                        let _e3769 = local_321;
                                                                        let _e3770 = local_324;
                                                                        let _e3772 = local_323;
                                                                        let _e3773 = local_325;
                                                                        phi_3052_ = (_e3772 - _e3773);
                                                                        phi_3053_ = (_e3769 - _e3770);
                                                                    }
                                                                    let _e3776 = phi_3052_;
                                                                    let _e3778 = phi_3053_;
                                                                    local_326 = _e3776;
                                                                    local_327 = _e3778;
                                                                    let _e3779 = local_324;
                                                                    let _e3781 = local_324;
                                                                    let _e3784 = local_324;
                                                                    let _e3788 = local_324;
                                                                    let _e3789 = local_324;
                                                                    let _e3791 = select(0i, select(select(i32(_e3779), i32(-2147483648), !((_e3781 >= -2147483600f))), 2147483647i, (_e3784 > 2147483500f)), (_e3788 == _e3789));
                                                                    local_328 = _e3791;
                                                                    let _e3792 = local_325;
                                                                    let _e3794 = local_325;
                                                                    let _e3797 = local_325;
                                                                    let _e3801 = local_325;
                                                                    let _e3802 = local_325;
                                                                    let _e3804 = select(0i, select(select(i32(_e3792), i32(-2147483648), !((_e3794 >= -2147483600f))), 2147483647i, (_e3797 > 2147483500f)), (_e3801 == _e3802));
                                                                    local_329 = _e3804;
                                                                    let _e3805 = local_318;
                                                                    local_330 = _e3805.member_3;
                                                                    let _e3807 = local_320;
                                                                    local_331 = bitcast<i32>(_e3807);
                                                                    let _e3809 = (_e3805.member_3 == 1u);
                                                                    local_332 = _e3809;
                                                                    if _e3809 {
                                                                        let _e3863 = local_328;
                                                                        if (_e3863 < 0i) {
                                                                            phi_3089_ = 0i;
                                                                        } else {
                                                                            let _e3865 = local_328;
                                                                            let _e3866 = local_331;
                                                                            if (_e3865 >= _e3866) {
                                                                                let _e3868 = local_331;
                                                                                phi_3088_ = (_e3868 - 1i);
                                                                            } else {
                                                                                phi_3088_ = _e3791;
                                                                            }
                                                                            let _e3871 = phi_3088_;
                                                                            phi_3089_ = _e3871;
                                                                        }
                                                                        let _e3873 = phi_3089_;
                                                                        phi_3149_ = _e3873;
                                                                    } else {
                                                                        let _e3810 = local_330;
                                                                        if (_e3810 == 2u) {
                                                                            let _e3832 = local_331;
                                                                            let _e3833 = (2i * _e3832);
                                                                            local_333 = _e3833;
                                                                            let _e3834 = (_e3833 == 0i);
                                                                            local_334 = _e3834;
                                                                            if _e3834 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3835 = local_333;
                                                                            let _e3836 = (_e3835 == -1i);
                                                                            local_335 = _e3836;
                                                                            let _e3837 = local_328;
                                                                            if (_e3836 && (_e3837 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3840 = local_328;
                                                                            let _e3841 = local_333;
                                                                            let _e3843 = local_333;
                                                                            local_336 = ((_e3840 % _e3841) + _e3843);
                                                                            let _e3845 = local_334;
                                                                            if _e3845 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3846 = local_336;
                                                                            let _e3848 = local_335;
                                                                            if (_e3848 && (_e3846 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3850 = local_336;
                                                                            let _e3851 = local_333;
                                                                            let _e3852 = (_e3850 % _e3851);
                                                                            local_337 = _e3852;
                                                                            let _e3853 = local_331;
                                                                            if (_e3852 < _e3853) {
                                                                                phi_3124_ = _e3852;
                                                                            } else {
                                                                                let _e3855 = local_333;
                                                                                let _e3857 = local_337;
                                                                                phi_3124_ = ((_e3855 - 1i) - _e3857);
                                                                            }
                                                                            let _e3860 = phi_3124_;
                                                                            phi_3148_ = _e3860;
                                                                        } else {
                                                                            let _e3812 = local_331;
                                                                            let _e3813 = (_e3812 == 0i);
                                                                            local_338 = _e3813;
                                                                            if _e3813 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3814 = local_331;
                                                                            let _e3815 = (_e3814 == -1i);
                                                                            local_339 = _e3815;
                                                                            let _e3816 = local_328;
                                                                            if (_e3815 && (_e3816 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3819 = local_328;
                                                                            let _e3820 = local_331;
                                                                            let _e3822 = local_331;
                                                                            local_340 = ((_e3819 % _e3820) + _e3822);
                                                                            let _e3824 = local_338;
                                                                            if _e3824 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3825 = local_340;
                                                                            let _e3827 = local_339;
                                                                            if (_e3827 && (_e3825 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3829 = local_340;
                                                                            let _e3830 = local_331;
                                                                            phi_3148_ = (_e3829 % _e3830);
                                                                        }
                                                                        let _e3862 = phi_3148_;
                                                                        phi_3149_ = _e3862;
                                                                    }
                                                                    let _e3875 = phi_3149_;
                                                                    local_341 = bitcast<u32>(_e3875);
                                                                    let _e3877 = local_328;
                                                                    let _e3878 = (_e3877 + 1i);
                                                                    local_342 = _e3878;
                                                                    let _e3879 = local_332;
                                                                    if _e3879 {
                                                                        let _e3933 = local_342;
                                                                        if (_e3933 < 0i) {
                                                                            phi_3169_ = 0i;
                                                                        } else {
                                                                            let _e3935 = local_342;
                                                                            let _e3936 = local_331;
                                                                            if (_e3935 >= _e3936) {
                                                                                let _e3938 = local_331;
                                                                                phi_3168_ = (_e3938 - 1i);
                                                                            } else {
                                                                                phi_3168_ = _e3878;
                                                                            }
                                                                            let _e3941 = phi_3168_;
                                                                            phi_3169_ = _e3941;
                                                                        }
                                                                        let _e3943 = phi_3169_;
                                                                        phi_3229_ = _e3943;
                                                                    } else {
                                                                        let _e3880 = local_330;
                                                                        if (_e3880 == 2u) {
                                                                            let _e3902 = local_331;
                                                                            let _e3903 = (2i * _e3902);
                                                                            local_343 = _e3903;
                                                                            let _e3904 = (_e3903 == 0i);
                                                                            local_344 = _e3904;
                                                                            if _e3904 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3905 = local_343;
                                                                            let _e3906 = (_e3905 == -1i);
                                                                            local_345 = _e3906;
                                                                            let _e3907 = local_342;
                                                                            if (_e3906 && (_e3907 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3910 = local_342;
                                                                            let _e3911 = local_343;
                                                                            let _e3913 = local_343;
                                                                            local_346 = ((_e3910 % _e3911) + _e3913);
                                                                            let _e3915 = local_344;
                                                                            if _e3915 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3916 = local_346;
                                                                            let _e3918 = local_345;
                                                                            if (_e3918 && (_e3916 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3920 = local_346;
                                                                            let _e3921 = local_343;
                                                                            let _e3922 = (_e3920 % _e3921);
                                                                            local_347 = _e3922;
                                                                            let _e3923 = local_331;
                                                                            if (_e3922 < _e3923) {
                                                                                phi_3204_ = _e3922;
                                                                            } else {
                                                                                let _e3925 = local_343;
                                                                                let _e3927 = local_347;
                                                                                phi_3204_ = ((_e3925 - 1i) - _e3927);
                                                                            }
                                                                            let _e3930 = phi_3204_;
                                                                            phi_3228_ = _e3930;
                                                                        } else {
                                                                            let _e3882 = local_331;
                                                                            let _e3883 = (_e3882 == 0i);
                                                                            local_348 = _e3883;
                                                                            if _e3883 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3884 = local_331;
                                                                            let _e3885 = (_e3884 == -1i);
                                                                            local_349 = _e3885;
                                                                            let _e3886 = local_342;
                                                                            if (_e3885 && (_e3886 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3889 = local_342;
                                                                            let _e3890 = local_331;
                                                                            let _e3892 = local_331;
                                                                            local_350 = ((_e3889 % _e3890) + _e3892);
                                                                            let _e3894 = local_348;
                                                                            if _e3894 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3895 = local_350;
                                                                            let _e3897 = local_349;
                                                                            if (_e3897 && (_e3895 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3899 = local_350;
                                                                            let _e3900 = local_331;
                                                                            phi_3228_ = (_e3899 % _e3900);
                                                                        }
                                                                        let _e3932 = phi_3228_;
                                                                        phi_3229_ = _e3932;
                                                                    }
                                                                    let _e3945 = phi_3229_;
                                                                    local_351 = bitcast<u32>(_e3945);
                                                                    let _e3947 = local_318;
                                                                    local_352 = _e3947.member_4;
                                                                    let _e3949 = local_322;
                                                                    local_353 = bitcast<i32>(_e3949);
                                                                    let _e3951 = (_e3947.member_4 == 1u);
                                                                    local_354 = _e3951;
                                                                    if _e3951 {
                                                                        let _e4005 = local_329;
                                                                        if (_e4005 < 0i) {
                                                                            phi_3248_ = 0i;
                                                                        } else {
                                                                            let _e4007 = local_329;
                                                                            let _e4008 = local_353;
                                                                            if (_e4007 >= _e4008) {
                                                                                let _e4010 = local_353;
                                                                                phi_3247_ = (_e4010 - 1i);
                                                                            } else {
                                                                                phi_3247_ = _e3804;
                                                                            }
                                                                            let _e4013 = phi_3247_;
                                                                            phi_3248_ = _e4013;
                                                                        }
                                                                        let _e4015 = phi_3248_;
                                                                        phi_3308_ = _e4015;
                                                                    } else {
                                                                        let _e3952 = local_352;
                                                                        if (_e3952 == 2u) {
                                                                            let _e3974 = local_353;
                                                                            let _e3975 = (2i * _e3974);
                                                                            local_355 = _e3975;
                                                                            let _e3976 = (_e3975 == 0i);
                                                                            local_356 = _e3976;
                                                                            if _e3976 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3977 = local_355;
                                                                            let _e3978 = (_e3977 == -1i);
                                                                            local_357 = _e3978;
                                                                            let _e3979 = local_329;
                                                                            if (_e3978 && (_e3979 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3982 = local_329;
                                                                            let _e3983 = local_355;
                                                                            let _e3985 = local_355;
                                                                            local_358 = ((_e3982 % _e3983) + _e3985);
                                                                            let _e3987 = local_356;
                                                                            if _e3987 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3988 = local_358;
                                                                            let _e3990 = local_357;
                                                                            if (_e3990 && (_e3988 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3992 = local_358;
                                                                            let _e3993 = local_355;
                                                                            let _e3994 = (_e3992 % _e3993);
                                                                            local_359 = _e3994;
                                                                            let _e3995 = local_353;
                                                                            if (_e3994 < _e3995) {
                                                                                phi_3283_ = _e3994;
                                                                            } else {
                                                                                let _e3997 = local_355;
                                                                                let _e3999 = local_359;
                                                                                phi_3283_ = ((_e3997 - 1i) - _e3999);
                                                                            }
                                                                            let _e4002 = phi_3283_;
                                                                            phi_3307_ = _e4002;
                                                                        } else {
                                                                            let _e3954 = local_353;
                                                                            let _e3955 = (_e3954 == 0i);
                                                                            local_360 = _e3955;
                                                                            if _e3955 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3956 = local_353;
                                                                            let _e3957 = (_e3956 == -1i);
                                                                            local_361 = _e3957;
                                                                            let _e3958 = local_329;
                                                                            if (_e3957 && (_e3958 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3961 = local_329;
                                                                            let _e3962 = local_353;
                                                                            let _e3964 = local_353;
                                                                            local_362 = ((_e3961 % _e3962) + _e3964);
                                                                            let _e3966 = local_360;
                                                                            if _e3966 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3967 = local_362;
                                                                            let _e3969 = local_361;
                                                                            if (_e3969 && (_e3967 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3971 = local_362;
                                                                            let _e3972 = local_353;
                                                                            phi_3307_ = (_e3971 % _e3972);
                                                                        }
                                                                        let _e4004 = phi_3307_;
                                                                        phi_3308_ = _e4004;
                                                                    }
                                                                    let _e4017 = phi_3308_;
                                                                    local_363 = bitcast<u32>(_e4017);
                                                                    let _e4019 = local_329;
                                                                    let _e4020 = (_e4019 + 1i);
                                                                    local_364 = _e4020;
                                                                    let _e4021 = local_354;
                                                                    if _e4021 {
                                                                        let _e4075 = local_364;
                                                                        if (_e4075 < 0i) {
                                                                            phi_3328_ = 0i;
                                                                        } else {
                                                                            let _e4077 = local_364;
                                                                            let _e4078 = local_353;
                                                                            if (_e4077 >= _e4078) {
                                                                                let _e4080 = local_353;
                                                                                phi_3327_ = (_e4080 - 1i);
                                                                            } else {
                                                                                phi_3327_ = _e4020;
                                                                            }
                                                                            let _e4083 = phi_3327_;
                                                                            phi_3328_ = _e4083;
                                                                        }
                                                                        let _e4085 = phi_3328_;
                                                                        phi_3388_ = _e4085;
                                                                    } else {
                                                                        let _e4022 = local_352;
                                                                        if (_e4022 == 2u) {
                                                                            let _e4044 = local_353;
                                                                            let _e4045 = (2i * _e4044);
                                                                            local_365 = _e4045;
                                                                            let _e4046 = (_e4045 == 0i);
                                                                            local_366 = _e4046;
                                                                            if _e4046 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4047 = local_365;
                                                                            let _e4048 = (_e4047 == -1i);
                                                                            local_367 = _e4048;
                                                                            let _e4049 = local_364;
                                                                            if (_e4048 && (_e4049 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4052 = local_364;
                                                                            let _e4053 = local_365;
                                                                            let _e4055 = local_365;
                                                                            local_368 = ((_e4052 % _e4053) + _e4055);
                                                                            let _e4057 = local_366;
                                                                            if _e4057 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4058 = local_368;
                                                                            let _e4060 = local_367;
                                                                            if (_e4060 && (_e4058 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4062 = local_368;
                                                                            let _e4063 = local_365;
                                                                            let _e4064 = (_e4062 % _e4063);
                                                                            local_369 = _e4064;
                                                                            let _e4065 = local_353;
                                                                            if (_e4064 < _e4065) {
                                                                                phi_3363_ = _e4064;
                                                                            } else {
                                                                                let _e4067 = local_365;
                                                                                let _e4069 = local_369;
                                                                                phi_3363_ = ((_e4067 - 1i) - _e4069);
                                                                            }
                                                                            let _e4072 = phi_3363_;
                                                                            phi_3387_ = _e4072;
                                                                        } else {
                                                                            let _e4024 = local_353;
                                                                            let _e4025 = (_e4024 == 0i);
                                                                            local_370 = _e4025;
                                                                            if _e4025 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4026 = local_353;
                                                                            let _e4027 = (_e4026 == -1i);
                                                                            local_371 = _e4027;
                                                                            let _e4028 = local_364;
                                                                            if (_e4027 && (_e4028 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4031 = local_364;
                                                                            let _e4032 = local_353;
                                                                            let _e4034 = local_353;
                                                                            local_372 = ((_e4031 % _e4032) + _e4034);
                                                                            let _e4036 = local_370;
                                                                            if _e4036 {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4037 = local_372;
                                                                            let _e4039 = local_371;
                                                                            if (_e4039 && (_e4037 == i32(-2147483648))) {
                                                                                phi_5871_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4041 = local_372;
                                                                            let _e4042 = local_353;
                                                                            phi_3387_ = (_e4041 % _e4042);
                                                                        }
                                                                        let _e4074 = phi_3387_;
                                                                        phi_3388_ = _e4074;
                                                                    }
                                                                    let _e4087 = phi_3388_;
                                                                    local_373 = bitcast<u32>(_e4087);
                                                                    let _e4089 = local_318;
                                                                    local_374 = _e4089.member;
                                                                    let _e4091 = local_363;
                                                                    let _e4092 = local_320;
                                                                    let _e4094 = (_e4089.member + (_e4091 * _e4092));
                                                                    local_375 = _e4094;
                                                                    let _e4095 = local_341;
                                                                    let _e4097 = ((_e4094 + _e4095) * 2u);
                                                                    local_376 = _e4097;
                                                                    let _e4098 = local_6;
                                                                    if (_e4097 < _e4098) {
                                                                    } else {
                                                                        phi_5871_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4100 = local_376;
                                                                    let _e4103 = global_9.member[_e4100];
                                                                    local_377 = _e4103;
                                                                    let _e4104 = local_376;
                                                                    let _e4105 = (_e4104 + 1u);
                                                                    local_378 = _e4105;
                                                                    let _e4106 = local_6;
                                                                    if (_e4105 < _e4106) {
                                                                    } else {
                                                                        phi_5871_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4108 = local_378;
                                                                    let _e4111 = global_9.member[_e4108];
                                                                    local_379 = _e4111;
                                                                    let _e4112 = local_377;
                                                                    let _e4113 = (_e4112 & 65535u);
                                                                    local_591 = select(-1f, 1f, ((_e4113 & 32768u) == 0u));
                                                                    let _e4119 = ((_e4113 >> bitcast<u32>(10i)) & 31u);
                                                                    local_380 = _e4119;
                                                                    local_381 = (_e4113 & 1023u);
                                                                    if (_e4119 == 0u) {
                                                                        let _e4141 = local_381;
                                                                        let _e4143 = local_591;
                                                                        phi_3458_ = ((_e4143 * f32(_e4141)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4122 = local_380;
                                                                        if (_e4122 == 31u) {
                                                                            let _e4132 = local_381;
                                                                            phi_3455_ = (2139095040u | (_e4132 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4124 = local_380;
                                                                            let _e4128 = local_381;
                                                                            phi_3455_ = (((_e4124 + 112u) << bitcast<u32>(23i)) | (_e4128 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4137 = phi_3455_;
                                                                        let _e4139 = local_591;
                                                                        phi_3458_ = (_e4139 * bitcast<f32>(_e4137));
                                                                    }
                                                                    let _e4147 = phi_3458_;
                                                                    local_382 = _e4147;
                                                                    let _e4148 = local_377;
                                                                    let _e4150 = (_e4148 >> bitcast<u32>(16i));
                                                                    local_592 = select(-1f, 1f, ((_e4150 & 32768u) == 0u));
                                                                    let _e4156 = ((_e4150 >> bitcast<u32>(10i)) & 31u);
                                                                    local_383 = _e4156;
                                                                    local_384 = (_e4150 & 1023u);
                                                                    if (_e4156 == 0u) {
                                                                        let _e4178 = local_384;
                                                                        let _e4180 = local_592;
                                                                        phi_3490_ = ((_e4180 * f32(_e4178)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4159 = local_383;
                                                                        if (_e4159 == 31u) {
                                                                            let _e4169 = local_384;
                                                                            phi_3487_ = (2139095040u | (_e4169 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4161 = local_383;
                                                                            let _e4165 = local_384;
                                                                            phi_3487_ = (((_e4161 + 112u) << bitcast<u32>(23i)) | (_e4165 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4174 = phi_3487_;
                                                                        let _e4176 = local_592;
                                                                        phi_3490_ = (_e4176 * bitcast<f32>(_e4174));
                                                                    }
                                                                    let _e4184 = phi_3490_;
                                                                    local_385 = _e4184;
                                                                    let _e4185 = local_379;
                                                                    let _e4186 = (_e4185 & 65535u);
                                                                    local_593 = select(-1f, 1f, ((_e4186 & 32768u) == 0u));
                                                                    let _e4192 = ((_e4186 >> bitcast<u32>(10i)) & 31u);
                                                                    local_386 = _e4192;
                                                                    local_387 = (_e4186 & 1023u);
                                                                    if (_e4192 == 0u) {
                                                                        let _e4214 = local_387;
                                                                        let _e4216 = local_593;
                                                                        phi_3522_ = ((_e4216 * f32(_e4214)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4195 = local_386;
                                                                        if (_e4195 == 31u) {
                                                                            let _e4205 = local_387;
                                                                            phi_3519_ = (2139095040u | (_e4205 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4197 = local_386;
                                                                            let _e4201 = local_387;
                                                                            phi_3519_ = (((_e4197 + 112u) << bitcast<u32>(23i)) | (_e4201 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4210 = phi_3519_;
                                                                        let _e4212 = local_593;
                                                                        phi_3522_ = (_e4212 * bitcast<f32>(_e4210));
                                                                    }
                                                                    let _e4220 = phi_3522_;
                                                                    local_388 = _e4220;
                                                                    let _e4221 = local_379;
                                                                    let _e4223 = (_e4221 >> bitcast<u32>(16i));
                                                                    local_594 = select(-1f, 1f, ((_e4223 & 32768u) == 0u));
                                                                    let _e4229 = ((_e4223 >> bitcast<u32>(10i)) & 31u);
                                                                    local_389 = _e4229;
                                                                    local_390 = (_e4223 & 1023u);
                                                                    if (_e4229 == 0u) {
                                                                        let _e4251 = local_390;
                                                                        let _e4253 = local_594;
                                                                        phi_3554_ = ((_e4253 * f32(_e4251)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4232 = local_389;
                                                                        if (_e4232 == 31u) {
                                                                            let _e4242 = local_390;
                                                                            phi_3551_ = (2139095040u | (_e4242 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4234 = local_389;
                                                                            let _e4238 = local_390;
                                                                            phi_3551_ = (((_e4234 + 112u) << bitcast<u32>(23i)) | (_e4238 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4247 = phi_3551_;
                                                                        let _e4249 = local_594;
                                                                        phi_3554_ = (_e4249 * bitcast<f32>(_e4247));
                                                                    }
                                                                    let _e4257 = phi_3554_;
                                                                    local_391 = _e4257;
                                                                    let _e4258 = local_375;
                                                                    let _e4259 = local_351;
                                                                    let _e4261 = ((_e4258 + _e4259) * 2u);
                                                                    local_392 = _e4261;
                                                                    let _e4262 = local_6;
                                                                    if (_e4261 < _e4262) {
                                                                    } else {
                                                                        phi_5871_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4264 = local_392;
                                                                    let _e4267 = global_9.member[_e4264];
                                                                    local_393 = _e4267;
                                                                    let _e4268 = local_392;
                                                                    let _e4269 = (_e4268 + 1u);
                                                                    local_394 = _e4269;
                                                                    let _e4270 = local_6;
                                                                    if (_e4269 < _e4270) {
                                                                    } else {
                                                                        phi_5871_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4272 = local_394;
                                                                    let _e4275 = global_9.member[_e4272];
                                                                    local_395 = _e4275;
                                                                    let _e4276 = local_393;
                                                                    let _e4277 = (_e4276 & 65535u);
                                                                    local_595 = select(-1f, 1f, ((_e4277 & 32768u) == 0u));
                                                                    let _e4283 = ((_e4277 >> bitcast<u32>(10i)) & 31u);
                                                                    local_396 = _e4283;
                                                                    local_397 = (_e4277 & 1023u);
                                                                    if (_e4283 == 0u) {
                                                                        let _e4305 = local_397;
                                                                        let _e4307 = local_595;
                                                                        phi_3623_ = ((_e4307 * f32(_e4305)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4286 = local_396;
                                                                        if (_e4286 == 31u) {
                                                                            let _e4296 = local_397;
                                                                            phi_3620_ = (2139095040u | (_e4296 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4288 = local_396;
                                                                            let _e4292 = local_397;
                                                                            phi_3620_ = (((_e4288 + 112u) << bitcast<u32>(23i)) | (_e4292 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4301 = phi_3620_;
                                                                        let _e4303 = local_595;
                                                                        phi_3623_ = (_e4303 * bitcast<f32>(_e4301));
                                                                    }
                                                                    let _e4311 = phi_3623_;
                                                                    local_398 = _e4311;
                                                                    let _e4312 = local_393;
                                                                    let _e4314 = (_e4312 >> bitcast<u32>(16i));
                                                                    local_596 = select(-1f, 1f, ((_e4314 & 32768u) == 0u));
                                                                    let _e4320 = ((_e4314 >> bitcast<u32>(10i)) & 31u);
                                                                    local_399 = _e4320;
                                                                    local_400 = (_e4314 & 1023u);
                                                                    if (_e4320 == 0u) {
                                                                        let _e4342 = local_400;
                                                                        let _e4344 = local_596;
                                                                        phi_3655_ = ((_e4344 * f32(_e4342)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4323 = local_399;
                                                                        if (_e4323 == 31u) {
                                                                            let _e4333 = local_400;
                                                                            phi_3652_ = (2139095040u | (_e4333 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4325 = local_399;
                                                                            let _e4329 = local_400;
                                                                            phi_3652_ = (((_e4325 + 112u) << bitcast<u32>(23i)) | (_e4329 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4338 = phi_3652_;
                                                                        let _e4340 = local_596;
                                                                        phi_3655_ = (_e4340 * bitcast<f32>(_e4338));
                                                                    }
                                                                    let _e4348 = phi_3655_;
                                                                    local_401 = _e4348;
                                                                    let _e4349 = local_395;
                                                                    let _e4350 = (_e4349 & 65535u);
                                                                    local_597 = select(-1f, 1f, ((_e4350 & 32768u) == 0u));
                                                                    let _e4356 = ((_e4350 >> bitcast<u32>(10i)) & 31u);
                                                                    local_402 = _e4356;
                                                                    local_403 = (_e4350 & 1023u);
                                                                    if (_e4356 == 0u) {
                                                                        let _e4378 = local_403;
                                                                        let _e4380 = local_597;
                                                                        phi_3687_ = ((_e4380 * f32(_e4378)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4359 = local_402;
                                                                        if (_e4359 == 31u) {
                                                                            let _e4369 = local_403;
                                                                            phi_3684_ = (2139095040u | (_e4369 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4361 = local_402;
                                                                            let _e4365 = local_403;
                                                                            phi_3684_ = (((_e4361 + 112u) << bitcast<u32>(23i)) | (_e4365 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4374 = phi_3684_;
                                                                        let _e4376 = local_597;
                                                                        phi_3687_ = (_e4376 * bitcast<f32>(_e4374));
                                                                    }
                                                                    let _e4384 = phi_3687_;
                                                                    local_404 = _e4384;
                                                                    let _e4385 = local_395;
                                                                    let _e4387 = (_e4385 >> bitcast<u32>(16i));
                                                                    local_598 = select(-1f, 1f, ((_e4387 & 32768u) == 0u));
                                                                    let _e4393 = ((_e4387 >> bitcast<u32>(10i)) & 31u);
                                                                    local_405 = _e4393;
                                                                    local_406 = (_e4387 & 1023u);
                                                                    if (_e4393 == 0u) {
                                                                        let _e4415 = local_406;
                                                                        let _e4417 = local_598;
                                                                        phi_3719_ = ((_e4417 * f32(_e4415)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4396 = local_405;
                                                                        if (_e4396 == 31u) {
                                                                            let _e4406 = local_406;
                                                                            phi_3716_ = (2139095040u | (_e4406 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4398 = local_405;
                                                                            let _e4402 = local_406;
                                                                            phi_3716_ = (((_e4398 + 112u) << bitcast<u32>(23i)) | (_e4402 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4411 = phi_3716_;
                                                                        let _e4413 = local_598;
                                                                        phi_3719_ = (_e4413 * bitcast<f32>(_e4411));
                                                                    }
                                                                    let _e4421 = phi_3719_;
                                                                    let _e4422 = local_398;
                                                                    let _e4423 = local_382;
                                                                    let _e4425 = local_327;
                                                                    let _e4427 = local_382;
                                                                    local_407 = (_e4427 + ((_e4422 - _e4423) * _e4425));
                                                                    let _e4429 = local_401;
                                                                    let _e4430 = local_385;
                                                                    let _e4432 = local_327;
                                                                    let _e4434 = local_385;
                                                                    local_408 = (_e4434 + ((_e4429 - _e4430) * _e4432));
                                                                    let _e4436 = local_404;
                                                                    let _e4437 = local_388;
                                                                    let _e4439 = local_327;
                                                                    let _e4441 = local_388;
                                                                    local_409 = (_e4441 + ((_e4436 - _e4437) * _e4439));
                                                                    let _e4443 = local_391;
                                                                    let _e4445 = local_327;
                                                                    let _e4447 = local_391;
                                                                    local_410 = (_e4447 + ((_e4421 - _e4443) * _e4445));
                                                                    let _e4449 = local_373;
                                                                    let _e4450 = local_320;
                                                                    let _e4452 = local_374;
                                                                    let _e4453 = (_e4452 + (_e4449 * _e4450));
                                                                    local_411 = _e4453;
                                                                    let _e4454 = local_341;
                                                                    let _e4456 = ((_e4453 + _e4454) * 2u);
                                                                    local_412 = _e4456;
                                                                    let _e4457 = local_6;
                                                                    if (_e4456 < _e4457) {
                                                                    } else {
                                                                        phi_5871_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4459 = local_412;
                                                                    let _e4462 = global_9.member[_e4459];
                                                                    local_413 = _e4462;
                                                                    let _e4463 = local_412;
                                                                    let _e4464 = (_e4463 + 1u);
                                                                    local_414 = _e4464;
                                                                    let _e4465 = local_6;
                                                                    if (_e4464 < _e4465) {
                                                                    } else {
                                                                        phi_5871_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4467 = local_414;
                                                                    let _e4470 = global_9.member[_e4467];
                                                                    local_415 = _e4470;
                                                                    let _e4471 = local_413;
                                                                    let _e4472 = (_e4471 & 65535u);
                                                                    local_599 = select(-1f, 1f, ((_e4472 & 32768u) == 0u));
                                                                    let _e4478 = ((_e4472 >> bitcast<u32>(10i)) & 31u);
                                                                    local_416 = _e4478;
                                                                    local_417 = (_e4472 & 1023u);
                                                                    if (_e4478 == 0u) {
                                                                        let _e4500 = local_417;
                                                                        let _e4502 = local_599;
                                                                        phi_3800_ = ((_e4502 * f32(_e4500)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4481 = local_416;
                                                                        if (_e4481 == 31u) {
                                                                            let _e4491 = local_417;
                                                                            phi_3797_ = (2139095040u | (_e4491 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4483 = local_416;
                                                                            let _e4487 = local_417;
                                                                            phi_3797_ = (((_e4483 + 112u) << bitcast<u32>(23i)) | (_e4487 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4496 = phi_3797_;
                                                                        let _e4498 = local_599;
                                                                        phi_3800_ = (_e4498 * bitcast<f32>(_e4496));
                                                                    }
                                                                    let _e4506 = phi_3800_;
                                                                    local_418 = _e4506;
                                                                    let _e4507 = local_413;
                                                                    let _e4509 = (_e4507 >> bitcast<u32>(16i));
                                                                    local_600 = select(-1f, 1f, ((_e4509 & 32768u) == 0u));
                                                                    let _e4515 = ((_e4509 >> bitcast<u32>(10i)) & 31u);
                                                                    local_419 = _e4515;
                                                                    local_420 = (_e4509 & 1023u);
                                                                    if (_e4515 == 0u) {
                                                                        let _e4537 = local_420;
                                                                        let _e4539 = local_600;
                                                                        phi_3832_ = ((_e4539 * f32(_e4537)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4518 = local_419;
                                                                        if (_e4518 == 31u) {
                                                                            let _e4528 = local_420;
                                                                            phi_3829_ = (2139095040u | (_e4528 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4520 = local_419;
                                                                            let _e4524 = local_420;
                                                                            phi_3829_ = (((_e4520 + 112u) << bitcast<u32>(23i)) | (_e4524 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4533 = phi_3829_;
                                                                        let _e4535 = local_600;
                                                                        phi_3832_ = (_e4535 * bitcast<f32>(_e4533));
                                                                    }
                                                                    let _e4543 = phi_3832_;
                                                                    local_421 = _e4543;
                                                                    let _e4544 = local_415;
                                                                    let _e4545 = (_e4544 & 65535u);
                                                                    local_601 = select(-1f, 1f, ((_e4545 & 32768u) == 0u));
                                                                    let _e4551 = ((_e4545 >> bitcast<u32>(10i)) & 31u);
                                                                    local_422 = _e4551;
                                                                    local_423 = (_e4545 & 1023u);
                                                                    if (_e4551 == 0u) {
                                                                        let _e4573 = local_423;
                                                                        let _e4575 = local_601;
                                                                        phi_3864_ = ((_e4575 * f32(_e4573)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4554 = local_422;
                                                                        if (_e4554 == 31u) {
                                                                            let _e4564 = local_423;
                                                                            phi_3861_ = (2139095040u | (_e4564 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4556 = local_422;
                                                                            let _e4560 = local_423;
                                                                            phi_3861_ = (((_e4556 + 112u) << bitcast<u32>(23i)) | (_e4560 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4569 = phi_3861_;
                                                                        let _e4571 = local_601;
                                                                        phi_3864_ = (_e4571 * bitcast<f32>(_e4569));
                                                                    }
                                                                    let _e4579 = phi_3864_;
                                                                    local_424 = _e4579;
                                                                    let _e4580 = local_415;
                                                                    let _e4582 = (_e4580 >> bitcast<u32>(16i));
                                                                    local_602 = select(-1f, 1f, ((_e4582 & 32768u) == 0u));
                                                                    let _e4588 = ((_e4582 >> bitcast<u32>(10i)) & 31u);
                                                                    local_425 = _e4588;
                                                                    local_426 = (_e4582 & 1023u);
                                                                    if (_e4588 == 0u) {
                                                                        let _e4610 = local_426;
                                                                        let _e4612 = local_602;
                                                                        phi_3896_ = ((_e4612 * f32(_e4610)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4591 = local_425;
                                                                        if (_e4591 == 31u) {
                                                                            let _e4601 = local_426;
                                                                            phi_3893_ = (2139095040u | (_e4601 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4593 = local_425;
                                                                            let _e4597 = local_426;
                                                                            phi_3893_ = (((_e4593 + 112u) << bitcast<u32>(23i)) | (_e4597 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4606 = phi_3893_;
                                                                        let _e4608 = local_602;
                                                                        phi_3896_ = (_e4608 * bitcast<f32>(_e4606));
                                                                    }
                                                                    let _e4616 = phi_3896_;
                                                                    local_427 = _e4616;
                                                                    let _e4617 = local_411;
                                                                    let _e4618 = local_351;
                                                                    let _e4620 = ((_e4617 + _e4618) * 2u);
                                                                    local_428 = _e4620;
                                                                    let _e4621 = local_6;
                                                                    if (_e4620 < _e4621) {
                                                                    } else {
                                                                        phi_5871_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4623 = local_428;
                                                                    let _e4626 = global_9.member[_e4623];
                                                                    local_429 = _e4626;
                                                                    let _e4627 = local_428;
                                                                    let _e4628 = (_e4627 + 1u);
                                                                    local_430 = _e4628;
                                                                    let _e4629 = local_6;
                                                                    if (_e4628 < _e4629) {
                                                                    } else {
                                                                        phi_5871_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4631 = local_430;
                                                                    let _e4634 = global_9.member[_e4631];
                                                                    local_431 = _e4634;
                                                                    let _e4635 = local_429;
                                                                    let _e4636 = (_e4635 & 65535u);
                                                                    local_603 = select(-1f, 1f, ((_e4636 & 32768u) == 0u));
                                                                    let _e4642 = ((_e4636 >> bitcast<u32>(10i)) & 31u);
                                                                    local_432 = _e4642;
                                                                    local_433 = (_e4636 & 1023u);
                                                                    if (_e4642 == 0u) {
                                                                        let _e4664 = local_433;
                                                                        let _e4666 = local_603;
                                                                        phi_3965_ = ((_e4666 * f32(_e4664)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4645 = local_432;
                                                                        if (_e4645 == 31u) {
                                                                            let _e4655 = local_433;
                                                                            phi_3962_ = (2139095040u | (_e4655 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4647 = local_432;
                                                                            let _e4651 = local_433;
                                                                            phi_3962_ = (((_e4647 + 112u) << bitcast<u32>(23i)) | (_e4651 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4660 = phi_3962_;
                                                                        let _e4662 = local_603;
                                                                        phi_3965_ = (_e4662 * bitcast<f32>(_e4660));
                                                                    }
                                                                    let _e4670 = phi_3965_;
                                                                    local_434 = _e4670;
                                                                    let _e4671 = local_429;
                                                                    let _e4673 = (_e4671 >> bitcast<u32>(16i));
                                                                    local_604 = select(-1f, 1f, ((_e4673 & 32768u) == 0u));
                                                                    let _e4679 = ((_e4673 >> bitcast<u32>(10i)) & 31u);
                                                                    local_435 = _e4679;
                                                                    local_436 = (_e4673 & 1023u);
                                                                    if (_e4679 == 0u) {
                                                                        let _e4701 = local_436;
                                                                        let _e4703 = local_604;
                                                                        phi_3997_ = ((_e4703 * f32(_e4701)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4682 = local_435;
                                                                        if (_e4682 == 31u) {
                                                                            let _e4692 = local_436;
                                                                            phi_3994_ = (2139095040u | (_e4692 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4684 = local_435;
                                                                            let _e4688 = local_436;
                                                                            phi_3994_ = (((_e4684 + 112u) << bitcast<u32>(23i)) | (_e4688 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4697 = phi_3994_;
                                                                        let _e4699 = local_604;
                                                                        phi_3997_ = (_e4699 * bitcast<f32>(_e4697));
                                                                    }
                                                                    let _e4707 = phi_3997_;
                                                                    local_437 = _e4707;
                                                                    let _e4708 = local_431;
                                                                    let _e4709 = (_e4708 & 65535u);
                                                                    local_605 = select(-1f, 1f, ((_e4709 & 32768u) == 0u));
                                                                    let _e4715 = ((_e4709 >> bitcast<u32>(10i)) & 31u);
                                                                    local_438 = _e4715;
                                                                    local_439 = (_e4709 & 1023u);
                                                                    if (_e4715 == 0u) {
                                                                        let _e4737 = local_439;
                                                                        let _e4739 = local_605;
                                                                        phi_4029_ = ((_e4739 * f32(_e4737)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4718 = local_438;
                                                                        if (_e4718 == 31u) {
                                                                            let _e4728 = local_439;
                                                                            phi_4026_ = (2139095040u | (_e4728 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4720 = local_438;
                                                                            let _e4724 = local_439;
                                                                            phi_4026_ = (((_e4720 + 112u) << bitcast<u32>(23i)) | (_e4724 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4733 = phi_4026_;
                                                                        let _e4735 = local_605;
                                                                        phi_4029_ = (_e4735 * bitcast<f32>(_e4733));
                                                                    }
                                                                    let _e4743 = phi_4029_;
                                                                    local_440 = _e4743;
                                                                    let _e4744 = local_431;
                                                                    let _e4746 = (_e4744 >> bitcast<u32>(16i));
                                                                    local_606 = select(-1f, 1f, ((_e4746 & 32768u) == 0u));
                                                                    let _e4752 = ((_e4746 >> bitcast<u32>(10i)) & 31u);
                                                                    local_441 = _e4752;
                                                                    local_442 = (_e4746 & 1023u);
                                                                    if (_e4752 == 0u) {
                                                                        let _e4774 = local_442;
                                                                        let _e4776 = local_606;
                                                                        phi_4061_ = ((_e4776 * f32(_e4774)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4755 = local_441;
                                                                        if (_e4755 == 31u) {
                                                                            let _e4765 = local_442;
                                                                            phi_4058_ = (2139095040u | (_e4765 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4757 = local_441;
                                                                            let _e4761 = local_442;
                                                                            phi_4058_ = (((_e4757 + 112u) << bitcast<u32>(23i)) | (_e4761 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4770 = phi_4058_;
                                                                        let _e4772 = local_606;
                                                                        phi_4061_ = (_e4772 * bitcast<f32>(_e4770));
                                                                    }
                                                                    let _e4780 = phi_4061_;
                                                                    let _e4781 = local_434;
                                                                    let _e4782 = local_418;
                                                                    let _e4784 = local_327;
                                                                    let _e4786 = local_418;
                                                                    let _e4788 = local_437;
                                                                    let _e4789 = local_421;
                                                                    let _e4791 = local_327;
                                                                    let _e4793 = local_421;
                                                                    let _e4795 = local_440;
                                                                    let _e4796 = local_424;
                                                                    let _e4798 = local_327;
                                                                    let _e4800 = local_424;
                                                                    let _e4802 = local_427;
                                                                    let _e4804 = local_327;
                                                                    let _e4806 = local_427;
                                                                    let _e4808 = local_407;
                                                                    let _e4810 = local_326;
                                                                    let _e4812 = local_407;
                                                                    let _e4814 = local_408;
                                                                    let _e4816 = local_326;
                                                                    let _e4818 = local_408;
                                                                    let _e4820 = local_409;
                                                                    let _e4822 = local_326;
                                                                    let _e4824 = local_409;
                                                                    let _e4826 = local_410;
                                                                    let _e4828 = local_326;
                                                                    let _e4830 = local_410;
                                                                    let _e4832 = local_319;
                                                                    let _e4834 = local_319;
                                                                    let _e4836 = local_319;
                                                                    let _e4838 = local_319;
                                                                    let _e4840 = local_316;
                                                                    let _e4843 = local_316;
                                                                    let _e4846 = local_316;
                                                                    let _e4849 = local_316;
                                                                    let _e4853 = local_315;
                                                                    phi_3016_ = (_e4853 + 1u);
                                                                    phi_3019_ = type_5((_e4840.member + ((_e4812 + (((_e4786 + ((_e4781 - _e4782) * _e4784)) - _e4808) * _e4810)) * _e4832)), (_e4843.member_1 + ((_e4818 + (((_e4793 + ((_e4788 - _e4789) * _e4791)) - _e4814) * _e4816)) * _e4834)), (_e4846.member_2 + ((_e4824 + (((_e4800 + ((_e4795 - _e4796) * _e4798)) - _e4820) * _e4822)) * _e4836)), (_e4849.member_3 + ((_e4830 + (((_e4806 + ((_e4780 - _e4802) * _e4804)) - _e4826) * _e4828)) * _e4838)));
                                                                } else {
                                                                    phi_3016_ = u32();
                                                                    phi_3019_ = type_5();
                                                                }
                                                                let _e4856 = phi_3016_;
                                                                let _e4858 = phi_3019_;
                                                                continue;
                                                                continuing {
                                                                    let _e4859 = local_317;
                                                                    phi_3015_ = _e4856;
                                                                    phi_3018_ = _e4858;
                                                                    phi_5871_ = _e3708;
                                                                    break if !(_e4859);
                                                                }
                                                            }
                                                            let _e4862 = phi_5871_;
                                                            phi_5983_ = _e4862;
                                                            if _e4862 {
                                                                break;
                                                            }
                                                            let _e4863 = local_311;
                                                            phi_5984_ = _e4862;
                                                            phi_2987_ = (_e4863 + 1u);
                                                            let _e5773 = local_634;
                                                            phi_2990_ = _e5773;
                                                        } else {
                                                            phi_5984_ = _e3708;
                                                            phi_2987_ = u32();
                                                            phi_2990_ = type_5();
                                                        }
                                                        let _e4866 = phi_5984_;
                                                        let _e4868 = phi_2987_;
                                                        let _e4870 = phi_2990_;
                                                        continue;
                                                        continuing {
                                                            let _e4871 = local_312;
                                                            phi_5917_ = _e4866;
                                                            phi_2986_ = _e4868;
                                                            phi_2989_ = _e4870;
                                                            phi_5983_ = _e4866;
                                                            break if !(_e4871);
                                                        }
                                                    }
                                                    let _e4874 = phi_5983_;
                                                    phi_5985_ = _e4874;
                                                    if _e4874 {
                                                        break;
                                                    }
                                                    let _e4875 = local_307;
                                                    phi_5986_ = _e4874;
                                                    phi_2970_ = (_e4875 + 1u);
                                                    let _e5779 = local_635;
                                                    phi_2973_ = _e5779;
                                                } else {
                                                    phi_5986_ = _e3692;
                                                    phi_2970_ = u32();
                                                    phi_2973_ = type_5();
                                                }
                                                let _e4878 = phi_5986_;
                                                let _e4880 = phi_2970_;
                                                let _e4882 = phi_2973_;
                                                continue;
                                                continuing {
                                                    let _e4883 = local_309;
                                                    phi_5918_ = _e4878;
                                                    phi_2969_ = _e4880;
                                                    phi_2972_ = _e4882;
                                                    phi_5985_ = _e4878;
                                                    break if !(_e4883);
                                                }
                                            }
                                            let _e4886 = phi_5985_;
                                            phi_6024_ = _e4886;
                                            if _e4886 {
                                                break;
                                            }
                                            let _e4887 = local_298;
                                            let _e4888 = local_297;
                                            let _e4891 = (1f / f32((_e4887 * _e4888)));
                                            let _e4892 = local_308;
                                            let _e4895 = local_308;
                                            let _e4898 = local_308;
                                            let _e4901 = local_308;
                                            phi_6003_ = _e4886;
                                            phi_4114_ = type_5((_e4892.member * _e4891), (_e4895.member_1 * _e4891), (_e4898.member_2 * _e4891), (_e4901.member_3 * _e4891));
                                        }
                                        let _e4906 = phi_6003_;
                                        let _e4908 = phi_4114_;
                                        phi_6002_ = _e4906;
                                        phi_4115_ = _e4908;
                                        phi_4116_ = _e3344;
                                    }
                                    let _e4910 = phi_6002_;
                                    let _e4912 = phi_4115_;
                                    let _e4914 = phi_4116_;
                                    if _e4914 {
                                        phi_4120_ = type_5(1f, 1f, 1f, 1f);
                                    } else {
                                        phi_4120_ = _e4912;
                                    }
                                    let _e4916 = phi_4120_;
                                    phi_6000_ = _e4910;
                                    phi_4121_ = _e4916;
                                }
                                let _e4918 = phi_6000_;
                                let _e4920 = phi_4121_;
                                phi_5999_ = _e4918;
                                phi_4122_ = _e4920;
                                phi_4123_ = _e3308;
                            }
                            let _e4922 = phi_5999_;
                            let _e4924 = phi_4122_;
                            let _e4926 = phi_4123_;
                            if _e4926 {
                                phi_4127_ = type_5(1f, 1f, 1f, 1f);
                            } else {
                                phi_4127_ = _e4924;
                            }
                            let _e4928 = phi_4127_;
                            local_624 = array<f32, 4>(_e4928.member, _e4928.member_1, _e4928.member_2, _e4928.member_3);
                            let _e4934 = local_37;
                            local_614 = _e4934;
                            let _e4936 = local_18;
                            local_615[0u] = _e4936;
                            let _e4938 = local_20;
                            local_615[1u] = _e4938;
                            let _e4940 = local_38;
                            local_615[2u] = _e4940;
                            phi_4155_ = 0u;
                            phi_4158_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            loop {
                                let _e4942 = phi_4155_;
                                let _e4944 = phi_4158_;
                                local_443 = _e4942;
                                local_444 = _e4944;
                                let _e4945 = local_443;
                                let _e4946 = (_e4945 < 3u);
                                local_445 = _e4946;
                                if _e4946 {
                                    let _e4947 = local_443;
                                    if (_e4947 < 4u) {
                                    } else {
                                        phi_5987_ = true;
                                        break;
                                    }
                                    let _e4949 = local_443;
                                    let _e4951 = local_614[_e4949];
                                    let _e4952 = (_e4951 * 10u);
                                    local_446 = _e4952;
                                    let _e4953 = (_e4952 + 8u);
                                    local_447 = _e4953;
                                    let _e4954 = local_2;
                                    if (_e4953 < _e4954) {
                                    } else {
                                        phi_5987_ = true;
                                        break;
                                    }
                                    let _e4956 = local_447;
                                    let _e4959 = global_5.member[_e4956];
                                    local_448 = _e4959;
                                    let _e4960 = local_446;
                                    let _e4961 = (_e4960 + 9u);
                                    local_449 = _e4961;
                                    let _e4962 = local_2;
                                    if (_e4961 < _e4962) {
                                    } else {
                                        phi_5987_ = true;
                                        break;
                                    }
                                    let _e4964 = local_449;
                                    let _e4967 = global_5.member[_e4964];
                                    local_450 = _e4967;
                                    let _e4968 = local_445;
                                    if _e4968 {
                                    } else {
                                        phi_5987_ = true;
                                        break;
                                    }
                                    let _e4969 = local_443;
                                    let _e4971 = local_615[_e4969];
                                    local_451 = _e4971;
                                    let _e4972 = local_448;
                                    let _e4973 = (_e4972 & 65535u);
                                    local_607 = select(-1f, 1f, ((_e4973 & 32768u) == 0u));
                                    let _e4979 = ((_e4973 >> bitcast<u32>(10i)) & 31u);
                                    local_452 = _e4979;
                                    local_453 = (_e4973 & 1023u);
                                    if (_e4979 == 0u) {
                                        let _e5001 = local_453;
                                        let _e5003 = local_607;
                                        phi_4244_ = ((_e5003 * f32(_e5001)) * 0.000000059604645f);
                                    } else {
                                        let _e4982 = local_452;
                                        if (_e4982 == 31u) {
                                            let _e4992 = local_453;
                                            phi_4241_ = (2139095040u | (_e4992 << bitcast<u32>(13i)));
                                        } else {
                                            let _e4984 = local_452;
                                            let _e4988 = local_453;
                                            phi_4241_ = (((_e4984 + 112u) << bitcast<u32>(23i)) | (_e4988 << bitcast<u32>(13i)));
                                        }
                                        let _e4997 = phi_4241_;
                                        let _e4999 = local_607;
                                        phi_4244_ = (_e4999 * bitcast<f32>(_e4997));
                                    }
                                    let _e5007 = phi_4244_;
                                    let _e5008 = local_451;
                                    let _e5010 = local_444;
                                    local_454 = (_e5010[0] + (_e5008 * _e5007));
                                    let _e5013 = local_445;
                                    if _e5013 {
                                    } else {
                                        phi_5987_ = true;
                                        break;
                                    }
                                    let _e5014 = local_615[_e4969];
                                    local_455 = _e5014;
                                    let _e5015 = local_448;
                                    let _e5017 = (_e5015 >> bitcast<u32>(16i));
                                    local_608 = select(-1f, 1f, ((_e5017 & 32768u) == 0u));
                                    let _e5023 = ((_e5017 >> bitcast<u32>(10i)) & 31u);
                                    local_456 = _e5023;
                                    local_457 = (_e5017 & 1023u);
                                    if (_e5023 == 0u) {
                                        let _e5045 = local_457;
                                        let _e5047 = local_608;
                                        phi_4287_ = ((_e5047 * f32(_e5045)) * 0.000000059604645f);
                                    } else {
                                        let _e5026 = local_456;
                                        if (_e5026 == 31u) {
                                            let _e5036 = local_457;
                                            phi_4284_ = (2139095040u | (_e5036 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5028 = local_456;
                                            let _e5032 = local_457;
                                            phi_4284_ = (((_e5028 + 112u) << bitcast<u32>(23i)) | (_e5032 << bitcast<u32>(13i)));
                                        }
                                        let _e5041 = phi_4284_;
                                        let _e5043 = local_608;
                                        phi_4287_ = (_e5043 * bitcast<f32>(_e5041));
                                    }
                                    let _e5051 = phi_4287_;
                                    let _e5052 = local_455;
                                    let _e5054 = local_444;
                                    local_458 = (_e5054[1] + (_e5052 * _e5051));
                                    let _e5057 = local_445;
                                    if _e5057 {
                                    } else {
                                        phi_5987_ = true;
                                        break;
                                    }
                                    let _e5058 = local_615[_e4969];
                                    local_459 = _e5058;
                                    let _e5059 = local_450;
                                    let _e5060 = (_e5059 & 65535u);
                                    local_609 = select(-1f, 1f, ((_e5060 & 32768u) == 0u));
                                    let _e5066 = ((_e5060 >> bitcast<u32>(10i)) & 31u);
                                    local_460 = _e5066;
                                    local_461 = (_e5060 & 1023u);
                                    if (_e5066 == 0u) {
                                        let _e5088 = local_461;
                                        let _e5090 = local_609;
                                        phi_4330_ = ((_e5090 * f32(_e5088)) * 0.000000059604645f);
                                    } else {
                                        let _e5069 = local_460;
                                        if (_e5069 == 31u) {
                                            let _e5079 = local_461;
                                            phi_4327_ = (2139095040u | (_e5079 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5071 = local_460;
                                            let _e5075 = local_461;
                                            phi_4327_ = (((_e5071 + 112u) << bitcast<u32>(23i)) | (_e5075 << bitcast<u32>(13i)));
                                        }
                                        let _e5084 = phi_4327_;
                                        let _e5086 = local_609;
                                        phi_4330_ = (_e5086 * bitcast<f32>(_e5084));
                                    }
                                    let _e5094 = phi_4330_;
                                    let _e5095 = local_459;
                                    let _e5097 = local_444;
                                    local_462 = (_e5097[2] + (_e5095 * _e5094));
                                    let _e5100 = local_445;
                                    if _e5100 {
                                    } else {
                                        phi_5987_ = true;
                                        break;
                                    }
                                    let _e5101 = local_615[_e4969];
                                    local_463 = _e5101;
                                    let _e5102 = local_450;
                                    let _e5104 = (_e5102 >> bitcast<u32>(16i));
                                    local_610 = select(-1f, 1f, ((_e5104 & 32768u) == 0u));
                                    let _e5110 = ((_e5104 >> bitcast<u32>(10i)) & 31u);
                                    local_464 = _e5110;
                                    local_465 = (_e5104 & 1023u);
                                    if (_e5110 == 0u) {
                                        let _e5132 = local_465;
                                        let _e5134 = local_610;
                                        phi_4373_ = ((_e5134 * f32(_e5132)) * 0.000000059604645f);
                                    } else {
                                        let _e5113 = local_464;
                                        if (_e5113 == 31u) {
                                            let _e5123 = local_465;
                                            phi_4370_ = (2139095040u | (_e5123 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5115 = local_464;
                                            let _e5119 = local_465;
                                            phi_4370_ = (((_e5115 + 112u) << bitcast<u32>(23i)) | (_e5119 << bitcast<u32>(13i)));
                                        }
                                        let _e5128 = phi_4370_;
                                        let _e5130 = local_610;
                                        phi_4373_ = (_e5130 * bitcast<f32>(_e5128));
                                    }
                                    let _e5138 = phi_4373_;
                                    let _e5139 = local_463;
                                    let _e5141 = local_444;
                                    let _e5144 = local_454;
                                    let _e5145 = local_458;
                                    let _e5146 = local_462;
                                    let _e5148 = local_443;
                                    phi_4156_ = (_e5148 + 1u);
                                    phi_4159_ = array<f32, 4>(_e5144, _e5145, _e5146, (_e5141[3] + (_e5139 * _e5138)));
                                } else {
                                    phi_4156_ = u32();
                                    phi_4159_ = array<f32, 4>();
                                }
                                let _e5151 = phi_4156_;
                                let _e5153 = phi_4159_;
                                continue;
                                continuing {
                                    let _e5154 = local_445;
                                    phi_4155_ = _e5151;
                                    phi_4158_ = _e5153;
                                    phi_5987_ = _e4922;
                                    break if !(_e5154);
                                }
                            }
                            let _e5157 = phi_5987_;
                            phi_6024_ = _e5157;
                            if _e5157 {
                                break;
                            }
                            let _e5158 = local_444;
                            let _e5160 = local_444;
                            let _e5162 = local_444;
                            let _e5164 = local_444;
                            local_625 = array<f32, 4>(_e5158[0], _e5160[1], _e5162[2], _e5164[3]);
                            let _e5167 = local_86;
                            let _e5168 = (_e5167 + 10u);
                            local_466 = _e5168;
                            let _e5169 = local_4;
                            if (_e5168 < _e5169) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e5171 = local_466;
                            let _e5174 = global_7.member[_e5171];
                            local_467 = _e5174;
                            let _e5178 = global_3.member.member.member;
                            let _e5179 = local_76;
                            let _e5183 = local_76;
                            let _e5188 = local_76;
                            let _e5192 = (((_e5179[0] * _e5178[0]) + (_e5183[1] * _e5178[1])) + (_e5188[2] * _e5178[2]));
                            local_468 = _e5192;
                            if !((_e5192 == _e5192)) {
                                phi_5713_ = true;
                            } else {
                                let _e5195 = local_468;
                                phi_5713_ = (0f >= _e5195);
                            }
                            let _e5198 = phi_5713_;
                            let _e5199 = local_468;
                            local_611 = select(_e5199, 0f, _e5198);
                            local_626 = array<f32, 3>(0f, 0f, 0f);
                            phi_4415_ = 0u;
                            loop {
                                let _e5202 = phi_4415_;
                                local_469 = _e5202;
                                let _e5203 = local_469;
                                let _e5204 = (_e5203 < 3u);
                                local_470 = _e5204;
                                if _e5204 {
                                    let _e5205 = local_86;
                                    let _e5206 = local_469;
                                    let _e5207 = (_e5205 + _e5206);
                                    local_471 = _e5207;
                                    let _e5208 = local_4;
                                    if (_e5207 < _e5208) {
                                    } else {
                                        phi_6008_ = true;
                                        break;
                                    }
                                    let _e5210 = local_471;
                                    let _e5213 = global_7.member[_e5210];
                                    local_472 = bitcast<f32>(_e5213);
                                    let _e5215 = local_469;
                                    let _e5216 = (_e5215 < 4u);
                                    local_473 = _e5216;
                                    if _e5216 {
                                    } else {
                                        phi_6008_ = true;
                                        break;
                                    }
                                    let _e5217 = local_469;
                                    let _e5219 = local_623[_e5217];
                                    let _e5220 = local_472;
                                    local_474 = (_e5220 * _e5219);
                                    let _e5222 = local_473;
                                    if _e5222 {
                                    } else {
                                        phi_6008_ = true;
                                        break;
                                    }
                                    let _e5223 = local_469;
                                    let _e5225 = local_625[_e5223];
                                    let _e5226 = local_474;
                                    let _e5227 = (_e5226 * _e5225);
                                    local_475 = _e5227;
                                    let _e5228 = local_467;
                                    if ((_e5228 & 1u) == 0u) {
                                        let _e5231 = local_470;
                                        if _e5231 {
                                        } else {
                                            phi_6008_ = true;
                                            break;
                                        }
                                        let _e5232 = local_469;
                                        let _e5237 = global_3.member.member.member_4[_e5232];
                                        local_476 = _e5237;
                                        let _e5238 = local_470;
                                        if _e5238 {
                                        } else {
                                            phi_6008_ = true;
                                            break;
                                        }
                                        let _e5239 = local_469;
                                        let _e5244 = global_3.member.member.member_2[_e5239];
                                        let _e5245 = local_611;
                                        let _e5247 = local_476;
                                        let _e5249 = local_475;
                                        phi_4481_ = (_e5249 * (_e5247 + (_e5244 * _e5245)));
                                    } else {
                                        phi_4481_ = _e5227;
                                    }
                                    let _e5252 = phi_4481_;
                                    local_477 = _e5252;
                                    let _e5253 = local_86;
                                    let _e5255 = local_469;
                                    let _e5256 = ((_e5253 + 4u) + _e5255);
                                    local_478 = _e5256;
                                    let _e5257 = local_4;
                                    if (_e5256 < _e5257) {
                                    } else {
                                        phi_6008_ = true;
                                        break;
                                    }
                                    let _e5259 = local_478;
                                    let _e5262 = global_7.member[_e5259];
                                    local_479 = bitcast<f32>(_e5262);
                                    let _e5264 = local_473;
                                    if _e5264 {
                                    } else {
                                        phi_6008_ = true;
                                        break;
                                    }
                                    let _e5265 = local_469;
                                    let _e5267 = local_624[_e5265];
                                    let _e5268 = local_479;
                                    local_480 = (_e5268 * _e5267);
                                    let _e5270 = local_470;
                                    if _e5270 {
                                    } else {
                                        phi_6008_ = true;
                                        break;
                                    }
                                    let _e5271 = local_469;
                                    let _e5273 = local_477;
                                    let _e5274 = local_480;
                                    local_626[_e5271] = (_e5273 + _e5274);
                                    let _e5276 = local_469;
                                    phi_4416_ = (_e5276 + 1u);
                                } else {
                                    phi_4416_ = u32();
                                }
                                let _e5279 = phi_4416_;
                                continue;
                                continuing {
                                    let _e5280 = local_470;
                                    phi_4415_ = _e5279;
                                    phi_6008_ = _e5157;
                                    break if !(_e5280);
                                }
                            }
                            let _e5283 = phi_6008_;
                            phi_6024_ = _e5283;
                            if _e5283 {
                                break;
                            }
                            let _e5284 = local_467;
                            if ((_e5284 & 8u) == 0u) {
                                phi_4558_ = 1f;
                            } else {
                                let _e5287 = local_86;
                                let _e5288 = (_e5287 + 3u);
                                local_481 = _e5288;
                                let _e5289 = local_4;
                                if (_e5288 < _e5289) {
                                } else {
                                    phi_6024_ = true;
                                    break;
                                }
                                let _e5291 = local_481;
                                let _e5294 = global_7.member[_e5291];
                                let _e5297 = local_623[3u];
                                let _e5300 = local_625[3u];
                                let _e5301 = ((bitcast<f32>(_e5294) * _e5297) * _e5300);
                                let _e5303 = select(_e5301, 0f, (_e5301 < 0f));
                                phi_4558_ = select(_e5303, 1f, (_e5303 > 1f));
                            }
                            let _e5307 = phi_4558_;
                            let _e5308 = local_626;
                            local_627 = _e5308;
                            phi_6017_ = _e5283;
                            phi_4608_ = _e5307;
                            phi_4609_ = _e829;
                        } else {
                            let _e777 = global_3.member.member_2;
                            if ((_e777 & 255u) == 1u) {
                                phi_4597_ = true;
                            } else {
                                let _e780 = local_13;
                                let _e781 = local_8;
                                if (_e780 < _e781) {
                                } else {
                                    phi_6024_ = true;
                                    break;
                                }
                                let _e783 = local_13;
                                let _e786 = global_11.member[_e783];
                                let _e790 = ((bitcast<u32>(bitcast<f32>(_e786)) & 2139095040u) != 2139095040u);
                                if _e790 {
                                } else {
                                    local_627 = array<f32, 3>(0f, 0f, 0f);
                                }
                                phi_4597_ = _e790;
                            }
                            let _e792 = phi_4597_;
                            local_482 = _e792;
                            if _e792 {
                                let _e796 = global_3.member.member.member_6;
                                local_627 = array<f32, 3>(_e796[0], _e796[1], _e796[2]);
                            }
                            let _e801 = local_482;
                            phi_6017_ = _e748;
                            phi_4608_ = select(0f, 1f, _e801);
                            phi_4609_ = _e715;
                        }
                        let _e5310 = phi_6017_;
                        let _e5312 = phi_4608_;
                        let _e5314 = phi_4609_;
                        local_483 = _e5312;
                        local_484 = _e5314;
                        let _e5317 = global_3.member.member_2;
                        if ((_e5317 & 255u) == 1u) {
                            phi_4618_ = 0u;
                            loop {
                                let _e5464 = phi_4618_;
                                local_485 = _e5464;
                                let _e5465 = local_485;
                                let _e5466 = (_e5465 < 3u);
                                local_486 = _e5466;
                                if _e5466 {
                                    let _e5467 = local_13;
                                    let _e5469 = local_485;
                                    let _e5470 = ((3u * _e5467) + _e5469);
                                    local_487 = _e5470;
                                    let _e5471 = local_7;
                                    let _e5472 = (_e5470 < _e5471);
                                    local_488 = _e5472;
                                    if _e5472 {
                                    } else {
                                        phi_6014_ = true;
                                        break;
                                    }
                                    let _e5473 = local_487;
                                    let _e5476 = global_10.member[_e5473];
                                    local_489 = bitcast<f32>(_e5476);
                                    let _e5478 = local_486;
                                    if _e5478 {
                                    } else {
                                        phi_6014_ = true;
                                        break;
                                    }
                                    let _e5479 = local_485;
                                    let _e5481 = local_627[_e5479];
                                    let _e5482 = local_483;
                                    let _e5484 = local_489;
                                    local_490 = bitcast<u32>((_e5484 + (_e5482 * _e5481)));
                                    let _e5487 = local_488;
                                    if _e5487 {
                                    } else {
                                        phi_6014_ = true;
                                        break;
                                    }
                                    let _e5488 = local_490;
                                    global_10.member[_e5473] = _e5488;
                                    let _e5489 = local_485;
                                    phi_4619_ = (_e5489 + 1u);
                                } else {
                                    phi_4619_ = u32();
                                }
                                let _e5492 = phi_4619_;
                                continue;
                                continuing {
                                    let _e5493 = local_486;
                                    phi_4618_ = _e5492;
                                    phi_6014_ = _e5310;
                                    break if !(_e5493);
                                }
                            }
                            let _e5496 = phi_6014_;
                            phi_6024_ = _e5496;
                            if _e5496 {
                                break;
                            }
                            phi_6027_ = _e5496;
                        } else {
                            let _e5320 = local_13;
                            let _e5321 = (_e5320 * 5u);
                            local_491 = _e5321;
                            let _e5323 = local_627[0u];
                            local_492 = bitcast<u32>(_e5323);
                            let _e5325 = local_7;
                            if (_e5321 < _e5325) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e5327 = local_491;
                            let _e5330 = local_492;
                            global_10.member[_e5327] = _e5330;
                            let _e5331 = local_491;
                            let _e5332 = (_e5331 + 1u);
                            local_493 = _e5332;
                            let _e5334 = local_627[1u];
                            local_494 = bitcast<u32>(_e5334);
                            let _e5336 = local_7;
                            if (_e5332 < _e5336) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e5338 = local_493;
                            let _e5341 = local_494;
                            global_10.member[_e5338] = _e5341;
                            let _e5342 = local_491;
                            let _e5343 = (_e5342 + 2u);
                            local_495 = _e5343;
                            let _e5345 = local_627[2u];
                            local_496 = bitcast<u32>(_e5345);
                            let _e5347 = local_7;
                            if (_e5343 < _e5347) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e5349 = local_495;
                            let _e5352 = local_496;
                            global_10.member[_e5349] = _e5352;
                            let _e5353 = local_491;
                            let _e5354 = (_e5353 + 3u);
                            local_497 = _e5354;
                            let _e5355 = local_483;
                            local_498 = bitcast<u32>(_e5355);
                            let _e5357 = local_7;
                            if (_e5354 < _e5357) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e5359 = local_497;
                            let _e5362 = local_498;
                            global_10.member[_e5359] = _e5362;
                            let _e5363 = local_491;
                            let _e5364 = (_e5363 + 4u);
                            local_499 = _e5364;
                            let _e5365 = local_484;
                            local_500 = bitcast<u32>(_e5365);
                            let _e5367 = local_7;
                            if (_e5364 < _e5367) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e5369 = local_499;
                            let _e5372 = local_500;
                            global_10.member[_e5369] = _e5372;
                            let _e5375 = global_3.member.member_4;
                            local_501 = _e5375;
                            let _e5376 = local_16;
                            if _e5376 {
                                let _e5377 = local_483;
                                if (_e5377 < 1f) {
                                    phi_4832_ = _e5314;
                                } else {
                                    let _e5379 = local_484;
                                    let _e5380 = local_501;
                                    local_502 = (_e5379 * _e5380);
                                    let _e5382 = local_500;
                                    if (_e5382 == 0u) {
                                        phi_4773_ = false;
                                    } else {
                                        let _e5384 = local_500;
                                        phi_4773_ = (_e5384 <= 2139095040u);
                                    }
                                    let _e5387 = phi_4773_;
                                    if _e5387 {
                                        let _e5388 = local_502;
                                        if (_e5388 >= 0f) {
                                            let _e5390 = local_502;
                                            let _e5393 = ((bitcast<u32>(_e5390) & 2147483647u) > 2139095040u);
                                            if _e5393 {
                                                phi_4804_ = f32();
                                                phi_4805_ = f32();
                                                phi_4806_ = false;
                                            } else {
                                                let _e5394 = local_502;
                                                let _e5395 = (_e5394 == 0f);
                                                local_503 = _e5395;
                                                if _e5395 {
                                                    phi_4802_ = f32();
                                                    phi_4803_ = true;
                                                } else {
                                                    let _e5399 = global_3.member.member_3.member_1;
                                                    local_504 = _e5399;
                                                    let _e5400 = local_502;
                                                    let _e5401 = (_e5400 >= _e5399);
                                                    if _e5401 {
                                                        phi_4800_ = f32();
                                                    } else {
                                                        let _e5402 = local_502;
                                                        let _e5403 = local_484;
                                                        let _e5405 = local_504;
                                                        let _e5406 = local_502;
                                                        phi_4800_ = ((_e5402 * _e5403) / (_e5405 - _e5406));
                                                    }
                                                    let _e5410 = phi_4800_;
                                                    phi_4802_ = _e5410;
                                                    phi_4803_ = _e5401;
                                                }
                                                let _e5412 = phi_4802_;
                                                let _e5414 = phi_4803_;
                                                let _e5415 = local_503;
                                                let _e5416 = local_613;
                                                phi_4804_ = select(_e5416, 0f, _e5415);
                                                phi_4805_ = _e5412;
                                                phi_4806_ = _e5414;
                                            }
                                            let _e5419 = phi_4804_;
                                            let _e5421 = phi_4805_;
                                            let _e5423 = phi_4806_;
                                            phi_4807_ = _e5419;
                                            phi_4808_ = _e5421;
                                            phi_4809_ = _e5393;
                                            phi_4810_ = _e5423;
                                        } else {
                                            phi_4807_ = f32();
                                            phi_4808_ = f32();
                                            phi_4809_ = true;
                                            phi_4810_ = false;
                                        }
                                        let _e5425 = phi_4807_;
                                        let _e5427 = phi_4808_;
                                        let _e5429 = phi_4809_;
                                        let _e5431 = phi_4810_;
                                        phi_4811_ = _e5425;
                                        phi_4812_ = _e5427;
                                        phi_4813_ = _e5429;
                                        phi_4814_ = _e5431;
                                    } else {
                                        phi_4811_ = f32();
                                        phi_4812_ = f32();
                                        phi_4813_ = true;
                                        phi_4814_ = false;
                                    }
                                    let _e5433 = phi_4811_;
                                    let _e5435 = phi_4812_;
                                    let _e5437 = phi_4813_;
                                    let _e5439 = phi_4814_;
                                    let _e5440 = local_612;
                                    let _e5444 = local_484;
                                    let _e5445 = (_e5444 + select(_e5435, select(_e5433, _e5440, _e5437), select(_e5439, true, _e5437)));
                                    let _e5449 = local_613;
                                    phi_4832_ = select(_e5449, _e5445, ((bitcast<u32>(_e5445) & 2139095040u) != 2139095040u));
                                }
                                let _e5452 = phi_4832_;
                                phi_4833_ = _e5452;
                            } else {
                                phi_4833_ = _e715;
                            }
                            let _e5454 = phi_4833_;
                            local_505 = bitcast<u32>(_e5454);
                            let _e5456 = local_13;
                            let _e5457 = local_8;
                            if (_e5456 < _e5457) {
                            } else {
                                phi_6024_ = true;
                                break;
                            }
                            let _e5459 = local_13;
                            let _e5462 = local_505;
                            global_11.member[_e5459] = _e5462;
                            phi_6027_ = _e5310;
                        }
                        let _e5498 = phi_6027_;
                        phi_6026_ = _e5498;
                    } else {
                        phi_6026_ = _e748;
                    }
                    let _e5500 = phi_6026_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e5501 = local_11;
                    let _e5502 = local_10;
                    phi_6025_ = _e5500;
                    phi_280_ = (_e5501 + _e5502);
                } else {
                    phi_6025_ = _e748;
                    phi_280_ = u32();
                }
                let _e5505 = phi_6025_;
                let _e5507 = phi_280_;
                continue;
                continuing {
                    let _e5508 = local_12;
                    phi_5740_ = _e5505;
                    phi_279_ = _e5507;
                    phi_6024_ = _e5505;
                    break if !(_e5508);
                }
            }
            let _e5511 = phi_6024_;
            if _e5511 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn raster_shade(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
