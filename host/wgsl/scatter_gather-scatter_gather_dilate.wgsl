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

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<immediate> global_2: type_7;
@group(0) @binding(0) 
var<storage> global_3: type_10;
@group(0) @binding(1) 
var<storage, read_write> global_4: type_10;

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
    var local_10: i32;
    var local_11: u32;
    var local_12: u32;
    var local_13: i32;
    var local_14: u32;
    var local_15: f32;
    var local_16: bool;
    var local_17: i32;
    var local_18: i32;
    var local_19: u32;
    var local_20: f32;
    var local_21: i32;
    var local_22: u32;
    var local_23: f32;
    var local_24: f32;
    var local_25: f32;
    var local_26: f32;
    var local_27: u32;
    var local_28: bool;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var phi_82_: u32;
    var phi_100_: u32;
    var phi_118_: u32;
    var phi_343_: bool;
    var phi_138_: i32;
    var phi_141_: u32;
    var phi_143_: f32;
    var phi_155_: i32;
    var phi_158_: u32;
    var phi_160_: f32;
    var phi_199_: f32;
    var phi_214_: f32;
    var phi_273_: u32;
    var phi_274_: u32;
    var phi_275_: f32;
    var phi_276_: u32;
    var phi_277_: f32;
    var phi_279_: i32;
    var phi_280_: u32;
    var phi_281_: f32;
    var phi_283_: i32;
    var phi_284_: u32;
    var phi_285_: f32;
    var phi_286_: bool;
    var phi_156_: i32;
    var phi_159_: u32;
    var phi_161_: f32;
    var phi_288_: bool;
    var phi_327_: bool;
    var phi_348_: bool;
    var phi_139_: i32;
    var phi_142_: u32;
    var phi_144_: f32;
    var phi_347_: bool;
    var local_32: u32;
    var local_33: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e57 = global;
            local = _e57;
            let _e58 = global_1;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = _e58.x;
            local_4 = _e58.y;
            let _e67 = global_2.member.member;
            let _e68 = (_e67 / 16u);
            local_5 = _e68;
            if ((_e67 % 16u) > 0u) {
                let _e71 = local_5;
                phi_82_ = (_e71 + 1u);
            } else {
                phi_82_ = _e68;
            }
            let _e74 = phi_82_;
            local_6 = _e74;
            let _e77 = global_2.member.member_1;
            let _e78 = (_e77 / 16u);
            local_7 = _e78;
            if ((_e77 % 16u) > 0u) {
                let _e81 = local_7;
                phi_100_ = (_e81 + 1u);
            } else {
                phi_100_ = _e78;
            }
            let _e84 = phi_100_;
            local_8 = _e84;
            let _e87 = global_2.member.member_3;
            let _e88 = (_e87 / 16u);
            local_9 = _e88;
            if ((_e87 % 16u) > 0u) {
                let _e91 = local_9;
                phi_118_ = (_e91 + 1u);
            } else {
                phi_118_ = _e88;
            }
            let _e94 = phi_118_;
            local_10 = bitcast<i32>((_e94 + 1u));
            let _e97 = local_3;
            let _e99 = local;
            let _e101 = ((_e97 * 8u) + (_e99 % 8u));
            local_11 = _e101;
            let _e102 = local_4;
            let _e104 = local;
            local_12 = ((_e102 * 8u) + (_e104 / 8u));
            let _e107 = local_6;
            if (_e101 >= _e107) {
            } else {
                let _e109 = local_12;
                let _e110 = local_8;
                if (_e109 >= _e110) {
                } else {
                    let _e112 = local_10;
                    let _e113 = -(_e112);
                    phi_343_ = false;
                    phi_138_ = _e113;
                    phi_141_ = 2139095040u;
                    phi_143_ = 0f;
                    loop {
                        let _e115 = phi_343_;
                        let _e117 = phi_138_;
                        let _e119 = phi_141_;
                        let _e121 = phi_143_;
                        local_13 = _e117;
                        local_14 = _e119;
                        local_15 = _e121;
                        let _e122 = local_13;
                        let _e123 = local_10;
                        let _e124 = (_e122 <= _e123);
                        local_16 = _e124;
                        if _e124 {
                            let _e125 = local_12;
                            let _e127 = local_13;
                            local_17 = (bitcast<i32>(_e125) + _e127);
                            phi_155_ = _e113;
                            phi_158_ = _e119;
                            phi_160_ = _e121;
                            loop {
                                let _e130 = phi_155_;
                                let _e132 = phi_158_;
                                let _e134 = phi_160_;
                                local_18 = _e130;
                                local_19 = _e132;
                                local_20 = _e134;
                                local_32 = _e132;
                                local_33 = _e134;
                                let _e135 = local_17;
                                if (_e135 >= 0i) {
                                    let _e137 = local_8;
                                    let _e139 = local_17;
                                    if (_e139 < bitcast<i32>(_e137)) {
                                        let _e141 = local_18;
                                        let _e142 = local_10;
                                        let _e143 = (_e141 <= _e142);
                                        if _e143 {
                                            let _e144 = local_11;
                                            let _e146 = local_18;
                                            let _e147 = (bitcast<i32>(_e144) + _e146);
                                            local_21 = _e147;
                                            if (_e147 >= 0i) {
                                                let _e149 = local_6;
                                                let _e151 = local_21;
                                                if (_e151 < bitcast<i32>(_e149)) {
                                                    let _e153 = local_17;
                                                    let _e155 = local_6;
                                                    let _e157 = local_21;
                                                    local_22 = (2u * ((bitcast<u32>(_e153) * _e155) + bitcast<u32>(_e157)));
                                                    let _e161 = local_18;
                                                    let _e162 = f32(_e161);
                                                    local_23 = _e162;
                                                    if (_e162 < 0f) {
                                                        let _e164 = local_23;
                                                        phi_199_ = -(_e164);
                                                    } else {
                                                        phi_199_ = _e162;
                                                    }
                                                    let _e167 = phi_199_;
                                                    let _e168 = (_e167 - 1f);
                                                    local_24 = (select(0f, _e168, (_e168 > 0f)) * 16f);
                                                    let _e172 = local_13;
                                                    let _e173 = f32(_e172);
                                                    local_25 = _e173;
                                                    if (_e173 < 0f) {
                                                        let _e175 = local_25;
                                                        phi_214_ = -(_e175);
                                                    } else {
                                                        phi_214_ = _e173;
                                                    }
                                                    let _e178 = phi_214_;
                                                    let _e179 = (_e178 - 1f);
                                                    let _e182 = (select(0f, _e179, (_e179 > 0f)) * 16f);
                                                    let _e183 = local_24;
                                                    let _e184 = local_24;
                                                    local_26 = sqrt(((_e183 * _e184) + (_e182 * _e182)));
                                                    let _e189 = local_22;
                                                    let _e190 = local_1;
                                                    if (_e189 < _e190) {
                                                    } else {
                                                        phi_327_ = true;
                                                        break;
                                                    }
                                                    let _e192 = local_22;
                                                    let _e195 = global_3.member[_e192];
                                                    let _e196 = bitcast<f32>(_e195);
                                                    let _e197 = local_26;
                                                    let _e200 = (((_e196 - _e197) * 0.0625f) + 1f);
                                                    let _e202 = select(0f, _e200, (_e200 > 0f));
                                                    let _e205 = (_e196 * select(1f, _e202, (_e202 < 1f)));
                                                    let _e206 = local_20;
                                                    let _e208 = local_20;
                                                    let _e210 = local_26;
                                                    if (_e196 >= _e210) {
                                                        let _e212 = local_22;
                                                        let _e213 = (_e212 + 1u);
                                                        local_27 = _e213;
                                                        let _e214 = local_1;
                                                        if (_e213 < _e214) {
                                                        } else {
                                                            phi_327_ = true;
                                                            break;
                                                        }
                                                        let _e216 = local_27;
                                                        let _e219 = global_3.member[_e216];
                                                        let _e220 = local_19;
                                                        let _e222 = local_19;
                                                        phi_273_ = select(_e222, _e219, (_e219 < _e220));
                                                    } else {
                                                        phi_273_ = _e132;
                                                    }
                                                    let _e225 = phi_273_;
                                                    phi_274_ = _e225;
                                                    phi_275_ = select(_e205, _e208, (_e206 > _e205));
                                                } else {
                                                    phi_274_ = _e132;
                                                    phi_275_ = _e134;
                                                }
                                                let _e227 = phi_274_;
                                                let _e229 = phi_275_;
                                                phi_276_ = _e227;
                                                phi_277_ = _e229;
                                            } else {
                                                phi_276_ = _e132;
                                                phi_277_ = _e134;
                                            }
                                            let _e231 = phi_276_;
                                            let _e233 = phi_277_;
                                            let _e234 = local_18;
                                            phi_279_ = (_e234 + 1i);
                                            phi_280_ = _e231;
                                            phi_281_ = _e233;
                                        } else {
                                            phi_279_ = i32();
                                            phi_280_ = u32();
                                            phi_281_ = f32();
                                        }
                                        let _e237 = phi_279_;
                                        let _e239 = phi_280_;
                                        let _e241 = phi_281_;
                                        phi_283_ = _e237;
                                        phi_284_ = _e239;
                                        phi_285_ = _e241;
                                        phi_286_ = _e143;
                                    } else {
                                        phi_283_ = i32();
                                        phi_284_ = u32();
                                        phi_285_ = f32();
                                        phi_286_ = false;
                                    }
                                    let _e243 = phi_283_;
                                    let _e245 = phi_284_;
                                    let _e247 = phi_285_;
                                    let _e249 = phi_286_;
                                    phi_156_ = _e243;
                                    phi_159_ = _e245;
                                    phi_161_ = _e247;
                                    phi_288_ = _e249;
                                } else {
                                    phi_156_ = i32();
                                    phi_159_ = u32();
                                    phi_161_ = f32();
                                    phi_288_ = false;
                                }
                                let _e251 = phi_156_;
                                let _e253 = phi_159_;
                                let _e255 = phi_161_;
                                let _e257 = phi_288_;
                                local_28 = _e257;
                                continue;
                                continuing {
                                    let _e258 = local_28;
                                    phi_155_ = _e251;
                                    phi_158_ = _e253;
                                    phi_160_ = _e255;
                                    phi_327_ = _e115;
                                    break if !(_e258);
                                }
                            }
                            let _e261 = phi_327_;
                            phi_347_ = _e261;
                            if _e261 {
                                break;
                            }
                            let _e262 = local_13;
                            phi_348_ = _e261;
                            phi_139_ = (_e262 + 1i);
                            let _e331 = local_32;
                            phi_142_ = _e331;
                            let _e334 = local_33;
                            phi_144_ = _e334;
                        } else {
                            phi_348_ = _e115;
                            phi_139_ = i32();
                            phi_142_ = u32();
                            phi_144_ = f32();
                        }
                        let _e265 = phi_348_;
                        let _e267 = phi_139_;
                        let _e269 = phi_142_;
                        let _e271 = phi_144_;
                        continue;
                        continuing {
                            let _e272 = local_16;
                            phi_343_ = _e265;
                            phi_138_ = _e267;
                            phi_141_ = _e269;
                            phi_143_ = _e271;
                            phi_347_ = _e265;
                            break if !(_e272);
                        }
                    }
                    let _e275 = phi_347_;
                    if _e275 {
                        break;
                    }
                    let _e276 = local_12;
                    let _e277 = local_6;
                    let _e279 = local_11;
                    let _e281 = (2u * ((_e276 * _e277) + _e279));
                    local_29 = _e281;
                    let _e282 = local_15;
                    local_30 = bitcast<u32>(_e282);
                    let _e284 = local_2;
                    if (_e281 < _e284) {
                    } else {
                        break;
                    }
                    let _e286 = local_29;
                    let _e289 = local_30;
                    global_4.member[_e286] = _e289;
                    let _e290 = local_29;
                    let _e291 = (_e290 + 1u);
                    local_31 = _e291;
                    let _e292 = local_2;
                    if (_e291 < _e292) {
                    } else {
                        break;
                    }
                    let _e294 = local_31;
                    let _e297 = local_14;
                    global_4.member[_e294] = _e297;
                }
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn scatter_gather_dilate(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
