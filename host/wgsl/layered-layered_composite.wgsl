struct type_6 {
    member: array<u32>,
}

struct type_13 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: array<f32, 4>,
    member_9: u32,
    member_10: array<u32, 3>,
}

struct type_14 {
    member: type_13,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_6;
var<immediate> global_4: type_14;
@group(0) @binding(1) 
var<storage, read_write> global_5: type_6;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: bool;
    var local_7: u32;
    var local_8: u32;
    var local_9: f32;
    var local_10: u32;
    var local_11: f32;
    var local_12: u32;
    var local_13: f32;
    var local_14: u32;
    var local_15: bool;
    var local_16: f32;
    var local_17: bool;
    var local_18: f32;
    var local_19: bool;
    var local_20: f32;
    var local_21: bool;
    var local_22: array<f32, 4>;
    var local_23: array<f32, 4>;
    var local_24: f32;
    var local_25: f32;
    var local_26: f32;
    var local_27: f32;
    var local_28: f32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var phi_94_: u32;
    var phi_259_: array<f32, 4>;
    var phi_260_: array<f32, 4>;
    var phi_366_: bool;
    var phi_95_: u32;
    var phi_375_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e53 = global;
            local = _e53;
            let _e54 = global_1;
            let _e55 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_5.member));
            let _e64 = global_4.member.member;
            let _e67 = global_4.member.member_1;
            local_3 = (_e64 * _e67);
            local_4 = (_e55.x * 256u);
            phi_94_ = (_e54.x * 256u);
            loop {
                let _e72 = phi_94_;
                local_5 = _e72;
                let _e73 = local_5;
                let _e74 = local_3;
                let _e75 = (_e73 < _e74);
                local_6 = _e75;
                if _e75 {
                    let _e76 = local_5;
                    let _e77 = local;
                    let _e78 = (_e76 + _e77);
                    local_7 = _e78;
                    let _e79 = local_3;
                    if (_e78 < _e79) {
                        let _e81 = local_7;
                        let _e82 = (4u * _e81);
                        local_8 = _e82;
                        let _e83 = local_1;
                        if (_e82 < _e83) {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e85 = local_8;
                        let _e88 = global_3.member[_e85];
                        local_9 = bitcast<f32>(_e88);
                        let _e90 = local_8;
                        let _e91 = (_e90 + 1u);
                        local_10 = _e91;
                        let _e92 = local_1;
                        if (_e91 < _e92) {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e94 = local_10;
                        let _e97 = global_3.member[_e94];
                        local_11 = bitcast<f32>(_e97);
                        let _e99 = local_8;
                        let _e100 = (_e99 + 2u);
                        local_12 = _e100;
                        let _e101 = local_1;
                        if (_e100 < _e101) {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e103 = local_12;
                        let _e106 = global_3.member[_e103];
                        local_13 = bitcast<f32>(_e106);
                        let _e108 = local_8;
                        let _e109 = (_e108 + 3u);
                        local_14 = _e109;
                        let _e110 = local_1;
                        if (_e109 < _e110) {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e112 = local_14;
                        let _e115 = global_3.member[_e112];
                        let _e117 = local_9;
                        let _e118 = local_11;
                        let _e119 = local_13;
                        let _e120 = array<f32, 4>(_e117, _e118, _e119, bitcast<f32>(_e115));
                        let _e121 = local_8;
                        let _e122 = local_2;
                        let _e123 = (_e121 < _e122);
                        local_15 = _e123;
                        if _e123 {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e124 = local_8;
                        let _e127 = global_5.member[_e124];
                        local_16 = bitcast<f32>(_e127);
                        let _e129 = local_10;
                        let _e130 = local_2;
                        let _e131 = (_e129 < _e130);
                        local_17 = _e131;
                        if _e131 {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e132 = local_10;
                        let _e135 = global_5.member[_e132];
                        local_18 = bitcast<f32>(_e135);
                        let _e137 = local_12;
                        let _e138 = local_2;
                        let _e139 = (_e137 < _e138);
                        local_19 = _e139;
                        if _e139 {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e140 = local_12;
                        let _e143 = global_5.member[_e140];
                        local_20 = bitcast<f32>(_e143);
                        let _e145 = local_14;
                        let _e146 = local_2;
                        let _e147 = (_e145 < _e146);
                        local_21 = _e147;
                        if _e147 {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e148 = local_14;
                        let _e151 = global_5.member[_e148];
                        let _e153 = local_16;
                        let _e154 = local_18;
                        let _e155 = local_20;
                        let _e156 = array<f32, 4>(_e153, _e154, _e155, bitcast<f32>(_e151));
                        let _e159 = global_4.member.member_5;
                        if (_e159 == 0u) {
                            phi_259_ = _e120;
                            phi_260_ = _e156;
                        } else {
                            phi_259_ = _e156;
                            phi_260_ = _e120;
                        }
                        let _e162 = phi_259_;
                        let _e164 = phi_260_;
                        local_22 = _e162;
                        local_23 = _e164;
                        local_24 = _e162[3];
                        let _e166 = (1f - _e162[3]);
                        local_25 = _e166;
                        if !((_e166 == _e166)) {
                            phi_366_ = true;
                        } else {
                            let _e169 = local_25;
                            phi_366_ = (0f >= _e169);
                        }
                        let _e172 = phi_366_;
                        let _e173 = local_25;
                        let _e174 = select(_e173, 0f, _e172);
                        let _e175 = local_22;
                        let _e177 = local_23;
                        let _e181 = local_22;
                        let _e183 = local_23;
                        local_26 = (_e181[1] + (_e174 * _e183[1]));
                        let _e187 = local_22;
                        let _e189 = local_23;
                        local_27 = (_e187[2] + (_e174 * _e189[2]));
                        let _e193 = local_23;
                        let _e196 = local_24;
                        local_28 = (_e196 + (_e174 * _e193[3]));
                        local_29 = bitcast<u32>((_e175[0] + (_e174 * _e177[0])));
                        let _e199 = local_15;
                        if _e199 {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e200 = local_29;
                        global_5.member[_e124] = _e200;
                        let _e201 = local_26;
                        local_30 = bitcast<u32>(_e201);
                        let _e203 = local_17;
                        if _e203 {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e204 = local_30;
                        global_5.member[_e132] = _e204;
                        let _e205 = local_27;
                        local_31 = bitcast<u32>(_e205);
                        let _e207 = local_19;
                        if _e207 {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e208 = local_31;
                        global_5.member[_e140] = _e208;
                        let _e209 = local_28;
                        local_32 = bitcast<u32>(_e209);
                        let _e211 = local_21;
                        if _e211 {
                        } else {
                            phi_375_ = true;
                            break;
                        }
                        let _e212 = local_32;
                        global_5.member[_e148] = _e212;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e213 = local_5;
                    let _e214 = local_4;
                    phi_95_ = (_e213 + _e214);
                } else {
                    phi_95_ = u32();
                }
                let _e217 = phi_95_;
                continue;
                continuing {
                    let _e218 = local_6;
                    phi_94_ = _e217;
                    phi_375_ = false;
                    break if !(_e218);
                }
            }
            let _e221 = phi_375_;
            if _e221 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn layered_composite(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
