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

struct type_15 {
    member: type_14,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_15;
@group(0) @binding(0) 
var<storage, read_write> global_4: type_7;
var<private> global_5: u32 = 4286578688u;
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
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: bool;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: bool;
    var local_26: u32;
    var local_27: bool;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: f32;
    var local_32: f32;
    var local_33: bool;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: f32;
    var local_38: u32;
    var local_39: f32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var phi_129_: u32;
    var phi_147_: u32;
    var phi_170_: u32;
    var phi_188_: u32;
    var phi_408_: bool;
    var phi_215_: u32;
    var phi_243_: u32;
    var phi_246_: f32;
    var phi_248_: f32;
    var phi_377_: bool;
    var phi_392_: bool;
    var phi_314_: f32;
    var phi_315_: f32;
    var phi_316_: f32;
    var phi_317_: f32;
    var phi_244_: u32;
    var phi_247_: f32;
    var phi_249_: f32;
    var phi_399_: bool;
    var phi_415_: bool;
    var phi_414_: bool;
    var phi_216_: u32;
    var phi_413_: bool;

    let _e67 = global_5;
    let _e69 = global_6;
    switch bitcast<i32>(0u) {
        default: {
            let _e72 = global;
            local = _e72;
            let _e73 = global_1;
            let _e74 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = _e73.x;
            local_3 = _e74.x;
            let _e81 = global_3.member.member_6;
            local_4 = _e81;
            let _e84 = (1u << bitcast<u32>((_e81 & 31u)));
            local_5 = _e84;
            let _e87 = global_3.member.member;
            local_6 = _e87;
            let _e88 = (_e84 == 0u);
            local_7 = _e88;
            if _e88 {
                break;
            }
            let _e89 = local_6;
            let _e90 = local_5;
            let _e91 = (_e89 / _e90);
            local_8 = _e91;
            let _e92 = local_7;
            if _e92 {
                break;
            }
            let _e93 = local_6;
            let _e94 = local_5;
            if ((_e93 % _e94) > 0u) {
                let _e97 = local_8;
                phi_129_ = (_e97 + 1u);
            } else {
                phi_129_ = _e91;
            }
            let _e100 = phi_129_;
            local_9 = _e100;
            let _e103 = global_3.member.member_1;
            local_10 = _e103;
            let _e104 = local_7;
            if _e104 {
                break;
            }
            let _e105 = local_10;
            let _e106 = local_5;
            let _e107 = (_e105 / _e106);
            local_11 = _e107;
            let _e108 = local_7;
            if _e108 {
                break;
            }
            let _e109 = local_10;
            let _e110 = local_5;
            if ((_e109 % _e110) > 0u) {
                let _e113 = local_11;
                phi_147_ = (_e113 + 1u);
            } else {
                phi_147_ = _e107;
            }
            let _e116 = phi_147_;
            local_12 = _e116;
            let _e117 = local_4;
            let _e118 = (_e117 - 1u);
            local_13 = _e118;
            let _e121 = (1u << bitcast<u32>((_e118 & 31u)));
            local_14 = _e121;
            let _e122 = (_e121 == 0u);
            local_15 = _e122;
            if _e122 {
                break;
            }
            let _e123 = local_6;
            let _e124 = local_14;
            let _e125 = (_e123 / _e124);
            local_16 = _e125;
            let _e126 = local_15;
            if _e126 {
                break;
            }
            let _e127 = local_6;
            let _e128 = local_14;
            if ((_e127 % _e128) > 0u) {
                let _e131 = local_16;
                phi_170_ = (_e131 + 1u);
            } else {
                phi_170_ = _e125;
            }
            let _e134 = phi_170_;
            local_17 = _e134;
            let _e135 = local_15;
            if _e135 {
                break;
            }
            let _e136 = local_10;
            let _e137 = local_14;
            let _e138 = (_e136 / _e137);
            local_18 = _e138;
            let _e139 = local_15;
            if _e139 {
                break;
            }
            let _e140 = local_10;
            let _e141 = local_14;
            if ((_e140 % _e141) > 0u) {
                let _e144 = local_18;
                phi_188_ = (_e144 + 1u);
            } else {
                phi_188_ = _e138;
            }
            let _e147 = phi_188_;
            local_19 = _e147;
            let _e148 = local_4;
            if (_e148 < 14u) {
            } else {
                break;
            }
            let _e150 = local_4;
            let _e154 = global_3.member.member_9[_e150];
            local_20 = _e154;
            let _e155 = local_13;
            if (_e155 < 14u) {
            } else {
                break;
            }
            let _e157 = local_13;
            let _e161 = global_3.member.member_9[_e157];
            local_21 = _e161;
            let _e162 = local_9;
            let _e163 = local_12;
            local_22 = (_e162 * _e163);
            let _e165 = local_3;
            local_23 = (_e165 * 256u);
            let _e167 = local_2;
            phi_408_ = false;
            phi_215_ = (_e167 * 256u);
            loop {
                let _e170 = phi_408_;
                let _e172 = phi_215_;
                local_24 = _e172;
                let _e173 = local_24;
                let _e174 = local_22;
                let _e175 = (_e173 < _e174);
                local_25 = _e175;
                if _e175 {
                    let _e176 = local_24;
                    let _e177 = local;
                    let _e178 = (_e176 + _e177);
                    local_26 = _e178;
                    let _e179 = local_22;
                    if (_e178 < _e179) {
                        let _e181 = local_9;
                        let _e182 = (_e181 == 0u);
                        local_27 = _e182;
                        if _e182 {
                            phi_413_ = true;
                            break;
                        }
                        let _e183 = local_26;
                        let _e184 = local_9;
                        local_28 = (_e183 % _e184);
                        let _e186 = local_27;
                        if _e186 {
                            phi_413_ = true;
                            break;
                        }
                        let _e187 = local_26;
                        let _e188 = local_9;
                        local_29 = (_e187 / _e188);
                        phi_243_ = 0u;
                        phi_246_ = bitcast<f32>(_e67);
                        phi_248_ = bitcast<f32>(_e69);
                        loop {
                            let _e191 = phi_243_;
                            let _e193 = phi_246_;
                            let _e195 = phi_248_;
                            local_30 = _e191;
                            local_31 = _e193;
                            local_32 = _e195;
                            let _e196 = local_30;
                            let _e197 = (_e196 < 4u);
                            local_33 = _e197;
                            if _e197 {
                                let _e198 = local_28;
                                let _e200 = local_30;
                                let _e202 = ((2u * _e198) + (_e200 % 2u));
                                local_34 = _e202;
                                let _e203 = local_29;
                                let _e205 = local_30;
                                local_35 = ((2u * _e203) + (_e205 / 2u));
                                let _e208 = local_17;
                                if (_e202 < _e208) {
                                    let _e210 = local_35;
                                    let _e211 = local_19;
                                    if (_e210 < _e211) {
                                        let _e213 = local_35;
                                        let _e214 = local_17;
                                        let _e216 = local_21;
                                        let _e218 = local_34;
                                        let _e220 = (2u * ((_e216 + (_e213 * _e214)) + _e218));
                                        local_36 = _e220;
                                        let _e221 = local_1;
                                        if (_e220 < _e221) {
                                        } else {
                                            phi_399_ = true;
                                            break;
                                        }
                                        let _e223 = local_36;
                                        let _e226 = global_4.member[_e223];
                                        local_37 = bitcast<f32>(_e226);
                                        let _e228 = local_32;
                                        let _e229 = local_32;
                                        if !((_e228 == _e229)) {
                                            phi_377_ = true;
                                        } else {
                                            let _e232 = local_37;
                                            let _e233 = local_32;
                                            phi_377_ = (_e232 <= _e233);
                                        }
                                        let _e236 = phi_377_;
                                        let _e237 = local_37;
                                        let _e238 = local_32;
                                        let _e240 = local_36;
                                        let _e241 = (_e240 + 1u);
                                        local_38 = _e241;
                                        let _e242 = local_1;
                                        if (_e241 < _e242) {
                                        } else {
                                            phi_399_ = true;
                                            break;
                                        }
                                        let _e244 = local_38;
                                        let _e247 = global_4.member[_e244];
                                        local_39 = bitcast<f32>(_e247);
                                        let _e249 = local_31;
                                        let _e250 = local_31;
                                        if !((_e249 == _e250)) {
                                            phi_392_ = true;
                                        } else {
                                            let _e253 = local_39;
                                            let _e254 = local_31;
                                            phi_392_ = (_e253 >= _e254);
                                        }
                                        let _e257 = phi_392_;
                                        let _e258 = local_39;
                                        let _e259 = local_31;
                                        phi_314_ = select(_e259, _e258, _e257);
                                        phi_315_ = select(_e238, _e237, _e236);
                                    } else {
                                        phi_314_ = _e193;
                                        phi_315_ = _e195;
                                    }
                                    let _e262 = phi_314_;
                                    let _e264 = phi_315_;
                                    phi_316_ = _e262;
                                    phi_317_ = _e264;
                                } else {
                                    phi_316_ = _e193;
                                    phi_317_ = _e195;
                                }
                                let _e266 = phi_316_;
                                let _e268 = phi_317_;
                                let _e269 = local_30;
                                phi_244_ = (_e269 + 1u);
                                phi_247_ = _e266;
                                phi_249_ = _e268;
                            } else {
                                phi_244_ = u32();
                                phi_247_ = f32();
                                phi_249_ = f32();
                            }
                            let _e272 = phi_244_;
                            let _e274 = phi_247_;
                            let _e276 = phi_249_;
                            continue;
                            continuing {
                                let _e277 = local_33;
                                phi_243_ = _e272;
                                phi_246_ = _e274;
                                phi_248_ = _e276;
                                phi_399_ = _e170;
                                break if !(_e277);
                            }
                        }
                        let _e280 = phi_399_;
                        phi_413_ = _e280;
                        if _e280 {
                            break;
                        }
                        let _e281 = local_20;
                        let _e282 = local_26;
                        let _e284 = (2u * (_e281 + _e282));
                        local_40 = _e284;
                        let _e285 = local_32;
                        local_41 = bitcast<u32>(_e285);
                        let _e287 = local_1;
                        if (_e284 < _e287) {
                        } else {
                            phi_413_ = true;
                            break;
                        }
                        let _e289 = local_40;
                        let _e292 = local_41;
                        global_4.member[_e289] = _e292;
                        let _e293 = local_40;
                        let _e294 = (_e293 + 1u);
                        local_42 = _e294;
                        let _e295 = local_31;
                        local_43 = bitcast<u32>(_e295);
                        let _e297 = local_1;
                        if (_e294 < _e297) {
                        } else {
                            phi_413_ = true;
                            break;
                        }
                        let _e299 = local_42;
                        let _e302 = local_43;
                        global_4.member[_e299] = _e302;
                        phi_415_ = _e280;
                    } else {
                        phi_415_ = _e170;
                    }
                    let _e304 = phi_415_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e305 = local_24;
                    let _e306 = local_23;
                    phi_414_ = _e304;
                    phi_216_ = (_e305 + _e306);
                } else {
                    phi_414_ = _e170;
                    phi_216_ = u32();
                }
                let _e309 = phi_414_;
                let _e311 = phi_216_;
                continue;
                continuing {
                    let _e312 = local_25;
                    phi_408_ = _e309;
                    phi_215_ = _e311;
                    phi_413_ = _e309;
                    break if !(_e312);
                }
            }
            let _e315 = phi_413_;
            if _e315 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn raytrace_reduce(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
