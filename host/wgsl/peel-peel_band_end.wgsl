struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_16 {
    member: array<array<f32, 4>, 5>,
    member_1: array<f32, 3>,
    member_2: u32,
    member_3: array<f32, 3>,
    member_4: u32,
    member_5: type_5,
}

struct type_17 {
    member: type_16,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_17;
@group(0) @binding(0) 
var<storage, read_write> global_4: type_7;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: bool;
    var local_5: bool;
    var local_6: f32;
    var local_7: u32;
    var local_8: bool;
    var local_9: u32;
    var local_10: f32;
    var phi_80_: u32;
    var phi_212_: u32;
    var phi_213_: u32;
    var phi_81_: u32;
    var phi_288_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e37 = global;
            local = _e37;
            let _e38 = global_1;
            let _e39 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = (_e39.x * 64u);
            phi_80_ = (_e38.x * 64u);
            loop {
                let _e47 = phi_80_;
                local_3 = _e47;
                let _e48 = local_3;
                let _e49 = (_e48 < 1u);
                local_4 = _e49;
                if _e49 {
                    let _e50 = local_3;
                    let _e51 = local;
                    if ((_e50 + _e51) < 1u) {
                        let _e54 = local_1;
                        let _e55 = (0u < _e54);
                        local_5 = _e55;
                        if _e55 {
                        } else {
                            phi_288_ = true;
                            break;
                        }
                        let _e58 = global_4.member[0u];
                        let _e59 = bitcast<f32>(_e58);
                        let _e63 = global_3.member.member_5.member_1;
                        let _e68 = global_3.member.member_5.member;
                        let _e73 = global_3.member.member_5.member_2;
                        let _e79 = global_3.member.member_5.member_3;
                        let _e81 = (0.5f * ((((2f * _e63) * _e68) / (_e73 - _e68)) * _e79));
                        let _e85 = select(_e81, 0f, ((bitcast<u32>(_e81) & 2147483647u) > 2139095040u));
                        let _e87 = select(_e85, _e59, (_e59 > _e85));
                        local_10 = _e87;
                        if ((bitcast<u32>(_e87) & 2147483647u) > 2139095040u) {
                            phi_213_ = 96u;
                        } else {
                            let _e91 = local_10;
                            let _e93 = local_10;
                            let _e95 = ceil(select(0f, _e93, (_e91 > 0f)));
                            local_6 = _e95;
                            if (_e95 >= 96f) {
                                phi_212_ = 96u;
                            } else {
                                let _e97 = local_6;
                                let _e99 = local_6;
                                let _e102 = local_6;
                                phi_212_ = select(select(u32(_e97), 0u, !((_e99 >= 0f))), 4294967295u, (_e102 > 4294967000f));
                            }
                            let _e107 = phi_212_;
                            phi_213_ = _e107;
                        }
                        let _e109 = phi_213_;
                        local_7 = _e109;
                        let _e110 = local_1;
                        if (1u < _e110) {
                        } else {
                            phi_288_ = true;
                            break;
                        }
                        let _e114 = local_7;
                        global_4.member[1u] = _e114;
                        let _e117 = global_3.member.member_4;
                        let _e118 = local_7;
                        if (_e118 > _e117) {
                            let _e120 = local_1;
                            let _e121 = (2u < _e120);
                            local_8 = _e121;
                            if _e121 {
                            } else {
                                phi_288_ = true;
                                break;
                            }
                            let _e124 = global_4.member[2u];
                            local_9 = (_e124 + 1u);
                            let _e126 = local_8;
                            if _e126 {
                            } else {
                                phi_288_ = true;
                                break;
                            }
                            let _e127 = local_9;
                            global_4.member[2u] = _e127;
                        }
                        let _e128 = local_5;
                        if _e128 {
                        } else {
                            phi_288_ = true;
                            break;
                        }
                        global_4.member[0u] = 0u;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e129 = local_3;
                    let _e130 = local_2;
                    phi_81_ = (_e129 + _e130);
                } else {
                    phi_81_ = u32();
                }
                let _e133 = phi_81_;
                continue;
                continuing {
                    let _e134 = local_4;
                    phi_80_ = _e133;
                    phi_288_ = false;
                    break if !(_e134);
                }
            }
            let _e137 = phi_288_;
            if _e137 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn peel_band_end(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
