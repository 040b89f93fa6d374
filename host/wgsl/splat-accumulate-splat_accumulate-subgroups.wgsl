struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_17 {
    member: u32,
    member_1: u32,
}

struct type_18 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_19 {
    member: f32,
    member_1: f32,
}

struct type_20 {
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
    member_16: type_18,
    member_17: u32,
    member_18: u32,
}

struct type_21 {
    member: type_20,
}

struct type_30 {
    member: array<u32, 2>,
    member_1: array<f32, 3>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_32 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: bool,
    member_4: bool,
}

struct type_42 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
@group(0) @binding(5) 
var<storage, read_write> global_2: type_7;
var<private> global_3: u32;
var<private> global_4: u32;
var<private> global_5: u32;
var<private> global_6: u32;
var<immediate> global_7: type_21;
@group(0) @binding(0) 
var<storage> global_8: type_7;
@group(0) @binding(1) 
var<storage> global_9: type_7;
@group(0) @binding(2) 
var<storage> global_10: type_7;
@group(0) @binding(3) 
var<storage> global_11: type_7;
@group(0) @binding(4) 
var<storage> global_12: type_7;
@group(0) @binding(6) 
var<storage, read_write> global_13: type_42;
@group(0) @binding(7) 
var<storage> global_14: type_7;
var<workgroup> global_15: array<u32, 5888>;
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
    var local_15: type_20;
    var local_16: f32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: f32;
    var local_26: f32;
    var local_27: f32;
    var local_28: f32;
    var local_29: u32;
    var local_30: f32;
    var local_31: array<f32, 2>;
    var local_32: f32;
    var local_33: f32;
    var local_34: f32;
    var local_35: f32;
    var local_36: u32;
    var local_37: bool;
    var local_38: u32;
    var local_39: bool;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
    var local_54: u32;
    var local_55: bool;
    var local_56: u32;
    var local_57: u32;
    var local_58: u32;
    var local_59: bool;
    var local_60: bool;
    var local_61: bool;
    var local_62: u32;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: bool;
    var local_67: u32;
    var local_68: bool;
    var local_69: u32;
    var local_70: u32;
    var local_71: u32;
    var local_72: u32;
    var local_73: u32;
    var local_74: u32;
    var local_75: bool;
    var local_76: u32;
    var local_77: u32;
    var local_78: u32;
    var local_79: u32;
    var local_80: bool;
    var local_81: u32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: bool;
    var local_86: bool;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: u32;
    var local_91: u32;
    var local_92: u32;
    var local_93: bool;
    var local_94: u32;
    var local_95: u32;
    var local_96: u32;
    var local_97: u32;
    var local_98: u32;
    var local_99: u32;
    var local_100: bool;
    var local_101: u32;
    var local_102: u32;
    var local_103: u32;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: u32;
    var local_112: u32;
    var local_113: u32;
    var local_114: u32;
    var local_115: u32;
    var local_116: array<f32, 3>;
    var local_117: u32;
    var local_118: f32;
    var local_119: f32;
    var local_120: u32;
    var local_121: array<u32, 2>;
    var local_122: u32;
    var local_123: u32;
    var local_124: u32;
    var local_125: u32;
    var local_126: u32;
    var local_127: u32;
    var local_128: bool;
    var local_129: u32;
    var local_130: u32;
    var local_131: type_30;
    var local_132: u32;
    var local_133: bool;
    var local_134: f32;
    var local_135: f32;
    var local_136: u32;
    var local_137: f32;
    var local_138: f32;
    var local_139: f32;
    var local_140: f32;
    var local_141: u32;
    var local_142: u32;
    var local_143: u32;
    var local_144: u32;
    var local_145: u32;
    var local_146: u32;
    var local_147: f32;
    var local_148: f32;
    var local_149: f32;
    var local_150: f32;
    var local_151: f32;
    var local_152: bool;
    var local_153: f32;
    var local_154: f32;
    var local_155: bool;
    var local_156: f32;
    var local_157: f32;
    var local_158: bool;
    var local_159: f32;
    var local_160: f32;
    var local_161: f32;
    var local_162: f32;
    var local_163: f32;
    var local_164: f32;
    var local_165: bool;
    var local_166: f32;
    var local_167: f32;
    var local_168: f32;
    var local_169: f32;
    var local_170: bool;
    var local_171: u32;
    var local_172: f32;
    var local_173: f32;
    var local_174: f32;
    var local_175: bool;
    var local_176: u32;
    var local_177: f32;
    var local_178: f32;
    var local_179: u32;
    var local_180: f32;
    var local_181: u32;
    var local_182: f32;
    var local_183: u32;
    var local_184: f32;
    var local_185: array<f32, 2>;
    var local_186: bool;
    var local_187: u32;
    var local_188: f32;
    var local_189: bool;
    var local_190: f32;
    var local_191: u32;
    var local_192: bool;
    var local_193: u32;
    var local_194: u32;
    var local_195: u32;
    var local_196: u32;
    var local_197: u32;
    var local_198: u32;
    var local_199: u32;
    var local_200: u32;
    var local_201: u32;
    var local_202: u32;
    var local_203: u32;
    var local_204: u32;
    var local_205: u32;
    var local_206: u32;
    var local_207: u32;
    var local_208: u32;
    var local_209: u32;
    var local_210: bool;
    var local_211: u32;
    var local_212: u32;
    var local_213: u32;
    var local_214: bool;
    var local_215: f32;
    var local_216: f32;
    var local_217: u32;
    var local_218: f32;
    var local_219: f32;
    var local_220: u32;
    var local_221: f32;
    var local_222: u32;
    var local_223: f32;
    var local_224: u32;
    var local_225: f32;
    var local_226: u32;
    var local_227: f32;
    var local_228: u32;
    var local_229: bool;
    var local_230: bool;
    var local_231: u32;
    var local_232: bool;
    var local_233: bool;
    var local_234: u32;
    var local_235: bool;
    var local_236: u32;
    var local_237: f32;
    var local_238: u32;
    var local_239: u32;
    var local_240: bool;
    var local_241: u32;
    var local_242: u32;
    var local_243: bool;
    var local_244: u32;
    var local_245: u32;
    var local_246: f32;
    var local_247: type_32;
    var local_248: u32;
    var local_249: u32;
    var local_250: f32;
    var local_251: f32;
    var local_252: bool;
    var local_253: array<f32, 3>;
    var local_254: bool;
    var local_255: u32;
    var local_256: f32;
    var local_257: u32;
    var local_258: f32;
    var local_259: u32;
    var local_260: f32;
    var local_261: f32;
    var local_262: f32;
    var local_263: f32;
    var local_264: bool;
    var local_265: u32;
    var local_266: u32;
    var local_267: u32;
    var local_268: f32;
    var local_269: bool;
    var local_270: f32;
    var local_271: bool;
    var local_272: f32;
    var local_273: f32;
    var local_274: bool;
    var local_275: u32;
    var local_276: u32;
    var local_277: f32;
    var local_278: u32;
    var local_279: f32;
    var local_280: bool;
    var local_281: f32;
    var local_282: f32;
    var local_283: f32;
    var local_284: f32;
    var local_285: f32;
    var local_286: f32;
    var local_287: f32;
    var local_288: bool;
    var local_289: f32;
    var local_290: bool;
    var local_291: bool;
    var local_292: bool;
    var local_293: u32;
    var local_294: f32;
    var local_295: f32;
    var local_296: f32;
    var local_297: f32;
    var local_298: f32;
    var local_299: f32;
    var local_300: f32;
    var local_301: bool;
    var local_302: f32;
    var local_303: f32;
    var local_304: f32;
    var local_305: f32;
    var local_306: bool;
    var local_307: u32;
    var local_308: f32;
    var local_309: f32;
    var local_310: f32;
    var local_311: bool;
    var local_312: u32;
    var local_313: f32;
    var local_314: f32;
    var local_315: u32;
    var local_316: f32;
    var local_317: u32;
    var local_318: f32;
    var local_319: u32;
    var local_320: f32;
    var local_321: array<f32, 2>;
    var local_322: bool;
    var local_323: f32;
    var local_324: u32;
    var local_325: f32;
    var local_326: u32;
    var local_327: f32;
    var local_328: u32;
    var local_329: f32;
    var local_330: f32;
    var local_331: f32;
    var local_332: f32;
    var local_333: bool;
    var local_334: bool;
    var local_335: bool;
    var local_336: bool;
    var local_337: f32;
    var local_338: f32;
    var local_339: bool;
    var local_340: f32;
    var local_341: f32;
    var local_342: bool;
    var local_343: f32;
    var local_344: bool;
    var local_345: f32;
    var local_346: f32;
    var local_347: bool;
    var local_348: f32;
    var local_349: f32;
    var local_350: f32;
    var local_351: u32;
    var local_352: f32;
    var local_353: u32;
    var local_354: f32;
    var local_355: u32;
    var local_356: bool;
    var local_357: f32;
    var local_358: u32;
    var local_359: bool;
    var local_360: u32;
    var local_361: u32;
    var local_362: f32;
    var local_363: u32;
    var local_364: bool;
    var local_365: u32;
    var local_366: u32;
    var local_367: f32;
    var local_368: u32;
    var local_369: bool;
    var local_370: u32;
    var local_371: u32;
    var local_372: u32;
    var local_373: bool;
    var local_374: u32;
    var local_375: u32;
    var local_376: u32;
    var local_377: bool;
    var local_378: u32;
    var local_379: u32;
    var local_380: u32;
    var local_381: u32;
    var local_382: u32;
    var local_383: u32;
    var local_384: u32;
    var local_385: u32;
    var local_386: u32;
    var local_387: u32;
    var local_388: bool;
    var local_389: u32;
    var local_390: bool;
    var local_391: u32;
    var local_392: u32;
    var local_393: u32;
    var local_394: bool;
    var local_395: u32;
    var local_396: u32;
    var local_397: u32;
    var local_398: u32;
    var local_399: bool;
    var local_400: u32;
    var local_401: bool;
    var local_402: u32;
    var local_403: u32;
    var local_404: u32;
    var local_405: u32;
    var local_406: u32;
    var local_407: u32;
    var local_408: bool;
    var local_409: u32;
    var local_410: u32;
    var local_411: bool;
    var local_412: bool;
    var local_413: u32;
    var local_414: u32;
    var local_415: f32;
    var local_416: u32;
    var local_417: f32;
    var local_418: u32;
    var local_419: f32;
    var local_420: u32;
    var local_421: f32;
    var local_422: u32;
    var local_423: bool;
    var local_424: f32;
    var local_425: bool;
    var local_426: u32;
    var local_427: u32;
    var local_428: bool;
    var local_429: u32;
    var local_430: u32;
    var local_431: bool;
    var local_432: u32;
    var local_433: u32;
    var local_434: f32;
    var local_435: f32;
    var local_436: f32;
    var local_437: u32;
    var local_438: f32;
    var local_439: u32;
    var local_440: f32;
    var local_441: u32;
    var local_442: u32;
    var local_443: u32;
    var local_444: u32;
    var local_445: u32;
    var local_446: u32;
    var local_447: u32;
    var local_448: u32;
    var local_449: u32;
    var local_450: bool;
    var local_451: u32;
    var local_452: u32;
    var local_453: u32;
    var local_454: u32;
    var local_455: bool;
    var local_456: u32;
    var local_457: u32;
    var local_458: bool;
    var local_459: u32;
    var local_460: u32;
    var local_461: f32;
    var local_462: u32;
    var local_463: f32;
    var local_464: u32;
    var local_465: u32;
    var local_466: array<f32, 3>;
    var local_467: u32;
    var local_468: u32;
    var local_469: u32;
    var local_470: u32;
    var local_471: u32;
    var local_472: u32;
    var local_473: u32;
    var local_474: u32;
    var local_475: f32;
    var local_476: f32;
    var local_477: f32;
    var local_478: u32;
    var local_479: bool;
    var local_480: f32;
    var local_481: bool;
    var local_482: f32;
    var local_483: f32;
    var local_484: u32;
    var local_485: array<u32, 1>;
    var local_486: array<bool, 1>;
    var local_487: array<bool, 1>;
    var local_488: array<bool, 1>;
    var local_489: array<u32, 1>;
    var local_490: array<bool, 1>;
    var phi_4863_: bool;
    var phi_4865_: bool;
    var phi_4866_: bool;
    var phi_4921_: array<f32, 3>;
    var phi_367_: u32;
    var phi_370_: u32;
    var phi_402_: u32;
    var phi_368_: u32;
    var phi_371_: u32;
    var phi_5074_: bool;
    var phi_427_: type_17;
    var phi_429_: type_17;
    var phi_430_: bool;
    var phi_431_: type_17;
    var phi_432_: bool;
    var phi_437_: type_17;
    var phi_580_: u32;
    var phi_581_: u32;
    var phi_5081_: bool;
    var phi_449_: u32;
    var phi_452_: u32;
    var phi_476_: u32;
    var phi_450_: u32;
    var phi_453_: u32;
    var phi_5090_: bool;
    var phi_547_: u32;
    var phi_5099_: bool;
    var phi_628_: u32;
    var phi_630_: u32;
    var phi_631_: u32;
    var phi_5096_: bool;
    var phi_703_: bool;
    var phi_705_: bool;
    var phi_706_: bool;
    var phi_751_: f32;
    var phi_762_: u32;
    var phi_763_: u32;
    var phi_5101_: bool;
    var phi_5131_: bool;
    var phi_813_: u32;
    var phi_816_: u32;
    var phi_896_: array<f32, 3>;
    var phi_907_: f32;
    var phi_933_: u32;
    var phi_946_: u32;
    var phi_985_: type_30;
    var phi_999_: f32;
    var phi_1028_: bool;
    var phi_1056_: f32;
    var phi_1057_: f32;
    var phi_1063_: f32;
    var phi_1065_: f32;
    var phi_5115_: bool;
    var phi_1180_: f32;
    var phi_1183_: f32;
    var phi_1194_: f32;
    var phi_1197_: f32;
    var phi_1221_: bool;
    var phi_1257_: bool;
    var phi_1593_: u32;
    var phi_1596_: f32;
    var phi_1598_: array<f32, 2>;
    var phi_1594_: u32;
    var phi_1597_: f32;
    var phi_1599_: array<f32, 2>;
    var phi_1651_: f32;
    var phi_1373_: f32;
    var phi_1374_: f32;
    var phi_1375_: bool;
    var phi_1376_: f32;
    var phi_1377_: bool;
    var phi_1378_: f32;
    var phi_1379_: bool;
    var phi_1429_: f32;
    var phi_1430_: f32;
    var phi_1431_: bool;
    var phi_1432_: f32;
    var phi_1433_: bool;
    var phi_1434_: f32;
    var phi_1435_: bool;
    var phi_1485_: f32;
    var phi_1486_: f32;
    var phi_1487_: bool;
    var phi_1488_: f32;
    var phi_1489_: bool;
    var phi_1490_: f32;
    var phi_1491_: bool;
    var phi_1542_: f32;
    var phi_1543_: f32;
    var phi_1544_: bool;
    var phi_1545_: f32;
    var phi_1546_: bool;
    var phi_1547_: f32;
    var phi_1548_: bool;
    var phi_1559_: f32;
    var phi_1561_: f32;
    var phi_1562_: bool;
    var phi_1563_: f32;
    var phi_1564_: bool;
    var phi_1565_: f32;
    var phi_1566_: bool;
    var phi_1571_: f32;
    var phi_1664_: f32;
    var phi_1665_: f32;
    var phi_1666_: f32;
    var phi_1672_: u32;
    var phi_1675_: f32;
    var phi_1673_: u32;
    var phi_1676_: f32;
    var phi_1195_: f32;
    var phi_1198_: f32;
    var phi_5112_: bool;
    var phi_5180_: bool;
    var phi_1181_: f32;
    var phi_1184_: f32;
    var phi_5179_: bool;
    var phi_1165_: f32;
    var phi_5189_: bool;
    var phi_1688_: f32;
    var phi_5188_: bool;
    var phi_1690_: f32;
    var phi_1692_: u32;
    var phi_1693_: u32;
    var phi_1714_: bool;
    var phi_5185_: bool;
    var phi_1819_: u32;
    var phi_1885_: bool;
    var phi_1887_: bool;
    var phi_1888_: bool;
    var phi_1820_: u32;
    var phi_5181_: bool;
    var phi_2119_: u32;
    var phi_2140_: bool;
    var phi_2120_: u32;
    var phi_5199_: bool;
    var phi_5210_: bool;
    var phi_2153_: u32;
    var phi_2183_: u32;
    var phi_2186_: u32;
    var phi_2210_: u32;
    var phi_2184_: u32;
    var phi_2187_: u32;
    var phi_5207_: bool;
    var phi_5214_: bool;
    var phi_2212_: u32;
    var phi_5213_: bool;
    var phi_2154_: u32;
    var phi_5212_: bool;
    var phi_5218_: bool;
    var phi_2243_: f32;
    var phi_2246_: type_32;
    var phi_2248_: u32;
    var phi_2250_: u32;
    var phi_2252_: f32;
    var phi_2254_: f32;
    var phi_2256_: bool;
    var phi_2258_: array<f32, 3>;
    var phi_3222_: bool;
    var phi_3268_: bool;
    var phi_3604_: u32;
    var phi_3607_: f32;
    var phi_3609_: array<f32, 2>;
    var phi_3605_: u32;
    var phi_3608_: f32;
    var phi_3610_: array<f32, 2>;
    var phi_3662_: f32;
    var phi_3384_: f32;
    var phi_3385_: f32;
    var phi_3386_: bool;
    var phi_3387_: f32;
    var phi_3388_: bool;
    var phi_3389_: f32;
    var phi_3390_: bool;
    var phi_3440_: f32;
    var phi_3441_: f32;
    var phi_3442_: bool;
    var phi_3443_: f32;
    var phi_3444_: bool;
    var phi_3445_: f32;
    var phi_3446_: bool;
    var phi_3496_: f32;
    var phi_3497_: f32;
    var phi_3498_: bool;
    var phi_3499_: f32;
    var phi_3500_: bool;
    var phi_3501_: f32;
    var phi_3502_: bool;
    var phi_3553_: f32;
    var phi_3554_: f32;
    var phi_3555_: bool;
    var phi_3556_: f32;
    var phi_3557_: bool;
    var phi_3558_: f32;
    var phi_3559_: bool;
    var phi_3570_: f32;
    var phi_3572_: f32;
    var phi_3573_: bool;
    var phi_3574_: f32;
    var phi_3575_: bool;
    var phi_3576_: f32;
    var phi_3577_: bool;
    var phi_3582_: f32;
    var phi_3675_: f32;
    var phi_3676_: f32;
    var phi_3677_: f32;
    var phi_2346_: u32;
    var phi_2349_: f32;
    var phi_2351_: u32;
    var phi_3162_: f32;
    var phi_3167_: f32;
    var phi_3186_: f32;
    var phi_3189_: f32;
    var phi_3190_: u32;
    var phi_3192_: u32;
    var phi_3193_: f32;
    var phi_3194_: u32;
    var phi_2347_: u32;
    var phi_2350_: f32;
    var phi_2352_: u32;
    var phi_3195_: bool;
    var phi_5215_: bool;
    var phi_3206_: f32;
    var phi_5377_: bool;
    var phi_3211_: f32;
    var phi_5333_: bool;
    var phi_3678_: f32;
    var phi_3839_: f32;
    var phi_3763_: f32;
    var phi_3773_: type_19;
    var phi_3774_: type_19;
    var phi_3786_: f32;
    var phi_3797_: type_19;
    var phi_3849_: type_32;
    var phi_3850_: type_19;
    var phi_3935_: u32;
    var phi_3936_: f32;
    var phi_3937_: f32;
    var phi_3938_: bool;
    var phi_5323_: bool;
    var phi_3939_: f32;
    var phi_3940_: type_32;
    var phi_3941_: u32;
    var phi_3942_: f32;
    var phi_3943_: f32;
    var phi_3944_: bool;
    var phi_3945_: array<f32, 3>;
    var phi_5322_: bool;
    var phi_2244_: f32;
    var phi_2247_: type_32;
    var phi_2249_: u32;
    var phi_2251_: u32;
    var phi_2253_: f32;
    var phi_2255_: f32;
    var phi_2257_: bool;
    var phi_2259_: array<f32, 3>;
    var phi_5321_: bool;
    var phi_3949_: u32;
    var phi_3950_: u32;
    var phi_5397_: bool;
    var phi_3970_: u32;
    var phi_3971_: u32;
    var phi_5400_: bool;
    var phi_3991_: u32;
    var phi_3992_: u32;
    var phi_5403_: bool;
    var phi_4011_: u32;
    var phi_4012_: u32;
    var phi_5406_: bool;
    var phi_4032_: u32;
    var phi_4033_: u32;
    var phi_5409_: bool;
    var phi_4088_: u32;
    var phi_4137_: u32;
    var phi_4146_: bool;
    var phi_4147_: u32;
    var phi_4148_: bool;
    var phi_4149_: u32;
    var phi_4089_: u32;
    var phi_5412_: bool;
    var phi_4196_: type_17;
    var phi_4198_: type_17;
    var phi_4199_: bool;
    var phi_4200_: type_17;
    var phi_4201_: bool;
    var phi_4206_: type_17;
    var phi_4349_: u32;
    var phi_4350_: u32;
    var phi_5419_: bool;
    var phi_4218_: u32;
    var phi_4221_: u32;
    var phi_4245_: u32;
    var phi_4219_: u32;
    var phi_4222_: u32;
    var phi_5429_: bool;
    var phi_4316_: u32;
    var phi_5438_: bool;
    var phi_4397_: u32;
    var phi_5437_: bool;
    var phi_4399_: u32;
    var phi_4400_: u32;
    var phi_5436_: bool;
    var phi_814_: u32;
    var phi_817_: u32;
    var phi_4402_: bool;
    var phi_5435_: bool;
    var phi_4463_: bool;
    var phi_4465_: bool;
    var phi_4466_: bool;
    var phi_4623_: f32;
    var phi_4688_: u32;
    var phi_4691_: u32;
    var phi_4693_: u32;
    var phi_4766_: bool;
    var phi_4768_: bool;
    var phi_4769_: bool;
    var phi_4784_: u32;
    var phi_4785_: u32;
    var phi_4786_: u32;
    var phi_4787_: u32;
    var phi_4689_: u32;
    var phi_4692_: u32;
    var phi_4694_: u32;
    var phi_5440_: bool;
    var local_491: f32;
    var local_492: f32;
    var local_493: f32;
    var local_494: u32;

    let _e600 = global_16;
    let _e601 = bitcast<f32>(_e600);
    switch bitcast<i32>(0u) {
        default: {
            let _e603 = global;
            local = _e603;
            let _e604 = global_1;
            let _e605 = global_3;
            local_1 = _e605;
            let _e606 = global_4;
            local_2 = _e606;
            let _e607 = global_5;
            local_3 = _e607;
            let _e608 = global_6;
            local_4 = _e608;
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_9.member));
            local_7 = arrayLength((&global_10.member));
            local_8 = arrayLength((&global_11.member));
            local_9 = arrayLength((&global_12.member));
            local_10 = arrayLength((&global_2.member));
            let _e623 = arrayLength((&global_13.member));
            local_11 = _e623;
            local_12 = arrayLength((&global_14.member));
            local_13 = _e604.x;
            local_14 = _e604.y;
            let _e628 = global_7.member;
            local_15 = _e628;
            if (18u < _e623) {
            } else {
                break;
            }
            let _e630 = local_11;
            if (19u < _e630) {
            } else {
                break;
            }
            let _e634 = atomicLoad((&global_13.member[19u]));
            local_16 = bitcast<f32>(_e634);
            let _e636 = local_15;
            local_17 = _e636.member;
            let _e638 = local_15;
            local_18 = _e638.member_1;
            let _e640 = local_15;
            local_19 = _e640.member_2;
            let _e642 = local_15;
            local_20 = _e642.member_3;
            let _e644 = local_15;
            local_21 = _e644.member_6;
            let _e646 = local_15;
            local_22 = _e646.member_7;
            let _e648 = local_15;
            local_23 = _e648.member_8;
            let _e650 = local_15;
            local_24 = _e650.member_10;
            let _e652 = local_15;
            local_25 = _e652.member_15.member;
            local_26 = _e652.member_15.member_1;
            local_27 = _e652.member_15.member_2;
            local_28 = _e652.member_15.member_3;
            let _e658 = local_15;
            local_29 = _e658.member_16.member;
            local_30 = _e658.member_16.member_1;
            local_31 = _e658.member_16.member_2;
            local_32 = _e658.member_16.member_3[0];
            local_33 = _e658.member_16.member_3[1];
            local_34 = _e658.member_16.member_4;
            local_35 = _e658.member_16.member_5;
            local_36 = _e658.member_16.member_6;
            let _e670 = select(16u, 12u, (_e644.member_6 == 24u));
            local_473 = _e670;
            let _e671 = (_e670 == 0u);
            local_37 = _e671;
            if _e671 {
                break;
            }
            let _e672 = local_21;
            let _e673 = local_473;
            let _e674 = (_e672 / _e673);
            local_38 = _e674;
            let _e675 = (_e674 == 0u);
            local_39 = _e675;
            if _e675 {
                break;
            }
            let _e676 = local_13;
            let _e677 = local_38;
            local_40 = (_e676 / _e677);
            let _e679 = local_39;
            if _e679 {
                break;
            }
            let _e680 = local_14;
            let _e681 = local_38;
            let _e682 = (_e680 / _e681);
            local_41 = _e682;
            let _e683 = local_22;
            let _e685 = local_40;
            local_42 = ((_e682 * _e683) + _e685);
            let _e687 = local_40;
            let _e688 = local_21;
            local_43 = (_e687 * _e688);
            let _e690 = local_39;
            if _e690 {
                break;
            }
            let _e691 = local_13;
            let _e692 = local_38;
            let _e694 = local_473;
            let _e696 = local_43;
            local_44 = (_e696 + ((_e691 % _e692) * _e694));
            let _e698 = local_41;
            let _e699 = local_21;
            local_45 = (_e698 * _e699);
            let _e701 = local_39;
            if _e701 {
                break;
            }
            let _e702 = local_14;
            let _e703 = local_38;
            let _e705 = local_473;
            let _e707 = local_45;
            local_46 = (_e707 + ((_e702 % _e703) * _e705));
            let _e709 = local_42;
            let _e710 = local_9;
            if (_e709 < _e710) {
            } else {
                break;
            }
            let _e712 = local_42;
            let _e715 = global_12.member[_e712];
            local_47 = _e715;
            if ((_e715 & 1u) == 0u) {
                let _e830 = local_47;
                local_48 = (_e830 >> bitcast<u32>(1u));
                let _e833 = local_42;
                let _e834 = (2u * _e833);
                local_49 = _e834;
                let _e835 = local_8;
                if (_e834 < _e835) {
                } else {
                    break;
                }
                let _e837 = local_49;
                let _e840 = global_11.member[_e837];
                local_50 = _e840;
                let _e841 = local_49;
                let _e842 = (_e841 + 1u);
                local_51 = _e842;
                let _e843 = local_8;
                if (_e842 < _e843) {
                } else {
                    break;
                }
                let _e845 = local_51;
                let _e848 = global_11.member[_e845];
                local_52 = _e848;
                phi_367_ = _e603;
                phi_370_ = 0u;
                loop {
                    let _e850 = phi_367_;
                    let _e852 = phi_370_;
                    local_53 = _e850;
                    local_54 = _e852;
                    let _e853 = local_53;
                    let _e854 = local_52;
                    let _e855 = (_e853 < _e854);
                    local_55 = _e855;
                    if _e855 {
                        let _e856 = local_50;
                        let _e857 = local_53;
                        let _e858 = (_e856 + _e857);
                        local_56 = _e858;
                        let _e859 = local_7;
                        if (_e858 < _e859) {
                        } else {
                            phi_5074_ = true;
                            break;
                        }
                        let _e861 = local_56;
                        let _e864 = global_10.member[_e861];
                        let _e866 = ((4u * _e864) + 1u);
                        local_57 = _e866;
                        let _e867 = local_6;
                        if (_e866 < _e867) {
                        } else {
                            phi_5074_ = true;
                            break;
                        }
                        let _e869 = local_57;
                        let _e872 = global_9.member[_e869];
                        if (((_e872 >> bitcast<u32>(14u)) & 1023u) == 1023u) {
                            phi_402_ = _e852;
                        } else {
                            let _e877 = local_53;
                            phi_402_ = (_e877 + 1u);
                        }
                        let _e880 = phi_402_;
                        let _e881 = local_53;
                        phi_368_ = (_e881 + 256u);
                        phi_371_ = _e880;
                    } else {
                        phi_368_ = u32();
                        phi_371_ = u32();
                    }
                    let _e884 = phi_368_;
                    let _e886 = phi_371_;
                    continue;
                    continuing {
                        let _e887 = local_55;
                        phi_367_ = _e884;
                        phi_370_ = _e886;
                        phi_5074_ = false;
                        break if !(_e887);
                    }
                }
                let _e890 = phi_5074_;
                if _e890 {
                    break;
                }
                let _e891 = local;
                let _e892 = (4352u + _e891);
                local_58 = _e892;
                let _e893 = (_e892 < 5888u);
                local_59 = _e893;
                if _e893 {
                } else {
                    break;
                }
                let _e894 = local_58;
                let _e896 = local_54;
                global_15[_e894] = _e896;
                storageBarrier();
                workgroupBarrier();
                let _e897 = local_1;
                let _e898 = (_e897 >= 2u);
                local_60 = _e898;
                if _e898 {
                    let _e899 = local_1;
                    let _e901 = local_1;
                    if ((_e901 & (_e899 - 1u)) == 0u) {
                        let _e904 = local_2;
                        let _e905 = local_1;
                        let _e907 = ((_e904 * _e905) == 256u);
                        local_61 = _e907;
                        if _e907 {
                            let _e908 = local_1;
                            phi_427_ = type_17(1u, _e908);
                        } else {
                            phi_427_ = type_17();
                        }
                        let _e911 = phi_427_;
                        let _e912 = local_61;
                        phi_429_ = _e911;
                        phi_430_ = select(true, false, _e912);
                    } else {
                        phi_429_ = type_17();
                        phi_430_ = true;
                    }
                    let _e915 = phi_429_;
                    let _e917 = phi_430_;
                    phi_431_ = _e915;
                    phi_432_ = _e917;
                } else {
                    phi_431_ = type_17();
                    phi_432_ = true;
                }
                let _e919 = phi_431_;
                let _e921 = phi_432_;
                if _e921 {
                    phi_437_ = type_17(0u, type_17().member_1);
                } else {
                    phi_437_ = _e919;
                }
                let _e926 = phi_437_;
                local_62 = _e926.member_1;
                if (bitcast<i32>(_e926.member) != 0i) {
                    let _e963 = local_62;
                    let _e965 = local_62;
                    local_63 = select(firstTrailingBit(_e963), 32u, (_e965 == 0u));
                    phi_449_ = 0u;
                    phi_452_ = 256u;
                    loop {
                        let _e969 = phi_449_;
                        let _e971 = phi_452_;
                        local_64 = _e969;
                        local_65 = _e971;
                        let _e972 = local_65;
                        let _e973 = local_62;
                        let _e974 = (_e972 > _e973);
                        local_66 = _e974;
                        if _e974 {
                            let _e975 = local_3;
                            let _e976 = local_1;
                            let _e978 = local_4;
                            let _e979 = ((_e975 * _e976) + _e978);
                            local_67 = _e979;
                            let _e980 = local_65;
                            let _e981 = (_e979 < _e980);
                            local_68 = _e981;
                            if _e981 {
                                let _e982 = local_64;
                                let _e984 = local_67;
                                let _e987 = (4352u + (_e984 << bitcast<u32>((_e982 & 31u))));
                                local_69 = _e987;
                                if (_e987 < 5888u) {
                                } else {
                                    phi_5090_ = true;
                                    break;
                                }
                                let _e989 = local_69;
                                let _e991 = global_15[_e989];
                                phi_476_ = _e991;
                            } else {
                                phi_476_ = 0u;
                            }
                            let _e993 = phi_476_;
                            let _e994 = subgroupMax(_e993);
                            local_70 = _e994;
                            let _e995 = local_68;
                            if _e995 {
                                let _e996 = local_62;
                                let _e998 = local_67;
                                if ((_e998 & (_e996 - 1u)) == 0u) {
                                    let _e1001 = local_64;
                                    let _e1003 = local_67;
                                    let _e1006 = (4352u + (_e1003 << bitcast<u32>((_e1001 & 31u))));
                                    local_71 = _e1006;
                                    if (_e1006 < 5888u) {
                                    } else {
                                        phi_5090_ = true;
                                        break;
                                    }
                                    let _e1008 = local_71;
                                    let _e1010 = local_70;
                                    global_15[_e1008] = _e1010;
                                }
                            }
                            storageBarrier();
                            workgroupBarrier();
                            let _e1011 = local_63;
                            let _e1013 = local_65;
                            let _e1016 = local_64;
                            let _e1017 = local_63;
                            phi_450_ = (_e1016 + _e1017);
                            phi_453_ = (_e1013 >> bitcast<u32>((_e1011 & 31u)));
                        } else {
                            phi_450_ = u32();
                            phi_453_ = u32();
                        }
                        let _e1020 = phi_450_;
                        let _e1022 = phi_453_;
                        continue;
                        continuing {
                            let _e1023 = local_66;
                            phi_449_ = _e1020;
                            phi_452_ = _e1022;
                            phi_5090_ = _e890;
                            break if !(_e1023);
                        }
                    }
                    let _e1026 = phi_5090_;
                    if _e1026 {
                        break;
                    }
                    let _e1027 = local_3;
                    let _e1028 = local_1;
                    let _e1030 = local_4;
                    let _e1032 = local_62;
                    let _e1034 = (((_e1027 * _e1028) + _e1030) & (_e1032 - 1u));
                    local_72 = _e1034;
                    let _e1035 = local_65;
                    if (_e1034 < _e1035) {
                        let _e1037 = local_64;
                        let _e1039 = local_72;
                        let _e1042 = (4352u + (_e1039 << bitcast<u32>((_e1037 & 31u))));
                        local_73 = _e1042;
                        if (_e1042 < 5888u) {
                        } else {
                            break;
                        }
                        let _e1044 = local_73;
                        let _e1046 = global_15[_e1044];
                        phi_547_ = _e1046;
                    } else {
                        phi_547_ = 0u;
                    }
                    let _e1048 = phi_547_;
                    let _e1049 = subgroupMax(_e1048);
                    storageBarrier();
                    workgroupBarrier();
                    phi_5099_ = _e1026;
                    phi_628_ = _e1049;
                } else {
                    phi_580_ = 128u;
                    loop {
                        let _e932 = phi_580_;
                        local_74 = _e932;
                        let _e933 = local_74;
                        let _e934 = (_e933 > 0u);
                        local_75 = _e934;
                        if _e934 {
                            let _e935 = local;
                            let _e936 = local_74;
                            if (_e935 < _e936) {
                                let _e938 = local_59;
                                if _e938 {
                                } else {
                                    phi_5081_ = true;
                                    break;
                                }
                                let _e939 = global_15[_e894];
                                local_76 = _e939;
                                let _e940 = local_58;
                                let _e941 = local_74;
                                let _e942 = (_e940 + _e941);
                                local_77 = _e942;
                                if (_e942 < 5888u) {
                                } else {
                                    phi_5081_ = true;
                                    break;
                                }
                                let _e944 = local_77;
                                let _e946 = global_15[_e944];
                                let _e947 = local_76;
                                let _e949 = local_76;
                                local_474 = select(_e946, _e949, (_e947 > _e946));
                                let _e951 = local_59;
                                if _e951 {
                                } else {
                                    phi_5081_ = true;
                                    break;
                                }
                                let _e952 = local_474;
                                global_15[_e894] = _e952;
                            }
                            storageBarrier();
                            workgroupBarrier();
                            let _e953 = local_74;
                            phi_581_ = (_e953 / 2u);
                        } else {
                            phi_581_ = u32();
                        }
                        let _e956 = phi_581_;
                        continue;
                        continuing {
                            let _e957 = local_75;
                            phi_580_ = _e956;
                            phi_5081_ = _e890;
                            break if !(_e957);
                        }
                    }
                    let _e960 = phi_5081_;
                    if _e960 {
                        break;
                    }
                    let _e962 = global_15[4352u];
                    storageBarrier();
                    workgroupBarrier();
                    phi_5099_ = _e960;
                    phi_628_ = _e962;
                }
                let _e1051 = phi_5099_;
                let _e1053 = phi_628_;
                local_78 = _e1053;
                phi_630_ = 0u;
                loop {
                    let _e1055 = phi_630_;
                    local_79 = _e1055;
                    let _e1056 = local_79;
                    let _e1057 = (_e1056 <= 1280u);
                    local_80 = _e1057;
                    if _e1057 {
                        let _e1058 = local_79;
                        let _e1059 = local;
                        let _e1060 = (_e1058 + _e1059);
                        local_81 = _e1060;
                        if (_e1060 < 5888u) {
                        } else {
                            phi_5096_ = true;
                            break;
                        }
                        let _e1062 = local_81;
                        global_15[_e1062] = 0u;
                        let _e1064 = local_79;
                        phi_631_ = (_e1064 + 256u);
                    } else {
                        phi_631_ = u32();
                    }
                    let _e1067 = phi_631_;
                    continue;
                    continuing {
                        let _e1068 = local_80;
                        phi_630_ = _e1067;
                        phi_5096_ = _e1051;
                        break if !(_e1068);
                    }
                }
                let _e1071 = phi_5096_;
                if _e1071 {
                    break;
                }
                let _e1072 = local_37;
                if _e1072 {
                    break;
                }
                let _e1073 = local;
                let _e1074 = local_473;
                let _e1076 = local_44;
                local_82 = (_e1076 + (_e1073 % _e1074));
                let _e1078 = local_37;
                if _e1078 {
                    break;
                }
                let _e1079 = local;
                let _e1080 = local_473;
                let _e1082 = local_46;
                local_83 = (_e1082 + (_e1079 / _e1080));
                let _e1084 = local_473;
                let _e1085 = local_473;
                let _e1086 = (_e1084 * _e1085);
                local_84 = _e1086;
                let _e1087 = local;
                let _e1088 = (_e1087 < _e1086);
                local_85 = _e1088;
                if _e1088 {
                    let _e1089 = local_82;
                    let _e1090 = local_17;
                    let _e1091 = (_e1089 < _e1090);
                    local_86 = _e1091;
                    if _e1091 {
                        let _e1092 = local_83;
                        let _e1093 = local_18;
                        phi_703_ = (_e1092 < _e1093);
                    } else {
                        phi_703_ = bool();
                    }
                    let _e1096 = phi_703_;
                    let _e1097 = local_86;
                    phi_705_ = _e1096;
                    phi_706_ = select(true, false, _e1097);
                } else {
                    phi_705_ = bool();
                    phi_706_ = true;
                }
                let _e1100 = phi_705_;
                let _e1102 = phi_706_;
                if select(_e1100, false, _e1102) {
                    let _e1104 = local_83;
                    let _e1105 = local_17;
                    let _e1107 = local_82;
                    let _e1109 = (4u * ((_e1104 * _e1105) + _e1107));
                    local_87 = _e1109;
                    let _e1110 = local_5;
                    if (_e1109 < _e1110) {
                    } else {
                        break;
                    }
                    let _e1112 = local_87;
                    let _e1114 = local_5;
                    if ((_e1112 + 1u) < _e1114) {
                    } else {
                        break;
                    }
                    let _e1116 = local_87;
                    let _e1118 = local_5;
                    if ((_e1116 + 2u) < _e1118) {
                    } else {
                        break;
                    }
                    let _e1120 = local_87;
                    let _e1121 = (_e1120 + 3u);
                    local_88 = _e1121;
                    let _e1122 = local_5;
                    if (_e1121 < _e1122) {
                    } else {
                        break;
                    }
                    let _e1124 = local_88;
                    let _e1127 = global_8.member[_e1124];
                    phi_751_ = bitcast<f32>(_e1127);
                } else {
                    phi_751_ = _e601;
                }
                let _e1130 = phi_751_;
                local_89 = bitcast<u32>(_e1130);
                let _e1132 = local;
                let _e1133 = (1024u + _e1132);
                local_90 = _e1133;
                if (_e1133 < 5888u) {
                } else {
                    break;
                }
                let _e1135 = local_90;
                let _e1137 = local_89;
                global_15[_e1135] = _e1137;
                let _e1138 = local;
                local_91 = (4608u + _e1138);
                phi_762_ = 0u;
                loop {
                    let _e1141 = phi_762_;
                    local_92 = _e1141;
                    let _e1142 = local_92;
                    let _e1143 = (_e1142 < 1u);
                    local_93 = _e1143;
                    if _e1143 {
                        let _e1144 = local_91;
                        let _e1145 = local_92;
                        let _e1146 = (_e1144 + _e1145);
                        local_94 = _e1146;
                        if (_e1146 < 5888u) {
                        } else {
                            phi_5101_ = true;
                            break;
                        }
                        let _e1148 = local_94;
                        global_15[_e1148] = 2143289344u;
                        let _e1150 = local;
                        let _e1152 = local_92;
                        let _e1153 = ((_e1150 + 4864u) + _e1152);
                        local_95 = _e1153;
                        if (_e1153 < 5888u) {
                        } else {
                            phi_5101_ = true;
                            break;
                        }
                        let _e1155 = local_95;
                        global_15[_e1155] = 0u;
                        let _e1157 = local;
                        let _e1159 = local_92;
                        let _e1160 = ((_e1157 + 5120u) + _e1159);
                        local_96 = _e1160;
                        if (_e1160 < 5888u) {
                        } else {
                            phi_5101_ = true;
                            break;
                        }
                        let _e1162 = local_96;
                        global_15[_e1162] = 1065353216u;
                        let _e1164 = local;
                        let _e1166 = local_92;
                        let _e1167 = ((_e1164 + 5376u) + _e1166);
                        local_97 = _e1167;
                        if (_e1167 < 5888u) {
                        } else {
                            phi_5101_ = true;
                            break;
                        }
                        let _e1169 = local_97;
                        global_15[_e1169] = 1u;
                        let _e1171 = local_92;
                        phi_763_ = (_e1171 + 1u);
                    } else {
                        phi_763_ = u32();
                    }
                    let _e1174 = phi_763_;
                    continue;
                    continuing {
                        let _e1175 = local_93;
                        phi_762_ = _e1174;
                        phi_5101_ = _e1071;
                        break if !(_e1175);
                    }
                }
                let _e1178 = phi_5101_;
                if _e1178 {
                    break;
                }
                storageBarrier();
                workgroupBarrier();
                phi_5131_ = _e1178;
                phi_813_ = 0u;
                phi_816_ = 1u;
                loop {
                    let _e1180 = phi_5131_;
                    let _e1182 = phi_813_;
                    let _e1184 = phi_816_;
                    local_98 = _e1182;
                    local_99 = _e1184;
                    let _e1185 = local_98;
                    let _e1186 = local_52;
                    if (_e1185 < _e1186) {
                        let _e1188 = local_99;
                        let _e1189 = (_e1188 == 0u);
                        local_100 = _e1189;
                        if _e1189 {
                            phi_5437_ = _e1180;
                            phi_4399_ = u32();
                            phi_4400_ = u32();
                        } else {
                            let _e1190 = local_98;
                            let _e1191 = local;
                            let _e1192 = (_e1190 + _e1191);
                            local_101 = _e1192;
                            let _e1193 = local_52;
                            if (_e1192 < _e1193) {
                                let _e1195 = local_50;
                                let _e1196 = local_101;
                                let _e1197 = (_e1195 + _e1196);
                                local_102 = _e1197;
                                let _e1198 = local_7;
                                if (_e1197 < _e1198) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e1200 = local_102;
                                let _e1203 = global_10.member[_e1200];
                                local_103 = _e1203;
                                let _e1204 = (4u * _e1203);
                                local_104 = _e1204;
                                let _e1205 = local_6;
                                if (_e1204 < _e1205) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e1207 = local_104;
                                let _e1210 = global_9.member[_e1207];
                                local_105 = _e1210;
                                let _e1211 = local_104;
                                let _e1212 = (_e1211 + 1u);
                                local_106 = _e1212;
                                let _e1213 = local_6;
                                if (_e1212 < _e1213) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e1215 = local_106;
                                let _e1218 = global_9.member[_e1215];
                                local_107 = _e1218;
                                let _e1219 = local_104;
                                let _e1220 = (_e1219 + 2u);
                                local_108 = _e1220;
                                let _e1221 = local_6;
                                if (_e1220 < _e1221) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e1223 = local_108;
                                let _e1226 = global_9.member[_e1223];
                                local_109 = _e1226;
                                let _e1227 = local_104;
                                let _e1228 = (_e1227 + 3u);
                                local_110 = _e1228;
                                let _e1229 = local_6;
                                if (_e1228 < _e1229) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e1231 = local_110;
                                let _e1234 = global_9.member[_e1231];
                                local_111 = _e1234;
                                let _e1235 = local_105;
                                local_112 = (_e1235 & 16383u);
                                let _e1237 = local_105;
                                local_113 = ((_e1237 >> bitcast<u32>(14u)) & 16383u);
                                let _e1241 = local_107;
                                local_114 = (_e1241 & 16383u);
                                let _e1243 = local_107;
                                let _e1245 = (_e1243 >> bitcast<u32>(24i));
                                local_115 = _e1245;
                                if (_e1245 == 0u) {
                                    phi_896_ = array<f32, 3>(0f, 0f, 0f);
                                } else {
                                    let _e1247 = local_115;
                                    let _e1253 = bitcast<f32>((bitcast<u32>((bitcast<i32>(_e1247) + -13i)) << bitcast<u32>(23i)));
                                    let _e1254 = local_112;
                                    let _e1257 = local_113;
                                    let _e1260 = local_114;
                                    phi_896_ = array<f32, 3>((f32(_e1254) * _e1253), (f32(_e1257) * _e1253), (f32(_e1260) * _e1253));
                                }
                                let _e1265 = phi_896_;
                                local_116 = _e1265;
                                let _e1266 = local_107;
                                let _e1269 = ((_e1266 >> bitcast<u32>(14u)) & 1023u);
                                local_117 = _e1269;
                                if (_e1269 >= 1023u) {
                                    phi_907_ = 1f;
                                } else {
                                    let _e1271 = local_117;
                                    phi_907_ = (f32(_e1271) * 0.0009775171f);
                                }
                                let _e1275 = phi_907_;
                                local_118 = _e1275;
                                let _e1276 = local_109;
                                let _e1277 = bitcast<f32>(_e1276);
                                local_119 = _e1277;
                                let _e1278 = local_105;
                                let _e1281 = ((_e1278 >> bitcast<u32>(28i)) & 3u);
                                local_120 = _e1281;
                                let _e1282 = local_111;
                                let _e1284 = local_111;
                                let _e1287 = array<u32, 2>((_e1282 & 65535u), (_e1284 >> bitcast<u32>(16i)));
                                local_121 = _e1287;
                                let _e1288 = local_116;
                                let _e1290 = local_24;
                                let _e1293 = ((_e1290 >> bitcast<u32>(8u)) & 7u);
                                local_122 = _e1293;
                                if (_e1293 == 0u) {
                                    phi_985_ = type_30(_e1287, _e1288, _e1275, _e1277, _e1281, 0u);
                                } else {
                                    let _e1295 = local_122;
                                    let _e1296 = local_122;
                                    let _e1297 = (_e1295 * _e1296);
                                    local_123 = _e1297;
                                    if (_e1297 <= 1u) {
                                        phi_933_ = 1u;
                                    } else {
                                        let _e1299 = local_123;
                                        phi_933_ = select(16u, 4u, (_e1299 <= 4u));
                                    }
                                    let _e1303 = phi_933_;
                                    local_124 = _e1303;
                                    if (_e1303 == 0u) {
                                        phi_5435_ = true;
                                        break;
                                    }
                                    let _e1305 = local_124;
                                    local_125 = (32u / _e1305);
                                    let _e1307 = local_124;
                                    if (_e1307 >= 32u) {
                                        phi_946_ = 4294967295u;
                                    } else {
                                        let _e1309 = local_124;
                                        phi_946_ = ((1u << bitcast<u32>((_e1309 & 31u))) - 1u);
                                    }
                                    let _e1315 = phi_946_;
                                    local_126 = _e1315;
                                    let _e1316 = local_22;
                                    let _e1317 = local_23;
                                    let _e1319 = local_21;
                                    let _e1321 = local_21;
                                    let _e1323 = local_19;
                                    local_127 = (4u * ((((_e1316 * _e1317) * _e1319) * _e1321) * _e1323));
                                    let _e1326 = local_125;
                                    let _e1327 = (_e1326 == 0u);
                                    local_128 = _e1327;
                                    if _e1327 {
                                        phi_5435_ = true;
                                        break;
                                    }
                                    let _e1328 = local_103;
                                    let _e1329 = local_125;
                                    let _e1331 = local_127;
                                    local_129 = (_e1331 + (_e1328 / _e1329));
                                    let _e1333 = local_128;
                                    if _e1333 {
                                        phi_5435_ = true;
                                        break;
                                    }
                                    let _e1334 = local_103;
                                    let _e1335 = local_125;
                                    let _e1337 = local_124;
                                    local_130 = ((_e1334 % _e1335) * _e1337);
                                    let _e1339 = local_129;
                                    let _e1340 = local_6;
                                    if (_e1339 < _e1340) {
                                    } else {
                                        phi_5435_ = true;
                                        break;
                                    }
                                    let _e1342 = local_129;
                                    let _e1345 = global_9.member[_e1342];
                                    let _e1346 = local_130;
                                    let _e1350 = local_126;
                                    let _e1352 = local_121;
                                    let _e1353 = local_116;
                                    let _e1354 = local_118;
                                    let _e1355 = local_119;
                                    let _e1356 = local_120;
                                    phi_985_ = type_30(_e1352, _e1353, _e1354, _e1355, _e1356, ((_e1345 >> bitcast<u32>((_e1346 & 31u))) & _e1350));
                                }
                                let _e1359 = phi_985_;
                                local_131 = _e1359;
                                local_132 = _e1359.member_5;
                                let _e1361 = (_e1359.member_5 != 0u);
                                local_133 = _e1361;
                                if _e1361 {
                                    phi_999_ = 1.4142135f;
                                } else {
                                    let _e1362 = local_131;
                                    phi_999_ = (0.5f * f32((1u << bitcast<u32>((_e1362.member_4 & 31u)))));
                                }
                                let _e1370 = phi_999_;
                                local_134 = _e1370;
                                let _e1371 = local_131;
                                local_135 = _e1371.member_3;
                                let _e1373 = bitcast<u32>(_e1371.member_3);
                                local_136 = _e1373;
                                if (_e1373 == 2139095040u) {
                                    let _e1408 = local_26;
                                    let _e1410 = local_25;
                                    let _e1412 = local_27;
                                    let _e1413 = local_25;
                                    let _e1416 = local_28;
                                    phi_1065_ = (0.5f * ((((2f * _e1408) * _e1410) / (_e1412 - _e1413)) * _e1416));
                                } else {
                                    let _e1375 = local_136;
                                    if (_e1375 == 0u) {
                                        phi_1028_ = false;
                                    } else {
                                        let _e1377 = local_136;
                                        phi_1028_ = (_e1377 <= 2139095040u);
                                    }
                                    let _e1380 = phi_1028_;
                                    if _e1380 {
                                        let _e1381 = local_26;
                                        let _e1383 = local_25;
                                        let _e1385 = local_27;
                                        let _e1386 = local_25;
                                        let _e1389 = local_28;
                                        let _e1390 = ((((2f * _e1381) * _e1383) / (_e1385 - _e1386)) * _e1389);
                                        local_137 = _e1390;
                                        if (_e1390 == 0f) {
                                            phi_1056_ = 0f;
                                        } else {
                                            let _e1392 = local_27;
                                            let _e1393 = local_135;
                                            let _e1396 = local_137;
                                            phi_1056_ = (_e1396 * (1f - (_e1392 / _e1393)));
                                        }
                                        let _e1399 = phi_1056_;
                                        phi_1057_ = _e1399;
                                    } else {
                                        phi_1057_ = _e601;
                                    }
                                    let _e1401 = phi_1057_;
                                    local_138 = _e1401;
                                    if (_e1401 < 0f) {
                                        let _e1403 = local_138;
                                        phi_1063_ = -(_e1403);
                                    } else {
                                        phi_1063_ = _e1401;
                                    }
                                    let _e1406 = phi_1063_;
                                    phi_1065_ = (0.5f * _e1406);
                                }
                                let _e1420 = phi_1065_;
                                let _e1425 = local_134;
                                let _e1426 = (select(_e1420, 0f, ((bitcast<u32>(_e1420) & 2147483647u) > 2139095040u)) + _e1425);
                                let _e1427 = local_16;
                                let _e1429 = local_16;
                                let _e1430 = select(_e1429, _e1426, (_e1426 < _e1427));
                                local_475 = select(0.5f, _e1430, (_e1430 > 0.5f));
                                let _e1433 = local_131;
                                let _e1437 = (f32(_e1433.member[0]) * 0.5f);
                                local_139 = _e1437;
                                let _e1438 = local_131;
                                local_140 = (f32(_e1438.member[1]) * 0.5f);
                                local_141 = bitcast<u32>(_e1437);
                                let _e1444 = local;
                                let _e1445 = (1536u + _e1444);
                                local_142 = _e1445;
                                if (_e1445 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e1447 = local_142;
                                let _e1449 = local_141;
                                global_15[_e1447] = _e1449;
                                let _e1450 = local_140;
                                local_143 = bitcast<u32>(_e1450);
                                let _e1452 = local;
                                let _e1453 = (1792u + _e1452);
                                local_144 = _e1453;
                                if (_e1453 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e1455 = local_144;
                                let _e1457 = local_143;
                                global_15[_e1455] = _e1457;
                                let _e1458 = local_475;
                                local_145 = bitcast<u32>(_e1458);
                                let _e1460 = local;
                                let _e1461 = (2048u + _e1460);
                                local_146 = _e1461;
                                if (_e1461 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e1463 = local_146;
                                let _e1465 = local_145;
                                global_15[_e1463] = _e1465;
                                let _e1466 = local_135;
                                let _e1467 = local_27;
                                local_476 = select(1f, -1f, (_e1466 < _e1467));
                                let _e1470 = local_133;
                                if _e1470 {
                                    phi_5188_ = _e1180;
                                    phi_1690_ = 1f;
                                } else {
                                    let _e1471 = local_131;
                                    local_147 = f32((1u << bitcast<u32>(((2u * _e1471.member_4) & 31u))));
                                    let _e1481 = f32((1u << bitcast<u32>((_e1471.member_4 & 31u))));
                                    local_148 = _e1481;
                                    let _e1483 = local_475;
                                    if (_e1483 >= (4f + _e1481)) {
                                        let _e2010 = local_36;
                                        if (_e2010 > 0u) {
                                            let _e2024 = local_148;
                                            let _e2026 = local_475;
                                            let _e2027 = (_e2026 - (0.5f * _e2024));
                                            let _e2028 = local_35;
                                            phi_1165_ = ((_e2028 * _e2027) * _e2027);
                                        } else {
                                            let _e2012 = local_475;
                                            let _e2013 = local_148;
                                            let _e2015 = local_475;
                                            let _e2017 = local_148;
                                            let _e2018 = local_148;
                                            let _e2022 = local_35;
                                            phi_1165_ = (_e2022 * (((_e2012 - _e2013) * _e2015) + ((_e2017 * _e2018) * 0.33333334f)));
                                        }
                                        let _e2032 = phi_1165_;
                                        phi_5189_ = _e1180;
                                        phi_1688_ = _e2032;
                                    } else {
                                        let _e1485 = local_140;
                                        let _e1486 = local_475;
                                        let _e1490 = local_140;
                                        let _e1491 = local_475;
                                        local_149 = floor(((_e1490 + _e1491) - 0.5f));
                                        let _e1495 = local_139;
                                        let _e1496 = local_475;
                                        let _e1500 = local_139;
                                        let _e1501 = local_475;
                                        local_150 = floor(((_e1500 + _e1501) - 0.5f));
                                        phi_5115_ = _e1180;
                                        phi_1180_ = ceil(((_e1485 - _e1486) - 0.5f));
                                        phi_1183_ = 0f;
                                        loop {
                                            let _e1506 = phi_5115_;
                                            let _e1508 = phi_1180_;
                                            let _e1510 = phi_1183_;
                                            local_151 = _e1508;
                                            local_493 = _e1510;
                                            let _e1511 = local_151;
                                            let _e1512 = local_149;
                                            let _e1513 = (_e1511 <= _e1512);
                                            local_152 = _e1513;
                                            if _e1513 {
                                                let _e1514 = local_151;
                                                let _e1516 = local_140;
                                                local_153 = ((_e1514 + 0.5f) - _e1516);
                                                phi_1194_ = ceil(((_e1495 - _e1496) - 0.5f));
                                                phi_1197_ = _e1510;
                                                loop {
                                                    let _e1519 = phi_1194_;
                                                    let _e1521 = phi_1197_;
                                                    local_154 = _e1519;
                                                    local_492 = _e1521;
                                                    let _e1522 = local_154;
                                                    let _e1523 = local_150;
                                                    let _e1524 = (_e1522 <= _e1523);
                                                    local_155 = _e1524;
                                                    if _e1524 {
                                                        let _e1525 = local_154;
                                                        let _e1527 = local_139;
                                                        let _e1528 = ((_e1525 + 0.5f) - _e1527);
                                                        local_156 = _e1528;
                                                        let _e1530 = local_153;
                                                        let _e1531 = local_153;
                                                        local_157 = ((_e1528 * _e1528) + (_e1530 * _e1531));
                                                        let _e1534 = local_29;
                                                        let _e1535 = (_e1534 == 0u);
                                                        local_158 = _e1535;
                                                        if _e1535 {
                                                            let _e1536 = local_36;
                                                            phi_1221_ = (_e1536 == 0u);
                                                        } else {
                                                            phi_1221_ = false;
                                                        }
                                                        let _e1539 = phi_1221_;
                                                        if _e1539 {
                                                            let _e1947 = local_475;
                                                            let _e1948 = local_148;
                                                            let _e1949 = (_e1947 - _e1948);
                                                            let _e1952 = local_157;
                                                            let _e1955 = local_157;
                                                            let _e1957 = local_475;
                                                            let _e1959 = local_148;
                                                            let _e1961 = ((_e1957 - sqrt(_e1955)) * (1f / _e1959));
                                                            phi_1666_ = select(select(0f, select(1f, _e1961, (_e1961 < 1f)), (0f < _e1961)), 1f, ((0f < _e1949) && (_e1952 <= (_e1949 * _e1949))));
                                                        } else {
                                                            let _e1540 = local_158;
                                                            if _e1540 {
                                                                let _e1541 = local_36;
                                                                phi_1257_ = (_e1541 == 0u);
                                                            } else {
                                                                phi_1257_ = false;
                                                            }
                                                            let _e1544 = phi_1257_;
                                                            if _e1544 {
                                                                let _e1925 = local_475;
                                                                let _e1926 = local_148;
                                                                let _e1927 = (_e1925 - _e1926);
                                                                let _e1930 = local_157;
                                                                let _e1933 = local_157;
                                                                let _e1935 = local_475;
                                                                let _e1937 = local_148;
                                                                let _e1939 = ((_e1935 - sqrt(_e1933)) * (1f / _e1937));
                                                                phi_1665_ = select(select(0f, select(1f, _e1939, (_e1939 < 1f)), (0f < _e1939)), 1f, ((0f < _e1927) && (_e1930 <= (_e1927 * _e1927))));
                                                            } else {
                                                                let _e1545 = local_476;
                                                                let _e1546 = local_156;
                                                                local_159 = (_e1545 * _e1546);
                                                                let _e1548 = local_476;
                                                                let _e1549 = local_153;
                                                                local_160 = (_e1548 * _e1549);
                                                                let _e1551 = local_36;
                                                                if (_e1551 > 0u) {
                                                                    let _e1634 = local_148;
                                                                    let _e1636 = local_475;
                                                                    let _e1637 = (_e1636 - (0.5f * _e1634));
                                                                    local_161 = _e1637;
                                                                    if (_e1637 > 0f) {
                                                                        let _e1639 = local_159;
                                                                        let _e1640 = local_161;
                                                                        let _e1642 = local_160;
                                                                        let _e1643 = local_161;
                                                                        let _e1645 = local_36;
                                                                        let _e1646 = f32(_e1645);
                                                                        local_162 = _e1646;
                                                                        let _e1650 = (((((_e1639 / _e1640) + 1f) * 0.5f) * _e1646) - 0.5f);
                                                                        local_163 = _e1650;
                                                                        local_164 = (((((_e1642 / _e1643) + 1f) * 0.5f) * _e1646) - 0.5f);
                                                                        if (_e1650 > -1f) {
                                                                            let _e1656 = local_164;
                                                                            if (_e1656 > -1f) {
                                                                                let _e1658 = local_163;
                                                                                let _e1659 = local_162;
                                                                                if (_e1658 < _e1659) {
                                                                                    let _e1661 = local_164;
                                                                                    let _e1662 = local_162;
                                                                                    let _e1663 = (_e1661 < _e1662);
                                                                                    local_165 = _e1663;
                                                                                    if _e1663 {
                                                                                        let _e1664 = local_163;
                                                                                        let _e1665 = floor(_e1664);
                                                                                        local_166 = _e1665;
                                                                                        let _e1666 = local_164;
                                                                                        let _e1667 = floor(_e1666);
                                                                                        local_167 = _e1667;
                                                                                        let _e1668 = local_163;
                                                                                        local_168 = (_e1668 - _e1665);
                                                                                        let _e1670 = local_164;
                                                                                        local_169 = (_e1670 - _e1667);
                                                                                        let _e1672 = (_e1665 < 0f);
                                                                                        local_170 = _e1672;
                                                                                        if _e1672 {
                                                                                            phi_1378_ = f32();
                                                                                            phi_1379_ = true;
                                                                                        } else {
                                                                                            let _e1673 = local_167;
                                                                                            if (_e1673 < 0f) {
                                                                                                phi_1376_ = f32();
                                                                                                phi_1377_ = true;
                                                                                            } else {
                                                                                                let _e1675 = local_166;
                                                                                                let _e1676 = local_162;
                                                                                                if (_e1675 >= _e1676) {
                                                                                                    phi_1374_ = f32();
                                                                                                    phi_1375_ = true;
                                                                                                } else {
                                                                                                    let _e1678 = local_167;
                                                                                                    let _e1679 = local_162;
                                                                                                    let _e1680 = (_e1678 >= _e1679);
                                                                                                    if _e1680 {
                                                                                                        phi_1373_ = f32();
                                                                                                    } else {
                                                                                                        let _e1681 = local_167;
                                                                                                        let _e1683 = local_167;
                                                                                                        let _e1686 = local_167;
                                                                                                        let _e1690 = local_36;
                                                                                                        let _e1692 = local_166;
                                                                                                        let _e1694 = local_166;
                                                                                                        let _e1697 = local_166;
                                                                                                        let _e1701 = ((select(select(u32(_e1681), 0u, !((_e1683 >= 0f))), 4294967295u, (_e1686 > 4294967000f)) * _e1690) + select(select(u32(_e1692), 0u, !((_e1694 >= 0f))), 4294967295u, (_e1697 > 4294967000f)));
                                                                                                        local_171 = _e1701;
                                                                                                        let _e1702 = local_12;
                                                                                                        if (_e1701 < _e1702) {
                                                                                                        } else {
                                                                                                            phi_5112_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1704 = local_171;
                                                                                                        let _e1707 = global_14.member[_e1704];
                                                                                                        phi_1373_ = bitcast<f32>(_e1707);
                                                                                                    }
                                                                                                    let _e1710 = phi_1373_;
                                                                                                    phi_1374_ = _e1710;
                                                                                                    phi_1375_ = _e1680;
                                                                                                }
                                                                                                let _e1712 = phi_1374_;
                                                                                                let _e1714 = phi_1375_;
                                                                                                phi_1376_ = _e1712;
                                                                                                phi_1377_ = _e1714;
                                                                                            }
                                                                                            let _e1716 = phi_1376_;
                                                                                            let _e1718 = phi_1377_;
                                                                                            phi_1378_ = _e1716;
                                                                                            phi_1379_ = _e1718;
                                                                                        }
                                                                                        let _e1720 = phi_1378_;
                                                                                        let _e1722 = phi_1379_;
                                                                                        let _e1724 = local_168;
                                                                                        let _e1725 = (1f - _e1724);
                                                                                        local_172 = _e1725;
                                                                                        local_173 = (select(_e1720, 0f, _e1722) * _e1725);
                                                                                        let _e1727 = local_166;
                                                                                        let _e1728 = (_e1727 + 1f);
                                                                                        local_174 = _e1728;
                                                                                        let _e1729 = (_e1728 < 0f);
                                                                                        local_175 = _e1729;
                                                                                        if _e1729 {
                                                                                            phi_1434_ = f32();
                                                                                            phi_1435_ = true;
                                                                                        } else {
                                                                                            let _e1730 = local_167;
                                                                                            if (_e1730 < 0f) {
                                                                                                phi_1432_ = f32();
                                                                                                phi_1433_ = true;
                                                                                            } else {
                                                                                                let _e1732 = local_174;
                                                                                                let _e1733 = local_162;
                                                                                                if (_e1732 >= _e1733) {
                                                                                                    phi_1430_ = f32();
                                                                                                    phi_1431_ = true;
                                                                                                } else {
                                                                                                    let _e1735 = local_167;
                                                                                                    let _e1736 = local_162;
                                                                                                    let _e1737 = (_e1735 >= _e1736);
                                                                                                    if _e1737 {
                                                                                                        phi_1429_ = f32();
                                                                                                    } else {
                                                                                                        let _e1738 = local_167;
                                                                                                        let _e1740 = local_167;
                                                                                                        let _e1743 = local_167;
                                                                                                        let _e1747 = local_36;
                                                                                                        let _e1749 = local_174;
                                                                                                        let _e1751 = local_174;
                                                                                                        let _e1754 = local_174;
                                                                                                        let _e1758 = ((select(select(u32(_e1738), 0u, !((_e1740 >= 0f))), 4294967295u, (_e1743 > 4294967000f)) * _e1747) + select(select(u32(_e1749), 0u, !((_e1751 >= 0f))), 4294967295u, (_e1754 > 4294967000f)));
                                                                                                        local_176 = _e1758;
                                                                                                        let _e1759 = local_12;
                                                                                                        if (_e1758 < _e1759) {
                                                                                                        } else {
                                                                                                            phi_5112_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1761 = local_176;
                                                                                                        let _e1764 = global_14.member[_e1761];
                                                                                                        phi_1429_ = bitcast<f32>(_e1764);
                                                                                                    }
                                                                                                    let _e1767 = phi_1429_;
                                                                                                    phi_1430_ = _e1767;
                                                                                                    phi_1431_ = _e1737;
                                                                                                }
                                                                                                let _e1769 = phi_1430_;
                                                                                                let _e1771 = phi_1431_;
                                                                                                phi_1432_ = _e1769;
                                                                                                phi_1433_ = _e1771;
                                                                                            }
                                                                                            let _e1773 = phi_1432_;
                                                                                            let _e1775 = phi_1433_;
                                                                                            phi_1434_ = _e1773;
                                                                                            phi_1435_ = _e1775;
                                                                                        }
                                                                                        let _e1777 = phi_1434_;
                                                                                        let _e1779 = phi_1435_;
                                                                                        let _e1781 = local_168;
                                                                                        let _e1783 = local_173;
                                                                                        local_177 = (_e1783 + (select(_e1777, 0f, _e1779) * _e1781));
                                                                                        let _e1785 = local_167;
                                                                                        local_178 = (_e1785 + 1f);
                                                                                        let _e1787 = local_170;
                                                                                        if _e1787 {
                                                                                            phi_1490_ = f32();
                                                                                            phi_1491_ = true;
                                                                                        } else {
                                                                                            let _e1788 = local_178;
                                                                                            if (_e1788 < 0f) {
                                                                                                phi_1488_ = f32();
                                                                                                phi_1489_ = true;
                                                                                            } else {
                                                                                                let _e1790 = local_166;
                                                                                                let _e1791 = local_162;
                                                                                                if (_e1790 >= _e1791) {
                                                                                                    phi_1486_ = f32();
                                                                                                    phi_1487_ = true;
                                                                                                } else {
                                                                                                    let _e1793 = local_178;
                                                                                                    let _e1794 = local_162;
                                                                                                    let _e1795 = (_e1793 >= _e1794);
                                                                                                    if _e1795 {
                                                                                                        phi_1485_ = f32();
                                                                                                    } else {
                                                                                                        let _e1796 = local_178;
                                                                                                        let _e1798 = local_178;
                                                                                                        let _e1801 = local_178;
                                                                                                        let _e1805 = local_36;
                                                                                                        let _e1807 = local_166;
                                                                                                        let _e1809 = local_166;
                                                                                                        let _e1812 = local_166;
                                                                                                        let _e1816 = ((select(select(u32(_e1796), 0u, !((_e1798 >= 0f))), 4294967295u, (_e1801 > 4294967000f)) * _e1805) + select(select(u32(_e1807), 0u, !((_e1809 >= 0f))), 4294967295u, (_e1812 > 4294967000f)));
                                                                                                        local_179 = _e1816;
                                                                                                        let _e1817 = local_12;
                                                                                                        if (_e1816 < _e1817) {
                                                                                                        } else {
                                                                                                            phi_5112_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1819 = local_179;
                                                                                                        let _e1822 = global_14.member[_e1819];
                                                                                                        phi_1485_ = bitcast<f32>(_e1822);
                                                                                                    }
                                                                                                    let _e1825 = phi_1485_;
                                                                                                    phi_1486_ = _e1825;
                                                                                                    phi_1487_ = _e1795;
                                                                                                }
                                                                                                let _e1827 = phi_1486_;
                                                                                                let _e1829 = phi_1487_;
                                                                                                phi_1488_ = _e1827;
                                                                                                phi_1489_ = _e1829;
                                                                                            }
                                                                                            let _e1831 = phi_1488_;
                                                                                            let _e1833 = phi_1489_;
                                                                                            phi_1490_ = _e1831;
                                                                                            phi_1491_ = _e1833;
                                                                                        }
                                                                                        let _e1835 = phi_1490_;
                                                                                        let _e1837 = phi_1491_;
                                                                                        let _e1839 = local_172;
                                                                                        local_180 = (select(_e1835, 0f, _e1837) * _e1839);
                                                                                        let _e1841 = local_175;
                                                                                        if _e1841 {
                                                                                            phi_1547_ = f32();
                                                                                            phi_1548_ = true;
                                                                                        } else {
                                                                                            let _e1842 = local_178;
                                                                                            if (_e1842 < 0f) {
                                                                                                phi_1545_ = f32();
                                                                                                phi_1546_ = true;
                                                                                            } else {
                                                                                                let _e1844 = local_174;
                                                                                                let _e1845 = local_162;
                                                                                                if (_e1844 >= _e1845) {
                                                                                                    phi_1543_ = f32();
                                                                                                    phi_1544_ = true;
                                                                                                } else {
                                                                                                    let _e1847 = local_178;
                                                                                                    let _e1848 = local_162;
                                                                                                    let _e1849 = (_e1847 >= _e1848);
                                                                                                    if _e1849 {
                                                                                                        phi_1542_ = f32();
                                                                                                    } else {
                                                                                                        let _e1850 = local_178;
                                                                                                        let _e1852 = local_178;
                                                                                                        let _e1855 = local_178;
                                                                                                        let _e1859 = local_36;
                                                                                                        let _e1861 = local_174;
                                                                                                        let _e1863 = local_174;
                                                                                                        let _e1866 = local_174;
                                                                                                        let _e1870 = ((select(select(u32(_e1850), 0u, !((_e1852 >= 0f))), 4294967295u, (_e1855 > 4294967000f)) * _e1859) + select(select(u32(_e1861), 0u, !((_e1863 >= 0f))), 4294967295u, (_e1866 > 4294967000f)));
                                                                                                        local_181 = _e1870;
                                                                                                        let _e1871 = local_12;
                                                                                                        if (_e1870 < _e1871) {
                                                                                                        } else {
                                                                                                            phi_5112_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1873 = local_181;
                                                                                                        let _e1876 = global_14.member[_e1873];
                                                                                                        phi_1542_ = bitcast<f32>(_e1876);
                                                                                                    }
                                                                                                    let _e1879 = phi_1542_;
                                                                                                    phi_1543_ = _e1879;
                                                                                                    phi_1544_ = _e1849;
                                                                                                }
                                                                                                let _e1881 = phi_1543_;
                                                                                                let _e1883 = phi_1544_;
                                                                                                phi_1545_ = _e1881;
                                                                                                phi_1546_ = _e1883;
                                                                                            }
                                                                                            let _e1885 = phi_1545_;
                                                                                            let _e1887 = phi_1546_;
                                                                                            phi_1547_ = _e1885;
                                                                                            phi_1548_ = _e1887;
                                                                                        }
                                                                                        let _e1889 = phi_1547_;
                                                                                        let _e1891 = phi_1548_;
                                                                                        let _e1893 = local_168;
                                                                                        let _e1895 = local_180;
                                                                                        let _e1897 = local_169;
                                                                                        let _e1899 = local_177;
                                                                                        let _e1901 = local_169;
                                                                                        phi_1559_ = ((_e1899 * (1f - _e1897)) + ((_e1895 + (select(_e1889, 0f, _e1891) * _e1893)) * _e1901));
                                                                                    } else {
                                                                                        phi_1559_ = f32();
                                                                                    }
                                                                                    let _e1905 = phi_1559_;
                                                                                    let _e1906 = local_165;
                                                                                    phi_1561_ = _e1905;
                                                                                    phi_1562_ = select(true, false, _e1906);
                                                                                } else {
                                                                                    phi_1561_ = f32();
                                                                                    phi_1562_ = true;
                                                                                }
                                                                                let _e1909 = phi_1561_;
                                                                                let _e1911 = phi_1562_;
                                                                                phi_1563_ = _e1909;
                                                                                phi_1564_ = _e1911;
                                                                            } else {
                                                                                phi_1563_ = f32();
                                                                                phi_1564_ = true;
                                                                            }
                                                                            let _e1913 = phi_1563_;
                                                                            let _e1915 = phi_1564_;
                                                                            phi_1565_ = _e1913;
                                                                            phi_1566_ = _e1915;
                                                                        } else {
                                                                            phi_1565_ = f32();
                                                                            phi_1566_ = true;
                                                                        }
                                                                        let _e1917 = phi_1565_;
                                                                        let _e1919 = phi_1566_;
                                                                        phi_1571_ = select(_e1917, 0f, _e1919);
                                                                    } else {
                                                                        phi_1571_ = 0f;
                                                                    }
                                                                    let _e1922 = phi_1571_;
                                                                    phi_1664_ = _e1922;
                                                                } else {
                                                                    let _e1553 = local_159;
                                                                    let _e1554 = local_159;
                                                                    let _e1556 = local_160;
                                                                    let _e1557 = local_160;
                                                                    let _e1560 = sqrt(((_e1553 * _e1554) + (_e1556 * _e1557)));
                                                                    local_182 = _e1560;
                                                                    let _e1561 = local_158;
                                                                    if _e1561 {
                                                                        phi_1651_ = _e1560;
                                                                    } else {
                                                                        let _e1562 = local_31;
                                                                        let _e1564 = local_159;
                                                                        let _e1566 = local_31;
                                                                        let _e1568 = local_160;
                                                                        phi_1593_ = 1u;
                                                                        phi_1596_ = ((_e1564 * _e1562[0]) + (_e1568 * _e1566[1]));
                                                                        phi_1598_ = _e658.member_16.member_2;
                                                                        loop {
                                                                            let _e1572 = phi_1593_;
                                                                            let _e1574 = phi_1596_;
                                                                            let _e1576 = phi_1598_;
                                                                            local_183 = _e1572;
                                                                            local_184 = _e1574;
                                                                            local_185 = _e1576;
                                                                            let _e1577 = local_183;
                                                                            let _e1578 = local_29;
                                                                            let _e1579 = (_e1577 < _e1578);
                                                                            local_186 = _e1579;
                                                                            if _e1579 {
                                                                                let _e1580 = local_185;
                                                                                let _e1582 = local_32;
                                                                                let _e1584 = local_185;
                                                                                let _e1586 = local_33;
                                                                                let _e1588 = ((_e1580[0] * _e1582) - (_e1584[1] * _e1586));
                                                                                let _e1589 = local_33;
                                                                                let _e1591 = local_32;
                                                                                let _e1593 = ((_e1580[0] * _e1589) + (_e1584[1] * _e1591));
                                                                                let _e1595 = local_159;
                                                                                let _e1597 = local_160;
                                                                                let _e1599 = ((_e1595 * _e1588) + (_e1597 * _e1593));
                                                                                let _e1600 = local_184;
                                                                                let _e1602 = local_184;
                                                                                let _e1604 = local_183;
                                                                                phi_1594_ = (_e1604 + 1u);
                                                                                phi_1597_ = select(_e1602, _e1599, (_e1599 > _e1600));
                                                                                phi_1599_ = array<f32, 2>(_e1588, _e1593);
                                                                            } else {
                                                                                phi_1594_ = u32();
                                                                                phi_1597_ = f32();
                                                                                phi_1599_ = array<f32, 2>();
                                                                            }
                                                                            let _e1607 = phi_1594_;
                                                                            let _e1609 = phi_1597_;
                                                                            let _e1611 = phi_1599_;
                                                                            continue;
                                                                            continuing {
                                                                                let _e1612 = local_186;
                                                                                phi_1593_ = _e1607;
                                                                                phi_1596_ = _e1609;
                                                                                phi_1598_ = _e1611;
                                                                                break if !(_e1612);
                                                                            }
                                                                        }
                                                                        let _e1614 = local_30;
                                                                        let _e1616 = local_184;
                                                                        let _e1618 = local_34;
                                                                        let _e1620 = local_30;
                                                                        let _e1621 = local_182;
                                                                        phi_1651_ = ((((1f - _e1614) * _e1616) * _e1618) + (_e1620 * _e1621));
                                                                    }
                                                                    let _e1625 = phi_1651_;
                                                                    let _e1626 = local_475;
                                                                    let _e1628 = local_148;
                                                                    let _e1629 = ((_e1626 - _e1625) / _e1628);
                                                                    phi_1664_ = select(0f, select(1f, _e1629, (_e1629 < 1f)), (0f < _e1629));
                                                                }
                                                                let _e1924 = phi_1664_;
                                                                phi_1665_ = _e1924;
                                                            }
                                                            let _e1946 = phi_1665_;
                                                            phi_1666_ = _e1946;
                                                        }
                                                        let _e1968 = phi_1666_;
                                                        let _e1969 = local_155;
                                                        local_477 = select(0f, _e1968, _e1969);
                                                        phi_1672_ = 0u;
                                                        phi_1675_ = _e1521;
                                                        loop {
                                                            let _e1972 = phi_1672_;
                                                            let _e1974 = phi_1675_;
                                                            local_187 = _e1972;
                                                            local_188 = _e1974;
                                                            local_491 = _e1974;
                                                            let _e1975 = local_187;
                                                            let _e1976 = (_e1975 < 1u);
                                                            local_189 = _e1976;
                                                            if _e1976 {
                                                                let _e1977 = local_188;
                                                                let _e1978 = local_477;
                                                                let _e1980 = local_187;
                                                                phi_1673_ = (_e1980 + 1u);
                                                                phi_1676_ = (_e1977 + _e1978);
                                                            } else {
                                                                phi_1673_ = u32();
                                                                phi_1676_ = f32();
                                                            }
                                                            let _e1983 = phi_1673_;
                                                            let _e1985 = phi_1676_;
                                                            continue;
                                                            continuing {
                                                                let _e1986 = local_189;
                                                                phi_1672_ = _e1983;
                                                                phi_1675_ = _e1985;
                                                                break if !(_e1986);
                                                            }
                                                        }
                                                        let _e1988 = local_154;
                                                        phi_1195_ = (_e1988 + 1f);
                                                        let _e4551 = local_491;
                                                        phi_1198_ = _e4551;
                                                    } else {
                                                        phi_1195_ = f32();
                                                        phi_1198_ = f32();
                                                    }
                                                    let _e1991 = phi_1195_;
                                                    let _e1993 = phi_1198_;
                                                    continue;
                                                    continuing {
                                                        let _e1994 = local_155;
                                                        phi_1194_ = _e1991;
                                                        phi_1197_ = _e1993;
                                                        phi_5112_ = _e1506;
                                                        break if !(_e1994);
                                                    }
                                                }
                                                let _e1997 = phi_5112_;
                                                phi_5179_ = _e1997;
                                                if _e1997 {
                                                    break;
                                                }
                                                let _e1998 = local_151;
                                                phi_5180_ = _e1997;
                                                phi_1181_ = (_e1998 + 1f);
                                                let _e4557 = local_492;
                                                phi_1184_ = _e4557;
                                            } else {
                                                phi_5180_ = _e1506;
                                                phi_1181_ = f32();
                                                phi_1184_ = f32();
                                            }
                                            let _e2001 = phi_5180_;
                                            let _e2003 = phi_1181_;
                                            let _e2005 = phi_1184_;
                                            continue;
                                            continuing {
                                                let _e2006 = local_152;
                                                phi_5115_ = _e2001;
                                                phi_1180_ = _e2003;
                                                phi_1183_ = _e2005;
                                                phi_5179_ = _e2001;
                                                break if !(_e2006);
                                            }
                                        }
                                        let _e2009 = phi_5179_;
                                        phi_5435_ = _e2009;
                                        if _e2009 {
                                            break;
                                        }
                                        phi_5189_ = _e2009;
                                        let _e4563 = local_493;
                                        phi_1688_ = _e4563;
                                    }
                                    let _e2034 = phi_5189_;
                                    let _e2036 = phi_1688_;
                                    let _e2037 = local_147;
                                    phi_5188_ = _e2034;
                                    phi_1690_ = (_e2037 / _e2036);
                                }
                                let _e2040 = phi_5188_;
                                let _e2042 = phi_1690_;
                                local_190 = _e2042;
                                phi_1692_ = 0u;
                                loop {
                                    let _e2044 = phi_1692_;
                                    local_191 = _e2044;
                                    let _e2045 = local_191;
                                    let _e2046 = local_48;
                                    if (_e2045 < _e2046) {
                                        let _e2048 = local_191;
                                        let _e2049 = (_e2048 + 1u);
                                        let _e2051 = local_20;
                                        let _e2056 = local_475;
                                        let _e2057 = (_e2056 >= f32((2u * (_e2051 << bitcast<u32>((_e2049 & 31u))))));
                                        phi_1693_ = select(u32(), _e2049, _e2057);
                                        phi_1714_ = _e2057;
                                    } else {
                                        phi_1693_ = u32();
                                        phi_1714_ = false;
                                    }
                                    let _e2060 = phi_1693_;
                                    let _e2062 = phi_1714_;
                                    local_192 = _e2062;
                                    continue;
                                    continuing {
                                        let _e2063 = local_192;
                                        phi_1692_ = _e2060;
                                        break if !(_e2063);
                                    }
                                }
                                let _e2065 = local_191;
                                let _e2071 = local_190;
                                local_193 = bitcast<u32>((_e2071 * f32((1u << bitcast<u32>(((2u * _e2065) & 31u))))));
                                let _e2074 = local;
                                let _e2075 = (2304u + _e2074);
                                local_194 = _e2075;
                                if (_e2075 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e2077 = local_194;
                                let _e2079 = local_193;
                                global_15[_e2077] = _e2079;
                                let _e2080 = local;
                                let _e2081 = (5632u + _e2080);
                                local_195 = _e2081;
                                if (_e2081 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e2083 = local_195;
                                let _e2085 = local_132;
                                global_15[_e2083] = _e2085;
                                let _e2086 = local_131;
                                local_196 = bitcast<u32>(f32((1u << bitcast<u32>((_e2086.member_4 & 31u)))));
                                let _e2093 = local;
                                let _e2094 = (3584u + _e2093);
                                local_197 = _e2094;
                                if (_e2094 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e2096 = local_197;
                                let _e2098 = local_196;
                                global_15[_e2096] = _e2098;
                                let _e2099 = local_476;
                                local_198 = bitcast<u32>(_e2099);
                                let _e2101 = local;
                                let _e2102 = (3840u + _e2101);
                                local_199 = _e2102;
                                if (_e2102 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e2104 = local_199;
                                let _e2106 = local_198;
                                global_15[_e2104] = _e2106;
                                let _e2107 = local_131;
                                local_200 = bitcast<u32>(_e2107.member_2);
                                let _e2110 = local;
                                let _e2111 = (4096u + _e2110);
                                local_201 = _e2111;
                                if (_e2111 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e2113 = local_201;
                                let _e2115 = local_200;
                                global_15[_e2113] = _e2115;
                                let _e2116 = local_131;
                                local_202 = bitcast<u32>(_e2116.member_1[0]);
                                let _e2120 = local;
                                let _e2121 = (2560u + _e2120);
                                local_203 = _e2121;
                                if (_e2121 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e2123 = local_203;
                                let _e2125 = local_202;
                                global_15[_e2123] = _e2125;
                                let _e2126 = local_131;
                                local_204 = bitcast<u32>(_e2126.member_1[1]);
                                let _e2130 = local;
                                let _e2131 = (2816u + _e2130);
                                local_205 = _e2131;
                                if (_e2131 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e2133 = local_205;
                                let _e2135 = local_204;
                                global_15[_e2133] = _e2135;
                                let _e2136 = local_131;
                                local_206 = bitcast<u32>(_e2136.member_1[2]);
                                let _e2140 = local;
                                let _e2141 = (3072u + _e2140);
                                local_207 = _e2141;
                                if (_e2141 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e2143 = local_207;
                                let _e2145 = local_206;
                                global_15[_e2143] = _e2145;
                                let _e2146 = local;
                                let _e2147 = (3328u + _e2146);
                                local_208 = _e2147;
                                if (_e2147 < 5888u) {
                                } else {
                                    phi_5435_ = true;
                                    break;
                                }
                                let _e2149 = local_208;
                                let _e2151 = local_136;
                                global_15[_e2149] = _e2151;
                                phi_5185_ = _e2040;
                            } else {
                                phi_5185_ = _e1180;
                            }
                            let _e2153 = phi_5185_;
                            storageBarrier();
                            workgroupBarrier();
                            let _e2154 = local_52;
                            let _e2155 = local_98;
                            let _e2156 = (_e2154 - _e2155);
                            let _e2158 = select(256u, _e2156, (_e2156 < 256u));
                            local_478 = _e2158;
                            local_490[0u] = false;
                            phi_1819_ = 0u;
                            loop {
                                let _e2161 = phi_1819_;
                                local_209 = _e2161;
                                let _e2162 = local_209;
                                let _e2163 = (_e2162 < 1u);
                                local_210 = _e2163;
                                if _e2163 {
                                    let _e2164 = local;
                                    let _e2165 = local_209;
                                    local_211 = (_e2164 + _e2165);
                                    let _e2167 = local_37;
                                    if _e2167 {
                                        phi_5181_ = true;
                                        break;
                                    }
                                    let _e2168 = local_211;
                                    let _e2169 = local_473;
                                    let _e2171 = local_44;
                                    local_212 = (_e2171 + (_e2168 % _e2169));
                                    let _e2173 = local_37;
                                    if _e2173 {
                                        phi_5181_ = true;
                                        break;
                                    }
                                    let _e2174 = local_211;
                                    let _e2175 = local_473;
                                    let _e2177 = local_46;
                                    local_213 = (_e2177 + (_e2174 / _e2175));
                                    let _e2179 = local_211;
                                    let _e2180 = local_84;
                                    if (_e2179 < _e2180) {
                                        let _e2182 = local_212;
                                        let _e2183 = local_17;
                                        let _e2184 = (_e2182 < _e2183);
                                        local_214 = _e2184;
                                        if _e2184 {
                                            let _e2185 = local_213;
                                            let _e2186 = local_18;
                                            phi_1885_ = (_e2185 < _e2186);
                                        } else {
                                            phi_1885_ = bool();
                                        }
                                        let _e2189 = phi_1885_;
                                        let _e2190 = local_214;
                                        phi_1887_ = _e2189;
                                        phi_1888_ = select(true, false, _e2190);
                                    } else {
                                        phi_1887_ = bool();
                                        phi_1888_ = true;
                                    }
                                    let _e2193 = phi_1887_;
                                    let _e2195 = phi_1888_;
                                    local_479 = select(_e2193, false, _e2195);
                                    let _e2197 = local_210;
                                    if _e2197 {
                                    } else {
                                        phi_5181_ = true;
                                        break;
                                    }
                                    let _e2198 = local_209;
                                    let _e2200 = local_479;
                                    local_490[_e2198] = _e2200;
                                    let _e2201 = local_209;
                                    phi_1820_ = (_e2201 + 1u);
                                } else {
                                    phi_1820_ = u32();
                                }
                                let _e2204 = phi_1820_;
                                continue;
                                continuing {
                                    let _e2205 = local_210;
                                    phi_1819_ = _e2204;
                                    phi_5181_ = _e2153;
                                    break if !(_e2205);
                                }
                            }
                            let _e2208 = phi_5181_;
                            phi_5435_ = _e2208;
                            if _e2208 {
                                break;
                            }
                            let _e2209 = local_490[0u];
                            local_487[0u] = _e2209;
                            let _e2211 = local_37;
                            if _e2211 {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2212 = local_37;
                            if _e2212 {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2213 = local_82;
                            local_215 = (f32(_e2213) + 0.5f);
                            let _e2216 = local_37;
                            if _e2216 {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2217 = local_37;
                            if _e2217 {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2218 = local_83;
                            local_216 = (f32(_e2218) + 0.5f);
                            let _e2221 = local;
                            let _e2222 = (768u + _e2221);
                            local_217 = _e2222;
                            if (_e2222 < 5888u) {
                            } else {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2224 = local_217;
                            let _e2226 = global_15[_e2224];
                            let _e2227 = bitcast<f32>(_e2226);
                            local_218 = _e2227;
                            let _e2228 = local;
                            if (_e2228 < 5888u) {
                            } else {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2230 = local;
                            let _e2232 = global_15[_e2230];
                            local_219 = bitcast<f32>(_e2232);
                            let _e2234 = local;
                            let _e2235 = (256u + _e2234);
                            local_220 = _e2235;
                            if (_e2235 < 5888u) {
                            } else {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2237 = local_220;
                            let _e2239 = global_15[_e2237];
                            local_221 = bitcast<f32>(_e2239);
                            let _e2241 = local;
                            let _e2242 = (512u + _e2241);
                            local_222 = _e2242;
                            if (_e2242 < 5888u) {
                            } else {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2244 = local_222;
                            let _e2246 = global_15[_e2244];
                            let _e2248 = local_219;
                            let _e2249 = local_221;
                            let _e2251 = local_91;
                            if (_e2251 < 5888u) {
                            } else {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2253 = local_91;
                            let _e2255 = global_15[_e2253];
                            local_223 = bitcast<f32>(_e2255);
                            let _e2257 = local;
                            let _e2258 = (_e2257 + 4864u);
                            local_224 = _e2258;
                            if (_e2258 < 5888u) {
                            } else {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2260 = local_224;
                            let _e2262 = global_15[_e2260];
                            local_225 = bitcast<f32>(_e2262);
                            let _e2264 = local;
                            let _e2265 = (_e2264 + 5120u);
                            local_226 = _e2265;
                            if (_e2265 < 5888u) {
                            } else {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2267 = local_226;
                            let _e2269 = global_15[_e2267];
                            local_227 = bitcast<f32>(_e2269);
                            let _e2271 = local;
                            let _e2272 = (_e2271 + 5376u);
                            local_228 = _e2272;
                            let _e2273 = (_e2272 < 5888u);
                            local_229 = _e2273;
                            if _e2273 {
                            } else {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2274 = local_228;
                            let _e2276 = global_15[_e2274];
                            local_230 = ((_e2276 & 1u) != 0u);
                            let _e2279 = local_229;
                            if _e2279 {
                            } else {
                                phi_5435_ = true;
                                break;
                            }
                            let _e2280 = global_15[_e2274];
                            let _e2283 = local_223;
                            let _e2284 = local_225;
                            let _e2285 = local_227;
                            let _e2286 = local_230;
                            local_486[0u] = false;
                            phi_2119_ = 0u;
                            loop {
                                let _e2290 = phi_2119_;
                                local_231 = _e2290;
                                let _e2291 = local_231;
                                let _e2292 = (_e2291 < 1u);
                                local_232 = _e2292;
                                if _e2292 {
                                    let _e2293 = local_232;
                                    if _e2293 {
                                    } else {
                                        phi_5199_ = true;
                                        break;
                                    }
                                    let _e2294 = local_231;
                                    let _e2296 = local_487[_e2294];
                                    if _e2296 {
                                        let _e2297 = local_218;
                                        phi_2140_ = (_e2297 < 0.99902344f);
                                    } else {
                                        phi_2140_ = false;
                                    }
                                    let _e2300 = phi_2140_;
                                    local_233 = _e2300;
                                    let _e2301 = local_232;
                                    if _e2301 {
                                    } else {
                                        phi_5199_ = true;
                                        break;
                                    }
                                    let _e2302 = local_231;
                                    let _e2304 = local_233;
                                    local_486[_e2302] = _e2304;
                                    let _e2305 = local_231;
                                    phi_2120_ = (_e2305 + 1u);
                                } else {
                                    phi_2120_ = u32();
                                }
                                let _e2308 = phi_2120_;
                                continue;
                                continuing {
                                    let _e2309 = local_232;
                                    phi_2119_ = _e2308;
                                    phi_5199_ = _e2208;
                                    break if !(_e2309);
                                }
                            }
                            let _e2312 = phi_5199_;
                            phi_5435_ = _e2312;
                            if _e2312 {
                                break;
                            }
                            let _e2313 = local_486[0u];
                            local_488[0u] = _e2313;
                            local_485[0u] = 0u;
                            phi_5210_ = _e2312;
                            phi_2153_ = 0u;
                            loop {
                                let _e2317 = phi_5210_;
                                let _e2319 = phi_2153_;
                                local_234 = _e2319;
                                let _e2320 = local_234;
                                let _e2321 = (_e2320 < 1u);
                                local_235 = _e2321;
                                if _e2321 {
                                    let _e2322 = local_235;
                                    if _e2322 {
                                    } else {
                                        phi_5212_ = true;
                                        break;
                                    }
                                    let _e2323 = local_234;
                                    let _e2325 = local_488[_e2323];
                                    if _e2325 {
                                        let _e2326 = local;
                                        let _e2327 = local_234;
                                        let _e2329 = (1024u + (_e2326 + _e2327));
                                        local_236 = _e2329;
                                        if (_e2329 < 5888u) {
                                        } else {
                                            phi_5212_ = true;
                                            break;
                                        }
                                        let _e2331 = local_236;
                                        let _e2333 = global_15[_e2331];
                                        local_237 = bitcast<f32>(_e2333);
                                        phi_2183_ = 0u;
                                        phi_2186_ = _e2158;
                                        loop {
                                            let _e2336 = phi_2183_;
                                            let _e2338 = phi_2186_;
                                            local_238 = _e2336;
                                            local_239 = _e2338;
                                            local_494 = _e2336;
                                            let _e2339 = local_238;
                                            let _e2340 = local_239;
                                            let _e2341 = (_e2339 < _e2340);
                                            local_240 = _e2341;
                                            if _e2341 {
                                                let _e2342 = local_238;
                                                let _e2343 = local_239;
                                                let _e2345 = ((_e2342 + _e2343) / 2u);
                                                local_241 = _e2345;
                                                let _e2346 = (3328u + _e2345);
                                                local_242 = _e2346;
                                                if (_e2346 < 5888u) {
                                                } else {
                                                    phi_5207_ = true;
                                                    break;
                                                }
                                                let _e2348 = local_242;
                                                let _e2350 = global_15[_e2348];
                                                let _e2352 = local_237;
                                                let _e2353 = (bitcast<f32>(_e2350) >= _e2352);
                                                local_243 = _e2353;
                                                if _e2353 {
                                                    phi_2210_ = _e2336;
                                                } else {
                                                    let _e2354 = local_241;
                                                    phi_2210_ = (_e2354 + 1u);
                                                }
                                                let _e2357 = phi_2210_;
                                                let _e2358 = local_243;
                                                let _e2359 = local_241;
                                                let _e2360 = local_239;
                                                phi_2184_ = _e2357;
                                                phi_2187_ = select(_e2360, _e2359, _e2358);
                                            } else {
                                                phi_2184_ = u32();
                                                phi_2187_ = u32();
                                            }
                                            let _e2363 = phi_2184_;
                                            let _e2365 = phi_2187_;
                                            continue;
                                            continuing {
                                                let _e2366 = local_240;
                                                phi_2183_ = _e2363;
                                                phi_2186_ = _e2365;
                                                phi_5207_ = _e2317;
                                                break if !(_e2366);
                                            }
                                        }
                                        let _e2369 = phi_5207_;
                                        phi_5212_ = _e2369;
                                        if _e2369 {
                                            break;
                                        }
                                        phi_5214_ = _e2369;
                                        let _e4591 = local_494;
                                        phi_2212_ = _e4591;
                                    } else {
                                        phi_5214_ = _e2317;
                                        phi_2212_ = 0u;
                                    }
                                    let _e2371 = phi_5214_;
                                    let _e2373 = phi_2212_;
                                    local_244 = _e2373;
                                    let _e2374 = local_235;
                                    if _e2374 {
                                    } else {
                                        phi_5212_ = true;
                                        break;
                                    }
                                    let _e2375 = local_234;
                                    let _e2377 = local_244;
                                    local_485[_e2375] = _e2377;
                                    let _e2378 = local_234;
                                    phi_5213_ = _e2371;
                                    phi_2154_ = (_e2378 + 1u);
                                } else {
                                    phi_5213_ = _e2317;
                                    phi_2154_ = u32();
                                }
                                let _e2381 = phi_5213_;
                                let _e2383 = phi_2154_;
                                continue;
                                continuing {
                                    let _e2384 = local_235;
                                    phi_5210_ = _e2381;
                                    phi_2153_ = _e2383;
                                    phi_5212_ = _e2381;
                                    break if !(_e2384);
                                }
                            }
                            let _e2387 = phi_5212_;
                            phi_5435_ = _e2387;
                            if _e2387 {
                                break;
                            }
                            let _e2388 = local_485[0u];
                            local_489[0u] = _e2388;
                            let _e2390 = local_489[0u];
                            let _e2391 = f32(_e2390);
                            let _e2392 = local_24;
                            local_245 = ((_e2392 >> bitcast<u32>(8u)) & 7u);
                            phi_5218_ = _e2387;
                            phi_2243_ = _e2227;
                            phi_2246_ = type_32(_e2283, _e2284, _e2285, _e2286, ((_e2280 & 2u) != 0u));
                            phi_2248_ = 0u;
                            phi_2250_ = select(select(u32(_e2391), 0u, !((_e2391 >= 0f))), 4294967295u, (_e2391 > 4294967000f));
                            phi_2252_ = _e2391;
                            phi_2254_ = 0f;
                            phi_2256_ = false;
                            phi_2258_ = array<f32, 3>(_e2248, _e2249, bitcast<f32>(_e2246));
                            loop {
                                let _e2403 = phi_5218_;
                                let _e2405 = phi_2243_;
                                let _e2407 = phi_2246_;
                                let _e2409 = phi_2248_;
                                let _e2411 = phi_2250_;
                                let _e2413 = phi_2252_;
                                let _e2415 = phi_2254_;
                                let _e2417 = phi_2256_;
                                let _e2419 = phi_2258_;
                                local_246 = _e2405;
                                local_247 = _e2407;
                                local_248 = _e2409;
                                local_249 = _e2411;
                                local_250 = _e2413;
                                local_251 = _e2415;
                                local_252 = _e2417;
                                local_253 = _e2419;
                                let _e2420 = local_248;
                                let _e2421 = local_249;
                                let _e2422 = (_e2420 < _e2421);
                                local_254 = _e2422;
                                if _e2422 {
                                    let _e2423 = local_248;
                                    let _e2424 = (1536u + _e2423);
                                    local_255 = _e2424;
                                    if (_e2424 < 5888u) {
                                    } else {
                                        phi_5321_ = true;
                                        break;
                                    }
                                    let _e2426 = local_255;
                                    let _e2428 = global_15[_e2426];
                                    local_256 = bitcast<f32>(_e2428);
                                    let _e2430 = local_248;
                                    let _e2431 = (1792u + _e2430);
                                    local_257 = _e2431;
                                    if (_e2431 < 5888u) {
                                    } else {
                                        phi_5321_ = true;
                                        break;
                                    }
                                    let _e2433 = local_257;
                                    let _e2435 = global_15[_e2433];
                                    local_258 = bitcast<f32>(_e2435);
                                    let _e2437 = local_248;
                                    let _e2438 = (2048u + _e2437);
                                    local_259 = _e2438;
                                    if (_e2438 < 5888u) {
                                    } else {
                                        phi_5321_ = true;
                                        break;
                                    }
                                    let _e2440 = local_259;
                                    let _e2442 = global_15[_e2440];
                                    let _e2443 = bitcast<f32>(_e2442);
                                    local_260 = _e2443;
                                    let _e2444 = local_215;
                                    let _e2445 = local_256;
                                    let _e2446 = (_e2444 - _e2445);
                                    local_261 = _e2446;
                                    let _e2447 = local_216;
                                    let _e2448 = local_258;
                                    let _e2449 = (_e2447 - _e2448);
                                    local_262 = _e2449;
                                    let _e2452 = ((_e2446 * _e2446) + (_e2449 * _e2449));
                                    local_263 = _e2452;
                                    let _e2455 = local_248;
                                    let _e2457 = local_250;
                                    let _e2459 = ((_e2452 < (_e2443 * _e2443)) && (f32(_e2455) < _e2457));
                                    local_264 = _e2459;
                                    if _e2459 {
                                        let _e2460 = local_248;
                                        let _e2461 = (5632u + _e2460);
                                        local_265 = _e2461;
                                        if (_e2461 < 5888u) {
                                        } else {
                                            phi_5321_ = true;
                                            break;
                                        }
                                        let _e2463 = local_265;
                                        let _e2465 = global_15[_e2463];
                                        local_266 = _e2465;
                                        let _e2466 = local_248;
                                        let _e2467 = (3584u + _e2466);
                                        local_267 = _e2467;
                                        if (_e2467 < 5888u) {
                                        } else {
                                            phi_5321_ = true;
                                            break;
                                        }
                                        let _e2469 = local_267;
                                        let _e2471 = global_15[_e2469];
                                        local_268 = bitcast<f32>(_e2471);
                                        let _e2473 = local_266;
                                        let _e2474 = (_e2473 != 0u);
                                        local_269 = _e2474;
                                        if _e2474 {
                                            let _e2917 = local_260;
                                            let _e2918 = (_e2917 - 1.4142135f);
                                            local_270 = _e2918;
                                            let _e2919 = local_260;
                                            let _e2920 = (_e2919 - 2.828427f);
                                            let _e2923 = local_263;
                                            let _e2925 = ((_e2920 > 0f) && (_e2923 <= (_e2920 * _e2920)));
                                            local_271 = _e2925;
                                            let _e2927 = ((3.1415927f * _e2918) * _e2918);
                                            local_272 = _e2927;
                                            let _e2928 = (1f / _e2927);
                                            local_273 = _e2928;
                                            let _e2930 = local_264;
                                            let _e2931 = (_e2930 && !(_e2925));
                                            local_274 = _e2931;
                                            if _e2931 {
                                                let _e2932 = local_245;
                                                let _e2933 = local_245;
                                                local_275 = (_e2932 * _e2933);
                                                phi_2346_ = 0u;
                                                phi_2349_ = 0f;
                                                phi_2351_ = 0u;
                                                loop {
                                                    let _e2936 = phi_2346_;
                                                    let _e2938 = phi_2349_;
                                                    let _e2940 = phi_2351_;
                                                    local_276 = _e2936;
                                                    local_277 = _e2938;
                                                    local_278 = _e2940;
                                                    let _e2941 = local_276;
                                                    let _e2942 = local_275;
                                                    if (_e2941 < _e2942) {
                                                        let _e2944 = local_276;
                                                        let _e2945 = (_e2944 < 16u);
                                                        if _e2945 {
                                                            let _e2946 = local_276;
                                                            let _e2950 = local_266;
                                                            if ((_e2950 & (1u << bitcast<u32>((_e2946 & 31u)))) == 0u) {
                                                                phi_3189_ = _e2938;
                                                                phi_3190_ = _e2940;
                                                            } else {
                                                                let _e2953 = local_245;
                                                                local_279 = f32(_e2953);
                                                                let _e2955 = local_245;
                                                                let _e2956 = (_e2955 == 0u);
                                                                local_280 = _e2956;
                                                                if _e2956 {
                                                                    phi_5215_ = true;
                                                                    break;
                                                                }
                                                                let _e2957 = local_276;
                                                                let _e2958 = local_245;
                                                                let _e2962 = local_279;
                                                                local_281 = ((f32((_e2957 % _e2958)) + 0.5f) / _e2962);
                                                                let _e2964 = local_280;
                                                                if _e2964 {
                                                                    phi_5215_ = true;
                                                                    break;
                                                                }
                                                                let _e2965 = local_276;
                                                                let _e2966 = local_245;
                                                                let _e2970 = local_279;
                                                                let _e2972 = local_261;
                                                                let _e2973 = local_281;
                                                                let _e2974 = (_e2972 - _e2973);
                                                                local_282 = _e2974;
                                                                let _e2975 = local_262;
                                                                let _e2976 = (_e2975 - ((f32((_e2965 / _e2966)) + 0.5f) / _e2970));
                                                                local_283 = _e2976;
                                                                local_284 = (_e2974 + 1f);
                                                                local_285 = (_e2976 + 1f);
                                                                let _e2979 = local_270;
                                                                if (_e2979 >= 0.0001f) {
                                                                    let _e2993 = local_282;
                                                                    let _e2995 = local_284;
                                                                    let _e2997 = local_282;
                                                                    let _e3000 = local_282;
                                                                    let _e3001 = select(select(0f, (-1f - _e2997), (_e2995 < 0f)), _e3000, (0f < _e2993));
                                                                    let _e3002 = local_283;
                                                                    let _e3004 = local_285;
                                                                    let _e3006 = local_283;
                                                                    let _e3007 = (-1f - _e3006);
                                                                    local_286 = _e3007;
                                                                    let _e3009 = local_283;
                                                                    let _e3010 = select(select(0f, _e3007, (_e3004 < 0f)), _e3009, (0f < _e3002));
                                                                    let _e3011 = local_270;
                                                                    let _e3012 = local_270;
                                                                    let _e3013 = (_e3011 * _e3012);
                                                                    local_287 = _e3013;
                                                                    let _e3017 = (_e3013 <= ((_e3001 * _e3001) + (_e3010 * _e3010)));
                                                                    local_288 = _e3017;
                                                                    let _e3018 = local_282;
                                                                    let _e3019 = -(_e3018);
                                                                    let _e3020 = local_284;
                                                                    let _e3022 = local_284;
                                                                    let _e3023 = select(_e3022, _e3019, (_e3020 < _e3019));
                                                                    let _e3024 = local_283;
                                                                    let _e3025 = -(_e3024);
                                                                    local_289 = _e3025;
                                                                    let _e3026 = local_285;
                                                                    let _e3028 = local_285;
                                                                    let _e3029 = select(_e3028, _e3025, (_e3026 < _e3025));
                                                                    let _e3033 = (((_e3023 * _e3023) + (_e3029 * _e3029)) <= _e3013);
                                                                    local_290 = _e3033;
                                                                    let _e3035 = local_274;
                                                                    if ((_e3035 && !(_e3017)) && !(_e3033)) {
                                                                        let _e3039 = local_270;
                                                                        if (_e3039 > 0f) {
                                                                            let _e3041 = local_283;
                                                                            let _e3042 = (0f <= _e3041);
                                                                            let _e3044 = local_285;
                                                                            let _e3046 = (!(_e3042) && (_e3044 <= 0f));
                                                                            let _e3047 = local_289;
                                                                            let _e3048 = local_285;
                                                                            let _e3049 = select(_e3048, _e3047, _e3046);
                                                                            let _e3050 = local_286;
                                                                            let _e3051 = local_289;
                                                                            let _e3053 = local_283;
                                                                            let _e3054 = select(select(_e3051, _e3050, _e3046), _e3053, _e3042);
                                                                            let _e3058 = local_287;
                                                                            let _e3059 = (_e3058 - (_e3049 * _e3049));
                                                                            let _e3062 = select(0f, sqrt(_e3059), (0f < _e3059));
                                                                            let _e3063 = local_282;
                                                                            let _e3065 = -(_e3062);
                                                                            let _e3066 = local_282;
                                                                            let _e3068 = local_282;
                                                                            let _e3070 = select(select(_e3068, _e3065, (_e3066 < _e3065)), _e3062, (_e3062 < _e3063));
                                                                            let _e3071 = local_284;
                                                                            let _e3073 = local_284;
                                                                            let _e3075 = local_284;
                                                                            let _e3077 = select(select(_e3075, _e3065, (_e3073 < _e3065)), _e3062, (_e3062 < _e3071));
                                                                            let _e3078 = local_270;
                                                                            let _e3079 = local_282;
                                                                            let _e3081 = local_260;
                                                                            let _e3082 = (1.4142135f - _e3081);
                                                                            let _e3083 = local_282;
                                                                            let _e3085 = local_282;
                                                                            let _e3087 = local_270;
                                                                            let _e3088 = select(select(_e3085, _e3082, (_e3083 < _e3082)), _e3087, (_e3078 < _e3079));
                                                                            let _e3089 = local_270;
                                                                            let _e3090 = local_284;
                                                                            let _e3092 = local_284;
                                                                            let _e3094 = local_284;
                                                                            let _e3096 = local_270;
                                                                            let _e3097 = select(select(_e3094, _e3082, (_e3092 < _e3082)), _e3096, (_e3089 < _e3090));
                                                                            let _e3101 = local_287;
                                                                            let _e3102 = (_e3101 - (_e3097 * _e3097));
                                                                            let _e3106 = local_270;
                                                                            let _e3107 = (_e3097 / _e3106);
                                                                            let _e3111 = select(select(_e3107, -1f, (_e3107 < -1f)), 1f, (1f < _e3107));
                                                                            let _e3113 = (_e3111 < 0f);
                                                                            let _e3115 = select(_e3111, -(_e3111), _e3113);
                                                                            let _e3117 = select(_e3115, 1f, (1f < _e3115));
                                                                            let _e3118 = (_e3117 <= 0.5f);
                                                                            let _e3122 = select(sqrt((0.5f * (1f - _e3117))), _e3117, _e3118);
                                                                            let _e3123 = (_e3122 * _e3122);
                                                                            let _e3134 = (_e3122 + ((_e3122 * _e3123) * (0.1666673f + (_e3123 * (0.07496333f + (_e3123 * (0.04533125f + (_e3123 * (0.024905317f + (_e3123 * 0.04087546f))))))))));
                                                                            let _e3137 = select((1.5707964f - (2f * _e3134)), _e3134, _e3118);
                                                                            let _e3140 = local_287;
                                                                            let _e3145 = local_287;
                                                                            let _e3146 = (_e3145 - (_e3088 * _e3088));
                                                                            let _e3150 = local_270;
                                                                            let _e3151 = (_e3088 / _e3150);
                                                                            let _e3155 = select(select(_e3151, -1f, (_e3151 < -1f)), 1f, (1f < _e3151));
                                                                            let _e3157 = (_e3155 < 0f);
                                                                            let _e3159 = select(_e3155, -(_e3155), _e3157);
                                                                            let _e3161 = select(_e3159, 1f, (1f < _e3159));
                                                                            let _e3162 = (_e3161 <= 0.5f);
                                                                            let _e3166 = select(sqrt((0.5f * (1f - _e3161))), _e3161, _e3162);
                                                                            let _e3167 = (_e3166 * _e3166);
                                                                            let _e3178 = (_e3166 + ((_e3166 * _e3167) * (0.1666673f + (_e3167 * (0.07496333f + (_e3167 * (0.04533125f + (_e3167 * (0.024905317f + (_e3167 * 0.04087546f))))))))));
                                                                            let _e3181 = select((1.5707964f - (2f * _e3178)), _e3178, _e3162);
                                                                            let _e3184 = local_287;
                                                                            let _e3188 = ((0.5f * ((_e3097 * select(0f, sqrt(_e3102), (0f < _e3102))) + (_e3140 * select(_e3137, -(_e3137), _e3113)))) - (0.5f * ((_e3088 * select(0f, sqrt(_e3146), (0f < _e3146))) + (_e3184 * select(_e3181, -(_e3181), _e3157)))));
                                                                            let _e3191 = local_287;
                                                                            let _e3192 = (_e3191 - (_e3077 * _e3077));
                                                                            let _e3196 = local_270;
                                                                            let _e3197 = (_e3077 / _e3196);
                                                                            let _e3201 = select(select(_e3197, -1f, (_e3197 < -1f)), 1f, (1f < _e3197));
                                                                            let _e3203 = (_e3201 < 0f);
                                                                            let _e3205 = select(_e3201, -(_e3201), _e3203);
                                                                            let _e3207 = select(_e3205, 1f, (1f < _e3205));
                                                                            let _e3208 = (_e3207 <= 0.5f);
                                                                            let _e3212 = select(sqrt((0.5f * (1f - _e3207))), _e3207, _e3208);
                                                                            let _e3213 = (_e3212 * _e3212);
                                                                            let _e3224 = (_e3212 + ((_e3212 * _e3213) * (0.1666673f + (_e3213 * (0.07496333f + (_e3213 * (0.04533125f + (_e3213 * (0.024905317f + (_e3213 * 0.04087546f))))))))));
                                                                            let _e3227 = select((1.5707964f - (2f * _e3224)), _e3224, _e3208);
                                                                            let _e3230 = local_287;
                                                                            let _e3235 = local_287;
                                                                            let _e3236 = (_e3235 - (_e3070 * _e3070));
                                                                            let _e3240 = local_270;
                                                                            let _e3241 = (_e3070 / _e3240);
                                                                            let _e3245 = select(select(_e3241, -1f, (_e3241 < -1f)), 1f, (1f < _e3241));
                                                                            let _e3247 = (_e3245 < 0f);
                                                                            let _e3249 = select(_e3245, -(_e3245), _e3247);
                                                                            let _e3251 = select(_e3249, 1f, (1f < _e3249));
                                                                            let _e3252 = (_e3251 <= 0.5f);
                                                                            let _e3256 = select(sqrt((0.5f * (1f - _e3251))), _e3251, _e3252);
                                                                            let _e3257 = (_e3256 * _e3256);
                                                                            let _e3268 = (_e3256 + ((_e3256 * _e3257) * (0.1666673f + (_e3257 * (0.07496333f + (_e3257 * (0.04533125f + (_e3257 * (0.024905317f + (_e3257 * 0.04087546f))))))))));
                                                                            let _e3271 = select((1.5707964f - (2f * _e3268)), _e3268, _e3252);
                                                                            let _e3274 = local_287;
                                                                            let _e3281 = local_287;
                                                                            let _e3282 = (_e3281 - (_e3054 * _e3054));
                                                                            let _e3285 = select(0f, sqrt(_e3282), (0f < _e3282));
                                                                            let _e3286 = local_282;
                                                                            let _e3288 = -(_e3285);
                                                                            let _e3289 = local_282;
                                                                            let _e3291 = local_282;
                                                                            let _e3293 = select(select(_e3291, _e3288, (_e3289 < _e3288)), _e3285, (_e3285 < _e3286));
                                                                            let _e3294 = local_284;
                                                                            let _e3296 = local_284;
                                                                            let _e3298 = local_284;
                                                                            let _e3300 = select(select(_e3298, _e3288, (_e3296 < _e3288)), _e3285, (_e3285 < _e3294));
                                                                            let _e3305 = local_287;
                                                                            let _e3306 = (_e3305 - (_e3300 * _e3300));
                                                                            let _e3310 = local_270;
                                                                            let _e3311 = (_e3300 / _e3310);
                                                                            let _e3315 = select(select(_e3311, -1f, (_e3311 < -1f)), 1f, (1f < _e3311));
                                                                            let _e3317 = (_e3315 < 0f);
                                                                            let _e3319 = select(_e3315, -(_e3315), _e3317);
                                                                            let _e3321 = select(_e3319, 1f, (1f < _e3319));
                                                                            let _e3322 = (_e3321 <= 0.5f);
                                                                            let _e3326 = select(sqrt((0.5f * (1f - _e3321))), _e3321, _e3322);
                                                                            let _e3327 = (_e3326 * _e3326);
                                                                            let _e3338 = (_e3326 + ((_e3326 * _e3327) * (0.1666673f + (_e3327 * (0.07496333f + (_e3327 * (0.04533125f + (_e3327 * (0.024905317f + (_e3327 * 0.04087546f))))))))));
                                                                            let _e3341 = select((1.5707964f - (2f * _e3338)), _e3338, _e3322);
                                                                            let _e3344 = local_287;
                                                                            let _e3349 = local_287;
                                                                            let _e3350 = (_e3349 - (_e3293 * _e3293));
                                                                            let _e3354 = local_270;
                                                                            let _e3355 = (_e3293 / _e3354);
                                                                            let _e3359 = select(select(_e3355, -1f, (_e3355 < -1f)), 1f, (1f < _e3355));
                                                                            let _e3361 = (_e3359 < 0f);
                                                                            let _e3363 = select(_e3359, -(_e3359), _e3361);
                                                                            let _e3365 = select(_e3363, 1f, (1f < _e3363));
                                                                            let _e3366 = (_e3365 <= 0.5f);
                                                                            let _e3370 = select(sqrt((0.5f * (1f - _e3365))), _e3365, _e3366);
                                                                            let _e3371 = (_e3370 * _e3370);
                                                                            let _e3382 = (_e3370 + ((_e3370 * _e3371) * (0.1666673f + (_e3371 * (0.07496333f + (_e3371 * (0.04533125f + (_e3371 * (0.024905317f + (_e3371 * 0.04087546f))))))))));
                                                                            let _e3385 = select((1.5707964f - (2f * _e3382)), _e3382, _e3366);
                                                                            let _e3388 = local_287;
                                                                            let _e3395 = ((((_e3049 * (_e3077 - _e3070)) + _e3188) - ((0.5f * ((_e3077 * select(0f, sqrt(_e3192), (0f < _e3192))) + (_e3230 * select(_e3227, -(_e3227), _e3203)))) - (0.5f * ((_e3070 * select(0f, sqrt(_e3236), (0f < _e3236))) + (_e3274 * select(_e3271, -(_e3271), _e3247)))))) + (select(1f, -1f, (_e3042 || _e3046)) * (((_e3054 * (_e3300 - _e3293)) + _e3188) - ((0.5f * ((_e3300 * select(0f, sqrt(_e3306), (0f < _e3306))) + (_e3344 * select(_e3341, -(_e3341), _e3317)))) - (0.5f * ((_e3293 * select(0f, sqrt(_e3350), (0f < _e3350))) + (_e3388 * select(_e3385, -(_e3385), _e3361))))))));
                                                                            let _e3396 = local_284;
                                                                            let _e3397 = local_282;
                                                                            let _e3399 = local_285;
                                                                            let _e3400 = local_283;
                                                                            let _e3402 = ((_e3396 - _e3397) * (_e3399 - _e3400));
                                                                            phi_3162_ = select(select(0f, _e3395, (0f < _e3395)), _e3402, (_e3402 < _e3395));
                                                                        } else {
                                                                            phi_3162_ = 0f;
                                                                        }
                                                                        let _e3408 = phi_3162_;
                                                                        let _e3409 = local_290;
                                                                        phi_3167_ = select(_e3408, 1f, _e3409);
                                                                    } else {
                                                                        phi_3167_ = 1f;
                                                                    }
                                                                    let _e3412 = phi_3167_;
                                                                    let _e3413 = local_272;
                                                                    let _e3415 = local_288;
                                                                    phi_3186_ = select((_e3412 / _e3413), 0f, _e3415);
                                                                } else {
                                                                    let _e2981 = local_282;
                                                                    let _e2983 = local_284;
                                                                    let _e2986 = local_283;
                                                                    let _e2989 = local_285;
                                                                    phi_3186_ = select(0f, 1f, ((((_e2981 <= 0f) && (0f < _e2983)) && (_e2986 <= 0f)) && (0f < _e2989)));
                                                                }
                                                                let _e3418 = phi_3186_;
                                                                let _e3419 = local_277;
                                                                let _e3421 = local_278;
                                                                phi_3189_ = (_e3419 + _e3418);
                                                                phi_3190_ = (_e3421 + 1u);
                                                            }
                                                            let _e3424 = phi_3189_;
                                                            let _e3426 = phi_3190_;
                                                            let _e3427 = local_276;
                                                            phi_3192_ = (_e3427 + 1u);
                                                            phi_3193_ = _e3424;
                                                            phi_3194_ = _e3426;
                                                        } else {
                                                            phi_3192_ = u32();
                                                            phi_3193_ = f32();
                                                            phi_3194_ = u32();
                                                        }
                                                        let _e3430 = phi_3192_;
                                                        let _e3432 = phi_3193_;
                                                        let _e3434 = phi_3194_;
                                                        phi_2347_ = _e3430;
                                                        phi_2350_ = _e3432;
                                                        phi_2352_ = _e3434;
                                                        phi_3195_ = _e2945;
                                                    } else {
                                                        phi_2347_ = u32();
                                                        phi_2350_ = f32();
                                                        phi_2352_ = u32();
                                                        phi_3195_ = false;
                                                    }
                                                    let _e3436 = phi_2347_;
                                                    let _e3438 = phi_2350_;
                                                    let _e3440 = phi_2352_;
                                                    let _e3442 = phi_3195_;
                                                    local_291 = _e3442;
                                                    continue;
                                                    continuing {
                                                        let _e3443 = local_291;
                                                        phi_2346_ = _e3436;
                                                        phi_2349_ = _e3438;
                                                        phi_2351_ = _e3440;
                                                        phi_5215_ = _e2403;
                                                        break if !(_e3443);
                                                    }
                                                }
                                                let _e3446 = phi_5215_;
                                                phi_5321_ = _e3446;
                                                if _e3446 {
                                                    break;
                                                }
                                                let _e3447 = local_278;
                                                if (_e3447 == 0u) {
                                                    phi_3206_ = 0f;
                                                } else {
                                                    let _e3449 = local_278;
                                                    let _e3451 = local_277;
                                                    phi_3206_ = (_e3451 / f32(_e3449));
                                                }
                                                let _e3454 = phi_3206_;
                                                let _e3455 = local_271;
                                                let _e3456 = local_273;
                                                phi_5377_ = _e3446;
                                                phi_3211_ = select(_e3454, _e3456, _e3455);
                                            } else {
                                                phi_5377_ = _e2403;
                                                phi_3211_ = _e2928;
                                            }
                                            let _e3459 = phi_5377_;
                                            let _e3461 = phi_3211_;
                                            phi_5333_ = _e3459;
                                            phi_3678_ = _e3461;
                                        } else {
                                            let _e2475 = local_29;
                                            let _e2476 = (_e2475 == 0u);
                                            local_292 = _e2476;
                                            if _e2476 {
                                                let _e2477 = local_36;
                                                phi_3222_ = (_e2477 == 0u);
                                            } else {
                                                phi_3222_ = false;
                                            }
                                            let _e2480 = phi_3222_;
                                            if _e2480 {
                                                let _e2895 = local_260;
                                                let _e2896 = local_268;
                                                let _e2897 = (_e2895 - _e2896);
                                                let _e2900 = local_263;
                                                let _e2903 = local_263;
                                                let _e2905 = local_260;
                                                let _e2907 = local_268;
                                                let _e2909 = ((_e2905 - sqrt(_e2903)) * (1f / _e2907));
                                                phi_3677_ = select(select(0f, select(1f, _e2909, (_e2909 < 1f)), (0f < _e2909)), 1f, ((0f < _e2897) && (_e2900 <= (_e2897 * _e2897))));
                                            } else {
                                                let _e2481 = local_248;
                                                let _e2482 = (3840u + _e2481);
                                                local_293 = _e2482;
                                                if (_e2482 < 5888u) {
                                                } else {
                                                    phi_5321_ = true;
                                                    break;
                                                }
                                                let _e2484 = local_293;
                                                let _e2486 = global_15[_e2484];
                                                local_294 = bitcast<f32>(_e2486);
                                                let _e2488 = local_292;
                                                if _e2488 {
                                                    let _e2489 = local_36;
                                                    phi_3268_ = (_e2489 == 0u);
                                                } else {
                                                    phi_3268_ = false;
                                                }
                                                let _e2492 = phi_3268_;
                                                if _e2492 {
                                                    let _e2873 = local_260;
                                                    let _e2874 = local_268;
                                                    let _e2875 = (_e2873 - _e2874);
                                                    let _e2878 = local_263;
                                                    let _e2881 = local_263;
                                                    let _e2883 = local_260;
                                                    let _e2885 = local_268;
                                                    let _e2887 = ((_e2883 - sqrt(_e2881)) * (1f / _e2885));
                                                    phi_3676_ = select(select(0f, select(1f, _e2887, (_e2887 < 1f)), (0f < _e2887)), 1f, ((0f < _e2875) && (_e2878 <= (_e2875 * _e2875))));
                                                } else {
                                                    let _e2493 = local_294;
                                                    let _e2494 = local_261;
                                                    local_295 = (_e2493 * _e2494);
                                                    let _e2496 = local_294;
                                                    let _e2497 = local_262;
                                                    local_296 = (_e2496 * _e2497);
                                                    let _e2499 = local_36;
                                                    if (_e2499 > 0u) {
                                                        let _e2582 = local_268;
                                                        let _e2584 = local_260;
                                                        let _e2585 = (_e2584 - (0.5f * _e2582));
                                                        local_297 = _e2585;
                                                        if (_e2585 > 0f) {
                                                            let _e2587 = local_295;
                                                            let _e2588 = local_297;
                                                            let _e2590 = local_296;
                                                            let _e2591 = local_297;
                                                            let _e2593 = local_36;
                                                            let _e2594 = f32(_e2593);
                                                            local_298 = _e2594;
                                                            let _e2598 = (((((_e2587 / _e2588) + 1f) * 0.5f) * _e2594) - 0.5f);
                                                            local_299 = _e2598;
                                                            local_300 = (((((_e2590 / _e2591) + 1f) * 0.5f) * _e2594) - 0.5f);
                                                            if (_e2598 > -1f) {
                                                                let _e2604 = local_300;
                                                                if (_e2604 > -1f) {
                                                                    let _e2606 = local_299;
                                                                    let _e2607 = local_298;
                                                                    if (_e2606 < _e2607) {
                                                                        let _e2609 = local_300;
                                                                        let _e2610 = local_298;
                                                                        let _e2611 = (_e2609 < _e2610);
                                                                        local_301 = _e2611;
                                                                        if _e2611 {
                                                                            let _e2612 = local_299;
                                                                            let _e2613 = floor(_e2612);
                                                                            local_302 = _e2613;
                                                                            let _e2614 = local_300;
                                                                            let _e2615 = floor(_e2614);
                                                                            local_303 = _e2615;
                                                                            let _e2616 = local_299;
                                                                            local_304 = (_e2616 - _e2613);
                                                                            let _e2618 = local_300;
                                                                            local_305 = (_e2618 - _e2615);
                                                                            let _e2620 = (_e2613 < 0f);
                                                                            local_306 = _e2620;
                                                                            if _e2620 {
                                                                                phi_3389_ = f32();
                                                                                phi_3390_ = true;
                                                                            } else {
                                                                                let _e2621 = local_303;
                                                                                if (_e2621 < 0f) {
                                                                                    phi_3387_ = f32();
                                                                                    phi_3388_ = true;
                                                                                } else {
                                                                                    let _e2623 = local_302;
                                                                                    let _e2624 = local_298;
                                                                                    if (_e2623 >= _e2624) {
                                                                                        phi_3385_ = f32();
                                                                                        phi_3386_ = true;
                                                                                    } else {
                                                                                        let _e2626 = local_303;
                                                                                        let _e2627 = local_298;
                                                                                        let _e2628 = (_e2626 >= _e2627);
                                                                                        if _e2628 {
                                                                                            phi_3384_ = f32();
                                                                                        } else {
                                                                                            let _e2629 = local_303;
                                                                                            let _e2631 = local_303;
                                                                                            let _e2634 = local_303;
                                                                                            let _e2638 = local_36;
                                                                                            let _e2640 = local_302;
                                                                                            let _e2642 = local_302;
                                                                                            let _e2645 = local_302;
                                                                                            let _e2649 = ((select(select(u32(_e2629), 0u, !((_e2631 >= 0f))), 4294967295u, (_e2634 > 4294967000f)) * _e2638) + select(select(u32(_e2640), 0u, !((_e2642 >= 0f))), 4294967295u, (_e2645 > 4294967000f)));
                                                                                            local_307 = _e2649;
                                                                                            let _e2650 = local_12;
                                                                                            if (_e2649 < _e2650) {
                                                                                            } else {
                                                                                                phi_5321_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2652 = local_307;
                                                                                            let _e2655 = global_14.member[_e2652];
                                                                                            phi_3384_ = bitcast<f32>(_e2655);
                                                                                        }
                                                                                        let _e2658 = phi_3384_;
                                                                                        phi_3385_ = _e2658;
                                                                                        phi_3386_ = _e2628;
                                                                                    }
                                                                                    let _e2660 = phi_3385_;
                                                                                    let _e2662 = phi_3386_;
                                                                                    phi_3387_ = _e2660;
                                                                                    phi_3388_ = _e2662;
                                                                                }
                                                                                let _e2664 = phi_3387_;
                                                                                let _e2666 = phi_3388_;
                                                                                phi_3389_ = _e2664;
                                                                                phi_3390_ = _e2666;
                                                                            }
                                                                            let _e2668 = phi_3389_;
                                                                            let _e2670 = phi_3390_;
                                                                            let _e2672 = local_304;
                                                                            let _e2673 = (1f - _e2672);
                                                                            local_308 = _e2673;
                                                                            local_309 = (select(_e2668, 0f, _e2670) * _e2673);
                                                                            let _e2675 = local_302;
                                                                            let _e2676 = (_e2675 + 1f);
                                                                            local_310 = _e2676;
                                                                            let _e2677 = (_e2676 < 0f);
                                                                            local_311 = _e2677;
                                                                            if _e2677 {
                                                                                phi_3445_ = f32();
                                                                                phi_3446_ = true;
                                                                            } else {
                                                                                let _e2678 = local_303;
                                                                                if (_e2678 < 0f) {
                                                                                    phi_3443_ = f32();
                                                                                    phi_3444_ = true;
                                                                                } else {
                                                                                    let _e2680 = local_310;
                                                                                    let _e2681 = local_298;
                                                                                    if (_e2680 >= _e2681) {
                                                                                        phi_3441_ = f32();
                                                                                        phi_3442_ = true;
                                                                                    } else {
                                                                                        let _e2683 = local_303;
                                                                                        let _e2684 = local_298;
                                                                                        let _e2685 = (_e2683 >= _e2684);
                                                                                        if _e2685 {
                                                                                            phi_3440_ = f32();
                                                                                        } else {
                                                                                            let _e2686 = local_303;
                                                                                            let _e2688 = local_303;
                                                                                            let _e2691 = local_303;
                                                                                            let _e2695 = local_36;
                                                                                            let _e2697 = local_310;
                                                                                            let _e2699 = local_310;
                                                                                            let _e2702 = local_310;
                                                                                            let _e2706 = ((select(select(u32(_e2686), 0u, !((_e2688 >= 0f))), 4294967295u, (_e2691 > 4294967000f)) * _e2695) + select(select(u32(_e2697), 0u, !((_e2699 >= 0f))), 4294967295u, (_e2702 > 4294967000f)));
                                                                                            local_312 = _e2706;
                                                                                            let _e2707 = local_12;
                                                                                            if (_e2706 < _e2707) {
                                                                                            } else {
                                                                                                phi_5321_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2709 = local_312;
                                                                                            let _e2712 = global_14.member[_e2709];
                                                                                            phi_3440_ = bitcast<f32>(_e2712);
                                                                                        }
                                                                                        let _e2715 = phi_3440_;
                                                                                        phi_3441_ = _e2715;
                                                                                        phi_3442_ = _e2685;
                                                                                    }
                                                                                    let _e2717 = phi_3441_;
                                                                                    let _e2719 = phi_3442_;
                                                                                    phi_3443_ = _e2717;
                                                                                    phi_3444_ = _e2719;
                                                                                }
                                                                                let _e2721 = phi_3443_;
                                                                                let _e2723 = phi_3444_;
                                                                                phi_3445_ = _e2721;
                                                                                phi_3446_ = _e2723;
                                                                            }
                                                                            let _e2725 = phi_3445_;
                                                                            let _e2727 = phi_3446_;
                                                                            let _e2729 = local_304;
                                                                            let _e2731 = local_309;
                                                                            local_313 = (_e2731 + (select(_e2725, 0f, _e2727) * _e2729));
                                                                            let _e2733 = local_303;
                                                                            local_314 = (_e2733 + 1f);
                                                                            let _e2735 = local_306;
                                                                            if _e2735 {
                                                                                phi_3501_ = f32();
                                                                                phi_3502_ = true;
                                                                            } else {
                                                                                let _e2736 = local_314;
                                                                                if (_e2736 < 0f) {
                                                                                    phi_3499_ = f32();
                                                                                    phi_3500_ = true;
                                                                                } else {
                                                                                    let _e2738 = local_302;
                                                                                    let _e2739 = local_298;
                                                                                    if (_e2738 >= _e2739) {
                                                                                        phi_3497_ = f32();
                                                                                        phi_3498_ = true;
                                                                                    } else {
                                                                                        let _e2741 = local_314;
                                                                                        let _e2742 = local_298;
                                                                                        let _e2743 = (_e2741 >= _e2742);
                                                                                        if _e2743 {
                                                                                            phi_3496_ = f32();
                                                                                        } else {
                                                                                            let _e2744 = local_314;
                                                                                            let _e2746 = local_314;
                                                                                            let _e2749 = local_314;
                                                                                            let _e2753 = local_36;
                                                                                            let _e2755 = local_302;
                                                                                            let _e2757 = local_302;
                                                                                            let _e2760 = local_302;
                                                                                            let _e2764 = ((select(select(u32(_e2744), 0u, !((_e2746 >= 0f))), 4294967295u, (_e2749 > 4294967000f)) * _e2753) + select(select(u32(_e2755), 0u, !((_e2757 >= 0f))), 4294967295u, (_e2760 > 4294967000f)));
                                                                                            local_315 = _e2764;
                                                                                            let _e2765 = local_12;
                                                                                            if (_e2764 < _e2765) {
                                                                                            } else {
                                                                                                phi_5321_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2767 = local_315;
                                                                                            let _e2770 = global_14.member[_e2767];
                                                                                            phi_3496_ = bitcast<f32>(_e2770);
                                                                                        }
                                                                                        let _e2773 = phi_3496_;
                                                                                        phi_3497_ = _e2773;
                                                                                        phi_3498_ = _e2743;
                                                                                    }
                                                                                    let _e2775 = phi_3497_;
                                                                                    let _e2777 = phi_3498_;
                                                                                    phi_3499_ = _e2775;
                                                                                    phi_3500_ = _e2777;
                                                                                }
                                                                                let _e2779 = phi_3499_;
                                                                                let _e2781 = phi_3500_;
                                                                                phi_3501_ = _e2779;
                                                                                phi_3502_ = _e2781;
                                                                            }
                                                                            let _e2783 = phi_3501_;
                                                                            let _e2785 = phi_3502_;
                                                                            let _e2787 = local_308;
                                                                            local_316 = (select(_e2783, 0f, _e2785) * _e2787);
                                                                            let _e2789 = local_311;
                                                                            if _e2789 {
                                                                                phi_3558_ = f32();
                                                                                phi_3559_ = true;
                                                                            } else {
                                                                                let _e2790 = local_314;
                                                                                if (_e2790 < 0f) {
                                                                                    phi_3556_ = f32();
                                                                                    phi_3557_ = true;
                                                                                } else {
                                                                                    let _e2792 = local_310;
                                                                                    let _e2793 = local_298;
                                                                                    if (_e2792 >= _e2793) {
                                                                                        phi_3554_ = f32();
                                                                                        phi_3555_ = true;
                                                                                    } else {
                                                                                        let _e2795 = local_314;
                                                                                        let _e2796 = local_298;
                                                                                        let _e2797 = (_e2795 >= _e2796);
                                                                                        if _e2797 {
                                                                                            phi_3553_ = f32();
                                                                                        } else {
                                                                                            let _e2798 = local_314;
                                                                                            let _e2800 = local_314;
                                                                                            let _e2803 = local_314;
                                                                                            let _e2807 = local_36;
                                                                                            let _e2809 = local_310;
                                                                                            let _e2811 = local_310;
                                                                                            let _e2814 = local_310;
                                                                                            let _e2818 = ((select(select(u32(_e2798), 0u, !((_e2800 >= 0f))), 4294967295u, (_e2803 > 4294967000f)) * _e2807) + select(select(u32(_e2809), 0u, !((_e2811 >= 0f))), 4294967295u, (_e2814 > 4294967000f)));
                                                                                            local_317 = _e2818;
                                                                                            let _e2819 = local_12;
                                                                                            if (_e2818 < _e2819) {
                                                                                            } else {
                                                                                                phi_5321_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2821 = local_317;
                                                                                            let _e2824 = global_14.member[_e2821];
                                                                                            phi_3553_ = bitcast<f32>(_e2824);
                                                                                        }
                                                                                        let _e2827 = phi_3553_;
                                                                                        phi_3554_ = _e2827;
                                                                                        phi_3555_ = _e2797;
                                                                                    }
                                                                                    let _e2829 = phi_3554_;
                                                                                    let _e2831 = phi_3555_;
                                                                                    phi_3556_ = _e2829;
                                                                                    phi_3557_ = _e2831;
                                                                                }
                                                                                let _e2833 = phi_3556_;
                                                                                let _e2835 = phi_3557_;
                                                                                phi_3558_ = _e2833;
                                                                                phi_3559_ = _e2835;
                                                                            }
                                                                            let _e2837 = phi_3558_;
                                                                            let _e2839 = phi_3559_;
                                                                            let _e2841 = local_304;
                                                                            let _e2843 = local_316;
                                                                            let _e2845 = local_305;
                                                                            let _e2847 = local_313;
                                                                            let _e2849 = local_305;
                                                                            phi_3570_ = ((_e2847 * (1f - _e2845)) + ((_e2843 + (select(_e2837, 0f, _e2839) * _e2841)) * _e2849));
                                                                        } else {
                                                                            phi_3570_ = f32();
                                                                        }
                                                                        let _e2853 = phi_3570_;
                                                                        let _e2854 = local_301;
                                                                        phi_3572_ = _e2853;
                                                                        phi_3573_ = select(true, false, _e2854);
                                                                    } else {
                                                                        phi_3572_ = f32();
                                                                        phi_3573_ = true;
                                                                    }
                                                                    let _e2857 = phi_3572_;
                                                                    let _e2859 = phi_3573_;
                                                                    phi_3574_ = _e2857;
                                                                    phi_3575_ = _e2859;
                                                                } else {
                                                                    phi_3574_ = f32();
                                                                    phi_3575_ = true;
                                                                }
                                                                let _e2861 = phi_3574_;
                                                                let _e2863 = phi_3575_;
                                                                phi_3576_ = _e2861;
                                                                phi_3577_ = _e2863;
                                                            } else {
                                                                phi_3576_ = f32();
                                                                phi_3577_ = true;
                                                            }
                                                            let _e2865 = phi_3576_;
                                                            let _e2867 = phi_3577_;
                                                            phi_3582_ = select(_e2865, 0f, _e2867);
                                                        } else {
                                                            phi_3582_ = 0f;
                                                        }
                                                        let _e2870 = phi_3582_;
                                                        phi_3675_ = _e2870;
                                                    } else {
                                                        let _e2501 = local_295;
                                                        let _e2502 = local_295;
                                                        let _e2504 = local_296;
                                                        let _e2505 = local_296;
                                                        let _e2508 = sqrt(((_e2501 * _e2502) + (_e2504 * _e2505)));
                                                        local_318 = _e2508;
                                                        let _e2509 = local_292;
                                                        if _e2509 {
                                                            phi_3662_ = _e2508;
                                                        } else {
                                                            let _e2510 = local_31;
                                                            let _e2512 = local_295;
                                                            let _e2514 = local_31;
                                                            let _e2516 = local_296;
                                                            phi_3604_ = 1u;
                                                            phi_3607_ = ((_e2512 * _e2510[0]) + (_e2516 * _e2514[1]));
                                                            phi_3609_ = _e658.member_16.member_2;
                                                            loop {
                                                                let _e2520 = phi_3604_;
                                                                let _e2522 = phi_3607_;
                                                                let _e2524 = phi_3609_;
                                                                local_319 = _e2520;
                                                                local_320 = _e2522;
                                                                local_321 = _e2524;
                                                                let _e2525 = local_319;
                                                                let _e2526 = local_29;
                                                                let _e2527 = (_e2525 < _e2526);
                                                                local_322 = _e2527;
                                                                if _e2527 {
                                                                    let _e2528 = local_321;
                                                                    let _e2530 = local_32;
                                                                    let _e2532 = local_321;
                                                                    let _e2534 = local_33;
                                                                    let _e2536 = ((_e2528[0] * _e2530) - (_e2532[1] * _e2534));
                                                                    let _e2537 = local_33;
                                                                    let _e2539 = local_32;
                                                                    let _e2541 = ((_e2528[0] * _e2537) + (_e2532[1] * _e2539));
                                                                    let _e2543 = local_295;
                                                                    let _e2545 = local_296;
                                                                    let _e2547 = ((_e2543 * _e2536) + (_e2545 * _e2541));
                                                                    let _e2548 = local_320;
                                                                    let _e2550 = local_320;
                                                                    let _e2552 = local_319;
                                                                    phi_3605_ = (_e2552 + 1u);
                                                                    phi_3608_ = select(_e2550, _e2547, (_e2547 > _e2548));
                                                                    phi_3610_ = array<f32, 2>(_e2536, _e2541);
                                                                } else {
                                                                    phi_3605_ = u32();
                                                                    phi_3608_ = f32();
                                                                    phi_3610_ = array<f32, 2>();
                                                                }
                                                                let _e2555 = phi_3605_;
                                                                let _e2557 = phi_3608_;
                                                                let _e2559 = phi_3610_;
                                                                continue;
                                                                continuing {
                                                                    let _e2560 = local_322;
                                                                    phi_3604_ = _e2555;
                                                                    phi_3607_ = _e2557;
                                                                    phi_3609_ = _e2559;
                                                                    break if !(_e2560);
                                                                }
                                                            }
                                                            let _e2562 = local_30;
                                                            let _e2564 = local_320;
                                                            let _e2566 = local_34;
                                                            let _e2568 = local_30;
                                                            let _e2569 = local_318;
                                                            phi_3662_ = ((((1f - _e2562) * _e2564) * _e2566) + (_e2568 * _e2569));
                                                        }
                                                        let _e2573 = phi_3662_;
                                                        let _e2574 = local_260;
                                                        let _e2576 = local_268;
                                                        let _e2577 = ((_e2574 - _e2573) / _e2576);
                                                        phi_3675_ = select(0f, select(1f, _e2577, (_e2577 < 1f)), (0f < _e2577));
                                                    }
                                                    let _e2872 = phi_3675_;
                                                    phi_3676_ = _e2872;
                                                }
                                                let _e2894 = phi_3676_;
                                                phi_3677_ = _e2894;
                                            }
                                            let _e2916 = phi_3677_;
                                            phi_5333_ = _e2403;
                                            phi_3678_ = _e2916;
                                        }
                                        let _e3463 = phi_5333_;
                                        let _e3465 = phi_3678_;
                                        local_323 = _e3465;
                                        let _e3466 = local_248;
                                        let _e3467 = (2304u + _e3466);
                                        local_324 = _e3467;
                                        if (_e3467 < 5888u) {
                                        } else {
                                            phi_5321_ = true;
                                            break;
                                        }
                                        let _e3469 = local_324;
                                        let _e3471 = global_15[_e3469];
                                        let _e3473 = local_323;
                                        local_325 = (bitcast<f32>(_e3471) * _e3473);
                                        let _e3475 = local_248;
                                        let _e3476 = (4096u + _e3475);
                                        local_326 = _e3476;
                                        if (_e3476 < 5888u) {
                                        } else {
                                            phi_5321_ = true;
                                            break;
                                        }
                                        let _e3478 = local_326;
                                        let _e3480 = global_15[_e3478];
                                        local_327 = bitcast<f32>(_e3480);
                                        let _e3482 = local_98;
                                        let _e3483 = local_248;
                                        let _e3485 = local_78;
                                        if ((_e3482 + _e3483) < _e3485) {
                                            let _e3508 = local_248;
                                            let _e3509 = (3328u + _e3508);
                                            local_328 = _e3509;
                                            if (_e3509 < 5888u) {
                                            } else {
                                                phi_5321_ = true;
                                                break;
                                            }
                                            let _e3511 = local_328;
                                            let _e3513 = global_15[_e3511];
                                            let _e3514 = bitcast<f32>(_e3513);
                                            local_329 = _e3514;
                                            let _e3515 = local_246;
                                            let _e3516 = (1f - _e3515);
                                            local_330 = _e3516;
                                            let _e3517 = local_247;
                                            local_331 = _e3517.member;
                                            let _e3522 = local_247;
                                            local_332 = _e3522.member_1;
                                            let _e3524 = local_325;
                                            let _e3528 = (!((_e3514 <= (_e3517.member * 1.05f))) || (1f < (_e3522.member_1 + (0.5f * _e3524))));
                                            let _e3529 = local_247;
                                            local_333 = _e3529.member_3;
                                            let _e3532 = local_247;
                                            local_334 = _e3532.member_4;
                                            let _e3535 = !(_e3528);
                                            local_335 = ((_e3528 && !(_e3529.member_3)) || (_e3535 && _e3532.member_4));
                                            local_336 = (_e3535 && _e3529.member_3);
                                            let _e3539 = local_247;
                                            local_337 = _e3539.member_2;
                                            local_480 = select(_e3539.member_2, _e3516, _e3528);
                                            let _e3543 = local_325;
                                            local_338 = (select(_e3522.member_1, 0f, _e3528) + _e3543);
                                            let _e3545 = local_327;
                                            let _e3546 = (_e3545 < 1f);
                                            local_339 = _e3546;
                                            if _e3546 {
                                                let _e3547 = local_269;
                                                if _e3547 {
                                                    phi_3773_ = type_19();
                                                } else {
                                                    let _e3548 = local_335;
                                                    let _e3549 = local_480;
                                                    let _e3551 = local_325;
                                                    let _e3552 = (_e3551 * select(1f, _e3549, _e3548));
                                                    local_340 = _e3552;
                                                    let _e3553 = local_327;
                                                    let _e3554 = (_e3552 * _e3553);
                                                    local_341 = _e3554;
                                                    let _e3555 = local_330;
                                                    local_342 = (_e3554 < _e3555);
                                                    let _e3557 = local_327;
                                                    if (_e3557 == 1f) {
                                                        phi_3763_ = _e3516;
                                                    } else {
                                                        let _e3559 = local_330;
                                                        let _e3560 = local_327;
                                                        phi_3763_ = (_e3559 / _e3560);
                                                    }
                                                    let _e3563 = phi_3763_;
                                                    let _e3564 = local_342;
                                                    let _e3565 = local_340;
                                                    let _e3567 = local_342;
                                                    let _e3568 = local_341;
                                                    let _e3569 = local_330;
                                                    phi_3773_ = type_19(select(_e3563, _e3565, _e3564), select(_e3569, _e3568, _e3567));
                                                }
                                                let _e3573 = phi_3773_;
                                                phi_3774_ = _e3573;
                                            } else {
                                                phi_3774_ = type_19();
                                            }
                                            let _e3575 = phi_3774_;
                                            let _e3576 = local_339;
                                            let _e3577 = local_269;
                                            let _e3578 = select(true, _e3577, _e3576);
                                            local_481 = _e3578;
                                            if _e3578 {
                                                let _e3579 = local_325;
                                                let _e3580 = local_327;
                                                let _e3581 = (_e3579 * _e3580);
                                                local_343 = _e3581;
                                                let _e3582 = local_330;
                                                local_344 = (_e3581 < _e3582);
                                                let _e3584 = local_327;
                                                if (_e3584 == 1f) {
                                                    phi_3786_ = _e3516;
                                                } else {
                                                    let _e3586 = local_330;
                                                    let _e3587 = local_327;
                                                    phi_3786_ = (_e3586 / _e3587);
                                                }
                                                let _e3590 = phi_3786_;
                                                let _e3591 = local_344;
                                                let _e3592 = local_325;
                                                let _e3594 = local_344;
                                                let _e3595 = local_343;
                                                let _e3596 = local_330;
                                                phi_3797_ = type_19(select(_e3590, _e3592, _e3591), select(_e3596, _e3595, _e3594));
                                            } else {
                                                phi_3797_ = _e3575;
                                            }
                                            let _e3600 = phi_3797_;
                                            let _e3601 = local_481;
                                            let _e3602 = local_336;
                                            let _e3604 = local_264;
                                            let _e3605 = local_329;
                                            let _e3606 = local_331;
                                            let _e3608 = local_264;
                                            let _e3609 = local_338;
                                            let _e3610 = local_332;
                                            let _e3612 = local_264;
                                            let _e3613 = local_480;
                                            let _e3614 = local_337;
                                            let _e3616 = local_264;
                                            let _e3618 = local_264;
                                            let _e3619 = !(_e3618);
                                            let _e3620 = local_333;
                                            let _e3623 = local_264;
                                            let _e3624 = local_335;
                                            let _e3626 = local_334;
                                            phi_3849_ = type_32(select(_e3606, _e3605, _e3604), select(_e3610, _e3609, _e3608), select(_e3614, _e3613, _e3612), ((_e3616 && select(_e3602, true, _e3601)) || (_e3619 && _e3620)), ((_e3623 && _e3624) || (_e3619 && _e3626)));
                                            phi_3850_ = _e3600;
                                        } else {
                                            let _e3487 = local_246;
                                            let _e3488 = (1f - _e3487);
                                            local_345 = _e3488;
                                            let _e3489 = local_325;
                                            let _e3490 = local_327;
                                            let _e3491 = (_e3489 * _e3490);
                                            local_346 = _e3491;
                                            local_347 = (_e3491 < _e3488);
                                            let _e3493 = local_327;
                                            if (_e3493 == 1f) {
                                                phi_3839_ = _e3488;
                                            } else {
                                                let _e3495 = local_345;
                                                let _e3496 = local_327;
                                                phi_3839_ = (_e3495 / _e3496);
                                            }
                                            let _e3499 = phi_3839_;
                                            let _e3500 = local_347;
                                            let _e3501 = local_325;
                                            let _e3503 = local_347;
                                            let _e3504 = local_346;
                                            let _e3505 = local_345;
                                            phi_3849_ = _e2407;
                                            phi_3850_ = type_19(select(_e3499, _e3501, _e3500), select(_e3505, _e3504, _e3503));
                                        }
                                        let _e3631 = phi_3849_;
                                        let _e3633 = phi_3850_;
                                        local_348 = _e3633.member;
                                        local_349 = _e3633.member_1;
                                        let _e3636 = local_253;
                                        local_350 = _e3636[0];
                                        let _e3638 = local_248;
                                        let _e3639 = (2560u + _e3638);
                                        local_351 = _e3639;
                                        if (_e3639 < 5888u) {
                                        } else {
                                            phi_5321_ = true;
                                            break;
                                        }
                                        let _e3641 = local_351;
                                        let _e3643 = global_15[_e3641];
                                        let _e3645 = local_348;
                                        let _e3647 = local_350;
                                        let _e3649 = local_264;
                                        let _e3650 = local_350;
                                        local_482 = select(_e3650, (_e3647 + (_e3645 * bitcast<f32>(_e3643))), _e3649);
                                        let _e3652 = local_253;
                                        local_352 = _e3652[1];
                                        let _e3654 = local_248;
                                        let _e3655 = (2816u + _e3654);
                                        local_353 = _e3655;
                                        if (_e3655 < 5888u) {
                                        } else {
                                            phi_5321_ = true;
                                            break;
                                        }
                                        let _e3657 = local_353;
                                        let _e3659 = global_15[_e3657];
                                        let _e3661 = local_348;
                                        let _e3663 = local_352;
                                        let _e3665 = local_264;
                                        let _e3666 = local_352;
                                        local_483 = select(_e3666, (_e3663 + (_e3661 * bitcast<f32>(_e3659))), _e3665);
                                        let _e3668 = local_253;
                                        local_354 = _e3668[2];
                                        let _e3670 = local_248;
                                        let _e3671 = (3072u + _e3670);
                                        local_355 = _e3671;
                                        if (_e3671 < 5888u) {
                                        } else {
                                            phi_5321_ = true;
                                            break;
                                        }
                                        let _e3673 = local_355;
                                        let _e3675 = global_15[_e3673];
                                        let _e3677 = local_348;
                                        let _e3679 = local_354;
                                        let _e3681 = local_264;
                                        let _e3682 = local_354;
                                        let _e3684 = local_482;
                                        let _e3685 = local_483;
                                        let _e3687 = local_246;
                                        let _e3688 = local_349;
                                        let _e3690 = local_264;
                                        let _e3691 = local_246;
                                        let _e3692 = select(_e3691, (_e3687 + _e3688), _e3690);
                                        let _e3695 = local_264;
                                        let _e3696 = (_e3695 && !((_e3692 < 0.99902344f)));
                                        local_356 = _e3696;
                                        if _e3696 {
                                            let _e3697 = local_252;
                                            let _e3698 = local_356;
                                            let _e3700 = local_248;
                                            let _e3703 = local_356;
                                            let _e3704 = local_251;
                                            let _e3706 = local_356;
                                            let _e3707 = local_250;
                                            let _e3708 = select(_e3707, 0f, _e3706);
                                            phi_3935_ = select(select(u32(_e3708), 0u, !((_e3708 >= 0f))), 4294967295u, (_e3708 > 4294967000f));
                                            phi_3936_ = _e3708;
                                            phi_3937_ = select(_e3704, f32((_e3700 + 1u)), _e3703);
                                            phi_3938_ = (_e3697 || _e3698);
                                        } else {
                                            phi_3935_ = _e2411;
                                            phi_3936_ = _e2413;
                                            phi_3937_ = _e2415;
                                            phi_3938_ = _e2417;
                                        }
                                        let _e3716 = phi_3935_;
                                        let _e3718 = phi_3936_;
                                        let _e3720 = phi_3937_;
                                        let _e3722 = phi_3938_;
                                        phi_5323_ = _e3463;
                                        phi_3939_ = _e3692;
                                        phi_3940_ = _e3631;
                                        phi_3941_ = _e3716;
                                        phi_3942_ = _e3718;
                                        phi_3943_ = _e3720;
                                        phi_3944_ = _e3722;
                                        phi_3945_ = array<f32, 3>(_e3684, _e3685, select(_e3682, (_e3679 + (_e3677 * bitcast<f32>(_e3675))), _e3681));
                                    } else {
                                        phi_5323_ = _e2403;
                                        phi_3939_ = _e2405;
                                        phi_3940_ = _e2407;
                                        phi_3941_ = _e2411;
                                        phi_3942_ = _e2413;
                                        phi_3943_ = _e2415;
                                        phi_3944_ = _e2417;
                                        phi_3945_ = _e2419;
                                    }
                                    let _e3724 = phi_5323_;
                                    let _e3726 = phi_3939_;
                                    let _e3728 = phi_3940_;
                                    let _e3730 = phi_3941_;
                                    let _e3732 = phi_3942_;
                                    let _e3734 = phi_3943_;
                                    let _e3736 = phi_3944_;
                                    let _e3738 = phi_3945_;
                                    let _e3739 = local_248;
                                    phi_5322_ = _e3724;
                                    phi_2244_ = _e3726;
                                    phi_2247_ = _e3728;
                                    phi_2249_ = (_e3739 + 1u);
                                    phi_2251_ = _e3730;
                                    phi_2253_ = _e3732;
                                    phi_2255_ = _e3734;
                                    phi_2257_ = _e3736;
                                    phi_2259_ = _e3738;
                                } else {
                                    phi_5322_ = _e2403;
                                    phi_2244_ = f32();
                                    phi_2247_ = type_32();
                                    phi_2249_ = u32();
                                    phi_2251_ = u32();
                                    phi_2253_ = f32();
                                    phi_2255_ = f32();
                                    phi_2257_ = bool();
                                    phi_2259_ = array<f32, 3>();
                                }
                                let _e3742 = phi_5322_;
                                let _e3744 = phi_2244_;
                                let _e3746 = phi_2247_;
                                let _e3748 = phi_2249_;
                                let _e3750 = phi_2251_;
                                let _e3752 = phi_2253_;
                                let _e3754 = phi_2255_;
                                let _e3756 = phi_2257_;
                                let _e3758 = phi_2259_;
                                continue;
                                continuing {
                                    let _e3759 = local_254;
                                    phi_5218_ = _e3742;
                                    phi_2243_ = _e3744;
                                    phi_2246_ = _e3746;
                                    phi_2248_ = _e3748;
                                    phi_2250_ = _e3750;
                                    phi_2252_ = _e3752;
                                    phi_2254_ = _e3754;
                                    phi_2256_ = _e3756;
                                    phi_2258_ = _e3758;
                                    phi_5321_ = _e3742;
                                    break if !(_e3759);
                                }
                            }
                            let _e3762 = phi_5321_;
                            phi_5435_ = _e3762;
                            if _e3762 {
                                break;
                            }
                            let _e3763 = local_253;
                            local_357 = _e3763[0];
                            phi_3949_ = 0u;
                            loop {
                                let _e3766 = phi_3949_;
                                local_358 = _e3766;
                                let _e3767 = local_358;
                                let _e3768 = (_e3767 < 1u);
                                local_359 = _e3768;
                                if _e3768 {
                                    let _e3769 = local;
                                    let _e3770 = local_358;
                                    let _e3771 = (_e3769 + _e3770);
                                    local_360 = _e3771;
                                    let _e3772 = local_357;
                                    local_361 = bitcast<u32>(_e3772);
                                    if (_e3771 < 5888u) {
                                    } else {
                                        phi_5397_ = true;
                                        break;
                                    }
                                    let _e3775 = local_360;
                                    let _e3777 = local_361;
                                    global_15[_e3775] = _e3777;
                                    let _e3778 = local_358;
                                    phi_3950_ = (_e3778 + 1u);
                                } else {
                                    phi_3950_ = u32();
                                }
                                let _e3781 = phi_3950_;
                                continue;
                                continuing {
                                    let _e3782 = local_359;
                                    phi_3949_ = _e3781;
                                    phi_5397_ = _e3762;
                                    break if !(_e3782);
                                }
                            }
                            let _e3785 = phi_5397_;
                            phi_5435_ = _e3785;
                            if _e3785 {
                                break;
                            }
                            let _e3786 = local_253;
                            local_362 = _e3786[1];
                            phi_3970_ = 0u;
                            loop {
                                let _e3789 = phi_3970_;
                                local_363 = _e3789;
                                let _e3790 = local_363;
                                let _e3791 = (_e3790 < 1u);
                                local_364 = _e3791;
                                if _e3791 {
                                    let _e3792 = local;
                                    let _e3793 = local_363;
                                    let _e3795 = local_362;
                                    local_365 = bitcast<u32>(_e3795);
                                    let _e3797 = (256u + (_e3792 + _e3793));
                                    local_366 = _e3797;
                                    if (_e3797 < 5888u) {
                                    } else {
                                        phi_5400_ = true;
                                        break;
                                    }
                                    let _e3799 = local_366;
                                    let _e3801 = local_365;
                                    global_15[_e3799] = _e3801;
                                    let _e3802 = local_363;
                                    phi_3971_ = (_e3802 + 1u);
                                } else {
                                    phi_3971_ = u32();
                                }
                                let _e3805 = phi_3971_;
                                continue;
                                continuing {
                                    let _e3806 = local_364;
                                    phi_3970_ = _e3805;
                                    phi_5400_ = _e3785;
                                    break if !(_e3806);
                                }
                            }
                            let _e3809 = phi_5400_;
                            phi_5435_ = _e3809;
                            if _e3809 {
                                break;
                            }
                            let _e3810 = local_253;
                            local_367 = _e3810[2];
                            phi_3991_ = 0u;
                            loop {
                                let _e3813 = phi_3991_;
                                local_368 = _e3813;
                                let _e3814 = local_368;
                                let _e3815 = (_e3814 < 1u);
                                local_369 = _e3815;
                                if _e3815 {
                                    let _e3816 = local;
                                    let _e3817 = local_368;
                                    let _e3819 = local_367;
                                    local_370 = bitcast<u32>(_e3819);
                                    let _e3821 = (512u + (_e3816 + _e3817));
                                    local_371 = _e3821;
                                    if (_e3821 < 5888u) {
                                    } else {
                                        phi_5403_ = true;
                                        break;
                                    }
                                    let _e3823 = local_371;
                                    let _e3825 = local_370;
                                    global_15[_e3823] = _e3825;
                                    let _e3826 = local_368;
                                    phi_3992_ = (_e3826 + 1u);
                                } else {
                                    phi_3992_ = u32();
                                }
                                let _e3829 = phi_3992_;
                                continue;
                                continuing {
                                    let _e3830 = local_369;
                                    phi_3991_ = _e3829;
                                    phi_5403_ = _e3809;
                                    break if !(_e3830);
                                }
                            }
                            let _e3833 = phi_5403_;
                            phi_5435_ = _e3833;
                            if _e3833 {
                                break;
                            }
                            phi_4011_ = 0u;
                            loop {
                                let _e3835 = phi_4011_;
                                local_372 = _e3835;
                                let _e3836 = local_372;
                                let _e3837 = (_e3836 < 1u);
                                local_373 = _e3837;
                                if _e3837 {
                                    let _e3838 = local;
                                    let _e3839 = local_372;
                                    let _e3841 = local_246;
                                    local_374 = bitcast<u32>(_e3841);
                                    let _e3843 = (768u + (_e3838 + _e3839));
                                    local_375 = _e3843;
                                    if (_e3843 < 5888u) {
                                    } else {
                                        phi_5406_ = true;
                                        break;
                                    }
                                    let _e3845 = local_375;
                                    let _e3847 = local_374;
                                    global_15[_e3845] = _e3847;
                                    let _e3848 = local_372;
                                    phi_4012_ = (_e3848 + 1u);
                                } else {
                                    phi_4012_ = u32();
                                }
                                let _e3851 = phi_4012_;
                                continue;
                                continuing {
                                    let _e3852 = local_373;
                                    phi_4011_ = _e3851;
                                    phi_5406_ = _e3833;
                                    break if !(_e3852);
                                }
                            }
                            let _e3855 = phi_5406_;
                            phi_5435_ = _e3855;
                            if _e3855 {
                                break;
                            }
                            phi_4032_ = 0u;
                            loop {
                                let _e3857 = phi_4032_;
                                local_376 = _e3857;
                                let _e3858 = local_376;
                                let _e3859 = (_e3858 < 1u);
                                local_377 = _e3859;
                                if _e3859 {
                                    let _e3860 = local_247;
                                    local_378 = bitcast<u32>(_e3860.member);
                                    let _e3863 = local_91;
                                    let _e3864 = local_376;
                                    let _e3865 = (_e3863 + _e3864);
                                    local_379 = _e3865;
                                    if (_e3865 < 5888u) {
                                    } else {
                                        phi_5409_ = true;
                                        break;
                                    }
                                    let _e3867 = local_379;
                                    let _e3869 = local_378;
                                    global_15[_e3867] = _e3869;
                                    let _e3870 = local_247;
                                    local_380 = bitcast<u32>(_e3870.member_1);
                                    let _e3873 = local_224;
                                    let _e3874 = local_376;
                                    let _e3875 = (_e3873 + _e3874);
                                    local_381 = _e3875;
                                    if (_e3875 < 5888u) {
                                    } else {
                                        phi_5409_ = true;
                                        break;
                                    }
                                    let _e3877 = local_381;
                                    let _e3879 = local_380;
                                    global_15[_e3877] = _e3879;
                                    let _e3880 = local_247;
                                    local_382 = bitcast<u32>(_e3880.member_2);
                                    let _e3883 = local_226;
                                    let _e3884 = local_376;
                                    let _e3885 = (_e3883 + _e3884);
                                    local_383 = _e3885;
                                    if (_e3885 < 5888u) {
                                    } else {
                                        phi_5409_ = true;
                                        break;
                                    }
                                    let _e3887 = local_383;
                                    let _e3889 = local_382;
                                    global_15[_e3887] = _e3889;
                                    let _e3890 = local_247;
                                    local_384 = select(0u, 1u, _e3890.member_3);
                                    let _e3893 = local_247;
                                    local_385 = (select(0u, 1u, _e3893.member_4) << bitcast<u32>(1i));
                                    let _e3898 = local_228;
                                    let _e3899 = local_376;
                                    let _e3900 = (_e3898 + _e3899);
                                    local_386 = _e3900;
                                    if (_e3900 < 5888u) {
                                    } else {
                                        phi_5409_ = true;
                                        break;
                                    }
                                    let _e3902 = local_386;
                                    let _e3904 = local_384;
                                    let _e3905 = local_385;
                                    global_15[_e3902] = (_e3904 | _e3905);
                                    let _e3907 = local_376;
                                    phi_4033_ = (_e3907 + 1u);
                                } else {
                                    phi_4033_ = u32();
                                }
                                let _e3910 = phi_4033_;
                                continue;
                                continuing {
                                    let _e3911 = local_377;
                                    phi_4032_ = _e3910;
                                    phi_5409_ = _e3855;
                                    break if !(_e3911);
                                }
                            }
                            let _e3914 = phi_5409_;
                            phi_5435_ = _e3914;
                            if _e3914 {
                                break;
                            }
                            phi_4088_ = 0u;
                            loop {
                                let _e3916 = phi_4088_;
                                local_387 = _e3916;
                                let _e3917 = local_387;
                                let _e3918 = (_e3917 < 1u);
                                local_388 = _e3918;
                                if _e3918 {
                                    let _e3919 = local;
                                    let _e3920 = local_387;
                                    local_389 = (_e3919 + _e3920);
                                    let _e3922 = local_252;
                                    if _e3922 {
                                        let _e3946 = local_251;
                                        let _e3948 = local_251;
                                        let _e3951 = local_251;
                                        phi_4148_ = false;
                                        phi_4149_ = select(select(u32(_e3946), 0u, !((_e3948 >= 0f))), 4294967295u, (_e3951 > 4294967000f));
                                    } else {
                                        let _e3923 = local_388;
                                        if _e3923 {
                                        } else {
                                            phi_5412_ = true;
                                            break;
                                        }
                                        let _e3924 = local_387;
                                        let _e3926 = local_488[_e3924];
                                        if _e3926 {
                                            let _e3927 = local_388;
                                            if _e3927 {
                                            } else {
                                                phi_5412_ = true;
                                                break;
                                            }
                                            let _e3928 = local_387;
                                            let _e3930 = local_489[_e3928];
                                            let _e3931 = local_478;
                                            if (_e3930 < _e3931) {
                                                let _e3933 = local_388;
                                                if _e3933 {
                                                } else {
                                                    phi_5412_ = true;
                                                    break;
                                                }
                                                let _e3934 = local_489[_e3928];
                                                phi_4137_ = (_e3934 + 1u);
                                            } else {
                                                phi_4137_ = _e2158;
                                            }
                                            let _e3937 = phi_4137_;
                                            let _e3938 = local_388;
                                            if _e3938 {
                                            } else {
                                                phi_5412_ = true;
                                                break;
                                            }
                                            let _e3939 = local_489[_e3928];
                                            let _e3940 = local_478;
                                            phi_4146_ = (_e3939 == _e3940);
                                            phi_4147_ = _e3937;
                                        } else {
                                            phi_4146_ = false;
                                            phi_4147_ = 0u;
                                        }
                                        let _e3943 = phi_4146_;
                                        let _e3945 = phi_4147_;
                                        phi_4148_ = _e3943;
                                        phi_4149_ = _e3945;
                                    }
                                    let _e3956 = phi_4148_;
                                    let _e3958 = phi_4149_;
                                    local_390 = _e3956;
                                    local_391 = _e3958;
                                    let _e3959 = local_388;
                                    if _e3959 {
                                    } else {
                                        phi_5412_ = true;
                                        break;
                                    }
                                    let _e3960 = local_387;
                                    let _e3962 = local_487[_e3960];
                                    if _e3962 {
                                        let _e3963 = local_389;
                                        let _e3964 = (1280u + _e3963);
                                        local_392 = _e3964;
                                        if (_e3964 < 5888u) {
                                        } else {
                                            phi_5412_ = true;
                                            break;
                                        }
                                        let _e3966 = local_392;
                                        let _e3968 = global_15[_e3966];
                                        let _e3969 = local_391;
                                        global_15[_e3966] = (_e3968 + _e3969);
                                    }
                                    let _e3971 = local_389;
                                    let _e3972 = (4352u + _e3971);
                                    local_393 = _e3972;
                                    if (_e3972 < 5888u) {
                                    } else {
                                        phi_5412_ = true;
                                        break;
                                    }
                                    let _e3974 = local_393;
                                    let _e3976 = local_390;
                                    global_15[_e3974] = select(0u, 1u, _e3976);
                                    let _e3978 = local_387;
                                    phi_4089_ = (_e3978 + 1u);
                                } else {
                                    phi_4089_ = u32();
                                }
                                let _e3981 = phi_4089_;
                                continue;
                                continuing {
                                    let _e3982 = local_388;
                                    phi_4088_ = _e3981;
                                    phi_5412_ = _e3914;
                                    break if !(_e3982);
                                }
                            }
                            let _e3985 = phi_5412_;
                            phi_5435_ = _e3985;
                            if _e3985 {
                                break;
                            }
                            storageBarrier();
                            workgroupBarrier();
                            let _e3986 = local_60;
                            if _e3986 {
                                let _e3987 = local_1;
                                let _e3989 = local_1;
                                if ((_e3989 & (_e3987 - 1u)) == 0u) {
                                    let _e3992 = local_2;
                                    let _e3993 = local_1;
                                    let _e3995 = ((_e3992 * _e3993) == 256u);
                                    local_394 = _e3995;
                                    if _e3995 {
                                        let _e3996 = local_1;
                                        phi_4196_ = type_17(1u, _e3996);
                                    } else {
                                        phi_4196_ = type_17();
                                    }
                                    let _e3999 = phi_4196_;
                                    let _e4000 = local_394;
                                    phi_4198_ = _e3999;
                                    phi_4199_ = select(true, false, _e4000);
                                } else {
                                    phi_4198_ = type_17();
                                    phi_4199_ = true;
                                }
                                let _e4003 = phi_4198_;
                                let _e4005 = phi_4199_;
                                phi_4200_ = _e4003;
                                phi_4201_ = _e4005;
                            } else {
                                phi_4200_ = type_17();
                                phi_4201_ = true;
                            }
                            let _e4007 = phi_4200_;
                            let _e4009 = phi_4201_;
                            if _e4009 {
                                phi_4206_ = type_17(0u, type_17().member_1);
                            } else {
                                phi_4206_ = _e4007;
                            }
                            let _e4014 = phi_4206_;
                            local_395 = _e4014.member_1;
                            if (bitcast<i32>(_e4014.member) != 0i) {
                                let _e4051 = local_395;
                                let _e4053 = local_395;
                                local_396 = select(firstTrailingBit(_e4051), 32u, (_e4053 == 0u));
                                phi_4218_ = 0u;
                                phi_4221_ = 256u;
                                loop {
                                    let _e4057 = phi_4218_;
                                    let _e4059 = phi_4221_;
                                    local_397 = _e4057;
                                    local_398 = _e4059;
                                    let _e4060 = local_398;
                                    let _e4061 = local_395;
                                    let _e4062 = (_e4060 > _e4061);
                                    local_399 = _e4062;
                                    if _e4062 {
                                        let _e4063 = local_3;
                                        let _e4064 = local_1;
                                        let _e4066 = local_4;
                                        let _e4067 = ((_e4063 * _e4064) + _e4066);
                                        local_400 = _e4067;
                                        let _e4068 = local_398;
                                        let _e4069 = (_e4067 < _e4068);
                                        local_401 = _e4069;
                                        if _e4069 {
                                            let _e4070 = local_397;
                                            let _e4072 = local_400;
                                            let _e4075 = (4352u + (_e4072 << bitcast<u32>((_e4070 & 31u))));
                                            local_402 = _e4075;
                                            if (_e4075 < 5888u) {
                                            } else {
                                                phi_5429_ = true;
                                                break;
                                            }
                                            let _e4077 = local_402;
                                            let _e4079 = global_15[_e4077];
                                            phi_4245_ = _e4079;
                                        } else {
                                            phi_4245_ = 0u;
                                        }
                                        let _e4081 = phi_4245_;
                                        let _e4082 = subgroupMax(_e4081);
                                        local_403 = _e4082;
                                        let _e4083 = local_401;
                                        if _e4083 {
                                            let _e4084 = local_395;
                                            let _e4086 = local_400;
                                            if ((_e4086 & (_e4084 - 1u)) == 0u) {
                                                let _e4089 = local_397;
                                                let _e4091 = local_400;
                                                let _e4094 = (4352u + (_e4091 << bitcast<u32>((_e4089 & 31u))));
                                                local_404 = _e4094;
                                                if (_e4094 < 5888u) {
                                                } else {
                                                    phi_5429_ = true;
                                                    break;
                                                }
                                                let _e4096 = local_404;
                                                let _e4098 = local_403;
                                                global_15[_e4096] = _e4098;
                                            }
                                        }
                                        storageBarrier();
                                        workgroupBarrier();
                                        let _e4099 = local_396;
                                        let _e4101 = local_398;
                                        let _e4104 = local_397;
                                        let _e4105 = local_396;
                                        phi_4219_ = (_e4104 + _e4105);
                                        phi_4222_ = (_e4101 >> bitcast<u32>((_e4099 & 31u)));
                                    } else {
                                        phi_4219_ = u32();
                                        phi_4222_ = u32();
                                    }
                                    let _e4108 = phi_4219_;
                                    let _e4110 = phi_4222_;
                                    continue;
                                    continuing {
                                        let _e4111 = local_399;
                                        phi_4218_ = _e4108;
                                        phi_4221_ = _e4110;
                                        phi_5429_ = _e3985;
                                        break if !(_e4111);
                                    }
                                }
                                let _e4114 = phi_5429_;
                                phi_5435_ = _e4114;
                                if _e4114 {
                                    break;
                                }
                                let _e4115 = local_3;
                                let _e4116 = local_1;
                                let _e4118 = local_4;
                                let _e4120 = local_395;
                                let _e4122 = (((_e4115 * _e4116) + _e4118) & (_e4120 - 1u));
                                local_405 = _e4122;
                                let _e4123 = local_398;
                                if (_e4122 < _e4123) {
                                    let _e4125 = local_397;
                                    let _e4127 = local_405;
                                    let _e4130 = (4352u + (_e4127 << bitcast<u32>((_e4125 & 31u))));
                                    local_406 = _e4130;
                                    if (_e4130 < 5888u) {
                                    } else {
                                        phi_5435_ = true;
                                        break;
                                    }
                                    let _e4132 = local_406;
                                    let _e4134 = global_15[_e4132];
                                    phi_4316_ = _e4134;
                                } else {
                                    phi_4316_ = 0u;
                                }
                                let _e4136 = phi_4316_;
                                let _e4137 = subgroupMax(_e4136);
                                storageBarrier();
                                workgroupBarrier();
                                phi_5438_ = _e4114;
                                phi_4397_ = _e4137;
                            } else {
                                phi_4349_ = 128u;
                                loop {
                                    let _e4020 = phi_4349_;
                                    local_407 = _e4020;
                                    let _e4021 = local_407;
                                    let _e4022 = (_e4021 > 0u);
                                    local_408 = _e4022;
                                    if _e4022 {
                                        let _e4023 = local;
                                        let _e4024 = local_407;
                                        if (_e4023 < _e4024) {
                                            let _e4026 = local_59;
                                            if _e4026 {
                                            } else {
                                                phi_5419_ = true;
                                                break;
                                            }
                                            let _e4027 = global_15[_e894];
                                            local_409 = _e4027;
                                            let _e4028 = local_58;
                                            let _e4029 = local_407;
                                            let _e4030 = (_e4028 + _e4029);
                                            local_410 = _e4030;
                                            if (_e4030 < 5888u) {
                                            } else {
                                                phi_5419_ = true;
                                                break;
                                            }
                                            let _e4032 = local_410;
                                            let _e4034 = global_15[_e4032];
                                            let _e4035 = local_409;
                                            let _e4037 = local_409;
                                            local_484 = select(_e4034, _e4037, (_e4035 > _e4034));
                                            let _e4039 = local_59;
                                            if _e4039 {
                                            } else {
                                                phi_5419_ = true;
                                                break;
                                            }
                                            let _e4040 = local_484;
                                            global_15[_e894] = _e4040;
                                        }
                                        storageBarrier();
                                        workgroupBarrier();
                                        let _e4041 = local_407;
                                        phi_4350_ = (_e4041 / 2u);
                                    } else {
                                        phi_4350_ = u32();
                                    }
                                    let _e4044 = phi_4350_;
                                    continue;
                                    continuing {
                                        let _e4045 = local_408;
                                        phi_4349_ = _e4044;
                                        phi_5419_ = _e3985;
                                        break if !(_e4045);
                                    }
                                }
                                let _e4048 = phi_5419_;
                                phi_5435_ = _e4048;
                                if _e4048 {
                                    break;
                                }
                                let _e4050 = global_15[4352u];
                                storageBarrier();
                                workgroupBarrier();
                                phi_5438_ = _e4048;
                                phi_4397_ = _e4050;
                            }
                            let _e4139 = phi_5438_;
                            let _e4141 = phi_4397_;
                            let _e4142 = local_98;
                            phi_5437_ = _e4139;
                            phi_4399_ = (_e4142 + 256u);
                            phi_4400_ = _e4141;
                        }
                        let _e4145 = phi_5437_;
                        let _e4147 = phi_4399_;
                        let _e4149 = phi_4400_;
                        let _e4150 = local_100;
                        phi_5436_ = _e4145;
                        phi_814_ = _e4147;
                        phi_817_ = _e4149;
                        phi_4402_ = select(true, false, _e4150);
                    } else {
                        phi_5436_ = _e1180;
                        phi_814_ = u32();
                        phi_817_ = u32();
                        phi_4402_ = false;
                    }
                    let _e4153 = phi_5436_;
                    let _e4155 = phi_814_;
                    let _e4157 = phi_817_;
                    let _e4159 = phi_4402_;
                    local_411 = _e4159;
                    continue;
                    continuing {
                        let _e4160 = local_411;
                        phi_5131_ = _e4153;
                        phi_813_ = _e4155;
                        phi_816_ = _e4157;
                        phi_5435_ = _e4153;
                        break if !(_e4160);
                    }
                }
                let _e4163 = phi_5435_;
                if _e4163 {
                    break;
                }
                let _e4164 = local_37;
                if _e4164 {
                    break;
                }
                let _e4165 = local_37;
                if _e4165 {
                    break;
                }
                let _e4166 = local_85;
                if _e4166 {
                    let _e4167 = local_82;
                    let _e4168 = local_17;
                    let _e4169 = (_e4167 < _e4168);
                    local_412 = _e4169;
                    if _e4169 {
                        let _e4170 = local_83;
                        let _e4171 = local_18;
                        phi_4463_ = (_e4170 < _e4171);
                    } else {
                        phi_4463_ = bool();
                    }
                    let _e4174 = phi_4463_;
                    let _e4175 = local_412;
                    phi_4465_ = _e4174;
                    phi_4466_ = select(true, false, _e4175);
                } else {
                    phi_4465_ = bool();
                    phi_4466_ = true;
                }
                let _e4178 = phi_4465_;
                let _e4180 = phi_4466_;
                if select(_e4178, false, _e4180) {
                    let _e4182 = local_83;
                    let _e4183 = local_17;
                    let _e4185 = local_82;
                    let _e4186 = ((_e4182 * _e4183) + _e4185);
                    local_413 = _e4186;
                    let _e4187 = (4u * _e4186);
                    local_414 = _e4187;
                    let _e4188 = local_5;
                    if (_e4187 < _e4188) {
                    } else {
                        break;
                    }
                    let _e4190 = local_414;
                    let _e4193 = global_8.member[_e4190];
                    local_415 = bitcast<f32>(_e4193);
                    let _e4195 = local_414;
                    let _e4196 = (_e4195 + 1u);
                    local_416 = _e4196;
                    let _e4197 = local_5;
                    if (_e4196 < _e4197) {
                    } else {
                        break;
                    }
                    let _e4199 = local_416;
                    let _e4202 = global_8.member[_e4199];
                    local_417 = bitcast<f32>(_e4202);
                    let _e4204 = local_414;
                    let _e4205 = (_e4204 + 2u);
                    local_418 = _e4205;
                    let _e4206 = local_5;
                    if (_e4205 < _e4206) {
                    } else {
                        break;
                    }
                    let _e4208 = local_418;
                    let _e4211 = global_8.member[_e4208];
                    local_419 = bitcast<f32>(_e4211);
                    let _e4213 = local_414;
                    let _e4214 = (_e4213 + 3u);
                    local_420 = _e4214;
                    let _e4215 = local_5;
                    if (_e4214 < _e4215) {
                    } else {
                        break;
                    }
                    let _e4217 = local_420;
                    let _e4220 = global_8.member[_e4217];
                    local_421 = bitcast<f32>(_e4220);
                    let _e4222 = local;
                    let _e4223 = (768u + _e4222);
                    local_422 = _e4223;
                    let _e4224 = (_e4223 < 5888u);
                    local_423 = _e4224;
                    if _e4224 {
                    } else {
                        break;
                    }
                    let _e4225 = local_422;
                    let _e4227 = global_15[_e4225];
                    local_424 = (1f - bitcast<f32>(_e4227));
                    let _e4230 = local_421;
                    if ((bitcast<u32>(_e4230) & 2147483647u) > 2139095040u) {
                    } else {
                        let _e4234 = local_424;
                        if (_e4234 > 0f) {
                            let _e4236 = local;
                            let _e4237 = (_e4236 < 5888u);
                            local_425 = _e4237;
                            if _e4237 {
                            } else {
                                break;
                            }
                            let _e4238 = local;
                            let _e4240 = global_15[_e4238];
                            let _e4242 = local_424;
                            let _e4243 = local_415;
                            local_426 = bitcast<u32>((bitcast<f32>(_e4240) + (_e4242 * _e4243)));
                            let _e4247 = local_425;
                            if _e4247 {
                            } else {
                                break;
                            }
                            let _e4248 = local_426;
                            global_15[_e4238] = _e4248;
                            let _e4249 = local;
                            let _e4250 = (256u + _e4249);
                            local_427 = _e4250;
                            let _e4251 = (_e4250 < 5888u);
                            local_428 = _e4251;
                            if _e4251 {
                            } else {
                                break;
                            }
                            let _e4252 = local_427;
                            let _e4254 = global_15[_e4252];
                            let _e4256 = local_424;
                            let _e4257 = local_417;
                            local_429 = bitcast<u32>((bitcast<f32>(_e4254) + (_e4256 * _e4257)));
                            let _e4261 = local_428;
                            if _e4261 {
                            } else {
                                break;
                            }
                            let _e4262 = local_429;
                            global_15[_e4252] = _e4262;
                            let _e4263 = local;
                            let _e4264 = (512u + _e4263);
                            local_430 = _e4264;
                            let _e4265 = (_e4264 < 5888u);
                            local_431 = _e4265;
                            if _e4265 {
                            } else {
                                break;
                            }
                            let _e4266 = local_430;
                            let _e4268 = global_15[_e4266];
                            let _e4270 = local_424;
                            let _e4271 = local_419;
                            local_432 = bitcast<u32>((bitcast<f32>(_e4268) + (_e4270 * _e4271)));
                            let _e4275 = local_431;
                            if _e4275 {
                            } else {
                                break;
                            }
                            let _e4276 = local_432;
                            global_15[_e4266] = _e4276;
                            let _e4277 = local_423;
                            if _e4277 {
                            } else {
                                break;
                            }
                            let _e4278 = global_15[_e4225];
                            let _e4280 = local_424;
                            local_433 = bitcast<u32>((bitcast<f32>(_e4278) + _e4280));
                            let _e4283 = local_423;
                            if _e4283 {
                            } else {
                                break;
                            }
                            let _e4284 = local_433;
                            global_15[_e4225] = _e4284;
                        }
                    }
                    let _e4285 = local_423;
                    if _e4285 {
                    } else {
                        break;
                    }
                    let _e4286 = global_15[_e4225];
                    let _e4287 = bitcast<f32>(_e4286);
                    local_434 = _e4287;
                    if (_e4287 > 0.000001f) {
                        let _e4289 = local_434;
                        phi_4623_ = (1f / _e4289);
                    } else {
                        phi_4623_ = 0f;
                    }
                    let _e4292 = phi_4623_;
                    local_435 = _e4292;
                    let _e4293 = local;
                    if (_e4293 < 5888u) {
                    } else {
                        break;
                    }
                    let _e4295 = local;
                    let _e4297 = global_15[_e4295];
                    let _e4299 = local_435;
                    local_436 = (bitcast<f32>(_e4297) * _e4299);
                    let _e4301 = local;
                    let _e4302 = (256u + _e4301);
                    local_437 = _e4302;
                    if (_e4302 < 5888u) {
                    } else {
                        break;
                    }
                    let _e4304 = local_437;
                    let _e4306 = global_15[_e4304];
                    let _e4308 = local_435;
                    local_438 = (bitcast<f32>(_e4306) * _e4308);
                    let _e4310 = local;
                    let _e4311 = (512u + _e4310);
                    local_439 = _e4311;
                    if (_e4311 < 5888u) {
                    } else {
                        break;
                    }
                    let _e4313 = local_439;
                    let _e4315 = global_15[_e4313];
                    let _e4317 = local_435;
                    local_440 = (bitcast<f32>(_e4315) * _e4317);
                    let _e4319 = local_413;
                    let _e4320 = (3u * _e4319);
                    local_441 = _e4320;
                    let _e4321 = local_436;
                    local_442 = bitcast<u32>(_e4321);
                    let _e4323 = local_10;
                    if (_e4320 < _e4323) {
                    } else {
                        break;
                    }
                    let _e4325 = local_441;
                    let _e4328 = local_442;
                    global_2.member[_e4325] = _e4328;
                    let _e4329 = local_441;
                    let _e4330 = (_e4329 + 1u);
                    local_443 = _e4330;
                    let _e4331 = local_438;
                    local_444 = bitcast<u32>(_e4331);
                    let _e4333 = local_10;
                    if (_e4330 < _e4333) {
                    } else {
                        break;
                    }
                    let _e4335 = local_443;
                    let _e4338 = local_444;
                    global_2.member[_e4335] = _e4338;
                    let _e4339 = local_441;
                    let _e4340 = (_e4339 + 2u);
                    local_445 = _e4340;
                    let _e4341 = local_440;
                    local_446 = bitcast<u32>(_e4341);
                    let _e4343 = local_10;
                    if (_e4340 < _e4343) {
                    } else {
                        break;
                    }
                    let _e4345 = local_445;
                    let _e4348 = local_446;
                    global_2.member[_e4345] = _e4348;
                }
                storageBarrier();
                workgroupBarrier();
                phi_4688_ = _e603;
                phi_4691_ = 0u;
                phi_4693_ = 0u;
                loop {
                    let _e4350 = phi_4688_;
                    let _e4352 = phi_4691_;
                    let _e4354 = phi_4693_;
                    local_447 = _e4350;
                    local_448 = _e4352;
                    local_449 = _e4354;
                    let _e4355 = local;
                    let _e4357 = local_447;
                    let _e4358 = (_e4357 < (_e4355 + 1u));
                    local_450 = _e4358;
                    if _e4358 {
                        let _e4359 = local_447;
                        let _e4360 = (1280u + _e4359);
                        local_451 = _e4360;
                        if (_e4360 < 5888u) {
                        } else {
                            phi_5440_ = true;
                            break;
                        }
                        let _e4362 = local_451;
                        let _e4364 = global_15[_e4362];
                        local_452 = _e4364;
                        let _e4365 = local_37;
                        if _e4365 {
                            phi_5440_ = true;
                            break;
                        }
                        let _e4366 = local_447;
                        let _e4367 = local_473;
                        let _e4369 = local_44;
                        local_453 = (_e4369 + (_e4366 % _e4367));
                        let _e4371 = local_37;
                        if _e4371 {
                            phi_5440_ = true;
                            break;
                        }
                        let _e4372 = local_447;
                        let _e4373 = local_473;
                        let _e4375 = local_46;
                        local_454 = (_e4375 + (_e4372 / _e4373));
                        let _e4377 = local_447;
                        let _e4378 = local_84;
                        if (_e4377 < _e4378) {
                            let _e4380 = local_453;
                            let _e4381 = local_17;
                            let _e4382 = (_e4380 < _e4381);
                            local_455 = _e4382;
                            if _e4382 {
                                let _e4383 = local_454;
                                let _e4384 = local_18;
                                phi_4766_ = (_e4383 < _e4384);
                            } else {
                                phi_4766_ = bool();
                            }
                            let _e4387 = phi_4766_;
                            let _e4388 = local_455;
                            phi_4768_ = _e4387;
                            phi_4769_ = select(true, false, _e4388);
                        } else {
                            phi_4768_ = bool();
                            phi_4769_ = true;
                        }
                        let _e4391 = phi_4768_;
                        let _e4393 = phi_4769_;
                        if select(_e4391, false, _e4393) {
                            let _e4395 = local_452;
                            let _e4396 = local_52;
                            if (_e4395 < _e4396) {
                                let _e4398 = local_449;
                                let _e4400 = local_52;
                                let _e4401 = local_452;
                                let _e4403 = local_448;
                                phi_4784_ = (_e4403 + (_e4400 - _e4401));
                                phi_4785_ = (_e4398 + 1u);
                            } else {
                                phi_4784_ = _e4352;
                                phi_4785_ = _e4354;
                            }
                            let _e4406 = phi_4784_;
                            let _e4408 = phi_4785_;
                            phi_4786_ = _e4406;
                            phi_4787_ = _e4408;
                        } else {
                            phi_4786_ = _e4352;
                            phi_4787_ = _e4354;
                        }
                        let _e4410 = phi_4786_;
                        let _e4412 = phi_4787_;
                        let _e4413 = local_447;
                        phi_4689_ = (_e4413 + 1u);
                        phi_4692_ = _e4410;
                        phi_4694_ = _e4412;
                    } else {
                        phi_4689_ = u32();
                        phi_4692_ = u32();
                        phi_4694_ = u32();
                    }
                    let _e4416 = phi_4689_;
                    let _e4418 = phi_4692_;
                    let _e4420 = phi_4694_;
                    continue;
                    continuing {
                        let _e4421 = local_450;
                        phi_4688_ = _e4416;
                        phi_4691_ = _e4418;
                        phi_4693_ = _e4420;
                        phi_5440_ = _e4163;
                        break if !(_e4421);
                    }
                }
                let _e4424 = phi_5440_;
                if _e4424 {
                    break;
                }
                let _e4425 = local_449;
                if (_e4425 > 0u) {
                    let _e4427 = local_11;
                    if (9u < _e4427) {
                    } else {
                        break;
                    }
                    let _e4431 = local_449;
                    let _e4432 = atomicAdd((&global_13.member[9u]), _e4431);
                    let _e4433 = local_11;
                    if (10u < _e4433) {
                    } else {
                        break;
                    }
                    let _e4437 = local_448;
                    let _e4438 = atomicAdd((&global_13.member[10u]), _e4437);
                }
                storageBarrier();
                workgroupBarrier();
            } else {
                let _e718 = local_37;
                if _e718 {
                    break;
                }
                let _e719 = local;
                let _e720 = local_473;
                let _e722 = local_44;
                local_456 = (_e722 + (_e719 % _e720));
                let _e724 = local_37;
                if _e724 {
                    break;
                }
                let _e725 = local;
                let _e726 = local_473;
                let _e728 = local_46;
                local_457 = (_e728 + (_e725 / _e726));
                let _e730 = local_473;
                let _e731 = local_473;
                let _e733 = local;
                if (_e733 < (_e730 * _e731)) {
                    let _e735 = local_456;
                    let _e736 = local_17;
                    let _e737 = (_e735 < _e736);
                    local_458 = _e737;
                    if _e737 {
                        let _e738 = local_457;
                        let _e739 = local_18;
                        phi_4863_ = (_e738 < _e739);
                    } else {
                        phi_4863_ = bool();
                    }
                    let _e742 = phi_4863_;
                    let _e743 = local_458;
                    phi_4865_ = _e742;
                    phi_4866_ = select(true, false, _e743);
                } else {
                    phi_4865_ = bool();
                    phi_4866_ = true;
                }
                let _e746 = phi_4865_;
                let _e748 = phi_4866_;
                if select(_e746, false, _e748) {
                    let _e750 = local_457;
                    let _e751 = local_17;
                    let _e753 = local_456;
                    let _e754 = ((_e750 * _e751) + _e753);
                    local_459 = _e754;
                    let _e755 = (4u * _e754);
                    local_460 = _e755;
                    let _e756 = local_5;
                    if (_e755 < _e756) {
                    } else {
                        break;
                    }
                    let _e758 = local_460;
                    let _e761 = global_8.member[_e758];
                    local_461 = bitcast<f32>(_e761);
                    let _e763 = local_460;
                    let _e764 = (_e763 + 1u);
                    local_462 = _e764;
                    let _e765 = local_5;
                    if (_e764 < _e765) {
                    } else {
                        break;
                    }
                    let _e767 = local_462;
                    let _e770 = global_8.member[_e767];
                    local_463 = bitcast<f32>(_e770);
                    let _e772 = local_460;
                    let _e773 = (_e772 + 2u);
                    local_464 = _e773;
                    let _e774 = local_5;
                    if (_e773 < _e774) {
                    } else {
                        break;
                    }
                    let _e776 = local_464;
                    let _e779 = global_8.member[_e776];
                    let _e781 = local_461;
                    let _e782 = local_463;
                    let _e784 = local_460;
                    let _e785 = (_e784 + 3u);
                    local_465 = _e785;
                    let _e786 = local_5;
                    if (_e785 < _e786) {
                    } else {
                        break;
                    }
                    let _e788 = local_465;
                    let _e791 = global_8.member[_e788];
                    if ((bitcast<u32>(bitcast<f32>(_e791)) & 2147483647u) > 2139095040u) {
                        phi_4921_ = array<f32, 3>(0f, 0f, 0f);
                    } else {
                        phi_4921_ = array<f32, 3>(_e781, _e782, bitcast<f32>(_e779));
                    }
                    let _e797 = phi_4921_;
                    local_466 = _e797;
                    let _e798 = local_459;
                    let _e799 = (3u * _e798);
                    local_467 = _e799;
                    local_468 = bitcast<u32>(_e797[0]);
                    let _e802 = local_10;
                    if (_e799 < _e802) {
                    } else {
                        break;
                    }
                    let _e804 = local_467;
                    let _e807 = local_468;
                    global_2.member[_e804] = _e807;
                    let _e808 = local_467;
                    let _e809 = (_e808 + 1u);
                    local_469 = _e809;
                    let _e810 = local_466;
                    local_470 = bitcast<u32>(_e810[1]);
                    let _e813 = local_10;
                    if (_e809 < _e813) {
                    } else {
                        break;
                    }
                    let _e815 = local_469;
                    let _e818 = local_470;
                    global_2.member[_e815] = _e818;
                    let _e819 = local_467;
                    let _e820 = (_e819 + 2u);
                    local_471 = _e820;
                    let _e821 = local_466;
                    local_472 = bitcast<u32>(_e821[2]);
                    let _e824 = local_10;
                    if (_e820 < _e824) {
                    } else {
                        break;
                    }
                    let _e826 = local_471;
                    let _e829 = local_472;
                    global_2.member[_e826] = _e829;
                }
                storageBarrier();
                workgroupBarrier();
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
    global_3 = param_2;
    global_4 = param_3;
    global_5 = param_4;
    global_6 = param_5;
    function_();
}
