struct type_6 {
    member: array<u32>,
}

struct type_15 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_16 {
    member: type_15,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_3: type_6;
@group(0) @binding(0) 
var<storage> global_4: type_6;
@group(0) @binding(2) 
var<storage, read_write> global_5: type_6;
@group(0) @binding(3) 
var<storage, read_write> global_6: type_6;
var<immediate> global_7: type_16;
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
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: bool;
    var local_15: u32;
    var local_16: bool;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: f32;
    var local_21: u32;
    var local_22: f32;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: f32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: f32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: f32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: f32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: f32;
    var local_54: f32;
    var local_55: f32;
    var local_56: u32;
    var local_57: f32;
    var local_58: u32;
    var local_59: f32;
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
    var local_70: f32;
    var local_71: u32;
    var local_72: u32;
    var local_73: u32;
    var local_74: f32;
    var local_75: u32;
    var local_76: u32;
    var local_77: u32;
    var local_78: f32;
    var local_79: u32;
    var local_80: u32;
    var local_81: u32;
    var local_82: f32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: f32;
    var local_91: u32;
    var local_92: bool;
    var local_93: f32;
    var local_94: bool;
    var local_95: f32;
    var local_96: f32;
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
    var local_107: bool;
    var local_108: u32;
    var local_109: f32;
    var local_110: f32;
    var local_111: f32;
    var local_112: f32;
    var local_113: f32;
    var local_114: f32;
    var local_115: f32;
    var local_116: f32;
    var local_117: f32;
    var local_118: f32;
    var local_119: f32;
    var local_120: f32;
    var phi_106_: u32;
    var phi_1166_: bool;
    var phi_133_: u32;
    var phi_144_: u32;
    var phi_269_: f32;
    var phi_284_: f32;
    var phi_285_: f32;
    var phi_286_: f32;
    var phi_287_: f32;
    var phi_288_: bool;
    var phi_310_: f32;
    var phi_325_: f32;
    var phi_326_: f32;
    var phi_327_: f32;
    var phi_328_: f32;
    var phi_329_: bool;
    var phi_351_: f32;
    var phi_366_: f32;
    var phi_367_: f32;
    var phi_368_: f32;
    var phi_369_: f32;
    var phi_370_: bool;
    var phi_392_: f32;
    var phi_407_: f32;
    var phi_408_: f32;
    var phi_409_: f32;
    var phi_410_: f32;
    var phi_411_: bool;
    var phi_463_: f32;
    var phi_464_: f32;
    var phi_465_: f32;
    var phi_466_: f32;
    var phi_467_: bool;
    var phi_506_: f32;
    var phi_507_: f32;
    var phi_508_: f32;
    var phi_509_: f32;
    var phi_510_: bool;
    var phi_548_: f32;
    var phi_549_: f32;
    var phi_550_: f32;
    var phi_551_: f32;
    var phi_552_: bool;
    var phi_586_: array<f32, 4>;
    var phi_587_: array<f32, 4>;
    var phi_588_: array<f32, 4>;
    var phi_589_: array<f32, 4>;
    var phi_690_: f32;
    var phi_705_: f32;
    var phi_706_: f32;
    var phi_707_: f32;
    var phi_708_: f32;
    var phi_709_: bool;
    var phi_731_: f32;
    var phi_746_: f32;
    var phi_747_: f32;
    var phi_748_: f32;
    var phi_749_: f32;
    var phi_750_: bool;
    var phi_772_: f32;
    var phi_787_: f32;
    var phi_788_: f32;
    var phi_789_: f32;
    var phi_790_: f32;
    var phi_791_: bool;
    var phi_813_: f32;
    var phi_828_: f32;
    var phi_829_: f32;
    var phi_830_: f32;
    var phi_831_: f32;
    var phi_832_: bool;
    var phi_884_: f32;
    var phi_885_: f32;
    var phi_886_: f32;
    var phi_887_: f32;
    var phi_888_: bool;
    var phi_927_: f32;
    var phi_928_: f32;
    var phi_929_: f32;
    var phi_930_: f32;
    var phi_931_: bool;
    var phi_969_: f32;
    var phi_970_: f32;
    var phi_971_: f32;
    var phi_972_: f32;
    var phi_973_: bool;
    var phi_1007_: array<f32, 4>;
    var phi_1008_: array<f32, 4>;
    var phi_1009_: array<f32, 4>;
    var phi_1010_: array<f32, 4>;
    var phi_1055_: f32;
    var phi_1056_: f32;
    var phi_1076_: f32;
    var phi_1077_: f32;
    var phi_1078_: f32;
    var phi_1079_: f32;
    var phi_1085_: f32;
    var phi_1086_: f32;
    var phi_1088_: f32;
    var phi_1089_: bool;
    var phi_1094_: f32;
    var phi_1142_: u32;
    var phi_145_: u32;
    var phi_1143_: bool;
    var phi_1159_: bool;
    var phi_1234_: bool;
    var phi_134_: u32;
    var phi_1233_: bool;

    let _e171 = global_8;
    local_119 = bitcast<f32>(_e171);
    let _e173 = global_9;
    let _e174 = bitcast<f32>(_e173);
    local_120 = _e174;
    switch bitcast<i32>(0u) {
        default: {
            let _e176 = global;
            local = _e176;
            let _e177 = global_1;
            let _e178 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = arrayLength((&global_6.member));
            local_5 = _e177.x;
            local_6 = _e178.x;
            let _e193 = global_7.member.member;
            local_7 = _e193;
            let _e196 = global_7.member.member_2;
            local_8 = _e196;
            if (_e196 == 1u) {
                phi_106_ = 2u;
            } else {
                let _e198 = local_8;
                phi_106_ = select(0u, 1u, (_e198 == 2u));
            }
            let _e202 = phi_106_;
            local_9 = _e202;
            let _e205 = global_7.member.member_7;
            local_108 = select(3u, 4u, (_e205 == 1u));
            let _e210 = global_7.member.member_1;
            let _e211 = local_7;
            local_10 = (_e211 * _e210);
            let _e213 = local_6;
            local_11 = (_e213 * 256u);
            let _e215 = local;
            local_12 = (_e215 + 1u);
            let _e217 = local_5;
            phi_1166_ = false;
            phi_133_ = (_e217 * 256u);
            loop {
                let _e220 = phi_1166_;
                let _e222 = phi_133_;
                local_13 = _e222;
                let _e223 = local_13;
                let _e224 = local_10;
                let _e225 = (_e223 < _e224);
                local_14 = _e225;
                if _e225 {
                    let _e226 = local_13;
                    let _e227 = local;
                    phi_144_ = (_e226 + _e227);
                    loop {
                        let _e230 = phi_144_;
                        local_15 = _e230;
                        let _e231 = local_15;
                        let _e232 = local_10;
                        if (_e231 < _e232) {
                            let _e234 = local_13;
                            let _e235 = local_12;
                            let _e237 = local_15;
                            let _e238 = (_e237 < (_e234 + _e235));
                            if _e238 {
                                let _e239 = local_7;
                                let _e240 = (_e239 == 0u);
                                local_16 = _e240;
                                if _e240 {
                                    phi_1159_ = true;
                                    break;
                                }
                                let _e241 = local_15;
                                let _e242 = local_7;
                                local_17 = (_e241 % _e242);
                                let _e244 = local_16;
                                if _e244 {
                                    phi_1159_ = true;
                                    break;
                                }
                                let _e245 = local_15;
                                let _e246 = local_7;
                                let _e248 = local_7;
                                let _e250 = local_17;
                                local_18 = (((_e245 / _e246) * _e248) + _e250);
                                let _e252 = local_9;
                                if (_e252 == 0u) {
                                    let _e254 = local_18;
                                    let _e255 = (4u * _e254);
                                    local_19 = _e255;
                                    let _e256 = local_1;
                                    if (_e255 < _e256) {
                                    } else {
                                        phi_1159_ = true;
                                        break;
                                    }
                                    let _e258 = local_19;
                                    let _e260 = global_4.member[_e258];
                                    local_20 = bitcast<f32>(_e260);
                                    let _e262 = local_19;
                                    let _e263 = (_e262 + 1u);
                                    local_21 = _e263;
                                    let _e264 = local_1;
                                    if (_e263 < _e264) {
                                    } else {
                                        phi_1159_ = true;
                                        break;
                                    }
                                    let _e266 = local_21;
                                    let _e268 = global_4.member[_e266];
                                    local_22 = bitcast<f32>(_e268);
                                    let _e270 = local_19;
                                    let _e271 = (_e270 + 2u);
                                    local_23 = _e271;
                                    let _e272 = local_1;
                                    if (_e271 < _e272) {
                                    } else {
                                        phi_1159_ = true;
                                        break;
                                    }
                                    let _e274 = local_23;
                                    let _e276 = global_4.member[_e274];
                                    local_24 = bitcast<f32>(_e276);
                                    let _e278 = local_19;
                                    let _e279 = (_e278 + 3u);
                                    local_25 = _e279;
                                    let _e280 = local_1;
                                    if (_e279 < _e280) {
                                    } else {
                                        phi_1159_ = true;
                                        break;
                                    }
                                    let _e282 = local_25;
                                    let _e284 = global_4.member[_e282];
                                    let _e286 = local_20;
                                    let _e287 = local_22;
                                    let _e288 = local_24;
                                    phi_589_ = array<f32, 4>(_e286, _e287, _e288, bitcast<f32>(_e284));
                                } else {
                                    let _e290 = local_9;
                                    if (_e290 == 1u) {
                                        let _e292 = local_18;
                                        let _e293 = (2u * _e292);
                                        local_26 = _e293;
                                        let _e294 = local_1;
                                        if (_e293 < _e294) {
                                        } else {
                                            phi_1159_ = true;
                                            break;
                                        }
                                        let _e296 = local_26;
                                        let _e298 = global_4.member[_e296];
                                        local_27 = _e298;
                                        let _e299 = local_26;
                                        let _e300 = (_e299 + 1u);
                                        local_28 = _e300;
                                        let _e301 = local_1;
                                        if (_e300 < _e301) {
                                        } else {
                                            phi_1159_ = true;
                                            break;
                                        }
                                        let _e303 = local_28;
                                        let _e305 = global_4.member[_e303];
                                        local_29 = _e305;
                                        let _e306 = local_27;
                                        let _e307 = (_e306 & 65535u);
                                        local_30 = ((_e307 & 32768u) << bitcast<u32>(16i));
                                        let _e313 = ((_e307 >> bitcast<u32>(10i)) & 31u);
                                        local_31 = _e313;
                                        local_32 = (_e307 & 1023u);
                                        if (_e313 == 0u) {
                                            let _e316 = local_32;
                                            let _e317 = f32(_e316);
                                            local_33 = _e317;
                                            let _e319 = local_30;
                                            if (_e319 == 0u) {
                                                phi_269_ = (_e317 * 0.000000059604645f);
                                            } else {
                                                let _e321 = local_33;
                                                phi_269_ = (_e321 * -0.000000059604645f);
                                            }
                                            let _e324 = phi_269_;
                                            phi_286_ = _e324;
                                            phi_287_ = f32();
                                            phi_288_ = true;
                                        } else {
                                            let _e325 = local_31;
                                            let _e326 = (_e325 == 31u);
                                            if _e326 {
                                                let _e327 = local_30;
                                                let _e329 = local_32;
                                                phi_284_ = bitcast<f32>(((_e327 | 2139095040u) | (_e329 << bitcast<u32>(13i))));
                                                phi_285_ = f32();
                                            } else {
                                                let _e334 = local_31;
                                                let _e338 = local_30;
                                                let _e340 = local_32;
                                                phi_284_ = f32();
                                                phi_285_ = bitcast<f32>(((_e338 | ((_e334 + 112u) << bitcast<u32>(23i))) | (_e340 << bitcast<u32>(13i))));
                                            }
                                            let _e346 = phi_284_;
                                            let _e348 = phi_285_;
                                            phi_286_ = _e346;
                                            phi_287_ = _e348;
                                            phi_288_ = _e326;
                                        }
                                        let _e350 = phi_286_;
                                        let _e352 = phi_287_;
                                        let _e354 = phi_288_;
                                        local_109 = select(_e352, _e350, _e354);
                                        let _e356 = local_27;
                                        let _e358 = (_e356 >> bitcast<u32>(16i));
                                        local_34 = ((_e358 & 32768u) << bitcast<u32>(16i));
                                        let _e364 = ((_e358 >> bitcast<u32>(10i)) & 31u);
                                        local_35 = _e364;
                                        local_36 = (_e358 & 1023u);
                                        if (_e364 == 0u) {
                                            let _e367 = local_36;
                                            let _e368 = f32(_e367);
                                            local_37 = _e368;
                                            let _e370 = local_34;
                                            if (_e370 == 0u) {
                                                phi_310_ = (_e368 * 0.000000059604645f);
                                            } else {
                                                let _e372 = local_37;
                                                phi_310_ = (_e372 * -0.000000059604645f);
                                            }
                                            let _e375 = phi_310_;
                                            phi_327_ = _e375;
                                            phi_328_ = f32();
                                            phi_329_ = true;
                                        } else {
                                            let _e376 = local_35;
                                            let _e377 = (_e376 == 31u);
                                            if _e377 {
                                                let _e378 = local_34;
                                                let _e380 = local_36;
                                                phi_325_ = bitcast<f32>(((_e378 | 2139095040u) | (_e380 << bitcast<u32>(13i))));
                                                phi_326_ = f32();
                                            } else {
                                                let _e385 = local_35;
                                                let _e389 = local_34;
                                                let _e391 = local_36;
                                                phi_325_ = f32();
                                                phi_326_ = bitcast<f32>(((_e389 | ((_e385 + 112u) << bitcast<u32>(23i))) | (_e391 << bitcast<u32>(13i))));
                                            }
                                            let _e397 = phi_325_;
                                            let _e399 = phi_326_;
                                            phi_327_ = _e397;
                                            phi_328_ = _e399;
                                            phi_329_ = _e377;
                                        }
                                        let _e401 = phi_327_;
                                        let _e403 = phi_328_;
                                        let _e405 = phi_329_;
                                        local_110 = select(_e403, _e401, _e405);
                                        let _e407 = local_29;
                                        let _e408 = (_e407 & 65535u);
                                        local_38 = ((_e408 & 32768u) << bitcast<u32>(16i));
                                        let _e414 = ((_e408 >> bitcast<u32>(10i)) & 31u);
                                        local_39 = _e414;
                                        local_40 = (_e408 & 1023u);
                                        if (_e414 == 0u) {
                                            let _e417 = local_40;
                                            let _e418 = f32(_e417);
                                            local_41 = _e418;
                                            let _e420 = local_38;
                                            if (_e420 == 0u) {
                                                phi_351_ = (_e418 * 0.000000059604645f);
                                            } else {
                                                let _e422 = local_41;
                                                phi_351_ = (_e422 * -0.000000059604645f);
                                            }
                                            let _e425 = phi_351_;
                                            phi_368_ = _e425;
                                            phi_369_ = f32();
                                            phi_370_ = true;
                                        } else {
                                            let _e426 = local_39;
                                            let _e427 = (_e426 == 31u);
                                            if _e427 {
                                                let _e428 = local_38;
                                                let _e430 = local_40;
                                                phi_366_ = bitcast<f32>(((_e428 | 2139095040u) | (_e430 << bitcast<u32>(13i))));
                                                phi_367_ = f32();
                                            } else {
                                                let _e435 = local_39;
                                                let _e439 = local_38;
                                                let _e441 = local_40;
                                                phi_366_ = f32();
                                                phi_367_ = bitcast<f32>(((_e439 | ((_e435 + 112u) << bitcast<u32>(23i))) | (_e441 << bitcast<u32>(13i))));
                                            }
                                            let _e447 = phi_366_;
                                            let _e449 = phi_367_;
                                            phi_368_ = _e447;
                                            phi_369_ = _e449;
                                            phi_370_ = _e427;
                                        }
                                        let _e451 = phi_368_;
                                        let _e453 = phi_369_;
                                        let _e455 = phi_370_;
                                        local_111 = select(_e453, _e451, _e455);
                                        let _e457 = local_29;
                                        let _e459 = (_e457 >> bitcast<u32>(16i));
                                        local_42 = ((_e459 & 32768u) << bitcast<u32>(16i));
                                        let _e465 = ((_e459 >> bitcast<u32>(10i)) & 31u);
                                        local_43 = _e465;
                                        local_44 = (_e459 & 1023u);
                                        if (_e465 == 0u) {
                                            let _e468 = local_44;
                                            let _e469 = f32(_e468);
                                            local_45 = _e469;
                                            let _e471 = local_42;
                                            if (_e471 == 0u) {
                                                phi_392_ = (_e469 * 0.000000059604645f);
                                            } else {
                                                let _e473 = local_45;
                                                phi_392_ = (_e473 * -0.000000059604645f);
                                            }
                                            let _e476 = phi_392_;
                                            phi_409_ = _e476;
                                            phi_410_ = f32();
                                            phi_411_ = true;
                                        } else {
                                            let _e477 = local_43;
                                            let _e478 = (_e477 == 31u);
                                            if _e478 {
                                                let _e479 = local_42;
                                                let _e481 = local_44;
                                                phi_407_ = bitcast<f32>(((_e479 | 2139095040u) | (_e481 << bitcast<u32>(13i))));
                                                phi_408_ = f32();
                                            } else {
                                                let _e486 = local_43;
                                                let _e490 = local_42;
                                                let _e492 = local_44;
                                                phi_407_ = f32();
                                                phi_408_ = bitcast<f32>(((_e490 | ((_e486 + 112u) << bitcast<u32>(23i))) | (_e492 << bitcast<u32>(13i))));
                                            }
                                            let _e498 = phi_407_;
                                            let _e500 = phi_408_;
                                            phi_409_ = _e498;
                                            phi_410_ = _e500;
                                            phi_411_ = _e478;
                                        }
                                        let _e502 = phi_409_;
                                        let _e504 = phi_410_;
                                        let _e506 = phi_411_;
                                        let _e508 = local_109;
                                        let _e509 = local_110;
                                        let _e510 = local_111;
                                        phi_588_ = array<f32, 4>(_e508, _e509, _e510, select(_e504, _e502, _e506));
                                    } else {
                                        let _e512 = local_9;
                                        if (_e512 == 2u) {
                                            let _e514 = local_18;
                                            let _e515 = local_1;
                                            if (_e514 < _e515) {
                                            } else {
                                                phi_1159_ = true;
                                                break;
                                            }
                                            let _e517 = local_18;
                                            let _e519 = global_4.member[_e517];
                                            local_46 = _e519;
                                            let _e520 = (_e519 & 2047u);
                                            let _e523 = ((_e520 >> bitcast<u32>(6u)) & 31u);
                                            local_47 = _e523;
                                            local_48 = (_e520 & 63u);
                                            if (_e523 == 0u) {
                                                let _e526 = local_48;
                                                phi_465_ = (f32(_e526) * 0.0000009536743f);
                                                phi_466_ = f32();
                                                phi_467_ = true;
                                            } else {
                                                let _e529 = local_47;
                                                let _e530 = (_e529 == 31u);
                                                if _e530 {
                                                    let _e531 = local_48;
                                                    phi_463_ = bitcast<f32>((2139095040u | (_e531 << bitcast<u32>(17u))));
                                                    phi_464_ = f32();
                                                } else {
                                                    let _e536 = local_47;
                                                    let _e540 = local_48;
                                                    phi_463_ = f32();
                                                    phi_464_ = bitcast<f32>((((_e536 + 112u) << bitcast<u32>(23i)) | (_e540 << bitcast<u32>(17u))));
                                                }
                                                let _e546 = phi_463_;
                                                let _e548 = phi_464_;
                                                phi_465_ = _e546;
                                                phi_466_ = _e548;
                                                phi_467_ = _e530;
                                            }
                                            let _e550 = phi_465_;
                                            let _e552 = phi_466_;
                                            let _e554 = phi_467_;
                                            local_112 = select(_e552, _e550, _e554);
                                            let _e556 = local_46;
                                            let _e559 = ((_e556 >> bitcast<u32>(11i)) & 2047u);
                                            let _e562 = ((_e559 >> bitcast<u32>(6u)) & 31u);
                                            local_49 = _e562;
                                            local_50 = (_e559 & 63u);
                                            if (_e562 == 0u) {
                                                let _e565 = local_50;
                                                phi_508_ = (f32(_e565) * 0.0000009536743f);
                                                phi_509_ = f32();
                                                phi_510_ = true;
                                            } else {
                                                let _e568 = local_49;
                                                let _e569 = (_e568 == 31u);
                                                if _e569 {
                                                    let _e570 = local_50;
                                                    phi_506_ = bitcast<f32>((2139095040u | (_e570 << bitcast<u32>(17u))));
                                                    phi_507_ = f32();
                                                } else {
                                                    let _e575 = local_49;
                                                    let _e579 = local_50;
                                                    phi_506_ = f32();
                                                    phi_507_ = bitcast<f32>((((_e575 + 112u) << bitcast<u32>(23i)) | (_e579 << bitcast<u32>(17u))));
                                                }
                                                let _e585 = phi_506_;
                                                let _e587 = phi_507_;
                                                phi_508_ = _e585;
                                                phi_509_ = _e587;
                                                phi_510_ = _e569;
                                            }
                                            let _e589 = phi_508_;
                                            let _e591 = phi_509_;
                                            let _e593 = phi_510_;
                                            local_113 = select(_e591, _e589, _e593);
                                            let _e595 = local_46;
                                            let _e597 = (_e595 >> bitcast<u32>(22i));
                                            let _e600 = ((_e597 >> bitcast<u32>(5u)) & 31u);
                                            local_51 = _e600;
                                            local_52 = (_e597 & 31u);
                                            if (_e600 == 0u) {
                                                let _e603 = local_52;
                                                phi_550_ = (f32(_e603) * 0.0000019073486f);
                                                phi_551_ = f32();
                                                phi_552_ = true;
                                            } else {
                                                let _e606 = local_51;
                                                let _e607 = (_e606 == 31u);
                                                if _e607 {
                                                    let _e608 = local_52;
                                                    phi_548_ = bitcast<f32>((2139095040u | (_e608 << bitcast<u32>(18u))));
                                                    phi_549_ = f32();
                                                } else {
                                                    let _e613 = local_51;
                                                    let _e617 = local_52;
                                                    phi_548_ = f32();
                                                    phi_549_ = bitcast<f32>((((_e613 + 112u) << bitcast<u32>(23i)) | (_e617 << bitcast<u32>(18u))));
                                                }
                                                let _e623 = phi_548_;
                                                let _e625 = phi_549_;
                                                phi_550_ = _e623;
                                                phi_551_ = _e625;
                                                phi_552_ = _e607;
                                            }
                                            let _e627 = phi_550_;
                                            let _e629 = phi_551_;
                                            let _e631 = phi_552_;
                                            let _e633 = local_112;
                                            let _e634 = local_113;
                                            phi_587_ = array<f32, 4>(_e633, _e634, select(_e629, _e627, _e631), 1f);
                                        } else {
                                            let _e636 = local_9;
                                            if (_e636 == 4u) {
                                                let _e638 = local_18;
                                                let _e639 = local_1;
                                                if (_e638 < _e639) {
                                                } else {
                                                    phi_1159_ = true;
                                                    break;
                                                }
                                                let _e641 = local_18;
                                                let _e643 = global_4.member[_e641];
                                                phi_586_ = array<f32, 4>((f32((_e643 & 16777215u)) * 0.00000005960465f), 0f, 0f, 1f);
                                            } else {
                                                let _e648 = local_18;
                                                let _e649 = local_1;
                                                if (_e648 < _e649) {
                                                } else {
                                                    phi_1159_ = true;
                                                    break;
                                                }
                                                let _e651 = local_18;
                                                let _e653 = global_4.member[_e651];
                                                phi_586_ = array<f32, 4>(bitcast<f32>(_e653), 0f, 0f, 1f);
                                            }
                                            let _e657 = phi_586_;
                                            phi_587_ = _e657;
                                        }
                                        let _e659 = phi_587_;
                                        phi_588_ = _e659;
                                    }
                                    let _e661 = phi_588_;
                                    phi_589_ = _e661;
                                }
                                let _e663 = phi_589_;
                                local_53 = _e663[0];
                                local_54 = _e663[1];
                                local_55 = _e663[2];
                                let _e667 = local_108;
                                if (_e667 == 0u) {
                                    let _e669 = local_18;
                                    let _e670 = (4u * _e669);
                                    local_56 = _e670;
                                    let _e671 = local_2;
                                    if (_e670 < _e671) {
                                    } else {
                                        phi_1159_ = true;
                                        break;
                                    }
                                    let _e673 = local_56;
                                    let _e675 = global_3.member[_e673];
                                    local_57 = bitcast<f32>(_e675);
                                    let _e677 = local_56;
                                    let _e678 = (_e677 + 1u);
                                    local_58 = _e678;
                                    let _e679 = local_2;
                                    if (_e678 < _e679) {
                                    } else {
                                        phi_1159_ = true;
                                        break;
                                    }
                                    let _e681 = local_58;
                                    let _e683 = global_3.member[_e681];
                                    local_59 = bitcast<f32>(_e683);
                                    let _e685 = local_56;
                                    let _e686 = (_e685 + 2u);
                                    local_60 = _e686;
                                    let _e687 = local_2;
                                    if (_e686 < _e687) {
                                    } else {
                                        phi_1159_ = true;
                                        break;
                                    }
                                    let _e689 = local_60;
                                    let _e691 = global_3.member[_e689];
                                    local_61 = bitcast<f32>(_e691);
                                    let _e693 = local_56;
                                    let _e694 = (_e693 + 3u);
                                    local_62 = _e694;
                                    let _e695 = local_2;
                                    if (_e694 < _e695) {
                                    } else {
                                        phi_1159_ = true;
                                        break;
                                    }
                                    let _e697 = local_62;
                                    let _e699 = global_3.member[_e697];
                                    let _e701 = local_57;
                                    let _e702 = local_59;
                                    let _e703 = local_61;
                                    phi_1010_ = array<f32, 4>(_e701, _e702, _e703, bitcast<f32>(_e699));
                                } else {
                                    let _e705 = local_108;
                                    if (_e705 == 1u) {
                                        let _e707 = local_18;
                                        let _e708 = (2u * _e707);
                                        local_63 = _e708;
                                        let _e709 = local_2;
                                        if (_e708 < _e709) {
                                        } else {
                                            phi_1159_ = true;
                                            break;
                                        }
                                        let _e711 = local_63;
                                        let _e713 = global_3.member[_e711];
                                        local_64 = _e713;
                                        let _e714 = local_63;
                                        let _e715 = (_e714 + 1u);
                                        local_65 = _e715;
                                        let _e716 = local_2;
                                        if (_e715 < _e716) {
                                        } else {
                                            phi_1159_ = true;
                                            break;
                                        }
                                        let _e718 = local_65;
                                        let _e720 = global_3.member[_e718];
                                        local_66 = _e720;
                                        let _e721 = local_64;
                                        let _e722 = (_e721 & 65535u);
                                        local_67 = ((_e722 & 32768u) << bitcast<u32>(16i));
                                        let _e728 = ((_e722 >> bitcast<u32>(10i)) & 31u);
                                        local_68 = _e728;
                                        local_69 = (_e722 & 1023u);
                                        if (_e728 == 0u) {
                                            let _e731 = local_69;
                                            let _e732 = f32(_e731);
                                            local_70 = _e732;
                                            let _e734 = local_67;
                                            if (_e734 == 0u) {
                                                phi_690_ = (_e732 * 0.000000059604645f);
                                            } else {
                                                let _e736 = local_70;
                                                phi_690_ = (_e736 * -0.000000059604645f);
                                            }
                                            let _e739 = phi_690_;
                                            phi_707_ = _e739;
                                            phi_708_ = f32();
                                            phi_709_ = true;
                                        } else {
                                            let _e740 = local_68;
                                            let _e741 = (_e740 == 31u);
                                            if _e741 {
                                                let _e742 = local_67;
                                                let _e744 = local_69;
                                                phi_705_ = bitcast<f32>(((_e742 | 2139095040u) | (_e744 << bitcast<u32>(13i))));
                                                phi_706_ = f32();
                                            } else {
                                                let _e749 = local_68;
                                                let _e753 = local_67;
                                                let _e755 = local_69;
                                                phi_705_ = f32();
                                                phi_706_ = bitcast<f32>(((_e753 | ((_e749 + 112u) << bitcast<u32>(23i))) | (_e755 << bitcast<u32>(13i))));
                                            }
                                            let _e761 = phi_705_;
                                            let _e763 = phi_706_;
                                            phi_707_ = _e761;
                                            phi_708_ = _e763;
                                            phi_709_ = _e741;
                                        }
                                        let _e765 = phi_707_;
                                        let _e767 = phi_708_;
                                        let _e769 = phi_709_;
                                        local_114 = select(_e767, _e765, _e769);
                                        let _e771 = local_64;
                                        let _e773 = (_e771 >> bitcast<u32>(16i));
                                        local_71 = ((_e773 & 32768u) << bitcast<u32>(16i));
                                        let _e779 = ((_e773 >> bitcast<u32>(10i)) & 31u);
                                        local_72 = _e779;
                                        local_73 = (_e773 & 1023u);
                                        if (_e779 == 0u) {
                                            let _e782 = local_73;
                                            let _e783 = f32(_e782);
                                            local_74 = _e783;
                                            let _e785 = local_71;
                                            if (_e785 == 0u) {
                                                phi_731_ = (_e783 * 0.000000059604645f);
                                            } else {
                                                let _e787 = local_74;
                                                phi_731_ = (_e787 * -0.000000059604645f);
                                            }
                                            let _e790 = phi_731_;
                                            phi_748_ = _e790;
                                            phi_749_ = f32();
                                            phi_750_ = true;
                                        } else {
                                            let _e791 = local_72;
                                            let _e792 = (_e791 == 31u);
                                            if _e792 {
                                                let _e793 = local_71;
                                                let _e795 = local_73;
                                                phi_746_ = bitcast<f32>(((_e793 | 2139095040u) | (_e795 << bitcast<u32>(13i))));
                                                phi_747_ = f32();
                                            } else {
                                                let _e800 = local_72;
                                                let _e804 = local_71;
                                                let _e806 = local_73;
                                                phi_746_ = f32();
                                                phi_747_ = bitcast<f32>(((_e804 | ((_e800 + 112u) << bitcast<u32>(23i))) | (_e806 << bitcast<u32>(13i))));
                                            }
                                            let _e812 = phi_746_;
                                            let _e814 = phi_747_;
                                            phi_748_ = _e812;
                                            phi_749_ = _e814;
                                            phi_750_ = _e792;
                                        }
                                        let _e816 = phi_748_;
                                        let _e818 = phi_749_;
                                        let _e820 = phi_750_;
                                        local_115 = select(_e818, _e816, _e820);
                                        let _e822 = local_66;
                                        let _e823 = (_e822 & 65535u);
                                        local_75 = ((_e823 & 32768u) << bitcast<u32>(16i));
                                        let _e829 = ((_e823 >> bitcast<u32>(10i)) & 31u);
                                        local_76 = _e829;
                                        local_77 = (_e823 & 1023u);
                                        if (_e829 == 0u) {
                                            let _e832 = local_77;
                                            let _e833 = f32(_e832);
                                            local_78 = _e833;
                                            let _e835 = local_75;
                                            if (_e835 == 0u) {
                                                phi_772_ = (_e833 * 0.000000059604645f);
                                            } else {
                                                let _e837 = local_78;
                                                phi_772_ = (_e837 * -0.000000059604645f);
                                            }
                                            let _e840 = phi_772_;
                                            phi_789_ = _e840;
                                            phi_790_ = f32();
                                            phi_791_ = true;
                                        } else {
                                            let _e841 = local_76;
                                            let _e842 = (_e841 == 31u);
                                            if _e842 {
                                                let _e843 = local_75;
                                                let _e845 = local_77;
                                                phi_787_ = bitcast<f32>(((_e843 | 2139095040u) | (_e845 << bitcast<u32>(13i))));
                                                phi_788_ = f32();
                                            } else {
                                                let _e850 = local_76;
                                                let _e854 = local_75;
                                                let _e856 = local_77;
                                                phi_787_ = f32();
                                                phi_788_ = bitcast<f32>(((_e854 | ((_e850 + 112u) << bitcast<u32>(23i))) | (_e856 << bitcast<u32>(13i))));
                                            }
                                            let _e862 = phi_787_;
                                            let _e864 = phi_788_;
                                            phi_789_ = _e862;
                                            phi_790_ = _e864;
                                            phi_791_ = _e842;
                                        }
                                        let _e866 = phi_789_;
                                        let _e868 = phi_790_;
                                        let _e870 = phi_791_;
                                        local_116 = select(_e868, _e866, _e870);
                                        let _e872 = local_66;
                                        let _e874 = (_e872 >> bitcast<u32>(16i));
                                        local_79 = ((_e874 & 32768u) << bitcast<u32>(16i));
                                        let _e880 = ((_e874 >> bitcast<u32>(10i)) & 31u);
                                        local_80 = _e880;
                                        local_81 = (_e874 & 1023u);
                                        if (_e880 == 0u) {
                                            let _e883 = local_81;
                                            let _e884 = f32(_e883);
                                            local_82 = _e884;
                                            let _e886 = local_79;
                                            if (_e886 == 0u) {
                                                phi_813_ = (_e884 * 0.000000059604645f);
                                            } else {
                                                let _e888 = local_82;
                                                phi_813_ = (_e888 * -0.000000059604645f);
                                            }
                                            let _e891 = phi_813_;
                                            phi_830_ = _e891;
                                            phi_831_ = f32();
                                            phi_832_ = true;
                                        } else {
                                            let _e892 = local_80;
                                            let _e893 = (_e892 == 31u);
                                            if _e893 {
                                                let _e894 = local_79;
                                                let _e896 = local_81;
                                                phi_828_ = bitcast<f32>(((_e894 | 2139095040u) | (_e896 << bitcast<u32>(13i))));
                                                phi_829_ = f32();
                                            } else {
                                                let _e901 = local_80;
                                                let _e905 = local_79;
                                                let _e907 = local_81;
                                                phi_828_ = f32();
                                                phi_829_ = bitcast<f32>(((_e905 | ((_e901 + 112u) << bitcast<u32>(23i))) | (_e907 << bitcast<u32>(13i))));
                                            }
                                            let _e913 = phi_828_;
                                            let _e915 = phi_829_;
                                            phi_830_ = _e913;
                                            phi_831_ = _e915;
                                            phi_832_ = _e893;
                                        }
                                        let _e917 = phi_830_;
                                        let _e919 = phi_831_;
                                        let _e921 = phi_832_;
                                        let _e923 = local_114;
                                        let _e924 = local_115;
                                        let _e925 = local_116;
                                        phi_1009_ = array<f32, 4>(_e923, _e924, _e925, select(_e919, _e917, _e921));
                                    } else {
                                        let _e927 = local_108;
                                        if (_e927 == 2u) {
                                            let _e929 = local_18;
                                            let _e930 = local_2;
                                            if (_e929 < _e930) {
                                            } else {
                                                phi_1159_ = true;
                                                break;
                                            }
                                            let _e932 = local_18;
                                            let _e934 = global_3.member[_e932];
                                            local_83 = _e934;
                                            let _e935 = (_e934 & 2047u);
                                            let _e938 = ((_e935 >> bitcast<u32>(6u)) & 31u);
                                            local_84 = _e938;
                                            local_85 = (_e935 & 63u);
                                            if (_e938 == 0u) {
                                                let _e941 = local_85;
                                                phi_886_ = (f32(_e941) * 0.0000009536743f);
                                                phi_887_ = f32();
                                                phi_888_ = true;
                                            } else {
                                                let _e944 = local_84;
                                                let _e945 = (_e944 == 31u);
                                                if _e945 {
                                                    let _e946 = local_85;
                                                    phi_884_ = bitcast<f32>((2139095040u | (_e946 << bitcast<u32>(17u))));
                                                    phi_885_ = f32();
                                                } else {
                                                    let _e951 = local_84;
                                                    let _e955 = local_85;
                                                    phi_884_ = f32();
                                                    phi_885_ = bitcast<f32>((((_e951 + 112u) << bitcast<u32>(23i)) | (_e955 << bitcast<u32>(17u))));
                                                }
                                                let _e961 = phi_884_;
                                                let _e963 = phi_885_;
                                                phi_886_ = _e961;
                                                phi_887_ = _e963;
                                                phi_888_ = _e945;
                                            }
                                            let _e965 = phi_886_;
                                            let _e967 = phi_887_;
                                            let _e969 = phi_888_;
                                            local_117 = select(_e967, _e965, _e969);
                                            let _e971 = local_83;
                                            let _e974 = ((_e971 >> bitcast<u32>(11i)) & 2047u);
                                            let _e977 = ((_e974 >> bitcast<u32>(6u)) & 31u);
                                            local_86 = _e977;
                                            local_87 = (_e974 & 63u);
                                            if (_e977 == 0u) {
                                                let _e980 = local_87;
                                                phi_929_ = (f32(_e980) * 0.0000009536743f);
                                                phi_930_ = f32();
                                                phi_931_ = true;
                                            } else {
                                                let _e983 = local_86;
                                                let _e984 = (_e983 == 31u);
                                                if _e984 {
                                                    let _e985 = local_87;
                                                    phi_927_ = bitcast<f32>((2139095040u | (_e985 << bitcast<u32>(17u))));
                                                    phi_928_ = f32();
                                                } else {
                                                    let _e990 = local_86;
                                                    let _e994 = local_87;
                                                    phi_927_ = f32();
                                                    phi_928_ = bitcast<f32>((((_e990 + 112u) << bitcast<u32>(23i)) | (_e994 << bitcast<u32>(17u))));
                                                }
                                                let _e1000 = phi_927_;
                                                let _e1002 = phi_928_;
                                                phi_929_ = _e1000;
                                                phi_930_ = _e1002;
                                                phi_931_ = _e984;
                                            }
                                            let _e1004 = phi_929_;
                                            let _e1006 = phi_930_;
                                            let _e1008 = phi_931_;
                                            local_118 = select(_e1006, _e1004, _e1008);
                                            let _e1010 = local_83;
                                            let _e1012 = (_e1010 >> bitcast<u32>(22i));
                                            let _e1015 = ((_e1012 >> bitcast<u32>(5u)) & 31u);
                                            local_88 = _e1015;
                                            local_89 = (_e1012 & 31u);
                                            if (_e1015 == 0u) {
                                                let _e1018 = local_89;
                                                phi_971_ = (f32(_e1018) * 0.0000019073486f);
                                                phi_972_ = f32();
                                                phi_973_ = true;
                                            } else {
                                                let _e1021 = local_88;
                                                let _e1022 = (_e1021 == 31u);
                                                if _e1022 {
                                                    let _e1023 = local_89;
                                                    phi_969_ = bitcast<f32>((2139095040u | (_e1023 << bitcast<u32>(18u))));
                                                    phi_970_ = f32();
                                                } else {
                                                    let _e1028 = local_88;
                                                    let _e1032 = local_89;
                                                    phi_969_ = f32();
                                                    phi_970_ = bitcast<f32>((((_e1028 + 112u) << bitcast<u32>(23i)) | (_e1032 << bitcast<u32>(18u))));
                                                }
                                                let _e1038 = phi_969_;
                                                let _e1040 = phi_970_;
                                                phi_971_ = _e1038;
                                                phi_972_ = _e1040;
                                                phi_973_ = _e1022;
                                            }
                                            let _e1042 = phi_971_;
                                            let _e1044 = phi_972_;
                                            let _e1046 = phi_973_;
                                            let _e1048 = local_117;
                                            let _e1049 = local_118;
                                            phi_1008_ = array<f32, 4>(_e1048, _e1049, select(_e1044, _e1042, _e1046), 1f);
                                        } else {
                                            let _e1051 = local_108;
                                            if (_e1051 == 4u) {
                                                let _e1053 = local_18;
                                                let _e1054 = local_2;
                                                if (_e1053 < _e1054) {
                                                } else {
                                                    phi_1159_ = true;
                                                    break;
                                                }
                                                let _e1056 = local_18;
                                                let _e1058 = global_3.member[_e1056];
                                                phi_1007_ = array<f32, 4>((f32((_e1058 & 16777215u)) * 0.00000005960465f), 0f, 0f, 1f);
                                            } else {
                                                let _e1063 = local_18;
                                                let _e1064 = local_2;
                                                if (_e1063 < _e1064) {
                                                } else {
                                                    phi_1159_ = true;
                                                    break;
                                                }
                                                let _e1066 = local_18;
                                                let _e1068 = global_3.member[_e1066];
                                                phi_1007_ = array<f32, 4>(bitcast<f32>(_e1068), 0f, 0f, 1f);
                                            }
                                            let _e1072 = phi_1007_;
                                            phi_1008_ = _e1072;
                                        }
                                        let _e1074 = phi_1008_;
                                        phi_1009_ = _e1074;
                                    }
                                    let _e1076 = phi_1009_;
                                    phi_1010_ = _e1076;
                                }
                                let _e1078 = phi_1010_;
                                local_90 = _e1078[0];
                                let _e1082 = global_7.member.member_3;
                                local_91 = _e1082;
                                if (_e1082 == 0u) {
                                    phi_1094_ = _e1078[0];
                                } else {
                                    let _e1084 = local_90;
                                    if (_e1084 >= 0f) {
                                        let _e1086 = local_90;
                                        let _e1087 = (_e1086 <= 1f);
                                        local_92 = _e1087;
                                        if _e1087 {
                                            let _e1090 = global_7.member.member_5;
                                            local_93 = _e1090;
                                            let _e1091 = local_120;
                                            local_94 = (_e1090 == _e1091);
                                            let _e1093 = local_91;
                                            if (_e1093 == 1u) {
                                                let _e1095 = local_94;
                                                if _e1095 {
                                                    let _e1098 = global_7.member.member_4;
                                                    let _e1099 = local_90;
                                                    phi_1055_ = (1f - _e1099);
                                                    phi_1056_ = _e1098;
                                                } else {
                                                    let _e1103 = global_7.member.member_4;
                                                    let _e1104 = local_93;
                                                    let _e1106 = local_93;
                                                    let _e1108 = local_90;
                                                    let _e1110 = local_93;
                                                    phi_1055_ = (_e1110 - (_e1108 * (_e1106 - _e1103)));
                                                    phi_1056_ = (_e1103 * _e1104);
                                                }
                                                let _e1113 = phi_1055_;
                                                let _e1115 = phi_1056_;
                                                phi_1078_ = _e1113;
                                                phi_1079_ = _e1115;
                                            } else {
                                                let _e1116 = local_94;
                                                if _e1116 {
                                                    let _e1119 = global_7.member.member_4;
                                                    phi_1076_ = _e1078[0];
                                                    phi_1077_ = _e1119;
                                                } else {
                                                    let _e1122 = global_7.member.member_4;
                                                    let _e1123 = local_93;
                                                    let _e1125 = local_93;
                                                    let _e1127 = local_90;
                                                    phi_1076_ = (_e1122 + (_e1127 * (_e1125 - _e1122)));
                                                    phi_1077_ = (_e1122 * _e1123);
                                                }
                                                let _e1131 = phi_1076_;
                                                let _e1133 = phi_1077_;
                                                phi_1078_ = _e1131;
                                                phi_1079_ = _e1133;
                                            }
                                            let _e1135 = phi_1078_;
                                            let _e1137 = phi_1079_;
                                            local_95 = _e1135;
                                            local_96 = _e1137;
                                            if (_e1135 <= 0f) {
                                                phi_1085_ = _e174;
                                            } else {
                                                let _e1139 = local_96;
                                                let _e1140 = local_95;
                                                phi_1085_ = (_e1139 / _e1140);
                                            }
                                            let _e1143 = phi_1085_;
                                            phi_1086_ = _e1143;
                                        } else {
                                            phi_1086_ = f32();
                                        }
                                        let _e1145 = phi_1086_;
                                        let _e1146 = local_92;
                                        phi_1088_ = _e1145;
                                        phi_1089_ = select(true, false, _e1146);
                                    } else {
                                        phi_1088_ = f32();
                                        phi_1089_ = true;
                                    }
                                    let _e1149 = phi_1088_;
                                    let _e1151 = phi_1089_;
                                    let _e1152 = local_119;
                                    phi_1094_ = select(_e1149, _e1152, _e1151);
                                }
                                let _e1155 = phi_1094_;
                                local_97 = _e1155;
                                let _e1156 = local_15;
                                let _e1157 = (5u * _e1156);
                                local_98 = _e1157;
                                let _e1158 = local_53;
                                local_99 = bitcast<u32>(_e1158);
                                let _e1160 = local_3;
                                if (_e1157 < _e1160) {
                                } else {
                                    phi_1159_ = true;
                                    break;
                                }
                                let _e1162 = local_98;
                                let _e1165 = local_99;
                                global_5.member[_e1162] = _e1165;
                                let _e1166 = local_98;
                                let _e1167 = (_e1166 + 1u);
                                local_100 = _e1167;
                                let _e1168 = local_54;
                                local_101 = bitcast<u32>(_e1168);
                                let _e1170 = local_3;
                                if (_e1167 < _e1170) {
                                } else {
                                    phi_1159_ = true;
                                    break;
                                }
                                let _e1172 = local_100;
                                let _e1175 = local_101;
                                global_5.member[_e1172] = _e1175;
                                let _e1176 = local_98;
                                let _e1177 = (_e1176 + 2u);
                                local_102 = _e1177;
                                let _e1178 = local_55;
                                local_103 = bitcast<u32>(_e1178);
                                let _e1180 = local_3;
                                if (_e1177 < _e1180) {
                                } else {
                                    phi_1159_ = true;
                                    break;
                                }
                                let _e1182 = local_102;
                                let _e1185 = local_103;
                                global_5.member[_e1182] = _e1185;
                                let _e1186 = local_98;
                                let _e1187 = (_e1186 + 3u);
                                local_104 = _e1187;
                                let _e1188 = local_97;
                                local_105 = bitcast<u32>(_e1188);
                                let _e1190 = local_3;
                                if (_e1187 < _e1190) {
                                } else {
                                    phi_1159_ = true;
                                    break;
                                }
                                let _e1192 = local_104;
                                let _e1195 = local_105;
                                global_5.member[_e1192] = _e1195;
                                let _e1196 = local_98;
                                let _e1197 = (_e1196 + 4u);
                                local_106 = _e1197;
                                let _e1198 = local_3;
                                if (_e1197 < _e1198) {
                                } else {
                                    phi_1159_ = true;
                                    break;
                                }
                                let _e1200 = local_106;
                                global_5.member[_e1200] = 1065353216u;
                                let _e1203 = local_15;
                                let _e1204 = local_4;
                                if (_e1203 < _e1204) {
                                } else {
                                    phi_1159_ = true;
                                    break;
                                }
                                let _e1206 = local_15;
                                global_6.member[_e1206] = 1u;
                                let _e1209 = local_15;
                                phi_1142_ = (_e1209 + 1u);
                            } else {
                                phi_1142_ = u32();
                            }
                            let _e1212 = phi_1142_;
                            phi_145_ = _e1212;
                            phi_1143_ = _e238;
                        } else {
                            phi_145_ = u32();
                            phi_1143_ = false;
                        }
                        let _e1214 = phi_145_;
                        let _e1216 = phi_1143_;
                        local_107 = _e1216;
                        continue;
                        continuing {
                            let _e1217 = local_107;
                            phi_144_ = _e1214;
                            phi_1159_ = _e220;
                            break if !(_e1217);
                        }
                    }
                    let _e1220 = phi_1159_;
                    phi_1233_ = _e1220;
                    if _e1220 {
                        break;
                    }
                    let _e1221 = local_13;
                    let _e1222 = local_11;
                    phi_1234_ = _e1220;
                    phi_134_ = (_e1221 + _e1222);
                } else {
                    phi_1234_ = _e220;
                    phi_134_ = u32();
                }
                let _e1225 = phi_1234_;
                let _e1227 = phi_134_;
                continue;
                continuing {
                    let _e1228 = local_14;
                    phi_1166_ = _e1225;
                    phi_133_ = _e1227;
                    phi_1233_ = _e1225;
                    break if !(_e1228);
                }
            }
            let _e1231 = phi_1233_;
            if _e1231 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn frame_from_images(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
