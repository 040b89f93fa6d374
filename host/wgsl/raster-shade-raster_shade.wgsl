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
                        let _e765 = select(select(u32(_e759), 0u, !((_e759 >= 0f))), 4294967295u, (_e759 > 4294967000f));
                        local_15 = _e765;
                        let _e766 = (_e765 > 0u);
                        local_16 = _e766;
                        if _e766 {
                            let _e794 = local_14;
                            let _e795 = (_e794 + 2u);
                            local_17 = _e795;
                            let _e796 = local_1;
                            if (_e795 < _e796) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e798 = local_17;
                            let _e801 = global_4.member[_e798];
                            local_18 = bitcast<f32>(_e801);
                            let _e803 = local_14;
                            let _e804 = (_e803 + 3u);
                            local_19 = _e804;
                            let _e805 = local_1;
                            if (_e804 < _e805) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e807 = local_19;
                            let _e810 = global_4.member[_e807];
                            local_20 = bitcast<f32>(_e810);
                            let _e812 = local_14;
                            let _e813 = (_e812 + 1u);
                            local_21 = _e813;
                            let _e814 = local_1;
                            if (_e813 < _e814) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e816 = local_21;
                            let _e819 = global_4.member[_e816];
                            let _e820 = bitcast<f32>(_e819);
                            let _e823 = global_3.member.member_4;
                            local_22 = ((2f * _e823) * _e820);
                            let _e828 = global_3.member.member_1;
                            local_23 = _e828;
                            let _e831 = global_3.member.member_8;
                            local_24 = _e831;
                            let _e834 = global_3.member.member_7;
                            local_25 = _e834;
                            let _e835 = local_15;
                            let _e837 = ((_e835 - 1u) * 4u);
                            local_26 = _e837;
                            let _e838 = local_3;
                            if (_e837 < _e838) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e840 = local_26;
                            let _e843 = global_6.member[_e840];
                            local_27 = _e843;
                            let _e844 = local_26;
                            let _e845 = (_e844 + 1u);
                            local_28 = _e845;
                            let _e846 = local_3;
                            if (_e845 < _e846) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e848 = local_28;
                            let _e851 = global_6.member[_e848];
                            local_29 = _e851;
                            let _e852 = local_26;
                            let _e853 = (_e852 + 2u);
                            local_30 = _e853;
                            let _e854 = local_3;
                            if (_e853 < _e854) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e856 = local_30;
                            let _e859 = global_6.member[_e856];
                            local_31 = _e859;
                            let _e860 = local_26;
                            let _e861 = (_e860 + 3u);
                            local_32 = _e861;
                            let _e862 = local_3;
                            if (_e861 < _e862) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e864 = local_32;
                            let _e867 = global_6.member[_e864];
                            let _e868 = local_27;
                            let _e869 = local_29;
                            let _e870 = local_31;
                            let _e871 = array<u32, 4>(_e868, _e869, _e870, _e867);
                            local_33 = _e871;
                            local_614 = _e871;
                            let _e872 = local_18;
                            let _e874 = local_20;
                            let _e875 = ((1f - _e872) - _e874);
                            local_34 = _e875;
                            let _e877 = local_18;
                            local_615[0u] = _e877;
                            let _e879 = local_20;
                            local_615[1u] = _e879;
                            local_615[2u] = _e875;
                            let _e882 = local_614[0u];
                            let _e883 = (_e882 * 10u);
                            local_35 = _e883;
                            let _e884 = local_2;
                            if (_e883 < _e884) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e886 = local_35;
                            let _e889 = global_5.member[_e886];
                            local_36 = bitcast<f32>(_e889);
                            let _e891 = local_35;
                            let _e892 = (_e891 + 1u);
                            local_37 = _e892;
                            let _e893 = local_2;
                            if (_e892 < _e893) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e895 = local_37;
                            let _e898 = global_5.member[_e895];
                            local_38 = bitcast<f32>(_e898);
                            let _e900 = local_35;
                            let _e901 = (_e900 + 2u);
                            local_39 = _e901;
                            let _e902 = local_2;
                            if (_e901 < _e902) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e904 = local_39;
                            let _e907 = global_5.member[_e904];
                            local_40 = bitcast<f32>(_e907);
                            let _e910 = local_614[1u];
                            let _e911 = (_e910 * 10u);
                            local_41 = _e911;
                            let _e912 = local_2;
                            if (_e911 < _e912) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e914 = local_41;
                            let _e917 = global_5.member[_e914];
                            local_42 = bitcast<f32>(_e917);
                            let _e919 = local_41;
                            let _e920 = (_e919 + 1u);
                            local_43 = _e920;
                            let _e921 = local_2;
                            if (_e920 < _e921) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e923 = local_43;
                            let _e926 = global_5.member[_e923];
                            local_44 = bitcast<f32>(_e926);
                            let _e928 = local_41;
                            let _e929 = (_e928 + 2u);
                            local_45 = _e929;
                            let _e930 = local_2;
                            if (_e929 < _e930) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e932 = local_45;
                            let _e935 = global_5.member[_e932];
                            local_46 = bitcast<f32>(_e935);
                            let _e938 = local_614[2u];
                            let _e939 = (_e938 * 10u);
                            local_47 = _e939;
                            let _e940 = local_2;
                            if (_e939 < _e940) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e942 = local_47;
                            let _e945 = global_5.member[_e942];
                            local_48 = bitcast<f32>(_e945);
                            let _e947 = local_47;
                            let _e948 = (_e947 + 1u);
                            local_49 = _e948;
                            let _e949 = local_2;
                            if (_e948 < _e949) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e951 = local_49;
                            let _e954 = global_5.member[_e951];
                            local_50 = bitcast<f32>(_e954);
                            let _e956 = local_47;
                            let _e957 = (_e956 + 2u);
                            local_51 = _e957;
                            let _e958 = local_2;
                            if (_e957 < _e958) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e960 = local_51;
                            let _e963 = global_5.member[_e960];
                            let _e966 = local_36;
                            let _e967 = local_38;
                            let _e968 = local_40;
                            local_616[0u] = array<f32, 3>(_e966, _e967, _e968);
                            let _e971 = local_42;
                            let _e972 = local_44;
                            let _e973 = local_46;
                            local_616[1u] = array<f32, 3>(_e971, _e972, _e973);
                            let _e976 = local_48;
                            let _e977 = local_50;
                            local_616[2u] = array<f32, 3>(_e976, _e977, bitcast<f32>(_e963));
                            local_617 = array<f32, 3>(0f, 0f, 0f);
                            local_618 = array<f32, 3>(0f, 0f, 0f);
                            phi_5693_ = _e740;
                            phi_633_ = 0u;
                            loop {
                                let _e980 = phi_5693_;
                                let _e982 = phi_633_;
                                local_52 = _e982;
                                let _e983 = local_52;
                                let _e984 = (_e983 < 3u);
                                local_53 = _e984;
                                if _e984 {
                                    let _e985 = local_52;
                                    if (_e985 < 4u) {
                                    } else {
                                        phi_5695_ = true;
                                        break;
                                    }
                                    let _e987 = local_52;
                                    let _e989 = local_614[_e987];
                                    local_54 = (_e989 * 10u);
                                    phi_651_ = 0u;
                                    loop {
                                        let _e992 = phi_651_;
                                        local_55 = _e992;
                                        let _e993 = local_55;
                                        let _e994 = (_e993 < 3u);
                                        local_56 = _e994;
                                        if _e994 {
                                            let _e995 = local_53;
                                            if _e995 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e996 = local_52;
                                            let _e998 = local_615[_e996];
                                            local_57 = _e998;
                                            let _e999 = local_53;
                                            if _e999 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1000 = local_56;
                                            if _e1000 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1001 = local_52;
                                            let _e1002 = local_55;
                                            let _e1005 = local_616[_e1001][_e1002];
                                            let _e1006 = local_57;
                                            local_58 = (_e1006 * _e1005);
                                            let _e1008 = local_56;
                                            if _e1008 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1009 = local_55;
                                            let _e1011 = local_617[_e1009];
                                            let _e1012 = local_58;
                                            local_617[_e1009] = (_e1011 + _e1012);
                                            let _e1014 = local_53;
                                            if _e1014 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1015 = local_615[_e996];
                                            local_59 = _e1015;
                                            let _e1016 = local_54;
                                            let _e1018 = local_55;
                                            let _e1019 = ((_e1016 + 4u) + _e1018);
                                            local_60 = _e1019;
                                            let _e1020 = local_2;
                                            if (_e1019 < _e1020) {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1022 = local_60;
                                            let _e1025 = global_5.member[_e1022];
                                            let _e1027 = local_59;
                                            local_61 = (_e1027 * bitcast<f32>(_e1025));
                                            let _e1029 = local_56;
                                            if _e1029 {
                                            } else {
                                                phi_5690_ = true;
                                                break;
                                            }
                                            let _e1030 = local_55;
                                            let _e1032 = local_618[_e1030];
                                            let _e1033 = local_61;
                                            local_618[_e1030] = (_e1032 + _e1033);
                                            let _e1035 = local_55;
                                            phi_652_ = (_e1035 + 1u);
                                        } else {
                                            phi_652_ = u32();
                                        }
                                        let _e1038 = phi_652_;
                                        continue;
                                        continuing {
                                            let _e1039 = local_56;
                                            phi_651_ = _e1038;
                                            phi_5690_ = _e980;
                                            break if !(_e1039);
                                        }
                                    }
                                    let _e1042 = phi_5690_;
                                    phi_5695_ = _e1042;
                                    if _e1042 {
                                        break;
                                    }
                                    let _e1043 = local_52;
                                    phi_5696_ = _e1042;
                                    phi_634_ = (_e1043 + 1u);
                                } else {
                                    phi_5696_ = _e980;
                                    phi_634_ = u32();
                                }
                                let _e1046 = phi_5696_;
                                let _e1048 = phi_634_;
                                continue;
                                continuing {
                                    let _e1049 = local_53;
                                    phi_5693_ = _e1046;
                                    phi_633_ = _e1048;
                                    phi_5695_ = _e1046;
                                    break if !(_e1049);
                                }
                            }
                            let _e1052 = phi_5695_;
                            phi_5975_ = _e1052;
                            if _e1052 {
                                break;
                            }
                            let _e1053 = local_616[1u];
                            let _e1057 = local_616[0u];
                            let _e1061 = (_e1053[0] - _e1057[0]);
                            let _e1062 = (_e1053[1] - _e1057[1]);
                            let _e1063 = (_e1053[2] - _e1057[2]);
                            let _e1064 = local_616[2u];
                            let _e1068 = local_616[0u];
                            let _e1072 = (_e1064[0] - _e1068[0]);
                            let _e1073 = (_e1064[1] - _e1068[1]);
                            let _e1074 = (_e1064[2] - _e1068[2]);
                            let _e1077 = ((_e1062 * _e1074) - (_e1063 * _e1073));
                            local_62 = _e1077;
                            let _e1080 = ((_e1063 * _e1072) - (_e1061 * _e1074));
                            local_63 = _e1080;
                            let _e1083 = ((_e1061 * _e1073) - (_e1062 * _e1072));
                            local_64 = _e1083;
                            let _e1085 = local_618;
                            if ((((_e1085[0] * _e1085[0]) + (_e1085[1] * _e1085[1])) + (_e1085[2] * _e1085[2])) > 0f) {
                                let _e1120 = local_618;
                                local_65 = _e1120[0];
                                local_66 = _e1120[1];
                                local_67 = _e1120[2];
                                let _e1130 = sqrt((((_e1120[0] * _e1120[0]) + (_e1120[1] * _e1120[1])) + (_e1120[2] * _e1120[2])));
                                local_502 = _e1130;
                                if (_e1130 > 0f) {
                                    let _e1132 = local_65;
                                    let _e1133 = local_502;
                                    let _e1135 = local_66;
                                    let _e1136 = local_502;
                                    let _e1138 = local_67;
                                    let _e1139 = local_502;
                                    phi_5160_ = array<f32, 3>((_e1132 / _e1133), (_e1135 / _e1136), (_e1138 / _e1139));
                                } else {
                                    phi_5160_ = array<f32, 3>(_e1120[0], _e1120[1], _e1120[2]);
                                }
                                let _e1143 = phi_5160_;
                                phi_813_ = _e1143;
                            } else {
                                let _e1095 = local_62;
                                let _e1096 = local_62;
                                let _e1098 = local_63;
                                let _e1099 = local_63;
                                let _e1102 = local_64;
                                let _e1103 = local_64;
                                let _e1106 = sqrt((((_e1095 * _e1096) + (_e1098 * _e1099)) + (_e1102 * _e1103)));
                                local_503 = _e1106;
                                if (_e1106 > 0f) {
                                    let _e1108 = local_62;
                                    let _e1109 = local_503;
                                    let _e1111 = local_63;
                                    let _e1112 = local_503;
                                    let _e1114 = local_64;
                                    let _e1115 = local_503;
                                    phi_5186_ = array<f32, 3>((_e1108 / _e1109), (_e1111 / _e1112), (_e1114 / _e1115));
                                } else {
                                    phi_5186_ = array<f32, 3>(_e1077, _e1080, _e1083);
                                }
                                let _e1119 = phi_5186_;
                                phi_813_ = _e1119;
                            }
                            let _e1145 = phi_813_;
                            local_68 = _e1145;
                            let _e1146 = local_617;
                            let _e1150 = local_23;
                            local_69 = _e1150[0];
                            let _e1153 = local_23;
                            local_70 = _e1153[1];
                            let _e1156 = local_23;
                            local_71 = _e1156[2];
                            let _e1159 = local_62;
                            let _e1161 = local_63;
                            let _e1164 = local_64;
                            if ((((_e1159 * (_e1146[0] - _e1150[0])) + (_e1161 * (_e1146[1] - _e1153[1]))) + (_e1164 * (_e1146[2] - _e1156[2]))) > 0f) {
                                let _e1168 = local_68;
                                let _e1171 = local_68;
                                let _e1174 = local_68;
                                phi_844_ = array<f32, 3>(-(_e1168[0]), -(_e1171[1]), -(_e1174[2]));
                            } else {
                                phi_844_ = _e1145;
                            }
                            let _e1179 = phi_844_;
                            local_72 = _e1179;
                            let _e1180 = local_33;
                            local_612 = _e1180;
                            let _e1182 = local_18;
                            local_613[0u] = _e1182;
                            let _e1184 = local_20;
                            local_613[1u] = _e1184;
                            let _e1186 = local_34;
                            local_613[2u] = _e1186;
                            phi_862_ = 0u;
                            phi_865_ = 0f;
                            phi_867_ = 0f;
                            loop {
                                let _e1188 = phi_862_;
                                let _e1190 = phi_865_;
                                let _e1192 = phi_867_;
                                local_73 = _e1188;
                                local_74 = _e1190;
                                local_75 = _e1192;
                                let _e1193 = local_73;
                                let _e1194 = (_e1193 < 3u);
                                local_76 = _e1194;
                                if _e1194 {
                                    let _e1195 = local_73;
                                    if (_e1195 < 4u) {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1197 = local_73;
                                    let _e1199 = local_612[_e1197];
                                    local_77 = (_e1199 * 10u);
                                    let _e1201 = local_76;
                                    if _e1201 {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1202 = local_73;
                                    let _e1204 = local_613[_e1202];
                                    local_78 = _e1204;
                                    let _e1205 = local_77;
                                    let _e1206 = (_e1205 + 3u);
                                    local_79 = _e1206;
                                    let _e1207 = local_2;
                                    if (_e1206 < _e1207) {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1209 = local_79;
                                    let _e1212 = global_5.member[_e1209];
                                    let _e1214 = local_78;
                                    let _e1216 = local_75;
                                    let _e1218 = local_76;
                                    if _e1218 {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1219 = local_613[_e1202];
                                    local_80 = _e1219;
                                    let _e1220 = local_77;
                                    let _e1221 = (_e1220 + 7u);
                                    local_81 = _e1221;
                                    let _e1222 = local_2;
                                    if (_e1221 < _e1222) {
                                    } else {
                                        phi_5697_ = true;
                                        break;
                                    }
                                    let _e1224 = local_81;
                                    let _e1227 = global_5.member[_e1224];
                                    let _e1229 = local_80;
                                    let _e1231 = local_74;
                                    let _e1233 = local_73;
                                    phi_863_ = (_e1233 + 1u);
                                    phi_866_ = (_e1231 + (_e1229 * bitcast<f32>(_e1227)));
                                    phi_868_ = (_e1216 + (_e1214 * bitcast<f32>(_e1212)));
                                } else {
                                    phi_863_ = u32();
                                    phi_866_ = f32();
                                    phi_868_ = f32();
                                }
                                let _e1236 = phi_863_;
                                let _e1238 = phi_866_;
                                let _e1240 = phi_868_;
                                continue;
                                continuing {
                                    let _e1241 = local_76;
                                    phi_862_ = _e1236;
                                    phi_865_ = _e1238;
                                    phi_867_ = _e1240;
                                    phi_5697_ = _e1052;
                                    break if !(_e1241);
                                }
                            }
                            let _e1244 = phi_5697_;
                            phi_5975_ = _e1244;
                            if _e1244 {
                                break;
                            }
                            let _e1246 = local_614[3u];
                            let _e1247 = (_e1246 * 16u);
                            local_82 = _e1247;
                            let _e1248 = (_e1247 + 8u);
                            local_83 = _e1248;
                            let _e1249 = local_4;
                            if (_e1248 < _e1249) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e1251 = local_83;
                            let _e1254 = global_7.member[_e1251];
                            local_84 = _e1254;
                            let _e1255 = local_82;
                            let _e1256 = (_e1255 + 9u);
                            local_85 = _e1256;
                            let _e1257 = local_4;
                            if (_e1256 < _e1257) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e1259 = local_85;
                            let _e1262 = global_7.member[_e1259];
                            local_86 = _e1262;
                            let _e1263 = local_84;
                            let _e1264 = local_25;
                            if (_e1263 < _e1264) {
                                phi_979_ = true;
                            } else {
                                let _e1266 = local_86;
                                let _e1267 = local_25;
                                phi_979_ = (_e1266 < _e1267);
                            }
                            let _e1270 = phi_979_;
                            if _e1270 {
                                let _e1271 = local_27;
                                let _e1272 = (_e1271 * 10u);
                                local_87 = _e1272;
                                let _e1273 = (_e1272 + 3u);
                                local_88 = _e1273;
                                let _e1274 = local_2;
                                if (_e1273 < _e1274) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1276 = local_88;
                                let _e1279 = global_5.member[_e1276];
                                local_89 = bitcast<f32>(_e1279);
                                let _e1281 = local_87;
                                let _e1282 = (_e1281 + 7u);
                                local_90 = _e1282;
                                let _e1283 = local_2;
                                if (_e1282 < _e1283) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1285 = local_90;
                                let _e1288 = global_5.member[_e1285];
                                local_91 = bitcast<f32>(_e1288);
                                let _e1290 = local_29;
                                let _e1291 = (_e1290 * 10u);
                                local_92 = _e1291;
                                let _e1292 = (_e1291 + 3u);
                                local_93 = _e1292;
                                let _e1293 = local_2;
                                if (_e1292 < _e1293) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1295 = local_93;
                                let _e1298 = global_5.member[_e1295];
                                local_94 = bitcast<f32>(_e1298);
                                let _e1300 = local_92;
                                let _e1301 = (_e1300 + 7u);
                                local_95 = _e1301;
                                let _e1302 = local_2;
                                if (_e1301 < _e1302) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1304 = local_95;
                                let _e1307 = global_5.member[_e1304];
                                local_96 = bitcast<f32>(_e1307);
                                let _e1309 = local_31;
                                let _e1310 = (_e1309 * 10u);
                                local_97 = _e1310;
                                let _e1311 = (_e1310 + 3u);
                                local_98 = _e1311;
                                let _e1312 = local_2;
                                if (_e1311 < _e1312) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1314 = local_98;
                                let _e1317 = global_5.member[_e1314];
                                local_99 = bitcast<f32>(_e1317);
                                let _e1319 = local_97;
                                let _e1320 = (_e1319 + 7u);
                                local_100 = _e1320;
                                let _e1321 = local_2;
                                if (_e1320 < _e1321) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e1323 = local_100;
                                let _e1326 = global_5.member[_e1323];
                                local_101 = bitcast<f32>(_e1326);
                                let _e1328 = local_617;
                                let _e1332 = local_616;
                                let _e1345 = local_69;
                                local_504 = (_e1328[0] - _e1345);
                                let _e1347 = local_70;
                                local_505 = (_e1328[1] - _e1347);
                                let _e1349 = local_71;
                                local_506 = (_e1328[2] - _e1349);
                                let _e1351 = (_e1332[1][0] - _e1332[0][0]);
                                local_507 = _e1351;
                                let _e1352 = (_e1332[1][1] - _e1332[0][1]);
                                local_508 = _e1352;
                                let _e1353 = (_e1332[1][2] - _e1332[0][2]);
                                local_509 = _e1353;
                                let _e1354 = (_e1332[2][0] - _e1332[0][0]);
                                local_510 = _e1354;
                                let _e1355 = (_e1332[2][1] - _e1332[0][1]);
                                local_511 = _e1355;
                                let _e1356 = (_e1332[2][2] - _e1332[0][2]);
                                local_512 = _e1356;
                                local_513 = ((_e1352 * _e1356) - (_e1353 * _e1355));
                                local_514 = ((_e1353 * _e1354) - (_e1351 * _e1356));
                                local_515 = ((_e1351 * _e1355) - (_e1352 * _e1354));
                                let _e1370 = (((_e1351 * _e1351) + (_e1352 * _e1352)) + (_e1353 * _e1353));
                                local_516 = _e1370;
                                let _e1375 = (((_e1351 * _e1354) + (_e1352 * _e1355)) + (_e1353 * _e1356));
                                local_517 = _e1375;
                                let _e1380 = (((_e1354 * _e1354) + (_e1355 * _e1355)) + (_e1356 * _e1356));
                                local_518 = _e1380;
                                let _e1383 = ((_e1370 * _e1380) - (_e1375 * _e1375));
                                local_519 = _e1383;
                                if (_e1383 > 0f) {
                                    let _e1385 = local_22;
                                    let _e1386 = (_e1385 > 0f);
                                    local_520 = _e1386;
                                    if _e1386 {
                                        let _e1387 = local_24;
                                        let _e1389 = local_24;
                                        let _e1391 = local_24;
                                        let _e1393 = (2f * _e1391[2]);
                                        let _e1394 = (_e1389[1] * -2f);
                                        let _e1401 = local_24;
                                        local_525 = (1f + ((_e1389[1] * _e1394) - (_e1391[2] * _e1393)));
                                        local_526 = ((_e1401[3] * _e1393) + -((_e1387[0] * _e1394)));
                                        local_527 = ((_e1401[3] * _e1394) + (_e1387[0] * _e1393));
                                        let _e1408 = (_e1391[2] * -2f);
                                        let _e1409 = (2f * _e1387[0]);
                                        local_528 = ((_e1401[3] * _e1408) + (_e1389[1] * _e1409));
                                        local_529 = (1f + ((_e1391[2] * _e1408) - (_e1387[0] * _e1409)));
                                        local_530 = ((_e1401[3] * _e1409) + -((_e1389[1] * _e1408)));
                                        let _e1421 = local_504;
                                        let _e1422 = local_513;
                                        let _e1424 = local_505;
                                        let _e1425 = local_514;
                                        let _e1428 = local_506;
                                        let _e1429 = local_515;
                                        let _e1431 = (((_e1421 * _e1422) + (_e1424 * _e1425)) + (_e1428 * _e1429));
                                        local_521 = _e1431;
                                        let _e1432 = local_504;
                                        let _e1433 = local_504;
                                        let _e1435 = local_505;
                                        let _e1436 = local_505;
                                        let _e1439 = local_506;
                                        let _e1440 = local_506;
                                        let _e1443 = local_513;
                                        let _e1444 = local_513;
                                        let _e1446 = local_514;
                                        let _e1447 = local_514;
                                        let _e1450 = local_515;
                                        let _e1451 = local_515;
                                        let _e1455 = sqrt(((((_e1432 * _e1433) + (_e1435 * _e1436)) + (_e1439 * _e1440)) * (((_e1443 * _e1444) + (_e1446 * _e1447)) + (_e1450 * _e1451))));
                                        local_522 = _e1455;
                                        let _e1456 = (0.001f * _e1455);
                                        local_523 = _e1456;
                                        let _e1457 = (_e1431 < 0f);
                                        local_524 = _e1457;
                                        if _e1457 {
                                            let _e1458 = local_521;
                                            phi_5279_ = -(_e1458);
                                        } else {
                                            phi_5279_ = _e1431;
                                        }
                                        let _e1461 = phi_5279_;
                                        let _e1462 = local_523;
                                        if (_e1461 >= _e1462) {
                                            phi_5290_ = _e1431;
                                        } else {
                                            let _e1464 = local_524;
                                            if _e1464 {
                                                let _e1465 = local_522;
                                                phi_5288_ = (_e1465 * -0.001f);
                                            } else {
                                                phi_5288_ = _e1456;
                                            }
                                            let _e1468 = phi_5288_;
                                            phi_5290_ = _e1468;
                                        }
                                        let _e1470 = phi_5290_;
                                        let _e1471 = local_94;
                                        let _e1472 = local_89;
                                        let _e1473 = (_e1471 - _e1472);
                                        let _e1474 = local_96;
                                        let _e1475 = local_91;
                                        let _e1476 = (_e1474 - _e1475);
                                        let _e1477 = local_99;
                                        let _e1478 = local_89;
                                        let _e1479 = (_e1477 - _e1478);
                                        let _e1480 = local_101;
                                        let _e1481 = local_91;
                                        let _e1482 = (_e1480 - _e1481);
                                        let _e1483 = local_525;
                                        let _e1484 = local_513;
                                        let _e1486 = local_526;
                                        let _e1487 = local_514;
                                        let _e1490 = local_527;
                                        let _e1491 = local_515;
                                        let _e1494 = ((((_e1483 * _e1484) + (_e1486 * _e1487)) + (_e1490 * _e1491)) / _e1470);
                                        let _e1495 = local_504;
                                        let _e1497 = local_525;
                                        let _e1499 = local_22;
                                        let _e1500 = (_e1499 * (_e1497 - (_e1495 * _e1494)));
                                        let _e1501 = local_505;
                                        let _e1503 = local_526;
                                        let _e1505 = local_22;
                                        let _e1506 = (_e1505 * (_e1503 - (_e1501 * _e1494)));
                                        let _e1507 = local_506;
                                        let _e1509 = local_527;
                                        let _e1511 = local_22;
                                        let _e1512 = (_e1511 * (_e1509 - (_e1507 * _e1494)));
                                        let _e1513 = local_507;
                                        let _e1515 = local_508;
                                        let _e1518 = local_509;
                                        let _e1520 = (((_e1500 * _e1513) + (_e1506 * _e1515)) + (_e1512 * _e1518));
                                        let _e1521 = local_510;
                                        let _e1523 = local_511;
                                        let _e1526 = local_512;
                                        let _e1528 = (((_e1500 * _e1521) + (_e1506 * _e1523)) + (_e1512 * _e1526));
                                        let _e1529 = local_518;
                                        let _e1531 = local_517;
                                        let _e1534 = local_519;
                                        let _e1535 = (((_e1520 * _e1529) - (_e1528 * _e1531)) / _e1534);
                                        let _e1536 = local_516;
                                        let _e1538 = local_517;
                                        let _e1541 = local_519;
                                        let _e1542 = (((_e1528 * _e1536) - (_e1520 * _e1538)) / _e1541);
                                        let _e1549 = local_528;
                                        let _e1550 = local_513;
                                        let _e1552 = local_529;
                                        let _e1553 = local_514;
                                        let _e1556 = local_530;
                                        let _e1557 = local_515;
                                        let _e1560 = ((((_e1549 * _e1550) + (_e1552 * _e1553)) + (_e1556 * _e1557)) / _e1470);
                                        let _e1561 = local_504;
                                        let _e1563 = local_528;
                                        let _e1565 = local_22;
                                        let _e1566 = (_e1565 * (_e1563 - (_e1561 * _e1560)));
                                        let _e1567 = local_505;
                                        let _e1569 = local_529;
                                        let _e1571 = local_22;
                                        let _e1572 = (_e1571 * (_e1569 - (_e1567 * _e1560)));
                                        let _e1573 = local_506;
                                        let _e1575 = local_530;
                                        let _e1577 = local_22;
                                        let _e1578 = (_e1577 * (_e1575 - (_e1573 * _e1560)));
                                        let _e1579 = local_507;
                                        let _e1581 = local_508;
                                        let _e1584 = local_509;
                                        let _e1586 = (((_e1566 * _e1579) + (_e1572 * _e1581)) + (_e1578 * _e1584));
                                        let _e1587 = local_510;
                                        let _e1589 = local_511;
                                        let _e1592 = local_512;
                                        let _e1594 = (((_e1566 * _e1587) + (_e1572 * _e1589)) + (_e1578 * _e1592));
                                        let _e1595 = local_518;
                                        let _e1597 = local_517;
                                        let _e1600 = local_519;
                                        let _e1601 = (((_e1586 * _e1595) - (_e1594 * _e1597)) / _e1600);
                                        let _e1602 = local_516;
                                        let _e1604 = local_517;
                                        let _e1607 = local_519;
                                        let _e1608 = (((_e1594 * _e1602) - (_e1586 * _e1604)) / _e1607);
                                        phi_5396_ = type_5(((_e1535 * _e1473) + (_e1542 * _e1479)), ((_e1535 * _e1476) + (_e1542 * _e1482)), ((_e1601 * _e1473) + (_e1608 * _e1479)), ((_e1601 * _e1476) + (_e1608 * _e1482)));
                                    } else {
                                        phi_5396_ = type_5();
                                    }
                                    let _e1617 = phi_5396_;
                                    let _e1618 = local_520;
                                    phi_5400_ = _e1617;
                                    phi_5401_ = select(true, false, _e1618);
                                } else {
                                    phi_5400_ = type_5();
                                    phi_5401_ = true;
                                }
                                let _e1621 = phi_5400_;
                                let _e1623 = phi_5401_;
                                if _e1623 {
                                    phi_5405_ = type_5(0f, 0f, 0f, 0f);
                                } else {
                                    phi_5405_ = _e1621;
                                }
                                let _e1625 = phi_5405_;
                                phi_1129_ = _e1625;
                            } else {
                                phi_1129_ = type_5(0f, 0f, 0f, 0f);
                            }
                            let _e1627 = phi_1129_;
                            local_102 = _e1627;
                            let _e1628 = local_84;
                            if (_e1628 == 4294967295u) {
                                phi_5891_ = _e1244;
                                phi_2597_ = type_5();
                                phi_2598_ = true;
                            } else {
                                let _e1630 = local_84;
                                let _e1631 = local_25;
                                let _e1632 = (_e1630 >= _e1631);
                                if _e1632 {
                                    phi_5892_ = _e1244;
                                    phi_2596_ = type_5();
                                } else {
                                    let _e1633 = local_84;
                                    let _e1634 = (_e1633 * 4u);
                                    local_103 = _e1634;
                                    let _e1635 = local_5;
                                    if (_e1634 < _e1635) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e1637 = local_103;
                                    let _e1640 = global_8.member[_e1637];
                                    local_104 = _e1640;
                                    let _e1641 = local_103;
                                    let _e1642 = (_e1641 + 1u);
                                    local_105 = _e1642;
                                    let _e1643 = local_5;
                                    if (_e1642 < _e1643) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e1645 = local_105;
                                    let _e1648 = global_8.member[_e1645];
                                    local_106 = _e1648;
                                    let _e1649 = local_103;
                                    let _e1650 = (_e1649 + 2u);
                                    local_107 = _e1650;
                                    let _e1651 = local_5;
                                    if (_e1650 < _e1651) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e1653 = local_107;
                                    let _e1656 = global_8.member[_e1653];
                                    local_108 = _e1656;
                                    let _e1657 = local_103;
                                    let _e1658 = (_e1657 + 3u);
                                    local_109 = _e1658;
                                    let _e1659 = local_5;
                                    if (_e1658 < _e1659) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e1661 = local_109;
                                    let _e1664 = global_8.member[_e1661];
                                    local_110 = _e1664;
                                    let _e1665 = local_106;
                                    if (_e1665 == 0u) {
                                        phi_5894_ = _e1244;
                                        phi_2590_ = type_5();
                                        phi_2591_ = true;
                                    } else {
                                        let _e1667 = local_108;
                                        let _e1668 = (_e1667 == 0u);
                                        if _e1668 {
                                            phi_5895_ = _e1244;
                                            phi_2589_ = type_5();
                                        } else {
                                            let _e1669 = local_110;
                                            let _e1672 = ((_e1669 >> bitcast<u32>(8u)) & 31u);
                                            local_559 = select(_e1672, 1u, (_e1672 == 0u));
                                            let _e1675 = local_110;
                                            let _e1679 = local_110;
                                            let _e1683 = local_104;
                                            let _e1684 = local_106;
                                            let _e1685 = local_108;
                                            let _e1686 = type_22(_e1683, _e1684, _e1685, ((_e1675 >> bitcast<u32>(1u)) & 3u), ((_e1679 >> bitcast<u32>(3u)) & 3u));
                                            let _e1687 = local_106;
                                            let _e1688 = f32(_e1687);
                                            local_111 = _e1688;
                                            let _e1689 = local_75;
                                            if ((bitcast<u32>((_e1689 * _e1688)) & 2139095040u) != 2139095040u) {
                                                let _e1694 = local_108;
                                                let _e1696 = local_74;
                                                phi_1239_ = select(true, false, ((bitcast<u32>((_e1696 * f32(_e1694))) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_1239_ = true;
                                            }
                                            let _e1703 = phi_1239_;
                                            let _e1704 = local_74;
                                            local_560 = select(_e1704, 0f, _e1703);
                                            let _e1706 = local_75;
                                            local_561 = select(_e1706, 0f, _e1703);
                                            let _e1708 = local_102;
                                            local_112 = _e1708.member;
                                            let _e1710 = local_111;
                                            let _e1711 = (_e1708.member * _e1710);
                                            let _e1712 = local_102;
                                            local_113 = _e1712.member_1;
                                            let _e1714 = local_108;
                                            let _e1715 = f32(_e1714);
                                            let _e1716 = (_e1712.member_1 * _e1715);
                                            let _e1717 = local_102;
                                            local_114 = _e1717.member_2;
                                            let _e1719 = local_111;
                                            let _e1720 = (_e1717.member_2 * _e1719);
                                            let _e1721 = local_102;
                                            local_115 = _e1721.member_3;
                                            let _e1723 = (_e1721.member_3 * _e1715);
                                            let _e1727 = sqrt(((_e1711 * _e1711) + (_e1716 * _e1716)));
                                            local_116 = _e1727;
                                            let _e1731 = sqrt(((_e1720 * _e1720) + (_e1723 * _e1723)));
                                            local_117 = _e1731;
                                            let _e1733 = select(_e1731, _e1727, (_e1727 > _e1731));
                                            local_562 = _e1733;
                                            if (_e1733 > 1f) {
                                                let _e1735 = local_562;
                                                phi_1278_ = !(((bitcast<u32>(_e1735) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_1278_ = true;
                                            }
                                            let _e1741 = phi_1278_;
                                            local_118 = _e1741;
                                            if _e1741 {
                                                phi_1374_ = 1u;
                                                phi_1375_ = 1u;
                                            } else {
                                                let _e1742 = local_116;
                                                let _e1743 = local_117;
                                                if (_e1742 >= _e1743) {
                                                    let _e1783 = local_117;
                                                    let _e1785 = local_117;
                                                    let _e1787 = ceil(select(8f, _e1785, (_e1783 < 8f)));
                                                    local_119 = _e1787;
                                                    if (_e1787 < 1f) {
                                                        phi_1304_ = 1u;
                                                    } else {
                                                        let _e1789 = local_119;
                                                        let _e1791 = local_119;
                                                        let _e1794 = local_119;
                                                        phi_1304_ = select(select(u32(_e1789), 0u, !((_e1791 >= 0f))), 4294967295u, (_e1794 > 4294967000f));
                                                    }
                                                    let _e1799 = phi_1304_;
                                                    local_120 = _e1799;
                                                    if (_e1799 == 0u) {
                                                        phi_5975_ = true;
                                                        break;
                                                    }
                                                    let _e1801 = local_120;
                                                    let _e1803 = f32((64u / _e1801));
                                                    let _e1804 = local_116;
                                                    let _e1806 = local_116;
                                                    let _e1808 = ceil(select(_e1803, _e1806, (_e1804 < _e1803)));
                                                    local_121 = _e1808;
                                                    if (_e1808 < 1f) {
                                                        phi_1328_ = 1u;
                                                    } else {
                                                        let _e1810 = local_121;
                                                        let _e1812 = local_121;
                                                        let _e1815 = local_121;
                                                        phi_1328_ = select(select(u32(_e1810), 0u, !((_e1812 >= 0f))), 4294967295u, (_e1815 > 4294967000f));
                                                    }
                                                    let _e1820 = phi_1328_;
                                                    phi_1372_ = _e1799;
                                                    phi_1373_ = _e1820;
                                                } else {
                                                    let _e1745 = local_116;
                                                    let _e1747 = local_116;
                                                    let _e1749 = ceil(select(8f, _e1747, (_e1745 < 8f)));
                                                    local_122 = _e1749;
                                                    if (_e1749 < 1f) {
                                                        phi_1347_ = 1u;
                                                    } else {
                                                        let _e1751 = local_122;
                                                        let _e1753 = local_122;
                                                        let _e1756 = local_122;
                                                        phi_1347_ = select(select(u32(_e1751), 0u, !((_e1753 >= 0f))), 4294967295u, (_e1756 > 4294967000f));
                                                    }
                                                    let _e1761 = phi_1347_;
                                                    local_123 = _e1761;
                                                    if (_e1761 == 0u) {
                                                        phi_5975_ = true;
                                                        break;
                                                    }
                                                    let _e1763 = local_123;
                                                    let _e1765 = f32((64u / _e1763));
                                                    let _e1766 = local_117;
                                                    let _e1768 = local_117;
                                                    let _e1770 = ceil(select(_e1765, _e1768, (_e1766 < _e1765)));
                                                    local_124 = _e1770;
                                                    if (_e1770 < 1f) {
                                                        phi_1371_ = 1u;
                                                    } else {
                                                        let _e1772 = local_124;
                                                        let _e1774 = local_124;
                                                        let _e1777 = local_124;
                                                        phi_1371_ = select(select(u32(_e1772), 0u, !((_e1774 >= 0f))), 4294967295u, (_e1777 > 4294967000f));
                                                    }
                                                    let _e1782 = phi_1371_;
                                                    phi_1372_ = _e1782;
                                                    phi_1373_ = _e1761;
                                                }
                                                let _e1822 = phi_1372_;
                                                let _e1824 = phi_1373_;
                                                phi_1374_ = _e1822;
                                                phi_1375_ = _e1824;
                                            }
                                            let _e1826 = phi_1374_;
                                            let _e1828 = phi_1375_;
                                            local_125 = _e1826;
                                            local_126 = _e1828;
                                            let _e1829 = local_118;
                                            if _e1829 {
                                                phi_1388_ = 1f;
                                            } else {
                                                let _e1830 = local_126;
                                                let _e1832 = local_116;
                                                let _e1833 = (_e1832 / f32(_e1830));
                                                let _e1834 = local_125;
                                                let _e1836 = local_117;
                                                let _e1837 = (_e1836 / f32(_e1834));
                                                phi_1388_ = select(_e1837, _e1833, (_e1833 > _e1837));
                                            }
                                            let _e1841 = phi_1388_;
                                            local_127 = _e1841;
                                            if (_e1841 > 1f) {
                                                let _e1843 = local_127;
                                                let _e1844 = bitcast<u32>(_e1843);
                                                let _e1853 = (bitcast<f32>(((_e1844 & 8388607u) | 1065353216u)) - 1f);
                                                phi_1409_ = (f32((bitcast<i32>(((_e1844 >> bitcast<u32>(23i)) & 255u)) - 127i)) + (_e1853 * (1.4208645f + (_e1853 * (-0.5772506f + (_e1853 * 0.1563861f))))));
                                            } else {
                                                phi_1409_ = 0f;
                                            }
                                            let _e1862 = phi_1409_;
                                            local_128 = _e1862;
                                            let _e1863 = local_559;
                                            let _e1864 = (_e1863 - 1u);
                                            local_129 = _e1864;
                                            let _e1865 = floor(_e1862);
                                            let _e1871 = select(select(u32(_e1865), 0u, !((_e1865 >= 0f))), 4294967295u, (_e1865 > 4294967000f));
                                            local_130 = _e1871;
                                            let _e1872 = (_e1871 >= _e1864);
                                            local_131 = _e1872;
                                            if _e1872 {
                                                phi_1425_ = 0f;
                                            } else {
                                                let _e1873 = local_130;
                                                let _e1875 = local_128;
                                                phi_1425_ = (_e1875 - f32(_e1873));
                                            }
                                            let _e1878 = phi_1425_;
                                            local_132 = _e1878;
                                            let _e1879 = local_131;
                                            let _e1880 = local_129;
                                            let _e1881 = local_130;
                                            local_563 = select(_e1881, _e1880, _e1879);
                                            local_564 = select(1u, 2u, (_e1878 > 0f));
                                            phi_5506_ = 0u;
                                            phi_5507_ = _e1686;
                                            loop {
                                                let _e1886 = phi_5506_;
                                                let _e1888 = phi_5507_;
                                                local_531 = _e1886;
                                                local_532 = _e1888;
                                                local_624 = _e1888;
                                                let _e1889 = local_531;
                                                let _e1890 = local_563;
                                                let _e1891 = (_e1889 < _e1890);
                                                local_533 = _e1891;
                                                if _e1891 {
                                                    let _e1892 = local_532;
                                                    local_534 = _e1892.member_1;
                                                    let _e1894 = local_532;
                                                    local_535 = _e1894.member_2;
                                                    let _e1897 = local_532;
                                                    let _e1900 = local_532;
                                                    local_536 = type_22((_e1897.member + (_e1892.member_1 * _e1894.member_2)), _e1900.member_1, _e1900.member_2, _e1900.member_3, _e1900.member_4);
                                                    if (_e1892.member_1 > 1u) {
                                                        let _e1908 = local_534;
                                                        phi_5524_ = (_e1908 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5524_ = 1u;
                                                    }
                                                    let _e1912 = phi_5524_;
                                                    let _e1913 = local_536;
                                                    local_537 = type_22(_e1913.member, _e1912, _e1913.member_2, _e1913.member_3, _e1913.member_4);
                                                    let _e1920 = local_535;
                                                    if (_e1920 > 1u) {
                                                        let _e1922 = local_535;
                                                        phi_5533_ = (_e1922 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5533_ = 1u;
                                                    }
                                                    let _e1926 = phi_5533_;
                                                    let _e1927 = local_537;
                                                    let _e1934 = local_531;
                                                    phi_5538_ = (_e1934 + 1u);
                                                    phi_5539_ = type_22(_e1927.member, _e1927.member_1, _e1926, _e1927.member_3, _e1927.member_4);
                                                } else {
                                                    phi_5538_ = u32();
                                                    phi_5539_ = type_22();
                                                }
                                                let _e1937 = phi_5538_;
                                                let _e1939 = phi_5539_;
                                                continue;
                                                continuing {
                                                    let _e1940 = local_533;
                                                    phi_5506_ = _e1937;
                                                    phi_5507_ = _e1939;
                                                    break if !(_e1940);
                                                }
                                            }
                                            let _e1942 = local_563;
                                            let _e1943 = local_564;
                                            local_133 = ((_e1942 + _e1943) - 1u);
                                            phi_5545_ = 0u;
                                            phi_5546_ = _e1686;
                                            loop {
                                                let _e1947 = phi_5545_;
                                                let _e1949 = phi_5546_;
                                                local_538 = _e1947;
                                                local_539 = _e1949;
                                                local_625 = _e1949;
                                                let _e1950 = local_538;
                                                let _e1951 = local_133;
                                                let _e1952 = (_e1950 < _e1951);
                                                local_540 = _e1952;
                                                if _e1952 {
                                                    let _e1953 = local_539;
                                                    local_541 = _e1953.member_1;
                                                    let _e1955 = local_539;
                                                    local_542 = _e1955.member_2;
                                                    let _e1958 = local_539;
                                                    let _e1961 = local_539;
                                                    local_543 = type_22((_e1958.member + (_e1953.member_1 * _e1955.member_2)), _e1961.member_1, _e1961.member_2, _e1961.member_3, _e1961.member_4);
                                                    if (_e1953.member_1 > 1u) {
                                                        let _e1969 = local_541;
                                                        phi_5563_ = (_e1969 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5563_ = 1u;
                                                    }
                                                    let _e1973 = phi_5563_;
                                                    let _e1974 = local_543;
                                                    local_544 = type_22(_e1974.member, _e1973, _e1974.member_2, _e1974.member_3, _e1974.member_4);
                                                    let _e1981 = local_542;
                                                    if (_e1981 > 1u) {
                                                        let _e1983 = local_542;
                                                        phi_5572_ = (_e1983 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5572_ = 1u;
                                                    }
                                                    let _e1987 = phi_5572_;
                                                    let _e1988 = local_544;
                                                    let _e1995 = local_538;
                                                    phi_5577_ = (_e1995 + 1u);
                                                    phi_5578_ = type_22(_e1988.member, _e1988.member_1, _e1987, _e1988.member_3, _e1988.member_4);
                                                } else {
                                                    phi_5577_ = u32();
                                                    phi_5578_ = type_22();
                                                }
                                                let _e1998 = phi_5577_;
                                                let _e2000 = phi_5578_;
                                                continue;
                                                continuing {
                                                    let _e2001 = local_540;
                                                    phi_5545_ = _e1998;
                                                    phi_5546_ = _e2000;
                                                    break if !(_e2001);
                                                }
                                            }
                                            let _e2003 = local_118;
                                            if _e2003 {
                                                let _e2004 = local_110;
                                                phi_1441_ = ((_e2004 & 1u) != 0u);
                                            } else {
                                                phi_1441_ = false;
                                            }
                                            let _e2008 = phi_1441_;
                                            local_134 = _e2008;
                                            phi_5751_ = _e1244;
                                            phi_1444_ = 0u;
                                            phi_1447_ = type_5(0f, 0f, 0f, 0f);
                                            loop {
                                                let _e2010 = phi_5751_;
                                                let _e2012 = phi_1444_;
                                                let _e2014 = phi_1447_;
                                                local_135 = _e2012;
                                                local_136 = _e2014;
                                                let _e2015 = local_135;
                                                let _e2016 = local_126;
                                                let _e2017 = (_e2015 < _e2016);
                                                local_137 = _e2017;
                                                if _e2017 {
                                                    let _e2018 = local_135;
                                                    let _e2021 = local_126;
                                                    local_138 = (((f32(_e2018) + 0.5f) / f32(_e2021)) - 0.5f);
                                                    phi_5750_ = _e2010;
                                                    phi_1461_ = 0u;
                                                    phi_1464_ = _e2014;
                                                    loop {
                                                        let _e2026 = phi_5750_;
                                                        let _e2028 = phi_1461_;
                                                        let _e2030 = phi_1464_;
                                                        local_139 = _e2028;
                                                        local_627 = _e2030;
                                                        let _e2031 = local_139;
                                                        let _e2032 = local_125;
                                                        let _e2033 = (_e2031 < _e2032);
                                                        local_140 = _e2033;
                                                        if _e2033 {
                                                            let _e2034 = local_139;
                                                            let _e2037 = local_125;
                                                            let _e2040 = (((f32(_e2034) + 0.5f) / f32(_e2037)) - 0.5f);
                                                            let _e2041 = local_138;
                                                            let _e2042 = local_112;
                                                            let _e2044 = local_561;
                                                            let _e2046 = local_114;
                                                            local_141 = ((_e2044 + (_e2041 * _e2042)) + (_e2040 * _e2046));
                                                            let _e2049 = local_138;
                                                            let _e2050 = local_113;
                                                            let _e2052 = local_560;
                                                            let _e2054 = local_115;
                                                            local_142 = ((_e2052 + (_e2049 * _e2050)) + (_e2040 * _e2054));
                                                            phi_1490_ = 0u;
                                                            phi_1493_ = _e2030;
                                                            loop {
                                                                let _e2058 = phi_1490_;
                                                                let _e2060 = phi_1493_;
                                                                local_143 = _e2058;
                                                                local_144 = _e2060;
                                                                local_626 = _e2060;
                                                                let _e2061 = local_143;
                                                                let _e2062 = local_564;
                                                                let _e2063 = (_e2061 < _e2062);
                                                                local_145 = _e2063;
                                                                if _e2063 {
                                                                    let _e2064 = local_143;
                                                                    if (_e2064 == 0u) {
                                                                        let _e2066 = local_132;
                                                                        let _e5520 = local_624;
                                                                        phi_1506_ = _e5520;
                                                                        phi_1507_ = (1f - _e2066);
                                                                    } else {
                                                                        let _e5522 = local_625;
                                                                        phi_1506_ = _e5522;
                                                                        phi_1507_ = _e1878;
                                                                    }
                                                                    let _e2069 = phi_1506_;
                                                                    let _e2071 = phi_1507_;
                                                                    local_146 = _e2069;
                                                                    local_147 = _e2071;
                                                                    let _e2072 = local_134;
                                                                    let _e2073 = select(0.5f, 0f, _e2072);
                                                                    local_148 = _e2069.member_1;
                                                                    let _e2076 = local_141;
                                                                    let _e2078 = ((_e2076 * f32(_e2069.member_1)) - _e2073);
                                                                    local_149 = _e2078;
                                                                    local_150 = _e2069.member_2;
                                                                    let _e2081 = local_142;
                                                                    let _e2083 = ((_e2081 * f32(_e2069.member_2)) - _e2073);
                                                                    local_151 = _e2083;
                                                                    local_152 = floor(_e2078);
                                                                    local_153 = floor(_e2083);
                                                                    let _e2086 = local_134;
                                                                    if _e2086 {
                                                                        phi_1527_ = 0f;
                                                                        phi_1528_ = 0f;
                                                                    } else {
                                                                        let _e2087 = local_149;
                                                                        let _e2088 = local_152;
                                                                        let _e2090 = local_151;
                                                                        let _e2091 = local_153;
                                                                        phi_1527_ = (_e2090 - _e2091);
                                                                        phi_1528_ = (_e2087 - _e2088);
                                                                    }
                                                                    let _e2094 = phi_1527_;
                                                                    let _e2096 = phi_1528_;
                                                                    local_154 = _e2094;
                                                                    local_155 = _e2096;
                                                                    let _e2097 = local_152;
                                                                    let _e2099 = local_152;
                                                                    let _e2102 = local_152;
                                                                    let _e2106 = local_152;
                                                                    let _e2107 = local_152;
                                                                    let _e2109 = select(0i, select(select(i32(_e2097), i32(-2147483648), !((_e2099 >= -2147483600f))), 2147483647i, (_e2102 > 2147483500f)), (_e2106 == _e2107));
                                                                    local_156 = _e2109;
                                                                    let _e2110 = local_153;
                                                                    let _e2112 = local_153;
                                                                    let _e2115 = local_153;
                                                                    let _e2119 = local_153;
                                                                    let _e2120 = local_153;
                                                                    let _e2122 = select(0i, select(select(i32(_e2110), i32(-2147483648), !((_e2112 >= -2147483600f))), 2147483647i, (_e2115 > 2147483500f)), (_e2119 == _e2120));
                                                                    local_157 = _e2122;
                                                                    let _e2123 = local_146;
                                                                    local_158 = _e2123.member_3;
                                                                    let _e2125 = local_148;
                                                                    local_159 = bitcast<i32>(_e2125);
                                                                    let _e2127 = (_e2123.member_3 == 1u);
                                                                    local_160 = _e2127;
                                                                    if _e2127 {
                                                                        let _e2181 = local_156;
                                                                        if (_e2181 < 0i) {
                                                                            phi_1564_ = 0i;
                                                                        } else {
                                                                            let _e2183 = local_156;
                                                                            let _e2184 = local_159;
                                                                            if (_e2183 >= _e2184) {
                                                                                let _e2186 = local_159;
                                                                                phi_1563_ = (_e2186 - 1i);
                                                                            } else {
                                                                                phi_1563_ = _e2109;
                                                                            }
                                                                            let _e2189 = phi_1563_;
                                                                            phi_1564_ = _e2189;
                                                                        }
                                                                        let _e2191 = phi_1564_;
                                                                        phi_1624_ = _e2191;
                                                                    } else {
                                                                        let _e2128 = local_158;
                                                                        if (_e2128 == 2u) {
                                                                            let _e2150 = local_159;
                                                                            let _e2151 = (2i * _e2150);
                                                                            local_161 = _e2151;
                                                                            let _e2152 = (_e2151 == 0i);
                                                                            local_162 = _e2152;
                                                                            if _e2152 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2153 = local_161;
                                                                            let _e2154 = (_e2153 == -1i);
                                                                            local_163 = _e2154;
                                                                            let _e2155 = local_156;
                                                                            if (_e2154 && (_e2155 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2158 = local_156;
                                                                            let _e2159 = local_161;
                                                                            let _e2161 = local_161;
                                                                            local_164 = ((_e2158 % _e2159) + _e2161);
                                                                            let _e2163 = local_162;
                                                                            if _e2163 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2164 = local_164;
                                                                            let _e2166 = local_163;
                                                                            if (_e2166 && (_e2164 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2168 = local_164;
                                                                            let _e2169 = local_161;
                                                                            let _e2170 = (_e2168 % _e2169);
                                                                            local_165 = _e2170;
                                                                            let _e2171 = local_159;
                                                                            if (_e2170 < _e2171) {
                                                                                phi_1599_ = _e2170;
                                                                            } else {
                                                                                let _e2173 = local_161;
                                                                                let _e2175 = local_165;
                                                                                phi_1599_ = ((_e2173 - 1i) - _e2175);
                                                                            }
                                                                            let _e2178 = phi_1599_;
                                                                            phi_1623_ = _e2178;
                                                                        } else {
                                                                            let _e2130 = local_159;
                                                                            let _e2131 = (_e2130 == 0i);
                                                                            local_166 = _e2131;
                                                                            if _e2131 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2132 = local_159;
                                                                            let _e2133 = (_e2132 == -1i);
                                                                            local_167 = _e2133;
                                                                            let _e2134 = local_156;
                                                                            if (_e2133 && (_e2134 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2137 = local_156;
                                                                            let _e2138 = local_159;
                                                                            let _e2140 = local_159;
                                                                            local_168 = ((_e2137 % _e2138) + _e2140);
                                                                            let _e2142 = local_166;
                                                                            if _e2142 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2143 = local_168;
                                                                            let _e2145 = local_167;
                                                                            if (_e2145 && (_e2143 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2147 = local_168;
                                                                            let _e2148 = local_159;
                                                                            phi_1623_ = (_e2147 % _e2148);
                                                                        }
                                                                        let _e2180 = phi_1623_;
                                                                        phi_1624_ = _e2180;
                                                                    }
                                                                    let _e2193 = phi_1624_;
                                                                    local_169 = bitcast<u32>(_e2193);
                                                                    let _e2195 = local_156;
                                                                    let _e2196 = (_e2195 + 1i);
                                                                    local_170 = _e2196;
                                                                    let _e2197 = local_160;
                                                                    if _e2197 {
                                                                        let _e2251 = local_170;
                                                                        if (_e2251 < 0i) {
                                                                            phi_1644_ = 0i;
                                                                        } else {
                                                                            let _e2253 = local_170;
                                                                            let _e2254 = local_159;
                                                                            if (_e2253 >= _e2254) {
                                                                                let _e2256 = local_159;
                                                                                phi_1643_ = (_e2256 - 1i);
                                                                            } else {
                                                                                phi_1643_ = _e2196;
                                                                            }
                                                                            let _e2259 = phi_1643_;
                                                                            phi_1644_ = _e2259;
                                                                        }
                                                                        let _e2261 = phi_1644_;
                                                                        phi_1704_ = _e2261;
                                                                    } else {
                                                                        let _e2198 = local_158;
                                                                        if (_e2198 == 2u) {
                                                                            let _e2220 = local_159;
                                                                            let _e2221 = (2i * _e2220);
                                                                            local_171 = _e2221;
                                                                            let _e2222 = (_e2221 == 0i);
                                                                            local_172 = _e2222;
                                                                            if _e2222 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2223 = local_171;
                                                                            let _e2224 = (_e2223 == -1i);
                                                                            local_173 = _e2224;
                                                                            let _e2225 = local_170;
                                                                            if (_e2224 && (_e2225 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2228 = local_170;
                                                                            let _e2229 = local_171;
                                                                            let _e2231 = local_171;
                                                                            local_174 = ((_e2228 % _e2229) + _e2231);
                                                                            let _e2233 = local_172;
                                                                            if _e2233 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2234 = local_174;
                                                                            let _e2236 = local_173;
                                                                            if (_e2236 && (_e2234 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2238 = local_174;
                                                                            let _e2239 = local_171;
                                                                            let _e2240 = (_e2238 % _e2239);
                                                                            local_175 = _e2240;
                                                                            let _e2241 = local_159;
                                                                            if (_e2240 < _e2241) {
                                                                                phi_1679_ = _e2240;
                                                                            } else {
                                                                                let _e2243 = local_171;
                                                                                let _e2245 = local_175;
                                                                                phi_1679_ = ((_e2243 - 1i) - _e2245);
                                                                            }
                                                                            let _e2248 = phi_1679_;
                                                                            phi_1703_ = _e2248;
                                                                        } else {
                                                                            let _e2200 = local_159;
                                                                            let _e2201 = (_e2200 == 0i);
                                                                            local_176 = _e2201;
                                                                            if _e2201 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2202 = local_159;
                                                                            let _e2203 = (_e2202 == -1i);
                                                                            local_177 = _e2203;
                                                                            let _e2204 = local_170;
                                                                            if (_e2203 && (_e2204 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2207 = local_170;
                                                                            let _e2208 = local_159;
                                                                            let _e2210 = local_159;
                                                                            local_178 = ((_e2207 % _e2208) + _e2210);
                                                                            let _e2212 = local_176;
                                                                            if _e2212 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2213 = local_178;
                                                                            let _e2215 = local_177;
                                                                            if (_e2215 && (_e2213 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2217 = local_178;
                                                                            let _e2218 = local_159;
                                                                            phi_1703_ = (_e2217 % _e2218);
                                                                        }
                                                                        let _e2250 = phi_1703_;
                                                                        phi_1704_ = _e2250;
                                                                    }
                                                                    let _e2263 = phi_1704_;
                                                                    local_179 = bitcast<u32>(_e2263);
                                                                    let _e2265 = local_146;
                                                                    local_180 = _e2265.member_4;
                                                                    let _e2267 = local_150;
                                                                    local_181 = bitcast<i32>(_e2267);
                                                                    let _e2269 = (_e2265.member_4 == 1u);
                                                                    local_182 = _e2269;
                                                                    if _e2269 {
                                                                        let _e2323 = local_157;
                                                                        if (_e2323 < 0i) {
                                                                            phi_1723_ = 0i;
                                                                        } else {
                                                                            let _e2325 = local_157;
                                                                            let _e2326 = local_181;
                                                                            if (_e2325 >= _e2326) {
                                                                                let _e2328 = local_181;
                                                                                phi_1722_ = (_e2328 - 1i);
                                                                            } else {
                                                                                phi_1722_ = _e2122;
                                                                            }
                                                                            let _e2331 = phi_1722_;
                                                                            phi_1723_ = _e2331;
                                                                        }
                                                                        let _e2333 = phi_1723_;
                                                                        phi_1783_ = _e2333;
                                                                    } else {
                                                                        let _e2270 = local_180;
                                                                        if (_e2270 == 2u) {
                                                                            let _e2292 = local_181;
                                                                            let _e2293 = (2i * _e2292);
                                                                            local_183 = _e2293;
                                                                            let _e2294 = (_e2293 == 0i);
                                                                            local_184 = _e2294;
                                                                            if _e2294 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2295 = local_183;
                                                                            let _e2296 = (_e2295 == -1i);
                                                                            local_185 = _e2296;
                                                                            let _e2297 = local_157;
                                                                            if (_e2296 && (_e2297 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2300 = local_157;
                                                                            let _e2301 = local_183;
                                                                            let _e2303 = local_183;
                                                                            local_186 = ((_e2300 % _e2301) + _e2303);
                                                                            let _e2305 = local_184;
                                                                            if _e2305 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2306 = local_186;
                                                                            let _e2308 = local_185;
                                                                            if (_e2308 && (_e2306 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2310 = local_186;
                                                                            let _e2311 = local_183;
                                                                            let _e2312 = (_e2310 % _e2311);
                                                                            local_187 = _e2312;
                                                                            let _e2313 = local_181;
                                                                            if (_e2312 < _e2313) {
                                                                                phi_1758_ = _e2312;
                                                                            } else {
                                                                                let _e2315 = local_183;
                                                                                let _e2317 = local_187;
                                                                                phi_1758_ = ((_e2315 - 1i) - _e2317);
                                                                            }
                                                                            let _e2320 = phi_1758_;
                                                                            phi_1782_ = _e2320;
                                                                        } else {
                                                                            let _e2272 = local_181;
                                                                            let _e2273 = (_e2272 == 0i);
                                                                            local_188 = _e2273;
                                                                            if _e2273 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2274 = local_181;
                                                                            let _e2275 = (_e2274 == -1i);
                                                                            local_189 = _e2275;
                                                                            let _e2276 = local_157;
                                                                            if (_e2275 && (_e2276 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2279 = local_157;
                                                                            let _e2280 = local_181;
                                                                            let _e2282 = local_181;
                                                                            local_190 = ((_e2279 % _e2280) + _e2282);
                                                                            let _e2284 = local_188;
                                                                            if _e2284 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2285 = local_190;
                                                                            let _e2287 = local_189;
                                                                            if (_e2287 && (_e2285 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2289 = local_190;
                                                                            let _e2290 = local_181;
                                                                            phi_1782_ = (_e2289 % _e2290);
                                                                        }
                                                                        let _e2322 = phi_1782_;
                                                                        phi_1783_ = _e2322;
                                                                    }
                                                                    let _e2335 = phi_1783_;
                                                                    local_191 = bitcast<u32>(_e2335);
                                                                    let _e2337 = local_157;
                                                                    let _e2338 = (_e2337 + 1i);
                                                                    local_192 = _e2338;
                                                                    let _e2339 = local_182;
                                                                    if _e2339 {
                                                                        let _e2393 = local_192;
                                                                        if (_e2393 < 0i) {
                                                                            phi_1803_ = 0i;
                                                                        } else {
                                                                            let _e2395 = local_192;
                                                                            let _e2396 = local_181;
                                                                            if (_e2395 >= _e2396) {
                                                                                let _e2398 = local_181;
                                                                                phi_1802_ = (_e2398 - 1i);
                                                                            } else {
                                                                                phi_1802_ = _e2338;
                                                                            }
                                                                            let _e2401 = phi_1802_;
                                                                            phi_1803_ = _e2401;
                                                                        }
                                                                        let _e2403 = phi_1803_;
                                                                        phi_1863_ = _e2403;
                                                                    } else {
                                                                        let _e2340 = local_180;
                                                                        if (_e2340 == 2u) {
                                                                            let _e2362 = local_181;
                                                                            let _e2363 = (2i * _e2362);
                                                                            local_193 = _e2363;
                                                                            let _e2364 = (_e2363 == 0i);
                                                                            local_194 = _e2364;
                                                                            if _e2364 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2365 = local_193;
                                                                            let _e2366 = (_e2365 == -1i);
                                                                            local_195 = _e2366;
                                                                            let _e2367 = local_192;
                                                                            if (_e2366 && (_e2367 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2370 = local_192;
                                                                            let _e2371 = local_193;
                                                                            let _e2373 = local_193;
                                                                            local_196 = ((_e2370 % _e2371) + _e2373);
                                                                            let _e2375 = local_194;
                                                                            if _e2375 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2376 = local_196;
                                                                            let _e2378 = local_195;
                                                                            if (_e2378 && (_e2376 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2380 = local_196;
                                                                            let _e2381 = local_193;
                                                                            let _e2382 = (_e2380 % _e2381);
                                                                            local_197 = _e2382;
                                                                            let _e2383 = local_181;
                                                                            if (_e2382 < _e2383) {
                                                                                phi_1838_ = _e2382;
                                                                            } else {
                                                                                let _e2385 = local_193;
                                                                                let _e2387 = local_197;
                                                                                phi_1838_ = ((_e2385 - 1i) - _e2387);
                                                                            }
                                                                            let _e2390 = phi_1838_;
                                                                            phi_1862_ = _e2390;
                                                                        } else {
                                                                            let _e2342 = local_181;
                                                                            let _e2343 = (_e2342 == 0i);
                                                                            local_198 = _e2343;
                                                                            if _e2343 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2344 = local_181;
                                                                            let _e2345 = (_e2344 == -1i);
                                                                            local_199 = _e2345;
                                                                            let _e2346 = local_192;
                                                                            if (_e2345 && (_e2346 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2349 = local_192;
                                                                            let _e2350 = local_181;
                                                                            let _e2352 = local_181;
                                                                            local_200 = ((_e2349 % _e2350) + _e2352);
                                                                            let _e2354 = local_198;
                                                                            if _e2354 {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2355 = local_200;
                                                                            let _e2357 = local_199;
                                                                            if (_e2357 && (_e2355 == i32(-2147483648))) {
                                                                                phi_5704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2359 = local_200;
                                                                            let _e2360 = local_181;
                                                                            phi_1862_ = (_e2359 % _e2360);
                                                                        }
                                                                        let _e2392 = phi_1862_;
                                                                        phi_1863_ = _e2392;
                                                                    }
                                                                    let _e2405 = phi_1863_;
                                                                    local_201 = bitcast<u32>(_e2405);
                                                                    let _e2407 = local_146;
                                                                    local_202 = _e2407.member;
                                                                    let _e2409 = local_191;
                                                                    let _e2410 = local_148;
                                                                    let _e2412 = (_e2407.member + (_e2409 * _e2410));
                                                                    local_203 = _e2412;
                                                                    let _e2413 = local_169;
                                                                    let _e2415 = ((_e2412 + _e2413) * 2u);
                                                                    local_204 = _e2415;
                                                                    let _e2416 = local_6;
                                                                    if (_e2415 < _e2416) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2418 = local_204;
                                                                    let _e2421 = global_9.member[_e2418];
                                                                    local_205 = _e2421;
                                                                    let _e2422 = local_204;
                                                                    let _e2423 = (_e2422 + 1u);
                                                                    local_206 = _e2423;
                                                                    let _e2424 = local_6;
                                                                    if (_e2423 < _e2424) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2426 = local_206;
                                                                    let _e2429 = global_9.member[_e2426];
                                                                    local_207 = _e2429;
                                                                    let _e2430 = local_205;
                                                                    let _e2431 = (_e2430 & 65535u);
                                                                    local_565 = select(-1f, 1f, ((_e2431 & 32768u) == 0u));
                                                                    let _e2437 = ((_e2431 >> bitcast<u32>(10i)) & 31u);
                                                                    local_208 = _e2437;
                                                                    local_209 = (_e2431 & 1023u);
                                                                    if (_e2437 == 0u) {
                                                                        let _e2459 = local_209;
                                                                        let _e2461 = local_565;
                                                                        phi_1933_ = ((_e2461 * f32(_e2459)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2440 = local_208;
                                                                        if (_e2440 == 31u) {
                                                                            let _e2450 = local_209;
                                                                            phi_1930_ = (2139095040u | (_e2450 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2442 = local_208;
                                                                            let _e2446 = local_209;
                                                                            phi_1930_ = (((_e2442 + 112u) << bitcast<u32>(23i)) | (_e2446 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2455 = phi_1930_;
                                                                        let _e2457 = local_565;
                                                                        phi_1933_ = (_e2457 * bitcast<f32>(_e2455));
                                                                    }
                                                                    let _e2465 = phi_1933_;
                                                                    local_210 = _e2465;
                                                                    let _e2466 = local_205;
                                                                    let _e2468 = (_e2466 >> bitcast<u32>(16i));
                                                                    local_566 = select(-1f, 1f, ((_e2468 & 32768u) == 0u));
                                                                    let _e2474 = ((_e2468 >> bitcast<u32>(10i)) & 31u);
                                                                    local_211 = _e2474;
                                                                    local_212 = (_e2468 & 1023u);
                                                                    if (_e2474 == 0u) {
                                                                        let _e2496 = local_212;
                                                                        let _e2498 = local_566;
                                                                        phi_1965_ = ((_e2498 * f32(_e2496)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2477 = local_211;
                                                                        if (_e2477 == 31u) {
                                                                            let _e2487 = local_212;
                                                                            phi_1962_ = (2139095040u | (_e2487 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2479 = local_211;
                                                                            let _e2483 = local_212;
                                                                            phi_1962_ = (((_e2479 + 112u) << bitcast<u32>(23i)) | (_e2483 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2492 = phi_1962_;
                                                                        let _e2494 = local_566;
                                                                        phi_1965_ = (_e2494 * bitcast<f32>(_e2492));
                                                                    }
                                                                    let _e2502 = phi_1965_;
                                                                    local_213 = _e2502;
                                                                    let _e2503 = local_207;
                                                                    let _e2504 = (_e2503 & 65535u);
                                                                    local_567 = select(-1f, 1f, ((_e2504 & 32768u) == 0u));
                                                                    let _e2510 = ((_e2504 >> bitcast<u32>(10i)) & 31u);
                                                                    local_214 = _e2510;
                                                                    local_215 = (_e2504 & 1023u);
                                                                    if (_e2510 == 0u) {
                                                                        let _e2532 = local_215;
                                                                        let _e2534 = local_567;
                                                                        phi_1997_ = ((_e2534 * f32(_e2532)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2513 = local_214;
                                                                        if (_e2513 == 31u) {
                                                                            let _e2523 = local_215;
                                                                            phi_1994_ = (2139095040u | (_e2523 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2515 = local_214;
                                                                            let _e2519 = local_215;
                                                                            phi_1994_ = (((_e2515 + 112u) << bitcast<u32>(23i)) | (_e2519 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2528 = phi_1994_;
                                                                        let _e2530 = local_567;
                                                                        phi_1997_ = (_e2530 * bitcast<f32>(_e2528));
                                                                    }
                                                                    let _e2538 = phi_1997_;
                                                                    local_216 = _e2538;
                                                                    let _e2539 = local_207;
                                                                    let _e2541 = (_e2539 >> bitcast<u32>(16i));
                                                                    local_568 = select(-1f, 1f, ((_e2541 & 32768u) == 0u));
                                                                    let _e2547 = ((_e2541 >> bitcast<u32>(10i)) & 31u);
                                                                    local_217 = _e2547;
                                                                    local_218 = (_e2541 & 1023u);
                                                                    if (_e2547 == 0u) {
                                                                        let _e2569 = local_218;
                                                                        let _e2571 = local_568;
                                                                        phi_2029_ = ((_e2571 * f32(_e2569)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2550 = local_217;
                                                                        if (_e2550 == 31u) {
                                                                            let _e2560 = local_218;
                                                                            phi_2026_ = (2139095040u | (_e2560 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2552 = local_217;
                                                                            let _e2556 = local_218;
                                                                            phi_2026_ = (((_e2552 + 112u) << bitcast<u32>(23i)) | (_e2556 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2565 = phi_2026_;
                                                                        let _e2567 = local_568;
                                                                        phi_2029_ = (_e2567 * bitcast<f32>(_e2565));
                                                                    }
                                                                    let _e2575 = phi_2029_;
                                                                    local_219 = _e2575;
                                                                    let _e2576 = local_203;
                                                                    let _e2577 = local_179;
                                                                    let _e2579 = ((_e2576 + _e2577) * 2u);
                                                                    local_220 = _e2579;
                                                                    let _e2580 = local_6;
                                                                    if (_e2579 < _e2580) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2582 = local_220;
                                                                    let _e2585 = global_9.member[_e2582];
                                                                    local_221 = _e2585;
                                                                    let _e2586 = local_220;
                                                                    let _e2587 = (_e2586 + 1u);
                                                                    local_222 = _e2587;
                                                                    let _e2588 = local_6;
                                                                    if (_e2587 < _e2588) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2590 = local_222;
                                                                    let _e2593 = global_9.member[_e2590];
                                                                    local_223 = _e2593;
                                                                    let _e2594 = local_221;
                                                                    let _e2595 = (_e2594 & 65535u);
                                                                    local_569 = select(-1f, 1f, ((_e2595 & 32768u) == 0u));
                                                                    let _e2601 = ((_e2595 >> bitcast<u32>(10i)) & 31u);
                                                                    local_224 = _e2601;
                                                                    local_225 = (_e2595 & 1023u);
                                                                    if (_e2601 == 0u) {
                                                                        let _e2623 = local_225;
                                                                        let _e2625 = local_569;
                                                                        phi_2098_ = ((_e2625 * f32(_e2623)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2604 = local_224;
                                                                        if (_e2604 == 31u) {
                                                                            let _e2614 = local_225;
                                                                            phi_2095_ = (2139095040u | (_e2614 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2606 = local_224;
                                                                            let _e2610 = local_225;
                                                                            phi_2095_ = (((_e2606 + 112u) << bitcast<u32>(23i)) | (_e2610 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2619 = phi_2095_;
                                                                        let _e2621 = local_569;
                                                                        phi_2098_ = (_e2621 * bitcast<f32>(_e2619));
                                                                    }
                                                                    let _e2629 = phi_2098_;
                                                                    local_226 = _e2629;
                                                                    let _e2630 = local_221;
                                                                    let _e2632 = (_e2630 >> bitcast<u32>(16i));
                                                                    local_570 = select(-1f, 1f, ((_e2632 & 32768u) == 0u));
                                                                    let _e2638 = ((_e2632 >> bitcast<u32>(10i)) & 31u);
                                                                    local_227 = _e2638;
                                                                    local_228 = (_e2632 & 1023u);
                                                                    if (_e2638 == 0u) {
                                                                        let _e2660 = local_228;
                                                                        let _e2662 = local_570;
                                                                        phi_2130_ = ((_e2662 * f32(_e2660)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2641 = local_227;
                                                                        if (_e2641 == 31u) {
                                                                            let _e2651 = local_228;
                                                                            phi_2127_ = (2139095040u | (_e2651 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2643 = local_227;
                                                                            let _e2647 = local_228;
                                                                            phi_2127_ = (((_e2643 + 112u) << bitcast<u32>(23i)) | (_e2647 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2656 = phi_2127_;
                                                                        let _e2658 = local_570;
                                                                        phi_2130_ = (_e2658 * bitcast<f32>(_e2656));
                                                                    }
                                                                    let _e2666 = phi_2130_;
                                                                    local_229 = _e2666;
                                                                    let _e2667 = local_223;
                                                                    let _e2668 = (_e2667 & 65535u);
                                                                    local_571 = select(-1f, 1f, ((_e2668 & 32768u) == 0u));
                                                                    let _e2674 = ((_e2668 >> bitcast<u32>(10i)) & 31u);
                                                                    local_230 = _e2674;
                                                                    local_231 = (_e2668 & 1023u);
                                                                    if (_e2674 == 0u) {
                                                                        let _e2696 = local_231;
                                                                        let _e2698 = local_571;
                                                                        phi_2162_ = ((_e2698 * f32(_e2696)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2677 = local_230;
                                                                        if (_e2677 == 31u) {
                                                                            let _e2687 = local_231;
                                                                            phi_2159_ = (2139095040u | (_e2687 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2679 = local_230;
                                                                            let _e2683 = local_231;
                                                                            phi_2159_ = (((_e2679 + 112u) << bitcast<u32>(23i)) | (_e2683 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2692 = phi_2159_;
                                                                        let _e2694 = local_571;
                                                                        phi_2162_ = (_e2694 * bitcast<f32>(_e2692));
                                                                    }
                                                                    let _e2702 = phi_2162_;
                                                                    local_232 = _e2702;
                                                                    let _e2703 = local_223;
                                                                    let _e2705 = (_e2703 >> bitcast<u32>(16i));
                                                                    local_572 = select(-1f, 1f, ((_e2705 & 32768u) == 0u));
                                                                    let _e2711 = ((_e2705 >> bitcast<u32>(10i)) & 31u);
                                                                    local_233 = _e2711;
                                                                    local_234 = (_e2705 & 1023u);
                                                                    if (_e2711 == 0u) {
                                                                        let _e2733 = local_234;
                                                                        let _e2735 = local_572;
                                                                        phi_2194_ = ((_e2735 * f32(_e2733)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2714 = local_233;
                                                                        if (_e2714 == 31u) {
                                                                            let _e2724 = local_234;
                                                                            phi_2191_ = (2139095040u | (_e2724 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2716 = local_233;
                                                                            let _e2720 = local_234;
                                                                            phi_2191_ = (((_e2716 + 112u) << bitcast<u32>(23i)) | (_e2720 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2729 = phi_2191_;
                                                                        let _e2731 = local_572;
                                                                        phi_2194_ = (_e2731 * bitcast<f32>(_e2729));
                                                                    }
                                                                    let _e2739 = phi_2194_;
                                                                    let _e2740 = local_226;
                                                                    let _e2741 = local_210;
                                                                    let _e2743 = local_155;
                                                                    let _e2745 = local_210;
                                                                    local_235 = (_e2745 + ((_e2740 - _e2741) * _e2743));
                                                                    let _e2747 = local_229;
                                                                    let _e2748 = local_213;
                                                                    let _e2750 = local_155;
                                                                    let _e2752 = local_213;
                                                                    local_236 = (_e2752 + ((_e2747 - _e2748) * _e2750));
                                                                    let _e2754 = local_232;
                                                                    let _e2755 = local_216;
                                                                    let _e2757 = local_155;
                                                                    let _e2759 = local_216;
                                                                    local_237 = (_e2759 + ((_e2754 - _e2755) * _e2757));
                                                                    let _e2761 = local_219;
                                                                    let _e2763 = local_155;
                                                                    let _e2765 = local_219;
                                                                    local_238 = (_e2765 + ((_e2739 - _e2761) * _e2763));
                                                                    let _e2767 = local_201;
                                                                    let _e2768 = local_148;
                                                                    let _e2770 = local_202;
                                                                    let _e2771 = (_e2770 + (_e2767 * _e2768));
                                                                    local_239 = _e2771;
                                                                    let _e2772 = local_169;
                                                                    let _e2774 = ((_e2771 + _e2772) * 2u);
                                                                    local_240 = _e2774;
                                                                    let _e2775 = local_6;
                                                                    if (_e2774 < _e2775) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2777 = local_240;
                                                                    let _e2780 = global_9.member[_e2777];
                                                                    local_241 = _e2780;
                                                                    let _e2781 = local_240;
                                                                    let _e2782 = (_e2781 + 1u);
                                                                    local_242 = _e2782;
                                                                    let _e2783 = local_6;
                                                                    if (_e2782 < _e2783) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2785 = local_242;
                                                                    let _e2788 = global_9.member[_e2785];
                                                                    local_243 = _e2788;
                                                                    let _e2789 = local_241;
                                                                    let _e2790 = (_e2789 & 65535u);
                                                                    local_573 = select(-1f, 1f, ((_e2790 & 32768u) == 0u));
                                                                    let _e2796 = ((_e2790 >> bitcast<u32>(10i)) & 31u);
                                                                    local_244 = _e2796;
                                                                    local_245 = (_e2790 & 1023u);
                                                                    if (_e2796 == 0u) {
                                                                        let _e2818 = local_245;
                                                                        let _e2820 = local_573;
                                                                        phi_2275_ = ((_e2820 * f32(_e2818)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2799 = local_244;
                                                                        if (_e2799 == 31u) {
                                                                            let _e2809 = local_245;
                                                                            phi_2272_ = (2139095040u | (_e2809 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2801 = local_244;
                                                                            let _e2805 = local_245;
                                                                            phi_2272_ = (((_e2801 + 112u) << bitcast<u32>(23i)) | (_e2805 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2814 = phi_2272_;
                                                                        let _e2816 = local_573;
                                                                        phi_2275_ = (_e2816 * bitcast<f32>(_e2814));
                                                                    }
                                                                    let _e2824 = phi_2275_;
                                                                    local_246 = _e2824;
                                                                    let _e2825 = local_241;
                                                                    let _e2827 = (_e2825 >> bitcast<u32>(16i));
                                                                    local_574 = select(-1f, 1f, ((_e2827 & 32768u) == 0u));
                                                                    let _e2833 = ((_e2827 >> bitcast<u32>(10i)) & 31u);
                                                                    local_247 = _e2833;
                                                                    local_248 = (_e2827 & 1023u);
                                                                    if (_e2833 == 0u) {
                                                                        let _e2855 = local_248;
                                                                        let _e2857 = local_574;
                                                                        phi_2307_ = ((_e2857 * f32(_e2855)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2836 = local_247;
                                                                        if (_e2836 == 31u) {
                                                                            let _e2846 = local_248;
                                                                            phi_2304_ = (2139095040u | (_e2846 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2838 = local_247;
                                                                            let _e2842 = local_248;
                                                                            phi_2304_ = (((_e2838 + 112u) << bitcast<u32>(23i)) | (_e2842 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2851 = phi_2304_;
                                                                        let _e2853 = local_574;
                                                                        phi_2307_ = (_e2853 * bitcast<f32>(_e2851));
                                                                    }
                                                                    let _e2861 = phi_2307_;
                                                                    local_249 = _e2861;
                                                                    let _e2862 = local_243;
                                                                    let _e2863 = (_e2862 & 65535u);
                                                                    local_575 = select(-1f, 1f, ((_e2863 & 32768u) == 0u));
                                                                    let _e2869 = ((_e2863 >> bitcast<u32>(10i)) & 31u);
                                                                    local_250 = _e2869;
                                                                    local_251 = (_e2863 & 1023u);
                                                                    if (_e2869 == 0u) {
                                                                        let _e2891 = local_251;
                                                                        let _e2893 = local_575;
                                                                        phi_2339_ = ((_e2893 * f32(_e2891)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2872 = local_250;
                                                                        if (_e2872 == 31u) {
                                                                            let _e2882 = local_251;
                                                                            phi_2336_ = (2139095040u | (_e2882 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2874 = local_250;
                                                                            let _e2878 = local_251;
                                                                            phi_2336_ = (((_e2874 + 112u) << bitcast<u32>(23i)) | (_e2878 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2887 = phi_2336_;
                                                                        let _e2889 = local_575;
                                                                        phi_2339_ = (_e2889 * bitcast<f32>(_e2887));
                                                                    }
                                                                    let _e2897 = phi_2339_;
                                                                    local_252 = _e2897;
                                                                    let _e2898 = local_243;
                                                                    let _e2900 = (_e2898 >> bitcast<u32>(16i));
                                                                    local_576 = select(-1f, 1f, ((_e2900 & 32768u) == 0u));
                                                                    let _e2906 = ((_e2900 >> bitcast<u32>(10i)) & 31u);
                                                                    local_253 = _e2906;
                                                                    local_254 = (_e2900 & 1023u);
                                                                    if (_e2906 == 0u) {
                                                                        let _e2928 = local_254;
                                                                        let _e2930 = local_576;
                                                                        phi_2371_ = ((_e2930 * f32(_e2928)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2909 = local_253;
                                                                        if (_e2909 == 31u) {
                                                                            let _e2919 = local_254;
                                                                            phi_2368_ = (2139095040u | (_e2919 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2911 = local_253;
                                                                            let _e2915 = local_254;
                                                                            phi_2368_ = (((_e2911 + 112u) << bitcast<u32>(23i)) | (_e2915 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2924 = phi_2368_;
                                                                        let _e2926 = local_576;
                                                                        phi_2371_ = (_e2926 * bitcast<f32>(_e2924));
                                                                    }
                                                                    let _e2934 = phi_2371_;
                                                                    local_255 = _e2934;
                                                                    let _e2935 = local_239;
                                                                    let _e2936 = local_179;
                                                                    let _e2938 = ((_e2935 + _e2936) * 2u);
                                                                    local_256 = _e2938;
                                                                    let _e2939 = local_6;
                                                                    if (_e2938 < _e2939) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2941 = local_256;
                                                                    let _e2944 = global_9.member[_e2941];
                                                                    local_257 = _e2944;
                                                                    let _e2945 = local_256;
                                                                    let _e2946 = (_e2945 + 1u);
                                                                    local_258 = _e2946;
                                                                    let _e2947 = local_6;
                                                                    if (_e2946 < _e2947) {
                                                                    } else {
                                                                        phi_5704_ = true;
                                                                        break;
                                                                    }
                                                                    let _e2949 = local_258;
                                                                    let _e2952 = global_9.member[_e2949];
                                                                    local_259 = _e2952;
                                                                    let _e2953 = local_257;
                                                                    let _e2954 = (_e2953 & 65535u);
                                                                    local_577 = select(-1f, 1f, ((_e2954 & 32768u) == 0u));
                                                                    let _e2960 = ((_e2954 >> bitcast<u32>(10i)) & 31u);
                                                                    local_260 = _e2960;
                                                                    local_261 = (_e2954 & 1023u);
                                                                    if (_e2960 == 0u) {
                                                                        let _e2982 = local_261;
                                                                        let _e2984 = local_577;
                                                                        phi_2440_ = ((_e2984 * f32(_e2982)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e2963 = local_260;
                                                                        if (_e2963 == 31u) {
                                                                            let _e2973 = local_261;
                                                                            phi_2437_ = (2139095040u | (_e2973 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e2965 = local_260;
                                                                            let _e2969 = local_261;
                                                                            phi_2437_ = (((_e2965 + 112u) << bitcast<u32>(23i)) | (_e2969 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e2978 = phi_2437_;
                                                                        let _e2980 = local_577;
                                                                        phi_2440_ = (_e2980 * bitcast<f32>(_e2978));
                                                                    }
                                                                    let _e2988 = phi_2440_;
                                                                    local_262 = _e2988;
                                                                    let _e2989 = local_257;
                                                                    let _e2991 = (_e2989 >> bitcast<u32>(16i));
                                                                    local_578 = select(-1f, 1f, ((_e2991 & 32768u) == 0u));
                                                                    let _e2997 = ((_e2991 >> bitcast<u32>(10i)) & 31u);
                                                                    local_263 = _e2997;
                                                                    local_264 = (_e2991 & 1023u);
                                                                    if (_e2997 == 0u) {
                                                                        let _e3019 = local_264;
                                                                        let _e3021 = local_578;
                                                                        phi_2472_ = ((_e3021 * f32(_e3019)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3000 = local_263;
                                                                        if (_e3000 == 31u) {
                                                                            let _e3010 = local_264;
                                                                            phi_2469_ = (2139095040u | (_e3010 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3002 = local_263;
                                                                            let _e3006 = local_264;
                                                                            phi_2469_ = (((_e3002 + 112u) << bitcast<u32>(23i)) | (_e3006 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3015 = phi_2469_;
                                                                        let _e3017 = local_578;
                                                                        phi_2472_ = (_e3017 * bitcast<f32>(_e3015));
                                                                    }
                                                                    let _e3025 = phi_2472_;
                                                                    local_265 = _e3025;
                                                                    let _e3026 = local_259;
                                                                    let _e3027 = (_e3026 & 65535u);
                                                                    local_579 = select(-1f, 1f, ((_e3027 & 32768u) == 0u));
                                                                    let _e3033 = ((_e3027 >> bitcast<u32>(10i)) & 31u);
                                                                    local_266 = _e3033;
                                                                    local_267 = (_e3027 & 1023u);
                                                                    if (_e3033 == 0u) {
                                                                        let _e3055 = local_267;
                                                                        let _e3057 = local_579;
                                                                        phi_2504_ = ((_e3057 * f32(_e3055)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3036 = local_266;
                                                                        if (_e3036 == 31u) {
                                                                            let _e3046 = local_267;
                                                                            phi_2501_ = (2139095040u | (_e3046 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3038 = local_266;
                                                                            let _e3042 = local_267;
                                                                            phi_2501_ = (((_e3038 + 112u) << bitcast<u32>(23i)) | (_e3042 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3051 = phi_2501_;
                                                                        let _e3053 = local_579;
                                                                        phi_2504_ = (_e3053 * bitcast<f32>(_e3051));
                                                                    }
                                                                    let _e3061 = phi_2504_;
                                                                    local_268 = _e3061;
                                                                    let _e3062 = local_259;
                                                                    let _e3064 = (_e3062 >> bitcast<u32>(16i));
                                                                    local_580 = select(-1f, 1f, ((_e3064 & 32768u) == 0u));
                                                                    let _e3070 = ((_e3064 >> bitcast<u32>(10i)) & 31u);
                                                                    local_269 = _e3070;
                                                                    local_270 = (_e3064 & 1023u);
                                                                    if (_e3070 == 0u) {
                                                                        let _e3092 = local_270;
                                                                        let _e3094 = local_580;
                                                                        phi_2536_ = ((_e3094 * f32(_e3092)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e3073 = local_269;
                                                                        if (_e3073 == 31u) {
                                                                            let _e3083 = local_270;
                                                                            phi_2533_ = (2139095040u | (_e3083 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e3075 = local_269;
                                                                            let _e3079 = local_270;
                                                                            phi_2533_ = (((_e3075 + 112u) << bitcast<u32>(23i)) | (_e3079 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e3088 = phi_2533_;
                                                                        let _e3090 = local_580;
                                                                        phi_2536_ = (_e3090 * bitcast<f32>(_e3088));
                                                                    }
                                                                    let _e3098 = phi_2536_;
                                                                    let _e3099 = local_262;
                                                                    let _e3100 = local_246;
                                                                    let _e3102 = local_155;
                                                                    let _e3104 = local_246;
                                                                    let _e3106 = local_265;
                                                                    let _e3107 = local_249;
                                                                    let _e3109 = local_155;
                                                                    let _e3111 = local_249;
                                                                    let _e3113 = local_268;
                                                                    let _e3114 = local_252;
                                                                    let _e3116 = local_155;
                                                                    let _e3118 = local_252;
                                                                    let _e3120 = local_255;
                                                                    let _e3122 = local_155;
                                                                    let _e3124 = local_255;
                                                                    let _e3126 = local_235;
                                                                    let _e3128 = local_154;
                                                                    let _e3130 = local_235;
                                                                    let _e3132 = local_236;
                                                                    let _e3134 = local_154;
                                                                    let _e3136 = local_236;
                                                                    let _e3138 = local_237;
                                                                    let _e3140 = local_154;
                                                                    let _e3142 = local_237;
                                                                    let _e3144 = local_238;
                                                                    let _e3146 = local_154;
                                                                    let _e3148 = local_238;
                                                                    let _e3150 = local_147;
                                                                    let _e3152 = local_147;
                                                                    let _e3154 = local_147;
                                                                    let _e3156 = local_147;
                                                                    let _e3158 = local_144;
                                                                    let _e3161 = local_144;
                                                                    let _e3164 = local_144;
                                                                    let _e3167 = local_144;
                                                                    let _e3171 = local_143;
                                                                    phi_1491_ = (_e3171 + 1u);
                                                                    phi_1494_ = type_5((_e3158.member + ((_e3130 + (((_e3104 + ((_e3099 - _e3100) * _e3102)) - _e3126) * _e3128)) * _e3150)), (_e3161.member_1 + ((_e3136 + (((_e3111 + ((_e3106 - _e3107) * _e3109)) - _e3132) * _e3134)) * _e3152)), (_e3164.member_2 + ((_e3142 + (((_e3118 + ((_e3113 - _e3114) * _e3116)) - _e3138) * _e3140)) * _e3154)), (_e3167.member_3 + ((_e3148 + (((_e3124 + ((_e3098 - _e3120) * _e3122)) - _e3144) * _e3146)) * _e3156)));
                                                                } else {
                                                                    phi_1491_ = u32();
                                                                    phi_1494_ = type_5();
                                                                }
                                                                let _e3174 = phi_1491_;
                                                                let _e3176 = phi_1494_;
                                                                continue;
                                                                continuing {
                                                                    let _e3177 = local_145;
                                                                    phi_1490_ = _e3174;
                                                                    phi_1493_ = _e3176;
                                                                    phi_5704_ = _e2026;
                                                                    break if !(_e3177);
                                                                }
                                                            }
                                                            let _e3180 = phi_5704_;
                                                            phi_5818_ = _e3180;
                                                            if _e3180 {
                                                                break;
                                                            }
                                                            let _e3181 = local_139;
                                                            phi_5819_ = _e3180;
                                                            phi_1462_ = (_e3181 + 1u);
                                                            let _e5585 = local_626;
                                                            phi_1465_ = _e5585;
                                                        } else {
                                                            phi_5819_ = _e2026;
                                                            phi_1462_ = u32();
                                                            phi_1465_ = type_5();
                                                        }
                                                        let _e3184 = phi_5819_;
                                                        let _e3186 = phi_1462_;
                                                        let _e3188 = phi_1465_;
                                                        continue;
                                                        continuing {
                                                            let _e3189 = local_140;
                                                            phi_5750_ = _e3184;
                                                            phi_1461_ = _e3186;
                                                            phi_1464_ = _e3188;
                                                            phi_5818_ = _e3184;
                                                            break if !(_e3189);
                                                        }
                                                    }
                                                    let _e3192 = phi_5818_;
                                                    phi_5820_ = _e3192;
                                                    if _e3192 {
                                                        break;
                                                    }
                                                    let _e3193 = local_135;
                                                    phi_5821_ = _e3192;
                                                    phi_1445_ = (_e3193 + 1u);
                                                    let _e5591 = local_627;
                                                    phi_1448_ = _e5591;
                                                } else {
                                                    phi_5821_ = _e2010;
                                                    phi_1445_ = u32();
                                                    phi_1448_ = type_5();
                                                }
                                                let _e3196 = phi_5821_;
                                                let _e3198 = phi_1445_;
                                                let _e3200 = phi_1448_;
                                                continue;
                                                continuing {
                                                    let _e3201 = local_137;
                                                    phi_5751_ = _e3196;
                                                    phi_1444_ = _e3198;
                                                    phi_1447_ = _e3200;
                                                    phi_5820_ = _e3196;
                                                    break if !(_e3201);
                                                }
                                            }
                                            let _e3204 = phi_5820_;
                                            phi_5975_ = _e3204;
                                            if _e3204 {
                                                break;
                                            }
                                            let _e3205 = local_126;
                                            let _e3206 = local_125;
                                            let _e3209 = (1f / f32((_e3205 * _e3206)));
                                            let _e3210 = local_136;
                                            let _e3213 = local_136;
                                            let _e3216 = local_136;
                                            let _e3219 = local_136;
                                            phi_5895_ = _e3204;
                                            phi_2589_ = type_5((_e3210.member * _e3209), (_e3213.member_1 * _e3209), (_e3216.member_2 * _e3209), (_e3219.member_3 * _e3209));
                                        }
                                        let _e3224 = phi_5895_;
                                        let _e3226 = phi_2589_;
                                        phi_5894_ = _e3224;
                                        phi_2590_ = _e3226;
                                        phi_2591_ = _e1668;
                                    }
                                    let _e3228 = phi_5894_;
                                    let _e3230 = phi_2590_;
                                    let _e3232 = phi_2591_;
                                    if _e3232 {
                                        phi_2595_ = type_5(1f, 1f, 1f, 1f);
                                    } else {
                                        phi_2595_ = _e3230;
                                    }
                                    let _e3234 = phi_2595_;
                                    phi_5892_ = _e3228;
                                    phi_2596_ = _e3234;
                                }
                                let _e3236 = phi_5892_;
                                let _e3238 = phi_2596_;
                                phi_5891_ = _e3236;
                                phi_2597_ = _e3238;
                                phi_2598_ = _e1632;
                            }
                            let _e3240 = phi_5891_;
                            let _e3242 = phi_2597_;
                            let _e3244 = phi_2598_;
                            if _e3244 {
                                phi_2602_ = type_5(1f, 1f, 1f, 1f);
                            } else {
                                phi_2602_ = _e3242;
                            }
                            let _e3246 = phi_2602_;
                            local_619 = array<f32, 4>(_e3246.member, _e3246.member_1, _e3246.member_2, _e3246.member_3);
                            let _e3252 = local_86;
                            if (_e3252 == 4294967295u) {
                                phi_5950_ = _e3240;
                                phi_4080_ = type_5();
                                phi_4081_ = true;
                            } else {
                                let _e3254 = local_86;
                                let _e3255 = local_25;
                                let _e3256 = (_e3254 >= _e3255);
                                if _e3256 {
                                    phi_5951_ = _e3240;
                                    phi_4079_ = type_5();
                                } else {
                                    let _e3257 = local_86;
                                    let _e3258 = (_e3257 * 4u);
                                    local_271 = _e3258;
                                    let _e3259 = local_5;
                                    if (_e3258 < _e3259) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e3261 = local_271;
                                    let _e3264 = global_8.member[_e3261];
                                    local_272 = _e3264;
                                    let _e3265 = local_271;
                                    let _e3266 = (_e3265 + 1u);
                                    local_273 = _e3266;
                                    let _e3267 = local_5;
                                    if (_e3266 < _e3267) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e3269 = local_273;
                                    let _e3272 = global_8.member[_e3269];
                                    local_274 = _e3272;
                                    let _e3273 = local_271;
                                    let _e3274 = (_e3273 + 2u);
                                    local_275 = _e3274;
                                    let _e3275 = local_5;
                                    if (_e3274 < _e3275) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e3277 = local_275;
                                    let _e3280 = global_8.member[_e3277];
                                    local_276 = _e3280;
                                    let _e3281 = local_271;
                                    let _e3282 = (_e3281 + 3u);
                                    local_277 = _e3282;
                                    let _e3283 = local_5;
                                    if (_e3282 < _e3283) {
                                    } else {
                                        phi_5975_ = true;
                                        break;
                                    }
                                    let _e3285 = local_277;
                                    let _e3288 = global_8.member[_e3285];
                                    local_278 = _e3288;
                                    let _e3289 = local_274;
                                    if (_e3289 == 0u) {
                                        phi_5953_ = _e3240;
                                        phi_4073_ = type_5();
                                        phi_4074_ = true;
                                    } else {
                                        let _e3291 = local_276;
                                        let _e3292 = (_e3291 == 0u);
                                        if _e3292 {
                                            phi_5954_ = _e3240;
                                            phi_4072_ = type_5();
                                        } else {
                                            let _e3293 = local_278;
                                            let _e3296 = ((_e3293 >> bitcast<u32>(8u)) & 31u);
                                            local_581 = select(_e3296, 1u, (_e3296 == 0u));
                                            let _e3299 = local_278;
                                            let _e3303 = local_278;
                                            let _e3307 = local_272;
                                            let _e3308 = local_274;
                                            let _e3309 = local_276;
                                            let _e3310 = type_22(_e3307, _e3308, _e3309, ((_e3299 >> bitcast<u32>(1u)) & 3u), ((_e3303 >> bitcast<u32>(3u)) & 3u));
                                            let _e3311 = local_274;
                                            let _e3312 = f32(_e3311);
                                            local_279 = _e3312;
                                            let _e3313 = local_75;
                                            if ((bitcast<u32>((_e3313 * _e3312)) & 2139095040u) != 2139095040u) {
                                                let _e3318 = local_276;
                                                let _e3320 = local_74;
                                                phi_2722_ = select(true, false, ((bitcast<u32>((_e3320 * f32(_e3318))) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_2722_ = true;
                                            }
                                            let _e3327 = phi_2722_;
                                            let _e3328 = local_74;
                                            local_582 = select(_e3328, 0f, _e3327);
                                            let _e3330 = local_75;
                                            local_583 = select(_e3330, 0f, _e3327);
                                            let _e3332 = local_102;
                                            local_280 = _e3332.member;
                                            let _e3334 = local_279;
                                            let _e3335 = (_e3332.member * _e3334);
                                            let _e3336 = local_102;
                                            local_281 = _e3336.member_1;
                                            let _e3338 = local_276;
                                            let _e3339 = f32(_e3338);
                                            let _e3340 = (_e3336.member_1 * _e3339);
                                            let _e3341 = local_102;
                                            local_282 = _e3341.member_2;
                                            let _e3343 = local_279;
                                            let _e3344 = (_e3341.member_2 * _e3343);
                                            let _e3345 = local_102;
                                            local_283 = _e3345.member_3;
                                            let _e3347 = (_e3345.member_3 * _e3339);
                                            let _e3351 = sqrt(((_e3335 * _e3335) + (_e3340 * _e3340)));
                                            local_284 = _e3351;
                                            let _e3355 = sqrt(((_e3344 * _e3344) + (_e3347 * _e3347)));
                                            local_285 = _e3355;
                                            let _e3357 = select(_e3355, _e3351, (_e3351 > _e3355));
                                            local_584 = _e3357;
                                            if (_e3357 > 1f) {
                                                let _e3359 = local_584;
                                                phi_2761_ = !(((bitcast<u32>(_e3359) & 2139095040u) != 2139095040u));
                                            } else {
                                                phi_2761_ = true;
                                            }
                                            let _e3365 = phi_2761_;
                                            local_286 = _e3365;
                                            if _e3365 {
                                                phi_2857_ = 1u;
                                                phi_2858_ = 1u;
                                            } else {
                                                let _e3366 = local_284;
                                                let _e3367 = local_285;
                                                if (_e3366 >= _e3367) {
                                                    let _e3407 = local_285;
                                                    let _e3409 = local_285;
                                                    let _e3411 = ceil(select(8f, _e3409, (_e3407 < 8f)));
                                                    local_287 = _e3411;
                                                    if (_e3411 < 1f) {
                                                        phi_2787_ = 1u;
                                                    } else {
                                                        let _e3413 = local_287;
                                                        let _e3415 = local_287;
                                                        let _e3418 = local_287;
                                                        phi_2787_ = select(select(u32(_e3413), 0u, !((_e3415 >= 0f))), 4294967295u, (_e3418 > 4294967000f));
                                                    }
                                                    let _e3423 = phi_2787_;
                                                    local_288 = _e3423;
                                                    if (_e3423 == 0u) {
                                                        phi_5975_ = true;
                                                        break;
                                                    }
                                                    let _e3425 = local_288;
                                                    let _e3427 = f32((64u / _e3425));
                                                    let _e3428 = local_284;
                                                    let _e3430 = local_284;
                                                    let _e3432 = ceil(select(_e3427, _e3430, (_e3428 < _e3427)));
                                                    local_289 = _e3432;
                                                    if (_e3432 < 1f) {
                                                        phi_2811_ = 1u;
                                                    } else {
                                                        let _e3434 = local_289;
                                                        let _e3436 = local_289;
                                                        let _e3439 = local_289;
                                                        phi_2811_ = select(select(u32(_e3434), 0u, !((_e3436 >= 0f))), 4294967295u, (_e3439 > 4294967000f));
                                                    }
                                                    let _e3444 = phi_2811_;
                                                    phi_2855_ = _e3423;
                                                    phi_2856_ = _e3444;
                                                } else {
                                                    let _e3369 = local_284;
                                                    let _e3371 = local_284;
                                                    let _e3373 = ceil(select(8f, _e3371, (_e3369 < 8f)));
                                                    local_290 = _e3373;
                                                    if (_e3373 < 1f) {
                                                        phi_2830_ = 1u;
                                                    } else {
                                                        let _e3375 = local_290;
                                                        let _e3377 = local_290;
                                                        let _e3380 = local_290;
                                                        phi_2830_ = select(select(u32(_e3375), 0u, !((_e3377 >= 0f))), 4294967295u, (_e3380 > 4294967000f));
                                                    }
                                                    let _e3385 = phi_2830_;
                                                    local_291 = _e3385;
                                                    if (_e3385 == 0u) {
                                                        phi_5975_ = true;
                                                        break;
                                                    }
                                                    let _e3387 = local_291;
                                                    let _e3389 = f32((64u / _e3387));
                                                    let _e3390 = local_285;
                                                    let _e3392 = local_285;
                                                    let _e3394 = ceil(select(_e3389, _e3392, (_e3390 < _e3389)));
                                                    local_292 = _e3394;
                                                    if (_e3394 < 1f) {
                                                        phi_2854_ = 1u;
                                                    } else {
                                                        let _e3396 = local_292;
                                                        let _e3398 = local_292;
                                                        let _e3401 = local_292;
                                                        phi_2854_ = select(select(u32(_e3396), 0u, !((_e3398 >= 0f))), 4294967295u, (_e3401 > 4294967000f));
                                                    }
                                                    let _e3406 = phi_2854_;
                                                    phi_2855_ = _e3406;
                                                    phi_2856_ = _e3385;
                                                }
                                                let _e3446 = phi_2855_;
                                                let _e3448 = phi_2856_;
                                                phi_2857_ = _e3446;
                                                phi_2858_ = _e3448;
                                            }
                                            let _e3450 = phi_2857_;
                                            let _e3452 = phi_2858_;
                                            local_293 = _e3450;
                                            local_294 = _e3452;
                                            let _e3453 = local_286;
                                            if _e3453 {
                                                phi_2871_ = 1f;
                                            } else {
                                                let _e3454 = local_294;
                                                let _e3456 = local_284;
                                                let _e3457 = (_e3456 / f32(_e3454));
                                                let _e3458 = local_293;
                                                let _e3460 = local_285;
                                                let _e3461 = (_e3460 / f32(_e3458));
                                                phi_2871_ = select(_e3461, _e3457, (_e3457 > _e3461));
                                            }
                                            let _e3465 = phi_2871_;
                                            local_295 = _e3465;
                                            if (_e3465 > 1f) {
                                                let _e3467 = local_295;
                                                let _e3468 = bitcast<u32>(_e3467);
                                                let _e3477 = (bitcast<f32>(((_e3468 & 8388607u) | 1065353216u)) - 1f);
                                                phi_2892_ = (f32((bitcast<i32>(((_e3468 >> bitcast<u32>(23i)) & 255u)) - 127i)) + (_e3477 * (1.4208645f + (_e3477 * (-0.5772506f + (_e3477 * 0.1563861f))))));
                                            } else {
                                                phi_2892_ = 0f;
                                            }
                                            let _e3486 = phi_2892_;
                                            local_296 = _e3486;
                                            let _e3487 = local_581;
                                            let _e3488 = (_e3487 - 1u);
                                            local_297 = _e3488;
                                            let _e3489 = floor(_e3486);
                                            let _e3495 = select(select(u32(_e3489), 0u, !((_e3489 >= 0f))), 4294967295u, (_e3489 > 4294967000f));
                                            local_298 = _e3495;
                                            let _e3496 = (_e3495 >= _e3488);
                                            local_299 = _e3496;
                                            if _e3496 {
                                                phi_2908_ = 0f;
                                            } else {
                                                let _e3497 = local_298;
                                                let _e3499 = local_296;
                                                phi_2908_ = (_e3499 - f32(_e3497));
                                            }
                                            let _e3502 = phi_2908_;
                                            local_300 = _e3502;
                                            let _e3503 = local_299;
                                            let _e3504 = local_297;
                                            let _e3505 = local_298;
                                            local_585 = select(_e3505, _e3504, _e3503);
                                            local_586 = select(1u, 2u, (_e3502 > 0f));
                                            phi_5584_ = 0u;
                                            phi_5585_ = _e3310;
                                            loop {
                                                let _e3510 = phi_5584_;
                                                let _e3512 = phi_5585_;
                                                local_545 = _e3510;
                                                local_546 = _e3512;
                                                local_628 = _e3512;
                                                let _e3513 = local_545;
                                                let _e3514 = local_585;
                                                let _e3515 = (_e3513 < _e3514);
                                                local_547 = _e3515;
                                                if _e3515 {
                                                    let _e3516 = local_546;
                                                    local_548 = _e3516.member_1;
                                                    let _e3518 = local_546;
                                                    local_549 = _e3518.member_2;
                                                    let _e3521 = local_546;
                                                    let _e3524 = local_546;
                                                    local_550 = type_22((_e3521.member + (_e3516.member_1 * _e3518.member_2)), _e3524.member_1, _e3524.member_2, _e3524.member_3, _e3524.member_4);
                                                    if (_e3516.member_1 > 1u) {
                                                        let _e3532 = local_548;
                                                        phi_5602_ = (_e3532 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5602_ = 1u;
                                                    }
                                                    let _e3536 = phi_5602_;
                                                    let _e3537 = local_550;
                                                    local_551 = type_22(_e3537.member, _e3536, _e3537.member_2, _e3537.member_3, _e3537.member_4);
                                                    let _e3544 = local_549;
                                                    if (_e3544 > 1u) {
                                                        let _e3546 = local_549;
                                                        phi_5611_ = (_e3546 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5611_ = 1u;
                                                    }
                                                    let _e3550 = phi_5611_;
                                                    let _e3551 = local_551;
                                                    let _e3558 = local_545;
                                                    phi_5616_ = (_e3558 + 1u);
                                                    phi_5617_ = type_22(_e3551.member, _e3551.member_1, _e3550, _e3551.member_3, _e3551.member_4);
                                                } else {
                                                    phi_5616_ = u32();
                                                    phi_5617_ = type_22();
                                                }
                                                let _e3561 = phi_5616_;
                                                let _e3563 = phi_5617_;
                                                continue;
                                                continuing {
                                                    let _e3564 = local_547;
                                                    phi_5584_ = _e3561;
                                                    phi_5585_ = _e3563;
                                                    break if !(_e3564);
                                                }
                                            }
                                            let _e3566 = local_585;
                                            let _e3567 = local_586;
                                            local_301 = ((_e3566 + _e3567) - 1u);
                                            phi_5623_ = 0u;
                                            phi_5624_ = _e3310;
                                            loop {
                                                let _e3571 = phi_5623_;
                                                let _e3573 = phi_5624_;
                                                local_552 = _e3571;
                                                local_553 = _e3573;
                                                local_629 = _e3573;
                                                let _e3574 = local_552;
                                                let _e3575 = local_301;
                                                let _e3576 = (_e3574 < _e3575);
                                                local_554 = _e3576;
                                                if _e3576 {
                                                    let _e3577 = local_553;
                                                    local_555 = _e3577.member_1;
                                                    let _e3579 = local_553;
                                                    local_556 = _e3579.member_2;
                                                    let _e3582 = local_553;
                                                    let _e3585 = local_553;
                                                    local_557 = type_22((_e3582.member + (_e3577.member_1 * _e3579.member_2)), _e3585.member_1, _e3585.member_2, _e3585.member_3, _e3585.member_4);
                                                    if (_e3577.member_1 > 1u) {
                                                        let _e3593 = local_555;
                                                        phi_5641_ = (_e3593 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5641_ = 1u;
                                                    }
                                                    let _e3597 = phi_5641_;
                                                    let _e3598 = local_557;
                                                    local_558 = type_22(_e3598.member, _e3597, _e3598.member_2, _e3598.member_3, _e3598.member_4);
                                                    let _e3605 = local_556;
                                                    if (_e3605 > 1u) {
                                                        let _e3607 = local_556;
                                                        phi_5650_ = (_e3607 >> bitcast<u32>(1i));
                                                    } else {
                                                        phi_5650_ = 1u;
                                                    }
                                                    let _e3611 = phi_5650_;
                                                    let _e3612 = local_558;
                                                    let _e3619 = local_552;
                                                    phi_5655_ = (_e3619 + 1u);
                                                    phi_5656_ = type_22(_e3612.member, _e3612.member_1, _e3611, _e3612.member_3, _e3612.member_4);
                                                } else {
                                                    phi_5655_ = u32();
                                                    phi_5656_ = type_22();
                                                }
                                                let _e3622 = phi_5655_;
                                                let _e3624 = phi_5656_;
                                                continue;
                                                continuing {
                                                    let _e3625 = local_554;
                                                    phi_5623_ = _e3622;
                                                    phi_5624_ = _e3624;
                                                    break if !(_e3625);
                                                }
                                            }
                                            let _e3627 = local_286;
                                            if _e3627 {
                                                let _e3628 = local_278;
                                                phi_2924_ = ((_e3628 & 1u) != 0u);
                                            } else {
                                                phi_2924_ = false;
                                            }
                                            let _e3632 = phi_2924_;
                                            local_302 = _e3632;
                                            phi_5869_ = _e3240;
                                            phi_2927_ = 0u;
                                            phi_2930_ = type_5(0f, 0f, 0f, 0f);
                                            loop {
                                                let _e3634 = phi_5869_;
                                                let _e3636 = phi_2927_;
                                                let _e3638 = phi_2930_;
                                                local_303 = _e3636;
                                                local_304 = _e3638;
                                                let _e3639 = local_303;
                                                let _e3640 = local_294;
                                                let _e3641 = (_e3639 < _e3640);
                                                local_305 = _e3641;
                                                if _e3641 {
                                                    let _e3642 = local_303;
                                                    let _e3645 = local_294;
                                                    local_306 = (((f32(_e3642) + 0.5f) / f32(_e3645)) - 0.5f);
                                                    phi_5868_ = _e3634;
                                                    phi_2944_ = 0u;
                                                    phi_2947_ = _e3638;
                                                    loop {
                                                        let _e3650 = phi_5868_;
                                                        let _e3652 = phi_2944_;
                                                        let _e3654 = phi_2947_;
                                                        local_307 = _e3652;
                                                        local_631 = _e3654;
                                                        let _e3655 = local_307;
                                                        let _e3656 = local_293;
                                                        let _e3657 = (_e3655 < _e3656);
                                                        local_308 = _e3657;
                                                        if _e3657 {
                                                            let _e3658 = local_307;
                                                            let _e3661 = local_293;
                                                            let _e3664 = (((f32(_e3658) + 0.5f) / f32(_e3661)) - 0.5f);
                                                            let _e3665 = local_306;
                                                            let _e3666 = local_280;
                                                            let _e3668 = local_583;
                                                            let _e3670 = local_282;
                                                            local_309 = ((_e3668 + (_e3665 * _e3666)) + (_e3664 * _e3670));
                                                            let _e3673 = local_306;
                                                            let _e3674 = local_281;
                                                            let _e3676 = local_582;
                                                            let _e3678 = local_283;
                                                            local_310 = ((_e3676 + (_e3673 * _e3674)) + (_e3664 * _e3678));
                                                            phi_2973_ = 0u;
                                                            phi_2976_ = _e3654;
                                                            loop {
                                                                let _e3682 = phi_2973_;
                                                                let _e3684 = phi_2976_;
                                                                local_311 = _e3682;
                                                                local_312 = _e3684;
                                                                local_630 = _e3684;
                                                                let _e3685 = local_311;
                                                                let _e3686 = local_586;
                                                                let _e3687 = (_e3685 < _e3686);
                                                                local_313 = _e3687;
                                                                if _e3687 {
                                                                    let _e3688 = local_311;
                                                                    if (_e3688 == 0u) {
                                                                        let _e3690 = local_300;
                                                                        let _e5641 = local_628;
                                                                        phi_2989_ = _e5641;
                                                                        phi_2990_ = (1f - _e3690);
                                                                    } else {
                                                                        let _e5643 = local_629;
                                                                        phi_2989_ = _e5643;
                                                                        phi_2990_ = _e3502;
                                                                    }
                                                                    let _e3693 = phi_2989_;
                                                                    let _e3695 = phi_2990_;
                                                                    local_314 = _e3693;
                                                                    local_315 = _e3695;
                                                                    let _e3696 = local_302;
                                                                    let _e3697 = select(0.5f, 0f, _e3696);
                                                                    local_316 = _e3693.member_1;
                                                                    let _e3700 = local_309;
                                                                    let _e3702 = ((_e3700 * f32(_e3693.member_1)) - _e3697);
                                                                    local_317 = _e3702;
                                                                    local_318 = _e3693.member_2;
                                                                    let _e3705 = local_310;
                                                                    let _e3707 = ((_e3705 * f32(_e3693.member_2)) - _e3697);
                                                                    local_319 = _e3707;
                                                                    local_320 = floor(_e3702);
                                                                    local_321 = floor(_e3707);
                                                                    let _e3710 = local_302;
                                                                    if _e3710 {
                                                                        phi_3010_ = 0f;
                                                                        phi_3011_ = 0f;
                                                                    } else {
                                                                        let _e3711 = local_317;
                                                                        let _e3712 = local_320;
                                                                        let _e3714 = local_319;
                                                                        let _e3715 = local_321;
                                                                        phi_3010_ = (_e3714 - _e3715);
                                                                        phi_3011_ = (_e3711 - _e3712);
                                                                    }
                                                                    let _e3718 = phi_3010_;
                                                                    let _e3720 = phi_3011_;
                                                                    local_322 = _e3718;
                                                                    local_323 = _e3720;
                                                                    let _e3721 = local_320;
                                                                    let _e3723 = local_320;
                                                                    let _e3726 = local_320;
                                                                    let _e3730 = local_320;
                                                                    let _e3731 = local_320;
                                                                    let _e3733 = select(0i, select(select(i32(_e3721), i32(-2147483648), !((_e3723 >= -2147483600f))), 2147483647i, (_e3726 > 2147483500f)), (_e3730 == _e3731));
                                                                    local_324 = _e3733;
                                                                    let _e3734 = local_321;
                                                                    let _e3736 = local_321;
                                                                    let _e3739 = local_321;
                                                                    let _e3743 = local_321;
                                                                    let _e3744 = local_321;
                                                                    let _e3746 = select(0i, select(select(i32(_e3734), i32(-2147483648), !((_e3736 >= -2147483600f))), 2147483647i, (_e3739 > 2147483500f)), (_e3743 == _e3744));
                                                                    local_325 = _e3746;
                                                                    let _e3747 = local_314;
                                                                    local_326 = _e3747.member_3;
                                                                    let _e3749 = local_316;
                                                                    local_327 = bitcast<i32>(_e3749);
                                                                    let _e3751 = (_e3747.member_3 == 1u);
                                                                    local_328 = _e3751;
                                                                    if _e3751 {
                                                                        let _e3805 = local_324;
                                                                        if (_e3805 < 0i) {
                                                                            phi_3047_ = 0i;
                                                                        } else {
                                                                            let _e3807 = local_324;
                                                                            let _e3808 = local_327;
                                                                            if (_e3807 >= _e3808) {
                                                                                let _e3810 = local_327;
                                                                                phi_3046_ = (_e3810 - 1i);
                                                                            } else {
                                                                                phi_3046_ = _e3733;
                                                                            }
                                                                            let _e3813 = phi_3046_;
                                                                            phi_3047_ = _e3813;
                                                                        }
                                                                        let _e3815 = phi_3047_;
                                                                        phi_3107_ = _e3815;
                                                                    } else {
                                                                        let _e3752 = local_326;
                                                                        if (_e3752 == 2u) {
                                                                            let _e3774 = local_327;
                                                                            let _e3775 = (2i * _e3774);
                                                                            local_329 = _e3775;
                                                                            let _e3776 = (_e3775 == 0i);
                                                                            local_330 = _e3776;
                                                                            if _e3776 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3777 = local_329;
                                                                            let _e3778 = (_e3777 == -1i);
                                                                            local_331 = _e3778;
                                                                            let _e3779 = local_324;
                                                                            if (_e3778 && (_e3779 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3782 = local_324;
                                                                            let _e3783 = local_329;
                                                                            let _e3785 = local_329;
                                                                            local_332 = ((_e3782 % _e3783) + _e3785);
                                                                            let _e3787 = local_330;
                                                                            if _e3787 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3788 = local_332;
                                                                            let _e3790 = local_331;
                                                                            if (_e3790 && (_e3788 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3792 = local_332;
                                                                            let _e3793 = local_329;
                                                                            let _e3794 = (_e3792 % _e3793);
                                                                            local_333 = _e3794;
                                                                            let _e3795 = local_327;
                                                                            if (_e3794 < _e3795) {
                                                                                phi_3082_ = _e3794;
                                                                            } else {
                                                                                let _e3797 = local_329;
                                                                                let _e3799 = local_333;
                                                                                phi_3082_ = ((_e3797 - 1i) - _e3799);
                                                                            }
                                                                            let _e3802 = phi_3082_;
                                                                            phi_3106_ = _e3802;
                                                                        } else {
                                                                            let _e3754 = local_327;
                                                                            let _e3755 = (_e3754 == 0i);
                                                                            local_334 = _e3755;
                                                                            if _e3755 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3756 = local_327;
                                                                            let _e3757 = (_e3756 == -1i);
                                                                            local_335 = _e3757;
                                                                            let _e3758 = local_324;
                                                                            if (_e3757 && (_e3758 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3761 = local_324;
                                                                            let _e3762 = local_327;
                                                                            let _e3764 = local_327;
                                                                            local_336 = ((_e3761 % _e3762) + _e3764);
                                                                            let _e3766 = local_334;
                                                                            if _e3766 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3767 = local_336;
                                                                            let _e3769 = local_335;
                                                                            if (_e3769 && (_e3767 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3771 = local_336;
                                                                            let _e3772 = local_327;
                                                                            phi_3106_ = (_e3771 % _e3772);
                                                                        }
                                                                        let _e3804 = phi_3106_;
                                                                        phi_3107_ = _e3804;
                                                                    }
                                                                    let _e3817 = phi_3107_;
                                                                    local_337 = bitcast<u32>(_e3817);
                                                                    let _e3819 = local_324;
                                                                    let _e3820 = (_e3819 + 1i);
                                                                    local_338 = _e3820;
                                                                    let _e3821 = local_328;
                                                                    if _e3821 {
                                                                        let _e3875 = local_338;
                                                                        if (_e3875 < 0i) {
                                                                            phi_3127_ = 0i;
                                                                        } else {
                                                                            let _e3877 = local_338;
                                                                            let _e3878 = local_327;
                                                                            if (_e3877 >= _e3878) {
                                                                                let _e3880 = local_327;
                                                                                phi_3126_ = (_e3880 - 1i);
                                                                            } else {
                                                                                phi_3126_ = _e3820;
                                                                            }
                                                                            let _e3883 = phi_3126_;
                                                                            phi_3127_ = _e3883;
                                                                        }
                                                                        let _e3885 = phi_3127_;
                                                                        phi_3187_ = _e3885;
                                                                    } else {
                                                                        let _e3822 = local_326;
                                                                        if (_e3822 == 2u) {
                                                                            let _e3844 = local_327;
                                                                            let _e3845 = (2i * _e3844);
                                                                            local_339 = _e3845;
                                                                            let _e3846 = (_e3845 == 0i);
                                                                            local_340 = _e3846;
                                                                            if _e3846 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3847 = local_339;
                                                                            let _e3848 = (_e3847 == -1i);
                                                                            local_341 = _e3848;
                                                                            let _e3849 = local_338;
                                                                            if (_e3848 && (_e3849 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3852 = local_338;
                                                                            let _e3853 = local_339;
                                                                            let _e3855 = local_339;
                                                                            local_342 = ((_e3852 % _e3853) + _e3855);
                                                                            let _e3857 = local_340;
                                                                            if _e3857 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3858 = local_342;
                                                                            let _e3860 = local_341;
                                                                            if (_e3860 && (_e3858 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3862 = local_342;
                                                                            let _e3863 = local_339;
                                                                            let _e3864 = (_e3862 % _e3863);
                                                                            local_343 = _e3864;
                                                                            let _e3865 = local_327;
                                                                            if (_e3864 < _e3865) {
                                                                                phi_3162_ = _e3864;
                                                                            } else {
                                                                                let _e3867 = local_339;
                                                                                let _e3869 = local_343;
                                                                                phi_3162_ = ((_e3867 - 1i) - _e3869);
                                                                            }
                                                                            let _e3872 = phi_3162_;
                                                                            phi_3186_ = _e3872;
                                                                        } else {
                                                                            let _e3824 = local_327;
                                                                            let _e3825 = (_e3824 == 0i);
                                                                            local_344 = _e3825;
                                                                            if _e3825 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3826 = local_327;
                                                                            let _e3827 = (_e3826 == -1i);
                                                                            local_345 = _e3827;
                                                                            let _e3828 = local_338;
                                                                            if (_e3827 && (_e3828 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3831 = local_338;
                                                                            let _e3832 = local_327;
                                                                            let _e3834 = local_327;
                                                                            local_346 = ((_e3831 % _e3832) + _e3834);
                                                                            let _e3836 = local_344;
                                                                            if _e3836 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3837 = local_346;
                                                                            let _e3839 = local_345;
                                                                            if (_e3839 && (_e3837 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3841 = local_346;
                                                                            let _e3842 = local_327;
                                                                            phi_3186_ = (_e3841 % _e3842);
                                                                        }
                                                                        let _e3874 = phi_3186_;
                                                                        phi_3187_ = _e3874;
                                                                    }
                                                                    let _e3887 = phi_3187_;
                                                                    local_347 = bitcast<u32>(_e3887);
                                                                    let _e3889 = local_314;
                                                                    local_348 = _e3889.member_4;
                                                                    let _e3891 = local_318;
                                                                    local_349 = bitcast<i32>(_e3891);
                                                                    let _e3893 = (_e3889.member_4 == 1u);
                                                                    local_350 = _e3893;
                                                                    if _e3893 {
                                                                        let _e3947 = local_325;
                                                                        if (_e3947 < 0i) {
                                                                            phi_3206_ = 0i;
                                                                        } else {
                                                                            let _e3949 = local_325;
                                                                            let _e3950 = local_349;
                                                                            if (_e3949 >= _e3950) {
                                                                                let _e3952 = local_349;
                                                                                phi_3205_ = (_e3952 - 1i);
                                                                            } else {
                                                                                phi_3205_ = _e3746;
                                                                            }
                                                                            let _e3955 = phi_3205_;
                                                                            phi_3206_ = _e3955;
                                                                        }
                                                                        let _e3957 = phi_3206_;
                                                                        phi_3266_ = _e3957;
                                                                    } else {
                                                                        let _e3894 = local_348;
                                                                        if (_e3894 == 2u) {
                                                                            let _e3916 = local_349;
                                                                            let _e3917 = (2i * _e3916);
                                                                            local_351 = _e3917;
                                                                            let _e3918 = (_e3917 == 0i);
                                                                            local_352 = _e3918;
                                                                            if _e3918 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3919 = local_351;
                                                                            let _e3920 = (_e3919 == -1i);
                                                                            local_353 = _e3920;
                                                                            let _e3921 = local_325;
                                                                            if (_e3920 && (_e3921 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3924 = local_325;
                                                                            let _e3925 = local_351;
                                                                            let _e3927 = local_351;
                                                                            local_354 = ((_e3924 % _e3925) + _e3927);
                                                                            let _e3929 = local_352;
                                                                            if _e3929 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3930 = local_354;
                                                                            let _e3932 = local_353;
                                                                            if (_e3932 && (_e3930 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3934 = local_354;
                                                                            let _e3935 = local_351;
                                                                            let _e3936 = (_e3934 % _e3935);
                                                                            local_355 = _e3936;
                                                                            let _e3937 = local_349;
                                                                            if (_e3936 < _e3937) {
                                                                                phi_3241_ = _e3936;
                                                                            } else {
                                                                                let _e3939 = local_351;
                                                                                let _e3941 = local_355;
                                                                                phi_3241_ = ((_e3939 - 1i) - _e3941);
                                                                            }
                                                                            let _e3944 = phi_3241_;
                                                                            phi_3265_ = _e3944;
                                                                        } else {
                                                                            let _e3896 = local_349;
                                                                            let _e3897 = (_e3896 == 0i);
                                                                            local_356 = _e3897;
                                                                            if _e3897 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3898 = local_349;
                                                                            let _e3899 = (_e3898 == -1i);
                                                                            local_357 = _e3899;
                                                                            let _e3900 = local_325;
                                                                            if (_e3899 && (_e3900 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3903 = local_325;
                                                                            let _e3904 = local_349;
                                                                            let _e3906 = local_349;
                                                                            local_358 = ((_e3903 % _e3904) + _e3906);
                                                                            let _e3908 = local_356;
                                                                            if _e3908 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3909 = local_358;
                                                                            let _e3911 = local_357;
                                                                            if (_e3911 && (_e3909 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3913 = local_358;
                                                                            let _e3914 = local_349;
                                                                            phi_3265_ = (_e3913 % _e3914);
                                                                        }
                                                                        let _e3946 = phi_3265_;
                                                                        phi_3266_ = _e3946;
                                                                    }
                                                                    let _e3959 = phi_3266_;
                                                                    local_359 = bitcast<u32>(_e3959);
                                                                    let _e3961 = local_325;
                                                                    let _e3962 = (_e3961 + 1i);
                                                                    local_360 = _e3962;
                                                                    let _e3963 = local_350;
                                                                    if _e3963 {
                                                                        let _e4017 = local_360;
                                                                        if (_e4017 < 0i) {
                                                                            phi_3286_ = 0i;
                                                                        } else {
                                                                            let _e4019 = local_360;
                                                                            let _e4020 = local_349;
                                                                            if (_e4019 >= _e4020) {
                                                                                let _e4022 = local_349;
                                                                                phi_3285_ = (_e4022 - 1i);
                                                                            } else {
                                                                                phi_3285_ = _e3962;
                                                                            }
                                                                            let _e4025 = phi_3285_;
                                                                            phi_3286_ = _e4025;
                                                                        }
                                                                        let _e4027 = phi_3286_;
                                                                        phi_3346_ = _e4027;
                                                                    } else {
                                                                        let _e3964 = local_348;
                                                                        if (_e3964 == 2u) {
                                                                            let _e3986 = local_349;
                                                                            let _e3987 = (2i * _e3986);
                                                                            local_361 = _e3987;
                                                                            let _e3988 = (_e3987 == 0i);
                                                                            local_362 = _e3988;
                                                                            if _e3988 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3989 = local_361;
                                                                            let _e3990 = (_e3989 == -1i);
                                                                            local_363 = _e3990;
                                                                            let _e3991 = local_360;
                                                                            if (_e3990 && (_e3991 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3994 = local_360;
                                                                            let _e3995 = local_361;
                                                                            let _e3997 = local_361;
                                                                            local_364 = ((_e3994 % _e3995) + _e3997);
                                                                            let _e3999 = local_362;
                                                                            if _e3999 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4000 = local_364;
                                                                            let _e4002 = local_363;
                                                                            if (_e4002 && (_e4000 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e4004 = local_364;
                                                                            let _e4005 = local_361;
                                                                            let _e4006 = (_e4004 % _e4005);
                                                                            local_365 = _e4006;
                                                                            let _e4007 = local_349;
                                                                            if (_e4006 < _e4007) {
                                                                                phi_3321_ = _e4006;
                                                                            } else {
                                                                                let _e4009 = local_361;
                                                                                let _e4011 = local_365;
                                                                                phi_3321_ = ((_e4009 - 1i) - _e4011);
                                                                            }
                                                                            let _e4014 = phi_3321_;
                                                                            phi_3345_ = _e4014;
                                                                        } else {
                                                                            let _e3966 = local_349;
                                                                            let _e3967 = (_e3966 == 0i);
                                                                            local_366 = _e3967;
                                                                            if _e3967 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3968 = local_349;
                                                                            let _e3969 = (_e3968 == -1i);
                                                                            local_367 = _e3969;
                                                                            let _e3970 = local_360;
                                                                            if (_e3969 && (_e3970 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3973 = local_360;
                                                                            let _e3974 = local_349;
                                                                            let _e3976 = local_349;
                                                                            local_368 = ((_e3973 % _e3974) + _e3976);
                                                                            let _e3978 = local_366;
                                                                            if _e3978 {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3979 = local_368;
                                                                            let _e3981 = local_367;
                                                                            if (_e3981 && (_e3979 == i32(-2147483648))) {
                                                                                phi_5822_ = true;
                                                                                break;
                                                                            }
                                                                            let _e3983 = local_368;
                                                                            let _e3984 = local_349;
                                                                            phi_3345_ = (_e3983 % _e3984);
                                                                        }
                                                                        let _e4016 = phi_3345_;
                                                                        phi_3346_ = _e4016;
                                                                    }
                                                                    let _e4029 = phi_3346_;
                                                                    local_369 = bitcast<u32>(_e4029);
                                                                    let _e4031 = local_314;
                                                                    local_370 = _e4031.member;
                                                                    let _e4033 = local_359;
                                                                    let _e4034 = local_316;
                                                                    let _e4036 = (_e4031.member + (_e4033 * _e4034));
                                                                    local_371 = _e4036;
                                                                    let _e4037 = local_337;
                                                                    let _e4039 = ((_e4036 + _e4037) * 2u);
                                                                    local_372 = _e4039;
                                                                    let _e4040 = local_6;
                                                                    if (_e4039 < _e4040) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4042 = local_372;
                                                                    let _e4045 = global_9.member[_e4042];
                                                                    local_373 = _e4045;
                                                                    let _e4046 = local_372;
                                                                    let _e4047 = (_e4046 + 1u);
                                                                    local_374 = _e4047;
                                                                    let _e4048 = local_6;
                                                                    if (_e4047 < _e4048) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4050 = local_374;
                                                                    let _e4053 = global_9.member[_e4050];
                                                                    local_375 = _e4053;
                                                                    let _e4054 = local_373;
                                                                    let _e4055 = (_e4054 & 65535u);
                                                                    local_587 = select(-1f, 1f, ((_e4055 & 32768u) == 0u));
                                                                    let _e4061 = ((_e4055 >> bitcast<u32>(10i)) & 31u);
                                                                    local_376 = _e4061;
                                                                    local_377 = (_e4055 & 1023u);
                                                                    if (_e4061 == 0u) {
                                                                        let _e4083 = local_377;
                                                                        let _e4085 = local_587;
                                                                        phi_3416_ = ((_e4085 * f32(_e4083)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4064 = local_376;
                                                                        if (_e4064 == 31u) {
                                                                            let _e4074 = local_377;
                                                                            phi_3413_ = (2139095040u | (_e4074 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4066 = local_376;
                                                                            let _e4070 = local_377;
                                                                            phi_3413_ = (((_e4066 + 112u) << bitcast<u32>(23i)) | (_e4070 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4079 = phi_3413_;
                                                                        let _e4081 = local_587;
                                                                        phi_3416_ = (_e4081 * bitcast<f32>(_e4079));
                                                                    }
                                                                    let _e4089 = phi_3416_;
                                                                    local_378 = _e4089;
                                                                    let _e4090 = local_373;
                                                                    let _e4092 = (_e4090 >> bitcast<u32>(16i));
                                                                    local_588 = select(-1f, 1f, ((_e4092 & 32768u) == 0u));
                                                                    let _e4098 = ((_e4092 >> bitcast<u32>(10i)) & 31u);
                                                                    local_379 = _e4098;
                                                                    local_380 = (_e4092 & 1023u);
                                                                    if (_e4098 == 0u) {
                                                                        let _e4120 = local_380;
                                                                        let _e4122 = local_588;
                                                                        phi_3448_ = ((_e4122 * f32(_e4120)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4101 = local_379;
                                                                        if (_e4101 == 31u) {
                                                                            let _e4111 = local_380;
                                                                            phi_3445_ = (2139095040u | (_e4111 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4103 = local_379;
                                                                            let _e4107 = local_380;
                                                                            phi_3445_ = (((_e4103 + 112u) << bitcast<u32>(23i)) | (_e4107 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4116 = phi_3445_;
                                                                        let _e4118 = local_588;
                                                                        phi_3448_ = (_e4118 * bitcast<f32>(_e4116));
                                                                    }
                                                                    let _e4126 = phi_3448_;
                                                                    local_381 = _e4126;
                                                                    let _e4127 = local_375;
                                                                    let _e4128 = (_e4127 & 65535u);
                                                                    local_589 = select(-1f, 1f, ((_e4128 & 32768u) == 0u));
                                                                    let _e4134 = ((_e4128 >> bitcast<u32>(10i)) & 31u);
                                                                    local_382 = _e4134;
                                                                    local_383 = (_e4128 & 1023u);
                                                                    if (_e4134 == 0u) {
                                                                        let _e4156 = local_383;
                                                                        let _e4158 = local_589;
                                                                        phi_3480_ = ((_e4158 * f32(_e4156)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4137 = local_382;
                                                                        if (_e4137 == 31u) {
                                                                            let _e4147 = local_383;
                                                                            phi_3477_ = (2139095040u | (_e4147 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4139 = local_382;
                                                                            let _e4143 = local_383;
                                                                            phi_3477_ = (((_e4139 + 112u) << bitcast<u32>(23i)) | (_e4143 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4152 = phi_3477_;
                                                                        let _e4154 = local_589;
                                                                        phi_3480_ = (_e4154 * bitcast<f32>(_e4152));
                                                                    }
                                                                    let _e4162 = phi_3480_;
                                                                    local_384 = _e4162;
                                                                    let _e4163 = local_375;
                                                                    let _e4165 = (_e4163 >> bitcast<u32>(16i));
                                                                    local_590 = select(-1f, 1f, ((_e4165 & 32768u) == 0u));
                                                                    let _e4171 = ((_e4165 >> bitcast<u32>(10i)) & 31u);
                                                                    local_385 = _e4171;
                                                                    local_386 = (_e4165 & 1023u);
                                                                    if (_e4171 == 0u) {
                                                                        let _e4193 = local_386;
                                                                        let _e4195 = local_590;
                                                                        phi_3512_ = ((_e4195 * f32(_e4193)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4174 = local_385;
                                                                        if (_e4174 == 31u) {
                                                                            let _e4184 = local_386;
                                                                            phi_3509_ = (2139095040u | (_e4184 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4176 = local_385;
                                                                            let _e4180 = local_386;
                                                                            phi_3509_ = (((_e4176 + 112u) << bitcast<u32>(23i)) | (_e4180 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4189 = phi_3509_;
                                                                        let _e4191 = local_590;
                                                                        phi_3512_ = (_e4191 * bitcast<f32>(_e4189));
                                                                    }
                                                                    let _e4199 = phi_3512_;
                                                                    local_387 = _e4199;
                                                                    let _e4200 = local_371;
                                                                    let _e4201 = local_347;
                                                                    let _e4203 = ((_e4200 + _e4201) * 2u);
                                                                    local_388 = _e4203;
                                                                    let _e4204 = local_6;
                                                                    if (_e4203 < _e4204) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4206 = local_388;
                                                                    let _e4209 = global_9.member[_e4206];
                                                                    local_389 = _e4209;
                                                                    let _e4210 = local_388;
                                                                    let _e4211 = (_e4210 + 1u);
                                                                    local_390 = _e4211;
                                                                    let _e4212 = local_6;
                                                                    if (_e4211 < _e4212) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4214 = local_390;
                                                                    let _e4217 = global_9.member[_e4214];
                                                                    local_391 = _e4217;
                                                                    let _e4218 = local_389;
                                                                    let _e4219 = (_e4218 & 65535u);
                                                                    local_591 = select(-1f, 1f, ((_e4219 & 32768u) == 0u));
                                                                    let _e4225 = ((_e4219 >> bitcast<u32>(10i)) & 31u);
                                                                    local_392 = _e4225;
                                                                    local_393 = (_e4219 & 1023u);
                                                                    if (_e4225 == 0u) {
                                                                        let _e4247 = local_393;
                                                                        let _e4249 = local_591;
                                                                        phi_3581_ = ((_e4249 * f32(_e4247)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4228 = local_392;
                                                                        if (_e4228 == 31u) {
                                                                            let _e4238 = local_393;
                                                                            phi_3578_ = (2139095040u | (_e4238 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4230 = local_392;
                                                                            let _e4234 = local_393;
                                                                            phi_3578_ = (((_e4230 + 112u) << bitcast<u32>(23i)) | (_e4234 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4243 = phi_3578_;
                                                                        let _e4245 = local_591;
                                                                        phi_3581_ = (_e4245 * bitcast<f32>(_e4243));
                                                                    }
                                                                    let _e4253 = phi_3581_;
                                                                    local_394 = _e4253;
                                                                    let _e4254 = local_389;
                                                                    let _e4256 = (_e4254 >> bitcast<u32>(16i));
                                                                    local_592 = select(-1f, 1f, ((_e4256 & 32768u) == 0u));
                                                                    let _e4262 = ((_e4256 >> bitcast<u32>(10i)) & 31u);
                                                                    local_395 = _e4262;
                                                                    local_396 = (_e4256 & 1023u);
                                                                    if (_e4262 == 0u) {
                                                                        let _e4284 = local_396;
                                                                        let _e4286 = local_592;
                                                                        phi_3613_ = ((_e4286 * f32(_e4284)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4265 = local_395;
                                                                        if (_e4265 == 31u) {
                                                                            let _e4275 = local_396;
                                                                            phi_3610_ = (2139095040u | (_e4275 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4267 = local_395;
                                                                            let _e4271 = local_396;
                                                                            phi_3610_ = (((_e4267 + 112u) << bitcast<u32>(23i)) | (_e4271 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4280 = phi_3610_;
                                                                        let _e4282 = local_592;
                                                                        phi_3613_ = (_e4282 * bitcast<f32>(_e4280));
                                                                    }
                                                                    let _e4290 = phi_3613_;
                                                                    local_397 = _e4290;
                                                                    let _e4291 = local_391;
                                                                    let _e4292 = (_e4291 & 65535u);
                                                                    local_593 = select(-1f, 1f, ((_e4292 & 32768u) == 0u));
                                                                    let _e4298 = ((_e4292 >> bitcast<u32>(10i)) & 31u);
                                                                    local_398 = _e4298;
                                                                    local_399 = (_e4292 & 1023u);
                                                                    if (_e4298 == 0u) {
                                                                        let _e4320 = local_399;
                                                                        let _e4322 = local_593;
                                                                        phi_3645_ = ((_e4322 * f32(_e4320)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4301 = local_398;
                                                                        if (_e4301 == 31u) {
                                                                            let _e4311 = local_399;
                                                                            phi_3642_ = (2139095040u | (_e4311 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4303 = local_398;
                                                                            let _e4307 = local_399;
                                                                            phi_3642_ = (((_e4303 + 112u) << bitcast<u32>(23i)) | (_e4307 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4316 = phi_3642_;
                                                                        let _e4318 = local_593;
                                                                        phi_3645_ = (_e4318 * bitcast<f32>(_e4316));
                                                                    }
                                                                    let _e4326 = phi_3645_;
                                                                    local_400 = _e4326;
                                                                    let _e4327 = local_391;
                                                                    let _e4329 = (_e4327 >> bitcast<u32>(16i));
                                                                    local_594 = select(-1f, 1f, ((_e4329 & 32768u) == 0u));
                                                                    let _e4335 = ((_e4329 >> bitcast<u32>(10i)) & 31u);
                                                                    local_401 = _e4335;
                                                                    local_402 = (_e4329 & 1023u);
                                                                    if (_e4335 == 0u) {
                                                                        let _e4357 = local_402;
                                                                        let _e4359 = local_594;
                                                                        phi_3677_ = ((_e4359 * f32(_e4357)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4338 = local_401;
                                                                        if (_e4338 == 31u) {
                                                                            let _e4348 = local_402;
                                                                            phi_3674_ = (2139095040u | (_e4348 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4340 = local_401;
                                                                            let _e4344 = local_402;
                                                                            phi_3674_ = (((_e4340 + 112u) << bitcast<u32>(23i)) | (_e4344 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4353 = phi_3674_;
                                                                        let _e4355 = local_594;
                                                                        phi_3677_ = (_e4355 * bitcast<f32>(_e4353));
                                                                    }
                                                                    let _e4363 = phi_3677_;
                                                                    let _e4364 = local_394;
                                                                    let _e4365 = local_378;
                                                                    let _e4367 = local_323;
                                                                    let _e4369 = local_378;
                                                                    local_403 = (_e4369 + ((_e4364 - _e4365) * _e4367));
                                                                    let _e4371 = local_397;
                                                                    let _e4372 = local_381;
                                                                    let _e4374 = local_323;
                                                                    let _e4376 = local_381;
                                                                    local_404 = (_e4376 + ((_e4371 - _e4372) * _e4374));
                                                                    let _e4378 = local_400;
                                                                    let _e4379 = local_384;
                                                                    let _e4381 = local_323;
                                                                    let _e4383 = local_384;
                                                                    local_405 = (_e4383 + ((_e4378 - _e4379) * _e4381));
                                                                    let _e4385 = local_387;
                                                                    let _e4387 = local_323;
                                                                    let _e4389 = local_387;
                                                                    local_406 = (_e4389 + ((_e4363 - _e4385) * _e4387));
                                                                    let _e4391 = local_369;
                                                                    let _e4392 = local_316;
                                                                    let _e4394 = local_370;
                                                                    let _e4395 = (_e4394 + (_e4391 * _e4392));
                                                                    local_407 = _e4395;
                                                                    let _e4396 = local_337;
                                                                    let _e4398 = ((_e4395 + _e4396) * 2u);
                                                                    local_408 = _e4398;
                                                                    let _e4399 = local_6;
                                                                    if (_e4398 < _e4399) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4401 = local_408;
                                                                    let _e4404 = global_9.member[_e4401];
                                                                    local_409 = _e4404;
                                                                    let _e4405 = local_408;
                                                                    let _e4406 = (_e4405 + 1u);
                                                                    local_410 = _e4406;
                                                                    let _e4407 = local_6;
                                                                    if (_e4406 < _e4407) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4409 = local_410;
                                                                    let _e4412 = global_9.member[_e4409];
                                                                    local_411 = _e4412;
                                                                    let _e4413 = local_409;
                                                                    let _e4414 = (_e4413 & 65535u);
                                                                    local_595 = select(-1f, 1f, ((_e4414 & 32768u) == 0u));
                                                                    let _e4420 = ((_e4414 >> bitcast<u32>(10i)) & 31u);
                                                                    local_412 = _e4420;
                                                                    local_413 = (_e4414 & 1023u);
                                                                    if (_e4420 == 0u) {
                                                                        let _e4442 = local_413;
                                                                        let _e4444 = local_595;
                                                                        phi_3758_ = ((_e4444 * f32(_e4442)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4423 = local_412;
                                                                        if (_e4423 == 31u) {
                                                                            let _e4433 = local_413;
                                                                            phi_3755_ = (2139095040u | (_e4433 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4425 = local_412;
                                                                            let _e4429 = local_413;
                                                                            phi_3755_ = (((_e4425 + 112u) << bitcast<u32>(23i)) | (_e4429 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4438 = phi_3755_;
                                                                        let _e4440 = local_595;
                                                                        phi_3758_ = (_e4440 * bitcast<f32>(_e4438));
                                                                    }
                                                                    let _e4448 = phi_3758_;
                                                                    local_414 = _e4448;
                                                                    let _e4449 = local_409;
                                                                    let _e4451 = (_e4449 >> bitcast<u32>(16i));
                                                                    local_596 = select(-1f, 1f, ((_e4451 & 32768u) == 0u));
                                                                    let _e4457 = ((_e4451 >> bitcast<u32>(10i)) & 31u);
                                                                    local_415 = _e4457;
                                                                    local_416 = (_e4451 & 1023u);
                                                                    if (_e4457 == 0u) {
                                                                        let _e4479 = local_416;
                                                                        let _e4481 = local_596;
                                                                        phi_3790_ = ((_e4481 * f32(_e4479)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4460 = local_415;
                                                                        if (_e4460 == 31u) {
                                                                            let _e4470 = local_416;
                                                                            phi_3787_ = (2139095040u | (_e4470 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4462 = local_415;
                                                                            let _e4466 = local_416;
                                                                            phi_3787_ = (((_e4462 + 112u) << bitcast<u32>(23i)) | (_e4466 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4475 = phi_3787_;
                                                                        let _e4477 = local_596;
                                                                        phi_3790_ = (_e4477 * bitcast<f32>(_e4475));
                                                                    }
                                                                    let _e4485 = phi_3790_;
                                                                    local_417 = _e4485;
                                                                    let _e4486 = local_411;
                                                                    let _e4487 = (_e4486 & 65535u);
                                                                    local_597 = select(-1f, 1f, ((_e4487 & 32768u) == 0u));
                                                                    let _e4493 = ((_e4487 >> bitcast<u32>(10i)) & 31u);
                                                                    local_418 = _e4493;
                                                                    local_419 = (_e4487 & 1023u);
                                                                    if (_e4493 == 0u) {
                                                                        let _e4515 = local_419;
                                                                        let _e4517 = local_597;
                                                                        phi_3822_ = ((_e4517 * f32(_e4515)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4496 = local_418;
                                                                        if (_e4496 == 31u) {
                                                                            let _e4506 = local_419;
                                                                            phi_3819_ = (2139095040u | (_e4506 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4498 = local_418;
                                                                            let _e4502 = local_419;
                                                                            phi_3819_ = (((_e4498 + 112u) << bitcast<u32>(23i)) | (_e4502 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4511 = phi_3819_;
                                                                        let _e4513 = local_597;
                                                                        phi_3822_ = (_e4513 * bitcast<f32>(_e4511));
                                                                    }
                                                                    let _e4521 = phi_3822_;
                                                                    local_420 = _e4521;
                                                                    let _e4522 = local_411;
                                                                    let _e4524 = (_e4522 >> bitcast<u32>(16i));
                                                                    local_598 = select(-1f, 1f, ((_e4524 & 32768u) == 0u));
                                                                    let _e4530 = ((_e4524 >> bitcast<u32>(10i)) & 31u);
                                                                    local_421 = _e4530;
                                                                    local_422 = (_e4524 & 1023u);
                                                                    if (_e4530 == 0u) {
                                                                        let _e4552 = local_422;
                                                                        let _e4554 = local_598;
                                                                        phi_3854_ = ((_e4554 * f32(_e4552)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4533 = local_421;
                                                                        if (_e4533 == 31u) {
                                                                            let _e4543 = local_422;
                                                                            phi_3851_ = (2139095040u | (_e4543 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4535 = local_421;
                                                                            let _e4539 = local_422;
                                                                            phi_3851_ = (((_e4535 + 112u) << bitcast<u32>(23i)) | (_e4539 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4548 = phi_3851_;
                                                                        let _e4550 = local_598;
                                                                        phi_3854_ = (_e4550 * bitcast<f32>(_e4548));
                                                                    }
                                                                    let _e4558 = phi_3854_;
                                                                    local_423 = _e4558;
                                                                    let _e4559 = local_407;
                                                                    let _e4560 = local_347;
                                                                    let _e4562 = ((_e4559 + _e4560) * 2u);
                                                                    local_424 = _e4562;
                                                                    let _e4563 = local_6;
                                                                    if (_e4562 < _e4563) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4565 = local_424;
                                                                    let _e4568 = global_9.member[_e4565];
                                                                    local_425 = _e4568;
                                                                    let _e4569 = local_424;
                                                                    let _e4570 = (_e4569 + 1u);
                                                                    local_426 = _e4570;
                                                                    let _e4571 = local_6;
                                                                    if (_e4570 < _e4571) {
                                                                    } else {
                                                                        phi_5822_ = true;
                                                                        break;
                                                                    }
                                                                    let _e4573 = local_426;
                                                                    let _e4576 = global_9.member[_e4573];
                                                                    local_427 = _e4576;
                                                                    let _e4577 = local_425;
                                                                    let _e4578 = (_e4577 & 65535u);
                                                                    local_599 = select(-1f, 1f, ((_e4578 & 32768u) == 0u));
                                                                    let _e4584 = ((_e4578 >> bitcast<u32>(10i)) & 31u);
                                                                    local_428 = _e4584;
                                                                    local_429 = (_e4578 & 1023u);
                                                                    if (_e4584 == 0u) {
                                                                        let _e4606 = local_429;
                                                                        let _e4608 = local_599;
                                                                        phi_3923_ = ((_e4608 * f32(_e4606)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4587 = local_428;
                                                                        if (_e4587 == 31u) {
                                                                            let _e4597 = local_429;
                                                                            phi_3920_ = (2139095040u | (_e4597 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4589 = local_428;
                                                                            let _e4593 = local_429;
                                                                            phi_3920_ = (((_e4589 + 112u) << bitcast<u32>(23i)) | (_e4593 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4602 = phi_3920_;
                                                                        let _e4604 = local_599;
                                                                        phi_3923_ = (_e4604 * bitcast<f32>(_e4602));
                                                                    }
                                                                    let _e4612 = phi_3923_;
                                                                    local_430 = _e4612;
                                                                    let _e4613 = local_425;
                                                                    let _e4615 = (_e4613 >> bitcast<u32>(16i));
                                                                    local_600 = select(-1f, 1f, ((_e4615 & 32768u) == 0u));
                                                                    let _e4621 = ((_e4615 >> bitcast<u32>(10i)) & 31u);
                                                                    local_431 = _e4621;
                                                                    local_432 = (_e4615 & 1023u);
                                                                    if (_e4621 == 0u) {
                                                                        let _e4643 = local_432;
                                                                        let _e4645 = local_600;
                                                                        phi_3955_ = ((_e4645 * f32(_e4643)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4624 = local_431;
                                                                        if (_e4624 == 31u) {
                                                                            let _e4634 = local_432;
                                                                            phi_3952_ = (2139095040u | (_e4634 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4626 = local_431;
                                                                            let _e4630 = local_432;
                                                                            phi_3952_ = (((_e4626 + 112u) << bitcast<u32>(23i)) | (_e4630 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4639 = phi_3952_;
                                                                        let _e4641 = local_600;
                                                                        phi_3955_ = (_e4641 * bitcast<f32>(_e4639));
                                                                    }
                                                                    let _e4649 = phi_3955_;
                                                                    local_433 = _e4649;
                                                                    let _e4650 = local_427;
                                                                    let _e4651 = (_e4650 & 65535u);
                                                                    local_601 = select(-1f, 1f, ((_e4651 & 32768u) == 0u));
                                                                    let _e4657 = ((_e4651 >> bitcast<u32>(10i)) & 31u);
                                                                    local_434 = _e4657;
                                                                    local_435 = (_e4651 & 1023u);
                                                                    if (_e4657 == 0u) {
                                                                        let _e4679 = local_435;
                                                                        let _e4681 = local_601;
                                                                        phi_3987_ = ((_e4681 * f32(_e4679)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4660 = local_434;
                                                                        if (_e4660 == 31u) {
                                                                            let _e4670 = local_435;
                                                                            phi_3984_ = (2139095040u | (_e4670 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4662 = local_434;
                                                                            let _e4666 = local_435;
                                                                            phi_3984_ = (((_e4662 + 112u) << bitcast<u32>(23i)) | (_e4666 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4675 = phi_3984_;
                                                                        let _e4677 = local_601;
                                                                        phi_3987_ = (_e4677 * bitcast<f32>(_e4675));
                                                                    }
                                                                    let _e4685 = phi_3987_;
                                                                    local_436 = _e4685;
                                                                    let _e4686 = local_427;
                                                                    let _e4688 = (_e4686 >> bitcast<u32>(16i));
                                                                    local_602 = select(-1f, 1f, ((_e4688 & 32768u) == 0u));
                                                                    let _e4694 = ((_e4688 >> bitcast<u32>(10i)) & 31u);
                                                                    local_437 = _e4694;
                                                                    local_438 = (_e4688 & 1023u);
                                                                    if (_e4694 == 0u) {
                                                                        let _e4716 = local_438;
                                                                        let _e4718 = local_602;
                                                                        phi_4019_ = ((_e4718 * f32(_e4716)) * 0.000000059604645f);
                                                                    } else {
                                                                        let _e4697 = local_437;
                                                                        if (_e4697 == 31u) {
                                                                            let _e4707 = local_438;
                                                                            phi_4016_ = (2139095040u | (_e4707 << bitcast<u32>(13i)));
                                                                        } else {
                                                                            let _e4699 = local_437;
                                                                            let _e4703 = local_438;
                                                                            phi_4016_ = (((_e4699 + 112u) << bitcast<u32>(23i)) | (_e4703 << bitcast<u32>(13i)));
                                                                        }
                                                                        let _e4712 = phi_4016_;
                                                                        let _e4714 = local_602;
                                                                        phi_4019_ = (_e4714 * bitcast<f32>(_e4712));
                                                                    }
                                                                    let _e4722 = phi_4019_;
                                                                    let _e4723 = local_430;
                                                                    let _e4724 = local_414;
                                                                    let _e4726 = local_323;
                                                                    let _e4728 = local_414;
                                                                    let _e4730 = local_433;
                                                                    let _e4731 = local_417;
                                                                    let _e4733 = local_323;
                                                                    let _e4735 = local_417;
                                                                    let _e4737 = local_436;
                                                                    let _e4738 = local_420;
                                                                    let _e4740 = local_323;
                                                                    let _e4742 = local_420;
                                                                    let _e4744 = local_423;
                                                                    let _e4746 = local_323;
                                                                    let _e4748 = local_423;
                                                                    let _e4750 = local_403;
                                                                    let _e4752 = local_322;
                                                                    let _e4754 = local_403;
                                                                    let _e4756 = local_404;
                                                                    let _e4758 = local_322;
                                                                    let _e4760 = local_404;
                                                                    let _e4762 = local_405;
                                                                    let _e4764 = local_322;
                                                                    let _e4766 = local_405;
                                                                    let _e4768 = local_406;
                                                                    let _e4770 = local_322;
                                                                    let _e4772 = local_406;
                                                                    let _e4774 = local_315;
                                                                    let _e4776 = local_315;
                                                                    let _e4778 = local_315;
                                                                    let _e4780 = local_315;
                                                                    let _e4782 = local_312;
                                                                    let _e4785 = local_312;
                                                                    let _e4788 = local_312;
                                                                    let _e4791 = local_312;
                                                                    let _e4795 = local_311;
                                                                    phi_2974_ = (_e4795 + 1u);
                                                                    phi_2977_ = type_5((_e4782.member + ((_e4754 + (((_e4728 + ((_e4723 - _e4724) * _e4726)) - _e4750) * _e4752)) * _e4774)), (_e4785.member_1 + ((_e4760 + (((_e4735 + ((_e4730 - _e4731) * _e4733)) - _e4756) * _e4758)) * _e4776)), (_e4788.member_2 + ((_e4766 + (((_e4742 + ((_e4737 - _e4738) * _e4740)) - _e4762) * _e4764)) * _e4778)), (_e4791.member_3 + ((_e4772 + (((_e4748 + ((_e4722 - _e4744) * _e4746)) - _e4768) * _e4770)) * _e4780)));
                                                                } else {
                                                                    phi_2974_ = u32();
                                                                    phi_2977_ = type_5();
                                                                }
                                                                let _e4798 = phi_2974_;
                                                                let _e4800 = phi_2977_;
                                                                continue;
                                                                continuing {
                                                                    let _e4801 = local_313;
                                                                    phi_2973_ = _e4798;
                                                                    phi_2976_ = _e4800;
                                                                    phi_5822_ = _e3650;
                                                                    break if !(_e4801);
                                                                }
                                                            }
                                                            let _e4804 = phi_5822_;
                                                            phi_5934_ = _e4804;
                                                            if _e4804 {
                                                                break;
                                                            }
                                                            let _e4805 = local_307;
                                                            phi_5935_ = _e4804;
                                                            phi_2945_ = (_e4805 + 1u);
                                                            let _e5706 = local_630;
                                                            phi_2948_ = _e5706;
                                                        } else {
                                                            phi_5935_ = _e3650;
                                                            phi_2945_ = u32();
                                                            phi_2948_ = type_5();
                                                        }
                                                        let _e4808 = phi_5935_;
                                                        let _e4810 = phi_2945_;
                                                        let _e4812 = phi_2948_;
                                                        continue;
                                                        continuing {
                                                            let _e4813 = local_308;
                                                            phi_5868_ = _e4808;
                                                            phi_2944_ = _e4810;
                                                            phi_2947_ = _e4812;
                                                            phi_5934_ = _e4808;
                                                            break if !(_e4813);
                                                        }
                                                    }
                                                    let _e4816 = phi_5934_;
                                                    phi_5936_ = _e4816;
                                                    if _e4816 {
                                                        break;
                                                    }
                                                    let _e4817 = local_303;
                                                    phi_5937_ = _e4816;
                                                    phi_2928_ = (_e4817 + 1u);
                                                    let _e5712 = local_631;
                                                    phi_2931_ = _e5712;
                                                } else {
                                                    phi_5937_ = _e3634;
                                                    phi_2928_ = u32();
                                                    phi_2931_ = type_5();
                                                }
                                                let _e4820 = phi_5937_;
                                                let _e4822 = phi_2928_;
                                                let _e4824 = phi_2931_;
                                                continue;
                                                continuing {
                                                    let _e4825 = local_305;
                                                    phi_5869_ = _e4820;
                                                    phi_2927_ = _e4822;
                                                    phi_2930_ = _e4824;
                                                    phi_5936_ = _e4820;
                                                    break if !(_e4825);
                                                }
                                            }
                                            let _e4828 = phi_5936_;
                                            phi_5975_ = _e4828;
                                            if _e4828 {
                                                break;
                                            }
                                            let _e4829 = local_294;
                                            let _e4830 = local_293;
                                            let _e4833 = (1f / f32((_e4829 * _e4830)));
                                            let _e4834 = local_304;
                                            let _e4837 = local_304;
                                            let _e4840 = local_304;
                                            let _e4843 = local_304;
                                            phi_5954_ = _e4828;
                                            phi_4072_ = type_5((_e4834.member * _e4833), (_e4837.member_1 * _e4833), (_e4840.member_2 * _e4833), (_e4843.member_3 * _e4833));
                                        }
                                        let _e4848 = phi_5954_;
                                        let _e4850 = phi_4072_;
                                        phi_5953_ = _e4848;
                                        phi_4073_ = _e4850;
                                        phi_4074_ = _e3292;
                                    }
                                    let _e4852 = phi_5953_;
                                    let _e4854 = phi_4073_;
                                    let _e4856 = phi_4074_;
                                    if _e4856 {
                                        phi_4078_ = type_5(1f, 1f, 1f, 1f);
                                    } else {
                                        phi_4078_ = _e4854;
                                    }
                                    let _e4858 = phi_4078_;
                                    phi_5951_ = _e4852;
                                    phi_4079_ = _e4858;
                                }
                                let _e4860 = phi_5951_;
                                let _e4862 = phi_4079_;
                                phi_5950_ = _e4860;
                                phi_4080_ = _e4862;
                                phi_4081_ = _e3256;
                            }
                            let _e4864 = phi_5950_;
                            let _e4866 = phi_4080_;
                            let _e4868 = phi_4081_;
                            if _e4868 {
                                phi_4085_ = type_5(1f, 1f, 1f, 1f);
                            } else {
                                phi_4085_ = _e4866;
                            }
                            let _e4870 = phi_4085_;
                            local_620 = array<f32, 4>(_e4870.member, _e4870.member_1, _e4870.member_2, _e4870.member_3);
                            let _e4876 = local_33;
                            local_610 = _e4876;
                            let _e4878 = local_18;
                            local_611[0u] = _e4878;
                            let _e4880 = local_20;
                            local_611[1u] = _e4880;
                            let _e4882 = local_34;
                            local_611[2u] = _e4882;
                            phi_4113_ = 0u;
                            phi_4116_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            loop {
                                let _e4884 = phi_4113_;
                                let _e4886 = phi_4116_;
                                local_439 = _e4884;
                                local_440 = _e4886;
                                let _e4887 = local_439;
                                let _e4888 = (_e4887 < 3u);
                                local_441 = _e4888;
                                if _e4888 {
                                    let _e4889 = local_439;
                                    if (_e4889 < 4u) {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4891 = local_439;
                                    let _e4893 = local_610[_e4891];
                                    let _e4894 = (_e4893 * 10u);
                                    local_442 = _e4894;
                                    let _e4895 = (_e4894 + 8u);
                                    local_443 = _e4895;
                                    let _e4896 = local_2;
                                    if (_e4895 < _e4896) {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4898 = local_443;
                                    let _e4901 = global_5.member[_e4898];
                                    local_444 = _e4901;
                                    let _e4902 = local_442;
                                    let _e4903 = (_e4902 + 9u);
                                    local_445 = _e4903;
                                    let _e4904 = local_2;
                                    if (_e4903 < _e4904) {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4906 = local_445;
                                    let _e4909 = global_5.member[_e4906];
                                    local_446 = _e4909;
                                    let _e4910 = local_441;
                                    if _e4910 {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4911 = local_439;
                                    let _e4913 = local_611[_e4911];
                                    local_447 = _e4913;
                                    let _e4914 = local_444;
                                    let _e4915 = (_e4914 & 65535u);
                                    local_603 = select(-1f, 1f, ((_e4915 & 32768u) == 0u));
                                    let _e4921 = ((_e4915 >> bitcast<u32>(10i)) & 31u);
                                    local_448 = _e4921;
                                    local_449 = (_e4915 & 1023u);
                                    if (_e4921 == 0u) {
                                        let _e4943 = local_449;
                                        let _e4945 = local_603;
                                        phi_4202_ = ((_e4945 * f32(_e4943)) * 0.000000059604645f);
                                    } else {
                                        let _e4924 = local_448;
                                        if (_e4924 == 31u) {
                                            let _e4934 = local_449;
                                            phi_4199_ = (2139095040u | (_e4934 << bitcast<u32>(13i)));
                                        } else {
                                            let _e4926 = local_448;
                                            let _e4930 = local_449;
                                            phi_4199_ = (((_e4926 + 112u) << bitcast<u32>(23i)) | (_e4930 << bitcast<u32>(13i)));
                                        }
                                        let _e4939 = phi_4199_;
                                        let _e4941 = local_603;
                                        phi_4202_ = (_e4941 * bitcast<f32>(_e4939));
                                    }
                                    let _e4949 = phi_4202_;
                                    let _e4950 = local_447;
                                    let _e4952 = local_440;
                                    local_450 = (_e4952[0] + (_e4950 * _e4949));
                                    let _e4955 = local_441;
                                    if _e4955 {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e4956 = local_611[_e4911];
                                    local_451 = _e4956;
                                    let _e4957 = local_444;
                                    let _e4959 = (_e4957 >> bitcast<u32>(16i));
                                    local_604 = select(-1f, 1f, ((_e4959 & 32768u) == 0u));
                                    let _e4965 = ((_e4959 >> bitcast<u32>(10i)) & 31u);
                                    local_452 = _e4965;
                                    local_453 = (_e4959 & 1023u);
                                    if (_e4965 == 0u) {
                                        let _e4987 = local_453;
                                        let _e4989 = local_604;
                                        phi_4245_ = ((_e4989 * f32(_e4987)) * 0.000000059604645f);
                                    } else {
                                        let _e4968 = local_452;
                                        if (_e4968 == 31u) {
                                            let _e4978 = local_453;
                                            phi_4242_ = (2139095040u | (_e4978 << bitcast<u32>(13i)));
                                        } else {
                                            let _e4970 = local_452;
                                            let _e4974 = local_453;
                                            phi_4242_ = (((_e4970 + 112u) << bitcast<u32>(23i)) | (_e4974 << bitcast<u32>(13i)));
                                        }
                                        let _e4983 = phi_4242_;
                                        let _e4985 = local_604;
                                        phi_4245_ = (_e4985 * bitcast<f32>(_e4983));
                                    }
                                    let _e4993 = phi_4245_;
                                    let _e4994 = local_451;
                                    let _e4996 = local_440;
                                    local_454 = (_e4996[1] + (_e4994 * _e4993));
                                    let _e4999 = local_441;
                                    if _e4999 {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e5000 = local_611[_e4911];
                                    local_455 = _e5000;
                                    let _e5001 = local_446;
                                    let _e5002 = (_e5001 & 65535u);
                                    local_605 = select(-1f, 1f, ((_e5002 & 32768u) == 0u));
                                    let _e5008 = ((_e5002 >> bitcast<u32>(10i)) & 31u);
                                    local_456 = _e5008;
                                    local_457 = (_e5002 & 1023u);
                                    if (_e5008 == 0u) {
                                        let _e5030 = local_457;
                                        let _e5032 = local_605;
                                        phi_4288_ = ((_e5032 * f32(_e5030)) * 0.000000059604645f);
                                    } else {
                                        let _e5011 = local_456;
                                        if (_e5011 == 31u) {
                                            let _e5021 = local_457;
                                            phi_4285_ = (2139095040u | (_e5021 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5013 = local_456;
                                            let _e5017 = local_457;
                                            phi_4285_ = (((_e5013 + 112u) << bitcast<u32>(23i)) | (_e5017 << bitcast<u32>(13i)));
                                        }
                                        let _e5026 = phi_4285_;
                                        let _e5028 = local_605;
                                        phi_4288_ = (_e5028 * bitcast<f32>(_e5026));
                                    }
                                    let _e5036 = phi_4288_;
                                    let _e5037 = local_455;
                                    let _e5039 = local_440;
                                    local_458 = (_e5039[2] + (_e5037 * _e5036));
                                    let _e5042 = local_441;
                                    if _e5042 {
                                    } else {
                                        phi_5938_ = true;
                                        break;
                                    }
                                    let _e5043 = local_611[_e4911];
                                    local_459 = _e5043;
                                    let _e5044 = local_446;
                                    let _e5046 = (_e5044 >> bitcast<u32>(16i));
                                    local_606 = select(-1f, 1f, ((_e5046 & 32768u) == 0u));
                                    let _e5052 = ((_e5046 >> bitcast<u32>(10i)) & 31u);
                                    local_460 = _e5052;
                                    local_461 = (_e5046 & 1023u);
                                    if (_e5052 == 0u) {
                                        let _e5074 = local_461;
                                        let _e5076 = local_606;
                                        phi_4331_ = ((_e5076 * f32(_e5074)) * 0.000000059604645f);
                                    } else {
                                        let _e5055 = local_460;
                                        if (_e5055 == 31u) {
                                            let _e5065 = local_461;
                                            phi_4328_ = (2139095040u | (_e5065 << bitcast<u32>(13i)));
                                        } else {
                                            let _e5057 = local_460;
                                            let _e5061 = local_461;
                                            phi_4328_ = (((_e5057 + 112u) << bitcast<u32>(23i)) | (_e5061 << bitcast<u32>(13i)));
                                        }
                                        let _e5070 = phi_4328_;
                                        let _e5072 = local_606;
                                        phi_4331_ = (_e5072 * bitcast<f32>(_e5070));
                                    }
                                    let _e5080 = phi_4331_;
                                    let _e5081 = local_459;
                                    let _e5083 = local_440;
                                    let _e5086 = local_450;
                                    let _e5087 = local_454;
                                    let _e5088 = local_458;
                                    let _e5090 = local_439;
                                    phi_4114_ = (_e5090 + 1u);
                                    phi_4117_ = array<f32, 4>(_e5086, _e5087, _e5088, (_e5083[3] + (_e5081 * _e5080)));
                                } else {
                                    phi_4114_ = u32();
                                    phi_4117_ = array<f32, 4>();
                                }
                                let _e5093 = phi_4114_;
                                let _e5095 = phi_4117_;
                                continue;
                                continuing {
                                    let _e5096 = local_441;
                                    phi_4113_ = _e5093;
                                    phi_4116_ = _e5095;
                                    phi_5938_ = _e4864;
                                    break if !(_e5096);
                                }
                            }
                            let _e5099 = phi_5938_;
                            phi_5975_ = _e5099;
                            if _e5099 {
                                break;
                            }
                            let _e5100 = local_440;
                            let _e5102 = local_440;
                            let _e5104 = local_440;
                            let _e5106 = local_440;
                            local_621 = array<f32, 4>(_e5100[0], _e5102[1], _e5104[2], _e5106[3]);
                            let _e5109 = local_82;
                            let _e5110 = (_e5109 + 10u);
                            local_462 = _e5110;
                            let _e5111 = local_4;
                            if (_e5110 < _e5111) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5113 = local_462;
                            let _e5116 = global_7.member[_e5113];
                            local_463 = _e5116;
                            let _e5120 = global_3.member.member.member;
                            let _e5121 = local_72;
                            let _e5125 = local_72;
                            let _e5130 = local_72;
                            let _e5134 = (((_e5121[0] * _e5120[0]) + (_e5125[1] * _e5120[1])) + (_e5130[2] * _e5120[2]));
                            local_464 = _e5134;
                            if !((_e5134 == _e5134)) {
                                phi_5669_ = true;
                            } else {
                                let _e5137 = local_464;
                                phi_5669_ = (0f >= _e5137);
                            }
                            let _e5140 = phi_5669_;
                            let _e5141 = local_464;
                            local_607 = select(_e5141, 0f, _e5140);
                            local_622 = array<f32, 3>(0f, 0f, 0f);
                            phi_4373_ = 0u;
                            loop {
                                let _e5144 = phi_4373_;
                                local_465 = _e5144;
                                let _e5145 = local_465;
                                let _e5146 = (_e5145 < 3u);
                                local_466 = _e5146;
                                if _e5146 {
                                    let _e5147 = local_82;
                                    let _e5148 = local_465;
                                    let _e5149 = (_e5147 + _e5148);
                                    local_467 = _e5149;
                                    let _e5150 = local_4;
                                    if (_e5149 < _e5150) {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5152 = local_467;
                                    let _e5155 = global_7.member[_e5152];
                                    local_468 = bitcast<f32>(_e5155);
                                    let _e5157 = local_465;
                                    let _e5158 = (_e5157 < 4u);
                                    local_469 = _e5158;
                                    if _e5158 {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5159 = local_465;
                                    let _e5161 = local_619[_e5159];
                                    let _e5162 = local_468;
                                    local_470 = (_e5162 * _e5161);
                                    let _e5164 = local_469;
                                    if _e5164 {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5165 = local_465;
                                    let _e5167 = local_621[_e5165];
                                    let _e5168 = local_470;
                                    let _e5169 = (_e5168 * _e5167);
                                    local_471 = _e5169;
                                    let _e5170 = local_463;
                                    if ((_e5170 & 1u) == 0u) {
                                        let _e5173 = local_466;
                                        if _e5173 {
                                        } else {
                                            phi_5959_ = true;
                                            break;
                                        }
                                        let _e5174 = local_465;
                                        let _e5179 = global_3.member.member.member_4[_e5174];
                                        local_472 = _e5179;
                                        let _e5180 = local_466;
                                        if _e5180 {
                                        } else {
                                            phi_5959_ = true;
                                            break;
                                        }
                                        let _e5181 = local_465;
                                        let _e5186 = global_3.member.member.member_2[_e5181];
                                        let _e5187 = local_607;
                                        let _e5189 = local_472;
                                        let _e5191 = local_471;
                                        phi_4439_ = (_e5191 * (_e5189 + (_e5186 * _e5187)));
                                    } else {
                                        phi_4439_ = _e5169;
                                    }
                                    let _e5194 = phi_4439_;
                                    local_473 = _e5194;
                                    let _e5195 = local_82;
                                    let _e5197 = local_465;
                                    let _e5198 = ((_e5195 + 4u) + _e5197);
                                    local_474 = _e5198;
                                    let _e5199 = local_4;
                                    if (_e5198 < _e5199) {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5201 = local_474;
                                    let _e5204 = global_7.member[_e5201];
                                    local_475 = bitcast<f32>(_e5204);
                                    let _e5206 = local_469;
                                    if _e5206 {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5207 = local_465;
                                    let _e5209 = local_620[_e5207];
                                    let _e5210 = local_475;
                                    local_476 = (_e5210 * _e5209);
                                    let _e5212 = local_466;
                                    if _e5212 {
                                    } else {
                                        phi_5959_ = true;
                                        break;
                                    }
                                    let _e5213 = local_465;
                                    let _e5215 = local_473;
                                    let _e5216 = local_476;
                                    local_622[_e5213] = (_e5215 + _e5216);
                                    let _e5218 = local_465;
                                    phi_4374_ = (_e5218 + 1u);
                                } else {
                                    phi_4374_ = u32();
                                }
                                let _e5221 = phi_4374_;
                                continue;
                                continuing {
                                    let _e5222 = local_466;
                                    phi_4373_ = _e5221;
                                    phi_5959_ = _e5099;
                                    break if !(_e5222);
                                }
                            }
                            let _e5225 = phi_5959_;
                            phi_5975_ = _e5225;
                            if _e5225 {
                                break;
                            }
                            let _e5226 = local_463;
                            if ((_e5226 & 8u) == 0u) {
                                phi_4516_ = 1f;
                            } else {
                                let _e5229 = local_82;
                                let _e5230 = (_e5229 + 3u);
                                local_477 = _e5230;
                                let _e5231 = local_4;
                                if (_e5230 < _e5231) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e5233 = local_477;
                                let _e5236 = global_7.member[_e5233];
                                let _e5239 = local_619[3u];
                                let _e5242 = local_621[3u];
                                let _e5243 = ((bitcast<f32>(_e5236) * _e5239) * _e5242);
                                let _e5245 = select(_e5243, 0f, (_e5243 < 0f));
                                phi_4516_ = select(_e5245, 1f, (_e5245 > 1f));
                            }
                            let _e5249 = phi_4516_;
                            let _e5250 = local_622;
                            local_623 = _e5250;
                            phi_5968_ = _e5225;
                            phi_4565_ = _e5249;
                            phi_4566_ = _e820;
                        } else {
                            let _e769 = global_3.member.member_2;
                            if (_e769 == 1u) {
                                phi_4554_ = true;
                            } else {
                                let _e771 = local_13;
                                let _e772 = local_8;
                                if (_e771 < _e772) {
                                } else {
                                    phi_5975_ = true;
                                    break;
                                }
                                let _e774 = local_13;
                                let _e777 = global_11.member[_e774];
                                let _e781 = ((bitcast<u32>(bitcast<f32>(_e777)) & 2139095040u) != 2139095040u);
                                if _e781 {
                                } else {
                                    local_623 = array<f32, 3>(0f, 0f, 0f);
                                }
                                phi_4554_ = _e781;
                            }
                            let _e783 = phi_4554_;
                            local_478 = _e783;
                            if _e783 {
                                let _e787 = global_3.member.member.member_6;
                                local_623 = array<f32, 3>(_e787[0], _e787[1], _e787[2]);
                            }
                            let _e792 = local_478;
                            phi_5968_ = _e740;
                            phi_4565_ = select(0f, 1f, _e792);
                            phi_4566_ = _e707;
                        }
                        let _e5252 = phi_5968_;
                        let _e5254 = phi_4565_;
                        let _e5256 = phi_4566_;
                        local_479 = _e5254;
                        local_480 = _e5256;
                        let _e5259 = global_3.member.member_2;
                        if (_e5259 == 1u) {
                            phi_4574_ = 0u;
                            loop {
                                let _e5405 = phi_4574_;
                                local_481 = _e5405;
                                let _e5406 = local_481;
                                let _e5407 = (_e5406 < 3u);
                                local_482 = _e5407;
                                if _e5407 {
                                    let _e5408 = local_13;
                                    let _e5410 = local_481;
                                    let _e5411 = ((3u * _e5408) + _e5410);
                                    local_483 = _e5411;
                                    let _e5412 = local_7;
                                    let _e5413 = (_e5411 < _e5412);
                                    local_484 = _e5413;
                                    if _e5413 {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e5414 = local_483;
                                    let _e5417 = global_10.member[_e5414];
                                    local_485 = bitcast<f32>(_e5417);
                                    let _e5419 = local_482;
                                    if _e5419 {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e5420 = local_481;
                                    let _e5422 = local_623[_e5420];
                                    let _e5423 = local_479;
                                    let _e5425 = local_485;
                                    local_486 = bitcast<u32>((_e5425 + (_e5423 * _e5422)));
                                    let _e5428 = local_484;
                                    if _e5428 {
                                    } else {
                                        phi_5965_ = true;
                                        break;
                                    }
                                    let _e5429 = local_486;
                                    global_10.member[_e5414] = _e5429;
                                    let _e5430 = local_481;
                                    phi_4575_ = (_e5430 + 1u);
                                } else {
                                    phi_4575_ = u32();
                                }
                                let _e5433 = phi_4575_;
                                continue;
                                continuing {
                                    let _e5434 = local_482;
                                    phi_4574_ = _e5433;
                                    phi_5965_ = _e5252;
                                    break if !(_e5434);
                                }
                            }
                            let _e5437 = phi_5965_;
                            phi_5975_ = _e5437;
                            if _e5437 {
                                break;
                            }
                            phi_5978_ = _e5437;
                        } else {
                            let _e5261 = local_13;
                            let _e5262 = (_e5261 * 5u);
                            local_487 = _e5262;
                            let _e5264 = local_623[0u];
                            local_488 = bitcast<u32>(_e5264);
                            let _e5266 = local_7;
                            if (_e5262 < _e5266) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5268 = local_487;
                            let _e5271 = local_488;
                            global_10.member[_e5268] = _e5271;
                            let _e5272 = local_487;
                            let _e5273 = (_e5272 + 1u);
                            local_489 = _e5273;
                            let _e5275 = local_623[1u];
                            local_490 = bitcast<u32>(_e5275);
                            let _e5277 = local_7;
                            if (_e5273 < _e5277) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5279 = local_489;
                            let _e5282 = local_490;
                            global_10.member[_e5279] = _e5282;
                            let _e5283 = local_487;
                            let _e5284 = (_e5283 + 2u);
                            local_491 = _e5284;
                            let _e5286 = local_623[2u];
                            local_492 = bitcast<u32>(_e5286);
                            let _e5288 = local_7;
                            if (_e5284 < _e5288) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5290 = local_491;
                            let _e5293 = local_492;
                            global_10.member[_e5290] = _e5293;
                            let _e5294 = local_487;
                            let _e5295 = (_e5294 + 3u);
                            local_493 = _e5295;
                            let _e5296 = local_479;
                            local_494 = bitcast<u32>(_e5296);
                            let _e5298 = local_7;
                            if (_e5295 < _e5298) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5300 = local_493;
                            let _e5303 = local_494;
                            global_10.member[_e5300] = _e5303;
                            let _e5304 = local_487;
                            let _e5305 = (_e5304 + 4u);
                            local_495 = _e5305;
                            let _e5306 = local_480;
                            local_496 = bitcast<u32>(_e5306);
                            let _e5308 = local_7;
                            if (_e5305 < _e5308) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5310 = local_495;
                            let _e5313 = local_496;
                            global_10.member[_e5310] = _e5313;
                            let _e5316 = global_3.member.member_4;
                            local_497 = _e5316;
                            let _e5317 = local_16;
                            if _e5317 {
                                let _e5318 = local_479;
                                if (_e5318 < 1f) {
                                    phi_4788_ = _e5256;
                                } else {
                                    let _e5320 = local_480;
                                    let _e5321 = local_497;
                                    local_498 = (_e5320 * _e5321);
                                    let _e5323 = local_496;
                                    if (_e5323 == 0u) {
                                        phi_4729_ = false;
                                    } else {
                                        let _e5325 = local_496;
                                        phi_4729_ = (_e5325 <= 2139095040u);
                                    }
                                    let _e5328 = phi_4729_;
                                    if _e5328 {
                                        let _e5329 = local_498;
                                        if (_e5329 >= 0f) {
                                            let _e5331 = local_498;
                                            let _e5334 = ((bitcast<u32>(_e5331) & 2147483647u) > 2139095040u);
                                            if _e5334 {
                                                phi_4760_ = f32();
                                                phi_4761_ = f32();
                                                phi_4762_ = false;
                                            } else {
                                                let _e5335 = local_498;
                                                let _e5336 = (_e5335 == 0f);
                                                local_499 = _e5336;
                                                if _e5336 {
                                                    phi_4758_ = f32();
                                                    phi_4759_ = true;
                                                } else {
                                                    let _e5340 = global_3.member.member_3.member_1;
                                                    local_500 = _e5340;
                                                    let _e5341 = local_498;
                                                    let _e5342 = (_e5341 >= _e5340);
                                                    if _e5342 {
                                                        phi_4756_ = f32();
                                                    } else {
                                                        let _e5343 = local_498;
                                                        let _e5344 = local_480;
                                                        let _e5346 = local_500;
                                                        let _e5347 = local_498;
                                                        phi_4756_ = ((_e5343 * _e5344) / (_e5346 - _e5347));
                                                    }
                                                    let _e5351 = phi_4756_;
                                                    phi_4758_ = _e5351;
                                                    phi_4759_ = _e5342;
                                                }
                                                let _e5353 = phi_4758_;
                                                let _e5355 = phi_4759_;
                                                let _e5356 = local_499;
                                                let _e5357 = local_609;
                                                phi_4760_ = select(_e5357, 0f, _e5356);
                                                phi_4761_ = _e5353;
                                                phi_4762_ = _e5355;
                                            }
                                            let _e5360 = phi_4760_;
                                            let _e5362 = phi_4761_;
                                            let _e5364 = phi_4762_;
                                            phi_4763_ = _e5360;
                                            phi_4764_ = _e5362;
                                            phi_4765_ = _e5334;
                                            phi_4766_ = _e5364;
                                        } else {
                                            phi_4763_ = f32();
                                            phi_4764_ = f32();
                                            phi_4765_ = true;
                                            phi_4766_ = false;
                                        }
                                        let _e5366 = phi_4763_;
                                        let _e5368 = phi_4764_;
                                        let _e5370 = phi_4765_;
                                        let _e5372 = phi_4766_;
                                        phi_4767_ = _e5366;
                                        phi_4768_ = _e5368;
                                        phi_4769_ = _e5370;
                                        phi_4770_ = _e5372;
                                    } else {
                                        phi_4767_ = f32();
                                        phi_4768_ = f32();
                                        phi_4769_ = true;
                                        phi_4770_ = false;
                                    }
                                    let _e5374 = phi_4767_;
                                    let _e5376 = phi_4768_;
                                    let _e5378 = phi_4769_;
                                    let _e5380 = phi_4770_;
                                    let _e5381 = local_608;
                                    let _e5385 = local_480;
                                    let _e5386 = (_e5385 + select(_e5376, select(_e5374, _e5381, _e5378), select(_e5380, true, _e5378)));
                                    let _e5390 = local_609;
                                    phi_4788_ = select(_e5390, _e5386, ((bitcast<u32>(_e5386) & 2139095040u) != 2139095040u));
                                }
                                let _e5393 = phi_4788_;
                                phi_4789_ = _e5393;
                            } else {
                                phi_4789_ = _e707;
                            }
                            let _e5395 = phi_4789_;
                            local_501 = bitcast<u32>(_e5395);
                            let _e5397 = local_13;
                            let _e5398 = local_8;
                            if (_e5397 < _e5398) {
                            } else {
                                phi_5975_ = true;
                                break;
                            }
                            let _e5400 = local_13;
                            let _e5403 = local_501;
                            global_11.member[_e5400] = _e5403;
                            phi_5978_ = _e5252;
                        }
                        let _e5439 = phi_5978_;
                        phi_5977_ = _e5439;
                    } else {
                        phi_5977_ = _e740;
                    }
                    let _e5441 = phi_5977_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e5442 = local_11;
                    let _e5443 = local_10;
                    phi_5976_ = _e5441;
                    phi_275_ = (_e5442 + _e5443);
                } else {
                    phi_5976_ = _e740;
                    phi_275_ = u32();
                }
                let _e5446 = phi_5976_;
                let _e5448 = phi_275_;
                continue;
                continuing {
                    let _e5449 = local_12;
                    phi_5694_ = _e5446;
                    phi_274_ = _e5448;
                    phi_5975_ = _e5446;
                    break if !(_e5449);
                }
            }
            let _e5452 = phi_5975_;
            if _e5452 {
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
