struct type_5 {
    member: array<u32>,
}

struct type_11 {
    member: u32,
    member_1: u32,
}

struct type_12 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
}

struct type_13 {
    member: type_12,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_5;
var<immediate> global_4: type_13;
@group(0) @binding(1) 
var<storage> global_5: type_5;
@group(0) @binding(2) 
var<storage> global_6: type_5;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_5;
@group(0) @binding(4) 
var<storage, read_write> global_8: type_5;

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
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: bool;
    var local_18: bool;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: bool;
    var local_28: u32;
    var local_29: bool;
    var local_30: u32;
    var local_31: u32;
    var local_32: bool;
    var local_33: u32;
    var local_34: bool;
    var local_35: u32;
    var local_36: bool;
    var phi_294_: bool;
    var phi_79_: u32;
    var phi_131_: u32;
    var phi_134_: u32;
    var phi_154_: u32;
    var phi_188_: type_11;
    var phi_239_: bool;
    var phi_240_: bool;
    var phi_273_: u32;
    var phi_135_: u32;
    var phi_274_: bool;
    var phi_284_: bool;
    var phi_297_: bool;
    var phi_80_: u32;
    var phi_296_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e61 = global;
            local = _e61;
            let _e62 = global_1;
            let _e63 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = arrayLength((&global_7.member));
            local_4 = arrayLength((&global_8.member));
            local_5 = _e63.y;
            local_6 = (_e62.x * 256u);
            local_7 = (_e63.x * 256u);
            if (9u < arrayLength((&global_5.member))) {
            } else {
                break;
            }
            let _e83 = global_5.member[9u];
            local_8 = _e83;
            phi_294_ = false;
            phi_79_ = _e62.y;
            loop {
                let _e85 = phi_294_;
                let _e87 = phi_79_;
                local_9 = _e87;
                let _e88 = local_9;
                let _e89 = local_8;
                let _e90 = (_e88 < _e89);
                local_10 = _e90;
                if _e90 {
                    let _e93 = global_4.member.member;
                    let _e95 = local_9;
                    let _e96 = ((9u * _e93) + _e95);
                    local_11 = _e96;
                    let _e97 = local_2;
                    if (_e96 < _e97) {
                    } else {
                        phi_296_ = true;
                        break;
                    }
                    let _e99 = local_11;
                    let _e102 = global_6.member[_e99];
                    let _e103 = (2u * _e102);
                    local_12 = _e103;
                    let _e104 = local_1;
                    if (_e103 < _e104) {
                    } else {
                        phi_296_ = true;
                        break;
                    }
                    let _e106 = local_12;
                    let _e109 = global_3.member[_e106];
                    local_13 = _e109;
                    let _e110 = local_12;
                    let _e111 = (_e110 + 1u);
                    local_14 = _e111;
                    let _e112 = local_1;
                    if (_e111 < _e112) {
                    } else {
                        phi_296_ = true;
                        break;
                    }
                    let _e114 = local_14;
                    let _e117 = global_3.member[_e114];
                    local_15 = _e117;
                    let _e118 = local_6;
                    let _e119 = local;
                    let _e123 = global_4.member.member_2;
                    local_16 = _e123;
                    let _e124 = (_e117 <= 1u);
                    local_17 = _e124;
                    if _e124 {
                        phi_131_ = 1u;
                    } else {
                        let _e125 = local_15;
                        let _e126 = (_e125 - 1u);
                        phi_131_ = (1u << bitcast<u32>(((32u - select((bitcast<u32>(31i) - firstLeadingBit(_e126)), 32u, (_e126 == 0u))) & 31u)));
                    }
                    let _e137 = phi_131_;
                    let _e138 = local_16;
                    local_18 = (_e138 <= _e137);
                    phi_134_ = (_e118 + _e119);
                    loop {
                        let _e141 = phi_134_;
                        local_19 = _e141;
                        let _e142 = local_18;
                        if _e142 {
                            let _e143 = local_17;
                            if _e143 {
                                phi_154_ = 1u;
                            } else {
                                let _e144 = local_15;
                                let _e145 = (_e144 - 1u);
                                phi_154_ = (1u << bitcast<u32>(((32u - select((bitcast<u32>(31i) - firstLeadingBit(_e145)), 32u, (_e145 == 0u))) & 31u)));
                            }
                            let _e156 = phi_154_;
                            let _e158 = local_19;
                            let _e159 = (_e158 < (_e156 / 2u));
                            if _e159 {
                                let _e162 = global_4.member.member_3;
                                local_20 = _e162;
                                let _e163 = (_e162 - 1u);
                                let _e165 = local_19;
                                let _e168 = ((_e165 & ~(_e163)) << bitcast<u32>(1i));
                                local_21 = _e168;
                                let _e169 = local_19;
                                let _e170 = (_e169 & _e163);
                                local_22 = _e170;
                                local_23 = (_e168 + _e170);
                                let _e172 = local_16;
                                if (_e162 == (_e172 >> bitcast<u32>(1i))) {
                                    let _e176 = local_21;
                                    let _e177 = local_16;
                                    let _e180 = local_22;
                                    let _e182 = local_23;
                                    phi_188_ = type_11(_e182, (((_e176 + _e177) - 1u) - _e180));
                                } else {
                                    let _e184 = local_23;
                                    let _e185 = local_20;
                                    let _e187 = local_23;
                                    phi_188_ = type_11(_e187, (_e184 + _e185));
                                }
                                let _e190 = phi_188_;
                                local_24 = _e190.member;
                                local_25 = _e190.member_1;
                                let _e193 = local_15;
                                if (_e190.member_1 < _e193) {
                                    let _e195 = local_13;
                                    let _e196 = local_24;
                                    let _e197 = (_e195 + _e196);
                                    local_26 = _e197;
                                    let _e198 = local_3;
                                    let _e199 = (_e197 < _e198);
                                    local_27 = _e199;
                                    if _e199 {
                                    } else {
                                        phi_284_ = true;
                                        break;
                                    }
                                    let _e200 = local_26;
                                    let _e203 = global_7.member[_e200];
                                    local_28 = _e203;
                                    let _e204 = local_26;
                                    let _e205 = local_4;
                                    let _e206 = (_e204 < _e205);
                                    local_29 = _e206;
                                    if _e206 {
                                    } else {
                                        phi_284_ = true;
                                        break;
                                    }
                                    let _e207 = local_26;
                                    let _e210 = global_8.member[_e207];
                                    local_30 = _e210;
                                    let _e211 = local_13;
                                    let _e212 = local_25;
                                    let _e213 = (_e211 + _e212);
                                    local_31 = _e213;
                                    let _e214 = local_3;
                                    let _e215 = (_e213 < _e214);
                                    local_32 = _e215;
                                    if _e215 {
                                    } else {
                                        phi_284_ = true;
                                        break;
                                    }
                                    let _e216 = local_31;
                                    let _e219 = global_7.member[_e216];
                                    local_33 = _e219;
                                    let _e220 = local_31;
                                    let _e221 = local_4;
                                    let _e222 = (_e220 < _e221);
                                    local_34 = _e222;
                                    if _e222 {
                                    } else {
                                        phi_284_ = true;
                                        break;
                                    }
                                    let _e223 = local_31;
                                    let _e226 = global_8.member[_e223];
                                    local_35 = _e226;
                                    let _e227 = local_28;
                                    let _e228 = local_33;
                                    if (_e227 > _e228) {
                                        phi_240_ = true;
                                    } else {
                                        let _e230 = local_28;
                                        let _e231 = local_33;
                                        if (_e230 == _e231) {
                                            let _e233 = local_30;
                                            let _e234 = local_35;
                                            phi_239_ = (_e233 > _e234);
                                        } else {
                                            phi_239_ = false;
                                        }
                                        let _e237 = phi_239_;
                                        phi_240_ = _e237;
                                    }
                                    let _e239 = phi_240_;
                                    if _e239 {
                                        let _e240 = local_27;
                                        if _e240 {
                                        } else {
                                            phi_284_ = true;
                                            break;
                                        }
                                        let _e241 = local_33;
                                        global_7.member[_e200] = _e241;
                                        let _e242 = local_29;
                                        if _e242 {
                                        } else {
                                            phi_284_ = true;
                                            break;
                                        }
                                        let _e243 = local_35;
                                        global_8.member[_e207] = _e243;
                                        let _e244 = local_32;
                                        if _e244 {
                                        } else {
                                            phi_284_ = true;
                                            break;
                                        }
                                        let _e245 = local_28;
                                        global_7.member[_e216] = _e245;
                                        let _e246 = local_34;
                                        if _e246 {
                                        } else {
                                            phi_284_ = true;
                                            break;
                                        }
                                        let _e247 = local_30;
                                        global_8.member[_e223] = _e247;
                                    }
                                }
                                let _e248 = local_19;
                                let _e249 = local_7;
                                phi_273_ = (_e248 + _e249);
                            } else {
                                phi_273_ = u32();
                            }
                            let _e252 = phi_273_;
                            phi_135_ = _e252;
                            phi_274_ = _e159;
                        } else {
                            phi_135_ = u32();
                            phi_274_ = false;
                        }
                        let _e254 = phi_135_;
                        let _e256 = phi_274_;
                        local_36 = _e256;
                        continue;
                        continuing {
                            let _e257 = local_36;
                            phi_134_ = _e254;
                            phi_284_ = _e85;
                            break if !(_e257);
                        }
                    }
                    let _e260 = phi_284_;
                    phi_296_ = _e260;
                    if _e260 {
                        break;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e261 = local_9;
                    let _e262 = local_5;
                    phi_297_ = _e260;
                    phi_80_ = (_e261 + _e262);
                } else {
                    phi_297_ = _e85;
                    phi_80_ = u32();
                }
                let _e265 = phi_297_;
                let _e267 = phi_80_;
                continue;
                continuing {
                    let _e268 = local_10;
                    phi_294_ = _e265;
                    phi_79_ = _e267;
                    phi_296_ = _e265;
                    break if !(_e268);
                }
            }
            let _e271 = phi_296_;
            if _e271 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn sort_global_step(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
