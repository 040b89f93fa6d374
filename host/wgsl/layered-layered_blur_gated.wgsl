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
@group(0) @binding(3) 
var<storage> global_3: type_6;
var<immediate> global_4: type_15;
@group(0) @binding(0) 
var<storage> global_5: type_6;
@group(0) @binding(1) 
var<storage> global_6: type_6;
@group(0) @binding(2) 
var<storage, read_write> global_7: type_6;

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
    var local_15: i32;
    var local_16: bool;
    var local_17: i32;
    var local_18: i32;
    var local_19: bool;
    var local_20: i32;
    var local_21: i32;
    var local_22: array<f32, 4>;
    var local_23: bool;
    var local_24: i32;
    var local_25: u32;
    var local_26: u32;
    var local_27: f32;
    var local_28: u32;
    var local_29: f32;
    var local_30: u32;
    var local_31: f32;
    var local_32: u32;
    var local_33: f32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: i32;
    var phi_98_: bool;
    var phi_408_: bool;
    var phi_110_: u32;
    var phi_156_: i32;
    var phi_160_: i32;
    var phi_163_: array<f32, 4>;
    var phi_187_: i32;
    var phi_222_: u32;
    var phi_310_: array<f32, 4>;
    var phi_311_: array<f32, 4>;
    var phi_161_: i32;
    var phi_164_: array<f32, 4>;
    var phi_400_: bool;
    var phi_412_: bool;
    var phi_411_: bool;
    var phi_111_: u32;
    var phi_410_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e72 = global;
            local = _e72;
            let _e73 = global_1;
            let _e74 = global_2;
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = arrayLength((&global_7.member));
            local_4 = arrayLength((&global_3.member));
            local_5 = _e73.x;
            local_6 = _e74.x;
            let _e87 = global_4.member.member_7;
            local_7 = _e87;
            if (_e87 == 4294967295u) {
                phi_98_ = true;
            } else {
                let _e89 = local_7;
                let _e90 = local_4;
                if (_e89 < _e90) {
                } else {
                    break;
                }
                let _e92 = local_7;
                let _e95 = global_3.member[_e92];
                phi_98_ = (_e95 != 0u);
            }
            let _e98 = phi_98_;
            if _e98 {
                let _e101 = global_4.member.member;
                local_8 = _e101;
                let _e104 = global_4.member.member_1;
                local_9 = _e104;
                local_10 = (_e101 * _e104);
                let _e106 = local_6;
                local_11 = (_e106 * 256u);
                let _e108 = local_5;
                phi_408_ = false;
                phi_110_ = (_e108 * 256u);
                loop {
                    let _e111 = phi_408_;
                    let _e113 = phi_110_;
                    local_12 = _e113;
                    let _e114 = local_12;
                    let _e115 = local_10;
                    let _e116 = (_e114 < _e115);
                    local_13 = _e116;
                    if _e116 {
                        let _e117 = local_12;
                        let _e118 = local;
                        let _e119 = (_e117 + _e118);
                        local_14 = _e119;
                        let _e120 = local_10;
                        if (_e119 < _e120) {
                            let _e124 = global_4.member.member_3;
                            local_15 = bitcast<i32>(_e124);
                            let _e126 = local_8;
                            let _e127 = (_e126 == 0u);
                            local_16 = _e127;
                            if _e127 {
                                phi_410_ = true;
                                break;
                            }
                            let _e128 = local_14;
                            let _e129 = local_8;
                            local_17 = bitcast<i32>((_e128 % _e129));
                            let _e132 = local_16;
                            if _e132 {
                                phi_410_ = true;
                                break;
                            }
                            let _e133 = local_14;
                            let _e134 = local_8;
                            local_18 = bitcast<i32>((_e133 / _e134));
                            let _e139 = global_4.member.member_5;
                            let _e140 = (_e139 == 0u);
                            local_19 = _e140;
                            if _e140 {
                                let _e141 = local_8;
                                phi_156_ = bitcast<i32>(_e141);
                            } else {
                                let _e143 = local_9;
                                phi_156_ = bitcast<i32>(_e143);
                            }
                            let _e146 = phi_156_;
                            local_20 = _e146;
                            let _e147 = local_19;
                            let _e148 = local_17;
                            let _e149 = local_18;
                            local_43 = select(_e149, _e148, _e147);
                            let _e151 = local_15;
                            phi_160_ = -(_e151);
                            phi_163_ = array<f32, 4>(0f, 0f, 0f, 0f);
                            loop {
                                let _e154 = phi_160_;
                                let _e156 = phi_163_;
                                local_21 = _e154;
                                local_22 = _e156;
                                let _e157 = local_21;
                                let _e158 = local_15;
                                let _e159 = (_e157 <= _e158);
                                local_23 = _e159;
                                if _e159 {
                                    let _e160 = local_43;
                                    let _e161 = local_21;
                                    let _e162 = (_e160 + _e161);
                                    local_24 = _e162;
                                    if (_e162 >= 0i) {
                                        let _e164 = local_24;
                                        let _e165 = local_20;
                                        if (_e164 < _e165) {
                                            let _e169 = global_4.member.member_4;
                                            local_25 = _e169;
                                            let _e170 = local_21;
                                            if (_e170 < 0i) {
                                                let _e172 = local_21;
                                                phi_187_ = (0i - _e172);
                                            } else {
                                                phi_187_ = _e154;
                                            }
                                            let _e175 = phi_187_;
                                            let _e177 = local_25;
                                            let _e178 = (_e177 + bitcast<u32>(_e175));
                                            local_26 = _e178;
                                            let _e179 = local_2;
                                            if (_e178 < _e179) {
                                            } else {
                                                phi_400_ = true;
                                                break;
                                            }
                                            let _e181 = local_26;
                                            let _e184 = global_6.member[_e181];
                                            local_27 = bitcast<f32>(_e184);
                                            let _e186 = local_19;
                                            if _e186 {
                                                let _e187 = local_17;
                                                let _e189 = local_14;
                                                let _e191 = local_24;
                                                phi_222_ = ((_e189 - bitcast<u32>(_e187)) + bitcast<u32>(_e191));
                                            } else {
                                                let _e194 = local_24;
                                                let _e196 = local_8;
                                                let _e198 = local_17;
                                                phi_222_ = ((bitcast<u32>(_e194) * _e196) + bitcast<u32>(_e198));
                                            }
                                            let _e202 = phi_222_;
                                            let _e203 = (4u * _e202);
                                            local_28 = _e203;
                                            let _e204 = local_1;
                                            if (_e203 < _e204) {
                                            } else {
                                                phi_400_ = true;
                                                break;
                                            }
                                            let _e206 = local_28;
                                            let _e209 = global_5.member[_e206];
                                            local_29 = bitcast<f32>(_e209);
                                            let _e211 = local_28;
                                            let _e212 = (_e211 + 1u);
                                            local_30 = _e212;
                                            let _e213 = local_1;
                                            if (_e212 < _e213) {
                                            } else {
                                                phi_400_ = true;
                                                break;
                                            }
                                            let _e215 = local_30;
                                            let _e218 = global_5.member[_e215];
                                            local_31 = bitcast<f32>(_e218);
                                            let _e220 = local_28;
                                            let _e221 = (_e220 + 2u);
                                            local_32 = _e221;
                                            let _e222 = local_1;
                                            if (_e221 < _e222) {
                                            } else {
                                                phi_400_ = true;
                                                break;
                                            }
                                            let _e224 = local_32;
                                            let _e227 = global_5.member[_e224];
                                            local_33 = bitcast<f32>(_e227);
                                            let _e229 = local_28;
                                            let _e230 = (_e229 + 3u);
                                            local_34 = _e230;
                                            let _e231 = local_1;
                                            if (_e230 < _e231) {
                                            } else {
                                                phi_400_ = true;
                                                break;
                                            }
                                            let _e233 = local_34;
                                            let _e236 = global_5.member[_e233];
                                            let _e238 = local_27;
                                            let _e239 = local_29;
                                            let _e241 = local_22;
                                            let _e244 = local_27;
                                            let _e245 = local_31;
                                            let _e247 = local_22;
                                            let _e250 = local_27;
                                            let _e251 = local_33;
                                            let _e253 = local_22;
                                            let _e256 = local_27;
                                            let _e258 = local_22;
                                            phi_310_ = array<f32, 4>((_e241[0] + (_e238 * _e239)), (_e247[1] + (_e244 * _e245)), (_e253[2] + (_e250 * _e251)), (_e258[3] + (_e256 * bitcast<f32>(_e236))));
                                        } else {
                                            phi_310_ = _e156;
                                        }
                                        let _e263 = phi_310_;
                                        phi_311_ = _e263;
                                    } else {
                                        phi_311_ = _e156;
                                    }
                                    let _e265 = phi_311_;
                                    let _e266 = local_21;
                                    phi_161_ = (_e266 + 1i);
                                    phi_164_ = _e265;
                                } else {
                                    phi_161_ = i32();
                                    phi_164_ = array<f32, 4>();
                                }
                                let _e269 = phi_161_;
                                let _e271 = phi_164_;
                                continue;
                                continuing {
                                    let _e272 = local_23;
                                    phi_160_ = _e269;
                                    phi_163_ = _e271;
                                    phi_400_ = _e111;
                                    break if !(_e272);
                                }
                            }
                            let _e275 = phi_400_;
                            phi_410_ = _e275;
                            if _e275 {
                                break;
                            }
                            let _e276 = local_14;
                            let _e277 = (4u * _e276);
                            local_35 = _e277;
                            let _e278 = local_22;
                            local_36 = bitcast<u32>(_e278[0]);
                            let _e281 = local_3;
                            if (_e277 < _e281) {
                            } else {
                                phi_410_ = true;
                                break;
                            }
                            let _e283 = local_35;
                            let _e286 = local_36;
                            global_7.member[_e283] = _e286;
                            let _e287 = local_35;
                            let _e288 = (_e287 + 1u);
                            local_37 = _e288;
                            let _e289 = local_22;
                            local_38 = bitcast<u32>(_e289[1]);
                            let _e292 = local_3;
                            if (_e288 < _e292) {
                            } else {
                                phi_410_ = true;
                                break;
                            }
                            let _e294 = local_37;
                            let _e297 = local_38;
                            global_7.member[_e294] = _e297;
                            let _e298 = local_35;
                            let _e299 = (_e298 + 2u);
                            local_39 = _e299;
                            let _e300 = local_22;
                            local_40 = bitcast<u32>(_e300[2]);
                            let _e303 = local_3;
                            if (_e299 < _e303) {
                            } else {
                                phi_410_ = true;
                                break;
                            }
                            let _e305 = local_39;
                            let _e308 = local_40;
                            global_7.member[_e305] = _e308;
                            let _e309 = local_35;
                            let _e310 = (_e309 + 3u);
                            local_41 = _e310;
                            let _e311 = local_22;
                            local_42 = bitcast<u32>(_e311[3]);
                            let _e314 = local_3;
                            if (_e310 < _e314) {
                            } else {
                                phi_410_ = true;
                                break;
                            }
                            let _e316 = local_41;
                            let _e319 = local_42;
                            global_7.member[_e316] = _e319;
                            phi_412_ = _e275;
                        } else {
                            phi_412_ = _e111;
                        }
                        let _e321 = phi_412_;
                        storageBarrier();
                        workgroupBarrier();
                        let _e322 = local_12;
                        let _e323 = local_11;
                        phi_411_ = _e321;
                        phi_111_ = (_e322 + _e323);
                    } else {
                        phi_411_ = _e111;
                        phi_111_ = u32();
                    }
                    let _e326 = phi_411_;
                    let _e328 = phi_111_;
                    continue;
                    continuing {
                        let _e329 = local_13;
                        phi_408_ = _e326;
                        phi_110_ = _e328;
                        phi_410_ = _e326;
                        break if !(_e329);
                    }
                }
                let _e332 = phi_410_;
                if _e332 {
                    break;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn layered_blur_gated(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
