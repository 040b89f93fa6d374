struct type_6 {
    member: array<u32>,
}

struct type_13 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: array<f32, 4>,
    member_9: u32,
    member_10: array<u32, 3>,
}

struct type_14 {
    member: type_13,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_6;
var<immediate> global_4: type_14;
@group(0) @binding(2) 
var<storage> global_5: type_6;
@group(0) @binding(1) 
var<storage, read_write> global_6: type_6;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: u32;
    var local_8: u32;
    var local_9: u32;
    var local_10: bool;
    var local_11: u32;
    var local_12: u32;
    var local_13: f32;
    var local_14: u32;
    var local_15: f32;
    var local_16: u32;
    var local_17: f32;
    var local_18: u32;
    var local_19: bool;
    var local_20: f32;
    var local_21: bool;
    var local_22: f32;
    var local_23: bool;
    var local_24: f32;
    var local_25: bool;
    var local_26: array<f32, 4>;
    var local_27: array<f32, 4>;
    var local_28: f32;
    var local_29: f32;
    var local_30: f32;
    var local_31: f32;
    var local_32: f32;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var phi_105_: bool;
    var phi_117_: u32;
    var phi_282_: array<f32, 4>;
    var phi_283_: array<f32, 4>;
    var phi_389_: bool;
    var phi_118_: u32;
    var phi_398_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e60 = global;
            local = _e60;
            let _e61 = global_1;
            let _e62 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = arrayLength((&global_5.member));
            local_4 = _e61.x;
            local_5 = _e62.x;
            let _e73 = global_4.member.member_7;
            local_6 = _e73;
            if (_e73 == 4294967295u) {
                phi_105_ = true;
            } else {
                let _e75 = local_6;
                let _e76 = local_3;
                if (_e75 < _e76) {
                } else {
                    break;
                }
                let _e78 = local_6;
                let _e81 = global_5.member[_e78];
                phi_105_ = (_e81 != 0u);
            }
            let _e84 = phi_105_;
            if _e84 {
                let _e87 = global_4.member.member;
                let _e90 = global_4.member.member_1;
                local_7 = (_e87 * _e90);
                let _e92 = local_5;
                local_8 = (_e92 * 256u);
                let _e94 = local_4;
                phi_117_ = (_e94 * 256u);
                loop {
                    let _e97 = phi_117_;
                    local_9 = _e97;
                    let _e98 = local_9;
                    let _e99 = local_7;
                    let _e100 = (_e98 < _e99);
                    local_10 = _e100;
                    if _e100 {
                        let _e101 = local_9;
                        let _e102 = local;
                        let _e103 = (_e101 + _e102);
                        local_11 = _e103;
                        let _e104 = local_7;
                        if (_e103 < _e104) {
                            let _e106 = local_11;
                            let _e107 = (4u * _e106);
                            local_12 = _e107;
                            let _e108 = local_1;
                            if (_e107 < _e108) {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e110 = local_12;
                            let _e113 = global_3.member[_e110];
                            local_13 = bitcast<f32>(_e113);
                            let _e115 = local_12;
                            let _e116 = (_e115 + 1u);
                            local_14 = _e116;
                            let _e117 = local_1;
                            if (_e116 < _e117) {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e119 = local_14;
                            let _e122 = global_3.member[_e119];
                            local_15 = bitcast<f32>(_e122);
                            let _e124 = local_12;
                            let _e125 = (_e124 + 2u);
                            local_16 = _e125;
                            let _e126 = local_1;
                            if (_e125 < _e126) {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e128 = local_16;
                            let _e131 = global_3.member[_e128];
                            local_17 = bitcast<f32>(_e131);
                            let _e133 = local_12;
                            let _e134 = (_e133 + 3u);
                            local_18 = _e134;
                            let _e135 = local_1;
                            if (_e134 < _e135) {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e137 = local_18;
                            let _e140 = global_3.member[_e137];
                            let _e142 = local_13;
                            let _e143 = local_15;
                            let _e144 = local_17;
                            let _e145 = array<f32, 4>(_e142, _e143, _e144, bitcast<f32>(_e140));
                            let _e146 = local_12;
                            let _e147 = local_2;
                            let _e148 = (_e146 < _e147);
                            local_19 = _e148;
                            if _e148 {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e149 = local_12;
                            let _e152 = global_6.member[_e149];
                            local_20 = bitcast<f32>(_e152);
                            let _e154 = local_14;
                            let _e155 = local_2;
                            let _e156 = (_e154 < _e155);
                            local_21 = _e156;
                            if _e156 {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e157 = local_14;
                            let _e160 = global_6.member[_e157];
                            local_22 = bitcast<f32>(_e160);
                            let _e162 = local_16;
                            let _e163 = local_2;
                            let _e164 = (_e162 < _e163);
                            local_23 = _e164;
                            if _e164 {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e165 = local_16;
                            let _e168 = global_6.member[_e165];
                            local_24 = bitcast<f32>(_e168);
                            let _e170 = local_18;
                            let _e171 = local_2;
                            let _e172 = (_e170 < _e171);
                            local_25 = _e172;
                            if _e172 {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e173 = local_18;
                            let _e176 = global_6.member[_e173];
                            let _e178 = local_20;
                            let _e179 = local_22;
                            let _e180 = local_24;
                            let _e181 = array<f32, 4>(_e178, _e179, _e180, bitcast<f32>(_e176));
                            let _e184 = global_4.member.member_5;
                            if (_e184 == 0u) {
                                phi_282_ = _e145;
                                phi_283_ = _e181;
                            } else {
                                phi_282_ = _e181;
                                phi_283_ = _e145;
                            }
                            let _e187 = phi_282_;
                            let _e189 = phi_283_;
                            local_26 = _e187;
                            local_27 = _e189;
                            local_28 = _e187[3];
                            let _e191 = (1f - _e187[3]);
                            local_29 = _e191;
                            if !((_e191 == _e191)) {
                                phi_389_ = true;
                            } else {
                                let _e194 = local_29;
                                phi_389_ = (0f >= _e194);
                            }
                            let _e197 = phi_389_;
                            let _e198 = local_29;
                            let _e199 = select(_e198, 0f, _e197);
                            let _e200 = local_26;
                            let _e202 = local_27;
                            let _e206 = local_26;
                            let _e208 = local_27;
                            local_30 = (_e206[1] + (_e199 * _e208[1]));
                            let _e212 = local_26;
                            let _e214 = local_27;
                            local_31 = (_e212[2] + (_e199 * _e214[2]));
                            let _e218 = local_27;
                            let _e221 = local_28;
                            local_32 = (_e221 + (_e199 * _e218[3]));
                            local_33 = bitcast<u32>((_e200[0] + (_e199 * _e202[0])));
                            let _e224 = local_19;
                            if _e224 {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e225 = local_33;
                            global_6.member[_e149] = _e225;
                            let _e226 = local_30;
                            local_34 = bitcast<u32>(_e226);
                            let _e228 = local_21;
                            if _e228 {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e229 = local_34;
                            global_6.member[_e157] = _e229;
                            let _e230 = local_31;
                            local_35 = bitcast<u32>(_e230);
                            let _e232 = local_23;
                            if _e232 {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e233 = local_35;
                            global_6.member[_e165] = _e233;
                            let _e234 = local_32;
                            local_36 = bitcast<u32>(_e234);
                            let _e236 = local_25;
                            if _e236 {
                            } else {
                                phi_398_ = true;
                                break;
                            }
                            let _e237 = local_36;
                            global_6.member[_e173] = _e237;
                        }
                        storageBarrier();
                        workgroupBarrier();
                        let _e238 = local_9;
                        let _e239 = local_8;
                        phi_118_ = (_e238 + _e239);
                    } else {
                        phi_118_ = u32();
                    }
                    let _e242 = phi_118_;
                    continue;
                    continuing {
                        let _e243 = local_10;
                        phi_117_ = _e242;
                        phi_398_ = false;
                        break if !(_e243);
                    }
                }
                let _e246 = phi_398_;
                if _e246 {
                    break;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn layered_composite_gated(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
