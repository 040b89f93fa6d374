struct type_3 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_5 {
    member: array<u32>,
}

struct type_19 {
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
    var local_85: type_19;
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
    var local_213: type_19;
    var local_214: bool;
    var local_215: u32;
    var local_216: u32;
    var local_217: type_19;
    var local_218: type_19;
    var local_219: u32;
    var local_220: type_19;
    var local_221: bool;
    var local_222: u32;
    var local_223: u32;
    var local_224: type_19;
    var local_225: type_19;
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
    var phi_2022_: type_19;
    var phi_2039_: u32;
    var phi_2048_: u32;
    var phi_2053_: u32;
    var phi_2054_: type_19;
    var phi_2060_: u32;
    var phi_2061_: type_19;
    var phi_2078_: u32;
    var phi_2087_: u32;
    var phi_2092_: u32;
    var phi_2093_: type_19;
    var phi_2164_: bool;
    var phi_870_: u32;
    var phi_873_: type_3;
    var phi_2163_: bool;
    var phi_887_: u32;
    var phi_890_: type_3;
    var phi_916_: u32;
    var phi_919_: type_3;
    var phi_932_: type_19;
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
    var local_255: type_19;
    var local_256: type_19;
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
            let _e344 = global_8.member.member_5;
            local_10 = ((select(select(u32(_e316.y), 0u, !((_e316.y >= 0f))), 4294967295u, (_e316.y > 4294967000f)) * _e344) + select(select(u32(_e316.x), 0u, !((_e316.x >= 0f))), 4294967295u, (_e316.x > 4294967000f)));
            let _e356 = global_8.member.member_4;
            if (_e333 >= _e356) {
                let _e360 = global_8.member.member_9;
                if (_e360 == 0u) {
                    phi_228_ = true;
                } else {
                    let _e362 = local_10;
                    let _e363 = local_5;
                    if (_e362 < _e363) {
                    } else {
                        break;
                    }
                    let _e365 = local_10;
                    let _e368 = global_6.member[_e365];
                    let _e370 = local_8;
                    phi_228_ = (_e370 > bitcast<f32>(_e368));
                }
                let _e373 = phi_228_;
                local_11 = _e373;
                if _e373 {
                    let _e374 = local_9;
                    let _e375 = (_e374 * 4u);
                    local_12 = _e375;
                    let _e376 = local_1;
                    if (_e375 < _e376) {
                    } else {
                        break;
                    }
                    let _e378 = local_12;
                    let _e381 = global_1.member[_e378];
                    local_13 = _e381;
                    let _e382 = local_12;
                    let _e383 = (_e382 + 1u);
                    local_14 = _e383;
                    let _e384 = local_1;
                    if (_e383 < _e384) {
                    } else {
                        break;
                    }
                    let _e386 = local_14;
                    let _e389 = global_1.member[_e386];
                    local_15 = _e389;
                    let _e390 = local_12;
                    let _e391 = (_e390 + 2u);
                    local_16 = _e391;
                    let _e392 = local_1;
                    if (_e391 < _e392) {
                    } else {
                        break;
                    }
                    let _e394 = local_16;
                    let _e397 = global_1.member[_e394];
                    local_17 = _e397;
                    let _e398 = local_12;
                    let _e399 = (_e398 + 3u);
                    local_18 = _e399;
                    let _e400 = local_1;
                    if (_e399 < _e400) {
                    } else {
                        break;
                    }
                    let _e402 = local_18;
                    let _e405 = global_1.member[_e402];
                    local_19 = _e405;
                    let _e406 = (_e405 * 16u);
                    local_20 = _e406;
                    let _e407 = (_e406 + 10u);
                    local_21 = _e407;
                    let _e408 = local_2;
                    if (_e407 < _e408) {
                    } else {
                        break;
                    }
                    let _e410 = local_21;
                    let _e413 = global_3.member[_e410];
                    local_22 = _e413;
                    if ((_e413 & 12u) == 0u) {
                        phi_1986_ = true;
                    } else {
                        let _e416 = local_13;
                        let _e417 = local_15;
                        let _e418 = local_17;
                        let _e419 = local_19;
                        let _e420 = array<u32, 4>(_e416, _e417, _e418, _e419);
                        local_23 = _e420;
                        local_253 = _e420;
                        let _e421 = local_6;
                        let _e423 = local_7;
                        let _e424 = ((1f - _e421) - _e423);
                        local_24 = _e424;
                        let _e426 = local_6;
                        local_254[0u] = _e426;
                        let _e428 = local_7;
                        local_254[1u] = _e428;
                        local_254[2u] = _e424;
                        phi_290_ = 0u;
                        phi_293_ = array<f32, 4>(0f, 0f, 0f, 0f);
                        loop {
                            let _e431 = phi_290_;
                            let _e433 = phi_293_;
                            local_25 = _e431;
                            local_26 = _e433;
                            let _e434 = local_25;
                            let _e435 = (_e434 < 3u);
                            local_27 = _e435;
                            if _e435 {
                                let _e436 = local_25;
                                if (_e436 < 4u) {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e438 = local_25;
                                let _e440 = local_253[_e438];
                                let _e441 = (_e440 * 10u);
                                local_28 = _e441;
                                let _e442 = (_e441 + 8u);
                                local_29 = _e442;
                                let _e443 = local;
                                if (_e442 < _e443) {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e445 = local_29;
                                let _e448 = global.member[_e445];
                                local_30 = _e448;
                                let _e449 = local_28;
                                let _e450 = (_e449 + 9u);
                                local_31 = _e450;
                                let _e451 = local;
                                if (_e450 < _e451) {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e453 = local_31;
                                let _e456 = global.member[_e453];
                                local_32 = _e456;
                                let _e457 = local_27;
                                if _e457 {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e458 = local_25;
                                let _e460 = local_254[_e458];
                                local_33 = _e460;
                                let _e461 = local_30;
                                let _e462 = (_e461 & 65535u);
                                local_226 = select(-1f, 1f, ((_e462 & 32768u) == 0u));
                                let _e468 = ((_e462 >> bitcast<u32>(10i)) & 31u);
                                local_34 = _e468;
                                local_35 = (_e462 & 1023u);
                                if (_e468 == 0u) {
                                    let _e490 = local_35;
                                    let _e492 = local_226;
                                    phi_363_ = ((_e492 * f32(_e490)) * 0.000000059604645f);
                                } else {
                                    let _e471 = local_34;
                                    if (_e471 == 31u) {
                                        let _e481 = local_35;
                                        phi_360_ = (2139095040u | (_e481 << bitcast<u32>(13i)));
                                    } else {
                                        let _e473 = local_34;
                                        let _e477 = local_35;
                                        phi_360_ = (((_e473 + 112u) << bitcast<u32>(23i)) | (_e477 << bitcast<u32>(13i)));
                                    }
                                    let _e486 = phi_360_;
                                    let _e488 = local_226;
                                    phi_363_ = (_e488 * bitcast<f32>(_e486));
                                }
                                let _e496 = phi_363_;
                                let _e497 = local_33;
                                let _e499 = local_26;
                                local_36 = (_e499[0] + (_e497 * _e496));
                                let _e502 = local_27;
                                if _e502 {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e503 = local_254[_e458];
                                local_37 = _e503;
                                let _e504 = local_30;
                                let _e506 = (_e504 >> bitcast<u32>(16i));
                                local_227 = select(-1f, 1f, ((_e506 & 32768u) == 0u));
                                let _e512 = ((_e506 >> bitcast<u32>(10i)) & 31u);
                                local_38 = _e512;
                                local_39 = (_e506 & 1023u);
                                if (_e512 == 0u) {
                                    let _e534 = local_39;
                                    let _e536 = local_227;
                                    phi_406_ = ((_e536 * f32(_e534)) * 0.000000059604645f);
                                } else {
                                    let _e515 = local_38;
                                    if (_e515 == 31u) {
                                        let _e525 = local_39;
                                        phi_403_ = (2139095040u | (_e525 << bitcast<u32>(13i)));
                                    } else {
                                        let _e517 = local_38;
                                        let _e521 = local_39;
                                        phi_403_ = (((_e517 + 112u) << bitcast<u32>(23i)) | (_e521 << bitcast<u32>(13i)));
                                    }
                                    let _e530 = phi_403_;
                                    let _e532 = local_227;
                                    phi_406_ = (_e532 * bitcast<f32>(_e530));
                                }
                                let _e540 = phi_406_;
                                let _e541 = local_37;
                                let _e543 = local_26;
                                local_40 = (_e543[1] + (_e541 * _e540));
                                let _e546 = local_27;
                                if _e546 {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e547 = local_254[_e458];
                                local_41 = _e547;
                                let _e548 = local_32;
                                let _e549 = (_e548 & 65535u);
                                local_228 = select(-1f, 1f, ((_e549 & 32768u) == 0u));
                                let _e555 = ((_e549 >> bitcast<u32>(10i)) & 31u);
                                local_42 = _e555;
                                local_43 = (_e549 & 1023u);
                                if (_e555 == 0u) {
                                    let _e577 = local_43;
                                    let _e579 = local_228;
                                    phi_449_ = ((_e579 * f32(_e577)) * 0.000000059604645f);
                                } else {
                                    let _e558 = local_42;
                                    if (_e558 == 31u) {
                                        let _e568 = local_43;
                                        phi_446_ = (2139095040u | (_e568 << bitcast<u32>(13i)));
                                    } else {
                                        let _e560 = local_42;
                                        let _e564 = local_43;
                                        phi_446_ = (((_e560 + 112u) << bitcast<u32>(23i)) | (_e564 << bitcast<u32>(13i)));
                                    }
                                    let _e573 = phi_446_;
                                    let _e575 = local_228;
                                    phi_449_ = (_e575 * bitcast<f32>(_e573));
                                }
                                let _e583 = phi_449_;
                                let _e584 = local_41;
                                let _e586 = local_26;
                                local_44 = (_e586[2] + (_e584 * _e583));
                                let _e589 = local_27;
                                if _e589 {
                                } else {
                                    phi_2098_ = true;
                                    break;
                                }
                                let _e590 = local_254[_e458];
                                local_45 = _e590;
                                let _e591 = local_32;
                                let _e593 = (_e591 >> bitcast<u32>(16i));
                                local_229 = select(-1f, 1f, ((_e593 & 32768u) == 0u));
                                let _e599 = ((_e593 >> bitcast<u32>(10i)) & 31u);
                                local_46 = _e599;
                                local_47 = (_e593 & 1023u);
                                if (_e599 == 0u) {
                                    let _e621 = local_47;
                                    let _e623 = local_229;
                                    phi_492_ = ((_e623 * f32(_e621)) * 0.000000059604645f);
                                } else {
                                    let _e602 = local_46;
                                    if (_e602 == 31u) {
                                        let _e612 = local_47;
                                        phi_489_ = (2139095040u | (_e612 << bitcast<u32>(13i)));
                                    } else {
                                        let _e604 = local_46;
                                        let _e608 = local_47;
                                        phi_489_ = (((_e604 + 112u) << bitcast<u32>(23i)) | (_e608 << bitcast<u32>(13i)));
                                    }
                                    let _e617 = phi_489_;
                                    let _e619 = local_229;
                                    phi_492_ = (_e619 * bitcast<f32>(_e617));
                                }
                                let _e627 = phi_492_;
                                let _e628 = local_45;
                                let _e630 = local_26;
                                let _e633 = local_36;
                                let _e634 = local_40;
                                let _e635 = local_44;
                                let _e637 = local_25;
                                phi_291_ = (_e637 + 1u);
                                phi_294_ = array<f32, 4>(_e633, _e634, _e635, (_e630[3] + (_e628 * _e627)));
                            } else {
                                phi_291_ = u32();
                                phi_294_ = array<f32, 4>();
                            }
                            let _e640 = phi_291_;
                            let _e642 = phi_294_;
                            continue;
                            continuing {
                                let _e643 = local_27;
                                phi_290_ = _e640;
                                phi_293_ = _e642;
                                phi_2098_ = false;
                                break if !(_e643);
                            }
                        }
                        let _e646 = phi_2098_;
                        if _e646 {
                            break;
                        }
                        let _e647 = local_26;
                        local_48 = _e647[3];
                        let _e649 = local_23;
                        local_251 = _e649;
                        let _e651 = local_6;
                        local_252[0u] = _e651;
                        let _e653 = local_7;
                        local_252[1u] = _e653;
                        let _e655 = local_24;
                        local_252[2u] = _e655;
                        phi_510_ = 0u;
                        phi_513_ = 0f;
                        phi_515_ = 0f;
                        loop {
                            let _e657 = phi_510_;
                            let _e659 = phi_513_;
                            let _e661 = phi_515_;
                            local_49 = _e657;
                            local_50 = _e659;
                            local_51 = _e661;
                            let _e662 = local_49;
                            let _e663 = (_e662 < 3u);
                            local_52 = _e663;
                            if _e663 {
                                let _e664 = local_49;
                                if (_e664 < 4u) {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e666 = local_49;
                                let _e668 = local_251[_e666];
                                local_53 = (_e668 * 10u);
                                let _e670 = local_52;
                                if _e670 {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e671 = local_49;
                                let _e673 = local_252[_e671];
                                local_54 = _e673;
                                let _e674 = local_53;
                                let _e675 = (_e674 + 3u);
                                local_55 = _e675;
                                let _e676 = local;
                                if (_e675 < _e676) {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e678 = local_55;
                                let _e681 = global.member[_e678];
                                let _e683 = local_54;
                                let _e685 = local_51;
                                let _e687 = local_52;
                                if _e687 {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e688 = local_252[_e671];
                                local_56 = _e688;
                                let _e689 = local_53;
                                let _e690 = (_e689 + 7u);
                                local_57 = _e690;
                                let _e691 = local;
                                if (_e690 < _e691) {
                                } else {
                                    phi_2114_ = true;
                                    break;
                                }
                                let _e693 = local_57;
                                let _e696 = global.member[_e693];
                                let _e698 = local_56;
                                let _e700 = local_50;
                                let _e702 = local_49;
                                phi_511_ = (_e702 + 1u);
                                phi_514_ = (_e700 + (_e698 * bitcast<f32>(_e696)));
                                phi_516_ = (_e685 + (_e683 * bitcast<f32>(_e681)));
                            } else {
                                phi_511_ = u32();
                                phi_514_ = f32();
                                phi_516_ = f32();
                            }
                            let _e705 = phi_511_;
                            let _e707 = phi_514_;
                            let _e709 = phi_516_;
                            continue;
                            continuing {
                                let _e710 = local_52;
                                phi_510_ = _e705;
                                phi_513_ = _e707;
                                phi_515_ = _e709;
                                phi_2114_ = _e646;
                                break if !(_e710);
                            }
                        }
                        let _e713 = phi_2114_;
                        if _e713 {
                            break;
                        }
                        let _e714 = local_20;
                        let _e715 = (_e714 + 8u);
                        local_58 = _e715;
                        let _e716 = local_2;
                        if (_e715 < _e716) {
                        } else {
                            break;
                        }
                        let _e718 = local_58;
                        let _e721 = global_3.member[_e718];
                        local_59 = _e721;
                        let _e722 = local_20;
                        let _e723 = (_e722 + 3u);
                        local_60 = _e723;
                        let _e724 = local_2;
                        if (_e723 < _e724) {
                        } else {
                            break;
                        }
                        let _e726 = local_60;
                        let _e729 = global_3.member[_e726];
                        local_61 = bitcast<f32>(_e729);
                        let _e733 = global_8.member.member_8;
                        local_62 = _e733;
                        let _e734 = local_59;
                        if (_e734 == 4294967295u) {
                            phi_1959_ = type_3();
                            phi_1960_ = true;
                        } else {
                            let _e736 = local_59;
                            let _e737 = local_62;
                            let _e738 = (_e736 >= _e737);
                            if _e738 {
                                phi_1958_ = type_3();
                            } else {
                                let _e739 = local_59;
                                let _e740 = (_e739 * 4u);
                                local_63 = _e740;
                                let _e741 = local_3;
                                if (_e740 < _e741) {
                                } else {
                                    break;
                                }
                                let _e743 = local_63;
                                let _e746 = global_4.member[_e743];
                                local_64 = _e746;
                                let _e747 = local_63;
                                let _e748 = (_e747 + 1u);
                                local_65 = _e748;
                                let _e749 = local_3;
                                if (_e748 < _e749) {
                                } else {
                                    break;
                                }
                                let _e751 = local_65;
                                let _e754 = global_4.member[_e751];
                                local_66 = _e754;
                                let _e755 = local_63;
                                let _e756 = (_e755 + 2u);
                                local_67 = _e756;
                                let _e757 = local_3;
                                if (_e756 < _e757) {
                                } else {
                                    break;
                                }
                                let _e759 = local_67;
                                let _e762 = global_4.member[_e759];
                                local_68 = _e762;
                                let _e763 = local_63;
                                let _e764 = (_e763 + 3u);
                                local_69 = _e764;
                                let _e765 = local_3;
                                if (_e764 < _e765) {
                                } else {
                                    break;
                                }
                                let _e767 = local_69;
                                let _e770 = global_4.member[_e767];
                                local_70 = _e770;
                                let _e771 = local_66;
                                if (_e771 == 0u) {
                                    phi_1952_ = type_3();
                                    phi_1953_ = true;
                                } else {
                                    let _e773 = local_68;
                                    let _e774 = (_e773 == 0u);
                                    if _e774 {
                                        phi_1951_ = type_3();
                                    } else {
                                        let _e775 = local_70;
                                        let _e778 = ((_e775 >> bitcast<u32>(8u)) & 31u);
                                        local_230 = select(_e778, 1u, (_e778 == 0u));
                                        let _e781 = local_70;
                                        let _e785 = local_70;
                                        let _e789 = local_64;
                                        let _e790 = local_66;
                                        let _e791 = local_68;
                                        let _e792 = type_19(_e789, _e790, _e791, ((_e781 >> bitcast<u32>(1u)) & 3u), ((_e785 >> bitcast<u32>(3u)) & 3u));
                                        let _e793 = local_66;
                                        let _e795 = local_51;
                                        if ((bitcast<u32>((_e795 * f32(_e793))) & 2139095040u) != 2139095040u) {
                                            let _e800 = local_68;
                                            let _e802 = local_50;
                                            phi_665_ = select(true, false, ((bitcast<u32>((_e802 * f32(_e800))) & 2139095040u) != 2139095040u));
                                        } else {
                                            phi_665_ = true;
                                        }
                                        let _e809 = phi_665_;
                                        let _e810 = local_50;
                                        local_231 = select(_e810, 0f, _e809);
                                        let _e812 = local_51;
                                        local_232 = select(_e812, 0f, _e809);
                                        if false {
                                        }
                                        let _e814 = local_230;
                                        let _e815 = (_e814 - 1u);
                                        local_71 = _e815;
                                        let _e816 = floor(0f);
                                        let _e822 = select(select(u32(_e816), 0u, !((_e816 >= 0f))), 4294967295u, (_e816 > 4294967000f));
                                        local_72 = _e822;
                                        let _e823 = (_e822 >= _e815);
                                        local_73 = _e823;
                                        if _e823 {
                                            phi_851_ = 0f;
                                        } else {
                                            let _e824 = local_72;
                                            phi_851_ = -(f32(_e824));
                                        }
                                        let _e828 = phi_851_;
                                        local_74 = _e828;
                                        let _e829 = local_73;
                                        let _e830 = local_71;
                                        let _e831 = local_72;
                                        local_233 = select(_e831, _e830, _e829);
                                        local_234 = select(1u, 2u, (_e828 > 0f));
                                        phi_2021_ = 0u;
                                        phi_2022_ = _e792;
                                        loop {
                                            let _e836 = phi_2021_;
                                            let _e838 = phi_2022_;
                                            local_212 = _e836;
                                            local_213 = _e838;
                                            local_255 = _e838;
                                            let _e839 = local_212;
                                            let _e840 = local_233;
                                            let _e841 = (_e839 < _e840);
                                            local_214 = _e841;
                                            if _e841 {
                                                let _e842 = local_213;
                                                local_215 = _e842.member_1;
                                                let _e844 = local_213;
                                                local_216 = _e844.member_2;
                                                let _e847 = local_213;
                                                let _e850 = local_213;
                                                local_217 = type_19((_e847.member + (_e842.member_1 * _e844.member_2)), _e850.member_1, _e850.member_2, _e850.member_3, _e850.member_4);
                                                if (_e842.member_1 > 1u) {
                                                    let _e858 = local_215;
                                                    phi_2039_ = (_e858 >> bitcast<u32>(1i));
                                                } else {
                                                    phi_2039_ = 1u;
                                                }
                                                let _e862 = phi_2039_;
                                                let _e863 = local_217;
                                                local_218 = type_19(_e863.member, _e862, _e863.member_2, _e863.member_3, _e863.member_4);
                                                let _e870 = local_216;
                                                if (_e870 > 1u) {
                                                    let _e872 = local_216;
                                                    phi_2048_ = (_e872 >> bitcast<u32>(1i));
                                                } else {
                                                    phi_2048_ = 1u;
                                                }
                                                let _e876 = phi_2048_;
                                                let _e877 = local_218;
                                                let _e884 = local_212;
                                                phi_2053_ = (_e884 + 1u);
                                                phi_2054_ = type_19(_e877.member, _e877.member_1, _e876, _e877.member_3, _e877.member_4);
                                            } else {
                                                phi_2053_ = u32();
                                                phi_2054_ = type_19();
                                            }
                                            let _e887 = phi_2053_;
                                            let _e889 = phi_2054_;
                                            continue;
                                            continuing {
                                                let _e890 = local_214;
                                                phi_2021_ = _e887;
                                                phi_2022_ = _e889;
                                                break if !(_e890);
                                            }
                                        }
                                        let _e892 = local_233;
                                        let _e893 = local_234;
                                        local_75 = ((_e892 + _e893) - 1u);
                                        phi_2060_ = 0u;
                                        phi_2061_ = _e792;
                                        loop {
                                            let _e897 = phi_2060_;
                                            let _e899 = phi_2061_;
                                            local_219 = _e897;
                                            local_220 = _e899;
                                            local_256 = _e899;
                                            let _e900 = local_219;
                                            let _e901 = local_75;
                                            let _e902 = (_e900 < _e901);
                                            local_221 = _e902;
                                            if _e902 {
                                                let _e903 = local_220;
                                                local_222 = _e903.member_1;
                                                let _e905 = local_220;
                                                local_223 = _e905.member_2;
                                                let _e908 = local_220;
                                                let _e911 = local_220;
                                                local_224 = type_19((_e908.member + (_e903.member_1 * _e905.member_2)), _e911.member_1, _e911.member_2, _e911.member_3, _e911.member_4);
                                                if (_e903.member_1 > 1u) {
                                                    let _e919 = local_222;
                                                    phi_2078_ = (_e919 >> bitcast<u32>(1i));
                                                } else {
                                                    phi_2078_ = 1u;
                                                }
                                                let _e923 = phi_2078_;
                                                let _e924 = local_224;
                                                local_225 = type_19(_e924.member, _e923, _e924.member_2, _e924.member_3, _e924.member_4);
                                                let _e931 = local_223;
                                                if (_e931 > 1u) {
                                                    let _e933 = local_223;
                                                    phi_2087_ = (_e933 >> bitcast<u32>(1i));
                                                } else {
                                                    phi_2087_ = 1u;
                                                }
                                                let _e937 = phi_2087_;
                                                let _e938 = local_225;
                                                let _e945 = local_219;
                                                phi_2092_ = (_e945 + 1u);
                                                phi_2093_ = type_19(_e938.member, _e938.member_1, _e937, _e938.member_3, _e938.member_4);
                                            } else {
                                                phi_2092_ = u32();
                                                phi_2093_ = type_19();
                                            }
                                            let _e948 = phi_2092_;
                                            let _e950 = phi_2093_;
                                            continue;
                                            continuing {
                                                let _e951 = local_221;
                                                phi_2060_ = _e948;
                                                phi_2061_ = _e950;
                                                break if !(_e951);
                                            }
                                        }
                                        let _e953 = local_70;
                                        local_76 = ((_e953 & 1u) != 0u);
                                        phi_2164_ = _e713;
                                        phi_870_ = 0u;
                                        phi_873_ = type_3(0f, 0f, 0f, 0f);
                                        loop {
                                            let _e957 = phi_2164_;
                                            let _e959 = phi_870_;
                                            let _e961 = phi_873_;
                                            local_77 = _e959;
                                            local_78 = _e961;
                                            local_259 = _e961;
                                            let _e962 = local_77;
                                            let _e963 = (_e962 < 1u);
                                            local_79 = _e963;
                                            if _e963 {
                                                phi_2163_ = _e957;
                                                phi_887_ = 0u;
                                                phi_890_ = _e961;
                                                loop {
                                                    let _e965 = phi_2163_;
                                                    let _e967 = phi_887_;
                                                    let _e969 = phi_890_;
                                                    local_80 = _e967;
                                                    local_258 = _e969;
                                                    let _e970 = local_80;
                                                    let _e971 = (_e970 < 1u);
                                                    local_81 = _e971;
                                                    if _e971 {
                                                        phi_916_ = 0u;
                                                        phi_919_ = _e969;
                                                        loop {
                                                            let _e973 = phi_916_;
                                                            let _e975 = phi_919_;
                                                            local_82 = _e973;
                                                            local_83 = _e975;
                                                            local_257 = _e975;
                                                            let _e976 = local_82;
                                                            let _e977 = local_234;
                                                            let _e978 = (_e976 < _e977);
                                                            local_84 = _e978;
                                                            if _e978 {
                                                                let _e979 = local_82;
                                                                if (_e979 == 0u) {
                                                                    let _e981 = local_74;
                                                                    let _e2230 = local_255;
                                                                    phi_932_ = _e2230;
                                                                    phi_933_ = (1f - _e981);
                                                                } else {
                                                                    let _e2232 = local_256;
                                                                    phi_932_ = _e2232;
                                                                    phi_933_ = _e828;
                                                                }
                                                                let _e984 = phi_932_;
                                                                let _e986 = phi_933_;
                                                                local_85 = _e984;
                                                                local_86 = _e986;
                                                                let _e987 = local_76;
                                                                let _e988 = select(0.5f, 0f, _e987);
                                                                local_87 = _e984.member_1;
                                                                let _e991 = local_232;
                                                                let _e993 = ((_e991 * f32(_e984.member_1)) - _e988);
                                                                local_88 = _e993;
                                                                local_89 = _e984.member_2;
                                                                let _e996 = local_231;
                                                                let _e998 = ((_e996 * f32(_e984.member_2)) - _e988);
                                                                local_90 = _e998;
                                                                local_91 = floor(_e993);
                                                                local_92 = floor(_e998);
                                                                let _e1001 = local_76;
                                                                if _e1001 {
                                                                    phi_953_ = 0f;
                                                                    phi_954_ = 0f;
                                                                } else {
                                                                    let _e1002 = local_88;
                                                                    let _e1003 = local_91;
                                                                    let _e1005 = local_90;
                                                                    let _e1006 = local_92;
                                                                    phi_953_ = (_e1005 - _e1006);
                                                                    phi_954_ = (_e1002 - _e1003);
                                                                }
                                                                let _e1009 = phi_953_;
                                                                let _e1011 = phi_954_;
                                                                local_93 = _e1009;
                                                                local_94 = _e1011;
                                                                let _e1012 = local_91;
                                                                let _e1014 = local_91;
                                                                let _e1017 = local_91;
                                                                let _e1021 = local_91;
                                                                let _e1022 = local_91;
                                                                let _e1024 = select(0i, select(select(i32(_e1012), i32(-2147483648), !((_e1014 >= -2147483600f))), 2147483647i, (_e1017 > 2147483500f)), (_e1021 == _e1022));
                                                                local_95 = _e1024;
                                                                let _e1025 = local_92;
                                                                let _e1027 = local_92;
                                                                let _e1030 = local_92;
                                                                let _e1034 = local_92;
                                                                let _e1035 = local_92;
                                                                let _e1037 = select(0i, select(select(i32(_e1025), i32(-2147483648), !((_e1027 >= -2147483600f))), 2147483647i, (_e1030 > 2147483500f)), (_e1034 == _e1035));
                                                                local_96 = _e1037;
                                                                let _e1038 = local_85;
                                                                local_97 = _e1038.member_3;
                                                                let _e1040 = local_87;
                                                                local_98 = bitcast<i32>(_e1040);
                                                                let _e1042 = (_e1038.member_3 == 1u);
                                                                local_99 = _e1042;
                                                                if _e1042 {
                                                                    let _e1096 = local_95;
                                                                    if (_e1096 < 0i) {
                                                                        phi_990_ = 0i;
                                                                    } else {
                                                                        let _e1098 = local_95;
                                                                        let _e1099 = local_98;
                                                                        if (_e1098 >= _e1099) {
                                                                            let _e1101 = local_98;
                                                                            phi_989_ = (_e1101 - 1i);
                                                                        } else {
                                                                            phi_989_ = _e1024;
                                                                        }
                                                                        let _e1104 = phi_989_;
                                                                        phi_990_ = _e1104;
                                                                    }
                                                                    let _e1106 = phi_990_;
                                                                    phi_1050_ = _e1106;
                                                                } else {
                                                                    let _e1043 = local_97;
                                                                    if (_e1043 == 2u) {
                                                                        let _e1065 = local_98;
                                                                        let _e1066 = (2i * _e1065);
                                                                        local_100 = _e1066;
                                                                        let _e1067 = (_e1066 == 0i);
                                                                        local_101 = _e1067;
                                                                        if _e1067 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1068 = local_100;
                                                                        let _e1069 = (_e1068 == -1i);
                                                                        local_102 = _e1069;
                                                                        let _e1070 = local_95;
                                                                        if (_e1069 && (_e1070 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1073 = local_95;
                                                                        let _e1074 = local_100;
                                                                        let _e1076 = local_100;
                                                                        local_103 = ((_e1073 % _e1074) + _e1076);
                                                                        let _e1078 = local_101;
                                                                        if _e1078 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1079 = local_103;
                                                                        let _e1081 = local_102;
                                                                        if (_e1081 && (_e1079 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1083 = local_103;
                                                                        let _e1084 = local_100;
                                                                        let _e1085 = (_e1083 % _e1084);
                                                                        local_104 = _e1085;
                                                                        let _e1086 = local_98;
                                                                        if (_e1085 < _e1086) {
                                                                            phi_1025_ = _e1085;
                                                                        } else {
                                                                            let _e1088 = local_100;
                                                                            let _e1090 = local_104;
                                                                            phi_1025_ = ((_e1088 - 1i) - _e1090);
                                                                        }
                                                                        let _e1093 = phi_1025_;
                                                                        phi_1049_ = _e1093;
                                                                    } else {
                                                                        let _e1045 = local_98;
                                                                        let _e1046 = (_e1045 == 0i);
                                                                        local_105 = _e1046;
                                                                        if _e1046 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1047 = local_98;
                                                                        let _e1048 = (_e1047 == -1i);
                                                                        local_106 = _e1048;
                                                                        let _e1049 = local_95;
                                                                        if (_e1048 && (_e1049 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1052 = local_95;
                                                                        let _e1053 = local_98;
                                                                        let _e1055 = local_98;
                                                                        local_107 = ((_e1052 % _e1053) + _e1055);
                                                                        let _e1057 = local_105;
                                                                        if _e1057 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1058 = local_107;
                                                                        let _e1060 = local_106;
                                                                        if (_e1060 && (_e1058 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1062 = local_107;
                                                                        let _e1063 = local_98;
                                                                        phi_1049_ = (_e1062 % _e1063);
                                                                    }
                                                                    let _e1095 = phi_1049_;
                                                                    phi_1050_ = _e1095;
                                                                }
                                                                let _e1108 = phi_1050_;
                                                                local_108 = bitcast<u32>(_e1108);
                                                                let _e1110 = local_95;
                                                                let _e1111 = (_e1110 + 1i);
                                                                local_109 = _e1111;
                                                                let _e1112 = local_99;
                                                                if _e1112 {
                                                                    let _e1166 = local_109;
                                                                    if (_e1166 < 0i) {
                                                                        phi_1070_ = 0i;
                                                                    } else {
                                                                        let _e1168 = local_109;
                                                                        let _e1169 = local_98;
                                                                        if (_e1168 >= _e1169) {
                                                                            let _e1171 = local_98;
                                                                            phi_1069_ = (_e1171 - 1i);
                                                                        } else {
                                                                            phi_1069_ = _e1111;
                                                                        }
                                                                        let _e1174 = phi_1069_;
                                                                        phi_1070_ = _e1174;
                                                                    }
                                                                    let _e1176 = phi_1070_;
                                                                    phi_1130_ = _e1176;
                                                                } else {
                                                                    let _e1113 = local_97;
                                                                    if (_e1113 == 2u) {
                                                                        let _e1135 = local_98;
                                                                        let _e1136 = (2i * _e1135);
                                                                        local_110 = _e1136;
                                                                        let _e1137 = (_e1136 == 0i);
                                                                        local_111 = _e1137;
                                                                        if _e1137 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1138 = local_110;
                                                                        let _e1139 = (_e1138 == -1i);
                                                                        local_112 = _e1139;
                                                                        let _e1140 = local_109;
                                                                        if (_e1139 && (_e1140 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1143 = local_109;
                                                                        let _e1144 = local_110;
                                                                        let _e1146 = local_110;
                                                                        local_113 = ((_e1143 % _e1144) + _e1146);
                                                                        let _e1148 = local_111;
                                                                        if _e1148 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1149 = local_113;
                                                                        let _e1151 = local_112;
                                                                        if (_e1151 && (_e1149 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1153 = local_113;
                                                                        let _e1154 = local_110;
                                                                        let _e1155 = (_e1153 % _e1154);
                                                                        local_114 = _e1155;
                                                                        let _e1156 = local_98;
                                                                        if (_e1155 < _e1156) {
                                                                            phi_1105_ = _e1155;
                                                                        } else {
                                                                            let _e1158 = local_110;
                                                                            let _e1160 = local_114;
                                                                            phi_1105_ = ((_e1158 - 1i) - _e1160);
                                                                        }
                                                                        let _e1163 = phi_1105_;
                                                                        phi_1129_ = _e1163;
                                                                    } else {
                                                                        let _e1115 = local_98;
                                                                        let _e1116 = (_e1115 == 0i);
                                                                        local_115 = _e1116;
                                                                        if _e1116 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1117 = local_98;
                                                                        let _e1118 = (_e1117 == -1i);
                                                                        local_116 = _e1118;
                                                                        let _e1119 = local_109;
                                                                        if (_e1118 && (_e1119 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1122 = local_109;
                                                                        let _e1123 = local_98;
                                                                        let _e1125 = local_98;
                                                                        local_117 = ((_e1122 % _e1123) + _e1125);
                                                                        let _e1127 = local_115;
                                                                        if _e1127 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1128 = local_117;
                                                                        let _e1130 = local_116;
                                                                        if (_e1130 && (_e1128 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1132 = local_117;
                                                                        let _e1133 = local_98;
                                                                        phi_1129_ = (_e1132 % _e1133);
                                                                    }
                                                                    let _e1165 = phi_1129_;
                                                                    phi_1130_ = _e1165;
                                                                }
                                                                let _e1178 = phi_1130_;
                                                                local_118 = bitcast<u32>(_e1178);
                                                                let _e1180 = local_85;
                                                                local_119 = _e1180.member_4;
                                                                let _e1182 = local_89;
                                                                local_120 = bitcast<i32>(_e1182);
                                                                let _e1184 = (_e1180.member_4 == 1u);
                                                                local_121 = _e1184;
                                                                if _e1184 {
                                                                    let _e1238 = local_96;
                                                                    if (_e1238 < 0i) {
                                                                        phi_1149_ = 0i;
                                                                    } else {
                                                                        let _e1240 = local_96;
                                                                        let _e1241 = local_120;
                                                                        if (_e1240 >= _e1241) {
                                                                            let _e1243 = local_120;
                                                                            phi_1148_ = (_e1243 - 1i);
                                                                        } else {
                                                                            phi_1148_ = _e1037;
                                                                        }
                                                                        let _e1246 = phi_1148_;
                                                                        phi_1149_ = _e1246;
                                                                    }
                                                                    let _e1248 = phi_1149_;
                                                                    phi_1209_ = _e1248;
                                                                } else {
                                                                    let _e1185 = local_119;
                                                                    if (_e1185 == 2u) {
                                                                        let _e1207 = local_120;
                                                                        let _e1208 = (2i * _e1207);
                                                                        local_122 = _e1208;
                                                                        let _e1209 = (_e1208 == 0i);
                                                                        local_123 = _e1209;
                                                                        if _e1209 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1210 = local_122;
                                                                        let _e1211 = (_e1210 == -1i);
                                                                        local_124 = _e1211;
                                                                        let _e1212 = local_96;
                                                                        if (_e1211 && (_e1212 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1215 = local_96;
                                                                        let _e1216 = local_122;
                                                                        let _e1218 = local_122;
                                                                        local_125 = ((_e1215 % _e1216) + _e1218);
                                                                        let _e1220 = local_123;
                                                                        if _e1220 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1221 = local_125;
                                                                        let _e1223 = local_124;
                                                                        if (_e1223 && (_e1221 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1225 = local_125;
                                                                        let _e1226 = local_122;
                                                                        let _e1227 = (_e1225 % _e1226);
                                                                        local_126 = _e1227;
                                                                        let _e1228 = local_120;
                                                                        if (_e1227 < _e1228) {
                                                                            phi_1184_ = _e1227;
                                                                        } else {
                                                                            let _e1230 = local_122;
                                                                            let _e1232 = local_126;
                                                                            phi_1184_ = ((_e1230 - 1i) - _e1232);
                                                                        }
                                                                        let _e1235 = phi_1184_;
                                                                        phi_1208_ = _e1235;
                                                                    } else {
                                                                        let _e1187 = local_120;
                                                                        let _e1188 = (_e1187 == 0i);
                                                                        local_127 = _e1188;
                                                                        if _e1188 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1189 = local_120;
                                                                        let _e1190 = (_e1189 == -1i);
                                                                        local_128 = _e1190;
                                                                        let _e1191 = local_96;
                                                                        if (_e1190 && (_e1191 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1194 = local_96;
                                                                        let _e1195 = local_120;
                                                                        let _e1197 = local_120;
                                                                        local_129 = ((_e1194 % _e1195) + _e1197);
                                                                        let _e1199 = local_127;
                                                                        if _e1199 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1200 = local_129;
                                                                        let _e1202 = local_128;
                                                                        if (_e1202 && (_e1200 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1204 = local_129;
                                                                        let _e1205 = local_120;
                                                                        phi_1208_ = (_e1204 % _e1205);
                                                                    }
                                                                    let _e1237 = phi_1208_;
                                                                    phi_1209_ = _e1237;
                                                                }
                                                                let _e1250 = phi_1209_;
                                                                local_130 = bitcast<u32>(_e1250);
                                                                let _e1252 = local_96;
                                                                let _e1253 = (_e1252 + 1i);
                                                                local_131 = _e1253;
                                                                let _e1254 = local_121;
                                                                if _e1254 {
                                                                    let _e1308 = local_131;
                                                                    if (_e1308 < 0i) {
                                                                        phi_1229_ = 0i;
                                                                    } else {
                                                                        let _e1310 = local_131;
                                                                        let _e1311 = local_120;
                                                                        if (_e1310 >= _e1311) {
                                                                            let _e1313 = local_120;
                                                                            phi_1228_ = (_e1313 - 1i);
                                                                        } else {
                                                                            phi_1228_ = _e1253;
                                                                        }
                                                                        let _e1316 = phi_1228_;
                                                                        phi_1229_ = _e1316;
                                                                    }
                                                                    let _e1318 = phi_1229_;
                                                                    phi_1289_ = _e1318;
                                                                } else {
                                                                    let _e1255 = local_119;
                                                                    if (_e1255 == 2u) {
                                                                        let _e1277 = local_120;
                                                                        let _e1278 = (2i * _e1277);
                                                                        local_132 = _e1278;
                                                                        let _e1279 = (_e1278 == 0i);
                                                                        local_133 = _e1279;
                                                                        if _e1279 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1280 = local_132;
                                                                        let _e1281 = (_e1280 == -1i);
                                                                        local_134 = _e1281;
                                                                        let _e1282 = local_131;
                                                                        if (_e1281 && (_e1282 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1285 = local_131;
                                                                        let _e1286 = local_132;
                                                                        let _e1288 = local_132;
                                                                        local_135 = ((_e1285 % _e1286) + _e1288);
                                                                        let _e1290 = local_133;
                                                                        if _e1290 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1291 = local_135;
                                                                        let _e1293 = local_134;
                                                                        if (_e1293 && (_e1291 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1295 = local_135;
                                                                        let _e1296 = local_132;
                                                                        let _e1297 = (_e1295 % _e1296);
                                                                        local_136 = _e1297;
                                                                        let _e1298 = local_120;
                                                                        if (_e1297 < _e1298) {
                                                                            phi_1264_ = _e1297;
                                                                        } else {
                                                                            let _e1300 = local_132;
                                                                            let _e1302 = local_136;
                                                                            phi_1264_ = ((_e1300 - 1i) - _e1302);
                                                                        }
                                                                        let _e1305 = phi_1264_;
                                                                        phi_1288_ = _e1305;
                                                                    } else {
                                                                        let _e1257 = local_120;
                                                                        let _e1258 = (_e1257 == 0i);
                                                                        local_137 = _e1258;
                                                                        if _e1258 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1259 = local_120;
                                                                        let _e1260 = (_e1259 == -1i);
                                                                        local_138 = _e1260;
                                                                        let _e1261 = local_131;
                                                                        if (_e1260 && (_e1261 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1264 = local_131;
                                                                        let _e1265 = local_120;
                                                                        let _e1267 = local_120;
                                                                        local_139 = ((_e1264 % _e1265) + _e1267);
                                                                        let _e1269 = local_137;
                                                                        if _e1269 {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1270 = local_139;
                                                                        let _e1272 = local_138;
                                                                        if (_e1272 && (_e1270 == i32(-2147483648))) {
                                                                            phi_2117_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1274 = local_139;
                                                                        let _e1275 = local_120;
                                                                        phi_1288_ = (_e1274 % _e1275);
                                                                    }
                                                                    let _e1307 = phi_1288_;
                                                                    phi_1289_ = _e1307;
                                                                }
                                                                let _e1320 = phi_1289_;
                                                                local_140 = bitcast<u32>(_e1320);
                                                                let _e1322 = local_85;
                                                                local_141 = _e1322.member;
                                                                let _e1324 = local_130;
                                                                let _e1325 = local_87;
                                                                let _e1327 = (_e1322.member + (_e1324 * _e1325));
                                                                local_142 = _e1327;
                                                                let _e1328 = local_108;
                                                                let _e1330 = ((_e1327 + _e1328) * 2u);
                                                                local_143 = _e1330;
                                                                let _e1331 = local_4;
                                                                if (_e1330 < _e1331) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1333 = local_143;
                                                                let _e1336 = global_5.member[_e1333];
                                                                local_144 = _e1336;
                                                                let _e1337 = local_143;
                                                                let _e1338 = (_e1337 + 1u);
                                                                local_145 = _e1338;
                                                                let _e1339 = local_4;
                                                                if (_e1338 < _e1339) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1341 = local_145;
                                                                let _e1344 = global_5.member[_e1341];
                                                                local_146 = _e1344;
                                                                let _e1345 = local_144;
                                                                let _e1346 = (_e1345 & 65535u);
                                                                local_235 = select(-1f, 1f, ((_e1346 & 32768u) == 0u));
                                                                let _e1352 = ((_e1346 >> bitcast<u32>(10i)) & 31u);
                                                                local_147 = _e1352;
                                                                local_148 = (_e1346 & 1023u);
                                                                if (_e1352 == 0u) {
                                                                    let _e1374 = local_148;
                                                                    let _e1376 = local_235;
                                                                    phi_1343_ = ((_e1376 * f32(_e1374)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1355 = local_147;
                                                                    if (_e1355 == 31u) {
                                                                        let _e1365 = local_148;
                                                                        phi_1340_ = (2139095040u | (_e1365 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1357 = local_147;
                                                                        let _e1361 = local_148;
                                                                        phi_1340_ = (((_e1357 + 112u) << bitcast<u32>(23i)) | (_e1361 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1370 = phi_1340_;
                                                                    let _e1372 = local_235;
                                                                    phi_1343_ = (_e1372 * bitcast<f32>(_e1370));
                                                                }
                                                                let _e1380 = phi_1343_;
                                                                local_149 = _e1380;
                                                                let _e1381 = local_144;
                                                                let _e1383 = (_e1381 >> bitcast<u32>(16i));
                                                                local_236 = select(-1f, 1f, ((_e1383 & 32768u) == 0u));
                                                                let _e1389 = ((_e1383 >> bitcast<u32>(10i)) & 31u);
                                                                local_150 = _e1389;
                                                                local_151 = (_e1383 & 1023u);
                                                                if (_e1389 == 0u) {
                                                                    let _e1411 = local_151;
                                                                    let _e1413 = local_236;
                                                                    phi_1375_ = ((_e1413 * f32(_e1411)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1392 = local_150;
                                                                    if (_e1392 == 31u) {
                                                                        let _e1402 = local_151;
                                                                        phi_1372_ = (2139095040u | (_e1402 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1394 = local_150;
                                                                        let _e1398 = local_151;
                                                                        phi_1372_ = (((_e1394 + 112u) << bitcast<u32>(23i)) | (_e1398 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1407 = phi_1372_;
                                                                    let _e1409 = local_236;
                                                                    phi_1375_ = (_e1409 * bitcast<f32>(_e1407));
                                                                }
                                                                let _e1417 = phi_1375_;
                                                                local_152 = _e1417;
                                                                let _e1418 = local_146;
                                                                let _e1419 = (_e1418 & 65535u);
                                                                local_237 = select(-1f, 1f, ((_e1419 & 32768u) == 0u));
                                                                let _e1425 = ((_e1419 >> bitcast<u32>(10i)) & 31u);
                                                                local_153 = _e1425;
                                                                local_154 = (_e1419 & 1023u);
                                                                if (_e1425 == 0u) {
                                                                    let _e1447 = local_154;
                                                                    let _e1449 = local_237;
                                                                    phi_1407_ = ((_e1449 * f32(_e1447)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1428 = local_153;
                                                                    if (_e1428 == 31u) {
                                                                        let _e1438 = local_154;
                                                                        phi_1404_ = (2139095040u | (_e1438 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1430 = local_153;
                                                                        let _e1434 = local_154;
                                                                        phi_1404_ = (((_e1430 + 112u) << bitcast<u32>(23i)) | (_e1434 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1443 = phi_1404_;
                                                                    let _e1445 = local_237;
                                                                    phi_1407_ = (_e1445 * bitcast<f32>(_e1443));
                                                                }
                                                                let _e1453 = phi_1407_;
                                                                local_155 = _e1453;
                                                                let _e1454 = local_146;
                                                                let _e1456 = (_e1454 >> bitcast<u32>(16i));
                                                                local_238 = select(-1f, 1f, ((_e1456 & 32768u) == 0u));
                                                                let _e1462 = ((_e1456 >> bitcast<u32>(10i)) & 31u);
                                                                local_156 = _e1462;
                                                                local_157 = (_e1456 & 1023u);
                                                                if (_e1462 == 0u) {
                                                                    let _e1484 = local_157;
                                                                    let _e1486 = local_238;
                                                                    phi_1439_ = ((_e1486 * f32(_e1484)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1465 = local_156;
                                                                    if (_e1465 == 31u) {
                                                                        let _e1475 = local_157;
                                                                        phi_1436_ = (2139095040u | (_e1475 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1467 = local_156;
                                                                        let _e1471 = local_157;
                                                                        phi_1436_ = (((_e1467 + 112u) << bitcast<u32>(23i)) | (_e1471 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1480 = phi_1436_;
                                                                    let _e1482 = local_238;
                                                                    phi_1439_ = (_e1482 * bitcast<f32>(_e1480));
                                                                }
                                                                let _e1490 = phi_1439_;
                                                                local_158 = _e1490;
                                                                let _e1491 = local_142;
                                                                let _e1492 = local_118;
                                                                let _e1494 = ((_e1491 + _e1492) * 2u);
                                                                local_159 = _e1494;
                                                                let _e1495 = local_4;
                                                                if (_e1494 < _e1495) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1497 = local_159;
                                                                let _e1500 = global_5.member[_e1497];
                                                                local_160 = _e1500;
                                                                let _e1501 = local_159;
                                                                let _e1502 = (_e1501 + 1u);
                                                                local_161 = _e1502;
                                                                let _e1503 = local_4;
                                                                if (_e1502 < _e1503) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1505 = local_161;
                                                                let _e1508 = global_5.member[_e1505];
                                                                local_162 = _e1508;
                                                                let _e1509 = local_160;
                                                                let _e1510 = (_e1509 & 65535u);
                                                                local_239 = select(-1f, 1f, ((_e1510 & 32768u) == 0u));
                                                                let _e1516 = ((_e1510 >> bitcast<u32>(10i)) & 31u);
                                                                local_163 = _e1516;
                                                                local_164 = (_e1510 & 1023u);
                                                                if (_e1516 == 0u) {
                                                                    let _e1538 = local_164;
                                                                    let _e1540 = local_239;
                                                                    phi_1492_ = ((_e1540 * f32(_e1538)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1519 = local_163;
                                                                    if (_e1519 == 31u) {
                                                                        let _e1529 = local_164;
                                                                        phi_1489_ = (2139095040u | (_e1529 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1521 = local_163;
                                                                        let _e1525 = local_164;
                                                                        phi_1489_ = (((_e1521 + 112u) << bitcast<u32>(23i)) | (_e1525 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1534 = phi_1489_;
                                                                    let _e1536 = local_239;
                                                                    phi_1492_ = (_e1536 * bitcast<f32>(_e1534));
                                                                }
                                                                let _e1544 = phi_1492_;
                                                                local_165 = _e1544;
                                                                let _e1545 = local_160;
                                                                let _e1547 = (_e1545 >> bitcast<u32>(16i));
                                                                local_240 = select(-1f, 1f, ((_e1547 & 32768u) == 0u));
                                                                let _e1553 = ((_e1547 >> bitcast<u32>(10i)) & 31u);
                                                                local_166 = _e1553;
                                                                local_167 = (_e1547 & 1023u);
                                                                if (_e1553 == 0u) {
                                                                    let _e1575 = local_167;
                                                                    let _e1577 = local_240;
                                                                    phi_1524_ = ((_e1577 * f32(_e1575)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1556 = local_166;
                                                                    if (_e1556 == 31u) {
                                                                        let _e1566 = local_167;
                                                                        phi_1521_ = (2139095040u | (_e1566 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1558 = local_166;
                                                                        let _e1562 = local_167;
                                                                        phi_1521_ = (((_e1558 + 112u) << bitcast<u32>(23i)) | (_e1562 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1571 = phi_1521_;
                                                                    let _e1573 = local_240;
                                                                    phi_1524_ = (_e1573 * bitcast<f32>(_e1571));
                                                                }
                                                                let _e1581 = phi_1524_;
                                                                local_168 = _e1581;
                                                                let _e1582 = local_162;
                                                                let _e1583 = (_e1582 & 65535u);
                                                                local_241 = select(-1f, 1f, ((_e1583 & 32768u) == 0u));
                                                                let _e1589 = ((_e1583 >> bitcast<u32>(10i)) & 31u);
                                                                local_169 = _e1589;
                                                                local_170 = (_e1583 & 1023u);
                                                                if (_e1589 == 0u) {
                                                                    let _e1611 = local_170;
                                                                    let _e1613 = local_241;
                                                                    phi_1556_ = ((_e1613 * f32(_e1611)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1592 = local_169;
                                                                    if (_e1592 == 31u) {
                                                                        let _e1602 = local_170;
                                                                        phi_1553_ = (2139095040u | (_e1602 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1594 = local_169;
                                                                        let _e1598 = local_170;
                                                                        phi_1553_ = (((_e1594 + 112u) << bitcast<u32>(23i)) | (_e1598 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1607 = phi_1553_;
                                                                    let _e1609 = local_241;
                                                                    phi_1556_ = (_e1609 * bitcast<f32>(_e1607));
                                                                }
                                                                let _e1617 = phi_1556_;
                                                                local_171 = _e1617;
                                                                let _e1618 = local_162;
                                                                let _e1620 = (_e1618 >> bitcast<u32>(16i));
                                                                local_242 = select(-1f, 1f, ((_e1620 & 32768u) == 0u));
                                                                let _e1626 = ((_e1620 >> bitcast<u32>(10i)) & 31u);
                                                                local_172 = _e1626;
                                                                local_173 = (_e1620 & 1023u);
                                                                if (_e1626 == 0u) {
                                                                    let _e1648 = local_173;
                                                                    let _e1650 = local_242;
                                                                    phi_1588_ = ((_e1650 * f32(_e1648)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1629 = local_172;
                                                                    if (_e1629 == 31u) {
                                                                        let _e1639 = local_173;
                                                                        phi_1585_ = (2139095040u | (_e1639 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1631 = local_172;
                                                                        let _e1635 = local_173;
                                                                        phi_1585_ = (((_e1631 + 112u) << bitcast<u32>(23i)) | (_e1635 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1644 = phi_1585_;
                                                                    let _e1646 = local_242;
                                                                    phi_1588_ = (_e1646 * bitcast<f32>(_e1644));
                                                                }
                                                                let _e1654 = phi_1588_;
                                                                let _e1655 = local_165;
                                                                let _e1656 = local_149;
                                                                let _e1658 = local_94;
                                                                let _e1660 = local_149;
                                                                local_174 = (_e1660 + ((_e1655 - _e1656) * _e1658));
                                                                let _e1662 = local_168;
                                                                let _e1663 = local_152;
                                                                let _e1665 = local_94;
                                                                let _e1667 = local_152;
                                                                local_175 = (_e1667 + ((_e1662 - _e1663) * _e1665));
                                                                let _e1669 = local_171;
                                                                let _e1670 = local_155;
                                                                let _e1672 = local_94;
                                                                let _e1674 = local_155;
                                                                local_176 = (_e1674 + ((_e1669 - _e1670) * _e1672));
                                                                let _e1676 = local_158;
                                                                let _e1678 = local_94;
                                                                let _e1680 = local_158;
                                                                local_177 = (_e1680 + ((_e1654 - _e1676) * _e1678));
                                                                let _e1682 = local_140;
                                                                let _e1683 = local_87;
                                                                let _e1685 = local_141;
                                                                let _e1686 = (_e1685 + (_e1682 * _e1683));
                                                                local_178 = _e1686;
                                                                let _e1687 = local_108;
                                                                let _e1689 = ((_e1686 + _e1687) * 2u);
                                                                local_179 = _e1689;
                                                                let _e1690 = local_4;
                                                                if (_e1689 < _e1690) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1692 = local_179;
                                                                let _e1695 = global_5.member[_e1692];
                                                                local_180 = _e1695;
                                                                let _e1696 = local_179;
                                                                let _e1697 = (_e1696 + 1u);
                                                                local_181 = _e1697;
                                                                let _e1698 = local_4;
                                                                if (_e1697 < _e1698) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1700 = local_181;
                                                                let _e1703 = global_5.member[_e1700];
                                                                local_182 = _e1703;
                                                                let _e1704 = local_180;
                                                                let _e1705 = (_e1704 & 65535u);
                                                                local_243 = select(-1f, 1f, ((_e1705 & 32768u) == 0u));
                                                                let _e1711 = ((_e1705 >> bitcast<u32>(10i)) & 31u);
                                                                local_183 = _e1711;
                                                                local_184 = (_e1705 & 1023u);
                                                                if (_e1711 == 0u) {
                                                                    let _e1733 = local_184;
                                                                    let _e1735 = local_243;
                                                                    phi_1653_ = ((_e1735 * f32(_e1733)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1714 = local_183;
                                                                    if (_e1714 == 31u) {
                                                                        let _e1724 = local_184;
                                                                        phi_1650_ = (2139095040u | (_e1724 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1716 = local_183;
                                                                        let _e1720 = local_184;
                                                                        phi_1650_ = (((_e1716 + 112u) << bitcast<u32>(23i)) | (_e1720 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1729 = phi_1650_;
                                                                    let _e1731 = local_243;
                                                                    phi_1653_ = (_e1731 * bitcast<f32>(_e1729));
                                                                }
                                                                let _e1739 = phi_1653_;
                                                                local_185 = _e1739;
                                                                let _e1740 = local_180;
                                                                let _e1742 = (_e1740 >> bitcast<u32>(16i));
                                                                local_244 = select(-1f, 1f, ((_e1742 & 32768u) == 0u));
                                                                let _e1748 = ((_e1742 >> bitcast<u32>(10i)) & 31u);
                                                                local_186 = _e1748;
                                                                local_187 = (_e1742 & 1023u);
                                                                if (_e1748 == 0u) {
                                                                    let _e1770 = local_187;
                                                                    let _e1772 = local_244;
                                                                    phi_1685_ = ((_e1772 * f32(_e1770)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1751 = local_186;
                                                                    if (_e1751 == 31u) {
                                                                        let _e1761 = local_187;
                                                                        phi_1682_ = (2139095040u | (_e1761 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1753 = local_186;
                                                                        let _e1757 = local_187;
                                                                        phi_1682_ = (((_e1753 + 112u) << bitcast<u32>(23i)) | (_e1757 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1766 = phi_1682_;
                                                                    let _e1768 = local_244;
                                                                    phi_1685_ = (_e1768 * bitcast<f32>(_e1766));
                                                                }
                                                                let _e1776 = phi_1685_;
                                                                local_188 = _e1776;
                                                                let _e1777 = local_182;
                                                                let _e1778 = (_e1777 & 65535u);
                                                                local_245 = select(-1f, 1f, ((_e1778 & 32768u) == 0u));
                                                                let _e1784 = ((_e1778 >> bitcast<u32>(10i)) & 31u);
                                                                local_189 = _e1784;
                                                                local_190 = (_e1778 & 1023u);
                                                                if (_e1784 == 0u) {
                                                                    let _e1806 = local_190;
                                                                    let _e1808 = local_245;
                                                                    phi_1717_ = ((_e1808 * f32(_e1806)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1787 = local_189;
                                                                    if (_e1787 == 31u) {
                                                                        let _e1797 = local_190;
                                                                        phi_1714_ = (2139095040u | (_e1797 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1789 = local_189;
                                                                        let _e1793 = local_190;
                                                                        phi_1714_ = (((_e1789 + 112u) << bitcast<u32>(23i)) | (_e1793 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1802 = phi_1714_;
                                                                    let _e1804 = local_245;
                                                                    phi_1717_ = (_e1804 * bitcast<f32>(_e1802));
                                                                }
                                                                let _e1812 = phi_1717_;
                                                                local_191 = _e1812;
                                                                let _e1813 = local_182;
                                                                let _e1815 = (_e1813 >> bitcast<u32>(16i));
                                                                local_246 = select(-1f, 1f, ((_e1815 & 32768u) == 0u));
                                                                let _e1821 = ((_e1815 >> bitcast<u32>(10i)) & 31u);
                                                                local_192 = _e1821;
                                                                local_193 = (_e1815 & 1023u);
                                                                if (_e1821 == 0u) {
                                                                    let _e1843 = local_193;
                                                                    let _e1845 = local_246;
                                                                    phi_1749_ = ((_e1845 * f32(_e1843)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1824 = local_192;
                                                                    if (_e1824 == 31u) {
                                                                        let _e1834 = local_193;
                                                                        phi_1746_ = (2139095040u | (_e1834 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1826 = local_192;
                                                                        let _e1830 = local_193;
                                                                        phi_1746_ = (((_e1826 + 112u) << bitcast<u32>(23i)) | (_e1830 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1839 = phi_1746_;
                                                                    let _e1841 = local_246;
                                                                    phi_1749_ = (_e1841 * bitcast<f32>(_e1839));
                                                                }
                                                                let _e1849 = phi_1749_;
                                                                local_194 = _e1849;
                                                                let _e1850 = local_178;
                                                                let _e1851 = local_118;
                                                                let _e1853 = ((_e1850 + _e1851) * 2u);
                                                                local_195 = _e1853;
                                                                let _e1854 = local_4;
                                                                if (_e1853 < _e1854) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1856 = local_195;
                                                                let _e1859 = global_5.member[_e1856];
                                                                local_196 = _e1859;
                                                                let _e1860 = local_195;
                                                                let _e1861 = (_e1860 + 1u);
                                                                local_197 = _e1861;
                                                                let _e1862 = local_4;
                                                                if (_e1861 < _e1862) {
                                                                } else {
                                                                    phi_2117_ = true;
                                                                    break;
                                                                }
                                                                let _e1864 = local_197;
                                                                let _e1867 = global_5.member[_e1864];
                                                                local_198 = _e1867;
                                                                let _e1868 = local_196;
                                                                let _e1869 = (_e1868 & 65535u);
                                                                local_247 = select(-1f, 1f, ((_e1869 & 32768u) == 0u));
                                                                let _e1875 = ((_e1869 >> bitcast<u32>(10i)) & 31u);
                                                                local_199 = _e1875;
                                                                local_200 = (_e1869 & 1023u);
                                                                if (_e1875 == 0u) {
                                                                    let _e1897 = local_200;
                                                                    let _e1899 = local_247;
                                                                    phi_1802_ = ((_e1899 * f32(_e1897)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1878 = local_199;
                                                                    if (_e1878 == 31u) {
                                                                        let _e1888 = local_200;
                                                                        phi_1799_ = (2139095040u | (_e1888 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1880 = local_199;
                                                                        let _e1884 = local_200;
                                                                        phi_1799_ = (((_e1880 + 112u) << bitcast<u32>(23i)) | (_e1884 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1893 = phi_1799_;
                                                                    let _e1895 = local_247;
                                                                    phi_1802_ = (_e1895 * bitcast<f32>(_e1893));
                                                                }
                                                                let _e1903 = phi_1802_;
                                                                local_201 = _e1903;
                                                                let _e1904 = local_196;
                                                                let _e1906 = (_e1904 >> bitcast<u32>(16i));
                                                                local_248 = select(-1f, 1f, ((_e1906 & 32768u) == 0u));
                                                                let _e1912 = ((_e1906 >> bitcast<u32>(10i)) & 31u);
                                                                local_202 = _e1912;
                                                                local_203 = (_e1906 & 1023u);
                                                                if (_e1912 == 0u) {
                                                                    let _e1934 = local_203;
                                                                    let _e1936 = local_248;
                                                                    phi_1834_ = ((_e1936 * f32(_e1934)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1915 = local_202;
                                                                    if (_e1915 == 31u) {
                                                                        let _e1925 = local_203;
                                                                        phi_1831_ = (2139095040u | (_e1925 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1917 = local_202;
                                                                        let _e1921 = local_203;
                                                                        phi_1831_ = (((_e1917 + 112u) << bitcast<u32>(23i)) | (_e1921 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1930 = phi_1831_;
                                                                    let _e1932 = local_248;
                                                                    phi_1834_ = (_e1932 * bitcast<f32>(_e1930));
                                                                }
                                                                let _e1940 = phi_1834_;
                                                                local_204 = _e1940;
                                                                let _e1941 = local_198;
                                                                let _e1942 = (_e1941 & 65535u);
                                                                local_249 = select(-1f, 1f, ((_e1942 & 32768u) == 0u));
                                                                let _e1948 = ((_e1942 >> bitcast<u32>(10i)) & 31u);
                                                                local_205 = _e1948;
                                                                local_206 = (_e1942 & 1023u);
                                                                if (_e1948 == 0u) {
                                                                    let _e1970 = local_206;
                                                                    let _e1972 = local_249;
                                                                    phi_1866_ = ((_e1972 * f32(_e1970)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1951 = local_205;
                                                                    if (_e1951 == 31u) {
                                                                        let _e1961 = local_206;
                                                                        phi_1863_ = (2139095040u | (_e1961 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1953 = local_205;
                                                                        let _e1957 = local_206;
                                                                        phi_1863_ = (((_e1953 + 112u) << bitcast<u32>(23i)) | (_e1957 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e1966 = phi_1863_;
                                                                    let _e1968 = local_249;
                                                                    phi_1866_ = (_e1968 * bitcast<f32>(_e1966));
                                                                }
                                                                let _e1976 = phi_1866_;
                                                                local_207 = _e1976;
                                                                let _e1977 = local_198;
                                                                let _e1979 = (_e1977 >> bitcast<u32>(16i));
                                                                local_250 = select(-1f, 1f, ((_e1979 & 32768u) == 0u));
                                                                let _e1985 = ((_e1979 >> bitcast<u32>(10i)) & 31u);
                                                                local_208 = _e1985;
                                                                local_209 = (_e1979 & 1023u);
                                                                if (_e1985 == 0u) {
                                                                    let _e2007 = local_209;
                                                                    let _e2009 = local_250;
                                                                    phi_1898_ = ((_e2009 * f32(_e2007)) * 0.000000059604645f);
                                                                } else {
                                                                    let _e1988 = local_208;
                                                                    if (_e1988 == 31u) {
                                                                        let _e1998 = local_209;
                                                                        phi_1895_ = (2139095040u | (_e1998 << bitcast<u32>(13i)));
                                                                    } else {
                                                                        let _e1990 = local_208;
                                                                        let _e1994 = local_209;
                                                                        phi_1895_ = (((_e1990 + 112u) << bitcast<u32>(23i)) | (_e1994 << bitcast<u32>(13i)));
                                                                    }
                                                                    let _e2003 = phi_1895_;
                                                                    let _e2005 = local_250;
                                                                    phi_1898_ = (_e2005 * bitcast<f32>(_e2003));
                                                                }
                                                                let _e2013 = phi_1898_;
                                                                let _e2014 = local_201;
                                                                let _e2015 = local_185;
                                                                let _e2017 = local_94;
                                                                let _e2019 = local_185;
                                                                let _e2021 = local_204;
                                                                let _e2022 = local_188;
                                                                let _e2024 = local_94;
                                                                let _e2026 = local_188;
                                                                let _e2028 = local_207;
                                                                let _e2029 = local_191;
                                                                let _e2031 = local_94;
                                                                let _e2033 = local_191;
                                                                let _e2035 = local_194;
                                                                let _e2037 = local_94;
                                                                let _e2039 = local_194;
                                                                let _e2041 = local_174;
                                                                let _e2043 = local_93;
                                                                let _e2045 = local_174;
                                                                let _e2047 = local_175;
                                                                let _e2049 = local_93;
                                                                let _e2051 = local_175;
                                                                let _e2053 = local_176;
                                                                let _e2055 = local_93;
                                                                let _e2057 = local_176;
                                                                let _e2059 = local_177;
                                                                let _e2061 = local_93;
                                                                let _e2063 = local_177;
                                                                let _e2065 = local_86;
                                                                let _e2067 = local_86;
                                                                let _e2069 = local_86;
                                                                let _e2071 = local_86;
                                                                let _e2073 = local_83;
                                                                let _e2076 = local_83;
                                                                let _e2079 = local_83;
                                                                let _e2082 = local_83;
                                                                let _e2086 = local_82;
                                                                phi_917_ = (_e2086 + 1u);
                                                                phi_920_ = type_3((_e2073.member + ((_e2045 + (((_e2019 + ((_e2014 - _e2015) * _e2017)) - _e2041) * _e2043)) * _e2065)), (_e2076.member_1 + ((_e2051 + (((_e2026 + ((_e2021 - _e2022) * _e2024)) - _e2047) * _e2049)) * _e2067)), (_e2079.member_2 + ((_e2057 + (((_e2033 + ((_e2028 - _e2029) * _e2031)) - _e2053) * _e2055)) * _e2069)), (_e2082.member_3 + ((_e2063 + (((_e2039 + ((_e2013 - _e2035) * _e2037)) - _e2059) * _e2061)) * _e2071)));
                                                            } else {
                                                                phi_917_ = u32();
                                                                phi_920_ = type_3();
                                                            }
                                                            let _e2089 = phi_917_;
                                                            let _e2091 = phi_920_;
                                                            continue;
                                                            continuing {
                                                                let _e2092 = local_84;
                                                                phi_916_ = _e2089;
                                                                phi_919_ = _e2091;
                                                                phi_2117_ = _e965;
                                                                break if !(_e2092);
                                                            }
                                                        }
                                                        let _e2095 = phi_2117_;
                                                        phi_2223_ = _e2095;
                                                        if _e2095 {
                                                            break;
                                                        }
                                                        let _e2096 = local_80;
                                                        phi_2224_ = _e2095;
                                                        phi_888_ = (_e2096 + 1u);
                                                        let _e2295 = local_257;
                                                        phi_891_ = _e2295;
                                                    } else {
                                                        phi_2224_ = _e965;
                                                        phi_888_ = u32();
                                                        phi_891_ = type_3();
                                                    }
                                                    let _e2099 = phi_2224_;
                                                    let _e2101 = phi_888_;
                                                    let _e2103 = phi_891_;
                                                    continue;
                                                    continuing {
                                                        let _e2104 = local_81;
                                                        phi_2163_ = _e2099;
                                                        phi_887_ = _e2101;
                                                        phi_890_ = _e2103;
                                                        phi_2223_ = _e2099;
                                                        break if !(_e2104);
                                                    }
                                                }
                                                let _e2107 = phi_2223_;
                                                phi_2225_ = _e2107;
                                                if _e2107 {
                                                    break;
                                                }
                                                let _e2108 = local_77;
                                                phi_2226_ = _e2107;
                                                phi_871_ = (_e2108 + 1u);
                                                let _e2301 = local_258;
                                                phi_874_ = _e2301;
                                            } else {
                                                phi_2226_ = _e957;
                                                phi_871_ = u32();
                                                phi_874_ = type_3();
                                            }
                                            let _e2111 = phi_2226_;
                                            let _e2113 = phi_871_;
                                            let _e2115 = phi_874_;
                                            continue;
                                            continuing {
                                                let _e2116 = local_79;
                                                phi_2164_ = _e2111;
                                                phi_870_ = _e2113;
                                                phi_873_ = _e2115;
                                                phi_2225_ = _e2111;
                                                break if !(_e2116);
                                            }
                                        }
                                        let _e2119 = phi_2225_;
                                        if _e2119 {
                                            break;
                                        }
                                        let _e2120 = local_78;
                                        let _e2122 = local_78;
                                        let _e2124 = local_78;
                                        let _e2126 = local_78;
                                        let _e2305 = local_259;
                                        phi_1951_ = _e2305;
                                    }
                                    let _e2129 = phi_1951_;
                                    phi_1952_ = _e2129;
                                    phi_1953_ = _e774;
                                }
                                let _e2131 = phi_1952_;
                                let _e2133 = phi_1953_;
                                if _e2133 {
                                    phi_1957_ = type_3(1f, 1f, 1f, 1f);
                                } else {
                                    phi_1957_ = _e2131;
                                }
                                let _e2135 = phi_1957_;
                                phi_1958_ = _e2135;
                            }
                            let _e2137 = phi_1958_;
                            phi_1959_ = _e2137;
                            phi_1960_ = _e738;
                        }
                        let _e2139 = phi_1959_;
                        let _e2141 = phi_1960_;
                        if _e2141 {
                            phi_1964_ = type_3(1f, 1f, 1f, 1f);
                        } else {
                            phi_1964_ = _e2139;
                        }
                        let _e2143 = phi_1964_;
                        let _e2145 = local_61;
                        let _e2147 = local_48;
                        local_210 = ((_e2145 * _e2143.member_3) * _e2147);
                        let _e2149 = local_22;
                        if ((_e2149 & 4u) == 0u) {
                            let _e2163 = local_210;
                            phi_1985_ = (_e2163 > 0f);
                        } else {
                            let _e2152 = local_20;
                            let _e2153 = (_e2152 + 7u);
                            local_211 = _e2153;
                            let _e2154 = local_2;
                            if (_e2153 < _e2154) {
                            } else {
                                break;
                            }
                            let _e2156 = local_211;
                            let _e2159 = global_3.member[_e2156];
                            let _e2161 = local_210;
                            phi_1985_ = (_e2161 >= bitcast<f32>(_e2159));
                        }
                        let _e2166 = phi_1985_;
                        phi_1986_ = _e2166;
                    }
                    let _e2168 = phi_1986_;
                    phi_1987_ = _e2168;
                } else {
                    phi_1987_ = bool();
                }
                let _e2170 = phi_1987_;
                let _e2171 = local_11;
                phi_1989_ = _e2170;
                phi_1990_ = select(true, false, _e2171);
            } else {
                phi_1989_ = bool();
                phi_1990_ = true;
            }
            let _e2174 = phi_1989_;
            let _e2176 = phi_1990_;
            if select(_e2174, false, _e2176) {
            } else {
                discard;
            }
            let _e2178 = local_9;
            let _e2181 = local_8;
            let _e2182 = local_6;
            let _e2183 = local_7;
            global_2 = vec4<f32>(f32((_e2178 + 1u)), _e2181, _e2182, _e2183);
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
