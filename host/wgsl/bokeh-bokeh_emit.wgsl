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
                                let _e1608 = local_139;
                                phi_476_ = _e1608;
                                let _e1611 = local_140;
                                phi_478_ = _e1611;
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
                        if (_e703 != _e703) {
                            phi_1716_ = true;
                        } else {
                            let _e708 = local_63;
                            let _e709 = local_132;
                            phi_1716_ = (_e708 <= _e709);
                        }
                        let _e712 = phi_1716_;
                        let _e713 = local_63;
                        let _e714 = local_132;
                        local_133 = select(_e714, _e713, _e712);
                        let _e716 = local_33;
                        if ((bitcast<u32>(_e716) & 2139095040u) != 2139095040u) {
                            let _e720 = local_34;
                            let _e723 = ((bitcast<u32>(_e720) & 2139095040u) != 2139095040u);
                            local_64 = _e723;
                            if _e723 {
                                let _e724 = local_35;
                                phi_851_ = ((bitcast<u32>(_e724) & 2139095040u) != 2139095040u);
                            } else {
                                phi_851_ = bool();
                            }
                            let _e729 = phi_851_;
                            let _e730 = local_64;
                            phi_853_ = _e729;
                            phi_854_ = select(true, false, _e730);
                        } else {
                            phi_853_ = bool();
                            phi_854_ = true;
                        }
                        let _e733 = phi_853_;
                        let _e735 = phi_854_;
                        if select(_e733, false, _e735) {
                            let _e737 = local_59;
                            if (_e737 == 0u) {
                                phi_868_ = false;
                            } else {
                                let _e739 = local_59;
                                phi_868_ = (_e739 <= 2139095040u);
                            }
                            let _e742 = phi_868_;
                            if _e742 {
                                let _e743 = local_33;
                                let _e745 = local_34;
                                let _e748 = local_35;
                                let _e751 = local_57;
                                let _e754 = local_57;
                                let _e758 = local_57;
                                let _e765 = global_5.member.member_4;
                                if (((((0.2126f * _e743) + (0.7152f * _e745)) + (0.0722f * _e748)) - (((0.2126f * _e751[0]) + (0.7152f * _e754[1])) + (0.0722f * _e758[2]))) > _e765) {
                                    let _e769 = global_5.member.member_5;
                                    let _e770 = local_133;
                                    let _e771 = (_e770 > _e769);
                                    local_65 = _e771;
                                    if _e771 {
                                        let _e772 = local_36;
                                        let _e773 = local_57;
                                        let _e774 = local_133;
                                        let _e775 = local_58;
                                        phi_900_ = type_24(1u, type_23(_e772, _e773, _e774, _e775));
                                    } else {
                                        phi_900_ = type_24();
                                    }
                                    let _e779 = phi_900_;
                                    let _e780 = local_65;
                                    phi_902_ = _e779;
                                    phi_903_ = select(true, false, _e780);
                                } else {
                                    phi_902_ = type_24();
                                    phi_903_ = true;
                                }
                                let _e783 = phi_902_;
                                let _e785 = phi_903_;
                                phi_904_ = _e783;
                                phi_905_ = _e785;
                            } else {
                                phi_904_ = type_24();
                                phi_905_ = true;
                            }
                            let _e787 = phi_904_;
                            let _e789 = phi_905_;
                            phi_906_ = _e787;
                            phi_907_ = _e789;
                        } else {
                            phi_906_ = type_24();
                            phi_907_ = true;
                        }
                        let _e791 = phi_906_;
                        let _e793 = phi_907_;
                        if _e793 {
                            phi_912_ = type_24(0u, type_24().member_1);
                        } else {
                            phi_912_ = _e791;
                        }
                        let _e798 = phi_912_;
                        local_66 = _e798;
                        if (bitcast<i32>(_e798.member) != 0i) {
                            let _e802 = local_66;
                            local_67 = _e802.member_1.member;
                            let _e805 = local_66;
                            local_68 = _e805.member_1.member_1;
                            let _e808 = local_66;
                            local_69 = _e808.member_1.member_2;
                            let _e811 = local_66;
                            local_70 = _e811.member_1.member_3;
                            let _e814 = local_13;
                            let _e815 = local_3;
                            if (_e814 < _e815) {
                            } else {
                                phi_1935_ = true;
                                break;
                            }
                            let _e817 = local_13;
                            let _e820 = global_6.member[_e817];
                            local_71 = _e820;
                            let _e823 = global_5.member.member_2;
                            if (_e820 < _e823) {
                                let _e825 = local_28;
                                if _e825 {
                                    phi_1935_ = true;
                                    break;
                                }
                                let _e826 = local_29;
                                local_72 = (f32(_e826) + 0.5f);
                                let _e829 = local_28;
                                if _e829 {
                                    phi_1935_ = true;
                                    break;
                                }
                                let _e830 = local_31;
                                local_73 = (f32(_e830) + 0.5f);
                                let _e833 = local_69;
                                let _e834 = (_e833 + 0.5f);
                                local_74 = _e834;
                                let _e838 = global_5.member.member_8.member_2;
                                let _e839 = local_70;
                                local_134 = select(1f, -1f, (_e839 < _e838));
                                if (_e834 >= 5f) {
                                    let _e846 = global_5.member.member_9.member_6;
                                    if (_e846 > 0u) {
                                        let _e851 = global_5.member.member_9.member_5;
                                        let _e852 = local_69;
                                        let _e854 = local_69;
                                        phi_999_ = ((_e851 * _e852) * _e854);
                                    } else {
                                        let _e856 = local_69;
                                        let _e857 = (_e856 + -0.5f);
                                        let _e861 = global_5.member.member_9.member_5;
                                        phi_999_ = (_e861 * (((_e857 * _e857) + _e857) + 0.33333334f));
                                    }
                                    let _e867 = phi_999_;
                                    phi_1933_ = _e604;
                                    phi_1551_ = _e867;
                                } else {
                                    let _e868 = local_73;
                                    let _e869 = local_74;
                                    let _e873 = local_73;
                                    let _e874 = local_74;
                                    local_75 = floor(((_e873 + _e874) - 0.5f));
                                    let _e878 = local_72;
                                    let _e879 = local_74;
                                    let _e883 = local_72;
                                    let _e884 = local_74;
                                    local_76 = floor(((_e883 + _e884) - 0.5f));
                                    phi_1864_ = _e604;
                                    phi_1014_ = ceil(((_e868 - _e869) - 0.5f));
                                    phi_1017_ = 0f;
                                    loop {
                                        let _e889 = phi_1864_;
                                        let _e891 = phi_1014_;
                                        let _e893 = phi_1017_;
                                        local_77 = _e891;
                                        local_143 = _e893;
                                        let _e894 = local_77;
                                        let _e895 = local_75;
                                        let _e896 = (_e894 <= _e895);
                                        local_78 = _e896;
                                        if _e896 {
                                            let _e897 = local_77;
                                            let _e899 = local_73;
                                            local_79 = ((_e897 + 0.5f) - _e899);
                                            phi_1028_ = ceil(((_e878 - _e879) - 0.5f));
                                            phi_1031_ = _e893;
                                            loop {
                                                let _e902 = phi_1028_;
                                                let _e904 = phi_1031_;
                                                local_80 = _e902;
                                                local_142 = _e904;
                                                let _e905 = local_80;
                                                let _e906 = local_76;
                                                let _e907 = (_e905 <= _e906);
                                                local_81 = _e907;
                                                if _e907 {
                                                    let _e908 = local_80;
                                                    let _e910 = local_72;
                                                    let _e911 = ((_e908 + 0.5f) - _e910);
                                                    local_82 = _e911;
                                                    let _e913 = local_79;
                                                    let _e914 = local_79;
                                                    local_83 = ((_e911 * _e911) + (_e913 * _e914));
                                                    let _e920 = global_5.member.member_9.member;
                                                    local_84 = _e920;
                                                    let _e921 = (_e920 == 0u);
                                                    local_85 = _e921;
                                                    if _e921 {
                                                        let _e925 = global_5.member.member_9.member_6;
                                                        phi_1055_ = (_e925 == 0u);
                                                    } else {
                                                        phi_1055_ = false;
                                                    }
                                                    let _e928 = phi_1055_;
                                                    if _e928 {
                                                        let _e929 = local_69;
                                                        let _e930 = (_e929 + -0.5f);
                                                        let _e933 = local_83;
                                                        let _e936 = local_83;
                                                        let _e938 = local_74;
                                                        let _e939 = (_e938 - sqrt(_e936));
                                                        phi_1529_ = select(select(0f, select(1f, _e939, (_e939 < 1f)), (0f < _e939)), 1f, ((0f < _e930) && (_e933 <= (_e930 * _e930))));
                                                    } else {
                                                        let _e945 = local_85;
                                                        if _e945 {
                                                            let _e949 = global_5.member.member_9.member_6;
                                                            phi_1091_ = (_e949 == 0u);
                                                        } else {
                                                            phi_1091_ = false;
                                                        }
                                                        let _e952 = phi_1091_;
                                                        if _e952 {
                                                            let _e953 = local_69;
                                                            let _e954 = (_e953 + -0.5f);
                                                            let _e957 = local_83;
                                                            let _e960 = local_83;
                                                            let _e962 = local_74;
                                                            let _e963 = (_e962 - sqrt(_e960));
                                                            phi_1528_ = select(select(0f, select(1f, _e963, (_e963 < 1f)), (0f < _e963)), 1f, ((0f < _e954) && (_e957 <= (_e954 * _e954))));
                                                        } else {
                                                            let _e969 = local_134;
                                                            let _e970 = local_82;
                                                            local_86 = (_e969 * _e970);
                                                            let _e972 = local_134;
                                                            let _e973 = local_79;
                                                            local_87 = (_e972 * _e973);
                                                            let _e978 = global_5.member.member_9.member_6;
                                                            local_88 = _e978;
                                                            if (_e978 > 0u) {
                                                                let _e980 = local_69;
                                                                if (_e980 > 0f) {
                                                                    let _e982 = local_86;
                                                                    let _e983 = local_69;
                                                                    let _e985 = local_87;
                                                                    let _e986 = local_69;
                                                                    let _e988 = local_88;
                                                                    let _e989 = f32(_e988);
                                                                    local_89 = _e989;
                                                                    let _e993 = (((((_e982 / _e983) + 1f) * 0.5f) * _e989) - 0.5f);
                                                                    local_90 = _e993;
                                                                    local_91 = (((((_e985 / _e986) + 1f) * 0.5f) * _e989) - 0.5f);
                                                                    if (_e993 > -1f) {
                                                                        let _e999 = local_91;
                                                                        if (_e999 > -1f) {
                                                                            let _e1001 = local_90;
                                                                            let _e1002 = local_89;
                                                                            if (_e1001 < _e1002) {
                                                                                let _e1004 = local_91;
                                                                                let _e1005 = local_89;
                                                                                let _e1006 = (_e1004 < _e1005);
                                                                                local_92 = _e1006;
                                                                                if _e1006 {
                                                                                    let _e1007 = local_90;
                                                                                    let _e1008 = floor(_e1007);
                                                                                    local_93 = _e1008;
                                                                                    let _e1009 = local_91;
                                                                                    let _e1010 = floor(_e1009);
                                                                                    local_94 = _e1010;
                                                                                    let _e1011 = local_90;
                                                                                    local_95 = (_e1011 - _e1008);
                                                                                    let _e1013 = local_91;
                                                                                    local_96 = (_e1013 - _e1010);
                                                                                    let _e1015 = (_e1008 < 0f);
                                                                                    local_97 = _e1015;
                                                                                    if _e1015 {
                                                                                        phi_1220_ = f32();
                                                                                        phi_1221_ = true;
                                                                                    } else {
                                                                                        let _e1016 = local_94;
                                                                                        if (_e1016 < 0f) {
                                                                                            phi_1218_ = f32();
                                                                                            phi_1219_ = true;
                                                                                        } else {
                                                                                            let _e1018 = local_93;
                                                                                            let _e1019 = local_89;
                                                                                            if (_e1018 >= _e1019) {
                                                                                                phi_1216_ = f32();
                                                                                                phi_1217_ = true;
                                                                                            } else {
                                                                                                let _e1021 = local_94;
                                                                                                let _e1022 = local_89;
                                                                                                let _e1023 = (_e1021 >= _e1022);
                                                                                                if _e1023 {
                                                                                                    phi_1215_ = f32();
                                                                                                } else {
                                                                                                    let _e1024 = local_94;
                                                                                                    let _e1026 = local_94;
                                                                                                    let _e1028 = local_94;
                                                                                                    let _e1032 = local_88;
                                                                                                    let _e1034 = local_93;
                                                                                                    let _e1036 = local_93;
                                                                                                    let _e1038 = local_93;
                                                                                                    let _e1042 = ((select(select(u32(_e1024), 0u, (_e1026 < 0f)), 4294967295u, (_e1028 > 4294967000f)) * _e1032) + select(select(u32(_e1034), 0u, (_e1036 < 0f)), 4294967295u, (_e1038 > 4294967000f)));
                                                                                                    local_98 = _e1042;
                                                                                                    let _e1043 = local_6;
                                                                                                    if (_e1042 < _e1043) {
                                                                                                    } else {
                                                                                                        phi_1853_ = true;
                                                                                                        break;
                                                                                                    }
                                                                                                    let _e1045 = local_98;
                                                                                                    let _e1048 = global_9.member[_e1045];
                                                                                                    phi_1215_ = bitcast<f32>(_e1048);
                                                                                                }
                                                                                                let _e1051 = phi_1215_;
                                                                                                phi_1216_ = _e1051;
                                                                                                phi_1217_ = _e1023;
                                                                                            }
                                                                                            let _e1053 = phi_1216_;
                                                                                            let _e1055 = phi_1217_;
                                                                                            phi_1218_ = _e1053;
                                                                                            phi_1219_ = _e1055;
                                                                                        }
                                                                                        let _e1057 = phi_1218_;
                                                                                        let _e1059 = phi_1219_;
                                                                                        phi_1220_ = _e1057;
                                                                                        phi_1221_ = _e1059;
                                                                                    }
                                                                                    let _e1061 = phi_1220_;
                                                                                    let _e1063 = phi_1221_;
                                                                                    let _e1065 = local_95;
                                                                                    let _e1066 = (1f - _e1065);
                                                                                    local_99 = _e1066;
                                                                                    local_100 = (select(_e1061, 0f, _e1063) * _e1066);
                                                                                    let _e1068 = local_93;
                                                                                    let _e1069 = (_e1068 + 1f);
                                                                                    local_101 = _e1069;
                                                                                    let _e1070 = (_e1069 < 0f);
                                                                                    local_102 = _e1070;
                                                                                    if _e1070 {
                                                                                        phi_1284_ = f32();
                                                                                        phi_1285_ = true;
                                                                                    } else {
                                                                                        let _e1071 = local_94;
                                                                                        if (_e1071 < 0f) {
                                                                                            phi_1282_ = f32();
                                                                                            phi_1283_ = true;
                                                                                        } else {
                                                                                            let _e1073 = local_101;
                                                                                            let _e1074 = local_89;
                                                                                            if (_e1073 >= _e1074) {
                                                                                                phi_1280_ = f32();
                                                                                                phi_1281_ = true;
                                                                                            } else {
                                                                                                let _e1076 = local_94;
                                                                                                let _e1077 = local_89;
                                                                                                let _e1078 = (_e1076 >= _e1077);
                                                                                                if _e1078 {
                                                                                                    phi_1279_ = f32();
                                                                                                } else {
                                                                                                    let _e1079 = local_94;
                                                                                                    let _e1081 = local_94;
                                                                                                    let _e1083 = local_94;
                                                                                                    let _e1087 = local_88;
                                                                                                    let _e1089 = local_101;
                                                                                                    let _e1091 = local_101;
                                                                                                    let _e1093 = local_101;
                                                                                                    let _e1097 = ((select(select(u32(_e1079), 0u, (_e1081 < 0f)), 4294967295u, (_e1083 > 4294967000f)) * _e1087) + select(select(u32(_e1089), 0u, (_e1091 < 0f)), 4294967295u, (_e1093 > 4294967000f)));
                                                                                                    local_103 = _e1097;
                                                                                                    let _e1098 = local_6;
                                                                                                    if (_e1097 < _e1098) {
                                                                                                    } else {
                                                                                                        phi_1853_ = true;
                                                                                                        break;
                                                                                                    }
                                                                                                    let _e1100 = local_103;
                                                                                                    let _e1103 = global_9.member[_e1100];
                                                                                                    phi_1279_ = bitcast<f32>(_e1103);
                                                                                                }
                                                                                                let _e1106 = phi_1279_;
                                                                                                phi_1280_ = _e1106;
                                                                                                phi_1281_ = _e1078;
                                                                                            }
                                                                                            let _e1108 = phi_1280_;
                                                                                            let _e1110 = phi_1281_;
                                                                                            phi_1282_ = _e1108;
                                                                                            phi_1283_ = _e1110;
                                                                                        }
                                                                                        let _e1112 = phi_1282_;
                                                                                        let _e1114 = phi_1283_;
                                                                                        phi_1284_ = _e1112;
                                                                                        phi_1285_ = _e1114;
                                                                                    }
                                                                                    let _e1116 = phi_1284_;
                                                                                    let _e1118 = phi_1285_;
                                                                                    let _e1120 = local_95;
                                                                                    let _e1122 = local_100;
                                                                                    local_104 = (_e1122 + (select(_e1116, 0f, _e1118) * _e1120));
                                                                                    let _e1124 = local_94;
                                                                                    local_105 = (_e1124 + 1f);
                                                                                    let _e1126 = local_97;
                                                                                    if _e1126 {
                                                                                        phi_1348_ = f32();
                                                                                        phi_1349_ = true;
                                                                                    } else {
                                                                                        let _e1127 = local_105;
                                                                                        if (_e1127 < 0f) {
                                                                                            phi_1346_ = f32();
                                                                                            phi_1347_ = true;
                                                                                        } else {
                                                                                            let _e1129 = local_93;
                                                                                            let _e1130 = local_89;
                                                                                            if (_e1129 >= _e1130) {
                                                                                                phi_1344_ = f32();
                                                                                                phi_1345_ = true;
                                                                                            } else {
                                                                                                let _e1132 = local_105;
                                                                                                let _e1133 = local_89;
                                                                                                let _e1134 = (_e1132 >= _e1133);
                                                                                                if _e1134 {
                                                                                                    phi_1343_ = f32();
                                                                                                } else {
                                                                                                    let _e1135 = local_105;
                                                                                                    let _e1137 = local_105;
                                                                                                    let _e1139 = local_105;
                                                                                                    let _e1143 = local_88;
                                                                                                    let _e1145 = local_93;
                                                                                                    let _e1147 = local_93;
                                                                                                    let _e1149 = local_93;
                                                                                                    let _e1153 = ((select(select(u32(_e1135), 0u, (_e1137 < 0f)), 4294967295u, (_e1139 > 4294967000f)) * _e1143) + select(select(u32(_e1145), 0u, (_e1147 < 0f)), 4294967295u, (_e1149 > 4294967000f)));
                                                                                                    local_106 = _e1153;
                                                                                                    let _e1154 = local_6;
                                                                                                    if (_e1153 < _e1154) {
                                                                                                    } else {
                                                                                                        phi_1853_ = true;
                                                                                                        break;
                                                                                                    }
                                                                                                    let _e1156 = local_106;
                                                                                                    let _e1159 = global_9.member[_e1156];
                                                                                                    phi_1343_ = bitcast<f32>(_e1159);
                                                                                                }
                                                                                                let _e1162 = phi_1343_;
                                                                                                phi_1344_ = _e1162;
                                                                                                phi_1345_ = _e1134;
                                                                                            }
                                                                                            let _e1164 = phi_1344_;
                                                                                            let _e1166 = phi_1345_;
                                                                                            phi_1346_ = _e1164;
                                                                                            phi_1347_ = _e1166;
                                                                                        }
                                                                                        let _e1168 = phi_1346_;
                                                                                        let _e1170 = phi_1347_;
                                                                                        phi_1348_ = _e1168;
                                                                                        phi_1349_ = _e1170;
                                                                                    }
                                                                                    let _e1172 = phi_1348_;
                                                                                    let _e1174 = phi_1349_;
                                                                                    let _e1176 = local_99;
                                                                                    local_107 = (select(_e1172, 0f, _e1174) * _e1176);
                                                                                    let _e1178 = local_102;
                                                                                    if _e1178 {
                                                                                        phi_1413_ = f32();
                                                                                        phi_1414_ = true;
                                                                                    } else {
                                                                                        let _e1179 = local_105;
                                                                                        if (_e1179 < 0f) {
                                                                                            phi_1411_ = f32();
                                                                                            phi_1412_ = true;
                                                                                        } else {
                                                                                            let _e1181 = local_101;
                                                                                            let _e1182 = local_89;
                                                                                            if (_e1181 >= _e1182) {
                                                                                                phi_1409_ = f32();
                                                                                                phi_1410_ = true;
                                                                                            } else {
                                                                                                let _e1184 = local_105;
                                                                                                let _e1185 = local_89;
                                                                                                let _e1186 = (_e1184 >= _e1185);
                                                                                                if _e1186 {
                                                                                                    phi_1408_ = f32();
                                                                                                } else {
                                                                                                    let _e1187 = local_105;
                                                                                                    let _e1189 = local_105;
                                                                                                    let _e1191 = local_105;
                                                                                                    let _e1195 = local_88;
                                                                                                    let _e1197 = local_101;
                                                                                                    let _e1199 = local_101;
                                                                                                    let _e1201 = local_101;
                                                                                                    let _e1205 = ((select(select(u32(_e1187), 0u, (_e1189 < 0f)), 4294967295u, (_e1191 > 4294967000f)) * _e1195) + select(select(u32(_e1197), 0u, (_e1199 < 0f)), 4294967295u, (_e1201 > 4294967000f)));
                                                                                                    local_108 = _e1205;
                                                                                                    let _e1206 = local_6;
                                                                                                    if (_e1205 < _e1206) {
                                                                                                    } else {
                                                                                                        phi_1853_ = true;
                                                                                                        break;
                                                                                                    }
                                                                                                    let _e1208 = local_108;
                                                                                                    let _e1211 = global_9.member[_e1208];
                                                                                                    phi_1408_ = bitcast<f32>(_e1211);
                                                                                                }
                                                                                                let _e1214 = phi_1408_;
                                                                                                phi_1409_ = _e1214;
                                                                                                phi_1410_ = _e1186;
                                                                                            }
                                                                                            let _e1216 = phi_1409_;
                                                                                            let _e1218 = phi_1410_;
                                                                                            phi_1411_ = _e1216;
                                                                                            phi_1412_ = _e1218;
                                                                                        }
                                                                                        let _e1220 = phi_1411_;
                                                                                        let _e1222 = phi_1412_;
                                                                                        phi_1413_ = _e1220;
                                                                                        phi_1414_ = _e1222;
                                                                                    }
                                                                                    let _e1224 = phi_1413_;
                                                                                    let _e1226 = phi_1414_;
                                                                                    let _e1228 = local_95;
                                                                                    let _e1230 = local_107;
                                                                                    let _e1232 = local_96;
                                                                                    let _e1234 = local_104;
                                                                                    let _e1236 = local_96;
                                                                                    phi_1425_ = ((_e1234 * (1f - _e1232)) + ((_e1230 + (select(_e1224, 0f, _e1226) * _e1228)) * _e1236));
                                                                                } else {
                                                                                    phi_1425_ = f32();
                                                                                }
                                                                                let _e1240 = phi_1425_;
                                                                                let _e1241 = local_92;
                                                                                phi_1427_ = _e1240;
                                                                                phi_1428_ = select(true, false, _e1241);
                                                                            } else {
                                                                                phi_1427_ = f32();
                                                                                phi_1428_ = true;
                                                                            }
                                                                            let _e1244 = phi_1427_;
                                                                            let _e1246 = phi_1428_;
                                                                            phi_1429_ = _e1244;
                                                                            phi_1430_ = _e1246;
                                                                        } else {
                                                                            phi_1429_ = f32();
                                                                            phi_1430_ = true;
                                                                        }
                                                                        let _e1248 = phi_1429_;
                                                                        let _e1250 = phi_1430_;
                                                                        phi_1431_ = _e1248;
                                                                        phi_1432_ = _e1250;
                                                                    } else {
                                                                        phi_1431_ = f32();
                                                                        phi_1432_ = true;
                                                                    }
                                                                    let _e1252 = phi_1431_;
                                                                    let _e1254 = phi_1432_;
                                                                    phi_1437_ = select(_e1252, 0f, _e1254);
                                                                } else {
                                                                    phi_1437_ = 0f;
                                                                }
                                                                let _e1257 = phi_1437_;
                                                                phi_1527_ = _e1257;
                                                            } else {
                                                                let _e1258 = local_86;
                                                                let _e1259 = local_86;
                                                                let _e1261 = local_87;
                                                                let _e1262 = local_87;
                                                                let _e1265 = sqrt(((_e1258 * _e1259) + (_e1261 * _e1262)));
                                                                local_109 = _e1265;
                                                                let _e1266 = local_85;
                                                                if _e1266 {
                                                                    phi_1514_ = _e1265;
                                                                } else {
                                                                    let _e1270 = global_5.member.member_9.member_2;
                                                                    let _e1272 = local_86;
                                                                    let _e1275 = local_87;
                                                                    phi_1456_ = 1u;
                                                                    phi_1459_ = ((_e1272 * _e1270[0]) + (_e1275 * _e1270[1]));
                                                                    phi_1461_ = _e1270;
                                                                    loop {
                                                                        let _e1279 = phi_1456_;
                                                                        let _e1281 = phi_1459_;
                                                                        let _e1283 = phi_1461_;
                                                                        local_110 = _e1279;
                                                                        local_111 = _e1281;
                                                                        local_112 = _e1283;
                                                                        let _e1284 = local_110;
                                                                        let _e1285 = local_84;
                                                                        let _e1286 = (_e1284 < _e1285);
                                                                        local_113 = _e1286;
                                                                        if _e1286 {
                                                                            let _e1287 = local_112;
                                                                            let _e1293 = global_5.member.member_9.member_3[0u];
                                                                            let _e1295 = local_112;
                                                                            let _e1301 = global_5.member.member_9.member_3[1u];
                                                                            let _e1303 = ((_e1287[0] * _e1293) - (_e1295[1] * _e1301));
                                                                            let _e1306 = ((_e1287[0] * _e1301) + (_e1295[1] * _e1293));
                                                                            let _e1308 = local_86;
                                                                            let _e1310 = local_87;
                                                                            let _e1312 = ((_e1308 * _e1303) + (_e1310 * _e1306));
                                                                            let _e1313 = local_111;
                                                                            let _e1315 = local_111;
                                                                            let _e1317 = local_110;
                                                                            phi_1457_ = (_e1317 + 1u);
                                                                            phi_1460_ = select(_e1315, _e1312, (_e1312 > _e1313));
                                                                            phi_1462_ = array<f32, 2>(_e1303, _e1306);
                                                                        } else {
                                                                            phi_1457_ = u32();
                                                                            phi_1460_ = f32();
                                                                            phi_1462_ = array<f32, 2>();
                                                                        }
                                                                        let _e1320 = phi_1457_;
                                                                        let _e1322 = phi_1460_;
                                                                        let _e1324 = phi_1462_;
                                                                        continue;
                                                                        continuing {
                                                                            let _e1325 = local_113;
                                                                            phi_1456_ = _e1320;
                                                                            phi_1459_ = _e1322;
                                                                            phi_1461_ = _e1324;
                                                                            break if !(_e1325);
                                                                        }
                                                                    }
                                                                    let _e1330 = global_5.member.member_9.member_1;
                                                                    let _e1332 = local_111;
                                                                    let _e1337 = global_5.member.member_9.member_4;
                                                                    let _e1339 = local_109;
                                                                    phi_1514_ = ((((1f - _e1330) * _e1332) * _e1337) + (_e1330 * _e1339));
                                                                }
                                                                let _e1343 = phi_1514_;
                                                                let _e1344 = local_74;
                                                                let _e1345 = (_e1344 - _e1343);
                                                                phi_1527_ = select(0f, select(1f, _e1345, (_e1345 < 1f)), (0f < _e1345));
                                                            }
                                                            let _e1351 = phi_1527_;
                                                            phi_1528_ = _e1351;
                                                        }
                                                        let _e1353 = phi_1528_;
                                                        phi_1529_ = _e1353;
                                                    }
                                                    let _e1355 = phi_1529_;
                                                    let _e1356 = local_81;
                                                    local_135 = select(0f, _e1355, _e1356);
                                                    phi_1535_ = 0u;
                                                    phi_1538_ = _e904;
                                                    loop {
                                                        let _e1359 = phi_1535_;
                                                        let _e1361 = phi_1538_;
                                                        local_114 = _e1359;
                                                        local_115 = _e1361;
                                                        local_141 = _e1361;
                                                        let _e1362 = local_114;
                                                        let _e1363 = (_e1362 < 1u);
                                                        local_116 = _e1363;
                                                        if _e1363 {
                                                            let _e1364 = local_115;
                                                            let _e1365 = local_135;
                                                            let _e1367 = local_114;
                                                            phi_1536_ = (_e1367 + 1u);
                                                            phi_1539_ = (_e1364 + _e1365);
                                                        } else {
                                                            phi_1536_ = u32();
                                                            phi_1539_ = f32();
                                                        }
                                                        let _e1370 = phi_1536_;
                                                        let _e1372 = phi_1539_;
                                                        continue;
                                                        continuing {
                                                            let _e1373 = local_116;
                                                            phi_1535_ = _e1370;
                                                            phi_1538_ = _e1372;
                                                            break if !(_e1373);
                                                        }
                                                    }
                                                    let _e1375 = local_80;
                                                    phi_1029_ = (_e1375 + 1f);
                                                    let _e1693 = local_141;
                                                    phi_1032_ = _e1693;
                                                } else {
                                                    phi_1029_ = f32();
                                                    phi_1032_ = f32();
                                                }
                                                let _e1378 = phi_1029_;
                                                let _e1380 = phi_1032_;
                                                continue;
                                                continuing {
                                                    let _e1381 = local_81;
                                                    phi_1028_ = _e1378;
                                                    phi_1031_ = _e1380;
                                                    phi_1853_ = _e889;
                                                    break if !(_e1381);
                                                }
                                            }
                                            let _e1384 = phi_1853_;
                                            phi_1922_ = _e1384;
                                            if _e1384 {
                                                break;
                                            }
                                            let _e1385 = local_77;
                                            phi_1923_ = _e1384;
                                            phi_1015_ = (_e1385 + 1f);
                                            let _e1699 = local_142;
                                            phi_1018_ = _e1699;
                                        } else {
                                            phi_1923_ = _e889;
                                            phi_1015_ = f32();
                                            phi_1018_ = f32();
                                        }
                                        let _e1388 = phi_1923_;
                                        let _e1390 = phi_1015_;
                                        let _e1392 = phi_1018_;
                                        continue;
                                        continuing {
                                            let _e1393 = local_78;
                                            phi_1864_ = _e1388;
                                            phi_1014_ = _e1390;
                                            phi_1017_ = _e1392;
                                            phi_1922_ = _e1388;
                                            break if !(_e1393);
                                        }
                                    }
                                    let _e1396 = phi_1922_;
                                    phi_1935_ = _e1396;
                                    if _e1396 {
                                        break;
                                    }
                                    phi_1933_ = _e1396;
                                    let _e1704 = local_143;
                                    phi_1551_ = _e1704;
                                }
                                let _e1398 = phi_1933_;
                                let _e1400 = phi_1551_;
                                local_117 = (1f / _e1400);
                                let _e1402 = local_67;
                                local_118 = _e1402[0];
                                let _e1404 = local_68;
                                local_119 = _e1404[0];
                                if (_e1402[0] != _e1402[0]) {
                                    phi_1734_ = true;
                                } else {
                                    let _e1407 = local_119;
                                    let _e1408 = local_118;
                                    phi_1734_ = (_e1407 <= _e1408);
                                }
                                let _e1411 = phi_1734_;
                                let _e1412 = local_119;
                                let _e1413 = local_118;
                                local_136 = select(_e1413, _e1412, _e1411);
                                let _e1415 = local_67;
                                local_120 = _e1415[1];
                                let _e1417 = local_68;
                                local_121 = _e1417[1];
                                if (_e1415[1] != _e1415[1]) {
                                    phi_1749_ = true;
                                } else {
                                    let _e1420 = local_121;
                                    let _e1421 = local_120;
                                    phi_1749_ = (_e1420 <= _e1421);
                                }
                                let _e1424 = phi_1749_;
                                let _e1425 = local_121;
                                let _e1426 = local_120;
                                local_137 = select(_e1426, _e1425, _e1424);
                                let _e1428 = local_67;
                                local_122 = _e1428[2];
                                let _e1430 = local_68;
                                local_123 = _e1430[2];
                                if (_e1428[2] != _e1428[2]) {
                                    phi_1764_ = true;
                                } else {
                                    let _e1433 = local_123;
                                    let _e1434 = local_122;
                                    phi_1764_ = (_e1433 <= _e1434);
                                }
                                let _e1437 = phi_1764_;
                                let _e1438 = local_123;
                                let _e1439 = local_122;
                                let _e1440 = select(_e1439, _e1438, _e1437);
                                let _e1441 = local_136;
                                let _e1442 = local_137;
                                let _e1444 = local_118;
                                let _e1445 = local_136;
                                let _e1447 = local_117;
                                let _e1449 = local_120;
                                let _e1450 = local_137;
                                let _e1452 = local_117;
                                let _e1454 = local_122;
                                let _e1456 = local_117;
                                let _e1459 = local_72;
                                local_138[0u] = _e1459;
                                let _e1461 = local_73;
                                local_138[1u] = _e1461;
                                let _e1463 = local_74;
                                local_138[2u] = _e1463;
                                let _e1465 = local_134;
                                local_138[3u] = _e1465;
                                local_138[4u] = ((_e1444 - _e1445) * _e1447);
                                local_138[5u] = ((_e1449 - _e1450) * _e1452);
                                local_138[6u] = ((_e1454 - _e1440) * _e1456);
                                local_138[7u] = 0f;
                                phi_1581_ = 0u;
                                loop {
                                    let _e1471 = phi_1581_;
                                    local_124 = _e1471;
                                    let _e1472 = local_124;
                                    let _e1473 = (_e1472 < 8u);
                                    local_125 = _e1473;
                                    if _e1473 {
                                        let _e1474 = local_71;
                                        let _e1476 = local_124;
                                        local_126 = ((_e1474 * 8u) + _e1476);
                                        let _e1478 = local_125;
                                        if _e1478 {
                                        } else {
                                            phi_1924_ = true;
                                            break;
                                        }
                                        let _e1479 = local_124;
                                        let _e1481 = local_138[_e1479];
                                        local_127 = bitcast<u32>(_e1481);
                                        let _e1483 = local_126;
                                        let _e1484 = local_4;
                                        if (_e1483 < _e1484) {
                                        } else {
                                            phi_1924_ = true;
                                            break;
                                        }
                                        let _e1486 = local_126;
                                        let _e1489 = local_127;
                                        global_7.member[_e1486] = _e1489;
                                        let _e1490 = local_124;
                                        phi_1582_ = (_e1490 + 1u);
                                    } else {
                                        phi_1582_ = u32();
                                    }
                                    let _e1493 = phi_1582_;
                                    continue;
                                    continuing {
                                        let _e1494 = local_125;
                                        phi_1581_ = _e1493;
                                        phi_1924_ = _e1398;
                                        break if !(_e1494);
                                    }
                                }
                                let _e1497 = phi_1924_;
                                phi_1935_ = _e1497;
                                if _e1497 {
                                    break;
                                }
                                phi_1939_ = _e1497;
                                phi_1615_ = array<f32, 3>(_e1441, _e1442, _e1440);
                            } else {
                                phi_1939_ = _e604;
                                phi_1615_ = _e320;
                            }
                            let _e1499 = phi_1939_;
                            let _e1501 = phi_1615_;
                            phi_1938_ = _e1499;
                            phi_1616_ = _e1501;
                        } else {
                            phi_1938_ = _e604;
                            phi_1616_ = _e320;
                        }
                        let _e1503 = phi_1938_;
                        let _e1505 = phi_1616_;
                        local_128 = _e1505;
                        local_129 = bitcast<u32>(_e1505[0]);
                        let _e1508 = local_14;
                        let _e1509 = local_5;
                        if (_e1508 < _e1509) {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e1511 = local_14;
                        let _e1514 = local_129;
                        global_8.member[_e1511] = _e1514;
                        let _e1515 = local_128;
                        local_130 = bitcast<u32>(_e1515[1]);
                        let _e1518 = local_17;
                        let _e1519 = local_5;
                        if (_e1518 < _e1519) {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e1521 = local_17;
                        let _e1524 = local_130;
                        global_8.member[_e1521] = _e1524;
                        let _e1525 = local_128;
                        local_131 = bitcast<u32>(_e1525[2]);
                        let _e1528 = local_20;
                        let _e1529 = local_5;
                        if (_e1528 < _e1529) {
                        } else {
                            phi_1935_ = true;
                            break;
                        }
                        let _e1531 = local_20;
                        let _e1534 = local_131;
                        global_8.member[_e1531] = _e1534;
                        phi_1937_ = _e1503;
                    } else {
                        phi_1937_ = _e226;
                    }
                    let _e1536 = phi_1937_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e1537 = local_11;
                    let _e1538 = local_10;
                    phi_1936_ = _e1536;
                    phi_159_ = (_e1537 + _e1538);
                } else {
                    phi_1936_ = _e226;
                    phi_159_ = u32();
                }
                let _e1541 = phi_1936_;
                let _e1543 = phi_159_;
                continue;
                continuing {
                    let _e1544 = local_12;
                    phi_1850_ = _e1541;
                    phi_158_ = _e1543;
                    phi_1935_ = _e1541;
                    break if !(_e1544);
                }
            }
            let _e1547 = phi_1935_;
            if _e1547 {
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
