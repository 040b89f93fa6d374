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
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_16 {
    member: type_15,
    member_1: type_5,
    member_2: f32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
}

struct type_17 {
    member: type_16,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
var<immediate> global_3: type_17;
@group(0) @binding(0) 
var<storage> global_4: type_7;
@group(0) @binding(1) 
var<storage> global_5: type_7;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_7;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_7;
var<private> global_8: u32 = 2143289344u;
var<private> global_9: u32 = 4286578688u;
var<private> global_10: u32 = 2139095040u;

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
    var local_10: bool;
    var local_11: f32;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: bool;
    var local_17: f32;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: bool;
    var local_22: f32;
    var local_23: f32;
    var local_24: f32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: u32;
    var local_31: f32;
    var local_32: u32;
    var local_33: bool;
    var local_34: f32;
    var local_35: bool;
    var local_36: f32;
    var local_37: f32;
    var local_38: f32;
    var local_39: u32;
    var local_40: bool;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: bool;
    var local_45: f32;
    var local_46: u32;
    var local_47: u32;
    var local_48: u32;
    var local_49: bool;
    var local_50: f32;
    var local_51: f32;
    var local_52: f32;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: u32;
    var local_57: u32;
    var local_58: u32;
    var local_59: f32;
    var local_60: u32;
    var local_61: bool;
    var local_62: bool;
    var local_63: f32;
    var local_64: bool;
    var local_65: f32;
    var local_66: f32;
    var local_67: f32;
    var local_68: bool;
    var local_69: bool;
    var local_70: f32;
    var local_71: bool;
    var local_72: u32;
    var local_73: u32;
    var local_74: f32;
    var local_75: u32;
    var local_76: u32;
    var local_77: f32;
    var local_78: f32;
    var local_79: f32;
    var local_80: f32;
    var local_81: f32;
    var local_82: u32;
    var local_83: f32;
    var local_84: f32;
    var local_85: f32;
    var local_86: f32;
    var local_87: f32;
    var local_88: u32;
    var local_89: f32;
    var local_90: f32;
    var phi_125_: u32;
    var phi_246_: f32;
    var phi_261_: f32;
    var phi_262_: f32;
    var phi_263_: f32;
    var phi_264_: f32;
    var phi_265_: bool;
    var phi_287_: f32;
    var phi_302_: f32;
    var phi_303_: f32;
    var phi_304_: f32;
    var phi_305_: f32;
    var phi_306_: bool;
    var phi_328_: f32;
    var phi_343_: f32;
    var phi_344_: f32;
    var phi_345_: f32;
    var phi_346_: f32;
    var phi_347_: bool;
    var phi_369_: f32;
    var phi_384_: f32;
    var phi_385_: f32;
    var phi_386_: f32;
    var phi_387_: f32;
    var phi_388_: bool;
    var phi_431_: f32;
    var phi_432_: f32;
    var phi_433_: f32;
    var phi_434_: f32;
    var phi_435_: bool;
    var phi_474_: f32;
    var phi_475_: f32;
    var phi_476_: f32;
    var phi_477_: f32;
    var phi_478_: bool;
    var phi_516_: f32;
    var phi_517_: f32;
    var phi_518_: f32;
    var phi_519_: f32;
    var phi_520_: bool;
    var phi_536_: array<f32, 4>;
    var phi_537_: array<f32, 4>;
    var phi_538_: array<f32, 4>;
    var phi_539_: array<f32, 4>;
    var phi_584_: f32;
    var phi_585_: f32;
    var phi_605_: f32;
    var phi_606_: f32;
    var phi_607_: f32;
    var phi_608_: f32;
    var phi_614_: f32;
    var phi_615_: f32;
    var phi_617_: f32;
    var phi_618_: bool;
    var phi_623_: f32;
    var phi_625_: bool;
    var phi_644_: bool;
    var phi_645_: bool;
    var phi_718_: f32;
    var phi_733_: f32;
    var phi_734_: f32;
    var phi_735_: f32;
    var phi_736_: f32;
    var phi_737_: bool;
    var phi_759_: f32;
    var phi_774_: f32;
    var phi_775_: f32;
    var phi_776_: f32;
    var phi_777_: f32;
    var phi_778_: bool;
    var phi_800_: f32;
    var phi_815_: f32;
    var phi_816_: f32;
    var phi_817_: f32;
    var phi_818_: f32;
    var phi_819_: bool;
    var phi_841_: f32;
    var phi_856_: f32;
    var phi_857_: f32;
    var phi_858_: f32;
    var phi_859_: f32;
    var phi_860_: bool;
    var phi_903_: f32;
    var phi_904_: f32;
    var phi_905_: f32;
    var phi_906_: f32;
    var phi_907_: bool;
    var phi_946_: f32;
    var phi_947_: f32;
    var phi_948_: f32;
    var phi_949_: f32;
    var phi_950_: bool;
    var phi_988_: f32;
    var phi_989_: f32;
    var phi_990_: f32;
    var phi_991_: f32;
    var phi_992_: bool;
    var phi_1008_: array<f32, 4>;
    var phi_1009_: array<f32, 4>;
    var phi_1010_: array<f32, 4>;
    var phi_1011_: array<f32, 4>;
    var phi_1056_: f32;
    var phi_1057_: f32;
    var phi_1077_: f32;
    var phi_1078_: f32;
    var phi_1079_: f32;
    var phi_1080_: f32;
    var phi_1086_: f32;
    var phi_1087_: f32;
    var phi_1089_: f32;
    var phi_1090_: bool;
    var phi_1095_: f32;
    var phi_1145_: f32;
    var phi_1165_: f32;
    var phi_1166_: f32;
    var phi_1167_: f32;
    var phi_1169_: f32;
    var phi_1170_: bool;
    var phi_1175_: f32;
    var phi_1176_: f32;
    var phi_1203_: u32;
    var phi_1204_: u32;
    var phi_1226_: f32;
    var phi_1232_: f32;
    var phi_1238_: f32;
    var phi_1255_: f32;
    var phi_1256_: f32;
    var phi_1257_: f32;
    var phi_1259_: f32;
    var phi_1260_: bool;
    var phi_1261_: f32;
    var phi_1262_: bool;
    var phi_1267_: f32;
    var phi_1268_: f32;
    var phi_126_: u32;
    var phi_1321_: bool;

    let _e147 = global_8;
    local_89 = bitcast<f32>(_e147);
    let _e149 = global_9;
    let _e151 = global_10;
    let _e152 = bitcast<f32>(_e151);
    local_90 = _e152;
    switch bitcast<i32>(0u) {
        default: {
            let _e154 = global;
            local = _e154;
            let _e155 = global_1;
            let _e156 = global_2;
            local_1 = arrayLength((&global_4.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e170 = global_3.member.member.member;
            let _e174 = global_3.member.member.member_1;
            local_5 = (_e170 * _e174);
            local_6 = (_e156.x * 256u);
            phi_125_ = (_e155.x * 256u);
            loop {
                let _e179 = phi_125_;
                local_7 = _e179;
                let _e180 = local_7;
                let _e181 = local_5;
                let _e182 = (_e180 < _e181);
                local_8 = _e182;
                if _e182 {
                    let _e183 = local_7;
                    let _e184 = local;
                    let _e185 = (_e183 + _e184);
                    local_9 = _e185;
                    let _e186 = local_5;
                    if (_e185 < _e186) {
                        let _e190 = global_3.member.member_3;
                        if (_e190 == 0u) {
                            phi_1268_ = bitcast<f32>(_e149);
                        } else {
                            let _e194 = global_3.member.member_4;
                            if (_e194 == 0u) {
                                phi_645_ = true;
                            } else {
                                let _e196 = local_9;
                                let _e197 = local_2;
                                if (_e196 < _e197) {
                                } else {
                                    phi_1321_ = true;
                                    break;
                                }
                                let _e199 = local_9;
                                let _e202 = global_5.member[_e199];
                                if (_e202 == 0u) {
                                    let _e204 = local_9;
                                    let _e205 = local_3;
                                    let _e206 = (_e204 < _e205);
                                    local_10 = _e206;
                                    if _e206 {
                                    } else {
                                        phi_1321_ = true;
                                        break;
                                    }
                                    let _e207 = local_9;
                                    let _e210 = global_6.member[_e207];
                                    local_11 = bitcast<f32>(_e210);
                                    let _e212 = local_9;
                                    let _e213 = local_1;
                                    if (_e212 < _e213) {
                                    } else {
                                        phi_1321_ = true;
                                        break;
                                    }
                                    let _e215 = local_9;
                                    let _e218 = global_4.member[_e215];
                                    local_12 = _e218;
                                    let _e219 = local_11;
                                    if ((bitcast<u32>(_e219) & 2139095040u) != 2139095040u) {
                                        let _e226 = global_3.member.member.member_7;
                                        let _e228 = select(3u, 4u, (_e226 == 1u));
                                        local_76 = _e228;
                                        if (_e228 == 0u) {
                                            let _e230 = local_12;
                                            let _e231 = bitcast<f32>(_e230);
                                            phi_539_ = array<f32, 4>(_e231, _e231, _e231, _e231);
                                        } else {
                                            let _e233 = local_76;
                                            if (_e233 == 1u) {
                                                let _e235 = local_12;
                                                let _e236 = (_e235 & 65535u);
                                                local_13 = ((_e236 & 32768u) << bitcast<u32>(16i));
                                                let _e242 = ((_e236 >> bitcast<u32>(10i)) & 31u);
                                                local_14 = _e242;
                                                local_15 = (_e236 & 1023u);
                                                let _e244 = (_e242 == 0u);
                                                local_16 = _e244;
                                                if _e244 {
                                                    let _e245 = local_15;
                                                    let _e246 = f32(_e245);
                                                    local_17 = _e246;
                                                    let _e248 = local_13;
                                                    if (_e248 == 0u) {
                                                        phi_246_ = (_e246 * 0.000000059604645f);
                                                    } else {
                                                        let _e250 = local_17;
                                                        phi_246_ = (_e250 * -0.000000059604645f);
                                                    }
                                                    let _e253 = phi_246_;
                                                    phi_263_ = _e253;
                                                    phi_264_ = f32();
                                                    phi_265_ = true;
                                                } else {
                                                    let _e254 = local_14;
                                                    let _e255 = (_e254 == 31u);
                                                    if _e255 {
                                                        let _e256 = local_13;
                                                        let _e258 = local_15;
                                                        phi_261_ = bitcast<f32>(((_e256 | 2139095040u) | (_e258 << bitcast<u32>(13i))));
                                                        phi_262_ = f32();
                                                    } else {
                                                        let _e263 = local_14;
                                                        let _e267 = local_13;
                                                        let _e269 = local_15;
                                                        phi_261_ = f32();
                                                        phi_262_ = bitcast<f32>(((_e267 | ((_e263 + 112u) << bitcast<u32>(23i))) | (_e269 << bitcast<u32>(13i))));
                                                    }
                                                    let _e275 = phi_261_;
                                                    let _e277 = phi_262_;
                                                    phi_263_ = _e275;
                                                    phi_264_ = _e277;
                                                    phi_265_ = _e255;
                                                }
                                                let _e279 = phi_263_;
                                                let _e281 = phi_264_;
                                                let _e283 = phi_265_;
                                                local_77 = select(_e281, _e279, _e283);
                                                let _e285 = local_12;
                                                let _e287 = (_e285 >> bitcast<u32>(16i));
                                                local_18 = ((_e287 & 32768u) << bitcast<u32>(16i));
                                                let _e293 = ((_e287 >> bitcast<u32>(10i)) & 31u);
                                                local_19 = _e293;
                                                local_20 = (_e287 & 1023u);
                                                let _e295 = (_e293 == 0u);
                                                local_21 = _e295;
                                                if _e295 {
                                                    let _e296 = local_20;
                                                    let _e297 = f32(_e296);
                                                    local_22 = _e297;
                                                    let _e299 = local_18;
                                                    if (_e299 == 0u) {
                                                        phi_287_ = (_e297 * 0.000000059604645f);
                                                    } else {
                                                        let _e301 = local_22;
                                                        phi_287_ = (_e301 * -0.000000059604645f);
                                                    }
                                                    let _e304 = phi_287_;
                                                    phi_304_ = _e304;
                                                    phi_305_ = f32();
                                                    phi_306_ = true;
                                                } else {
                                                    let _e305 = local_19;
                                                    let _e306 = (_e305 == 31u);
                                                    if _e306 {
                                                        let _e307 = local_18;
                                                        let _e309 = local_20;
                                                        phi_302_ = bitcast<f32>(((_e307 | 2139095040u) | (_e309 << bitcast<u32>(13i))));
                                                        phi_303_ = f32();
                                                    } else {
                                                        let _e314 = local_19;
                                                        let _e318 = local_18;
                                                        let _e320 = local_20;
                                                        phi_302_ = f32();
                                                        phi_303_ = bitcast<f32>(((_e318 | ((_e314 + 112u) << bitcast<u32>(23i))) | (_e320 << bitcast<u32>(13i))));
                                                    }
                                                    let _e326 = phi_302_;
                                                    let _e328 = phi_303_;
                                                    phi_304_ = _e326;
                                                    phi_305_ = _e328;
                                                    phi_306_ = _e306;
                                                }
                                                let _e330 = phi_304_;
                                                let _e332 = phi_305_;
                                                let _e334 = phi_306_;
                                                local_78 = select(_e332, _e330, _e334);
                                                let _e336 = local_16;
                                                if _e336 {
                                                    let _e337 = local_15;
                                                    let _e338 = f32(_e337);
                                                    local_23 = _e338;
                                                    let _e340 = local_13;
                                                    if (_e340 == 0u) {
                                                        phi_328_ = (_e338 * 0.000000059604645f);
                                                    } else {
                                                        let _e342 = local_23;
                                                        phi_328_ = (_e342 * -0.000000059604645f);
                                                    }
                                                    let _e345 = phi_328_;
                                                    phi_345_ = _e345;
                                                    phi_346_ = f32();
                                                    phi_347_ = true;
                                                } else {
                                                    let _e346 = local_14;
                                                    let _e347 = (_e346 == 31u);
                                                    if _e347 {
                                                        let _e348 = local_13;
                                                        let _e350 = local_15;
                                                        phi_343_ = bitcast<f32>(((_e348 | 2139095040u) | (_e350 << bitcast<u32>(13i))));
                                                        phi_344_ = f32();
                                                    } else {
                                                        let _e355 = local_14;
                                                        let _e359 = local_13;
                                                        let _e361 = local_15;
                                                        phi_343_ = f32();
                                                        phi_344_ = bitcast<f32>(((_e359 | ((_e355 + 112u) << bitcast<u32>(23i))) | (_e361 << bitcast<u32>(13i))));
                                                    }
                                                    let _e367 = phi_343_;
                                                    let _e369 = phi_344_;
                                                    phi_345_ = _e367;
                                                    phi_346_ = _e369;
                                                    phi_347_ = _e347;
                                                }
                                                let _e371 = phi_345_;
                                                let _e373 = phi_346_;
                                                let _e375 = phi_347_;
                                                local_79 = select(_e373, _e371, _e375);
                                                let _e377 = local_21;
                                                if _e377 {
                                                    let _e378 = local_20;
                                                    let _e379 = f32(_e378);
                                                    local_24 = _e379;
                                                    let _e381 = local_18;
                                                    if (_e381 == 0u) {
                                                        phi_369_ = (_e379 * 0.000000059604645f);
                                                    } else {
                                                        let _e383 = local_24;
                                                        phi_369_ = (_e383 * -0.000000059604645f);
                                                    }
                                                    let _e386 = phi_369_;
                                                    phi_386_ = _e386;
                                                    phi_387_ = f32();
                                                    phi_388_ = true;
                                                } else {
                                                    let _e387 = local_19;
                                                    let _e388 = (_e387 == 31u);
                                                    if _e388 {
                                                        let _e389 = local_18;
                                                        let _e391 = local_20;
                                                        phi_384_ = bitcast<f32>(((_e389 | 2139095040u) | (_e391 << bitcast<u32>(13i))));
                                                        phi_385_ = f32();
                                                    } else {
                                                        let _e396 = local_19;
                                                        let _e400 = local_18;
                                                        let _e402 = local_20;
                                                        phi_384_ = f32();
                                                        phi_385_ = bitcast<f32>(((_e400 | ((_e396 + 112u) << bitcast<u32>(23i))) | (_e402 << bitcast<u32>(13i))));
                                                    }
                                                    let _e408 = phi_384_;
                                                    let _e410 = phi_385_;
                                                    phi_386_ = _e408;
                                                    phi_387_ = _e410;
                                                    phi_388_ = _e388;
                                                }
                                                let _e412 = phi_386_;
                                                let _e414 = phi_387_;
                                                let _e416 = phi_388_;
                                                let _e418 = local_77;
                                                let _e419 = local_78;
                                                let _e420 = local_79;
                                                phi_538_ = array<f32, 4>(_e418, _e419, _e420, select(_e414, _e412, _e416));
                                            } else {
                                                let _e422 = local_76;
                                                if (_e422 == 2u) {
                                                    let _e424 = local_12;
                                                    let _e425 = (_e424 & 2047u);
                                                    let _e428 = ((_e425 >> bitcast<u32>(6u)) & 31u);
                                                    local_25 = _e428;
                                                    local_26 = (_e425 & 63u);
                                                    if (_e428 == 0u) {
                                                        let _e431 = local_26;
                                                        phi_433_ = (f32(_e431) * 0.0000009536743f);
                                                        phi_434_ = f32();
                                                        phi_435_ = true;
                                                    } else {
                                                        let _e434 = local_25;
                                                        let _e435 = (_e434 == 31u);
                                                        if _e435 {
                                                            let _e436 = local_26;
                                                            phi_431_ = bitcast<f32>((2139095040u | (_e436 << bitcast<u32>(17u))));
                                                            phi_432_ = f32();
                                                        } else {
                                                            let _e441 = local_25;
                                                            let _e445 = local_26;
                                                            phi_431_ = f32();
                                                            phi_432_ = bitcast<f32>((((_e441 + 112u) << bitcast<u32>(23i)) | (_e445 << bitcast<u32>(17u))));
                                                        }
                                                        let _e451 = phi_431_;
                                                        let _e453 = phi_432_;
                                                        phi_433_ = _e451;
                                                        phi_434_ = _e453;
                                                        phi_435_ = _e435;
                                                    }
                                                    let _e455 = phi_433_;
                                                    let _e457 = phi_434_;
                                                    let _e459 = phi_435_;
                                                    local_80 = select(_e457, _e455, _e459);
                                                    let _e461 = local_12;
                                                    let _e464 = ((_e461 >> bitcast<u32>(11i)) & 2047u);
                                                    let _e467 = ((_e464 >> bitcast<u32>(6u)) & 31u);
                                                    local_27 = _e467;
                                                    local_28 = (_e464 & 63u);
                                                    if (_e467 == 0u) {
                                                        let _e470 = local_28;
                                                        phi_476_ = (f32(_e470) * 0.0000009536743f);
                                                        phi_477_ = f32();
                                                        phi_478_ = true;
                                                    } else {
                                                        let _e473 = local_27;
                                                        let _e474 = (_e473 == 31u);
                                                        if _e474 {
                                                            let _e475 = local_28;
                                                            phi_474_ = bitcast<f32>((2139095040u | (_e475 << bitcast<u32>(17u))));
                                                            phi_475_ = f32();
                                                        } else {
                                                            let _e480 = local_27;
                                                            let _e484 = local_28;
                                                            phi_474_ = f32();
                                                            phi_475_ = bitcast<f32>((((_e480 + 112u) << bitcast<u32>(23i)) | (_e484 << bitcast<u32>(17u))));
                                                        }
                                                        let _e490 = phi_474_;
                                                        let _e492 = phi_475_;
                                                        phi_476_ = _e490;
                                                        phi_477_ = _e492;
                                                        phi_478_ = _e474;
                                                    }
                                                    let _e494 = phi_476_;
                                                    let _e496 = phi_477_;
                                                    let _e498 = phi_478_;
                                                    local_81 = select(_e496, _e494, _e498);
                                                    let _e500 = local_12;
                                                    let _e502 = (_e500 >> bitcast<u32>(22i));
                                                    let _e505 = ((_e502 >> bitcast<u32>(5u)) & 31u);
                                                    local_29 = _e505;
                                                    local_30 = (_e502 & 31u);
                                                    if (_e505 == 0u) {
                                                        let _e508 = local_30;
                                                        phi_518_ = (f32(_e508) * 0.0000019073486f);
                                                        phi_519_ = f32();
                                                        phi_520_ = true;
                                                    } else {
                                                        let _e511 = local_29;
                                                        let _e512 = (_e511 == 31u);
                                                        if _e512 {
                                                            let _e513 = local_30;
                                                            phi_516_ = bitcast<f32>((2139095040u | (_e513 << bitcast<u32>(18u))));
                                                            phi_517_ = f32();
                                                        } else {
                                                            let _e518 = local_29;
                                                            let _e522 = local_30;
                                                            phi_516_ = f32();
                                                            phi_517_ = bitcast<f32>((((_e518 + 112u) << bitcast<u32>(23i)) | (_e522 << bitcast<u32>(18u))));
                                                        }
                                                        let _e528 = phi_516_;
                                                        let _e530 = phi_517_;
                                                        phi_518_ = _e528;
                                                        phi_519_ = _e530;
                                                        phi_520_ = _e512;
                                                    }
                                                    let _e532 = phi_518_;
                                                    let _e534 = phi_519_;
                                                    let _e536 = phi_520_;
                                                    let _e538 = local_80;
                                                    let _e539 = local_81;
                                                    phi_537_ = array<f32, 4>(_e538, _e539, select(_e534, _e532, _e536), 1f);
                                                } else {
                                                    let _e541 = local_76;
                                                    if (_e541 == 4u) {
                                                        let _e543 = local_12;
                                                        phi_536_ = array<f32, 4>((f32((_e543 & 16777215u)) * 0.00000005960465f), 0f, 0f, 1f);
                                                    } else {
                                                        let _e548 = local_12;
                                                        phi_536_ = array<f32, 4>(bitcast<f32>(_e548), 0f, 0f, 1f);
                                                    }
                                                    let _e552 = phi_536_;
                                                    phi_537_ = _e552;
                                                }
                                                let _e554 = phi_537_;
                                                phi_538_ = _e554;
                                            }
                                            let _e556 = phi_538_;
                                            phi_539_ = _e556;
                                        }
                                        let _e558 = phi_539_;
                                        local_31 = _e558[0];
                                        let _e563 = global_3.member.member.member_3;
                                        local_32 = _e563;
                                        if (_e563 == 0u) {
                                            phi_623_ = _e558[0];
                                        } else {
                                            let _e565 = local_31;
                                            if (_e565 >= 0f) {
                                                let _e567 = local_31;
                                                let _e568 = (_e567 <= 1f);
                                                local_33 = _e568;
                                                if _e568 {
                                                    let _e572 = global_3.member.member.member_5;
                                                    local_34 = _e572;
                                                    let _e573 = local_90;
                                                    local_35 = (_e572 == _e573);
                                                    let _e575 = local_32;
                                                    if (_e575 == 1u) {
                                                        let _e577 = local_35;
                                                        if _e577 {
                                                            let _e581 = global_3.member.member.member_4;
                                                            let _e582 = local_31;
                                                            phi_584_ = (1f - _e582);
                                                            phi_585_ = _e581;
                                                        } else {
                                                            let _e587 = global_3.member.member.member_4;
                                                            let _e588 = local_34;
                                                            let _e590 = local_34;
                                                            let _e592 = local_31;
                                                            let _e594 = local_34;
                                                            phi_584_ = (_e594 - (_e592 * (_e590 - _e587)));
                                                            phi_585_ = (_e587 * _e588);
                                                        }
                                                        let _e597 = phi_584_;
                                                        let _e599 = phi_585_;
                                                        phi_607_ = _e597;
                                                        phi_608_ = _e599;
                                                    } else {
                                                        let _e600 = local_35;
                                                        if _e600 {
                                                            let _e604 = global_3.member.member.member_4;
                                                            phi_605_ = _e558[0];
                                                            phi_606_ = _e604;
                                                        } else {
                                                            let _e608 = global_3.member.member.member_4;
                                                            let _e609 = local_34;
                                                            let _e611 = local_34;
                                                            let _e613 = local_31;
                                                            phi_605_ = (_e608 + (_e613 * (_e611 - _e608)));
                                                            phi_606_ = (_e608 * _e609);
                                                        }
                                                        let _e617 = phi_605_;
                                                        let _e619 = phi_606_;
                                                        phi_607_ = _e617;
                                                        phi_608_ = _e619;
                                                    }
                                                    let _e621 = phi_607_;
                                                    let _e623 = phi_608_;
                                                    local_36 = _e621;
                                                    local_37 = _e623;
                                                    if (_e621 <= 0f) {
                                                        phi_614_ = _e152;
                                                    } else {
                                                        let _e625 = local_37;
                                                        let _e626 = local_36;
                                                        phi_614_ = (_e625 / _e626);
                                                    }
                                                    let _e629 = phi_614_;
                                                    phi_615_ = _e629;
                                                } else {
                                                    phi_615_ = f32();
                                                }
                                                let _e631 = phi_615_;
                                                let _e632 = local_33;
                                                phi_617_ = _e631;
                                                phi_618_ = select(true, false, _e632);
                                            } else {
                                                phi_617_ = f32();
                                                phi_618_ = true;
                                            }
                                            let _e635 = phi_617_;
                                            let _e637 = phi_618_;
                                            let _e638 = local_89;
                                            phi_623_ = select(_e635, _e638, _e637);
                                        }
                                        let _e641 = phi_623_;
                                        let _e642 = local_11;
                                        phi_625_ = (_e642 == _e641);
                                    } else {
                                        phi_625_ = false;
                                    }
                                    let _e645 = phi_625_;
                                    if _e645 {
                                    } else {
                                        let _e646 = local_10;
                                        if _e646 {
                                        } else {
                                            phi_1321_ = true;
                                            break;
                                        }
                                        global_6.member[_e207] = 2139095040u;
                                    }
                                    phi_644_ = _e645;
                                } else {
                                    phi_644_ = true;
                                }
                                let _e648 = phi_644_;
                                phi_645_ = _e648;
                            }
                            let _e650 = phi_645_;
                            if _e650 {
                                let _e651 = local_9;
                                let _e652 = local_3;
                                if (_e651 < _e652) {
                                } else {
                                    phi_1321_ = true;
                                    break;
                                }
                                let _e654 = local_9;
                                let _e657 = global_6.member[_e654];
                                let _e658 = bitcast<f32>(_e657);
                                local_38 = _e658;
                                let _e659 = local_9;
                                let _e660 = local_1;
                                if (_e659 < _e660) {
                                } else {
                                    phi_1321_ = true;
                                    break;
                                }
                                let _e662 = local_9;
                                let _e665 = global_4.member[_e662];
                                local_39 = _e665;
                                let _e669 = global_3.member.member.member_7;
                                let _e670 = (_e669 == 1u);
                                local_40 = _e670;
                                let _e671 = select(3u, 4u, _e670);
                                local_82 = _e671;
                                if (_e671 == 0u) {
                                    let _e673 = local_39;
                                    let _e674 = bitcast<f32>(_e673);
                                    phi_1011_ = array<f32, 4>(_e674, _e674, _e674, _e674);
                                } else {
                                    let _e676 = local_82;
                                    if (_e676 == 1u) {
                                        let _e678 = local_39;
                                        let _e679 = (_e678 & 65535u);
                                        local_41 = ((_e679 & 32768u) << bitcast<u32>(16i));
                                        let _e685 = ((_e679 >> bitcast<u32>(10i)) & 31u);
                                        local_42 = _e685;
                                        local_43 = (_e679 & 1023u);
                                        let _e687 = (_e685 == 0u);
                                        local_44 = _e687;
                                        if _e687 {
                                            let _e688 = local_43;
                                            let _e689 = f32(_e688);
                                            local_45 = _e689;
                                            let _e691 = local_41;
                                            if (_e691 == 0u) {
                                                phi_718_ = (_e689 * 0.000000059604645f);
                                            } else {
                                                let _e693 = local_45;
                                                phi_718_ = (_e693 * -0.000000059604645f);
                                            }
                                            let _e696 = phi_718_;
                                            phi_735_ = _e696;
                                            phi_736_ = f32();
                                            phi_737_ = true;
                                        } else {
                                            let _e697 = local_42;
                                            let _e698 = (_e697 == 31u);
                                            if _e698 {
                                                let _e699 = local_41;
                                                let _e701 = local_43;
                                                phi_733_ = bitcast<f32>(((_e699 | 2139095040u) | (_e701 << bitcast<u32>(13i))));
                                                phi_734_ = f32();
                                            } else {
                                                let _e706 = local_42;
                                                let _e710 = local_41;
                                                let _e712 = local_43;
                                                phi_733_ = f32();
                                                phi_734_ = bitcast<f32>(((_e710 | ((_e706 + 112u) << bitcast<u32>(23i))) | (_e712 << bitcast<u32>(13i))));
                                            }
                                            let _e718 = phi_733_;
                                            let _e720 = phi_734_;
                                            phi_735_ = _e718;
                                            phi_736_ = _e720;
                                            phi_737_ = _e698;
                                        }
                                        let _e722 = phi_735_;
                                        let _e724 = phi_736_;
                                        let _e726 = phi_737_;
                                        local_83 = select(_e724, _e722, _e726);
                                        let _e728 = local_39;
                                        let _e730 = (_e728 >> bitcast<u32>(16i));
                                        local_46 = ((_e730 & 32768u) << bitcast<u32>(16i));
                                        let _e736 = ((_e730 >> bitcast<u32>(10i)) & 31u);
                                        local_47 = _e736;
                                        local_48 = (_e730 & 1023u);
                                        let _e738 = (_e736 == 0u);
                                        local_49 = _e738;
                                        if _e738 {
                                            let _e739 = local_48;
                                            let _e740 = f32(_e739);
                                            local_50 = _e740;
                                            let _e742 = local_46;
                                            if (_e742 == 0u) {
                                                phi_759_ = (_e740 * 0.000000059604645f);
                                            } else {
                                                let _e744 = local_50;
                                                phi_759_ = (_e744 * -0.000000059604645f);
                                            }
                                            let _e747 = phi_759_;
                                            phi_776_ = _e747;
                                            phi_777_ = f32();
                                            phi_778_ = true;
                                        } else {
                                            let _e748 = local_47;
                                            let _e749 = (_e748 == 31u);
                                            if _e749 {
                                                let _e750 = local_46;
                                                let _e752 = local_48;
                                                phi_774_ = bitcast<f32>(((_e750 | 2139095040u) | (_e752 << bitcast<u32>(13i))));
                                                phi_775_ = f32();
                                            } else {
                                                let _e757 = local_47;
                                                let _e761 = local_46;
                                                let _e763 = local_48;
                                                phi_774_ = f32();
                                                phi_775_ = bitcast<f32>(((_e761 | ((_e757 + 112u) << bitcast<u32>(23i))) | (_e763 << bitcast<u32>(13i))));
                                            }
                                            let _e769 = phi_774_;
                                            let _e771 = phi_775_;
                                            phi_776_ = _e769;
                                            phi_777_ = _e771;
                                            phi_778_ = _e749;
                                        }
                                        let _e773 = phi_776_;
                                        let _e775 = phi_777_;
                                        let _e777 = phi_778_;
                                        local_84 = select(_e775, _e773, _e777);
                                        let _e779 = local_44;
                                        if _e779 {
                                            let _e780 = local_43;
                                            let _e781 = f32(_e780);
                                            local_51 = _e781;
                                            let _e783 = local_41;
                                            if (_e783 == 0u) {
                                                phi_800_ = (_e781 * 0.000000059604645f);
                                            } else {
                                                let _e785 = local_51;
                                                phi_800_ = (_e785 * -0.000000059604645f);
                                            }
                                            let _e788 = phi_800_;
                                            phi_817_ = _e788;
                                            phi_818_ = f32();
                                            phi_819_ = true;
                                        } else {
                                            let _e789 = local_42;
                                            let _e790 = (_e789 == 31u);
                                            if _e790 {
                                                let _e791 = local_41;
                                                let _e793 = local_43;
                                                phi_815_ = bitcast<f32>(((_e791 | 2139095040u) | (_e793 << bitcast<u32>(13i))));
                                                phi_816_ = f32();
                                            } else {
                                                let _e798 = local_42;
                                                let _e802 = local_41;
                                                let _e804 = local_43;
                                                phi_815_ = f32();
                                                phi_816_ = bitcast<f32>(((_e802 | ((_e798 + 112u) << bitcast<u32>(23i))) | (_e804 << bitcast<u32>(13i))));
                                            }
                                            let _e810 = phi_815_;
                                            let _e812 = phi_816_;
                                            phi_817_ = _e810;
                                            phi_818_ = _e812;
                                            phi_819_ = _e790;
                                        }
                                        let _e814 = phi_817_;
                                        let _e816 = phi_818_;
                                        let _e818 = phi_819_;
                                        local_85 = select(_e816, _e814, _e818);
                                        let _e820 = local_49;
                                        if _e820 {
                                            let _e821 = local_48;
                                            let _e822 = f32(_e821);
                                            local_52 = _e822;
                                            let _e824 = local_46;
                                            if (_e824 == 0u) {
                                                phi_841_ = (_e822 * 0.000000059604645f);
                                            } else {
                                                let _e826 = local_52;
                                                phi_841_ = (_e826 * -0.000000059604645f);
                                            }
                                            let _e829 = phi_841_;
                                            phi_858_ = _e829;
                                            phi_859_ = f32();
                                            phi_860_ = true;
                                        } else {
                                            let _e830 = local_47;
                                            let _e831 = (_e830 == 31u);
                                            if _e831 {
                                                let _e832 = local_46;
                                                let _e834 = local_48;
                                                phi_856_ = bitcast<f32>(((_e832 | 2139095040u) | (_e834 << bitcast<u32>(13i))));
                                                phi_857_ = f32();
                                            } else {
                                                let _e839 = local_47;
                                                let _e843 = local_46;
                                                let _e845 = local_48;
                                                phi_856_ = f32();
                                                phi_857_ = bitcast<f32>(((_e843 | ((_e839 + 112u) << bitcast<u32>(23i))) | (_e845 << bitcast<u32>(13i))));
                                            }
                                            let _e851 = phi_856_;
                                            let _e853 = phi_857_;
                                            phi_858_ = _e851;
                                            phi_859_ = _e853;
                                            phi_860_ = _e831;
                                        }
                                        let _e855 = phi_858_;
                                        let _e857 = phi_859_;
                                        let _e859 = phi_860_;
                                        let _e861 = local_83;
                                        let _e862 = local_84;
                                        let _e863 = local_85;
                                        phi_1010_ = array<f32, 4>(_e861, _e862, _e863, select(_e857, _e855, _e859));
                                    } else {
                                        let _e865 = local_82;
                                        if (_e865 == 2u) {
                                            let _e867 = local_39;
                                            let _e868 = (_e867 & 2047u);
                                            let _e871 = ((_e868 >> bitcast<u32>(6u)) & 31u);
                                            local_53 = _e871;
                                            local_54 = (_e868 & 63u);
                                            if (_e871 == 0u) {
                                                let _e874 = local_54;
                                                phi_905_ = (f32(_e874) * 0.0000009536743f);
                                                phi_906_ = f32();
                                                phi_907_ = true;
                                            } else {
                                                let _e877 = local_53;
                                                let _e878 = (_e877 == 31u);
                                                if _e878 {
                                                    let _e879 = local_54;
                                                    phi_903_ = bitcast<f32>((2139095040u | (_e879 << bitcast<u32>(17u))));
                                                    phi_904_ = f32();
                                                } else {
                                                    let _e884 = local_53;
                                                    let _e888 = local_54;
                                                    phi_903_ = f32();
                                                    phi_904_ = bitcast<f32>((((_e884 + 112u) << bitcast<u32>(23i)) | (_e888 << bitcast<u32>(17u))));
                                                }
                                                let _e894 = phi_903_;
                                                let _e896 = phi_904_;
                                                phi_905_ = _e894;
                                                phi_906_ = _e896;
                                                phi_907_ = _e878;
                                            }
                                            let _e898 = phi_905_;
                                            let _e900 = phi_906_;
                                            let _e902 = phi_907_;
                                            local_86 = select(_e900, _e898, _e902);
                                            let _e904 = local_39;
                                            let _e907 = ((_e904 >> bitcast<u32>(11i)) & 2047u);
                                            let _e910 = ((_e907 >> bitcast<u32>(6u)) & 31u);
                                            local_55 = _e910;
                                            local_56 = (_e907 & 63u);
                                            if (_e910 == 0u) {
                                                let _e913 = local_56;
                                                phi_948_ = (f32(_e913) * 0.0000009536743f);
                                                phi_949_ = f32();
                                                phi_950_ = true;
                                            } else {
                                                let _e916 = local_55;
                                                let _e917 = (_e916 == 31u);
                                                if _e917 {
                                                    let _e918 = local_56;
                                                    phi_946_ = bitcast<f32>((2139095040u | (_e918 << bitcast<u32>(17u))));
                                                    phi_947_ = f32();
                                                } else {
                                                    let _e923 = local_55;
                                                    let _e927 = local_56;
                                                    phi_946_ = f32();
                                                    phi_947_ = bitcast<f32>((((_e923 + 112u) << bitcast<u32>(23i)) | (_e927 << bitcast<u32>(17u))));
                                                }
                                                let _e933 = phi_946_;
                                                let _e935 = phi_947_;
                                                phi_948_ = _e933;
                                                phi_949_ = _e935;
                                                phi_950_ = _e917;
                                            }
                                            let _e937 = phi_948_;
                                            let _e939 = phi_949_;
                                            let _e941 = phi_950_;
                                            local_87 = select(_e939, _e937, _e941);
                                            let _e943 = local_39;
                                            let _e945 = (_e943 >> bitcast<u32>(22i));
                                            let _e948 = ((_e945 >> bitcast<u32>(5u)) & 31u);
                                            local_57 = _e948;
                                            local_58 = (_e945 & 31u);
                                            if (_e948 == 0u) {
                                                let _e951 = local_58;
                                                phi_990_ = (f32(_e951) * 0.0000019073486f);
                                                phi_991_ = f32();
                                                phi_992_ = true;
                                            } else {
                                                let _e954 = local_57;
                                                let _e955 = (_e954 == 31u);
                                                if _e955 {
                                                    let _e956 = local_58;
                                                    phi_988_ = bitcast<f32>((2139095040u | (_e956 << bitcast<u32>(18u))));
                                                    phi_989_ = f32();
                                                } else {
                                                    let _e961 = local_57;
                                                    let _e965 = local_58;
                                                    phi_988_ = f32();
                                                    phi_989_ = bitcast<f32>((((_e961 + 112u) << bitcast<u32>(23i)) | (_e965 << bitcast<u32>(18u))));
                                                }
                                                let _e971 = phi_988_;
                                                let _e973 = phi_989_;
                                                phi_990_ = _e971;
                                                phi_991_ = _e973;
                                                phi_992_ = _e955;
                                            }
                                            let _e975 = phi_990_;
                                            let _e977 = phi_991_;
                                            let _e979 = phi_992_;
                                            let _e981 = local_86;
                                            let _e982 = local_87;
                                            phi_1009_ = array<f32, 4>(_e981, _e982, select(_e977, _e975, _e979), 1f);
                                        } else {
                                            let _e984 = local_82;
                                            if (_e984 == 4u) {
                                                let _e986 = local_39;
                                                phi_1008_ = array<f32, 4>((f32((_e986 & 16777215u)) * 0.00000005960465f), 0f, 0f, 1f);
                                            } else {
                                                let _e991 = local_39;
                                                phi_1008_ = array<f32, 4>(bitcast<f32>(_e991), 0f, 0f, 1f);
                                            }
                                            let _e995 = phi_1008_;
                                            phi_1009_ = _e995;
                                        }
                                        let _e997 = phi_1009_;
                                        phi_1010_ = _e997;
                                    }
                                    let _e999 = phi_1010_;
                                    phi_1011_ = _e999;
                                }
                                let _e1001 = phi_1011_;
                                local_59 = _e1001[0];
                                let _e1006 = global_3.member.member.member_3;
                                local_60 = _e1006;
                                let _e1007 = (_e1006 == 0u);
                                local_61 = _e1007;
                                if _e1007 {
                                    phi_1095_ = _e1001[0];
                                } else {
                                    let _e1008 = local_59;
                                    if (_e1008 >= 0f) {
                                        let _e1010 = local_59;
                                        let _e1011 = (_e1010 <= 1f);
                                        local_62 = _e1011;
                                        if _e1011 {
                                            let _e1015 = global_3.member.member.member_5;
                                            local_63 = _e1015;
                                            let _e1016 = local_90;
                                            local_64 = (_e1015 == _e1016);
                                            let _e1018 = local_60;
                                            if (_e1018 == 1u) {
                                                let _e1020 = local_64;
                                                if _e1020 {
                                                    let _e1024 = global_3.member.member.member_4;
                                                    let _e1025 = local_59;
                                                    phi_1056_ = (1f - _e1025);
                                                    phi_1057_ = _e1024;
                                                } else {
                                                    let _e1030 = global_3.member.member.member_4;
                                                    let _e1031 = local_63;
                                                    let _e1033 = local_63;
                                                    let _e1035 = local_59;
                                                    let _e1037 = local_63;
                                                    phi_1056_ = (_e1037 - (_e1035 * (_e1033 - _e1030)));
                                                    phi_1057_ = (_e1030 * _e1031);
                                                }
                                                let _e1040 = phi_1056_;
                                                let _e1042 = phi_1057_;
                                                phi_1079_ = _e1040;
                                                phi_1080_ = _e1042;
                                            } else {
                                                let _e1043 = local_64;
                                                if _e1043 {
                                                    let _e1047 = global_3.member.member.member_4;
                                                    phi_1077_ = _e1001[0];
                                                    phi_1078_ = _e1047;
                                                } else {
                                                    let _e1051 = global_3.member.member.member_4;
                                                    let _e1052 = local_63;
                                                    let _e1054 = local_63;
                                                    let _e1056 = local_59;
                                                    phi_1077_ = (_e1051 + (_e1056 * (_e1054 - _e1051)));
                                                    phi_1078_ = (_e1051 * _e1052);
                                                }
                                                let _e1060 = phi_1077_;
                                                let _e1062 = phi_1078_;
                                                phi_1079_ = _e1060;
                                                phi_1080_ = _e1062;
                                            }
                                            let _e1064 = phi_1079_;
                                            let _e1066 = phi_1080_;
                                            local_65 = _e1064;
                                            local_66 = _e1066;
                                            if (_e1064 <= 0f) {
                                                phi_1086_ = _e152;
                                            } else {
                                                let _e1068 = local_66;
                                                let _e1069 = local_65;
                                                phi_1086_ = (_e1068 / _e1069);
                                            }
                                            let _e1072 = phi_1086_;
                                            phi_1087_ = _e1072;
                                        } else {
                                            phi_1087_ = f32();
                                        }
                                        let _e1074 = phi_1087_;
                                        let _e1075 = local_62;
                                        phi_1089_ = _e1074;
                                        phi_1090_ = select(true, false, _e1075);
                                    } else {
                                        phi_1089_ = f32();
                                        phi_1090_ = true;
                                    }
                                    let _e1078 = phi_1089_;
                                    let _e1080 = phi_1090_;
                                    let _e1081 = local_89;
                                    phi_1095_ = select(_e1078, _e1081, _e1080);
                                }
                                let _e1084 = phi_1095_;
                                let _e1085 = local_38;
                                if (_e1085 == _e1084) {
                                    phi_1176_ = _e1001[0];
                                } else {
                                    let _e1087 = local_61;
                                    if _e1087 {
                                        phi_1175_ = _e658;
                                    } else {
                                        let _e1088 = local_38;
                                        if (_e1088 > 0f) {
                                            let _e1093 = global_3.member.member.member_5;
                                            local_67 = _e1093;
                                            let _e1094 = local_38;
                                            let _e1095 = (_e1094 < _e1093);
                                            local_68 = _e1095;
                                            if _e1095 {
                                                let _e1096 = local_67;
                                                let _e1097 = local_90;
                                                local_69 = (_e1096 == _e1097);
                                                let _e1099 = local_60;
                                                if (_e1099 == 1u) {
                                                    let _e1101 = local_69;
                                                    if _e1101 {
                                                        let _e1105 = global_3.member.member.member_4;
                                                        let _e1106 = local_38;
                                                        phi_1145_ = (1f - (_e1105 / _e1106));
                                                    } else {
                                                        let _e1112 = global_3.member.member.member_4;
                                                        let _e1113 = local_38;
                                                        let _e1115 = local_67;
                                                        let _e1117 = local_67;
                                                        let _e1119 = local_38;
                                                        phi_1145_ = ((_e1115 * (_e1113 - _e1112)) / (_e1119 * (_e1117 - _e1112)));
                                                    }
                                                    let _e1123 = phi_1145_;
                                                    phi_1166_ = _e1123;
                                                } else {
                                                    let _e1124 = local_69;
                                                    if _e1124 {
                                                        let _e1128 = global_3.member.member.member_4;
                                                        let _e1129 = local_38;
                                                        phi_1165_ = (_e1128 / _e1129);
                                                    } else {
                                                        let _e1134 = global_3.member.member.member_4;
                                                        let _e1135 = local_67;
                                                        let _e1136 = local_38;
                                                        let _e1139 = local_67;
                                                        let _e1141 = local_38;
                                                        phi_1165_ = ((_e1134 * (_e1135 - _e1136)) / (_e1141 * (_e1139 - _e1134)));
                                                    }
                                                    let _e1145 = phi_1165_;
                                                    phi_1166_ = _e1145;
                                                }
                                                let _e1147 = phi_1166_;
                                                phi_1167_ = _e1147;
                                            } else {
                                                phi_1167_ = f32();
                                            }
                                            let _e1149 = phi_1167_;
                                            let _e1150 = local_68;
                                            phi_1169_ = _e1149;
                                            phi_1170_ = select(true, false, _e1150);
                                        } else {
                                            phi_1169_ = f32();
                                            phi_1170_ = true;
                                        }
                                        let _e1153 = phi_1169_;
                                        let _e1155 = phi_1170_;
                                        let _e1156 = local_90;
                                        phi_1175_ = select(_e1153, _e1156, _e1155);
                                    }
                                    let _e1159 = phi_1175_;
                                    phi_1176_ = _e1159;
                                }
                                let _e1161 = phi_1176_;
                                local_70 = _e1161;
                                if ((bitcast<u32>(_e1161) & 2139095040u) != 2139095040u) {
                                    let _e1165 = local_59;
                                    if (_e1165 >= 0f) {
                                        let _e1167 = local_59;
                                        let _e1168 = (_e1167 <= 1f);
                                        local_71 = _e1168;
                                        if _e1168 {
                                            let _e1169 = local_39;
                                            let _e1170 = (_e1169 & 16777215u);
                                            local_72 = _e1170;
                                            let _e1171 = local_40;
                                            if _e1171 {
                                                let _e1172 = local_70;
                                                let _e1173 = local_59;
                                                if (_e1172 == _e1173) {
                                                    phi_1203_ = _e1170;
                                                } else {
                                                    let _e1175 = local_70;
                                                    let _e1177 = ((_e1175 * 16777215f) + 0.5f);
                                                    phi_1203_ = select(select(u32(_e1177), 0u, !((_e1177 >= 0f))), 4294967295u, (_e1177 > 4294967000f));
                                                }
                                                let _e1185 = phi_1203_;
                                                phi_1204_ = _e1185;
                                            } else {
                                                phi_1204_ = 0u;
                                            }
                                            let _e1187 = phi_1204_;
                                            local_73 = _e1187;
                                            let _e1188 = local_60;
                                            if (_e1188 == 2u) {
                                                let _e1190 = local_40;
                                                if _e1190 {
                                                    let _e1191 = local_73;
                                                    let _e1192 = local_72;
                                                    let _e1194 = local_73;
                                                    let _e1195 = local_72;
                                                    let _e1196 = select(_e1195, _e1194, (_e1191 < _e1192));
                                                    local_88 = _e1196;
                                                    if (_e1196 < 2u) {
                                                        phi_1226_ = 0f;
                                                    } else {
                                                        let _e1198 = local_88;
                                                        phi_1226_ = (f32((_e1198 - 1u)) * 0.00000005960465f);
                                                    }
                                                    let _e1203 = phi_1226_;
                                                    phi_1232_ = _e1203;
                                                } else {
                                                    let _e1204 = local_70;
                                                    let _e1205 = local_59;
                                                    let _e1207 = local_70;
                                                    let _e1208 = local_59;
                                                    phi_1232_ = select(_e1208, _e1207, (_e1204 < _e1205));
                                                }
                                                let _e1211 = phi_1232_;
                                                local_74 = _e1211;
                                                if (_e1211 > 0f) {
                                                    let _e1213 = local_74;
                                                    phi_1238_ = -(_e1213);
                                                } else {
                                                    phi_1238_ = _e152;
                                                }
                                                let _e1216 = phi_1238_;
                                                phi_1256_ = _e1216;
                                            } else {
                                                let _e1217 = local_40;
                                                if _e1217 {
                                                    let _e1218 = local_73;
                                                    let _e1219 = local_72;
                                                    let _e1221 = local_73;
                                                    let _e1222 = local_72;
                                                    phi_1255_ = (f32((select(_e1222, _e1221, (_e1218 > _e1219)) + 1u)) * 0.00000005960465f);
                                                } else {
                                                    let _e1227 = local_70;
                                                    let _e1228 = local_59;
                                                    let _e1230 = local_70;
                                                    let _e1231 = local_59;
                                                    phi_1255_ = select(_e1231, _e1230, (_e1227 > _e1228));
                                                }
                                                let _e1234 = phi_1255_;
                                                phi_1256_ = _e1234;
                                            }
                                            let _e1236 = phi_1256_;
                                            phi_1257_ = _e1236;
                                        } else {
                                            phi_1257_ = f32();
                                        }
                                        let _e1238 = phi_1257_;
                                        let _e1239 = local_71;
                                        phi_1259_ = _e1238;
                                        phi_1260_ = select(true, false, _e1239);
                                    } else {
                                        phi_1259_ = f32();
                                        phi_1260_ = true;
                                    }
                                    let _e1242 = phi_1259_;
                                    let _e1244 = phi_1260_;
                                    phi_1261_ = _e1242;
                                    phi_1262_ = _e1244;
                                } else {
                                    phi_1261_ = f32();
                                    phi_1262_ = true;
                                }
                                let _e1246 = phi_1261_;
                                let _e1248 = phi_1262_;
                                let _e1249 = local_90;
                                phi_1267_ = select(_e1246, _e1249, _e1248);
                            } else {
                                phi_1267_ = _e152;
                            }
                            let _e1252 = phi_1267_;
                            phi_1268_ = _e1252;
                        }
                        let _e1254 = phi_1268_;
                        local_75 = bitcast<u32>(_e1254);
                        let _e1256 = local_9;
                        let _e1257 = local_4;
                        if (_e1256 < _e1257) {
                        } else {
                            phi_1321_ = true;
                            break;
                        }
                        let _e1259 = local_9;
                        let _e1262 = local_75;
                        global_7.member[_e1259] = _e1262;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e1263 = local_7;
                    let _e1264 = local_6;
                    phi_126_ = (_e1263 + _e1264);
                } else {
                    phi_126_ = u32();
                }
                let _e1267 = phi_126_;
                continue;
                continuing {
                    let _e1268 = local_8;
                    phi_125_ = _e1267;
                    phi_1321_ = false;
                    break if !(_e1268);
                }
            }
            let _e1271 = phi_1321_;
            if _e1271 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn peel_renderer_bound(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
