struct type_5 {
    member: array<u32>,
}

struct type_11 {
    member: u32,
    member_1: u32,
}

struct type_12 {
    member: type_11,
}

struct type_19 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_12;
@group(0) @binding(0) 
var<storage> global_4: type_5;
@group(0) @binding(1) 
var<storage, read_write> global_5: type_19;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_5;

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
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: bool;
    var local_13: bool;
    var local_14: u32;
    var local_15: bool;
    var local_16: u32;
    var local_17: array<u32, 9>;
    var phi_184_: bool;
    var phi_72_: u32;
    var phi_107_: u32;
    var phi_128_: u32;
    var phi_108_: u32;
    var phi_130_: bool;
    var phi_131_: bool;
    var phi_180_: bool;
    var phi_179_: bool;
    var phi_187_: bool;
    var phi_186_: bool;
    var phi_73_: u32;
    var phi_185_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e47 = global;
            let _e48 = global_1;
            let _e49 = global_2;
            local = arrayLength((&global_4.member));
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = (_e49.x * 256u);
            phi_184_ = false;
            phi_72_ = ((_e48.x * 256u) + _e47);
            loop {
                let _e62 = phi_184_;
                let _e64 = phi_72_;
                local_4 = _e64;
                let _e67 = global_3.member.member;
                local_5 = _e67;
                let _e68 = local_4;
                let _e69 = (_e68 < _e67);
                local_6 = _e69;
                if _e69 {
                    let _e70 = local_4;
                    let _e71 = (2u * _e70);
                    local_7 = _e71;
                    let _e72 = local;
                    if (_e71 < _e72) {
                    } else {
                        phi_185_ = true;
                        break;
                    }
                    let _e74 = local_7;
                    let _e75 = (_e74 + 1u);
                    local_8 = _e75;
                    let _e76 = local;
                    if (_e75 < _e76) {
                    } else {
                        phi_185_ = true;
                        break;
                    }
                    let _e78 = local_8;
                    let _e81 = global_4.member[_e78];
                    local_9 = _e81;
                    if (_e81 > 0u) {
                        let _e85 = global_3.member.member_1;
                        local_10 = _e85;
                        phi_107_ = 0u;
                        loop {
                            let _e87 = phi_107_;
                            local_11 = _e87;
                            let _e88 = local_11;
                            let _e89 = local_10;
                            if (_e88 <= _e89) {
                                local_17 = array<u32, 9>(64u, 128u, 256u, 512u, 1024u, 2048u, 4096u, 6144u, 8192u);
                                let _e91 = local_11;
                                if (_e91 < 9u) {
                                } else {
                                    phi_180_ = true;
                                    phi_179_ = bool();
                                    break;
                                }
                                let _e93 = local_11;
                                let _e95 = local_17[_e93];
                                let _e96 = local_9;
                                let _e97 = (_e96 <= _e95);
                                local_12 = _e97;
                                if _e97 {
                                    phi_128_ = u32();
                                } else {
                                    let _e98 = local_11;
                                    phi_128_ = (_e98 + 1u);
                                }
                                let _e101 = phi_128_;
                                let _e102 = local_12;
                                phi_108_ = _e101;
                                phi_130_ = select(true, false, _e102);
                                phi_131_ = _e97;
                            } else {
                                phi_108_ = u32();
                                phi_130_ = false;
                                phi_131_ = false;
                            }
                            let _e105 = phi_108_;
                            let _e107 = phi_130_;
                            let _e109 = phi_131_;
                            local_13 = _e107;
                            continue;
                            continuing {
                                let _e110 = local_13;
                                phi_107_ = _e105;
                                phi_180_ = _e62;
                                phi_179_ = _e109;
                                break if !(_e110);
                            }
                        }
                        let _e113 = phi_180_;
                        let _e115 = phi_179_;
                        local_15 = _e115;
                        phi_185_ = _e113;
                        if _e113 {
                            break;
                        }
                        let _e116 = local_15;
                        let _e118 = local_11;
                        let _e119 = select(_e118, 9u, select(true, false, _e116));
                        local_16 = _e119;
                        let _e120 = local_1;
                        if (_e119 < _e120) {
                        } else {
                            phi_185_ = true;
                            break;
                        }
                        let _e122 = local_16;
                        let _e125 = atomicAdd((&global_5.member[_e122]), 1u);
                        let _e126 = local_16;
                        let _e127 = local_5;
                        let _e129 = ((_e126 * _e127) + _e125);
                        local_14 = _e129;
                        let _e130 = local_2;
                        if (_e129 < _e130) {
                        } else {
                            phi_185_ = true;
                            break;
                        }
                        let _e132 = local_14;
                        let _e135 = local_4;
                        global_6.member[_e132] = _e135;
                        let _e136 = local_16;
                        if (_e136 == 9u) {
                            let _e138 = local_1;
                            if (10u < _e138) {
                            } else {
                                phi_185_ = true;
                                break;
                            }
                            let _e142 = local_9;
                            let _e143 = atomicMax((&global_5.member[10u]), _e142);
                        }
                        phi_187_ = _e113;
                    } else {
                        phi_187_ = _e62;
                    }
                    let _e145 = phi_187_;
                    let _e146 = local_4;
                    let _e147 = local_3;
                    phi_186_ = _e145;
                    phi_73_ = (_e146 + _e147);
                } else {
                    phi_186_ = _e62;
                    phi_73_ = u32();
                }
                let _e150 = phi_186_;
                let _e152 = phi_73_;
                continue;
                continuing {
                    let _e153 = local_6;
                    phi_184_ = _e150;
                    phi_72_ = _e152;
                    phi_185_ = _e150;
                    break if !(_e153);
                }
            }
            let _e156 = phi_185_;
            if _e156 {
                break;
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn sort_classify(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
