struct type_6 {
    member: array<u32>,
}

struct type_21 {
    member: array<f32, 4>,
    member_1: array<f32, 4>,
    member_2: array<f32, 4>,
    member_3: array<f32, 3>,
    member_4: f32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: array<u32, 3>,
}

struct type_22 {
    member: type_21,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_6;
@group(0) @binding(1) 
var<storage> global_4: type_6;
var<immediate> global_5: type_22;
@group(0) @binding(2) 
var<storage> global_6: type_6;
@group(0) @binding(6) 
var<storage, read_write> global_7: type_6;
@group(0) @binding(7) 
var<storage> global_8: type_6;

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
    var local_9: bool;
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
    var local_20: f32;
    var local_21: u32;
    var local_22: f32;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: u32;
    var local_28: f32;
    var local_29: u32;
    var local_30: f32;
    var local_31: u32;
    var local_32: f32;
    var local_33: u32;
    var local_34: f32;
    var local_35: u32;
    var local_36: f32;
    var local_37: f32;
    var local_38: f32;
    var local_39: f32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var local_44: u32;
    var local_45: u32;
    var local_46: u32;
    var local_47: bool;
    var local_48: bool;
    var local_49: bool;
    var local_50: f32;
    var local_51: f32;
    var local_52: u32;
    var local_53: array<f32, 2>;
    var local_54: array<f32, 2>;
    var local_55: bool;
    var local_56: f32;
    var local_57: f32;
    var local_58: f32;
    var local_59: f32;
    var local_60: f32;
    var local_61: f32;
    var local_62: f32;
    var local_63: f32;
    var local_64: f32;
    var local_65: f32;
    var local_66: f32;
    var local_67: f32;
    var local_68: bool;
    var local_69: u32;
    var local_70: u32;
    var local_71: u32;
    var local_72: bool;
    var local_73: bool;
    var local_74: u32;
    var local_75: bool;
    var local_76: u32;
    var local_77: u32;
    var local_78: f32;
    var local_79: f32;
    var local_80: f32;
    var local_81: f32;
    var local_82: u32;
    var local_83: f32;
    var local_84: f32;
    var local_85: array<array<f32, 3>, 3>;
    var local_86: array<u32, 4>;
    var phi_1119_: bool;
    var phi_174_: u32;
    var phi_466_: bool;
    var phi_467_: bool;
    var phi_614_: u32;
    var phi_632_: u32;
    var phi_660_: array<u32, 4>;
    var phi_662_: array<u32, 4>;
    var phi_663_: bool;
    var phi_664_: array<u32, 4>;
    var phi_665_: bool;
    var phi_687_: u32;
    var phi_690_: array<f32, 2>;
    var phi_692_: array<f32, 2>;
    var phi_924_: bool;
    var phi_939_: bool;
    var phi_954_: bool;
    var phi_969_: bool;
    var phi_688_: u32;
    var phi_691_: array<f32, 2>;
    var phi_693_: array<f32, 2>;
    var phi_1102_: bool;
    var phi_996_: bool;
    var phi_1023_: bool;
    var phi_1056_: bool;
    var phi_1089_: bool;
    var phi_790_: array<u32, 4>;
    var phi_792_: array<u32, 4>;
    var phi_793_: bool;
    var phi_794_: array<u32, 4>;
    var phi_795_: bool;
    var phi_796_: array<u32, 4>;
    var phi_797_: bool;
    var phi_802_: array<u32, 4>;
    var phi_1131_: bool;
    var phi_803_: array<u32, 4>;
    var phi_804_: array<u32, 4>;
    var phi_805_: bool;
    var phi_1130_: bool;
    var phi_806_: array<u32, 4>;
    var phi_807_: array<u32, 4>;
    var phi_809_: bool;
    var phi_1129_: bool;
    var phi_810_: array<u32, 4>;
    var phi_811_: array<u32, 4>;
    var phi_812_: bool;
    var phi_813_: bool;
    var phi_820_: array<u32, 4>;
    var phi_1127_: bool;
    var phi_822_: array<u32, 4>;
    var phi_823_: array<u32, 4>;
    var phi_824_: bool;
    var phi_828_: array<u32, 4>;
    var phi_1125_: bool;
    var phi_839_: u32;
    var phi_840_: u32;
    var phi_1122_: bool;
    var phi_1149_: bool;
    var phi_1148_: bool;
    var phi_175_: u32;
    var phi_1147_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e124 = global;
            local = _e124;
            let _e125 = global_1;
            let _e126 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_4.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            local_5 = _e125.x;
            local_6 = _e126.x;
            if (0u < arrayLength((&global_8.member))) {
            } else {
                break;
            }
            let _e142 = global_8.member[0u];
            let _e143 = (_e142 / 3u);
            let _e146 = global_5.member.member_7;
            local_82 = select(_e146, _e143, (_e143 < _e146));
            let _e149 = local_6;
            local_7 = (_e149 * 64u);
            let _e151 = local_5;
            phi_1119_ = false;
            phi_174_ = (_e151 * 64u);
            loop {
                let _e154 = phi_1119_;
                let _e156 = phi_174_;
                local_8 = _e156;
                let _e157 = local_8;
                let _e158 = local_82;
                let _e159 = (_e157 < _e158);
                local_9 = _e159;
                if _e159 {
                    let _e160 = local_8;
                    let _e161 = local;
                    let _e162 = (_e160 + _e161);
                    local_10 = _e162;
                    let _e163 = local_82;
                    if (_e162 < _e163) {
                        let _e165 = local_10;
                        let _e166 = (_e165 * 4u);
                        local_11 = _e166;
                        let _e167 = local_2;
                        if (_e166 < _e167) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e169 = local_11;
                        let _e172 = global_4.member[_e169];
                        local_12 = _e172;
                        let _e173 = local_11;
                        let _e174 = (_e173 + 1u);
                        local_13 = _e174;
                        let _e175 = local_2;
                        if (_e174 < _e175) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e177 = local_13;
                        let _e180 = global_4.member[_e177];
                        local_14 = _e180;
                        let _e181 = local_11;
                        let _e182 = (_e181 + 2u);
                        local_15 = _e182;
                        let _e183 = local_2;
                        if (_e182 < _e183) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e185 = local_15;
                        let _e188 = global_4.member[_e185];
                        local_16 = _e188;
                        let _e189 = local_11;
                        let _e190 = (_e189 + 3u);
                        local_17 = _e190;
                        let _e191 = local_2;
                        if (_e190 < _e191) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e193 = local_17;
                        let _e196 = global_4.member[_e193];
                        local_18 = _e196;
                        let _e197 = local_12;
                        let _e198 = (_e197 * 10u);
                        local_19 = _e198;
                        let _e199 = local_1;
                        if (_e198 < _e199) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e201 = local_19;
                        let _e204 = global_3.member[_e201];
                        local_20 = bitcast<f32>(_e204);
                        let _e206 = local_19;
                        let _e207 = (_e206 + 1u);
                        local_21 = _e207;
                        let _e208 = local_1;
                        if (_e207 < _e208) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e210 = local_21;
                        let _e213 = global_3.member[_e210];
                        local_22 = bitcast<f32>(_e213);
                        let _e215 = local_19;
                        let _e216 = (_e215 + 2u);
                        local_23 = _e216;
                        let _e217 = local_1;
                        if (_e216 < _e217) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e219 = local_23;
                        let _e222 = global_3.member[_e219];
                        local_24 = bitcast<f32>(_e222);
                        let _e224 = local_14;
                        let _e225 = (_e224 * 10u);
                        local_25 = _e225;
                        let _e226 = local_1;
                        if (_e225 < _e226) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e228 = local_25;
                        let _e231 = global_3.member[_e228];
                        local_26 = bitcast<f32>(_e231);
                        let _e233 = local_25;
                        let _e234 = (_e233 + 1u);
                        local_27 = _e234;
                        let _e235 = local_1;
                        if (_e234 < _e235) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e237 = local_27;
                        let _e240 = global_3.member[_e237];
                        local_28 = bitcast<f32>(_e240);
                        let _e242 = local_25;
                        let _e243 = (_e242 + 2u);
                        local_29 = _e243;
                        let _e244 = local_1;
                        if (_e243 < _e244) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e246 = local_29;
                        let _e249 = global_3.member[_e246];
                        local_30 = bitcast<f32>(_e249);
                        let _e251 = local_16;
                        let _e252 = (_e251 * 10u);
                        local_31 = _e252;
                        let _e253 = local_1;
                        if (_e252 < _e253) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e255 = local_31;
                        let _e258 = global_3.member[_e255];
                        local_32 = bitcast<f32>(_e258);
                        let _e260 = local_31;
                        let _e261 = (_e260 + 1u);
                        local_33 = _e261;
                        let _e262 = local_1;
                        if (_e261 < _e262) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e264 = local_33;
                        let _e267 = global_3.member[_e264];
                        local_34 = bitcast<f32>(_e267);
                        let _e269 = local_31;
                        let _e270 = (_e269 + 2u);
                        local_35 = _e270;
                        let _e271 = local_1;
                        if (_e270 < _e271) {
                        } else {
                            phi_1147_ = true;
                            break;
                        }
                        let _e273 = local_35;
                        let _e276 = global_3.member[_e273];
                        let _e277 = bitcast<f32>(_e276);
                        local_36 = _e277;
                        let _e278 = local_26;
                        let _e279 = local_20;
                        let _e280 = (_e278 - _e279);
                        let _e281 = local_28;
                        let _e282 = local_22;
                        let _e283 = (_e281 - _e282);
                        let _e284 = local_30;
                        let _e285 = local_24;
                        let _e286 = (_e284 - _e285);
                        let _e287 = local_32;
                        let _e288 = local_20;
                        let _e289 = (_e287 - _e288);
                        let _e290 = local_34;
                        let _e291 = local_22;
                        let _e292 = (_e290 - _e291);
                        let _e293 = local_24;
                        let _e294 = (_e277 - _e293);
                        let _e297 = ((_e283 * _e294) - (_e286 * _e292));
                        local_37 = _e297;
                        let _e300 = ((_e286 * _e289) - (_e280 * _e294));
                        local_38 = _e300;
                        let _e303 = ((_e280 * _e292) - (_e283 * _e289));
                        local_39 = _e303;
                        if ((((_e297 * _e297) + (_e300 * _e300)) + (_e303 * _e303)) == 0f) {
                            phi_467_ = false;
                        } else {
                            let _e310 = local_18;
                            let _e312 = ((_e310 * 16u) + 10u);
                            local_40 = _e312;
                            let _e313 = local_3;
                            if (_e312 < _e313) {
                            } else {
                                phi_1147_ = true;
                                break;
                            }
                            let _e315 = local_40;
                            let _e318 = global_6.member[_e315];
                            if ((_e318 & 2u) == 0u) {
                                let _e323 = global_5.member.member_3;
                                let _e325 = local_20;
                                let _e328 = local_22;
                                let _e331 = local_24;
                                let _e333 = local_37;
                                let _e335 = local_38;
                                let _e338 = local_39;
                                phi_466_ = ((((_e333 * (_e325 - _e323[0])) + (_e335 * (_e328 - _e323[1]))) + (_e338 * (_e331 - _e323[2]))) < 0f);
                            } else {
                                phi_466_ = true;
                            }
                            let _e343 = phi_466_;
                            phi_467_ = _e343;
                        }
                        let _e345 = phi_467_;
                        let _e348 = global_5.member.member;
                        let _e350 = local_20;
                        let _e353 = local_22;
                        let _e357 = local_24;
                        let _e364 = global_5.member.member_1;
                        let _e366 = local_20;
                        let _e369 = local_22;
                        let _e373 = local_24;
                        let _e380 = global_5.member.member_2;
                        let _e382 = local_20;
                        let _e385 = local_22;
                        let _e389 = local_24;
                        let _e394 = local_26;
                        let _e396 = local_28;
                        let _e399 = local_30;
                        let _e403 = local_26;
                        let _e405 = local_28;
                        let _e408 = local_30;
                        let _e412 = local_26;
                        let _e414 = local_28;
                        let _e417 = local_30;
                        let _e421 = local_32;
                        let _e423 = local_34;
                        let _e426 = local_36;
                        let _e430 = local_32;
                        let _e432 = local_34;
                        let _e435 = local_36;
                        let _e439 = local_32;
                        let _e441 = local_34;
                        let _e444 = local_36;
                        local_85[0u] = array<f32, 3>(((((_e348[0] * _e350) + (_e348[1] * _e353)) + (_e348[2] * _e357)) + _e348[3]), ((((_e364[0] * _e366) + (_e364[1] * _e369)) + (_e364[2] * _e373)) + _e364[3]), ((((_e380[0] * _e382) + (_e380[1] * _e385)) + (_e380[2] * _e389)) + _e380[3]));
                        local_85[1u] = array<f32, 3>(((((_e348[0] * _e394) + (_e348[1] * _e396)) + (_e348[2] * _e399)) + _e348[3]), ((((_e364[0] * _e403) + (_e364[1] * _e405)) + (_e364[2] * _e408)) + _e364[3]), ((((_e380[0] * _e412) + (_e380[1] * _e414)) + (_e380[2] * _e417)) + _e380[3]));
                        local_85[2u] = array<f32, 3>(((((_e348[0] * _e421) + (_e348[1] * _e423)) + (_e348[2] * _e426)) + _e348[3]), ((((_e364[0] * _e430) + (_e364[1] * _e432)) + (_e364[2] * _e435)) + _e364[3]), ((((_e380[0] * _e439) + (_e380[1] * _e441)) + (_e380[2] * _e444)) + _e380[3]));
                        if _e345 {
                            let _e460 = global_5.member.member_5;
                            local_41 = _e460;
                            let _e461 = (_e460 / 16u);
                            local_42 = _e461;
                            if ((_e460 % 16u) > 0u) {
                                let _e464 = local_42;
                                phi_614_ = (_e464 + 1u);
                            } else {
                                phi_614_ = _e461;
                            }
                            let _e467 = phi_614_;
                            local_43 = _e467;
                            let _e470 = global_5.member.member_6;
                            local_44 = _e470;
                            let _e471 = (_e470 / 16u);
                            local_45 = _e471;
                            if ((_e470 % 16u) > 0u) {
                                let _e474 = local_45;
                                phi_632_ = (_e474 + 1u);
                            } else {
                                phi_632_ = _e471;
                            }
                            let _e477 = phi_632_;
                            local_46 = _e477;
                            let _e480 = local_85[0u][2u];
                            let _e483 = global_5.member.member_4;
                            let _e484 = (_e480 < _e483);
                            local_47 = _e484;
                            let _e487 = local_85[1u][2u];
                            local_48 = (_e487 < _e483);
                            let _e491 = local_85[2u][2u];
                            local_49 = (_e491 < _e483);
                            if _e484 {
                                let _e493 = local_48;
                                if _e493 {
                                    let _e494 = local_49;
                                    if _e494 {
                                        phi_660_ = array<u32, 4>(1u, 1u, 0u, 0u);
                                    } else {
                                        phi_660_ = array<u32, 4>();
                                    }
                                    let _e496 = phi_660_;
                                    let _e497 = local_49;
                                    phi_662_ = _e496;
                                    phi_663_ = select(true, false, _e497);
                                } else {
                                    phi_662_ = array<u32, 4>();
                                    phi_663_ = true;
                                }
                                let _e500 = phi_662_;
                                let _e502 = phi_663_;
                                phi_664_ = _e500;
                                phi_665_ = _e502;
                            } else {
                                phi_664_ = array<u32, 4>();
                                phi_665_ = true;
                            }
                            let _e504 = phi_664_;
                            let _e506 = phi_665_;
                            if _e506 {
                                let _e507 = local_47;
                                if _e507 {
                                    phi_1129_ = _e154;
                                    phi_810_ = array<u32, 4>();
                                    phi_811_ = array<u32, 4>();
                                    phi_812_ = true;
                                    phi_813_ = false;
                                } else {
                                    let _e508 = local_48;
                                    if _e508 {
                                        phi_1130_ = _e154;
                                        phi_806_ = array<u32, 4>();
                                        phi_807_ = array<u32, 4>();
                                        phi_809_ = false;
                                    } else {
                                        let _e509 = local_49;
                                        if _e509 {
                                            phi_1131_ = _e154;
                                            phi_803_ = array<u32, 4>();
                                            phi_804_ = array<u32, 4>();
                                            phi_805_ = false;
                                        } else {
                                            let _e510 = local_41;
                                            local_50 = f32(_e510);
                                            let _e512 = local_44;
                                            local_51 = f32(_e512);
                                            phi_687_ = 0u;
                                            phi_690_ = array<f32, 2>(-340282350000000000000000000000000000000f, -340282350000000000000000000000000000000f);
                                            phi_692_ = array<f32, 2>(340282350000000000000000000000000000000f, 340282350000000000000000000000000000000f);
                                            loop {
                                                let _e515 = phi_687_;
                                                let _e517 = phi_690_;
                                                let _e519 = phi_692_;
                                                local_52 = _e515;
                                                local_53 = _e517;
                                                local_54 = _e519;
                                                let _e520 = local_52;
                                                let _e521 = (_e520 < 3u);
                                                local_55 = _e521;
                                                if _e521 {
                                                    let _e522 = local_55;
                                                    if _e522 {
                                                    } else {
                                                        phi_1102_ = true;
                                                        break;
                                                    }
                                                    let _e523 = local_52;
                                                    let _e526 = local_85[_e523][0u];
                                                    local_56 = _e526;
                                                    let _e527 = local_55;
                                                    if _e527 {
                                                    } else {
                                                        phi_1102_ = true;
                                                        break;
                                                    }
                                                    let _e528 = local_52;
                                                    let _e531 = local_85[_e528][2u];
                                                    let _e532 = local_56;
                                                    let _e536 = local_50;
                                                    local_57 = ((((_e532 / _e531) + 1f) * 0.5f) * _e536);
                                                    let _e538 = local_55;
                                                    if _e538 {
                                                    } else {
                                                        phi_1102_ = true;
                                                        break;
                                                    }
                                                    let _e539 = local_52;
                                                    let _e542 = local_85[_e539][1u];
                                                    local_58 = _e542;
                                                    let _e543 = local_55;
                                                    if _e543 {
                                                    } else {
                                                        phi_1102_ = true;
                                                        break;
                                                    }
                                                    let _e544 = local_85[_e528][2u];
                                                    let _e545 = local_58;
                                                    let _e549 = local_51;
                                                    local_59 = ((((_e545 / _e544) + 1f) * 0.5f) * _e549);
                                                    let _e551 = local_54;
                                                    local_60 = _e551[0];
                                                    if !((_e551[0] == _e551[0])) {
                                                        phi_924_ = true;
                                                    } else {
                                                        let _e555 = local_57;
                                                        let _e556 = local_60;
                                                        phi_924_ = (_e555 <= _e556);
                                                    }
                                                    let _e559 = phi_924_;
                                                    let _e560 = local_57;
                                                    let _e561 = local_60;
                                                    local_83 = select(_e561, _e560, _e559);
                                                    let _e563 = local_54;
                                                    local_61 = _e563[1];
                                                    if !((_e563[1] == _e563[1])) {
                                                        phi_939_ = true;
                                                    } else {
                                                        let _e567 = local_59;
                                                        let _e568 = local_61;
                                                        phi_939_ = (_e567 <= _e568);
                                                    }
                                                    let _e571 = phi_939_;
                                                    let _e572 = local_59;
                                                    let _e573 = local_61;
                                                    let _e575 = local_83;
                                                    let _e577 = local_53;
                                                    local_62 = _e577[0];
                                                    if !((_e577[0] == _e577[0])) {
                                                        phi_954_ = true;
                                                    } else {
                                                        let _e581 = local_57;
                                                        let _e582 = local_62;
                                                        phi_954_ = (_e581 >= _e582);
                                                    }
                                                    let _e585 = phi_954_;
                                                    let _e586 = local_57;
                                                    let _e587 = local_62;
                                                    local_84 = select(_e587, _e586, _e585);
                                                    let _e589 = local_53;
                                                    local_63 = _e589[1];
                                                    if !((_e589[1] == _e589[1])) {
                                                        phi_969_ = true;
                                                    } else {
                                                        let _e593 = local_59;
                                                        let _e594 = local_63;
                                                        phi_969_ = (_e593 >= _e594);
                                                    }
                                                    let _e597 = phi_969_;
                                                    let _e598 = local_59;
                                                    let _e599 = local_63;
                                                    let _e601 = local_84;
                                                    let _e603 = local_52;
                                                    phi_688_ = (_e603 + 1u);
                                                    phi_691_ = array<f32, 2>(_e601, select(_e599, _e598, _e597));
                                                    phi_693_ = array<f32, 2>(_e575, select(_e573, _e572, _e571));
                                                } else {
                                                    phi_688_ = u32();
                                                    phi_691_ = array<f32, 2>();
                                                    phi_693_ = array<f32, 2>();
                                                }
                                                let _e606 = phi_688_;
                                                let _e608 = phi_691_;
                                                let _e610 = phi_693_;
                                                continue;
                                                continuing {
                                                    let _e611 = local_55;
                                                    phi_687_ = _e606;
                                                    phi_690_ = _e608;
                                                    phi_692_ = _e610;
                                                    phi_1102_ = _e154;
                                                    break if !(_e611);
                                                }
                                            }
                                            let _e614 = phi_1102_;
                                            phi_1147_ = _e614;
                                            if _e614 {
                                                break;
                                            }
                                            let _e615 = local_53;
                                            local_64 = _e615[0];
                                            if (_e615[0] >= 0.5f) {
                                                let _e618 = local_53;
                                                local_65 = _e618[1];
                                                if (_e618[1] >= 0.5f) {
                                                    let _e621 = local_54;
                                                    local_66 = _e621[0];
                                                    let _e623 = local_50;
                                                    if (_e621[0] <= (_e623 - 0.5f)) {
                                                        let _e626 = local_54;
                                                        local_67 = _e626[1];
                                                        let _e628 = local_51;
                                                        let _e630 = (_e626[1] <= (_e628 - 0.5f));
                                                        local_68 = _e630;
                                                        if _e630 {
                                                            let _e631 = local_66;
                                                            let _e633 = ceil((_e631 - 0.5f));
                                                            local_78 = _e633;
                                                            if !((_e633 == _e633)) {
                                                                phi_996_ = true;
                                                            } else {
                                                                let _e636 = local_78;
                                                                phi_996_ = (0f >= _e636);
                                                            }
                                                            let _e639 = phi_996_;
                                                            let _e640 = local_78;
                                                            let _e641 = select(_e640, 0f, _e639);
                                                            local_69 = (select(select(u32(_e641), 0u, !((_e641 >= 0f))), 4294967295u, (_e641 > 4294967000f)) / 16u);
                                                            let _e649 = local_67;
                                                            let _e651 = ceil((_e649 - 0.5f));
                                                            local_79 = _e651;
                                                            if !((_e651 == _e651)) {
                                                                phi_1023_ = true;
                                                            } else {
                                                                let _e654 = local_79;
                                                                phi_1023_ = (0f >= _e654);
                                                            }
                                                            let _e657 = phi_1023_;
                                                            let _e658 = local_79;
                                                            let _e659 = select(_e658, 0f, _e657);
                                                            local_70 = (select(select(u32(_e659), 0u, !((_e659 >= 0f))), 4294967295u, (_e659 > 4294967000f)) / 16u);
                                                            let _e667 = local_64;
                                                            let _e669 = floor((_e667 - 0.5f));
                                                            local_80 = _e669;
                                                            if !((_e669 == _e669)) {
                                                                phi_1056_ = true;
                                                            } else {
                                                                let _e672 = local_80;
                                                                phi_1056_ = (0f >= _e672);
                                                            }
                                                            let _e675 = phi_1056_;
                                                            let _e676 = local_80;
                                                            let _e677 = select(_e676, 0f, _e675);
                                                            let _e683 = select(select(u32(_e677), 0u, !((_e677 >= 0f))), 4294967295u, (_e677 > 4294967000f));
                                                            let _e684 = local_41;
                                                            let _e685 = (_e684 - 1u);
                                                            local_71 = (select(_e683, _e685, (_e685 < _e683)) / 16u);
                                                            let _e689 = local_65;
                                                            let _e691 = floor((_e689 - 0.5f));
                                                            local_81 = _e691;
                                                            if !((_e691 == _e691)) {
                                                                phi_1089_ = true;
                                                            } else {
                                                                let _e694 = local_81;
                                                                phi_1089_ = (0f >= _e694);
                                                            }
                                                            let _e697 = phi_1089_;
                                                            let _e698 = local_81;
                                                            let _e699 = select(_e698, 0f, _e697);
                                                            let _e705 = select(select(u32(_e699), 0u, !((_e699 >= 0f))), 4294967295u, (_e699 > 4294967000f));
                                                            let _e706 = local_44;
                                                            let _e707 = (_e706 - 1u);
                                                            let _e711 = local_69;
                                                            let _e712 = local_70;
                                                            let _e713 = local_71;
                                                            phi_790_ = array<u32, 4>(_e711, _e712, _e713, (select(_e705, _e707, (_e707 < _e705)) / 16u));
                                                        } else {
                                                            phi_790_ = array<u32, 4>();
                                                        }
                                                        let _e716 = phi_790_;
                                                        let _e717 = local_68;
                                                        phi_792_ = _e716;
                                                        phi_793_ = select(true, false, _e717);
                                                    } else {
                                                        phi_792_ = array<u32, 4>();
                                                        phi_793_ = true;
                                                    }
                                                    let _e720 = phi_792_;
                                                    let _e722 = phi_793_;
                                                    phi_794_ = _e720;
                                                    phi_795_ = _e722;
                                                } else {
                                                    phi_794_ = array<u32, 4>();
                                                    phi_795_ = true;
                                                }
                                                let _e724 = phi_794_;
                                                let _e726 = phi_795_;
                                                phi_796_ = _e724;
                                                phi_797_ = _e726;
                                            } else {
                                                phi_796_ = array<u32, 4>();
                                                phi_797_ = true;
                                            }
                                            let _e728 = phi_796_;
                                            let _e730 = phi_797_;
                                            if _e730 {
                                                phi_802_ = array<u32, 4>(1u, 1u, 0u, 0u);
                                            } else {
                                                phi_802_ = array<u32, 4>();
                                            }
                                            let _e732 = phi_802_;
                                            phi_1131_ = _e614;
                                            phi_803_ = _e732;
                                            phi_804_ = _e728;
                                            phi_805_ = _e730;
                                        }
                                        let _e734 = phi_1131_;
                                        let _e736 = phi_803_;
                                        let _e738 = phi_804_;
                                        let _e740 = phi_805_;
                                        phi_1130_ = _e734;
                                        phi_806_ = _e736;
                                        phi_807_ = _e738;
                                        phi_809_ = _e740;
                                    }
                                    let _e742 = phi_1130_;
                                    let _e744 = phi_806_;
                                    let _e746 = phi_807_;
                                    let _e748 = phi_809_;
                                    let _e749 = local_48;
                                    let _e750 = local_49;
                                    phi_1129_ = _e742;
                                    phi_810_ = _e744;
                                    phi_811_ = _e746;
                                    phi_812_ = select(_e750, true, _e749);
                                    phi_813_ = _e748;
                                }
                                let _e753 = phi_1129_;
                                let _e755 = phi_810_;
                                let _e757 = phi_811_;
                                let _e759 = phi_812_;
                                let _e761 = phi_813_;
                                local_72 = _e759;
                                local_73 = _e761;
                                if _e759 {
                                    let _e762 = local_43;
                                    let _e764 = local_46;
                                    phi_820_ = array<u32, 4>(0u, 0u, (_e762 - 1u), (_e764 - 1u));
                                } else {
                                    phi_820_ = _e755;
                                }
                                let _e768 = phi_820_;
                                let _e769 = local_72;
                                let _e770 = local_73;
                                phi_1127_ = _e753;
                                phi_822_ = _e768;
                                phi_823_ = _e757;
                                phi_824_ = select(_e770, true, _e769);
                            } else {
                                phi_1127_ = _e154;
                                phi_822_ = _e504;
                                phi_823_ = array<u32, 4>();
                                phi_824_ = true;
                            }
                            let _e773 = phi_1127_;
                            let _e775 = phi_822_;
                            let _e777 = phi_823_;
                            let _e779 = phi_824_;
                            if _e779 {
                                phi_828_ = _e775;
                            } else {
                                phi_828_ = _e777;
                            }
                            let _e781 = phi_828_;
                            local_86 = array<u32, 4>(_e781[0], _e781[1], _e781[2], _e781[3]);
                            phi_1125_ = _e773;
                        } else {
                            local_86[0u] = 1u;
                            local_86[1u] = 1u;
                            local_86[2u] = 0u;
                            local_86[3u] = 0u;
                            phi_1125_ = _e154;
                        }
                        let _e788 = phi_1125_;
                        phi_839_ = 0u;
                        loop {
                            let _e790 = phi_839_;
                            local_74 = _e790;
                            let _e791 = local_74;
                            let _e792 = (_e791 < 4u);
                            local_75 = _e792;
                            if _e792 {
                                let _e793 = local_10;
                                let _e795 = local_74;
                                local_76 = ((4u * _e793) + _e795);
                                let _e797 = local_75;
                                if _e797 {
                                } else {
                                    phi_1122_ = true;
                                    break;
                                }
                                let _e798 = local_74;
                                let _e800 = local_86[_e798];
                                local_77 = _e800;
                                let _e801 = local_76;
                                let _e802 = local_4;
                                if (_e801 < _e802) {
                                } else {
                                    phi_1122_ = true;
                                    break;
                                }
                                let _e804 = local_76;
                                let _e807 = local_77;
                                global_7.member[_e804] = _e807;
                                let _e808 = local_74;
                                phi_840_ = (_e808 + 1u);
                            } else {
                                phi_840_ = u32();
                            }
                            let _e811 = phi_840_;
                            continue;
                            continuing {
                                let _e812 = local_75;
                                phi_839_ = _e811;
                                phi_1122_ = _e788;
                                break if !(_e812);
                            }
                        }
                        let _e815 = phi_1122_;
                        phi_1147_ = _e815;
                        if _e815 {
                            break;
                        }
                        phi_1149_ = _e815;
                    } else {
                        phi_1149_ = _e154;
                    }
                    let _e817 = phi_1149_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e818 = local_8;
                    let _e819 = local_7;
                    phi_1148_ = _e817;
                    phi_175_ = (_e818 + _e819);
                } else {
                    phi_1148_ = _e154;
                    phi_175_ = u32();
                }
                let _e822 = phi_1148_;
                let _e824 = phi_175_;
                continue;
                continuing {
                    let _e825 = local_9;
                    phi_1119_ = _e822;
                    phi_174_ = _e824;
                    phi_1147_ = _e822;
                    break if !(_e825);
                }
            }
            let _e828 = phi_1147_;
            if _e828 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn raster_setup(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
