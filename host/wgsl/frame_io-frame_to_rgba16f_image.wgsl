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
@group(0) @binding(0) 
var<storage> global_3: type_6;
var<immediate> global_4: type_15;
@group(0) @binding(1) 
var global_5: texture_storage_2d<rgba16float,read_write>;
var<private> global_6: u32 = 2139095040u;

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
    var local_9: bool;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: f32;
    var local_14: u32;
    var local_15: f32;
    var local_16: u32;
    var local_17: f32;
    var local_18: bool;
    var local_19: u32;
    var local_20: i32;
    var local_21: u32;
    var local_22: i32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: f32;
    var local_32: u32;
    var local_33: i32;
    var local_34: u32;
    var local_35: i32;
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
    var local_57: f32;
    var local_58: f32;
    var local_59: f32;
    var local_60: f32;
    var phi_908_: bool;
    var phi_93_: u32;
    var phi_104_: u32;
    var phi_402_: bool;
    var phi_404_: bool;
    var phi_379_: bool;
    var phi_381_: bool;
    var phi_386_: u32;
    var phi_409_: u32;
    var phi_410_: u32;
    var phi_412_: u32;
    var phi_413_: u32;
    var phi_414_: bool;
    var phi_419_: u32;
    var phi_420_: u32;
    var phi_421_: bool;
    var phi_456_: f32;
    var phi_457_: f32;
    var phi_440_: f32;
    var phi_459_: f32;
    var phi_460_: f32;
    var phi_461_: bool;
    var phi_540_: bool;
    var phi_542_: bool;
    var phi_517_: bool;
    var phi_519_: bool;
    var phi_524_: u32;
    var phi_547_: u32;
    var phi_548_: u32;
    var phi_550_: u32;
    var phi_551_: u32;
    var phi_552_: bool;
    var phi_557_: u32;
    var phi_558_: u32;
    var phi_559_: bool;
    var phi_594_: f32;
    var phi_595_: f32;
    var phi_578_: f32;
    var phi_597_: f32;
    var phi_598_: f32;
    var phi_599_: bool;
    var phi_678_: bool;
    var phi_680_: bool;
    var phi_655_: bool;
    var phi_657_: bool;
    var phi_662_: u32;
    var phi_685_: u32;
    var phi_686_: u32;
    var phi_688_: u32;
    var phi_689_: u32;
    var phi_690_: bool;
    var phi_695_: u32;
    var phi_696_: u32;
    var phi_697_: bool;
    var phi_732_: f32;
    var phi_733_: f32;
    var phi_716_: f32;
    var phi_735_: f32;
    var phi_736_: f32;
    var phi_737_: bool;
    var phi_870_: f32;
    var phi_871_: f32;
    var phi_854_: f32;
    var phi_873_: f32;
    var phi_874_: f32;
    var phi_875_: bool;
    var phi_172_: u32;
    var phi_105_: u32;
    var phi_173_: bool;
    var phi_880_: bool;
    var phi_942_: bool;
    var phi_94_: u32;
    var phi_941_: bool;

    let _e105 = global_6;
    switch bitcast<i32>(0u) {
        default: {
            let _e108 = global;
            local = _e108;
            let _e109 = global_1;
            let _e110 = global_2;
            local_1 = arrayLength((&global_3.member));
            let _e117 = global_4.member.member;
            local_2 = _e117;
            let _e120 = global_4.member.member_1;
            local_3 = (_e117 * _e120);
            local_4 = (_e110.x * 256u);
            local_5 = (_e108 + 1u);
            phi_908_ = false;
            phi_93_ = (_e109.x * 256u);
            loop {
                let _e126 = phi_908_;
                let _e128 = phi_93_;
                local_6 = _e128;
                let _e129 = local_6;
                let _e130 = local_3;
                let _e131 = (_e129 < _e130);
                local_7 = _e131;
                if _e131 {
                    let _e132 = local_6;
                    let _e133 = local;
                    phi_104_ = (_e132 + _e133);
                    loop {
                        let _e136 = phi_104_;
                        local_8 = _e136;
                        let _e137 = local_8;
                        let _e138 = local_3;
                        if (_e137 < _e138) {
                            let _e140 = local_6;
                            let _e141 = local_5;
                            let _e143 = local_8;
                            let _e144 = (_e143 < (_e140 + _e141));
                            if _e144 {
                                let _e145 = local_2;
                                let _e146 = (_e145 == 0u);
                                local_9 = _e146;
                                if _e146 {
                                    phi_880_ = true;
                                    break;
                                }
                                let _e147 = local_8;
                                let _e148 = local_2;
                                local_10 = (_e147 % _e148);
                                let _e150 = local_9;
                                if _e150 {
                                    phi_880_ = true;
                                    break;
                                }
                                let _e151 = local_8;
                                let _e152 = local_2;
                                local_11 = (_e151 / _e152);
                                let _e154 = local_8;
                                let _e155 = (3u * _e154);
                                local_12 = _e155;
                                let _e156 = local_1;
                                if (_e155 < _e156) {
                                } else {
                                    phi_880_ = true;
                                    break;
                                }
                                let _e158 = local_12;
                                let _e161 = global_3.member[_e158];
                                local_13 = bitcast<f32>(_e161);
                                let _e163 = local_12;
                                let _e164 = (_e163 + 1u);
                                local_14 = _e164;
                                let _e165 = local_1;
                                if (_e164 < _e165) {
                                } else {
                                    phi_880_ = true;
                                    break;
                                }
                                let _e167 = local_14;
                                let _e170 = global_3.member[_e167];
                                local_15 = bitcast<f32>(_e170);
                                let _e172 = local_12;
                                let _e173 = (_e172 + 2u);
                                local_16 = _e173;
                                let _e174 = local_1;
                                if (_e173 < _e174) {
                                } else {
                                    phi_880_ = true;
                                    break;
                                }
                                let _e176 = local_16;
                                let _e179 = global_3.member[_e176];
                                local_17 = bitcast<f32>(_e179);
                                let _e181 = local_13;
                                let _e182 = bitcast<u32>(_e181);
                                let _e185 = ((_e182 >> bitcast<u32>(16i)) & 32768u);
                                local_19 = _e185;
                                let _e189 = bitcast<i32>(((_e182 >> bitcast<u32>(23i)) & 255u));
                                local_20 = _e189;
                                local_21 = (_e182 & 8388607u);
                                if (_e189 == 255i) {
                                    let _e270 = local_19;
                                    let _e272 = local_21;
                                    phi_419_ = ((_e270 | 31744u) | select(512u, 0u, (_e272 == 0u)));
                                    phi_420_ = u32();
                                    phi_421_ = true;
                                } else {
                                    let _e192 = local_20;
                                    let _e193 = (_e192 + -112i);
                                    local_22 = _e193;
                                    if (_e193 >= 31i) {
                                        let _e262 = local_19;
                                        phi_412_ = (_e262 | 31744u);
                                        phi_413_ = u32();
                                        phi_414_ = true;
                                    } else {
                                        let _e195 = local_22;
                                        let _e196 = (_e195 <= 0i);
                                        if _e196 {
                                            let _e222 = local_22;
                                            if (_e222 < -10i) {
                                                phi_386_ = _e185;
                                            } else {
                                                let _e224 = local_21;
                                                let _e225 = (_e224 | 8388608u);
                                                let _e226 = local_20;
                                                let _e228 = bitcast<u32>((126i - _e226));
                                                let _e229 = (_e228 & 31u);
                                                local_23 = (_e225 >> bitcast<u32>(_e229));
                                                let _e235 = (_e225 & ((1u << bitcast<u32>(_e229)) - 1u));
                                                local_24 = _e235;
                                                let _e239 = (1u << bitcast<u32>(((_e228 - 1u) & 31u)));
                                                local_25 = _e239;
                                                if (_e235 > _e239) {
                                                    phi_381_ = true;
                                                } else {
                                                    let _e241 = local_24;
                                                    let _e242 = local_25;
                                                    if (_e241 == _e242) {
                                                        let _e244 = local_23;
                                                        phi_379_ = ((_e244 & 1u) == 1u);
                                                    } else {
                                                        phi_379_ = false;
                                                    }
                                                    let _e248 = phi_379_;
                                                    phi_381_ = _e248;
                                                }
                                                let _e250 = phi_381_;
                                                let _e252 = local_23;
                                                let _e254 = local_19;
                                                phi_386_ = (_e254 | (_e252 + select(0u, 1u, _e250)));
                                            }
                                            let _e257 = phi_386_;
                                            phi_409_ = _e257;
                                            phi_410_ = u32();
                                        } else {
                                            let _e197 = local_22;
                                            let _e201 = local_21;
                                            local_26 = ((bitcast<u32>(_e197) << bitcast<u32>(10i)) | (_e201 >> bitcast<u32>(13i)));
                                            let _e205 = local_21;
                                            let _e206 = (_e205 & 8191u);
                                            local_27 = _e206;
                                            if (_e206 > 4096u) {
                                                phi_404_ = true;
                                            } else {
                                                let _e208 = local_27;
                                                if (_e208 == 4096u) {
                                                    let _e210 = local_26;
                                                    phi_402_ = ((_e210 & 1u) == 1u);
                                                } else {
                                                    phi_402_ = false;
                                                }
                                                let _e214 = phi_402_;
                                                phi_404_ = _e214;
                                            }
                                            let _e216 = phi_404_;
                                            let _e218 = local_26;
                                            let _e220 = local_19;
                                            phi_409_ = u32();
                                            phi_410_ = (_e220 | (_e218 + select(0u, 1u, _e216)));
                                        }
                                        let _e259 = phi_409_;
                                        let _e261 = phi_410_;
                                        phi_412_ = _e259;
                                        phi_413_ = _e261;
                                        phi_414_ = _e196;
                                    }
                                    let _e265 = phi_412_;
                                    let _e267 = phi_413_;
                                    let _e269 = phi_414_;
                                    phi_419_ = _e265;
                                    phi_420_ = _e267;
                                    phi_421_ = _e269;
                                }
                                let _e277 = phi_419_;
                                let _e279 = phi_420_;
                                let _e281 = phi_421_;
                                let _e282 = select(_e279, _e277, _e281);
                                local_28 = ((_e282 & 32768u) << bitcast<u32>(16i));
                                let _e288 = ((_e282 >> bitcast<u32>(10i)) & 31u);
                                local_29 = _e288;
                                local_30 = (_e282 & 1023u);
                                if (_e288 == 0u) {
                                    let _e315 = local_30;
                                    let _e316 = f32(_e315);
                                    local_31 = _e316;
                                    let _e318 = local_28;
                                    if (_e318 == 0u) {
                                        phi_440_ = (_e316 * 0.000000059604645f);
                                    } else {
                                        let _e320 = local_31;
                                        phi_440_ = (_e320 * -0.000000059604645f);
                                    }
                                    let _e323 = phi_440_;
                                    phi_459_ = _e323;
                                    phi_460_ = f32();
                                    phi_461_ = true;
                                } else {
                                    let _e291 = local_29;
                                    let _e292 = (_e291 == 31u);
                                    if _e292 {
                                        let _e304 = local_28;
                                        let _e306 = local_30;
                                        phi_456_ = bitcast<f32>(((_e304 | 2139095040u) | (_e306 << bitcast<u32>(13i))));
                                        phi_457_ = f32();
                                    } else {
                                        let _e293 = local_29;
                                        let _e297 = local_28;
                                        let _e299 = local_30;
                                        phi_456_ = f32();
                                        phi_457_ = bitcast<f32>(((_e297 | ((_e293 + 112u) << bitcast<u32>(23i))) | (_e299 << bitcast<u32>(13i))));
                                    }
                                    let _e312 = phi_456_;
                                    let _e314 = phi_457_;
                                    phi_459_ = _e312;
                                    phi_460_ = _e314;
                                    phi_461_ = _e292;
                                }
                                let _e325 = phi_459_;
                                let _e327 = phi_460_;
                                let _e329 = phi_461_;
                                local_58 = select(_e327, _e325, _e329);
                                let _e331 = local_15;
                                let _e332 = bitcast<u32>(_e331);
                                let _e335 = ((_e332 >> bitcast<u32>(16i)) & 32768u);
                                local_32 = _e335;
                                let _e339 = bitcast<i32>(((_e332 >> bitcast<u32>(23i)) & 255u));
                                local_33 = _e339;
                                local_34 = (_e332 & 8388607u);
                                if (_e339 == 255i) {
                                    let _e420 = local_32;
                                    let _e422 = local_34;
                                    phi_557_ = ((_e420 | 31744u) | select(512u, 0u, (_e422 == 0u)));
                                    phi_558_ = u32();
                                    phi_559_ = true;
                                } else {
                                    let _e342 = local_33;
                                    let _e343 = (_e342 + -112i);
                                    local_35 = _e343;
                                    if (_e343 >= 31i) {
                                        let _e412 = local_32;
                                        phi_550_ = (_e412 | 31744u);
                                        phi_551_ = u32();
                                        phi_552_ = true;
                                    } else {
                                        let _e345 = local_35;
                                        let _e346 = (_e345 <= 0i);
                                        if _e346 {
                                            let _e372 = local_35;
                                            if (_e372 < -10i) {
                                                phi_524_ = _e335;
                                            } else {
                                                let _e374 = local_34;
                                                let _e375 = (_e374 | 8388608u);
                                                let _e376 = local_33;
                                                let _e378 = bitcast<u32>((126i - _e376));
                                                let _e379 = (_e378 & 31u);
                                                local_36 = (_e375 >> bitcast<u32>(_e379));
                                                let _e385 = (_e375 & ((1u << bitcast<u32>(_e379)) - 1u));
                                                local_37 = _e385;
                                                let _e389 = (1u << bitcast<u32>(((_e378 - 1u) & 31u)));
                                                local_38 = _e389;
                                                if (_e385 > _e389) {
                                                    phi_519_ = true;
                                                } else {
                                                    let _e391 = local_37;
                                                    let _e392 = local_38;
                                                    if (_e391 == _e392) {
                                                        let _e394 = local_36;
                                                        phi_517_ = ((_e394 & 1u) == 1u);
                                                    } else {
                                                        phi_517_ = false;
                                                    }
                                                    let _e398 = phi_517_;
                                                    phi_519_ = _e398;
                                                }
                                                let _e400 = phi_519_;
                                                let _e402 = local_36;
                                                let _e404 = local_32;
                                                phi_524_ = (_e404 | (_e402 + select(0u, 1u, _e400)));
                                            }
                                            let _e407 = phi_524_;
                                            phi_547_ = _e407;
                                            phi_548_ = u32();
                                        } else {
                                            let _e347 = local_35;
                                            let _e351 = local_34;
                                            local_39 = ((bitcast<u32>(_e347) << bitcast<u32>(10i)) | (_e351 >> bitcast<u32>(13i)));
                                            let _e355 = local_34;
                                            let _e356 = (_e355 & 8191u);
                                            local_40 = _e356;
                                            if (_e356 > 4096u) {
                                                phi_542_ = true;
                                            } else {
                                                let _e358 = local_40;
                                                if (_e358 == 4096u) {
                                                    let _e360 = local_39;
                                                    phi_540_ = ((_e360 & 1u) == 1u);
                                                } else {
                                                    phi_540_ = false;
                                                }
                                                let _e364 = phi_540_;
                                                phi_542_ = _e364;
                                            }
                                            let _e366 = phi_542_;
                                            let _e368 = local_39;
                                            let _e370 = local_32;
                                            phi_547_ = u32();
                                            phi_548_ = (_e370 | (_e368 + select(0u, 1u, _e366)));
                                        }
                                        let _e409 = phi_547_;
                                        let _e411 = phi_548_;
                                        phi_550_ = _e409;
                                        phi_551_ = _e411;
                                        phi_552_ = _e346;
                                    }
                                    let _e415 = phi_550_;
                                    let _e417 = phi_551_;
                                    let _e419 = phi_552_;
                                    phi_557_ = _e415;
                                    phi_558_ = _e417;
                                    phi_559_ = _e419;
                                }
                                let _e427 = phi_557_;
                                let _e429 = phi_558_;
                                let _e431 = phi_559_;
                                let _e432 = select(_e429, _e427, _e431);
                                local_41 = ((_e432 & 32768u) << bitcast<u32>(16i));
                                let _e438 = ((_e432 >> bitcast<u32>(10i)) & 31u);
                                local_42 = _e438;
                                local_43 = (_e432 & 1023u);
                                if (_e438 == 0u) {
                                    let _e465 = local_43;
                                    let _e466 = f32(_e465);
                                    local_44 = _e466;
                                    let _e468 = local_41;
                                    if (_e468 == 0u) {
                                        phi_578_ = (_e466 * 0.000000059604645f);
                                    } else {
                                        let _e470 = local_44;
                                        phi_578_ = (_e470 * -0.000000059604645f);
                                    }
                                    let _e473 = phi_578_;
                                    phi_597_ = _e473;
                                    phi_598_ = f32();
                                    phi_599_ = true;
                                } else {
                                    let _e441 = local_42;
                                    let _e442 = (_e441 == 31u);
                                    if _e442 {
                                        let _e454 = local_41;
                                        let _e456 = local_43;
                                        phi_594_ = bitcast<f32>(((_e454 | 2139095040u) | (_e456 << bitcast<u32>(13i))));
                                        phi_595_ = f32();
                                    } else {
                                        let _e443 = local_42;
                                        let _e447 = local_41;
                                        let _e449 = local_43;
                                        phi_594_ = f32();
                                        phi_595_ = bitcast<f32>(((_e447 | ((_e443 + 112u) << bitcast<u32>(23i))) | (_e449 << bitcast<u32>(13i))));
                                    }
                                    let _e462 = phi_594_;
                                    let _e464 = phi_595_;
                                    phi_597_ = _e462;
                                    phi_598_ = _e464;
                                    phi_599_ = _e442;
                                }
                                let _e475 = phi_597_;
                                let _e477 = phi_598_;
                                let _e479 = phi_599_;
                                local_59 = select(_e477, _e475, _e479);
                                let _e481 = local_17;
                                let _e482 = bitcast<u32>(_e481);
                                let _e485 = ((_e482 >> bitcast<u32>(16i)) & 32768u);
                                local_45 = _e485;
                                let _e489 = bitcast<i32>(((_e482 >> bitcast<u32>(23i)) & 255u));
                                local_46 = _e489;
                                local_47 = (_e482 & 8388607u);
                                if (_e489 == 255i) {
                                    let _e570 = local_45;
                                    let _e572 = local_47;
                                    phi_695_ = ((_e570 | 31744u) | select(512u, 0u, (_e572 == 0u)));
                                    phi_696_ = u32();
                                    phi_697_ = true;
                                } else {
                                    let _e492 = local_46;
                                    let _e493 = (_e492 + -112i);
                                    local_48 = _e493;
                                    if (_e493 >= 31i) {
                                        let _e562 = local_45;
                                        phi_688_ = (_e562 | 31744u);
                                        phi_689_ = u32();
                                        phi_690_ = true;
                                    } else {
                                        let _e495 = local_48;
                                        let _e496 = (_e495 <= 0i);
                                        if _e496 {
                                            let _e522 = local_48;
                                            if (_e522 < -10i) {
                                                phi_662_ = _e485;
                                            } else {
                                                let _e524 = local_47;
                                                let _e525 = (_e524 | 8388608u);
                                                let _e526 = local_46;
                                                let _e528 = bitcast<u32>((126i - _e526));
                                                let _e529 = (_e528 & 31u);
                                                local_49 = (_e525 >> bitcast<u32>(_e529));
                                                let _e535 = (_e525 & ((1u << bitcast<u32>(_e529)) - 1u));
                                                local_50 = _e535;
                                                let _e539 = (1u << bitcast<u32>(((_e528 - 1u) & 31u)));
                                                local_51 = _e539;
                                                if (_e535 > _e539) {
                                                    phi_657_ = true;
                                                } else {
                                                    let _e541 = local_50;
                                                    let _e542 = local_51;
                                                    if (_e541 == _e542) {
                                                        let _e544 = local_49;
                                                        phi_655_ = ((_e544 & 1u) == 1u);
                                                    } else {
                                                        phi_655_ = false;
                                                    }
                                                    let _e548 = phi_655_;
                                                    phi_657_ = _e548;
                                                }
                                                let _e550 = phi_657_;
                                                let _e552 = local_49;
                                                let _e554 = local_45;
                                                phi_662_ = (_e554 | (_e552 + select(0u, 1u, _e550)));
                                            }
                                            let _e557 = phi_662_;
                                            phi_685_ = _e557;
                                            phi_686_ = u32();
                                        } else {
                                            let _e497 = local_48;
                                            let _e501 = local_47;
                                            local_52 = ((bitcast<u32>(_e497) << bitcast<u32>(10i)) | (_e501 >> bitcast<u32>(13i)));
                                            let _e505 = local_47;
                                            let _e506 = (_e505 & 8191u);
                                            local_53 = _e506;
                                            if (_e506 > 4096u) {
                                                phi_680_ = true;
                                            } else {
                                                let _e508 = local_53;
                                                if (_e508 == 4096u) {
                                                    let _e510 = local_52;
                                                    phi_678_ = ((_e510 & 1u) == 1u);
                                                } else {
                                                    phi_678_ = false;
                                                }
                                                let _e514 = phi_678_;
                                                phi_680_ = _e514;
                                            }
                                            let _e516 = phi_680_;
                                            let _e518 = local_52;
                                            let _e520 = local_45;
                                            phi_685_ = u32();
                                            phi_686_ = (_e520 | (_e518 + select(0u, 1u, _e516)));
                                        }
                                        let _e559 = phi_685_;
                                        let _e561 = phi_686_;
                                        phi_688_ = _e559;
                                        phi_689_ = _e561;
                                        phi_690_ = _e496;
                                    }
                                    let _e565 = phi_688_;
                                    let _e567 = phi_689_;
                                    let _e569 = phi_690_;
                                    phi_695_ = _e565;
                                    phi_696_ = _e567;
                                    phi_697_ = _e569;
                                }
                                let _e577 = phi_695_;
                                let _e579 = phi_696_;
                                let _e581 = phi_697_;
                                let _e582 = select(_e579, _e577, _e581);
                                local_54 = ((_e582 & 32768u) << bitcast<u32>(16i));
                                let _e588 = ((_e582 >> bitcast<u32>(10i)) & 31u);
                                local_55 = _e588;
                                local_56 = (_e582 & 1023u);
                                if (_e588 == 0u) {
                                    let _e615 = local_56;
                                    let _e616 = f32(_e615);
                                    local_57 = _e616;
                                    let _e618 = local_54;
                                    if (_e618 == 0u) {
                                        phi_716_ = (_e616 * 0.000000059604645f);
                                    } else {
                                        let _e620 = local_57;
                                        phi_716_ = (_e620 * -0.000000059604645f);
                                    }
                                    let _e623 = phi_716_;
                                    phi_735_ = _e623;
                                    phi_736_ = f32();
                                    phi_737_ = true;
                                } else {
                                    let _e591 = local_55;
                                    let _e592 = (_e591 == 31u);
                                    if _e592 {
                                        let _e604 = local_54;
                                        let _e606 = local_56;
                                        phi_732_ = bitcast<f32>(((_e604 | 2139095040u) | (_e606 << bitcast<u32>(13i))));
                                        phi_733_ = f32();
                                    } else {
                                        let _e593 = local_55;
                                        let _e597 = local_54;
                                        let _e599 = local_56;
                                        phi_732_ = f32();
                                        phi_733_ = bitcast<f32>(((_e597 | ((_e593 + 112u) << bitcast<u32>(23i))) | (_e599 << bitcast<u32>(13i))));
                                    }
                                    let _e612 = phi_732_;
                                    let _e614 = phi_733_;
                                    phi_735_ = _e612;
                                    phi_736_ = _e614;
                                    phi_737_ = _e592;
                                }
                                let _e625 = phi_735_;
                                let _e627 = phi_736_;
                                let _e629 = phi_737_;
                                local_60 = select(_e627, _e625, _e629);
                                if false {
                                    if true {
                                        phi_854_ = 0f;
                                    } else {
                                        phi_854_ = -0f;
                                    }
                                    let _e636 = phi_854_;
                                    phi_873_ = _e636;
                                    phi_874_ = f32();
                                    phi_875_ = true;
                                } else {
                                    if false {
                                        phi_870_ = bitcast<f32>(_e105);
                                        phi_871_ = f32();
                                    } else {
                                        phi_870_ = f32();
                                        phi_871_ = 1f;
                                    }
                                    let _e632 = phi_870_;
                                    let _e634 = phi_871_;
                                    phi_873_ = _e632;
                                    phi_874_ = _e634;
                                    phi_875_ = false;
                                }
                                let _e638 = phi_873_;
                                let _e640 = phi_874_;
                                let _e642 = phi_875_;
                                let _e644 = local_10;
                                let _e646 = local_11;
                                let _e648 = local_58;
                                let _e649 = local_59;
                                let _e650 = local_60;
                                textureStore(global_5, vec2<i32>(bitcast<i32>(_e644), bitcast<i32>(_e646)), vec4<f32>(_e648, _e649, _e650, select(_e640, _e638, _e642)));
                                let _e653 = local_8;
                                phi_172_ = (_e653 + 1u);
                            } else {
                                phi_172_ = u32();
                            }
                            let _e656 = phi_172_;
                            phi_105_ = _e656;
                            phi_173_ = _e144;
                        } else {
                            phi_105_ = u32();
                            phi_173_ = false;
                        }
                        let _e658 = phi_105_;
                        let _e660 = phi_173_;
                        local_18 = _e660;
                        continue;
                        continuing {
                            let _e661 = local_18;
                            phi_104_ = _e658;
                            phi_880_ = _e126;
                            break if !(_e661);
                        }
                    }
                    let _e664 = phi_880_;
                    phi_941_ = _e664;
                    if _e664 {
                        break;
                    }
                    let _e665 = local_6;
                    let _e666 = local_4;
                    phi_942_ = _e664;
                    phi_94_ = (_e665 + _e666);
                } else {
                    phi_942_ = _e126;
                    phi_94_ = u32();
                }
                let _e669 = phi_942_;
                let _e671 = phi_94_;
                continue;
                continuing {
                    let _e672 = local_7;
                    phi_908_ = _e669;
                    phi_93_ = _e671;
                    phi_941_ = _e669;
                    break if !(_e672);
                }
            }
            let _e675 = phi_941_;
            if _e675 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn frame_to_rgba16f_image(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
