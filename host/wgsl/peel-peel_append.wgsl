struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_14 {
    member: type_5,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: array<u32, 2>,
}

struct type_15 {
    member: type_14,
}

struct type_17 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: f32,
}

struct type_25 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_15;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage, read_write> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_25;

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
    var local_12: f32;
    var local_13: u32;
    var local_14: f32;
    var local_15: bool;
    var local_16: bool;
    var local_17: u32;
    var local_18: u32;
    var local_19: bool;
    var local_20: u32;
    var local_21: u32;
    var local_22: f32;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: array<f32, 3>;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: f32;
    var local_32: u32;
    var local_33: f32;
    var local_34: u32;
    var local_35: f32;
    var local_36: u32;
    var local_37: f32;
    var local_38: u32;
    var local_39: array<f32, 3>;
    var local_40: type_17;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: f32;
    var local_51: u32;
    var local_52: bool;
    var local_53: f32;
    var phi_95_: u32;
    var phi_152_: bool;
    var phi_204_: f32;
    var phi_206_: f32;
    var phi_207_: bool;
    var phi_227_: u32;
    var phi_228_: u32;
    var phi_229_: bool;
    var phi_234_: u32;
    var phi_300_: array<f32, 3>;
    var phi_429_: type_17;
    var phi_430_: type_17;
    var phi_532_: bool;
    var phi_96_: u32;
    var phi_585_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e78 = global;
            local = _e78;
            let _e79 = global_1;
            let _e80 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e93 = global_3.member.member_1;
            let _e96 = global_3.member.member_2;
            local_5 = (_e93 * _e96);
            local_6 = (_e80.x * 256u);
            phi_95_ = (_e79.x * 256u);
            loop {
                let _e101 = phi_95_;
                local_7 = _e101;
                let _e102 = local_7;
                let _e103 = local_5;
                let _e104 = (_e102 < _e103);
                local_8 = _e104;
                if _e104 {
                    let _e105 = local_7;
                    let _e106 = local;
                    let _e107 = (_e105 + _e106);
                    local_9 = _e107;
                    let _e108 = local_5;
                    if (_e107 < _e108) {
                        let _e110 = local_9;
                        let _e111 = (5u * _e110);
                        local_10 = _e111;
                        let _e112 = (_e111 + 3u);
                        local_11 = _e112;
                        let _e113 = local_1;
                        if (_e112 < _e113) {
                        } else {
                            phi_585_ = true;
                            break;
                        }
                        let _e115 = local_11;
                        let _e118 = global_4.member[_e115];
                        local_12 = bitcast<f32>(_e118);
                        let _e120 = local_10;
                        let _e121 = (_e120 + 4u);
                        local_13 = _e121;
                        let _e122 = local_1;
                        if (_e121 < _e122) {
                        } else {
                            phi_585_ = true;
                            break;
                        }
                        let _e124 = local_13;
                        let _e127 = global_4.member[_e124];
                        let _e128 = bitcast<f32>(_e127);
                        local_14 = _e128;
                        let _e131 = ((bitcast<u32>(_e128) & 2139095040u) != 2139095040u);
                        local_15 = _e131;
                        if _e131 {
                            phi_152_ = true;
                        } else {
                            let _e132 = local_12;
                            phi_152_ = (_e132 > 0f);
                        }
                        let _e135 = phi_152_;
                        if _e135 {
                            let _e136 = local_9;
                            let _e137 = local_3;
                            let _e138 = (_e136 < _e137);
                            local_16 = _e138;
                            if _e138 {
                            } else {
                                phi_585_ = true;
                                break;
                            }
                            let _e139 = local_9;
                            let _e142 = global_6.member[_e139];
                            local_17 = _e142;
                            let _e145 = global_3.member.member_3;
                            local_18 = _e145;
                            if (_e142 >= _e145) {
                                let _e147 = local_17;
                                let _e148 = (_e147 > 0u);
                                local_19 = _e148;
                                if _e148 {
                                    let _e149 = local_9;
                                    let _e150 = local_18;
                                    let _e152 = local_17;
                                    let _e156 = ((5u * (((_e149 * _e150) + _e152) - 1u)) + 4u);
                                    local_20 = _e156;
                                    let _e157 = local_2;
                                    if (_e156 < _e157) {
                                    } else {
                                        phi_585_ = true;
                                        break;
                                    }
                                    let _e159 = local_20;
                                    let _e162 = global_5.member[_e159];
                                    phi_204_ = bitcast<f32>(_e162);
                                } else {
                                    phi_204_ = f32();
                                }
                                let _e165 = phi_204_;
                                let _e166 = local_19;
                                phi_206_ = _e165;
                                phi_207_ = select(true, false, _e166);
                            } else {
                                phi_206_ = f32();
                                phi_207_ = true;
                            }
                            let _e169 = phi_206_;
                            let _e171 = phi_207_;
                            local_53 = select(_e169, 0f, _e171);
                            let _e173 = local_17;
                            let _e174 = local_18;
                            if (_e173 < _e174) {
                                phi_234_ = _e142;
                            } else {
                                let _e176 = local_17;
                                if (_e176 > 0u) {
                                    let _e178 = local_53;
                                    let _e179 = (_e178 >= 1f);
                                    if _e179 {
                                        phi_227_ = u32();
                                    } else {
                                        let _e180 = local_17;
                                        phi_227_ = (_e180 - 1u);
                                    }
                                    let _e183 = phi_227_;
                                    phi_228_ = _e183;
                                    phi_229_ = _e179;
                                } else {
                                    phi_228_ = u32();
                                    phi_229_ = true;
                                }
                                let _e185 = phi_228_;
                                let _e187 = phi_229_;
                                let _e188 = local_18;
                                phi_234_ = select(_e185, _e188, _e187);
                            }
                            let _e191 = phi_234_;
                            local_21 = _e191;
                            let _e192 = local_18;
                            if (_e191 == _e192) {
                            } else {
                                let _e194 = local_10;
                                let _e195 = local_1;
                                if (_e194 < _e195) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e197 = local_10;
                                let _e200 = global_4.member[_e197];
                                local_22 = bitcast<f32>(_e200);
                                let _e202 = local_10;
                                let _e203 = (_e202 + 1u);
                                local_23 = _e203;
                                let _e204 = local_1;
                                if (_e203 < _e204) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e206 = local_23;
                                let _e209 = global_4.member[_e206];
                                local_24 = bitcast<f32>(_e209);
                                let _e211 = local_10;
                                let _e212 = (_e211 + 2u);
                                local_25 = _e212;
                                let _e213 = local_1;
                                if (_e212 < _e213) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e215 = local_25;
                                let _e218 = global_4.member[_e215];
                                let _e219 = bitcast<f32>(_e218);
                                local_26 = _e219;
                                let _e220 = local_22;
                                let _e221 = local_24;
                                let _e223 = local_12;
                                if (_e223 == 1f) {
                                    phi_300_ = array<f32, 3>(_e220, _e221, _e219);
                                } else {
                                    let _e225 = local_22;
                                    let _e226 = local_12;
                                    let _e228 = local_24;
                                    let _e229 = local_12;
                                    let _e231 = local_26;
                                    let _e232 = local_12;
                                    phi_300_ = array<f32, 3>((_e225 * _e226), (_e228 * _e229), (_e231 * _e232));
                                }
                                let _e236 = phi_300_;
                                local_27 = _e236;
                                let _e237 = local_14;
                                let _e238 = local_12;
                                let _e240 = local_9;
                                let _e241 = local_18;
                                let _e243 = local_21;
                                local_28 = ((_e240 * _e241) + _e243);
                                let _e245 = local_21;
                                let _e246 = local_17;
                                if (_e245 == _e246) {
                                    let _e248 = local_17;
                                    local_29 = (_e248 + 1u);
                                    let _e250 = local_16;
                                    if _e250 {
                                    } else {
                                        phi_585_ = true;
                                        break;
                                    }
                                    let _e251 = local_29;
                                    global_6.member[_e139] = _e251;
                                    phi_430_ = type_17(_e236, _e237, _e238);
                                } else {
                                    let _e252 = local_28;
                                    let _e253 = (5u * _e252);
                                    local_30 = _e253;
                                    let _e254 = local_2;
                                    if (_e253 < _e254) {
                                    } else {
                                        phi_585_ = true;
                                        break;
                                    }
                                    let _e256 = local_30;
                                    let _e259 = global_5.member[_e256];
                                    local_31 = bitcast<f32>(_e259);
                                    let _e261 = local_30;
                                    let _e262 = (_e261 + 1u);
                                    local_32 = _e262;
                                    let _e263 = local_2;
                                    if (_e262 < _e263) {
                                    } else {
                                        phi_585_ = true;
                                        break;
                                    }
                                    let _e265 = local_32;
                                    let _e268 = global_5.member[_e265];
                                    local_33 = bitcast<f32>(_e268);
                                    let _e270 = local_30;
                                    let _e271 = (_e270 + 2u);
                                    local_34 = _e271;
                                    let _e272 = local_2;
                                    if (_e271 < _e272) {
                                    } else {
                                        phi_585_ = true;
                                        break;
                                    }
                                    let _e274 = local_34;
                                    let _e277 = global_5.member[_e274];
                                    local_35 = bitcast<f32>(_e277);
                                    let _e279 = local_30;
                                    let _e280 = (_e279 + 3u);
                                    local_36 = _e280;
                                    let _e281 = local_2;
                                    if (_e280 < _e281) {
                                    } else {
                                        phi_585_ = true;
                                        break;
                                    }
                                    let _e283 = local_36;
                                    let _e286 = global_5.member[_e283];
                                    local_37 = bitcast<f32>(_e286);
                                    let _e288 = local_30;
                                    let _e289 = (_e288 + 4u);
                                    local_38 = _e289;
                                    let _e290 = local_2;
                                    if (_e289 < _e290) {
                                    } else {
                                        phi_585_ = true;
                                        break;
                                    }
                                    let _e292 = local_38;
                                    let _e295 = global_5.member[_e292];
                                    let _e296 = bitcast<f32>(_e295);
                                    let _e297 = (1f - _e296);
                                    let _e298 = local_27;
                                    let _e301 = local_31;
                                    let _e303 = local_27;
                                    let _e306 = local_33;
                                    let _e308 = local_27;
                                    let _e311 = local_35;
                                    let _e313 = array<f32, 3>((_e301 + (_e297 * _e298[0])), (_e306 + (_e297 * _e303[1])), (_e311 + (_e297 * _e308[2])));
                                    local_39 = _e313;
                                    let _e314 = local_12;
                                    let _e317 = local_37;
                                    let _e319 = local_12;
                                    if (_e319 >= 1f) {
                                        let _e321 = local_39;
                                        let _e322 = local_37;
                                        phi_429_ = type_17(_e321, _e322, 1f);
                                    } else {
                                        phi_429_ = type_17(_e313, _e317, (_e296 + (_e297 * _e314)));
                                    }
                                    let _e325 = phi_429_;
                                    phi_430_ = _e325;
                                }
                                let _e327 = phi_430_;
                                local_40 = _e327;
                                let _e328 = local_28;
                                let _e329 = (5u * _e328);
                                local_41 = _e329;
                                local_42 = bitcast<u32>(_e327.member[0]);
                                let _e333 = local_2;
                                if (_e329 < _e333) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e335 = local_41;
                                let _e338 = local_42;
                                global_5.member[_e335] = _e338;
                                let _e339 = local_41;
                                let _e340 = (_e339 + 1u);
                                local_43 = _e340;
                                let _e341 = local_40;
                                local_44 = bitcast<u32>(_e341.member[1]);
                                let _e345 = local_2;
                                if (_e340 < _e345) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e347 = local_43;
                                let _e350 = local_44;
                                global_5.member[_e347] = _e350;
                                let _e351 = local_41;
                                let _e352 = (_e351 + 2u);
                                local_45 = _e352;
                                let _e353 = local_40;
                                local_46 = bitcast<u32>(_e353.member[2]);
                                let _e357 = local_2;
                                if (_e352 < _e357) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e359 = local_45;
                                let _e362 = local_46;
                                global_5.member[_e359] = _e362;
                                let _e363 = local_41;
                                let _e364 = (_e363 + 3u);
                                local_47 = _e364;
                                let _e365 = local_40;
                                local_48 = bitcast<u32>(_e365.member_1);
                                let _e368 = local_2;
                                if (_e364 < _e368) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e370 = local_47;
                                let _e373 = local_48;
                                global_5.member[_e370] = _e373;
                                let _e374 = local_41;
                                let _e375 = (_e374 + 4u);
                                local_49 = _e375;
                                let _e376 = local_40;
                                local_50 = _e376.member_2;
                                local_51 = bitcast<u32>(_e376.member_2);
                                let _e379 = local_2;
                                if (_e375 < _e379) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e381 = local_49;
                                let _e384 = local_51;
                                global_5.member[_e381] = _e384;
                                let _e385 = local_15;
                                if _e385 {
                                    let _e386 = local_21;
                                    let _e388 = local_18;
                                    if ((_e386 + 1u) < _e388) {
                                        phi_532_ = true;
                                    } else {
                                        let _e390 = local_50;
                                        phi_532_ = !((_e390 >= 1f));
                                    }
                                    let _e394 = phi_532_;
                                    if _e394 {
                                        let _e395 = local_4;
                                        let _e396 = (0u < _e395);
                                        local_52 = _e396;
                                        if _e396 {
                                        } else {
                                            phi_585_ = true;
                                            break;
                                        }
                                        let _e399 = atomicLoad((&global_7.member[0u]));
                                        if (_e399 == 0u) {
                                            let _e401 = local_52;
                                            if _e401 {
                                            } else {
                                                phi_585_ = true;
                                                break;
                                            }
                                            let _e402 = atomicMax((&global_7.member[0u]), 1u);
                                        }
                                    }
                                }
                            }
                        }
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e403 = local_7;
                    let _e404 = local_6;
                    phi_96_ = (_e403 + _e404);
                } else {
                    phi_96_ = u32();
                }
                let _e407 = phi_96_;
                continue;
                continuing {
                    let _e408 = local_8;
                    phi_95_ = _e407;
                    phi_585_ = false;
                    break if !(_e408);
                }
            }
            let _e411 = phi_585_;
            if _e411 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn peel_append(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
