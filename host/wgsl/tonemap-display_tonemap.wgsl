struct type_6 {
    member: array<u32>,
}

struct type_12 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: f32,
}

struct type_13 {
    member: type_12,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_13;
@group(0) @binding(0) 
var<storage> global_4: type_6;
@group(0) @binding(1) 
var<storage, read_write> global_5: type_6;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: bool;
    var local_7: u32;
    var local_8: u32;
    var local_9: bool;
    var local_10: u32;
    var local_11: f32;
    var local_12: f32;
    var local_13: f32;
    var local_14: f32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var phi_293_: bool;
    var phi_105_: u32;
    var phi_121_: u32;
    var phi_171_: f32;
    var phi_172_: f32;
    var phi_173_: f32;
    var phi_278_: bool;
    var phi_199_: f32;
    var phi_200_: f32;
    var phi_218_: f32;
    var phi_219_: f32;
    var phi_220_: f32;
    var phi_221_: f32;
    var phi_122_: u32;
    var phi_287_: bool;
    var phi_305_: bool;
    var phi_304_: bool;
    var phi_106_: u32;
    var phi_303_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e49 = global;
            local = _e49;
            let _e50 = global_1;
            let _e51 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            let _e60 = global_3.member.member;
            let _e63 = global_3.member.member_1;
            local_3 = (_e60 * _e63);
            local_4 = (_e51.x * 256u);
            phi_293_ = false;
            phi_105_ = (_e50.x * 256u);
            loop {
                let _e68 = phi_293_;
                let _e70 = phi_105_;
                local_5 = _e70;
                let _e71 = local_5;
                let _e72 = local_3;
                let _e73 = (_e71 < _e72);
                local_6 = _e73;
                if _e73 {
                    let _e74 = local_5;
                    let _e75 = local;
                    let _e76 = (_e74 + _e75);
                    local_7 = _e76;
                    let _e77 = local_3;
                    if (_e76 < _e77) {
                        phi_121_ = 0u;
                        loop {
                            let _e80 = phi_121_;
                            local_8 = _e80;
                            let _e81 = local_8;
                            let _e82 = (_e81 < 3u);
                            local_9 = _e82;
                            if _e82 {
                                let _e83 = local_7;
                                let _e85 = local_8;
                                let _e86 = ((3u * _e83) + _e85);
                                local_10 = _e86;
                                let _e87 = local_1;
                                if (_e86 < _e87) {
                                } else {
                                    phi_287_ = true;
                                    break;
                                }
                                let _e89 = local_10;
                                let _e92 = global_4.member[_e89];
                                local_11 = bitcast<f32>(_e92);
                                let _e96 = global_3.member.member_2;
                                if (_e96 == 1u) {
                                    let _e98 = local_11;
                                    if (_e98 > 0f) {
                                        let _e100 = local_11;
                                        if (_e100 >= 1f) {
                                            phi_172_ = 1f;
                                        } else {
                                            let _e102 = local_11;
                                            if (_e102 <= 0.0031308f) {
                                                let _e104 = local_11;
                                                phi_171_ = (12.92f * _e104);
                                            } else {
                                                let _e106 = local_11;
                                                phi_171_ = ((1.055f * pow(_e106, 0.41666666f)) - 0.055f);
                                            }
                                            let _e111 = phi_171_;
                                            phi_172_ = _e111;
                                        }
                                        let _e113 = phi_172_;
                                        phi_173_ = _e113;
                                    } else {
                                        phi_173_ = 0f;
                                    }
                                    let _e115 = phi_173_;
                                    phi_221_ = _e115;
                                } else {
                                    let _e118 = global_3.member.member_3;
                                    let _e119 = local_11;
                                    let _e120 = (_e119 * _e118);
                                    local_12 = _e120;
                                    if (_e120 > 0f) {
                                        let _e122 = local_12;
                                        let _e123 = local_12;
                                        if !((_e122 == _e123)) {
                                            phi_278_ = true;
                                        } else {
                                            let _e126 = local_12;
                                            phi_278_ = (65504f <= _e126);
                                        }
                                        let _e129 = phi_278_;
                                        let _e130 = local_12;
                                        let _e131 = select(_e130, 65504f, _e129);
                                        let _e139 = ((_e131 * ((2.51f * _e131) + 0.03f)) / ((_e131 * ((2.43f * _e131) + 0.59f)) + 0.14f));
                                        local_13 = _e139;
                                        if (_e139 < 0f) {
                                            phi_199_ = 0f;
                                        } else {
                                            let _e141 = local_13;
                                            let _e143 = local_13;
                                            phi_199_ = select(_e143, 1f, (_e141 > 1f));
                                        }
                                        let _e146 = phi_199_;
                                        phi_200_ = _e146;
                                    } else {
                                        phi_200_ = 0f;
                                    }
                                    let _e148 = phi_200_;
                                    local_14 = _e148;
                                    if (_e148 > 0f) {
                                        let _e150 = local_14;
                                        if (_e150 >= 1f) {
                                            phi_219_ = 1f;
                                        } else {
                                            let _e152 = local_14;
                                            if (_e152 <= 0.0031308f) {
                                                let _e154 = local_14;
                                                phi_218_ = (12.92f * _e154);
                                            } else {
                                                let _e156 = local_14;
                                                phi_218_ = ((1.055f * pow(_e156, 0.41666666f)) - 0.055f);
                                            }
                                            let _e161 = phi_218_;
                                            phi_219_ = _e161;
                                        }
                                        let _e163 = phi_219_;
                                        phi_220_ = _e163;
                                    } else {
                                        phi_220_ = 0f;
                                    }
                                    let _e165 = phi_220_;
                                    phi_221_ = _e165;
                                }
                                let _e167 = phi_221_;
                                let _e168 = local_7;
                                let _e170 = local_8;
                                let _e171 = ((4u * _e168) + _e170);
                                local_15 = _e171;
                                local_16 = bitcast<u32>(_e167);
                                let _e173 = local_2;
                                if (_e171 < _e173) {
                                } else {
                                    phi_287_ = true;
                                    break;
                                }
                                let _e175 = local_15;
                                let _e178 = local_16;
                                global_5.member[_e175] = _e178;
                                let _e179 = local_8;
                                phi_122_ = (_e179 + 1u);
                            } else {
                                phi_122_ = u32();
                            }
                            let _e182 = phi_122_;
                            continue;
                            continuing {
                                let _e183 = local_9;
                                phi_121_ = _e182;
                                phi_287_ = _e68;
                                break if !(_e183);
                            }
                        }
                        let _e186 = phi_287_;
                        phi_303_ = _e186;
                        if _e186 {
                            break;
                        }
                        let _e187 = local_7;
                        let _e189 = ((4u * _e187) + 3u);
                        local_17 = _e189;
                        let _e190 = local_2;
                        if (_e189 < _e190) {
                        } else {
                            phi_303_ = true;
                            break;
                        }
                        let _e192 = local_17;
                        global_5.member[_e192] = 1065353216u;
                        phi_305_ = _e186;
                    } else {
                        phi_305_ = _e68;
                    }
                    let _e196 = phi_305_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e197 = local_5;
                    let _e198 = local_4;
                    phi_304_ = _e196;
                    phi_106_ = (_e197 + _e198);
                } else {
                    phi_304_ = _e68;
                    phi_106_ = u32();
                }
                let _e201 = phi_304_;
                let _e203 = phi_106_;
                continue;
                continuing {
                    let _e204 = local_6;
                    phi_293_ = _e201;
                    phi_105_ = _e203;
                    phi_303_ = _e201;
                    break if !(_e204);
                }
            }
            let _e207 = phi_303_;
            if _e207 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn display_tonemap(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
