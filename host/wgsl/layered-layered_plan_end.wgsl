struct type_3 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_5 {
    member: array<u32>,
}

struct type_11 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: f32,
    member_6: array<u32, 2>,
    member_7: type_3,
}

struct type_12 {
    member: type_11,
}

var<private> global: u32;
@group(0) @binding(0) 
var<storage, read_write> global_1: type_5;
var<immediate> global_2: type_12;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: bool;
    var local_5: u32;
    var local_6: u32;
    var local_7: u32;
    var local_8: u32;
    var local_9: bool;
    var local_10: u32;
    var local_11: u32;
    var phi_56_: u32;
    var phi_59_: u32;
    var phi_57_: u32;
    var phi_60_: u32;
    var phi_123_: bool;
    var phi_85_: u32;
    var phi_88_: u32;
    var phi_86_: u32;
    var phi_89_: u32;
    var phi_126_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e29 = global;
            local = arrayLength((&global_1.member));
            let _e34 = global_2.member.member_3;
            let _e37 = global_2.member.member_4;
            local_1 = _e37;
            if (_e29 == 0u) {
                phi_56_ = _e34;
                phi_59_ = 0u;
                loop {
                    let _e40 = phi_56_;
                    let _e42 = phi_59_;
                    local_2 = _e40;
                    local_3 = _e42;
                    let _e43 = local_2;
                    let _e44 = local_1;
                    let _e45 = (_e43 > _e44);
                    local_4 = _e45;
                    if _e45 {
                        let _e46 = local_2;
                        let _e48 = local_2;
                        let _e49 = (_e48 + 383u);
                        local_5 = _e49;
                        let _e50 = local;
                        if (_e49 < _e50) {
                        } else {
                            phi_123_ = true;
                            break;
                        }
                        let _e52 = local_5;
                        let _e55 = local_3;
                        global_1.member[_e52] = _e55;
                        let _e56 = local_2;
                        let _e57 = (_e56 + 255u);
                        local_6 = _e57;
                        let _e58 = local;
                        if (_e57 < _e58) {
                        } else {
                            phi_123_ = true;
                            break;
                        }
                        let _e60 = local_6;
                        let _e63 = global_1.member[_e60];
                        let _e64 = local_3;
                        phi_57_ = (_e46 - 1u);
                        phi_60_ = (_e64 | _e63);
                    } else {
                        phi_57_ = u32();
                        phi_60_ = u32();
                    }
                    let _e67 = phi_57_;
                    let _e69 = phi_60_;
                    continue;
                    continuing {
                        let _e70 = local_4;
                        phi_56_ = _e67;
                        phi_59_ = _e69;
                        phi_123_ = false;
                        break if !(_e70);
                    }
                }
                let _e73 = phi_123_;
                if _e73 {
                    break;
                }
                phi_85_ = 0u;
                phi_88_ = 0u;
                loop {
                    let _e75 = phi_85_;
                    let _e77 = phi_88_;
                    local_7 = _e75;
                    local_8 = _e77;
                    let _e78 = local_7;
                    let _e79 = local_1;
                    let _e80 = (_e78 <= _e79);
                    local_9 = _e80;
                    if _e80 {
                        let _e81 = local_7;
                        let _e82 = (512u + _e81);
                        local_10 = _e82;
                        let _e83 = local;
                        if (_e82 < _e83) {
                        } else {
                            phi_126_ = true;
                            break;
                        }
                        let _e85 = local_10;
                        let _e88 = local_8;
                        global_1.member[_e85] = _e88;
                        let _e89 = local_7;
                        let _e90 = (256u + _e89);
                        local_11 = _e90;
                        let _e91 = local;
                        if (_e90 < _e91) {
                        } else {
                            phi_126_ = true;
                            break;
                        }
                        let _e93 = local_11;
                        let _e96 = global_1.member[_e93];
                        let _e97 = local_8;
                        let _e99 = local_7;
                        phi_86_ = (_e99 + 1u);
                        phi_89_ = (_e97 | _e96);
                    } else {
                        phi_86_ = u32();
                        phi_89_ = u32();
                    }
                    let _e102 = phi_86_;
                    let _e104 = phi_89_;
                    continue;
                    continuing {
                        let _e105 = local_9;
                        phi_85_ = _e102;
                        phi_88_ = _e104;
                        phi_126_ = _e73;
                        break if !(_e105);
                    }
                }
                let _e108 = phi_126_;
                if _e108 {
                    break;
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
fn layered_plan_end(@builtin(local_invocation_index) param: u32) {
    global = param;
    function_();
}
