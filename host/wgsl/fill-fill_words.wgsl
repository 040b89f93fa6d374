struct type_5 {
    member: array<u32>,
}

struct type_10 {
    member: u32,
    member_1: u32,
    member_2: u32,
}

struct type_11 {
    member: type_10,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_11;
@group(0) @binding(0) 
var<storage, read_write> global_4: type_5;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: bool;
    var local_4: u32;
    var local_5: u32;
    var phi_47_: u32;
    var phi_48_: u32;
    var phi_78_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e20 = global;
            let _e21 = global_1;
            let _e22 = global_2;
            local = arrayLength((&global_4.member));
            local_1 = (256u * _e22.x);
            phi_47_ = ((_e21.x * 256u) + _e20);
            loop {
                let _e31 = phi_47_;
                local_2 = _e31;
                let _e34 = global_3.member.member_1;
                let _e35 = local_2;
                let _e36 = (_e35 < _e34);
                local_3 = _e36;
                if _e36 {
                    let _e39 = global_3.member.member;
                    let _e40 = local_2;
                    let _e41 = (_e39 + _e40);
                    local_4 = _e41;
                    let _e44 = global_3.member.member_2;
                    local_5 = _e44;
                    let _e45 = local;
                    if (_e41 < _e45) {
                    } else {
                        phi_78_ = true;
                        break;
                    }
                    let _e47 = local_4;
                    let _e50 = local_5;
                    global_4.member[_e47] = _e50;
                    let _e51 = local_2;
                    let _e52 = local_1;
                    phi_48_ = (_e51 + _e52);
                } else {
                    phi_48_ = u32();
                }
                let _e55 = phi_48_;
                continue;
                continuing {
                    let _e56 = local_3;
                    phi_47_ = _e55;
                    phi_78_ = false;
                    break if !(_e56);
                }
            }
            let _e59 = phi_78_;
            if _e59 {
                break;
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn fill_words(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
