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
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_17 {
    member: type_16,
    member_1: type_5,
    member_2: f32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
}

struct type_18 {
    member: type_17,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_7;
var<immediate> global_5: type_18;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_7;
var<private> global_8: u32 = 2143289344u;
var<private> global_9: u32 = 2139095040u;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: u32;
    var local_8: bool;
    var local_9: u32;
    var local_10: u32;
    var local_11: f32;
    var local_12: u32;
    var local_13: bool;
    var local_14: f32;
    var local_15: bool;
    var local_16: f32;
    var local_17: f32;
    var local_18: f32;
    var local_19: bool;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
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
    var local_35: f32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: f32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: f32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: f32;
    var local_48: u32;
    var local_49: f32;
    var local_50: u32;
    var local_51: f32;
    var local_52: u32;
    var local_53: f32;
    var local_54: u32;
    var local_55: array<f32, 4>;
    var local_56: u32;
    var local_57: u32;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: u32;
    var local_62: u32;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: u32;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: f32;
    var local_72: u32;
    var local_73: u32;
    var local_74: u32;
    var local_75: f32;
    var local_76: u32;
    var local_77: u32;
    var local_78: u32;
    var local_79: f32;
    var local_80: u32;
    var local_81: u32;
    var local_82: u32;
    var local_83: f32;
    var local_84: u32;
    var local_85: f32;
    var local_86: u32;
    var local_87: f32;
    var local_88: u32;
    var local_89: f32;
    var local_90: u32;
    var local_91: bool;
    var local_92: array<f32, 4>;
    var local_93: bool;
    var local_94: bool;
    var local_95: bool;
    var local_96: array<f32, 3>;
    var local_97: f32;
    var local_98: u32;
    var local_99: u32;
    var local_100: u32;
    var local_101: u32;
    var local_102: u32;
    var local_103: u32;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: f32;
    var local_109: f32;
    var local_110: bool;
    var local_111: f32;
    var local_112: u32;
    var local_113: f32;
    var local_114: f32;
    var local_115: f32;
    var local_116: f32;
    var local_117: f32;
    var local_118: f32;
    var local_119: f32;
    var local_120: f32;
    var local_121: f32;
    var local_122: f32;
    var local_123: bool;
    var local_124: f32;
    var local_125: f32;
    var local_126: f32;
    var phi_125_: u32;
    var phi_166_: f32;
    var phi_211_: f32;
    var phi_212_: f32;
    var phi_232_: f32;
    var phi_233_: f32;
    var phi_234_: f32;
    var phi_235_: f32;
    var phi_241_: f32;
    var phi_242_: f32;
    var phi_244_: f32;
    var phi_245_: bool;
    var phi_250_: f32;
    var phi_260_: bool;
    var phi_322_: f32;
    var phi_323_: f32;
    var phi_324_: f32;
    var phi_325_: f32;
    var phi_326_: bool;
    var phi_365_: f32;
    var phi_366_: f32;
    var phi_367_: f32;
    var phi_368_: f32;
    var phi_369_: bool;
    var phi_407_: f32;
    var phi_408_: f32;
    var phi_409_: f32;
    var phi_410_: f32;
    var phi_411_: bool;
    var phi_473_: f32;
    var phi_488_: f32;
    var phi_489_: f32;
    var phi_490_: f32;
    var phi_491_: f32;
    var phi_492_: bool;
    var phi_514_: f32;
    var phi_529_: f32;
    var phi_530_: f32;
    var phi_531_: f32;
    var phi_532_: f32;
    var phi_533_: bool;
    var phi_555_: f32;
    var phi_570_: f32;
    var phi_571_: f32;
    var phi_572_: f32;
    var phi_573_: f32;
    var phi_574_: bool;
    var phi_596_: f32;
    var phi_611_: f32;
    var phi_612_: f32;
    var phi_613_: f32;
    var phi_614_: f32;
    var phi_615_: bool;
    var phi_694_: array<f32, 4>;
    var phi_695_: array<f32, 4>;
    var phi_704_: array<f32, 3>;
    var phi_705_: f32;
    var phi_762_: f32;
    var phi_763_: f32;
    var phi_764_: f32;
    var phi_765_: f32;
    var phi_766_: bool;
    var phi_805_: f32;
    var phi_806_: f32;
    var phi_807_: f32;
    var phi_808_: f32;
    var phi_809_: bool;
    var phi_847_: f32;
    var phi_848_: f32;
    var phi_849_: f32;
    var phi_850_: f32;
    var phi_851_: bool;
    var phi_913_: f32;
    var phi_928_: f32;
    var phi_929_: f32;
    var phi_930_: f32;
    var phi_931_: f32;
    var phi_932_: bool;
    var phi_954_: f32;
    var phi_969_: f32;
    var phi_970_: f32;
    var phi_971_: f32;
    var phi_972_: f32;
    var phi_973_: bool;
    var phi_995_: f32;
    var phi_1010_: f32;
    var phi_1011_: f32;
    var phi_1012_: f32;
    var phi_1013_: f32;
    var phi_1014_: bool;
    var phi_1036_: f32;
    var phi_1051_: f32;
    var phi_1052_: f32;
    var phi_1053_: f32;
    var phi_1054_: f32;
    var phi_1055_: bool;
    var phi_1134_: array<f32, 4>;
    var phi_1135_: array<f32, 4>;
    var phi_1136_: array<f32, 3>;
    var phi_1137_: f32;
    var phi_1138_: bool;
    var phi_1139_: array<f32, 4>;
    var phi_1140_: bool;
    var phi_1141_: bool;
    var phi_1171_: array<f32, 3>;
    var phi_1173_: array<f32, 3>;
    var phi_1174_: f32;
    var phi_1277_: bool;
    var phi_1304_: f32;
    var phi_1306_: f32;
    var phi_1307_: bool;
    var phi_1308_: f32;
    var phi_1309_: f32;
    var phi_1310_: bool;
    var phi_1311_: f32;
    var phi_1312_: f32;
    var phi_1313_: bool;
    var phi_1314_: bool;
    var phi_1315_: f32;
    var phi_1316_: f32;
    var phi_1317_: bool;
    var phi_1318_: bool;
    var phi_1336_: f32;
    var phi_1337_: f32;
    var phi_126_: u32;
    var phi_1368_: bool;

    let _e181 = global_8;
    local_125 = bitcast<f32>(_e181);
    let _e183 = global_9;
    let _e184 = bitcast<f32>(_e183);
    local_126 = _e184;
    switch bitcast<i32>(0u) {
        default: {
            let _e186 = global;
            local = _e186;
            let _e187 = global_1;
            let _e188 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e202 = global_5.member.member.member;
            let _e206 = global_5.member.member.member_1;
            local_5 = (_e202 * _e206);
            local_6 = (_e188.x * 256u);
            phi_125_ = (_e187.x * 256u);
            loop {
                let _e211 = phi_125_;
                local_7 = _e211;
                let _e212 = local_7;
                let _e213 = local_5;
                let _e214 = (_e212 < _e213);
                local_8 = _e214;
                if _e214 {
                    let _e215 = local_7;
                    let _e216 = local;
                    let _e217 = (_e215 + _e216);
                    local_9 = _e217;
                    let _e218 = local_5;
                    if (_e217 < _e218) {
                        let _e220 = local_9;
                        let _e221 = local_2;
                        if (_e220 < _e221) {
                        } else {
                            phi_1368_ = true;
                            break;
                        }
                        let _e223 = local_9;
                        let _e226 = global_3.member[_e223];
                        local_10 = _e226;
                        let _e230 = global_5.member.member.member_7;
                        if (_e230 == 1u) {
                            let _e232 = local_10;
                            phi_166_ = (f32((_e232 & 16777215u)) * 0.00000005960465f);
                        } else {
                            let _e236 = local_10;
                            phi_166_ = bitcast<f32>(_e236);
                        }
                        let _e239 = phi_166_;
                        local_11 = _e239;
                        let _e243 = global_5.member.member.member_3;
                        local_12 = _e243;
                        if (_e243 == 0u) {
                            phi_250_ = _e239;
                        } else {
                            let _e245 = local_11;
                            if (_e245 >= 0f) {
                                let _e247 = local_11;
                                let _e248 = (_e247 <= 1f);
                                local_13 = _e248;
                                if _e248 {
                                    let _e252 = global_5.member.member.member_5;
                                    local_14 = _e252;
                                    let _e253 = local_126;
                                    local_15 = (_e252 == _e253);
                                    let _e255 = local_12;
                                    if (_e255 == 1u) {
                                        let _e257 = local_15;
                                        if _e257 {
                                            let _e261 = global_5.member.member.member_4;
                                            let _e262 = local_11;
                                            phi_211_ = (1f - _e262);
                                            phi_212_ = _e261;
                                        } else {
                                            let _e267 = global_5.member.member.member_4;
                                            let _e268 = local_14;
                                            let _e270 = local_14;
                                            let _e272 = local_11;
                                            let _e274 = local_14;
                                            phi_211_ = (_e274 - (_e272 * (_e270 - _e267)));
                                            phi_212_ = (_e267 * _e268);
                                        }
                                        let _e277 = phi_211_;
                                        let _e279 = phi_212_;
                                        phi_234_ = _e277;
                                        phi_235_ = _e279;
                                    } else {
                                        let _e280 = local_15;
                                        if _e280 {
                                            let _e284 = global_5.member.member.member_4;
                                            phi_232_ = _e239;
                                            phi_233_ = _e284;
                                        } else {
                                            let _e288 = global_5.member.member.member_4;
                                            let _e289 = local_14;
                                            let _e291 = local_14;
                                            let _e293 = local_11;
                                            phi_232_ = (_e288 + (_e293 * (_e291 - _e288)));
                                            phi_233_ = (_e288 * _e289);
                                        }
                                        let _e297 = phi_232_;
                                        let _e299 = phi_233_;
                                        phi_234_ = _e297;
                                        phi_235_ = _e299;
                                    }
                                    let _e301 = phi_234_;
                                    let _e303 = phi_235_;
                                    local_16 = _e301;
                                    local_17 = _e303;
                                    if (_e301 <= 0f) {
                                        phi_241_ = _e184;
                                    } else {
                                        let _e305 = local_17;
                                        let _e306 = local_16;
                                        phi_241_ = (_e305 / _e306);
                                    }
                                    let _e309 = phi_241_;
                                    phi_242_ = _e309;
                                } else {
                                    phi_242_ = f32();
                                }
                                let _e311 = phi_242_;
                                let _e312 = local_13;
                                phi_244_ = _e311;
                                phi_245_ = select(true, false, _e312);
                            } else {
                                phi_244_ = f32();
                                phi_245_ = true;
                            }
                            let _e315 = phi_244_;
                            let _e317 = phi_245_;
                            let _e318 = local_125;
                            phi_250_ = select(_e315, _e318, _e317);
                        }
                        let _e321 = phi_250_;
                        local_18 = _e321;
                        let _e322 = local_12;
                        if (_e322 == 2u) {
                            let _e324 = local_11;
                            phi_260_ = (_e324 > 0f);
                        } else {
                            let _e326 = local_11;
                            phi_260_ = (_e326 < 1f);
                        }
                        let _e329 = phi_260_;
                        if _e329 {
                            let _e330 = local_18;
                            let _e333 = ((bitcast<u32>(_e330) & 2139095040u) != 2139095040u);
                            local_19 = _e333;
                            let _e337 = global_5.member.member.member_2;
                            local_20 = _e337;
                            if (_e337 == 1u) {
                                let _e339 = local_9;
                                let _e340 = local_1;
                                if (_e339 < _e340) {
                                } else {
                                    phi_1368_ = true;
                                    break;
                                }
                                let _e342 = local_9;
                                let _e345 = global_4.member[_e342];
                                local_21 = _e345;
                                let _e346 = (_e345 & 2047u);
                                let _e349 = ((_e346 >> bitcast<u32>(6u)) & 31u);
                                local_22 = _e349;
                                local_23 = (_e346 & 63u);
                                if (_e349 == 0u) {
                                    let _e352 = local_23;
                                    phi_324_ = (f32(_e352) * 0.0000009536743f);
                                    phi_325_ = f32();
                                    phi_326_ = true;
                                } else {
                                    let _e355 = local_22;
                                    let _e356 = (_e355 == 31u);
                                    if _e356 {
                                        let _e357 = local_23;
                                        phi_322_ = bitcast<f32>((2139095040u | (_e357 << bitcast<u32>(17u))));
                                        phi_323_ = f32();
                                    } else {
                                        let _e362 = local_22;
                                        let _e366 = local_23;
                                        phi_322_ = f32();
                                        phi_323_ = bitcast<f32>((((_e362 + 112u) << bitcast<u32>(23i)) | (_e366 << bitcast<u32>(17u))));
                                    }
                                    let _e372 = phi_322_;
                                    let _e374 = phi_323_;
                                    phi_324_ = _e372;
                                    phi_325_ = _e374;
                                    phi_326_ = _e356;
                                }
                                let _e376 = phi_324_;
                                let _e378 = phi_325_;
                                let _e380 = phi_326_;
                                local_113 = select(_e378, _e376, _e380);
                                let _e382 = local_21;
                                let _e385 = ((_e382 >> bitcast<u32>(11i)) & 2047u);
                                let _e388 = ((_e385 >> bitcast<u32>(6u)) & 31u);
                                local_24 = _e388;
                                local_25 = (_e385 & 63u);
                                if (_e388 == 0u) {
                                    let _e391 = local_25;
                                    phi_367_ = (f32(_e391) * 0.0000009536743f);
                                    phi_368_ = f32();
                                    phi_369_ = true;
                                } else {
                                    let _e394 = local_24;
                                    let _e395 = (_e394 == 31u);
                                    if _e395 {
                                        let _e396 = local_25;
                                        phi_365_ = bitcast<f32>((2139095040u | (_e396 << bitcast<u32>(17u))));
                                        phi_366_ = f32();
                                    } else {
                                        let _e401 = local_24;
                                        let _e405 = local_25;
                                        phi_365_ = f32();
                                        phi_366_ = bitcast<f32>((((_e401 + 112u) << bitcast<u32>(23i)) | (_e405 << bitcast<u32>(17u))));
                                    }
                                    let _e411 = phi_365_;
                                    let _e413 = phi_366_;
                                    phi_367_ = _e411;
                                    phi_368_ = _e413;
                                    phi_369_ = _e395;
                                }
                                let _e415 = phi_367_;
                                let _e417 = phi_368_;
                                let _e419 = phi_369_;
                                local_114 = select(_e417, _e415, _e419);
                                let _e421 = local_21;
                                let _e423 = (_e421 >> bitcast<u32>(22i));
                                let _e426 = ((_e423 >> bitcast<u32>(5u)) & 31u);
                                local_26 = _e426;
                                local_27 = (_e423 & 31u);
                                if (_e426 == 0u) {
                                    let _e429 = local_27;
                                    phi_409_ = (f32(_e429) * 0.0000019073486f);
                                    phi_410_ = f32();
                                    phi_411_ = true;
                                } else {
                                    let _e432 = local_26;
                                    let _e433 = (_e432 == 31u);
                                    if _e433 {
                                        let _e434 = local_27;
                                        phi_407_ = bitcast<f32>((2139095040u | (_e434 << bitcast<u32>(18u))));
                                        phi_408_ = f32();
                                    } else {
                                        let _e439 = local_26;
                                        let _e443 = local_27;
                                        phi_407_ = f32();
                                        phi_408_ = bitcast<f32>((((_e439 + 112u) << bitcast<u32>(23i)) | (_e443 << bitcast<u32>(18u))));
                                    }
                                    let _e449 = phi_407_;
                                    let _e451 = phi_408_;
                                    phi_409_ = _e449;
                                    phi_410_ = _e451;
                                    phi_411_ = _e433;
                                }
                                let _e453 = phi_409_;
                                let _e455 = phi_410_;
                                let _e457 = phi_411_;
                                let _e459 = local_113;
                                let _e460 = local_114;
                                phi_695_ = array<f32, 4>(_e459, _e460, select(_e455, _e453, _e457), 1f);
                            } else {
                                let _e462 = local_20;
                                if (_e462 == 2u) {
                                    let _e464 = local_9;
                                    let _e465 = (2u * _e464);
                                    local_28 = _e465;
                                    let _e466 = local_1;
                                    if (_e465 < _e466) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e468 = local_28;
                                    let _e471 = global_4.member[_e468];
                                    local_29 = _e471;
                                    let _e472 = local_28;
                                    let _e473 = (_e472 + 1u);
                                    local_30 = _e473;
                                    let _e474 = local_1;
                                    if (_e473 < _e474) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e476 = local_30;
                                    let _e479 = global_4.member[_e476];
                                    local_31 = _e479;
                                    let _e480 = local_29;
                                    let _e481 = (_e480 & 65535u);
                                    local_32 = ((_e481 & 32768u) << bitcast<u32>(16i));
                                    let _e487 = ((_e481 >> bitcast<u32>(10i)) & 31u);
                                    local_33 = _e487;
                                    local_34 = (_e481 & 1023u);
                                    if (_e487 == 0u) {
                                        let _e490 = local_34;
                                        let _e491 = f32(_e490);
                                        local_35 = _e491;
                                        let _e493 = local_32;
                                        if (_e493 == 0u) {
                                            phi_473_ = (_e491 * 0.000000059604645f);
                                        } else {
                                            let _e495 = local_35;
                                            phi_473_ = (_e495 * -0.000000059604645f);
                                        }
                                        let _e498 = phi_473_;
                                        phi_490_ = _e498;
                                        phi_491_ = f32();
                                        phi_492_ = true;
                                    } else {
                                        let _e499 = local_33;
                                        let _e500 = (_e499 == 31u);
                                        if _e500 {
                                            let _e501 = local_32;
                                            let _e503 = local_34;
                                            phi_488_ = bitcast<f32>(((_e501 | 2139095040u) | (_e503 << bitcast<u32>(13i))));
                                            phi_489_ = f32();
                                        } else {
                                            let _e508 = local_33;
                                            let _e512 = local_32;
                                            let _e514 = local_34;
                                            phi_488_ = f32();
                                            phi_489_ = bitcast<f32>(((_e512 | ((_e508 + 112u) << bitcast<u32>(23i))) | (_e514 << bitcast<u32>(13i))));
                                        }
                                        let _e520 = phi_488_;
                                        let _e522 = phi_489_;
                                        phi_490_ = _e520;
                                        phi_491_ = _e522;
                                        phi_492_ = _e500;
                                    }
                                    let _e524 = phi_490_;
                                    let _e526 = phi_491_;
                                    let _e528 = phi_492_;
                                    local_115 = select(_e526, _e524, _e528);
                                    let _e530 = local_29;
                                    let _e532 = (_e530 >> bitcast<u32>(16i));
                                    local_36 = ((_e532 & 32768u) << bitcast<u32>(16i));
                                    let _e538 = ((_e532 >> bitcast<u32>(10i)) & 31u);
                                    local_37 = _e538;
                                    local_38 = (_e532 & 1023u);
                                    if (_e538 == 0u) {
                                        let _e541 = local_38;
                                        let _e542 = f32(_e541);
                                        local_39 = _e542;
                                        let _e544 = local_36;
                                        if (_e544 == 0u) {
                                            phi_514_ = (_e542 * 0.000000059604645f);
                                        } else {
                                            let _e546 = local_39;
                                            phi_514_ = (_e546 * -0.000000059604645f);
                                        }
                                        let _e549 = phi_514_;
                                        phi_531_ = _e549;
                                        phi_532_ = f32();
                                        phi_533_ = true;
                                    } else {
                                        let _e550 = local_37;
                                        let _e551 = (_e550 == 31u);
                                        if _e551 {
                                            let _e552 = local_36;
                                            let _e554 = local_38;
                                            phi_529_ = bitcast<f32>(((_e552 | 2139095040u) | (_e554 << bitcast<u32>(13i))));
                                            phi_530_ = f32();
                                        } else {
                                            let _e559 = local_37;
                                            let _e563 = local_36;
                                            let _e565 = local_38;
                                            phi_529_ = f32();
                                            phi_530_ = bitcast<f32>(((_e563 | ((_e559 + 112u) << bitcast<u32>(23i))) | (_e565 << bitcast<u32>(13i))));
                                        }
                                        let _e571 = phi_529_;
                                        let _e573 = phi_530_;
                                        phi_531_ = _e571;
                                        phi_532_ = _e573;
                                        phi_533_ = _e551;
                                    }
                                    let _e575 = phi_531_;
                                    let _e577 = phi_532_;
                                    let _e579 = phi_533_;
                                    local_116 = select(_e577, _e575, _e579);
                                    let _e581 = local_31;
                                    let _e582 = (_e581 & 65535u);
                                    local_40 = ((_e582 & 32768u) << bitcast<u32>(16i));
                                    let _e588 = ((_e582 >> bitcast<u32>(10i)) & 31u);
                                    local_41 = _e588;
                                    local_42 = (_e582 & 1023u);
                                    if (_e588 == 0u) {
                                        let _e591 = local_42;
                                        let _e592 = f32(_e591);
                                        local_43 = _e592;
                                        let _e594 = local_40;
                                        if (_e594 == 0u) {
                                            phi_555_ = (_e592 * 0.000000059604645f);
                                        } else {
                                            let _e596 = local_43;
                                            phi_555_ = (_e596 * -0.000000059604645f);
                                        }
                                        let _e599 = phi_555_;
                                        phi_572_ = _e599;
                                        phi_573_ = f32();
                                        phi_574_ = true;
                                    } else {
                                        let _e600 = local_41;
                                        let _e601 = (_e600 == 31u);
                                        if _e601 {
                                            let _e602 = local_40;
                                            let _e604 = local_42;
                                            phi_570_ = bitcast<f32>(((_e602 | 2139095040u) | (_e604 << bitcast<u32>(13i))));
                                            phi_571_ = f32();
                                        } else {
                                            let _e609 = local_41;
                                            let _e613 = local_40;
                                            let _e615 = local_42;
                                            phi_570_ = f32();
                                            phi_571_ = bitcast<f32>(((_e613 | ((_e609 + 112u) << bitcast<u32>(23i))) | (_e615 << bitcast<u32>(13i))));
                                        }
                                        let _e621 = phi_570_;
                                        let _e623 = phi_571_;
                                        phi_572_ = _e621;
                                        phi_573_ = _e623;
                                        phi_574_ = _e601;
                                    }
                                    let _e625 = phi_572_;
                                    let _e627 = phi_573_;
                                    let _e629 = phi_574_;
                                    local_117 = select(_e627, _e625, _e629);
                                    let _e631 = local_31;
                                    let _e633 = (_e631 >> bitcast<u32>(16i));
                                    local_44 = ((_e633 & 32768u) << bitcast<u32>(16i));
                                    let _e639 = ((_e633 >> bitcast<u32>(10i)) & 31u);
                                    local_45 = _e639;
                                    local_46 = (_e633 & 1023u);
                                    if (_e639 == 0u) {
                                        let _e642 = local_46;
                                        let _e643 = f32(_e642);
                                        local_47 = _e643;
                                        let _e645 = local_44;
                                        if (_e645 == 0u) {
                                            phi_596_ = (_e643 * 0.000000059604645f);
                                        } else {
                                            let _e647 = local_47;
                                            phi_596_ = (_e647 * -0.000000059604645f);
                                        }
                                        let _e650 = phi_596_;
                                        phi_613_ = _e650;
                                        phi_614_ = f32();
                                        phi_615_ = true;
                                    } else {
                                        let _e651 = local_45;
                                        let _e652 = (_e651 == 31u);
                                        if _e652 {
                                            let _e653 = local_44;
                                            let _e655 = local_46;
                                            phi_611_ = bitcast<f32>(((_e653 | 2139095040u) | (_e655 << bitcast<u32>(13i))));
                                            phi_612_ = f32();
                                        } else {
                                            let _e660 = local_45;
                                            let _e664 = local_44;
                                            let _e666 = local_46;
                                            phi_611_ = f32();
                                            phi_612_ = bitcast<f32>(((_e664 | ((_e660 + 112u) << bitcast<u32>(23i))) | (_e666 << bitcast<u32>(13i))));
                                        }
                                        let _e672 = phi_611_;
                                        let _e674 = phi_612_;
                                        phi_613_ = _e672;
                                        phi_614_ = _e674;
                                        phi_615_ = _e652;
                                    }
                                    let _e676 = phi_613_;
                                    let _e678 = phi_614_;
                                    let _e680 = phi_615_;
                                    let _e682 = local_115;
                                    let _e683 = local_116;
                                    let _e684 = local_117;
                                    phi_694_ = array<f32, 4>(_e682, _e683, _e684, select(_e678, _e676, _e680));
                                } else {
                                    let _e686 = local_9;
                                    let _e687 = (4u * _e686);
                                    local_48 = _e687;
                                    let _e688 = local_1;
                                    if (_e687 < _e688) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e690 = local_48;
                                    let _e693 = global_4.member[_e690];
                                    local_49 = bitcast<f32>(_e693);
                                    let _e695 = local_48;
                                    let _e696 = (_e695 + 1u);
                                    local_50 = _e696;
                                    let _e697 = local_1;
                                    if (_e696 < _e697) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e699 = local_50;
                                    let _e702 = global_4.member[_e699];
                                    local_51 = bitcast<f32>(_e702);
                                    let _e704 = local_48;
                                    let _e705 = (_e704 + 2u);
                                    local_52 = _e705;
                                    let _e706 = local_1;
                                    if (_e705 < _e706) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e708 = local_52;
                                    let _e711 = global_4.member[_e708];
                                    local_53 = bitcast<f32>(_e711);
                                    let _e713 = local_48;
                                    let _e714 = (_e713 + 3u);
                                    local_54 = _e714;
                                    let _e715 = local_1;
                                    if (_e714 < _e715) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e717 = local_54;
                                    let _e720 = global_4.member[_e717];
                                    let _e722 = local_49;
                                    let _e723 = local_51;
                                    let _e724 = local_53;
                                    phi_694_ = array<f32, 4>(_e722, _e723, _e724, bitcast<f32>(_e720));
                                }
                                let _e727 = phi_694_;
                                phi_695_ = _e727;
                            }
                            let _e729 = phi_695_;
                            local_55 = _e729;
                            let _e730 = local_19;
                            if _e730 {
                                let _e731 = local_55;
                                let _e733 = local_55;
                                let _e735 = local_55;
                                let _e738 = local_55;
                                phi_704_ = array<f32, 3>(_e731[0], _e733[1], _e735[2]);
                                phi_705_ = _e738[3];
                            } else {
                                phi_704_ = array<f32, 3>();
                                phi_705_ = f32();
                            }
                            let _e741 = phi_704_;
                            let _e743 = phi_705_;
                            let _e744 = local_19;
                            phi_1136_ = _e741;
                            phi_1137_ = _e743;
                            phi_1138_ = _e333;
                            phi_1139_ = _e729;
                            phi_1140_ = _e333;
                            phi_1141_ = select(true, false, _e744);
                        } else {
                            let _e749 = global_5.member.member.member_2;
                            local_56 = _e749;
                            if (_e749 == 1u) {
                                let _e751 = local_9;
                                let _e752 = local_1;
                                if (_e751 < _e752) {
                                } else {
                                    phi_1368_ = true;
                                    break;
                                }
                                let _e754 = local_9;
                                let _e757 = global_4.member[_e754];
                                local_57 = _e757;
                                let _e758 = (_e757 & 2047u);
                                let _e761 = ((_e758 >> bitcast<u32>(6u)) & 31u);
                                local_58 = _e761;
                                local_59 = (_e758 & 63u);
                                if (_e761 == 0u) {
                                    let _e764 = local_59;
                                    phi_764_ = (f32(_e764) * 0.0000009536743f);
                                    phi_765_ = f32();
                                    phi_766_ = true;
                                } else {
                                    let _e767 = local_58;
                                    let _e768 = (_e767 == 31u);
                                    if _e768 {
                                        let _e769 = local_59;
                                        phi_762_ = bitcast<f32>((2139095040u | (_e769 << bitcast<u32>(17u))));
                                        phi_763_ = f32();
                                    } else {
                                        let _e774 = local_58;
                                        let _e778 = local_59;
                                        phi_762_ = f32();
                                        phi_763_ = bitcast<f32>((((_e774 + 112u) << bitcast<u32>(23i)) | (_e778 << bitcast<u32>(17u))));
                                    }
                                    let _e784 = phi_762_;
                                    let _e786 = phi_763_;
                                    phi_764_ = _e784;
                                    phi_765_ = _e786;
                                    phi_766_ = _e768;
                                }
                                let _e788 = phi_764_;
                                let _e790 = phi_765_;
                                let _e792 = phi_766_;
                                local_118 = select(_e790, _e788, _e792);
                                let _e794 = local_57;
                                let _e797 = ((_e794 >> bitcast<u32>(11i)) & 2047u);
                                let _e800 = ((_e797 >> bitcast<u32>(6u)) & 31u);
                                local_60 = _e800;
                                local_61 = (_e797 & 63u);
                                if (_e800 == 0u) {
                                    let _e803 = local_61;
                                    phi_807_ = (f32(_e803) * 0.0000009536743f);
                                    phi_808_ = f32();
                                    phi_809_ = true;
                                } else {
                                    let _e806 = local_60;
                                    let _e807 = (_e806 == 31u);
                                    if _e807 {
                                        let _e808 = local_61;
                                        phi_805_ = bitcast<f32>((2139095040u | (_e808 << bitcast<u32>(17u))));
                                        phi_806_ = f32();
                                    } else {
                                        let _e813 = local_60;
                                        let _e817 = local_61;
                                        phi_805_ = f32();
                                        phi_806_ = bitcast<f32>((((_e813 + 112u) << bitcast<u32>(23i)) | (_e817 << bitcast<u32>(17u))));
                                    }
                                    let _e823 = phi_805_;
                                    let _e825 = phi_806_;
                                    phi_807_ = _e823;
                                    phi_808_ = _e825;
                                    phi_809_ = _e807;
                                }
                                let _e827 = phi_807_;
                                let _e829 = phi_808_;
                                let _e831 = phi_809_;
                                local_119 = select(_e829, _e827, _e831);
                                let _e833 = local_57;
                                let _e835 = (_e833 >> bitcast<u32>(22i));
                                let _e838 = ((_e835 >> bitcast<u32>(5u)) & 31u);
                                local_62 = _e838;
                                local_63 = (_e835 & 31u);
                                if (_e838 == 0u) {
                                    let _e841 = local_63;
                                    phi_849_ = (f32(_e841) * 0.0000019073486f);
                                    phi_850_ = f32();
                                    phi_851_ = true;
                                } else {
                                    let _e844 = local_62;
                                    let _e845 = (_e844 == 31u);
                                    if _e845 {
                                        let _e846 = local_63;
                                        phi_847_ = bitcast<f32>((2139095040u | (_e846 << bitcast<u32>(18u))));
                                        phi_848_ = f32();
                                    } else {
                                        let _e851 = local_62;
                                        let _e855 = local_63;
                                        phi_847_ = f32();
                                        phi_848_ = bitcast<f32>((((_e851 + 112u) << bitcast<u32>(23i)) | (_e855 << bitcast<u32>(18u))));
                                    }
                                    let _e861 = phi_847_;
                                    let _e863 = phi_848_;
                                    phi_849_ = _e861;
                                    phi_850_ = _e863;
                                    phi_851_ = _e845;
                                }
                                let _e865 = phi_849_;
                                let _e867 = phi_850_;
                                let _e869 = phi_851_;
                                let _e871 = local_118;
                                let _e872 = local_119;
                                phi_1135_ = array<f32, 4>(_e871, _e872, select(_e867, _e865, _e869), 1f);
                            } else {
                                let _e874 = local_56;
                                if (_e874 == 2u) {
                                    let _e876 = local_9;
                                    let _e877 = (2u * _e876);
                                    local_64 = _e877;
                                    let _e878 = local_1;
                                    if (_e877 < _e878) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e880 = local_64;
                                    let _e883 = global_4.member[_e880];
                                    local_65 = _e883;
                                    let _e884 = local_64;
                                    let _e885 = (_e884 + 1u);
                                    local_66 = _e885;
                                    let _e886 = local_1;
                                    if (_e885 < _e886) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e888 = local_66;
                                    let _e891 = global_4.member[_e888];
                                    local_67 = _e891;
                                    let _e892 = local_65;
                                    let _e893 = (_e892 & 65535u);
                                    local_68 = ((_e893 & 32768u) << bitcast<u32>(16i));
                                    let _e899 = ((_e893 >> bitcast<u32>(10i)) & 31u);
                                    local_69 = _e899;
                                    local_70 = (_e893 & 1023u);
                                    if (_e899 == 0u) {
                                        let _e902 = local_70;
                                        let _e903 = f32(_e902);
                                        local_71 = _e903;
                                        let _e905 = local_68;
                                        if (_e905 == 0u) {
                                            phi_913_ = (_e903 * 0.000000059604645f);
                                        } else {
                                            let _e907 = local_71;
                                            phi_913_ = (_e907 * -0.000000059604645f);
                                        }
                                        let _e910 = phi_913_;
                                        phi_930_ = _e910;
                                        phi_931_ = f32();
                                        phi_932_ = true;
                                    } else {
                                        let _e911 = local_69;
                                        let _e912 = (_e911 == 31u);
                                        if _e912 {
                                            let _e913 = local_68;
                                            let _e915 = local_70;
                                            phi_928_ = bitcast<f32>(((_e913 | 2139095040u) | (_e915 << bitcast<u32>(13i))));
                                            phi_929_ = f32();
                                        } else {
                                            let _e920 = local_69;
                                            let _e924 = local_68;
                                            let _e926 = local_70;
                                            phi_928_ = f32();
                                            phi_929_ = bitcast<f32>(((_e924 | ((_e920 + 112u) << bitcast<u32>(23i))) | (_e926 << bitcast<u32>(13i))));
                                        }
                                        let _e932 = phi_928_;
                                        let _e934 = phi_929_;
                                        phi_930_ = _e932;
                                        phi_931_ = _e934;
                                        phi_932_ = _e912;
                                    }
                                    let _e936 = phi_930_;
                                    let _e938 = phi_931_;
                                    let _e940 = phi_932_;
                                    local_120 = select(_e938, _e936, _e940);
                                    let _e942 = local_65;
                                    let _e944 = (_e942 >> bitcast<u32>(16i));
                                    local_72 = ((_e944 & 32768u) << bitcast<u32>(16i));
                                    let _e950 = ((_e944 >> bitcast<u32>(10i)) & 31u);
                                    local_73 = _e950;
                                    local_74 = (_e944 & 1023u);
                                    if (_e950 == 0u) {
                                        let _e953 = local_74;
                                        let _e954 = f32(_e953);
                                        local_75 = _e954;
                                        let _e956 = local_72;
                                        if (_e956 == 0u) {
                                            phi_954_ = (_e954 * 0.000000059604645f);
                                        } else {
                                            let _e958 = local_75;
                                            phi_954_ = (_e958 * -0.000000059604645f);
                                        }
                                        let _e961 = phi_954_;
                                        phi_971_ = _e961;
                                        phi_972_ = f32();
                                        phi_973_ = true;
                                    } else {
                                        let _e962 = local_73;
                                        let _e963 = (_e962 == 31u);
                                        if _e963 {
                                            let _e964 = local_72;
                                            let _e966 = local_74;
                                            phi_969_ = bitcast<f32>(((_e964 | 2139095040u) | (_e966 << bitcast<u32>(13i))));
                                            phi_970_ = f32();
                                        } else {
                                            let _e971 = local_73;
                                            let _e975 = local_72;
                                            let _e977 = local_74;
                                            phi_969_ = f32();
                                            phi_970_ = bitcast<f32>(((_e975 | ((_e971 + 112u) << bitcast<u32>(23i))) | (_e977 << bitcast<u32>(13i))));
                                        }
                                        let _e983 = phi_969_;
                                        let _e985 = phi_970_;
                                        phi_971_ = _e983;
                                        phi_972_ = _e985;
                                        phi_973_ = _e963;
                                    }
                                    let _e987 = phi_971_;
                                    let _e989 = phi_972_;
                                    let _e991 = phi_973_;
                                    local_121 = select(_e989, _e987, _e991);
                                    let _e993 = local_67;
                                    let _e994 = (_e993 & 65535u);
                                    local_76 = ((_e994 & 32768u) << bitcast<u32>(16i));
                                    let _e1000 = ((_e994 >> bitcast<u32>(10i)) & 31u);
                                    local_77 = _e1000;
                                    local_78 = (_e994 & 1023u);
                                    if (_e1000 == 0u) {
                                        let _e1003 = local_78;
                                        let _e1004 = f32(_e1003);
                                        local_79 = _e1004;
                                        let _e1006 = local_76;
                                        if (_e1006 == 0u) {
                                            phi_995_ = (_e1004 * 0.000000059604645f);
                                        } else {
                                            let _e1008 = local_79;
                                            phi_995_ = (_e1008 * -0.000000059604645f);
                                        }
                                        let _e1011 = phi_995_;
                                        phi_1012_ = _e1011;
                                        phi_1013_ = f32();
                                        phi_1014_ = true;
                                    } else {
                                        let _e1012 = local_77;
                                        let _e1013 = (_e1012 == 31u);
                                        if _e1013 {
                                            let _e1014 = local_76;
                                            let _e1016 = local_78;
                                            phi_1010_ = bitcast<f32>(((_e1014 | 2139095040u) | (_e1016 << bitcast<u32>(13i))));
                                            phi_1011_ = f32();
                                        } else {
                                            let _e1021 = local_77;
                                            let _e1025 = local_76;
                                            let _e1027 = local_78;
                                            phi_1010_ = f32();
                                            phi_1011_ = bitcast<f32>(((_e1025 | ((_e1021 + 112u) << bitcast<u32>(23i))) | (_e1027 << bitcast<u32>(13i))));
                                        }
                                        let _e1033 = phi_1010_;
                                        let _e1035 = phi_1011_;
                                        phi_1012_ = _e1033;
                                        phi_1013_ = _e1035;
                                        phi_1014_ = _e1013;
                                    }
                                    let _e1037 = phi_1012_;
                                    let _e1039 = phi_1013_;
                                    let _e1041 = phi_1014_;
                                    local_122 = select(_e1039, _e1037, _e1041);
                                    let _e1043 = local_67;
                                    let _e1045 = (_e1043 >> bitcast<u32>(16i));
                                    local_80 = ((_e1045 & 32768u) << bitcast<u32>(16i));
                                    let _e1051 = ((_e1045 >> bitcast<u32>(10i)) & 31u);
                                    local_81 = _e1051;
                                    local_82 = (_e1045 & 1023u);
                                    if (_e1051 == 0u) {
                                        let _e1054 = local_82;
                                        let _e1055 = f32(_e1054);
                                        local_83 = _e1055;
                                        let _e1057 = local_80;
                                        if (_e1057 == 0u) {
                                            phi_1036_ = (_e1055 * 0.000000059604645f);
                                        } else {
                                            let _e1059 = local_83;
                                            phi_1036_ = (_e1059 * -0.000000059604645f);
                                        }
                                        let _e1062 = phi_1036_;
                                        phi_1053_ = _e1062;
                                        phi_1054_ = f32();
                                        phi_1055_ = true;
                                    } else {
                                        let _e1063 = local_81;
                                        let _e1064 = (_e1063 == 31u);
                                        if _e1064 {
                                            let _e1065 = local_80;
                                            let _e1067 = local_82;
                                            phi_1051_ = bitcast<f32>(((_e1065 | 2139095040u) | (_e1067 << bitcast<u32>(13i))));
                                            phi_1052_ = f32();
                                        } else {
                                            let _e1072 = local_81;
                                            let _e1076 = local_80;
                                            let _e1078 = local_82;
                                            phi_1051_ = f32();
                                            phi_1052_ = bitcast<f32>(((_e1076 | ((_e1072 + 112u) << bitcast<u32>(23i))) | (_e1078 << bitcast<u32>(13i))));
                                        }
                                        let _e1084 = phi_1051_;
                                        let _e1086 = phi_1052_;
                                        phi_1053_ = _e1084;
                                        phi_1054_ = _e1086;
                                        phi_1055_ = _e1064;
                                    }
                                    let _e1088 = phi_1053_;
                                    let _e1090 = phi_1054_;
                                    let _e1092 = phi_1055_;
                                    let _e1094 = local_120;
                                    let _e1095 = local_121;
                                    let _e1096 = local_122;
                                    phi_1134_ = array<f32, 4>(_e1094, _e1095, _e1096, select(_e1090, _e1088, _e1092));
                                } else {
                                    let _e1098 = local_9;
                                    let _e1099 = (4u * _e1098);
                                    local_84 = _e1099;
                                    let _e1100 = local_1;
                                    if (_e1099 < _e1100) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e1102 = local_84;
                                    let _e1105 = global_4.member[_e1102];
                                    local_85 = bitcast<f32>(_e1105);
                                    let _e1107 = local_84;
                                    let _e1108 = (_e1107 + 1u);
                                    local_86 = _e1108;
                                    let _e1109 = local_1;
                                    if (_e1108 < _e1109) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e1111 = local_86;
                                    let _e1114 = global_4.member[_e1111];
                                    local_87 = bitcast<f32>(_e1114);
                                    let _e1116 = local_84;
                                    let _e1117 = (_e1116 + 2u);
                                    local_88 = _e1117;
                                    let _e1118 = local_1;
                                    if (_e1117 < _e1118) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e1120 = local_88;
                                    let _e1123 = global_4.member[_e1120];
                                    local_89 = bitcast<f32>(_e1123);
                                    let _e1125 = local_84;
                                    let _e1126 = (_e1125 + 3u);
                                    local_90 = _e1126;
                                    let _e1127 = local_1;
                                    if (_e1126 < _e1127) {
                                    } else {
                                        phi_1368_ = true;
                                        break;
                                    }
                                    let _e1129 = local_90;
                                    let _e1132 = global_4.member[_e1129];
                                    let _e1134 = local_85;
                                    let _e1135 = local_87;
                                    let _e1136 = local_89;
                                    phi_1134_ = array<f32, 4>(_e1134, _e1135, _e1136, bitcast<f32>(_e1132));
                                }
                                let _e1139 = phi_1134_;
                                phi_1135_ = _e1139;
                            }
                            let _e1141 = phi_1135_;
                            phi_1136_ = array<f32, 3>();
                            phi_1137_ = f32();
                            phi_1138_ = bool();
                            phi_1139_ = _e1141;
                            phi_1140_ = false;
                            phi_1141_ = true;
                        }
                        let _e1143 = phi_1136_;
                        let _e1145 = phi_1137_;
                        let _e1147 = phi_1138_;
                        let _e1149 = phi_1139_;
                        let _e1151 = phi_1140_;
                        let _e1153 = phi_1141_;
                        local_91 = _e1147;
                        local_92 = _e1149;
                        local_93 = _e1151;
                        local_94 = _e1153;
                        if _e1153 {
                            let _e1154 = local_9;
                            let _e1155 = local_3;
                            if (_e1154 < _e1155) {
                            } else {
                                phi_1368_ = true;
                                break;
                            }
                            let _e1157 = local_9;
                            let _e1160 = global_6.member[_e1157];
                            let _e1164 = ((bitcast<u32>(bitcast<f32>(_e1160)) & 2139095040u) != 2139095040u);
                            local_95 = _e1164;
                            if _e1164 {
                                let _e1165 = local_92;
                                let _e1167 = local_92;
                                let _e1169 = local_92;
                                phi_1171_ = array<f32, 3>(_e1165[0], _e1167[1], _e1169[2]);
                            } else {
                                phi_1171_ = array<f32, 3>(0f, 0f, 0f);
                            }
                            let _e1173 = phi_1171_;
                            let _e1174 = local_95;
                            phi_1173_ = _e1173;
                            phi_1174_ = select(0f, 1f, _e1174);
                        } else {
                            phi_1173_ = _e1143;
                            phi_1174_ = _e1145;
                        }
                        let _e1177 = phi_1173_;
                        let _e1179 = phi_1174_;
                        local_96 = _e1177;
                        local_97 = _e1179;
                        let _e1180 = local_94;
                        let _e1181 = local_93;
                        let _e1182 = local_91;
                        local_123 = select(_e1182, _e1181, _e1180);
                        let _e1184 = local_94;
                        let _e1185 = local_126;
                        let _e1186 = local_18;
                        let _e1187 = select(_e1186, _e1185, _e1184);
                        local_124 = _e1187;
                        let _e1188 = local_9;
                        let _e1189 = (5u * _e1188);
                        local_98 = _e1189;
                        local_99 = bitcast<u32>(_e1177[0]);
                        let _e1192 = local_4;
                        if (_e1189 < _e1192) {
                        } else {
                            phi_1368_ = true;
                            break;
                        }
                        let _e1194 = local_98;
                        let _e1197 = local_99;
                        global_7.member[_e1194] = _e1197;
                        let _e1198 = local_98;
                        let _e1199 = (_e1198 + 1u);
                        local_100 = _e1199;
                        let _e1200 = local_96;
                        local_101 = bitcast<u32>(_e1200[1]);
                        let _e1203 = local_4;
                        if (_e1199 < _e1203) {
                        } else {
                            phi_1368_ = true;
                            break;
                        }
                        let _e1205 = local_100;
                        let _e1208 = local_101;
                        global_7.member[_e1205] = _e1208;
                        let _e1209 = local_98;
                        let _e1210 = (_e1209 + 2u);
                        local_102 = _e1210;
                        let _e1211 = local_96;
                        local_103 = bitcast<u32>(_e1211[2]);
                        let _e1214 = local_4;
                        if (_e1210 < _e1214) {
                        } else {
                            phi_1368_ = true;
                            break;
                        }
                        let _e1216 = local_102;
                        let _e1219 = local_103;
                        global_7.member[_e1216] = _e1219;
                        let _e1220 = local_98;
                        let _e1221 = (_e1220 + 3u);
                        local_104 = _e1221;
                        let _e1222 = local_97;
                        local_105 = bitcast<u32>(_e1222);
                        let _e1224 = local_4;
                        if (_e1221 < _e1224) {
                        } else {
                            phi_1368_ = true;
                            break;
                        }
                        let _e1226 = local_104;
                        let _e1229 = local_105;
                        global_7.member[_e1226] = _e1229;
                        let _e1230 = local_98;
                        let _e1231 = (_e1230 + 4u);
                        local_106 = _e1231;
                        let _e1232 = local_124;
                        local_107 = bitcast<u32>(_e1232);
                        let _e1234 = local_4;
                        if (_e1231 < _e1234) {
                        } else {
                            phi_1368_ = true;
                            break;
                        }
                        let _e1236 = local_106;
                        let _e1239 = local_107;
                        global_7.member[_e1236] = _e1239;
                        let _e1242 = global_5.member.member_2;
                        local_108 = _e1242;
                        let _e1243 = local_123;
                        if _e1243 {
                            let _e1244 = local_97;
                            if (_e1244 < 1f) {
                                phi_1336_ = _e1187;
                            } else {
                                let _e1246 = local_124;
                                let _e1247 = local_108;
                                local_109 = (_e1246 * _e1247);
                                let _e1249 = local_107;
                                if (_e1249 == 0u) {
                                    phi_1277_ = false;
                                } else {
                                    let _e1251 = local_107;
                                    phi_1277_ = (_e1251 <= 2139095040u);
                                }
                                let _e1254 = phi_1277_;
                                if _e1254 {
                                    let _e1255 = local_109;
                                    if (_e1255 >= 0f) {
                                        let _e1257 = local_109;
                                        let _e1260 = ((bitcast<u32>(_e1257) & 2147483647u) > 2139095040u);
                                        if _e1260 {
                                            phi_1308_ = f32();
                                            phi_1309_ = f32();
                                            phi_1310_ = false;
                                        } else {
                                            let _e1261 = local_109;
                                            let _e1262 = (_e1261 == 0f);
                                            local_110 = _e1262;
                                            if _e1262 {
                                                phi_1306_ = f32();
                                                phi_1307_ = true;
                                            } else {
                                                let _e1266 = global_5.member.member_1.member_1;
                                                local_111 = _e1266;
                                                let _e1267 = local_109;
                                                let _e1268 = (_e1267 >= _e1266);
                                                if _e1268 {
                                                    phi_1304_ = f32();
                                                } else {
                                                    let _e1269 = local_109;
                                                    let _e1270 = local_124;
                                                    let _e1272 = local_111;
                                                    let _e1273 = local_109;
                                                    phi_1304_ = ((_e1269 * _e1270) / (_e1272 - _e1273));
                                                }
                                                let _e1277 = phi_1304_;
                                                phi_1306_ = _e1277;
                                                phi_1307_ = _e1268;
                                            }
                                            let _e1279 = phi_1306_;
                                            let _e1281 = phi_1307_;
                                            let _e1282 = local_110;
                                            let _e1283 = local_126;
                                            phi_1308_ = select(_e1283, 0f, _e1282);
                                            phi_1309_ = _e1279;
                                            phi_1310_ = _e1281;
                                        }
                                        let _e1286 = phi_1308_;
                                        let _e1288 = phi_1309_;
                                        let _e1290 = phi_1310_;
                                        phi_1311_ = _e1286;
                                        phi_1312_ = _e1288;
                                        phi_1313_ = _e1260;
                                        phi_1314_ = _e1290;
                                    } else {
                                        phi_1311_ = f32();
                                        phi_1312_ = f32();
                                        phi_1313_ = true;
                                        phi_1314_ = false;
                                    }
                                    let _e1292 = phi_1311_;
                                    let _e1294 = phi_1312_;
                                    let _e1296 = phi_1313_;
                                    let _e1298 = phi_1314_;
                                    phi_1315_ = _e1292;
                                    phi_1316_ = _e1294;
                                    phi_1317_ = _e1296;
                                    phi_1318_ = _e1298;
                                } else {
                                    phi_1315_ = f32();
                                    phi_1316_ = f32();
                                    phi_1317_ = true;
                                    phi_1318_ = false;
                                }
                                let _e1300 = phi_1315_;
                                let _e1302 = phi_1316_;
                                let _e1304 = phi_1317_;
                                let _e1306 = phi_1318_;
                                let _e1307 = local_125;
                                let _e1311 = local_124;
                                let _e1312 = (_e1311 + select(_e1302, select(_e1300, _e1307, _e1304), select(_e1306, true, _e1304)));
                                let _e1316 = local_126;
                                phi_1336_ = select(_e1316, _e1312, ((bitcast<u32>(_e1312) & 2139095040u) != 2139095040u));
                            }
                            let _e1319 = phi_1336_;
                            phi_1337_ = _e1319;
                        } else {
                            phi_1337_ = _e184;
                        }
                        let _e1321 = phi_1337_;
                        local_112 = bitcast<u32>(_e1321);
                        let _e1323 = local_9;
                        let _e1324 = local_3;
                        if (_e1323 < _e1324) {
                        } else {
                            phi_1368_ = true;
                            break;
                        }
                        let _e1326 = local_9;
                        let _e1329 = local_112;
                        global_6.member[_e1326] = _e1329;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e1330 = local_7;
                    let _e1331 = local_6;
                    phi_126_ = (_e1330 + _e1331);
                } else {
                    phi_126_ = u32();
                }
                let _e1334 = phi_126_;
                continue;
                continuing {
                    let _e1335 = local_8;
                    phi_125_ = _e1334;
                    phi_1368_ = false;
                    break if !(_e1335);
                }
            }
            let _e1338 = phi_1368_;
            if _e1338 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn peel_renderer_layer(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
