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

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_15;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_7;
@group(0) @binding(4) 
var<storage, read_write> global_8: type_7;

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
    var local_9: i32;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: bool;
    var local_14: u32;
    var local_15: bool;
    var local_16: u32;
    var local_17: i32;
    var local_18: bool;
    var local_19: i32;
    var local_20: u32;
    var local_21: u32;
    var local_22: bool;
    var local_23: u32;
    var local_24: bool;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: bool;
    var local_30: bool;
    var local_31: bool;
    var local_32: u32;
    var local_33: u32;
    var local_34: bool;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: bool;
    var local_41: i32;
    var local_42: u32;
    var phi_527_: bool;
    var phi_117_: u32;
    var phi_170_: bool;
    var phi_173_: i32;
    var phi_212_: bool;
    var phi_214_: bool;
    var phi_215_: i32;
    var phi_171_: bool;
    var phi_174_: i32;
    var phi_217_: bool;
    var phi_521_: bool;
    var phi_262_: u32;
    var phi_361_: u32;
    var phi_263_: u32;
    var phi_363_: bool;
    var phi_364_: bool;
    var phi_529_: bool;
    var phi_512_: bool;
    var phi_369_: u32;
    var phi_538_: bool;
    var phi_394_: u32;
    var phi_537_: bool;
    var phi_395_: u32;
    var phi_536_: bool;
    var phi_396_: u32;
    var phi_398_: u32;
    var phi_399_: u32;
    var phi_533_: bool;
    var phi_544_: bool;
    var phi_543_: bool;
    var phi_118_: u32;
    var phi_542_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e72 = global;
            local = _e72;
            let _e73 = global_1;
            let _e74 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = arrayLength((&global_7.member));
            local_4 = arrayLength((&global_8.member));
            local_5 = _e73.x;
            local_6 = _e74.x;
            let _e89 = global_3.member.member_1;
            local_7 = _e89;
            let _e92 = global_3.member.member_2;
            local_8 = _e92;
            if (0u < arrayLength((&global_5.member))) {
            } else {
                break;
            }
            let _e96 = global_5.member[0u];
            local_9 = (bitcast<i32>(_e96) - 1i);
            let _e99 = local_7;
            let _e100 = local_8;
            local_10 = (_e99 * _e100);
            let _e102 = local_6;
            local_11 = (_e102 * 256u);
            let _e104 = local_5;
            phi_527_ = false;
            phi_117_ = (_e104 * 256u);
            loop {
                let _e107 = phi_527_;
                let _e109 = phi_117_;
                local_12 = _e109;
                let _e110 = local_12;
                let _e111 = local_10;
                let _e112 = (_e110 < _e111);
                local_13 = _e112;
                if _e112 {
                    let _e113 = local_12;
                    let _e114 = local;
                    let _e115 = (_e113 + _e114);
                    local_14 = _e115;
                    let _e116 = local_10;
                    if (_e115 < _e116) {
                        let _e118 = local_7;
                        let _e119 = (_e118 == 0u);
                        local_15 = _e119;
                        if _e119 {
                            phi_542_ = true;
                            break;
                        }
                        let _e120 = local_14;
                        let _e121 = local_7;
                        local_16 = (_e120 % _e121);
                        let _e123 = local_15;
                        if _e123 {
                            phi_542_ = true;
                            break;
                        }
                        let _e124 = local_14;
                        let _e125 = local_7;
                        let _e127 = bitcast<i32>((_e124 / _e125));
                        local_17 = _e127;
                        let _e128 = local_9;
                        let _e129 = (_e127 - _e128);
                        let _e132 = local_9;
                        let _e133 = (_e127 + _e132);
                        let _e134 = local_8;
                        let _e136 = (bitcast<i32>(_e134) - 1i);
                        local_41 = select(_e136, _e133, (_e133 < _e136));
                        phi_170_ = false;
                        phi_173_ = select(0i, _e129, (_e129 > 0i));
                        loop {
                            let _e140 = phi_170_;
                            let _e142 = phi_173_;
                            local_18 = _e140;
                            local_19 = _e142;
                            let _e143 = local_19;
                            let _e144 = local_41;
                            if (_e143 <= _e144) {
                                let _e146 = local_18;
                                if _e146 {
                                    phi_214_ = bool();
                                    phi_215_ = i32();
                                } else {
                                    let _e147 = local_19;
                                    let _e149 = local_7;
                                    let _e151 = local_16;
                                    let _e152 = ((bitcast<u32>(_e147) * _e149) + _e151);
                                    local_20 = _e152;
                                    let _e153 = local_1;
                                    if (_e152 < _e153) {
                                    } else {
                                        phi_521_ = true;
                                        break;
                                    }
                                    let _e155 = local_20;
                                    let _e158 = global_4.member[_e155];
                                    local_21 = _e158;
                                    if (_e158 > 0u) {
                                        let _e160 = local_21;
                                        let _e163 = local_19;
                                        let _e164 = local_17;
                                        let _e165 = (_e163 - _e164);
                                        phi_212_ = ((bitcast<i32>(_e160) - 1i) >= (_e165 * _e165));
                                    } else {
                                        phi_212_ = false;
                                    }
                                    let _e169 = phi_212_;
                                    let _e170 = local_19;
                                    phi_214_ = _e169;
                                    phi_215_ = (_e170 + 1i);
                                }
                                let _e173 = phi_214_;
                                let _e175 = phi_215_;
                                let _e176 = local_18;
                                phi_171_ = _e173;
                                phi_174_ = _e175;
                                phi_217_ = select(true, false, _e176);
                            } else {
                                phi_171_ = bool();
                                phi_174_ = i32();
                                phi_217_ = false;
                            }
                            let _e179 = phi_171_;
                            let _e181 = phi_174_;
                            let _e183 = phi_217_;
                            local_22 = _e183;
                            continue;
                            continuing {
                                let _e184 = local_22;
                                phi_170_ = _e179;
                                phi_173_ = _e181;
                                phi_521_ = _e107;
                                break if !(_e184);
                            }
                        }
                        let _e187 = phi_521_;
                        phi_542_ = _e187;
                        if _e187 {
                            break;
                        }
                        let _e188 = local_18;
                        local_23 = select(0u, 1u, _e188);
                        let _e190 = local_14;
                        let _e191 = local_2;
                        if (_e190 < _e191) {
                        } else {
                            phi_542_ = true;
                            break;
                        }
                        let _e193 = local_14;
                        let _e196 = local_23;
                        global_6.member[_e193] = _e196;
                        let _e197 = local_14;
                        let _e198 = local_4;
                        let _e199 = (_e197 < _e198);
                        local_24 = _e199;
                        if _e199 {
                        } else {
                            phi_542_ = true;
                            break;
                        }
                        let _e200 = local_14;
                        let _e203 = global_8.member[_e200];
                        local_25 = _e203;
                        let _e206 = global_3.member.member_6;
                        if (_e206 == 0u) {
                            phi_536_ = _e187;
                            phi_396_ = _e203;
                        } else {
                            let _e208 = local_18;
                            if _e208 {
                                phi_537_ = _e187;
                                phi_395_ = _e203;
                            } else {
                                let _e209 = local_25;
                                if (_e209 > 1u) {
                                    phi_262_ = 0u;
                                    loop {
                                        let _e212 = phi_262_;
                                        local_26 = _e212;
                                        let _e213 = local_26;
                                        let _e214 = local_25;
                                        if (_e213 < _e214) {
                                            let _e218 = global_3.member.member_3;
                                            let _e219 = local_14;
                                            let _e221 = local_26;
                                            let _e223 = (5u * ((_e219 * _e218) + _e221));
                                            local_27 = _e223;
                                            let _e224 = local_3;
                                            if (_e223 < _e224) {
                                            } else {
                                                phi_529_ = true;
                                                phi_512_ = bool();
                                                break;
                                            }
                                            let _e226 = local_27;
                                            let _e228 = local_3;
                                            if ((_e226 + 1u) < _e228) {
                                            } else {
                                                phi_529_ = true;
                                                phi_512_ = bool();
                                                break;
                                            }
                                            let _e230 = local_27;
                                            let _e232 = local_3;
                                            if ((_e230 + 2u) < _e232) {
                                            } else {
                                                phi_529_ = true;
                                                phi_512_ = bool();
                                                break;
                                            }
                                            let _e234 = local_27;
                                            let _e236 = local_3;
                                            if ((_e234 + 3u) < _e236) {
                                            } else {
                                                phi_529_ = true;
                                                phi_512_ = bool();
                                                break;
                                            }
                                            let _e238 = local_27;
                                            let _e239 = (_e238 + 4u);
                                            local_28 = _e239;
                                            let _e240 = local_3;
                                            if (_e239 < _e240) {
                                            } else {
                                                phi_529_ = true;
                                                phi_512_ = bool();
                                                break;
                                            }
                                            let _e242 = local_28;
                                            let _e245 = global_7.member[_e242];
                                            let _e247 = (bitcast<f32>(_e245) >= 1f);
                                            local_29 = _e247;
                                            if _e247 {
                                                phi_361_ = u32();
                                            } else {
                                                let _e248 = local_26;
                                                phi_361_ = (_e248 + 1u);
                                            }
                                            let _e251 = phi_361_;
                                            let _e252 = local_29;
                                            phi_263_ = _e251;
                                            phi_363_ = select(true, false, _e252);
                                            phi_364_ = _e247;
                                        } else {
                                            phi_263_ = u32();
                                            phi_363_ = false;
                                            phi_364_ = false;
                                        }
                                        let _e255 = phi_263_;
                                        let _e257 = phi_363_;
                                        let _e259 = phi_364_;
                                        local_30 = _e257;
                                        continue;
                                        continuing {
                                            let _e260 = local_30;
                                            phi_262_ = _e255;
                                            phi_529_ = _e187;
                                            phi_512_ = _e259;
                                            break if !(_e260);
                                        }
                                    }
                                    let _e263 = phi_529_;
                                    let _e265 = phi_512_;
                                    local_40 = _e265;
                                    phi_542_ = _e263;
                                    if _e263 {
                                        break;
                                    }
                                    let _e266 = local_40;
                                    if _e266 {
                                        let _e267 = local_26;
                                        phi_369_ = (_e267 + 1u);
                                    } else {
                                        phi_369_ = u32();
                                    }
                                    let _e270 = phi_369_;
                                    let _e271 = local_40;
                                    let _e273 = local_25;
                                    let _e274 = select(_e270, _e273, select(true, false, _e271));
                                    local_42 = _e274;
                                    let _e275 = local_25;
                                    let _e276 = (_e274 < _e275);
                                    local_31 = _e276;
                                    if _e276 {
                                        let _e277 = local_24;
                                        if _e277 {
                                        } else {
                                            phi_542_ = true;
                                            break;
                                        }
                                        let _e278 = local_42;
                                        global_8.member[_e200] = _e278;
                                    }
                                    let _e279 = local_31;
                                    let _e280 = local_42;
                                    let _e281 = local_25;
                                    phi_538_ = _e263;
                                    phi_394_ = select(_e281, _e280, _e279);
                                } else {
                                    phi_538_ = _e187;
                                    phi_394_ = _e203;
                                }
                                let _e284 = phi_538_;
                                let _e286 = phi_394_;
                                phi_537_ = _e284;
                                phi_395_ = _e286;
                            }
                            let _e288 = phi_537_;
                            let _e290 = phi_395_;
                            phi_536_ = _e288;
                            phi_396_ = _e290;
                        }
                        let _e292 = phi_536_;
                        let _e294 = phi_396_;
                        phi_398_ = _e294;
                        loop {
                            let _e296 = phi_398_;
                            local_32 = _e296;
                            let _e299 = global_3.member.member_3;
                            local_33 = _e299;
                            let _e300 = local_32;
                            let _e301 = (_e300 < _e299);
                            local_34 = _e301;
                            if _e301 {
                                let _e302 = local_14;
                                let _e303 = local_33;
                                let _e305 = local_32;
                                let _e307 = (5u * ((_e302 * _e303) + _e305));
                                local_35 = _e307;
                                let _e308 = local_3;
                                if (_e307 < _e308) {
                                } else {
                                    phi_533_ = true;
                                    break;
                                }
                                let _e310 = local_35;
                                global_7.member[_e310] = 0u;
                                let _e313 = local_35;
                                let _e314 = (_e313 + 1u);
                                local_36 = _e314;
                                let _e315 = local_3;
                                if (_e314 < _e315) {
                                } else {
                                    phi_533_ = true;
                                    break;
                                }
                                let _e317 = local_36;
                                global_7.member[_e317] = 0u;
                                let _e320 = local_35;
                                let _e321 = (_e320 + 2u);
                                local_37 = _e321;
                                let _e322 = local_3;
                                if (_e321 < _e322) {
                                } else {
                                    phi_533_ = true;
                                    break;
                                }
                                let _e324 = local_37;
                                global_7.member[_e324] = 0u;
                                let _e327 = local_35;
                                let _e328 = (_e327 + 3u);
                                local_38 = _e328;
                                let _e329 = local_3;
                                if (_e328 < _e329) {
                                } else {
                                    phi_533_ = true;
                                    break;
                                }
                                let _e331 = local_38;
                                global_7.member[_e331] = 2139095040u;
                                let _e334 = local_35;
                                let _e335 = (_e334 + 4u);
                                local_39 = _e335;
                                let _e336 = local_3;
                                if (_e335 < _e336) {
                                } else {
                                    phi_533_ = true;
                                    break;
                                }
                                let _e338 = local_39;
                                global_7.member[_e338] = 0u;
                                let _e341 = local_32;
                                phi_399_ = (_e341 + 1u);
                            } else {
                                phi_399_ = u32();
                            }
                            let _e344 = phi_399_;
                            continue;
                            continuing {
                                let _e345 = local_34;
                                phi_398_ = _e344;
                                phi_533_ = _e292;
                                break if !(_e345);
                            }
                        }
                        let _e348 = phi_533_;
                        phi_542_ = _e348;
                        if _e348 {
                            break;
                        }
                        phi_544_ = _e348;
                    } else {
                        phi_544_ = _e107;
                    }
                    let _e350 = phi_544_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e351 = local_12;
                    let _e352 = local_11;
                    phi_543_ = _e350;
                    phi_118_ = (_e351 + _e352);
                } else {
                    phi_543_ = _e107;
                    phi_118_ = u32();
                }
                let _e355 = phi_543_;
                let _e357 = phi_118_;
                continue;
                continuing {
                    let _e358 = local_13;
                    phi_527_ = _e355;
                    phi_117_ = _e357;
                    phi_542_ = _e355;
                    break if !(_e358);
                }
            }
            let _e361 = phi_542_;
            if _e361 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn peel_mask(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
