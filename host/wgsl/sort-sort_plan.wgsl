struct type_3 {
    member: array<u32>,
}

var<private> global: u32;
@group(0) @binding(0) 
var<storage, read_write> global_1: type_3;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: bool;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: u32;
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var phi_54_: u32;
    var phi_55_: u32;
    var phi_263_: bool;
    var phi_133_: u32;
    var phi_151_: u32;
    var phi_168_: u32;
    var phi_189_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e47 = global;
            local = arrayLength((&global_1.member));
            if (_e47 == 0u) {
                phi_54_ = 0u;
                loop {
                    let _e52 = phi_54_;
                    local_1 = _e52;
                    let _e53 = local_1;
                    let _e54 = (_e53 < 9u);
                    local_2 = _e54;
                    if _e54 {
                        let _e55 = local_1;
                        let _e56 = local;
                        if (_e55 < _e56) {
                        } else {
                            phi_263_ = true;
                            break;
                        }
                        let _e58 = local_1;
                        let _e61 = global_1.member[_e58];
                        let _e62 = local_1;
                        let _e63 = (3u * _e62);
                        local_3 = _e63;
                        let _e64 = (12u + _e63);
                        local_4 = _e64;
                        local_11 = select(_e61, 65535u, (65535u < _e61));
                        let _e67 = local;
                        if (_e64 < _e67) {
                        } else {
                            phi_263_ = true;
                            break;
                        }
                        let _e69 = local_4;
                        let _e72 = local_11;
                        global_1.member[_e69] = _e72;
                        let _e73 = local_3;
                        let _e74 = (_e73 + 13u);
                        local_5 = _e74;
                        let _e75 = local;
                        if (_e74 < _e75) {
                        } else {
                            phi_263_ = true;
                            break;
                        }
                        let _e77 = local_5;
                        global_1.member[_e77] = 1u;
                        let _e80 = local_3;
                        let _e81 = (_e80 + 14u);
                        local_6 = _e81;
                        let _e82 = local;
                        if (_e81 < _e82) {
                        } else {
                            phi_263_ = true;
                            break;
                        }
                        let _e84 = local_6;
                        global_1.member[_e84] = 1u;
                        let _e87 = local_1;
                        phi_55_ = (_e87 + 1u);
                    } else {
                        phi_55_ = u32();
                    }
                    let _e90 = phi_55_;
                    continue;
                    continuing {
                        let _e91 = local_2;
                        phi_54_ = _e90;
                        phi_263_ = false;
                        break if !(_e91);
                    }
                }
                let _e94 = phi_263_;
                if _e94 {
                    break;
                }
                let _e95 = local;
                if (9u < _e95) {
                } else {
                    break;
                }
                let _e99 = global_1.member[9u];
                local_12 = select(_e99, 65535u, (65535u < _e99));
                let _e102 = local;
                if (10u < _e102) {
                } else {
                    break;
                }
                let _e106 = global_1.member[10u];
                local_7 = _e106;
                let _e107 = (_e106 / 2048u);
                local_8 = _e107;
                if ((_e106 % 2048u) > 0u) {
                    let _e110 = local_8;
                    phi_133_ = (_e110 + 1u);
                } else {
                    phi_133_ = _e107;
                }
                let _e113 = phi_133_;
                local_13 = select(_e113, 65535u, (65535u < _e113));
                let _e116 = local_7;
                if (_e116 <= 1u) {
                    phi_151_ = 1u;
                } else {
                    let _e118 = local_7;
                    let _e119 = (_e118 - 1u);
                    phi_151_ = (1u << bitcast<u32>(((32u - select((bitcast<u32>(31i) - firstLeadingBit(_e119)), 32u, (_e119 == 0u))) & 31u)));
                }
                let _e130 = phi_151_;
                let _e131 = (_e130 / 2u);
                let _e132 = (_e131 / 256u);
                local_9 = _e132;
                if ((_e131 % 256u) > 0u) {
                    let _e135 = local_9;
                    phi_168_ = (_e135 + 1u);
                } else {
                    phi_168_ = _e132;
                }
                let _e138 = phi_168_;
                local_14 = select(_e138, 65535u, (65535u < _e138));
                let _e141 = local_7;
                let _e142 = (_e141 / 256u);
                local_10 = _e142;
                let _e143 = local_7;
                if ((_e143 % 256u) > 0u) {
                    let _e146 = local_10;
                    phi_189_ = (_e146 + 1u);
                } else {
                    phi_189_ = _e142;
                }
                let _e149 = phi_189_;
                local_15 = select(_e149, 65535u, (65535u < _e149));
                let _e152 = local;
                if (39u < _e152) {
                } else {
                    break;
                }
                let _e156 = local_13;
                global_1.member[39u] = _e156;
                let _e157 = local;
                if (40u < _e157) {
                } else {
                    break;
                }
                let _e161 = local_12;
                global_1.member[40u] = _e161;
                let _e162 = local;
                if (41u < _e162) {
                } else {
                    break;
                }
                global_1.member[41u] = 1u;
                let _e166 = local;
                if (42u < _e166) {
                } else {
                    break;
                }
                let _e170 = local_14;
                global_1.member[42u] = _e170;
                let _e171 = local;
                if (43u < _e171) {
                } else {
                    break;
                }
                let _e175 = local_12;
                global_1.member[43u] = _e175;
                let _e176 = local;
                if (44u < _e176) {
                } else {
                    break;
                }
                global_1.member[44u] = 1u;
                let _e180 = local;
                if (45u < _e180) {
                } else {
                    break;
                }
                let _e184 = local_15;
                global_1.member[45u] = _e184;
                let _e185 = local;
                if (46u < _e185) {
                } else {
                    break;
                }
                let _e189 = local_12;
                global_1.member[46u] = _e189;
                let _e190 = local;
                if (47u < _e190) {
                } else {
                    break;
                }
                global_1.member[47u] = 1u;
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn sort_plan(@builtin(local_invocation_index) param: u32) {
    global = param;
    function_();
}
