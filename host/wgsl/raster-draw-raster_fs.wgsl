struct type_3 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_5 {
    member: array<u32>,
}

struct type_18 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
}

struct type_24 {
    member: array<f32, 4>,
    member_1: array<f32, 4>,
    member_2: array<f32, 4>,
    member_3: array<f32, 3>,
    member_4: f32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: array<u32, 3>,
}

struct type_25 {
    member: type_24,
}

@group(0) @binding(0) 
var<storage> global: type_5;
@group(0) @binding(1) 
var<storage> global_1: type_5;
var<private> global_2: vec4<f32>;
@group(0) @binding(2) 
var<storage> global_3: type_5;
@group(0) @binding(3) 
var<storage> global_4: type_5;
@group(0) @binding(4) 
var<storage> global_5: type_5;
@group(0) @binding(5) 
var<storage> global_6: type_5;
var<private> global_7: vec4<f32>;
var<immediate> global_8: type_25;
var<private> global_9: vec2<f32>;
var<private> global_10: f32;
var<private> global_11: u32;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: f32;
    var local_7: f32;
    var local_8: f32;
    var local_9: u32;
    var local_10: u32;
    var local_11: bool;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: array<u32, 4>;
    var local_24: f32;
    var local_25: u32;
    var local_26: array<f32, 4>;
    var local_27: bool;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: f32;
    var local_34: u32;
    var local_35: u32;
    var local_36: f32;
    var local_37: f32;
    var local_38: u32;
    var local_39: u32;
    var local_40: f32;
    var local_41: f32;
    var local_42: u32;
    var local_43: u32;
    var local_44: f32;
    var local_45: f32;
    var local_46: u32;
    var local_47: u32;
    var local_48: f32;
    var local_49: u32;
    var local_50: f32;
    var local_51: f32;
    var local_52: bool;
    var local_53: u32;
    var local_54: f32;
    var local_55: u32;
    var local_56: f32;
    var local_57: u32;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: f32;
    var local_62: u32;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: u32;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: u32;
    var local_72: u32;
    var local_73: bool;
    var local_74: f32;
    var local_75: u32;
    var local_76: bool;
    var local_77: u32;
    var local_78: type_3;
    var local_79: bool;
    var local_80: u32;
    var local_81: bool;
    var local_82: u32;
    var local_83: type_3;
    var local_84: bool;
    var local_85: type_18;
    var local_86: f32;
    var local_87: u32;
    var local_88: f32;
    var local_89: u32;
    var local_90: f32;
    var local_91: f32;
    var local_92: f32;
    var local_93: f32;
    var local_94: f32;
    var local_95: i32;
    var local_96: i32;
    var local_97: u32;
    var local_98: i32;
    var local_99: bool;
    var local_100: i32;
    var local_101: bool;
    var local_102: bool;
    var local_103: i32;
    var local_104: i32;
    var local_105: bool;
    var local_106: bool;
    var local_107: i32;
    var local_108: u32;
    var local_109: i32;
    var local_110: i32;
    var local_111: bool;
    var local_112: bool;
    var local_113: i32;
    var local_114: i32;
    var local_115: bool;
    var local_116: bool;
    var local_117: i32;
    var local_118: u32;
    var local_119: u32;
    var local_120: i32;
    var local_121: bool;
    var local_122: i32;
    var local_123: bool;
    var local_124: bool;
    var local_125: i32;
    var local_126: i32;
    var local_127: bool;
    var local_128: bool;
    var local_129: i32;
    var local_130: u32;
    var local_131: i32;
    var local_132: i32;
    var local_133: bool;
    var local_134: bool;
    var local_135: i32;
    var local_136: i32;
    var local_137: bool;
    var local_138: bool;
    var local_139: i32;
    var local_140: u32;
    var local_141: u32;
    var local_142: u32;
    var local_143: u32;
    var local_144: u32;
    var local_145: u32;
    var local_146: u32;
    var local_147: u32;
    var local_148: u32;
    var local_149: f32;
    var local_150: u32;
    var local_151: u32;
    var local_152: f32;
    var local_153: u32;
    var local_154: u32;
    var local_155: f32;
    var local_156: u32;
    var local_157: u32;
    var local_158: f32;
    var local_159: u32;
    var local_160: u32;
    var local_161: u32;
    var local_162: u32;
    var local_163: u32;
    var local_164: u32;
    var local_165: f32;
    var local_166: u32;
    var local_167: u32;
    var local_168: f32;
    var local_169: u32;
    var local_170: u32;
    var local_171: f32;
    var local_172: u32;
    var local_173: u32;
    var local_174: f32;
    var local_175: f32;
    var local_176: f32;
    var local_177: f32;
    var local_178: u32;
    var local_179: u32;
    var local_180: u32;
    var local_181: u32;
    var local_182: u32;
    var local_183: u32;
    var local_184: u32;
    var local_185: f32;
    var local_186: u32;
    var local_187: u32;
    var local_188: f32;
    var local_189: u32;
    var local_190: u32;
    var local_191: f32;
    var local_192: u32;
    var local_193: u32;
    var local_194: f32;
    var local_195: u32;
    var local_196: u32;
    var local_197: u32;
    var local_198: u32;
    var local_199: u32;
    var local_200: u32;
    var local_201: f32;
    var local_202: u32;
    var local_203: u32;
    var local_204: f32;
    var local_205: u32;
    var local_206: u32;
    var local_207: f32;
    var local_208: u32;
    var local_209: u32;
    var local_210: f32;
    var local_211: u32;
    var local_212: u32;
    var local_213: type_18;
    var local_214: bool;
    var local_215: u32;
    var local_216: u32;
    var local_217: type_18;
    var local_218: type_18;
    var local_219: u32;
    var local_220: type_18;
    var local_221: bool;
    var local_222: u32;
    var local_223: u32;
    var local_224: type_18;
    var local_225: type_18;
    var local_226: f32;
    var local_227: f32;
    var local_228: f32;
    var local_229: f32;
    var local_230: u32;
    var local_231: f32;
    var local_232: f32;
    var local_233: u32;
    var local_234: u32;
    var local_235: f32;
    var local_236: f32;
    var local_237: f32;
    var local_238: f32;
    var local_239: f32;
    var local_240: f32;
    var local_241: f32;
    var local_242: f32;
    var local_243: f32;
    var local_244: f32;
    var local_245: f32;
    var local_246: f32;
    var local_247: f32;
    var local_248: f32;
    var local_249: f32;
    var local_250: f32;
    var local_251: array<u32, 4>;
    var local_252: array<f32, 3>;
    var local_253: array<u32, 4>;
    var local_254: array<f32, 3>;
    var phi_228_: bool;
    var phi_290_: u32;
    var phi_293_: array<f32, 4>;
    var phi_360_: u32;
    var phi_363_: f32;
    var phi_403_: u32;
    var phi_406_: f32;
    var phi_446_: u32;
    var phi_449_: f32;
    var phi_489_: u32;
    var phi_492_: f32;
    var phi_291_: u32;
    var phi_294_: array<f32, 4>;
    var phi_2098_: bool;
    var phi_510_: u32;
    var phi_513_: f32;
    var phi_515_: f32;
    var phi_511_: u32;
    var phi_514_: f32;
    var phi_516_: f32;
    var phi_2114_: bool;
    var phi_665_: bool;
    var phi_851_: f32;
    var phi_2021_: u32;
    var phi_2022_: type_18;
    var phi_2039_: u32;
    var phi_2048_: u32;
    var phi_2053_: u32;
    var phi_2054_: type_18;
    var phi_2060_: u32;
    var phi_2061_: type_18;
    var phi_2078_: u32;
    var phi_2087_: u32;
    var phi_2092_: u32;
    var phi_2093_: type_18;
    var phi_2164_: bool;
    var phi_870_: u32;
    var phi_873_: type_3;
    var phi_2163_: bool;
    var phi_887_: u32;
    var phi_890_: type_3;
    var phi_916_: u32;
    var phi_919_: type_3;
    var phi_932_: type_18;
    var phi_933_: f32;
    var phi_953_: f32;
    var phi_954_: f32;
    var phi_1025_: i32;
    var phi_1049_: i32;
    var phi_989_: i32;
    var phi_990_: i32;
    var phi_1050_: i32;
    var phi_1105_: i32;
    var phi_1129_: i32;
    var phi_1069_: i32;
    var phi_1070_: i32;
    var phi_1130_: i32;
    var phi_1184_: i32;
    var phi_1208_: i32;
    var phi_1148_: i32;
    var phi_1149_: i32;
    var phi_1209_: i32;
    var phi_1264_: i32;
    var phi_1288_: i32;
    var phi_1228_: i32;
    var phi_1229_: i32;
    var phi_1289_: i32;
    var phi_1340_: u32;
    var phi_1343_: f32;
    var phi_1372_: u32;
    var phi_1375_: f32;
    var phi_1404_: u32;
    var phi_1407_: f32;
    var phi_1436_: u32;
    var phi_1439_: f32;
    var phi_1489_: u32;
    var phi_1492_: f32;
    var phi_1521_: u32;
    var phi_1524_: f32;
    var phi_1553_: u32;
    var phi_1556_: f32;
    var phi_1585_: u32;
    var phi_1588_: f32;
    var phi_1650_: u32;
    var phi_1653_: f32;
    var phi_1682_: u32;
    var phi_1685_: f32;
    var phi_1714_: u32;
    var phi_1717_: f32;
    var phi_1746_: u32;
    var phi_1749_: f32;
    var phi_1799_: u32;
    var phi_1802_: f32;
    var phi_1831_: u32;
    var phi_1834_: f32;
    var phi_1863_: u32;
    var phi_1866_: f32;
    var phi_1895_: u32;
    var phi_1898_: f32;
    var phi_917_: u32;
    var phi_920_: type_3;
    var phi_2117_: bool;
    var phi_2224_: bool;
    var phi_888_: u32;
    var phi_891_: type_3;
    var phi_2223_: bool;
    var phi_2226_: bool;
    var phi_871_: u32;
    var phi_874_: type_3;
    var phi_2225_: bool;
    var phi_1951_: type_3;
    var phi_1952_: type_3;
    var phi_1953_: bool;
    var phi_1957_: type_3;
    var phi_1958_: type_3;
    var phi_1959_: type_3;
    var phi_1960_: bool;
    var phi_1964_: type_3;
    var phi_1985_: bool;
    var phi_1986_: bool;
    var phi_1987_: bool;
    var phi_1989_: bool;
    var phi_1990_: bool;
    var local_255: type_18;
    var local_256: type_18;
    var local_257: type_3;
    var local_258: type_3;
    var local_259: type_3;

    switch bitcast<i32>(0u) {
        default: {
            let _e316 = global_7;
            local = arrayLength((&global.member));
            local_1 = arrayLength((&global_1.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_4.member));
            local_4 = arrayLength((&global_5.member));
            local_5 = arrayLength((&global_6.member));
            let _e330 = global_9[0u];
            local_6 = _e330;
            let _e332 = global_9[1u];
            local_7 = _e332;
            let _e333 = global_10;
            local_8 = _e333;
            let _e334 = global_11;
            local_9 = _e334;
            let _e343 = global_8.member.member_5;
            local_10 = ((select(select(u32(_e316.y), 0u, (_e316.y < 0f)), 4294967295u, (_e316.y > 4294967000f)) * _e343) + select(select(u32(_e316.x), 0u, (_e316.x < 0f)), 4294967295u, (_e316.x > 4294967000f)));
            let _e354 = global_8.member.member_4;
            if (_e333 >= _e354) {
                let _e358 = global_8.member.member_9;
                if (_e358 == 0u) {
                    phi_228_ = true;
                } else {
                    let _e360 = local_10;
                    let _e361 = local_5;
                    if (_e360 < _e361) {
                    } else {
                        break;
                    }
                    let _e363 = local_10;
                    let _e366 = global_6.member[_e363];
                    let _e368 = local_8;
                    phi_228_ = (_e368 > bitcast<f32>(_e366));
                }
                let _e371 = phi_228_;
                local_11 = _e371;
                if _e371 {
                    let _e372 = local_9;
                    let _e373 = (_e372 * 4u);
                    local_12 = _e373;
                    let _e374 = local_1;
                    if (_e373 < _e374) {
                    } else {
                        break;
                    }
                    let _e376 = local_12;
                    let _e379 = global_1.member[_e376];
                    local_13 = _e379;
                    let _e380 = local_12;
                    let _e381 = (_e380 + 1u);
                    local_14 = _e381;
                    let _e382 = local_1;
                    if (_e381 < _e382) {
                    } else {
                        break;
                    }
                    let _e384 = local_14;
                    let _e387 = global_1.member[_e384];
                    local_15 = _e387;
                    let _e388 = local_12;
                    let _e389 = (_e388 + 2u);
                    local_16 = _e389;
                    let _e390 = local_1;
                    if (_e389 < _e390) {
                    } else {
                        break;
                    }
                    let _e392 = local_16;
                    let _e395 = global_1.member[_e392];
                    local_17 = _e395;
                    let _e396 = local_12;
                    let _e397 = (_e396 + 3u);
                    local_18 = _e397;
                    let _e398 = local_1;
                    if (_e397 < _e398) {
                    } else {
                        break;
                    }
                    let _e400 = local_18;
                    let _e403 = global_1.member[_e400];
                    local_19 = _e403;
                    let _e404 = (_e403 * 16u);
                    local_20 = _e404;
                    let _e405 = (_e404 + 10u);
                    local_21 = _e405;
                    let _e406 = local_2;
                    if (_e405 < _e406) {
                    } else {
                        break;
                    }
                    let _e408 = local_21;
                    let _e411 = global_3.member[_e408];
                    local_22 = _e411;
                    if ((_e411 & 12u) == 0u) {
                        phi_1986_ = true;
                    } else {
                        let _e414 = local_13;
                        let _e415 = local_15;
                        let _e416 = local_17;
                        let _e417 = local_19;
                        let _e418 = array<u32, 4>(_e414, _e415, _e416, _e417);
                        local_23 = _e418;
                        local_253 = _e418;
                        let _e419 = local_6;
                        let _e421 = local_7;
                        let _e422 = ((1f - _e419) - _e421);
                        local_24 = _e422;
                        let _e424 = local_6;
                        local_254[0u] = _e424;
                        let _e426 = local_7;
                        local_254[1u] = _e426;
                        local_254[2u] = _e422;
                        phi_290_ = 0u;
                        phi_293_ = array<f32, 4>(0f, 0f, 0f, 0f);
                        loop {
                            let _e429 = phi_290_;
                            let _e431 = phi_293_;
                            local_25 = _e429;
                            local_26 = _e431;
                            let _e432 = local_25;
                            let _e433 = (_e432 < 3u);
                            local_27 = _e433;
                            if _e433 {
                                let _e434 = local_25;
                                if (_e434 < 4u) {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e436 = local_25;
                                let _e438 = local_253[_e436];
                                let _e439 = (_e438 * 10u);
                                local_28 = _e439;
                                let _e440 = (_e439 + 8u);
                                local_29 = _e440;
                                let _e441 = local;
                                if (_e440 < _e441) {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e443 = local_29;
                                let _e446 = global.member[_e443];
                                local_30 = _e446;
                                let _e447 = local_28;
                                let _e448 = (_e447 + 9u);
                                local_31 = _e448;
                                let _e449 = local;
                                if (_e448 < _e449) {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e451 = local_31;
                                let _e454 = global.member[_e451];
                                local_32 = _e454;
                                let _e455 = local_27;
                                if _e455 {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e456 = local_25;
                                let _e458 = local_254[_e456];
                                local_33 = _e458;
                                let _e459 = local_30;
                                let _e460 = (_e459 & 65535u);
                                local_226 = select(-1f, 1f, ((_e460 & 32768u) == 0u));
                                let _e466 = ((_e460 >> bitcast<u32>(10i)) & 31u);
                                local_34 = _e466;
                                local_35 = (_e460 & 1023u);
                                if (_e466 == 0u) {
                                    let _e488 = local_35;
                                    let _e490 = local_226;
                                    phi_363_ = ((_e490 * f32(_e488)) * 0.000000059604645f);
                                } else {
                                    let _e469 = local_34;
                                    if (_e469 == 31u) {
                                        let _e479 = local_35;
                                        phi_360_ = (2139095040u | (_e479 << bitcast<u32>(13i)));
                                    } else {
                                        let _e471 = local_34;
                                        let _e475 = local_35;
                                        phi_360_ = (((_e471 + 112u) << bitcast<u32>(23i)) | (_e475 << bitcast<u32>(13i)));
                                    }
                                    let _e484 = phi_360_;
                                    let _e486 = local_226;
                                    phi_363_ = (_e486 * bitcast<f32>(_e484));
                                }
                                let _e494 = phi_363_;
                                let _e495 = local_33;
                                let _e497 = local_26;
                                local_36 = (_e497[0] + (_e495 * _e494));
                                let _e500 = local_27;
                                if _e500 {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e501 = local_254[_e456];
                                local_37 = _e501;
                                let _e502 = local_30;
                                let _e504 = (_e502 >> bitcast<u32>(16i));
                                local_227 = select(-1f, 1f, ((_e504 & 32768u) == 0u));
                                let _e510 = ((_e504 >> bitcast<u32>(10i)) & 31u);
                                local_38 = _e510;
                                local_39 = (_e504 & 1023u);
                                if (_e510 == 0u) {
                                    let _e532 = local_39;
                                    let _e534 = local_227;
                                    phi_406_ = ((_e534 * f32(_e532)) * 0.000000059604645f);
                                } else {
                                    let _e513 = local_38;
                                    if (_e513 == 31u) {
                                        let _e523 = local_39;
                                        phi_403_ = (2139095040u | (_e523 << bitcast<u32>(13i)));
                                    } else {
                                        let _e515 = local_38;
                                        let _e519 = local_39;
                                        phi_403_ = (((_e515 + 112u) << bitcast<u32>(23i)) | (_e519 << bitcast<u32>(13i)));
                                    }
                                    let _e528 = phi_403_;
                                    let _e530 = local_227;
                                    phi_406_ = (_e530 * bitcast<f32>(_e528));
                                }
                                let _e538 = phi_406_;
                                let _e539 = local_37;
                                let _e541 = local_26;
                                local_40 = (_e541[1] + (_e539 * _e538));
                                let _e544 = local_27;
                                if _e544 {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e545 = local_254[_e456];
                                local_41 = _e545;
                                let _e546 = local_32;
                                let _e547 = (_e546 & 65535u);
                                local_228 = select(-1f, 1f, ((_e547 & 32768u) == 0u));
                                let _e553 = ((_e547 >> bitcast<u32>(10i)) & 31u);
                                local_42 = _e553;
                                local_43 = (_e547 & 1023u);
                                if (_e553 == 0u) {
                                    let _e575 = local_43;
                                    let _e577 = local_228;
                                    phi_449_ = ((_e577 * f32(_e575)) * 0.000000059604645f);
                                } else {
                                    let _e556 = local_42;
                                    if (_e556 == 31u) {
                                        let _e566 = local_43;
                                        phi_446_ = (2139095040u | (_e566 << bitcast<u32>(13i)));
                                    } else {
                                        let _e558 = local_42;
                                        let _e562 = local_43;
                                        phi_446_ = (((_e558 + 112u) << bitcast<u32>(23i)) | (_e562 << bitcast<u32>(13i)));
                                    }
                                    let _e571 = phi_446_;
                                    let _e573 = local_228;
                                    phi_449_ = (_e573 * bitcast<f32>(_e571));
                                }
                                let _e581 = phi_449_;
                                let _e582 = local_41;
                                let _e584 = local_26;
                                local_44 = (_e584[2] + (_e582 * _e581));
                                let _e587 = local_27;
                                if _e587 {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e588 = local_254[_e456];
                                local_45 = _e588;
                                let _e589 = local_32;
                                let _e591 = (_e589 >> bitcast<u32>(16i));
                                local_229 = select(-1f, 1f, ((_e591 & 32768u) == 0u));
                                let _e597 = ((_e591 >> bitcast<u32>(10i)) & 31u);
                                local_46 = _e597;
                                local_47 = (_e591 & 1023u);
                                if (_e597 == 0u) {
                                    let _e619 = local_47;
                                    let _e621 = local_229;
                                    phi_492_ = ((_e621 * f32(_e619)) * 0.000000059604645f);
                                } else {
                                    let _e600 = local_46;
                                    if (_e600 == 31u) {
                                        let _e610 = local_47;
                                        phi_489_ = (2139095040u | (_e610 << bitcast<u32>(13i)));
                                    } else {
                                        let _e602 = local_46;
                                        let _e606 = local_47;
                                        phi_489_ = (((_e602 + 112u) << bitcast<u32>(23i)) | (_e606 << bitcast<u32>(13i)));
                                    }
                                    let _e615 = phi_489_;
                                    let _e617 = local_229;
                                    phi_492_ = (_e617 * bitcast<f32>(_e615));
                                }
                                let _e625 = phi_492_;
                                let _e626 = local_45;
                                let _e628 = local_26;
                                let _e631 = local_36;
                                let _e632 = local_40;
                                let _e633 = local_44;
                                let _e635 = local_25;
                                phi_291_ = (_e635 + 1u);
                                phi_294_ = array<f32, 4>(_e631, _e632, _e633, (_e628[3] + (_e626 * _e625)));
                            } else {
                                phi_291_ = u32();
                                phi_294_ = array<f32, 4>();
                            }
                            let _e638 = phi_291_;
                            let _e640 = phi_294_;
                            continue;
                            continuing {
                                let _e641 = local_27;
                                phi_290_ = _e638;
                                phi_293_ = _e640;
                                phi_2098_ = false;
                                break if !(_e641);
                            }
                        }
                        let _e644 = phi_2098_;
                        if _e644 {
                            break;
                        }
                        let _e645 = local_26;
                        local_48 = _e645[3];
                        let _e647 = local_23;
                        local_251 = _e647;
                        let _e649 = local_6;
                        local_252[0u] = _e649;
                        let _e651 = local_7;
                        local_252[1u] = _e651;
                        let _e653 = local_24;
                        local_252[2u] = _e653;
                        phi_510_ = 0u;
                        phi_513_ = 0f;
                        phi_515_ = 0f;
                        loop {
                            let _e655 = phi_510_;
                            let _e657 = phi_513_;
                            let _e659 = phi_515_;
                            local_49 = _e655;
                            local_50 = _e657;
                            local_51 = _e659;
                            let _e660 = local_49;
                            let _e661 = (_e660 < 3u);
                            local_52 = _e661;
                            if _e661 {
                                let _e662 = local_49;
                                if (_e662 < 4u) {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e664 = local_49;
                                let _e666 = local_251[_e664];
                                local_53 = (_e666 * 10u);
                                let _e668 = local_52;
                                if _e668 {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e669 = local_49;
                                let _e671 = local_252[_e669];
                                local_54 = _e671;
                                let _e672 = local_53;
                                let _e673 = (_e672 + 3u);
                                local_55 = _e673;
                                let _e674 = local;
                                if (_e673 < _e674) {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e676 = local_55;
                                let _e679 = global.member[_e676];
                                let _e681 = local_54;
                                let _e683 = local_51;
                                let _e685 = local_52;
                                if _e685 {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e686 = local_252[_e669];
                                local_56 = _e686;
                                let _e687 = local_53;
                                let _e688 = (_e687 + 7u);
                                local_57 = _e688;
                                let _e689 = local;
                                if (_e688 < _e689) {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e691 = local_57;
                                let _e694 = global.member[_e691];
                                let _e696 = local_56;
                                let _e698 = local_50;
                                let _e700 = local_49;
                                phi_511_ = (_e700 + 1u);
                                phi_514_ = (_e698 + (_e696 * bitcast<f32>(_e694)));
                                phi_516_ = (_e683 + (_e681 * bitcast<f32>(_e679)));
                            } else {
                                phi_511_ = u32();
                                phi_514_ = f32();
                                phi_516_ = f32();
                            }
                            let _e703 = phi_511_;
                            let _e705 = phi_514_;
                            let _e707 = phi_516_;
                            continue;
                            continuing {
                                let _e708 = local_52;
                                phi_510_ = _e703;
                                phi_513_ = _e705;
                                phi_515_ = _e707;
                                phi_2114_ = _e644;
                                break if !(_e708);
                            }
                        }
                        let _e711 = phi_2114_;
                        if _e711 {
                            break;
                        }
                        let _e712 = local_20;
                        let _e713 = (_e712 + 8u);
                        local_58 = _e713;
                        let _e714 = local_2;
                        if (_e713 < _e714) {
                        } else {
                            break;
                        }
                        let _e716 = local_58;
                        let _e719 = global_3.member[_e716];
                        local_59 = _e719;
                        let _e720 = local_20;
                        let _e721 = (_e720 + 3u);
                        local_60 = _e721;
                        let _e722 = local_2;
                        if (_e721 < _e722) {
                        } else {
                            break;
                        }
                        let _e724 = local_60;
                        let _e727 = global_3.member[_e724];
                        local_61 = bitcast<f32>(_e727);
                        let _e731 = global_8.member.member_8;
                        local_62 = _e731;
                        let _e732 = local_59;
                        if (_e732 == 4294967295u) {
                            phi_1959_ = type_3();
                            phi_1960_ = true;
                        } else {
                            let _e734 = local_59;
                            let _e735 = local_62;
                            let _e736 = (_e734 >= _e735);
                            if _e736 {
                                phi_1958_ = type_3();
                            } else {
                                let _e737 = local_59;
                                let _e738 = (_e737 * 4u);
                                local_63 = _e738;
                                let _e739 = local_3;
                                if (_e738 < _e739) {
                                } else {
                                    break;
                                }
                                let _e741 = local_63;
                                let _e744 = global_4.member[_e741];
                                local_64 = _e744;
                                let _e745 = local_63;
                                let _e746 = (_e745 + 1u);
                                local_65 = _e746;
                                let _e747 = local_3;
                                if (_e746 < _e747) {
                                } else {
                                    break;
                                }
                                let _e749 = local_65;
                                let _e752 = global_4.member[_e749];
                                local_66 = _e752;
                                let _e753 = local_63;
                                let _e754 = (_e753 + 2u);
                                local_67 = _e754;
                                let _e755 = local_3;
                                if (_e754 < _e755) {
                                } else {
                                    break;
                                }
                                let _e757 = local_67;
                                let _e760 = global_4.member[_e757];
                                local_68 = _e760;
                                let _e761 = local_63;
                                let _e762 = (_e761 + 3u);
                                local_69 = _e762;
                                let _e763 = local_3;
                                if (_e762 < _e763) {
                                } else {
                                    break;
                                }
                                let _e765 = local_69;
                                let _e768 = global_4.member[_e765];
                                local_70 = _e768;
                                let _e769 = local_66;
                                if (_e769 == 0u) {
                                    phi_1952_ = type_3();
                                    phi_1953_ = true;
                                } else {
                                    let _e771 = local_68;
                                    let _e772 = (_e771 == 0u);
                                    if _e772 {
                                        phi_1951_ = type_3();
                                    } else {
                                        let _e773 = local_70;
                                        let _e776 = ((_e773 >> bitcast<u32>(8u)) & 31u);
                                        local_230 = select(_e776, 1u, (_e776 == 0u));
                                        let _e779 = local_70;
                                        let _e783 = local_70;
                                        let _e787 = local_64;
                                        let _e788 = local_66;
                                        let _e789 = local_68;
                                        let _e790 = type_18(_e787, _e788, _e789, ((_e779 >> bitcast<u32>(1u)) & 3u), ((_e783 >> bitcast<u32>(3u)) & 3u));
                                        let _e791 = local_66;
                                        let _e793 = local_51;
                                        if ((bitcast<u32>((_e793 * f32(_e791))) & 2139095040u) != 2139095040u) {
                                            let _e798 = local_68;
                                            let _e800 = local_50;
                                            phi_665_ = select(true, false, ((bitcast<u32>((_e800 * f32(_e798))) & 2139095040u) != 2139095040u));
                                        } else {
                                            phi_665_ = true;
                                        }
                                        let _e807 = phi_665_;
                                        let _e808 = local_50;
                                        local_231 = select(_e808, 0f, _e807);
                                        let _e810 = local_51;
                                        local_232 = select(_e810, 0f, _e807);
                                        if false {
                                        }
                                        let _e812 = local_230;
                                        let _e813 = (_e812 - 1u);
                                        local_71 = _e813;
                                        let _e814 = floor(0f);
                                        let _e819 = select(select(u32(_e814), 0u, (_e814 < 0f)), 4294967295u, (_e814 > 4294967000f));
                                        local_72 = _e819;
                                        let _e820 = (_e819 >= _e813);
                                        local_73 = _e820;
                                        if _e820 {
                                            phi_851_ = 0f;
                                        } else {
                                            let _e821 = local_72;
                                            phi_851_ = -(f32(_e821));
                                        }
                                        let _e825 = phi_851_;
                                        local_74 = _e825;
                                        let _e826 = local_73;
                                        let _e827 = local_71;
                                        let _e828 = local_72;
                                        local_233 = select(_e828, _e827, _e826);
                                        local_234 = select(1u, 2u, (_e825 > 0f));
                                        phi_2021_ = 0u;
                                        phi_2022_ = _e790;
                                        loop {
                                            let _e833 = phi_2021_;
                                            let _e835 = phi_2022_;
                                            local_212 = _e833;
                                            local_213 = _e835;
                                            local_255 = _e835;
                                            let _e836 = local_212;
                                            let _e837 = local_233;
                                            let _e838 = (_e836 < _e837);
                                            local_214 = _e838;
                                            if _e838 {
                                                let _e839 = local_213;
                                                local_215 = _e839.member_1;
                                                let _e841 = local_213;
                                                local_216 = _e841.member_2;
                                                let _e844 = local_213;
                                                let _e847 = local_213;
                                                local_217 = type_18((_e844.member + (_e839.member_1 * _e841.member_2)), _e847.member_1, _e847.member_2, _e847.member_3, _e847.member_4);
                                                if (_e839.member_1 > 1u) {
                                                    let _e855 = local_215;
                                                    phi_2039_ = (_e855 >> bitcast<u32>(1i));
                                                } else {
                                                    phi_2039_ = 1u;
                                                }
                                                let _e859 = phi_2039_;
                                                let _e860 = local_217;
                                                local_218 = type_18(_e860.member, _e859, _e860.member_2, _e860.member_3, _e860.member_4);
                                                let _e867 = local_216;
                                                if (_e867 > 1u) {
                                                    let _e869 = local_216;
                                                    phi_2048_ = (_e869 >> bitcast<u32>(1i));
                                                } else {
                                                    phi_2048_ = 1u;
                                                }
                                                let _e873 = phi_2048_;
                                                let _e874 = local_218;
                                                let _e881 = local_212;
                                                phi_2053_ = (_e881 + 1u);
                                                phi_2054_ = type_18(_e874.member, _e874.member_1, _e873, _e874.member_3, _e874.member_4);
                                            } else {
                                                phi_2053_ = u32();
                                                phi_2054_ = type_18();
                                            }
                                            let _e884 = phi_2053_;
                                            let _e886 = phi_2054_;
                                            continue;
                                            continuing {
                                                let _e887 = local_214;
                                                phi_2021_ = _e884;
                                                phi_2022_ = _e886;
                                                break if !(_e887);
                                            }
                                        }
                                        let _e889 = local_233;
                                        let _e890 = local_234;
                                        local_75 = ((_e889 + _e890) - 1u);
                                        phi_2060_ = 0u;
                                        phi_2061_ = _e790;
                                        loop {
                                            let _e894 = phi_2060_;
                                            let _e896 = phi_2061_;
                                            local_219 = _e894;
                                            local_220 = _e896;
                                            local_256 = _e896;
                                            let _e897 = local_219;
                                            let _e898 = local_75;
                                            let _e899 = (_e897 < _e898);
                                            local_221 = _e899;
                                            if _e899 {
                                                let _e900 = local_220;
                                                local_222 = _e900.member_1;
                                                let _e902 = local_220;
                                                local_223 = _e902.member_2;
                                                let _e905 = local_220;
                                                let _e908 = local_220;
                                                local_224 = type_18((_e905.member + (_e900.member_1 * _e902.member_2)), _e908.member_1, _e908.member_2, _e908.member_3, _e908.member_4);
                                                if (_e900.member_1 > 1u) {
                                                    let _e916 = local_222;
                                                    phi_2078_ = (_e916 >> bitcast<u32>(1i));
                                                } else {
                                                    phi_2078_ = 1u;
                                                }
                                                let _e920 = phi_2078_;
                                                let _e921 = local_224;
                                                local_225 = type_18(_e921.member, _e920, _e921.member_2, _e921.member_3, _e921.member_4);
                                                let _e928 = local_223;
                                                if (_e928 > 1u) {
                                                    let _e930 = local_223;
                                                    phi_2087_ = (_e930 >> bitcast<u32>(1i));
                                                } else {
                                                    phi_2087_ = 1u;
                                                }
                                                let _e934 = phi_2087_;
                                                let _e935 = local_225;
                                                let _e942 = local_219;
                                                phi_2092_ = (_e942 + 1u);
                                                phi_2093_ = type_18(_e935.member, _e935.member_1, _e934, _e935.member_3, _e935.member_4);
                                            } else {
                                                phi_2092_ = u32();
                                                phi_2093_ = type_18();
                                            }
                                            let _e945 = phi_2092_;
                                            let _e947 = phi_2093_;
                                            continue;
                                            continuing {
                                                let _e948 = local_221;
                                                phi_2060_ = _e945;
                                                phi_2061_ = _e947;
                                                break if !(_e948);
                                            }
                                        }
                                        let _e950 = local_70;
                                        local_76 = ((_e950 & 1u) != 0u);
                                        phi_2164_ = _e711;
                                        phi_870_ = 0u;
                                        phi_873_ = type_3(0f, 0f, 0f, 0f);
                                        loop {
                                            let _e954 = phi_2164_;
                                            let _e956 = phi_870_;
                                            let _e958 = phi_873_;
                                            local_77 = _e956;
                                            local_78 = _e958;
                                            local_259 = _e958;
                                            let _e959 = local_77;
                                            let _e960 = (_e959 < 1u);
                                            local_79 = _e960;
                                            if _e960 {
                                                phi_2163_ = _e954;
                                                phi_887_ = 0u;
                                                phi_890_ = _e958;
                                                loop {
                                                    let _e962 = phi_2163_;
                                                    let _e964 = phi_887_;
                                                    let _e966 = phi_890_;
                                                    local_80 = _e964;
                                                    local_258 = _e966;
                                                    let _e967 = local_80;
                                                    let _e968 = (_e967 < 1u);
                                                    local_81 = _e968;
                                                    if _e968 {
                                                        phi_916_ = 0u;
                                                        phi_919_ = _e966;
                                                        loop {
                                                            let _e970 = phi_916_;
                                                            let _e972 = phi_919_;
                                                            local_82 = _e970;
                                                            local_83 = _e972;
                                                            local_257 = _e972;
                                                            let _e973 = local_82;
                                                            let _e974 = local_234;
                                                            let _e975 = (_e973 < _e974);
                                                            local_84 = _e975;
                                                            if _e975 {
                                                                let _e976 = local_82;
                                                                if (_e976 == 0u) {
                                                                    let _e978 = local_74;
                                                                    let _e2225 = local_255;
                                                                    phi_932_ = _e2225;
                                                                    phi_933_ = (1f - _e978);
                                                                } else {
                                                                    let _e2227 = local_256;
                                                                    phi_932_ = _e2227;
                                                                    phi_933_ = _e825;
                                                                }
                                                                let _e981 = phi_932_;
                                                                let _e983 = phi_933_;
                                                                local_85 = _e981;
                                                                local_86 = _e983;
                                                                let _e984 = local_76;
                                                                let _e985 = select(0.5f, 0f, _e984);
                                                                local_87 = _e981.member_1;
                                                                let _e988 = local_232;
                                                                let _e990 = ((_e988 * f32(_e981.member_1)) - _e985);
                                                                local_88 = _e990;
                                                                local_89 = _e981.member_2;
                                                                let _e993 = local_231;
                                                                let _e995 = ((_e993 * f32(_e981.member_2)) - _e985);
                                                                local_90 = _e995;
                                                                local_91 = floor(_e990);
                                                                local_92 = floor(_e995);
                                                                let _e998 = local_76;
                                                                if _e998 {
                                                                    phi_953_ = 0f;
                                                                    phi_954_ = 0f;
                                                                } else {
                                                                    let _e999 = local_88;
                                                                    let _e1000 = local_91;
                                                                    let _e1002 = local_90;
                                                                    let _e1003 = local_92;
                                                                    phi_953_ = (_e1002 - _e1003);
                                                                    phi_954_ = (_e999 - _e1000);
                                                                }
                                                                let _e1006 = phi_953_;
                                                                let _e1008 = phi_954_;
                                                                local_93 = _e1006;
                                                                local_94 = _e1008;
                                                                let _e1009 = local_91;
                                                                let _e1011 = local_91;
                                                                let _e1013 = local_91;
                                                                let _e1017 = local_91;
                                                                let _e1018 = local_91;
                                                                let _e1020 = select(0i, select(select(i32(_e1009), i32(-2147483648), (_e1011 < -2147483600f)), 2147483647i, (_e1013 > 2147483500f)), (_e1017 == _e1018));
                                                                local_95 = _e1020;
                                                                let _e1021 = local_92;
                                                                let _e1023 = local_92;
                                                                let _e1025 = local_92;
                                                                let _e1029 = local_92;
                                                                let _e1030 = local_92;
                                                                let _e1032 = select(0i, select(select(i32(_e1021), i32(-2147483648), (_e1023 < -2147483600f)), 2147483647i, (_e1025 > 2147483500f)), (_e1029 == _e1030));
                                                                local_96 = _e1032;
                                                                let _e1033 = local_85;
                                                                local_97 = _e1033.member_3;
                                                                let _e1035 = local_87;
                                                                local_98 = bitcast<i32>(_e1035);
                                                                let _e1037 = (_e1033.member_3 == 1u);
                                                                local_99 = _e1037;
                                                                if _e1037 {
                                                                    let _e1091 = local_95;
                                                                    if (_e1091 < 0i) {
                                                                        phi_990_ = 0i;
                                                                    } else {
                                                                        let _e1093 = local_95;
                                                                        let _e1094 = local_98;
                                                                        if (_e1093 >= _e1094) {
                                                                            let _e1096 = local_98;
                                                                            phi_989_ = (_e1096 - 1i);
                                                                        } else {
                                                                            phi_989_ = _e1020;
                                                                        }
                                                                        let _e1099 = phi_989_;
                                                                        phi_990_ = _e1099;
                                                                    }
                                                                    let _e1101 = phi_990_;
                                                                    phi_1050_ = _e1101;
                                                                } else {
                                                                    let _e1038 = local_97;
                                                                    if (_e1038 == 2u) {
                                                                        let _e1060 = local_98;
                                                                        let _e1061 = (2i * _e1060);
                                                                        local_100 = _e1061;
                                                                        let _e1062 = (_e1061 == 0i);
                                                                        local_101 = _e1062;
                                                                        if _e1062 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1063 = local_100;
                                                                        let _e1064 = (_e1063 == -1i);
                                                                        local_102 = _e1064;
                                                                        let _e1065 = local_95;
                                                                        if (_e1064 && (_e1065 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1068 = local_95;
                                                                        let _e1069 = local_100;
                                                                        let _e1071 = local_100;
                                                                        local_103 = ((_e1068 % _e1069) + _e1071);
                                                                        let _e1073 = local_101;
                                                                        if _e1073 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1074 = local_103;
                                                                        let _e1076 = local_102;
                                                                        if (_e1076 && (_e1074 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1078 = local_103;
                                                                        let _e1079 = local_100;
                                                                        let _e1080 = (_e1078 % _e1079);
                                                                        local_104 = _e1080;
                                                                        let _e1081 = local_98;
                                                                        if (_e1080 < _e1081) {
                                                                            phi_1025_ = _e1080;
                                                                        } else {
                                                                            let _e1083 = local_100;
                                                                            let _e1085 = local_104;
                                                                            phi_1025_ = ((_e1083 - 1i) - _e1085);
                                                                        }
                                                                        let _e1088 = phi_1025_;
                                                                        phi_1049_ = _e1088;
                                                                    } else {
                                                                        let _e1040 = local_98;
                                                                        let _e1041 = (_e1040 == 0i);
                                                                        local_105 = _e1041;
                                                                        if _e1041 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1042 = local_98;
                                                                        let _e1043 = (_e1042 == -1i);
                                                                        local_106 = _e1043;
                                                                        let _e1044 = local_95;
                                                                        if (_e1043 && (_e1044 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1047 = local_95;
                                                                        let _e1048 = local_98;
                                                                        let _e1050 = local_98;
                                                                        local_107 = ((_e1047 % _e1048) + _e1050);
                                                                        let _e1052 = local_105;
                                                                        if _e1052 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1053 = local_107;
                                                                        let _e1055 = local_106;
                                                                        if (_e1055 && (_e1053 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1057 = local_107;
                                                                        let _e1058 = local_98;
                                                                        phi_1049_ = (_e1057 % _e1058);
                                                                    }
                                                                    let _e1090 = phi_1049_;
                                                                    phi_1050_ = _e1090;
                                                                }
                                                                let _e1103 = phi_1050_;
                                                                local_108 = bitcast<u32>(_e1103);
                                                                let _e1105 = local_95;
                                                                let _e1106 = (_e1105 + 1i);
                                                                local_109 = _e1106;
                                                                let _e1107 = local_99;
                                                                if _e1107 {
                                                                    let _e1161 = local_109;
                                                                    if (_e1161 < 0i) {
                                                                        phi_1070_ = 0i;
                                                                    } else {
                                                                        let _e1163 = local_109;
                                                                        let _e1164 = local_98;
                                                                        if (_e1163 >= _e1164) {
                                                                            let _e1166 = local_98;
                                                                            phi_1069_ = (_e1166 - 1i);
                                                                        } else {
                                                                            phi_1069_ = _e1106;
                                                                        }
                                                                        let _e1169 = phi_1069_;
                                                                        phi_1070_ = _e1169;
                                                                    }
                                                                    let _e1171 = phi_1070_;
                                                                    phi_1130_ = _e1171;
                                                                } else {
                                                                    let _e1108 = local_97;
                                                                    if (_e1108 == 2u) {
                                                                        let _e1130 = local_98;
                                                                        let _e1131 = (2i * _e1130);
                                                                        local_110 = _e1131;
                                                                        let _e1132 = (_e1131 == 0i);
                                                                        local_111 = _e1132;
                                                                        if _e1132 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1133 = local_110;
                                                                        let _e1134 = (_e1133 == -1i);
                                                                        local_112 = _e1134;
                                                                        let _e1135 = local_109;
                                                                        if (_e1134 && (_e1135 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1138 = local_109;
                                                                        let _e1139 = local_110;
                                                                        let _e1141 = local_110;
                                                                        local_113 = ((_e1138 % _e1139) + _e1141);
                                                                        let _e1143 = local_111;
                                                                        if _e1143 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1144 = local_113;
                                                                        let _e1146 = local_112;
                                                                        if (_e1146 && (_e1144 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1148 = local_113;
                                                                        let _e1149 = local_110;
                                                                        let _e1150 = (_e1148 % _e1149);
                                                                        local_114 = _e1150;
                                                                        let _e1151 = local_98;
                                                                        if (_e1150 < _e1151) {
                                                                            phi_1105_ = _e1150;
                                                                        } else {
                                                                            let _e1153 = local_110;
                                                                            let _e1155 = local_114;
                                                                            phi_1105_ = ((_e1153 - 1i) - _e1155);
                                                                        }
                                                                        let _e1158 = phi_1105_;
                                                                        phi_1129_ = _e1158;
                                                                    } else {
                                                                        let _e1110 = local_98;
                                                                        let _e1111 = (_e1110 == 0i);
                                                                        local_115 = _e1111;
                                                                        if _e1111 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1112 = local_98;
                                                                        let _e1113 = (_e1112 == -1i);
                                                                        local_116 = _e1113;
                                                                        let _e1114 = local_109;
                                                                        if (_e1113 && (_e1114 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1117 = local_109;
                                                                        let _e1118 = local_98;
                                                                        let _e1120 = local_98;
                                                                        local_117 = ((_e1117 % _e1118) + _e1120);
                                                                        let _e1122 = local_115;
                                                                        if _e1122 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1123 = local_117;
                                                                        let _e1125 = local_116;
                                                                        if (_e1125 && (_e1123 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1127 = local_117;
                                                                        let _e1128 = local_98;
                                                                        phi_1129_ = (_e1127 % _e1128);
                                                                    }
                                                                    let _e1160 = phi_1129_;
                                                                    phi_1130_ = _e1160;
                                                                }
                                                                let _e1173 = phi_1130_;
                                                                local_118 = bitcast<u32>(_e1173);
                                                                let _e1175 = local_85;
                                                                local_119 = _e1175.member_4;
                                                                let _e1177 = local_89;
                                                                local_120 = bitcast<i32>(_e1177);
                                                                let _e1179 = (_e1175.member_4 == 1u);
                                                                local_121 = _e1179;
                                                                if _e1179 {
                                                                    let _e1233 = local_96;
                                                                    if (_e1233 < 0i) {
                                                                        phi_1149_ = 0i;
                                                                    } else {
                                                                        let _e1235 = local_96;
                                                                        let _e1236 = local_120;
                                                                        if (_e1235 >= _e1236) {
                                                                            let _e1238 = local_120;
                                                                            phi_1148_ = (_e1238 - 1i);
                                                                        } else {
                                                                            phi_1148_ = _e1032;
                                                                        }
                                                                        let _e1241 = phi_1148_;
                                                                        phi_1149_ = _e1241;
                                                                    }
                                                                    let _e1243 = phi_1149_;
                                                                    phi_1209_ = _e1243;
                                                                } else {
                                                                    let _e1180 = local_119;
                                                                    if (_e1180 == 2u) {
                                                                        let _e1202 = local_120;
                                                                        let _e1203 = (2i * _e1202);
                                                                        local_122 = _e1203;
                                                                        let _e1204 = (_e1203 == 0i);
                                                                        local_123 = _e1204;
                                                                        if _e1204 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1205 = local_122;
                                                                        let _e1206 = (_e1205 == -1i);
                                                                        local_124 = _e1206;
                                                                        let _e1207 = local_96;
                                                                        if (_e1206 && (_e1207 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1210 = local_96;
                                                                        let _e1211 = local_122;
                                                                        let _e1213 = local_122;
                                                                        local_125 = ((_e1210 % _e1211) + _e1213);
                                                                        let _e1215 = local_123;
                                                                        if _e1215 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1216 = local_125;
                                                                        let _e1218 = local_124;
                                                                        if (_e1218 && (_e1216 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1220 = local_125;
                                                                        let _e1221 = local_122;
                                                                        let _e1222 = (_e1220 % _e1221);
                                                                        local_126 = _e1222;
                                                                        let _e1223 = local_120;
                                                                        if (_e1222 < _e1223) {
                                                                            phi_1184_ = _e1222;
                                                                        } else {
                                                                            let _e1225 = local_122;
                                                                            let _e1227 = local_126;
                                                                            phi_1184_ = ((_e1225 - 1i) - _e1227);
                                                                        }
                                                                        let _e1230 = phi_1184_;
                                                                        phi_1208_ = _e1230;
                                                                    } else {
                                                                        let _e1182 = local_120;
                                                                        let _e1183 = (_e1182 == 0i);
                                                                        local_127 = _e1183;
                                                                        if _e1183 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1184 = local_120;
                                                                        let _e1185 = (_e1184 == -1i);
                                                                        local_128 = _e1185;
                                                                        let _e1186 = local_96;
                                                                        if (_e1185 && (_e1186 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1189 = local_96;
                                                                        let _e1190 = local_120;
                                                                        let _e1192 = local_120;
                                                                        local_129 = ((_e1189 % _e1190) + _e1192);
                                                                        let _e1194 = local_127;
                                                                        if _e1194 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1195 = local_129;
                                                                        let _e1197 = local_128;
                                                                        if (_e1197 && (_e1195 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1199 = local_129;
                                                                        let _e1200 = local_120;
                                                                        phi_1208_ = (_e1199 % _e1200);
                                                                    }
                                                                    let _e1232 = phi_1208_;
                                                                    phi_1209_ = _e1232;
                                                                }
                                                                let _e1245 = phi_1209_;
                                                                local_130 = bitcast<u32>(_e1245);
                                                                let _e1247 = local_96;
                                                                let _e1248 = (_e1247 + 1i);
                                                                local_131 = _e1248;
                                                                let _e1249 = local_121;
                                                                if _e1249 {
                                                                    let _e1303 = local_131;
                                                                    if (_e1303 < 0i) {
                                                                        phi_1229_ = 0i;
                                                                    } else {
                                                                        let _e1305 = local_131;
                                                                        let _e1306 = local_120;
                                                                        if (_e1305 >= _e1306) {
                                                                            let _e1308 = local_120;
                                                                            phi_1228_ = (_e1308 - 1i);
                                                                        } else {
                                                                            phi_1228_ = _e1248;
                                                                        }
                                                                        let _e1311 = phi_1228_;
                                                                        phi_1229_ = _e1311;
                                                                    }
                                                                    let _e1313 = phi_1229_;
                                                                    phi_1289_ = _e1313;
                                                                } else {
                                                                    let _e1250 = local_119;
                                                                    if (_e1250 == 2u) {
                                                                        let _e1272 = local_120;
                                                                        let _e1273 = (2i * _e1272);
                                                                        local_132 = _e1273;
                                                                        let _e1274 = (_e1273 == 0i);
                                                                        local_133 = _e1274;
                                                                        if _e1274 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1275 = local_132;
                                                                        let _e1276 = (_e1275 == -1i);
                                                                        local_134 = _e1276;
                                                                        let _e1277 = local_131;
                                                                        if (_e1276 && (_e1277 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1280 = local_131;
                                                                        let _e1281 = local_132;
                                                                        let _e1283 = local_132;
                                                                        local_135 = ((_e1280 % _e1281) + _e1283);
                                                                        let _e1285 = local_133;
                                                                        if _e1285 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1286 = local_135;
                                                                        let _e1288 = local_134;
                                                                        if (_e1288 && (_e1286 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1290 = local_135;
                                                                        let _e1291 = local_132;
                                                                        let _e1292 = (_e1290 % _e1291);
                                                                        local_136 = _e1292;
                                                                        let _e1293 = local_120;
                                                                        if (_e1292 < _e1293) {
                                                                            phi_1264_ = _e1292;
                                                                        } else {
                                                                            let _e1295 = local_132;
                                                                            let _e1297 = local_136;
                                                                            phi_1264_ = ((_e1295 - 1i) - _e1297);
                                                                        }
                                                                        let _e1300 = phi_1264_;
                                                                        phi_1288_ = _e1300;
                                                                    } else {
                                                                        let _e1252 = local_120;
                                                                        let _e1253 = (_e1252 == 0i);
                                                                        local_137 = _e1253;
                                                                        if _e1253 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1254 = local_120;
                                                                        let _e1255 = (_e1254 == -1i);
                                                                        local_138 = _e1255;
                                                                        let _e1256 = local_131;
                                                                        if (_e1255 && (_e1256 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1259 = local_131;
                                                                        let _e1260 = local_120;
                                                                        let _e1262 = local_120;
                                                                        local_139 = ((_e1259 % _e1260) + _e1262);
                                                                        let _e1264 = local_137;
                                                                        if _e1264 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1265 = local_139;
                                                                        let _e1267 = local_138;
                                                                        if (_e1267 && (_e1265 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1269 = local_139;
                                                                        let _e1270 = local_120;
                                                                        phi_1288_ = (_e1269 % _e1270);
                                                                    }
                                                                    let _e1302 = phi_1288_;
                                                                    phi_1289_ = _e1302;
                                                                }
                                                                let _e1315 = phi_1289_;
                                                                local_140 = bitcast<u32>(_e1315);
                                                                let _e1317 = local_85;
                                                                local_141 = _e1317.member;
                                                                let _e1319 = local_130;
                                                                let _e1320 = local_87;
                                                                let _e1322 = (_e1317.member + (_e1319 * _e1320));
                                                                local_142 = _e1322;
                                                                let _e1323 = local_108;
                                                                let _e1325 = ((_e1322 + _e1323) * 2u);
                                                                local_143 = _e1325;
                                                                let _e1326 = local_4;
                                                                if (_e1325 < _e1326) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1328 = local_143;
                                                                let _e1331 = global_5.member[_e1328];
                                                                local_144 = _e1331;
                                                                let _e1332 = local_143;
                                                                let _e1333 = (_e1332 + 1u);
                                                                local_145 = _e1333;
                                                                let _e1334 = local_4;
                                                                if (_e1333 < _e1334) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1336 = local_145;
                                                                let _e1339 = global_5.member[_e1336];
                                                                local_146 = _e1339;
                                                                let _e1340 = local_144;
                                                                let _e1341 = (_e1340 & 65535u);
                                                                local_235 = select(-1f, 1f, ((_e1341 & 32768u) == 0u));
                                                                let _e1347 = ((_e1341 >> bitcast<u32>(10i)) & 31u);
                                                                local_147 = _e1347;
                                                                local_148 = (_e1341 & 1023u);
                                                                if (_e1347 == 0u) {
                                                                    let _e1369 = local_148;
                                                                    let _e1371 = local_235;
                                                                    phi_1343_ = ((_e1371 * f32(_e1369)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1350 = local_147;
                                                                    if (_e1350 == 31u) {
                                                                        let _e1360 = local_148;
                                                                        phi_1340_ = (2139095040u | (_e1360 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1352 = local_147;
                                                                        let _e1356 = local_148;
                                                                        phi_1340_ = (((_e1352 + 112u) << bitcast<u32>(23i)) | (_e1356 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1365 = phi_1340_;
                                                                    let _e1367 = local_235;
                                                                    phi_1343_ = (_e1367 * bitcast<f32>(_e1365));
                                                                }
                                                                let _e1375 = phi_1343_;
                                                                local_149 = _e1375;
                                                                let _e1376 = local_144;
                                                                let _e1378 = (_e1376 >> bitcast<u32>(16i));
                                                                local_236 = select(-1f, 1f, ((_e1378 & 32768u) == 0u));
                                                                let _e1384 = ((_e1378 >> bitcast<u32>(10i)) & 31u);
                                                                local_150 = _e1384;
                                                                local_151 = (_e1378 & 1023u);
                                                                if (_e1384 == 0u) {
                                                                    let _e1406 = local_151;
                                                                    let _e1408 = local_236;
                                                                    phi_1375_ = ((_e1408 * f32(_e1406)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1387 = local_150;
                                                                    if (_e1387 == 31u) {
                                                                        let _e1397 = local_151;
                                                                        phi_1372_ = (2139095040u | (_e1397 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1389 = local_150;
                                                                        let _e1393 = local_151;
                                                                        phi_1372_ = (((_e1389 + 112u) << bitcast<u32>(23i)) | (_e1393 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1402 = phi_1372_;
                                                                    let _e1404 = local_236;
                                                                    phi_1375_ = (_e1404 * bitcast<f32>(_e1402));
                                                                }
                                                                let _e1412 = phi_1375_;
                                                                local_152 = _e1412;
                                                                let _e1413 = local_146;
                                                                let _e1414 = (_e1413 & 65535u);
                                                                local_237 = select(-1f, 1f, ((_e1414 & 32768u) == 0u));
                                                                let _e1420 = ((_e1414 >> bitcast<u32>(10i)) & 31u);
                                                                local_153 = _e1420;
                                                                local_154 = (_e1414 & 1023u);
                                                                if (_e1420 == 0u) {
                                                                    let _e1442 = local_154;
                                                                    let _e1444 = local_237;
                                                                    phi_1407_ = ((_e1444 * f32(_e1442)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1423 = local_153;
                                                                    if (_e1423 == 31u) {
                                                                        let _e1433 = local_154;
                                                                        phi_1404_ = (2139095040u | (_e1433 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1425 = local_153;
                                                                        let _e1429 = local_154;
                                                                        phi_1404_ = (((_e1425 + 112u) << bitcast<u32>(23i)) | (_e1429 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1438 = phi_1404_;
                                                                    let _e1440 = local_237;
                                                                    phi_1407_ = (_e1440 * bitcast<f32>(_e1438));
                                                                }
                                                                let _e1448 = phi_1407_;
                                                                local_155 = _e1448;
                                                                let _e1449 = local_146;
                                                                let _e1451 = (_e1449 >> bitcast<u32>(16i));
                                                                local_238 = select(-1f, 1f, ((_e1451 & 32768u) == 0u));
                                                                let _e1457 = ((_e1451 >> bitcast<u32>(10i)) & 31u);
                                                                local_156 = _e1457;
                                                                local_157 = (_e1451 & 1023u);
                                                                if (_e1457 == 0u) {
                                                                    let _e1479 = local_157;
                                                                    let _e1481 = local_238;
                                                                    phi_1439_ = ((_e1481 * f32(_e1479)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1460 = local_156;
                                                                    if (_e1460 == 31u) {
                                                                        let _e1470 = local_157;
                                                                        phi_1436_ = (2139095040u | (_e1470 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1462 = local_156;
                                                                        let _e1466 = local_157;
                                                                        phi_1436_ = (((_e1462 + 112u) << bitcast<u32>(23i)) | (_e1466 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1475 = phi_1436_;
                                                                    let _e1477 = local_238;
                                                                    phi_1439_ = (_e1477 * bitcast<f32>(_e1475));
                                                                }
                                                                let _e1485 = phi_1439_;
                                                                local_158 = _e1485;
                                                                let _e1486 = local_142;
                                                                let _e1487 = local_118;
                                                                let _e1489 = ((_e1486 + _e1487) * 2u);
                                                                local_159 = _e1489;
                                                                let _e1490 = local_4;
                                                                if (_e1489 < _e1490) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1492 = local_159;
                                                                let _e1495 = global_5.member[_e1492];
                                                                local_160 = _e1495;
                                                                let _e1496 = local_159;
                                                                let _e1497 = (_e1496 + 1u);
                                                                local_161 = _e1497;
                                                                let _e1498 = local_4;
                                                                if (_e1497 < _e1498) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1500 = local_161;
                                                                let _e1503 = global_5.member[_e1500];
                                                                local_162 = _e1503;
                                                                let _e1504 = local_160;
                                                                let _e1505 = (_e1504 & 65535u);
                                                                local_239 = select(-1f, 1f, ((_e1505 & 32768u) == 0u));
                                                                let _e1511 = ((_e1505 >> bitcast<u32>(10i)) & 31u);
                                                                local_163 = _e1511;
                                                                local_164 = (_e1505 & 1023u);
                                                                if (_e1511 == 0u) {
                                                                    let _e1533 = local_164;
                                                                    let _e1535 = local_239;
                                                                    phi_1492_ = ((_e1535 * f32(_e1533)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1514 = local_163;
                                                                    if (_e1514 == 31u) {
                                                                        let _e1524 = local_164;
                                                                        phi_1489_ = (2139095040u | (_e1524 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1516 = local_163;
                                                                        let _e1520 = local_164;
                                                                        phi_1489_ = (((_e1516 + 112u) << bitcast<u32>(23i)) | (_e1520 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1529 = phi_1489_;
                                                                    let _e1531 = local_239;
                                                                    phi_1492_ = (_e1531 * bitcast<f32>(_e1529));
                                                                }
                                                                let _e1539 = phi_1492_;
                                                                local_165 = _e1539;
                                                                let _e1540 = local_160;
                                                                let _e1542 = (_e1540 >> bitcast<u32>(16i));
                                                                local_240 = select(-1f, 1f, ((_e1542 & 32768u) == 0u));
                                                                let _e1548 = ((_e1542 >> bitcast<u32>(10i)) & 31u);
                                                                local_166 = _e1548;
                                                                local_167 = (_e1542 & 1023u);
                                                                if (_e1548 == 0u) {
                                                                    let _e1570 = local_167;
                                                                    let _e1572 = local_240;
                                                                    phi_1524_ = ((_e1572 * f32(_e1570)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1551 = local_166;
                                                                    if (_e1551 == 31u) {
                                                                        let _e1561 = local_167;
                                                                        phi_1521_ = (2139095040u | (_e1561 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1553 = local_166;
                                                                        let _e1557 = local_167;
                                                                        phi_1521_ = (((_e1553 + 112u) << bitcast<u32>(23i)) | (_e1557 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1566 = phi_1521_;
                                                                    let _e1568 = local_240;
                                                                    phi_1524_ = (_e1568 * bitcast<f32>(_e1566));
                                                                }
                                                                let _e1576 = phi_1524_;
                                                                local_168 = _e1576;
                                                                let _e1577 = local_162;
                                                                let _e1578 = (_e1577 & 65535u);
                                                                local_241 = select(-1f, 1f, ((_e1578 & 32768u) == 0u));
                                                                let _e1584 = ((_e1578 >> bitcast<u32>(10i)) & 31u);
                                                                local_169 = _e1584;
                                                                local_170 = (_e1578 & 1023u);
                                                                if (_e1584 == 0u) {
                                                                    let _e1606 = local_170;
                                                                    let _e1608 = local_241;
                                                                    phi_1556_ = ((_e1608 * f32(_e1606)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1587 = local_169;
                                                                    if (_e1587 == 31u) {
                                                                        let _e1597 = local_170;
                                                                        phi_1553_ = (2139095040u | (_e1597 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1589 = local_169;
                                                                        let _e1593 = local_170;
                                                                        phi_1553_ = (((_e1589 + 112u) << bitcast<u32>(23i)) | (_e1593 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1602 = phi_1553_;
                                                                    let _e1604 = local_241;
                                                                    phi_1556_ = (_e1604 * bitcast<f32>(_e1602));
                                                                }
                                                                let _e1612 = phi_1556_;
                                                                local_171 = _e1612;
                                                                let _e1613 = local_162;
                                                                let _e1615 = (_e1613 >> bitcast<u32>(16i));
                                                                local_242 = select(-1f, 1f, ((_e1615 & 32768u) == 0u));
                                                                let _e1621 = ((_e1615 >> bitcast<u32>(10i)) & 31u);
                                                                local_172 = _e1621;
                                                                local_173 = (_e1615 & 1023u);
                                                                if (_e1621 == 0u) {
                                                                    let _e1643 = local_173;
                                                                    let _e1645 = local_242;
                                                                    phi_1588_ = ((_e1645 * f32(_e1643)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1624 = local_172;
                                                                    if (_e1624 == 31u) {
                                                                        let _e1634 = local_173;
                                                                        phi_1585_ = (2139095040u | (_e1634 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1626 = local_172;
                                                                        let _e1630 = local_173;
                                                                        phi_1585_ = (((_e1626 + 112u) << bitcast<u32>(23i)) | (_e1630 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1639 = phi_1585_;
                                                                    let _e1641 = local_242;
                                                                    phi_1588_ = (_e1641 * bitcast<f32>(_e1639));
                                                                }
                                                                let _e1649 = phi_1588_;
                                                                let _e1650 = local_165;
                                                                let _e1651 = local_149;
                                                                let _e1653 = local_94;
                                                                let _e1655 = local_149;
                                                                local_174 = (_e1655 + ((_e1650 - _e1651) * _e1653));
                                                                let _e1657 = local_168;
                                                                let _e1658 = local_152;
                                                                let _e1660 = local_94;
                                                                let _e1662 = local_152;
                                                                local_175 = (_e1662 + ((_e1657 - _e1658) * _e1660));
                                                                let _e1664 = local_171;
                                                                let _e1665 = local_155;
                                                                let _e1667 = local_94;
                                                                let _e1669 = local_155;
                                                                local_176 = (_e1669 + ((_e1664 - _e1665) * _e1667));
                                                                let _e1671 = local_158;
                                                                let _e1673 = local_94;
                                                                let _e1675 = local_158;
                                                                local_177 = (_e1675 + ((_e1649 - _e1671) * _e1673));
                                                                let _e1677 = local_140;
                                                                let _e1678 = local_87;
                                                                let _e1680 = local_141;
                                                                let _e1681 = (_e1680 + (_e1677 * _e1678));
                                                                local_178 = _e1681;
                                                                let _e1682 = local_108;
                                                                let _e1684 = ((_e1681 + _e1682) * 2u);
                                                                local_179 = _e1684;
                                                                let _e1685 = local_4;
                                                                if (_e1684 < _e1685) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1687 = local_179;
                                                                let _e1690 = global_5.member[_e1687];
                                                                local_180 = _e1690;
                                                                let _e1691 = local_179;
                                                                let _e1692 = (_e1691 + 1u);
                                                                local_181 = _e1692;
                                                                let _e1693 = local_4;
                                                                if (_e1692 < _e1693) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1695 = local_181;
                                                                let _e1698 = global_5.member[_e1695];
                                                                local_182 = _e1698;
                                                                let _e1699 = local_180;
                                                                let _e1700 = (_e1699 & 65535u);
                                                                local_243 = select(-1f, 1f, ((_e1700 & 32768u) == 0u));
                                                                let _e1706 = ((_e1700 >> bitcast<u32>(10i)) & 31u);
                                                                local_183 = _e1706;
                                                                local_184 = (_e1700 & 1023u);
                                                                if (_e1706 == 0u) {
                                                                    let _e1728 = local_184;
                                                                    let _e1730 = local_243;
                                                                    phi_1653_ = ((_e1730 * f32(_e1728)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1709 = local_183;
                                                                    if (_e1709 == 31u) {
                                                                        let _e1719 = local_184;
                                                                        phi_1650_ = (2139095040u | (_e1719 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1711 = local_183;
                                                                        let _e1715 = local_184;
                                                                        phi_1650_ = (((_e1711 + 112u) << bitcast<u32>(23i)) | (_e1715 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1724 = phi_1650_;
                                                                    let _e1726 = local_243;
                                                                    phi_1653_ = (_e1726 * bitcast<f32>(_e1724));
                                                                }
                                                                let _e1734 = phi_1653_;
                                                                local_185 = _e1734;
                                                                let _e1735 = local_180;
                                                                let _e1737 = (_e1735 >> bitcast<u32>(16i));
                                                                local_244 = select(-1f, 1f, ((_e1737 & 32768u) == 0u));
                                                                let _e1743 = ((_e1737 >> bitcast<u32>(10i)) & 31u);
                                                                local_186 = _e1743;
                                                                local_187 = (_e1737 & 1023u);
                                                                if (_e1743 == 0u) {
                                                                    let _e1765 = local_187;
                                                                    let _e1767 = local_244;
                                                                    phi_1685_ = ((_e1767 * f32(_e1765)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1746 = local_186;
                                                                    if (_e1746 == 31u) {
                                                                        let _e1756 = local_187;
                                                                        phi_1682_ = (2139095040u | (_e1756 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1748 = local_186;
                                                                        let _e1752 = local_187;
                                                                        phi_1682_ = (((_e1748 + 112u) << bitcast<u32>(23i)) | (_e1752 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1761 = phi_1682_;
                                                                    let _e1763 = local_244;
                                                                    phi_1685_ = (_e1763 * bitcast<f32>(_e1761));
                                                                }
                                                                let _e1771 = phi_1685_;
                                                                local_188 = _e1771;
                                                                let _e1772 = local_182;
                                                                let _e1773 = (_e1772 & 65535u);
                                                                local_245 = select(-1f, 1f, ((_e1773 & 32768u) == 0u));
                                                                let _e1779 = ((_e1773 >> bitcast<u32>(10i)) & 31u);
                                                                local_189 = _e1779;
                                                                local_190 = (_e1773 & 1023u);
                                                                if (_e1779 == 0u) {
                                                                    let _e1801 = local_190;
                                                                    let _e1803 = local_245;
                                                                    phi_1717_ = ((_e1803 * f32(_e1801)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1782 = local_189;
                                                                    if (_e1782 == 31u) {
                                                                        let _e1792 = local_190;
                                                                        phi_1714_ = (2139095040u | (_e1792 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1784 = local_189;
                                                                        let _e1788 = local_190;
                                                                        phi_1714_ = (((_e1784 + 112u) << bitcast<u32>(23i)) | (_e1788 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1797 = phi_1714_;
                                                                    let _e1799 = local_245;
                                                                    phi_1717_ = (_e1799 * bitcast<f32>(_e1797));
                                                                }
                                                                let _e1807 = phi_1717_;
                                                                local_191 = _e1807;
                                                                let _e1808 = local_182;
                                                                let _e1810 = (_e1808 >> bitcast<u32>(16i));
                                                                local_246 = select(-1f, 1f, ((_e1810 & 32768u) == 0u));
                                                                let _e1816 = ((_e1810 >> bitcast<u32>(10i)) & 31u);
                                                                local_192 = _e1816;
                                                                local_193 = (_e1810 & 1023u);
                                                                if (_e1816 == 0u) {
                                                                    let _e1838 = local_193;
                                                                    let _e1840 = local_246;
                                                                    phi_1749_ = ((_e1840 * f32(_e1838)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1819 = local_192;
                                                                    if (_e1819 == 31u) {
                                                                        let _e1829 = local_193;
                                                                        phi_1746_ = (2139095040u | (_e1829 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1821 = local_192;
                                                                        let _e1825 = local_193;
                                                                        phi_1746_ = (((_e1821 + 112u) << bitcast<u32>(23i)) | (_e1825 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1834 = phi_1746_;
                                                                    let _e1836 = local_246;
                                                                    phi_1749_ = (_e1836 * bitcast<f32>(_e1834));
                                                                }
                                                                let _e1844 = phi_1749_;
                                                                local_194 = _e1844;
                                                                let _e1845 = local_178;
                                                                let _e1846 = local_118;
                                                                let _e1848 = ((_e1845 + _e1846) * 2u);
                                                                local_195 = _e1848;
                                                                let _e1849 = local_4;
                                                                if (_e1848 < _e1849) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1851 = local_195;
                                                                let _e1854 = global_5.member[_e1851];
                                                                local_196 = _e1854;
                                                                let _e1855 = local_195;
                                                                let _e1856 = (_e1855 + 1u);
                                                                local_197 = _e1856;
                                                                let _e1857 = local_4;
                                                                if (_e1856 < _e1857) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1859 = local_197;
                                                                let _e1862 = global_5.member[_e1859];
                                                                local_198 = _e1862;
                                                                let _e1863 = local_196;
                                                                let _e1864 = (_e1863 & 65535u);
                                                                local_247 = select(-1f, 1f, ((_e1864 & 32768u) == 0u));
                                                                let _e1870 = ((_e1864 >> bitcast<u32>(10i)) & 31u);
                                                                local_199 = _e1870;
                                                                local_200 = (_e1864 & 1023u);
                                                                if (_e1870 == 0u) {
                                                                    let _e1892 = local_200;
                                                                    let _e1894 = local_247;
                                                                    phi_1802_ = ((_e1894 * f32(_e1892)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1873 = local_199;
                                                                    if (_e1873 == 31u) {
                                                                        let _e1883 = local_200;
                                                                        phi_1799_ = (2139095040u | (_e1883 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1875 = local_199;
                                                                        let _e1879 = local_200;
                                                                        phi_1799_ = (((_e1875 + 112u) << bitcast<u32>(23i)) | (_e1879 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1888 = phi_1799_;
                                                                    let _e1890 = local_247;
                                                                    phi_1802_ = (_e1890 * bitcast<f32>(_e1888));
                                                                }
                                                                let _e1898 = phi_1802_;
                                                                local_201 = _e1898;
                                                                let _e1899 = local_196;
                                                                let _e1901 = (_e1899 >> bitcast<u32>(16i));
                                                                local_248 = select(-1f, 1f, ((_e1901 & 32768u) == 0u));
                                                                let _e1907 = ((_e1901 >> bitcast<u32>(10i)) & 31u);
                                                                local_202 = _e1907;
                                                                local_203 = (_e1901 & 1023u);
                                                                if (_e1907 == 0u) {
                                                                    let _e1929 = local_203;
                                                                    let _e1931 = local_248;
                                                                    phi_1834_ = ((_e1931 * f32(_e1929)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1910 = local_202;
                                                                    if (_e1910 == 31u) {
                                                                        let _e1920 = local_203;
                                                                        phi_1831_ = (2139095040u | (_e1920 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1912 = local_202;
                                                                        let _e1916 = local_203;
                                                                        phi_1831_ = (((_e1912 + 112u) << bitcast<u32>(23i)) | (_e1916 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1925 = phi_1831_;
                                                                    let _e1927 = local_248;
                                                                    phi_1834_ = (_e1927 * bitcast<f32>(_e1925));
                                                                }
                                                                let _e1935 = phi_1834_;
                                                                local_204 = _e1935;
                                                                let _e1936 = local_198;
                                                                let _e1937 = (_e1936 & 65535u);
                                                                local_249 = select(-1f, 1f, ((_e1937 & 32768u) == 0u));
                                                                let _e1943 = ((_e1937 >> bitcast<u32>(10i)) & 31u);
                                                                local_205 = _e1943;
                                                                local_206 = (_e1937 & 1023u);
                                                                if (_e1943 == 0u) {
                                                                    let _e1965 = local_206;
                                                                    let _e1967 = local_249;
                                                                    phi_1866_ = ((_e1967 * f32(_e1965)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1946 = local_205;
                                                                    if (_e1946 == 31u) {
                                                                        let _e1956 = local_206;
                                                                        phi_1863_ = (2139095040u | (_e1956 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1948 = local_205;
                                                                        let _e1952 = local_206;
                                                                        phi_1863_ = (((_e1948 + 112u) << bitcast<u32>(23i)) | (_e1952 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1961 = phi_1863_;
                                                                    let _e1963 = local_249;
                                                                    phi_1866_ = (_e1963 * bitcast<f32>(_e1961));
                                                                }
                                                                let _e1971 = phi_1866_;
                                                                local_207 = _e1971;
                                                                let _e1972 = local_198;
                                                                let _e1974 = (_e1972 >> bitcast<u32>(16i));
                                                                local_250 = select(-1f, 1f, ((_e1974 & 32768u) == 0u));
                                                                let _e1980 = ((_e1974 >> bitcast<u32>(10i)) & 31u);
                                                                local_208 = _e1980;
                                                                local_209 = (_e1974 & 1023u);
                                                                if (_e1980 == 0u) {
                                                                    let _e2002 = local_209;
                                                                    let _e2004 = local_250;
                                                                    phi_1898_ = ((_e2004 * f32(_e2002)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1983 = local_208;
                                                                    if (_e1983 == 31u) {
                                                                        let _e1993 = local_209;
                                                                        phi_1895_ = (2139095040u | (_e1993 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1985 = local_208;
                                                                        let _e1989 = local_209;
                                                                        phi_1895_ = (((_e1985 + 112u) << bitcast<u32>(23i)) | (_e1989 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1998 = phi_1895_;
                                                                    let _e2000 = local_250;
                                                                    phi_1898_ = (_e2000 * bitcast<f32>(_e1998));
                                                                }
                                                                let _e2008 = phi_1898_;
                                                                let _e2009 = local_201;
                                                                let _e2010 = local_185;
                                                                let _e2012 = local_94;
                                                                let _e2014 = local_185;
                                                                let _e2016 = local_204;
                                                                let _e2017 = local_188;
                                                                let _e2019 = local_94;
                                                                let _e2021 = local_188;
                                                                let _e2023 = local_207;
                                                                let _e2024 = local_191;
                                                                let _e2026 = local_94;
                                                                let _e2028 = local_191;
                                                                let _e2030 = local_194;
                                                                let _e2032 = local_94;
                                                                let _e2034 = local_194;
                                                                let _e2036 = local_174;
                                                                let _e2038 = local_93;
                                                                let _e2040 = local_174;
                                                                let _e2042 = local_175;
                                                                let _e2044 = local_93;
                                                                let _e2046 = local_175;
                                                                let _e2048 = local_176;
                                                                let _e2050 = local_93;
                                                                let _e2052 = local_176;
                                                                let _e2054 = local_177;
                                                                let _e2056 = local_93;
                                                                let _e2058 = local_177;
                                                                let _e2060 = local_86;
                                                                let _e2062 = local_86;
                                                                let _e2064 = local_86;
                                                                let _e2066 = local_86;
                                                                let _e2068 = local_83;
                                                                let _e2071 = local_83;
                                                                let _e2074 = local_83;
                                                                let _e2077 = local_83;
                                                                let _e2081 = local_82;
                                                                phi_917_ = (_e2081 + 1u);
                                                                phi_920_ = type_3((_e2068.member + ((_e2040 + (((_e2014 + ((_e2009 - _e2010) * _e2012)) - _e2036) * _e2038)) * _e2060)), (_e2071.member_1 + ((_e2046 + (((_e2021 + ((_e2016 - _e2017) * _e2019)) - _e2042) * _e2044)) * _e2062)), (_e2074.member_2 + ((_e2052 + (((_e2028 + ((_e2023 - _e2024) * _e2026)) - _e2048) * _e2050)) * _e2064)), (_e2077.member_3 + ((_e2058 + (((_e2034 + ((_e2008 - _e2030) * _e2032)) - _e2054) * _e2056)) * _e2066)));
                                                            } else {
                                                                phi_917_ = u32();
                                                                phi_920_ = type_3();
                                                            }
                                                            let _e2084 = phi_917_;
                                                            let _e2086 = phi_920_;
                                                            continue;
                                                            continuing {
                                                                let _e2087 = local_84;
                                                                phi_916_ = _e2084;
                                                                phi_919_ = _e2086;
                                                                phi_2117_ = _e962;
                                                                break if !(_e2087);
                                                            }
                                                        }
                                                        let _e2090 = phi_2117_;
                                                        phi_2223_ = _e2090;
                                                        if _e2090 {
                                                            break;
                                                        }
                                                        let _e2091 = local_80;
                                                        phi_2224_ = _e2090;
                                                        phi_888_ = (_e2091 + 1u);
                                                        let _e2290 = local_257;
                                                        phi_891_ = _e2290;
                                                    } else {
                                                        phi_2224_ = _e962;
                                                        phi_888_ = u32();
                                                        phi_891_ = type_3();
                                                    }
                                                    let _e2094 = phi_2224_;
                                                    let _e2096 = phi_888_;
                                                    let _e2098 = phi_891_;
                                                    continue;
                                                    continuing {
                                                        let _e2099 = local_81;
                                                        phi_2163_ = _e2094;
                                                        phi_887_ = _e2096;
                                                        phi_890_ = _e2098;
                                                        phi_2223_ = _e2094;
                                                        break if !(_e2099);
                                                    }
                                                }
                                                let _e2102 = phi_2223_;
                                                phi_2225_ = _e2102;
                                                if _e2102 {
                                                    break;
                                                }
                                                let _e2103 = local_77;
                                                phi_2226_ = _e2102;
                                                phi_871_ = (_e2103 + 1u);
                                                let _e2296 = local_258;
                                                phi_874_ = _e2296;
                                            } else {
                                                phi_2226_ = _e954;
                                                phi_871_ = u32();
                                                phi_874_ = type_3();
                                            }
                                            let _e2106 = phi_2226_;
                                            let _e2108 = phi_871_;
                                            let _e2110 = phi_874_;
                                            continue;
                                            continuing {
                                                let _e2111 = local_79;
                                                phi_2164_ = _e2106;
                                                phi_870_ = _e2108;
                                                phi_873_ = _e2110;
                                                phi_2225_ = _e2106;
                                                break if !(_e2111);
                                            }
                                        }
                                        let _e2114 = phi_2225_;
                                        if _e2114 {
                                            break;
                                        }
                                        let _e2115 = local_78;
                                        let _e2117 = local_78;
                                        let _e2119 = local_78;
                                        let _e2121 = local_78;
                                        let _e2300 = local_259;
                                        phi_1951_ = _e2300;
                                    }
                                    let _e2124 = phi_1951_;
                                    phi_1952_ = _e2124;
                                    phi_1953_ = _e772;
                                }
                                let _e2126 = phi_1952_;
                                let _e2128 = phi_1953_;
                                if _e2128 {
                                    phi_1957_ = type_3(1f, 1f, 1f, 1f);
                                } else {
                                    phi_1957_ = _e2126;
                                }
                                let _e2130 = phi_1957_;
                                phi_1958_ = _e2130;
                            }
                            let _e2132 = phi_1958_;
                            phi_1959_ = _e2132;
                            phi_1960_ = _e736;
                        }
                        let _e2134 = phi_1959_;
                        let _e2136 = phi_1960_;
                        if _e2136 {
                            phi_1964_ = type_3(1f, 1f, 1f, 1f);
                        } else {
                            phi_1964_ = _e2134;
                        }
                        let _e2138 = phi_1964_;
                        let _e2140 = local_61;
                        let _e2142 = local_48;
                        local_210 = ((_e2140 * _e2138.member_3) * _e2142);
                        let _e2144 = local_22;
                        if ((_e2144 & 4u) == 0u) {
                            let _e2158 = local_210;
                            phi_1985_ = (_e2158 > 0f);
                        } else {
                            let _e2147 = local_20;
                            let _e2148 = (_e2147 + 7u);
                            local_211 = _e2148;
                            let _e2149 = local_2;
                            if (_e2148 < _e2149) {
                            } else {
                                break;
                            }
                            let _e2151 = local_211;
                            let _e2154 = global_3.member[_e2151];
                            let _e2156 = local_210;
                            phi_1985_ = (_e2156 >= bitcast<f32>(_e2154));
                        }
                        let _e2161 = phi_1985_;
                        phi_1986_ = _e2161;
                    }
                    let _e2163 = phi_1986_;
                    phi_1987_ = _e2163;
                } else {
                    phi_1987_ = bool();
                }
                let _e2165 = phi_1987_;
                let _e2166 = local_11;
                phi_1989_ = _e2165;
                phi_1990_ = select(true, false, _e2166);
            } else {
                phi_1989_ = bool();
                phi_1990_ = true;
            }
            let _e2169 = phi_1989_;
            let _e2171 = phi_1990_;
            if select(_e2169, false, _e2171) {
            } else {
                discard;
            }
            let _e2173 = local_9;
            let _e2176 = local_8;
            let _e2177 = local_6;
            let _e2178 = local_7;
            global_2 = vec4<f32>(f32((_e2173 + 1u)), _e2176, _e2177, _e2178);
            break;
        }
    }
    return;
}

@fragment 
fn raster_fs(@builtin(position) param: vec4<f32>, @location(0) param_1: vec2<f32>, @location(1) param_2: f32, @location(2) @interpolate(flat) param_3: u32) -> @location(0) vec4<f32> {
    global_7 = param;
    global_9 = param_1;
    global_10 = param_2;
    global_11 = param_3;
    function_();
    let _e9 = global_2;
    return _e9;
}
