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
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: type_5,
    member_9: type_17,
}

struct type_19 {
    member: type_18,
}

struct type_23 {
    member: array<f32, 3>,
    member_1: array<f32, 3>,
    member_2: f32,
    member_3: f32,
}

struct type_24 {
    member: u32,
    member_1: type_23,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_7;
var<immediate> global_5: type_19;
@group(0) @binding(2) 
var<storage> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_7;
@group(0) @binding(4) 
var<storage, read_write> global_8: type_7;
@group(0) @binding(5) 
var<storage> global_9: type_7;
var<private> global_10: u32 = 2143289344u;

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
    var local_12: bool;
    var local_13: u32;
    var local_14: u32;
    var local_15: bool;
    var local_16: f32;
    var local_17: u32;
    var local_18: bool;
    var local_19: f32;
    var local_20: u32;
    var local_21: bool;
    var local_22: f32;
    var local_23: bool;
    var local_24: f32;
    var local_25: bool;
    var local_26: f32;
    var local_27: bool;
    var local_28: bool;
    var local_29: u32;
    var local_30: i32;
    var local_31: u32;
    var local_32: i32;
    var local_33: f32;
    var local_34: f32;
    var local_35: f32;
    var local_36: array<f32, 3>;
    var local_37: i32;
    var local_38: f32;
    var local_39: array<f32, 3>;
    var local_40: bool;
    var local_41: i32;
    var local_42: f32;
    var local_43: array<f32, 3>;
    var local_44: bool;
    var local_45: i32;
    var local_46: i32;
    var local_47: u32;
    var local_48: f32;
    var local_49: u32;
    var local_50: f32;
    var local_51: u32;
    var local_52: f32;
    var local_53: f32;
    var local_54: f32;
    var local_55: f32;
    var local_56: bool;
    var local_57: array<f32, 3>;
    var local_58: f32;
    var local_59: u32;
    var local_60: f32;
    var local_61: f32;
    var local_62: f32;
    var local_63: f32;
    var local_64: bool;
    var local_65: bool;
    var local_66: type_24;
    var local_67: array<f32, 3>;
    var local_68: array<f32, 3>;
    var local_69: f32;
    var local_70: f32;
    var local_71: u32;
    var local_72: f32;
    var local_73: f32;
    var local_74: f32;
    var local_75: f32;
    var local_76: f32;
    var local_77: f32;
    var local_78: bool;
    var local_79: f32;
    var local_80: f32;
    var local_81: bool;
    var local_82: f32;
    var local_83: f32;
    var local_84: u32;
    var local_85: bool;
    var local_86: f32;
    var local_87: f32;
    var local_88: u32;
    var local_89: f32;
    var local_90: f32;
    var local_91: f32;
    var local_92: bool;
    var local_93: f32;
    var local_94: f32;
    var local_95: f32;
    var local_96: f32;
    var local_97: bool;
    var local_98: u32;
    var local_99: f32;
    var local_100: f32;
    var local_101: f32;
    var local_102: bool;
    var local_103: u32;
    var local_104: f32;
    var local_105: f32;
    var local_106: u32;
    var local_107: f32;
    var local_108: u32;
    var local_109: f32;
    var local_110: u32;
    var local_111: f32;
    var local_112: array<f32, 2>;
    var local_113: bool;
    var local_114: u32;
    var local_115: f32;
    var local_116: bool;
    var local_117: f32;
    var local_118: f32;
    var local_119: f32;
    var local_120: f32;
    var local_121: f32;
    var local_122: f32;
    var local_123: f32;
    var local_124: u32;
    var local_125: bool;
    var local_126: u32;
    var local_127: u32;
    var local_128: array<f32, 3>;
    var local_129: u32;
    var local_130: u32;
    var local_131: u32;
    var local_132: f32;
    var local_133: f32;
    var local_134: f32;
    var local_135: f32;
    var local_136: f32;
    var local_137: f32;
    var local_138: array<f32, 8>;
    var phi_1850_: bool;
    var phi_158_: u32;
    var phi_235_: bool;
    var phi_249_: bool;
    var phi_254_: f32;
    var phi_264_: bool;
    var phi_278_: bool;
    var phi_283_: f32;
    var phi_293_: bool;
    var phi_307_: bool;
    var phi_312_: f32;
    var phi_392_: bool;
    var phi_406_: bool;
    var phi_411_: f32;
    var phi_421_: bool;
    var phi_435_: bool;
    var phi_440_: f32;
    var phi_450_: bool;
    var phi_464_: bool;
    var phi_469_: f32;
    var phi_1813_: bool;
    var phi_472_: i32;
    var phi_475_: f32;
    var phi_477_: array<f32, 3>;
    var phi_486_: i32;
    var phi_489_: f32;
    var phi_491_: array<f32, 3>;
    var phi_510_: bool;
    var phi_604_: bool;
    var phi_618_: bool;
    var phi_623_: f32;
    var phi_633_: bool;
    var phi_647_: bool;
    var phi_652_: f32;
    var phi_662_: bool;
    var phi_676_: bool;
    var phi_681_: f32;
    var phi_697_: bool;
    var phi_699_: bool;
    var phi_700_: bool;
    var phi_718_: f32;
    var phi_719_: array<f32, 3>;
    var phi_720_: f32;
    var phi_721_: array<f32, 3>;
    var phi_722_: f32;
    var phi_723_: array<f32, 3>;
    var phi_724_: f32;
    var phi_725_: array<f32, 3>;
    var phi_726_: f32;
    var phi_727_: array<f32, 3>;
    var phi_728_: f32;
    var phi_729_: array<f32, 3>;
    var phi_487_: i32;
    var phi_490_: f32;
    var phi_492_: array<f32, 3>;
    var phi_1781_: bool;
    var phi_1852_: bool;
    var phi_473_: i32;
    var phi_476_: f32;
    var phi_478_: array<f32, 3>;
    var phi_1851_: bool;
    var phi_743_: array<f32, 3>;
    var phi_788_: bool;
    var phi_816_: f32;
    var phi_817_: f32;
    var phi_823_: f32;
    var phi_825_: f32;
    var phi_1716_: bool;
    var phi_851_: bool;
    var phi_853_: bool;
    var phi_854_: bool;
    var phi_868_: bool;
    var phi_900_: type_24;
    var phi_902_: type_24;
    var phi_903_: bool;
    var phi_904_: type_24;
    var phi_905_: bool;
    var phi_906_: type_24;
    var phi_907_: bool;
    var phi_912_: type_24;
    var phi_999_: f32;
    var phi_1864_: bool;
    var phi_1014_: f32;
    var phi_1017_: f32;
    var phi_1028_: f32;
    var phi_1031_: f32;
    var phi_1055_: bool;
    var phi_1091_: bool;
    var phi_1215_: f32;
    var phi_1216_: f32;
    var phi_1217_: bool;
    var phi_1218_: f32;
    var phi_1219_: bool;
    var phi_1220_: f32;
    var phi_1221_: bool;
    var phi_1279_: f32;
    var phi_1280_: f32;
    var phi_1281_: bool;
    var phi_1282_: f32;
    var phi_1283_: bool;
    var phi_1284_: f32;
    var phi_1285_: bool;
    var phi_1343_: f32;
    var phi_1344_: f32;
    var phi_1345_: bool;
    var phi_1346_: f32;
    var phi_1347_: bool;
    var phi_1348_: f32;
    var phi_1349_: bool;
    var phi_1408_: f32;
    var phi_1409_: f32;
    var phi_1410_: bool;
    var phi_1411_: f32;
    var phi_1412_: bool;
    var phi_1413_: f32;
    var phi_1414_: bool;
    var phi_1425_: f32;
    var phi_1427_: f32;
    var phi_1428_: bool;
    var phi_1429_: f32;
    var phi_1430_: bool;
    var phi_1431_: f32;
    var phi_1432_: bool;
    var phi_1437_: f32;
    var phi_1456_: u32;
    var phi_1459_: f32;
    var phi_1461_: array<f32, 2>;
    var phi_1457_: u32;
    var phi_1460_: f32;
    var phi_1462_: array<f32, 2>;
    var phi_1514_: f32;
    var phi_1527_: f32;
    var phi_1528_: f32;
    var phi_1529_: f32;
    var phi_1535_: u32;
    var phi_1538_: f32;
    var phi_1536_: u32;
    var phi_1539_: f32;
    var phi_1029_: f32;
    var phi_1032_: f32;
    var phi_1853_: bool;
    var phi_1923_: bool;
    var phi_1015_: f32;
    var phi_1018_: f32;
    var phi_1922_: bool;
    var phi_1933_: bool;
    var phi_1551_: f32;
    var phi_1734_: bool;
    var phi_1749_: bool;
    var phi_1764_: bool;
    var phi_1581_: u32;
    var phi_1582_: u32;
    var phi_1924_: bool;
    var phi_1939_: bool;
    var phi_1615_: array<f32, 3>;
    var phi_1938_: bool;
    var phi_1616_: array<f32, 3>;
    var phi_1937_: bool;
    var phi_1936_: bool;
    var phi_159_: u32;
    var phi_1935_: bool;
    var local_139: f32;
    var local_140: array<f32, 3>;
    var local_141: f32;
    var local_142: f32;
    var local_143: f32;

    let _e196 = global_10;
    switch bitcast<i32>(0u) {
        default: {
            let _e199 = global;
            local = _e199;
            let _e200 = global_1;
            let _e201 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            local_6 = arrayLength((&global_9.member));
            let _e218 = global_5.member.member;
            local_7 = _e218;
            let _e221 = global_5.member.member_1;
            local_8 = _e221;
            local_9 = (_e218 * _e221);
            local_10 = (_e201.x * 256u);
            phi_1850_ = false;
            phi_158_ = (_e200.x * 256u);
            loop {
                let _e226 = phi_1850_;
                let _e228 = phi_158_;
                local_11 = _e228;
                let _e229 = local_11;
                let _e230 = local_9;
                let _e231 = (_e229 < _e230);
                local_12 = _e231;
                if _e231 {
                    let _e232 = local_11;
                    let _e233 = local;
                    let _e234 = (_e232 + _e233);
                    local_13 = _e234;
                    let _e235 = local_9;
                    if (_e234 < _e235) {
                        let _e237 = local_13;
                        let _e238 = (3u * _e237);
                        local_14 = _e238;
                        let _e239 = local_1;
                        let _e240 = (_e238 < _e239);
                        local_15 = _e240;
                        if _e240 {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e241 = local_14;
                        let _e244 = global_4.member[_e241];
                        local_16 = bitcast<f32>(_e244);
                        let _e246 = local_14;
                        let _e247 = (_e246 + 1u);
                        local_17 = _e247;
                        let _e248 = local_1;
                        let _e249 = (_e247 < _e248);
                        local_18 = _e249;
                        if _e249 {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e250 = local_17;
                        let _e253 = global_4.member[_e250];
                        local_19 = bitcast<f32>(_e253);
                        let _e255 = local_14;
                        let _e256 = (_e255 + 2u);
                        local_20 = _e256;
                        let _e257 = local_1;
                        let _e258 = (_e256 < _e257);
                        local_21 = _e258;
                        if _e258 {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e259 = local_20;
                        let _e262 = global_4.member[_e259];
                        local_22 = bitcast<f32>(_e262);
                        let _e264 = local_16;
                        let _e265 = (_e264 > 1267650600000000000000000000000f);
                        local_23 = _e265;
                        if _e265 {
                            let _e266 = local_16;
                            phi_235_ = select(true, false, (_e266 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_235_ = true;
                        }
                        let _e270 = phi_235_;
                        if _e270 {
                            let _e271 = local_16;
                            if (_e271 < 0.000000000000000000000000000000000000011754944f) {
                                let _e273 = local_16;
                                phi_249_ = select(true, false, (_e273 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_249_ = true;
                            }
                            let _e277 = phi_249_;
                            let _e278 = local_16;
                            phi_254_ = select(0f, _e278, _e277);
                        } else {
                            phi_254_ = 1267650600000000000000000000000f;
                        }
                        let _e281 = phi_254_;
                        local_24 = _e281;
                        let _e282 = local_19;
                        let _e283 = (_e282 > 1267650600000000000000000000000f);
                        local_25 = _e283;
                        if _e283 {
                            let _e284 = local_19;
                            phi_264_ = select(true, false, (_e284 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_264_ = true;
                        }
                        let _e288 = phi_264_;
                        if _e288 {
                            let _e289 = local_19;
                            if (_e289 < 0.000000000000000000000000000000000000011754944f) {
                                let _e291 = local_19;
                                phi_278_ = select(true, false, (_e291 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_278_ = true;
                            }
                            let _e295 = phi_278_;
                            let _e296 = local_19;
                            phi_283_ = select(0f, _e296, _e295);
                        } else {
                            phi_283_ = 1267650600000000000000000000000f;
                        }
                        let _e299 = phi_283_;
                        local_26 = _e299;
                        let _e300 = local_22;
                        let _e301 = (_e300 > 1267650600000000000000000000000f);
                        local_27 = _e301;
                        if _e301 {
                            let _e302 = local_22;
                            phi_293_ = select(true, false, (_e302 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_293_ = true;
                        }
                        let _e306 = phi_293_;
                        if _e306 {
                            let _e307 = local_22;
                            if (_e307 < 0.000000000000000000000000000000000000011754944f) {
                                let _e309 = local_22;
                                phi_307_ = select(true, false, (_e309 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_307_ = true;
                            }
                            let _e313 = phi_307_;
                            let _e314 = local_22;
                            phi_312_ = select(0f, _e314, _e313);
                        } else {
                            phi_312_ = 1267650600000000000000000000000f;
                        }
                        let _e317 = phi_312_;
                        let _e318 = local_24;
                        let _e319 = local_26;
                        let _e320 = array<f32, 3>(_e318, _e319, _e317);
                        let _e321 = local_7;
                        let _e322 = (_e321 == 0u);
                        local_28 = _e322;
                        if _e322 {
                            phi_1935_ = true;
                            break;
                        }
                        let _e323 = local_13;
                        let _e324 = local_7;
                        let _e325 = (_e323 % _e324);
                        local_29 = _e325;
                        local_30 = bitcast<i32>(_e325);
                        let _e327 = local_28;
                        if _e327 {
                            phi_1935_ = true;
                            break;
                        }
                        let _e328 = local_13;
                        let _e329 = local_7;
                        let _e330 = (_e328 / _e329);
                        local_31 = _e330;
                        local_32 = bitcast<i32>(_e330);
                        let _e332 = local_15;
                        if _e332 {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e333 = local_18;
                        if _e333 {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e334 = local_21;
                        if _e334 {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e335 = local_23;
                        if _e335 {
                            let _e336 = local_16;
                            phi_392_ = select(true, false, (_e336 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_392_ = true;
                        }
                        let _e340 = phi_392_;
                        if _e340 {
                            let _e341 = local_16;
                            if (_e341 < 0.000000000000000000000000000000000000011754944f) {
                                let _e343 = local_16;
                                phi_406_ = select(true, false, (_e343 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_406_ = true;
                            }
                            let _e347 = phi_406_;
                            let _e348 = local_16;
                            phi_411_ = select(0f, _e348, _e347);
                        } else {
                            phi_411_ = 1267650600000000000000000000000f;
                        }
                        let _e351 = phi_411_;
                        local_33 = _e351;
                        let _e352 = local_25;
                        if _e352 {
                            let _e353 = local_19;
                            phi_421_ = select(true, false, (_e353 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_421_ = true;
                        }
                        let _e357 = phi_421_;
                        if _e357 {
                            let _e358 = local_19;
                            if (_e358 < 0.000000000000000000000000000000000000011754944f) {
                                let _e360 = local_19;
                                phi_435_ = select(true, false, (_e360 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_435_ = true;
                            }
                            let _e364 = phi_435_;
                            let _e365 = local_19;
                            phi_440_ = select(0f, _e365, _e364);
                        } else {
                            phi_440_ = 1267650600000000000000000000000f;
                        }
                        let _e368 = phi_440_;
                        local_34 = _e368;
                        let _e369 = local_27;
                        if _e369 {
                            let _e370 = local_22;
                            phi_450_ = select(true, false, (_e370 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_450_ = true;
                        }
                        let _e374 = phi_450_;
                        if _e374 {
                            let _e375 = local_22;
                            if (_e375 < 0.000000000000000000000000000000000000011754944f) {
                                let _e377 = local_22;
                                phi_464_ = select(true, false, (_e377 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_464_ = true;
                            }
                            let _e381 = phi_464_;
                            let _e382 = local_22;
                            phi_469_ = select(0f, _e382, _e381);
                        } else {
                            phi_469_ = 1267650600000000000000000000000f;
                        }
                        let _e385 = phi_469_;
                        local_35 = _e385;
                        let _e386 = local_33;
                        let _e387 = local_34;
                        local_36 = array<f32, 3>(_e386, _e387, _e385);
                        phi_1813_ = _e226;
                        phi_472_ = -2i;
                        phi_475_ = 0f;
                        phi_477_ = array<f32, 3>(0f, 0f, 0f);
                        loop {
                            let _e390 = phi_1813_;
                            let _e392 = phi_472_;
                            let _e394 = phi_475_;
                            let _e396 = phi_477_;
                            local_37 = _e392;
                            local_38 = _e394;
                            local_39 = _e396;
                            let _e397 = local_37;
                            let _e398 = (_e397 <= 2i);
                            local_40 = _e398;
                            if _e398 {
                                phi_486_ = -2i;
                                phi_489_ = _e394;
                                phi_491_ = _e396;
                                loop {
                                    let _e400 = phi_486_;
                                    let _e402 = phi_489_;
                                    let _e404 = phi_491_;
                                    local_41 = _e400;
                                    local_42 = _e402;
                                    local_43 = _e404;
                                    local_139 = _e402;
                                    local_140 = _e404;
                                    let _e405 = local_41;
                                    let _e406 = (_e405 <= 2i);
                                    local_44 = _e406;
                                    if _e406 {
                                        let _e407 = local_30;
                                        let _e408 = local_41;
                                        local_45 = (_e407 + _e408);
                                        let _e410 = local_32;
                                        let _e411 = local_37;
                                        local_46 = (_e410 + _e411);
                                        let _e413 = local_41;
                                        if (_e413 == 0i) {
                                            let _e415 = local_37;
                                            phi_510_ = select(true, false, (_e415 == 0i));
                                        } else {
                                            phi_510_ = true;
                                        }
                                        let _e419 = phi_510_;
                                        if _e419 {
                                            let _e420 = local_45;
                                            if (_e420 >= 0i) {
                                                let _e422 = local_46;
                                                if (_e422 >= 0i) {
                                                    let _e424 = local_7;
                                                    let _e426 = local_45;
                                                    if (_e426 < bitcast<i32>(_e424)) {
                                                        let _e428 = local_8;
                                                        let _e430 = local_46;
                                                        if (_e430 < bitcast<i32>(_e428)) {
                                                            let _e432 = local_46;
                                                            let _e434 = local_7;
                                                            let _e436 = local_45;
                                                            let _e439 = (3u * ((bitcast<u32>(_e432) * _e434) + bitcast<u32>(_e436)));
                                                            local_47 = _e439;
                                                            let _e440 = local_1;
                                                            if (_e439 < _e440) {
                                                            } else {
                                                                phi_1781_ = true;
                                                                break;
                                                            }
                                                            let _e442 = local_47;
                                                            let _e445 = global_4.member[_e442];
                                                            local_48 = bitcast<f32>(_e445);
                                                            let _e447 = local_47;
                                                            let _e448 = (_e447 + 1u);
                                                            local_49 = _e448;
                                                            let _e449 = local_1;
                                                            if (_e448 < _e449) {
                                                            } else {
                                                                phi_1781_ = true;
                                                                break;
                                                            }
                                                            let _e451 = local_49;
                                                            let _e454 = global_4.member[_e451];
                                                            local_50 = bitcast<f32>(_e454);
                                                            let _e456 = local_47;
                                                            let _e457 = (_e456 + 2u);
                                                            local_51 = _e457;
                                                            let _e458 = local_1;
                                                            if (_e457 < _e458) {
                                                            } else {
                                                                phi_1781_ = true;
                                                                break;
                                                            }
                                                            let _e460 = local_51;
                                                            let _e463 = global_4.member[_e460];
                                                            local_52 = bitcast<f32>(_e463);
                                                            let _e465 = local_48;
                                                            if (_e465 > 1267650600000000000000000000000f) {
                                                                let _e467 = local_48;
                                                                phi_604_ = select(true, false, (_e467 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_604_ = true;
                                                            }
                                                            let _e471 = phi_604_;
                                                            if _e471 {
                                                                let _e472 = local_48;
                                                                if (_e472 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e474 = local_48;
                                                                    phi_618_ = select(true, false, (_e474 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_618_ = true;
                                                                }
                                                                let _e478 = phi_618_;
                                                                let _e479 = local_48;
                                                                phi_623_ = select(0f, _e479, _e478);
                                                            } else {
                                                                phi_623_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e482 = phi_623_;
                                                            local_53 = _e482;
                                                            let _e483 = local_50;
                                                            if (_e483 > 1267650600000000000000000000000f) {
                                                                let _e485 = local_50;
                                                                phi_633_ = select(true, false, (_e485 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_633_ = true;
                                                            }
                                                            let _e489 = phi_633_;
                                                            if _e489 {
                                                                let _e490 = local_50;
                                                                if (_e490 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e492 = local_50;
                                                                    phi_647_ = select(true, false, (_e492 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_647_ = true;
                                                                }
                                                                let _e496 = phi_647_;
                                                                let _e497 = local_50;
                                                                phi_652_ = select(0f, _e497, _e496);
                                                            } else {
                                                                phi_652_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e500 = phi_652_;
                                                            local_54 = _e500;
                                                            let _e501 = local_52;
                                                            if (_e501 > 1267650600000000000000000000000f) {
                                                                let _e503 = local_52;
                                                                phi_662_ = select(true, false, (_e503 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_662_ = true;
                                                            }
                                                            let _e507 = phi_662_;
                                                            if _e507 {
                                                                let _e508 = local_52;
                                                                if (_e508 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e510 = local_52;
                                                                    phi_676_ = select(true, false, (_e510 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_676_ = true;
                                                                }
                                                                let _e514 = phi_676_;
                                                                let _e515 = local_52;
                                                                phi_681_ = select(0f, _e515, _e514);
                                                            } else {
                                                                phi_681_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e518 = phi_681_;
                                                            local_55 = _e518;
                                                            let _e519 = local_53;
                                                            if ((bitcast<u32>(_e519) & 2139095040u) != 2139095040u) {
                                                                let _e523 = local_54;
                                                                let _e526 = ((bitcast<u32>(_e523) & 2139095040u) != 2139095040u);
                                                                local_56 = _e526;
                                                                if _e526 {
                                                                    let _e527 = local_55;
                                                                    phi_697_ = ((bitcast<u32>(_e527) & 2139095040u) != 2139095040u);
                                                                } else {
                                                                    phi_697_ = bool();
                                                                }
                                                                let _e532 = phi_697_;
                                                                let _e533 = local_56;
                                                                phi_699_ = _e532;
                                                                phi_700_ = select(true, false, _e533);
                                                            } else {
                                                                phi_699_ = bool();
                                                                phi_700_ = true;
                                                            }
                                                            let _e536 = phi_699_;
                                                            let _e538 = phi_700_;
                                                            if select(_e536, false, _e538) {
                                                                let _e540 = local_43;
                                                                let _e542 = local_53;
                                                                let _e544 = local_43;
                                                                let _e546 = local_54;
                                                                let _e548 = local_43;
                                                                let _e550 = local_55;
                                                                let _e553 = local_42;
                                                                phi_718_ = (_e553 + 1f);
                                                                phi_719_ = array<f32, 3>((_e540[0] + _e542), (_e544[1] + _e546), (_e548[2] + _e550));
                                                            } else {
                                                                phi_718_ = _e402;
                                                                phi_719_ = _e404;
                                                            }
                                                            let _e556 = phi_718_;
                                                            let _e558 = phi_719_;
                                                            phi_720_ = _e556;
                                                            phi_721_ = _e558;
                                                        } else {
                                                            phi_720_ = _e402;
                                                            phi_721_ = _e404;
                                                        }
                                                        let _e560 = phi_720_;
                                                        let _e562 = phi_721_;
                                                        phi_722_ = _e560;
                                                        phi_723_ = _e562;
                                                    } else {
                                                        phi_722_ = _e402;
                                                        phi_723_ = _e404;
                                                    }
                                                    let _e564 = phi_722_;
                                                    let _e566 = phi_723_;
                                                    phi_724_ = _e564;
                                                    phi_725_ = _e566;
                                                } else {
                                                    phi_724_ = _e402;
                                                    phi_725_ = _e404;
                                                }
                                                let _e568 = phi_724_;
                                                let _e570 = phi_725_;
                                                phi_726_ = _e568;
                                                phi_727_ = _e570;
                                            } else {
                                                phi_726_ = _e402;
                                                phi_727_ = _e404;
                                            }
                                            let _e572 = phi_726_;
                                            let _e574 = phi_727_;
                                            phi_728_ = _e572;
                                            phi_729_ = _e574;
                                        } else {
                                            phi_728_ = _e402;
                                            phi_729_ = _e404;
                                        }
                                        let _e576 = phi_728_;
                                        let _e578 = phi_729_;
                                        let _e579 = local_41;
                                        phi_487_ = (_e579 + 1i);
                                        phi_490_ = _e576;
                                        phi_492_ = _e578;
                                    } else {
                                        phi_487_ = i32();
                                        phi_490_ = f32();
                                        phi_492_ = array<f32, 3>();
                                    }
                                    let _e582 = phi_487_;
                                    let _e584 = phi_490_;
                                    let _e586 = phi_492_;
                                    continue;
                                    continuing {
                                        let _e587 = local_44;
                                        phi_486_ = _e582;
                                        phi_489_ = _e584;
                                        phi_491_ = _e586;
                                        phi_1781_ = _e390;
                                        break if !(_e587);
                                    }
                                }
                                let _e590 = phi_1781_;
                                phi_1851_ = _e590;
                                if _e590 {
                                    break;
                                }
                                let _e591 = local_37;
                                phi_1852_ = _e590;
                                phi_473_ = (_e591 + 1i);
                                let _e1620 = local_139;
                                phi_476_ = _e1620;
                                let _e1623 = local_140;
                                phi_478_ = _e1623;
                            } else {
                                phi_1852_ = _e390;
                                phi_473_ = i32();
                                phi_476_ = f32();
                                phi_478_ = array<f32, 3>();
                            }
                            let _e594 = phi_1852_;
                            let _e596 = phi_473_;
                            let _e598 = phi_476_;
                            let _e600 = phi_478_;
                            continue;
                            continuing {
                                let _e601 = local_40;
                                phi_1813_ = _e594;
                                phi_472_ = _e596;
                                phi_475_ = _e598;
                                phi_477_ = _e600;
                                phi_1851_ = _e594;
                                break if !(_e601);
                            }
                        }
                        let _e604 = phi_1851_;
                        phi_1935_ = _e604;
                        if _e604 {
                            break;
                        }
                        let _e605 = local_38;
                        if (_e605 > 0f) {
                            let _e607 = local_39;
                            let _e609 = local_38;
                            let _e611 = local_39;
                            let _e613 = local_38;
                            let _e615 = local_39;
                            let _e617 = local_38;
                            phi_743_ = array<f32, 3>((_e607[0] / _e609), (_e611[1] / _e613), (_e615[2] / _e617));
                        } else {
                            phi_743_ = array<f32, 3>(0f, 0f, 0f);
                        }
                        let _e621 = phi_743_;
                        local_57 = _e621;
                        let _e622 = local_13;
                        let _e623 = local_2;
                        if (_e622 < _e623) {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e625 = local_13;
                        let _e628 = global_3.member[_e625];
                        let _e629 = bitcast<f32>(_e628);
                        local_58 = _e629;
                        let _e630 = bitcast<u32>(_e629);
                        local_59 = _e630;
                        if (_e630 == 2139095040u) {
                            let _e635 = global_5.member.member_8.member_1;
                            let _e640 = global_5.member.member_8.member;
                            let _e645 = global_5.member.member_8.member_2;
                            let _e651 = global_5.member.member_8.member_3;
                            phi_825_ = (0.5f * ((((2f * _e635) * _e640) / (_e645 - _e640)) * _e651));
                        } else {
                            let _e654 = local_59;
                            if (_e654 == 0u) {
                                phi_788_ = false;
                            } else {
                                let _e656 = local_59;
                                phi_788_ = (_e656 <= 2139095040u);
                            }
                            let _e659 = phi_788_;
                            if _e659 {
                                let _e663 = global_5.member.member_8.member_1;
                                let _e668 = global_5.member.member_8.member;
                                let _e673 = global_5.member.member_8.member_2;
                                local_60 = _e673;
                                let _e679 = global_5.member.member_8.member_3;
                                let _e680 = ((((2f * _e663) * _e668) / (_e673 - _e668)) * _e679);
                                local_61 = _e680;
                                if (_e680 == 0f) {
                                    phi_816_ = 0f;
                                } else {
                                    let _e682 = local_60;
                                    let _e683 = local_58;
                                    let _e686 = local_61;
                                    phi_816_ = (_e686 * (1f - (_e682 / _e683)));
                                }
                                let _e689 = phi_816_;
                                phi_817_ = _e689;
                            } else {
                                phi_817_ = bitcast<f32>(_e196);
                            }
                            let _e691 = phi_817_;
                            local_62 = _e691;
                            if (_e691 < 0f) {
                                let _e693 = local_62;
                                phi_823_ = -(_e693);
                            } else {
                                phi_823_ = _e691;
                            }
                            let _e696 = phi_823_;
                            phi_825_ = (0.5f * _e696);
                        }
                        let _e699 = phi_825_;
                        let _e703 = select(_e699, 0f, ((bitcast<u32>(_e699) & 2147483647u) > 2139095040u));
                        local_132 = _e703;
                        let _e706 = global_5.member.member_6;
                        local_63 = _e706;
                        if !((_e703 == _e703)) {
                            phi_1716_ = true;
                        } else {
                            let _e709 = local_63;
                            let _e710 = local_132;
                            phi_1716_ = (_e709 <= _e710);
                        }
                        let _e713 = phi_1716_;
                        let _e714 = local_63;
                        let _e715 = local_132;
                        local_133 = select(_e715, _e714, _e713);
                        let _e717 = local_33;
                        if ((bitcast<u32>(_e717) & 2139095040u) != 2139095040u) {
                            let _e721 = local_34;
                            let _e724 = ((bitcast<u32>(_e721) & 2139095040u) != 2139095040u);
                            local_64 = _e724;
                            if _e724 {
                                let _e725 = local_35;
                                phi_851_ = ((bitcast<u32>(_e725) & 2139095040u) != 2139095040u);
                            } else {
                                phi_851_ = bool();
                            }
                            let _e730 = phi_851_;
                            let _e731 = local_64;
                            phi_853_ = _e730;
                            phi_854_ = select(true, false, _e731);
                        } else {
                            phi_853_ = bool();
                            phi_854_ = true;
                        }
                        let _e734 = phi_853_;
                        let _e736 = phi_854_;
                        if select(_e734, false, _e736) {
                            let _e738 = local_59;
                            if (_e738 == 0u) {
                                phi_868_ = false;
                            } else {
                                let _e740 = local_59;
                                phi_868_ = (_e740 <= 2139095040u);
                            }
                            let _e743 = phi_868_;
                            if _e743 {
                                let _e744 = local_33;
                                let _e746 = local_34;
                                let _e749 = local_35;
                                let _e752 = local_57;
                                let _e755 = local_57;
                                let _e759 = local_57;
                                let _e766 = global_5.member.member_4;
                                if (((((0.2126f * _e744) + (0.7152f * _e746)) + (0.0722f * _e749)) - (((0.2126f * _e752[0]) + (0.7152f * _e755[1])) + (0.0722f * _e759[2]))) > _e766) {
                                    let _e770 = global_5.member.member_5;
                                    let _e771 = local_133;
                                    let _e772 = (_e771 > _e770);
                                    local_65 = _e772;
                                    if _e772 {
                                        let _e773 = local_36;
                                        let _e774 = local_57;
                                        let _e775 = local_133;
                                        let _e776 = local_58;
                                        phi_900_ = type_24(1u, type_23(_e773, _e774, _e775, _e776));
                                    } else {
                                        phi_900_ = type_24();
                                    }
                                    let _e780 = phi_900_;
                                    let _e781 = local_65;
                                    phi_902_ = _e780;
                                    phi_903_ = select(true, false, _e781);
                                } else {
                                    phi_902_ = type_24();
                                    phi_903_ = true;
                                }
                                let _e784 = phi_902_;
                                let _e786 = phi_903_;
                                phi_904_ = _e784;
                                phi_905_ = _e786;
                            } else {
                                phi_904_ = type_24();
                                phi_905_ = true;
                            }
                            let _e788 = phi_904_;
                            let _e790 = phi_905_;
                            phi_906_ = _e788;
                            phi_907_ = _e790;
                        } else {
                            phi_906_ = type_24();
                            phi_907_ = true;
                        }
                        let _e792 = phi_906_;
                        let _e794 = phi_907_;
                        if _e794 {
                            phi_912_ = type_24(0u, type_24().member_1);
                        } else {
                            phi_912_ = _e792;
                        }
                        let _e799 = phi_912_;
                        local_66 = _e799;
                        if (bitcast<i32>(_e799.member) != 0i) {
                            let _e803 = local_66;
                            local_67 = _e803.member_1.member;
                            let _e806 = local_66;
                            local_68 = _e806.member_1.member_1;
                            let _e809 = local_66;
                            local_69 = _e809.member_1.member_2;
                            let _e812 = local_66;
                            local_70 = _e812.member_1.member_3;
                            let _e815 = local_13;
                            let _e816 = local_3;
                            if (_e815 < _e816) {
                            } else {
                                phi_1935_ = true;
                                break;
                            }
                            let _e818 = local_13;
                            let _e821 = global_6.member[_e818];
                            local_71 = _e821;
                            let _e824 = global_5.member.member_2;
                            if (_e821 < _e824) {
                                let _e826 = local_28;
                                if _e826 {
                                    phi_1935_ = true;
                                    break;
                                }
                                let _e827 = local_29;
                                local_72 = (f32(_e827) + 0.5f);
                                let _e830 = local_28;
                                if _e830 {
                                    phi_1935_ = true;
                                    break;
                                }
                                let _e831 = local_31;
                                local_73 = (f32(_e831) + 0.5f);
                                let _e834 = local_69;
                                let _e835 = (_e834 + 0.5f);
                                local_74 = _e835;
                                let _e839 = global_5.member.member_8.member_2;
                                let _e840 = local_70;
                                local_134 = select(1f, -1f, (_e840 < _e839));
                                if (_e835 >= 5f) {
                                    let _e847 = global_5.member.member_9.member_6;
                                    if (_e847 > 0u) {
                                        let _e852 = global_5.member.member_9.member_5;
                                        let _e853 = local_69;
                                        let _e855 = local_69;
                                        phi_999_ = ((_e852 * _e853) * _e855);
                                    } else {
                                        let _e857 = local_69;
                                        let _e858 = (_e857 + -0.5f);
                                        let _e862 = global_5.member.member_9.member_5;
                                        phi_999_ = (_e862 * (((_e858 * _e858) + _e858) + 0.33333334f));
                                    }
                                    let _e868 = phi_999_;
                                    phi_1933_ = _e604;
                                    phi_1551_ = _e868;
                                } else {
                                    let _e869 = local_73;
                                    let _e870 = local_74;
                                    let _e874 = local_73;
                                    let _e875 = local_74;
                                    local_75 = floor(((_e874 + _e875) - 0.5f));
                                    let _e879 = local_72;
                                    let _e880 = local_74;
                                    let _e884 = local_72;
                                    let _e885 = local_74;
                                    local_76 = floor(((_e884 + _e885) - 0.5f));
                                    phi_1864_ = _e604;
                                    phi_1014_ = ceil(((_e869 - _e870) - 0.5f));
                                    phi_1017_ = 0f;
                                    loop {
                                        let _e890 = phi_1864_;
                                        let _e892 = phi_1014_;
                                        let _e894 = phi_1017_;
                                        local_77 = _e892;
                                        local_143 = _e894;
                                        let _e895 = local_77;
                                        let _e896 = local_75;
                                        let _e897 = (_e895 <= _e896);
                                        local_78 = _e897;
                                        if _e897 {
                                            let _e898 = local_77;
                                            let _e900 = local_73;
                                            local_79 = ((_e898 + 0.5f) - _e900);
                                            phi_1028_ = ceil(((_e879 - _e880) - 0.5f));
                                            phi_1031_ = _e894;
                                            loop {
                                                let _e903 = phi_1028_;
                                                let _e905 = phi_1031_;
                                                local_80 = _e903;
                                                local_142 = _e905;
                                                let _e906 = local_80;
                                                let _e907 = local_76;
                                                let _e908 = (_e906 <= _e907);
                                                local_81 = _e908;
                                                if _e908 {
                                                    let _e909 = local_80;
                                                    let _e911 = local_72;
                                                    let _e912 = ((_e909 + 0.5f) - _e911);
                                                    local_82 = _e912;
                                                    let _e914 = local_79;
                                                    let _e915 = local_79;
                                                    local_83 = ((_e912 * _e912) + (_e914 * _e915));
                                                    let _e921 = global_5.member.member_9.member;
                                                    local_84 = _e921;
                                                    let _e922 = (_e921 == 0u);
                                                    local_85 = _e922;
                                                    if _e922 {
                                                        let _e926 = global_5.member.member_9.member_6;
                                                        phi_1055_ = (_e926 == 0u);
                                                    } else {
                                                        phi_1055_ = false;
                                                    }
                                                    let _e929 = phi_1055_;
                                                    if _e929 {
                                                        let _e930 = local_69;
                                                        let _e931 = (_e930 + -0.5f);
                                                        let _e934 = local_83;
                                                        let _e937 = local_83;
                                                        let _e939 = local_74;
                                                        let _e940 = (_e939 - sqrt(_e937));
                                                        phi_1529_ = select(select(0f, select(1f, _e940, (_e940 < 1f)), (0f < _e940)), 1f, ((0f < _e931) && (_e934 <= (_e931 * _e931))));
                                                    } else {
                                                        let _e946 = local_85;
                                                        if _e946 {
                                                            let _e950 = global_5.member.member_9.member_6;
                                                            phi_1091_ = (_e950 == 0u);
                                                        } else {
                                                            phi_1091_ = false;
                                                        }
                                                        let _e953 = phi_1091_;
                                                        if _e953 {
                                                            let _e954 = local_69;
                                                            let _e955 = (_e954 + -0.5f);
                                                            let _e958 = local_83;
                                                            let _e961 = local_83;
                                                            let _e963 = local_74;
                                                            let _e964 = (_e963 - sqrt(_e961));
                                                            phi_1528_ = select(select(0f, select(1f, _e964, (_e964 < 1f)), (0f < _e964)), 1f, ((0f < _e955) && (_e958 <= (_e955 * _e955))));
                                                        } else {
                                                            let _e970 = local_134;
                                                            let _e971 = local_82;
                                                            local_86 = (_e970 * _e971);
                                                            let _e973 = local_134;
                                                            let _e974 = local_79;
                                                            local_87 = (_e973 * _e974);
                                                            let _e979 = global_5.member.member_9.member_6;
                                                            local_88 = _e979;
                                                            if (_e979 > 0u) {
                                                                let _e981 = local_69;
                                                                if (_e981 > 0f) {
                                                                    let _e983 = local_86;
                                                                    let _e984 = local_69;
                                                                    let _e986 = local_87;
                                                                    let _e987 = local_69;
                                                                    let _e989 = local_88;
                                                                    let _e990 = f32(_e989);
                                                                    local_89 = _e990;
                                                                    let _e994 = (((((_e983 / _e984) + 1f) * 0.5f) * _e990) - 0.5f);
                                                                    local_90 = _e994;
                                                                    local_91 = (((((_e986 / _e987) + 1f) * 0.5f) * _e990) - 0.5f);
                                                                    if (_e994 > -1f) {
                                                                        let _e1000 = local_91;
                                                                        if (_e1000 > -1f) {
                                                                            let _e1002 = local_90;
                                                                            let _e1003 = local_89;
                                                                            if (_e1002 < _e1003) {
                                                                                let _e1005 = local_91;
                                                                                let _e1006 = local_89;
                                                                                let _e1007 = (_e1005 < _e1006);
                                                                                local_92 = _e1007;
                                                                                if _e1007 {
                                                                                    let _e1008 = local_90;
                                                                                    let _e1009 = floor(_e1008);
                                                                                    local_93 = _e1009;
                                                                                    let _e1010 = local_91;
                                                                                    let _e1011 = floor(_e1010);
                                                                                    local_94 = _e1011;
                                                                                    let _e1012 = local_90;
                                                                                    local_95 = (_e1012 - _e1009);
                                                                                    let _e1014 = local_91;
                                                                                    local_96 = (_e1014 - _e1011);
                                                                                    let _e1016 = (_e1009 < 0f);
                                                                                    local_97 = _e1016;
                                                                                    if _e1016 {
                                                                                        phi_1220_ = f32();
                                                                                        phi_1221_ = true;
                                                                                    } else {
                                                                                        let _e1017 = local_94;
                                                                                        if (_e1017 < 0f) {
                                                                                            phi_1218_ = f32();
                                                                                            phi_1219_ = true;
                                                                                        } else {
                                                                                            let _e1019 = local_93;
                                                                                            let _e1020 = local_89;
                                                                                            if (_e1019 >= _e1020) {
                                                                                                phi_1216_ = f32();
                                                                                                phi_1217_ = true;
                                                                                            } else {
                                                                                                let _e1022 = local_94;
                                                                                                let _e1023 = local_89;
                                                                                                let _e1024 = (_e1022 >= _e1023);
                                                                                                if _e1024 {
                                                                                                    phi_1215_ = f32();
                                                                                                } else {
                                                                                                    let _e1025 = local_94;
                                                                                                    let _e1027 = local_94;
                                                                                                    let _e1030 = local_94;
                                                                                                    let _e1034 = local_88;
                                                                                                    let _e1036 = local_93;
                                                                                                    let _e1038 = local_93;
                                                                                                    let _e1041 = local_93;
                                                                                                    let _e1045 = ((select(select(u32(_e1025), 0u, !((_e1027 >= 0f))), 4294967295u, (_e1030 > 4294967000f)) * _e1034) + select(select(u32(_e1036), 0u, !((_e1038 >= 0f))), 4294967295u, (_e1041 > 4294967000f)));
                                                                                                    local_98 = _e1045;
                                                                                                    let _e1046 = local_6;
                                                                                                    if (_e1045 < _e1046) {
                                                                                                    } else {
                                                                                                        phi_1853_ = true;
                                                                                                        break;
                                                                                                    }
                                                                                                    let _e1048 = local_98;
                                                                                                    let _e1051 = global_9.member[_e1048];
                                                                                                    phi_1215_ = bitcast<f32>(_e1051);
                                                                                                }
                                                                                                let _e1054 = phi_1215_;
                                                                                                phi_1216_ = _e1054;
                                                                                                phi_1217_ = _e1024;
                                                                                            }
                                                                                            let _e1056 = phi_1216_;
                                                                                            let _e1058 = phi_1217_;
                                                                                            phi_1218_ = _e1056;
                                                                                            phi_1219_ = _e1058;
                                                                                        }
                                                                                        let _e1060 = phi_1218_;
                                                                                        let _e1062 = phi_1219_;
                                                                                        phi_1220_ = _e1060;
                                                                                        phi_1221_ = _e1062;
                                                                                    }
                                                                                    let _e1064 = phi_1220_;
                                                                                    let _e1066 = phi_1221_;
                                                                                    let _e1068 = local_95;
                                                                                    let _e1069 = (1f - _e1068);
                                                                                    local_99 = _e1069;
                                                                                    local_100 = (select(_e1064, 0f, _e1066) * _e1069);
                                                                                    let _e1071 = local_93;
                                                                                    let _e1072 = (_e1071 + 1f);
                                                                                    local_101 = _e1072;
                                                                                    let _e1073 = (_e1072 < 0f);
                                                                                    local_102 = _e1073;
                                                                                    if _e1073 {
                                                                                        phi_1284_ = f32();
                                                                                        phi_1285_ = true;
                                                                                    } else {
                                                                                        let _e1074 = local_94;
                                                                                        if (_e1074 < 0f) {
                                                                                            phi_1282_ = f32();
                                                                                            phi_1283_ = true;
                                                                                        } else {
                                                                                            let _e1076 = local_101;
                                                                                            let _e1077 = local_89;
                                                                                            if (_e1076 >= _e1077) {
                                                                                                phi_1280_ = f32();
                                                                                                phi_1281_ = true;
                                                                                            } else {
                                                                                                let _e1079 = local_94;
                                                                                                let _e1080 = local_89;
                                                                                                let _e1081 = (_e1079 >= _e1080);
                                                                                                if _e1081 {
                                                                                                    phi_1279_ = f32();
                                                                                                } else {
                                                                                                    let _e1082 = local_94;
                                                                                                    let _e1084 = local_94;
                                                                                                    let _e1087 = local_94;
                                                                                                    let _e1091 = local_88;
                                                                                                    let _e1093 = local_101;
                                                                                                    let _e1095 = local_101;
                                                                                                    let _e1098 = local_101;
                                                                                                    let _e1102 = ((select(select(u32(_e1082), 0u, !((_e1084 >= 0f))), 4294967295u, (_e1087 > 4294967000f)) * _e1091) + select(select(u32(_e1093), 0u, !((_e1095 >= 0f))), 4294967295u, (_e1098 > 4294967000f)));
                                                                                                    local_103 = _e1102;
                                                                                                    let _e1103 = local_6;
                                                                                                    if (_e1102 < _e1103) {
                                                                                                    } else {
                                                                                                        phi_1853_ = true;
                                                                                                        break;
                                                                                                    }
                                                                                                    let _e1105 = local_103;
                                                                                                    let _e1108 = global_9.member[_e1105];
                                                                                                    phi_1279_ = bitcast<f32>(_e1108);
                                                                                                }
                                                                                                let _e1111 = phi_1279_;
                                                                                                phi_1280_ = _e1111;
                                                                                                phi_1281_ = _e1081;
                                                                                            }
                                                                                            let _e1113 = phi_1280_;
                                                                                            let _e1115 = phi_1281_;
                                                                                            phi_1282_ = _e1113;
                                                                                            phi_1283_ = _e1115;
                                                                                        }
                                                                                        let _e1117 = phi_1282_;
                                                                                        let _e1119 = phi_1283_;
                                                                                        phi_1284_ = _e1117;
                                                                                        phi_1285_ = _e1119;
                                                                                    }
                                                                                    let _e1121 = phi_1284_;
                                                                                    let _e1123 = phi_1285_;
                                                                                    let _e1125 = local_95;
                                                                                    let _e1127 = local_100;
                                                                                    local_104 = (_e1127 + (select(_e1121, 0f, _e1123) * _e1125));
                                                                                    let _e1129 = local_94;
                                                                                    local_105 = (_e1129 + 1f);
                                                                                    let _e1131 = local_97;
                                                                                    if _e1131 {
                                                                                        phi_1348_ = f32();
                                                                                        phi_1349_ = true;
                                                                                    } else {
                                                                                        let _e1132 = local_105;
                                                                                        if (_e1132 < 0f) {
                                                                                            phi_1346_ = f32();
                                                                                            phi_1347_ = true;
                                                                                        } else {
                                                                                            let _e1134 = local_93;
                                                                                            let _e1135 = local_89;
                                                                                            if (_e1134 >= _e1135) {
                                                                                                phi_1344_ = f32();
                                                                                                phi_1345_ = true;
                                                                                            } else {
                                                                                                let _e1137 = local_105;
                                                                                                let _e1138 = local_89;
                                                                                                let _e1139 = (_e1137 >= _e1138);
                                                                                                if _e1139 {
                                                                                                    phi_1343_ = f32();
                                                                                                } else {
                                                                                                    let _e1140 = local_105;
                                                                                                    let _e1142 = local_105;
                                                                                                    let _e1145 = local_105;
                                                                                                    let _e1149 = local_88;
                                                                                                    let _e1151 = local_93;
                                                                                                    let _e1153 = local_93;
                                                                                                    let _e1156 = local_93;
                                                                                                    let _e1160 = ((select(select(u32(_e1140), 0u, !((_e1142 >= 0f))), 4294967295u, (_e1145 > 4294967000f)) * _e1149) + select(select(u32(_e1151), 0u, !((_e1153 >= 0f))), 4294967295u, (_e1156 > 4294967000f)));
                                                                                                    local_106 = _e1160;
                                                                                                    let _e1161 = local_6;
                                                                                                    if (_e1160 < _e1161) {
                                                                                                    } else {
                                                                                                        phi_1853_ = true;
                                                                                                        break;
                                                                                                    }
                                                                                                    let _e1163 = local_106;
                                                                                                    let _e1166 = global_9.member[_e1163];
                                                                                                    phi_1343_ = bitcast<f32>(_e1166);
                                                                                                }
                                                                                                let _e1169 = phi_1343_;
                                                                                                phi_1344_ = _e1169;
                                                                                                phi_1345_ = _e1139;
                                                                                            }
                                                                                            let _e1171 = phi_1344_;
                                                                                            let _e1173 = phi_1345_;
                                                                                            phi_1346_ = _e1171;
                                                                                            phi_1347_ = _e1173;
                                                                                        }
                                                                                        let _e1175 = phi_1346_;
                                                                                        let _e1177 = phi_1347_;
                                                                                        phi_1348_ = _e1175;
                                                                                        phi_1349_ = _e1177;
                                                                                    }
                                                                                    let _e1179 = phi_1348_;
                                                                                    let _e1181 = phi_1349_;
                                                                                    let _e1183 = local_99;
                                                                                    local_107 = (select(_e1179, 0f, _e1181) * _e1183);
                                                                                    let _e1185 = local_102;
                                                                                    if _e1185 {
                                                                                        phi_1413_ = f32();
                                                                                        phi_1414_ = true;
                                                                                    } else {
                                                                                        let _e1186 = local_105;
                                                                                        if (_e1186 < 0f) {
                                                                                            phi_1411_ = f32();
                                                                                            phi_1412_ = true;
                                                                                        } else {
                                                                                            let _e1188 = local_101;
                                                                                            let _e1189 = local_89;
                                                                                            if (_e1188 >= _e1189) {
                                                                                                phi_1409_ = f32();
                                                                                                phi_1410_ = true;
                                                                                            } else {
                                                                                                let _e1191 = local_105;
                                                                                                let _e1192 = local_89;
                                                                                                let _e1193 = (_e1191 >= _e1192);
                                                                                                if _e1193 {
                                                                                                    phi_1408_ = f32();
                                                                                                } else {
                                                                                                    let _e1194 = local_105;
                                                                                                    let _e1196 = local_105;
                                                                                                    let _e1199 = local_105;
                                                                                                    let _e1203 = local_88;
                                                                                                    let _e1205 = local_101;
                                                                                                    let _e1207 = local_101;
                                                                                                    let _e1210 = local_101;
                                                                                                    let _e1214 = ((select(select(u32(_e1194), 0u, !((_e1196 >= 0f))), 4294967295u, (_e1199 > 4294967000f)) * _e1203) + select(select(u32(_e1205), 0u, !((_e1207 >= 0f))), 4294967295u, (_e1210 > 4294967000f)));
                                                                                                    local_108 = _e1214;
                                                                                                    let _e1215 = local_6;
                                                                                                    if (_e1214 < _e1215) {
                                                                                                    } else {
                                                                                                        phi_1853_ = true;
                                                                                                        break;
                                                                                                    }
                                                                                                    let _e1217 = local_108;
                                                                                                    let _e1220 = global_9.member[_e1217];
                                                                                                    phi_1408_ = bitcast<f32>(_e1220);
                                                                                                }
                                                                                                let _e1223 = phi_1408_;
                                                                                                phi_1409_ = _e1223;
                                                                                                phi_1410_ = _e1193;
                                                                                            }
                                                                                            let _e1225 = phi_1409_;
                                                                                            let _e1227 = phi_1410_;
                                                                                            phi_1411_ = _e1225;
                                                                                            phi_1412_ = _e1227;
                                                                                        }
                                                                                        let _e1229 = phi_1411_;
                                                                                        let _e1231 = phi_1412_;
                                                                                        phi_1413_ = _e1229;
                                                                                        phi_1414_ = _e1231;
                                                                                    }
                                                                                    let _e1233 = phi_1413_;
                                                                                    let _e1235 = phi_1414_;
                                                                                    let _e1237 = local_95;
                                                                                    let _e1239 = local_107;
                                                                                    let _e1241 = local_96;
                                                                                    let _e1243 = local_104;
                                                                                    let _e1245 = local_96;
                                                                                    phi_1425_ = ((_e1243 * (1f - _e1241)) + ((_e1239 + (select(_e1233, 0f, _e1235) * _e1237)) * _e1245));
                                                                                } else {
                                                                                    phi_1425_ = f32();
                                                                                }
                                                                                let _e1249 = phi_1425_;
                                                                                let _e1250 = local_92;
                                                                                phi_1427_ = _e1249;
                                                                                phi_1428_ = select(true, false, _e1250);
                                                                            } else {
                                                                                phi_1427_ = f32();
                                                                                phi_1428_ = true;
                                                                            }
                                                                            let _e1253 = phi_1427_;
                                                                            let _e1255 = phi_1428_;
                                                                            phi_1429_ = _e1253;
                                                                            phi_1430_ = _e1255;
                                                                        } else {
                                                                            phi_1429_ = f32();
                                                                            phi_1430_ = true;
                                                                        }
                                                                        let _e1257 = phi_1429_;
                                                                        let _e1259 = phi_1430_;
                                                                        phi_1431_ = _e1257;
                                                                        phi_1432_ = _e1259;
                                                                    } else {
                                                                        phi_1431_ = f32();
                                                                        phi_1432_ = true;
                                                                    }
                                                                    let _e1261 = phi_1431_;
                                                                    let _e1263 = phi_1432_;
                                                                    phi_1437_ = select(_e1261, 0f, _e1263);
                                                                } else {
                                                                    phi_1437_ = 0f;
                                                                }
                                                                let _e1266 = phi_1437_;
                                                                phi_1527_ = _e1266;
                                                            } else {
                                                                let _e1267 = local_86;
                                                                let _e1268 = local_86;
                                                                let _e1270 = local_87;
                                                                let _e1271 = local_87;
                                                                let _e1274 = sqrt(((_e1267 * _e1268) + (_e1270 * _e1271)));
                                                                local_109 = _e1274;
                                                                let _e1275 = local_85;
                                                                if _e1275 {
                                                                    phi_1514_ = _e1274;
                                                                } else {
                                                                    let _e1279 = global_5.member.member_9.member_2;
                                                                    let _e1281 = local_86;
                                                                    let _e1284 = local_87;
                                                                    phi_1456_ = 1u;
                                                                    phi_1459_ = ((_e1281 * _e1279[0]) + (_e1284 * _e1279[1]));
                                                                    phi_1461_ = _e1279;
                                                                    loop {
                                                                        let _e1288 = phi_1456_;
                                                                        let _e1290 = phi_1459_;
                                                                        let _e1292 = phi_1461_;
                                                                        local_110 = _e1288;
                                                                        local_111 = _e1290;
                                                                        local_112 = _e1292;
                                                                        let _e1293 = local_110;
                                                                        let _e1294 = local_84;
                                                                        let _e1295 = (_e1293 < _e1294);
                                                                        local_113 = _e1295;
                                                                        if _e1295 {
                                                                            let _e1296 = local_112;
                                                                            let _e1302 = global_5.member.member_9.member_3[0u];
                                                                            let _e1304 = local_112;
                                                                            let _e1310 = global_5.member.member_9.member_3[1u];
                                                                            let _e1312 = ((_e1296[0] * _e1302) - (_e1304[1] * _e1310));
                                                                            let _e1315 = ((_e1296[0] * _e1310) + (_e1304[1] * _e1302));
                                                                            let _e1317 = local_86;
                                                                            let _e1319 = local_87;
                                                                            let _e1321 = ((_e1317 * _e1312) + (_e1319 * _e1315));
                                                                            let _e1322 = local_111;
                                                                            let _e1324 = local_111;
                                                                            let _e1326 = local_110;
                                                                            phi_1457_ = (_e1326 + 1u);
                                                                            phi_1460_ = select(_e1324, _e1321, (_e1321 > _e1322));
                                                                            phi_1462_ = array<f32, 2>(_e1312, _e1315);
                                                                        } else {
                                                                            phi_1457_ = u32();
                                                                            phi_1460_ = f32();
                                                                            phi_1462_ = array<f32, 2>();
                                                                        }
                                                                        let _e1329 = phi_1457_;
                                                                        let _e1331 = phi_1460_;
                                                                        let _e1333 = phi_1462_;
                                                                        continue;
                                                                        continuing {
                                                                            let _e1334 = local_113;
                                                                            phi_1456_ = _e1329;
                                                                            phi_1459_ = _e1331;
                                                                            phi_1461_ = _e1333;
                                                                            break if !(_e1334);
                                                                        }
                                                                    }
                                                                    let _e1339 = global_5.member.member_9.member_1;
                                                                    let _e1341 = local_111;
                                                                    let _e1346 = global_5.member.member_9.member_4;
                                                                    let _e1348 = local_109;
                                                                    phi_1514_ = ((((1f - _e1339) * _e1341) * _e1346) + (_e1339 * _e1348));
                                                                }
                                                                let _e1352 = phi_1514_;
                                                                let _e1353 = local_74;
                                                                let _e1354 = (_e1353 - _e1352);
                                                                phi_1527_ = select(0f, select(1f, _e1354, (_e1354 < 1f)), (0f < _e1354));
                                                            }
                                                            let _e1360 = phi_1527_;
                                                            phi_1528_ = _e1360;
                                                        }
                                                        let _e1362 = phi_1528_;
                                                        phi_1529_ = _e1362;
                                                    }
                                                    let _e1364 = phi_1529_;
                                                    let _e1365 = local_81;
                                                    local_135 = select(0f, _e1364, _e1365);
                                                    phi_1535_ = 0u;
                                                    phi_1538_ = _e905;
                                                    loop {
                                                        let _e1368 = phi_1535_;
                                                        let _e1370 = phi_1538_;
                                                        local_114 = _e1368;
                                                        local_115 = _e1370;
                                                        local_141 = _e1370;
                                                        let _e1371 = local_114;
                                                        let _e1372 = (_e1371 < 1u);
                                                        local_116 = _e1372;
                                                        if _e1372 {
                                                            let _e1373 = local_115;
                                                            let _e1374 = local_135;
                                                            let _e1376 = local_114;
                                                            phi_1536_ = (_e1376 + 1u);
                                                            phi_1539_ = (_e1373 + _e1374);
                                                        } else {
                                                            phi_1536_ = u32();
                                                            phi_1539_ = f32();
                                                        }
                                                        let _e1379 = phi_1536_;
                                                        let _e1381 = phi_1539_;
                                                        continue;
                                                        continuing {
                                                            let _e1382 = local_116;
                                                            phi_1535_ = _e1379;
                                                            phi_1538_ = _e1381;
                                                            break if !(_e1382);
                                                        }
                                                    }
                                                    let _e1384 = local_80;
                                                    phi_1029_ = (_e1384 + 1f);
                                                    let _e1705 = local_141;
                                                    phi_1032_ = _e1705;
                                                } else {
                                                    phi_1029_ = f32();
                                                    phi_1032_ = f32();
                                                }
                                                let _e1387 = phi_1029_;
                                                let _e1389 = phi_1032_;
                                                continue;
                                                continuing {
                                                    let _e1390 = local_81;
                                                    phi_1028_ = _e1387;
                                                    phi_1031_ = _e1389;
                                                    phi_1853_ = _e890;
                                                    break if !(_e1390);
                                                }
                                            }
                                            let _e1393 = phi_1853_;
                                            phi_1922_ = _e1393;
                                            if _e1393 {
                                                break;
                                            }
                                            let _e1394 = local_77;
                                            phi_1923_ = _e1393;
                                            phi_1015_ = (_e1394 + 1f);
                                            let _e1711 = local_142;
                                            phi_1018_ = _e1711;
                                        } else {
                                            phi_1923_ = _e890;
                                            phi_1015_ = f32();
                                            phi_1018_ = f32();
                                        }
                                        let _e1397 = phi_1923_;
                                        let _e1399 = phi_1015_;
                                        let _e1401 = phi_1018_;
                                        continue;
                                        continuing {
                                            let _e1402 = local_78;
                                            phi_1864_ = _e1397;
                                            phi_1014_ = _e1399;
                                            phi_1017_ = _e1401;
                                            phi_1922_ = _e1397;
                                            break if !(_e1402);
                                        }
                                    }
                                    let _e1405 = phi_1922_;
                                    phi_1935_ = _e1405;
                                    if _e1405 {
                                        break;
                                    }
                                    phi_1933_ = _e1405;
                                    let _e1716 = local_143;
                                    phi_1551_ = _e1716;
                                }
                                let _e1407 = phi_1933_;
                                let _e1409 = phi_1551_;
                                local_117 = (1f / _e1409);
                                let _e1411 = local_67;
                                local_118 = _e1411[0];
                                let _e1413 = local_68;
                                local_119 = _e1413[0];
                                if !((_e1411[0] == _e1411[0])) {
                                    phi_1734_ = true;
                                } else {
                                    let _e1417 = local_119;
                                    let _e1418 = local_118;
                                    phi_1734_ = (_e1417 <= _e1418);
                                }
                                let _e1421 = phi_1734_;
                                let _e1422 = local_119;
                                let _e1423 = local_118;
                                local_136 = select(_e1423, _e1422, _e1421);
                                let _e1425 = local_67;
                                local_120 = _e1425[1];
                                let _e1427 = local_68;
                                local_121 = _e1427[1];
                                if !((_e1425[1] == _e1425[1])) {
                                    phi_1749_ = true;
                                } else {
                                    let _e1431 = local_121;
                                    let _e1432 = local_120;
                                    phi_1749_ = (_e1431 <= _e1432);
                                }
                                let _e1435 = phi_1749_;
                                let _e1436 = local_121;
                                let _e1437 = local_120;
                                local_137 = select(_e1437, _e1436, _e1435);
                                let _e1439 = local_67;
                                local_122 = _e1439[2];
                                let _e1441 = local_68;
                                local_123 = _e1441[2];
                                if !((_e1439[2] == _e1439[2])) {
                                    phi_1764_ = true;
                                } else {
                                    let _e1445 = local_123;
                                    let _e1446 = local_122;
                                    phi_1764_ = (_e1445 <= _e1446);
                                }
                                let _e1449 = phi_1764_;
                                let _e1450 = local_123;
                                let _e1451 = local_122;
                                let _e1452 = select(_e1451, _e1450, _e1449);
                                let _e1453 = local_136;
                                let _e1454 = local_137;
                                let _e1456 = local_118;
                                let _e1457 = local_136;
                                let _e1459 = local_117;
                                let _e1461 = local_120;
                                let _e1462 = local_137;
                                let _e1464 = local_117;
                                let _e1466 = local_122;
                                let _e1468 = local_117;
                                let _e1471 = local_72;
                                local_138[0u] = _e1471;
                                let _e1473 = local_73;
                                local_138[1u] = _e1473;
                                let _e1475 = local_74;
                                local_138[2u] = _e1475;
                                let _e1477 = local_134;
                                local_138[3u] = _e1477;
                                local_138[4u] = ((_e1456 - _e1457) * _e1459);
                                local_138[5u] = ((_e1461 - _e1462) * _e1464);
                                local_138[6u] = ((_e1466 - _e1452) * _e1468);
                                local_138[7u] = 0f;
                                phi_1581_ = 0u;
                                loop {
                                    let _e1483 = phi_1581_;
                                    local_124 = _e1483;
                                    let _e1484 = local_124;
                                    let _e1485 = (_e1484 < 8u);
                                    local_125 = _e1485;
                                    if _e1485 {
                                        let _e1486 = local_71;
                                        let _e1488 = local_124;
                                        local_126 = ((_e1486 * 8u) + _e1488);
                                        let _e1490 = local_125;
                                        if _e1490 {
                                        } else {
                                            phi_1924_ = true;
                                            break;
                                        }
                                        let _e1491 = local_124;
                                        let _e1493 = local_138[_e1491];
                                        local_127 = bitcast<u32>(_e1493);
                                        let _e1495 = local_126;
                                        let _e1496 = local_4;
                                        if (_e1495 < _e1496) {
                                        } else {
                                            phi_1924_ = true;
                                            break;
                                        }
                                        let _e1498 = local_126;
                                        let _e1501 = local_127;
                                        global_7.member[_e1498] = _e1501;
                                        let _e1502 = local_124;
                                        phi_1582_ = (_e1502 + 1u);
                                    } else {
                                        phi_1582_ = u32();
                                    }
                                    let _e1505 = phi_1582_;
                                    continue;
                                    continuing {
                                        let _e1506 = local_125;
                                        phi_1581_ = _e1505;
                                        phi_1924_ = _e1407;
                                        break if !(_e1506);
                                    }
                                }
                                let _e1509 = phi_1924_;
                                phi_1935_ = _e1509;
                                if _e1509 {
                                    break;
                                }
                                phi_1939_ = _e1509;
                                phi_1615_ = array<f32, 3>(_e1453, _e1454, _e1452);
                            } else {
                                phi_1939_ = _e604;
                                phi_1615_ = _e320;
                            }
                            let _e1511 = phi_1939_;
                            let _e1513 = phi_1615_;
                            phi_1938_ = _e1511;
                            phi_1616_ = _e1513;
                        } else {
                            phi_1938_ = _e604;
                            phi_1616_ = _e320;
                        }
                        let _e1515 = phi_1938_;
                        let _e1517 = phi_1616_;
                        local_128 = _e1517;
                        local_129 = bitcast<u32>(_e1517[0]);
                        let _e1520 = local_14;
                        let _e1521 = local_5;
                        if (_e1520 < _e1521) {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e1523 = local_14;
                        let _e1526 = local_129;
                        global_8.member[_e1523] = _e1526;
                        let _e1527 = local_128;
                        local_130 = bitcast<u32>(_e1527[1]);
                        let _e1530 = local_17;
                        let _e1531 = local_5;
                        if (_e1530 < _e1531) {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e1533 = local_17;
                        let _e1536 = local_130;
                        global_8.member[_e1533] = _e1536;
                        let _e1537 = local_128;
                        local_131 = bitcast<u32>(_e1537[2]);
                        let _e1540 = local_20;
                        let _e1541 = local_5;
                        if (_e1540 < _e1541) {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e1543 = local_20;
                        let _e1546 = local_131;
                        global_8.member[_e1543] = _e1546;
                        phi_1937_ = _e1515;
                    } else {
                        phi_1937_ = _e226;
                    }
                    let _e1548 = phi_1937_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e1549 = local_11;
                    let _e1550 = local_10;
                    phi_1936_ = _e1548;
                    phi_159_ = (_e1549 + _e1550);
                } else {
                    phi_1936_ = _e226;
                    phi_159_ = u32();
                }
                let _e1553 = phi_1936_;
                let _e1555 = phi_159_;
                continue;
                continuing {
                    let _e1556 = local_12;
                    phi_1850_ = _e1553;
                    phi_158_ = _e1555;
                    phi_1935_ = _e1553;
                    break if !(_e1556);
                }
            }
            let _e1559 = phi_1935_;
            if _e1559 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn bokeh_emit(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
