struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_6 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: type_5,
}

struct type_7 {
    member: type_6,
}

struct type_10 {
    member: array<u32>,
}

struct type_18 {
    member: u32,
    member_1: array<f32, 3>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<immediate> global_2: type_7;
@group(0) @binding(1) 
var<storage> global_3: type_10;
@group(0) @binding(0) 
var<storage> global_4: type_10;
@group(0) @binding(2) 
var<storage, read_write> global_5: type_10;
@group(0) @binding(3) 
var<storage> global_6: type_10;
var<private> global_7: u32 = 2143289344u;

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
    var local_10: f32;
    var local_11: u32;
    var local_12: f32;
    var local_13: u32;
    var local_14: f32;
    var local_15: f32;
    var local_16: f32;
    var local_17: i32;
    var local_18: i32;
    var local_19: f32;
    var local_20: array<f32, 3>;
    var local_21: bool;
    var local_22: i32;
    var local_23: i32;
    var local_24: f32;
    var local_25: array<f32, 3>;
    var local_26: i32;
    var local_27: u32;
    var local_28: f32;
    var local_29: u32;
    var local_30: f32;
    var local_31: u32;
    var local_32: f32;
    var local_33: u32;
    var local_34: f32;
    var local_35: bool;
    var local_36: f32;
    var local_37: f32;
    var local_38: type_18;
    var local_39: array<f32, 3>;
    var local_40: type_18;
    var local_41: array<f32, 3>;
    var local_42: u32;
    var local_43: f32;
    var local_44: f32;
    var local_45: f32;
    var local_46: f32;
    var local_47: bool;
    var local_48: f32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: u32;
    var local_57: f32;
    var local_58: f32;
    var local_59: f32;
    var local_60: f32;
    var phi_181_: bool;
    var phi_209_: f32;
    var phi_210_: f32;
    var phi_216_: f32;
    var phi_218_: f32;
    var phi_676_: bool;
    var phi_762_: bool;
    var phi_230_: i32;
    var phi_233_: f32;
    var phi_235_: array<f32, 3>;
    var phi_247_: i32;
    var phi_250_: f32;
    var phi_252_: array<f32, 3>;
    var phi_354_: bool;
    var phi_368_: bool;
    var phi_373_: f32;
    var phi_383_: bool;
    var phi_397_: bool;
    var phi_402_: f32;
    var phi_412_: bool;
    var phi_426_: bool;
    var phi_431_: f32;
    var phi_434_: type_18;
    var phi_436_: type_18;
    var phi_437_: bool;
    var phi_438_: type_18;
    var phi_439_: bool;
    var phi_444_: type_18;
    var phi_690_: bool;
    var phi_458_: type_18;
    var phi_460_: type_18;
    var phi_497_: bool;
    var phi_525_: f32;
    var phi_526_: f32;
    var phi_532_: f32;
    var phi_534_: f32;
    var phi_701_: bool;
    var phi_716_: bool;
    var phi_549_: f32;
    var phi_578_: f32;
    var phi_579_: array<f32, 3>;
    var phi_580_: f32;
    var phi_581_: array<f32, 3>;
    var phi_582_: f32;
    var phi_583_: array<f32, 3>;
    var phi_584_: f32;
    var phi_585_: array<f32, 3>;
    var phi_587_: i32;
    var phi_588_: f32;
    var phi_589_: array<f32, 3>;
    var phi_591_: i32;
    var phi_592_: f32;
    var phi_593_: array<f32, 3>;
    var phi_594_: bool;
    var phi_248_: i32;
    var phi_251_: f32;
    var phi_253_: array<f32, 3>;
    var phi_596_: bool;
    var phi_721_: bool;
    var phi_777_: bool;
    var phi_231_: i32;
    var phi_234_: f32;
    var phi_236_: array<f32, 3>;
    var phi_776_: bool;
    var phi_612_: f32;
    var local_61: f32;
    var local_62: array<f32, 3>;

    let _e96 = global_7;
    let _e97 = bitcast<f32>(_e96);
    switch bitcast<i32>(0u) {
        default: {
            let _e99 = global;
            local = _e99;
            let _e100 = global_1;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = _e100.x;
            local_5 = _e100.y;
            if (0u < arrayLength((&global_6.member))) {
            } else {
                break;
            }
            let _e114 = global_6.member[0u];
            let _e117 = global_2.member.member_2;
            local_56 = select(_e117, _e114, (_e114 < _e117));
            let _e120 = local_4;
            let _e122 = local;
            let _e124 = ((_e120 * 8u) + (_e122 % 8u));
            local_6 = _e124;
            let _e125 = local_5;
            let _e127 = local;
            local_7 = ((_e125 * 8u) + (_e127 / 8u));
            let _e132 = global_2.member.member;
            local_8 = _e132;
            if (_e124 >= _e132) {
            } else {
                let _e136 = global_2.member.member_1;
                local_9 = _e136;
                let _e137 = local_7;
                if (_e137 >= _e136) {
                } else {
                    let _e139 = local_56;
                    local_10 = f32(_e139);
                    let _e141 = local_7;
                    let _e142 = local_8;
                    let _e144 = local_6;
                    let _e145 = ((_e141 * _e142) + _e144);
                    local_11 = _e145;
                    let _e146 = local_2;
                    if (_e145 < _e146) {
                    } else {
                        break;
                    }
                    let _e148 = local_11;
                    let _e151 = global_3.member[_e148];
                    let _e152 = bitcast<f32>(_e151);
                    local_12 = _e152;
                    let _e153 = bitcast<u32>(_e152);
                    local_13 = _e153;
                    if (_e153 == 2139095040u) {
                        let _e158 = global_2.member.member_4.member_1;
                        let _e163 = global_2.member.member_4.member;
                        let _e168 = global_2.member.member_4.member_2;
                        let _e174 = global_2.member.member_4.member_3;
                        phi_218_ = (0.5f * ((((2f * _e158) * _e163) / (_e168 - _e163)) * _e174));
                    } else {
                        let _e177 = local_13;
                        if (_e177 == 0u) {
                            phi_181_ = false;
                        } else {
                            let _e179 = local_13;
                            phi_181_ = (_e179 <= 2139095040u);
                        }
                        let _e182 = phi_181_;
                        if _e182 {
                            let _e186 = global_2.member.member_4.member_1;
                            let _e191 = global_2.member.member_4.member;
                            let _e196 = global_2.member.member_4.member_2;
                            local_14 = _e196;
                            let _e202 = global_2.member.member_4.member_3;
                            let _e203 = ((((2f * _e186) * _e191) / (_e196 - _e191)) * _e202);
                            local_15 = _e203;
                            if (_e203 == 0f) {
                                phi_209_ = 0f;
                            } else {
                                let _e205 = local_14;
                                let _e206 = local_12;
                                let _e209 = local_15;
                                phi_209_ = (_e209 * (1f - (_e205 / _e206)));
                            }
                            let _e212 = phi_209_;
                            phi_210_ = _e212;
                        } else {
                            phi_210_ = _e97;
                        }
                        let _e214 = phi_210_;
                        local_16 = _e214;
                        if (_e214 < 0f) {
                            let _e216 = local_16;
                            phi_216_ = -(_e216);
                        } else {
                            phi_216_ = _e214;
                        }
                        let _e219 = phi_216_;
                        phi_218_ = (0.5f * _e219);
                    }
                    let _e222 = phi_218_;
                    let _e226 = select(_e222, 0f, ((bitcast<u32>(_e222) & 2147483647u) > 2139095040u));
                    local_57 = _e226;
                    if (_e226 != _e226) {
                        phi_676_ = true;
                    } else {
                        let _e228 = local_10;
                        let _e229 = local_57;
                        phi_676_ = (_e228 <= _e229);
                    }
                    let _e232 = phi_676_;
                    let _e233 = local_10;
                    let _e234 = local_57;
                    local_58 = select(_e234, _e233, _e232);
                    let _e236 = local_56;
                    let _e237 = bitcast<i32>(_e236);
                    local_17 = _e237;
                    let _e238 = -(_e237);
                    phi_762_ = false;
                    phi_230_ = _e238;
                    phi_233_ = 0f;
                    phi_235_ = array<f32, 3>(0f, 0f, 0f);
                    loop {
                        let _e240 = phi_762_;
                        let _e242 = phi_230_;
                        let _e244 = phi_233_;
                        let _e246 = phi_235_;
                        local_18 = _e242;
                        local_19 = _e244;
                        local_20 = _e246;
                        let _e247 = local_18;
                        let _e248 = local_17;
                        let _e249 = (_e247 <= _e248);
                        local_21 = _e249;
                        if _e249 {
                            let _e250 = local_7;
                            let _e252 = local_18;
                            local_22 = (bitcast<i32>(_e250) + _e252);
                            phi_247_ = _e238;
                            phi_250_ = _e244;
                            phi_252_ = _e246;
                            loop {
                                let _e255 = phi_247_;
                                let _e257 = phi_250_;
                                let _e259 = phi_252_;
                                local_23 = _e255;
                                local_24 = _e257;
                                local_25 = _e259;
                                local_61 = _e257;
                                local_62 = _e259;
                                let _e260 = local_22;
                                if (_e260 >= 0i) {
                                    let _e262 = local_9;
                                    let _e264 = local_22;
                                    if (_e264 < bitcast<i32>(_e262)) {
                                        let _e266 = local_23;
                                        let _e267 = local_17;
                                        let _e268 = (_e266 <= _e267);
                                        if _e268 {
                                            let _e269 = local_6;
                                            let _e271 = local_23;
                                            let _e272 = (bitcast<i32>(_e269) + _e271);
                                            local_26 = _e272;
                                            if (_e272 >= 0i) {
                                                let _e274 = local_8;
                                                let _e276 = local_26;
                                                if (_e276 < bitcast<i32>(_e274)) {
                                                    let _e278 = local_22;
                                                    let _e280 = local_8;
                                                    let _e282 = local_26;
                                                    let _e284 = ((bitcast<u32>(_e278) * _e280) + bitcast<u32>(_e282));
                                                    local_27 = _e284;
                                                    let _e285 = local_2;
                                                    if (_e284 < _e285) {
                                                    } else {
                                                        phi_721_ = true;
                                                        break;
                                                    }
                                                    let _e287 = local_27;
                                                    let _e290 = global_3.member[_e287];
                                                    local_28 = bitcast<f32>(_e290);
                                                    let _e292 = local_27;
                                                    let _e293 = (3u * _e292);
                                                    local_29 = _e293;
                                                    let _e294 = local_1;
                                                    if (_e293 < _e294) {
                                                    } else {
                                                        phi_721_ = true;
                                                        break;
                                                    }
                                                    let _e296 = local_29;
                                                    let _e299 = global_4.member[_e296];
                                                    local_30 = bitcast<f32>(_e299);
                                                    let _e301 = local_29;
                                                    let _e302 = (_e301 + 1u);
                                                    local_31 = _e302;
                                                    let _e303 = local_1;
                                                    if (_e302 < _e303) {
                                                    } else {
                                                        phi_721_ = true;
                                                        break;
                                                    }
                                                    let _e305 = local_31;
                                                    let _e308 = global_4.member[_e305];
                                                    local_32 = bitcast<f32>(_e308);
                                                    let _e310 = local_29;
                                                    let _e311 = (_e310 + 2u);
                                                    local_33 = _e311;
                                                    let _e312 = local_1;
                                                    if (_e311 < _e312) {
                                                    } else {
                                                        phi_721_ = true;
                                                        break;
                                                    }
                                                    let _e314 = local_33;
                                                    let _e317 = global_4.member[_e314];
                                                    local_34 = bitcast<f32>(_e317);
                                                    let _e319 = local_30;
                                                    if ((bitcast<u32>(_e319) & 2139095040u) != 2139095040u) {
                                                        let _e323 = local_32;
                                                        if ((bitcast<u32>(_e323) & 2139095040u) != 2139095040u) {
                                                            let _e327 = local_34;
                                                            let _e330 = ((bitcast<u32>(_e327) & 2139095040u) != 2139095040u);
                                                            local_35 = _e330;
                                                            if _e330 {
                                                                let _e331 = local_30;
                                                                if (_e331 > 1267650600000000000000000000000f) {
                                                                    let _e333 = local_30;
                                                                    phi_354_ = select(true, false, (_e333 <= 340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_354_ = true;
                                                                }
                                                                let _e337 = phi_354_;
                                                                if _e337 {
                                                                    let _e338 = local_30;
                                                                    if (_e338 < 0.000000000000000000000000000000000000011754944f) {
                                                                        let _e340 = local_30;
                                                                        phi_368_ = select(true, false, (_e340 >= -340282350000000000000000000000000000000f));
                                                                    } else {
                                                                        phi_368_ = true;
                                                                    }
                                                                    let _e344 = phi_368_;
                                                                    let _e345 = local_30;
                                                                    phi_373_ = select(0f, _e345, _e344);
                                                                } else {
                                                                    phi_373_ = 1267650600000000000000000000000f;
                                                                }
                                                                let _e348 = phi_373_;
                                                                local_36 = _e348;
                                                                let _e349 = local_32;
                                                                if (_e349 > 1267650600000000000000000000000f) {
                                                                    let _e351 = local_32;
                                                                    phi_383_ = select(true, false, (_e351 <= 340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_383_ = true;
                                                                }
                                                                let _e355 = phi_383_;
                                                                if _e355 {
                                                                    let _e356 = local_32;
                                                                    if (_e356 < 0.000000000000000000000000000000000000011754944f) {
                                                                        let _e358 = local_32;
                                                                        phi_397_ = select(true, false, (_e358 >= -340282350000000000000000000000000000000f));
                                                                    } else {
                                                                        phi_397_ = true;
                                                                    }
                                                                    let _e362 = phi_397_;
                                                                    let _e363 = local_32;
                                                                    phi_402_ = select(0f, _e363, _e362);
                                                                } else {
                                                                    phi_402_ = 1267650600000000000000000000000f;
                                                                }
                                                                let _e366 = phi_402_;
                                                                local_37 = _e366;
                                                                let _e367 = local_34;
                                                                if (_e367 > 1267650600000000000000000000000f) {
                                                                    let _e369 = local_34;
                                                                    phi_412_ = select(true, false, (_e369 <= 340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_412_ = true;
                                                                }
                                                                let _e373 = phi_412_;
                                                                if _e373 {
                                                                    let _e374 = local_34;
                                                                    if (_e374 < 0.000000000000000000000000000000000000011754944f) {
                                                                        let _e376 = local_34;
                                                                        phi_426_ = select(true, false, (_e376 >= -340282350000000000000000000000000000000f));
                                                                    } else {
                                                                        phi_426_ = true;
                                                                    }
                                                                    let _e380 = phi_426_;
                                                                    let _e381 = local_34;
                                                                    phi_431_ = select(0f, _e381, _e380);
                                                                } else {
                                                                    phi_431_ = 1267650600000000000000000000000f;
                                                                }
                                                                let _e384 = phi_431_;
                                                                let _e385 = local_36;
                                                                let _e386 = local_37;
                                                                phi_434_ = type_18(1u, array<f32, 3>(_e385, _e386, _e384));
                                                            } else {
                                                                phi_434_ = type_18();
                                                            }
                                                            let _e390 = phi_434_;
                                                            let _e391 = local_35;
                                                            phi_436_ = _e390;
                                                            phi_437_ = select(true, false, _e391);
                                                        } else {
                                                            phi_436_ = type_18();
                                                            phi_437_ = true;
                                                        }
                                                        let _e394 = phi_436_;
                                                        let _e396 = phi_437_;
                                                        phi_438_ = _e394;
                                                        phi_439_ = _e396;
                                                    } else {
                                                        phi_438_ = type_18();
                                                        phi_439_ = true;
                                                    }
                                                    let _e398 = phi_438_;
                                                    let _e400 = phi_439_;
                                                    if _e400 {
                                                        phi_444_ = type_18(0u, type_18().member_1);
                                                    } else {
                                                        phi_444_ = _e398;
                                                    }
                                                    let _e405 = phi_444_;
                                                    local_38 = _e405;
                                                    if (bitcast<i32>(_e405.member) != 0i) {
                                                        let _e409 = local_38;
                                                        local_39 = _e409.member_1;
                                                        let _e411 = local_28;
                                                        let _e412 = bitcast<u32>(_e411);
                                                        local_55 = _e412;
                                                        if (_e412 == 0u) {
                                                            phi_690_ = false;
                                                        } else {
                                                            let _e414 = local_55;
                                                            phi_690_ = (_e414 <= 2139095040u);
                                                        }
                                                        let _e417 = phi_690_;
                                                        if _e417 {
                                                            let _e418 = local_39;
                                                            phi_458_ = type_18(1u, _e418);
                                                        } else {
                                                            phi_458_ = type_18(0u, type_18().member_1);
                                                        }
                                                        let _e424 = phi_458_;
                                                        phi_460_ = _e424;
                                                    } else {
                                                        phi_460_ = type_18(0u, type_18().member_1);
                                                    }
                                                    let _e429 = phi_460_;
                                                    local_40 = _e429;
                                                    if (bitcast<i32>(_e429.member) != 0i) {
                                                        let _e433 = local_40;
                                                        local_41 = _e433.member_1;
                                                        let _e435 = local_28;
                                                        let _e436 = bitcast<u32>(_e435);
                                                        local_42 = _e436;
                                                        if (_e436 == 2139095040u) {
                                                            let _e441 = global_2.member.member_4.member_1;
                                                            let _e446 = global_2.member.member_4.member;
                                                            let _e451 = global_2.member.member_4.member_2;
                                                            let _e457 = global_2.member.member_4.member_3;
                                                            phi_534_ = (0.5f * ((((2f * _e441) * _e446) / (_e451 - _e446)) * _e457));
                                                        } else {
                                                            let _e460 = local_42;
                                                            if (_e460 == 0u) {
                                                                phi_497_ = false;
                                                            } else {
                                                                let _e462 = local_42;
                                                                phi_497_ = (_e462 <= 2139095040u);
                                                            }
                                                            let _e465 = phi_497_;
                                                            if _e465 {
                                                                let _e469 = global_2.member.member_4.member_1;
                                                                let _e474 = global_2.member.member_4.member;
                                                                let _e479 = global_2.member.member_4.member_2;
                                                                local_43 = _e479;
                                                                let _e485 = global_2.member.member_4.member_3;
                                                                let _e486 = ((((2f * _e469) * _e474) / (_e479 - _e474)) * _e485);
                                                                local_44 = _e486;
                                                                if (_e486 == 0f) {
                                                                    phi_525_ = 0f;
                                                                } else {
                                                                    let _e488 = local_43;
                                                                    let _e489 = local_28;
                                                                    let _e492 = local_44;
                                                                    phi_525_ = (_e492 * (1f - (_e488 / _e489)));
                                                                }
                                                                let _e495 = phi_525_;
                                                                phi_526_ = _e495;
                                                            } else {
                                                                phi_526_ = _e97;
                                                            }
                                                            let _e497 = phi_526_;
                                                            local_45 = _e497;
                                                            if (_e497 < 0f) {
                                                                let _e499 = local_45;
                                                                phi_532_ = -(_e499);
                                                            } else {
                                                                phi_532_ = _e497;
                                                            }
                                                            let _e502 = phi_532_;
                                                            phi_534_ = (0.5f * _e502);
                                                        }
                                                        let _e505 = phi_534_;
                                                        let _e509 = select(_e505, 0f, ((bitcast<u32>(_e505) & 2147483647u) > 2139095040u));
                                                        local_59 = _e509;
                                                        if (_e509 != _e509) {
                                                            phi_701_ = true;
                                                        } else {
                                                            let _e511 = local_10;
                                                            let _e512 = local_59;
                                                            phi_701_ = (_e511 <= _e512);
                                                        }
                                                        let _e515 = phi_701_;
                                                        let _e516 = local_10;
                                                        let _e517 = local_59;
                                                        let _e518 = select(_e517, _e516, _e515);
                                                        local_60 = _e518;
                                                        let _e519 = local_28;
                                                        let _e520 = local_12;
                                                        if (_e519 > _e520) {
                                                            let _e522 = local_60;
                                                            let _e523 = local_60;
                                                            if (_e522 != _e523) {
                                                                phi_716_ = true;
                                                            } else {
                                                                let _e525 = local_58;
                                                                let _e526 = local_60;
                                                                phi_716_ = (_e525 <= _e526);
                                                            }
                                                            let _e529 = phi_716_;
                                                            let _e530 = local_58;
                                                            let _e531 = local_60;
                                                            phi_549_ = select(_e531, _e530, _e529);
                                                        } else {
                                                            phi_549_ = _e518;
                                                        }
                                                        let _e534 = phi_549_;
                                                        let _e535 = (_e534 + 0.5f);
                                                        let _e536 = local_23;
                                                        let _e537 = local_23;
                                                        let _e539 = local_18;
                                                        let _e540 = local_18;
                                                        let _e544 = (_e535 * _e535);
                                                        local_46 = _e544;
                                                        if (f32(((_e536 * _e537) + (_e539 * _e540))) <= _e544) {
                                                            let _e546 = local_46;
                                                            let _e547 = (1f / _e546);
                                                            let _e548 = local_41;
                                                            let _e551 = local_25;
                                                            let _e554 = local_41;
                                                            let _e557 = local_25;
                                                            let _e560 = local_41;
                                                            let _e563 = local_25;
                                                            let _e567 = local_24;
                                                            phi_578_ = (_e567 + _e547);
                                                            phi_579_ = array<f32, 3>((_e551[0] + (_e547 * _e548[0])), (_e557[1] + (_e547 * _e554[1])), (_e563[2] + (_e547 * _e560[2])));
                                                        } else {
                                                            phi_578_ = _e257;
                                                            phi_579_ = _e259;
                                                        }
                                                        let _e570 = phi_578_;
                                                        let _e572 = phi_579_;
                                                        phi_580_ = _e570;
                                                        phi_581_ = _e572;
                                                    } else {
                                                        phi_580_ = _e257;
                                                        phi_581_ = _e259;
                                                    }
                                                    let _e574 = phi_580_;
                                                    let _e576 = phi_581_;
                                                    phi_582_ = _e574;
                                                    phi_583_ = _e576;
                                                } else {
                                                    phi_582_ = _e257;
                                                    phi_583_ = _e259;
                                                }
                                                let _e578 = phi_582_;
                                                let _e580 = phi_583_;
                                                phi_584_ = _e578;
                                                phi_585_ = _e580;
                                            } else {
                                                phi_584_ = _e257;
                                                phi_585_ = _e259;
                                            }
                                            let _e582 = phi_584_;
                                            let _e584 = phi_585_;
                                            let _e585 = local_23;
                                            phi_587_ = (_e585 + 1i);
                                            phi_588_ = _e582;
                                            phi_589_ = _e584;
                                        } else {
                                            phi_587_ = i32();
                                            phi_588_ = f32();
                                            phi_589_ = array<f32, 3>();
                                        }
                                        let _e588 = phi_587_;
                                        let _e590 = phi_588_;
                                        let _e592 = phi_589_;
                                        phi_591_ = _e588;
                                        phi_592_ = _e590;
                                        phi_593_ = _e592;
                                        phi_594_ = _e268;
                                    } else {
                                        phi_591_ = i32();
                                        phi_592_ = f32();
                                        phi_593_ = array<f32, 3>();
                                        phi_594_ = false;
                                    }
                                    let _e594 = phi_591_;
                                    let _e596 = phi_592_;
                                    let _e598 = phi_593_;
                                    let _e600 = phi_594_;
                                    phi_248_ = _e594;
                                    phi_251_ = _e596;
                                    phi_253_ = _e598;
                                    phi_596_ = _e600;
                                } else {
                                    phi_248_ = i32();
                                    phi_251_ = f32();
                                    phi_253_ = array<f32, 3>();
                                    phi_596_ = false;
                                }
                                let _e602 = phi_248_;
                                let _e604 = phi_251_;
                                let _e606 = phi_253_;
                                let _e608 = phi_596_;
                                local_47 = _e608;
                                continue;
                                continuing {
                                    let _e609 = local_47;
                                    phi_247_ = _e602;
                                    phi_250_ = _e604;
                                    phi_252_ = _e606;
                                    phi_721_ = _e240;
                                    break if !(_e609);
                                }
                            }
                            let _e612 = phi_721_;
                            phi_776_ = _e612;
                            if _e612 {
                                break;
                            }
                            let _e613 = local_18;
                            phi_777_ = _e612;
                            phi_231_ = (_e613 + 1i);
                            let _e734 = local_61;
                            phi_234_ = _e734;
                            let _e737 = local_62;
                            phi_236_ = _e737;
                        } else {
                            phi_777_ = _e240;
                            phi_231_ = i32();
                            phi_234_ = f32();
                            phi_236_ = array<f32, 3>();
                        }
                        let _e616 = phi_777_;
                        let _e618 = phi_231_;
                        let _e620 = phi_234_;
                        let _e622 = phi_236_;
                        continue;
                        continuing {
                            let _e623 = local_21;
                            phi_762_ = _e616;
                            phi_230_ = _e618;
                            phi_233_ = _e620;
                            phi_235_ = _e622;
                            phi_776_ = _e616;
                            break if !(_e623);
                        }
                    }
                    let _e626 = phi_776_;
                    if _e626 {
                        break;
                    }
                    let _e627 = local_19;
                    if (_e627 > 0f) {
                        let _e629 = local_19;
                        phi_612_ = (1f / _e629);
                    } else {
                        phi_612_ = 0f;
                    }
                    let _e632 = phi_612_;
                    local_48 = _e632;
                    let _e633 = local_11;
                    let _e634 = (3u * _e633);
                    local_49 = _e634;
                    let _e635 = local_20;
                    local_50 = bitcast<u32>((_e635[0] * _e632));
                    let _e639 = local_3;
                    if (_e634 < _e639) {
                    } else {
                        break;
                    }
                    let _e641 = local_49;
                    let _e644 = local_50;
                    global_5.member[_e641] = _e644;
                    let _e645 = local_49;
                    let _e646 = (_e645 + 1u);
                    local_51 = _e646;
                    let _e647 = local_20;
                    let _e649 = local_48;
                    local_52 = bitcast<u32>((_e647[1] * _e649));
                    let _e652 = local_3;
                    if (_e646 < _e652) {
                    } else {
                        break;
                    }
                    let _e654 = local_51;
                    let _e657 = local_52;
                    global_5.member[_e654] = _e657;
                    let _e658 = local_49;
                    let _e659 = (_e658 + 2u);
                    local_53 = _e659;
                    let _e660 = local_20;
                    let _e662 = local_48;
                    local_54 = bitcast<u32>((_e660[2] * _e662));
                    let _e665 = local_3;
                    if (_e659 < _e665) {
                    } else {
                        break;
                    }
                    let _e667 = local_53;
                    let _e670 = local_54;
                    global_5.member[_e667] = _e670;
                }
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn gather(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
