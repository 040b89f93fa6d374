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
    member_10: array<u32, 3>,
}

struct type_15 {
    member: type_14,
}

struct type_23 {
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
var<storage, read_write> global_7: type_23;

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
    var local_14: u32;
    var local_15: bool;
    var local_16: bool;
    var local_17: u32;
    var local_18: u32;
    var local_19: f32;
    var local_20: u32;
    var local_21: f32;
    var local_22: u32;
    var local_23: f32;
    var local_24: u32;
    var local_25: array<f32, 3>;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: bool;
    var phi_93_: u32;
    var phi_150_: bool;
    var phi_238_: array<f32, 3>;
    var phi_94_: u32;
    var phi_394_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e60 = global;
            local = _e60;
            let _e61 = global_1;
            let _e62 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e75 = global_3.member.member_1;
            let _e78 = global_3.member.member_2;
            local_5 = (_e75 * _e78);
            local_6 = (_e62.x * 256u);
            phi_93_ = (_e61.x * 256u);
            loop {
                let _e83 = phi_93_;
                local_7 = _e83;
                let _e84 = local_7;
                let _e85 = local_5;
                let _e86 = (_e84 < _e85);
                local_8 = _e86;
                if _e86 {
                    let _e87 = local_7;
                    let _e88 = local;
                    let _e89 = (_e87 + _e88);
                    local_9 = _e89;
                    let _e90 = local_5;
                    if (_e89 < _e90) {
                        let _e92 = local_9;
                        let _e93 = (5u * _e92);
                        local_10 = _e93;
                        let _e94 = (_e93 + 3u);
                        local_11 = _e94;
                        let _e95 = local_1;
                        if (_e94 < _e95) {
                        } else {
                            phi_394_ = true;
                            break;
                        }
                        let _e97 = local_11;
                        let _e100 = global_4.member[_e97];
                        local_12 = bitcast<f32>(_e100);
                        let _e102 = local_10;
                        let _e103 = (_e102 + 4u);
                        local_13 = _e103;
                        let _e104 = local_1;
                        if (_e103 < _e104) {
                        } else {
                            phi_394_ = true;
                            break;
                        }
                        let _e106 = local_13;
                        let _e109 = global_4.member[_e106];
                        let _e111 = bitcast<u32>(bitcast<f32>(_e109));
                        local_14 = _e111;
                        let _e113 = ((_e111 & 2139095040u) != 2139095040u);
                        local_15 = _e113;
                        if _e113 {
                            phi_150_ = true;
                        } else {
                            let _e114 = local_12;
                            phi_150_ = (_e114 > 0f);
                        }
                        let _e117 = phi_150_;
                        if _e117 {
                            let _e118 = local_9;
                            let _e119 = local_3;
                            let _e120 = (_e118 < _e119);
                            local_16 = _e120;
                            if _e120 {
                            } else {
                                phi_394_ = true;
                                break;
                            }
                            let _e121 = local_9;
                            let _e124 = global_6.member[_e121];
                            local_17 = _e124;
                            let _e127 = global_3.member.member_3;
                            local_18 = _e127;
                            if (_e124 < _e127) {
                                let _e129 = local_10;
                                let _e130 = local_1;
                                if (_e129 < _e130) {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e132 = local_10;
                                let _e135 = global_4.member[_e132];
                                local_19 = bitcast<f32>(_e135);
                                let _e137 = local_10;
                                let _e138 = (_e137 + 1u);
                                local_20 = _e138;
                                let _e139 = local_1;
                                if (_e138 < _e139) {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e141 = local_20;
                                let _e144 = global_4.member[_e141];
                                local_21 = bitcast<f32>(_e144);
                                let _e146 = local_10;
                                let _e147 = (_e146 + 2u);
                                local_22 = _e147;
                                let _e148 = local_1;
                                if (_e147 < _e148) {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e150 = local_22;
                                let _e153 = global_4.member[_e150];
                                let _e154 = bitcast<f32>(_e153);
                                local_23 = _e154;
                                let _e155 = local_19;
                                let _e156 = local_21;
                                let _e158 = local_9;
                                let _e159 = local_18;
                                let _e161 = local_17;
                                local_24 = ((_e158 * _e159) + _e161);
                                let _e163 = local_12;
                                if (_e163 == 1f) {
                                    phi_238_ = array<f32, 3>(_e155, _e156, _e154);
                                } else {
                                    let _e165 = local_19;
                                    let _e166 = local_12;
                                    let _e168 = local_21;
                                    let _e169 = local_12;
                                    let _e171 = local_23;
                                    let _e172 = local_12;
                                    phi_238_ = array<f32, 3>((_e165 * _e166), (_e168 * _e169), (_e171 * _e172));
                                }
                                let _e176 = phi_238_;
                                local_25 = _e176;
                                let _e177 = local_24;
                                let _e178 = (5u * _e177);
                                local_26 = _e178;
                                local_27 = bitcast<u32>(_e176[0]);
                                let _e181 = local_2;
                                if (_e178 < _e181) {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e183 = local_26;
                                let _e186 = local_27;
                                global_5.member[_e183] = _e186;
                                let _e187 = local_26;
                                let _e188 = (_e187 + 1u);
                                local_28 = _e188;
                                let _e189 = local_25;
                                local_29 = bitcast<u32>(_e189[1]);
                                let _e192 = local_2;
                                if (_e188 < _e192) {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e194 = local_28;
                                let _e197 = local_29;
                                global_5.member[_e194] = _e197;
                                let _e198 = local_26;
                                let _e199 = (_e198 + 2u);
                                local_30 = _e199;
                                let _e200 = local_25;
                                local_31 = bitcast<u32>(_e200[2]);
                                let _e203 = local_2;
                                if (_e199 < _e203) {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e205 = local_30;
                                let _e208 = local_31;
                                global_5.member[_e205] = _e208;
                                let _e209 = local_26;
                                let _e210 = (_e209 + 3u);
                                local_32 = _e210;
                                let _e211 = local_2;
                                if (_e210 < _e211) {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e213 = local_32;
                                let _e216 = local_14;
                                global_5.member[_e213] = _e216;
                                let _e217 = local_26;
                                let _e218 = (_e217 + 4u);
                                local_33 = _e218;
                                let _e219 = local_12;
                                local_34 = bitcast<u32>(_e219);
                                let _e221 = local_2;
                                if (_e218 < _e221) {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e223 = local_33;
                                let _e226 = local_34;
                                global_5.member[_e223] = _e226;
                                let _e227 = local_17;
                                local_35 = (_e227 + 1u);
                                let _e229 = local_16;
                                if _e229 {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e230 = local_35;
                                global_6.member[_e121] = _e230;
                            }
                            let _e231 = local_15;
                            if _e231 {
                                let _e232 = local_4;
                                let _e233 = (0u < _e232);
                                local_36 = _e233;
                                if _e233 {
                                } else {
                                    phi_394_ = true;
                                    break;
                                }
                                let _e236 = atomicLoad((&global_7.member[0u]));
                                if (_e236 == 0u) {
                                    let _e238 = local_36;
                                    if _e238 {
                                    } else {
                                        phi_394_ = true;
                                        break;
                                    }
                                    let _e239 = atomicMax((&global_7.member[0u]), 1u);
                                }
                            }
                        }
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e240 = local_7;
                    let _e241 = local_6;
                    phi_94_ = (_e240 + _e241);
                } else {
                    phi_94_ = u32();
                }
                let _e244 = phi_94_;
                continue;
                continuing {
                    let _e245 = local_8;
                    phi_93_ = _e244;
                    phi_394_ = false;
                    break if !(_e245);
                }
            }
            let _e248 = phi_394_;
            if _e248 {
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
