struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_14 {
    member: type_5,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: array<u32, 2>,
}

struct type_15 {
    member: type_14,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_15;
@group(0) @binding(0) 
var<storage, read_write> global_4: type_7;
@group(0) @binding(1) 
var<storage, read_write> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: bool;
    var local_7: bool;
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: bool;
    var local_12: u32;
    var local_13: bool;
    var local_14: u32;
    var local_15: u32;
    var local_16: array<u32, 12>;
    var phi_263_: bool;
    var phi_82_: u32;
    var phi_177_: u32;
    var phi_178_: u32;
    var phi_256_: bool;
    var phi_267_: bool;
    var phi_266_: bool;
    var phi_265_: bool;
    var phi_83_: u32;
    var phi_264_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e43 = global;
            local = _e43;
            let _e44 = global_1;
            let _e45 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = (_e45.x * 64u);
            phi_263_ = false;
            phi_82_ = (_e44.x * 64u);
            loop {
                let _e57 = phi_263_;
                let _e59 = phi_82_;
                local_5 = _e59;
                let _e60 = local_5;
                let _e61 = (_e60 < 1u);
                local_6 = _e61;
                if _e61 {
                    let _e62 = local_5;
                    let _e63 = local;
                    if ((_e62 + _e63) < 1u) {
                        let _e66 = local_1;
                        let _e67 = (0u < _e66);
                        local_7 = _e67;
                        if _e67 {
                        } else {
                            phi_264_ = true;
                            break;
                        }
                        let _e70 = global_4.member[0u];
                        local_8 = _e70;
                        let _e73 = global_3.member.member_4;
                        local_9 = _e73;
                        if (_e73 > 0u) {
                            let _e77 = global_3.member.member_10;
                            let _e78 = local_9;
                            let _e80 = ((_e77 + _e78) - 1u);
                            local_10 = _e80;
                            let _e81 = local_3;
                            if (_e80 < _e81) {
                            } else {
                                phi_264_ = true;
                                break;
                            }
                            let _e83 = local_10;
                            let _e86 = local_8;
                            global_6.member[_e83] = _e86;
                        }
                        let _e89 = global_3.member.member_10;
                        let _e90 = local_9;
                        if (_e90 < _e89) {
                            let _e92 = local_8;
                            let _e93 = (_e92 != 0u);
                            local_11 = _e93;
                            let _e96 = global_3.member.member_7;
                            let _e100 = global_3.member.member_8;
                            let _e104 = global_3.member.member_9;
                            local_16[0u] = select(0u, _e96, _e93);
                            local_16[1u] = 1u;
                            local_16[2u] = 0u;
                            local_16[3u] = 0u;
                            local_16[4u] = select(0u, _e100, _e93);
                            local_16[5u] = 1u;
                            local_16[6u] = 1u;
                            local_16[7u] = 0u;
                            local_16[8u] = select(0u, _e104, _e93);
                            local_16[9u] = 1u;
                            local_16[10u] = 1u;
                            local_16[11u] = 0u;
                            phi_177_ = 0u;
                            loop {
                                let _e119 = phi_177_;
                                local_12 = _e119;
                                let _e120 = local_12;
                                let _e121 = (_e120 < 12u);
                                local_13 = _e121;
                                if _e121 {
                                    let _e122 = local_13;
                                    if _e122 {
                                    } else {
                                        phi_256_ = true;
                                        break;
                                    }
                                    let _e123 = local_12;
                                    let _e125 = local_16[_e123];
                                    local_14 = _e125;
                                    let _e126 = local_12;
                                    let _e127 = local_2;
                                    if (_e126 < _e127) {
                                    } else {
                                        phi_256_ = true;
                                        break;
                                    }
                                    let _e129 = local_12;
                                    let _e132 = local_14;
                                    global_5.member[_e129] = _e132;
                                    let _e133 = local_12;
                                    phi_178_ = (_e133 + 1u);
                                } else {
                                    phi_178_ = u32();
                                }
                                let _e136 = phi_178_;
                                continue;
                                continuing {
                                    let _e137 = local_13;
                                    phi_177_ = _e136;
                                    phi_256_ = _e57;
                                    break if !(_e137);
                                }
                            }
                            let _e140 = phi_256_;
                            phi_264_ = _e140;
                            if _e140 {
                                break;
                            }
                            let _e141 = local_11;
                            local_15 = select(0u, 1u, _e141);
                            let _e143 = local_9;
                            let _e144 = local_3;
                            if (_e143 < _e144) {
                            } else {
                                phi_264_ = true;
                                break;
                            }
                            let _e146 = local_9;
                            let _e149 = local_15;
                            global_6.member[_e146] = _e149;
                            phi_267_ = _e140;
                        } else {
                            phi_267_ = _e57;
                        }
                        let _e151 = phi_267_;
                        let _e152 = local_7;
                        if _e152 {
                        } else {
                            phi_264_ = true;
                            break;
                        }
                        global_4.member[0u] = 0u;
                        phi_266_ = _e151;
                    } else {
                        phi_266_ = _e57;
                    }
                    let _e154 = phi_266_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e155 = local_5;
                    let _e156 = local_4;
                    phi_265_ = _e154;
                    phi_83_ = (_e155 + _e156);
                } else {
                    phi_265_ = _e57;
                    phi_83_ = u32();
                }
                let _e159 = phi_265_;
                let _e161 = phi_83_;
                continue;
                continuing {
                    let _e162 = local_6;
                    phi_263_ = _e159;
                    phi_82_ = _e161;
                    phi_264_ = _e159;
                    break if !(_e162);
                }
            }
            let _e165 = phi_264_;
            if _e165 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn peel_plan(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
