struct type_6 {
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
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_6;
@group(0) @binding(1) 
var<storage, read_write> global_4: type_6;
var<immediate> global_5: type_14;

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
    var local_14: bool;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: f32;
    var local_19: u32;
    var local_20: f32;
    var local_21: u32;
    var local_22: f32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: i32;
    var local_27: u32;
    var local_28: i32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: u32;
    var local_34: u32;
    var local_35: i32;
    var local_36: u32;
    var local_37: i32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: i32;
    var local_47: u32;
    var local_48: i32;
    var local_49: u32;
    var local_50: u32;
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
    var local_61: u32;
    var local_62: bool;
    var local_63: u32;
    var phi_92_: u32;
    var phi_666_: bool;
    var phi_106_: u32;
    var phi_117_: u32;
    var phi_258_: bool;
    var phi_259_: bool;
    var phi_237_: bool;
    var phi_238_: bool;
    var phi_242_: u32;
    var phi_263_: u32;
    var phi_264_: u32;
    var phi_265_: u32;
    var phi_266_: u32;
    var phi_267_: bool;
    var phi_271_: u32;
    var phi_272_: u32;
    var phi_273_: bool;
    var phi_354_: bool;
    var phi_355_: bool;
    var phi_333_: bool;
    var phi_334_: bool;
    var phi_338_: u32;
    var phi_359_: u32;
    var phi_360_: u32;
    var phi_361_: u32;
    var phi_362_: u32;
    var phi_363_: bool;
    var phi_367_: u32;
    var phi_368_: u32;
    var phi_369_: bool;
    var phi_462_: bool;
    var phi_463_: bool;
    var phi_441_: bool;
    var phi_442_: bool;
    var phi_446_: u32;
    var phi_467_: u32;
    var phi_468_: u32;
    var phi_469_: u32;
    var phi_470_: u32;
    var phi_471_: bool;
    var phi_475_: u32;
    var phi_476_: u32;
    var phi_477_: bool;
    var phi_632_: u32;
    var phi_118_: u32;
    var phi_633_: bool;
    var phi_649_: bool;
    var phi_698_: bool;
    var phi_107_: u32;
    var phi_697_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e101 = global;
            local = _e101;
            let _e102 = global_1;
            let _e103 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = _e102.x;
            local_4 = _e103.x;
            let _e113 = global_5.member.member;
            local_5 = _e113;
            let _e116 = global_5.member.member_2;
            local_6 = _e116;
            if (_e116 == 1u) {
                phi_92_ = 2u;
            } else {
                let _e118 = local_6;
                phi_92_ = select(0u, 1u, (_e118 == 2u));
            }
            let _e122 = phi_92_;
            local_7 = _e122;
            let _e125 = global_5.member.member_1;
            let _e126 = local_5;
            local_8 = (_e126 * _e125);
            let _e128 = local_4;
            local_9 = (_e128 * 256u);
            let _e130 = local;
            local_10 = (_e130 + 1u);
            let _e132 = local_3;
            phi_666_ = false;
            phi_106_ = (_e132 * 256u);
            loop {
                let _e135 = phi_666_;
                let _e137 = phi_106_;
                local_11 = _e137;
                let _e138 = local_11;
                let _e139 = local_8;
                let _e140 = (_e138 < _e139);
                local_12 = _e140;
                if _e140 {
                    let _e141 = local_11;
                    let _e142 = local;
                    phi_117_ = (_e141 + _e142);
                    loop {
                        let _e145 = phi_117_;
                        local_13 = _e145;
                        let _e146 = local_13;
                        let _e147 = local_8;
                        if (_e146 < _e147) {
                            let _e149 = local_11;
                            let _e150 = local_10;
                            let _e152 = local_13;
                            let _e153 = (_e152 < (_e149 + _e150));
                            if _e153 {
                                let _e154 = local_5;
                                let _e155 = (_e154 == 0u);
                                local_14 = _e155;
                                if _e155 {
                                    phi_649_ = true;
                                    break;
                                }
                                let _e156 = local_13;
                                let _e157 = local_5;
                                local_15 = (_e156 % _e157);
                                let _e159 = local_14;
                                if _e159 {
                                    phi_649_ = true;
                                    break;
                                }
                                let _e160 = local_13;
                                let _e161 = local_5;
                                local_16 = (_e160 / _e161);
                                let _e163 = local_13;
                                let _e164 = (3u * _e163);
                                local_17 = _e164;
                                let _e165 = local_1;
                                if (_e164 < _e165) {
                                } else {
                                    phi_649_ = true;
                                    break;
                                }
                                let _e167 = local_17;
                                let _e170 = global_3.member[_e167];
                                local_18 = bitcast<f32>(_e170);
                                let _e172 = local_17;
                                let _e173 = (_e172 + 1u);
                                local_19 = _e173;
                                let _e174 = local_1;
                                if (_e173 < _e174) {
                                } else {
                                    phi_649_ = true;
                                    break;
                                }
                                let _e176 = local_19;
                                let _e179 = global_3.member[_e176];
                                local_20 = bitcast<f32>(_e179);
                                let _e181 = local_17;
                                let _e182 = (_e181 + 2u);
                                local_21 = _e182;
                                let _e183 = local_1;
                                if (_e182 < _e183) {
                                } else {
                                    phi_649_ = true;
                                    break;
                                }
                                let _e185 = local_21;
                                let _e188 = global_3.member[_e185];
                                local_22 = bitcast<f32>(_e188);
                                let _e190 = local_16;
                                let _e191 = local_5;
                                let _e193 = local_15;
                                local_23 = ((_e190 * _e191) + _e193);
                                let _e195 = local_7;
                                if (_e195 == 1u) {
                                    let _e230 = local_23;
                                    local_24 = (2u * _e230);
                                    let _e232 = local_18;
                                    let _e233 = bitcast<u32>(_e232);
                                    let _e236 = ((_e233 >> bitcast<u32>(16i)) & 32768u);
                                    local_25 = _e236;
                                    let _e240 = bitcast<i32>(((_e233 >> bitcast<u32>(23i)) & 255u));
                                    local_26 = _e240;
                                    local_27 = (_e233 & 8388607u);
                                    if (_e240 == 255i) {
                                        let _e321 = local_25;
                                        let _e323 = local_27;
                                        phi_271_ = ((_e321 | 31744u) | select(512u, 0u, (_e323 == 0u)));
                                        phi_272_ = u32();
                                        phi_273_ = true;
                                    } else {
                                        let _e243 = local_26;
                                        let _e244 = (_e243 + -112i);
                                        local_28 = _e244;
                                        if (_e244 >= 31i) {
                                            let _e313 = local_25;
                                            phi_265_ = (_e313 | 31744u);
                                            phi_266_ = u32();
                                            phi_267_ = true;
                                        } else {
                                            let _e246 = local_28;
                                            let _e247 = (_e246 <= 0i);
                                            if _e247 {
                                                let _e273 = local_28;
                                                if (_e273 < -10i) {
                                                    phi_242_ = _e236;
                                                } else {
                                                    let _e275 = local_27;
                                                    let _e276 = (_e275 | 8388608u);
                                                    let _e277 = local_26;
                                                    let _e279 = bitcast<u32>((126i - _e277));
                                                    let _e280 = (_e279 & 31u);
                                                    local_29 = (_e276 >> bitcast<u32>(_e280));
                                                    let _e286 = (_e276 & ((1u << bitcast<u32>(_e280)) - 1u));
                                                    local_30 = _e286;
                                                    let _e290 = (1u << bitcast<u32>(((_e279 - 1u) & 31u)));
                                                    local_31 = _e290;
                                                    if (_e286 > _e290) {
                                                        phi_238_ = true;
                                                    } else {
                                                        let _e292 = local_30;
                                                        let _e293 = local_31;
                                                        if (_e292 == _e293) {
                                                            let _e295 = local_29;
                                                            phi_237_ = ((_e295 & 1u) == 1u);
                                                        } else {
                                                            phi_237_ = false;
                                                        }
                                                        let _e299 = phi_237_;
                                                        phi_238_ = _e299;
                                                    }
                                                    let _e301 = phi_238_;
                                                    let _e303 = local_29;
                                                    let _e305 = local_25;
                                                    phi_242_ = (_e305 | (_e303 + select(0u, 1u, _e301)));
                                                }
                                                let _e308 = phi_242_;
                                                phi_263_ = _e308;
                                                phi_264_ = u32();
                                            } else {
                                                let _e248 = local_28;
                                                let _e252 = local_27;
                                                local_32 = ((bitcast<u32>(_e248) << bitcast<u32>(10i)) | (_e252 >> bitcast<u32>(13i)));
                                                let _e256 = local_27;
                                                let _e257 = (_e256 & 8191u);
                                                local_33 = _e257;
                                                if (_e257 > 4096u) {
                                                    phi_259_ = true;
                                                } else {
                                                    let _e259 = local_33;
                                                    if (_e259 == 4096u) {
                                                        let _e261 = local_32;
                                                        phi_258_ = ((_e261 & 1u) == 1u);
                                                    } else {
                                                        phi_258_ = false;
                                                    }
                                                    let _e265 = phi_258_;
                                                    phi_259_ = _e265;
                                                }
                                                let _e267 = phi_259_;
                                                let _e269 = local_32;
                                                let _e271 = local_25;
                                                phi_263_ = u32();
                                                phi_264_ = (_e271 | (_e269 + select(0u, 1u, _e267)));
                                            }
                                            let _e310 = phi_263_;
                                            let _e312 = phi_264_;
                                            phi_265_ = _e310;
                                            phi_266_ = _e312;
                                            phi_267_ = _e247;
                                        }
                                        let _e316 = phi_265_;
                                        let _e318 = phi_266_;
                                        let _e320 = phi_267_;
                                        phi_271_ = _e316;
                                        phi_272_ = _e318;
                                        phi_273_ = _e320;
                                    }
                                    let _e328 = phi_271_;
                                    let _e330 = phi_272_;
                                    let _e332 = phi_273_;
                                    local_63 = select(_e330, _e328, _e332);
                                    let _e334 = local_20;
                                    let _e335 = bitcast<u32>(_e334);
                                    let _e338 = ((_e335 >> bitcast<u32>(16i)) & 32768u);
                                    local_34 = _e338;
                                    let _e342 = bitcast<i32>(((_e335 >> bitcast<u32>(23i)) & 255u));
                                    local_35 = _e342;
                                    local_36 = (_e335 & 8388607u);
                                    if (_e342 == 255i) {
                                        let _e423 = local_34;
                                        let _e425 = local_36;
                                        phi_367_ = ((_e423 | 31744u) | select(512u, 0u, (_e425 == 0u)));
                                        phi_368_ = u32();
                                        phi_369_ = true;
                                    } else {
                                        let _e345 = local_35;
                                        let _e346 = (_e345 + -112i);
                                        local_37 = _e346;
                                        if (_e346 >= 31i) {
                                            let _e415 = local_34;
                                            phi_361_ = (_e415 | 31744u);
                                            phi_362_ = u32();
                                            phi_363_ = true;
                                        } else {
                                            let _e348 = local_37;
                                            let _e349 = (_e348 <= 0i);
                                            if _e349 {
                                                let _e375 = local_37;
                                                if (_e375 < -10i) {
                                                    phi_338_ = _e338;
                                                } else {
                                                    let _e377 = local_36;
                                                    let _e378 = (_e377 | 8388608u);
                                                    let _e379 = local_35;
                                                    let _e381 = bitcast<u32>((126i - _e379));
                                                    let _e382 = (_e381 & 31u);
                                                    local_38 = (_e378 >> bitcast<u32>(_e382));
                                                    let _e388 = (_e378 & ((1u << bitcast<u32>(_e382)) - 1u));
                                                    local_39 = _e388;
                                                    let _e392 = (1u << bitcast<u32>(((_e381 - 1u) & 31u)));
                                                    local_40 = _e392;
                                                    if (_e388 > _e392) {
                                                        phi_334_ = true;
                                                    } else {
                                                        let _e394 = local_39;
                                                        let _e395 = local_40;
                                                        if (_e394 == _e395) {
                                                            let _e397 = local_38;
                                                            phi_333_ = ((_e397 & 1u) == 1u);
                                                        } else {
                                                            phi_333_ = false;
                                                        }
                                                        let _e401 = phi_333_;
                                                        phi_334_ = _e401;
                                                    }
                                                    let _e403 = phi_334_;
                                                    let _e405 = local_38;
                                                    let _e407 = local_34;
                                                    phi_338_ = (_e407 | (_e405 + select(0u, 1u, _e403)));
                                                }
                                                let _e410 = phi_338_;
                                                phi_359_ = _e410;
                                                phi_360_ = u32();
                                            } else {
                                                let _e350 = local_37;
                                                let _e354 = local_36;
                                                local_41 = ((bitcast<u32>(_e350) << bitcast<u32>(10i)) | (_e354 >> bitcast<u32>(13i)));
                                                let _e358 = local_36;
                                                let _e359 = (_e358 & 8191u);
                                                local_42 = _e359;
                                                if (_e359 > 4096u) {
                                                    phi_355_ = true;
                                                } else {
                                                    let _e361 = local_42;
                                                    if (_e361 == 4096u) {
                                                        let _e363 = local_41;
                                                        phi_354_ = ((_e363 & 1u) == 1u);
                                                    } else {
                                                        phi_354_ = false;
                                                    }
                                                    let _e367 = phi_354_;
                                                    phi_355_ = _e367;
                                                }
                                                let _e369 = phi_355_;
                                                let _e371 = local_41;
                                                let _e373 = local_34;
                                                phi_359_ = u32();
                                                phi_360_ = (_e373 | (_e371 + select(0u, 1u, _e369)));
                                            }
                                            let _e412 = phi_359_;
                                            let _e414 = phi_360_;
                                            phi_361_ = _e412;
                                            phi_362_ = _e414;
                                            phi_363_ = _e349;
                                        }
                                        let _e418 = phi_361_;
                                        let _e420 = phi_362_;
                                        let _e422 = phi_363_;
                                        phi_367_ = _e418;
                                        phi_368_ = _e420;
                                        phi_369_ = _e422;
                                    }
                                    let _e430 = phi_367_;
                                    let _e432 = phi_368_;
                                    let _e434 = phi_369_;
                                    let _e438 = local_63;
                                    local_43 = (_e438 | (select(_e432, _e430, _e434) << bitcast<u32>(16i)));
                                    let _e440 = local_24;
                                    let _e441 = local_2;
                                    if (_e440 < _e441) {
                                    } else {
                                        phi_649_ = true;
                                        break;
                                    }
                                    let _e443 = local_24;
                                    let _e445 = local_43;
                                    global_4.member[_e443] = _e445;
                                    let _e446 = local_24;
                                    local_44 = (_e446 + 1u);
                                    let _e448 = local_22;
                                    let _e449 = bitcast<u32>(_e448);
                                    let _e452 = ((_e449 >> bitcast<u32>(16i)) & 32768u);
                                    local_45 = _e452;
                                    let _e456 = bitcast<i32>(((_e449 >> bitcast<u32>(23i)) & 255u));
                                    local_46 = _e456;
                                    local_47 = (_e449 & 8388607u);
                                    if (_e456 == 255i) {
                                        let _e537 = local_45;
                                        let _e539 = local_47;
                                        phi_475_ = ((_e537 | 31744u) | select(512u, 0u, (_e539 == 0u)));
                                        phi_476_ = u32();
                                        phi_477_ = true;
                                    } else {
                                        let _e459 = local_46;
                                        let _e460 = (_e459 + -112i);
                                        local_48 = _e460;
                                        if (_e460 >= 31i) {
                                            let _e529 = local_45;
                                            phi_469_ = (_e529 | 31744u);
                                            phi_470_ = u32();
                                            phi_471_ = true;
                                        } else {
                                            let _e462 = local_48;
                                            let _e463 = (_e462 <= 0i);
                                            if _e463 {
                                                let _e489 = local_48;
                                                if (_e489 < -10i) {
                                                    phi_446_ = _e452;
                                                } else {
                                                    let _e491 = local_47;
                                                    let _e492 = (_e491 | 8388608u);
                                                    let _e493 = local_46;
                                                    let _e495 = bitcast<u32>((126i - _e493));
                                                    let _e496 = (_e495 & 31u);
                                                    local_49 = (_e492 >> bitcast<u32>(_e496));
                                                    let _e502 = (_e492 & ((1u << bitcast<u32>(_e496)) - 1u));
                                                    local_50 = _e502;
                                                    let _e506 = (1u << bitcast<u32>(((_e495 - 1u) & 31u)));
                                                    local_51 = _e506;
                                                    if (_e502 > _e506) {
                                                        phi_442_ = true;
                                                    } else {
                                                        let _e508 = local_50;
                                                        let _e509 = local_51;
                                                        if (_e508 == _e509) {
                                                            let _e511 = local_49;
                                                            phi_441_ = ((_e511 & 1u) == 1u);
                                                        } else {
                                                            phi_441_ = false;
                                                        }
                                                        let _e515 = phi_441_;
                                                        phi_442_ = _e515;
                                                    }
                                                    let _e517 = phi_442_;
                                                    let _e519 = local_49;
                                                    let _e521 = local_45;
                                                    phi_446_ = (_e521 | (_e519 + select(0u, 1u, _e517)));
                                                }
                                                let _e524 = phi_446_;
                                                phi_467_ = _e524;
                                                phi_468_ = u32();
                                            } else {
                                                let _e464 = local_48;
                                                let _e468 = local_47;
                                                local_52 = ((bitcast<u32>(_e464) << bitcast<u32>(10i)) | (_e468 >> bitcast<u32>(13i)));
                                                let _e472 = local_47;
                                                let _e473 = (_e472 & 8191u);
                                                local_53 = _e473;
                                                if (_e473 > 4096u) {
                                                    phi_463_ = true;
                                                } else {
                                                    let _e475 = local_53;
                                                    if (_e475 == 4096u) {
                                                        let _e477 = local_52;
                                                        phi_462_ = ((_e477 & 1u) == 1u);
                                                    } else {
                                                        phi_462_ = false;
                                                    }
                                                    let _e481 = phi_462_;
                                                    phi_463_ = _e481;
                                                }
                                                let _e483 = phi_463_;
                                                let _e485 = local_52;
                                                let _e487 = local_45;
                                                phi_467_ = u32();
                                                phi_468_ = (_e487 | (_e485 + select(0u, 1u, _e483)));
                                            }
                                            let _e526 = phi_467_;
                                            let _e528 = phi_468_;
                                            phi_469_ = _e526;
                                            phi_470_ = _e528;
                                            phi_471_ = _e463;
                                        }
                                        let _e532 = phi_469_;
                                        let _e534 = phi_470_;
                                        let _e536 = phi_471_;
                                        phi_475_ = _e532;
                                        phi_476_ = _e534;
                                        phi_477_ = _e536;
                                    }
                                    let _e544 = phi_475_;
                                    let _e546 = phi_476_;
                                    let _e548 = phi_477_;
                                    local_54 = (select(_e546, _e544, _e548) | 1006632960u);
                                    let _e551 = local_44;
                                    let _e552 = local_2;
                                    if (_e551 < _e552) {
                                    } else {
                                        phi_649_ = true;
                                        break;
                                    }
                                    let _e554 = local_44;
                                    let _e556 = local_54;
                                    global_4.member[_e554] = _e556;
                                } else {
                                    let _e197 = local_23;
                                    let _e198 = (4u * _e197);
                                    local_55 = _e198;
                                    let _e199 = local_18;
                                    local_56 = bitcast<u32>(_e199);
                                    let _e201 = local_2;
                                    if (_e198 < _e201) {
                                    } else {
                                        phi_649_ = true;
                                        break;
                                    }
                                    let _e203 = local_55;
                                    let _e205 = local_56;
                                    global_4.member[_e203] = _e205;
                                    let _e206 = local_55;
                                    let _e207 = (_e206 + 1u);
                                    local_57 = _e207;
                                    let _e208 = local_20;
                                    local_58 = bitcast<u32>(_e208);
                                    let _e210 = local_2;
                                    if (_e207 < _e210) {
                                    } else {
                                        phi_649_ = true;
                                        break;
                                    }
                                    let _e212 = local_57;
                                    let _e214 = local_58;
                                    global_4.member[_e212] = _e214;
                                    let _e215 = local_55;
                                    let _e216 = (_e215 + 2u);
                                    local_59 = _e216;
                                    let _e217 = local_22;
                                    local_60 = bitcast<u32>(_e217);
                                    let _e219 = local_2;
                                    if (_e216 < _e219) {
                                    } else {
                                        phi_649_ = true;
                                        break;
                                    }
                                    let _e221 = local_59;
                                    let _e223 = local_60;
                                    global_4.member[_e221] = _e223;
                                    let _e224 = local_55;
                                    let _e225 = (_e224 + 3u);
                                    local_61 = _e225;
                                    let _e226 = local_2;
                                    if (_e225 < _e226) {
                                    } else {
                                        phi_649_ = true;
                                        break;
                                    }
                                    let _e228 = local_61;
                                    global_4.member[_e228] = 1065353216u;
                                }
                                let _e557 = local_13;
                                phi_632_ = (_e557 + 1u);
                            } else {
                                phi_632_ = u32();
                            }
                            let _e560 = phi_632_;
                            phi_118_ = _e560;
                            phi_633_ = _e153;
                        } else {
                            phi_118_ = u32();
                            phi_633_ = false;
                        }
                        let _e562 = phi_118_;
                        let _e564 = phi_633_;
                        local_62 = _e564;
                        continue;
                        continuing {
                            let _e565 = local_62;
                            phi_117_ = _e562;
                            phi_649_ = _e135;
                            break if !(_e565);
                        }
                    }
                    let _e568 = phi_649_;
                    phi_697_ = _e568;
                    if _e568 {
                        break;
                    }
                    let _e569 = local_11;
                    let _e570 = local_9;
                    phi_698_ = _e568;
                    phi_107_ = (_e569 + _e570);
                } else {
                    phi_698_ = _e135;
                    phi_107_ = u32();
                }
                let _e573 = phi_698_;
                let _e575 = phi_107_;
                continue;
                continuing {
                    let _e576 = local_12;
                    phi_666_ = _e573;
                    phi_106_ = _e575;
                    phi_697_ = _e573;
                    break if !(_e576);
                }
            }
            let _e579 = phi_697_;
            if _e579 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn frame_to_rgba(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
