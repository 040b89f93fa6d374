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
    var local_26: u32;
    var local_27: bool;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: u32;
    var local_34: bool;
    var local_35: u32;
    var local_36: u32;
    var local_37: type_20;
    var local_38: bool;
    var local_39: u32;
    var local_40: bool;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: bool;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: bool;
    var local_50: u32;
    var local_51: u32;
    var local_52: type_20;
    var local_53: bool;
    var local_54: u32;
    var local_55: u32;
    var local_56: bool;
    var local_57: u32;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: u32;
    var local_62: u32;
    var local_63: u32;
    var local_64: type_20;
    var local_65: u32;
    var local_66: u32;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: u32;
    var local_72: u32;
    var local_73: bool;
    var local_74: u32;
    var local_75: u32;
    var local_76: bool;
    var local_77: u32;
    var local_78: u32;
    var local_79: type_20;
    var local_80: type_20;
    var local_81: u32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: u32;
    var local_88: bool;
    var local_89: u32;
    var local_90: u32;
    var local_91: u32;
    var phi_130_: u32;
    var phi_1444_: bool;
    var phi_136_: u32;
    var phi_139_: u32;
    var phi_176_: u32;
    var phi_207_: u32;
    var phi_177_: u32;
    var phi_208_: bool;
    var phi_1440_: bool;
    var phi_240_: type_20;
    var phi_249_: u32;
    var phi_1449_: bool;
    var phi_250_: u32;
    var phi_1448_: bool;
    var phi_252_: u32;
    var phi_253_: u32;
    var phi_1447_: bool;
    var phi_137_: u32;
    var phi_140_: u32;
    var phi_254_: bool;
    var phi_1446_: bool;
    var phi_353_: u32;
    var phi_354_: u32;
    var phi_1452_: bool;
    var phi_1480_: bool;
    var phi_406_: u32;
    var phi_409_: u32;
    var phi_433_: u32;
    var phi_1478_: bool;
    var phi_438_: u32;
    var phi_441_: u32;
    var phi_478_: u32;
    var phi_509_: u32;
    var phi_479_: u32;
    var phi_510_: bool;
    var phi_1474_: bool;
    var phi_542_: type_20;
    var phi_551_: u32;
    var phi_1487_: bool;
    var phi_552_: u32;
    var phi_1486_: bool;
    var phi_554_: u32;
    var phi_555_: u32;
    var phi_1485_: bool;
    var phi_439_: u32;
    var phi_442_: u32;
    var phi_556_: bool;
    var phi_1484_: bool;
    var phi_655_: u32;
    var phi_656_: u32;
    var phi_1490_: bool;
    var phi_707_: u32;
    var phi_1513_: bool;
    var phi_407_: u32;
    var phi_410_: u32;
    var phi_1512_: bool;
    var phi_1521_: bool;
    var phi_712_: u32;
    var phi_715_: u32;
    var phi_752_: u32;
    var phi_783_: u32;
    var phi_753_: u32;
    var phi_784_: bool;
    var phi_1517_: bool;
    var phi_816_: type_20;
    var phi_825_: u32;
    var phi_1525_: bool;
    var phi_826_: u32;
    var phi_1524_: bool;
    var phi_828_: u32;
    var phi_829_: u32;
    var phi_1523_: bool;
    var phi_713_: u32;
    var phi_716_: u32;
    var phi_830_: bool;
    var phi_1522_: bool;
    var phi_980_: u32;
    var phi_983_: u32;
    var phi_1019_: u32;
    var phi_981_: u32;
    var phi_984_: u32;
    var phi_1528_: bool;
    var phi_1048_: u32;
    var phi_1557_: bool;
    var phi_1052_: u32;
    var phi_1055_: type_20;
    var phi_1057_: u32;
    var phi_1059_: u32;
    var phi_1061_: u32;
    var phi_1063_: u32;
    var phi_1065_: u32;
    var phi_1067_: u32;
    var phi_1125_: u32;
    var phi_1156_: u32;
    var phi_1126_: u32;
    var phi_1157_: bool;
    var phi_1552_: bool;
    var phi_1189_: type_20;
    var phi_1568_: bool;
    var phi_1191_: type_20;
    var phi_1218_: type_20;
    var phi_1220_: type_20;
    var phi_1304_: u32;
    var phi_1305_: u32;
    var phi_1266_: u32;
    var phi_1267_: u32;
    var phi_1306_: u32;
    var phi_1307_: u32;
    var phi_1308_: u32;
    var phi_1309_: u32;
    var phi_1310_: u32;
    var phi_1562_: bool;
    var phi_1312_: u32;
    var phi_1313_: type_20;
    var phi_1314_: u32;
    var phi_1315_: u32;
    var phi_1316_: u32;
    var phi_1317_: u32;
    var phi_1318_: u32;
    var phi_1319_: u32;
    var phi_1561_: bool;
    var phi_1053_: u32;
    var phi_1056_: type_20;
    var phi_1058_: u32;
    var phi_1060_: u32;
    var phi_1062_: u32;
    var phi_1064_: u32;
    var phi_1066_: u32;
    var phi_1068_: u32;
    var phi_1320_: bool;
    var phi_1560_: bool;

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
                phi_130_ = (_e143 + 1u);
            } else {
                phi_130_ = _e140;
            }
            let _e146 = phi_130_;
            local_7 = _e146;
            let _e149 = global_2.member.member_18;
            local_8 = _e149;
            let _e150 = local;
            let _e151 = (_e150 * _e146);
            phi_1444_ = false;
            phi_136_ = _e151;
            phi_139_ = 0u;
            loop {
                let _e153 = phi_1444_;
                let _e155 = phi_136_;
                let _e157 = phi_139_;
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
                            phi_1446_ = true;
                            break;
                        }
                        let _e170 = local_9;
                        let _e173 = global_5.member[_e170];
                        if ((_e173 & 1u) == 0u) {
                            phi_176_ = 0u;
                            loop {
                                let _e177 = phi_176_;
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
                                        phi_1440_ = true;
                                        break;
                                    }
                                    let _e186 = local_12;
                                    let _e189 = global_4.member[_e186];
                                    let _e190 = local_8;
                                    let _e191 = (_e189 > _e190);
                                    if _e191 {
                                        let _e192 = local_11;
                                        phi_207_ = (_e192 + 1u);
                                    } else {
                                        phi_207_ = u32();
                                    }
                                    let _e195 = phi_207_;
                                    phi_177_ = _e195;
                                    phi_208_ = _e191;
                                } else {
                                    phi_177_ = u32();
                                    phi_208_ = false;
                                }
                                let _e197 = phi_177_;
                                let _e199 = phi_208_;
                                local_13 = _e199;
                                continue;
                                continuing {
                                    let _e200 = local_13;
                                    phi_176_ = _e197;
                                    phi_1440_ = _e153;
                                    break if !(_e200);
                                }
                            }
                            let _e203 = phi_1440_;
                            phi_1446_ = _e203;
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
                                phi_1446_ = true;
                                break;
                            }
                            let _e210 = local_14;
                            let _e213 = global_4.member[_e210];
                            local_15 = _e213;
                            let _e214 = local_8;
                            if (_e213 <= _e214) {
                                let _e219 = local_11;
                                let _e220 = local_15;
                                phi_240_ = type_20(1u, type_15(_e219, _e220));
                            } else {
                                phi_240_ = type_20(0u, type_20().member_1);
                            }
                            let _e224 = phi_240_;
                            local_16 = _e224;
                            if (bitcast<i32>(_e224.member) != 0i) {
                                let _e228 = local_16;
                                let _e231 = local_10;
                                phi_249_ = (_e231 + _e228.member_1.member_1);
                            } else {
                                phi_249_ = _e157;
                            }
                            let _e234 = phi_249_;
                            phi_1449_ = _e203;
                            phi_250_ = _e234;
                        } else {
                            phi_1449_ = _e153;
                            phi_250_ = _e157;
                        }
                        let _e236 = phi_1449_;
                        let _e238 = phi_250_;
                        let _e239 = local_9;
                        phi_1448_ = _e236;
                        phi_252_ = (_e239 + 1u);
                        phi_253_ = _e238;
                    } else {
                        phi_1448_ = _e153;
                        phi_252_ = u32();
                        phi_253_ = u32();
                    }
                    let _e242 = phi_1448_;
                    let _e244 = phi_252_;
                    let _e246 = phi_253_;
                    phi_1447_ = _e242;
                    phi_137_ = _e244;
                    phi_140_ = _e246;
                    phi_254_ = _e166;
                } else {
                    phi_1447_ = _e153;
                    phi_137_ = u32();
                    phi_140_ = u32();
                    phi_254_ = false;
                }
                let _e248 = phi_1447_;
                let _e250 = phi_137_;
                let _e252 = phi_140_;
                let _e254 = phi_254_;
                local_17 = _e254;
                continue;
                continuing {
                    let _e255 = local_17;
                    phi_1444_ = _e248;
                    phi_136_ = _e250;
                    phi_139_ = _e252;
                    phi_1446_ = _e248;
                    break if !(_e255);
                }
            }
            let _e258 = phi_1446_;
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
            phi_353_ = 128u;
            loop {
                let _e265 = phi_353_;
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
                            phi_1452_ = true;
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
                            phi_1452_ = true;
                            break;
                        }
                        let _e277 = local_22;
                        let _e279 = global_1[_e277];
                        let _e280 = local_21;
                        local_23 = (_e280 + _e279);
                        let _e282 = local_18;
                        if _e282 {
                        } else {
                            phi_1452_ = true;
                            break;
                        }
                        let _e283 = local_23;
                        global_1[_e261] = _e283;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e284 = local_19;
                    phi_354_ = (_e284 / 2u);
                } else {
                    phi_354_ = u32();
                }
                let _e287 = phi_354_;
                continue;
                continuing {
                    let _e288 = local_20;
                    phi_353_ = _e287;
                    phi_1452_ = _e258;
                    break if !(_e288);
                }
            }
            let _e291 = phi_1452_;
            if _e291 {
                break;
            }
            let _e293 = global_1[0u];
            storageBarrier();
            workgroupBarrier();
            let _e296 = global_2.member.member_17;
            local_24 = _e296;
            let _e298 = local_8;
            phi_1480_ = _e291;
            phi_406_ = _e149;
            phi_409_ = select(0u, _e298, (_e293 <= _e296));
            loop {
                let _e301 = phi_1480_;
                let _e303 = phi_406_;
                let _e305 = phi_409_;
                local_25 = _e303;
                local_26 = _e305;
                let _e306 = local_26;
                let _e307 = local_25;
                let _e308 = (_e306 < _e307);
                local_27 = _e308;
                if _e308 {
                    let _e309 = local_25;
                    let _e310 = local_26;
                    let _e311 = (_e309 - _e310);
                    let _e312 = (_e311 / 2u);
                    local_28 = _e312;
                    if ((_e311 % 2u) > 0u) {
                        let _e315 = local_28;
                        phi_433_ = (_e315 + 1u);
                    } else {
                        phi_433_ = _e312;
                    }
                    let _e318 = phi_433_;
                    let _e319 = local_26;
                    local_29 = (_e319 + _e318);
                    phi_1478_ = _e301;
                    phi_438_ = _e151;
                    phi_441_ = 0u;
                    loop {
                        let _e322 = phi_1478_;
                        let _e324 = phi_438_;
                        let _e326 = phi_441_;
                        local_30 = _e324;
                        local_31 = _e326;
                        let _e327 = local_30;
                        let _e328 = local_5;
                        if (_e327 < _e328) {
                            let _e330 = local;
                            let _e332 = local_7;
                            let _e334 = local_30;
                            let _e335 = (_e334 < ((_e330 + 1u) * _e332));
                            if _e335 {
                                let _e336 = local_30;
                                let _e337 = local_2;
                                if (_e336 < _e337) {
                                } else {
                                    phi_1484_ = true;
                                    break;
                                }
                                let _e339 = local_30;
                                let _e342 = global_5.member[_e339];
                                if ((_e342 & 1u) == 0u) {
                                    phi_478_ = 0u;
                                    loop {
                                        let _e346 = phi_478_;
                                        local_32 = _e346;
                                        let _e347 = local_32;
                                        if (_e347 < 4u) {
                                            let _e349 = local_30;
                                            let _e351 = local_32;
                                            let _e352 = ((_e349 * 5u) + _e351);
                                            local_33 = _e352;
                                            let _e353 = local_1;
                                            if (_e352 < _e353) {
                                            } else {
                                                phi_1474_ = true;
                                                break;
                                            }
                                            let _e355 = local_33;
                                            let _e358 = global_4.member[_e355];
                                            let _e359 = local_29;
                                            let _e360 = (_e358 > _e359);
                                            if _e360 {
                                                let _e361 = local_32;
                                                phi_509_ = (_e361 + 1u);
                                            } else {
                                                phi_509_ = u32();
                                            }
                                            let _e364 = phi_509_;
                                            phi_479_ = _e364;
                                            phi_510_ = _e360;
                                        } else {
                                            phi_479_ = u32();
                                            phi_510_ = false;
                                        }
                                        let _e366 = phi_479_;
                                        let _e368 = phi_510_;
                                        local_34 = _e368;
                                        continue;
                                        continuing {
                                            let _e369 = local_34;
                                            phi_478_ = _e366;
                                            phi_1474_ = _e322;
                                            break if !(_e369);
                                        }
                                    }
                                    let _e372 = phi_1474_;
                                    phi_1484_ = _e372;
                                    if _e372 {
                                        break;
                                    }
                                    let _e373 = local_30;
                                    let _e375 = local_32;
                                    let _e376 = ((_e373 * 5u) + _e375);
                                    local_35 = _e376;
                                    let _e377 = local_1;
                                    if (_e376 < _e377) {
                                    } else {
                                        phi_1484_ = true;
                                        break;
                                    }
                                    let _e379 = local_35;
                                    let _e382 = global_4.member[_e379];
                                    local_36 = _e382;
                                    let _e383 = local_8;
                                    if (_e382 <= _e383) {
                                        let _e388 = local_32;
                                        let _e389 = local_36;
                                        phi_542_ = type_20(1u, type_15(_e388, _e389));
                                    } else {
                                        phi_542_ = type_20(0u, type_20().member_1);
                                    }
                                    let _e393 = phi_542_;
                                    local_37 = _e393;
                                    if (bitcast<i32>(_e393.member) != 0i) {
                                        let _e397 = local_37;
                                        let _e400 = local_31;
                                        phi_551_ = (_e400 + _e397.member_1.member_1);
                                    } else {
                                        phi_551_ = _e326;
                                    }
                                    let _e403 = phi_551_;
                                    phi_1487_ = _e372;
                                    phi_552_ = _e403;
                                } else {
                                    phi_1487_ = _e322;
                                    phi_552_ = _e326;
                                }
                                let _e405 = phi_1487_;
                                let _e407 = phi_552_;
                                let _e408 = local_30;
                                phi_1486_ = _e405;
                                phi_554_ = (_e408 + 1u);
                                phi_555_ = _e407;
                            } else {
                                phi_1486_ = _e322;
                                phi_554_ = u32();
                                phi_555_ = u32();
                            }
                            let _e411 = phi_1486_;
                            let _e413 = phi_554_;
                            let _e415 = phi_555_;
                            phi_1485_ = _e411;
                            phi_439_ = _e413;
                            phi_442_ = _e415;
                            phi_556_ = _e335;
                        } else {
                            phi_1485_ = _e322;
                            phi_439_ = u32();
                            phi_442_ = u32();
                            phi_556_ = false;
                        }
                        let _e417 = phi_1485_;
                        let _e419 = phi_439_;
                        let _e421 = phi_442_;
                        let _e423 = phi_556_;
                        local_38 = _e423;
                        continue;
                        continuing {
                            let _e424 = local_38;
                            phi_1478_ = _e417;
                            phi_438_ = _e419;
                            phi_441_ = _e421;
                            phi_1484_ = _e417;
                            break if !(_e424);
                        }
                    }
                    let _e427 = phi_1484_;
                    phi_1512_ = _e427;
                    if _e427 {
                        break;
                    }
                    let _e428 = local_18;
                    if _e428 {
                    } else {
                        phi_1512_ = true;
                        break;
                    }
                    let _e429 = local_31;
                    global_1[_e261] = _e429;
                    storageBarrier();
                    workgroupBarrier();
                    phi_655_ = 128u;
                    loop {
                        let _e431 = phi_655_;
                        local_39 = _e431;
                        let _e432 = local_39;
                        let _e433 = (_e432 > 0u);
                        local_40 = _e433;
                        if _e433 {
                            let _e434 = local;
                            let _e435 = local_39;
                            if (_e434 < _e435) {
                                let _e437 = local_18;
                                if _e437 {
                                } else {
                                    phi_1490_ = true;
                                    break;
                                }
                                let _e438 = global_1[_e261];
                                local_41 = _e438;
                                let _e439 = local;
                                let _e440 = local_39;
                                let _e441 = (_e439 + _e440);
                                local_42 = _e441;
                                if (_e441 < 512u) {
                                } else {
                                    phi_1490_ = true;
                                    break;
                                }
                                let _e443 = local_42;
                                let _e445 = global_1[_e443];
                                let _e446 = local_41;
                                local_43 = (_e446 + _e445);
                                let _e448 = local_18;
                                if _e448 {
                                } else {
                                    phi_1490_ = true;
                                    break;
                                }
                                let _e449 = local_43;
                                global_1[_e261] = _e449;
                            }
                            storageBarrier();
                            workgroupBarrier();
                            let _e450 = local_39;
                            phi_656_ = (_e450 / 2u);
                        } else {
                            phi_656_ = u32();
                        }
                        let _e453 = phi_656_;
                        continue;
                        continuing {
                            let _e454 = local_40;
                            phi_655_ = _e453;
                            phi_1490_ = _e427;
                            break if !(_e454);
                        }
                    }
                    let _e457 = phi_1490_;
                    phi_1512_ = _e457;
                    if _e457 {
                        break;
                    }
                    let _e458 = global_1[0u];
                    storageBarrier();
                    workgroupBarrier();
                    let _e459 = local_24;
                    let _e460 = (_e458 <= _e459);
                    local_44 = _e460;
                    if _e460 {
                        phi_707_ = _e303;
                    } else {
                        let _e461 = local_29;
                        phi_707_ = (_e461 - 1u);
                    }
                    let _e464 = phi_707_;
                    let _e465 = local_44;
                    let _e466 = local_29;
                    let _e467 = local_26;
                    phi_1513_ = _e457;
                    phi_407_ = _e464;
                    phi_410_ = select(_e467, _e466, _e465);
                } else {
                    phi_1513_ = _e301;
                    phi_407_ = u32();
                    phi_410_ = u32();
                }
                let _e470 = phi_1513_;
                let _e472 = phi_407_;
                let _e474 = phi_410_;
                continue;
                continuing {
                    let _e475 = local_27;
                    phi_1480_ = _e470;
                    phi_406_ = _e472;
                    phi_409_ = _e474;
                    phi_1512_ = _e470;
                    break if !(_e475);
                }
            }
            let _e478 = phi_1512_;
            if _e478 {
                break;
            }
            phi_1521_ = _e478;
            phi_712_ = _e151;
            phi_715_ = 0u;
            loop {
                let _e480 = phi_1521_;
                let _e482 = phi_712_;
                let _e484 = phi_715_;
                local_45 = _e482;
                local_46 = _e484;
                let _e485 = local_45;
                let _e486 = local_5;
                if (_e485 < _e486) {
                    let _e488 = local;
                    let _e490 = local_7;
                    let _e492 = local_45;
                    let _e493 = (_e492 < ((_e488 + 1u) * _e490));
                    if _e493 {
                        let _e494 = local_45;
                        let _e495 = local_2;
                        if (_e494 < _e495) {
                        } else {
                            phi_1522_ = true;
                            break;
                        }
                        let _e497 = local_45;
                        let _e500 = global_5.member[_e497];
                        if ((_e500 & 1u) == 0u) {
                            phi_752_ = 0u;
                            loop {
                                let _e504 = phi_752_;
                                local_47 = _e504;
                                let _e505 = local_47;
                                if (_e505 < 4u) {
                                    let _e507 = local_45;
                                    let _e509 = local_47;
                                    let _e510 = ((_e507 * 5u) + _e509);
                                    local_48 = _e510;
                                    let _e511 = local_1;
                                    if (_e510 < _e511) {
                                    } else {
                                        phi_1517_ = true;
                                        break;
                                    }
                                    let _e513 = local_48;
                                    let _e516 = global_4.member[_e513];
                                    let _e517 = local_26;
                                    let _e518 = (_e516 > _e517);
                                    if _e518 {
                                        let _e519 = local_47;
                                        phi_783_ = (_e519 + 1u);
                                    } else {
                                        phi_783_ = u32();
                                    }
                                    let _e522 = phi_783_;
                                    phi_753_ = _e522;
                                    phi_784_ = _e518;
                                } else {
                                    phi_753_ = u32();
                                    phi_784_ = false;
                                }
                                let _e524 = phi_753_;
                                let _e526 = phi_784_;
                                local_49 = _e526;
                                continue;
                                continuing {
                                    let _e527 = local_49;
                                    phi_752_ = _e524;
                                    phi_1517_ = _e480;
                                    break if !(_e527);
                                }
                            }
                            let _e530 = phi_1517_;
                            phi_1522_ = _e530;
                            if _e530 {
                                break;
                            }
                            let _e531 = local_45;
                            let _e533 = local_47;
                            let _e534 = ((_e531 * 5u) + _e533);
                            local_50 = _e534;
                            let _e535 = local_1;
                            if (_e534 < _e535) {
                            } else {
                                phi_1522_ = true;
                                break;
                            }
                            let _e537 = local_50;
                            let _e540 = global_4.member[_e537];
                            local_51 = _e540;
                            let _e541 = local_8;
                            if (_e540 <= _e541) {
                                let _e546 = local_47;
                                let _e547 = local_51;
                                phi_816_ = type_20(1u, type_15(_e546, _e547));
                            } else {
                                phi_816_ = type_20(0u, type_20().member_1);
                            }
                            let _e551 = phi_816_;
                            local_52 = _e551;
                            if (bitcast<i32>(_e551.member) != 0i) {
                                let _e555 = local_52;
                                let _e558 = local_46;
                                phi_825_ = (_e558 + _e555.member_1.member_1);
                            } else {
                                phi_825_ = _e484;
                            }
                            let _e561 = phi_825_;
                            phi_1525_ = _e530;
                            phi_826_ = _e561;
                        } else {
                            phi_1525_ = _e480;
                            phi_826_ = _e484;
                        }
                        let _e563 = phi_1525_;
                        let _e565 = phi_826_;
                        let _e566 = local_45;
                        phi_1524_ = _e563;
                        phi_828_ = (_e566 + 1u);
                        phi_829_ = _e565;
                    } else {
                        phi_1524_ = _e480;
                        phi_828_ = u32();
                        phi_829_ = u32();
                    }
                    let _e569 = phi_1524_;
                    let _e571 = phi_828_;
                    let _e573 = phi_829_;
                    phi_1523_ = _e569;
                    phi_713_ = _e571;
                    phi_716_ = _e573;
                    phi_830_ = _e493;
                } else {
                    phi_1523_ = _e480;
                    phi_713_ = u32();
                    phi_716_ = u32();
                    phi_830_ = false;
                }
                let _e575 = phi_1523_;
                let _e577 = phi_713_;
                let _e579 = phi_716_;
                let _e581 = phi_830_;
                local_53 = _e581;
                continue;
                continuing {
                    let _e582 = local_53;
                    phi_1521_ = _e575;
                    phi_712_ = _e577;
                    phi_715_ = _e579;
                    phi_1522_ = _e575;
                    break if !(_e582);
                }
            }
            let _e585 = phi_1522_;
            if _e585 {
                break;
            }
            let _e586 = local_18;
            if _e586 {
            } else {
                break;
            }
            let _e587 = local_46;
            global_1[_e261] = _e587;
            storageBarrier();
            workgroupBarrier();
            phi_980_ = 1u;
            phi_983_ = 0u;
            loop {
                let _e589 = phi_980_;
                let _e591 = phi_983_;
                local_54 = _e589;
                local_55 = _e591;
                let _e592 = local_54;
                let _e593 = (_e592 < 256u);
                local_56 = _e593;
                if _e593 {
                    let _e594 = local_55;
                    let _e596 = select(0u, 256u, (_e594 == 0u));
                    local_91 = _e596;
                    let _e597 = local_55;
                    let _e598 = local;
                    let _e599 = (_e597 + _e598);
                    local_57 = _e599;
                    if (_e599 < 512u) {
                    } else {
                        phi_1528_ = true;
                        break;
                    }
                    let _e601 = local_57;
                    let _e603 = global_1[_e601];
                    local_58 = _e603;
                    let _e604 = local;
                    let _e605 = local_54;
                    if (_e604 >= _e605) {
                        let _e607 = local;
                        let _e608 = local_54;
                        let _e610 = local_55;
                        let _e611 = (_e610 + (_e607 - _e608));
                        local_59 = _e611;
                        if (_e611 < 512u) {
                        } else {
                            phi_1528_ = true;
                            break;
                        }
                        let _e613 = local_59;
                        let _e615 = global_1[_e613];
                        let _e616 = local_58;
                        phi_1019_ = (_e615 + _e616);
                    } else {
                        phi_1019_ = _e603;
                    }
                    let _e619 = phi_1019_;
                    local_60 = _e619;
                    let _e620 = local_91;
                    let _e621 = local;
                    let _e622 = (_e620 + _e621);
                    local_61 = _e622;
                    if (_e622 < 512u) {
                    } else {
                        phi_1528_ = true;
                        break;
                    }
                    let _e624 = local_61;
                    let _e626 = local_60;
                    global_1[_e624] = _e626;
                    storageBarrier();
                    workgroupBarrier();
                    let _e627 = local_54;
                    phi_981_ = (_e627 * 2u);
                    phi_984_ = _e596;
                } else {
                    phi_981_ = u32();
                    phi_984_ = u32();
                }
                let _e630 = phi_981_;
                let _e632 = phi_984_;
                continue;
                continuing {
                    let _e633 = local_56;
                    phi_980_ = _e630;
                    phi_983_ = _e632;
                    phi_1528_ = _e585;
                    break if !(_e633);
                }
            }
            let _e636 = phi_1528_;
            if _e636 {
                break;
            }
            let _e637 = local;
            if (_e637 == 0u) {
                phi_1048_ = 0u;
            } else {
                let _e639 = local_55;
                let _e640 = local;
                let _e642 = ((_e639 + _e640) - 1u);
                local_62 = _e642;
                if (_e642 < 512u) {
                } else {
                    break;
                }
                let _e644 = local_62;
                let _e646 = global_1[_e644];
                phi_1048_ = _e646;
            }
            let _e648 = phi_1048_;
            phi_1557_ = _e636;
            phi_1052_ = _e648;
            phi_1055_ = type_20();
            phi_1057_ = _e151;
            phi_1059_ = 0u;
            phi_1061_ = 0u;
            phi_1063_ = 0u;
            phi_1065_ = 0u;
            phi_1067_ = 0u;
            loop {
                let _e650 = phi_1557_;
                let _e652 = phi_1052_;
                let _e654 = phi_1055_;
                let _e656 = phi_1057_;
                let _e658 = phi_1059_;
                let _e660 = phi_1061_;
                let _e662 = phi_1063_;
                let _e664 = phi_1065_;
                let _e666 = phi_1067_;
                local_63 = _e652;
                local_64 = _e654;
                local_65 = _e656;
                local_66 = _e658;
                local_67 = _e660;
                local_68 = _e662;
                local_69 = _e664;
                local_70 = _e666;
                let _e667 = local_65;
                let _e668 = local_5;
                if (_e667 < _e668) {
                    let _e670 = local;
                    let _e672 = local_7;
                    let _e674 = local_65;
                    let _e675 = (_e674 < ((_e670 + 1u) * _e672));
                    if _e675 {
                        let _e676 = local_65;
                        let _e677 = (_e676 * 5u);
                        local_71 = _e677;
                        let _e678 = local_1;
                        if (_e677 < _e678) {
                        } else {
                            phi_1560_ = true;
                            break;
                        }
                        let _e680 = local_71;
                        let _e683 = global_4.member[_e680];
                        local_72 = _e683;
                        let _e684 = local_66;
                        let _e686 = local_66;
                        let _e688 = local_65;
                        let _e689 = local_2;
                        let _e690 = (_e688 < _e689);
                        local_73 = _e690;
                        if _e690 {
                        } else {
                            phi_1560_ = true;
                            break;
                        }
                        let _e691 = local_65;
                        let _e694 = global_5.member[_e691];
                        if ((_e694 & 1u) == 0u) {
                            phi_1125_ = 0u;
                            loop {
                                let _e702 = phi_1125_;
                                local_74 = _e702;
                                let _e703 = local_74;
                                if (_e703 < 4u) {
                                    let _e705 = local_71;
                                    let _e706 = local_74;
                                    let _e707 = (_e705 + _e706);
                                    local_75 = _e707;
                                    let _e708 = local_1;
                                    if (_e707 < _e708) {
                                    } else {
                                        phi_1552_ = true;
                                        break;
                                    }
                                    let _e710 = local_75;
                                    let _e713 = global_4.member[_e710];
                                    let _e714 = local_26;
                                    let _e715 = (_e713 > _e714);
                                    if _e715 {
                                        let _e716 = local_74;
                                        phi_1156_ = (_e716 + 1u);
                                    } else {
                                        phi_1156_ = u32();
                                    }
                                    let _e719 = phi_1156_;
                                    phi_1126_ = _e719;
                                    phi_1157_ = _e715;
                                } else {
                                    phi_1126_ = u32();
                                    phi_1157_ = false;
                                }
                                let _e721 = phi_1126_;
                                let _e723 = phi_1157_;
                                local_76 = _e723;
                                continue;
                                continuing {
                                    let _e724 = local_76;
                                    phi_1125_ = _e721;
                                    phi_1552_ = _e650;
                                    break if !(_e724);
                                }
                            }
                            let _e727 = phi_1552_;
                            phi_1560_ = _e727;
                            if _e727 {
                                break;
                            }
                            let _e728 = local_71;
                            let _e729 = local_74;
                            let _e730 = (_e728 + _e729);
                            local_77 = _e730;
                            let _e731 = local_1;
                            if (_e730 < _e731) {
                            } else {
                                phi_1560_ = true;
                                break;
                            }
                            let _e733 = local_77;
                            let _e736 = global_4.member[_e733];
                            local_78 = _e736;
                            let _e737 = local_8;
                            if (_e736 <= _e737) {
                                let _e742 = local_74;
                                let _e743 = local_78;
                                phi_1189_ = type_20(1u, type_15(_e742, _e743));
                            } else {
                                phi_1189_ = type_20(0u, type_20().member_1);
                            }
                            let _e747 = phi_1189_;
                            phi_1568_ = _e727;
                            phi_1191_ = _e747;
                        } else {
                            let _e697 = local_64;
                            phi_1568_ = _e650;
                            phi_1191_ = type_20(0u, _e697.member_1);
                        }
                        let _e749 = phi_1568_;
                        let _e751 = phi_1191_;
                        local_79 = _e751;
                        if (bitcast<i32>(_e751.member) != 0i) {
                            let _e758 = local_79;
                            let _e761 = local_24;
                            let _e762 = local_63;
                            let _e764 = local_24;
                            let _e765 = local_63;
                            let _e767 = local_24;
                            if (_e758.member_1.member_1 <= (_e767 - select(_e765, _e764, (_e761 < _e762)))) {
                                let _e773 = local_79;
                                phi_1218_ = type_20(1u, _e773.member_1);
                            } else {
                                phi_1218_ = type_20(0u, type_20().member_1);
                            }
                            let _e777 = phi_1218_;
                            phi_1220_ = _e777;
                        } else {
                            phi_1220_ = type_20(0u, type_20().member_1);
                        }
                        let _e779 = phi_1220_;
                        local_80 = _e779;
                        if (bitcast<i32>(_e779.member) != 0i) {
                            let _e809 = local_80;
                            local_81 = _e809.member_1.member;
                            let _e812 = local_80;
                            local_82 = _e812.member_1.member_1;
                            let _e815 = local_65;
                            let _e816 = (2u * _e815);
                            local_83 = _e816;
                            let _e817 = local_3;
                            if (_e816 < _e817) {
                            } else {
                                phi_1560_ = true;
                                break;
                            }
                            let _e819 = local_83;
                            let _e822 = local_63;
                            global_6.member[_e819] = _e822;
                            let _e823 = local_83;
                            let _e824 = (_e823 + 1u);
                            local_84 = _e824;
                            let _e825 = local_3;
                            if (_e824 < _e825) {
                            } else {
                                phi_1560_ = true;
                                break;
                            }
                            let _e827 = local_84;
                            let _e830 = local_82;
                            global_6.member[_e827] = _e830;
                            let _e831 = local_81;
                            local_85 = (_e831 << bitcast<u32>(1u));
                            let _e834 = local_73;
                            if _e834 {
                            } else {
                                phi_1560_ = true;
                                break;
                            }
                            let _e835 = local_85;
                            global_5.member[_e691] = _e835;
                            let _e836 = local_81;
                            if (_e836 > 0u) {
                                let _e838 = local_70;
                                let _e840 = local_72;
                                let _e841 = local_82;
                                let _e843 = local_69;
                                phi_1266_ = (_e843 + (_e840 - _e841));
                                phi_1267_ = (_e838 + 1u);
                            } else {
                                phi_1266_ = _e664;
                                phi_1267_ = _e666;
                            }
                            let _e846 = phi_1266_;
                            let _e848 = phi_1267_;
                            let _e849 = local_63;
                            let _e850 = local_82;
                            phi_1306_ = (_e849 + _e850);
                            phi_1307_ = _e660;
                            phi_1308_ = _e662;
                            phi_1309_ = _e846;
                            phi_1310_ = _e848;
                        } else {
                            let _e783 = local_65;
                            let _e784 = (2u * _e783);
                            local_86 = _e784;
                            let _e785 = local_3;
                            if (_e784 < _e785) {
                            } else {
                                phi_1560_ = true;
                                break;
                            }
                            let _e787 = local_86;
                            global_6.member[_e787] = 0u;
                            let _e790 = local_86;
                            let _e791 = (_e790 + 1u);
                            local_87 = _e791;
                            let _e792 = local_3;
                            if (_e791 < _e792) {
                            } else {
                                phi_1560_ = true;
                                break;
                            }
                            let _e794 = local_87;
                            global_6.member[_e794] = 0u;
                            let _e797 = local_72;
                            if (_e797 > 0u) {
                                let _e799 = local_73;
                                if _e799 {
                                } else {
                                    phi_1560_ = true;
                                    break;
                                }
                                global_5.member[_e691] = 1u;
                                let _e800 = local_68;
                                let _e802 = local_67;
                                let _e803 = local_72;
                                phi_1304_ = (_e802 + _e803);
                                phi_1305_ = (_e800 + 1u);
                            } else {
                                phi_1304_ = _e660;
                                phi_1305_ = _e662;
                            }
                            let _e806 = phi_1304_;
                            let _e808 = phi_1305_;
                            phi_1306_ = _e652;
                            phi_1307_ = _e806;
                            phi_1308_ = _e808;
                            phi_1309_ = _e664;
                            phi_1310_ = _e666;
                        }
                        let _e853 = phi_1306_;
                        let _e855 = phi_1307_;
                        let _e857 = phi_1308_;
                        let _e859 = phi_1309_;
                        let _e861 = phi_1310_;
                        let _e862 = local_65;
                        phi_1562_ = _e749;
                        phi_1312_ = _e853;
                        phi_1313_ = _e751;
                        phi_1314_ = (_e862 + 1u);
                        phi_1315_ = select(_e686, _e683, (_e683 > _e684));
                        phi_1316_ = _e855;
                        phi_1317_ = _e857;
                        phi_1318_ = _e859;
                        phi_1319_ = _e861;
                    } else {
                        phi_1562_ = _e650;
                        phi_1312_ = u32();
                        phi_1313_ = type_20();
                        phi_1314_ = u32();
                        phi_1315_ = u32();
                        phi_1316_ = u32();
                        phi_1317_ = u32();
                        phi_1318_ = u32();
                        phi_1319_ = u32();
                    }
                    let _e865 = phi_1562_;
                    let _e867 = phi_1312_;
                    let _e869 = phi_1313_;
                    let _e871 = phi_1314_;
                    let _e873 = phi_1315_;
                    let _e875 = phi_1316_;
                    let _e877 = phi_1317_;
                    let _e879 = phi_1318_;
                    let _e881 = phi_1319_;
                    phi_1561_ = _e865;
                    phi_1053_ = _e867;
                    phi_1056_ = _e869;
                    phi_1058_ = _e871;
                    phi_1060_ = _e873;
                    phi_1062_ = _e875;
                    phi_1064_ = _e877;
                    phi_1066_ = _e879;
                    phi_1068_ = _e881;
                    phi_1320_ = _e675;
                } else {
                    phi_1561_ = _e650;
                    phi_1053_ = u32();
                    phi_1056_ = type_20();
                    phi_1058_ = u32();
                    phi_1060_ = u32();
                    phi_1062_ = u32();
                    phi_1064_ = u32();
                    phi_1066_ = u32();
                    phi_1068_ = u32();
                    phi_1320_ = false;
                }
                let _e883 = phi_1561_;
                let _e885 = phi_1053_;
                let _e887 = phi_1056_;
                let _e889 = phi_1058_;
                let _e891 = phi_1060_;
                let _e893 = phi_1062_;
                let _e895 = phi_1064_;
                let _e897 = phi_1066_;
                let _e899 = phi_1068_;
                let _e901 = phi_1320_;
                local_88 = _e901;
                continue;
                continuing {
                    let _e902 = local_88;
                    phi_1557_ = _e883;
                    phi_1052_ = _e885;
                    phi_1055_ = _e887;
                    phi_1057_ = _e889;
                    phi_1059_ = _e891;
                    phi_1061_ = _e893;
                    phi_1063_ = _e895;
                    phi_1065_ = _e897;
                    phi_1067_ = _e899;
                    phi_1560_ = _e883;
                    break if !(_e902);
                }
            }
            let _e905 = phi_1560_;
            if _e905 {
                break;
            }
            let _e906 = local_70;
            if (_e906 > 0u) {
                let _e908 = local_4;
                if (22u < _e908) {
                } else {
                    break;
                }
                let _e912 = local_70;
                let _e913 = atomicAdd((&global_3.member[22u]), _e912);
                let _e914 = local_4;
                if (23u < _e914) {
                } else {
                    break;
                }
                let _e918 = local_69;
                let _e919 = atomicAdd((&global_3.member[23u]), _e918);
            }
            let _e920 = local_68;
            if (_e920 > 0u) {
                let _e922 = local_4;
                if (14u < _e922) {
                } else {
                    break;
                }
                let _e926 = local_68;
                let _e927 = atomicAdd((&global_3.member[14u]), _e926);
                let _e928 = local_4;
                if (15u < _e928) {
                } else {
                    break;
                }
                let _e932 = local_67;
                let _e933 = atomicAdd((&global_3.member[15u]), _e932);
            }
            let _e934 = local_66;
            if (_e934 > 0u) {
                let _e936 = local_4;
                if (8u < _e936) {
                } else {
                    break;
                }
                let _e940 = local_66;
                let _e941 = atomicMax((&global_3.member[8u]), _e940);
            }
            let _e942 = local;
            if (_e942 == 255u) {
                let _e944 = local_55;
                let _e945 = local;
                let _e946 = (_e944 + _e945);
                local_89 = _e946;
                if (_e946 < 512u) {
                } else {
                    break;
                }
                let _e948 = local_89;
                let _e950 = global_1[_e948];
                local_90 = _e950;
                let _e951 = local_4;
                if (16u < _e951) {
                } else {
                    break;
                }
                let _e955 = local_90;
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
