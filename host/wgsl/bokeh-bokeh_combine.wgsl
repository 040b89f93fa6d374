struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_13 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_14 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: type_5,
    member_9: type_13,
}

struct type_15 {
    member: type_14,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_15;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;

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
    var local_10: bool;
    var local_11: u32;
    var local_12: f32;
    var local_13: u32;
    var local_14: u32;
    var phi_178_: bool;
    var phi_78_: u32;
    var phi_94_: u32;
    var phi_95_: u32;
    var phi_175_: bool;
    var phi_181_: bool;
    var phi_180_: bool;
    var phi_79_: u32;
    var phi_179_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e33 = global;
            local = _e33;
            let _e34 = global_1;
            let _e35 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            let _e46 = global_3.member.member;
            let _e49 = global_3.member.member_1;
            local_4 = (_e46 * _e49);
            local_5 = (_e35.x * 256u);
            phi_178_ = false;
            phi_78_ = (_e34.x * 256u);
            loop {
                let _e54 = phi_178_;
                let _e56 = phi_78_;
                local_6 = _e56;
                let _e57 = local_6;
                let _e58 = local_4;
                let _e59 = (_e57 < _e58);
                local_7 = _e59;
                if _e59 {
                    let _e60 = local_6;
                    let _e61 = local;
                    let _e62 = (_e60 + _e61);
                    local_8 = _e62;
                    let _e63 = local_4;
                    if (_e62 < _e63) {
                        phi_94_ = 0u;
                        loop {
                            let _e66 = phi_94_;
                            local_9 = _e66;
                            let _e67 = local_9;
                            let _e68 = (_e67 < 3u);
                            local_10 = _e68;
                            if _e68 {
                                let _e69 = local_8;
                                let _e71 = local_9;
                                let _e72 = ((3u * _e69) + _e71);
                                local_11 = _e72;
                                let _e73 = local_1;
                                if (_e72 < _e73) {
                                } else {
                                    phi_175_ = true;
                                    break;
                                }
                                let _e75 = local_11;
                                let _e78 = global_4.member[_e75];
                                local_12 = bitcast<f32>(_e78);
                                let _e80 = local_8;
                                let _e82 = local_9;
                                let _e83 = ((4u * _e80) + _e82);
                                local_13 = _e83;
                                let _e84 = local_2;
                                if (_e83 < _e84) {
                                } else {
                                    phi_175_ = true;
                                    break;
                                }
                                let _e86 = local_13;
                                let _e89 = global_5.member[_e86];
                                let _e91 = local_12;
                                local_14 = bitcast<u32>((_e91 + bitcast<f32>(_e89)));
                                let _e94 = local_11;
                                let _e95 = local_3;
                                if (_e94 < _e95) {
                                } else {
                                    phi_175_ = true;
                                    break;
                                }
                                let _e97 = local_11;
                                let _e100 = local_14;
                                global_6.member[_e97] = _e100;
                                let _e101 = local_9;
                                phi_95_ = (_e101 + 1u);
                            } else {
                                phi_95_ = u32();
                            }
                            let _e104 = phi_95_;
                            continue;
                            continuing {
                                let _e105 = local_10;
                                phi_94_ = _e104;
                                phi_175_ = _e54;
                                break if !(_e105);
                            }
                        }
                        let _e108 = phi_175_;
                        phi_179_ = _e108;
                        if _e108 {
                            break;
                        }
                        phi_181_ = _e108;
                    } else {
                        phi_181_ = _e54;
                    }
                    let _e110 = phi_181_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e111 = local_6;
                    let _e112 = local_5;
                    phi_180_ = _e110;
                    phi_79_ = (_e111 + _e112);
                } else {
                    phi_180_ = _e54;
                    phi_79_ = u32();
                }
                let _e115 = phi_180_;
                let _e117 = phi_79_;
                continue;
                continuing {
                    let _e118 = local_7;
                    phi_178_ = _e115;
                    phi_78_ = _e117;
                    phi_179_ = _e115;
                    break if !(_e118);
                }
            }
            let _e121 = phi_179_;
            if _e121 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn bokeh_combine(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
