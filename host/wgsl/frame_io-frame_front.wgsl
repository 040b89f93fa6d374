struct type_6 {
    member: array<u32>,
}

struct type_12 {
    member: array<f32, 3>,
    member_1: f32,
}

struct type_13 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_14 {
    member: type_13,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_6;
@group(0) @binding(1) 
var<storage> global_4: type_6;
var<immediate> global_5: type_14;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_6;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_6;
var<private> global_8: u32 = 2143289344u;
var<private> global_9: u32 = 2139095040u;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: u32;
    var local_8: bool;
    var local_9: u32;
    var local_10: u32;
    var local_11: type_12;
    var local_12: f32;
    var local_13: u32;
    var local_14: f32;
    var local_15: bool;
    var local_16: u32;
    var local_17: f32;
    var local_18: u32;
    var local_19: f32;
    var local_20: u32;
    var local_21: f32;
    var local_22: array<f32, 3>;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: bool;
    var local_28: u32;
    var local_29: f32;
    var local_30: bool;
    var local_31: bool;
    var local_32: bool;
    var local_33: u32;
    var local_34: f32;
    var local_35: u32;
    var local_36: f32;
    var local_37: u32;
    var local_38: array<f32, 3>;
    var local_39: u32;
    var local_40: f32;
    var local_41: array<f32, 3>;
    var local_42: f32;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: u32;
    var phi_582_: bool;
    var phi_100_: u32;
    var phi_143_: type_12;
    var phi_146_: f32;
    var phi_148_: u32;
    var phi_275_: bool;
    var phi_276_: bool;
    var phi_278_: bool;
    var phi_279_: bool;
    var phi_280_: bool;
    var phi_281_: bool;
    var phi_303_: f32;
    var phi_322_: bool;
    var phi_324_: bool;
    var phi_325_: bool;
    var phi_326_: bool;
    var phi_327_: bool;
    var phi_356_: type_12;
    var phi_357_: type_12;
    var phi_358_: type_12;
    var phi_359_: f32;
    var phi_361_: type_12;
    var phi_362_: f32;
    var phi_363_: u32;
    var phi_144_: type_12;
    var phi_147_: f32;
    var phi_149_: u32;
    var phi_364_: bool;
    var phi_564_: bool;
    var phi_465_: type_12;
    var phi_466_: type_12;
    var phi_589_: bool;
    var phi_468_: type_12;
    var phi_469_: type_12;
    var phi_470_: bool;
    var phi_474_: type_12;
    var phi_587_: bool;
    var phi_586_: bool;
    var phi_101_: u32;
    var phi_585_: bool;

    let _e83 = global_8;
    let _e85 = global_9;
    switch bitcast<i32>(0u) {
        default: {
            let _e89 = global;
            local = _e89;
            let _e90 = global_1;
            let _e91 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e104 = global_5.member.member;
            let _e107 = global_5.member.member_1;
            local_5 = (_e104 * _e107);
            local_6 = (_e91.x * 256u);
            phi_582_ = false;
            phi_100_ = (_e90.x * 256u);
            loop {
                let _e112 = phi_582_;
                let _e114 = phi_100_;
                local_7 = _e114;
                let _e115 = local_7;
                let _e116 = local_5;
                let _e117 = (_e115 < _e116);
                local_8 = _e117;
                if _e117 {
                    let _e118 = local_7;
                    let _e119 = local;
                    let _e120 = (_e118 + _e119);
                    local_9 = _e120;
                    let _e121 = local_5;
                    if (_e120 < _e121) {
                        let _e123 = local_9;
                        let _e124 = local_2;
                        if (_e123 < _e124) {
                        } else {
                            phi_585_ = true;
                            break;
                        }
                        let _e126 = local_9;
                        let _e129 = global_4.member[_e126];
                        let _e132 = global_5.member.member_6;
                        local_10 = _e132;
                        let _e134 = select(_e129, _e132, (_e132 < _e129));
                        local_50 = _e134;
                        if (_e134 == 0u) {
                            phi_589_ = _e112;
                            phi_468_ = type_12(array<f32, 3>(0f, 0f, 0f), bitcast<f32>(_e85));
                            phi_469_ = type_12();
                            phi_470_ = true;
                        } else {
                            phi_143_ = type_12(array<f32, 3>(0f, 0f, 0f), 1f);
                            phi_146_ = bitcast<f32>(_e83);
                            phi_148_ = 0u;
                            loop {
                                let _e137 = phi_143_;
                                let _e139 = phi_146_;
                                let _e141 = phi_148_;
                                local_11 = _e137;
                                local_12 = _e139;
                                local_13 = _e141;
                                let _e142 = local_13;
                                let _e143 = local_50;
                                if (_e142 < _e143) {
                                    let _e145 = local_11;
                                    local_14 = _e145.member_1;
                                    let _e147 = (_e145.member_1 > 0f);
                                    local_15 = _e147;
                                    if _e147 {
                                        let _e148 = local_9;
                                        let _e149 = local_10;
                                        let _e151 = local_13;
                                        let _e153 = (5u * ((_e148 * _e149) + _e151));
                                        local_16 = _e153;
                                        let _e154 = local_1;
                                        if (_e153 < _e154) {
                                        } else {
                                            phi_564_ = true;
                                            break;
                                        }
                                        let _e156 = local_16;
                                        let _e159 = global_3.member[_e156];
                                        local_17 = bitcast<f32>(_e159);
                                        let _e161 = local_16;
                                        let _e162 = (_e161 + 1u);
                                        local_18 = _e162;
                                        let _e163 = local_1;
                                        if (_e162 < _e163) {
                                        } else {
                                            phi_564_ = true;
                                            break;
                                        }
                                        let _e165 = local_18;
                                        let _e168 = global_3.member[_e165];
                                        local_19 = bitcast<f32>(_e168);
                                        let _e170 = local_16;
                                        let _e171 = (_e170 + 2u);
                                        local_20 = _e171;
                                        let _e172 = local_1;
                                        if (_e171 < _e172) {
                                        } else {
                                            phi_564_ = true;
                                            break;
                                        }
                                        let _e174 = local_20;
                                        let _e177 = global_3.member[_e174];
                                        let _e178 = bitcast<f32>(_e177);
                                        local_21 = _e178;
                                        let _e179 = local_17;
                                        let _e180 = local_19;
                                        local_22 = array<f32, 3>(_e179, _e180, _e178);
                                        let _e182 = local_16;
                                        let _e183 = (_e182 + 3u);
                                        local_23 = _e183;
                                        let _e184 = local_1;
                                        if (_e183 < _e184) {
                                        } else {
                                            phi_564_ = true;
                                            break;
                                        }
                                        let _e186 = local_23;
                                        let _e189 = global_3.member[_e186];
                                        local_24 = bitcast<f32>(_e189);
                                        let _e191 = local_16;
                                        let _e192 = (_e191 + 4u);
                                        local_25 = _e192;
                                        let _e193 = local_1;
                                        if (_e192 < _e193) {
                                        } else {
                                            phi_564_ = true;
                                            break;
                                        }
                                        let _e195 = local_25;
                                        let _e198 = global_3.member[_e195];
                                        local_26 = bitcast<f32>(_e198);
                                        let _e200 = local_17;
                                        if ((bitcast<u32>(_e200) & 2139095040u) != 2139095040u) {
                                            let _e204 = local_19;
                                            if ((bitcast<u32>(_e204) & 2139095040u) != 2139095040u) {
                                                let _e208 = local_21;
                                                let _e211 = ((bitcast<u32>(_e208) & 2139095040u) != 2139095040u);
                                                local_27 = _e211;
                                                if _e211 {
                                                    let _e212 = local_24;
                                                    let _e213 = bitcast<u32>(_e212);
                                                    local_28 = _e213;
                                                    if (_e213 == 0u) {
                                                        phi_275_ = false;
                                                    } else {
                                                        let _e215 = local_28;
                                                        phi_275_ = (_e215 <= 2139095040u);
                                                    }
                                                    let _e218 = phi_275_;
                                                    phi_276_ = _e218;
                                                } else {
                                                    phi_276_ = bool();
                                                }
                                                let _e220 = phi_276_;
                                                let _e221 = local_27;
                                                phi_278_ = _e220;
                                                phi_279_ = select(true, false, _e221);
                                            } else {
                                                phi_278_ = bool();
                                                phi_279_ = true;
                                            }
                                            let _e224 = phi_278_;
                                            let _e226 = phi_279_;
                                            phi_280_ = _e224;
                                            phi_281_ = _e226;
                                        } else {
                                            phi_280_ = bool();
                                            phi_281_ = true;
                                        }
                                        let _e228 = phi_280_;
                                        let _e230 = phi_281_;
                                        if select(_e228, false, _e230) {
                                            let _e232 = local_12;
                                            let _e234 = local_12;
                                            let _e235 = local_24;
                                            let _e237 = local_26;
                                            if (_e237 > 1f) {
                                                phi_303_ = 1f;
                                            } else {
                                                let _e239 = local_26;
                                                let _e241 = local_26;
                                                phi_303_ = select(0f, _e241, (_e239 >= 0f));
                                            }
                                            let _e244 = phi_303_;
                                            local_29 = _e244;
                                            let _e245 = local_14;
                                            if (_e245 >= 1f) {
                                                let _e247 = local_11;
                                                if (_e247.member[0] == 0f) {
                                                    let _e251 = local_11;
                                                    let _e254 = (_e251.member[1] == 0f);
                                                    local_30 = _e254;
                                                    if _e254 {
                                                        let _e255 = local_11;
                                                        phi_322_ = (_e255.member[2] == 0f);
                                                    } else {
                                                        phi_322_ = bool();
                                                    }
                                                    let _e260 = phi_322_;
                                                    let _e261 = local_30;
                                                    phi_324_ = _e260;
                                                    phi_325_ = select(true, false, _e261);
                                                } else {
                                                    phi_324_ = bool();
                                                    phi_325_ = true;
                                                }
                                                let _e264 = phi_324_;
                                                let _e266 = phi_325_;
                                                phi_326_ = _e264;
                                                phi_327_ = _e266;
                                            } else {
                                                phi_326_ = bool();
                                                phi_327_ = true;
                                            }
                                            let _e268 = phi_326_;
                                            let _e270 = phi_327_;
                                            if select(_e268, false, _e270) {
                                                let _e272 = local_29;
                                                let _e274 = local_22;
                                                phi_357_ = type_12(_e274, (1f - _e272));
                                            } else {
                                                let _e276 = local_15;
                                                if _e276 {
                                                    let _e277 = local_11;
                                                    let _e280 = local_14;
                                                    let _e281 = local_17;
                                                    let _e284 = local_11;
                                                    let _e287 = local_14;
                                                    let _e288 = local_19;
                                                    let _e291 = local_11;
                                                    let _e294 = local_14;
                                                    let _e295 = local_21;
                                                    let _e299 = local_29;
                                                    let _e301 = local_14;
                                                    phi_356_ = type_12(array<f32, 3>((_e277.member[0] + (_e280 * _e281)), (_e284.member[1] + (_e287 * _e288)), (_e291.member[2] + (_e294 * _e295))), (_e301 * (1f - _e299)));
                                                } else {
                                                    phi_356_ = _e137;
                                                }
                                                let _e305 = phi_356_;
                                                phi_357_ = _e305;
                                            }
                                            let _e307 = phi_357_;
                                            phi_358_ = _e307;
                                            phi_359_ = select(_e235, _e234, (_e232 > 0f));
                                        } else {
                                            phi_358_ = _e137;
                                            phi_359_ = _e139;
                                        }
                                        let _e309 = phi_358_;
                                        let _e311 = phi_359_;
                                        let _e312 = local_13;
                                        phi_361_ = _e309;
                                        phi_362_ = _e311;
                                        phi_363_ = (_e312 + 1u);
                                    } else {
                                        phi_361_ = type_12();
                                        phi_362_ = f32();
                                        phi_363_ = u32();
                                    }
                                    let _e315 = phi_361_;
                                    let _e317 = phi_362_;
                                    let _e319 = phi_363_;
                                    phi_144_ = _e315;
                                    phi_147_ = _e317;
                                    phi_149_ = _e319;
                                    phi_364_ = _e147;
                                } else {
                                    phi_144_ = type_12();
                                    phi_147_ = f32();
                                    phi_149_ = u32();
                                    phi_364_ = false;
                                }
                                let _e321 = phi_144_;
                                let _e323 = phi_147_;
                                let _e325 = phi_149_;
                                let _e327 = phi_364_;
                                local_31 = _e327;
                                continue;
                                continuing {
                                    let _e328 = local_31;
                                    phi_143_ = _e321;
                                    phi_146_ = _e323;
                                    phi_148_ = _e325;
                                    phi_564_ = _e112;
                                    break if !(_e328);
                                }
                            }
                            let _e331 = phi_564_;
                            phi_585_ = _e331;
                            if _e331 {
                                break;
                            }
                            let _e332 = local_12;
                            let _e333 = (_e332 > 0f);
                            local_32 = _e333;
                            if _e333 {
                                let _e334 = local_11;
                                let _e336 = local_12;
                                phi_465_ = type_12(_e334.member, _e336);
                                phi_466_ = type_12();
                            } else {
                                let _e338 = local_9;
                                let _e339 = local_10;
                                let _e341 = (5u * (_e338 * _e339));
                                local_33 = _e341;
                                let _e342 = local_1;
                                if (_e341 < _e342) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e344 = local_33;
                                let _e347 = global_3.member[_e344];
                                local_34 = bitcast<f32>(_e347);
                                let _e349 = local_33;
                                let _e350 = (_e349 + 1u);
                                local_35 = _e350;
                                let _e351 = local_1;
                                if (_e350 < _e351) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e353 = local_35;
                                let _e356 = global_3.member[_e353];
                                local_36 = bitcast<f32>(_e356);
                                let _e358 = local_33;
                                let _e359 = (_e358 + 2u);
                                local_37 = _e359;
                                let _e360 = local_1;
                                if (_e359 < _e360) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e362 = local_37;
                                let _e365 = global_3.member[_e362];
                                let _e367 = local_34;
                                let _e368 = local_36;
                                local_38 = array<f32, 3>(_e367, _e368, bitcast<f32>(_e365));
                                let _e370 = local_33;
                                let _e371 = (_e370 + 3u);
                                local_39 = _e371;
                                let _e372 = local_1;
                                if (_e371 < _e372) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e374 = local_39;
                                let _e377 = global_3.member[_e374];
                                local_40 = bitcast<f32>(_e377);
                                let _e379 = local_33;
                                let _e381 = local_1;
                                if ((_e379 + 4u) < _e381) {
                                } else {
                                    phi_585_ = true;
                                    break;
                                }
                                let _e383 = local_38;
                                let _e384 = local_40;
                                phi_465_ = type_12();
                                phi_466_ = type_12(_e383, _e384);
                            }
                            let _e387 = phi_465_;
                            let _e389 = phi_466_;
                            let _e390 = local_32;
                            phi_589_ = _e331;
                            phi_468_ = _e389;
                            phi_469_ = _e387;
                            phi_470_ = select(true, false, _e390);
                        }
                        let _e393 = phi_589_;
                        let _e395 = phi_468_;
                        let _e397 = phi_469_;
                        let _e399 = phi_470_;
                        if _e399 {
                            phi_474_ = _e395;
                        } else {
                            phi_474_ = _e397;
                        }
                        let _e401 = phi_474_;
                        local_41 = _e401.member;
                        local_42 = _e401.member_1;
                        let _e404 = local_9;
                        let _e405 = (3u * _e404);
                        local_43 = _e405;
                        local_44 = bitcast<u32>(_e401.member[0]);
                        let _e408 = local_3;
                        if (_e405 < _e408) {
                        } else {
                            phi_585_ = true;
                            break;
                        }
                        let _e410 = local_43;
                        let _e413 = local_44;
                        global_6.member[_e410] = _e413;
                        let _e414 = local_43;
                        let _e415 = (_e414 + 1u);
                        local_45 = _e415;
                        let _e416 = local_41;
                        local_46 = bitcast<u32>(_e416[1]);
                        let _e419 = local_3;
                        if (_e415 < _e419) {
                        } else {
                            phi_585_ = true;
                            break;
                        }
                        let _e421 = local_45;
                        let _e424 = local_46;
                        global_6.member[_e421] = _e424;
                        let _e425 = local_43;
                        let _e426 = (_e425 + 2u);
                        local_47 = _e426;
                        let _e427 = local_41;
                        local_48 = bitcast<u32>(_e427[2]);
                        let _e430 = local_3;
                        if (_e426 < _e430) {
                        } else {
                            phi_585_ = true;
                            break;
                        }
                        let _e432 = local_47;
                        let _e435 = local_48;
                        global_6.member[_e432] = _e435;
                        let _e436 = local_42;
                        local_49 = bitcast<u32>(_e436);
                        let _e438 = local_9;
                        let _e439 = local_4;
                        if (_e438 < _e439) {
                        } else {
                            phi_585_ = true;
                            break;
                        }
                        let _e441 = local_9;
                        let _e444 = local_49;
                        global_7.member[_e441] = _e444;
                        phi_587_ = _e393;
                    } else {
                        phi_587_ = _e112;
                    }
                    let _e446 = phi_587_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e447 = local_7;
                    let _e448 = local_6;
                    phi_586_ = _e446;
                    phi_101_ = (_e447 + _e448);
                } else {
                    phi_586_ = _e112;
                    phi_101_ = u32();
                }
                let _e451 = phi_586_;
                let _e453 = phi_101_;
                continue;
                continuing {
                    let _e454 = local_8;
                    phi_582_ = _e451;
                    phi_100_ = _e453;
                    phi_585_ = _e451;
                    break if !(_e454);
                }
            }
            let _e457 = phi_585_;
            if _e457 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn frame_front(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
