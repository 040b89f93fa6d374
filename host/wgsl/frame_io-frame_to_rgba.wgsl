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
    var local_14: u32;
    var local_15: f32;
    var local_16: u32;
    var local_17: f32;
    var local_18: u32;
    var local_19: f32;
    var local_20: u32;
    var local_21: u32;
    var local_22: i32;
    var local_23: u32;
    var local_24: i32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: i32;
    var local_32: u32;
    var local_33: i32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: i32;
    var local_43: u32;
    var local_44: i32;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: u32;
    var local_57: u32;
    var local_58: bool;
    var local_59: u32;
    var phi_92_: u32;
    var phi_663_: bool;
    var phi_106_: u32;
    var phi_117_: u32;
    var phi_255_: bool;
    var phi_256_: bool;
    var phi_234_: bool;
    var phi_235_: bool;
    var phi_239_: u32;
    var phi_260_: u32;
    var phi_261_: u32;
    var phi_262_: u32;
    var phi_263_: u32;
    var phi_264_: bool;
    var phi_268_: u32;
    var phi_269_: u32;
    var phi_270_: bool;
    var phi_351_: bool;
    var phi_352_: bool;
    var phi_330_: bool;
    var phi_331_: bool;
    var phi_335_: u32;
    var phi_356_: u32;
    var phi_357_: u32;
    var phi_358_: u32;
    var phi_359_: u32;
    var phi_360_: bool;
    var phi_364_: u32;
    var phi_365_: u32;
    var phi_366_: bool;
    var phi_459_: bool;
    var phi_460_: bool;
    var phi_438_: bool;
    var phi_439_: bool;
    var phi_443_: u32;
    var phi_464_: u32;
    var phi_465_: u32;
    var phi_466_: u32;
    var phi_467_: u32;
    var phi_468_: bool;
    var phi_472_: u32;
    var phi_473_: u32;
    var phi_474_: bool;
    var phi_629_: u32;
    var phi_118_: u32;
    var phi_630_: bool;
    var phi_646_: bool;
    var phi_695_: bool;
    var phi_107_: u32;
    var phi_694_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e97 = global;
            local = _e97;
            let _e98 = global_1;
            let _e99 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = _e98.x;
            local_4 = _e99.x;
            let _e109 = global_5.member.member;
            local_5 = _e109;
            let _e112 = global_5.member.member_2;
            local_6 = _e112;
            if (_e112 == 1u) {
                phi_92_ = 2u;
            } else {
                let _e114 = local_6;
                phi_92_ = select(0u, 1u, (_e114 == 2u));
            }
            let _e118 = phi_92_;
            local_7 = _e118;
            let _e121 = global_5.member.member_1;
            let _e122 = local_5;
            local_8 = (_e122 * _e121);
            let _e124 = local_4;
            local_9 = (_e124 * 256u);
            let _e126 = local;
            local_10 = (_e126 + 1u);
            let _e128 = local_3;
            phi_663_ = false;
            phi_106_ = (_e128 * 256u);
            loop {
                let _e131 = phi_663_;
                let _e133 = phi_106_;
                local_11 = _e133;
                let _e134 = local_11;
                let _e135 = local_8;
                let _e136 = (_e134 < _e135);
                local_12 = _e136;
                if _e136 {
                    let _e137 = local_11;
                    let _e138 = local;
                    phi_117_ = (_e137 + _e138);
                    loop {
                        let _e141 = phi_117_;
                        local_13 = _e141;
                        let _e142 = local_13;
                        let _e143 = local_8;
                        if (_e142 < _e143) {
                            let _e145 = local_11;
                            let _e146 = local_10;
                            let _e148 = local_13;
                            let _e149 = (_e148 < (_e145 + _e146));
                            if _e149 {
                                let _e150 = local_5;
                                if (_e150 == 0u) {
                                    phi_646_ = true;
                                    break;
                                }
                                let _e152 = local_13;
                                let _e153 = (3u * _e152);
                                local_14 = _e153;
                                let _e154 = local_1;
                                if (_e153 < _e154) {
                                } else {
                                    phi_646_ = true;
                                    break;
                                }
                                let _e156 = local_14;
                                let _e159 = global_3.member[_e156];
                                local_15 = bitcast<f32>(_e159);
                                let _e161 = local_14;
                                let _e162 = (_e161 + 1u);
                                local_16 = _e162;
                                let _e163 = local_1;
                                if (_e162 < _e163) {
                                } else {
                                    phi_646_ = true;
                                    break;
                                }
                                let _e165 = local_16;
                                let _e168 = global_3.member[_e165];
                                local_17 = bitcast<f32>(_e168);
                                let _e170 = local_14;
                                let _e171 = (_e170 + 2u);
                                local_18 = _e171;
                                let _e172 = local_1;
                                if (_e171 < _e172) {
                                } else {
                                    phi_646_ = true;
                                    break;
                                }
                                let _e174 = local_18;
                                let _e177 = global_3.member[_e174];
                                local_19 = bitcast<f32>(_e177);
                                let _e179 = local_7;
                                if (_e179 == 1u) {
                                    let _e214 = local_13;
                                    local_20 = (2u * _e214);
                                    let _e216 = local_15;
                                    let _e217 = bitcast<u32>(_e216);
                                    let _e220 = ((_e217 >> bitcast<u32>(16i)) & 32768u);
                                    local_21 = _e220;
                                    let _e224 = bitcast<i32>(((_e217 >> bitcast<u32>(23i)) & 255u));
                                    local_22 = _e224;
                                    local_23 = (_e217 & 8388607u);
                                    if (_e224 == 255i) {
                                        let _e305 = local_21;
                                        let _e307 = local_23;
                                        phi_268_ = ((_e305 | 31744u) | select(512u, 0u, (_e307 == 0u)));
                                        phi_269_ = u32();
                                        phi_270_ = true;
                                    } else {
                                        let _e227 = local_22;
                                        let _e228 = (_e227 + -112i);
                                        local_24 = _e228;
                                        if (_e228 >= 31i) {
                                            let _e297 = local_21;
                                            phi_262_ = (_e297 | 31744u);
                                            phi_263_ = u32();
                                            phi_264_ = true;
                                        } else {
                                            let _e230 = local_24;
                                            let _e231 = (_e230 <= 0i);
                                            if _e231 {
                                                let _e257 = local_24;
                                                if (_e257 < -10i) {
                                                    phi_239_ = _e220;
                                                } else {
                                                    let _e259 = local_23;
                                                    let _e260 = (_e259 | 8388608u);
                                                    let _e261 = local_22;
                                                    let _e263 = bitcast<u32>((126i - _e261));
                                                    let _e264 = (_e263 & 31u);
                                                    local_25 = (_e260 >> bitcast<u32>(_e264));
                                                    let _e270 = (_e260 & ((1u << bitcast<u32>(_e264)) - 1u));
                                                    local_26 = _e270;
                                                    let _e274 = (1u << bitcast<u32>(((_e263 - 1u) & 31u)));
                                                    local_27 = _e274;
                                                    if (_e270 > _e274) {
                                                        phi_235_ = true;
                                                    } else {
                                                        let _e276 = local_26;
                                                        let _e277 = local_27;
                                                        if (_e276 == _e277) {
                                                            let _e279 = local_25;
                                                            phi_234_ = ((_e279 & 1u) == 1u);
                                                        } else {
                                                            phi_234_ = false;
                                                        }
                                                        let _e283 = phi_234_;
                                                        phi_235_ = _e283;
                                                    }
                                                    let _e285 = phi_235_;
                                                    let _e287 = local_25;
                                                    let _e289 = local_21;
                                                    phi_239_ = (_e289 | (_e287 + select(0u, 1u, _e285)));
                                                }
                                                let _e292 = phi_239_;
                                                phi_260_ = _e292;
                                                phi_261_ = u32();
                                            } else {
                                                let _e232 = local_24;
                                                let _e236 = local_23;
                                                local_28 = ((bitcast<u32>(_e232) << bitcast<u32>(10i)) | (_e236 >> bitcast<u32>(13i)));
                                                let _e240 = local_23;
                                                let _e241 = (_e240 & 8191u);
                                                local_29 = _e241;
                                                if (_e241 > 4096u) {
                                                    phi_256_ = true;
                                                } else {
                                                    let _e243 = local_29;
                                                    if (_e243 == 4096u) {
                                                        let _e245 = local_28;
                                                        phi_255_ = ((_e245 & 1u) == 1u);
                                                    } else {
                                                        phi_255_ = false;
                                                    }
                                                    let _e249 = phi_255_;
                                                    phi_256_ = _e249;
                                                }
                                                let _e251 = phi_256_;
                                                let _e253 = local_28;
                                                let _e255 = local_21;
                                                phi_260_ = u32();
                                                phi_261_ = (_e255 | (_e253 + select(0u, 1u, _e251)));
                                            }
                                            let _e294 = phi_260_;
                                            let _e296 = phi_261_;
                                            phi_262_ = _e294;
                                            phi_263_ = _e296;
                                            phi_264_ = _e231;
                                        }
                                        let _e300 = phi_262_;
                                        let _e302 = phi_263_;
                                        let _e304 = phi_264_;
                                        phi_268_ = _e300;
                                        phi_269_ = _e302;
                                        phi_270_ = _e304;
                                    }
                                    let _e312 = phi_268_;
                                    let _e314 = phi_269_;
                                    let _e316 = phi_270_;
                                    local_59 = select(_e314, _e312, _e316);
                                    let _e318 = local_17;
                                    let _e319 = bitcast<u32>(_e318);
                                    let _e322 = ((_e319 >> bitcast<u32>(16i)) & 32768u);
                                    local_30 = _e322;
                                    let _e326 = bitcast<i32>(((_e319 >> bitcast<u32>(23i)) & 255u));
                                    local_31 = _e326;
                                    local_32 = (_e319 & 8388607u);
                                    if (_e326 == 255i) {
                                        let _e407 = local_30;
                                        let _e409 = local_32;
                                        phi_364_ = ((_e407 | 31744u) | select(512u, 0u, (_e409 == 0u)));
                                        phi_365_ = u32();
                                        phi_366_ = true;
                                    } else {
                                        let _e329 = local_31;
                                        let _e330 = (_e329 + -112i);
                                        local_33 = _e330;
                                        if (_e330 >= 31i) {
                                            let _e399 = local_30;
                                            phi_358_ = (_e399 | 31744u);
                                            phi_359_ = u32();
                                            phi_360_ = true;
                                        } else {
                                            let _e332 = local_33;
                                            let _e333 = (_e332 <= 0i);
                                            if _e333 {
                                                let _e359 = local_33;
                                                if (_e359 < -10i) {
                                                    phi_335_ = _e322;
                                                } else {
                                                    let _e361 = local_32;
                                                    let _e362 = (_e361 | 8388608u);
                                                    let _e363 = local_31;
                                                    let _e365 = bitcast<u32>((126i - _e363));
                                                    let _e366 = (_e365 & 31u);
                                                    local_34 = (_e362 >> bitcast<u32>(_e366));
                                                    let _e372 = (_e362 & ((1u << bitcast<u32>(_e366)) - 1u));
                                                    local_35 = _e372;
                                                    let _e376 = (1u << bitcast<u32>(((_e365 - 1u) & 31u)));
                                                    local_36 = _e376;
                                                    if (_e372 > _e376) {
                                                        phi_331_ = true;
                                                    } else {
                                                        let _e378 = local_35;
                                                        let _e379 = local_36;
                                                        if (_e378 == _e379) {
                                                            let _e381 = local_34;
                                                            phi_330_ = ((_e381 & 1u) == 1u);
                                                        } else {
                                                            phi_330_ = false;
                                                        }
                                                        let _e385 = phi_330_;
                                                        phi_331_ = _e385;
                                                    }
                                                    let _e387 = phi_331_;
                                                    let _e389 = local_34;
                                                    let _e391 = local_30;
                                                    phi_335_ = (_e391 | (_e389 + select(0u, 1u, _e387)));
                                                }
                                                let _e394 = phi_335_;
                                                phi_356_ = _e394;
                                                phi_357_ = u32();
                                            } else {
                                                let _e334 = local_33;
                                                let _e338 = local_32;
                                                local_37 = ((bitcast<u32>(_e334) << bitcast<u32>(10i)) | (_e338 >> bitcast<u32>(13i)));
                                                let _e342 = local_32;
                                                let _e343 = (_e342 & 8191u);
                                                local_38 = _e343;
                                                if (_e343 > 4096u) {
                                                    phi_352_ = true;
                                                } else {
                                                    let _e345 = local_38;
                                                    if (_e345 == 4096u) {
                                                        let _e347 = local_37;
                                                        phi_351_ = ((_e347 & 1u) == 1u);
                                                    } else {
                                                        phi_351_ = false;
                                                    }
                                                    let _e351 = phi_351_;
                                                    phi_352_ = _e351;
                                                }
                                                let _e353 = phi_352_;
                                                let _e355 = local_37;
                                                let _e357 = local_30;
                                                phi_356_ = u32();
                                                phi_357_ = (_e357 | (_e355 + select(0u, 1u, _e353)));
                                            }
                                            let _e396 = phi_356_;
                                            let _e398 = phi_357_;
                                            phi_358_ = _e396;
                                            phi_359_ = _e398;
                                            phi_360_ = _e333;
                                        }
                                        let _e402 = phi_358_;
                                        let _e404 = phi_359_;
                                        let _e406 = phi_360_;
                                        phi_364_ = _e402;
                                        phi_365_ = _e404;
                                        phi_366_ = _e406;
                                    }
                                    let _e414 = phi_364_;
                                    let _e416 = phi_365_;
                                    let _e418 = phi_366_;
                                    let _e422 = local_59;
                                    local_39 = (_e422 | (select(_e416, _e414, _e418) << bitcast<u32>(16i)));
                                    let _e424 = local_20;
                                    let _e425 = local_2;
                                    if (_e424 < _e425) {
                                    } else {
                                        phi_646_ = true;
                                        break;
                                    }
                                    let _e427 = local_20;
                                    let _e429 = local_39;
                                    global_4.member[_e427] = _e429;
                                    let _e430 = local_20;
                                    local_40 = (_e430 + 1u);
                                    let _e432 = local_19;
                                    let _e433 = bitcast<u32>(_e432);
                                    let _e436 = ((_e433 >> bitcast<u32>(16i)) & 32768u);
                                    local_41 = _e436;
                                    let _e440 = bitcast<i32>(((_e433 >> bitcast<u32>(23i)) & 255u));
                                    local_42 = _e440;
                                    local_43 = (_e433 & 8388607u);
                                    if (_e440 == 255i) {
                                        let _e521 = local_41;
                                        let _e523 = local_43;
                                        phi_472_ = ((_e521 | 31744u) | select(512u, 0u, (_e523 == 0u)));
                                        phi_473_ = u32();
                                        phi_474_ = true;
                                    } else {
                                        let _e443 = local_42;
                                        let _e444 = (_e443 + -112i);
                                        local_44 = _e444;
                                        if (_e444 >= 31i) {
                                            let _e513 = local_41;
                                            phi_466_ = (_e513 | 31744u);
                                            phi_467_ = u32();
                                            phi_468_ = true;
                                        } else {
                                            let _e446 = local_44;
                                            let _e447 = (_e446 <= 0i);
                                            if _e447 {
                                                let _e473 = local_44;
                                                if (_e473 < -10i) {
                                                    phi_443_ = _e436;
                                                } else {
                                                    let _e475 = local_43;
                                                    let _e476 = (_e475 | 8388608u);
                                                    let _e477 = local_42;
                                                    let _e479 = bitcast<u32>((126i - _e477));
                                                    let _e480 = (_e479 & 31u);
                                                    local_45 = (_e476 >> bitcast<u32>(_e480));
                                                    let _e486 = (_e476 & ((1u << bitcast<u32>(_e480)) - 1u));
                                                    local_46 = _e486;
                                                    let _e490 = (1u << bitcast<u32>(((_e479 - 1u) & 31u)));
                                                    local_47 = _e490;
                                                    if (_e486 > _e490) {
                                                        phi_439_ = true;
                                                    } else {
                                                        let _e492 = local_46;
                                                        let _e493 = local_47;
                                                        if (_e492 == _e493) {
                                                            let _e495 = local_45;
                                                            phi_438_ = ((_e495 & 1u) == 1u);
                                                        } else {
                                                            phi_438_ = false;
                                                        }
                                                        let _e499 = phi_438_;
                                                        phi_439_ = _e499;
                                                    }
                                                    let _e501 = phi_439_;
                                                    let _e503 = local_45;
                                                    let _e505 = local_41;
                                                    phi_443_ = (_e505 | (_e503 + select(0u, 1u, _e501)));
                                                }
                                                let _e508 = phi_443_;
                                                phi_464_ = _e508;
                                                phi_465_ = u32();
                                            } else {
                                                let _e448 = local_44;
                                                let _e452 = local_43;
                                                local_48 = ((bitcast<u32>(_e448) << bitcast<u32>(10i)) | (_e452 >> bitcast<u32>(13i)));
                                                let _e456 = local_43;
                                                let _e457 = (_e456 & 8191u);
                                                local_49 = _e457;
                                                if (_e457 > 4096u) {
                                                    phi_460_ = true;
                                                } else {
                                                    let _e459 = local_49;
                                                    if (_e459 == 4096u) {
                                                        let _e461 = local_48;
                                                        phi_459_ = ((_e461 & 1u) == 1u);
                                                    } else {
                                                        phi_459_ = false;
                                                    }
                                                    let _e465 = phi_459_;
                                                    phi_460_ = _e465;
                                                }
                                                let _e467 = phi_460_;
                                                let _e469 = local_48;
                                                let _e471 = local_41;
                                                phi_464_ = u32();
                                                phi_465_ = (_e471 | (_e469 + select(0u, 1u, _e467)));
                                            }
                                            let _e510 = phi_464_;
                                            let _e512 = phi_465_;
                                            phi_466_ = _e510;
                                            phi_467_ = _e512;
                                            phi_468_ = _e447;
                                        }
                                        let _e516 = phi_466_;
                                        let _e518 = phi_467_;
                                        let _e520 = phi_468_;
                                        phi_472_ = _e516;
                                        phi_473_ = _e518;
                                        phi_474_ = _e520;
                                    }
                                    let _e528 = phi_472_;
                                    let _e530 = phi_473_;
                                    let _e532 = phi_474_;
                                    local_50 = (select(_e530, _e528, _e532) | 1006632960u);
                                    let _e535 = local_40;
                                    let _e536 = local_2;
                                    if (_e535 < _e536) {
                                    } else {
                                        phi_646_ = true;
                                        break;
                                    }
                                    let _e538 = local_40;
                                    let _e540 = local_50;
                                    global_4.member[_e538] = _e540;
                                } else {
                                    let _e181 = local_13;
                                    let _e182 = (4u * _e181);
                                    local_51 = _e182;
                                    let _e183 = local_15;
                                    local_52 = bitcast<u32>(_e183);
                                    let _e185 = local_2;
                                    if (_e182 < _e185) {
                                    } else {
                                        phi_646_ = true;
                                        break;
                                    }
                                    let _e187 = local_51;
                                    let _e189 = local_52;
                                    global_4.member[_e187] = _e189;
                                    let _e190 = local_51;
                                    let _e191 = (_e190 + 1u);
                                    local_53 = _e191;
                                    let _e192 = local_17;
                                    local_54 = bitcast<u32>(_e192);
                                    let _e194 = local_2;
                                    if (_e191 < _e194) {
                                    } else {
                                        phi_646_ = true;
                                        break;
                                    }
                                    let _e196 = local_53;
                                    let _e198 = local_54;
                                    global_4.member[_e196] = _e198;
                                    let _e199 = local_51;
                                    let _e200 = (_e199 + 2u);
                                    local_55 = _e200;
                                    let _e201 = local_19;
                                    local_56 = bitcast<u32>(_e201);
                                    let _e203 = local_2;
                                    if (_e200 < _e203) {
                                    } else {
                                        phi_646_ = true;
                                        break;
                                    }
                                    let _e205 = local_55;
                                    let _e207 = local_56;
                                    global_4.member[_e205] = _e207;
                                    let _e208 = local_51;
                                    let _e209 = (_e208 + 3u);
                                    local_57 = _e209;
                                    let _e210 = local_2;
                                    if (_e209 < _e210) {
                                    } else {
                                        phi_646_ = true;
                                        break;
                                    }
                                    let _e212 = local_57;
                                    global_4.member[_e212] = 1065353216u;
                                }
                                let _e541 = local_13;
                                phi_629_ = (_e541 + 1u);
                            } else {
                                phi_629_ = u32();
                            }
                            let _e544 = phi_629_;
                            phi_118_ = _e544;
                            phi_630_ = _e149;
                        } else {
                            phi_118_ = u32();
                            phi_630_ = false;
                        }
                        let _e546 = phi_118_;
                        let _e548 = phi_630_;
                        local_58 = _e548;
                        continue;
                        continuing {
                            let _e549 = local_58;
                            phi_117_ = _e546;
                            phi_646_ = _e131;
                            break if !(_e549);
                        }
                    }
                    let _e552 = phi_646_;
                    phi_694_ = _e552;
                    if _e552 {
                        break;
                    }
                    let _e553 = local_11;
                    let _e554 = local_9;
                    phi_695_ = _e552;
                    phi_107_ = (_e553 + _e554);
                } else {
                    phi_695_ = _e131;
                    phi_107_ = u32();
                }
                let _e557 = phi_695_;
                let _e559 = phi_107_;
                continue;
                continuing {
                    let _e560 = local_12;
                    phi_663_ = _e557;
                    phi_106_ = _e559;
                    phi_694_ = _e557;
                    break if !(_e560);
                }
            }
            let _e563 = phi_694_;
            if _e563 {
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
