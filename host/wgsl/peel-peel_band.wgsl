struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_18 {
    member: array<array<f32, 4>, 5>,
    member_1: array<f32, 3>,
    member_2: u32,
    member_3: array<f32, 3>,
    member_4: u32,
    member_5: type_5,
}

struct type_19 {
    member: type_18,
}

struct type_30 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_19;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_30;
var<private> global_7: u32 = 2143289344u;
var<private> global_8: u32 = 2139095040u;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: bool;
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: f32;
    var local_17: u32;
    var local_18: f32;
    var local_19: u32;
    var local_20: f32;
    var local_21: u32;
    var local_22: f32;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: u32;
    var local_28: f32;
    var local_29: u32;
    var local_30: f32;
    var local_31: u32;
    var local_32: array<f32, 3>;
    var local_33: array<f32, 3>;
    var local_34: u32;
    var local_35: u32;
    var local_36: bool;
    var local_37: array<f32, 4>;
    var local_38: f32;
    var local_39: f32;
    var local_40: f32;
    var local_41: u32;
    var local_42: u32;
    var local_43: bool;
    var local_44: array<f32, 3>;
    var local_45: f32;
    var local_46: f32;
    var local_47: f32;
    var local_48: f32;
    var local_49: f32;
    var local_50: f32;
    var local_51: f32;
    var local_52: f32;
    var local_53: bool;
    var local_54: bool;
    var local_55: u32;
    var local_56: bool;
    var local_57: f32;
    var local_58: f32;
    var local_59: f32;
    var local_60: bool;
    var local_61: bool;
    var local_62: u32;
    var local_63: f32;
    var local_64: bool;
    var local_65: f32;
    var local_66: u32;
    var local_67: f32;
    var local_68: f32;
    var local_69: f32;
    var local_70: u32;
    var local_71: bool;
    var local_72: u32;
    var local_73: f32;
    var local_74: array<array<f32, 3>, 9>;
    var local_75: array<array<f32, 3>, 9>;
    var phi_732_: bool;
    var phi_109_: u32;
    var phi_730_: bool;
    var phi_384_: u32;
    var phi_387_: u32;
    var phi_415_: u32;
    var phi_418_: u32;
    var phi_494_: u32;
    var phi_495_: u32;
    var phi_536_: u32;
    var phi_537_: u32;
    var phi_416_: u32;
    var phi_419_: u32;
    var phi_722_: bool;
    var phi_544_: u32;
    var phi_734_: bool;
    var phi_385_: u32;
    var phi_388_: u32;
    var phi_546_: bool;
    var phi_547_: bool;
    var phi_733_: bool;
    var phi_715_: bool;
    var phi_556_: u32;
    var phi_559_: f32;
    var phi_557_: u32;
    var phi_560_: f32;
    var phi_736_: bool;
    var phi_748_: bool;
    var phi_601_: f32;
    var phi_636_: bool;
    var phi_664_: f32;
    var phi_665_: f32;
    var phi_671_: f32;
    var phi_673_: f32;
    var phi_743_: bool;
    var phi_742_: bool;
    var phi_110_: u32;
    var phi_741_: bool;
    var local_76: u32;
    var local_77: f32;

    let _e112 = global_7;
    let _e114 = global_8;
    let _e115 = bitcast<f32>(_e114);
    switch bitcast<i32>(0u) {
        default: {
            let _e117 = global;
            local = _e117;
            let _e118 = global_1;
            let _e119 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            let _e130 = global_3.member.member_2;
            local_4 = _e130;
            local_5 = (_e119.x * 64u);
            phi_732_ = false;
            phi_109_ = (_e118.x * 64u);
            loop {
                let _e134 = phi_732_;
                let _e136 = phi_109_;
                local_6 = _e136;
                let _e137 = local_6;
                let _e138 = local_4;
                let _e139 = (_e137 < _e138);
                local_7 = _e139;
                if _e139 {
                    let _e140 = local_6;
                    let _e141 = local;
                    let _e142 = (_e140 + _e141);
                    local_8 = _e142;
                    let _e143 = local_4;
                    if (_e142 < _e143) {
                        let _e145 = local_8;
                        let _e146 = (_e145 * 4u);
                        local_9 = _e146;
                        let _e147 = local_2;
                        if (_e146 < _e147) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e149 = local_9;
                        let _e152 = global_5.member[_e149];
                        local_10 = _e152;
                        let _e153 = local_9;
                        let _e154 = (_e153 + 1u);
                        local_11 = _e154;
                        let _e155 = local_2;
                        if (_e154 < _e155) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e157 = local_11;
                        let _e160 = global_5.member[_e157];
                        local_12 = _e160;
                        let _e161 = local_9;
                        let _e162 = (_e161 + 2u);
                        local_13 = _e162;
                        let _e163 = local_2;
                        if (_e162 < _e163) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e165 = local_13;
                        let _e168 = global_5.member[_e165];
                        local_14 = _e168;
                        let _e169 = local_9;
                        let _e171 = local_2;
                        if ((_e169 + 3u) < _e171) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e173 = local_10;
                        let _e174 = (_e173 * 10u);
                        local_15 = _e174;
                        let _e175 = local_1;
                        if (_e174 < _e175) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e177 = local_15;
                        let _e180 = global_4.member[_e177];
                        local_16 = bitcast<f32>(_e180);
                        let _e182 = local_15;
                        let _e183 = (_e182 + 1u);
                        local_17 = _e183;
                        let _e184 = local_1;
                        if (_e183 < _e184) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e186 = local_17;
                        let _e189 = global_4.member[_e186];
                        local_18 = bitcast<f32>(_e189);
                        let _e191 = local_15;
                        let _e192 = (_e191 + 2u);
                        local_19 = _e192;
                        let _e193 = local_1;
                        if (_e192 < _e193) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e195 = local_19;
                        let _e198 = global_4.member[_e195];
                        local_20 = bitcast<f32>(_e198);
                        let _e200 = local_12;
                        let _e201 = (_e200 * 10u);
                        local_21 = _e201;
                        let _e202 = local_1;
                        if (_e201 < _e202) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e204 = local_21;
                        let _e207 = global_4.member[_e204];
                        local_22 = bitcast<f32>(_e207);
                        let _e209 = local_21;
                        let _e210 = (_e209 + 1u);
                        local_23 = _e210;
                        let _e211 = local_1;
                        if (_e210 < _e211) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e213 = local_23;
                        let _e216 = global_4.member[_e213];
                        local_24 = bitcast<f32>(_e216);
                        let _e218 = local_21;
                        let _e219 = (_e218 + 2u);
                        local_25 = _e219;
                        let _e220 = local_1;
                        if (_e219 < _e220) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e222 = local_25;
                        let _e225 = global_4.member[_e222];
                        local_26 = bitcast<f32>(_e225);
                        let _e227 = local_14;
                        let _e228 = (_e227 * 10u);
                        local_27 = _e228;
                        let _e229 = local_1;
                        if (_e228 < _e229) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e231 = local_27;
                        let _e234 = global_4.member[_e231];
                        local_28 = bitcast<f32>(_e234);
                        let _e236 = local_27;
                        let _e237 = (_e236 + 1u);
                        local_29 = _e237;
                        let _e238 = local_1;
                        if (_e237 < _e238) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e240 = local_29;
                        let _e243 = global_4.member[_e240];
                        local_30 = bitcast<f32>(_e243);
                        let _e245 = local_27;
                        let _e246 = (_e245 + 2u);
                        local_31 = _e246;
                        let _e247 = local_1;
                        if (_e246 < _e247) {
                        } else {
                            phi_741_ = true;
                            break;
                        }
                        let _e249 = local_31;
                        let _e252 = global_4.member[_e249];
                        let _e256 = global_3.member.member_1;
                        local_32 = _e256;
                        let _e259 = global_3.member.member_3;
                        local_33 = _e259;
                        local_74[0u] = array<f32, 3>(0f, 0f, 0f);
                        local_74[1u] = array<f32, 3>(0f, 0f, 0f);
                        local_74[2u] = array<f32, 3>(0f, 0f, 0f);
                        local_74[3u] = array<f32, 3>(0f, 0f, 0f);
                        local_74[4u] = array<f32, 3>(0f, 0f, 0f);
                        local_74[5u] = array<f32, 3>(0f, 0f, 0f);
                        local_74[6u] = array<f32, 3>(0f, 0f, 0f);
                        local_74[7u] = array<f32, 3>(0f, 0f, 0f);
                        local_74[8u] = array<f32, 3>(0f, 0f, 0f);
                        let _e269 = local_16;
                        let _e270 = local_18;
                        let _e271 = local_20;
                        let _e272 = array<f32, 3>(_e269, _e270, _e271);
                        local_74[0u] = _e272;
                        let _e273 = local_22;
                        let _e274 = local_24;
                        let _e275 = local_26;
                        local_74[1u] = array<f32, 3>(_e273, _e274, _e275);
                        let _e277 = local_28;
                        let _e278 = local_30;
                        local_74[2u] = array<f32, 3>(_e277, _e278, bitcast<f32>(_e252));
                        local_74[3u] = _e272;
                        phi_730_ = _e134;
                        phi_384_ = 0u;
                        phi_387_ = 3u;
                        loop {
                            let _e281 = phi_730_;
                            let _e283 = phi_384_;
                            let _e285 = phi_387_;
                            local_34 = _e283;
                            local_35 = _e285;
                            let _e286 = local_34;
                            let _e287 = (_e286 < 5u);
                            local_36 = _e287;
                            if _e287 {
                                let _e288 = local_36;
                                if _e288 {
                                } else {
                                    phi_733_ = true;
                                    phi_715_ = bool();
                                    break;
                                }
                                let _e289 = local_34;
                                let _e293 = global_3.member.member[_e289];
                                local_37 = _e293;
                                local_38 = _e293[0];
                                local_39 = _e293[1];
                                local_40 = _e293[2];
                                local_75[0u] = array<f32, 3>(0f, 0f, 0f);
                                local_75[1u] = array<f32, 3>(0f, 0f, 0f);
                                local_75[2u] = array<f32, 3>(0f, 0f, 0f);
                                local_75[3u] = array<f32, 3>(0f, 0f, 0f);
                                local_75[4u] = array<f32, 3>(0f, 0f, 0f);
                                local_75[5u] = array<f32, 3>(0f, 0f, 0f);
                                local_75[6u] = array<f32, 3>(0f, 0f, 0f);
                                local_75[7u] = array<f32, 3>(0f, 0f, 0f);
                                local_75[8u] = array<f32, 3>(0f, 0f, 0f);
                                phi_415_ = 0u;
                                phi_418_ = 0u;
                                loop {
                                    let _e307 = phi_415_;
                                    let _e309 = phi_418_;
                                    local_41 = _e307;
                                    local_42 = _e309;
                                    local_76 = _e309;
                                    let _e310 = local_41;
                                    let _e311 = local_35;
                                    let _e312 = (_e310 < _e311);
                                    local_43 = _e312;
                                    if _e312 {
                                        let _e313 = local_41;
                                        if (_e313 < 9u) {
                                        } else {
                                            phi_722_ = true;
                                            break;
                                        }
                                        let _e315 = local_41;
                                        let _e317 = local_74[_e315];
                                        local_44 = _e317;
                                        local_45 = _e317[0];
                                        local_46 = _e317[1];
                                        local_47 = _e317[2];
                                        let _e321 = local_41;
                                        let _e322 = (_e321 + 1u);
                                        let _e323 = local_35;
                                        let _e325 = select(_e322, 0u, (_e322 == _e323));
                                        local_72 = _e325;
                                        if (_e325 < 9u) {
                                        } else {
                                            phi_722_ = true;
                                            break;
                                        }
                                        let _e327 = local_72;
                                        let _e329 = local_74[_e327];
                                        local_48 = _e329[0];
                                        local_49 = _e329[1];
                                        local_50 = _e329[2];
                                        let _e333 = local_38;
                                        let _e334 = local_45;
                                        let _e336 = local_39;
                                        let _e337 = local_46;
                                        let _e340 = local_40;
                                        let _e341 = local_47;
                                        let _e344 = local_37;
                                        let _e346 = ((((_e333 * _e334) + (_e336 * _e337)) + (_e340 * _e341)) - _e344[3]);
                                        local_51 = _e346;
                                        let _e347 = local_38;
                                        let _e349 = local_39;
                                        let _e352 = local_40;
                                        local_52 = ((((_e347 * _e329[0]) + (_e349 * _e329[1])) + (_e352 * _e329[2])) - _e344[3]);
                                        let _e356 = (_e346 >= 0f);
                                        local_53 = _e356;
                                        if _e356 {
                                            let _e357 = local_42;
                                            let _e358 = (_e357 < 9u);
                                            local_54 = _e358;
                                            if _e358 {
                                                let _e359 = local_54;
                                                if _e359 {
                                                } else {
                                                    phi_722_ = true;
                                                    break;
                                                }
                                                let _e360 = local_42;
                                                let _e362 = local_44;
                                                local_75[_e360] = _e362;
                                                let _e363 = local_42;
                                                phi_494_ = (_e363 + 1u);
                                            } else {
                                                phi_494_ = _e309;
                                            }
                                            let _e366 = phi_494_;
                                            phi_495_ = _e366;
                                        } else {
                                            phi_495_ = _e309;
                                        }
                                        let _e368 = phi_495_;
                                        local_55 = _e368;
                                        let _e369 = local_52;
                                        let _e371 = local_53;
                                        if (_e371 != (_e369 >= 0f)) {
                                            let _e373 = local_55;
                                            let _e374 = (_e373 < 9u);
                                            local_56 = _e374;
                                            if _e374 {
                                                let _e375 = local_51;
                                                let _e376 = local_52;
                                                let _e378 = local_51;
                                                let _e379 = (_e378 / (_e375 - _e376));
                                                let _e380 = local_48;
                                                let _e381 = local_45;
                                                let _e384 = local_45;
                                                local_57 = (_e384 + ((_e380 - _e381) * _e379));
                                                let _e386 = local_49;
                                                let _e387 = local_46;
                                                let _e390 = local_46;
                                                local_58 = (_e390 + ((_e386 - _e387) * _e379));
                                                let _e392 = local_50;
                                                let _e393 = local_47;
                                                let _e396 = local_47;
                                                local_59 = (_e396 + ((_e392 - _e393) * _e379));
                                                let _e398 = local_56;
                                                if _e398 {
                                                } else {
                                                    phi_722_ = true;
                                                    break;
                                                }
                                                let _e399 = local_55;
                                                let _e402 = local_57;
                                                local_75[_e399][0u] = _e402;
                                                let _e403 = local_55;
                                                let _e406 = local_58;
                                                local_75[_e403][1u] = _e406;
                                                let _e407 = local_55;
                                                let _e410 = local_59;
                                                local_75[_e407][2u] = _e410;
                                                let _e411 = local_55;
                                                phi_536_ = (_e411 + 1u);
                                            } else {
                                                phi_536_ = _e368;
                                            }
                                            let _e414 = phi_536_;
                                            phi_537_ = _e414;
                                        } else {
                                            phi_537_ = _e368;
                                        }
                                        let _e416 = phi_537_;
                                        phi_416_ = _e322;
                                        phi_419_ = _e416;
                                    } else {
                                        phi_416_ = u32();
                                        phi_419_ = u32();
                                    }
                                    let _e418 = phi_416_;
                                    let _e420 = phi_419_;
                                    continue;
                                    continuing {
                                        let _e421 = local_43;
                                        phi_415_ = _e418;
                                        phi_418_ = _e420;
                                        phi_722_ = _e281;
                                        break if !(_e421);
                                    }
                                }
                                let _e424 = phi_722_;
                                phi_733_ = _e424;
                                phi_715_ = bool();
                                if _e424 {
                                    break;
                                }
                                let _e425 = local_75;
                                local_74 = _e425;
                                let _e426 = local_42;
                                let _e427 = (_e426 == 0u);
                                local_60 = _e427;
                                if _e427 {
                                    phi_544_ = u32();
                                } else {
                                    let _e428 = local_34;
                                    phi_544_ = (_e428 + 1u);
                                }
                                let _e431 = phi_544_;
                                let _e432 = local_60;
                                phi_734_ = _e424;
                                phi_385_ = _e431;
                                let _e623 = local_76;
                                phi_388_ = _e623;
                                phi_546_ = select(true, false, _e432);
                                phi_547_ = _e427;
                            } else {
                                phi_734_ = _e281;
                                phi_385_ = u32();
                                phi_388_ = u32();
                                phi_546_ = false;
                                phi_547_ = false;
                            }
                            let _e435 = phi_734_;
                            let _e437 = phi_385_;
                            let _e439 = phi_388_;
                            let _e441 = phi_546_;
                            let _e443 = phi_547_;
                            local_61 = _e441;
                            continue;
                            continuing {
                                let _e444 = local_61;
                                phi_730_ = _e435;
                                phi_384_ = _e437;
                                phi_387_ = _e439;
                                phi_733_ = _e435;
                                phi_715_ = _e443;
                                break if !(_e444);
                            }
                        }
                        let _e447 = phi_733_;
                        let _e449 = phi_715_;
                        local_71 = _e449;
                        phi_741_ = _e447;
                        if _e447 {
                            break;
                        }
                        let _e450 = local_71;
                        if select(true, false, _e450) {
                            phi_556_ = 0u;
                            phi_559_ = _e115;
                            loop {
                                let _e453 = phi_556_;
                                let _e455 = phi_559_;
                                local_62 = _e453;
                                local_63 = _e455;
                                local_77 = _e455;
                                let _e456 = local_62;
                                let _e457 = local_35;
                                let _e458 = (_e456 < _e457);
                                local_64 = _e458;
                                if _e458 {
                                    let _e459 = local_62;
                                    if (_e459 < 9u) {
                                    } else {
                                        phi_736_ = true;
                                        break;
                                    }
                                    let _e461 = local_62;
                                    let _e463 = local_74[_e461];
                                    let _e467 = local_32;
                                    let _e470 = local_32;
                                    let _e473 = local_32;
                                    let _e476 = local_33;
                                    let _e479 = local_33;
                                    let _e483 = local_33;
                                    let _e486 = ((((_e463[0] - _e467[0]) * _e476[0]) + ((_e463[1] - _e470[1]) * _e479[1])) + ((_e463[2] - _e473[2]) * _e483[2]));
                                    let _e487 = local_63;
                                    let _e489 = local_63;
                                    let _e491 = local_62;
                                    phi_557_ = (_e491 + 1u);
                                    phi_560_ = select(_e489, _e486, (_e486 < _e487));
                                } else {
                                    phi_557_ = u32();
                                    phi_560_ = f32();
                                }
                                let _e494 = phi_557_;
                                let _e496 = phi_560_;
                                continue;
                                continuing {
                                    let _e497 = local_64;
                                    phi_556_ = _e494;
                                    phi_559_ = _e496;
                                    phi_736_ = _e447;
                                    break if !(_e497);
                                }
                            }
                            let _e500 = phi_736_;
                            phi_741_ = _e500;
                            if _e500 {
                                break;
                            }
                            phi_748_ = _e500;
                            let _e636 = local_77;
                            phi_601_ = _e636;
                        } else {
                            phi_748_ = _e447;
                            phi_601_ = _e115;
                        }
                        let _e502 = phi_748_;
                        let _e504 = phi_601_;
                        local_65 = _e504;
                        let _e505 = bitcast<u32>(_e504);
                        local_66 = _e505;
                        if ((_e505 & 2139095040u) != 2139095040u) {
                            let _e508 = local_66;
                            if (_e508 == 2139095040u) {
                                let _e513 = global_3.member.member_5.member_1;
                                let _e518 = global_3.member.member_5.member;
                                let _e523 = global_3.member.member_5.member_2;
                                let _e529 = global_3.member.member_5.member_3;
                                phi_673_ = (0.5f * ((((2f * _e513) * _e518) / (_e523 - _e518)) * _e529));
                            } else {
                                let _e532 = local_66;
                                if (_e532 == 0u) {
                                    phi_636_ = false;
                                } else {
                                    let _e534 = local_66;
                                    phi_636_ = (_e534 <= 2139095040u);
                                }
                                let _e537 = phi_636_;
                                if _e537 {
                                    let _e541 = global_3.member.member_5.member_1;
                                    let _e546 = global_3.member.member_5.member;
                                    let _e551 = global_3.member.member_5.member_2;
                                    local_67 = _e551;
                                    let _e557 = global_3.member.member_5.member_3;
                                    let _e558 = ((((2f * _e541) * _e546) / (_e551 - _e546)) * _e557);
                                    local_68 = _e558;
                                    if (_e558 == 0f) {
                                        phi_664_ = 0f;
                                    } else {
                                        let _e560 = local_67;
                                        let _e561 = local_65;
                                        let _e564 = local_68;
                                        phi_664_ = (_e564 * (1f - (_e560 / _e561)));
                                    }
                                    let _e567 = phi_664_;
                                    phi_665_ = _e567;
                                } else {
                                    phi_665_ = bitcast<f32>(_e112);
                                }
                                let _e569 = phi_665_;
                                local_69 = _e569;
                                if (_e569 < 0f) {
                                    let _e571 = local_69;
                                    phi_671_ = -(_e571);
                                } else {
                                    phi_671_ = _e569;
                                }
                                let _e574 = phi_671_;
                                phi_673_ = (0.5f * _e574);
                            }
                            let _e577 = phi_673_;
                            let _e581 = select(_e577, 0f, ((bitcast<u32>(_e577) & 2147483647u) > 2139095040u));
                            local_73 = _e581;
                            if (_e581 > 0f) {
                                let _e583 = local_73;
                                local_70 = bitcast<u32>(_e583);
                                let _e585 = local_3;
                                if (0u < _e585) {
                                } else {
                                    phi_741_ = true;
                                    break;
                                }
                                let _e589 = local_70;
                                let _e590 = atomicMax((&global_6.member[0u]), _e589);
                            }
                        }
                        phi_743_ = _e502;
                    } else {
                        phi_743_ = _e134;
                    }
                    let _e592 = phi_743_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e593 = local_6;
                    let _e594 = local_5;
                    phi_742_ = _e592;
                    phi_110_ = (_e593 + _e594);
                } else {
                    phi_742_ = _e134;
                    phi_110_ = u32();
                }
                let _e597 = phi_742_;
                let _e599 = phi_110_;
                continue;
                continuing {
                    let _e600 = local_7;
                    phi_732_ = _e597;
                    phi_109_ = _e599;
                    phi_741_ = _e597;
                    break if !(_e600);
                }
            }
            let _e603 = phi_741_;
            if _e603 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn peel_band(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
