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

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_10;
@group(0) @binding(1) 
var<storage> global_5: type_10;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_10;

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
    var local_13: i32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: bool;
    var local_18: u32;
    var local_19: bool;
    var local_20: i32;
    var local_21: i32;
    var local_22: i32;
    var local_23: u32;
    var local_24: f32;
    var local_25: bool;
    var local_26: i32;
    var local_27: i32;
    var local_28: u32;
    var local_29: f32;
    var local_30: i32;
    var local_31: u32;
    var local_32: f32;
    var local_33: bool;
    var local_34: f32;
    var local_35: f32;
    var local_36: bool;
    var local_37: f32;
    var local_38: u32;
    var local_39: u32;
    var local_40: f32;
    var local_41: bool;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var phi_108_: u32;
    var phi_124_: u32;
    var phi_142_: u32;
    var phi_158_: u32;
    var phi_177_: u32;
    var phi_520_: bool;
    var phi_185_: u32;
    var phi_519_: bool;
    var phi_217_: i32;
    var phi_220_: u32;
    var phi_222_: f32;
    var phi_235_: i32;
    var phi_238_: u32;
    var phi_240_: f32;
    var phi_281_: f32;
    var phi_296_: f32;
    var phi_394_: f32;
    var phi_401_: f32;
    var phi_420_: u32;
    var phi_421_: u32;
    var phi_422_: u32;
    var phi_423_: f32;
    var phi_424_: u32;
    var phi_425_: f32;
    var phi_427_: i32;
    var phi_428_: u32;
    var phi_429_: f32;
    var phi_431_: i32;
    var phi_432_: u32;
    var phi_433_: f32;
    var phi_434_: bool;
    var phi_236_: i32;
    var phi_239_: u32;
    var phi_241_: f32;
    var phi_436_: bool;
    var phi_499_: bool;
    var phi_527_: bool;
    var phi_218_: i32;
    var phi_221_: u32;
    var phi_223_: f32;
    var phi_526_: bool;
    var phi_530_: bool;
    var phi_529_: bool;
    var phi_186_: u32;
    var phi_528_: bool;
    var local_45: u32;
    var local_46: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e76 = global;
            local = _e76;
            let _e77 = global_1;
            let _e78 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = _e77.x;
            local_5 = _e78.x;
            let _e89 = global_3.member.member;
            let _e90 = (_e89 / 2u);
            local_6 = _e90;
            if ((_e89 % 2u) > 0u) {
                let _e93 = local_6;
                phi_108_ = (_e93 + 1u);
            } else {
                phi_108_ = _e90;
            }
            let _e96 = phi_108_;
            let _e97 = (_e96 / 8u);
            local_7 = _e97;
            if ((_e96 % 8u) > 0u) {
                let _e100 = local_7;
                phi_124_ = (_e100 + 1u);
            } else {
                phi_124_ = _e97;
            }
            let _e103 = phi_124_;
            local_8 = _e103;
            let _e106 = global_3.member.member_1;
            let _e107 = (_e106 / 2u);
            local_9 = _e107;
            if ((_e106 % 2u) > 0u) {
                let _e110 = local_9;
                phi_142_ = (_e110 + 1u);
            } else {
                phi_142_ = _e107;
            }
            let _e113 = phi_142_;
            let _e114 = (_e113 / 8u);
            local_10 = _e114;
            if ((_e113 % 8u) > 0u) {
                let _e117 = local_10;
                phi_158_ = (_e117 + 1u);
            } else {
                phi_158_ = _e114;
            }
            let _e120 = phi_158_;
            local_11 = _e120;
            let _e123 = global_3.member.member_3;
            let _e124 = (_e123 + 1u);
            let _e125 = (_e124 / 16u);
            local_12 = _e125;
            if ((_e124 % 16u) > 0u) {
                let _e128 = local_12;
                phi_177_ = (_e128 + 1u);
            } else {
                phi_177_ = _e125;
            }
            let _e131 = phi_177_;
            local_13 = bitcast<i32>(_e131);
            let _e133 = local_8;
            let _e134 = local_11;
            local_14 = (_e133 * _e134);
            let _e136 = local_5;
            local_15 = (_e136 * 64u);
            let _e138 = local_4;
            phi_520_ = false;
            phi_185_ = (_e138 * 64u);
            loop {
                let _e141 = phi_520_;
                let _e143 = phi_185_;
                local_16 = _e143;
                let _e144 = local_16;
                let _e145 = local_14;
                let _e146 = (_e144 < _e145);
                local_17 = _e146;
                if _e146 {
                    let _e147 = local_16;
                    let _e148 = local;
                    let _e149 = (_e147 + _e148);
                    local_18 = _e149;
                    let _e150 = local_14;
                    if (_e149 < _e150) {
                        let _e152 = local_8;
                        let _e153 = (_e152 == 0u);
                        local_19 = _e153;
                        if _e153 {
                            phi_528_ = true;
                            break;
                        }
                        let _e154 = local_18;
                        let _e155 = local_8;
                        local_20 = bitcast<i32>((_e154 % _e155));
                        let _e158 = local_19;
                        if _e158 {
                            phi_528_ = true;
                            break;
                        }
                        let _e159 = local_18;
                        let _e160 = local_8;
                        local_21 = bitcast<i32>((_e159 / _e160));
                        let _e163 = local_13;
                        let _e164 = -(_e163);
                        phi_519_ = _e141;
                        phi_217_ = _e164;
                        phi_220_ = 0u;
                        phi_222_ = 0f;
                        loop {
                            let _e166 = phi_519_;
                            let _e168 = phi_217_;
                            let _e170 = phi_220_;
                            let _e172 = phi_222_;
                            local_22 = _e168;
                            local_23 = _e170;
                            local_24 = _e172;
                            let _e173 = local_22;
                            let _e174 = local_13;
                            let _e175 = (_e173 <= _e174);
                            local_25 = _e175;
                            if _e175 {
                                let _e176 = local_21;
                                let _e177 = local_22;
                                local_26 = (_e176 + _e177);
                                phi_235_ = _e164;
                                phi_238_ = _e170;
                                phi_240_ = _e172;
                                loop {
                                    let _e180 = phi_235_;
                                    let _e182 = phi_238_;
                                    let _e184 = phi_240_;
                                    local_27 = _e180;
                                    local_28 = _e182;
                                    local_29 = _e184;
                                    local_45 = _e182;
                                    local_46 = _e184;
                                    let _e185 = local_26;
                                    if (_e185 >= 0i) {
                                        let _e187 = local_11;
                                        let _e189 = local_26;
                                        if (_e189 < bitcast<i32>(_e187)) {
                                            let _e191 = local_27;
                                            let _e192 = local_13;
                                            let _e193 = (_e191 <= _e192);
                                            if _e193 {
                                                let _e194 = local_20;
                                                let _e195 = local_27;
                                                let _e196 = (_e194 + _e195);
                                                local_30 = _e196;
                                                if (_e196 >= 0i) {
                                                    let _e198 = local_8;
                                                    let _e200 = local_30;
                                                    if (_e200 < bitcast<i32>(_e198)) {
                                                        let _e202 = local_26;
                                                        let _e204 = local_8;
                                                        let _e206 = local_30;
                                                        local_31 = ((bitcast<u32>(_e202) * _e204) + bitcast<u32>(_e206));
                                                        let _e209 = local_27;
                                                        let _e210 = f32(_e209);
                                                        local_32 = _e210;
                                                        let _e211 = (_e210 < 0f);
                                                        local_33 = _e211;
                                                        if _e211 {
                                                            let _e212 = local_32;
                                                            phi_281_ = -(_e212);
                                                        } else {
                                                            phi_281_ = _e210;
                                                        }
                                                        let _e215 = phi_281_;
                                                        let _e216 = (_e215 - 1f);
                                                        local_34 = (select(0f, _e216, (_e216 > 0f)) * 8f);
                                                        let _e220 = local_22;
                                                        let _e221 = f32(_e220);
                                                        local_35 = _e221;
                                                        let _e222 = (_e221 < 0f);
                                                        local_36 = _e222;
                                                        if _e222 {
                                                            let _e223 = local_35;
                                                            phi_296_ = -(_e223);
                                                        } else {
                                                            phi_296_ = _e221;
                                                        }
                                                        let _e226 = phi_296_;
                                                        let _e227 = (_e226 - 1f);
                                                        let _e230 = (select(0f, _e227, (_e227 > 0f)) * 8f);
                                                        let _e231 = local_34;
                                                        let _e232 = local_34;
                                                        local_37 = sqrt(((_e231 * _e232) + (_e230 * _e230)));
                                                        let _e237 = local_31;
                                                        let _e238 = local_1;
                                                        if (_e237 < _e238) {
                                                        } else {
                                                            phi_499_ = true;
                                                            break;
                                                        }
                                                        let _e240 = local_31;
                                                        let _e243 = global_4.member[_e240];
                                                        let _e244 = bitcast<f32>(_e243);
                                                        let _e245 = local_37;
                                                        let _e248 = (((_e244 - _e245) * 0.125f) + 1f);
                                                        let _e250 = select(0f, _e248, (_e248 > 0f));
                                                        let _e253 = (_e244 * select(1f, _e250, (_e250 < 1f)));
                                                        let _e254 = local_29;
                                                        let _e256 = local_29;
                                                        let _e258 = local_31;
                                                        let _e259 = (66u * _e258);
                                                        local_38 = _e259;
                                                        let _e260 = local_2;
                                                        if (_e259 < _e260) {
                                                        } else {
                                                            phi_499_ = true;
                                                            break;
                                                        }
                                                        let _e262 = local_38;
                                                        let _e265 = global_5.member[_e262];
                                                        if (_e265 > 0u) {
                                                            let _e267 = local_38;
                                                            let _e268 = (_e267 + 1u);
                                                            local_39 = _e268;
                                                            let _e269 = local_2;
                                                            if (_e268 < _e269) {
                                                            } else {
                                                                phi_499_ = true;
                                                                break;
                                                            }
                                                            let _e271 = local_39;
                                                            let _e274 = global_5.member[_e271];
                                                            let _e277 = local_37;
                                                            if ((bitcast<f32>(_e274) + 1f) >= (2f * _e277)) {
                                                                let _e280 = local_33;
                                                                if _e280 {
                                                                    let _e281 = local_32;
                                                                    phi_394_ = -(_e281);
                                                                } else {
                                                                    phi_394_ = _e210;
                                                                }
                                                                let _e284 = phi_394_;
                                                                local_40 = _e284;
                                                                let _e285 = local_36;
                                                                if _e285 {
                                                                    let _e286 = local_35;
                                                                    phi_401_ = -(_e286);
                                                                } else {
                                                                    phi_401_ = _e221;
                                                                }
                                                                let _e289 = phi_401_;
                                                                let _e290 = local_40;
                                                                let _e292 = local_40;
                                                                let _e293 = select(_e289, _e292, (_e290 > _e289));
                                                                let _e300 = (select(select(u32(_e293), 0u, !((_e293 >= 0f))), 4294967295u, (_e293 > 4294967000f)) + 1u);
                                                                let _e301 = local_28;
                                                                let _e303 = local_28;
                                                                phi_420_ = select(_e303, _e300, (_e300 > _e301));
                                                            } else {
                                                                phi_420_ = _e182;
                                                            }
                                                            let _e306 = phi_420_;
                                                            phi_421_ = _e306;
                                                        } else {
                                                            phi_421_ = _e182;
                                                        }
                                                        let _e308 = phi_421_;
                                                        phi_422_ = _e308;
                                                        phi_423_ = select(_e253, _e256, (_e254 > _e253));
                                                    } else {
                                                        phi_422_ = _e182;
                                                        phi_423_ = _e184;
                                                    }
                                                    let _e310 = phi_422_;
                                                    let _e312 = phi_423_;
                                                    phi_424_ = _e310;
                                                    phi_425_ = _e312;
                                                } else {
                                                    phi_424_ = _e182;
                                                    phi_425_ = _e184;
                                                }
                                                let _e314 = phi_424_;
                                                let _e316 = phi_425_;
                                                let _e317 = local_27;
                                                phi_427_ = (_e317 + 1i);
                                                phi_428_ = _e314;
                                                phi_429_ = _e316;
                                            } else {
                                                phi_427_ = i32();
                                                phi_428_ = u32();
                                                phi_429_ = f32();
                                            }
                                            let _e320 = phi_427_;
                                            let _e322 = phi_428_;
                                            let _e324 = phi_429_;
                                            phi_431_ = _e320;
                                            phi_432_ = _e322;
                                            phi_433_ = _e324;
                                            phi_434_ = _e193;
                                        } else {
                                            phi_431_ = i32();
                                            phi_432_ = u32();
                                            phi_433_ = f32();
                                            phi_434_ = false;
                                        }
                                        let _e326 = phi_431_;
                                        let _e328 = phi_432_;
                                        let _e330 = phi_433_;
                                        let _e332 = phi_434_;
                                        phi_236_ = _e326;
                                        phi_239_ = _e328;
                                        phi_241_ = _e330;
                                        phi_436_ = _e332;
                                    } else {
                                        phi_236_ = i32();
                                        phi_239_ = u32();
                                        phi_241_ = f32();
                                        phi_436_ = false;
                                    }
                                    let _e334 = phi_236_;
                                    let _e336 = phi_239_;
                                    let _e338 = phi_241_;
                                    let _e340 = phi_436_;
                                    local_41 = _e340;
                                    continue;
                                    continuing {
                                        let _e341 = local_41;
                                        phi_235_ = _e334;
                                        phi_238_ = _e336;
                                        phi_240_ = _e338;
                                        phi_499_ = _e166;
                                        break if !(_e341);
                                    }
                                }
                                let _e344 = phi_499_;
                                phi_526_ = _e344;
                                if _e344 {
                                    break;
                                }
                                let _e345 = local_22;
                                phi_527_ = _e344;
                                phi_218_ = (_e345 + 1i);
                                let _e430 = local_45;
                                phi_221_ = _e430;
                                let _e433 = local_46;
                                phi_223_ = _e433;
                            } else {
                                phi_527_ = _e166;
                                phi_218_ = i32();
                                phi_221_ = u32();
                                phi_223_ = f32();
                            }
                            let _e348 = phi_527_;
                            let _e350 = phi_218_;
                            let _e352 = phi_221_;
                            let _e354 = phi_223_;
                            continue;
                            continuing {
                                let _e355 = local_25;
                                phi_519_ = _e348;
                                phi_217_ = _e350;
                                phi_220_ = _e352;
                                phi_222_ = _e354;
                                phi_526_ = _e348;
                                break if !(_e355);
                            }
                        }
                        let _e358 = phi_526_;
                        phi_528_ = _e358;
                        if _e358 {
                            break;
                        }
                        let _e359 = local_18;
                        let _e360 = (2u * _e359);
                        local_42 = _e360;
                        let _e361 = local_24;
                        local_43 = bitcast<u32>(_e361);
                        let _e363 = local_3;
                        if (_e360 < _e363) {
                        } else {
                            phi_528_ = true;
                            break;
                        }
                        let _e365 = local_42;
                        let _e368 = local_43;
                        global_6.member[_e365] = _e368;
                        let _e369 = local_42;
                        let _e370 = (_e369 + 1u);
                        local_44 = _e370;
                        let _e371 = local_3;
                        if (_e370 < _e371) {
                        } else {
                            phi_528_ = true;
                            break;
                        }
                        let _e373 = local_44;
                        let _e376 = local_23;
                        global_6.member[_e373] = _e376;
                        phi_530_ = _e358;
                    } else {
                        phi_530_ = _e141;
                    }
                    let _e378 = phi_530_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e379 = local_16;
                    let _e380 = local_15;
                    phi_529_ = _e378;
                    phi_186_ = (_e379 + _e380);
                } else {
                    phi_529_ = _e141;
                    phi_186_ = u32();
                }
                let _e383 = phi_529_;
                let _e385 = phi_186_;
                continue;
                continuing {
                    let _e386 = local_17;
                    phi_520_ = _e383;
                    phi_185_ = _e385;
                    phi_528_ = _e383;
                    break if !(_e386);
                }
            }
            let _e389 = phi_528_;
            if _e389 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn ring_gather_dilate(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
