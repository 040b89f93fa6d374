struct type_5 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_7 {
    member: array<u32>,
}

struct type_14 {
    member: u32,
    member_1: u32,
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
    member_16: type_15,
    member_17: u32,
    member_18: u32,
}

struct type_17 {
    member: type_16,
}

struct type_21 {
    member: u32,
    member_1: f32,
}

struct type_27 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_17;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage, read_write> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_7;
@group(0) @binding(4) 
var<storage, read_write> global_8: type_27;
var<workgroup> global_9: array<u32, 1536>;

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
    var local_13: u32;
    var local_14: bool;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: u32;
    var local_20: bool;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: bool;
    var local_25: u32;
    var local_26: u32;
    var local_27: bool;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: bool;
    var local_32: bool;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: f32;
    var local_37: u32;
    var local_38: bool;
    var local_39: u32;
    var local_40: u32;
    var local_41: bool;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: bool;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: u32;
    var local_50: f32;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
    var local_54: bool;
    var local_55: u32;
    var local_56: bool;
    var local_57: u32;
    var local_58: bool;
    var local_59: bool;
    var local_60: u32;
    var local_61: u32;
    var local_62: u32;
    var local_63: u32;
    var local_64: u32;
    var local_65: u32;
    var local_66: bool;
    var local_67: u32;
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
    var local_78: u32;
    var local_79: u32;
    var local_80: u32;
    var local_81: u32;
    var local_82: bool;
    var local_83: u32;
    var local_84: u32;
    var local_85: bool;
    var local_86: u32;
    var local_87: u32;
    var local_88: u32;
    var local_89: bool;
    var local_90: u32;
    var local_91: u32;
    var local_92: u32;
    var local_93: bool;
    var local_94: u32;
    var local_95: u32;
    var local_96: u32;
    var local_97: u32;
    var local_98: u32;
    var local_99: u32;
    var local_100: u32;
    var local_101: u32;
    var phi_150_: u32;
    var phi_167_: u32;
    var phi_183_: u32;
    var phi_749_: bool;
    var phi_185_: u32;
    var phi_238_: u32;
    var phi_241_: f32;
    var phi_243_: u32;
    var phi_296_: u32;
    var phi_298_: u32;
    var phi_299_: bool;
    var phi_304_: u32;
    var phi_332_: f32;
    var phi_333_: u32;
    var phi_239_: u32;
    var phi_242_: f32;
    var phi_244_: u32;
    var phi_743_: bool;
    var phi_767_: bool;
    var phi_336_: type_21;
    var phi_766_: bool;
    var phi_338_: type_21;
    var phi_339_: bool;
    var phi_344_: type_21;
    var phi_377_: u32;
    var phi_380_: bool;
    var phi_440_: bool;
    var phi_454_: u32;
    var phi_479_: u32;
    var phi_378_: u32;
    var phi_381_: bool;
    var phi_756_: bool;
    var phi_496_: type_14;
    var phi_559_: u32;
    var phi_564_: u32;
    var phi_617_: u32;
    var phi_619_: u32;
    var phi_620_: bool;
    var phi_625_: u32;
    var phi_674_: u32;
    var phi_560_: u32;
    var phi_565_: u32;
    var phi_768_: bool;
    var phi_693_: bool;
    var phi_780_: bool;
    var phi_779_: bool;
    var phi_778_: bool;
    var phi_186_: u32;
    var phi_777_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e143 = global;
            local = _e143;
            let _e144 = global_1;
            let _e145 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = arrayLength((&global_8.member));
            local_6 = _e145.x;
            let _e160 = global_3.member.member_4;
            local_7 = _e160;
            let _e163 = global_3.member.member_5;
            local_8 = _e163;
            local_9 = (_e160 * _e163);
            let _e167 = global_3.member.member_7;
            local_10 = _e167;
            let _e170 = global_3.member.member_8;
            local_11 = (_e167 * _e170);
            let _e174 = global_3.member.member_6;
            local_12 = _e174;
            let _e177 = global_3.member.member_3;
            local_13 = _e177;
            let _e178 = (_e177 == 0u);
            local_14 = _e178;
            if _e178 {
                break;
            }
            let _e179 = local_12;
            let _e180 = local_13;
            local_15 = (_e179 / _e180);
            let _e182 = local_14;
            if _e182 {
                break;
            }
            let _e183 = local_15;
            let _e184 = local_15;
            local_16 = (_e183 * _e184);
            let _e186 = local_14;
            if _e186 {
                break;
            }
            let _e187 = local_14;
            if _e187 {
                break;
            }
            let _e188 = local_16;
            if (_e188 >= 256u) {
                phi_150_ = 1u;
            } else {
                let _e190 = local_16;
                if (_e190 == 0u) {
                    break;
                }
                let _e192 = local_16;
                phi_150_ = (256u / _e192);
            }
            let _e195 = phi_150_;
            local_17 = _e195;
            let _e196 = local_16;
            let _e197 = (_e196 / 256u);
            local_18 = _e197;
            let _e198 = local_16;
            if ((_e198 % 256u) > 0u) {
                let _e201 = local_18;
                phi_167_ = (_e201 + 1u);
            } else {
                phi_167_ = _e197;
            }
            let _e204 = phi_167_;
            local_19 = _e204;
            let _e205 = local_17;
            let _e206 = (_e205 == 0u);
            local_20 = _e206;
            if _e206 {
                break;
            }
            let _e207 = local_11;
            let _e208 = local_17;
            let _e209 = (_e207 / _e208);
            local_21 = _e209;
            let _e210 = local_20;
            if _e210 {
                break;
            }
            let _e211 = local_11;
            let _e212 = local_17;
            if ((_e211 % _e212) > 0u) {
                let _e215 = local_21;
                phi_183_ = (_e215 + 1u);
            } else {
                phi_183_ = _e209;
            }
            let _e218 = phi_183_;
            local_22 = _e218;
            phi_749_ = false;
            phi_185_ = _e144.x;
            loop {
                let _e220 = phi_749_;
                let _e222 = phi_185_;
                local_23 = _e222;
                let _e223 = local_23;
                let _e224 = local_22;
                let _e225 = (_e223 < _e224);
                local_24 = _e225;
                if _e225 {
                    let _e226 = local_23;
                    let _e227 = local_17;
                    local_25 = (_e226 * _e227);
                    let _e229 = local;
                    let _e230 = local_19;
                    local_26 = (_e229 * _e230);
                    let _e232 = local_16;
                    let _e233 = (_e232 == 0u);
                    local_27 = _e233;
                    if _e233 {
                        phi_777_ = true;
                        break;
                    }
                    let _e234 = local_26;
                    let _e235 = local_16;
                    let _e236 = (_e234 / _e235);
                    local_28 = _e236;
                    let _e237 = local_25;
                    local_29 = (_e237 + _e236);
                    let _e239 = local_16;
                    let _e241 = local_26;
                    local_30 = (_e241 - (_e236 * _e239));
                    let _e243 = local_17;
                    if (_e236 < _e243) {
                        let _e245 = local_29;
                        let _e246 = local_11;
                        let _e247 = (_e245 < _e246);
                        local_31 = _e247;
                        if _e247 {
                            let _e248 = local_10;
                            let _e249 = (_e248 == 0u);
                            local_32 = _e249;
                            if _e249 {
                                phi_777_ = true;
                                break;
                            }
                            let _e250 = local_29;
                            let _e251 = local_10;
                            local_33 = (_e250 % _e251);
                            let _e253 = local_32;
                            if _e253 {
                                phi_777_ = true;
                                break;
                            }
                            let _e254 = local_29;
                            let _e255 = local_10;
                            local_34 = (_e254 / _e255);
                            phi_238_ = 0u;
                            phi_241_ = 0f;
                            phi_243_ = 0u;
                            loop {
                                let _e258 = phi_238_;
                                let _e260 = phi_241_;
                                let _e262 = phi_243_;
                                local_35 = _e258;
                                local_36 = _e260;
                                local_37 = _e262;
                                let _e263 = local_35;
                                let _e264 = local_19;
                                let _e265 = (_e263 < _e264);
                                local_38 = _e265;
                                if _e265 {
                                    let _e266 = local_30;
                                    let _e267 = local_35;
                                    local_39 = (_e266 + _e267);
                                    let _e269 = local_14;
                                    if _e269 {
                                        phi_743_ = true;
                                        break;
                                    }
                                    let _e270 = local_39;
                                    let _e271 = local_16;
                                    if (_e270 >= _e271) {
                                        phi_304_ = 4294967295u;
                                    } else {
                                        let _e273 = local_33;
                                        let _e274 = local_15;
                                        local_40 = (_e273 * _e274);
                                        let _e276 = local_15;
                                        let _e277 = (_e276 == 0u);
                                        local_41 = _e277;
                                        if _e277 {
                                            phi_743_ = true;
                                            break;
                                        }
                                        let _e278 = local_39;
                                        let _e279 = local_15;
                                        let _e281 = local_40;
                                        local_42 = (_e281 + (_e278 % _e279));
                                        let _e283 = local_34;
                                        let _e284 = local_15;
                                        local_43 = (_e283 * _e284);
                                        let _e286 = local_41;
                                        if _e286 {
                                            phi_743_ = true;
                                            break;
                                        }
                                        let _e287 = local_39;
                                        let _e288 = local_15;
                                        let _e290 = local_43;
                                        local_44 = (_e290 + (_e287 / _e288));
                                        let _e292 = local_42;
                                        let _e293 = local_7;
                                        if (_e292 < _e293) {
                                            let _e295 = local_44;
                                            let _e296 = local_8;
                                            let _e297 = (_e295 < _e296);
                                            local_45 = _e297;
                                            if _e297 {
                                                let _e298 = local_44;
                                                let _e299 = local_7;
                                                let _e301 = local_42;
                                                phi_296_ = ((_e298 * _e299) + _e301);
                                            } else {
                                                phi_296_ = u32();
                                            }
                                            let _e304 = phi_296_;
                                            let _e305 = local_45;
                                            phi_298_ = _e304;
                                            phi_299_ = select(true, false, _e305);
                                        } else {
                                            phi_298_ = u32();
                                            phi_299_ = true;
                                        }
                                        let _e308 = phi_298_;
                                        let _e310 = phi_299_;
                                        phi_304_ = select(_e308, 4294967295u, _e310);
                                    }
                                    let _e313 = phi_304_;
                                    local_46 = _e313;
                                    if (_e313 != 4294967295u) {
                                        let _e315 = local_46;
                                        let _e316 = local_1;
                                        if (_e315 < _e316) {
                                        } else {
                                            phi_743_ = true;
                                            break;
                                        }
                                        let _e318 = local_46;
                                        let _e321 = global_4.member[_e318];
                                        local_47 = _e321;
                                        let _e322 = local_9;
                                        let _e323 = local_46;
                                        let _e324 = (_e322 + _e323);
                                        local_48 = _e324;
                                        let _e325 = local_1;
                                        if (_e324 < _e325) {
                                        } else {
                                            phi_743_ = true;
                                            break;
                                        }
                                        let _e327 = local_48;
                                        let _e330 = global_4.member[_e327];
                                        let _e331 = bitcast<f32>(_e330);
                                        let _e332 = local_37;
                                        let _e333 = local_47;
                                        let _e335 = local_36;
                                        let _e337 = local_36;
                                        phi_332_ = select(_e337, _e331, (_e331 > _e335));
                                        phi_333_ = (_e332 + _e333);
                                    } else {
                                        phi_332_ = _e260;
                                        phi_333_ = _e262;
                                    }
                                    let _e340 = phi_332_;
                                    let _e342 = phi_333_;
                                    let _e343 = local_35;
                                    phi_239_ = (_e343 + 1u);
                                    phi_242_ = _e340;
                                    phi_244_ = _e342;
                                } else {
                                    phi_239_ = u32();
                                    phi_242_ = f32();
                                    phi_244_ = u32();
                                }
                                let _e346 = phi_239_;
                                let _e348 = phi_242_;
                                let _e350 = phi_244_;
                                continue;
                                continuing {
                                    let _e351 = local_38;
                                    phi_238_ = _e346;
                                    phi_241_ = _e348;
                                    phi_243_ = _e350;
                                    phi_743_ = _e220;
                                    break if !(_e351);
                                }
                            }
                            let _e354 = phi_743_;
                            phi_777_ = _e354;
                            if _e354 {
                                break;
                            }
                            let _e355 = local_37;
                            let _e356 = local_36;
                            phi_767_ = _e354;
                            phi_336_ = type_21(_e355, _e356);
                        } else {
                            phi_767_ = _e220;
                            phi_336_ = type_21();
                        }
                        let _e359 = phi_767_;
                        let _e361 = phi_336_;
                        let _e362 = local_31;
                        phi_766_ = _e359;
                        phi_338_ = _e361;
                        phi_339_ = select(true, false, _e362);
                    } else {
                        phi_766_ = _e220;
                        phi_338_ = type_21();
                        phi_339_ = true;
                    }
                    let _e365 = phi_766_;
                    let _e367 = phi_338_;
                    let _e369 = phi_339_;
                    if _e369 {
                        phi_344_ = type_21(0u, 0f);
                    } else {
                        phi_344_ = _e367;
                    }
                    let _e371 = phi_344_;
                    local_49 = _e371.member;
                    local_50 = _e371.member_1;
                    let _e374 = local;
                    if (_e374 < 1536u) {
                    } else {
                        phi_777_ = true;
                        break;
                    }
                    let _e376 = local;
                    let _e378 = local_49;
                    global_9[_e376] = _e378;
                    let _e379 = local_50;
                    local_51 = bitcast<u32>(_e379);
                    let _e381 = local;
                    let _e382 = (512u + _e381);
                    local_52 = _e382;
                    if (_e382 < 1536u) {
                    } else {
                        phi_777_ = true;
                        break;
                    }
                    let _e384 = local_52;
                    let _e386 = local_51;
                    global_9[_e384] = _e386;
                    let _e387 = local;
                    let _e388 = (1024u + _e387);
                    local_53 = _e388;
                    let _e389 = (_e388 < 1536u);
                    local_54 = _e389;
                    if _e389 {
                    } else {
                        phi_777_ = true;
                        break;
                    }
                    let _e390 = local_53;
                    let _e392 = local_28;
                    global_9[_e390] = _e392;
                    let _e393 = local;
                    let _e394 = (1280u + _e393);
                    local_55 = _e394;
                    let _e395 = (_e394 < 1536u);
                    local_56 = _e395;
                    if _e395 {
                    } else {
                        phi_777_ = true;
                        break;
                    }
                    let _e396 = local_55;
                    let _e398 = local_49;
                    global_9[_e396] = _e398;
                    storageBarrier();
                    workgroupBarrier();
                    phi_377_ = 1u;
                    phi_380_ = false;
                    loop {
                        let _e400 = phi_377_;
                        let _e402 = phi_380_;
                        local_57 = _e400;
                        local_58 = _e402;
                        let _e403 = local_57;
                        let _e404 = (_e403 < 256u);
                        local_59 = _e404;
                        if _e404 {
                            let _e405 = local_58;
                            local_98 = select(512u, 768u, _e405);
                            let _e407 = local_58;
                            let _e408 = select(0u, 256u, _e407);
                            local_99 = _e408;
                            let _e409 = local_58;
                            local_100 = select(768u, 512u, _e409);
                            let _e411 = local_58;
                            local_101 = select(256u, 0u, _e411);
                            let _e413 = local;
                            let _e414 = (_e408 + _e413);
                            local_60 = _e414;
                            if (_e414 < 1536u) {
                            } else {
                                phi_756_ = true;
                                break;
                            }
                            let _e416 = local_60;
                            let _e418 = global_9[_e416];
                            local_61 = _e418;
                            let _e419 = local_98;
                            let _e420 = local;
                            let _e421 = (_e419 + _e420);
                            local_62 = _e421;
                            if (_e421 < 1536u) {
                            } else {
                                phi_756_ = true;
                                break;
                            }
                            let _e423 = local_62;
                            let _e425 = global_9[_e423];
                            local_63 = _e425;
                            let _e426 = local;
                            let _e427 = local_57;
                            if (_e426 >= _e427) {
                                let _e429 = local;
                                let _e430 = local_57;
                                let _e432 = (1024u + (_e429 - _e430));
                                local_64 = _e432;
                                if (_e432 < 1536u) {
                                } else {
                                    phi_756_ = true;
                                    break;
                                }
                                let _e434 = local_64;
                                let _e436 = global_9[_e434];
                                local_65 = _e436;
                                let _e437 = local_54;
                                if _e437 {
                                } else {
                                    phi_756_ = true;
                                    break;
                                }
                                let _e438 = global_9[_e390];
                                let _e439 = local_65;
                                phi_440_ = (_e439 == _e438);
                            } else {
                                phi_440_ = false;
                            }
                            let _e442 = phi_440_;
                            local_66 = _e442;
                            if _e442 {
                                let _e443 = local;
                                let _e444 = local_57;
                                let _e446 = local_99;
                                let _e447 = (_e446 + (_e443 - _e444));
                                local_67 = _e447;
                                if (_e447 < 1536u) {
                                } else {
                                    phi_756_ = true;
                                    break;
                                }
                                let _e449 = local_67;
                                let _e451 = global_9[_e449];
                                let _e452 = local_61;
                                phi_454_ = (_e451 + _e452);
                            } else {
                                phi_454_ = _e418;
                            }
                            let _e455 = phi_454_;
                            local_68 = _e455;
                            let _e456 = local_101;
                            let _e457 = local;
                            let _e458 = (_e456 + _e457);
                            local_69 = _e458;
                            if (_e458 < 1536u) {
                            } else {
                                phi_756_ = true;
                                break;
                            }
                            let _e460 = local_69;
                            let _e462 = local_68;
                            global_9[_e460] = _e462;
                            let _e463 = local_66;
                            if _e463 {
                                let _e464 = local;
                                let _e465 = local_57;
                                let _e467 = local_98;
                                let _e468 = (_e467 + (_e464 - _e465));
                                local_70 = _e468;
                                if (_e468 < 1536u) {
                                } else {
                                    phi_756_ = true;
                                    break;
                                }
                                let _e470 = local_70;
                                let _e472 = global_9[_e470];
                                let _e473 = local_63;
                                let _e475 = local_63;
                                phi_479_ = select(_e475, _e472, (_e472 > _e473));
                            } else {
                                phi_479_ = _e425;
                            }
                            let _e478 = phi_479_;
                            local_71 = _e478;
                            let _e479 = local_100;
                            let _e480 = local;
                            let _e481 = (_e479 + _e480);
                            local_72 = _e481;
                            if (_e481 < 1536u) {
                            } else {
                                phi_756_ = true;
                                break;
                            }
                            let _e483 = local_72;
                            let _e485 = local_71;
                            global_9[_e483] = _e485;
                            storageBarrier();
                            workgroupBarrier();
                            let _e486 = local_58;
                            let _e488 = local_57;
                            phi_378_ = (_e488 * 2u);
                            phi_381_ = !(_e486);
                        } else {
                            phi_378_ = u32();
                            phi_381_ = bool();
                        }
                        let _e491 = phi_378_;
                        let _e493 = phi_381_;
                        continue;
                        continuing {
                            let _e494 = local_59;
                            phi_377_ = _e491;
                            phi_380_ = _e493;
                            phi_756_ = _e365;
                            break if !(_e494);
                        }
                    }
                    let _e497 = phi_756_;
                    phi_777_ = _e497;
                    if _e497 {
                        break;
                    }
                    let _e498 = local_58;
                    if _e498 {
                        phi_496_ = type_14(256u, 768u);
                    } else {
                        phi_496_ = type_14(0u, 512u);
                    }
                    let _e500 = phi_496_;
                    local_73 = _e500.member;
                    local_74 = _e500.member_1;
                    let _e503 = local_27;
                    if _e503 {
                        phi_777_ = true;
                        break;
                    }
                    let _e504 = local_28;
                    let _e505 = local_17;
                    if (_e504 >= _e505) {
                        phi_779_ = _e497;
                    } else {
                        let _e507 = local_29;
                        let _e508 = local_11;
                        if (_e507 >= _e508) {
                            phi_780_ = _e497;
                        } else {
                            let _e510 = local_73;
                            let _e511 = local;
                            let _e512 = (_e510 + _e511);
                            local_75 = _e512;
                            if (_e512 < 1536u) {
                            } else {
                                phi_777_ = true;
                                break;
                            }
                            let _e514 = local_75;
                            let _e516 = global_9[_e514];
                            local_76 = _e516;
                            let _e517 = local_56;
                            if _e517 {
                            } else {
                                phi_777_ = true;
                                break;
                            }
                            let _e518 = global_9[_e396];
                            let _e519 = local_76;
                            let _e521 = local_10;
                            let _e522 = (_e521 == 0u);
                            local_77 = _e522;
                            if _e522 {
                                phi_777_ = true;
                                break;
                            }
                            let _e523 = local_29;
                            let _e524 = local_10;
                            local_78 = (_e523 % _e524);
                            let _e526 = local_77;
                            if _e526 {
                                phi_777_ = true;
                                break;
                            }
                            let _e527 = local_29;
                            let _e528 = local_10;
                            local_79 = (_e527 / _e528);
                            phi_559_ = 0u;
                            phi_564_ = (_e519 - _e518);
                            loop {
                                let _e531 = phi_559_;
                                let _e533 = phi_564_;
                                local_80 = _e531;
                                local_81 = _e533;
                                let _e534 = local_80;
                                let _e535 = local_19;
                                let _e536 = (_e534 < _e535);
                                local_82 = _e536;
                                if _e536 {
                                    let _e537 = local_30;
                                    let _e538 = local_80;
                                    local_83 = (_e537 + _e538);
                                    let _e540 = local_14;
                                    if _e540 {
                                        phi_768_ = true;
                                        break;
                                    }
                                    let _e541 = local_83;
                                    let _e542 = local_16;
                                    if (_e541 >= _e542) {
                                        phi_625_ = 4294967295u;
                                    } else {
                                        let _e544 = local_78;
                                        let _e545 = local_15;
                                        local_84 = (_e544 * _e545);
                                        let _e547 = local_15;
                                        let _e548 = (_e547 == 0u);
                                        local_85 = _e548;
                                        if _e548 {
                                            phi_768_ = true;
                                            break;
                                        }
                                        let _e549 = local_83;
                                        let _e550 = local_15;
                                        let _e552 = local_84;
                                        local_86 = (_e552 + (_e549 % _e550));
                                        let _e554 = local_79;
                                        let _e555 = local_15;
                                        local_87 = (_e554 * _e555);
                                        let _e557 = local_85;
                                        if _e557 {
                                            phi_768_ = true;
                                            break;
                                        }
                                        let _e558 = local_83;
                                        let _e559 = local_15;
                                        let _e561 = local_87;
                                        local_88 = (_e561 + (_e558 / _e559));
                                        let _e563 = local_86;
                                        let _e564 = local_7;
                                        if (_e563 < _e564) {
                                            let _e566 = local_88;
                                            let _e567 = local_8;
                                            let _e568 = (_e566 < _e567);
                                            local_89 = _e568;
                                            if _e568 {
                                                let _e569 = local_88;
                                                let _e570 = local_7;
                                                let _e572 = local_86;
                                                phi_617_ = ((_e569 * _e570) + _e572);
                                            } else {
                                                phi_617_ = u32();
                                            }
                                            let _e575 = phi_617_;
                                            let _e576 = local_89;
                                            phi_619_ = _e575;
                                            phi_620_ = select(true, false, _e576);
                                        } else {
                                            phi_619_ = u32();
                                            phi_620_ = true;
                                        }
                                        let _e579 = phi_619_;
                                        let _e581 = phi_620_;
                                        phi_625_ = select(_e579, 4294967295u, _e581);
                                    }
                                    let _e584 = phi_625_;
                                    local_90 = _e584;
                                    if (_e584 != 4294967295u) {
                                        let _e586 = local_90;
                                        let _e587 = local_1;
                                        if (_e586 < _e587) {
                                        } else {
                                            phi_768_ = true;
                                            break;
                                        }
                                        let _e589 = local_90;
                                        let _e592 = global_4.member[_e589];
                                        local_91 = _e592;
                                        let _e593 = local_9;
                                        let _e594 = local_90;
                                        let _e595 = (_e593 + _e594);
                                        local_92 = _e595;
                                        let _e596 = local_1;
                                        let _e597 = (_e595 < _e596);
                                        local_93 = _e597;
                                        if _e597 {
                                        } else {
                                            phi_768_ = true;
                                            break;
                                        }
                                        let _e598 = local_90;
                                        let _e599 = local_3;
                                        if (_e598 < _e599) {
                                        } else {
                                            phi_768_ = true;
                                            break;
                                        }
                                        let _e601 = local_90;
                                        let _e604 = local_81;
                                        global_6.member[_e601] = _e604;
                                        let _e605 = local_93;
                                        if _e605 {
                                        } else {
                                            phi_768_ = true;
                                            break;
                                        }
                                        let _e606 = local_92;
                                        let _e609 = global_4.member[_e606];
                                        local_94 = _e609;
                                        let _e610 = local_92;
                                        let _e611 = local_3;
                                        if (_e610 < _e611) {
                                        } else {
                                            phi_768_ = true;
                                            break;
                                        }
                                        let _e613 = local_92;
                                        let _e616 = local_94;
                                        global_6.member[_e613] = _e616;
                                        let _e617 = local_81;
                                        let _e618 = local_91;
                                        phi_674_ = (_e617 + _e618);
                                    } else {
                                        phi_674_ = _e533;
                                    }
                                    let _e621 = phi_674_;
                                    let _e622 = local_80;
                                    phi_560_ = (_e622 + 1u);
                                    phi_565_ = _e621;
                                } else {
                                    phi_560_ = u32();
                                    phi_565_ = u32();
                                }
                                let _e625 = phi_560_;
                                let _e627 = phi_565_;
                                continue;
                                continuing {
                                    let _e628 = local_82;
                                    phi_559_ = _e625;
                                    phi_564_ = _e627;
                                    phi_768_ = _e497;
                                    break if !(_e628);
                                }
                            }
                            let _e631 = phi_768_;
                            phi_777_ = _e631;
                            if _e631 {
                                break;
                            }
                            let _e632 = local;
                            if (_e632 == 255u) {
                                phi_693_ = true;
                            } else {
                                let _e634 = local;
                                let _e635 = (_e634 + 1025u);
                                local_95 = _e635;
                                if (_e635 < 1536u) {
                                } else {
                                    phi_777_ = true;
                                    break;
                                }
                                let _e637 = local_95;
                                let _e639 = global_9[_e637];
                                let _e640 = local_28;
                                phi_693_ = (_e639 != _e640);
                            }
                            let _e643 = phi_693_;
                            if _e643 {
                                let _e644 = local_29;
                                let _e645 = local_2;
                                if (_e644 < _e645) {
                                } else {
                                    phi_777_ = true;
                                    break;
                                }
                                let _e647 = local_29;
                                let _e650 = local_76;
                                global_5.member[_e647] = _e650;
                                let _e651 = local_74;
                                let _e652 = local;
                                let _e653 = (_e651 + _e652);
                                local_96 = _e653;
                                if (_e653 < 1536u) {
                                } else {
                                    phi_777_ = true;
                                    break;
                                }
                                let _e655 = local_96;
                                let _e657 = global_9[_e655];
                                local_97 = _e657;
                                let _e658 = local_29;
                                let _e659 = local_4;
                                if (_e658 < _e659) {
                                } else {
                                    phi_777_ = true;
                                    break;
                                }
                                let _e661 = local_29;
                                let _e664 = local_97;
                                global_7.member[_e661] = _e664;
                                let _e665 = local_76;
                                if (_e665 > 0u) {
                                    let _e667 = local_5;
                                    if (13u < _e667) {
                                    } else {
                                        phi_777_ = true;
                                        break;
                                    }
                                    let _e671 = local_76;
                                    let _e672 = atomicAdd((&global_8.member[13u]), _e671);
                                }
                            }
                            phi_780_ = _e631;
                        }
                        let _e674 = phi_780_;
                        phi_779_ = _e674;
                    }
                    let _e676 = phi_779_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e677 = local_23;
                    let _e678 = local_6;
                    phi_778_ = _e676;
                    phi_186_ = (_e677 + _e678);
                } else {
                    phi_778_ = _e220;
                    phi_186_ = u32();
                }
                let _e681 = phi_778_;
                let _e683 = phi_186_;
                continue;
                continuing {
                    let _e684 = local_24;
                    phi_749_ = _e681;
                    phi_185_ = _e683;
                    phi_777_ = _e681;
                    break if !(_e684);
                }
            }
            let _e687 = phi_777_;
            if _e687 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn splat_tile_count(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
