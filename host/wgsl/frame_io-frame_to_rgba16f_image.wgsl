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
var global_5: texture_storage_2d<rgba16float,write>;
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
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: f32;
    var local_13: u32;
    var local_14: f32;
    var local_15: u32;
    var local_16: f32;
    var local_17: bool;
    var local_18: u32;
    var local_19: i32;
    var local_20: u32;
    var local_21: i32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: f32;
    var local_31: u32;
    var local_32: i32;
    var local_33: u32;
    var local_34: i32;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: f32;
    var local_44: u32;
    var local_45: i32;
    var local_46: u32;
    var local_47: i32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: f32;
    var local_57: f32;
    var local_58: f32;
    var local_59: f32;
    var phi_905_: bool;
    var phi_93_: u32;
    var phi_104_: u32;
    var phi_399_: bool;
    var phi_401_: bool;
    var phi_376_: bool;
    var phi_378_: bool;
    var phi_383_: u32;
    var phi_406_: u32;
    var phi_407_: u32;
    var phi_409_: u32;
    var phi_410_: u32;
    var phi_411_: bool;
    var phi_416_: u32;
    var phi_417_: u32;
    var phi_418_: bool;
    var phi_453_: f32;
    var phi_454_: f32;
    var phi_437_: f32;
    var phi_456_: f32;
    var phi_457_: f32;
    var phi_458_: bool;
    var phi_537_: bool;
    var phi_539_: bool;
    var phi_514_: bool;
    var phi_516_: bool;
    var phi_521_: u32;
    var phi_544_: u32;
    var phi_545_: u32;
    var phi_547_: u32;
    var phi_548_: u32;
    var phi_549_: bool;
    var phi_554_: u32;
    var phi_555_: u32;
    var phi_556_: bool;
    var phi_591_: f32;
    var phi_592_: f32;
    var phi_575_: f32;
    var phi_594_: f32;
    var phi_595_: f32;
    var phi_596_: bool;
    var phi_675_: bool;
    var phi_677_: bool;
    var phi_652_: bool;
    var phi_654_: bool;
    var phi_659_: u32;
    var phi_682_: u32;
    var phi_683_: u32;
    var phi_685_: u32;
    var phi_686_: u32;
    var phi_687_: bool;
    var phi_692_: u32;
    var phi_693_: u32;
    var phi_694_: bool;
    var phi_729_: f32;
    var phi_730_: f32;
    var phi_713_: f32;
    var phi_732_: f32;
    var phi_733_: f32;
    var phi_734_: bool;
    var phi_867_: f32;
    var phi_868_: f32;
    var phi_851_: f32;
    var phi_870_: f32;
    var phi_871_: f32;
    var phi_872_: bool;
    var phi_169_: u32;
    var phi_105_: u32;
    var phi_170_: bool;
    var phi_877_: bool;
    var phi_939_: bool;
    var phi_94_: u32;
    var phi_938_: bool;

    let _e104 = global_6;
    switch bitcast<i32>(0u) {
        default: {
            let _e107 = global;
            local = _e107;
            let _e108 = global_1;
            let _e109 = global_2;
            local_1 = arrayLength((&global_3.member));
            let _e116 = global_4.member.member;
            local_2 = _e116;
            let _e119 = global_4.member.member_1;
            local_3 = (_e116 * _e119);
            local_4 = (_e109.x * 256u);
            local_5 = (_e107 + 1u);
            phi_905_ = false;
            phi_93_ = (_e108.x * 256u);
            loop {
                let _e125 = phi_905_;
                let _e127 = phi_93_;
                local_6 = _e127;
                let _e128 = local_6;
                let _e129 = local_3;
                let _e130 = (_e128 < _e129);
                local_7 = _e130;
                if _e130 {
                    let _e131 = local_6;
                    let _e132 = local;
                    phi_104_ = (_e131 + _e132);
                    loop {
                        let _e135 = phi_104_;
                        local_8 = _e135;
                        let _e136 = local_8;
                        let _e137 = local_3;
                        if (_e136 < _e137) {
                            let _e139 = local_6;
                            let _e140 = local_5;
                            let _e142 = local_8;
                            let _e143 = (_e142 < (_e139 + _e140));
                            if _e143 {
                                let _e144 = local_2;
                                if (_e144 == 0u) {
                                    phi_877_ = true;
                                    break;
                                }
                                let _e146 = local_8;
                                let _e147 = local_2;
                                let _e148 = (_e146 / _e147);
                                local_9 = _e148;
                                let _e149 = local_2;
                                let _e151 = local_8;
                                local_10 = (_e151 - (_e148 * _e149));
                                let _e153 = local_8;
                                let _e154 = (3u * _e153);
                                local_11 = _e154;
                                let _e155 = local_1;
                                if (_e154 < _e155) {
                                } else {
                                    phi_877_ = true;
                                    break;
                                }
                                let _e157 = local_11;
                                let _e160 = global_3.member[_e157];
                                local_12 = bitcast<f32>(_e160);
                                let _e162 = local_11;
                                let _e163 = (_e162 + 1u);
                                local_13 = _e163;
                                let _e164 = local_1;
                                if (_e163 < _e164) {
                                } else {
                                    phi_877_ = true;
                                    break;
                                }
                                let _e166 = local_13;
                                let _e169 = global_3.member[_e166];
                                local_14 = bitcast<f32>(_e169);
                                let _e171 = local_11;
                                let _e172 = (_e171 + 2u);
                                local_15 = _e172;
                                let _e173 = local_1;
                                if (_e172 < _e173) {
                                } else {
                                    phi_877_ = true;
                                    break;
                                }
                                let _e175 = local_15;
                                let _e178 = global_3.member[_e175];
                                local_16 = bitcast<f32>(_e178);
                                let _e180 = local_12;
                                let _e181 = bitcast<u32>(_e180);
                                let _e184 = ((_e181 >> bitcast<u32>(16i)) & 32768u);
                                local_18 = _e184;
                                let _e188 = bitcast<i32>(((_e181 >> bitcast<u32>(23i)) & 255u));
                                local_19 = _e188;
                                local_20 = (_e181 & 8388607u);
                                if (_e188 == 255i) {
                                    let _e269 = local_18;
                                    let _e271 = local_20;
                                    phi_416_ = ((_e269 | 31744u) | select(512u, 0u, (_e271 == 0u)));
                                    phi_417_ = u32();
                                    phi_418_ = true;
                                } else {
                                    let _e191 = local_19;
                                    let _e192 = (_e191 + -112i);
                                    local_21 = _e192;
                                    if (_e192 >= 31i) {
                                        let _e261 = local_18;
                                        phi_409_ = (_e261 | 31744u);
                                        phi_410_ = u32();
                                        phi_411_ = true;
                                    } else {
                                        let _e194 = local_21;
                                        let _e195 = (_e194 <= 0i);
                                        if _e195 {
                                            let _e221 = local_21;
                                            if (_e221 < -10i) {
                                                phi_383_ = _e184;
                                            } else {
                                                let _e223 = local_20;
                                                let _e224 = (_e223 | 8388608u);
                                                let _e225 = local_19;
                                                let _e227 = bitcast<u32>((126i - _e225));
                                                let _e228 = (_e227 & 31u);
                                                local_22 = (_e224 >> bitcast<u32>(_e228));
                                                let _e234 = (_e224 & ((1u << bitcast<u32>(_e228)) - 1u));
                                                local_23 = _e234;
                                                let _e238 = (1u << bitcast<u32>(((_e227 - 1u) & 31u)));
                                                local_24 = _e238;
                                                if (_e234 > _e238) {
                                                    phi_378_ = true;
                                                } else {
                                                    let _e240 = local_23;
                                                    let _e241 = local_24;
                                                    if (_e240 == _e241) {
                                                        let _e243 = local_22;
                                                        phi_376_ = ((_e243 & 1u) == 1u);
                                                    } else {
                                                        phi_376_ = false;
                                                    }
                                                    let _e247 = phi_376_;
                                                    phi_378_ = _e247;
                                                }
                                                let _e249 = phi_378_;
                                                let _e251 = local_22;
                                                let _e253 = local_18;
                                                phi_383_ = (_e253 | (_e251 + select(0u, 1u, _e249)));
                                            }
                                            let _e256 = phi_383_;
                                            phi_406_ = _e256;
                                            phi_407_ = u32();
                                        } else {
                                            let _e196 = local_21;
                                            let _e200 = local_20;
                                            local_25 = ((bitcast<u32>(_e196) << bitcast<u32>(10i)) | (_e200 >> bitcast<u32>(13i)));
                                            let _e204 = local_20;
                                            let _e205 = (_e204 & 8191u);
                                            local_26 = _e205;
                                            if (_e205 > 4096u) {
                                                phi_401_ = true;
                                            } else {
                                                let _e207 = local_26;
                                                if (_e207 == 4096u) {
                                                    let _e209 = local_25;
                                                    phi_399_ = ((_e209 & 1u) == 1u);
                                                } else {
                                                    phi_399_ = false;
                                                }
                                                let _e213 = phi_399_;
                                                phi_401_ = _e213;
                                            }
                                            let _e215 = phi_401_;
                                            let _e217 = local_25;
                                            let _e219 = local_18;
                                            phi_406_ = u32();
                                            phi_407_ = (_e219 | (_e217 + select(0u, 1u, _e215)));
                                        }
                                        let _e258 = phi_406_;
                                        let _e260 = phi_407_;
                                        phi_409_ = _e258;
                                        phi_410_ = _e260;
                                        phi_411_ = _e195;
                                    }
                                    let _e264 = phi_409_;
                                    let _e266 = phi_410_;
                                    let _e268 = phi_411_;
                                    phi_416_ = _e264;
                                    phi_417_ = _e266;
                                    phi_418_ = _e268;
                                }
                                let _e276 = phi_416_;
                                let _e278 = phi_417_;
                                let _e280 = phi_418_;
                                let _e281 = select(_e278, _e276, _e280);
                                local_27 = ((_e281 & 32768u) << bitcast<u32>(16i));
                                let _e287 = ((_e281 >> bitcast<u32>(10i)) & 31u);
                                local_28 = _e287;
                                local_29 = (_e281 & 1023u);
                                if (_e287 == 0u) {
                                    let _e314 = local_29;
                                    let _e315 = f32(_e314);
                                    local_30 = _e315;
                                    let _e317 = local_27;
                                    if (_e317 == 0u) {
                                        phi_437_ = (_e315 * 0.000000059604645f);
                                    } else {
                                        let _e319 = local_30;
                                        phi_437_ = (_e319 * -0.000000059604645f);
                                    }
                                    let _e322 = phi_437_;
                                    phi_456_ = _e322;
                                    phi_457_ = f32();
                                    phi_458_ = true;
                                } else {
                                    let _e290 = local_28;
                                    let _e291 = (_e290 == 31u);
                                    if _e291 {
                                        let _e303 = local_27;
                                        let _e305 = local_29;
                                        phi_453_ = bitcast<f32>(((_e303 | 2139095040u) | (_e305 << bitcast<u32>(13i))));
                                        phi_454_ = f32();
                                    } else {
                                        let _e292 = local_28;
                                        let _e296 = local_27;
                                        let _e298 = local_29;
                                        phi_453_ = f32();
                                        phi_454_ = bitcast<f32>(((_e296 | ((_e292 + 112u) << bitcast<u32>(23i))) | (_e298 << bitcast<u32>(13i))));
                                    }
                                    let _e311 = phi_453_;
                                    let _e313 = phi_454_;
                                    phi_456_ = _e311;
                                    phi_457_ = _e313;
                                    phi_458_ = _e291;
                                }
                                let _e324 = phi_456_;
                                let _e326 = phi_457_;
                                let _e328 = phi_458_;
                                local_57 = select(_e326, _e324, _e328);
                                let _e330 = local_14;
                                let _e331 = bitcast<u32>(_e330);
                                let _e334 = ((_e331 >> bitcast<u32>(16i)) & 32768u);
                                local_31 = _e334;
                                let _e338 = bitcast<i32>(((_e331 >> bitcast<u32>(23i)) & 255u));
                                local_32 = _e338;
                                local_33 = (_e331 & 8388607u);
                                if (_e338 == 255i) {
                                    let _e419 = local_31;
                                    let _e421 = local_33;
                                    phi_554_ = ((_e419 | 31744u) | select(512u, 0u, (_e421 == 0u)));
                                    phi_555_ = u32();
                                    phi_556_ = true;
                                } else {
                                    let _e341 = local_32;
                                    let _e342 = (_e341 + -112i);
                                    local_34 = _e342;
                                    if (_e342 >= 31i) {
                                        let _e411 = local_31;
                                        phi_547_ = (_e411 | 31744u);
                                        phi_548_ = u32();
                                        phi_549_ = true;
                                    } else {
                                        let _e344 = local_34;
                                        let _e345 = (_e344 <= 0i);
                                        if _e345 {
                                            let _e371 = local_34;
                                            if (_e371 < -10i) {
                                                phi_521_ = _e334;
                                            } else {
                                                let _e373 = local_33;
                                                let _e374 = (_e373 | 8388608u);
                                                let _e375 = local_32;
                                                let _e377 = bitcast<u32>((126i - _e375));
                                                let _e378 = (_e377 & 31u);
                                                local_35 = (_e374 >> bitcast<u32>(_e378));
                                                let _e384 = (_e374 & ((1u << bitcast<u32>(_e378)) - 1u));
                                                local_36 = _e384;
                                                let _e388 = (1u << bitcast<u32>(((_e377 - 1u) & 31u)));
                                                local_37 = _e388;
                                                if (_e384 > _e388) {
                                                    phi_516_ = true;
                                                } else {
                                                    let _e390 = local_36;
                                                    let _e391 = local_37;
                                                    if (_e390 == _e391) {
                                                        let _e393 = local_35;
                                                        phi_514_ = ((_e393 & 1u) == 1u);
                                                    } else {
                                                        phi_514_ = false;
                                                    }
                                                    let _e397 = phi_514_;
                                                    phi_516_ = _e397;
                                                }
                                                let _e399 = phi_516_;
                                                let _e401 = local_35;
                                                let _e403 = local_31;
                                                phi_521_ = (_e403 | (_e401 + select(0u, 1u, _e399)));
                                            }
                                            let _e406 = phi_521_;
                                            phi_544_ = _e406;
                                            phi_545_ = u32();
                                        } else {
                                            let _e346 = local_34;
                                            let _e350 = local_33;
                                            local_38 = ((bitcast<u32>(_e346) << bitcast<u32>(10i)) | (_e350 >> bitcast<u32>(13i)));
                                            let _e354 = local_33;
                                            let _e355 = (_e354 & 8191u);
                                            local_39 = _e355;
                                            if (_e355 > 4096u) {
                                                phi_539_ = true;
                                            } else {
                                                let _e357 = local_39;
                                                if (_e357 == 4096u) {
                                                    let _e359 = local_38;
                                                    phi_537_ = ((_e359 & 1u) == 1u);
                                                } else {
                                                    phi_537_ = false;
                                                }
                                                let _e363 = phi_537_;
                                                phi_539_ = _e363;
                                            }
                                            let _e365 = phi_539_;
                                            let _e367 = local_38;
                                            let _e369 = local_31;
                                            phi_544_ = u32();
                                            phi_545_ = (_e369 | (_e367 + select(0u, 1u, _e365)));
                                        }
                                        let _e408 = phi_544_;
                                        let _e410 = phi_545_;
                                        phi_547_ = _e408;
                                        phi_548_ = _e410;
                                        phi_549_ = _e345;
                                    }
                                    let _e414 = phi_547_;
                                    let _e416 = phi_548_;
                                    let _e418 = phi_549_;
                                    phi_554_ = _e414;
                                    phi_555_ = _e416;
                                    phi_556_ = _e418;
                                }
                                let _e426 = phi_554_;
                                let _e428 = phi_555_;
                                let _e430 = phi_556_;
                                let _e431 = select(_e428, _e426, _e430);
                                local_40 = ((_e431 & 32768u) << bitcast<u32>(16i));
                                let _e437 = ((_e431 >> bitcast<u32>(10i)) & 31u);
                                local_41 = _e437;
                                local_42 = (_e431 & 1023u);
                                if (_e437 == 0u) {
                                    let _e464 = local_42;
                                    let _e465 = f32(_e464);
                                    local_43 = _e465;
                                    let _e467 = local_40;
                                    if (_e467 == 0u) {
                                        phi_575_ = (_e465 * 0.000000059604645f);
                                    } else {
                                        let _e469 = local_43;
                                        phi_575_ = (_e469 * -0.000000059604645f);
                                    }
                                    let _e472 = phi_575_;
                                    phi_594_ = _e472;
                                    phi_595_ = f32();
                                    phi_596_ = true;
                                } else {
                                    let _e440 = local_41;
                                    let _e441 = (_e440 == 31u);
                                    if _e441 {
                                        let _e453 = local_40;
                                        let _e455 = local_42;
                                        phi_591_ = bitcast<f32>(((_e453 | 2139095040u) | (_e455 << bitcast<u32>(13i))));
                                        phi_592_ = f32();
                                    } else {
                                        let _e442 = local_41;
                                        let _e446 = local_40;
                                        let _e448 = local_42;
                                        phi_591_ = f32();
                                        phi_592_ = bitcast<f32>(((_e446 | ((_e442 + 112u) << bitcast<u32>(23i))) | (_e448 << bitcast<u32>(13i))));
                                    }
                                    let _e461 = phi_591_;
                                    let _e463 = phi_592_;
                                    phi_594_ = _e461;
                                    phi_595_ = _e463;
                                    phi_596_ = _e441;
                                }
                                let _e474 = phi_594_;
                                let _e476 = phi_595_;
                                let _e478 = phi_596_;
                                local_58 = select(_e476, _e474, _e478);
                                let _e480 = local_16;
                                let _e481 = bitcast<u32>(_e480);
                                let _e484 = ((_e481 >> bitcast<u32>(16i)) & 32768u);
                                local_44 = _e484;
                                let _e488 = bitcast<i32>(((_e481 >> bitcast<u32>(23i)) & 255u));
                                local_45 = _e488;
                                local_46 = (_e481 & 8388607u);
                                if (_e488 == 255i) {
                                    let _e569 = local_44;
                                    let _e571 = local_46;
                                    phi_692_ = ((_e569 | 31744u) | select(512u, 0u, (_e571 == 0u)));
                                    phi_693_ = u32();
                                    phi_694_ = true;
                                } else {
                                    let _e491 = local_45;
                                    let _e492 = (_e491 + -112i);
                                    local_47 = _e492;
                                    if (_e492 >= 31i) {
                                        let _e561 = local_44;
                                        phi_685_ = (_e561 | 31744u);
                                        phi_686_ = u32();
                                        phi_687_ = true;
                                    } else {
                                        let _e494 = local_47;
                                        let _e495 = (_e494 <= 0i);
                                        if _e495 {
                                            let _e521 = local_47;
                                            if (_e521 < -10i) {
                                                phi_659_ = _e484;
                                            } else {
                                                let _e523 = local_46;
                                                let _e524 = (_e523 | 8388608u);
                                                let _e525 = local_45;
                                                let _e527 = bitcast<u32>((126i - _e525));
                                                let _e528 = (_e527 & 31u);
                                                local_48 = (_e524 >> bitcast<u32>(_e528));
                                                let _e534 = (_e524 & ((1u << bitcast<u32>(_e528)) - 1u));
                                                local_49 = _e534;
                                                let _e538 = (1u << bitcast<u32>(((_e527 - 1u) & 31u)));
                                                local_50 = _e538;
                                                if (_e534 > _e538) {
                                                    phi_654_ = true;
                                                } else {
                                                    let _e540 = local_49;
                                                    let _e541 = local_50;
                                                    if (_e540 == _e541) {
                                                        let _e543 = local_48;
                                                        phi_652_ = ((_e543 & 1u) == 1u);
                                                    } else {
                                                        phi_652_ = false;
                                                    }
                                                    let _e547 = phi_652_;
                                                    phi_654_ = _e547;
                                                }
                                                let _e549 = phi_654_;
                                                let _e551 = local_48;
                                                let _e553 = local_44;
                                                phi_659_ = (_e553 | (_e551 + select(0u, 1u, _e549)));
                                            }
                                            let _e556 = phi_659_;
                                            phi_682_ = _e556;
                                            phi_683_ = u32();
                                        } else {
                                            let _e496 = local_47;
                                            let _e500 = local_46;
                                            local_51 = ((bitcast<u32>(_e496) << bitcast<u32>(10i)) | (_e500 >> bitcast<u32>(13i)));
                                            let _e504 = local_46;
                                            let _e505 = (_e504 & 8191u);
                                            local_52 = _e505;
                                            if (_e505 > 4096u) {
                                                phi_677_ = true;
                                            } else {
                                                let _e507 = local_52;
                                                if (_e507 == 4096u) {
                                                    let _e509 = local_51;
                                                    phi_675_ = ((_e509 & 1u) == 1u);
                                                } else {
                                                    phi_675_ = false;
                                                }
                                                let _e513 = phi_675_;
                                                phi_677_ = _e513;
                                            }
                                            let _e515 = phi_677_;
                                            let _e517 = local_51;
                                            let _e519 = local_44;
                                            phi_682_ = u32();
                                            phi_683_ = (_e519 | (_e517 + select(0u, 1u, _e515)));
                                        }
                                        let _e558 = phi_682_;
                                        let _e560 = phi_683_;
                                        phi_685_ = _e558;
                                        phi_686_ = _e560;
                                        phi_687_ = _e495;
                                    }
                                    let _e564 = phi_685_;
                                    let _e566 = phi_686_;
                                    let _e568 = phi_687_;
                                    phi_692_ = _e564;
                                    phi_693_ = _e566;
                                    phi_694_ = _e568;
                                }
                                let _e576 = phi_692_;
                                let _e578 = phi_693_;
                                let _e580 = phi_694_;
                                let _e581 = select(_e578, _e576, _e580);
                                local_53 = ((_e581 & 32768u) << bitcast<u32>(16i));
                                let _e587 = ((_e581 >> bitcast<u32>(10i)) & 31u);
                                local_54 = _e587;
                                local_55 = (_e581 & 1023u);
                                if (_e587 == 0u) {
                                    let _e614 = local_55;
                                    let _e615 = f32(_e614);
                                    local_56 = _e615;
                                    let _e617 = local_53;
                                    if (_e617 == 0u) {
                                        phi_713_ = (_e615 * 0.000000059604645f);
                                    } else {
                                        let _e619 = local_56;
                                        phi_713_ = (_e619 * -0.000000059604645f);
                                    }
                                    let _e622 = phi_713_;
                                    phi_732_ = _e622;
                                    phi_733_ = f32();
                                    phi_734_ = true;
                                } else {
                                    let _e590 = local_54;
                                    let _e591 = (_e590 == 31u);
                                    if _e591 {
                                        let _e603 = local_53;
                                        let _e605 = local_55;
                                        phi_729_ = bitcast<f32>(((_e603 | 2139095040u) | (_e605 << bitcast<u32>(13i))));
                                        phi_730_ = f32();
                                    } else {
                                        let _e592 = local_54;
                                        let _e596 = local_53;
                                        let _e598 = local_55;
                                        phi_729_ = f32();
                                        phi_730_ = bitcast<f32>(((_e596 | ((_e592 + 112u) << bitcast<u32>(23i))) | (_e598 << bitcast<u32>(13i))));
                                    }
                                    let _e611 = phi_729_;
                                    let _e613 = phi_730_;
                                    phi_732_ = _e611;
                                    phi_733_ = _e613;
                                    phi_734_ = _e591;
                                }
                                let _e624 = phi_732_;
                                let _e626 = phi_733_;
                                let _e628 = phi_734_;
                                local_59 = select(_e626, _e624, _e628);
                                if false {
                                    if true {
                                        phi_851_ = 0f;
                                    } else {
                                        phi_851_ = -0f;
                                    }
                                    let _e635 = phi_851_;
                                    phi_870_ = _e635;
                                    phi_871_ = f32();
                                    phi_872_ = true;
                                } else {
                                    if false {
                                        phi_867_ = bitcast<f32>(_e104);
                                        phi_868_ = f32();
                                    } else {
                                        phi_867_ = f32();
                                        phi_868_ = 1f;
                                    }
                                    let _e631 = phi_867_;
                                    let _e633 = phi_868_;
                                    phi_870_ = _e631;
                                    phi_871_ = _e633;
                                    phi_872_ = false;
                                }
                                let _e637 = phi_870_;
                                let _e639 = phi_871_;
                                let _e641 = phi_872_;
                                let _e643 = local_10;
                                let _e645 = local_9;
                                let _e647 = local_57;
                                let _e648 = local_58;
                                let _e649 = local_59;
                                textureStore(global_5, vec2<i32>(bitcast<i32>(_e643), bitcast<i32>(_e645)), vec4<f32>(_e647, _e648, _e649, select(_e639, _e637, _e641)));
                                let _e652 = local_8;
                                phi_169_ = (_e652 + 1u);
                            } else {
                                phi_169_ = u32();
                            }
                            let _e655 = phi_169_;
                            phi_105_ = _e655;
                            phi_170_ = _e143;
                        } else {
                            phi_105_ = u32();
                            phi_170_ = false;
                        }
                        let _e657 = phi_105_;
                        let _e659 = phi_170_;
                        local_17 = _e659;
                        continue;
                        continuing {
                            let _e660 = local_17;
                            phi_104_ = _e657;
                            phi_877_ = _e125;
                            break if !(_e660);
                        }
                    }
                    let _e663 = phi_877_;
                    phi_938_ = _e663;
                    if _e663 {
                        break;
                    }
                    let _e664 = local_6;
                    let _e665 = local_4;
                    phi_939_ = _e663;
                    phi_94_ = (_e664 + _e665);
                } else {
                    phi_939_ = _e125;
                    phi_94_ = u32();
                }
                let _e668 = phi_939_;
                let _e670 = phi_94_;
                continue;
                continuing {
                    let _e671 = local_7;
                    phi_905_ = _e668;
                    phi_93_ = _e670;
                    phi_938_ = _e668;
                    break if !(_e671);
                }
            }
            let _e674 = phi_938_;
            if _e674 {
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
