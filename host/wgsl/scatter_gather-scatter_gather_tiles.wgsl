struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_6 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: type_5,
}

struct type_7 {
    member: type_6,
}

struct type_10 {
    member: array<u32>,
}

struct type_24 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<immediate> global_2: type_7;
@group(0) @binding(1) 
var<storage> global_3: type_10;
@group(0) @binding(0) 
var<storage> global_4: type_10;
@group(0) @binding(3) 
var<storage, read_write> global_5: type_10;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_10;
@group(0) @binding(4) 
var<storage, read_write> global_7: type_24;
var<workgroup> global_8: array<u32, 512>;
var<private> global_9: u32 = 2143289344u;

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
    var local_13: f32;
    var local_14: u32;
    var local_15: f32;
    var local_16: u32;
    var local_17: f32;
    var local_18: bool;
    var local_19: u32;
    var local_20: f32;
    var local_21: u32;
    var local_22: bool;
    var local_23: bool;
    var local_24: f32;
    var local_25: f32;
    var local_26: f32;
    var local_27: u32;
    var local_28: bool;
    var local_29: u32;
    var local_30: u32;
    var local_31: bool;
    var local_32: u32;
    var local_33: bool;
    var local_34: u32;
    var local_35: bool;
    var local_36: u32;
    var local_37: bool;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: bool;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: f32;
    var local_51: f32;
    var phi_170_: bool;
    var phi_205_: bool;
    var phi_233_: f32;
    var phi_234_: f32;
    var phi_236_: f32;
    var phi_248_: f32;
    var phi_250_: f32;
    var phi_251_: bool;
    var phi_252_: f32;
    var phi_253_: bool;
    var phi_254_: f32;
    var phi_255_: bool;
    var phi_278_: f32;
    var phi_288_: u32;
    var phi_289_: u32;
    var phi_290_: u32;
    var phi_291_: u32;
    var phi_292_: u32;
    var phi_307_: u32;
    var phi_353_: u32;
    var phi_396_: u32;
    var phi_308_: u32;
    var phi_462_: bool;
    var phi_426_: u32;

    let _e84 = global_9;
    let _e85 = bitcast<f32>(_e84);
    local_51 = _e85;
    switch bitcast<i32>(0u) {
        default: {
            let _e87 = global;
            local = _e87;
            let _e88 = global_1;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_5.member));
            local_5 = arrayLength((&global_7.member));
            local_6 = _e88.x;
            local_7 = _e88.y;
            let _e103 = ((_e88.x * 16u) + (_e87 % 16u));
            local_8 = _e103;
            local_9 = ((_e88.y * 16u) + (_e87 / 16u));
            let _e109 = global_2.member.member;
            local_10 = _e109;
            if (_e103 < _e109) {
                let _e113 = global_2.member.member_1;
                let _e114 = local_9;
                if (_e114 < _e113) {
                    let _e116 = local_9;
                    let _e117 = local_10;
                    let _e119 = local_8;
                    let _e120 = ((_e116 * _e117) + _e119);
                    local_11 = _e120;
                    let _e121 = (3u * _e120);
                    local_12 = _e121;
                    let _e122 = local_1;
                    if (_e121 < _e122) {
                    } else {
                        break;
                    }
                    let _e124 = local_12;
                    let _e127 = global_4.member[_e124];
                    local_13 = bitcast<f32>(_e127);
                    let _e129 = local_12;
                    let _e130 = (_e129 + 1u);
                    local_14 = _e130;
                    let _e131 = local_1;
                    if (_e130 < _e131) {
                    } else {
                        break;
                    }
                    let _e133 = local_14;
                    let _e136 = global_4.member[_e133];
                    local_15 = bitcast<f32>(_e136);
                    let _e138 = local_12;
                    let _e139 = (_e138 + 2u);
                    local_16 = _e139;
                    let _e140 = local_1;
                    if (_e139 < _e140) {
                    } else {
                        break;
                    }
                    let _e142 = local_16;
                    let _e145 = global_4.member[_e142];
                    local_17 = bitcast<f32>(_e145);
                    let _e147 = local_11;
                    let _e148 = local_2;
                    let _e149 = (_e147 < _e148);
                    local_18 = _e149;
                    if _e149 {
                    } else {
                        break;
                    }
                    let _e150 = local_11;
                    let _e153 = global_3.member[_e150];
                    local_19 = _e153;
                    local_20 = bitcast<f32>(_e153);
                    let _e155 = local_13;
                    if ((bitcast<u32>(_e155) & 2139095040u) != 2139095040u) {
                        let _e159 = local_15;
                        if ((bitcast<u32>(_e159) & 2139095040u) != 2139095040u) {
                            let _e163 = local_17;
                            if ((bitcast<u32>(_e163) & 2139095040u) != 2139095040u) {
                                let _e167 = local_20;
                                let _e168 = bitcast<u32>(_e167);
                                local_21 = _e168;
                                let _e169 = (_e168 == 0u);
                                local_22 = _e169;
                                if _e169 {
                                    phi_170_ = false;
                                } else {
                                    let _e170 = local_21;
                                    phi_170_ = (_e170 <= 2139095040u);
                                }
                                let _e173 = phi_170_;
                                local_23 = _e173;
                                if _e173 {
                                    let _e176 = global_2.member.member_3;
                                    local_24 = f32(_e176);
                                    let _e178 = local_21;
                                    if (_e178 == 2139095040u) {
                                        let _e221 = global_2.member.member_4.member_1;
                                        let _e226 = global_2.member.member_4.member;
                                        let _e231 = global_2.member.member_4.member_2;
                                        let _e237 = global_2.member.member_4.member_3;
                                        phi_236_ = (0.5f * ((((2f * _e221) * _e226) / (_e231 - _e226)) * _e237));
                                    } else {
                                        let _e180 = local_22;
                                        if _e180 {
                                            phi_205_ = false;
                                        } else {
                                            let _e181 = local_21;
                                            phi_205_ = (_e181 <= 2139095040u);
                                        }
                                        let _e184 = phi_205_;
                                        if _e184 {
                                            let _e188 = global_2.member.member_4.member_1;
                                            let _e193 = global_2.member.member_4.member;
                                            let _e198 = global_2.member.member_4.member_2;
                                            local_25 = _e198;
                                            let _e204 = global_2.member.member_4.member_3;
                                            let _e205 = ((((2f * _e188) * _e193) / (_e198 - _e193)) * _e204);
                                            local_26 = _e205;
                                            if (_e205 == 0f) {
                                                phi_233_ = 0f;
                                            } else {
                                                let _e207 = local_25;
                                                let _e208 = local_20;
                                                let _e211 = local_26;
                                                phi_233_ = (_e211 * (1f - (_e207 / _e208)));
                                            }
                                            let _e214 = phi_233_;
                                            phi_234_ = _e214;
                                        } else {
                                            phi_234_ = _e85;
                                        }
                                        let _e216 = phi_234_;
                                        phi_236_ = (0.5f * _e216);
                                    }
                                    let _e241 = phi_236_;
                                    let _e242 = local_24;
                                    let _e244 = local_24;
                                    let _e245 = select(_e244, _e241, (_e241 < _e242));
                                    let _e246 = local_24;
                                    let _e247 = -(_e246);
                                    phi_248_ = select(_e247, _e245, (_e245 > _e247));
                                } else {
                                    phi_248_ = f32();
                                }
                                let _e251 = phi_248_;
                                let _e252 = local_23;
                                phi_250_ = _e251;
                                phi_251_ = select(true, false, _e252);
                            } else {
                                phi_250_ = f32();
                                phi_251_ = true;
                            }
                            let _e255 = phi_250_;
                            let _e257 = phi_251_;
                            phi_252_ = _e255;
                            phi_253_ = _e257;
                        } else {
                            phi_252_ = f32();
                            phi_253_ = true;
                        }
                        let _e259 = phi_252_;
                        let _e261 = phi_253_;
                        phi_254_ = _e259;
                        phi_255_ = _e261;
                    } else {
                        phi_254_ = f32();
                        phi_255_ = true;
                    }
                    let _e263 = phi_254_;
                    let _e265 = phi_255_;
                    let _e266 = local_51;
                    let _e267 = select(_e263, _e266, _e265);
                    local_50 = _e267;
                    local_27 = bitcast<u32>(_e267);
                    let _e269 = local_11;
                    let _e270 = local_3;
                    if (_e269 < _e270) {
                    } else {
                        break;
                    }
                    let _e272 = local_11;
                    let _e275 = local_27;
                    global_6.member[_e272] = _e275;
                    let _e276 = local_27;
                    let _e278 = ((_e276 & 2147483647u) > 2139095040u);
                    local_28 = _e278;
                    if _e278 {
                        phi_288_ = 0u;
                    } else {
                        let _e279 = local_50;
                        if (_e279 < 0f) {
                            let _e281 = local_50;
                            phi_278_ = -(_e281);
                        } else {
                            phi_278_ = _e267;
                        }
                        let _e284 = phi_278_;
                        let _e286 = local_18;
                        if _e286 {
                        } else {
                            break;
                        }
                        phi_288_ = bitcast<u32>(_e284);
                    }
                    let _e288 = phi_288_;
                    let _e289 = local_28;
                    let _e290 = local_19;
                    phi_289_ = select(_e290, 2139095040u, _e289);
                    phi_290_ = _e288;
                } else {
                    phi_289_ = 2139095040u;
                    phi_290_ = 0u;
                }
                let _e293 = phi_289_;
                let _e295 = phi_290_;
                phi_291_ = _e293;
                phi_292_ = _e295;
            } else {
                phi_291_ = 2139095040u;
                phi_292_ = 0u;
            }
            let _e297 = phi_291_;
            let _e299 = phi_292_;
            local_29 = _e297;
            local_30 = _e299;
            let _e300 = local;
            let _e301 = (_e300 < 512u);
            local_31 = _e301;
            if _e301 {
            } else {
                break;
            }
            let _e302 = local;
            let _e304 = local_30;
            global_8[_e302] = _e304;
            let _e305 = local;
            let _e306 = (256u + _e305);
            local_32 = _e306;
            let _e307 = (_e306 < 512u);
            local_33 = _e307;
            if _e307 {
            } else {
                break;
            }
            let _e308 = local_32;
            let _e310 = local_29;
            global_8[_e308] = _e310;
            storageBarrier();
            workgroupBarrier();
            phi_307_ = 128u;
            loop {
                let _e312 = phi_307_;
                local_34 = _e312;
                let _e313 = local_34;
                let _e314 = (_e313 > 0u);
                local_35 = _e314;
                if _e314 {
                    let _e315 = local;
                    let _e316 = local_34;
                    if (_e315 < _e316) {
                        let _e318 = local;
                        let _e319 = local_34;
                        let _e320 = (_e318 + _e319);
                        local_36 = _e320;
                        let _e321 = (_e320 < 512u);
                        local_37 = _e321;
                        if _e321 {
                        } else {
                            phi_462_ = true;
                            break;
                        }
                        let _e322 = local_36;
                        let _e324 = global_8[_e322];
                        local_38 = _e324;
                        let _e325 = local_31;
                        if _e325 {
                        } else {
                            phi_462_ = true;
                            break;
                        }
                        let _e326 = global_8[_e302];
                        let _e327 = local_38;
                        if (_e327 > _e326) {
                            let _e331 = local_37;
                            if _e331 {
                            } else {
                                phi_462_ = true;
                                break;
                            }
                            let _e332 = global_8[_e322];
                            phi_353_ = _e332;
                        } else {
                            let _e329 = local_31;
                            if _e329 {
                            } else {
                                phi_462_ = true;
                                break;
                            }
                            let _e330 = global_8[_e302];
                            phi_353_ = _e330;
                        }
                        let _e334 = phi_353_;
                        local_39 = _e334;
                        let _e335 = local_31;
                        if _e335 {
                        } else {
                            phi_462_ = true;
                            break;
                        }
                        let _e336 = local_39;
                        global_8[_e302] = _e336;
                        let _e337 = local_36;
                        let _e338 = (256u + _e337);
                        local_40 = _e338;
                        let _e339 = (_e338 < 512u);
                        local_41 = _e339;
                        if _e339 {
                        } else {
                            phi_462_ = true;
                            break;
                        }
                        let _e340 = local_40;
                        let _e342 = global_8[_e340];
                        local_42 = _e342;
                        let _e343 = local_33;
                        if _e343 {
                        } else {
                            phi_462_ = true;
                            break;
                        }
                        let _e344 = global_8[_e308];
                        let _e345 = local_42;
                        if (_e345 < _e344) {
                            let _e349 = local_41;
                            if _e349 {
                            } else {
                                phi_462_ = true;
                                break;
                            }
                            let _e350 = global_8[_e340];
                            phi_396_ = _e350;
                        } else {
                            let _e347 = local_33;
                            if _e347 {
                            } else {
                                phi_462_ = true;
                                break;
                            }
                            let _e348 = global_8[_e308];
                            phi_396_ = _e348;
                        }
                        let _e352 = phi_396_;
                        local_43 = _e352;
                        let _e353 = local_33;
                        if _e353 {
                        } else {
                            phi_462_ = true;
                            break;
                        }
                        let _e354 = local_43;
                        global_8[_e308] = _e354;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e355 = local_34;
                    phi_308_ = (_e355 / 2u);
                } else {
                    phi_308_ = u32();
                }
                let _e358 = phi_308_;
                continue;
                continuing {
                    let _e359 = local_35;
                    phi_307_ = _e358;
                    phi_462_ = false;
                    break if !(_e359);
                }
            }
            let _e362 = phi_462_;
            if _e362 {
                break;
            }
            let _e363 = local;
            if (_e363 == 0u) {
                let _e365 = local_10;
                let _e366 = (_e365 / 16u);
                local_44 = _e366;
                let _e367 = local_10;
                if ((_e367 % 16u) > 0u) {
                    let _e370 = local_44;
                    phi_426_ = (_e370 + 1u);
                } else {
                    phi_426_ = _e366;
                }
                let _e373 = phi_426_;
                let _e374 = local_7;
                let _e376 = local_6;
                let _e378 = (2u * ((_e374 * _e373) + _e376));
                local_45 = _e378;
                let _e380 = global_8[0u];
                local_46 = _e380;
                let _e381 = local_4;
                if (_e378 < _e381) {
                } else {
                    break;
                }
                let _e383 = local_45;
                let _e386 = local_46;
                global_5.member[_e383] = _e386;
                let _e387 = local_45;
                let _e388 = (_e387 + 1u);
                local_47 = _e388;
                let _e390 = global_8[256u];
                local_48 = _e390;
                let _e391 = local_4;
                if (_e388 < _e391) {
                } else {
                    break;
                }
                let _e393 = local_47;
                let _e396 = local_48;
                global_5.member[_e393] = _e396;
                let _e397 = global_8[0u];
                local_49 = _e397;
                let _e398 = local_5;
                if (1u < _e398) {
                } else {
                    break;
                }
                let _e402 = local_49;
                let _e403 = atomicMax((&global_7.member[1u]), _e402);
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn scatter_gather_tiles(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
