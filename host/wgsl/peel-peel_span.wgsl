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
    member_10: array<u32, 3>,
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
    var phi_229_: bool;
    var phi_91_: u32;
    var phi_144_: i32;
    var phi_147_: i32;
    var phi_189_: i32;
    var phi_145_: i32;
    var phi_148_: i32;
    var phi_222_: bool;
    var phi_232_: bool;
    var phi_231_: bool;
    var phi_92_: u32;
    var phi_230_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e44 = global;
            local = _e44;
            let _e45 = global_1;
            let _e46 = global_2;
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = _e45.x;
            local_4 = _e46.x;
            let _e57 = global_3.member.member_1;
            local_5 = _e57;
            let _e60 = global_3.member.member_2;
            local_6 = _e60;
            if (0u < arrayLength((&global_4.member))) {
            } else {
                break;
            }
            let _e64 = global_4.member[0u];
            local_7 = (bitcast<i32>(_e64) - 1i);
            let _e67 = local_5;
            let _e68 = local_6;
            local_8 = (_e67 * _e68);
            let _e70 = local_4;
            local_9 = (_e70 * 256u);
            let _e72 = local_3;
            phi_229_ = false;
            phi_91_ = (_e72 * 256u);
            loop {
                let _e75 = phi_229_;
                let _e77 = phi_91_;
                local_10 = _e77;
                let _e78 = local_10;
                let _e79 = local_8;
                let _e80 = (_e78 < _e79);
                local_11 = _e80;
                if _e80 {
                    let _e81 = local_10;
                    let _e82 = local;
                    let _e83 = (_e81 + _e82);
                    local_12 = _e83;
                    let _e84 = local_8;
                    if (_e83 < _e84) {
                        let _e86 = local_5;
                        let _e87 = (_e86 == 0u);
                        local_13 = _e87;
                        if _e87 {
                            phi_230_ = true;
                            break;
                        }
                        let _e88 = local_12;
                        let _e89 = local_5;
                        local_14 = bitcast<i32>((_e88 % _e89));
                        let _e92 = local_13;
                        if _e92 {
                            phi_230_ = true;
                            break;
                        }
                        let _e93 = local_12;
                        let _e94 = local_5;
                        local_15 = (_e93 / _e94);
                        let _e96 = local_14;
                        let _e97 = local_7;
                        let _e98 = (_e96 - _e97);
                        let _e101 = local_14;
                        let _e102 = local_7;
                        let _e103 = (_e101 + _e102);
                        let _e104 = local_5;
                        let _e106 = (bitcast<i32>(_e104) - 1i);
                        local_22 = select(_e106, _e103, (_e103 < _e106));
                        phi_144_ = -1i;
                        phi_147_ = select(0i, _e98, (_e98 > 0i));
                        loop {
                            let _e110 = phi_144_;
                            let _e112 = phi_147_;
                            local_16 = _e110;
                            local_17 = _e112;
                            let _e113 = local_17;
                            let _e114 = local_22;
                            let _e115 = (_e113 <= _e114);
                            local_18 = _e115;
                            if _e115 {
                                let _e116 = local_15;
                                let _e117 = local_5;
                                let _e119 = local_17;
                                let _e121 = ((_e116 * _e117) + bitcast<u32>(_e119));
                                local_19 = _e121;
                                let _e122 = local_1;
                                if (_e121 < _e122) {
                                } else {
                                    phi_222_ = true;
                                    break;
                                }
                                let _e124 = local_19;
                                let _e127 = global_5.member[_e124];
                                local_20 = _e127;
                                if (_e127 > 0u) {
                                    let _e129 = local_17;
                                    let _e130 = local_14;
                                    let _e131 = (_e129 - _e130);
                                    let _e132 = local_20;
                                    let _e134 = (bitcast<i32>(_e132) - 1i);
                                    let _e137 = ((_e134 * _e134) - (_e131 * _e131));
                                    let _e138 = local_16;
                                    let _e140 = local_16;
                                    phi_189_ = select(_e137, _e140, (_e137 < _e138));
                                } else {
                                    phi_189_ = _e110;
                                }
                                let _e143 = phi_189_;
                                let _e144 = local_17;
                                phi_145_ = _e143;
                                phi_148_ = (_e144 + 1i);
                            } else {
                                phi_145_ = i32();
                                phi_148_ = i32();
                            }
                            let _e147 = phi_145_;
                            let _e149 = phi_148_;
                            continue;
                            continuing {
                                let _e150 = local_18;
                                phi_144_ = _e147;
                                phi_147_ = _e149;
                                phi_222_ = _e75;
                                break if !(_e150);
                            }
                        }
                        let _e153 = phi_222_;
                        phi_230_ = _e153;
                        if _e153 {
                            break;
                        }
                        let _e154 = local_16;
                        local_21 = bitcast<u32>((_e154 + 1i));
                        let _e157 = local_12;
                        let _e158 = local_2;
                        if (_e157 < _e158) {
                        } else {
                            phi_230_ = true;
                            break;
                        }
                        let _e160 = local_12;
                        let _e163 = local_21;
                        global_6.member[_e160] = _e163;
                        phi_232_ = _e153;
                    } else {
                        phi_232_ = _e75;
                    }
                    let _e165 = phi_232_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e166 = local_10;
                    let _e167 = local_9;
                    phi_231_ = _e165;
                    phi_92_ = (_e166 + _e167);
                } else {
                    phi_231_ = _e75;
                    phi_92_ = u32();
                }
                let _e170 = phi_231_;
                let _e172 = phi_92_;
                continue;
                continuing {
                    let _e173 = local_11;
                    phi_229_ = _e170;
                    phi_91_ = _e172;
                    phi_230_ = _e170;
                    break if !(_e173);
                }
            }
            let _e176 = phi_230_;
            if _e176 {
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
