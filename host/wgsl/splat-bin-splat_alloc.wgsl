struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_13 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
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
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: f32,
    member_12: f32,
    member_13: f32,
    member_14: f32,
    member_15: type_5,
    member_16: type_13,
    member_17: u32,
    member_18: u32,
}

struct type_15 {
    member: type_14,
}

struct type_24 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_15;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_24;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: type_14;
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: bool;
    var local_18: u32;
    var local_19: bool;
    var local_20: u32;
    var local_21: u32;
    var local_22: i32;
    var local_23: bool;
    var local_24: i32;
    var local_25: bool;
    var local_26: i32;
    var local_27: i32;
    var local_28: i32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: bool;
    var local_33: bool;
    var local_34: u32;
    var phi_509_: bool;
    var phi_178_: u32;
    var phi_508_: bool;
    var phi_212_: bool;
    var phi_215_: i32;
    var phi_228_: bool;
    var phi_231_: i32;
    var phi_413_: bool;
    var phi_414_: bool;
    var phi_415_: bool;
    var phi_416_: bool;
    var phi_417_: bool;
    var phi_418_: bool;
    var phi_419_: bool;
    var phi_420_: bool;
    var phi_421_: bool;
    var phi_426_: bool;
    var phi_427_: i32;
    var phi_229_: bool;
    var phi_232_: i32;
    var phi_429_: bool;
    var phi_504_: bool;
    var phi_527_: bool;
    var phi_431_: bool;
    var phi_432_: i32;
    var phi_526_: bool;
    var phi_213_: bool;
    var phi_216_: i32;
    var phi_434_: bool;
    var phi_525_: bool;
    var phi_530_: bool;
    var phi_529_: bool;
    var phi_179_: u32;
    var phi_528_: bool;
    var local_35: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e62 = global;
            local = _e62;
            let _e63 = global_1;
            let _e64 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            let _e73 = arrayLength((&global_7.member));
            local_4 = _e73;
            local_5 = _e63.x;
            local_6 = _e64.x;
            let _e76 = global_3.member;
            local_7 = _e76;
            if (18u < _e73) {
            } else {
                break;
            }
            let _e80 = atomicLoad((&global_7.member[18u]));
            local_8 = _e80;
            let _e81 = local_4;
            if (19u < _e81) {
            } else {
                break;
            }
            let _e83 = local_7;
            local_9 = _e83.member;
            let _e85 = local_7;
            local_10 = _e85.member_1;
            let _e87 = local_7;
            local_11 = _e87.member_6;
            let _e89 = local_7;
            local_12 = _e89.member_7;
            let _e91 = local_7;
            local_13 = _e91.member_8;
            local_14 = (_e89.member_7 * _e91.member_8);
            let _e94 = local_6;
            local_15 = (_e94 * 256u);
            let _e96 = local_5;
            phi_509_ = false;
            phi_178_ = (_e96 * 256u);
            loop {
                let _e99 = phi_509_;
                let _e101 = phi_178_;
                local_16 = _e101;
                let _e102 = local_16;
                let _e103 = local_14;
                let _e104 = (_e102 < _e103);
                local_17 = _e104;
                if _e104 {
                    let _e105 = local_16;
                    let _e106 = local;
                    let _e107 = (_e105 + _e106);
                    local_18 = _e107;
                    let _e108 = local_14;
                    if (_e107 < _e108) {
                        let _e110 = local_12;
                        let _e111 = (_e110 == 0u);
                        local_19 = _e111;
                        if _e111 {
                            phi_528_ = true;
                            break;
                        }
                        let _e112 = local_18;
                        let _e113 = local_12;
                        local_20 = (_e112 % _e113);
                        let _e115 = local_19;
                        if _e115 {
                            phi_528_ = true;
                            break;
                        }
                        let _e116 = local_18;
                        let _e117 = local_12;
                        local_21 = (_e116 / _e117);
                        let _e119 = local_8;
                        let _e120 = bitcast<i32>(_e119);
                        local_22 = _e120;
                        let _e121 = -(_e120);
                        phi_508_ = _e99;
                        phi_212_ = false;
                        phi_215_ = _e121;
                        loop {
                            let _e123 = phi_508_;
                            let _e125 = phi_212_;
                            let _e127 = phi_215_;
                            local_23 = _e125;
                            local_24 = _e127;
                            let _e128 = local_24;
                            let _e129 = local_22;
                            if (_e128 <= _e129) {
                                let _e131 = local_23;
                                if _e131 {
                                    phi_527_ = _e123;
                                    phi_431_ = bool();
                                    phi_432_ = i32();
                                } else {
                                    phi_228_ = _e125;
                                    phi_231_ = _e121;
                                    loop {
                                        let _e133 = phi_228_;
                                        let _e135 = phi_231_;
                                        local_25 = _e133;
                                        local_26 = _e135;
                                        local_35 = _e133;
                                        let _e136 = local_26;
                                        let _e137 = local_22;
                                        if (_e136 <= _e137) {
                                            let _e139 = local_25;
                                            if _e139 {
                                                phi_426_ = bool();
                                                phi_427_ = i32();
                                            } else {
                                                let _e140 = local_20;
                                                let _e142 = local_26;
                                                let _e143 = (bitcast<i32>(_e140) + _e142);
                                                local_27 = _e143;
                                                let _e144 = local_21;
                                                let _e146 = local_24;
                                                local_28 = (bitcast<i32>(_e144) + _e146);
                                                let _e148 = local_26;
                                                if (_e143 < 0i) {
                                                    phi_420_ = bool();
                                                    phi_421_ = true;
                                                } else {
                                                    let _e151 = local_28;
                                                    if (_e151 < 0i) {
                                                        phi_418_ = bool();
                                                        phi_419_ = true;
                                                    } else {
                                                        let _e153 = local_12;
                                                        let _e155 = local_27;
                                                        if (_e155 >= bitcast<i32>(_e153)) {
                                                            phi_416_ = bool();
                                                            phi_417_ = true;
                                                        } else {
                                                            let _e157 = local_13;
                                                            let _e159 = local_28;
                                                            let _e160 = (_e159 >= bitcast<i32>(_e157));
                                                            if _e160 {
                                                                phi_415_ = bool();
                                                            } else {
                                                                let _e161 = local_28;
                                                                let _e162 = bitcast<u32>(_e161);
                                                                local_29 = _e162;
                                                                let _e163 = local_12;
                                                                let _e165 = local_27;
                                                                let _e166 = bitcast<u32>(_e165);
                                                                local_30 = _e166;
                                                                let _e167 = ((_e162 * _e163) + _e166);
                                                                local_31 = _e167;
                                                                let _e168 = local_1;
                                                                if (_e167 < _e168) {
                                                                } else {
                                                                    phi_504_ = true;
                                                                    break;
                                                                }
                                                                let _e170 = local_31;
                                                                let _e173 = global_4.member[_e170];
                                                                if (_e173 > 0u) {
                                                                    let _e175 = local_31;
                                                                    let _e176 = local_18;
                                                                    if (_e175 == _e176) {
                                                                        phi_413_ = true;
                                                                    } else {
                                                                        let _e178 = local_31;
                                                                        let _e179 = local_2;
                                                                        if (_e178 < _e179) {
                                                                        } else {
                                                                            phi_504_ = true;
                                                                            break;
                                                                        }
                                                                        let _e181 = local_31;
                                                                        let _e184 = global_5.member[_e181];
                                                                        let _e185 = bitcast<f32>(_e184);
                                                                        let _e186 = local_30;
                                                                        let _e188 = local_11;
                                                                        let _e189 = ((_e186 + 1u) * _e188);
                                                                        let _e190 = local_9;
                                                                        let _e192 = local_9;
                                                                        let _e194 = local_30;
                                                                        let _e195 = local_11;
                                                                        let _e199 = local_29;
                                                                        let _e201 = local_11;
                                                                        let _e202 = ((_e199 + 1u) * _e201);
                                                                        let _e203 = local_10;
                                                                        let _e205 = local_10;
                                                                        let _e207 = local_29;
                                                                        let _e208 = local_11;
                                                                        let _e212 = local_20;
                                                                        let _e214 = local_11;
                                                                        let _e215 = ((_e212 + 1u) * _e214);
                                                                        let _e216 = local_9;
                                                                        let _e218 = local_9;
                                                                        let _e220 = local_20;
                                                                        let _e221 = local_11;
                                                                        let _e225 = local_21;
                                                                        let _e227 = local_11;
                                                                        let _e228 = ((_e225 + 1u) * _e227);
                                                                        let _e229 = local_10;
                                                                        let _e231 = local_10;
                                                                        let _e233 = local_21;
                                                                        let _e234 = local_11;
                                                                        let _e240 = ((f32((_e220 * _e221)) + 0.5f) - f32(select(_e192, _e189, (_e189 < _e190))));
                                                                        let _e241 = (f32((_e194 * _e195)) - (f32(select(_e218, _e215, (_e215 < _e216))) - 0.5f));
                                                                        let _e243 = select(_e241, _e240, (_e240 > _e241));
                                                                        let _e245 = select(0f, _e243, (_e243 > 0f));
                                                                        let _e248 = ((f32((_e233 * _e234)) + 0.5f) - f32(select(_e205, _e202, (_e202 < _e203))));
                                                                        let _e249 = (f32((_e207 * _e208)) - (f32(select(_e231, _e228, (_e228 < _e229))) - 0.5f));
                                                                        let _e251 = select(_e249, _e248, (_e248 > _e249));
                                                                        let _e253 = select(0f, _e251, (_e251 > 0f));
                                                                        phi_413_ = (((_e245 * _e245) + (_e253 * _e253)) <= (_e185 * _e185));
                                                                    }
                                                                    let _e260 = phi_413_;
                                                                    phi_414_ = _e260;
                                                                } else {
                                                                    phi_414_ = false;
                                                                }
                                                                let _e262 = phi_414_;
                                                                phi_415_ = _e262;
                                                            }
                                                            let _e264 = phi_415_;
                                                            phi_416_ = _e264;
                                                            phi_417_ = _e160;
                                                        }
                                                        let _e266 = phi_416_;
                                                        let _e268 = phi_417_;
                                                        phi_418_ = _e266;
                                                        phi_419_ = _e268;
                                                    }
                                                    let _e270 = phi_418_;
                                                    let _e272 = phi_419_;
                                                    phi_420_ = _e270;
                                                    phi_421_ = _e272;
                                                }
                                                let _e274 = phi_420_;
                                                let _e276 = phi_421_;
                                                let _e277 = local_25;
                                                phi_426_ = select(_e274, _e277, _e276);
                                                phi_427_ = (_e148 + 1i);
                                            }
                                            let _e280 = phi_426_;
                                            let _e282 = phi_427_;
                                            let _e283 = local_25;
                                            phi_229_ = _e280;
                                            phi_232_ = _e282;
                                            phi_429_ = select(true, false, _e283);
                                        } else {
                                            phi_229_ = bool();
                                            phi_232_ = i32();
                                            phi_429_ = false;
                                        }
                                        let _e286 = phi_229_;
                                        let _e288 = phi_232_;
                                        let _e290 = phi_429_;
                                        local_32 = _e290;
                                        continue;
                                        continuing {
                                            let _e291 = local_32;
                                            phi_228_ = _e286;
                                            phi_231_ = _e288;
                                            phi_504_ = _e123;
                                            break if !(_e291);
                                        }
                                    }
                                    let _e294 = phi_504_;
                                    phi_525_ = _e294;
                                    if _e294 {
                                        break;
                                    }
                                    let _e295 = local_24;
                                    phi_527_ = _e294;
                                    let _e371 = local_35;
                                    phi_431_ = _e371;
                                    phi_432_ = (_e295 + 1i);
                                }
                                let _e298 = phi_527_;
                                let _e300 = phi_431_;
                                let _e302 = phi_432_;
                                let _e303 = local_23;
                                phi_526_ = _e298;
                                phi_213_ = _e300;
                                phi_216_ = _e302;
                                phi_434_ = select(true, false, _e303);
                            } else {
                                phi_526_ = _e123;
                                phi_213_ = bool();
                                phi_216_ = i32();
                                phi_434_ = false;
                            }
                            let _e306 = phi_526_;
                            let _e308 = phi_213_;
                            let _e310 = phi_216_;
                            let _e312 = phi_434_;
                            local_33 = _e312;
                            continue;
                            continuing {
                                let _e313 = local_33;
                                phi_508_ = _e306;
                                phi_212_ = _e308;
                                phi_215_ = _e310;
                                phi_525_ = _e306;
                                break if !(_e313);
                            }
                        }
                        let _e316 = phi_525_;
                        phi_528_ = _e316;
                        if _e316 {
                            break;
                        }
                        let _e317 = local_23;
                        local_34 = select(0u, 1u, !(_e317));
                        let _e320 = local_18;
                        let _e321 = local_3;
                        if (_e320 < _e321) {
                        } else {
                            phi_528_ = true;
                            break;
                        }
                        let _e323 = local_18;
                        let _e326 = local_34;
                        global_6.member[_e323] = _e326;
                        let _e327 = local_23;
                        if _e327 {
                        } else {
                            let _e328 = local_4;
                            if (7u < _e328) {
                            } else {
                                phi_528_ = true;
                                break;
                            }
                            let _e332 = atomicAdd((&global_7.member[7u]), 1u);
                        }
                        phi_530_ = _e316;
                    } else {
                        phi_530_ = _e99;
                    }
                    let _e334 = phi_530_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e335 = local_16;
                    let _e336 = local_15;
                    phi_529_ = _e334;
                    phi_179_ = (_e335 + _e336);
                } else {
                    phi_529_ = _e99;
                    phi_179_ = u32();
                }
                let _e339 = phi_529_;
                let _e341 = phi_179_;
                continue;
                continuing {
                    let _e342 = local_17;
                    phi_509_ = _e339;
                    phi_178_ = _e341;
                    phi_528_ = _e339;
                    break if !(_e342);
                }
            }
            let _e345 = phi_528_;
            if _e345 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn splat_alloc(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
