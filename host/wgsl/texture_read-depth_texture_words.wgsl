struct type_6 {
    member: array<u32>,
}

struct type_12 {
    member: u32,
    member_1: u32,
    member_2: u32,
}

struct type_13 {
    member: type_12,
}

var<private> global: vec3<u32>;
var<private> global_1: vec3<u32>;
var<private> global_2: u32;
var<immediate> global_3: type_13;
@group(0) @binding(1) 
var<storage, read_write> global_4: type_6;
@group(0) @binding(0) 
var global_5: texture_depth_2d;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: bool;
    var local_6: bool;
    var local_7: i32;
    var local_8: u32;
    var local_9: u32;
    var phi_59_: u32;
    var phi_60_: u32;
    var phi_113_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e24 = global;
            let _e25 = global_1;
            let _e26 = global_2;
            local = arrayLength((&global_4.member));
            let _e31 = global_3.member.member;
            local_1 = _e31;
            let _e34 = global_3.member.member_1;
            local_2 = (_e31 * _e34);
            local_3 = (_e25.x * 64u);
            phi_59_ = ((_e24.x * 64u) + _e26);
            loop {
                let _e42 = phi_59_;
                local_4 = _e42;
                let _e43 = local_4;
                let _e44 = local_2;
                let _e45 = (_e43 < _e44);
                local_5 = _e45;
                if _e45 {
                    let _e46 = local_1;
                    let _e47 = (_e46 == 0u);
                    local_6 = _e47;
                    if _e47 {
                        phi_113_ = true;
                        break;
                    }
                    let _e48 = local_4;
                    let _e49 = local_1;
                    local_7 = bitcast<i32>((_e48 % _e49));
                    let _e52 = local_6;
                    if _e52 {
                        phi_113_ = true;
                        break;
                    }
                    let _e53 = local_4;
                    let _e54 = local_1;
                    let _e57 = local_7;
                    let _e59 = textureLoad(global_5, vec2<i32>(_e57, bitcast<i32>((_e53 / _e54))), 0u);
                    local_8 = bitcast<u32>(vec4(_e59).x);
                    let _e65 = global_3.member.member_2;
                    let _e66 = local_4;
                    let _e67 = (_e65 + _e66);
                    local_9 = _e67;
                    let _e68 = local;
                    if (_e67 < _e68) {
                    } else {
                        phi_113_ = true;
                        break;
                    }
                    let _e70 = local_9;
                    let _e73 = local_8;
                    global_4.member[_e70] = _e73;
                    let _e74 = local_4;
                    let _e75 = local_3;
                    phi_60_ = (_e74 + _e75);
                } else {
                    phi_60_ = u32();
                }
                let _e78 = phi_60_;
                continue;
                continuing {
                    let _e79 = local_5;
                    phi_59_ = _e78;
                    phi_113_ = false;
                    break if !(_e79);
                }
            }
            let _e82 = phi_113_;
            if _e82 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn depth_texture_words(@builtin(workgroup_id) param: vec3<u32>, @builtin(num_workgroups) param_1: vec3<u32>, @builtin(local_invocation_index) param_2: u32) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
