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
var<workgroup> global_11: array<u32, 8192>;

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
    var phi_1199_: bool;
    var phi_96_: u32;
    var phi_136_: u32;
    var phi_169_: u32;
    var phi_170_: u32;
    var phi_171_: u32;
    var phi_137_: u32;
    var phi_1195_: bool;
    var phi_1208_: bool;
    var phi_509_: u32;
    var phi_1206_: bool;
    var phi_527_: u32;
    var phi_553_: u32;
    var phi_554_: u32;
    var phi_600_: bool;
    var phi_1202_: bool;
    var phi_1210_: bool;
    var phi_528_: u32;
    var phi_1209_: bool;
    var phi_1212_: bool;
    var phi_510_: u32;
    var phi_1211_: bool;
    var phi_1221_: bool;
    var phi_621_: bool;
    var phi_624_: u32;
    var phi_1220_: bool;
    var phi_843_: u32;
    var phi_867_: u32;
    var phi_870_: u32;
    var phi_872_: u32;
    var phi_950_: u32;
    var phi_951_: u32;
    var phi_953_: u32;
    var phi_954_: u32;
    var phi_955_: u32;
    var phi_868_: u32;
    var phi_871_: u32;
    var phi_873_: u32;
    var phi_956_: bool;
    var phi_1213_: bool;
    var phi_962_: u32;
    var phi_965_: u32;
    var phi_963_: u32;
    var phi_966_: u32;
    var phi_1222_: bool;
    var phi_1006_: u32;
    var phi_1009_: u32;
    var phi_1007_: u32;
    var phi_1010_: u32;
    var phi_1225_: bool;
    var phi_1229_: bool;
    var phi_844_: u32;
    var phi_1228_: bool;
    var phi_1237_: bool;
    var phi_636_: u32;
    var phi_660_: u32;
    var phi_663_: u32;
    var phi_665_: u32;
    var phi_743_: u32;
    var phi_744_: u32;
    var phi_746_: u32;
    var phi_747_: u32;
    var phi_748_: u32;
    var phi_661_: u32;
    var phi_664_: u32;
    var phi_666_: u32;
    var phi_749_: bool;
    var phi_1230_: bool;
    var phi_755_: u32;
    var phi_758_: u32;
    var phi_756_: u32;
    var phi_759_: u32;
    var phi_1238_: bool;
    var phi_799_: u32;
    var phi_802_: u32;
    var phi_800_: u32;
    var phi_803_: u32;
    var phi_1241_: bool;
    var phi_1245_: bool;
    var phi_637_: u32;
    var phi_1244_: bool;
    var phi_1248_: bool;
    var phi_1247_: bool;
    var phi_622_: bool;
    var phi_625_: u32;
    var phi_1246_: bool;
    var phi_1055_: u32;
    var phi_1056_: u32;
    var phi_1249_: bool;
    var phi_1285_: bool;
    var phi_1284_: bool;
    var phi_204_: u32;
    var phi_1260_: bool;
    var phi_206_: u32;
    var phi_1259_: bool;
    var phi_222_: u32;
    var phi_237_: u32;
    var phi_271_: type_12;
    var phi_325_: bool;
    var phi_326_: bool;
    var phi_238_: u32;
    var phi_1252_: bool;
    var phi_1265_: bool;
    var phi_360_: u32;
    var phi_1264_: bool;
    var phi_223_: u32;
    var phi_362_: bool;
    var phi_363_: bool;
    var phi_1263_: bool;
    var phi_1194_: bool;
    var phi_1273_: bool;
    var phi_370_: u32;
    var phi_380_: u32;
    var phi_414_: type_12;
    var phi_468_: bool;
    var phi_469_: bool;
    var phi_381_: u32;
    var phi_1266_: bool;
    var phi_1276_: bool;
    var phi_371_: u32;
    var phi_1275_: bool;
    var phi_1279_: bool;
    var phi_1278_: bool;
    var phi_207_: u32;
    var phi_1277_: bool;
    var phi_1283_: bool;
    var phi_1096_: u32;
    var phi_1097_: u32;
    var phi_1280_: bool;
    var phi_1287_: bool;
    var phi_97_: u32;
    var phi_1286_: bool;
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
            let _e199 = global;
            local = _e199;
            let _e200 = global_1;
            let _e201 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = arrayLength((&global_7.member));
            local_4 = arrayLength((&global_8.member));
            local_5 = arrayLength((&global_9.member));
            local_6 = arrayLength((&global_10.member));
            local_7 = _e201.x;
            let _e220 = global_4.member.member_1;
            local_8 = _e220;
            if (_e220 < arrayLength((&global_5.member))) {
            } else {
                break;
            }
            let _e222 = local_8;
            let _e225 = global_5.member[_e222];
            local_9 = _e225;
            phi_1199_ = false;
            phi_96_ = _e200.x;
            loop {
                let _e227 = phi_1199_;
                let _e229 = phi_96_;
                local_10 = _e229;
                let _e230 = local_10;
                let _e231 = local_9;
                let _e232 = (_e230 < _e231);
                local_11 = _e232;
                if _e232 {
                    let _e235 = global_4.member.member;
                    let _e236 = local_8;
                    let _e238 = local_10;
                    let _e239 = ((_e236 * _e235) + _e238);
                    local_12 = _e239;
                    let _e240 = local_2;
                    if (_e239 < _e240) {
                    } else {
                        phi_1286_ = true;
                        break;
                    }
                    let _e242 = local_12;
                    let _e245 = global_6.member[_e242];
                    let _e246 = (2u * _e245);
                    local_13 = _e246;
                    let _e247 = local_1;
                    if (_e246 < _e247) {
                    } else {
                        phi_1286_ = true;
                        break;
                    }
                    let _e249 = local_13;
                    let _e252 = global_3.member[_e249];
                    local_14 = _e252;
                    let _e253 = local_13;
                    let _e254 = (_e253 + 1u);
                    local_15 = _e254;
                    let _e255 = local_1;
                    if (_e254 < _e255) {
                    } else {
                        phi_1286_ = true;
                        break;
                    }
                    let _e257 = local_15;
                    let _e260 = global_3.member[_e257];
                    local_16 = _e260;
                    phi_136_ = _e199;
                    loop {
                        let _e262 = phi_136_;
                        local_17 = _e262;
                        let _e263 = local_17;
                        let _e264 = local_16;
                        let _e265 = (_e263 < _e264);
                        local_18 = _e265;
                        if _e265 {
                            let _e266 = local_14;
                            let _e267 = local_17;
                            let _e268 = (_e266 + _e267);
                            local_19 = _e268;
                            let _e269 = local_3;
                            if (_e268 < _e269) {
                            } else {
                                phi_1195_ = true;
                                break;
                            }
                            let _e271 = local_19;
                            let _e274 = global_7.member[_e271];
                            local_20 = _e274;
                            let _e275 = (_e274 & 2147483647u);
                            local_21 = _e275;
                            if (_e275 > 2139095040u) {
                                phi_171_ = 4294967295u;
                            } else {
                                let _e277 = local_21;
                                if (_e277 == 0u) {
                                    phi_170_ = 2147483648u;
                                } else {
                                    let _e279 = local_20;
                                    if ((_e279 & 2147483648u) == 0u) {
                                        let _e284 = local_20;
                                        phi_169_ = (_e284 | 2147483648u);
                                    } else {
                                        let _e282 = local_20;
                                        phi_169_ = ~(_e282);
                                    }
                                    let _e287 = phi_169_;
                                    phi_170_ = _e287;
                                }
                                let _e289 = phi_170_;
                                phi_171_ = _e289;
                            }
                            let _e291 = phi_171_;
                            local_22 = _e291;
                            let _e292 = local_17;
                            if (_e292 < 8192u) {
                            } else {
                                phi_1195_ = true;
                                break;
                            }
                            let _e294 = local_17;
                            let _e296 = local_22;
                            global_11[_e294] = _e296;
                            let _e297 = local_17;
                            let _e298 = (4096u + _e297);
                            local_23 = _e298;
                            if (_e298 < 8192u) {
                            } else {
                                phi_1195_ = true;
                                break;
                            }
                            let _e300 = local_23;
                            let _e302 = local_17;
                            global_11[_e300] = _e302;
                            let _e303 = local_17;
                            phi_137_ = (_e303 + 256u);
                        } else {
                            phi_137_ = u32();
                        }
                        let _e306 = phi_137_;
                        continue;
                        continuing {
                            let _e307 = local_18;
                            phi_136_ = _e306;
                            phi_1195_ = _e227;
                            break if !(_e307);
                        }
                    }
                    let _e310 = phi_1195_;
                    phi_1286_ = _e310;
                    if _e310 {
                        break;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e313 = global_4.member.member_4;
                    if (_e313 == 0u) {
                        let _e928 = local_16;
                        if (_e928 <= 1u) {
                            phi_204_ = 1u;
                        } else {
                            let _e930 = local_16;
                            let _e931 = (_e930 - 1u);
                            phi_204_ = (1u << bitcast<u32>(((32u - select((bitcast<u32>(31i) - firstLeadingBit(_e931)), 32u, (_e931 == 0u))) & 31u)));
                        }
                        let _e942 = phi_204_;
                        local_24 = _e942;
                        phi_1260_ = _e310;
                        phi_206_ = 2u;
                        loop {
                            let _e944 = phi_1260_;
                            let _e946 = phi_206_;
                            local_25 = _e946;
                            let _e947 = local_25;
                            let _e948 = local_24;
                            let _e949 = (_e947 <= _e948);
                            local_26 = _e949;
                            if _e949 {
                                let _e950 = local_25;
                                let _e952 = local_24;
                                local_27 = (_e952 / 256u);
                                phi_1259_ = _e944;
                                phi_222_ = (_e950 / 2u);
                                loop {
                                    let _e955 = phi_1259_;
                                    let _e957 = phi_222_;
                                    local_28 = _e957;
                                    local_171 = _e957;
                                    let _e958 = local_28;
                                    if (_e958 > 0u) {
                                        let _e960 = local_28;
                                        let _e962 = local_27;
                                        let _e963 = ((2u * _e960) <= _e962);
                                        local_29 = _e963;
                                        if _e963 {
                                            phi_1265_ = _e955;
                                            phi_360_ = u32();
                                        } else {
                                            phi_237_ = _e199;
                                            loop {
                                                let _e965 = phi_237_;
                                                local_30 = _e965;
                                                let _e966 = local_24;
                                                let _e968 = local_30;
                                                let _e969 = (_e968 < (_e966 / 2u));
                                                local_31 = _e969;
                                                if _e969 {
                                                    let _e970 = local_28;
                                                    let _e971 = (_e970 - 1u);
                                                    let _e973 = local_30;
                                                    let _e976 = ((_e973 & ~(_e971)) << bitcast<u32>(1i));
                                                    local_32 = _e976;
                                                    let _e977 = local_30;
                                                    let _e978 = (_e977 & _e971);
                                                    local_33 = _e978;
                                                    local_34 = (_e976 + _e978);
                                                    let _e980 = local_25;
                                                    let _e983 = local_28;
                                                    if (_e983 == (_e980 >> bitcast<u32>(1i))) {
                                                        let _e990 = local_32;
                                                        let _e991 = local_25;
                                                        let _e994 = local_33;
                                                        let _e996 = local_34;
                                                        phi_271_ = type_12(_e996, (((_e990 + _e991) - 1u) - _e994));
                                                    } else {
                                                        let _e985 = local_34;
                                                        let _e986 = local_28;
                                                        let _e988 = local_34;
                                                        phi_271_ = type_12(_e988, (_e985 + _e986));
                                                    }
                                                    let _e999 = phi_271_;
                                                    local_35 = _e999.member;
                                                    local_36 = _e999.member_1;
                                                    let _e1002 = local_16;
                                                    if (_e999.member_1 < _e1002) {
                                                        let _e1004 = local_35;
                                                        let _e1005 = (_e1004 < 8192u);
                                                        local_37 = _e1005;
                                                        if _e1005 {
                                                        } else {
                                                            phi_1252_ = true;
                                                            break;
                                                        }
                                                        let _e1006 = local_35;
                                                        let _e1008 = global_11[_e1006];
                                                        local_38 = _e1008;
                                                        let _e1009 = local_35;
                                                        let _e1010 = (4096u + _e1009);
                                                        local_39 = _e1010;
                                                        let _e1011 = (_e1010 < 8192u);
                                                        local_40 = _e1011;
                                                        if _e1011 {
                                                        } else {
                                                            phi_1252_ = true;
                                                            break;
                                                        }
                                                        let _e1012 = local_39;
                                                        let _e1014 = global_11[_e1012];
                                                        local_41 = _e1014;
                                                        let _e1015 = local_36;
                                                        let _e1016 = (_e1015 < 8192u);
                                                        local_42 = _e1016;
                                                        if _e1016 {
                                                        } else {
                                                            phi_1252_ = true;
                                                            break;
                                                        }
                                                        let _e1017 = local_36;
                                                        let _e1019 = global_11[_e1017];
                                                        local_43 = _e1019;
                                                        let _e1020 = local_36;
                                                        let _e1021 = (4096u + _e1020);
                                                        local_44 = _e1021;
                                                        let _e1022 = (_e1021 < 8192u);
                                                        local_45 = _e1022;
                                                        if _e1022 {
                                                        } else {
                                                            phi_1252_ = true;
                                                            break;
                                                        }
                                                        let _e1023 = local_44;
                                                        let _e1025 = global_11[_e1023];
                                                        local_46 = _e1025;
                                                        let _e1026 = local_38;
                                                        let _e1027 = local_43;
                                                        if (_e1026 > _e1027) {
                                                            phi_326_ = true;
                                                        } else {
                                                            let _e1029 = local_38;
                                                            let _e1030 = local_43;
                                                            if (_e1029 == _e1030) {
                                                                let _e1032 = local_41;
                                                                let _e1033 = local_46;
                                                                phi_325_ = (_e1032 > _e1033);
                                                            } else {
                                                                phi_325_ = false;
                                                            }
                                                            let _e1036 = phi_325_;
                                                            phi_326_ = _e1036;
                                                        }
                                                        let _e1038 = phi_326_;
                                                        if _e1038 {
                                                            let _e1039 = local_37;
                                                            if _e1039 {
                                                            } else {
                                                                phi_1252_ = true;
                                                                break;
                                                            }
                                                            let _e1040 = local_43;
                                                            global_11[_e1006] = _e1040;
                                                            let _e1041 = local_40;
                                                            if _e1041 {
                                                            } else {
                                                                phi_1252_ = true;
                                                                break;
                                                            }
                                                            let _e1042 = local_46;
                                                            global_11[_e1012] = _e1042;
                                                            let _e1043 = local_42;
                                                            if _e1043 {
                                                            } else {
                                                                phi_1252_ = true;
                                                                break;
                                                            }
                                                            let _e1044 = local_38;
                                                            global_11[_e1017] = _e1044;
                                                            let _e1045 = local_45;
                                                            if _e1045 {
                                                            } else {
                                                                phi_1252_ = true;
                                                                break;
                                                            }
                                                            let _e1046 = local_41;
                                                            global_11[_e1023] = _e1046;
                                                        }
                                                    }
                                                    let _e1047 = local_30;
                                                    phi_238_ = (_e1047 + 256u);
                                                } else {
                                                    phi_238_ = u32();
                                                }
                                                let _e1050 = phi_238_;
                                                continue;
                                                continuing {
                                                    let _e1051 = local_31;
                                                    phi_237_ = _e1050;
                                                    phi_1252_ = _e955;
                                                    break if !(_e1051);
                                                }
                                            }
                                            let _e1054 = phi_1252_;
                                            phi_1263_ = _e1054;
                                            phi_1194_ = bool();
                                            if _e1054 {
                                                break;
                                            }
                                            storageBarrier();
                                            workgroupBarrier();
                                            let _e1055 = local_28;
                                            phi_1265_ = _e1054;
                                            phi_360_ = (_e1055 / 2u);
                                        }
                                        let _e1058 = phi_1265_;
                                        let _e1060 = phi_360_;
                                        let _e1061 = local_29;
                                        phi_1264_ = _e1058;
                                        phi_223_ = _e1060;
                                        phi_362_ = select(true, false, _e1061);
                                        phi_363_ = _e963;
                                    } else {
                                        phi_1264_ = _e955;
                                        phi_223_ = u32();
                                        phi_362_ = false;
                                        phi_363_ = false;
                                    }
                                    let _e1064 = phi_1264_;
                                    let _e1066 = phi_223_;
                                    let _e1068 = phi_362_;
                                    let _e1070 = phi_363_;
                                    local_47 = _e1068;
                                    continue;
                                    continuing {
                                        let _e1071 = local_47;
                                        phi_1259_ = _e1064;
                                        phi_222_ = _e1066;
                                        phi_1263_ = _e1064;
                                        phi_1194_ = _e1070;
                                        break if !(_e1071);
                                    }
                                }
                                let _e1074 = phi_1263_;
                                let _e1076 = phi_1194_;
                                local_157 = _e1076;
                                phi_1277_ = _e1074;
                                if _e1074 {
                                    break;
                                }
                                let _e1077 = local_157;
                                if _e1077 {
                                    let _e1078 = local;
                                    let _e1079 = local_27;
                                    local_48 = (_e1078 * _e1079);
                                    phi_1273_ = _e1074;
                                    let _e1397 = local_171;
                                    phi_370_ = _e1397;
                                    loop {
                                        let _e1082 = phi_1273_;
                                        let _e1084 = phi_370_;
                                        local_49 = _e1084;
                                        let _e1085 = local_49;
                                        let _e1086 = (_e1085 > 0u);
                                        local_50 = _e1086;
                                        if _e1086 {
                                            phi_380_ = 0u;
                                            loop {
                                                let _e1088 = phi_380_;
                                                local_51 = _e1088;
                                                let _e1089 = local_27;
                                                let _e1091 = local_51;
                                                let _e1092 = (_e1091 < (_e1089 / 2u));
                                                local_52 = _e1092;
                                                if _e1092 {
                                                    let _e1093 = local_49;
                                                    let _e1094 = (_e1093 - 1u);
                                                    let _e1096 = local_51;
                                                    let _e1099 = ((_e1096 & ~(_e1094)) << bitcast<u32>(1i));
                                                    local_53 = _e1099;
                                                    let _e1100 = local_51;
                                                    let _e1101 = (_e1100 & _e1094);
                                                    local_54 = _e1101;
                                                    local_55 = (_e1099 + _e1101);
                                                    let _e1103 = local_25;
                                                    let _e1106 = local_49;
                                                    if (_e1106 == (_e1103 >> bitcast<u32>(1i))) {
                                                        let _e1113 = local_53;
                                                        let _e1114 = local_25;
                                                        let _e1117 = local_54;
                                                        let _e1119 = local_55;
                                                        phi_414_ = type_12(_e1119, (((_e1113 + _e1114) - 1u) - _e1117));
                                                    } else {
                                                        let _e1108 = local_55;
                                                        let _e1109 = local_49;
                                                        let _e1111 = local_55;
                                                        phi_414_ = type_12(_e1111, (_e1108 + _e1109));
                                                    }
                                                    let _e1122 = phi_414_;
                                                    local_56 = _e1122.member;
                                                    let _e1125 = local_48;
                                                    let _e1126 = (_e1125 + _e1122.member_1);
                                                    local_57 = _e1126;
                                                    let _e1127 = local_16;
                                                    if (_e1126 < _e1127) {
                                                        let _e1129 = local_48;
                                                        let _e1130 = local_56;
                                                        let _e1131 = (_e1129 + _e1130);
                                                        local_58 = _e1131;
                                                        let _e1132 = (_e1131 < 8192u);
                                                        local_59 = _e1132;
                                                        if _e1132 {
                                                        } else {
                                                            phi_1266_ = true;
                                                            break;
                                                        }
                                                        let _e1133 = local_58;
                                                        let _e1135 = global_11[_e1133];
                                                        local_60 = _e1135;
                                                        let _e1136 = local_58;
                                                        let _e1137 = (4096u + _e1136);
                                                        local_61 = _e1137;
                                                        let _e1138 = (_e1137 < 8192u);
                                                        local_62 = _e1138;
                                                        if _e1138 {
                                                        } else {
                                                            phi_1266_ = true;
                                                            break;
                                                        }
                                                        let _e1139 = local_61;
                                                        let _e1141 = global_11[_e1139];
                                                        local_63 = _e1141;
                                                        let _e1142 = local_57;
                                                        let _e1143 = (_e1142 < 8192u);
                                                        local_64 = _e1143;
                                                        if _e1143 {
                                                        } else {
                                                            phi_1266_ = true;
                                                            break;
                                                        }
                                                        let _e1144 = local_57;
                                                        let _e1146 = global_11[_e1144];
                                                        local_65 = _e1146;
                                                        let _e1147 = local_57;
                                                        let _e1148 = (4096u + _e1147);
                                                        local_66 = _e1148;
                                                        let _e1149 = (_e1148 < 8192u);
                                                        local_67 = _e1149;
                                                        if _e1149 {
                                                        } else {
                                                            phi_1266_ = true;
                                                            break;
                                                        }
                                                        let _e1150 = local_66;
                                                        let _e1152 = global_11[_e1150];
                                                        local_68 = _e1152;
                                                        let _e1153 = local_60;
                                                        let _e1154 = local_65;
                                                        if (_e1153 > _e1154) {
                                                            phi_469_ = true;
                                                        } else {
                                                            let _e1156 = local_60;
                                                            let _e1157 = local_65;
                                                            if (_e1156 == _e1157) {
                                                                let _e1159 = local_63;
                                                                let _e1160 = local_68;
                                                                phi_468_ = (_e1159 > _e1160);
                                                            } else {
                                                                phi_468_ = false;
                                                            }
                                                            let _e1163 = phi_468_;
                                                            phi_469_ = _e1163;
                                                        }
                                                        let _e1165 = phi_469_;
                                                        if _e1165 {
                                                            let _e1166 = local_59;
                                                            if _e1166 {
                                                            } else {
                                                                phi_1266_ = true;
                                                                break;
                                                            }
                                                            let _e1167 = local_65;
                                                            global_11[_e1133] = _e1167;
                                                            let _e1168 = local_62;
                                                            if _e1168 {
                                                            } else {
                                                                phi_1266_ = true;
                                                                break;
                                                            }
                                                            let _e1169 = local_68;
                                                            global_11[_e1139] = _e1169;
                                                            let _e1170 = local_64;
                                                            if _e1170 {
                                                            } else {
                                                                phi_1266_ = true;
                                                                break;
                                                            }
                                                            let _e1171 = local_60;
                                                            global_11[_e1144] = _e1171;
                                                            let _e1172 = local_67;
                                                            if _e1172 {
                                                            } else {
                                                                phi_1266_ = true;
                                                                break;
                                                            }
                                                            let _e1173 = local_63;
                                                            global_11[_e1150] = _e1173;
                                                        }
                                                    }
                                                    let _e1174 = local_51;
                                                    phi_381_ = (_e1174 + 1u);
                                                } else {
                                                    phi_381_ = u32();
                                                }
                                                let _e1177 = phi_381_;
                                                continue;
                                                continuing {
                                                    let _e1178 = local_52;
                                                    phi_380_ = _e1177;
                                                    phi_1266_ = _e1082;
                                                    break if !(_e1178);
                                                }
                                            }
                                            let _e1181 = phi_1266_;
                                            phi_1275_ = _e1181;
                                            if _e1181 {
                                                break;
                                            }
                                            let _e1182 = local_49;
                                            phi_1276_ = _e1181;
                                            phi_371_ = (_e1182 / 2u);
                                        } else {
                                            phi_1276_ = _e1082;
                                            phi_371_ = u32();
                                        }
                                        let _e1185 = phi_1276_;
                                        let _e1187 = phi_371_;
                                        continue;
                                        continuing {
                                            let _e1188 = local_50;
                                            phi_1273_ = _e1185;
                                            phi_370_ = _e1187;
                                            phi_1275_ = _e1185;
                                            break if !(_e1188);
                                        }
                                    }
                                    let _e1191 = phi_1275_;
                                    phi_1277_ = _e1191;
                                    if _e1191 {
                                        break;
                                    }
                                    storageBarrier();
                                    workgroupBarrier();
                                    phi_1279_ = _e1191;
                                } else {
                                    phi_1279_ = _e1074;
                                }
                                let _e1193 = phi_1279_;
                                let _e1194 = local_25;
                                phi_1278_ = _e1193;
                                phi_207_ = (_e1194 * 2u);
                            } else {
                                phi_1278_ = _e944;
                                phi_207_ = u32();
                            }
                            let _e1197 = phi_1278_;
                            let _e1199 = phi_207_;
                            continue;
                            continuing {
                                let _e1200 = local_26;
                                phi_1260_ = _e1197;
                                phi_206_ = _e1199;
                                phi_1277_ = _e1197;
                                break if !(_e1200);
                            }
                        }
                        let _e1203 = phi_1277_;
                        phi_1286_ = _e1203;
                        if _e1203 {
                            break;
                        }
                        phi_1283_ = _e1203;
                    } else {
                        let _e315 = local;
                        if (_e315 == 0u) {
                            phi_1208_ = _e310;
                            phi_509_ = 0u;
                            loop {
                                let _e318 = phi_1208_;
                                let _e320 = phi_509_;
                                local_69 = _e320;
                                let _e321 = local_69;
                                let _e322 = local_16;
                                let _e323 = (_e321 < _e322);
                                local_70 = _e323;
                                if _e323 {
                                    let _e324 = local_69;
                                    let _e325 = (_e324 + 16u);
                                    let _e326 = local_16;
                                    let _e328 = local_16;
                                    let _e329 = select(_e328, _e325, (_e325 < _e326));
                                    local_158 = _e329;
                                    let _e330 = local_69;
                                    phi_1206_ = _e318;
                                    phi_527_ = (_e330 + 1u);
                                    loop {
                                        let _e333 = phi_1206_;
                                        let _e335 = phi_527_;
                                        local_71 = _e335;
                                        let _e336 = local_71;
                                        let _e337 = local_158;
                                        let _e338 = (_e336 < _e337);
                                        local_72 = _e338;
                                        if _e338 {
                                            let _e339 = local_71;
                                            if (_e339 < 8192u) {
                                            } else {
                                                phi_1209_ = true;
                                                break;
                                            }
                                            let _e341 = local_71;
                                            let _e343 = global_11[_e341];
                                            local_73 = _e343;
                                            let _e344 = local_71;
                                            let _e345 = (4096u + _e344);
                                            local_74 = _e345;
                                            if (_e345 < 8192u) {
                                            } else {
                                                phi_1209_ = true;
                                                break;
                                            }
                                            let _e347 = local_74;
                                            let _e349 = global_11[_e347];
                                            local_75 = _e349;
                                            phi_553_ = _e335;
                                            loop {
                                                let _e351 = phi_553_;
                                                local_76 = _e351;
                                                let _e352 = local_76;
                                                let _e353 = local_69;
                                                if (_e352 > _e353) {
                                                    let _e355 = local_76;
                                                    let _e356 = (_e355 - 1u);
                                                    local_77 = _e356;
                                                    if (_e356 < 8192u) {
                                                    } else {
                                                        phi_1202_ = true;
                                                        break;
                                                    }
                                                    let _e358 = local_77;
                                                    let _e360 = global_11[_e358];
                                                    local_78 = _e360;
                                                    let _e361 = local_76;
                                                    let _e362 = (_e361 + 4095u);
                                                    local_79 = _e362;
                                                    if (_e362 < 8192u) {
                                                    } else {
                                                        phi_1202_ = true;
                                                        break;
                                                    }
                                                    let _e364 = local_79;
                                                    let _e366 = global_11[_e364];
                                                    local_80 = _e366;
                                                    let _e367 = local_78;
                                                    let _e368 = local_73;
                                                    let _e369 = (_e367 <= _e368);
                                                    local_81 = _e369;
                                                    if _e369 {
                                                    } else {
                                                        let _e370 = local_76;
                                                        if (_e370 < 8192u) {
                                                        } else {
                                                            phi_1202_ = true;
                                                            break;
                                                        }
                                                        let _e372 = local_76;
                                                        let _e374 = local_78;
                                                        global_11[_e372] = _e374;
                                                        let _e375 = local_76;
                                                        let _e376 = (4096u + _e375);
                                                        local_82 = _e376;
                                                        if (_e376 < 8192u) {
                                                        } else {
                                                            phi_1202_ = true;
                                                            break;
                                                        }
                                                        let _e378 = local_82;
                                                        let _e380 = local_80;
                                                        global_11[_e378] = _e380;
                                                    }
                                                    let _e381 = local_81;
                                                    let _e382 = local_77;
                                                    let _e384 = local_81;
                                                    phi_554_ = select(_e382, u32(), _e381);
                                                    phi_600_ = select(true, false, _e384);
                                                } else {
                                                    phi_554_ = u32();
                                                    phi_600_ = false;
                                                }
                                                let _e387 = phi_554_;
                                                let _e389 = phi_600_;
                                                local_83 = _e389;
                                                continue;
                                                continuing {
                                                    let _e390 = local_83;
                                                    phi_553_ = _e387;
                                                    phi_1202_ = _e333;
                                                    break if !(_e390);
                                                }
                                            }
                                            let _e393 = phi_1202_;
                                            phi_1209_ = _e393;
                                            if _e393 {
                                                break;
                                            }
                                            let _e394 = local_76;
                                            if (_e394 < 8192u) {
                                            } else {
                                                phi_1209_ = true;
                                                break;
                                            }
                                            let _e396 = local_76;
                                            let _e398 = local_73;
                                            global_11[_e396] = _e398;
                                            let _e399 = local_76;
                                            let _e400 = (4096u + _e399);
                                            local_84 = _e400;
                                            if (_e400 < 8192u) {
                                            } else {
                                                phi_1209_ = true;
                                                break;
                                            }
                                            let _e402 = local_84;
                                            let _e404 = local_75;
                                            global_11[_e402] = _e404;
                                            let _e405 = local_71;
                                            phi_1210_ = _e393;
                                            phi_528_ = (_e405 + 1u);
                                        } else {
                                            phi_1210_ = _e333;
                                            phi_528_ = u32();
                                        }
                                        let _e408 = phi_1210_;
                                        let _e410 = phi_528_;
                                        continue;
                                        continuing {
                                            let _e411 = local_72;
                                            phi_1206_ = _e408;
                                            phi_527_ = _e410;
                                            phi_1209_ = _e408;
                                            break if !(_e411);
                                        }
                                    }
                                    let _e414 = phi_1209_;
                                    phi_1211_ = _e414;
                                    if _e414 {
                                        break;
                                    }
                                    phi_1212_ = _e414;
                                    phi_510_ = _e329;
                                } else {
                                    phi_1212_ = _e318;
                                    phi_510_ = u32();
                                }
                                let _e416 = phi_1212_;
                                let _e418 = phi_510_;
                                continue;
                                continuing {
                                    let _e419 = local_70;
                                    phi_1208_ = _e416;
                                    phi_509_ = _e418;
                                    phi_1211_ = _e416;
                                    break if !(_e419);
                                }
                            }
                            let _e422 = phi_1211_;
                            phi_1286_ = _e422;
                            if _e422 {
                                break;
                            }
                            phi_1221_ = _e422;
                            phi_621_ = true;
                            phi_624_ = 16u;
                            loop {
                                let _e424 = phi_1221_;
                                let _e426 = phi_621_;
                                let _e428 = phi_624_;
                                local_85 = _e426;
                                local_86 = _e428;
                                let _e429 = local_86;
                                let _e430 = local_16;
                                let _e431 = (_e429 < _e430);
                                local_87 = _e431;
                                if _e431 {
                                    let _e432 = local_85;
                                    if _e432 {
                                        phi_1237_ = _e424;
                                        phi_636_ = 0u;
                                        loop {
                                            let _e651 = phi_1237_;
                                            let _e653 = phi_636_;
                                            local_88 = _e653;
                                            let _e654 = local_88;
                                            let _e655 = local_16;
                                            let _e656 = (_e654 < _e655);
                                            local_89 = _e656;
                                            if _e656 {
                                                let _e657 = local_88;
                                                let _e658 = local_86;
                                                let _e659 = (_e657 + _e658);
                                                let _e660 = local_16;
                                                let _e662 = local_16;
                                                let _e663 = select(_e662, _e659, (_e659 < _e660));
                                                local_161 = _e663;
                                                let _e664 = local_86;
                                                let _e665 = (_e663 + _e664);
                                                let _e666 = local_16;
                                                let _e668 = local_16;
                                                let _e669 = select(_e668, _e665, (_e665 < _e666));
                                                local_162 = _e669;
                                                phi_660_ = _e663;
                                                phi_663_ = _e653;
                                                phi_665_ = _e653;
                                                loop {
                                                    let _e671 = phi_660_;
                                                    let _e673 = phi_663_;
                                                    let _e675 = phi_665_;
                                                    local_90 = _e671;
                                                    local_91 = _e673;
                                                    local_92 = _e675;
                                                    local_167 = _e673;
                                                    local_168 = _e675;
                                                    local_169 = _e671;
                                                    let _e676 = local_91;
                                                    let _e677 = local_161;
                                                    if (_e676 < _e677) {
                                                        let _e679 = local_90;
                                                        let _e680 = local_162;
                                                        let _e681 = (_e679 < _e680);
                                                        if _e681 {
                                                            let _e682 = local_91;
                                                            if (_e682 < 8192u) {
                                                            } else {
                                                                phi_1230_ = true;
                                                                break;
                                                            }
                                                            let _e684 = local_91;
                                                            let _e686 = global_11[_e684];
                                                            local_93 = _e686;
                                                            let _e687 = local_91;
                                                            let _e688 = (4096u + _e687);
                                                            local_94 = _e688;
                                                            if (_e688 < 8192u) {
                                                            } else {
                                                                phi_1230_ = true;
                                                                break;
                                                            }
                                                            let _e690 = local_94;
                                                            let _e692 = global_11[_e690];
                                                            local_95 = _e692;
                                                            let _e693 = local_90;
                                                            if (_e693 < 8192u) {
                                                            } else {
                                                                phi_1230_ = true;
                                                                break;
                                                            }
                                                            let _e695 = local_90;
                                                            let _e697 = global_11[_e695];
                                                            local_96 = _e697;
                                                            let _e698 = local_90;
                                                            let _e699 = (4096u + _e698);
                                                            local_97 = _e699;
                                                            if (_e699 < 8192u) {
                                                            } else {
                                                                phi_1230_ = true;
                                                                break;
                                                            }
                                                            let _e701 = local_97;
                                                            let _e703 = global_11[_e701];
                                                            local_98 = _e703;
                                                            let _e704 = local_96;
                                                            let _e705 = local_93;
                                                            if (_e704 < _e705) {
                                                                let _e725 = local_14;
                                                                let _e726 = local_92;
                                                                let _e727 = (_e725 + _e726);
                                                                local_99 = _e727;
                                                                let _e728 = local_5;
                                                                if (_e727 < _e728) {
                                                                } else {
                                                                    phi_1230_ = true;
                                                                    break;
                                                                }
                                                                let _e730 = local_99;
                                                                let _e733 = local_96;
                                                                global_9.member[_e730] = _e733;
                                                                let _e734 = local_99;
                                                                let _e735 = local_6;
                                                                if (_e734 < _e735) {
                                                                } else {
                                                                    phi_1230_ = true;
                                                                    break;
                                                                }
                                                                let _e737 = local_99;
                                                                let _e740 = local_98;
                                                                global_10.member[_e737] = _e740;
                                                                let _e741 = local_90;
                                                                phi_743_ = (_e741 + 1u);
                                                                phi_744_ = _e673;
                                                            } else {
                                                                let _e707 = local_14;
                                                                let _e708 = local_92;
                                                                let _e709 = (_e707 + _e708);
                                                                local_100 = _e709;
                                                                let _e710 = local_5;
                                                                if (_e709 < _e710) {
                                                                } else {
                                                                    phi_1230_ = true;
                                                                    break;
                                                                }
                                                                let _e712 = local_100;
                                                                let _e715 = local_93;
                                                                global_9.member[_e712] = _e715;
                                                                let _e716 = local_100;
                                                                let _e717 = local_6;
                                                                if (_e716 < _e717) {
                                                                } else {
                                                                    phi_1230_ = true;
                                                                    break;
                                                                }
                                                                let _e719 = local_100;
                                                                let _e722 = local_95;
                                                                global_10.member[_e719] = _e722;
                                                                let _e723 = local_91;
                                                                phi_743_ = _e671;
                                                                phi_744_ = (_e723 + 1u);
                                                            }
                                                            let _e744 = phi_743_;
                                                            let _e746 = phi_744_;
                                                            let _e747 = local_92;
                                                            phi_746_ = _e744;
                                                            phi_747_ = _e746;
                                                            phi_748_ = (_e747 + 1u);
                                                        } else {
                                                            phi_746_ = u32();
                                                            phi_747_ = u32();
                                                            phi_748_ = u32();
                                                        }
                                                        let _e750 = phi_746_;
                                                        let _e752 = phi_747_;
                                                        let _e754 = phi_748_;
                                                        phi_661_ = _e750;
                                                        phi_664_ = _e752;
                                                        phi_666_ = _e754;
                                                        phi_749_ = _e681;
                                                    } else {
                                                        phi_661_ = u32();
                                                        phi_664_ = u32();
                                                        phi_666_ = u32();
                                                        phi_749_ = false;
                                                    }
                                                    let _e756 = phi_661_;
                                                    let _e758 = phi_664_;
                                                    let _e760 = phi_666_;
                                                    let _e762 = phi_749_;
                                                    local_101 = _e762;
                                                    continue;
                                                    continuing {
                                                        let _e763 = local_101;
                                                        phi_660_ = _e756;
                                                        phi_663_ = _e758;
                                                        phi_665_ = _e760;
                                                        phi_1230_ = _e651;
                                                        break if !(_e763);
                                                    }
                                                }
                                                let _e766 = phi_1230_;
                                                phi_1244_ = _e766;
                                                if _e766 {
                                                    break;
                                                }
                                                let _e1346 = local_167;
                                                phi_755_ = _e1346;
                                                let _e1349 = local_168;
                                                phi_758_ = _e1349;
                                                loop {
                                                    let _e768 = phi_755_;
                                                    let _e770 = phi_758_;
                                                    local_102 = _e768;
                                                    local_103 = _e770;
                                                    local_170 = _e770;
                                                    let _e771 = local_102;
                                                    let _e772 = local_161;
                                                    let _e773 = (_e771 < _e772);
                                                    local_104 = _e773;
                                                    if _e773 {
                                                        let _e774 = local_102;
                                                        if (_e774 < 8192u) {
                                                        } else {
                                                            phi_1238_ = true;
                                                            break;
                                                        }
                                                        let _e776 = local_102;
                                                        let _e778 = global_11[_e776];
                                                        local_105 = _e778;
                                                        let _e779 = local_102;
                                                        let _e780 = (4096u + _e779);
                                                        local_106 = _e780;
                                                        if (_e780 < 8192u) {
                                                        } else {
                                                            phi_1238_ = true;
                                                            break;
                                                        }
                                                        let _e782 = local_106;
                                                        let _e784 = global_11[_e782];
                                                        local_107 = _e784;
                                                        let _e785 = local_14;
                                                        let _e786 = local_103;
                                                        let _e787 = (_e785 + _e786);
                                                        local_108 = _e787;
                                                        let _e788 = local_5;
                                                        if (_e787 < _e788) {
                                                        } else {
                                                            phi_1238_ = true;
                                                            break;
                                                        }
                                                        let _e790 = local_108;
                                                        let _e793 = local_105;
                                                        global_9.member[_e790] = _e793;
                                                        let _e794 = local_108;
                                                        let _e795 = local_6;
                                                        if (_e794 < _e795) {
                                                        } else {
                                                            phi_1238_ = true;
                                                            break;
                                                        }
                                                        let _e797 = local_108;
                                                        let _e800 = local_107;
                                                        global_10.member[_e797] = _e800;
                                                        let _e801 = local_102;
                                                        let _e803 = local_103;
                                                        phi_756_ = (_e801 + 1u);
                                                        phi_759_ = (_e803 + 1u);
                                                    } else {
                                                        phi_756_ = u32();
                                                        phi_759_ = u32();
                                                    }
                                                    let _e806 = phi_756_;
                                                    let _e808 = phi_759_;
                                                    continue;
                                                    continuing {
                                                        let _e809 = local_104;
                                                        phi_755_ = _e806;
                                                        phi_758_ = _e808;
                                                        phi_1238_ = _e766;
                                                        break if !(_e809);
                                                    }
                                                }
                                                let _e812 = phi_1238_;
                                                phi_1244_ = _e812;
                                                if _e812 {
                                                    break;
                                                }
                                                let _e1355 = local_169;
                                                phi_799_ = _e1355;
                                                let _e1358 = local_170;
                                                phi_802_ = _e1358;
                                                loop {
                                                    let _e814 = phi_799_;
                                                    let _e816 = phi_802_;
                                                    local_109 = _e814;
                                                    local_110 = _e816;
                                                    let _e817 = local_109;
                                                    let _e818 = local_162;
                                                    let _e819 = (_e817 < _e818);
                                                    local_111 = _e819;
                                                    if _e819 {
                                                        let _e820 = local_109;
                                                        if (_e820 < 8192u) {
                                                        } else {
                                                            phi_1241_ = true;
                                                            break;
                                                        }
                                                        let _e822 = local_109;
                                                        let _e824 = global_11[_e822];
                                                        local_112 = _e824;
                                                        let _e825 = local_109;
                                                        let _e826 = (4096u + _e825);
                                                        local_113 = _e826;
                                                        if (_e826 < 8192u) {
                                                        } else {
                                                            phi_1241_ = true;
                                                            break;
                                                        }
                                                        let _e828 = local_113;
                                                        let _e830 = global_11[_e828];
                                                        local_114 = _e830;
                                                        let _e831 = local_14;
                                                        let _e832 = local_110;
                                                        let _e833 = (_e831 + _e832);
                                                        local_115 = _e833;
                                                        let _e834 = local_5;
                                                        if (_e833 < _e834) {
                                                        } else {
                                                            phi_1241_ = true;
                                                            break;
                                                        }
                                                        let _e836 = local_115;
                                                        let _e839 = local_112;
                                                        global_9.member[_e836] = _e839;
                                                        let _e840 = local_115;
                                                        let _e841 = local_6;
                                                        if (_e840 < _e841) {
                                                        } else {
                                                            phi_1241_ = true;
                                                            break;
                                                        }
                                                        let _e843 = local_115;
                                                        let _e846 = local_114;
                                                        global_10.member[_e843] = _e846;
                                                        let _e847 = local_109;
                                                        let _e849 = local_110;
                                                        phi_800_ = (_e847 + 1u);
                                                        phi_803_ = (_e849 + 1u);
                                                    } else {
                                                        phi_800_ = u32();
                                                        phi_803_ = u32();
                                                    }
                                                    let _e852 = phi_800_;
                                                    let _e854 = phi_803_;
                                                    continue;
                                                    continuing {
                                                        let _e855 = local_111;
                                                        phi_799_ = _e852;
                                                        phi_802_ = _e854;
                                                        phi_1241_ = _e812;
                                                        break if !(_e855);
                                                    }
                                                }
                                                let _e858 = phi_1241_;
                                                phi_1244_ = _e858;
                                                if _e858 {
                                                    break;
                                                }
                                                phi_1245_ = _e858;
                                                phi_637_ = _e669;
                                            } else {
                                                phi_1245_ = _e651;
                                                phi_637_ = u32();
                                            }
                                            let _e860 = phi_1245_;
                                            let _e862 = phi_637_;
                                            continue;
                                            continuing {
                                                let _e863 = local_89;
                                                phi_1237_ = _e860;
                                                phi_636_ = _e862;
                                                phi_1244_ = _e860;
                                                break if !(_e863);
                                            }
                                        }
                                        let _e866 = phi_1244_;
                                        phi_1246_ = _e866;
                                        if _e866 {
                                            break;
                                        }
                                        phi_1248_ = _e866;
                                    } else {
                                        phi_1220_ = _e424;
                                        phi_843_ = 0u;
                                        loop {
                                            let _e434 = phi_1220_;
                                            let _e436 = phi_843_;
                                            local_116 = _e436;
                                            let _e437 = local_116;
                                            let _e438 = local_16;
                                            let _e439 = (_e437 < _e438);
                                            local_117 = _e439;
                                            if _e439 {
                                                let _e440 = local_116;
                                                let _e441 = local_86;
                                                let _e442 = (_e440 + _e441);
                                                let _e443 = local_16;
                                                let _e445 = local_16;
                                                let _e446 = select(_e445, _e442, (_e442 < _e443));
                                                local_159 = _e446;
                                                let _e447 = local_86;
                                                let _e448 = (_e446 + _e447);
                                                let _e449 = local_16;
                                                let _e451 = local_16;
                                                let _e452 = select(_e451, _e448, (_e448 < _e449));
                                                local_160 = _e452;
                                                phi_867_ = _e446;
                                                phi_870_ = _e436;
                                                phi_872_ = _e436;
                                                loop {
                                                    let _e454 = phi_867_;
                                                    let _e456 = phi_870_;
                                                    let _e458 = phi_872_;
                                                    local_118 = _e454;
                                                    local_119 = _e456;
                                                    local_120 = _e458;
                                                    local_163 = _e456;
                                                    local_164 = _e458;
                                                    local_165 = _e454;
                                                    let _e459 = local_119;
                                                    let _e460 = local_159;
                                                    if (_e459 < _e460) {
                                                        let _e462 = local_118;
                                                        let _e463 = local_160;
                                                        let _e464 = (_e462 < _e463);
                                                        if _e464 {
                                                            let _e465 = local_14;
                                                            let _e466 = local_119;
                                                            let _e467 = (_e465 + _e466);
                                                            local_121 = _e467;
                                                            let _e468 = local_5;
                                                            if (_e467 < _e468) {
                                                            } else {
                                                                phi_1213_ = true;
                                                                break;
                                                            }
                                                            let _e470 = local_121;
                                                            let _e473 = global_9.member[_e470];
                                                            local_122 = _e473;
                                                            let _e474 = local_121;
                                                            let _e475 = local_6;
                                                            if (_e474 < _e475) {
                                                            } else {
                                                                phi_1213_ = true;
                                                                break;
                                                            }
                                                            let _e477 = local_121;
                                                            let _e480 = global_10.member[_e477];
                                                            local_123 = _e480;
                                                            let _e481 = local_14;
                                                            let _e482 = local_118;
                                                            let _e483 = (_e481 + _e482);
                                                            local_124 = _e483;
                                                            let _e484 = local_5;
                                                            if (_e483 < _e484) {
                                                            } else {
                                                                phi_1213_ = true;
                                                                break;
                                                            }
                                                            let _e486 = local_124;
                                                            let _e489 = global_9.member[_e486];
                                                            local_125 = _e489;
                                                            let _e490 = local_124;
                                                            let _e491 = local_6;
                                                            if (_e490 < _e491) {
                                                            } else {
                                                                phi_1213_ = true;
                                                                break;
                                                            }
                                                            let _e493 = local_124;
                                                            let _e496 = global_10.member[_e493];
                                                            local_126 = _e496;
                                                            let _e497 = local_125;
                                                            let _e498 = local_122;
                                                            if (_e497 < _e498) {
                                                                let _e513 = local_120;
                                                                if (_e513 < 8192u) {
                                                                } else {
                                                                    phi_1213_ = true;
                                                                    break;
                                                                }
                                                                let _e515 = local_120;
                                                                let _e517 = local_125;
                                                                global_11[_e515] = _e517;
                                                                let _e518 = local_120;
                                                                let _e519 = (4096u + _e518);
                                                                local_127 = _e519;
                                                                if (_e519 < 8192u) {
                                                                } else {
                                                                    phi_1213_ = true;
                                                                    break;
                                                                }
                                                                let _e521 = local_127;
                                                                let _e523 = local_126;
                                                                global_11[_e521] = _e523;
                                                                let _e524 = local_118;
                                                                phi_950_ = (_e524 + 1u);
                                                                phi_951_ = _e456;
                                                            } else {
                                                                let _e500 = local_120;
                                                                if (_e500 < 8192u) {
                                                                } else {
                                                                    phi_1213_ = true;
                                                                    break;
                                                                }
                                                                let _e502 = local_120;
                                                                let _e504 = local_122;
                                                                global_11[_e502] = _e504;
                                                                let _e505 = local_120;
                                                                let _e506 = (4096u + _e505);
                                                                local_128 = _e506;
                                                                if (_e506 < 8192u) {
                                                                } else {
                                                                    phi_1213_ = true;
                                                                    break;
                                                                }
                                                                let _e508 = local_128;
                                                                let _e510 = local_123;
                                                                global_11[_e508] = _e510;
                                                                let _e511 = local_119;
                                                                phi_950_ = _e454;
                                                                phi_951_ = (_e511 + 1u);
                                                            }
                                                            let _e527 = phi_950_;
                                                            let _e529 = phi_951_;
                                                            let _e530 = local_120;
                                                            phi_953_ = _e527;
                                                            phi_954_ = _e529;
                                                            phi_955_ = (_e530 + 1u);
                                                        } else {
                                                            phi_953_ = u32();
                                                            phi_954_ = u32();
                                                            phi_955_ = u32();
                                                        }
                                                        let _e533 = phi_953_;
                                                        let _e535 = phi_954_;
                                                        let _e537 = phi_955_;
                                                        phi_868_ = _e533;
                                                        phi_871_ = _e535;
                                                        phi_873_ = _e537;
                                                        phi_956_ = _e464;
                                                    } else {
                                                        phi_868_ = u32();
                                                        phi_871_ = u32();
                                                        phi_873_ = u32();
                                                        phi_956_ = false;
                                                    }
                                                    let _e539 = phi_868_;
                                                    let _e541 = phi_871_;
                                                    let _e543 = phi_873_;
                                                    let _e545 = phi_956_;
                                                    local_129 = _e545;
                                                    continue;
                                                    continuing {
                                                        let _e546 = local_129;
                                                        phi_867_ = _e539;
                                                        phi_870_ = _e541;
                                                        phi_872_ = _e543;
                                                        phi_1213_ = _e434;
                                                        break if !(_e546);
                                                    }
                                                }
                                                let _e549 = phi_1213_;
                                                phi_1228_ = _e549;
                                                if _e549 {
                                                    break;
                                                }
                                                let _e1310 = local_163;
                                                phi_962_ = _e1310;
                                                let _e1313 = local_164;
                                                phi_965_ = _e1313;
                                                loop {
                                                    let _e551 = phi_962_;
                                                    let _e553 = phi_965_;
                                                    local_130 = _e551;
                                                    local_131 = _e553;
                                                    local_166 = _e553;
                                                    let _e554 = local_130;
                                                    let _e555 = local_159;
                                                    let _e556 = (_e554 < _e555);
                                                    local_132 = _e556;
                                                    if _e556 {
                                                        let _e557 = local_14;
                                                        let _e558 = local_130;
                                                        let _e559 = (_e557 + _e558);
                                                        local_133 = _e559;
                                                        let _e560 = local_5;
                                                        if (_e559 < _e560) {
                                                        } else {
                                                            phi_1222_ = true;
                                                            break;
                                                        }
                                                        let _e562 = local_133;
                                                        let _e565 = global_9.member[_e562];
                                                        local_134 = _e565;
                                                        let _e566 = local_133;
                                                        let _e567 = local_6;
                                                        if (_e566 < _e567) {
                                                        } else {
                                                            phi_1222_ = true;
                                                            break;
                                                        }
                                                        let _e569 = local_133;
                                                        let _e572 = global_10.member[_e569];
                                                        local_135 = _e572;
                                                        let _e573 = local_131;
                                                        if (_e573 < 8192u) {
                                                        } else {
                                                            phi_1222_ = true;
                                                            break;
                                                        }
                                                        let _e575 = local_131;
                                                        let _e577 = local_134;
                                                        global_11[_e575] = _e577;
                                                        let _e578 = local_131;
                                                        let _e579 = (4096u + _e578);
                                                        local_136 = _e579;
                                                        if (_e579 < 8192u) {
                                                        } else {
                                                            phi_1222_ = true;
                                                            break;
                                                        }
                                                        let _e581 = local_136;
                                                        let _e583 = local_135;
                                                        global_11[_e581] = _e583;
                                                        let _e584 = local_130;
                                                        let _e586 = local_131;
                                                        phi_963_ = (_e584 + 1u);
                                                        phi_966_ = (_e586 + 1u);
                                                    } else {
                                                        phi_963_ = u32();
                                                        phi_966_ = u32();
                                                    }
                                                    let _e589 = phi_963_;
                                                    let _e591 = phi_966_;
                                                    continue;
                                                    continuing {
                                                        let _e592 = local_132;
                                                        phi_962_ = _e589;
                                                        phi_965_ = _e591;
                                                        phi_1222_ = _e549;
                                                        break if !(_e592);
                                                    }
                                                }
                                                let _e595 = phi_1222_;
                                                phi_1228_ = _e595;
                                                if _e595 {
                                                    break;
                                                }
                                                let _e1319 = local_165;
                                                phi_1006_ = _e1319;
                                                let _e1322 = local_166;
                                                phi_1009_ = _e1322;
                                                loop {
                                                    let _e597 = phi_1006_;
                                                    let _e599 = phi_1009_;
                                                    local_137 = _e597;
                                                    local_138 = _e599;
                                                    let _e600 = local_137;
                                                    let _e601 = local_160;
                                                    let _e602 = (_e600 < _e601);
                                                    local_139 = _e602;
                                                    if _e602 {
                                                        let _e603 = local_14;
                                                        let _e604 = local_137;
                                                        let _e605 = (_e603 + _e604);
                                                        local_140 = _e605;
                                                        let _e606 = local_5;
                                                        if (_e605 < _e606) {
                                                        } else {
                                                            phi_1225_ = true;
                                                            break;
                                                        }
                                                        let _e608 = local_140;
                                                        let _e611 = global_9.member[_e608];
                                                        local_141 = _e611;
                                                        let _e612 = local_140;
                                                        let _e613 = local_6;
                                                        if (_e612 < _e613) {
                                                        } else {
                                                            phi_1225_ = true;
                                                            break;
                                                        }
                                                        let _e615 = local_140;
                                                        let _e618 = global_10.member[_e615];
                                                        local_142 = _e618;
                                                        let _e619 = local_138;
                                                        if (_e619 < 8192u) {
                                                        } else {
                                                            phi_1225_ = true;
                                                            break;
                                                        }
                                                        let _e621 = local_138;
                                                        let _e623 = local_141;
                                                        global_11[_e621] = _e623;
                                                        let _e624 = local_138;
                                                        let _e625 = (4096u + _e624);
                                                        local_143 = _e625;
                                                        if (_e625 < 8192u) {
                                                        } else {
                                                            phi_1225_ = true;
                                                            break;
                                                        }
                                                        let _e627 = local_143;
                                                        let _e629 = local_142;
                                                        global_11[_e627] = _e629;
                                                        let _e630 = local_137;
                                                        let _e632 = local_138;
                                                        phi_1007_ = (_e630 + 1u);
                                                        phi_1010_ = (_e632 + 1u);
                                                    } else {
                                                        phi_1007_ = u32();
                                                        phi_1010_ = u32();
                                                    }
                                                    let _e635 = phi_1007_;
                                                    let _e637 = phi_1010_;
                                                    continue;
                                                    continuing {
                                                        let _e638 = local_139;
                                                        phi_1006_ = _e635;
                                                        phi_1009_ = _e637;
                                                        phi_1225_ = _e595;
                                                        break if !(_e638);
                                                    }
                                                }
                                                let _e641 = phi_1225_;
                                                phi_1228_ = _e641;
                                                if _e641 {
                                                    break;
                                                }
                                                phi_1229_ = _e641;
                                                phi_844_ = _e452;
                                            } else {
                                                phi_1229_ = _e434;
                                                phi_844_ = u32();
                                            }
                                            let _e643 = phi_1229_;
                                            let _e645 = phi_844_;
                                            continue;
                                            continuing {
                                                let _e646 = local_117;
                                                phi_1220_ = _e643;
                                                phi_843_ = _e645;
                                                phi_1228_ = _e643;
                                                break if !(_e646);
                                            }
                                        }
                                        let _e649 = phi_1228_;
                                        phi_1246_ = _e649;
                                        if _e649 {
                                            break;
                                        }
                                        phi_1248_ = _e649;
                                    }
                                    let _e868 = phi_1248_;
                                    let _e869 = local_85;
                                    let _e871 = local_86;
                                    phi_1247_ = _e868;
                                    phi_622_ = !(_e869);
                                    phi_625_ = (_e871 * 2u);
                                } else {
                                    phi_1247_ = _e424;
                                    phi_622_ = bool();
                                    phi_625_ = u32();
                                }
                                let _e874 = phi_1247_;
                                let _e876 = phi_622_;
                                let _e878 = phi_625_;
                                continue;
                                continuing {
                                    let _e879 = local_87;
                                    phi_1221_ = _e874;
                                    phi_621_ = _e876;
                                    phi_624_ = _e878;
                                    phi_1246_ = _e874;
                                    break if !(_e879);
                                }
                            }
                            let _e882 = phi_1246_;
                            phi_1286_ = _e882;
                            if _e882 {
                                break;
                            }
                            let _e883 = local_85;
                            if _e883 {
                                phi_1285_ = _e882;
                            } else {
                                phi_1055_ = 0u;
                                loop {
                                    let _e885 = phi_1055_;
                                    local_144 = _e885;
                                    let _e886 = local_144;
                                    let _e887 = local_16;
                                    let _e888 = (_e886 < _e887);
                                    local_145 = _e888;
                                    if _e888 {
                                        let _e889 = local_14;
                                        let _e890 = local_144;
                                        let _e891 = (_e889 + _e890);
                                        local_146 = _e891;
                                        let _e892 = local_5;
                                        if (_e891 < _e892) {
                                        } else {
                                            phi_1249_ = true;
                                            break;
                                        }
                                        let _e894 = local_146;
                                        let _e897 = global_9.member[_e894];
                                        local_147 = _e897;
                                        let _e898 = local_146;
                                        let _e899 = local_6;
                                        if (_e898 < _e899) {
                                        } else {
                                            phi_1249_ = true;
                                            break;
                                        }
                                        let _e901 = local_146;
                                        let _e904 = global_10.member[_e901];
                                        local_148 = _e904;
                                        let _e905 = local_144;
                                        if (_e905 < 8192u) {
                                        } else {
                                            phi_1249_ = true;
                                            break;
                                        }
                                        let _e907 = local_144;
                                        let _e909 = local_147;
                                        global_11[_e907] = _e909;
                                        let _e910 = local_144;
                                        let _e911 = (4096u + _e910);
                                        local_149 = _e911;
                                        if (_e911 < 8192u) {
                                        } else {
                                            phi_1249_ = true;
                                            break;
                                        }
                                        let _e913 = local_149;
                                        let _e915 = local_148;
                                        global_11[_e913] = _e915;
                                        let _e916 = local_144;
                                        phi_1056_ = (_e916 + 1u);
                                    } else {
                                        phi_1056_ = u32();
                                    }
                                    let _e919 = phi_1056_;
                                    continue;
                                    continuing {
                                        let _e920 = local_145;
                                        phi_1055_ = _e919;
                                        phi_1249_ = _e882;
                                        break if !(_e920);
                                    }
                                }
                                let _e923 = phi_1249_;
                                phi_1286_ = _e923;
                                if _e923 {
                                    break;
                                }
                                phi_1285_ = _e923;
                            }
                            let _e925 = phi_1285_;
                            phi_1284_ = _e925;
                        } else {
                            phi_1284_ = _e310;
                        }
                        let _e927 = phi_1284_;
                        storageBarrier();
                        workgroupBarrier();
                        phi_1283_ = _e927;
                    }
                    let _e1205 = phi_1283_;
                    phi_1096_ = _e199;
                    loop {
                        let _e1207 = phi_1096_;
                        local_150 = _e1207;
                        let _e1208 = local_150;
                        let _e1209 = local_16;
                        let _e1210 = (_e1208 < _e1209);
                        local_151 = _e1210;
                        if _e1210 {
                            let _e1211 = local_150;
                            let _e1212 = (4096u + _e1211);
                            local_152 = _e1212;
                            if (_e1212 < 8192u) {
                            } else {
                                phi_1280_ = true;
                                break;
                            }
                            let _e1214 = local_152;
                            let _e1216 = global_11[_e1214];
                            let _e1217 = local_14;
                            let _e1218 = (_e1217 + _e1216);
                            local_153 = _e1218;
                            let _e1219 = local_14;
                            let _e1220 = local_150;
                            local_154 = (_e1219 + _e1220);
                            let _e1222 = local_3;
                            if (_e1218 < _e1222) {
                            } else {
                                phi_1280_ = true;
                                break;
                            }
                            let _e1224 = local_153;
                            let _e1227 = global_7.member[_e1224];
                            local_155 = _e1227;
                            let _e1228 = local_154;
                            let _e1229 = local_5;
                            if (_e1228 < _e1229) {
                            } else {
                                phi_1280_ = true;
                                break;
                            }
                            let _e1231 = local_154;
                            let _e1234 = local_155;
                            global_9.member[_e1231] = _e1234;
                            let _e1235 = local_153;
                            let _e1236 = local_4;
                            if (_e1235 < _e1236) {
                            } else {
                                phi_1280_ = true;
                                break;
                            }
                            let _e1238 = local_153;
                            let _e1241 = global_8.member[_e1238];
                            local_156 = _e1241;
                            let _e1242 = local_154;
                            let _e1243 = local_6;
                            if (_e1242 < _e1243) {
                            } else {
                                phi_1280_ = true;
                                break;
                            }
                            let _e1245 = local_154;
                            let _e1248 = local_156;
                            global_10.member[_e1245] = _e1248;
                            let _e1249 = local_150;
                            phi_1097_ = (_e1249 + 256u);
                        } else {
                            phi_1097_ = u32();
                        }
                        let _e1252 = phi_1097_;
                        continue;
                        continuing {
                            let _e1253 = local_151;
                            phi_1096_ = _e1252;
                            phi_1280_ = _e1205;
                            break if !(_e1253);
                        }
                    }
                    let _e1256 = phi_1280_;
                    phi_1286_ = _e1256;
                    if _e1256 {
                        break;
                    }
                    storageBarrier();
                    workgroupBarrier();
                    let _e1257 = local_10;
                    let _e1258 = local_7;
                    phi_1287_ = _e1256;
                    phi_97_ = (_e1257 + _e1258);
                } else {
                    phi_1287_ = _e227;
                    phi_97_ = u32();
                }
                let _e1261 = phi_1287_;
                let _e1263 = phi_97_;
                continue;
                continuing {
                    let _e1264 = local_11;
                    phi_1199_ = _e1261;
                    phi_96_ = _e1263;
                    phi_1286_ = _e1261;
                    break if !(_e1264);
                }
            }
            let _e1267 = phi_1286_;
            if _e1267 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn sort_shared_4096_(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
