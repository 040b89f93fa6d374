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
@group(0) @binding(1) 
var<storage> global_4: type_7;
@group(0) @binding(0) 
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
    var local_7: i32;
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: bool;
    var local_12: u32;
    var local_13: bool;
    var local_14: i32;
    var local_15: u32;
    var local_16: i32;
    var local_17: i32;
    var local_18: bool;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: i32;
    var phi_228_: bool;
    var phi_90_: u32;
    var phi_143_: i32;
    var phi_146_: i32;
    var phi_188_: i32;
    var phi_144_: i32;
    var phi_147_: i32;
    var phi_221_: bool;
    var phi_231_: bool;
    var phi_230_: bool;
    var phi_91_: u32;
    var phi_229_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e43 = global;
            local = _e43;
            let _e44 = global_1;
            let _e45 = global_2;
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = _e44.x;
            local_4 = _e45.x;
            let _e56 = global_3.member.member_1;
            local_5 = _e56;
            let _e59 = global_3.member.member_2;
            local_6 = _e59;
            if (0u < arrayLength((&global_4.member))) {
            } else {
                break;
            }
            let _e63 = global_4.member[0u];
            local_7 = (bitcast<i32>(_e63) - 1i);
            let _e66 = local_5;
            let _e67 = local_6;
            local_8 = (_e66 * _e67);
            let _e69 = local_4;
            local_9 = (_e69 * 256u);
            let _e71 = local_3;
            phi_228_ = false;
            phi_90_ = (_e71 * 256u);
            loop {
                let _e74 = phi_228_;
                let _e76 = phi_90_;
                local_10 = _e76;
                let _e77 = local_10;
                let _e78 = local_8;
                let _e79 = (_e77 < _e78);
                local_11 = _e79;
                if _e79 {
                    let _e80 = local_10;
                    let _e81 = local;
                    let _e82 = (_e80 + _e81);
                    local_12 = _e82;
                    let _e83 = local_8;
                    if (_e82 < _e83) {
                        let _e85 = local_5;
                        let _e86 = (_e85 == 0u);
                        local_13 = _e86;
                        if _e86 {
                            phi_229_ = true;
                            break;
                        }
                        let _e87 = local_12;
                        let _e88 = local_5;
                        local_14 = bitcast<i32>((_e87 % _e88));
                        let _e91 = local_13;
                        if _e91 {
                            phi_229_ = true;
                            break;
                        }
                        let _e92 = local_12;
                        let _e93 = local_5;
                        local_15 = (_e92 / _e93);
                        let _e95 = local_14;
                        let _e96 = local_7;
                        let _e97 = (_e95 - _e96);
                        let _e100 = local_14;
                        let _e101 = local_7;
                        let _e102 = (_e100 + _e101);
                        let _e103 = local_5;
                        let _e105 = (bitcast<i32>(_e103) - 1i);
                        local_22 = select(_e105, _e102, (_e102 < _e105));
                        phi_143_ = -1i;
                        phi_146_ = select(0i, _e97, (_e97 > 0i));
                        loop {
                            let _e109 = phi_143_;
                            let _e111 = phi_146_;
                            local_16 = _e109;
                            local_17 = _e111;
                            let _e112 = local_17;
                            let _e113 = local_22;
                            let _e114 = (_e112 <= _e113);
                            local_18 = _e114;
                            if _e114 {
                                let _e115 = local_15;
                                let _e116 = local_5;
                                let _e118 = local_17;
                                let _e120 = ((_e115 * _e116) + bitcast<u32>(_e118));
                                local_19 = _e120;
                                let _e121 = local_1;
                                if (_e120 < _e121) {
                                } else {
                                    phi_221_ = true;
                                    break;
                                }
                                let _e123 = local_19;
                                let _e126 = global_5.member[_e123];
                                local_20 = _e126;
                                if (_e126 > 0u) {
                                    let _e128 = local_17;
                                    let _e129 = local_14;
                                    let _e130 = (_e128 - _e129);
                                    let _e131 = local_20;
                                    let _e133 = (bitcast<i32>(_e131) - 1i);
                                    let _e136 = ((_e133 * _e133) - (_e130 * _e130));
                                    let _e137 = local_16;
                                    let _e139 = local_16;
                                    phi_188_ = select(_e136, _e139, (_e136 < _e137));
                                } else {
                                    phi_188_ = _e109;
                                }
                                let _e142 = phi_188_;
                                let _e143 = local_17;
                                phi_144_ = _e142;
                                phi_147_ = (_e143 + 1i);
                            } else {
                                phi_144_ = i32();
                                phi_147_ = i32();
                            }
                            let _e146 = phi_144_;
                            let _e148 = phi_147_;
                            continue;
                            continuing {
                                let _e149 = local_18;
                                phi_143_ = _e146;
                                phi_146_ = _e148;
                                phi_221_ = _e74;
                                break if !(_e149);
                            }
                        }
                        let _e152 = phi_221_;
                        phi_229_ = _e152;
                        if _e152 {
                            break;
                        }
                        let _e153 = local_16;
                        local_21 = bitcast<u32>((_e153 + 1i));
                        let _e156 = local_12;
                        let _e157 = local_2;
                        if (_e156 < _e157) {
                        } else {
                            phi_229_ = true;
                            break;
                        }
                        let _e159 = local_12;
                        let _e162 = local_21;
                        global_6.member[_e159] = _e162;
                        phi_231_ = _e152;
                    } else {
                        phi_231_ = _e74;
                    }
                    let _e164 = phi_231_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e165 = local_10;
                    let _e166 = local_9;
                    phi_230_ = _e164;
                    phi_91_ = (_e165 + _e166);
                } else {
                    phi_230_ = _e74;
                    phi_91_ = u32();
                }
                let _e169 = phi_230_;
                let _e171 = phi_91_;
                continue;
                continuing {
                    let _e172 = local_11;
                    phi_228_ = _e169;
                    phi_90_ = _e171;
                    phi_229_ = _e169;
                    break if !(_e172);
                }
            }
            let _e175 = phi_229_;
            if _e175 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn peel_span(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
