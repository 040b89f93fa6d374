struct type_6 {
    member: array<u32>,
}

struct type_11 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
}

struct type_12 {
    member: type_11,
}

struct type_19 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_3: type_6;
var<immediate> global_4: type_12;
@group(0) @binding(0) 
var<storage> global_5: type_6;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_19;

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
    var local_12: bool;
    var local_13: u32;
    var local_14: f32;
    var local_15: u32;
    var local_16: f32;
    var local_17: u32;
    var local_18: f32;
    var local_19: u32;
    var local_20: f32;
    var local_21: u32;
    var local_22: f32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: bool;
    var local_27: u32;
    var local_28: f32;
    var local_29: f32;
    var local_30: f32;
    var local_31: u32;
    var local_32: u32;
    var local_33: bool;
    var local_34: u32;
    var phi_503_: bool;
    var phi_89_: u32;
    var phi_134_: u32;
    var phi_137_: u32;
    var phi_258_: bool;
    var phi_271_: bool;
    var phi_285_: bool;
    var phi_290_: f32;
    var phi_300_: bool;
    var phi_314_: bool;
    var phi_319_: f32;
    var phi_329_: bool;
    var phi_343_: bool;
    var phi_348_: f32;
    var phi_440_: bool;
    var phi_450_: bool;
    var phi_460_: bool;
    var phi_358_: bool;
    var phi_360_: bool;
    var phi_361_: bool;
    var phi_373_: bool;
    var phi_378_: u32;
    var phi_379_: u32;
    var phi_381_: u32;
    var phi_382_: bool;
    var phi_383_: u32;
    var phi_384_: bool;
    var phi_135_: u32;
    var phi_138_: u32;
    var phi_467_: bool;
    var phi_506_: bool;
    var phi_505_: bool;
    var phi_90_: u32;
    var phi_504_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e63 = global;
            local = _e63;
            let _e64 = global_1;
            let _e65 = global_2;
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            let _e76 = global_4.member.member;
            local_4 = _e76;
            local_5 = (_e65.x * 256u);
            phi_503_ = false;
            phi_89_ = (_e64.x * 256u);
            loop {
                let _e80 = phi_503_;
                let _e82 = phi_89_;
                local_6 = _e82;
                let _e83 = local_6;
                let _e84 = local_4;
                let _e85 = (_e83 < _e84);
                local_7 = _e85;
                if _e85 {
                    let _e86 = local_6;
                    let _e87 = local;
                    let _e88 = (_e86 + _e87);
                    local_8 = _e88;
                    let _e89 = local_4;
                    if (_e88 < _e89) {
                        let _e91 = local_8;
                        let _e92 = local_2;
                        if (_e91 < _e92) {
                        } else {
                            phi_504_ = true;
                            break;
                        }
                        let _e94 = local_8;
                        let _e97 = global_3.member[_e94];
                        let _e100 = global_4.member.member_1;
                        local_9 = _e100;
                        let _e102 = select(_e97, _e100, (_e100 < _e97));
                        let _e105 = global_4.member.member_3;
                        local_34 = select(_e102, _e105, (_e105 < _e102));
                        phi_134_ = 0u;
                        phi_137_ = 0u;
                        loop {
                            let _e109 = phi_134_;
                            let _e111 = phi_137_;
                            local_10 = _e109;
                            local_11 = _e111;
                            let _e112 = local_10;
                            let _e113 = local_34;
                            let _e114 = (_e112 < _e113);
                            local_12 = _e114;
                            if _e114 {
                                let _e115 = local_8;
                                let _e116 = local_9;
                                let _e118 = local_10;
                                let _e120 = (5u * ((_e115 * _e116) + _e118));
                                local_13 = _e120;
                                let _e121 = local_1;
                                if (_e120 < _e121) {
                                } else {
                                    phi_467_ = true;
                                    break;
                                }
                                let _e123 = local_13;
                                let _e126 = global_5.member[_e123];
                                local_14 = bitcast<f32>(_e126);
                                let _e128 = local_13;
                                let _e129 = (_e128 + 1u);
                                local_15 = _e129;
                                let _e130 = local_1;
                                if (_e129 < _e130) {
                                } else {
                                    phi_467_ = true;
                                    break;
                                }
                                let _e132 = local_15;
                                let _e135 = global_5.member[_e132];
                                local_16 = bitcast<f32>(_e135);
                                let _e137 = local_13;
                                let _e138 = (_e137 + 2u);
                                local_17 = _e138;
                                let _e139 = local_1;
                                if (_e138 < _e139) {
                                } else {
                                    phi_467_ = true;
                                    break;
                                }
                                let _e141 = local_17;
                                let _e144 = global_5.member[_e141];
                                local_18 = bitcast<f32>(_e144);
                                let _e146 = local_13;
                                let _e147 = (_e146 + 3u);
                                local_19 = _e147;
                                let _e148 = local_1;
                                if (_e147 < _e148) {
                                } else {
                                    phi_467_ = true;
                                    break;
                                }
                                let _e150 = local_19;
                                let _e153 = global_5.member[_e150];
                                local_20 = bitcast<f32>(_e153);
                                let _e155 = local_13;
                                let _e156 = (_e155 + 4u);
                                local_21 = _e156;
                                let _e157 = local_1;
                                if (_e156 < _e157) {
                                } else {
                                    phi_467_ = true;
                                    break;
                                }
                                let _e159 = local_21;
                                let _e162 = global_5.member[_e159];
                                local_22 = bitcast<f32>(_e162);
                                let _e164 = local_14;
                                let _e165 = bitcast<u32>(_e164);
                                local_23 = _e165;
                                if ((_e165 & 2139095040u) != 2139095040u) {
                                    let _e168 = local_16;
                                    let _e169 = bitcast<u32>(_e168);
                                    local_24 = _e169;
                                    if ((_e169 & 2139095040u) != 2139095040u) {
                                        let _e172 = local_18;
                                        let _e173 = bitcast<u32>(_e172);
                                        local_25 = _e173;
                                        let _e175 = ((_e173 & 2139095040u) != 2139095040u);
                                        local_26 = _e175;
                                        if _e175 {
                                            let _e176 = local_20;
                                            let _e177 = bitcast<u32>(_e176);
                                            local_27 = _e177;
                                            if (_e177 == 0u) {
                                                phi_258_ = false;
                                            } else {
                                                let _e179 = local_27;
                                                phi_258_ = (_e179 <= 2139095040u);
                                            }
                                            let _e182 = phi_258_;
                                            if _e182 {
                                                let _e183 = local_14;
                                                if (_e183 > 1267650600000000000000000000000f) {
                                                    let _e185 = local_14;
                                                    phi_271_ = select(true, false, (_e185 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_271_ = true;
                                                }
                                                let _e189 = phi_271_;
                                                if _e189 {
                                                    let _e190 = local_14;
                                                    if (_e190 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e192 = local_14;
                                                        phi_285_ = select(true, false, (_e192 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_285_ = true;
                                                    }
                                                    let _e196 = phi_285_;
                                                    let _e197 = local_14;
                                                    phi_290_ = select(0f, _e197, _e196);
                                                } else {
                                                    phi_290_ = 1267650600000000000000000000000f;
                                                }
                                                let _e200 = phi_290_;
                                                local_28 = _e200;
                                                let _e201 = local_16;
                                                if (_e201 > 1267650600000000000000000000000f) {
                                                    let _e203 = local_16;
                                                    phi_300_ = select(true, false, (_e203 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_300_ = true;
                                                }
                                                let _e207 = phi_300_;
                                                if _e207 {
                                                    let _e208 = local_16;
                                                    if (_e208 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e210 = local_16;
                                                        phi_314_ = select(true, false, (_e210 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_314_ = true;
                                                    }
                                                    let _e214 = phi_314_;
                                                    let _e215 = local_16;
                                                    phi_319_ = select(0f, _e215, _e214);
                                                } else {
                                                    phi_319_ = 1267650600000000000000000000000f;
                                                }
                                                let _e218 = phi_319_;
                                                local_29 = _e218;
                                                let _e219 = local_18;
                                                if (_e219 > 1267650600000000000000000000000f) {
                                                    let _e221 = local_18;
                                                    phi_329_ = select(true, false, (_e221 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_329_ = true;
                                                }
                                                let _e225 = phi_329_;
                                                if _e225 {
                                                    let _e226 = local_18;
                                                    if (_e226 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e228 = local_18;
                                                        phi_343_ = select(true, false, (_e228 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_343_ = true;
                                                    }
                                                    let _e232 = phi_343_;
                                                    let _e233 = local_18;
                                                    phi_348_ = select(0f, _e233, _e232);
                                                } else {
                                                    phi_348_ = 1267650600000000000000000000000f;
                                                }
                                                let _e236 = phi_348_;
                                                local_30 = _e236;
                                                let _e237 = local_14;
                                                let _e238 = local_28;
                                                if (_e237 == _e238) {
                                                    phi_440_ = true;
                                                } else {
                                                    let _e240 = local_23;
                                                    phi_440_ = ((_e240 & 2147483647u) > 2139095040u);
                                                }
                                                let _e244 = phi_440_;
                                                if _e244 {
                                                    let _e245 = local_16;
                                                    let _e246 = local_29;
                                                    if (_e245 == _e246) {
                                                        phi_450_ = true;
                                                    } else {
                                                        let _e248 = local_24;
                                                        phi_450_ = ((_e248 & 2147483647u) > 2139095040u);
                                                    }
                                                    let _e252 = phi_450_;
                                                    local_33 = _e252;
                                                    if _e252 {
                                                        let _e253 = local_18;
                                                        let _e254 = local_30;
                                                        if (_e253 == _e254) {
                                                            phi_460_ = true;
                                                        } else {
                                                            let _e256 = local_25;
                                                            phi_460_ = ((_e256 & 2147483647u) > 2139095040u);
                                                        }
                                                        let _e260 = phi_460_;
                                                        phi_358_ = _e260;
                                                    } else {
                                                        phi_358_ = bool();
                                                    }
                                                    let _e262 = phi_358_;
                                                    let _e263 = local_33;
                                                    phi_360_ = _e262;
                                                    phi_361_ = select(true, false, _e263);
                                                } else {
                                                    phi_360_ = bool();
                                                    phi_361_ = true;
                                                }
                                                let _e266 = phi_360_;
                                                let _e268 = phi_361_;
                                                local_31 = select(0u, 1u, !(select(_e266, false, _e268)));
                                                let _e272 = local_22;
                                                if (_e272 >= 0f) {
                                                    let _e274 = local_22;
                                                    phi_373_ = (_e274 <= 1f);
                                                } else {
                                                    phi_373_ = false;
                                                }
                                                let _e277 = phi_373_;
                                                let _e280 = local_31;
                                                let _e282 = local_11;
                                                phi_378_ = (_e282 + (_e280 + select(0u, 1u, !(_e277))));
                                            } else {
                                                phi_378_ = _e111;
                                            }
                                            let _e285 = phi_378_;
                                            phi_379_ = _e285;
                                        } else {
                                            phi_379_ = u32();
                                        }
                                        let _e287 = phi_379_;
                                        let _e288 = local_26;
                                        phi_381_ = _e287;
                                        phi_382_ = select(true, false, _e288);
                                    } else {
                                        phi_381_ = u32();
                                        phi_382_ = true;
                                    }
                                    let _e291 = phi_381_;
                                    let _e293 = phi_382_;
                                    phi_383_ = _e291;
                                    phi_384_ = _e293;
                                } else {
                                    phi_383_ = u32();
                                    phi_384_ = true;
                                }
                                let _e295 = phi_383_;
                                let _e297 = phi_384_;
                                let _e298 = local_11;
                                let _e300 = local_10;
                                phi_135_ = (_e300 + 1u);
                                phi_138_ = select(_e295, _e298, _e297);
                            } else {
                                phi_135_ = u32();
                                phi_138_ = u32();
                            }
                            let _e303 = phi_135_;
                            let _e305 = phi_138_;
                            continue;
                            continuing {
                                let _e306 = local_12;
                                phi_134_ = _e303;
                                phi_137_ = _e305;
                                phi_467_ = _e80;
                                break if !(_e306);
                            }
                        }
                        let _e309 = phi_467_;
                        phi_504_ = _e309;
                        if _e309 {
                            break;
                        }
                        let _e310 = local_11;
                        if (_e310 > 0u) {
                            let _e314 = global_4.member.member_2;
                            local_32 = _e314;
                            let _e315 = local_3;
                            if (_e314 < _e315) {
                            } else {
                                phi_504_ = true;
                                break;
                            }
                            let _e317 = local_32;
                            let _e320 = local_11;
                            let _e321 = atomicAdd((&global_6.member[_e317]), _e320);
                        }
                        phi_506_ = _e309;
                    } else {
                        phi_506_ = _e80;
                    }
                    let _e323 = phi_506_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e324 = local_6;
                    let _e325 = local_5;
                    phi_505_ = _e323;
                    phi_90_ = (_e324 + _e325);
                } else {
                    phi_505_ = _e80;
                    phi_90_ = u32();
                }
                let _e328 = phi_505_;
                let _e330 = phi_90_;
                continue;
                continuing {
                    let _e331 = local_7;
                    phi_503_ = _e328;
                    phi_89_ = _e330;
                    phi_504_ = _e328;
                    break if !(_e331);
                }
            }
            let _e334 = phi_504_;
            if _e334 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn radiance_count_clamped(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
