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
    var local_10: bool;
    var local_11: u32;
    var local_12: f32;
    var local_13: f32;
    var local_14: f32;
    var local_15: f32;
    var local_16: u32;
    var local_17: bool;
    var local_18: f32;
    var local_19: bool;
    var local_20: f32;
    var local_21: f32;
    var local_22: f32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: bool;
    var local_33: f32;
    var local_34: f32;
    var phi_295_: bool;
    var phi_83_: u32;
    var phi_94_: u32;
    var phi_181_: f32;
    var phi_182_: f32;
    var phi_202_: f32;
    var phi_203_: f32;
    var phi_204_: f32;
    var phi_205_: f32;
    var phi_211_: f32;
    var phi_212_: f32;
    var phi_214_: f32;
    var phi_215_: bool;
    var phi_220_: f32;
    var phi_268_: u32;
    var phi_95_: u32;
    var phi_269_: bool;
    var phi_290_: bool;
    var phi_304_: bool;
    var phi_84_: u32;
    var phi_303_: bool;

    let _e61 = global_8;
    local_33 = bitcast<f32>(_e61);
    let _e63 = global_9;
    let _e64 = bitcast<f32>(_e63);
    local_34 = _e64;
    switch bitcast<i32>(0u) {
        default: {
            let _e66 = global;
            local = _e66;
            let _e67 = global_1;
            let _e68 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            let _e77 = global_5.member.member;
            local_3 = _e77;
            let _e80 = global_5.member.member_1;
            local_4 = (_e77 * _e80);
            local_5 = (_e68.x * 256u);
            local_6 = (_e66 + 1u);
            phi_295_ = false;
            phi_83_ = (_e67.x * 256u);
            loop {
                let _e86 = phi_295_;
                let _e88 = phi_83_;
                local_7 = _e88;
                let _e89 = local_7;
                let _e90 = local_4;
                let _e91 = (_e89 < _e90);
                local_8 = _e91;
                if _e91 {
                    let _e92 = local_7;
                    let _e93 = local;
                    phi_94_ = (_e92 + _e93);
                    loop {
                        let _e96 = phi_94_;
                        local_9 = _e96;
                        let _e97 = local_9;
                        let _e98 = local_4;
                        if (_e97 < _e98) {
                            let _e100 = local_7;
                            let _e101 = local_6;
                            let _e103 = local_9;
                            let _e104 = (_e103 < (_e100 + _e101));
                            if _e104 {
                                let _e105 = local_3;
                                let _e106 = (_e105 == 0u);
                                local_10 = _e106;
                                if _e106 {
                                    phi_290_ = true;
                                    break;
                                }
                                let _e107 = local_9;
                                let _e108 = local_3;
                                local_11 = (_e107 % _e108);
                                let _e110 = local_10;
                                if _e110 {
                                    phi_290_ = true;
                                    break;
                                }
                                let _e111 = local_9;
                                let _e112 = local_3;
                                let _e114 = local_11;
                                let _e117 = vec2<i32>(bitcast<i32>(_e114), bitcast<i32>((_e111 / _e112)));
                                let _e118 = textureLoad(global_6, _e117, 0u);
                                local_12 = _e118.x;
                                local_13 = _e118.y;
                                local_14 = _e118.z;
                                let _e122 = textureLoad(global_7, _e117, 0u);
                                local_15 = vec4(_e122).x;
                                let _e127 = global_5.member.member_3;
                                local_16 = _e127;
                                if (_e127 == 0u) {
                                    phi_220_ = vec4(_e122).x;
                                } else {
                                    let _e129 = local_15;
                                    if (_e129 >= 0f) {
                                        let _e131 = local_15;
                                        let _e132 = (_e131 <= 1f);
                                        local_17 = _e132;
                                        if _e132 {
                                            let _e135 = global_5.member.member_5;
                                            local_18 = _e135;
                                            let _e136 = local_34;
                                            local_19 = (_e135 == _e136);
                                            let _e138 = local_16;
                                            if (_e138 == 1u) {
                                                let _e140 = local_19;
                                                if _e140 {
                                                    let _e143 = global_5.member.member_4;
                                                    let _e144 = local_15;
                                                    phi_181_ = (1f - _e144);
                                                    phi_182_ = _e143;
                                                } else {
                                                    let _e148 = global_5.member.member_4;
                                                    let _e149 = local_18;
                                                    let _e151 = local_18;
                                                    let _e153 = local_15;
                                                    let _e155 = local_18;
                                                    phi_181_ = (_e155 - (_e153 * (_e151 - _e148)));
                                                    phi_182_ = (_e148 * _e149);
                                                }
                                                let _e158 = phi_181_;
                                                let _e160 = phi_182_;
                                                phi_204_ = _e158;
                                                phi_205_ = _e160;
                                            } else {
                                                let _e161 = local_19;
                                                if _e161 {
                                                    let _e164 = global_5.member.member_4;
                                                    phi_202_ = vec4(_e122).x;
                                                    phi_203_ = _e164;
                                                } else {
                                                    let _e167 = global_5.member.member_4;
                                                    let _e168 = local_18;
                                                    let _e170 = local_18;
                                                    let _e172 = local_15;
                                                    phi_202_ = (_e167 + (_e172 * (_e170 - _e167)));
                                                    phi_203_ = (_e167 * _e168);
                                                }
                                                let _e176 = phi_202_;
                                                let _e178 = phi_203_;
                                                phi_204_ = _e176;
                                                phi_205_ = _e178;
                                            }
                                            let _e180 = phi_204_;
                                            let _e182 = phi_205_;
                                            local_20 = _e180;
                                            local_21 = _e182;
                                            if (_e180 <= 0f) {
                                                phi_211_ = _e64;
                                            } else {
                                                let _e184 = local_21;
                                                let _e185 = local_20;
                                                phi_211_ = (_e184 / _e185);
                                            }
                                            let _e188 = phi_211_;
                                            phi_212_ = _e188;
                                        } else {
                                            phi_212_ = f32();
                                        }
                                        let _e190 = phi_212_;
                                        let _e191 = local_17;
                                        phi_214_ = _e190;
                                        phi_215_ = select(true, false, _e191);
                                    } else {
                                        phi_214_ = f32();
                                        phi_215_ = true;
                                    }
                                    let _e194 = phi_214_;
                                    let _e196 = phi_215_;
                                    let _e197 = local_33;
                                    phi_220_ = select(_e194, _e197, _e196);
                                }
                                let _e200 = phi_220_;
                                local_22 = _e200;
                                let _e201 = local_9;
                                let _e202 = (5u * _e201);
                                local_23 = _e202;
                                let _e203 = local_12;
                                local_24 = bitcast<u32>(_e203);
                                let _e205 = local_1;
                                if (_e202 < _e205) {
                                } else {
                                    phi_290_ = true;
                                    break;
                                }
                                let _e207 = local_23;
                                let _e210 = local_24;
                                global_3.member[_e207] = _e210;
                                let _e211 = local_23;
                                let _e212 = (_e211 + 1u);
                                local_25 = _e212;
                                let _e213 = local_13;
                                local_26 = bitcast<u32>(_e213);
                                let _e215 = local_1;
                                if (_e212 < _e215) {
                                } else {
                                    phi_290_ = true;
                                    break;
                                }
                                let _e217 = local_25;
                                let _e220 = local_26;
                                global_3.member[_e217] = _e220;
                                let _e221 = local_23;
                                let _e222 = (_e221 + 2u);
                                local_27 = _e222;
                                let _e223 = local_14;
                                local_28 = bitcast<u32>(_e223);
                                let _e225 = local_1;
                                if (_e222 < _e225) {
                                } else {
                                    phi_290_ = true;
                                    break;
                                }
                                let _e227 = local_27;
                                let _e230 = local_28;
                                global_3.member[_e227] = _e230;
                                let _e231 = local_23;
                                let _e232 = (_e231 + 3u);
                                local_29 = _e232;
                                let _e233 = local_22;
                                local_30 = bitcast<u32>(_e233);
                                let _e235 = local_1;
                                if (_e232 < _e235) {
                                } else {
                                    phi_290_ = true;
                                    break;
                                }
                                let _e237 = local_29;
                                let _e240 = local_30;
                                global_3.member[_e237] = _e240;
                                let _e241 = local_23;
                                let _e242 = (_e241 + 4u);
                                local_31 = _e242;
                                let _e243 = local_1;
                                if (_e242 < _e243) {
                                } else {
                                    phi_290_ = true;
                                    break;
                                }
                                let _e245 = local_31;
                                global_3.member[_e245] = 1065353216u;
                                let _e248 = local_9;
                                let _e249 = local_2;
                                if (_e248 < _e249) {
                                } else {
                                    phi_290_ = true;
                                    break;
                                }
                                let _e251 = local_9;
                                global_4.member[_e251] = 1u;
                                let _e254 = local_9;
                                phi_268_ = (_e254 + 1u);
                            } else {
                                phi_268_ = u32();
                            }
                            let _e257 = phi_268_;
                            phi_95_ = _e257;
                            phi_269_ = _e104;
                        } else {
                            phi_95_ = u32();
                            phi_269_ = false;
                        }
                        let _e259 = phi_95_;
                        let _e261 = phi_269_;
                        local_32 = _e261;
                        continue;
                        continuing {
                            let _e262 = local_32;
                            phi_94_ = _e259;
                            phi_290_ = _e86;
                            break if !(_e262);
                        }
                    }
                    let _e265 = phi_290_;
                    phi_303_ = _e265;
                    if _e265 {
                        break;
                    }
                    let _e266 = local_7;
                    let _e267 = local_5;
                    phi_304_ = _e265;
                    phi_84_ = (_e266 + _e267);
                } else {
                    phi_304_ = _e86;
                    phi_84_ = u32();
                }
                let _e270 = phi_304_;
                let _e272 = phi_84_;
                continue;
                continuing {
                    let _e273 = local_8;
                    phi_295_ = _e270;
                    phi_83_ = _e272;
                    phi_303_ = _e270;
                    break if !(_e273);
                }
            }
            let _e276 = phi_303_;
            if _e276 {
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
