struct type_6 {
    member: array<u32>,
}

struct type_15 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: f32,
}

struct type_16 {
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

struct type_17 {
    member: type_16,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(1) 
var<storage> global_3: type_6;
var<immediate> global_4: type_17;
@group(0) @binding(0) 
var<storage> global_5: type_6;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_6;
var<private> global_7: u32 = 2139095040u;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var local_5: u32;
    var local_6: u32;
    var local_7: bool;
    var local_8: u32;
    var local_9: u32;
    var local_10: f32;
    var local_11: f32;
    var local_12: bool;
    var local_13: u32;
    var local_14: bool;
    var local_15: f32;
    var local_16: bool;
    var local_17: u32;
    var local_18: f32;
    var local_19: u32;
    var local_20: f32;
    var local_21: u32;
    var local_22: f32;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: bool;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: bool;
    var local_32: array<f32, 4>;
    var local_33: bool;
    var local_34: u32;
    var local_35: f32;
    var local_36: u32;
    var local_37: f32;
    var local_38: u32;
    var local_39: array<f32, 3>;
    var local_40: u32;
    var local_41: f32;
    var local_42: u32;
    var local_43: type_15;
    var local_44: bool;
    var local_45: u32;
    var local_46: array<f32, 3>;
    var local_47: f32;
    var local_48: f32;
    var local_49: f32;
    var local_50: f32;
    var local_51: f32;
    var local_52: f32;
    var local_53: f32;
    var local_54: f32;
    var local_55: f32;
    var local_56: f32;
    var local_57: f32;
    var local_58: bool;
    var local_59: f32;
    var local_60: f32;
    var local_61: bool;
    var local_62: f32;
    var local_63: f32;
    var local_64: bool;
    var local_65: f32;
    var local_66: f32;
    var local_67: f32;
    var local_68: u32;
    var local_69: u32;
    var local_70: u32;
    var local_71: u32;
    var local_72: u32;
    var local_73: u32;
    var local_74: u32;
    var local_75: u32;
    var local_76: u32;
    var local_77: bool;
    var local_78: bool;
    var local_79: f32;
    var phi_941_: bool;
    var phi_104_: u32;
    var phi_159_: bool;
    var phi_184_: f32;
    var phi_186_: f32;
    var phi_187_: bool;
    var phi_192_: f32;
    var phi_194_: array<f32, 4>;
    var phi_196_: u32;
    var phi_199_: bool;
    var phi_201_: f32;
    var phi_322_: bool;
    var phi_323_: bool;
    var phi_325_: bool;
    var phi_326_: bool;
    var phi_327_: bool;
    var phi_328_: bool;
    var phi_345_: f32;
    var phi_349_: f32;
    var phi_197_: u32;
    var phi_200_: bool;
    var phi_202_: f32;
    var phi_923_: bool;
    var phi_355_: bool;
    var phi_360_: u32;
    var phi_362_: u32;
    var phi_365_: bool;
    var phi_367_: array<f32, 4>;
    var phi_471_: type_15;
    var phi_500_: bool;
    var phi_501_: bool;
    var phi_503_: bool;
    var phi_504_: bool;
    var phi_505_: bool;
    var phi_506_: bool;
    var phi_525_: bool;
    var phi_539_: bool;
    var phi_544_: f32;
    var phi_555_: bool;
    var phi_569_: bool;
    var phi_574_: f32;
    var phi_585_: bool;
    var phi_599_: bool;
    var phi_604_: f32;
    var phi_616_: f32;
    var phi_634_: bool;
    var phi_671_: f32;
    var phi_673_: f32;
    var phi_674_: bool;
    var phi_675_: f32;
    var phi_676_: bool;
    var phi_693_: bool;
    var phi_718_: f32;
    var phi_720_: f32;
    var phi_721_: bool;
    var phi_726_: f32;
    var phi_727_: f32;
    var phi_741_: bool;
    var phi_766_: f32;
    var phi_768_: f32;
    var phi_769_: bool;
    var phi_774_: f32;
    var phi_775_: f32;
    var phi_776_: f32;
    var phi_912_: bool;
    var phi_801_: array<f32, 4>;
    var phi_363_: u32;
    var phi_366_: bool;
    var phi_368_: array<f32, 4>;
    var phi_943_: bool;
    var phi_1000_: bool;
    var phi_999_: bool;
    var phi_105_: u32;
    var phi_998_: bool;

    let _e113 = global_7;
    let _e114 = bitcast<f32>(_e113);
    local_79 = _e114;
    switch bitcast<i32>(0u) {
        default: {
            let _e117 = global;
            local = _e117;
            let _e118 = global_1;
            let _e119 = global_2;
            local_1 = arrayLength((&global_5.member));
            local_2 = arrayLength((&global_3.member));
            local_3 = arrayLength((&global_6.member));
            let _e130 = global_4.member.member;
            let _e133 = global_4.member.member_1;
            local_4 = (_e130 * _e133);
            local_5 = (_e119.x * 256u);
            phi_941_ = false;
            phi_104_ = (_e118.x * 256u);
            loop {
                let _e138 = phi_941_;
                let _e140 = phi_104_;
                local_6 = _e140;
                let _e141 = local_6;
                let _e142 = local_4;
                let _e143 = (_e141 < _e142);
                local_7 = _e143;
                if _e143 {
                    let _e144 = local_6;
                    let _e145 = local;
                    let _e146 = (_e144 + _e145);
                    local_8 = _e146;
                    let _e147 = local_4;
                    if (_e146 < _e147) {
                        let _e149 = local_8;
                        let _e150 = local_2;
                        if (_e149 < _e150) {
                        } else {
                            phi_998_ = true;
                            break;
                        }
                        let _e152 = local_8;
                        let _e155 = global_3.member[_e152];
                        let _e158 = global_4.member.member_2;
                        local_9 = _e158;
                        let _e160 = select(_e155, _e158, (_e158 < _e155));
                        local_76 = _e160;
                        if (_e160 == 0u) {
                            let _e165 = global_4.member.member_8[1u];
                            local_10 = _e165;
                            let _e166 = local_79;
                            if (_e166 >= _e165) {
                                let _e171 = global_4.member.member_8[2u];
                                let _e172 = local_79;
                                phi_159_ = select(true, false, (_e172 <= _e171));
                            } else {
                                phi_159_ = true;
                            }
                            let _e176 = phi_159_;
                            if _e176 {
                                let _e180 = global_4.member.member_8[0u];
                                local_11 = _e180;
                                let _e181 = local_79;
                                if (_e181 > _e180) {
                                    let _e183 = local_79;
                                    let _e184 = local_10;
                                    let _e185 = (_e183 < _e184);
                                    local_12 = _e185;
                                    if _e185 {
                                        let _e186 = local_79;
                                        let _e187 = local_11;
                                        let _e189 = local_10;
                                        let _e190 = local_11;
                                        phi_184_ = ((_e186 - _e187) / (_e189 - _e190));
                                    } else {
                                        phi_184_ = f32();
                                    }
                                    let _e194 = phi_184_;
                                    let _e195 = local_12;
                                    phi_186_ = _e194;
                                    phi_187_ = select(true, false, _e195);
                                } else {
                                    phi_186_ = f32();
                                    phi_187_ = true;
                                }
                                let _e198 = phi_186_;
                                let _e200 = phi_187_;
                                phi_192_ = select(_e198, 0f, _e200);
                            } else {
                                phi_192_ = 1f;
                            }
                            let _e203 = phi_192_;
                            phi_194_ = array<f32, 4>(array<f32, 4>(0f, 0f, 0f, 0f)[0], array<f32, 4>(0f, 0f, 0f, 0f)[1], array<f32, 4>(0f, 0f, 0f, 0f)[2], _e203);
                        } else {
                            phi_194_ = array<f32, 4>(0f, 0f, 0f, 0f);
                        }
                        let _e210 = phi_194_;
                        phi_196_ = 0u;
                        phi_199_ = false;
                        phi_201_ = 1f;
                        loop {
                            let _e212 = phi_196_;
                            let _e214 = phi_199_;
                            let _e216 = phi_201_;
                            local_13 = _e212;
                            local_14 = _e214;
                            local_15 = _e216;
                            let _e217 = local_13;
                            let _e218 = local_76;
                            let _e219 = (_e217 < _e218);
                            local_16 = _e219;
                            if _e219 {
                                let _e220 = local_8;
                                let _e221 = local_9;
                                let _e223 = local_13;
                                let _e225 = (5u * ((_e220 * _e221) + _e223));
                                local_17 = _e225;
                                let _e226 = local_1;
                                if (_e225 < _e226) {
                                } else {
                                    phi_923_ = true;
                                    break;
                                }
                                let _e228 = local_17;
                                let _e231 = global_5.member[_e228];
                                local_18 = bitcast<f32>(_e231);
                                let _e233 = local_17;
                                let _e234 = (_e233 + 1u);
                                local_19 = _e234;
                                let _e235 = local_1;
                                if (_e234 < _e235) {
                                } else {
                                    phi_923_ = true;
                                    break;
                                }
                                let _e237 = local_19;
                                let _e240 = global_5.member[_e237];
                                local_20 = bitcast<f32>(_e240);
                                let _e242 = local_17;
                                let _e243 = (_e242 + 2u);
                                local_21 = _e243;
                                let _e244 = local_1;
                                if (_e243 < _e244) {
                                } else {
                                    phi_923_ = true;
                                    break;
                                }
                                let _e246 = local_21;
                                let _e249 = global_5.member[_e246];
                                local_22 = bitcast<f32>(_e249);
                                let _e251 = local_17;
                                let _e252 = (_e251 + 3u);
                                local_23 = _e252;
                                let _e253 = local_1;
                                if (_e252 < _e253) {
                                } else {
                                    phi_923_ = true;
                                    break;
                                }
                                let _e255 = local_23;
                                let _e258 = global_5.member[_e255];
                                local_24 = bitcast<f32>(_e258);
                                let _e260 = local_17;
                                let _e261 = (_e260 + 4u);
                                local_25 = _e261;
                                let _e262 = local_1;
                                if (_e261 < _e262) {
                                } else {
                                    phi_923_ = true;
                                    break;
                                }
                                let _e264 = local_25;
                                let _e267 = global_5.member[_e264];
                                local_26 = bitcast<f32>(_e267);
                                let _e269 = local_18;
                                if ((bitcast<u32>(_e269) & 2139095040u) != 2139095040u) {
                                    let _e273 = local_20;
                                    if ((bitcast<u32>(_e273) & 2139095040u) != 2139095040u) {
                                        let _e277 = local_22;
                                        let _e280 = ((bitcast<u32>(_e277) & 2139095040u) != 2139095040u);
                                        local_27 = _e280;
                                        if _e280 {
                                            let _e281 = local_24;
                                            let _e282 = bitcast<u32>(_e281);
                                            local_28 = _e282;
                                            if (_e282 == 0u) {
                                                phi_322_ = false;
                                            } else {
                                                let _e284 = local_28;
                                                phi_322_ = (_e284 <= 2139095040u);
                                            }
                                            let _e287 = phi_322_;
                                            phi_323_ = _e287;
                                        } else {
                                            phi_323_ = bool();
                                        }
                                        let _e289 = phi_323_;
                                        let _e290 = local_27;
                                        phi_325_ = _e289;
                                        phi_326_ = select(true, false, _e290);
                                    } else {
                                        phi_325_ = bool();
                                        phi_326_ = true;
                                    }
                                    let _e293 = phi_325_;
                                    let _e295 = phi_326_;
                                    phi_327_ = _e293;
                                    phi_328_ = _e295;
                                } else {
                                    phi_327_ = bool();
                                    phi_328_ = true;
                                }
                                let _e297 = phi_327_;
                                let _e299 = phi_328_;
                                let _e300 = select(_e297, false, _e299);
                                local_77 = _e300;
                                if _e300 {
                                    let _e301 = local_26;
                                    if (_e301 > 1f) {
                                        phi_345_ = 1f;
                                    } else {
                                        let _e303 = local_26;
                                        let _e305 = local_26;
                                        phi_345_ = select(0f, _e305, (_e303 >= 0f));
                                    }
                                    let _e308 = phi_345_;
                                    let _e310 = local_15;
                                    phi_349_ = (_e310 * (1f - _e308));
                                } else {
                                    phi_349_ = _e216;
                                }
                                let _e313 = phi_349_;
                                let _e314 = local_77;
                                let _e315 = local_14;
                                let _e317 = local_13;
                                phi_197_ = (_e317 + 1u);
                                phi_200_ = select(_e315, true, _e314);
                                phi_202_ = _e313;
                            } else {
                                phi_197_ = u32();
                                phi_200_ = bool();
                                phi_202_ = f32();
                            }
                            let _e320 = phi_197_;
                            let _e322 = phi_200_;
                            let _e324 = phi_202_;
                            continue;
                            continuing {
                                let _e325 = local_16;
                                phi_196_ = _e320;
                                phi_199_ = _e322;
                                phi_201_ = _e324;
                                phi_923_ = _e138;
                                break if !(_e325);
                            }
                        }
                        let _e328 = phi_923_;
                        phi_998_ = _e328;
                        if _e328 {
                            break;
                        }
                        let _e329 = local_14;
                        if _e329 {
                            let _e330 = local_15;
                            phi_355_ = (_e330 > 0f);
                        } else {
                            phi_355_ = false;
                        }
                        let _e333 = phi_355_;
                        if _e333 {
                            let _e334 = local_76;
                            phi_360_ = (_e334 + 1u);
                        } else {
                            phi_360_ = _e160;
                        }
                        let _e337 = phi_360_;
                        local_29 = _e337;
                        phi_362_ = 0u;
                        phi_365_ = true;
                        phi_367_ = _e210;
                        loop {
                            let _e339 = phi_362_;
                            let _e341 = phi_365_;
                            let _e343 = phi_367_;
                            local_30 = _e339;
                            local_31 = _e341;
                            local_32 = _e343;
                            let _e344 = local_30;
                            let _e345 = local_29;
                            let _e346 = (_e344 < _e345);
                            local_33 = _e346;
                            if _e346 {
                                let _e347 = local_30;
                                let _e348 = local_76;
                                if (_e347 < _e348) {
                                    let _e350 = local_8;
                                    let _e351 = local_9;
                                    let _e353 = local_30;
                                    let _e355 = (5u * ((_e350 * _e351) + _e353));
                                    local_34 = _e355;
                                    let _e356 = local_1;
                                    if (_e355 < _e356) {
                                    } else {
                                        phi_943_ = true;
                                        break;
                                    }
                                    let _e358 = local_34;
                                    let _e361 = global_5.member[_e358];
                                    local_35 = bitcast<f32>(_e361);
                                    let _e363 = local_34;
                                    let _e364 = (_e363 + 1u);
                                    local_36 = _e364;
                                    let _e365 = local_1;
                                    if (_e364 < _e365) {
                                    } else {
                                        phi_943_ = true;
                                        break;
                                    }
                                    let _e367 = local_36;
                                    let _e370 = global_5.member[_e367];
                                    local_37 = bitcast<f32>(_e370);
                                    let _e372 = local_34;
                                    let _e373 = (_e372 + 2u);
                                    local_38 = _e373;
                                    let _e374 = local_1;
                                    if (_e373 < _e374) {
                                    } else {
                                        phi_943_ = true;
                                        break;
                                    }
                                    let _e376 = local_38;
                                    let _e379 = global_5.member[_e376];
                                    let _e381 = local_35;
                                    let _e382 = local_37;
                                    local_39 = array<f32, 3>(_e381, _e382, bitcast<f32>(_e379));
                                    let _e384 = local_34;
                                    let _e385 = (_e384 + 3u);
                                    local_40 = _e385;
                                    let _e386 = local_1;
                                    if (_e385 < _e386) {
                                    } else {
                                        phi_943_ = true;
                                        break;
                                    }
                                    let _e388 = local_40;
                                    let _e391 = global_5.member[_e388];
                                    local_41 = bitcast<f32>(_e391);
                                    let _e393 = local_34;
                                    let _e394 = (_e393 + 4u);
                                    local_42 = _e394;
                                    let _e395 = local_1;
                                    if (_e394 < _e395) {
                                    } else {
                                        phi_943_ = true;
                                        break;
                                    }
                                    let _e397 = local_42;
                                    let _e400 = global_5.member[_e397];
                                    let _e402 = local_39;
                                    let _e403 = local_41;
                                    phi_471_ = type_15(_e402, _e403, bitcast<f32>(_e400));
                                } else {
                                    phi_471_ = type_15(array<f32, 3>(0f, 0f, 0f), _e114, 1f);
                                }
                                let _e406 = phi_471_;
                                local_43 = _e406;
                                if ((bitcast<u32>(_e406.member[0]) & 2139095040u) != 2139095040u) {
                                    let _e412 = local_43;
                                    if ((bitcast<u32>(_e412.member[1]) & 2139095040u) != 2139095040u) {
                                        let _e418 = local_43;
                                        let _e423 = ((bitcast<u32>(_e418.member[2]) & 2139095040u) != 2139095040u);
                                        local_44 = _e423;
                                        if _e423 {
                                            let _e424 = local_43;
                                            let _e426 = bitcast<u32>(_e424.member_1);
                                            local_45 = _e426;
                                            if (_e426 == 0u) {
                                                phi_500_ = false;
                                            } else {
                                                let _e428 = local_45;
                                                phi_500_ = (_e428 <= 2139095040u);
                                            }
                                            let _e431 = phi_500_;
                                            phi_501_ = _e431;
                                        } else {
                                            phi_501_ = bool();
                                        }
                                        let _e433 = phi_501_;
                                        let _e434 = local_44;
                                        phi_503_ = _e433;
                                        phi_504_ = select(true, false, _e434);
                                    } else {
                                        phi_503_ = bool();
                                        phi_504_ = true;
                                    }
                                    let _e437 = phi_503_;
                                    let _e439 = phi_504_;
                                    phi_505_ = _e437;
                                    phi_506_ = _e439;
                                } else {
                                    phi_505_ = bool();
                                    phi_506_ = true;
                                }
                                let _e441 = phi_505_;
                                let _e443 = phi_506_;
                                let _e444 = select(_e441, false, _e443);
                                local_78 = _e444;
                                if _e444 {
                                    let _e445 = local_43;
                                    local_46 = _e445.member;
                                    local_47 = _e445.member[0];
                                    if (_e445.member[0] > 1267650600000000000000000000000f) {
                                        let _e449 = local_47;
                                        phi_525_ = select(true, false, (_e449 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_525_ = true;
                                    }
                                    let _e453 = phi_525_;
                                    if _e453 {
                                        let _e454 = local_47;
                                        if (_e454 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e456 = local_47;
                                            phi_539_ = select(true, false, (_e456 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_539_ = true;
                                        }
                                        let _e460 = phi_539_;
                                        let _e461 = local_47;
                                        phi_544_ = select(0f, _e461, _e460);
                                    } else {
                                        phi_544_ = 1267650600000000000000000000000f;
                                    }
                                    let _e464 = phi_544_;
                                    local_48 = _e464;
                                    let _e465 = local_46;
                                    local_49 = _e465[1];
                                    if (_e465[1] > 1267650600000000000000000000000f) {
                                        let _e468 = local_49;
                                        phi_555_ = select(true, false, (_e468 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_555_ = true;
                                    }
                                    let _e472 = phi_555_;
                                    if _e472 {
                                        let _e473 = local_49;
                                        if (_e473 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e475 = local_49;
                                            phi_569_ = select(true, false, (_e475 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_569_ = true;
                                        }
                                        let _e479 = phi_569_;
                                        let _e480 = local_49;
                                        phi_574_ = select(0f, _e480, _e479);
                                    } else {
                                        phi_574_ = 1267650600000000000000000000000f;
                                    }
                                    let _e483 = phi_574_;
                                    local_50 = _e483;
                                    let _e484 = local_46;
                                    local_51 = _e484[2];
                                    if (_e484[2] > 1267650600000000000000000000000f) {
                                        let _e487 = local_51;
                                        phi_585_ = select(true, false, (_e487 <= 340282350000000000000000000000000000000f));
                                    } else {
                                        phi_585_ = true;
                                    }
                                    let _e491 = phi_585_;
                                    if _e491 {
                                        let _e492 = local_51;
                                        if (_e492 < 0.000000000000000000000000000000000000011754944f) {
                                            let _e494 = local_51;
                                            phi_599_ = select(true, false, (_e494 >= -340282350000000000000000000000000000000f));
                                        } else {
                                            phi_599_ = true;
                                        }
                                        let _e498 = phi_599_;
                                        let _e499 = local_51;
                                        phi_604_ = select(0f, _e499, _e498);
                                    } else {
                                        phi_604_ = 1267650600000000000000000000000f;
                                    }
                                    let _e502 = phi_604_;
                                    local_52 = _e502;
                                    let _e503 = local_43;
                                    local_53 = _e503.member_1;
                                    let _e505 = local_43;
                                    local_54 = _e505.member_2;
                                    if (_e505.member_2 > 1f) {
                                        phi_616_ = 1f;
                                    } else {
                                        let _e508 = local_54;
                                        let _e510 = local_54;
                                        phi_616_ = select(0f, _e510, (_e508 >= 0f));
                                    }
                                    let _e513 = phi_616_;
                                    local_55 = _e513;
                                    if (_e513 < 1f) {
                                        let _e518 = global_4.member.member_8[1u];
                                        let _e519 = local_53;
                                        if (_e519 > _e518) {
                                            let _e524 = global_4.member.member_8[2u];
                                            let _e525 = local_53;
                                            phi_634_ = select(true, false, (_e525 <= _e524));
                                        } else {
                                            phi_634_ = true;
                                        }
                                        let _e529 = phi_634_;
                                        phi_776_ = select(1f, 0f, _e529);
                                    } else {
                                        let _e531 = local_31;
                                        if _e531 {
                                            let _e535 = global_4.member.member_8[2u];
                                            local_56 = _e535;
                                            let _e536 = local_53;
                                            if (_e536 > _e535) {
                                                let _e541 = global_4.member.member_8[3u];
                                                local_57 = _e541;
                                                let _e542 = local_53;
                                                if (_e542 < _e541) {
                                                    let _e544 = local_57;
                                                    let _e547 = ((bitcast<u32>(_e544) & 2139095040u) != 2139095040u);
                                                    local_58 = _e547;
                                                    if _e547 {
                                                        let _e548 = local_57;
                                                        let _e549 = local_53;
                                                        let _e551 = local_57;
                                                        let _e552 = local_56;
                                                        phi_671_ = ((_e548 - _e549) / (_e551 - _e552));
                                                    } else {
                                                        phi_671_ = f32();
                                                    }
                                                    let _e556 = phi_671_;
                                                    let _e557 = local_58;
                                                    phi_673_ = _e556;
                                                    phi_674_ = select(true, false, _e557);
                                                } else {
                                                    phi_673_ = f32();
                                                    phi_674_ = true;
                                                }
                                                let _e560 = phi_673_;
                                                let _e562 = phi_674_;
                                                phi_675_ = _e560;
                                                phi_676_ = _e562;
                                            } else {
                                                phi_675_ = f32();
                                                phi_676_ = true;
                                            }
                                            let _e564 = phi_675_;
                                            let _e566 = phi_676_;
                                            if _e566 {
                                                let _e570 = global_4.member.member_8[1u];
                                                local_59 = _e570;
                                                let _e571 = local_53;
                                                if (_e571 >= _e570) {
                                                    let _e573 = local_53;
                                                    let _e574 = local_56;
                                                    phi_693_ = select(true, false, (_e573 <= _e574));
                                                } else {
                                                    phi_693_ = true;
                                                }
                                                let _e578 = phi_693_;
                                                if _e578 {
                                                    let _e582 = global_4.member.member_8[0u];
                                                    local_60 = _e582;
                                                    let _e583 = local_53;
                                                    if (_e583 > _e582) {
                                                        let _e585 = local_53;
                                                        let _e586 = local_59;
                                                        let _e587 = (_e585 < _e586);
                                                        local_61 = _e587;
                                                        if _e587 {
                                                            let _e588 = local_53;
                                                            let _e589 = local_60;
                                                            let _e591 = local_59;
                                                            let _e592 = local_60;
                                                            phi_718_ = ((_e588 - _e589) / (_e591 - _e592));
                                                        } else {
                                                            phi_718_ = f32();
                                                        }
                                                        let _e596 = phi_718_;
                                                        let _e597 = local_61;
                                                        phi_720_ = _e596;
                                                        phi_721_ = select(true, false, _e597);
                                                    } else {
                                                        phi_720_ = f32();
                                                        phi_721_ = true;
                                                    }
                                                    let _e600 = phi_720_;
                                                    let _e602 = phi_721_;
                                                    phi_726_ = select(_e600, 0f, _e602);
                                                } else {
                                                    phi_726_ = 1f;
                                                }
                                                let _e605 = phi_726_;
                                                phi_727_ = _e605;
                                            } else {
                                                phi_727_ = _e564;
                                            }
                                            let _e607 = phi_727_;
                                            phi_775_ = _e607;
                                        } else {
                                            let _e611 = global_4.member.member_8[1u];
                                            local_62 = _e611;
                                            let _e612 = local_53;
                                            if (_e612 >= _e611) {
                                                let _e617 = global_4.member.member_8[2u];
                                                let _e618 = local_53;
                                                phi_741_ = select(true, false, (_e618 <= _e617));
                                            } else {
                                                phi_741_ = true;
                                            }
                                            let _e622 = phi_741_;
                                            if _e622 {
                                                let _e626 = global_4.member.member_8[0u];
                                                local_63 = _e626;
                                                let _e627 = local_53;
                                                if (_e627 > _e626) {
                                                    let _e629 = local_53;
                                                    let _e630 = local_62;
                                                    let _e631 = (_e629 < _e630);
                                                    local_64 = _e631;
                                                    if _e631 {
                                                        let _e632 = local_53;
                                                        let _e633 = local_63;
                                                        let _e635 = local_62;
                                                        let _e636 = local_63;
                                                        phi_766_ = ((_e632 - _e633) / (_e635 - _e636));
                                                    } else {
                                                        phi_766_ = f32();
                                                    }
                                                    let _e640 = phi_766_;
                                                    let _e641 = local_64;
                                                    phi_768_ = _e640;
                                                    phi_769_ = select(true, false, _e641);
                                                } else {
                                                    phi_768_ = f32();
                                                    phi_769_ = true;
                                                }
                                                let _e644 = phi_768_;
                                                let _e646 = phi_769_;
                                                phi_774_ = select(_e644, 0f, _e646);
                                            } else {
                                                phi_774_ = 1f;
                                            }
                                            let _e649 = phi_774_;
                                            phi_775_ = _e649;
                                        }
                                        let _e651 = phi_775_;
                                        phi_776_ = _e651;
                                    }
                                    let _e653 = phi_776_;
                                    local_65 = _e653;
                                    let _e654 = local_32;
                                    local_66 = _e654[3];
                                    let _e656 = (1f - _e654[3]);
                                    local_67 = _e656;
                                    if !((_e656 == _e656)) {
                                        phi_912_ = true;
                                    } else {
                                        let _e659 = local_67;
                                        phi_912_ = (0f >= _e659);
                                    }
                                    let _e662 = phi_912_;
                                    let _e663 = local_67;
                                    let _e665 = local_65;
                                    let _e666 = (select(_e663, 0f, _e662) * _e665);
                                    let _e667 = local_48;
                                    let _e669 = local_32;
                                    let _e672 = local_50;
                                    let _e674 = local_32;
                                    let _e677 = local_52;
                                    let _e679 = local_32;
                                    let _e682 = local_55;
                                    let _e684 = local_66;
                                    phi_801_ = array<f32, 4>((_e669[0] + (_e666 * _e667)), (_e674[1] + (_e666 * _e672)), (_e679[2] + (_e666 * _e677)), (_e684 + (_e666 * _e682)));
                                } else {
                                    phi_801_ = _e343;
                                }
                                let _e688 = phi_801_;
                                let _e689 = local_78;
                                let _e690 = local_31;
                                let _e692 = local_30;
                                phi_363_ = (_e692 + 1u);
                                phi_366_ = select(_e690, false, _e689);
                                phi_368_ = _e688;
                            } else {
                                phi_363_ = u32();
                                phi_366_ = bool();
                                phi_368_ = array<f32, 4>();
                            }
                            let _e695 = phi_363_;
                            let _e697 = phi_366_;
                            let _e699 = phi_368_;
                            continue;
                            continuing {
                                let _e700 = local_33;
                                phi_362_ = _e695;
                                phi_365_ = _e697;
                                phi_367_ = _e699;
                                phi_943_ = _e328;
                                break if !(_e700);
                            }
                        }
                        let _e703 = phi_943_;
                        phi_998_ = _e703;
                        if _e703 {
                            break;
                        }
                        let _e704 = local_8;
                        let _e705 = (4u * _e704);
                        local_68 = _e705;
                        let _e706 = local_32;
                        local_69 = bitcast<u32>(_e706[0]);
                        let _e709 = local_3;
                        if (_e705 < _e709) {
                        } else {
                            phi_998_ = true;
                            break;
                        }
                        let _e711 = local_68;
                        let _e714 = local_69;
                        global_6.member[_e711] = _e714;
                        let _e715 = local_68;
                        let _e716 = (_e715 + 1u);
                        local_70 = _e716;
                        let _e717 = local_32;
                        local_71 = bitcast<u32>(_e717[1]);
                        let _e720 = local_3;
                        if (_e716 < _e720) {
                        } else {
                            phi_998_ = true;
                            break;
                        }
                        let _e722 = local_70;
                        let _e725 = local_71;
                        global_6.member[_e722] = _e725;
                        let _e726 = local_68;
                        let _e727 = (_e726 + 2u);
                        local_72 = _e727;
                        let _e728 = local_32;
                        local_73 = bitcast<u32>(_e728[2]);
                        let _e731 = local_3;
                        if (_e727 < _e731) {
                        } else {
                            phi_998_ = true;
                            break;
                        }
                        let _e733 = local_72;
                        let _e736 = local_73;
                        global_6.member[_e733] = _e736;
                        let _e737 = local_68;
                        let _e738 = (_e737 + 3u);
                        local_74 = _e738;
                        let _e739 = local_32;
                        local_75 = bitcast<u32>(_e739[3]);
                        let _e742 = local_3;
                        if (_e738 < _e742) {
                        } else {
                            phi_998_ = true;
                            break;
                        }
                        let _e744 = local_74;
                        let _e747 = local_75;
                        global_6.member[_e744] = _e747;
                        phi_1000_ = _e703;
                    } else {
                        phi_1000_ = _e138;
                    }
                    let _e749 = phi_1000_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e750 = local_6;
                    let _e751 = local_5;
                    phi_999_ = _e749;
                    phi_105_ = (_e750 + _e751);
                } else {
                    phi_999_ = _e138;
                    phi_105_ = u32();
                }
                let _e754 = phi_999_;
                let _e756 = phi_105_;
                continue;
                continuing {
                    let _e757 = local_7;
                    phi_941_ = _e754;
                    phi_104_ = _e756;
                    phi_998_ = _e754;
                    break if !(_e757);
                }
            }
            let _e760 = phi_998_;
            if _e760 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn layered_matte(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
