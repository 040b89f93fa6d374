struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_6 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: type_5,
}

struct type_7 {
    member: type_6,
}

struct type_10 {
    member: array<u32>,
}

struct type_24 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_10;
var<workgroup> global_5: array<u32, 512>;
@group(0) @binding(1) 
var<storage, read_write> global_6: type_24;
var<private> global_7: u32 = 2143289344u;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: bool;
    var local_8: f32;
    var local_9: u32;
    var local_10: bool;
    var local_11: f32;
    var local_12: f32;
    var local_13: f32;
    var local_14: f32;
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
    var local_25: f32;
    var local_26: u32;
    var phi_113_: u32;
    var phi_116_: u32;
    var phi_138_: bool;
    var phi_173_: bool;
    var phi_201_: f32;
    var phi_202_: f32;
    var phi_208_: f32;
    var phi_210_: f32;
    var phi_497_: bool;
    var phi_245_: u32;
    var phi_114_: u32;
    var phi_117_: u32;
    var phi_502_: bool;
    var phi_396_: u32;
    var phi_399_: u32;
    var phi_439_: u32;
    var phi_397_: u32;
    var phi_400_: u32;
    var phi_517_: bool;

    let _e57 = global_7;
    switch bitcast<i32>(0u) {
        default: {
            let _e60 = global;
            local = _e60;
            let _e61 = global_1;
            let _e62 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = (_e62.x * 256u);
            let _e73 = global_3.member.member;
            let _e76 = global_3.member.member_1;
            local_4 = (_e73 * _e76);
            phi_113_ = ((_e61.x * 256u) + _e60);
            phi_116_ = 0u;
            loop {
                let _e80 = phi_113_;
                let _e82 = phi_116_;
                local_5 = _e80;
                local_6 = _e82;
                let _e83 = local_5;
                let _e84 = local_4;
                let _e85 = (_e83 < _e84);
                local_7 = _e85;
                if _e85 {
                    let _e86 = local_5;
                    let _e87 = local_1;
                    if (_e86 < _e87) {
                    } else {
                        phi_502_ = true;
                        break;
                    }
                    let _e89 = local_5;
                    let _e92 = global_4.member[_e89];
                    let _e93 = bitcast<f32>(_e92);
                    local_8 = _e93;
                    let _e94 = bitcast<u32>(_e93);
                    local_9 = _e94;
                    let _e95 = (_e94 == 0u);
                    local_10 = _e95;
                    if _e95 {
                        phi_138_ = false;
                    } else {
                        let _e96 = local_9;
                        phi_138_ = (_e96 <= 2139095040u);
                    }
                    let _e99 = phi_138_;
                    if _e99 {
                        let _e102 = global_3.member.member_2;
                        local_11 = f32(_e102);
                        let _e104 = local_9;
                        if (_e104 == 2139095040u) {
                            let _e152 = global_3.member.member_4.member_1;
                            let _e157 = global_3.member.member_4.member;
                            let _e162 = global_3.member.member_4.member_2;
                            let _e168 = global_3.member.member_4.member_3;
                            phi_210_ = (0.5f * ((((2f * _e152) * _e157) / (_e162 - _e157)) * _e168));
                        } else {
                            let _e106 = local_10;
                            if _e106 {
                                phi_173_ = false;
                            } else {
                                let _e107 = local_9;
                                phi_173_ = (_e107 <= 2139095040u);
                            }
                            let _e110 = phi_173_;
                            if _e110 {
                                let _e114 = global_3.member.member_4.member_1;
                                let _e119 = global_3.member.member_4.member;
                                let _e124 = global_3.member.member_4.member_2;
                                local_12 = _e124;
                                let _e130 = global_3.member.member_4.member_3;
                                let _e131 = ((((2f * _e114) * _e119) / (_e124 - _e119)) * _e130);
                                local_13 = _e131;
                                if (_e131 == 0f) {
                                    phi_201_ = 0f;
                                } else {
                                    let _e133 = local_12;
                                    let _e134 = local_8;
                                    let _e137 = local_13;
                                    phi_201_ = (_e137 * (1f - (_e133 / _e134)));
                                }
                                let _e140 = phi_201_;
                                phi_202_ = _e140;
                            } else {
                                phi_202_ = bitcast<f32>(_e57);
                            }
                            let _e142 = phi_202_;
                            local_14 = _e142;
                            if (_e142 < 0f) {
                                let _e144 = local_14;
                                phi_208_ = -(_e144);
                            } else {
                                phi_208_ = _e142;
                            }
                            let _e147 = phi_208_;
                            phi_210_ = (0.5f * _e147);
                        }
                        let _e172 = phi_210_;
                        let _e176 = select(_e172, 0f, ((bitcast<u32>(_e172) & 2147483647u) > 2139095040u));
                        local_25 = _e176;
                        if !((_e176 == _e176)) {
                            phi_497_ = true;
                        } else {
                            let _e179 = local_11;
                            let _e180 = local_25;
                            phi_497_ = (_e179 <= _e180);
                        }
                        let _e183 = phi_497_;
                        let _e184 = local_11;
                        let _e185 = local_25;
                        let _e186 = select(_e185, _e184, _e183);
                        let _e192 = select(select(u32(_e186), 0u, !((_e186 >= 0f))), 4294967295u, (_e186 > 4294967000f));
                        let _e196 = (_e192 + select(1u, 0u, (f32(_e192) == _e186)));
                        let _e197 = local_6;
                        let _e199 = local_6;
                        phi_245_ = select(_e199, _e196, (_e196 > _e197));
                    } else {
                        phi_245_ = _e82;
                    }
                    let _e202 = phi_245_;
                    let _e203 = local_5;
                    let _e204 = local_3;
                    phi_114_ = (_e203 + _e204);
                    phi_117_ = _e202;
                } else {
                    phi_114_ = u32();
                    phi_117_ = u32();
                }
                let _e207 = phi_114_;
                let _e209 = phi_117_;
                continue;
                continuing {
                    let _e210 = local_7;
                    phi_113_ = _e207;
                    phi_116_ = _e209;
                    phi_502_ = false;
                    break if !(_e210);
                }
            }
            let _e213 = phi_502_;
            if _e213 {
                break;
            }
            let _e214 = local;
            if (_e214 < 512u) {
            } else {
                break;
            }
            let _e216 = local;
            let _e218 = local_6;
            global_5[_e216] = _e218;
            storageBarrier();
            workgroupBarrier();
            phi_396_ = 1u;
            phi_399_ = 0u;
            loop {
                let _e220 = phi_396_;
                let _e222 = phi_399_;
                local_15 = _e220;
                local_16 = _e222;
                let _e223 = local_15;
                let _e224 = (_e223 < 256u);
                local_17 = _e224;
                if _e224 {
                    let _e225 = local_16;
                    let _e227 = select(0u, 256u, (_e225 == 0u));
                    local_26 = _e227;
                    let _e228 = local_16;
                    let _e229 = local;
                    let _e230 = (_e228 + _e229);
                    local_18 = _e230;
                    if (_e230 < 512u) {
                    } else {
                        phi_517_ = true;
                        break;
                    }
                    let _e232 = local_18;
                    let _e234 = global_5[_e232];
                    local_19 = _e234;
                    let _e235 = local;
                    let _e236 = local_15;
                    if (_e235 >= _e236) {
                        let _e238 = local;
                        let _e239 = local_15;
                        let _e241 = local_16;
                        let _e242 = (_e241 + (_e238 - _e239));
                        local_20 = _e242;
                        if (_e242 < 512u) {
                        } else {
                            phi_517_ = true;
                            break;
                        }
                        let _e244 = local_20;
                        let _e246 = global_5[_e244];
                        let _e247 = local_19;
                        let _e249 = local_19;
                        phi_439_ = select(_e249, _e246, (_e246 > _e247));
                    } else {
                        phi_439_ = _e234;
                    }
                    let _e252 = phi_439_;
                    local_21 = _e252;
                    let _e253 = local_26;
                    let _e254 = local;
                    let _e255 = (_e253 + _e254);
                    local_22 = _e255;
                    if (_e255 < 512u) {
                    } else {
                        phi_517_ = true;
                        break;
                    }
                    let _e257 = local_22;
                    let _e259 = local_21;
                    global_5[_e257] = _e259;
                    storageBarrier();
                    workgroupBarrier();
                    let _e260 = local_15;
                    phi_397_ = (_e260 * 2u);
                    phi_400_ = _e227;
                } else {
                    phi_397_ = u32();
                    phi_400_ = u32();
                }
                let _e263 = phi_397_;
                let _e265 = phi_400_;
                continue;
                continuing {
                    let _e266 = local_17;
                    phi_396_ = _e263;
                    phi_399_ = _e265;
                    phi_517_ = _e213;
                    break if !(_e266);
                }
            }
            let _e269 = phi_517_;
            if _e269 {
                break;
            }
            let _e270 = local;
            if (_e270 == 255u) {
                let _e272 = local_16;
                let _e273 = local;
                let _e274 = (_e272 + _e273);
                local_23 = _e274;
                if (_e274 < 512u) {
                } else {
                    break;
                }
                let _e276 = local_23;
                let _e278 = global_5[_e276];
                local_24 = _e278;
                let _e279 = local_2;
                if (0u < _e279) {
                } else {
                    break;
                }
                let _e283 = local_24;
                let _e284 = atomicMax((&global_6.member[0u]), _e283);
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn gather_plan(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
