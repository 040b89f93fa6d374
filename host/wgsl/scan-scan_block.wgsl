struct type_5 {
    member: array<u32>,
}

struct type_11 {
    member: u32,
    member_1: u32,
    member_2: u32,
}

struct type_12 {
    member: type_11,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<workgroup> global_3: array<u32, 512>;
var<immediate> global_4: type_12;
@group(0) @binding(0) 
var<storage, read_write> global_5: type_5;
@group(0) @binding(1) 
var<storage, read_write> global_6: type_5;

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
    var local_13: bool;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: bool;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: bool;
    var local_29: u32;
    var local_30: bool;
    var local_31: u32;
    var local_32: u32;
    var local_33: u32;
    var phi_83_: u32;
    var phi_425_: bool;
    var phi_85_: u32;
    var phi_104_: u32;
    var phi_107_: u32;
    var phi_130_: u32;
    var phi_105_: u32;
    var phi_108_: u32;
    var phi_421_: bool;
    var phi_277_: u32;
    var phi_280_: u32;
    var phi_316_: u32;
    var phi_278_: u32;
    var phi_281_: u32;
    var phi_427_: bool;
    var phi_353_: u32;
    var phi_355_: u32;
    var phi_358_: u32;
    var phi_387_: u32;
    var phi_356_: u32;
    var phi_359_: u32;
    var phi_451_: bool;
    var phi_458_: bool;
    var phi_86_: u32;
    var phi_457_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e54 = global;
            local = _e54;
            let _e55 = global_1;
            let _e56 = global_2;
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = _e56.x;
            let _e65 = global_4.member.member;
            local_4 = _e65;
            let _e66 = (_e65 / 1024u);
            local_5 = _e66;
            if ((_e65 % 1024u) > 0u) {
                let _e69 = local_5;
                phi_83_ = (_e69 + 1u);
            } else {
                phi_83_ = _e66;
            }
            let _e72 = phi_83_;
            local_6 = _e72;
            phi_425_ = false;
            phi_85_ = _e55.x;
            loop {
                let _e74 = phi_425_;
                let _e76 = phi_85_;
                local_7 = _e76;
                let _e77 = local_7;
                let _e78 = local_6;
                let _e79 = (_e77 < _e78);
                local_8 = _e79;
                if _e79 {
                    let _e82 = global_4.member.member_1;
                    let _e83 = local_7;
                    local_9 = (_e82 + (_e83 * 1024u));
                    let _e86 = local_4;
                    local_10 = (_e82 + _e86);
                    phi_104_ = 0u;
                    phi_107_ = 0u;
                    loop {
                        let _e89 = phi_104_;
                        let _e91 = phi_107_;
                        local_11 = _e89;
                        local_12 = _e91;
                        let _e92 = local_11;
                        let _e93 = (_e92 < 4u);
                        local_13 = _e93;
                        if _e93 {
                            let _e94 = local;
                            let _e96 = local_9;
                            let _e98 = local_11;
                            let _e99 = ((_e96 + (_e94 * 4u)) + _e98);
                            local_14 = _e99;
                            let _e100 = local_10;
                            if (_e99 < _e100) {
                                let _e102 = local_14;
                                let _e103 = local_1;
                                if (_e102 < _e103) {
                                } else {
                                    phi_421_ = true;
                                    break;
                                }
                                let _e105 = local_14;
                                let _e108 = global_5.member[_e105];
                                let _e109 = local_12;
                                phi_130_ = (_e109 + _e108);
                            } else {
                                phi_130_ = _e91;
                            }
                            let _e112 = phi_130_;
                            let _e113 = local_11;
                            phi_105_ = (_e113 + 1u);
                            phi_108_ = _e112;
                        } else {
                            phi_105_ = u32();
                            phi_108_ = u32();
                        }
                        let _e116 = phi_105_;
                        let _e118 = phi_108_;
                        continue;
                        continuing {
                            let _e119 = local_13;
                            phi_104_ = _e116;
                            phi_107_ = _e118;
                            phi_421_ = _e74;
                            break if !(_e119);
                        }
                    }
                    let _e122 = phi_421_;
                    phi_457_ = _e122;
                    if _e122 {
                        break;
                    }
                    let _e123 = local;
                    if (_e123 < 512u) {
                    } else {
                        phi_457_ = true;
                        break;
                    }
                    let _e125 = local;
                    let _e127 = local_12;
                    global_3[_e125] = _e127;
                    storageBarrier();
                    workgroupBarrier();
                    phi_277_ = 1u;
                    phi_280_ = 0u;
                    loop {
                        let _e129 = phi_277_;
                        let _e131 = phi_280_;
                        local_15 = _e129;
                        local_16 = _e131;
                        let _e132 = local_15;
                        let _e133 = (_e132 < 256u);
                        local_17 = _e133;
                        if _e133 {
                            let _e134 = local_16;
                            let _e136 = select(0u, 256u, (_e134 == 0u));
                            local_33 = _e136;
                            let _e137 = local_16;
                            let _e138 = local;
                            let _e139 = (_e137 + _e138);
                            local_18 = _e139;
                            if (_e139 < 512u) {
                            } else {
                                phi_427_ = true;
                                break;
                            }
                            let _e141 = local_18;
                            let _e143 = global_3[_e141];
                            local_19 = _e143;
                            let _e144 = local;
                            let _e145 = local_15;
                            if (_e144 >= _e145) {
                                let _e147 = local;
                                let _e148 = local_15;
                                let _e150 = local_16;
                                let _e151 = (_e150 + (_e147 - _e148));
                                local_20 = _e151;
                                if (_e151 < 512u) {
                                } else {
                                    phi_427_ = true;
                                    break;
                                }
                                let _e153 = local_20;
                                let _e155 = global_3[_e153];
                                let _e156 = local_19;
                                phi_316_ = (_e155 + _e156);
                            } else {
                                phi_316_ = _e143;
                            }
                            let _e159 = phi_316_;
                            local_21 = _e159;
                            let _e160 = local_33;
                            let _e161 = local;
                            let _e162 = (_e160 + _e161);
                            local_22 = _e162;
                            if (_e162 < 512u) {
                            } else {
                                phi_427_ = true;
                                break;
                            }
                            let _e164 = local_22;
                            let _e166 = local_21;
                            global_3[_e164] = _e166;
                            storageBarrier();
                            workgroupBarrier();
                            let _e167 = local_15;
                            phi_278_ = (_e167 * 2u);
                            phi_281_ = _e136;
                        } else {
                            phi_278_ = u32();
                            phi_281_ = u32();
                        }
                        let _e170 = phi_278_;
                        let _e172 = phi_281_;
                        continue;
                        continuing {
                            let _e173 = local_17;
                            phi_277_ = _e170;
                            phi_280_ = _e172;
                            phi_427_ = _e122;
                            break if !(_e173);
                        }
                    }
                    let _e176 = phi_427_;
                    phi_457_ = _e176;
                    if _e176 {
                        break;
                    }
                    let _e177 = local_16;
                    let _e178 = local;
                    let _e179 = (_e177 + _e178);
                    local_23 = _e179;
                    if (_e179 < 512u) {
                    } else {
                        phi_457_ = true;
                        break;
                    }
                    let _e181 = local_23;
                    let _e183 = global_3[_e181];
                    local_24 = _e183;
                    let _e184 = local;
                    if (_e184 == 0u) {
                        phi_353_ = 0u;
                    } else {
                        let _e186 = local_23;
                        let _e187 = (_e186 - 1u);
                        local_25 = _e187;
                        if (_e187 < 512u) {
                        } else {
                            phi_457_ = true;
                            break;
                        }
                        let _e189 = local_25;
                        let _e191 = global_3[_e189];
                        phi_353_ = _e191;
                    }
                    let _e193 = phi_353_;
                    phi_355_ = 0u;
                    phi_358_ = _e193;
                    loop {
                        let _e195 = phi_355_;
                        let _e197 = phi_358_;
                        local_26 = _e195;
                        local_27 = _e197;
                        let _e198 = local_26;
                        let _e199 = (_e198 < 4u);
                        local_28 = _e199;
                        if _e199 {
                            let _e200 = local;
                            let _e202 = local_9;
                            let _e204 = local_26;
                            let _e205 = ((_e202 + (_e200 * 4u)) + _e204);
                            local_29 = _e205;
                            let _e206 = local_10;
                            if (_e205 < _e206) {
                                let _e208 = local_29;
                                let _e209 = local_1;
                                let _e210 = (_e208 < _e209);
                                local_30 = _e210;
                                if _e210 {
                                } else {
                                    phi_451_ = true;
                                    break;
                                }
                                let _e211 = local_29;
                                let _e214 = global_5.member[_e211];
                                local_31 = _e214;
                                let _e215 = local_30;
                                if _e215 {
                                } else {
                                    phi_451_ = true;
                                    break;
                                }
                                let _e216 = local_27;
                                global_5.member[_e211] = _e216;
                                let _e217 = local_27;
                                let _e218 = local_31;
                                phi_387_ = (_e217 + _e218);
                            } else {
                                phi_387_ = _e197;
                            }
                            let _e221 = phi_387_;
                            let _e222 = local_26;
                            phi_356_ = (_e222 + 1u);
                            phi_359_ = _e221;
                        } else {
                            phi_356_ = u32();
                            phi_359_ = u32();
                        }
                        let _e225 = phi_356_;
                        let _e227 = phi_359_;
                        continue;
                        continuing {
                            let _e228 = local_28;
                            phi_355_ = _e225;
                            phi_358_ = _e227;
                            phi_451_ = _e176;
                            break if !(_e228);
                        }
                    }
                    let _e231 = phi_451_;
                    phi_457_ = _e231;
                    if _e231 {
                        break;
                    }
                    let _e232 = local;
                    if (_e232 == 255u) {
                        let _e236 = global_4.member.member_2;
                        let _e237 = local_7;
                        let _e238 = (_e236 + _e237);
                        local_32 = _e238;
                        let _e239 = local_2;
                        if (_e238 < _e239) {
                        } else {
                            phi_457_ = true;
                            break;
                        }
                        let _e241 = local_32;
                        let _e244 = local_24;
                        global_6.member[_e241] = _e244;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e245 = local_7;
                    let _e246 = local_3;
                    phi_458_ = _e231;
                    phi_86_ = (_e245 + _e246);
                } else {
                    phi_458_ = _e74;
                    phi_86_ = u32();
                }
                let _e249 = phi_458_;
                let _e251 = phi_86_;
                continue;
                continuing {
                    let _e252 = local_8;
                    phi_425_ = _e249;
                    phi_85_ = _e251;
                    phi_457_ = _e249;
                    break if !(_e252);
                }
            }
            let _e255 = phi_457_;
            if _e255 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn scan_block(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
