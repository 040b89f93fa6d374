struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_13 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_14 {
    member: type_13,
    member_1: type_5,
    member_2: f32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
}

struct type_15 {
    member: type_14,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_15;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_7;
var<private> global_8: u32 = 2143289344u;
var<private> global_9: u32 = 4286578688u;
var<private> global_10: u32 = 2139095040u;

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
    var local_10: bool;
    var local_11: f32;
    var local_12: u32;
    var local_13: f32;
    var local_14: u32;
    var local_15: bool;
    var local_16: f32;
    var local_17: bool;
    var local_18: f32;
    var local_19: f32;
    var local_20: f32;
    var local_21: u32;
    var local_22: bool;
    var local_23: f32;
    var local_24: u32;
    var local_25: bool;
    var local_26: bool;
    var local_27: f32;
    var local_28: bool;
    var local_29: f32;
    var local_30: f32;
    var local_31: f32;
    var local_32: bool;
    var local_33: bool;
    var local_34: f32;
    var local_35: bool;
    var local_36: u32;
    var local_37: u32;
    var local_38: f32;
    var local_39: u32;
    var local_40: u32;
    var local_41: f32;
    var local_42: f32;
    var phi_105_: u32;
    var phi_199_: f32;
    var phi_243_: f32;
    var phi_244_: f32;
    var phi_264_: f32;
    var phi_265_: f32;
    var phi_266_: f32;
    var phi_267_: f32;
    var phi_273_: f32;
    var phi_274_: f32;
    var phi_276_: f32;
    var phi_277_: bool;
    var phi_282_: f32;
    var phi_284_: bool;
    var phi_303_: bool;
    var phi_304_: bool;
    var phi_350_: f32;
    var phi_394_: f32;
    var phi_395_: f32;
    var phi_415_: f32;
    var phi_416_: f32;
    var phi_417_: f32;
    var phi_418_: f32;
    var phi_424_: f32;
    var phi_425_: f32;
    var phi_427_: f32;
    var phi_428_: bool;
    var phi_433_: f32;
    var phi_483_: f32;
    var phi_503_: f32;
    var phi_504_: f32;
    var phi_505_: f32;
    var phi_507_: f32;
    var phi_508_: bool;
    var phi_513_: f32;
    var phi_514_: f32;
    var phi_541_: u32;
    var phi_542_: u32;
    var phi_564_: f32;
    var phi_570_: f32;
    var phi_576_: f32;
    var phi_593_: f32;
    var phi_594_: f32;
    var phi_595_: f32;
    var phi_597_: f32;
    var phi_598_: bool;
    var phi_599_: f32;
    var phi_600_: bool;
    var phi_605_: f32;
    var phi_606_: f32;
    var phi_106_: u32;
    var phi_659_: bool;

    let _e79 = global_8;
    local_41 = bitcast<f32>(_e79);
    let _e81 = global_9;
    let _e83 = global_10;
    let _e84 = bitcast<f32>(_e83);
    local_42 = _e84;
    switch bitcast<i32>(0u) {
        default: {
            let _e86 = global;
            local = _e86;
            let _e87 = global_1;
            let _e88 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e102 = global_3.member.member.member;
            let _e106 = global_3.member.member.member_1;
            local_5 = (_e102 * _e106);
            local_6 = (_e88.x * 256u);
            phi_105_ = (_e87.x * 256u);
            loop {
                let _e111 = phi_105_;
                local_7 = _e111;
                let _e112 = local_7;
                let _e113 = local_5;
                let _e114 = (_e112 < _e113);
                local_8 = _e114;
                if _e114 {
                    let _e115 = local_7;
                    let _e116 = local;
                    let _e117 = (_e115 + _e116);
                    local_9 = _e117;
                    let _e118 = local_5;
                    if (_e117 < _e118) {
                        let _e122 = global_3.member.member_3;
                        if (_e122 == 0u) {
                            phi_606_ = bitcast<f32>(_e81);
                        } else {
                            let _e126 = global_3.member.member_4;
                            if (_e126 == 0u) {
                                phi_304_ = true;
                            } else {
                                let _e128 = local_9;
                                let _e129 = local_2;
                                if (_e128 < _e129) {
                                } else {
                                    phi_659_ = true;
                                    break;
                                }
                                let _e131 = local_9;
                                let _e134 = global_5.member[_e131];
                                if (_e134 == 0u) {
                                    let _e136 = local_9;
                                    let _e137 = local_3;
                                    let _e138 = (_e136 < _e137);
                                    local_10 = _e138;
                                    if _e138 {
                                    } else {
                                        phi_659_ = true;
                                        break;
                                    }
                                    let _e139 = local_9;
                                    let _e142 = global_6.member[_e139];
                                    local_11 = bitcast<f32>(_e142);
                                    let _e144 = local_9;
                                    let _e145 = local_1;
                                    if (_e144 < _e145) {
                                    } else {
                                        phi_659_ = true;
                                        break;
                                    }
                                    let _e147 = local_9;
                                    let _e150 = global_4.member[_e147];
                                    local_12 = _e150;
                                    let _e151 = local_11;
                                    if ((bitcast<u32>(_e151) & 2139095040u) != 2139095040u) {
                                        let _e158 = global_3.member.member.member_7;
                                        if (_e158 == 1u) {
                                            let _e160 = local_12;
                                            phi_199_ = (f32((_e160 & 16777215u)) * 0.00000005960465f);
                                        } else {
                                            let _e164 = local_12;
                                            phi_199_ = bitcast<f32>(_e164);
                                        }
                                        let _e167 = phi_199_;
                                        local_13 = _e167;
                                        let _e171 = global_3.member.member.member_3;
                                        local_14 = _e171;
                                        if (_e171 == 0u) {
                                            phi_282_ = _e167;
                                        } else {
                                            let _e173 = local_13;
                                            if (_e173 >= 0f) {
                                                let _e175 = local_13;
                                                let _e176 = (_e175 <= 1f);
                                                local_15 = _e176;
                                                if _e176 {
                                                    let _e180 = global_3.member.member.member_5;
                                                    local_16 = _e180;
                                                    let _e181 = local_42;
                                                    local_17 = (_e180 == _e181);
                                                    let _e183 = local_14;
                                                    if (_e183 == 1u) {
                                                        let _e185 = local_17;
                                                        if _e185 {
                                                            let _e189 = global_3.member.member.member_4;
                                                            let _e190 = local_13;
                                                            phi_243_ = (1f - _e190);
                                                            phi_244_ = _e189;
                                                        } else {
                                                            let _e195 = global_3.member.member.member_4;
                                                            let _e196 = local_16;
                                                            let _e198 = local_16;
                                                            let _e200 = local_13;
                                                            let _e202 = local_16;
                                                            phi_243_ = (_e202 - (_e200 * (_e198 - _e195)));
                                                            phi_244_ = (_e195 * _e196);
                                                        }
                                                        let _e205 = phi_243_;
                                                        let _e207 = phi_244_;
                                                        phi_266_ = _e205;
                                                        phi_267_ = _e207;
                                                    } else {
                                                        let _e208 = local_17;
                                                        if _e208 {
                                                            let _e212 = global_3.member.member.member_4;
                                                            phi_264_ = _e167;
                                                            phi_265_ = _e212;
                                                        } else {
                                                            let _e216 = global_3.member.member.member_4;
                                                            let _e217 = local_16;
                                                            let _e219 = local_16;
                                                            let _e221 = local_13;
                                                            phi_264_ = (_e216 + (_e221 * (_e219 - _e216)));
                                                            phi_265_ = (_e216 * _e217);
                                                        }
                                                        let _e225 = phi_264_;
                                                        let _e227 = phi_265_;
                                                        phi_266_ = _e225;
                                                        phi_267_ = _e227;
                                                    }
                                                    let _e229 = phi_266_;
                                                    let _e231 = phi_267_;
                                                    local_18 = _e229;
                                                    local_19 = _e231;
                                                    if (_e229 <= 0f) {
                                                        phi_273_ = _e84;
                                                    } else {
                                                        let _e233 = local_19;
                                                        let _e234 = local_18;
                                                        phi_273_ = (_e233 / _e234);
                                                    }
                                                    let _e237 = phi_273_;
                                                    phi_274_ = _e237;
                                                } else {
                                                    phi_274_ = f32();
                                                }
                                                let _e239 = phi_274_;
                                                let _e240 = local_15;
                                                phi_276_ = _e239;
                                                phi_277_ = select(true, false, _e240);
                                            } else {
                                                phi_276_ = f32();
                                                phi_277_ = true;
                                            }
                                            let _e243 = phi_276_;
                                            let _e245 = phi_277_;
                                            let _e246 = local_41;
                                            phi_282_ = select(_e243, _e246, _e245);
                                        }
                                        let _e249 = phi_282_;
                                        let _e250 = local_11;
                                        phi_284_ = (_e250 == _e249);
                                    } else {
                                        phi_284_ = false;
                                    }
                                    let _e253 = phi_284_;
                                    if _e253 {
                                    } else {
                                        let _e254 = local_10;
                                        if _e254 {
                                        } else {
                                            phi_659_ = true;
                                            break;
                                        }
                                        global_6.member[_e139] = 2139095040u;
                                    }
                                    phi_303_ = _e253;
                                } else {
                                    phi_303_ = true;
                                }
                                let _e256 = phi_303_;
                                phi_304_ = _e256;
                            }
                            let _e258 = phi_304_;
                            if _e258 {
                                let _e259 = local_9;
                                let _e260 = local_3;
                                if (_e259 < _e260) {
                                } else {
                                    phi_659_ = true;
                                    break;
                                }
                                let _e262 = local_9;
                                let _e265 = global_6.member[_e262];
                                let _e266 = bitcast<f32>(_e265);
                                local_20 = _e266;
                                let _e267 = local_9;
                                let _e268 = local_1;
                                if (_e267 < _e268) {
                                } else {
                                    phi_659_ = true;
                                    break;
                                }
                                let _e270 = local_9;
                                let _e273 = global_4.member[_e270];
                                local_21 = _e273;
                                let _e277 = global_3.member.member.member_7;
                                let _e278 = (_e277 == 1u);
                                local_22 = _e278;
                                if _e278 {
                                    let _e279 = local_21;
                                    phi_350_ = (f32((_e279 & 16777215u)) * 0.00000005960465f);
                                } else {
                                    let _e283 = local_21;
                                    phi_350_ = bitcast<f32>(_e283);
                                }
                                let _e286 = phi_350_;
                                local_23 = _e286;
                                let _e290 = global_3.member.member.member_3;
                                local_24 = _e290;
                                let _e291 = (_e290 == 0u);
                                local_25 = _e291;
                                if _e291 {
                                    phi_433_ = _e286;
                                } else {
                                    let _e292 = local_23;
                                    if (_e292 >= 0f) {
                                        let _e294 = local_23;
                                        let _e295 = (_e294 <= 1f);
                                        local_26 = _e295;
                                        if _e295 {
                                            let _e299 = global_3.member.member.member_5;
                                            local_27 = _e299;
                                            let _e300 = local_42;
                                            local_28 = (_e299 == _e300);
                                            let _e302 = local_24;
                                            if (_e302 == 1u) {
                                                let _e304 = local_28;
                                                if _e304 {
                                                    let _e308 = global_3.member.member.member_4;
                                                    let _e309 = local_23;
                                                    phi_394_ = (1f - _e309);
                                                    phi_395_ = _e308;
                                                } else {
                                                    let _e314 = global_3.member.member.member_4;
                                                    let _e315 = local_27;
                                                    let _e317 = local_27;
                                                    let _e319 = local_23;
                                                    let _e321 = local_27;
                                                    phi_394_ = (_e321 - (_e319 * (_e317 - _e314)));
                                                    phi_395_ = (_e314 * _e315);
                                                }
                                                let _e324 = phi_394_;
                                                let _e326 = phi_395_;
                                                phi_417_ = _e324;
                                                phi_418_ = _e326;
                                            } else {
                                                let _e327 = local_28;
                                                if _e327 {
                                                    let _e331 = global_3.member.member.member_4;
                                                    phi_415_ = _e286;
                                                    phi_416_ = _e331;
                                                } else {
                                                    let _e335 = global_3.member.member.member_4;
                                                    let _e336 = local_27;
                                                    let _e338 = local_27;
                                                    let _e340 = local_23;
                                                    phi_415_ = (_e335 + (_e340 * (_e338 - _e335)));
                                                    phi_416_ = (_e335 * _e336);
                                                }
                                                let _e344 = phi_415_;
                                                let _e346 = phi_416_;
                                                phi_417_ = _e344;
                                                phi_418_ = _e346;
                                            }
                                            let _e348 = phi_417_;
                                            let _e350 = phi_418_;
                                            local_29 = _e348;
                                            local_30 = _e350;
                                            if (_e348 <= 0f) {
                                                phi_424_ = _e84;
                                            } else {
                                                let _e352 = local_30;
                                                let _e353 = local_29;
                                                phi_424_ = (_e352 / _e353);
                                            }
                                            let _e356 = phi_424_;
                                            phi_425_ = _e356;
                                        } else {
                                            phi_425_ = f32();
                                        }
                                        let _e358 = phi_425_;
                                        let _e359 = local_26;
                                        phi_427_ = _e358;
                                        phi_428_ = select(true, false, _e359);
                                    } else {
                                        phi_427_ = f32();
                                        phi_428_ = true;
                                    }
                                    let _e362 = phi_427_;
                                    let _e364 = phi_428_;
                                    let _e365 = local_41;
                                    phi_433_ = select(_e362, _e365, _e364);
                                }
                                let _e368 = phi_433_;
                                let _e369 = local_20;
                                if (_e369 == _e368) {
                                    phi_514_ = _e286;
                                } else {
                                    let _e371 = local_25;
                                    if _e371 {
                                        phi_513_ = _e266;
                                    } else {
                                        let _e372 = local_20;
                                        if (_e372 > 0f) {
                                            let _e377 = global_3.member.member.member_5;
                                            local_31 = _e377;
                                            let _e378 = local_20;
                                            let _e379 = (_e378 < _e377);
                                            local_32 = _e379;
                                            if _e379 {
                                                let _e380 = local_31;
                                                let _e381 = local_42;
                                                local_33 = (_e380 == _e381);
                                                let _e383 = local_24;
                                                if (_e383 == 1u) {
                                                    let _e385 = local_33;
                                                    if _e385 {
                                                        let _e389 = global_3.member.member.member_4;
                                                        let _e390 = local_20;
                                                        phi_483_ = (1f - (_e389 / _e390));
                                                    } else {
                                                        let _e396 = global_3.member.member.member_4;
                                                        let _e397 = local_20;
                                                        let _e399 = local_31;
                                                        let _e401 = local_31;
                                                        let _e403 = local_20;
                                                        phi_483_ = ((_e399 * (_e397 - _e396)) / (_e403 * (_e401 - _e396)));
                                                    }
                                                    let _e407 = phi_483_;
                                                    phi_504_ = _e407;
                                                } else {
                                                    let _e408 = local_33;
                                                    if _e408 {
                                                        let _e412 = global_3.member.member.member_4;
                                                        let _e413 = local_20;
                                                        phi_503_ = (_e412 / _e413);
                                                    } else {
                                                        let _e418 = global_3.member.member.member_4;
                                                        let _e419 = local_31;
                                                        let _e420 = local_20;
                                                        let _e423 = local_31;
                                                        let _e425 = local_20;
                                                        phi_503_ = ((_e418 * (_e419 - _e420)) / (_e425 * (_e423 - _e418)));
                                                    }
                                                    let _e429 = phi_503_;
                                                    phi_504_ = _e429;
                                                }
                                                let _e431 = phi_504_;
                                                phi_505_ = _e431;
                                            } else {
                                                phi_505_ = f32();
                                            }
                                            let _e433 = phi_505_;
                                            let _e434 = local_32;
                                            phi_507_ = _e433;
                                            phi_508_ = select(true, false, _e434);
                                        } else {
                                            phi_507_ = f32();
                                            phi_508_ = true;
                                        }
                                        let _e437 = phi_507_;
                                        let _e439 = phi_508_;
                                        let _e440 = local_42;
                                        phi_513_ = select(_e437, _e440, _e439);
                                    }
                                    let _e443 = phi_513_;
                                    phi_514_ = _e443;
                                }
                                let _e445 = phi_514_;
                                local_34 = _e445;
                                if ((bitcast<u32>(_e445) & 2139095040u) != 2139095040u) {
                                    let _e449 = local_23;
                                    if (_e449 >= 0f) {
                                        let _e451 = local_23;
                                        let _e452 = (_e451 <= 1f);
                                        local_35 = _e452;
                                        if _e452 {
                                            let _e453 = local_21;
                                            let _e454 = (_e453 & 16777215u);
                                            local_36 = _e454;
                                            let _e455 = local_22;
                                            if _e455 {
                                                let _e456 = local_34;
                                                let _e457 = local_23;
                                                if (_e456 == _e457) {
                                                    phi_541_ = _e454;
                                                } else {
                                                    let _e459 = local_34;
                                                    let _e461 = ((_e459 * 16777215f) + 0.5f);
                                                    phi_541_ = select(select(u32(_e461), 0u, !((_e461 >= 0f))), 4294967295u, (_e461 > 4294967000f));
                                                }
                                                let _e469 = phi_541_;
                                                phi_542_ = _e469;
                                            } else {
                                                phi_542_ = 0u;
                                            }
                                            let _e471 = phi_542_;
                                            local_37 = _e471;
                                            let _e472 = local_24;
                                            if (_e472 == 2u) {
                                                let _e474 = local_22;
                                                if _e474 {
                                                    let _e475 = local_37;
                                                    let _e476 = local_36;
                                                    let _e478 = local_37;
                                                    let _e479 = local_36;
                                                    let _e480 = select(_e479, _e478, (_e475 < _e476));
                                                    local_40 = _e480;
                                                    if (_e480 < 2u) {
                                                        phi_564_ = 0f;
                                                    } else {
                                                        let _e482 = local_40;
                                                        phi_564_ = (f32((_e482 - 1u)) * 0.00000005960465f);
                                                    }
                                                    let _e487 = phi_564_;
                                                    phi_570_ = _e487;
                                                } else {
                                                    let _e488 = local_34;
                                                    let _e489 = local_23;
                                                    let _e491 = local_34;
                                                    let _e492 = local_23;
                                                    phi_570_ = select(_e492, _e491, (_e488 < _e489));
                                                }
                                                let _e495 = phi_570_;
                                                local_38 = _e495;
                                                if (_e495 > 0f) {
                                                    let _e497 = local_38;
                                                    phi_576_ = -(_e497);
                                                } else {
                                                    phi_576_ = _e84;
                                                }
                                                let _e500 = phi_576_;
                                                phi_594_ = _e500;
                                            } else {
                                                let _e501 = local_22;
                                                if _e501 {
                                                    let _e502 = local_37;
                                                    let _e503 = local_36;
                                                    let _e505 = local_37;
                                                    let _e506 = local_36;
                                                    phi_593_ = (f32((select(_e506, _e505, (_e502 > _e503)) + 1u)) * 0.00000005960465f);
                                                } else {
                                                    let _e511 = local_34;
                                                    let _e512 = local_23;
                                                    let _e514 = local_34;
                                                    let _e515 = local_23;
                                                    phi_593_ = select(_e515, _e514, (_e511 > _e512));
                                                }
                                                let _e518 = phi_593_;
                                                phi_594_ = _e518;
                                            }
                                            let _e520 = phi_594_;
                                            phi_595_ = _e520;
                                        } else {
                                            phi_595_ = f32();
                                        }
                                        let _e522 = phi_595_;
                                        let _e523 = local_35;
                                        phi_597_ = _e522;
                                        phi_598_ = select(true, false, _e523);
                                    } else {
                                        phi_597_ = f32();
                                        phi_598_ = true;
                                    }
                                    let _e526 = phi_597_;
                                    let _e528 = phi_598_;
                                    phi_599_ = _e526;
                                    phi_600_ = _e528;
                                } else {
                                    phi_599_ = f32();
                                    phi_600_ = true;
                                }
                                let _e530 = phi_599_;
                                let _e532 = phi_600_;
                                let _e533 = local_42;
                                phi_605_ = select(_e530, _e533, _e532);
                            } else {
                                phi_605_ = _e84;
                            }
                            let _e536 = phi_605_;
                            phi_606_ = _e536;
                        }
                        let _e538 = phi_606_;
                        local_39 = bitcast<u32>(_e538);
                        let _e540 = local_9;
                        let _e541 = local_4;
                        if (_e540 < _e541) {
                        } else {
                            phi_659_ = true;
                            break;
                        }
                        let _e543 = local_9;
                        let _e546 = local_39;
                        global_7.member[_e543] = _e546;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e547 = local_7;
                    let _e548 = local_6;
                    phi_106_ = (_e547 + _e548);
                } else {
                    phi_106_ = u32();
                }
                let _e551 = phi_106_;
                continue;
                continuing {
                    let _e552 = local_8;
                    phi_105_ = _e551;
                    phi_659_ = false;
                    break if !(_e552);
                }
            }
            let _e555 = phi_659_;
            if _e555 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn peel_renderer_bound(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
