struct type_5 {
    member: array<u32>,
}

struct type_12 {
    member: u32,
    member_1: u32,
    member_2: u32,
}

struct type_13 {
    member: type_12,
}

struct type_17 {
    member: u32,
    member_1: u32,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<workgroup> global_3: array<u32, 512>;
var<immediate> global_4: type_13;
@group(0) @binding(0) 
var<storage, read_write> global_5: type_5;
@group(0) @binding(1) 
var<storage, read_write> global_6: type_5;
var<private> global_7: u32;
var<private> global_8: u32;
var<private> global_9: u32;
var<private> global_10: u32;

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
    var local_15: u32;
    var local_16: u32;
    var local_17: bool;
    var local_18: u32;
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
    var local_29: bool;
    var local_30: u32;
    var local_31: u32;
    var local_32: bool;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: bool;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: bool;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: bool;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: u32;
    var local_57: u32;
    var local_58: u32;
    var local_59: u32;
    var local_60: u32;
    var local_61: bool;
    var local_62: u32;
    var local_63: bool;
    var local_64: u32;
    var local_65: u32;
    var local_66: u32;
    var phi_94_: u32;
    var phi_474_: bool;
    var phi_96_: u32;
    var phi_115_: u32;
    var phi_118_: u32;
    var phi_141_: u32;
    var phi_116_: u32;
    var phi_119_: u32;
    var phi_471_: bool;
    var phi_165_: type_17;
    var phi_167_: type_17;
    var phi_168_: bool;
    var phi_169_: type_17;
    var phi_170_: bool;
    var phi_175_: type_17;
    var phi_325_: u32;
    var phi_328_: u32;
    var phi_364_: u32;
    var phi_326_: u32;
    var phi_329_: u32;
    var phi_477_: bool;
    var phi_212_: u32;
    var phi_215_: u32;
    var phi_216_: u32;
    var phi_218_: u32;
    var phi_246_: u32;
    var phi_213_: u32;
    var phi_217_: u32;
    var phi_219_: u32;
    var phi_487_: bool;
    var phi_268_: u32;
    var phi_271_: u32;
    var phi_273_: u32;
    var phi_288_: u32;
    var phi_269_: u32;
    var phi_272_: u32;
    var phi_274_: u32;
    var phi_492_: bool;
    var phi_502_: bool;
    var phi_379_: u32;
    var phi_401_: u32;
    var phi_403_: u32;
    var phi_406_: u32;
    var phi_435_: u32;
    var phi_404_: u32;
    var phi_407_: u32;
    var phi_498_: bool;
    var phi_505_: bool;
    var phi_97_: u32;
    var phi_504_: bool;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e96 = global;
            local = _e96;
            let _e97 = global_1;
            let _e98 = global_2;
            let _e99 = global_7;
            local_1 = _e99;
            let _e100 = global_8;
            local_2 = _e100;
            let _e101 = global_9;
            local_3 = _e101;
            let _e102 = global_10;
            local_4 = _e102;
            local_5 = arrayLength((&global_5.member));
            local_6 = arrayLength((&global_6.member));
            local_7 = _e98.x;
            let _e111 = global_4.member.member;
            local_8 = _e111;
            let _e112 = (_e111 / 1024u);
            local_9 = _e112;
            if ((_e111 % 1024u) > 0u) {
                let _e115 = local_9;
                phi_94_ = (_e115 + 1u);
            } else {
                phi_94_ = _e112;
            }
            let _e118 = phi_94_;
            local_10 = _e118;
            phi_474_ = false;
            phi_96_ = _e97.x;
            loop {
                let _e120 = phi_474_;
                let _e122 = phi_96_;
                local_11 = _e122;
                let _e123 = local_11;
                let _e124 = local_10;
                let _e125 = (_e123 < _e124);
                local_12 = _e125;
                if _e125 {
                    let _e128 = global_4.member.member_1;
                    let _e129 = local_11;
                    local_13 = (_e128 + (_e129 * 1024u));
                    let _e132 = local_8;
                    local_14 = (_e128 + _e132);
                    phi_115_ = 0u;
                    phi_118_ = 0u;
                    loop {
                        let _e135 = phi_115_;
                        let _e137 = phi_118_;
                        local_15 = _e135;
                        local_16 = _e137;
                        let _e138 = local_15;
                        let _e139 = (_e138 < 4u);
                        local_17 = _e139;
                        if _e139 {
                            let _e140 = local;
                            let _e142 = local_13;
                            let _e144 = local_15;
                            let _e145 = ((_e142 + (_e140 * 4u)) + _e144);
                            local_18 = _e145;
                            let _e146 = local_14;
                            if (_e145 < _e146) {
                                let _e148 = local_18;
                                let _e149 = local_5;
                                if (_e148 < _e149) {
                                } else {
                                    phi_471_ = true;
                                    break;
                                }
                                let _e151 = local_18;
                                let _e154 = global_5.member[_e151];
                                let _e155 = local_16;
                                phi_141_ = (_e155 + _e154);
                            } else {
                                phi_141_ = _e137;
                            }
                            let _e158 = phi_141_;
                            let _e159 = local_15;
                            phi_116_ = (_e159 + 1u);
                            phi_119_ = _e158;
                        } else {
                            phi_116_ = u32();
                            phi_119_ = u32();
                        }
                        let _e162 = phi_116_;
                        let _e164 = phi_119_;
                        continue;
                        continuing {
                            let _e165 = local_17;
                            phi_115_ = _e162;
                            phi_118_ = _e164;
                            phi_471_ = _e120;
                            break if !(_e165);
                        }
                    }
                    let _e168 = phi_471_;
                    phi_504_ = _e168;
                    if _e168 {
                        break;
                    }
                    let _e169 = local;
                    if (_e169 < 512u) {
                    } else {
                        phi_504_ = true;
                        break;
                    }
                    let _e171 = local;
                    let _e173 = local_16;
                    global_3[_e171] = _e173;
                    storageBarrier();
                    workgroupBarrier();
                    let _e174 = local_1;
                    if (_e174 >= 2u) {
                        let _e176 = local_1;
                        let _e178 = local_1;
                        if ((_e178 & (_e176 - 1u)) == 0u) {
                            let _e181 = local_2;
                            let _e182 = local_1;
                            let _e184 = ((_e181 * _e182) == 256u);
                            local_19 = _e184;
                            if _e184 {
                                let _e185 = local_1;
                                phi_165_ = type_17(1u, _e185);
                            } else {
                                phi_165_ = type_17();
                            }
                            let _e188 = phi_165_;
                            let _e189 = local_19;
                            phi_167_ = _e188;
                            phi_168_ = select(true, false, _e189);
                        } else {
                            phi_167_ = type_17();
                            phi_168_ = true;
                        }
                        let _e192 = phi_167_;
                        let _e194 = phi_168_;
                        phi_169_ = _e192;
                        phi_170_ = _e194;
                    } else {
                        phi_169_ = type_17();
                        phi_170_ = true;
                    }
                    let _e196 = phi_169_;
                    let _e198 = phi_170_;
                    if _e198 {
                        phi_175_ = type_17(0u, type_17().member_1);
                    } else {
                        phi_175_ = _e196;
                    }
                    let _e203 = phi_175_;
                    local_20 = _e203.member_1;
                    if (bitcast<i32>(_e203.member) != 0i) {
                        let _e257 = local_20;
                        let _e259 = local_20;
                        local_21 = select(firstTrailingBit(_e257), 32u, (_e259 == 0u));
                        let _e262 = local_3;
                        let _e263 = local_1;
                        let _e265 = local_4;
                        let _e266 = ((_e262 * _e263) + _e265);
                        local_22 = _e266;
                        if (_e266 < 512u) {
                        } else {
                            phi_504_ = true;
                            break;
                        }
                        let _e268 = local_22;
                        let _e270 = global_3[_e268];
                        let _e271 = subgroupInclusiveAdd(_e270);
                        local_23 = _e271;
                        let _e272 = local_22;
                        let _e273 = (256u + _e272);
                        local_24 = _e273;
                        if (_e273 < 512u) {
                        } else {
                            phi_504_ = true;
                            break;
                        }
                        let _e275 = local_24;
                        let _e277 = local_23;
                        global_3[_e275] = _e277;
                        storageBarrier();
                        workgroupBarrier();
                        phi_212_ = 0u;
                        phi_215_ = 256u;
                        phi_216_ = 256u;
                        phi_218_ = 0u;
                        loop {
                            let _e279 = phi_212_;
                            let _e281 = phi_215_;
                            let _e283 = phi_216_;
                            let _e285 = phi_218_;
                            local_25 = _e279;
                            local_26 = _e281;
                            local_27 = _e283;
                            local_28 = _e285;
                            local_67 = _e281;
                            local_68 = _e283;
                            local_69 = _e285;
                            let _e286 = local_27;
                            let _e287 = local_20;
                            let _e288 = (_e286 > _e287);
                            local_29 = _e288;
                            if _e288 {
                                let _e289 = local_21;
                                let _e290 = (_e289 & 31u);
                                local_30 = _e290;
                                let _e291 = local_27;
                                let _e293 = (_e291 >> bitcast<u32>(_e290));
                                local_31 = _e293;
                                let _e294 = local_22;
                                let _e295 = (_e294 < _e293);
                                local_32 = _e295;
                                if _e295 {
                                    let _e296 = local_22;
                                    let _e298 = local_30;
                                    let _e301 = local_26;
                                    let _e303 = ((_e301 + ((_e296 + 1u) << bitcast<u32>(_e298))) - 1u);
                                    local_33 = _e303;
                                    if (_e303 < 512u) {
                                    } else {
                                        phi_487_ = true;
                                        break;
                                    }
                                    let _e305 = local_33;
                                    let _e307 = global_3[_e305];
                                    phi_246_ = _e307;
                                } else {
                                    phi_246_ = 0u;
                                }
                                let _e309 = phi_246_;
                                let _e310 = subgroupInclusiveAdd(_e309);
                                local_34 = _e310;
                                let _e311 = local_32;
                                if _e311 {
                                    let _e312 = local_25;
                                    let _e313 = local_22;
                                    let _e314 = (_e312 + _e313);
                                    local_35 = _e314;
                                    if (_e314 < 512u) {
                                    } else {
                                        phi_487_ = true;
                                        break;
                                    }
                                    let _e316 = local_35;
                                    let _e318 = local_34;
                                    global_3[_e316] = _e318;
                                }
                                storageBarrier();
                                workgroupBarrier();
                                let _e319 = local_25;
                                let _e320 = local_31;
                                let _e322 = local_28;
                                phi_213_ = (_e319 + _e320);
                                phi_217_ = _e293;
                                phi_219_ = (_e322 + 1u);
                            } else {
                                phi_213_ = u32();
                                phi_217_ = u32();
                                phi_219_ = u32();
                            }
                            let _e325 = phi_213_;
                            let _e327 = phi_217_;
                            let _e329 = phi_219_;
                            continue;
                            continuing {
                                let _e330 = local_29;
                                phi_212_ = _e325;
                                phi_215_ = _e279;
                                phi_216_ = _e327;
                                phi_218_ = _e329;
                                phi_487_ = _e168;
                                break if !(_e330);
                            }
                        }
                        let _e333 = phi_487_;
                        phi_504_ = _e333;
                        if _e333 {
                            break;
                        }
                        let _e509 = local_67;
                        phi_268_ = _e509;
                        let _e512 = local_68;
                        phi_271_ = _e512;
                        let _e515 = local_69;
                        phi_273_ = _e515;
                        loop {
                            let _e335 = phi_268_;
                            let _e337 = phi_271_;
                            let _e339 = phi_273_;
                            local_36 = _e335;
                            local_37 = _e337;
                            local_38 = _e339;
                            let _e340 = local_38;
                            let _e341 = (_e340 > 0u);
                            local_39 = _e341;
                            if _e341 {
                                let _e342 = local_21;
                                let _e343 = (_e342 & 31u);
                                local_40 = _e343;
                                let _e344 = local_37;
                                let _e346 = (_e344 << bitcast<u32>(_e343));
                                local_41 = _e346;
                                let _e347 = local_38;
                                if (_e347 == 1u) {
                                    phi_288_ = 256u;
                                } else {
                                    let _e349 = local_36;
                                    let _e350 = local_41;
                                    phi_288_ = (_e349 - _e350);
                                }
                                let _e353 = phi_288_;
                                local_42 = _e353;
                                let _e354 = local;
                                let _e355 = local_20;
                                if (_e354 >= _e355) {
                                    let _e357 = local;
                                    let _e358 = local_41;
                                    if (_e357 < _e358) {
                                        let _e360 = local_42;
                                        let _e361 = local;
                                        local_43 = (_e360 + _e361);
                                        let _e363 = local;
                                        let _e364 = local_40;
                                        let _e367 = local_36;
                                        let _e369 = ((_e367 + (_e363 >> bitcast<u32>(_e364))) - 1u);
                                        local_44 = _e369;
                                        if (_e369 < 512u) {
                                        } else {
                                            phi_492_ = true;
                                            break;
                                        }
                                        let _e371 = local_44;
                                        let _e373 = global_3[_e371];
                                        local_45 = _e373;
                                        let _e374 = local_43;
                                        let _e375 = (_e374 < 512u);
                                        local_46 = _e375;
                                        if _e375 {
                                        } else {
                                            phi_492_ = true;
                                            break;
                                        }
                                        let _e376 = local_43;
                                        let _e378 = global_3[_e376];
                                        let _e379 = local_45;
                                        local_47 = (_e379 + _e378);
                                        let _e381 = local_46;
                                        if _e381 {
                                        } else {
                                            phi_492_ = true;
                                            break;
                                        }
                                        let _e382 = local_47;
                                        global_3[_e376] = _e382;
                                    }
                                }
                                storageBarrier();
                                workgroupBarrier();
                                let _e383 = local_38;
                                phi_269_ = _e353;
                                phi_272_ = _e346;
                                phi_274_ = (_e383 - 1u);
                            } else {
                                phi_269_ = u32();
                                phi_272_ = u32();
                                phi_274_ = u32();
                            }
                            let _e386 = phi_269_;
                            let _e388 = phi_272_;
                            let _e390 = phi_274_;
                            continue;
                            continuing {
                                let _e391 = local_39;
                                phi_268_ = _e386;
                                phi_271_ = _e388;
                                phi_273_ = _e390;
                                phi_492_ = _e333;
                                break if !(_e391);
                            }
                        }
                        let _e394 = phi_492_;
                        phi_504_ = _e394;
                        if _e394 {
                            break;
                        }
                        phi_502_ = _e394;
                        phi_379_ = 256u;
                    } else {
                        phi_325_ = 1u;
                        phi_328_ = 0u;
                        loop {
                            let _e209 = phi_325_;
                            let _e211 = phi_328_;
                            local_48 = _e209;
                            local_49 = _e211;
                            local_70 = _e211;
                            let _e212 = local_48;
                            let _e213 = (_e212 < 256u);
                            local_50 = _e213;
                            if _e213 {
                                let _e214 = local_49;
                                let _e216 = select(0u, 256u, (_e214 == 0u));
                                local_66 = _e216;
                                let _e217 = local_49;
                                let _e218 = local;
                                let _e219 = (_e217 + _e218);
                                local_51 = _e219;
                                if (_e219 < 512u) {
                                } else {
                                    phi_477_ = true;
                                    break;
                                }
                                let _e221 = local_51;
                                let _e223 = global_3[_e221];
                                local_52 = _e223;
                                let _e224 = local;
                                let _e225 = local_48;
                                if (_e224 >= _e225) {
                                    let _e227 = local;
                                    let _e228 = local_48;
                                    let _e230 = local_49;
                                    let _e231 = (_e230 + (_e227 - _e228));
                                    local_53 = _e231;
                                    if (_e231 < 512u) {
                                    } else {
                                        phi_477_ = true;
                                        break;
                                    }
                                    let _e233 = local_53;
                                    let _e235 = global_3[_e233];
                                    let _e236 = local_52;
                                    phi_364_ = (_e235 + _e236);
                                } else {
                                    phi_364_ = _e223;
                                }
                                let _e239 = phi_364_;
                                local_54 = _e239;
                                let _e240 = local_66;
                                let _e241 = local;
                                let _e242 = (_e240 + _e241);
                                local_55 = _e242;
                                if (_e242 < 512u) {
                                } else {
                                    phi_477_ = true;
                                    break;
                                }
                                let _e244 = local_55;
                                let _e246 = local_54;
                                global_3[_e244] = _e246;
                                storageBarrier();
                                workgroupBarrier();
                                let _e247 = local_48;
                                phi_326_ = (_e247 * 2u);
                                phi_329_ = _e216;
                            } else {
                                phi_326_ = u32();
                                phi_329_ = u32();
                            }
                            let _e250 = phi_326_;
                            let _e252 = phi_329_;
                            continue;
                            continuing {
                                let _e253 = local_50;
                                phi_325_ = _e250;
                                phi_328_ = _e252;
                                phi_477_ = _e168;
                                break if !(_e253);
                            }
                        }
                        let _e256 = phi_477_;
                        phi_504_ = _e256;
                        if _e256 {
                            break;
                        }
                        phi_502_ = _e256;
                        let _e524 = local_70;
                        phi_379_ = _e524;
                    }
                    let _e396 = phi_502_;
                    let _e398 = phi_379_;
                    let _e399 = local;
                    let _e400 = (_e398 + _e399);
                    local_56 = _e400;
                    if (_e400 < 512u) {
                    } else {
                        phi_504_ = true;
                        break;
                    }
                    let _e402 = local_56;
                    let _e404 = global_3[_e402];
                    local_57 = _e404;
                    let _e405 = local;
                    if (_e405 == 0u) {
                        phi_401_ = 0u;
                    } else {
                        let _e407 = local_56;
                        let _e408 = (_e407 - 1u);
                        local_58 = _e408;
                        if (_e408 < 512u) {
                        } else {
                            phi_504_ = true;
                            break;
                        }
                        let _e410 = local_58;
                        let _e412 = global_3[_e410];
                        phi_401_ = _e412;
                    }
                    let _e414 = phi_401_;
                    phi_403_ = 0u;
                    phi_406_ = _e414;
                    loop {
                        let _e416 = phi_403_;
                        let _e418 = phi_406_;
                        local_59 = _e416;
                        local_60 = _e418;
                        let _e419 = local_59;
                        let _e420 = (_e419 < 4u);
                        local_61 = _e420;
                        if _e420 {
                            let _e421 = local;
                            let _e423 = local_13;
                            let _e425 = local_59;
                            let _e426 = ((_e423 + (_e421 * 4u)) + _e425);
                            local_62 = _e426;
                            let _e427 = local_14;
                            if (_e426 < _e427) {
                                let _e429 = local_62;
                                let _e430 = local_5;
                                let _e431 = (_e429 < _e430);
                                local_63 = _e431;
                                if _e431 {
                                } else {
                                    phi_498_ = true;
                                    break;
                                }
                                let _e432 = local_62;
                                let _e435 = global_5.member[_e432];
                                local_64 = _e435;
                                let _e436 = local_63;
                                if _e436 {
                                } else {
                                    phi_498_ = true;
                                    break;
                                }
                                let _e437 = local_60;
                                global_5.member[_e432] = _e437;
                                let _e438 = local_60;
                                let _e439 = local_64;
                                phi_435_ = (_e438 + _e439);
                            } else {
                                phi_435_ = _e418;
                            }
                            let _e442 = phi_435_;
                            let _e443 = local_59;
                            phi_404_ = (_e443 + 1u);
                            phi_407_ = _e442;
                        } else {
                            phi_404_ = u32();
                            phi_407_ = u32();
                        }
                        let _e446 = phi_404_;
                        let _e448 = phi_407_;
                        continue;
                        continuing {
                            let _e449 = local_61;
                            phi_403_ = _e446;
                            phi_406_ = _e448;
                            phi_498_ = _e396;
                            break if !(_e449);
                        }
                    }
                    let _e452 = phi_498_;
                    phi_504_ = _e452;
                    if _e452 {
                        break;
                    }
                    let _e453 = local;
                    if (_e453 == 255u) {
                        let _e457 = global_4.member.member_2;
                        let _e458 = local_11;
                        let _e459 = (_e457 + _e458);
                        local_65 = _e459;
                        let _e460 = local_6;
                        if (_e459 < _e460) {
                        } else {
                            phi_504_ = true;
                            break;
                        }
                        let _e462 = local_65;
                        let _e465 = local_57;
                        global_6.member[_e462] = _e465;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e466 = local_11;
                    let _e467 = local_7;
                    phi_505_ = _e452;
                    phi_97_ = (_e466 + _e467);
                } else {
                    phi_505_ = _e120;
                    phi_97_ = u32();
                }
                let _e470 = phi_505_;
                let _e472 = phi_97_;
                continue;
                continuing {
                    let _e473 = local_12;
                    phi_474_ = _e470;
                    phi_96_ = _e472;
                    phi_504_ = _e470;
                    break if !(_e473);
                }
            }
            let _e476 = phi_504_;
            if _e476 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn subgroups(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>, @builtin(subgroup_size) param_3: u32, @builtin(num_subgroups) param_4: u32, @builtin(subgroup_id) param_5: u32, @builtin(subgroup_invocation_id) param_6: u32) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    global_7 = param_3;
    global_8 = param_4;
    global_9 = param_5;
    global_10 = param_6;
    function_();
}
