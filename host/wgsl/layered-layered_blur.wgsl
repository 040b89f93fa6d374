struct type_6 {
    member: array<u32>,
}

struct type_14 {
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

struct type_15 {
    member: type_14,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_15;
@group(0) @binding(0) 
var<storage> global_4: type_6;
@group(0) @binding(1) 
var<storage> global_5: type_6;
@group(0) @binding(2) 
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
    var local_9: bool;
    var local_10: u32;
    var local_11: i32;
    var local_12: bool;
    var local_13: i32;
    var local_14: i32;
    var local_15: bool;
    var local_16: i32;
    var local_17: i32;
    var local_18: array<f32, 4>;
    var local_19: bool;
    var local_20: i32;
    var local_21: u32;
    var local_22: u32;
    var local_23: f32;
    var local_24: u32;
    var local_25: f32;
    var local_26: u32;
    var local_27: f32;
    var local_28: u32;
    var local_29: f32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: i32;
    var phi_385_: bool;
    var phi_86_: u32;
    var phi_132_: i32;
    var phi_136_: i32;
    var phi_139_: array<f32, 4>;
    var phi_163_: i32;
    var phi_198_: u32;
    var phi_286_: array<f32, 4>;
    var phi_287_: array<f32, 4>;
    var phi_137_: i32;
    var phi_140_: array<f32, 4>;
    var phi_377_: bool;
    var phi_388_: bool;
    var phi_387_: bool;
    var phi_87_: u32;
    var phi_386_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e65 = global;
            local = _e65;
            let _e66 = global_1;
            let _e67 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            let _e78 = global_3.member.member;
            local_4 = _e78;
            let _e81 = global_3.member.member_1;
            local_5 = _e81;
            local_6 = (_e78 * _e81);
            local_7 = (_e67.x * 256u);
            phi_385_ = false;
            phi_86_ = (_e66.x * 256u);
            loop {
                let _e86 = phi_385_;
                let _e88 = phi_86_;
                local_8 = _e88;
                let _e89 = local_8;
                let _e90 = local_6;
                let _e91 = (_e89 < _e90);
                local_9 = _e91;
                if _e91 {
                    let _e92 = local_8;
                    let _e93 = local;
                    let _e94 = (_e92 + _e93);
                    local_10 = _e94;
                    let _e95 = local_6;
                    if (_e94 < _e95) {
                        let _e99 = global_3.member.member_3;
                        local_11 = bitcast<i32>(_e99);
                        let _e101 = local_4;
                        let _e102 = (_e101 == 0u);
                        local_12 = _e102;
                        if _e102 {
                            phi_386_ = true;
                            break;
                        }
                        let _e103 = local_10;
                        let _e104 = local_4;
                        local_13 = bitcast<i32>((_e103 % _e104));
                        let _e107 = local_12;
                        if _e107 {
                            phi_386_ = true;
                            break;
                        }
                        let _e108 = local_10;
                        let _e109 = local_4;
                        local_14 = bitcast<i32>((_e108 / _e109));
                        let _e114 = global_3.member.member_5;
                        let _e115 = (_e114 == 0u);
                        local_15 = _e115;
                        if _e115 {
                            let _e116 = local_4;
                            phi_132_ = bitcast<i32>(_e116);
                        } else {
                            let _e118 = local_5;
                            phi_132_ = bitcast<i32>(_e118);
                        }
                        let _e121 = phi_132_;
                        local_16 = _e121;
                        let _e122 = local_15;
                        let _e123 = local_13;
                        let _e124 = local_14;
                        local_39 = select(_e124, _e123, _e122);
                        let _e126 = local_11;
                        phi_136_ = -(_e126);
                        phi_139_ = array<f32, 4>(0f, 0f, 0f, 0f);
                        loop {
                            let _e129 = phi_136_;
                            let _e131 = phi_139_;
                            local_17 = _e129;
                            local_18 = _e131;
                            let _e132 = local_17;
                            let _e133 = local_11;
                            let _e134 = (_e132 <= _e133);
                            local_19 = _e134;
                            if _e134 {
                                let _e135 = local_39;
                                let _e136 = local_17;
                                let _e137 = (_e135 + _e136);
                                local_20 = _e137;
                                if (_e137 >= 0i) {
                                    let _e139 = local_20;
                                    let _e140 = local_16;
                                    if (_e139 < _e140) {
                                        let _e144 = global_3.member.member_4;
                                        local_21 = _e144;
                                        let _e145 = local_17;
                                        if (_e145 < 0i) {
                                            let _e147 = local_17;
                                            phi_163_ = (0i - _e147);
                                        } else {
                                            phi_163_ = _e129;
                                        }
                                        let _e150 = phi_163_;
                                        let _e152 = local_21;
                                        let _e153 = (_e152 + bitcast<u32>(_e150));
                                        local_22 = _e153;
                                        let _e154 = local_2;
                                        if (_e153 < _e154) {
                                        } else {
                                            phi_377_ = true;
                                            break;
                                        }
                                        let _e156 = local_22;
                                        let _e159 = global_5.member[_e156];
                                        local_23 = bitcast<f32>(_e159);
                                        let _e161 = local_15;
                                        if _e161 {
                                            let _e162 = local_13;
                                            let _e164 = local_10;
                                            let _e166 = local_20;
                                            phi_198_ = ((_e164 - bitcast<u32>(_e162)) + bitcast<u32>(_e166));
                                        } else {
                                            let _e169 = local_20;
                                            let _e171 = local_4;
                                            let _e173 = local_13;
                                            phi_198_ = ((bitcast<u32>(_e169) * _e171) + bitcast<u32>(_e173));
                                        }
                                        let _e177 = phi_198_;
                                        let _e178 = (4u * _e177);
                                        local_24 = _e178;
                                        let _e179 = local_1;
                                        if (_e178 < _e179) {
                                        } else {
                                            phi_377_ = true;
                                            break;
                                        }
                                        let _e181 = local_24;
                                        let _e184 = global_4.member[_e181];
                                        local_25 = bitcast<f32>(_e184);
                                        let _e186 = local_24;
                                        let _e187 = (_e186 + 1u);
                                        local_26 = _e187;
                                        let _e188 = local_1;
                                        if (_e187 < _e188) {
                                        } else {
                                            phi_377_ = true;
                                            break;
                                        }
                                        let _e190 = local_26;
                                        let _e193 = global_4.member[_e190];
                                        local_27 = bitcast<f32>(_e193);
                                        let _e195 = local_24;
                                        let _e196 = (_e195 + 2u);
                                        local_28 = _e196;
                                        let _e197 = local_1;
                                        if (_e196 < _e197) {
                                        } else {
                                            phi_377_ = true;
                                            break;
                                        }
                                        let _e199 = local_28;
                                        let _e202 = global_4.member[_e199];
                                        local_29 = bitcast<f32>(_e202);
                                        let _e204 = local_24;
                                        let _e205 = (_e204 + 3u);
                                        local_30 = _e205;
                                        let _e206 = local_1;
                                        if (_e205 < _e206) {
                                        } else {
                                            phi_377_ = true;
                                            break;
                                        }
                                        let _e208 = local_30;
                                        let _e211 = global_4.member[_e208];
                                        let _e213 = local_23;
                                        let _e214 = local_25;
                                        let _e216 = local_18;
                                        let _e219 = local_23;
                                        let _e220 = local_27;
                                        let _e222 = local_18;
                                        let _e225 = local_23;
                                        let _e226 = local_29;
                                        let _e228 = local_18;
                                        let _e231 = local_23;
                                        let _e233 = local_18;
                                        phi_286_ = array<f32, 4>((_e216[0] + (_e213 * _e214)), (_e222[1] + (_e219 * _e220)), (_e228[2] + (_e225 * _e226)), (_e233[3] + (_e231 * bitcast<f32>(_e211))));
                                    } else {
                                        phi_286_ = _e131;
                                    }
                                    let _e238 = phi_286_;
                                    phi_287_ = _e238;
                                } else {
                                    phi_287_ = _e131;
                                }
                                let _e240 = phi_287_;
                                let _e241 = local_17;
                                phi_137_ = (_e241 + 1i);
                                phi_140_ = _e240;
                            } else {
                                phi_137_ = i32();
                                phi_140_ = array<f32, 4>();
                            }
                            let _e244 = phi_137_;
                            let _e246 = phi_140_;
                            continue;
                            continuing {
                                let _e247 = local_19;
                                phi_136_ = _e244;
                                phi_139_ = _e246;
                                phi_377_ = _e86;
                                break if !(_e247);
                            }
                        }
                        let _e250 = phi_377_;
                        phi_386_ = _e250;
                        if _e250 {
                            break;
                        }
                        let _e251 = local_10;
                        let _e252 = (4u * _e251);
                        local_31 = _e252;
                        let _e253 = local_18;
                        local_32 = bitcast<u32>(_e253[0]);
                        let _e256 = local_3;
                        if (_e252 < _e256) {
                        } else {
                            phi_386_ = true;
                            break;
                        }
                        let _e258 = local_31;
                        let _e261 = local_32;
                        global_6.member[_e258] = _e261;
                        let _e262 = local_31;
                        let _e263 = (_e262 + 1u);
                        local_33 = _e263;
                        let _e264 = local_18;
                        local_34 = bitcast<u32>(_e264[1]);
                        let _e267 = local_3;
                        if (_e263 < _e267) {
                        } else {
                            phi_386_ = true;
                            break;
                        }
                        let _e269 = local_33;
                        let _e272 = local_34;
                        global_6.member[_e269] = _e272;
                        let _e273 = local_31;
                        let _e274 = (_e273 + 2u);
                        local_35 = _e274;
                        let _e275 = local_18;
                        local_36 = bitcast<u32>(_e275[2]);
                        let _e278 = local_3;
                        if (_e274 < _e278) {
                        } else {
                            phi_386_ = true;
                            break;
                        }
                        let _e280 = local_35;
                        let _e283 = local_36;
                        global_6.member[_e280] = _e283;
                        let _e284 = local_31;
                        let _e285 = (_e284 + 3u);
                        local_37 = _e285;
                        let _e286 = local_18;
                        local_38 = bitcast<u32>(_e286[3]);
                        let _e289 = local_3;
                        if (_e285 < _e289) {
                        } else {
                            phi_386_ = true;
                            break;
                        }
                        let _e291 = local_37;
                        let _e294 = local_38;
                        global_6.member[_e291] = _e294;
                        phi_388_ = _e250;
                    } else {
                        phi_388_ = _e86;
                    }
                    let _e296 = phi_388_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e297 = local_8;
                    let _e298 = local_7;
                    phi_387_ = _e296;
                    phi_87_ = (_e297 + _e298);
                } else {
                    phi_387_ = _e86;
                    phi_87_ = u32();
                }
                let _e301 = phi_387_;
                let _e303 = phi_87_;
                continue;
                continuing {
                    let _e304 = local_9;
                    phi_385_ = _e301;
                    phi_86_ = _e303;
                    phi_386_ = _e301;
                    break if !(_e304);
                }
            }
            let _e307 = phi_386_;
            if _e307 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn layered_blur(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
