struct type_6 {
    member: array<u32>,
}

struct type_14 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: f32,
}

struct type_15 {
    member: u32,
    member_1: u32,
}

struct type_16 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: f32,
    member_6: u32,
    member_7: u32,
}

struct type_17 {
    member: type_16,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_6;
var<immediate> global_4: type_17;
@group(0) @binding(1) 
var<storage> global_5: type_6;
@group(0) @binding(2) 
var<storage, read_write> global_6: type_6;
@group(0) @binding(3) 
var<storage, read_write> global_7: type_6;
var<private> global_8: u32 = 2139095040u;

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
    var local_12: u32;
    var local_13: bool;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: u32;
    var local_19: f32;
    var local_20: bool;
    var local_21: u32;
    var local_22: type_14;
    var local_23: type_15;
    var local_24: u32;
    var local_25: bool;
    var local_26: f32;
    var local_27: bool;
    var local_28: bool;
    var local_29: u32;
    var local_30: u32;
    var local_31: bool;
    var local_32: u32;
    var local_33: u32;
    var local_34: u32;
    var local_35: bool;
    var local_36: u32;
    var local_37: u32;
    var local_38: u32;
    var local_39: f32;
    var local_40: bool;
    var local_41: f32;
    var local_42: f32;
    var local_43: f32;
    var local_44: u32;
    var local_45: bool;
    var local_46: u32;
    var local_47: f32;
    var local_48: array<f32, 3>;
    var local_49: f32;
    var local_50: u32;
    var local_51: bool;
    var local_52: u32;
    var local_53: bool;
    var local_54: u32;
    var local_55: u32;
    var local_56: u32;
    var local_57: bool;
    var local_58: u32;
    var local_59: u32;
    var local_60: f32;
    var local_61: bool;
    var local_62: u32;
    var local_63: u32;
    var local_64: f32;
    var local_65: f32;
    var local_66: f32;
    var local_67: u32;
    var local_68: u32;
    var local_69: f32;
    var local_70: array<f32, 3>;
    var local_71: array<f32, 3>;
    var local_72: f32;
    var local_73: u32;
    var local_74: f32;
    var local_75: u32;
    var local_76: f32;
    var local_77: u32;
    var local_78: f32;
    var local_79: u32;
    var local_80: f32;
    var local_81: u32;
    var local_82: f32;
    var local_83: f32;
    var local_84: f32;
    var local_85: bool;
    var local_86: bool;
    var local_87: bool;
    var local_88: bool;
    var local_89: f32;
    var local_90: f32;
    var local_91: f32;
    var local_92: array<f32, 3>;
    var local_93: f32;
    var local_94: u32;
    var local_95: u32;
    var local_96: u32;
    var local_97: u32;
    var local_98: u32;
    var local_99: u32;
    var local_100: u32;
    var local_101: u32;
    var local_102: u32;
    var local_103: u32;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: bool;
    var local_110: bool;
    var local_111: u32;
    var local_112: u32;
    var local_113: bool;
    var local_114: u32;
    var local_115: u32;
    var local_116: bool;
    var local_117: u32;
    var local_118: bool;
    var local_119: u32;
    var local_120: u32;
    var local_121: u32;
    var local_122: u32;
    var local_123: u32;
    var local_124: u32;
    var local_125: u32;
    var local_126: u32;
    var local_127: u32;
    var local_128: u32;
    var local_129: u32;
    var local_130: u32;
    var local_131: u32;
    var local_132: u32;
    var local_133: u32;
    var local_134: u32;
    var local_135: bool;
    var local_136: u32;
    var local_137: u32;
    var local_138: array<u32, 16>;
    var phi_1388_: bool;
    var phi_119_: u32;
    var phi_1386_: bool;
    var phi_171_: bool;
    var phi_174_: u32;
    var phi_176_: type_14;
    var phi_178_: type_15;
    var phi_183_: u32;
    var phi_186_: bool;
    var phi_188_: f32;
    var phi_376_: bool;
    var phi_382_: f32;
    var phi_184_: u32;
    var phi_187_: bool;
    var phi_189_: f32;
    var phi_1379_: bool;
    var phi_395_: f32;
    var phi_1394_: bool;
    var phi_397_: f32;
    var phi_400_: f32;
    var phi_402_: u32;
    var phi_404_: bool;
    var phi_406_: u32;
    var phi_408_: f32;
    var phi_410_: array<f32, 3>;
    var phi_412_: array<f32, 3>;
    var phi_414_: f32;
    var phi_416_: u32;
    var phi_484_: u32;
    var phi_487_: f32;
    var phi_612_: f32;
    var phi_485_: u32;
    var phi_488_: f32;
    var phi_1389_: bool;
    var phi_618_: f32;
    var phi_621_: f32;
    var phi_623_: u32;
    var phi_625_: bool;
    var phi_626_: u32;
    var phi_628_: f32;
    var phi_630_: array<f32, 3>;
    var phi_632_: array<f32, 3>;
    var phi_634_: f32;
    var phi_767_: f32;
    var phi_789_: bool;
    var phi_790_: bool;
    var phi_791_: bool;
    var phi_792_: bool;
    var phi_799_: u32;
    var phi_835_: f32;
    var phi_839_: f32;
    var phi_840_: f32;
    var phi_841_: u32;
    var phi_842_: u32;
    var phi_843_: f32;
    var phi_844_: array<f32, 3>;
    var phi_845_: array<f32, 3>;
    var phi_846_: f32;
    var phi_619_: f32;
    var phi_622_: f32;
    var phi_624_: u32;
    var phi_627_: u32;
    var phi_629_: f32;
    var phi_631_: array<f32, 3>;
    var phi_633_: array<f32, 3>;
    var phi_635_: f32;
    var phi_847_: bool;
    var phi_1397_: bool;
    var phi_1411_: bool;
    var phi_858_: f32;
    var phi_859_: f32;
    var phi_860_: bool;
    var phi_861_: u32;
    var phi_862_: f32;
    var phi_863_: array<f32, 3>;
    var phi_864_: array<f32, 3>;
    var phi_865_: f32;
    var phi_866_: u32;
    var phi_1410_: bool;
    var phi_398_: f32;
    var phi_401_: f32;
    var phi_403_: u32;
    var phi_405_: bool;
    var phi_407_: u32;
    var phi_409_: f32;
    var phi_411_: array<f32, 3>;
    var phi_413_: array<f32, 3>;
    var phi_415_: f32;
    var phi_417_: u32;
    var phi_1409_: bool;
    var phi_891_: bool;
    var phi_892_: bool;
    var phi_893_: bool;
    var phi_902_: f32;
    var phi_904_: array<f32, 3>;
    var phi_921_: f32;
    var phi_922_: f32;
    var phi_1067_: u32;
    var phi_1068_: type_14;
    var phi_1069_: type_15;
    var phi_1071_: u32;
    var phi_1072_: type_14;
    var phi_1073_: type_15;
    var phi_1074_: bool;
    var phi_1075_: u32;
    var phi_1076_: type_14;
    var phi_1077_: type_15;
    var phi_1080_: u32;
    var phi_1081_: u32;
    var phi_1412_: bool;
    var phi_1420_: bool;
    var phi_1158_: bool;
    var phi_1159_: u32;
    var phi_1160_: type_14;
    var phi_1161_: type_15;
    var phi_1162_: bool;
    var phi_1168_: type_14;
    var phi_1169_: type_15;
    var phi_1418_: bool;
    var phi_172_: bool;
    var phi_175_: u32;
    var phi_177_: type_14;
    var phi_179_: type_15;
    var phi_1417_: bool;
    var phi_1290_: type_15;
    var phi_1291_: type_15;
    var phi_1308_: u32;
    var phi_1343_: u32;
    var phi_1309_: u32;
    var phi_1344_: bool;
    var phi_1432_: bool;
    var phi_1441_: bool;
    var phi_1440_: bool;
    var phi_120_: u32;
    var phi_1439_: bool;
    var local_139: f32;
    var local_140: bool;
    var local_141: u32;
    var local_142: f32;
    var local_143: array<f32, 3>;
    var local_144: array<f32, 3>;
    var local_145: f32;
    var local_146: f32;
    var local_147: array<f32, 3>;
    var local_148: array<f32, 3>;
    var local_149: f32;
    var local_150: u32;
    var local_151: u32;
    var local_152: type_15;
    var local_153: type_15;

    let _e175 = global_8;
    let _e176 = bitcast<f32>(_e175);
    switch bitcast<i32>(0u) {
        default: {
            let _e178 = global;
            local = _e178;
            let _e179 = global_1;
            let _e180 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_5.member));
            local_3 = arrayLength((&global_6.member));
            local_4 = arrayLength((&global_7.member));
            let _e193 = global_4.member.member;
            local_5 = _e193;
            let _e196 = global_4.member.member_2;
            local_6 = _e196;
            local_7 = (_e193 * _e196);
            let _e200 = global_4.member.member_1;
            local_8 = (_e193 * _e200);
            local_9 = (_e180.x * 64u);
            phi_1388_ = false;
            phi_119_ = (_e179.x * 64u);
            loop {
                let _e205 = phi_1388_;
                let _e207 = phi_119_;
                local_10 = _e207;
                let _e208 = local_10;
                let _e209 = local_8;
                let _e210 = (_e208 < _e209);
                local_11 = _e210;
                if _e210 {
                    let _e211 = local_10;
                    let _e212 = local;
                    let _e213 = (_e211 + _e212);
                    local_12 = _e213;
                    let _e214 = local_8;
                    if (_e213 < _e214) {
                        let _e216 = local_5;
                        let _e217 = (_e216 == 0u);
                        local_13 = _e217;
                        if _e217 {
                            phi_1439_ = true;
                            break;
                        }
                        let _e218 = local_12;
                        let _e219 = local_5;
                        local_14 = (_e218 % _e219);
                        let _e221 = local_13;
                        if _e221 {
                            phi_1439_ = true;
                            break;
                        }
                        let _e222 = local_12;
                        let _e223 = local_5;
                        local_15 = (_e222 / _e223);
                        let _e227 = global_4.member.member_4;
                        local_16 = _e227;
                        let _e228 = local_12;
                        local_17 = (_e228 * _e227);
                        let _e230 = local_8;
                        local_18 = (_e230 * _e227);
                        let _e232 = local_6;
                        let _e233 = local_6;
                        let _e234 = (_e232 * _e233);
                        let _e237 = global_4.member.member_5;
                        local_19 = _e237;
                        local_136 = select(16u, _e234, (_e234 < 16u));
                        local_138 = array<u32, 16>(0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
                        phi_1386_ = _e205;
                        phi_171_ = false;
                        phi_174_ = 0u;
                        phi_176_ = type_14(array<f32, 3>(0f, 0f, 0f), 0f, 0f);
                        phi_178_ = type_15(0u, 0u);
                        loop {
                            let _e241 = phi_1386_;
                            let _e243 = phi_171_;
                            let _e245 = phi_174_;
                            let _e247 = phi_176_;
                            let _e249 = phi_178_;
                            local_20 = _e243;
                            local_21 = _e245;
                            local_22 = _e247;
                            local_23 = _e249;
                            phi_183_ = 0u;
                            phi_186_ = false;
                            phi_188_ = _e176;
                            local_152 = _e249;
                            local_153 = _e249;
                            loop {
                                let _e251 = phi_183_;
                                let _e253 = phi_186_;
                                let _e255 = phi_188_;
                                local_24 = _e251;
                                local_25 = _e253;
                                local_26 = _e255;
                                local_149 = _e255;
                                let _e256 = local_24;
                                let _e257 = local_136;
                                let _e258 = (_e256 < _e257);
                                local_27 = _e258;
                                if _e258 {
                                    let _e259 = local_24;
                                    let _e260 = (_e259 < 16u);
                                    local_28 = _e260;
                                    if _e260 {
                                    } else {
                                        phi_1379_ = true;
                                        break;
                                    }
                                    let _e261 = local_24;
                                    let _e263 = local_138[_e261];
                                    local_29 = _e263;
                                    let _e264 = local_15;
                                    let _e265 = local_6;
                                    local_30 = (_e264 * _e265);
                                    let _e267 = local_6;
                                    let _e268 = (_e267 == 0u);
                                    local_31 = _e268;
                                    if _e268 {
                                        phi_1379_ = true;
                                        break;
                                    }
                                    let _e269 = local_24;
                                    let _e270 = local_6;
                                    let _e272 = local_30;
                                    let _e274 = local_7;
                                    let _e276 = local_14;
                                    let _e277 = local_6;
                                    local_32 = (((_e272 + (_e269 / _e270)) * _e274) + (_e276 * _e277));
                                    let _e280 = local_31;
                                    if _e280 {
                                        phi_1379_ = true;
                                        break;
                                    }
                                    let _e281 = local_24;
                                    let _e282 = local_6;
                                    let _e284 = local_32;
                                    let _e285 = (_e284 + (_e281 % _e282));
                                    local_33 = _e285;
                                    let _e286 = local_2;
                                    if (_e285 < _e286) {
                                    } else {
                                        phi_1379_ = true;
                                        break;
                                    }
                                    let _e288 = local_33;
                                    let _e291 = global_5.member[_e288];
                                    let _e294 = global_4.member.member_3;
                                    local_34 = _e294;
                                    let _e297 = local_29;
                                    let _e298 = (_e297 < select(_e294, _e291, (_e291 < _e294)));
                                    local_35 = _e298;
                                    if _e298 {
                                        let _e299 = local_28;
                                        if _e299 {
                                        } else {
                                            phi_1379_ = true;
                                            break;
                                        }
                                        let _e300 = local_138[_e261];
                                        local_36 = _e300;
                                        let _e301 = local_31;
                                        if _e301 {
                                            phi_1379_ = true;
                                            break;
                                        }
                                        let _e302 = local_31;
                                        if _e302 {
                                            phi_1379_ = true;
                                            break;
                                        }
                                        let _e303 = local_33;
                                        let _e304 = local_34;
                                        let _e306 = local_36;
                                        let _e308 = (5u * ((_e303 * _e304) + _e306));
                                        local_37 = _e308;
                                        let _e309 = local_1;
                                        if (_e308 < _e309) {
                                        } else {
                                            phi_1379_ = true;
                                            break;
                                        }
                                        let _e311 = local_37;
                                        let _e313 = local_1;
                                        if ((_e311 + 1u) < _e313) {
                                        } else {
                                            phi_1379_ = true;
                                            break;
                                        }
                                        let _e315 = local_37;
                                        let _e317 = local_1;
                                        if ((_e315 + 2u) < _e317) {
                                        } else {
                                            phi_1379_ = true;
                                            break;
                                        }
                                        let _e319 = local_37;
                                        let _e320 = (_e319 + 3u);
                                        local_38 = _e320;
                                        let _e321 = local_1;
                                        if (_e320 < _e321) {
                                        } else {
                                            phi_1379_ = true;
                                            break;
                                        }
                                        let _e323 = local_38;
                                        let _e326 = global_3.member[_e323];
                                        local_39 = bitcast<f32>(_e326);
                                        let _e328 = local_37;
                                        let _e330 = local_1;
                                        if ((_e328 + 4u) < _e330) {
                                        } else {
                                            phi_1379_ = true;
                                            break;
                                        }
                                        let _e332 = local_25;
                                        if _e332 {
                                            let _e333 = local_39;
                                            let _e334 = local_26;
                                            phi_376_ = (_e333 < _e334);
                                        } else {
                                            phi_376_ = true;
                                        }
                                        let _e337 = phi_376_;
                                        let _e338 = local_39;
                                        let _e339 = local_26;
                                        phi_382_ = select(_e339, _e338, _e337);
                                    } else {
                                        phi_382_ = _e255;
                                    }
                                    let _e342 = phi_382_;
                                    let _e343 = local_35;
                                    let _e344 = local_25;
                                    let _e346 = local_24;
                                    phi_184_ = (_e346 + 1u);
                                    phi_187_ = select(_e344, true, _e343);
                                    phi_189_ = _e342;
                                } else {
                                    phi_184_ = u32();
                                    phi_187_ = bool();
                                    phi_189_ = f32();
                                }
                                let _e349 = phi_184_;
                                let _e351 = phi_187_;
                                let _e353 = phi_189_;
                                continue;
                                continuing {
                                    let _e354 = local_27;
                                    phi_183_ = _e349;
                                    phi_186_ = _e351;
                                    phi_188_ = _e353;
                                    phi_1379_ = _e241;
                                    break if !(_e354);
                                }
                            }
                            let _e357 = phi_1379_;
                            phi_1417_ = _e357;
                            if _e357 {
                                break;
                            }
                            let _e358 = local_25;
                            if _e358 {
                                let _e359 = local_26;
                                let _e362 = ((bitcast<u32>(_e359) & 2139095040u) != 2139095040u);
                                local_40 = _e362;
                                if _e362 {
                                    let _e363 = local_19;
                                    let _e364 = local_26;
                                    let _e366 = local_26;
                                    phi_395_ = (_e366 + (_e363 * _e364));
                                } else {
                                    phi_395_ = _e176;
                                }
                                let _e369 = phi_395_;
                                local_41 = _e369;
                                phi_1394_ = _e357;
                                phi_397_ = 0f;
                                phi_400_ = 0f;
                                phi_402_ = 0u;
                                phi_404_ = false;
                                phi_406_ = 0u;
                                phi_408_ = 0f;
                                phi_410_ = array<f32, 3>(0f, 0f, 0f);
                                phi_412_ = array<f32, 3>(0f, 0f, 0f);
                                phi_414_ = 0f;
                                phi_416_ = 0u;
                                loop {
                                    let _e371 = phi_1394_;
                                    let _e373 = phi_397_;
                                    let _e375 = phi_400_;
                                    let _e377 = phi_402_;
                                    let _e379 = phi_404_;
                                    let _e381 = phi_406_;
                                    let _e383 = phi_408_;
                                    let _e385 = phi_410_;
                                    let _e387 = phi_412_;
                                    let _e389 = phi_414_;
                                    let _e391 = phi_416_;
                                    local_42 = _e373;
                                    local_43 = _e375;
                                    local_44 = _e377;
                                    local_45 = _e379;
                                    local_46 = _e381;
                                    local_47 = _e383;
                                    local_48 = _e387;
                                    local_49 = _e389;
                                    local_50 = _e391;
                                    local_146 = _e373;
                                    local_147 = _e385;
                                    local_148 = _e387;
                                    local_150 = _e381;
                                    local_151 = _e381;
                                    let _e392 = local_44;
                                    let _e393 = local_136;
                                    let _e394 = (_e392 < _e393);
                                    local_51 = _e394;
                                    if _e394 {
                                        let _e395 = local_15;
                                        let _e396 = local_6;
                                        local_52 = (_e395 * _e396);
                                        let _e398 = local_6;
                                        let _e399 = (_e398 == 0u);
                                        local_53 = _e399;
                                        if _e399 {
                                            phi_1409_ = true;
                                            break;
                                        }
                                        let _e400 = local_44;
                                        let _e401 = local_6;
                                        let _e403 = local_52;
                                        let _e405 = local_7;
                                        let _e407 = local_14;
                                        let _e408 = local_6;
                                        local_54 = (((_e403 + (_e400 / _e401)) * _e405) + (_e407 * _e408));
                                        let _e411 = local_53;
                                        if _e411 {
                                            phi_1409_ = true;
                                            break;
                                        }
                                        let _e412 = local_44;
                                        let _e413 = local_6;
                                        let _e415 = local_54;
                                        let _e416 = (_e415 + (_e412 % _e413));
                                        local_55 = _e416;
                                        let _e417 = local_2;
                                        if (_e416 < _e417) {
                                        } else {
                                            phi_1409_ = true;
                                            break;
                                        }
                                        let _e419 = local_55;
                                        let _e422 = global_5.member[_e419];
                                        let _e425 = global_4.member.member_3;
                                        local_56 = _e425;
                                        local_137 = select(_e425, _e422, (_e422 < _e425));
                                        let _e428 = local_44;
                                        let _e429 = (_e428 < 16u);
                                        local_57 = _e429;
                                        if _e429 {
                                        } else {
                                            phi_1409_ = true;
                                            break;
                                        }
                                        let _e430 = local_44;
                                        let _e432 = local_138[_e430];
                                        local_58 = _e432;
                                        let _e433 = local_137;
                                        if (_e432 < _e433) {
                                            let _e435 = local_50;
                                            phi_484_ = 0u;
                                            phi_487_ = 1f;
                                            loop {
                                                let _e438 = phi_484_;
                                                let _e440 = phi_487_;
                                                local_59 = _e438;
                                                local_60 = _e440;
                                                let _e441 = local_59;
                                                let _e442 = local_58;
                                                let _e443 = (_e441 < _e442);
                                                local_61 = _e443;
                                                if _e443 {
                                                    let _e444 = local_53;
                                                    if _e444 {
                                                        phi_1389_ = true;
                                                        break;
                                                    }
                                                    let _e445 = local_53;
                                                    if _e445 {
                                                        phi_1389_ = true;
                                                        break;
                                                    }
                                                    let _e446 = local_55;
                                                    let _e447 = local_56;
                                                    let _e449 = local_59;
                                                    let _e451 = (5u * ((_e446 * _e447) + _e449));
                                                    local_62 = _e451;
                                                    let _e452 = local_1;
                                                    if (_e451 < _e452) {
                                                    } else {
                                                        phi_1389_ = true;
                                                        break;
                                                    }
                                                    let _e454 = local_62;
                                                    let _e456 = local_1;
                                                    if ((_e454 + 1u) < _e456) {
                                                    } else {
                                                        phi_1389_ = true;
                                                        break;
                                                    }
                                                    let _e458 = local_62;
                                                    let _e460 = local_1;
                                                    if ((_e458 + 2u) < _e460) {
                                                    } else {
                                                        phi_1389_ = true;
                                                        break;
                                                    }
                                                    let _e462 = local_62;
                                                    let _e464 = local_1;
                                                    if ((_e462 + 3u) < _e464) {
                                                    } else {
                                                        phi_1389_ = true;
                                                        break;
                                                    }
                                                    let _e466 = local_62;
                                                    let _e467 = (_e466 + 4u);
                                                    local_63 = _e467;
                                                    let _e468 = local_1;
                                                    if (_e467 < _e468) {
                                                    } else {
                                                        phi_1389_ = true;
                                                        break;
                                                    }
                                                    let _e470 = local_63;
                                                    let _e473 = global_3.member[_e470];
                                                    let _e474 = bitcast<f32>(_e473);
                                                    local_64 = _e474;
                                                    if (_e474 > 1f) {
                                                        phi_612_ = 1f;
                                                    } else {
                                                        let _e476 = local_64;
                                                        let _e478 = local_64;
                                                        phi_612_ = select(0f, _e478, (_e476 >= 0f));
                                                    }
                                                    let _e481 = phi_612_;
                                                    let _e483 = local_60;
                                                    let _e485 = local_59;
                                                    phi_485_ = (_e485 + 1u);
                                                    phi_488_ = (_e483 * (1f - _e481));
                                                } else {
                                                    phi_485_ = u32();
                                                    phi_488_ = f32();
                                                }
                                                let _e488 = phi_485_;
                                                let _e490 = phi_488_;
                                                continue;
                                                continuing {
                                                    let _e491 = local_61;
                                                    phi_484_ = _e488;
                                                    phi_487_ = _e490;
                                                    phi_1389_ = _e371;
                                                    break if !(_e491);
                                                }
                                            }
                                            let _e494 = phi_1389_;
                                            phi_1409_ = _e494;
                                            if _e494 {
                                                break;
                                            }
                                            let _e495 = local_42;
                                            let _e496 = local_60;
                                            phi_618_ = _e375;
                                            phi_621_ = 1f;
                                            phi_623_ = _e432;
                                            phi_625_ = _e379;
                                            phi_626_ = _e381;
                                            phi_628_ = _e383;
                                            phi_630_ = _e385;
                                            phi_632_ = _e387;
                                            phi_634_ = _e389;
                                            loop {
                                                let _e499 = phi_618_;
                                                let _e501 = phi_621_;
                                                let _e503 = phi_623_;
                                                let _e505 = phi_625_;
                                                let _e507 = phi_626_;
                                                let _e509 = phi_628_;
                                                let _e511 = phi_630_;
                                                let _e513 = phi_632_;
                                                let _e515 = phi_634_;
                                                local_65 = _e499;
                                                local_66 = _e501;
                                                local_67 = _e503;
                                                local_68 = _e507;
                                                local_69 = _e509;
                                                local_70 = _e511;
                                                local_71 = _e513;
                                                local_72 = _e515;
                                                local_139 = _e499;
                                                local_140 = _e505;
                                                local_141 = _e507;
                                                local_142 = _e509;
                                                local_143 = _e511;
                                                local_144 = _e513;
                                                local_145 = _e515;
                                                let _e516 = local_67;
                                                let _e517 = local_137;
                                                if (_e516 < _e517) {
                                                    let _e519 = local_53;
                                                    if _e519 {
                                                        phi_1397_ = true;
                                                        break;
                                                    }
                                                    let _e520 = local_53;
                                                    if _e520 {
                                                        phi_1397_ = true;
                                                        break;
                                                    }
                                                    let _e521 = local_55;
                                                    let _e522 = local_56;
                                                    let _e524 = local_67;
                                                    let _e526 = (5u * ((_e521 * _e522) + _e524));
                                                    local_73 = _e526;
                                                    let _e527 = local_1;
                                                    if (_e526 < _e527) {
                                                    } else {
                                                        phi_1397_ = true;
                                                        break;
                                                    }
                                                    let _e529 = local_73;
                                                    let _e532 = global_3.member[_e529];
                                                    local_74 = bitcast<f32>(_e532);
                                                    let _e534 = local_73;
                                                    let _e535 = (_e534 + 1u);
                                                    local_75 = _e535;
                                                    let _e536 = local_1;
                                                    if (_e535 < _e536) {
                                                    } else {
                                                        phi_1397_ = true;
                                                        break;
                                                    }
                                                    let _e538 = local_75;
                                                    let _e541 = global_3.member[_e538];
                                                    local_76 = bitcast<f32>(_e541);
                                                    let _e543 = local_73;
                                                    let _e544 = (_e543 + 2u);
                                                    local_77 = _e544;
                                                    let _e545 = local_1;
                                                    if (_e544 < _e545) {
                                                    } else {
                                                        phi_1397_ = true;
                                                        break;
                                                    }
                                                    let _e547 = local_77;
                                                    let _e550 = global_3.member[_e547];
                                                    local_78 = bitcast<f32>(_e550);
                                                    let _e552 = local_73;
                                                    let _e553 = (_e552 + 3u);
                                                    local_79 = _e553;
                                                    let _e554 = local_1;
                                                    if (_e553 < _e554) {
                                                    } else {
                                                        phi_1397_ = true;
                                                        break;
                                                    }
                                                    let _e556 = local_79;
                                                    let _e559 = global_3.member[_e556];
                                                    local_80 = bitcast<f32>(_e559);
                                                    let _e561 = local_73;
                                                    let _e562 = (_e561 + 4u);
                                                    local_81 = _e562;
                                                    let _e563 = local_1;
                                                    if (_e562 < _e563) {
                                                    } else {
                                                        phi_1397_ = true;
                                                        break;
                                                    }
                                                    let _e565 = local_81;
                                                    let _e568 = global_3.member[_e565];
                                                    local_82 = bitcast<f32>(_e568);
                                                    let _e570 = local_80;
                                                    let _e571 = local_41;
                                                    let _e572 = (_e570 <= _e571);
                                                    if _e572 {
                                                        let _e573 = local_82;
                                                        if (_e573 > 1f) {
                                                            phi_767_ = 1f;
                                                        } else {
                                                            let _e575 = local_82;
                                                            let _e577 = local_82;
                                                            phi_767_ = select(0f, _e577, (_e575 >= 0f));
                                                        }
                                                        let _e580 = phi_767_;
                                                        local_83 = _e580;
                                                        let _e581 = local_66;
                                                        let _e582 = (_e581 * _e580);
                                                        local_84 = _e582;
                                                        if (_e582 > 0f) {
                                                            phi_792_ = true;
                                                        } else {
                                                            let _e584 = local_66;
                                                            if (_e584 > 0f) {
                                                                let _e586 = local_74;
                                                                if (_e586 > 0f) {
                                                                    phi_790_ = true;
                                                                } else {
                                                                    let _e588 = local_76;
                                                                    if (_e588 > 0f) {
                                                                        phi_789_ = true;
                                                                    } else {
                                                                        let _e590 = local_78;
                                                                        phi_789_ = (_e590 > 0f);
                                                                    }
                                                                    let _e593 = phi_789_;
                                                                    phi_790_ = _e593;
                                                                }
                                                                let _e595 = phi_790_;
                                                                phi_791_ = _e595;
                                                            } else {
                                                                phi_791_ = false;
                                                            }
                                                            let _e597 = phi_791_;
                                                            phi_792_ = _e597;
                                                        }
                                                        let _e599 = phi_792_;
                                                        if _e599 {
                                                            let _e600 = local_44;
                                                            let _e604 = local_68;
                                                            phi_799_ = (_e604 | (1u << bitcast<u32>((_e600 & 31u))));
                                                        } else {
                                                            phi_799_ = _e507;
                                                        }
                                                        let _e607 = phi_799_;
                                                        let _e608 = local_66;
                                                        let _e609 = local_74;
                                                        let _e611 = local_71;
                                                        let _e614 = local_66;
                                                        let _e615 = local_76;
                                                        let _e617 = local_71;
                                                        let _e620 = local_66;
                                                        let _e621 = local_78;
                                                        let _e623 = local_71;
                                                        let _e627 = local_60;
                                                        let _e628 = local_66;
                                                        let _e629 = (_e627 * _e628);
                                                        let _e630 = local_74;
                                                        let _e632 = local_70;
                                                        let _e635 = local_76;
                                                        let _e637 = local_70;
                                                        let _e640 = local_78;
                                                        let _e642 = local_70;
                                                        let _e646 = local_72;
                                                        let _e647 = local_84;
                                                        let _e649 = local_60;
                                                        let _e650 = local_84;
                                                        let _e652 = local_65;
                                                        let _e654 = local_40;
                                                        if _e654 {
                                                            let _e655 = local_84;
                                                            let _e656 = local_80;
                                                            let _e658 = local_69;
                                                            phi_835_ = (_e658 + (_e655 * _e656));
                                                        } else {
                                                            phi_835_ = _e509;
                                                        }
                                                        let _e661 = phi_835_;
                                                        let _e662 = local_83;
                                                        let _e664 = local_66;
                                                        let _e666 = local_67;
                                                        phi_839_ = (_e652 + (_e649 * _e650));
                                                        phi_840_ = (_e664 * (1f - _e662));
                                                        phi_841_ = (_e666 + 1u);
                                                        phi_842_ = _e607;
                                                        phi_843_ = _e661;
                                                        phi_844_ = array<f32, 3>((_e632[0] + (_e629 * _e630)), (_e637[1] + (_e629 * _e635)), (_e642[2] + (_e629 * _e640)));
                                                        phi_845_ = array<f32, 3>((_e611[0] + (_e608 * _e609)), (_e617[1] + (_e614 * _e615)), (_e623[2] + (_e620 * _e621)));
                                                        phi_846_ = (_e646 + _e647);
                                                    } else {
                                                        phi_839_ = f32();
                                                        phi_840_ = f32();
                                                        phi_841_ = u32();
                                                        phi_842_ = u32();
                                                        phi_843_ = f32();
                                                        phi_844_ = array<f32, 3>();
                                                        phi_845_ = array<f32, 3>();
                                                        phi_846_ = f32();
                                                    }
                                                    let _e669 = phi_839_;
                                                    let _e671 = phi_840_;
                                                    let _e673 = phi_841_;
                                                    let _e675 = phi_842_;
                                                    let _e677 = phi_843_;
                                                    let _e679 = phi_844_;
                                                    let _e681 = phi_845_;
                                                    let _e683 = phi_846_;
                                                    phi_619_ = _e669;
                                                    phi_622_ = _e671;
                                                    phi_624_ = _e673;
                                                    phi_627_ = _e675;
                                                    phi_629_ = _e677;
                                                    phi_631_ = _e679;
                                                    phi_633_ = _e681;
                                                    phi_635_ = _e683;
                                                    phi_847_ = _e572;
                                                } else {
                                                    phi_619_ = f32();
                                                    phi_622_ = f32();
                                                    phi_624_ = u32();
                                                    phi_627_ = u32();
                                                    phi_629_ = f32();
                                                    phi_631_ = array<f32, 3>();
                                                    phi_633_ = array<f32, 3>();
                                                    phi_635_ = f32();
                                                    phi_847_ = false;
                                                }
                                                let _e685 = phi_619_;
                                                let _e687 = phi_622_;
                                                let _e689 = phi_624_;
                                                let _e691 = phi_627_;
                                                let _e693 = phi_629_;
                                                let _e695 = phi_631_;
                                                let _e697 = phi_633_;
                                                let _e699 = phi_635_;
                                                let _e701 = phi_847_;
                                                local_85 = _e701;
                                                continue;
                                                continuing {
                                                    let _e702 = local_85;
                                                    phi_618_ = _e685;
                                                    phi_621_ = _e687;
                                                    phi_623_ = _e689;
                                                    phi_625_ = true;
                                                    phi_626_ = _e691;
                                                    phi_628_ = _e693;
                                                    phi_630_ = _e695;
                                                    phi_632_ = _e697;
                                                    phi_634_ = _e699;
                                                    phi_1397_ = _e494;
                                                    break if !(_e702);
                                                }
                                            }
                                            let _e705 = phi_1397_;
                                            phi_1409_ = _e705;
                                            if _e705 {
                                                break;
                                            }
                                            let _e706 = local_57;
                                            if _e706 {
                                            } else {
                                                phi_1409_ = true;
                                                break;
                                            }
                                            let _e707 = local_67;
                                            local_138[_e430] = _e707;
                                            phi_1411_ = _e705;
                                            phi_858_ = (_e495 + _e496);
                                            let _e1262 = local_139;
                                            phi_859_ = _e1262;
                                            let _e1265 = local_140;
                                            phi_860_ = _e1265;
                                            let _e1268 = local_141;
                                            phi_861_ = _e1268;
                                            let _e1271 = local_142;
                                            phi_862_ = _e1271;
                                            let _e1274 = local_143;
                                            phi_863_ = _e1274;
                                            let _e1277 = local_144;
                                            phi_864_ = _e1277;
                                            let _e1280 = local_145;
                                            phi_865_ = _e1280;
                                            phi_866_ = (_e435 + 1u);
                                        } else {
                                            phi_1411_ = _e371;
                                            phi_858_ = _e373;
                                            phi_859_ = _e375;
                                            phi_860_ = _e379;
                                            phi_861_ = _e381;
                                            phi_862_ = _e383;
                                            phi_863_ = _e385;
                                            phi_864_ = _e387;
                                            phi_865_ = _e389;
                                            phi_866_ = _e391;
                                        }
                                        let _e709 = phi_1411_;
                                        let _e711 = phi_858_;
                                        let _e713 = phi_859_;
                                        let _e715 = phi_860_;
                                        let _e717 = phi_861_;
                                        let _e719 = phi_862_;
                                        let _e721 = phi_863_;
                                        let _e723 = phi_864_;
                                        let _e725 = phi_865_;
                                        let _e727 = phi_866_;
                                        let _e728 = local_44;
                                        phi_1410_ = _e709;
                                        phi_398_ = _e711;
                                        phi_401_ = _e713;
                                        phi_403_ = (_e728 + 1u);
                                        phi_405_ = _e715;
                                        phi_407_ = _e717;
                                        phi_409_ = _e719;
                                        phi_411_ = _e721;
                                        phi_413_ = _e723;
                                        phi_415_ = _e725;
                                        phi_417_ = _e727;
                                    } else {
                                        phi_1410_ = _e371;
                                        phi_398_ = f32();
                                        phi_401_ = f32();
                                        phi_403_ = u32();
                                        phi_405_ = bool();
                                        phi_407_ = u32();
                                        phi_409_ = f32();
                                        phi_411_ = array<f32, 3>();
                                        phi_413_ = array<f32, 3>();
                                        phi_415_ = f32();
                                        phi_417_ = u32();
                                    }
                                    let _e731 = phi_1410_;
                                    let _e733 = phi_398_;
                                    let _e735 = phi_401_;
                                    let _e737 = phi_403_;
                                    let _e739 = phi_405_;
                                    let _e741 = phi_407_;
                                    let _e743 = phi_409_;
                                    let _e745 = phi_411_;
                                    let _e747 = phi_413_;
                                    let _e749 = phi_415_;
                                    let _e751 = phi_417_;
                                    continue;
                                    continuing {
                                        let _e752 = local_51;
                                        phi_1394_ = _e731;
                                        phi_397_ = _e733;
                                        phi_400_ = _e735;
                                        phi_402_ = _e737;
                                        phi_404_ = _e739;
                                        phi_406_ = _e741;
                                        phi_408_ = _e743;
                                        phi_410_ = _e745;
                                        phi_412_ = _e747;
                                        phi_414_ = _e749;
                                        phi_416_ = _e751;
                                        phi_1409_ = _e731;
                                        break if !(_e752);
                                    }
                                }
                                let _e755 = phi_1409_;
                                phi_1417_ = _e755;
                                if _e755 {
                                    break;
                                }
                                let _e756 = local_45;
                                if _e756 {
                                    let _e757 = local_49;
                                    let _e758 = (_e757 > 0f);
                                    local_86 = _e758;
                                    if _e758 {
                                        phi_893_ = true;
                                    } else {
                                        let _e759 = local_48;
                                        if (_e759[0] == 0f) {
                                            let _e762 = local_48;
                                            if (_e762[1] == 0f) {
                                                let _e765 = local_48;
                                                phi_891_ = select(true, false, (_e765[2] == 0f));
                                            } else {
                                                phi_891_ = true;
                                            }
                                            let _e770 = phi_891_;
                                            phi_892_ = _e770;
                                        } else {
                                            phi_892_ = true;
                                        }
                                        let _e772 = phi_892_;
                                        phi_893_ = _e772;
                                    }
                                    let _e774 = phi_893_;
                                    local_87 = _e774;
                                    if _e774 {
                                        let _e775 = local_42;
                                        let _e776 = (_e775 > 0f);
                                        local_88 = _e776;
                                        if _e776 {
                                            let _e1299 = local_146;
                                            phi_902_ = _e1299;
                                            let _e1302 = local_147;
                                            phi_904_ = _e1302;
                                        } else {
                                            let _e777 = local_50;
                                            phi_902_ = f32(_e777);
                                            let _e1304 = local_148;
                                            phi_904_ = _e1304;
                                        }
                                        let _e780 = phi_902_;
                                        let _e782 = phi_904_;
                                        let _e783 = local_88;
                                        let _e784 = local_43;
                                        let _e785 = local_49;
                                        let _e788 = (_e782[0] / _e780);
                                        local_89 = _e788;
                                        let _e790 = (_e782[1] / _e780);
                                        local_90 = _e790;
                                        let _e792 = (_e782[2] / _e780);
                                        local_91 = _e792;
                                        local_92 = array<f32, 3>(_e788, _e790, _e792);
                                        local_93 = (select(_e785, _e784, _e783) / _e780);
                                        let _e795 = local_40;
                                        if _e795 {
                                            let _e796 = local_86;
                                            if _e796 {
                                                let _e797 = local_47;
                                                let _e798 = local_49;
                                                phi_921_ = (_e797 / _e798);
                                            } else {
                                                let _e1307 = local_149;
                                                phi_921_ = _e1307;
                                            }
                                            let _e801 = phi_921_;
                                            phi_922_ = _e801;
                                        } else {
                                            phi_922_ = _e176;
                                        }
                                        let _e803 = phi_922_;
                                        let _e804 = local_92;
                                        let _e805 = local_93;
                                        let _e806 = type_14(_e804, _e803, _e805);
                                        let _e807 = local_20;
                                        if _e807 {
                                            let _e808 = local_23;
                                            local_94 = _e808.member;
                                            let _e810 = (_e808.member + 1u);
                                            local_95 = _e810;
                                            let _e811 = local_16;
                                            if (_e810 < _e811) {
                                                let _e813 = local_17;
                                                let _e814 = local_94;
                                                let _e815 = (_e813 + _e814);
                                                local_96 = _e815;
                                                let _e816 = (5u * _e815);
                                                local_97 = _e816;
                                                let _e817 = local_22;
                                                local_98 = bitcast<u32>(_e817.member[0]);
                                                let _e821 = local_3;
                                                if (_e816 < _e821) {
                                                } else {
                                                    phi_1417_ = true;
                                                    break;
                                                }
                                                let _e823 = local_97;
                                                let _e826 = local_98;
                                                global_6.member[_e823] = _e826;
                                                let _e827 = local_97;
                                                let _e828 = (_e827 + 1u);
                                                local_99 = _e828;
                                                let _e829 = local_22;
                                                local_100 = bitcast<u32>(_e829.member[1]);
                                                let _e833 = local_3;
                                                if (_e828 < _e833) {
                                                } else {
                                                    phi_1417_ = true;
                                                    break;
                                                }
                                                let _e835 = local_99;
                                                let _e838 = local_100;
                                                global_6.member[_e835] = _e838;
                                                let _e839 = local_97;
                                                let _e840 = (_e839 + 2u);
                                                local_101 = _e840;
                                                let _e841 = local_22;
                                                local_102 = bitcast<u32>(_e841.member[2]);
                                                let _e845 = local_3;
                                                if (_e840 < _e845) {
                                                } else {
                                                    phi_1417_ = true;
                                                    break;
                                                }
                                                let _e847 = local_101;
                                                let _e850 = local_102;
                                                global_6.member[_e847] = _e850;
                                                let _e851 = local_97;
                                                let _e852 = (_e851 + 3u);
                                                local_103 = _e852;
                                                let _e853 = local_22;
                                                local_104 = bitcast<u32>(_e853.member_1);
                                                let _e856 = local_3;
                                                if (_e852 < _e856) {
                                                } else {
                                                    phi_1417_ = true;
                                                    break;
                                                }
                                                let _e858 = local_103;
                                                let _e861 = local_104;
                                                global_6.member[_e858] = _e861;
                                                let _e862 = local_97;
                                                let _e863 = (_e862 + 4u);
                                                local_105 = _e863;
                                                let _e864 = local_22;
                                                local_106 = bitcast<u32>(_e864.member_2);
                                                let _e867 = local_3;
                                                if (_e863 < _e867) {
                                                } else {
                                                    phi_1417_ = true;
                                                    break;
                                                }
                                                let _e869 = local_105;
                                                let _e872 = local_106;
                                                global_6.member[_e869] = _e872;
                                                let _e875 = global_4.member.member_6;
                                                if (_e875 == 0u) {
                                                } else {
                                                    let _e877 = local_18;
                                                    let _e879 = local_96;
                                                    let _e880 = ((5u * _e877) + _e879);
                                                    local_107 = _e880;
                                                    let _e881 = local_3;
                                                    if (_e880 < _e881) {
                                                    } else {
                                                        phi_1417_ = true;
                                                        break;
                                                    }
                                                    let _e883 = local_107;
                                                    let _e886 = local_21;
                                                    global_6.member[_e883] = _e886;
                                                }
                                                let _e887 = local_95;
                                                let _e888 = local_23;
                                                let _e1311 = local_150;
                                                phi_1067_ = _e1311;
                                                phi_1068_ = _e806;
                                                phi_1069_ = type_15(_e887, _e888.member_1);
                                            } else {
                                                let _e892 = local_22;
                                                let _e894 = (1f - _e892.member_2);
                                                let _e895 = local_22;
                                                let _e898 = local_89;
                                                let _e901 = local_22;
                                                let _e904 = local_90;
                                                let _e907 = local_22;
                                                let _e910 = local_91;
                                                let _e914 = local_93;
                                                let _e917 = local_22;
                                                let _e920 = local_21;
                                                let _e921 = local_46;
                                                let _e923 = local_23;
                                                let _e926 = local_23;
                                                phi_1067_ = (_e920 | _e921);
                                                phi_1068_ = type_14(array<f32, 3>((_e895.member[0] + (_e894 * _e898)), (_e901.member[1] + (_e894 * _e904)), (_e907.member[2] + (_e894 * _e910))), _e917.member_1, (_e892.member_2 + (_e894 * _e914)));
                                                phi_1069_ = type_15(_e926.member, (_e923.member_1 + 1u));
                                            }
                                            let _e931 = phi_1067_;
                                            let _e933 = phi_1068_;
                                            let _e935 = phi_1069_;
                                            phi_1071_ = _e931;
                                            phi_1072_ = _e933;
                                            phi_1073_ = _e935;
                                        } else {
                                            let _e1316 = local_151;
                                            phi_1071_ = _e1316;
                                            phi_1072_ = _e806;
                                            phi_1073_ = _e249;
                                        }
                                        let _e937 = phi_1071_;
                                        let _e939 = phi_1072_;
                                        let _e941 = phi_1073_;
                                        let _e942 = local_20;
                                        let _e943 = local_20;
                                        phi_1074_ = select(true, _e943, _e942);
                                        phi_1075_ = _e937;
                                        phi_1076_ = _e939;
                                        phi_1077_ = _e941;
                                    } else {
                                        phi_1074_ = bool();
                                        phi_1075_ = u32();
                                        phi_1076_ = type_14();
                                        phi_1077_ = type_15();
                                    }
                                    let _e946 = phi_1074_;
                                    let _e948 = phi_1075_;
                                    let _e950 = phi_1076_;
                                    let _e952 = phi_1077_;
                                    let _e953 = local_87;
                                    phi_1420_ = _e755;
                                    phi_1158_ = _e946;
                                    phi_1159_ = _e948;
                                    phi_1160_ = _e950;
                                    phi_1161_ = _e952;
                                    phi_1162_ = select(true, false, _e953);
                                } else {
                                    phi_1080_ = 0u;
                                    loop {
                                        let _e956 = phi_1080_;
                                        local_108 = _e956;
                                        let _e957 = local_108;
                                        let _e958 = local_136;
                                        let _e959 = (_e957 < _e958);
                                        local_109 = _e959;
                                        if _e959 {
                                            let _e960 = local_108;
                                            let _e961 = (_e960 < 16u);
                                            local_110 = _e961;
                                            if _e961 {
                                            } else {
                                                phi_1412_ = true;
                                                break;
                                            }
                                            let _e962 = local_108;
                                            let _e964 = local_138[_e962];
                                            local_111 = _e964;
                                            let _e965 = local_15;
                                            let _e966 = local_6;
                                            local_112 = (_e965 * _e966);
                                            let _e968 = local_6;
                                            let _e969 = (_e968 == 0u);
                                            local_113 = _e969;
                                            if _e969 {
                                                phi_1412_ = true;
                                                break;
                                            }
                                            let _e970 = local_108;
                                            let _e971 = local_6;
                                            let _e973 = local_112;
                                            let _e975 = local_7;
                                            let _e977 = local_14;
                                            let _e978 = local_6;
                                            local_114 = (((_e973 + (_e970 / _e971)) * _e975) + (_e977 * _e978));
                                            let _e981 = local_113;
                                            if _e981 {
                                                phi_1412_ = true;
                                                break;
                                            }
                                            let _e982 = local_108;
                                            let _e983 = local_6;
                                            let _e985 = local_114;
                                            let _e986 = (_e985 + (_e982 % _e983));
                                            local_115 = _e986;
                                            let _e987 = local_2;
                                            if (_e986 < _e987) {
                                            } else {
                                                phi_1412_ = true;
                                                break;
                                            }
                                            let _e989 = local_115;
                                            let _e992 = global_5.member[_e989];
                                            let _e995 = global_4.member.member_3;
                                            let _e998 = local_111;
                                            if (_e998 < select(_e995, _e992, (_e992 < _e995))) {
                                                let _e1000 = local_110;
                                                if _e1000 {
                                                } else {
                                                    phi_1412_ = true;
                                                    break;
                                                }
                                                let _e1001 = local_138[_e962];
                                                local_138[_e962] = (_e1001 + 1u);
                                            }
                                            let _e1003 = local_108;
                                            phi_1081_ = (_e1003 + 1u);
                                        } else {
                                            phi_1081_ = u32();
                                        }
                                        let _e1006 = phi_1081_;
                                        continue;
                                        continuing {
                                            let _e1007 = local_109;
                                            phi_1080_ = _e1006;
                                            phi_1412_ = _e755;
                                            break if !(_e1007);
                                        }
                                    }
                                    let _e1010 = phi_1412_;
                                    phi_1417_ = _e1010;
                                    if _e1010 {
                                        break;
                                    }
                                    phi_1420_ = _e1010;
                                    phi_1158_ = bool();
                                    phi_1159_ = u32();
                                    phi_1160_ = type_14();
                                    phi_1161_ = type_15();
                                    phi_1162_ = true;
                                }
                                let _e1012 = phi_1420_;
                                let _e1014 = phi_1158_;
                                let _e1016 = phi_1159_;
                                let _e1018 = phi_1160_;
                                let _e1020 = phi_1161_;
                                let _e1022 = phi_1162_;
                                local_116 = _e1014;
                                local_117 = _e1016;
                                local_118 = _e1022;
                                if _e1022 {
                                    phi_1168_ = _e247;
                                    phi_1169_ = _e249;
                                } else {
                                    phi_1168_ = _e1018;
                                    phi_1169_ = _e1020;
                                }
                                let _e1024 = phi_1168_;
                                let _e1026 = phi_1169_;
                                let _e1027 = local_118;
                                let _e1028 = local_20;
                                let _e1029 = local_116;
                                let _e1031 = local_118;
                                let _e1032 = local_21;
                                let _e1033 = local_117;
                                phi_1418_ = _e1012;
                                phi_172_ = select(_e1029, _e1028, _e1027);
                                phi_175_ = select(_e1033, _e1032, _e1031);
                                phi_177_ = _e1024;
                                phi_179_ = _e1026;
                            } else {
                                phi_1418_ = _e357;
                                phi_172_ = bool();
                                phi_175_ = u32();
                                phi_177_ = type_14();
                                phi_179_ = type_15();
                            }
                            let _e1036 = phi_1418_;
                            let _e1038 = phi_172_;
                            let _e1040 = phi_175_;
                            let _e1042 = phi_177_;
                            let _e1044 = phi_179_;
                            continue;
                            continuing {
                                let _e1045 = local_25;
                                phi_1386_ = _e1036;
                                phi_171_ = _e1038;
                                phi_174_ = _e1040;
                                phi_176_ = _e1042;
                                phi_178_ = _e1044;
                                phi_1417_ = _e1036;
                                break if !(_e1045);
                            }
                        }
                        let _e1048 = phi_1417_;
                        phi_1439_ = _e1048;
                        if _e1048 {
                            break;
                        }
                        let _e1049 = local_20;
                        if _e1049 {
                            let _e1050 = local_16;
                            if (_e1050 > 0u) {
                                let _e1052 = local_23;
                                local_119 = _e1052.member;
                                let _e1054 = local_17;
                                let _e1055 = (_e1054 + _e1052.member);
                                local_120 = _e1055;
                                let _e1056 = (5u * _e1055);
                                local_121 = _e1056;
                                let _e1057 = local_22;
                                local_122 = bitcast<u32>(_e1057.member[0]);
                                let _e1061 = local_3;
                                if (_e1056 < _e1061) {
                                } else {
                                    phi_1439_ = true;
                                    break;
                                }
                                let _e1063 = local_121;
                                let _e1066 = local_122;
                                global_6.member[_e1063] = _e1066;
                                let _e1067 = local_121;
                                let _e1068 = (_e1067 + 1u);
                                local_123 = _e1068;
                                let _e1069 = local_22;
                                local_124 = bitcast<u32>(_e1069.member[1]);
                                let _e1073 = local_3;
                                if (_e1068 < _e1073) {
                                } else {
                                    phi_1439_ = true;
                                    break;
                                }
                                let _e1075 = local_123;
                                let _e1078 = local_124;
                                global_6.member[_e1075] = _e1078;
                                let _e1079 = local_121;
                                let _e1080 = (_e1079 + 2u);
                                local_125 = _e1080;
                                let _e1081 = local_22;
                                local_126 = bitcast<u32>(_e1081.member[2]);
                                let _e1085 = local_3;
                                if (_e1080 < _e1085) {
                                } else {
                                    phi_1439_ = true;
                                    break;
                                }
                                let _e1087 = local_125;
                                let _e1090 = local_126;
                                global_6.member[_e1087] = _e1090;
                                let _e1091 = local_121;
                                let _e1092 = (_e1091 + 3u);
                                local_127 = _e1092;
                                let _e1093 = local_22;
                                local_128 = bitcast<u32>(_e1093.member_1);
                                let _e1096 = local_3;
                                if (_e1092 < _e1096) {
                                } else {
                                    phi_1439_ = true;
                                    break;
                                }
                                let _e1098 = local_127;
                                let _e1101 = local_128;
                                global_6.member[_e1098] = _e1101;
                                let _e1102 = local_121;
                                let _e1103 = (_e1102 + 4u);
                                local_129 = _e1103;
                                let _e1104 = local_22;
                                local_130 = bitcast<u32>(_e1104.member_2);
                                let _e1107 = local_3;
                                if (_e1103 < _e1107) {
                                } else {
                                    phi_1439_ = true;
                                    break;
                                }
                                let _e1109 = local_129;
                                let _e1112 = local_130;
                                global_6.member[_e1109] = _e1112;
                                let _e1115 = global_4.member.member_6;
                                if (_e1115 == 0u) {
                                } else {
                                    let _e1117 = local_18;
                                    let _e1119 = local_120;
                                    let _e1120 = ((5u * _e1117) + _e1119);
                                    local_131 = _e1120;
                                    let _e1121 = local_3;
                                    if (_e1120 < _e1121) {
                                    } else {
                                        phi_1439_ = true;
                                        break;
                                    }
                                    let _e1123 = local_131;
                                    let _e1126 = local_21;
                                    global_6.member[_e1123] = _e1126;
                                }
                                let _e1127 = local_119;
                                let _e1129 = local_23;
                                phi_1290_ = type_15((_e1127 + 1u), _e1129.member_1);
                            } else {
                                let _e1342 = local_152;
                                phi_1290_ = _e1342;
                            }
                            let _e1134 = phi_1290_;
                            phi_1291_ = _e1134;
                        } else {
                            let _e1345 = local_153;
                            phi_1291_ = _e1345;
                        }
                        let _e1136 = phi_1291_;
                        local_132 = _e1136.member;
                        let _e1138 = local_12;
                        let _e1139 = local_4;
                        if (_e1138 < _e1139) {
                        } else {
                            phi_1439_ = true;
                            break;
                        }
                        let _e1141 = local_12;
                        let _e1144 = local_132;
                        global_7.member[_e1141] = _e1144;
                        phi_1308_ = _e1136.member;
                        loop {
                            let _e1146 = phi_1308_;
                            local_133 = _e1146;
                            let _e1149 = global_4.member.member_6;
                            if (_e1149 == 0u) {
                                phi_1309_ = u32();
                                phi_1344_ = false;
                            } else {
                                let _e1151 = local_133;
                                let _e1152 = local_16;
                                let _e1153 = (_e1151 < _e1152);
                                if _e1153 {
                                    let _e1154 = local_17;
                                    let _e1155 = local_133;
                                    let _e1157 = local_18;
                                    let _e1159 = ((5u * _e1157) + (_e1154 + _e1155));
                                    local_134 = _e1159;
                                    let _e1160 = local_3;
                                    if (_e1159 < _e1160) {
                                    } else {
                                        phi_1432_ = true;
                                        break;
                                    }
                                    let _e1162 = local_134;
                                    global_6.member[_e1162] = 0u;
                                    let _e1165 = local_133;
                                    phi_1343_ = (_e1165 + 1u);
                                } else {
                                    phi_1343_ = u32();
                                }
                                let _e1168 = phi_1343_;
                                phi_1309_ = _e1168;
                                phi_1344_ = _e1153;
                            }
                            let _e1170 = phi_1309_;
                            let _e1172 = phi_1344_;
                            local_135 = _e1172;
                            continue;
                            continuing {
                                let _e1173 = local_135;
                                phi_1308_ = _e1170;
                                phi_1432_ = _e1048;
                                break if !(_e1173);
                            }
                        }
                        let _e1176 = phi_1432_;
                        phi_1439_ = _e1176;
                        if _e1176 {
                            break;
                        }
                        phi_1441_ = _e1176;
                    } else {
                        phi_1441_ = _e205;
                    }
                    let _e1178 = phi_1441_;
                    storageBarrier();
                    workgroupBarrier();
                    let _e1179 = local_10;
                    let _e1180 = local_9;
                    phi_1440_ = _e1178;
                    phi_120_ = (_e1179 + _e1180);
                } else {
                    phi_1440_ = _e205;
                    phi_120_ = u32();
                }
                let _e1183 = phi_1440_;
                let _e1185 = phi_120_;
                continue;
                continuing {
                    let _e1186 = local_11;
                    phi_1388_ = _e1183;
                    phi_119_ = _e1185;
                    phi_1439_ = _e1183;
                    break if !(_e1186);
                }
            }
            let _e1189 = phi_1439_;
            if _e1189 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn resolve(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
