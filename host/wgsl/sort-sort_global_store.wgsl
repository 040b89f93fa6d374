struct type_5 {
    member: array<u32>,
}

struct type_10 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
}

struct type_11 {
    member: type_10,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_5;
var<immediate> global_4: type_11;
@group(0) @binding(1) 
var<storage> global_5: type_5;
@group(0) @binding(2) 
var<storage> global_6: type_5;
@group(0) @binding(3) 
var<storage> global_7: type_5;
@group(0) @binding(4) 
var<storage> global_8: type_5;
@group(0) @binding(5) 
var<storage> global_9: type_5;
@group(0) @binding(6) 
var<storage, read_write> global_10: type_5;
@group(0) @binding(7) 
var<storage, read_write> global_11: type_5;

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
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: bool;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: bool;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var phi_177_: bool;
    var phi_77_: u32;
    var phi_116_: u32;
    var phi_117_: u32;
    var phi_174_: bool;
    var phi_179_: bool;
    var phi_78_: u32;
    var phi_178_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e47 = global;
            local = _e47;
            let _e48 = global_1;
            let _e49 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = arrayLength((&global_7.member));
            local_4 = arrayLength((&global_8.member));
            local_5 = arrayLength((&global_9.member));
            local_6 = arrayLength((&global_10.member));
            local_7 = arrayLength((&global_11.member));
            local_8 = _e49.y;
            local_9 = (_e48.x * 256u);
            local_10 = (_e49.x * 256u);
            if (9u < arrayLength((&global_5.member))) {
            } else {
                break;
            }
            let _e75 = global_5.member[9u];
            local_11 = _e75;
            phi_177_ = false;
            phi_77_ = _e48.y;
            loop {
                let _e77 = phi_177_;
                let _e79 = phi_77_;
                local_12 = _e79;
                let _e80 = local_12;
                let _e81 = local_11;
                let _e82 = (_e80 < _e81);
                local_13 = _e82;
                if _e82 {
                    let _e85 = global_4.member.member;
                    let _e87 = local_12;
                    let _e88 = ((9u * _e85) + _e87);
                    local_14 = _e88;
                    let _e89 = local_2;
                    if (_e88 < _e89) {
                    } else {
                        phi_178_ = true;
                        break;
                    }
                    let _e91 = local_14;
                    let _e94 = global_6.member[_e91];
                    let _e95 = (2u * _e94);
                    local_15 = _e95;
                    let _e96 = local_1;
                    if (_e95 < _e96) {
                    } else {
                        phi_178_ = true;
                        break;
                    }
                    let _e98 = local_15;
                    let _e101 = global_3.member[_e98];
                    local_16 = _e101;
                    let _e102 = local_15;
                    let _e103 = (_e102 + 1u);
                    local_17 = _e103;
                    let _e104 = local_1;
                    if (_e103 < _e104) {
                    } else {
                        phi_178_ = true;
                        break;
                    }
                    let _e106 = local_17;
                    let _e109 = global_3.member[_e106];
                    local_18 = _e109;
                    let _e110 = local_9;
                    let _e111 = local;
                    phi_116_ = (_e110 + _e111);
                    loop {
                        let _e114 = phi_116_;
                        local_19 = _e114;
                        let _e115 = local_19;
                        let _e116 = local_18;
                        let _e117 = (_e115 < _e116);
                        local_20 = _e117;
                        if _e117 {
                            let _e118 = local_16;
                            let _e119 = local_19;
                            let _e120 = (_e118 + _e119);
                            local_21 = _e120;
                            let _e121 = local_5;
                            if (_e120 < _e121) {
                            } else {
                                phi_174_ = true;
                                break;
                            }
                            let _e123 = local_21;
                            let _e126 = global_9.member[_e123];
                            let _e127 = local_16;
                            let _e128 = (_e127 + _e126);
                            local_22 = _e128;
                            let _e129 = local_3;
                            if (_e128 < _e129) {
                            } else {
                                phi_174_ = true;
                                break;
                            }
                            let _e131 = local_22;
                            let _e134 = global_7.member[_e131];
                            local_23 = _e134;
                            let _e135 = local_21;
                            let _e136 = local_6;
                            if (_e135 < _e136) {
                            } else {
                                phi_174_ = true;
                                break;
                            }
                            let _e138 = local_21;
                            let _e141 = local_23;
                            global_10.member[_e138] = _e141;
                            let _e142 = local_22;
                            let _e143 = local_4;
                            if (_e142 < _e143) {
                            } else {
                                phi_174_ = true;
                                break;
                            }
                            let _e145 = local_22;
                            let _e148 = global_8.member[_e145];
                            local_24 = _e148;
                            let _e149 = local_21;
                            let _e150 = local_7;
                            if (_e149 < _e150) {
                            } else {
                                phi_174_ = true;
                                break;
                            }
                            let _e152 = local_21;
                            let _e155 = local_24;
                            global_11.member[_e152] = _e155;
                            let _e156 = local_19;
                            let _e157 = local_10;
                            phi_117_ = (_e156 + _e157);
                        } else {
                            phi_117_ = u32();
                        }
                        let _e160 = phi_117_;
                        continue;
                        continuing {
                            let _e161 = local_20;
                            phi_116_ = _e160;
                            phi_174_ = _e77;
                            break if !(_e161);
                        }
                    }
                    let _e164 = phi_174_;
                    phi_178_ = _e164;
                    if _e164 {
                        break;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e165 = local_12;
                    let _e166 = local_8;
                    phi_179_ = _e164;
                    phi_78_ = (_e165 + _e166);
                } else {
                    phi_179_ = _e77;
                    phi_78_ = u32();
                }
                let _e169 = phi_179_;
                let _e171 = phi_78_;
                continue;
                continuing {
                    let _e172 = local_13;
                    phi_177_ = _e169;
                    phi_77_ = _e171;
                    phi_178_ = _e169;
                    break if !(_e172);
                }
            }
            let _e175 = phi_178_;
            if _e175 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn sort_global_store(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
