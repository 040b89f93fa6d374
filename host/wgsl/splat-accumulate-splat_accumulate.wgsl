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
    var local_251: bool;
    var local_252: f32;
    var local_253: bool;
    var local_254: f32;
    var local_255: f32;
    var local_256: bool;
    var local_257: u32;
    var local_258: u32;
    var local_259: f32;
    var local_260: u32;
    var local_261: f32;
    var local_262: bool;
    var local_263: f32;
    var local_264: f32;
    var local_265: f32;
    var local_266: f32;
    var local_267: f32;
    var local_268: f32;
    var local_269: f32;
    var local_270: bool;
    var local_271: f32;
    var local_272: bool;
    var local_273: bool;
    var local_274: bool;
    var local_275: u32;
    var local_276: f32;
    var local_277: f32;
    var local_278: f32;
    var local_279: f32;
    var local_280: f32;
    var local_281: f32;
    var local_282: f32;
    var local_283: bool;
    var local_284: f32;
    var local_285: f32;
    var local_286: f32;
    var local_287: f32;
    var local_288: bool;
    var local_289: u32;
    var local_290: f32;
    var local_291: f32;
    var local_292: f32;
    var local_293: bool;
    var local_294: u32;
    var local_295: f32;
    var local_296: f32;
    var local_297: u32;
    var local_298: f32;
    var local_299: u32;
    var local_300: f32;
    var local_301: u32;
    var local_302: f32;
    var local_303: array<f32, 2>;
    var local_304: bool;
    var local_305: f32;
    var local_306: u32;
    var local_307: f32;
    var local_308: u32;
    var local_309: f32;
    var local_310: u32;
    var local_311: f32;
    var local_312: f32;
    var local_313: f32;
    var local_314: f32;
    var local_315: bool;
    var local_316: bool;
    var local_317: bool;
    var local_318: bool;
    var local_319: f32;
    var local_320: f32;
    var local_321: bool;
    var local_322: f32;
    var local_323: f32;
    var local_324: bool;
    var local_325: f32;
    var local_326: bool;
    var local_327: f32;
    var local_328: f32;
    var local_329: bool;
    var local_330: f32;
    var local_331: f32;
    var local_332: f32;
    var local_333: u32;
    var local_334: f32;
    var local_335: u32;
    var local_336: f32;
    var local_337: u32;
    var local_338: bool;
    var local_339: f32;
    var local_340: u32;
    var local_341: bool;
    var local_342: u32;
    var local_343: u32;
    var local_344: f32;
    var local_345: u32;
    var local_346: bool;
    var local_347: u32;
    var local_348: u32;
    var local_349: f32;
    var local_350: u32;
    var local_351: bool;
    var local_352: u32;
    var local_353: u32;
    var local_354: u32;
    var local_355: bool;
    var local_356: u32;
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
    var local_370: bool;
    var local_371: u32;
    var local_372: bool;
    var local_373: u32;
    var local_374: u32;
    var local_375: u32;
    var local_376: u32;
    var local_377: bool;
    var local_378: u32;
    var local_379: u32;
    var local_380: bool;
    var local_381: bool;
    var local_382: u32;
    var local_383: u32;
    var local_384: f32;
    var local_385: u32;
    var local_386: f32;
    var local_387: u32;
    var local_388: f32;
    var local_389: u32;
    var local_390: f32;
    var local_391: u32;
    var local_392: bool;
    var local_393: f32;
    var local_394: bool;
    var local_395: u32;
    var local_396: u32;
    var local_397: bool;
    var local_398: u32;
    var local_399: u32;
    var local_400: bool;
    var local_401: u32;
    var local_402: u32;
    var local_403: f32;
    var local_404: f32;
    var local_405: f32;
    var local_406: u32;
    var local_407: f32;
    var local_408: u32;
    var local_409: f32;
    var local_410: u32;
    var local_411: u32;
    var local_412: u32;
    var local_413: u32;
    var local_414: u32;
    var local_415: u32;
    var local_416: u32;
    var local_417: u32;
    var local_418: u32;
    var local_419: bool;
    var local_420: u32;
    var local_421: u32;
    var local_422: u32;
    var local_423: u32;
    var local_424: bool;
    var local_425: u32;
    var local_426: u32;
    var local_427: bool;
    var local_428: u32;
    var local_429: u32;
    var local_430: f32;
    var local_431: u32;
    var local_432: f32;
    var local_433: u32;
    var local_434: u32;
    var local_435: array<f32, 3>;
    var local_436: u32;
    var local_437: u32;
    var local_438: u32;
    var local_439: u32;
    var local_440: u32;
    var local_441: u32;
    var local_442: u32;
    var local_443: u32;
    var local_444: f32;
    var local_445: f32;
    var local_446: f32;
    var local_447: u32;
    var local_448: bool;
    var local_449: f32;
    var local_450: bool;
    var local_451: f32;
    var local_452: f32;
    var local_453: u32;
    var local_454: array<u32, 1>;
    var local_455: array<bool, 1>;
    var local_456: array<bool, 1>;
    var local_457: array<bool, 1>;
    var local_458: array<u32, 1>;
    var local_459: array<bool, 1>;
    var phi_4696_: bool;
    var phi_4698_: bool;
    var phi_4699_: bool;
    var phi_4754_: array<f32, 3>;
    var phi_362_: u32;
    var phi_365_: u32;
    var phi_397_: u32;
    var phi_363_: u32;
    var phi_366_: u32;
    var phi_4901_: bool;
    var phi_494_: u32;
    var phi_495_: u32;
    var phi_4908_: bool;
    var phi_544_: u32;
    var phi_545_: u32;
    var phi_4931_: bool;
    var phi_617_: bool;
    var phi_619_: bool;
    var phi_620_: bool;
    var phi_665_: f32;
    var phi_676_: u32;
    var phi_677_: u32;
    var phi_4936_: bool;
    var phi_4968_: bool;
    var phi_727_: u32;
    var phi_730_: u32;
    var phi_810_: array<f32, 3>;
    var phi_821_: f32;
    var phi_847_: u32;
    var phi_860_: u32;
    var phi_899_: type_29;
    var phi_913_: f32;
    var phi_942_: bool;
    var phi_970_: f32;
    var phi_971_: f32;
    var phi_977_: f32;
    var phi_979_: f32;
    var phi_4958_: bool;
    var phi_1094_: f32;
    var phi_1097_: f32;
    var phi_1108_: f32;
    var phi_1111_: f32;
    var phi_1135_: bool;
    var phi_1171_: bool;
    var phi_1507_: u32;
    var phi_1510_: f32;
    var phi_1512_: array<f32, 2>;
    var phi_1508_: u32;
    var phi_1511_: f32;
    var phi_1513_: array<f32, 2>;
    var phi_1565_: f32;
    var phi_1287_: f32;
    var phi_1288_: f32;
    var phi_1289_: bool;
    var phi_1290_: f32;
    var phi_1291_: bool;
    var phi_1292_: f32;
    var phi_1293_: bool;
    var phi_1343_: f32;
    var phi_1344_: f32;
    var phi_1345_: bool;
    var phi_1346_: f32;
    var phi_1347_: bool;
    var phi_1348_: f32;
    var phi_1349_: bool;
    var phi_1399_: f32;
    var phi_1400_: f32;
    var phi_1401_: bool;
    var phi_1402_: f32;
    var phi_1403_: bool;
    var phi_1404_: f32;
    var phi_1405_: bool;
    var phi_1456_: f32;
    var phi_1457_: f32;
    var phi_1458_: bool;
    var phi_1459_: f32;
    var phi_1460_: bool;
    var phi_1461_: f32;
    var phi_1462_: bool;
    var phi_1473_: f32;
    var phi_1475_: f32;
    var phi_1476_: bool;
    var phi_1477_: f32;
    var phi_1478_: bool;
    var phi_1479_: f32;
    var phi_1480_: bool;
    var phi_1485_: f32;
    var phi_1578_: f32;
    var phi_1579_: f32;
    var phi_1580_: f32;
    var phi_1586_: u32;
    var phi_1589_: f32;
    var phi_1587_: u32;
    var phi_1590_: f32;
    var phi_1109_: f32;
    var phi_1112_: f32;
    var phi_4947_: bool;
    var phi_5015_: bool;
    var phi_1095_: f32;
    var phi_1098_: f32;
    var phi_5014_: bool;
    var phi_1079_: f32;
    var phi_5032_: bool;
    var phi_1602_: f32;
    var phi_5031_: bool;
    var phi_1604_: f32;
    var phi_1606_: u32;
    var phi_1607_: u32;
    var phi_1628_: bool;
    var phi_5027_: bool;
    var phi_1733_: u32;
    var phi_1799_: bool;
    var phi_1801_: bool;
    var phi_1802_: bool;
    var phi_1734_: u32;
    var phi_5016_: bool;
    var phi_2033_: u32;
    var phi_2054_: bool;
    var phi_2034_: u32;
    var phi_5034_: bool;
    var phi_5046_: bool;
    var phi_2067_: u32;
    var phi_2097_: u32;
    var phi_2100_: u32;
    var phi_2124_: u32;
    var phi_2098_: u32;
    var phi_2101_: u32;
    var phi_5042_: bool;
    var phi_5049_: bool;
    var phi_2126_: u32;
    var phi_5048_: bool;
    var phi_2068_: u32;
    var phi_5047_: bool;
    var phi_5055_: bool;
    var phi_2157_: f32;
    var phi_2160_: type_31;
    var phi_2162_: u32;
    var phi_2164_: u32;
    var phi_2166_: f32;
    var phi_2168_: f32;
    var phi_2170_: bool;
    var phi_2172_: array<f32, 3>;
    var phi_3136_: bool;
    var phi_3182_: bool;
    var phi_3518_: u32;
    var phi_3521_: f32;
    var phi_3523_: array<f32, 2>;
    var phi_3519_: u32;
    var phi_3522_: f32;
    var phi_3524_: array<f32, 2>;
    var phi_3576_: f32;
    var phi_3298_: f32;
    var phi_3299_: f32;
    var phi_3300_: bool;
    var phi_3301_: f32;
    var phi_3302_: bool;
    var phi_3303_: f32;
    var phi_3304_: bool;
    var phi_3354_: f32;
    var phi_3355_: f32;
    var phi_3356_: bool;
    var phi_3357_: f32;
    var phi_3358_: bool;
    var phi_3359_: f32;
    var phi_3360_: bool;
    var phi_3410_: f32;
    var phi_3411_: f32;
    var phi_3412_: bool;
    var phi_3413_: f32;
    var phi_3414_: bool;
    var phi_3415_: f32;
    var phi_3416_: bool;
    var phi_3467_: f32;
    var phi_3468_: f32;
    var phi_3469_: bool;
    var phi_3470_: f32;
    var phi_3471_: bool;
    var phi_3472_: f32;
    var phi_3473_: bool;
    var phi_3484_: f32;
    var phi_3486_: f32;
    var phi_3487_: bool;
    var phi_3488_: f32;
    var phi_3489_: bool;
    var phi_3490_: f32;
    var phi_3491_: bool;
    var phi_3496_: f32;
    var phi_3589_: f32;
    var phi_3590_: f32;
    var phi_3591_: f32;
    var phi_2260_: u32;
    var phi_2263_: f32;
    var phi_2265_: u32;
    var phi_3076_: f32;
    var phi_3081_: f32;
    var phi_3100_: f32;
    var phi_3103_: f32;
    var phi_3104_: u32;
    var phi_3106_: u32;
    var phi_3107_: f32;
    var phi_3108_: u32;
    var phi_2261_: u32;
    var phi_2264_: f32;
    var phi_2266_: u32;
    var phi_3109_: bool;
    var phi_5050_: bool;
    var phi_3120_: f32;
    var phi_5179_: bool;
    var phi_3125_: f32;
    var phi_5178_: bool;
    var phi_3592_: f32;
    var phi_3753_: f32;
    var phi_3677_: f32;
    var phi_3687_: type_18;
    var phi_3688_: type_18;
    var phi_3700_: f32;
    var phi_3711_: type_18;
    var phi_3763_: type_31;
    var phi_3764_: type_18;
    var phi_3849_: u32;
    var phi_3850_: f32;
    var phi_3851_: f32;
    var phi_3852_: bool;
    var phi_5158_: bool;
    var phi_3853_: f32;
    var phi_3854_: type_31;
    var phi_3855_: u32;
    var phi_3856_: f32;
    var phi_3857_: f32;
    var phi_3858_: bool;
    var phi_3859_: array<f32, 3>;
    var phi_5157_: bool;
    var phi_2158_: f32;
    var phi_2161_: type_31;
    var phi_2163_: u32;
    var phi_2165_: u32;
    var phi_2167_: f32;
    var phi_2169_: f32;
    var phi_2171_: bool;
    var phi_2173_: array<f32, 3>;
    var phi_5156_: bool;
    var phi_3863_: u32;
    var phi_3864_: u32;
    var phi_5232_: bool;
    var phi_3884_: u32;
    var phi_3885_: u32;
    var phi_5235_: bool;
    var phi_3905_: u32;
    var phi_3906_: u32;
    var phi_5238_: bool;
    var phi_3925_: u32;
    var phi_3926_: u32;
    var phi_5241_: bool;
    var phi_3946_: u32;
    var phi_3947_: u32;
    var phi_5244_: bool;
    var phi_4002_: u32;
    var phi_4051_: u32;
    var phi_4060_: bool;
    var phi_4061_: u32;
    var phi_4062_: bool;
    var phi_4063_: u32;
    var phi_4003_: u32;
    var phi_5247_: bool;
    var phi_4182_: u32;
    var phi_4183_: u32;
    var phi_5254_: bool;
    var phi_5280_: bool;
    var phi_4232_: u32;
    var phi_4233_: u32;
    var phi_5279_: bool;
    var phi_728_: u32;
    var phi_731_: u32;
    var phi_4235_: bool;
    var phi_5278_: bool;
    var phi_4296_: bool;
    var phi_4298_: bool;
    var phi_4299_: bool;
    var phi_4456_: f32;
    var phi_4521_: u32;
    var phi_4524_: u32;
    var phi_4526_: u32;
    var phi_4599_: bool;
    var phi_4601_: bool;
    var phi_4602_: bool;
    var phi_4617_: u32;
    var phi_4618_: u32;
    var phi_4619_: u32;
    var phi_4620_: u32;
    var phi_4522_: u32;
    var phi_4525_: u32;
    var phi_4527_: u32;
    var phi_5283_: bool;
    var local_460: f32;
    var local_461: f32;
    var local_462: f32;
    var local_463: u32;

    let _e563 = global_12;
    let _e564 = bitcast<f32>(_e563);
    switch bitcast<i32>(0u) {
        default: {
            let _e566 = global;
            local = _e566;
            let _e567 = global_1;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_2.member));
            let _e582 = arrayLength((&global_9.member));
            local_7 = _e582;
            local_8 = arrayLength((&global_10.member));
            local_9 = _e567.x;
            local_10 = _e567.y;
            let _e587 = global_3.member;
            local_11 = _e587;
            if (18u < _e582) {
            } else {
                break;
            }
            let _e589 = local_7;
            if (19u < _e589) {
            } else {
                break;
            }
            let _e593 = atomicLoad((&global_9.member[19u]));
            local_12 = bitcast<f32>(_e593);
            let _e595 = local_11;
            local_13 = _e595.member;
            let _e597 = local_11;
            local_14 = _e597.member_1;
            let _e599 = local_11;
            local_15 = _e599.member_2;
            let _e601 = local_11;
            local_16 = _e601.member_3;
            let _e603 = local_11;
            local_17 = _e603.member_6;
            let _e605 = local_11;
            local_18 = _e605.member_7;
            let _e607 = local_11;
            local_19 = _e607.member_8;
            let _e609 = local_11;
            local_20 = _e609.member_10;
            let _e611 = local_11;
            local_21 = _e611.member_15.member;
            local_22 = _e611.member_15.member_1;
            local_23 = _e611.member_15.member_2;
            local_24 = _e611.member_15.member_3;
            let _e617 = local_11;
            local_25 = _e617.member_16.member;
            local_26 = _e617.member_16.member_1;
            local_27 = _e617.member_16.member_2;
            local_28 = _e617.member_16.member_3[0];
            local_29 = _e617.member_16.member_3[1];
            local_30 = _e617.member_16.member_4;
            local_31 = _e617.member_16.member_5;
            local_32 = _e617.member_16.member_6;
            let _e629 = select(16u, 12u, (_e603.member_6 == 24u));
            local_442 = _e629;
            let _e630 = (_e629 == 0u);
            local_33 = _e630;
            if _e630 {
                break;
            }
            let _e631 = local_17;
            let _e632 = local_442;
            let _e633 = (_e631 / _e632);
            local_34 = _e633;
            let _e634 = (_e633 == 0u);
            local_35 = _e634;
            if _e634 {
                break;
            }
            let _e635 = local_9;
            let _e636 = local_34;
            local_36 = (_e635 / _e636);
            let _e638 = local_35;
            if _e638 {
                break;
            }
            let _e639 = local_10;
            let _e640 = local_34;
            let _e641 = (_e639 / _e640);
            local_37 = _e641;
            let _e642 = local_18;
            let _e644 = local_36;
            local_38 = ((_e641 * _e642) + _e644);
            let _e646 = local_36;
            let _e647 = local_17;
            local_39 = (_e646 * _e647);
            let _e649 = local_35;
            if _e649 {
                break;
            }
            let _e650 = local_9;
            let _e651 = local_34;
            let _e653 = local_442;
            let _e655 = local_39;
            local_40 = (_e655 + ((_e650 % _e651) * _e653));
            let _e657 = local_37;
            let _e658 = local_17;
            local_41 = (_e657 * _e658);
            let _e660 = local_35;
            if _e660 {
                break;
            }
            let _e661 = local_10;
            let _e662 = local_34;
            let _e664 = local_442;
            let _e666 = local_41;
            local_42 = (_e666 + ((_e661 % _e662) * _e664));
            let _e668 = local_38;
            let _e669 = local_5;
            if (_e668 < _e669) {
            } else {
                break;
            }
            let _e671 = local_38;
            let _e674 = global_8.member[_e671];
            local_43 = _e674;
            if ((_e674 & 1u) == 0u) {
                let _e789 = local_43;
                local_44 = (_e789 >> bitcast<u32>(1u));
                let _e792 = local_38;
                let _e793 = (2u * _e792);
                local_45 = _e793;
                let _e794 = local_4;
                if (_e793 < _e794) {
                } else {
                    break;
                }
                let _e796 = local_45;
                let _e799 = global_7.member[_e796];
                local_46 = _e799;
                let _e800 = local_45;
                let _e801 = (_e800 + 1u);
                local_47 = _e801;
                let _e802 = local_4;
                if (_e801 < _e802) {
                } else {
                    break;
                }
                let _e804 = local_47;
                let _e807 = global_7.member[_e804];
                local_48 = _e807;
                phi_362_ = _e566;
                phi_365_ = 0u;
                loop {
                    let _e809 = phi_362_;
                    let _e811 = phi_365_;
                    local_49 = _e809;
                    local_50 = _e811;
                    let _e812 = local_49;
                    let _e813 = local_48;
                    let _e814 = (_e812 < _e813);
                    local_51 = _e814;
                    if _e814 {
                        let _e815 = local_46;
                        let _e816 = local_49;
                        let _e817 = (_e815 + _e816);
                        local_52 = _e817;
                        let _e818 = local_3;
                        if (_e817 < _e818) {
                        } else {
                            phi_4901_ = true;
                            break;
                        }
                        let _e820 = local_52;
                        let _e823 = global_6.member[_e820];
                        let _e825 = ((4u * _e823) + 1u);
                        local_53 = _e825;
                        let _e826 = local_2;
                        if (_e825 < _e826) {
                        } else {
                            phi_4901_ = true;
                            break;
                        }
                        let _e828 = local_53;
                        let _e831 = global_5.member[_e828];
                        if (((_e831 >> bitcast<u32>(14u)) & 1023u) == 1023u) {
                            phi_397_ = _e811;
                        } else {
                            let _e836 = local_49;
                            phi_397_ = (_e836 + 1u);
                        }
                        let _e839 = phi_397_;
                        let _e840 = local_49;
                        phi_363_ = (_e840 + 256u);
                        phi_366_ = _e839;
                    } else {
                        phi_363_ = u32();
                        phi_366_ = u32();
                    }
                    let _e843 = phi_363_;
                    let _e845 = phi_366_;
                    continue;
                    continuing {
                        let _e846 = local_51;
                        phi_362_ = _e843;
                        phi_365_ = _e845;
                        phi_4901_ = false;
                        break if !(_e846);
                    }
                }
                let _e849 = phi_4901_;
                if _e849 {
                    break;
                }
                let _e850 = local;
                let _e851 = (4352u + _e850);
                local_54 = _e851;
                let _e852 = (_e851 < 5888u);
                local_55 = _e852;
                if _e852 {
                } else {
                    break;
                }
                let _e853 = local_54;
                let _e855 = local_50;
                global_11[_e853] = _e855;
                storageBarrier();
                workgroupBarrier();
                phi_494_ = 128u;
                loop {
                    let _e857 = phi_494_;
                    local_56 = _e857;
                    let _e858 = local_56;
                    let _e859 = (_e858 > 0u);
                    local_57 = _e859;
                    if _e859 {
                        let _e860 = local;
                        let _e861 = local_56;
                        if (_e860 < _e861) {
                            let _e863 = local_55;
                            if _e863 {
                            } else {
                                phi_4908_ = true;
                                break;
                            }
                            let _e864 = global_11[_e853];
                            local_58 = _e864;
                            let _e865 = local_54;
                            let _e866 = local_56;
                            let _e867 = (_e865 + _e866);
                            local_59 = _e867;
                            if (_e867 < 5888u) {
                            } else {
                                phi_4908_ = true;
                                break;
                            }
                            let _e869 = local_59;
                            let _e871 = global_11[_e869];
                            let _e872 = local_58;
                            let _e874 = local_58;
                            local_443 = select(_e871, _e874, (_e872 > _e871));
                            let _e876 = local_55;
                            if _e876 {
                            } else {
                                phi_4908_ = true;
                                break;
                            }
                            let _e877 = local_443;
                            global_11[_e853] = _e877;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e878 = local_56;
                        phi_495_ = (_e878 / 2u);
                    } else {
                        phi_495_ = u32();
                    }
                    let _e881 = phi_495_;
                    continue;
                    continuing {
                        let _e882 = local_57;
                        phi_494_ = _e881;
                        phi_4908_ = _e849;
                        break if !(_e882);
                    }
                }
                let _e885 = phi_4908_;
                if _e885 {
                    break;
                }
                let _e887 = global_11[4352u];
                local_60 = _e887;
                storageBarrier();
                workgroupBarrier();
                phi_544_ = 0u;
                loop {
                    let _e889 = phi_544_;
                    local_61 = _e889;
                    let _e890 = local_61;
                    let _e891 = (_e890 <= 1280u);
                    local_62 = _e891;
                    if _e891 {
                        let _e892 = local_61;
                        let _e893 = local;
                        let _e894 = (_e892 + _e893);
                        local_63 = _e894;
                        if (_e894 < 5888u) {
                        } else {
                            phi_4931_ = true;
                            break;
                        }
                        let _e896 = local_63;
                        global_11[_e896] = 0u;
                        let _e898 = local_61;
                        phi_545_ = (_e898 + 256u);
                    } else {
                        phi_545_ = u32();
                    }
                    let _e901 = phi_545_;
                    continue;
                    continuing {
                        let _e902 = local_62;
                        phi_544_ = _e901;
                        phi_4931_ = _e885;
                        break if !(_e902);
                    }
                }
                let _e905 = phi_4931_;
                if _e905 {
                    break;
                }
                let _e906 = local_33;
                if _e906 {
                    break;
                }
                let _e907 = local;
                let _e908 = local_442;
                let _e910 = local_40;
                local_64 = (_e910 + (_e907 % _e908));
                let _e912 = local_33;
                if _e912 {
                    break;
                }
                let _e913 = local;
                let _e914 = local_442;
                let _e916 = local_42;
                local_65 = (_e916 + (_e913 / _e914));
                let _e918 = local_442;
                let _e919 = local_442;
                let _e920 = (_e918 * _e919);
                local_66 = _e920;
                let _e921 = local;
                let _e922 = (_e921 < _e920);
                local_67 = _e922;
                if _e922 {
                    let _e923 = local_64;
                    let _e924 = local_13;
                    let _e925 = (_e923 < _e924);
                    local_68 = _e925;
                    if _e925 {
                        let _e926 = local_65;
                        let _e927 = local_14;
                        phi_617_ = (_e926 < _e927);
                    } else {
                        phi_617_ = bool();
                    }
                    let _e930 = phi_617_;
                    let _e931 = local_68;
                    phi_619_ = _e930;
                    phi_620_ = select(true, false, _e931);
                } else {
                    phi_619_ = bool();
                    phi_620_ = true;
                }
                let _e934 = phi_619_;
                let _e936 = phi_620_;
                if select(_e934, false, _e936) {
                    let _e938 = local_65;
                    let _e939 = local_13;
                    let _e941 = local_64;
                    let _e943 = (4u * ((_e938 * _e939) + _e941));
                    local_69 = _e943;
                    let _e944 = local_1;
                    if (_e943 < _e944) {
                    } else {
                        break;
                    }
                    let _e946 = local_69;
                    let _e948 = local_1;
                    if ((_e946 + 1u) < _e948) {
                    } else {
                        break;
                    }
                    let _e950 = local_69;
                    let _e952 = local_1;
                    if ((_e950 + 2u) < _e952) {
                    } else {
                        break;
                    }
                    let _e954 = local_69;
                    let _e955 = (_e954 + 3u);
                    local_70 = _e955;
                    let _e956 = local_1;
                    if (_e955 < _e956) {
                    } else {
                        break;
                    }
                    let _e958 = local_70;
                    let _e961 = global_4.member[_e958];
                    phi_665_ = bitcast<f32>(_e961);
                } else {
                    phi_665_ = _e564;
                }
                let _e964 = phi_665_;
                local_71 = bitcast<u32>(_e964);
                let _e966 = local;
                let _e967 = (1024u + _e966);
                local_72 = _e967;
                if (_e967 < 5888u) {
                } else {
                    break;
                }
                let _e969 = local_72;
                let _e971 = local_71;
                global_11[_e969] = _e971;
                let _e972 = local;
                local_73 = (4608u + _e972);
                phi_676_ = 0u;
                loop {
                    let _e975 = phi_676_;
                    local_74 = _e975;
                    let _e976 = local_74;
                    let _e977 = (_e976 < 1u);
                    local_75 = _e977;
                    if _e977 {
                        let _e978 = local_73;
                        let _e979 = local_74;
                        let _e980 = (_e978 + _e979);
                        local_76 = _e980;
                        if (_e980 < 5888u) {
                        } else {
                            phi_4936_ = true;
                            break;
                        }
                        let _e982 = local_76;
                        global_11[_e982] = 2143289344u;
                        let _e984 = local;
                        let _e986 = local_74;
                        let _e987 = ((_e984 + 4864u) + _e986);
                        local_77 = _e987;
                        if (_e987 < 5888u) {
                        } else {
                            phi_4936_ = true;
                            break;
                        }
                        let _e989 = local_77;
                        global_11[_e989] = 0u;
                        let _e991 = local;
                        let _e993 = local_74;
                        let _e994 = ((_e991 + 5120u) + _e993);
                        local_78 = _e994;
                        if (_e994 < 5888u) {
                        } else {
                            phi_4936_ = true;
                            break;
                        }
                        let _e996 = local_78;
                        global_11[_e996] = 1065353216u;
                        let _e998 = local;
                        let _e1000 = local_74;
                        let _e1001 = ((_e998 + 5376u) + _e1000);
                        local_79 = _e1001;
                        if (_e1001 < 5888u) {
                        } else {
                            phi_4936_ = true;
                            break;
                        }
                        let _e1003 = local_79;
                        global_11[_e1003] = 1u;
                        let _e1005 = local_74;
                        phi_677_ = (_e1005 + 1u);
                    } else {
                        phi_677_ = u32();
                    }
                    let _e1008 = phi_677_;
                    continue;
                    continuing {
                        let _e1009 = local_75;
                        phi_676_ = _e1008;
                        phi_4936_ = _e905;
                        break if !(_e1009);
                    }
                }
                let _e1012 = phi_4936_;
                if _e1012 {
                    break;
                }
                storageBarrier();
                workgroupBarrier();
                phi_4968_ = _e1012;
                phi_727_ = 0u;
                phi_730_ = 1u;
                loop {
                    let _e1014 = phi_4968_;
                    let _e1016 = phi_727_;
                    let _e1018 = phi_730_;
                    local_80 = _e1016;
                    local_81 = _e1018;
                    let _e1019 = local_80;
                    let _e1020 = local_48;
                    if (_e1019 < _e1020) {
                        let _e1022 = local_81;
                        let _e1023 = (_e1022 == 0u);
                        local_82 = _e1023;
                        if _e1023 {
                            phi_5280_ = _e1014;
                            phi_4232_ = u32();
                            phi_4233_ = u32();
                        } else {
                            let _e1024 = local_80;
                            let _e1025 = local;
                            let _e1026 = (_e1024 + _e1025);
                            local_83 = _e1026;
                            let _e1027 = local_48;
                            if (_e1026 < _e1027) {
                                let _e1029 = local_46;
                                let _e1030 = local_83;
                                let _e1031 = (_e1029 + _e1030);
                                local_84 = _e1031;
                                let _e1032 = local_3;
                                if (_e1031 < _e1032) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1034 = local_84;
                                let _e1037 = global_6.member[_e1034];
                                local_85 = _e1037;
                                let _e1038 = (4u * _e1037);
                                local_86 = _e1038;
                                let _e1039 = local_2;
                                if (_e1038 < _e1039) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1041 = local_86;
                                let _e1044 = global_5.member[_e1041];
                                local_87 = _e1044;
                                let _e1045 = local_86;
                                let _e1046 = (_e1045 + 1u);
                                local_88 = _e1046;
                                let _e1047 = local_2;
                                if (_e1046 < _e1047) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1049 = local_88;
                                let _e1052 = global_5.member[_e1049];
                                local_89 = _e1052;
                                let _e1053 = local_86;
                                let _e1054 = (_e1053 + 2u);
                                local_90 = _e1054;
                                let _e1055 = local_2;
                                if (_e1054 < _e1055) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1057 = local_90;
                                let _e1060 = global_5.member[_e1057];
                                local_91 = _e1060;
                                let _e1061 = local_86;
                                let _e1062 = (_e1061 + 3u);
                                local_92 = _e1062;
                                let _e1063 = local_2;
                                if (_e1062 < _e1063) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1065 = local_92;
                                let _e1068 = global_5.member[_e1065];
                                local_93 = _e1068;
                                let _e1069 = local_87;
                                local_94 = (_e1069 & 16383u);
                                let _e1071 = local_87;
                                local_95 = ((_e1071 >> bitcast<u32>(14u)) & 16383u);
                                let _e1075 = local_89;
                                local_96 = (_e1075 & 16383u);
                                let _e1077 = local_89;
                                let _e1079 = (_e1077 >> bitcast<u32>(24i));
                                local_97 = _e1079;
                                if (_e1079 == 0u) {
                                    phi_810_ = array<f32, 3>(0f, 0f, 0f);
                                } else {
                                    let _e1081 = local_97;
                                    let _e1087 = bitcast<f32>((bitcast<u32>((bitcast<i32>(_e1081) + -13i)) << bitcast<u32>(23i)));
                                    let _e1088 = local_94;
                                    let _e1091 = local_95;
                                    let _e1094 = local_96;
                                    phi_810_ = array<f32, 3>((f32(_e1088) * _e1087), (f32(_e1091) * _e1087), (f32(_e1094) * _e1087));
                                }
                                let _e1099 = phi_810_;
                                local_98 = _e1099;
                                let _e1100 = local_89;
                                let _e1103 = ((_e1100 >> bitcast<u32>(14u)) & 1023u);
                                local_99 = _e1103;
                                if (_e1103 >= 1023u) {
                                    phi_821_ = 1f;
                                } else {
                                    let _e1105 = local_99;
                                    phi_821_ = (f32(_e1105) * 0.0009775171f);
                                }
                                let _e1109 = phi_821_;
                                local_100 = _e1109;
                                let _e1110 = local_91;
                                let _e1111 = bitcast<f32>(_e1110);
                                local_101 = _e1111;
                                let _e1112 = local_87;
                                let _e1115 = ((_e1112 >> bitcast<u32>(28i)) & 3u);
                                local_102 = _e1115;
                                let _e1116 = local_93;
                                let _e1118 = local_93;
                                let _e1121 = array<u32, 2>((_e1116 & 65535u), (_e1118 >> bitcast<u32>(16i)));
                                local_103 = _e1121;
                                let _e1122 = local_98;
                                let _e1124 = local_20;
                                let _e1127 = ((_e1124 >> bitcast<u32>(8u)) & 7u);
                                local_104 = _e1127;
                                if (_e1127 == 0u) {
                                    phi_899_ = type_29(_e1121, _e1122, _e1109, _e1111, _e1115, 0u);
                                } else {
                                    let _e1129 = local_104;
                                    let _e1130 = local_104;
                                    let _e1131 = (_e1129 * _e1130);
                                    local_105 = _e1131;
                                    if (_e1131 <= 1u) {
                                        phi_847_ = 1u;
                                    } else {
                                        let _e1133 = local_105;
                                        phi_847_ = select(16u, 4u, (_e1133 <= 4u));
                                    }
                                    let _e1137 = phi_847_;
                                    local_106 = _e1137;
                                    if (_e1137 == 0u) {
                                        phi_5278_ = true;
                                        break;
                                    }
                                    let _e1139 = local_106;
                                    local_107 = (32u / _e1139);
                                    let _e1141 = local_106;
                                    if (_e1141 >= 32u) {
                                        phi_860_ = 4294967295u;
                                    } else {
                                        let _e1143 = local_106;
                                        phi_860_ = ((1u << bitcast<u32>((_e1143 & 31u))) - 1u);
                                    }
                                    let _e1149 = phi_860_;
                                    local_108 = _e1149;
                                    let _e1150 = local_18;
                                    let _e1151 = local_19;
                                    let _e1153 = local_17;
                                    let _e1155 = local_17;
                                    let _e1157 = local_15;
                                    local_109 = (4u * ((((_e1150 * _e1151) * _e1153) * _e1155) * _e1157));
                                    let _e1160 = local_107;
                                    let _e1161 = (_e1160 == 0u);
                                    local_110 = _e1161;
                                    if _e1161 {
                                        phi_5278_ = true;
                                        break;
                                    }
                                    let _e1162 = local_85;
                                    let _e1163 = local_107;
                                    let _e1165 = local_109;
                                    local_111 = (_e1165 + (_e1162 / _e1163));
                                    let _e1167 = local_110;
                                    if _e1167 {
                                        phi_5278_ = true;
                                        break;
                                    }
                                    let _e1168 = local_85;
                                    let _e1169 = local_107;
                                    let _e1171 = local_106;
                                    local_112 = ((_e1168 % _e1169) * _e1171);
                                    let _e1173 = local_111;
                                    let _e1174 = local_2;
                                    if (_e1173 < _e1174) {
                                    } else {
                                        phi_5278_ = true;
                                        break;
                                    }
                                    let _e1176 = local_111;
                                    let _e1179 = global_5.member[_e1176];
                                    let _e1180 = local_112;
                                    let _e1184 = local_108;
                                    let _e1186 = local_103;
                                    let _e1187 = local_98;
                                    let _e1188 = local_100;
                                    let _e1189 = local_101;
                                    let _e1190 = local_102;
                                    phi_899_ = type_29(_e1186, _e1187, _e1188, _e1189, _e1190, ((_e1179 >> bitcast<u32>((_e1180 & 31u))) & _e1184));
                                }
                                let _e1193 = phi_899_;
                                local_113 = _e1193;
                                local_114 = _e1193.member_5;
                                let _e1195 = (_e1193.member_5 != 0u);
                                local_115 = _e1195;
                                if _e1195 {
                                    phi_913_ = 1.4142135f;
                                } else {
                                    let _e1196 = local_113;
                                    phi_913_ = (0.5f * f32((1u << bitcast<u32>((_e1196.member_4 & 31u)))));
                                }
                                let _e1204 = phi_913_;
                                local_116 = _e1204;
                                let _e1205 = local_113;
                                local_117 = _e1205.member_3;
                                let _e1207 = bitcast<u32>(_e1205.member_3);
                                local_118 = _e1207;
                                if (_e1207 == 2139095040u) {
                                    let _e1242 = local_22;
                                    let _e1244 = local_21;
                                    let _e1246 = local_23;
                                    let _e1247 = local_21;
                                    let _e1250 = local_24;
                                    phi_979_ = (0.5f * ((((2f * _e1242) * _e1244) / (_e1246 - _e1247)) * _e1250));
                                } else {
                                    let _e1209 = local_118;
                                    if (_e1209 == 0u) {
                                        phi_942_ = false;
                                    } else {
                                        let _e1211 = local_118;
                                        phi_942_ = (_e1211 <= 2139095040u);
                                    }
                                    let _e1214 = phi_942_;
                                    if _e1214 {
                                        let _e1215 = local_22;
                                        let _e1217 = local_21;
                                        let _e1219 = local_23;
                                        let _e1220 = local_21;
                                        let _e1223 = local_24;
                                        let _e1224 = ((((2f * _e1215) * _e1217) / (_e1219 - _e1220)) * _e1223);
                                        local_119 = _e1224;
                                        if (_e1224 == 0f) {
                                            phi_970_ = 0f;
                                        } else {
                                            let _e1226 = local_23;
                                            let _e1227 = local_117;
                                            let _e1230 = local_119;
                                            phi_970_ = (_e1230 * (1f - (_e1226 / _e1227)));
                                        }
                                        let _e1233 = phi_970_;
                                        phi_971_ = _e1233;
                                    } else {
                                        phi_971_ = _e564;
                                    }
                                    let _e1235 = phi_971_;
                                    local_120 = _e1235;
                                    if (_e1235 < 0f) {
                                        let _e1237 = local_120;
                                        phi_977_ = -(_e1237);
                                    } else {
                                        phi_977_ = _e1235;
                                    }
                                    let _e1240 = phi_977_;
                                    phi_979_ = (0.5f * _e1240);
                                }
                                let _e1254 = phi_979_;
                                let _e1259 = local_116;
                                let _e1260 = (select(_e1254, 0f, ((bitcast<u32>(_e1254) & 2147483647u) > 2139095040u)) + _e1259);
                                let _e1261 = local_12;
                                let _e1263 = local_12;
                                let _e1264 = select(_e1263, _e1260, (_e1260 < _e1261));
                                local_444 = select(0.5f, _e1264, (_e1264 > 0.5f));
                                let _e1267 = local_113;
                                let _e1271 = (f32(_e1267.member[0]) * 0.5f);
                                local_121 = _e1271;
                                let _e1272 = local_113;
                                local_122 = (f32(_e1272.member[1]) * 0.5f);
                                local_123 = bitcast<u32>(_e1271);
                                let _e1278 = local;
                                let _e1279 = (1536u + _e1278);
                                local_124 = _e1279;
                                if (_e1279 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1281 = local_124;
                                let _e1283 = local_123;
                                global_11[_e1281] = _e1283;
                                let _e1284 = local_122;
                                local_125 = bitcast<u32>(_e1284);
                                let _e1286 = local;
                                let _e1287 = (1792u + _e1286);
                                local_126 = _e1287;
                                if (_e1287 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1289 = local_126;
                                let _e1291 = local_125;
                                global_11[_e1289] = _e1291;
                                let _e1292 = local_444;
                                local_127 = bitcast<u32>(_e1292);
                                let _e1294 = local;
                                let _e1295 = (2048u + _e1294);
                                local_128 = _e1295;
                                if (_e1295 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1297 = local_128;
                                let _e1299 = local_127;
                                global_11[_e1297] = _e1299;
                                let _e1300 = local_117;
                                let _e1301 = local_23;
                                local_445 = select(1f, -1f, (_e1300 < _e1301));
                                let _e1304 = local_115;
                                if _e1304 {
                                    phi_5031_ = _e1014;
                                    phi_1604_ = 1f;
                                } else {
                                    let _e1305 = local_113;
                                    local_129 = f32((1u << bitcast<u32>(((2u * _e1305.member_4) & 31u))));
                                    let _e1315 = f32((1u << bitcast<u32>((_e1305.member_4 & 31u))));
                                    local_130 = _e1315;
                                    let _e1317 = local_444;
                                    if (_e1317 >= (4f + _e1315)) {
                                        let _e1844 = local_32;
                                        if (_e1844 > 0u) {
                                            let _e1858 = local_130;
                                            let _e1860 = local_444;
                                            let _e1861 = (_e1860 - (0.5f * _e1858));
                                            let _e1862 = local_31;
                                            phi_1079_ = ((_e1862 * _e1861) * _e1861);
                                        } else {
                                            let _e1846 = local_444;
                                            let _e1847 = local_130;
                                            let _e1849 = local_444;
                                            let _e1851 = local_130;
                                            let _e1852 = local_130;
                                            let _e1856 = local_31;
                                            phi_1079_ = (_e1856 * (((_e1846 - _e1847) * _e1849) + ((_e1851 * _e1852) * 0.33333334f)));
                                        }
                                        let _e1866 = phi_1079_;
                                        phi_5032_ = _e1014;
                                        phi_1602_ = _e1866;
                                    } else {
                                        let _e1319 = local_122;
                                        let _e1320 = local_444;
                                        let _e1324 = local_122;
                                        let _e1325 = local_444;
                                        local_131 = floor(((_e1324 + _e1325) - 0.5f));
                                        let _e1329 = local_121;
                                        let _e1330 = local_444;
                                        let _e1334 = local_121;
                                        let _e1335 = local_444;
                                        local_132 = floor(((_e1334 + _e1335) - 0.5f));
                                        phi_4958_ = _e1014;
                                        phi_1094_ = ceil(((_e1319 - _e1320) - 0.5f));
                                        phi_1097_ = 0f;
                                        loop {
                                            let _e1340 = phi_4958_;
                                            let _e1342 = phi_1094_;
                                            let _e1344 = phi_1097_;
                                            local_133 = _e1342;
                                            local_462 = _e1344;
                                            let _e1345 = local_133;
                                            let _e1346 = local_131;
                                            let _e1347 = (_e1345 <= _e1346);
                                            local_134 = _e1347;
                                            if _e1347 {
                                                let _e1348 = local_133;
                                                let _e1350 = local_122;
                                                local_135 = ((_e1348 + 0.5f) - _e1350);
                                                phi_1108_ = ceil(((_e1329 - _e1330) - 0.5f));
                                                phi_1111_ = _e1344;
                                                loop {
                                                    let _e1353 = phi_1108_;
                                                    let _e1355 = phi_1111_;
                                                    local_136 = _e1353;
                                                    local_461 = _e1355;
                                                    let _e1356 = local_136;
                                                    let _e1357 = local_132;
                                                    let _e1358 = (_e1356 <= _e1357);
                                                    local_137 = _e1358;
                                                    if _e1358 {
                                                        let _e1359 = local_136;
                                                        let _e1361 = local_121;
                                                        let _e1362 = ((_e1359 + 0.5f) - _e1361);
                                                        local_138 = _e1362;
                                                        let _e1364 = local_135;
                                                        let _e1365 = local_135;
                                                        local_139 = ((_e1362 * _e1362) + (_e1364 * _e1365));
                                                        let _e1368 = local_25;
                                                        let _e1369 = (_e1368 == 0u);
                                                        local_140 = _e1369;
                                                        if _e1369 {
                                                            let _e1370 = local_32;
                                                            phi_1135_ = (_e1370 == 0u);
                                                        } else {
                                                            phi_1135_ = false;
                                                        }
                                                        let _e1373 = phi_1135_;
                                                        if _e1373 {
                                                            let _e1781 = local_444;
                                                            let _e1782 = local_130;
                                                            let _e1783 = (_e1781 - _e1782);
                                                            let _e1786 = local_139;
                                                            let _e1789 = local_139;
                                                            let _e1791 = local_444;
                                                            let _e1793 = local_130;
                                                            let _e1795 = ((_e1791 - sqrt(_e1789)) * (1f / _e1793));
                                                            phi_1580_ = select(select(0f, select(1f, _e1795, (_e1795 < 1f)), (0f < _e1795)), 1f, ((0f < _e1783) && (_e1786 <= (_e1783 * _e1783))));
                                                        } else {
                                                            let _e1374 = local_140;
                                                            if _e1374 {
                                                                let _e1375 = local_32;
                                                                phi_1171_ = (_e1375 == 0u);
                                                            } else {
                                                                phi_1171_ = false;
                                                            }
                                                            let _e1378 = phi_1171_;
                                                            if _e1378 {
                                                                let _e1759 = local_444;
                                                                let _e1760 = local_130;
                                                                let _e1761 = (_e1759 - _e1760);
                                                                let _e1764 = local_139;
                                                                let _e1767 = local_139;
                                                                let _e1769 = local_444;
                                                                let _e1771 = local_130;
                                                                let _e1773 = ((_e1769 - sqrt(_e1767)) * (1f / _e1771));
                                                                phi_1579_ = select(select(0f, select(1f, _e1773, (_e1773 < 1f)), (0f < _e1773)), 1f, ((0f < _e1761) && (_e1764 <= (_e1761 * _e1761))));
                                                            } else {
                                                                let _e1379 = local_445;
                                                                let _e1380 = local_138;
                                                                local_141 = (_e1379 * _e1380);
                                                                let _e1382 = local_445;
                                                                let _e1383 = local_135;
                                                                local_142 = (_e1382 * _e1383);
                                                                let _e1385 = local_32;
                                                                if (_e1385 > 0u) {
                                                                    let _e1468 = local_130;
                                                                    let _e1470 = local_444;
                                                                    let _e1471 = (_e1470 - (0.5f * _e1468));
                                                                    local_143 = _e1471;
                                                                    if (_e1471 > 0f) {
                                                                        let _e1473 = local_141;
                                                                        let _e1474 = local_143;
                                                                        let _e1476 = local_142;
                                                                        let _e1477 = local_143;
                                                                        let _e1479 = local_32;
                                                                        let _e1480 = f32(_e1479);
                                                                        local_144 = _e1480;
                                                                        let _e1484 = (((((_e1473 / _e1474) + 1f) * 0.5f) * _e1480) - 0.5f);
                                                                        local_145 = _e1484;
                                                                        local_146 = (((((_e1476 / _e1477) + 1f) * 0.5f) * _e1480) - 0.5f);
                                                                        if (_e1484 > -1f) {
                                                                            let _e1490 = local_146;
                                                                            if (_e1490 > -1f) {
                                                                                let _e1492 = local_145;
                                                                                let _e1493 = local_144;
                                                                                if (_e1492 < _e1493) {
                                                                                    let _e1495 = local_146;
                                                                                    let _e1496 = local_144;
                                                                                    let _e1497 = (_e1495 < _e1496);
                                                                                    local_147 = _e1497;
                                                                                    if _e1497 {
                                                                                        let _e1498 = local_145;
                                                                                        let _e1499 = floor(_e1498);
                                                                                        local_148 = _e1499;
                                                                                        let _e1500 = local_146;
                                                                                        let _e1501 = floor(_e1500);
                                                                                        local_149 = _e1501;
                                                                                        let _e1502 = local_145;
                                                                                        local_150 = (_e1502 - _e1499);
                                                                                        let _e1504 = local_146;
                                                                                        local_151 = (_e1504 - _e1501);
                                                                                        let _e1506 = (_e1499 < 0f);
                                                                                        local_152 = _e1506;
                                                                                        if _e1506 {
                                                                                            phi_1292_ = f32();
                                                                                            phi_1293_ = true;
                                                                                        } else {
                                                                                            let _e1507 = local_149;
                                                                                            if (_e1507 < 0f) {
                                                                                                phi_1290_ = f32();
                                                                                                phi_1291_ = true;
                                                                                            } else {
                                                                                                let _e1509 = local_148;
                                                                                                let _e1510 = local_144;
                                                                                                if (_e1509 >= _e1510) {
                                                                                                    phi_1288_ = f32();
                                                                                                    phi_1289_ = true;
                                                                                                } else {
                                                                                                    let _e1512 = local_149;
                                                                                                    let _e1513 = local_144;
                                                                                                    let _e1514 = (_e1512 >= _e1513);
                                                                                                    if _e1514 {
                                                                                                        phi_1287_ = f32();
                                                                                                    } else {
                                                                                                        let _e1515 = local_149;
                                                                                                        let _e1517 = local_149;
                                                                                                        let _e1520 = local_149;
                                                                                                        let _e1524 = local_32;
                                                                                                        let _e1526 = local_148;
                                                                                                        let _e1528 = local_148;
                                                                                                        let _e1531 = local_148;
                                                                                                        let _e1535 = ((select(select(u32(_e1515), 0u, !((_e1517 >= 0f))), 4294967295u, (_e1520 > 4294967000f)) * _e1524) + select(select(u32(_e1526), 0u, !((_e1528 >= 0f))), 4294967295u, (_e1531 > 4294967000f)));
                                                                                                        local_153 = _e1535;
                                                                                                        let _e1536 = local_8;
                                                                                                        if (_e1535 < _e1536) {
                                                                                                        } else {
                                                                                                            phi_4947_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1538 = local_153;
                                                                                                        let _e1541 = global_10.member[_e1538];
                                                                                                        phi_1287_ = bitcast<f32>(_e1541);
                                                                                                    }
                                                                                                    let _e1544 = phi_1287_;
                                                                                                    phi_1288_ = _e1544;
                                                                                                    phi_1289_ = _e1514;
                                                                                                }
                                                                                                let _e1546 = phi_1288_;
                                                                                                let _e1548 = phi_1289_;
                                                                                                phi_1290_ = _e1546;
                                                                                                phi_1291_ = _e1548;
                                                                                            }
                                                                                            let _e1550 = phi_1290_;
                                                                                            let _e1552 = phi_1291_;
                                                                                            phi_1292_ = _e1550;
                                                                                            phi_1293_ = _e1552;
                                                                                        }
                                                                                        let _e1554 = phi_1292_;
                                                                                        let _e1556 = phi_1293_;
                                                                                        let _e1558 = local_150;
                                                                                        let _e1559 = (1f - _e1558);
                                                                                        local_154 = _e1559;
                                                                                        local_155 = (select(_e1554, 0f, _e1556) * _e1559);
                                                                                        let _e1561 = local_148;
                                                                                        let _e1562 = (_e1561 + 1f);
                                                                                        local_156 = _e1562;
                                                                                        let _e1563 = (_e1562 < 0f);
                                                                                        local_157 = _e1563;
                                                                                        if _e1563 {
                                                                                            phi_1348_ = f32();
                                                                                            phi_1349_ = true;
                                                                                        } else {
                                                                                            let _e1564 = local_149;
                                                                                            if (_e1564 < 0f) {
                                                                                                phi_1346_ = f32();
                                                                                                phi_1347_ = true;
                                                                                            } else {
                                                                                                let _e1566 = local_156;
                                                                                                let _e1567 = local_144;
                                                                                                if (_e1566 >= _e1567) {
                                                                                                    phi_1344_ = f32();
                                                                                                    phi_1345_ = true;
                                                                                                } else {
                                                                                                    let _e1569 = local_149;
                                                                                                    let _e1570 = local_144;
                                                                                                    let _e1571 = (_e1569 >= _e1570);
                                                                                                    if _e1571 {
                                                                                                        phi_1343_ = f32();
                                                                                                    } else {
                                                                                                        let _e1572 = local_149;
                                                                                                        let _e1574 = local_149;
                                                                                                        let _e1577 = local_149;
                                                                                                        let _e1581 = local_32;
                                                                                                        let _e1583 = local_156;
                                                                                                        let _e1585 = local_156;
                                                                                                        let _e1588 = local_156;
                                                                                                        let _e1592 = ((select(select(u32(_e1572), 0u, !((_e1574 >= 0f))), 4294967295u, (_e1577 > 4294967000f)) * _e1581) + select(select(u32(_e1583), 0u, !((_e1585 >= 0f))), 4294967295u, (_e1588 > 4294967000f)));
                                                                                                        local_158 = _e1592;
                                                                                                        let _e1593 = local_8;
                                                                                                        if (_e1592 < _e1593) {
                                                                                                        } else {
                                                                                                            phi_4947_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1595 = local_158;
                                                                                                        let _e1598 = global_10.member[_e1595];
                                                                                                        phi_1343_ = bitcast<f32>(_e1598);
                                                                                                    }
                                                                                                    let _e1601 = phi_1343_;
                                                                                                    phi_1344_ = _e1601;
                                                                                                    phi_1345_ = _e1571;
                                                                                                }
                                                                                                let _e1603 = phi_1344_;
                                                                                                let _e1605 = phi_1345_;
                                                                                                phi_1346_ = _e1603;
                                                                                                phi_1347_ = _e1605;
                                                                                            }
                                                                                            let _e1607 = phi_1346_;
                                                                                            let _e1609 = phi_1347_;
                                                                                            phi_1348_ = _e1607;
                                                                                            phi_1349_ = _e1609;
                                                                                        }
                                                                                        let _e1611 = phi_1348_;
                                                                                        let _e1613 = phi_1349_;
                                                                                        let _e1615 = local_150;
                                                                                        let _e1617 = local_155;
                                                                                        local_159 = (_e1617 + (select(_e1611, 0f, _e1613) * _e1615));
                                                                                        let _e1619 = local_149;
                                                                                        local_160 = (_e1619 + 1f);
                                                                                        let _e1621 = local_152;
                                                                                        if _e1621 {
                                                                                            phi_1404_ = f32();
                                                                                            phi_1405_ = true;
                                                                                        } else {
                                                                                            let _e1622 = local_160;
                                                                                            if (_e1622 < 0f) {
                                                                                                phi_1402_ = f32();
                                                                                                phi_1403_ = true;
                                                                                            } else {
                                                                                                let _e1624 = local_148;
                                                                                                let _e1625 = local_144;
                                                                                                if (_e1624 >= _e1625) {
                                                                                                    phi_1400_ = f32();
                                                                                                    phi_1401_ = true;
                                                                                                } else {
                                                                                                    let _e1627 = local_160;
                                                                                                    let _e1628 = local_144;
                                                                                                    let _e1629 = (_e1627 >= _e1628);
                                                                                                    if _e1629 {
                                                                                                        phi_1399_ = f32();
                                                                                                    } else {
                                                                                                        let _e1630 = local_160;
                                                                                                        let _e1632 = local_160;
                                                                                                        let _e1635 = local_160;
                                                                                                        let _e1639 = local_32;
                                                                                                        let _e1641 = local_148;
                                                                                                        let _e1643 = local_148;
                                                                                                        let _e1646 = local_148;
                                                                                                        let _e1650 = ((select(select(u32(_e1630), 0u, !((_e1632 >= 0f))), 4294967295u, (_e1635 > 4294967000f)) * _e1639) + select(select(u32(_e1641), 0u, !((_e1643 >= 0f))), 4294967295u, (_e1646 > 4294967000f)));
                                                                                                        local_161 = _e1650;
                                                                                                        let _e1651 = local_8;
                                                                                                        if (_e1650 < _e1651) {
                                                                                                        } else {
                                                                                                            phi_4947_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1653 = local_161;
                                                                                                        let _e1656 = global_10.member[_e1653];
                                                                                                        phi_1399_ = bitcast<f32>(_e1656);
                                                                                                    }
                                                                                                    let _e1659 = phi_1399_;
                                                                                                    phi_1400_ = _e1659;
                                                                                                    phi_1401_ = _e1629;
                                                                                                }
                                                                                                let _e1661 = phi_1400_;
                                                                                                let _e1663 = phi_1401_;
                                                                                                phi_1402_ = _e1661;
                                                                                                phi_1403_ = _e1663;
                                                                                            }
                                                                                            let _e1665 = phi_1402_;
                                                                                            let _e1667 = phi_1403_;
                                                                                            phi_1404_ = _e1665;
                                                                                            phi_1405_ = _e1667;
                                                                                        }
                                                                                        let _e1669 = phi_1404_;
                                                                                        let _e1671 = phi_1405_;
                                                                                        let _e1673 = local_154;
                                                                                        local_162 = (select(_e1669, 0f, _e1671) * _e1673);
                                                                                        let _e1675 = local_157;
                                                                                        if _e1675 {
                                                                                            phi_1461_ = f32();
                                                                                            phi_1462_ = true;
                                                                                        } else {
                                                                                            let _e1676 = local_160;
                                                                                            if (_e1676 < 0f) {
                                                                                                phi_1459_ = f32();
                                                                                                phi_1460_ = true;
                                                                                            } else {
                                                                                                let _e1678 = local_156;
                                                                                                let _e1679 = local_144;
                                                                                                if (_e1678 >= _e1679) {
                                                                                                    phi_1457_ = f32();
                                                                                                    phi_1458_ = true;
                                                                                                } else {
                                                                                                    let _e1681 = local_160;
                                                                                                    let _e1682 = local_144;
                                                                                                    let _e1683 = (_e1681 >= _e1682);
                                                                                                    if _e1683 {
                                                                                                        phi_1456_ = f32();
                                                                                                    } else {
                                                                                                        let _e1684 = local_160;
                                                                                                        let _e1686 = local_160;
                                                                                                        let _e1689 = local_160;
                                                                                                        let _e1693 = local_32;
                                                                                                        let _e1695 = local_156;
                                                                                                        let _e1697 = local_156;
                                                                                                        let _e1700 = local_156;
                                                                                                        let _e1704 = ((select(select(u32(_e1684), 0u, !((_e1686 >= 0f))), 4294967295u, (_e1689 > 4294967000f)) * _e1693) + select(select(u32(_e1695), 0u, !((_e1697 >= 0f))), 4294967295u, (_e1700 > 4294967000f)));
                                                                                                        local_163 = _e1704;
                                                                                                        let _e1705 = local_8;
                                                                                                        if (_e1704 < _e1705) {
                                                                                                        } else {
                                                                                                            phi_4947_ = true;
                                                                                                            break;
                                                                                                        }
                                                                                                        let _e1707 = local_163;
                                                                                                        let _e1710 = global_10.member[_e1707];
                                                                                                        phi_1456_ = bitcast<f32>(_e1710);
                                                                                                    }
                                                                                                    let _e1713 = phi_1456_;
                                                                                                    phi_1457_ = _e1713;
                                                                                                    phi_1458_ = _e1683;
                                                                                                }
                                                                                                let _e1715 = phi_1457_;
                                                                                                let _e1717 = phi_1458_;
                                                                                                phi_1459_ = _e1715;
                                                                                                phi_1460_ = _e1717;
                                                                                            }
                                                                                            let _e1719 = phi_1459_;
                                                                                            let _e1721 = phi_1460_;
                                                                                            phi_1461_ = _e1719;
                                                                                            phi_1462_ = _e1721;
                                                                                        }
                                                                                        let _e1723 = phi_1461_;
                                                                                        let _e1725 = phi_1462_;
                                                                                        let _e1727 = local_150;
                                                                                        let _e1729 = local_162;
                                                                                        let _e1731 = local_151;
                                                                                        let _e1733 = local_159;
                                                                                        let _e1735 = local_151;
                                                                                        phi_1473_ = ((_e1733 * (1f - _e1731)) + ((_e1729 + (select(_e1723, 0f, _e1725) * _e1727)) * _e1735));
                                                                                    } else {
                                                                                        phi_1473_ = f32();
                                                                                    }
                                                                                    let _e1739 = phi_1473_;
                                                                                    let _e1740 = local_147;
                                                                                    phi_1475_ = _e1739;
                                                                                    phi_1476_ = select(true, false, _e1740);
                                                                                } else {
                                                                                    phi_1475_ = f32();
                                                                                    phi_1476_ = true;
                                                                                }
                                                                                let _e1743 = phi_1475_;
                                                                                let _e1745 = phi_1476_;
                                                                                phi_1477_ = _e1743;
                                                                                phi_1478_ = _e1745;
                                                                            } else {
                                                                                phi_1477_ = f32();
                                                                                phi_1478_ = true;
                                                                            }
                                                                            let _e1747 = phi_1477_;
                                                                            let _e1749 = phi_1478_;
                                                                            phi_1479_ = _e1747;
                                                                            phi_1480_ = _e1749;
                                                                        } else {
                                                                            phi_1479_ = f32();
                                                                            phi_1480_ = true;
                                                                        }
                                                                        let _e1751 = phi_1479_;
                                                                        let _e1753 = phi_1480_;
                                                                        phi_1485_ = select(_e1751, 0f, _e1753);
                                                                    } else {
                                                                        phi_1485_ = 0f;
                                                                    }
                                                                    let _e1756 = phi_1485_;
                                                                    phi_1578_ = _e1756;
                                                                } else {
                                                                    let _e1387 = local_141;
                                                                    let _e1388 = local_141;
                                                                    let _e1390 = local_142;
                                                                    let _e1391 = local_142;
                                                                    let _e1394 = sqrt(((_e1387 * _e1388) + (_e1390 * _e1391)));
                                                                    local_164 = _e1394;
                                                                    let _e1395 = local_140;
                                                                    if _e1395 {
                                                                        phi_1565_ = _e1394;
                                                                    } else {
                                                                        let _e1396 = local_27;
                                                                        let _e1398 = local_141;
                                                                        let _e1400 = local_27;
                                                                        let _e1402 = local_142;
                                                                        phi_1507_ = 1u;
                                                                        phi_1510_ = ((_e1398 * _e1396[0]) + (_e1402 * _e1400[1]));
                                                                        phi_1512_ = _e617.member_16.member_2;
                                                                        loop {
                                                                            let _e1406 = phi_1507_;
                                                                            let _e1408 = phi_1510_;
                                                                            let _e1410 = phi_1512_;
                                                                            local_165 = _e1406;
                                                                            local_166 = _e1408;
                                                                            local_167 = _e1410;
                                                                            let _e1411 = local_165;
                                                                            let _e1412 = local_25;
                                                                            let _e1413 = (_e1411 < _e1412);
                                                                            local_168 = _e1413;
                                                                            if _e1413 {
                                                                                let _e1414 = local_167;
                                                                                let _e1416 = local_28;
                                                                                let _e1418 = local_167;
                                                                                let _e1420 = local_29;
                                                                                let _e1422 = ((_e1414[0] * _e1416) - (_e1418[1] * _e1420));
                                                                                let _e1423 = local_29;
                                                                                let _e1425 = local_28;
                                                                                let _e1427 = ((_e1414[0] * _e1423) + (_e1418[1] * _e1425));
                                                                                let _e1429 = local_141;
                                                                                let _e1431 = local_142;
                                                                                let _e1433 = ((_e1429 * _e1422) + (_e1431 * _e1427));
                                                                                let _e1434 = local_166;
                                                                                let _e1436 = local_166;
                                                                                let _e1438 = local_165;
                                                                                phi_1508_ = (_e1438 + 1u);
                                                                                phi_1511_ = select(_e1436, _e1433, (_e1433 > _e1434));
                                                                                phi_1513_ = array<f32, 2>(_e1422, _e1427);
                                                                            } else {
                                                                                phi_1508_ = u32();
                                                                                phi_1511_ = f32();
                                                                                phi_1513_ = array<f32, 2>();
                                                                            }
                                                                            let _e1441 = phi_1508_;
                                                                            let _e1443 = phi_1511_;
                                                                            let _e1445 = phi_1513_;
                                                                            continue;
                                                                            continuing {
                                                                                let _e1446 = local_168;
                                                                                phi_1507_ = _e1441;
                                                                                phi_1510_ = _e1443;
                                                                                phi_1512_ = _e1445;
                                                                                break if !(_e1446);
                                                                            }
                                                                        }
                                                                        let _e1448 = local_26;
                                                                        let _e1450 = local_166;
                                                                        let _e1452 = local_30;
                                                                        let _e1454 = local_26;
                                                                        let _e1455 = local_164;
                                                                        phi_1565_ = ((((1f - _e1448) * _e1450) * _e1452) + (_e1454 * _e1455));
                                                                    }
                                                                    let _e1459 = phi_1565_;
                                                                    let _e1460 = local_444;
                                                                    let _e1462 = local_130;
                                                                    let _e1463 = ((_e1460 - _e1459) / _e1462);
                                                                    phi_1578_ = select(0f, select(1f, _e1463, (_e1463 < 1f)), (0f < _e1463));
                                                                }
                                                                let _e1758 = phi_1578_;
                                                                phi_1579_ = _e1758;
                                                            }
                                                            let _e1780 = phi_1579_;
                                                            phi_1580_ = _e1780;
                                                        }
                                                        let _e1802 = phi_1580_;
                                                        let _e1803 = local_137;
                                                        local_446 = select(0f, _e1802, _e1803);
                                                        phi_1586_ = 0u;
                                                        phi_1589_ = _e1355;
                                                        loop {
                                                            let _e1806 = phi_1586_;
                                                            let _e1808 = phi_1589_;
                                                            local_169 = _e1806;
                                                            local_170 = _e1808;
                                                            local_460 = _e1808;
                                                            let _e1809 = local_169;
                                                            let _e1810 = (_e1809 < 1u);
                                                            local_171 = _e1810;
                                                            if _e1810 {
                                                                let _e1811 = local_170;
                                                                let _e1812 = local_446;
                                                                let _e1814 = local_169;
                                                                phi_1587_ = (_e1814 + 1u);
                                                                phi_1590_ = (_e1811 + _e1812);
                                                            } else {
                                                                phi_1587_ = u32();
                                                                phi_1590_ = f32();
                                                            }
                                                            let _e1817 = phi_1587_;
                                                            let _e1819 = phi_1590_;
                                                            continue;
                                                            continuing {
                                                                let _e1820 = local_171;
                                                                phi_1586_ = _e1817;
                                                                phi_1589_ = _e1819;
                                                                break if !(_e1820);
                                                            }
                                                        }
                                                        let _e1822 = local_136;
                                                        phi_1109_ = (_e1822 + 1f);
                                                        let _e4245 = local_460;
                                                        phi_1112_ = _e4245;
                                                    } else {
                                                        phi_1109_ = f32();
                                                        phi_1112_ = f32();
                                                    }
                                                    let _e1825 = phi_1109_;
                                                    let _e1827 = phi_1112_;
                                                    continue;
                                                    continuing {
                                                        let _e1828 = local_137;
                                                        phi_1108_ = _e1825;
                                                        phi_1111_ = _e1827;
                                                        phi_4947_ = _e1340;
                                                        break if !(_e1828);
                                                    }
                                                }
                                                let _e1831 = phi_4947_;
                                                phi_5014_ = _e1831;
                                                if _e1831 {
                                                    break;
                                                }
                                                let _e1832 = local_133;
                                                phi_5015_ = _e1831;
                                                phi_1095_ = (_e1832 + 1f);
                                                let _e4251 = local_461;
                                                phi_1098_ = _e4251;
                                            } else {
                                                phi_5015_ = _e1340;
                                                phi_1095_ = f32();
                                                phi_1098_ = f32();
                                            }
                                            let _e1835 = phi_5015_;
                                            let _e1837 = phi_1095_;
                                            let _e1839 = phi_1098_;
                                            continue;
                                            continuing {
                                                let _e1840 = local_134;
                                                phi_4958_ = _e1835;
                                                phi_1094_ = _e1837;
                                                phi_1097_ = _e1839;
                                                phi_5014_ = _e1835;
                                                break if !(_e1840);
                                            }
                                        }
                                        let _e1843 = phi_5014_;
                                        phi_5278_ = _e1843;
                                        if _e1843 {
                                            break;
                                        }
                                        phi_5032_ = _e1843;
                                        let _e4257 = local_462;
                                        phi_1602_ = _e4257;
                                    }
                                    let _e1868 = phi_5032_;
                                    let _e1870 = phi_1602_;
                                    let _e1871 = local_129;
                                    phi_5031_ = _e1868;
                                    phi_1604_ = (_e1871 / _e1870);
                                }
                                let _e1874 = phi_5031_;
                                let _e1876 = phi_1604_;
                                local_172 = _e1876;
                                phi_1606_ = 0u;
                                loop {
                                    let _e1878 = phi_1606_;
                                    local_173 = _e1878;
                                    let _e1879 = local_173;
                                    let _e1880 = local_44;
                                    if (_e1879 < _e1880) {
                                        let _e1882 = local_173;
                                        let _e1883 = (_e1882 + 1u);
                                        let _e1885 = local_16;
                                        let _e1890 = local_444;
                                        let _e1891 = (_e1890 >= f32((2u * (_e1885 << bitcast<u32>((_e1883 & 31u))))));
                                        phi_1607_ = select(u32(), _e1883, _e1891);
                                        phi_1628_ = _e1891;
                                    } else {
                                        phi_1607_ = u32();
                                        phi_1628_ = false;
                                    }
                                    let _e1894 = phi_1607_;
                                    let _e1896 = phi_1628_;
                                    local_174 = _e1896;
                                    continue;
                                    continuing {
                                        let _e1897 = local_174;
                                        phi_1606_ = _e1894;
                                        break if !(_e1897);
                                    }
                                }
                                let _e1899 = local_173;
                                let _e1905 = local_172;
                                local_175 = bitcast<u32>((_e1905 * f32((1u << bitcast<u32>(((2u * _e1899) & 31u))))));
                                let _e1908 = local;
                                let _e1909 = (2304u + _e1908);
                                local_176 = _e1909;
                                if (_e1909 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1911 = local_176;
                                let _e1913 = local_175;
                                global_11[_e1911] = _e1913;
                                let _e1914 = local;
                                let _e1915 = (5632u + _e1914);
                                local_177 = _e1915;
                                if (_e1915 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1917 = local_177;
                                let _e1919 = local_114;
                                global_11[_e1917] = _e1919;
                                let _e1920 = local_113;
                                local_178 = bitcast<u32>(f32((1u << bitcast<u32>((_e1920.member_4 & 31u)))));
                                let _e1927 = local;
                                let _e1928 = (3584u + _e1927);
                                local_179 = _e1928;
                                if (_e1928 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1930 = local_179;
                                let _e1932 = local_178;
                                global_11[_e1930] = _e1932;
                                let _e1933 = local_445;
                                local_180 = bitcast<u32>(_e1933);
                                let _e1935 = local;
                                let _e1936 = (3840u + _e1935);
                                local_181 = _e1936;
                                if (_e1936 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1938 = local_181;
                                let _e1940 = local_180;
                                global_11[_e1938] = _e1940;
                                let _e1941 = local_113;
                                local_182 = bitcast<u32>(_e1941.member_2);
                                let _e1944 = local;
                                let _e1945 = (4096u + _e1944);
                                local_183 = _e1945;
                                if (_e1945 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1947 = local_183;
                                let _e1949 = local_182;
                                global_11[_e1947] = _e1949;
                                let _e1950 = local_113;
                                local_184 = bitcast<u32>(_e1950.member_1[0]);
                                let _e1954 = local;
                                let _e1955 = (2560u + _e1954);
                                local_185 = _e1955;
                                if (_e1955 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1957 = local_185;
                                let _e1959 = local_184;
                                global_11[_e1957] = _e1959;
                                let _e1960 = local_113;
                                local_186 = bitcast<u32>(_e1960.member_1[1]);
                                let _e1964 = local;
                                let _e1965 = (2816u + _e1964);
                                local_187 = _e1965;
                                if (_e1965 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1967 = local_187;
                                let _e1969 = local_186;
                                global_11[_e1967] = _e1969;
                                let _e1970 = local_113;
                                local_188 = bitcast<u32>(_e1970.member_1[2]);
                                let _e1974 = local;
                                let _e1975 = (3072u + _e1974);
                                local_189 = _e1975;
                                if (_e1975 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1977 = local_189;
                                let _e1979 = local_188;
                                global_11[_e1977] = _e1979;
                                let _e1980 = local;
                                let _e1981 = (3328u + _e1980);
                                local_190 = _e1981;
                                if (_e1981 < 5888u) {
                                } else {
                                    phi_5278_ = true;
                                    break;
                                }
                                let _e1983 = local_190;
                                let _e1985 = local_118;
                                global_11[_e1983] = _e1985;
                                phi_5027_ = _e1874;
                            } else {
                                phi_5027_ = _e1014;
                            }
                            let _e1987 = phi_5027_;
                            storageBarrier();
                            workgroupBarrier();
                            let _e1988 = local_48;
                            let _e1989 = local_80;
                            let _e1990 = (_e1988 - _e1989);
                            let _e1992 = select(256u, _e1990, (_e1990 < 256u));
                            local_447 = _e1992;
                            local_459[0u] = false;
                            phi_1733_ = 0u;
                            loop {
                                let _e1995 = phi_1733_;
                                local_191 = _e1995;
                                let _e1996 = local_191;
                                let _e1997 = (_e1996 < 1u);
                                local_192 = _e1997;
                                if _e1997 {
                                    let _e1998 = local;
                                    let _e1999 = local_191;
                                    local_193 = (_e1998 + _e1999);
                                    let _e2001 = local_33;
                                    if _e2001 {
                                        phi_5016_ = true;
                                        break;
                                    }
                                    let _e2002 = local_193;
                                    let _e2003 = local_442;
                                    let _e2005 = local_40;
                                    local_194 = (_e2005 + (_e2002 % _e2003));
                                    let _e2007 = local_33;
                                    if _e2007 {
                                        phi_5016_ = true;
                                        break;
                                    }
                                    let _e2008 = local_193;
                                    let _e2009 = local_442;
                                    let _e2011 = local_42;
                                    local_195 = (_e2011 + (_e2008 / _e2009));
                                    let _e2013 = local_193;
                                    let _e2014 = local_66;
                                    if (_e2013 < _e2014) {
                                        let _e2016 = local_194;
                                        let _e2017 = local_13;
                                        let _e2018 = (_e2016 < _e2017);
                                        local_196 = _e2018;
                                        if _e2018 {
                                            let _e2019 = local_195;
                                            let _e2020 = local_14;
                                            phi_1799_ = (_e2019 < _e2020);
                                        } else {
                                            phi_1799_ = bool();
                                        }
                                        let _e2023 = phi_1799_;
                                        let _e2024 = local_196;
                                        phi_1801_ = _e2023;
                                        phi_1802_ = select(true, false, _e2024);
                                    } else {
                                        phi_1801_ = bool();
                                        phi_1802_ = true;
                                    }
                                    let _e2027 = phi_1801_;
                                    let _e2029 = phi_1802_;
                                    local_448 = select(_e2027, false, _e2029);
                                    let _e2031 = local_192;
                                    if _e2031 {
                                    } else {
                                        phi_5016_ = true;
                                        break;
                                    }
                                    let _e2032 = local_191;
                                    let _e2034 = local_448;
                                    local_459[_e2032] = _e2034;
                                    let _e2035 = local_191;
                                    phi_1734_ = (_e2035 + 1u);
                                } else {
                                    phi_1734_ = u32();
                                }
                                let _e2038 = phi_1734_;
                                continue;
                                continuing {
                                    let _e2039 = local_192;
                                    phi_1733_ = _e2038;
                                    phi_5016_ = _e1987;
                                    break if !(_e2039);
                                }
                            }
                            let _e2042 = phi_5016_;
                            phi_5278_ = _e2042;
                            if _e2042 {
                                break;
                            }
                            let _e2043 = local_459[0u];
                            local_456[0u] = _e2043;
                            let _e2045 = local_33;
                            if _e2045 {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2046 = local_33;
                            if _e2046 {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2047 = local_64;
                            local_197 = (f32(_e2047) + 0.5f);
                            let _e2050 = local_33;
                            if _e2050 {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2051 = local_33;
                            if _e2051 {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2052 = local_65;
                            local_198 = (f32(_e2052) + 0.5f);
                            let _e2055 = local;
                            let _e2056 = (768u + _e2055);
                            local_199 = _e2056;
                            if (_e2056 < 5888u) {
                            } else {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2058 = local_199;
                            let _e2060 = global_11[_e2058];
                            let _e2061 = bitcast<f32>(_e2060);
                            local_200 = _e2061;
                            let _e2062 = local;
                            if (_e2062 < 5888u) {
                            } else {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2064 = local;
                            let _e2066 = global_11[_e2064];
                            local_201 = bitcast<f32>(_e2066);
                            let _e2068 = local;
                            let _e2069 = (256u + _e2068);
                            local_202 = _e2069;
                            if (_e2069 < 5888u) {
                            } else {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2071 = local_202;
                            let _e2073 = global_11[_e2071];
                            local_203 = bitcast<f32>(_e2073);
                            let _e2075 = local;
                            let _e2076 = (512u + _e2075);
                            local_204 = _e2076;
                            if (_e2076 < 5888u) {
                            } else {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2078 = local_204;
                            let _e2080 = global_11[_e2078];
                            let _e2082 = local_201;
                            let _e2083 = local_203;
                            let _e2085 = local_73;
                            if (_e2085 < 5888u) {
                            } else {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2087 = local_73;
                            let _e2089 = global_11[_e2087];
                            local_205 = bitcast<f32>(_e2089);
                            let _e2091 = local;
                            let _e2092 = (_e2091 + 4864u);
                            local_206 = _e2092;
                            if (_e2092 < 5888u) {
                            } else {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2094 = local_206;
                            let _e2096 = global_11[_e2094];
                            local_207 = bitcast<f32>(_e2096);
                            let _e2098 = local;
                            let _e2099 = (_e2098 + 5120u);
                            local_208 = _e2099;
                            if (_e2099 < 5888u) {
                            } else {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2101 = local_208;
                            let _e2103 = global_11[_e2101];
                            local_209 = bitcast<f32>(_e2103);
                            let _e2105 = local;
                            let _e2106 = (_e2105 + 5376u);
                            local_210 = _e2106;
                            let _e2107 = (_e2106 < 5888u);
                            local_211 = _e2107;
                            if _e2107 {
                            } else {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2108 = local_210;
                            let _e2110 = global_11[_e2108];
                            local_212 = ((_e2110 & 1u) != 0u);
                            let _e2113 = local_211;
                            if _e2113 {
                            } else {
                                phi_5278_ = true;
                                break;
                            }
                            let _e2114 = global_11[_e2108];
                            let _e2117 = local_205;
                            let _e2118 = local_207;
                            let _e2119 = local_209;
                            let _e2120 = local_212;
                            local_455[0u] = false;
                            phi_2033_ = 0u;
                            loop {
                                let _e2124 = phi_2033_;
                                local_213 = _e2124;
                                let _e2125 = local_213;
                                let _e2126 = (_e2125 < 1u);
                                local_214 = _e2126;
                                if _e2126 {
                                    let _e2127 = local_214;
                                    if _e2127 {
                                    } else {
                                        phi_5034_ = true;
                                        break;
                                    }
                                    let _e2128 = local_213;
                                    let _e2130 = local_456[_e2128];
                                    if _e2130 {
                                        let _e2131 = local_200;
                                        phi_2054_ = (_e2131 < 0.99902344f);
                                    } else {
                                        phi_2054_ = false;
                                    }
                                    let _e2134 = phi_2054_;
                                    local_215 = _e2134;
                                    let _e2135 = local_214;
                                    if _e2135 {
                                    } else {
                                        phi_5034_ = true;
                                        break;
                                    }
                                    let _e2136 = local_213;
                                    let _e2138 = local_215;
                                    local_455[_e2136] = _e2138;
                                    let _e2139 = local_213;
                                    phi_2034_ = (_e2139 + 1u);
                                } else {
                                    phi_2034_ = u32();
                                }
                                let _e2142 = phi_2034_;
                                continue;
                                continuing {
                                    let _e2143 = local_214;
                                    phi_2033_ = _e2142;
                                    phi_5034_ = _e2042;
                                    break if !(_e2143);
                                }
                            }
                            let _e2146 = phi_5034_;
                            phi_5278_ = _e2146;
                            if _e2146 {
                                break;
                            }
                            let _e2147 = local_455[0u];
                            local_457[0u] = _e2147;
                            local_454[0u] = 0u;
                            phi_5046_ = _e2146;
                            phi_2067_ = 0u;
                            loop {
                                let _e2151 = phi_5046_;
                                let _e2153 = phi_2067_;
                                local_216 = _e2153;
                                let _e2154 = local_216;
                                let _e2155 = (_e2154 < 1u);
                                local_217 = _e2155;
                                if _e2155 {
                                    let _e2156 = local_217;
                                    if _e2156 {
                                    } else {
                                        phi_5047_ = true;
                                        break;
                                    }
                                    let _e2157 = local_216;
                                    let _e2159 = local_457[_e2157];
                                    if _e2159 {
                                        let _e2160 = local;
                                        let _e2161 = local_216;
                                        let _e2163 = (1024u + (_e2160 + _e2161));
                                        local_218 = _e2163;
                                        if (_e2163 < 5888u) {
                                        } else {
                                            phi_5047_ = true;
                                            break;
                                        }
                                        let _e2165 = local_218;
                                        let _e2167 = global_11[_e2165];
                                        local_219 = bitcast<f32>(_e2167);
                                        phi_2097_ = 0u;
                                        phi_2100_ = _e1992;
                                        loop {
                                            let _e2170 = phi_2097_;
                                            let _e2172 = phi_2100_;
                                            local_220 = _e2170;
                                            local_221 = _e2172;
                                            local_463 = _e2170;
                                            let _e2173 = local_220;
                                            let _e2174 = local_221;
                                            let _e2175 = (_e2173 < _e2174);
                                            local_222 = _e2175;
                                            if _e2175 {
                                                let _e2176 = local_220;
                                                let _e2177 = local_221;
                                                let _e2179 = ((_e2176 + _e2177) / 2u);
                                                local_223 = _e2179;
                                                let _e2180 = (3328u + _e2179);
                                                local_224 = _e2180;
                                                if (_e2180 < 5888u) {
                                                } else {
                                                    phi_5042_ = true;
                                                    break;
                                                }
                                                let _e2182 = local_224;
                                                let _e2184 = global_11[_e2182];
                                                let _e2186 = local_219;
                                                let _e2187 = (bitcast<f32>(_e2184) >= _e2186);
                                                local_225 = _e2187;
                                                if _e2187 {
                                                    phi_2124_ = _e2170;
                                                } else {
                                                    let _e2188 = local_223;
                                                    phi_2124_ = (_e2188 + 1u);
                                                }
                                                let _e2191 = phi_2124_;
                                                let _e2192 = local_225;
                                                let _e2193 = local_223;
                                                let _e2194 = local_221;
                                                phi_2098_ = _e2191;
                                                phi_2101_ = select(_e2194, _e2193, _e2192);
                                            } else {
                                                phi_2098_ = u32();
                                                phi_2101_ = u32();
                                            }
                                            let _e2197 = phi_2098_;
                                            let _e2199 = phi_2101_;
                                            continue;
                                            continuing {
                                                let _e2200 = local_222;
                                                phi_2097_ = _e2197;
                                                phi_2100_ = _e2199;
                                                phi_5042_ = _e2151;
                                                break if !(_e2200);
                                            }
                                        }
                                        let _e2203 = phi_5042_;
                                        phi_5047_ = _e2203;
                                        if _e2203 {
                                            break;
                                        }
                                        phi_5049_ = _e2203;
                                        let _e4285 = local_463;
                                        phi_2126_ = _e4285;
                                    } else {
                                        phi_5049_ = _e2151;
                                        phi_2126_ = 0u;
                                    }
                                    let _e2205 = phi_5049_;
                                    let _e2207 = phi_2126_;
                                    local_226 = _e2207;
                                    let _e2208 = local_217;
                                    if _e2208 {
                                    } else {
                                        phi_5047_ = true;
                                        break;
                                    }
                                    let _e2209 = local_216;
                                    let _e2211 = local_226;
                                    local_454[_e2209] = _e2211;
                                    let _e2212 = local_216;
                                    phi_5048_ = _e2205;
                                    phi_2068_ = (_e2212 + 1u);
                                } else {
                                    phi_5048_ = _e2151;
                                    phi_2068_ = u32();
                                }
                                let _e2215 = phi_5048_;
                                let _e2217 = phi_2068_;
                                continue;
                                continuing {
                                    let _e2218 = local_217;
                                    phi_5046_ = _e2215;
                                    phi_2067_ = _e2217;
                                    phi_5047_ = _e2215;
                                    break if !(_e2218);
                                }
                            }
                            let _e2221 = phi_5047_;
                            phi_5278_ = _e2221;
                            if _e2221 {
                                break;
                            }
                            let _e2222 = local_454[0u];
                            local_458[0u] = _e2222;
                            let _e2224 = local_458[0u];
                            let _e2225 = f32(_e2224);
                            let _e2226 = local_20;
                            local_227 = ((_e2226 >> bitcast<u32>(8u)) & 7u);
                            phi_5055_ = _e2221;
                            phi_2157_ = _e2061;
                            phi_2160_ = type_31(_e2117, _e2118, _e2119, _e2120, ((_e2114 & 2u) != 0u));
                            phi_2162_ = 0u;
                            phi_2164_ = select(select(u32(_e2225), 0u, !((_e2225 >= 0f))), 4294967295u, (_e2225 > 4294967000f));
                            phi_2166_ = _e2225;
                            phi_2168_ = 0f;
                            phi_2170_ = false;
                            phi_2172_ = array<f32, 3>(_e2082, _e2083, bitcast<f32>(_e2080));
                            loop {
                                let _e2237 = phi_5055_;
                                let _e2239 = phi_2157_;
                                let _e2241 = phi_2160_;
                                let _e2243 = phi_2162_;
                                let _e2245 = phi_2164_;
                                let _e2247 = phi_2166_;
                                let _e2249 = phi_2168_;
                                let _e2251 = phi_2170_;
                                let _e2253 = phi_2172_;
                                local_228 = _e2239;
                                local_229 = _e2241;
                                local_230 = _e2243;
                                local_231 = _e2245;
                                local_232 = _e2247;
                                local_233 = _e2249;
                                local_234 = _e2251;
                                local_235 = _e2253;
                                let _e2254 = local_230;
                                let _e2255 = local_231;
                                let _e2256 = (_e2254 < _e2255);
                                local_236 = _e2256;
                                if _e2256 {
                                    let _e2257 = local_230;
                                    let _e2258 = (1536u + _e2257);
                                    local_237 = _e2258;
                                    if (_e2258 < 5888u) {
                                    } else {
                                        phi_5156_ = true;
                                        break;
                                    }
                                    let _e2260 = local_237;
                                    let _e2262 = global_11[_e2260];
                                    local_238 = bitcast<f32>(_e2262);
                                    let _e2264 = local_230;
                                    let _e2265 = (1792u + _e2264);
                                    local_239 = _e2265;
                                    if (_e2265 < 5888u) {
                                    } else {
                                        phi_5156_ = true;
                                        break;
                                    }
                                    let _e2267 = local_239;
                                    let _e2269 = global_11[_e2267];
                                    local_240 = bitcast<f32>(_e2269);
                                    let _e2271 = local_230;
                                    let _e2272 = (2048u + _e2271);
                                    local_241 = _e2272;
                                    if (_e2272 < 5888u) {
                                    } else {
                                        phi_5156_ = true;
                                        break;
                                    }
                                    let _e2274 = local_241;
                                    let _e2276 = global_11[_e2274];
                                    let _e2277 = bitcast<f32>(_e2276);
                                    local_242 = _e2277;
                                    let _e2278 = local_197;
                                    let _e2279 = local_238;
                                    let _e2280 = (_e2278 - _e2279);
                                    local_243 = _e2280;
                                    let _e2281 = local_198;
                                    let _e2282 = local_240;
                                    let _e2283 = (_e2281 - _e2282);
                                    local_244 = _e2283;
                                    let _e2286 = ((_e2280 * _e2280) + (_e2283 * _e2283));
                                    local_245 = _e2286;
                                    let _e2289 = local_230;
                                    let _e2291 = local_232;
                                    let _e2293 = ((_e2286 < (_e2277 * _e2277)) && (f32(_e2289) < _e2291));
                                    local_246 = _e2293;
                                    if _e2293 {
                                        let _e2294 = local_230;
                                        let _e2295 = (5632u + _e2294);
                                        local_247 = _e2295;
                                        if (_e2295 < 5888u) {
                                        } else {
                                            phi_5156_ = true;
                                            break;
                                        }
                                        let _e2297 = local_247;
                                        let _e2299 = global_11[_e2297];
                                        local_248 = _e2299;
                                        let _e2300 = local_230;
                                        let _e2301 = (3584u + _e2300);
                                        local_249 = _e2301;
                                        if (_e2301 < 5888u) {
                                        } else {
                                            phi_5156_ = true;
                                            break;
                                        }
                                        let _e2303 = local_249;
                                        let _e2305 = global_11[_e2303];
                                        local_250 = bitcast<f32>(_e2305);
                                        let _e2307 = local_248;
                                        let _e2308 = (_e2307 != 0u);
                                        local_251 = _e2308;
                                        if _e2308 {
                                            let _e2751 = local_242;
                                            let _e2752 = (_e2751 - 1.4142135f);
                                            local_252 = _e2752;
                                            let _e2753 = local_242;
                                            let _e2754 = (_e2753 - 2.828427f);
                                            let _e2757 = local_245;
                                            let _e2759 = ((_e2754 > 0f) && (_e2757 <= (_e2754 * _e2754)));
                                            local_253 = _e2759;
                                            let _e2761 = ((3.1415927f * _e2752) * _e2752);
                                            local_254 = _e2761;
                                            let _e2762 = (1f / _e2761);
                                            local_255 = _e2762;
                                            let _e2764 = local_246;
                                            let _e2765 = (_e2764 && !(_e2759));
                                            local_256 = _e2765;
                                            if _e2765 {
                                                let _e2766 = local_227;
                                                let _e2767 = local_227;
                                                local_257 = (_e2766 * _e2767);
                                                phi_2260_ = 0u;
                                                phi_2263_ = 0f;
                                                phi_2265_ = 0u;
                                                loop {
                                                    let _e2770 = phi_2260_;
                                                    let _e2772 = phi_2263_;
                                                    let _e2774 = phi_2265_;
                                                    local_258 = _e2770;
                                                    local_259 = _e2772;
                                                    local_260 = _e2774;
                                                    let _e2775 = local_258;
                                                    let _e2776 = local_257;
                                                    if (_e2775 < _e2776) {
                                                        let _e2778 = local_258;
                                                        let _e2779 = (_e2778 < 16u);
                                                        if _e2779 {
                                                            let _e2780 = local_258;
                                                            let _e2784 = local_248;
                                                            if ((_e2784 & (1u << bitcast<u32>((_e2780 & 31u)))) == 0u) {
                                                                phi_3103_ = _e2772;
                                                                phi_3104_ = _e2774;
                                                            } else {
                                                                let _e2787 = local_227;
                                                                local_261 = f32(_e2787);
                                                                let _e2789 = local_227;
                                                                let _e2790 = (_e2789 == 0u);
                                                                local_262 = _e2790;
                                                                if _e2790 {
                                                                    phi_5050_ = true;
                                                                    break;
                                                                }
                                                                let _e2791 = local_258;
                                                                let _e2792 = local_227;
                                                                let _e2796 = local_261;
                                                                local_263 = ((f32((_e2791 % _e2792)) + 0.5f) / _e2796);
                                                                let _e2798 = local_262;
                                                                if _e2798 {
                                                                    phi_5050_ = true;
                                                                    break;
                                                                }
                                                                let _e2799 = local_258;
                                                                let _e2800 = local_227;
                                                                let _e2804 = local_261;
                                                                let _e2806 = local_243;
                                                                let _e2807 = local_263;
                                                                let _e2808 = (_e2806 - _e2807);
                                                                local_264 = _e2808;
                                                                let _e2809 = local_244;
                                                                let _e2810 = (_e2809 - ((f32((_e2799 / _e2800)) + 0.5f) / _e2804));
                                                                local_265 = _e2810;
                                                                local_266 = (_e2808 + 1f);
                                                                local_267 = (_e2810 + 1f);
                                                                let _e2813 = local_252;
                                                                if (_e2813 >= 0.0001f) {
                                                                    let _e2827 = local_264;
                                                                    let _e2829 = local_266;
                                                                    let _e2831 = local_264;
                                                                    let _e2834 = local_264;
                                                                    let _e2835 = select(select(0f, (-1f - _e2831), (_e2829 < 0f)), _e2834, (0f < _e2827));
                                                                    let _e2836 = local_265;
                                                                    let _e2838 = local_267;
                                                                    let _e2840 = local_265;
                                                                    let _e2841 = (-1f - _e2840);
                                                                    local_268 = _e2841;
                                                                    let _e2843 = local_265;
                                                                    let _e2844 = select(select(0f, _e2841, (_e2838 < 0f)), _e2843, (0f < _e2836));
                                                                    let _e2845 = local_252;
                                                                    let _e2846 = local_252;
                                                                    let _e2847 = (_e2845 * _e2846);
                                                                    local_269 = _e2847;
                                                                    let _e2851 = (_e2847 <= ((_e2835 * _e2835) + (_e2844 * _e2844)));
                                                                    local_270 = _e2851;
                                                                    let _e2852 = local_264;
                                                                    let _e2853 = -(_e2852);
                                                                    let _e2854 = local_266;
                                                                    let _e2856 = local_266;
                                                                    let _e2857 = select(_e2856, _e2853, (_e2854 < _e2853));
                                                                    let _e2858 = local_265;
                                                                    let _e2859 = -(_e2858);
                                                                    local_271 = _e2859;
                                                                    let _e2860 = local_267;
                                                                    let _e2862 = local_267;
                                                                    let _e2863 = select(_e2862, _e2859, (_e2860 < _e2859));
                                                                    let _e2867 = (((_e2857 * _e2857) + (_e2863 * _e2863)) <= _e2847);
                                                                    local_272 = _e2867;
                                                                    let _e2869 = local_256;
                                                                    if ((_e2869 && !(_e2851)) && !(_e2867)) {
                                                                        let _e2873 = local_252;
                                                                        if (_e2873 > 0f) {
                                                                            let _e2875 = local_265;
                                                                            let _e2876 = (0f <= _e2875);
                                                                            let _e2878 = local_267;
                                                                            let _e2880 = (!(_e2876) && (_e2878 <= 0f));
                                                                            let _e2881 = local_271;
                                                                            let _e2882 = local_267;
                                                                            let _e2883 = select(_e2882, _e2881, _e2880);
                                                                            let _e2884 = local_268;
                                                                            let _e2885 = local_271;
                                                                            let _e2887 = local_265;
                                                                            let _e2888 = select(select(_e2885, _e2884, _e2880), _e2887, _e2876);
                                                                            let _e2892 = local_269;
                                                                            let _e2893 = (_e2892 - (_e2883 * _e2883));
                                                                            let _e2896 = select(0f, sqrt(_e2893), (0f < _e2893));
                                                                            let _e2897 = local_264;
                                                                            let _e2899 = -(_e2896);
                                                                            let _e2900 = local_264;
                                                                            let _e2902 = local_264;
                                                                            let _e2904 = select(select(_e2902, _e2899, (_e2900 < _e2899)), _e2896, (_e2896 < _e2897));
                                                                            let _e2905 = local_266;
                                                                            let _e2907 = local_266;
                                                                            let _e2909 = local_266;
                                                                            let _e2911 = select(select(_e2909, _e2899, (_e2907 < _e2899)), _e2896, (_e2896 < _e2905));
                                                                            let _e2912 = local_252;
                                                                            let _e2913 = local_264;
                                                                            let _e2915 = local_242;
                                                                            let _e2916 = (1.4142135f - _e2915);
                                                                            let _e2917 = local_264;
                                                                            let _e2919 = local_264;
                                                                            let _e2921 = local_252;
                                                                            let _e2922 = select(select(_e2919, _e2916, (_e2917 < _e2916)), _e2921, (_e2912 < _e2913));
                                                                            let _e2923 = local_252;
                                                                            let _e2924 = local_266;
                                                                            let _e2926 = local_266;
                                                                            let _e2928 = local_266;
                                                                            let _e2930 = local_252;
                                                                            let _e2931 = select(select(_e2928, _e2916, (_e2926 < _e2916)), _e2930, (_e2923 < _e2924));
                                                                            let _e2935 = local_269;
                                                                            let _e2936 = (_e2935 - (_e2931 * _e2931));
                                                                            let _e2940 = local_252;
                                                                            let _e2941 = (_e2931 / _e2940);
                                                                            let _e2945 = select(select(_e2941, -1f, (_e2941 < -1f)), 1f, (1f < _e2941));
                                                                            let _e2947 = (_e2945 < 0f);
                                                                            let _e2949 = select(_e2945, -(_e2945), _e2947);
                                                                            let _e2951 = select(_e2949, 1f, (1f < _e2949));
                                                                            let _e2952 = (_e2951 <= 0.5f);
                                                                            let _e2956 = select(sqrt((0.5f * (1f - _e2951))), _e2951, _e2952);
                                                                            let _e2957 = (_e2956 * _e2956);
                                                                            let _e2968 = (_e2956 + ((_e2956 * _e2957) * (0.1666673f + (_e2957 * (0.07496333f + (_e2957 * (0.04533125f + (_e2957 * (0.024905317f + (_e2957 * 0.04087546f))))))))));
                                                                            let _e2971 = select((1.5707964f - (2f * _e2968)), _e2968, _e2952);
                                                                            let _e2974 = local_269;
                                                                            let _e2979 = local_269;
                                                                            let _e2980 = (_e2979 - (_e2922 * _e2922));
                                                                            let _e2984 = local_252;
                                                                            let _e2985 = (_e2922 / _e2984);
                                                                            let _e2989 = select(select(_e2985, -1f, (_e2985 < -1f)), 1f, (1f < _e2985));
                                                                            let _e2991 = (_e2989 < 0f);
                                                                            let _e2993 = select(_e2989, -(_e2989), _e2991);
                                                                            let _e2995 = select(_e2993, 1f, (1f < _e2993));
                                                                            let _e2996 = (_e2995 <= 0.5f);
                                                                            let _e3000 = select(sqrt((0.5f * (1f - _e2995))), _e2995, _e2996);
                                                                            let _e3001 = (_e3000 * _e3000);
                                                                            let _e3012 = (_e3000 + ((_e3000 * _e3001) * (0.1666673f + (_e3001 * (0.07496333f + (_e3001 * (0.04533125f + (_e3001 * (0.024905317f + (_e3001 * 0.04087546f))))))))));
                                                                            let _e3015 = select((1.5707964f - (2f * _e3012)), _e3012, _e2996);
                                                                            let _e3018 = local_269;
                                                                            let _e3022 = ((0.5f * ((_e2931 * select(0f, sqrt(_e2936), (0f < _e2936))) + (_e2974 * select(_e2971, -(_e2971), _e2947)))) - (0.5f * ((_e2922 * select(0f, sqrt(_e2980), (0f < _e2980))) + (_e3018 * select(_e3015, -(_e3015), _e2991)))));
                                                                            let _e3025 = local_269;
                                                                            let _e3026 = (_e3025 - (_e2911 * _e2911));
                                                                            let _e3030 = local_252;
                                                                            let _e3031 = (_e2911 / _e3030);
                                                                            let _e3035 = select(select(_e3031, -1f, (_e3031 < -1f)), 1f, (1f < _e3031));
                                                                            let _e3037 = (_e3035 < 0f);
                                                                            let _e3039 = select(_e3035, -(_e3035), _e3037);
                                                                            let _e3041 = select(_e3039, 1f, (1f < _e3039));
                                                                            let _e3042 = (_e3041 <= 0.5f);
                                                                            let _e3046 = select(sqrt((0.5f * (1f - _e3041))), _e3041, _e3042);
                                                                            let _e3047 = (_e3046 * _e3046);
                                                                            let _e3058 = (_e3046 + ((_e3046 * _e3047) * (0.1666673f + (_e3047 * (0.07496333f + (_e3047 * (0.04533125f + (_e3047 * (0.024905317f + (_e3047 * 0.04087546f))))))))));
                                                                            let _e3061 = select((1.5707964f - (2f * _e3058)), _e3058, _e3042);
                                                                            let _e3064 = local_269;
                                                                            let _e3069 = local_269;
                                                                            let _e3070 = (_e3069 - (_e2904 * _e2904));
                                                                            let _e3074 = local_252;
                                                                            let _e3075 = (_e2904 / _e3074);
                                                                            let _e3079 = select(select(_e3075, -1f, (_e3075 < -1f)), 1f, (1f < _e3075));
                                                                            let _e3081 = (_e3079 < 0f);
                                                                            let _e3083 = select(_e3079, -(_e3079), _e3081);
                                                                            let _e3085 = select(_e3083, 1f, (1f < _e3083));
                                                                            let _e3086 = (_e3085 <= 0.5f);
                                                                            let _e3090 = select(sqrt((0.5f * (1f - _e3085))), _e3085, _e3086);
                                                                            let _e3091 = (_e3090 * _e3090);
                                                                            let _e3102 = (_e3090 + ((_e3090 * _e3091) * (0.1666673f + (_e3091 * (0.07496333f + (_e3091 * (0.04533125f + (_e3091 * (0.024905317f + (_e3091 * 0.04087546f))))))))));
                                                                            let _e3105 = select((1.5707964f - (2f * _e3102)), _e3102, _e3086);
                                                                            let _e3108 = local_269;
                                                                            let _e3115 = local_269;
                                                                            let _e3116 = (_e3115 - (_e2888 * _e2888));
                                                                            let _e3119 = select(0f, sqrt(_e3116), (0f < _e3116));
                                                                            let _e3120 = local_264;
                                                                            let _e3122 = -(_e3119);
                                                                            let _e3123 = local_264;
                                                                            let _e3125 = local_264;
                                                                            let _e3127 = select(select(_e3125, _e3122, (_e3123 < _e3122)), _e3119, (_e3119 < _e3120));
                                                                            let _e3128 = local_266;
                                                                            let _e3130 = local_266;
                                                                            let _e3132 = local_266;
                                                                            let _e3134 = select(select(_e3132, _e3122, (_e3130 < _e3122)), _e3119, (_e3119 < _e3128));
                                                                            let _e3139 = local_269;
                                                                            let _e3140 = (_e3139 - (_e3134 * _e3134));
                                                                            let _e3144 = local_252;
                                                                            let _e3145 = (_e3134 / _e3144);
                                                                            let _e3149 = select(select(_e3145, -1f, (_e3145 < -1f)), 1f, (1f < _e3145));
                                                                            let _e3151 = (_e3149 < 0f);
                                                                            let _e3153 = select(_e3149, -(_e3149), _e3151);
                                                                            let _e3155 = select(_e3153, 1f, (1f < _e3153));
                                                                            let _e3156 = (_e3155 <= 0.5f);
                                                                            let _e3160 = select(sqrt((0.5f * (1f - _e3155))), _e3155, _e3156);
                                                                            let _e3161 = (_e3160 * _e3160);
                                                                            let _e3172 = (_e3160 + ((_e3160 * _e3161) * (0.1666673f + (_e3161 * (0.07496333f + (_e3161 * (0.04533125f + (_e3161 * (0.024905317f + (_e3161 * 0.04087546f))))))))));
                                                                            let _e3175 = select((1.5707964f - (2f * _e3172)), _e3172, _e3156);
                                                                            let _e3178 = local_269;
                                                                            let _e3183 = local_269;
                                                                            let _e3184 = (_e3183 - (_e3127 * _e3127));
                                                                            let _e3188 = local_252;
                                                                            let _e3189 = (_e3127 / _e3188);
                                                                            let _e3193 = select(select(_e3189, -1f, (_e3189 < -1f)), 1f, (1f < _e3189));
                                                                            let _e3195 = (_e3193 < 0f);
                                                                            let _e3197 = select(_e3193, -(_e3193), _e3195);
                                                                            let _e3199 = select(_e3197, 1f, (1f < _e3197));
                                                                            let _e3200 = (_e3199 <= 0.5f);
                                                                            let _e3204 = select(sqrt((0.5f * (1f - _e3199))), _e3199, _e3200);
                                                                            let _e3205 = (_e3204 * _e3204);
                                                                            let _e3216 = (_e3204 + ((_e3204 * _e3205) * (0.1666673f + (_e3205 * (0.07496333f + (_e3205 * (0.04533125f + (_e3205 * (0.024905317f + (_e3205 * 0.04087546f))))))))));
                                                                            let _e3219 = select((1.5707964f - (2f * _e3216)), _e3216, _e3200);
                                                                            let _e3222 = local_269;
                                                                            let _e3229 = ((((_e2883 * (_e2911 - _e2904)) + _e3022) - ((0.5f * ((_e2911 * select(0f, sqrt(_e3026), (0f < _e3026))) + (_e3064 * select(_e3061, -(_e3061), _e3037)))) - (0.5f * ((_e2904 * select(0f, sqrt(_e3070), (0f < _e3070))) + (_e3108 * select(_e3105, -(_e3105), _e3081)))))) + (select(1f, -1f, (_e2876 || _e2880)) * (((_e2888 * (_e3134 - _e3127)) + _e3022) - ((0.5f * ((_e3134 * select(0f, sqrt(_e3140), (0f < _e3140))) + (_e3178 * select(_e3175, -(_e3175), _e3151)))) - (0.5f * ((_e3127 * select(0f, sqrt(_e3184), (0f < _e3184))) + (_e3222 * select(_e3219, -(_e3219), _e3195))))))));
                                                                            let _e3230 = local_266;
                                                                            let _e3231 = local_264;
                                                                            let _e3233 = local_267;
                                                                            let _e3234 = local_265;
                                                                            let _e3236 = ((_e3230 - _e3231) * (_e3233 - _e3234));
                                                                            phi_3076_ = select(select(0f, _e3229, (0f < _e3229)), _e3236, (_e3236 < _e3229));
                                                                        } else {
                                                                            phi_3076_ = 0f;
                                                                        }
                                                                        let _e3242 = phi_3076_;
                                                                        let _e3243 = local_272;
                                                                        phi_3081_ = select(_e3242, 1f, _e3243);
                                                                    } else {
                                                                        phi_3081_ = 1f;
                                                                    }
                                                                    let _e3246 = phi_3081_;
                                                                    let _e3247 = local_254;
                                                                    let _e3249 = local_270;
                                                                    phi_3100_ = select((_e3246 / _e3247), 0f, _e3249);
                                                                } else {
                                                                    let _e2815 = local_264;
                                                                    let _e2817 = local_266;
                                                                    let _e2820 = local_265;
                                                                    let _e2823 = local_267;
                                                                    phi_3100_ = select(0f, 1f, ((((_e2815 <= 0f) && (0f < _e2817)) && (_e2820 <= 0f)) && (0f < _e2823)));
                                                                }
                                                                let _e3252 = phi_3100_;
                                                                let _e3253 = local_259;
                                                                let _e3255 = local_260;
                                                                phi_3103_ = (_e3253 + _e3252);
                                                                phi_3104_ = (_e3255 + 1u);
                                                            }
                                                            let _e3258 = phi_3103_;
                                                            let _e3260 = phi_3104_;
                                                            let _e3261 = local_258;
                                                            phi_3106_ = (_e3261 + 1u);
                                                            phi_3107_ = _e3258;
                                                            phi_3108_ = _e3260;
                                                        } else {
                                                            phi_3106_ = u32();
                                                            phi_3107_ = f32();
                                                            phi_3108_ = u32();
                                                        }
                                                        let _e3264 = phi_3106_;
                                                        let _e3266 = phi_3107_;
                                                        let _e3268 = phi_3108_;
                                                        phi_2261_ = _e3264;
                                                        phi_2264_ = _e3266;
                                                        phi_2266_ = _e3268;
                                                        phi_3109_ = _e2779;
                                                    } else {
                                                        phi_2261_ = u32();
                                                        phi_2264_ = f32();
                                                        phi_2266_ = u32();
                                                        phi_3109_ = false;
                                                    }
                                                    let _e3270 = phi_2261_;
                                                    let _e3272 = phi_2264_;
                                                    let _e3274 = phi_2266_;
                                                    let _e3276 = phi_3109_;
                                                    local_273 = _e3276;
                                                    continue;
                                                    continuing {
                                                        let _e3277 = local_273;
                                                        phi_2260_ = _e3270;
                                                        phi_2263_ = _e3272;
                                                        phi_2265_ = _e3274;
                                                        phi_5050_ = _e2237;
                                                        break if !(_e3277);
                                                    }
                                                }
                                                let _e3280 = phi_5050_;
                                                phi_5156_ = _e3280;
                                                if _e3280 {
                                                    break;
                                                }
                                                let _e3281 = local_260;
                                                if (_e3281 == 0u) {
                                                    phi_3120_ = 0f;
                                                } else {
                                                    let _e3283 = local_260;
                                                    let _e3285 = local_259;
                                                    phi_3120_ = (_e3285 / f32(_e3283));
                                                }
                                                let _e3288 = phi_3120_;
                                                let _e3289 = local_253;
                                                let _e3290 = local_255;
                                                phi_5179_ = _e3280;
                                                phi_3125_ = select(_e3288, _e3290, _e3289);
                                            } else {
                                                phi_5179_ = _e2237;
                                                phi_3125_ = _e2762;
                                            }
                                            let _e3293 = phi_5179_;
                                            let _e3295 = phi_3125_;
                                            phi_5178_ = _e3293;
                                            phi_3592_ = _e3295;
                                        } else {
                                            let _e2309 = local_25;
                                            let _e2310 = (_e2309 == 0u);
                                            local_274 = _e2310;
                                            if _e2310 {
                                                let _e2311 = local_32;
                                                phi_3136_ = (_e2311 == 0u);
                                            } else {
                                                phi_3136_ = false;
                                            }
                                            let _e2314 = phi_3136_;
                                            if _e2314 {
                                                let _e2729 = local_242;
                                                let _e2730 = local_250;
                                                let _e2731 = (_e2729 - _e2730);
                                                let _e2734 = local_245;
                                                let _e2737 = local_245;
                                                let _e2739 = local_242;
                                                let _e2741 = local_250;
                                                let _e2743 = ((_e2739 - sqrt(_e2737)) * (1f / _e2741));
                                                phi_3591_ = select(select(0f, select(1f, _e2743, (_e2743 < 1f)), (0f < _e2743)), 1f, ((0f < _e2731) && (_e2734 <= (_e2731 * _e2731))));
                                            } else {
                                                let _e2315 = local_230;
                                                let _e2316 = (3840u + _e2315);
                                                local_275 = _e2316;
                                                if (_e2316 < 5888u) {
                                                } else {
                                                    phi_5156_ = true;
                                                    break;
                                                }
                                                let _e2318 = local_275;
                                                let _e2320 = global_11[_e2318];
                                                local_276 = bitcast<f32>(_e2320);
                                                let _e2322 = local_274;
                                                if _e2322 {
                                                    let _e2323 = local_32;
                                                    phi_3182_ = (_e2323 == 0u);
                                                } else {
                                                    phi_3182_ = false;
                                                }
                                                let _e2326 = phi_3182_;
                                                if _e2326 {
                                                    let _e2707 = local_242;
                                                    let _e2708 = local_250;
                                                    let _e2709 = (_e2707 - _e2708);
                                                    let _e2712 = local_245;
                                                    let _e2715 = local_245;
                                                    let _e2717 = local_242;
                                                    let _e2719 = local_250;
                                                    let _e2721 = ((_e2717 - sqrt(_e2715)) * (1f / _e2719));
                                                    phi_3590_ = select(select(0f, select(1f, _e2721, (_e2721 < 1f)), (0f < _e2721)), 1f, ((0f < _e2709) && (_e2712 <= (_e2709 * _e2709))));
                                                } else {
                                                    let _e2327 = local_276;
                                                    let _e2328 = local_243;
                                                    local_277 = (_e2327 * _e2328);
                                                    let _e2330 = local_276;
                                                    let _e2331 = local_244;
                                                    local_278 = (_e2330 * _e2331);
                                                    let _e2333 = local_32;
                                                    if (_e2333 > 0u) {
                                                        let _e2416 = local_250;
                                                        let _e2418 = local_242;
                                                        let _e2419 = (_e2418 - (0.5f * _e2416));
                                                        local_279 = _e2419;
                                                        if (_e2419 > 0f) {
                                                            let _e2421 = local_277;
                                                            let _e2422 = local_279;
                                                            let _e2424 = local_278;
                                                            let _e2425 = local_279;
                                                            let _e2427 = local_32;
                                                            let _e2428 = f32(_e2427);
                                                            local_280 = _e2428;
                                                            let _e2432 = (((((_e2421 / _e2422) + 1f) * 0.5f) * _e2428) - 0.5f);
                                                            local_281 = _e2432;
                                                            local_282 = (((((_e2424 / _e2425) + 1f) * 0.5f) * _e2428) - 0.5f);
                                                            if (_e2432 > -1f) {
                                                                let _e2438 = local_282;
                                                                if (_e2438 > -1f) {
                                                                    let _e2440 = local_281;
                                                                    let _e2441 = local_280;
                                                                    if (_e2440 < _e2441) {
                                                                        let _e2443 = local_282;
                                                                        let _e2444 = local_280;
                                                                        let _e2445 = (_e2443 < _e2444);
                                                                        local_283 = _e2445;
                                                                        if _e2445 {
                                                                            let _e2446 = local_281;
                                                                            let _e2447 = floor(_e2446);
                                                                            local_284 = _e2447;
                                                                            let _e2448 = local_282;
                                                                            let _e2449 = floor(_e2448);
                                                                            local_285 = _e2449;
                                                                            let _e2450 = local_281;
                                                                            local_286 = (_e2450 - _e2447);
                                                                            let _e2452 = local_282;
                                                                            local_287 = (_e2452 - _e2449);
                                                                            let _e2454 = (_e2447 < 0f);
                                                                            local_288 = _e2454;
                                                                            if _e2454 {
                                                                                phi_3303_ = f32();
                                                                                phi_3304_ = true;
                                                                            } else {
                                                                                let _e2455 = local_285;
                                                                                if (_e2455 < 0f) {
                                                                                    phi_3301_ = f32();
                                                                                    phi_3302_ = true;
                                                                                } else {
                                                                                    let _e2457 = local_284;
                                                                                    let _e2458 = local_280;
                                                                                    if (_e2457 >= _e2458) {
                                                                                        phi_3299_ = f32();
                                                                                        phi_3300_ = true;
                                                                                    } else {
                                                                                        let _e2460 = local_285;
                                                                                        let _e2461 = local_280;
                                                                                        let _e2462 = (_e2460 >= _e2461);
                                                                                        if _e2462 {
                                                                                            phi_3298_ = f32();
                                                                                        } else {
                                                                                            let _e2463 = local_285;
                                                                                            let _e2465 = local_285;
                                                                                            let _e2468 = local_285;
                                                                                            let _e2472 = local_32;
                                                                                            let _e2474 = local_284;
                                                                                            let _e2476 = local_284;
                                                                                            let _e2479 = local_284;
                                                                                            let _e2483 = ((select(select(u32(_e2463), 0u, !((_e2465 >= 0f))), 4294967295u, (_e2468 > 4294967000f)) * _e2472) + select(select(u32(_e2474), 0u, !((_e2476 >= 0f))), 4294967295u, (_e2479 > 4294967000f)));
                                                                                            local_289 = _e2483;
                                                                                            let _e2484 = local_8;
                                                                                            if (_e2483 < _e2484) {
                                                                                            } else {
                                                                                                phi_5156_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2486 = local_289;
                                                                                            let _e2489 = global_10.member[_e2486];
                                                                                            phi_3298_ = bitcast<f32>(_e2489);
                                                                                        }
                                                                                        let _e2492 = phi_3298_;
                                                                                        phi_3299_ = _e2492;
                                                                                        phi_3300_ = _e2462;
                                                                                    }
                                                                                    let _e2494 = phi_3299_;
                                                                                    let _e2496 = phi_3300_;
                                                                                    phi_3301_ = _e2494;
                                                                                    phi_3302_ = _e2496;
                                                                                }
                                                                                let _e2498 = phi_3301_;
                                                                                let _e2500 = phi_3302_;
                                                                                phi_3303_ = _e2498;
                                                                                phi_3304_ = _e2500;
                                                                            }
                                                                            let _e2502 = phi_3303_;
                                                                            let _e2504 = phi_3304_;
                                                                            let _e2506 = local_286;
                                                                            let _e2507 = (1f - _e2506);
                                                                            local_290 = _e2507;
                                                                            local_291 = (select(_e2502, 0f, _e2504) * _e2507);
                                                                            let _e2509 = local_284;
                                                                            let _e2510 = (_e2509 + 1f);
                                                                            local_292 = _e2510;
                                                                            let _e2511 = (_e2510 < 0f);
                                                                            local_293 = _e2511;
                                                                            if _e2511 {
                                                                                phi_3359_ = f32();
                                                                                phi_3360_ = true;
                                                                            } else {
                                                                                let _e2512 = local_285;
                                                                                if (_e2512 < 0f) {
                                                                                    phi_3357_ = f32();
                                                                                    phi_3358_ = true;
                                                                                } else {
                                                                                    let _e2514 = local_292;
                                                                                    let _e2515 = local_280;
                                                                                    if (_e2514 >= _e2515) {
                                                                                        phi_3355_ = f32();
                                                                                        phi_3356_ = true;
                                                                                    } else {
                                                                                        let _e2517 = local_285;
                                                                                        let _e2518 = local_280;
                                                                                        let _e2519 = (_e2517 >= _e2518);
                                                                                        if _e2519 {
                                                                                            phi_3354_ = f32();
                                                                                        } else {
                                                                                            let _e2520 = local_285;
                                                                                            let _e2522 = local_285;
                                                                                            let _e2525 = local_285;
                                                                                            let _e2529 = local_32;
                                                                                            let _e2531 = local_292;
                                                                                            let _e2533 = local_292;
                                                                                            let _e2536 = local_292;
                                                                                            let _e2540 = ((select(select(u32(_e2520), 0u, !((_e2522 >= 0f))), 4294967295u, (_e2525 > 4294967000f)) * _e2529) + select(select(u32(_e2531), 0u, !((_e2533 >= 0f))), 4294967295u, (_e2536 > 4294967000f)));
                                                                                            local_294 = _e2540;
                                                                                            let _e2541 = local_8;
                                                                                            if (_e2540 < _e2541) {
                                                                                            } else {
                                                                                                phi_5156_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2543 = local_294;
                                                                                            let _e2546 = global_10.member[_e2543];
                                                                                            phi_3354_ = bitcast<f32>(_e2546);
                                                                                        }
                                                                                        let _e2549 = phi_3354_;
                                                                                        phi_3355_ = _e2549;
                                                                                        phi_3356_ = _e2519;
                                                                                    }
                                                                                    let _e2551 = phi_3355_;
                                                                                    let _e2553 = phi_3356_;
                                                                                    phi_3357_ = _e2551;
                                                                                    phi_3358_ = _e2553;
                                                                                }
                                                                                let _e2555 = phi_3357_;
                                                                                let _e2557 = phi_3358_;
                                                                                phi_3359_ = _e2555;
                                                                                phi_3360_ = _e2557;
                                                                            }
                                                                            let _e2559 = phi_3359_;
                                                                            let _e2561 = phi_3360_;
                                                                            let _e2563 = local_286;
                                                                            let _e2565 = local_291;
                                                                            local_295 = (_e2565 + (select(_e2559, 0f, _e2561) * _e2563));
                                                                            let _e2567 = local_285;
                                                                            local_296 = (_e2567 + 1f);
                                                                            let _e2569 = local_288;
                                                                            if _e2569 {
                                                                                phi_3415_ = f32();
                                                                                phi_3416_ = true;
                                                                            } else {
                                                                                let _e2570 = local_296;
                                                                                if (_e2570 < 0f) {
                                                                                    phi_3413_ = f32();
                                                                                    phi_3414_ = true;
                                                                                } else {
                                                                                    let _e2572 = local_284;
                                                                                    let _e2573 = local_280;
                                                                                    if (_e2572 >= _e2573) {
                                                                                        phi_3411_ = f32();
                                                                                        phi_3412_ = true;
                                                                                    } else {
                                                                                        let _e2575 = local_296;
                                                                                        let _e2576 = local_280;
                                                                                        let _e2577 = (_e2575 >= _e2576);
                                                                                        if _e2577 {
                                                                                            phi_3410_ = f32();
                                                                                        } else {
                                                                                            let _e2578 = local_296;
                                                                                            let _e2580 = local_296;
                                                                                            let _e2583 = local_296;
                                                                                            let _e2587 = local_32;
                                                                                            let _e2589 = local_284;
                                                                                            let _e2591 = local_284;
                                                                                            let _e2594 = local_284;
                                                                                            let _e2598 = ((select(select(u32(_e2578), 0u, !((_e2580 >= 0f))), 4294967295u, (_e2583 > 4294967000f)) * _e2587) + select(select(u32(_e2589), 0u, !((_e2591 >= 0f))), 4294967295u, (_e2594 > 4294967000f)));
                                                                                            local_297 = _e2598;
                                                                                            let _e2599 = local_8;
                                                                                            if (_e2598 < _e2599) {
                                                                                            } else {
                                                                                                phi_5156_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2601 = local_297;
                                                                                            let _e2604 = global_10.member[_e2601];
                                                                                            phi_3410_ = bitcast<f32>(_e2604);
                                                                                        }
                                                                                        let _e2607 = phi_3410_;
                                                                                        phi_3411_ = _e2607;
                                                                                        phi_3412_ = _e2577;
                                                                                    }
                                                                                    let _e2609 = phi_3411_;
                                                                                    let _e2611 = phi_3412_;
                                                                                    phi_3413_ = _e2609;
                                                                                    phi_3414_ = _e2611;
                                                                                }
                                                                                let _e2613 = phi_3413_;
                                                                                let _e2615 = phi_3414_;
                                                                                phi_3415_ = _e2613;
                                                                                phi_3416_ = _e2615;
                                                                            }
                                                                            let _e2617 = phi_3415_;
                                                                            let _e2619 = phi_3416_;
                                                                            let _e2621 = local_290;
                                                                            local_298 = (select(_e2617, 0f, _e2619) * _e2621);
                                                                            let _e2623 = local_293;
                                                                            if _e2623 {
                                                                                phi_3472_ = f32();
                                                                                phi_3473_ = true;
                                                                            } else {
                                                                                let _e2624 = local_296;
                                                                                if (_e2624 < 0f) {
                                                                                    phi_3470_ = f32();
                                                                                    phi_3471_ = true;
                                                                                } else {
                                                                                    let _e2626 = local_292;
                                                                                    let _e2627 = local_280;
                                                                                    if (_e2626 >= _e2627) {
                                                                                        phi_3468_ = f32();
                                                                                        phi_3469_ = true;
                                                                                    } else {
                                                                                        let _e2629 = local_296;
                                                                                        let _e2630 = local_280;
                                                                                        let _e2631 = (_e2629 >= _e2630);
                                                                                        if _e2631 {
                                                                                            phi_3467_ = f32();
                                                                                        } else {
                                                                                            let _e2632 = local_296;
                                                                                            let _e2634 = local_296;
                                                                                            let _e2637 = local_296;
                                                                                            let _e2641 = local_32;
                                                                                            let _e2643 = local_292;
                                                                                            let _e2645 = local_292;
                                                                                            let _e2648 = local_292;
                                                                                            let _e2652 = ((select(select(u32(_e2632), 0u, !((_e2634 >= 0f))), 4294967295u, (_e2637 > 4294967000f)) * _e2641) + select(select(u32(_e2643), 0u, !((_e2645 >= 0f))), 4294967295u, (_e2648 > 4294967000f)));
                                                                                            local_299 = _e2652;
                                                                                            let _e2653 = local_8;
                                                                                            if (_e2652 < _e2653) {
                                                                                            } else {
                                                                                                phi_5156_ = true;
                                                                                                break;
                                                                                            }
                                                                                            let _e2655 = local_299;
                                                                                            let _e2658 = global_10.member[_e2655];
                                                                                            phi_3467_ = bitcast<f32>(_e2658);
                                                                                        }
                                                                                        let _e2661 = phi_3467_;
                                                                                        phi_3468_ = _e2661;
                                                                                        phi_3469_ = _e2631;
                                                                                    }
                                                                                    let _e2663 = phi_3468_;
                                                                                    let _e2665 = phi_3469_;
                                                                                    phi_3470_ = _e2663;
                                                                                    phi_3471_ = _e2665;
                                                                                }
                                                                                let _e2667 = phi_3470_;
                                                                                let _e2669 = phi_3471_;
                                                                                phi_3472_ = _e2667;
                                                                                phi_3473_ = _e2669;
                                                                            }
                                                                            let _e2671 = phi_3472_;
                                                                            let _e2673 = phi_3473_;
                                                                            let _e2675 = local_286;
                                                                            let _e2677 = local_298;
                                                                            let _e2679 = local_287;
                                                                            let _e2681 = local_295;
                                                                            let _e2683 = local_287;
                                                                            phi_3484_ = ((_e2681 * (1f - _e2679)) + ((_e2677 + (select(_e2671, 0f, _e2673) * _e2675)) * _e2683));
                                                                        } else {
                                                                            phi_3484_ = f32();
                                                                        }
                                                                        let _e2687 = phi_3484_;
                                                                        let _e2688 = local_283;
                                                                        phi_3486_ = _e2687;
                                                                        phi_3487_ = select(true, false, _e2688);
                                                                    } else {
                                                                        phi_3486_ = f32();
                                                                        phi_3487_ = true;
                                                                    }
                                                                    let _e2691 = phi_3486_;
                                                                    let _e2693 = phi_3487_;
                                                                    phi_3488_ = _e2691;
                                                                    phi_3489_ = _e2693;
                                                                } else {
                                                                    phi_3488_ = f32();
                                                                    phi_3489_ = true;
                                                                }
                                                                let _e2695 = phi_3488_;
                                                                let _e2697 = phi_3489_;
                                                                phi_3490_ = _e2695;
                                                                phi_3491_ = _e2697;
                                                            } else {
                                                                phi_3490_ = f32();
                                                                phi_3491_ = true;
                                                            }
                                                            let _e2699 = phi_3490_;
                                                            let _e2701 = phi_3491_;
                                                            phi_3496_ = select(_e2699, 0f, _e2701);
                                                        } else {
                                                            phi_3496_ = 0f;
                                                        }
                                                        let _e2704 = phi_3496_;
                                                        phi_3589_ = _e2704;
                                                    } else {
                                                        let _e2335 = local_277;
                                                        let _e2336 = local_277;
                                                        let _e2338 = local_278;
                                                        let _e2339 = local_278;
                                                        let _e2342 = sqrt(((_e2335 * _e2336) + (_e2338 * _e2339)));
                                                        local_300 = _e2342;
                                                        let _e2343 = local_274;
                                                        if _e2343 {
                                                            phi_3576_ = _e2342;
                                                        } else {
                                                            let _e2344 = local_27;
                                                            let _e2346 = local_277;
                                                            let _e2348 = local_27;
                                                            let _e2350 = local_278;
                                                            phi_3518_ = 1u;
                                                            phi_3521_ = ((_e2346 * _e2344[0]) + (_e2350 * _e2348[1]));
                                                            phi_3523_ = _e617.member_16.member_2;
                                                            loop {
                                                                let _e2354 = phi_3518_;
                                                                let _e2356 = phi_3521_;
                                                                let _e2358 = phi_3523_;
                                                                local_301 = _e2354;
                                                                local_302 = _e2356;
                                                                local_303 = _e2358;
                                                                let _e2359 = local_301;
                                                                let _e2360 = local_25;
                                                                let _e2361 = (_e2359 < _e2360);
                                                                local_304 = _e2361;
                                                                if _e2361 {
                                                                    let _e2362 = local_303;
                                                                    let _e2364 = local_28;
                                                                    let _e2366 = local_303;
                                                                    let _e2368 = local_29;
                                                                    let _e2370 = ((_e2362[0] * _e2364) - (_e2366[1] * _e2368));
                                                                    let _e2371 = local_29;
                                                                    let _e2373 = local_28;
                                                                    let _e2375 = ((_e2362[0] * _e2371) + (_e2366[1] * _e2373));
                                                                    let _e2377 = local_277;
                                                                    let _e2379 = local_278;
                                                                    let _e2381 = ((_e2377 * _e2370) + (_e2379 * _e2375));
                                                                    let _e2382 = local_302;
                                                                    let _e2384 = local_302;
                                                                    let _e2386 = local_301;
                                                                    phi_3519_ = (_e2386 + 1u);
                                                                    phi_3522_ = select(_e2384, _e2381, (_e2381 > _e2382));
                                                                    phi_3524_ = array<f32, 2>(_e2370, _e2375);
                                                                } else {
                                                                    phi_3519_ = u32();
                                                                    phi_3522_ = f32();
                                                                    phi_3524_ = array<f32, 2>();
                                                                }
                                                                let _e2389 = phi_3519_;
                                                                let _e2391 = phi_3522_;
                                                                let _e2393 = phi_3524_;
                                                                continue;
                                                                continuing {
                                                                    let _e2394 = local_304;
                                                                    phi_3518_ = _e2389;
                                                                    phi_3521_ = _e2391;
                                                                    phi_3523_ = _e2393;
                                                                    break if !(_e2394);
                                                                }
                                                            }
                                                            let _e2396 = local_26;
                                                            let _e2398 = local_302;
                                                            let _e2400 = local_30;
                                                            let _e2402 = local_26;
                                                            let _e2403 = local_300;
                                                            phi_3576_ = ((((1f - _e2396) * _e2398) * _e2400) + (_e2402 * _e2403));
                                                        }
                                                        let _e2407 = phi_3576_;
                                                        let _e2408 = local_242;
                                                        let _e2410 = local_250;
                                                        let _e2411 = ((_e2408 - _e2407) / _e2410);
                                                        phi_3589_ = select(0f, select(1f, _e2411, (_e2411 < 1f)), (0f < _e2411));
                                                    }
                                                    let _e2706 = phi_3589_;
                                                    phi_3590_ = _e2706;
                                                }
                                                let _e2728 = phi_3590_;
                                                phi_3591_ = _e2728;
                                            }
                                            let _e2750 = phi_3591_;
                                            phi_5178_ = _e2237;
                                            phi_3592_ = _e2750;
                                        }
                                        let _e3297 = phi_5178_;
                                        let _e3299 = phi_3592_;
                                        local_305 = _e3299;
                                        let _e3300 = local_230;
                                        let _e3301 = (2304u + _e3300);
                                        local_306 = _e3301;
                                        if (_e3301 < 5888u) {
                                        } else {
                                            phi_5156_ = true;
                                            break;
                                        }
                                        let _e3303 = local_306;
                                        let _e3305 = global_11[_e3303];
                                        let _e3307 = local_305;
                                        local_307 = (bitcast<f32>(_e3305) * _e3307);
                                        let _e3309 = local_230;
                                        let _e3310 = (4096u + _e3309);
                                        local_308 = _e3310;
                                        if (_e3310 < 5888u) {
                                        } else {
                                            phi_5156_ = true;
                                            break;
                                        }
                                        let _e3312 = local_308;
                                        let _e3314 = global_11[_e3312];
                                        local_309 = bitcast<f32>(_e3314);
                                        let _e3316 = local_80;
                                        let _e3317 = local_230;
                                        let _e3319 = local_60;
                                        if ((_e3316 + _e3317) < _e3319) {
                                            let _e3342 = local_230;
                                            let _e3343 = (3328u + _e3342);
                                            local_310 = _e3343;
                                            if (_e3343 < 5888u) {
                                            } else {
                                                phi_5156_ = true;
                                                break;
                                            }
                                            let _e3345 = local_310;
                                            let _e3347 = global_11[_e3345];
                                            let _e3348 = bitcast<f32>(_e3347);
                                            local_311 = _e3348;
                                            let _e3349 = local_228;
                                            let _e3350 = (1f - _e3349);
                                            local_312 = _e3350;
                                            let _e3351 = local_229;
                                            local_313 = _e3351.member;
                                            let _e3356 = local_229;
                                            local_314 = _e3356.member_1;
                                            let _e3358 = local_307;
                                            let _e3362 = (!((_e3348 <= (_e3351.member * 1.05f))) || (1f < (_e3356.member_1 + (0.5f * _e3358))));
                                            let _e3363 = local_229;
                                            local_315 = _e3363.member_3;
                                            let _e3366 = local_229;
                                            local_316 = _e3366.member_4;
                                            let _e3369 = !(_e3362);
                                            local_317 = ((_e3362 && !(_e3363.member_3)) || (_e3369 && _e3366.member_4));
                                            local_318 = (_e3369 && _e3363.member_3);
                                            let _e3373 = local_229;
                                            local_319 = _e3373.member_2;
                                            local_449 = select(_e3373.member_2, _e3350, _e3362);
                                            let _e3377 = local_307;
                                            local_320 = (select(_e3356.member_1, 0f, _e3362) + _e3377);
                                            let _e3379 = local_309;
                                            let _e3380 = (_e3379 < 1f);
                                            local_321 = _e3380;
                                            if _e3380 {
                                                let _e3381 = local_251;
                                                if _e3381 {
                                                    phi_3687_ = type_18();
                                                } else {
                                                    let _e3382 = local_317;
                                                    let _e3383 = local_449;
                                                    let _e3385 = local_307;
                                                    let _e3386 = (_e3385 * select(1f, _e3383, _e3382));
                                                    local_322 = _e3386;
                                                    let _e3387 = local_309;
                                                    let _e3388 = (_e3386 * _e3387);
                                                    local_323 = _e3388;
                                                    let _e3389 = local_312;
                                                    local_324 = (_e3388 < _e3389);
                                                    let _e3391 = local_309;
                                                    if (_e3391 == 1f) {
                                                        phi_3677_ = _e3350;
                                                    } else {
                                                        let _e3393 = local_312;
                                                        let _e3394 = local_309;
                                                        phi_3677_ = (_e3393 / _e3394);
                                                    }
                                                    let _e3397 = phi_3677_;
                                                    let _e3398 = local_324;
                                                    let _e3399 = local_322;
                                                    let _e3401 = local_324;
                                                    let _e3402 = local_323;
                                                    let _e3403 = local_312;
                                                    phi_3687_ = type_18(select(_e3397, _e3399, _e3398), select(_e3403, _e3402, _e3401));
                                                }
                                                let _e3407 = phi_3687_;
                                                phi_3688_ = _e3407;
                                            } else {
                                                phi_3688_ = type_18();
                                            }
                                            let _e3409 = phi_3688_;
                                            let _e3410 = local_321;
                                            let _e3411 = local_251;
                                            let _e3412 = select(true, _e3411, _e3410);
                                            local_450 = _e3412;
                                            if _e3412 {
                                                let _e3413 = local_307;
                                                let _e3414 = local_309;
                                                let _e3415 = (_e3413 * _e3414);
                                                local_325 = _e3415;
                                                let _e3416 = local_312;
                                                local_326 = (_e3415 < _e3416);
                                                let _e3418 = local_309;
                                                if (_e3418 == 1f) {
                                                    phi_3700_ = _e3350;
                                                } else {
                                                    let _e3420 = local_312;
                                                    let _e3421 = local_309;
                                                    phi_3700_ = (_e3420 / _e3421);
                                                }
                                                let _e3424 = phi_3700_;
                                                let _e3425 = local_326;
                                                let _e3426 = local_307;
                                                let _e3428 = local_326;
                                                let _e3429 = local_325;
                                                let _e3430 = local_312;
                                                phi_3711_ = type_18(select(_e3424, _e3426, _e3425), select(_e3430, _e3429, _e3428));
                                            } else {
                                                phi_3711_ = _e3409;
                                            }
                                            let _e3434 = phi_3711_;
                                            let _e3435 = local_450;
                                            let _e3436 = local_318;
                                            let _e3438 = local_246;
                                            let _e3439 = local_311;
                                            let _e3440 = local_313;
                                            let _e3442 = local_246;
                                            let _e3443 = local_320;
                                            let _e3444 = local_314;
                                            let _e3446 = local_246;
                                            let _e3447 = local_449;
                                            let _e3448 = local_319;
                                            let _e3450 = local_246;
                                            let _e3452 = local_246;
                                            let _e3453 = !(_e3452);
                                            let _e3454 = local_315;
                                            let _e3457 = local_246;
                                            let _e3458 = local_317;
                                            let _e3460 = local_316;
                                            phi_3763_ = type_31(select(_e3440, _e3439, _e3438), select(_e3444, _e3443, _e3442), select(_e3448, _e3447, _e3446), ((_e3450 && select(_e3436, true, _e3435)) || (_e3453 && _e3454)), ((_e3457 && _e3458) || (_e3453 && _e3460)));
                                            phi_3764_ = _e3434;
                                        } else {
                                            let _e3321 = local_228;
                                            let _e3322 = (1f - _e3321);
                                            local_327 = _e3322;
                                            let _e3323 = local_307;
                                            let _e3324 = local_309;
                                            let _e3325 = (_e3323 * _e3324);
                                            local_328 = _e3325;
                                            local_329 = (_e3325 < _e3322);
                                            let _e3327 = local_309;
                                            if (_e3327 == 1f) {
                                                phi_3753_ = _e3322;
                                            } else {
                                                let _e3329 = local_327;
                                                let _e3330 = local_309;
                                                phi_3753_ = (_e3329 / _e3330);
                                            }
                                            let _e3333 = phi_3753_;
                                            let _e3334 = local_329;
                                            let _e3335 = local_307;
                                            let _e3337 = local_329;
                                            let _e3338 = local_328;
                                            let _e3339 = local_327;
                                            phi_3763_ = _e2241;
                                            phi_3764_ = type_18(select(_e3333, _e3335, _e3334), select(_e3339, _e3338, _e3337));
                                        }
                                        let _e3465 = phi_3763_;
                                        let _e3467 = phi_3764_;
                                        local_330 = _e3467.member;
                                        local_331 = _e3467.member_1;
                                        let _e3470 = local_235;
                                        local_332 = _e3470[0];
                                        let _e3472 = local_230;
                                        let _e3473 = (2560u + _e3472);
                                        local_333 = _e3473;
                                        if (_e3473 < 5888u) {
                                        } else {
                                            phi_5156_ = true;
                                            break;
                                        }
                                        let _e3475 = local_333;
                                        let _e3477 = global_11[_e3475];
                                        let _e3479 = local_330;
                                        let _e3481 = local_332;
                                        let _e3483 = local_246;
                                        let _e3484 = local_332;
                                        local_451 = select(_e3484, (_e3481 + (_e3479 * bitcast<f32>(_e3477))), _e3483);
                                        let _e3486 = local_235;
                                        local_334 = _e3486[1];
                                        let _e3488 = local_230;
                                        let _e3489 = (2816u + _e3488);
                                        local_335 = _e3489;
                                        if (_e3489 < 5888u) {
                                        } else {
                                            phi_5156_ = true;
                                            break;
                                        }
                                        let _e3491 = local_335;
                                        let _e3493 = global_11[_e3491];
                                        let _e3495 = local_330;
                                        let _e3497 = local_334;
                                        let _e3499 = local_246;
                                        let _e3500 = local_334;
                                        local_452 = select(_e3500, (_e3497 + (_e3495 * bitcast<f32>(_e3493))), _e3499);
                                        let _e3502 = local_235;
                                        local_336 = _e3502[2];
                                        let _e3504 = local_230;
                                        let _e3505 = (3072u + _e3504);
                                        local_337 = _e3505;
                                        if (_e3505 < 5888u) {
                                        } else {
                                            phi_5156_ = true;
                                            break;
                                        }
                                        let _e3507 = local_337;
                                        let _e3509 = global_11[_e3507];
                                        let _e3511 = local_330;
                                        let _e3513 = local_336;
                                        let _e3515 = local_246;
                                        let _e3516 = local_336;
                                        let _e3518 = local_451;
                                        let _e3519 = local_452;
                                        let _e3521 = local_228;
                                        let _e3522 = local_331;
                                        let _e3524 = local_246;
                                        let _e3525 = local_228;
                                        let _e3526 = select(_e3525, (_e3521 + _e3522), _e3524);
                                        let _e3529 = local_246;
                                        let _e3530 = (_e3529 && !((_e3526 < 0.99902344f)));
                                        local_338 = _e3530;
                                        if _e3530 {
                                            let _e3531 = local_234;
                                            let _e3532 = local_338;
                                            let _e3534 = local_230;
                                            let _e3537 = local_338;
                                            let _e3538 = local_233;
                                            let _e3540 = local_338;
                                            let _e3541 = local_232;
                                            let _e3542 = select(_e3541, 0f, _e3540);
                                            phi_3849_ = select(select(u32(_e3542), 0u, !((_e3542 >= 0f))), 4294967295u, (_e3542 > 4294967000f));
                                            phi_3850_ = _e3542;
                                            phi_3851_ = select(_e3538, f32((_e3534 + 1u)), _e3537);
                                            phi_3852_ = (_e3531 || _e3532);
                                        } else {
                                            phi_3849_ = _e2245;
                                            phi_3850_ = _e2247;
                                            phi_3851_ = _e2249;
                                            phi_3852_ = _e2251;
                                        }
                                        let _e3550 = phi_3849_;
                                        let _e3552 = phi_3850_;
                                        let _e3554 = phi_3851_;
                                        let _e3556 = phi_3852_;
                                        phi_5158_ = _e3297;
                                        phi_3853_ = _e3526;
                                        phi_3854_ = _e3465;
                                        phi_3855_ = _e3550;
                                        phi_3856_ = _e3552;
                                        phi_3857_ = _e3554;
                                        phi_3858_ = _e3556;
                                        phi_3859_ = array<f32, 3>(_e3518, _e3519, select(_e3516, (_e3513 + (_e3511 * bitcast<f32>(_e3509))), _e3515));
                                    } else {
                                        phi_5158_ = _e2237;
                                        phi_3853_ = _e2239;
                                        phi_3854_ = _e2241;
                                        phi_3855_ = _e2245;
                                        phi_3856_ = _e2247;
                                        phi_3857_ = _e2249;
                                        phi_3858_ = _e2251;
                                        phi_3859_ = _e2253;
                                    }
                                    let _e3558 = phi_5158_;
                                    let _e3560 = phi_3853_;
                                    let _e3562 = phi_3854_;
                                    let _e3564 = phi_3855_;
                                    let _e3566 = phi_3856_;
                                    let _e3568 = phi_3857_;
                                    let _e3570 = phi_3858_;
                                    let _e3572 = phi_3859_;
                                    let _e3573 = local_230;
                                    phi_5157_ = _e3558;
                                    phi_2158_ = _e3560;
                                    phi_2161_ = _e3562;
                                    phi_2163_ = (_e3573 + 1u);
                                    phi_2165_ = _e3564;
                                    phi_2167_ = _e3566;
                                    phi_2169_ = _e3568;
                                    phi_2171_ = _e3570;
                                    phi_2173_ = _e3572;
                                } else {
                                    phi_5157_ = _e2237;
                                    phi_2158_ = f32();
                                    phi_2161_ = type_31();
                                    phi_2163_ = u32();
                                    phi_2165_ = u32();
                                    phi_2167_ = f32();
                                    phi_2169_ = f32();
                                    phi_2171_ = bool();
                                    phi_2173_ = array<f32, 3>();
                                }
                                let _e3576 = phi_5157_;
                                let _e3578 = phi_2158_;
                                let _e3580 = phi_2161_;
                                let _e3582 = phi_2163_;
                                let _e3584 = phi_2165_;
                                let _e3586 = phi_2167_;
                                let _e3588 = phi_2169_;
                                let _e3590 = phi_2171_;
                                let _e3592 = phi_2173_;
                                continue;
                                continuing {
                                    let _e3593 = local_236;
                                    phi_5055_ = _e3576;
                                    phi_2157_ = _e3578;
                                    phi_2160_ = _e3580;
                                    phi_2162_ = _e3582;
                                    phi_2164_ = _e3584;
                                    phi_2166_ = _e3586;
                                    phi_2168_ = _e3588;
                                    phi_2170_ = _e3590;
                                    phi_2172_ = _e3592;
                                    phi_5156_ = _e3576;
                                    break if !(_e3593);
                                }
                            }
                            let _e3596 = phi_5156_;
                            phi_5278_ = _e3596;
                            if _e3596 {
                                break;
                            }
                            let _e3597 = local_235;
                            local_339 = _e3597[0];
                            phi_3863_ = 0u;
                            loop {
                                let _e3600 = phi_3863_;
                                local_340 = _e3600;
                                let _e3601 = local_340;
                                let _e3602 = (_e3601 < 1u);
                                local_341 = _e3602;
                                if _e3602 {
                                    let _e3603 = local;
                                    let _e3604 = local_340;
                                    let _e3605 = (_e3603 + _e3604);
                                    local_342 = _e3605;
                                    let _e3606 = local_339;
                                    local_343 = bitcast<u32>(_e3606);
                                    if (_e3605 < 5888u) {
                                    } else {
                                        phi_5232_ = true;
                                        break;
                                    }
                                    let _e3609 = local_342;
                                    let _e3611 = local_343;
                                    global_11[_e3609] = _e3611;
                                    let _e3612 = local_340;
                                    phi_3864_ = (_e3612 + 1u);
                                } else {
                                    phi_3864_ = u32();
                                }
                                let _e3615 = phi_3864_;
                                continue;
                                continuing {
                                    let _e3616 = local_341;
                                    phi_3863_ = _e3615;
                                    phi_5232_ = _e3596;
                                    break if !(_e3616);
                                }
                            }
                            let _e3619 = phi_5232_;
                            phi_5278_ = _e3619;
                            if _e3619 {
                                break;
                            }
                            let _e3620 = local_235;
                            local_344 = _e3620[1];
                            phi_3884_ = 0u;
                            loop {
                                let _e3623 = phi_3884_;
                                local_345 = _e3623;
                                let _e3624 = local_345;
                                let _e3625 = (_e3624 < 1u);
                                local_346 = _e3625;
                                if _e3625 {
                                    let _e3626 = local;
                                    let _e3627 = local_345;
                                    let _e3629 = local_344;
                                    local_347 = bitcast<u32>(_e3629);
                                    let _e3631 = (256u + (_e3626 + _e3627));
                                    local_348 = _e3631;
                                    if (_e3631 < 5888u) {
                                    } else {
                                        phi_5235_ = true;
                                        break;
                                    }
                                    let _e3633 = local_348;
                                    let _e3635 = local_347;
                                    global_11[_e3633] = _e3635;
                                    let _e3636 = local_345;
                                    phi_3885_ = (_e3636 + 1u);
                                } else {
                                    phi_3885_ = u32();
                                }
                                let _e3639 = phi_3885_;
                                continue;
                                continuing {
                                    let _e3640 = local_346;
                                    phi_3884_ = _e3639;
                                    phi_5235_ = _e3619;
                                    break if !(_e3640);
                                }
                            }
                            let _e3643 = phi_5235_;
                            phi_5278_ = _e3643;
                            if _e3643 {
                                break;
                            }
                            let _e3644 = local_235;
                            local_349 = _e3644[2];
                            phi_3905_ = 0u;
                            loop {
                                let _e3647 = phi_3905_;
                                local_350 = _e3647;
                                let _e3648 = local_350;
                                let _e3649 = (_e3648 < 1u);
                                local_351 = _e3649;
                                if _e3649 {
                                    let _e3650 = local;
                                    let _e3651 = local_350;
                                    let _e3653 = local_349;
                                    local_352 = bitcast<u32>(_e3653);
                                    let _e3655 = (512u + (_e3650 + _e3651));
                                    local_353 = _e3655;
                                    if (_e3655 < 5888u) {
                                    } else {
                                        phi_5238_ = true;
                                        break;
                                    }
                                    let _e3657 = local_353;
                                    let _e3659 = local_352;
                                    global_11[_e3657] = _e3659;
                                    let _e3660 = local_350;
                                    phi_3906_ = (_e3660 + 1u);
                                } else {
                                    phi_3906_ = u32();
                                }
                                let _e3663 = phi_3906_;
                                continue;
                                continuing {
                                    let _e3664 = local_351;
                                    phi_3905_ = _e3663;
                                    phi_5238_ = _e3643;
                                    break if !(_e3664);
                                }
                            }
                            let _e3667 = phi_5238_;
                            phi_5278_ = _e3667;
                            if _e3667 {
                                break;
                            }
                            phi_3925_ = 0u;
                            loop {
                                let _e3669 = phi_3925_;
                                local_354 = _e3669;
                                let _e3670 = local_354;
                                let _e3671 = (_e3670 < 1u);
                                local_355 = _e3671;
                                if _e3671 {
                                    let _e3672 = local;
                                    let _e3673 = local_354;
                                    let _e3675 = local_228;
                                    local_356 = bitcast<u32>(_e3675);
                                    let _e3677 = (768u + (_e3672 + _e3673));
                                    local_357 = _e3677;
                                    if (_e3677 < 5888u) {
                                    } else {
                                        phi_5241_ = true;
                                        break;
                                    }
                                    let _e3679 = local_357;
                                    let _e3681 = local_356;
                                    global_11[_e3679] = _e3681;
                                    let _e3682 = local_354;
                                    phi_3926_ = (_e3682 + 1u);
                                } else {
                                    phi_3926_ = u32();
                                }
                                let _e3685 = phi_3926_;
                                continue;
                                continuing {
                                    let _e3686 = local_355;
                                    phi_3925_ = _e3685;
                                    phi_5241_ = _e3667;
                                    break if !(_e3686);
                                }
                            }
                            let _e3689 = phi_5241_;
                            phi_5278_ = _e3689;
                            if _e3689 {
                                break;
                            }
                            phi_3946_ = 0u;
                            loop {
                                let _e3691 = phi_3946_;
                                local_358 = _e3691;
                                let _e3692 = local_358;
                                let _e3693 = (_e3692 < 1u);
                                local_359 = _e3693;
                                if _e3693 {
                                    let _e3694 = local_229;
                                    local_360 = bitcast<u32>(_e3694.member);
                                    let _e3697 = local_73;
                                    let _e3698 = local_358;
                                    let _e3699 = (_e3697 + _e3698);
                                    local_361 = _e3699;
                                    if (_e3699 < 5888u) {
                                    } else {
                                        phi_5244_ = true;
                                        break;
                                    }
                                    let _e3701 = local_361;
                                    let _e3703 = local_360;
                                    global_11[_e3701] = _e3703;
                                    let _e3704 = local_229;
                                    local_362 = bitcast<u32>(_e3704.member_1);
                                    let _e3707 = local_206;
                                    let _e3708 = local_358;
                                    let _e3709 = (_e3707 + _e3708);
                                    local_363 = _e3709;
                                    if (_e3709 < 5888u) {
                                    } else {
                                        phi_5244_ = true;
                                        break;
                                    }
                                    let _e3711 = local_363;
                                    let _e3713 = local_362;
                                    global_11[_e3711] = _e3713;
                                    let _e3714 = local_229;
                                    local_364 = bitcast<u32>(_e3714.member_2);
                                    let _e3717 = local_208;
                                    let _e3718 = local_358;
                                    let _e3719 = (_e3717 + _e3718);
                                    local_365 = _e3719;
                                    if (_e3719 < 5888u) {
                                    } else {
                                        phi_5244_ = true;
                                        break;
                                    }
                                    let _e3721 = local_365;
                                    let _e3723 = local_364;
                                    global_11[_e3721] = _e3723;
                                    let _e3724 = local_229;
                                    local_366 = select(0u, 1u, _e3724.member_3);
                                    let _e3727 = local_229;
                                    local_367 = (select(0u, 1u, _e3727.member_4) << bitcast<u32>(1i));
                                    let _e3732 = local_210;
                                    let _e3733 = local_358;
                                    let _e3734 = (_e3732 + _e3733);
                                    local_368 = _e3734;
                                    if (_e3734 < 5888u) {
                                    } else {
                                        phi_5244_ = true;
                                        break;
                                    }
                                    let _e3736 = local_368;
                                    let _e3738 = local_366;
                                    let _e3739 = local_367;
                                    global_11[_e3736] = (_e3738 | _e3739);
                                    let _e3741 = local_358;
                                    phi_3947_ = (_e3741 + 1u);
                                } else {
                                    phi_3947_ = u32();
                                }
                                let _e3744 = phi_3947_;
                                continue;
                                continuing {
                                    let _e3745 = local_359;
                                    phi_3946_ = _e3744;
                                    phi_5244_ = _e3689;
                                    break if !(_e3745);
                                }
                            }
                            let _e3748 = phi_5244_;
                            phi_5278_ = _e3748;
                            if _e3748 {
                                break;
                            }
                            phi_4002_ = 0u;
                            loop {
                                let _e3750 = phi_4002_;
                                local_369 = _e3750;
                                let _e3751 = local_369;
                                let _e3752 = (_e3751 < 1u);
                                local_370 = _e3752;
                                if _e3752 {
                                    let _e3753 = local;
                                    let _e3754 = local_369;
                                    local_371 = (_e3753 + _e3754);
                                    let _e3756 = local_234;
                                    if _e3756 {
                                        let _e3780 = local_233;
                                        let _e3782 = local_233;
                                        let _e3785 = local_233;
                                        phi_4062_ = false;
                                        phi_4063_ = select(select(u32(_e3780), 0u, !((_e3782 >= 0f))), 4294967295u, (_e3785 > 4294967000f));
                                    } else {
                                        let _e3757 = local_370;
                                        if _e3757 {
                                        } else {
                                            phi_5247_ = true;
                                            break;
                                        }
                                        let _e3758 = local_369;
                                        let _e3760 = local_457[_e3758];
                                        if _e3760 {
                                            let _e3761 = local_370;
                                            if _e3761 {
                                            } else {
                                                phi_5247_ = true;
                                                break;
                                            }
                                            let _e3762 = local_369;
                                            let _e3764 = local_458[_e3762];
                                            let _e3765 = local_447;
                                            if (_e3764 < _e3765) {
                                                let _e3767 = local_370;
                                                if _e3767 {
                                                } else {
                                                    phi_5247_ = true;
                                                    break;
                                                }
                                                let _e3768 = local_458[_e3762];
                                                phi_4051_ = (_e3768 + 1u);
                                            } else {
                                                phi_4051_ = _e1992;
                                            }
                                            let _e3771 = phi_4051_;
                                            let _e3772 = local_370;
                                            if _e3772 {
                                            } else {
                                                phi_5247_ = true;
                                                break;
                                            }
                                            let _e3773 = local_458[_e3762];
                                            let _e3774 = local_447;
                                            phi_4060_ = (_e3773 == _e3774);
                                            phi_4061_ = _e3771;
                                        } else {
                                            phi_4060_ = false;
                                            phi_4061_ = 0u;
                                        }
                                        let _e3777 = phi_4060_;
                                        let _e3779 = phi_4061_;
                                        phi_4062_ = _e3777;
                                        phi_4063_ = _e3779;
                                    }
                                    let _e3790 = phi_4062_;
                                    let _e3792 = phi_4063_;
                                    local_372 = _e3790;
                                    local_373 = _e3792;
                                    let _e3793 = local_370;
                                    if _e3793 {
                                    } else {
                                        phi_5247_ = true;
                                        break;
                                    }
                                    let _e3794 = local_369;
                                    let _e3796 = local_456[_e3794];
                                    if _e3796 {
                                        let _e3797 = local_371;
                                        let _e3798 = (1280u + _e3797);
                                        local_374 = _e3798;
                                        if (_e3798 < 5888u) {
                                        } else {
                                            phi_5247_ = true;
                                            break;
                                        }
                                        let _e3800 = local_374;
                                        let _e3802 = global_11[_e3800];
                                        let _e3803 = local_373;
                                        global_11[_e3800] = (_e3802 + _e3803);
                                    }
                                    let _e3805 = local_371;
                                    let _e3806 = (4352u + _e3805);
                                    local_375 = _e3806;
                                    if (_e3806 < 5888u) {
                                    } else {
                                        phi_5247_ = true;
                                        break;
                                    }
                                    let _e3808 = local_375;
                                    let _e3810 = local_372;
                                    global_11[_e3808] = select(0u, 1u, _e3810);
                                    let _e3812 = local_369;
                                    phi_4003_ = (_e3812 + 1u);
                                } else {
                                    phi_4003_ = u32();
                                }
                                let _e3815 = phi_4003_;
                                continue;
                                continuing {
                                    let _e3816 = local_370;
                                    phi_4002_ = _e3815;
                                    phi_5247_ = _e3748;
                                    break if !(_e3816);
                                }
                            }
                            let _e3819 = phi_5247_;
                            phi_5278_ = _e3819;
                            if _e3819 {
                                break;
                            }
                            storageBarrier();
                            workgroupBarrier();
                            phi_4182_ = 128u;
                            loop {
                                let _e3821 = phi_4182_;
                                local_376 = _e3821;
                                let _e3822 = local_376;
                                let _e3823 = (_e3822 > 0u);
                                local_377 = _e3823;
                                if _e3823 {
                                    let _e3824 = local;
                                    let _e3825 = local_376;
                                    if (_e3824 < _e3825) {
                                        let _e3827 = local_55;
                                        if _e3827 {
                                        } else {
                                            phi_5254_ = true;
                                            break;
                                        }
                                        let _e3828 = global_11[_e853];
                                        local_378 = _e3828;
                                        let _e3829 = local_54;
                                        let _e3830 = local_376;
                                        let _e3831 = (_e3829 + _e3830);
                                        local_379 = _e3831;
                                        if (_e3831 < 5888u) {
                                        } else {
                                            phi_5254_ = true;
                                            break;
                                        }
                                        let _e3833 = local_379;
                                        let _e3835 = global_11[_e3833];
                                        let _e3836 = local_378;
                                        let _e3838 = local_378;
                                        local_453 = select(_e3835, _e3838, (_e3836 > _e3835));
                                        let _e3840 = local_55;
                                        if _e3840 {
                                        } else {
                                            phi_5254_ = true;
                                            break;
                                        }
                                        let _e3841 = local_453;
                                        global_11[_e853] = _e3841;
                                    }
                                    storageBarrier();
                                    workgroupBarrier();
                                    let _e3842 = local_376;
                                    phi_4183_ = (_e3842 / 2u);
                                } else {
                                    phi_4183_ = u32();
                                }
                                let _e3845 = phi_4183_;
                                continue;
                                continuing {
                                    let _e3846 = local_377;
                                    phi_4182_ = _e3845;
                                    phi_5254_ = _e3819;
                                    break if !(_e3846);
                                }
                            }
                            let _e3849 = phi_5254_;
                            phi_5278_ = _e3849;
                            if _e3849 {
                                break;
                            }
                            let _e3850 = global_11[4352u];
                            storageBarrier();
                            workgroupBarrier();
                            let _e3851 = local_80;
                            phi_5280_ = _e3849;
                            phi_4232_ = (_e3851 + 256u);
                            phi_4233_ = _e3850;
                        }
                        let _e3854 = phi_5280_;
                        let _e3856 = phi_4232_;
                        let _e3858 = phi_4233_;
                        let _e3859 = local_82;
                        phi_5279_ = _e3854;
                        phi_728_ = _e3856;
                        phi_731_ = _e3858;
                        phi_4235_ = select(true, false, _e3859);
                    } else {
                        phi_5279_ = _e1014;
                        phi_728_ = u32();
                        phi_731_ = u32();
                        phi_4235_ = false;
                    }
                    let _e3862 = phi_5279_;
                    let _e3864 = phi_728_;
                    let _e3866 = phi_731_;
                    let _e3868 = phi_4235_;
                    local_380 = _e3868;
                    continue;
                    continuing {
                        let _e3869 = local_380;
                        phi_4968_ = _e3862;
                        phi_727_ = _e3864;
                        phi_730_ = _e3866;
                        phi_5278_ = _e3862;
                        break if !(_e3869);
                    }
                }
                let _e3872 = phi_5278_;
                if _e3872 {
                    break;
                }
                let _e3873 = local_33;
                if _e3873 {
                    break;
                }
                let _e3874 = local_33;
                if _e3874 {
                    break;
                }
                let _e3875 = local_67;
                if _e3875 {
                    let _e3876 = local_64;
                    let _e3877 = local_13;
                    let _e3878 = (_e3876 < _e3877);
                    local_381 = _e3878;
                    if _e3878 {
                        let _e3879 = local_65;
                        let _e3880 = local_14;
                        phi_4296_ = (_e3879 < _e3880);
                    } else {
                        phi_4296_ = bool();
                    }
                    let _e3883 = phi_4296_;
                    let _e3884 = local_381;
                    phi_4298_ = _e3883;
                    phi_4299_ = select(true, false, _e3884);
                } else {
                    phi_4298_ = bool();
                    phi_4299_ = true;
                }
                let _e3887 = phi_4298_;
                let _e3889 = phi_4299_;
                if select(_e3887, false, _e3889) {
                    let _e3891 = local_65;
                    let _e3892 = local_13;
                    let _e3894 = local_64;
                    let _e3895 = ((_e3891 * _e3892) + _e3894);
                    local_382 = _e3895;
                    let _e3896 = (4u * _e3895);
                    local_383 = _e3896;
                    let _e3897 = local_1;
                    if (_e3896 < _e3897) {
                    } else {
                        break;
                    }
                    let _e3899 = local_383;
                    let _e3902 = global_4.member[_e3899];
                    local_384 = bitcast<f32>(_e3902);
                    let _e3904 = local_383;
                    let _e3905 = (_e3904 + 1u);
                    local_385 = _e3905;
                    let _e3906 = local_1;
                    if (_e3905 < _e3906) {
                    } else {
                        break;
                    }
                    let _e3908 = local_385;
                    let _e3911 = global_4.member[_e3908];
                    local_386 = bitcast<f32>(_e3911);
                    let _e3913 = local_383;
                    let _e3914 = (_e3913 + 2u);
                    local_387 = _e3914;
                    let _e3915 = local_1;
                    if (_e3914 < _e3915) {
                    } else {
                        break;
                    }
                    let _e3917 = local_387;
                    let _e3920 = global_4.member[_e3917];
                    local_388 = bitcast<f32>(_e3920);
                    let _e3922 = local_383;
                    let _e3923 = (_e3922 + 3u);
                    local_389 = _e3923;
                    let _e3924 = local_1;
                    if (_e3923 < _e3924) {
                    } else {
                        break;
                    }
                    let _e3926 = local_389;
                    let _e3929 = global_4.member[_e3926];
                    local_390 = bitcast<f32>(_e3929);
                    let _e3931 = local;
                    let _e3932 = (768u + _e3931);
                    local_391 = _e3932;
                    let _e3933 = (_e3932 < 5888u);
                    local_392 = _e3933;
                    if _e3933 {
                    } else {
                        break;
                    }
                    let _e3934 = local_391;
                    let _e3936 = global_11[_e3934];
                    local_393 = (1f - bitcast<f32>(_e3936));
                    let _e3939 = local_390;
                    if ((bitcast<u32>(_e3939) & 2147483647u) > 2139095040u) {
                    } else {
                        let _e3943 = local_393;
                        if (_e3943 > 0f) {
                            let _e3945 = local;
                            let _e3946 = (_e3945 < 5888u);
                            local_394 = _e3946;
                            if _e3946 {
                            } else {
                                break;
                            }
                            let _e3947 = local;
                            let _e3949 = global_11[_e3947];
                            let _e3951 = local_393;
                            let _e3952 = local_384;
                            local_395 = bitcast<u32>((bitcast<f32>(_e3949) + (_e3951 * _e3952)));
                            let _e3956 = local_394;
                            if _e3956 {
                            } else {
                                break;
                            }
                            let _e3957 = local_395;
                            global_11[_e3947] = _e3957;
                            let _e3958 = local;
                            let _e3959 = (256u + _e3958);
                            local_396 = _e3959;
                            let _e3960 = (_e3959 < 5888u);
                            local_397 = _e3960;
                            if _e3960 {
                            } else {
                                break;
                            }
                            let _e3961 = local_396;
                            let _e3963 = global_11[_e3961];
                            let _e3965 = local_393;
                            let _e3966 = local_386;
                            local_398 = bitcast<u32>((bitcast<f32>(_e3963) + (_e3965 * _e3966)));
                            let _e3970 = local_397;
                            if _e3970 {
                            } else {
                                break;
                            }
                            let _e3971 = local_398;
                            global_11[_e3961] = _e3971;
                            let _e3972 = local;
                            let _e3973 = (512u + _e3972);
                            local_399 = _e3973;
                            let _e3974 = (_e3973 < 5888u);
                            local_400 = _e3974;
                            if _e3974 {
                            } else {
                                break;
                            }
                            let _e3975 = local_399;
                            let _e3977 = global_11[_e3975];
                            let _e3979 = local_393;
                            let _e3980 = local_388;
                            local_401 = bitcast<u32>((bitcast<f32>(_e3977) + (_e3979 * _e3980)));
                            let _e3984 = local_400;
                            if _e3984 {
                            } else {
                                break;
                            }
                            let _e3985 = local_401;
                            global_11[_e3975] = _e3985;
                            let _e3986 = local_392;
                            if _e3986 {
                            } else {
                                break;
                            }
                            let _e3987 = global_11[_e3934];
                            let _e3989 = local_393;
                            local_402 = bitcast<u32>((bitcast<f32>(_e3987) + _e3989));
                            let _e3992 = local_392;
                            if _e3992 {
                            } else {
                                break;
                            }
                            let _e3993 = local_402;
                            global_11[_e3934] = _e3993;
                        }
                    }
                    let _e3994 = local_392;
                    if _e3994 {
                    } else {
                        break;
                    }
                    let _e3995 = global_11[_e3934];
                    let _e3996 = bitcast<f32>(_e3995);
                    local_403 = _e3996;
                    if (_e3996 > 0.000001f) {
                        let _e3998 = local_403;
                        phi_4456_ = (1f / _e3998);
                    } else {
                        phi_4456_ = 0f;
                    }
                    let _e4001 = phi_4456_;
                    local_404 = _e4001;
                    let _e4002 = local;
                    if (_e4002 < 5888u) {
                    } else {
                        break;
                    }
                    let _e4004 = local;
                    let _e4006 = global_11[_e4004];
                    let _e4008 = local_404;
                    local_405 = (bitcast<f32>(_e4006) * _e4008);
                    let _e4010 = local;
                    let _e4011 = (256u + _e4010);
                    local_406 = _e4011;
                    if (_e4011 < 5888u) {
                    } else {
                        break;
                    }
                    let _e4013 = local_406;
                    let _e4015 = global_11[_e4013];
                    let _e4017 = local_404;
                    local_407 = (bitcast<f32>(_e4015) * _e4017);
                    let _e4019 = local;
                    let _e4020 = (512u + _e4019);
                    local_408 = _e4020;
                    if (_e4020 < 5888u) {
                    } else {
                        break;
                    }
                    let _e4022 = local_408;
                    let _e4024 = global_11[_e4022];
                    let _e4026 = local_404;
                    local_409 = (bitcast<f32>(_e4024) * _e4026);
                    let _e4028 = local_382;
                    let _e4029 = (3u * _e4028);
                    local_410 = _e4029;
                    let _e4030 = local_405;
                    local_411 = bitcast<u32>(_e4030);
                    let _e4032 = local_6;
                    if (_e4029 < _e4032) {
                    } else {
                        break;
                    }
                    let _e4034 = local_410;
                    let _e4037 = local_411;
                    global_2.member[_e4034] = _e4037;
                    let _e4038 = local_410;
                    let _e4039 = (_e4038 + 1u);
                    local_412 = _e4039;
                    let _e4040 = local_407;
                    local_413 = bitcast<u32>(_e4040);
                    let _e4042 = local_6;
                    if (_e4039 < _e4042) {
                    } else {
                        break;
                    }
                    let _e4044 = local_412;
                    let _e4047 = local_413;
                    global_2.member[_e4044] = _e4047;
                    let _e4048 = local_410;
                    let _e4049 = (_e4048 + 2u);
                    local_414 = _e4049;
                    let _e4050 = local_409;
                    local_415 = bitcast<u32>(_e4050);
                    let _e4052 = local_6;
                    if (_e4049 < _e4052) {
                    } else {
                        break;
                    }
                    let _e4054 = local_414;
                    let _e4057 = local_415;
                    global_2.member[_e4054] = _e4057;
                }
                storageBarrier();
                workgroupBarrier();
                phi_4521_ = _e566;
                phi_4524_ = 0u;
                phi_4526_ = 0u;
                loop {
                    let _e4059 = phi_4521_;
                    let _e4061 = phi_4524_;
                    let _e4063 = phi_4526_;
                    local_416 = _e4059;
                    local_417 = _e4061;
                    local_418 = _e4063;
                    let _e4064 = local;
                    let _e4066 = local_416;
                    let _e4067 = (_e4066 < (_e4064 + 1u));
                    local_419 = _e4067;
                    if _e4067 {
                        let _e4068 = local_416;
                        let _e4069 = (1280u + _e4068);
                        local_420 = _e4069;
                        if (_e4069 < 5888u) {
                        } else {
                            phi_5283_ = true;
                            break;
                        }
                        let _e4071 = local_420;
                        let _e4073 = global_11[_e4071];
                        local_421 = _e4073;
                        let _e4074 = local_33;
                        if _e4074 {
                            phi_5283_ = true;
                            break;
                        }
                        let _e4075 = local_416;
                        let _e4076 = local_442;
                        let _e4078 = local_40;
                        local_422 = (_e4078 + (_e4075 % _e4076));
                        let _e4080 = local_33;
                        if _e4080 {
                            phi_5283_ = true;
                            break;
                        }
                        let _e4081 = local_416;
                        let _e4082 = local_442;
                        let _e4084 = local_42;
                        local_423 = (_e4084 + (_e4081 / _e4082));
                        let _e4086 = local_416;
                        let _e4087 = local_66;
                        if (_e4086 < _e4087) {
                            let _e4089 = local_422;
                            let _e4090 = local_13;
                            let _e4091 = (_e4089 < _e4090);
                            local_424 = _e4091;
                            if _e4091 {
                                let _e4092 = local_423;
                                let _e4093 = local_14;
                                phi_4599_ = (_e4092 < _e4093);
                            } else {
                                phi_4599_ = bool();
                            }
                            let _e4096 = phi_4599_;
                            let _e4097 = local_424;
                            phi_4601_ = _e4096;
                            phi_4602_ = select(true, false, _e4097);
                        } else {
                            phi_4601_ = bool();
                            phi_4602_ = true;
                        }
                        let _e4100 = phi_4601_;
                        let _e4102 = phi_4602_;
                        if select(_e4100, false, _e4102) {
                            let _e4104 = local_421;
                            let _e4105 = local_48;
                            if (_e4104 < _e4105) {
                                let _e4107 = local_418;
                                let _e4109 = local_48;
                                let _e4110 = local_421;
                                let _e4112 = local_417;
                                phi_4617_ = (_e4112 + (_e4109 - _e4110));
                                phi_4618_ = (_e4107 + 1u);
                            } else {
                                phi_4617_ = _e4061;
                                phi_4618_ = _e4063;
                            }
                            let _e4115 = phi_4617_;
                            let _e4117 = phi_4618_;
                            phi_4619_ = _e4115;
                            phi_4620_ = _e4117;
                        } else {
                            phi_4619_ = _e4061;
                            phi_4620_ = _e4063;
                        }
                        let _e4119 = phi_4619_;
                        let _e4121 = phi_4620_;
                        let _e4122 = local_416;
                        phi_4522_ = (_e4122 + 1u);
                        phi_4525_ = _e4119;
                        phi_4527_ = _e4121;
                    } else {
                        phi_4522_ = u32();
                        phi_4525_ = u32();
                        phi_4527_ = u32();
                    }
                    let _e4125 = phi_4522_;
                    let _e4127 = phi_4525_;
                    let _e4129 = phi_4527_;
                    continue;
                    continuing {
                        let _e4130 = local_419;
                        phi_4521_ = _e4125;
                        phi_4524_ = _e4127;
                        phi_4526_ = _e4129;
                        phi_5283_ = _e3872;
                        break if !(_e4130);
                    }
                }
                let _e4133 = phi_5283_;
                if _e4133 {
                    break;
                }
                let _e4134 = local_418;
                if (_e4134 > 0u) {
                    let _e4136 = local_7;
                    if (9u < _e4136) {
                    } else {
                        break;
                    }
                    let _e4140 = local_418;
                    let _e4141 = atomicAdd((&global_9.member[9u]), _e4140);
                    let _e4142 = local_7;
                    if (10u < _e4142) {
                    } else {
                        break;
                    }
                    let _e4146 = local_417;
                    let _e4147 = atomicAdd((&global_9.member[10u]), _e4146);
                }
                storageBarrier();
                workgroupBarrier();
            } else {
                let _e677 = local_33;
                if _e677 {
                    break;
                }
                let _e678 = local;
                let _e679 = local_442;
                let _e681 = local_40;
                local_425 = (_e681 + (_e678 % _e679));
                let _e683 = local_33;
                if _e683 {
                    break;
                }
                let _e684 = local;
                let _e685 = local_442;
                let _e687 = local_42;
                local_426 = (_e687 + (_e684 / _e685));
                let _e689 = local_442;
                let _e690 = local_442;
                let _e692 = local;
                if (_e692 < (_e689 * _e690)) {
                    let _e694 = local_425;
                    let _e695 = local_13;
                    let _e696 = (_e694 < _e695);
                    local_427 = _e696;
                    if _e696 {
                        let _e697 = local_426;
                        let _e698 = local_14;
                        phi_4696_ = (_e697 < _e698);
                    } else {
                        phi_4696_ = bool();
                    }
                    let _e701 = phi_4696_;
                    let _e702 = local_427;
                    phi_4698_ = _e701;
                    phi_4699_ = select(true, false, _e702);
                } else {
                    phi_4698_ = bool();
                    phi_4699_ = true;
                }
                let _e705 = phi_4698_;
                let _e707 = phi_4699_;
                if select(_e705, false, _e707) {
                    let _e709 = local_426;
                    let _e710 = local_13;
                    let _e712 = local_425;
                    let _e713 = ((_e709 * _e710) + _e712);
                    local_428 = _e713;
                    let _e714 = (4u * _e713);
                    local_429 = _e714;
                    let _e715 = local_1;
                    if (_e714 < _e715) {
                    } else {
                        break;
                    }
                    let _e717 = local_429;
                    let _e720 = global_4.member[_e717];
                    local_430 = bitcast<f32>(_e720);
                    let _e722 = local_429;
                    let _e723 = (_e722 + 1u);
                    local_431 = _e723;
                    let _e724 = local_1;
                    if (_e723 < _e724) {
                    } else {
                        break;
                    }
                    let _e726 = local_431;
                    let _e729 = global_4.member[_e726];
                    local_432 = bitcast<f32>(_e729);
                    let _e731 = local_429;
                    let _e732 = (_e731 + 2u);
                    local_433 = _e732;
                    let _e733 = local_1;
                    if (_e732 < _e733) {
                    } else {
                        break;
                    }
                    let _e735 = local_433;
                    let _e738 = global_4.member[_e735];
                    let _e740 = local_430;
                    let _e741 = local_432;
                    let _e743 = local_429;
                    let _e744 = (_e743 + 3u);
                    local_434 = _e744;
                    let _e745 = local_1;
                    if (_e744 < _e745) {
                    } else {
                        break;
                    }
                    let _e747 = local_434;
                    let _e750 = global_4.member[_e747];
                    if ((bitcast<u32>(bitcast<f32>(_e750)) & 2147483647u) > 2139095040u) {
                        phi_4754_ = array<f32, 3>(0f, 0f, 0f);
                    } else {
                        phi_4754_ = array<f32, 3>(_e740, _e741, bitcast<f32>(_e738));
                    }
                    let _e756 = phi_4754_;
                    local_435 = _e756;
                    let _e757 = local_428;
                    let _e758 = (3u * _e757);
                    local_436 = _e758;
                    local_437 = bitcast<u32>(_e756[0]);
                    let _e761 = local_6;
                    if (_e758 < _e761) {
                    } else {
                        break;
                    }
                    let _e763 = local_436;
                    let _e766 = local_437;
                    global_2.member[_e763] = _e766;
                    let _e767 = local_436;
                    let _e768 = (_e767 + 1u);
                    local_438 = _e768;
                    let _e769 = local_435;
                    local_439 = bitcast<u32>(_e769[1]);
                    let _e772 = local_6;
                    if (_e768 < _e772) {
                    } else {
                        break;
                    }
                    let _e774 = local_438;
                    let _e777 = local_439;
                    global_2.member[_e774] = _e777;
                    let _e778 = local_436;
                    let _e779 = (_e778 + 2u);
                    local_440 = _e779;
                    let _e780 = local_435;
                    local_441 = bitcast<u32>(_e780[2]);
                    let _e783 = local_6;
                    if (_e779 < _e783) {
                    } else {
                        break;
                    }
                    let _e785 = local_440;
                    let _e788 = local_441;
                    global_2.member[_e785] = _e788;
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
