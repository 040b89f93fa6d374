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
var global_5: texture_storage_2d<rgba32float,write>;

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
    var local_10: u32;
    var local_11: u32;
    var local_12: f32;
    var local_13: u32;
    var local_14: f32;
    var local_15: u32;
    var local_16: bool;
    var phi_158_: bool;
    var phi_65_: u32;
    var phi_76_: u32;
    var phi_137_: u32;
    var phi_77_: u32;
    var phi_138_: bool;
    var phi_154_: bool;
    var phi_160_: bool;
    var phi_66_: u32;
    var phi_159_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e33 = global;
            local = _e33;
            let _e34 = global_1;
            let _e35 = global_2;
            local_1 = arrayLength((&global_3.member));
            let _e42 = global_4.member.member;
            local_2 = _e42;
            let _e45 = global_4.member.member_1;
            local_3 = (_e42 * _e45);
            local_4 = (_e35.x * 256u);
            local_5 = (_e33 + 1u);
            phi_158_ = false;
            phi_65_ = (_e34.x * 256u);
            loop {
                let _e51 = phi_158_;
                let _e53 = phi_65_;
                local_6 = _e53;
                let _e54 = local_6;
                let _e55 = local_3;
                let _e56 = (_e54 < _e55);
                local_7 = _e56;
                if _e56 {
                    let _e57 = local_6;
                    let _e58 = local;
                    phi_76_ = (_e57 + _e58);
                    loop {
                        let _e61 = phi_76_;
                        local_8 = _e61;
                        let _e62 = local_8;
                        let _e63 = local_3;
                        if (_e62 < _e63) {
                            let _e65 = local_6;
                            let _e66 = local_5;
                            let _e68 = local_8;
                            let _e69 = (_e68 < (_e65 + _e66));
                            if _e69 {
                                let _e70 = local_2;
                                if (_e70 == 0u) {
                                    phi_154_ = true;
                                    break;
                                }
                                let _e72 = local_8;
                                let _e73 = local_2;
                                let _e74 = (_e72 / _e73);
                                local_9 = _e74;
                                let _e75 = local_2;
                                let _e77 = local_8;
                                local_10 = (_e77 - (_e74 * _e75));
                                let _e79 = local_8;
                                let _e80 = (3u * _e79);
                                local_11 = _e80;
                                let _e81 = local_1;
                                if (_e80 < _e81) {
                                } else {
                                    phi_154_ = true;
                                    break;
                                }
                                let _e83 = local_11;
                                let _e86 = global_3.member[_e83];
                                local_12 = bitcast<f32>(_e86);
                                let _e88 = local_11;
                                let _e89 = (_e88 + 1u);
                                local_13 = _e89;
                                let _e90 = local_1;
                                if (_e89 < _e90) {
                                } else {
                                    phi_154_ = true;
                                    break;
                                }
                                let _e92 = local_13;
                                let _e95 = global_3.member[_e92];
                                local_14 = bitcast<f32>(_e95);
                                let _e97 = local_11;
                                let _e98 = (_e97 + 2u);
                                local_15 = _e98;
                                let _e99 = local_1;
                                if (_e98 < _e99) {
                                } else {
                                    phi_154_ = true;
                                    break;
                                }
                                let _e101 = local_15;
                                let _e104 = global_3.member[_e101];
                                let _e106 = local_10;
                                let _e108 = local_9;
                                let _e110 = local_12;
                                let _e111 = local_14;
                                textureStore(global_5, vec2<i32>(bitcast<i32>(_e106), bitcast<i32>(_e108)), vec4<f32>(_e110, _e111, bitcast<f32>(_e104), 1f));
                                let _e114 = local_8;
                                phi_137_ = (_e114 + 1u);
                            } else {
                                phi_137_ = u32();
                            }
                            let _e117 = phi_137_;
                            phi_77_ = _e117;
                            phi_138_ = _e69;
                        } else {
                            phi_77_ = u32();
                            phi_138_ = false;
                        }
                        let _e119 = phi_77_;
                        let _e121 = phi_138_;
                        local_16 = _e121;
                        continue;
                        continuing {
                            let _e122 = local_16;
                            phi_76_ = _e119;
                            phi_154_ = _e51;
                            break if !(_e122);
                        }
                    }
                    let _e125 = phi_154_;
                    phi_159_ = _e125;
                    if _e125 {
                        break;
                    }
                    let _e126 = local_6;
                    let _e127 = local_4;
                    phi_160_ = _e125;
                    phi_66_ = (_e126 + _e127);
                } else {
                    phi_160_ = _e51;
                    phi_66_ = u32();
                }
                let _e130 = phi_160_;
                let _e132 = phi_66_;
                continue;
                continuing {
                    let _e133 = local_7;
                    phi_158_ = _e130;
                    phi_65_ = _e132;
                    phi_159_ = _e130;
                    break if !(_e133);
                }
            }
            let _e136 = phi_159_;
            if _e136 {
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
