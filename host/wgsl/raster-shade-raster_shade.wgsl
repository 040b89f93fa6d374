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
    var local_33: array<u32, 4>;
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
    var local_49: u32;
    var local_50: f32;
    var local_51: u32;
    var local_52: u32;
    var local_53: bool;
    var local_54: u32;
    var local_55: u32;
    var local_56: bool;
    var local_57: f32;
    var local_58: f32;
    var local_59: f32;
    var local_60: u32;
    var local_61: f32;
    var local_62: f32;
    var local_63: f32;
    var local_64: f32;
    var local_65: f32;
    var local_66: f32;
    var local_67: f32;
    var local_68: array<f32, 3>;
    var local_69: f32;
    var local_70: f32;
    var local_71: f32;
    var local_72: array<f32, 3>;
    var local_73: u32;
    var local_74: f32;
    var local_75: f32;
    var local_76: bool;
    var local_77: u32;
    var local_78: f32;
    var local_79: u32;
    var local_80: f32;
    var local_81: u32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: f32;
    var local_90: u32;
    var local_91: f32;
    var local_92: u32;
    var local_93: u32;
    var local_94: f32;
    var local_95: u32;
    var local_96: f32;
    var local_97: u32;
    var local_98: u32;
    var local_99: f32;
    var local_100: u32;
    var local_101: f32;
    var local_102: type_5;
    var local_103: u32;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: f32;
    var local_112: f32;
    var local_113: f32;
    var local_114: f32;
    var local_115: f32;
    var local_116: f32;
    var local_117: f32;
    var local_118: bool;
    var local_119: f32;
    var local_120: u32;
    var local_121: f32;
    var local_122: f32;
    var local_123: u32;
    var local_124: f32;
    var local_125: u32;
    var local_126: u32;
    var local_127: f32;
    var local_128: f32;
    var local_129: u32;
    var local_130: u32;
    var local_131: bool;
    var local_132: f32;
    var local_133: u32;
    var local_134: bool;
    var local_135: u32;
    var local_136: type_5;
    var local_137: bool;
    var local_138: f32;
    var local_139: u32;
    var local_140: bool;
    var local_141: f32;
    var local_142: f32;
    var local_143: u32;
    var local_144: type_5;
    var local_145: bool;
    var local_146: type_22;
    var local_147: f32;
    var local_148: u32;
    var local_149: f32;
    var local_150: u32;
    var local_151: f32;
    var local_152: f32;
    var local_153: f32;
    var local_154: f32;
    var local_155: f32;
    var local_156: i32;
    var local_157: i32;
    var local_158: u32;
    var local_159: i32;
    var local_160: bool;
    var local_161: i32;
    var local_162: bool;
    var local_163: bool;
    var local_164: i32;
    var local_165: i32;
    var local_166: bool;
    var local_167: bool;
    var local_168: i32;
    var local_169: u32;
    var local_170: i32;
    var local_171: i32;
    var local_172: bool;
    var local_173: bool;
    var local_174: i32;
    var local_175: i32;
    var local_176: bool;
    var local_177: bool;
    var local_178: i32;
    var local_179: u32;
    var local_180: u32;
    var local_181: i32;
    var local_182: bool;
    var local_183: i32;
    var local_184: bool;
    var local_185: bool;
    var local_186: i32;
    var local_187: i32;
    var local_188: bool;
    var local_189: bool;
    var local_190: i32;
    var local_191: u32;
    var local_192: i32;
    var local_193: i32;
    var local_194: bool;
    var local_195: bool;
    var local_196: i32;
    var local_197: i32;
    var local_198: bool;
    var local_199: bool;
    var local_200: i32;
    var local_201: u32;
    var local_202: u32;
    var local_203: u32;
    var local_204: u32;
    var local_205: u32;
    var local_206: u32;
    var local_207: u32;
    var local_208: u32;
    var local_209: u32;
    var local_210: f32;
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
    var local_222: u32;
    var local_223: u32;
    var local_224: u32;
    var local_225: u32;
    var local_226: f32;
    var local_227: u32;
    var local_228: u32;
    var local_229: f32;
    var local_230: u32;
    var local_231: u32;
    var local_232: f32;
    var local_233: u32;
    var local_234: u32;
    var local_235: f32;
    var local_236: f32;
    var local_237: f32;
    var local_238: f32;
    var local_239: u32;
    var local_240: u32;
    var local_241: u32;
    var local_242: u32;
    var local_243: u32;
    var local_244: u32;
    var local_245: u32;
    var local_246: f32;
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
    var local_258: u32;
    var local_259: u32;
    var local_260: u32;
    var local_261: u32;
    var local_262: f32;
    var local_263: u32;
    var local_264: u32;
    var local_265: f32;
    var local_266: u32;
    var local_267: u32;
    var local_268: f32;
    var local_269: u32;
    var local_270: u32;
    var local_271: u32;
    var local_272: u32;
    var local_273: u32;
    var local_274: u32;
    var local_275: u32;
    var local_276: u32;
    var local_277: u32;
    var local_278: u32;
    var local_279: f32;
    var local_280: f32;
    var local_281: f32;
    var local_282: f32;
    var local_283: f32;
    var local_284: f32;
    var local_285: f32;
    var local_286: bool;
    var local_287: f32;
    var local_288: u32;
    var local_289: f32;
    var local_290: f32;
    var local_291: u32;
    var local_292: f32;
    var local_293: u32;
    var local_294: u32;
    var local_295: f32;
    var local_296: f32;
    var local_297: u32;
    var local_298: u32;
    var local_299: bool;
    var local_300: f32;
    var local_301: u32;
    var local_302: bool;
    var local_303: u32;
    var local_304: type_5;
    var local_305: bool;
    var local_306: f32;
    var local_307: u32;
    var local_308: bool;
    var local_309: f32;
    var local_310: f32;
    var local_311: u32;
    var local_312: type_5;
    var local_313: bool;
    var local_314: type_22;
    var local_315: f32;
    var local_316: u32;
    var local_317: f32;
    var local_318: u32;
    var local_319: f32;
    var local_320: f32;
    var local_321: f32;
    var local_322: f32;
    var local_323: f32;
    var local_324: i32;
    var local_325: i32;
    var local_326: u32;
    var local_327: i32;
    var local_328: bool;
    var local_329: i32;
    var local_330: bool;
    var local_331: bool;
    var local_332: i32;
    var local_333: i32;
    var local_334: bool;
    var local_335: bool;
    var local_336: i32;
    var local_337: u32;
    var local_338: i32;
    var local_339: i32;
    var local_340: bool;
    var local_341: bool;
    var local_342: i32;
    var local_343: i32;
    var local_344: bool;
    var local_345: bool;
    var local_346: i32;
    var local_347: u32;
    var local_348: u32;
    var local_349: i32;
    var local_350: bool;
    var local_351: i32;
    var local_352: bool;
    var local_353: bool;
    var local_354: i32;
    var local_355: i32;
    var local_356: bool;
    var local_357: bool;
    var local_358: i32;
    var local_359: u32;
    var local_360: i32;
    var local_361: i32;
    var local_362: bool;
    var local_363: bool;
    var local_364: i32;
    var local_365: i32;
    var local_366: bool;
    var local_367: bool;
    var local_368: i32;
    var local_369: u32;
    var local_370: u32;
    var local_371: u32;
    var local_372: u32;
    var local_373: u32;
    var local_374: u32;
    var local_375: u32;
    var local_376: u32;
    var local_377: u32;
    var local_378: f32;
    var local_379: u32;
    var local_380: u32;
    var local_381: f32;
    var local_382: u32;
    var local_383: u32;
    var local_384: f32;
    var local_385: u32;
    var local_386: u32;
    var local_387: f32;
    var local_388: u32;
    var local_389: u32;
    var local_390: u32;
    var local_391: u32;
    var local_392: u32;
    var local_393: u32;
    var local_394: f32;
    var local_395: u32;
    var local_396: u32;
    var local_397: f32;
    var local_398: u32;
    var local_399: u32;
    var local_400: f32;
    var local_401: u32;
    var local_402: u32;
    var local_403: f32;
    var local_404: f32;
    var local_405: f32;
    var local_406: f32;
    var local_407: u32;
    var local_408: u32;
    var local_409: u32;
    var local_410: u32;
    var local_411: u32;
    var local_412: u32;
    var local_413: u32;
    var local_414: f32;
    var local_415: u32;
    var local_416: u32;
    var local_417: f32;
    var local_418: u32;
    var local_419: u32;
    var local_420: f32;
    var local_421: u32;
    var local_422: u32;
    var local_423: f32;
    var local_424: u32;
    var local_425: u32;
    var local_426: u32;
    var local_427: u32;
    var local_428: u32;
    var local_429: u32;
    var local_430: f32;
    var local_431: u32;
    var local_432: u32;
    var local_433: f32;
    var local_434: u32;
    var local_435: u32;
    var local_436: f32;
    var local_437: u32;
    var local_438: u32;
    var local_439: u32;
    var local_440: array<f32, 4>;
    var local_441: bool;
    var local_442: u32;
    var local_443: u32;
    var local_444: u32;
    var local_445: u32;
    var local_446: u32;
    var local_447: f32;
    var local_448: u32;
    var local_449: u32;
    var local_450: f32;
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
    var local_462: u32;
    var local_463: u32;
    var local_464: f32;
    var local_465: u32;
    var local_466: bool;
    var local_467: u32;
    var local_468: f32;
    var local_469: bool;
    var local_470: f32;
    var local_471: f32;
    var local_472: f32;
    var local_473: f32;
    var local_474: u32;
    var local_475: f32;
    var local_476: f32;
    var local_477: u32;
    var local_478: bool;
    var local_479: f32;
    var local_480: f32;
    var local_481: u32;
    var local_482: bool;
    var local_483: u32;
    var local_484: bool;
    var local_485: f32;
    var local_486: u32;
    var local_487: u32;
    var local_488: u32;
    var local_489: u32;
    var local_490: u32;
    var local_491: u32;
    var local_492: u32;
    var local_493: u32;
    var local_494: u32;
    var local_495: u32;
    var local_496: u32;
    var local_497: f32;
    var local_498: f32;
    var local_499: bool;
    var local_500: f32;
    var local_501: u32;
    var local_502: f32;
    var local_503: f32;
    var local_504: f32;
    var local_505: f32;
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
    var local_520: bool;
    var local_521: f32;
    var local_522: f32;
    var local_523: f32;
    var local_524: bool;
    var local_525: f32;
    var local_526: f32;
    var local_527: f32;
    var local_528: f32;
    var local_529: f32;
    var local_530: f32;
    var local_531: u32;
    var local_532: type_22;
    var local_533: bool;
    var local_534: u32;
    var local_535: u32;
    var local_536: type_22;
    var local_537: type_22;
    var local_538: u32;
    var local_539: type_22;
    var local_540: bool;
    var local_541: u32;
    var local_542: u32;
    var local_543: type_22;
    var local_544: type_22;
    var local_545: u32;
    var local_546: type_22;
    var local_547: bool;
    var local_548: u32;
    var local_549: u32;
    var local_550: type_22;
    var local_551: type_22;
    var local_552: u32;
    var local_553: type_22;
    var local_554: bool;
    var local_555: u32;
    var local_556: u32;
    var local_557: type_22;
    var local_558: type_22;
    var local_559: u32;
    var local_560: f32;
    var local_561: f32;
    var local_562: f32;
    var local_563: u32;
    var local_564: u32;
    var local_565: f32;
    var local_566: f32;
    var local_567: f32;
    var local_568: f32;
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
    var local_581: u32;
    var local_582: f32;
    var local_583: f32;
    var local_584: f32;
    var local_585: u32;
    var local_586: u32;
    var local_587: f32;
    var local_588: f32;
    var local_589: f32;
    var local_590: f32;
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
    var local_610: array<u32, 4>;
    var local_611: array<f32, 3>;
    var local_612: array<u32, 4>;
    var local_613: array<f32, 3>;
    var local_614: array<u32, 4>;
    var local_615: array<f32, 3>;
    var local_616: array<array<f32, 3>, 3>;
    var local_617: array<f32, 3>;
    var local_618: array<f32, 3>;
    var local_619: array<f32, 4>;
    var local_620: array<f32, 4>;
    var local_621: array<f32, 4>;
    var local_622: array<f32, 3>;
    var local_623: array<f32, 3>;
    var phi_5694_: bool;
    var phi_274_: u32;
    var phi_4554_: bool;
    var phi_5693_: bool;
    var phi_633_: u32;
    var phi_651_: u32;
    var phi_652_: u32;
    var phi_5690_: bool;
    var phi_5696_: bool;
    var phi_634_: u32;
    var phi_5695_: bool;
    var phi_5186_: array<f32, 3>;
    var phi_5160_: array<f32, 3>;
    var phi_813_: array<f32, 3>;
    var phi_844_: array<f32, 3>;
    var phi_862_: u32;
    var phi_865_: f32;
    var phi_867_: f32;
    var phi_863_: u32;
    var phi_866_: f32;
    var phi_868_: f32;
    var phi_5697_: bool;
    var phi_979_: bool;
    var phi_5279_: f32;
    var phi_5288_: f32;
    var phi_5290_: f32;
    var phi_5396_: type_5;
    var phi_5400_: type_5;
    var phi_5401_: bool;
    var phi_5405_: type_5;
    var phi_1129_: type_5;
    var phi_1239_: bool;
    var phi_1278_: bool;
    var phi_1347_: u32;
    var phi_1371_: u32;
    var phi_1304_: u32;
    var phi_1328_: u32;
    var phi_1372_: u32;
    var phi_1373_: u32;
    var phi_1374_: u32;
    var phi_1375_: u32;
    var phi_1388_: f32;
    var phi_1409_: f32;
    var phi_1425_: f32;
    var phi_5506_: u32;
    var phi_5507_: type_22;
    var phi_5524_: u32;
    var phi_5533_: u32;
    var phi_5538_: u32;
    var phi_5539_: type_22;
    var phi_5545_: u32;
    var phi_5546_: type_22;
    var phi_5563_: u32;
    var phi_5572_: u32;
    var phi_5577_: u32;
    var phi_5578_: type_22;
    var phi_1441_: bool;
    var phi_5751_: bool;
    var phi_1444_: u32;
    var phi_1447_: type_5;
    var phi_5750_: bool;
    var phi_1461_: u32;
    var phi_1464_: type_5;
    var phi_1490_: u32;
    var phi_1493_: type_5;
    var phi_1506_: type_22;
    var phi_1507_: f32;
    var phi_1527_: f32;
    var phi_1528_: f32;
    var phi_1599_: i32;
    var phi_1623_: i32;
    var phi_1563_: i32;
    var phi_1564_: i32;
    var phi_1624_: i32;
    var phi_1679_: i32;
    var phi_1703_: i32;
    var phi_1643_: i32;
    var phi_1644_: i32;
    var phi_1704_: i32;
    var phi_1758_: i32;
    var phi_1782_: i32;
    var phi_1722_: i32;
    var phi_1723_: i32;
    var phi_1783_: i32;
    var phi_1838_: i32;
    var phi_1862_: i32;
    var phi_1802_: i32;
    var phi_1803_: i32;
    var phi_1863_: i32;
    var phi_1930_: u32;
    var phi_1933_: f32;
    var phi_1962_: u32;
    var phi_1965_: f32;
    var phi_1994_: u32;
    var phi_1997_: f32;
    var phi_2026_: u32;
    var phi_2029_: f32;
    var phi_2095_: u32;
    var phi_2098_: f32;
    var phi_2127_: u32;
    var phi_2130_: f32;
    var phi_2159_: u32;
    var phi_2162_: f32;
    var phi_2191_: u32;
    var phi_2194_: f32;
    var phi_2272_: u32;
    var phi_2275_: f32;
    var phi_2304_: u32;
    var phi_2307_: f32;
    var phi_2336_: u32;
    var phi_2339_: f32;
    var phi_2368_: u32;
    var phi_2371_: f32;
    var phi_2437_: u32;
    var phi_2440_: f32;
    var phi_2469_: u32;
    var phi_2472_: f32;
    var phi_2501_: u32;
    var phi_2504_: f32;
    var phi_2533_: u32;
    var phi_2536_: f32;
    var phi_1491_: u32;
    var phi_1494_: type_5;
    var phi_5704_: bool;
    var phi_5819_: bool;
    var phi_1462_: u32;
    var phi_1465_: type_5;
    var phi_5818_: bool;
    var phi_5821_: bool;
    var phi_1445_: u32;
    var phi_1448_: type_5;
    var phi_5820_: bool;
    var phi_5895_: bool;
    var phi_2589_: type_5;
    var phi_5894_: bool;
    var phi_2590_: type_5;
    var phi_2591_: bool;
    var phi_2595_: type_5;
    var phi_5892_: bool;
    var phi_2596_: type_5;
    var phi_5891_: bool;
    var phi_2597_: type_5;
    var phi_2598_: bool;
    var phi_2602_: type_5;
    var phi_2722_: bool;
    var phi_2761_: bool;
    var phi_2830_: u32;
    var phi_2854_: u32;
    var phi_2787_: u32;
    var phi_2811_: u32;
    var phi_2855_: u32;
    var phi_2856_: u32;
    var phi_2857_: u32;
    var phi_2858_: u32;
    var phi_2871_: f32;
    var phi_2892_: f32;
    var phi_2908_: f32;
    var phi_5584_: u32;
    var phi_5585_: type_22;
    var phi_5602_: u32;
    var phi_5611_: u32;
    var phi_5616_: u32;
    var phi_5617_: type_22;
    var phi_5623_: u32;
    var phi_5624_: type_22;
    var phi_5641_: u32;
    var phi_5650_: u32;
    var phi_5655_: u32;
    var phi_5656_: type_22;
    var phi_2924_: bool;
    var phi_5869_: bool;
    var phi_2927_: u32;
    var phi_2930_: type_5;
    var phi_5868_: bool;
    var phi_2944_: u32;
    var phi_2947_: type_5;
    var phi_2973_: u32;
    var phi_2976_: type_5;
    var phi_2989_: type_22;
    var phi_2990_: f32;
    var phi_3010_: f32;
    var phi_3011_: f32;
    var phi_3082_: i32;
    var phi_3106_: i32;
    var phi_3046_: i32;
    var phi_3047_: i32;
    var phi_3107_: i32;
    var phi_3162_: i32;
    var phi_3186_: i32;
    var phi_3126_: i32;
    var phi_3127_: i32;
    var phi_3187_: i32;
    var phi_3241_: i32;
    var phi_3265_: i32;
    var phi_3205_: i32;
    var phi_3206_: i32;
    var phi_3266_: i32;
    var phi_3321_: i32;
    var phi_3345_: i32;
    var phi_3285_: i32;
    var phi_3286_: i32;
    var phi_3346_: i32;
    var phi_3413_: u32;
    var phi_3416_: f32;
    var phi_3445_: u32;
    var phi_3448_: f32;
    var phi_3477_: u32;
    var phi_3480_: f32;
    var phi_3509_: u32;
    var phi_3512_: f32;
    var phi_3578_: u32;
    var phi_3581_: f32;
    var phi_3610_: u32;
    var phi_3613_: f32;
    var phi_3642_: u32;
    var phi_3645_: f32;
    var phi_3674_: u32;
    var phi_3677_: f32;
    var phi_3755_: u32;
    var phi_3758_: f32;
    var phi_3787_: u32;
    var phi_3790_: f32;
    var phi_3819_: u32;
    var phi_3822_: f32;
    var phi_3851_: u32;
    var phi_3854_: f32;
    var phi_3920_: u32;
    var phi_3923_: f32;
    var phi_3952_: u32;
    var phi_3955_: f32;
    var phi_3984_: u32;
    var phi_3987_: f32;
    var phi_4016_: u32;
    var phi_4019_: f32;
    var phi_2974_: u32;
    var phi_2977_: type_5;
    var phi_5822_: bool;
    var phi_5935_: bool;
    var phi_2945_: u32;
    var phi_2948_: type_5;
    var phi_5934_: bool;
    var phi_5937_: bool;
    var phi_2928_: u32;
    var phi_2931_: type_5;
    var phi_5936_: bool;
    var phi_5954_: bool;
    var phi_4072_: type_5;
    var phi_5953_: bool;
    var phi_4073_: type_5;
    var phi_4074_: bool;
    var phi_4078_: type_5;
    var phi_5951_: bool;
    var phi_4079_: type_5;
    var phi_5950_: bool;
    var phi_4080_: type_5;
    var phi_4081_: bool;
    var phi_4085_: type_5;
    var phi_4113_: u32;
    var phi_4116_: array<f32, 4>;
    var phi_4199_: u32;
    var phi_4202_: f32;
    var phi_4242_: u32;
    var phi_4245_: f32;
    var phi_4285_: u32;
    var phi_4288_: f32;
    var phi_4328_: u32;
    var phi_4331_: f32;
    var phi_4114_: u32;
    var phi_4117_: array<f32, 4>;
    var phi_5938_: bool;
    var phi_5669_: bool;
    var phi_4373_: u32;
    var phi_4439_: f32;
    var phi_4374_: u32;
    var phi_5959_: bool;
    var phi_4516_: f32;
    var phi_5968_: bool;
    var phi_4565_: f32;
    var phi_4566_: f32;
    var phi_4729_: bool;
    var phi_4756_: f32;
    var phi_4758_: f32;
    var phi_4759_: bool;
    var phi_4760_: f32;
    var phi_4761_: f32;
    var phi_4762_: bool;
    var phi_4763_: f32;
    var phi_4764_: f32;
    var phi_4765_: bool;
    var phi_4766_: bool;
    var phi_4767_: f32;
    var phi_4768_: f32;
    var phi_4769_: bool;
    var phi_4770_: bool;
    var phi_4788_: f32;
    var phi_4789_: f32;
    var phi_4574_: u32;
    var phi_4575_: u32;
    var phi_5965_: bool;
    var phi_5978_: bool;
    var phi_5977_: bool;
    var phi_5976_: bool;
    var phi_275_: u32;
    var phi_5975_: bool;
    var local_624: type_22;
    var local_625: type_22;
    var local_626: type_5;
    var local_627: type_5;
    var local_628: type_22;
    var local_629: type_22;
    var local_630: type_5;
    var local_631: type_5;

    let _e704 = global_12;
    local_608 = bitcast<f32>(_e704);
    let _e706 = global_13;
    let _e707 = bitcast<f32>(_e706);
    local_609 = _e707;
    switch bitcast<i32>(0u) {
        default: {
            let _e709 = global;
            local = _e709;
            let _e710 = global_1;
            let _e711 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_9.member));
            local_7 = arrayLength((&global_10.member));
            local_8 = arrayLength((&global_11.member));
            let _e732 = global_3.member.member_5;
            let _e735 = global_3.member.member_6;
            local_9 = (_e732 * _e735);
            local_10 = (_e711.x * 256u);
            phi_5694_ = false;
            phi_274_ = (_e710.x * 256u);
            loop {
                let _e740 = phi_5694_;
                let _e742 = phi_274_;
                local_11 = _e742;
                let _e743 = local_11;
                let _e744 = local_9;
                let _e745 = (_e743 < _e744);
                local_12 = _e745;
                if _e745 {
                    let _e746 = local_11;
                    let _e747 = local;
                    let _e748 = (_e746 + _e747);
                    local_13 = _e748;
                    let _e749 = local_9;
                    if (_e748 < _e749) {
                        let _e751 = local_13;
                        let _e752 = (_e751 * 4u);
                        local_14 = _e752;
                        let _e753 = local_1;
                        if (_e752 < _e753) {
                        } else {
                            phi_5975_ = true;
                            break;
                        }
                        let _e755 = local_14;
                        let _e758 = global_4.member[_e755];
                        let _e759 = bitcast<f32>(_e758);
                        let _e764 = select(select(u32(_e759), 0u, (_e759 < 0f)), 4294967295u, (_e759 > 4294967000f));
                        local_15 = _e764;
                        let _e765 = (_e764 > 0u);
                        local_16 = _e765;
                        if _e765 {
                            let _e793 = local_14;
                            let _e794 = (_e793 + 2u);
                            local_17 = _e794;
                            let _e795 = local_1;
                            if (_e794 < _e795) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e797 = local_17;
                            let _e800 = global_4.member[_e797];
                            local_18 = bitcast<f32>(_e800);
                            let _e802 = local_14;
                            let _e803 = (_e802 + 3u);
                            local_19 = _e803;
                            let _e804 = local_1;
                            if (_e803 < _e804) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e806 = local_19;
                            let _e809 = global_4.member[_e806];
                            local_20 = bitcast<f32>(_e809);
                            let _e811 = local_14;
                            let _e812 = (_e811 + 1u);
                            local_21 = _e812;
                            let _e813 = local_1;
                            if (_e812 < _e813) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e815 = local_21;
                            let _e818 = global_4.member[_e815];
                            let _e819 = bitcast<f32>(_e818);
                            let _e822 = global_3.member.member_4;
                            local_22 = ((2f * _e822) * _e819);
                            let _e827 = global_3.member.member_1;
                            local_23 = _e827;
                            let _e830 = global_3.member.member_8;
                            local_24 = _e830;
                            let _e833 = global_3.member.member_7;
                            local_25 = _e833;
                            let _e834 = local_15;
                            let _e836 = ((_e834 - 1u) * 4u);
                            local_26 = _e836;
                            let _e837 = local_3;
                            if (_e836 < _e837) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e839 = local_26;
                            let _e842 = global_6.member[_e839];
                            local_27 = _e842;
                            let _e843 = local_26;
                            let _e844 = (_e843 + 1u);
                            local_28 = _e844;
                            let _e845 = local_3;
                            if (_e844 < _e845) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e847 = local_28;
                            let _e850 = global_6.member[_e847];
                            local_29 = _e850;
                            let _e851 = local_26;
                            let _e852 = (_e851 + 2u);
                            local_30 = _e852;
                            let _e853 = local_3;
                            if (_e852 < _e853) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e855 = local_30;
                            let _e858 = global_6.member[_e855];
                            local_31 = _e858;
                            let _e859 = local_26;
                            let _e860 = (_e859 + 3u);
                            local_32 = _e860;
                            let _e861 = local_3;
                            if (_e860 < _e861) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e863 = local_32;
                            let _e866 = global_6.member[_e863];
                            let _e867 = local_27;
                            let _e868 = local_29;
                            let _e869 = local_31;
                            let _e870 = array<u32, 4>(_e867, _e868, _e869, _e866);
                            local_33 = _e870;
                            local_614 = _e870;
                            let _e871 = local_18;
                            let _e873 = local_20;
                            let _e874 = ((1f - _e871) - _e873);
                            local_34 = _e874;
                            let _e876 = local_18;
                            local_615[0u] = _e876;
                            let _e878 = local_20;
                            local_615[1u] = _e878;
                            local_615[2u] = _e874;
                            let _e881 = local_614[0u];
                            let _e882 = (_e881 * 10u);
                            local_35 = _e882;
                            let _e883 = local_2;
                            if (_e882 < _e883) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e885 = local_35;
                            let _e888 = global_5.member[_e885];
                            local_36 = bitcast<f32>(_e888);
                            let _e890 = local_35;
                            let _e891 = (_e890 + 1u);
                            local_37 = _e891;
                            let _e892 = local_2;
                            if (_e891 < _e892) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e894 = local_37;
                            let _e897 = global_5.member[_e894];
                            local_38 = bitcast<f32>(_e897);
                            let _e899 = local_35;
                            let _e900 = (_e899 + 2u);
                            local_39 = _e900;
                            let _e901 = local_2;
                            if (_e900 < _e901) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e903 = local_39;
                            let _e906 = global_5.member[_e903];
                            local_40 = bitcast<f32>(_e906);
                            let _e909 = local_614[1u];
                            let _e910 = (_e909 * 10u);
                            local_41 = _e910;
                            let _e911 = local_2;
                            if (_e910 < _e911) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e913 = local_41;
                            let _e916 = global_5.member[_e913];
                            local_42 = bitcast<f32>(_e916);
                            let _e918 = local_41;
                            let _e919 = (_e918 + 1u);
                            local_43 = _e919;
                            let _e920 = local_2;
                            if (_e919 < _e920) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e922 = local_43;
                            let _e925 = global_5.member[_e922];
                            local_44 = bitcast<f32>(_e925);
                            let _e927 = local_41;
                            let _e928 = (_e927 + 2u);
                            local_45 = _e928;
                            let _e929 = local_2;
                            if (_e928 < _e929) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e931 = local_45;
                            let _e934 = global_5.member[_e931];
                            local_46 = bitcast<f32>(_e934);
                            let _e937 = local_614[2u];
                            let _e938 = (_e937 * 10u);
                            local_47 = _e938;
                            let _e939 = local_2;
                            if (_e938 < _e939) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e941 = local_47;
                            let _e944 = global_5.member[_e941];
                            local_48 = bitcast<f32>(_e944);
                            let _e946 = local_47;
                            let _e947 = (_e946 + 1u);
                            local_49 = _e947;
                            let _e948 = local_2;
                            if (_e947 < _e948) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e950 = local_49;
                            let _e953 = global_5.member[_e950];
                            local_50 = bitcast<f32>(_e953);
                            let _e955 = local_47;
                            let _e956 = (_e955 + 2u);
                            local_51 = _e956;
                            let _e957 = local_2;
                            if (_e956 < _e957) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e959 = local_51;
                            let _e962 = global_5.member[_e959];
                            let _e965 = local_36;
                            let _e966 = local_38;
                            let _e967 = local_40;
                            local_616[0u] = array<f32, 3>(_e965, _e966, _e967);
                            let _e970 = local_42;
                            let _e971 = local_44;
                            let _e972 = local_46;
                            local_616[1u] = array<f32, 3>(_e970, _e971, _e972);
                            let _e975 = local_48;
                            let _e976 = local_50;
                            local_616[2u] = array<f32, 3>(_e975, _e976, bitcast<f32>(_e962));
                            local_617 = array<f32, 3>(0f, 0f, 0f);
                            local_618 = array<f32, 3>(0f, 0f, 0f);
                            phi_5693_ = _e740;
                            phi_633_ = 0u;
                            loop {
                                let _e979 = phi_5693_;
                                let _e981 = phi_633_;
                                local_52 = _e981;
                                let _e982 = local_52;
                                let _e983 = (_e982 < 3u);
                                local_53 = _e983;
                                if _e983 {
                                    let _e984 = local_52;
                                    if (_e984 < 4u) {
                                    } else {
                                        phi_5695_ = true;
                                        break;
                                    }
                                    let _e986 = local_52;
                                    let _e988 = local_614[_e986];
                                    local_54 = (_e988 * 10u);
                                    phi_651_ = 0u;
                                    loop {
                                        let _e991 = phi_651_;
                                        local_55 = _e991;
                                        let _e992 = local_55;
                                        let _e993 = (_e992 < 3u);
                                        local_56 = _e993;
                                        if _e993 {
                                            let _e994 = local_53;
                                            if _e994 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e995 = local_52;
                                            let _e997 = local_615[_e995];
                                            local_57 = _e997;
                                            let _e998 = local_53;
                                            if _e998 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e999 = local_56;
                                            if _e999 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1000 = local_52;
                                            let _e1001 = local_55;
                                            let _e1004 = local_616[_e1000][_e1001];
                                            let _e1005 = local_57;
                                            local_58 = (_e1005 * _e1004);
                                            let _e1007 = local_56;
                                            if _e1007 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1008 = local_55;
                                            let _e1010 = local_617[_e1008];
                                            let _e1011 = local_58;
                                            local_617[_e1008] = (_e1010 + _e1011);
                                            let _e1013 = local_53;
                                            if _e1013 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1014 = local_615[_e995];
                                            local_59 = _e1014;
                                            let _e1015 = local_54;
                                            let _e1017 = local_55;
                                            let _e1018 = ((_e1015 + 4u) + _e1017);
                                            local_60 = _e1018;
                                            let _e1019 = local_2;
                                            if (_e1018 < _e1019) {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1021 = local_60;
                                            let _e1024 = global_5.member[_e1021];
                                            let _e1026 = local_59;
                                            local_61 = (_e1026 * bitcast<f32>(_e1024));
                                            let _e1028 = local_56;
                                            if _e1028 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1029 = local_55;
                                            let _e1031 = local_618[_e1029];
                                            let _e1032 = local_61;
                                            local_618[_e1029] = (_e1031 + _e1032);
                                            let _e1034 = local_55;
                                            phi_652_ = (_e1034 + 1u);
                                        } else {
                                            phi_652_ = u32();
                                        }
                                        let _e1037 = phi_652_;
                                        continue;
                                        continuing {
                                            let _e1038 = local_56;
                                            phi_651_ = _e1037;
                                            phi_5690_ = _e979;
                                            break if !(_e1038);
                                        }
                                    }
                                    let _e1041 = phi_5690_;
                                    phi_5695_ = _e1041;
                                    if _e1041 {
                                        break;
                                    }
                                    let _e1042 = local_52;
                                    phi_5696_ = _e1041;
                                    phi_634_ = (_e1042 + 1u);
                                } else {
                                    phi_5696_ = _e979;
                                    phi_634_ = u32();
                                }
                                let _e1045 = phi_5696_;
                                let _e1047 = phi_634_;
                                continue;
                                continuing {
                                    let _e1048 = local_53;
                                    phi_5693_ = _e1045;
                                    phi_633_ = _e1047;
                                    phi_5695_ = _e1045;
                                    break if !(_e1048);
                                }
                            }
                            let _e1051 = phi_5695_;
                            phi_5975_ = _e1051;
                            if _e1051 {
                                break;
                            }
                            let _e1052 = local_616[1u];
                            let _e1056 = local_616[0u];
                            let _e1060 = (_e1052[0] - _e1056[0]);
                            let _e1061 = (_e1052[1] - _e1056[1]);
                            let _e1062 = (_e1052[2] - _e1056[2]);
                            let _e1063 = local_616[2u];
                            let _e1067 = local_616[0u];
                            let _e1071 = (_e1063[0] - _e1067[0]);
                            let _e1072 = (_e1063[1] - _e1067[1]);
                            let _e1073 = (_e1063[2] - _e1067[2]);
                            let _e1076 = ((_e1061 * _e1073) - (_e1062 * _e1072));
                            local_62 = _e1076;
                            let _e1079 = ((_e1062 * _e1071) - (_e1060 * _e1073));
                            local_63 = _e1079;
                            let _e1082 = ((_e1060 * _e1072) - (_e1061 * _e1071));
                            local_64 = _e1082;
                            let _e1084 = local_618;
                            if ((((_e1084[0] * _e1084[0]) + (_e1084[1] * _e1084[1])) + (_e1084[2] * _e1084[2])) > 0f) {
                                let _e1119 = local_618;
                                local_65 = _e1119[0];
                                local_66 = _e1119[1];
                                local_67 = _e1119[2];
                                let _e1129 = sqrt((((_e1119[0] * _e1119[0]) + (_e1119[1] * _e1119[1])) + (_e1119[2] * _e1119[2])));
                                local_502 = _e1129;
                                if (_e1129 > 0f) {
                                    let _e1131 = local_65;
                                    let _e1132 = local_502;
                                    let _e1134 = local_66;
                                    let _e1135 = local_502;
                                    let _e1137 = local_67;
                                    let _e1138 = local_502;
                                    phi_5160_ = array<f32, 3>((_e1131 / _e1132), (_e1134 / _e1135), (_e1137 / _e1138));
                                } else {
                                    phi_5160_ = array<f32, 3>(_e1119[0], _e1119[1], _e1119[2]);
                                }
                                let _e1142 = phi_5160_;
                                phi_813_ = _e1142;
                            } else {
                                let _e1094 = local_62;
                                let _e1095 = local_62;
                                let _e1097 = local_63;
                                let _e1098 = local_63;
                                let _e1101 = local_64;
                                let _e1102 = local_64;
                                let _e1105 = sqrt((((_e1094 * _e1095) + (_e1097 * _e1098)) + (_e1101 * _e1102)));
                                local_503 = _e1105;
                                if (_e1105 > 0f) {
                                    let _e1107 = local_62;
                                    let _e1108 = local_503;
                                    let _e1110 = local_63;
                                    let _e1111 = local_503;
                                    let _e1113 = local_64;
                                    let _e1114 = local_503;
                                    phi_5186_ = array<f32, 3>((_e1107 / _e1108), (_e1110 / _e1111), (_e1113 / _e1114));
                                } else {
                                    phi_5186_ = array<f32, 3>(_e1076, _e1079, _e1082);
                                }
                                let _e1118 = phi_5186_;
                                phi_813_ = _e1118;
                            }
                            let _e1144 = phi_813_;
                            local_68 = _e1144;
                            let _e1145 = local_617;
                            let _e1149 = local_23;
                            local_69 = _e1149[0];
                            let _e1152 = local_23;
                            local_70 = _e1152[1];
                            let _e1155 = local_23;
                            local_71 = _e1155[2];
                            let _e1158 = local_62;
                            let _e1160 = local_63;
                            let _e1163 = local_64;
                            if ((((_e1158 * (_e1145[0] - _e1149[0])) + (_e1160 * (_e1145[1] - _e1152[1]))) + (_e1163 * (_e1145[2] - _e1155[2]))) > 0f) {
                                let _e1167 = local_68;
                                let _e1170 = local_68;
                                let _e1173 = local_68;
                                phi_844_ = array<f32, 3>(-(_e1167[0]), -(_e1170[1]), -(_e1173[2]));
                            } else {
                                phi_844_ = _e1144;
                            }
                            let _e1178 = phi_844_;
                            local_72 = _e1178;
                            let _e1179 = local_33;
                            local_612 = _e1179;
                            let _e1181 = local_18;
                            local_613[0u] = _e1181;
                            let _e1183 = local_20;
                            local_613[1u] = _e1183;
                            let _e1185 = local_34;
                            local_613[2u] = _e1185;
                            phi_862_ = 0u;
                            phi_865_ = 0f;
                            phi_867_ = 0f;
                            loop {
                                let _e1187 = phi_862_;
                                let _e1189 = phi_865_;
                                let _e1191 = phi_867_;
                                local_73 = _e1187;
                                local_74 = _e1189;
                                local_75 = _e1191;
                                let _e1192 = local_73;
                                let _e1193 = (_e1192 < 3u);
                                local_76 = _e1193;
                                if _e1193 {
                                    let _e1194 = local_73;
                                    if (_e1194 < 4u) {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1196 = local_73;
                                    let _e1198 = local_612[_e1196];
                                    local_77 = (_e1198 * 10u);
                                    let _e1200 = local_76;
                                    if _e1200 {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1201 = local_73;
                                    let _e1203 = local_613[_e1201];
                                    local_78 = _e1203;
                                    let _e1204 = local_77;
                                    let _e1205 = (_e1204 + 3u);
                                    local_79 = _e1205;
                                    let _e1206 = local_2;
                                    if (_e1205 < _e1206) {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1208 = local_79;
                                    let _e1211 = global_5.member[_e1208];
                                    let _e1213 = local_78;
                                    let _e1215 = local_75;
                                    let _e1217 = local_76;
                                    if _e1217 {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1218 = local_613[_e1201];
                                    local_80 = _e1218;
                                    let _e1219 = local_77;
                                    let _e1220 = (_e1219 + 7u);
                                    local_81 = _e1220;
                                    let _e1221 = local_2;
                                    if (_e1220 < _e1221) {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1223 = local_81;
                                    let _e1226 = global_5.member[_e1223];
                                    let _e1228 = local_80;
                                    let _e1230 = local_74;
                                    let _e1232 = local_73;
                                    phi_863_ = (_e1232 + 1u);
                                    phi_866_ = (_e1230 + (_e1228 * bitcast<f32>(_e1226)));
                                    phi_868_ = (_e1215 + (_e1213 * bitcast<f32>(_e1211)));
                                } else {
                                    phi_863_ = u32();
                                    phi_866_ = f32();
                                    phi_868_ = f32();
                                }
                                let _e1235 = phi_863_;
                                let _e1237 = phi_866_;
                                let _e1239 = phi_868_;
                                continue;
                                continuing {
                                    let _e1240 = local_76;
                                    phi_862_ = _e1235;
                                    phi_865_ = _e1237;
                                    phi_867_ = _e1239;
                                    phi_5697_ = _e1051;
                                    break if !(_e1240);
                                }
                            }
                            let _e1243 = phi_5697_;
                            phi_5975_ = _e1243;
                            if _e1243 {
                                break;
                            }
                            let _e1245 = local_614[3u];
                            let _e1246 = (_e1245 * 16u);
                            local_82 = _e1246;
                            let _e1247 = (_e1246 + 8u);
                            local_83 = _e1247;
                            let _e1248 = local_4;
                            if (_e1247 < _e1248) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e1250 = local_83;
                            let _e1253 = global_7.member[_e1250];
                            local_84 = _e1253;
                            let _e1254 = local_82;
                            let _e1255 = (_e1254 + 9u);
                            local_85 = _e1255;
                            let _e1256 = local_4;
                            if (_e1255 < _e1256) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e1258 = local_85;
                            let _e1261 = global_7.member[_e1258];
                            local_86 = _e1261;
                            let _e1262 = local_84;
                            let _e1263 = local_25;
                            if (_e1262 < _e1263) {
                                phi_979_ = true;
                            } else {
                                let _e1265 = local_86;
                                let _e1266 = local_25;
                                phi_979_ = (_e1265 < _e1266);
                            }
                            let _e1269 = phi_979_;
                            if _e1269 {
                                let _e1270 = local_27;
                                let _e1271 = (_e1270 * 10u);
                                local_87 = _e1271;
                                let _e1272 = (_e1271 + 3u);
                                local_88 = _e1272;
                                let _e1273 = local_2;
                                if (_e1272 < _e1273) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1275 = local_88;
                                let _e1278 = global_5.member[_e1275];
                                local_89 = bitcast<f32>(_e1278);
                                let _e1280 = local_87;
                                let _e1281 = (_e1280 + 7u);
                                local_90 = _e1281;
                                let _e1282 = local_2;
                                if (_e1281 < _e1282) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1284 = local_90;
                                let _e1287 = global_5.member[_e1284];
                                local_91 = bitcast<f32>(_e1287);
                                let _e1289 = local_29;
                                let _e1290 = (_e1289 * 10u);
                                local_92 = _e1290;
                                let _e1291 = (_e1290 + 3u);
                                local_93 = _e1291;
                                let _e1292 = local_2;
                                if (_e1291 < _e1292) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1294 = local_93;
                                let _e1297 = global_5.member[_e1294];
                                local_94 = bitcast<f32>(_e1297);
                                let _e1299 = local_92;
                                let _e1300 = (_e1299 + 7u);
                                local_95 = _e1300;
                                let _e1301 = local_2;
                                if (_e1300 < _e1301) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1303 = local_95;
                                let _e1306 = global_5.member[_e1303];
                                local_96 = bitcast<f32>(_e1306);
                                let _e1308 = local_31;
                                let _e1309 = (_e1308 * 10u);
                                local_97 = _e1309;
                                let _e1310 = (_e1309 + 3u);
                                local_98 = _e1310;
                                let _e1311 = local_2;
                                if (_e1310 < _e1311) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1313 = local_98;
                                let _e1316 = global_5.member[_e1313];
                                local_99 = bitcast<f32>(_e1316);
                                let _e1318 = local_97;
                                let _e1319 = (_e1318 + 7u);
                                local_100 = _e1319;
                                let _e1320 = local_2;
                                if (_e1319 < _e1320) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1322 = local_100;
                                let _e1325 = global_5.member[_e1322];
                                local_101 = bitcast<f32>(_e1325);
                                let _e1327 = local_617;
                                let _e1331 = local_616;
                                let _e1344 = local_69;
                                local_504 = (_e1327[0] - _e1344);
                                let _e1346 = local_70;
                                local_505 = (_e1327[1] - _e1346);
                                let _e1348 = local_71;
                                local_506 = (_e1327[2] - _e1348);
                                let _e1350 = (_e1331[1][0] - _e1331[0][0]);
                                local_507 = _e1350;
                                let _e1351 = (_e1331[1][1] - _e1331[0][1]);
                                local_508 = _e1351;
                                let _e1352 = (_e1331[1][2] - _e1331[0][2]);
                                local_509 = _e1352;
                                let _e1353 = (_e1331[2][0] - _e1331[0][0]);
                                local_510 = _e1353;
                                let _e1354 = (_e1331[2][1] - _e1331[0][1]);
                                local_511 = _e1354;
                                let _e1355 = (_e1331[2][2] - _e1331[0][2]);
                                local_512 = _e1355;
                                local_513 = ((_e1351 * _e1355) - (_e1352 * _e1354));
                                local_514 = ((_e1352 * _e1353) - (_e1350 * _e1355));
                                local_515 = ((_e1350 * _e1354) - (_e1351 * _e1353));
                                let _e1369 = (((_e1350 * _e1350) + (_e1351 * _e1351)) + (_e1352 * _e1352));
                                local_516 = _e1369;
                                let _e1374 = (((_e1350 * _e1353) + (_e1351 * _e1354)) + (_e1352 * _e1355));
                                local_517 = _e1374;
                                let _e1379 = (((_e1353 * _e1353) + (_e1354 * _e1354)) + (_e1355 * _e1355));
                                local_518 = _e1379;
                                let _e1382 = ((_e1369 * _e1379) - (_e1374 * _e1374));
                                local_519 = _e1382;
                                if (_e1382 > 0f) {
                                    let _e1384 = local_22;
                                    let _e1385 = (_e1384 > 0f);
                                    local_520 = _e1385;
                                    if _e1385 {
                                        let _e1386 = local_24;
                                        let _e1388 = local_24;
                                        let _e1390 = local_24;
                                        let _e1392 = (2f * _e1390[2]);
                                        let _e1393 = (_e1388[1] * -2f);
                                        let _e1400 = local_24;
                                        local_525 = (1f + ((_e1388[1] * _e1393) - (_e1390[2] * _e1392)));
                                        local_526 = ((_e1400[3] * _e1392) + -((_e1386[0] * _e1393)));
                                        local_527 = ((_e1400[3] * _e1393) + (_e1386[0] * _e1392));
                                        let _e1407 = (_e1390[2] * -2f);
                                        let _e1408 = (2f * _e1386[0]);
                                        local_528 = ((_e1400[3] * _e1407) + (_e1388[1] * _e1408));
                                        local_529 = (1f + ((_e1390[2] * _e1407) - (_e1386[0] * _e1408)));
                                        local_530 = ((_e1400[3] * _e1408) + -((_e1388[1] * _e1407)));
                                        let _e1420 = local_504;
                                        let _e1421 = local_513;
                                        let _e1423 = local_505;
                                        let _e1424 = local_514;
                                        let _e1427 = local_506;
                                        let _e1428 = local_515;
                                        let _e1430 = (((_e1420 * _e1421) + (_e1423 * _e1424)) + (_e1427 * _e1428));
                                        local_521 = _e1430;
                                        let _e1431 = local_504;
                                        let _e1432 = local_504;
                                        let _e1434 = local_505;
                                        let _e1435 = local_505;
                                        let _e1438 = local_506;
                                        let _e1439 = local_506;
                                        let _e1442 = local_513;
                                        let _e1443 = local_513;
                                        let _e1445 = local_514;
                                        let _e1446 = local_514;
                                        let _e1449 = local_515;
                                        let _e1450 = local_515;
                                        let _e1454 = sqrt(((((_e1431 * _e1432) + (_e1434 * _e1435)) + (_e1438 * _e1439)) * (((_e1442 * _e1443) + (_e1445 * _e1446)) + (_e1449 * _e1450))));
                                        local_522 = _e1454;
                                        let _e1455 = (0.001f * _e1454);
                                        local_523 = _e1455;
                                        let _e1456 = (_e1430 < 0f);
                                        local_524 = _e1456;
                                        if _e1456 {
                                            let _e1457 = local_521;
                                            phi_5279_ = -(_e1457);
                                        } else {
                                            phi_5279_ = _e1430;
                                        }
                                        let _e1460 = phi_5279_;
                                        let _e1461 = local_523;
                                        if (_e1460 >= _e1461) {
                                            phi_5290_ = _e1430;
                                        } else {
                                            let _e1463 = local_524;
                                            if _e1463 {
                                                let _e1464 = local_522;
                                                phi_5288_ = (_e1464 * -0.001f);
                                            } else {
                                                phi_5288_ = _e1455;
                                            }
                                            let _e1467 = phi_5288_;
                                            phi_5290_ = _e1467;
                                        }
                                        let _e1469 = phi_5290_;
                                        let _e1470 = local_94;
                                        let _e1471 = local_89;
                                        let _e1472 = (_e1470 - _e1471);
                                        let _e1473 = local_96;
                                        let _e1474 = local_91;
                                        let _e1475 = (_e1473 - _e1474);
                                        let _e1476 = local_99;
                                        let _e1477 = local_89;
                                        let _e1478 = (_e1476 - _e1477);
                                        let _e1479 = local_101;
                                        let _e1480 = local_91;
                                        let _e1481 = (_e1479 - _e1480);
                                        let _e1482 = local_525;
                                        let _e1483 = local_513;
                                        let _e1485 = local_526;
                                        let _e1486 = local_514;
                                        let _e1489 = local_527;
                                        let _e1490 = local_515;
                                        let _e1493 = ((((_e1482 * _e1483) + (_e1485 * _e1486)) + (_e1489 * _e1490)) / _e1469);
                                        let _e1494 = local_504;
                                        let _e1496 = local_525;
                                        let _e1498 = local_22;
                                        let _e1499 = (_e1498 * (_e1496 - (_e1494 * _e1493)));
                                        let _e1500 = local_505;
                                        let _e1502 = local_526;
                                        let _e1504 = local_22;
                                        let _e1505 = (_e1504 * (_e1502 - (_e1500 * _e1493)));
                                        let _e1506 = local_506;
                                        let _e1508 = local_527;
                                        let _e1510 = local_22;
                                        let _e1511 = (_e1510 * (_e1508 - (_e1506 * _e1493)));
                                        let _e1512 = local_507;
                                        let _e1514 = local_508;
                                        let _e1517 = local_509;
                                        let _e1519 = (((_e1499 * _e1512) + (_e1505 * _e1514)) + (_e1511 * _e1517));
                                        let _e1520 = local_510;
                                        let _e1522 = local_511;
                                        let _e1525 = local_512;
                                        let _e1527 = (((_e1499 * _e1520) + (_e1505 * _e1522)) + (_e1511 * _e1525));
                                        let _e1528 = local_518;
                                        let _e1530 = local_517;
                                        let _e1533 = local_519;
                                        let _e1534 = (((_e1519 * _e1528) - (_e1527 * _e1530)) / _e1533);
                                        let _e1535 = local_516;
                                        let _e1537 = local_517;
                                        let _e1540 = local_519;
                                        let _e1541 = (((_e1527 * _e1535) - (_e1519 * _e1537)) / _e1540);
                                        let _e1548 = local_528;
                                        let _e1549 = local_513;
                                        let _e1551 = local_529;
                                        let _e1552 = local_514;
                                        let _e1555 = local_530;
                                        let _e1556 = local_515;
                                        let _e1559 = ((((_e1548 * _e1549) + (_e1551 * _e1552)) + (_e1555 * _e1556)) / _e1469);
                                        let _e1560 = local_504;
                                        let _e1562 = local_528;
                                        let _e1564 = local_22;
                                        let _e1565 = (_e1564 * (_e1562 - (_e1560 * _e1559)));
                                        let _e1566 = local_505;
                                        let _e1568 = local_529;
                                        let _e1570 = local_22;
                                        let _e1571 = (_e1570 * (_e1568 - (_e1566 * _e1559)));
                                        let _e1572 = local_506;
                                        let _e1574 = local_530;
                                        let _e1576 = local_22;
                                        let _e1577 = (_e1576 * (_e1574 - (_e1572 * _e1559)));
                                        let _e1578 = local_507;
                                        let _e1580 = local_508;
                                        let _e1583 = local_509;
                                        let _e1585 = (((_e1565 * _e1578) + (_e1571 * _e1580)) + (_e1577 * _e1583));
                                        let _e1586 = local_510;
                                        let _e1588 = local_511;
                                        let _e1591 = local_512;
                                        let _e1593 = (((_e1565 * _e1586) + (_e1571 * _e1588)) + (_e1577 * _e1591));
                                        let _e1594 = local_518;
                                        let _e1596 = local_517;
                                        let _e1599 = local_519;
                                        let _e1600 = (((_e1585 * _e1594) - (_e1593 * _e1596)) / _e1599);
                                        let _e1601 = local_516;
                                        let _e1603 = local_517;
                                        let _e1606 = local_519;
                                        let _e1607 = (((_e1593 * _e1601) - (_e1585 * _e1603)) / _e1606);
                                        phi_5396_ = type_5(((_e1534 * _e1472) + (_e1541 * _e1478)), ((_e1534 * _e1475) + (_e1541 * _e1481)), ((_e1600 * _e1472) + (_e1607 * _e1478)), ((_e1600 * _e1475) + (_e1607 * _e1481)));
                                    } else {
                                        phi_5396_ = type_5();
                                    }
                                    let _e1616 = phi_5396_;
                                    let _e1617 = local_520;
                                    phi_5400_ = _e1616;
                                    phi_5401_ = select(true, false, _e1617);
                                } else {
                                    phi_5400_ = type_5();
                                    phi_5401_ = true;
                                }
                                let _e1620 = phi_5400_;
                                let _e1622 = phi_5401_;
                                if _e1622 {
                                    phi_5405_ = type_5(0f, 0f, 0f, 0f);
                                } else {
                                    phi_5405_ = _e1620;
                                }
                                let _e1624 = phi_5405_;
                                phi_1129_ = _e1624;
                            } else {
                                phi_1129_ = type_5(0f, 0f, 0f, 0f);
                            }
                            let _e1626 = phi_1129_;
                            local_102 = _e1626;
                            let _e1627 = local_84;
                            if (_e1627 == 4294967295u) {
                                phi_5891_ = _e1243;
                                phi_2597_ = type_5();
                                phi_2598_ = true;
                            } else {
                                let _e1629 = local_84;
                                let _e1630 = local_25;
                                let _e1631 = (_e1629 >= _e1630);
                                if _e1631 {
                                    phi_5892_ = _e1243;
                                    phi_2596_ = type_5();
                                } else {
                                    let _e1632 = local_84;
                                    let _e1633 = (_e1632 * 4u);
                                    local_103 = _e1633;
                                    let _e1634 = local_5;
                                    if (_e1633 < _e1634) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e1636 = local_103;
                                    let _e1639 = global_8.member[_e1636];
                                    local_104 = _e1639;
                                    let _e1640 = local_103;
                                    let _e1641 = (_e1640 + 1u);
                                    local_105 = _e1641;
                                    let _e1642 = local_5;
                                    if (_e1641 < _e1642) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e1644 = local_105;
                                    let _e1647 = global_8.member[_e1644];
                                    local_106 = _e1647;
                                    let _e1648 = local_103;
                                    let _e1649 = (_e1648 + 2u);
                                    local_107 = _e1649;
                                    let _e1650 = local_5;
                                    if (_e1649 < _e1650) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e1652 = local_107;
                                    let _e1655 = global_8.member[_e1652];
                                    local_108 = _e1655;
                                    let _e1656 = local_103;
                                    let _e1657 = (_e1656 + 3u);
                                    local_109 = _e1657;
                                    let _e1658 = local_5;
                                    if (_e1657 < _e1658) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e1660 = local_109;
                                    let _e1663 = global_8.member[_e1660];
                                    local_110 = _e1663;
                                    let _e1664 = local_106;
                                    if (_e1664 == 0u) {
                                        phi_5894_ = _e1243;
                                        phi_2590_ = type_5();
                                        phi_2591_ = true;
                                    } else {
                                        let _e1666 = local_108;
                                        let _e1667 = (_e1666 == 0u);
                                        if _e1667 {
                                            phi_5895_ = _e1243;
                                            phi_2589_ = type_5();
                                        } else {
                                            let _e1668 = local_110;
                                            let _e1671 = ((_e1668 >> bitcast<u32>(8u)) & 31u);
                                            local_559 = select(_e1671, 1u, (_e1671 == 0u));
                                            let _e1674 = local_110;
                                            let _e1678 = local_110;
                                            let _e1682 = local_104;
                                            let _e1683 = local_106;
                                            let _e1684 = local_108;
                                            let _e1685 = type_22(_e1682, _e1683, _e1684, ((_e1674 >> bitcast<u32>(1u)) & 3u), ((_e1678 >> bitcast<u32>(3u)) & 3u));
                                            let _e1686 = local_106;
                                            let _e1687 = f32(_e1686);
                                            local_111 = _e1687;
                                            let _e1688 = local_75;
                                            if ((bitcast<u32>((_e1688 * _e1687)) & 2139095040u) != 2139095040u) {
                                                let _e1693 = local_108;
                                                let _e1695 = local_74;
                                                phi_1239_ = select(true, false, ((bitcast<u32>((_e1695 * f32(_e1693))) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_1239_ = true;
                                            }
                                            let _e1702 = phi_1239_;
                                            let _e1703 = local_74;
                                            local_560 = select(_e1703, 0f, _e1702);
                                            let _e1705 = local_75;
                                            local_561 = select(_e1705, 0f, _e1702);
                                            let _e1707 = local_102;
                                            local_112 = _e1707.member;
                                            let _e1709 = local_111;
                                            let _e1710 = (_e1707.member * _e1709);
                                            let _e1711 = local_102;
                                            local_113 = _e1711.member_1;
                                            let _e1713 = local_108;
                                            let _e1714 = f32(_e1713);
                                            let _e1715 = (_e1711.member_1 * _e1714);
                                            let _e1716 = local_102;
                                            local_114 = _e1716.member_2;
                                            let _e1718 = local_111;
                                            let _e1719 = (_e1716.member_2 * _e1718);
                                            let _e1720 = local_102;
                                            local_115 = _e1720.member_3;
                                            let _e1722 = (_e1720.member_3 * _e1714);
                                            let _e1726 = sqrt(((_e1710 * _e1710) + (_e1715 * _e1715)));
                                            local_116 = _e1726;
                                            let _e1730 = sqrt(((_e1719 * _e1719) + (_e1722 * _e1722)));
                                            local_117 = _e1730;
                                            let _e1732 = select(_e1730, _e1726, (_e1726 > _e1730));
                                            local_562 = _e1732;
                                            if (_e1732 > 1f) {
                                                let _e1734 = local_562;
                                                phi_1278_ = !(((bitcast<u32>(_e1734) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_1278_ = true;
                                            }
                                            let _e1740 = phi_1278_;
                                            local_118 = _e1740;
                                            if _e1740 {
                                                phi_1374_ = 1u;
                                                phi_1375_ = 1u;
                                            } else {
                                                let _e1741 = local_116;
                                                let _e1742 = local_117;
                                                if (_e1741 >= _e1742) {
                                                    let _e1780 = local_117;
                                                    let _e1782 = local_117;
                                                    let _e1784 = ceil(select(8f, _e1782, (_e1780 < 8f)));
                                                    local_119 = _e1784;
                                                    if (_e1784 < 1f) {
                                                        phi_1304_ = 1u;
                                                    } else {
                                                        let _e1786 = local_119;
                                                        let _e1788 = local_119;
                                                        let _e1790 = local_119;
                                                        phi_1304_ = select(select(u32(_e1786), 0u, (_e1788 < 0f)), 4294967295u, (_e1790 > 4294967000f));
                                                    }
                                                    let _e1795 = phi_1304_;
                                                    local_120 = _e1795;
                                                    if (_e1795 == 0u) {
                                                        phi_5975_ = true;
                                                        break;
                                                    }
                                                    let _e1797 = local_120;
                                                    let _e1799 = f32((64u / _e1797));
                                                    let _e1800 = local_116;
                                                    let _e1802 = local_116;
                                                    let _e1804 = ceil(select(_e1799, _e1802, (_e1800 < _e1799)));
                                                    local_121 = _e1804;
                                                    if (_e1804 < 1f) {
                                                        phi_1328_ = 1u;
                                                    } else {
                                                        let _e1806 = local_121;
                                                        let _e1808 = local_121;
                                                        let _e1810 = local_121;
                                                        phi_1328_ = select(select(u32(_e1806), 0u, (_e1808 < 0f)), 4294967295u, (_e1810 > 4294967000f));
                                                    }
                                                    let _e1815 = phi_1328_;
                                                    phi_1372_ = _e1795;
                                                    phi_1373_ = _e1815;
                                                } else {
                                                    let _e1744 = local_116;
                                                    let _e1746 = local_116;
                                                    let _e1748 = ceil(select(8f, _e1746, (_e1744 < 8f)));
                                                    local_122 = _e1748;
                                                    if (_e1748 < 1f) {
                                                        phi_1347_ = 1u;
                                                    } else {
                                                        let _e1750 = local_122;
                                                        let _e1752 = local_122;
                                                        let _e1754 = local_122;
                                                        phi_1347_ = select(select(u32(_e1750), 0u, (_e1752 < 0f)), 4294967295u, (_e1754 > 4294967000f));
                                                    }
                                                    let _e1759 = phi_1347_;
                                                    local_123 = _e1759;
                                                    if (_e1759 == 0u) {
                                                        phi_5975_ = true;
                                                        break;
                                                    }
                                                    let _e1761 = local_123;
                                                    let _e1763 = f32((64u / _e1761));
                                                    let _e1764 = local_117;
                                                    let _e1766 = local_117;
                                                    let _e1768 = ceil(select(_e1763, _e1766, (_e1764 < _e1763)));
                                                    local_124 = _e1768;
                                                    if (_e1768 < 1f) {
                                                        phi_1371_ = 1u;
                                                    } else {
                                                        let _e1770 = local_124;
                                                        let _e1772 = local_124;
                                                        let _e1774 = local_124;
                                                        phi_1371_ = select(select(u32(_e1770), 0u, (_e1772 < 0f)), 4294967295u, (_e1774 > 4294967000f));
                                                    }
                                                    let _e1779 = phi_1371_;
                                                    phi_1372_ = _e1779;
                                                    phi_1373_ = _e1759;
                                                }
                                                let _e1817 = phi_1372_;
                                                let _e1819 = phi_1373_;
                                                phi_1374_ = _e1817;
                                                phi_1375_ = _e1819;
                                            }
                                            let _e1821 = phi_1374_;
                                            let _e1823 = phi_1375_;
                                            local_125 = _e1821;
                                            local_126 = _e1823;
                                            let _e1824 = local_118;
                                            if _e1824 {
                                                phi_1388_ = 1f;
                                            } else {
                                                let _e1825 = local_126;
                                                let _e1827 = local_116;
                                                let _e1828 = (_e1827 / f32(_e1825));
                                                let _e1829 = local_125;
                                                let _e1831 = local_117;
                                                let _e1832 = (_e1831 / f32(_e1829));
                                                phi_1388_ = select(_e1832, _e1828, (_e1828 > _e1832));
                                            }
                                            let _e1836 = phi_1388_;
                                            local_127 = _e1836;
                                            if (_e1836 > 1f) {
                                                let _e1838 = local_127;
                                                let _e1839 = bitcast<u32>(_e1838);
                                                let _e1848 = (bitcast<f32>(((_e1839 & 8388607u) | 1065353216u)) - 1f);
                                                phi_1409_ = (f32((bitcast<i32>(((_e1839 >> bitcast<u32>(23i)) & 255u)) - 127i)) + (_e1848 * (1.4208645f + (_e1848 * (-0.5772506f + (_e1848 * 0.1563861f))))));
                                            } else {
                                                phi_1409_ = 0f;
                                            }
                                            let _e1857 = phi_1409_;
                                            local_128 = _e1857;
                                            let _e1858 = local_559;
                                            let _e1859 = (_e1858 - 1u);
                                            local_129 = _e1859;
                                            let _e1860 = floor(_e1857);
                                            let _e1865 = select(select(u32(_e1860), 0u, (_e1860 < 0f)), 4294967295u, (_e1860 > 4294967000f));
                                            local_130 = _e1865;
                                            let _e1866 = (_e1865 >= _e1859);
                                            local_131 = _e1866;
                                            if _e1866 {
                                                phi_1425_ = 0f;
                                            } else {
                                                let _e1867 = local_130;
                                                let _e1869 = local_128;
                                                phi_1425_ = (_e1869 - f32(_e1867));
                                            }
                                            let _e1872 = phi_1425_;
                                            local_132 = _e1872;
                                            let _e1873 = local_131;
                                            let _e1874 = local_129;
                                            let _e1875 = local_130;
                                            local_563 = select(_e1875, _e1874, _e1873);
                                            local_564 = select(1u, 2u, (_e1872 > 0f));
                                            phi_5506_ = 0u;
                                            phi_5507_ = _e1685;
                                            loop {
                                                let _e1880 = phi_5506_;
                                                let _e1882 = phi_5507_;
                                                local_531 = _e1880;
                                                local_532 = _e1882;
                                                local_624 = _e1882;
                                                let _e1883 = local_531;
                                                let _e1884 = local_563;
                                                let _e1885 = (_e1883 < _e1884);
                                                local_533 = _e1885;
                                                if _e1885 {
                                                    let _e1886 = local_532;
                                                    local_534 = _e1886.member_1;
                                                    let _e1888 = local_532;
                                                    local_535 = _e1888.member_2;
                                                    let _e1891 = local_532;
                                                    let _e1894 = local_532;
                                                    local_536 = type_22((_e1891.member + (_e1886.member_1 * _e1888.member_2)), _e1894.member_1, _e1894.member_2, _e1894.member_3, _e1894.member_4);
                                                    if (_e1886.member_1 > 1u) {
                                                        let _e1902 = local_534;
                                                        phi_5524_ = (_e1902 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5524_ = 1u;
                                                    }
                                                    let _e1906 = phi_5524_;
                                                    let _e1907 = local_536;
                                                    local_537 = type_22(_e1907.member, _e1906, _e1907.member_2, _e1907.member_3, _e1907.member_4);
                                                    let _e1914 = local_535;
                                                    if (_e1914 > 1u) {
                                                        let _e1916 = local_535;
                                                        phi_5533_ = (_e1916 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5533_ = 1u;
                                                    }
                                                    let _e1920 = phi_5533_;
                                                    let _e1921 = local_537;
                                                    let _e1928 = local_531;
                                                    phi_5538_ = (_e1928 + 1u);
                                                    phi_5539_ = type_22(_e1921.member, _e1921.member_1, _e1920, _e1921.member_3, _e1921.member_4);
                                                } else {
                                                    phi_5538_ = u32();
                                                    phi_5539_ = type_22();
                                                }
                                                let _e1931 = phi_5538_;
                                                let _e1933 = phi_5539_;
                                                continue;
                                                continuing {
                                                    let _e1934 = local_533;
                                                    phi_5506_ = _e1931;
                                                    phi_5507_ = _e1933;
                                                    break if !(_e1934);
                                                }
                                            }
                                            let _e1936 = local_563;
                                            let _e1937 = local_564;
                                            local_133 = ((_e1936 + _e1937) - 1u);
                                            phi_5545_ = 0u;
                                            phi_5546_ = _e1685;
                                            loop {
                                                let _e1941 = phi_5545_;
                                                let _e1943 = phi_5546_;
                                                local_538 = _e1941;
                                                local_539 = _e1943;
                                                local_625 = _e1943;
                                                let _e1944 = local_538;
                                                let _e1945 = local_133;
                                                let _e1946 = (_e1944 < _e1945);
                                                local_540 = _e1946;
                                                if _e1946 {
                                                    let _e1947 = local_539;
                                                    local_541 = _e1947.member_1;
                                                    let _e1949 = local_539;
                                                    local_542 = _e1949.member_2;
                                                    let _e1952 = local_539;
                                                    let _e1955 = local_539;
                                                    local_543 = type_22((_e1952.member + (_e1947.member_1 * _e1949.member_2)), _e1955.member_1, _e1955.member_2, _e1955.member_3, _e1955.member_4);
                                                    if (_e1947.member_1 > 1u) {
                                                        let _e1963 = local_541;
                                                        phi_5563_ = (_e1963 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5563_ = 1u;
                                                    }
                                                    let _e1967 = phi_5563_;
                                                    let _e1968 = local_543;
                                                    local_544 = type_22(_e1968.member, _e1967, _e1968.member_2, _e1968.member_3, _e1968.member_4);
                                                    let _e1975 = local_542;
                                                    if (_e1975 > 1u) {
                                                        let _e1977 = local_542;
                                                        phi_5572_ = (_e1977 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5572_ = 1u;
                                                    }
                                                    let _e1981 = phi_5572_;
                                                    let _e1982 = local_544;
                                                    let _e1989 = local_538;
                                                    phi_5577_ = (_e1989 + 1u);
                                                    phi_5578_ = type_22(_e1982.member, _e1982.member_1, _e1981, _e1982.member_3, _e1982.member_4);
                                                } else {
                                                    phi_5577_ = u32();
                                                    phi_5578_ = type_22();
                                                }
                                                let _e1992 = phi_5577_;
                                                let _e1994 = phi_5578_;
                                                continue;
                                                continuing {
                                                    let _e1995 = local_540;
                                                    phi_5545_ = _e1992;
                                                    phi_5546_ = _e1994;
                                                    break if !(_e1995);
                                                }
                                            }
                                            let _e1997 = local_118;
                                            if _e1997 {
                                                let _e1998 = local_110;
                                                phi_1441_ = ((_e1998 & 1u) != 0u);
                                            } else {
                                                phi_1441_ = false;
                                            }
                                            let _e2002 = phi_1441_;
                                            local_134 = _e2002;
                                            phi_5751_ = _e1243;
                                            phi_1444_ = 0u;
                                            phi_1447_ = type_5(0f, 0f, 0f, 0f);
                                            loop {
                                                let _e2004 = phi_5751_;
                                                let _e2006 = phi_1444_;
                                                let _e2008 = phi_1447_;
                                                local_135 = _e2006;
                                                local_136 = _e2008;
                                                let _e2009 = local_135;
                                                let _e2010 = local_126;
                                                let _e2011 = (_e2009 < _e2010);
                                                local_137 = _e2011;
                                                if _e2011 {
                                                    let _e2012 = local_135;
                                                    let _e2015 = local_126;
                                                    local_138 = (((f32(_e2012) + 0.5f) / f32(_e2015)) - 0.5f);
                                                    phi_5750_ = _e2004;
                                                    phi_1461_ = 0u;
                                                    phi_1464_ = _e2008;
                                                    loop {
                                                        let _e2020 = phi_5750_;
                                                        let _e2022 = phi_1461_;
                                                        let _e2024 = phi_1464_;
                                                        local_139 = _e2022;
                                                        local_627 = _e2024;
                                                        let _e2025 = local_139;
                                                        let _e2026 = local_125;
                                                        let _e2027 = (_e2025 < _e2026);
                                                        local_140 = _e2027;
                                                        if _e2027 {
                                                            let _e2028 = local_139;
                                                            let _e2031 = local_125;
                                                            let _e2034 = (((f32(_e2028) + 0.5f) / f32(_e2031)) - 0.5f);
                                                            let _e2035 = local_138;
                                                            let _e2036 = local_112;
                                                            let _e2038 = local_561;
                                                            let _e2040 = local_114;
                                                            local_141 = ((_e2038 + (_e2035 * _e2036)) + (_e2034 * _e2040));
                                                            let _e2043 = local_138;
                                                            let _e2044 = local_113;
                                                            let _e2046 = local_560;
                                                            let _e2048 = local_115;
                                                            local_142 = ((_e2046 + (_e2043 * _e2044)) + (_e2034 * _e2048));
                                                            phi_1490_ = 0u;
                                                            phi_1493_ = _e2024;
                                                            loop {
                                                                let _e2052 = phi_1490_;
                                                                let _e2054 = phi_1493_;
                                                                local_143 = _e2052;
                                                                local_144 = _e2054;
                                                                local_626 = _e2054;
                                                                let _e2055 = local_143;
                                                                let _e2056 = local_564;
                                                                let _e2057 = (_e2055 < _e2056);
                                                                local_145 = _e2057;
                                                                if _e2057 {
                                                                    let _e2058 = local_143;
                                                                    if (_e2058 == 0u) {
                                                                        let _e2060 = local_132;
                                                                        let _e5504 = local_624;
                                                                        phi_1506_ = _e5504;
                                                                        phi_1507_ = (1f - _e2060);
                                                                    } else {
                                                                        let _e5506 = local_625;
                                                                        phi_1506_ = _e5506;
                                                                        phi_1507_ = _e1872;
                                                                    }
                                                                    let _e2063 = phi_1506_;
                                                                    let _e2065 = phi_1507_;
                                                                    local_146 = _e2063;
                                                                    local_147 = _e2065;
                                                                    let _e2066 = local_134;
                                                                    let _e2067 = select(0.5f, 0f, _e2066);
                                                                    local_148 = _e2063.member_1;
                                                                    let _e2070 = local_141;
                                                                    let _e2072 = ((_e2070 * f32(_e2063.member_1)) - _e2067);
                                                                    local_149 = _e2072;
                                                                    local_150 = _e2063.member_2;
                                                                    let _e2075 = local_142;
                                                                    let _e2077 = ((_e2075 * f32(_e2063.member_2)) - _e2067);
                                                                    local_151 = _e2077;
                                                                    local_152 = floor(_e2072);
                                                                    local_153 = floor(_e2077);
                                                                    let _e2080 = local_134;
                                                                    if _e2080 {
                                                                        phi_1527_ = 0f;
                                                                        phi_1528_ = 0f;
                                                                    } else {
                                                                        let _e2081 = local_149;
                                                                        let _e2082 = local_152;
                                                                        let _e2084 = local_151;
                                                                        let _e2085 = local_153;
                                                                        phi_1527_ = (_e2084 - _e2085);
                                                                        phi_1528_ = (_e2081 - _e2082);
                                                                    }
                                                                    let _e2088 = phi_1527_;
                                                                    let _e2090 = phi_1528_;
                                                                    local_154 = _e2088;
                                                                    local_155 = _e2090;
                                                                    let _e2091 = local_152;
                                                                    let _e2093 = local_152;
                                                                    let _e2095 = local_152;
                                                                    let _e2099 = local_152;
                                                                    let _e2100 = local_152;
                                                                    let _e2102 = select(0i, select(select(i32(_e2091), i32(-2147483648), (_e2093 < -2147483600f)), 2147483647i, (_e2095 > 2147483500f)), (_e2099 == _e2100));
                                                                    local_156 = _e2102;
                                                                    let _e2103 = local_153;
                                                                    let _e2105 = local_153;
                                                                    let _e2107 = local_153;
                                                                    let _e2111 = local_153;
                                                                    let _e2112 = local_153;
                                                                    let _e2114 = select(0i, select(select(i32(_e2103), i32(-2147483648), (_e2105 < -2147483600f)), 2147483647i, (_e2107 > 2147483500f)), (_e2111 == _e2112));
                                                                    local_157 = _e2114;
                                                                    let _e2115 = local_146;
                                                                    local_158 = _e2115.member_3;
                                                                    let _e2117 = local_148;
                                                                    local_159 = bitcast<i32>(_e2117);
                                                                    let _e2119 = (_e2115.member_3 == 1u);
                                                                    local_160 = _e2119;
                                                                    if _e2119 {
                                                                        let _e2173 = local_156;
                                                                        if (_e2173 < 0i) {
                                                                            phi_1564_ = 0i;
                                                                        } else {
                                                                            let _e2175 = local_156;
                                                                            let _e2176 = local_159;
                                                                            if (_e2175 >= _e2176) {
                                                                                let _e2178 = local_159;
                                                                                phi_1563_ = (_e2178 - 1i);
                                                                            } else {
                                                                                phi_1563_ = _e2102;
                                                                            }
                                                                            let _e2181 = phi_1563_;
                                                                            phi_1564_ = _e2181;
                                                                        }
                                                                        let _e2183 = phi_1564_;
                                                                        phi_1624_ = _e2183;
                                                                    } else {
                                                                        let _e2120 = local_158;
                                                                        if (_e2120 == 2u) {
                                                                            let _e2142 = local_159;
                                                                            let _e2143 = (2i * _e2142);
                                                                            local_161 = _e2143;
                                                                            let _e2144 = (_e2143 == 0i);
                                                                            local_162 = _e2144;
                                                                            if _e2144 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2145 = local_161;
                                                                            let _e2146 = (_e2145 == -1i);
                                                                            local_163 = _e2146;
                                                                            let _e2147 = local_156;
                                                                            if (_e2146 && (_e2147 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2150 = local_156;
                                                                            let _e2151 = local_161;
                                                                            let _e2153 = local_161;
                                                                            local_164 = ((_e2150 % _e2151) + _e2153);
                                                                            let _e2155 = local_162;
                                                                            if _e2155 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2156 = local_164;
                                                                            let _e2158 = local_163;
                                                                            if (_e2158 && (_e2156 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2160 = local_164;
                                                                            let _e2161 = local_161;
                                                                            let _e2162 = (_e2160 % _e2161);
                                                                            local_165 = _e2162;
                                                                            let _e2163 = local_159;
                                                                            if (_e2162 < _e2163) {
                                                                                phi_1599_ = _e2162;
                                                                            } else {
                                                                                let _e2165 = local_161;
                                                                                let _e2167 = local_165;
                                                                                phi_1599_ = ((_e2165 - 1i) - _e2167);
                                                                            }
                                                                            let _e2170 = phi_1599_;
                                                                            phi_1623_ = _e2170;
                                                                        } else {
                                                                            let _e2122 = local_159;
                                                                            let _e2123 = (_e2122 == 0i);
                                                                            local_166 = _e2123;
                                                                            if _e2123 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2124 = local_159;
                                                                            let _e2125 = (_e2124 == -1i);
                                                                            local_167 = _e2125;
                                                                            let _e2126 = local_156;
                                                                            if (_e2125 && (_e2126 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2129 = local_156;
                                                                            let _e2130 = local_159;
                                                                            let _e2132 = local_159;
                                                                            local_168 = ((_e2129 % _e2130) + _e2132);
                                                                            let _e2134 = local_166;
                                                                            if _e2134 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2135 = local_168;
                                                                            let _e2137 = local_167;
                                                                            if (_e2137 && (_e2135 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2139 = local_168;
                                                                            let _e2140 = local_159;
                                                                            phi_1623_ = (_e2139 % _e2140);
                                                                        }
                                                                        let _e2172 = phi_1623_;
                                                                        phi_1624_ = _e2172;
                                                                    }
                                                                    let _e2185 = phi_1624_;
                                                                    local_169 = bitcast<u32>(_e2185);
                                                                    let _e2187 = local_156;
                                                                    let _e2188 = (_e2187 + 1i);
                                                                    local_170 = _e2188;
                                                                    let _e2189 = local_160;
                                                                    if _e2189 {
                                                                        let _e2243 = local_170;
                                                                        if (_e2243 < 0i) {
                                                                            phi_1644_ = 0i;
                                                                        } else {
                                                                            let _e2245 = local_170;
                                                                            let _e2246 = local_159;
                                                                            if (_e2245 >= _e2246) {
                                                                                let _e2248 = local_159;
                                                                                phi_1643_ = (_e2248 - 1i);
                                                                            } else {
                                                                                phi_1643_ = _e2188;
                                                                            }
                                                                            let _e2251 = phi_1643_;
                                                                            phi_1644_ = _e2251;
                                                                        }
                                                                        let _e2253 = phi_1644_;
                                                                        phi_1704_ = _e2253;
                                                                    } else {
                                                                        let _e2190 = local_158;
                                                                        if (_e2190 == 2u) {
                                                                            let _e2212 = local_159;
                                                                            let _e2213 = (2i * _e2212);
                                                                            local_171 = _e2213;
                                                                            let _e2214 = (_e2213 == 0i);
                                                                            local_172 = _e2214;
                                                                            if _e2214 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2215 = local_171;
                                                                            let _e2216 = (_e2215 == -1i);
                                                                            local_173 = _e2216;
                                                                            let _e2217 = local_170;
                                                                            if (_e2216 && (_e2217 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2220 = local_170;
                                                                            let _e2221 = local_171;
                                                                            let _e2223 = local_171;
                                                                            local_174 = ((_e2220 % _e2221) + _e2223);
                                                                            let _e2225 = local_172;
                                                                            if _e2225 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2226 = local_174;
                                                                            let _e2228 = local_173;
                                                                            if (_e2228 && (_e2226 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2230 = local_174;
                                                                            let _e2231 = local_171;
                                                                            let _e2232 = (_e2230 % _e2231);
                                                                            local_175 = _e2232;
                                                                            let _e2233 = local_159;
                                                                            if (_e2232 < _e2233) {
                                                                                phi_1679_ = _e2232;
                                                                            } else {
                                                                                let _e2235 = local_171;
                                                                                let _e2237 = local_175;
                                                                                phi_1679_ = ((_e2235 - 1i) - _e2237);
                                                                            }
                                                                            let _e2240 = phi_1679_;
                                                                            phi_1703_ = _e2240;
                                                                        } else {
                                                                            let _e2192 = local_159;
                                                                            let _e2193 = (_e2192 == 0i);
                                                                            local_176 = _e2193;
                                                                            if _e2193 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2194 = local_159;
                                                                            let _e2195 = (_e2194 == -1i);
                                                                            local_177 = _e2195;
                                                                            let _e2196 = local_170;
                                                                            if (_e2195 && (_e2196 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2199 = local_170;
                                                                            let _e2200 = local_159;
                                                                            let _e2202 = local_159;
                                                                            local_178 = ((_e2199 % _e2200) + _e2202);
                                                                            let _e2204 = local_176;
                                                                            if _e2204 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2205 = local_178;
                                                                            let _e2207 = local_177;
                                                                            if (_e2207 && (_e2205 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2209 = local_178;
                                                                            let _e2210 = local_159;
                                                                            phi_1703_ = (_e2209 % _e2210);
                                                                        }
                                                                        let _e2242 = phi_1703_;
                                                                        phi_1704_ = _e2242;
                                                                    }
                                                                    let _e2255 = phi_1704_;
                                                                    local_179 = bitcast<u32>(_e2255);
                                                                    let _e2257 = local_146;
                                                                    local_180 = _e2257.member_4;
                                                                    let _e2259 = local_150;
                                                                    local_181 = bitcast<i32>(_e2259);
                                                                    let _e2261 = (_e2257.member_4 == 1u);
                                                                    local_182 = _e2261;
                                                                    if _e2261 {
                                                                        let _e2315 = local_157;
                                                                        if (_e2315 < 0i) {
                                                                            phi_1723_ = 0i;
                                                                        } else {
                                                                            let _e2317 = local_157;
                                                                            let _e2318 = local_181;
                                                                            if (_e2317 >= _e2318) {
                                                                                let _e2320 = local_181;
                                                                                phi_1722_ = (_e2320 - 1i);
                                                                            } else {
                                                                                phi_1722_ = _e2114;
                                                                            }
                                                                            let _e2323 = phi_1722_;
                                                                            phi_1723_ = _e2323;
                                                                        }
                                                                        let _e2325 = phi_1723_;
                                                                        phi_1783_ = _e2325;
                                                                    } else {
                                                                        let _e2262 = local_180;
                                                                        if (_e2262 == 2u) {
                                                                            let _e2284 = local_181;
                                                                            let _e2285 = (2i * _e2284);
                                                                            local_183 = _e2285;
                                                                            let _e2286 = (_e2285 == 0i);
                                                                            local_184 = _e2286;
                                                                            if _e2286 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2287 = local_183;
                                                                            let _e2288 = (_e2287 == -1i);
                                                                            local_185 = _e2288;
                                                                            let _e2289 = local_157;
                                                                            if (_e2288 && (_e2289 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2292 = local_157;
                                                                            let _e2293 = local_183;
                                                                            let _e2295 = local_183;
                                                                            local_186 = ((_e2292 % _e2293) + _e2295);
                                                                            let _e2297 = local_184;
                                                                            if _e2297 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2298 = local_186;
                                                                            let _e2300 = local_185;
                                                                            if (_e2300 && (_e2298 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2302 = local_186;
                                                                            let _e2303 = local_183;
                                                                            let _e2304 = (_e2302 % _e2303);
                                                                            local_187 = _e2304;
                                                                            let _e2305 = local_181;
                                                                            if (_e2304 < _e2305) {
                                                                                phi_1758_ = _e2304;
                                                                            } else {
                                                                                let _e2307 = local_183;
                                                                                let _e2309 = local_187;
                                                                                phi_1758_ = ((_e2307 - 1i) - _e2309);
                                                                            }
                                                                            let _e2312 = phi_1758_;
                                                                            phi_1782_ = _e2312;
                                                                        } else {
                                                                            let _e2264 = local_181;
                                                                            let _e2265 = (_e2264 == 0i);
                                                                            local_188 = _e2265;
                                                                            if _e2265 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2266 = local_181;
                                                                            let _e2267 = (_e2266 == -1i);
                                                                            local_189 = _e2267;
                                                                            let _e2268 = local_157;
                                                                            if (_e2267 && (_e2268 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2271 = local_157;
                                                                            let _e2272 = local_181;
                                                                            let _e2274 = local_181;
                                                                            local_190 = ((_e2271 % _e2272) + _e2274);
                                                                            let _e2276 = local_188;
                                                                            if _e2276 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2277 = local_190;
                                                                            let _e2279 = local_189;
                                                                            if (_e2279 && (_e2277 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2281 = local_190;
                                                                            let _e2282 = local_181;
                                                                            phi_1782_ = (_e2281 % _e2282);
                                                                        }
                                                                        let _e2314 = phi_1782_;
                                                                        phi_1783_ = _e2314;
                                                                    }
                                                                    let _e2327 = phi_1783_;
                                                                    local_191 = bitcast<u32>(_e2327);
                                                                    let _e2329 = local_157;
                                                                    let _e2330 = (_e2329 + 1i);
                                                                    local_192 = _e2330;
                                                                    let _e2331 = local_182;
                                                                    if _e2331 {
                                                                        let _e2385 = local_192;
                                                                        if (_e2385 < 0i) {
                                                                            phi_1803_ = 0i;
                                                                        } else {
                                                                            let _e2387 = local_192;
                                                                            let _e2388 = local_181;
                                                                            if (_e2387 >= _e2388) {
                                                                                let _e2390 = local_181;
                                                                                phi_1802_ = (_e2390 - 1i);
                                                                            } else {
                                                                                phi_1802_ = _e2330;
                                                                            }
                                                                            let _e2393 = phi_1802_;
                                                                            phi_1803_ = _e2393;
                                                                        }
                                                                        let _e2395 = phi_1803_;
                                                                        phi_1863_ = _e2395;
                                                                    } else {
                                                                        let _e2332 = local_180;
                                                                        if (_e2332 == 2u) {
                                                                            let _e2354 = local_181;
                                                                            let _e2355 = (2i * _e2354);
                                                                            local_193 = _e2355;
                                                                            let _e2356 = (_e2355 == 0i);
                                                                            local_194 = _e2356;
                                                                            if _e2356 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2357 = local_193;
                                                                            let _e2358 = (_e2357 == -1i);
                                                                            local_195 = _e2358;
                                                                            let _e2359 = local_192;
                                                                            if (_e2358 && (_e2359 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2362 = local_192;
                                                                            let _e2363 = local_193;
                                                                            let _e2365 = local_193;
                                                                            local_196 = ((_e2362 % _e2363) + _e2365);
                                                                            let _e2367 = local_194;
                                                                            if _e2367 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2368 = local_196;
                                                                            let _e2370 = local_195;
                                                                            if (_e2370 && (_e2368 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2372 = local_196;
                                                                            let _e2373 = local_193;
                                                                            let _e2374 = (_e2372 % _e2373);
                                                                            local_197 = _e2374;
                                                                            let _e2375 = local_181;
                                                                            if (_e2374 < _e2375) {
                                                                                phi_1838_ = _e2374;
                                                                            } else {
                                                                                let _e2377 = local_193;
                                                                                let _e2379 = local_197;
                                                                                phi_1838_ = ((_e2377 - 1i) - _e2379);
                                                                            }
                                                                            let _e2382 = phi_1838_;
                                                                            phi_1862_ = _e2382;
                                                                        } else {
                                                                            let _e2334 = local_181;
                                                                            let _e2335 = (_e2334 == 0i);
                                                                            local_198 = _e2335;
                                                                            if _e2335 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2336 = local_181;
                                                                            let _e2337 = (_e2336 == -1i);
                                                                            local_199 = _e2337;
                                                                            let _e2338 = local_192;
                                                                            if (_e2337 && (_e2338 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2341 = local_192;
                                                                            let _e2342 = local_181;
                                                                            let _e2344 = local_181;
                                                                            local_200 = ((_e2341 % _e2342) + _e2344);
                                                                            let _e2346 = local_198;
                                                                            if _e2346 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2347 = local_200;
                                                                            let _e2349 = local_199;
                                                                            if (_e2349 && (_e2347 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2351 = local_200;
                                                                            let _e2352 = local_181;
                                                                            phi_1862_ = (_e2351 % _e2352);
                                                                        }
                                                                        let _e2384 = phi_1862_;
                                                                        phi_1863_ = _e2384;
                                                                    }
                                                                    let _e2397 = phi_1863_;
                                                                    local_201 = bitcast<u32>(_e2397);
                                                                    let _e2399 = local_146;
                                                                    local_202 = _e2399.member;
                                                                    let _e2401 = local_191;
                                                                    let _e2402 = local_148;
                                                                    let _e2404 = (_e2399.member + (_e2401 * _e2402));
                                                                    local_203 = _e2404;
                                                                    let _e2405 = local_169;
                                                                    let _e2407 = ((_e2404 + _e2405) * 2u);
                                                                    local_204 = _e2407;
                                                                    let _e2408 = local_6;
                                                                    if (_e2407 < _e2408) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2410 = local_204;
                                                                    let _e2413 = global_9.member[_e2410];
                                                                    local_205 = _e2413;
                                                                    let _e2414 = local_204;
                                                                    let _e2415 = (_e2414 + 1u);
                                                                    local_206 = _e2415;
                                                                    let _e2416 = local_6;
                                                                    if (_e2415 < _e2416) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2418 = local_206;
                                                                    let _e2421 = global_9.member[_e2418];
                                                                    local_207 = _e2421;
                                                                    let _e2422 = local_205;
                                                                    let _e2423 = (_e2422 & 65535u);
                                                                    local_565 = select(-1f, 1f, ((_e2423 & 32768u) == 0u));
                                                                    let _e2429 = ((_e2423 >> bitcast<u32>(10i)) & 31u);
                                                                    local_208 = _e2429;
                                                                    local_209 = (_e2423 & 1023u);
                                                                    if (_e2429 == 0u) {
                                                                        let _e2451 = local_209;
                                                                        let _e2453 = local_565;
                                                                        phi_1933_ = ((_e2453 * f32(_e2451)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2432 = local_208;
                                                                        if (_e2432 == 31u) {
                                                                            let _e2442 = local_209;
                                                                            phi_1930_ = (2139095040u | (_e2442 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2434 = local_208;
                                                                            let _e2438 = local_209;
                                                                            phi_1930_ = (((_e2434 + 112u) << bitcast<u32>(23i)) | (_e2438 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2447 = phi_1930_;
                                                                        let _e2449 = local_565;
                                                                        phi_1933_ = (_e2449 * bitcast<f32>(_e2447));
                                                                    }
                                                                    let _e2457 = phi_1933_;
                                                                    local_210 = _e2457;
                                                                    let _e2458 = local_205;
                                                                    let _e2460 = (_e2458 >> bitcast<u32>(16i));
                                                                    local_566 = select(-1f, 1f, ((_e2460 & 32768u) == 0u));
                                                                    let _e2466 = ((_e2460 >> bitcast<u32>(10i)) & 31u);
                                                                    local_211 = _e2466;
                                                                    local_212 = (_e2460 & 1023u);
                                                                    if (_e2466 == 0u) {
                                                                        let _e2488 = local_212;
                                                                        let _e2490 = local_566;
                                                                        phi_1965_ = ((_e2490 * f32(_e2488)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2469 = local_211;
                                                                        if (_e2469 == 31u) {
                                                                            let _e2479 = local_212;
                                                                            phi_1962_ = (2139095040u | (_e2479 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2471 = local_211;
                                                                            let _e2475 = local_212;
                                                                            phi_1962_ = (((_e2471 + 112u) << bitcast<u32>(23i)) | (_e2475 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2484 = phi_1962_;
                                                                        let _e2486 = local_566;
                                                                        phi_1965_ = (_e2486 * bitcast<f32>(_e2484));
                                                                    }
                                                                    let _e2494 = phi_1965_;
                                                                    local_213 = _e2494;
                                                                    let _e2495 = local_207;
                                                                    let _e2496 = (_e2495 & 65535u);
                                                                    local_567 = select(-1f, 1f, ((_e2496 & 32768u) == 0u));
                                                                    let _e2502 = ((_e2496 >> bitcast<u32>(10i)) & 31u);
                                                                    local_214 = _e2502;
                                                                    local_215 = (_e2496 & 1023u);
                                                                    if (_e2502 == 0u) {
                                                                        let _e2524 = local_215;
                                                                        let _e2526 = local_567;
                                                                        phi_1997_ = ((_e2526 * f32(_e2524)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2505 = local_214;
                                                                        if (_e2505 == 31u) {
                                                                            let _e2515 = local_215;
                                                                            phi_1994_ = (2139095040u | (_e2515 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2507 = local_214;
                                                                            let _e2511 = local_215;
                                                                            phi_1994_ = (((_e2507 + 112u) << bitcast<u32>(23i)) | (_e2511 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2520 = phi_1994_;
                                                                        let _e2522 = local_567;
                                                                        phi_1997_ = (_e2522 * bitcast<f32>(_e2520));
                                                                    }
                                                                    let _e2530 = phi_1997_;
                                                                    local_216 = _e2530;
                                                                    let _e2531 = local_207;
                                                                    let _e2533 = (_e2531 >> bitcast<u32>(16i));
                                                                    local_568 = select(-1f, 1f, ((_e2533 & 32768u) == 0u));
                                                                    let _e2539 = ((_e2533 >> bitcast<u32>(10i)) & 31u);
                                                                    local_217 = _e2539;
                                                                    local_218 = (_e2533 & 1023u);
                                                                    if (_e2539 == 0u) {
                                                                        let _e2561 = local_218;
                                                                        let _e2563 = local_568;
                                                                        phi_2029_ = ((_e2563 * f32(_e2561)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2542 = local_217;
                                                                        if (_e2542 == 31u) {
                                                                            let _e2552 = local_218;
                                                                            phi_2026_ = (2139095040u | (_e2552 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2544 = local_217;
                                                                            let _e2548 = local_218;
                                                                            phi_2026_ = (((_e2544 + 112u) << bitcast<u32>(23i)) | (_e2548 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2557 = phi_2026_;
                                                                        let _e2559 = local_568;
                                                                        phi_2029_ = (_e2559 * bitcast<f32>(_e2557));
                                                                    }
                                                                    let _e2567 = phi_2029_;
                                                                    local_219 = _e2567;
                                                                    let _e2568 = local_203;
                                                                    let _e2569 = local_179;
                                                                    let _e2571 = ((_e2568 + _e2569) * 2u);
                                                                    local_220 = _e2571;
                                                                    let _e2572 = local_6;
                                                                    if (_e2571 < _e2572) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2574 = local_220;
                                                                    let _e2577 = global_9.member[_e2574];
                                                                    local_221 = _e2577;
                                                                    let _e2578 = local_220;
                                                                    let _e2579 = (_e2578 + 1u);
                                                                    local_222 = _e2579;
                                                                    let _e2580 = local_6;
                                                                    if (_e2579 < _e2580) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2582 = local_222;
                                                                    let _e2585 = global_9.member[_e2582];
                                                                    local_223 = _e2585;
                                                                    let _e2586 = local_221;
                                                                    let _e2587 = (_e2586 & 65535u);
                                                                    local_569 = select(-1f, 1f, ((_e2587 & 32768u) == 0u));
                                                                    let _e2593 = ((_e2587 >> bitcast<u32>(10i)) & 31u);
                                                                    local_224 = _e2593;
                                                                    local_225 = (_e2587 & 1023u);
                                                                    if (_e2593 == 0u) {
                                                                        let _e2615 = local_225;
                                                                        let _e2617 = local_569;
                                                                        phi_2098_ = ((_e2617 * f32(_e2615)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2596 = local_224;
                                                                        if (_e2596 == 31u) {
                                                                            let _e2606 = local_225;
                                                                            phi_2095_ = (2139095040u | (_e2606 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2598 = local_224;
                                                                            let _e2602 = local_225;
                                                                            phi_2095_ = (((_e2598 + 112u) << bitcast<u32>(23i)) | (_e2602 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2611 = phi_2095_;
                                                                        let _e2613 = local_569;
                                                                        phi_2098_ = (_e2613 * bitcast<f32>(_e2611));
                                                                    }
                                                                    let _e2621 = phi_2098_;
                                                                    local_226 = _e2621;
                                                                    let _e2622 = local_221;
                                                                    let _e2624 = (_e2622 >> bitcast<u32>(16i));
                                                                    local_570 = select(-1f, 1f, ((_e2624 & 32768u) == 0u));
                                                                    let _e2630 = ((_e2624 >> bitcast<u32>(10i)) & 31u);
                                                                    local_227 = _e2630;
                                                                    local_228 = (_e2624 & 1023u);
                                                                    if (_e2630 == 0u) {
                                                                        let _e2652 = local_228;
                                                                        let _e2654 = local_570;
                                                                        phi_2130_ = ((_e2654 * f32(_e2652)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2633 = local_227;
                                                                        if (_e2633 == 31u) {
                                                                            let _e2643 = local_228;
                                                                            phi_2127_ = (2139095040u | (_e2643 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2635 = local_227;
                                                                            let _e2639 = local_228;
                                                                            phi_2127_ = (((_e2635 + 112u) << bitcast<u32>(23i)) | (_e2639 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2648 = phi_2127_;
                                                                        let _e2650 = local_570;
                                                                        phi_2130_ = (_e2650 * bitcast<f32>(_e2648));
                                                                    }
                                                                    let _e2658 = phi_2130_;
                                                                    local_229 = _e2658;
                                                                    let _e2659 = local_223;
                                                                    let _e2660 = (_e2659 & 65535u);
                                                                    local_571 = select(-1f, 1f, ((_e2660 & 32768u) == 0u));
                                                                    let _e2666 = ((_e2660 >> bitcast<u32>(10i)) & 31u);
                                                                    local_230 = _e2666;
                                                                    local_231 = (_e2660 & 1023u);
                                                                    if (_e2666 == 0u) {
                                                                        let _e2688 = local_231;
                                                                        let _e2690 = local_571;
                                                                        phi_2162_ = ((_e2690 * f32(_e2688)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2669 = local_230;
                                                                        if (_e2669 == 31u) {
                                                                            let _e2679 = local_231;
                                                                            phi_2159_ = (2139095040u | (_e2679 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2671 = local_230;
                                                                            let _e2675 = local_231;
                                                                            phi_2159_ = (((_e2671 + 112u) << bitcast<u32>(23i)) | (_e2675 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2684 = phi_2159_;
                                                                        let _e2686 = local_571;
                                                                        phi_2162_ = (_e2686 * bitcast<f32>(_e2684));
                                                                    }
                                                                    let _e2694 = phi_2162_;
                                                                    local_232 = _e2694;
                                                                    let _e2695 = local_223;
                                                                    let _e2697 = (_e2695 >> bitcast<u32>(16i));
                                                                    local_572 = select(-1f, 1f, ((_e2697 & 32768u) == 0u));
                                                                    let _e2703 = ((_e2697 >> bitcast<u32>(10i)) & 31u);
                                                                    local_233 = _e2703;
                                                                    local_234 = (_e2697 & 1023u);
                                                                    if (_e2703 == 0u) {
                                                                        let _e2725 = local_234;
                                                                        let _e2727 = local_572;
                                                                        phi_2194_ = ((_e2727 * f32(_e2725)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2706 = local_233;
                                                                        if (_e2706 == 31u) {
                                                                            let _e2716 = local_234;
                                                                            phi_2191_ = (2139095040u | (_e2716 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2708 = local_233;
                                                                            let _e2712 = local_234;
                                                                            phi_2191_ = (((_e2708 + 112u) << bitcast<u32>(23i)) | (_e2712 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2721 = phi_2191_;
                                                                        let _e2723 = local_572;
                                                                        phi_2194_ = (_e2723 * bitcast<f32>(_e2721));
                                                                    }
                                                                    let _e2731 = phi_2194_;
                                                                    let _e2732 = local_226;
                                                                    let _e2733 = local_210;
                                                                    let _e2735 = local_155;
                                                                    let _e2737 = local_210;
                                                                    local_235 = (_e2737 + ((_e2732 - _e2733) * _e2735));
                                                                    let _e2739 = local_229;
                                                                    let _e2740 = local_213;
                                                                    let _e2742 = local_155;
                                                                    let _e2744 = local_213;
                                                                    local_236 = (_e2744 + ((_e2739 - _e2740) * _e2742));
                                                                    let _e2746 = local_232;
                                                                    let _e2747 = local_216;
                                                                    let _e2749 = local_155;
                                                                    let _e2751 = local_216;
                                                                    local_237 = (_e2751 + ((_e2746 - _e2747) * _e2749));
                                                                    let _e2753 = local_219;
                                                                    let _e2755 = local_155;
                                                                    let _e2757 = local_219;
                                                                    local_238 = (_e2757 + ((_e2731 - _e2753) * _e2755));
                                                                    let _e2759 = local_201;
                                                                    let _e2760 = local_148;
                                                                    let _e2762 = local_202;
                                                                    let _e2763 = (_e2762 + (_e2759 * _e2760));
                                                                    local_239 = _e2763;
                                                                    let _e2764 = local_169;
                                                                    let _e2766 = ((_e2763 + _e2764) * 2u);
                                                                    local_240 = _e2766;
                                                                    let _e2767 = local_6;
                                                                    if (_e2766 < _e2767) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2769 = local_240;
                                                                    let _e2772 = global_9.member[_e2769];
                                                                    local_241 = _e2772;
                                                                    let _e2773 = local_240;
                                                                    let _e2774 = (_e2773 + 1u);
                                                                    local_242 = _e2774;
                                                                    let _e2775 = local_6;
                                                                    if (_e2774 < _e2775) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2777 = local_242;
                                                                    let _e2780 = global_9.member[_e2777];
                                                                    local_243 = _e2780;
                                                                    let _e2781 = local_241;
                                                                    let _e2782 = (_e2781 & 65535u);
                                                                    local_573 = select(-1f, 1f, ((_e2782 & 32768u) == 0u));
                                                                    let _e2788 = ((_e2782 >> bitcast<u32>(10i)) & 31u);
                                                                    local_244 = _e2788;
                                                                    local_245 = (_e2782 & 1023u);
                                                                    if (_e2788 == 0u) {
                                                                        let _e2810 = local_245;
                                                                        let _e2812 = local_573;
                                                                        phi_2275_ = ((_e2812 * f32(_e2810)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2791 = local_244;
                                                                        if (_e2791 == 31u) {
                                                                            let _e2801 = local_245;
                                                                            phi_2272_ = (2139095040u | (_e2801 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2793 = local_244;
                                                                            let _e2797 = local_245;
                                                                            phi_2272_ = (((_e2793 + 112u) << bitcast<u32>(23i)) | (_e2797 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2806 = phi_2272_;
                                                                        let _e2808 = local_573;
                                                                        phi_2275_ = (_e2808 * bitcast<f32>(_e2806));
                                                                    }
                                                                    let _e2816 = phi_2275_;
                                                                    local_246 = _e2816;
                                                                    let _e2817 = local_241;
                                                                    let _e2819 = (_e2817 >> bitcast<u32>(16i));
                                                                    local_574 = select(-1f, 1f, ((_e2819 & 32768u) == 0u));
                                                                    let _e2825 = ((_e2819 >> bitcast<u32>(10i)) & 31u);
                                                                    local_247 = _e2825;
                                                                    local_248 = (_e2819 & 1023u);
                                                                    if (_e2825 == 0u) {
                                                                        let _e2847 = local_248;
                                                                        let _e2849 = local_574;
                                                                        phi_2307_ = ((_e2849 * f32(_e2847)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2828 = local_247;
                                                                        if (_e2828 == 31u) {
                                                                            let _e2838 = local_248;
                                                                            phi_2304_ = (2139095040u | (_e2838 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2830 = local_247;
                                                                            let _e2834 = local_248;
                                                                            phi_2304_ = (((_e2830 + 112u) << bitcast<u32>(23i)) | (_e2834 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2843 = phi_2304_;
                                                                        let _e2845 = local_574;
                                                                        phi_2307_ = (_e2845 * bitcast<f32>(_e2843));
                                                                    }
                                                                    let _e2853 = phi_2307_;
                                                                    local_249 = _e2853;
                                                                    let _e2854 = local_243;
                                                                    let _e2855 = (_e2854 & 65535u);
                                                                    local_575 = select(-1f, 1f, ((_e2855 & 32768u) == 0u));
                                                                    let _e2861 = ((_e2855 >> bitcast<u32>(10i)) & 31u);
                                                                    local_250 = _e2861;
                                                                    local_251 = (_e2855 & 1023u);
                                                                    if (_e2861 == 0u) {
                                                                        let _e2883 = local_251;
                                                                        let _e2885 = local_575;
                                                                        phi_2339_ = ((_e2885 * f32(_e2883)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2864 = local_250;
                                                                        if (_e2864 == 31u) {
                                                                            let _e2874 = local_251;
                                                                            phi_2336_ = (2139095040u | (_e2874 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2866 = local_250;
                                                                            let _e2870 = local_251;
                                                                            phi_2336_ = (((_e2866 + 112u) << bitcast<u32>(23i)) | (_e2870 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2879 = phi_2336_;
                                                                        let _e2881 = local_575;
                                                                        phi_2339_ = (_e2881 * bitcast<f32>(_e2879));
                                                                    }
                                                                    let _e2889 = phi_2339_;
                                                                    local_252 = _e2889;
                                                                    let _e2890 = local_243;
                                                                    let _e2892 = (_e2890 >> bitcast<u32>(16i));
                                                                    local_576 = select(-1f, 1f, ((_e2892 & 32768u) == 0u));
                                                                    let _e2898 = ((_e2892 >> bitcast<u32>(10i)) & 31u);
                                                                    local_253 = _e2898;
                                                                    local_254 = (_e2892 & 1023u);
                                                                    if (_e2898 == 0u) {
                                                                        let _e2920 = local_254;
                                                                        let _e2922 = local_576;
                                                                        phi_2371_ = ((_e2922 * f32(_e2920)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2901 = local_253;
                                                                        if (_e2901 == 31u) {
                                                                            let _e2911 = local_254;
                                                                            phi_2368_ = (2139095040u | (_e2911 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2903 = local_253;
                                                                            let _e2907 = local_254;
                                                                            phi_2368_ = (((_e2903 + 112u) << bitcast<u32>(23i)) | (_e2907 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2916 = phi_2368_;
                                                                        let _e2918 = local_576;
                                                                        phi_2371_ = (_e2918 * bitcast<f32>(_e2916));
                                                                    }
                                                                    let _e2926 = phi_2371_;
                                                                    local_255 = _e2926;
                                                                    let _e2927 = local_239;
                                                                    let _e2928 = local_179;
                                                                    let _e2930 = ((_e2927 + _e2928) * 2u);
                                                                    local_256 = _e2930;
                                                                    let _e2931 = local_6;
                                                                    if (_e2930 < _e2931) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2933 = local_256;
                                                                    let _e2936 = global_9.member[_e2933];
                                                                    local_257 = _e2936;
                                                                    let _e2937 = local_256;
                                                                    let _e2938 = (_e2937 + 1u);
                                                                    local_258 = _e2938;
                                                                    let _e2939 = local_6;
                                                                    if (_e2938 < _e2939) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2941 = local_258;
                                                                    let _e2944 = global_9.member[_e2941];
                                                                    local_259 = _e2944;
                                                                    let _e2945 = local_257;
                                                                    let _e2946 = (_e2945 & 65535u);
                                                                    local_577 = select(-1f, 1f, ((_e2946 & 32768u) == 0u));
                                                                    let _e2952 = ((_e2946 >> bitcast<u32>(10i)) & 31u);
                                                                    local_260 = _e2952;
                                                                    local_261 = (_e2946 & 1023u);
                                                                    if (_e2952 == 0u) {
                                                                        let _e2974 = local_261;
                                                                        let _e2976 = local_577;
                                                                        phi_2440_ = ((_e2976 * f32(_e2974)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2955 = local_260;
                                                                        if (_e2955 == 31u) {
                                                                            let _e2965 = local_261;
                                                                            phi_2437_ = (2139095040u | (_e2965 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2957 = local_260;
                                                                            let _e2961 = local_261;
                                                                            phi_2437_ = (((_e2957 + 112u) << bitcast<u32>(23i)) | (_e2961 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2970 = phi_2437_;
                                                                        let _e2972 = local_577;
                                                                        phi_2440_ = (_e2972 * bitcast<f32>(_e2970));
                                                                    }
                                                                    let _e2980 = phi_2440_;
                                                                    local_262 = _e2980;
                                                                    let _e2981 = local_257;
                                                                    let _e2983 = (_e2981 >> bitcast<u32>(16i));
                                                                    local_578 = select(-1f, 1f, ((_e2983 & 32768u) == 0u));
                                                                    let _e2989 = ((_e2983 >> bitcast<u32>(10i)) & 31u);
                                                                    local_263 = _e2989;
                                                                    local_264 = (_e2983 & 1023u);
                                                                    if (_e2989 == 0u) {
                                                                        let _e3011 = local_264;
                                                                        let _e3013 = local_578;
                                                                        phi_2472_ = ((_e3013 * f32(_e3011)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2992 = local_263;
                                                                        if (_e2992 == 31u) {
                                                                            let _e3002 = local_264;
                                                                            phi_2469_ = (2139095040u | (_e3002 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2994 = local_263;
                                                                            let _e2998 = local_264;
                                                                            phi_2469_ = (((_e2994 + 112u) << bitcast<u32>(23i)) | (_e2998 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3007 = phi_2469_;
                                                                        let _e3009 = local_578;
                                                                        phi_2472_ = (_e3009 * bitcast<f32>(_e3007));
                                                                    }
                                                                    let _e3017 = phi_2472_;
                                                                    local_265 = _e3017;
                                                                    let _e3018 = local_259;
                                                                    let _e3019 = (_e3018 & 65535u);
                                                                    local_579 = select(-1f, 1f, ((_e3019 & 32768u) == 0u));
                                                                    let _e3025 = ((_e3019 >> bitcast<u32>(10i)) & 31u);
                                                                    local_266 = _e3025;
                                                                    local_267 = (_e3019 & 1023u);
                                                                    if (_e3025 == 0u) {
                                                                        let _e3047 = local_267;
                                                                        let _e3049 = local_579;
                                                                        phi_2504_ = ((_e3049 * f32(_e3047)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3028 = local_266;
                                                                        if (_e3028 == 31u) {
                                                                            let _e3038 = local_267;
                                                                            phi_2501_ = (2139095040u | (_e3038 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3030 = local_266;
                                                                            let _e3034 = local_267;
                                                                            phi_2501_ = (((_e3030 + 112u) << bitcast<u32>(23i)) | (_e3034 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3043 = phi_2501_;
                                                                        let _e3045 = local_579;
                                                                        phi_2504_ = (_e3045 * bitcast<f32>(_e3043));
                                                                    }
                                                                    let _e3053 = phi_2504_;
                                                                    local_268 = _e3053;
                                                                    let _e3054 = local_259;
                                                                    let _e3056 = (_e3054 >> bitcast<u32>(16i));
                                                                    local_580 = select(-1f, 1f, ((_e3056 & 32768u) == 0u));
                                                                    let _e3062 = ((_e3056 >> bitcast<u32>(10i)) & 31u);
                                                                    local_269 = _e3062;
                                                                    local_270 = (_e3056 & 1023u);
                                                                    if (_e3062 == 0u) {
                                                                        let _e3084 = local_270;
                                                                        let _e3086 = local_580;
                                                                        phi_2536_ = ((_e3086 * f32(_e3084)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3065 = local_269;
                                                                        if (_e3065 == 31u) {
                                                                            let _e3075 = local_270;
                                                                            phi_2533_ = (2139095040u | (_e3075 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3067 = local_269;
                                                                            let _e3071 = local_270;
                                                                            phi_2533_ = (((_e3067 + 112u) << bitcast<u32>(23i)) | (_e3071 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3080 = phi_2533_;
                                                                        let _e3082 = local_580;
                                                                        phi_2536_ = (_e3082 * bitcast<f32>(_e3080));
                                                                    }
                                                                    let _e3090 = phi_2536_;
                                                                    let _e3091 = local_262;
                                                                    let _e3092 = local_246;
                                                                    let _e3094 = local_155;
                                                                    let _e3096 = local_246;
                                                                    let _e3098 = local_265;
                                                                    let _e3099 = local_249;
                                                                    let _e3101 = local_155;
                                                                    let _e3103 = local_249;
                                                                    let _e3105 = local_268;
                                                                    let _e3106 = local_252;
                                                                    let _e3108 = local_155;
                                                                    let _e3110 = local_252;
                                                                    let _e3112 = local_255;
                                                                    let _e3114 = local_155;
                                                                    let _e3116 = local_255;
                                                                    let _e3118 = local_235;
                                                                    let _e3120 = local_154;
                                                                    let _e3122 = local_235;
                                                                    let _e3124 = local_236;
                                                                    let _e3126 = local_154;
                                                                    let _e3128 = local_236;
                                                                    let _e3130 = local_237;
                                                                    let _e3132 = local_154;
                                                                    let _e3134 = local_237;
                                                                    let _e3136 = local_238;
                                                                    let _e3138 = local_154;
                                                                    let _e3140 = local_238;
                                                                    let _e3142 = local_147;
                                                                    let _e3144 = local_147;
                                                                    let _e3146 = local_147;
                                                                    let _e3148 = local_147;
                                                                    let _e3150 = local_144;
                                                                    let _e3153 = local_144;
                                                                    let _e3156 = local_144;
                                                                    let _e3159 = local_144;
                                                                    let _e3163 = local_143;
                                                                    phi_1491_ = (_e3163 + 1u);
                                                                    phi_1494_ = type_5((_e3150.member + ((_e3122 + (((_e3096 + ((_e3091 - _e3092) * _e3094)) - _e3118) * _e3120)) * _e3142)), (_e3153.member_1 + ((_e3128 + (((_e3103 + ((_e3098 - _e3099) * _e3101)) - _e3124) * _e3126)) * _e3144)), (_e3156.member_2 + ((_e3134 + (((_e3110 + ((_e3105 - _e3106) * _e3108)) - _e3130) * _e3132)) * _e3146)), (_e3159.member_3 + ((_e3140 + (((_e3116 + ((_e3090 - _e3112) * _e3114)) - _e3136) * _e3138)) * _e3148)));
                                                                } else {
                                                                    phi_1491_ = u32();
                                                                    phi_1494_ = type_5();
                                                                }
                                                                let _e3166 = phi_1491_;
                                                                let _e3168 = phi_1494_;
                                                                continue;
                                                                continuing {
                                                                    let _e3169 = local_145;
                                                                    phi_1490_ = _e3166;
                                                                    phi_1493_ = _e3168;
                                                                    phi_5704_ = _e2020;
                                                                    break if !(_e3169);
                                                                }
                                                            }
                                                            let _e3172 = phi_5704_;
                                                            phi_5818_ = _e3172;
                                                            if _e3172 {
                                                                break;
                                                            }
                                                            let _e3173 = local_139;
                                                            phi_5819_ = _e3172;
                                                            phi_1462_ = (_e3173 + 1u);
                                                            let _e5569 = local_626;
                                                            phi_1465_ = _e5569;
                                                        } else {
                                                            phi_5819_ = _e2020;
                                                            phi_1462_ = u32();
                                                            phi_1465_ = type_5();
                                                        }
                                                        let _e3176 = phi_5819_;
                                                        let _e3178 = phi_1462_;
                                                        let _e3180 = phi_1465_;
                                                        continue;
                                                        continuing {
                                                            let _e3181 = local_140;
                                                            phi_5750_ = _e3176;
                                                            phi_1461_ = _e3178;
                                                            phi_1464_ = _e3180;
                                                            phi_5818_ = _e3176;
                                                            break if !(_e3181);
                                                        }
                                                    }
                                                    let _e3184 = phi_5818_;
                                                    phi_5820_ = _e3184;
                                                    if _e3184 {
                                                        break;
                                                    }
                                                    let _e3185 = local_135;
                                                    phi_5821_ = _e3184;
                                                    phi_1445_ = (_e3185 + 1u);
                                                    let _e5575 = local_627;
                                                    phi_1448_ = _e5575;
                                                } else {
                                                    phi_5821_ = _e2004;
                                                    phi_1445_ = u32();
                                                    phi_1448_ = type_5();
                                                }
                                                let _e3188 = phi_5821_;
                                                let _e3190 = phi_1445_;
                                                let _e3192 = phi_1448_;
                                                continue;
                                                continuing {
                                                    let _e3193 = local_137;
                                                    phi_5751_ = _e3188;
                                                    phi_1444_ = _e3190;
                                                    phi_1447_ = _e3192;
                                                    phi_5820_ = _e3188;
                                                    break if !(_e3193);
                                                }
                                            }
                                            let _e3196 = phi_5820_;
                                            phi_5975_ = _e3196;
                                            if _e3196 {
                                                break;
                                            }
                                            let _e3197 = local_126;
                                            let _e3198 = local_125;
                                            let _e3201 = (1f / f32((_e3197 * _e3198)));
                                            let _e3202 = local_136;
                                            let _e3205 = local_136;
                                            let _e3208 = local_136;
                                            let _e3211 = local_136;
                                            phi_5895_ = _e3196;
                                            phi_2589_ = type_5((_e3202.member * _e3201), (_e3205.member_1 * _e3201), (_e3208.member_2 * _e3201), (_e3211.member_3 * _e3201));
                                        }
                                        let _e3216 = phi_5895_;
                                        let _e3218 = phi_2589_;
                                        phi_5894_ = _e3216;
                                        phi_2590_ = _e3218;
                                        phi_2591_ = _e1667;
                                    }
                                    let _e3220 = phi_5894_;
                                    let _e3222 = phi_2590_;
                                    let _e3224 = phi_2591_;
                                    if _e3224 {
                                        phi_2595_ = type_5(1f, 1f, 1f, 1f);
                                    } else {
                                        phi_2595_ = _e3222;
                                    }
                                    let _e3226 = phi_2595_;
                                    phi_5892_ = _e3220;
                                    phi_2596_ = _e3226;
                                }
                                let _e3228 = phi_5892_;
                                let _e3230 = phi_2596_;
                                phi_5891_ = _e3228;
                                phi_2597_ = _e3230;
                                phi_2598_ = _e1631;
                            }
                            let _e3232 = phi_5891_;
                            let _e3234 = phi_2597_;
                            let _e3236 = phi_2598_;
                            if _e3236 {
                                phi_2602_ = type_5(1f, 1f, 1f, 1f);
                            } else {
                                phi_2602_ = _e3234;
                            }
                            let _e3238 = phi_2602_;
                            local_619 = array<f32, 4>(_e3238.member, _e3238.member_1, _e3238.member_2, _e3238.member_3);
                            let _e3244 = local_86;
                            if (_e3244 == 4294967295u) {
                                phi_5950_ = _e3232;
                                phi_4080_ = type_5();
                                phi_4081_ = true;
                            } else {
                                let _e3246 = local_86;
                                let _e3247 = local_25;
                                let _e3248 = (_e3246 >= _e3247);
                                if _e3248 {
                                    phi_5951_ = _e3232;
                                    phi_4079_ = type_5();
                                } else {
                                    let _e3249 = local_86;
                                    let _e3250 = (_e3249 * 4u);
                                    local_271 = _e3250;
                                    let _e3251 = local_5;
                                    if (_e3250 < _e3251) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e3253 = local_271;
                                    let _e3256 = global_8.member[_e3253];
                                    local_272 = _e3256;
                                    let _e3257 = local_271;
                                    let _e3258 = (_e3257 + 1u);
                                    local_273 = _e3258;
                                    let _e3259 = local_5;
                                    if (_e3258 < _e3259) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e3261 = local_273;
                                    let _e3264 = global_8.member[_e3261];
                                    local_274 = _e3264;
                                    let _e3265 = local_271;
                                    let _e3266 = (_e3265 + 2u);
                                    local_275 = _e3266;
                                    let _e3267 = local_5;
                                    if (_e3266 < _e3267) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e3269 = local_275;
                                    let _e3272 = global_8.member[_e3269];
                                    local_276 = _e3272;
                                    let _e3273 = local_271;
                                    let _e3274 = (_e3273 + 3u);
                                    local_277 = _e3274;
                                    let _e3275 = local_5;
                                    if (_e3274 < _e3275) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e3277 = local_277;
                                    let _e3280 = global_8.member[_e3277];
                                    local_278 = _e3280;
                                    let _e3281 = local_274;
                                    if (_e3281 == 0u) {
                                        phi_5953_ = _e3232;
                                        phi_4073_ = type_5();
                                        phi_4074_ = true;
                                    } else {
                                        let _e3283 = local_276;
                                        let _e3284 = (_e3283 == 0u);
                                        if _e3284 {
                                            phi_5954_ = _e3232;
                                            phi_4072_ = type_5();
                                        } else {
                                            let _e3285 = local_278;
                                            let _e3288 = ((_e3285 >> bitcast<u32>(8u)) & 31u);
                                            local_581 = select(_e3288, 1u, (_e3288 == 0u));
                                            let _e3291 = local_278;
                                            let _e3295 = local_278;
                                            let _e3299 = local_272;
                                            let _e3300 = local_274;
                                            let _e3301 = local_276;
                                            let _e3302 = type_22(_e3299, _e3300, _e3301, ((_e3291 >> bitcast<u32>(1u)) & 3u), ((_e3295 >> bitcast<u32>(3u)) & 3u));
                                            let _e3303 = local_274;
                                            let _e3304 = f32(_e3303);
                                            local_279 = _e3304;
                                            let _e3305 = local_75;
                                            if ((bitcast<u32>((_e3305 * _e3304)) & 2139095040u) != 2139095040u) {
                                                let _e3310 = local_276;
                                                let _e3312 = local_74;
                                                phi_2722_ = select(true, false, ((bitcast<u32>((_e3312 * f32(_e3310))) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_2722_ = true;
                                            }
                                            let _e3319 = phi_2722_;
                                            let _e3320 = local_74;
                                            local_582 = select(_e3320, 0f, _e3319);
                                            let _e3322 = local_75;
                                            local_583 = select(_e3322, 0f, _e3319);
                                            let _e3324 = local_102;
                                            local_280 = _e3324.member;
                                            let _e3326 = local_279;
                                            let _e3327 = (_e3324.member * _e3326);
                                            let _e3328 = local_102;
                                            local_281 = _e3328.member_1;
                                            let _e3330 = local_276;
                                            let _e3331 = f32(_e3330);
                                            let _e3332 = (_e3328.member_1 * _e3331);
                                            let _e3333 = local_102;
                                            local_282 = _e3333.member_2;
                                            let _e3335 = local_279;
                                            let _e3336 = (_e3333.member_2 * _e3335);
                                            let _e3337 = local_102;
                                            local_283 = _e3337.member_3;
                                            let _e3339 = (_e3337.member_3 * _e3331);
                                            let _e3343 = sqrt(((_e3327 * _e3327) + (_e3332 * _e3332)));
                                            local_284 = _e3343;
                                            let _e3347 = sqrt(((_e3336 * _e3336) + (_e3339 * _e3339)));
                                            local_285 = _e3347;
                                            let _e3349 = select(_e3347, _e3343, (_e3343 > _e3347));
                                            local_584 = _e3349;
                                            if (_e3349 > 1f) {
                                                let _e3351 = local_584;
                                                phi_2761_ = !(((bitcast<u32>(_e3351) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_2761_ = true;
                                            }
                                            let _e3357 = phi_2761_;
                                            local_286 = _e3357;
                                            if _e3357 {
                                                phi_2857_ = 1u;
                                                phi_2858_ = 1u;
                                            } else {
                                                let _e3358 = local_284;
                                                let _e3359 = local_285;
                                                if (_e3358 >= _e3359) {
                                                    let _e3397 = local_285;
                                                    let _e3399 = local_285;
                                                    let _e3401 = ceil(select(8f, _e3399, (_e3397 < 8f)));
                                                    local_287 = _e3401;
                                                    if (_e3401 < 1f) {
                                                        phi_2787_ = 1u;
                                                    } else {
                                                        let _e3403 = local_287;
                                                        let _e3405 = local_287;
                                                        let _e3407 = local_287;
                                                        phi_2787_ = select(select(u32(_e3403), 0u, (_e3405 < 0f)), 4294967295u, (_e3407 > 4294967000f));
                                                    }
                                                    let _e3412 = phi_2787_;
                                                    local_288 = _e3412;
                                                    if (_e3412 == 0u) {
                                                        phi_5975_ = true;
                                                        break;
                                                    }
                                                    let _e3414 = local_288;
                                                    let _e3416 = f32((64u / _e3414));
                                                    let _e3417 = local_284;
                                                    let _e3419 = local_284;
                                                    let _e3421 = ceil(select(_e3416, _e3419, (_e3417 < _e3416)));
                                                    local_289 = _e3421;
                                                    if (_e3421 < 1f) {
                                                        phi_2811_ = 1u;
                                                    } else {
                                                        let _e3423 = local_289;
                                                        let _e3425 = local_289;
                                                        let _e3427 = local_289;
                                                        phi_2811_ = select(select(u32(_e3423), 0u, (_e3425 < 0f)), 4294967295u, (_e3427 > 4294967000f));
                                                    }
                                                    let _e3432 = phi_2811_;
                                                    phi_2855_ = _e3412;
                                                    phi_2856_ = _e3432;
                                                } else {
                                                    let _e3361 = local_284;
                                                    let _e3363 = local_284;
                                                    let _e3365 = ceil(select(8f, _e3363, (_e3361 < 8f)));
                                                    local_290 = _e3365;
                                                    if (_e3365 < 1f) {
                                                        phi_2830_ = 1u;
                                                    } else {
                                                        let _e3367 = local_290;
                                                        let _e3369 = local_290;
                                                        let _e3371 = local_290;
                                                        phi_2830_ = select(select(u32(_e3367), 0u, (_e3369 < 0f)), 4294967295u, (_e3371 > 4294967000f));
                                                    }
                                                    let _e3376 = phi_2830_;
                                                    local_291 = _e3376;
                                                    if (_e3376 == 0u) {
                                                        phi_5975_ = true;
                                                        break;
                                                    }
                                                    let _e3378 = local_291;
                                                    let _e3380 = f32((64u / _e3378));
                                                    let _e3381 = local_285;
                                                    let _e3383 = local_285;
                                                    let _e3385 = ceil(select(_e3380, _e3383, (_e3381 < _e3380)));
                                                    local_292 = _e3385;
                                                    if (_e3385 < 1f) {
                                                        phi_2854_ = 1u;
                                                    } else {
                                                        let _e3387 = local_292;
                                                        let _e3389 = local_292;
                                                        let _e3391 = local_292;
                                                        phi_2854_ = select(select(u32(_e3387), 0u, (_e3389 < 0f)), 4294967295u, (_e3391 > 4294967000f));
                                                    }
                                                    let _e3396 = phi_2854_;
                                                    phi_2855_ = _e3396;
                                                    phi_2856_ = _e3376;
                                                }
                                                let _e3434 = phi_2855_;
                                                let _e3436 = phi_2856_;
                                                phi_2857_ = _e3434;
                                                phi_2858_ = _e3436;
                                            }
                                            let _e3438 = phi_2857_;
                                            let _e3440 = phi_2858_;
                                            local_293 = _e3438;
                                            local_294 = _e3440;
                                            let _e3441 = local_286;
                                            if _e3441 {
                                                phi_2871_ = 1f;
                                            } else {
                                                let _e3442 = local_294;
                                                let _e3444 = local_284;
                                                let _e3445 = (_e3444 / f32(_e3442));
                                                let _e3446 = local_293;
                                                let _e3448 = local_285;
                                                let _e3449 = (_e3448 / f32(_e3446));
                                                phi_2871_ = select(_e3449, _e3445, (_e3445 > _e3449));
                                            }
                                            let _e3453 = phi_2871_;
                                            local_295 = _e3453;
                                            if (_e3453 > 1f) {
                                                let _e3455 = local_295;
                                                let _e3456 = bitcast<u32>(_e3455);
                                                let _e3465 = (bitcast<f32>(((_e3456 & 8388607u) | 1065353216u)) - 1f);
                                                phi_2892_ = (f32((bitcast<i32>(((_e3456 >> bitcast<u32>(23i)) & 255u)) - 127i)) + (_e3465 * (1.4208645f + (_e3465 * (-0.5772506f + (_e3465 * 0.1563861f))))));
                                            } else {
                                                phi_2892_ = 0f;
                                            }
                                            let _e3474 = phi_2892_;
                                            local_296 = _e3474;
                                            let _e3475 = local_581;
                                            let _e3476 = (_e3475 - 1u);
                                            local_297 = _e3476;
                                            let _e3477 = floor(_e3474);
                                            let _e3482 = select(select(u32(_e3477), 0u, (_e3477 < 0f)), 4294967295u, (_e3477 > 4294967000f));
                                            local_298 = _e3482;
                                            let _e3483 = (_e3482 >= _e3476);
                                            local_299 = _e3483;
                                            if _e3483 {
                                                phi_2908_ = 0f;
                                            } else {
                                                let _e3484 = local_298;
                                                let _e3486 = local_296;
                                                phi_2908_ = (_e3486 - f32(_e3484));
                                            }
                                            let _e3489 = phi_2908_;
                                            local_300 = _e3489;
                                            let _e3490 = local_299;
                                            let _e3491 = local_297;
                                            let _e3492 = local_298;
                                            local_585 = select(_e3492, _e3491, _e3490);
                                            local_586 = select(1u, 2u, (_e3489 > 0f));
                                            phi_5584_ = 0u;
                                            phi_5585_ = _e3302;
                                            loop {
                                                let _e3497 = phi_5584_;
                                                let _e3499 = phi_5585_;
                                                local_545 = _e3497;
                                                local_546 = _e3499;
                                                local_628 = _e3499;
                                                let _e3500 = local_545;
                                                let _e3501 = local_585;
                                                let _e3502 = (_e3500 < _e3501);
                                                local_547 = _e3502;
                                                if _e3502 {
                                                    let _e3503 = local_546;
                                                    local_548 = _e3503.member_1;
                                                    let _e3505 = local_546;
                                                    local_549 = _e3505.member_2;
                                                    let _e3508 = local_546;
                                                    let _e3511 = local_546;
                                                    local_550 = type_22((_e3508.member + (_e3503.member_1 * _e3505.member_2)), _e3511.member_1, _e3511.member_2, _e3511.member_3, _e3511.member_4);
                                                    if (_e3503.member_1 > 1u) {
                                                        let _e3519 = local_548;
                                                        phi_5602_ = (_e3519 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5602_ = 1u;
                                                    }
                                                    let _e3523 = phi_5602_;
                                                    let _e3524 = local_550;
                                                    local_551 = type_22(_e3524.member, _e3523, _e3524.member_2, _e3524.member_3, _e3524.member_4);
                                                    let _e3531 = local_549;
                                                    if (_e3531 > 1u) {
                                                        let _e3533 = local_549;
                                                        phi_5611_ = (_e3533 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5611_ = 1u;
                                                    }
                                                    let _e3537 = phi_5611_;
                                                    let _e3538 = local_551;
                                                    let _e3545 = local_545;
                                                    phi_5616_ = (_e3545 + 1u);
                                                    phi_5617_ = type_22(_e3538.member, _e3538.member_1, _e3537, _e3538.member_3, _e3538.member_4);
                                                } else {
                                                    phi_5616_ = u32();
                                                    phi_5617_ = type_22();
                                                }
                                                let _e3548 = phi_5616_;
                                                let _e3550 = phi_5617_;
                                                continue;
                                                continuing {
                                                    let _e3551 = local_547;
                                                    phi_5584_ = _e3548;
                                                    phi_5585_ = _e3550;
                                                    break if !(_e3551);
                                                }
                                            }
                                            let _e3553 = local_585;
                                            let _e3554 = local_586;
                                            local_301 = ((_e3553 + _e3554) - 1u);
                                            phi_5623_ = 0u;
                                            phi_5624_ = _e3302;
                                            loop {
                                                let _e3558 = phi_5623_;
                                                let _e3560 = phi_5624_;
                                                local_552 = _e3558;
                                                local_553 = _e3560;
                                                local_629 = _e3560;
                                                let _e3561 = local_552;
                                                let _e3562 = local_301;
                                                let _e3563 = (_e3561 < _e3562);
                                                local_554 = _e3563;
                                                if _e3563 {
                                                    let _e3564 = local_553;
                                                    local_555 = _e3564.member_1;
                                                    let _e3566 = local_553;
                                                    local_556 = _e3566.member_2;
                                                    let _e3569 = local_553;
                                                    let _e3572 = local_553;
                                                    local_557 = type_22((_e3569.member + (_e3564.member_1 * _e3566.member_2)), _e3572.member_1, _e3572.member_2, _e3572.member_3, _e3572.member_4);
                                                    if (_e3564.member_1 > 1u) {
                                                        let _e3580 = local_555;
                                                        phi_5641_ = (_e3580 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5641_ = 1u;
                                                    }
                                                    let _e3584 = phi_5641_;
                                                    let _e3585 = local_557;
                                                    local_558 = type_22(_e3585.member, _e3584, _e3585.member_2, _e3585.member_3, _e3585.member_4);
                                                    let _e3592 = local_556;
                                                    if (_e3592 > 1u) {
                                                        let _e3594 = local_556;
                                                        phi_5650_ = (_e3594 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5650_ = 1u;
                                                    }
                                                    let _e3598 = phi_5650_;
                                                    let _e3599 = local_558;
                                                    let _e3606 = local_552;
                                                    phi_5655_ = (_e3606 + 1u);
                                                    phi_5656_ = type_22(_e3599.member, _e3599.member_1, _e3598, _e3599.member_3, _e3599.member_4);
                                                } else {
                                                    phi_5655_ = u32();
                                                    phi_5656_ = type_22();
                                                }
                                                let _e3609 = phi_5655_;
                                                let _e3611 = phi_5656_;
                                                continue;
                                                continuing {
                                                    let _e3612 = local_554;
                                                    phi_5623_ = _e3609;
                                                    phi_5624_ = _e3611;
                                                    break if !(_e3612);
                                                }
                                            }
                                            let _e3614 = local_286;
                                            if _e3614 {
                                                let _e3615 = local_278;
                                                phi_2924_ = ((_e3615 & 1u) != 0u);
                                            } else {
                                                phi_2924_ = false;
                                            }
                                            let _e3619 = phi_2924_;
                                            local_302 = _e3619;
                                            phi_5869_ = _e3232;
                                            phi_2927_ = 0u;
                                            phi_2930_ = type_5(0f, 0f, 0f, 0f);
                                            loop {
                                                let _e3621 = phi_5869_;
                                                let _e3623 = phi_2927_;
                                                let _e3625 = phi_2930_;
                                                local_303 = _e3623;
                                                local_304 = _e3625;
                                                let _e3626 = local_303;
                                                let _e3627 = local_294;
                                                let _e3628 = (_e3626 < _e3627);
                                                local_305 = _e3628;
                                                if _e3628 {
                                                    let _e3629 = local_303;
                                                    let _e3632 = local_294;
                                                    local_306 = (((f32(_e3629) + 0.5f) / f32(_e3632)) - 0.5f);
                                                    phi_5868_ = _e3621;
                                                    phi_2944_ = 0u;
                                                    phi_2947_ = _e3625;
                                                    loop {
                                                        let _e3637 = phi_5868_;
                                                        let _e3639 = phi_2944_;
                                                        let _e3641 = phi_2947_;
                                                        local_307 = _e3639;
                                                        local_631 = _e3641;
                                                        let _e3642 = local_307;
                                                        let _e3643 = local_293;
                                                        let _e3644 = (_e3642 < _e3643);
                                                        local_308 = _e3644;
                                                        if _e3644 {
                                                            let _e3645 = local_307;
                                                            let _e3648 = local_293;
                                                            let _e3651 = (((f32(_e3645) + 0.5f) / f32(_e3648)) - 0.5f);
                                                            let _e3652 = local_306;
                                                            let _e3653 = local_280;
                                                            let _e3655 = local_583;
                                                            let _e3657 = local_282;
                                                            local_309 = ((_e3655 + (_e3652 * _e3653)) + (_e3651 * _e3657));
                                                            let _e3660 = local_306;
                                                            let _e3661 = local_281;
                                                            let _e3663 = local_582;
                                                            let _e3665 = local_283;
                                                            local_310 = ((_e3663 + (_e3660 * _e3661)) + (_e3651 * _e3665));
                                                            phi_2973_ = 0u;
                                                            phi_2976_ = _e3641;
                                                            loop {
                                                                let _e3669 = phi_2973_;
                                                                let _e3671 = phi_2976_;
                                                                local_311 = _e3669;
                                                                local_312 = _e3671;
                                                                local_630 = _e3671;
                                                                let _e3672 = local_311;
                                                                let _e3673 = local_586;
                                                                let _e3674 = (_e3672 < _e3673);
                                                                local_313 = _e3674;
                                                                if _e3674 {
                                                                    let _e3675 = local_311;
                                                                    if (_e3675 == 0u) {
                                                                        let _e3677 = local_300;
                                                                        let _e5625 = local_628;
                                                                        phi_2989_ = _e5625;
                                                                        phi_2990_ = (1f - _e3677);
                                                                    } else {
                                                                        let _e5627 = local_629;
                                                                        phi_2989_ = _e5627;
                                                                        phi_2990_ = _e3489;
                                                                    }
                                                                    let _e3680 = phi_2989_;
                                                                    let _e3682 = phi_2990_;
                                                                    local_314 = _e3680;
                                                                    local_315 = _e3682;
                                                                    let _e3683 = local_302;
                                                                    let _e3684 = select(0.5f, 0f, _e3683);
                                                                    local_316 = _e3680.member_1;
                                                                    let _e3687 = local_309;
                                                                    let _e3689 = ((_e3687 * f32(_e3680.member_1)) - _e3684);
                                                                    local_317 = _e3689;
                                                                    local_318 = _e3680.member_2;
                                                                    let _e3692 = local_310;
                                                                    let _e3694 = ((_e3692 * f32(_e3680.member_2)) - _e3684);
                                                                    local_319 = _e3694;
                                                                    local_320 = floor(_e3689);
                                                                    local_321 = floor(_e3694);
                                                                    let _e3697 = local_302;
                                                                    if _e3697 {
                                                                        phi_3010_ = 0f;
                                                                        phi_3011_ = 0f;
                                                                    } else {
                                                                        let _e3698 = local_317;
                                                                        let _e3699 = local_320;
                                                                        let _e3701 = local_319;
                                                                        let _e3702 = local_321;
                                                                        phi_3010_ = (_e3701 - _e3702);
                                                                        phi_3011_ = (_e3698 - _e3699);
                                                                    }
                                                                    let _e3705 = phi_3010_;
                                                                    let _e3707 = phi_3011_;
                                                                    local_322 = _e3705;
                                                                    local_323 = _e3707;
                                                                    let _e3708 = local_320;
                                                                    let _e3710 = local_320;
                                                                    let _e3712 = local_320;
                                                                    let _e3716 = local_320;
                                                                    let _e3717 = local_320;
                                                                    let _e3719 = select(0i, select(select(i32(_e3708), i32(-2147483648), (_e3710 < -2147483600f)), 2147483647i, (_e3712 > 2147483500f)), (_e3716 == _e3717));
                                                                    local_324 = _e3719;
                                                                    let _e3720 = local_321;
                                                                    let _e3722 = local_321;
                                                                    let _e3724 = local_321;
                                                                    let _e3728 = local_321;
                                                                    let _e3729 = local_321;
                                                                    let _e3731 = select(0i, select(select(i32(_e3720), i32(-2147483648), (_e3722 < -2147483600f)), 2147483647i, (_e3724 > 2147483500f)), (_e3728 == _e3729));
                                                                    local_325 = _e3731;
                                                                    let _e3732 = local_314;
                                                                    local_326 = _e3732.member_3;
                                                                    let _e3734 = local_316;
                                                                    local_327 = bitcast<i32>(_e3734);
                                                                    let _e3736 = (_e3732.member_3 == 1u);
                                                                    local_328 = _e3736;
                                                                    if _e3736 {
                                                                        let _e3790 = local_324;
                                                                        if (_e3790 < 0i) {
                                                                            phi_3047_ = 0i;
                                                                        } else {
                                                                            let _e3792 = local_324;
                                                                            let _e3793 = local_327;
                                                                            if (_e3792 >= _e3793) {
                                                                                let _e3795 = local_327;
                                                                                phi_3046_ = (_e3795 - 1i);
                                                                            } else {
                                                                                phi_3046_ = _e3719;
                                                                            }
                                                                            let _e3798 = phi_3046_;
                                                                            phi_3047_ = _e3798;
                                                                        }
                                                                        let _e3800 = phi_3047_;
                                                                        phi_3107_ = _e3800;
                                                                    } else {
                                                                        let _e3737 = local_326;
                                                                        if (_e3737 == 2u) {
                                                                            let _e3759 = local_327;
                                                                            let _e3760 = (2i * _e3759);
                                                                            local_329 = _e3760;
                                                                            let _e3761 = (_e3760 == 0i);
                                                                            local_330 = _e3761;
                                                                            if _e3761 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3762 = local_329;
                                                                            let _e3763 = (_e3762 == -1i);
                                                                            local_331 = _e3763;
                                                                            let _e3764 = local_324;
                                                                            if (_e3763 && (_e3764 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3767 = local_324;
                                                                            let _e3768 = local_329;
                                                                            let _e3770 = local_329;
                                                                            local_332 = ((_e3767 % _e3768) + _e3770);
                                                                            let _e3772 = local_330;
                                                                            if _e3772 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3773 = local_332;
                                                                            let _e3775 = local_331;
                                                                            if (_e3775 && (_e3773 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3777 = local_332;
                                                                            let _e3778 = local_329;
                                                                            let _e3779 = (_e3777 % _e3778);
                                                                            local_333 = _e3779;
                                                                            let _e3780 = local_327;
                                                                            if (_e3779 < _e3780) {
                                                                                phi_3082_ = _e3779;
                                                                            } else {
                                                                                let _e3782 = local_329;
                                                                                let _e3784 = local_333;
                                                                                phi_3082_ = ((_e3782 - 1i) - _e3784);
                                                                            }
                                                                            let _e3787 = phi_3082_;
                                                                            phi_3106_ = _e3787;
                                                                        } else {
                                                                            let _e3739 = local_327;
                                                                            let _e3740 = (_e3739 == 0i);
                                                                            local_334 = _e3740;
                                                                            if _e3740 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3741 = local_327;
                                                                            let _e3742 = (_e3741 == -1i);
                                                                            local_335 = _e3742;
                                                                            let _e3743 = local_324;
                                                                            if (_e3742 && (_e3743 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3746 = local_324;
                                                                            let _e3747 = local_327;
                                                                            let _e3749 = local_327;
                                                                            local_336 = ((_e3746 % _e3747) + _e3749);
                                                                            let _e3751 = local_334;
                                                                            if _e3751 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3752 = local_336;
                                                                            let _e3754 = local_335;
                                                                            if (_e3754 && (_e3752 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3756 = local_336;
                                                                            let _e3757 = local_327;
                                                                            phi_3106_ = (_e3756 % _e3757);
                                                                        }
                                                                        let _e3789 = phi_3106_;
                                                                        phi_3107_ = _e3789;
                                                                    }
                                                                    let _e3802 = phi_3107_;
                                                                    local_337 = bitcast<u32>(_e3802);
                                                                    let _e3804 = local_324;
                                                                    let _e3805 = (_e3804 + 1i);
                                                                    local_338 = _e3805;
                                                                    let _e3806 = local_328;
                                                                    if _e3806 {
                                                                        let _e3860 = local_338;
                                                                        if (_e3860 < 0i) {
                                                                            phi_3127_ = 0i;
                                                                        } else {
                                                                            let _e3862 = local_338;
                                                                            let _e3863 = local_327;
                                                                            if (_e3862 >= _e3863) {
                                                                                let _e3865 = local_327;
                                                                                phi_3126_ = (_e3865 - 1i);
                                                                            } else {
                                                                                phi_3126_ = _e3805;
                                                                            }
                                                                            let _e3868 = phi_3126_;
                                                                            phi_3127_ = _e3868;
                                                                        }
                                                                        let _e3870 = phi_3127_;
                                                                        phi_3187_ = _e3870;
                                                                    } else {
                                                                        let _e3807 = local_326;
                                                                        if (_e3807 == 2u) {
                                                                            let _e3829 = local_327;
                                                                            let _e3830 = (2i * _e3829);
                                                                            local_339 = _e3830;
                                                                            let _e3831 = (_e3830 == 0i);
                                                                            local_340 = _e3831;
                                                                            if _e3831 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3832 = local_339;
                                                                            let _e3833 = (_e3832 == -1i);
                                                                            local_341 = _e3833;
                                                                            let _e3834 = local_338;
                                                                            if (_e3833 && (_e3834 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3837 = local_338;
                                                                            let _e3838 = local_339;
                                                                            let _e3840 = local_339;
                                                                            local_342 = ((_e3837 % _e3838) + _e3840);
                                                                            let _e3842 = local_340;
                                                                            if _e3842 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3843 = local_342;
                                                                            let _e3845 = local_341;
                                                                            if (_e3845 && (_e3843 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3847 = local_342;
                                                                            let _e3848 = local_339;
                                                                            let _e3849 = (_e3847 % _e3848);
                                                                            local_343 = _e3849;
                                                                            let _e3850 = local_327;
                                                                            if (_e3849 < _e3850) {
                                                                                phi_3162_ = _e3849;
                                                                            } else {
                                                                                let _e3852 = local_339;
                                                                                let _e3854 = local_343;
                                                                                phi_3162_ = ((_e3852 - 1i) - _e3854);
                                                                            }
                                                                            let _e3857 = phi_3162_;
                                                                            phi_3186_ = _e3857;
                                                                        } else {
                                                                            let _e3809 = local_327;
                                                                            let _e3810 = (_e3809 == 0i);
                                                                            local_344 = _e3810;
                                                                            if _e3810 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3811 = local_327;
                                                                            let _e3812 = (_e3811 == -1i);
                                                                            local_345 = _e3812;
                                                                            let _e3813 = local_338;
                                                                            if (_e3812 && (_e3813 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3816 = local_338;
                                                                            let _e3817 = local_327;
                                                                            let _e3819 = local_327;
                                                                            local_346 = ((_e3816 % _e3817) + _e3819);
                                                                            let _e3821 = local_344;
                                                                            if _e3821 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3822 = local_346;
                                                                            let _e3824 = local_345;
                                                                            if (_e3824 && (_e3822 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3826 = local_346;
                                                                            let _e3827 = local_327;
                                                                            phi_3186_ = (_e3826 % _e3827);
                                                                        }
                                                                        let _e3859 = phi_3186_;
                                                                        phi_3187_ = _e3859;
                                                                    }
                                                                    let _e3872 = phi_3187_;
                                                                    local_347 = bitcast<u32>(_e3872);
                                                                    let _e3874 = local_314;
                                                                    local_348 = _e3874.member_4;
                                                                    let _e3876 = local_318;
                                                                    local_349 = bitcast<i32>(_e3876);
                                                                    let _e3878 = (_e3874.member_4 == 1u);
                                                                    local_350 = _e3878;
                                                                    if _e3878 {
                                                                        let _e3932 = local_325;
                                                                        if (_e3932 < 0i) {
                                                                            phi_3206_ = 0i;
                                                                        } else {
                                                                            let _e3934 = local_325;
                                                                            let _e3935 = local_349;
                                                                            if (_e3934 >= _e3935) {
                                                                                let _e3937 = local_349;
                                                                                phi_3205_ = (_e3937 - 1i);
                                                                            } else {
                                                                                phi_3205_ = _e3731;
                                                                            }
                                                                            let _e3940 = phi_3205_;
                                                                            phi_3206_ = _e3940;
                                                                        }
                                                                        let _e3942 = phi_3206_;
                                                                        phi_3266_ = _e3942;
                                                                    } else {
                                                                        let _e3879 = local_348;
                                                                        if (_e3879 == 2u) {
                                                                            let _e3901 = local_349;
                                                                            let _e3902 = (2i * _e3901);
                                                                            local_351 = _e3902;
                                                                            let _e3903 = (_e3902 == 0i);
                                                                            local_352 = _e3903;
                                                                            if _e3903 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3904 = local_351;
                                                                            let _e3905 = (_e3904 == -1i);
                                                                            local_353 = _e3905;
                                                                            let _e3906 = local_325;
                                                                            if (_e3905 && (_e3906 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3909 = local_325;
                                                                            let _e3910 = local_351;
                                                                            let _e3912 = local_351;
                                                                            local_354 = ((_e3909 % _e3910) + _e3912);
                                                                            let _e3914 = local_352;
                                                                            if _e3914 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3915 = local_354;
                                                                            let _e3917 = local_353;
                                                                            if (_e3917 && (_e3915 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3919 = local_354;
                                                                            let _e3920 = local_351;
                                                                            let _e3921 = (_e3919 % _e3920);
                                                                            local_355 = _e3921;
                                                                            let _e3922 = local_349;
                                                                            if (_e3921 < _e3922) {
                                                                                phi_3241_ = _e3921;
                                                                            } else {
                                                                                let _e3924 = local_351;
                                                                                let _e3926 = local_355;
                                                                                phi_3241_ = ((_e3924 - 1i) - _e3926);
                                                                            }
                                                                            let _e3929 = phi_3241_;
                                                                            phi_3265_ = _e3929;
                                                                        } else {
                                                                            let _e3881 = local_349;
                                                                            let _e3882 = (_e3881 == 0i);
                                                                            local_356 = _e3882;
                                                                            if _e3882 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3883 = local_349;
                                                                            let _e3884 = (_e3883 == -1i);
                                                                            local_357 = _e3884;
                                                                            let _e3885 = local_325;
                                                                            if (_e3884 && (_e3885 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3888 = local_325;
                                                                            let _e3889 = local_349;
                                                                            let _e3891 = local_349;
                                                                            local_358 = ((_e3888 % _e3889) + _e3891);
                                                                            let _e3893 = local_356;
                                                                            if _e3893 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3894 = local_358;
                                                                            let _e3896 = local_357;
                                                                            if (_e3896 && (_e3894 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3898 = local_358;
                                                                            let _e3899 = local_349;
                                                                            phi_3265_ = (_e3898 % _e3899);
                                                                        }
                                                                        let _e3931 = phi_3265_;
                                                                        phi_3266_ = _e3931;
                                                                    }
                                                                    let _e3944 = phi_3266_;
                                                                    local_359 = bitcast<u32>(_e3944);
                                                                    let _e3946 = local_325;
                                                                    let _e3947 = (_e3946 + 1i);
                                                                    local_360 = _e3947;
                                                                    let _e3948 = local_350;
                                                                    if _e3948 {
                                                                        let _e4002 = local_360;
                                                                        if (_e4002 < 0i) {
                                                                            phi_3286_ = 0i;
                                                                        } else {
                                                                            let _e4004 = local_360;
                                                                            let _e4005 = local_349;
                                                                            if (_e4004 >= _e4005) {
                                                                                let _e4007 = local_349;
                                                                                phi_3285_ = (_e4007 - 1i);
                                                                            } else {
                                                                                phi_3285_ = _e3947;
                                                                            }
                                                                            let _e4010 = phi_3285_;
                                                                            phi_3286_ = _e4010;
                                                                        }
                                                                        let _e4012 = phi_3286_;
                                                                        phi_3346_ = _e4012;
                                                                    } else {
                                                                        let _e3949 = local_348;
                                                                        if (_e3949 == 2u) {
                                                                            let _e3971 = local_349;
                                                                            let _e3972 = (2i * _e3971);
                                                                            local_361 = _e3972;
                                                                            let _e3973 = (_e3972 == 0i);
                                                                            local_362 = _e3973;
                                                                            if _e3973 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3974 = local_361;
                                                                            let _e3975 = (_e3974 == -1i);
                                                                            local_363 = _e3975;
                                                                            let _e3976 = local_360;
                                                                            if (_e3975 && (_e3976 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3979 = local_360;
                                                                            let _e3980 = local_361;
                                                                            let _e3982 = local_361;
                                                                            local_364 = ((_e3979 % _e3980) + _e3982);
                                                                            let _e3984 = local_362;
                                                                            if _e3984 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3985 = local_364;
                                                                            let _e3987 = local_363;
                                                                            if (_e3987 && (_e3985 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3989 = local_364;
                                                                            let _e3990 = local_361;
                                                                            let _e3991 = (_e3989 % _e3990);
                                                                            local_365 = _e3991;
                                                                            let _e3992 = local_349;
                                                                            if (_e3991 < _e3992) {
                                                                                phi_3321_ = _e3991;
                                                                            } else {
                                                                                let _e3994 = local_361;
                                                                                let _e3996 = local_365;
                                                                                phi_3321_ = ((_e3994 - 1i) - _e3996);
                                                                            }
                                                                            let _e3999 = phi_3321_;
                                                                            phi_3345_ = _e3999;
                                                                        } else {
                                                                            let _e3951 = local_349;
                                                                            let _e3952 = (_e3951 == 0i);
                                                                            local_366 = _e3952;
                                                                            if _e3952 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3953 = local_349;
                                                                            let _e3954 = (_e3953 == -1i);
                                                                            local_367 = _e3954;
                                                                            let _e3955 = local_360;
                                                                            if (_e3954 && (_e3955 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3958 = local_360;
                                                                            let _e3959 = local_349;
                                                                            let _e3961 = local_349;
                                                                            local_368 = ((_e3958 % _e3959) + _e3961);
                                                                            let _e3963 = local_366;
                                                                            if _e3963 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3964 = local_368;
                                                                            let _e3966 = local_367;
                                                                            if (_e3966 && (_e3964 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3968 = local_368;
                                                                            let _e3969 = local_349;
                                                                            phi_3345_ = (_e3968 % _e3969);
                                                                        }
                                                                        let _e4001 = phi_3345_;
                                                                        phi_3346_ = _e4001;
                                                                    }
                                                                    let _e4014 = phi_3346_;
                                                                    local_369 = bitcast<u32>(_e4014);
                                                                    let _e4016 = local_314;
                                                                    local_370 = _e4016.member;
                                                                    let _e4018 = local_359;
                                                                    let _e4019 = local_316;
                                                                    let _e4021 = (_e4016.member + (_e4018 * _e4019));
                                                                    local_371 = _e4021;
                                                                    let _e4022 = local_337;
                                                                    let _e4024 = ((_e4021 + _e4022) * 2u);
                                                                    local_372 = _e4024;
                                                                    let _e4025 = local_6;
                                                                    if (_e4024 < _e4025) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4027 = local_372;
                                                                    let _e4030 = global_9.member[_e4027];
                                                                    local_373 = _e4030;
                                                                    let _e4031 = local_372;
                                                                    let _e4032 = (_e4031 + 1u);
                                                                    local_374 = _e4032;
                                                                    let _e4033 = local_6;
                                                                    if (_e4032 < _e4033) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4035 = local_374;
                                                                    let _e4038 = global_9.member[_e4035];
                                                                    local_375 = _e4038;
                                                                    let _e4039 = local_373;
                                                                    let _e4040 = (_e4039 & 65535u);
                                                                    local_587 = select(-1f, 1f, ((_e4040 & 32768u) == 0u));
                                                                    let _e4046 = ((_e4040 >> bitcast<u32>(10i)) & 31u);
                                                                    local_376 = _e4046;
                                                                    local_377 = (_e4040 & 1023u);
                                                                    if (_e4046 == 0u) {
                                                                        let _e4068 = local_377;
                                                                        let _e4070 = local_587;
                                                                        phi_3416_ = ((_e4070 * f32(_e4068)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4049 = local_376;
                                                                        if (_e4049 == 31u) {
                                                                            let _e4059 = local_377;
                                                                            phi_3413_ = (2139095040u | (_e4059 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4051 = local_376;
                                                                            let _e4055 = local_377;
                                                                            phi_3413_ = (((_e4051 + 112u) << bitcast<u32>(23i)) | (_e4055 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4064 = phi_3413_;
                                                                        let _e4066 = local_587;
                                                                        phi_3416_ = (_e4066 * bitcast<f32>(_e4064));
                                                                    }
                                                                    let _e4074 = phi_3416_;
                                                                    local_378 = _e4074;
                                                                    let _e4075 = local_373;
                                                                    let _e4077 = (_e4075 >> bitcast<u32>(16i));
                                                                    local_588 = select(-1f, 1f, ((_e4077 & 32768u) == 0u));
                                                                    let _e4083 = ((_e4077 >> bitcast<u32>(10i)) & 31u);
                                                                    local_379 = _e4083;
                                                                    local_380 = (_e4077 & 1023u);
                                                                    if (_e4083 == 0u) {
                                                                        let _e4105 = local_380;
                                                                        let _e4107 = local_588;
                                                                        phi_3448_ = ((_e4107 * f32(_e4105)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4086 = local_379;
                                                                        if (_e4086 == 31u) {
                                                                            let _e4096 = local_380;
                                                                            phi_3445_ = (2139095040u | (_e4096 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4088 = local_379;
                                                                            let _e4092 = local_380;
                                                                            phi_3445_ = (((_e4088 + 112u) << bitcast<u32>(23i)) | (_e4092 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4101 = phi_3445_;
                                                                        let _e4103 = local_588;
                                                                        phi_3448_ = (_e4103 * bitcast<f32>(_e4101));
                                                                    }
                                                                    let _e4111 = phi_3448_;
                                                                    local_381 = _e4111;
                                                                    let _e4112 = local_375;
                                                                    let _e4113 = (_e4112 & 65535u);
                                                                    local_589 = select(-1f, 1f, ((_e4113 & 32768u) == 0u));
                                                                    let _e4119 = ((_e4113 >> bitcast<u32>(10i)) & 31u);
                                                                    local_382 = _e4119;
                                                                    local_383 = (_e4113 & 1023u);
                                                                    if (_e4119 == 0u) {
                                                                        let _e4141 = local_383;
                                                                        let _e4143 = local_589;
                                                                        phi_3480_ = ((_e4143 * f32(_e4141)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4122 = local_382;
                                                                        if (_e4122 == 31u) {
                                                                            let _e4132 = local_383;
                                                                            phi_3477_ = (2139095040u | (_e4132 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4124 = local_382;
                                                                            let _e4128 = local_383;
                                                                            phi_3477_ = (((_e4124 + 112u) << bitcast<u32>(23i)) | (_e4128 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4137 = phi_3477_;
                                                                        let _e4139 = local_589;
                                                                        phi_3480_ = (_e4139 * bitcast<f32>(_e4137));
                                                                    }
                                                                    let _e4147 = phi_3480_;
                                                                    local_384 = _e4147;
                                                                    let _e4148 = local_375;
                                                                    let _e4150 = (_e4148 >> bitcast<u32>(16i));
                                                                    local_590 = select(-1f, 1f, ((_e4150 & 32768u) == 0u));
                                                                    let _e4156 = ((_e4150 >> bitcast<u32>(10i)) & 31u);
                                                                    local_385 = _e4156;
                                                                    local_386 = (_e4150 & 1023u);
                                                                    if (_e4156 == 0u) {
                                                                        let _e4178 = local_386;
                                                                        let _e4180 = local_590;
                                                                        phi_3512_ = ((_e4180 * f32(_e4178)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4159 = local_385;
                                                                        if (_e4159 == 31u) {
                                                                            let _e4169 = local_386;
                                                                            phi_3509_ = (2139095040u | (_e4169 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4161 = local_385;
                                                                            let _e4165 = local_386;
                                                                            phi_3509_ = (((_e4161 + 112u) << bitcast<u32>(23i)) | (_e4165 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4174 = phi_3509_;
                                                                        let _e4176 = local_590;
                                                                        phi_3512_ = (_e4176 * bitcast<f32>(_e4174));
                                                                    }
                                                                    let _e4184 = phi_3512_;
                                                                    local_387 = _e4184;
                                                                    let _e4185 = local_371;
                                                                    let _e4186 = local_347;
                                                                    let _e4188 = ((_e4185 + _e4186) * 2u);
                                                                    local_388 = _e4188;
                                                                    let _e4189 = local_6;
                                                                    if (_e4188 < _e4189) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4191 = local_388;
                                                                    let _e4194 = global_9.member[_e4191];
                                                                    local_389 = _e4194;
                                                                    let _e4195 = local_388;
                                                                    let _e4196 = (_e4195 + 1u);
                                                                    local_390 = _e4196;
                                                                    let _e4197 = local_6;
                                                                    if (_e4196 < _e4197) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4199 = local_390;
                                                                    let _e4202 = global_9.member[_e4199];
                                                                    local_391 = _e4202;
                                                                    let _e4203 = local_389;
                                                                    let _e4204 = (_e4203 & 65535u);
                                                                    local_591 = select(-1f, 1f, ((_e4204 & 32768u) == 0u));
                                                                    let _e4210 = ((_e4204 >> bitcast<u32>(10i)) & 31u);
                                                                    local_392 = _e4210;
                                                                    local_393 = (_e4204 & 1023u);
                                                                    if (_e4210 == 0u) {
                                                                        let _e4232 = local_393;
                                                                        let _e4234 = local_591;
                                                                        phi_3581_ = ((_e4234 * f32(_e4232)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4213 = local_392;
                                                                        if (_e4213 == 31u) {
                                                                            let _e4223 = local_393;
                                                                            phi_3578_ = (2139095040u | (_e4223 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4215 = local_392;
                                                                            let _e4219 = local_393;
                                                                            phi_3578_ = (((_e4215 + 112u) << bitcast<u32>(23i)) | (_e4219 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4228 = phi_3578_;
                                                                        let _e4230 = local_591;
                                                                        phi_3581_ = (_e4230 * bitcast<f32>(_e4228));
                                                                    }
                                                                    let _e4238 = phi_3581_;
                                                                    local_394 = _e4238;
                                                                    let _e4239 = local_389;
                                                                    let _e4241 = (_e4239 >> bitcast<u32>(16i));
                                                                    local_592 = select(-1f, 1f, ((_e4241 & 32768u) == 0u));
                                                                    let _e4247 = ((_e4241 >> bitcast<u32>(10i)) & 31u);
                                                                    local_395 = _e4247;
                                                                    local_396 = (_e4241 & 1023u);
                                                                    if (_e4247 == 0u) {
                                                                        let _e4269 = local_396;
                                                                        let _e4271 = local_592;
                                                                        phi_3613_ = ((_e4271 * f32(_e4269)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4250 = local_395;
                                                                        if (_e4250 == 31u) {
                                                                            let _e4260 = local_396;
                                                                            phi_3610_ = (2139095040u | (_e4260 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4252 = local_395;
                                                                            let _e4256 = local_396;
                                                                            phi_3610_ = (((_e4252 + 112u) << bitcast<u32>(23i)) | (_e4256 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4265 = phi_3610_;
                                                                        let _e4267 = local_592;
                                                                        phi_3613_ = (_e4267 * bitcast<f32>(_e4265));
                                                                    }
                                                                    let _e4275 = phi_3613_;
                                                                    local_397 = _e4275;
                                                                    let _e4276 = local_391;
                                                                    let _e4277 = (_e4276 & 65535u);
                                                                    local_593 = select(-1f, 1f, ((_e4277 & 32768u) == 0u));
                                                                    let _e4283 = ((_e4277 >> bitcast<u32>(10i)) & 31u);
                                                                    local_398 = _e4283;
                                                                    local_399 = (_e4277 & 1023u);
                                                                    if (_e4283 == 0u) {
                                                                        let _e4305 = local_399;
                                                                        let _e4307 = local_593;
                                                                        phi_3645_ = ((_e4307 * f32(_e4305)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4286 = local_398;
                                                                        if (_e4286 == 31u) {
                                                                            let _e4296 = local_399;
                                                                            phi_3642_ = (2139095040u | (_e4296 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4288 = local_398;
                                                                            let _e4292 = local_399;
                                                                            phi_3642_ = (((_e4288 + 112u) << bitcast<u32>(23i)) | (_e4292 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4301 = phi_3642_;
                                                                        let _e4303 = local_593;
                                                                        phi_3645_ = (_e4303 * bitcast<f32>(_e4301));
                                                                    }
                                                                    let _e4311 = phi_3645_;
                                                                    local_400 = _e4311;
                                                                    let _e4312 = local_391;
                                                                    let _e4314 = (_e4312 >> bitcast<u32>(16i));
                                                                    local_594 = select(-1f, 1f, ((_e4314 & 32768u) == 0u));
                                                                    let _e4320 = ((_e4314 >> bitcast<u32>(10i)) & 31u);
                                                                    local_401 = _e4320;
                                                                    local_402 = (_e4314 & 1023u);
                                                                    if (_e4320 == 0u) {
                                                                        let _e4342 = local_402;
                                                                        let _e4344 = local_594;
                                                                        phi_3677_ = ((_e4344 * f32(_e4342)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4323 = local_401;
                                                                        if (_e4323 == 31u) {
                                                                            let _e4333 = local_402;
                                                                            phi_3674_ = (2139095040u | (_e4333 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4325 = local_401;
                                                                            let _e4329 = local_402;
                                                                            phi_3674_ = (((_e4325 + 112u) << bitcast<u32>(23i)) | (_e4329 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4338 = phi_3674_;
                                                                        let _e4340 = local_594;
                                                                        phi_3677_ = (_e4340 * bitcast<f32>(_e4338));
                                                                    }
                                                                    let _e4348 = phi_3677_;
                                                                    let _e4349 = local_394;
                                                                    let _e4350 = local_378;
                                                                    let _e4352 = local_323;
                                                                    let _e4354 = local_378;
                                                                    local_403 = (_e4354 + ((_e4349 - _e4350) * _e4352));
                                                                    let _e4356 = local_397;
                                                                    let _e4357 = local_381;
                                                                    let _e4359 = local_323;
                                                                    let _e4361 = local_381;
                                                                    local_404 = (_e4361 + ((_e4356 - _e4357) * _e4359));
                                                                    let _e4363 = local_400;
                                                                    let _e4364 = local_384;
                                                                    let _e4366 = local_323;
                                                                    let _e4368 = local_384;
                                                                    local_405 = (_e4368 + ((_e4363 - _e4364) * _e4366));
                                                                    let _e4370 = local_387;
                                                                    let _e4372 = local_323;
                                                                    let _e4374 = local_387;
                                                                    local_406 = (_e4374 + ((_e4348 - _e4370) * _e4372));
                                                                    let _e4376 = local_369;
                                                                    let _e4377 = local_316;
                                                                    let _e4379 = local_370;
                                                                    let _e4380 = (_e4379 + (_e4376 * _e4377));
                                                                    local_407 = _e4380;
                                                                    let _e4381 = local_337;
                                                                    let _e4383 = ((_e4380 + _e4381) * 2u);
                                                                    local_408 = _e4383;
                                                                    let _e4384 = local_6;
                                                                    if (_e4383 < _e4384) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4386 = local_408;
                                                                    let _e4389 = global_9.member[_e4386];
                                                                    local_409 = _e4389;
                                                                    let _e4390 = local_408;
                                                                    let _e4391 = (_e4390 + 1u);
                                                                    local_410 = _e4391;
                                                                    let _e4392 = local_6;
                                                                    if (_e4391 < _e4392) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4394 = local_410;
                                                                    let _e4397 = global_9.member[_e4394];
                                                                    local_411 = _e4397;
                                                                    let _e4398 = local_409;
                                                                    let _e4399 = (_e4398 & 65535u);
                                                                    local_595 = select(-1f, 1f, ((_e4399 & 32768u) == 0u));
                                                                    let _e4405 = ((_e4399 >> bitcast<u32>(10i)) & 31u);
                                                                    local_412 = _e4405;
                                                                    local_413 = (_e4399 & 1023u);
                                                                    if (_e4405 == 0u) {
                                                                        let _e4427 = local_413;
                                                                        let _e4429 = local_595;
                                                                        phi_3758_ = ((_e4429 * f32(_e4427)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4408 = local_412;
                                                                        if (_e4408 == 31u) {
                                                                            let _e4418 = local_413;
                                                                            phi_3755_ = (2139095040u | (_e4418 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4410 = local_412;
                                                                            let _e4414 = local_413;
                                                                            phi_3755_ = (((_e4410 + 112u) << bitcast<u32>(23i)) | (_e4414 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4423 = phi_3755_;
                                                                        let _e4425 = local_595;
                                                                        phi_3758_ = (_e4425 * bitcast<f32>(_e4423));
                                                                    }
                                                                    let _e4433 = phi_3758_;
                                                                    local_414 = _e4433;
                                                                    let _e4434 = local_409;
                                                                    let _e4436 = (_e4434 >> bitcast<u32>(16i));
                                                                    local_596 = select(-1f, 1f, ((_e4436 & 32768u) == 0u));
                                                                    let _e4442 = ((_e4436 >> bitcast<u32>(10i)) & 31u);
                                                                    local_415 = _e4442;
                                                                    local_416 = (_e4436 & 1023u);
                                                                    if (_e4442 == 0u) {
                                                                        let _e4464 = local_416;
                                                                        let _e4466 = local_596;
                                                                        phi_3790_ = ((_e4466 * f32(_e4464)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4445 = local_415;
                                                                        if (_e4445 == 31u) {
                                                                            let _e4455 = local_416;
                                                                            phi_3787_ = (2139095040u | (_e4455 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4447 = local_415;
                                                                            let _e4451 = local_416;
                                                                            phi_3787_ = (((_e4447 + 112u) << bitcast<u32>(23i)) | (_e4451 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4460 = phi_3787_;
                                                                        let _e4462 = local_596;
                                                                        phi_3790_ = (_e4462 * bitcast<f32>(_e4460));
                                                                    }
                                                                    let _e4470 = phi_3790_;
                                                                    local_417 = _e4470;
                                                                    let _e4471 = local_411;
                                                                    let _e4472 = (_e4471 & 65535u);
                                                                    local_597 = select(-1f, 1f, ((_e4472 & 32768u) == 0u));
                                                                    let _e4478 = ((_e4472 >> bitcast<u32>(10i)) & 31u);
                                                                    local_418 = _e4478;
                                                                    local_419 = (_e4472 & 1023u);
                                                                    if (_e4478 == 0u) {
                                                                        let _e4500 = local_419;
                                                                        let _e4502 = local_597;
                                                                        phi_3822_ = ((_e4502 * f32(_e4500)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4481 = local_418;
                                                                        if (_e4481 == 31u) {
                                                                            let _e4491 = local_419;
                                                                            phi_3819_ = (2139095040u | (_e4491 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4483 = local_418;
                                                                            let _e4487 = local_419;
                                                                            phi_3819_ = (((_e4483 + 112u) << bitcast<u32>(23i)) | (_e4487 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4496 = phi_3819_;
                                                                        let _e4498 = local_597;
                                                                        phi_3822_ = (_e4498 * bitcast<f32>(_e4496));
                                                                    }
                                                                    let _e4506 = phi_3822_;
                                                                    local_420 = _e4506;
                                                                    let _e4507 = local_411;
                                                                    let _e4509 = (_e4507 >> bitcast<u32>(16i));
                                                                    local_598 = select(-1f, 1f, ((_e4509 & 32768u) == 0u));
                                                                    let _e4515 = ((_e4509 >> bitcast<u32>(10i)) & 31u);
                                                                    local_421 = _e4515;
                                                                    local_422 = (_e4509 & 1023u);
                                                                    if (_e4515 == 0u) {
                                                                        let _e4537 = local_422;
                                                                        let _e4539 = local_598;
                                                                        phi_3854_ = ((_e4539 * f32(_e4537)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4518 = local_421;
                                                                        if (_e4518 == 31u) {
                                                                            let _e4528 = local_422;
                                                                            phi_3851_ = (2139095040u | (_e4528 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4520 = local_421;
                                                                            let _e4524 = local_422;
                                                                            phi_3851_ = (((_e4520 + 112u) << bitcast<u32>(23i)) | (_e4524 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4533 = phi_3851_;
                                                                        let _e4535 = local_598;
                                                                        phi_3854_ = (_e4535 * bitcast<f32>(_e4533));
                                                                    }
                                                                    let _e4543 = phi_3854_;
                                                                    local_423 = _e4543;
                                                                    let _e4544 = local_407;
                                                                    let _e4545 = local_347;
                                                                    let _e4547 = ((_e4544 + _e4545) * 2u);
                                                                    local_424 = _e4547;
                                                                    let _e4548 = local_6;
                                                                    if (_e4547 < _e4548) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4550 = local_424;
                                                                    let _e4553 = global_9.member[_e4550];
                                                                    local_425 = _e4553;
                                                                    let _e4554 = local_424;
                                                                    let _e4555 = (_e4554 + 1u);
                                                                    local_426 = _e4555;
                                                                    let _e4556 = local_6;
                                                                    if (_e4555 < _e4556) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4558 = local_426;
                                                                    let _e4561 = global_9.member[_e4558];
                                                                    local_427 = _e4561;
                                                                    let _e4562 = local_425;
                                                                    let _e4563 = (_e4562 & 65535u);
                                                                    local_599 = select(-1f, 1f, ((_e4563 & 32768u) == 0u));
                                                                    let _e4569 = ((_e4563 >> bitcast<u32>(10i)) & 31u);
                                                                    local_428 = _e4569;
                                                                    local_429 = (_e4563 & 1023u);
                                                                    if (_e4569 == 0u) {
                                                                        let _e4591 = local_429;
                                                                        let _e4593 = local_599;
                                                                        phi_3923_ = ((_e4593 * f32(_e4591)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4572 = local_428;
                                                                        if (_e4572 == 31u) {
                                                                            let _e4582 = local_429;
                                                                            phi_3920_ = (2139095040u | (_e4582 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4574 = local_428;
                                                                            let _e4578 = local_429;
                                                                            phi_3920_ = (((_e4574 + 112u) << bitcast<u32>(23i)) | (_e4578 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4587 = phi_3920_;
                                                                        let _e4589 = local_599;
                                                                        phi_3923_ = (_e4589 * bitcast<f32>(_e4587));
                                                                    }
                                                                    let _e4597 = phi_3923_;
                                                                    local_430 = _e4597;
                                                                    let _e4598 = local_425;
                                                                    let _e4600 = (_e4598 >> bitcast<u32>(16i));
                                                                    local_600 = select(-1f, 1f, ((_e4600 & 32768u) == 0u));
                                                                    let _e4606 = ((_e4600 >> bitcast<u32>(10i)) & 31u);
                                                                    local_431 = _e4606;
                                                                    local_432 = (_e4600 & 1023u);
                                                                    if (_e4606 == 0u) {
                                                                        let _e4628 = local_432;
                                                                        let _e4630 = local_600;
                                                                        phi_3955_ = ((_e4630 * f32(_e4628)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4609 = local_431;
                                                                        if (_e4609 == 31u) {
                                                                            let _e4619 = local_432;
                                                                            phi_3952_ = (2139095040u | (_e4619 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4611 = local_431;
                                                                            let _e4615 = local_432;
                                                                            phi_3952_ = (((_e4611 + 112u) << bitcast<u32>(23i)) | (_e4615 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4624 = phi_3952_;
                                                                        let _e4626 = local_600;
                                                                        phi_3955_ = (_e4626 * bitcast<f32>(_e4624));
                                                                    }
                                                                    let _e4634 = phi_3955_;
                                                                    local_433 = _e4634;
                                                                    let _e4635 = local_427;
                                                                    let _e4636 = (_e4635 & 65535u);
                                                                    local_601 = select(-1f, 1f, ((_e4636 & 32768u) == 0u));
                                                                    let _e4642 = ((_e4636 >> bitcast<u32>(10i)) & 31u);
                                                                    local_434 = _e4642;
                                                                    local_435 = (_e4636 & 1023u);
                                                                    if (_e4642 == 0u) {
                                                                        let _e4664 = local_435;
                                                                        let _e4666 = local_601;
                                                                        phi_3987_ = ((_e4666 * f32(_e4664)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4645 = local_434;
                                                                        if (_e4645 == 31u) {
                                                                            let _e4655 = local_435;
                                                                            phi_3984_ = (2139095040u | (_e4655 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4647 = local_434;
                                                                            let _e4651 = local_435;
                                                                            phi_3984_ = (((_e4647 + 112u) << bitcast<u32>(23i)) | (_e4651 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4660 = phi_3984_;
                                                                        let _e4662 = local_601;
                                                                        phi_3987_ = (_e4662 * bitcast<f32>(_e4660));
                                                                    }
                                                                    let _e4670 = phi_3987_;
                                                                    local_436 = _e4670;
                                                                    let _e4671 = local_427;
                                                                    let _e4673 = (_e4671 >> bitcast<u32>(16i));
                                                                    local_602 = select(-1f, 1f, ((_e4673 & 32768u) == 0u));
                                                                    let _e4679 = ((_e4673 >> bitcast<u32>(10i)) & 31u);
                                                                    local_437 = _e4679;
                                                                    local_438 = (_e4673 & 1023u);
                                                                    if (_e4679 == 0u) {
                                                                        let _e4701 = local_438;
                                                                        let _e4703 = local_602;
                                                                        phi_4019_ = ((_e4703 * f32(_e4701)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4682 = local_437;
                                                                        if (_e4682 == 31u) {
                                                                            let _e4692 = local_438;
                                                                            phi_4016_ = (2139095040u | (_e4692 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4684 = local_437;
                                                                            let _e4688 = local_438;
                                                                            phi_4016_ = (((_e4684 + 112u) << bitcast<u32>(23i)) | (_e4688 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4697 = phi_4016_;
                                                                        let _e4699 = local_602;
                                                                        phi_4019_ = (_e4699 * bitcast<f32>(_e4697));
                                                                    }
                                                                    let _e4707 = phi_4019_;
                                                                    let _e4708 = local_430;
                                                                    let _e4709 = local_414;
                                                                    let _e4711 = local_323;
                                                                    let _e4713 = local_414;
                                                                    let _e4715 = local_433;
                                                                    let _e4716 = local_417;
                                                                    let _e4718 = local_323;
                                                                    let _e4720 = local_417;
                                                                    let _e4722 = local_436;
                                                                    let _e4723 = local_420;
                                                                    let _e4725 = local_323;
                                                                    let _e4727 = local_420;
                                                                    let _e4729 = local_423;
                                                                    let _e4731 = local_323;
                                                                    let _e4733 = local_423;
                                                                    let _e4735 = local_403;
                                                                    let _e4737 = local_322;
                                                                    let _e4739 = local_403;
                                                                    let _e4741 = local_404;
                                                                    let _e4743 = local_322;
                                                                    let _e4745 = local_404;
                                                                    let _e4747 = local_405;
                                                                    let _e4749 = local_322;
                                                                    let _e4751 = local_405;
                                                                    let _e4753 = local_406;
                                                                    let _e4755 = local_322;
                                                                    let _e4757 = local_406;
                                                                    let _e4759 = local_315;
                                                                    let _e4761 = local_315;
                                                                    let _e4763 = local_315;
                                                                    let _e4765 = local_315;
                                                                    let _e4767 = local_312;
                                                                    let _e4770 = local_312;
                                                                    let _e4773 = local_312;
                                                                    let _e4776 = local_312;
                                                                    let _e4780 = local_311;
                                                                    phi_2974_ = (_e4780 + 1u);
                                                                    phi_2977_ = type_5((_e4767.member + ((_e4739 + (((_e4713 + ((_e4708 - _e4709) * _e4711)) - _e4735) * _e4737)) * _e4759)), (_e4770.member_1 + ((_e4745 + (((_e4720 + ((_e4715 - _e4716) * _e4718)) - _e4741) * _e4743)) * _e4761)), (_e4773.member_2 + ((_e4751 + (((_e4727 + ((_e4722 - _e4723) * _e4725)) - _e4747) * _e4749)) * _e4763)), (_e4776.member_3 + ((_e4757 + (((_e4733 + ((_e4707 - _e4729) * _e4731)) - _e4753) * _e4755)) * _e4765)));
                                                                } else {
                                                                    phi_2974_ = u32();
                                                                    phi_2977_ = type_5();
                                                                }
                                                                let _e4783 = phi_2974_;
                                                                let _e4785 = phi_2977_;
                                                                continue;
                                                                continuing {
                                                                    let _e4786 = local_313;
                                                                    phi_2973_ = _e4783;
                                                                    phi_2976_ = _e4785;
                                                                    phi_5822_ = _e3637;
                                                                    break if !(_e4786);
                                                                }
                                                            }
                                                            let _e4789 = phi_5822_;
                                                            phi_5934_ = _e4789;
                                                            if _e4789 {
                                                                break;
                                                            }
                                                            let _e4790 = local_307;
                                                            phi_5935_ = _e4789;
                                                            phi_2945_ = (_e4790 + 1u);
                                                            let _e5690 = local_630;
                                                            phi_2948_ = _e5690;
                                                        } else {
                                                            phi_5935_ = _e3637;
                                                            phi_2945_ = u32();
                                                            phi_2948_ = type_5();
                                                        }
                                                        let _e4793 = phi_5935_;
                                                        let _e4795 = phi_2945_;
                                                        let _e4797 = phi_2948_;
                                                        continue;
                                                        continuing {
                                                            let _e4798 = local_308;
                                                            phi_5868_ = _e4793;
                                                            phi_2944_ = _e4795;
                                                            phi_2947_ = _e4797;
                                                            phi_5934_ = _e4793;
                                                            break if !(_e4798);
                                                        }
                                                    }
                                                    let _e4801 = phi_5934_;
                                                    phi_5936_ = _e4801;
                                                    if _e4801 {
                                                        break;
                                                    }
                                                    let _e4802 = local_303;
                                                    phi_5937_ = _e4801;
                                                    phi_2928_ = (_e4802 + 1u);
                                                    let _e5696 = local_631;
                                                    phi_2931_ = _e5696;
                                                } else {
                                                    phi_5937_ = _e3621;
                                                    phi_2928_ = u32();
                                                    phi_2931_ = type_5();
                                                }
                                                let _e4805 = phi_5937_;
                                                let _e4807 = phi_2928_;
                                                let _e4809 = phi_2931_;
                                                continue;
                                                continuing {
                                                    let _e4810 = local_305;
                                                    phi_5869_ = _e4805;
                                                    phi_2927_ = _e4807;
                                                    phi_2930_ = _e4809;
                                                    phi_5936_ = _e4805;
                                                    break if !(_e4810);
                                                }
                                            }
                                            let _e4813 = phi_5936_;
                                            phi_5975_ = _e4813;
                                            if _e4813 {
                                                break;
                                            }
                                            let _e4814 = local_294;
                                            let _e4815 = local_293;
                                            let _e4818 = (1f / f32((_e4814 * _e4815)));
                                            let _e4819 = local_304;
                                            let _e4822 = local_304;
                                            let _e4825 = local_304;
                                            let _e4828 = local_304;
                                            phi_5954_ = _e4813;
                                            phi_4072_ = type_5((_e4819.member * _e4818), (_e4822.member_1 * _e4818), (_e4825.member_2 * _e4818), (_e4828.member_3 * _e4818));
                                        }
                                        let _e4833 = phi_5954_;
                                        let _e4835 = phi_4072_;
                                        phi_5953_ = _e4833;
                                        phi_4073_ = _e4835;
                                        phi_4074_ = _e3284;
                                    }
                                    let _e4837 = phi_5953_;
                                    let _e4839 = phi_4073_;
                                    let _e4841 = phi_4074_;
                                    if _e4841 {
                                        phi_4078_ = type_5(1f, 1f, 1f, 1f);
                                    } else {
                                        phi_4078_ = _e4839;
                                    }
                                    let _e4843 = phi_4078_;
                                    phi_5951_ = _e4837;
                                    phi_4079_ = _e4843;
                                }
                                let _e4845 = phi_5951_;
                                let _e4847 = phi_4079_;
                                phi_5950_ = _e4845;
                                phi_4080_ = _e4847;
                                phi_4081_ = _e3248;
                            }
                            let _e4849 = phi_5950_;
                            let _e4851 = phi_4080_;
                            let _e4853 = phi_4081_;
                            if _e4853 {
                                phi_4085_ = type_5(1f, 1f, 1f, 1f);
                            } else {
                                phi_4085_ = _e4851;
                            }
                            let _e4855 = phi_4085_;
                            local_620 = array<f32, 4>(_e4855.member, _e4855.member_1, _e4855.member_2, _e4855.member_3);
                            let _e4861 = local_33;
                            local_610 = _e4861;
                            let _e4863 = local_18;
                            local_611[0u] = _e4863;
                            let _e4865 = local_20;
                            local_611[1u] = _e4865;
                            let _e4867 = local_34;
                            local_611[2u] = _e4867;
                            phi_4113_ = 0u;
                            phi_4116_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            loop {
                                let _e4869 = phi_4113_;
                                let _e4871 = phi_4116_;
                                local_439 = _e4869;
                                local_440 = _e4871;
                                let _e4872 = local_439;
                                let _e4873 = (_e4872 < 3u);
                                local_441 = _e4873;
                                if _e4873 {
                                    let _e4874 = local_439;
                                    if (_e4874 < 4u) {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4876 = local_439;
                                    let _e4878 = local_610[_e4876];
                                    let _e4879 = (_e4878 * 10u);
                                    local_442 = _e4879;
                                    let _e4880 = (_e4879 + 8u);
                                    local_443 = _e4880;
                                    let _e4881 = local_2;
                                    if (_e4880 < _e4881) {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4883 = local_443;
                                    let _e4886 = global_5.member[_e4883];
                                    local_444 = _e4886;
                                    let _e4887 = local_442;
                                    let _e4888 = (_e4887 + 9u);
                                    local_445 = _e4888;
                                    let _e4889 = local_2;
                                    if (_e4888 < _e4889) {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4891 = local_445;
                                    let _e4894 = global_5.member[_e4891];
                                    local_446 = _e4894;
                                    let _e4895 = local_441;
                                    if _e4895 {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4896 = local_439;
                                    let _e4898 = local_611[_e4896];
                                    local_447 = _e4898;
                                    let _e4899 = local_444;
                                    let _e4900 = (_e4899 & 65535u);
                                    local_603 = select(-1f, 1f, ((_e4900 & 32768u) == 0u));
                                    let _e4906 = ((_e4900 >> bitcast<u32>(10i)) & 31u);
                                    local_448 = _e4906;
                                    local_449 = (_e4900 & 1023u);
                                    if (_e4906 == 0u) {
                                        let _e4928 = local_449;
                                        let _e4930 = local_603;
                                        phi_4202_ = ((_e4930 * f32(_e4928)) * 0.000000059604645f);
                                    } else {
                                        let _e4909 = local_448;
                                        if (_e4909 == 31u) {
                                            let _e4919 = local_449;
                                            phi_4199_ = (2139095040u | (_e4919 << bitcast<u32>(13i)));
                                        } else {
                                            let _e4911 = local_448;
                                            let _e4915 = local_449;
                                            phi_4199_ = (((_e4911 + 112u) << bitcast<u32>(23i)) | (_e4915 << bitcast<u32>(13i)));
                                        }
                                        let _e4924 = phi_4199_;
                                        let _e4926 = local_603;
                                        phi_4202_ = (_e4926 * bitcast<f32>(_e4924));
                                    }
                                    let _e4934 = phi_4202_;
                                    let _e4935 = local_447;
                                    let _e4937 = local_440;
                                    local_450 = (_e4937[0] + (_e4935 * _e4934));
                                    let _e4940 = local_441;
                                    if _e4940 {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4941 = local_611[_e4896];
                                    local_451 = _e4941;
                                    let _e4942 = local_444;
                                    let _e4944 = (_e4942 >> bitcast<u32>(16i));
                                    local_604 = select(-1f, 1f, ((_e4944 & 32768u) == 0u));
                                    let _e4950 = ((_e4944 >> bitcast<u32>(10i)) & 31u);
                                    local_452 = _e4950;
                                    local_453 = (_e4944 & 1023u);
                                    if (_e4950 == 0u) {
                                        let _e4972 = local_453;
                                        let _e4974 = local_604;
                                        phi_4245_ = ((_e4974 * f32(_e4972)) * 0.000000059604645f);
                                    } else {
                                        let _e4953 = local_452;
                                        if (_e4953 == 31u) {
                                            let _e4963 = local_453;
                                            phi_4242_ = (2139095040u | (_e4963 << bitcast<u32>(13i)));
                                        } else {
                                            let _e4955 = local_452;
                                            let _e4959 = local_453;
                                            phi_4242_ = (((_e4955 + 112u) << bitcast<u32>(23i)) | (_e4959 << bitcast<u32>(13i)));
                                        }
                                        let _e4968 = phi_4242_;
                                        let _e4970 = local_604;
                                        phi_4245_ = (_e4970 * bitcast<f32>(_e4968));
                                    }
                                    let _e4978 = phi_4245_;
                                    let _e4979 = local_451;
                                    let _e4981 = local_440;
                                    local_454 = (_e4981[1] + (_e4979 * _e4978));
                                    let _e4984 = local_441;
                                    if _e4984 {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4985 = local_611[_e4896];
                                    local_455 = _e4985;
                                    let _e4986 = local_446;
                                    let _e4987 = (_e4986 & 65535u);
                                    local_605 = select(-1f, 1f, ((_e4987 & 32768u) == 0u));
                                    let _e4993 = ((_e4987 >> bitcast<u32>(10i)) & 31u);
                                    local_456 = _e4993;
                                    local_457 = (_e4987 & 1023u);
                                    if (_e4993 == 0u) {
                                        let _e5015 = local_457;
                                        let _e5017 = local_605;
                                        phi_4288_ = ((_e5017 * f32(_e5015)) * 0.000000059604645f);
                                    } else {
                                        let _e4996 = local_456;
                                        if (_e4996 == 31u) {
                                            let _e5006 = local_457;
                                            phi_4285_ = (2139095040u | (_e5006 << bitcast<u32>(13i)));
                                        } else {
                                            let _e4998 = local_456;
                                            let _e5002 = local_457;
                                            phi_4285_ = (((_e4998 + 112u) << bitcast<u32>(23i)) | (_e5002 << bitcast<u32>(13i)));
                                        }
                                        let _e5011 = phi_4285_;
                                        let _e5013 = local_605;
                                        phi_4288_ = (_e5013 * bitcast<f32>(_e5011));
                                    }
                                    let _e5021 = phi_4288_;
                                    let _e5022 = local_455;
                                    let _e5024 = local_440;
                                    local_458 = (_e5024[2] + (_e5022 * _e5021));
                                    let _e5027 = local_441;
                                    if _e5027 {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e5028 = local_611[_e4896];
                                    local_459 = _e5028;
                                    let _e5029 = local_446;
                                    let _e5031 = (_e5029 >> bitcast<u32>(16i));
                                    local_606 = select(-1f, 1f, ((_e5031 & 32768u) == 0u));
                                    let _e5037 = ((_e5031 >> bitcast<u32>(10i)) & 31u);
                                    local_460 = _e5037;
                                    local_461 = (_e5031 & 1023u);
                                    if (_e5037 == 0u) {
                                        let _e5059 = local_461;
                                        let _e5061 = local_606;
                                        phi_4331_ = ((_e5061 * f32(_e5059)) * 0.000000059604645f);
                                    } else {
                                        let _e5040 = local_460;
                                        if (_e5040 == 31u) {
                                            let _e5050 = local_461;
                                            phi_4328_ = (2139095040u | (_e5050 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5042 = local_460;
                                            let _e5046 = local_461;
                                            phi_4328_ = (((_e5042 + 112u) << bitcast<u32>(23i)) | (_e5046 << bitcast<u32>(13i)));
                                        }
                                        let _e5055 = phi_4328_;
                                        let _e5057 = local_606;
                                        phi_4331_ = (_e5057 * bitcast<f32>(_e5055));
                                    }
                                    let _e5065 = phi_4331_;
                                    let _e5066 = local_459;
                                    let _e5068 = local_440;
                                    let _e5071 = local_450;
                                    let _e5072 = local_454;
                                    let _e5073 = local_458;
                                    let _e5075 = local_439;
                                    phi_4114_ = (_e5075 + 1u);
                                    phi_4117_ = array<f32, 4>(_e5071, _e5072, _e5073, (_e5068[3] + (_e5066 * _e5065)));
                                } else {
                                    phi_4114_ = u32();
                                    phi_4117_ = array<f32, 4>();
                                }
                                let _e5078 = phi_4114_;
                                let _e5080 = phi_4117_;
                                continue;
                                continuing {
                                    let _e5081 = local_441;
                                    phi_4113_ = _e5078;
                                    phi_4116_ = _e5080;
                                    phi_5938_ = _e4849;
                                    break if !(_e5081);
                                }
                            }
                            let _e5084 = phi_5938_;
                            phi_5975_ = _e5084;
                            if _e5084 {
                                break;
                            }
                            let _e5085 = local_440;
                            let _e5087 = local_440;
                            let _e5089 = local_440;
                            let _e5091 = local_440;
                            local_621 = array<f32, 4>(_e5085[0], _e5087[1], _e5089[2], _e5091[3]);
                            let _e5094 = local_82;
                            let _e5095 = (_e5094 + 10u);
                            local_462 = _e5095;
                            let _e5096 = local_4;
                            if (_e5095 < _e5096) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5098 = local_462;
                            let _e5101 = global_7.member[_e5098];
                            local_463 = _e5101;
                            let _e5105 = global_3.member.member.member;
                            let _e5106 = local_72;
                            let _e5110 = local_72;
                            let _e5115 = local_72;
                            let _e5119 = (((_e5106[0] * _e5105[0]) + (_e5110[1] * _e5105[1])) + (_e5115[2] * _e5105[2]));
                            local_464 = _e5119;
                            if (_e5119 != _e5119) {
                                phi_5669_ = true;
                            } else {
                                let _e5121 = local_464;
                                phi_5669_ = (0f >= _e5121);
                            }
                            let _e5124 = phi_5669_;
                            let _e5125 = local_464;
                            local_607 = select(_e5125, 0f, _e5124);
                            local_622 = array<f32, 3>(0f, 0f, 0f);
                            phi_4373_ = 0u;
                            loop {
                                let _e5128 = phi_4373_;
                                local_465 = _e5128;
                                let _e5129 = local_465;
                                let _e5130 = (_e5129 < 3u);
                                local_466 = _e5130;
                                if _e5130 {
                                    let _e5131 = local_82;
                                    let _e5132 = local_465;
                                    let _e5133 = (_e5131 + _e5132);
                                    local_467 = _e5133;
                                    let _e5134 = local_4;
                                    if (_e5133 < _e5134) {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5136 = local_467;
                                    let _e5139 = global_7.member[_e5136];
                                    local_468 = bitcast<f32>(_e5139);
                                    let _e5141 = local_465;
                                    let _e5142 = (_e5141 < 4u);
                                    local_469 = _e5142;
                                    if _e5142 {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5143 = local_465;
                                    let _e5145 = local_619[_e5143];
                                    let _e5146 = local_468;
                                    local_470 = (_e5146 * _e5145);
                                    let _e5148 = local_469;
                                    if _e5148 {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5149 = local_465;
                                    let _e5151 = local_621[_e5149];
                                    let _e5152 = local_470;
                                    let _e5153 = (_e5152 * _e5151);
                                    local_471 = _e5153;
                                    let _e5154 = local_463;
                                    if ((_e5154 & 1u) == 0u) {
                                        let _e5157 = local_466;
                                        if _e5157 {
                                        } else {
                                            phi_5959_ = true;
                                            break;
                                        }
                                        let _e5158 = local_465;
                                        let _e5163 = global_3.member.member.member_4[_e5158];
                                        local_472 = _e5163;
                                        let _e5164 = local_466;
                                        if _e5164 {
                                        } else {
                                            phi_5959_ = true;
                                            break;
                                        }
                                        let _e5165 = local_465;
                                        let _e5170 = global_3.member.member.member_2[_e5165];
                                        let _e5171 = local_607;
                                        let _e5173 = local_472;
                                        let _e5175 = local_471;
                                        phi_4439_ = (_e5175 * (_e5173 + (_e5170 * _e5171)));
                                    } else {
                                        phi_4439_ = _e5153;
                                    }
                                    let _e5178 = phi_4439_;
                                    local_473 = _e5178;
                                    let _e5179 = local_82;
                                    let _e5181 = local_465;
                                    let _e5182 = ((_e5179 + 4u) + _e5181);
                                    local_474 = _e5182;
                                    let _e5183 = local_4;
                                    if (_e5182 < _e5183) {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5185 = local_474;
                                    let _e5188 = global_7.member[_e5185];
                                    local_475 = bitcast<f32>(_e5188);
                                    let _e5190 = local_469;
                                    if _e5190 {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5191 = local_465;
                                    let _e5193 = local_620[_e5191];
                                    let _e5194 = local_475;
                                    local_476 = (_e5194 * _e5193);
                                    let _e5196 = local_466;
                                    if _e5196 {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5197 = local_465;
                                    let _e5199 = local_473;
                                    let _e5200 = local_476;
                                    local_622[_e5197] = (_e5199 + _e5200);
                                    let _e5202 = local_465;
                                    phi_4374_ = (_e5202 + 1u);
                                } else {
                                    phi_4374_ = u32();
                                }
                                let _e5205 = phi_4374_;
                                continue;
                                continuing {
                                    let _e5206 = local_466;
                                    phi_4373_ = _e5205;
                                    phi_5959_ = _e5084;
                                    break if !(_e5206);
                                }
                            }
                            let _e5209 = phi_5959_;
                            phi_5975_ = _e5209;
                            if _e5209 {
                                break;
                            }
                            let _e5210 = local_463;
                            if ((_e5210 & 8u) == 0u) {
                                phi_4516_ = 1f;
                            } else {
                                let _e5213 = local_82;
                                let _e5214 = (_e5213 + 3u);
                                local_477 = _e5214;
                                let _e5215 = local_4;
                                if (_e5214 < _e5215) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e5217 = local_477;
                                let _e5220 = global_7.member[_e5217];
                                let _e5223 = local_619[3u];
                                let _e5226 = local_621[3u];
                                let _e5227 = ((bitcast<f32>(_e5220) * _e5223) * _e5226);
                                let _e5229 = select(_e5227, 0f, (_e5227 < 0f));
                                phi_4516_ = select(_e5229, 1f, (_e5229 > 1f));
                            }
                            let _e5233 = phi_4516_;
                            let _e5234 = local_622;
                            local_623 = _e5234;
                            phi_5968_ = _e5209;
                            phi_4565_ = _e5233;
                            phi_4566_ = _e819;
                        } else {
                            let _e768 = global_3.member.member_2;
                            if (_e768 == 1u) {
                                phi_4554_ = true;
                            } else {
                                let _e770 = local_13;
                                let _e771 = local_8;
                                if (_e770 < _e771) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e773 = local_13;
                                let _e776 = global_11.member[_e773];
                                let _e780 = ((bitcast<u32>(bitcast<f32>(_e776)) & 2139095040u) != 2139095040u);
                                if _e780 {
                                } else {
                                    local_623 = array<f32, 3>(0f, 0f, 0f);
                                }
                                phi_4554_ = _e780;
                            }
                            let _e782 = phi_4554_;
                            local_478 = _e782;
                            if _e782 {
                                let _e786 = global_3.member.member.member_6;
                                local_623 = array<f32, 3>(_e786[0], _e786[1], _e786[2]);
                            }
                            let _e791 = local_478;
                            phi_5968_ = _e740;
                            phi_4565_ = select(0f, 1f, _e791);
                            phi_4566_ = _e707;
                        }
                        let _e5236 = phi_5968_;
                        let _e5238 = phi_4565_;
                        let _e5240 = phi_4566_;
                        local_479 = _e5238;
                        local_480 = _e5240;
                        let _e5243 = global_3.member.member_2;
                        if (_e5243 == 1u) {
                            phi_4574_ = 0u;
                            loop {
                                let _e5389 = phi_4574_;
                                local_481 = _e5389;
                                let _e5390 = local_481;
                                let _e5391 = (_e5390 < 3u);
                                local_482 = _e5391;
                                if _e5391 {
                                    let _e5392 = local_13;
                                    let _e5394 = local_481;
                                    let _e5395 = ((3u * _e5392) + _e5394);
                                    local_483 = _e5395;
                                    let _e5396 = local_7;
                                    let _e5397 = (_e5395 < _e5396);
                                    local_484 = _e5397;
                                    if _e5397 {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e5398 = local_483;
                                    let _e5401 = global_10.member[_e5398];
                                    local_485 = bitcast<f32>(_e5401);
                                    let _e5403 = local_482;
                                    if _e5403 {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e5404 = local_481;
                                    let _e5406 = local_623[_e5404];
                                    let _e5407 = local_479;
                                    let _e5409 = local_485;
                                    local_486 = bitcast<u32>((_e5409 + (_e5407 * _e5406)));
                                    let _e5412 = local_484;
                                    if _e5412 {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e5413 = local_486;
                                    global_10.member[_e5398] = _e5413;
                                    let _e5414 = local_481;
                                    phi_4575_ = (_e5414 + 1u);
                                } else {
                                    phi_4575_ = u32();
                                }
                                let _e5417 = phi_4575_;
                                continue;
                                continuing {
                                    let _e5418 = local_482;
                                    phi_4574_ = _e5417;
                                    phi_5965_ = _e5236;
                                    break if !(_e5418);
                                }
                            }
                            let _e5421 = phi_5965_;
                            phi_5975_ = _e5421;
                            if _e5421 {
                                break;
                            }
                            phi_5978_ = _e5421;
                        } else {
                            let _e5245 = local_13;
                            let _e5246 = (_e5245 * 5u);
                            local_487 = _e5246;
                            let _e5248 = local_623[0u];
                            local_488 = bitcast<u32>(_e5248);
                            let _e5250 = local_7;
                            if (_e5246 < _e5250) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5252 = local_487;
                            let _e5255 = local_488;
                            global_10.member[_e5252] = _e5255;
                            let _e5256 = local_487;
                            let _e5257 = (_e5256 + 1u);
                            local_489 = _e5257;
                            let _e5259 = local_623[1u];
                            local_490 = bitcast<u32>(_e5259);
                            let _e5261 = local_7;
                            if (_e5257 < _e5261) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5263 = local_489;
                            let _e5266 = local_490;
                            global_10.member[_e5263] = _e5266;
                            let _e5267 = local_487;
                            let _e5268 = (_e5267 + 2u);
                            local_491 = _e5268;
                            let _e5270 = local_623[2u];
                            local_492 = bitcast<u32>(_e5270);
                            let _e5272 = local_7;
                            if (_e5268 < _e5272) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5274 = local_491;
                            let _e5277 = local_492;
                            global_10.member[_e5274] = _e5277;
                            let _e5278 = local_487;
                            let _e5279 = (_e5278 + 3u);
                            local_493 = _e5279;
                            let _e5280 = local_479;
                            local_494 = bitcast<u32>(_e5280);
                            let _e5282 = local_7;
                            if (_e5279 < _e5282) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5284 = local_493;
                            let _e5287 = local_494;
                            global_10.member[_e5284] = _e5287;
                            let _e5288 = local_487;
                            let _e5289 = (_e5288 + 4u);
                            local_495 = _e5289;
                            let _e5290 = local_480;
                            local_496 = bitcast<u32>(_e5290);
                            let _e5292 = local_7;
                            if (_e5289 < _e5292) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5294 = local_495;
                            let _e5297 = local_496;
                            global_10.member[_e5294] = _e5297;
                            let _e5300 = global_3.member.member_4;
                            local_497 = _e5300;
                            let _e5301 = local_16;
                            if _e5301 {
                                let _e5302 = local_479;
                                if (_e5302 < 1f) {
                                    phi_4788_ = _e5240;
                                } else {
                                    let _e5304 = local_480;
                                    let _e5305 = local_497;
                                    local_498 = (_e5304 * _e5305);
                                    let _e5307 = local_496;
                                    if (_e5307 == 0u) {
                                        phi_4729_ = false;
                                    } else {
                                        let _e5309 = local_496;
                                        phi_4729_ = (_e5309 <= 2139095040u);
                                    }
                                    let _e5312 = phi_4729_;
                                    if _e5312 {
                                        let _e5313 = local_498;
                                        if (_e5313 >= 0f) {
                                            let _e5315 = local_498;
                                            let _e5318 = ((bitcast<u32>(_e5315) & 2147483647u) > 2139095040u);
                                            if _e5318 {
                                                phi_4760_ = f32();
                                                phi_4761_ = f32();
                                                phi_4762_ = false;
                                            } else {
                                                let _e5319 = local_498;
                                                let _e5320 = (_e5319 == 0f);
                                                local_499 = _e5320;
                                                if _e5320 {
                                                    phi_4758_ = f32();
                                                    phi_4759_ = true;
                                                } else {
                                                    let _e5324 = global_3.member.member_3.member_1;
                                                    local_500 = _e5324;
                                                    let _e5325 = local_498;
                                                    let _e5326 = (_e5325 >= _e5324);
                                                    if _e5326 {
                                                        phi_4756_ = f32();
                                                    } else {
                                                        let _e5327 = local_498;
                                                        let _e5328 = local_480;
                                                        let _e5330 = local_500;
                                                        let _e5331 = local_498;
                                                        phi_4756_ = ((_e5327 * _e5328) / (_e5330 - _e5331));
                                                    }
                                                    let _e5335 = phi_4756_;
                                                    phi_4758_ = _e5335;
                                                    phi_4759_ = _e5326;
                                                }
                                                let _e5337 = phi_4758_;
                                                let _e5339 = phi_4759_;
                                                let _e5340 = local_499;
                                                let _e5341 = local_609;
                                                phi_4760_ = select(_e5341, 0f, _e5340);
                                                phi_4761_ = _e5337;
                                                phi_4762_ = _e5339;
                                            }
                                            let _e5344 = phi_4760_;
                                            let _e5346 = phi_4761_;
                                            let _e5348 = phi_4762_;
                                            phi_4763_ = _e5344;
                                            phi_4764_ = _e5346;
                                            phi_4765_ = _e5318;
                                            phi_4766_ = _e5348;
                                        } else {
                                            phi_4763_ = f32();
                                            phi_4764_ = f32();
                                            phi_4765_ = true;
                                            phi_4766_ = false;
                                        }
                                        let _e5350 = phi_4763_;
                                        let _e5352 = phi_4764_;
                                        let _e5354 = phi_4765_;
                                        let _e5356 = phi_4766_;
                                        phi_4767_ = _e5350;
                                        phi_4768_ = _e5352;
                                        phi_4769_ = _e5354;
                                        phi_4770_ = _e5356;
                                    } else {
                                        phi_4767_ = f32();
                                        phi_4768_ = f32();
                                        phi_4769_ = true;
                                        phi_4770_ = false;
                                    }
                                    let _e5358 = phi_4767_;
                                    let _e5360 = phi_4768_;
                                    let _e5362 = phi_4769_;
                                    let _e5364 = phi_4770_;
                                    let _e5365 = local_608;
                                    let _e5369 = local_480;
                                    let _e5370 = (_e5369 + select(_e5360, select(_e5358, _e5365, _e5362), select(_e5364, true, _e5362)));
                                    let _e5374 = local_609;
                                    phi_4788_ = select(_e5374, _e5370, ((bitcast<u32>(_e5370) & 2139095040u) != 2139095040u));
                                }
                                let _e5377 = phi_4788_;
                                phi_4789_ = _e5377;
                            } else {
                                phi_4789_ = _e707;
                            }
                            let _e5379 = phi_4789_;
                            local_501 = bitcast<u32>(_e5379);
                            let _e5381 = local_13;
                            let _e5382 = local_8;
                            if (_e5381 < _e5382) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5384 = local_13;
                            let _e5387 = local_501;
                            global_11.member[_e5384] = _e5387;
                            phi_5978_ = _e5236;
                        }
                        let _e5423 = phi_5978_;
                        phi_5977_ = _e5423;
                    } else {
                        phi_5977_ = _e740;
                    }
                    let _e5425 = phi_5977_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e5426 = local_11;
                    let _e5427 = local_10;
                    phi_5976_ = _e5425;
                    phi_275_ = (_e5426 + _e5427);
                } else {
                    phi_5976_ = _e740;
                    phi_275_ = u32();
                }
                let _e5430 = phi_5976_;
                let _e5432 = phi_275_;
                continue;
                continuing {
                    let _e5433 = local_12;
                    phi_5694_ = _e5430;
                    phi_274_ = _e5432;
                    phi_5975_ = _e5430;
                    break if !(_e5433);
                }
            }
            let _e5436 = phi_5975_;
            if _e5436 {
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
