struct type_6 {
    member: array<u32>,
}

struct type_17 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_18 {
    member: type_17,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(2) 
var<storage, read_write> global_3: type_6;
@group(0) @binding(3) 
var<storage, read_write> global_4: type_6;
var<immediate> global_5: type_18;
@group(0) @binding(0) 
var global_6: texture_2d<f32>;
@group(0) @binding(1) 
var global_7: texture_depth_2d;
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
    var local_8: bool;
    var local_9: u32;
    var local_10: f32;
    var local_11: f32;
    var local_12: f32;
    var local_13: f32;
    var local_14: u32;
    var local_15: bool;
    var local_16: f32;
    var local_17: bool;
    var local_18: f32;
    var local_19: f32;
    var local_20: f32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: bool;
    var local_31: f32;
    var local_32: f32;
    var phi_292_: bool;
    var phi_83_: u32;
    var phi_94_: u32;
    var phi_178_: f32;
    var phi_179_: f32;
    var phi_199_: f32;
    var phi_200_: f32;
    var phi_201_: f32;
    var phi_202_: f32;
    var phi_208_: f32;
    var phi_209_: f32;
    var phi_211_: f32;
    var phi_212_: bool;
    var phi_217_: f32;
    var phi_265_: u32;
    var phi_95_: u32;
    var phi_266_: bool;
    var phi_287_: bool;
    var phi_301_: bool;
    var phi_84_: u32;
    var phi_300_: bool;

    let _e59 = global_8;
    local_31 = bitcast<f32>(_e59);
    let _e61 = global_9;
    let _e62 = bitcast<f32>(_e61);
    local_32 = _e62;
    switch bitcast<i32>(0u) {
        default: {
            let _e64 = global;
            local = _e64;
            let _e65 = global_1;
            let _e66 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            let _e75 = global_5.member.member;
            local_3 = _e75;
            let _e78 = global_5.member.member_1;
            local_4 = (_e75 * _e78);
            local_5 = (_e66.x * 256u);
            local_6 = (_e64 + 1u);
            phi_292_ = false;
            phi_83_ = (_e65.x * 256u);
            loop {
                let _e84 = phi_292_;
                let _e86 = phi_83_;
                local_7 = _e86;
                let _e87 = local_7;
                let _e88 = local_4;
                let _e89 = (_e87 < _e88);
                local_8 = _e89;
                if _e89 {
                    let _e90 = local_7;
                    let _e91 = local;
                    phi_94_ = (_e90 + _e91);
                    loop {
                        let _e94 = phi_94_;
                        local_9 = _e94;
                        let _e95 = local_9;
                        let _e96 = local_4;
                        if (_e95 < _e96) {
                            let _e98 = local_7;
                            let _e99 = local_6;
                            let _e101 = local_9;
                            let _e102 = (_e101 < (_e98 + _e99));
                            if _e102 {
                                let _e103 = local_3;
                                if (_e103 == 0u) {
                                    phi_287_ = true;
                                    break;
                                }
                                let _e105 = local_9;
                                let _e106 = local_3;
                                let _e107 = (_e105 / _e106);
                                let _e108 = local_3;
                                let _e110 = local_9;
                                let _e114 = vec2<i32>(bitcast<i32>((_e110 - (_e107 * _e108))), bitcast<i32>(_e107));
                                let _e115 = textureLoad(global_6, _e114, 0u);
                                local_10 = _e115.x;
                                local_11 = _e115.y;
                                local_12 = _e115.z;
                                let _e119 = textureLoad(global_7, _e114, 0u);
                                local_13 = vec4(_e119).x;
                                let _e124 = global_5.member.member_3;
                                local_14 = _e124;
                                if (_e124 == 0u) {
                                    phi_217_ = vec4(_e119).x;
                                } else {
                                    let _e126 = local_13;
                                    if (_e126 >= 0f) {
                                        let _e128 = local_13;
                                        let _e129 = (_e128 <= 1f);
                                        local_15 = _e129;
                                        if _e129 {
                                            let _e132 = global_5.member.member_5;
                                            local_16 = _e132;
                                            let _e133 = local_32;
                                            local_17 = (_e132 == _e133);
                                            let _e135 = local_14;
                                            if (_e135 == 1u) {
                                                let _e137 = local_17;
                                                if _e137 {
                                                    let _e140 = global_5.member.member_4;
                                                    let _e141 = local_13;
                                                    phi_178_ = (1f - _e141);
                                                    phi_179_ = _e140;
                                                } else {
                                                    let _e145 = global_5.member.member_4;
                                                    let _e146 = local_16;
                                                    let _e148 = local_16;
                                                    let _e150 = local_13;
                                                    let _e152 = local_16;
                                                    phi_178_ = (_e152 - (_e150 * (_e148 - _e145)));
                                                    phi_179_ = (_e145 * _e146);
                                                }
                                                let _e155 = phi_178_;
                                                let _e157 = phi_179_;
                                                phi_201_ = _e155;
                                                phi_202_ = _e157;
                                            } else {
                                                let _e158 = local_17;
                                                if _e158 {
                                                    let _e161 = global_5.member.member_4;
                                                    phi_199_ = vec4(_e119).x;
                                                    phi_200_ = _e161;
                                                } else {
                                                    let _e164 = global_5.member.member_4;
                                                    let _e165 = local_16;
                                                    let _e167 = local_16;
                                                    let _e169 = local_13;
                                                    phi_199_ = (_e164 + (_e169 * (_e167 - _e164)));
                                                    phi_200_ = (_e164 * _e165);
                                                }
                                                let _e173 = phi_199_;
                                                let _e175 = phi_200_;
                                                phi_201_ = _e173;
                                                phi_202_ = _e175;
                                            }
                                            let _e177 = phi_201_;
                                            let _e179 = phi_202_;
                                            local_18 = _e177;
                                            local_19 = _e179;
                                            if (_e177 <= 0f) {
                                                phi_208_ = _e62;
                                            } else {
                                                let _e181 = local_19;
                                                let _e182 = local_18;
                                                phi_208_ = (_e181 / _e182);
                                            }
                                            let _e185 = phi_208_;
                                            phi_209_ = _e185;
                                        } else {
                                            phi_209_ = f32();
                                        }
                                        let _e187 = phi_209_;
                                        let _e188 = local_15;
                                        phi_211_ = _e187;
                                        phi_212_ = select(true, false, _e188);
                                    } else {
                                        phi_211_ = f32();
                                        phi_212_ = true;
                                    }
                                    let _e191 = phi_211_;
                                    let _e193 = phi_212_;
                                    let _e194 = local_31;
                                    phi_217_ = select(_e191, _e194, _e193);
                                }
                                let _e197 = phi_217_;
                                local_20 = _e197;
                                let _e198 = local_9;
                                let _e199 = (5u * _e198);
                                local_21 = _e199;
                                let _e200 = local_10;
                                local_22 = bitcast<u32>(_e200);
                                let _e202 = local_1;
                                if (_e199 < _e202) {
                                } else {
                                    phi_287_ = true;
                                    break;
                                }
                                let _e204 = local_21;
                                let _e207 = local_22;
                                global_3.member[_e204] = _e207;
                                let _e208 = local_21;
                                let _e209 = (_e208 + 1u);
                                local_23 = _e209;
                                let _e210 = local_11;
                                local_24 = bitcast<u32>(_e210);
                                let _e212 = local_1;
                                if (_e209 < _e212) {
                                } else {
                                    phi_287_ = true;
                                    break;
                                }
                                let _e214 = local_23;
                                let _e217 = local_24;
                                global_3.member[_e214] = _e217;
                                let _e218 = local_21;
                                let _e219 = (_e218 + 2u);
                                local_25 = _e219;
                                let _e220 = local_12;
                                local_26 = bitcast<u32>(_e220);
                                let _e222 = local_1;
                                if (_e219 < _e222) {
                                } else {
                                    phi_287_ = true;
                                    break;
                                }
                                let _e224 = local_25;
                                let _e227 = local_26;
                                global_3.member[_e224] = _e227;
                                let _e228 = local_21;
                                let _e229 = (_e228 + 3u);
                                local_27 = _e229;
                                let _e230 = local_20;
                                local_28 = bitcast<u32>(_e230);
                                let _e232 = local_1;
                                if (_e229 < _e232) {
                                } else {
                                    phi_287_ = true;
                                    break;
                                }
                                let _e234 = local_27;
                                let _e237 = local_28;
                                global_3.member[_e234] = _e237;
                                let _e238 = local_21;
                                let _e239 = (_e238 + 4u);
                                local_29 = _e239;
                                let _e240 = local_1;
                                if (_e239 < _e240) {
                                } else {
                                    phi_287_ = true;
                                    break;
                                }
                                let _e242 = local_29;
                                global_3.member[_e242] = 1065353216u;
                                let _e245 = local_9;
                                let _e246 = local_2;
                                if (_e245 < _e246) {
                                } else {
                                    phi_287_ = true;
                                    break;
                                }
                                let _e248 = local_9;
                                global_4.member[_e248] = 1u;
                                let _e251 = local_9;
                                phi_265_ = (_e251 + 1u);
                            } else {
                                phi_265_ = u32();
                            }
                            let _e254 = phi_265_;
                            phi_95_ = _e254;
                            phi_266_ = _e102;
                        } else {
                            phi_95_ = u32();
                            phi_266_ = false;
                        }
                        let _e256 = phi_95_;
                        let _e258 = phi_266_;
                        local_30 = _e258;
                        continue;
                        continuing {
                            let _e259 = local_30;
                            phi_94_ = _e256;
                            phi_287_ = _e84;
                            break if !(_e259);
                        }
                    }
                    let _e262 = phi_287_;
                    phi_300_ = _e262;
                    if _e262 {
                        break;
                    }
                    let _e263 = local_7;
                    let _e264 = local_5;
                    phi_301_ = _e262;
                    phi_84_ = (_e263 + _e264);
                } else {
                    phi_301_ = _e84;
                    phi_84_ = u32();
                }
                let _e267 = phi_301_;
                let _e269 = phi_84_;
                continue;
                continuing {
                    let _e270 = local_8;
                    phi_292_ = _e267;
                    phi_83_ = _e269;
                    phi_300_ = _e267;
                    break if !(_e270);
                }
            }
            let _e273 = phi_300_;
            if _e273 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn frame_from_textures(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
