struct type_6 {
    member: array<u32>,
}

struct type_14 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_15 {
    member: type_14,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_6;
var<immediate> global_4: type_15;
@group(0) @binding(1) 
var global_5: texture_storage_2d<rgba32float,read_write>;

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
    var local_9: bool;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: f32;
    var local_14: u32;
    var local_15: f32;
    var local_16: u32;
    var local_17: bool;
    var phi_161_: bool;
    var phi_65_: u32;
    var phi_76_: u32;
    var phi_140_: u32;
    var phi_77_: u32;
    var phi_141_: bool;
    var phi_157_: bool;
    var phi_163_: bool;
    var phi_66_: u32;
    var phi_162_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e34 = global;
            local = _e34;
            let _e35 = global_1;
            let _e36 = global_2;
            local_1 = arrayLength((&global_3.member));
            let _e43 = global_4.member.member;
            local_2 = _e43;
            let _e46 = global_4.member.member_1;
            local_3 = (_e43 * _e46);
            local_4 = (_e36.x * 256u);
            local_5 = (_e34 + 1u);
            phi_161_ = false;
            phi_65_ = (_e35.x * 256u);
            loop {
                let _e52 = phi_161_;
                let _e54 = phi_65_;
                local_6 = _e54;
                let _e55 = local_6;
                let _e56 = local_3;
                let _e57 = (_e55 < _e56);
                local_7 = _e57;
                if _e57 {
                    let _e58 = local_6;
                    let _e59 = local;
                    phi_76_ = (_e58 + _e59);
                    loop {
                        let _e62 = phi_76_;
                        local_8 = _e62;
                        let _e63 = local_8;
                        let _e64 = local_3;
                        if (_e63 < _e64) {
                            let _e66 = local_6;
                            let _e67 = local_5;
                            let _e69 = local_8;
                            let _e70 = (_e69 < (_e66 + _e67));
                            if _e70 {
                                let _e71 = local_2;
                                let _e72 = (_e71 == 0u);
                                local_9 = _e72;
                                if _e72 {
                                    phi_157_ = true;
                                    break;
                                }
                                let _e73 = local_8;
                                let _e74 = local_2;
                                local_10 = (_e73 % _e74);
                                let _e76 = local_9;
                                if _e76 {
                                    phi_157_ = true;
                                    break;
                                }
                                let _e77 = local_8;
                                let _e78 = local_2;
                                local_11 = (_e77 / _e78);
                                let _e80 = local_8;
                                let _e81 = (3u * _e80);
                                local_12 = _e81;
                                let _e82 = local_1;
                                if (_e81 < _e82) {
                                } else {
                                    phi_157_ = true;
                                    break;
                                }
                                let _e84 = local_12;
                                let _e87 = global_3.member[_e84];
                                local_13 = bitcast<f32>(_e87);
                                let _e89 = local_12;
                                let _e90 = (_e89 + 1u);
                                local_14 = _e90;
                                let _e91 = local_1;
                                if (_e90 < _e91) {
                                } else {
                                    phi_157_ = true;
                                    break;
                                }
                                let _e93 = local_14;
                                let _e96 = global_3.member[_e93];
                                local_15 = bitcast<f32>(_e96);
                                let _e98 = local_12;
                                let _e99 = (_e98 + 2u);
                                local_16 = _e99;
                                let _e100 = local_1;
                                if (_e99 < _e100) {
                                } else {
                                    phi_157_ = true;
                                    break;
                                }
                                let _e102 = local_16;
                                let _e105 = global_3.member[_e102];
                                let _e107 = local_10;
                                let _e109 = local_11;
                                let _e111 = local_13;
                                let _e112 = local_15;
                                textureStore(global_5, vec2<i32>(bitcast<i32>(_e107), bitcast<i32>(_e109)), vec4<f32>(_e111, _e112, bitcast<f32>(_e105), 1f));
                                let _e115 = local_8;
                                phi_140_ = (_e115 + 1u);
                            } else {
                                phi_140_ = u32();
                            }
                            let _e118 = phi_140_;
                            phi_77_ = _e118;
                            phi_141_ = _e70;
                        } else {
                            phi_77_ = u32();
                            phi_141_ = false;
                        }
                        let _e120 = phi_77_;
                        let _e122 = phi_141_;
                        local_17 = _e122;
                        continue;
                        continuing {
                            let _e123 = local_17;
                            phi_76_ = _e120;
                            phi_157_ = _e52;
                            break if !(_e123);
                        }
                    }
                    let _e126 = phi_157_;
                    phi_162_ = _e126;
                    if _e126 {
                        break;
                    }
                    let _e127 = local_6;
                    let _e128 = local_4;
                    phi_163_ = _e126;
                    phi_66_ = (_e127 + _e128);
                } else {
                    phi_163_ = _e52;
                    phi_66_ = u32();
                }
                let _e131 = phi_163_;
                let _e133 = phi_66_;
                continue;
                continuing {
                    let _e134 = local_7;
                    phi_161_ = _e131;
                    phi_65_ = _e133;
                    phi_162_ = _e131;
                    break if !(_e134);
                }
            }
            let _e137 = phi_162_;
            if _e137 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn frame_to_rgba32f_image(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
