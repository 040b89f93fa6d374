struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_17 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_18 {
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
    member_16: type_17,
    member_17: u32,
    member_18: u32,
}

struct type_19 {
    member: type_18,
}

struct type_26 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<workgroup> global_3: array<u32, 512>;
@group(0) @binding(1) 
var<storage> global_4: type_7;
var<immediate> global_5: type_19;
@group(0) @binding(0) 
var<storage> global_6: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_7: type_26;
var<private> global_8: u32 = 2143289344u;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: f32;
    var local_8: bool;
    var local_9: u32;
    var local_10: u32;
    var local_11: bool;
    var local_12: f32;
    var local_13: f32;
    var local_14: bool;
    var local_15: u32;
    var local_16: f32;
    var local_17: u32;
    var local_18: f32;
    var local_19: u32;
    var local_20: f32;
    var local_21: u32;
    var local_22: f32;
    var local_23: u32;
    var local_24: f32;
    var local_25: bool;
    var local_26: u32;
    var local_27: u32;
    var local_28: f32;
    var local_29: f32;
    var local_30: f32;
    var local_31: u32;
    var local_32: bool;
    var local_33: u32;
    var local_34: bool;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: bool;
    var local_40: u32;
    var phi_604_: bool;
    var phi_103_: u32;
    var phi_106_: f32;
    var phi_131_: u32;
    var phi_134_: bool;
    var phi_136_: f32;
    var phi_138_: f32;
    var phi_220_: bool;
    var phi_221_: bool;
    var phi_223_: bool;
    var phi_224_: bool;
    var phi_225_: bool;
    var phi_226_: bool;
    var phi_243_: f32;
    var phi_274_: bool;
    var phi_302_: f32;
    var phi_303_: f32;
    var phi_309_: f32;
    var phi_311_: f32;
    var phi_325_: f32;
    var phi_326_: f32;
    var phi_132_: u32;
    var phi_135_: bool;
    var phi_137_: f32;
    var phi_139_: f32;
    var phi_590_: bool;
    var phi_338_: bool;
    var phi_339_: bool;
    var phi_421_: f32;
    var phi_611_: bool;
    var phi_104_: u32;
    var phi_107_: f32;
    var phi_610_: bool;
    var phi_518_: u32;
    var phi_519_: u32;
    var phi_622_: bool;
    var local_41: f32;

    let _e74 = global_8;
    switch bitcast<i32>(0u) {
        default: {
            let _e77 = global;
            local = _e77;
            let _e78 = global_1;
            let _e79 = global_2;
            local_1 = arrayLength((&global_6.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = arrayLength((&global_7.member));
            let _e90 = global_5.member.member;
            let _e93 = global_5.member.member_1;
            local_4 = (_e90 * _e93);
            local_5 = (_e79.x * 256u);
            phi_604_ = false;
            phi_103_ = ((_e78.x * 256u) + _e77);
            phi_106_ = 0f;
            loop {
                let _e99 = phi_604_;
                let _e101 = phi_103_;
                let _e103 = phi_106_;
                local_6 = _e101;
                local_7 = _e103;
                let _e104 = local_6;
                let _e105 = local_4;
                let _e106 = (_e104 < _e105);
                local_8 = _e106;
                if _e106 {
                    let _e107 = local_6;
                    let _e108 = local_2;
                    if (_e107 < _e108) {
                    } else {
                        phi_610_ = true;
                        break;
                    }
                    let _e110 = local_6;
                    let _e113 = global_4.member[_e110];
                    let _e116 = global_5.member.member_2;
                    local_9 = _e116;
                    local_38 = select(_e116, _e113, (_e113 < _e116));
                    phi_131_ = 0u;
                    phi_134_ = false;
                    phi_136_ = 1f;
                    phi_138_ = _e103;
                    loop {
                        let _e120 = phi_131_;
                        let _e122 = phi_134_;
                        let _e124 = phi_136_;
                        let _e126 = phi_138_;
                        local_10 = _e120;
                        local_11 = _e122;
                        local_12 = _e124;
                        local_13 = _e126;
                        local_41 = _e126;
                        let _e127 = local_10;
                        let _e128 = local_38;
                        let _e129 = (_e127 < _e128);
                        local_14 = _e129;
                        if _e129 {
                            let _e130 = local_6;
                            let _e131 = local_9;
                            let _e133 = local_10;
                            let _e135 = (5u * ((_e130 * _e131) + _e133));
                            local_15 = _e135;
                            let _e136 = local_1;
                            if (_e135 < _e136) {
                            } else {
                                phi_590_ = true;
                                break;
                            }
                            let _e138 = local_15;
                            let _e141 = global_6.member[_e138];
                            local_16 = bitcast<f32>(_e141);
                            let _e143 = local_15;
                            let _e144 = (_e143 + 1u);
                            local_17 = _e144;
                            let _e145 = local_1;
                            if (_e144 < _e145) {
                            } else {
                                phi_590_ = true;
                                break;
                            }
                            let _e147 = local_17;
                            let _e150 = global_6.member[_e147];
                            local_18 = bitcast<f32>(_e150);
                            let _e152 = local_15;
                            let _e153 = (_e152 + 2u);
                            local_19 = _e153;
                            let _e154 = local_1;
                            if (_e153 < _e154) {
                            } else {
                                phi_590_ = true;
                                break;
                            }
                            let _e156 = local_19;
                            let _e159 = global_6.member[_e156];
                            local_20 = bitcast<f32>(_e159);
                            let _e161 = local_15;
                            let _e162 = (_e161 + 3u);
                            local_21 = _e162;
                            let _e163 = local_1;
                            if (_e162 < _e163) {
                            } else {
                                phi_590_ = true;
                                break;
                            }
                            let _e165 = local_21;
                            let _e168 = global_6.member[_e165];
                            local_22 = bitcast<f32>(_e168);
                            let _e170 = local_15;
                            let _e171 = (_e170 + 4u);
                            local_23 = _e171;
                            let _e172 = local_1;
                            if (_e171 < _e172) {
                            } else {
                                phi_590_ = true;
                                break;
                            }
                            let _e174 = local_23;
                            let _e177 = global_6.member[_e174];
                            local_24 = bitcast<f32>(_e177);
                            let _e179 = local_10;
                            let _e181 = local_16;
                            if ((bitcast<u32>(_e181) & 2139095040u) != 2139095040u) {
                                let _e185 = local_18;
                                if ((bitcast<u32>(_e185) & 2139095040u) != 2139095040u) {
                                    let _e189 = local_20;
                                    let _e192 = ((bitcast<u32>(_e189) & 2139095040u) != 2139095040u);
                                    local_25 = _e192;
                                    if _e192 {
                                        let _e193 = local_22;
                                        let _e194 = bitcast<u32>(_e193);
                                        local_26 = _e194;
                                        if (_e194 == 0u) {
                                            phi_220_ = false;
                                        } else {
                                            let _e196 = local_26;
                                            phi_220_ = (_e196 <= 2139095040u);
                                        }
                                        let _e199 = phi_220_;
                                        phi_221_ = _e199;
                                    } else {
                                        phi_221_ = bool();
                                    }
                                    let _e201 = phi_221_;
                                    let _e202 = local_25;
                                    phi_223_ = _e201;
                                    phi_224_ = select(true, false, _e202);
                                } else {
                                    phi_223_ = bool();
                                    phi_224_ = true;
                                }
                                let _e205 = phi_223_;
                                let _e207 = phi_224_;
                                phi_225_ = _e205;
                                phi_226_ = _e207;
                            } else {
                                phi_225_ = bool();
                                phi_226_ = true;
                            }
                            let _e209 = phi_225_;
                            let _e211 = phi_226_;
                            let _e212 = select(_e209, false, _e211);
                            local_39 = _e212;
                            if _e212 {
                                let _e213 = local_24;
                                if (_e213 > 1f) {
                                    phi_243_ = 1f;
                                } else {
                                    let _e215 = local_24;
                                    let _e217 = local_24;
                                    phi_243_ = select(0f, _e217, (_e215 >= 0f));
                                }
                                let _e220 = phi_243_;
                                let _e222 = local_12;
                                let _e224 = local_22;
                                let _e225 = bitcast<u32>(_e224);
                                local_27 = _e225;
                                if (_e225 == 2139095040u) {
                                    let _e274 = global_5.member.member_15.member_1;
                                    let _e279 = global_5.member.member_15.member;
                                    let _e284 = global_5.member.member_15.member_2;
                                    let _e290 = global_5.member.member_15.member_3;
                                    phi_311_ = (0.5f * ((((2f * _e274) * _e279) / (_e284 - _e279)) * _e290));
                                } else {
                                    let _e227 = local_27;
                                    if (_e227 == 0u) {
                                        phi_274_ = false;
                                    } else {
                                        let _e229 = local_27;
                                        phi_274_ = (_e229 <= 2139095040u);
                                    }
                                    let _e232 = phi_274_;
                                    if _e232 {
                                        let _e236 = global_5.member.member_15.member_1;
                                        let _e241 = global_5.member.member_15.member;
                                        let _e246 = global_5.member.member_15.member_2;
                                        local_28 = _e246;
                                        let _e252 = global_5.member.member_15.member_3;
                                        let _e253 = ((((2f * _e236) * _e241) / (_e246 - _e241)) * _e252);
                                        local_29 = _e253;
                                        if (_e253 == 0f) {
                                            phi_302_ = 0f;
                                        } else {
                                            let _e255 = local_28;
                                            let _e256 = local_22;
                                            let _e259 = local_29;
                                            phi_302_ = (_e259 * (1f - (_e255 / _e256)));
                                        }
                                        let _e262 = phi_302_;
                                        phi_303_ = _e262;
                                    } else {
                                        phi_303_ = bitcast<f32>(_e74);
                                    }
                                    let _e264 = phi_303_;
                                    local_30 = _e264;
                                    if (_e264 < 0f) {
                                        let _e266 = local_30;
                                        phi_309_ = -(_e266);
                                    } else {
                                        phi_309_ = _e264;
                                    }
                                    let _e269 = phi_309_;
                                    phi_311_ = (0.5f * _e269);
                                }
                                let _e294 = phi_311_;
                                let _e298 = select(_e294, 0f, ((bitcast<u32>(_e294) & 2147483647u) > 2139095040u));
                                let _e299 = local_13;
                                let _e301 = local_13;
                                phi_325_ = (_e222 * (1f - _e220));
                                phi_326_ = select(_e301, _e298, (_e298 > _e299));
                            } else {
                                phi_325_ = _e124;
                                phi_326_ = _e126;
                            }
                            let _e304 = phi_325_;
                            let _e306 = phi_326_;
                            let _e307 = local_39;
                            let _e308 = local_11;
                            phi_132_ = (_e179 + 1u);
                            phi_135_ = select(_e308, true, _e307);
                            phi_137_ = _e304;
                            phi_139_ = _e306;
                        } else {
                            phi_132_ = u32();
                            phi_135_ = bool();
                            phi_137_ = f32();
                            phi_139_ = f32();
                        }
                        let _e311 = phi_132_;
                        let _e313 = phi_135_;
                        let _e315 = phi_137_;
                        let _e317 = phi_139_;
                        continue;
                        continuing {
                            let _e318 = local_14;
                            phi_131_ = _e311;
                            phi_134_ = _e313;
                            phi_136_ = _e315;
                            phi_138_ = _e317;
                            phi_590_ = _e99;
                            break if !(_e318);
                        }
                    }
                    let _e321 = phi_590_;
                    phi_610_ = _e321;
                    if _e321 {
                        break;
                    }
                    let _e322 = local_38;
                    if (_e322 == 0u) {
                        phi_339_ = true;
                    } else {
                        let _e324 = local_11;
                        if _e324 {
                            let _e325 = local_12;
                            phi_338_ = (_e325 > 0f);
                        } else {
                            phi_338_ = false;
                        }
                        let _e328 = phi_338_;
                        phi_339_ = _e328;
                    }
                    let _e330 = phi_339_;
                    if _e330 {
                        let _e334 = global_5.member.member_15.member_1;
                        let _e339 = global_5.member.member_15.member;
                        let _e344 = global_5.member.member_15.member_2;
                        let _e350 = global_5.member.member_15.member_3;
                        let _e352 = (0.5f * ((((2f * _e334) * _e339) / (_e344 - _e339)) * _e350));
                        let _e356 = select(_e352, 0f, ((bitcast<u32>(_e352) & 2147483647u) > 2139095040u));
                        let _e357 = local_13;
                        let _e359 = local_13;
                        phi_421_ = select(_e359, _e356, (_e356 > _e357));
                    } else {
                        let _e453 = local_41;
                        phi_421_ = _e453;
                    }
                    let _e362 = phi_421_;
                    let _e363 = local_6;
                    let _e364 = local_5;
                    phi_611_ = _e321;
                    phi_104_ = (_e363 + _e364);
                    phi_107_ = _e362;
                } else {
                    phi_611_ = _e99;
                    phi_104_ = u32();
                    phi_107_ = f32();
                }
                let _e367 = phi_611_;
                let _e369 = phi_104_;
                let _e371 = phi_107_;
                continue;
                continuing {
                    let _e372 = local_8;
                    phi_604_ = _e367;
                    phi_103_ = _e369;
                    phi_106_ = _e371;
                    phi_610_ = _e367;
                    break if !(_e372);
                }
            }
            let _e375 = phi_610_;
            if _e375 {
                break;
            }
            let _e376 = local_7;
            local_31 = bitcast<u32>(_e376);
            let _e378 = local;
            let _e379 = (_e378 < 512u);
            local_32 = _e379;
            if _e379 {
            } else {
                break;
            }
            let _e380 = local;
            let _e382 = local_31;
            global_3[_e380] = _e382;
            storageBarrier();
            workgroupBarrier();
            phi_518_ = 128u;
            loop {
                let _e384 = phi_518_;
                local_33 = _e384;
                let _e385 = local_33;
                let _e386 = (_e385 > 0u);
                local_34 = _e386;
                if _e386 {
                    let _e387 = local;
                    let _e388 = local_33;
                    if (_e387 < _e388) {
                        let _e390 = local_32;
                        if _e390 {
                        } else {
                            phi_622_ = true;
                            break;
                        }
                        let _e391 = global_3[_e380];
                        local_35 = _e391;
                        let _e392 = local;
                        let _e393 = local_33;
                        let _e394 = (_e392 + _e393);
                        local_36 = _e394;
                        if (_e394 < 512u) {
                        } else {
                            phi_622_ = true;
                            break;
                        }
                        let _e396 = local_36;
                        let _e398 = global_3[_e396];
                        let _e399 = local_35;
                        let _e401 = local_35;
                        local_40 = select(_e398, _e401, (_e399 > _e398));
                        let _e403 = local_32;
                        if _e403 {
                        } else {
                            phi_622_ = true;
                            break;
                        }
                        let _e404 = local_40;
                        global_3[_e380] = _e404;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e405 = local_33;
                    phi_519_ = (_e405 / 2u);
                } else {
                    phi_519_ = u32();
                }
                let _e408 = phi_519_;
                continue;
                continuing {
                    let _e409 = local_34;
                    phi_518_ = _e408;
                    phi_622_ = _e375;
                    break if !(_e409);
                }
            }
            let _e412 = phi_622_;
            if _e412 {
                break;
            }
            let _e414 = global_3[0u];
            local_37 = _e414;
            storageBarrier();
            workgroupBarrier();
            let _e415 = local;
            if (_e415 == 0u) {
                let _e417 = local_3;
                if (17u < _e417) {
                } else {
                    break;
                }
                let _e421 = local_37;
                let _e422 = atomicMax((&global_7.member[17u]), _e421);
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn splat_plan_reduce(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
