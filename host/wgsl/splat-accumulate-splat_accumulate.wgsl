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
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_18 {
    member: f32,
    member_1: f32,
}

struct type_19 {
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

struct type_20 {
    member: type_19,
}

struct type_29 {
    member: array<u32, 2>,
    member_1: array<f32, 3>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_31 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: bool,
    member_4: bool,
}

struct type_41 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
@group(0) @binding(5) 
var<storage, read_write> global_2: type_7;
var<immediate> global_3: type_20;
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
@group(0) @binding(6) 
var<storage, read_write> global_9: type_41;
@group(0) @binding(7) 
var<storage> global_10: type_7;
var<workgroup> global_11: array<u32, 5888>;
var<private> global_12: u32 = 2143289344u;

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
    var local_11: type_19;
    var local_12: f32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: f32;
    var local_22: f32;
    var local_23: f32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: array<f32, 2>;
    var local_28: f32;
    var local_29: f32;
    var local_30: f32;
    var local_31: f32;
    var local_32: u32;
    var local_33: bool;
    var local_34: u32;
    var local_35: bool;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
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
    var local_49: u32;
    var local_50: u32;
    var local_51: bool;
    var local_52: u32;
    var local_53: u32;
    var local_54: u32;
    var local_55: bool;
    var local_56: u32;
    var local_57: bool;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: u32;
    var local_62: bool;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: u32;
    var local_67: bool;
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
    var local_80: u32;
    var local_81: u32;
    var local_82: bool;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: u32;
    var local_91: u32;
    var local_92: u32;
    var local_93: u32;
    var local_94: u32;
    var local_95: u32;
    var local_96: u32;
    var local_97: u32;
    var local_98: array<f32, 3>;
    var local_99: u32;
    var local_100: f32;
    var local_101: f32;
    var local_102: u32;
    var local_103: array<u32, 2>;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: bool;
    var local_111: u32;
    var local_112: u32;
    var local_113: type_29;
    var local_114: u32;
    var local_115: bool;
    var local_116: f32;
    var local_117: f32;
    var local_118: u32;
    var local_119: f32;
    var local_120: f32;
    var local_121: f32;
    var local_122: f32;
    var local_123: u32;
    var local_124: u32;
    var local_125: u32;
    var local_126: u32;
    var local_127: u32;
    var local_128: u32;
    var local_129: f32;
    var local_130: f32;
    var local_131: f32;
    var local_132: f32;
    var local_133: f32;
    var local_134: bool;
    var local_135: f32;
    var local_136: f32;
    var local_137: bool;
    var local_138: f32;
    var local_139: f32;
    var local_140: bool;
    var local_141: f32;
    var local_142: f32;
    var local_143: f32;
    var local_144: f32;
    var local_145: f32;
    var local_146: f32;
    var local_147: bool;
    var local_148: f32;
    var local_149: f32;
    var local_150: f32;
    var local_151: f32;
    var local_152: bool;
    var local_153: u32;
    var local_154: f32;
    var local_155: f32;
    var local_156: f32;
    var local_157: bool;
    var local_158: u32;
    var local_159: f32;
    var local_160: f32;
    var local_161: u32;
    var local_162: f32;
    var local_163: u32;
    var local_164: f32;
    var local_165: u32;
    var local_166: f32;
    var local_167: array<f32, 2>;
    var local_168: bool;
    var local_169: u32;
    var local_170: f32;
    var local_171: bool;
    var local_172: f32;
    var local_173: u32;
    var local_174: bool;
    var local_175: u32;
    var local_176: u32;
    var local_177: u32;
    var local_178: u32;
    var local_179: u32;
    var local_180: u32;
    var local_181: u32;
    var local_182: u32;
    var local_183: u32;
    var local_184: u32;
    var local_185: u32;
    var local_186: u32;
    var local_187: u32;
    var local_188: u32;
    var local_189: u32;
    var local_190: u32;
    var local_191: u32;
    var local_192: bool;
    var local_193: u32;
    var local_194: u32;
    var local_195: u32;
    var local_196: bool;
    var local_197: f32;
    var local_198: f32;
    var local_199: u32;
    var local_200: f32;
    var local_201: f32;
    var local_202: u32;
    var local_203: f32;
    var local_204: u32;
    var local_205: f32;
    var local_206: u32;
    var local_207: f32;
    var local_208: u32;
    var local_209: f32;
    var local_210: u32;
    var local_211: bool;
    var local_212: bool;
    var local_213: u32;
    var local_214: bool;
    var local_215: bool;
    var local_216: u32;
    var local_217: bool;
    var local_218: u32;
    var local_219: f32;
    var local_220: u32;
    var local_221: u32;
    var local_222: bool;
    var local_223: u32;
    var local_224: u32;
    var local_225: bool;
    var local_226: u32;
    var local_227: u32;
    var local_228: f32;
    var local_229: type_31;
    var local_230: u32;
    var local_231: u32;
    var local_232: f32;
    var local_233: f32;
    var local_234: bool;
    var local_235: array<f32, 3>;
    var local_236: bool;
    var local_237: u32;
    var local_238: f32;
    var local_239: u32;
    var local_240: f32;
    var local_241: u32;
    var local_242: f32;
    var local_243: f32;
    var local_244: f32;
    var local_245: f32;
    var local_246: bool;
    var local_247: u32;
    var local_248: u32;
    var local_249: u32;
    var local_250: f32;
    var local_251: f32;
    var local_252: bool;
    var local_253: f32;
    var local_254: f32;
    var local_255: bool;
    var local_256: u32;
    var local_257: u32;
    var local_258: f32;
    var local_259: u32;
    var local_260: f32;
    var local_261: bool;
    var local_262: f32;
    var local_263: f32;
    var local_264: f32;
    var local_265: f32;
    var local_266: f32;
    var local_267: f32;
    var local_268: f32;
    var local_269: bool;
    var local_270: f32;
    var local_271: bool;
    var local_272: bool;
    var local_273: bool;
    var local_274: u32;
    var local_275: f32;
    var local_276: f32;
    var local_277: f32;
    var local_278: f32;
    var local_279: f32;
    var local_280: f32;
    var local_281: f32;
    var local_282: bool;
    var local_283: f32;
    var local_284: f32;
    var local_285: f32;
    var local_286: f32;
    var local_287: bool;
    var local_288: u32;
    var local_289: f32;
    var local_290: f32;
    var local_291: f32;
    var local_292: bool;
    var local_293: u32;
    var local_294: f32;
    var local_295: f32;
    var local_296: u32;
    var local_297: f32;
    var local_298: u32;
    var local_299: f32;
    var local_300: u32;
    var local_301: f32;
    var local_302: array<f32, 2>;
    var local_303: bool;
    var local_304: f32;
    var local_305: u32;
    var local_306: f32;
    var local_307: u32;
    var local_308: f32;
    var local_309: u32;
    var local_310: f32;
    var local_311: f32;
    var local_312: f32;
    var local_313: f32;
    var local_314: bool;
    var local_315: bool;
    var local_316: bool;
    var local_317: bool;
    var local_318: f32;
    var local_319: f32;
    var local_320: bool;
    var local_321: f32;
    var local_322: f32;
    var local_323: bool;
    var local_324: f32;
    var local_325: bool;
    var local_326: f32;
    var local_327: f32;
    var local_328: bool;
    var local_329: f32;
    var local_330: f32;
    var local_331: f32;
    var local_332: u32;
    var local_333: f32;
    var local_334: u32;
    var local_335: f32;
    var local_336: u32;
    var local_337: bool;
    var local_338: f32;
    var local_339: u32;
    var local_340: bool;
    var local_341: u32;
    var local_342: u32;
    var local_343: f32;
    var local_344: u32;
    var local_345: bool;
    var local_346: u32;
    var local_347: u32;
    var local_348: f32;
    var local_349: u32;
    var local_350: bool;
    var local_351: u32;
    var local_352: u32;
    var local_353: u32;
    var local_354: bool;
    var local_355: u32;
    var local_356: u32;
    var local_357: u32;
    var local_358: bool;
    var local_359: u32;
    var local_360: u32;
    var local_361: u32;
    var local_362: u32;
    var local_363: u32;
    var local_364: u32;
    var local_365: u32;
    var local_366: u32;
    var local_367: u32;
    var local_368: u32;
    var local_369: bool;
    var local_370: u32;
    var local_371: bool;
    var local_372: u32;
    var local_373: u32;
    var local_374: u32;
    var local_375: u32;
    var local_376: bool;
    var local_377: u32;
    var local_378: u32;
    var local_379: bool;
    var local_380: bool;
    var local_381: u32;
    var local_382: u32;
    var local_383: f32;
    var local_384: u32;
    var local_385: f32;
    var local_386: u32;
    var local_387: f32;
    var local_388: u32;
    var local_389: f32;
    var local_390: u32;
    var local_391: bool;
    var local_392: f32;
    var local_393: bool;
    var local_394: u32;
    var local_395: u32;
    var local_396: bool;
    var local_397: u32;
    var local_398: u32;
    var local_399: bool;
    var local_400: u32;
    var local_401: u32;
    var local_402: f32;
    var local_403: f32;
    var local_404: f32;
    var local_405: u32;
    var local_406: f32;
    var local_407: u32;
    var local_408: f32;
    var local_409: u32;
    var local_410: u32;
    var local_411: u32;
    var local_412: u32;
    var local_413: u32;
    var local_414: u32;
    var local_415: u32;
    var local_416: u32;
    var local_417: u32;
    var local_418: bool;
    var local_419: u32;
    var local_420: u32;
    var local_421: u32;
    var local_422: u32;
    var local_423: bool;
    var local_424: u32;
    var local_425: u32;
    var local_426: bool;
    var local_427: u32;
    var local_428: u32;
    var local_429: f32;
    var local_430: u32;
    var local_431: f32;
    var local_432: u32;
    var local_433: u32;
    var local_434: array<f32, 3>;
    var local_435: u32;
    var local_436: u32;
    var local_437: u32;
    var local_438: u32;
    var local_439: u32;
    var local_440: u32;
    var local_441: u32;
    var local_442: u32;
    var local_443: f32;
    var local_444: f32;
    var local_445: f32;
    var local_446: u32;
    var local_447: bool;
    var local_448: f32;
    var local_449: f32;
    var local_450: f32;
    var local_451: u32;
    var local_452: array<u32, 1>;
    var local_453: array<bool, 1>;
    var local_454: array<bool, 1>;
    var local_455: array<bool, 1>;
    var local_456: array<u32, 1>;
    var local_457: array<bool, 1>;
    var phi_4503_: bool;
    var phi_4505_: bool;
    var phi_4506_: bool;
    var phi_4561_: array<f32, 3>;
    var phi_361_: u32;
    var phi_364_: u32;
    var phi_396_: u32;
    var phi_362_: u32;
    var phi_365_: u32;
    var phi_4718_: bool;
    var phi_407_: u32;
    var phi_408_: u32;
    var phi_4725_: bool;
    var phi_452_: u32;
    var phi_453_: u32;
    var phi_4730_: bool;
    var phi_525_: bool;
    var phi_527_: bool;
    var phi_528_: bool;
    var phi_573_: f32;
    var phi_584_: u32;
    var phi_585_: u32;
    var phi_4733_: bool;
    var phi_4765_: bool;
    var phi_635_: u32;
    var phi_638_: u32;
    var phi_718_: array<f32, 3>;
    var phi_729_: f32;
    var phi_755_: u32;
    var phi_768_: u32;
    var phi_807_: type_29;
    var phi_821_: f32;
    var phi_850_: bool;
    var phi_878_: f32;
    var phi_879_: f32;
    var phi_885_: f32;
    var phi_887_: f32;
    var phi_4755_: bool;
    var phi_1002_: f32;
    var phi_1005_: f32;
    var phi_1016_: f32;
    var phi_1019_: f32;
    var phi_1043_: bool;
    var phi_1079_: bool;
    var phi_1415_: u32;
    var phi_1418_: f32;
    var phi_1420_: array<f32, 2>;
    var phi_1416_: u32;
    var phi_1419_: f32;
    var phi_1421_: array<f32, 2>;
    var phi_1473_: f32;
    var phi_1195_: f32;
    var phi_1196_: f32;
    var phi_1197_: bool;
    var phi_1198_: f32;
    var phi_1199_: bool;
    var phi_1200_: f32;
    var phi_1201_: bool;
    var phi_1251_: f32;
    var phi_1252_: f32;
    var phi_1253_: bool;
    var phi_1254_: f32;
    var phi_1255_: bool;
    var phi_1256_: f32;
    var phi_1257_: bool;
    var phi_1307_: f32;
    var phi_1308_: f32;
    var phi_1309_: bool;
    var phi_1310_: f32;
    var phi_1311_: bool;
    var phi_1312_: f32;
    var phi_1313_: bool;
    var phi_1364_: f32;
    var phi_1365_: f32;
    var phi_1366_: bool;
    var phi_1367_: f32;
    var phi_1368_: bool;
    var phi_1369_: f32;
    var phi_1370_: bool;
    var phi_1381_: f32;
    var phi_1383_: f32;
    var phi_1384_: bool;
    var phi_1385_: f32;
    var phi_1386_: bool;
    var phi_1387_: f32;
    var phi_1388_: bool;
    var phi_1393_: f32;
    var phi_1486_: f32;
    var phi_1487_: f32;
    var phi_1488_: f32;
    var phi_1494_: u32;
    var phi_1497_: f32;
    var phi_1495_: u32;
    var phi_1498_: f32;
    var phi_1017_: f32;
    var phi_1020_: f32;
    var phi_4744_: bool;
    var phi_4812_: bool;
    var phi_1003_: f32;
    var phi_1006_: f32;
    var phi_4811_: bool;
    var phi_987_: f32;
    var phi_4829_: bool;
    var phi_1510_: f32;
    var phi_4828_: bool;
    var phi_1512_: f32;
    var phi_1514_: u32;
    var phi_1515_: u32;
    var phi_1536_: bool;
    var phi_4824_: bool;
    var phi_1641_: u32;
    var phi_1707_: bool;
    var phi_1709_: bool;
    var phi_1710_: bool;
    var phi_1642_: u32;
    var phi_4813_: bool;
    var phi_1941_: u32;
    var phi_1962_: bool;
    var phi_1942_: u32;
    var phi_4831_: bool;
    var phi_4843_: bool;
    var phi_1975_: u32;
    var phi_2005_: u32;
    var phi_2008_: u32;
    var phi_2032_: u32;
    var phi_2006_: u32;
    var phi_2009_: u32;
    var phi_4839_: bool;
    var phi_4846_: bool;
    var phi_2034_: u32;
    var phi_4845_: bool;
    var phi_1976_: u32;
    var phi_4844_: bool;
    var phi_4852_: bool;
    var phi_2065_: f32;
    var phi_2068_: type_31;
    var phi_2070_: u32;
    var phi_2072_: u32;
    var phi_2074_: f32;
    var phi_2076_: f32;
    var phi_2078_: bool;
    var phi_2080_: array<f32, 3>;
    var phi_3044_: bool;
    var phi_3090_: bool;
    var phi_3426_: u32;
    var phi_3429_: f32;
    var phi_3431_: array<f32, 2>;
    var phi_3427_: u32;
    var phi_3430_: f32;
    var phi_3432_: array<f32, 2>;
    var phi_3484_: f32;
    var phi_3206_: f32;
    var phi_3207_: f32;
    var phi_3208_: bool;
    var phi_3209_: f32;
    var phi_3210_: bool;
    var phi_3211_: f32;
    var phi_3212_: bool;
    var phi_3262_: f32;
    var phi_3263_: f32;
    var phi_3264_: bool;
    var phi_3265_: f32;
    var phi_3266_: bool;
    var phi_3267_: f32;
    var phi_3268_: bool;
    var phi_3318_: f32;
    var phi_3319_: f32;
    var phi_3320_: bool;
    var phi_3321_: f32;
    var phi_3322_: bool;
    var phi_3323_: f32;
    var phi_3324_: bool;
    var phi_3375_: f32;
    var phi_3376_: f32;
    var phi_3377_: bool;
    var phi_3378_: f32;
    var phi_3379_: bool;
    var phi_3380_: f32;
    var phi_3381_: bool;
    var phi_3392_: f32;
    var phi_3394_: f32;
    var phi_3395_: bool;
    var phi_3396_: f32;
    var phi_3397_: bool;
    var phi_3398_: f32;
    var phi_3399_: bool;
    var phi_3404_: f32;
    var phi_3497_: f32;
    var phi_3498_: f32;
    var phi_3499_: f32;
    var phi_2168_: u32;
    var phi_2171_: f32;
    var phi_2173_: u32;
    var phi_2984_: f32;
    var phi_2989_: f32;
    var phi_3008_: f32;
    var phi_3011_: f32;
    var phi_3012_: u32;
    var phi_3014_: u32;
    var phi_3015_: f32;
    var phi_3016_: u32;
    var phi_2169_: u32;
    var phi_2172_: f32;
    var phi_2174_: u32;
    var phi_3017_: bool;
    var phi_4847_: bool;
    var phi_3028_: f32;
    var phi_4975_: bool;
    var phi_3033_: f32;
    var phi_4974_: bool;
    var phi_3500_: f32;
    var phi_3651_: f32;
    var phi_3598_: f32;
    var phi_3581_: f32;
    var phi_3609_: type_18;
    var phi_3661_: type_31;
    var phi_3662_: type_18;
    var phi_3747_: u32;
    var phi_3748_: f32;
    var phi_3749_: f32;
    var phi_3750_: bool;
    var phi_4955_: bool;
    var phi_3751_: f32;
    var phi_3752_: type_31;
    var phi_3753_: u32;
    var phi_3754_: f32;
    var phi_3755_: f32;
    var phi_3756_: bool;
    var phi_3757_: array<f32, 3>;
    var phi_4954_: bool;
    var phi_2066_: f32;
    var phi_2069_: type_31;
    var phi_2071_: u32;
    var phi_2073_: u32;
    var phi_2075_: f32;
    var phi_2077_: f32;
    var phi_2079_: bool;
    var phi_2081_: array<f32, 3>;
    var phi_4953_: bool;
    var phi_3761_: u32;
    var phi_3762_: u32;
    var phi_5027_: bool;
    var phi_3782_: u32;
    var phi_3783_: u32;
    var phi_5030_: bool;
    var phi_3803_: u32;
    var phi_3804_: u32;
    var phi_5033_: bool;
    var phi_3823_: u32;
    var phi_3824_: u32;
    var phi_5036_: bool;
    var phi_3844_: u32;
    var phi_3845_: u32;
    var phi_5039_: bool;
    var phi_3900_: u32;
    var phi_3949_: u32;
    var phi_3958_: bool;
    var phi_3959_: u32;
    var phi_3960_: bool;
    var phi_3961_: u32;
    var phi_3901_: u32;
    var phi_5042_: bool;
    var phi_3994_: u32;
    var phi_3995_: u32;
    var phi_5049_: bool;
    var phi_5057_: bool;
    var phi_4039_: u32;
    var phi_4040_: u32;
    var phi_5056_: bool;
    var phi_636_: u32;
    var phi_639_: u32;
    var phi_4042_: bool;
    var phi_5055_: bool;
    var phi_4103_: bool;
    var phi_4105_: bool;
    var phi_4106_: bool;
    var phi_4263_: f32;
    var phi_4328_: u32;
    var phi_4331_: u32;
    var phi_4333_: u32;
    var phi_4406_: bool;
    var phi_4408_: bool;
    var phi_4409_: bool;
    var phi_4424_: u32;
    var phi_4425_: u32;
    var phi_4426_: u32;
    var phi_4427_: u32;
    var phi_4329_: u32;
    var phi_4332_: u32;
    var phi_4334_: u32;
    var phi_5058_: bool;
    var local_458: f32;
    var local_459: f32;
    var local_460: f32;
    var local_461: u32;

    let _e560 = global_12;
    let _e561 = bitcast<f32>(_e560);
    switch bitcast<i32>(0u) {
        default: {
            let _e563 = global;
            local = _e563;
            let _e564 = global_1;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_2.member));
            let _e579 = arrayLength((&global_9.member));
            local_7 = _e579;
            local_8 = arrayLength((&global_10.member));
            local_9 = _e564.x;
            local_10 = _e564.y;
            let _e584 = global_3.member;
            local_11 = _e584;
            if (18u < _e579) {
            } else {
                break;
            }
            let _e586 = local_7;
            if (19u < _e586) {
            } else {
                break;
            }
            let _e590 = atomicLoad((&global_9.member[19u]));
            local_12 = bitcast<f32>(_e590);
            let _e592 = local_11;
            local_13 = _e592.member;
            let _e594 = local_11;
            local_14 = _e594.member_1;
            let _e596 = local_11;
            local_15 = _e596.member_2;
            let _e598 = local_11;
            local_16 = _e598.member_3;
            let _e600 = local_11;
            local_17 = _e600.member_6;
            let _e602 = local_11;
            local_18 = _e602.member_7;
            let _e604 = local_11;
            local_19 = _e604.member_8;
            let _e606 = local_11;
            local_20 = _e606.member_10;
            let _e608 = local_11;
            local_21 = _e608.member_15.member;
            local_22 = _e608.member_15.member_1;
            local_23 = _e608.member_15.member_2;
            local_24 = _e608.member_15.member_3;
            let _e614 = local_11;
            local_25 = _e614.member_16.member;
            local_26 = _e614.member_16.member_1;
            local_27 = _e614.member_16.member_2;
            local_28 = _e614.member_16.member_3[0];
            local_29 = _e614.member_16.member_3[1];
            local_30 = _e614.member_16.member_4;
            local_31 = _e614.member_16.member_5;
            local_32 = _e614.member_16.member_6;
            let _e626 = select(16u, 12u, (_e600.member_6 == 24u));
            local_441 = _e626;
            let _e627 = (_e626 == 0u);
            local_33 = _e627;
            if _e627 {
                break;
            }
            let _e628 = local_17;
            let _e629 = local_441;
            let _e630 = (_e628 / _e629);
            local_34 = _e630;
            let _e631 = (_e630 == 0u);
            local_35 = _e631;
            if _e631 {
                break;
            }
            let _e632 = local_9;
            let _e633 = local_34;
            local_36 = (_e632 / _e633);
            let _e635 = local_35;
            if _e635 {
                break;
            }
            let _e636 = local_10;
            let _e637 = local_34;
            let _e638 = (_e636 / _e637);
            local_37 = _e638;
            let _e639 = local_18;
            let _e641 = local_36;
            local_38 = ((_e638 * _e639) + _e641);
            let _e643 = local_36;
            let _e644 = local_17;
            local_39 = (_e643 * _e644);
            let _e646 = local_35;
            if _e646 {
                break;
            }
            let _e647 = local_9;
            let _e648 = local_34;
            let _e650 = local_441;
            let _e652 = local_39;
            local_40 = (_e652 + ((_e647 % _e648) * _e650));
            let _e654 = local_37;
            let _e655 = local_17;
            local_41 = (_e654 * _e655);
            let _e657 = local_35;
            if _e657 {
                break;
            }
            let _e658 = local_10;
            let _e659 = local_34;
            let _e661 = local_441;
            let _e663 = local_41;
            local_42 = (_e663 + ((_e658 % _e659) * _e661));
            let _e665 = local_38;
            let _e666 = local_5;
            if (_e665 < _e666) {
            } else {
                break;
            }
            let _e668 = local_38;
            let _e671 = global_8.member[_e668];
            local_43 = _e671;
            if ((_e671 & 1u) == 0u) {
                let _e786 = local_43;
                local_44 = (_e786 >> bitcast<u32>(1u));
                let _e789 = local_38;
                let _e790 = (2u * _e789);
                local_45 = _e790;
                let _e791 = local_4;
                if (_e790 < _e791) {
                } else {
                    break;
                }
                let _e793 = local_45;
                let _e796 = global_7.member[_e793];
                local_46 = _e796;
                let _e797 = local_45;
                let _e798 = (_e797 + 1u);
                local_47 = _e798;
                let _e799 = local_4;
                if (_e798 < _e799) {
                } else {
                    break;
                }
                let _e801 = local_47;
                let _e804 = global_7.member[_e801];
                local_48 = _e804;
                phi_361_ = _e563;
                phi_364_ = 0u;
                loop {
                    let _e806 = phi_361_;
                    let _e808 = phi_364_;
                    local_49 = _e806;
                    local_50 = _e808;
                    let _e809 = local_49;
                    let _e810 = local_48;
                    let _e811 = (_e809 < _e810);
                    local_51 = _e811;
                    if _e811 {
                        let _e812 = local_46;
                        let _e813 = local_49;
                        let _e814 = (_e812 + _e813);
                        local_52 = _e814;
                        let _e815 = local_3;
                        if (_e814 < _e815) {
                        } else {
                            phi_4718_ = true;
                            break;
                        }
                        let _e817 = local_52;
                        let _e820 = global_6.member[_e817];
                        let _e822 = ((4u * _e820) + 1u);
                        local_53 = _e822;
                        let _e823 = local_2;
                        if (_e822 < _e823) {
                        } else {
                            phi_4718_ = true;
                            break;
                        }
                        let _e825 = local_53;
                        let _e828 = global_5.member[_e825];
                        if (((_e828 >> bitcast<u32>(14u)) & 1023u) == 1023u) {
                            phi_396_ = _e808;
                        } else {
                            let _e833 = local_49;
                            phi_396_ = (_e833 + 1u);
                        }
                        let _e836 = phi_396_;
                        let _e837 = local_49;
                        phi_362_ = (_e837 + 256u);
                        phi_365_ = _e836;
                    } else {
                        phi_362_ = u32();
                        phi_365_ = u32();
                    }
                    let _e840 = phi_362_;
                    let _e842 = phi_365_;
                    continue;
                    continuing {
                        let _e843 = local_51;
                        phi_361_ = _e840;
                        phi_364_ = _e842;
                        phi_4718_ = false;
                        break if !(_e843);
                    }
                }
                let _e846 = phi_4718_;
                if _e846 {
                    break;
                }
                let _e847 = local;
                let _e848 = (4352u + _e847);
                local_54 = _e848;
                let _e849 = (_e848 < 5888u);
                local_55 = _e849;
                if _e849 {
                } else {
                    break;
                }
                let _e850 = local_54;
                let _e852 = local_50;
                global_11[_e850] = _e852;
                storageBarrier();
                workgroupBarrier();
                phi_407_ = 128u;
                loop {
                    let _e854 = phi_407_;
                    local_56 = _e854;
                    let _e855 = local_56;
                    let _e856 = (_e855 > 0u);
                    local_57 = _e856;
                    if _e856 {
                        let _e857 = local;
                        let _e858 = local_56;
                        if (_e857 < _e858) {
                            let _e860 = local_55;
                            if _e860 {
                            } else {
                                phi_4725_ = true;
                                break;
                            }
                            let _e861 = global_11[_e850];
                            local_58 = _e861;
                            let _e862 = local_54;
                            let _e863 = local_56;
                            let _e864 = (_e862 + _e863);
                            local_59 = _e864;
                            if (_e864 < 5888u) {
                            } else {
                                phi_4725_ = true;
                                break;
                            }
                            let _e866 = local_59;
                            let _e868 = global_11[_e866];
                            let _e869 = local_58;
                            let _e871 = local_58;
                            local_442 = select(_e868, _e871, (_e869 > _e868));
                            let _e873 = local_55;
                            if _e873 {
                            } else {
                                phi_4725_ = true;
                                break;
                            }
                            let _e874 = local_442;
                            global_11[_e850] = _e874;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e875 = local_56;
                        phi_408_ = (_e875 / 2u);
                    } else {
                        phi_408_ = u32();
                    }
                    let _e878 = phi_408_;
                    continue;
                    continuing {
                        let _e879 = local_57;
                        phi_407_ = _e878;
                        phi_4725_ = _e846;
                        break if !(_e879);
                    }
                }
                let _e882 = phi_4725_;
                if _e882 {
                    break;
                }
                let _e884 = global_11[4352u];
                local_60 = _e884;
                storageBarrier();
                workgroupBarrier();
                phi_452_ = 0u;
                loop {
                    let _e886 = phi_452_;
                    local_61 = _e886;
                    let _e887 = local_61;
                    let _e888 = (_e887 <= 1280u);
                    local_62 = _e888;
                    if _e888 {
                        let _e889 = local_61;
                        let _e890 = local;
                        let _e891 = (_e889 + _e890);
                        local_63 = _e891;
                        if (_e891 < 5888u) {
                        } else {
                            phi_4730_ = true;
                            break;
                        }
                        let _e893 = local_63;
                        global_11[_e893] = 0u;
                        let _e895 = local_61;
                        phi_453_ = (_e895 + 256u);
                    } else {
                        phi_453_ = u32();
                    }
                    let _e898 = phi_453_;
                    continue;
                    continuing {
                        let _e899 = local_62;
                        phi_452_ = _e898;
                        phi_4730_ = _e882;
                        break if !(_e899);
                    }
                }
                let _e902 = phi_4730_;
                if _e902 {
                    break;
                }
                let _e903 = local_33;
                if _e903 {
                    break;
                }
                let _e904 = local;
                let _e905 = local_441;
                let _e907 = local_40;
                local_64 = (_e907 + (_e904 % _e905));
                let _e909 = local_33;
                if _e909 {
                    break;
                }
                let _e910 = local;
                let _e911 = local_441;
                let _e913 = local_42;
                local_65 = (_e913 + (_e910 / _e911));
                let _e915 = local_441;
                let _e916 = local_441;
                let _e917 = (_e915 * _e916);
                local_66 = _e917;
                let _e918 = local;
                let _e919 = (_e918 < _e917);
                local_67 = _e919;
                if _e919 {
                    let _e920 = local_64;
                    let _e921 = local_13;
                    let _e922 = (_e920 < _e921);
                    local_68 = _e922;
                    if _e922 {
                        let _e923 = local_65;
                        let _e924 = local_14;
                        phi_525_ = (_e923 < _e924);
                    } else {
                        phi_525_ = bool();
                    }
                    let _e927 = phi_525_;
                    let _e928 = local_68;
                    phi_527_ = _e927;
                    phi_528_ = select(true, false, _e928);
                } else {
                    phi_527_ = bool();
                    phi_528_ = true;
                }
                let _e931 = phi_527_;
                let _e933 = phi_528_;
                if select(_e931, false, _e933) {
                    let _e935 = local_65;
                    let _e936 = local_13;
                    let _e938 = local_64;
                    let _e940 = (4u * ((_e935 * _e936) + _e938));
                    local_69 = _e940;
                    let _e941 = local_1;
                    if (_e940 < _e941) {
                    } else {
                        break;
                    }
                    let _e943 = local_69;
                    let _e945 = local_1;
                    if ((_e943 + 1u) < _e945) {
                    } else {
                        break;
                    }
                    let _e947 = local_69;
                    let _e949 = local_1;
                    if ((_e947 + 2u) < _e949) {
                    } else {
                        break;
                    }
                    let _e951 = local_69;
                    let _e952 = (_e951 + 3u);
                    local_70 = _e952;
                    let _e953 = local_1;
                    if (_e952 < _e953) {
                    } else {
                        break;
                    }
                    let _e955 = local_70;
                    let _e958 = global_4.member[_e955];
                    phi_573_ = bitcast<f32>(_e958);
                } else {
                    phi_573_ = _e561;
                }
                let _e961 = phi_573_;
                local_71 = bitcast<u32>(_e961);
                let _e963 = local;
                let _e964 = (1024u + _e963);
                local_72 = _e964;
                if (_e964 < 5888u) {
                } else {
                    break;
                }
                let _e966 = local_72;
                let _e968 = local_71;
                global_11[_e966] = _e968;
                let _e969 = local;
                local_73 = (4608u + _e969);
                phi_584_ = 0u;
                loop {
                    let _e972 = phi_584_;
                    local_74 = _e972;
                    let _e973 = local_74;
                    let _e974 = (_e973 < 1u);
                    local_75 = _e974;
                    if _e974 {
                        let _e975 = local_73;
                        let _e976 = local_74;
                        let _e977 = (_e975 + _e976);
                        local_76 = _e977;
                        if (_e977 < 5888u) {
                        } else {
                            phi_4733_ = true;
                            break;
                        }
                        let _e979 = local_76;
                        global_11[_e979] = 2143289344u;
                        let _e981 = local;
                        let _e983 = local_74;
                        let _e984 = ((_e981 + 4864u) + _e983);
                        local_77 = _e984;
                        if (_e984 < 5888u) {
                        } else {
                            phi_4733_ = true;
                            break;
                        }
                        let _e986 = local_77;
                        global_11[_e986] = 0u;
                        let _e988 = local;
                        let _e990 = local_74;
                        let _e991 = ((_e988 + 5120u) + _e990);
                        local_78 = _e991;
                        if (_e991 < 5888u) {
                        } else {
                            phi_4733_ = true;
                            break;
                        }
                        let _e993 = local_78;
                        global_11[_e993] = 1065353216u;
                        let _e995 = local;
                        let _e997 = local_74;
                        let _e998 = ((_e995 + 5376u) + _e997);
                        local_79 = _e998;
                        if (_e998 < 5888u) {
                        } else {
                            phi_4733_ = true;
                            break;
                        }
                        let _e1000 = local_79;
                        global_11[_e1000] = 1u;
                        let _e1002 = local_74;
                        phi_585_ = (_e1002 + 1u);
                    } else {
                        phi_585_ = u32();
                    }
                    let _e1005 = phi_585_;
                    continue;
                    continuing {
                        let _e1006 = local_75;
                        phi_584_ = _e1005;
                        phi_4733_ = _e902;
                        break if !(_e1006);
                    }
                }
                let _e1009 = phi_4733_;
                if _e1009 {
                    break;
                }
                storageBarrier();
                workgroupBarrier();
                phi_4765_ = _e1009;
                phi_635_ = 0u;
                phi_638_ = 1u;
                loop {
                    let _e1011 = phi_4765_;
                    let _e1013 = phi_635_;
                    let _e1015 = phi_638_;
                    local_80 = _e1013;
                    local_81 = _e1015;
                    let _e1016 = local_80;
                    let _e1017 = local_48;
                    if (_e1016 < _e1017) {
                        let _e1019 = local_81;
                        let _e1020 = (_e1019 == 0u);
                        local_82 = _e1020;
                        if _e1020 {
                            phi_5057_ = _e1011;
                            phi_4039_ = u32();
                            phi_4040_ = u32();
                        } else {
                            let _e1021 = local_80;
                            let _e1022 = local;
                            let _e1023 = (_e1021 + _e1022);
                            local_83 = _e1023;
                            let _e1024 = local_48;
                            if (_e1023 < _e1024) {
                                let _e1026 = local_46;
                                let _e1027 = local_83;
                                let _e1028 = (_e1026 + _e1027);
                                local_84 = _e1028;
                                let _e1029 = local_3;
                                if (_e1028 < _e1029) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1031 = local_84;
                                let _e1034 = global_6.member[_e1031];
                                local_85 = _e1034;
                                let _e1035 = (4u * _e1034);
                                local_86 = _e1035;
                                let _e1036 = local_2;
                                if (_e1035 < _e1036) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1038 = local_86;
                                let _e1041 = global_5.member[_e1038];
                                local_87 = _e1041;
                                let _e1042 = local_86;
                                let _e1043 = (_e1042 + 1u);
                                local_88 = _e1043;
                                let _e1044 = local_2;
                                if (_e1043 < _e1044) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1046 = local_88;
                                let _e1049 = global_5.member[_e1046];
                                local_89 = _e1049;
                                let _e1050 = local_86;
                                let _e1051 = (_e1050 + 2u);
                                local_90 = _e1051;
                                let _e1052 = local_2;
                                if (_e1051 < _e1052) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1054 = local_90;
                                let _e1057 = global_5.member[_e1054];
                                local_91 = _e1057;
                                let _e1058 = local_86;
                                let _e1059 = (_e1058 + 3u);
                                local_92 = _e1059;
                                let _e1060 = local_2;
                                if (_e1059 < _e1060) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1062 = local_92;
                                let _e1065 = global_5.member[_e1062];
                                local_93 = _e1065;
                                let _e1066 = local_87;
                                local_94 = (_e1066 & 16383u);
                                let _e1068 = local_87;
                                local_95 = ((_e1068 >> bitcast<u32>(14u)) & 16383u);
                                let _e1072 = local_89;
                                local_96 = (_e1072 & 16383u);
                                let _e1074 = local_89;
                                let _e1076 = (_e1074 >> bitcast<u32>(24i));
                                local_97 = _e1076;
                                if (_e1076 == 0u) {
                                    phi_718_ = array<f32, 3>(0f, 0f, 0f);
                                } else {
                                    let _e1078 = local_97;
                                    let _e1084 = bitcast<f32>((bitcast<u32>((bitcast<i32>(_e1078) + -13i)) << bitcast<u32>(23i)));
                                    let _e1085 = local_94;
                                    let _e1088 = local_95;
                                    let _e1091 = local_96;
                                    phi_718_ = array<f32, 3>((f32(_e1085) * _e1084), (f32(_e1088) * _e1084), (f32(_e1091) * _e1084));
                                }
                                let _e1096 = phi_718_;
                                local_98 = _e1096;
                                let _e1097 = local_89;
                                let _e1100 = ((_e1097 >> bitcast<u32>(14u)) & 1023u);
                                local_99 = _e1100;
                                if (_e1100 >= 1023u) {
                                    phi_729_ = 1f;
                                } else {
                                    let _e1102 = local_99;
                                    phi_729_ = (f32(_e1102) * 0.0009775171f);
                                }
                                let _e1106 = phi_729_;
                                local_100 = _e1106;
                                let _e1107 = local_91;
                                let _e1108 = bitcast<f32>(_e1107);
                                local_101 = _e1108;
                                let _e1109 = local_87;
                                let _e1112 = ((_e1109 >> bitcast<u32>(28i)) & 3u);
                                local_102 = _e1112;
                                let _e1113 = local_93;
                                let _e1115 = local_93;
                                let _e1118 = array<u32, 2>((_e1113 & 65535u), (_e1115 >> bitcast<u32>(16i)));
                                local_103 = _e1118;
                                let _e1119 = local_98;
                                let _e1121 = local_20;
                                let _e1124 = ((_e1121 >> bitcast<u32>(8u)) & 7u);
                                local_104 = _e1124;
                                if (_e1124 == 0u) {
                                    phi_807_ = type_29(_e1118, _e1119, _e1106, _e1108, _e1112, 0u);
                                } else {
                                    let _e1126 = local_104;
                                    let _e1127 = local_104;
                                    let _e1128 = (_e1126 * _e1127);
                                    local_105 = _e1128;
                                    if (_e1128 <= 1u) {
                                        phi_755_ = 1u;
                                    } else {
                                        let _e1130 = local_105;
                                        phi_755_ = select(16u, 4u, (_e1130 <= 4u));
                                    }
                                    let _e1134 = phi_755_;
                                    local_106 = _e1134;
                                    if (_e1134 == 0u) {
                                        phi_5055_ = true;
                                        break;
                                    }
                                    let _e1136 = local_106;
                                    local_107 = (32u / _e1136);
                                    let _e1138 = local_106;
                                    if (_e1138 >= 32u) {
                                        phi_768_ = 4294967295u;
                                    } else {
                                        let _e1140 = local_106;
                                        phi_768_ = ((1u << bitcast<u32>((_e1140 & 31u))) - 1u);
                                    }
                                    let _e1146 = phi_768_;
                                    local_108 = _e1146;
                                    let _e1147 = local_18;
                                    let _e1148 = local_19;
                                    let _e1150 = local_17;
                                    let _e1152 = local_17;
                                    let _e1154 = local_15;
                                    local_109 = (4u * ((((_e1147 * _e1148) * _e1150) * _e1152) * _e1154));
                                    let _e1157 = local_107;
                                    let _e1158 = (_e1157 == 0u);
                                    local_110 = _e1158;
                                    if _e1158 {
                                        phi_5055_ = true;
                                        break;
                                    }
                                    let _e1159 = local_85;
                                    let _e1160 = local_107;
                                    let _e1162 = local_109;
                                    local_111 = (_e1162 + (_e1159 / _e1160));
                                    let _e1164 = local_110;
                                    if _e1164 {
                                        phi_5055_ = true;
                                        break;
                                    }
                                    let _e1165 = local_85;
                                    let _e1166 = local_107;
                                    let _e1168 = local_106;
                                    local_112 = ((_e1165 % _e1166) * _e1168);
                                    let _e1170 = local_111;
                                    let _e1171 = local_2;
                                    if (_e1170 < _e1171) {
                                    } else {
                                        phi_5055_ = true;
                                        break;
                                    }
                                    let _e1173 = local_111;
                                    let _e1176 = global_5.member[_e1173];
                                    let _e1177 = local_112;
                                    let _e1181 = local_108;
                                    let _e1183 = local_103;
                                    let _e1184 = local_98;
                                    let _e1185 = local_100;
                                    let _e1186 = local_101;
                                    let _e1187 = local_102;
                                    phi_807_ = type_29(_e1183, _e1184, _e1185, _e1186, _e1187, ((_e1176 >> bitcast<u32>((_e1177 & 31u))) & _e1181));
                                }
                                let _e1190 = phi_807_;
                                local_113 = _e1190;
                                local_114 = _e1190.member_5;
                                let _e1192 = (_e1190.member_5 != 0u);
                                local_115 = _e1192;
                                if _e1192 {
                                    phi_821_ = 1.4142135f;
                                } else {
                                    let _e1193 = local_113;
                                    phi_821_ = (0.5f * f32((1u << bitcast<u32>((_e1193.member_4 & 31u)))));
                                }
                                let _e1201 = phi_821_;
                                local_116 = _e1201;
                                let _e1202 = local_113;
                                local_117 = _e1202.member_3;
                                let _e1204 = bitcast<u32>(_e1202.member_3);
                                local_118 = _e1204;
                                if (_e1204 == 2139095040u) {
                                    let _e1239 = local_22;
                                    let _e1241 = local_21;
                                    let _e1243 = local_23;
                                    let _e1244 = local_21;
                                    let _e1247 = local_24;
                                    phi_887_ = (0.5f * ((((2f * _e1239) * _e1241) / (_e1243 - _e1244)) * _e1247));
                                } else {
                                    let _e1206 = local_118;
                                    if (_e1206 == 0u) {
                                        phi_850_ = false;
                                    } else {
                                        let _e1208 = local_118;
                                        phi_850_ = (_e1208 <= 2139095040u);
                                    }
                                    let _e1211 = phi_850_;
                                    if _e1211 {
                                        let _e1212 = local_22;
                                        let _e1214 = local_21;
                                        let _e1216 = local_23;
                                        let _e1217 = local_21;
                                        let _e1220 = local_24;
                                        let _e1221 = ((((2f * _e1212) * _e1214) / (_e1216 - _e1217)) * _e1220);
                                        local_119 = _e1221;
                                        if (_e1221 == 0f) {
                                            phi_878_ = 0f;
                                        } else {
                                            let _e1223 = local_23;
                                            let _e1224 = local_117;
                                            let _e1227 = local_119;
                                            phi_878_ = (_e1227 * (1f - (_e1223 / _e1224)));
                                        }
                                        let _e1230 = phi_878_;
                                        phi_879_ = _e1230;
                                    } else {
                                        phi_879_ = _e561;
                                    }
                                    let _e1232 = phi_879_;
                                    local_120 = _e1232;
                                    if (_e1232 < 0f) {
                                        let _e1234 = local_120;
                                        phi_885_ = -(_e1234);
                                    } else {
                                        phi_885_ = _e1232;
                                    }
                                    let _e1237 = phi_885_;
                                    phi_887_ = (0.5f * _e1237);
                                }
                                let _e1251 = phi_887_;
                                let _e1256 = local_116;
                                let _e1257 = (select(_e1251, 0f, ((bitcast<u32>(_e1251) & 2147483647u) > 2139095040u)) + _e1256);
                                let _e1258 = local_12;
                                let _e1260 = local_12;
                                let _e1261 = select(_e1260, _e1257, (_e1257 < _e1258));
                                local_443 = select(0.5f, _e1261, (_e1261 > 0.5f));
                                let _e1264 = local_113;
                                let _e1268 = (f32(_e1264.member[0]) * 0.5f);
                                local_121 = _e1268;
                                let _e1269 = local_113;
                                local_122 = (f32(_e1269.member[1]) * 0.5f);
                                local_123 = bitcast<u32>(_e1268);
                                let _e1275 = local;
                                let _e1276 = (1536u + _e1275);
                                local_124 = _e1276;
                                if (_e1276 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1278 = local_124;
                                let _e1280 = local_123;
                                global_11[_e1278] = _e1280;
                                let _e1281 = local_122;
                                local_125 = bitcast<u32>(_e1281);
                                let _e1283 = local;
                                let _e1284 = (1792u + _e1283);
                                local_126 = _e1284;
                                if (_e1284 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1286 = local_126;
                                let _e1288 = local_125;
                                global_11[_e1286] = _e1288;
                                let _e1289 = local_443;
                                local_127 = bitcast<u32>(_e1289);
                                let _e1291 = local;
                                let _e1292 = (2048u + _e1291);
                                local_128 = _e1292;
                                if (_e1292 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1294 = local_128;
                                let _e1296 = local_127;
                                global_11[_e1294] = _e1296;
                                let _e1297 = local_117;
                                let _e1298 = local_23;
                                local_444 = select(1f, -1f, (_e1297 < _e1298));
                                let _e1301 = local_115;
                                if _e1301 {
                                    phi_4828_ = _e1011;
                                    phi_1512_ = 1f;
                                } else {
                                    let _e1302 = local_113;
                                    local_129 = f32((1u << bitcast<u32>(((2u * _e1302.member_4) & 31u))));
                                    let _e1312 = f32((1u << bitcast<u32>((_e1302.member_4 & 31u))));
                                    local_130 = _e1312;
                                    let _e1314 = local_443;
                                    if (_e1314 >= (4f + _e1312)) {
                                        let _e1841 = local_32;
                                        if (_e1841 > 0u) {
                                            let _e1855 = local_130;
                                            let _e1857 = local_443;
                                            let _e1858 = (_e1857 - (0.5f * _e1855));
                                            let _e1859 = local_31;
                                            phi_987_ = ((_e1859 * _e1858) * _e1858);
                                        } else {
                                            let _e1843 = local_443;
                                            let _e1844 = local_130;
                                            let _e1846 = local_443;
                                            let _e1848 = local_130;
                                            let _e1849 = local_130;
                                            let _e1853 = local_31;
                                            phi_987_ = (_e1853 * (((_e1843 - _e1844) * _e1846) + ((_e1848 * _e1849) * 0.33333334f)));
                                        }
                                        let _e1863 = phi_987_;
                                        phi_4829_ = _e1011;
                                        phi_1510_ = _e1863;
                                    } else {
                                        let _e1316 = local_122;
                                        let _e1317 = local_443;
                                        let _e1321 = local_122;
                                        let _e1322 = local_443;
                                        local_131 = floor(((_e1321 + _e1322) - 0.5f));
                                        let _e1326 = local_121;
                                        let _e1327 = local_443;
                                        let _e1331 = local_121;
                                        let _e1332 = local_443;
                                        local_132 = floor(((_e1331 + _e1332) - 0.5f));
                                        phi_4755_ = _e1011;
                                        phi_1002_ = ceil(((_e1316 - _e1317) - 0.5f));
                                        phi_1005_ = 0f;
                                        loop {
                                            let _e1337 = phi_4755_;
                                            let _e1339 = phi_1002_;
                                            let _e1341 = phi_1005_;
                                            local_133 = _e1339;
                                            local_460 = _e1341;
                                            let _e1342 = local_133;
                                            let _e1343 = local_131;
                                            let _e1344 = (_e1342 <= _e1343);
                                            local_134 = _e1344;
                                            if _e1344 {
                                                let _e1345 = local_133;
                                                let _e1347 = local_122;
                                                local_135 = ((_e1345 + 0.5f) - _e1347);
                                                phi_1016_ = ceil(((_e1326 - _e1327) - 0.5f));
                                                phi_1019_ = _e1341;
                                                loop {
                                                    let _e1350 = phi_1016_;
                                                    let _e1352 = phi_1019_;
                                                    local_136 = _e1350;
                                                    local_459 = _e1352;
                                                    let _e1353 = local_136;
                                                    let _e1354 = local_132;
                                                    let _e1355 = (_e1353 <= _e1354);
                                                    local_137 = _e1355;
                                                    if _e1355 {
                                                        let _e1356 = local_136;
                                                        let _e1358 = local_121;
                                                        let _e1359 = ((_e1356 + 0.5f) - _e1358);
                                                        local_138 = _e1359;
                                                        let _e1361 = local_135;
                                                        let _e1362 = local_135;
                                                        local_139 = ((_e1359 * _e1359) + (_e1361 * _e1362));
                                                        let _e1365 = local_25;
                                                        let _e1366 = (_e1365 == 0u);
                                                        local_140 = _e1366;
                                                        if _e1366 {
                                                            let _e1367 = local_32;
                                                            phi_1043_ = (_e1367 == 0u);
                                                        } else {
                                                            phi_1043_ = false;
                                                        }
                                                        let _e1370 = phi_1043_;
                                                        if _e1370 {
                                                            let _e1778 = local_443;
                                                            let _e1779 = local_130;
                                                            let _e1780 = (_e1778 - _e1779);
                                                            let _e1783 = local_139;
                                                            let _e1786 = local_139;
                                                            let _e1788 = local_443;
                                                            let _e1790 = local_130;
                                                            let _e1792 = ((_e1788 - sqrt(_e1786)) * (1f / _e1790));
                                                            phi_1488_ = select(select(0f, select(1f, _e1792, (_e1792 < 1f)), (0f < _e1792)), 1f, ((0f < _e1780) && (_e1783 <= (_e1780 * _e1780))));
                                                        } else {
                                                            let _e1371 = local_140;
                                                            if _e1371 {
                                                                let _e1372 = local_32;
                                                                phi_1079_ = (_e1372 == 0u);
                                                            } else {
                                                                phi_1079_ = false;
                                                            }
                                                            let _e1375 = phi_1079_;
                                                            if _e1375 {
                                                                let _e1756 = local_443;
                                                                let _e1757 = local_130;
                                                                let _e1758 = (_e1756 - _e1757);
                                                                let _e1761 = local_139;
                                                                let _e1764 = local_139;
                                                                let _e1766 = local_443;
                                                                let _e1768 = local_130;
                                                                let _e1770 = ((_e1766 - sqrt(_e1764)) * (1f / _e1768));
                                                                phi_1487_ = select(select(0f, select(1f, _e1770, (_e1770 < 1f)), (0f < _e1770)), 1f, ((0f < _e1758) && (_e1761 <= (_e1758 * _e1758))));
                                                            } else {
                                                                let _e1376 = local_444;
                                                                let _e1377 = local_138;
                                                                local_141 = (_e1376 * _e1377);
                                                                let _e1379 = local_444;
                                                                let _e1380 = local_135;
                                                                local_142 = (_e1379 * _e1380);
                                                                let _e1382 = local_32;
                                                                if (_e1382 > 0u) {
                                                                    let _e1465 = local_130;
                                                                    let _e1467 = local_443;
                                                                    let _e1468 = (_e1467 - (0.5f * _e1465));
                                                                    local_143 = _e1468;
                                                                    if (_e1468 > 0f) {
                                                                        let _e1470 = local_141;
                                                                        let _e1471 = local_143;
                                                                        let _e1473 = local_142;
                                                                        let _e1474 = local_143;
                                                                        let _e1476 = local_32;
                                                                        let _e1477 = f32(_e1476);
                                                                        local_144 = _e1477;
                                                                        let _e1481 = (((((_e1470 / _e1471) + 1f) * 0.5f) * _e1477) - 0.5f);
                                                                        local_145 = _e1481;
                                                                        local_146 = (((((_e1473 / _e1474) + 1f) * 0.5f) * _e1477) - 0.5f);
                                                                        if (_e1481 > -1f) {
                                                                            let _e1487 = local_146;
                                                                            if (_e1487 > -1f) {
                                                                                let _e1489 = local_145;
                                                                                let _e1490 = local_144;
                                                                                if (_e1489 < _e1490) {
                                                                                    let _e1492 = local_146;
                                                                                    let _e1493 = local_144;
                                                                                    let _e1494 = (_e1492 < _e1493);
                                                                                    local_147 = _e1494;
                                                                                    if _e1494 {
                                                                                        let _e1495 = local_145;
                                                                                        let _e1496 = floor(_e1495);
                                                                                        local_148 = _e1496;
                                                                                        let _e1497 = local_146;
                                                                                        let _e1498 = floor(_e1497);
                                                                                        local_149 = _e1498;
                                                                                        let _e1499 = local_145;
                                                                                        local_150 = (_e1499 - _e1496);
                                                                                        let _e1501 = local_146;
                                                                                        local_151 = (_e1501 - _e1498);
                                                                                        let _e1503 = (_e1496 < 0f);
                                                                                        local_152 = _e1503;
                                                                                        if _e1503 {
                                                                                            phi_1200_ = f32();
                                                                                            phi_1201_ = true;
                                                                                        } else {
                                                                                            let _e1504 = local_149;
                                                                                            if (_e1504 < 0f) {
                                                                                                phi_1198_ = f32();
                                                                                                phi_1199_ = true;
                                                                                            } else {
                                                                                                let _e1506 = local_148;
                                                                                                let _e1507 = local_144;
                                                                                                if (_e1506 >= _e1507) {
                                                                                                    phi_1196_ = f32();
                                                                                                    phi_1197_ = true;
                                                                                                } else {
                                                                                                    let _e1509 = local_149;
                                                                                                    let _e1510 = local_144;
                                                                                                    let _e1511 = (_e1509 >= _e1510);
                                                                                                    if _e1511 {
                                                                                                        phi_1195_ = f32();
                                                                                                    } else {
                                                                                                        let _e1512 = local_149;
                                                                                                        let _e1514 = local_149;
                                                                                                        let _e1517 = local_149;
                                                                                                        let _e1521 = local_32;
                                                                                                        let _e1523 = local_148;
                                                                                                        let _e1525 = local_148;
                                                                                                        let _e1528 = local_148;
                                                                                                        let _e1532 = ((select(select(u32(_e1512), 0u, !((_e1514 >= 0f))), 4294967295u, (_e1517 > 4294967000f)) * _e1521) + select(select(u32(_e1523), 0u, !((_e1525 >= 0f))), 4294967295u, (_e1528 > 4294967000f)));
                                                                                                        local_153 = _e1532;
                                                                                                        let _e1533 = local_8;
                                                                                                        if (_e1532 < _e1533) {
                                                                                                        } else {
                                                                                                            phi_4744_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1535 = local_153;
                                                                                                        let _e1538 = global_10.member[_e1535];
                                                                                                        phi_1195_ = bitcast<f32>(_e1538);
                                                                                                    }
                                                                                                    let _e1541 = phi_1195_;
                                                                                                    phi_1196_ = _e1541;
                                                                                                    phi_1197_ = _e1511;
                                                                                                }
                                                                                                let _e1543 = phi_1196_;
                                                                                                let _e1545 = phi_1197_;
                                                                                                phi_1198_ = _e1543;
                                                                                                phi_1199_ = _e1545;
                                                                                            }
                                                                                            let _e1547 = phi_1198_;
                                                                                            let _e1549 = phi_1199_;
                                                                                            phi_1200_ = _e1547;
                                                                                            phi_1201_ = _e1549;
                                                                                        }
                                                                                        let _e1551 = phi_1200_;
                                                                                        let _e1553 = phi_1201_;
                                                                                        let _e1555 = local_150;
                                                                                        let _e1556 = (1f - _e1555);
                                                                                        local_154 = _e1556;
                                                                                        local_155 = (select(_e1551, 0f, _e1553) * _e1556);
                                                                                        let _e1558 = local_148;
                                                                                        let _e1559 = (_e1558 + 1f);
                                                                                        local_156 = _e1559;
                                                                                        let _e1560 = (_e1559 < 0f);
                                                                                        local_157 = _e1560;
                                                                                        if _e1560 {
                                                                                            phi_1256_ = f32();
                                                                                            phi_1257_ = true;
                                                                                        } else {
                                                                                            let _e1561 = local_149;
                                                                                            if (_e1561 < 0f) {
                                                                                                phi_1254_ = f32();
                                                                                                phi_1255_ = true;
                                                                                            } else {
                                                                                                let _e1563 = local_156;
                                                                                                let _e1564 = local_144;
                                                                                                if (_e1563 >= _e1564) {
                                                                                                    phi_1252_ = f32();
                                                                                                    phi_1253_ = true;
                                                                                                } else {
                                                                                                    let _e1566 = local_149;
                                                                                                    let _e1567 = local_144;
                                                                                                    let _e1568 = (_e1566 >= _e1567);
                                                                                                    if _e1568 {
                                                                                                        phi_1251_ = f32();
                                                                                                    } else {
                                                                                                        let _e1569 = local_149;
                                                                                                        let _e1571 = local_149;
                                                                                                        let _e1574 = local_149;
                                                                                                        let _e1578 = local_32;
                                                                                                        let _e1580 = local_156;
                                                                                                        let _e1582 = local_156;
                                                                                                        let _e1585 = local_156;
                                                                                                        let _e1589 = ((select(select(u32(_e1569), 0u, !((_e1571 >= 0f))), 4294967295u, (_e1574 > 4294967000f)) * _e1578) + select(select(u32(_e1580), 0u, !((_e1582 >= 0f))), 4294967295u, (_e1585 > 4294967000f)));
                                                                                                        local_158 = _e1589;
                                                                                                        let _e1590 = local_8;
                                                                                                        if (_e1589 < _e1590) {
                                                                                                        } else {
                                                                                                            phi_4744_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1592 = local_158;
                                                                                                        let _e1595 = global_10.member[_e1592];
                                                                                                        phi_1251_ = bitcast<f32>(_e1595);
                                                                                                    }
                                                                                                    let _e1598 = phi_1251_;
                                                                                                    phi_1252_ = _e1598;
                                                                                                    phi_1253_ = _e1568;
                                                                                                }
                                                                                                let _e1600 = phi_1252_;
                                                                                                let _e1602 = phi_1253_;
                                                                                                phi_1254_ = _e1600;
                                                                                                phi_1255_ = _e1602;
                                                                                            }
                                                                                            let _e1604 = phi_1254_;
                                                                                            let _e1606 = phi_1255_;
                                                                                            phi_1256_ = _e1604;
                                                                                            phi_1257_ = _e1606;
                                                                                        }
                                                                                        let _e1608 = phi_1256_;
                                                                                        let _e1610 = phi_1257_;
                                                                                        let _e1612 = local_150;
                                                                                        let _e1614 = local_155;
                                                                                        local_159 = (_e1614 + (select(_e1608, 0f, _e1610) * _e1612));
                                                                                        let _e1616 = local_149;
                                                                                        local_160 = (_e1616 + 1f);
                                                                                        let _e1618 = local_152;
                                                                                        if _e1618 {
                                                                                            phi_1312_ = f32();
                                                                                            phi_1313_ = true;
                                                                                        } else {
                                                                                            let _e1619 = local_160;
                                                                                            if (_e1619 < 0f) {
                                                                                                phi_1310_ = f32();
                                                                                                phi_1311_ = true;
                                                                                            } else {
                                                                                                let _e1621 = local_148;
                                                                                                let _e1622 = local_144;
                                                                                                if (_e1621 >= _e1622) {
                                                                                                    phi_1308_ = f32();
                                                                                                    phi_1309_ = true;
                                                                                                } else {
                                                                                                    let _e1624 = local_160;
                                                                                                    let _e1625 = local_144;
                                                                                                    let _e1626 = (_e1624 >= _e1625);
                                                                                                    if _e1626 {
                                                                                                        phi_1307_ = f32();
                                                                                                    } else {
                                                                                                        let _e1627 = local_160;
                                                                                                        let _e1629 = local_160;
                                                                                                        let _e1632 = local_160;
                                                                                                        let _e1636 = local_32;
                                                                                                        let _e1638 = local_148;
                                                                                                        let _e1640 = local_148;
                                                                                                        let _e1643 = local_148;
                                                                                                        let _e1647 = ((select(select(u32(_e1627), 0u, !((_e1629 >= 0f))), 4294967295u, (_e1632 > 4294967000f)) * _e1636) + select(select(u32(_e1638), 0u, !((_e1640 >= 0f))), 4294967295u, (_e1643 > 4294967000f)));
                                                                                                        local_161 = _e1647;
                                                                                                        let _e1648 = local_8;
                                                                                                        if (_e1647 < _e1648) {
                                                                                                        } else {
                                                                                                            phi_4744_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1650 = local_161;
                                                                                                        let _e1653 = global_10.member[_e1650];
                                                                                                        phi_1307_ = bitcast<f32>(_e1653);
                                                                                                    }
                                                                                                    let _e1656 = phi_1307_;
                                                                                                    phi_1308_ = _e1656;
                                                                                                    phi_1309_ = _e1626;
                                                                                                }
                                                                                                let _e1658 = phi_1308_;
                                                                                                let _e1660 = phi_1309_;
                                                                                                phi_1310_ = _e1658;
                                                                                                phi_1311_ = _e1660;
                                                                                            }
                                                                                            let _e1662 = phi_1310_;
                                                                                            let _e1664 = phi_1311_;
                                                                                            phi_1312_ = _e1662;
                                                                                            phi_1313_ = _e1664;
                                                                                        }
                                                                                        let _e1666 = phi_1312_;
                                                                                        let _e1668 = phi_1313_;
                                                                                        let _e1670 = local_154;
                                                                                        local_162 = (select(_e1666, 0f, _e1668) * _e1670);
                                                                                        let _e1672 = local_157;
                                                                                        if _e1672 {
                                                                                            phi_1369_ = f32();
                                                                                            phi_1370_ = true;
                                                                                        } else {
                                                                                            let _e1673 = local_160;
                                                                                            if (_e1673 < 0f) {
                                                                                                phi_1367_ = f32();
                                                                                                phi_1368_ = true;
                                                                                            } else {
                                                                                                let _e1675 = local_156;
                                                                                                let _e1676 = local_144;
                                                                                                if (_e1675 >= _e1676) {
                                                                                                    phi_1365_ = f32();
                                                                                                    phi_1366_ = true;
                                                                                                } else {
                                                                                                    let _e1678 = local_160;
                                                                                                    let _e1679 = local_144;
                                                                                                    let _e1680 = (_e1678 >= _e1679);
                                                                                                    if _e1680 {
                                                                                                        phi_1364_ = f32();
                                                                                                    } else {
                                                                                                        let _e1681 = local_160;
                                                                                                        let _e1683 = local_160;
                                                                                                        let _e1686 = local_160;
                                                                                                        let _e1690 = local_32;
                                                                                                        let _e1692 = local_156;
                                                                                                        let _e1694 = local_156;
                                                                                                        let _e1697 = local_156;
                                                                                                        let _e1701 = ((select(select(u32(_e1681), 0u, !((_e1683 >= 0f))), 4294967295u, (_e1686 > 4294967000f)) * _e1690) + select(select(u32(_e1692), 0u, !((_e1694 >= 0f))), 4294967295u, (_e1697 > 4294967000f)));
                                                                                                        local_163 = _e1701;
                                                                                                        let _e1702 = local_8;
                                                                                                        if (_e1701 < _e1702) {
                                                                                                        } else {
                                                                                                            phi_4744_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1704 = local_163;
                                                                                                        let _e1707 = global_10.member[_e1704];
                                                                                                        phi_1364_ = bitcast<f32>(_e1707);
                                                                                                    }
                                                                                                    let _e1710 = phi_1364_;
                                                                                                    phi_1365_ = _e1710;
                                                                                                    phi_1366_ = _e1680;
                                                                                                }
                                                                                                let _e1712 = phi_1365_;
                                                                                                let _e1714 = phi_1366_;
                                                                                                phi_1367_ = _e1712;
                                                                                                phi_1368_ = _e1714;
                                                                                            }
                                                                                            let _e1716 = phi_1367_;
                                                                                            let _e1718 = phi_1368_;
                                                                                            phi_1369_ = _e1716;
                                                                                            phi_1370_ = _e1718;
                                                                                        }
                                                                                        let _e1720 = phi_1369_;
                                                                                        let _e1722 = phi_1370_;
                                                                                        let _e1724 = local_150;
                                                                                        let _e1726 = local_162;
                                                                                        let _e1728 = local_151;
                                                                                        let _e1730 = local_159;
                                                                                        let _e1732 = local_151;
                                                                                        phi_1381_ = ((_e1730 * (1f - _e1728)) + ((_e1726 + (select(_e1720, 0f, _e1722) * _e1724)) * _e1732));
                                                                                    } else {
                                                                                        phi_1381_ = f32();
                                                                                    }
                                                                                    let _e1736 = phi_1381_;
                                                                                    let _e1737 = local_147;
                                                                                    phi_1383_ = _e1736;
                                                                                    phi_1384_ = select(true, false, _e1737);
                                                                                } else {
                                                                                    phi_1383_ = f32();
                                                                                    phi_1384_ = true;
                                                                                }
                                                                                let _e1740 = phi_1383_;
                                                                                let _e1742 = phi_1384_;
                                                                                phi_1385_ = _e1740;
                                                                                phi_1386_ = _e1742;
                                                                            } else {
                                                                                phi_1385_ = f32();
                                                                                phi_1386_ = true;
                                                                            }
                                                                            let _e1744 = phi_1385_;
                                                                            let _e1746 = phi_1386_;
                                                                            phi_1387_ = _e1744;
                                                                            phi_1388_ = _e1746;
                                                                        } else {
                                                                            phi_1387_ = f32();
                                                                            phi_1388_ = true;
                                                                        }
                                                                        let _e1748 = phi_1387_;
                                                                        let _e1750 = phi_1388_;
                                                                        phi_1393_ = select(_e1748, 0f, _e1750);
                                                                    } else {
                                                                        phi_1393_ = 0f;
                                                                    }
                                                                    let _e1753 = phi_1393_;
                                                                    phi_1486_ = _e1753;
                                                                } else {
                                                                    let _e1384 = local_141;
                                                                    let _e1385 = local_141;
                                                                    let _e1387 = local_142;
                                                                    let _e1388 = local_142;
                                                                    let _e1391 = sqrt(((_e1384 * _e1385) + (_e1387 * _e1388)));
                                                                    local_164 = _e1391;
                                                                    let _e1392 = local_140;
                                                                    if _e1392 {
                                                                        phi_1473_ = _e1391;
                                                                    } else {
                                                                        let _e1393 = local_27;
                                                                        let _e1395 = local_141;
                                                                        let _e1397 = local_27;
                                                                        let _e1399 = local_142;
                                                                        phi_1415_ = 1u;
                                                                        phi_1418_ = ((_e1395 * _e1393[0]) + (_e1399 * _e1397[1]));
                                                                        phi_1420_ = _e614.member_16.member_2;
                                                                        loop {
                                                                            let _e1403 = phi_1415_;
                                                                            let _e1405 = phi_1418_;
                                                                            let _e1407 = phi_1420_;
                                                                            local_165 = _e1403;
                                                                            local_166 = _e1405;
                                                                            local_167 = _e1407;
                                                                            let _e1408 = local_165;
                                                                            let _e1409 = local_25;
                                                                            let _e1410 = (_e1408 < _e1409);
                                                                            local_168 = _e1410;
                                                                            if _e1410 {
                                                                                let _e1411 = local_167;
                                                                                let _e1413 = local_28;
                                                                                let _e1415 = local_167;
                                                                                let _e1417 = local_29;
                                                                                let _e1419 = ((_e1411[0] * _e1413) - (_e1415[1] * _e1417));
                                                                                let _e1420 = local_29;
                                                                                let _e1422 = local_28;
                                                                                let _e1424 = ((_e1411[0] * _e1420) + (_e1415[1] * _e1422));
                                                                                let _e1426 = local_141;
                                                                                let _e1428 = local_142;
                                                                                let _e1430 = ((_e1426 * _e1419) + (_e1428 * _e1424));
                                                                                let _e1431 = local_166;
                                                                                let _e1433 = local_166;
                                                                                let _e1435 = local_165;
                                                                                phi_1416_ = (_e1435 + 1u);
                                                                                phi_1419_ = select(_e1433, _e1430, (_e1430 > _e1431));
                                                                                phi_1421_ = array<f32, 2>(_e1419, _e1424);
                                                                            } else {
                                                                                phi_1416_ = u32();
                                                                                phi_1419_ = f32();
                                                                                phi_1421_ = array<f32, 2>();
                                                                            }
                                                                            let _e1438 = phi_1416_;
                                                                            let _e1440 = phi_1419_;
                                                                            let _e1442 = phi_1421_;
                                                                            continue;
                                                                            continuing {
                                                                                let _e1443 = local_168;
                                                                                phi_1415_ = _e1438;
                                                                                phi_1418_ = _e1440;
                                                                                phi_1420_ = _e1442;
                                                                                break if !(_e1443);
                                                                            }
                                                                        }
                                                                        let _e1445 = local_26;
                                                                        let _e1447 = local_166;
                                                                        let _e1449 = local_30;
                                                                        let _e1451 = local_26;
                                                                        let _e1452 = local_164;
                                                                        phi_1473_ = ((((1f - _e1445) * _e1447) * _e1449) + (_e1451 * _e1452));
                                                                    }
                                                                    let _e1456 = phi_1473_;
                                                                    let _e1457 = local_443;
                                                                    let _e1459 = local_130;
                                                                    let _e1460 = ((_e1457 - _e1456) / _e1459);
                                                                    phi_1486_ = select(0f, select(1f, _e1460, (_e1460 < 1f)), (0f < _e1460));
                                                                }
                                                                let _e1755 = phi_1486_;
                                                                phi_1487_ = _e1755;
                                                            }
                                                            let _e1777 = phi_1487_;
                                                            phi_1488_ = _e1777;
                                                        }
                                                        let _e1799 = phi_1488_;
                                                        let _e1800 = local_137;
                                                        local_445 = select(0f, _e1799, _e1800);
                                                        phi_1494_ = 0u;
                                                        phi_1497_ = _e1352;
                                                        loop {
                                                            let _e1803 = phi_1494_;
                                                            let _e1805 = phi_1497_;
                                                            local_169 = _e1803;
                                                            local_170 = _e1805;
                                                            local_458 = _e1805;
                                                            let _e1806 = local_169;
                                                            let _e1807 = (_e1806 < 1u);
                                                            local_171 = _e1807;
                                                            if _e1807 {
                                                                let _e1808 = local_170;
                                                                let _e1809 = local_445;
                                                                let _e1811 = local_169;
                                                                phi_1495_ = (_e1811 + 1u);
                                                                phi_1498_ = (_e1808 + _e1809);
                                                            } else {
                                                                phi_1495_ = u32();
                                                                phi_1498_ = f32();
                                                            }
                                                            let _e1814 = phi_1495_;
                                                            let _e1816 = phi_1498_;
                                                            continue;
                                                            continuing {
                                                                let _e1817 = local_171;
                                                                phi_1494_ = _e1814;
                                                                phi_1497_ = _e1816;
                                                                break if !(_e1817);
                                                            }
                                                        }
                                                        let _e1819 = local_136;
                                                        phi_1017_ = (_e1819 + 1f);
                                                        let _e4234 = local_458;
                                                        phi_1020_ = _e4234;
                                                    } else {
                                                        phi_1017_ = f32();
                                                        phi_1020_ = f32();
                                                    }
                                                    let _e1822 = phi_1017_;
                                                    let _e1824 = phi_1020_;
                                                    continue;
                                                    continuing {
                                                        let _e1825 = local_137;
                                                        phi_1016_ = _e1822;
                                                        phi_1019_ = _e1824;
                                                        phi_4744_ = _e1337;
                                                        break if !(_e1825);
                                                    }
                                                }
                                                let _e1828 = phi_4744_;
                                                phi_4811_ = _e1828;
                                                if _e1828 {
                                                    break;
                                                }
                                                let _e1829 = local_133;
                                                phi_4812_ = _e1828;
                                                phi_1003_ = (_e1829 + 1f);
                                                let _e4240 = local_459;
                                                phi_1006_ = _e4240;
                                            } else {
                                                phi_4812_ = _e1337;
                                                phi_1003_ = f32();
                                                phi_1006_ = f32();
                                            }
                                            let _e1832 = phi_4812_;
                                            let _e1834 = phi_1003_;
                                            let _e1836 = phi_1006_;
                                            continue;
                                            continuing {
                                                let _e1837 = local_134;
                                                phi_4755_ = _e1832;
                                                phi_1002_ = _e1834;
                                                phi_1005_ = _e1836;
                                                phi_4811_ = _e1832;
                                                break if !(_e1837);
                                            }
                                        }
                                        let _e1840 = phi_4811_;
                                        phi_5055_ = _e1840;
                                        if _e1840 {
                                            break;
                                        }
                                        phi_4829_ = _e1840;
                                        let _e4246 = local_460;
                                        phi_1510_ = _e4246;
                                    }
                                    let _e1865 = phi_4829_;
                                    let _e1867 = phi_1510_;
                                    let _e1868 = local_129;
                                    phi_4828_ = _e1865;
                                    phi_1512_ = (_e1868 / _e1867);
                                }
                                let _e1871 = phi_4828_;
                                let _e1873 = phi_1512_;
                                local_172 = _e1873;
                                phi_1514_ = 0u;
                                loop {
                                    let _e1875 = phi_1514_;
                                    local_173 = _e1875;
                                    let _e1876 = local_173;
                                    let _e1877 = local_44;
                                    if (_e1876 < _e1877) {
                                        let _e1879 = local_173;
                                        let _e1880 = (_e1879 + 1u);
                                        let _e1882 = local_16;
                                        let _e1887 = local_443;
                                        let _e1888 = (_e1887 >= f32((2u * (_e1882 << bitcast<u32>((_e1880 & 31u))))));
                                        phi_1515_ = select(u32(), _e1880, _e1888);
                                        phi_1536_ = _e1888;
                                    } else {
                                        phi_1515_ = u32();
                                        phi_1536_ = false;
                                    }
                                    let _e1891 = phi_1515_;
                                    let _e1893 = phi_1536_;
                                    local_174 = _e1893;
                                    continue;
                                    continuing {
                                        let _e1894 = local_174;
                                        phi_1514_ = _e1891;
                                        break if !(_e1894);
                                    }
                                }
                                let _e1896 = local_173;
                                let _e1902 = local_172;
                                local_175 = bitcast<u32>((_e1902 * f32((1u << bitcast<u32>(((2u * _e1896) & 31u))))));
                                let _e1905 = local;
                                let _e1906 = (2304u + _e1905);
                                local_176 = _e1906;
                                if (_e1906 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1908 = local_176;
                                let _e1910 = local_175;
                                global_11[_e1908] = _e1910;
                                let _e1911 = local;
                                let _e1912 = (5632u + _e1911);
                                local_177 = _e1912;
                                if (_e1912 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1914 = local_177;
                                let _e1916 = local_114;
                                global_11[_e1914] = _e1916;
                                let _e1917 = local_113;
                                local_178 = bitcast<u32>(f32((1u << bitcast<u32>((_e1917.member_4 & 31u)))));
                                let _e1924 = local;
                                let _e1925 = (3584u + _e1924);
                                local_179 = _e1925;
                                if (_e1925 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1927 = local_179;
                                let _e1929 = local_178;
                                global_11[_e1927] = _e1929;
                                let _e1930 = local_444;
                                local_180 = bitcast<u32>(_e1930);
                                let _e1932 = local;
                                let _e1933 = (3840u + _e1932);
                                local_181 = _e1933;
                                if (_e1933 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1935 = local_181;
                                let _e1937 = local_180;
                                global_11[_e1935] = _e1937;
                                let _e1938 = local_113;
                                local_182 = bitcast<u32>(_e1938.member_2);
                                let _e1941 = local;
                                let _e1942 = (4096u + _e1941);
                                local_183 = _e1942;
                                if (_e1942 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1944 = local_183;
                                let _e1946 = local_182;
                                global_11[_e1944] = _e1946;
                                let _e1947 = local_113;
                                local_184 = bitcast<u32>(_e1947.member_1[0]);
                                let _e1951 = local;
                                let _e1952 = (2560u + _e1951);
                                local_185 = _e1952;
                                if (_e1952 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1954 = local_185;
                                let _e1956 = local_184;
                                global_11[_e1954] = _e1956;
                                let _e1957 = local_113;
                                local_186 = bitcast<u32>(_e1957.member_1[1]);
                                let _e1961 = local;
                                let _e1962 = (2816u + _e1961);
                                local_187 = _e1962;
                                if (_e1962 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1964 = local_187;
                                let _e1966 = local_186;
                                global_11[_e1964] = _e1966;
                                let _e1967 = local_113;
                                local_188 = bitcast<u32>(_e1967.member_1[2]);
                                let _e1971 = local;
                                let _e1972 = (3072u + _e1971);
                                local_189 = _e1972;
                                if (_e1972 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1974 = local_189;
                                let _e1976 = local_188;
                                global_11[_e1974] = _e1976;
                                let _e1977 = local;
                                let _e1978 = (3328u + _e1977);
                                local_190 = _e1978;
                                if (_e1978 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1980 = local_190;
                                let _e1982 = local_118;
                                global_11[_e1980] = _e1982;
                                phi_4824_ = _e1871;
                            } else {
                                phi_4824_ = _e1011;
                            }
                            let _e1984 = phi_4824_;
                            storageBarrier();
                            workgroupBarrier();
                            let _e1985 = local_48;
                            let _e1986 = local_80;
                            let _e1987 = (_e1985 - _e1986);
                            let _e1989 = select(256u, _e1987, (_e1987 < 256u));
                            local_446 = _e1989;
                            local_457[0u] = false;
                            phi_1641_ = 0u;
                            loop {
                                let _e1992 = phi_1641_;
                                local_191 = _e1992;
                                let _e1993 = local_191;
                                let _e1994 = (_e1993 < 1u);
                                local_192 = _e1994;
                                if _e1994 {
                                    let _e1995 = local;
                                    let _e1996 = local_191;
                                    local_193 = (_e1995 + _e1996);
                                    let _e1998 = local_33;
                                    if _e1998 {
                                        phi_4813_ = true;
                                        break;
                                    }
                                    let _e1999 = local_193;
                                    let _e2000 = local_441;
                                    let _e2002 = local_40;
                                    local_194 = (_e2002 + (_e1999 % _e2000));
                                    let _e2004 = local_33;
                                    if _e2004 {
                                        phi_4813_ = true;
                                        break;
                                    }
                                    let _e2005 = local_193;
                                    let _e2006 = local_441;
                                    let _e2008 = local_42;
                                    local_195 = (_e2008 + (_e2005 / _e2006));
                                    let _e2010 = local_193;
                                    let _e2011 = local_66;
                                    if (_e2010 < _e2011) {
                                        let _e2013 = local_194;
                                        let _e2014 = local_13;
                                        let _e2015 = (_e2013 < _e2014);
                                        local_196 = _e2015;
                                        if _e2015 {
                                            let _e2016 = local_195;
                                            let _e2017 = local_14;
                                            phi_1707_ = (_e2016 < _e2017);
                                        } else {
                                            phi_1707_ = bool();
                                        }
                                        let _e2020 = phi_1707_;
                                        let _e2021 = local_196;
                                        phi_1709_ = _e2020;
                                        phi_1710_ = select(true, false, _e2021);
                                    } else {
                                        phi_1709_ = bool();
                                        phi_1710_ = true;
                                    }
                                    let _e2024 = phi_1709_;
                                    let _e2026 = phi_1710_;
                                    local_447 = select(_e2024, false, _e2026);
                                    let _e2028 = local_192;
                                    if _e2028 {
                                    } else {
                                        phi_4813_ = true;
                                        break;
                                    }
                                    let _e2029 = local_191;
                                    let _e2031 = local_447;
                                    local_457[_e2029] = _e2031;
                                    let _e2032 = local_191;
                                    phi_1642_ = (_e2032 + 1u);
                                } else {
                                    phi_1642_ = u32();
                                }
                                let _e2035 = phi_1642_;
                                continue;
                                continuing {
                                    let _e2036 = local_192;
                                    phi_1641_ = _e2035;
                                    phi_4813_ = _e1984;
                                    break if !(_e2036);
                                }
                            }
                            let _e2039 = phi_4813_;
                            phi_5055_ = _e2039;
                            if _e2039 {
                                break;
                            }
                            let _e2040 = local_457[0u];
                            local_454[0u] = _e2040;
                            let _e2042 = local_33;
                            if _e2042 {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2043 = local_33;
                            if _e2043 {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2044 = local_64;
                            local_197 = (f32(_e2044) + 0.5f);
                            let _e2047 = local_33;
                            if _e2047 {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2048 = local_33;
                            if _e2048 {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2049 = local_65;
                            local_198 = (f32(_e2049) + 0.5f);
                            let _e2052 = local;
                            let _e2053 = (768u + _e2052);
                            local_199 = _e2053;
                            if (_e2053 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2055 = local_199;
                            let _e2057 = global_11[_e2055];
                            let _e2058 = bitcast<f32>(_e2057);
                            local_200 = _e2058;
                            let _e2059 = local;
                            if (_e2059 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2061 = local;
                            let _e2063 = global_11[_e2061];
                            local_201 = bitcast<f32>(_e2063);
                            let _e2065 = local;
                            let _e2066 = (256u + _e2065);
                            local_202 = _e2066;
                            if (_e2066 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2068 = local_202;
                            let _e2070 = global_11[_e2068];
                            local_203 = bitcast<f32>(_e2070);
                            let _e2072 = local;
                            let _e2073 = (512u + _e2072);
                            local_204 = _e2073;
                            if (_e2073 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2075 = local_204;
                            let _e2077 = global_11[_e2075];
                            let _e2079 = local_201;
                            let _e2080 = local_203;
                            let _e2082 = local_73;
                            if (_e2082 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2084 = local_73;
                            let _e2086 = global_11[_e2084];
                            local_205 = bitcast<f32>(_e2086);
                            let _e2088 = local;
                            let _e2089 = (_e2088 + 4864u);
                            local_206 = _e2089;
                            if (_e2089 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2091 = local_206;
                            let _e2093 = global_11[_e2091];
                            local_207 = bitcast<f32>(_e2093);
                            let _e2095 = local;
                            let _e2096 = (_e2095 + 5120u);
                            local_208 = _e2096;
                            if (_e2096 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2098 = local_208;
                            let _e2100 = global_11[_e2098];
                            local_209 = bitcast<f32>(_e2100);
                            let _e2102 = local;
                            let _e2103 = (_e2102 + 5376u);
                            local_210 = _e2103;
                            let _e2104 = (_e2103 < 5888u);
                            local_211 = _e2104;
                            if _e2104 {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2105 = local_210;
                            let _e2107 = global_11[_e2105];
                            local_212 = ((_e2107 & 1u) != 0u);
                            let _e2110 = local_211;
                            if _e2110 {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2111 = global_11[_e2105];
                            let _e2114 = local_205;
                            let _e2115 = local_207;
                            let _e2116 = local_209;
                            let _e2117 = local_212;
                            local_453[0u] = false;
                            phi_1941_ = 0u;
                            loop {
                                let _e2121 = phi_1941_;
                                local_213 = _e2121;
                                let _e2122 = local_213;
                                let _e2123 = (_e2122 < 1u);
                                local_214 = _e2123;
                                if _e2123 {
                                    let _e2124 = local_214;
                                    if _e2124 {
                                    } else {
                                        phi_4831_ = true;
                                        break;
                                    }
                                    let _e2125 = local_213;
                                    let _e2127 = local_454[_e2125];
                                    if _e2127 {
                                        let _e2128 = local_200;
                                        phi_1962_ = (_e2128 < 0.99902344f);
                                    } else {
                                        phi_1962_ = false;
                                    }
                                    let _e2131 = phi_1962_;
                                    local_215 = _e2131;
                                    let _e2132 = local_214;
                                    if _e2132 {
                                    } else {
                                        phi_4831_ = true;
                                        break;
                                    }
                                    let _e2133 = local_213;
                                    let _e2135 = local_215;
                                    local_453[_e2133] = _e2135;
                                    let _e2136 = local_213;
                                    phi_1942_ = (_e2136 + 1u);
                                } else {
                                    phi_1942_ = u32();
                                }
                                let _e2139 = phi_1942_;
                                continue;
                                continuing {
                                    let _e2140 = local_214;
                                    phi_1941_ = _e2139;
                                    phi_4831_ = _e2039;
                                    break if !(_e2140);
                                }
                            }
                            let _e2143 = phi_4831_;
                            phi_5055_ = _e2143;
                            if _e2143 {
                                break;
                            }
                            let _e2144 = local_453[0u];
                            local_455[0u] = _e2144;
                            local_452[0u] = 0u;
                            phi_4843_ = _e2143;
                            phi_1975_ = 0u;
                            loop {
                                let _e2148 = phi_4843_;
                                let _e2150 = phi_1975_;
                                local_216 = _e2150;
                                let _e2151 = local_216;
                                let _e2152 = (_e2151 < 1u);
                                local_217 = _e2152;
                                if _e2152 {
                                    let _e2153 = local_217;
                                    if _e2153 {
                                    } else {
                                        phi_4844_ = true;
                                        break;
                                    }
                                    let _e2154 = local_216;
                                    let _e2156 = local_455[_e2154];
                                    if _e2156 {
                                        let _e2157 = local;
                                        let _e2158 = local_216;
                                        let _e2160 = (1024u + (_e2157 + _e2158));
                                        local_218 = _e2160;
                                        if (_e2160 < 5888u) {
                                        } else {
                                            phi_4844_ = true;
                                            break;
                                        }
                                        let _e2162 = local_218;
                                        let _e2164 = global_11[_e2162];
                                        local_219 = bitcast<f32>(_e2164);
                                        phi_2005_ = 0u;
                                        phi_2008_ = _e1989;
                                        loop {
                                            let _e2167 = phi_2005_;
                                            let _e2169 = phi_2008_;
                                            local_220 = _e2167;
                                            local_221 = _e2169;
                                            local_461 = _e2167;
                                            let _e2170 = local_220;
                                            let _e2171 = local_221;
                                            let _e2172 = (_e2170 < _e2171);
                                            local_222 = _e2172;
                                            if _e2172 {
                                                let _e2173 = local_220;
                                                let _e2174 = local_221;
                                                let _e2176 = ((_e2173 + _e2174) / 2u);
                                                local_223 = _e2176;
                                                let _e2177 = (3328u + _e2176);
                                                local_224 = _e2177;
                                                if (_e2177 < 5888u) {
                                                } else {
                                                    phi_4839_ = true;
                                                    break;
                                                }
                                                let _e2179 = local_224;
                                                let _e2181 = global_11[_e2179];
                                                let _e2183 = local_219;
                                                let _e2184 = (bitcast<f32>(_e2181) >= _e2183);
                                                local_225 = _e2184;
                                                if _e2184 {
                                                    phi_2032_ = _e2167;
                                                } else {
                                                    let _e2185 = local_223;
                                                    phi_2032_ = (_e2185 + 1u);
                                                }
                                                let _e2188 = phi_2032_;
                                                let _e2189 = local_225;
                                                let _e2190 = local_223;
                                                let _e2191 = local_221;
                                                phi_2006_ = _e2188;
                                                phi_2009_ = select(_e2191, _e2190, _e2189);
                                            } else {
                                                phi_2006_ = u32();
                                                phi_2009_ = u32();
                                            }
                                            let _e2194 = phi_2006_;
                                            let _e2196 = phi_2009_;
                                            continue;
                                            continuing {
                                                let _e2197 = local_222;
                                                phi_2005_ = _e2194;
                                                phi_2008_ = _e2196;
                                                phi_4839_ = _e2148;
                                                break if !(_e2197);
                                            }
                                        }
                                        let _e2200 = phi_4839_;
                                        phi_4844_ = _e2200;
                                        if _e2200 {
                                            break;
                                        }
                                        phi_4846_ = _e2200;
                                        let _e4274 = local_461;
                                        phi_2034_ = _e4274;
                                    } else {
                                        phi_4846_ = _e2148;
                                        phi_2034_ = 0u;
                                    }
                                    let _e2202 = phi_4846_;
                                    let _e2204 = phi_2034_;
                                    local_226 = _e2204;
                                    let _e2205 = local_217;
                                    if _e2205 {
                                    } else {
                                        phi_4844_ = true;
                                        break;
                                    }
                                    let _e2206 = local_216;
                                    let _e2208 = local_226;
                                    local_452[_e2206] = _e2208;
                                    let _e2209 = local_216;
                                    phi_4845_ = _e2202;
                                    phi_1976_ = (_e2209 + 1u);
                                } else {
                                    phi_4845_ = _e2148;
                                    phi_1976_ = u32();
                                }
                                let _e2212 = phi_4845_;
                                let _e2214 = phi_1976_;
                                continue;
                                continuing {
                                    let _e2215 = local_217;
                                    phi_4843_ = _e2212;
                                    phi_1975_ = _e2214;
                                    phi_4844_ = _e2212;
                                    break if !(_e2215);
                                }
                            }
                            let _e2218 = phi_4844_;
                            phi_5055_ = _e2218;
                            if _e2218 {
                                break;
                            }
                            let _e2219 = local_452[0u];
                            local_456[0u] = _e2219;
                            let _e2221 = local_456[0u];
                            let _e2222 = f32(_e2221);
                            let _e2223 = local_20;
                            local_227 = ((_e2223 >> bitcast<u32>(8u)) & 7u);
                            phi_4852_ = _e2218;
                            phi_2065_ = _e2058;
                            phi_2068_ = type_31(_e2114, _e2115, _e2116, _e2117, ((_e2111 & 2u) != 0u));
                            phi_2070_ = 0u;
                            phi_2072_ = select(select(u32(_e2222), 0u, !((_e2222 >= 0f))), 4294967295u, (_e2222 > 4294967000f));
                            phi_2074_ = _e2222;
                            phi_2076_ = 0f;
                            phi_2078_ = false;
                            phi_2080_ = array<f32, 3>(_e2079, _e2080, bitcast<f32>(_e2077));
                            loop {
                                let _e2234 = phi_4852_;
                                let _e2236 = phi_2065_;
                                let _e2238 = phi_2068_;
                                let _e2240 = phi_2070_;
                                let _e2242 = phi_2072_;
                                let _e2244 = phi_2074_;
                                let _e2246 = phi_2076_;
                                let _e2248 = phi_2078_;
                                let _e2250 = phi_2080_;
                                local_228 = _e2236;
                                local_229 = _e2238;
                                local_230 = _e2240;
                                local_231 = _e2242;
                                local_232 = _e2244;
                                local_233 = _e2246;
                                local_234 = _e2248;
                                local_235 = _e2250;
                                let _e2251 = local_230;
                                let _e2252 = local_231;
                                let _e2253 = (_e2251 < _e2252);
                                local_236 = _e2253;
                                if _e2253 {
                                    let _e2254 = local_230;
                                    let _e2255 = (1536u + _e2254);
                                    local_237 = _e2255;
                                    if (_e2255 < 5888u) {
                                    } else {
                                        phi_4953_ = true;
                                        break;
                                    }
                                    let _e2257 = local_237;
                                    let _e2259 = global_11[_e2257];
                                    local_238 = bitcast<f32>(_e2259);
                                    let _e2261 = local_230;
                                    let _e2262 = (1792u + _e2261);
                                    local_239 = _e2262;
                                    if (_e2262 < 5888u) {
                                    } else {
                                        phi_4953_ = true;
                                        break;
                                    }
                                    let _e2264 = local_239;
                                    let _e2266 = global_11[_e2264];
                                    local_240 = bitcast<f32>(_e2266);
                                    let _e2268 = local_230;
                                    let _e2269 = (2048u + _e2268);
                                    local_241 = _e2269;
                                    if (_e2269 < 5888u) {
                                    } else {
                                        phi_4953_ = true;
                                        break;
                                    }
                                    let _e2271 = local_241;
                                    let _e2273 = global_11[_e2271];
                                    let _e2274 = bitcast<f32>(_e2273);
                                    local_242 = _e2274;
                                    let _e2275 = local_197;
                                    let _e2276 = local_238;
                                    let _e2277 = (_e2275 - _e2276);
                                    local_243 = _e2277;
                                    let _e2278 = local_198;
                                    let _e2279 = local_240;
                                    let _e2280 = (_e2278 - _e2279);
                                    local_244 = _e2280;
                                    let _e2283 = ((_e2277 * _e2277) + (_e2280 * _e2280));
                                    local_245 = _e2283;
                                    let _e2286 = local_230;
                                    let _e2288 = local_232;
                                    let _e2290 = ((_e2283 < (_e2274 * _e2274)) && (f32(_e2286) < _e2288));
                                    local_246 = _e2290;
                                    if _e2290 {
                                        let _e2291 = local_230;
                                        let _e2292 = (5632u + _e2291);
                                        local_247 = _e2292;
                                        if (_e2292 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e2294 = local_247;
                                        let _e2296 = global_11[_e2294];
                                        local_248 = _e2296;
                                        let _e2297 = local_230;
                                        let _e2298 = (3584u + _e2297);
                                        local_249 = _e2298;
                                        if (_e2298 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e2300 = local_249;
                                        let _e2302 = global_11[_e2300];
                                        local_250 = bitcast<f32>(_e2302);
                                        let _e2304 = local_248;
                                        if (_e2304 != 0u) {
                                            let _e2748 = local_242;
                                            let _e2749 = (_e2748 - 1.4142135f);
                                            local_251 = _e2749;
                                            let _e2750 = local_242;
                                            let _e2751 = (_e2750 - 2.828427f);
                                            let _e2754 = local_245;
                                            let _e2756 = ((_e2751 > 0f) && (_e2754 <= (_e2751 * _e2751)));
                                            local_252 = _e2756;
                                            let _e2758 = ((3.1415927f * _e2749) * _e2749);
                                            local_253 = _e2758;
                                            let _e2759 = (1f / _e2758);
                                            local_254 = _e2759;
                                            let _e2761 = local_246;
                                            let _e2762 = (_e2761 && !(_e2756));
                                            local_255 = _e2762;
                                            if _e2762 {
                                                let _e2763 = local_227;
                                                let _e2764 = local_227;
                                                local_256 = (_e2763 * _e2764);
                                                phi_2168_ = 0u;
                                                phi_2171_ = 0f;
                                                phi_2173_ = 0u;
                                                loop {
                                                    let _e2767 = phi_2168_;
                                                    let _e2769 = phi_2171_;
                                                    let _e2771 = phi_2173_;
                                                    local_257 = _e2767;
                                                    local_258 = _e2769;
                                                    local_259 = _e2771;
                                                    let _e2772 = local_257;
                                                    let _e2773 = local_256;
                                                    if (_e2772 < _e2773) {
                                                        let _e2775 = local_257;
                                                        let _e2776 = (_e2775 < 16u);
                                                        if _e2776 {
                                                            let _e2777 = local_257;
                                                            let _e2781 = local_248;
                                                            if ((_e2781 & (1u << bitcast<u32>((_e2777 & 31u)))) == 0u) {
                                                                phi_3011_ = _e2769;
                                                                phi_3012_ = _e2771;
                                                            } else {
                                                                let _e2784 = local_227;
                                                                local_260 = f32(_e2784);
                                                                let _e2786 = local_227;
                                                                let _e2787 = (_e2786 == 0u);
                                                                local_261 = _e2787;
                                                                if _e2787 {
                                                                    phi_4847_ = true;
                                                                    break;
                                                                }
                                                                let _e2788 = local_257;
                                                                let _e2789 = local_227;
                                                                let _e2793 = local_260;
                                                                local_262 = ((f32((_e2788 % _e2789)) + 0.5f) / _e2793);
                                                                let _e2795 = local_261;
                                                                if _e2795 {
                                                                    phi_4847_ = true;
                                                                    break;
                                                                }
                                                                let _e2796 = local_257;
                                                                let _e2797 = local_227;
                                                                let _e2801 = local_260;
                                                                let _e2803 = local_243;
                                                                let _e2804 = local_262;
                                                                let _e2805 = (_e2803 - _e2804);
                                                                local_263 = _e2805;
                                                                let _e2806 = local_244;
                                                                let _e2807 = (_e2806 - ((f32((_e2796 / _e2797)) + 0.5f) / _e2801));
                                                                local_264 = _e2807;
                                                                local_265 = (_e2805 + 1f);
                                                                local_266 = (_e2807 + 1f);
                                                                let _e2810 = local_251;
                                                                if (_e2810 >= 0.0001f) {
                                                                    let _e2824 = local_263;
                                                                    let _e2826 = local_265;
                                                                    let _e2828 = local_263;
                                                                    let _e2831 = local_263;
                                                                    let _e2832 = select(select(0f, (-1f - _e2828), (_e2826 < 0f)), _e2831, (0f < _e2824));
                                                                    let _e2833 = local_264;
                                                                    let _e2835 = local_266;
                                                                    let _e2837 = local_264;
                                                                    let _e2838 = (-1f - _e2837);
                                                                    local_267 = _e2838;
                                                                    let _e2840 = local_264;
                                                                    let _e2841 = select(select(0f, _e2838, (_e2835 < 0f)), _e2840, (0f < _e2833));
                                                                    let _e2842 = local_251;
                                                                    let _e2843 = local_251;
                                                                    let _e2844 = (_e2842 * _e2843);
                                                                    local_268 = _e2844;
                                                                    let _e2848 = (_e2844 <= ((_e2832 * _e2832) + (_e2841 * _e2841)));
                                                                    local_269 = _e2848;
                                                                    let _e2849 = local_263;
                                                                    let _e2850 = -(_e2849);
                                                                    let _e2851 = local_265;
                                                                    let _e2853 = local_265;
                                                                    let _e2854 = select(_e2853, _e2850, (_e2851 < _e2850));
                                                                    let _e2855 = local_264;
                                                                    let _e2856 = -(_e2855);
                                                                    local_270 = _e2856;
                                                                    let _e2857 = local_266;
                                                                    let _e2859 = local_266;
                                                                    let _e2860 = select(_e2859, _e2856, (_e2857 < _e2856));
                                                                    let _e2864 = (((_e2854 * _e2854) + (_e2860 * _e2860)) <= _e2844);
                                                                    local_271 = _e2864;
                                                                    let _e2866 = local_255;
                                                                    if ((_e2866 && !(_e2848)) && !(_e2864)) {
                                                                        let _e2870 = local_251;
                                                                        if (_e2870 > 0f) {
                                                                            let _e2872 = local_264;
                                                                            let _e2873 = (0f <= _e2872);
                                                                            let _e2875 = local_266;
                                                                            let _e2877 = (!(_e2873) && (_e2875 <= 0f));
                                                                            let _e2878 = local_270;
                                                                            let _e2879 = local_266;
                                                                            let _e2880 = select(_e2879, _e2878, _e2877);
                                                                            let _e2881 = local_267;
                                                                            let _e2882 = local_270;
                                                                            let _e2884 = local_264;
                                                                            let _e2885 = select(select(_e2882, _e2881, _e2877), _e2884, _e2873);
                                                                            let _e2889 = local_268;
                                                                            let _e2890 = (_e2889 - (_e2880 * _e2880));
                                                                            let _e2893 = select(0f, sqrt(_e2890), (0f < _e2890));
                                                                            let _e2894 = local_263;
                                                                            let _e2896 = -(_e2893);
                                                                            let _e2897 = local_263;
                                                                            let _e2899 = local_263;
                                                                            let _e2901 = select(select(_e2899, _e2896, (_e2897 < _e2896)), _e2893, (_e2893 < _e2894));
                                                                            let _e2902 = local_265;
                                                                            let _e2904 = local_265;
                                                                            let _e2906 = local_265;
                                                                            let _e2908 = select(select(_e2906, _e2896, (_e2904 < _e2896)), _e2893, (_e2893 < _e2902));
                                                                            let _e2909 = local_251;
                                                                            let _e2910 = local_263;
                                                                            let _e2912 = local_242;
                                                                            let _e2913 = (1.4142135f - _e2912);
                                                                            let _e2914 = local_263;
                                                                            let _e2916 = local_263;
                                                                            let _e2918 = local_251;
                                                                            let _e2919 = select(select(_e2916, _e2913, (_e2914 < _e2913)), _e2918, (_e2909 < _e2910));
                                                                            let _e2920 = local_251;
                                                                            let _e2921 = local_265;
                                                                            let _e2923 = local_265;
                                                                            let _e2925 = local_265;
                                                                            let _e2927 = local_251;
                                                                            let _e2928 = select(select(_e2925, _e2913, (_e2923 < _e2913)), _e2927, (_e2920 < _e2921));
                                                                            let _e2932 = local_268;
                                                                            let _e2933 = (_e2932 - (_e2928 * _e2928));
                                                                            let _e2937 = local_251;
                                                                            let _e2938 = (_e2928 / _e2937);
                                                                            let _e2942 = select(select(_e2938, -1f, (_e2938 < -1f)), 1f, (1f < _e2938));
                                                                            let _e2944 = (_e2942 < 0f);
                                                                            let _e2946 = select(_e2942, -(_e2942), _e2944);
                                                                            let _e2948 = select(_e2946, 1f, (1f < _e2946));
                                                                            let _e2949 = (_e2948 <= 0.5f);
                                                                            let _e2953 = select(sqrt((0.5f * (1f - _e2948))), _e2948, _e2949);
                                                                            let _e2954 = (_e2953 * _e2953);
                                                                            let _e2965 = (_e2953 + ((_e2953 * _e2954) * (0.1666673f + (_e2954 * (0.07496333f + (_e2954 * (0.04533125f + (_e2954 * (0.024905317f + (_e2954 * 0.04087546f))))))))));
                                                                            let _e2968 = select((1.5707964f - (2f * _e2965)), _e2965, _e2949);
                                                                            let _e2971 = local_268;
                                                                            let _e2976 = local_268;
                                                                            let _e2977 = (_e2976 - (_e2919 * _e2919));
                                                                            let _e2981 = local_251;
                                                                            let _e2982 = (_e2919 / _e2981);
                                                                            let _e2986 = select(select(_e2982, -1f, (_e2982 < -1f)), 1f, (1f < _e2982));
                                                                            let _e2988 = (_e2986 < 0f);
                                                                            let _e2990 = select(_e2986, -(_e2986), _e2988);
                                                                            let _e2992 = select(_e2990, 1f, (1f < _e2990));
                                                                            let _e2993 = (_e2992 <= 0.5f);
                                                                            let _e2997 = select(sqrt((0.5f * (1f - _e2992))), _e2992, _e2993);
                                                                            let _e2998 = (_e2997 * _e2997);
                                                                            let _e3009 = (_e2997 + ((_e2997 * _e2998) * (0.1666673f + (_e2998 * (0.07496333f + (_e2998 * (0.04533125f + (_e2998 * (0.024905317f + (_e2998 * 0.04087546f))))))))));
                                                                            let _e3012 = select((1.5707964f - (2f * _e3009)), _e3009, _e2993);
                                                                            let _e3015 = local_268;
                                                                            let _e3019 = ((0.5f * ((_e2928 * select(0f, sqrt(_e2933), (0f < _e2933))) + (_e2971 * select(_e2968, -(_e2968), _e2944)))) - (0.5f * ((_e2919 * select(0f, sqrt(_e2977), (0f < _e2977))) + (_e3015 * select(_e3012, -(_e3012), _e2988)))));
                                                                            let _e3022 = local_268;
                                                                            let _e3023 = (_e3022 - (_e2908 * _e2908));
                                                                            let _e3027 = local_251;
                                                                            let _e3028 = (_e2908 / _e3027);
                                                                            let _e3032 = select(select(_e3028, -1f, (_e3028 < -1f)), 1f, (1f < _e3028));
                                                                            let _e3034 = (_e3032 < 0f);
                                                                            let _e3036 = select(_e3032, -(_e3032), _e3034);
                                                                            let _e3038 = select(_e3036, 1f, (1f < _e3036));
                                                                            let _e3039 = (_e3038 <= 0.5f);
                                                                            let _e3043 = select(sqrt((0.5f * (1f - _e3038))), _e3038, _e3039);
                                                                            let _e3044 = (_e3043 * _e3043);
                                                                            let _e3055 = (_e3043 + ((_e3043 * _e3044) * (0.1666673f + (_e3044 * (0.07496333f + (_e3044 * (0.04533125f + (_e3044 * (0.024905317f + (_e3044 * 0.04087546f))))))))));
                                                                            let _e3058 = select((1.5707964f - (2f * _e3055)), _e3055, _e3039);
                                                                            let _e3061 = local_268;
                                                                            let _e3066 = local_268;
                                                                            let _e3067 = (_e3066 - (_e2901 * _e2901));
                                                                            let _e3071 = local_251;
                                                                            let _e3072 = (_e2901 / _e3071);
                                                                            let _e3076 = select(select(_e3072, -1f, (_e3072 < -1f)), 1f, (1f < _e3072));
                                                                            let _e3078 = (_e3076 < 0f);
                                                                            let _e3080 = select(_e3076, -(_e3076), _e3078);
                                                                            let _e3082 = select(_e3080, 1f, (1f < _e3080));
                                                                            let _e3083 = (_e3082 <= 0.5f);
                                                                            let _e3087 = select(sqrt((0.5f * (1f - _e3082))), _e3082, _e3083);
                                                                            let _e3088 = (_e3087 * _e3087);
                                                                            let _e3099 = (_e3087 + ((_e3087 * _e3088) * (0.1666673f + (_e3088 * (0.07496333f + (_e3088 * (0.04533125f + (_e3088 * (0.024905317f + (_e3088 * 0.04087546f))))))))));
                                                                            let _e3102 = select((1.5707964f - (2f * _e3099)), _e3099, _e3083);
                                                                            let _e3105 = local_268;
                                                                            let _e3112 = local_268;
                                                                            let _e3113 = (_e3112 - (_e2885 * _e2885));
                                                                            let _e3116 = select(0f, sqrt(_e3113), (0f < _e3113));
                                                                            let _e3117 = local_263;
                                                                            let _e3119 = -(_e3116);
                                                                            let _e3120 = local_263;
                                                                            let _e3122 = local_263;
                                                                            let _e3124 = select(select(_e3122, _e3119, (_e3120 < _e3119)), _e3116, (_e3116 < _e3117));
                                                                            let _e3125 = local_265;
                                                                            let _e3127 = local_265;
                                                                            let _e3129 = local_265;
                                                                            let _e3131 = select(select(_e3129, _e3119, (_e3127 < _e3119)), _e3116, (_e3116 < _e3125));
                                                                            let _e3136 = local_268;
                                                                            let _e3137 = (_e3136 - (_e3131 * _e3131));
                                                                            let _e3141 = local_251;
                                                                            let _e3142 = (_e3131 / _e3141);
                                                                            let _e3146 = select(select(_e3142, -1f, (_e3142 < -1f)), 1f, (1f < _e3142));
                                                                            let _e3148 = (_e3146 < 0f);
                                                                            let _e3150 = select(_e3146, -(_e3146), _e3148);
                                                                            let _e3152 = select(_e3150, 1f, (1f < _e3150));
                                                                            let _e3153 = (_e3152 <= 0.5f);
                                                                            let _e3157 = select(sqrt((0.5f * (1f - _e3152))), _e3152, _e3153);
                                                                            let _e3158 = (_e3157 * _e3157);
                                                                            let _e3169 = (_e3157 + ((_e3157 * _e3158) * (0.1666673f + (_e3158 * (0.07496333f + (_e3158 * (0.04533125f + (_e3158 * (0.024905317f + (_e3158 * 0.04087546f))))))))));
                                                                            let _e3172 = select((1.5707964f - (2f * _e3169)), _e3169, _e3153);
                                                                            let _e3175 = local_268;
                                                                            let _e3180 = local_268;
                                                                            let _e3181 = (_e3180 - (_e3124 * _e3124));
                                                                            let _e3185 = local_251;
                                                                            let _e3186 = (_e3124 / _e3185);
                                                                            let _e3190 = select(select(_e3186, -1f, (_e3186 < -1f)), 1f, (1f < _e3186));
                                                                            let _e3192 = (_e3190 < 0f);
                                                                            let _e3194 = select(_e3190, -(_e3190), _e3192);
                                                                            let _e3196 = select(_e3194, 1f, (1f < _e3194));
                                                                            let _e3197 = (_e3196 <= 0.5f);
                                                                            let _e3201 = select(sqrt((0.5f * (1f - _e3196))), _e3196, _e3197);
                                                                            let _e3202 = (_e3201 * _e3201);
                                                                            let _e3213 = (_e3201 + ((_e3201 * _e3202) * (0.1666673f + (_e3202 * (0.07496333f + (_e3202 * (0.04533125f + (_e3202 * (0.024905317f + (_e3202 * 0.04087546f))))))))));
                                                                            let _e3216 = select((1.5707964f - (2f * _e3213)), _e3213, _e3197);
                                                                            let _e3219 = local_268;
                                                                            let _e3226 = ((((_e2880 * (_e2908 - _e2901)) + _e3019) - ((0.5f * ((_e2908 * select(0f, sqrt(_e3023), (0f < _e3023))) + (_e3061 * select(_e3058, -(_e3058), _e3034)))) - (0.5f * ((_e2901 * select(0f, sqrt(_e3067), (0f < _e3067))) + (_e3105 * select(_e3102, -(_e3102), _e3078)))))) + (select(1f, -1f, (_e2873 || _e2877)) * (((_e2885 * (_e3131 - _e3124)) + _e3019) - ((0.5f * ((_e3131 * select(0f, sqrt(_e3137), (0f < _e3137))) + (_e3175 * select(_e3172, -(_e3172), _e3148)))) - (0.5f * ((_e3124 * select(0f, sqrt(_e3181), (0f < _e3181))) + (_e3219 * select(_e3216, -(_e3216), _e3192))))))));
                                                                            let _e3227 = local_265;
                                                                            let _e3228 = local_263;
                                                                            let _e3230 = local_266;
                                                                            let _e3231 = local_264;
                                                                            let _e3233 = ((_e3227 - _e3228) * (_e3230 - _e3231));
                                                                            phi_2984_ = select(select(0f, _e3226, (0f < _e3226)), _e3233, (_e3233 < _e3226));
                                                                        } else {
                                                                            phi_2984_ = 0f;
                                                                        }
                                                                        let _e3239 = phi_2984_;
                                                                        let _e3240 = local_271;
                                                                        phi_2989_ = select(_e3239, 1f, _e3240);
                                                                    } else {
                                                                        phi_2989_ = 1f;
                                                                    }
                                                                    let _e3243 = phi_2989_;
                                                                    let _e3244 = local_253;
                                                                    let _e3246 = local_269;
                                                                    phi_3008_ = select((_e3243 / _e3244), 0f, _e3246);
                                                                } else {
                                                                    let _e2812 = local_263;
                                                                    let _e2814 = local_265;
                                                                    let _e2817 = local_264;
                                                                    let _e2820 = local_266;
                                                                    phi_3008_ = select(0f, 1f, ((((_e2812 <= 0f) && (0f < _e2814)) && (_e2817 <= 0f)) && (0f < _e2820)));
                                                                }
                                                                let _e3249 = phi_3008_;
                                                                let _e3250 = local_258;
                                                                let _e3252 = local_259;
                                                                phi_3011_ = (_e3250 + _e3249);
                                                                phi_3012_ = (_e3252 + 1u);
                                                            }
                                                            let _e3255 = phi_3011_;
                                                            let _e3257 = phi_3012_;
                                                            let _e3258 = local_257;
                                                            phi_3014_ = (_e3258 + 1u);
                                                            phi_3015_ = _e3255;
                                                            phi_3016_ = _e3257;
                                                        } else {
                                                            phi_3014_ = u32();
                                                            phi_3015_ = f32();
                                                            phi_3016_ = u32();
                                                        }
                                                        let _e3261 = phi_3014_;
                                                        let _e3263 = phi_3015_;
                                                        let _e3265 = phi_3016_;
                                                        phi_2169_ = _e3261;
                                                        phi_2172_ = _e3263;
                                                        phi_2174_ = _e3265;
                                                        phi_3017_ = _e2776;
                                                    } else {
                                                        phi_2169_ = u32();
                                                        phi_2172_ = f32();
                                                        phi_2174_ = u32();
                                                        phi_3017_ = false;
                                                    }
                                                    let _e3267 = phi_2169_;
                                                    let _e3269 = phi_2172_;
                                                    let _e3271 = phi_2174_;
                                                    let _e3273 = phi_3017_;
                                                    local_272 = _e3273;
                                                    continue;
                                                    continuing {
                                                        let _e3274 = local_272;
                                                        phi_2168_ = _e3267;
                                                        phi_2171_ = _e3269;
                                                        phi_2173_ = _e3271;
                                                        phi_4847_ = _e2234;
                                                        break if !(_e3274);
                                                    }
                                                }
                                                let _e3277 = phi_4847_;
                                                phi_4953_ = _e3277;
                                                if _e3277 {
                                                    break;
                                                }
                                                let _e3278 = local_259;
                                                if (_e3278 == 0u) {
                                                    phi_3028_ = 0f;
                                                } else {
                                                    let _e3280 = local_259;
                                                    let _e3282 = local_258;
                                                    phi_3028_ = (_e3282 / f32(_e3280));
                                                }
                                                let _e3285 = phi_3028_;
                                                let _e3286 = local_252;
                                                let _e3287 = local_254;
                                                phi_4975_ = _e3277;
                                                phi_3033_ = select(_e3285, _e3287, _e3286);
                                            } else {
                                                phi_4975_ = _e2234;
                                                phi_3033_ = _e2759;
                                            }
                                            let _e3290 = phi_4975_;
                                            let _e3292 = phi_3033_;
                                            phi_4974_ = _e3290;
                                            phi_3500_ = _e3292;
                                        } else {
                                            let _e2306 = local_25;
                                            let _e2307 = (_e2306 == 0u);
                                            local_273 = _e2307;
                                            if _e2307 {
                                                let _e2308 = local_32;
                                                phi_3044_ = (_e2308 == 0u);
                                            } else {
                                                phi_3044_ = false;
                                            }
                                            let _e2311 = phi_3044_;
                                            if _e2311 {
                                                let _e2726 = local_242;
                                                let _e2727 = local_250;
                                                let _e2728 = (_e2726 - _e2727);
                                                let _e2731 = local_245;
                                                let _e2734 = local_245;
                                                let _e2736 = local_242;
                                                let _e2738 = local_250;
                                                let _e2740 = ((_e2736 - sqrt(_e2734)) * (1f / _e2738));
                                                phi_3499_ = select(select(0f, select(1f, _e2740, (_e2740 < 1f)), (0f < _e2740)), 1f, ((0f < _e2728) && (_e2731 <= (_e2728 * _e2728))));
                                            } else {
                                                let _e2312 = local_230;
                                                let _e2313 = (3840u + _e2312);
                                                local_274 = _e2313;
                                                if (_e2313 < 5888u) {
                                                } else {
                                                    phi_4953_ = true;
                                                    break;
                                                }
                                                let _e2315 = local_274;
                                                let _e2317 = global_11[_e2315];
                                                local_275 = bitcast<f32>(_e2317);
                                                let _e2319 = local_273;
                                                if _e2319 {
                                                    let _e2320 = local_32;
                                                    phi_3090_ = (_e2320 == 0u);
                                                } else {
                                                    phi_3090_ = false;
                                                }
                                                let _e2323 = phi_3090_;
                                                if _e2323 {
                                                    let _e2704 = local_242;
                                                    let _e2705 = local_250;
                                                    let _e2706 = (_e2704 - _e2705);
                                                    let _e2709 = local_245;
                                                    let _e2712 = local_245;
                                                    let _e2714 = local_242;
                                                    let _e2716 = local_250;
                                                    let _e2718 = ((_e2714 - sqrt(_e2712)) * (1f / _e2716));
                                                    phi_3498_ = select(select(0f, select(1f, _e2718, (_e2718 < 1f)), (0f < _e2718)), 1f, ((0f < _e2706) && (_e2709 <= (_e2706 * _e2706))));
                                                } else {
                                                    let _e2324 = local_275;
                                                    let _e2325 = local_243;
                                                    local_276 = (_e2324 * _e2325);
                                                    let _e2327 = local_275;
                                                    let _e2328 = local_244;
                                                    local_277 = (_e2327 * _e2328);
                                                    let _e2330 = local_32;
                                                    if (_e2330 > 0u) {
                                                        let _e2413 = local_250;
                                                        let _e2415 = local_242;
                                                        let _e2416 = (_e2415 - (0.5f * _e2413));
                                                        local_278 = _e2416;
                                                        if (_e2416 > 0f) {
                                                            let _e2418 = local_276;
                                                            let _e2419 = local_278;
                                                            let _e2421 = local_277;
                                                            let _e2422 = local_278;
                                                            let _e2424 = local_32;
                                                            let _e2425 = f32(_e2424);
                                                            local_279 = _e2425;
                                                            let _e2429 = (((((_e2418 / _e2419) + 1f) * 0.5f) * _e2425) - 0.5f);
                                                            local_280 = _e2429;
                                                            local_281 = (((((_e2421 / _e2422) + 1f) * 0.5f) * _e2425) - 0.5f);
                                                            if (_e2429 > -1f) {
                                                                let _e2435 = local_281;
                                                                if (_e2435 > -1f) {
                                                                    let _e2437 = local_280;
                                                                    let _e2438 = local_279;
                                                                    if (_e2437 < _e2438) {
                                                                        let _e2440 = local_281;
                                                                        let _e2441 = local_279;
                                                                        let _e2442 = (_e2440 < _e2441);
                                                                        local_282 = _e2442;
                                                                        if _e2442 {
                                                                            let _e2443 = local_280;
                                                                            let _e2444 = floor(_e2443);
                                                                            local_283 = _e2444;
                                                                            let _e2445 = local_281;
                                                                            let _e2446 = floor(_e2445);
                                                                            local_284 = _e2446;
                                                                            let _e2447 = local_280;
                                                                            local_285 = (_e2447 - _e2444);
                                                                            let _e2449 = local_281;
                                                                            local_286 = (_e2449 - _e2446);
                                                                            let _e2451 = (_e2444 < 0f);
                                                                            local_287 = _e2451;
                                                                            if _e2451 {
                                                                                phi_3211_ = f32();
                                                                                phi_3212_ = true;
                                                                            } else {
                                                                                let _e2452 = local_284;
                                                                                if (_e2452 < 0f) {
                                                                                    phi_3209_ = f32();
                                                                                    phi_3210_ = true;
                                                                                } else {
                                                                                    let _e2454 = local_283;
                                                                                    let _e2455 = local_279;
                                                                                    if (_e2454 >= _e2455) {
                                                                                        phi_3207_ = f32();
                                                                                        phi_3208_ = true;
                                                                                    } else {
                                                                                        let _e2457 = local_284;
                                                                                        let _e2458 = local_279;
                                                                                        let _e2459 = (_e2457 >= _e2458);
                                                                                        if _e2459 {
                                                                                            phi_3206_ = f32();
                                                                                        } else {
                                                                                            let _e2460 = local_284;
                                                                                            let _e2462 = local_284;
                                                                                            let _e2465 = local_284;
                                                                                            let _e2469 = local_32;
                                                                                            let _e2471 = local_283;
                                                                                            let _e2473 = local_283;
                                                                                            let _e2476 = local_283;
                                                                                            let _e2480 = ((select(select(u32(_e2460), 0u, !((_e2462 >= 0f))), 4294967295u, (_e2465 > 4294967000f)) * _e2469) + select(select(u32(_e2471), 0u, !((_e2473 >= 0f))), 4294967295u, (_e2476 > 4294967000f)));
                                                                                            local_288 = _e2480;
                                                                                            let _e2481 = local_8;
                                                                                            if (_e2480 < _e2481) {
                                                                                            } else {
                                                                                                phi_4953_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2483 = local_288;
                                                                                            let _e2486 = global_10.member[_e2483];
                                                                                            phi_3206_ = bitcast<f32>(_e2486);
                                                                                        }
                                                                                        let _e2489 = phi_3206_;
                                                                                        phi_3207_ = _e2489;
                                                                                        phi_3208_ = _e2459;
                                                                                    }
                                                                                    let _e2491 = phi_3207_;
                                                                                    let _e2493 = phi_3208_;
                                                                                    phi_3209_ = _e2491;
                                                                                    phi_3210_ = _e2493;
                                                                                }
                                                                                let _e2495 = phi_3209_;
                                                                                let _e2497 = phi_3210_;
                                                                                phi_3211_ = _e2495;
                                                                                phi_3212_ = _e2497;
                                                                            }
                                                                            let _e2499 = phi_3211_;
                                                                            let _e2501 = phi_3212_;
                                                                            let _e2503 = local_285;
                                                                            let _e2504 = (1f - _e2503);
                                                                            local_289 = _e2504;
                                                                            local_290 = (select(_e2499, 0f, _e2501) * _e2504);
                                                                            let _e2506 = local_283;
                                                                            let _e2507 = (_e2506 + 1f);
                                                                            local_291 = _e2507;
                                                                            let _e2508 = (_e2507 < 0f);
                                                                            local_292 = _e2508;
                                                                            if _e2508 {
                                                                                phi_3267_ = f32();
                                                                                phi_3268_ = true;
                                                                            } else {
                                                                                let _e2509 = local_284;
                                                                                if (_e2509 < 0f) {
                                                                                    phi_3265_ = f32();
                                                                                    phi_3266_ = true;
                                                                                } else {
                                                                                    let _e2511 = local_291;
                                                                                    let _e2512 = local_279;
                                                                                    if (_e2511 >= _e2512) {
                                                                                        phi_3263_ = f32();
                                                                                        phi_3264_ = true;
                                                                                    } else {
                                                                                        let _e2514 = local_284;
                                                                                        let _e2515 = local_279;
                                                                                        let _e2516 = (_e2514 >= _e2515);
                                                                                        if _e2516 {
                                                                                            phi_3262_ = f32();
                                                                                        } else {
                                                                                            let _e2517 = local_284;
                                                                                            let _e2519 = local_284;
                                                                                            let _e2522 = local_284;
                                                                                            let _e2526 = local_32;
                                                                                            let _e2528 = local_291;
                                                                                            let _e2530 = local_291;
                                                                                            let _e2533 = local_291;
                                                                                            let _e2537 = ((select(select(u32(_e2517), 0u, !((_e2519 >= 0f))), 4294967295u, (_e2522 > 4294967000f)) * _e2526) + select(select(u32(_e2528), 0u, !((_e2530 >= 0f))), 4294967295u, (_e2533 > 4294967000f)));
                                                                                            local_293 = _e2537;
                                                                                            let _e2538 = local_8;
                                                                                            if (_e2537 < _e2538) {
                                                                                            } else {
                                                                                                phi_4953_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2540 = local_293;
                                                                                            let _e2543 = global_10.member[_e2540];
                                                                                            phi_3262_ = bitcast<f32>(_e2543);
                                                                                        }
                                                                                        let _e2546 = phi_3262_;
                                                                                        phi_3263_ = _e2546;
                                                                                        phi_3264_ = _e2516;
                                                                                    }
                                                                                    let _e2548 = phi_3263_;
                                                                                    let _e2550 = phi_3264_;
                                                                                    phi_3265_ = _e2548;
                                                                                    phi_3266_ = _e2550;
                                                                                }
                                                                                let _e2552 = phi_3265_;
                                                                                let _e2554 = phi_3266_;
                                                                                phi_3267_ = _e2552;
                                                                                phi_3268_ = _e2554;
                                                                            }
                                                                            let _e2556 = phi_3267_;
                                                                            let _e2558 = phi_3268_;
                                                                            let _e2560 = local_285;
                                                                            let _e2562 = local_290;
                                                                            local_294 = (_e2562 + (select(_e2556, 0f, _e2558) * _e2560));
                                                                            let _e2564 = local_284;
                                                                            local_295 = (_e2564 + 1f);
                                                                            let _e2566 = local_287;
                                                                            if _e2566 {
                                                                                phi_3323_ = f32();
                                                                                phi_3324_ = true;
                                                                            } else {
                                                                                let _e2567 = local_295;
                                                                                if (_e2567 < 0f) {
                                                                                    phi_3321_ = f32();
                                                                                    phi_3322_ = true;
                                                                                } else {
                                                                                    let _e2569 = local_283;
                                                                                    let _e2570 = local_279;
                                                                                    if (_e2569 >= _e2570) {
                                                                                        phi_3319_ = f32();
                                                                                        phi_3320_ = true;
                                                                                    } else {
                                                                                        let _e2572 = local_295;
                                                                                        let _e2573 = local_279;
                                                                                        let _e2574 = (_e2572 >= _e2573);
                                                                                        if _e2574 {
                                                                                            phi_3318_ = f32();
                                                                                        } else {
                                                                                            let _e2575 = local_295;
                                                                                            let _e2577 = local_295;
                                                                                            let _e2580 = local_295;
                                                                                            let _e2584 = local_32;
                                                                                            let _e2586 = local_283;
                                                                                            let _e2588 = local_283;
                                                                                            let _e2591 = local_283;
                                                                                            let _e2595 = ((select(select(u32(_e2575), 0u, !((_e2577 >= 0f))), 4294967295u, (_e2580 > 4294967000f)) * _e2584) + select(select(u32(_e2586), 0u, !((_e2588 >= 0f))), 4294967295u, (_e2591 > 4294967000f)));
                                                                                            local_296 = _e2595;
                                                                                            let _e2596 = local_8;
                                                                                            if (_e2595 < _e2596) {
                                                                                            } else {
                                                                                                phi_4953_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2598 = local_296;
                                                                                            let _e2601 = global_10.member[_e2598];
                                                                                            phi_3318_ = bitcast<f32>(_e2601);
                                                                                        }
                                                                                        let _e2604 = phi_3318_;
                                                                                        phi_3319_ = _e2604;
                                                                                        phi_3320_ = _e2574;
                                                                                    }
                                                                                    let _e2606 = phi_3319_;
                                                                                    let _e2608 = phi_3320_;
                                                                                    phi_3321_ = _e2606;
                                                                                    phi_3322_ = _e2608;
                                                                                }
                                                                                let _e2610 = phi_3321_;
                                                                                let _e2612 = phi_3322_;
                                                                                phi_3323_ = _e2610;
                                                                                phi_3324_ = _e2612;
                                                                            }
                                                                            let _e2614 = phi_3323_;
                                                                            let _e2616 = phi_3324_;
                                                                            let _e2618 = local_289;
                                                                            local_297 = (select(_e2614, 0f, _e2616) * _e2618);
                                                                            let _e2620 = local_292;
                                                                            if _e2620 {
                                                                                phi_3380_ = f32();
                                                                                phi_3381_ = true;
                                                                            } else {
                                                                                let _e2621 = local_295;
                                                                                if (_e2621 < 0f) {
                                                                                    phi_3378_ = f32();
                                                                                    phi_3379_ = true;
                                                                                } else {
                                                                                    let _e2623 = local_291;
                                                                                    let _e2624 = local_279;
                                                                                    if (_e2623 >= _e2624) {
                                                                                        phi_3376_ = f32();
                                                                                        phi_3377_ = true;
                                                                                    } else {
                                                                                        let _e2626 = local_295;
                                                                                        let _e2627 = local_279;
                                                                                        let _e2628 = (_e2626 >= _e2627);
                                                                                        if _e2628 {
                                                                                            phi_3375_ = f32();
                                                                                        } else {
                                                                                            let _e2629 = local_295;
                                                                                            let _e2631 = local_295;
                                                                                            let _e2634 = local_295;
                                                                                            let _e2638 = local_32;
                                                                                            let _e2640 = local_291;
                                                                                            let _e2642 = local_291;
                                                                                            let _e2645 = local_291;
                                                                                            let _e2649 = ((select(select(u32(_e2629), 0u, !((_e2631 >= 0f))), 4294967295u, (_e2634 > 4294967000f)) * _e2638) + select(select(u32(_e2640), 0u, !((_e2642 >= 0f))), 4294967295u, (_e2645 > 4294967000f)));
                                                                                            local_298 = _e2649;
                                                                                            let _e2650 = local_8;
                                                                                            if (_e2649 < _e2650) {
                                                                                            } else {
                                                                                                phi_4953_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2652 = local_298;
                                                                                            let _e2655 = global_10.member[_e2652];
                                                                                            phi_3375_ = bitcast<f32>(_e2655);
                                                                                        }
                                                                                        let _e2658 = phi_3375_;
                                                                                        phi_3376_ = _e2658;
                                                                                        phi_3377_ = _e2628;
                                                                                    }
                                                                                    let _e2660 = phi_3376_;
                                                                                    let _e2662 = phi_3377_;
                                                                                    phi_3378_ = _e2660;
                                                                                    phi_3379_ = _e2662;
                                                                                }
                                                                                let _e2664 = phi_3378_;
                                                                                let _e2666 = phi_3379_;
                                                                                phi_3380_ = _e2664;
                                                                                phi_3381_ = _e2666;
                                                                            }
                                                                            let _e2668 = phi_3380_;
                                                                            let _e2670 = phi_3381_;
                                                                            let _e2672 = local_285;
                                                                            let _e2674 = local_297;
                                                                            let _e2676 = local_286;
                                                                            let _e2678 = local_294;
                                                                            let _e2680 = local_286;
                                                                            phi_3392_ = ((_e2678 * (1f - _e2676)) + ((_e2674 + (select(_e2668, 0f, _e2670) * _e2672)) * _e2680));
                                                                        } else {
                                                                            phi_3392_ = f32();
                                                                        }
                                                                        let _e2684 = phi_3392_;
                                                                        let _e2685 = local_282;
                                                                        phi_3394_ = _e2684;
                                                                        phi_3395_ = select(true, false, _e2685);
                                                                    } else {
                                                                        phi_3394_ = f32();
                                                                        phi_3395_ = true;
                                                                    }
                                                                    let _e2688 = phi_3394_;
                                                                    let _e2690 = phi_3395_;
                                                                    phi_3396_ = _e2688;
                                                                    phi_3397_ = _e2690;
                                                                } else {
                                                                    phi_3396_ = f32();
                                                                    phi_3397_ = true;
                                                                }
                                                                let _e2692 = phi_3396_;
                                                                let _e2694 = phi_3397_;
                                                                phi_3398_ = _e2692;
                                                                phi_3399_ = _e2694;
                                                            } else {
                                                                phi_3398_ = f32();
                                                                phi_3399_ = true;
                                                            }
                                                            let _e2696 = phi_3398_;
                                                            let _e2698 = phi_3399_;
                                                            phi_3404_ = select(_e2696, 0f, _e2698);
                                                        } else {
                                                            phi_3404_ = 0f;
                                                        }
                                                        let _e2701 = phi_3404_;
                                                        phi_3497_ = _e2701;
                                                    } else {
                                                        let _e2332 = local_276;
                                                        let _e2333 = local_276;
                                                        let _e2335 = local_277;
                                                        let _e2336 = local_277;
                                                        let _e2339 = sqrt(((_e2332 * _e2333) + (_e2335 * _e2336)));
                                                        local_299 = _e2339;
                                                        let _e2340 = local_273;
                                                        if _e2340 {
                                                            phi_3484_ = _e2339;
                                                        } else {
                                                            let _e2341 = local_27;
                                                            let _e2343 = local_276;
                                                            let _e2345 = local_27;
                                                            let _e2347 = local_277;
                                                            phi_3426_ = 1u;
                                                            phi_3429_ = ((_e2343 * _e2341[0]) + (_e2347 * _e2345[1]));
                                                            phi_3431_ = _e614.member_16.member_2;
                                                            loop {
                                                                let _e2351 = phi_3426_;
                                                                let _e2353 = phi_3429_;
                                                                let _e2355 = phi_3431_;
                                                                local_300 = _e2351;
                                                                local_301 = _e2353;
                                                                local_302 = _e2355;
                                                                let _e2356 = local_300;
                                                                let _e2357 = local_25;
                                                                let _e2358 = (_e2356 < _e2357);
                                                                local_303 = _e2358;
                                                                if _e2358 {
                                                                    let _e2359 = local_302;
                                                                    let _e2361 = local_28;
                                                                    let _e2363 = local_302;
                                                                    let _e2365 = local_29;
                                                                    let _e2367 = ((_e2359[0] * _e2361) - (_e2363[1] * _e2365));
                                                                    let _e2368 = local_29;
                                                                    let _e2370 = local_28;
                                                                    let _e2372 = ((_e2359[0] * _e2368) + (_e2363[1] * _e2370));
                                                                    let _e2374 = local_276;
                                                                    let _e2376 = local_277;
                                                                    let _e2378 = ((_e2374 * _e2367) + (_e2376 * _e2372));
                                                                    let _e2379 = local_301;
                                                                    let _e2381 = local_301;
                                                                    let _e2383 = local_300;
                                                                    phi_3427_ = (_e2383 + 1u);
                                                                    phi_3430_ = select(_e2381, _e2378, (_e2378 > _e2379));
                                                                    phi_3432_ = array<f32, 2>(_e2367, _e2372);
                                                                } else {
                                                                    phi_3427_ = u32();
                                                                    phi_3430_ = f32();
                                                                    phi_3432_ = array<f32, 2>();
                                                                }
                                                                let _e2386 = phi_3427_;
                                                                let _e2388 = phi_3430_;
                                                                let _e2390 = phi_3432_;
                                                                continue;
                                                                continuing {
                                                                    let _e2391 = local_303;
                                                                    phi_3426_ = _e2386;
                                                                    phi_3429_ = _e2388;
                                                                    phi_3431_ = _e2390;
                                                                    break if !(_e2391);
                                                                }
                                                            }
                                                            let _e2393 = local_26;
                                                            let _e2395 = local_301;
                                                            let _e2397 = local_30;
                                                            let _e2399 = local_26;
                                                            let _e2400 = local_299;
                                                            phi_3484_ = ((((1f - _e2393) * _e2395) * _e2397) + (_e2399 * _e2400));
                                                        }
                                                        let _e2404 = phi_3484_;
                                                        let _e2405 = local_242;
                                                        let _e2407 = local_250;
                                                        let _e2408 = ((_e2405 - _e2404) / _e2407);
                                                        phi_3497_ = select(0f, select(1f, _e2408, (_e2408 < 1f)), (0f < _e2408));
                                                    }
                                                    let _e2703 = phi_3497_;
                                                    phi_3498_ = _e2703;
                                                }
                                                let _e2725 = phi_3498_;
                                                phi_3499_ = _e2725;
                                            }
                                            let _e2747 = phi_3499_;
                                            phi_4974_ = _e2234;
                                            phi_3500_ = _e2747;
                                        }
                                        let _e3294 = phi_4974_;
                                        let _e3296 = phi_3500_;
                                        local_304 = _e3296;
                                        let _e3297 = local_230;
                                        let _e3298 = (2304u + _e3297);
                                        local_305 = _e3298;
                                        if (_e3298 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3300 = local_305;
                                        let _e3302 = global_11[_e3300];
                                        let _e3304 = local_304;
                                        local_306 = (bitcast<f32>(_e3302) * _e3304);
                                        let _e3306 = local_230;
                                        let _e3307 = (4096u + _e3306);
                                        local_307 = _e3307;
                                        if (_e3307 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3309 = local_307;
                                        let _e3311 = global_11[_e3309];
                                        local_308 = bitcast<f32>(_e3311);
                                        let _e3313 = local_80;
                                        let _e3314 = local_230;
                                        let _e3316 = local_60;
                                        if ((_e3313 + _e3314) < _e3316) {
                                            let _e3339 = local_230;
                                            let _e3340 = (3328u + _e3339);
                                            local_309 = _e3340;
                                            if (_e3340 < 5888u) {
                                            } else {
                                                phi_4953_ = true;
                                                break;
                                            }
                                            let _e3342 = local_309;
                                            let _e3344 = global_11[_e3342];
                                            let _e3345 = bitcast<f32>(_e3344);
                                            local_310 = _e3345;
                                            let _e3346 = local_228;
                                            let _e3347 = (1f - _e3346);
                                            local_311 = _e3347;
                                            let _e3348 = local_229;
                                            local_312 = _e3348.member;
                                            let _e3353 = local_229;
                                            local_313 = _e3353.member_1;
                                            let _e3355 = local_306;
                                            let _e3359 = (!((_e3345 <= (_e3348.member * 1.05f))) || (1f < (_e3353.member_1 + (0.5f * _e3355))));
                                            let _e3360 = local_229;
                                            local_314 = _e3360.member_3;
                                            let _e3363 = local_229;
                                            local_315 = _e3363.member_4;
                                            let _e3366 = !(_e3359);
                                            local_316 = ((_e3359 && !(_e3360.member_3)) || (_e3366 && _e3363.member_4));
                                            local_317 = (_e3366 && _e3360.member_3);
                                            let _e3370 = local_229;
                                            local_318 = _e3370.member_2;
                                            local_448 = select(_e3370.member_2, _e3347, _e3359);
                                            let _e3374 = local_306;
                                            local_319 = (select(_e3353.member_1, 0f, _e3359) + _e3374);
                                            let _e3376 = local_308;
                                            let _e3377 = (_e3376 < 1f);
                                            local_320 = _e3377;
                                            if _e3377 {
                                                let _e3398 = local_316;
                                                let _e3399 = local_448;
                                                let _e3401 = local_306;
                                                let _e3402 = (_e3401 * select(1f, _e3399, _e3398));
                                                local_321 = _e3402;
                                                let _e3403 = local_308;
                                                let _e3404 = (_e3402 * _e3403);
                                                local_322 = _e3404;
                                                let _e3405 = local_311;
                                                local_323 = (_e3404 < _e3405);
                                                let _e3407 = local_308;
                                                if (_e3407 == 1f) {
                                                    phi_3581_ = _e3347;
                                                } else {
                                                    let _e3409 = local_311;
                                                    let _e3410 = local_308;
                                                    phi_3581_ = (_e3409 / _e3410);
                                                }
                                                let _e3413 = phi_3581_;
                                                let _e3414 = local_323;
                                                let _e3415 = local_321;
                                                let _e3417 = local_323;
                                                let _e3418 = local_322;
                                                let _e3419 = local_311;
                                                phi_3609_ = type_18(select(_e3413, _e3415, _e3414), select(_e3419, _e3418, _e3417));
                                            } else {
                                                let _e3378 = local_306;
                                                let _e3379 = local_308;
                                                let _e3380 = (_e3378 * _e3379);
                                                local_324 = _e3380;
                                                let _e3381 = local_311;
                                                local_325 = (_e3380 < _e3381);
                                                let _e3383 = local_308;
                                                if (_e3383 == 1f) {
                                                    phi_3598_ = _e3347;
                                                } else {
                                                    let _e3385 = local_311;
                                                    let _e3386 = local_308;
                                                    phi_3598_ = (_e3385 / _e3386);
                                                }
                                                let _e3389 = phi_3598_;
                                                let _e3390 = local_325;
                                                let _e3391 = local_306;
                                                let _e3393 = local_325;
                                                let _e3394 = local_324;
                                                let _e3395 = local_311;
                                                phi_3609_ = type_18(select(_e3389, _e3391, _e3390), select(_e3395, _e3394, _e3393));
                                            }
                                            let _e3423 = phi_3609_;
                                            let _e3424 = local_320;
                                            let _e3425 = local_317;
                                            let _e3427 = local_246;
                                            let _e3428 = local_310;
                                            let _e3429 = local_312;
                                            let _e3431 = local_246;
                                            let _e3432 = local_319;
                                            let _e3433 = local_313;
                                            let _e3435 = local_246;
                                            let _e3436 = local_448;
                                            let _e3437 = local_318;
                                            let _e3439 = local_246;
                                            let _e3441 = local_246;
                                            let _e3442 = !(_e3441);
                                            let _e3443 = local_314;
                                            let _e3446 = local_246;
                                            let _e3447 = local_316;
                                            let _e3449 = local_315;
                                            phi_3661_ = type_31(select(_e3429, _e3428, _e3427), select(_e3433, _e3432, _e3431), select(_e3437, _e3436, _e3435), ((_e3439 && select(true, _e3425, _e3424)) || (_e3442 && _e3443)), ((_e3446 && _e3447) || (_e3442 && _e3449)));
                                            phi_3662_ = _e3423;
                                        } else {
                                            let _e3318 = local_228;
                                            let _e3319 = (1f - _e3318);
                                            local_326 = _e3319;
                                            let _e3320 = local_306;
                                            let _e3321 = local_308;
                                            let _e3322 = (_e3320 * _e3321);
                                            local_327 = _e3322;
                                            local_328 = (_e3322 < _e3319);
                                            let _e3324 = local_308;
                                            if (_e3324 == 1f) {
                                                phi_3651_ = _e3319;
                                            } else {
                                                let _e3326 = local_326;
                                                let _e3327 = local_308;
                                                phi_3651_ = (_e3326 / _e3327);
                                            }
                                            let _e3330 = phi_3651_;
                                            let _e3331 = local_328;
                                            let _e3332 = local_306;
                                            let _e3334 = local_328;
                                            let _e3335 = local_327;
                                            let _e3336 = local_326;
                                            phi_3661_ = _e2238;
                                            phi_3662_ = type_18(select(_e3330, _e3332, _e3331), select(_e3336, _e3335, _e3334));
                                        }
                                        let _e3454 = phi_3661_;
                                        let _e3456 = phi_3662_;
                                        local_329 = _e3456.member;
                                        local_330 = _e3456.member_1;
                                        let _e3459 = local_235;
                                        local_331 = _e3459[0];
                                        let _e3461 = local_230;
                                        let _e3462 = (2560u + _e3461);
                                        local_332 = _e3462;
                                        if (_e3462 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3464 = local_332;
                                        let _e3466 = global_11[_e3464];
                                        let _e3468 = local_329;
                                        let _e3470 = local_331;
                                        let _e3472 = local_246;
                                        let _e3473 = local_331;
                                        local_449 = select(_e3473, (_e3470 + (_e3468 * bitcast<f32>(_e3466))), _e3472);
                                        let _e3475 = local_235;
                                        local_333 = _e3475[1];
                                        let _e3477 = local_230;
                                        let _e3478 = (2816u + _e3477);
                                        local_334 = _e3478;
                                        if (_e3478 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3480 = local_334;
                                        let _e3482 = global_11[_e3480];
                                        let _e3484 = local_329;
                                        let _e3486 = local_333;
                                        let _e3488 = local_246;
                                        let _e3489 = local_333;
                                        local_450 = select(_e3489, (_e3486 + (_e3484 * bitcast<f32>(_e3482))), _e3488);
                                        let _e3491 = local_235;
                                        local_335 = _e3491[2];
                                        let _e3493 = local_230;
                                        let _e3494 = (3072u + _e3493);
                                        local_336 = _e3494;
                                        if (_e3494 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3496 = local_336;
                                        let _e3498 = global_11[_e3496];
                                        let _e3500 = local_329;
                                        let _e3502 = local_335;
                                        let _e3504 = local_246;
                                        let _e3505 = local_335;
                                        let _e3507 = local_449;
                                        let _e3508 = local_450;
                                        let _e3510 = local_228;
                                        let _e3511 = local_330;
                                        let _e3513 = local_246;
                                        let _e3514 = local_228;
                                        let _e3515 = select(_e3514, (_e3510 + _e3511), _e3513);
                                        let _e3518 = local_246;
                                        let _e3519 = (_e3518 && !((_e3515 < 0.99902344f)));
                                        local_337 = _e3519;
                                        if _e3519 {
                                            let _e3520 = local_234;
                                            let _e3521 = local_337;
                                            let _e3523 = local_230;
                                            let _e3526 = local_337;
                                            let _e3527 = local_233;
                                            let _e3529 = local_337;
                                            let _e3530 = local_232;
                                            let _e3531 = select(_e3530, 0f, _e3529);
                                            phi_3747_ = select(select(u32(_e3531), 0u, !((_e3531 >= 0f))), 4294967295u, (_e3531 > 4294967000f));
                                            phi_3748_ = _e3531;
                                            phi_3749_ = select(_e3527, f32((_e3523 + 1u)), _e3526);
                                            phi_3750_ = (_e3520 || _e3521);
                                        } else {
                                            phi_3747_ = _e2242;
                                            phi_3748_ = _e2244;
                                            phi_3749_ = _e2246;
                                            phi_3750_ = _e2248;
                                        }
                                        let _e3539 = phi_3747_;
                                        let _e3541 = phi_3748_;
                                        let _e3543 = phi_3749_;
                                        let _e3545 = phi_3750_;
                                        phi_4955_ = _e3294;
                                        phi_3751_ = _e3515;
                                        phi_3752_ = _e3454;
                                        phi_3753_ = _e3539;
                                        phi_3754_ = _e3541;
                                        phi_3755_ = _e3543;
                                        phi_3756_ = _e3545;
                                        phi_3757_ = array<f32, 3>(_e3507, _e3508, select(_e3505, (_e3502 + (_e3500 * bitcast<f32>(_e3498))), _e3504));
                                    } else {
                                        phi_4955_ = _e2234;
                                        phi_3751_ = _e2236;
                                        phi_3752_ = _e2238;
                                        phi_3753_ = _e2242;
                                        phi_3754_ = _e2244;
                                        phi_3755_ = _e2246;
                                        phi_3756_ = _e2248;
                                        phi_3757_ = _e2250;
                                    }
                                    let _e3547 = phi_4955_;
                                    let _e3549 = phi_3751_;
                                    let _e3551 = phi_3752_;
                                    let _e3553 = phi_3753_;
                                    let _e3555 = phi_3754_;
                                    let _e3557 = phi_3755_;
                                    let _e3559 = phi_3756_;
                                    let _e3561 = phi_3757_;
                                    let _e3562 = local_230;
                                    phi_4954_ = _e3547;
                                    phi_2066_ = _e3549;
                                    phi_2069_ = _e3551;
                                    phi_2071_ = (_e3562 + 1u);
                                    phi_2073_ = _e3553;
                                    phi_2075_ = _e3555;
                                    phi_2077_ = _e3557;
                                    phi_2079_ = _e3559;
                                    phi_2081_ = _e3561;
                                } else {
                                    phi_4954_ = _e2234;
                                    phi_2066_ = f32();
                                    phi_2069_ = type_31();
                                    phi_2071_ = u32();
                                    phi_2073_ = u32();
                                    phi_2075_ = f32();
                                    phi_2077_ = f32();
                                    phi_2079_ = bool();
                                    phi_2081_ = array<f32, 3>();
                                }
                                let _e3565 = phi_4954_;
                                let _e3567 = phi_2066_;
                                let _e3569 = phi_2069_;
                                let _e3571 = phi_2071_;
                                let _e3573 = phi_2073_;
                                let _e3575 = phi_2075_;
                                let _e3577 = phi_2077_;
                                let _e3579 = phi_2079_;
                                let _e3581 = phi_2081_;
                                continue;
                                continuing {
                                    let _e3582 = local_236;
                                    phi_4852_ = _e3565;
                                    phi_2065_ = _e3567;
                                    phi_2068_ = _e3569;
                                    phi_2070_ = _e3571;
                                    phi_2072_ = _e3573;
                                    phi_2074_ = _e3575;
                                    phi_2076_ = _e3577;
                                    phi_2078_ = _e3579;
                                    phi_2080_ = _e3581;
                                    phi_4953_ = _e3565;
                                    break if !(_e3582);
                                }
                            }
                            let _e3585 = phi_4953_;
                            phi_5055_ = _e3585;
                            if _e3585 {
                                break;
                            }
                            let _e3586 = local_235;
                            local_338 = _e3586[0];
                            phi_3761_ = 0u;
                            loop {
                                let _e3589 = phi_3761_;
                                local_339 = _e3589;
                                let _e3590 = local_339;
                                let _e3591 = (_e3590 < 1u);
                                local_340 = _e3591;
                                if _e3591 {
                                    let _e3592 = local;
                                    let _e3593 = local_339;
                                    let _e3594 = (_e3592 + _e3593);
                                    local_341 = _e3594;
                                    let _e3595 = local_338;
                                    local_342 = bitcast<u32>(_e3595);
                                    if (_e3594 < 5888u) {
                                    } else {
                                        phi_5027_ = true;
                                        break;
                                    }
                                    let _e3598 = local_341;
                                    let _e3600 = local_342;
                                    global_11[_e3598] = _e3600;
                                    let _e3601 = local_339;
                                    phi_3762_ = (_e3601 + 1u);
                                } else {
                                    phi_3762_ = u32();
                                }
                                let _e3604 = phi_3762_;
                                continue;
                                continuing {
                                    let _e3605 = local_340;
                                    phi_3761_ = _e3604;
                                    phi_5027_ = _e3585;
                                    break if !(_e3605);
                                }
                            }
                            let _e3608 = phi_5027_;
                            phi_5055_ = _e3608;
                            if _e3608 {
                                break;
                            }
                            let _e3609 = local_235;
                            local_343 = _e3609[1];
                            phi_3782_ = 0u;
                            loop {
                                let _e3612 = phi_3782_;
                                local_344 = _e3612;
                                let _e3613 = local_344;
                                let _e3614 = (_e3613 < 1u);
                                local_345 = _e3614;
                                if _e3614 {
                                    let _e3615 = local;
                                    let _e3616 = local_344;
                                    let _e3618 = local_343;
                                    local_346 = bitcast<u32>(_e3618);
                                    let _e3620 = (256u + (_e3615 + _e3616));
                                    local_347 = _e3620;
                                    if (_e3620 < 5888u) {
                                    } else {
                                        phi_5030_ = true;
                                        break;
                                    }
                                    let _e3622 = local_347;
                                    let _e3624 = local_346;
                                    global_11[_e3622] = _e3624;
                                    let _e3625 = local_344;
                                    phi_3783_ = (_e3625 + 1u);
                                } else {
                                    phi_3783_ = u32();
                                }
                                let _e3628 = phi_3783_;
                                continue;
                                continuing {
                                    let _e3629 = local_345;
                                    phi_3782_ = _e3628;
                                    phi_5030_ = _e3608;
                                    break if !(_e3629);
                                }
                            }
                            let _e3632 = phi_5030_;
                            phi_5055_ = _e3632;
                            if _e3632 {
                                break;
                            }
                            let _e3633 = local_235;
                            local_348 = _e3633[2];
                            phi_3803_ = 0u;
                            loop {
                                let _e3636 = phi_3803_;
                                local_349 = _e3636;
                                let _e3637 = local_349;
                                let _e3638 = (_e3637 < 1u);
                                local_350 = _e3638;
                                if _e3638 {
                                    let _e3639 = local;
                                    let _e3640 = local_349;
                                    let _e3642 = local_348;
                                    local_351 = bitcast<u32>(_e3642);
                                    let _e3644 = (512u + (_e3639 + _e3640));
                                    local_352 = _e3644;
                                    if (_e3644 < 5888u) {
                                    } else {
                                        phi_5033_ = true;
                                        break;
                                    }
                                    let _e3646 = local_352;
                                    let _e3648 = local_351;
                                    global_11[_e3646] = _e3648;
                                    let _e3649 = local_349;
                                    phi_3804_ = (_e3649 + 1u);
                                } else {
                                    phi_3804_ = u32();
                                }
                                let _e3652 = phi_3804_;
                                continue;
                                continuing {
                                    let _e3653 = local_350;
                                    phi_3803_ = _e3652;
                                    phi_5033_ = _e3632;
                                    break if !(_e3653);
                                }
                            }
                            let _e3656 = phi_5033_;
                            phi_5055_ = _e3656;
                            if _e3656 {
                                break;
                            }
                            phi_3823_ = 0u;
                            loop {
                                let _e3658 = phi_3823_;
                                local_353 = _e3658;
                                let _e3659 = local_353;
                                let _e3660 = (_e3659 < 1u);
                                local_354 = _e3660;
                                if _e3660 {
                                    let _e3661 = local;
                                    let _e3662 = local_353;
                                    let _e3664 = local_228;
                                    local_355 = bitcast<u32>(_e3664);
                                    let _e3666 = (768u + (_e3661 + _e3662));
                                    local_356 = _e3666;
                                    if (_e3666 < 5888u) {
                                    } else {
                                        phi_5036_ = true;
                                        break;
                                    }
                                    let _e3668 = local_356;
                                    let _e3670 = local_355;
                                    global_11[_e3668] = _e3670;
                                    let _e3671 = local_353;
                                    phi_3824_ = (_e3671 + 1u);
                                } else {
                                    phi_3824_ = u32();
                                }
                                let _e3674 = phi_3824_;
                                continue;
                                continuing {
                                    let _e3675 = local_354;
                                    phi_3823_ = _e3674;
                                    phi_5036_ = _e3656;
                                    break if !(_e3675);
                                }
                            }
                            let _e3678 = phi_5036_;
                            phi_5055_ = _e3678;
                            if _e3678 {
                                break;
                            }
                            phi_3844_ = 0u;
                            loop {
                                let _e3680 = phi_3844_;
                                local_357 = _e3680;
                                let _e3681 = local_357;
                                let _e3682 = (_e3681 < 1u);
                                local_358 = _e3682;
                                if _e3682 {
                                    let _e3683 = local_229;
                                    local_359 = bitcast<u32>(_e3683.member);
                                    let _e3686 = local_73;
                                    let _e3687 = local_357;
                                    let _e3688 = (_e3686 + _e3687);
                                    local_360 = _e3688;
                                    if (_e3688 < 5888u) {
                                    } else {
                                        phi_5039_ = true;
                                        break;
                                    }
                                    let _e3690 = local_360;
                                    let _e3692 = local_359;
                                    global_11[_e3690] = _e3692;
                                    let _e3693 = local_229;
                                    local_361 = bitcast<u32>(_e3693.member_1);
                                    let _e3696 = local_206;
                                    let _e3697 = local_357;
                                    let _e3698 = (_e3696 + _e3697);
                                    local_362 = _e3698;
                                    if (_e3698 < 5888u) {
                                    } else {
                                        phi_5039_ = true;
                                        break;
                                    }
                                    let _e3700 = local_362;
                                    let _e3702 = local_361;
                                    global_11[_e3700] = _e3702;
                                    let _e3703 = local_229;
                                    local_363 = bitcast<u32>(_e3703.member_2);
                                    let _e3706 = local_208;
                                    let _e3707 = local_357;
                                    let _e3708 = (_e3706 + _e3707);
                                    local_364 = _e3708;
                                    if (_e3708 < 5888u) {
                                    } else {
                                        phi_5039_ = true;
                                        break;
                                    }
                                    let _e3710 = local_364;
                                    let _e3712 = local_363;
                                    global_11[_e3710] = _e3712;
                                    let _e3713 = local_229;
                                    local_365 = select(0u, 1u, _e3713.member_3);
                                    let _e3716 = local_229;
                                    local_366 = (select(0u, 1u, _e3716.member_4) << bitcast<u32>(1i));
                                    let _e3721 = local_210;
                                    let _e3722 = local_357;
                                    let _e3723 = (_e3721 + _e3722);
                                    local_367 = _e3723;
                                    if (_e3723 < 5888u) {
                                    } else {
                                        phi_5039_ = true;
                                        break;
                                    }
                                    let _e3725 = local_367;
                                    let _e3727 = local_365;
                                    let _e3728 = local_366;
                                    global_11[_e3725] = (_e3727 | _e3728);
                                    let _e3730 = local_357;
                                    phi_3845_ = (_e3730 + 1u);
                                } else {
                                    phi_3845_ = u32();
                                }
                                let _e3733 = phi_3845_;
                                continue;
                                continuing {
                                    let _e3734 = local_358;
                                    phi_3844_ = _e3733;
                                    phi_5039_ = _e3678;
                                    break if !(_e3734);
                                }
                            }
                            let _e3737 = phi_5039_;
                            phi_5055_ = _e3737;
                            if _e3737 {
                                break;
                            }
                            phi_3900_ = 0u;
                            loop {
                                let _e3739 = phi_3900_;
                                local_368 = _e3739;
                                let _e3740 = local_368;
                                let _e3741 = (_e3740 < 1u);
                                local_369 = _e3741;
                                if _e3741 {
                                    let _e3742 = local;
                                    let _e3743 = local_368;
                                    local_370 = (_e3742 + _e3743);
                                    let _e3745 = local_234;
                                    if _e3745 {
                                        let _e3769 = local_233;
                                        let _e3771 = local_233;
                                        let _e3774 = local_233;
                                        phi_3960_ = false;
                                        phi_3961_ = select(select(u32(_e3769), 0u, !((_e3771 >= 0f))), 4294967295u, (_e3774 > 4294967000f));
                                    } else {
                                        let _e3746 = local_369;
                                        if _e3746 {
                                        } else {
                                            phi_5042_ = true;
                                            break;
                                        }
                                        let _e3747 = local_368;
                                        let _e3749 = local_455[_e3747];
                                        if _e3749 {
                                            let _e3750 = local_369;
                                            if _e3750 {
                                            } else {
                                                phi_5042_ = true;
                                                break;
                                            }
                                            let _e3751 = local_368;
                                            let _e3753 = local_456[_e3751];
                                            let _e3754 = local_446;
                                            if (_e3753 < _e3754) {
                                                let _e3756 = local_369;
                                                if _e3756 {
                                                } else {
                                                    phi_5042_ = true;
                                                    break;
                                                }
                                                let _e3757 = local_456[_e3751];
                                                phi_3949_ = (_e3757 + 1u);
                                            } else {
                                                phi_3949_ = _e1989;
                                            }
                                            let _e3760 = phi_3949_;
                                            let _e3761 = local_369;
                                            if _e3761 {
                                            } else {
                                                phi_5042_ = true;
                                                break;
                                            }
                                            let _e3762 = local_456[_e3751];
                                            let _e3763 = local_446;
                                            phi_3958_ = (_e3762 == _e3763);
                                            phi_3959_ = _e3760;
                                        } else {
                                            phi_3958_ = false;
                                            phi_3959_ = 0u;
                                        }
                                        let _e3766 = phi_3958_;
                                        let _e3768 = phi_3959_;
                                        phi_3960_ = _e3766;
                                        phi_3961_ = _e3768;
                                    }
                                    let _e3779 = phi_3960_;
                                    let _e3781 = phi_3961_;
                                    local_371 = _e3779;
                                    local_372 = _e3781;
                                    let _e3782 = local_369;
                                    if _e3782 {
                                    } else {
                                        phi_5042_ = true;
                                        break;
                                    }
                                    let _e3783 = local_368;
                                    let _e3785 = local_454[_e3783];
                                    if _e3785 {
                                        let _e3786 = local_370;
                                        let _e3787 = (1280u + _e3786);
                                        local_373 = _e3787;
                                        if (_e3787 < 5888u) {
                                        } else {
                                            phi_5042_ = true;
                                            break;
                                        }
                                        let _e3789 = local_373;
                                        let _e3791 = global_11[_e3789];
                                        let _e3792 = local_372;
                                        global_11[_e3789] = (_e3791 + _e3792);
                                    }
                                    let _e3794 = local_370;
                                    let _e3795 = (4352u + _e3794);
                                    local_374 = _e3795;
                                    if (_e3795 < 5888u) {
                                    } else {
                                        phi_5042_ = true;
                                        break;
                                    }
                                    let _e3797 = local_374;
                                    let _e3799 = local_371;
                                    global_11[_e3797] = select(0u, 1u, _e3799);
                                    let _e3801 = local_368;
                                    phi_3901_ = (_e3801 + 1u);
                                } else {
                                    phi_3901_ = u32();
                                }
                                let _e3804 = phi_3901_;
                                continue;
                                continuing {
                                    let _e3805 = local_369;
                                    phi_3900_ = _e3804;
                                    phi_5042_ = _e3737;
                                    break if !(_e3805);
                                }
                            }
                            let _e3808 = phi_5042_;
                            phi_5055_ = _e3808;
                            if _e3808 {
                                break;
                            }
                            storageBarrier();
                            workgroupBarrier();
                            phi_3994_ = 128u;
                            loop {
                                let _e3810 = phi_3994_;
                                local_375 = _e3810;
                                let _e3811 = local_375;
                                let _e3812 = (_e3811 > 0u);
                                local_376 = _e3812;
                                if _e3812 {
                                    let _e3813 = local;
                                    let _e3814 = local_375;
                                    if (_e3813 < _e3814) {
                                        let _e3816 = local_55;
                                        if _e3816 {
                                        } else {
                                            phi_5049_ = true;
                                            break;
                                        }
                                        let _e3817 = global_11[_e850];
                                        local_377 = _e3817;
                                        let _e3818 = local_54;
                                        let _e3819 = local_375;
                                        let _e3820 = (_e3818 + _e3819);
                                        local_378 = _e3820;
                                        if (_e3820 < 5888u) {
                                        } else {
                                            phi_5049_ = true;
                                            break;
                                        }
                                        let _e3822 = local_378;
                                        let _e3824 = global_11[_e3822];
                                        let _e3825 = local_377;
                                        let _e3827 = local_377;
                                        local_451 = select(_e3824, _e3827, (_e3825 > _e3824));
                                        let _e3829 = local_55;
                                        if _e3829 {
                                        } else {
                                            phi_5049_ = true;
                                            break;
                                        }
                                        let _e3830 = local_451;
                                        global_11[_e850] = _e3830;
                                    }
                                    storageBarrier();
                                    workgroupBarrier();
                                    let _e3831 = local_375;
                                    phi_3995_ = (_e3831 / 2u);
                                } else {
                                    phi_3995_ = u32();
                                }
                                let _e3834 = phi_3995_;
                                continue;
                                continuing {
                                    let _e3835 = local_376;
                                    phi_3994_ = _e3834;
                                    phi_5049_ = _e3808;
                                    break if !(_e3835);
                                }
                            }
                            let _e3838 = phi_5049_;
                            phi_5055_ = _e3838;
                            if _e3838 {
                                break;
                            }
                            let _e3839 = global_11[4352u];
                            storageBarrier();
                            workgroupBarrier();
                            let _e3840 = local_80;
                            phi_5057_ = _e3838;
                            phi_4039_ = (_e3840 + 256u);
                            phi_4040_ = _e3839;
                        }
                        let _e3843 = phi_5057_;
                        let _e3845 = phi_4039_;
                        let _e3847 = phi_4040_;
                        let _e3848 = local_82;
                        phi_5056_ = _e3843;
                        phi_636_ = _e3845;
                        phi_639_ = _e3847;
                        phi_4042_ = select(true, false, _e3848);
                    } else {
                        phi_5056_ = _e1011;
                        phi_636_ = u32();
                        phi_639_ = u32();
                        phi_4042_ = false;
                    }
                    let _e3851 = phi_5056_;
                    let _e3853 = phi_636_;
                    let _e3855 = phi_639_;
                    let _e3857 = phi_4042_;
                    local_379 = _e3857;
                    continue;
                    continuing {
                        let _e3858 = local_379;
                        phi_4765_ = _e3851;
                        phi_635_ = _e3853;
                        phi_638_ = _e3855;
                        phi_5055_ = _e3851;
                        break if !(_e3858);
                    }
                }
                let _e3861 = phi_5055_;
                if _e3861 {
                    break;
                }
                let _e3862 = local_33;
                if _e3862 {
                    break;
                }
                let _e3863 = local_33;
                if _e3863 {
                    break;
                }
                let _e3864 = local_67;
                if _e3864 {
                    let _e3865 = local_64;
                    let _e3866 = local_13;
                    let _e3867 = (_e3865 < _e3866);
                    local_380 = _e3867;
                    if _e3867 {
                        let _e3868 = local_65;
                        let _e3869 = local_14;
                        phi_4103_ = (_e3868 < _e3869);
                    } else {
                        phi_4103_ = bool();
                    }
                    let _e3872 = phi_4103_;
                    let _e3873 = local_380;
                    phi_4105_ = _e3872;
                    phi_4106_ = select(true, false, _e3873);
                } else {
                    phi_4105_ = bool();
                    phi_4106_ = true;
                }
                let _e3876 = phi_4105_;
                let _e3878 = phi_4106_;
                if select(_e3876, false, _e3878) {
                    let _e3880 = local_65;
                    let _e3881 = local_13;
                    let _e3883 = local_64;
                    let _e3884 = ((_e3880 * _e3881) + _e3883);
                    local_381 = _e3884;
                    let _e3885 = (4u * _e3884);
                    local_382 = _e3885;
                    let _e3886 = local_1;
                    if (_e3885 < _e3886) {
                    } else {
                        break;
                    }
                    let _e3888 = local_382;
                    let _e3891 = global_4.member[_e3888];
                    local_383 = bitcast<f32>(_e3891);
                    let _e3893 = local_382;
                    let _e3894 = (_e3893 + 1u);
                    local_384 = _e3894;
                    let _e3895 = local_1;
                    if (_e3894 < _e3895) {
                    } else {
                        break;
                    }
                    let _e3897 = local_384;
                    let _e3900 = global_4.member[_e3897];
                    local_385 = bitcast<f32>(_e3900);
                    let _e3902 = local_382;
                    let _e3903 = (_e3902 + 2u);
                    local_386 = _e3903;
                    let _e3904 = local_1;
                    if (_e3903 < _e3904) {
                    } else {
                        break;
                    }
                    let _e3906 = local_386;
                    let _e3909 = global_4.member[_e3906];
                    local_387 = bitcast<f32>(_e3909);
                    let _e3911 = local_382;
                    let _e3912 = (_e3911 + 3u);
                    local_388 = _e3912;
                    let _e3913 = local_1;
                    if (_e3912 < _e3913) {
                    } else {
                        break;
                    }
                    let _e3915 = local_388;
                    let _e3918 = global_4.member[_e3915];
                    local_389 = bitcast<f32>(_e3918);
                    let _e3920 = local;
                    let _e3921 = (768u + _e3920);
                    local_390 = _e3921;
                    let _e3922 = (_e3921 < 5888u);
                    local_391 = _e3922;
                    if _e3922 {
                    } else {
                        break;
                    }
                    let _e3923 = local_390;
                    let _e3925 = global_11[_e3923];
                    local_392 = (1f - bitcast<f32>(_e3925));
                    let _e3928 = local_389;
                    if ((bitcast<u32>(_e3928) & 2147483647u) > 2139095040u) {
                    } else {
                        let _e3932 = local_392;
                        if (_e3932 > 0f) {
                            let _e3934 = local;
                            let _e3935 = (_e3934 < 5888u);
                            local_393 = _e3935;
                            if _e3935 {
                            } else {
                                break;
                            }
                            let _e3936 = local;
                            let _e3938 = global_11[_e3936];
                            let _e3940 = local_392;
                            let _e3941 = local_383;
                            local_394 = bitcast<u32>((bitcast<f32>(_e3938) + (_e3940 * _e3941)));
                            let _e3945 = local_393;
                            if _e3945 {
                            } else {
                                break;
                            }
                            let _e3946 = local_394;
                            global_11[_e3936] = _e3946;
                            let _e3947 = local;
                            let _e3948 = (256u + _e3947);
                            local_395 = _e3948;
                            let _e3949 = (_e3948 < 5888u);
                            local_396 = _e3949;
                            if _e3949 {
                            } else {
                                break;
                            }
                            let _e3950 = local_395;
                            let _e3952 = global_11[_e3950];
                            let _e3954 = local_392;
                            let _e3955 = local_385;
                            local_397 = bitcast<u32>((bitcast<f32>(_e3952) + (_e3954 * _e3955)));
                            let _e3959 = local_396;
                            if _e3959 {
                            } else {
                                break;
                            }
                            let _e3960 = local_397;
                            global_11[_e3950] = _e3960;
                            let _e3961 = local;
                            let _e3962 = (512u + _e3961);
                            local_398 = _e3962;
                            let _e3963 = (_e3962 < 5888u);
                            local_399 = _e3963;
                            if _e3963 {
                            } else {
                                break;
                            }
                            let _e3964 = local_398;
                            let _e3966 = global_11[_e3964];
                            let _e3968 = local_392;
                            let _e3969 = local_387;
                            local_400 = bitcast<u32>((bitcast<f32>(_e3966) + (_e3968 * _e3969)));
                            let _e3973 = local_399;
                            if _e3973 {
                            } else {
                                break;
                            }
                            let _e3974 = local_400;
                            global_11[_e3964] = _e3974;
                            let _e3975 = local_391;
                            if _e3975 {
                            } else {
                                break;
                            }
                            let _e3976 = global_11[_e3923];
                            let _e3978 = local_392;
                            local_401 = bitcast<u32>((bitcast<f32>(_e3976) + _e3978));
                            let _e3981 = local_391;
                            if _e3981 {
                            } else {
                                break;
                            }
                            let _e3982 = local_401;
                            global_11[_e3923] = _e3982;
                        }
                    }
                    let _e3983 = local_391;
                    if _e3983 {
                    } else {
                        break;
                    }
                    let _e3984 = global_11[_e3923];
                    let _e3985 = bitcast<f32>(_e3984);
                    local_402 = _e3985;
                    if (_e3985 > 0.000001f) {
                        let _e3987 = local_402;
                        phi_4263_ = (1f / _e3987);
                    } else {
                        phi_4263_ = 0f;
                    }
                    let _e3990 = phi_4263_;
                    local_403 = _e3990;
                    let _e3991 = local;
                    if (_e3991 < 5888u) {
                    } else {
                        break;
                    }
                    let _e3993 = local;
                    let _e3995 = global_11[_e3993];
                    let _e3997 = local_403;
                    local_404 = (bitcast<f32>(_e3995) * _e3997);
                    let _e3999 = local;
                    let _e4000 = (256u + _e3999);
                    local_405 = _e4000;
                    if (_e4000 < 5888u) {
                    } else {
                        break;
                    }
                    let _e4002 = local_405;
                    let _e4004 = global_11[_e4002];
                    let _e4006 = local_403;
                    local_406 = (bitcast<f32>(_e4004) * _e4006);
                    let _e4008 = local;
                    let _e4009 = (512u + _e4008);
                    local_407 = _e4009;
                    if (_e4009 < 5888u) {
                    } else {
                        break;
                    }
                    let _e4011 = local_407;
                    let _e4013 = global_11[_e4011];
                    let _e4015 = local_403;
                    local_408 = (bitcast<f32>(_e4013) * _e4015);
                    let _e4017 = local_381;
                    let _e4018 = (3u * _e4017);
                    local_409 = _e4018;
                    let _e4019 = local_404;
                    local_410 = bitcast<u32>(_e4019);
                    let _e4021 = local_6;
                    if (_e4018 < _e4021) {
                    } else {
                        break;
                    }
                    let _e4023 = local_409;
                    let _e4026 = local_410;
                    global_2.member[_e4023] = _e4026;
                    let _e4027 = local_409;
                    let _e4028 = (_e4027 + 1u);
                    local_411 = _e4028;
                    let _e4029 = local_406;
                    local_412 = bitcast<u32>(_e4029);
                    let _e4031 = local_6;
                    if (_e4028 < _e4031) {
                    } else {
                        break;
                    }
                    let _e4033 = local_411;
                    let _e4036 = local_412;
                    global_2.member[_e4033] = _e4036;
                    let _e4037 = local_409;
                    let _e4038 = (_e4037 + 2u);
                    local_413 = _e4038;
                    let _e4039 = local_408;
                    local_414 = bitcast<u32>(_e4039);
                    let _e4041 = local_6;
                    if (_e4038 < _e4041) {
                    } else {
                        break;
                    }
                    let _e4043 = local_413;
                    let _e4046 = local_414;
                    global_2.member[_e4043] = _e4046;
                }
                storageBarrier();
                workgroupBarrier();
                phi_4328_ = _e563;
                phi_4331_ = 0u;
                phi_4333_ = 0u;
                loop {
                    let _e4048 = phi_4328_;
                    let _e4050 = phi_4331_;
                    let _e4052 = phi_4333_;
                    local_415 = _e4048;
                    local_416 = _e4050;
                    local_417 = _e4052;
                    let _e4053 = local;
                    let _e4055 = local_415;
                    let _e4056 = (_e4055 < (_e4053 + 1u));
                    local_418 = _e4056;
                    if _e4056 {
                        let _e4057 = local_415;
                        let _e4058 = (1280u + _e4057);
                        local_419 = _e4058;
                        if (_e4058 < 5888u) {
                        } else {
                            phi_5058_ = true;
                            break;
                        }
                        let _e4060 = local_419;
                        let _e4062 = global_11[_e4060];
                        local_420 = _e4062;
                        let _e4063 = local_33;
                        if _e4063 {
                            phi_5058_ = true;
                            break;
                        }
                        let _e4064 = local_415;
                        let _e4065 = local_441;
                        let _e4067 = local_40;
                        local_421 = (_e4067 + (_e4064 % _e4065));
                        let _e4069 = local_33;
                        if _e4069 {
                            phi_5058_ = true;
                            break;
                        }
                        let _e4070 = local_415;
                        let _e4071 = local_441;
                        let _e4073 = local_42;
                        local_422 = (_e4073 + (_e4070 / _e4071));
                        let _e4075 = local_415;
                        let _e4076 = local_66;
                        if (_e4075 < _e4076) {
                            let _e4078 = local_421;
                            let _e4079 = local_13;
                            let _e4080 = (_e4078 < _e4079);
                            local_423 = _e4080;
                            if _e4080 {
                                let _e4081 = local_422;
                                let _e4082 = local_14;
                                phi_4406_ = (_e4081 < _e4082);
                            } else {
                                phi_4406_ = bool();
                            }
                            let _e4085 = phi_4406_;
                            let _e4086 = local_423;
                            phi_4408_ = _e4085;
                            phi_4409_ = select(true, false, _e4086);
                        } else {
                            phi_4408_ = bool();
                            phi_4409_ = true;
                        }
                        let _e4089 = phi_4408_;
                        let _e4091 = phi_4409_;
                        if select(_e4089, false, _e4091) {
                            let _e4093 = local_420;
                            let _e4094 = local_48;
                            if (_e4093 < _e4094) {
                                let _e4096 = local_417;
                                let _e4098 = local_48;
                                let _e4099 = local_420;
                                let _e4101 = local_416;
                                phi_4424_ = (_e4101 + (_e4098 - _e4099));
                                phi_4425_ = (_e4096 + 1u);
                            } else {
                                phi_4424_ = _e4050;
                                phi_4425_ = _e4052;
                            }
                            let _e4104 = phi_4424_;
                            let _e4106 = phi_4425_;
                            phi_4426_ = _e4104;
                            phi_4427_ = _e4106;
                        } else {
                            phi_4426_ = _e4050;
                            phi_4427_ = _e4052;
                        }
                        let _e4108 = phi_4426_;
                        let _e4110 = phi_4427_;
                        let _e4111 = local_415;
                        phi_4329_ = (_e4111 + 1u);
                        phi_4332_ = _e4108;
                        phi_4334_ = _e4110;
                    } else {
                        phi_4329_ = u32();
                        phi_4332_ = u32();
                        phi_4334_ = u32();
                    }
                    let _e4114 = phi_4329_;
                    let _e4116 = phi_4332_;
                    let _e4118 = phi_4334_;
                    continue;
                    continuing {
                        let _e4119 = local_418;
                        phi_4328_ = _e4114;
                        phi_4331_ = _e4116;
                        phi_4333_ = _e4118;
                        phi_5058_ = _e3861;
                        break if !(_e4119);
                    }
                }
                let _e4122 = phi_5058_;
                if _e4122 {
                    break;
                }
                let _e4123 = local_417;
                if (_e4123 > 0u) {
                    let _e4125 = local_7;
                    if (9u < _e4125) {
                    } else {
                        break;
                    }
                    let _e4129 = local_417;
                    let _e4130 = atomicAdd((&global_9.member[9u]), _e4129);
                    let _e4131 = local_7;
                    if (10u < _e4131) {
                    } else {
                        break;
                    }
                    let _e4135 = local_416;
                    let _e4136 = atomicAdd((&global_9.member[10u]), _e4135);
                }
                storageBarrier();
                workgroupBarrier();
            } else {
                let _e674 = local_33;
                if _e674 {
                    break;
                }
                let _e675 = local;
                let _e676 = local_441;
                let _e678 = local_40;
                local_424 = (_e678 + (_e675 % _e676));
                let _e680 = local_33;
                if _e680 {
                    break;
                }
                let _e681 = local;
                let _e682 = local_441;
                let _e684 = local_42;
                local_425 = (_e684 + (_e681 / _e682));
                let _e686 = local_441;
                let _e687 = local_441;
                let _e689 = local;
                if (_e689 < (_e686 * _e687)) {
                    let _e691 = local_424;
                    let _e692 = local_13;
                    let _e693 = (_e691 < _e692);
                    local_426 = _e693;
                    if _e693 {
                        let _e694 = local_425;
                        let _e695 = local_14;
                        phi_4503_ = (_e694 < _e695);
                    } else {
                        phi_4503_ = bool();
                    }
                    let _e698 = phi_4503_;
                    let _e699 = local_426;
                    phi_4505_ = _e698;
                    phi_4506_ = select(true, false, _e699);
                } else {
                    phi_4505_ = bool();
                    phi_4506_ = true;
                }
                let _e702 = phi_4505_;
                let _e704 = phi_4506_;
                if select(_e702, false, _e704) {
                    let _e706 = local_425;
                    let _e707 = local_13;
                    let _e709 = local_424;
                    let _e710 = ((_e706 * _e707) + _e709);
                    local_427 = _e710;
                    let _e711 = (4u * _e710);
                    local_428 = _e711;
                    let _e712 = local_1;
                    if (_e711 < _e712) {
                    } else {
                        break;
                    }
                    let _e714 = local_428;
                    let _e717 = global_4.member[_e714];
                    local_429 = bitcast<f32>(_e717);
                    let _e719 = local_428;
                    let _e720 = (_e719 + 1u);
                    local_430 = _e720;
                    let _e721 = local_1;
                    if (_e720 < _e721) {
                    } else {
                        break;
                    }
                    let _e723 = local_430;
                    let _e726 = global_4.member[_e723];
                    local_431 = bitcast<f32>(_e726);
                    let _e728 = local_428;
                    let _e729 = (_e728 + 2u);
                    local_432 = _e729;
                    let _e730 = local_1;
                    if (_e729 < _e730) {
                    } else {
                        break;
                    }
                    let _e732 = local_432;
                    let _e735 = global_4.member[_e732];
                    let _e737 = local_429;
                    let _e738 = local_431;
                    let _e740 = local_428;
                    let _e741 = (_e740 + 3u);
                    local_433 = _e741;
                    let _e742 = local_1;
                    if (_e741 < _e742) {
                    } else {
                        break;
                    }
                    let _e744 = local_433;
                    let _e747 = global_4.member[_e744];
                    if ((bitcast<u32>(bitcast<f32>(_e747)) & 2147483647u) > 2139095040u) {
                        phi_4561_ = array<f32, 3>(0f, 0f, 0f);
                    } else {
                        phi_4561_ = array<f32, 3>(_e737, _e738, bitcast<f32>(_e735));
                    }
                    let _e753 = phi_4561_;
                    local_434 = _e753;
                    let _e754 = local_427;
                    let _e755 = (3u * _e754);
                    local_435 = _e755;
                    local_436 = bitcast<u32>(_e753[0]);
                    let _e758 = local_6;
                    if (_e755 < _e758) {
                    } else {
                        break;
                    }
                    let _e760 = local_435;
                    let _e763 = local_436;
                    global_2.member[_e760] = _e763;
                    let _e764 = local_435;
                    let _e765 = (_e764 + 1u);
                    local_437 = _e765;
                    let _e766 = local_434;
                    local_438 = bitcast<u32>(_e766[1]);
                    let _e769 = local_6;
                    if (_e765 < _e769) {
                    } else {
                        break;
                    }
                    let _e771 = local_437;
                    let _e774 = local_438;
                    global_2.member[_e771] = _e774;
                    let _e775 = local_435;
                    let _e776 = (_e775 + 2u);
                    local_439 = _e776;
                    let _e777 = local_434;
                    local_440 = bitcast<u32>(_e777[2]);
                    let _e780 = local_6;
                    if (_e776 < _e780) {
                    } else {
                        break;
                    }
                    let _e782 = local_439;
                    let _e785 = local_440;
                    global_2.member[_e782] = _e785;
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
fn splat_accumulate(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
