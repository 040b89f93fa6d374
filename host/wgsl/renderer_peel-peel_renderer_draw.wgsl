struct type_5 {
    member: array<u32>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_5;
@group(0) @binding(1) 
var<storage, read_write> global_4: type_5;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: bool;
    var local_6: u32;
    var local_7: bool;
    var local_8: u32;
    var phi_140_: bool;
    var phi_54_: u32;
    var phi_69_: u32;
    var phi_70_: u32;
    var phi_137_: bool;
    var phi_143_: bool;
    var phi_142_: bool;
    var phi_55_: u32;
    var phi_141_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e24 = global;
            local = _e24;
            let _e25 = global_1;
            let _e26 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = (_e26.x * 64u);
            phi_140_ = false;
            phi_54_ = (_e25.x * 64u);
            loop {
                let _e36 = phi_140_;
                let _e38 = phi_54_;
                local_4 = _e38;
                let _e39 = local_4;
                let _e40 = (_e39 < 1u);
                local_5 = _e40;
                if _e40 {
                    let _e41 = local_4;
                    let _e42 = local;
                    if ((_e41 + _e42) < 1u) {
                        phi_69_ = 0u;
                        loop {
                            let _e46 = phi_69_;
                            local_6 = _e46;
                            let _e47 = local_6;
                            let _e48 = (_e47 < 4u);
                            local_7 = _e48;
                            if _e48 {
                                let _e49 = local_6;
                                let _e50 = local_1;
                                if (_e49 < _e50) {
                                } else {
                                    phi_137_ = true;
                                    break;
                                }
                                let _e52 = local_6;
                                let _e55 = global_3.member[_e52];
                                local_8 = _e55;
                                let _e56 = local_6;
                                let _e57 = local_2;
                                if (_e56 < _e57) {
                                } else {
                                    phi_137_ = true;
                                    break;
                                }
                                let _e59 = local_6;
                                let _e62 = local_8;
                                global_4.member[_e59] = _e62;
                                let _e63 = local_6;
                                phi_70_ = (_e63 + 1u);
                            } else {
                                phi_70_ = u32();
                            }
                            let _e66 = phi_70_;
                            continue;
                            continuing {
                                let _e67 = local_7;
                                phi_69_ = _e66;
                                phi_137_ = _e36;
                                break if !(_e67);
                            }
                        }
                        let _e70 = phi_137_;
                        phi_141_ = _e70;
                        if _e70 {
                            break;
                        }
                        let _e71 = local_2;
                        if (4u < _e71) {
                        } else {
                            phi_141_ = true;
                            break;
                        }
                        global_4.member[4u] = 0u;
                        phi_143_ = _e70;
                    } else {
                        phi_143_ = _e36;
                    }
                    let _e76 = phi_143_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e77 = local_4;
                    let _e78 = local_3;
                    phi_142_ = _e76;
                    phi_55_ = (_e77 + _e78);
                } else {
                    phi_142_ = _e36;
                    phi_55_ = u32();
                }
                let _e81 = phi_142_;
                let _e83 = phi_55_;
                continue;
                continuing {
                    let _e84 = local_5;
                    phi_140_ = _e81;
                    phi_54_ = _e83;
                    phi_141_ = _e81;
                    break if !(_e84);
                }
            }
            let _e87 = phi_141_;
            if _e87 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn peel_renderer_draw(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
