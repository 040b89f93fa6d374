struct type_6 {
    member: array<u32>,
}

struct type_12 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_13 {
    member: type_12,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_6;
@group(0) @binding(1) 
var<storage, read_write> global_4: type_6;
var<immediate> global_5: type_13;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: bool;
    var local_7: u32;
    var local_8: u32;
    var local_9: u32;
    var local_10: u32;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: i32;
    var local_24: u32;
    var local_25: i32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: i32;
    var local_33: u32;
    var local_34: i32;
    var local_35: u32;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: i32;
    var local_42: u32;
    var local_43: i32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var phi_96_: u32;
    var phi_546_: bool;
    var phi_548_: bool;
    var phi_523_: bool;
    var phi_525_: bool;
    var phi_530_: u32;
    var phi_553_: u32;
    var phi_554_: u32;
    var phi_556_: u32;
    var phi_557_: u32;
    var phi_558_: bool;
    var phi_563_: u32;
    var phi_564_: u32;
    var phi_565_: bool;
    var phi_645_: bool;
    var phi_647_: bool;
    var phi_622_: bool;
    var phi_624_: bool;
    var phi_629_: u32;
    var phi_652_: u32;
    var phi_653_: u32;
    var phi_655_: u32;
    var phi_656_: u32;
    var phi_657_: bool;
    var phi_662_: u32;
    var phi_663_: u32;
    var phi_664_: bool;
    var phi_744_: bool;
    var phi_746_: bool;
    var phi_721_: bool;
    var phi_723_: bool;
    var phi_728_: u32;
    var phi_751_: u32;
    var phi_752_: u32;
    var phi_754_: u32;
    var phi_755_: u32;
    var phi_756_: bool;
    var phi_761_: u32;
    var phi_762_: u32;
    var phi_763_: bool;
    var phi_97_: u32;
    var phi_772_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e88 = global;
            local = _e88;
            let _e89 = global_1;
            let _e90 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            let _e99 = global_5.member.member;
            let _e102 = global_5.member.member_1;
            local_3 = (_e99 * _e102);
            local_4 = (_e90.x * 256u);
            phi_96_ = (_e89.x * 256u);
            loop {
                let _e107 = phi_96_;
                local_5 = _e107;
                let _e108 = local_5;
                let _e109 = local_3;
                let _e110 = (_e108 < _e109);
                local_6 = _e110;
                if _e110 {
                    let _e111 = local_5;
                    let _e112 = local;
                    let _e113 = (_e111 + _e112);
                    local_7 = _e113;
                    let _e114 = local_3;
                    if (_e113 < _e114) {
                        let _e116 = local_7;
                        let _e117 = (3u * _e116);
                        local_8 = _e117;
                        let _e118 = local_1;
                        if (_e117 < _e118) {
                        } else {
                            phi_772_ = true;
                            break;
                        }
                        let _e120 = local_8;
                        let _e123 = global_3.member[_e120];
                        local_9 = _e123;
                        let _e124 = local_8;
                        let _e125 = (_e124 + 1u);
                        local_10 = _e125;
                        let _e126 = local_1;
                        if (_e125 < _e126) {
                        } else {
                            phi_772_ = true;
                            break;
                        }
                        let _e128 = local_10;
                        let _e131 = global_3.member[_e128];
                        local_11 = _e131;
                        let _e132 = local_8;
                        let _e133 = (_e132 + 2u);
                        local_12 = _e133;
                        let _e134 = local_1;
                        if (_e133 < _e134) {
                        } else {
                            phi_772_ = true;
                            break;
                        }
                        let _e136 = local_12;
                        let _e139 = global_3.member[_e136];
                        local_13 = _e139;
                        let _e142 = global_5.member.member_2;
                        if (_e142 == 2u) {
                            let _e175 = local_7;
                            local_14 = (2u * _e175);
                            let _e177 = local_9;
                            let _e179 = bitcast<u32>(bitcast<f32>(_e177));
                            let _e182 = ((_e179 >> bitcast<u32>(16i)) & 32768u);
                            local_22 = _e182;
                            let _e186 = bitcast<i32>(((_e179 >> bitcast<u32>(23i)) & 255u));
                            local_23 = _e186;
                            local_24 = (_e179 & 8388607u);
                            if (_e186 == 255i) {
                                let _e267 = local_22;
                                let _e269 = local_24;
                                phi_563_ = ((_e267 | 31744u) | select(512u, 0u, (_e269 == 0u)));
                                phi_564_ = u32();
                                phi_565_ = true;
                            } else {
                                let _e189 = local_23;
                                let _e190 = (_e189 + -112i);
                                local_25 = _e190;
                                if (_e190 >= 31i) {
                                    let _e259 = local_22;
                                    phi_556_ = (_e259 | 31744u);
                                    phi_557_ = u32();
                                    phi_558_ = true;
                                } else {
                                    let _e192 = local_25;
                                    let _e193 = (_e192 <= 0i);
                                    if _e193 {
                                        let _e219 = local_25;
                                        if (_e219 < -10i) {
                                            phi_530_ = _e182;
                                        } else {
                                            let _e221 = local_24;
                                            let _e222 = (_e221 | 8388608u);
                                            let _e223 = local_23;
                                            let _e225 = bitcast<u32>((126i - _e223));
                                            let _e226 = (_e225 & 31u);
                                            local_26 = (_e222 >> bitcast<u32>(_e226));
                                            let _e232 = (_e222 & ((1u << bitcast<u32>(_e226)) - 1u));
                                            local_27 = _e232;
                                            let _e236 = (1u << bitcast<u32>(((_e225 - 1u) & 31u)));
                                            local_28 = _e236;
                                            if (_e232 > _e236) {
                                                phi_525_ = true;
                                            } else {
                                                let _e238 = local_27;
                                                let _e239 = local_28;
                                                if (_e238 == _e239) {
                                                    let _e241 = local_26;
                                                    phi_523_ = ((_e241 & 1u) == 1u);
                                                } else {
                                                    phi_523_ = false;
                                                }
                                                let _e245 = phi_523_;
                                                phi_525_ = _e245;
                                            }
                                            let _e247 = phi_525_;
                                            let _e249 = local_26;
                                            let _e251 = local_22;
                                            phi_530_ = (_e251 | (_e249 + select(0u, 1u, _e247)));
                                        }
                                        let _e254 = phi_530_;
                                        phi_553_ = _e254;
                                        phi_554_ = u32();
                                    } else {
                                        let _e194 = local_25;
                                        let _e198 = local_24;
                                        local_29 = ((bitcast<u32>(_e194) << bitcast<u32>(10i)) | (_e198 >> bitcast<u32>(13i)));
                                        let _e202 = local_24;
                                        let _e203 = (_e202 & 8191u);
                                        local_30 = _e203;
                                        if (_e203 > 4096u) {
                                            phi_548_ = true;
                                        } else {
                                            let _e205 = local_30;
                                            if (_e205 == 4096u) {
                                                let _e207 = local_29;
                                                phi_546_ = ((_e207 & 1u) == 1u);
                                            } else {
                                                phi_546_ = false;
                                            }
                                            let _e211 = phi_546_;
                                            phi_548_ = _e211;
                                        }
                                        let _e213 = phi_548_;
                                        let _e215 = local_29;
                                        let _e217 = local_22;
                                        phi_553_ = u32();
                                        phi_554_ = (_e217 | (_e215 + select(0u, 1u, _e213)));
                                    }
                                    let _e256 = phi_553_;
                                    let _e258 = phi_554_;
                                    phi_556_ = _e256;
                                    phi_557_ = _e258;
                                    phi_558_ = _e193;
                                }
                                let _e262 = phi_556_;
                                let _e264 = phi_557_;
                                let _e266 = phi_558_;
                                phi_563_ = _e262;
                                phi_564_ = _e264;
                                phi_565_ = _e266;
                            }
                            let _e274 = phi_563_;
                            let _e276 = phi_564_;
                            let _e278 = phi_565_;
                            local_49 = select(_e276, _e274, _e278);
                            let _e280 = local_11;
                            let _e282 = bitcast<u32>(bitcast<f32>(_e280));
                            let _e285 = ((_e282 >> bitcast<u32>(16i)) & 32768u);
                            local_31 = _e285;
                            let _e289 = bitcast<i32>(((_e282 >> bitcast<u32>(23i)) & 255u));
                            local_32 = _e289;
                            local_33 = (_e282 & 8388607u);
                            if (_e289 == 255i) {
                                let _e370 = local_31;
                                let _e372 = local_33;
                                phi_662_ = ((_e370 | 31744u) | select(512u, 0u, (_e372 == 0u)));
                                phi_663_ = u32();
                                phi_664_ = true;
                            } else {
                                let _e292 = local_32;
                                let _e293 = (_e292 + -112i);
                                local_34 = _e293;
                                if (_e293 >= 31i) {
                                    let _e362 = local_31;
                                    phi_655_ = (_e362 | 31744u);
                                    phi_656_ = u32();
                                    phi_657_ = true;
                                } else {
                                    let _e295 = local_34;
                                    let _e296 = (_e295 <= 0i);
                                    if _e296 {
                                        let _e322 = local_34;
                                        if (_e322 < -10i) {
                                            phi_629_ = _e285;
                                        } else {
                                            let _e324 = local_33;
                                            let _e325 = (_e324 | 8388608u);
                                            let _e326 = local_32;
                                            let _e328 = bitcast<u32>((126i - _e326));
                                            let _e329 = (_e328 & 31u);
                                            local_35 = (_e325 >> bitcast<u32>(_e329));
                                            let _e335 = (_e325 & ((1u << bitcast<u32>(_e329)) - 1u));
                                            local_36 = _e335;
                                            let _e339 = (1u << bitcast<u32>(((_e328 - 1u) & 31u)));
                                            local_37 = _e339;
                                            if (_e335 > _e339) {
                                                phi_624_ = true;
                                            } else {
                                                let _e341 = local_36;
                                                let _e342 = local_37;
                                                if (_e341 == _e342) {
                                                    let _e344 = local_35;
                                                    phi_622_ = ((_e344 & 1u) == 1u);
                                                } else {
                                                    phi_622_ = false;
                                                }
                                                let _e348 = phi_622_;
                                                phi_624_ = _e348;
                                            }
                                            let _e350 = phi_624_;
                                            let _e352 = local_35;
                                            let _e354 = local_31;
                                            phi_629_ = (_e354 | (_e352 + select(0u, 1u, _e350)));
                                        }
                                        let _e357 = phi_629_;
                                        phi_652_ = _e357;
                                        phi_653_ = u32();
                                    } else {
                                        let _e297 = local_34;
                                        let _e301 = local_33;
                                        local_38 = ((bitcast<u32>(_e297) << bitcast<u32>(10i)) | (_e301 >> bitcast<u32>(13i)));
                                        let _e305 = local_33;
                                        let _e306 = (_e305 & 8191u);
                                        local_39 = _e306;
                                        if (_e306 > 4096u) {
                                            phi_647_ = true;
                                        } else {
                                            let _e308 = local_39;
                                            if (_e308 == 4096u) {
                                                let _e310 = local_38;
                                                phi_645_ = ((_e310 & 1u) == 1u);
                                            } else {
                                                phi_645_ = false;
                                            }
                                            let _e314 = phi_645_;
                                            phi_647_ = _e314;
                                        }
                                        let _e316 = phi_647_;
                                        let _e318 = local_38;
                                        let _e320 = local_31;
                                        phi_652_ = u32();
                                        phi_653_ = (_e320 | (_e318 + select(0u, 1u, _e316)));
                                    }
                                    let _e359 = phi_652_;
                                    let _e361 = phi_653_;
                                    phi_655_ = _e359;
                                    phi_656_ = _e361;
                                    phi_657_ = _e296;
                                }
                                let _e365 = phi_655_;
                                let _e367 = phi_656_;
                                let _e369 = phi_657_;
                                phi_662_ = _e365;
                                phi_663_ = _e367;
                                phi_664_ = _e369;
                            }
                            let _e377 = phi_662_;
                            let _e379 = phi_663_;
                            let _e381 = phi_664_;
                            let _e385 = local_49;
                            local_15 = (_e385 | (select(_e379, _e377, _e381) << bitcast<u32>(16i)));
                            let _e387 = local_14;
                            let _e388 = local_2;
                            if (_e387 < _e388) {
                            } else {
                                phi_772_ = true;
                                break;
                            }
                            let _e390 = local_14;
                            let _e393 = local_15;
                            global_4.member[_e390] = _e393;
                            let _e394 = local_14;
                            local_16 = (_e394 + 1u);
                            let _e396 = local_13;
                            let _e398 = bitcast<u32>(bitcast<f32>(_e396));
                            let _e401 = ((_e398 >> bitcast<u32>(16i)) & 32768u);
                            local_40 = _e401;
                            let _e405 = bitcast<i32>(((_e398 >> bitcast<u32>(23i)) & 255u));
                            local_41 = _e405;
                            local_42 = (_e398 & 8388607u);
                            if (_e405 == 255i) {
                                let _e486 = local_40;
                                let _e488 = local_42;
                                phi_761_ = ((_e486 | 31744u) | select(512u, 0u, (_e488 == 0u)));
                                phi_762_ = u32();
                                phi_763_ = true;
                            } else {
                                let _e408 = local_41;
                                let _e409 = (_e408 + -112i);
                                local_43 = _e409;
                                if (_e409 >= 31i) {
                                    let _e478 = local_40;
                                    phi_754_ = (_e478 | 31744u);
                                    phi_755_ = u32();
                                    phi_756_ = true;
                                } else {
                                    let _e411 = local_43;
                                    let _e412 = (_e411 <= 0i);
                                    if _e412 {
                                        let _e438 = local_43;
                                        if (_e438 < -10i) {
                                            phi_728_ = _e401;
                                        } else {
                                            let _e440 = local_42;
                                            let _e441 = (_e440 | 8388608u);
                                            let _e442 = local_41;
                                            let _e444 = bitcast<u32>((126i - _e442));
                                            let _e445 = (_e444 & 31u);
                                            local_44 = (_e441 >> bitcast<u32>(_e445));
                                            let _e451 = (_e441 & ((1u << bitcast<u32>(_e445)) - 1u));
                                            local_45 = _e451;
                                            let _e455 = (1u << bitcast<u32>(((_e444 - 1u) & 31u)));
                                            local_46 = _e455;
                                            if (_e451 > _e455) {
                                                phi_723_ = true;
                                            } else {
                                                let _e457 = local_45;
                                                let _e458 = local_46;
                                                if (_e457 == _e458) {
                                                    let _e460 = local_44;
                                                    phi_721_ = ((_e460 & 1u) == 1u);
                                                } else {
                                                    phi_721_ = false;
                                                }
                                                let _e464 = phi_721_;
                                                phi_723_ = _e464;
                                            }
                                            let _e466 = phi_723_;
                                            let _e468 = local_44;
                                            let _e470 = local_40;
                                            phi_728_ = (_e470 | (_e468 + select(0u, 1u, _e466)));
                                        }
                                        let _e473 = phi_728_;
                                        phi_751_ = _e473;
                                        phi_752_ = u32();
                                    } else {
                                        let _e413 = local_43;
                                        let _e417 = local_42;
                                        local_47 = ((bitcast<u32>(_e413) << bitcast<u32>(10i)) | (_e417 >> bitcast<u32>(13i)));
                                        let _e421 = local_42;
                                        let _e422 = (_e421 & 8191u);
                                        local_48 = _e422;
                                        if (_e422 > 4096u) {
                                            phi_746_ = true;
                                        } else {
                                            let _e424 = local_48;
                                            if (_e424 == 4096u) {
                                                let _e426 = local_47;
                                                phi_744_ = ((_e426 & 1u) == 1u);
                                            } else {
                                                phi_744_ = false;
                                            }
                                            let _e430 = phi_744_;
                                            phi_746_ = _e430;
                                        }
                                        let _e432 = phi_746_;
                                        let _e434 = local_47;
                                        let _e436 = local_40;
                                        phi_751_ = u32();
                                        phi_752_ = (_e436 | (_e434 + select(0u, 1u, _e432)));
                                    }
                                    let _e475 = phi_751_;
                                    let _e477 = phi_752_;
                                    phi_754_ = _e475;
                                    phi_755_ = _e477;
                                    phi_756_ = _e412;
                                }
                                let _e481 = phi_754_;
                                let _e483 = phi_755_;
                                let _e485 = phi_756_;
                                phi_761_ = _e481;
                                phi_762_ = _e483;
                                phi_763_ = _e485;
                            }
                            let _e493 = phi_761_;
                            let _e495 = phi_762_;
                            let _e497 = phi_763_;
                            local_17 = (select(_e495, _e493, _e497) | 1006632960u);
                            let _e500 = local_16;
                            let _e501 = local_2;
                            if (_e500 < _e501) {
                            } else {
                                phi_772_ = true;
                                break;
                            }
                            let _e503 = local_16;
                            let _e506 = local_17;
                            global_4.member[_e503] = _e506;
                        } else {
                            let _e144 = local_7;
                            let _e145 = (4u * _e144);
                            local_18 = _e145;
                            let _e146 = local_2;
                            if (_e145 < _e146) {
                            } else {
                                phi_772_ = true;
                                break;
                            }
                            let _e148 = local_18;
                            let _e151 = local_9;
                            global_4.member[_e148] = _e151;
                            let _e152 = local_18;
                            let _e153 = (_e152 + 1u);
                            local_19 = _e153;
                            let _e154 = local_2;
                            if (_e153 < _e154) {
                            } else {
                                phi_772_ = true;
                                break;
                            }
                            let _e156 = local_19;
                            let _e159 = local_11;
                            global_4.member[_e156] = _e159;
                            let _e160 = local_18;
                            let _e161 = (_e160 + 2u);
                            local_20 = _e161;
                            let _e162 = local_2;
                            if (_e161 < _e162) {
                            } else {
                                phi_772_ = true;
                                break;
                            }
                            let _e164 = local_20;
                            let _e167 = local_13;
                            global_4.member[_e164] = _e167;
                            let _e168 = local_18;
                            let _e169 = (_e168 + 3u);
                            local_21 = _e169;
                            let _e170 = local_2;
                            if (_e169 < _e170) {
                            } else {
                                phi_772_ = true;
                                break;
                            }
                            let _e172 = local_21;
                            global_4.member[_e172] = 1065353216u;
                        }
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e507 = local_5;
                    let _e508 = local_4;
                    phi_97_ = (_e507 + _e508);
                } else {
                    phi_97_ = u32();
                }
                let _e511 = phi_97_;
                continue;
                continuing {
                    let _e512 = local_6;
                    phi_96_ = _e511;
                    phi_772_ = false;
                    break if !(_e512);
                }
            }
            let _e515 = phi_772_;
            if _e515 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn frame_to_rgba(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
