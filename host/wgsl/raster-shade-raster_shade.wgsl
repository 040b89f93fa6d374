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

struct type_27 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: array<f32, 3>,
    member_3: f32,
    member_4: array<f32, 3>,
    member_5: f32,
    member_6: array<f32, 3>,
    member_7: f32,
}

struct type_28 {
    member: type_27,
    member_1: array<f32, 3>,
    member_2: u32,
    member_3: type_5,
    member_4: f32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: array<f32, 4>,
}

struct type_29 {
    member: type_28,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_29;
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
    var local_34: array<u32, 4>;
    var local_35: f32;
    var local_36: u32;
    var local_37: f32;
    var local_38: u32;
    var local_39: f32;
    var local_40: u32;
    var local_41: f32;
    var local_42: u32;
    var local_43: f32;
    var local_44: u32;
    var local_45: f32;
    var local_46: u32;
    var local_47: f32;
    var local_48: u32;
    var local_49: f32;
    var local_50: u32;
    var local_51: f32;
    var local_52: u32;
    var local_53: u32;
    var local_54: bool;
    var local_55: u32;
    var local_56: u32;
    var local_57: bool;
    var local_58: f32;
    var local_59: f32;
    var local_60: f32;
    var local_61: u32;
    var local_62: f32;
    var local_63: f32;
    var local_64: f32;
    var local_65: f32;
    var local_66: f32;
    var local_67: f32;
    var local_68: f32;
    var local_69: array<f32, 3>;
    var local_70: f32;
    var local_71: f32;
    var local_72: f32;
    var local_73: array<f32, 3>;
    var local_74: u32;
    var local_75: f32;
    var local_76: f32;
    var local_77: bool;
    var local_78: u32;
    var local_79: f32;
    var local_80: u32;
    var local_81: f32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: f32;
    var local_91: u32;
    var local_92: f32;
    var local_93: u32;
    var local_94: u32;
    var local_95: f32;
    var local_96: u32;
    var local_97: f32;
    var local_98: u32;
    var local_99: u32;
    var local_100: f32;
    var local_101: u32;
    var local_102: f32;
    var local_103: type_5;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: u32;
    var local_112: f32;
    var local_113: f32;
    var local_114: f32;
    var local_115: f32;
    var local_116: f32;
    var local_117: f32;
    var local_118: f32;
    var local_119: bool;
    var local_120: u32;
    var local_121: bool;
    var local_122: f32;
    var local_123: u32;
    var local_124: f32;
    var local_125: f32;
    var local_126: u32;
    var local_127: f32;
    var local_128: u32;
    var local_129: u32;
    var local_130: f32;
    var local_131: f32;
    var local_132: u32;
    var local_133: u32;
    var local_134: bool;
    var local_135: f32;
    var local_136: u32;
    var local_137: bool;
    var local_138: u32;
    var local_139: type_5;
    var local_140: bool;
    var local_141: f32;
    var local_142: u32;
    var local_143: bool;
    var local_144: f32;
    var local_145: f32;
    var local_146: u32;
    var local_147: type_5;
    var local_148: bool;
    var local_149: type_22;
    var local_150: f32;
    var local_151: u32;
    var local_152: f32;
    var local_153: u32;
    var local_154: f32;
    var local_155: f32;
    var local_156: f32;
    var local_157: f32;
    var local_158: f32;
    var local_159: i32;
    var local_160: i32;
    var local_161: u32;
    var local_162: i32;
    var local_163: bool;
    var local_164: i32;
    var local_165: bool;
    var local_166: bool;
    var local_167: i32;
    var local_168: i32;
    var local_169: bool;
    var local_170: bool;
    var local_171: i32;
    var local_172: u32;
    var local_173: i32;
    var local_174: i32;
    var local_175: bool;
    var local_176: bool;
    var local_177: i32;
    var local_178: i32;
    var local_179: bool;
    var local_180: bool;
    var local_181: i32;
    var local_182: u32;
    var local_183: u32;
    var local_184: i32;
    var local_185: bool;
    var local_186: i32;
    var local_187: bool;
    var local_188: bool;
    var local_189: i32;
    var local_190: i32;
    var local_191: bool;
    var local_192: bool;
    var local_193: i32;
    var local_194: u32;
    var local_195: i32;
    var local_196: i32;
    var local_197: bool;
    var local_198: bool;
    var local_199: i32;
    var local_200: i32;
    var local_201: bool;
    var local_202: bool;
    var local_203: i32;
    var local_204: u32;
    var local_205: u32;
    var local_206: u32;
    var local_207: u32;
    var local_208: u32;
    var local_209: u32;
    var local_210: u32;
    var local_211: u32;
    var local_212: u32;
    var local_213: f32;
    var local_214: u32;
    var local_215: u32;
    var local_216: f32;
    var local_217: u32;
    var local_218: u32;
    var local_219: f32;
    var local_220: u32;
    var local_221: u32;
    var local_222: f32;
    var local_223: u32;
    var local_224: u32;
    var local_225: u32;
    var local_226: u32;
    var local_227: u32;
    var local_228: u32;
    var local_229: f32;
    var local_230: u32;
    var local_231: u32;
    var local_232: f32;
    var local_233: u32;
    var local_234: u32;
    var local_235: f32;
    var local_236: u32;
    var local_237: u32;
    var local_238: f32;
    var local_239: f32;
    var local_240: f32;
    var local_241: f32;
    var local_242: u32;
    var local_243: u32;
    var local_244: u32;
    var local_245: u32;
    var local_246: u32;
    var local_247: u32;
    var local_248: u32;
    var local_249: f32;
    var local_250: u32;
    var local_251: u32;
    var local_252: f32;
    var local_253: u32;
    var local_254: u32;
    var local_255: f32;
    var local_256: u32;
    var local_257: u32;
    var local_258: f32;
    var local_259: u32;
    var local_260: u32;
    var local_261: u32;
    var local_262: u32;
    var local_263: u32;
    var local_264: u32;
    var local_265: f32;
    var local_266: u32;
    var local_267: u32;
    var local_268: f32;
    var local_269: u32;
    var local_270: u32;
    var local_271: f32;
    var local_272: u32;
    var local_273: u32;
    var local_274: u32;
    var local_275: u32;
    var local_276: u32;
    var local_277: u32;
    var local_278: u32;
    var local_279: u32;
    var local_280: u32;
    var local_281: u32;
    var local_282: f32;
    var local_283: f32;
    var local_284: f32;
    var local_285: f32;
    var local_286: f32;
    var local_287: f32;
    var local_288: f32;
    var local_289: bool;
    var local_290: u32;
    var local_291: bool;
    var local_292: f32;
    var local_293: u32;
    var local_294: f32;
    var local_295: f32;
    var local_296: u32;
    var local_297: f32;
    var local_298: u32;
    var local_299: u32;
    var local_300: f32;
    var local_301: f32;
    var local_302: u32;
    var local_303: u32;
    var local_304: bool;
    var local_305: f32;
    var local_306: u32;
    var local_307: bool;
    var local_308: u32;
    var local_309: type_5;
    var local_310: bool;
    var local_311: f32;
    var local_312: u32;
    var local_313: bool;
    var local_314: f32;
    var local_315: f32;
    var local_316: u32;
    var local_317: type_5;
    var local_318: bool;
    var local_319: type_22;
    var local_320: f32;
    var local_321: u32;
    var local_322: f32;
    var local_323: u32;
    var local_324: f32;
    var local_325: f32;
    var local_326: f32;
    var local_327: f32;
    var local_328: f32;
    var local_329: i32;
    var local_330: i32;
    var local_331: u32;
    var local_332: i32;
    var local_333: bool;
    var local_334: i32;
    var local_335: bool;
    var local_336: bool;
    var local_337: i32;
    var local_338: i32;
    var local_339: bool;
    var local_340: bool;
    var local_341: i32;
    var local_342: u32;
    var local_343: i32;
    var local_344: i32;
    var local_345: bool;
    var local_346: bool;
    var local_347: i32;
    var local_348: i32;
    var local_349: bool;
    var local_350: bool;
    var local_351: i32;
    var local_352: u32;
    var local_353: u32;
    var local_354: i32;
    var local_355: bool;
    var local_356: i32;
    var local_357: bool;
    var local_358: bool;
    var local_359: i32;
    var local_360: i32;
    var local_361: bool;
    var local_362: bool;
    var local_363: i32;
    var local_364: u32;
    var local_365: i32;
    var local_366: i32;
    var local_367: bool;
    var local_368: bool;
    var local_369: i32;
    var local_370: i32;
    var local_371: bool;
    var local_372: bool;
    var local_373: i32;
    var local_374: u32;
    var local_375: u32;
    var local_376: u32;
    var local_377: u32;
    var local_378: u32;
    var local_379: u32;
    var local_380: u32;
    var local_381: u32;
    var local_382: u32;
    var local_383: f32;
    var local_384: u32;
    var local_385: u32;
    var local_386: f32;
    var local_387: u32;
    var local_388: u32;
    var local_389: f32;
    var local_390: u32;
    var local_391: u32;
    var local_392: f32;
    var local_393: u32;
    var local_394: u32;
    var local_395: u32;
    var local_396: u32;
    var local_397: u32;
    var local_398: u32;
    var local_399: f32;
    var local_400: u32;
    var local_401: u32;
    var local_402: f32;
    var local_403: u32;
    var local_404: u32;
    var local_405: f32;
    var local_406: u32;
    var local_407: u32;
    var local_408: f32;
    var local_409: f32;
    var local_410: f32;
    var local_411: f32;
    var local_412: u32;
    var local_413: u32;
    var local_414: u32;
    var local_415: u32;
    var local_416: u32;
    var local_417: u32;
    var local_418: u32;
    var local_419: f32;
    var local_420: u32;
    var local_421: u32;
    var local_422: f32;
    var local_423: u32;
    var local_424: u32;
    var local_425: f32;
    var local_426: u32;
    var local_427: u32;
    var local_428: f32;
    var local_429: u32;
    var local_430: u32;
    var local_431: u32;
    var local_432: u32;
    var local_433: u32;
    var local_434: u32;
    var local_435: f32;
    var local_436: u32;
    var local_437: u32;
    var local_438: f32;
    var local_439: u32;
    var local_440: u32;
    var local_441: f32;
    var local_442: u32;
    var local_443: u32;
    var local_444: u32;
    var local_445: array<f32, 4>;
    var local_446: bool;
    var local_447: u32;
    var local_448: u32;
    var local_449: u32;
    var local_450: u32;
    var local_451: u32;
    var local_452: f32;
    var local_453: u32;
    var local_454: u32;
    var local_455: f32;
    var local_456: f32;
    var local_457: u32;
    var local_458: u32;
    var local_459: f32;
    var local_460: f32;
    var local_461: u32;
    var local_462: u32;
    var local_463: f32;
    var local_464: f32;
    var local_465: u32;
    var local_466: u32;
    var local_467: u32;
    var local_468: u32;
    var local_469: f32;
    var local_470: u32;
    var local_471: bool;
    var local_472: u32;
    var local_473: f32;
    var local_474: bool;
    var local_475: f32;
    var local_476: f32;
    var local_477: f32;
    var local_478: f32;
    var local_479: u32;
    var local_480: f32;
    var local_481: f32;
    var local_482: u32;
    var local_483: bool;
    var local_484: f32;
    var local_485: f32;
    var local_486: u32;
    var local_487: bool;
    var local_488: u32;
    var local_489: bool;
    var local_490: f32;
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
    var local_501: u32;
    var local_502: f32;
    var local_503: f32;
    var local_504: bool;
    var local_505: f32;
    var local_506: u32;
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
    var local_524: f32;
    var local_525: bool;
    var local_526: f32;
    var local_527: f32;
    var local_528: f32;
    var local_529: bool;
    var local_530: f32;
    var local_531: f32;
    var local_532: f32;
    var local_533: f32;
    var local_534: f32;
    var local_535: f32;
    var local_536: u32;
    var local_537: type_22;
    var local_538: bool;
    var local_539: u32;
    var local_540: u32;
    var local_541: type_22;
    var local_542: type_22;
    var local_543: u32;
    var local_544: type_22;
    var local_545: bool;
    var local_546: u32;
    var local_547: u32;
    var local_548: type_22;
    var local_549: type_22;
    var local_550: u32;
    var local_551: type_22;
    var local_552: bool;
    var local_553: u32;
    var local_554: u32;
    var local_555: type_22;
    var local_556: type_22;
    var local_557: u32;
    var local_558: type_22;
    var local_559: bool;
    var local_560: u32;
    var local_561: u32;
    var local_562: type_22;
    var local_563: type_22;
    var local_564: u32;
    var local_565: u32;
    var local_566: f32;
    var local_567: f32;
    var local_568: f32;
    var local_569: u32;
    var local_570: u32;
    var local_571: u32;
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
    var local_585: f32;
    var local_586: f32;
    var local_587: f32;
    var local_588: u32;
    var local_589: f32;
    var local_590: f32;
    var local_591: f32;
    var local_592: u32;
    var local_593: u32;
    var local_594: u32;
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
    var local_614: f32;
    var local_615: f32;
    var local_616: f32;
    var local_617: f32;
    var local_618: array<u32, 4>;
    var local_619: array<f32, 3>;
    var local_620: array<u32, 4>;
    var local_621: array<f32, 3>;
    var local_622: array<u32, 4>;
    var local_623: array<f32, 3>;
    var local_624: array<array<f32, 3>, 3>;
    var local_625: array<f32, 3>;
    var local_626: array<f32, 3>;
    var local_627: array<f32, 4>;
    var local_628: array<f32, 4>;
    var local_629: array<f32, 4>;
    var local_630: array<f32, 3>;
    var local_631: array<f32, 3>;
    var phi_5773_: bool;
    var phi_274_: u32;
    var phi_4630_: bool;
    var phi_390_: bool;
    var phi_5770_: bool;
    var phi_650_: u32;
    var phi_668_: u32;
    var phi_669_: u32;
    var phi_5767_: bool;
    var phi_5775_: bool;
    var phi_651_: u32;
    var phi_5774_: bool;
    var phi_5263_: array<f32, 3>;
    var phi_5237_: array<f32, 3>;
    var phi_830_: array<f32, 3>;
    var phi_861_: array<f32, 3>;
    var phi_879_: u32;
    var phi_882_: f32;
    var phi_884_: f32;
    var phi_880_: u32;
    var phi_883_: f32;
    var phi_885_: f32;
    var phi_5776_: bool;
    var phi_996_: bool;
    var phi_5356_: f32;
    var phi_5365_: f32;
    var phi_5367_: f32;
    var phi_5473_: type_5;
    var phi_5477_: type_5;
    var phi_5478_: bool;
    var phi_5482_: type_5;
    var phi_1146_: type_5;
    var phi_1256_: bool;
    var phi_1295_: bool;
    var phi_1302_: u32;
    var phi_1303_: u32;
    var phi_1320_: bool;
    var phi_1393_: u32;
    var phi_1417_: u32;
    var phi_1350_: u32;
    var phi_1374_: u32;
    var phi_1418_: u32;
    var phi_1419_: u32;
    var phi_1420_: u32;
    var phi_1421_: u32;
    var phi_1434_: f32;
    var phi_1455_: f32;
    var phi_1471_: f32;
    var phi_5583_: u32;
    var phi_5584_: type_22;
    var phi_5601_: u32;
    var phi_5610_: u32;
    var phi_5615_: u32;
    var phi_5616_: type_22;
    var phi_5622_: u32;
    var phi_5623_: type_22;
    var phi_5640_: u32;
    var phi_5649_: u32;
    var phi_5654_: u32;
    var phi_5655_: type_22;
    var phi_1487_: bool;
    var phi_5830_: bool;
    var phi_1490_: u32;
    var phi_1493_: type_5;
    var phi_5829_: bool;
    var phi_1507_: u32;
    var phi_1510_: type_5;
    var phi_1536_: u32;
    var phi_1539_: type_5;
    var phi_1552_: type_22;
    var phi_1553_: f32;
    var phi_1573_: f32;
    var phi_1574_: f32;
    var phi_1645_: i32;
    var phi_1669_: i32;
    var phi_1609_: i32;
    var phi_1610_: i32;
    var phi_1670_: i32;
    var phi_1725_: i32;
    var phi_1749_: i32;
    var phi_1689_: i32;
    var phi_1690_: i32;
    var phi_1750_: i32;
    var phi_1804_: i32;
    var phi_1828_: i32;
    var phi_1768_: i32;
    var phi_1769_: i32;
    var phi_1829_: i32;
    var phi_1884_: i32;
    var phi_1908_: i32;
    var phi_1848_: i32;
    var phi_1849_: i32;
    var phi_1909_: i32;
    var phi_1976_: u32;
    var phi_1979_: f32;
    var phi_2008_: u32;
    var phi_2011_: f32;
    var phi_2040_: u32;
    var phi_2043_: f32;
    var phi_2072_: u32;
    var phi_2075_: f32;
    var phi_2141_: u32;
    var phi_2144_: f32;
    var phi_2173_: u32;
    var phi_2176_: f32;
    var phi_2205_: u32;
    var phi_2208_: f32;
    var phi_2237_: u32;
    var phi_2240_: f32;
    var phi_2318_: u32;
    var phi_2321_: f32;
    var phi_2350_: u32;
    var phi_2353_: f32;
    var phi_2382_: u32;
    var phi_2385_: f32;
    var phi_2414_: u32;
    var phi_2417_: f32;
    var phi_2483_: u32;
    var phi_2486_: f32;
    var phi_2515_: u32;
    var phi_2518_: f32;
    var phi_2547_: u32;
    var phi_2550_: f32;
    var phi_2579_: u32;
    var phi_2582_: f32;
    var phi_1537_: u32;
    var phi_1540_: type_5;
    var phi_5783_: bool;
    var phi_5902_: bool;
    var phi_1508_: u32;
    var phi_1511_: type_5;
    var phi_5901_: bool;
    var phi_5904_: bool;
    var phi_1491_: u32;
    var phi_1494_: type_5;
    var phi_5903_: bool;
    var phi_5982_: bool;
    var phi_2635_: type_5;
    var phi_5981_: bool;
    var phi_2636_: type_5;
    var phi_2637_: bool;
    var phi_2641_: type_5;
    var phi_5979_: bool;
    var phi_2642_: type_5;
    var phi_5978_: bool;
    var phi_2643_: type_5;
    var phi_2644_: bool;
    var phi_2648_: type_5;
    var phi_2768_: bool;
    var phi_2807_: bool;
    var phi_2814_: u32;
    var phi_2815_: u32;
    var phi_2832_: bool;
    var phi_2905_: u32;
    var phi_2929_: u32;
    var phi_2862_: u32;
    var phi_2886_: u32;
    var phi_2930_: u32;
    var phi_2931_: u32;
    var phi_2932_: u32;
    var phi_2933_: u32;
    var phi_2946_: f32;
    var phi_2967_: f32;
    var phi_2983_: f32;
    var phi_5661_: u32;
    var phi_5662_: type_22;
    var phi_5679_: u32;
    var phi_5688_: u32;
    var phi_5693_: u32;
    var phi_5694_: type_22;
    var phi_5700_: u32;
    var phi_5701_: type_22;
    var phi_5718_: u32;
    var phi_5727_: u32;
    var phi_5732_: u32;
    var phi_5733_: type_22;
    var phi_2999_: bool;
    var phi_5952_: bool;
    var phi_3002_: u32;
    var phi_3005_: type_5;
    var phi_5951_: bool;
    var phi_3019_: u32;
    var phi_3022_: type_5;
    var phi_3048_: u32;
    var phi_3051_: type_5;
    var phi_3064_: type_22;
    var phi_3065_: f32;
    var phi_3085_: f32;
    var phi_3086_: f32;
    var phi_3157_: i32;
    var phi_3181_: i32;
    var phi_3121_: i32;
    var phi_3122_: i32;
    var phi_3182_: i32;
    var phi_3237_: i32;
    var phi_3261_: i32;
    var phi_3201_: i32;
    var phi_3202_: i32;
    var phi_3262_: i32;
    var phi_3316_: i32;
    var phi_3340_: i32;
    var phi_3280_: i32;
    var phi_3281_: i32;
    var phi_3341_: i32;
    var phi_3396_: i32;
    var phi_3420_: i32;
    var phi_3360_: i32;
    var phi_3361_: i32;
    var phi_3421_: i32;
    var phi_3488_: u32;
    var phi_3491_: f32;
    var phi_3520_: u32;
    var phi_3523_: f32;
    var phi_3552_: u32;
    var phi_3555_: f32;
    var phi_3584_: u32;
    var phi_3587_: f32;
    var phi_3653_: u32;
    var phi_3656_: f32;
    var phi_3685_: u32;
    var phi_3688_: f32;
    var phi_3717_: u32;
    var phi_3720_: f32;
    var phi_3749_: u32;
    var phi_3752_: f32;
    var phi_3830_: u32;
    var phi_3833_: f32;
    var phi_3862_: u32;
    var phi_3865_: f32;
    var phi_3894_: u32;
    var phi_3897_: f32;
    var phi_3926_: u32;
    var phi_3929_: f32;
    var phi_3995_: u32;
    var phi_3998_: f32;
    var phi_4027_: u32;
    var phi_4030_: f32;
    var phi_4059_: u32;
    var phi_4062_: f32;
    var phi_4091_: u32;
    var phi_4094_: f32;
    var phi_3049_: u32;
    var phi_3052_: type_5;
    var phi_5905_: bool;
    var phi_6022_: bool;
    var phi_3020_: u32;
    var phi_3023_: type_5;
    var phi_6021_: bool;
    var phi_6024_: bool;
    var phi_3003_: u32;
    var phi_3006_: type_5;
    var phi_6023_: bool;
    var phi_6041_: bool;
    var phi_4147_: type_5;
    var phi_6040_: bool;
    var phi_4148_: type_5;
    var phi_4149_: bool;
    var phi_4153_: type_5;
    var phi_6038_: bool;
    var phi_4154_: type_5;
    var phi_6037_: bool;
    var phi_4155_: type_5;
    var phi_4156_: bool;
    var phi_4160_: type_5;
    var phi_4188_: u32;
    var phi_4191_: array<f32, 4>;
    var phi_4274_: u32;
    var phi_4277_: f32;
    var phi_4317_: u32;
    var phi_4320_: f32;
    var phi_4360_: u32;
    var phi_4363_: f32;
    var phi_4403_: u32;
    var phi_4406_: f32;
    var phi_4189_: u32;
    var phi_4192_: array<f32, 4>;
    var phi_6025_: bool;
    var phi_5746_: bool;
    var phi_4448_: u32;
    var phi_4514_: f32;
    var phi_4449_: u32;
    var phi_6046_: bool;
    var phi_4591_: f32;
    var phi_6055_: bool;
    var phi_4641_: f32;
    var phi_4642_: f32;
    var phi_4806_: bool;
    var phi_4833_: f32;
    var phi_4835_: f32;
    var phi_4836_: bool;
    var phi_4837_: f32;
    var phi_4838_: f32;
    var phi_4839_: bool;
    var phi_4840_: f32;
    var phi_4841_: f32;
    var phi_4842_: bool;
    var phi_4843_: bool;
    var phi_4844_: f32;
    var phi_4845_: f32;
    var phi_4846_: bool;
    var phi_4847_: bool;
    var phi_4865_: f32;
    var phi_4866_: f32;
    var phi_4651_: u32;
    var phi_4652_: u32;
    var phi_6052_: bool;
    var phi_6065_: bool;
    var phi_6064_: bool;
    var phi_6063_: bool;
    var phi_275_: u32;
    var phi_6062_: bool;
    var local_632: type_22;
    var local_633: type_22;
    var local_634: type_5;
    var local_635: type_5;
    var local_636: type_22;
    var local_637: type_22;
    var local_638: type_5;
    var local_639: type_5;

    let _e711 = global_12;
    local_616 = bitcast<f32>(_e711);
    let _e713 = global_13;
    let _e714 = bitcast<f32>(_e713);
    local_617 = _e714;
    switch bitcast<i32>(0u) {
        default: {
            let _e716 = global;
            local = _e716;
            let _e717 = global_1;
            let _e718 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_9.member));
            local_7 = arrayLength((&global_10.member));
            local_8 = arrayLength((&global_11.member));
            let _e739 = global_3.member.member_5;
            let _e742 = global_3.member.member_6;
            local_9 = (_e739 * _e742);
            local_10 = (_e718.x * 256u);
            phi_5773_ = false;
            phi_274_ = (_e717.x * 256u);
            loop {
                let _e747 = phi_5773_;
                let _e749 = phi_274_;
                local_11 = _e749;
                let _e750 = local_11;
                let _e751 = local_9;
                let _e752 = (_e750 < _e751);
                local_12 = _e752;
                if _e752 {
                    let _e753 = local_11;
                    let _e754 = local;
                    let _e755 = (_e753 + _e754);
                    local_13 = _e755;
                    let _e756 = local_9;
                    if (_e755 < _e756) {
                        let _e758 = local_13;
                        let _e759 = (_e758 * 4u);
                        local_14 = _e759;
                        let _e760 = local_1;
                        if (_e759 < _e760) {
                        } else {
                            phi_6062_ = true;
                            break;
                        }
                        let _e762 = local_14;
                        let _e765 = global_4.member[_e762];
                        let _e766 = bitcast<f32>(_e765);
                        let _e772 = select(select(u32(_e766), 0u, !((_e766 >= 0f))), 4294967295u, (_e766 > 4294967000f));
                        local_15 = _e772;
                        let _e773 = (_e772 > 0u);
                        local_16 = _e773;
                        if _e773 {
                            let _e802 = local_14;
                            let _e803 = (_e802 + 2u);
                            local_17 = _e803;
                            let _e804 = local_1;
                            if (_e803 < _e804) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e806 = local_17;
                            let _e809 = global_4.member[_e806];
                            local_18 = bitcast<f32>(_e809);
                            let _e811 = local_14;
                            let _e812 = (_e811 + 3u);
                            local_19 = _e812;
                            let _e813 = local_1;
                            if (_e812 < _e813) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e815 = local_19;
                            let _e818 = global_4.member[_e815];
                            local_20 = bitcast<f32>(_e818);
                            let _e820 = local_14;
                            let _e821 = (_e820 + 1u);
                            local_21 = _e821;
                            let _e822 = local_1;
                            if (_e821 < _e822) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e824 = local_21;
                            let _e827 = global_4.member[_e824];
                            let _e828 = bitcast<f32>(_e827);
                            let _e831 = global_3.member.member_4;
                            local_22 = ((2f * _e831) * _e828);
                            let _e836 = global_3.member.member_1;
                            local_23 = _e836;
                            let _e839 = global_3.member.member_8;
                            local_24 = _e839;
                            let _e842 = global_3.member.member_7;
                            local_25 = _e842;
                            let _e845 = global_3.member.member_2;
                            let _e848 = ((_e845 >> bitcast<u32>(8u)) & 255u);
                            local_26 = _e848;
                            if (_e848 == 0u) {
                                phi_390_ = true;
                            } else {
                                let _e850 = local_26;
                                phi_390_ = (_e850 > 64u);
                            }
                            let _e853 = phi_390_;
                            let _e854 = local_26;
                            local_564 = select(_e854, 64u, _e853);
                            let _e856 = local_15;
                            let _e858 = ((_e856 - 1u) * 4u);
                            local_27 = _e858;
                            let _e859 = local_3;
                            if (_e858 < _e859) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e861 = local_27;
                            let _e864 = global_6.member[_e861];
                            local_28 = _e864;
                            let _e865 = local_27;
                            let _e866 = (_e865 + 1u);
                            local_29 = _e866;
                            let _e867 = local_3;
                            if (_e866 < _e867) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e869 = local_29;
                            let _e872 = global_6.member[_e869];
                            local_30 = _e872;
                            let _e873 = local_27;
                            let _e874 = (_e873 + 2u);
                            local_31 = _e874;
                            let _e875 = local_3;
                            if (_e874 < _e875) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e877 = local_31;
                            let _e880 = global_6.member[_e877];
                            local_32 = _e880;
                            let _e881 = local_27;
                            let _e882 = (_e881 + 3u);
                            local_33 = _e882;
                            let _e883 = local_3;
                            if (_e882 < _e883) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e885 = local_33;
                            let _e888 = global_6.member[_e885];
                            let _e889 = local_28;
                            let _e890 = local_30;
                            let _e891 = local_32;
                            let _e892 = array<u32, 4>(_e889, _e890, _e891, _e888);
                            local_34 = _e892;
                            local_622 = _e892;
                            let _e893 = local_18;
                            let _e895 = local_20;
                            let _e896 = ((1f - _e893) - _e895);
                            local_35 = _e896;
                            let _e898 = local_18;
                            local_623[0u] = _e898;
                            let _e900 = local_20;
                            local_623[1u] = _e900;
                            local_623[2u] = _e896;
                            let _e903 = local_622[0u];
                            let _e904 = (_e903 * 10u);
                            local_36 = _e904;
                            let _e905 = local_2;
                            if (_e904 < _e905) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e907 = local_36;
                            let _e910 = global_5.member[_e907];
                            local_37 = bitcast<f32>(_e910);
                            let _e912 = local_36;
                            let _e913 = (_e912 + 1u);
                            local_38 = _e913;
                            let _e914 = local_2;
                            if (_e913 < _e914) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e916 = local_38;
                            let _e919 = global_5.member[_e916];
                            local_39 = bitcast<f32>(_e919);
                            let _e921 = local_36;
                            let _e922 = (_e921 + 2u);
                            local_40 = _e922;
                            let _e923 = local_2;
                            if (_e922 < _e923) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e925 = local_40;
                            let _e928 = global_5.member[_e925];
                            local_41 = bitcast<f32>(_e928);
                            let _e931 = local_622[1u];
                            let _e932 = (_e931 * 10u);
                            local_42 = _e932;
                            let _e933 = local_2;
                            if (_e932 < _e933) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e935 = local_42;
                            let _e938 = global_5.member[_e935];
                            local_43 = bitcast<f32>(_e938);
                            let _e940 = local_42;
                            let _e941 = (_e940 + 1u);
                            local_44 = _e941;
                            let _e942 = local_2;
                            if (_e941 < _e942) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e944 = local_44;
                            let _e947 = global_5.member[_e944];
                            local_45 = bitcast<f32>(_e947);
                            let _e949 = local_42;
                            let _e950 = (_e949 + 2u);
                            local_46 = _e950;
                            let _e951 = local_2;
                            if (_e950 < _e951) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e953 = local_46;
                            let _e956 = global_5.member[_e953];
                            local_47 = bitcast<f32>(_e956);
                            let _e959 = local_622[2u];
                            let _e960 = (_e959 * 10u);
                            local_48 = _e960;
                            let _e961 = local_2;
                            if (_e960 < _e961) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e963 = local_48;
                            let _e966 = global_5.member[_e963];
                            local_49 = bitcast<f32>(_e966);
                            let _e968 = local_48;
                            let _e969 = (_e968 + 1u);
                            local_50 = _e969;
                            let _e970 = local_2;
                            if (_e969 < _e970) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e972 = local_50;
                            let _e975 = global_5.member[_e972];
                            local_51 = bitcast<f32>(_e975);
                            let _e977 = local_48;
                            let _e978 = (_e977 + 2u);
                            local_52 = _e978;
                            let _e979 = local_2;
                            if (_e978 < _e979) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e981 = local_52;
                            let _e984 = global_5.member[_e981];
                            let _e987 = local_37;
                            let _e988 = local_39;
                            let _e989 = local_41;
                            local_624[0u] = array<f32, 3>(_e987, _e988, _e989);
                            let _e992 = local_43;
                            let _e993 = local_45;
                            let _e994 = local_47;
                            local_624[1u] = array<f32, 3>(_e992, _e993, _e994);
                            let _e997 = local_49;
                            let _e998 = local_51;
                            local_624[2u] = array<f32, 3>(_e997, _e998, bitcast<f32>(_e984));
                            local_625 = array<f32, 3>(0f, 0f, 0f);
                            local_626 = array<f32, 3>(0f, 0f, 0f);
                            phi_5770_ = _e747;
                            phi_650_ = 0u;
                            loop {
                                let _e1001 = phi_5770_;
                                let _e1003 = phi_650_;
                                local_53 = _e1003;
                                let _e1004 = local_53;
                                let _e1005 = (_e1004 < 3u);
                                local_54 = _e1005;
                                if _e1005 {
                                    let _e1006 = local_53;
                                    if (_e1006 < 4u) {
                                    } else {
                                        phi_5774_ = true;
                                        break;
                                    }
                                    let _e1008 = local_53;
                                    let _e1010 = local_622[_e1008];
                                    local_55 = (_e1010 * 10u);
                                    phi_668_ = 0u;
                                    loop {
                                        let _e1013 = phi_668_;
                                        local_56 = _e1013;
                                        let _e1014 = local_56;
                                        let _e1015 = (_e1014 < 3u);
                                        local_57 = _e1015;
                                        if _e1015 {
                                            let _e1016 = local_54;
                                            if _e1016 {
                                            } else {
                                                phi_5767_ = true;
                                                break;
                                            }
                                            let _e1017 = local_53;
                                            let _e1019 = local_623[_e1017];
                                            local_58 = _e1019;
                                            let _e1020 = local_54;
                                            if _e1020 {
                                            } else {
                                                phi_5767_ = true;
                                                break;
                                            }
                                            let _e1021 = local_57;
                                            if _e1021 {
                                            } else {
                                                phi_5767_ = true;
                                                break;
                                            }
                                            let _e1022 = local_53;
                                            let _e1023 = local_56;
                                            let _e1026 = local_624[_e1022][_e1023];
                                            let _e1027 = local_58;
                                            local_59 = (_e1027 * _e1026);
                                            let _e1029 = local_57;
                                            if _e1029 {
                                            } else {
                                                phi_5767_ = true;
                                                break;
                                            }
                                            let _e1030 = local_56;
                                            let _e1032 = local_625[_e1030];
                                            let _e1033 = local_59;
                                            local_625[_e1030] = (_e1032 + _e1033);
                                            let _e1035 = local_54;
                                            if _e1035 {
                                            } else {
                                                phi_5767_ = true;
                                                break;
                                            }
                                            let _e1036 = local_623[_e1017];
                                            local_60 = _e1036;
                                            let _e1037 = local_55;
                                            let _e1039 = local_56;
                                            let _e1040 = ((_e1037 + 4u) + _e1039);
                                            local_61 = _e1040;
                                            let _e1041 = local_2;
                                            if (_e1040 < _e1041) {
                                            } else {
                                                phi_5767_ = true;
                                                break;
                                            }
                                            let _e1043 = local_61;
                                            let _e1046 = global_5.member[_e1043];
                                            let _e1048 = local_60;
                                            local_62 = (_e1048 * bitcast<f32>(_e1046));
                                            let _e1050 = local_57;
                                            if _e1050 {
                                            } else {
                                                phi_5767_ = true;
                                                break;
                                            }
                                            let _e1051 = local_56;
                                            let _e1053 = local_626[_e1051];
                                            let _e1054 = local_62;
                                            local_626[_e1051] = (_e1053 + _e1054);
                                            let _e1056 = local_56;
                                            phi_669_ = (_e1056 + 1u);
                                        } else {
                                            phi_669_ = u32();
                                        }
                                        let _e1059 = phi_669_;
                                        continue;
                                        continuing {
                                            let _e1060 = local_57;
                                            phi_668_ = _e1059;
                                            phi_5767_ = _e1001;
                                            break if !(_e1060);
                                        }
                                    }
                                    let _e1063 = phi_5767_;
                                    phi_5774_ = _e1063;
                                    if _e1063 {
                                        break;
                                    }
                                    let _e1064 = local_53;
                                    phi_5775_ = _e1063;
                                    phi_651_ = (_e1064 + 1u);
                                } else {
                                    phi_5775_ = _e1001;
                                    phi_651_ = u32();
                                }
                                let _e1067 = phi_5775_;
                                let _e1069 = phi_651_;
                                continue;
                                continuing {
                                    let _e1070 = local_54;
                                    phi_5770_ = _e1067;
                                    phi_650_ = _e1069;
                                    phi_5774_ = _e1067;
                                    break if !(_e1070);
                                }
                            }
                            let _e1073 = phi_5774_;
                            phi_6062_ = _e1073;
                            if _e1073 {
                                break;
                            }
                            let _e1074 = local_624[1u];
                            let _e1078 = local_624[0u];
                            let _e1082 = (_e1074[0] - _e1078[0]);
                            let _e1083 = (_e1074[1] - _e1078[1]);
                            let _e1084 = (_e1074[2] - _e1078[2]);
                            let _e1085 = local_624[2u];
                            let _e1089 = local_624[0u];
                            let _e1093 = (_e1085[0] - _e1089[0]);
                            let _e1094 = (_e1085[1] - _e1089[1]);
                            let _e1095 = (_e1085[2] - _e1089[2]);
                            let _e1098 = ((_e1083 * _e1095) - (_e1084 * _e1094));
                            local_63 = _e1098;
                            let _e1101 = ((_e1084 * _e1093) - (_e1082 * _e1095));
                            local_64 = _e1101;
                            let _e1104 = ((_e1082 * _e1094) - (_e1083 * _e1093));
                            local_65 = _e1104;
                            let _e1106 = local_626;
                            if ((((_e1106[0] * _e1106[0]) + (_e1106[1] * _e1106[1])) + (_e1106[2] * _e1106[2])) > 0f) {
                                let _e1141 = local_626;
                                local_66 = _e1141[0];
                                local_67 = _e1141[1];
                                local_68 = _e1141[2];
                                let _e1151 = sqrt((((_e1141[0] * _e1141[0]) + (_e1141[1] * _e1141[1])) + (_e1141[2] * _e1141[2])));
                                local_507 = _e1151;
                                if (_e1151 > 0f) {
                                    let _e1153 = local_66;
                                    let _e1154 = local_507;
                                    let _e1156 = local_67;
                                    let _e1157 = local_507;
                                    let _e1159 = local_68;
                                    let _e1160 = local_507;
                                    phi_5237_ = array<f32, 3>((_e1153 / _e1154), (_e1156 / _e1157), (_e1159 / _e1160));
                                } else {
                                    phi_5237_ = array<f32, 3>(_e1141[0], _e1141[1], _e1141[2]);
                                }
                                let _e1164 = phi_5237_;
                                phi_830_ = _e1164;
                            } else {
                                let _e1116 = local_63;
                                let _e1117 = local_63;
                                let _e1119 = local_64;
                                let _e1120 = local_64;
                                let _e1123 = local_65;
                                let _e1124 = local_65;
                                let _e1127 = sqrt((((_e1116 * _e1117) + (_e1119 * _e1120)) + (_e1123 * _e1124)));
                                local_508 = _e1127;
                                if (_e1127 > 0f) {
                                    let _e1129 = local_63;
                                    let _e1130 = local_508;
                                    let _e1132 = local_64;
                                    let _e1133 = local_508;
                                    let _e1135 = local_65;
                                    let _e1136 = local_508;
                                    phi_5263_ = array<f32, 3>((_e1129 / _e1130), (_e1132 / _e1133), (_e1135 / _e1136));
                                } else {
                                    phi_5263_ = array<f32, 3>(_e1098, _e1101, _e1104);
                                }
                                let _e1140 = phi_5263_;
                                phi_830_ = _e1140;
                            }
                            let _e1166 = phi_830_;
                            local_69 = _e1166;
                            let _e1167 = local_625;
                            let _e1171 = local_23;
                            local_70 = _e1171[0];
                            let _e1174 = local_23;
                            local_71 = _e1174[1];
                            let _e1177 = local_23;
                            local_72 = _e1177[2];
                            let _e1180 = local_63;
                            let _e1182 = local_64;
                            let _e1185 = local_65;
                            if ((((_e1180 * (_e1167[0] - _e1171[0])) + (_e1182 * (_e1167[1] - _e1174[1]))) + (_e1185 * (_e1167[2] - _e1177[2]))) > 0f) {
                                let _e1189 = local_69;
                                let _e1192 = local_69;
                                let _e1195 = local_69;
                                phi_861_ = array<f32, 3>(-(_e1189[0]), -(_e1192[1]), -(_e1195[2]));
                            } else {
                                phi_861_ = _e1166;
                            }
                            let _e1200 = phi_861_;
                            local_73 = _e1200;
                            let _e1201 = local_34;
                            local_620 = _e1201;
                            let _e1203 = local_18;
                            local_621[0u] = _e1203;
                            let _e1205 = local_20;
                            local_621[1u] = _e1205;
                            let _e1207 = local_35;
                            local_621[2u] = _e1207;
                            phi_879_ = 0u;
                            phi_882_ = 0f;
                            phi_884_ = 0f;
                            loop {
                                let _e1209 = phi_879_;
                                let _e1211 = phi_882_;
                                let _e1213 = phi_884_;
                                local_74 = _e1209;
                                local_75 = _e1211;
                                local_76 = _e1213;
                                let _e1214 = local_74;
                                let _e1215 = (_e1214 < 3u);
                                local_77 = _e1215;
                                if _e1215 {
                                    let _e1216 = local_74;
                                    if (_e1216 < 4u) {
                                    } else {
                                        phi_5776_ = true;
                                        break;
                                    }
                                    let _e1218 = local_74;
                                    let _e1220 = local_620[_e1218];
                                    local_78 = (_e1220 * 10u);
                                    let _e1222 = local_77;
                                    if _e1222 {
                                    } else {
                                        phi_5776_ = true;
                                        break;
                                    }
                                    let _e1223 = local_74;
                                    let _e1225 = local_621[_e1223];
                                    local_79 = _e1225;
                                    let _e1226 = local_78;
                                    let _e1227 = (_e1226 + 3u);
                                    local_80 = _e1227;
                                    let _e1228 = local_2;
                                    if (_e1227 < _e1228) {
                                    } else {
                                        phi_5776_ = true;
                                        break;
                                    }
                                    let _e1230 = local_80;
                                    let _e1233 = global_5.member[_e1230];
                                    let _e1235 = local_79;
                                    let _e1237 = local_76;
                                    let _e1239 = local_77;
                                    if _e1239 {
                                    } else {
                                        phi_5776_ = true;
                                        break;
                                    }
                                    let _e1240 = local_621[_e1223];
                                    local_81 = _e1240;
                                    let _e1241 = local_78;
                                    let _e1242 = (_e1241 + 7u);
                                    local_82 = _e1242;
                                    let _e1243 = local_2;
                                    if (_e1242 < _e1243) {
                                    } else {
                                        phi_5776_ = true;
                                        break;
                                    }
                                    let _e1245 = local_82;
                                    let _e1248 = global_5.member[_e1245];
                                    let _e1250 = local_81;
                                    let _e1252 = local_75;
                                    let _e1254 = local_74;
                                    phi_880_ = (_e1254 + 1u);
                                    phi_883_ = (_e1252 + (_e1250 * bitcast<f32>(_e1248)));
                                    phi_885_ = (_e1237 + (_e1235 * bitcast<f32>(_e1233)));
                                } else {
                                    phi_880_ = u32();
                                    phi_883_ = f32();
                                    phi_885_ = f32();
                                }
                                let _e1257 = phi_880_;
                                let _e1259 = phi_883_;
                                let _e1261 = phi_885_;
                                continue;
                                continuing {
                                    let _e1262 = local_77;
                                    phi_879_ = _e1257;
                                    phi_882_ = _e1259;
                                    phi_884_ = _e1261;
                                    phi_5776_ = _e1073;
                                    break if !(_e1262);
                                }
                            }
                            let _e1265 = phi_5776_;
                            phi_6062_ = _e1265;
                            if _e1265 {
                                break;
                            }
                            let _e1267 = local_622[3u];
                            let _e1268 = (_e1267 * 16u);
                            local_83 = _e1268;
                            let _e1269 = (_e1268 + 8u);
                            local_84 = _e1269;
                            let _e1270 = local_4;
                            if (_e1269 < _e1270) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e1272 = local_84;
                            let _e1275 = global_7.member[_e1272];
                            local_85 = _e1275;
                            let _e1276 = local_83;
                            let _e1277 = (_e1276 + 9u);
                            local_86 = _e1277;
                            let _e1278 = local_4;
                            if (_e1277 < _e1278) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e1280 = local_86;
                            let _e1283 = global_7.member[_e1280];
                            local_87 = _e1283;
                            let _e1284 = local_85;
                            let _e1285 = local_25;
                            if (_e1284 < _e1285) {
                                phi_996_ = true;
                            } else {
                                let _e1287 = local_87;
                                let _e1288 = local_25;
                                phi_996_ = (_e1287 < _e1288);
                            }
                            let _e1291 = phi_996_;
                            if _e1291 {
                                let _e1292 = local_28;
                                let _e1293 = (_e1292 * 10u);
                                local_88 = _e1293;
                                let _e1294 = (_e1293 + 3u);
                                local_89 = _e1294;
                                let _e1295 = local_2;
                                if (_e1294 < _e1295) {
                                } else {
                                    phi_6062_ = true;
                                    break;
                                }
                                let _e1297 = local_89;
                                let _e1300 = global_5.member[_e1297];
                                local_90 = bitcast<f32>(_e1300);
                                let _e1302 = local_88;
                                let _e1303 = (_e1302 + 7u);
                                local_91 = _e1303;
                                let _e1304 = local_2;
                                if (_e1303 < _e1304) {
                                } else {
                                    phi_6062_ = true;
                                    break;
                                }
                                let _e1306 = local_91;
                                let _e1309 = global_5.member[_e1306];
                                local_92 = bitcast<f32>(_e1309);
                                let _e1311 = local_30;
                                let _e1312 = (_e1311 * 10u);
                                local_93 = _e1312;
                                let _e1313 = (_e1312 + 3u);
                                local_94 = _e1313;
                                let _e1314 = local_2;
                                if (_e1313 < _e1314) {
                                } else {
                                    phi_6062_ = true;
                                    break;
                                }
                                let _e1316 = local_94;
                                let _e1319 = global_5.member[_e1316];
                                local_95 = bitcast<f32>(_e1319);
                                let _e1321 = local_93;
                                let _e1322 = (_e1321 + 7u);
                                local_96 = _e1322;
                                let _e1323 = local_2;
                                if (_e1322 < _e1323) {
                                } else {
                                    phi_6062_ = true;
                                    break;
                                }
                                let _e1325 = local_96;
                                let _e1328 = global_5.member[_e1325];
                                local_97 = bitcast<f32>(_e1328);
                                let _e1330 = local_32;
                                let _e1331 = (_e1330 * 10u);
                                local_98 = _e1331;
                                let _e1332 = (_e1331 + 3u);
                                local_99 = _e1332;
                                let _e1333 = local_2;
                                if (_e1332 < _e1333) {
                                } else {
                                    phi_6062_ = true;
                                    break;
                                }
                                let _e1335 = local_99;
                                let _e1338 = global_5.member[_e1335];
                                local_100 = bitcast<f32>(_e1338);
                                let _e1340 = local_98;
                                let _e1341 = (_e1340 + 7u);
                                local_101 = _e1341;
                                let _e1342 = local_2;
                                if (_e1341 < _e1342) {
                                } else {
                                    phi_6062_ = true;
                                    break;
                                }
                                let _e1344 = local_101;
                                let _e1347 = global_5.member[_e1344];
                                local_102 = bitcast<f32>(_e1347);
                                let _e1349 = local_625;
                                let _e1353 = local_624;
                                let _e1366 = local_70;
                                local_509 = (_e1349[0] - _e1366);
                                let _e1368 = local_71;
                                local_510 = (_e1349[1] - _e1368);
                                let _e1370 = local_72;
                                local_511 = (_e1349[2] - _e1370);
                                let _e1372 = (_e1353[1][0] - _e1353[0][0]);
                                local_512 = _e1372;
                                let _e1373 = (_e1353[1][1] - _e1353[0][1]);
                                local_513 = _e1373;
                                let _e1374 = (_e1353[1][2] - _e1353[0][2]);
                                local_514 = _e1374;
                                let _e1375 = (_e1353[2][0] - _e1353[0][0]);
                                local_515 = _e1375;
                                let _e1376 = (_e1353[2][1] - _e1353[0][1]);
                                local_516 = _e1376;
                                let _e1377 = (_e1353[2][2] - _e1353[0][2]);
                                local_517 = _e1377;
                                local_518 = ((_e1373 * _e1377) - (_e1374 * _e1376));
                                local_519 = ((_e1374 * _e1375) - (_e1372 * _e1377));
                                local_520 = ((_e1372 * _e1376) - (_e1373 * _e1375));
                                let _e1391 = (((_e1372 * _e1372) + (_e1373 * _e1373)) + (_e1374 * _e1374));
                                local_521 = _e1391;
                                let _e1396 = (((_e1372 * _e1375) + (_e1373 * _e1376)) + (_e1374 * _e1377));
                                local_522 = _e1396;
                                let _e1401 = (((_e1375 * _e1375) + (_e1376 * _e1376)) + (_e1377 * _e1377));
                                local_523 = _e1401;
                                let _e1404 = ((_e1391 * _e1401) - (_e1396 * _e1396));
                                local_524 = _e1404;
                                if (_e1404 > 0f) {
                                    let _e1406 = local_22;
                                    let _e1407 = (_e1406 > 0f);
                                    local_525 = _e1407;
                                    if _e1407 {
                                        let _e1408 = local_24;
                                        let _e1410 = local_24;
                                        let _e1412 = local_24;
                                        let _e1414 = (2f * _e1412[2]);
                                        let _e1415 = (_e1410[1] * -2f);
                                        let _e1422 = local_24;
                                        local_530 = (1f + ((_e1410[1] * _e1415) - (_e1412[2] * _e1414)));
                                        local_531 = ((_e1422[3] * _e1414) + -((_e1408[0] * _e1415)));
                                        local_532 = ((_e1422[3] * _e1415) + (_e1408[0] * _e1414));
                                        let _e1429 = (_e1412[2] * -2f);
                                        let _e1430 = (2f * _e1408[0]);
                                        local_533 = ((_e1422[3] * _e1429) + (_e1410[1] * _e1430));
                                        local_534 = (1f + ((_e1412[2] * _e1429) - (_e1408[0] * _e1430)));
                                        local_535 = ((_e1422[3] * _e1430) + -((_e1410[1] * _e1429)));
                                        let _e1442 = local_509;
                                        let _e1443 = local_518;
                                        let _e1445 = local_510;
                                        let _e1446 = local_519;
                                        let _e1449 = local_511;
                                        let _e1450 = local_520;
                                        let _e1452 = (((_e1442 * _e1443) + (_e1445 * _e1446)) + (_e1449 * _e1450));
                                        local_526 = _e1452;
                                        let _e1453 = local_509;
                                        let _e1454 = local_509;
                                        let _e1456 = local_510;
                                        let _e1457 = local_510;
                                        let _e1460 = local_511;
                                        let _e1461 = local_511;
                                        let _e1464 = local_518;
                                        let _e1465 = local_518;
                                        let _e1467 = local_519;
                                        let _e1468 = local_519;
                                        let _e1471 = local_520;
                                        let _e1472 = local_520;
                                        let _e1476 = sqrt(((((_e1453 * _e1454) + (_e1456 * _e1457)) + (_e1460 * _e1461)) * (((_e1464 * _e1465) + (_e1467 * _e1468)) + (_e1471 * _e1472))));
                                        local_527 = _e1476;
                                        let _e1477 = (0.001f * _e1476);
                                        local_528 = _e1477;
                                        let _e1478 = (_e1452 < 0f);
                                        local_529 = _e1478;
                                        if _e1478 {
                                            let _e1479 = local_526;
                                            phi_5356_ = -(_e1479);
                                        } else {
                                            phi_5356_ = _e1452;
                                        }
                                        let _e1482 = phi_5356_;
                                        let _e1483 = local_528;
                                        if (_e1482 >= _e1483) {
                                            phi_5367_ = _e1452;
                                        } else {
                                            let _e1485 = local_529;
                                            if _e1485 {
                                                let _e1486 = local_527;
                                                phi_5365_ = (_e1486 * -0.001f);
                                            } else {
                                                phi_5365_ = _e1477;
                                            }
                                            let _e1489 = phi_5365_;
                                            phi_5367_ = _e1489;
                                        }
                                        let _e1491 = phi_5367_;
                                        let _e1492 = local_95;
                                        let _e1493 = local_90;
                                        let _e1494 = (_e1492 - _e1493);
                                        let _e1495 = local_97;
                                        let _e1496 = local_92;
                                        let _e1497 = (_e1495 - _e1496);
                                        let _e1498 = local_100;
                                        let _e1499 = local_90;
                                        let _e1500 = (_e1498 - _e1499);
                                        let _e1501 = local_102;
                                        let _e1502 = local_92;
                                        let _e1503 = (_e1501 - _e1502);
                                        let _e1504 = local_530;
                                        let _e1505 = local_518;
                                        let _e1507 = local_531;
                                        let _e1508 = local_519;
                                        let _e1511 = local_532;
                                        let _e1512 = local_520;
                                        let _e1515 = ((((_e1504 * _e1505) + (_e1507 * _e1508)) + (_e1511 * _e1512)) / _e1491);
                                        let _e1516 = local_509;
                                        let _e1518 = local_530;
                                        let _e1520 = local_22;
                                        let _e1521 = (_e1520 * (_e1518 - (_e1516 * _e1515)));
                                        let _e1522 = local_510;
                                        let _e1524 = local_531;
                                        let _e1526 = local_22;
                                        let _e1527 = (_e1526 * (_e1524 - (_e1522 * _e1515)));
                                        let _e1528 = local_511;
                                        let _e1530 = local_532;
                                        let _e1532 = local_22;
                                        let _e1533 = (_e1532 * (_e1530 - (_e1528 * _e1515)));
                                        let _e1534 = local_512;
                                        let _e1536 = local_513;
                                        let _e1539 = local_514;
                                        let _e1541 = (((_e1521 * _e1534) + (_e1527 * _e1536)) + (_e1533 * _e1539));
                                        let _e1542 = local_515;
                                        let _e1544 = local_516;
                                        let _e1547 = local_517;
                                        let _e1549 = (((_e1521 * _e1542) + (_e1527 * _e1544)) + (_e1533 * _e1547));
                                        let _e1550 = local_523;
                                        let _e1552 = local_522;
                                        let _e1555 = local_524;
                                        let _e1556 = (((_e1541 * _e1550) - (_e1549 * _e1552)) / _e1555);
                                        let _e1557 = local_521;
                                        let _e1559 = local_522;
                                        let _e1562 = local_524;
                                        let _e1563 = (((_e1549 * _e1557) - (_e1541 * _e1559)) / _e1562);
                                        let _e1570 = local_533;
                                        let _e1571 = local_518;
                                        let _e1573 = local_534;
                                        let _e1574 = local_519;
                                        let _e1577 = local_535;
                                        let _e1578 = local_520;
                                        let _e1581 = ((((_e1570 * _e1571) + (_e1573 * _e1574)) + (_e1577 * _e1578)) / _e1491);
                                        let _e1582 = local_509;
                                        let _e1584 = local_533;
                                        let _e1586 = local_22;
                                        let _e1587 = (_e1586 * (_e1584 - (_e1582 * _e1581)));
                                        let _e1588 = local_510;
                                        let _e1590 = local_534;
                                        let _e1592 = local_22;
                                        let _e1593 = (_e1592 * (_e1590 - (_e1588 * _e1581)));
                                        let _e1594 = local_511;
                                        let _e1596 = local_535;
                                        let _e1598 = local_22;
                                        let _e1599 = (_e1598 * (_e1596 - (_e1594 * _e1581)));
                                        let _e1600 = local_512;
                                        let _e1602 = local_513;
                                        let _e1605 = local_514;
                                        let _e1607 = (((_e1587 * _e1600) + (_e1593 * _e1602)) + (_e1599 * _e1605));
                                        let _e1608 = local_515;
                                        let _e1610 = local_516;
                                        let _e1613 = local_517;
                                        let _e1615 = (((_e1587 * _e1608) + (_e1593 * _e1610)) + (_e1599 * _e1613));
                                        let _e1616 = local_523;
                                        let _e1618 = local_522;
                                        let _e1621 = local_524;
                                        let _e1622 = (((_e1607 * _e1616) - (_e1615 * _e1618)) / _e1621);
                                        let _e1623 = local_521;
                                        let _e1625 = local_522;
                                        let _e1628 = local_524;
                                        let _e1629 = (((_e1615 * _e1623) - (_e1607 * _e1625)) / _e1628);
                                        phi_5473_ = type_5(((_e1556 * _e1494) + (_e1563 * _e1500)), ((_e1556 * _e1497) + (_e1563 * _e1503)), ((_e1622 * _e1494) + (_e1629 * _e1500)), ((_e1622 * _e1497) + (_e1629 * _e1503)));
                                    } else {
                                        phi_5473_ = type_5();
                                    }
                                    let _e1638 = phi_5473_;
                                    let _e1639 = local_525;
                                    phi_5477_ = _e1638;
                                    phi_5478_ = select(true, false, _e1639);
                                } else {
                                    phi_5477_ = type_5();
                                    phi_5478_ = true;
                                }
                                let _e1642 = phi_5477_;
                                let _e1644 = phi_5478_;
                                if _e1644 {
                                    phi_5482_ = type_5(0f, 0f, 0f, 0f);
                                } else {
                                    phi_5482_ = _e1642;
                                }
                                let _e1646 = phi_5482_;
                                phi_1146_ = _e1646;
                            } else {
                                phi_1146_ = type_5(0f, 0f, 0f, 0f);
                            }
                            let _e1648 = phi_1146_;
                            local_103 = _e1648;
                            let _e1649 = local_85;
                            if (_e1649 == 4294967295u) {
                                phi_5978_ = _e1265;
                                phi_2643_ = type_5();
                                phi_2644_ = true;
                            } else {
                                let _e1651 = local_85;
                                let _e1652 = local_25;
                                let _e1653 = (_e1651 >= _e1652);
                                if _e1653 {
                                    phi_5979_ = _e1265;
                                    phi_2642_ = type_5();
                                } else {
                                    let _e1654 = local_85;
                                    let _e1655 = (_e1654 * 4u);
                                    local_104 = _e1655;
                                    let _e1656 = local_5;
                                    if (_e1655 < _e1656) {
                                    } else {
                                        phi_6062_ = true;
                                        break;
                                    }
                                    let _e1658 = local_104;
                                    let _e1661 = global_8.member[_e1658];
                                    local_105 = _e1661;
                                    let _e1662 = local_104;
                                    let _e1663 = (_e1662 + 1u);
                                    local_106 = _e1663;
                                    let _e1664 = local_5;
                                    if (_e1663 < _e1664) {
                                    } else {
                                        phi_6062_ = true;
                                        break;
                                    }
                                    let _e1666 = local_106;
                                    let _e1669 = global_8.member[_e1666];
                                    local_107 = _e1669;
                                    let _e1670 = local_104;
                                    let _e1671 = (_e1670 + 2u);
                                    local_108 = _e1671;
                                    let _e1672 = local_5;
                                    if (_e1671 < _e1672) {
                                    } else {
                                        phi_6062_ = true;
                                        break;
                                    }
                                    let _e1674 = local_108;
                                    let _e1677 = global_8.member[_e1674];
                                    local_109 = _e1677;
                                    let _e1678 = local_104;
                                    let _e1679 = (_e1678 + 3u);
                                    local_110 = _e1679;
                                    let _e1680 = local_5;
                                    if (_e1679 < _e1680) {
                                    } else {
                                        phi_6062_ = true;
                                        break;
                                    }
                                    let _e1682 = local_110;
                                    let _e1685 = global_8.member[_e1682];
                                    local_111 = _e1685;
                                    let _e1686 = local_107;
                                    if (_e1686 == 0u) {
                                        phi_5981_ = _e1265;
                                        phi_2636_ = type_5();
                                        phi_2637_ = true;
                                    } else {
                                        let _e1688 = local_109;
                                        let _e1689 = (_e1688 == 0u);
                                        if _e1689 {
                                            phi_5982_ = _e1265;
                                            phi_2635_ = type_5();
                                        } else {
                                            let _e1690 = local_111;
                                            let _e1693 = ((_e1690 >> bitcast<u32>(8u)) & 31u);
                                            local_565 = select(_e1693, 1u, (_e1693 == 0u));
                                            let _e1696 = local_111;
                                            let _e1700 = local_111;
                                            let _e1704 = local_105;
                                            let _e1705 = local_107;
                                            let _e1706 = local_109;
                                            let _e1707 = type_22(_e1704, _e1705, _e1706, ((_e1696 >> bitcast<u32>(1u)) & 3u), ((_e1700 >> bitcast<u32>(3u)) & 3u));
                                            let _e1708 = local_107;
                                            let _e1709 = f32(_e1708);
                                            local_112 = _e1709;
                                            let _e1710 = local_76;
                                            if ((bitcast<u32>((_e1710 * _e1709)) & 2139095040u) != 2139095040u) {
                                                let _e1715 = local_109;
                                                let _e1717 = local_75;
                                                phi_1256_ = select(true, false, ((bitcast<u32>((_e1717 * f32(_e1715))) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_1256_ = true;
                                            }
                                            let _e1724 = phi_1256_;
                                            let _e1725 = local_75;
                                            local_566 = select(_e1725, 0f, _e1724);
                                            let _e1727 = local_76;
                                            local_567 = select(_e1727, 0f, _e1724);
                                            let _e1729 = local_103;
                                            local_113 = _e1729.member;
                                            let _e1731 = local_112;
                                            let _e1732 = (_e1729.member * _e1731);
                                            let _e1733 = local_103;
                                            local_114 = _e1733.member_1;
                                            let _e1735 = local_109;
                                            let _e1736 = f32(_e1735);
                                            let _e1737 = (_e1733.member_1 * _e1736);
                                            let _e1738 = local_103;
                                            local_115 = _e1738.member_2;
                                            let _e1740 = local_112;
                                            let _e1741 = (_e1738.member_2 * _e1740);
                                            let _e1742 = local_103;
                                            local_116 = _e1742.member_3;
                                            let _e1744 = (_e1742.member_3 * _e1736);
                                            let _e1748 = sqrt(((_e1732 * _e1732) + (_e1737 * _e1737)));
                                            local_117 = _e1748;
                                            let _e1752 = sqrt(((_e1741 * _e1741) + (_e1744 * _e1744)));
                                            local_118 = _e1752;
                                            let _e1754 = select(_e1752, _e1748, (_e1748 > _e1752));
                                            local_568 = _e1754;
                                            if (_e1754 > 1f) {
                                                let _e1756 = local_568;
                                                phi_1295_ = !(((bitcast<u32>(_e1756) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_1295_ = true;
                                            }
                                            let _e1762 = phi_1295_;
                                            local_119 = _e1762;
                                            let _e1763 = local_564;
                                            let _e1765 = local_564;
                                            local_569 = select(64u, _e1765, (_e1763 < 64u));
                                            phi_1302_ = 1u;
                                            loop {
                                                let _e1768 = phi_1302_;
                                                local_120 = _e1768;
                                                let _e1769 = local_120;
                                                if (_e1769 < 8u) {
                                                    let _e1771 = local_120;
                                                    let _e1772 = (_e1771 + 1u);
                                                    let _e1774 = local_569;
                                                    let _e1775 = ((_e1772 * _e1772) <= _e1774);
                                                    phi_1303_ = select(u32(), _e1772, _e1775);
                                                    phi_1320_ = _e1775;
                                                } else {
                                                    phi_1303_ = u32();
                                                    phi_1320_ = false;
                                                }
                                                let _e1778 = phi_1303_;
                                                let _e1780 = phi_1320_;
                                                local_121 = _e1780;
                                                continue;
                                                continuing {
                                                    let _e1781 = local_121;
                                                    phi_1302_ = _e1778;
                                                    break if !(_e1781);
                                                }
                                            }
                                            let _e1783 = local_119;
                                            if _e1783 {
                                                phi_1420_ = 1u;
                                                phi_1421_ = 1u;
                                            } else {
                                                let _e1784 = local_117;
                                                let _e1785 = local_118;
                                                if (_e1784 >= _e1785) {
                                                    let _e1828 = local_120;
                                                    let _e1829 = f32(_e1828);
                                                    let _e1830 = local_118;
                                                    let _e1832 = local_118;
                                                    let _e1834 = ceil(select(_e1829, _e1832, (_e1830 < _e1829)));
                                                    local_122 = _e1834;
                                                    if (_e1834 < 1f) {
                                                        phi_1350_ = 1u;
                                                    } else {
                                                        let _e1836 = local_122;
                                                        let _e1838 = local_122;
                                                        let _e1841 = local_122;
                                                        phi_1350_ = select(select(u32(_e1836), 0u, !((_e1838 >= 0f))), 4294967295u, (_e1841 > 4294967000f));
                                                    }
                                                    let _e1846 = phi_1350_;
                                                    local_123 = _e1846;
                                                    if (_e1846 == 0u) {
                                                        phi_6062_ = true;
                                                        break;
                                                    }
                                                    let _e1848 = local_569;
                                                    let _e1849 = local_123;
                                                    let _e1851 = f32((_e1848 / _e1849));
                                                    let _e1852 = local_117;
                                                    let _e1854 = local_117;
                                                    let _e1856 = ceil(select(_e1851, _e1854, (_e1852 < _e1851)));
                                                    local_124 = _e1856;
                                                    if (_e1856 < 1f) {
                                                        phi_1374_ = 1u;
                                                    } else {
                                                        let _e1858 = local_124;
                                                        let _e1860 = local_124;
                                                        let _e1863 = local_124;
                                                        phi_1374_ = select(select(u32(_e1858), 0u, !((_e1860 >= 0f))), 4294967295u, (_e1863 > 4294967000f));
                                                    }
                                                    let _e1868 = phi_1374_;
                                                    phi_1418_ = _e1846;
                                                    phi_1419_ = _e1868;
                                                } else {
                                                    let _e1787 = local_120;
                                                    let _e1788 = f32(_e1787);
                                                    let _e1789 = local_117;
                                                    let _e1791 = local_117;
                                                    let _e1793 = ceil(select(_e1788, _e1791, (_e1789 < _e1788)));
                                                    local_125 = _e1793;
                                                    if (_e1793 < 1f) {
                                                        phi_1393_ = 1u;
                                                    } else {
                                                        let _e1795 = local_125;
                                                        let _e1797 = local_125;
                                                        let _e1800 = local_125;
                                                        phi_1393_ = select(select(u32(_e1795), 0u, !((_e1797 >= 0f))), 4294967295u, (_e1800 > 4294967000f));
                                                    }
                                                    let _e1805 = phi_1393_;
                                                    local_126 = _e1805;
                                                    if (_e1805 == 0u) {
                                                        phi_6062_ = true;
                                                        break;
                                                    }
                                                    let _e1807 = local_569;
                                                    let _e1808 = local_126;
                                                    let _e1810 = f32((_e1807 / _e1808));
                                                    let _e1811 = local_118;
                                                    let _e1813 = local_118;
                                                    let _e1815 = ceil(select(_e1810, _e1813, (_e1811 < _e1810)));
                                                    local_127 = _e1815;
                                                    if (_e1815 < 1f) {
                                                        phi_1417_ = 1u;
                                                    } else {
                                                        let _e1817 = local_127;
                                                        let _e1819 = local_127;
                                                        let _e1822 = local_127;
                                                        phi_1417_ = select(select(u32(_e1817), 0u, !((_e1819 >= 0f))), 4294967295u, (_e1822 > 4294967000f));
                                                    }
                                                    let _e1827 = phi_1417_;
                                                    phi_1418_ = _e1827;
                                                    phi_1419_ = _e1805;
                                                }
                                                let _e1870 = phi_1418_;
                                                let _e1872 = phi_1419_;
                                                phi_1420_ = _e1870;
                                                phi_1421_ = _e1872;
                                            }
                                            let _e1874 = phi_1420_;
                                            let _e1876 = phi_1421_;
                                            local_128 = _e1874;
                                            local_129 = _e1876;
                                            let _e1877 = local_119;
                                            if _e1877 {
                                                phi_1434_ = 1f;
                                            } else {
                                                let _e1878 = local_129;
                                                let _e1880 = local_117;
                                                let _e1881 = (_e1880 / f32(_e1878));
                                                let _e1882 = local_128;
                                                let _e1884 = local_118;
                                                let _e1885 = (_e1884 / f32(_e1882));
                                                phi_1434_ = select(_e1885, _e1881, (_e1881 > _e1885));
                                            }
                                            let _e1889 = phi_1434_;
                                            local_130 = _e1889;
                                            if (_e1889 > 1f) {
                                                let _e1891 = local_130;
                                                let _e1892 = bitcast<u32>(_e1891);
                                                let _e1901 = (bitcast<f32>(((_e1892 & 8388607u) | 1065353216u)) - 1f);
                                                phi_1455_ = (f32((bitcast<i32>(((_e1892 >> bitcast<u32>(23i)) & 255u)) - 127i)) + (_e1901 * (1.4208645f + (_e1901 * (-0.5772506f + (_e1901 * 0.1563861f))))));
                                            } else {
                                                phi_1455_ = 0f;
                                            }
                                            let _e1910 = phi_1455_;
                                            local_131 = _e1910;
                                            let _e1911 = local_565;
                                            let _e1912 = (_e1911 - 1u);
                                            local_132 = _e1912;
                                            let _e1913 = floor(_e1910);
                                            let _e1919 = select(select(u32(_e1913), 0u, !((_e1913 >= 0f))), 4294967295u, (_e1913 > 4294967000f));
                                            local_133 = _e1919;
                                            let _e1920 = (_e1919 >= _e1912);
                                            local_134 = _e1920;
                                            if _e1920 {
                                                phi_1471_ = 0f;
                                            } else {
                                                let _e1921 = local_133;
                                                let _e1923 = local_131;
                                                phi_1471_ = (_e1923 - f32(_e1921));
                                            }
                                            let _e1926 = phi_1471_;
                                            local_135 = _e1926;
                                            let _e1927 = local_134;
                                            let _e1928 = local_132;
                                            let _e1929 = local_133;
                                            local_570 = select(_e1929, _e1928, _e1927);
                                            local_571 = select(1u, 2u, (_e1926 > 0f));
                                            phi_5583_ = 0u;
                                            phi_5584_ = _e1707;
                                            loop {
                                                let _e1934 = phi_5583_;
                                                let _e1936 = phi_5584_;
                                                local_536 = _e1934;
                                                local_537 = _e1936;
                                                local_632 = _e1936;
                                                let _e1937 = local_536;
                                                let _e1938 = local_570;
                                                let _e1939 = (_e1937 < _e1938);
                                                local_538 = _e1939;
                                                if _e1939 {
                                                    let _e1940 = local_537;
                                                    local_539 = _e1940.member_1;
                                                    let _e1942 = local_537;
                                                    local_540 = _e1942.member_2;
                                                    let _e1945 = local_537;
                                                    let _e1948 = local_537;
                                                    local_541 = type_22((_e1945.member + (_e1940.member_1 * _e1942.member_2)), _e1948.member_1, _e1948.member_2, _e1948.member_3, _e1948.member_4);
                                                    if (_e1940.member_1 > 1u) {
                                                        let _e1956 = local_539;
                                                        phi_5601_ = (_e1956 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5601_ = 1u;
                                                    }
                                                    let _e1960 = phi_5601_;
                                                    let _e1961 = local_541;
                                                    local_542 = type_22(_e1961.member, _e1960, _e1961.member_2, _e1961.member_3, _e1961.member_4);
                                                    let _e1968 = local_540;
                                                    if (_e1968 > 1u) {
                                                        let _e1970 = local_540;
                                                        phi_5610_ = (_e1970 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5610_ = 1u;
                                                    }
                                                    let _e1974 = phi_5610_;
                                                    let _e1975 = local_542;
                                                    let _e1982 = local_536;
                                                    phi_5615_ = (_e1982 + 1u);
                                                    phi_5616_ = type_22(_e1975.member, _e1975.member_1, _e1974, _e1975.member_3, _e1975.member_4);
                                                } else {
                                                    phi_5615_ = u32();
                                                    phi_5616_ = type_22();
                                                }
                                                let _e1985 = phi_5615_;
                                                let _e1987 = phi_5616_;
                                                continue;
                                                continuing {
                                                    let _e1988 = local_538;
                                                    phi_5583_ = _e1985;
                                                    phi_5584_ = _e1987;
                                                    break if !(_e1988);
                                                }
                                            }
                                            let _e1990 = local_570;
                                            let _e1991 = local_571;
                                            local_136 = ((_e1990 + _e1991) - 1u);
                                            phi_5622_ = 0u;
                                            phi_5623_ = _e1707;
                                            loop {
                                                let _e1995 = phi_5622_;
                                                let _e1997 = phi_5623_;
                                                local_543 = _e1995;
                                                local_544 = _e1997;
                                                local_633 = _e1997;
                                                let _e1998 = local_543;
                                                let _e1999 = local_136;
                                                let _e2000 = (_e1998 < _e1999);
                                                local_545 = _e2000;
                                                if _e2000 {
                                                    let _e2001 = local_544;
                                                    local_546 = _e2001.member_1;
                                                    let _e2003 = local_544;
                                                    local_547 = _e2003.member_2;
                                                    let _e2006 = local_544;
                                                    let _e2009 = local_544;
                                                    local_548 = type_22((_e2006.member + (_e2001.member_1 * _e2003.member_2)), _e2009.member_1, _e2009.member_2, _e2009.member_3, _e2009.member_4);
                                                    if (_e2001.member_1 > 1u) {
                                                        let _e2017 = local_546;
                                                        phi_5640_ = (_e2017 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5640_ = 1u;
                                                    }
                                                    let _e2021 = phi_5640_;
                                                    let _e2022 = local_548;
                                                    local_549 = type_22(_e2022.member, _e2021, _e2022.member_2, _e2022.member_3, _e2022.member_4);
                                                    let _e2029 = local_547;
                                                    if (_e2029 > 1u) {
                                                        let _e2031 = local_547;
                                                        phi_5649_ = (_e2031 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5649_ = 1u;
                                                    }
                                                    let _e2035 = phi_5649_;
                                                    let _e2036 = local_549;
                                                    let _e2043 = local_543;
                                                    phi_5654_ = (_e2043 + 1u);
                                                    phi_5655_ = type_22(_e2036.member, _e2036.member_1, _e2035, _e2036.member_3, _e2036.member_4);
                                                } else {
                                                    phi_5654_ = u32();
                                                    phi_5655_ = type_22();
                                                }
                                                let _e2046 = phi_5654_;
                                                let _e2048 = phi_5655_;
                                                continue;
                                                continuing {
                                                    let _e2049 = local_545;
                                                    phi_5622_ = _e2046;
                                                    phi_5623_ = _e2048;
                                                    break if !(_e2049);
                                                }
                                            }
                                            let _e2051 = local_119;
                                            if _e2051 {
                                                let _e2052 = local_111;
                                                phi_1487_ = ((_e2052 & 1u) != 0u);
                                            } else {
                                                phi_1487_ = false;
                                            }
                                            let _e2056 = phi_1487_;
                                            local_137 = _e2056;
                                            phi_5830_ = _e1265;
                                            phi_1490_ = 0u;
                                            phi_1493_ = type_5(0f, 0f, 0f, 0f);
                                            loop {
                                                let _e2058 = phi_5830_;
                                                let _e2060 = phi_1490_;
                                                let _e2062 = phi_1493_;
                                                local_138 = _e2060;
                                                local_139 = _e2062;
                                                let _e2063 = local_138;
                                                let _e2064 = local_129;
                                                let _e2065 = (_e2063 < _e2064);
                                                local_140 = _e2065;
                                                if _e2065 {
                                                    let _e2066 = local_138;
                                                    let _e2069 = local_129;
                                                    local_141 = (((f32(_e2066) + 0.5f) / f32(_e2069)) - 0.5f);
                                                    phi_5829_ = _e2058;
                                                    phi_1507_ = 0u;
                                                    phi_1510_ = _e2062;
                                                    loop {
                                                        let _e2074 = phi_5829_;
                                                        let _e2076 = phi_1507_;
                                                        let _e2078 = phi_1510_;
                                                        local_142 = _e2076;
                                                        local_635 = _e2078;
                                                        let _e2079 = local_142;
                                                        let _e2080 = local_128;
                                                        let _e2081 = (_e2079 < _e2080);
                                                        local_143 = _e2081;
                                                        if _e2081 {
                                                            let _e2082 = local_142;
                                                            let _e2085 = local_128;
                                                            let _e2088 = (((f32(_e2082) + 0.5f) / f32(_e2085)) - 0.5f);
                                                            let _e2089 = local_141;
                                                            let _e2090 = local_113;
                                                            let _e2092 = local_567;
                                                            let _e2094 = local_115;
                                                            local_144 = ((_e2092 + (_e2089 * _e2090)) + (_e2088 * _e2094));
                                                            let _e2097 = local_141;
                                                            let _e2098 = local_114;
                                                            let _e2100 = local_566;
                                                            let _e2102 = local_116;
                                                            local_145 = ((_e2100 + (_e2097 * _e2098)) + (_e2088 * _e2102));
                                                            phi_1536_ = 0u;
                                                            phi_1539_ = _e2078;
                                                            loop {
                                                                let _e2106 = phi_1536_;
                                                                let _e2108 = phi_1539_;
                                                                local_146 = _e2106;
                                                                local_147 = _e2108;
                                                                local_634 = _e2108;
                                                                let _e2109 = local_146;
                                                                let _e2110 = local_571;
                                                                let _e2111 = (_e2109 < _e2110);
                                                                local_148 = _e2111;
                                                                if _e2111 {
                                                                    let _e2112 = local_146;
                                                                    if (_e2112 == 0u) {
                                                                        let _e2114 = local_135;
                                                                        let _e5600 = local_632;
                                                                        phi_1552_ = _e5600;
                                                                        phi_1553_ = (1f - _e2114);
                                                                    } else {
                                                                        let _e5602 = local_633;
                                                                        phi_1552_ = _e5602;
                                                                        phi_1553_ = _e1926;
                                                                    }
                                                                    let _e2117 = phi_1552_;
                                                                    let _e2119 = phi_1553_;
                                                                    local_149 = _e2117;
                                                                    local_150 = _e2119;
                                                                    let _e2120 = local_137;
                                                                    let _e2121 = select(0.5f, 0f, _e2120);
                                                                    local_151 = _e2117.member_1;
                                                                    let _e2124 = local_144;
                                                                    let _e2126 = ((_e2124 * f32(_e2117.member_1)) - _e2121);
                                                                    local_152 = _e2126;
                                                                    local_153 = _e2117.member_2;
                                                                    let _e2129 = local_145;
                                                                    let _e2131 = ((_e2129 * f32(_e2117.member_2)) - _e2121);
                                                                    local_154 = _e2131;
                                                                    local_155 = floor(_e2126);
                                                                    local_156 = floor(_e2131);
                                                                    let _e2134 = local_137;
                                                                    if _e2134 {
                                                                        phi_1573_ = 0f;
                                                                        phi_1574_ = 0f;
                                                                    } else {
                                                                        let _e2135 = local_152;
                                                                        let _e2136 = local_155;
                                                                        let _e2138 = local_154;
                                                                        let _e2139 = local_156;
                                                                        phi_1573_ = (_e2138 - _e2139);
                                                                        phi_1574_ = (_e2135 - _e2136);
                                                                    }
                                                                    let _e2142 = phi_1573_;
                                                                    let _e2144 = phi_1574_;
                                                                    local_157 = _e2142;
                                                                    local_158 = _e2144;
                                                                    let _e2145 = local_155;
                                                                    let _e2147 = local_155;
                                                                    let _e2150 = local_155;
                                                                    let _e2154 = local_155;
                                                                    let _e2155 = local_155;
                                                                    let _e2157 = select(0i, select(select(i32(_e2145), i32(-2147483648), !((_e2147 >= -2147483600f))), 2147483647i, (_e2150 > 2147483500f)), (_e2154 == _e2155));
                                                                    local_159 = _e2157;
                                                                    let _e2158 = local_156;
                                                                    let _e2160 = local_156;
                                                                    let _e2163 = local_156;
                                                                    let _e2167 = local_156;
                                                                    let _e2168 = local_156;
                                                                    let _e2170 = select(0i, select(select(i32(_e2158), i32(-2147483648), !((_e2160 >= -2147483600f))), 2147483647i, (_e2163 > 2147483500f)), (_e2167 == _e2168));
                                                                    local_160 = _e2170;
                                                                    let _e2171 = local_149;
                                                                    local_161 = _e2171.member_3;
                                                                    let _e2173 = local_151;
                                                                    local_162 = bitcast<i32>(_e2173);
                                                                    let _e2175 = (_e2171.member_3 == 1u);
                                                                    local_163 = _e2175;
                                                                    if _e2175 {
                                                                        let _e2229 = local_159;
                                                                        if (_e2229 < 0i) {
                                                                            phi_1610_ = 0i;
                                                                        } else {
                                                                            let _e2231 = local_159;
                                                                            let _e2232 = local_162;
                                                                            if (_e2231 >= _e2232) {
                                                                                let _e2234 = local_162;
                                                                                phi_1609_ = (_e2234 - 1i);
                                                                            } else {
                                                                                phi_1609_ = _e2157;
                                                                            }
                                                                            let _e2237 = phi_1609_;
                                                                            phi_1610_ = _e2237;
                                                                        }
                                                                        let _e2239 = phi_1610_;
                                                                        phi_1670_ = _e2239;
                                                                    } else {
                                                                        let _e2176 = local_161;
                                                                        if (_e2176 == 2u) {
                                                                            let _e2198 = local_162;
                                                                            let _e2199 = (2i * _e2198);
                                                                            local_164 = _e2199;
                                                                            let _e2200 = (_e2199 == 0i);
                                                                            local_165 = _e2200;
                                                                            if _e2200 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2201 = local_164;
                                                                            let _e2202 = (_e2201 == -1i);
                                                                            local_166 = _e2202;
                                                                            let _e2203 = local_159;
                                                                            if (_e2202 && (_e2203 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2206 = local_159;
                                                                            let _e2207 = local_164;
                                                                            let _e2209 = local_164;
                                                                            local_167 = ((_e2206 % _e2207) + _e2209);
                                                                            let _e2211 = local_165;
                                                                            if _e2211 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2212 = local_167;
                                                                            let _e2214 = local_166;
                                                                            if (_e2214 && (_e2212 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2216 = local_167;
                                                                            let _e2217 = local_164;
                                                                            let _e2218 = (_e2216 % _e2217);
                                                                            local_168 = _e2218;
                                                                            let _e2219 = local_162;
                                                                            if (_e2218 < _e2219) {
                                                                                phi_1645_ = _e2218;
                                                                            } else {
                                                                                let _e2221 = local_164;
                                                                                let _e2223 = local_168;
                                                                                phi_1645_ = ((_e2221 - 1i) - _e2223);
                                                                            }
                                                                            let _e2226 = phi_1645_;
                                                                            phi_1669_ = _e2226;
                                                                        } else {
                                                                            let _e2178 = local_162;
                                                                            let _e2179 = (_e2178 == 0i);
                                                                            local_169 = _e2179;
                                                                            if _e2179 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2180 = local_162;
                                                                            let _e2181 = (_e2180 == -1i);
                                                                            local_170 = _e2181;
                                                                            let _e2182 = local_159;
                                                                            if (_e2181 && (_e2182 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2185 = local_159;
                                                                            let _e2186 = local_162;
                                                                            let _e2188 = local_162;
                                                                            local_171 = ((_e2185 % _e2186) + _e2188);
                                                                            let _e2190 = local_169;
                                                                            if _e2190 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2191 = local_171;
                                                                            let _e2193 = local_170;
                                                                            if (_e2193 && (_e2191 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2195 = local_171;
                                                                            let _e2196 = local_162;
                                                                            phi_1669_ = (_e2195 % _e2196);
                                                                        }
                                                                        let _e2228 = phi_1669_;
                                                                        phi_1670_ = _e2228;
                                                                    }
                                                                    let _e2241 = phi_1670_;
                                                                    local_172 = bitcast<u32>(_e2241);
                                                                    let _e2243 = local_159;
                                                                    let _e2244 = (_e2243 + 1i);
                                                                    local_173 = _e2244;
                                                                    let _e2245 = local_163;
                                                                    if _e2245 {
                                                                        let _e2299 = local_173;
                                                                        if (_e2299 < 0i) {
                                                                            phi_1690_ = 0i;
                                                                        } else {
                                                                            let _e2301 = local_173;
                                                                            let _e2302 = local_162;
                                                                            if (_e2301 >= _e2302) {
                                                                                let _e2304 = local_162;
                                                                                phi_1689_ = (_e2304 - 1i);
                                                                            } else {
                                                                                phi_1689_ = _e2244;
                                                                            }
                                                                            let _e2307 = phi_1689_;
                                                                            phi_1690_ = _e2307;
                                                                        }
                                                                        let _e2309 = phi_1690_;
                                                                        phi_1750_ = _e2309;
                                                                    } else {
                                                                        let _e2246 = local_161;
                                                                        if (_e2246 == 2u) {
                                                                            let _e2268 = local_162;
                                                                            let _e2269 = (2i * _e2268);
                                                                            local_174 = _e2269;
                                                                            let _e2270 = (_e2269 == 0i);
                                                                            local_175 = _e2270;
                                                                            if _e2270 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2271 = local_174;
                                                                            let _e2272 = (_e2271 == -1i);
                                                                            local_176 = _e2272;
                                                                            let _e2273 = local_173;
                                                                            if (_e2272 && (_e2273 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2276 = local_173;
                                                                            let _e2277 = local_174;
                                                                            let _e2279 = local_174;
                                                                            local_177 = ((_e2276 % _e2277) + _e2279);
                                                                            let _e2281 = local_175;
                                                                            if _e2281 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2282 = local_177;
                                                                            let _e2284 = local_176;
                                                                            if (_e2284 && (_e2282 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2286 = local_177;
                                                                            let _e2287 = local_174;
                                                                            let _e2288 = (_e2286 % _e2287);
                                                                            local_178 = _e2288;
                                                                            let _e2289 = local_162;
                                                                            if (_e2288 < _e2289) {
                                                                                phi_1725_ = _e2288;
                                                                            } else {
                                                                                let _e2291 = local_174;
                                                                                let _e2293 = local_178;
                                                                                phi_1725_ = ((_e2291 - 1i) - _e2293);
                                                                            }
                                                                            let _e2296 = phi_1725_;
                                                                            phi_1749_ = _e2296;
                                                                        } else {
                                                                            let _e2248 = local_162;
                                                                            let _e2249 = (_e2248 == 0i);
                                                                            local_179 = _e2249;
                                                                            if _e2249 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2250 = local_162;
                                                                            let _e2251 = (_e2250 == -1i);
                                                                            local_180 = _e2251;
                                                                            let _e2252 = local_173;
                                                                            if (_e2251 && (_e2252 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2255 = local_173;
                                                                            let _e2256 = local_162;
                                                                            let _e2258 = local_162;
                                                                            local_181 = ((_e2255 % _e2256) + _e2258);
                                                                            let _e2260 = local_179;
                                                                            if _e2260 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2261 = local_181;
                                                                            let _e2263 = local_180;
                                                                            if (_e2263 && (_e2261 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2265 = local_181;
                                                                            let _e2266 = local_162;
                                                                            phi_1749_ = (_e2265 % _e2266);
                                                                        }
                                                                        let _e2298 = phi_1749_;
                                                                        phi_1750_ = _e2298;
                                                                    }
                                                                    let _e2311 = phi_1750_;
                                                                    local_182 = bitcast<u32>(_e2311);
                                                                    let _e2313 = local_149;
                                                                    local_183 = _e2313.member_4;
                                                                    let _e2315 = local_153;
                                                                    local_184 = bitcast<i32>(_e2315);
                                                                    let _e2317 = (_e2313.member_4 == 1u);
                                                                    local_185 = _e2317;
                                                                    if _e2317 {
                                                                        let _e2371 = local_160;
                                                                        if (_e2371 < 0i) {
                                                                            phi_1769_ = 0i;
                                                                        } else {
                                                                            let _e2373 = local_160;
                                                                            let _e2374 = local_184;
                                                                            if (_e2373 >= _e2374) {
                                                                                let _e2376 = local_184;
                                                                                phi_1768_ = (_e2376 - 1i);
                                                                            } else {
                                                                                phi_1768_ = _e2170;
                                                                            }
                                                                            let _e2379 = phi_1768_;
                                                                            phi_1769_ = _e2379;
                                                                        }
                                                                        let _e2381 = phi_1769_;
                                                                        phi_1829_ = _e2381;
                                                                    } else {
                                                                        let _e2318 = local_183;
                                                                        if (_e2318 == 2u) {
                                                                            let _e2340 = local_184;
                                                                            let _e2341 = (2i * _e2340);
                                                                            local_186 = _e2341;
                                                                            let _e2342 = (_e2341 == 0i);
                                                                            local_187 = _e2342;
                                                                            if _e2342 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2343 = local_186;
                                                                            let _e2344 = (_e2343 == -1i);
                                                                            local_188 = _e2344;
                                                                            let _e2345 = local_160;
                                                                            if (_e2344 && (_e2345 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2348 = local_160;
                                                                            let _e2349 = local_186;
                                                                            let _e2351 = local_186;
                                                                            local_189 = ((_e2348 % _e2349) + _e2351);
                                                                            let _e2353 = local_187;
                                                                            if _e2353 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2354 = local_189;
                                                                            let _e2356 = local_188;
                                                                            if (_e2356 && (_e2354 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2358 = local_189;
                                                                            let _e2359 = local_186;
                                                                            let _e2360 = (_e2358 % _e2359);
                                                                            local_190 = _e2360;
                                                                            let _e2361 = local_184;
                                                                            if (_e2360 < _e2361) {
                                                                                phi_1804_ = _e2360;
                                                                            } else {
                                                                                let _e2363 = local_186;
                                                                                let _e2365 = local_190;
                                                                                phi_1804_ = ((_e2363 - 1i) - _e2365);
                                                                            }
                                                                            let _e2368 = phi_1804_;
                                                                            phi_1828_ = _e2368;
                                                                        } else {
                                                                            let _e2320 = local_184;
                                                                            let _e2321 = (_e2320 == 0i);
                                                                            local_191 = _e2321;
                                                                            if _e2321 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2322 = local_184;
                                                                            let _e2323 = (_e2322 == -1i);
                                                                            local_192 = _e2323;
                                                                            let _e2324 = local_160;
                                                                            if (_e2323 && (_e2324 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2327 = local_160;
                                                                            let _e2328 = local_184;
                                                                            let _e2330 = local_184;
                                                                            local_193 = ((_e2327 % _e2328) + _e2330);
                                                                            let _e2332 = local_191;
                                                                            if _e2332 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2333 = local_193;
                                                                            let _e2335 = local_192;
                                                                            if (_e2335 && (_e2333 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2337 = local_193;
                                                                            let _e2338 = local_184;
                                                                            phi_1828_ = (_e2337 % _e2338);
                                                                        }
                                                                        let _e2370 = phi_1828_;
                                                                        phi_1829_ = _e2370;
                                                                    }
                                                                    let _e2383 = phi_1829_;
                                                                    local_194 = bitcast<u32>(_e2383);
                                                                    let _e2385 = local_160;
                                                                    let _e2386 = (_e2385 + 1i);
                                                                    local_195 = _e2386;
                                                                    let _e2387 = local_185;
                                                                    if _e2387 {
                                                                        let _e2441 = local_195;
                                                                        if (_e2441 < 0i) {
                                                                            phi_1849_ = 0i;
                                                                        } else {
                                                                            let _e2443 = local_195;
                                                                            let _e2444 = local_184;
                                                                            if (_e2443 >= _e2444) {
                                                                                let _e2446 = local_184;
                                                                                phi_1848_ = (_e2446 - 1i);
                                                                            } else {
                                                                                phi_1848_ = _e2386;
                                                                            }
                                                                            let _e2449 = phi_1848_;
                                                                            phi_1849_ = _e2449;
                                                                        }
                                                                        let _e2451 = phi_1849_;
                                                                        phi_1909_ = _e2451;
                                                                    } else {
                                                                        let _e2388 = local_183;
                                                                        if (_e2388 == 2u) {
                                                                            let _e2410 = local_184;
                                                                            let _e2411 = (2i * _e2410);
                                                                            local_196 = _e2411;
                                                                            let _e2412 = (_e2411 == 0i);
                                                                            local_197 = _e2412;
                                                                            if _e2412 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2413 = local_196;
                                                                            let _e2414 = (_e2413 == -1i);
                                                                            local_198 = _e2414;
                                                                            let _e2415 = local_195;
                                                                            if (_e2414 && (_e2415 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2418 = local_195;
                                                                            let _e2419 = local_196;
                                                                            let _e2421 = local_196;
                                                                            local_199 = ((_e2418 % _e2419) + _e2421);
                                                                            let _e2423 = local_197;
                                                                            if _e2423 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2424 = local_199;
                                                                            let _e2426 = local_198;
                                                                            if (_e2426 && (_e2424 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2428 = local_199;
                                                                            let _e2429 = local_196;
                                                                            let _e2430 = (_e2428 % _e2429);
                                                                            local_200 = _e2430;
                                                                            let _e2431 = local_184;
                                                                            if (_e2430 < _e2431) {
                                                                                phi_1884_ = _e2430;
                                                                            } else {
                                                                                let _e2433 = local_196;
                                                                                let _e2435 = local_200;
                                                                                phi_1884_ = ((_e2433 - 1i) - _e2435);
                                                                            }
                                                                            let _e2438 = phi_1884_;
                                                                            phi_1908_ = _e2438;
                                                                        } else {
                                                                            let _e2390 = local_184;
                                                                            let _e2391 = (_e2390 == 0i);
                                                                            local_201 = _e2391;
                                                                            if _e2391 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2392 = local_184;
                                                                            let _e2393 = (_e2392 == -1i);
                                                                            local_202 = _e2393;
                                                                            let _e2394 = local_195;
                                                                            if (_e2393 && (_e2394 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2397 = local_195;
                                                                            let _e2398 = local_184;
                                                                            let _e2400 = local_184;
                                                                            local_203 = ((_e2397 % _e2398) + _e2400);
                                                                            let _e2402 = local_201;
                                                                            if _e2402 {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2403 = local_203;
                                                                            let _e2405 = local_202;
                                                                            if (_e2405 && (_e2403 == i32(-2147483648))) {
                                                                                phi_5783_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2407 = local_203;
                                                                            let _e2408 = local_184;
                                                                            phi_1908_ = (_e2407 % _e2408);
                                                                        }
                                                                        let _e2440 = phi_1908_;
                                                                        phi_1909_ = _e2440;
                                                                    }
                                                                    let _e2453 = phi_1909_;
                                                                    local_204 = bitcast<u32>(_e2453);
                                                                    let _e2455 = local_149;
                                                                    local_205 = _e2455.member;
                                                                    let _e2457 = local_194;
                                                                    let _e2458 = local_151;
                                                                    let _e2460 = (_e2455.member + (_e2457 * _e2458));
                                                                    local_206 = _e2460;
                                                                    let _e2461 = local_172;
                                                                    let _e2463 = ((_e2460 + _e2461) * 2u);
                                                                    local_207 = _e2463;
                                                                    let _e2464 = local_6;
                                                                    if (_e2463 < _e2464) {
                                                                    } else {
                                                                        phi_5783_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2466 = local_207;
                                                                    let _e2469 = global_9.member[_e2466];
                                                                    local_208 = _e2469;
                                                                    let _e2470 = local_207;
                                                                    let _e2471 = (_e2470 + 1u);
                                                                    local_209 = _e2471;
                                                                    let _e2472 = local_6;
                                                                    if (_e2471 < _e2472) {
                                                                    } else {
                                                                        phi_5783_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2474 = local_209;
                                                                    let _e2477 = global_9.member[_e2474];
                                                                    local_210 = _e2477;
                                                                    let _e2478 = local_208;
                                                                    let _e2479 = (_e2478 & 65535u);
                                                                    local_572 = select(-1f, 1f, ((_e2479 & 32768u) == 0u));
                                                                    let _e2485 = ((_e2479 >> bitcast<u32>(10i)) & 31u);
                                                                    local_211 = _e2485;
                                                                    local_212 = (_e2479 & 1023u);
                                                                    if (_e2485 == 0u) {
                                                                        let _e2507 = local_212;
                                                                        let _e2509 = local_572;
                                                                        phi_1979_ = ((_e2509 * f32(_e2507)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2488 = local_211;
                                                                        if (_e2488 == 31u) {
                                                                            let _e2498 = local_212;
                                                                            phi_1976_ = (2139095040u | (_e2498 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2490 = local_211;
                                                                            let _e2494 = local_212;
                                                                            phi_1976_ = (((_e2490 + 112u) << bitcast<u32>(23i)) | (_e2494 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2503 = phi_1976_;
                                                                        let _e2505 = local_572;
                                                                        phi_1979_ = (_e2505 * bitcast<f32>(_e2503));
                                                                    }
                                                                    let _e2513 = phi_1979_;
                                                                    local_213 = _e2513;
                                                                    let _e2514 = local_208;
                                                                    let _e2516 = (_e2514 >> bitcast<u32>(16i));
                                                                    local_573 = select(-1f, 1f, ((_e2516 & 32768u) == 0u));
                                                                    let _e2522 = ((_e2516 >> bitcast<u32>(10i)) & 31u);
                                                                    local_214 = _e2522;
                                                                    local_215 = (_e2516 & 1023u);
                                                                    if (_e2522 == 0u) {
                                                                        let _e2544 = local_215;
                                                                        let _e2546 = local_573;
                                                                        phi_2011_ = ((_e2546 * f32(_e2544)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2525 = local_214;
                                                                        if (_e2525 == 31u) {
                                                                            let _e2535 = local_215;
                                                                            phi_2008_ = (2139095040u | (_e2535 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2527 = local_214;
                                                                            let _e2531 = local_215;
                                                                            phi_2008_ = (((_e2527 + 112u) << bitcast<u32>(23i)) | (_e2531 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2540 = phi_2008_;
                                                                        let _e2542 = local_573;
                                                                        phi_2011_ = (_e2542 * bitcast<f32>(_e2540));
                                                                    }
                                                                    let _e2550 = phi_2011_;
                                                                    local_216 = _e2550;
                                                                    let _e2551 = local_210;
                                                                    let _e2552 = (_e2551 & 65535u);
                                                                    local_574 = select(-1f, 1f, ((_e2552 & 32768u) == 0u));
                                                                    let _e2558 = ((_e2552 >> bitcast<u32>(10i)) & 31u);
                                                                    local_217 = _e2558;
                                                                    local_218 = (_e2552 & 1023u);
                                                                    if (_e2558 == 0u) {
                                                                        let _e2580 = local_218;
                                                                        let _e2582 = local_574;
                                                                        phi_2043_ = ((_e2582 * f32(_e2580)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2561 = local_217;
                                                                        if (_e2561 == 31u) {
                                                                            let _e2571 = local_218;
                                                                            phi_2040_ = (2139095040u | (_e2571 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2563 = local_217;
                                                                            let _e2567 = local_218;
                                                                            phi_2040_ = (((_e2563 + 112u) << bitcast<u32>(23i)) | (_e2567 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2576 = phi_2040_;
                                                                        let _e2578 = local_574;
                                                                        phi_2043_ = (_e2578 * bitcast<f32>(_e2576));
                                                                    }
                                                                    let _e2586 = phi_2043_;
                                                                    local_219 = _e2586;
                                                                    let _e2587 = local_210;
                                                                    let _e2589 = (_e2587 >> bitcast<u32>(16i));
                                                                    local_575 = select(-1f, 1f, ((_e2589 & 32768u) == 0u));
                                                                    let _e2595 = ((_e2589 >> bitcast<u32>(10i)) & 31u);
                                                                    local_220 = _e2595;
                                                                    local_221 = (_e2589 & 1023u);
                                                                    if (_e2595 == 0u) {
                                                                        let _e2617 = local_221;
                                                                        let _e2619 = local_575;
                                                                        phi_2075_ = ((_e2619 * f32(_e2617)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2598 = local_220;
                                                                        if (_e2598 == 31u) {
                                                                            let _e2608 = local_221;
                                                                            phi_2072_ = (2139095040u | (_e2608 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2600 = local_220;
                                                                            let _e2604 = local_221;
                                                                            phi_2072_ = (((_e2600 + 112u) << bitcast<u32>(23i)) | (_e2604 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2613 = phi_2072_;
                                                                        let _e2615 = local_575;
                                                                        phi_2075_ = (_e2615 * bitcast<f32>(_e2613));
                                                                    }
                                                                    let _e2623 = phi_2075_;
                                                                    local_222 = _e2623;
                                                                    let _e2624 = local_206;
                                                                    let _e2625 = local_182;
                                                                    let _e2627 = ((_e2624 + _e2625) * 2u);
                                                                    local_223 = _e2627;
                                                                    let _e2628 = local_6;
                                                                    if (_e2627 < _e2628) {
                                                                    } else {
                                                                        phi_5783_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2630 = local_223;
                                                                    let _e2633 = global_9.member[_e2630];
                                                                    local_224 = _e2633;
                                                                    let _e2634 = local_223;
                                                                    let _e2635 = (_e2634 + 1u);
                                                                    local_225 = _e2635;
                                                                    let _e2636 = local_6;
                                                                    if (_e2635 < _e2636) {
                                                                    } else {
                                                                        phi_5783_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2638 = local_225;
                                                                    let _e2641 = global_9.member[_e2638];
                                                                    local_226 = _e2641;
                                                                    let _e2642 = local_224;
                                                                    let _e2643 = (_e2642 & 65535u);
                                                                    local_576 = select(-1f, 1f, ((_e2643 & 32768u) == 0u));
                                                                    let _e2649 = ((_e2643 >> bitcast<u32>(10i)) & 31u);
                                                                    local_227 = _e2649;
                                                                    local_228 = (_e2643 & 1023u);
                                                                    if (_e2649 == 0u) {
                                                                        let _e2671 = local_228;
                                                                        let _e2673 = local_576;
                                                                        phi_2144_ = ((_e2673 * f32(_e2671)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2652 = local_227;
                                                                        if (_e2652 == 31u) {
                                                                            let _e2662 = local_228;
                                                                            phi_2141_ = (2139095040u | (_e2662 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2654 = local_227;
                                                                            let _e2658 = local_228;
                                                                            phi_2141_ = (((_e2654 + 112u) << bitcast<u32>(23i)) | (_e2658 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2667 = phi_2141_;
                                                                        let _e2669 = local_576;
                                                                        phi_2144_ = (_e2669 * bitcast<f32>(_e2667));
                                                                    }
                                                                    let _e2677 = phi_2144_;
                                                                    local_229 = _e2677;
                                                                    let _e2678 = local_224;
                                                                    let _e2680 = (_e2678 >> bitcast<u32>(16i));
                                                                    local_577 = select(-1f, 1f, ((_e2680 & 32768u) == 0u));
                                                                    let _e2686 = ((_e2680 >> bitcast<u32>(10i)) & 31u);
                                                                    local_230 = _e2686;
                                                                    local_231 = (_e2680 & 1023u);
                                                                    if (_e2686 == 0u) {
                                                                        let _e2708 = local_231;
                                                                        let _e2710 = local_577;
                                                                        phi_2176_ = ((_e2710 * f32(_e2708)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2689 = local_230;
                                                                        if (_e2689 == 31u) {
                                                                            let _e2699 = local_231;
                                                                            phi_2173_ = (2139095040u | (_e2699 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2691 = local_230;
                                                                            let _e2695 = local_231;
                                                                            phi_2173_ = (((_e2691 + 112u) << bitcast<u32>(23i)) | (_e2695 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2704 = phi_2173_;
                                                                        let _e2706 = local_577;
                                                                        phi_2176_ = (_e2706 * bitcast<f32>(_e2704));
                                                                    }
                                                                    let _e2714 = phi_2176_;
                                                                    local_232 = _e2714;
                                                                    let _e2715 = local_226;
                                                                    let _e2716 = (_e2715 & 65535u);
                                                                    local_578 = select(-1f, 1f, ((_e2716 & 32768u) == 0u));
                                                                    let _e2722 = ((_e2716 >> bitcast<u32>(10i)) & 31u);
                                                                    local_233 = _e2722;
                                                                    local_234 = (_e2716 & 1023u);
                                                                    if (_e2722 == 0u) {
                                                                        let _e2744 = local_234;
                                                                        let _e2746 = local_578;
                                                                        phi_2208_ = ((_e2746 * f32(_e2744)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2725 = local_233;
                                                                        if (_e2725 == 31u) {
                                                                            let _e2735 = local_234;
                                                                            phi_2205_ = (2139095040u | (_e2735 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2727 = local_233;
                                                                            let _e2731 = local_234;
                                                                            phi_2205_ = (((_e2727 + 112u) << bitcast<u32>(23i)) | (_e2731 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2740 = phi_2205_;
                                                                        let _e2742 = local_578;
                                                                        phi_2208_ = (_e2742 * bitcast<f32>(_e2740));
                                                                    }
                                                                    let _e2750 = phi_2208_;
                                                                    local_235 = _e2750;
                                                                    let _e2751 = local_226;
                                                                    let _e2753 = (_e2751 >> bitcast<u32>(16i));
                                                                    local_579 = select(-1f, 1f, ((_e2753 & 32768u) == 0u));
                                                                    let _e2759 = ((_e2753 >> bitcast<u32>(10i)) & 31u);
                                                                    local_236 = _e2759;
                                                                    local_237 = (_e2753 & 1023u);
                                                                    if (_e2759 == 0u) {
                                                                        let _e2781 = local_237;
                                                                        let _e2783 = local_579;
                                                                        phi_2240_ = ((_e2783 * f32(_e2781)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2762 = local_236;
                                                                        if (_e2762 == 31u) {
                                                                            let _e2772 = local_237;
                                                                            phi_2237_ = (2139095040u | (_e2772 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2764 = local_236;
                                                                            let _e2768 = local_237;
                                                                            phi_2237_ = (((_e2764 + 112u) << bitcast<u32>(23i)) | (_e2768 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2777 = phi_2237_;
                                                                        let _e2779 = local_579;
                                                                        phi_2240_ = (_e2779 * bitcast<f32>(_e2777));
                                                                    }
                                                                    let _e2787 = phi_2240_;
                                                                    let _e2788 = local_229;
                                                                    let _e2789 = local_213;
                                                                    let _e2791 = local_158;
                                                                    let _e2793 = local_213;
                                                                    local_238 = (_e2793 + ((_e2788 - _e2789) * _e2791));
                                                                    let _e2795 = local_232;
                                                                    let _e2796 = local_216;
                                                                    let _e2798 = local_158;
                                                                    let _e2800 = local_216;
                                                                    local_239 = (_e2800 + ((_e2795 - _e2796) * _e2798));
                                                                    let _e2802 = local_235;
                                                                    let _e2803 = local_219;
                                                                    let _e2805 = local_158;
                                                                    let _e2807 = local_219;
                                                                    local_240 = (_e2807 + ((_e2802 - _e2803) * _e2805));
                                                                    let _e2809 = local_222;
                                                                    let _e2811 = local_158;
                                                                    let _e2813 = local_222;
                                                                    local_241 = (_e2813 + ((_e2787 - _e2809) * _e2811));
                                                                    let _e2815 = local_204;
                                                                    let _e2816 = local_151;
                                                                    let _e2818 = local_205;
                                                                    let _e2819 = (_e2818 + (_e2815 * _e2816));
                                                                    local_242 = _e2819;
                                                                    let _e2820 = local_172;
                                                                    let _e2822 = ((_e2819 + _e2820) * 2u);
                                                                    local_243 = _e2822;
                                                                    let _e2823 = local_6;
                                                                    if (_e2822 < _e2823) {
                                                                    } else {
                                                                        phi_5783_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2825 = local_243;
                                                                    let _e2828 = global_9.member[_e2825];
                                                                    local_244 = _e2828;
                                                                    let _e2829 = local_243;
                                                                    let _e2830 = (_e2829 + 1u);
                                                                    local_245 = _e2830;
                                                                    let _e2831 = local_6;
                                                                    if (_e2830 < _e2831) {
                                                                    } else {
                                                                        phi_5783_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2833 = local_245;
                                                                    let _e2836 = global_9.member[_e2833];
                                                                    local_246 = _e2836;
                                                                    let _e2837 = local_244;
                                                                    let _e2838 = (_e2837 & 65535u);
                                                                    local_580 = select(-1f, 1f, ((_e2838 & 32768u) == 0u));
                                                                    let _e2844 = ((_e2838 >> bitcast<u32>(10i)) & 31u);
                                                                    local_247 = _e2844;
                                                                    local_248 = (_e2838 & 1023u);
                                                                    if (_e2844 == 0u) {
                                                                        let _e2866 = local_248;
                                                                        let _e2868 = local_580;
                                                                        phi_2321_ = ((_e2868 * f32(_e2866)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2847 = local_247;
                                                                        if (_e2847 == 31u) {
                                                                            let _e2857 = local_248;
                                                                            phi_2318_ = (2139095040u | (_e2857 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2849 = local_247;
                                                                            let _e2853 = local_248;
                                                                            phi_2318_ = (((_e2849 + 112u) << bitcast<u32>(23i)) | (_e2853 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2862 = phi_2318_;
                                                                        let _e2864 = local_580;
                                                                        phi_2321_ = (_e2864 * bitcast<f32>(_e2862));
                                                                    }
                                                                    let _e2872 = phi_2321_;
                                                                    local_249 = _e2872;
                                                                    let _e2873 = local_244;
                                                                    let _e2875 = (_e2873 >> bitcast<u32>(16i));
                                                                    local_581 = select(-1f, 1f, ((_e2875 & 32768u) == 0u));
                                                                    let _e2881 = ((_e2875 >> bitcast<u32>(10i)) & 31u);
                                                                    local_250 = _e2881;
                                                                    local_251 = (_e2875 & 1023u);
                                                                    if (_e2881 == 0u) {
                                                                        let _e2903 = local_251;
                                                                        let _e2905 = local_581;
                                                                        phi_2353_ = ((_e2905 * f32(_e2903)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2884 = local_250;
                                                                        if (_e2884 == 31u) {
                                                                            let _e2894 = local_251;
                                                                            phi_2350_ = (2139095040u | (_e2894 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2886 = local_250;
                                                                            let _e2890 = local_251;
                                                                            phi_2350_ = (((_e2886 + 112u) << bitcast<u32>(23i)) | (_e2890 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2899 = phi_2350_;
                                                                        let _e2901 = local_581;
                                                                        phi_2353_ = (_e2901 * bitcast<f32>(_e2899));
                                                                    }
                                                                    let _e2909 = phi_2353_;
                                                                    local_252 = _e2909;
                                                                    let _e2910 = local_246;
                                                                    let _e2911 = (_e2910 & 65535u);
                                                                    local_582 = select(-1f, 1f, ((_e2911 & 32768u) == 0u));
                                                                    let _e2917 = ((_e2911 >> bitcast<u32>(10i)) & 31u);
                                                                    local_253 = _e2917;
                                                                    local_254 = (_e2911 & 1023u);
                                                                    if (_e2917 == 0u) {
                                                                        let _e2939 = local_254;
                                                                        let _e2941 = local_582;
                                                                        phi_2385_ = ((_e2941 * f32(_e2939)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2920 = local_253;
                                                                        if (_e2920 == 31u) {
                                                                            let _e2930 = local_254;
                                                                            phi_2382_ = (2139095040u | (_e2930 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2922 = local_253;
                                                                            let _e2926 = local_254;
                                                                            phi_2382_ = (((_e2922 + 112u) << bitcast<u32>(23i)) | (_e2926 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2935 = phi_2382_;
                                                                        let _e2937 = local_582;
                                                                        phi_2385_ = (_e2937 * bitcast<f32>(_e2935));
                                                                    }
                                                                    let _e2945 = phi_2385_;
                                                                    local_255 = _e2945;
                                                                    let _e2946 = local_246;
                                                                    let _e2948 = (_e2946 >> bitcast<u32>(16i));
                                                                    local_583 = select(-1f, 1f, ((_e2948 & 32768u) == 0u));
                                                                    let _e2954 = ((_e2948 >> bitcast<u32>(10i)) & 31u);
                                                                    local_256 = _e2954;
                                                                    local_257 = (_e2948 & 1023u);
                                                                    if (_e2954 == 0u) {
                                                                        let _e2976 = local_257;
                                                                        let _e2978 = local_583;
                                                                        phi_2417_ = ((_e2978 * f32(_e2976)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2957 = local_256;
                                                                        if (_e2957 == 31u) {
                                                                            let _e2967 = local_257;
                                                                            phi_2414_ = (2139095040u | (_e2967 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2959 = local_256;
                                                                            let _e2963 = local_257;
                                                                            phi_2414_ = (((_e2959 + 112u) << bitcast<u32>(23i)) | (_e2963 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2972 = phi_2414_;
                                                                        let _e2974 = local_583;
                                                                        phi_2417_ = (_e2974 * bitcast<f32>(_e2972));
                                                                    }
                                                                    let _e2982 = phi_2417_;
                                                                    local_258 = _e2982;
                                                                    let _e2983 = local_242;
                                                                    let _e2984 = local_182;
                                                                    let _e2986 = ((_e2983 + _e2984) * 2u);
                                                                    local_259 = _e2986;
                                                                    let _e2987 = local_6;
                                                                    if (_e2986 < _e2987) {
                                                                    } else {
                                                                        phi_5783_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2989 = local_259;
                                                                    let _e2992 = global_9.member[_e2989];
                                                                    local_260 = _e2992;
                                                                    let _e2993 = local_259;
                                                                    let _e2994 = (_e2993 + 1u);
                                                                    local_261 = _e2994;
                                                                    let _e2995 = local_6;
                                                                    if (_e2994 < _e2995) {
                                                                    } else {
                                                                        phi_5783_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2997 = local_261;
                                                                    let _e3000 = global_9.member[_e2997];
                                                                    local_262 = _e3000;
                                                                    let _e3001 = local_260;
                                                                    let _e3002 = (_e3001 & 65535u);
                                                                    local_584 = select(-1f, 1f, ((_e3002 & 32768u) == 0u));
                                                                    let _e3008 = ((_e3002 >> bitcast<u32>(10i)) & 31u);
                                                                    local_263 = _e3008;
                                                                    local_264 = (_e3002 & 1023u);
                                                                    if (_e3008 == 0u) {
                                                                        let _e3030 = local_264;
                                                                        let _e3032 = local_584;
                                                                        phi_2486_ = ((_e3032 * f32(_e3030)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3011 = local_263;
                                                                        if (_e3011 == 31u) {
                                                                            let _e3021 = local_264;
                                                                            phi_2483_ = (2139095040u | (_e3021 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3013 = local_263;
                                                                            let _e3017 = local_264;
                                                                            phi_2483_ = (((_e3013 + 112u) << bitcast<u32>(23i)) | (_e3017 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3026 = phi_2483_;
                                                                        let _e3028 = local_584;
                                                                        phi_2486_ = (_e3028 * bitcast<f32>(_e3026));
                                                                    }
                                                                    let _e3036 = phi_2486_;
                                                                    local_265 = _e3036;
                                                                    let _e3037 = local_260;
                                                                    let _e3039 = (_e3037 >> bitcast<u32>(16i));
                                                                    local_585 = select(-1f, 1f, ((_e3039 & 32768u) == 0u));
                                                                    let _e3045 = ((_e3039 >> bitcast<u32>(10i)) & 31u);
                                                                    local_266 = _e3045;
                                                                    local_267 = (_e3039 & 1023u);
                                                                    if (_e3045 == 0u) {
                                                                        let _e3067 = local_267;
                                                                        let _e3069 = local_585;
                                                                        phi_2518_ = ((_e3069 * f32(_e3067)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3048 = local_266;
                                                                        if (_e3048 == 31u) {
                                                                            let _e3058 = local_267;
                                                                            phi_2515_ = (2139095040u | (_e3058 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3050 = local_266;
                                                                            let _e3054 = local_267;
                                                                            phi_2515_ = (((_e3050 + 112u) << bitcast<u32>(23i)) | (_e3054 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3063 = phi_2515_;
                                                                        let _e3065 = local_585;
                                                                        phi_2518_ = (_e3065 * bitcast<f32>(_e3063));
                                                                    }
                                                                    let _e3073 = phi_2518_;
                                                                    local_268 = _e3073;
                                                                    let _e3074 = local_262;
                                                                    let _e3075 = (_e3074 & 65535u);
                                                                    local_586 = select(-1f, 1f, ((_e3075 & 32768u) == 0u));
                                                                    let _e3081 = ((_e3075 >> bitcast<u32>(10i)) & 31u);
                                                                    local_269 = _e3081;
                                                                    local_270 = (_e3075 & 1023u);
                                                                    if (_e3081 == 0u) {
                                                                        let _e3103 = local_270;
                                                                        let _e3105 = local_586;
                                                                        phi_2550_ = ((_e3105 * f32(_e3103)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3084 = local_269;
                                                                        if (_e3084 == 31u) {
                                                                            let _e3094 = local_270;
                                                                            phi_2547_ = (2139095040u | (_e3094 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3086 = local_269;
                                                                            let _e3090 = local_270;
                                                                            phi_2547_ = (((_e3086 + 112u) << bitcast<u32>(23i)) | (_e3090 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3099 = phi_2547_;
                                                                        let _e3101 = local_586;
                                                                        phi_2550_ = (_e3101 * bitcast<f32>(_e3099));
                                                                    }
                                                                    let _e3109 = phi_2550_;
                                                                    local_271 = _e3109;
                                                                    let _e3110 = local_262;
                                                                    let _e3112 = (_e3110 >> bitcast<u32>(16i));
                                                                    local_587 = select(-1f, 1f, ((_e3112 & 32768u) == 0u));
                                                                    let _e3118 = ((_e3112 >> bitcast<u32>(10i)) & 31u);
                                                                    local_272 = _e3118;
                                                                    local_273 = (_e3112 & 1023u);
                                                                    if (_e3118 == 0u) {
                                                                        let _e3140 = local_273;
                                                                        let _e3142 = local_587;
                                                                        phi_2582_ = ((_e3142 * f32(_e3140)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3121 = local_272;
                                                                        if (_e3121 == 31u) {
                                                                            let _e3131 = local_273;
                                                                            phi_2579_ = (2139095040u | (_e3131 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3123 = local_272;
                                                                            let _e3127 = local_273;
                                                                            phi_2579_ = (((_e3123 + 112u) << bitcast<u32>(23i)) | (_e3127 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3136 = phi_2579_;
                                                                        let _e3138 = local_587;
                                                                        phi_2582_ = (_e3138 * bitcast<f32>(_e3136));
                                                                    }
                                                                    let _e3146 = phi_2582_;
                                                                    let _e3147 = local_265;
                                                                    let _e3148 = local_249;
                                                                    let _e3150 = local_158;
                                                                    let _e3152 = local_249;
                                                                    let _e3154 = local_268;
                                                                    let _e3155 = local_252;
                                                                    let _e3157 = local_158;
                                                                    let _e3159 = local_252;
                                                                    let _e3161 = local_271;
                                                                    let _e3162 = local_255;
                                                                    let _e3164 = local_158;
                                                                    let _e3166 = local_255;
                                                                    let _e3168 = local_258;
                                                                    let _e3170 = local_158;
                                                                    let _e3172 = local_258;
                                                                    let _e3174 = local_238;
                                                                    let _e3176 = local_157;
                                                                    let _e3178 = local_238;
                                                                    let _e3180 = local_239;
                                                                    let _e3182 = local_157;
                                                                    let _e3184 = local_239;
                                                                    let _e3186 = local_240;
                                                                    let _e3188 = local_157;
                                                                    let _e3190 = local_240;
                                                                    let _e3192 = local_241;
                                                                    let _e3194 = local_157;
                                                                    let _e3196 = local_241;
                                                                    let _e3198 = local_150;
                                                                    let _e3200 = local_150;
                                                                    let _e3202 = local_150;
                                                                    let _e3204 = local_150;
                                                                    let _e3206 = local_147;
                                                                    let _e3209 = local_147;
                                                                    let _e3212 = local_147;
                                                                    let _e3215 = local_147;
                                                                    let _e3219 = local_146;
                                                                    phi_1537_ = (_e3219 + 1u);
                                                                    phi_1540_ = type_5((_e3206.member + ((_e3178 + (((_e3152 + ((_e3147 - _e3148) * _e3150)) - _e3174) * _e3176)) * _e3198)), (_e3209.member_1 + ((_e3184 + (((_e3159 + ((_e3154 - _e3155) * _e3157)) - _e3180) * _e3182)) * _e3200)), (_e3212.member_2 + ((_e3190 + (((_e3166 + ((_e3161 - _e3162) * _e3164)) - _e3186) * _e3188)) * _e3202)), (_e3215.member_3 + ((_e3196 + (((_e3172 + ((_e3146 - _e3168) * _e3170)) - _e3192) * _e3194)) * _e3204)));
                                                                } else {
                                                                    phi_1537_ = u32();
                                                                    phi_1540_ = type_5();
                                                                }
                                                                let _e3222 = phi_1537_;
                                                                let _e3224 = phi_1540_;
                                                                continue;
                                                                continuing {
                                                                    let _e3225 = local_148;
                                                                    phi_1536_ = _e3222;
                                                                    phi_1539_ = _e3224;
                                                                    phi_5783_ = _e2074;
                                                                    break if !(_e3225);
                                                                }
                                                            }
                                                            let _e3228 = phi_5783_;
                                                            phi_5901_ = _e3228;
                                                            if _e3228 {
                                                                break;
                                                            }
                                                            let _e3229 = local_142;
                                                            phi_5902_ = _e3228;
                                                            phi_1508_ = (_e3229 + 1u);
                                                            let _e5665 = local_634;
                                                            phi_1511_ = _e5665;
                                                        } else {
                                                            phi_5902_ = _e2074;
                                                            phi_1508_ = u32();
                                                            phi_1511_ = type_5();
                                                        }
                                                        let _e3232 = phi_5902_;
                                                        let _e3234 = phi_1508_;
                                                        let _e3236 = phi_1511_;
                                                        continue;
                                                        continuing {
                                                            let _e3237 = local_143;
                                                            phi_5829_ = _e3232;
                                                            phi_1507_ = _e3234;
                                                            phi_1510_ = _e3236;
                                                            phi_5901_ = _e3232;
                                                            break if !(_e3237);
                                                        }
                                                    }
                                                    let _e3240 = phi_5901_;
                                                    phi_5903_ = _e3240;
                                                    if _e3240 {
                                                        break;
                                                    }
                                                    let _e3241 = local_138;
                                                    phi_5904_ = _e3240;
                                                    phi_1491_ = (_e3241 + 1u);
                                                    let _e5671 = local_635;
                                                    phi_1494_ = _e5671;
                                                } else {
                                                    phi_5904_ = _e2058;
                                                    phi_1491_ = u32();
                                                    phi_1494_ = type_5();
                                                }
                                                let _e3244 = phi_5904_;
                                                let _e3246 = phi_1491_;
                                                let _e3248 = phi_1494_;
                                                continue;
                                                continuing {
                                                    let _e3249 = local_140;
                                                    phi_5830_ = _e3244;
                                                    phi_1490_ = _e3246;
                                                    phi_1493_ = _e3248;
                                                    phi_5903_ = _e3244;
                                                    break if !(_e3249);
                                                }
                                            }
                                            let _e3252 = phi_5903_;
                                            phi_6062_ = _e3252;
                                            if _e3252 {
                                                break;
                                            }
                                            let _e3253 = local_129;
                                            let _e3254 = local_128;
                                            let _e3257 = (1f / f32((_e3253 * _e3254)));
                                            let _e3258 = local_139;
                                            let _e3261 = local_139;
                                            let _e3264 = local_139;
                                            let _e3267 = local_139;
                                            phi_5982_ = _e3252;
                                            phi_2635_ = type_5((_e3258.member * _e3257), (_e3261.member_1 * _e3257), (_e3264.member_2 * _e3257), (_e3267.member_3 * _e3257));
                                        }
                                        let _e3272 = phi_5982_;
                                        let _e3274 = phi_2635_;
                                        phi_5981_ = _e3272;
                                        phi_2636_ = _e3274;
                                        phi_2637_ = _e1689;
                                    }
                                    let _e3276 = phi_5981_;
                                    let _e3278 = phi_2636_;
                                    let _e3280 = phi_2637_;
                                    if _e3280 {
                                        phi_2641_ = type_5(1f, 1f, 1f, 1f);
                                    } else {
                                        phi_2641_ = _e3278;
                                    }
                                    let _e3282 = phi_2641_;
                                    phi_5979_ = _e3276;
                                    phi_2642_ = _e3282;
                                }
                                let _e3284 = phi_5979_;
                                let _e3286 = phi_2642_;
                                phi_5978_ = _e3284;
                                phi_2643_ = _e3286;
                                phi_2644_ = _e1653;
                            }
                            let _e3288 = phi_5978_;
                            let _e3290 = phi_2643_;
                            let _e3292 = phi_2644_;
                            if _e3292 {
                                phi_2648_ = type_5(1f, 1f, 1f, 1f);
                            } else {
                                phi_2648_ = _e3290;
                            }
                            let _e3294 = phi_2648_;
                            local_627 = array<f32, 4>(_e3294.member, _e3294.member_1, _e3294.member_2, _e3294.member_3);
                            let _e3300 = local_87;
                            if (_e3300 == 4294967295u) {
                                phi_6037_ = _e3288;
                                phi_4155_ = type_5();
                                phi_4156_ = true;
                            } else {
                                let _e3302 = local_87;
                                let _e3303 = local_25;
                                let _e3304 = (_e3302 >= _e3303);
                                if _e3304 {
                                    phi_6038_ = _e3288;
                                    phi_4154_ = type_5();
                                } else {
                                    let _e3305 = local_87;
                                    let _e3306 = (_e3305 * 4u);
                                    local_274 = _e3306;
                                    let _e3307 = local_5;
                                    if (_e3306 < _e3307) {
                                    } else {
                                        phi_6062_ = true;
                                        break;
                                    }
                                    let _e3309 = local_274;
                                    let _e3312 = global_8.member[_e3309];
                                    local_275 = _e3312;
                                    let _e3313 = local_274;
                                    let _e3314 = (_e3313 + 1u);
                                    local_276 = _e3314;
                                    let _e3315 = local_5;
                                    if (_e3314 < _e3315) {
                                    } else {
                                        phi_6062_ = true;
                                        break;
                                    }
                                    let _e3317 = local_276;
                                    let _e3320 = global_8.member[_e3317];
                                    local_277 = _e3320;
                                    let _e3321 = local_274;
                                    let _e3322 = (_e3321 + 2u);
                                    local_278 = _e3322;
                                    let _e3323 = local_5;
                                    if (_e3322 < _e3323) {
                                    } else {
                                        phi_6062_ = true;
                                        break;
                                    }
                                    let _e3325 = local_278;
                                    let _e3328 = global_8.member[_e3325];
                                    local_279 = _e3328;
                                    let _e3329 = local_274;
                                    let _e3330 = (_e3329 + 3u);
                                    local_280 = _e3330;
                                    let _e3331 = local_5;
                                    if (_e3330 < _e3331) {
                                    } else {
                                        phi_6062_ = true;
                                        break;
                                    }
                                    let _e3333 = local_280;
                                    let _e3336 = global_8.member[_e3333];
                                    local_281 = _e3336;
                                    let _e3337 = local_277;
                                    if (_e3337 == 0u) {
                                        phi_6040_ = _e3288;
                                        phi_4148_ = type_5();
                                        phi_4149_ = true;
                                    } else {
                                        let _e3339 = local_279;
                                        let _e3340 = (_e3339 == 0u);
                                        if _e3340 {
                                            phi_6041_ = _e3288;
                                            phi_4147_ = type_5();
                                        } else {
                                            let _e3341 = local_281;
                                            let _e3344 = ((_e3341 >> bitcast<u32>(8u)) & 31u);
                                            local_588 = select(_e3344, 1u, (_e3344 == 0u));
                                            let _e3347 = local_281;
                                            let _e3351 = local_281;
                                            let _e3355 = local_275;
                                            let _e3356 = local_277;
                                            let _e3357 = local_279;
                                            let _e3358 = type_22(_e3355, _e3356, _e3357, ((_e3347 >> bitcast<u32>(1u)) & 3u), ((_e3351 >> bitcast<u32>(3u)) & 3u));
                                            let _e3359 = local_277;
                                            let _e3360 = f32(_e3359);
                                            local_282 = _e3360;
                                            let _e3361 = local_76;
                                            if ((bitcast<u32>((_e3361 * _e3360)) & 2139095040u) != 2139095040u) {
                                                let _e3366 = local_279;
                                                let _e3368 = local_75;
                                                phi_2768_ = select(true, false, ((bitcast<u32>((_e3368 * f32(_e3366))) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_2768_ = true;
                                            }
                                            let _e3375 = phi_2768_;
                                            let _e3376 = local_75;
                                            local_589 = select(_e3376, 0f, _e3375);
                                            let _e3378 = local_76;
                                            local_590 = select(_e3378, 0f, _e3375);
                                            let _e3380 = local_103;
                                            local_283 = _e3380.member;
                                            let _e3382 = local_282;
                                            let _e3383 = (_e3380.member * _e3382);
                                            let _e3384 = local_103;
                                            local_284 = _e3384.member_1;
                                            let _e3386 = local_279;
                                            let _e3387 = f32(_e3386);
                                            let _e3388 = (_e3384.member_1 * _e3387);
                                            let _e3389 = local_103;
                                            local_285 = _e3389.member_2;
                                            let _e3391 = local_282;
                                            let _e3392 = (_e3389.member_2 * _e3391);
                                            let _e3393 = local_103;
                                            local_286 = _e3393.member_3;
                                            let _e3395 = (_e3393.member_3 * _e3387);
                                            let _e3399 = sqrt(((_e3383 * _e3383) + (_e3388 * _e3388)));
                                            local_287 = _e3399;
                                            let _e3403 = sqrt(((_e3392 * _e3392) + (_e3395 * _e3395)));
                                            local_288 = _e3403;
                                            let _e3405 = select(_e3403, _e3399, (_e3399 > _e3403));
                                            local_591 = _e3405;
                                            if (_e3405 > 1f) {
                                                let _e3407 = local_591;
                                                phi_2807_ = !(((bitcast<u32>(_e3407) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_2807_ = true;
                                            }
                                            let _e3413 = phi_2807_;
                                            local_289 = _e3413;
                                            let _e3414 = local_564;
                                            let _e3416 = local_564;
                                            local_592 = select(64u, _e3416, (_e3414 < 64u));
                                            phi_2814_ = 1u;
                                            loop {
                                                let _e3419 = phi_2814_;
                                                local_290 = _e3419;
                                                let _e3420 = local_290;
                                                if (_e3420 < 8u) {
                                                    let _e3422 = local_290;
                                                    let _e3423 = (_e3422 + 1u);
                                                    let _e3425 = local_592;
                                                    let _e3426 = ((_e3423 * _e3423) <= _e3425);
                                                    phi_2815_ = select(u32(), _e3423, _e3426);
                                                    phi_2832_ = _e3426;
                                                } else {
                                                    phi_2815_ = u32();
                                                    phi_2832_ = false;
                                                }
                                                let _e3429 = phi_2815_;
                                                let _e3431 = phi_2832_;
                                                local_291 = _e3431;
                                                continue;
                                                continuing {
                                                    let _e3432 = local_291;
                                                    phi_2814_ = _e3429;
                                                    break if !(_e3432);
                                                }
                                            }
                                            let _e3434 = local_289;
                                            if _e3434 {
                                                phi_2932_ = 1u;
                                                phi_2933_ = 1u;
                                            } else {
                                                let _e3435 = local_287;
                                                let _e3436 = local_288;
                                                if (_e3435 >= _e3436) {
                                                    let _e3479 = local_290;
                                                    let _e3480 = f32(_e3479);
                                                    let _e3481 = local_288;
                                                    let _e3483 = local_288;
                                                    let _e3485 = ceil(select(_e3480, _e3483, (_e3481 < _e3480)));
                                                    local_292 = _e3485;
                                                    if (_e3485 < 1f) {
                                                        phi_2862_ = 1u;
                                                    } else {
                                                        let _e3487 = local_292;
                                                        let _e3489 = local_292;
                                                        let _e3492 = local_292;
                                                        phi_2862_ = select(select(u32(_e3487), 0u, !((_e3489 >= 0f))), 4294967295u, (_e3492 > 4294967000f));
                                                    }
                                                    let _e3497 = phi_2862_;
                                                    local_293 = _e3497;
                                                    if (_e3497 == 0u) {
                                                        phi_6062_ = true;
                                                        break;
                                                    }
                                                    let _e3499 = local_592;
                                                    let _e3500 = local_293;
                                                    let _e3502 = f32((_e3499 / _e3500));
                                                    let _e3503 = local_287;
                                                    let _e3505 = local_287;
                                                    let _e3507 = ceil(select(_e3502, _e3505, (_e3503 < _e3502)));
                                                    local_294 = _e3507;
                                                    if (_e3507 < 1f) {
                                                        phi_2886_ = 1u;
                                                    } else {
                                                        let _e3509 = local_294;
                                                        let _e3511 = local_294;
                                                        let _e3514 = local_294;
                                                        phi_2886_ = select(select(u32(_e3509), 0u, !((_e3511 >= 0f))), 4294967295u, (_e3514 > 4294967000f));
                                                    }
                                                    let _e3519 = phi_2886_;
                                                    phi_2930_ = _e3497;
                                                    phi_2931_ = _e3519;
                                                } else {
                                                    let _e3438 = local_290;
                                                    let _e3439 = f32(_e3438);
                                                    let _e3440 = local_287;
                                                    let _e3442 = local_287;
                                                    let _e3444 = ceil(select(_e3439, _e3442, (_e3440 < _e3439)));
                                                    local_295 = _e3444;
                                                    if (_e3444 < 1f) {
                                                        phi_2905_ = 1u;
                                                    } else {
                                                        let _e3446 = local_295;
                                                        let _e3448 = local_295;
                                                        let _e3451 = local_295;
                                                        phi_2905_ = select(select(u32(_e3446), 0u, !((_e3448 >= 0f))), 4294967295u, (_e3451 > 4294967000f));
                                                    }
                                                    let _e3456 = phi_2905_;
                                                    local_296 = _e3456;
                                                    if (_e3456 == 0u) {
                                                        phi_6062_ = true;
                                                        break;
                                                    }
                                                    let _e3458 = local_592;
                                                    let _e3459 = local_296;
                                                    let _e3461 = f32((_e3458 / _e3459));
                                                    let _e3462 = local_288;
                                                    let _e3464 = local_288;
                                                    let _e3466 = ceil(select(_e3461, _e3464, (_e3462 < _e3461)));
                                                    local_297 = _e3466;
                                                    if (_e3466 < 1f) {
                                                        phi_2929_ = 1u;
                                                    } else {
                                                        let _e3468 = local_297;
                                                        let _e3470 = local_297;
                                                        let _e3473 = local_297;
                                                        phi_2929_ = select(select(u32(_e3468), 0u, !((_e3470 >= 0f))), 4294967295u, (_e3473 > 4294967000f));
                                                    }
                                                    let _e3478 = phi_2929_;
                                                    phi_2930_ = _e3478;
                                                    phi_2931_ = _e3456;
                                                }
                                                let _e3521 = phi_2930_;
                                                let _e3523 = phi_2931_;
                                                phi_2932_ = _e3521;
                                                phi_2933_ = _e3523;
                                            }
                                            let _e3525 = phi_2932_;
                                            let _e3527 = phi_2933_;
                                            local_298 = _e3525;
                                            local_299 = _e3527;
                                            let _e3528 = local_289;
                                            if _e3528 {
                                                phi_2946_ = 1f;
                                            } else {
                                                let _e3529 = local_299;
                                                let _e3531 = local_287;
                                                let _e3532 = (_e3531 / f32(_e3529));
                                                let _e3533 = local_298;
                                                let _e3535 = local_288;
                                                let _e3536 = (_e3535 / f32(_e3533));
                                                phi_2946_ = select(_e3536, _e3532, (_e3532 > _e3536));
                                            }
                                            let _e3540 = phi_2946_;
                                            local_300 = _e3540;
                                            if (_e3540 > 1f) {
                                                let _e3542 = local_300;
                                                let _e3543 = bitcast<u32>(_e3542);
                                                let _e3552 = (bitcast<f32>(((_e3543 & 8388607u) | 1065353216u)) - 1f);
                                                phi_2967_ = (f32((bitcast<i32>(((_e3543 >> bitcast<u32>(23i)) & 255u)) - 127i)) + (_e3552 * (1.4208645f + (_e3552 * (-0.5772506f + (_e3552 * 0.1563861f))))));
                                            } else {
                                                phi_2967_ = 0f;
                                            }
                                            let _e3561 = phi_2967_;
                                            local_301 = _e3561;
                                            let _e3562 = local_588;
                                            let _e3563 = (_e3562 - 1u);
                                            local_302 = _e3563;
                                            let _e3564 = floor(_e3561);
                                            let _e3570 = select(select(u32(_e3564), 0u, !((_e3564 >= 0f))), 4294967295u, (_e3564 > 4294967000f));
                                            local_303 = _e3570;
                                            let _e3571 = (_e3570 >= _e3563);
                                            local_304 = _e3571;
                                            if _e3571 {
                                                phi_2983_ = 0f;
                                            } else {
                                                let _e3572 = local_303;
                                                let _e3574 = local_301;
                                                phi_2983_ = (_e3574 - f32(_e3572));
                                            }
                                            let _e3577 = phi_2983_;
                                            local_305 = _e3577;
                                            let _e3578 = local_304;
                                            let _e3579 = local_302;
                                            let _e3580 = local_303;
                                            local_593 = select(_e3580, _e3579, _e3578);
                                            local_594 = select(1u, 2u, (_e3577 > 0f));
                                            phi_5661_ = 0u;
                                            phi_5662_ = _e3358;
                                            loop {
                                                let _e3585 = phi_5661_;
                                                let _e3587 = phi_5662_;
                                                local_550 = _e3585;
                                                local_551 = _e3587;
                                                local_636 = _e3587;
                                                let _e3588 = local_550;
                                                let _e3589 = local_593;
                                                let _e3590 = (_e3588 < _e3589);
                                                local_552 = _e3590;
                                                if _e3590 {
                                                    let _e3591 = local_551;
                                                    local_553 = _e3591.member_1;
                                                    let _e3593 = local_551;
                                                    local_554 = _e3593.member_2;
                                                    let _e3596 = local_551;
                                                    let _e3599 = local_551;
                                                    local_555 = type_22((_e3596.member + (_e3591.member_1 * _e3593.member_2)), _e3599.member_1, _e3599.member_2, _e3599.member_3, _e3599.member_4);
                                                    if (_e3591.member_1 > 1u) {
                                                        let _e3607 = local_553;
                                                        phi_5679_ = (_e3607 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5679_ = 1u;
                                                    }
                                                    let _e3611 = phi_5679_;
                                                    let _e3612 = local_555;
                                                    local_556 = type_22(_e3612.member, _e3611, _e3612.member_2, _e3612.member_3, _e3612.member_4);
                                                    let _e3619 = local_554;
                                                    if (_e3619 > 1u) {
                                                        let _e3621 = local_554;
                                                        phi_5688_ = (_e3621 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5688_ = 1u;
                                                    }
                                                    let _e3625 = phi_5688_;
                                                    let _e3626 = local_556;
                                                    let _e3633 = local_550;
                                                    phi_5693_ = (_e3633 + 1u);
                                                    phi_5694_ = type_22(_e3626.member, _e3626.member_1, _e3625, _e3626.member_3, _e3626.member_4);
                                                } else {
                                                    phi_5693_ = u32();
                                                    phi_5694_ = type_22();
                                                }
                                                let _e3636 = phi_5693_;
                                                let _e3638 = phi_5694_;
                                                continue;
                                                continuing {
                                                    let _e3639 = local_552;
                                                    phi_5661_ = _e3636;
                                                    phi_5662_ = _e3638;
                                                    break if !(_e3639);
                                                }
                                            }
                                            let _e3641 = local_593;
                                            let _e3642 = local_594;
                                            local_306 = ((_e3641 + _e3642) - 1u);
                                            phi_5700_ = 0u;
                                            phi_5701_ = _e3358;
                                            loop {
                                                let _e3646 = phi_5700_;
                                                let _e3648 = phi_5701_;
                                                local_557 = _e3646;
                                                local_558 = _e3648;
                                                local_637 = _e3648;
                                                let _e3649 = local_557;
                                                let _e3650 = local_306;
                                                let _e3651 = (_e3649 < _e3650);
                                                local_559 = _e3651;
                                                if _e3651 {
                                                    let _e3652 = local_558;
                                                    local_560 = _e3652.member_1;
                                                    let _e3654 = local_558;
                                                    local_561 = _e3654.member_2;
                                                    let _e3657 = local_558;
                                                    let _e3660 = local_558;
                                                    local_562 = type_22((_e3657.member + (_e3652.member_1 * _e3654.member_2)), _e3660.member_1, _e3660.member_2, _e3660.member_3, _e3660.member_4);
                                                    if (_e3652.member_1 > 1u) {
                                                        let _e3668 = local_560;
                                                        phi_5718_ = (_e3668 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5718_ = 1u;
                                                    }
                                                    let _e3672 = phi_5718_;
                                                    let _e3673 = local_562;
                                                    local_563 = type_22(_e3673.member, _e3672, _e3673.member_2, _e3673.member_3, _e3673.member_4);
                                                    let _e3680 = local_561;
                                                    if (_e3680 > 1u) {
                                                        let _e3682 = local_561;
                                                        phi_5727_ = (_e3682 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5727_ = 1u;
                                                    }
                                                    let _e3686 = phi_5727_;
                                                    let _e3687 = local_563;
                                                    let _e3694 = local_557;
                                                    phi_5732_ = (_e3694 + 1u);
                                                    phi_5733_ = type_22(_e3687.member, _e3687.member_1, _e3686, _e3687.member_3, _e3687.member_4);
                                                } else {
                                                    phi_5732_ = u32();
                                                    phi_5733_ = type_22();
                                                }
                                                let _e3697 = phi_5732_;
                                                let _e3699 = phi_5733_;
                                                continue;
                                                continuing {
                                                    let _e3700 = local_559;
                                                    phi_5700_ = _e3697;
                                                    phi_5701_ = _e3699;
                                                    break if !(_e3700);
                                                }
                                            }
                                            let _e3702 = local_289;
                                            if _e3702 {
                                                let _e3703 = local_281;
                                                phi_2999_ = ((_e3703 & 1u) != 0u);
                                            } else {
                                                phi_2999_ = false;
                                            }
                                            let _e3707 = phi_2999_;
                                            local_307 = _e3707;
                                            phi_5952_ = _e3288;
                                            phi_3002_ = 0u;
                                            phi_3005_ = type_5(0f, 0f, 0f, 0f);
                                            loop {
                                                let _e3709 = phi_5952_;
                                                let _e3711 = phi_3002_;
                                                let _e3713 = phi_3005_;
                                                local_308 = _e3711;
                                                local_309 = _e3713;
                                                let _e3714 = local_308;
                                                let _e3715 = local_299;
                                                let _e3716 = (_e3714 < _e3715);
                                                local_310 = _e3716;
                                                if _e3716 {
                                                    let _e3717 = local_308;
                                                    let _e3720 = local_299;
                                                    local_311 = (((f32(_e3717) + 0.5f) / f32(_e3720)) - 0.5f);
                                                    phi_5951_ = _e3709;
                                                    phi_3019_ = 0u;
                                                    phi_3022_ = _e3713;
                                                    loop {
                                                        let _e3725 = phi_5951_;
                                                        let _e3727 = phi_3019_;
                                                        let _e3729 = phi_3022_;
                                                        local_312 = _e3727;
                                                        local_639 = _e3729;
                                                        let _e3730 = local_312;
                                                        let _e3731 = local_298;
                                                        let _e3732 = (_e3730 < _e3731);
                                                        local_313 = _e3732;
                                                        if _e3732 {
                                                            let _e3733 = local_312;
                                                            let _e3736 = local_298;
                                                            let _e3739 = (((f32(_e3733) + 0.5f) / f32(_e3736)) - 0.5f);
                                                            let _e3740 = local_311;
                                                            let _e3741 = local_283;
                                                            let _e3743 = local_590;
                                                            let _e3745 = local_285;
                                                            local_314 = ((_e3743 + (_e3740 * _e3741)) + (_e3739 * _e3745));
                                                            let _e3748 = local_311;
                                                            let _e3749 = local_284;
                                                            let _e3751 = local_589;
                                                            let _e3753 = local_286;
                                                            local_315 = ((_e3751 + (_e3748 * _e3749)) + (_e3739 * _e3753));
                                                            phi_3048_ = 0u;
                                                            phi_3051_ = _e3729;
                                                            loop {
                                                                let _e3757 = phi_3048_;
                                                                let _e3759 = phi_3051_;
                                                                local_316 = _e3757;
                                                                local_317 = _e3759;
                                                                local_638 = _e3759;
                                                                let _e3760 = local_316;
                                                                let _e3761 = local_594;
                                                                let _e3762 = (_e3760 < _e3761);
                                                                local_318 = _e3762;
                                                                if _e3762 {
                                                                    let _e3763 = local_316;
                                                                    if (_e3763 == 0u) {
                                                                        let _e3765 = local_305;
                                                                        let _e5724 = local_636;
                                                                        phi_3064_ = _e5724;
                                                                        phi_3065_ = (1f - _e3765);
                                                                    } else {
                                                                        let _e5726 = local_637;
                                                                        phi_3064_ = _e5726;
                                                                        phi_3065_ = _e3577;
                                                                    }
                                                                    let _e3768 = phi_3064_;
                                                                    let _e3770 = phi_3065_;
                                                                    local_319 = _e3768;
                                                                    local_320 = _e3770;
                                                                    let _e3771 = local_307;
                                                                    let _e3772 = select(0.5f, 0f, _e3771);
                                                                    local_321 = _e3768.member_1;
                                                                    let _e3775 = local_314;
                                                                    let _e3777 = ((_e3775 * f32(_e3768.member_1)) - _e3772);
                                                                    local_322 = _e3777;
                                                                    local_323 = _e3768.member_2;
                                                                    let _e3780 = local_315;
                                                                    let _e3782 = ((_e3780 * f32(_e3768.member_2)) - _e3772);
                                                                    local_324 = _e3782;
                                                                    local_325 = floor(_e3777);
                                                                    local_326 = floor(_e3782);
                                                                    let _e3785 = local_307;
                                                                    if _e3785 {
                                                                        phi_3085_ = 0f;
                                                                        phi_3086_ = 0f;
                                                                    } else {
                                                                        let _e3786 = local_322;
                                                                        let _e3787 = local_325;
                                                                        let _e3789 = local_324;
                                                                        let _e3790 = local_326;
                                                                        phi_3085_ = (_e3789 - _e3790);
                                                                        phi_3086_ = (_e3786 - _e3787);
                                                                    }
                                                                    let _e3793 = phi_3085_;
                                                                    let _e3795 = phi_3086_;
                                                                    local_327 = _e3793;
                                                                    local_328 = _e3795;
                                                                    let _e3796 = local_325;
                                                                    let _e3798 = local_325;
                                                                    let _e3801 = local_325;
                                                                    let _e3805 = local_325;
                                                                    let _e3806 = local_325;
                                                                    let _e3808 = select(0i, select(select(i32(_e3796), i32(-2147483648), !((_e3798 >= -2147483600f))), 2147483647i, (_e3801 > 2147483500f)), (_e3805 == _e3806));
                                                                    local_329 = _e3808;
                                                                    let _e3809 = local_326;
                                                                    let _e3811 = local_326;
                                                                    let _e3814 = local_326;
                                                                    let _e3818 = local_326;
                                                                    let _e3819 = local_326;
                                                                    let _e3821 = select(0i, select(select(i32(_e3809), i32(-2147483648), !((_e3811 >= -2147483600f))), 2147483647i, (_e3814 > 2147483500f)), (_e3818 == _e3819));
                                                                    local_330 = _e3821;
                                                                    let _e3822 = local_319;
                                                                    local_331 = _e3822.member_3;
                                                                    let _e3824 = local_321;
                                                                    local_332 = bitcast<i32>(_e3824);
                                                                    let _e3826 = (_e3822.member_3 == 1u);
                                                                    local_333 = _e3826;
                                                                    if _e3826 {
                                                                        let _e3880 = local_329;
                                                                        if (_e3880 < 0i) {
                                                                            phi_3122_ = 0i;
                                                                        } else {
                                                                            let _e3882 = local_329;
                                                                            let _e3883 = local_332;
                                                                            if (_e3882 >= _e3883) {
                                                                                let _e3885 = local_332;
                                                                                phi_3121_ = (_e3885 - 1i);
                                                                            } else {
                                                                                phi_3121_ = _e3808;
                                                                            }
                                                                            let _e3888 = phi_3121_;
                                                                            phi_3122_ = _e3888;
                                                                        }
                                                                        let _e3890 = phi_3122_;
                                                                        phi_3182_ = _e3890;
                                                                    } else {
                                                                        let _e3827 = local_331;
                                                                        if (_e3827 == 2u) {
                                                                            let _e3849 = local_332;
                                                                            let _e3850 = (2i * _e3849);
                                                                            local_334 = _e3850;
                                                                            let _e3851 = (_e3850 == 0i);
                                                                            local_335 = _e3851;
                                                                            if _e3851 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3852 = local_334;
                                                                            let _e3853 = (_e3852 == -1i);
                                                                            local_336 = _e3853;
                                                                            let _e3854 = local_329;
                                                                            if (_e3853 && (_e3854 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3857 = local_329;
                                                                            let _e3858 = local_334;
                                                                            let _e3860 = local_334;
                                                                            local_337 = ((_e3857 % _e3858) + _e3860);
                                                                            let _e3862 = local_335;
                                                                            if _e3862 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3863 = local_337;
                                                                            let _e3865 = local_336;
                                                                            if (_e3865 && (_e3863 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3867 = local_337;
                                                                            let _e3868 = local_334;
                                                                            let _e3869 = (_e3867 % _e3868);
                                                                            local_338 = _e3869;
                                                                            let _e3870 = local_332;
                                                                            if (_e3869 < _e3870) {
                                                                                phi_3157_ = _e3869;
                                                                            } else {
                                                                                let _e3872 = local_334;
                                                                                let _e3874 = local_338;
                                                                                phi_3157_ = ((_e3872 - 1i) - _e3874);
                                                                            }
                                                                            let _e3877 = phi_3157_;
                                                                            phi_3181_ = _e3877;
                                                                        } else {
                                                                            let _e3829 = local_332;
                                                                            let _e3830 = (_e3829 == 0i);
                                                                            local_339 = _e3830;
                                                                            if _e3830 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3831 = local_332;
                                                                            let _e3832 = (_e3831 == -1i);
                                                                            local_340 = _e3832;
                                                                            let _e3833 = local_329;
                                                                            if (_e3832 && (_e3833 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3836 = local_329;
                                                                            let _e3837 = local_332;
                                                                            let _e3839 = local_332;
                                                                            local_341 = ((_e3836 % _e3837) + _e3839);
                                                                            let _e3841 = local_339;
                                                                            if _e3841 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3842 = local_341;
                                                                            let _e3844 = local_340;
                                                                            if (_e3844 && (_e3842 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3846 = local_341;
                                                                            let _e3847 = local_332;
                                                                            phi_3181_ = (_e3846 % _e3847);
                                                                        }
                                                                        let _e3879 = phi_3181_;
                                                                        phi_3182_ = _e3879;
                                                                    }
                                                                    let _e3892 = phi_3182_;
                                                                    local_342 = bitcast<u32>(_e3892);
                                                                    let _e3894 = local_329;
                                                                    let _e3895 = (_e3894 + 1i);
                                                                    local_343 = _e3895;
                                                                    let _e3896 = local_333;
                                                                    if _e3896 {
                                                                        let _e3950 = local_343;
                                                                        if (_e3950 < 0i) {
                                                                            phi_3202_ = 0i;
                                                                        } else {
                                                                            let _e3952 = local_343;
                                                                            let _e3953 = local_332;
                                                                            if (_e3952 >= _e3953) {
                                                                                let _e3955 = local_332;
                                                                                phi_3201_ = (_e3955 - 1i);
                                                                            } else {
                                                                                phi_3201_ = _e3895;
                                                                            }
                                                                            let _e3958 = phi_3201_;
                                                                            phi_3202_ = _e3958;
                                                                        }
                                                                        let _e3960 = phi_3202_;
                                                                        phi_3262_ = _e3960;
                                                                    } else {
                                                                        let _e3897 = local_331;
                                                                        if (_e3897 == 2u) {
                                                                            let _e3919 = local_332;
                                                                            let _e3920 = (2i * _e3919);
                                                                            local_344 = _e3920;
                                                                            let _e3921 = (_e3920 == 0i);
                                                                            local_345 = _e3921;
                                                                            if _e3921 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3922 = local_344;
                                                                            let _e3923 = (_e3922 == -1i);
                                                                            local_346 = _e3923;
                                                                            let _e3924 = local_343;
                                                                            if (_e3923 && (_e3924 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3927 = local_343;
                                                                            let _e3928 = local_344;
                                                                            let _e3930 = local_344;
                                                                            local_347 = ((_e3927 % _e3928) + _e3930);
                                                                            let _e3932 = local_345;
                                                                            if _e3932 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3933 = local_347;
                                                                            let _e3935 = local_346;
                                                                            if (_e3935 && (_e3933 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3937 = local_347;
                                                                            let _e3938 = local_344;
                                                                            let _e3939 = (_e3937 % _e3938);
                                                                            local_348 = _e3939;
                                                                            let _e3940 = local_332;
                                                                            if (_e3939 < _e3940) {
                                                                                phi_3237_ = _e3939;
                                                                            } else {
                                                                                let _e3942 = local_344;
                                                                                let _e3944 = local_348;
                                                                                phi_3237_ = ((_e3942 - 1i) - _e3944);
                                                                            }
                                                                            let _e3947 = phi_3237_;
                                                                            phi_3261_ = _e3947;
                                                                        } else {
                                                                            let _e3899 = local_332;
                                                                            let _e3900 = (_e3899 == 0i);
                                                                            local_349 = _e3900;
                                                                            if _e3900 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3901 = local_332;
                                                                            let _e3902 = (_e3901 == -1i);
                                                                            local_350 = _e3902;
                                                                            let _e3903 = local_343;
                                                                            if (_e3902 && (_e3903 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3906 = local_343;
                                                                            let _e3907 = local_332;
                                                                            let _e3909 = local_332;
                                                                            local_351 = ((_e3906 % _e3907) + _e3909);
                                                                            let _e3911 = local_349;
                                                                            if _e3911 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3912 = local_351;
                                                                            let _e3914 = local_350;
                                                                            if (_e3914 && (_e3912 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3916 = local_351;
                                                                            let _e3917 = local_332;
                                                                            phi_3261_ = (_e3916 % _e3917);
                                                                        }
                                                                        let _e3949 = phi_3261_;
                                                                        phi_3262_ = _e3949;
                                                                    }
                                                                    let _e3962 = phi_3262_;
                                                                    local_352 = bitcast<u32>(_e3962);
                                                                    let _e3964 = local_319;
                                                                    local_353 = _e3964.member_4;
                                                                    let _e3966 = local_323;
                                                                    local_354 = bitcast<i32>(_e3966);
                                                                    let _e3968 = (_e3964.member_4 == 1u);
                                                                    local_355 = _e3968;
                                                                    if _e3968 {
                                                                        let _e4022 = local_330;
                                                                        if (_e4022 < 0i) {
                                                                            phi_3281_ = 0i;
                                                                        } else {
                                                                            let _e4024 = local_330;
                                                                            let _e4025 = local_354;
                                                                            if (_e4024 >= _e4025) {
                                                                                let _e4027 = local_354;
                                                                                phi_3280_ = (_e4027 - 1i);
                                                                            } else {
                                                                                phi_3280_ = _e3821;
                                                                            }
                                                                            let _e4030 = phi_3280_;
                                                                            phi_3281_ = _e4030;
                                                                        }
                                                                        let _e4032 = phi_3281_;
                                                                        phi_3341_ = _e4032;
                                                                    } else {
                                                                        let _e3969 = local_353;
                                                                        if (_e3969 == 2u) {
                                                                            let _e3991 = local_354;
                                                                            let _e3992 = (2i * _e3991);
                                                                            local_356 = _e3992;
                                                                            let _e3993 = (_e3992 == 0i);
                                                                            local_357 = _e3993;
                                                                            if _e3993 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3994 = local_356;
                                                                            let _e3995 = (_e3994 == -1i);
                                                                            local_358 = _e3995;
                                                                            let _e3996 = local_330;
                                                                            if (_e3995 && (_e3996 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3999 = local_330;
                                                                            let _e4000 = local_356;
                                                                            let _e4002 = local_356;
                                                                            local_359 = ((_e3999 % _e4000) + _e4002);
                                                                            let _e4004 = local_357;
                                                                            if _e4004 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4005 = local_359;
                                                                            let _e4007 = local_358;
                                                                            if (_e4007 && (_e4005 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4009 = local_359;
                                                                            let _e4010 = local_356;
                                                                            let _e4011 = (_e4009 % _e4010);
                                                                            local_360 = _e4011;
                                                                            let _e4012 = local_354;
                                                                            if (_e4011 < _e4012) {
                                                                                phi_3316_ = _e4011;
                                                                            } else {
                                                                                let _e4014 = local_356;
                                                                                let _e4016 = local_360;
                                                                                phi_3316_ = ((_e4014 - 1i) - _e4016);
                                                                            }
                                                                            let _e4019 = phi_3316_;
                                                                            phi_3340_ = _e4019;
                                                                        } else {
                                                                            let _e3971 = local_354;
                                                                            let _e3972 = (_e3971 == 0i);
                                                                            local_361 = _e3972;
                                                                            if _e3972 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3973 = local_354;
                                                                            let _e3974 = (_e3973 == -1i);
                                                                            local_362 = _e3974;
                                                                            let _e3975 = local_330;
                                                                            if (_e3974 && (_e3975 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3978 = local_330;
                                                                            let _e3979 = local_354;
                                                                            let _e3981 = local_354;
                                                                            local_363 = ((_e3978 % _e3979) + _e3981);
                                                                            let _e3983 = local_361;
                                                                            if _e3983 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3984 = local_363;
                                                                            let _e3986 = local_362;
                                                                            if (_e3986 && (_e3984 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3988 = local_363;
                                                                            let _e3989 = local_354;
                                                                            phi_3340_ = (_e3988 % _e3989);
                                                                        }
                                                                        let _e4021 = phi_3340_;
                                                                        phi_3341_ = _e4021;
                                                                    }
                                                                    let _e4034 = phi_3341_;
                                                                    local_364 = bitcast<u32>(_e4034);
                                                                    let _e4036 = local_330;
                                                                    let _e4037 = (_e4036 + 1i);
                                                                    local_365 = _e4037;
                                                                    let _e4038 = local_355;
                                                                    if _e4038 {
                                                                        let _e4092 = local_365;
                                                                        if (_e4092 < 0i) {
                                                                            phi_3361_ = 0i;
                                                                        } else {
                                                                            let _e4094 = local_365;
                                                                            let _e4095 = local_354;
                                                                            if (_e4094 >= _e4095) {
                                                                                let _e4097 = local_354;
                                                                                phi_3360_ = (_e4097 - 1i);
                                                                            } else {
                                                                                phi_3360_ = _e4037;
                                                                            }
                                                                            let _e4100 = phi_3360_;
                                                                            phi_3361_ = _e4100;
                                                                        }
                                                                        let _e4102 = phi_3361_;
                                                                        phi_3421_ = _e4102;
                                                                    } else {
                                                                        let _e4039 = local_353;
                                                                        if (_e4039 == 2u) {
                                                                            let _e4061 = local_354;
                                                                            let _e4062 = (2i * _e4061);
                                                                            local_366 = _e4062;
                                                                            let _e4063 = (_e4062 == 0i);
                                                                            local_367 = _e4063;
                                                                            if _e4063 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4064 = local_366;
                                                                            let _e4065 = (_e4064 == -1i);
                                                                            local_368 = _e4065;
                                                                            let _e4066 = local_365;
                                                                            if (_e4065 && (_e4066 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4069 = local_365;
                                                                            let _e4070 = local_366;
                                                                            let _e4072 = local_366;
                                                                            local_369 = ((_e4069 % _e4070) + _e4072);
                                                                            let _e4074 = local_367;
                                                                            if _e4074 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4075 = local_369;
                                                                            let _e4077 = local_368;
                                                                            if (_e4077 && (_e4075 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4079 = local_369;
                                                                            let _e4080 = local_366;
                                                                            let _e4081 = (_e4079 % _e4080);
                                                                            local_370 = _e4081;
                                                                            let _e4082 = local_354;
                                                                            if (_e4081 < _e4082) {
                                                                                phi_3396_ = _e4081;
                                                                            } else {
                                                                                let _e4084 = local_366;
                                                                                let _e4086 = local_370;
                                                                                phi_3396_ = ((_e4084 - 1i) - _e4086);
                                                                            }
                                                                            let _e4089 = phi_3396_;
                                                                            phi_3420_ = _e4089;
                                                                        } else {
                                                                            let _e4041 = local_354;
                                                                            let _e4042 = (_e4041 == 0i);
                                                                            local_371 = _e4042;
                                                                            if _e4042 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4043 = local_354;
                                                                            let _e4044 = (_e4043 == -1i);
                                                                            local_372 = _e4044;
                                                                            let _e4045 = local_365;
                                                                            if (_e4044 && (_e4045 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4048 = local_365;
                                                                            let _e4049 = local_354;
                                                                            let _e4051 = local_354;
                                                                            local_373 = ((_e4048 % _e4049) + _e4051);
                                                                            let _e4053 = local_371;
                                                                            if _e4053 {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4054 = local_373;
                                                                            let _e4056 = local_372;
                                                                            if (_e4056 && (_e4054 == i32(-2147483648))) {
                                                                                phi_5905_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4058 = local_373;
                                                                            let _e4059 = local_354;
                                                                            phi_3420_ = (_e4058 % _e4059);
                                                                        }
                                                                        let _e4091 = phi_3420_;
                                                                        phi_3421_ = _e4091;
                                                                    }
                                                                    let _e4104 = phi_3421_;
                                                                    local_374 = bitcast<u32>(_e4104);
                                                                    let _e4106 = local_319;
                                                                    local_375 = _e4106.member;
                                                                    let _e4108 = local_364;
                                                                    let _e4109 = local_321;
                                                                    let _e4111 = (_e4106.member + (_e4108 * _e4109));
                                                                    local_376 = _e4111;
                                                                    let _e4112 = local_342;
                                                                    let _e4114 = ((_e4111 + _e4112) * 2u);
                                                                    local_377 = _e4114;
                                                                    let _e4115 = local_6;
                                                                    if (_e4114 < _e4115) {
                                                                    } else {
                                                                        phi_5905_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4117 = local_377;
                                                                    let _e4120 = global_9.member[_e4117];
                                                                    local_378 = _e4120;
                                                                    let _e4121 = local_377;
                                                                    let _e4122 = (_e4121 + 1u);
                                                                    local_379 = _e4122;
                                                                    let _e4123 = local_6;
                                                                    if (_e4122 < _e4123) {
                                                                    } else {
                                                                        phi_5905_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4125 = local_379;
                                                                    let _e4128 = global_9.member[_e4125];
                                                                    local_380 = _e4128;
                                                                    let _e4129 = local_378;
                                                                    let _e4130 = (_e4129 & 65535u);
                                                                    local_595 = select(-1f, 1f, ((_e4130 & 32768u) == 0u));
                                                                    let _e4136 = ((_e4130 >> bitcast<u32>(10i)) & 31u);
                                                                    local_381 = _e4136;
                                                                    local_382 = (_e4130 & 1023u);
                                                                    if (_e4136 == 0u) {
                                                                        let _e4158 = local_382;
                                                                        let _e4160 = local_595;
                                                                        phi_3491_ = ((_e4160 * f32(_e4158)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4139 = local_381;
                                                                        if (_e4139 == 31u) {
                                                                            let _e4149 = local_382;
                                                                            phi_3488_ = (2139095040u | (_e4149 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4141 = local_381;
                                                                            let _e4145 = local_382;
                                                                            phi_3488_ = (((_e4141 + 112u) << bitcast<u32>(23i)) | (_e4145 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4154 = phi_3488_;
                                                                        let _e4156 = local_595;
                                                                        phi_3491_ = (_e4156 * bitcast<f32>(_e4154));
                                                                    }
                                                                    let _e4164 = phi_3491_;
                                                                    local_383 = _e4164;
                                                                    let _e4165 = local_378;
                                                                    let _e4167 = (_e4165 >> bitcast<u32>(16i));
                                                                    local_596 = select(-1f, 1f, ((_e4167 & 32768u) == 0u));
                                                                    let _e4173 = ((_e4167 >> bitcast<u32>(10i)) & 31u);
                                                                    local_384 = _e4173;
                                                                    local_385 = (_e4167 & 1023u);
                                                                    if (_e4173 == 0u) {
                                                                        let _e4195 = local_385;
                                                                        let _e4197 = local_596;
                                                                        phi_3523_ = ((_e4197 * f32(_e4195)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4176 = local_384;
                                                                        if (_e4176 == 31u) {
                                                                            let _e4186 = local_385;
                                                                            phi_3520_ = (2139095040u | (_e4186 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4178 = local_384;
                                                                            let _e4182 = local_385;
                                                                            phi_3520_ = (((_e4178 + 112u) << bitcast<u32>(23i)) | (_e4182 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4191 = phi_3520_;
                                                                        let _e4193 = local_596;
                                                                        phi_3523_ = (_e4193 * bitcast<f32>(_e4191));
                                                                    }
                                                                    let _e4201 = phi_3523_;
                                                                    local_386 = _e4201;
                                                                    let _e4202 = local_380;
                                                                    let _e4203 = (_e4202 & 65535u);
                                                                    local_597 = select(-1f, 1f, ((_e4203 & 32768u) == 0u));
                                                                    let _e4209 = ((_e4203 >> bitcast<u32>(10i)) & 31u);
                                                                    local_387 = _e4209;
                                                                    local_388 = (_e4203 & 1023u);
                                                                    if (_e4209 == 0u) {
                                                                        let _e4231 = local_388;
                                                                        let _e4233 = local_597;
                                                                        phi_3555_ = ((_e4233 * f32(_e4231)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4212 = local_387;
                                                                        if (_e4212 == 31u) {
                                                                            let _e4222 = local_388;
                                                                            phi_3552_ = (2139095040u | (_e4222 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4214 = local_387;
                                                                            let _e4218 = local_388;
                                                                            phi_3552_ = (((_e4214 + 112u) << bitcast<u32>(23i)) | (_e4218 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4227 = phi_3552_;
                                                                        let _e4229 = local_597;
                                                                        phi_3555_ = (_e4229 * bitcast<f32>(_e4227));
                                                                    }
                                                                    let _e4237 = phi_3555_;
                                                                    local_389 = _e4237;
                                                                    let _e4238 = local_380;
                                                                    let _e4240 = (_e4238 >> bitcast<u32>(16i));
                                                                    local_598 = select(-1f, 1f, ((_e4240 & 32768u) == 0u));
                                                                    let _e4246 = ((_e4240 >> bitcast<u32>(10i)) & 31u);
                                                                    local_390 = _e4246;
                                                                    local_391 = (_e4240 & 1023u);
                                                                    if (_e4246 == 0u) {
                                                                        let _e4268 = local_391;
                                                                        let _e4270 = local_598;
                                                                        phi_3587_ = ((_e4270 * f32(_e4268)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4249 = local_390;
                                                                        if (_e4249 == 31u) {
                                                                            let _e4259 = local_391;
                                                                            phi_3584_ = (2139095040u | (_e4259 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4251 = local_390;
                                                                            let _e4255 = local_391;
                                                                            phi_3584_ = (((_e4251 + 112u) << bitcast<u32>(23i)) | (_e4255 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4264 = phi_3584_;
                                                                        let _e4266 = local_598;
                                                                        phi_3587_ = (_e4266 * bitcast<f32>(_e4264));
                                                                    }
                                                                    let _e4274 = phi_3587_;
                                                                    local_392 = _e4274;
                                                                    let _e4275 = local_376;
                                                                    let _e4276 = local_352;
                                                                    let _e4278 = ((_e4275 + _e4276) * 2u);
                                                                    local_393 = _e4278;
                                                                    let _e4279 = local_6;
                                                                    if (_e4278 < _e4279) {
                                                                    } else {
                                                                        phi_5905_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4281 = local_393;
                                                                    let _e4284 = global_9.member[_e4281];
                                                                    local_394 = _e4284;
                                                                    let _e4285 = local_393;
                                                                    let _e4286 = (_e4285 + 1u);
                                                                    local_395 = _e4286;
                                                                    let _e4287 = local_6;
                                                                    if (_e4286 < _e4287) {
                                                                    } else {
                                                                        phi_5905_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4289 = local_395;
                                                                    let _e4292 = global_9.member[_e4289];
                                                                    local_396 = _e4292;
                                                                    let _e4293 = local_394;
                                                                    let _e4294 = (_e4293 & 65535u);
                                                                    local_599 = select(-1f, 1f, ((_e4294 & 32768u) == 0u));
                                                                    let _e4300 = ((_e4294 >> bitcast<u32>(10i)) & 31u);
                                                                    local_397 = _e4300;
                                                                    local_398 = (_e4294 & 1023u);
                                                                    if (_e4300 == 0u) {
                                                                        let _e4322 = local_398;
                                                                        let _e4324 = local_599;
                                                                        phi_3656_ = ((_e4324 * f32(_e4322)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4303 = local_397;
                                                                        if (_e4303 == 31u) {
                                                                            let _e4313 = local_398;
                                                                            phi_3653_ = (2139095040u | (_e4313 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4305 = local_397;
                                                                            let _e4309 = local_398;
                                                                            phi_3653_ = (((_e4305 + 112u) << bitcast<u32>(23i)) | (_e4309 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4318 = phi_3653_;
                                                                        let _e4320 = local_599;
                                                                        phi_3656_ = (_e4320 * bitcast<f32>(_e4318));
                                                                    }
                                                                    let _e4328 = phi_3656_;
                                                                    local_399 = _e4328;
                                                                    let _e4329 = local_394;
                                                                    let _e4331 = (_e4329 >> bitcast<u32>(16i));
                                                                    local_600 = select(-1f, 1f, ((_e4331 & 32768u) == 0u));
                                                                    let _e4337 = ((_e4331 >> bitcast<u32>(10i)) & 31u);
                                                                    local_400 = _e4337;
                                                                    local_401 = (_e4331 & 1023u);
                                                                    if (_e4337 == 0u) {
                                                                        let _e4359 = local_401;
                                                                        let _e4361 = local_600;
                                                                        phi_3688_ = ((_e4361 * f32(_e4359)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4340 = local_400;
                                                                        if (_e4340 == 31u) {
                                                                            let _e4350 = local_401;
                                                                            phi_3685_ = (2139095040u | (_e4350 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4342 = local_400;
                                                                            let _e4346 = local_401;
                                                                            phi_3685_ = (((_e4342 + 112u) << bitcast<u32>(23i)) | (_e4346 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4355 = phi_3685_;
                                                                        let _e4357 = local_600;
                                                                        phi_3688_ = (_e4357 * bitcast<f32>(_e4355));
                                                                    }
                                                                    let _e4365 = phi_3688_;
                                                                    local_402 = _e4365;
                                                                    let _e4366 = local_396;
                                                                    let _e4367 = (_e4366 & 65535u);
                                                                    local_601 = select(-1f, 1f, ((_e4367 & 32768u) == 0u));
                                                                    let _e4373 = ((_e4367 >> bitcast<u32>(10i)) & 31u);
                                                                    local_403 = _e4373;
                                                                    local_404 = (_e4367 & 1023u);
                                                                    if (_e4373 == 0u) {
                                                                        let _e4395 = local_404;
                                                                        let _e4397 = local_601;
                                                                        phi_3720_ = ((_e4397 * f32(_e4395)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4376 = local_403;
                                                                        if (_e4376 == 31u) {
                                                                            let _e4386 = local_404;
                                                                            phi_3717_ = (2139095040u | (_e4386 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4378 = local_403;
                                                                            let _e4382 = local_404;
                                                                            phi_3717_ = (((_e4378 + 112u) << bitcast<u32>(23i)) | (_e4382 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4391 = phi_3717_;
                                                                        let _e4393 = local_601;
                                                                        phi_3720_ = (_e4393 * bitcast<f32>(_e4391));
                                                                    }
                                                                    let _e4401 = phi_3720_;
                                                                    local_405 = _e4401;
                                                                    let _e4402 = local_396;
                                                                    let _e4404 = (_e4402 >> bitcast<u32>(16i));
                                                                    local_602 = select(-1f, 1f, ((_e4404 & 32768u) == 0u));
                                                                    let _e4410 = ((_e4404 >> bitcast<u32>(10i)) & 31u);
                                                                    local_406 = _e4410;
                                                                    local_407 = (_e4404 & 1023u);
                                                                    if (_e4410 == 0u) {
                                                                        let _e4432 = local_407;
                                                                        let _e4434 = local_602;
                                                                        phi_3752_ = ((_e4434 * f32(_e4432)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4413 = local_406;
                                                                        if (_e4413 == 31u) {
                                                                            let _e4423 = local_407;
                                                                            phi_3749_ = (2139095040u | (_e4423 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4415 = local_406;
                                                                            let _e4419 = local_407;
                                                                            phi_3749_ = (((_e4415 + 112u) << bitcast<u32>(23i)) | (_e4419 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4428 = phi_3749_;
                                                                        let _e4430 = local_602;
                                                                        phi_3752_ = (_e4430 * bitcast<f32>(_e4428));
                                                                    }
                                                                    let _e4438 = phi_3752_;
                                                                    let _e4439 = local_399;
                                                                    let _e4440 = local_383;
                                                                    let _e4442 = local_328;
                                                                    let _e4444 = local_383;
                                                                    local_408 = (_e4444 + ((_e4439 - _e4440) * _e4442));
                                                                    let _e4446 = local_402;
                                                                    let _e4447 = local_386;
                                                                    let _e4449 = local_328;
                                                                    let _e4451 = local_386;
                                                                    local_409 = (_e4451 + ((_e4446 - _e4447) * _e4449));
                                                                    let _e4453 = local_405;
                                                                    let _e4454 = local_389;
                                                                    let _e4456 = local_328;
                                                                    let _e4458 = local_389;
                                                                    local_410 = (_e4458 + ((_e4453 - _e4454) * _e4456));
                                                                    let _e4460 = local_392;
                                                                    let _e4462 = local_328;
                                                                    let _e4464 = local_392;
                                                                    local_411 = (_e4464 + ((_e4438 - _e4460) * _e4462));
                                                                    let _e4466 = local_374;
                                                                    let _e4467 = local_321;
                                                                    let _e4469 = local_375;
                                                                    let _e4470 = (_e4469 + (_e4466 * _e4467));
                                                                    local_412 = _e4470;
                                                                    let _e4471 = local_342;
                                                                    let _e4473 = ((_e4470 + _e4471) * 2u);
                                                                    local_413 = _e4473;
                                                                    let _e4474 = local_6;
                                                                    if (_e4473 < _e4474) {
                                                                    } else {
                                                                        phi_5905_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4476 = local_413;
                                                                    let _e4479 = global_9.member[_e4476];
                                                                    local_414 = _e4479;
                                                                    let _e4480 = local_413;
                                                                    let _e4481 = (_e4480 + 1u);
                                                                    local_415 = _e4481;
                                                                    let _e4482 = local_6;
                                                                    if (_e4481 < _e4482) {
                                                                    } else {
                                                                        phi_5905_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4484 = local_415;
                                                                    let _e4487 = global_9.member[_e4484];
                                                                    local_416 = _e4487;
                                                                    let _e4488 = local_414;
                                                                    let _e4489 = (_e4488 & 65535u);
                                                                    local_603 = select(-1f, 1f, ((_e4489 & 32768u) == 0u));
                                                                    let _e4495 = ((_e4489 >> bitcast<u32>(10i)) & 31u);
                                                                    local_417 = _e4495;
                                                                    local_418 = (_e4489 & 1023u);
                                                                    if (_e4495 == 0u) {
                                                                        let _e4517 = local_418;
                                                                        let _e4519 = local_603;
                                                                        phi_3833_ = ((_e4519 * f32(_e4517)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4498 = local_417;
                                                                        if (_e4498 == 31u) {
                                                                            let _e4508 = local_418;
                                                                            phi_3830_ = (2139095040u | (_e4508 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4500 = local_417;
                                                                            let _e4504 = local_418;
                                                                            phi_3830_ = (((_e4500 + 112u) << bitcast<u32>(23i)) | (_e4504 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4513 = phi_3830_;
                                                                        let _e4515 = local_603;
                                                                        phi_3833_ = (_e4515 * bitcast<f32>(_e4513));
                                                                    }
                                                                    let _e4523 = phi_3833_;
                                                                    local_419 = _e4523;
                                                                    let _e4524 = local_414;
                                                                    let _e4526 = (_e4524 >> bitcast<u32>(16i));
                                                                    local_604 = select(-1f, 1f, ((_e4526 & 32768u) == 0u));
                                                                    let _e4532 = ((_e4526 >> bitcast<u32>(10i)) & 31u);
                                                                    local_420 = _e4532;
                                                                    local_421 = (_e4526 & 1023u);
                                                                    if (_e4532 == 0u) {
                                                                        let _e4554 = local_421;
                                                                        let _e4556 = local_604;
                                                                        phi_3865_ = ((_e4556 * f32(_e4554)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4535 = local_420;
                                                                        if (_e4535 == 31u) {
                                                                            let _e4545 = local_421;
                                                                            phi_3862_ = (2139095040u | (_e4545 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4537 = local_420;
                                                                            let _e4541 = local_421;
                                                                            phi_3862_ = (((_e4537 + 112u) << bitcast<u32>(23i)) | (_e4541 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4550 = phi_3862_;
                                                                        let _e4552 = local_604;
                                                                        phi_3865_ = (_e4552 * bitcast<f32>(_e4550));
                                                                    }
                                                                    let _e4560 = phi_3865_;
                                                                    local_422 = _e4560;
                                                                    let _e4561 = local_416;
                                                                    let _e4562 = (_e4561 & 65535u);
                                                                    local_605 = select(-1f, 1f, ((_e4562 & 32768u) == 0u));
                                                                    let _e4568 = ((_e4562 >> bitcast<u32>(10i)) & 31u);
                                                                    local_423 = _e4568;
                                                                    local_424 = (_e4562 & 1023u);
                                                                    if (_e4568 == 0u) {
                                                                        let _e4590 = local_424;
                                                                        let _e4592 = local_605;
                                                                        phi_3897_ = ((_e4592 * f32(_e4590)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4571 = local_423;
                                                                        if (_e4571 == 31u) {
                                                                            let _e4581 = local_424;
                                                                            phi_3894_ = (2139095040u | (_e4581 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4573 = local_423;
                                                                            let _e4577 = local_424;
                                                                            phi_3894_ = (((_e4573 + 112u) << bitcast<u32>(23i)) | (_e4577 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4586 = phi_3894_;
                                                                        let _e4588 = local_605;
                                                                        phi_3897_ = (_e4588 * bitcast<f32>(_e4586));
                                                                    }
                                                                    let _e4596 = phi_3897_;
                                                                    local_425 = _e4596;
                                                                    let _e4597 = local_416;
                                                                    let _e4599 = (_e4597 >> bitcast<u32>(16i));
                                                                    local_606 = select(-1f, 1f, ((_e4599 & 32768u) == 0u));
                                                                    let _e4605 = ((_e4599 >> bitcast<u32>(10i)) & 31u);
                                                                    local_426 = _e4605;
                                                                    local_427 = (_e4599 & 1023u);
                                                                    if (_e4605 == 0u) {
                                                                        let _e4627 = local_427;
                                                                        let _e4629 = local_606;
                                                                        phi_3929_ = ((_e4629 * f32(_e4627)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4608 = local_426;
                                                                        if (_e4608 == 31u) {
                                                                            let _e4618 = local_427;
                                                                            phi_3926_ = (2139095040u | (_e4618 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4610 = local_426;
                                                                            let _e4614 = local_427;
                                                                            phi_3926_ = (((_e4610 + 112u) << bitcast<u32>(23i)) | (_e4614 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4623 = phi_3926_;
                                                                        let _e4625 = local_606;
                                                                        phi_3929_ = (_e4625 * bitcast<f32>(_e4623));
                                                                    }
                                                                    let _e4633 = phi_3929_;
                                                                    local_428 = _e4633;
                                                                    let _e4634 = local_412;
                                                                    let _e4635 = local_352;
                                                                    let _e4637 = ((_e4634 + _e4635) * 2u);
                                                                    local_429 = _e4637;
                                                                    let _e4638 = local_6;
                                                                    if (_e4637 < _e4638) {
                                                                    } else {
                                                                        phi_5905_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4640 = local_429;
                                                                    let _e4643 = global_9.member[_e4640];
                                                                    local_430 = _e4643;
                                                                    let _e4644 = local_429;
                                                                    let _e4645 = (_e4644 + 1u);
                                                                    local_431 = _e4645;
                                                                    let _e4646 = local_6;
                                                                    if (_e4645 < _e4646) {
                                                                    } else {
                                                                        phi_5905_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4648 = local_431;
                                                                    let _e4651 = global_9.member[_e4648];
                                                                    local_432 = _e4651;
                                                                    let _e4652 = local_430;
                                                                    let _e4653 = (_e4652 & 65535u);
                                                                    local_607 = select(-1f, 1f, ((_e4653 & 32768u) == 0u));
                                                                    let _e4659 = ((_e4653 >> bitcast<u32>(10i)) & 31u);
                                                                    local_433 = _e4659;
                                                                    local_434 = (_e4653 & 1023u);
                                                                    if (_e4659 == 0u) {
                                                                        let _e4681 = local_434;
                                                                        let _e4683 = local_607;
                                                                        phi_3998_ = ((_e4683 * f32(_e4681)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4662 = local_433;
                                                                        if (_e4662 == 31u) {
                                                                            let _e4672 = local_434;
                                                                            phi_3995_ = (2139095040u | (_e4672 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4664 = local_433;
                                                                            let _e4668 = local_434;
                                                                            phi_3995_ = (((_e4664 + 112u) << bitcast<u32>(23i)) | (_e4668 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4677 = phi_3995_;
                                                                        let _e4679 = local_607;
                                                                        phi_3998_ = (_e4679 * bitcast<f32>(_e4677));
                                                                    }
                                                                    let _e4687 = phi_3998_;
                                                                    local_435 = _e4687;
                                                                    let _e4688 = local_430;
                                                                    let _e4690 = (_e4688 >> bitcast<u32>(16i));
                                                                    local_608 = select(-1f, 1f, ((_e4690 & 32768u) == 0u));
                                                                    let _e4696 = ((_e4690 >> bitcast<u32>(10i)) & 31u);
                                                                    local_436 = _e4696;
                                                                    local_437 = (_e4690 & 1023u);
                                                                    if (_e4696 == 0u) {
                                                                        let _e4718 = local_437;
                                                                        let _e4720 = local_608;
                                                                        phi_4030_ = ((_e4720 * f32(_e4718)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4699 = local_436;
                                                                        if (_e4699 == 31u) {
                                                                            let _e4709 = local_437;
                                                                            phi_4027_ = (2139095040u | (_e4709 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4701 = local_436;
                                                                            let _e4705 = local_437;
                                                                            phi_4027_ = (((_e4701 + 112u) << bitcast<u32>(23i)) | (_e4705 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4714 = phi_4027_;
                                                                        let _e4716 = local_608;
                                                                        phi_4030_ = (_e4716 * bitcast<f32>(_e4714));
                                                                    }
                                                                    let _e4724 = phi_4030_;
                                                                    local_438 = _e4724;
                                                                    let _e4725 = local_432;
                                                                    let _e4726 = (_e4725 & 65535u);
                                                                    local_609 = select(-1f, 1f, ((_e4726 & 32768u) == 0u));
                                                                    let _e4732 = ((_e4726 >> bitcast<u32>(10i)) & 31u);
                                                                    local_439 = _e4732;
                                                                    local_440 = (_e4726 & 1023u);
                                                                    if (_e4732 == 0u) {
                                                                        let _e4754 = local_440;
                                                                        let _e4756 = local_609;
                                                                        phi_4062_ = ((_e4756 * f32(_e4754)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4735 = local_439;
                                                                        if (_e4735 == 31u) {
                                                                            let _e4745 = local_440;
                                                                            phi_4059_ = (2139095040u | (_e4745 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4737 = local_439;
                                                                            let _e4741 = local_440;
                                                                            phi_4059_ = (((_e4737 + 112u) << bitcast<u32>(23i)) | (_e4741 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4750 = phi_4059_;
                                                                        let _e4752 = local_609;
                                                                        phi_4062_ = (_e4752 * bitcast<f32>(_e4750));
                                                                    }
                                                                    let _e4760 = phi_4062_;
                                                                    local_441 = _e4760;
                                                                    let _e4761 = local_432;
                                                                    let _e4763 = (_e4761 >> bitcast<u32>(16i));
                                                                    local_610 = select(-1f, 1f, ((_e4763 & 32768u) == 0u));
                                                                    let _e4769 = ((_e4763 >> bitcast<u32>(10i)) & 31u);
                                                                    local_442 = _e4769;
                                                                    local_443 = (_e4763 & 1023u);
                                                                    if (_e4769 == 0u) {
                                                                        let _e4791 = local_443;
                                                                        let _e4793 = local_610;
                                                                        phi_4094_ = ((_e4793 * f32(_e4791)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4772 = local_442;
                                                                        if (_e4772 == 31u) {
                                                                            let _e4782 = local_443;
                                                                            phi_4091_ = (2139095040u | (_e4782 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4774 = local_442;
                                                                            let _e4778 = local_443;
                                                                            phi_4091_ = (((_e4774 + 112u) << bitcast<u32>(23i)) | (_e4778 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4787 = phi_4091_;
                                                                        let _e4789 = local_610;
                                                                        phi_4094_ = (_e4789 * bitcast<f32>(_e4787));
                                                                    }
                                                                    let _e4797 = phi_4094_;
                                                                    let _e4798 = local_435;
                                                                    let _e4799 = local_419;
                                                                    let _e4801 = local_328;
                                                                    let _e4803 = local_419;
                                                                    let _e4805 = local_438;
                                                                    let _e4806 = local_422;
                                                                    let _e4808 = local_328;
                                                                    let _e4810 = local_422;
                                                                    let _e4812 = local_441;
                                                                    let _e4813 = local_425;
                                                                    let _e4815 = local_328;
                                                                    let _e4817 = local_425;
                                                                    let _e4819 = local_428;
                                                                    let _e4821 = local_328;
                                                                    let _e4823 = local_428;
                                                                    let _e4825 = local_408;
                                                                    let _e4827 = local_327;
                                                                    let _e4829 = local_408;
                                                                    let _e4831 = local_409;
                                                                    let _e4833 = local_327;
                                                                    let _e4835 = local_409;
                                                                    let _e4837 = local_410;
                                                                    let _e4839 = local_327;
                                                                    let _e4841 = local_410;
                                                                    let _e4843 = local_411;
                                                                    let _e4845 = local_327;
                                                                    let _e4847 = local_411;
                                                                    let _e4849 = local_320;
                                                                    let _e4851 = local_320;
                                                                    let _e4853 = local_320;
                                                                    let _e4855 = local_320;
                                                                    let _e4857 = local_317;
                                                                    let _e4860 = local_317;
                                                                    let _e4863 = local_317;
                                                                    let _e4866 = local_317;
                                                                    let _e4870 = local_316;
                                                                    phi_3049_ = (_e4870 + 1u);
                                                                    phi_3052_ = type_5((_e4857.member + ((_e4829 + (((_e4803 + ((_e4798 - _e4799) * _e4801)) - _e4825) * _e4827)) * _e4849)), (_e4860.member_1 + ((_e4835 + (((_e4810 + ((_e4805 - _e4806) * _e4808)) - _e4831) * _e4833)) * _e4851)), (_e4863.member_2 + ((_e4841 + (((_e4817 + ((_e4812 - _e4813) * _e4815)) - _e4837) * _e4839)) * _e4853)), (_e4866.member_3 + ((_e4847 + (((_e4823 + ((_e4797 - _e4819) * _e4821)) - _e4843) * _e4845)) * _e4855)));
                                                                } else {
                                                                    phi_3049_ = u32();
                                                                    phi_3052_ = type_5();
                                                                }
                                                                let _e4873 = phi_3049_;
                                                                let _e4875 = phi_3052_;
                                                                continue;
                                                                continuing {
                                                                    let _e4876 = local_318;
                                                                    phi_3048_ = _e4873;
                                                                    phi_3051_ = _e4875;
                                                                    phi_5905_ = _e3725;
                                                                    break if !(_e4876);
                                                                }
                                                            }
                                                            let _e4879 = phi_5905_;
                                                            phi_6021_ = _e4879;
                                                            if _e4879 {
                                                                break;
                                                            }
                                                            let _e4880 = local_312;
                                                            phi_6022_ = _e4879;
                                                            phi_3020_ = (_e4880 + 1u);
                                                            let _e5789 = local_638;
                                                            phi_3023_ = _e5789;
                                                        } else {
                                                            phi_6022_ = _e3725;
                                                            phi_3020_ = u32();
                                                            phi_3023_ = type_5();
                                                        }
                                                        let _e4883 = phi_6022_;
                                                        let _e4885 = phi_3020_;
                                                        let _e4887 = phi_3023_;
                                                        continue;
                                                        continuing {
                                                            let _e4888 = local_313;
                                                            phi_5951_ = _e4883;
                                                            phi_3019_ = _e4885;
                                                            phi_3022_ = _e4887;
                                                            phi_6021_ = _e4883;
                                                            break if !(_e4888);
                                                        }
                                                    }
                                                    let _e4891 = phi_6021_;
                                                    phi_6023_ = _e4891;
                                                    if _e4891 {
                                                        break;
                                                    }
                                                    let _e4892 = local_308;
                                                    phi_6024_ = _e4891;
                                                    phi_3003_ = (_e4892 + 1u);
                                                    let _e5795 = local_639;
                                                    phi_3006_ = _e5795;
                                                } else {
                                                    phi_6024_ = _e3709;
                                                    phi_3003_ = u32();
                                                    phi_3006_ = type_5();
                                                }
                                                let _e4895 = phi_6024_;
                                                let _e4897 = phi_3003_;
                                                let _e4899 = phi_3006_;
                                                continue;
                                                continuing {
                                                    let _e4900 = local_310;
                                                    phi_5952_ = _e4895;
                                                    phi_3002_ = _e4897;
                                                    phi_3005_ = _e4899;
                                                    phi_6023_ = _e4895;
                                                    break if !(_e4900);
                                                }
                                            }
                                            let _e4903 = phi_6023_;
                                            phi_6062_ = _e4903;
                                            if _e4903 {
                                                break;
                                            }
                                            let _e4904 = local_299;
                                            let _e4905 = local_298;
                                            let _e4908 = (1f / f32((_e4904 * _e4905)));
                                            let _e4909 = local_309;
                                            let _e4912 = local_309;
                                            let _e4915 = local_309;
                                            let _e4918 = local_309;
                                            phi_6041_ = _e4903;
                                            phi_4147_ = type_5((_e4909.member * _e4908), (_e4912.member_1 * _e4908), (_e4915.member_2 * _e4908), (_e4918.member_3 * _e4908));
                                        }
                                        let _e4923 = phi_6041_;
                                        let _e4925 = phi_4147_;
                                        phi_6040_ = _e4923;
                                        phi_4148_ = _e4925;
                                        phi_4149_ = _e3340;
                                    }
                                    let _e4927 = phi_6040_;
                                    let _e4929 = phi_4148_;
                                    let _e4931 = phi_4149_;
                                    if _e4931 {
                                        phi_4153_ = type_5(1f, 1f, 1f, 1f);
                                    } else {
                                        phi_4153_ = _e4929;
                                    }
                                    let _e4933 = phi_4153_;
                                    phi_6038_ = _e4927;
                                    phi_4154_ = _e4933;
                                }
                                let _e4935 = phi_6038_;
                                let _e4937 = phi_4154_;
                                phi_6037_ = _e4935;
                                phi_4155_ = _e4937;
                                phi_4156_ = _e3304;
                            }
                            let _e4939 = phi_6037_;
                            let _e4941 = phi_4155_;
                            let _e4943 = phi_4156_;
                            if _e4943 {
                                phi_4160_ = type_5(1f, 1f, 1f, 1f);
                            } else {
                                phi_4160_ = _e4941;
                            }
                            let _e4945 = phi_4160_;
                            local_628 = array<f32, 4>(_e4945.member, _e4945.member_1, _e4945.member_2, _e4945.member_3);
                            let _e4951 = local_34;
                            local_618 = _e4951;
                            let _e4953 = local_18;
                            local_619[0u] = _e4953;
                            let _e4955 = local_20;
                            local_619[1u] = _e4955;
                            let _e4957 = local_35;
                            local_619[2u] = _e4957;
                            phi_4188_ = 0u;
                            phi_4191_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            loop {
                                let _e4959 = phi_4188_;
                                let _e4961 = phi_4191_;
                                local_444 = _e4959;
                                local_445 = _e4961;
                                let _e4962 = local_444;
                                let _e4963 = (_e4962 < 3u);
                                local_446 = _e4963;
                                if _e4963 {
                                    let _e4964 = local_444;
                                    if (_e4964 < 4u) {
                                    } else {
                                        phi_6025_ = true;
                                        break;
                                    }
                                    let _e4966 = local_444;
                                    let _e4968 = local_618[_e4966];
                                    let _e4969 = (_e4968 * 10u);
                                    local_447 = _e4969;
                                    let _e4970 = (_e4969 + 8u);
                                    local_448 = _e4970;
                                    let _e4971 = local_2;
                                    if (_e4970 < _e4971) {
                                    } else {
                                        phi_6025_ = true;
                                        break;
                                    }
                                    let _e4973 = local_448;
                                    let _e4976 = global_5.member[_e4973];
                                    local_449 = _e4976;
                                    let _e4977 = local_447;
                                    let _e4978 = (_e4977 + 9u);
                                    local_450 = _e4978;
                                    let _e4979 = local_2;
                                    if (_e4978 < _e4979) {
                                    } else {
                                        phi_6025_ = true;
                                        break;
                                    }
                                    let _e4981 = local_450;
                                    let _e4984 = global_5.member[_e4981];
                                    local_451 = _e4984;
                                    let _e4985 = local_446;
                                    if _e4985 {
                                    } else {
                                        phi_6025_ = true;
                                        break;
                                    }
                                    let _e4986 = local_444;
                                    let _e4988 = local_619[_e4986];
                                    local_452 = _e4988;
                                    let _e4989 = local_449;
                                    let _e4990 = (_e4989 & 65535u);
                                    local_611 = select(-1f, 1f, ((_e4990 & 32768u) == 0u));
                                    let _e4996 = ((_e4990 >> bitcast<u32>(10i)) & 31u);
                                    local_453 = _e4996;
                                    local_454 = (_e4990 & 1023u);
                                    if (_e4996 == 0u) {
                                        let _e5018 = local_454;
                                        let _e5020 = local_611;
                                        phi_4277_ = ((_e5020 * f32(_e5018)) * 0.000000059604645f);
                                    } else {
                                        let _e4999 = local_453;
                                        if (_e4999 == 31u) {
                                            let _e5009 = local_454;
                                            phi_4274_ = (2139095040u | (_e5009 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5001 = local_453;
                                            let _e5005 = local_454;
                                            phi_4274_ = (((_e5001 + 112u) << bitcast<u32>(23i)) | (_e5005 << bitcast<u32>(13i)));
                                        }
                                        let _e5014 = phi_4274_;
                                        let _e5016 = local_611;
                                        phi_4277_ = (_e5016 * bitcast<f32>(_e5014));
                                    }
                                    let _e5024 = phi_4277_;
                                    let _e5025 = local_452;
                                    let _e5027 = local_445;
                                    local_455 = (_e5027[0] + (_e5025 * _e5024));
                                    let _e5030 = local_446;
                                    if _e5030 {
                                    } else {
                                        phi_6025_ = true;
                                        break;
                                    }
                                    let _e5031 = local_619[_e4986];
                                    local_456 = _e5031;
                                    let _e5032 = local_449;
                                    let _e5034 = (_e5032 >> bitcast<u32>(16i));
                                    local_612 = select(-1f, 1f, ((_e5034 & 32768u) == 0u));
                                    let _e5040 = ((_e5034 >> bitcast<u32>(10i)) & 31u);
                                    local_457 = _e5040;
                                    local_458 = (_e5034 & 1023u);
                                    if (_e5040 == 0u) {
                                        let _e5062 = local_458;
                                        let _e5064 = local_612;
                                        phi_4320_ = ((_e5064 * f32(_e5062)) * 0.000000059604645f);
                                    } else {
                                        let _e5043 = local_457;
                                        if (_e5043 == 31u) {
                                            let _e5053 = local_458;
                                            phi_4317_ = (2139095040u | (_e5053 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5045 = local_457;
                                            let _e5049 = local_458;
                                            phi_4317_ = (((_e5045 + 112u) << bitcast<u32>(23i)) | (_e5049 << bitcast<u32>(13i)));
                                        }
                                        let _e5058 = phi_4317_;
                                        let _e5060 = local_612;
                                        phi_4320_ = (_e5060 * bitcast<f32>(_e5058));
                                    }
                                    let _e5068 = phi_4320_;
                                    let _e5069 = local_456;
                                    let _e5071 = local_445;
                                    local_459 = (_e5071[1] + (_e5069 * _e5068));
                                    let _e5074 = local_446;
                                    if _e5074 {
                                    } else {
                                        phi_6025_ = true;
                                        break;
                                    }
                                    let _e5075 = local_619[_e4986];
                                    local_460 = _e5075;
                                    let _e5076 = local_451;
                                    let _e5077 = (_e5076 & 65535u);
                                    local_613 = select(-1f, 1f, ((_e5077 & 32768u) == 0u));
                                    let _e5083 = ((_e5077 >> bitcast<u32>(10i)) & 31u);
                                    local_461 = _e5083;
                                    local_462 = (_e5077 & 1023u);
                                    if (_e5083 == 0u) {
                                        let _e5105 = local_462;
                                        let _e5107 = local_613;
                                        phi_4363_ = ((_e5107 * f32(_e5105)) * 0.000000059604645f);
                                    } else {
                                        let _e5086 = local_461;
                                        if (_e5086 == 31u) {
                                            let _e5096 = local_462;
                                            phi_4360_ = (2139095040u | (_e5096 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5088 = local_461;
                                            let _e5092 = local_462;
                                            phi_4360_ = (((_e5088 + 112u) << bitcast<u32>(23i)) | (_e5092 << bitcast<u32>(13i)));
                                        }
                                        let _e5101 = phi_4360_;
                                        let _e5103 = local_613;
                                        phi_4363_ = (_e5103 * bitcast<f32>(_e5101));
                                    }
                                    let _e5111 = phi_4363_;
                                    let _e5112 = local_460;
                                    let _e5114 = local_445;
                                    local_463 = (_e5114[2] + (_e5112 * _e5111));
                                    let _e5117 = local_446;
                                    if _e5117 {
                                    } else {
                                        phi_6025_ = true;
                                        break;
                                    }
                                    let _e5118 = local_619[_e4986];
                                    local_464 = _e5118;
                                    let _e5119 = local_451;
                                    let _e5121 = (_e5119 >> bitcast<u32>(16i));
                                    local_614 = select(-1f, 1f, ((_e5121 & 32768u) == 0u));
                                    let _e5127 = ((_e5121 >> bitcast<u32>(10i)) & 31u);
                                    local_465 = _e5127;
                                    local_466 = (_e5121 & 1023u);
                                    if (_e5127 == 0u) {
                                        let _e5149 = local_466;
                                        let _e5151 = local_614;
                                        phi_4406_ = ((_e5151 * f32(_e5149)) * 0.000000059604645f);
                                    } else {
                                        let _e5130 = local_465;
                                        if (_e5130 == 31u) {
                                            let _e5140 = local_466;
                                            phi_4403_ = (2139095040u | (_e5140 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5132 = local_465;
                                            let _e5136 = local_466;
                                            phi_4403_ = (((_e5132 + 112u) << bitcast<u32>(23i)) | (_e5136 << bitcast<u32>(13i)));
                                        }
                                        let _e5145 = phi_4403_;
                                        let _e5147 = local_614;
                                        phi_4406_ = (_e5147 * bitcast<f32>(_e5145));
                                    }
                                    let _e5155 = phi_4406_;
                                    let _e5156 = local_464;
                                    let _e5158 = local_445;
                                    let _e5161 = local_455;
                                    let _e5162 = local_459;
                                    let _e5163 = local_463;
                                    let _e5165 = local_444;
                                    phi_4189_ = (_e5165 + 1u);
                                    phi_4192_ = array<f32, 4>(_e5161, _e5162, _e5163, (_e5158[3] + (_e5156 * _e5155)));
                                } else {
                                    phi_4189_ = u32();
                                    phi_4192_ = array<f32, 4>();
                                }
                                let _e5168 = phi_4189_;
                                let _e5170 = phi_4192_;
                                continue;
                                continuing {
                                    let _e5171 = local_446;
                                    phi_4188_ = _e5168;
                                    phi_4191_ = _e5170;
                                    phi_6025_ = _e4939;
                                    break if !(_e5171);
                                }
                            }
                            let _e5174 = phi_6025_;
                            phi_6062_ = _e5174;
                            if _e5174 {
                                break;
                            }
                            let _e5175 = local_445;
                            let _e5177 = local_445;
                            let _e5179 = local_445;
                            let _e5181 = local_445;
                            local_629 = array<f32, 4>(_e5175[0], _e5177[1], _e5179[2], _e5181[3]);
                            let _e5184 = local_83;
                            let _e5185 = (_e5184 + 10u);
                            local_467 = _e5185;
                            let _e5186 = local_4;
                            if (_e5185 < _e5186) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e5188 = local_467;
                            let _e5191 = global_7.member[_e5188];
                            local_468 = _e5191;
                            let _e5195 = global_3.member.member.member;
                            let _e5196 = local_73;
                            let _e5200 = local_73;
                            let _e5205 = local_73;
                            let _e5209 = (((_e5196[0] * _e5195[0]) + (_e5200[1] * _e5195[1])) + (_e5205[2] * _e5195[2]));
                            local_469 = _e5209;
                            if !((_e5209 == _e5209)) {
                                phi_5746_ = true;
                            } else {
                                let _e5212 = local_469;
                                phi_5746_ = (0f >= _e5212);
                            }
                            let _e5215 = phi_5746_;
                            let _e5216 = local_469;
                            local_615 = select(_e5216, 0f, _e5215);
                            local_630 = array<f32, 3>(0f, 0f, 0f);
                            phi_4448_ = 0u;
                            loop {
                                let _e5219 = phi_4448_;
                                local_470 = _e5219;
                                let _e5220 = local_470;
                                let _e5221 = (_e5220 < 3u);
                                local_471 = _e5221;
                                if _e5221 {
                                    let _e5222 = local_83;
                                    let _e5223 = local_470;
                                    let _e5224 = (_e5222 + _e5223);
                                    local_472 = _e5224;
                                    let _e5225 = local_4;
                                    if (_e5224 < _e5225) {
                                    } else {
                                        phi_6046_ = true;
                                        break;
                                    }
                                    let _e5227 = local_472;
                                    let _e5230 = global_7.member[_e5227];
                                    local_473 = bitcast<f32>(_e5230);
                                    let _e5232 = local_470;
                                    let _e5233 = (_e5232 < 4u);
                                    local_474 = _e5233;
                                    if _e5233 {
                                    } else {
                                        phi_6046_ = true;
                                        break;
                                    }
                                    let _e5234 = local_470;
                                    let _e5236 = local_627[_e5234];
                                    let _e5237 = local_473;
                                    local_475 = (_e5237 * _e5236);
                                    let _e5239 = local_474;
                                    if _e5239 {
                                    } else {
                                        phi_6046_ = true;
                                        break;
                                    }
                                    let _e5240 = local_470;
                                    let _e5242 = local_629[_e5240];
                                    let _e5243 = local_475;
                                    let _e5244 = (_e5243 * _e5242);
                                    local_476 = _e5244;
                                    let _e5245 = local_468;
                                    if ((_e5245 & 1u) == 0u) {
                                        let _e5248 = local_471;
                                        if _e5248 {
                                        } else {
                                            phi_6046_ = true;
                                            break;
                                        }
                                        let _e5249 = local_470;
                                        let _e5254 = global_3.member.member.member_4[_e5249];
                                        local_477 = _e5254;
                                        let _e5255 = local_471;
                                        if _e5255 {
                                        } else {
                                            phi_6046_ = true;
                                            break;
                                        }
                                        let _e5256 = local_470;
                                        let _e5261 = global_3.member.member.member_2[_e5256];
                                        let _e5262 = local_615;
                                        let _e5264 = local_477;
                                        let _e5266 = local_476;
                                        phi_4514_ = (_e5266 * (_e5264 + (_e5261 * _e5262)));
                                    } else {
                                        phi_4514_ = _e5244;
                                    }
                                    let _e5269 = phi_4514_;
                                    local_478 = _e5269;
                                    let _e5270 = local_83;
                                    let _e5272 = local_470;
                                    let _e5273 = ((_e5270 + 4u) + _e5272);
                                    local_479 = _e5273;
                                    let _e5274 = local_4;
                                    if (_e5273 < _e5274) {
                                    } else {
                                        phi_6046_ = true;
                                        break;
                                    }
                                    let _e5276 = local_479;
                                    let _e5279 = global_7.member[_e5276];
                                    local_480 = bitcast<f32>(_e5279);
                                    let _e5281 = local_474;
                                    if _e5281 {
                                    } else {
                                        phi_6046_ = true;
                                        break;
                                    }
                                    let _e5282 = local_470;
                                    let _e5284 = local_628[_e5282];
                                    let _e5285 = local_480;
                                    local_481 = (_e5285 * _e5284);
                                    let _e5287 = local_471;
                                    if _e5287 {
                                    } else {
                                        phi_6046_ = true;
                                        break;
                                    }
                                    let _e5288 = local_470;
                                    let _e5290 = local_478;
                                    let _e5291 = local_481;
                                    local_630[_e5288] = (_e5290 + _e5291);
                                    let _e5293 = local_470;
                                    phi_4449_ = (_e5293 + 1u);
                                } else {
                                    phi_4449_ = u32();
                                }
                                let _e5296 = phi_4449_;
                                continue;
                                continuing {
                                    let _e5297 = local_471;
                                    phi_4448_ = _e5296;
                                    phi_6046_ = _e5174;
                                    break if !(_e5297);
                                }
                            }
                            let _e5300 = phi_6046_;
                            phi_6062_ = _e5300;
                            if _e5300 {
                                break;
                            }
                            let _e5301 = local_468;
                            if ((_e5301 & 8u) == 0u) {
                                phi_4591_ = 1f;
                            } else {
                                let _e5304 = local_83;
                                let _e5305 = (_e5304 + 3u);
                                local_482 = _e5305;
                                let _e5306 = local_4;
                                if (_e5305 < _e5306) {
                                } else {
                                    phi_6062_ = true;
                                    break;
                                }
                                let _e5308 = local_482;
                                let _e5311 = global_7.member[_e5308];
                                let _e5314 = local_627[3u];
                                let _e5317 = local_629[3u];
                                let _e5318 = ((bitcast<f32>(_e5311) * _e5314) * _e5317);
                                let _e5320 = select(_e5318, 0f, (_e5318 < 0f));
                                phi_4591_ = select(_e5320, 1f, (_e5320 > 1f));
                            }
                            let _e5324 = phi_4591_;
                            let _e5325 = local_630;
                            local_631 = _e5325;
                            phi_6055_ = _e5300;
                            phi_4641_ = _e5324;
                            phi_4642_ = _e828;
                        } else {
                            let _e776 = global_3.member.member_2;
                            if ((_e776 & 255u) == 1u) {
                                phi_4630_ = true;
                            } else {
                                let _e779 = local_13;
                                let _e780 = local_8;
                                if (_e779 < _e780) {
                                } else {
                                    phi_6062_ = true;
                                    break;
                                }
                                let _e782 = local_13;
                                let _e785 = global_11.member[_e782];
                                let _e789 = ((bitcast<u32>(bitcast<f32>(_e785)) & 2139095040u) != 2139095040u);
                                if _e789 {
                                } else {
                                    local_631 = array<f32, 3>(0f, 0f, 0f);
                                }
                                phi_4630_ = _e789;
                            }
                            let _e791 = phi_4630_;
                            local_483 = _e791;
                            if _e791 {
                                let _e795 = global_3.member.member.member_6;
                                local_631 = array<f32, 3>(_e795[0], _e795[1], _e795[2]);
                            }
                            let _e800 = local_483;
                            phi_6055_ = _e747;
                            phi_4641_ = select(0f, 1f, _e800);
                            phi_4642_ = _e714;
                        }
                        let _e5327 = phi_6055_;
                        let _e5329 = phi_4641_;
                        let _e5331 = phi_4642_;
                        local_484 = _e5329;
                        local_485 = _e5331;
                        let _e5334 = global_3.member.member_2;
                        if ((_e5334 & 255u) == 1u) {
                            phi_4651_ = 0u;
                            loop {
                                let _e5481 = phi_4651_;
                                local_486 = _e5481;
                                let _e5482 = local_486;
                                let _e5483 = (_e5482 < 3u);
                                local_487 = _e5483;
                                if _e5483 {
                                    let _e5484 = local_13;
                                    let _e5486 = local_486;
                                    let _e5487 = ((3u * _e5484) + _e5486);
                                    local_488 = _e5487;
                                    let _e5488 = local_7;
                                    let _e5489 = (_e5487 < _e5488);
                                    local_489 = _e5489;
                                    if _e5489 {
                                    } else {
                                        phi_6052_ = true;
                                        break;
                                    }
                                    let _e5490 = local_488;
                                    let _e5493 = global_10.member[_e5490];
                                    local_490 = bitcast<f32>(_e5493);
                                    let _e5495 = local_487;
                                    if _e5495 {
                                    } else {
                                        phi_6052_ = true;
                                        break;
                                    }
                                    let _e5496 = local_486;
                                    let _e5498 = local_631[_e5496];
                                    let _e5499 = local_484;
                                    let _e5501 = local_490;
                                    local_491 = bitcast<u32>((_e5501 + (_e5499 * _e5498)));
                                    let _e5504 = local_489;
                                    if _e5504 {
                                    } else {
                                        phi_6052_ = true;
                                        break;
                                    }
                                    let _e5505 = local_491;
                                    global_10.member[_e5490] = _e5505;
                                    let _e5506 = local_486;
                                    phi_4652_ = (_e5506 + 1u);
                                } else {
                                    phi_4652_ = u32();
                                }
                                let _e5509 = phi_4652_;
                                continue;
                                continuing {
                                    let _e5510 = local_487;
                                    phi_4651_ = _e5509;
                                    phi_6052_ = _e5327;
                                    break if !(_e5510);
                                }
                            }
                            let _e5513 = phi_6052_;
                            phi_6062_ = _e5513;
                            if _e5513 {
                                break;
                            }
                            phi_6065_ = _e5513;
                        } else {
                            let _e5337 = local_13;
                            let _e5338 = (_e5337 * 5u);
                            local_492 = _e5338;
                            let _e5340 = local_631[0u];
                            local_493 = bitcast<u32>(_e5340);
                            let _e5342 = local_7;
                            if (_e5338 < _e5342) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e5344 = local_492;
                            let _e5347 = local_493;
                            global_10.member[_e5344] = _e5347;
                            let _e5348 = local_492;
                            let _e5349 = (_e5348 + 1u);
                            local_494 = _e5349;
                            let _e5351 = local_631[1u];
                            local_495 = bitcast<u32>(_e5351);
                            let _e5353 = local_7;
                            if (_e5349 < _e5353) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e5355 = local_494;
                            let _e5358 = local_495;
                            global_10.member[_e5355] = _e5358;
                            let _e5359 = local_492;
                            let _e5360 = (_e5359 + 2u);
                            local_496 = _e5360;
                            let _e5362 = local_631[2u];
                            local_497 = bitcast<u32>(_e5362);
                            let _e5364 = local_7;
                            if (_e5360 < _e5364) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e5366 = local_496;
                            let _e5369 = local_497;
                            global_10.member[_e5366] = _e5369;
                            let _e5370 = local_492;
                            let _e5371 = (_e5370 + 3u);
                            local_498 = _e5371;
                            let _e5372 = local_484;
                            local_499 = bitcast<u32>(_e5372);
                            let _e5374 = local_7;
                            if (_e5371 < _e5374) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e5376 = local_498;
                            let _e5379 = local_499;
                            global_10.member[_e5376] = _e5379;
                            let _e5380 = local_492;
                            let _e5381 = (_e5380 + 4u);
                            local_500 = _e5381;
                            let _e5382 = local_485;
                            local_501 = bitcast<u32>(_e5382);
                            let _e5384 = local_7;
                            if (_e5381 < _e5384) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e5386 = local_500;
                            let _e5389 = local_501;
                            global_10.member[_e5386] = _e5389;
                            let _e5392 = global_3.member.member_4;
                            local_502 = _e5392;
                            let _e5393 = local_16;
                            if _e5393 {
                                let _e5394 = local_484;
                                if (_e5394 < 1f) {
                                    phi_4865_ = _e5331;
                                } else {
                                    let _e5396 = local_485;
                                    let _e5397 = local_502;
                                    local_503 = (_e5396 * _e5397);
                                    let _e5399 = local_501;
                                    if (_e5399 == 0u) {
                                        phi_4806_ = false;
                                    } else {
                                        let _e5401 = local_501;
                                        phi_4806_ = (_e5401 <= 2139095040u);
                                    }
                                    let _e5404 = phi_4806_;
                                    if _e5404 {
                                        let _e5405 = local_503;
                                        if (_e5405 >= 0f) {
                                            let _e5407 = local_503;
                                            let _e5410 = ((bitcast<u32>(_e5407) & 2147483647u) > 2139095040u);
                                            if _e5410 {
                                                phi_4837_ = f32();
                                                phi_4838_ = f32();
                                                phi_4839_ = false;
                                            } else {
                                                let _e5411 = local_503;
                                                let _e5412 = (_e5411 == 0f);
                                                local_504 = _e5412;
                                                if _e5412 {
                                                    phi_4835_ = f32();
                                                    phi_4836_ = true;
                                                } else {
                                                    let _e5416 = global_3.member.member_3.member_1;
                                                    local_505 = _e5416;
                                                    let _e5417 = local_503;
                                                    let _e5418 = (_e5417 >= _e5416);
                                                    if _e5418 {
                                                        phi_4833_ = f32();
                                                    } else {
                                                        let _e5419 = local_503;
                                                        let _e5420 = local_485;
                                                        let _e5422 = local_505;
                                                        let _e5423 = local_503;
                                                        phi_4833_ = ((_e5419 * _e5420) / (_e5422 - _e5423));
                                                    }
                                                    let _e5427 = phi_4833_;
                                                    phi_4835_ = _e5427;
                                                    phi_4836_ = _e5418;
                                                }
                                                let _e5429 = phi_4835_;
                                                let _e5431 = phi_4836_;
                                                let _e5432 = local_504;
                                                let _e5433 = local_617;
                                                phi_4837_ = select(_e5433, 0f, _e5432);
                                                phi_4838_ = _e5429;
                                                phi_4839_ = _e5431;
                                            }
                                            let _e5436 = phi_4837_;
                                            let _e5438 = phi_4838_;
                                            let _e5440 = phi_4839_;
                                            phi_4840_ = _e5436;
                                            phi_4841_ = _e5438;
                                            phi_4842_ = _e5410;
                                            phi_4843_ = _e5440;
                                        } else {
                                            phi_4840_ = f32();
                                            phi_4841_ = f32();
                                            phi_4842_ = true;
                                            phi_4843_ = false;
                                        }
                                        let _e5442 = phi_4840_;
                                        let _e5444 = phi_4841_;
                                        let _e5446 = phi_4842_;
                                        let _e5448 = phi_4843_;
                                        phi_4844_ = _e5442;
                                        phi_4845_ = _e5444;
                                        phi_4846_ = _e5446;
                                        phi_4847_ = _e5448;
                                    } else {
                                        phi_4844_ = f32();
                                        phi_4845_ = f32();
                                        phi_4846_ = true;
                                        phi_4847_ = false;
                                    }
                                    let _e5450 = phi_4844_;
                                    let _e5452 = phi_4845_;
                                    let _e5454 = phi_4846_;
                                    let _e5456 = phi_4847_;
                                    let _e5457 = local_616;
                                    let _e5461 = local_485;
                                    let _e5462 = (_e5461 + select(_e5452, select(_e5450, _e5457, _e5454), select(_e5456, true, _e5454)));
                                    let _e5466 = local_617;
                                    phi_4865_ = select(_e5466, _e5462, ((bitcast<u32>(_e5462) & 2139095040u) != 2139095040u));
                                }
                                let _e5469 = phi_4865_;
                                phi_4866_ = _e5469;
                            } else {
                                phi_4866_ = _e714;
                            }
                            let _e5471 = phi_4866_;
                            local_506 = bitcast<u32>(_e5471);
                            let _e5473 = local_13;
                            let _e5474 = local_8;
                            if (_e5473 < _e5474) {
                            } else {
                                phi_6062_ = true;
                                break;
                            }
                            let _e5476 = local_13;
                            let _e5479 = local_506;
                            global_11.member[_e5476] = _e5479;
                            phi_6065_ = _e5327;
                        }
                        let _e5515 = phi_6065_;
                        phi_6064_ = _e5515;
                    } else {
                        phi_6064_ = _e747;
                    }
                    let _e5517 = phi_6064_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e5518 = local_11;
                    let _e5519 = local_10;
                    phi_6063_ = _e5517;
                    phi_275_ = (_e5518 + _e5519);
                } else {
                    phi_6063_ = _e747;
                    phi_275_ = u32();
                }
                let _e5522 = phi_6063_;
                let _e5524 = phi_275_;
                continue;
                continuing {
                    let _e5525 = local_12;
                    phi_5773_ = _e5522;
                    phi_274_ = _e5524;
                    phi_6062_ = _e5522;
                    break if !(_e5525);
                }
            }
            let _e5528 = phi_6062_;
            if _e5528 {
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
