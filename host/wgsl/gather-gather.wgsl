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
                    if !((_e226 == _e226)) {
                        phi_676_ = true;
                    } else {
                        let _e229 = local_10;
                        let _e230 = local_57;
                        phi_676_ = (_e229 <= _e230);
                    }
                    let _e233 = phi_676_;
                    let _e234 = local_10;
                    let _e235 = local_57;
                    local_58 = select(_e235, _e234, _e233);
                    let _e237 = local_56;
                    let _e238 = bitcast<i32>(_e237);
                    local_17 = _e238;
                    let _e239 = -(_e238);
                    phi_762_ = false;
                    phi_230_ = _e239;
                    phi_233_ = 0f;
                    phi_235_ = array<f32, 3>(0f, 0f, 0f);
                    loop {
                        let _e241 = phi_762_;
                        let _e243 = phi_230_;
                        let _e245 = phi_233_;
                        let _e247 = phi_235_;
                        local_18 = _e243;
                        local_19 = _e245;
                        local_20 = _e247;
                        let _e248 = local_18;
                        let _e249 = local_17;
                        let _e250 = (_e248 <= _e249);
                        local_21 = _e250;
                        if _e250 {
                            let _e251 = local_7;
                            let _e253 = local_18;
                            local_22 = (bitcast<i32>(_e251) + _e253);
                            phi_247_ = _e239;
                            phi_250_ = _e245;
                            phi_252_ = _e247;
                            loop {
                                let _e256 = phi_247_;
                                let _e258 = phi_250_;
                                let _e260 = phi_252_;
                                local_23 = _e256;
                                local_24 = _e258;
                                local_25 = _e260;
                                local_61 = _e258;
                                local_62 = _e260;
                                let _e261 = local_22;
                                if (_e261 >= 0i) {
                                    let _e263 = local_9;
                                    let _e265 = local_22;
                                    if (_e265 < bitcast<i32>(_e263)) {
                                        let _e267 = local_23;
                                        let _e268 = local_17;
                                        let _e269 = (_e267 <= _e268);
                                        if _e269 {
                                            let _e270 = local_6;
                                            let _e272 = local_23;
                                            let _e273 = (bitcast<i32>(_e270) + _e272);
                                            local_26 = _e273;
                                            if (_e273 >= 0i) {
                                                let _e275 = local_8;
                                                let _e277 = local_26;
                                                if (_e277 < bitcast<i32>(_e275)) {
                                                    let _e279 = local_22;
                                                    let _e281 = local_8;
                                                    let _e283 = local_26;
                                                    let _e285 = ((bitcast<u32>(_e279) * _e281) + bitcast<u32>(_e283));
                                                    local_27 = _e285;
                                                    let _e286 = local_2;
                                                    if (_e285 < _e286) {
                                                    } else {
                                                        phi_721_ = true;
                                                        break;
                                                    }
                                                    let _e288 = local_27;
                                                    let _e291 = global_3.member[_e288];
                                                    local_28 = bitcast<f32>(_e291);
                                                    let _e293 = local_27;
                                                    let _e294 = (3u * _e293);
                                                    local_29 = _e294;
                                                    let _e295 = local_1;
                                                    if (_e294 < _e295) {
                                                    } else {
                                                        phi_721_ = true;
                                                        break;
                                                    }
                                                    let _e297 = local_29;
                                                    let _e300 = global_4.member[_e297];
                                                    local_30 = bitcast<f32>(_e300);
                                                    let _e302 = local_29;
                                                    let _e303 = (_e302 + 1u);
                                                    local_31 = _e303;
                                                    let _e304 = local_1;
                                                    if (_e303 < _e304) {
                                                    } else {
                                                        phi_721_ = true;
                                                        break;
                                                    }
                                                    let _e306 = local_31;
                                                    let _e309 = global_4.member[_e306];
                                                    local_32 = bitcast<f32>(_e309);
                                                    let _e311 = local_29;
                                                    let _e312 = (_e311 + 2u);
                                                    local_33 = _e312;
                                                    let _e313 = local_1;
                                                    if (_e312 < _e313) {
                                                    } else {
                                                        phi_721_ = true;
                                                        break;
                                                    }
                                                    let _e315 = local_33;
                                                    let _e318 = global_4.member[_e315];
                                                    local_34 = bitcast<f32>(_e318);
                                                    let _e320 = local_30;
                                                    if ((bitcast<u32>(_e320) & 2139095040u) != 2139095040u) {
                                                        let _e324 = local_32;
                                                        if ((bitcast<u32>(_e324) & 2139095040u) != 2139095040u) {
                                                            let _e328 = local_34;
                                                            let _e331 = ((bitcast<u32>(_e328) & 2139095040u) != 2139095040u);
                                                            local_35 = _e331;
                                                            if _e331 {
                                                                let _e332 = local_30;
                                                                if (_e332 > 1267650600000000000000000000000f) {
                                                                    let _e334 = local_30;
                                                                    phi_354_ = select(true, false, (_e334 <= 340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_354_ = true;
                                                                }
                                                                let _e338 = phi_354_;
                                                                if _e338 {
                                                                    let _e339 = local_30;
                                                                    if (_e339 < 0.000000000000000000000000000000000000011754944f) {
                                                                        let _e341 = local_30;
                                                                        phi_368_ = select(true, false, (_e341 >= -340282350000000000000000000000000000000f));
                                                                    } else {
                                                                        phi_368_ = true;
                                                                    }
                                                                    let _e345 = phi_368_;
                                                                    let _e346 = local_30;
                                                                    phi_373_ = select(0f, _e346, _e345);
                                                                } else {
                                                                    phi_373_ = 1267650600000000000000000000000f;
                                                                }
                                                                let _e349 = phi_373_;
                                                                local_36 = _e349;
                                                                let _e350 = local_32;
                                                                if (_e350 > 1267650600000000000000000000000f) {
                                                                    let _e352 = local_32;
                                                                    phi_383_ = select(true, false, (_e352 <= 340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_383_ = true;
                                                                }
                                                                let _e356 = phi_383_;
                                                                if _e356 {
                                                                    let _e357 = local_32;
                                                                    if (_e357 < 0.000000000000000000000000000000000000011754944f) {
                                                                        let _e359 = local_32;
                                                                        phi_397_ = select(true, false, (_e359 >= -340282350000000000000000000000000000000f));
                                                                    } else {
                                                                        phi_397_ = true;
                                                                    }
                                                                    let _e363 = phi_397_;
                                                                    let _e364 = local_32;
                                                                    phi_402_ = select(0f, _e364, _e363);
                                                                } else {
                                                                    phi_402_ = 1267650600000000000000000000000f;
                                                                }
                                                                let _e367 = phi_402_;
                                                                local_37 = _e367;
                                                                let _e368 = local_34;
                                                                if (_e368 > 1267650600000000000000000000000f) {
                                                                    let _e370 = local_34;
                                                                    phi_412_ = select(true, false, (_e370 <= 340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_412_ = true;
                                                                }
                                                                let _e374 = phi_412_;
                                                                if _e374 {
                                                                    let _e375 = local_34;
                                                                    if (_e375 < 0.000000000000000000000000000000000000011754944f) {
                                                                        let _e377 = local_34;
                                                                        phi_426_ = select(true, false, (_e377 >= -340282350000000000000000000000000000000f));
                                                                    } else {
                                                                        phi_426_ = true;
                                                                    }
                                                                    let _e381 = phi_426_;
                                                                    let _e382 = local_34;
                                                                    phi_431_ = select(0f, _e382, _e381);
                                                                } else {
                                                                    phi_431_ = 1267650600000000000000000000000f;
                                                                }
                                                                let _e385 = phi_431_;
                                                                let _e386 = local_36;
                                                                let _e387 = local_37;
                                                                phi_434_ = type_18(1u, array<f32, 3>(_e386, _e387, _e385));
                                                            } else {
                                                                phi_434_ = type_18();
                                                            }
                                                            let _e391 = phi_434_;
                                                            let _e392 = local_35;
                                                            phi_436_ = _e391;
                                                            phi_437_ = select(true, false, _e392);
                                                        } else {
                                                            phi_436_ = type_18();
                                                            phi_437_ = true;
                                                        }
                                                        let _e395 = phi_436_;
                                                        let _e397 = phi_437_;
                                                        phi_438_ = _e395;
                                                        phi_439_ = _e397;
                                                    } else {
                                                        phi_438_ = type_18();
                                                        phi_439_ = true;
                                                    }
                                                    let _e399 = phi_438_;
                                                    let _e401 = phi_439_;
                                                    if _e401 {
                                                        phi_444_ = type_18(0u, type_18().member_1);
                                                    } else {
                                                        phi_444_ = _e399;
                                                    }
                                                    let _e406 = phi_444_;
                                                    local_38 = _e406;
                                                    if (bitcast<i32>(_e406.member) != 0i) {
                                                        let _e410 = local_38;
                                                        local_39 = _e410.member_1;
                                                        let _e412 = local_28;
                                                        let _e413 = bitcast<u32>(_e412);
                                                        local_55 = _e413;
                                                        if (_e413 == 0u) {
                                                            phi_690_ = false;
                                                        } else {
                                                            let _e415 = local_55;
                                                            phi_690_ = (_e415 <= 2139095040u);
                                                        }
                                                        let _e418 = phi_690_;
                                                        if _e418 {
                                                            let _e419 = local_39;
                                                            phi_458_ = type_18(1u, _e419);
                                                        } else {
                                                            phi_458_ = type_18(0u, type_18().member_1);
                                                        }
                                                        let _e425 = phi_458_;
                                                        phi_460_ = _e425;
                                                    } else {
                                                        phi_460_ = type_18(0u, type_18().member_1);
                                                    }
                                                    let _e430 = phi_460_;
                                                    local_40 = _e430;
                                                    if (bitcast<i32>(_e430.member) != 0i) {
                                                        let _e434 = local_40;
                                                        local_41 = _e434.member_1;
                                                        let _e436 = local_28;
                                                        let _e437 = bitcast<u32>(_e436);
                                                        local_42 = _e437;
                                                        if (_e437 == 2139095040u) {
                                                            let _e442 = global_2.member.member_4.member_1;
                                                            let _e447 = global_2.member.member_4.member;
                                                            let _e452 = global_2.member.member_4.member_2;
                                                            let _e458 = global_2.member.member_4.member_3;
                                                            phi_534_ = (0.5f * ((((2f * _e442) * _e447) / (_e452 - _e447)) * _e458));
                                                        } else {
                                                            let _e461 = local_42;
                                                            if (_e461 == 0u) {
                                                                phi_497_ = false;
                                                            } else {
                                                                let _e463 = local_42;
                                                                phi_497_ = (_e463 <= 2139095040u);
                                                            }
                                                            let _e466 = phi_497_;
                                                            if _e466 {
                                                                let _e470 = global_2.member.member_4.member_1;
                                                                let _e475 = global_2.member.member_4.member;
                                                                let _e480 = global_2.member.member_4.member_2;
                                                                local_43 = _e480;
                                                                let _e486 = global_2.member.member_4.member_3;
                                                                let _e487 = ((((2f * _e470) * _e475) / (_e480 - _e475)) * _e486);
                                                                local_44 = _e487;
                                                                if (_e487 == 0f) {
                                                                    phi_525_ = 0f;
                                                                } else {
                                                                    let _e489 = local_43;
                                                                    let _e490 = local_28;
                                                                    let _e493 = local_44;
                                                                    phi_525_ = (_e493 * (1f - (_e489 / _e490)));
                                                                }
                                                                let _e496 = phi_525_;
                                                                phi_526_ = _e496;
                                                            } else {
                                                                phi_526_ = _e97;
                                                            }
                                                            let _e498 = phi_526_;
                                                            local_45 = _e498;
                                                            if (_e498 < 0f) {
                                                                let _e500 = local_45;
                                                                phi_532_ = -(_e500);
                                                            } else {
                                                                phi_532_ = _e498;
                                                            }
                                                            let _e503 = phi_532_;
                                                            phi_534_ = (0.5f * _e503);
                                                        }
                                                        let _e506 = phi_534_;
                                                        let _e510 = select(_e506, 0f, ((bitcast<u32>(_e506) & 2147483647u) > 2139095040u));
                                                        local_59 = _e510;
                                                        if !((_e510 == _e510)) {
                                                            phi_701_ = true;
                                                        } else {
                                                            let _e513 = local_10;
                                                            let _e514 = local_59;
                                                            phi_701_ = (_e513 <= _e514);
                                                        }
                                                        let _e517 = phi_701_;
                                                        let _e518 = local_10;
                                                        let _e519 = local_59;
                                                        let _e520 = select(_e519, _e518, _e517);
                                                        local_60 = _e520;
                                                        let _e521 = local_28;
                                                        let _e522 = local_12;
                                                        if (_e521 > _e522) {
                                                            let _e524 = local_60;
                                                            let _e525 = local_60;
                                                            if !((_e524 == _e525)) {
                                                                phi_716_ = true;
                                                            } else {
                                                                let _e528 = local_58;
                                                                let _e529 = local_60;
                                                                phi_716_ = (_e528 <= _e529);
                                                            }
                                                            let _e532 = phi_716_;
                                                            let _e533 = local_58;
                                                            let _e534 = local_60;
                                                            phi_549_ = select(_e534, _e533, _e532);
                                                        } else {
                                                            phi_549_ = _e520;
                                                        }
                                                        let _e537 = phi_549_;
                                                        let _e538 = (_e537 + 0.5f);
                                                        let _e539 = local_23;
                                                        let _e540 = local_23;
                                                        let _e542 = local_18;
                                                        let _e543 = local_18;
                                                        let _e547 = (_e538 * _e538);
                                                        local_46 = _e547;
                                                        if (f32(((_e539 * _e540) + (_e542 * _e543))) <= _e547) {
                                                            let _e549 = local_46;
                                                            let _e550 = (1f / _e549);
                                                            let _e551 = local_41;
                                                            let _e554 = local_25;
                                                            let _e557 = local_41;
                                                            let _e560 = local_25;
                                                            let _e563 = local_41;
                                                            let _e566 = local_25;
                                                            let _e570 = local_24;
                                                            phi_578_ = (_e570 + _e550);
                                                            phi_579_ = array<f32, 3>((_e554[0] + (_e550 * _e551[0])), (_e560[1] + (_e550 * _e557[1])), (_e566[2] + (_e550 * _e563[2])));
                                                        } else {
                                                            phi_578_ = _e258;
                                                            phi_579_ = _e260;
                                                        }
                                                        let _e573 = phi_578_;
                                                        let _e575 = phi_579_;
                                                        phi_580_ = _e573;
                                                        phi_581_ = _e575;
                                                    } else {
                                                        phi_580_ = _e258;
                                                        phi_581_ = _e260;
                                                    }
                                                    let _e577 = phi_580_;
                                                    let _e579 = phi_581_;
                                                    phi_582_ = _e577;
                                                    phi_583_ = _e579;
                                                } else {
                                                    phi_582_ = _e258;
                                                    phi_583_ = _e260;
                                                }
                                                let _e581 = phi_582_;
                                                let _e583 = phi_583_;
                                                phi_584_ = _e581;
                                                phi_585_ = _e583;
                                            } else {
                                                phi_584_ = _e258;
                                                phi_585_ = _e260;
                                            }
                                            let _e585 = phi_584_;
                                            let _e587 = phi_585_;
                                            let _e588 = local_23;
                                            phi_587_ = (_e588 + 1i);
                                            phi_588_ = _e585;
                                            phi_589_ = _e587;
                                        } else {
                                            phi_587_ = i32();
                                            phi_588_ = f32();
                                            phi_589_ = array<f32, 3>();
                                        }
                                        let _e591 = phi_587_;
                                        let _e593 = phi_588_;
                                        let _e595 = phi_589_;
                                        phi_591_ = _e591;
                                        phi_592_ = _e593;
                                        phi_593_ = _e595;
                                        phi_594_ = _e269;
                                    } else {
                                        phi_591_ = i32();
                                        phi_592_ = f32();
                                        phi_593_ = array<f32, 3>();
                                        phi_594_ = false;
                                    }
                                    let _e597 = phi_591_;
                                    let _e599 = phi_592_;
                                    let _e601 = phi_593_;
                                    let _e603 = phi_594_;
                                    phi_248_ = _e597;
                                    phi_251_ = _e599;
                                    phi_253_ = _e601;
                                    phi_596_ = _e603;
                                } else {
                                    phi_248_ = i32();
                                    phi_251_ = f32();
                                    phi_253_ = array<f32, 3>();
                                    phi_596_ = false;
                                }
                                let _e605 = phi_248_;
                                let _e607 = phi_251_;
                                let _e609 = phi_253_;
                                let _e611 = phi_596_;
                                local_47 = _e611;
                                continue;
                                continuing {
                                    let _e612 = local_47;
                                    phi_247_ = _e605;
                                    phi_250_ = _e607;
                                    phi_252_ = _e609;
                                    phi_721_ = _e241;
                                    break if !(_e612);
                                }
                            }
                            let _e615 = phi_721_;
                            phi_776_ = _e615;
                            if _e615 {
                                break;
                            }
                            let _e616 = local_18;
                            phi_777_ = _e615;
                            phi_231_ = (_e616 + 1i);
                            let _e737 = local_61;
                            phi_234_ = _e737;
                            let _e740 = local_62;
                            phi_236_ = _e740;
                        } else {
                            phi_777_ = _e241;
                            phi_231_ = i32();
                            phi_234_ = f32();
                            phi_236_ = array<f32, 3>();
                        }
                        let _e619 = phi_777_;
                        let _e621 = phi_231_;
                        let _e623 = phi_234_;
                        let _e625 = phi_236_;
                        continue;
                        continuing {
                            let _e626 = local_21;
                            phi_762_ = _e619;
                            phi_230_ = _e621;
                            phi_233_ = _e623;
                            phi_235_ = _e625;
                            phi_776_ = _e619;
                            break if !(_e626);
                        }
                    }
                    let _e629 = phi_776_;
                    if _e629 {
                        break;
                    }
                    let _e630 = local_19;
                    if (_e630 > 0f) {
                        let _e632 = local_19;
                        phi_612_ = (1f / _e632);
                    } else {
                        phi_612_ = 0f;
                    }
                    let _e635 = phi_612_;
                    local_48 = _e635;
                    let _e636 = local_11;
                    let _e637 = (3u * _e636);
                    local_49 = _e637;
                    let _e638 = local_20;
                    local_50 = bitcast<u32>((_e638[0] * _e635));
                    let _e642 = local_3;
                    if (_e637 < _e642) {
                    } else {
                        break;
                    }
                    let _e644 = local_49;
                    let _e647 = local_50;
                    global_5.member[_e644] = _e647;
                    let _e648 = local_49;
                    let _e649 = (_e648 + 1u);
                    local_51 = _e649;
                    let _e650 = local_20;
                    let _e652 = local_48;
                    local_52 = bitcast<u32>((_e650[1] * _e652));
                    let _e655 = local_3;
                    if (_e649 < _e655) {
                    } else {
                        break;
                    }
                    let _e657 = local_51;
                    let _e660 = local_52;
                    global_5.member[_e657] = _e660;
                    let _e661 = local_49;
                    let _e662 = (_e661 + 2u);
                    local_53 = _e662;
                    let _e663 = local_20;
                    let _e665 = local_48;
                    local_54 = bitcast<u32>((_e663[2] * _e665));
                    let _e668 = local_3;
                    if (_e662 < _e668) {
                    } else {
                        break;
                    }
                    let _e670 = local_53;
                    let _e673 = local_54;
                    global_5.member[_e670] = _e673;
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
