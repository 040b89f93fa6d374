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
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: f32,
    member_6: array<u32, 2>,
    member_7: type_3,
}

struct type_13 {
    member: type_12,
}

struct type_15 {
    member: f32,
    member_1: f32,
}

var<private> global: u32;
@group(0) @binding(0) 
var<storage, read_write> global_1: type_5;
var<immediate> global_2: type_13;
var<private> global_3: u32 = 2143289344u;
var<private> global_4: u32 = 2139095040u;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: bool;
    var local_5: u32;
    var local_6: f32;
    var local_7: f32;
    var local_8: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: f32;
    var local_12: f32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: f32;
    var phi_70_: u32;
    var phi_111_: f32;
    var phi_144_: f32;
    var phi_152_: f32;
    var phi_155_: type_15;
    var phi_157_: type_15;
    var phi_71_: u32;
    var phi_263_: bool;

    let _e48 = global_3;
    let _e49 = bitcast<f32>(_e48);
    let _e50 = global_4;
    let _e51 = bitcast<f32>(_e50);
    local_18 = _e51;
    switch bitcast<i32>(0u) {
        default: {
            let _e55 = global;
            local = _e55;
            local_1 = arrayLength((&global_1.member));
            let _e60 = global_2.member.member_3;
            local_2 = _e60;
            phi_70_ = _e55;
            loop {
                let _e62 = phi_70_;
                local_3 = _e62;
                let _e63 = local_3;
                let _e64 = (_e63 < 128u);
                local_4 = _e64;
                if _e64 {
                    let _e65 = local_3;
                    let _e66 = (_e65 + 1u);
                    local_5 = _e66;
                    let _e67 = local_2;
                    if (_e66 < _e67) {
                        let _e69 = local_3;
                        let _e70 = local_1;
                        if (_e69 < _e70) {
                        } else {
                            phi_263_ = true;
                            break;
                        }
                        let _e72 = local_3;
                        let _e75 = global_1.member[_e72];
                        local_6 = bitcast<f32>(_e75);
                        let _e77 = local_5;
                        let _e78 = local_1;
                        if (_e77 < _e78) {
                        } else {
                            phi_263_ = true;
                            break;
                        }
                        let _e80 = local_5;
                        let _e83 = global_1.member[_e80];
                        let _e85 = local_6;
                        let _e86 = (_e85 + bitcast<f32>(_e83));
                        local_7 = _e86;
                        let _e87 = (0.5f * _e86);
                        let _e88 = (_e87 < 0f);
                        local_8 = _e88;
                        if _e88 {
                            let _e89 = local_7;
                            phi_111_ = (_e89 * -0.5f);
                        } else {
                            phi_111_ = _e87;
                        }
                        let _e92 = phi_111_;
                        local_9 = _e92;
                        if (_e92 >= 0f) {
                            let _e97 = global_2.member.member_7.member_1;
                            let _e102 = global_2.member.member_7.member;
                            let _e107 = global_2.member.member_7.member_2;
                            local_10 = _e107;
                            let _e113 = global_2.member.member_7.member_3;
                            let _e114 = ((((2f * _e97) * _e102) / (_e107 - _e102)) * _e113);
                            local_11 = _e114;
                            if (_e114 > 0f) {
                                let _e116 = local_9;
                                let _e117 = local_18;
                                if (_e116 == _e117) {
                                    phi_144_ = 0f;
                                } else {
                                    let _e119 = local_10;
                                    let _e120 = local_11;
                                    let _e122 = local_11;
                                    let _e123 = local_9;
                                    phi_144_ = ((_e119 * _e120) / (_e122 + _e123));
                                }
                                let _e127 = phi_144_;
                                local_12 = _e127;
                                let _e128 = local_9;
                                let _e129 = local_11;
                                if (_e128 >= _e129) {
                                    phi_152_ = _e51;
                                } else {
                                    let _e131 = local_10;
                                    let _e132 = local_11;
                                    let _e134 = local_11;
                                    let _e135 = local_9;
                                    phi_152_ = ((_e131 * _e132) / (_e134 - _e135));
                                }
                                let _e139 = phi_152_;
                                let _e140 = local_12;
                                phi_155_ = type_15(_e140, _e139);
                            } else {
                                phi_155_ = type_15(0f, _e51);
                            }
                            let _e143 = phi_155_;
                            phi_157_ = _e143;
                        } else {
                            phi_157_ = type_15(_e49, _e49);
                        }
                        let _e145 = phi_157_;
                        let _e148 = local_8;
                        let _e150 = local_3;
                        let _e151 = (128u + _e150);
                        local_13 = _e151;
                        local_14 = bitcast<u32>(select(_e145.member_1, _e145.member, _e148));
                        let _e153 = local_1;
                        if (_e151 < _e153) {
                        } else {
                            phi_263_ = true;
                            break;
                        }
                        let _e155 = local_13;
                        let _e158 = local_14;
                        global_1.member[_e155] = _e158;
                    }
                    let _e159 = local_3;
                    let _e160 = (256u + _e159);
                    local_15 = _e160;
                    let _e161 = local_1;
                    if (_e160 < _e161) {
                    } else {
                        phi_263_ = true;
                        break;
                    }
                    let _e163 = local_15;
                    global_1.member[_e163] = 0u;
                    let _e166 = local_3;
                    let _e167 = (384u + _e166);
                    local_16 = _e167;
                    let _e168 = local_1;
                    if (_e167 < _e168) {
                    } else {
                        phi_263_ = true;
                        break;
                    }
                    let _e170 = local_16;
                    global_1.member[_e170] = 0u;
                    let _e173 = local_3;
                    let _e174 = (512u + _e173);
                    local_17 = _e174;
                    let _e175 = local_1;
                    if (_e174 < _e175) {
                    } else {
                        phi_263_ = true;
                        break;
                    }
                    let _e177 = local_17;
                    global_1.member[_e177] = 0u;
                    let _e180 = local_3;
                    phi_71_ = (_e180 + 64u);
                } else {
                    phi_71_ = u32();
                }
                let _e183 = phi_71_;
                continue;
                continuing {
                    let _e184 = local_4;
                    phi_70_ = _e183;
                    phi_263_ = false;
                    break if !(_e184);
                }
            }
            let _e187 = phi_263_;
            if _e187 {
                break;
            }
            let _e188 = local;
            if (_e188 == 0u) {
                let _e190 = local_1;
                if (640u < _e190) {
                } else {
                    break;
                }
                global_1.member[640u] = 2147483648u;
                let _e194 = local_1;
                if (641u < _e194) {
                } else {
                    break;
                }
                global_1.member[641u] = 2147483648u;
                let _e198 = local_1;
                if (642u < _e198) {
                } else {
                    break;
                }
                global_1.member[642u] = 0u;
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn layered_plan_begin(@builtin(local_invocation_index) param: u32) {
    global = param;
    function_();
}
