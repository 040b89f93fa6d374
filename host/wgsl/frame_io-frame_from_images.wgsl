struct type_6 {
    member: array<u32>,
}

struct type_14 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_15 {
    member: type_14,
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
var<immediate> global_7: type_15;
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
    var local_11: u32;
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
    var local_23: u32;
    var local_24: u32;
    var local_25: f32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: f32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: f32;
    var local_34: u32;
    var local_35: f32;
    var local_36: u32;
    var local_37: f32;
    var local_38: u32;
    var local_39: array<f32, 3>;
    var local_40: u32;
    var local_41: f32;
    var local_42: u32;
    var local_43: bool;
    var local_44: f32;
    var local_45: bool;
    var local_46: f32;
    var local_47: f32;
    var local_48: f32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: u32;
    var local_57: u32;
    var local_58: f32;
    var local_59: f32;
    var local_60: f32;
    var local_61: f32;
    var local_62: f32;
    var local_63: f32;
    var phi_115_: u32;
    var phi_184_: f32;
    var phi_185_: f32;
    var phi_186_: f32;
    var phi_187_: f32;
    var phi_188_: bool;
    var phi_227_: f32;
    var phi_228_: f32;
    var phi_229_: f32;
    var phi_230_: f32;
    var phi_231_: bool;
    var phi_269_: f32;
    var phi_270_: f32;
    var phi_271_: f32;
    var phi_272_: f32;
    var phi_273_: bool;
    var phi_335_: f32;
    var phi_350_: f32;
    var phi_351_: f32;
    var phi_352_: f32;
    var phi_353_: f32;
    var phi_354_: bool;
    var phi_376_: f32;
    var phi_391_: f32;
    var phi_392_: f32;
    var phi_393_: f32;
    var phi_394_: f32;
    var phi_395_: bool;
    var phi_417_: f32;
    var phi_432_: f32;
    var phi_433_: f32;
    var phi_434_: f32;
    var phi_435_: f32;
    var phi_436_: bool;
    var phi_496_: array<f32, 3>;
    var phi_497_: array<f32, 3>;
    var phi_523_: f32;
    var phi_567_: f32;
    var phi_568_: f32;
    var phi_588_: f32;
    var phi_589_: f32;
    var phi_590_: f32;
    var phi_591_: f32;
    var phi_597_: f32;
    var phi_598_: f32;
    var phi_600_: f32;
    var phi_601_: bool;
    var phi_606_: f32;
    var phi_116_: u32;
    var phi_720_: bool;

    let _e115 = global_8;
    local_62 = bitcast<f32>(_e115);
    let _e117 = global_9;
    let _e118 = bitcast<f32>(_e117);
    local_63 = _e118;
    switch bitcast<i32>(0u) {
        default: {
            let _e120 = global;
            local = _e120;
            let _e121 = global_1;
            let _e122 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = arrayLength((&global_6.member));
            let _e135 = global_7.member.member;
            let _e138 = global_7.member.member_1;
            local_5 = (_e135 * _e138);
            local_6 = (_e122.x * 256u);
            phi_115_ = (_e121.x * 256u);
            loop {
                let _e143 = phi_115_;
                local_7 = _e143;
                let _e144 = local_7;
                let _e145 = local_5;
                let _e146 = (_e144 < _e145);
                local_8 = _e146;
                if _e146 {
                    let _e147 = local_7;
                    let _e148 = local;
                    let _e149 = (_e147 + _e148);
                    local_9 = _e149;
                    let _e150 = local_5;
                    if (_e149 < _e150) {
                        let _e154 = global_7.member.member_2;
                        local_10 = _e154;
                        if (_e154 == 1u) {
                            let _e156 = local_9;
                            let _e157 = local_1;
                            if (_e156 < _e157) {
                            } else {
                                phi_720_ = true;
                                break;
                            }
                            let _e159 = local_9;
                            let _e162 = global_4.member[_e159];
                            local_11 = _e162;
                            let _e163 = (_e162 & 2047u);
                            let _e166 = ((_e163 >> bitcast<u32>(6u)) & 31u);
                            local_12 = _e166;
                            local_13 = (_e163 & 63u);
                            if (_e166 == 0u) {
                                let _e169 = local_13;
                                phi_186_ = (f32(_e169) * 0.0000009536743f);
                                phi_187_ = f32();
                                phi_188_ = true;
                            } else {
                                let _e172 = local_12;
                                let _e173 = (_e172 == 31u);
                                if _e173 {
                                    let _e174 = local_13;
                                    phi_184_ = bitcast<f32>((2139095040u | (_e174 << bitcast<u32>(17u))));
                                    phi_185_ = f32();
                                } else {
                                    let _e179 = local_12;
                                    let _e183 = local_13;
                                    phi_184_ = f32();
                                    phi_185_ = bitcast<f32>((((_e179 + 112u) << bitcast<u32>(23i)) | (_e183 << bitcast<u32>(17u))));
                                }
                                let _e189 = phi_184_;
                                let _e191 = phi_185_;
                                phi_186_ = _e189;
                                phi_187_ = _e191;
                                phi_188_ = _e173;
                            }
                            let _e193 = phi_186_;
                            let _e195 = phi_187_;
                            let _e197 = phi_188_;
                            local_58 = select(_e195, _e193, _e197);
                            let _e199 = local_11;
                            let _e202 = ((_e199 >> bitcast<u32>(11i)) & 2047u);
                            let _e205 = ((_e202 >> bitcast<u32>(6u)) & 31u);
                            local_14 = _e205;
                            local_15 = (_e202 & 63u);
                            if (_e205 == 0u) {
                                let _e208 = local_15;
                                phi_229_ = (f32(_e208) * 0.0000009536743f);
                                phi_230_ = f32();
                                phi_231_ = true;
                            } else {
                                let _e211 = local_14;
                                let _e212 = (_e211 == 31u);
                                if _e212 {
                                    let _e213 = local_15;
                                    phi_227_ = bitcast<f32>((2139095040u | (_e213 << bitcast<u32>(17u))));
                                    phi_228_ = f32();
                                } else {
                                    let _e218 = local_14;
                                    let _e222 = local_15;
                                    phi_227_ = f32();
                                    phi_228_ = bitcast<f32>((((_e218 + 112u) << bitcast<u32>(23i)) | (_e222 << bitcast<u32>(17u))));
                                }
                                let _e228 = phi_227_;
                                let _e230 = phi_228_;
                                phi_229_ = _e228;
                                phi_230_ = _e230;
                                phi_231_ = _e212;
                            }
                            let _e232 = phi_229_;
                            let _e234 = phi_230_;
                            let _e236 = phi_231_;
                            local_59 = select(_e234, _e232, _e236);
                            let _e238 = local_11;
                            let _e240 = (_e238 >> bitcast<u32>(22i));
                            let _e243 = ((_e240 >> bitcast<u32>(5u)) & 31u);
                            local_16 = _e243;
                            local_17 = (_e240 & 31u);
                            if (_e243 == 0u) {
                                let _e246 = local_17;
                                phi_271_ = (f32(_e246) * 0.0000019073486f);
                                phi_272_ = f32();
                                phi_273_ = true;
                            } else {
                                let _e249 = local_16;
                                let _e250 = (_e249 == 31u);
                                if _e250 {
                                    let _e251 = local_17;
                                    phi_269_ = bitcast<f32>((2139095040u | (_e251 << bitcast<u32>(18u))));
                                    phi_270_ = f32();
                                } else {
                                    let _e256 = local_16;
                                    let _e260 = local_17;
                                    phi_269_ = f32();
                                    phi_270_ = bitcast<f32>((((_e256 + 112u) << bitcast<u32>(23i)) | (_e260 << bitcast<u32>(18u))));
                                }
                                let _e266 = phi_269_;
                                let _e268 = phi_270_;
                                phi_271_ = _e266;
                                phi_272_ = _e268;
                                phi_273_ = _e250;
                            }
                            let _e270 = phi_271_;
                            let _e272 = phi_272_;
                            let _e274 = phi_273_;
                            let _e276 = local_58;
                            let _e277 = local_59;
                            phi_497_ = array<f32, 3>(_e276, _e277, select(_e272, _e270, _e274));
                        } else {
                            let _e279 = local_10;
                            if (_e279 == 2u) {
                                let _e281 = local_9;
                                let _e282 = (2u * _e281);
                                local_18 = _e282;
                                let _e283 = local_1;
                                if (_e282 < _e283) {
                                } else {
                                    phi_720_ = true;
                                    break;
                                }
                                let _e285 = local_18;
                                let _e288 = global_4.member[_e285];
                                local_19 = _e288;
                                let _e289 = local_18;
                                let _e290 = (_e289 + 1u);
                                local_20 = _e290;
                                let _e291 = local_1;
                                if (_e290 < _e291) {
                                } else {
                                    phi_720_ = true;
                                    break;
                                }
                                let _e293 = local_20;
                                let _e296 = global_4.member[_e293];
                                local_21 = _e296;
                                let _e297 = local_19;
                                let _e298 = (_e297 & 65535u);
                                local_22 = ((_e298 & 32768u) << bitcast<u32>(16i));
                                let _e304 = ((_e298 >> bitcast<u32>(10i)) & 31u);
                                local_23 = _e304;
                                local_24 = (_e298 & 1023u);
                                if (_e304 == 0u) {
                                    let _e307 = local_24;
                                    let _e308 = f32(_e307);
                                    local_25 = _e308;
                                    let _e310 = local_22;
                                    if (_e310 == 0u) {
                                        phi_335_ = (_e308 * 0.000000059604645f);
                                    } else {
                                        let _e312 = local_25;
                                        phi_335_ = (_e312 * -0.000000059604645f);
                                    }
                                    let _e315 = phi_335_;
                                    phi_352_ = _e315;
                                    phi_353_ = f32();
                                    phi_354_ = true;
                                } else {
                                    let _e316 = local_23;
                                    let _e317 = (_e316 == 31u);
                                    if _e317 {
                                        let _e318 = local_22;
                                        let _e320 = local_24;
                                        phi_350_ = bitcast<f32>(((_e318 | 2139095040u) | (_e320 << bitcast<u32>(13i))));
                                        phi_351_ = f32();
                                    } else {
                                        let _e325 = local_23;
                                        let _e329 = local_22;
                                        let _e331 = local_24;
                                        phi_350_ = f32();
                                        phi_351_ = bitcast<f32>(((_e329 | ((_e325 + 112u) << bitcast<u32>(23i))) | (_e331 << bitcast<u32>(13i))));
                                    }
                                    let _e337 = phi_350_;
                                    let _e339 = phi_351_;
                                    phi_352_ = _e337;
                                    phi_353_ = _e339;
                                    phi_354_ = _e317;
                                }
                                let _e341 = phi_352_;
                                let _e343 = phi_353_;
                                let _e345 = phi_354_;
                                local_60 = select(_e343, _e341, _e345);
                                let _e347 = local_19;
                                let _e349 = (_e347 >> bitcast<u32>(16i));
                                local_26 = ((_e349 & 32768u) << bitcast<u32>(16i));
                                let _e355 = ((_e349 >> bitcast<u32>(10i)) & 31u);
                                local_27 = _e355;
                                local_28 = (_e349 & 1023u);
                                if (_e355 == 0u) {
                                    let _e358 = local_28;
                                    let _e359 = f32(_e358);
                                    local_29 = _e359;
                                    let _e361 = local_26;
                                    if (_e361 == 0u) {
                                        phi_376_ = (_e359 * 0.000000059604645f);
                                    } else {
                                        let _e363 = local_29;
                                        phi_376_ = (_e363 * -0.000000059604645f);
                                    }
                                    let _e366 = phi_376_;
                                    phi_393_ = _e366;
                                    phi_394_ = f32();
                                    phi_395_ = true;
                                } else {
                                    let _e367 = local_27;
                                    let _e368 = (_e367 == 31u);
                                    if _e368 {
                                        let _e369 = local_26;
                                        let _e371 = local_28;
                                        phi_391_ = bitcast<f32>(((_e369 | 2139095040u) | (_e371 << bitcast<u32>(13i))));
                                        phi_392_ = f32();
                                    } else {
                                        let _e376 = local_27;
                                        let _e380 = local_26;
                                        let _e382 = local_28;
                                        phi_391_ = f32();
                                        phi_392_ = bitcast<f32>(((_e380 | ((_e376 + 112u) << bitcast<u32>(23i))) | (_e382 << bitcast<u32>(13i))));
                                    }
                                    let _e388 = phi_391_;
                                    let _e390 = phi_392_;
                                    phi_393_ = _e388;
                                    phi_394_ = _e390;
                                    phi_395_ = _e368;
                                }
                                let _e392 = phi_393_;
                                let _e394 = phi_394_;
                                let _e396 = phi_395_;
                                local_61 = select(_e394, _e392, _e396);
                                let _e398 = local_21;
                                let _e399 = (_e398 & 65535u);
                                local_30 = ((_e399 & 32768u) << bitcast<u32>(16i));
                                let _e405 = ((_e399 >> bitcast<u32>(10i)) & 31u);
                                local_31 = _e405;
                                local_32 = (_e399 & 1023u);
                                if (_e405 == 0u) {
                                    let _e408 = local_32;
                                    let _e409 = f32(_e408);
                                    local_33 = _e409;
                                    let _e411 = local_30;
                                    if (_e411 == 0u) {
                                        phi_417_ = (_e409 * 0.000000059604645f);
                                    } else {
                                        let _e413 = local_33;
                                        phi_417_ = (_e413 * -0.000000059604645f);
                                    }
                                    let _e416 = phi_417_;
                                    phi_434_ = _e416;
                                    phi_435_ = f32();
                                    phi_436_ = true;
                                } else {
                                    let _e417 = local_31;
                                    let _e418 = (_e417 == 31u);
                                    if _e418 {
                                        let _e419 = local_30;
                                        let _e421 = local_32;
                                        phi_432_ = bitcast<f32>(((_e419 | 2139095040u) | (_e421 << bitcast<u32>(13i))));
                                        phi_433_ = f32();
                                    } else {
                                        let _e426 = local_31;
                                        let _e430 = local_30;
                                        let _e432 = local_32;
                                        phi_432_ = f32();
                                        phi_433_ = bitcast<f32>(((_e430 | ((_e426 + 112u) << bitcast<u32>(23i))) | (_e432 << bitcast<u32>(13i))));
                                    }
                                    let _e438 = phi_432_;
                                    let _e440 = phi_433_;
                                    phi_434_ = _e438;
                                    phi_435_ = _e440;
                                    phi_436_ = _e418;
                                }
                                let _e442 = phi_434_;
                                let _e444 = phi_435_;
                                let _e446 = phi_436_;
                                let _e448 = local_60;
                                let _e449 = local_61;
                                phi_496_ = array<f32, 3>(_e448, _e449, select(_e444, _e442, _e446));
                            } else {
                                let _e451 = local_9;
                                let _e452 = (4u * _e451);
                                local_34 = _e452;
                                let _e453 = local_1;
                                if (_e452 < _e453) {
                                } else {
                                    phi_720_ = true;
                                    break;
                                }
                                let _e455 = local_34;
                                let _e458 = global_4.member[_e455];
                                local_35 = bitcast<f32>(_e458);
                                let _e460 = local_34;
                                let _e461 = (_e460 + 1u);
                                local_36 = _e461;
                                let _e462 = local_1;
                                if (_e461 < _e462) {
                                } else {
                                    phi_720_ = true;
                                    break;
                                }
                                let _e464 = local_36;
                                let _e467 = global_4.member[_e464];
                                local_37 = bitcast<f32>(_e467);
                                let _e469 = local_34;
                                let _e470 = (_e469 + 2u);
                                local_38 = _e470;
                                let _e471 = local_1;
                                if (_e470 < _e471) {
                                } else {
                                    phi_720_ = true;
                                    break;
                                }
                                let _e473 = local_38;
                                let _e476 = global_4.member[_e473];
                                let _e478 = local_35;
                                let _e479 = local_37;
                                phi_496_ = array<f32, 3>(_e478, _e479, bitcast<f32>(_e476));
                            }
                            let _e482 = phi_496_;
                            phi_497_ = _e482;
                        }
                        let _e484 = phi_497_;
                        local_39 = _e484;
                        let _e485 = local_9;
                        let _e486 = local_2;
                        if (_e485 < _e486) {
                        } else {
                            phi_720_ = true;
                            break;
                        }
                        let _e488 = local_9;
                        let _e491 = global_3.member[_e488];
                        local_40 = _e491;
                        let _e494 = global_7.member.member_7;
                        if (_e494 == 1u) {
                            let _e496 = local_40;
                            phi_523_ = (f32((_e496 & 16777215u)) * 0.00000005960465f);
                        } else {
                            let _e500 = local_40;
                            phi_523_ = bitcast<f32>(_e500);
                        }
                        let _e503 = phi_523_;
                        local_41 = _e503;
                        let _e506 = global_7.member.member_3;
                        local_42 = _e506;
                        if (_e506 == 0u) {
                            phi_606_ = _e503;
                        } else {
                            let _e508 = local_41;
                            if (_e508 >= 0f) {
                                let _e510 = local_41;
                                let _e511 = (_e510 <= 1f);
                                local_43 = _e511;
                                if _e511 {
                                    let _e514 = global_7.member.member_5;
                                    local_44 = _e514;
                                    let _e515 = local_63;
                                    local_45 = (_e514 == _e515);
                                    let _e517 = local_42;
                                    if (_e517 == 1u) {
                                        let _e519 = local_45;
                                        if _e519 {
                                            let _e522 = global_7.member.member_4;
                                            let _e523 = local_41;
                                            phi_567_ = (1f - _e523);
                                            phi_568_ = _e522;
                                        } else {
                                            let _e527 = global_7.member.member_4;
                                            let _e528 = local_44;
                                            let _e530 = local_44;
                                            let _e532 = local_41;
                                            let _e534 = local_44;
                                            phi_567_ = (_e534 - (_e532 * (_e530 - _e527)));
                                            phi_568_ = (_e527 * _e528);
                                        }
                                        let _e537 = phi_567_;
                                        let _e539 = phi_568_;
                                        phi_590_ = _e537;
                                        phi_591_ = _e539;
                                    } else {
                                        let _e540 = local_45;
                                        if _e540 {
                                            let _e543 = global_7.member.member_4;
                                            phi_588_ = _e503;
                                            phi_589_ = _e543;
                                        } else {
                                            let _e546 = global_7.member.member_4;
                                            let _e547 = local_44;
                                            let _e549 = local_44;
                                            let _e551 = local_41;
                                            phi_588_ = (_e546 + (_e551 * (_e549 - _e546)));
                                            phi_589_ = (_e546 * _e547);
                                        }
                                        let _e555 = phi_588_;
                                        let _e557 = phi_589_;
                                        phi_590_ = _e555;
                                        phi_591_ = _e557;
                                    }
                                    let _e559 = phi_590_;
                                    let _e561 = phi_591_;
                                    local_46 = _e559;
                                    local_47 = _e561;
                                    if (_e559 <= 0f) {
                                        phi_597_ = _e118;
                                    } else {
                                        let _e563 = local_47;
                                        let _e564 = local_46;
                                        phi_597_ = (_e563 / _e564);
                                    }
                                    let _e567 = phi_597_;
                                    phi_598_ = _e567;
                                } else {
                                    phi_598_ = f32();
                                }
                                let _e569 = phi_598_;
                                let _e570 = local_43;
                                phi_600_ = _e569;
                                phi_601_ = select(true, false, _e570);
                            } else {
                                phi_600_ = f32();
                                phi_601_ = true;
                            }
                            let _e573 = phi_600_;
                            let _e575 = phi_601_;
                            let _e576 = local_62;
                            phi_606_ = select(_e573, _e576, _e575);
                        }
                        let _e579 = phi_606_;
                        local_48 = _e579;
                        let _e580 = local_9;
                        let _e581 = (5u * _e580);
                        local_49 = _e581;
                        let _e582 = local_39;
                        local_50 = bitcast<u32>(_e582[0]);
                        let _e585 = local_3;
                        if (_e581 < _e585) {
                        } else {
                            phi_720_ = true;
                            break;
                        }
                        let _e587 = local_49;
                        let _e590 = local_50;
                        global_5.member[_e587] = _e590;
                        let _e591 = local_49;
                        let _e592 = (_e591 + 1u);
                        local_51 = _e592;
                        let _e593 = local_39;
                        local_52 = bitcast<u32>(_e593[1]);
                        let _e596 = local_3;
                        if (_e592 < _e596) {
                        } else {
                            phi_720_ = true;
                            break;
                        }
                        let _e598 = local_51;
                        let _e601 = local_52;
                        global_5.member[_e598] = _e601;
                        let _e602 = local_49;
                        let _e603 = (_e602 + 2u);
                        local_53 = _e603;
                        let _e604 = local_39;
                        local_54 = bitcast<u32>(_e604[2]);
                        let _e607 = local_3;
                        if (_e603 < _e607) {
                        } else {
                            phi_720_ = true;
                            break;
                        }
                        let _e609 = local_53;
                        let _e612 = local_54;
                        global_5.member[_e609] = _e612;
                        let _e613 = local_49;
                        let _e614 = (_e613 + 3u);
                        local_55 = _e614;
                        let _e615 = local_48;
                        local_56 = bitcast<u32>(_e615);
                        let _e617 = local_3;
                        if (_e614 < _e617) {
                        } else {
                            phi_720_ = true;
                            break;
                        }
                        let _e619 = local_55;
                        let _e622 = local_56;
                        global_5.member[_e619] = _e622;
                        let _e623 = local_49;
                        let _e624 = (_e623 + 4u);
                        local_57 = _e624;
                        let _e625 = local_3;
                        if (_e624 < _e625) {
                        } else {
                            phi_720_ = true;
                            break;
                        }
                        let _e627 = local_57;
                        global_5.member[_e627] = 1065353216u;
                        let _e630 = local_9;
                        let _e631 = local_4;
                        if (_e630 < _e631) {
                        } else {
                            phi_720_ = true;
                            break;
                        }
                        let _e633 = local_9;
                        global_6.member[_e633] = 1u;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e636 = local_7;
                    let _e637 = local_6;
                    phi_116_ = (_e636 + _e637);
                } else {
                    phi_116_ = u32();
                }
                let _e640 = phi_116_;
                continue;
                continuing {
                    let _e641 = local_8;
                    phi_115_ = _e640;
                    phi_720_ = false;
                    break if !(_e641);
                }
            }
            let _e644 = phi_720_;
            if _e644 {
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
