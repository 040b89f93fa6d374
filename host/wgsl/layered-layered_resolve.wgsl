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
var<immediate> global_3: type_14;
@group(0) @binding(0) 
var<storage> global_4: type_6;
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
    var local_15: f32;
    var local_16: f32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var phi_74_: u32;
    var phi_165_: f32;
    var phi_75_: u32;
    var phi_232_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e43 = global;
            local = _e43;
            let _e44 = global_1;
            let _e45 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            let _e54 = global_3.member.member;
            let _e57 = global_3.member.member_1;
            local_3 = (_e54 * _e57);
            local_4 = (_e45.x * 256u);
            phi_74_ = (_e44.x * 256u);
            loop {
                let _e62 = phi_74_;
                local_5 = _e62;
                let _e63 = local_5;
                let _e64 = local_3;
                let _e65 = (_e63 < _e64);
                local_6 = _e65;
                if _e65 {
                    let _e66 = local_5;
                    let _e67 = local;
                    let _e68 = (_e66 + _e67);
                    local_7 = _e68;
                    let _e69 = local_3;
                    if (_e68 < _e69) {
                        let _e71 = local_7;
                        let _e72 = (4u * _e71);
                        local_8 = _e72;
                        let _e73 = local_1;
                        if (_e72 < _e73) {
                        } else {
                            phi_232_ = true;
                            break;
                        }
                        let _e75 = local_8;
                        let _e78 = global_4.member[_e75];
                        local_9 = bitcast<f32>(_e78);
                        let _e80 = local_8;
                        let _e81 = (_e80 + 1u);
                        local_10 = _e81;
                        let _e82 = local_1;
                        if (_e81 < _e82) {
                        } else {
                            phi_232_ = true;
                            break;
                        }
                        let _e84 = local_10;
                        let _e87 = global_4.member[_e84];
                        local_11 = bitcast<f32>(_e87);
                        let _e89 = local_8;
                        let _e90 = (_e89 + 2u);
                        local_12 = _e90;
                        let _e91 = local_1;
                        if (_e90 < _e91) {
                        } else {
                            phi_232_ = true;
                            break;
                        }
                        let _e93 = local_12;
                        let _e96 = global_4.member[_e93];
                        local_13 = bitcast<f32>(_e96);
                        let _e98 = local_8;
                        let _e99 = (_e98 + 3u);
                        local_14 = _e99;
                        let _e100 = local_1;
                        if (_e99 < _e100) {
                        } else {
                            phi_232_ = true;
                            break;
                        }
                        let _e102 = local_14;
                        let _e105 = global_4.member[_e102];
                        let _e106 = bitcast<f32>(_e105);
                        local_15 = _e106;
                        if (_e106 > 0.000001f) {
                            let _e108 = local_15;
                            phi_165_ = (1f / _e108);
                        } else {
                            phi_165_ = 0f;
                        }
                        let _e111 = phi_165_;
                        local_16 = _e111;
                        let _e112 = local_7;
                        let _e113 = (3u * _e112);
                        local_17 = _e113;
                        let _e114 = local_9;
                        local_18 = bitcast<u32>((_e114 * _e111));
                        let _e117 = local_2;
                        if (_e113 < _e117) {
                        } else {
                            phi_232_ = true;
                            break;
                        }
                        let _e119 = local_17;
                        let _e122 = local_18;
                        global_5.member[_e119] = _e122;
                        let _e123 = local_17;
                        let _e124 = (_e123 + 1u);
                        local_19 = _e124;
                        let _e125 = local_11;
                        let _e126 = local_16;
                        local_20 = bitcast<u32>((_e125 * _e126));
                        let _e129 = local_2;
                        if (_e124 < _e129) {
                        } else {
                            phi_232_ = true;
                            break;
                        }
                        let _e131 = local_19;
                        let _e134 = local_20;
                        global_5.member[_e131] = _e134;
                        let _e135 = local_17;
                        let _e136 = (_e135 + 2u);
                        local_21 = _e136;
                        let _e137 = local_13;
                        let _e138 = local_16;
                        local_22 = bitcast<u32>((_e137 * _e138));
                        let _e141 = local_2;
                        if (_e136 < _e141) {
                        } else {
                            phi_232_ = true;
                            break;
                        }
                        let _e143 = local_21;
                        let _e146 = local_22;
                        global_5.member[_e143] = _e146;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e147 = local_5;
                    let _e148 = local_4;
                    phi_75_ = (_e147 + _e148);
                } else {
                    phi_75_ = u32();
                }
                let _e151 = phi_75_;
                continue;
                continuing {
                    let _e152 = local_6;
                    phi_74_ = _e151;
                    phi_232_ = false;
                    break if !(_e152);
                }
            }
            let _e155 = phi_232_;
            if _e155 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn layered_resolve(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
