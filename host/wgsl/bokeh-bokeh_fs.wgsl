struct type_2 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_4 {
    member: array<u32>,
}

struct type_12 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_13 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: type_2,
    member_9: type_12,
}

struct type_14 {
    member: type_13,
}

@group(0) @binding(1) 
var<storage> global: type_4;
var<immediate> global_1: type_14;
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
                                                            let _e168 = local_18;
                                                            let _e172 = local_11;
                                                            let _e174 = local_17;
                                                            let _e176 = local_17;
                                                            let _e179 = local_17;
                                                            let _e183 = ((select(select(u32(_e163), 0u, !((_e165 >= 0f))), 4294967295u, (_e168 > 4294967000f)) * _e172) + select(select(u32(_e174), 0u, !((_e176 >= 0f))), 4294967295u, (_e179 > 4294967000f)));
                                                            local_22 = _e183;
                                                            let _e184 = local;
                                                            if (_e183 < _e184) {
                                                            } else {
                                                                break;
                                                            }
                                                            let _e186 = local_22;
                                                            let _e189 = global.member[_e186];
                                                            phi_211_ = bitcast<f32>(_e189);
                                                        }
                                                        let _e192 = phi_211_;
                                                        phi_212_ = _e192;
                                                        phi_213_ = _e162;
                                                    }
                                                    let _e194 = phi_212_;
                                                    let _e196 = phi_213_;
                                                    phi_214_ = _e194;
                                                    phi_215_ = _e196;
                                                }
                                                let _e198 = phi_214_;
                                                let _e200 = phi_215_;
                                                phi_216_ = _e198;
                                                phi_217_ = _e200;
                                            }
                                            let _e202 = phi_216_;
                                            let _e204 = phi_217_;
                                            let _e206 = local_19;
                                            let _e207 = (1f - _e206);
                                            local_23 = _e207;
                                            local_24 = (select(_e202, 0f, _e204) * _e207);
                                            let _e209 = local_17;
                                            let _e210 = (_e209 + 1f);
                                            local_25 = _e210;
                                            let _e211 = (_e210 < 0f);
                                            local_26 = _e211;
                                            if _e211 {
                                                phi_272_ = f32();
                                                phi_273_ = true;
                                            } else {
                                                let _e212 = local_18;
                                                if (_e212 < 0f) {
                                                    phi_270_ = f32();
                                                    phi_271_ = true;
                                                } else {
                                                    let _e214 = local_25;
                                                    let _e215 = local_13;
                                                    if (_e214 >= _e215) {
                                                        phi_268_ = f32();
                                                        phi_269_ = true;
                                                    } else {
                                                        let _e217 = local_18;
                                                        let _e218 = local_13;
                                                        let _e219 = (_e217 >= _e218);
                                                        if _e219 {
                                                            phi_267_ = f32();
                                                        } else {
                                                            let _e220 = local_18;
                                                            let _e222 = local_18;
                                                            let _e225 = local_18;
                                                            let _e229 = local_11;
                                                            let _e231 = local_25;
                                                            let _e233 = local_25;
                                                            let _e236 = local_25;
                                                            let _e240 = ((select(select(u32(_e220), 0u, !((_e222 >= 0f))), 4294967295u, (_e225 > 4294967000f)) * _e229) + select(select(u32(_e231), 0u, !((_e233 >= 0f))), 4294967295u, (_e236 > 4294967000f)));
                                                            local_27 = _e240;
                                                            let _e241 = local;
                                                            if (_e240 < _e241) {
                                                            } else {
                                                                break;
                                                            }
                                                            let _e243 = local_27;
                                                            let _e246 = global.member[_e243];
                                                            phi_267_ = bitcast<f32>(_e246);
                                                        }
                                                        let _e249 = phi_267_;
                                                        phi_268_ = _e249;
                                                        phi_269_ = _e219;
                                                    }
                                                    let _e251 = phi_268_;
                                                    let _e253 = phi_269_;
                                                    phi_270_ = _e251;
                                                    phi_271_ = _e253;
                                                }
                                                let _e255 = phi_270_;
                                                let _e257 = phi_271_;
                                                phi_272_ = _e255;
                                                phi_273_ = _e257;
                                            }
                                            let _e259 = phi_272_;
                                            let _e261 = phi_273_;
                                            let _e263 = local_19;
                                            let _e265 = local_24;
                                            local_28 = (_e265 + (select(_e259, 0f, _e261) * _e263));
                                            let _e267 = local_18;
                                            local_29 = (_e267 + 1f);
                                            let _e269 = local_21;
                                            if _e269 {
                                                phi_328_ = f32();
                                                phi_329_ = true;
                                            } else {
                                                let _e270 = local_29;
                                                if (_e270 < 0f) {
                                                    phi_326_ = f32();
                                                    phi_327_ = true;
                                                } else {
                                                    let _e272 = local_17;
                                                    let _e273 = local_13;
                                                    if (_e272 >= _e273) {
                                                        phi_324_ = f32();
                                                        phi_325_ = true;
                                                    } else {
                                                        let _e275 = local_29;
                                                        let _e276 = local_13;
                                                        let _e277 = (_e275 >= _e276);
                                                        if _e277 {
                                                            phi_323_ = f32();
                                                        } else {
                                                            let _e278 = local_29;
                                                            let _e280 = local_29;
                                                            let _e283 = local_29;
                                                            let _e287 = local_11;
                                                            let _e289 = local_17;
                                                            let _e291 = local_17;
                                                            let _e294 = local_17;
                                                            let _e298 = ((select(select(u32(_e278), 0u, !((_e280 >= 0f))), 4294967295u, (_e283 > 4294967000f)) * _e287) + select(select(u32(_e289), 0u, !((_e291 >= 0f))), 4294967295u, (_e294 > 4294967000f)));
                                                            local_30 = _e298;
                                                            let _e299 = local;
                                                            if (_e298 < _e299) {
                                                            } else {
                                                                break;
                                                            }
                                                            let _e301 = local_30;
                                                            let _e304 = global.member[_e301];
                                                            phi_323_ = bitcast<f32>(_e304);
                                                        }
                                                        let _e307 = phi_323_;
                                                        phi_324_ = _e307;
                                                        phi_325_ = _e277;
                                                    }
                                                    let _e309 = phi_324_;
                                                    let _e311 = phi_325_;
                                                    phi_326_ = _e309;
                                                    phi_327_ = _e311;
                                                }
                                                let _e313 = phi_326_;
                                                let _e315 = phi_327_;
                                                phi_328_ = _e313;
                                                phi_329_ = _e315;
                                            }
                                            let _e317 = phi_328_;
                                            let _e319 = phi_329_;
                                            let _e321 = local_23;
                                            local_31 = (select(_e317, 0f, _e319) * _e321);
                                            let _e323 = local_26;
                                            if _e323 {
                                                phi_385_ = f32();
                                                phi_386_ = true;
                                            } else {
                                                let _e324 = local_29;
                                                if (_e324 < 0f) {
                                                    phi_383_ = f32();
                                                    phi_384_ = true;
                                                } else {
                                                    let _e326 = local_25;
                                                    let _e327 = local_13;
                                                    if (_e326 >= _e327) {
                                                        phi_381_ = f32();
                                                        phi_382_ = true;
                                                    } else {
                                                        let _e329 = local_29;
                                                        let _e330 = local_13;
                                                        let _e331 = (_e329 >= _e330);
                                                        if _e331 {
                                                            phi_380_ = f32();
                                                        } else {
                                                            let _e332 = local_29;
                                                            let _e334 = local_29;
                                                            let _e337 = local_29;
                                                            let _e341 = local_11;
                                                            let _e343 = local_25;
                                                            let _e345 = local_25;
                                                            let _e348 = local_25;
                                                            let _e352 = ((select(select(u32(_e332), 0u, !((_e334 >= 0f))), 4294967295u, (_e337 > 4294967000f)) * _e341) + select(select(u32(_e343), 0u, !((_e345 >= 0f))), 4294967295u, (_e348 > 4294967000f)));
                                                            local_32 = _e352;
                                                            let _e353 = local;
                                                            if (_e352 < _e353) {
                                                            } else {
                                                                break;
                                                            }
                                                            let _e355 = local_32;
                                                            let _e358 = global.member[_e355];
                                                            phi_380_ = bitcast<f32>(_e358);
                                                        }
                                                        let _e361 = phi_380_;
                                                        phi_381_ = _e361;
                                                        phi_382_ = _e331;
                                                    }
                                                    let _e363 = phi_381_;
                                                    let _e365 = phi_382_;
                                                    phi_383_ = _e363;
                                                    phi_384_ = _e365;
                                                }
                                                let _e367 = phi_383_;
                                                let _e369 = phi_384_;
                                                phi_385_ = _e367;
                                                phi_386_ = _e369;
                                            }
                                            let _e371 = phi_385_;
                                            let _e373 = phi_386_;
                                            let _e375 = local_19;
                                            let _e377 = local_31;
                                            let _e379 = local_20;
                                            let _e381 = local_28;
                                            let _e383 = local_20;
                                            phi_397_ = ((_e381 * (1f - _e379)) + ((_e377 + (select(_e371, 0f, _e373) * _e375)) * _e383));
                                        } else {
                                            phi_397_ = f32();
                                        }
                                        let _e387 = phi_397_;
                                        let _e388 = local_16;
                                        phi_399_ = _e387;
                                        phi_400_ = select(true, false, _e388);
                                    } else {
                                        phi_399_ = f32();
                                        phi_400_ = true;
                                    }
                                    let _e391 = phi_399_;
                                    let _e393 = phi_400_;
                                    phi_401_ = _e391;
                                    phi_402_ = _e393;
                                } else {
                                    phi_401_ = f32();
                                    phi_402_ = true;
                                }
                                let _e395 = phi_401_;
                                let _e397 = phi_402_;
                                phi_403_ = _e395;
                                phi_404_ = _e397;
                            } else {
                                phi_403_ = f32();
                                phi_404_ = true;
                            }
                            let _e399 = phi_403_;
                            let _e401 = phi_404_;
                            phi_409_ = select(_e399, 0f, _e401);
                        } else {
                            phi_409_ = 0f;
                        }
                        let _e404 = phi_409_;
                        phi_499_ = _e404;
                    } else {
                        let _e405 = local_9;
                        let _e406 = local_9;
                        let _e408 = local_10;
                        let _e409 = local_10;
                        let _e412 = sqrt(((_e405 * _e406) + (_e408 * _e409)));
                        local_33 = _e412;
                        let _e413 = local_8;
                        if _e413 {
                            phi_486_ = _e412;
                        } else {
                            let _e417 = global_1.member.member_9.member_2;
                            let _e419 = local_9;
                            let _e422 = local_10;
                            phi_428_ = 1u;
                            phi_431_ = ((_e419 * _e417[0]) + (_e422 * _e417[1]));
                            phi_433_ = _e417;
                            loop {
                                let _e426 = phi_428_;
                                let _e428 = phi_431_;
                                let _e430 = phi_433_;
                                local_34 = _e426;
                                local_35 = _e428;
                                local_36 = _e430;
                                let _e431 = local_34;
                                let _e432 = local_7;
                                let _e433 = (_e431 < _e432);
                                local_37 = _e433;
                                if _e433 {
                                    let _e434 = local_36;
                                    let _e440 = global_1.member.member_9.member_3[0u];
                                    let _e442 = local_36;
                                    let _e448 = global_1.member.member_9.member_3[1u];
                                    let _e450 = ((_e434[0] * _e440) - (_e442[1] * _e448));
                                    let _e453 = ((_e434[0] * _e448) + (_e442[1] * _e440));
                                    let _e455 = local_9;
                                    let _e457 = local_10;
                                    let _e459 = ((_e455 * _e450) + (_e457 * _e453));
                                    let _e460 = local_35;
                                    let _e462 = local_35;
                                    let _e464 = local_34;
                                    phi_429_ = (_e464 + 1u);
                                    phi_432_ = select(_e462, _e459, (_e459 > _e460));
                                    phi_434_ = array<f32, 2>(_e450, _e453);
                                } else {
                                    phi_429_ = u32();
                                    phi_432_ = f32();
                                    phi_434_ = array<f32, 2>();
                                }
                                let _e467 = phi_429_;
                                let _e469 = phi_432_;
                                let _e471 = phi_434_;
                                continue;
                                continuing {
                                    let _e472 = local_37;
                                    phi_428_ = _e467;
                                    phi_431_ = _e469;
                                    phi_433_ = _e471;
                                    break if !(_e472);
                                }
                            }
                            let _e477 = global_1.member.member_9.member_1;
                            let _e479 = local_35;
                            let _e484 = global_1.member.member_9.member_4;
                            let _e486 = local_33;
                            phi_486_ = ((((1f - _e477) * _e479) * _e484) + (_e477 * _e486));
                        }
                        let _e490 = phi_486_;
                        let _e491 = local_4;
                        let _e492 = (_e491 - _e490);
                        phi_499_ = select(0f, select(1f, _e492, (_e492 < 1f)), (0f < _e492));
                    }
                    let _e498 = phi_499_;
                    phi_500_ = _e498;
                }
                let _e500 = phi_500_;
                phi_501_ = _e500;
            } else {
                phi_501_ = 0f;
            }
            let _e502 = phi_501_;
            let _e503 = local_3;
            let _e506 = local_3;
            let _e509 = local_3;
            global_5 = vec4<f32>((_e502 * _e503.x), (_e502 * _e506.y), (_e502 * _e509.z), 0f);
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
