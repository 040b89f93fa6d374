struct type_3 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_5 {
    member: array<u32>,
}

struct type_12 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
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
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: f32,
    member_12: f32,
    member_13: f32,
    member_14: f32,
    member_15: type_3,
    member_16: type_12,
    member_17: u32,
    member_18: u32,
}

struct type_14 {
    member: type_13,
}

var<private> global: u32;
var<immediate> global_1: type_14;
@group(0) @binding(0) 
var<storage, read_write> global_2: type_5;

fn function_() {
    var local: u32;
    var local_1: f32;
    var local_2: f32;
    var local_3: u32;
    var local_4: u32;
    var local_5: bool;
    var local_6: u32;
    var local_7: f32;
    var local_8: f32;
    var phi_81_: f32;
    var phi_97_: u32;
    var phi_113_: u32;
    var phi_98_: u32;
    var phi_114_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e30 = global;
            local = arrayLength((&global_2.member));
            if (_e30 == 0u) {
                let _e34 = local;
                if (17u < _e34) {
                } else {
                    break;
                }
                let _e38 = global_2.member[17u];
                let _e39 = bitcast<f32>(_e38);
                local_1 = _e39;
                let _e42 = global_1.member.member_10;
                if (((_e42 >> bitcast<u32>(8u)) & 7u) > 0u) {
                    let _e47 = local_1;
                    phi_81_ = (_e47 + 0.91421354f);
                } else {
                    phi_81_ = _e39;
                }
                let _e50 = phi_81_;
                let _e53 = global_1.member.member_3;
                let _e56 = global_1.member.member_11;
                local_2 = _e56;
                let _e59 = global_1.member.member_6;
                local_3 = _e59;
                let _e62 = (_e50 + (0.5f * f32(_e53)));
                local_7 = select(_e56, _e62, (_e62 < _e56));
                phi_97_ = 1u;
                loop {
                    let _e66 = phi_97_;
                    local_4 = _e66;
                    let _e67 = local_4;
                    if (_e67 < 6u) {
                        let _e69 = local_4;
                        let _e70 = local_3;
                        let _e73 = local_7;
                        let _e74 = (f32((_e69 * _e70)) < _e73);
                        if _e74 {
                            let _e75 = local_4;
                            phi_113_ = (_e75 + 1u);
                        } else {
                            phi_113_ = u32();
                        }
                        let _e78 = phi_113_;
                        phi_98_ = _e78;
                        phi_114_ = _e74;
                    } else {
                        phi_98_ = u32();
                        phi_114_ = false;
                    }
                    let _e80 = phi_98_;
                    let _e82 = phi_114_;
                    local_5 = _e82;
                    continue;
                    continuing {
                        let _e83 = local_5;
                        phi_97_ = _e80;
                        break if !(_e83);
                    }
                }
                let _e85 = local_4;
                let _e86 = local_3;
                let _e88 = f32((_e85 * _e86));
                let _e89 = local_2;
                let _e91 = local_2;
                local_8 = select(_e88, _e91, (_e89 < _e88));
                let _e93 = local;
                if (18u < _e93) {
                } else {
                    break;
                }
                let _e97 = local_4;
                global_2.member[18u] = _e97;
                let _e98 = local_8;
                local_6 = bitcast<u32>(_e98);
                let _e100 = local;
                if (19u < _e100) {
                } else {
                    break;
                }
                let _e104 = local_6;
                global_2.member[19u] = _e104;
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn splat_plan_finish(@builtin(local_invocation_index) param: u32) {
    global = param;
    function_();
}
