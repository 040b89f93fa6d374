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
    member: array<f32, 3>,
    member_1: f32,
    member_2: f32,
}

struct type_18 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: type_5,
    member_9: array<u32, 14>,
    member_10: array<u32, 2>,
}

struct type_19 {
    member: type_18,
}

struct type_21 {
    member: u32,
    member_1: type_16,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_7;
var<immediate> global_5: type_19;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
var<private> global_7: u32 = 2143289344u;
var<private> global_8: u32 = 4286578688u;
var<private> global_9: u32 = 2139095040u;

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
    var local_11: f32;
    var local_12: f32;
    var local_13: bool;
    var local_14: u32;
    var local_15: f32;
    var local_16: u32;
    var local_17: f32;
    var local_18: u32;
    var local_19: f32;
    var local_20: u32;
    var local_21: f32;
    var local_22: u32;
    var local_23: f32;
    var local_24: bool;
    var local_25: u32;
    var local_26: u32;
    var local_27: f32;
    var local_28: f32;
    var local_29: f32;
    var local_30: bool;
    var local_31: f32;
    var local_32: f32;
    var local_33: array<f32, 3>;
    var local_34: type_21;
    var local_35: f32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var phi_646_: bool;
    var phi_144_: u32;
    var phi_219_: f32;
    var phi_220_: f32;
    var phi_222_: u32;
    var phi_225_: f32;
    var phi_227_: f32;
    var phi_348_: bool;
    var phi_349_: bool;
    var phi_351_: bool;
    var phi_352_: bool;
    var phi_353_: bool;
    var phi_354_: bool;
    var phi_369_: bool;
    var phi_397_: f32;
    var phi_398_: f32;
    var phi_415_: bool;
    var phi_429_: bool;
    var phi_434_: f32;
    var phi_444_: bool;
    var phi_458_: bool;
    var phi_463_: f32;
    var phi_473_: bool;
    var phi_487_: bool;
    var phi_492_: f32;
    var phi_503_: f32;
    var phi_506_: type_21;
    var phi_508_: type_21;
    var phi_509_: bool;
    var phi_514_: type_21;
    var phi_580_: bool;
    var phi_595_: bool;
    var phi_524_: f32;
    var phi_525_: f32;
    var phi_223_: u32;
    var phi_226_: f32;
    var phi_228_: f32;
    var phi_606_: bool;
    var phi_650_: bool;
    var phi_649_: bool;
    var phi_145_: u32;
    var phi_648_: bool;

    let _e80 = global_7;
    let _e82 = global_8;
    let _e84 = global_9;
    switch bitcast<i32>(0u) {
        default: {
            let _e87 = global;
            local = _e87;
            let _e88 = global_1;
            let _e89 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            let _e100 = global_5.member.member;
            let _e103 = global_5.member.member_1;
            local_4 = (_e100 * _e103);
            local_5 = (_e89.x * 256u);
            phi_646_ = false;
            phi_144_ = (_e88.x * 256u);
            loop {
                let _e108 = phi_646_;
                let _e110 = phi_144_;
                local_6 = _e110;
                let _e111 = local_6;
                let _e112 = local_4;
                let _e113 = (_e111 < _e112);
                local_7 = _e113;
                if _e113 {
                    let _e114 = local_6;
                    let _e115 = local;
                    let _e116 = (_e114 + _e115);
                    local_8 = _e116;
                    let _e117 = local_4;
                    if (_e116 < _e117) {
                        let _e119 = local_8;
                        let _e120 = local_2;
                        if (_e119 < _e120) {
                        } else {
                            phi_648_ = true;
                            break;
                        }
                        let _e122 = local_8;
                        let _e125 = global_3.member[_e122];
                        let _e128 = global_5.member.member_2;
                        local_9 = _e128;
                        let _e130 = select(_e125, _e128, (_e128 < _e125));
                        local_40 = _e130;
                        if (_e130 == 0u) {
                            let _e135 = global_5.member.member_8.member_1;
                            let _e140 = global_5.member.member_8.member;
                            let _e145 = global_5.member.member_8.member_2;
                            let _e151 = global_5.member.member_8.member_3;
                            let _e153 = (0.5f * ((((2f * _e135) * _e140) / (_e145 - _e140)) * _e151));
                            phi_219_ = _e153;
                            phi_220_ = _e153;
                        } else {
                            phi_219_ = bitcast<f32>(_e82);
                            phi_220_ = bitcast<f32>(_e84);
                        }
                        let _e155 = phi_219_;
                        let _e157 = phi_220_;
                        phi_222_ = 0u;
                        phi_225_ = _e155;
                        phi_227_ = _e157;
                        loop {
                            let _e159 = phi_222_;
                            let _e161 = phi_225_;
                            let _e163 = phi_227_;
                            local_10 = _e159;
                            local_11 = _e161;
                            local_12 = _e163;
                            let _e164 = local_10;
                            let _e165 = local_40;
                            let _e166 = (_e164 < _e165);
                            local_13 = _e166;
                            if _e166 {
                                let _e167 = local_8;
                                let _e168 = local_9;
                                let _e170 = local_10;
                                let _e172 = (5u * ((_e167 * _e168) + _e170));
                                local_14 = _e172;
                                let _e173 = local_1;
                                if (_e172 < _e173) {
                                } else {
                                    phi_606_ = true;
                                    break;
                                }
                                let _e175 = local_14;
                                let _e178 = global_4.member[_e175];
                                local_15 = bitcast<f32>(_e178);
                                let _e180 = local_14;
                                let _e181 = (_e180 + 1u);
                                local_16 = _e181;
                                let _e182 = local_1;
                                if (_e181 < _e182) {
                                } else {
                                    phi_606_ = true;
                                    break;
                                }
                                let _e184 = local_16;
                                let _e187 = global_4.member[_e184];
                                local_17 = bitcast<f32>(_e187);
                                let _e189 = local_14;
                                let _e190 = (_e189 + 2u);
                                local_18 = _e190;
                                let _e191 = local_1;
                                if (_e190 < _e191) {
                                } else {
                                    phi_606_ = true;
                                    break;
                                }
                                let _e193 = local_18;
                                let _e196 = global_4.member[_e193];
                                local_19 = bitcast<f32>(_e196);
                                let _e198 = local_14;
                                let _e199 = (_e198 + 3u);
                                local_20 = _e199;
                                let _e200 = local_1;
                                if (_e199 < _e200) {
                                } else {
                                    phi_606_ = true;
                                    break;
                                }
                                let _e202 = local_20;
                                let _e205 = global_4.member[_e202];
                                local_21 = bitcast<f32>(_e205);
                                let _e207 = local_14;
                                let _e208 = (_e207 + 4u);
                                local_22 = _e208;
                                let _e209 = local_1;
                                if (_e208 < _e209) {
                                } else {
                                    phi_606_ = true;
                                    break;
                                }
                                let _e211 = local_22;
                                let _e214 = global_4.member[_e211];
                                local_23 = bitcast<f32>(_e214);
                                let _e216 = local_15;
                                if ((bitcast<u32>(_e216) & 2139095040u) != 2139095040u) {
                                    let _e220 = local_17;
                                    if ((bitcast<u32>(_e220) & 2139095040u) != 2139095040u) {
                                        let _e224 = local_19;
                                        let _e227 = ((bitcast<u32>(_e224) & 2139095040u) != 2139095040u);
                                        local_24 = _e227;
                                        if _e227 {
                                            let _e228 = local_21;
                                            let _e229 = bitcast<u32>(_e228);
                                            local_25 = _e229;
                                            if (_e229 == 0u) {
                                                phi_348_ = false;
                                            } else {
                                                let _e231 = local_25;
                                                phi_348_ = (_e231 <= 2139095040u);
                                            }
                                            let _e234 = phi_348_;
                                            phi_349_ = _e234;
                                        } else {
                                            phi_349_ = bool();
                                        }
                                        let _e236 = phi_349_;
                                        let _e237 = local_24;
                                        phi_351_ = _e236;
                                        phi_352_ = select(true, false, _e237);
                                    } else {
                                        phi_351_ = bool();
                                        phi_352_ = true;
                                    }
                                    let _e240 = phi_351_;
                                    let _e242 = phi_352_;
                                    phi_353_ = _e240;
                                    phi_354_ = _e242;
                                } else {
                                    phi_353_ = bool();
                                    phi_354_ = true;
                                }
                                let _e244 = phi_353_;
                                let _e246 = phi_354_;
                                if select(_e244, false, _e246) {
                                    let _e248 = local_21;
                                    let _e249 = bitcast<u32>(_e248);
                                    local_26 = _e249;
                                    if (_e249 == 0u) {
                                        phi_369_ = false;
                                    } else {
                                        let _e251 = local_26;
                                        phi_369_ = (_e251 <= 2139095040u);
                                    }
                                    let _e254 = phi_369_;
                                    if _e254 {
                                        let _e258 = global_5.member.member_8.member_1;
                                        let _e263 = global_5.member.member_8.member;
                                        let _e268 = global_5.member.member_8.member_2;
                                        local_27 = _e268;
                                        let _e274 = global_5.member.member_8.member_3;
                                        let _e275 = ((((2f * _e258) * _e263) / (_e268 - _e263)) * _e274);
                                        local_28 = _e275;
                                        if (_e275 == 0f) {
                                            phi_397_ = 0f;
                                        } else {
                                            let _e277 = local_27;
                                            let _e278 = local_21;
                                            let _e281 = local_28;
                                            phi_397_ = (_e281 * (1f - (_e277 / _e278)));
                                        }
                                        let _e284 = phi_397_;
                                        phi_398_ = _e284;
                                    } else {
                                        phi_398_ = bitcast<f32>(_e80);
                                    }
                                    let _e286 = phi_398_;
                                    let _e287 = (0.5f * _e286);
                                    local_29 = _e287;
                                    let _e290 = ((bitcast<u32>(_e287) & 2139095040u) != 2139095040u);
                                    local_30 = _e290;
                                    if _e290 {
                                        let _e291 = local_15;
                                        if (_e291 > 1267650600000000000000000000000f) {
                                            let _e293 = local_15;
                                            phi_415_ = select(true, false, (_e293 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_415_ = true;
                                        }
                                        let _e297 = phi_415_;
                                        if _e297 {
                                            let _e298 = local_15;
                                            if (_e298 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e300 = local_15;
                                                phi_429_ = select(true, false, (_e300 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_429_ = true;
                                            }
                                            let _e304 = phi_429_;
                                            let _e305 = local_15;
                                            phi_434_ = select(0f, _e305, _e304);
                                        } else {
                                            phi_434_ = 1267650600000000000000000000000f;
                                        }
                                        let _e308 = phi_434_;
                                        local_31 = _e308;
                                        let _e309 = local_17;
                                        if (_e309 > 1267650600000000000000000000000f) {
                                            let _e311 = local_17;
                                            phi_444_ = select(true, false, (_e311 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_444_ = true;
                                        }
                                        let _e315 = phi_444_;
                                        if _e315 {
                                            let _e316 = local_17;
                                            if (_e316 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e318 = local_17;
                                                phi_458_ = select(true, false, (_e318 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_458_ = true;
                                            }
                                            let _e322 = phi_458_;
                                            let _e323 = local_17;
                                            phi_463_ = select(0f, _e323, _e322);
                                        } else {
                                            phi_463_ = 1267650600000000000000000000000f;
                                        }
                                        let _e326 = phi_463_;
                                        local_32 = _e326;
                                        let _e327 = local_19;
                                        if (_e327 > 1267650600000000000000000000000f) {
                                            let _e329 = local_19;
                                            phi_473_ = select(true, false, (_e329 <= 340282350000000000000000000000000000000f));
                                        } else {
                                            phi_473_ = true;
                                        }
                                        let _e333 = phi_473_;
                                        if _e333 {
                                            let _e334 = local_19;
                                            if (_e334 < 0.000000000000000000000000000000000000011754944f) {
                                                let _e336 = local_19;
                                                phi_487_ = select(true, false, (_e336 >= -340282350000000000000000000000000000000f));
                                            } else {
                                                phi_487_ = true;
                                            }
                                            let _e340 = phi_487_;
                                            let _e341 = local_19;
                                            phi_492_ = select(0f, _e341, _e340);
                                        } else {
                                            phi_492_ = 1267650600000000000000000000000f;
                                        }
                                        let _e344 = phi_492_;
                                        let _e345 = local_31;
                                        let _e346 = local_32;
                                        local_33 = array<f32, 3>(_e345, _e346, _e344);
                                        let _e348 = local_23;
                                        if (_e348 > 1f) {
                                            phi_503_ = 1f;
                                        } else {
                                            let _e350 = local_23;
                                            let _e352 = local_23;
                                            phi_503_ = select(0f, _e352, (_e350 >= 0f));
                                        }
                                        let _e355 = phi_503_;
                                        let _e356 = local_33;
                                        let _e357 = local_29;
                                        phi_506_ = type_21(1u, type_16(_e356, _e357, _e355));
                                    } else {
                                        phi_506_ = type_21();
                                    }
                                    let _e361 = phi_506_;
                                    let _e362 = local_30;
                                    phi_508_ = _e361;
                                    phi_509_ = select(true, false, _e362);
                                } else {
                                    phi_508_ = type_21();
                                    phi_509_ = true;
                                }
                                let _e365 = phi_508_;
                                let _e367 = phi_509_;
                                if _e367 {
                                    phi_514_ = type_21(0u, type_21().member_1);
                                } else {
                                    phi_514_ = _e365;
                                }
                                let _e372 = phi_514_;
                                local_34 = _e372;
                                if (bitcast<i32>(_e372.member) != 0i) {
                                    let _e376 = local_34;
                                    local_35 = _e376.member_1.member_1;
                                    let _e379 = local_12;
                                    let _e380 = local_12;
                                    if !((_e379 == _e380)) {
                                        phi_580_ = true;
                                    } else {
                                        let _e383 = local_35;
                                        let _e384 = local_12;
                                        phi_580_ = (_e383 <= _e384);
                                    }
                                    let _e387 = phi_580_;
                                    let _e388 = local_35;
                                    let _e389 = local_12;
                                    let _e391 = local_11;
                                    let _e392 = local_11;
                                    if !((_e391 == _e392)) {
                                        phi_595_ = true;
                                    } else {
                                        let _e395 = local_35;
                                        let _e396 = local_11;
                                        phi_595_ = (_e395 >= _e396);
                                    }
                                    let _e399 = phi_595_;
                                    let _e400 = local_35;
                                    let _e401 = local_11;
                                    phi_524_ = select(_e401, _e400, _e399);
                                    phi_525_ = select(_e389, _e388, _e387);
                                } else {
                                    phi_524_ = _e161;
                                    phi_525_ = _e163;
                                }
                                let _e404 = phi_524_;
                                let _e406 = phi_525_;
                                let _e407 = local_10;
                                phi_223_ = (_e407 + 1u);
                                phi_226_ = _e404;
                                phi_228_ = _e406;
                            } else {
                                phi_223_ = u32();
                                phi_226_ = f32();
                                phi_228_ = f32();
                            }
                            let _e410 = phi_223_;
                            let _e412 = phi_226_;
                            let _e414 = phi_228_;
                            continue;
                            continuing {
                                let _e415 = local_13;
                                phi_222_ = _e410;
                                phi_225_ = _e412;
                                phi_227_ = _e414;
                                phi_606_ = _e108;
                                break if !(_e415);
                            }
                        }
                        let _e418 = phi_606_;
                        phi_648_ = _e418;
                        if _e418 {
                            break;
                        }
                        let _e419 = local_8;
                        let _e420 = (2u * _e419);
                        local_36 = _e420;
                        let _e421 = local_12;
                        local_37 = bitcast<u32>(_e421);
                        let _e423 = local_3;
                        if (_e420 < _e423) {
                        } else {
                            phi_648_ = true;
                            break;
                        }
                        let _e425 = local_36;
                        let _e428 = local_37;
                        global_6.member[_e425] = _e428;
                        let _e429 = local_36;
                        let _e430 = (_e429 + 1u);
                        local_38 = _e430;
                        let _e431 = local_11;
                        local_39 = bitcast<u32>(_e431);
                        let _e433 = local_3;
                        if (_e430 < _e433) {
                        } else {
                            phi_648_ = true;
                            break;
                        }
                        let _e435 = local_38;
                        let _e438 = local_39;
                        global_6.member[_e435] = _e438;
                        phi_650_ = _e418;
                    } else {
                        phi_650_ = _e108;
                    }
                    let _e440 = phi_650_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e441 = local_6;
                    let _e442 = local_5;
                    phi_649_ = _e440;
                    phi_145_ = (_e441 + _e442);
                } else {
                    phi_649_ = _e108;
                    phi_145_ = u32();
                }
                let _e445 = phi_649_;
                let _e447 = phi_145_;
                continue;
                continuing {
                    let _e448 = local_7;
                    phi_646_ = _e445;
                    phi_144_ = _e447;
                    phi_648_ = _e445;
                    break if !(_e448);
                }
            }
            let _e451 = phi_648_;
            if _e451 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn raytrace_base(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
