struct type_3 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_5 {
    member: array<u32>,
}

struct type_15 {
    member: u32,
    member_1: u32,
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

struct type_17 {
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
    member_15: type_3,
    member_16: type_16,
    member_17: u32,
    member_18: u32,
}

struct type_18 {
    member: type_17,
}

struct type_20 {
    member: u32,
    member_1: type_15,
}

struct type_26 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<workgroup> global_1: array<u32, 512>;
var<immediate> global_2: type_18;
@group(0) @binding(3) 
var<storage, read_write> global_3: type_26;
@group(0) @binding(0) 
var<storage> global_4: type_5;
@group(0) @binding(1) 
var<storage, read_write> global_5: type_5;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_5;

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
    var local_13: bool;
    var local_14: u32;
    var local_15: u32;
    var local_16: type_20;
    var local_17: bool;
    var local_18: bool;
    var local_19: u32;
    var local_20: bool;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: bool;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: bool;
    var local_34: u32;
    var local_35: u32;
    var local_36: type_20;
    var local_37: bool;
    var local_38: u32;
    var local_39: bool;
    var local_40: u32;
    var local_41: u32;
    var local_42: bool;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: bool;
    var local_48: u32;
    var local_49: u32;
    var local_50: type_20;
    var local_51: bool;
    var local_52: u32;
    var local_53: u32;
    var local_54: bool;
    var local_55: u32;
    var local_56: u32;
    var local_57: u32;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: u32;
    var local_62: type_20;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: u32;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: bool;
    var local_72: u32;
    var local_73: u32;
    var local_74: bool;
    var local_75: u32;
    var local_76: u32;
    var local_77: type_20;
    var local_78: type_20;
    var local_79: u32;
    var local_80: u32;
    var local_81: u32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: bool;
    var local_87: u32;
    var local_88: u32;
    var local_89: u32;
    var local_90: u32;
    var local_91: u32;
    var phi_121_: u32;
    var phi_1123_: bool;
    var phi_127_: u32;
    var phi_130_: u32;
    var phi_167_: u32;
    var phi_198_: u32;
    var phi_168_: u32;
    var phi_199_: bool;
    var phi_1119_: bool;
    var phi_231_: type_20;
    var phi_240_: u32;
    var phi_1128_: bool;
    var phi_241_: u32;
    var phi_1127_: bool;
    var phi_243_: u32;
    var phi_244_: u32;
    var phi_1126_: bool;
    var phi_128_: u32;
    var phi_131_: u32;
    var phi_245_: bool;
    var phi_1125_: bool;
    var phi_258_: u32;
    var phi_259_: u32;
    var phi_1131_: bool;
    var phi_1141_: bool;
    var phi_310_: u32;
    var phi_313_: u32;
    var phi_337_: u32;
    var phi_1139_: bool;
    var phi_342_: u32;
    var phi_345_: u32;
    var phi_382_: u32;
    var phi_413_: u32;
    var phi_383_: u32;
    var phi_414_: bool;
    var phi_1135_: bool;
    var phi_446_: type_20;
    var phi_455_: u32;
    var phi_1146_: bool;
    var phi_456_: u32;
    var phi_1145_: bool;
    var phi_458_: u32;
    var phi_459_: u32;
    var phi_1144_: bool;
    var phi_343_: u32;
    var phi_346_: u32;
    var phi_460_: bool;
    var phi_1143_: bool;
    var phi_473_: u32;
    var phi_474_: u32;
    var phi_1149_: bool;
    var phi_524_: u32;
    var phi_1154_: bool;
    var phi_311_: u32;
    var phi_314_: u32;
    var phi_1153_: bool;
    var phi_1160_: bool;
    var phi_529_: u32;
    var phi_532_: u32;
    var phi_569_: u32;
    var phi_600_: u32;
    var phi_570_: u32;
    var phi_601_: bool;
    var phi_1156_: bool;
    var phi_633_: type_20;
    var phi_642_: u32;
    var phi_1164_: bool;
    var phi_643_: u32;
    var phi_1163_: bool;
    var phi_645_: u32;
    var phi_646_: u32;
    var phi_1162_: bool;
    var phi_530_: u32;
    var phi_533_: u32;
    var phi_647_: bool;
    var phi_1161_: bool;
    var phi_659_: u32;
    var phi_662_: u32;
    var phi_698_: u32;
    var phi_660_: u32;
    var phi_663_: u32;
    var phi_1167_: bool;
    var phi_726_: u32;
    var phi_1178_: bool;
    var phi_730_: u32;
    var phi_733_: type_20;
    var phi_735_: u32;
    var phi_737_: u32;
    var phi_739_: u32;
    var phi_741_: u32;
    var phi_743_: u32;
    var phi_745_: u32;
    var phi_803_: u32;
    var phi_834_: u32;
    var phi_804_: u32;
    var phi_835_: bool;
    var phi_1173_: bool;
    var phi_867_: type_20;
    var phi_1188_: bool;
    var phi_869_: type_20;
    var phi_896_: type_20;
    var phi_898_: type_20;
    var phi_982_: u32;
    var phi_983_: u32;
    var phi_944_: u32;
    var phi_945_: u32;
    var phi_984_: u32;
    var phi_985_: u32;
    var phi_986_: u32;
    var phi_987_: u32;
    var phi_988_: u32;
    var phi_1182_: bool;
    var phi_990_: u32;
    var phi_991_: type_20;
    var phi_992_: u32;
    var phi_993_: u32;
    var phi_994_: u32;
    var phi_995_: u32;
    var phi_996_: u32;
    var phi_997_: u32;
    var phi_1181_: bool;
    var phi_731_: u32;
    var phi_734_: type_20;
    var phi_736_: u32;
    var phi_738_: u32;
    var phi_740_: u32;
    var phi_742_: u32;
    var phi_744_: u32;
    var phi_746_: u32;
    var phi_998_: bool;
    var phi_1180_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e124 = global;
            local = _e124;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_3.member));
            let _e135 = global_2.member.member_7;
            let _e138 = global_2.member.member_8;
            let _e139 = (_e135 * _e138);
            local_5 = _e139;
            let _e140 = (_e139 / 256u);
            local_6 = _e140;
            if ((_e139 % 256u) > 0u) {
                let _e143 = local_6;
                phi_121_ = (_e143 + 1u);
            } else {
                phi_121_ = _e140;
            }
            let _e146 = phi_121_;
            local_7 = _e146;
            let _e149 = global_2.member.member_18;
            local_8 = _e149;
            let _e150 = local;
            let _e151 = (_e150 * _e146);
            phi_1123_ = false;
            phi_127_ = _e151;
            phi_130_ = 0u;
            loop {
                let _e153 = phi_1123_;
                let _e155 = phi_127_;
                let _e157 = phi_130_;
                local_9 = _e155;
                local_10 = _e157;
                let _e158 = local_9;
                let _e159 = local_5;
                if (_e158 < _e159) {
                    let _e161 = local;
                    let _e163 = local_7;
                    let _e165 = local_9;
                    let _e166 = (_e165 < ((_e161 + 1u) * _e163));
                    if _e166 {
                        let _e167 = local_9;
                        let _e168 = local_2;
                        if (_e167 < _e168) {
                        } else {
                            phi_1125_ = true;
                            break;
                        }
                        let _e170 = local_9;
                        let _e173 = global_5.member[_e170];
                        if ((_e173 & 1u) == 0u) {
                            phi_167_ = 0u;
                            loop {
                                let _e177 = phi_167_;
                                local_11 = _e177;
                                let _e178 = local_11;
                                if (_e178 < 4u) {
                                    let _e180 = local_9;
                                    let _e182 = local_11;
                                    let _e183 = ((_e180 * 5u) + _e182);
                                    local_12 = _e183;
                                    let _e184 = local_1;
                                    if (_e183 < _e184) {
                                    } else {
                                        phi_1119_ = true;
                                        break;
                                    }
                                    let _e186 = local_12;
                                    let _e189 = global_4.member[_e186];
                                    let _e190 = local_8;
                                    let _e191 = (_e189 > _e190);
                                    if _e191 {
                                        let _e192 = local_11;
                                        phi_198_ = (_e192 + 1u);
                                    } else {
                                        phi_198_ = u32();
                                    }
                                    let _e195 = phi_198_;
                                    phi_168_ = _e195;
                                    phi_199_ = _e191;
                                } else {
                                    phi_168_ = u32();
                                    phi_199_ = false;
                                }
                                let _e197 = phi_168_;
                                let _e199 = phi_199_;
                                local_13 = _e199;
                                continue;
                                continuing {
                                    let _e200 = local_13;
                                    phi_167_ = _e197;
                                    phi_1119_ = _e153;
                                    break if !(_e200);
                                }
                            }
                            let _e203 = phi_1119_;
                            phi_1125_ = _e203;
                            if _e203 {
                                break;
                            }
                            let _e204 = local_9;
                            let _e206 = local_11;
                            let _e207 = ((_e204 * 5u) + _e206);
                            local_14 = _e207;
                            let _e208 = local_1;
                            if (_e207 < _e208) {
                            } else {
                                phi_1125_ = true;
                                break;
                            }
                            let _e210 = local_14;
                            let _e213 = global_4.member[_e210];
                            local_15 = _e213;
                            let _e214 = local_8;
                            if (_e213 <= _e214) {
                                let _e219 = local_11;
                                let _e220 = local_15;
                                phi_231_ = type_20(1u, type_15(_e219, _e220));
                            } else {
                                phi_231_ = type_20(0u, type_20().member_1);
                            }
                            let _e224 = phi_231_;
                            local_16 = _e224;
                            if (bitcast<i32>(_e224.member) != 0i) {
                                let _e228 = local_16;
                                let _e231 = local_10;
                                phi_240_ = (_e231 + _e228.member_1.member_1);
                            } else {
                                phi_240_ = _e157;
                            }
                            let _e234 = phi_240_;
                            phi_1128_ = _e203;
                            phi_241_ = _e234;
                        } else {
                            phi_1128_ = _e153;
                            phi_241_ = _e157;
                        }
                        let _e236 = phi_1128_;
                        let _e238 = phi_241_;
                        let _e239 = local_9;
                        phi_1127_ = _e236;
                        phi_243_ = (_e239 + 1u);
                        phi_244_ = _e238;
                    } else {
                        phi_1127_ = _e153;
                        phi_243_ = u32();
                        phi_244_ = u32();
                    }
                    let _e242 = phi_1127_;
                    let _e244 = phi_243_;
                    let _e246 = phi_244_;
                    phi_1126_ = _e242;
                    phi_128_ = _e244;
                    phi_131_ = _e246;
                    phi_245_ = _e166;
                } else {
                    phi_1126_ = _e153;
                    phi_128_ = u32();
                    phi_131_ = u32();
                    phi_245_ = false;
                }
                let _e248 = phi_1126_;
                let _e250 = phi_128_;
                let _e252 = phi_131_;
                let _e254 = phi_245_;
                local_17 = _e254;
                continue;
                continuing {
                    let _e255 = local_17;
                    phi_1123_ = _e248;
                    phi_127_ = _e250;
                    phi_130_ = _e252;
                    phi_1125_ = _e248;
                    break if !(_e255);
                }
            }
            let _e258 = phi_1125_;
            if _e258 {
                break;
            }
            let _e259 = local;
            let _e260 = (_e259 < 512u);
            local_18 = _e260;
            if _e260 {
            } else {
                break;
            }
            let _e261 = local;
            let _e263 = local_10;
            global_1[_e261] = _e263;
            storageBarrier();
            workgroupBarrier();
            phi_258_ = 128u;
            loop {
                let _e265 = phi_258_;
                local_19 = _e265;
                let _e266 = local_19;
                let _e267 = (_e266 > 0u);
                local_20 = _e267;
                if _e267 {
                    let _e268 = local;
                    let _e269 = local_19;
                    if (_e268 < _e269) {
                        let _e271 = local_18;
                        if _e271 {
                        } else {
                            phi_1131_ = true;
                            break;
                        }
                        let _e272 = global_1[_e261];
                        local_21 = _e272;
                        let _e273 = local;
                        let _e274 = local_19;
                        let _e275 = (_e273 + _e274);
                        local_22 = _e275;
                        if (_e275 < 512u) {
                        } else {
                            phi_1131_ = true;
                            break;
                        }
                        let _e277 = local_22;
                        let _e279 = global_1[_e277];
                        let _e280 = local_21;
                        local_89 = (_e280 + _e279);
                        let _e282 = local_18;
                        if _e282 {
                        } else {
                            phi_1131_ = true;
                            break;
                        }
                        let _e283 = local_89;
                        global_1[_e261] = _e283;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e284 = local_19;
                    phi_259_ = (_e284 / 2u);
                } else {
                    phi_259_ = u32();
                }
                let _e287 = phi_259_;
                continue;
                continuing {
                    let _e288 = local_20;
                    phi_258_ = _e287;
                    phi_1131_ = _e258;
                    break if !(_e288);
                }
            }
            let _e291 = phi_1131_;
            if _e291 {
                break;
            }
            let _e293 = global_1[0u];
            storageBarrier();
            workgroupBarrier();
            let _e296 = global_2.member.member_17;
            local_23 = _e296;
            let _e298 = local_8;
            phi_1141_ = _e291;
            phi_310_ = _e149;
            phi_313_ = select(0u, _e298, (_e293 <= _e296));
            loop {
                let _e301 = phi_1141_;
                let _e303 = phi_310_;
                let _e305 = phi_313_;
                local_24 = _e303;
                local_25 = _e305;
                let _e306 = local_25;
                let _e307 = local_24;
                let _e308 = (_e306 < _e307);
                local_26 = _e308;
                if _e308 {
                    let _e309 = local_24;
                    let _e310 = local_25;
                    let _e311 = (_e309 - _e310);
                    let _e312 = (_e311 / 2u);
                    local_27 = _e312;
                    if ((_e311 % 2u) > 0u) {
                        let _e315 = local_27;
                        phi_337_ = (_e315 + 1u);
                    } else {
                        phi_337_ = _e312;
                    }
                    let _e318 = phi_337_;
                    let _e319 = local_25;
                    local_28 = (_e319 + _e318);
                    phi_1139_ = _e301;
                    phi_342_ = _e151;
                    phi_345_ = 0u;
                    loop {
                        let _e322 = phi_1139_;
                        let _e324 = phi_342_;
                        let _e326 = phi_345_;
                        local_29 = _e324;
                        local_30 = _e326;
                        let _e327 = local_29;
                        let _e328 = local_5;
                        if (_e327 < _e328) {
                            let _e330 = local;
                            let _e332 = local_7;
                            let _e334 = local_29;
                            let _e335 = (_e334 < ((_e330 + 1u) * _e332));
                            if _e335 {
                                let _e336 = local_29;
                                let _e337 = local_2;
                                if (_e336 < _e337) {
                                } else {
                                    phi_1143_ = true;
                                    break;
                                }
                                let _e339 = local_29;
                                let _e342 = global_5.member[_e339];
                                if ((_e342 & 1u) == 0u) {
                                    phi_382_ = 0u;
                                    loop {
                                        let _e346 = phi_382_;
                                        local_31 = _e346;
                                        let _e347 = local_31;
                                        if (_e347 < 4u) {
                                            let _e349 = local_29;
                                            let _e351 = local_31;
                                            let _e352 = ((_e349 * 5u) + _e351);
                                            local_32 = _e352;
                                            let _e353 = local_1;
                                            if (_e352 < _e353) {
                                            } else {
                                                phi_1135_ = true;
                                                break;
                                            }
                                            let _e355 = local_32;
                                            let _e358 = global_4.member[_e355];
                                            let _e359 = local_28;
                                            let _e360 = (_e358 > _e359);
                                            if _e360 {
                                                let _e361 = local_31;
                                                phi_413_ = (_e361 + 1u);
                                            } else {
                                                phi_413_ = u32();
                                            }
                                            let _e364 = phi_413_;
                                            phi_383_ = _e364;
                                            phi_414_ = _e360;
                                        } else {
                                            phi_383_ = u32();
                                            phi_414_ = false;
                                        }
                                        let _e366 = phi_383_;
                                        let _e368 = phi_414_;
                                        local_33 = _e368;
                                        continue;
                                        continuing {
                                            let _e369 = local_33;
                                            phi_382_ = _e366;
                                            phi_1135_ = _e322;
                                            break if !(_e369);
                                        }
                                    }
                                    let _e372 = phi_1135_;
                                    phi_1143_ = _e372;
                                    if _e372 {
                                        break;
                                    }
                                    let _e373 = local_29;
                                    let _e375 = local_31;
                                    let _e376 = ((_e373 * 5u) + _e375);
                                    local_34 = _e376;
                                    let _e377 = local_1;
                                    if (_e376 < _e377) {
                                    } else {
                                        phi_1143_ = true;
                                        break;
                                    }
                                    let _e379 = local_34;
                                    let _e382 = global_4.member[_e379];
                                    local_35 = _e382;
                                    let _e383 = local_8;
                                    if (_e382 <= _e383) {
                                        let _e388 = local_31;
                                        let _e389 = local_35;
                                        phi_446_ = type_20(1u, type_15(_e388, _e389));
                                    } else {
                                        phi_446_ = type_20(0u, type_20().member_1);
                                    }
                                    let _e393 = phi_446_;
                                    local_36 = _e393;
                                    if (bitcast<i32>(_e393.member) != 0i) {
                                        let _e397 = local_36;
                                        let _e400 = local_30;
                                        phi_455_ = (_e400 + _e397.member_1.member_1);
                                    } else {
                                        phi_455_ = _e326;
                                    }
                                    let _e403 = phi_455_;
                                    phi_1146_ = _e372;
                                    phi_456_ = _e403;
                                } else {
                                    phi_1146_ = _e322;
                                    phi_456_ = _e326;
                                }
                                let _e405 = phi_1146_;
                                let _e407 = phi_456_;
                                let _e408 = local_29;
                                phi_1145_ = _e405;
                                phi_458_ = (_e408 + 1u);
                                phi_459_ = _e407;
                            } else {
                                phi_1145_ = _e322;
                                phi_458_ = u32();
                                phi_459_ = u32();
                            }
                            let _e411 = phi_1145_;
                            let _e413 = phi_458_;
                            let _e415 = phi_459_;
                            phi_1144_ = _e411;
                            phi_343_ = _e413;
                            phi_346_ = _e415;
                            phi_460_ = _e335;
                        } else {
                            phi_1144_ = _e322;
                            phi_343_ = u32();
                            phi_346_ = u32();
                            phi_460_ = false;
                        }
                        let _e417 = phi_1144_;
                        let _e419 = phi_343_;
                        let _e421 = phi_346_;
                        let _e423 = phi_460_;
                        local_37 = _e423;
                        continue;
                        continuing {
                            let _e424 = local_37;
                            phi_1139_ = _e417;
                            phi_342_ = _e419;
                            phi_345_ = _e421;
                            phi_1143_ = _e417;
                            break if !(_e424);
                        }
                    }
                    let _e427 = phi_1143_;
                    phi_1153_ = _e427;
                    if _e427 {
                        break;
                    }
                    let _e428 = local_18;
                    if _e428 {
                    } else {
                        phi_1153_ = true;
                        break;
                    }
                    let _e429 = local_30;
                    global_1[_e261] = _e429;
                    storageBarrier();
                    workgroupBarrier();
                    phi_473_ = 128u;
                    loop {
                        let _e431 = phi_473_;
                        local_38 = _e431;
                        let _e432 = local_38;
                        let _e433 = (_e432 > 0u);
                        local_39 = _e433;
                        if _e433 {
                            let _e434 = local;
                            let _e435 = local_38;
                            if (_e434 < _e435) {
                                let _e437 = local_18;
                                if _e437 {
                                } else {
                                    phi_1149_ = true;
                                    break;
                                }
                                let _e438 = global_1[_e261];
                                local_40 = _e438;
                                let _e439 = local;
                                let _e440 = local_38;
                                let _e441 = (_e439 + _e440);
                                local_41 = _e441;
                                if (_e441 < 512u) {
                                } else {
                                    phi_1149_ = true;
                                    break;
                                }
                                let _e443 = local_41;
                                let _e445 = global_1[_e443];
                                let _e446 = local_40;
                                local_90 = (_e446 + _e445);
                                let _e448 = local_18;
                                if _e448 {
                                } else {
                                    phi_1149_ = true;
                                    break;
                                }
                                let _e449 = local_90;
                                global_1[_e261] = _e449;
                            }
                            storageBarrier();
                            workgroupBarrier();
                            let _e450 = local_38;
                            phi_474_ = (_e450 / 2u);
                        } else {
                            phi_474_ = u32();
                        }
                        let _e453 = phi_474_;
                        continue;
                        continuing {
                            let _e454 = local_39;
                            phi_473_ = _e453;
                            phi_1149_ = _e427;
                            break if !(_e454);
                        }
                    }
                    let _e457 = phi_1149_;
                    phi_1153_ = _e457;
                    if _e457 {
                        break;
                    }
                    let _e458 = global_1[0u];
                    storageBarrier();
                    workgroupBarrier();
                    let _e459 = local_23;
                    let _e460 = (_e458 <= _e459);
                    local_42 = _e460;
                    if _e460 {
                        phi_524_ = _e303;
                    } else {
                        let _e461 = local_28;
                        phi_524_ = (_e461 - 1u);
                    }
                    let _e464 = phi_524_;
                    let _e465 = local_42;
                    let _e466 = local_28;
                    let _e467 = local_25;
                    phi_1154_ = _e457;
                    phi_311_ = _e464;
                    phi_314_ = select(_e467, _e466, _e465);
                } else {
                    phi_1154_ = _e301;
                    phi_311_ = u32();
                    phi_314_ = u32();
                }
                let _e470 = phi_1154_;
                let _e472 = phi_311_;
                let _e474 = phi_314_;
                continue;
                continuing {
                    let _e475 = local_26;
                    phi_1141_ = _e470;
                    phi_310_ = _e472;
                    phi_313_ = _e474;
                    phi_1153_ = _e470;
                    break if !(_e475);
                }
            }
            let _e478 = phi_1153_;
            if _e478 {
                break;
            }
            phi_1160_ = _e478;
            phi_529_ = _e151;
            phi_532_ = 0u;
            loop {
                let _e480 = phi_1160_;
                let _e482 = phi_529_;
                let _e484 = phi_532_;
                local_43 = _e482;
                local_44 = _e484;
                let _e485 = local_43;
                let _e486 = local_5;
                if (_e485 < _e486) {
                    let _e488 = local;
                    let _e490 = local_7;
                    let _e492 = local_43;
                    let _e493 = (_e492 < ((_e488 + 1u) * _e490));
                    if _e493 {
                        let _e494 = local_43;
                        let _e495 = local_2;
                        if (_e494 < _e495) {
                        } else {
                            phi_1161_ = true;
                            break;
                        }
                        let _e497 = local_43;
                        let _e500 = global_5.member[_e497];
                        if ((_e500 & 1u) == 0u) {
                            phi_569_ = 0u;
                            loop {
                                let _e504 = phi_569_;
                                local_45 = _e504;
                                let _e505 = local_45;
                                if (_e505 < 4u) {
                                    let _e507 = local_43;
                                    let _e509 = local_45;
                                    let _e510 = ((_e507 * 5u) + _e509);
                                    local_46 = _e510;
                                    let _e511 = local_1;
                                    if (_e510 < _e511) {
                                    } else {
                                        phi_1156_ = true;
                                        break;
                                    }
                                    let _e513 = local_46;
                                    let _e516 = global_4.member[_e513];
                                    let _e517 = local_25;
                                    let _e518 = (_e516 > _e517);
                                    if _e518 {
                                        let _e519 = local_45;
                                        phi_600_ = (_e519 + 1u);
                                    } else {
                                        phi_600_ = u32();
                                    }
                                    let _e522 = phi_600_;
                                    phi_570_ = _e522;
                                    phi_601_ = _e518;
                                } else {
                                    phi_570_ = u32();
                                    phi_601_ = false;
                                }
                                let _e524 = phi_570_;
                                let _e526 = phi_601_;
                                local_47 = _e526;
                                continue;
                                continuing {
                                    let _e527 = local_47;
                                    phi_569_ = _e524;
                                    phi_1156_ = _e480;
                                    break if !(_e527);
                                }
                            }
                            let _e530 = phi_1156_;
                            phi_1161_ = _e530;
                            if _e530 {
                                break;
                            }
                            let _e531 = local_43;
                            let _e533 = local_45;
                            let _e534 = ((_e531 * 5u) + _e533);
                            local_48 = _e534;
                            let _e535 = local_1;
                            if (_e534 < _e535) {
                            } else {
                                phi_1161_ = true;
                                break;
                            }
                            let _e537 = local_48;
                            let _e540 = global_4.member[_e537];
                            local_49 = _e540;
                            let _e541 = local_8;
                            if (_e540 <= _e541) {
                                let _e546 = local_45;
                                let _e547 = local_49;
                                phi_633_ = type_20(1u, type_15(_e546, _e547));
                            } else {
                                phi_633_ = type_20(0u, type_20().member_1);
                            }
                            let _e551 = phi_633_;
                            local_50 = _e551;
                            if (bitcast<i32>(_e551.member) != 0i) {
                                let _e555 = local_50;
                                let _e558 = local_44;
                                phi_642_ = (_e558 + _e555.member_1.member_1);
                            } else {
                                phi_642_ = _e484;
                            }
                            let _e561 = phi_642_;
                            phi_1164_ = _e530;
                            phi_643_ = _e561;
                        } else {
                            phi_1164_ = _e480;
                            phi_643_ = _e484;
                        }
                        let _e563 = phi_1164_;
                        let _e565 = phi_643_;
                        let _e566 = local_43;
                        phi_1163_ = _e563;
                        phi_645_ = (_e566 + 1u);
                        phi_646_ = _e565;
                    } else {
                        phi_1163_ = _e480;
                        phi_645_ = u32();
                        phi_646_ = u32();
                    }
                    let _e569 = phi_1163_;
                    let _e571 = phi_645_;
                    let _e573 = phi_646_;
                    phi_1162_ = _e569;
                    phi_530_ = _e571;
                    phi_533_ = _e573;
                    phi_647_ = _e493;
                } else {
                    phi_1162_ = _e480;
                    phi_530_ = u32();
                    phi_533_ = u32();
                    phi_647_ = false;
                }
                let _e575 = phi_1162_;
                let _e577 = phi_530_;
                let _e579 = phi_533_;
                let _e581 = phi_647_;
                local_51 = _e581;
                continue;
                continuing {
                    let _e582 = local_51;
                    phi_1160_ = _e575;
                    phi_529_ = _e577;
                    phi_532_ = _e579;
                    phi_1161_ = _e575;
                    break if !(_e582);
                }
            }
            let _e585 = phi_1161_;
            if _e585 {
                break;
            }
            let _e586 = local_18;
            if _e586 {
            } else {
                break;
            }
            let _e587 = local_44;
            global_1[_e261] = _e587;
            storageBarrier();
            workgroupBarrier();
            phi_659_ = 1u;
            phi_662_ = 0u;
            loop {
                let _e589 = phi_659_;
                let _e591 = phi_662_;
                local_52 = _e589;
                local_53 = _e591;
                let _e592 = local_52;
                let _e593 = (_e592 < 256u);
                local_54 = _e593;
                if _e593 {
                    let _e594 = local_53;
                    let _e596 = select(0u, 256u, (_e594 == 0u));
                    local_91 = _e596;
                    let _e597 = local_53;
                    let _e598 = local;
                    let _e599 = (_e597 + _e598);
                    local_55 = _e599;
                    if (_e599 < 512u) {
                    } else {
                        phi_1167_ = true;
                        break;
                    }
                    let _e601 = local_55;
                    let _e603 = global_1[_e601];
                    local_56 = _e603;
                    let _e604 = local;
                    let _e605 = local_52;
                    if (_e604 >= _e605) {
                        let _e607 = local;
                        let _e608 = local_52;
                        let _e610 = local_53;
                        let _e611 = (_e610 + (_e607 - _e608));
                        local_57 = _e611;
                        if (_e611 < 512u) {
                        } else {
                            phi_1167_ = true;
                            break;
                        }
                        let _e613 = local_57;
                        let _e615 = global_1[_e613];
                        let _e616 = local_56;
                        phi_698_ = (_e615 + _e616);
                    } else {
                        phi_698_ = _e603;
                    }
                    let _e619 = phi_698_;
                    local_58 = _e619;
                    let _e620 = local_91;
                    let _e621 = local;
                    let _e622 = (_e620 + _e621);
                    local_59 = _e622;
                    if (_e622 < 512u) {
                    } else {
                        phi_1167_ = true;
                        break;
                    }
                    let _e624 = local_59;
                    let _e626 = local_58;
                    global_1[_e624] = _e626;
                    storageBarrier();
                    workgroupBarrier();
                    let _e627 = local_52;
                    phi_660_ = (_e627 * 2u);
                    phi_663_ = _e596;
                } else {
                    phi_660_ = u32();
                    phi_663_ = u32();
                }
                let _e630 = phi_660_;
                let _e632 = phi_663_;
                continue;
                continuing {
                    let _e633 = local_54;
                    phi_659_ = _e630;
                    phi_662_ = _e632;
                    phi_1167_ = _e585;
                    break if !(_e633);
                }
            }
            let _e636 = phi_1167_;
            if _e636 {
                break;
            }
            let _e637 = local;
            if (_e637 == 0u) {
                phi_726_ = 0u;
            } else {
                let _e639 = local_53;
                let _e640 = local;
                let _e642 = ((_e639 + _e640) - 1u);
                local_60 = _e642;
                if (_e642 < 512u) {
                } else {
                    break;
                }
                let _e644 = local_60;
                let _e646 = global_1[_e644];
                phi_726_ = _e646;
            }
            let _e648 = phi_726_;
            phi_1178_ = _e636;
            phi_730_ = _e648;
            phi_733_ = type_20();
            phi_735_ = _e151;
            phi_737_ = 0u;
            phi_739_ = 0u;
            phi_741_ = 0u;
            phi_743_ = 0u;
            phi_745_ = 0u;
            loop {
                let _e650 = phi_1178_;
                let _e652 = phi_730_;
                let _e654 = phi_733_;
                let _e656 = phi_735_;
                let _e658 = phi_737_;
                let _e660 = phi_739_;
                let _e662 = phi_741_;
                let _e664 = phi_743_;
                let _e666 = phi_745_;
                local_61 = _e652;
                local_62 = _e654;
                local_63 = _e656;
                local_64 = _e658;
                local_65 = _e660;
                local_66 = _e662;
                local_67 = _e664;
                local_68 = _e666;
                let _e667 = local_63;
                let _e668 = local_5;
                if (_e667 < _e668) {
                    let _e670 = local;
                    let _e672 = local_7;
                    let _e674 = local_63;
                    let _e675 = (_e674 < ((_e670 + 1u) * _e672));
                    if _e675 {
                        let _e676 = local_63;
                        let _e677 = (_e676 * 5u);
                        local_69 = _e677;
                        let _e678 = local_1;
                        if (_e677 < _e678) {
                        } else {
                            phi_1180_ = true;
                            break;
                        }
                        let _e680 = local_69;
                        let _e683 = global_4.member[_e680];
                        local_70 = _e683;
                        let _e684 = local_64;
                        let _e686 = local_64;
                        let _e688 = local_63;
                        let _e689 = local_2;
                        let _e690 = (_e688 < _e689);
                        local_71 = _e690;
                        if _e690 {
                        } else {
                            phi_1180_ = true;
                            break;
                        }
                        let _e691 = local_63;
                        let _e694 = global_5.member[_e691];
                        if ((_e694 & 1u) == 0u) {
                            phi_803_ = 0u;
                            loop {
                                let _e702 = phi_803_;
                                local_72 = _e702;
                                let _e703 = local_72;
                                if (_e703 < 4u) {
                                    let _e705 = local_69;
                                    let _e706 = local_72;
                                    let _e707 = (_e705 + _e706);
                                    local_73 = _e707;
                                    let _e708 = local_1;
                                    if (_e707 < _e708) {
                                    } else {
                                        phi_1173_ = true;
                                        break;
                                    }
                                    let _e710 = local_73;
                                    let _e713 = global_4.member[_e710];
                                    let _e714 = local_25;
                                    let _e715 = (_e713 > _e714);
                                    if _e715 {
                                        let _e716 = local_72;
                                        phi_834_ = (_e716 + 1u);
                                    } else {
                                        phi_834_ = u32();
                                    }
                                    let _e719 = phi_834_;
                                    phi_804_ = _e719;
                                    phi_835_ = _e715;
                                } else {
                                    phi_804_ = u32();
                                    phi_835_ = false;
                                }
                                let _e721 = phi_804_;
                                let _e723 = phi_835_;
                                local_74 = _e723;
                                continue;
                                continuing {
                                    let _e724 = local_74;
                                    phi_803_ = _e721;
                                    phi_1173_ = _e650;
                                    break if !(_e724);
                                }
                            }
                            let _e727 = phi_1173_;
                            phi_1180_ = _e727;
                            if _e727 {
                                break;
                            }
                            let _e728 = local_69;
                            let _e729 = local_72;
                            let _e730 = (_e728 + _e729);
                            local_75 = _e730;
                            let _e731 = local_1;
                            if (_e730 < _e731) {
                            } else {
                                phi_1180_ = true;
                                break;
                            }
                            let _e733 = local_75;
                            let _e736 = global_4.member[_e733];
                            local_76 = _e736;
                            let _e737 = local_8;
                            if (_e736 <= _e737) {
                                let _e742 = local_72;
                                let _e743 = local_76;
                                phi_867_ = type_20(1u, type_15(_e742, _e743));
                            } else {
                                phi_867_ = type_20(0u, type_20().member_1);
                            }
                            let _e747 = phi_867_;
                            phi_1188_ = _e727;
                            phi_869_ = _e747;
                        } else {
                            let _e697 = local_62;
                            phi_1188_ = _e650;
                            phi_869_ = type_20(0u, _e697.member_1);
                        }
                        let _e749 = phi_1188_;
                        let _e751 = phi_869_;
                        local_77 = _e751;
                        if (bitcast<i32>(_e751.member) != 0i) {
                            let _e758 = local_77;
                            let _e761 = local_23;
                            let _e762 = local_61;
                            let _e764 = local_23;
                            let _e765 = local_61;
                            let _e767 = local_23;
                            if (_e758.member_1.member_1 <= (_e767 - select(_e765, _e764, (_e761 < _e762)))) {
                                let _e773 = local_77;
                                phi_896_ = type_20(1u, _e773.member_1);
                            } else {
                                phi_896_ = type_20(0u, type_20().member_1);
                            }
                            let _e777 = phi_896_;
                            phi_898_ = _e777;
                        } else {
                            phi_898_ = type_20(0u, type_20().member_1);
                        }
                        let _e779 = phi_898_;
                        local_78 = _e779;
                        if (bitcast<i32>(_e779.member) != 0i) {
                            let _e809 = local_78;
                            local_79 = _e809.member_1.member;
                            let _e812 = local_78;
                            local_80 = _e812.member_1.member_1;
                            let _e815 = local_63;
                            let _e816 = (2u * _e815);
                            local_81 = _e816;
                            let _e817 = local_3;
                            if (_e816 < _e817) {
                            } else {
                                phi_1180_ = true;
                                break;
                            }
                            let _e819 = local_81;
                            let _e822 = local_61;
                            global_6.member[_e819] = _e822;
                            let _e823 = local_81;
                            let _e824 = (_e823 + 1u);
                            local_82 = _e824;
                            let _e825 = local_3;
                            if (_e824 < _e825) {
                            } else {
                                phi_1180_ = true;
                                break;
                            }
                            let _e827 = local_82;
                            let _e830 = local_80;
                            global_6.member[_e827] = _e830;
                            let _e831 = local_79;
                            local_83 = (_e831 << bitcast<u32>(1u));
                            let _e834 = local_71;
                            if _e834 {
                            } else {
                                phi_1180_ = true;
                                break;
                            }
                            let _e835 = local_83;
                            global_5.member[_e691] = _e835;
                            let _e836 = local_79;
                            if (_e836 > 0u) {
                                let _e838 = local_68;
                                let _e840 = local_70;
                                let _e841 = local_80;
                                let _e843 = local_67;
                                phi_944_ = (_e843 + (_e840 - _e841));
                                phi_945_ = (_e838 + 1u);
                            } else {
                                phi_944_ = _e664;
                                phi_945_ = _e666;
                            }
                            let _e846 = phi_944_;
                            let _e848 = phi_945_;
                            let _e849 = local_61;
                            let _e850 = local_80;
                            phi_984_ = (_e849 + _e850);
                            phi_985_ = _e660;
                            phi_986_ = _e662;
                            phi_987_ = _e846;
                            phi_988_ = _e848;
                        } else {
                            let _e783 = local_63;
                            let _e784 = (2u * _e783);
                            local_84 = _e784;
                            let _e785 = local_3;
                            if (_e784 < _e785) {
                            } else {
                                phi_1180_ = true;
                                break;
                            }
                            let _e787 = local_84;
                            global_6.member[_e787] = 0u;
                            let _e790 = local_84;
                            let _e791 = (_e790 + 1u);
                            local_85 = _e791;
                            let _e792 = local_3;
                            if (_e791 < _e792) {
                            } else {
                                phi_1180_ = true;
                                break;
                            }
                            let _e794 = local_85;
                            global_6.member[_e794] = 0u;
                            let _e797 = local_70;
                            if (_e797 > 0u) {
                                let _e799 = local_71;
                                if _e799 {
                                } else {
                                    phi_1180_ = true;
                                    break;
                                }
                                global_5.member[_e691] = 1u;
                                let _e800 = local_66;
                                let _e802 = local_65;
                                let _e803 = local_70;
                                phi_982_ = (_e802 + _e803);
                                phi_983_ = (_e800 + 1u);
                            } else {
                                phi_982_ = _e660;
                                phi_983_ = _e662;
                            }
                            let _e806 = phi_982_;
                            let _e808 = phi_983_;
                            phi_984_ = _e652;
                            phi_985_ = _e806;
                            phi_986_ = _e808;
                            phi_987_ = _e664;
                            phi_988_ = _e666;
                        }
                        let _e853 = phi_984_;
                        let _e855 = phi_985_;
                        let _e857 = phi_986_;
                        let _e859 = phi_987_;
                        let _e861 = phi_988_;
                        let _e862 = local_63;
                        phi_1182_ = _e749;
                        phi_990_ = _e853;
                        phi_991_ = _e751;
                        phi_992_ = (_e862 + 1u);
                        phi_993_ = select(_e686, _e683, (_e683 > _e684));
                        phi_994_ = _e855;
                        phi_995_ = _e857;
                        phi_996_ = _e859;
                        phi_997_ = _e861;
                    } else {
                        phi_1182_ = _e650;
                        phi_990_ = u32();
                        phi_991_ = type_20();
                        phi_992_ = u32();
                        phi_993_ = u32();
                        phi_994_ = u32();
                        phi_995_ = u32();
                        phi_996_ = u32();
                        phi_997_ = u32();
                    }
                    let _e865 = phi_1182_;
                    let _e867 = phi_990_;
                    let _e869 = phi_991_;
                    let _e871 = phi_992_;
                    let _e873 = phi_993_;
                    let _e875 = phi_994_;
                    let _e877 = phi_995_;
                    let _e879 = phi_996_;
                    let _e881 = phi_997_;
                    phi_1181_ = _e865;
                    phi_731_ = _e867;
                    phi_734_ = _e869;
                    phi_736_ = _e871;
                    phi_738_ = _e873;
                    phi_740_ = _e875;
                    phi_742_ = _e877;
                    phi_744_ = _e879;
                    phi_746_ = _e881;
                    phi_998_ = _e675;
                } else {
                    phi_1181_ = _e650;
                    phi_731_ = u32();
                    phi_734_ = type_20();
                    phi_736_ = u32();
                    phi_738_ = u32();
                    phi_740_ = u32();
                    phi_742_ = u32();
                    phi_744_ = u32();
                    phi_746_ = u32();
                    phi_998_ = false;
                }
                let _e883 = phi_1181_;
                let _e885 = phi_731_;
                let _e887 = phi_734_;
                let _e889 = phi_736_;
                let _e891 = phi_738_;
                let _e893 = phi_740_;
                let _e895 = phi_742_;
                let _e897 = phi_744_;
                let _e899 = phi_746_;
                let _e901 = phi_998_;
                local_86 = _e901;
                continue;
                continuing {
                    let _e902 = local_86;
                    phi_1178_ = _e883;
                    phi_730_ = _e885;
                    phi_733_ = _e887;
                    phi_735_ = _e889;
                    phi_737_ = _e891;
                    phi_739_ = _e893;
                    phi_741_ = _e895;
                    phi_743_ = _e897;
                    phi_745_ = _e899;
                    phi_1180_ = _e883;
                    break if !(_e902);
                }
            }
            let _e905 = phi_1180_;
            if _e905 {
                break;
            }
            let _e906 = local_68;
            if (_e906 > 0u) {
                let _e908 = local_4;
                if (22u < _e908) {
                } else {
                    break;
                }
                let _e912 = local_68;
                let _e913 = atomicAdd((&global_3.member[22u]), _e912);
                let _e914 = local_4;
                if (23u < _e914) {
                } else {
                    break;
                }
                let _e918 = local_67;
                let _e919 = atomicAdd((&global_3.member[23u]), _e918);
            }
            let _e920 = local_66;
            if (_e920 > 0u) {
                let _e922 = local_4;
                if (14u < _e922) {
                } else {
                    break;
                }
                let _e926 = local_66;
                let _e927 = atomicAdd((&global_3.member[14u]), _e926);
                let _e928 = local_4;
                if (15u < _e928) {
                } else {
                    break;
                }
                let _e932 = local_65;
                let _e933 = atomicAdd((&global_3.member[15u]), _e932);
            }
            let _e934 = local_64;
            if (_e934 > 0u) {
                let _e936 = local_4;
                if (8u < _e936) {
                } else {
                    break;
                }
                let _e940 = local_64;
                let _e941 = atomicMax((&global_3.member[8u]), _e940);
            }
            let _e942 = local;
            if (_e942 == 255u) {
                let _e944 = local_53;
                let _e945 = local;
                let _e946 = (_e944 + _e945);
                local_87 = _e946;
                if (_e946 < 512u) {
                } else {
                    break;
                }
                let _e948 = local_87;
                let _e950 = global_1[_e948];
                local_88 = _e950;
                let _e951 = local_4;
                if (16u < _e951) {
                } else {
                    break;
                }
                let _e955 = local_88;
                let _e956 = atomicAdd((&global_3.member[16u]), _e955);
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn splat_bin_plan(@builtin(local_invocation_index) param: u32) {
    global = param;
    function_();
}
