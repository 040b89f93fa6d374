struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_16 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_17 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: type_5,
    member_9: type_16,
}

struct type_18 {
    member: type_17,
}

struct type_20 {
    member: array<f32, 3>,
    member_1: array<f32, 3>,
    member_2: f32,
    member_3: f32,
}

struct type_21 {
    member: u32,
    member_1: type_20,
}

struct type_29 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_7;
var<immediate> global_5: type_18;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_29;
var<private> global_8: u32 = 2143289344u;

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
    var local_10: bool;
    var local_11: u32;
    var local_12: bool;
    var local_13: i32;
    var local_14: i32;
    var local_15: u32;
    var local_16: f32;
    var local_17: u32;
    var local_18: f32;
    var local_19: u32;
    var local_20: f32;
    var local_21: f32;
    var local_22: f32;
    var local_23: f32;
    var local_24: array<f32, 3>;
    var local_25: i32;
    var local_26: f32;
    var local_27: array<f32, 3>;
    var local_28: bool;
    var local_29: i32;
    var local_30: f32;
    var local_31: array<f32, 3>;
    var local_32: bool;
    var local_33: i32;
    var local_34: i32;
    var local_35: u32;
    var local_36: f32;
    var local_37: u32;
    var local_38: f32;
    var local_39: u32;
    var local_40: f32;
    var local_41: f32;
    var local_42: f32;
    var local_43: f32;
    var local_44: bool;
    var local_45: array<f32, 3>;
    var local_46: f32;
    var local_47: u32;
    var local_48: f32;
    var local_49: f32;
    var local_50: f32;
    var local_51: f32;
    var local_52: bool;
    var local_53: bool;
    var local_54: bool;
    var local_55: u32;
    var local_56: f32;
    var local_57: f32;
    var phi_877_: bool;
    var phi_141_: u32;
    var phi_234_: bool;
    var phi_248_: bool;
    var phi_253_: f32;
    var phi_263_: bool;
    var phi_277_: bool;
    var phi_282_: f32;
    var phi_292_: bool;
    var phi_306_: bool;
    var phi_311_: f32;
    var phi_858_: bool;
    var phi_314_: i32;
    var phi_317_: f32;
    var phi_319_: array<f32, 3>;
    var phi_328_: i32;
    var phi_331_: f32;
    var phi_333_: array<f32, 3>;
    var phi_352_: bool;
    var phi_446_: bool;
    var phi_460_: bool;
    var phi_465_: f32;
    var phi_475_: bool;
    var phi_489_: bool;
    var phi_494_: f32;
    var phi_504_: bool;
    var phi_518_: bool;
    var phi_523_: f32;
    var phi_539_: bool;
    var phi_541_: bool;
    var phi_542_: bool;
    var phi_560_: f32;
    var phi_561_: array<f32, 3>;
    var phi_562_: f32;
    var phi_563_: array<f32, 3>;
    var phi_564_: f32;
    var phi_565_: array<f32, 3>;
    var phi_566_: f32;
    var phi_567_: array<f32, 3>;
    var phi_568_: f32;
    var phi_569_: array<f32, 3>;
    var phi_570_: f32;
    var phi_571_: array<f32, 3>;
    var phi_329_: i32;
    var phi_332_: f32;
    var phi_334_: array<f32, 3>;
    var phi_826_: bool;
    var phi_879_: bool;
    var phi_315_: i32;
    var phi_318_: f32;
    var phi_320_: array<f32, 3>;
    var phi_878_: bool;
    var phi_585_: array<f32, 3>;
    var phi_630_: bool;
    var phi_658_: f32;
    var phi_659_: f32;
    var phi_665_: f32;
    var phi_667_: f32;
    var phi_813_: bool;
    var phi_693_: bool;
    var phi_695_: bool;
    var phi_696_: bool;
    var phi_710_: bool;
    var phi_742_: type_21;
    var phi_744_: type_21;
    var phi_745_: bool;
    var phi_746_: type_21;
    var phi_747_: bool;
    var phi_748_: type_21;
    var phi_749_: bool;
    var phi_754_: type_21;
    var phi_882_: bool;
    var phi_881_: bool;
    var phi_142_: u32;
    var phi_880_: bool;
    var local_58: f32;
    var local_59: array<f32, 3>;

    let _e104 = global_8;
    switch bitcast<i32>(0u) {
        default: {
            let _e107 = global;
            local = _e107;
            let _e108 = global_1;
            let _e109 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e122 = global_5.member.member;
            local_5 = _e122;
            let _e125 = global_5.member.member_1;
            local_6 = _e125;
            local_7 = (_e122 * _e125);
            local_8 = (_e109.x * 256u);
            phi_877_ = false;
            phi_141_ = (_e108.x * 256u);
            loop {
                let _e130 = phi_877_;
                let _e132 = phi_141_;
                local_9 = _e132;
                let _e133 = local_9;
                let _e134 = local_7;
                let _e135 = (_e133 < _e134);
                local_10 = _e135;
                if _e135 {
                    let _e136 = local_9;
                    let _e137 = local;
                    let _e138 = (_e136 + _e137);
                    local_11 = _e138;
                    let _e139 = local_7;
                    if (_e138 < _e139) {
                        let _e141 = local_5;
                        let _e142 = (_e141 == 0u);
                        local_12 = _e142;
                        if _e142 {
                            phi_880_ = true;
                            break;
                        }
                        let _e143 = local_11;
                        let _e144 = local_5;
                        local_13 = bitcast<i32>((_e143 % _e144));
                        let _e147 = local_12;
                        if _e147 {
                            phi_880_ = true;
                            break;
                        }
                        let _e148 = local_11;
                        let _e149 = local_5;
                        local_14 = bitcast<i32>((_e148 / _e149));
                        let _e152 = local_11;
                        let _e153 = (3u * _e152);
                        local_15 = _e153;
                        let _e154 = local_1;
                        if (_e153 < _e154) {
                        } else {
                            phi_880_ = true;
                            break;
                        }
                        let _e156 = local_15;
                        let _e159 = global_4.member[_e156];
                        local_16 = bitcast<f32>(_e159);
                        let _e161 = local_15;
                        let _e162 = (_e161 + 1u);
                        local_17 = _e162;
                        let _e163 = local_1;
                        if (_e162 < _e163) {
                        } else {
                            phi_880_ = true;
                            break;
                        }
                        let _e165 = local_17;
                        let _e168 = global_4.member[_e165];
                        local_18 = bitcast<f32>(_e168);
                        let _e170 = local_15;
                        let _e171 = (_e170 + 2u);
                        local_19 = _e171;
                        let _e172 = local_1;
                        if (_e171 < _e172) {
                        } else {
                            phi_880_ = true;
                            break;
                        }
                        let _e174 = local_19;
                        let _e177 = global_4.member[_e174];
                        local_20 = bitcast<f32>(_e177);
                        let _e179 = local_16;
                        if (_e179 > 1267650600000000000000000000000f) {
                            let _e181 = local_16;
                            phi_234_ = select(true, false, (_e181 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_234_ = true;
                        }
                        let _e185 = phi_234_;
                        if _e185 {
                            let _e186 = local_16;
                            if (_e186 < 0.000000000000000000000000000000000000011754944f) {
                                let _e188 = local_16;
                                phi_248_ = select(true, false, (_e188 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_248_ = true;
                            }
                            let _e192 = phi_248_;
                            let _e193 = local_16;
                            phi_253_ = select(0f, _e193, _e192);
                        } else {
                            phi_253_ = 1267650600000000000000000000000f;
                        }
                        let _e196 = phi_253_;
                        local_21 = _e196;
                        let _e197 = local_18;
                        if (_e197 > 1267650600000000000000000000000f) {
                            let _e199 = local_18;
                            phi_263_ = select(true, false, (_e199 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_263_ = true;
                        }
                        let _e203 = phi_263_;
                        if _e203 {
                            let _e204 = local_18;
                            if (_e204 < 0.000000000000000000000000000000000000011754944f) {
                                let _e206 = local_18;
                                phi_277_ = select(true, false, (_e206 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_277_ = true;
                            }
                            let _e210 = phi_277_;
                            let _e211 = local_18;
                            phi_282_ = select(0f, _e211, _e210);
                        } else {
                            phi_282_ = 1267650600000000000000000000000f;
                        }
                        let _e214 = phi_282_;
                        local_22 = _e214;
                        let _e215 = local_20;
                        if (_e215 > 1267650600000000000000000000000f) {
                            let _e217 = local_20;
                            phi_292_ = select(true, false, (_e217 <= 340282350000000000000000000000000000000f));
                        } else {
                            phi_292_ = true;
                        }
                        let _e221 = phi_292_;
                        if _e221 {
                            let _e222 = local_20;
                            if (_e222 < 0.000000000000000000000000000000000000011754944f) {
                                let _e224 = local_20;
                                phi_306_ = select(true, false, (_e224 >= -340282350000000000000000000000000000000f));
                            } else {
                                phi_306_ = true;
                            }
                            let _e228 = phi_306_;
                            let _e229 = local_20;
                            phi_311_ = select(0f, _e229, _e228);
                        } else {
                            phi_311_ = 1267650600000000000000000000000f;
                        }
                        let _e232 = phi_311_;
                        local_23 = _e232;
                        let _e233 = local_21;
                        let _e234 = local_22;
                        local_24 = array<f32, 3>(_e233, _e234, _e232);
                        phi_858_ = _e130;
                        phi_314_ = -2i;
                        phi_317_ = 0f;
                        phi_319_ = array<f32, 3>(0f, 0f, 0f);
                        loop {
                            let _e237 = phi_858_;
                            let _e239 = phi_314_;
                            let _e241 = phi_317_;
                            let _e243 = phi_319_;
                            local_25 = _e239;
                            local_26 = _e241;
                            local_27 = _e243;
                            let _e244 = local_25;
                            let _e245 = (_e244 <= 2i);
                            local_28 = _e245;
                            if _e245 {
                                phi_328_ = -2i;
                                phi_331_ = _e241;
                                phi_333_ = _e243;
                                loop {
                                    let _e247 = phi_328_;
                                    let _e249 = phi_331_;
                                    let _e251 = phi_333_;
                                    local_29 = _e247;
                                    local_30 = _e249;
                                    local_31 = _e251;
                                    local_58 = _e249;
                                    local_59 = _e251;
                                    let _e252 = local_29;
                                    let _e253 = (_e252 <= 2i);
                                    local_32 = _e253;
                                    if _e253 {
                                        let _e254 = local_13;
                                        let _e255 = local_29;
                                        local_33 = (_e254 + _e255);
                                        let _e257 = local_14;
                                        let _e258 = local_25;
                                        local_34 = (_e257 + _e258);
                                        let _e260 = local_29;
                                        if (_e260 == 0i) {
                                            let _e262 = local_25;
                                            phi_352_ = select(true, false, (_e262 == 0i));
                                        } else {
                                            phi_352_ = true;
                                        }
                                        let _e266 = phi_352_;
                                        if _e266 {
                                            let _e267 = local_33;
                                            if (_e267 >= 0i) {
                                                let _e269 = local_34;
                                                if (_e269 >= 0i) {
                                                    let _e271 = local_5;
                                                    let _e273 = local_33;
                                                    if (_e273 < bitcast<i32>(_e271)) {
                                                        let _e275 = local_6;
                                                        let _e277 = local_34;
                                                        if (_e277 < bitcast<i32>(_e275)) {
                                                            let _e279 = local_34;
                                                            let _e281 = local_5;
                                                            let _e283 = local_33;
                                                            let _e286 = (3u * ((bitcast<u32>(_e279) * _e281) + bitcast<u32>(_e283)));
                                                            local_35 = _e286;
                                                            let _e287 = local_1;
                                                            if (_e286 < _e287) {
                                                            } else {
                                                                phi_826_ = true;
                                                                break;
                                                            }
                                                            let _e289 = local_35;
                                                            let _e292 = global_4.member[_e289];
                                                            local_36 = bitcast<f32>(_e292);
                                                            let _e294 = local_35;
                                                            let _e295 = (_e294 + 1u);
                                                            local_37 = _e295;
                                                            let _e296 = local_1;
                                                            if (_e295 < _e296) {
                                                            } else {
                                                                phi_826_ = true;
                                                                break;
                                                            }
                                                            let _e298 = local_37;
                                                            let _e301 = global_4.member[_e298];
                                                            local_38 = bitcast<f32>(_e301);
                                                            let _e303 = local_35;
                                                            let _e304 = (_e303 + 2u);
                                                            local_39 = _e304;
                                                            let _e305 = local_1;
                                                            if (_e304 < _e305) {
                                                            } else {
                                                                phi_826_ = true;
                                                                break;
                                                            }
                                                            let _e307 = local_39;
                                                            let _e310 = global_4.member[_e307];
                                                            local_40 = bitcast<f32>(_e310);
                                                            let _e312 = local_36;
                                                            if (_e312 > 1267650600000000000000000000000f) {
                                                                let _e314 = local_36;
                                                                phi_446_ = select(true, false, (_e314 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_446_ = true;
                                                            }
                                                            let _e318 = phi_446_;
                                                            if _e318 {
                                                                let _e319 = local_36;
                                                                if (_e319 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e321 = local_36;
                                                                    phi_460_ = select(true, false, (_e321 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_460_ = true;
                                                                }
                                                                let _e325 = phi_460_;
                                                                let _e326 = local_36;
                                                                phi_465_ = select(0f, _e326, _e325);
                                                            } else {
                                                                phi_465_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e329 = phi_465_;
                                                            local_41 = _e329;
                                                            let _e330 = local_38;
                                                            if (_e330 > 1267650600000000000000000000000f) {
                                                                let _e332 = local_38;
                                                                phi_475_ = select(true, false, (_e332 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_475_ = true;
                                                            }
                                                            let _e336 = phi_475_;
                                                            if _e336 {
                                                                let _e337 = local_38;
                                                                if (_e337 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e339 = local_38;
                                                                    phi_489_ = select(true, false, (_e339 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_489_ = true;
                                                                }
                                                                let _e343 = phi_489_;
                                                                let _e344 = local_38;
                                                                phi_494_ = select(0f, _e344, _e343);
                                                            } else {
                                                                phi_494_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e347 = phi_494_;
                                                            local_42 = _e347;
                                                            let _e348 = local_40;
                                                            if (_e348 > 1267650600000000000000000000000f) {
                                                                let _e350 = local_40;
                                                                phi_504_ = select(true, false, (_e350 <= 340282350000000000000000000000000000000f));
                                                            } else {
                                                                phi_504_ = true;
                                                            }
                                                            let _e354 = phi_504_;
                                                            if _e354 {
                                                                let _e355 = local_40;
                                                                if (_e355 < 0.000000000000000000000000000000000000011754944f) {
                                                                    let _e357 = local_40;
                                                                    phi_518_ = select(true, false, (_e357 >= -340282350000000000000000000000000000000f));
                                                                } else {
                                                                    phi_518_ = true;
                                                                }
                                                                let _e361 = phi_518_;
                                                                let _e362 = local_40;
                                                                phi_523_ = select(0f, _e362, _e361);
                                                            } else {
                                                                phi_523_ = 1267650600000000000000000000000f;
                                                            }
                                                            let _e365 = phi_523_;
                                                            local_43 = _e365;
                                                            let _e366 = local_41;
                                                            if ((bitcast<u32>(_e366) & 2139095040u) != 2139095040u) {
                                                                let _e370 = local_42;
                                                                let _e373 = ((bitcast<u32>(_e370) & 2139095040u) != 2139095040u);
                                                                local_44 = _e373;
                                                                if _e373 {
                                                                    let _e374 = local_43;
                                                                    phi_539_ = ((bitcast<u32>(_e374) & 2139095040u) != 2139095040u);
                                                                } else {
                                                                    phi_539_ = bool();
                                                                }
                                                                let _e379 = phi_539_;
                                                                let _e380 = local_44;
                                                                phi_541_ = _e379;
                                                                phi_542_ = select(true, false, _e380);
                                                            } else {
                                                                phi_541_ = bool();
                                                                phi_542_ = true;
                                                            }
                                                            let _e383 = phi_541_;
                                                            let _e385 = phi_542_;
                                                            if select(_e383, false, _e385) {
                                                                let _e387 = local_31;
                                                                let _e389 = local_41;
                                                                let _e391 = local_31;
                                                                let _e393 = local_42;
                                                                let _e395 = local_31;
                                                                let _e397 = local_43;
                                                                let _e400 = local_30;
                                                                phi_560_ = (_e400 + 1f);
                                                                phi_561_ = array<f32, 3>((_e387[0] + _e389), (_e391[1] + _e393), (_e395[2] + _e397));
                                                            } else {
                                                                phi_560_ = _e249;
                                                                phi_561_ = _e251;
                                                            }
                                                            let _e403 = phi_560_;
                                                            let _e405 = phi_561_;
                                                            phi_562_ = _e403;
                                                            phi_563_ = _e405;
                                                        } else {
                                                            phi_562_ = _e249;
                                                            phi_563_ = _e251;
                                                        }
                                                        let _e407 = phi_562_;
                                                        let _e409 = phi_563_;
                                                        phi_564_ = _e407;
                                                        phi_565_ = _e409;
                                                    } else {
                                                        phi_564_ = _e249;
                                                        phi_565_ = _e251;
                                                    }
                                                    let _e411 = phi_564_;
                                                    let _e413 = phi_565_;
                                                    phi_566_ = _e411;
                                                    phi_567_ = _e413;
                                                } else {
                                                    phi_566_ = _e249;
                                                    phi_567_ = _e251;
                                                }
                                                let _e415 = phi_566_;
                                                let _e417 = phi_567_;
                                                phi_568_ = _e415;
                                                phi_569_ = _e417;
                                            } else {
                                                phi_568_ = _e249;
                                                phi_569_ = _e251;
                                            }
                                            let _e419 = phi_568_;
                                            let _e421 = phi_569_;
                                            phi_570_ = _e419;
                                            phi_571_ = _e421;
                                        } else {
                                            phi_570_ = _e249;
                                            phi_571_ = _e251;
                                        }
                                        let _e423 = phi_570_;
                                        let _e425 = phi_571_;
                                        let _e426 = local_29;
                                        phi_329_ = (_e426 + 1i);
                                        phi_332_ = _e423;
                                        phi_334_ = _e425;
                                    } else {
                                        phi_329_ = i32();
                                        phi_332_ = f32();
                                        phi_334_ = array<f32, 3>();
                                    }
                                    let _e429 = phi_329_;
                                    let _e431 = phi_332_;
                                    let _e433 = phi_334_;
                                    continue;
                                    continuing {
                                        let _e434 = local_32;
                                        phi_328_ = _e429;
                                        phi_331_ = _e431;
                                        phi_333_ = _e433;
                                        phi_826_ = _e237;
                                        break if !(_e434);
                                    }
                                }
                                let _e437 = phi_826_;
                                phi_878_ = _e437;
                                if _e437 {
                                    break;
                                }
                                let _e438 = local_25;
                                phi_879_ = _e437;
                                phi_315_ = (_e438 + 1i);
                                let _e728 = local_58;
                                phi_318_ = _e728;
                                let _e731 = local_59;
                                phi_320_ = _e731;
                            } else {
                                phi_879_ = _e237;
                                phi_315_ = i32();
                                phi_318_ = f32();
                                phi_320_ = array<f32, 3>();
                            }
                            let _e441 = phi_879_;
                            let _e443 = phi_315_;
                            let _e445 = phi_318_;
                            let _e447 = phi_320_;
                            continue;
                            continuing {
                                let _e448 = local_28;
                                phi_858_ = _e441;
                                phi_314_ = _e443;
                                phi_317_ = _e445;
                                phi_319_ = _e447;
                                phi_878_ = _e441;
                                break if !(_e448);
                            }
                        }
                        let _e451 = phi_878_;
                        phi_880_ = _e451;
                        if _e451 {
                            break;
                        }
                        let _e452 = local_26;
                        if (_e452 > 0f) {
                            let _e454 = local_27;
                            let _e456 = local_26;
                            let _e458 = local_27;
                            let _e460 = local_26;
                            let _e462 = local_27;
                            let _e464 = local_26;
                            phi_585_ = array<f32, 3>((_e454[0] / _e456), (_e458[1] / _e460), (_e462[2] / _e464));
                        } else {
                            phi_585_ = array<f32, 3>(0f, 0f, 0f);
                        }
                        let _e468 = phi_585_;
                        local_45 = _e468;
                        let _e469 = local_11;
                        let _e470 = local_2;
                        if (_e469 < _e470) {
                        } else {
                            phi_880_ = true;
                            break;
                        }
                        let _e472 = local_11;
                        let _e475 = global_3.member[_e472];
                        let _e476 = bitcast<f32>(_e475);
                        local_46 = _e476;
                        let _e477 = bitcast<u32>(_e476);
                        local_47 = _e477;
                        if (_e477 == 2139095040u) {
                            let _e482 = global_5.member.member_8.member_1;
                            let _e487 = global_5.member.member_8.member;
                            let _e492 = global_5.member.member_8.member_2;
                            let _e498 = global_5.member.member_8.member_3;
                            phi_667_ = (0.5f * ((((2f * _e482) * _e487) / (_e492 - _e487)) * _e498));
                        } else {
                            let _e501 = local_47;
                            if (_e501 == 0u) {
                                phi_630_ = false;
                            } else {
                                let _e503 = local_47;
                                phi_630_ = (_e503 <= 2139095040u);
                            }
                            let _e506 = phi_630_;
                            if _e506 {
                                let _e510 = global_5.member.member_8.member_1;
                                let _e515 = global_5.member.member_8.member;
                                let _e520 = global_5.member.member_8.member_2;
                                local_48 = _e520;
                                let _e526 = global_5.member.member_8.member_3;
                                let _e527 = ((((2f * _e510) * _e515) / (_e520 - _e515)) * _e526);
                                local_49 = _e527;
                                if (_e527 == 0f) {
                                    phi_658_ = 0f;
                                } else {
                                    let _e529 = local_48;
                                    let _e530 = local_46;
                                    let _e533 = local_49;
                                    phi_658_ = (_e533 * (1f - (_e529 / _e530)));
                                }
                                let _e536 = phi_658_;
                                phi_659_ = _e536;
                            } else {
                                phi_659_ = bitcast<f32>(_e104);
                            }
                            let _e538 = phi_659_;
                            local_50 = _e538;
                            if (_e538 < 0f) {
                                let _e540 = local_50;
                                phi_665_ = -(_e540);
                            } else {
                                phi_665_ = _e538;
                            }
                            let _e543 = phi_665_;
                            phi_667_ = (0.5f * _e543);
                        }
                        let _e546 = phi_667_;
                        let _e550 = select(_e546, 0f, ((bitcast<u32>(_e546) & 2147483647u) > 2139095040u));
                        local_56 = _e550;
                        let _e553 = global_5.member.member_6;
                        local_51 = _e553;
                        if !((_e550 == _e550)) {
                            phi_813_ = true;
                        } else {
                            let _e556 = local_51;
                            let _e557 = local_56;
                            phi_813_ = (_e556 <= _e557);
                        }
                        let _e560 = phi_813_;
                        let _e561 = local_51;
                        let _e562 = local_56;
                        local_57 = select(_e562, _e561, _e560);
                        let _e564 = local_21;
                        if ((bitcast<u32>(_e564) & 2139095040u) != 2139095040u) {
                            let _e568 = local_22;
                            let _e571 = ((bitcast<u32>(_e568) & 2139095040u) != 2139095040u);
                            local_52 = _e571;
                            if _e571 {
                                let _e572 = local_23;
                                phi_693_ = ((bitcast<u32>(_e572) & 2139095040u) != 2139095040u);
                            } else {
                                phi_693_ = bool();
                            }
                            let _e577 = phi_693_;
                            let _e578 = local_52;
                            phi_695_ = _e577;
                            phi_696_ = select(true, false, _e578);
                        } else {
                            phi_695_ = bool();
                            phi_696_ = true;
                        }
                        let _e581 = phi_695_;
                        let _e583 = phi_696_;
                        if select(_e581, false, _e583) {
                            let _e585 = local_47;
                            if (_e585 == 0u) {
                                phi_710_ = false;
                            } else {
                                let _e587 = local_47;
                                phi_710_ = (_e587 <= 2139095040u);
                            }
                            let _e590 = phi_710_;
                            if _e590 {
                                let _e591 = local_21;
                                let _e593 = local_22;
                                let _e596 = local_23;
                                let _e599 = local_45;
                                let _e602 = local_45;
                                let _e606 = local_45;
                                let _e613 = global_5.member.member_4;
                                if (((((0.2126f * _e591) + (0.7152f * _e593)) + (0.0722f * _e596)) - (((0.2126f * _e599[0]) + (0.7152f * _e602[1])) + (0.0722f * _e606[2]))) > _e613) {
                                    let _e617 = global_5.member.member_5;
                                    let _e618 = local_57;
                                    let _e619 = (_e618 > _e617);
                                    local_53 = _e619;
                                    if _e619 {
                                        let _e620 = local_24;
                                        let _e621 = local_45;
                                        let _e622 = local_57;
                                        let _e623 = local_46;
                                        phi_742_ = type_21(1u, type_20(_e620, _e621, _e622, _e623));
                                    } else {
                                        phi_742_ = type_21();
                                    }
                                    let _e627 = phi_742_;
                                    let _e628 = local_53;
                                    phi_744_ = _e627;
                                    phi_745_ = select(true, false, _e628);
                                } else {
                                    phi_744_ = type_21();
                                    phi_745_ = true;
                                }
                                let _e631 = phi_744_;
                                let _e633 = phi_745_;
                                phi_746_ = _e631;
                                phi_747_ = _e633;
                            } else {
                                phi_746_ = type_21();
                                phi_747_ = true;
                            }
                            let _e635 = phi_746_;
                            let _e637 = phi_747_;
                            phi_748_ = _e635;
                            phi_749_ = _e637;
                        } else {
                            phi_748_ = type_21();
                            phi_749_ = true;
                        }
                        let _e639 = phi_748_;
                        let _e641 = phi_749_;
                        if _e641 {
                            phi_754_ = type_21(0u, type_21().member_1);
                        } else {
                            phi_754_ = _e639;
                        }
                        let _e646 = phi_754_;
                        let _e649 = (bitcast<i32>(_e646.member) == 1i);
                        local_54 = _e649;
                        if _e649 {
                            let _e650 = local_4;
                            if (4u < _e650) {
                            } else {
                                phi_880_ = true;
                                break;
                            }
                            let _e654 = atomicAdd((&global_7.member[4u]), 1u);
                        }
                        let _e655 = local_54;
                        local_55 = select(0u, 1u, _e655);
                        let _e657 = local_11;
                        let _e658 = local_3;
                        if (_e657 < _e658) {
                        } else {
                            phi_880_ = true;
                            break;
                        }
                        let _e660 = local_11;
                        let _e663 = local_55;
                        global_6.member[_e660] = _e663;
                        phi_882_ = _e451;
                    } else {
                        phi_882_ = _e130;
                    }
                    let _e665 = phi_882_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e666 = local_9;
                    let _e667 = local_8;
                    phi_881_ = _e665;
                    phi_142_ = (_e666 + _e667);
                } else {
                    phi_881_ = _e130;
                    phi_142_ = u32();
                }
                let _e670 = phi_881_;
                let _e672 = phi_142_;
                continue;
                continuing {
                    let _e673 = local_10;
                    phi_877_ = _e670;
                    phi_141_ = _e672;
                    phi_880_ = _e670;
                    break if !(_e673);
                }
            }
            let _e676 = phi_880_;
            if _e676 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn bokeh_detect(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
