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
    var phi_106_: u32;
    var phi_205_: f32;
    var phi_249_: f32;
    var phi_250_: f32;
    var phi_270_: f32;
    var phi_271_: f32;
    var phi_272_: f32;
    var phi_273_: f32;
    var phi_279_: f32;
    var phi_280_: f32;
    var phi_282_: f32;
    var phi_283_: bool;
    var phi_288_: f32;
    var phi_290_: bool;
    var phi_309_: bool;
    var phi_310_: bool;
    var phi_361_: f32;
    var phi_405_: f32;
    var phi_406_: f32;
    var phi_426_: f32;
    var phi_427_: f32;
    var phi_428_: f32;
    var phi_429_: f32;
    var phi_435_: f32;
    var phi_436_: f32;
    var phi_438_: f32;
    var phi_439_: bool;
    var phi_444_: f32;
    var phi_494_: f32;
    var phi_514_: f32;
    var phi_515_: f32;
    var phi_516_: f32;
    var phi_518_: f32;
    var phi_519_: bool;
    var phi_524_: f32;
    var phi_525_: f32;
    var phi_552_: u32;
    var phi_553_: u32;
    var phi_575_: f32;
    var phi_581_: f32;
    var phi_587_: f32;
    var phi_604_: f32;
    var phi_605_: f32;
    var phi_606_: f32;
    var phi_608_: f32;
    var phi_609_: bool;
    var phi_610_: f32;
    var phi_611_: bool;
    var phi_616_: f32;
    var phi_617_: f32;
    var phi_107_: u32;
    var phi_670_: bool;

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
            phi_106_ = (_e87.x * 256u);
            loop {
                let _e111 = phi_106_;
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
                            phi_617_ = bitcast<f32>(_e81);
                        } else {
                            let _e126 = global_3.member.member_4;
                            if (_e126 == 0u) {
                                phi_310_ = true;
                            } else {
                                let _e128 = local_9;
                                let _e129 = local_2;
                                if (_e128 < _e129) {
                                } else {
                                    phi_670_ = true;
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
                                        phi_670_ = true;
                                        break;
                                    }
                                    let _e139 = local_9;
                                    let _e142 = global_6.member[_e139];
                                    local_11 = bitcast<f32>(_e142);
                                    let _e144 = local_9;
                                    let _e145 = local_1;
                                    if (_e144 < _e145) {
                                    } else {
                                        phi_670_ = true;
                                        break;
                                    }
                                    let _e147 = local_9;
                                    let _e150 = global_4.member[_e147];
                                    local_12 = _e150;
                                    let _e151 = local_11;
                                    if ((bitcast<u32>(_e151) & 2139095040u) != 2139095040u) {
                                        let _e158 = global_3.member.member.member_7;
                                        if (select(3u, 4u, (_e158 == 1u)) == 4u) {
                                            let _e162 = local_12;
                                            phi_205_ = (f32((_e162 & 16777215u)) * 0.00000005960465f);
                                        } else {
                                            let _e166 = local_12;
                                            phi_205_ = bitcast<f32>(_e166);
                                        }
                                        let _e169 = phi_205_;
                                        local_13 = _e169;
                                        let _e173 = global_3.member.member.member_3;
                                        local_14 = _e173;
                                        if (_e173 == 0u) {
                                            phi_288_ = _e169;
                                        } else {
                                            let _e175 = local_13;
                                            if (_e175 >= 0f) {
                                                let _e177 = local_13;
                                                let _e178 = (_e177 <= 1f);
                                                local_15 = _e178;
                                                if _e178 {
                                                    let _e182 = global_3.member.member.member_5;
                                                    local_16 = _e182;
                                                    let _e183 = local_42;
                                                    local_17 = (_e182 == _e183);
                                                    let _e185 = local_14;
                                                    if (_e185 == 1u) {
                                                        let _e187 = local_17;
                                                        if _e187 {
                                                            let _e191 = global_3.member.member.member_4;
                                                            let _e192 = local_13;
                                                            phi_249_ = (1f - _e192);
                                                            phi_250_ = _e191;
                                                        } else {
                                                            let _e197 = global_3.member.member.member_4;
                                                            let _e198 = local_16;
                                                            let _e200 = local_16;
                                                            let _e202 = local_13;
                                                            let _e204 = local_16;
                                                            phi_249_ = (_e204 - (_e202 * (_e200 - _e197)));
                                                            phi_250_ = (_e197 * _e198);
                                                        }
                                                        let _e207 = phi_249_;
                                                        let _e209 = phi_250_;
                                                        phi_272_ = _e207;
                                                        phi_273_ = _e209;
                                                    } else {
                                                        let _e210 = local_17;
                                                        if _e210 {
                                                            let _e214 = global_3.member.member.member_4;
                                                            phi_270_ = _e169;
                                                            phi_271_ = _e214;
                                                        } else {
                                                            let _e218 = global_3.member.member.member_4;
                                                            let _e219 = local_16;
                                                            let _e221 = local_16;
                                                            let _e223 = local_13;
                                                            phi_270_ = (_e218 + (_e223 * (_e221 - _e218)));
                                                            phi_271_ = (_e218 * _e219);
                                                        }
                                                        let _e227 = phi_270_;
                                                        let _e229 = phi_271_;
                                                        phi_272_ = _e227;
                                                        phi_273_ = _e229;
                                                    }
                                                    let _e231 = phi_272_;
                                                    let _e233 = phi_273_;
                                                    local_18 = _e231;
                                                    local_19 = _e233;
                                                    if (_e231 <= 0f) {
                                                        phi_279_ = _e84;
                                                    } else {
                                                        let _e235 = local_19;
                                                        let _e236 = local_18;
                                                        phi_279_ = (_e235 / _e236);
                                                    }
                                                    let _e239 = phi_279_;
                                                    phi_280_ = _e239;
                                                } else {
                                                    phi_280_ = f32();
                                                }
                                                let _e241 = phi_280_;
                                                let _e242 = local_15;
                                                phi_282_ = _e241;
                                                phi_283_ = select(true, false, _e242);
                                            } else {
                                                phi_282_ = f32();
                                                phi_283_ = true;
                                            }
                                            let _e245 = phi_282_;
                                            let _e247 = phi_283_;
                                            let _e248 = local_41;
                                            phi_288_ = select(_e245, _e248, _e247);
                                        }
                                        let _e251 = phi_288_;
                                        let _e252 = local_11;
                                        phi_290_ = (_e252 == _e251);
                                    } else {
                                        phi_290_ = false;
                                    }
                                    let _e255 = phi_290_;
                                    if _e255 {
                                    } else {
                                        let _e256 = local_10;
                                        if _e256 {
                                        } else {
                                            phi_670_ = true;
                                            break;
                                        }
                                        global_6.member[_e139] = 2139095040u;
                                    }
                                    phi_309_ = _e255;
                                } else {
                                    phi_309_ = true;
                                }
                                let _e258 = phi_309_;
                                phi_310_ = _e258;
                            }
                            let _e260 = phi_310_;
                            if _e260 {
                                let _e261 = local_9;
                                let _e262 = local_3;
                                if (_e261 < _e262) {
                                } else {
                                    phi_670_ = true;
                                    break;
                                }
                                let _e264 = local_9;
                                let _e267 = global_6.member[_e264];
                                let _e268 = bitcast<f32>(_e267);
                                local_20 = _e268;
                                let _e269 = local_9;
                                let _e270 = local_1;
                                if (_e269 < _e270) {
                                } else {
                                    phi_670_ = true;
                                    break;
                                }
                                let _e272 = local_9;
                                let _e275 = global_4.member[_e272];
                                local_21 = _e275;
                                let _e279 = global_3.member.member.member_7;
                                let _e280 = (_e279 == 1u);
                                local_22 = _e280;
                                if (select(3u, 4u, _e280) == 4u) {
                                    let _e283 = local_21;
                                    phi_361_ = (f32((_e283 & 16777215u)) * 0.00000005960465f);
                                } else {
                                    let _e287 = local_21;
                                    phi_361_ = bitcast<f32>(_e287);
                                }
                                let _e290 = phi_361_;
                                local_23 = _e290;
                                let _e294 = global_3.member.member.member_3;
                                local_24 = _e294;
                                let _e295 = (_e294 == 0u);
                                local_25 = _e295;
                                if _e295 {
                                    phi_444_ = _e290;
                                } else {
                                    let _e296 = local_23;
                                    if (_e296 >= 0f) {
                                        let _e298 = local_23;
                                        let _e299 = (_e298 <= 1f);
                                        local_26 = _e299;
                                        if _e299 {
                                            let _e303 = global_3.member.member.member_5;
                                            local_27 = _e303;
                                            let _e304 = local_42;
                                            local_28 = (_e303 == _e304);
                                            let _e306 = local_24;
                                            if (_e306 == 1u) {
                                                let _e308 = local_28;
                                                if _e308 {
                                                    let _e312 = global_3.member.member.member_4;
                                                    let _e313 = local_23;
                                                    phi_405_ = (1f - _e313);
                                                    phi_406_ = _e312;
                                                } else {
                                                    let _e318 = global_3.member.member.member_4;
                                                    let _e319 = local_27;
                                                    let _e321 = local_27;
                                                    let _e323 = local_23;
                                                    let _e325 = local_27;
                                                    phi_405_ = (_e325 - (_e323 * (_e321 - _e318)));
                                                    phi_406_ = (_e318 * _e319);
                                                }
                                                let _e328 = phi_405_;
                                                let _e330 = phi_406_;
                                                phi_428_ = _e328;
                                                phi_429_ = _e330;
                                            } else {
                                                let _e331 = local_28;
                                                if _e331 {
                                                    let _e335 = global_3.member.member.member_4;
                                                    phi_426_ = _e290;
                                                    phi_427_ = _e335;
                                                } else {
                                                    let _e339 = global_3.member.member.member_4;
                                                    let _e340 = local_27;
                                                    let _e342 = local_27;
                                                    let _e344 = local_23;
                                                    phi_426_ = (_e339 + (_e344 * (_e342 - _e339)));
                                                    phi_427_ = (_e339 * _e340);
                                                }
                                                let _e348 = phi_426_;
                                                let _e350 = phi_427_;
                                                phi_428_ = _e348;
                                                phi_429_ = _e350;
                                            }
                                            let _e352 = phi_428_;
                                            let _e354 = phi_429_;
                                            local_29 = _e352;
                                            local_30 = _e354;
                                            if (_e352 <= 0f) {
                                                phi_435_ = _e84;
                                            } else {
                                                let _e356 = local_30;
                                                let _e357 = local_29;
                                                phi_435_ = (_e356 / _e357);
                                            }
                                            let _e360 = phi_435_;
                                            phi_436_ = _e360;
                                        } else {
                                            phi_436_ = f32();
                                        }
                                        let _e362 = phi_436_;
                                        let _e363 = local_26;
                                        phi_438_ = _e362;
                                        phi_439_ = select(true, false, _e363);
                                    } else {
                                        phi_438_ = f32();
                                        phi_439_ = true;
                                    }
                                    let _e366 = phi_438_;
                                    let _e368 = phi_439_;
                                    let _e369 = local_41;
                                    phi_444_ = select(_e366, _e369, _e368);
                                }
                                let _e372 = phi_444_;
                                let _e373 = local_20;
                                if (_e373 == _e372) {
                                    phi_525_ = _e290;
                                } else {
                                    let _e375 = local_25;
                                    if _e375 {
                                        phi_524_ = _e268;
                                    } else {
                                        let _e376 = local_20;
                                        if (_e376 > 0f) {
                                            let _e381 = global_3.member.member.member_5;
                                            local_31 = _e381;
                                            let _e382 = local_20;
                                            let _e383 = (_e382 < _e381);
                                            local_32 = _e383;
                                            if _e383 {
                                                let _e384 = local_31;
                                                let _e385 = local_42;
                                                local_33 = (_e384 == _e385);
                                                let _e387 = local_24;
                                                if (_e387 == 1u) {
                                                    let _e389 = local_33;
                                                    if _e389 {
                                                        let _e393 = global_3.member.member.member_4;
                                                        let _e394 = local_20;
                                                        phi_494_ = (1f - (_e393 / _e394));
                                                    } else {
                                                        let _e400 = global_3.member.member.member_4;
                                                        let _e401 = local_20;
                                                        let _e403 = local_31;
                                                        let _e405 = local_31;
                                                        let _e407 = local_20;
                                                        phi_494_ = ((_e403 * (_e401 - _e400)) / (_e407 * (_e405 - _e400)));
                                                    }
                                                    let _e411 = phi_494_;
                                                    phi_515_ = _e411;
                                                } else {
                                                    let _e412 = local_33;
                                                    if _e412 {
                                                        let _e416 = global_3.member.member.member_4;
                                                        let _e417 = local_20;
                                                        phi_514_ = (_e416 / _e417);
                                                    } else {
                                                        let _e422 = global_3.member.member.member_4;
                                                        let _e423 = local_31;
                                                        let _e424 = local_20;
                                                        let _e427 = local_31;
                                                        let _e429 = local_20;
                                                        phi_514_ = ((_e422 * (_e423 - _e424)) / (_e429 * (_e427 - _e422)));
                                                    }
                                                    let _e433 = phi_514_;
                                                    phi_515_ = _e433;
                                                }
                                                let _e435 = phi_515_;
                                                phi_516_ = _e435;
                                            } else {
                                                phi_516_ = f32();
                                            }
                                            let _e437 = phi_516_;
                                            let _e438 = local_32;
                                            phi_518_ = _e437;
                                            phi_519_ = select(true, false, _e438);
                                        } else {
                                            phi_518_ = f32();
                                            phi_519_ = true;
                                        }
                                        let _e441 = phi_518_;
                                        let _e443 = phi_519_;
                                        let _e444 = local_42;
                                        phi_524_ = select(_e441, _e444, _e443);
                                    }
                                    let _e447 = phi_524_;
                                    phi_525_ = _e447;
                                }
                                let _e449 = phi_525_;
                                local_34 = _e449;
                                if ((bitcast<u32>(_e449) & 2139095040u) != 2139095040u) {
                                    let _e453 = local_23;
                                    if (_e453 >= 0f) {
                                        let _e455 = local_23;
                                        let _e456 = (_e455 <= 1f);
                                        local_35 = _e456;
                                        if _e456 {
                                            let _e457 = local_21;
                                            let _e458 = (_e457 & 16777215u);
                                            local_36 = _e458;
                                            let _e459 = local_22;
                                            if _e459 {
                                                let _e460 = local_34;
                                                let _e461 = local_23;
                                                if (_e460 == _e461) {
                                                    phi_552_ = _e458;
                                                } else {
                                                    let _e463 = local_34;
                                                    let _e465 = ((_e463 * 16777215f) + 0.5f);
                                                    phi_552_ = select(select(u32(_e465), 0u, !((_e465 >= 0f))), 4294967295u, (_e465 > 4294967000f));
                                                }
                                                let _e473 = phi_552_;
                                                phi_553_ = _e473;
                                            } else {
                                                phi_553_ = 0u;
                                            }
                                            let _e475 = phi_553_;
                                            local_37 = _e475;
                                            let _e476 = local_24;
                                            if (_e476 == 2u) {
                                                let _e478 = local_22;
                                                if _e478 {
                                                    let _e479 = local_37;
                                                    let _e480 = local_36;
                                                    let _e482 = local_37;
                                                    let _e483 = local_36;
                                                    let _e484 = select(_e483, _e482, (_e479 < _e480));
                                                    local_40 = _e484;
                                                    if (_e484 < 2u) {
                                                        phi_575_ = 0f;
                                                    } else {
                                                        let _e486 = local_40;
                                                        phi_575_ = (f32((_e486 - 1u)) * 0.00000005960465f);
                                                    }
                                                    let _e491 = phi_575_;
                                                    phi_581_ = _e491;
                                                } else {
                                                    let _e492 = local_34;
                                                    let _e493 = local_23;
                                                    let _e495 = local_34;
                                                    let _e496 = local_23;
                                                    phi_581_ = select(_e496, _e495, (_e492 < _e493));
                                                }
                                                let _e499 = phi_581_;
                                                local_38 = _e499;
                                                if (_e499 > 0f) {
                                                    let _e501 = local_38;
                                                    phi_587_ = -(_e501);
                                                } else {
                                                    phi_587_ = _e84;
                                                }
                                                let _e504 = phi_587_;
                                                phi_605_ = _e504;
                                            } else {
                                                let _e505 = local_22;
                                                if _e505 {
                                                    let _e506 = local_37;
                                                    let _e507 = local_36;
                                                    let _e509 = local_37;
                                                    let _e510 = local_36;
                                                    phi_604_ = (f32((select(_e510, _e509, (_e506 > _e507)) + 1u)) * 0.00000005960465f);
                                                } else {
                                                    let _e515 = local_34;
                                                    let _e516 = local_23;
                                                    let _e518 = local_34;
                                                    let _e519 = local_23;
                                                    phi_604_ = select(_e519, _e518, (_e515 > _e516));
                                                }
                                                let _e522 = phi_604_;
                                                phi_605_ = _e522;
                                            }
                                            let _e524 = phi_605_;
                                            phi_606_ = _e524;
                                        } else {
                                            phi_606_ = f32();
                                        }
                                        let _e526 = phi_606_;
                                        let _e527 = local_35;
                                        phi_608_ = _e526;
                                        phi_609_ = select(true, false, _e527);
                                    } else {
                                        phi_608_ = f32();
                                        phi_609_ = true;
                                    }
                                    let _e530 = phi_608_;
                                    let _e532 = phi_609_;
                                    phi_610_ = _e530;
                                    phi_611_ = _e532;
                                } else {
                                    phi_610_ = f32();
                                    phi_611_ = true;
                                }
                                let _e534 = phi_610_;
                                let _e536 = phi_611_;
                                let _e537 = local_42;
                                phi_616_ = select(_e534, _e537, _e536);
                            } else {
                                phi_616_ = _e84;
                            }
                            let _e540 = phi_616_;
                            phi_617_ = _e540;
                        }
                        let _e542 = phi_617_;
                        local_39 = bitcast<u32>(_e542);
                        let _e544 = local_9;
                        let _e545 = local_4;
                        if (_e544 < _e545) {
                        } else {
                            phi_670_ = true;
                            break;
                        }
                        let _e547 = local_9;
                        let _e550 = local_39;
                        global_7.member[_e547] = _e550;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e551 = local_7;
                    let _e552 = local_6;
                    phi_107_ = (_e551 + _e552);
                } else {
                    phi_107_ = u32();
                }
                let _e555 = phi_107_;
                continue;
                continuing {
                    let _e556 = local_8;
                    phi_106_ = _e555;
                    phi_670_ = false;
                    break if !(_e556);
                }
            }
            let _e559 = phi_670_;
            if _e559 {
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
