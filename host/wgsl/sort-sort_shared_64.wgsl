struct type_5 {
    member: array<u32>,
}

struct type_12 {
    member: u32,
    member_1: u32,
}

struct type_13 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
}

struct type_14 {
    member: type_13,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
var<private> global_2: vec3<u32>;
@group(0) @binding(0) 
var<storage> global_3: type_5;
var<immediate> global_4: type_14;
@group(0) @binding(1) 
var<storage> global_5: type_5;
@group(0) @binding(2) 
var<storage> global_6: type_5;
@group(0) @binding(3) 
var<storage> global_7: type_5;
@group(0) @binding(4) 
var<storage> global_8: type_5;
@group(0) @binding(5) 
var<storage, read_write> global_9: type_5;
@group(0) @binding(6) 
var<storage, read_write> global_10: type_5;
var<workgroup> global_11: array<u32, 128>;

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
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: u32;
    var local_18: bool;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: bool;
    var local_27: u32;
    var local_28: u32;
    var local_29: bool;
    var local_30: u32;
    var local_31: bool;
    var local_32: u32;
    var local_33: u32;
    var local_34: u32;
    var local_35: u32;
    var local_36: u32;
    var local_37: bool;
    var local_38: u32;
    var local_39: u32;
    var local_40: bool;
    var local_41: u32;
    var local_42: bool;
    var local_43: u32;
    var local_44: u32;
    var local_45: bool;
    var local_46: u32;
    var local_47: bool;
    var local_48: u32;
    var local_49: u32;
    var local_50: bool;
    var local_51: u32;
    var local_52: bool;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: u32;
    var local_57: u32;
    var local_58: u32;
    var local_59: bool;
    var local_60: u32;
    var local_61: u32;
    var local_62: bool;
    var local_63: u32;
    var local_64: bool;
    var local_65: u32;
    var local_66: u32;
    var local_67: bool;
    var local_68: u32;
    var local_69: u32;
    var local_70: bool;
    var local_71: u32;
    var local_72: bool;
    var local_73: u32;
    var local_74: u32;
    var local_75: u32;
    var local_76: u32;
    var local_77: u32;
    var local_78: u32;
    var local_79: u32;
    var local_80: u32;
    var local_81: bool;
    var local_82: u32;
    var local_83: bool;
    var local_84: u32;
    var local_85: bool;
    var local_86: u32;
    var local_87: bool;
    var local_88: u32;
    var local_89: bool;
    var local_90: u32;
    var local_91: u32;
    var local_92: u32;
    var local_93: u32;
    var local_94: u32;
    var local_95: u32;
    var local_96: u32;
    var local_97: u32;
    var local_98: u32;
    var local_99: u32;
    var local_100: u32;
    var local_101: bool;
    var local_102: u32;
    var local_103: u32;
    var local_104: bool;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: u32;
    var local_111: bool;
    var local_112: u32;
    var local_113: u32;
    var local_114: u32;
    var local_115: u32;
    var local_116: u32;
    var local_117: bool;
    var local_118: u32;
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
    var local_129: bool;
    var local_130: u32;
    var local_131: u32;
    var local_132: bool;
    var local_133: u32;
    var local_134: u32;
    var local_135: u32;
    var local_136: u32;
    var local_137: u32;
    var local_138: u32;
    var local_139: bool;
    var local_140: u32;
    var local_141: u32;
    var local_142: u32;
    var local_143: u32;
    var local_144: u32;
    var local_145: bool;
    var local_146: u32;
    var local_147: u32;
    var local_148: u32;
    var local_149: u32;
    var local_150: u32;
    var local_151: bool;
    var local_152: u32;
    var local_153: u32;
    var local_154: u32;
    var local_155: u32;
    var local_156: u32;
    var local_157: bool;
    var local_158: u32;
    var local_159: u32;
    var local_160: u32;
    var local_161: u32;
    var local_162: u32;
    var phi_1198_: bool;
    var phi_95_: u32;
    var phi_135_: u32;
    var phi_168_: u32;
    var phi_169_: u32;
    var phi_170_: u32;
    var phi_136_: u32;
    var phi_1194_: bool;
    var phi_1207_: bool;
    var phi_508_: u32;
    var phi_1205_: bool;
    var phi_526_: u32;
    var phi_552_: u32;
    var phi_553_: u32;
    var phi_599_: bool;
    var phi_1201_: bool;
    var phi_1209_: bool;
    var phi_527_: u32;
    var phi_1208_: bool;
    var phi_1211_: bool;
    var phi_509_: u32;
    var phi_1210_: bool;
    var phi_1220_: bool;
    var phi_620_: bool;
    var phi_623_: u32;
    var phi_1219_: bool;
    var phi_842_: u32;
    var phi_866_: u32;
    var phi_869_: u32;
    var phi_871_: u32;
    var phi_949_: u32;
    var phi_950_: u32;
    var phi_952_: u32;
    var phi_953_: u32;
    var phi_954_: u32;
    var phi_867_: u32;
    var phi_870_: u32;
    var phi_872_: u32;
    var phi_955_: bool;
    var phi_1212_: bool;
    var phi_961_: u32;
    var phi_964_: u32;
    var phi_962_: u32;
    var phi_965_: u32;
    var phi_1221_: bool;
    var phi_1005_: u32;
    var phi_1008_: u32;
    var phi_1006_: u32;
    var phi_1009_: u32;
    var phi_1224_: bool;
    var phi_1228_: bool;
    var phi_843_: u32;
    var phi_1227_: bool;
    var phi_1236_: bool;
    var phi_635_: u32;
    var phi_659_: u32;
    var phi_662_: u32;
    var phi_664_: u32;
    var phi_742_: u32;
    var phi_743_: u32;
    var phi_745_: u32;
    var phi_746_: u32;
    var phi_747_: u32;
    var phi_660_: u32;
    var phi_663_: u32;
    var phi_665_: u32;
    var phi_748_: bool;
    var phi_1229_: bool;
    var phi_754_: u32;
    var phi_757_: u32;
    var phi_755_: u32;
    var phi_758_: u32;
    var phi_1237_: bool;
    var phi_798_: u32;
    var phi_801_: u32;
    var phi_799_: u32;
    var phi_802_: u32;
    var phi_1240_: bool;
    var phi_1244_: bool;
    var phi_636_: u32;
    var phi_1243_: bool;
    var phi_1247_: bool;
    var phi_1246_: bool;
    var phi_621_: bool;
    var phi_624_: u32;
    var phi_1245_: bool;
    var phi_1054_: u32;
    var phi_1055_: u32;
    var phi_1248_: bool;
    var phi_1284_: bool;
    var phi_1283_: bool;
    var phi_203_: u32;
    var phi_1259_: bool;
    var phi_205_: u32;
    var phi_1258_: bool;
    var phi_221_: u32;
    var phi_236_: u32;
    var phi_270_: type_12;
    var phi_324_: bool;
    var phi_325_: bool;
    var phi_237_: u32;
    var phi_1251_: bool;
    var phi_1264_: bool;
    var phi_359_: u32;
    var phi_1263_: bool;
    var phi_222_: u32;
    var phi_361_: bool;
    var phi_362_: bool;
    var phi_1262_: bool;
    var phi_1193_: bool;
    var phi_1272_: bool;
    var phi_369_: u32;
    var phi_379_: u32;
    var phi_413_: type_12;
    var phi_467_: bool;
    var phi_468_: bool;
    var phi_380_: u32;
    var phi_1265_: bool;
    var phi_1275_: bool;
    var phi_370_: u32;
    var phi_1274_: bool;
    var phi_1278_: bool;
    var phi_1277_: bool;
    var phi_206_: u32;
    var phi_1276_: bool;
    var phi_1282_: bool;
    var phi_1095_: u32;
    var phi_1096_: u32;
    var phi_1279_: bool;
    var phi_1286_: bool;
    var phi_96_: u32;
    var phi_1285_: bool;
    var local_163: u32;
    var local_164: u32;
    var local_165: u32;
    var local_166: u32;
    var local_167: u32;
    var local_168: u32;
    var local_169: u32;
    var local_170: u32;
    var local_171: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e198 = global;
            local = _e198;
            let _e199 = global_1;
            let _e200 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = arrayLength((&global_7.member));
            local_4 = arrayLength((&global_8.member));
            local_5 = arrayLength((&global_9.member));
            local_6 = arrayLength((&global_10.member));
            local_7 = _e200.x;
            let _e219 = global_4.member.member_1;
            local_8 = _e219;
            if (_e219 < arrayLength((&global_5.member))) {
            } else {
                break;
            }
            let _e221 = local_8;
            let _e224 = global_5.member[_e221];
            local_9 = _e224;
            phi_1198_ = false;
            phi_95_ = _e199.x;
            loop {
                let _e226 = phi_1198_;
                let _e228 = phi_95_;
                local_10 = _e228;
                let _e229 = local_10;
                let _e230 = local_9;
                let _e231 = (_e229 < _e230);
                local_11 = _e231;
                if _e231 {
                    let _e234 = global_4.member.member;
                    let _e235 = local_8;
                    let _e237 = local_10;
                    let _e238 = ((_e235 * _e234) + _e237);
                    local_12 = _e238;
                    let _e239 = local_2;
                    if (_e238 < _e239) {
                    } else {
                        phi_1285_ = true;
                        break;
                    }
                    let _e241 = local_12;
                    let _e244 = global_6.member[_e241];
                    let _e245 = (2u * _e244);
                    local_13 = _e245;
                    let _e246 = local_1;
                    if (_e245 < _e246) {
                    } else {
                        phi_1285_ = true;
                        break;
                    }
                    let _e248 = local_13;
                    let _e251 = global_3.member[_e248];
                    local_14 = _e251;
                    let _e252 = local_13;
                    let _e253 = (_e252 + 1u);
                    local_15 = _e253;
                    let _e254 = local_1;
                    if (_e253 < _e254) {
                    } else {
                        phi_1285_ = true;
                        break;
                    }
                    let _e256 = local_15;
                    let _e259 = global_3.member[_e256];
                    local_16 = _e259;
                    phi_135_ = _e198;
                    loop {
                        let _e261 = phi_135_;
                        local_17 = _e261;
                        let _e262 = local_17;
                        let _e263 = local_16;
                        let _e264 = (_e262 < _e263);
                        local_18 = _e264;
                        if _e264 {
                            let _e265 = local_14;
                            let _e266 = local_17;
                            let _e267 = (_e265 + _e266);
                            local_19 = _e267;
                            let _e268 = local_3;
                            if (_e267 < _e268) {
                            } else {
                                phi_1194_ = true;
                                break;
                            }
                            let _e270 = local_19;
                            let _e273 = global_7.member[_e270];
                            local_20 = _e273;
                            let _e274 = (_e273 & 2147483647u);
                            local_21 = _e274;
                            if (_e274 > 2139095040u) {
                                phi_170_ = 4294967295u;
                            } else {
                                let _e276 = local_21;
                                if (_e276 == 0u) {
                                    phi_169_ = 2147483648u;
                                } else {
                                    let _e278 = local_20;
                                    if ((_e278 & 2147483648u) == 0u) {
                                        let _e283 = local_20;
                                        phi_168_ = (_e283 | 2147483648u);
                                    } else {
                                        let _e281 = local_20;
                                        phi_168_ = ~(_e281);
                                    }
                                    let _e286 = phi_168_;
                                    phi_169_ = _e286;
                                }
                                let _e288 = phi_169_;
                                phi_170_ = _e288;
                            }
                            let _e290 = phi_170_;
                            local_22 = _e290;
                            let _e291 = local_17;
                            if (_e291 < 128u) {
                            } else {
                                phi_1194_ = true;
                                break;
                            }
                            let _e293 = local_17;
                            let _e295 = local_22;
                            global_11[_e293] = _e295;
                            let _e296 = local_17;
                            let _e297 = (64u + _e296);
                            local_23 = _e297;
                            if (_e297 < 128u) {
                            } else {
                                phi_1194_ = true;
                                break;
                            }
                            let _e299 = local_23;
                            let _e301 = local_17;
                            global_11[_e299] = _e301;
                            let _e302 = local_17;
                            phi_136_ = (_e302 + 32u);
                        } else {
                            phi_136_ = u32();
                        }
                        let _e305 = phi_136_;
                        continue;
                        continuing {
                            let _e306 = local_18;
                            phi_135_ = _e305;
                            phi_1194_ = _e226;
                            break if !(_e306);
                        }
                    }
                    let _e309 = phi_1194_;
                    phi_1285_ = _e309;
                    if _e309 {
                        break;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e312 = global_4.member.member_4;
                    if (_e312 == 0u) {
                        let _e927 = local_16;
                        if (_e927 <= 1u) {
                            phi_203_ = 1u;
                        } else {
                            let _e929 = local_16;
                            let _e930 = (_e929 - 1u);
                            phi_203_ = (1u << bitcast<u32>(((32u - select((bitcast<u32>(31i) - firstLeadingBit(_e930)), 32u, (_e930 == 0u))) & 31u)));
                        }
                        let _e941 = phi_203_;
                        local_24 = _e941;
                        phi_1259_ = _e309;
                        phi_205_ = 2u;
                        loop {
                            let _e943 = phi_1259_;
                            let _e945 = phi_205_;
                            local_25 = _e945;
                            let _e946 = local_25;
                            let _e947 = local_24;
                            let _e948 = (_e946 <= _e947);
                            local_26 = _e948;
                            if _e948 {
                                let _e949 = local_25;
                                let _e951 = local_24;
                                local_27 = (_e951 / 32u);
                                phi_1258_ = _e943;
                                phi_221_ = (_e949 / 2u);
                                loop {
                                    let _e954 = phi_1258_;
                                    let _e956 = phi_221_;
                                    local_28 = _e956;
                                    local_171 = _e956;
                                    let _e957 = local_28;
                                    if (_e957 > 0u) {
                                        let _e959 = local_28;
                                        let _e961 = local_27;
                                        let _e962 = ((2u * _e959) <= _e961);
                                        local_29 = _e962;
                                        if _e962 {
                                            phi_1264_ = _e954;
                                            phi_359_ = u32();
                                        } else {
                                            phi_236_ = _e198;
                                            loop {
                                                let _e964 = phi_236_;
                                                local_30 = _e964;
                                                let _e965 = local_24;
                                                let _e967 = local_30;
                                                let _e968 = (_e967 < (_e965 / 2u));
                                                local_31 = _e968;
                                                if _e968 {
                                                    let _e969 = local_28;
                                                    let _e970 = (_e969 - 1u);
                                                    let _e972 = local_30;
                                                    let _e975 = ((_e972 & ~(_e970)) << bitcast<u32>(1i));
                                                    local_32 = _e975;
                                                    let _e976 = local_30;
                                                    let _e977 = (_e976 & _e970);
                                                    local_33 = _e977;
                                                    local_34 = (_e975 + _e977);
                                                    let _e979 = local_25;
                                                    let _e982 = local_28;
                                                    if (_e982 == (_e979 >> bitcast<u32>(1i))) {
                                                        let _e989 = local_32;
                                                        let _e990 = local_25;
                                                        let _e993 = local_33;
                                                        let _e995 = local_34;
                                                        phi_270_ = type_12(_e995, (((_e989 + _e990) - 1u) - _e993));
                                                    } else {
                                                        let _e984 = local_34;
                                                        let _e985 = local_28;
                                                        let _e987 = local_34;
                                                        phi_270_ = type_12(_e987, (_e984 + _e985));
                                                    }
                                                    let _e998 = phi_270_;
                                                    local_35 = _e998.member;
                                                    local_36 = _e998.member_1;
                                                    let _e1001 = local_16;
                                                    if (_e998.member_1 < _e1001) {
                                                        let _e1003 = local_35;
                                                        let _e1004 = (_e1003 < 128u);
                                                        local_37 = _e1004;
                                                        if _e1004 {
                                                        } else {
                                                            phi_1251_ = true;
                                                            break;
                                                        }
                                                        let _e1005 = local_35;
                                                        let _e1007 = global_11[_e1005];
                                                        local_38 = _e1007;
                                                        let _e1008 = local_35;
                                                        let _e1009 = (64u + _e1008);
                                                        local_39 = _e1009;
                                                        let _e1010 = (_e1009 < 128u);
                                                        local_40 = _e1010;
                                                        if _e1010 {
                                                        } else {
                                                            phi_1251_ = true;
                                                            break;
                                                        }
                                                        let _e1011 = local_39;
                                                        let _e1013 = global_11[_e1011];
                                                        local_41 = _e1013;
                                                        let _e1014 = local_36;
                                                        let _e1015 = (_e1014 < 128u);
                                                        local_42 = _e1015;
                                                        if _e1015 {
                                                        } else {
                                                            phi_1251_ = true;
                                                            break;
                                                        }
                                                        let _e1016 = local_36;
                                                        let _e1018 = global_11[_e1016];
                                                        local_43 = _e1018;
                                                        let _e1019 = local_36;
                                                        let _e1020 = (64u + _e1019);
                                                        local_44 = _e1020;
                                                        let _e1021 = (_e1020 < 128u);
                                                        local_45 = _e1021;
                                                        if _e1021 {
                                                        } else {
                                                            phi_1251_ = true;
                                                            break;
                                                        }
                                                        let _e1022 = local_44;
                                                        let _e1024 = global_11[_e1022];
                                                        local_46 = _e1024;
                                                        let _e1025 = local_38;
                                                        let _e1026 = local_43;
                                                        if (_e1025 > _e1026) {
                                                            phi_325_ = true;
                                                        } else {
                                                            let _e1028 = local_38;
                                                            let _e1029 = local_43;
                                                            if (_e1028 == _e1029) {
                                                                let _e1031 = local_41;
                                                                let _e1032 = local_46;
                                                                phi_324_ = (_e1031 > _e1032);
                                                            } else {
                                                                phi_324_ = false;
                                                            }
                                                            let _e1035 = phi_324_;
                                                            phi_325_ = _e1035;
                                                        }
                                                        let _e1037 = phi_325_;
                                                        if _e1037 {
                                                            let _e1038 = local_37;
                                                            if _e1038 {
                                                            } else {
                                                                phi_1251_ = true;
                                                                break;
                                                            }
                                                            let _e1039 = local_43;
                                                            global_11[_e1005] = _e1039;
                                                            let _e1040 = local_40;
                                                            if _e1040 {
                                                            } else {
                                                                phi_1251_ = true;
                                                                break;
                                                            }
                                                            let _e1041 = local_46;
                                                            global_11[_e1011] = _e1041;
                                                            let _e1042 = local_42;
                                                            if _e1042 {
                                                            } else {
                                                                phi_1251_ = true;
                                                                break;
                                                            }
                                                            let _e1043 = local_38;
                                                            global_11[_e1016] = _e1043;
                                                            let _e1044 = local_45;
                                                            if _e1044 {
                                                            } else {
                                                                phi_1251_ = true;
                                                                break;
                                                            }
                                                            let _e1045 = local_41;
                                                            global_11[_e1022] = _e1045;
                                                        }
                                                    }
                                                    let _e1046 = local_30;
                                                    phi_237_ = (_e1046 + 32u);
                                                } else {
                                                    phi_237_ = u32();
                                                }
                                                let _e1049 = phi_237_;
                                                continue;
                                                continuing {
                                                    let _e1050 = local_31;
                                                    phi_236_ = _e1049;
                                                    phi_1251_ = _e954;
                                                    break if !(_e1050);
                                                }
                                            }
                                            let _e1053 = phi_1251_;
                                            phi_1262_ = _e1053;
                                            phi_1193_ = bool();
                                            if _e1053 {
                                                break;
                                            }
                                            storageBarrier();
                                            workgroupBarrier();
                                            let _e1054 = local_28;
                                            phi_1264_ = _e1053;
                                            phi_359_ = (_e1054 / 2u);
                                        }
                                        let _e1057 = phi_1264_;
                                        let _e1059 = phi_359_;
                                        let _e1060 = local_29;
                                        phi_1263_ = _e1057;
                                        phi_222_ = _e1059;
                                        phi_361_ = select(true, false, _e1060);
                                        phi_362_ = _e962;
                                    } else {
                                        phi_1263_ = _e954;
                                        phi_222_ = u32();
                                        phi_361_ = false;
                                        phi_362_ = false;
                                    }
                                    let _e1063 = phi_1263_;
                                    let _e1065 = phi_222_;
                                    let _e1067 = phi_361_;
                                    let _e1069 = phi_362_;
                                    local_47 = _e1067;
                                    continue;
                                    continuing {
                                        let _e1070 = local_47;
                                        phi_1258_ = _e1063;
                                        phi_221_ = _e1065;
                                        phi_1262_ = _e1063;
                                        phi_1193_ = _e1069;
                                        break if !(_e1070);
                                    }
                                }
                                let _e1073 = phi_1262_;
                                let _e1075 = phi_1193_;
                                local_157 = _e1075;
                                phi_1276_ = _e1073;
                                if _e1073 {
                                    break;
                                }
                                let _e1076 = local_157;
                                if _e1076 {
                                    let _e1077 = local;
                                    let _e1078 = local_27;
                                    local_48 = (_e1077 * _e1078);
                                    phi_1272_ = _e1073;
                                    let _e1396 = local_171;
                                    phi_369_ = _e1396;
                                    loop {
                                        let _e1081 = phi_1272_;
                                        let _e1083 = phi_369_;
                                        local_49 = _e1083;
                                        let _e1084 = local_49;
                                        let _e1085 = (_e1084 > 0u);
                                        local_50 = _e1085;
                                        if _e1085 {
                                            phi_379_ = 0u;
                                            loop {
                                                let _e1087 = phi_379_;
                                                local_51 = _e1087;
                                                let _e1088 = local_27;
                                                let _e1090 = local_51;
                                                let _e1091 = (_e1090 < (_e1088 / 2u));
                                                local_52 = _e1091;
                                                if _e1091 {
                                                    let _e1092 = local_49;
                                                    let _e1093 = (_e1092 - 1u);
                                                    let _e1095 = local_51;
                                                    let _e1098 = ((_e1095 & ~(_e1093)) << bitcast<u32>(1i));
                                                    local_53 = _e1098;
                                                    let _e1099 = local_51;
                                                    let _e1100 = (_e1099 & _e1093);
                                                    local_54 = _e1100;
                                                    local_55 = (_e1098 + _e1100);
                                                    let _e1102 = local_25;
                                                    let _e1105 = local_49;
                                                    if (_e1105 == (_e1102 >> bitcast<u32>(1i))) {
                                                        let _e1112 = local_53;
                                                        let _e1113 = local_25;
                                                        let _e1116 = local_54;
                                                        let _e1118 = local_55;
                                                        phi_413_ = type_12(_e1118, (((_e1112 + _e1113) - 1u) - _e1116));
                                                    } else {
                                                        let _e1107 = local_55;
                                                        let _e1108 = local_49;
                                                        let _e1110 = local_55;
                                                        phi_413_ = type_12(_e1110, (_e1107 + _e1108));
                                                    }
                                                    let _e1121 = phi_413_;
                                                    local_56 = _e1121.member;
                                                    let _e1124 = local_48;
                                                    let _e1125 = (_e1124 + _e1121.member_1);
                                                    local_57 = _e1125;
                                                    let _e1126 = local_16;
                                                    if (_e1125 < _e1126) {
                                                        let _e1128 = local_48;
                                                        let _e1129 = local_56;
                                                        let _e1130 = (_e1128 + _e1129);
                                                        local_58 = _e1130;
                                                        let _e1131 = (_e1130 < 128u);
                                                        local_59 = _e1131;
                                                        if _e1131 {
                                                        } else {
                                                            phi_1265_ = true;
                                                            break;
                                                        }
                                                        let _e1132 = local_58;
                                                        let _e1134 = global_11[_e1132];
                                                        local_60 = _e1134;
                                                        let _e1135 = local_58;
                                                        let _e1136 = (64u + _e1135);
                                                        local_61 = _e1136;
                                                        let _e1137 = (_e1136 < 128u);
                                                        local_62 = _e1137;
                                                        if _e1137 {
                                                        } else {
                                                            phi_1265_ = true;
                                                            break;
                                                        }
                                                        let _e1138 = local_61;
                                                        let _e1140 = global_11[_e1138];
                                                        local_63 = _e1140;
                                                        let _e1141 = local_57;
                                                        let _e1142 = (_e1141 < 128u);
                                                        local_64 = _e1142;
                                                        if _e1142 {
                                                        } else {
                                                            phi_1265_ = true;
                                                            break;
                                                        }
                                                        let _e1143 = local_57;
                                                        let _e1145 = global_11[_e1143];
                                                        local_65 = _e1145;
                                                        let _e1146 = local_57;
                                                        let _e1147 = (64u + _e1146);
                                                        local_66 = _e1147;
                                                        let _e1148 = (_e1147 < 128u);
                                                        local_67 = _e1148;
                                                        if _e1148 {
                                                        } else {
                                                            phi_1265_ = true;
                                                            break;
                                                        }
                                                        let _e1149 = local_66;
                                                        let _e1151 = global_11[_e1149];
                                                        local_68 = _e1151;
                                                        let _e1152 = local_60;
                                                        let _e1153 = local_65;
                                                        if (_e1152 > _e1153) {
                                                            phi_468_ = true;
                                                        } else {
                                                            let _e1155 = local_60;
                                                            let _e1156 = local_65;
                                                            if (_e1155 == _e1156) {
                                                                let _e1158 = local_63;
                                                                let _e1159 = local_68;
                                                                phi_467_ = (_e1158 > _e1159);
                                                            } else {
                                                                phi_467_ = false;
                                                            }
                                                            let _e1162 = phi_467_;
                                                            phi_468_ = _e1162;
                                                        }
                                                        let _e1164 = phi_468_;
                                                        if _e1164 {
                                                            let _e1165 = local_59;
                                                            if _e1165 {
                                                            } else {
                                                                phi_1265_ = true;
                                                                break;
                                                            }
                                                            let _e1166 = local_65;
                                                            global_11[_e1132] = _e1166;
                                                            let _e1167 = local_62;
                                                            if _e1167 {
                                                            } else {
                                                                phi_1265_ = true;
                                                                break;
                                                            }
                                                            let _e1168 = local_68;
                                                            global_11[_e1138] = _e1168;
                                                            let _e1169 = local_64;
                                                            if _e1169 {
                                                            } else {
                                                                phi_1265_ = true;
                                                                break;
                                                            }
                                                            let _e1170 = local_60;
                                                            global_11[_e1143] = _e1170;
                                                            let _e1171 = local_67;
                                                            if _e1171 {
                                                            } else {
                                                                phi_1265_ = true;
                                                                break;
                                                            }
                                                            let _e1172 = local_63;
                                                            global_11[_e1149] = _e1172;
                                                        }
                                                    }
                                                    let _e1173 = local_51;
                                                    phi_380_ = (_e1173 + 1u);
                                                } else {
                                                    phi_380_ = u32();
                                                }
                                                let _e1176 = phi_380_;
                                                continue;
                                                continuing {
                                                    let _e1177 = local_52;
                                                    phi_379_ = _e1176;
                                                    phi_1265_ = _e1081;
                                                    break if !(_e1177);
                                                }
                                            }
                                            let _e1180 = phi_1265_;
                                            phi_1274_ = _e1180;
                                            if _e1180 {
                                                break;
                                            }
                                            let _e1181 = local_49;
                                            phi_1275_ = _e1180;
                                            phi_370_ = (_e1181 / 2u);
                                        } else {
                                            phi_1275_ = _e1081;
                                            phi_370_ = u32();
                                        }
                                        let _e1184 = phi_1275_;
                                        let _e1186 = phi_370_;
                                        continue;
                                        continuing {
                                            let _e1187 = local_50;
                                            phi_1272_ = _e1184;
                                            phi_369_ = _e1186;
                                            phi_1274_ = _e1184;
                                            break if !(_e1187);
                                        }
                                    }
                                    let _e1190 = phi_1274_;
                                    phi_1276_ = _e1190;
                                    if _e1190 {
                                        break;
                                    }
                                    storageBarrier();
                                    workgroupBarrier();
                                    phi_1278_ = _e1190;
                                } else {
                                    phi_1278_ = _e1073;
                                }
                                let _e1192 = phi_1278_;
                                let _e1193 = local_25;
                                phi_1277_ = _e1192;
                                phi_206_ = (_e1193 * 2u);
                            } else {
                                phi_1277_ = _e943;
                                phi_206_ = u32();
                            }
                            let _e1196 = phi_1277_;
                            let _e1198 = phi_206_;
                            continue;
                            continuing {
                                let _e1199 = local_26;
                                phi_1259_ = _e1196;
                                phi_205_ = _e1198;
                                phi_1276_ = _e1196;
                                break if !(_e1199);
                            }
                        }
                        let _e1202 = phi_1276_;
                        phi_1285_ = _e1202;
                        if _e1202 {
                            break;
                        }
                        phi_1282_ = _e1202;
                    } else {
                        let _e314 = local;
                        if (_e314 == 0u) {
                            phi_1207_ = _e309;
                            phi_508_ = 0u;
                            loop {
                                let _e317 = phi_1207_;
                                let _e319 = phi_508_;
                                local_69 = _e319;
                                let _e320 = local_69;
                                let _e321 = local_16;
                                let _e322 = (_e320 < _e321);
                                local_70 = _e322;
                                if _e322 {
                                    let _e323 = local_69;
                                    let _e324 = (_e323 + 16u);
                                    let _e325 = local_16;
                                    let _e327 = local_16;
                                    let _e328 = select(_e327, _e324, (_e324 < _e325));
                                    local_158 = _e328;
                                    let _e329 = local_69;
                                    phi_1205_ = _e317;
                                    phi_526_ = (_e329 + 1u);
                                    loop {
                                        let _e332 = phi_1205_;
                                        let _e334 = phi_526_;
                                        local_71 = _e334;
                                        let _e335 = local_71;
                                        let _e336 = local_158;
                                        let _e337 = (_e335 < _e336);
                                        local_72 = _e337;
                                        if _e337 {
                                            let _e338 = local_71;
                                            if (_e338 < 128u) {
                                            } else {
                                                phi_1208_ = true;
                                                break;
                                            }
                                            let _e340 = local_71;
                                            let _e342 = global_11[_e340];
                                            local_73 = _e342;
                                            let _e343 = local_71;
                                            let _e344 = (64u + _e343);
                                            local_74 = _e344;
                                            if (_e344 < 128u) {
                                            } else {
                                                phi_1208_ = true;
                                                break;
                                            }
                                            let _e346 = local_74;
                                            let _e348 = global_11[_e346];
                                            local_75 = _e348;
                                            phi_552_ = _e334;
                                            loop {
                                                let _e350 = phi_552_;
                                                local_76 = _e350;
                                                let _e351 = local_76;
                                                let _e352 = local_69;
                                                if (_e351 > _e352) {
                                                    let _e354 = local_76;
                                                    let _e355 = (_e354 - 1u);
                                                    local_77 = _e355;
                                                    if (_e355 < 128u) {
                                                    } else {
                                                        phi_1201_ = true;
                                                        break;
                                                    }
                                                    let _e357 = local_77;
                                                    let _e359 = global_11[_e357];
                                                    local_78 = _e359;
                                                    let _e360 = local_76;
                                                    let _e361 = (_e360 + 63u);
                                                    local_79 = _e361;
                                                    if (_e361 < 128u) {
                                                    } else {
                                                        phi_1201_ = true;
                                                        break;
                                                    }
                                                    let _e363 = local_79;
                                                    let _e365 = global_11[_e363];
                                                    local_80 = _e365;
                                                    let _e366 = local_78;
                                                    let _e367 = local_73;
                                                    let _e368 = (_e366 <= _e367);
                                                    local_81 = _e368;
                                                    if _e368 {
                                                    } else {
                                                        let _e369 = local_76;
                                                        if (_e369 < 128u) {
                                                        } else {
                                                            phi_1201_ = true;
                                                            break;
                                                        }
                                                        let _e371 = local_76;
                                                        let _e373 = local_78;
                                                        global_11[_e371] = _e373;
                                                        let _e374 = local_76;
                                                        let _e375 = (64u + _e374);
                                                        local_82 = _e375;
                                                        if (_e375 < 128u) {
                                                        } else {
                                                            phi_1201_ = true;
                                                            break;
                                                        }
                                                        let _e377 = local_82;
                                                        let _e379 = local_80;
                                                        global_11[_e377] = _e379;
                                                    }
                                                    let _e380 = local_81;
                                                    let _e381 = local_77;
                                                    let _e383 = local_81;
                                                    phi_553_ = select(_e381, u32(), _e380);
                                                    phi_599_ = select(true, false, _e383);
                                                } else {
                                                    phi_553_ = u32();
                                                    phi_599_ = false;
                                                }
                                                let _e386 = phi_553_;
                                                let _e388 = phi_599_;
                                                local_83 = _e388;
                                                continue;
                                                continuing {
                                                    let _e389 = local_83;
                                                    phi_552_ = _e386;
                                                    phi_1201_ = _e332;
                                                    break if !(_e389);
                                                }
                                            }
                                            let _e392 = phi_1201_;
                                            phi_1208_ = _e392;
                                            if _e392 {
                                                break;
                                            }
                                            let _e393 = local_76;
                                            if (_e393 < 128u) {
                                            } else {
                                                phi_1208_ = true;
                                                break;
                                            }
                                            let _e395 = local_76;
                                            let _e397 = local_73;
                                            global_11[_e395] = _e397;
                                            let _e398 = local_76;
                                            let _e399 = (64u + _e398);
                                            local_84 = _e399;
                                            if (_e399 < 128u) {
                                            } else {
                                                phi_1208_ = true;
                                                break;
                                            }
                                            let _e401 = local_84;
                                            let _e403 = local_75;
                                            global_11[_e401] = _e403;
                                            let _e404 = local_71;
                                            phi_1209_ = _e392;
                                            phi_527_ = (_e404 + 1u);
                                        } else {
                                            phi_1209_ = _e332;
                                            phi_527_ = u32();
                                        }
                                        let _e407 = phi_1209_;
                                        let _e409 = phi_527_;
                                        continue;
                                        continuing {
                                            let _e410 = local_72;
                                            phi_1205_ = _e407;
                                            phi_526_ = _e409;
                                            phi_1208_ = _e407;
                                            break if !(_e410);
                                        }
                                    }
                                    let _e413 = phi_1208_;
                                    phi_1210_ = _e413;
                                    if _e413 {
                                        break;
                                    }
                                    phi_1211_ = _e413;
                                    phi_509_ = _e328;
                                } else {
                                    phi_1211_ = _e317;
                                    phi_509_ = u32();
                                }
                                let _e415 = phi_1211_;
                                let _e417 = phi_509_;
                                continue;
                                continuing {
                                    let _e418 = local_70;
                                    phi_1207_ = _e415;
                                    phi_508_ = _e417;
                                    phi_1210_ = _e415;
                                    break if !(_e418);
                                }
                            }
                            let _e421 = phi_1210_;
                            phi_1285_ = _e421;
                            if _e421 {
                                break;
                            }
                            phi_1220_ = _e421;
                            phi_620_ = true;
                            phi_623_ = 16u;
                            loop {
                                let _e423 = phi_1220_;
                                let _e425 = phi_620_;
                                let _e427 = phi_623_;
                                local_85 = _e425;
                                local_86 = _e427;
                                let _e428 = local_86;
                                let _e429 = local_16;
                                let _e430 = (_e428 < _e429);
                                local_87 = _e430;
                                if _e430 {
                                    let _e431 = local_85;
                                    if _e431 {
                                        phi_1236_ = _e423;
                                        phi_635_ = 0u;
                                        loop {
                                            let _e650 = phi_1236_;
                                            let _e652 = phi_635_;
                                            local_88 = _e652;
                                            let _e653 = local_88;
                                            let _e654 = local_16;
                                            let _e655 = (_e653 < _e654);
                                            local_89 = _e655;
                                            if _e655 {
                                                let _e656 = local_88;
                                                let _e657 = local_86;
                                                let _e658 = (_e656 + _e657);
                                                let _e659 = local_16;
                                                let _e661 = local_16;
                                                let _e662 = select(_e661, _e658, (_e658 < _e659));
                                                local_161 = _e662;
                                                let _e663 = local_86;
                                                let _e664 = (_e662 + _e663);
                                                let _e665 = local_16;
                                                let _e667 = local_16;
                                                let _e668 = select(_e667, _e664, (_e664 < _e665));
                                                local_162 = _e668;
                                                phi_659_ = _e662;
                                                phi_662_ = _e652;
                                                phi_664_ = _e652;
                                                loop {
                                                    let _e670 = phi_659_;
                                                    let _e672 = phi_662_;
                                                    let _e674 = phi_664_;
                                                    local_90 = _e670;
                                                    local_91 = _e672;
                                                    local_92 = _e674;
                                                    local_167 = _e672;
                                                    local_168 = _e674;
                                                    local_169 = _e670;
                                                    let _e675 = local_91;
                                                    let _e676 = local_161;
                                                    if (_e675 < _e676) {
                                                        let _e678 = local_90;
                                                        let _e679 = local_162;
                                                        let _e680 = (_e678 < _e679);
                                                        if _e680 {
                                                            let _e681 = local_91;
                                                            if (_e681 < 128u) {
                                                            } else {
                                                                phi_1229_ = true;
                                                                break;
                                                            }
                                                            let _e683 = local_91;
                                                            let _e685 = global_11[_e683];
                                                            local_93 = _e685;
                                                            let _e686 = local_91;
                                                            let _e687 = (64u + _e686);
                                                            local_94 = _e687;
                                                            if (_e687 < 128u) {
                                                            } else {
                                                                phi_1229_ = true;
                                                                break;
                                                            }
                                                            let _e689 = local_94;
                                                            let _e691 = global_11[_e689];
                                                            local_95 = _e691;
                                                            let _e692 = local_90;
                                                            if (_e692 < 128u) {
                                                            } else {
                                                                phi_1229_ = true;
                                                                break;
                                                            }
                                                            let _e694 = local_90;
                                                            let _e696 = global_11[_e694];
                                                            local_96 = _e696;
                                                            let _e697 = local_90;
                                                            let _e698 = (64u + _e697);
                                                            local_97 = _e698;
                                                            if (_e698 < 128u) {
                                                            } else {
                                                                phi_1229_ = true;
                                                                break;
                                                            }
                                                            let _e700 = local_97;
                                                            let _e702 = global_11[_e700];
                                                            local_98 = _e702;
                                                            let _e703 = local_96;
                                                            let _e704 = local_93;
                                                            if (_e703 < _e704) {
                                                                let _e724 = local_14;
                                                                let _e725 = local_92;
                                                                let _e726 = (_e724 + _e725);
                                                                local_99 = _e726;
                                                                let _e727 = local_5;
                                                                if (_e726 < _e727) {
                                                                } else {
                                                                    phi_1229_ = true;
                                                                    break;
                                                                }
                                                                let _e729 = local_99;
                                                                let _e732 = local_96;
                                                                global_9.member[_e729] = _e732;
                                                                let _e733 = local_99;
                                                                let _e734 = local_6;
                                                                if (_e733 < _e734) {
                                                                } else {
                                                                    phi_1229_ = true;
                                                                    break;
                                                                }
                                                                let _e736 = local_99;
                                                                let _e739 = local_98;
                                                                global_10.member[_e736] = _e739;
                                                                let _e740 = local_90;
                                                                phi_742_ = (_e740 + 1u);
                                                                phi_743_ = _e672;
                                                            } else {
                                                                let _e706 = local_14;
                                                                let _e707 = local_92;
                                                                let _e708 = (_e706 + _e707);
                                                                local_100 = _e708;
                                                                let _e709 = local_5;
                                                                if (_e708 < _e709) {
                                                                } else {
                                                                    phi_1229_ = true;
                                                                    break;
                                                                }
                                                                let _e711 = local_100;
                                                                let _e714 = local_93;
                                                                global_9.member[_e711] = _e714;
                                                                let _e715 = local_100;
                                                                let _e716 = local_6;
                                                                if (_e715 < _e716) {
                                                                } else {
                                                                    phi_1229_ = true;
                                                                    break;
                                                                }
                                                                let _e718 = local_100;
                                                                let _e721 = local_95;
                                                                global_10.member[_e718] = _e721;
                                                                let _e722 = local_91;
                                                                phi_742_ = _e670;
                                                                phi_743_ = (_e722 + 1u);
                                                            }
                                                            let _e743 = phi_742_;
                                                            let _e745 = phi_743_;
                                                            let _e746 = local_92;
                                                            phi_745_ = _e743;
                                                            phi_746_ = _e745;
                                                            phi_747_ = (_e746 + 1u);
                                                        } else {
                                                            phi_745_ = u32();
                                                            phi_746_ = u32();
                                                            phi_747_ = u32();
                                                        }
                                                        let _e749 = phi_745_;
                                                        let _e751 = phi_746_;
                                                        let _e753 = phi_747_;
                                                        phi_660_ = _e749;
                                                        phi_663_ = _e751;
                                                        phi_665_ = _e753;
                                                        phi_748_ = _e680;
                                                    } else {
                                                        phi_660_ = u32();
                                                        phi_663_ = u32();
                                                        phi_665_ = u32();
                                                        phi_748_ = false;
                                                    }
                                                    let _e755 = phi_660_;
                                                    let _e757 = phi_663_;
                                                    let _e759 = phi_665_;
                                                    let _e761 = phi_748_;
                                                    local_101 = _e761;
                                                    continue;
                                                    continuing {
                                                        let _e762 = local_101;
                                                        phi_659_ = _e755;
                                                        phi_662_ = _e757;
                                                        phi_664_ = _e759;
                                                        phi_1229_ = _e650;
                                                        break if !(_e762);
                                                    }
                                                }
                                                let _e765 = phi_1229_;
                                                phi_1243_ = _e765;
                                                if _e765 {
                                                    break;
                                                }
                                                let _e1345 = local_167;
                                                phi_754_ = _e1345;
                                                let _e1348 = local_168;
                                                phi_757_ = _e1348;
                                                loop {
                                                    let _e767 = phi_754_;
                                                    let _e769 = phi_757_;
                                                    local_102 = _e767;
                                                    local_103 = _e769;
                                                    local_170 = _e769;
                                                    let _e770 = local_102;
                                                    let _e771 = local_161;
                                                    let _e772 = (_e770 < _e771);
                                                    local_104 = _e772;
                                                    if _e772 {
                                                        let _e773 = local_102;
                                                        if (_e773 < 128u) {
                                                        } else {
                                                            phi_1237_ = true;
                                                            break;
                                                        }
                                                        let _e775 = local_102;
                                                        let _e777 = global_11[_e775];
                                                        local_105 = _e777;
                                                        let _e778 = local_102;
                                                        let _e779 = (64u + _e778);
                                                        local_106 = _e779;
                                                        if (_e779 < 128u) {
                                                        } else {
                                                            phi_1237_ = true;
                                                            break;
                                                        }
                                                        let _e781 = local_106;
                                                        let _e783 = global_11[_e781];
                                                        local_107 = _e783;
                                                        let _e784 = local_14;
                                                        let _e785 = local_103;
                                                        let _e786 = (_e784 + _e785);
                                                        local_108 = _e786;
                                                        let _e787 = local_5;
                                                        if (_e786 < _e787) {
                                                        } else {
                                                            phi_1237_ = true;
                                                            break;
                                                        }
                                                        let _e789 = local_108;
                                                        let _e792 = local_105;
                                                        global_9.member[_e789] = _e792;
                                                        let _e793 = local_108;
                                                        let _e794 = local_6;
                                                        if (_e793 < _e794) {
                                                        } else {
                                                            phi_1237_ = true;
                                                            break;
                                                        }
                                                        let _e796 = local_108;
                                                        let _e799 = local_107;
                                                        global_10.member[_e796] = _e799;
                                                        let _e800 = local_102;
                                                        let _e802 = local_103;
                                                        phi_755_ = (_e800 + 1u);
                                                        phi_758_ = (_e802 + 1u);
                                                    } else {
                                                        phi_755_ = u32();
                                                        phi_758_ = u32();
                                                    }
                                                    let _e805 = phi_755_;
                                                    let _e807 = phi_758_;
                                                    continue;
                                                    continuing {
                                                        let _e808 = local_104;
                                                        phi_754_ = _e805;
                                                        phi_757_ = _e807;
                                                        phi_1237_ = _e765;
                                                        break if !(_e808);
                                                    }
                                                }
                                                let _e811 = phi_1237_;
                                                phi_1243_ = _e811;
                                                if _e811 {
                                                    break;
                                                }
                                                let _e1354 = local_169;
                                                phi_798_ = _e1354;
                                                let _e1357 = local_170;
                                                phi_801_ = _e1357;
                                                loop {
                                                    let _e813 = phi_798_;
                                                    let _e815 = phi_801_;
                                                    local_109 = _e813;
                                                    local_110 = _e815;
                                                    let _e816 = local_109;
                                                    let _e817 = local_162;
                                                    let _e818 = (_e816 < _e817);
                                                    local_111 = _e818;
                                                    if _e818 {
                                                        let _e819 = local_109;
                                                        if (_e819 < 128u) {
                                                        } else {
                                                            phi_1240_ = true;
                                                            break;
                                                        }
                                                        let _e821 = local_109;
                                                        let _e823 = global_11[_e821];
                                                        local_112 = _e823;
                                                        let _e824 = local_109;
                                                        let _e825 = (64u + _e824);
                                                        local_113 = _e825;
                                                        if (_e825 < 128u) {
                                                        } else {
                                                            phi_1240_ = true;
                                                            break;
                                                        }
                                                        let _e827 = local_113;
                                                        let _e829 = global_11[_e827];
                                                        local_114 = _e829;
                                                        let _e830 = local_14;
                                                        let _e831 = local_110;
                                                        let _e832 = (_e830 + _e831);
                                                        local_115 = _e832;
                                                        let _e833 = local_5;
                                                        if (_e832 < _e833) {
                                                        } else {
                                                            phi_1240_ = true;
                                                            break;
                                                        }
                                                        let _e835 = local_115;
                                                        let _e838 = local_112;
                                                        global_9.member[_e835] = _e838;
                                                        let _e839 = local_115;
                                                        let _e840 = local_6;
                                                        if (_e839 < _e840) {
                                                        } else {
                                                            phi_1240_ = true;
                                                            break;
                                                        }
                                                        let _e842 = local_115;
                                                        let _e845 = local_114;
                                                        global_10.member[_e842] = _e845;
                                                        let _e846 = local_109;
                                                        let _e848 = local_110;
                                                        phi_799_ = (_e846 + 1u);
                                                        phi_802_ = (_e848 + 1u);
                                                    } else {
                                                        phi_799_ = u32();
                                                        phi_802_ = u32();
                                                    }
                                                    let _e851 = phi_799_;
                                                    let _e853 = phi_802_;
                                                    continue;
                                                    continuing {
                                                        let _e854 = local_111;
                                                        phi_798_ = _e851;
                                                        phi_801_ = _e853;
                                                        phi_1240_ = _e811;
                                                        break if !(_e854);
                                                    }
                                                }
                                                let _e857 = phi_1240_;
                                                phi_1243_ = _e857;
                                                if _e857 {
                                                    break;
                                                }
                                                phi_1244_ = _e857;
                                                phi_636_ = _e668;
                                            } else {
                                                phi_1244_ = _e650;
                                                phi_636_ = u32();
                                            }
                                            let _e859 = phi_1244_;
                                            let _e861 = phi_636_;
                                            continue;
                                            continuing {
                                                let _e862 = local_89;
                                                phi_1236_ = _e859;
                                                phi_635_ = _e861;
                                                phi_1243_ = _e859;
                                                break if !(_e862);
                                            }
                                        }
                                        let _e865 = phi_1243_;
                                        phi_1245_ = _e865;
                                        if _e865 {
                                            break;
                                        }
                                        phi_1247_ = _e865;
                                    } else {
                                        phi_1219_ = _e423;
                                        phi_842_ = 0u;
                                        loop {
                                            let _e433 = phi_1219_;
                                            let _e435 = phi_842_;
                                            local_116 = _e435;
                                            let _e436 = local_116;
                                            let _e437 = local_16;
                                            let _e438 = (_e436 < _e437);
                                            local_117 = _e438;
                                            if _e438 {
                                                let _e439 = local_116;
                                                let _e440 = local_86;
                                                let _e441 = (_e439 + _e440);
                                                let _e442 = local_16;
                                                let _e444 = local_16;
                                                let _e445 = select(_e444, _e441, (_e441 < _e442));
                                                local_159 = _e445;
                                                let _e446 = local_86;
                                                let _e447 = (_e445 + _e446);
                                                let _e448 = local_16;
                                                let _e450 = local_16;
                                                let _e451 = select(_e450, _e447, (_e447 < _e448));
                                                local_160 = _e451;
                                                phi_866_ = _e445;
                                                phi_869_ = _e435;
                                                phi_871_ = _e435;
                                                loop {
                                                    let _e453 = phi_866_;
                                                    let _e455 = phi_869_;
                                                    let _e457 = phi_871_;
                                                    local_118 = _e453;
                                                    local_119 = _e455;
                                                    local_120 = _e457;
                                                    local_163 = _e455;
                                                    local_164 = _e457;
                                                    local_165 = _e453;
                                                    let _e458 = local_119;
                                                    let _e459 = local_159;
                                                    if (_e458 < _e459) {
                                                        let _e461 = local_118;
                                                        let _e462 = local_160;
                                                        let _e463 = (_e461 < _e462);
                                                        if _e463 {
                                                            let _e464 = local_14;
                                                            let _e465 = local_119;
                                                            let _e466 = (_e464 + _e465);
                                                            local_121 = _e466;
                                                            let _e467 = local_5;
                                                            if (_e466 < _e467) {
                                                            } else {
                                                                phi_1212_ = true;
                                                                break;
                                                            }
                                                            let _e469 = local_121;
                                                            let _e472 = global_9.member[_e469];
                                                            local_122 = _e472;
                                                            let _e473 = local_121;
                                                            let _e474 = local_6;
                                                            if (_e473 < _e474) {
                                                            } else {
                                                                phi_1212_ = true;
                                                                break;
                                                            }
                                                            let _e476 = local_121;
                                                            let _e479 = global_10.member[_e476];
                                                            local_123 = _e479;
                                                            let _e480 = local_14;
                                                            let _e481 = local_118;
                                                            let _e482 = (_e480 + _e481);
                                                            local_124 = _e482;
                                                            let _e483 = local_5;
                                                            if (_e482 < _e483) {
                                                            } else {
                                                                phi_1212_ = true;
                                                                break;
                                                            }
                                                            let _e485 = local_124;
                                                            let _e488 = global_9.member[_e485];
                                                            local_125 = _e488;
                                                            let _e489 = local_124;
                                                            let _e490 = local_6;
                                                            if (_e489 < _e490) {
                                                            } else {
                                                                phi_1212_ = true;
                                                                break;
                                                            }
                                                            let _e492 = local_124;
                                                            let _e495 = global_10.member[_e492];
                                                            local_126 = _e495;
                                                            let _e496 = local_125;
                                                            let _e497 = local_122;
                                                            if (_e496 < _e497) {
                                                                let _e512 = local_120;
                                                                if (_e512 < 128u) {
                                                                } else {
                                                                    phi_1212_ = true;
                                                                    break;
                                                                }
                                                                let _e514 = local_120;
                                                                let _e516 = local_125;
                                                                global_11[_e514] = _e516;
                                                                let _e517 = local_120;
                                                                let _e518 = (64u + _e517);
                                                                local_127 = _e518;
                                                                if (_e518 < 128u) {
                                                                } else {
                                                                    phi_1212_ = true;
                                                                    break;
                                                                }
                                                                let _e520 = local_127;
                                                                let _e522 = local_126;
                                                                global_11[_e520] = _e522;
                                                                let _e523 = local_118;
                                                                phi_949_ = (_e523 + 1u);
                                                                phi_950_ = _e455;
                                                            } else {
                                                                let _e499 = local_120;
                                                                if (_e499 < 128u) {
                                                                } else {
                                                                    phi_1212_ = true;
                                                                    break;
                                                                }
                                                                let _e501 = local_120;
                                                                let _e503 = local_122;
                                                                global_11[_e501] = _e503;
                                                                let _e504 = local_120;
                                                                let _e505 = (64u + _e504);
                                                                local_128 = _e505;
                                                                if (_e505 < 128u) {
                                                                } else {
                                                                    phi_1212_ = true;
                                                                    break;
                                                                }
                                                                let _e507 = local_128;
                                                                let _e509 = local_123;
                                                                global_11[_e507] = _e509;
                                                                let _e510 = local_119;
                                                                phi_949_ = _e453;
                                                                phi_950_ = (_e510 + 1u);
                                                            }
                                                            let _e526 = phi_949_;
                                                            let _e528 = phi_950_;
                                                            let _e529 = local_120;
                                                            phi_952_ = _e526;
                                                            phi_953_ = _e528;
                                                            phi_954_ = (_e529 + 1u);
                                                        } else {
                                                            phi_952_ = u32();
                                                            phi_953_ = u32();
                                                            phi_954_ = u32();
                                                        }
                                                        let _e532 = phi_952_;
                                                        let _e534 = phi_953_;
                                                        let _e536 = phi_954_;
                                                        phi_867_ = _e532;
                                                        phi_870_ = _e534;
                                                        phi_872_ = _e536;
                                                        phi_955_ = _e463;
                                                    } else {
                                                        phi_867_ = u32();
                                                        phi_870_ = u32();
                                                        phi_872_ = u32();
                                                        phi_955_ = false;
                                                    }
                                                    let _e538 = phi_867_;
                                                    let _e540 = phi_870_;
                                                    let _e542 = phi_872_;
                                                    let _e544 = phi_955_;
                                                    local_129 = _e544;
                                                    continue;
                                                    continuing {
                                                        let _e545 = local_129;
                                                        phi_866_ = _e538;
                                                        phi_869_ = _e540;
                                                        phi_871_ = _e542;
                                                        phi_1212_ = _e433;
                                                        break if !(_e545);
                                                    }
                                                }
                                                let _e548 = phi_1212_;
                                                phi_1227_ = _e548;
                                                if _e548 {
                                                    break;
                                                }
                                                let _e1309 = local_163;
                                                phi_961_ = _e1309;
                                                let _e1312 = local_164;
                                                phi_964_ = _e1312;
                                                loop {
                                                    let _e550 = phi_961_;
                                                    let _e552 = phi_964_;
                                                    local_130 = _e550;
                                                    local_131 = _e552;
                                                    local_166 = _e552;
                                                    let _e553 = local_130;
                                                    let _e554 = local_159;
                                                    let _e555 = (_e553 < _e554);
                                                    local_132 = _e555;
                                                    if _e555 {
                                                        let _e556 = local_14;
                                                        let _e557 = local_130;
                                                        let _e558 = (_e556 + _e557);
                                                        local_133 = _e558;
                                                        let _e559 = local_5;
                                                        if (_e558 < _e559) {
                                                        } else {
                                                            phi_1221_ = true;
                                                            break;
                                                        }
                                                        let _e561 = local_133;
                                                        let _e564 = global_9.member[_e561];
                                                        local_134 = _e564;
                                                        let _e565 = local_133;
                                                        let _e566 = local_6;
                                                        if (_e565 < _e566) {
                                                        } else {
                                                            phi_1221_ = true;
                                                            break;
                                                        }
                                                        let _e568 = local_133;
                                                        let _e571 = global_10.member[_e568];
                                                        local_135 = _e571;
                                                        let _e572 = local_131;
                                                        if (_e572 < 128u) {
                                                        } else {
                                                            phi_1221_ = true;
                                                            break;
                                                        }
                                                        let _e574 = local_131;
                                                        let _e576 = local_134;
                                                        global_11[_e574] = _e576;
                                                        let _e577 = local_131;
                                                        let _e578 = (64u + _e577);
                                                        local_136 = _e578;
                                                        if (_e578 < 128u) {
                                                        } else {
                                                            phi_1221_ = true;
                                                            break;
                                                        }
                                                        let _e580 = local_136;
                                                        let _e582 = local_135;
                                                        global_11[_e580] = _e582;
                                                        let _e583 = local_130;
                                                        let _e585 = local_131;
                                                        phi_962_ = (_e583 + 1u);
                                                        phi_965_ = (_e585 + 1u);
                                                    } else {
                                                        phi_962_ = u32();
                                                        phi_965_ = u32();
                                                    }
                                                    let _e588 = phi_962_;
                                                    let _e590 = phi_965_;
                                                    continue;
                                                    continuing {
                                                        let _e591 = local_132;
                                                        phi_961_ = _e588;
                                                        phi_964_ = _e590;
                                                        phi_1221_ = _e548;
                                                        break if !(_e591);
                                                    }
                                                }
                                                let _e594 = phi_1221_;
                                                phi_1227_ = _e594;
                                                if _e594 {
                                                    break;
                                                }
                                                let _e1318 = local_165;
                                                phi_1005_ = _e1318;
                                                let _e1321 = local_166;
                                                phi_1008_ = _e1321;
                                                loop {
                                                    let _e596 = phi_1005_;
                                                    let _e598 = phi_1008_;
                                                    local_137 = _e596;
                                                    local_138 = _e598;
                                                    let _e599 = local_137;
                                                    let _e600 = local_160;
                                                    let _e601 = (_e599 < _e600);
                                                    local_139 = _e601;
                                                    if _e601 {
                                                        let _e602 = local_14;
                                                        let _e603 = local_137;
                                                        let _e604 = (_e602 + _e603);
                                                        local_140 = _e604;
                                                        let _e605 = local_5;
                                                        if (_e604 < _e605) {
                                                        } else {
                                                            phi_1224_ = true;
                                                            break;
                                                        }
                                                        let _e607 = local_140;
                                                        let _e610 = global_9.member[_e607];
                                                        local_141 = _e610;
                                                        let _e611 = local_140;
                                                        let _e612 = local_6;
                                                        if (_e611 < _e612) {
                                                        } else {
                                                            phi_1224_ = true;
                                                            break;
                                                        }
                                                        let _e614 = local_140;
                                                        let _e617 = global_10.member[_e614];
                                                        local_142 = _e617;
                                                        let _e618 = local_138;
                                                        if (_e618 < 128u) {
                                                        } else {
                                                            phi_1224_ = true;
                                                            break;
                                                        }
                                                        let _e620 = local_138;
                                                        let _e622 = local_141;
                                                        global_11[_e620] = _e622;
                                                        let _e623 = local_138;
                                                        let _e624 = (64u + _e623);
                                                        local_143 = _e624;
                                                        if (_e624 < 128u) {
                                                        } else {
                                                            phi_1224_ = true;
                                                            break;
                                                        }
                                                        let _e626 = local_143;
                                                        let _e628 = local_142;
                                                        global_11[_e626] = _e628;
                                                        let _e629 = local_137;
                                                        let _e631 = local_138;
                                                        phi_1006_ = (_e629 + 1u);
                                                        phi_1009_ = (_e631 + 1u);
                                                    } else {
                                                        phi_1006_ = u32();
                                                        phi_1009_ = u32();
                                                    }
                                                    let _e634 = phi_1006_;
                                                    let _e636 = phi_1009_;
                                                    continue;
                                                    continuing {
                                                        let _e637 = local_139;
                                                        phi_1005_ = _e634;
                                                        phi_1008_ = _e636;
                                                        phi_1224_ = _e594;
                                                        break if !(_e637);
                                                    }
                                                }
                                                let _e640 = phi_1224_;
                                                phi_1227_ = _e640;
                                                if _e640 {
                                                    break;
                                                }
                                                phi_1228_ = _e640;
                                                phi_843_ = _e451;
                                            } else {
                                                phi_1228_ = _e433;
                                                phi_843_ = u32();
                                            }
                                            let _e642 = phi_1228_;
                                            let _e644 = phi_843_;
                                            continue;
                                            continuing {
                                                let _e645 = local_117;
                                                phi_1219_ = _e642;
                                                phi_842_ = _e644;
                                                phi_1227_ = _e642;
                                                break if !(_e645);
                                            }
                                        }
                                        let _e648 = phi_1227_;
                                        phi_1245_ = _e648;
                                        if _e648 {
                                            break;
                                        }
                                        phi_1247_ = _e648;
                                    }
                                    let _e867 = phi_1247_;
                                    let _e868 = local_85;
                                    let _e870 = local_86;
                                    phi_1246_ = _e867;
                                    phi_621_ = !(_e868);
                                    phi_624_ = (_e870 * 2u);
                                } else {
                                    phi_1246_ = _e423;
                                    phi_621_ = bool();
                                    phi_624_ = u32();
                                }
                                let _e873 = phi_1246_;
                                let _e875 = phi_621_;
                                let _e877 = phi_624_;
                                continue;
                                continuing {
                                    let _e878 = local_87;
                                    phi_1220_ = _e873;
                                    phi_620_ = _e875;
                                    phi_623_ = _e877;
                                    phi_1245_ = _e873;
                                    break if !(_e878);
                                }
                            }
                            let _e881 = phi_1245_;
                            phi_1285_ = _e881;
                            if _e881 {
                                break;
                            }
                            let _e882 = local_85;
                            if _e882 {
                                phi_1284_ = _e881;
                            } else {
                                phi_1054_ = 0u;
                                loop {
                                    let _e884 = phi_1054_;
                                    local_144 = _e884;
                                    let _e885 = local_144;
                                    let _e886 = local_16;
                                    let _e887 = (_e885 < _e886);
                                    local_145 = _e887;
                                    if _e887 {
                                        let _e888 = local_14;
                                        let _e889 = local_144;
                                        let _e890 = (_e888 + _e889);
                                        local_146 = _e890;
                                        let _e891 = local_5;
                                        if (_e890 < _e891) {
                                        } else {
                                            phi_1248_ = true;
                                            break;
                                        }
                                        let _e893 = local_146;
                                        let _e896 = global_9.member[_e893];
                                        local_147 = _e896;
                                        let _e897 = local_146;
                                        let _e898 = local_6;
                                        if (_e897 < _e898) {
                                        } else {
                                            phi_1248_ = true;
                                            break;
                                        }
                                        let _e900 = local_146;
                                        let _e903 = global_10.member[_e900];
                                        local_148 = _e903;
                                        let _e904 = local_144;
                                        if (_e904 < 128u) {
                                        } else {
                                            phi_1248_ = true;
                                            break;
                                        }
                                        let _e906 = local_144;
                                        let _e908 = local_147;
                                        global_11[_e906] = _e908;
                                        let _e909 = local_144;
                                        let _e910 = (64u + _e909);
                                        local_149 = _e910;
                                        if (_e910 < 128u) {
                                        } else {
                                            phi_1248_ = true;
                                            break;
                                        }
                                        let _e912 = local_149;
                                        let _e914 = local_148;
                                        global_11[_e912] = _e914;
                                        let _e915 = local_144;
                                        phi_1055_ = (_e915 + 1u);
                                    } else {
                                        phi_1055_ = u32();
                                    }
                                    let _e918 = phi_1055_;
                                    continue;
                                    continuing {
                                        let _e919 = local_145;
                                        phi_1054_ = _e918;
                                        phi_1248_ = _e881;
                                        break if !(_e919);
                                    }
                                }
                                let _e922 = phi_1248_;
                                phi_1285_ = _e922;
                                if _e922 {
                                    break;
                                }
                                phi_1284_ = _e922;
                            }
                            let _e924 = phi_1284_;
                            phi_1283_ = _e924;
                        } else {
                            phi_1283_ = _e309;
                        }
                        let _e926 = phi_1283_;
                        storageBarrier();
                        workgroupBarrier();
                        phi_1282_ = _e926;
                    }
                    let _e1204 = phi_1282_;
                    phi_1095_ = _e198;
                    loop {
                        let _e1206 = phi_1095_;
                        local_150 = _e1206;
                        let _e1207 = local_150;
                        let _e1208 = local_16;
                        let _e1209 = (_e1207 < _e1208);
                        local_151 = _e1209;
                        if _e1209 {
                            let _e1210 = local_150;
                            let _e1211 = (64u + _e1210);
                            local_152 = _e1211;
                            if (_e1211 < 128u) {
                            } else {
                                phi_1279_ = true;
                                break;
                            }
                            let _e1213 = local_152;
                            let _e1215 = global_11[_e1213];
                            let _e1216 = local_14;
                            let _e1217 = (_e1216 + _e1215);
                            local_153 = _e1217;
                            let _e1218 = local_14;
                            let _e1219 = local_150;
                            local_154 = (_e1218 + _e1219);
                            let _e1221 = local_3;
                            if (_e1217 < _e1221) {
                            } else {
                                phi_1279_ = true;
                                break;
                            }
                            let _e1223 = local_153;
                            let _e1226 = global_7.member[_e1223];
                            local_155 = _e1226;
                            let _e1227 = local_154;
                            let _e1228 = local_5;
                            if (_e1227 < _e1228) {
                            } else {
                                phi_1279_ = true;
                                break;
                            }
                            let _e1230 = local_154;
                            let _e1233 = local_155;
                            global_9.member[_e1230] = _e1233;
                            let _e1234 = local_153;
                            let _e1235 = local_4;
                            if (_e1234 < _e1235) {
                            } else {
                                phi_1279_ = true;
                                break;
                            }
                            let _e1237 = local_153;
                            let _e1240 = global_8.member[_e1237];
                            local_156 = _e1240;
                            let _e1241 = local_154;
                            let _e1242 = local_6;
                            if (_e1241 < _e1242) {
                            } else {
                                phi_1279_ = true;
                                break;
                            }
                            let _e1244 = local_154;
                            let _e1247 = local_156;
                            global_10.member[_e1244] = _e1247;
                            let _e1248 = local_150;
                            phi_1096_ = (_e1248 + 32u);
                        } else {
                            phi_1096_ = u32();
                        }
                        let _e1251 = phi_1096_;
                        continue;
                        continuing {
                            let _e1252 = local_151;
                            phi_1095_ = _e1251;
                            phi_1279_ = _e1204;
                            break if !(_e1252);
                        }
                    }
                    let _e1255 = phi_1279_;
                    phi_1285_ = _e1255;
                    if _e1255 {
                        break;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e1256 = local_10;
                    let _e1257 = local_7;
                    phi_1286_ = _e1255;
                    phi_96_ = (_e1256 + _e1257);
                } else {
                    phi_1286_ = _e226;
                    phi_96_ = u32();
                }
                let _e1260 = phi_1286_;
                let _e1262 = phi_96_;
                continue;
                continuing {
                    let _e1263 = local_11;
                    phi_1198_ = _e1260;
                    phi_95_ = _e1262;
                    phi_1285_ = _e1260;
                    break if !(_e1263);
                }
            }
            let _e1266 = phi_1285_;
            if _e1266 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(32, 1, 1) 
fn sort_shared_64_(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
