struct type_2 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_4 {
    member: array<u32>,
}

struct type_11 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_12 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: type_2,
    member_9: type_11,
}

struct type_13 {
    member: type_12,
}

@group(0) @binding(1) 
var<storage> global: type_4;
var<immediate> global_1: type_13;
var<private> global_2: vec2<f32>;
var<private> global_3: vec4<f32>;
var<private> global_4: vec2<f32>;
var<private> global_5: vec4<f32>;

fn function_() {
    var local: u32;
    var local_1: f32;
    var local_2: f32;
    var local_3: vec4<f32>;
    var local_4: f32;
    var local_5: f32;
    var local_6: f32;
    var local_7: u32;
    var local_8: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: u32;
    var local_12: f32;
    var local_13: f32;
    var local_14: f32;
    var local_15: f32;
    var local_16: bool;
    var local_17: f32;
    var local_18: f32;
    var local_19: f32;
    var local_20: f32;
    var local_21: bool;
    var local_22: u32;
    var local_23: f32;
    var local_24: f32;
    var local_25: f32;
    var local_26: bool;
    var local_27: u32;
    var local_28: f32;
    var local_29: f32;
    var local_30: u32;
    var local_31: f32;
    var local_32: u32;
    var local_33: f32;
    var local_34: u32;
    var local_35: f32;
    var local_36: array<f32, 2>;
    var local_37: bool;
    var phi_95_: bool;
    var phi_211_: f32;
    var phi_212_: f32;
    var phi_213_: bool;
    var phi_214_: f32;
    var phi_215_: bool;
    var phi_216_: f32;
    var phi_217_: bool;
    var phi_267_: f32;
    var phi_268_: f32;
    var phi_269_: bool;
    var phi_270_: f32;
    var phi_271_: bool;
    var phi_272_: f32;
    var phi_273_: bool;
    var phi_323_: f32;
    var phi_324_: f32;
    var phi_325_: bool;
    var phi_326_: f32;
    var phi_327_: bool;
    var phi_328_: f32;
    var phi_329_: bool;
    var phi_380_: f32;
    var phi_381_: f32;
    var phi_382_: bool;
    var phi_383_: f32;
    var phi_384_: bool;
    var phi_385_: f32;
    var phi_386_: bool;
    var phi_397_: f32;
    var phi_399_: f32;
    var phi_400_: bool;
    var phi_401_: f32;
    var phi_402_: bool;
    var phi_403_: f32;
    var phi_404_: bool;
    var phi_409_: f32;
    var phi_428_: u32;
    var phi_431_: f32;
    var phi_433_: array<f32, 2>;
    var phi_429_: u32;
    var phi_432_: f32;
    var phi_434_: array<f32, 2>;
    var phi_486_: f32;
    var phi_499_: f32;
    var phi_500_: f32;
    var phi_501_: f32;

    switch bitcast<i32>(0u) {
        default: {
            local = arrayLength((&global.member));
            let _e66 = global_2[0u];
            local_1 = _e66;
            let _e68 = global_2[1u];
            local_2 = _e68;
            let _e69 = global_3;
            local_3 = _e69;
            let _e71 = global_4[0u];
            local_4 = _e71;
            let _e73 = global_4[1u];
            local_5 = _e73;
            let _e76 = ((_e66 * _e66) + (_e68 * _e68));
            local_6 = _e76;
            if (_e76 < (_e71 * _e71)) {
                let _e82 = global_1.member.member_9.member;
                local_7 = _e82;
                let _e83 = (_e82 == 0u);
                local_8 = _e83;
                if _e83 {
                    let _e87 = global_1.member.member_9.member_6;
                    phi_95_ = (_e87 == 0u);
                } else {
                    phi_95_ = false;
                }
                let _e90 = phi_95_;
                if _e90 {
                    let _e91 = local_4;
                    let _e92 = (_e91 - 1f);
                    let _e95 = local_6;
                    let _e98 = local_6;
                    let _e100 = local_4;
                    let _e101 = (_e100 - sqrt(_e98));
                    phi_500_ = select(select(0f, select(1f, _e101, (_e101 < 1f)), (0f < _e101)), 1f, ((0f < _e92) && (_e95 <= (_e92 * _e92))));
                } else {
                    let _e107 = local_5;
                    let _e108 = local_1;
                    local_9 = (_e107 * _e108);
                    let _e110 = local_5;
                    let _e111 = local_2;
                    local_10 = (_e110 * _e111);
                    let _e116 = global_1.member.member_9.member_6;
                    local_11 = _e116;
                    if (_e116 > 0u) {
                        let _e118 = local_4;
                        let _e119 = (_e118 - 0.5f);
                        local_12 = _e119;
                        if (_e119 > 0f) {
                            let _e121 = local_9;
                            let _e122 = local_12;
                            let _e124 = local_10;
                            let _e125 = local_12;
                            let _e127 = local_11;
                            let _e128 = f32(_e127);
                            local_13 = _e128;
                            let _e132 = (((((_e121 / _e122) + 1f) * 0.5f) * _e128) - 0.5f);
                            local_14 = _e132;
                            local_15 = (((((_e124 / _e125) + 1f) * 0.5f) * _e128) - 0.5f);
                            if (_e132 > -1f) {
                                let _e138 = local_15;
                                if (_e138 > -1f) {
                                    let _e140 = local_14;
                                    let _e141 = local_13;
                                    if (_e140 < _e141) {
                                        let _e143 = local_15;
                                        let _e144 = local_13;
                                        let _e145 = (_e143 < _e144);
                                        local_16 = _e145;
                                        if _e145 {
                                            let _e146 = local_14;
                                            let _e147 = floor(_e146);
                                            local_17 = _e147;
                                            let _e148 = local_15;
                                            let _e149 = floor(_e148);
                                            local_18 = _e149;
                                            let _e150 = local_14;
                                            local_19 = (_e150 - _e147);
                                            let _e152 = local_15;
                                            local_20 = (_e152 - _e149);
                                            let _e154 = (_e147 < 0f);
                                            local_21 = _e154;
                                            if _e154 {
                                                phi_216_ = f32();
                                                phi_217_ = true;
                                            } else {
                                                let _e155 = local_18;
                                                if (_e155 < 0f) {
                                                    phi_214_ = f32();
                                                    phi_215_ = true;
                                                } else {
                                                    let _e157 = local_17;
                                                    let _e158 = local_13;
                                                    if (_e157 >= _e158) {
                                                        phi_212_ = f32();
                                                        phi_213_ = true;
                                                    } else {
                                                        let _e160 = local_18;
                                                        let _e161 = local_13;
                                                        let _e162 = (_e160 >= _e161);
                                                        if _e162 {
                                                            phi_211_ = f32();
                                                        } else {
                                                            let _e163 = local_18;
                                                            let _e165 = local_18;
                                                            let _e167 = local_18;
                                                            let _e171 = local_11;
                                                            let _e173 = local_17;
                                                            let _e175 = local_17;
                                                            let _e177 = local_17;
                                                            let _e181 = ((select(select(u32(_e163), 0u, (_e165 < 0f)), 4294967295u, (_e167 > 4294967000f)) * _e171) + select(select(u32(_e173), 0u, (_e175 < 0f)), 4294967295u, (_e177 > 4294967000f)));
                                                            local_22 = _e181;
                                                            let _e182 = local;
                                                            if (_e181 < _e182) {
                                                            } else {
                                                                break;
                                                            }
                                                            let _e184 = local_22;
                                                            let _e187 = global.member[_e184];
                                                            phi_211_ = bitcast<f32>(_e187);
                                                        }
                                                        let _e190 = phi_211_;
                                                        phi_212_ = _e190;
                                                        phi_213_ = _e162;
                                                    }
                                                    let _e192 = phi_212_;
                                                    let _e194 = phi_213_;
                                                    phi_214_ = _e192;
                                                    phi_215_ = _e194;
                                                }
                                                let _e196 = phi_214_;
                                                let _e198 = phi_215_;
                                                phi_216_ = _e196;
                                                phi_217_ = _e198;
                                            }
                                            let _e200 = phi_216_;
                                            let _e202 = phi_217_;
                                            let _e204 = local_19;
                                            let _e205 = (1f - _e204);
                                            local_23 = _e205;
                                            local_24 = (select(_e200, 0f, _e202) * _e205);
                                            let _e207 = local_17;
                                            let _e208 = (_e207 + 1f);
                                            local_25 = _e208;
                                            let _e209 = (_e208 < 0f);
                                            local_26 = _e209;
                                            if _e209 {
                                                phi_272_ = f32();
                                                phi_273_ = true;
                                            } else {
                                                let _e210 = local_18;
                                                if (_e210 < 0f) {
                                                    phi_270_ = f32();
                                                    phi_271_ = true;
                                                } else {
                                                    let _e212 = local_25;
                                                    let _e213 = local_13;
                                                    if (_e212 >= _e213) {
                                                        phi_268_ = f32();
                                                        phi_269_ = true;
                                                    } else {
                                                        let _e215 = local_18;
                                                        let _e216 = local_13;
                                                        let _e217 = (_e215 >= _e216);
                                                        if _e217 {
                                                            phi_267_ = f32();
                                                        } else {
                                                            let _e218 = local_18;
                                                            let _e220 = local_18;
                                                            let _e222 = local_18;
                                                            let _e226 = local_11;
                                                            let _e228 = local_25;
                                                            let _e230 = local_25;
                                                            let _e232 = local_25;
                                                            let _e236 = ((select(select(u32(_e218), 0u, (_e220 < 0f)), 4294967295u, (_e222 > 4294967000f)) * _e226) + select(select(u32(_e228), 0u, (_e230 < 0f)), 4294967295u, (_e232 > 4294967000f)));
                                                            local_27 = _e236;
                                                            let _e237 = local;
                                                            if (_e236 < _e237) {
                                                            } else {
                                                                break;
                                                            }
                                                            let _e239 = local_27;
                                                            let _e242 = global.member[_e239];
                                                            phi_267_ = bitcast<f32>(_e242);
                                                        }
                                                        let _e245 = phi_267_;
                                                        phi_268_ = _e245;
                                                        phi_269_ = _e217;
                                                    }
                                                    let _e247 = phi_268_;
                                                    let _e249 = phi_269_;
                                                    phi_270_ = _e247;
                                                    phi_271_ = _e249;
                                                }
                                                let _e251 = phi_270_;
                                                let _e253 = phi_271_;
                                                phi_272_ = _e251;
                                                phi_273_ = _e253;
                                            }
                                            let _e255 = phi_272_;
                                            let _e257 = phi_273_;
                                            let _e259 = local_19;
                                            let _e261 = local_24;
                                            local_28 = (_e261 + (select(_e255, 0f, _e257) * _e259));
                                            let _e263 = local_18;
                                            local_29 = (_e263 + 1f);
                                            let _e265 = local_21;
                                            if _e265 {
                                                phi_328_ = f32();
                                                phi_329_ = true;
                                            } else {
                                                let _e266 = local_29;
                                                if (_e266 < 0f) {
                                                    phi_326_ = f32();
                                                    phi_327_ = true;
                                                } else {
                                                    let _e268 = local_17;
                                                    let _e269 = local_13;
                                                    if (_e268 >= _e269) {
                                                        phi_324_ = f32();
                                                        phi_325_ = true;
                                                    } else {
                                                        let _e271 = local_29;
                                                        let _e272 = local_13;
                                                        let _e273 = (_e271 >= _e272);
                                                        if _e273 {
                                                            phi_323_ = f32();
                                                        } else {
                                                            let _e274 = local_29;
                                                            let _e276 = local_29;
                                                            let _e278 = local_29;
                                                            let _e282 = local_11;
                                                            let _e284 = local_17;
                                                            let _e286 = local_17;
                                                            let _e288 = local_17;
                                                            let _e292 = ((select(select(u32(_e274), 0u, (_e276 < 0f)), 4294967295u, (_e278 > 4294967000f)) * _e282) + select(select(u32(_e284), 0u, (_e286 < 0f)), 4294967295u, (_e288 > 4294967000f)));
                                                            local_30 = _e292;
                                                            let _e293 = local;
                                                            if (_e292 < _e293) {
                                                            } else {
                                                                break;
                                                            }
                                                            let _e295 = local_30;
                                                            let _e298 = global.member[_e295];
                                                            phi_323_ = bitcast<f32>(_e298);
                                                        }
                                                        let _e301 = phi_323_;
                                                        phi_324_ = _e301;
                                                        phi_325_ = _e273;
                                                    }
                                                    let _e303 = phi_324_;
                                                    let _e305 = phi_325_;
                                                    phi_326_ = _e303;
                                                    phi_327_ = _e305;
                                                }
                                                let _e307 = phi_326_;
                                                let _e309 = phi_327_;
                                                phi_328_ = _e307;
                                                phi_329_ = _e309;
                                            }
                                            let _e311 = phi_328_;
                                            let _e313 = phi_329_;
                                            let _e315 = local_23;
                                            local_31 = (select(_e311, 0f, _e313) * _e315);
                                            let _e317 = local_26;
                                            if _e317 {
                                                phi_385_ = f32();
                                                phi_386_ = true;
                                            } else {
                                                let _e318 = local_29;
                                                if (_e318 < 0f) {
                                                    phi_383_ = f32();
                                                    phi_384_ = true;
                                                } else {
                                                    let _e320 = local_25;
                                                    let _e321 = local_13;
                                                    if (_e320 >= _e321) {
                                                        phi_381_ = f32();
                                                        phi_382_ = true;
                                                    } else {
                                                        let _e323 = local_29;
                                                        let _e324 = local_13;
                                                        let _e325 = (_e323 >= _e324);
                                                        if _e325 {
                                                            phi_380_ = f32();
                                                        } else {
                                                            let _e326 = local_29;
                                                            let _e328 = local_29;
                                                            let _e330 = local_29;
                                                            let _e334 = local_11;
                                                            let _e336 = local_25;
                                                            let _e338 = local_25;
                                                            let _e340 = local_25;
                                                            let _e344 = ((select(select(u32(_e326), 0u, (_e328 < 0f)), 4294967295u, (_e330 > 4294967000f)) * _e334) + select(select(u32(_e336), 0u, (_e338 < 0f)), 4294967295u, (_e340 > 4294967000f)));
                                                            local_32 = _e344;
                                                            let _e345 = local;
                                                            if (_e344 < _e345) {
                                                            } else {
                                                                break;
                                                            }
                                                            let _e347 = local_32;
                                                            let _e350 = global.member[_e347];
                                                            phi_380_ = bitcast<f32>(_e350);
                                                        }
                                                        let _e353 = phi_380_;
                                                        phi_381_ = _e353;
                                                        phi_382_ = _e325;
                                                    }
                                                    let _e355 = phi_381_;
                                                    let _e357 = phi_382_;
                                                    phi_383_ = _e355;
                                                    phi_384_ = _e357;
                                                }
                                                let _e359 = phi_383_;
                                                let _e361 = phi_384_;
                                                phi_385_ = _e359;
                                                phi_386_ = _e361;
                                            }
                                            let _e363 = phi_385_;
                                            let _e365 = phi_386_;
                                            let _e367 = local_19;
                                            let _e369 = local_31;
                                            let _e371 = local_20;
                                            let _e373 = local_28;
                                            let _e375 = local_20;
                                            phi_397_ = ((_e373 * (1f - _e371)) + ((_e369 + (select(_e363, 0f, _e365) * _e367)) * _e375));
                                        } else {
                                            phi_397_ = f32();
                                        }
                                        let _e379 = phi_397_;
                                        let _e380 = local_16;
                                        phi_399_ = _e379;
                                        phi_400_ = select(true, false, _e380);
                                    } else {
                                        phi_399_ = f32();
                                        phi_400_ = true;
                                    }
                                    let _e383 = phi_399_;
                                    let _e385 = phi_400_;
                                    phi_401_ = _e383;
                                    phi_402_ = _e385;
                                } else {
                                    phi_401_ = f32();
                                    phi_402_ = true;
                                }
                                let _e387 = phi_401_;
                                let _e389 = phi_402_;
                                phi_403_ = _e387;
                                phi_404_ = _e389;
                            } else {
                                phi_403_ = f32();
                                phi_404_ = true;
                            }
                            let _e391 = phi_403_;
                            let _e393 = phi_404_;
                            phi_409_ = select(_e391, 0f, _e393);
                        } else {
                            phi_409_ = 0f;
                        }
                        let _e396 = phi_409_;
                        phi_499_ = _e396;
                    } else {
                        let _e397 = local_9;
                        let _e398 = local_9;
                        let _e400 = local_10;
                        let _e401 = local_10;
                        let _e404 = sqrt(((_e397 * _e398) + (_e400 * _e401)));
                        local_33 = _e404;
                        let _e405 = local_8;
                        if _e405 {
                            phi_486_ = _e404;
                        } else {
                            let _e409 = global_1.member.member_9.member_2;
                            let _e411 = local_9;
                            let _e414 = local_10;
                            phi_428_ = 1u;
                            phi_431_ = ((_e411 * _e409[0]) + (_e414 * _e409[1]));
                            phi_433_ = _e409;
                            loop {
                                let _e418 = phi_428_;
                                let _e420 = phi_431_;
                                let _e422 = phi_433_;
                                local_34 = _e418;
                                local_35 = _e420;
                                local_36 = _e422;
                                let _e423 = local_34;
                                let _e424 = local_7;
                                let _e425 = (_e423 < _e424);
                                local_37 = _e425;
                                if _e425 {
                                    let _e426 = local_36;
                                    let _e432 = global_1.member.member_9.member_3[0u];
                                    let _e434 = local_36;
                                    let _e440 = global_1.member.member_9.member_3[1u];
                                    let _e442 = ((_e426[0] * _e432) - (_e434[1] * _e440));
                                    let _e445 = ((_e426[0] * _e440) + (_e434[1] * _e432));
                                    let _e447 = local_9;
                                    let _e449 = local_10;
                                    let _e451 = ((_e447 * _e442) + (_e449 * _e445));
                                    let _e452 = local_35;
                                    let _e454 = local_35;
                                    let _e456 = local_34;
                                    phi_429_ = (_e456 + 1u);
                                    phi_432_ = select(_e454, _e451, (_e451 > _e452));
                                    phi_434_ = array<f32, 2>(_e442, _e445);
                                } else {
                                    phi_429_ = u32();
                                    phi_432_ = f32();
                                    phi_434_ = array<f32, 2>();
                                }
                                let _e459 = phi_429_;
                                let _e461 = phi_432_;
                                let _e463 = phi_434_;
                                continue;
                                continuing {
                                    let _e464 = local_37;
                                    phi_428_ = _e459;
                                    phi_431_ = _e461;
                                    phi_433_ = _e463;
                                    break if !(_e464);
                                }
                            }
                            let _e469 = global_1.member.member_9.member_1;
                            let _e471 = local_35;
                            let _e476 = global_1.member.member_9.member_4;
                            let _e478 = local_33;
                            phi_486_ = ((((1f - _e469) * _e471) * _e476) + (_e469 * _e478));
                        }
                        let _e482 = phi_486_;
                        let _e483 = local_4;
                        let _e484 = (_e483 - _e482);
                        phi_499_ = select(0f, select(1f, _e484, (_e484 < 1f)), (0f < _e484));
                    }
                    let _e490 = phi_499_;
                    phi_500_ = _e490;
                }
                let _e492 = phi_500_;
                phi_501_ = _e492;
            } else {
                phi_501_ = 0f;
            }
            let _e494 = phi_501_;
            let _e495 = local_3;
            let _e498 = local_3;
            let _e501 = local_3;
            global_5 = vec4<f32>((_e494 * _e495.x), (_e494 * _e498.y), (_e494 * _e501.z), 0f);
            break;
        }
    }
    return;
}

@fragment 
fn bokeh_fs(@location(0) param: vec2<f32>, @location(1) @interpolate(flat) param_1: vec4<f32>, @location(2) @interpolate(flat) param_2: vec2<f32>) -> @location(0) vec4<f32> {
    global_2 = param;
    global_3 = param_1;
    global_4 = param_2;
    function_();
    let _e7 = global_5;
    return _e7;
}
