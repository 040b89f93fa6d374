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
    member_16: type_16,
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
                                        let _e1833 = local_32;
                                        if (_e1833 > 0u) {
                                            let _e1847 = local_130;
                                            let _e1849 = local_443;
                                            let _e1850 = (_e1849 - (0.5f * _e1847));
                                            let _e1851 = local_31;
                                            phi_987_ = ((_e1851 * _e1850) * _e1850);
                                        } else {
                                            let _e1835 = local_443;
                                            let _e1836 = local_130;
                                            let _e1838 = local_443;
                                            let _e1840 = local_130;
                                            let _e1841 = local_130;
                                            let _e1845 = local_31;
                                            phi_987_ = (_e1845 * (((_e1835 - _e1836) * _e1838) + ((_e1840 * _e1841) * 0.33333334f)));
                                        }
                                        let _e1855 = phi_987_;
                                        phi_4829_ = _e1011;
                                        phi_1510_ = _e1855;
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
                                                            let _e1770 = local_443;
                                                            let _e1771 = local_130;
                                                            let _e1772 = (_e1770 - _e1771);
                                                            let _e1775 = local_139;
                                                            let _e1778 = local_139;
                                                            let _e1780 = local_443;
                                                            let _e1782 = local_130;
                                                            let _e1784 = ((_e1780 - sqrt(_e1778)) * (1f / _e1782));
                                                            phi_1488_ = select(select(0f, select(1f, _e1784, (_e1784 < 1f)), (0f < _e1784)), 1f, ((0f < _e1772) && (_e1775 <= (_e1772 * _e1772))));
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
                                                                let _e1748 = local_443;
                                                                let _e1749 = local_130;
                                                                let _e1750 = (_e1748 - _e1749);
                                                                let _e1753 = local_139;
                                                                let _e1756 = local_139;
                                                                let _e1758 = local_443;
                                                                let _e1760 = local_130;
                                                                let _e1762 = ((_e1758 - sqrt(_e1756)) * (1f / _e1760));
                                                                phi_1487_ = select(select(0f, select(1f, _e1762, (_e1762 < 1f)), (0f < _e1762)), 1f, ((0f < _e1750) && (_e1753 <= (_e1750 * _e1750))));
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
                                                                                                        let _e1516 = local_149;
                                                                                                        let _e1520 = local_32;
                                                                                                        let _e1522 = local_148;
                                                                                                        let _e1524 = local_148;
                                                                                                        let _e1526 = local_148;
                                                                                                        let _e1530 = ((select(select(u32(_e1512), 0u, (_e1514 < 0f)), 4294967295u, (_e1516 > 4294967000f)) * _e1520) + select(select(u32(_e1522), 0u, (_e1524 < 0f)), 4294967295u, (_e1526 > 4294967000f)));
                                                                                                        local_153 = _e1530;
                                                                                                        let _e1531 = local_8;
                                                                                                        if (_e1530 < _e1531) {
                                                                                                        } else {
                                                                                                            phi_4744_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1533 = local_153;
                                                                                                        let _e1536 = global_10.member[_e1533];
                                                                                                        phi_1195_ = bitcast<f32>(_e1536);
                                                                                                    }
                                                                                                    let _e1539 = phi_1195_;
                                                                                                    phi_1196_ = _e1539;
                                                                                                    phi_1197_ = _e1511;
                                                                                                }
                                                                                                let _e1541 = phi_1196_;
                                                                                                let _e1543 = phi_1197_;
                                                                                                phi_1198_ = _e1541;
                                                                                                phi_1199_ = _e1543;
                                                                                            }
                                                                                            let _e1545 = phi_1198_;
                                                                                            let _e1547 = phi_1199_;
                                                                                            phi_1200_ = _e1545;
                                                                                            phi_1201_ = _e1547;
                                                                                        }
                                                                                        let _e1549 = phi_1200_;
                                                                                        let _e1551 = phi_1201_;
                                                                                        let _e1553 = local_150;
                                                                                        let _e1554 = (1f - _e1553);
                                                                                        local_154 = _e1554;
                                                                                        local_155 = (select(_e1549, 0f, _e1551) * _e1554);
                                                                                        let _e1556 = local_148;
                                                                                        let _e1557 = (_e1556 + 1f);
                                                                                        local_156 = _e1557;
                                                                                        let _e1558 = (_e1557 < 0f);
                                                                                        local_157 = _e1558;
                                                                                        if _e1558 {
                                                                                            phi_1256_ = f32();
                                                                                            phi_1257_ = true;
                                                                                        } else {
                                                                                            let _e1559 = local_149;
                                                                                            if (_e1559 < 0f) {
                                                                                                phi_1254_ = f32();
                                                                                                phi_1255_ = true;
                                                                                            } else {
                                                                                                let _e1561 = local_156;
                                                                                                let _e1562 = local_144;
                                                                                                if (_e1561 >= _e1562) {
                                                                                                    phi_1252_ = f32();
                                                                                                    phi_1253_ = true;
                                                                                                } else {
                                                                                                    let _e1564 = local_149;
                                                                                                    let _e1565 = local_144;
                                                                                                    let _e1566 = (_e1564 >= _e1565);
                                                                                                    if _e1566 {
                                                                                                        phi_1251_ = f32();
                                                                                                    } else {
                                                                                                        let _e1567 = local_149;
                                                                                                        let _e1569 = local_149;
                                                                                                        let _e1571 = local_149;
                                                                                                        let _e1575 = local_32;
                                                                                                        let _e1577 = local_156;
                                                                                                        let _e1579 = local_156;
                                                                                                        let _e1581 = local_156;
                                                                                                        let _e1585 = ((select(select(u32(_e1567), 0u, (_e1569 < 0f)), 4294967295u, (_e1571 > 4294967000f)) * _e1575) + select(select(u32(_e1577), 0u, (_e1579 < 0f)), 4294967295u, (_e1581 > 4294967000f)));
                                                                                                        local_158 = _e1585;
                                                                                                        let _e1586 = local_8;
                                                                                                        if (_e1585 < _e1586) {
                                                                                                        } else {
                                                                                                            phi_4744_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1588 = local_158;
                                                                                                        let _e1591 = global_10.member[_e1588];
                                                                                                        phi_1251_ = bitcast<f32>(_e1591);
                                                                                                    }
                                                                                                    let _e1594 = phi_1251_;
                                                                                                    phi_1252_ = _e1594;
                                                                                                    phi_1253_ = _e1566;
                                                                                                }
                                                                                                let _e1596 = phi_1252_;
                                                                                                let _e1598 = phi_1253_;
                                                                                                phi_1254_ = _e1596;
                                                                                                phi_1255_ = _e1598;
                                                                                            }
                                                                                            let _e1600 = phi_1254_;
                                                                                            let _e1602 = phi_1255_;
                                                                                            phi_1256_ = _e1600;
                                                                                            phi_1257_ = _e1602;
                                                                                        }
                                                                                        let _e1604 = phi_1256_;
                                                                                        let _e1606 = phi_1257_;
                                                                                        let _e1608 = local_150;
                                                                                        let _e1610 = local_155;
                                                                                        local_159 = (_e1610 + (select(_e1604, 0f, _e1606) * _e1608));
                                                                                        let _e1612 = local_149;
                                                                                        local_160 = (_e1612 + 1f);
                                                                                        let _e1614 = local_152;
                                                                                        if _e1614 {
                                                                                            phi_1312_ = f32();
                                                                                            phi_1313_ = true;
                                                                                        } else {
                                                                                            let _e1615 = local_160;
                                                                                            if (_e1615 < 0f) {
                                                                                                phi_1310_ = f32();
                                                                                                phi_1311_ = true;
                                                                                            } else {
                                                                                                let _e1617 = local_148;
                                                                                                let _e1618 = local_144;
                                                                                                if (_e1617 >= _e1618) {
                                                                                                    phi_1308_ = f32();
                                                                                                    phi_1309_ = true;
                                                                                                } else {
                                                                                                    let _e1620 = local_160;
                                                                                                    let _e1621 = local_144;
                                                                                                    let _e1622 = (_e1620 >= _e1621);
                                                                                                    if _e1622 {
                                                                                                        phi_1307_ = f32();
                                                                                                    } else {
                                                                                                        let _e1623 = local_160;
                                                                                                        let _e1625 = local_160;
                                                                                                        let _e1627 = local_160;
                                                                                                        let _e1631 = local_32;
                                                                                                        let _e1633 = local_148;
                                                                                                        let _e1635 = local_148;
                                                                                                        let _e1637 = local_148;
                                                                                                        let _e1641 = ((select(select(u32(_e1623), 0u, (_e1625 < 0f)), 4294967295u, (_e1627 > 4294967000f)) * _e1631) + select(select(u32(_e1633), 0u, (_e1635 < 0f)), 4294967295u, (_e1637 > 4294967000f)));
                                                                                                        local_161 = _e1641;
                                                                                                        let _e1642 = local_8;
                                                                                                        if (_e1641 < _e1642) {
                                                                                                        } else {
                                                                                                            phi_4744_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1644 = local_161;
                                                                                                        let _e1647 = global_10.member[_e1644];
                                                                                                        phi_1307_ = bitcast<f32>(_e1647);
                                                                                                    }
                                                                                                    let _e1650 = phi_1307_;
                                                                                                    phi_1308_ = _e1650;
                                                                                                    phi_1309_ = _e1622;
                                                                                                }
                                                                                                let _e1652 = phi_1308_;
                                                                                                let _e1654 = phi_1309_;
                                                                                                phi_1310_ = _e1652;
                                                                                                phi_1311_ = _e1654;
                                                                                            }
                                                                                            let _e1656 = phi_1310_;
                                                                                            let _e1658 = phi_1311_;
                                                                                            phi_1312_ = _e1656;
                                                                                            phi_1313_ = _e1658;
                                                                                        }
                                                                                        let _e1660 = phi_1312_;
                                                                                        let _e1662 = phi_1313_;
                                                                                        let _e1664 = local_154;
                                                                                        local_162 = (select(_e1660, 0f, _e1662) * _e1664);
                                                                                        let _e1666 = local_157;
                                                                                        if _e1666 {
                                                                                            phi_1369_ = f32();
                                                                                            phi_1370_ = true;
                                                                                        } else {
                                                                                            let _e1667 = local_160;
                                                                                            if (_e1667 < 0f) {
                                                                                                phi_1367_ = f32();
                                                                                                phi_1368_ = true;
                                                                                            } else {
                                                                                                let _e1669 = local_156;
                                                                                                let _e1670 = local_144;
                                                                                                if (_e1669 >= _e1670) {
                                                                                                    phi_1365_ = f32();
                                                                                                    phi_1366_ = true;
                                                                                                } else {
                                                                                                    let _e1672 = local_160;
                                                                                                    let _e1673 = local_144;
                                                                                                    let _e1674 = (_e1672 >= _e1673);
                                                                                                    if _e1674 {
                                                                                                        phi_1364_ = f32();
                                                                                                    } else {
                                                                                                        let _e1675 = local_160;
                                                                                                        let _e1677 = local_160;
                                                                                                        let _e1679 = local_160;
                                                                                                        let _e1683 = local_32;
                                                                                                        let _e1685 = local_156;
                                                                                                        let _e1687 = local_156;
                                                                                                        let _e1689 = local_156;
                                                                                                        let _e1693 = ((select(select(u32(_e1675), 0u, (_e1677 < 0f)), 4294967295u, (_e1679 > 4294967000f)) * _e1683) + select(select(u32(_e1685), 0u, (_e1687 < 0f)), 4294967295u, (_e1689 > 4294967000f)));
                                                                                                        local_163 = _e1693;
                                                                                                        let _e1694 = local_8;
                                                                                                        if (_e1693 < _e1694) {
                                                                                                        } else {
                                                                                                            phi_4744_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1696 = local_163;
                                                                                                        let _e1699 = global_10.member[_e1696];
                                                                                                        phi_1364_ = bitcast<f32>(_e1699);
                                                                                                    }
                                                                                                    let _e1702 = phi_1364_;
                                                                                                    phi_1365_ = _e1702;
                                                                                                    phi_1366_ = _e1674;
                                                                                                }
                                                                                                let _e1704 = phi_1365_;
                                                                                                let _e1706 = phi_1366_;
                                                                                                phi_1367_ = _e1704;
                                                                                                phi_1368_ = _e1706;
                                                                                            }
                                                                                            let _e1708 = phi_1367_;
                                                                                            let _e1710 = phi_1368_;
                                                                                            phi_1369_ = _e1708;
                                                                                            phi_1370_ = _e1710;
                                                                                        }
                                                                                        let _e1712 = phi_1369_;
                                                                                        let _e1714 = phi_1370_;
                                                                                        let _e1716 = local_150;
                                                                                        let _e1718 = local_162;
                                                                                        let _e1720 = local_151;
                                                                                        let _e1722 = local_159;
                                                                                        let _e1724 = local_151;
                                                                                        phi_1381_ = ((_e1722 * (1f - _e1720)) + ((_e1718 + (select(_e1712, 0f, _e1714) * _e1716)) * _e1724));
                                                                                    } else {
                                                                                        phi_1381_ = f32();
                                                                                    }
                                                                                    let _e1728 = phi_1381_;
                                                                                    let _e1729 = local_147;
                                                                                    phi_1383_ = _e1728;
                                                                                    phi_1384_ = select(true, false, _e1729);
                                                                                } else {
                                                                                    phi_1383_ = f32();
                                                                                    phi_1384_ = true;
                                                                                }
                                                                                let _e1732 = phi_1383_;
                                                                                let _e1734 = phi_1384_;
                                                                                phi_1385_ = _e1732;
                                                                                phi_1386_ = _e1734;
                                                                            } else {
                                                                                phi_1385_ = f32();
                                                                                phi_1386_ = true;
                                                                            }
                                                                            let _e1736 = phi_1385_;
                                                                            let _e1738 = phi_1386_;
                                                                            phi_1387_ = _e1736;
                                                                            phi_1388_ = _e1738;
                                                                        } else {
                                                                            phi_1387_ = f32();
                                                                            phi_1388_ = true;
                                                                        }
                                                                        let _e1740 = phi_1387_;
                                                                        let _e1742 = phi_1388_;
                                                                        phi_1393_ = select(_e1740, 0f, _e1742);
                                                                    } else {
                                                                        phi_1393_ = 0f;
                                                                    }
                                                                    let _e1745 = phi_1393_;
                                                                    phi_1486_ = _e1745;
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
                                                                let _e1747 = phi_1486_;
                                                                phi_1487_ = _e1747;
                                                            }
                                                            let _e1769 = phi_1487_;
                                                            phi_1488_ = _e1769;
                                                        }
                                                        let _e1791 = phi_1488_;
                                                        let _e1792 = local_137;
                                                        local_445 = select(0f, _e1791, _e1792);
                                                        phi_1494_ = 0u;
                                                        phi_1497_ = _e1352;
                                                        loop {
                                                            let _e1795 = phi_1494_;
                                                            let _e1797 = phi_1497_;
                                                            local_169 = _e1795;
                                                            local_170 = _e1797;
                                                            local_458 = _e1797;
                                                            let _e1798 = local_169;
                                                            let _e1799 = (_e1798 < 1u);
                                                            local_171 = _e1799;
                                                            if _e1799 {
                                                                let _e1800 = local_170;
                                                                let _e1801 = local_445;
                                                                let _e1803 = local_169;
                                                                phi_1495_ = (_e1803 + 1u);
                                                                phi_1498_ = (_e1800 + _e1801);
                                                            } else {
                                                                phi_1495_ = u32();
                                                                phi_1498_ = f32();
                                                            }
                                                            let _e1806 = phi_1495_;
                                                            let _e1808 = phi_1498_;
                                                            continue;
                                                            continuing {
                                                                let _e1809 = local_171;
                                                                phi_1494_ = _e1806;
                                                                phi_1497_ = _e1808;
                                                                break if !(_e1809);
                                                            }
                                                        }
                                                        let _e1811 = local_136;
                                                        phi_1017_ = (_e1811 + 1f);
                                                        let _e4215 = local_458;
                                                        phi_1020_ = _e4215;
                                                    } else {
                                                        phi_1017_ = f32();
                                                        phi_1020_ = f32();
                                                    }
                                                    let _e1814 = phi_1017_;
                                                    let _e1816 = phi_1020_;
                                                    continue;
                                                    continuing {
                                                        let _e1817 = local_137;
                                                        phi_1016_ = _e1814;
                                                        phi_1019_ = _e1816;
                                                        phi_4744_ = _e1337;
                                                        break if !(_e1817);
                                                    }
                                                }
                                                let _e1820 = phi_4744_;
                                                phi_4811_ = _e1820;
                                                if _e1820 {
                                                    break;
                                                }
                                                let _e1821 = local_133;
                                                phi_4812_ = _e1820;
                                                phi_1003_ = (_e1821 + 1f);
                                                let _e4221 = local_459;
                                                phi_1006_ = _e4221;
                                            } else {
                                                phi_4812_ = _e1337;
                                                phi_1003_ = f32();
                                                phi_1006_ = f32();
                                            }
                                            let _e1824 = phi_4812_;
                                            let _e1826 = phi_1003_;
                                            let _e1828 = phi_1006_;
                                            continue;
                                            continuing {
                                                let _e1829 = local_134;
                                                phi_4755_ = _e1824;
                                                phi_1002_ = _e1826;
                                                phi_1005_ = _e1828;
                                                phi_4811_ = _e1824;
                                                break if !(_e1829);
                                            }
                                        }
                                        let _e1832 = phi_4811_;
                                        phi_5055_ = _e1832;
                                        if _e1832 {
                                            break;
                                        }
                                        phi_4829_ = _e1832;
                                        let _e4227 = local_460;
                                        phi_1510_ = _e4227;
                                    }
                                    let _e1857 = phi_4829_;
                                    let _e1859 = phi_1510_;
                                    let _e1860 = local_129;
                                    phi_4828_ = _e1857;
                                    phi_1512_ = (_e1860 / _e1859);
                                }
                                let _e1863 = phi_4828_;
                                let _e1865 = phi_1512_;
                                local_172 = _e1865;
                                phi_1514_ = 0u;
                                loop {
                                    let _e1867 = phi_1514_;
                                    local_173 = _e1867;
                                    let _e1868 = local_173;
                                    let _e1869 = local_44;
                                    if (_e1868 < _e1869) {
                                        let _e1871 = local_173;
                                        let _e1872 = (_e1871 + 1u);
                                        let _e1874 = local_16;
                                        let _e1879 = local_443;
                                        let _e1880 = (_e1879 >= f32((2u * (_e1874 << bitcast<u32>((_e1872 & 31u))))));
                                        phi_1515_ = select(u32(), _e1872, _e1880);
                                        phi_1536_ = _e1880;
                                    } else {
                                        phi_1515_ = u32();
                                        phi_1536_ = false;
                                    }
                                    let _e1883 = phi_1515_;
                                    let _e1885 = phi_1536_;
                                    local_174 = _e1885;
                                    continue;
                                    continuing {
                                        let _e1886 = local_174;
                                        phi_1514_ = _e1883;
                                        break if !(_e1886);
                                    }
                                }
                                let _e1888 = local_173;
                                let _e1894 = local_172;
                                local_175 = bitcast<u32>((_e1894 * f32((1u << bitcast<u32>(((2u * _e1888) & 31u))))));
                                let _e1897 = local;
                                let _e1898 = (2304u + _e1897);
                                local_176 = _e1898;
                                if (_e1898 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1900 = local_176;
                                let _e1902 = local_175;
                                global_11[_e1900] = _e1902;
                                let _e1903 = local;
                                let _e1904 = (5632u + _e1903);
                                local_177 = _e1904;
                                if (_e1904 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1906 = local_177;
                                let _e1908 = local_114;
                                global_11[_e1906] = _e1908;
                                let _e1909 = local_113;
                                local_178 = bitcast<u32>(f32((1u << bitcast<u32>((_e1909.member_4 & 31u)))));
                                let _e1916 = local;
                                let _e1917 = (3584u + _e1916);
                                local_179 = _e1917;
                                if (_e1917 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1919 = local_179;
                                let _e1921 = local_178;
                                global_11[_e1919] = _e1921;
                                let _e1922 = local_444;
                                local_180 = bitcast<u32>(_e1922);
                                let _e1924 = local;
                                let _e1925 = (3840u + _e1924);
                                local_181 = _e1925;
                                if (_e1925 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1927 = local_181;
                                let _e1929 = local_180;
                                global_11[_e1927] = _e1929;
                                let _e1930 = local_113;
                                local_182 = bitcast<u32>(_e1930.member_2);
                                let _e1933 = local;
                                let _e1934 = (4096u + _e1933);
                                local_183 = _e1934;
                                if (_e1934 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1936 = local_183;
                                let _e1938 = local_182;
                                global_11[_e1936] = _e1938;
                                let _e1939 = local_113;
                                local_184 = bitcast<u32>(_e1939.member_1[0]);
                                let _e1943 = local;
                                let _e1944 = (2560u + _e1943);
                                local_185 = _e1944;
                                if (_e1944 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1946 = local_185;
                                let _e1948 = local_184;
                                global_11[_e1946] = _e1948;
                                let _e1949 = local_113;
                                local_186 = bitcast<u32>(_e1949.member_1[1]);
                                let _e1953 = local;
                                let _e1954 = (2816u + _e1953);
                                local_187 = _e1954;
                                if (_e1954 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1956 = local_187;
                                let _e1958 = local_186;
                                global_11[_e1956] = _e1958;
                                let _e1959 = local_113;
                                local_188 = bitcast<u32>(_e1959.member_1[2]);
                                let _e1963 = local;
                                let _e1964 = (3072u + _e1963);
                                local_189 = _e1964;
                                if (_e1964 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1966 = local_189;
                                let _e1968 = local_188;
                                global_11[_e1966] = _e1968;
                                let _e1969 = local;
                                let _e1970 = (3328u + _e1969);
                                local_190 = _e1970;
                                if (_e1970 < 5888u) {
                                } else {
                                    phi_5055_ = true;
                                    break;
                                }
                                let _e1972 = local_190;
                                let _e1974 = local_118;
                                global_11[_e1972] = _e1974;
                                phi_4824_ = _e1863;
                            } else {
                                phi_4824_ = _e1011;
                            }
                            let _e1976 = phi_4824_;
                            storageBarrier();
                            workgroupBarrier();
                            let _e1977 = local_48;
                            let _e1978 = local_80;
                            let _e1979 = (_e1977 - _e1978);
                            let _e1981 = select(256u, _e1979, (_e1979 < 256u));
                            local_446 = _e1981;
                            local_457[0u] = false;
                            phi_1641_ = 0u;
                            loop {
                                let _e1984 = phi_1641_;
                                local_191 = _e1984;
                                let _e1985 = local_191;
                                let _e1986 = (_e1985 < 1u);
                                local_192 = _e1986;
                                if _e1986 {
                                    let _e1987 = local;
                                    let _e1988 = local_191;
                                    local_193 = (_e1987 + _e1988);
                                    let _e1990 = local_33;
                                    if _e1990 {
                                        phi_4813_ = true;
                                        break;
                                    }
                                    let _e1991 = local_193;
                                    let _e1992 = local_441;
                                    let _e1994 = local_40;
                                    local_194 = (_e1994 + (_e1991 % _e1992));
                                    let _e1996 = local_33;
                                    if _e1996 {
                                        phi_4813_ = true;
                                        break;
                                    }
                                    let _e1997 = local_193;
                                    let _e1998 = local_441;
                                    let _e2000 = local_42;
                                    local_195 = (_e2000 + (_e1997 / _e1998));
                                    let _e2002 = local_193;
                                    let _e2003 = local_66;
                                    if (_e2002 < _e2003) {
                                        let _e2005 = local_194;
                                        let _e2006 = local_13;
                                        let _e2007 = (_e2005 < _e2006);
                                        local_196 = _e2007;
                                        if _e2007 {
                                            let _e2008 = local_195;
                                            let _e2009 = local_14;
                                            phi_1707_ = (_e2008 < _e2009);
                                        } else {
                                            phi_1707_ = bool();
                                        }
                                        let _e2012 = phi_1707_;
                                        let _e2013 = local_196;
                                        phi_1709_ = _e2012;
                                        phi_1710_ = select(true, false, _e2013);
                                    } else {
                                        phi_1709_ = bool();
                                        phi_1710_ = true;
                                    }
                                    let _e2016 = phi_1709_;
                                    let _e2018 = phi_1710_;
                                    local_447 = select(_e2016, false, _e2018);
                                    let _e2020 = local_192;
                                    if _e2020 {
                                    } else {
                                        phi_4813_ = true;
                                        break;
                                    }
                                    let _e2021 = local_191;
                                    let _e2023 = local_447;
                                    local_457[_e2021] = _e2023;
                                    let _e2024 = local_191;
                                    phi_1642_ = (_e2024 + 1u);
                                } else {
                                    phi_1642_ = u32();
                                }
                                let _e2027 = phi_1642_;
                                continue;
                                continuing {
                                    let _e2028 = local_192;
                                    phi_1641_ = _e2027;
                                    phi_4813_ = _e1976;
                                    break if !(_e2028);
                                }
                            }
                            let _e2031 = phi_4813_;
                            phi_5055_ = _e2031;
                            if _e2031 {
                                break;
                            }
                            let _e2032 = local_457[0u];
                            local_454[0u] = _e2032;
                            let _e2034 = local_33;
                            if _e2034 {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2035 = local_33;
                            if _e2035 {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2036 = local_64;
                            local_197 = (f32(_e2036) + 0.5f);
                            let _e2039 = local_33;
                            if _e2039 {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2040 = local_33;
                            if _e2040 {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2041 = local_65;
                            local_198 = (f32(_e2041) + 0.5f);
                            let _e2044 = local;
                            let _e2045 = (768u + _e2044);
                            local_199 = _e2045;
                            if (_e2045 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2047 = local_199;
                            let _e2049 = global_11[_e2047];
                            let _e2050 = bitcast<f32>(_e2049);
                            local_200 = _e2050;
                            let _e2051 = local;
                            if (_e2051 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2053 = local;
                            let _e2055 = global_11[_e2053];
                            local_201 = bitcast<f32>(_e2055);
                            let _e2057 = local;
                            let _e2058 = (256u + _e2057);
                            local_202 = _e2058;
                            if (_e2058 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2060 = local_202;
                            let _e2062 = global_11[_e2060];
                            local_203 = bitcast<f32>(_e2062);
                            let _e2064 = local;
                            let _e2065 = (512u + _e2064);
                            local_204 = _e2065;
                            if (_e2065 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2067 = local_204;
                            let _e2069 = global_11[_e2067];
                            let _e2071 = local_201;
                            let _e2072 = local_203;
                            let _e2074 = local_73;
                            if (_e2074 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2076 = local_73;
                            let _e2078 = global_11[_e2076];
                            local_205 = bitcast<f32>(_e2078);
                            let _e2080 = local;
                            let _e2081 = (_e2080 + 4864u);
                            local_206 = _e2081;
                            if (_e2081 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2083 = local_206;
                            let _e2085 = global_11[_e2083];
                            local_207 = bitcast<f32>(_e2085);
                            let _e2087 = local;
                            let _e2088 = (_e2087 + 5120u);
                            local_208 = _e2088;
                            if (_e2088 < 5888u) {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2090 = local_208;
                            let _e2092 = global_11[_e2090];
                            local_209 = bitcast<f32>(_e2092);
                            let _e2094 = local;
                            let _e2095 = (_e2094 + 5376u);
                            local_210 = _e2095;
                            let _e2096 = (_e2095 < 5888u);
                            local_211 = _e2096;
                            if _e2096 {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2097 = local_210;
                            let _e2099 = global_11[_e2097];
                            local_212 = ((_e2099 & 1u) != 0u);
                            let _e2102 = local_211;
                            if _e2102 {
                            } else {
                                phi_5055_ = true;
                                break;
                            }
                            let _e2103 = global_11[_e2097];
                            let _e2106 = local_205;
                            let _e2107 = local_207;
                            let _e2108 = local_209;
                            let _e2109 = local_212;
                            local_453[0u] = false;
                            phi_1941_ = 0u;
                            loop {
                                let _e2113 = phi_1941_;
                                local_213 = _e2113;
                                let _e2114 = local_213;
                                let _e2115 = (_e2114 < 1u);
                                local_214 = _e2115;
                                if _e2115 {
                                    let _e2116 = local_214;
                                    if _e2116 {
                                    } else {
                                        phi_4831_ = true;
                                        break;
                                    }
                                    let _e2117 = local_213;
                                    let _e2119 = local_454[_e2117];
                                    if _e2119 {
                                        let _e2120 = local_200;
                                        phi_1962_ = (_e2120 < 0.99902344f);
                                    } else {
                                        phi_1962_ = false;
                                    }
                                    let _e2123 = phi_1962_;
                                    local_215 = _e2123;
                                    let _e2124 = local_214;
                                    if _e2124 {
                                    } else {
                                        phi_4831_ = true;
                                        break;
                                    }
                                    let _e2125 = local_213;
                                    let _e2127 = local_215;
                                    local_453[_e2125] = _e2127;
                                    let _e2128 = local_213;
                                    phi_1942_ = (_e2128 + 1u);
                                } else {
                                    phi_1942_ = u32();
                                }
                                let _e2131 = phi_1942_;
                                continue;
                                continuing {
                                    let _e2132 = local_214;
                                    phi_1941_ = _e2131;
                                    phi_4831_ = _e2031;
                                    break if !(_e2132);
                                }
                            }
                            let _e2135 = phi_4831_;
                            phi_5055_ = _e2135;
                            if _e2135 {
                                break;
                            }
                            let _e2136 = local_453[0u];
                            local_455[0u] = _e2136;
                            local_452[0u] = 0u;
                            phi_4843_ = _e2135;
                            phi_1975_ = 0u;
                            loop {
                                let _e2140 = phi_4843_;
                                let _e2142 = phi_1975_;
                                local_216 = _e2142;
                                let _e2143 = local_216;
                                let _e2144 = (_e2143 < 1u);
                                local_217 = _e2144;
                                if _e2144 {
                                    let _e2145 = local_217;
                                    if _e2145 {
                                    } else {
                                        phi_4844_ = true;
                                        break;
                                    }
                                    let _e2146 = local_216;
                                    let _e2148 = local_455[_e2146];
                                    if _e2148 {
                                        let _e2149 = local;
                                        let _e2150 = local_216;
                                        let _e2152 = (1024u + (_e2149 + _e2150));
                                        local_218 = _e2152;
                                        if (_e2152 < 5888u) {
                                        } else {
                                            phi_4844_ = true;
                                            break;
                                        }
                                        let _e2154 = local_218;
                                        let _e2156 = global_11[_e2154];
                                        local_219 = bitcast<f32>(_e2156);
                                        phi_2005_ = 0u;
                                        phi_2008_ = _e1981;
                                        loop {
                                            let _e2159 = phi_2005_;
                                            let _e2161 = phi_2008_;
                                            local_220 = _e2159;
                                            local_221 = _e2161;
                                            local_461 = _e2159;
                                            let _e2162 = local_220;
                                            let _e2163 = local_221;
                                            let _e2164 = (_e2162 < _e2163);
                                            local_222 = _e2164;
                                            if _e2164 {
                                                let _e2165 = local_220;
                                                let _e2166 = local_221;
                                                let _e2168 = ((_e2165 + _e2166) / 2u);
                                                local_223 = _e2168;
                                                let _e2169 = (3328u + _e2168);
                                                local_224 = _e2169;
                                                if (_e2169 < 5888u) {
                                                } else {
                                                    phi_4839_ = true;
                                                    break;
                                                }
                                                let _e2171 = local_224;
                                                let _e2173 = global_11[_e2171];
                                                let _e2175 = local_219;
                                                let _e2176 = (bitcast<f32>(_e2173) >= _e2175);
                                                local_225 = _e2176;
                                                if _e2176 {
                                                    phi_2032_ = _e2159;
                                                } else {
                                                    let _e2177 = local_223;
                                                    phi_2032_ = (_e2177 + 1u);
                                                }
                                                let _e2180 = phi_2032_;
                                                let _e2181 = local_225;
                                                let _e2182 = local_223;
                                                let _e2183 = local_221;
                                                phi_2006_ = _e2180;
                                                phi_2009_ = select(_e2183, _e2182, _e2181);
                                            } else {
                                                phi_2006_ = u32();
                                                phi_2009_ = u32();
                                            }
                                            let _e2186 = phi_2006_;
                                            let _e2188 = phi_2009_;
                                            continue;
                                            continuing {
                                                let _e2189 = local_222;
                                                phi_2005_ = _e2186;
                                                phi_2008_ = _e2188;
                                                phi_4839_ = _e2140;
                                                break if !(_e2189);
                                            }
                                        }
                                        let _e2192 = phi_4839_;
                                        phi_4844_ = _e2192;
                                        if _e2192 {
                                            break;
                                        }
                                        phi_4846_ = _e2192;
                                        let _e4255 = local_461;
                                        phi_2034_ = _e4255;
                                    } else {
                                        phi_4846_ = _e2140;
                                        phi_2034_ = 0u;
                                    }
                                    let _e2194 = phi_4846_;
                                    let _e2196 = phi_2034_;
                                    local_226 = _e2196;
                                    let _e2197 = local_217;
                                    if _e2197 {
                                    } else {
                                        phi_4844_ = true;
                                        break;
                                    }
                                    let _e2198 = local_216;
                                    let _e2200 = local_226;
                                    local_452[_e2198] = _e2200;
                                    let _e2201 = local_216;
                                    phi_4845_ = _e2194;
                                    phi_1976_ = (_e2201 + 1u);
                                } else {
                                    phi_4845_ = _e2140;
                                    phi_1976_ = u32();
                                }
                                let _e2204 = phi_4845_;
                                let _e2206 = phi_1976_;
                                continue;
                                continuing {
                                    let _e2207 = local_217;
                                    phi_4843_ = _e2204;
                                    phi_1975_ = _e2206;
                                    phi_4844_ = _e2204;
                                    break if !(_e2207);
                                }
                            }
                            let _e2210 = phi_4844_;
                            phi_5055_ = _e2210;
                            if _e2210 {
                                break;
                            }
                            let _e2211 = local_452[0u];
                            local_456[0u] = _e2211;
                            let _e2213 = local_456[0u];
                            let _e2214 = f32(_e2213);
                            let _e2215 = local_20;
                            local_227 = ((_e2215 >> bitcast<u32>(8u)) & 7u);
                            phi_4852_ = _e2210;
                            phi_2065_ = _e2050;
                            phi_2068_ = type_31(_e2106, _e2107, _e2108, _e2109, ((_e2103 & 2u) != 0u));
                            phi_2070_ = 0u;
                            phi_2072_ = select(select(u32(_e2214), 0u, (_e2214 < 0f)), 4294967295u, (_e2214 > 4294967000f));
                            phi_2074_ = _e2214;
                            phi_2076_ = 0f;
                            phi_2078_ = false;
                            phi_2080_ = array<f32, 3>(_e2071, _e2072, bitcast<f32>(_e2069));
                            loop {
                                let _e2225 = phi_4852_;
                                let _e2227 = phi_2065_;
                                let _e2229 = phi_2068_;
                                let _e2231 = phi_2070_;
                                let _e2233 = phi_2072_;
                                let _e2235 = phi_2074_;
                                let _e2237 = phi_2076_;
                                let _e2239 = phi_2078_;
                                let _e2241 = phi_2080_;
                                local_228 = _e2227;
                                local_229 = _e2229;
                                local_230 = _e2231;
                                local_231 = _e2233;
                                local_232 = _e2235;
                                local_233 = _e2237;
                                local_234 = _e2239;
                                local_235 = _e2241;
                                let _e2242 = local_230;
                                let _e2243 = local_231;
                                let _e2244 = (_e2242 < _e2243);
                                local_236 = _e2244;
                                if _e2244 {
                                    let _e2245 = local_230;
                                    let _e2246 = (1536u + _e2245);
                                    local_237 = _e2246;
                                    if (_e2246 < 5888u) {
                                    } else {
                                        phi_4953_ = true;
                                        break;
                                    }
                                    let _e2248 = local_237;
                                    let _e2250 = global_11[_e2248];
                                    local_238 = bitcast<f32>(_e2250);
                                    let _e2252 = local_230;
                                    let _e2253 = (1792u + _e2252);
                                    local_239 = _e2253;
                                    if (_e2253 < 5888u) {
                                    } else {
                                        phi_4953_ = true;
                                        break;
                                    }
                                    let _e2255 = local_239;
                                    let _e2257 = global_11[_e2255];
                                    local_240 = bitcast<f32>(_e2257);
                                    let _e2259 = local_230;
                                    let _e2260 = (2048u + _e2259);
                                    local_241 = _e2260;
                                    if (_e2260 < 5888u) {
                                    } else {
                                        phi_4953_ = true;
                                        break;
                                    }
                                    let _e2262 = local_241;
                                    let _e2264 = global_11[_e2262];
                                    let _e2265 = bitcast<f32>(_e2264);
                                    local_242 = _e2265;
                                    let _e2266 = local_197;
                                    let _e2267 = local_238;
                                    let _e2268 = (_e2266 - _e2267);
                                    local_243 = _e2268;
                                    let _e2269 = local_198;
                                    let _e2270 = local_240;
                                    let _e2271 = (_e2269 - _e2270);
                                    local_244 = _e2271;
                                    let _e2274 = ((_e2268 * _e2268) + (_e2271 * _e2271));
                                    local_245 = _e2274;
                                    let _e2277 = local_230;
                                    let _e2279 = local_232;
                                    let _e2281 = ((_e2274 < (_e2265 * _e2265)) && (f32(_e2277) < _e2279));
                                    local_246 = _e2281;
                                    if _e2281 {
                                        let _e2282 = local_230;
                                        let _e2283 = (5632u + _e2282);
                                        local_247 = _e2283;
                                        if (_e2283 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e2285 = local_247;
                                        let _e2287 = global_11[_e2285];
                                        local_248 = _e2287;
                                        let _e2288 = local_230;
                                        let _e2289 = (3584u + _e2288);
                                        local_249 = _e2289;
                                        if (_e2289 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e2291 = local_249;
                                        let _e2293 = global_11[_e2291];
                                        local_250 = bitcast<f32>(_e2293);
                                        let _e2295 = local_248;
                                        if (_e2295 != 0u) {
                                            let _e2731 = local_242;
                                            let _e2732 = (_e2731 - 1.4142135f);
                                            local_251 = _e2732;
                                            let _e2733 = local_242;
                                            let _e2734 = (_e2733 - 2.828427f);
                                            let _e2737 = local_245;
                                            let _e2739 = ((_e2734 > 0f) && (_e2737 <= (_e2734 * _e2734)));
                                            local_252 = _e2739;
                                            let _e2741 = ((3.1415927f * _e2732) * _e2732);
                                            local_253 = _e2741;
                                            let _e2742 = (1f / _e2741);
                                            local_254 = _e2742;
                                            let _e2744 = local_246;
                                            let _e2745 = (_e2744 && !(_e2739));
                                            local_255 = _e2745;
                                            if _e2745 {
                                                let _e2746 = local_227;
                                                let _e2747 = local_227;
                                                local_256 = (_e2746 * _e2747);
                                                phi_2168_ = 0u;
                                                phi_2171_ = 0f;
                                                phi_2173_ = 0u;
                                                loop {
                                                    let _e2750 = phi_2168_;
                                                    let _e2752 = phi_2171_;
                                                    let _e2754 = phi_2173_;
                                                    local_257 = _e2750;
                                                    local_258 = _e2752;
                                                    local_259 = _e2754;
                                                    let _e2755 = local_257;
                                                    let _e2756 = local_256;
                                                    if (_e2755 < _e2756) {
                                                        let _e2758 = local_257;
                                                        let _e2759 = (_e2758 < 16u);
                                                        if _e2759 {
                                                            let _e2760 = local_257;
                                                            let _e2764 = local_248;
                                                            if ((_e2764 & (1u << bitcast<u32>((_e2760 & 31u)))) == 0u) {
                                                                phi_3011_ = _e2752;
                                                                phi_3012_ = _e2754;
                                                            } else {
                                                                let _e2767 = local_227;
                                                                local_260 = f32(_e2767);
                                                                let _e2769 = local_227;
                                                                let _e2770 = (_e2769 == 0u);
                                                                local_261 = _e2770;
                                                                if _e2770 {
                                                                    phi_4847_ = true;
                                                                    break;
                                                                }
                                                                let _e2771 = local_257;
                                                                let _e2772 = local_227;
                                                                let _e2776 = local_260;
                                                                local_262 = ((f32((_e2771 % _e2772)) + 0.5f) / _e2776);
                                                                let _e2778 = local_261;
                                                                if _e2778 {
                                                                    phi_4847_ = true;
                                                                    break;
                                                                }
                                                                let _e2779 = local_257;
                                                                let _e2780 = local_227;
                                                                let _e2784 = local_260;
                                                                let _e2786 = local_243;
                                                                let _e2787 = local_262;
                                                                let _e2788 = (_e2786 - _e2787);
                                                                local_263 = _e2788;
                                                                let _e2789 = local_244;
                                                                let _e2790 = (_e2789 - ((f32((_e2779 / _e2780)) + 0.5f) / _e2784));
                                                                local_264 = _e2790;
                                                                local_265 = (_e2788 + 1f);
                                                                local_266 = (_e2790 + 1f);
                                                                let _e2793 = local_251;
                                                                if (_e2793 >= 0.0001f) {
                                                                    let _e2807 = local_263;
                                                                    let _e2809 = local_265;
                                                                    let _e2811 = local_263;
                                                                    let _e2814 = local_263;
                                                                    let _e2815 = select(select(0f, (-1f - _e2811), (_e2809 < 0f)), _e2814, (0f < _e2807));
                                                                    let _e2816 = local_264;
                                                                    let _e2818 = local_266;
                                                                    let _e2820 = local_264;
                                                                    let _e2821 = (-1f - _e2820);
                                                                    local_267 = _e2821;
                                                                    let _e2823 = local_264;
                                                                    let _e2824 = select(select(0f, _e2821, (_e2818 < 0f)), _e2823, (0f < _e2816));
                                                                    let _e2825 = local_251;
                                                                    let _e2826 = local_251;
                                                                    let _e2827 = (_e2825 * _e2826);
                                                                    local_268 = _e2827;
                                                                    let _e2831 = (_e2827 <= ((_e2815 * _e2815) + (_e2824 * _e2824)));
                                                                    local_269 = _e2831;
                                                                    let _e2832 = local_263;
                                                                    let _e2833 = -(_e2832);
                                                                    let _e2834 = local_265;
                                                                    let _e2836 = local_265;
                                                                    let _e2837 = select(_e2836, _e2833, (_e2834 < _e2833));
                                                                    let _e2838 = local_264;
                                                                    let _e2839 = -(_e2838);
                                                                    local_270 = _e2839;
                                                                    let _e2840 = local_266;
                                                                    let _e2842 = local_266;
                                                                    let _e2843 = select(_e2842, _e2839, (_e2840 < _e2839));
                                                                    let _e2847 = (((_e2837 * _e2837) + (_e2843 * _e2843)) <= _e2827);
                                                                    local_271 = _e2847;
                                                                    let _e2849 = local_255;
                                                                    if ((_e2849 && !(_e2831)) && !(_e2847)) {
                                                                        let _e2853 = local_251;
                                                                        if (_e2853 > 0f) {
                                                                            let _e2855 = local_264;
                                                                            let _e2856 = (0f <= _e2855);
                                                                            let _e2858 = local_266;
                                                                            let _e2860 = (!(_e2856) && (_e2858 <= 0f));
                                                                            let _e2861 = local_270;
                                                                            let _e2862 = local_266;
                                                                            let _e2863 = select(_e2862, _e2861, _e2860);
                                                                            let _e2864 = local_267;
                                                                            let _e2865 = local_270;
                                                                            let _e2867 = local_264;
                                                                            let _e2868 = select(select(_e2865, _e2864, _e2860), _e2867, _e2856);
                                                                            let _e2872 = local_268;
                                                                            let _e2873 = (_e2872 - (_e2863 * _e2863));
                                                                            let _e2876 = select(0f, sqrt(_e2873), (0f < _e2873));
                                                                            let _e2877 = local_263;
                                                                            let _e2879 = -(_e2876);
                                                                            let _e2880 = local_263;
                                                                            let _e2882 = local_263;
                                                                            let _e2884 = select(select(_e2882, _e2879, (_e2880 < _e2879)), _e2876, (_e2876 < _e2877));
                                                                            let _e2885 = local_265;
                                                                            let _e2887 = local_265;
                                                                            let _e2889 = local_265;
                                                                            let _e2891 = select(select(_e2889, _e2879, (_e2887 < _e2879)), _e2876, (_e2876 < _e2885));
                                                                            let _e2892 = local_251;
                                                                            let _e2893 = local_263;
                                                                            let _e2895 = local_242;
                                                                            let _e2896 = (1.4142135f - _e2895);
                                                                            let _e2897 = local_263;
                                                                            let _e2899 = local_263;
                                                                            let _e2901 = local_251;
                                                                            let _e2902 = select(select(_e2899, _e2896, (_e2897 < _e2896)), _e2901, (_e2892 < _e2893));
                                                                            let _e2903 = local_251;
                                                                            let _e2904 = local_265;
                                                                            let _e2906 = local_265;
                                                                            let _e2908 = local_265;
                                                                            let _e2910 = local_251;
                                                                            let _e2911 = select(select(_e2908, _e2896, (_e2906 < _e2896)), _e2910, (_e2903 < _e2904));
                                                                            let _e2915 = local_268;
                                                                            let _e2916 = (_e2915 - (_e2911 * _e2911));
                                                                            let _e2920 = local_251;
                                                                            let _e2921 = (_e2911 / _e2920);
                                                                            let _e2925 = select(select(_e2921, -1f, (_e2921 < -1f)), 1f, (1f < _e2921));
                                                                            let _e2927 = (_e2925 < 0f);
                                                                            let _e2929 = select(_e2925, -(_e2925), _e2927);
                                                                            let _e2931 = select(_e2929, 1f, (1f < _e2929));
                                                                            let _e2932 = (_e2931 <= 0.5f);
                                                                            let _e2936 = select(sqrt((0.5f * (1f - _e2931))), _e2931, _e2932);
                                                                            let _e2937 = (_e2936 * _e2936);
                                                                            let _e2948 = (_e2936 + ((_e2936 * _e2937) * (0.1666673f + (_e2937 * (0.07496333f + (_e2937 * (0.04533125f + (_e2937 * (0.024905317f + (_e2937 * 0.04087546f))))))))));
                                                                            let _e2951 = select((1.5707964f - (2f * _e2948)), _e2948, _e2932);
                                                                            let _e2954 = local_268;
                                                                            let _e2959 = local_268;
                                                                            let _e2960 = (_e2959 - (_e2902 * _e2902));
                                                                            let _e2964 = local_251;
                                                                            let _e2965 = (_e2902 / _e2964);
                                                                            let _e2969 = select(select(_e2965, -1f, (_e2965 < -1f)), 1f, (1f < _e2965));
                                                                            let _e2971 = (_e2969 < 0f);
                                                                            let _e2973 = select(_e2969, -(_e2969), _e2971);
                                                                            let _e2975 = select(_e2973, 1f, (1f < _e2973));
                                                                            let _e2976 = (_e2975 <= 0.5f);
                                                                            let _e2980 = select(sqrt((0.5f * (1f - _e2975))), _e2975, _e2976);
                                                                            let _e2981 = (_e2980 * _e2980);
                                                                            let _e2992 = (_e2980 + ((_e2980 * _e2981) * (0.1666673f + (_e2981 * (0.07496333f + (_e2981 * (0.04533125f + (_e2981 * (0.024905317f + (_e2981 * 0.04087546f))))))))));
                                                                            let _e2995 = select((1.5707964f - (2f * _e2992)), _e2992, _e2976);
                                                                            let _e2998 = local_268;
                                                                            let _e3002 = ((0.5f * ((_e2911 * select(0f, sqrt(_e2916), (0f < _e2916))) + (_e2954 * select(_e2951, -(_e2951), _e2927)))) - (0.5f * ((_e2902 * select(0f, sqrt(_e2960), (0f < _e2960))) + (_e2998 * select(_e2995, -(_e2995), _e2971)))));
                                                                            let _e3005 = local_268;
                                                                            let _e3006 = (_e3005 - (_e2891 * _e2891));
                                                                            let _e3010 = local_251;
                                                                            let _e3011 = (_e2891 / _e3010);
                                                                            let _e3015 = select(select(_e3011, -1f, (_e3011 < -1f)), 1f, (1f < _e3011));
                                                                            let _e3017 = (_e3015 < 0f);
                                                                            let _e3019 = select(_e3015, -(_e3015), _e3017);
                                                                            let _e3021 = select(_e3019, 1f, (1f < _e3019));
                                                                            let _e3022 = (_e3021 <= 0.5f);
                                                                            let _e3026 = select(sqrt((0.5f * (1f - _e3021))), _e3021, _e3022);
                                                                            let _e3027 = (_e3026 * _e3026);
                                                                            let _e3038 = (_e3026 + ((_e3026 * _e3027) * (0.1666673f + (_e3027 * (0.07496333f + (_e3027 * (0.04533125f + (_e3027 * (0.024905317f + (_e3027 * 0.04087546f))))))))));
                                                                            let _e3041 = select((1.5707964f - (2f * _e3038)), _e3038, _e3022);
                                                                            let _e3044 = local_268;
                                                                            let _e3049 = local_268;
                                                                            let _e3050 = (_e3049 - (_e2884 * _e2884));
                                                                            let _e3054 = local_251;
                                                                            let _e3055 = (_e2884 / _e3054);
                                                                            let _e3059 = select(select(_e3055, -1f, (_e3055 < -1f)), 1f, (1f < _e3055));
                                                                            let _e3061 = (_e3059 < 0f);
                                                                            let _e3063 = select(_e3059, -(_e3059), _e3061);
                                                                            let _e3065 = select(_e3063, 1f, (1f < _e3063));
                                                                            let _e3066 = (_e3065 <= 0.5f);
                                                                            let _e3070 = select(sqrt((0.5f * (1f - _e3065))), _e3065, _e3066);
                                                                            let _e3071 = (_e3070 * _e3070);
                                                                            let _e3082 = (_e3070 + ((_e3070 * _e3071) * (0.1666673f + (_e3071 * (0.07496333f + (_e3071 * (0.04533125f + (_e3071 * (0.024905317f + (_e3071 * 0.04087546f))))))))));
                                                                            let _e3085 = select((1.5707964f - (2f * _e3082)), _e3082, _e3066);
                                                                            let _e3088 = local_268;
                                                                            let _e3095 = local_268;
                                                                            let _e3096 = (_e3095 - (_e2868 * _e2868));
                                                                            let _e3099 = select(0f, sqrt(_e3096), (0f < _e3096));
                                                                            let _e3100 = local_263;
                                                                            let _e3102 = -(_e3099);
                                                                            let _e3103 = local_263;
                                                                            let _e3105 = local_263;
                                                                            let _e3107 = select(select(_e3105, _e3102, (_e3103 < _e3102)), _e3099, (_e3099 < _e3100));
                                                                            let _e3108 = local_265;
                                                                            let _e3110 = local_265;
                                                                            let _e3112 = local_265;
                                                                            let _e3114 = select(select(_e3112, _e3102, (_e3110 < _e3102)), _e3099, (_e3099 < _e3108));
                                                                            let _e3119 = local_268;
                                                                            let _e3120 = (_e3119 - (_e3114 * _e3114));
                                                                            let _e3124 = local_251;
                                                                            let _e3125 = (_e3114 / _e3124);
                                                                            let _e3129 = select(select(_e3125, -1f, (_e3125 < -1f)), 1f, (1f < _e3125));
                                                                            let _e3131 = (_e3129 < 0f);
                                                                            let _e3133 = select(_e3129, -(_e3129), _e3131);
                                                                            let _e3135 = select(_e3133, 1f, (1f < _e3133));
                                                                            let _e3136 = (_e3135 <= 0.5f);
                                                                            let _e3140 = select(sqrt((0.5f * (1f - _e3135))), _e3135, _e3136);
                                                                            let _e3141 = (_e3140 * _e3140);
                                                                            let _e3152 = (_e3140 + ((_e3140 * _e3141) * (0.1666673f + (_e3141 * (0.07496333f + (_e3141 * (0.04533125f + (_e3141 * (0.024905317f + (_e3141 * 0.04087546f))))))))));
                                                                            let _e3155 = select((1.5707964f - (2f * _e3152)), _e3152, _e3136);
                                                                            let _e3158 = local_268;
                                                                            let _e3163 = local_268;
                                                                            let _e3164 = (_e3163 - (_e3107 * _e3107));
                                                                            let _e3168 = local_251;
                                                                            let _e3169 = (_e3107 / _e3168);
                                                                            let _e3173 = select(select(_e3169, -1f, (_e3169 < -1f)), 1f, (1f < _e3169));
                                                                            let _e3175 = (_e3173 < 0f);
                                                                            let _e3177 = select(_e3173, -(_e3173), _e3175);
                                                                            let _e3179 = select(_e3177, 1f, (1f < _e3177));
                                                                            let _e3180 = (_e3179 <= 0.5f);
                                                                            let _e3184 = select(sqrt((0.5f * (1f - _e3179))), _e3179, _e3180);
                                                                            let _e3185 = (_e3184 * _e3184);
                                                                            let _e3196 = (_e3184 + ((_e3184 * _e3185) * (0.1666673f + (_e3185 * (0.07496333f + (_e3185 * (0.04533125f + (_e3185 * (0.024905317f + (_e3185 * 0.04087546f))))))))));
                                                                            let _e3199 = select((1.5707964f - (2f * _e3196)), _e3196, _e3180);
                                                                            let _e3202 = local_268;
                                                                            let _e3209 = ((((_e2863 * (_e2891 - _e2884)) + _e3002) - ((0.5f * ((_e2891 * select(0f, sqrt(_e3006), (0f < _e3006))) + (_e3044 * select(_e3041, -(_e3041), _e3017)))) - (0.5f * ((_e2884 * select(0f, sqrt(_e3050), (0f < _e3050))) + (_e3088 * select(_e3085, -(_e3085), _e3061)))))) + (select(1f, -1f, (_e2856 || _e2860)) * (((_e2868 * (_e3114 - _e3107)) + _e3002) - ((0.5f * ((_e3114 * select(0f, sqrt(_e3120), (0f < _e3120))) + (_e3158 * select(_e3155, -(_e3155), _e3131)))) - (0.5f * ((_e3107 * select(0f, sqrt(_e3164), (0f < _e3164))) + (_e3202 * select(_e3199, -(_e3199), _e3175))))))));
                                                                            let _e3210 = local_265;
                                                                            let _e3211 = local_263;
                                                                            let _e3213 = local_266;
                                                                            let _e3214 = local_264;
                                                                            let _e3216 = ((_e3210 - _e3211) * (_e3213 - _e3214));
                                                                            phi_2984_ = select(select(0f, _e3209, (0f < _e3209)), _e3216, (_e3216 < _e3209));
                                                                        } else {
                                                                            phi_2984_ = 0f;
                                                                        }
                                                                        let _e3222 = phi_2984_;
                                                                        let _e3223 = local_271;
                                                                        phi_2989_ = select(_e3222, 1f, _e3223);
                                                                    } else {
                                                                        phi_2989_ = 1f;
                                                                    }
                                                                    let _e3226 = phi_2989_;
                                                                    let _e3227 = local_253;
                                                                    let _e3229 = local_269;
                                                                    phi_3008_ = select((_e3226 / _e3227), 0f, _e3229);
                                                                } else {
                                                                    let _e2795 = local_263;
                                                                    let _e2797 = local_265;
                                                                    let _e2800 = local_264;
                                                                    let _e2803 = local_266;
                                                                    phi_3008_ = select(0f, 1f, ((((_e2795 <= 0f) && (0f < _e2797)) && (_e2800 <= 0f)) && (0f < _e2803)));
                                                                }
                                                                let _e3232 = phi_3008_;
                                                                let _e3233 = local_258;
                                                                let _e3235 = local_259;
                                                                phi_3011_ = (_e3233 + _e3232);
                                                                phi_3012_ = (_e3235 + 1u);
                                                            }
                                                            let _e3238 = phi_3011_;
                                                            let _e3240 = phi_3012_;
                                                            let _e3241 = local_257;
                                                            phi_3014_ = (_e3241 + 1u);
                                                            phi_3015_ = _e3238;
                                                            phi_3016_ = _e3240;
                                                        } else {
                                                            phi_3014_ = u32();
                                                            phi_3015_ = f32();
                                                            phi_3016_ = u32();
                                                        }
                                                        let _e3244 = phi_3014_;
                                                        let _e3246 = phi_3015_;
                                                        let _e3248 = phi_3016_;
                                                        phi_2169_ = _e3244;
                                                        phi_2172_ = _e3246;
                                                        phi_2174_ = _e3248;
                                                        phi_3017_ = _e2759;
                                                    } else {
                                                        phi_2169_ = u32();
                                                        phi_2172_ = f32();
                                                        phi_2174_ = u32();
                                                        phi_3017_ = false;
                                                    }
                                                    let _e3250 = phi_2169_;
                                                    let _e3252 = phi_2172_;
                                                    let _e3254 = phi_2174_;
                                                    let _e3256 = phi_3017_;
                                                    local_272 = _e3256;
                                                    continue;
                                                    continuing {
                                                        let _e3257 = local_272;
                                                        phi_2168_ = _e3250;
                                                        phi_2171_ = _e3252;
                                                        phi_2173_ = _e3254;
                                                        phi_4847_ = _e2225;
                                                        break if !(_e3257);
                                                    }
                                                }
                                                let _e3260 = phi_4847_;
                                                phi_4953_ = _e3260;
                                                if _e3260 {
                                                    break;
                                                }
                                                let _e3261 = local_259;
                                                if (_e3261 == 0u) {
                                                    phi_3028_ = 0f;
                                                } else {
                                                    let _e3263 = local_259;
                                                    let _e3265 = local_258;
                                                    phi_3028_ = (_e3265 / f32(_e3263));
                                                }
                                                let _e3268 = phi_3028_;
                                                let _e3269 = local_252;
                                                let _e3270 = local_254;
                                                phi_4975_ = _e3260;
                                                phi_3033_ = select(_e3268, _e3270, _e3269);
                                            } else {
                                                phi_4975_ = _e2225;
                                                phi_3033_ = _e2742;
                                            }
                                            let _e3273 = phi_4975_;
                                            let _e3275 = phi_3033_;
                                            phi_4974_ = _e3273;
                                            phi_3500_ = _e3275;
                                        } else {
                                            let _e2297 = local_25;
                                            let _e2298 = (_e2297 == 0u);
                                            local_273 = _e2298;
                                            if _e2298 {
                                                let _e2299 = local_32;
                                                phi_3044_ = (_e2299 == 0u);
                                            } else {
                                                phi_3044_ = false;
                                            }
                                            let _e2302 = phi_3044_;
                                            if _e2302 {
                                                let _e2709 = local_242;
                                                let _e2710 = local_250;
                                                let _e2711 = (_e2709 - _e2710);
                                                let _e2714 = local_245;
                                                let _e2717 = local_245;
                                                let _e2719 = local_242;
                                                let _e2721 = local_250;
                                                let _e2723 = ((_e2719 - sqrt(_e2717)) * (1f / _e2721));
                                                phi_3499_ = select(select(0f, select(1f, _e2723, (_e2723 < 1f)), (0f < _e2723)), 1f, ((0f < _e2711) && (_e2714 <= (_e2711 * _e2711))));
                                            } else {
                                                let _e2303 = local_230;
                                                let _e2304 = (3840u + _e2303);
                                                local_274 = _e2304;
                                                if (_e2304 < 5888u) {
                                                } else {
                                                    phi_4953_ = true;
                                                    break;
                                                }
                                                let _e2306 = local_274;
                                                let _e2308 = global_11[_e2306];
                                                local_275 = bitcast<f32>(_e2308);
                                                let _e2310 = local_273;
                                                if _e2310 {
                                                    let _e2311 = local_32;
                                                    phi_3090_ = (_e2311 == 0u);
                                                } else {
                                                    phi_3090_ = false;
                                                }
                                                let _e2314 = phi_3090_;
                                                if _e2314 {
                                                    let _e2687 = local_242;
                                                    let _e2688 = local_250;
                                                    let _e2689 = (_e2687 - _e2688);
                                                    let _e2692 = local_245;
                                                    let _e2695 = local_245;
                                                    let _e2697 = local_242;
                                                    let _e2699 = local_250;
                                                    let _e2701 = ((_e2697 - sqrt(_e2695)) * (1f / _e2699));
                                                    phi_3498_ = select(select(0f, select(1f, _e2701, (_e2701 < 1f)), (0f < _e2701)), 1f, ((0f < _e2689) && (_e2692 <= (_e2689 * _e2689))));
                                                } else {
                                                    let _e2315 = local_275;
                                                    let _e2316 = local_243;
                                                    local_276 = (_e2315 * _e2316);
                                                    let _e2318 = local_275;
                                                    let _e2319 = local_244;
                                                    local_277 = (_e2318 * _e2319);
                                                    let _e2321 = local_32;
                                                    if (_e2321 > 0u) {
                                                        let _e2404 = local_250;
                                                        let _e2406 = local_242;
                                                        let _e2407 = (_e2406 - (0.5f * _e2404));
                                                        local_278 = _e2407;
                                                        if (_e2407 > 0f) {
                                                            let _e2409 = local_276;
                                                            let _e2410 = local_278;
                                                            let _e2412 = local_277;
                                                            let _e2413 = local_278;
                                                            let _e2415 = local_32;
                                                            let _e2416 = f32(_e2415);
                                                            local_279 = _e2416;
                                                            let _e2420 = (((((_e2409 / _e2410) + 1f) * 0.5f) * _e2416) - 0.5f);
                                                            local_280 = _e2420;
                                                            local_281 = (((((_e2412 / _e2413) + 1f) * 0.5f) * _e2416) - 0.5f);
                                                            if (_e2420 > -1f) {
                                                                let _e2426 = local_281;
                                                                if (_e2426 > -1f) {
                                                                    let _e2428 = local_280;
                                                                    let _e2429 = local_279;
                                                                    if (_e2428 < _e2429) {
                                                                        let _e2431 = local_281;
                                                                        let _e2432 = local_279;
                                                                        let _e2433 = (_e2431 < _e2432);
                                                                        local_282 = _e2433;
                                                                        if _e2433 {
                                                                            let _e2434 = local_280;
                                                                            let _e2435 = floor(_e2434);
                                                                            local_283 = _e2435;
                                                                            let _e2436 = local_281;
                                                                            let _e2437 = floor(_e2436);
                                                                            local_284 = _e2437;
                                                                            let _e2438 = local_280;
                                                                            local_285 = (_e2438 - _e2435);
                                                                            let _e2440 = local_281;
                                                                            local_286 = (_e2440 - _e2437);
                                                                            let _e2442 = (_e2435 < 0f);
                                                                            local_287 = _e2442;
                                                                            if _e2442 {
                                                                                phi_3211_ = f32();
                                                                                phi_3212_ = true;
                                                                            } else {
                                                                                let _e2443 = local_284;
                                                                                if (_e2443 < 0f) {
                                                                                    phi_3209_ = f32();
                                                                                    phi_3210_ = true;
                                                                                } else {
                                                                                    let _e2445 = local_283;
                                                                                    let _e2446 = local_279;
                                                                                    if (_e2445 >= _e2446) {
                                                                                        phi_3207_ = f32();
                                                                                        phi_3208_ = true;
                                                                                    } else {
                                                                                        let _e2448 = local_284;
                                                                                        let _e2449 = local_279;
                                                                                        let _e2450 = (_e2448 >= _e2449);
                                                                                        if _e2450 {
                                                                                            phi_3206_ = f32();
                                                                                        } else {
                                                                                            let _e2451 = local_284;
                                                                                            let _e2453 = local_284;
                                                                                            let _e2455 = local_284;
                                                                                            let _e2459 = local_32;
                                                                                            let _e2461 = local_283;
                                                                                            let _e2463 = local_283;
                                                                                            let _e2465 = local_283;
                                                                                            let _e2469 = ((select(select(u32(_e2451), 0u, (_e2453 < 0f)), 4294967295u, (_e2455 > 4294967000f)) * _e2459) + select(select(u32(_e2461), 0u, (_e2463 < 0f)), 4294967295u, (_e2465 > 4294967000f)));
                                                                                            local_288 = _e2469;
                                                                                            let _e2470 = local_8;
                                                                                            if (_e2469 < _e2470) {
                                                                                            } else {
                                                                                                phi_4953_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2472 = local_288;
                                                                                            let _e2475 = global_10.member[_e2472];
                                                                                            phi_3206_ = bitcast<f32>(_e2475);
                                                                                        }
                                                                                        let _e2478 = phi_3206_;
                                                                                        phi_3207_ = _e2478;
                                                                                        phi_3208_ = _e2450;
                                                                                    }
                                                                                    let _e2480 = phi_3207_;
                                                                                    let _e2482 = phi_3208_;
                                                                                    phi_3209_ = _e2480;
                                                                                    phi_3210_ = _e2482;
                                                                                }
                                                                                let _e2484 = phi_3209_;
                                                                                let _e2486 = phi_3210_;
                                                                                phi_3211_ = _e2484;
                                                                                phi_3212_ = _e2486;
                                                                            }
                                                                            let _e2488 = phi_3211_;
                                                                            let _e2490 = phi_3212_;
                                                                            let _e2492 = local_285;
                                                                            let _e2493 = (1f - _e2492);
                                                                            local_289 = _e2493;
                                                                            local_290 = (select(_e2488, 0f, _e2490) * _e2493);
                                                                            let _e2495 = local_283;
                                                                            let _e2496 = (_e2495 + 1f);
                                                                            local_291 = _e2496;
                                                                            let _e2497 = (_e2496 < 0f);
                                                                            local_292 = _e2497;
                                                                            if _e2497 {
                                                                                phi_3267_ = f32();
                                                                                phi_3268_ = true;
                                                                            } else {
                                                                                let _e2498 = local_284;
                                                                                if (_e2498 < 0f) {
                                                                                    phi_3265_ = f32();
                                                                                    phi_3266_ = true;
                                                                                } else {
                                                                                    let _e2500 = local_291;
                                                                                    let _e2501 = local_279;
                                                                                    if (_e2500 >= _e2501) {
                                                                                        phi_3263_ = f32();
                                                                                        phi_3264_ = true;
                                                                                    } else {
                                                                                        let _e2503 = local_284;
                                                                                        let _e2504 = local_279;
                                                                                        let _e2505 = (_e2503 >= _e2504);
                                                                                        if _e2505 {
                                                                                            phi_3262_ = f32();
                                                                                        } else {
                                                                                            let _e2506 = local_284;
                                                                                            let _e2508 = local_284;
                                                                                            let _e2510 = local_284;
                                                                                            let _e2514 = local_32;
                                                                                            let _e2516 = local_291;
                                                                                            let _e2518 = local_291;
                                                                                            let _e2520 = local_291;
                                                                                            let _e2524 = ((select(select(u32(_e2506), 0u, (_e2508 < 0f)), 4294967295u, (_e2510 > 4294967000f)) * _e2514) + select(select(u32(_e2516), 0u, (_e2518 < 0f)), 4294967295u, (_e2520 > 4294967000f)));
                                                                                            local_293 = _e2524;
                                                                                            let _e2525 = local_8;
                                                                                            if (_e2524 < _e2525) {
                                                                                            } else {
                                                                                                phi_4953_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2527 = local_293;
                                                                                            let _e2530 = global_10.member[_e2527];
                                                                                            phi_3262_ = bitcast<f32>(_e2530);
                                                                                        }
                                                                                        let _e2533 = phi_3262_;
                                                                                        phi_3263_ = _e2533;
                                                                                        phi_3264_ = _e2505;
                                                                                    }
                                                                                    let _e2535 = phi_3263_;
                                                                                    let _e2537 = phi_3264_;
                                                                                    phi_3265_ = _e2535;
                                                                                    phi_3266_ = _e2537;
                                                                                }
                                                                                let _e2539 = phi_3265_;
                                                                                let _e2541 = phi_3266_;
                                                                                phi_3267_ = _e2539;
                                                                                phi_3268_ = _e2541;
                                                                            }
                                                                            let _e2543 = phi_3267_;
                                                                            let _e2545 = phi_3268_;
                                                                            let _e2547 = local_285;
                                                                            let _e2549 = local_290;
                                                                            local_294 = (_e2549 + (select(_e2543, 0f, _e2545) * _e2547));
                                                                            let _e2551 = local_284;
                                                                            local_295 = (_e2551 + 1f);
                                                                            let _e2553 = local_287;
                                                                            if _e2553 {
                                                                                phi_3323_ = f32();
                                                                                phi_3324_ = true;
                                                                            } else {
                                                                                let _e2554 = local_295;
                                                                                if (_e2554 < 0f) {
                                                                                    phi_3321_ = f32();
                                                                                    phi_3322_ = true;
                                                                                } else {
                                                                                    let _e2556 = local_283;
                                                                                    let _e2557 = local_279;
                                                                                    if (_e2556 >= _e2557) {
                                                                                        phi_3319_ = f32();
                                                                                        phi_3320_ = true;
                                                                                    } else {
                                                                                        let _e2559 = local_295;
                                                                                        let _e2560 = local_279;
                                                                                        let _e2561 = (_e2559 >= _e2560);
                                                                                        if _e2561 {
                                                                                            phi_3318_ = f32();
                                                                                        } else {
                                                                                            let _e2562 = local_295;
                                                                                            let _e2564 = local_295;
                                                                                            let _e2566 = local_295;
                                                                                            let _e2570 = local_32;
                                                                                            let _e2572 = local_283;
                                                                                            let _e2574 = local_283;
                                                                                            let _e2576 = local_283;
                                                                                            let _e2580 = ((select(select(u32(_e2562), 0u, (_e2564 < 0f)), 4294967295u, (_e2566 > 4294967000f)) * _e2570) + select(select(u32(_e2572), 0u, (_e2574 < 0f)), 4294967295u, (_e2576 > 4294967000f)));
                                                                                            local_296 = _e2580;
                                                                                            let _e2581 = local_8;
                                                                                            if (_e2580 < _e2581) {
                                                                                            } else {
                                                                                                phi_4953_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2583 = local_296;
                                                                                            let _e2586 = global_10.member[_e2583];
                                                                                            phi_3318_ = bitcast<f32>(_e2586);
                                                                                        }
                                                                                        let _e2589 = phi_3318_;
                                                                                        phi_3319_ = _e2589;
                                                                                        phi_3320_ = _e2561;
                                                                                    }
                                                                                    let _e2591 = phi_3319_;
                                                                                    let _e2593 = phi_3320_;
                                                                                    phi_3321_ = _e2591;
                                                                                    phi_3322_ = _e2593;
                                                                                }
                                                                                let _e2595 = phi_3321_;
                                                                                let _e2597 = phi_3322_;
                                                                                phi_3323_ = _e2595;
                                                                                phi_3324_ = _e2597;
                                                                            }
                                                                            let _e2599 = phi_3323_;
                                                                            let _e2601 = phi_3324_;
                                                                            let _e2603 = local_289;
                                                                            local_297 = (select(_e2599, 0f, _e2601) * _e2603);
                                                                            let _e2605 = local_292;
                                                                            if _e2605 {
                                                                                phi_3380_ = f32();
                                                                                phi_3381_ = true;
                                                                            } else {
                                                                                let _e2606 = local_295;
                                                                                if (_e2606 < 0f) {
                                                                                    phi_3378_ = f32();
                                                                                    phi_3379_ = true;
                                                                                } else {
                                                                                    let _e2608 = local_291;
                                                                                    let _e2609 = local_279;
                                                                                    if (_e2608 >= _e2609) {
                                                                                        phi_3376_ = f32();
                                                                                        phi_3377_ = true;
                                                                                    } else {
                                                                                        let _e2611 = local_295;
                                                                                        let _e2612 = local_279;
                                                                                        let _e2613 = (_e2611 >= _e2612);
                                                                                        if _e2613 {
                                                                                            phi_3375_ = f32();
                                                                                        } else {
                                                                                            let _e2614 = local_295;
                                                                                            let _e2616 = local_295;
                                                                                            let _e2618 = local_295;
                                                                                            let _e2622 = local_32;
                                                                                            let _e2624 = local_291;
                                                                                            let _e2626 = local_291;
                                                                                            let _e2628 = local_291;
                                                                                            let _e2632 = ((select(select(u32(_e2614), 0u, (_e2616 < 0f)), 4294967295u, (_e2618 > 4294967000f)) * _e2622) + select(select(u32(_e2624), 0u, (_e2626 < 0f)), 4294967295u, (_e2628 > 4294967000f)));
                                                                                            local_298 = _e2632;
                                                                                            let _e2633 = local_8;
                                                                                            if (_e2632 < _e2633) {
                                                                                            } else {
                                                                                                phi_4953_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2635 = local_298;
                                                                                            let _e2638 = global_10.member[_e2635];
                                                                                            phi_3375_ = bitcast<f32>(_e2638);
                                                                                        }
                                                                                        let _e2641 = phi_3375_;
                                                                                        phi_3376_ = _e2641;
                                                                                        phi_3377_ = _e2613;
                                                                                    }
                                                                                    let _e2643 = phi_3376_;
                                                                                    let _e2645 = phi_3377_;
                                                                                    phi_3378_ = _e2643;
                                                                                    phi_3379_ = _e2645;
                                                                                }
                                                                                let _e2647 = phi_3378_;
                                                                                let _e2649 = phi_3379_;
                                                                                phi_3380_ = _e2647;
                                                                                phi_3381_ = _e2649;
                                                                            }
                                                                            let _e2651 = phi_3380_;
                                                                            let _e2653 = phi_3381_;
                                                                            let _e2655 = local_285;
                                                                            let _e2657 = local_297;
                                                                            let _e2659 = local_286;
                                                                            let _e2661 = local_294;
                                                                            let _e2663 = local_286;
                                                                            phi_3392_ = ((_e2661 * (1f - _e2659)) + ((_e2657 + (select(_e2651, 0f, _e2653) * _e2655)) * _e2663));
                                                                        } else {
                                                                            phi_3392_ = f32();
                                                                        }
                                                                        let _e2667 = phi_3392_;
                                                                        let _e2668 = local_282;
                                                                        phi_3394_ = _e2667;
                                                                        phi_3395_ = select(true, false, _e2668);
                                                                    } else {
                                                                        phi_3394_ = f32();
                                                                        phi_3395_ = true;
                                                                    }
                                                                    let _e2671 = phi_3394_;
                                                                    let _e2673 = phi_3395_;
                                                                    phi_3396_ = _e2671;
                                                                    phi_3397_ = _e2673;
                                                                } else {
                                                                    phi_3396_ = f32();
                                                                    phi_3397_ = true;
                                                                }
                                                                let _e2675 = phi_3396_;
                                                                let _e2677 = phi_3397_;
                                                                phi_3398_ = _e2675;
                                                                phi_3399_ = _e2677;
                                                            } else {
                                                                phi_3398_ = f32();
                                                                phi_3399_ = true;
                                                            }
                                                            let _e2679 = phi_3398_;
                                                            let _e2681 = phi_3399_;
                                                            phi_3404_ = select(_e2679, 0f, _e2681);
                                                        } else {
                                                            phi_3404_ = 0f;
                                                        }
                                                        let _e2684 = phi_3404_;
                                                        phi_3497_ = _e2684;
                                                    } else {
                                                        let _e2323 = local_276;
                                                        let _e2324 = local_276;
                                                        let _e2326 = local_277;
                                                        let _e2327 = local_277;
                                                        let _e2330 = sqrt(((_e2323 * _e2324) + (_e2326 * _e2327)));
                                                        local_299 = _e2330;
                                                        let _e2331 = local_273;
                                                        if _e2331 {
                                                            phi_3484_ = _e2330;
                                                        } else {
                                                            let _e2332 = local_27;
                                                            let _e2334 = local_276;
                                                            let _e2336 = local_27;
                                                            let _e2338 = local_277;
                                                            phi_3426_ = 1u;
                                                            phi_3429_ = ((_e2334 * _e2332[0]) + (_e2338 * _e2336[1]));
                                                            phi_3431_ = _e614.member_16.member_2;
                                                            loop {
                                                                let _e2342 = phi_3426_;
                                                                let _e2344 = phi_3429_;
                                                                let _e2346 = phi_3431_;
                                                                local_300 = _e2342;
                                                                local_301 = _e2344;
                                                                local_302 = _e2346;
                                                                let _e2347 = local_300;
                                                                let _e2348 = local_25;
                                                                let _e2349 = (_e2347 < _e2348);
                                                                local_303 = _e2349;
                                                                if _e2349 {
                                                                    let _e2350 = local_302;
                                                                    let _e2352 = local_28;
                                                                    let _e2354 = local_302;
                                                                    let _e2356 = local_29;
                                                                    let _e2358 = ((_e2350[0] * _e2352) - (_e2354[1] * _e2356));
                                                                    let _e2359 = local_29;
                                                                    let _e2361 = local_28;
                                                                    let _e2363 = ((_e2350[0] * _e2359) + (_e2354[1] * _e2361));
                                                                    let _e2365 = local_276;
                                                                    let _e2367 = local_277;
                                                                    let _e2369 = ((_e2365 * _e2358) + (_e2367 * _e2363));
                                                                    let _e2370 = local_301;
                                                                    let _e2372 = local_301;
                                                                    let _e2374 = local_300;
                                                                    phi_3427_ = (_e2374 + 1u);
                                                                    phi_3430_ = select(_e2372, _e2369, (_e2369 > _e2370));
                                                                    phi_3432_ = array<f32, 2>(_e2358, _e2363);
                                                                } else {
                                                                    phi_3427_ = u32();
                                                                    phi_3430_ = f32();
                                                                    phi_3432_ = array<f32, 2>();
                                                                }
                                                                let _e2377 = phi_3427_;
                                                                let _e2379 = phi_3430_;
                                                                let _e2381 = phi_3432_;
                                                                continue;
                                                                continuing {
                                                                    let _e2382 = local_303;
                                                                    phi_3426_ = _e2377;
                                                                    phi_3429_ = _e2379;
                                                                    phi_3431_ = _e2381;
                                                                    break if !(_e2382);
                                                                }
                                                            }
                                                            let _e2384 = local_26;
                                                            let _e2386 = local_301;
                                                            let _e2388 = local_30;
                                                            let _e2390 = local_26;
                                                            let _e2391 = local_299;
                                                            phi_3484_ = ((((1f - _e2384) * _e2386) * _e2388) + (_e2390 * _e2391));
                                                        }
                                                        let _e2395 = phi_3484_;
                                                        let _e2396 = local_242;
                                                        let _e2398 = local_250;
                                                        let _e2399 = ((_e2396 - _e2395) / _e2398);
                                                        phi_3497_ = select(0f, select(1f, _e2399, (_e2399 < 1f)), (0f < _e2399));
                                                    }
                                                    let _e2686 = phi_3497_;
                                                    phi_3498_ = _e2686;
                                                }
                                                let _e2708 = phi_3498_;
                                                phi_3499_ = _e2708;
                                            }
                                            let _e2730 = phi_3499_;
                                            phi_4974_ = _e2225;
                                            phi_3500_ = _e2730;
                                        }
                                        let _e3277 = phi_4974_;
                                        let _e3279 = phi_3500_;
                                        local_304 = _e3279;
                                        let _e3280 = local_230;
                                        let _e3281 = (2304u + _e3280);
                                        local_305 = _e3281;
                                        if (_e3281 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3283 = local_305;
                                        let _e3285 = global_11[_e3283];
                                        let _e3287 = local_304;
                                        local_306 = (bitcast<f32>(_e3285) * _e3287);
                                        let _e3289 = local_230;
                                        let _e3290 = (4096u + _e3289);
                                        local_307 = _e3290;
                                        if (_e3290 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3292 = local_307;
                                        let _e3294 = global_11[_e3292];
                                        local_308 = bitcast<f32>(_e3294);
                                        let _e3296 = local_80;
                                        let _e3297 = local_230;
                                        let _e3299 = local_60;
                                        if ((_e3296 + _e3297) < _e3299) {
                                            let _e3322 = local_230;
                                            let _e3323 = (3328u + _e3322);
                                            local_309 = _e3323;
                                            if (_e3323 < 5888u) {
                                            } else {
                                                phi_4953_ = true;
                                                break;
                                            }
                                            let _e3325 = local_309;
                                            let _e3327 = global_11[_e3325];
                                            let _e3328 = bitcast<f32>(_e3327);
                                            local_310 = _e3328;
                                            let _e3329 = local_228;
                                            let _e3330 = (1f - _e3329);
                                            local_311 = _e3330;
                                            let _e3331 = local_229;
                                            local_312 = _e3331.member;
                                            let _e3336 = local_229;
                                            local_313 = _e3336.member_1;
                                            let _e3338 = local_306;
                                            let _e3342 = (!((_e3328 <= (_e3331.member * 1.05f))) || (1f < (_e3336.member_1 + (0.5f * _e3338))));
                                            let _e3343 = local_229;
                                            local_314 = _e3343.member_3;
                                            let _e3346 = local_229;
                                            local_315 = _e3346.member_4;
                                            let _e3349 = !(_e3342);
                                            local_316 = ((_e3342 && !(_e3343.member_3)) || (_e3349 && _e3346.member_4));
                                            local_317 = (_e3349 && _e3343.member_3);
                                            let _e3353 = local_229;
                                            local_318 = _e3353.member_2;
                                            local_448 = select(_e3353.member_2, _e3330, _e3342);
                                            let _e3357 = local_306;
                                            local_319 = (select(_e3336.member_1, 0f, _e3342) + _e3357);
                                            let _e3359 = local_308;
                                            let _e3360 = (_e3359 < 1f);
                                            local_320 = _e3360;
                                            if _e3360 {
                                                let _e3381 = local_316;
                                                let _e3382 = local_448;
                                                let _e3384 = local_306;
                                                let _e3385 = (_e3384 * select(1f, _e3382, _e3381));
                                                local_321 = _e3385;
                                                let _e3386 = local_308;
                                                let _e3387 = (_e3385 * _e3386);
                                                local_322 = _e3387;
                                                let _e3388 = local_311;
                                                local_323 = (_e3387 < _e3388);
                                                let _e3390 = local_308;
                                                if (_e3390 == 1f) {
                                                    phi_3581_ = _e3330;
                                                } else {
                                                    let _e3392 = local_311;
                                                    let _e3393 = local_308;
                                                    phi_3581_ = (_e3392 / _e3393);
                                                }
                                                let _e3396 = phi_3581_;
                                                let _e3397 = local_323;
                                                let _e3398 = local_321;
                                                let _e3400 = local_323;
                                                let _e3401 = local_322;
                                                let _e3402 = local_311;
                                                phi_3609_ = type_18(select(_e3396, _e3398, _e3397), select(_e3402, _e3401, _e3400));
                                            } else {
                                                let _e3361 = local_306;
                                                let _e3362 = local_308;
                                                let _e3363 = (_e3361 * _e3362);
                                                local_324 = _e3363;
                                                let _e3364 = local_311;
                                                local_325 = (_e3363 < _e3364);
                                                let _e3366 = local_308;
                                                if (_e3366 == 1f) {
                                                    phi_3598_ = _e3330;
                                                } else {
                                                    let _e3368 = local_311;
                                                    let _e3369 = local_308;
                                                    phi_3598_ = (_e3368 / _e3369);
                                                }
                                                let _e3372 = phi_3598_;
                                                let _e3373 = local_325;
                                                let _e3374 = local_306;
                                                let _e3376 = local_325;
                                                let _e3377 = local_324;
                                                let _e3378 = local_311;
                                                phi_3609_ = type_18(select(_e3372, _e3374, _e3373), select(_e3378, _e3377, _e3376));
                                            }
                                            let _e3406 = phi_3609_;
                                            let _e3407 = local_320;
                                            let _e3408 = local_317;
                                            let _e3410 = local_246;
                                            let _e3411 = local_310;
                                            let _e3412 = local_312;
                                            let _e3414 = local_246;
                                            let _e3415 = local_319;
                                            let _e3416 = local_313;
                                            let _e3418 = local_246;
                                            let _e3419 = local_448;
                                            let _e3420 = local_318;
                                            let _e3422 = local_246;
                                            let _e3424 = local_246;
                                            let _e3425 = !(_e3424);
                                            let _e3426 = local_314;
                                            let _e3429 = local_246;
                                            let _e3430 = local_316;
                                            let _e3432 = local_315;
                                            phi_3661_ = type_31(select(_e3412, _e3411, _e3410), select(_e3416, _e3415, _e3414), select(_e3420, _e3419, _e3418), ((_e3422 && select(true, _e3408, _e3407)) || (_e3425 && _e3426)), ((_e3429 && _e3430) || (_e3425 && _e3432)));
                                            phi_3662_ = _e3406;
                                        } else {
                                            let _e3301 = local_228;
                                            let _e3302 = (1f - _e3301);
                                            local_326 = _e3302;
                                            let _e3303 = local_306;
                                            let _e3304 = local_308;
                                            let _e3305 = (_e3303 * _e3304);
                                            local_327 = _e3305;
                                            local_328 = (_e3305 < _e3302);
                                            let _e3307 = local_308;
                                            if (_e3307 == 1f) {
                                                phi_3651_ = _e3302;
                                            } else {
                                                let _e3309 = local_326;
                                                let _e3310 = local_308;
                                                phi_3651_ = (_e3309 / _e3310);
                                            }
                                            let _e3313 = phi_3651_;
                                            let _e3314 = local_328;
                                            let _e3315 = local_306;
                                            let _e3317 = local_328;
                                            let _e3318 = local_327;
                                            let _e3319 = local_326;
                                            phi_3661_ = _e2229;
                                            phi_3662_ = type_18(select(_e3313, _e3315, _e3314), select(_e3319, _e3318, _e3317));
                                        }
                                        let _e3437 = phi_3661_;
                                        let _e3439 = phi_3662_;
                                        local_329 = _e3439.member;
                                        local_330 = _e3439.member_1;
                                        let _e3442 = local_235;
                                        local_331 = _e3442[0];
                                        let _e3444 = local_230;
                                        let _e3445 = (2560u + _e3444);
                                        local_332 = _e3445;
                                        if (_e3445 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3447 = local_332;
                                        let _e3449 = global_11[_e3447];
                                        let _e3451 = local_329;
                                        let _e3453 = local_331;
                                        let _e3455 = local_246;
                                        let _e3456 = local_331;
                                        local_449 = select(_e3456, (_e3453 + (_e3451 * bitcast<f32>(_e3449))), _e3455);
                                        let _e3458 = local_235;
                                        local_333 = _e3458[1];
                                        let _e3460 = local_230;
                                        let _e3461 = (2816u + _e3460);
                                        local_334 = _e3461;
                                        if (_e3461 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3463 = local_334;
                                        let _e3465 = global_11[_e3463];
                                        let _e3467 = local_329;
                                        let _e3469 = local_333;
                                        let _e3471 = local_246;
                                        let _e3472 = local_333;
                                        local_450 = select(_e3472, (_e3469 + (_e3467 * bitcast<f32>(_e3465))), _e3471);
                                        let _e3474 = local_235;
                                        local_335 = _e3474[2];
                                        let _e3476 = local_230;
                                        let _e3477 = (3072u + _e3476);
                                        local_336 = _e3477;
                                        if (_e3477 < 5888u) {
                                        } else {
                                            phi_4953_ = true;
                                            break;
                                        }
                                        let _e3479 = local_336;
                                        let _e3481 = global_11[_e3479];
                                        let _e3483 = local_329;
                                        let _e3485 = local_335;
                                        let _e3487 = local_246;
                                        let _e3488 = local_335;
                                        let _e3490 = local_449;
                                        let _e3491 = local_450;
                                        let _e3493 = local_228;
                                        let _e3494 = local_330;
                                        let _e3496 = local_246;
                                        let _e3497 = local_228;
                                        let _e3498 = select(_e3497, (_e3493 + _e3494), _e3496);
                                        let _e3501 = local_246;
                                        let _e3502 = (_e3501 && !((_e3498 < 0.99902344f)));
                                        local_337 = _e3502;
                                        if _e3502 {
                                            let _e3503 = local_234;
                                            let _e3504 = local_337;
                                            let _e3506 = local_230;
                                            let _e3509 = local_337;
                                            let _e3510 = local_233;
                                            let _e3512 = local_337;
                                            let _e3513 = local_232;
                                            let _e3514 = select(_e3513, 0f, _e3512);
                                            phi_3747_ = select(select(u32(_e3514), 0u, (_e3514 < 0f)), 4294967295u, (_e3514 > 4294967000f));
                                            phi_3748_ = _e3514;
                                            phi_3749_ = select(_e3510, f32((_e3506 + 1u)), _e3509);
                                            phi_3750_ = (_e3503 || _e3504);
                                        } else {
                                            phi_3747_ = _e2233;
                                            phi_3748_ = _e2235;
                                            phi_3749_ = _e2237;
                                            phi_3750_ = _e2239;
                                        }
                                        let _e3521 = phi_3747_;
                                        let _e3523 = phi_3748_;
                                        let _e3525 = phi_3749_;
                                        let _e3527 = phi_3750_;
                                        phi_4955_ = _e3277;
                                        phi_3751_ = _e3498;
                                        phi_3752_ = _e3437;
                                        phi_3753_ = _e3521;
                                        phi_3754_ = _e3523;
                                        phi_3755_ = _e3525;
                                        phi_3756_ = _e3527;
                                        phi_3757_ = array<f32, 3>(_e3490, _e3491, select(_e3488, (_e3485 + (_e3483 * bitcast<f32>(_e3481))), _e3487));
                                    } else {
                                        phi_4955_ = _e2225;
                                        phi_3751_ = _e2227;
                                        phi_3752_ = _e2229;
                                        phi_3753_ = _e2233;
                                        phi_3754_ = _e2235;
                                        phi_3755_ = _e2237;
                                        phi_3756_ = _e2239;
                                        phi_3757_ = _e2241;
                                    }
                                    let _e3529 = phi_4955_;
                                    let _e3531 = phi_3751_;
                                    let _e3533 = phi_3752_;
                                    let _e3535 = phi_3753_;
                                    let _e3537 = phi_3754_;
                                    let _e3539 = phi_3755_;
                                    let _e3541 = phi_3756_;
                                    let _e3543 = phi_3757_;
                                    let _e3544 = local_230;
                                    phi_4954_ = _e3529;
                                    phi_2066_ = _e3531;
                                    phi_2069_ = _e3533;
                                    phi_2071_ = (_e3544 + 1u);
                                    phi_2073_ = _e3535;
                                    phi_2075_ = _e3537;
                                    phi_2077_ = _e3539;
                                    phi_2079_ = _e3541;
                                    phi_2081_ = _e3543;
                                } else {
                                    phi_4954_ = _e2225;
                                    phi_2066_ = f32();
                                    phi_2069_ = type_31();
                                    phi_2071_ = u32();
                                    phi_2073_ = u32();
                                    phi_2075_ = f32();
                                    phi_2077_ = f32();
                                    phi_2079_ = bool();
                                    phi_2081_ = array<f32, 3>();
                                }
                                let _e3547 = phi_4954_;
                                let _e3549 = phi_2066_;
                                let _e3551 = phi_2069_;
                                let _e3553 = phi_2071_;
                                let _e3555 = phi_2073_;
                                let _e3557 = phi_2075_;
                                let _e3559 = phi_2077_;
                                let _e3561 = phi_2079_;
                                let _e3563 = phi_2081_;
                                continue;
                                continuing {
                                    let _e3564 = local_236;
                                    phi_4852_ = _e3547;
                                    phi_2065_ = _e3549;
                                    phi_2068_ = _e3551;
                                    phi_2070_ = _e3553;
                                    phi_2072_ = _e3555;
                                    phi_2074_ = _e3557;
                                    phi_2076_ = _e3559;
                                    phi_2078_ = _e3561;
                                    phi_2080_ = _e3563;
                                    phi_4953_ = _e3547;
                                    break if !(_e3564);
                                }
                            }
                            let _e3567 = phi_4953_;
                            phi_5055_ = _e3567;
                            if _e3567 {
                                break;
                            }
                            let _e3568 = local_235;
                            local_338 = _e3568[0];
                            phi_3761_ = 0u;
                            loop {
                                let _e3571 = phi_3761_;
                                local_339 = _e3571;
                                let _e3572 = local_339;
                                let _e3573 = (_e3572 < 1u);
                                local_340 = _e3573;
                                if _e3573 {
                                    let _e3574 = local;
                                    let _e3575 = local_339;
                                    let _e3576 = (_e3574 + _e3575);
                                    local_341 = _e3576;
                                    let _e3577 = local_338;
                                    local_342 = bitcast<u32>(_e3577);
                                    if (_e3576 < 5888u) {
                                    } else {
                                        phi_5027_ = true;
                                        break;
                                    }
                                    let _e3580 = local_341;
                                    let _e3582 = local_342;
                                    global_11[_e3580] = _e3582;
                                    let _e3583 = local_339;
                                    phi_3762_ = (_e3583 + 1u);
                                } else {
                                    phi_3762_ = u32();
                                }
                                let _e3586 = phi_3762_;
                                continue;
                                continuing {
                                    let _e3587 = local_340;
                                    phi_3761_ = _e3586;
                                    phi_5027_ = _e3567;
                                    break if !(_e3587);
                                }
                            }
                            let _e3590 = phi_5027_;
                            phi_5055_ = _e3590;
                            if _e3590 {
                                break;
                            }
                            let _e3591 = local_235;
                            local_343 = _e3591[1];
                            phi_3782_ = 0u;
                            loop {
                                let _e3594 = phi_3782_;
                                local_344 = _e3594;
                                let _e3595 = local_344;
                                let _e3596 = (_e3595 < 1u);
                                local_345 = _e3596;
                                if _e3596 {
                                    let _e3597 = local;
                                    let _e3598 = local_344;
                                    let _e3600 = local_343;
                                    local_346 = bitcast<u32>(_e3600);
                                    let _e3602 = (256u + (_e3597 + _e3598));
                                    local_347 = _e3602;
                                    if (_e3602 < 5888u) {
                                    } else {
                                        phi_5030_ = true;
                                        break;
                                    }
                                    let _e3604 = local_347;
                                    let _e3606 = local_346;
                                    global_11[_e3604] = _e3606;
                                    let _e3607 = local_344;
                                    phi_3783_ = (_e3607 + 1u);
                                } else {
                                    phi_3783_ = u32();
                                }
                                let _e3610 = phi_3783_;
                                continue;
                                continuing {
                                    let _e3611 = local_345;
                                    phi_3782_ = _e3610;
                                    phi_5030_ = _e3590;
                                    break if !(_e3611);
                                }
                            }
                            let _e3614 = phi_5030_;
                            phi_5055_ = _e3614;
                            if _e3614 {
                                break;
                            }
                            let _e3615 = local_235;
                            local_348 = _e3615[2];
                            phi_3803_ = 0u;
                            loop {
                                let _e3618 = phi_3803_;
                                local_349 = _e3618;
                                let _e3619 = local_349;
                                let _e3620 = (_e3619 < 1u);
                                local_350 = _e3620;
                                if _e3620 {
                                    let _e3621 = local;
                                    let _e3622 = local_349;
                                    let _e3624 = local_348;
                                    local_351 = bitcast<u32>(_e3624);
                                    let _e3626 = (512u + (_e3621 + _e3622));
                                    local_352 = _e3626;
                                    if (_e3626 < 5888u) {
                                    } else {
                                        phi_5033_ = true;
                                        break;
                                    }
                                    let _e3628 = local_352;
                                    let _e3630 = local_351;
                                    global_11[_e3628] = _e3630;
                                    let _e3631 = local_349;
                                    phi_3804_ = (_e3631 + 1u);
                                } else {
                                    phi_3804_ = u32();
                                }
                                let _e3634 = phi_3804_;
                                continue;
                                continuing {
                                    let _e3635 = local_350;
                                    phi_3803_ = _e3634;
                                    phi_5033_ = _e3614;
                                    break if !(_e3635);
                                }
                            }
                            let _e3638 = phi_5033_;
                            phi_5055_ = _e3638;
                            if _e3638 {
                                break;
                            }
                            phi_3823_ = 0u;
                            loop {
                                let _e3640 = phi_3823_;
                                local_353 = _e3640;
                                let _e3641 = local_353;
                                let _e3642 = (_e3641 < 1u);
                                local_354 = _e3642;
                                if _e3642 {
                                    let _e3643 = local;
                                    let _e3644 = local_353;
                                    let _e3646 = local_228;
                                    local_355 = bitcast<u32>(_e3646);
                                    let _e3648 = (768u + (_e3643 + _e3644));
                                    local_356 = _e3648;
                                    if (_e3648 < 5888u) {
                                    } else {
                                        phi_5036_ = true;
                                        break;
                                    }
                                    let _e3650 = local_356;
                                    let _e3652 = local_355;
                                    global_11[_e3650] = _e3652;
                                    let _e3653 = local_353;
                                    phi_3824_ = (_e3653 + 1u);
                                } else {
                                    phi_3824_ = u32();
                                }
                                let _e3656 = phi_3824_;
                                continue;
                                continuing {
                                    let _e3657 = local_354;
                                    phi_3823_ = _e3656;
                                    phi_5036_ = _e3638;
                                    break if !(_e3657);
                                }
                            }
                            let _e3660 = phi_5036_;
                            phi_5055_ = _e3660;
                            if _e3660 {
                                break;
                            }
                            phi_3844_ = 0u;
                            loop {
                                let _e3662 = phi_3844_;
                                local_357 = _e3662;
                                let _e3663 = local_357;
                                let _e3664 = (_e3663 < 1u);
                                local_358 = _e3664;
                                if _e3664 {
                                    let _e3665 = local_229;
                                    local_359 = bitcast<u32>(_e3665.member);
                                    let _e3668 = local_73;
                                    let _e3669 = local_357;
                                    let _e3670 = (_e3668 + _e3669);
                                    local_360 = _e3670;
                                    if (_e3670 < 5888u) {
                                    } else {
                                        phi_5039_ = true;
                                        break;
                                    }
                                    let _e3672 = local_360;
                                    let _e3674 = local_359;
                                    global_11[_e3672] = _e3674;
                                    let _e3675 = local_229;
                                    local_361 = bitcast<u32>(_e3675.member_1);
                                    let _e3678 = local_206;
                                    let _e3679 = local_357;
                                    let _e3680 = (_e3678 + _e3679);
                                    local_362 = _e3680;
                                    if (_e3680 < 5888u) {
                                    } else {
                                        phi_5039_ = true;
                                        break;
                                    }
                                    let _e3682 = local_362;
                                    let _e3684 = local_361;
                                    global_11[_e3682] = _e3684;
                                    let _e3685 = local_229;
                                    local_363 = bitcast<u32>(_e3685.member_2);
                                    let _e3688 = local_208;
                                    let _e3689 = local_357;
                                    let _e3690 = (_e3688 + _e3689);
                                    local_364 = _e3690;
                                    if (_e3690 < 5888u) {
                                    } else {
                                        phi_5039_ = true;
                                        break;
                                    }
                                    let _e3692 = local_364;
                                    let _e3694 = local_363;
                                    global_11[_e3692] = _e3694;
                                    let _e3695 = local_229;
                                    local_365 = select(0u, 1u, _e3695.member_3);
                                    let _e3698 = local_229;
                                    local_366 = (select(0u, 1u, _e3698.member_4) << bitcast<u32>(1i));
                                    let _e3703 = local_210;
                                    let _e3704 = local_357;
                                    let _e3705 = (_e3703 + _e3704);
                                    local_367 = _e3705;
                                    if (_e3705 < 5888u) {
                                    } else {
                                        phi_5039_ = true;
                                        break;
                                    }
                                    let _e3707 = local_367;
                                    let _e3709 = local_365;
                                    let _e3710 = local_366;
                                    global_11[_e3707] = (_e3709 | _e3710);
                                    let _e3712 = local_357;
                                    phi_3845_ = (_e3712 + 1u);
                                } else {
                                    phi_3845_ = u32();
                                }
                                let _e3715 = phi_3845_;
                                continue;
                                continuing {
                                    let _e3716 = local_358;
                                    phi_3844_ = _e3715;
                                    phi_5039_ = _e3660;
                                    break if !(_e3716);
                                }
                            }
                            let _e3719 = phi_5039_;
                            phi_5055_ = _e3719;
                            if _e3719 {
                                break;
                            }
                            phi_3900_ = 0u;
                            loop {
                                let _e3721 = phi_3900_;
                                local_368 = _e3721;
                                let _e3722 = local_368;
                                let _e3723 = (_e3722 < 1u);
                                local_369 = _e3723;
                                if _e3723 {
                                    let _e3724 = local;
                                    let _e3725 = local_368;
                                    local_370 = (_e3724 + _e3725);
                                    let _e3727 = local_234;
                                    if _e3727 {
                                        let _e3751 = local_233;
                                        let _e3753 = local_233;
                                        let _e3755 = local_233;
                                        phi_3960_ = false;
                                        phi_3961_ = select(select(u32(_e3751), 0u, (_e3753 < 0f)), 4294967295u, (_e3755 > 4294967000f));
                                    } else {
                                        let _e3728 = local_369;
                                        if _e3728 {
                                        } else {
                                            phi_5042_ = true;
                                            break;
                                        }
                                        let _e3729 = local_368;
                                        let _e3731 = local_455[_e3729];
                                        if _e3731 {
                                            let _e3732 = local_369;
                                            if _e3732 {
                                            } else {
                                                phi_5042_ = true;
                                                break;
                                            }
                                            let _e3733 = local_368;
                                            let _e3735 = local_456[_e3733];
                                            let _e3736 = local_446;
                                            if (_e3735 < _e3736) {
                                                let _e3738 = local_369;
                                                if _e3738 {
                                                } else {
                                                    phi_5042_ = true;
                                                    break;
                                                }
                                                let _e3739 = local_456[_e3733];
                                                phi_3949_ = (_e3739 + 1u);
                                            } else {
                                                phi_3949_ = _e1981;
                                            }
                                            let _e3742 = phi_3949_;
                                            let _e3743 = local_369;
                                            if _e3743 {
                                            } else {
                                                phi_5042_ = true;
                                                break;
                                            }
                                            let _e3744 = local_456[_e3733];
                                            let _e3745 = local_446;
                                            phi_3958_ = (_e3744 == _e3745);
                                            phi_3959_ = _e3742;
                                        } else {
                                            phi_3958_ = false;
                                            phi_3959_ = 0u;
                                        }
                                        let _e3748 = phi_3958_;
                                        let _e3750 = phi_3959_;
                                        phi_3960_ = _e3748;
                                        phi_3961_ = _e3750;
                                    }
                                    let _e3760 = phi_3960_;
                                    let _e3762 = phi_3961_;
                                    local_371 = _e3760;
                                    local_372 = _e3762;
                                    let _e3763 = local_369;
                                    if _e3763 {
                                    } else {
                                        phi_5042_ = true;
                                        break;
                                    }
                                    let _e3764 = local_368;
                                    let _e3766 = local_454[_e3764];
                                    if _e3766 {
                                        let _e3767 = local_370;
                                        let _e3768 = (1280u + _e3767);
                                        local_373 = _e3768;
                                        if (_e3768 < 5888u) {
                                        } else {
                                            phi_5042_ = true;
                                            break;
                                        }
                                        let _e3770 = local_373;
                                        let _e3772 = global_11[_e3770];
                                        let _e3773 = local_372;
                                        global_11[_e3770] = (_e3772 + _e3773);
                                    }
                                    let _e3775 = local_370;
                                    let _e3776 = (4352u + _e3775);
                                    local_374 = _e3776;
                                    if (_e3776 < 5888u) {
                                    } else {
                                        phi_5042_ = true;
                                        break;
                                    }
                                    let _e3778 = local_374;
                                    let _e3780 = local_371;
                                    global_11[_e3778] = select(0u, 1u, _e3780);
                                    let _e3782 = local_368;
                                    phi_3901_ = (_e3782 + 1u);
                                } else {
                                    phi_3901_ = u32();
                                }
                                let _e3785 = phi_3901_;
                                continue;
                                continuing {
                                    let _e3786 = local_369;
                                    phi_3900_ = _e3785;
                                    phi_5042_ = _e3719;
                                    break if !(_e3786);
                                }
                            }
                            let _e3789 = phi_5042_;
                            phi_5055_ = _e3789;
                            if _e3789 {
                                break;
                            }
                            storageBarrier();
                            workgroupBarrier();
                            phi_3994_ = 128u;
                            loop {
                                let _e3791 = phi_3994_;
                                local_375 = _e3791;
                                let _e3792 = local_375;
                                let _e3793 = (_e3792 > 0u);
                                local_376 = _e3793;
                                if _e3793 {
                                    let _e3794 = local;
                                    let _e3795 = local_375;
                                    if (_e3794 < _e3795) {
                                        let _e3797 = local_55;
                                        if _e3797 {
                                        } else {
                                            phi_5049_ = true;
                                            break;
                                        }
                                        let _e3798 = global_11[_e850];
                                        local_377 = _e3798;
                                        let _e3799 = local_54;
                                        let _e3800 = local_375;
                                        let _e3801 = (_e3799 + _e3800);
                                        local_378 = _e3801;
                                        if (_e3801 < 5888u) {
                                        } else {
                                            phi_5049_ = true;
                                            break;
                                        }
                                        let _e3803 = local_378;
                                        let _e3805 = global_11[_e3803];
                                        let _e3806 = local_377;
                                        let _e3808 = local_377;
                                        local_451 = select(_e3805, _e3808, (_e3806 > _e3805));
                                        let _e3810 = local_55;
                                        if _e3810 {
                                        } else {
                                            phi_5049_ = true;
                                            break;
                                        }
                                        let _e3811 = local_451;
                                        global_11[_e850] = _e3811;
                                    }
                                    storageBarrier();
                                    workgroupBarrier();
                                    let _e3812 = local_375;
                                    phi_3995_ = (_e3812 / 2u);
                                } else {
                                    phi_3995_ = u32();
                                }
                                let _e3815 = phi_3995_;
                                continue;
                                continuing {
                                    let _e3816 = local_376;
                                    phi_3994_ = _e3815;
                                    phi_5049_ = _e3789;
                                    break if !(_e3816);
                                }
                            }
                            let _e3819 = phi_5049_;
                            phi_5055_ = _e3819;
                            if _e3819 {
                                break;
                            }
                            let _e3820 = global_11[4352u];
                            storageBarrier();
                            workgroupBarrier();
                            let _e3821 = local_80;
                            phi_5057_ = _e3819;
                            phi_4039_ = (_e3821 + 256u);
                            phi_4040_ = _e3820;
                        }
                        let _e3824 = phi_5057_;
                        let _e3826 = phi_4039_;
                        let _e3828 = phi_4040_;
                        let _e3829 = local_82;
                        phi_5056_ = _e3824;
                        phi_636_ = _e3826;
                        phi_639_ = _e3828;
                        phi_4042_ = select(true, false, _e3829);
                    } else {
                        phi_5056_ = _e1011;
                        phi_636_ = u32();
                        phi_639_ = u32();
                        phi_4042_ = false;
                    }
                    let _e3832 = phi_5056_;
                    let _e3834 = phi_636_;
                    let _e3836 = phi_639_;
                    let _e3838 = phi_4042_;
                    local_379 = _e3838;
                    continue;
                    continuing {
                        let _e3839 = local_379;
                        phi_4765_ = _e3832;
                        phi_635_ = _e3834;
                        phi_638_ = _e3836;
                        phi_5055_ = _e3832;
                        break if !(_e3839);
                    }
                }
                let _e3842 = phi_5055_;
                if _e3842 {
                    break;
                }
                let _e3843 = local_33;
                if _e3843 {
                    break;
                }
                let _e3844 = local_33;
                if _e3844 {
                    break;
                }
                let _e3845 = local_67;
                if _e3845 {
                    let _e3846 = local_64;
                    let _e3847 = local_13;
                    let _e3848 = (_e3846 < _e3847);
                    local_380 = _e3848;
                    if _e3848 {
                        let _e3849 = local_65;
                        let _e3850 = local_14;
                        phi_4103_ = (_e3849 < _e3850);
                    } else {
                        phi_4103_ = bool();
                    }
                    let _e3853 = phi_4103_;
                    let _e3854 = local_380;
                    phi_4105_ = _e3853;
                    phi_4106_ = select(true, false, _e3854);
                } else {
                    phi_4105_ = bool();
                    phi_4106_ = true;
                }
                let _e3857 = phi_4105_;
                let _e3859 = phi_4106_;
                if select(_e3857, false, _e3859) {
                    let _e3861 = local_65;
                    let _e3862 = local_13;
                    let _e3864 = local_64;
                    let _e3865 = ((_e3861 * _e3862) + _e3864);
                    local_381 = _e3865;
                    let _e3866 = (4u * _e3865);
                    local_382 = _e3866;
                    let _e3867 = local_1;
                    if (_e3866 < _e3867) {
                    } else {
                        break;
                    }
                    let _e3869 = local_382;
                    let _e3872 = global_4.member[_e3869];
                    local_383 = bitcast<f32>(_e3872);
                    let _e3874 = local_382;
                    let _e3875 = (_e3874 + 1u);
                    local_384 = _e3875;
                    let _e3876 = local_1;
                    if (_e3875 < _e3876) {
                    } else {
                        break;
                    }
                    let _e3878 = local_384;
                    let _e3881 = global_4.member[_e3878];
                    local_385 = bitcast<f32>(_e3881);
                    let _e3883 = local_382;
                    let _e3884 = (_e3883 + 2u);
                    local_386 = _e3884;
                    let _e3885 = local_1;
                    if (_e3884 < _e3885) {
                    } else {
                        break;
                    }
                    let _e3887 = local_386;
                    let _e3890 = global_4.member[_e3887];
                    local_387 = bitcast<f32>(_e3890);
                    let _e3892 = local_382;
                    let _e3893 = (_e3892 + 3u);
                    local_388 = _e3893;
                    let _e3894 = local_1;
                    if (_e3893 < _e3894) {
                    } else {
                        break;
                    }
                    let _e3896 = local_388;
                    let _e3899 = global_4.member[_e3896];
                    local_389 = bitcast<f32>(_e3899);
                    let _e3901 = local;
                    let _e3902 = (768u + _e3901);
                    local_390 = _e3902;
                    let _e3903 = (_e3902 < 5888u);
                    local_391 = _e3903;
                    if _e3903 {
                    } else {
                        break;
                    }
                    let _e3904 = local_390;
                    let _e3906 = global_11[_e3904];
                    local_392 = (1f - bitcast<f32>(_e3906));
                    let _e3909 = local_389;
                    if ((bitcast<u32>(_e3909) & 2147483647u) > 2139095040u) {
                    } else {
                        let _e3913 = local_392;
                        if (_e3913 > 0f) {
                            let _e3915 = local;
                            let _e3916 = (_e3915 < 5888u);
                            local_393 = _e3916;
                            if _e3916 {
                            } else {
                                break;
                            }
                            let _e3917 = local;
                            let _e3919 = global_11[_e3917];
                            let _e3921 = local_392;
                            let _e3922 = local_383;
                            local_394 = bitcast<u32>((bitcast<f32>(_e3919) + (_e3921 * _e3922)));
                            let _e3926 = local_393;
                            if _e3926 {
                            } else {
                                break;
                            }
                            let _e3927 = local_394;
                            global_11[_e3917] = _e3927;
                            let _e3928 = local;
                            let _e3929 = (256u + _e3928);
                            local_395 = _e3929;
                            let _e3930 = (_e3929 < 5888u);
                            local_396 = _e3930;
                            if _e3930 {
                            } else {
                                break;
                            }
                            let _e3931 = local_395;
                            let _e3933 = global_11[_e3931];
                            let _e3935 = local_392;
                            let _e3936 = local_385;
                            local_397 = bitcast<u32>((bitcast<f32>(_e3933) + (_e3935 * _e3936)));
                            let _e3940 = local_396;
                            if _e3940 {
                            } else {
                                break;
                            }
                            let _e3941 = local_397;
                            global_11[_e3931] = _e3941;
                            let _e3942 = local;
                            let _e3943 = (512u + _e3942);
                            local_398 = _e3943;
                            let _e3944 = (_e3943 < 5888u);
                            local_399 = _e3944;
                            if _e3944 {
                            } else {
                                break;
                            }
                            let _e3945 = local_398;
                            let _e3947 = global_11[_e3945];
                            let _e3949 = local_392;
                            let _e3950 = local_387;
                            local_400 = bitcast<u32>((bitcast<f32>(_e3947) + (_e3949 * _e3950)));
                            let _e3954 = local_399;
                            if _e3954 {
                            } else {
                                break;
                            }
                            let _e3955 = local_400;
                            global_11[_e3945] = _e3955;
                            let _e3956 = local_391;
                            if _e3956 {
                            } else {
                                break;
                            }
                            let _e3957 = global_11[_e3904];
                            let _e3959 = local_392;
                            local_401 = bitcast<u32>((bitcast<f32>(_e3957) + _e3959));
                            let _e3962 = local_391;
                            if _e3962 {
                            } else {
                                break;
                            }
                            let _e3963 = local_401;
                            global_11[_e3904] = _e3963;
                        }
                    }
                    let _e3964 = local_391;
                    if _e3964 {
                    } else {
                        break;
                    }
                    let _e3965 = global_11[_e3904];
                    let _e3966 = bitcast<f32>(_e3965);
                    local_402 = _e3966;
                    if (_e3966 > 0.000001f) {
                        let _e3968 = local_402;
                        phi_4263_ = (1f / _e3968);
                    } else {
                        phi_4263_ = 0f;
                    }
                    let _e3971 = phi_4263_;
                    local_403 = _e3971;
                    let _e3972 = local;
                    if (_e3972 < 5888u) {
                    } else {
                        break;
                    }
                    let _e3974 = local;
                    let _e3976 = global_11[_e3974];
                    let _e3978 = local_403;
                    local_404 = (bitcast<f32>(_e3976) * _e3978);
                    let _e3980 = local;
                    let _e3981 = (256u + _e3980);
                    local_405 = _e3981;
                    if (_e3981 < 5888u) {
                    } else {
                        break;
                    }
                    let _e3983 = local_405;
                    let _e3985 = global_11[_e3983];
                    let _e3987 = local_403;
                    local_406 = (bitcast<f32>(_e3985) * _e3987);
                    let _e3989 = local;
                    let _e3990 = (512u + _e3989);
                    local_407 = _e3990;
                    if (_e3990 < 5888u) {
                    } else {
                        break;
                    }
                    let _e3992 = local_407;
                    let _e3994 = global_11[_e3992];
                    let _e3996 = local_403;
                    local_408 = (bitcast<f32>(_e3994) * _e3996);
                    let _e3998 = local_381;
                    let _e3999 = (3u * _e3998);
                    local_409 = _e3999;
                    let _e4000 = local_404;
                    local_410 = bitcast<u32>(_e4000);
                    let _e4002 = local_6;
                    if (_e3999 < _e4002) {
                    } else {
                        break;
                    }
                    let _e4004 = local_409;
                    let _e4007 = local_410;
                    global_2.member[_e4004] = _e4007;
                    let _e4008 = local_409;
                    let _e4009 = (_e4008 + 1u);
                    local_411 = _e4009;
                    let _e4010 = local_406;
                    local_412 = bitcast<u32>(_e4010);
                    let _e4012 = local_6;
                    if (_e4009 < _e4012) {
                    } else {
                        break;
                    }
                    let _e4014 = local_411;
                    let _e4017 = local_412;
                    global_2.member[_e4014] = _e4017;
                    let _e4018 = local_409;
                    let _e4019 = (_e4018 + 2u);
                    local_413 = _e4019;
                    let _e4020 = local_408;
                    local_414 = bitcast<u32>(_e4020);
                    let _e4022 = local_6;
                    if (_e4019 < _e4022) {
                    } else {
                        break;
                    }
                    let _e4024 = local_413;
                    let _e4027 = local_414;
                    global_2.member[_e4024] = _e4027;
                }
                storageBarrier();
                workgroupBarrier();
                phi_4328_ = _e563;
                phi_4331_ = 0u;
                phi_4333_ = 0u;
                loop {
                    let _e4029 = phi_4328_;
                    let _e4031 = phi_4331_;
                    let _e4033 = phi_4333_;
                    local_415 = _e4029;
                    local_416 = _e4031;
                    local_417 = _e4033;
                    let _e4034 = local;
                    let _e4036 = local_415;
                    let _e4037 = (_e4036 < (_e4034 + 1u));
                    local_418 = _e4037;
                    if _e4037 {
                        let _e4038 = local_415;
                        let _e4039 = (1280u + _e4038);
                        local_419 = _e4039;
                        if (_e4039 < 5888u) {
                        } else {
                            phi_5058_ = true;
                            break;
                        }
                        let _e4041 = local_419;
                        let _e4043 = global_11[_e4041];
                        local_420 = _e4043;
                        let _e4044 = local_33;
                        if _e4044 {
                            phi_5058_ = true;
                            break;
                        }
                        let _e4045 = local_415;
                        let _e4046 = local_441;
                        let _e4048 = local_40;
                        local_421 = (_e4048 + (_e4045 % _e4046));
                        let _e4050 = local_33;
                        if _e4050 {
                            phi_5058_ = true;
                            break;
                        }
                        let _e4051 = local_415;
                        let _e4052 = local_441;
                        let _e4054 = local_42;
                        local_422 = (_e4054 + (_e4051 / _e4052));
                        let _e4056 = local_415;
                        let _e4057 = local_66;
                        if (_e4056 < _e4057) {
                            let _e4059 = local_421;
                            let _e4060 = local_13;
                            let _e4061 = (_e4059 < _e4060);
                            local_423 = _e4061;
                            if _e4061 {
                                let _e4062 = local_422;
                                let _e4063 = local_14;
                                phi_4406_ = (_e4062 < _e4063);
                            } else {
                                phi_4406_ = bool();
                            }
                            let _e4066 = phi_4406_;
                            let _e4067 = local_423;
                            phi_4408_ = _e4066;
                            phi_4409_ = select(true, false, _e4067);
                        } else {
                            phi_4408_ = bool();
                            phi_4409_ = true;
                        }
                        let _e4070 = phi_4408_;
                        let _e4072 = phi_4409_;
                        if select(_e4070, false, _e4072) {
                            let _e4074 = local_420;
                            let _e4075 = local_48;
                            if (_e4074 < _e4075) {
                                let _e4077 = local_417;
                                let _e4079 = local_48;
                                let _e4080 = local_420;
                                let _e4082 = local_416;
                                phi_4424_ = (_e4082 + (_e4079 - _e4080));
                                phi_4425_ = (_e4077 + 1u);
                            } else {
                                phi_4424_ = _e4031;
                                phi_4425_ = _e4033;
                            }
                            let _e4085 = phi_4424_;
                            let _e4087 = phi_4425_;
                            phi_4426_ = _e4085;
                            phi_4427_ = _e4087;
                        } else {
                            phi_4426_ = _e4031;
                            phi_4427_ = _e4033;
                        }
                        let _e4089 = phi_4426_;
                        let _e4091 = phi_4427_;
                        let _e4092 = local_415;
                        phi_4329_ = (_e4092 + 1u);
                        phi_4332_ = _e4089;
                        phi_4334_ = _e4091;
                    } else {
                        phi_4329_ = u32();
                        phi_4332_ = u32();
                        phi_4334_ = u32();
                    }
                    let _e4095 = phi_4329_;
                    let _e4097 = phi_4332_;
                    let _e4099 = phi_4334_;
                    continue;
                    continuing {
                        let _e4100 = local_418;
                        phi_4328_ = _e4095;
                        phi_4331_ = _e4097;
                        phi_4333_ = _e4099;
                        phi_5058_ = _e3842;
                        break if !(_e4100);
                    }
                }
                let _e4103 = phi_5058_;
                if _e4103 {
                    break;
                }
                let _e4104 = local_417;
                if (_e4104 > 0u) {
                    let _e4106 = local_7;
                    if (9u < _e4106) {
                    } else {
                        break;
                    }
                    let _e4110 = local_417;
                    let _e4111 = atomicAdd((&global_9.member[9u]), _e4110);
                    let _e4112 = local_7;
                    if (10u < _e4112) {
                    } else {
                        break;
                    }
                    let _e4116 = local_416;
                    let _e4117 = atomicAdd((&global_9.member[10u]), _e4116);
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
