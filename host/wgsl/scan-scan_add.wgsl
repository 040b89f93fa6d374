struct type_5 {
    member: array<u32>,
}

struct type_10 {
    member: u32,
    member_1: u32,
    member_2: u32,
}

struct type_11 {
    member: type_10,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_11;
@group(0) @binding(0) 
var<storage, read_write> global_4: type_5;
@group(0) @binding(1) 
var<storage> global_5: type_5;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: u32;
    var local_8: bool;
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: bool;
    var local_15: u32;
    var local_16: bool;
    var local_17: u32;
    var phi_65_: u32;
    var phi_142_: bool;
    var phi_67_: u32;
    var phi_96_: u32;
    var phi_97_: u32;
    var phi_138_: bool;
    var phi_145_: bool;
    var phi_68_: u32;
    var phi_144_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e34 = global;
            local = _e34;
            let _e35 = global_1;
            let _e36 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = _e36.x;
            let _e45 = global_3.member.member;
            local_4 = _e45;
            let _e46 = (_e45 / 1024u);
            local_5 = _e46;
            if ((_e45 % 1024u) > 0u) {
                let _e49 = local_5;
                phi_65_ = (_e49 + 1u);
            } else {
                phi_65_ = _e46;
            }
            let _e52 = phi_65_;
            local_6 = _e52;
            phi_142_ = false;
            phi_67_ = _e35.x;
            loop {
                let _e54 = phi_142_;
                let _e56 = phi_67_;
                local_7 = _e56;
                let _e57 = local_7;
                let _e58 = local_6;
                let _e59 = (_e57 < _e58);
                local_8 = _e59;
                if _e59 {
                    let _e62 = global_3.member.member_1;
                    let _e63 = local_7;
                    local_9 = (_e62 + (_e63 * 1024u));
                    let _e66 = local_4;
                    local_10 = (_e62 + _e66);
                    let _e70 = global_3.member.member_2;
                    let _e71 = local_7;
                    let _e72 = (_e70 + _e71);
                    local_11 = _e72;
                    let _e73 = local_2;
                    if (_e72 < _e73) {
                    } else {
                        phi_144_ = true;
                        break;
                    }
                    let _e75 = local_11;
                    let _e78 = global_5.member[_e75];
                    local_12 = _e78;
                    phi_96_ = 0u;
                    loop {
                        let _e80 = phi_96_;
                        local_13 = _e80;
                        let _e81 = local_13;
                        let _e82 = (_e81 < 4u);
                        local_14 = _e82;
                        if _e82 {
                            let _e83 = local;
                            let _e85 = local_9;
                            let _e87 = local_13;
                            let _e88 = ((_e85 + (_e83 * 4u)) + _e87);
                            local_15 = _e88;
                            let _e89 = local_10;
                            if (_e88 < _e89) {
                                let _e91 = local_15;
                                let _e92 = local_1;
                                let _e93 = (_e91 < _e92);
                                local_16 = _e93;
                                if _e93 {
                                } else {
                                    phi_138_ = true;
                                    break;
                                }
                                let _e94 = local_15;
                                let _e97 = global_4.member[_e94];
                                let _e98 = local_12;
                                local_17 = (_e97 + _e98);
                                let _e100 = local_16;
                                if _e100 {
                                } else {
                                    phi_138_ = true;
                                    break;
                                }
                                let _e101 = local_17;
                                global_4.member[_e94] = _e101;
                            }
                            let _e102 = local_13;
                            phi_97_ = (_e102 + 1u);
                        } else {
                            phi_97_ = u32();
                        }
                        let _e105 = phi_97_;
                        continue;
                        continuing {
                            let _e106 = local_14;
                            phi_96_ = _e105;
                            phi_138_ = _e54;
                            break if !(_e106);
                        }
                    }
                    let _e109 = phi_138_;
                    phi_144_ = _e109;
                    if _e109 {
                        break;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e110 = local_7;
                    let _e111 = local_3;
                    phi_145_ = _e109;
                    phi_68_ = (_e110 + _e111);
                } else {
                    phi_145_ = _e54;
                    phi_68_ = u32();
                }
                let _e114 = phi_145_;
                let _e116 = phi_68_;
                continue;
                continuing {
                    let _e117 = local_8;
                    phi_142_ = _e114;
                    phi_67_ = _e116;
                    phi_144_ = _e114;
                    break if !(_e117);
                }
            }
            let _e120 = phi_144_;
            if _e120 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn scan_add(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
