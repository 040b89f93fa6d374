struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_15 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_16 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: type_5,
    member_9: type_15,
}

struct type_17 {
    member: type_16,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_2: type_7;
var<immediate> global_3: type_17;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(2) 
var<storage> global_5: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_6: type_7;

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
    var local_11: bool;
    var local_12: f32;
    var local_13: u32;
    var local_14: bool;
    var local_15: f32;
    var local_16: u32;
    var local_17: bool;
    var local_18: u32;
    var local_19: array<f32, 3>;
    var local_20: bool;
    var local_21: u32;
    var local_22: f32;
    var local_23: f32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: u32;
    var local_28: f32;
    var local_29: u32;
    var local_30: f32;
    var local_31: f32;
    var local_32: u32;
    var local_33: bool;
    var local_34: f32;
    var local_35: f32;
    var local_36: u32;
    var local_37: f32;
    var local_38: f32;
    var local_39: f32;
    var local_40: f32;
    var local_41: bool;
    var local_42: f32;
    var local_43: f32;
    var local_44: f32;
    var local_45: f32;
    var local_46: bool;
    var local_47: u32;
    var local_48: f32;
    var local_49: f32;
    var local_50: f32;
    var local_51: bool;
    var local_52: u32;
    var local_53: f32;
    var local_54: f32;
    var local_55: u32;
    var local_56: f32;
    var local_57: u32;
    var local_58: f32;
    var local_59: u32;
    var local_60: f32;
    var local_61: array<f32, 2>;
    var local_62: bool;
    var local_63: f32;
    var local_64: u32;
    var local_65: f32;
    var local_66: u32;
    var local_67: f32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: u32;
    var phi_145_: u32;
    var phi_148_: array<f32, 3>;
    var phi_217_: bool;
    var phi_333_: f32;
    var phi_334_: f32;
    var phi_335_: bool;
    var phi_336_: f32;
    var phi_337_: bool;
    var phi_338_: f32;
    var phi_339_: bool;
    var phi_389_: f32;
    var phi_390_: f32;
    var phi_391_: bool;
    var phi_392_: f32;
    var phi_393_: bool;
    var phi_394_: f32;
    var phi_395_: bool;
    var phi_445_: f32;
    var phi_446_: f32;
    var phi_447_: bool;
    var phi_448_: f32;
    var phi_449_: bool;
    var phi_450_: f32;
    var phi_451_: bool;
    var phi_502_: f32;
    var phi_503_: f32;
    var phi_504_: bool;
    var phi_505_: f32;
    var phi_506_: bool;
    var phi_507_: f32;
    var phi_508_: bool;
    var phi_519_: f32;
    var phi_521_: f32;
    var phi_522_: bool;
    var phi_523_: f32;
    var phi_524_: bool;
    var phi_525_: f32;
    var phi_526_: bool;
    var phi_531_: f32;
    var phi_550_: u32;
    var phi_553_: f32;
    var phi_555_: array<f32, 2>;
    var phi_551_: u32;
    var phi_554_: f32;
    var phi_556_: array<f32, 2>;
    var phi_608_: f32;
    var phi_621_: f32;
    var phi_622_: f32;
    var phi_623_: f32;
    var phi_667_: array<f32, 3>;
    var phi_146_: u32;
    var phi_149_: array<f32, 3>;
    var phi_704_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e103 = global;
            local = _e103;
            let _e104 = global_1;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_2.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = _e104.x;
            local_5 = _e104.y;
            if (1u < arrayLength((&global_5.member))) {
            } else {
                break;
            }
            let _e118 = global_5.member[1u];
            local_6 = _e118;
            let _e119 = local_4;
            let _e121 = local;
            let _e123 = ((_e119 * 16u) + (_e121 % 16u));
            local_7 = _e123;
            let _e124 = local_5;
            let _e126 = local;
            local_8 = ((_e124 * 16u) + (_e126 / 16u));
            let _e131 = global_3.member.member;
            local_9 = _e131;
            if (_e123 >= _e131) {
            } else {
                let _e135 = global_3.member.member_1;
                let _e136 = local_8;
                if (_e136 >= _e135) {
                } else {
                    let _e138 = local_8;
                    let _e139 = local_9;
                    let _e141 = local_7;
                    let _e143 = (4u * ((_e138 * _e139) + _e141));
                    local_10 = _e143;
                    let _e144 = local_3;
                    let _e145 = (_e143 < _e144);
                    local_11 = _e145;
                    if _e145 {
                    } else {
                        break;
                    }
                    let _e146 = local_10;
                    let _e149 = global_6.member[_e146];
                    local_12 = bitcast<f32>(_e149);
                    let _e151 = local_10;
                    let _e152 = (_e151 + 1u);
                    local_13 = _e152;
                    let _e153 = local_3;
                    let _e154 = (_e152 < _e153);
                    local_14 = _e154;
                    if _e154 {
                    } else {
                        break;
                    }
                    let _e155 = local_13;
                    let _e158 = global_6.member[_e155];
                    local_15 = bitcast<f32>(_e158);
                    let _e160 = local_10;
                    let _e161 = (_e160 + 2u);
                    local_16 = _e161;
                    let _e162 = local_3;
                    let _e163 = (_e161 < _e162);
                    local_17 = _e163;
                    if _e163 {
                    } else {
                        break;
                    }
                    let _e164 = local_16;
                    let _e167 = global_6.member[_e164];
                    let _e169 = local_12;
                    let _e170 = local_15;
                    phi_145_ = 0u;
                    phi_148_ = array<f32, 3>(_e169, _e170, bitcast<f32>(_e167));
                    loop {
                        let _e173 = phi_145_;
                        let _e175 = phi_148_;
                        local_18 = _e173;
                        local_19 = _e175;
                        let _e176 = local_18;
                        let _e177 = local_6;
                        let _e178 = (_e176 < _e177);
                        local_20 = _e178;
                        if _e178 {
                            let _e179 = local_18;
                            let _e180 = (_e179 * 8u);
                            local_21 = _e180;
                            let _e181 = local_7;
                            local_22 = (f32(_e181) + 0.5f);
                            let _e184 = local_1;
                            if (_e180 < _e184) {
                            } else {
                                phi_704_ = true;
                                break;
                            }
                            let _e186 = local_21;
                            let _e189 = global_4.member[_e186];
                            let _e191 = local_22;
                            local_23 = (_e191 - bitcast<f32>(_e189));
                            let _e193 = local_8;
                            local_24 = (f32(_e193) + 0.5f);
                            let _e196 = local_21;
                            let _e197 = (_e196 + 1u);
                            local_25 = _e197;
                            let _e198 = local_1;
                            if (_e197 < _e198) {
                            } else {
                                phi_704_ = true;
                                break;
                            }
                            let _e200 = local_25;
                            let _e203 = global_4.member[_e200];
                            let _e205 = local_24;
                            local_26 = (_e205 - bitcast<f32>(_e203));
                            let _e207 = local_21;
                            let _e208 = (_e207 + 2u);
                            local_27 = _e208;
                            let _e209 = local_1;
                            if (_e208 < _e209) {
                            } else {
                                phi_704_ = true;
                                break;
                            }
                            let _e211 = local_27;
                            let _e214 = global_4.member[_e211];
                            local_28 = bitcast<f32>(_e214);
                            let _e216 = local_21;
                            let _e217 = (_e216 + 3u);
                            local_29 = _e217;
                            let _e218 = local_1;
                            if (_e217 < _e218) {
                            } else {
                                phi_704_ = true;
                                break;
                            }
                            let _e220 = local_29;
                            let _e223 = global_4.member[_e220];
                            local_30 = bitcast<f32>(_e223);
                            let _e225 = local_23;
                            let _e226 = local_23;
                            let _e228 = local_26;
                            let _e229 = local_26;
                            let _e231 = ((_e225 * _e226) + (_e228 * _e229));
                            local_31 = _e231;
                            let _e232 = local_28;
                            let _e233 = local_28;
                            if (_e231 < (_e232 * _e233)) {
                                let _e239 = global_3.member.member_9.member;
                                local_32 = _e239;
                                let _e240 = (_e239 == 0u);
                                local_33 = _e240;
                                if _e240 {
                                    let _e244 = global_3.member.member_9.member_6;
                                    phi_217_ = (_e244 == 0u);
                                } else {
                                    phi_217_ = false;
                                }
                                let _e247 = phi_217_;
                                if _e247 {
                                    let _e248 = local_28;
                                    let _e249 = (_e248 - 1f);
                                    let _e252 = local_31;
                                    let _e255 = local_31;
                                    let _e257 = local_28;
                                    let _e258 = (_e257 - sqrt(_e255));
                                    phi_622_ = select(select(0f, select(1f, _e258, (_e258 < 1f)), (0f < _e258)), 1f, ((0f < _e249) && (_e252 <= (_e249 * _e249))));
                                } else {
                                    let _e264 = local_30;
                                    let _e265 = local_23;
                                    local_34 = (_e264 * _e265);
                                    let _e267 = local_30;
                                    let _e268 = local_26;
                                    local_35 = (_e267 * _e268);
                                    let _e273 = global_3.member.member_9.member_6;
                                    local_36 = _e273;
                                    if (_e273 > 0u) {
                                        let _e275 = local_28;
                                        let _e276 = (_e275 - 0.5f);
                                        local_37 = _e276;
                                        if (_e276 > 0f) {
                                            let _e278 = local_34;
                                            let _e279 = local_37;
                                            let _e281 = local_35;
                                            let _e282 = local_37;
                                            let _e284 = local_36;
                                            let _e285 = f32(_e284);
                                            local_38 = _e285;
                                            let _e289 = (((((_e278 / _e279) + 1f) * 0.5f) * _e285) - 0.5f);
                                            local_39 = _e289;
                                            local_40 = (((((_e281 / _e282) + 1f) * 0.5f) * _e285) - 0.5f);
                                            if (_e289 > -1f) {
                                                let _e295 = local_40;
                                                if (_e295 > -1f) {
                                                    let _e297 = local_39;
                                                    let _e298 = local_38;
                                                    if (_e297 < _e298) {
                                                        let _e300 = local_40;
                                                        let _e301 = local_38;
                                                        let _e302 = (_e300 < _e301);
                                                        local_41 = _e302;
                                                        if _e302 {
                                                            let _e303 = local_39;
                                                            let _e304 = floor(_e303);
                                                            local_42 = _e304;
                                                            let _e305 = local_40;
                                                            let _e306 = floor(_e305);
                                                            local_43 = _e306;
                                                            let _e307 = local_39;
                                                            local_44 = (_e307 - _e304);
                                                            let _e309 = local_40;
                                                            local_45 = (_e309 - _e306);
                                                            let _e311 = (_e304 < 0f);
                                                            local_46 = _e311;
                                                            if _e311 {
                                                                phi_338_ = f32();
                                                                phi_339_ = true;
                                                            } else {
                                                                let _e312 = local_43;
                                                                if (_e312 < 0f) {
                                                                    phi_336_ = f32();
                                                                    phi_337_ = true;
                                                                } else {
                                                                    let _e314 = local_42;
                                                                    let _e315 = local_38;
                                                                    if (_e314 >= _e315) {
                                                                        phi_334_ = f32();
                                                                        phi_335_ = true;
                                                                    } else {
                                                                        let _e317 = local_43;
                                                                        let _e318 = local_38;
                                                                        let _e319 = (_e317 >= _e318);
                                                                        if _e319 {
                                                                            phi_333_ = f32();
                                                                        } else {
                                                                            let _e320 = local_43;
                                                                            let _e322 = local_43;
                                                                            let _e325 = local_43;
                                                                            let _e329 = local_36;
                                                                            let _e331 = local_42;
                                                                            let _e333 = local_42;
                                                                            let _e336 = local_42;
                                                                            let _e340 = ((select(select(u32(_e320), 0u, !((_e322 >= 0f))), 4294967295u, (_e325 > 4294967000f)) * _e329) + select(select(u32(_e331), 0u, !((_e333 >= 0f))), 4294967295u, (_e336 > 4294967000f)));
                                                                            local_47 = _e340;
                                                                            let _e341 = local_2;
                                                                            if (_e340 < _e341) {
                                                                            } else {
                                                                                phi_704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e343 = local_47;
                                                                            let _e346 = global_2.member[_e343];
                                                                            phi_333_ = bitcast<f32>(_e346);
                                                                        }
                                                                        let _e349 = phi_333_;
                                                                        phi_334_ = _e349;
                                                                        phi_335_ = _e319;
                                                                    }
                                                                    let _e351 = phi_334_;
                                                                    let _e353 = phi_335_;
                                                                    phi_336_ = _e351;
                                                                    phi_337_ = _e353;
                                                                }
                                                                let _e355 = phi_336_;
                                                                let _e357 = phi_337_;
                                                                phi_338_ = _e355;
                                                                phi_339_ = _e357;
                                                            }
                                                            let _e359 = phi_338_;
                                                            let _e361 = phi_339_;
                                                            let _e363 = local_44;
                                                            let _e364 = (1f - _e363);
                                                            local_48 = _e364;
                                                            local_49 = (select(_e359, 0f, _e361) * _e364);
                                                            let _e366 = local_42;
                                                            let _e367 = (_e366 + 1f);
                                                            local_50 = _e367;
                                                            let _e368 = (_e367 < 0f);
                                                            local_51 = _e368;
                                                            if _e368 {
                                                                phi_394_ = f32();
                                                                phi_395_ = true;
                                                            } else {
                                                                let _e369 = local_43;
                                                                if (_e369 < 0f) {
                                                                    phi_392_ = f32();
                                                                    phi_393_ = true;
                                                                } else {
                                                                    let _e371 = local_50;
                                                                    let _e372 = local_38;
                                                                    if (_e371 >= _e372) {
                                                                        phi_390_ = f32();
                                                                        phi_391_ = true;
                                                                    } else {
                                                                        let _e374 = local_43;
                                                                        let _e375 = local_38;
                                                                        let _e376 = (_e374 >= _e375);
                                                                        if _e376 {
                                                                            phi_389_ = f32();
                                                                        } else {
                                                                            let _e377 = local_43;
                                                                            let _e379 = local_43;
                                                                            let _e382 = local_43;
                                                                            let _e386 = local_36;
                                                                            let _e388 = local_50;
                                                                            let _e390 = local_50;
                                                                            let _e393 = local_50;
                                                                            let _e397 = ((select(select(u32(_e377), 0u, !((_e379 >= 0f))), 4294967295u, (_e382 > 4294967000f)) * _e386) + select(select(u32(_e388), 0u, !((_e390 >= 0f))), 4294967295u, (_e393 > 4294967000f)));
                                                                            local_52 = _e397;
                                                                            let _e398 = local_2;
                                                                            if (_e397 < _e398) {
                                                                            } else {
                                                                                phi_704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e400 = local_52;
                                                                            let _e403 = global_2.member[_e400];
                                                                            phi_389_ = bitcast<f32>(_e403);
                                                                        }
                                                                        let _e406 = phi_389_;
                                                                        phi_390_ = _e406;
                                                                        phi_391_ = _e376;
                                                                    }
                                                                    let _e408 = phi_390_;
                                                                    let _e410 = phi_391_;
                                                                    phi_392_ = _e408;
                                                                    phi_393_ = _e410;
                                                                }
                                                                let _e412 = phi_392_;
                                                                let _e414 = phi_393_;
                                                                phi_394_ = _e412;
                                                                phi_395_ = _e414;
                                                            }
                                                            let _e416 = phi_394_;
                                                            let _e418 = phi_395_;
                                                            let _e420 = local_44;
                                                            let _e422 = local_49;
                                                            local_53 = (_e422 + (select(_e416, 0f, _e418) * _e420));
                                                            let _e424 = local_43;
                                                            local_54 = (_e424 + 1f);
                                                            let _e426 = local_46;
                                                            if _e426 {
                                                                phi_450_ = f32();
                                                                phi_451_ = true;
                                                            } else {
                                                                let _e427 = local_54;
                                                                if (_e427 < 0f) {
                                                                    phi_448_ = f32();
                                                                    phi_449_ = true;
                                                                } else {
                                                                    let _e429 = local_42;
                                                                    let _e430 = local_38;
                                                                    if (_e429 >= _e430) {
                                                                        phi_446_ = f32();
                                                                        phi_447_ = true;
                                                                    } else {
                                                                        let _e432 = local_54;
                                                                        let _e433 = local_38;
                                                                        let _e434 = (_e432 >= _e433);
                                                                        if _e434 {
                                                                            phi_445_ = f32();
                                                                        } else {
                                                                            let _e435 = local_54;
                                                                            let _e437 = local_54;
                                                                            let _e440 = local_54;
                                                                            let _e444 = local_36;
                                                                            let _e446 = local_42;
                                                                            let _e448 = local_42;
                                                                            let _e451 = local_42;
                                                                            let _e455 = ((select(select(u32(_e435), 0u, !((_e437 >= 0f))), 4294967295u, (_e440 > 4294967000f)) * _e444) + select(select(u32(_e446), 0u, !((_e448 >= 0f))), 4294967295u, (_e451 > 4294967000f)));
                                                                            local_55 = _e455;
                                                                            let _e456 = local_2;
                                                                            if (_e455 < _e456) {
                                                                            } else {
                                                                                phi_704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e458 = local_55;
                                                                            let _e461 = global_2.member[_e458];
                                                                            phi_445_ = bitcast<f32>(_e461);
                                                                        }
                                                                        let _e464 = phi_445_;
                                                                        phi_446_ = _e464;
                                                                        phi_447_ = _e434;
                                                                    }
                                                                    let _e466 = phi_446_;
                                                                    let _e468 = phi_447_;
                                                                    phi_448_ = _e466;
                                                                    phi_449_ = _e468;
                                                                }
                                                                let _e470 = phi_448_;
                                                                let _e472 = phi_449_;
                                                                phi_450_ = _e470;
                                                                phi_451_ = _e472;
                                                            }
                                                            let _e474 = phi_450_;
                                                            let _e476 = phi_451_;
                                                            let _e478 = local_48;
                                                            local_56 = (select(_e474, 0f, _e476) * _e478);
                                                            let _e480 = local_51;
                                                            if _e480 {
                                                                phi_507_ = f32();
                                                                phi_508_ = true;
                                                            } else {
                                                                let _e481 = local_54;
                                                                if (_e481 < 0f) {
                                                                    phi_505_ = f32();
                                                                    phi_506_ = true;
                                                                } else {
                                                                    let _e483 = local_50;
                                                                    let _e484 = local_38;
                                                                    if (_e483 >= _e484) {
                                                                        phi_503_ = f32();
                                                                        phi_504_ = true;
                                                                    } else {
                                                                        let _e486 = local_54;
                                                                        let _e487 = local_38;
                                                                        let _e488 = (_e486 >= _e487);
                                                                        if _e488 {
                                                                            phi_502_ = f32();
                                                                        } else {
                                                                            let _e489 = local_54;
                                                                            let _e491 = local_54;
                                                                            let _e494 = local_54;
                                                                            let _e498 = local_36;
                                                                            let _e500 = local_50;
                                                                            let _e502 = local_50;
                                                                            let _e505 = local_50;
                                                                            let _e509 = ((select(select(u32(_e489), 0u, !((_e491 >= 0f))), 4294967295u, (_e494 > 4294967000f)) * _e498) + select(select(u32(_e500), 0u, !((_e502 >= 0f))), 4294967295u, (_e505 > 4294967000f)));
                                                                            local_57 = _e509;
                                                                            let _e510 = local_2;
                                                                            if (_e509 < _e510) {
                                                                            } else {
                                                                                phi_704_ = true;
                                                                                break;
                                                                            }
                                                                            let _e512 = local_57;
                                                                            let _e515 = global_2.member[_e512];
                                                                            phi_502_ = bitcast<f32>(_e515);
                                                                        }
                                                                        let _e518 = phi_502_;
                                                                        phi_503_ = _e518;
                                                                        phi_504_ = _e488;
                                                                    }
                                                                    let _e520 = phi_503_;
                                                                    let _e522 = phi_504_;
                                                                    phi_505_ = _e520;
                                                                    phi_506_ = _e522;
                                                                }
                                                                let _e524 = phi_505_;
                                                                let _e526 = phi_506_;
                                                                phi_507_ = _e524;
                                                                phi_508_ = _e526;
                                                            }
                                                            let _e528 = phi_507_;
                                                            let _e530 = phi_508_;
                                                            let _e532 = local_44;
                                                            let _e534 = local_56;
                                                            let _e536 = local_45;
                                                            let _e538 = local_53;
                                                            let _e540 = local_45;
                                                            phi_519_ = ((_e538 * (1f - _e536)) + ((_e534 + (select(_e528, 0f, _e530) * _e532)) * _e540));
                                                        } else {
                                                            phi_519_ = f32();
                                                        }
                                                        let _e544 = phi_519_;
                                                        let _e545 = local_41;
                                                        phi_521_ = _e544;
                                                        phi_522_ = select(true, false, _e545);
                                                    } else {
                                                        phi_521_ = f32();
                                                        phi_522_ = true;
                                                    }
                                                    let _e548 = phi_521_;
                                                    let _e550 = phi_522_;
                                                    phi_523_ = _e548;
                                                    phi_524_ = _e550;
                                                } else {
                                                    phi_523_ = f32();
                                                    phi_524_ = true;
                                                }
                                                let _e552 = phi_523_;
                                                let _e554 = phi_524_;
                                                phi_525_ = _e552;
                                                phi_526_ = _e554;
                                            } else {
                                                phi_525_ = f32();
                                                phi_526_ = true;
                                            }
                                            let _e556 = phi_525_;
                                            let _e558 = phi_526_;
                                            phi_531_ = select(_e556, 0f, _e558);
                                        } else {
                                            phi_531_ = 0f;
                                        }
                                        let _e561 = phi_531_;
                                        phi_621_ = _e561;
                                    } else {
                                        let _e562 = local_34;
                                        let _e563 = local_34;
                                        let _e565 = local_35;
                                        let _e566 = local_35;
                                        let _e569 = sqrt(((_e562 * _e563) + (_e565 * _e566)));
                                        local_58 = _e569;
                                        let _e570 = local_33;
                                        if _e570 {
                                            phi_608_ = _e569;
                                        } else {
                                            let _e574 = global_3.member.member_9.member_2;
                                            let _e576 = local_34;
                                            let _e579 = local_35;
                                            phi_550_ = 1u;
                                            phi_553_ = ((_e576 * _e574[0]) + (_e579 * _e574[1]));
                                            phi_555_ = _e574;
                                            loop {
                                                let _e583 = phi_550_;
                                                let _e585 = phi_553_;
                                                let _e587 = phi_555_;
                                                local_59 = _e583;
                                                local_60 = _e585;
                                                local_61 = _e587;
                                                let _e588 = local_59;
                                                let _e589 = local_32;
                                                let _e590 = (_e588 < _e589);
                                                local_62 = _e590;
                                                if _e590 {
                                                    let _e591 = local_61;
                                                    let _e597 = global_3.member.member_9.member_3[0u];
                                                    let _e599 = local_61;
                                                    let _e605 = global_3.member.member_9.member_3[1u];
                                                    let _e607 = ((_e591[0] * _e597) - (_e599[1] * _e605));
                                                    let _e610 = ((_e591[0] * _e605) + (_e599[1] * _e597));
                                                    let _e612 = local_34;
                                                    let _e614 = local_35;
                                                    let _e616 = ((_e612 * _e607) + (_e614 * _e610));
                                                    let _e617 = local_60;
                                                    let _e619 = local_60;
                                                    let _e621 = local_59;
                                                    phi_551_ = (_e621 + 1u);
                                                    phi_554_ = select(_e619, _e616, (_e616 > _e617));
                                                    phi_556_ = array<f32, 2>(_e607, _e610);
                                                } else {
                                                    phi_551_ = u32();
                                                    phi_554_ = f32();
                                                    phi_556_ = array<f32, 2>();
                                                }
                                                let _e624 = phi_551_;
                                                let _e626 = phi_554_;
                                                let _e628 = phi_556_;
                                                continue;
                                                continuing {
                                                    let _e629 = local_62;
                                                    phi_550_ = _e624;
                                                    phi_553_ = _e626;
                                                    phi_555_ = _e628;
                                                    break if !(_e629);
                                                }
                                            }
                                            let _e634 = global_3.member.member_9.member_1;
                                            let _e636 = local_60;
                                            let _e641 = global_3.member.member_9.member_4;
                                            let _e643 = local_58;
                                            phi_608_ = ((((1f - _e634) * _e636) * _e641) + (_e634 * _e643));
                                        }
                                        let _e647 = phi_608_;
                                        let _e648 = local_28;
                                        let _e649 = (_e648 - _e647);
                                        phi_621_ = select(0f, select(1f, _e649, (_e649 < 1f)), (0f < _e649));
                                    }
                                    let _e655 = phi_621_;
                                    phi_622_ = _e655;
                                }
                                let _e657 = phi_622_;
                                phi_623_ = _e657;
                            } else {
                                phi_623_ = 0f;
                            }
                            let _e659 = phi_623_;
                            local_63 = _e659;
                            if (_e659 > 0f) {
                                let _e661 = local_21;
                                let _e662 = (_e661 + 4u);
                                local_64 = _e662;
                                let _e663 = local_1;
                                if (_e662 < _e663) {
                                } else {
                                    phi_704_ = true;
                                    break;
                                }
                                let _e665 = local_64;
                                let _e668 = global_4.member[_e665];
                                let _e670 = local_63;
                                let _e672 = local_19;
                                local_65 = (_e672[0] + (_e670 * bitcast<f32>(_e668)));
                                let _e675 = local_21;
                                let _e676 = (_e675 + 5u);
                                local_66 = _e676;
                                let _e677 = local_1;
                                if (_e676 < _e677) {
                                } else {
                                    phi_704_ = true;
                                    break;
                                }
                                let _e679 = local_66;
                                let _e682 = global_4.member[_e679];
                                let _e684 = local_63;
                                let _e686 = local_19;
                                local_67 = (_e686[1] + (_e684 * bitcast<f32>(_e682)));
                                let _e689 = local_21;
                                let _e690 = (_e689 + 6u);
                                local_68 = _e690;
                                let _e691 = local_1;
                                if (_e690 < _e691) {
                                } else {
                                    phi_704_ = true;
                                    break;
                                }
                                let _e693 = local_68;
                                let _e696 = global_4.member[_e693];
                                let _e698 = local_63;
                                let _e700 = local_19;
                                let _e703 = local_65;
                                let _e704 = local_67;
                                phi_667_ = array<f32, 3>(_e703, _e704, (_e700[2] + (_e698 * bitcast<f32>(_e696))));
                            } else {
                                phi_667_ = _e175;
                            }
                            let _e707 = phi_667_;
                            let _e708 = local_18;
                            phi_146_ = (_e708 + 1u);
                            phi_149_ = _e707;
                        } else {
                            phi_146_ = u32();
                            phi_149_ = array<f32, 3>();
                        }
                        let _e711 = phi_146_;
                        let _e713 = phi_149_;
                        continue;
                        continuing {
                            let _e714 = local_20;
                            phi_145_ = _e711;
                            phi_148_ = _e713;
                            phi_704_ = false;
                            break if !(_e714);
                        }
                    }
                    let _e717 = phi_704_;
                    if _e717 {
                        break;
                    }
                    let _e718 = local_19;
                    local_69 = bitcast<u32>(_e718[0]);
                    let _e721 = local_11;
                    if _e721 {
                    } else {
                        break;
                    }
                    let _e722 = local_69;
                    global_6.member[_e146] = _e722;
                    let _e723 = local_19;
                    local_70 = bitcast<u32>(_e723[1]);
                    let _e726 = local_14;
                    if _e726 {
                    } else {
                        break;
                    }
                    let _e727 = local_70;
                    global_6.member[_e155] = _e727;
                    let _e728 = local_19;
                    local_71 = bitcast<u32>(_e728[2]);
                    let _e731 = local_17;
                    if _e731 {
                    } else {
                        break;
                    }
                    let _e732 = local_71;
                    global_6.member[_e164] = _e732;
                }
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn bokeh_splat(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
