struct type_6 {
    member: array<u32>,
}

struct type_15 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_16 {
    member: type_15,
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
var<immediate> global_7: type_16;
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
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: bool;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: f32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: f32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: f32;
    var local_32: u32;
    var local_33: u32;
    var local_34: u32;
    var local_35: f32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: f32;
    var local_45: u32;
    var local_46: f32;
    var local_47: u32;
    var local_48: f32;
    var local_49: u32;
    var local_50: u32;
    var local_51: f32;
    var local_52: f32;
    var local_53: f32;
    var local_54: u32;
    var local_55: f32;
    var local_56: u32;
    var local_57: bool;
    var local_58: f32;
    var local_59: bool;
    var local_60: f32;
    var local_61: f32;
    var local_62: f32;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: u32;
    var local_67: u32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: u32;
    var local_72: bool;
    var local_73: u32;
    var local_74: f32;
    var local_75: f32;
    var local_76: f32;
    var local_77: f32;
    var local_78: f32;
    var local_79: f32;
    var local_80: f32;
    var phi_107_: u32;
    var phi_767_: bool;
    var phi_134_: u32;
    var phi_145_: u32;
    var phi_222_: f32;
    var phi_237_: f32;
    var phi_238_: f32;
    var phi_239_: f32;
    var phi_240_: f32;
    var phi_241_: bool;
    var phi_263_: f32;
    var phi_278_: f32;
    var phi_279_: f32;
    var phi_280_: f32;
    var phi_281_: f32;
    var phi_282_: bool;
    var phi_304_: f32;
    var phi_319_: f32;
    var phi_320_: f32;
    var phi_321_: f32;
    var phi_322_: f32;
    var phi_323_: bool;
    var phi_345_: f32;
    var phi_360_: f32;
    var phi_361_: f32;
    var phi_362_: f32;
    var phi_363_: f32;
    var phi_364_: bool;
    var phi_416_: f32;
    var phi_417_: f32;
    var phi_418_: f32;
    var phi_419_: f32;
    var phi_420_: bool;
    var phi_459_: f32;
    var phi_460_: f32;
    var phi_461_: f32;
    var phi_462_: f32;
    var phi_463_: bool;
    var phi_501_: f32;
    var phi_502_: f32;
    var phi_503_: f32;
    var phi_504_: f32;
    var phi_505_: bool;
    var phi_560_: array<f32, 4>;
    var phi_561_: array<f32, 4>;
    var phi_562_: array<f32, 4>;
    var phi_563_: array<f32, 4>;
    var phi_564_: bool;
    var phi_585_: f32;
    var phi_587_: array<f32, 4>;
    var phi_610_: f32;
    var phi_654_: f32;
    var phi_655_: f32;
    var phi_675_: f32;
    var phi_676_: f32;
    var phi_677_: f32;
    var phi_678_: f32;
    var phi_684_: f32;
    var phi_685_: f32;
    var phi_687_: f32;
    var phi_688_: bool;
    var phi_693_: f32;
    var phi_741_: u32;
    var phi_146_: u32;
    var phi_742_: bool;
    var phi_758_: bool;
    var phi_807_: bool;
    var phi_135_: u32;
    var phi_806_: bool;

    let _e132 = global_8;
    local_79 = bitcast<f32>(_e132);
    let _e134 = global_9;
    let _e135 = bitcast<f32>(_e134);
    local_80 = _e135;
    switch bitcast<i32>(0u) {
        default: {
            let _e137 = global;
            local = _e137;
            let _e138 = global_1;
            let _e139 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = arrayLength((&global_6.member));
            local_5 = _e138.x;
            local_6 = _e139.x;
            let _e154 = global_7.member.member;
            local_7 = _e154;
            let _e157 = global_7.member.member_2;
            local_8 = _e157;
            if (_e157 == 1u) {
                phi_107_ = 2u;
            } else {
                let _e159 = local_8;
                phi_107_ = select(0u, 1u, (_e159 == 2u));
            }
            let _e163 = phi_107_;
            local_9 = _e163;
            let _e166 = global_7.member.member_7;
            local_73 = select(3u, 4u, (_e166 == 1u));
            let _e171 = global_7.member.member_1;
            let _e172 = local_7;
            local_10 = (_e172 * _e171);
            let _e174 = local_6;
            local_11 = (_e174 * 256u);
            let _e176 = local;
            local_12 = (_e176 + 1u);
            let _e178 = local_5;
            phi_767_ = false;
            phi_134_ = (_e178 * 256u);
            loop {
                let _e181 = phi_767_;
                let _e183 = phi_134_;
                local_13 = _e183;
                let _e184 = local_13;
                let _e185 = local_10;
                let _e186 = (_e184 < _e185);
                local_14 = _e186;
                if _e186 {
                    let _e187 = local_13;
                    let _e188 = local;
                    phi_145_ = (_e187 + _e188);
                    loop {
                        let _e191 = phi_145_;
                        local_15 = _e191;
                        let _e192 = local_15;
                        let _e193 = local_10;
                        if (_e192 < _e193) {
                            let _e195 = local_13;
                            let _e196 = local_12;
                            let _e198 = local_15;
                            let _e199 = (_e198 < (_e195 + _e196));
                            if _e199 {
                                let _e200 = local_7;
                                if (_e200 == 0u) {
                                    phi_758_ = true;
                                    break;
                                }
                                let _e202 = local_9;
                                if (_e202 == 3u) {
                                    phi_563_ = array<f32, 4>();
                                    phi_564_ = true;
                                } else {
                                    let _e204 = local_9;
                                    let _e205 = (_e204 == 4u);
                                    if _e205 {
                                        phi_562_ = array<f32, 4>();
                                    } else {
                                        let _e206 = local_9;
                                        if (_e206 == 1u) {
                                            let _e208 = local_15;
                                            let _e209 = (2u * _e208);
                                            local_16 = _e209;
                                            let _e210 = local_1;
                                            if (_e209 < _e210) {
                                            } else {
                                                phi_758_ = true;
                                                break;
                                            }
                                            let _e212 = local_16;
                                            let _e214 = global_4.member[_e212];
                                            local_17 = _e214;
                                            let _e215 = local_16;
                                            let _e216 = (_e215 + 1u);
                                            local_18 = _e216;
                                            let _e217 = local_1;
                                            if (_e216 < _e217) {
                                            } else {
                                                phi_758_ = true;
                                                break;
                                            }
                                            let _e219 = local_18;
                                            let _e221 = global_4.member[_e219];
                                            local_19 = _e221;
                                            let _e222 = local_17;
                                            let _e223 = (_e222 & 65535u);
                                            local_20 = ((_e223 & 32768u) << bitcast<u32>(16i));
                                            let _e229 = ((_e223 >> bitcast<u32>(10i)) & 31u);
                                            local_21 = _e229;
                                            local_22 = (_e223 & 1023u);
                                            if (_e229 == 0u) {
                                                let _e232 = local_22;
                                                let _e233 = f32(_e232);
                                                local_23 = _e233;
                                                let _e235 = local_20;
                                                if (_e235 == 0u) {
                                                    phi_222_ = (_e233 * 0.000000059604645f);
                                                } else {
                                                    let _e237 = local_23;
                                                    phi_222_ = (_e237 * -0.000000059604645f);
                                                }
                                                let _e240 = phi_222_;
                                                phi_239_ = _e240;
                                                phi_240_ = f32();
                                                phi_241_ = true;
                                            } else {
                                                let _e241 = local_21;
                                                let _e242 = (_e241 == 31u);
                                                if _e242 {
                                                    let _e243 = local_20;
                                                    let _e245 = local_22;
                                                    phi_237_ = bitcast<f32>(((_e243 | 2139095040u) | (_e245 << bitcast<u32>(13i))));
                                                    phi_238_ = f32();
                                                } else {
                                                    let _e250 = local_21;
                                                    let _e254 = local_20;
                                                    let _e256 = local_22;
                                                    phi_237_ = f32();
                                                    phi_238_ = bitcast<f32>(((_e254 | ((_e250 + 112u) << bitcast<u32>(23i))) | (_e256 << bitcast<u32>(13i))));
                                                }
                                                let _e262 = phi_237_;
                                                let _e264 = phi_238_;
                                                phi_239_ = _e262;
                                                phi_240_ = _e264;
                                                phi_241_ = _e242;
                                            }
                                            let _e266 = phi_239_;
                                            let _e268 = phi_240_;
                                            let _e270 = phi_241_;
                                            local_74 = select(_e268, _e266, _e270);
                                            let _e272 = local_17;
                                            let _e274 = (_e272 >> bitcast<u32>(16i));
                                            local_24 = ((_e274 & 32768u) << bitcast<u32>(16i));
                                            let _e280 = ((_e274 >> bitcast<u32>(10i)) & 31u);
                                            local_25 = _e280;
                                            local_26 = (_e274 & 1023u);
                                            if (_e280 == 0u) {
                                                let _e283 = local_26;
                                                let _e284 = f32(_e283);
                                                local_27 = _e284;
                                                let _e286 = local_24;
                                                if (_e286 == 0u) {
                                                    phi_263_ = (_e284 * 0.000000059604645f);
                                                } else {
                                                    let _e288 = local_27;
                                                    phi_263_ = (_e288 * -0.000000059604645f);
                                                }
                                                let _e291 = phi_263_;
                                                phi_280_ = _e291;
                                                phi_281_ = f32();
                                                phi_282_ = true;
                                            } else {
                                                let _e292 = local_25;
                                                let _e293 = (_e292 == 31u);
                                                if _e293 {
                                                    let _e294 = local_24;
                                                    let _e296 = local_26;
                                                    phi_278_ = bitcast<f32>(((_e294 | 2139095040u) | (_e296 << bitcast<u32>(13i))));
                                                    phi_279_ = f32();
                                                } else {
                                                    let _e301 = local_25;
                                                    let _e305 = local_24;
                                                    let _e307 = local_26;
                                                    phi_278_ = f32();
                                                    phi_279_ = bitcast<f32>(((_e305 | ((_e301 + 112u) << bitcast<u32>(23i))) | (_e307 << bitcast<u32>(13i))));
                                                }
                                                let _e313 = phi_278_;
                                                let _e315 = phi_279_;
                                                phi_280_ = _e313;
                                                phi_281_ = _e315;
                                                phi_282_ = _e293;
                                            }
                                            let _e317 = phi_280_;
                                            let _e319 = phi_281_;
                                            let _e321 = phi_282_;
                                            local_75 = select(_e319, _e317, _e321);
                                            let _e323 = local_19;
                                            let _e324 = (_e323 & 65535u);
                                            local_28 = ((_e324 & 32768u) << bitcast<u32>(16i));
                                            let _e330 = ((_e324 >> bitcast<u32>(10i)) & 31u);
                                            local_29 = _e330;
                                            local_30 = (_e324 & 1023u);
                                            if (_e330 == 0u) {
                                                let _e333 = local_30;
                                                let _e334 = f32(_e333);
                                                local_31 = _e334;
                                                let _e336 = local_28;
                                                if (_e336 == 0u) {
                                                    phi_304_ = (_e334 * 0.000000059604645f);
                                                } else {
                                                    let _e338 = local_31;
                                                    phi_304_ = (_e338 * -0.000000059604645f);
                                                }
                                                let _e341 = phi_304_;
                                                phi_321_ = _e341;
                                                phi_322_ = f32();
                                                phi_323_ = true;
                                            } else {
                                                let _e342 = local_29;
                                                let _e343 = (_e342 == 31u);
                                                if _e343 {
                                                    let _e344 = local_28;
                                                    let _e346 = local_30;
                                                    phi_319_ = bitcast<f32>(((_e344 | 2139095040u) | (_e346 << bitcast<u32>(13i))));
                                                    phi_320_ = f32();
                                                } else {
                                                    let _e351 = local_29;
                                                    let _e355 = local_28;
                                                    let _e357 = local_30;
                                                    phi_319_ = f32();
                                                    phi_320_ = bitcast<f32>(((_e355 | ((_e351 + 112u) << bitcast<u32>(23i))) | (_e357 << bitcast<u32>(13i))));
                                                }
                                                let _e363 = phi_319_;
                                                let _e365 = phi_320_;
                                                phi_321_ = _e363;
                                                phi_322_ = _e365;
                                                phi_323_ = _e343;
                                            }
                                            let _e367 = phi_321_;
                                            let _e369 = phi_322_;
                                            let _e371 = phi_323_;
                                            local_76 = select(_e369, _e367, _e371);
                                            let _e373 = local_19;
                                            let _e375 = (_e373 >> bitcast<u32>(16i));
                                            local_32 = ((_e375 & 32768u) << bitcast<u32>(16i));
                                            let _e381 = ((_e375 >> bitcast<u32>(10i)) & 31u);
                                            local_33 = _e381;
                                            local_34 = (_e375 & 1023u);
                                            if (_e381 == 0u) {
                                                let _e384 = local_34;
                                                let _e385 = f32(_e384);
                                                local_35 = _e385;
                                                let _e387 = local_32;
                                                if (_e387 == 0u) {
                                                    phi_345_ = (_e385 * 0.000000059604645f);
                                                } else {
                                                    let _e389 = local_35;
                                                    phi_345_ = (_e389 * -0.000000059604645f);
                                                }
                                                let _e392 = phi_345_;
                                                phi_362_ = _e392;
                                                phi_363_ = f32();
                                                phi_364_ = true;
                                            } else {
                                                let _e393 = local_33;
                                                let _e394 = (_e393 == 31u);
                                                if _e394 {
                                                    let _e395 = local_32;
                                                    let _e397 = local_34;
                                                    phi_360_ = bitcast<f32>(((_e395 | 2139095040u) | (_e397 << bitcast<u32>(13i))));
                                                    phi_361_ = f32();
                                                } else {
                                                    let _e402 = local_33;
                                                    let _e406 = local_32;
                                                    let _e408 = local_34;
                                                    phi_360_ = f32();
                                                    phi_361_ = bitcast<f32>(((_e406 | ((_e402 + 112u) << bitcast<u32>(23i))) | (_e408 << bitcast<u32>(13i))));
                                                }
                                                let _e414 = phi_360_;
                                                let _e416 = phi_361_;
                                                phi_362_ = _e414;
                                                phi_363_ = _e416;
                                                phi_364_ = _e394;
                                            }
                                            let _e418 = phi_362_;
                                            let _e420 = phi_363_;
                                            let _e422 = phi_364_;
                                            let _e424 = local_74;
                                            let _e425 = local_75;
                                            let _e426 = local_76;
                                            phi_561_ = array<f32, 4>(_e424, _e425, _e426, select(_e420, _e418, _e422));
                                        } else {
                                            let _e428 = local_9;
                                            if (_e428 == 2u) {
                                                let _e430 = local_15;
                                                let _e431 = local_1;
                                                if (_e430 < _e431) {
                                                } else {
                                                    phi_758_ = true;
                                                    break;
                                                }
                                                let _e433 = local_15;
                                                let _e435 = global_4.member[_e433];
                                                local_36 = _e435;
                                                let _e436 = (_e435 & 2047u);
                                                let _e439 = ((_e436 >> bitcast<u32>(6u)) & 31u);
                                                local_37 = _e439;
                                                local_38 = (_e436 & 63u);
                                                if (_e439 == 0u) {
                                                    let _e442 = local_38;
                                                    phi_418_ = (f32(_e442) * 0.0000009536743f);
                                                    phi_419_ = f32();
                                                    phi_420_ = true;
                                                } else {
                                                    let _e445 = local_37;
                                                    let _e446 = (_e445 == 31u);
                                                    if _e446 {
                                                        let _e447 = local_38;
                                                        phi_416_ = bitcast<f32>((2139095040u | (_e447 << bitcast<u32>(17u))));
                                                        phi_417_ = f32();
                                                    } else {
                                                        let _e452 = local_37;
                                                        let _e456 = local_38;
                                                        phi_416_ = f32();
                                                        phi_417_ = bitcast<f32>((((_e452 + 112u) << bitcast<u32>(23i)) | (_e456 << bitcast<u32>(17u))));
                                                    }
                                                    let _e462 = phi_416_;
                                                    let _e464 = phi_417_;
                                                    phi_418_ = _e462;
                                                    phi_419_ = _e464;
                                                    phi_420_ = _e446;
                                                }
                                                let _e466 = phi_418_;
                                                let _e468 = phi_419_;
                                                let _e470 = phi_420_;
                                                local_77 = select(_e468, _e466, _e470);
                                                let _e472 = local_36;
                                                let _e475 = ((_e472 >> bitcast<u32>(11i)) & 2047u);
                                                let _e478 = ((_e475 >> bitcast<u32>(6u)) & 31u);
                                                local_39 = _e478;
                                                local_40 = (_e475 & 63u);
                                                if (_e478 == 0u) {
                                                    let _e481 = local_40;
                                                    phi_461_ = (f32(_e481) * 0.0000009536743f);
                                                    phi_462_ = f32();
                                                    phi_463_ = true;
                                                } else {
                                                    let _e484 = local_39;
                                                    let _e485 = (_e484 == 31u);
                                                    if _e485 {
                                                        let _e486 = local_40;
                                                        phi_459_ = bitcast<f32>((2139095040u | (_e486 << bitcast<u32>(17u))));
                                                        phi_460_ = f32();
                                                    } else {
                                                        let _e491 = local_39;
                                                        let _e495 = local_40;
                                                        phi_459_ = f32();
                                                        phi_460_ = bitcast<f32>((((_e491 + 112u) << bitcast<u32>(23i)) | (_e495 << bitcast<u32>(17u))));
                                                    }
                                                    let _e501 = phi_459_;
                                                    let _e503 = phi_460_;
                                                    phi_461_ = _e501;
                                                    phi_462_ = _e503;
                                                    phi_463_ = _e485;
                                                }
                                                let _e505 = phi_461_;
                                                let _e507 = phi_462_;
                                                let _e509 = phi_463_;
                                                local_78 = select(_e507, _e505, _e509);
                                                let _e511 = local_36;
                                                let _e513 = (_e511 >> bitcast<u32>(22i));
                                                let _e516 = ((_e513 >> bitcast<u32>(5u)) & 31u);
                                                local_41 = _e516;
                                                local_42 = (_e513 & 31u);
                                                if (_e516 == 0u) {
                                                    let _e519 = local_42;
                                                    phi_503_ = (f32(_e519) * 0.0000019073486f);
                                                    phi_504_ = f32();
                                                    phi_505_ = true;
                                                } else {
                                                    let _e522 = local_41;
                                                    let _e523 = (_e522 == 31u);
                                                    if _e523 {
                                                        let _e524 = local_42;
                                                        phi_501_ = bitcast<f32>((2139095040u | (_e524 << bitcast<u32>(18u))));
                                                        phi_502_ = f32();
                                                    } else {
                                                        let _e529 = local_41;
                                                        let _e533 = local_42;
                                                        phi_501_ = f32();
                                                        phi_502_ = bitcast<f32>((((_e529 + 112u) << bitcast<u32>(23i)) | (_e533 << bitcast<u32>(18u))));
                                                    }
                                                    let _e539 = phi_501_;
                                                    let _e541 = phi_502_;
                                                    phi_503_ = _e539;
                                                    phi_504_ = _e541;
                                                    phi_505_ = _e523;
                                                }
                                                let _e543 = phi_503_;
                                                let _e545 = phi_504_;
                                                let _e547 = phi_505_;
                                                let _e549 = local_77;
                                                let _e550 = local_78;
                                                phi_560_ = array<f32, 4>(_e549, _e550, select(_e545, _e543, _e547), 1f);
                                            } else {
                                                let _e552 = local_15;
                                                let _e553 = (4u * _e552);
                                                local_43 = _e553;
                                                let _e554 = local_1;
                                                if (_e553 < _e554) {
                                                } else {
                                                    phi_758_ = true;
                                                    break;
                                                }
                                                let _e556 = local_43;
                                                let _e558 = global_4.member[_e556];
                                                local_44 = bitcast<f32>(_e558);
                                                let _e560 = local_43;
                                                let _e561 = (_e560 + 1u);
                                                local_45 = _e561;
                                                let _e562 = local_1;
                                                if (_e561 < _e562) {
                                                } else {
                                                    phi_758_ = true;
                                                    break;
                                                }
                                                let _e564 = local_45;
                                                let _e566 = global_4.member[_e564];
                                                local_46 = bitcast<f32>(_e566);
                                                let _e568 = local_43;
                                                let _e569 = (_e568 + 2u);
                                                local_47 = _e569;
                                                let _e570 = local_1;
                                                if (_e569 < _e570) {
                                                } else {
                                                    phi_758_ = true;
                                                    break;
                                                }
                                                let _e572 = local_47;
                                                let _e574 = global_4.member[_e572];
                                                local_48 = bitcast<f32>(_e574);
                                                let _e576 = local_43;
                                                let _e577 = (_e576 + 3u);
                                                local_49 = _e577;
                                                let _e578 = local_1;
                                                if (_e577 < _e578) {
                                                } else {
                                                    phi_758_ = true;
                                                    break;
                                                }
                                                let _e580 = local_49;
                                                let _e582 = global_4.member[_e580];
                                                let _e584 = local_44;
                                                let _e585 = local_46;
                                                let _e586 = local_48;
                                                phi_560_ = array<f32, 4>(_e584, _e585, _e586, bitcast<f32>(_e582));
                                            }
                                            let _e589 = phi_560_;
                                            phi_561_ = _e589;
                                        }
                                        let _e591 = phi_561_;
                                        phi_562_ = _e591;
                                    }
                                    let _e593 = phi_562_;
                                    phi_563_ = _e593;
                                    phi_564_ = _e205;
                                }
                                let _e595 = phi_563_;
                                let _e597 = phi_564_;
                                if _e597 {
                                    let _e598 = local_15;
                                    let _e599 = local_1;
                                    if (_e598 < _e599) {
                                    } else {
                                        phi_758_ = true;
                                        break;
                                    }
                                    let _e601 = local_15;
                                    let _e603 = global_4.member[_e601];
                                    local_50 = _e603;
                                    let _e604 = local_9;
                                    if (_e604 == 4u) {
                                        let _e606 = local_50;
                                        phi_585_ = (f32((_e606 & 16777215u)) * 0.00000005960465f);
                                    } else {
                                        let _e610 = local_50;
                                        phi_585_ = bitcast<f32>(_e610);
                                    }
                                    let _e613 = phi_585_;
                                    phi_587_ = array<f32, 4>(_e613, 0f, 0f, 1f);
                                } else {
                                    phi_587_ = _e595;
                                }
                                let _e616 = phi_587_;
                                local_51 = _e616[0];
                                local_52 = _e616[1];
                                local_53 = _e616[2];
                                let _e620 = local_15;
                                let _e621 = local_2;
                                if (_e620 < _e621) {
                                } else {
                                    phi_758_ = true;
                                    break;
                                }
                                let _e623 = local_15;
                                let _e625 = global_3.member[_e623];
                                local_54 = _e625;
                                let _e626 = local_73;
                                if (_e626 == 4u) {
                                    let _e628 = local_54;
                                    phi_610_ = (f32((_e628 & 16777215u)) * 0.00000005960465f);
                                } else {
                                    let _e632 = local_54;
                                    phi_610_ = bitcast<f32>(_e632);
                                }
                                let _e635 = phi_610_;
                                local_55 = _e635;
                                let _e638 = global_7.member.member_3;
                                local_56 = _e638;
                                if (_e638 == 0u) {
                                    phi_693_ = _e635;
                                } else {
                                    let _e640 = local_55;
                                    if (_e640 >= 0f) {
                                        let _e642 = local_55;
                                        let _e643 = (_e642 <= 1f);
                                        local_57 = _e643;
                                        if _e643 {
                                            let _e646 = global_7.member.member_5;
                                            local_58 = _e646;
                                            let _e647 = local_80;
                                            local_59 = (_e646 == _e647);
                                            let _e649 = local_56;
                                            if (_e649 == 1u) {
                                                let _e651 = local_59;
                                                if _e651 {
                                                    let _e654 = global_7.member.member_4;
                                                    let _e655 = local_55;
                                                    phi_654_ = (1f - _e655);
                                                    phi_655_ = _e654;
                                                } else {
                                                    let _e659 = global_7.member.member_4;
                                                    let _e660 = local_58;
                                                    let _e662 = local_58;
                                                    let _e664 = local_55;
                                                    let _e666 = local_58;
                                                    phi_654_ = (_e666 - (_e664 * (_e662 - _e659)));
                                                    phi_655_ = (_e659 * _e660);
                                                }
                                                let _e669 = phi_654_;
                                                let _e671 = phi_655_;
                                                phi_677_ = _e669;
                                                phi_678_ = _e671;
                                            } else {
                                                let _e672 = local_59;
                                                if _e672 {
                                                    let _e675 = global_7.member.member_4;
                                                    phi_675_ = _e635;
                                                    phi_676_ = _e675;
                                                } else {
                                                    let _e678 = global_7.member.member_4;
                                                    let _e679 = local_58;
                                                    let _e681 = local_58;
                                                    let _e683 = local_55;
                                                    phi_675_ = (_e678 + (_e683 * (_e681 - _e678)));
                                                    phi_676_ = (_e678 * _e679);
                                                }
                                                let _e687 = phi_675_;
                                                let _e689 = phi_676_;
                                                phi_677_ = _e687;
                                                phi_678_ = _e689;
                                            }
                                            let _e691 = phi_677_;
                                            let _e693 = phi_678_;
                                            local_60 = _e691;
                                            local_61 = _e693;
                                            if (_e691 <= 0f) {
                                                phi_684_ = _e135;
                                            } else {
                                                let _e695 = local_61;
                                                let _e696 = local_60;
                                                phi_684_ = (_e695 / _e696);
                                            }
                                            let _e699 = phi_684_;
                                            phi_685_ = _e699;
                                        } else {
                                            phi_685_ = f32();
                                        }
                                        let _e701 = phi_685_;
                                        let _e702 = local_57;
                                        phi_687_ = _e701;
                                        phi_688_ = select(true, false, _e702);
                                    } else {
                                        phi_687_ = f32();
                                        phi_688_ = true;
                                    }
                                    let _e705 = phi_687_;
                                    let _e707 = phi_688_;
                                    let _e708 = local_79;
                                    phi_693_ = select(_e705, _e708, _e707);
                                }
                                let _e711 = phi_693_;
                                local_62 = _e711;
                                let _e712 = local_15;
                                let _e713 = (5u * _e712);
                                local_63 = _e713;
                                let _e714 = local_51;
                                local_64 = bitcast<u32>(_e714);
                                let _e716 = local_3;
                                if (_e713 < _e716) {
                                } else {
                                    phi_758_ = true;
                                    break;
                                }
                                let _e718 = local_63;
                                let _e721 = local_64;
                                global_5.member[_e718] = _e721;
                                let _e722 = local_63;
                                let _e723 = (_e722 + 1u);
                                local_65 = _e723;
                                let _e724 = local_52;
                                local_66 = bitcast<u32>(_e724);
                                let _e726 = local_3;
                                if (_e723 < _e726) {
                                } else {
                                    phi_758_ = true;
                                    break;
                                }
                                let _e728 = local_65;
                                let _e731 = local_66;
                                global_5.member[_e728] = _e731;
                                let _e732 = local_63;
                                let _e733 = (_e732 + 2u);
                                local_67 = _e733;
                                let _e734 = local_53;
                                local_68 = bitcast<u32>(_e734);
                                let _e736 = local_3;
                                if (_e733 < _e736) {
                                } else {
                                    phi_758_ = true;
                                    break;
                                }
                                let _e738 = local_67;
                                let _e741 = local_68;
                                global_5.member[_e738] = _e741;
                                let _e742 = local_63;
                                let _e743 = (_e742 + 3u);
                                local_69 = _e743;
                                let _e744 = local_62;
                                local_70 = bitcast<u32>(_e744);
                                let _e746 = local_3;
                                if (_e743 < _e746) {
                                } else {
                                    phi_758_ = true;
                                    break;
                                }
                                let _e748 = local_69;
                                let _e751 = local_70;
                                global_5.member[_e748] = _e751;
                                let _e752 = local_63;
                                let _e753 = (_e752 + 4u);
                                local_71 = _e753;
                                let _e754 = local_3;
                                if (_e753 < _e754) {
                                } else {
                                    phi_758_ = true;
                                    break;
                                }
                                let _e756 = local_71;
                                global_5.member[_e756] = 1065353216u;
                                let _e759 = local_15;
                                let _e760 = local_4;
                                if (_e759 < _e760) {
                                } else {
                                    phi_758_ = true;
                                    break;
                                }
                                let _e762 = local_15;
                                global_6.member[_e762] = 1u;
                                let _e765 = local_15;
                                phi_741_ = (_e765 + 1u);
                            } else {
                                phi_741_ = u32();
                            }
                            let _e768 = phi_741_;
                            phi_146_ = _e768;
                            phi_742_ = _e199;
                        } else {
                            phi_146_ = u32();
                            phi_742_ = false;
                        }
                        let _e770 = phi_146_;
                        let _e772 = phi_742_;
                        local_72 = _e772;
                        continue;
                        continuing {
                            let _e773 = local_72;
                            phi_145_ = _e770;
                            phi_758_ = _e181;
                            break if !(_e773);
                        }
                    }
                    let _e776 = phi_758_;
                    phi_806_ = _e776;
                    if _e776 {
                        break;
                    }
                    let _e777 = local_13;
                    let _e778 = local_11;
                    phi_807_ = _e776;
                    phi_135_ = (_e777 + _e778);
                } else {
                    phi_807_ = _e181;
                    phi_135_ = u32();
                }
                let _e781 = phi_807_;
                let _e783 = phi_135_;
                continue;
                continuing {
                    let _e784 = local_14;
                    phi_767_ = _e781;
                    phi_134_ = _e783;
                    phi_806_ = _e781;
                    break if !(_e784);
                }
            }
            let _e787 = phi_806_;
            if _e787 {
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
