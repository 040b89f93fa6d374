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
var<workgroup> global_8: array<u32, 4096>;
@group(0) @binding(4) 
var<storage, read_write> global_9: type_5;
@group(0) @binding(5) 
var<storage, read_write> global_10: type_5;

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
    var local_10: bool;
    var local_11: u32;
    var local_12: u32;
    var local_13: u32;
    var local_14: u32;
    var local_15: u32;
    var local_16: u32;
    var local_17: bool;
    var local_18: u32;
    var local_19: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var local_24: u32;
    var local_25: u32;
    var local_26: u32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: bool;
    var local_31: u32;
    var local_32: bool;
    var local_33: u32;
    var local_34: bool;
    var local_35: u32;
    var local_36: bool;
    var local_37: u32;
    var local_38: u32;
    var local_39: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: bool;
    var local_44: u32;
    var local_45: u32;
    var local_46: bool;
    var local_47: u32;
    var local_48: u32;
    var local_49: bool;
    var local_50: u32;
    var local_51: u32;
    var local_52: bool;
    var local_53: u32;
    var local_54: bool;
    var local_55: u32;
    var local_56: u32;
    var local_57: bool;
    var local_58: u32;
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
    var local_69: bool;
    var local_70: u32;
    var local_71: u32;
    var local_72: bool;
    var local_73: u32;
    var local_74: u32;
    var local_75: bool;
    var local_76: u32;
    var local_77: u32;
    var local_78: bool;
    var local_79: u32;
    var local_80: bool;
    var local_81: u32;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: u32;
    var local_86: u32;
    var local_87: bool;
    var local_88: u32;
    var local_89: u32;
    var local_90: bool;
    var local_91: u32;
    var local_92: u32;
    var local_93: bool;
    var local_94: u32;
    var local_95: u32;
    var local_96: bool;
    var local_97: u32;
    var local_98: bool;
    var local_99: u32;
    var local_100: u32;
    var local_101: bool;
    var local_102: u32;
    var local_103: bool;
    var local_104: u32;
    var local_105: u32;
    var local_106: u32;
    var local_107: u32;
    var local_108: u32;
    var local_109: u32;
    var local_110: bool;
    var local_111: u32;
    var local_112: u32;
    var local_113: bool;
    var local_114: u32;
    var local_115: u32;
    var local_116: bool;
    var local_117: u32;
    var local_118: u32;
    var local_119: bool;
    var local_120: u32;
    var local_121: u32;
    var local_122: u32;
    var local_123: u32;
    var local_124: u32;
    var local_125: u32;
    var local_126: bool;
    var local_127: bool;
    var local_128: bool;
    var local_129: bool;
    var phi_950_: bool;
    var phi_91_: u32;
    var phi_142_: u32;
    var phi_948_: bool;
    var phi_145_: u32;
    var phi_160_: u32;
    var phi_205_: u32;
    var phi_206_: u32;
    var phi_207_: u32;
    var phi_250_: u32;
    var phi_161_: u32;
    var phi_251_: bool;
    var phi_942_: bool;
    var phi_960_: bool;
    var phi_569_: u32;
    var phi_584_: u32;
    var phi_618_: type_12;
    var phi_672_: bool;
    var phi_673_: bool;
    var phi_585_: u32;
    var phi_953_: bool;
    var phi_964_: bool;
    var phi_707_: u32;
    var phi_963_: bool;
    var phi_570_: u32;
    var phi_709_: bool;
    var phi_710_: bool;
    var phi_962_: bool;
    var phi_939_: bool;
    var phi_972_: bool;
    var phi_717_: u32;
    var phi_727_: u32;
    var phi_761_: type_12;
    var phi_815_: bool;
    var phi_816_: bool;
    var phi_728_: u32;
    var phi_965_: bool;
    var phi_975_: bool;
    var phi_718_: u32;
    var phi_974_: bool;
    var phi_1008_: bool;
    var phi_984_: bool;
    var phi_263_: u32;
    var phi_983_: bool;
    var phi_279_: u32;
    var phi_294_: u32;
    var phi_328_: type_12;
    var phi_382_: bool;
    var phi_383_: bool;
    var phi_295_: u32;
    var phi_976_: bool;
    var phi_988_: bool;
    var phi_417_: u32;
    var phi_987_: bool;
    var phi_280_: u32;
    var phi_419_: bool;
    var phi_420_: bool;
    var phi_986_: bool;
    var phi_940_: bool;
    var phi_996_: bool;
    var phi_427_: u32;
    var phi_437_: u32;
    var phi_471_: type_12;
    var phi_525_: bool;
    var phi_526_: bool;
    var phi_438_: u32;
    var phi_989_: bool;
    var phi_999_: bool;
    var phi_428_: u32;
    var phi_998_: bool;
    var phi_1002_: bool;
    var phi_1001_: bool;
    var phi_264_: u32;
    var phi_1000_: bool;
    var phi_1007_: bool;
    var phi_851_: u32;
    var phi_897_: u32;
    var phi_852_: u32;
    var phi_898_: bool;
    var phi_1003_: bool;
    var phi_1011_: bool;
    var phi_904_: u32;
    var phi_1010_: bool;
    var phi_146_: u32;
    var phi_905_: bool;
    var phi_1009_: bool;
    var phi_1013_: bool;
    var phi_92_: u32;
    var phi_1012_: bool;
    var local_130: u32;
    var local_131: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e165 = global;
            local = _e165;
            let _e166 = global_1;
            let _e167 = global_2;
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = arrayLength((&global_7.member));
            local_4 = arrayLength((&global_9.member));
            local_5 = arrayLength((&global_10.member));
            local_6 = _e167.x;
            local_7 = _e167.y;
            if (9u < arrayLength((&global_5.member))) {
            } else {
                break;
            }
            let _e187 = global_5.member[9u];
            local_8 = _e187;
            phi_950_ = false;
            phi_91_ = _e166.y;
            loop {
                let _e189 = phi_950_;
                let _e191 = phi_91_;
                local_9 = _e191;
                let _e192 = local_9;
                let _e193 = local_8;
                let _e194 = (_e192 < _e193);
                local_10 = _e194;
                if _e194 {
                    let _e197 = global_4.member.member;
                    let _e199 = local_9;
                    let _e200 = ((9u * _e197) + _e199);
                    local_11 = _e200;
                    let _e201 = local_2;
                    if (_e200 < _e201) {
                    } else {
                        phi_1012_ = true;
                        break;
                    }
                    let _e203 = local_11;
                    let _e206 = global_6.member[_e203];
                    let _e207 = (2u * _e206);
                    local_12 = _e207;
                    let _e208 = local_1;
                    if (_e207 < _e208) {
                    } else {
                        phi_1012_ = true;
                        break;
                    }
                    let _e210 = local_12;
                    let _e213 = global_3.member[_e210];
                    local_13 = _e213;
                    let _e214 = local_12;
                    let _e215 = (_e214 + 1u);
                    local_14 = _e215;
                    let _e216 = local_1;
                    if (_e215 < _e216) {
                    } else {
                        phi_1012_ = true;
                        break;
                    }
                    let _e218 = local_14;
                    let _e221 = global_3.member[_e218];
                    local_15 = _e221;
                    let _e224 = global_4.member.member_2;
                    local_16 = _e224;
                    if (_e221 <= 1u) {
                        phi_142_ = 1u;
                    } else {
                        let _e226 = local_15;
                        let _e227 = (_e226 - 1u);
                        phi_142_ = (1u << bitcast<u32>(((32u - select((bitcast<u32>(31i) - firstLeadingBit(_e227)), 32u, (_e227 == 0u))) & 31u)));
                    }
                    let _e238 = phi_142_;
                    let _e239 = local_16;
                    local_17 = (_e239 <= _e238);
                    phi_948_ = _e189;
                    phi_145_ = _e166.x;
                    loop {
                        let _e242 = phi_948_;
                        let _e244 = phi_145_;
                        local_18 = _e244;
                        let _e245 = local_17;
                        if _e245 {
                            let _e246 = local_18;
                            let _e247 = (_e246 * 2048u);
                            local_19 = _e247;
                            let _e248 = local_15;
                            let _e249 = (_e247 < _e248);
                            if _e249 {
                                phi_160_ = _e165;
                                loop {
                                    let _e251 = phi_160_;
                                    local_20 = _e251;
                                    let _e252 = local_20;
                                    if (_e252 < 2048u) {
                                        let _e254 = local_19;
                                        let _e255 = local_20;
                                        let _e256 = (_e254 + _e255);
                                        local_21 = _e256;
                                        let _e257 = local_15;
                                        let _e258 = (_e256 < _e257);
                                        if _e258 {
                                            let _e259 = local_13;
                                            let _e260 = local_19;
                                            let _e262 = local_20;
                                            local_22 = ((_e259 + _e260) + _e262);
                                            let _e264 = local_16;
                                            if (_e264 == 0u) {
                                                let _e291 = local_22;
                                                let _e292 = local_3;
                                                if (_e291 < _e292) {
                                                } else {
                                                    phi_942_ = true;
                                                    break;
                                                }
                                                let _e294 = local_22;
                                                let _e297 = global_7.member[_e294];
                                                local_23 = _e297;
                                                let _e298 = (_e297 & 2147483647u);
                                                local_24 = _e298;
                                                if (_e298 > 2139095040u) {
                                                    phi_207_ = 4294967295u;
                                                } else {
                                                    let _e300 = local_24;
                                                    if (_e300 == 0u) {
                                                        phi_206_ = 2147483648u;
                                                    } else {
                                                        let _e302 = local_23;
                                                        if ((_e302 & 2147483648u) == 0u) {
                                                            let _e307 = local_23;
                                                            phi_205_ = (_e307 | 2147483648u);
                                                        } else {
                                                            let _e305 = local_23;
                                                            phi_205_ = ~(_e305);
                                                        }
                                                        let _e310 = phi_205_;
                                                        phi_206_ = _e310;
                                                    }
                                                    let _e312 = phi_206_;
                                                    phi_207_ = _e312;
                                                }
                                                let _e314 = phi_207_;
                                                local_25 = _e314;
                                                let _e315 = local_20;
                                                if (_e315 < 4096u) {
                                                } else {
                                                    phi_942_ = true;
                                                    break;
                                                }
                                                let _e317 = local_20;
                                                let _e319 = local_25;
                                                global_8[_e317] = _e319;
                                                let _e320 = local_20;
                                                let _e321 = (2048u + _e320);
                                                local_26 = _e321;
                                                if (_e321 < 4096u) {
                                                } else {
                                                    phi_942_ = true;
                                                    break;
                                                }
                                                let _e323 = local_26;
                                                let _e325 = local_21;
                                                global_8[_e323] = _e325;
                                            } else {
                                                let _e266 = local_22;
                                                let _e267 = local_4;
                                                if (_e266 < _e267) {
                                                } else {
                                                    phi_942_ = true;
                                                    break;
                                                }
                                                let _e269 = local_22;
                                                let _e272 = global_9.member[_e269];
                                                local_27 = _e272;
                                                let _e273 = local_20;
                                                if (_e273 < 4096u) {
                                                } else {
                                                    phi_942_ = true;
                                                    break;
                                                }
                                                let _e275 = local_20;
                                                let _e277 = local_27;
                                                global_8[_e275] = _e277;
                                                let _e278 = local_22;
                                                let _e279 = local_5;
                                                if (_e278 < _e279) {
                                                } else {
                                                    phi_942_ = true;
                                                    break;
                                                }
                                                let _e281 = local_22;
                                                let _e284 = global_10.member[_e281];
                                                local_28 = _e284;
                                                let _e285 = local_20;
                                                let _e286 = (2048u + _e285);
                                                local_29 = _e286;
                                                if (_e286 < 4096u) {
                                                } else {
                                                    phi_942_ = true;
                                                    break;
                                                }
                                                let _e288 = local_29;
                                                let _e290 = local_28;
                                                global_8[_e288] = _e290;
                                            }
                                            let _e326 = local_20;
                                            phi_250_ = (_e326 + 256u);
                                        } else {
                                            phi_250_ = u32();
                                        }
                                        let _e329 = phi_250_;
                                        phi_161_ = _e329;
                                        phi_251_ = _e258;
                                    } else {
                                        phi_161_ = u32();
                                        phi_251_ = false;
                                    }
                                    let _e331 = phi_161_;
                                    let _e333 = phi_251_;
                                    local_30 = _e333;
                                    continue;
                                    continuing {
                                        let _e334 = local_30;
                                        phi_160_ = _e331;
                                        phi_942_ = _e242;
                                        break if !(_e334);
                                    }
                                }
                                let _e337 = phi_942_;
                                phi_1009_ = _e337;
                                if _e337 {
                                    break;
                                }
                                storageBarrier();
                                workgroupBarrier();
                                let _e338 = local_16;
                                if (_e338 == 0u) {
                                    phi_984_ = _e337;
                                    phi_263_ = 2u;
                                    loop {
                                        let _e589 = phi_984_;
                                        let _e591 = phi_263_;
                                        local_31 = _e591;
                                        let _e592 = local_31;
                                        let _e593 = (_e592 <= 2048u);
                                        local_32 = _e593;
                                        if _e593 {
                                            let _e594 = local_31;
                                            phi_983_ = _e589;
                                            phi_279_ = (_e594 / 2u);
                                            loop {
                                                let _e597 = phi_983_;
                                                let _e599 = phi_279_;
                                                local_33 = _e599;
                                                local_131 = _e599;
                                                let _e600 = local_33;
                                                if (_e600 > 0u) {
                                                    let _e602 = local_33;
                                                    let _e604 = ((2u * _e602) <= 8u);
                                                    local_34 = _e604;
                                                    if _e604 {
                                                        phi_988_ = _e597;
                                                        phi_417_ = u32();
                                                    } else {
                                                        phi_294_ = _e165;
                                                        loop {
                                                            let _e606 = phi_294_;
                                                            local_35 = _e606;
                                                            let _e607 = local_35;
                                                            let _e608 = (_e607 < 1024u);
                                                            local_36 = _e608;
                                                            if _e608 {
                                                                let _e609 = local_33;
                                                                let _e610 = (_e609 - 1u);
                                                                let _e612 = local_35;
                                                                let _e615 = ((_e612 & ~(_e610)) << bitcast<u32>(1i));
                                                                local_37 = _e615;
                                                                let _e616 = local_35;
                                                                let _e617 = (_e616 & _e610);
                                                                local_38 = _e617;
                                                                local_39 = (_e615 + _e617);
                                                                let _e619 = local_31;
                                                                let _e622 = local_33;
                                                                if (_e622 == (_e619 >> bitcast<u32>(1i))) {
                                                                    let _e629 = local_37;
                                                                    let _e630 = local_31;
                                                                    let _e633 = local_38;
                                                                    let _e635 = local_39;
                                                                    phi_328_ = type_12(_e635, (((_e629 + _e630) - 1u) - _e633));
                                                                } else {
                                                                    let _e624 = local_39;
                                                                    let _e625 = local_33;
                                                                    let _e627 = local_39;
                                                                    phi_328_ = type_12(_e627, (_e624 + _e625));
                                                                }
                                                                let _e638 = phi_328_;
                                                                local_40 = _e638.member;
                                                                let _e641 = local_19;
                                                                let _e642 = (_e641 + _e638.member_1);
                                                                local_41 = _e642;
                                                                let _e643 = local_15;
                                                                if (_e642 < _e643) {
                                                                    let _e645 = local_19;
                                                                    let _e646 = local_40;
                                                                    let _e648 = local_19;
                                                                    let _e649 = ((_e645 + _e646) - _e648);
                                                                    local_42 = _e649;
                                                                    let _e650 = (_e649 < 4096u);
                                                                    local_43 = _e650;
                                                                    if _e650 {
                                                                    } else {
                                                                        phi_976_ = true;
                                                                        break;
                                                                    }
                                                                    let _e651 = local_42;
                                                                    let _e653 = global_8[_e651];
                                                                    local_44 = _e653;
                                                                    let _e654 = local_42;
                                                                    let _e655 = (2048u + _e654);
                                                                    local_45 = _e655;
                                                                    let _e656 = (_e655 < 4096u);
                                                                    local_46 = _e656;
                                                                    if _e656 {
                                                                    } else {
                                                                        phi_976_ = true;
                                                                        break;
                                                                    }
                                                                    let _e657 = local_45;
                                                                    let _e659 = global_8[_e657];
                                                                    local_47 = _e659;
                                                                    let _e660 = local_41;
                                                                    let _e661 = local_19;
                                                                    let _e662 = (_e660 - _e661);
                                                                    local_48 = _e662;
                                                                    let _e663 = (_e662 < 4096u);
                                                                    local_49 = _e663;
                                                                    if _e663 {
                                                                    } else {
                                                                        phi_976_ = true;
                                                                        break;
                                                                    }
                                                                    let _e664 = local_48;
                                                                    let _e666 = global_8[_e664];
                                                                    local_50 = _e666;
                                                                    let _e667 = local_48;
                                                                    let _e668 = (2048u + _e667);
                                                                    local_51 = _e668;
                                                                    let _e669 = (_e668 < 4096u);
                                                                    local_52 = _e669;
                                                                    if _e669 {
                                                                    } else {
                                                                        phi_976_ = true;
                                                                        break;
                                                                    }
                                                                    let _e670 = local_51;
                                                                    let _e672 = global_8[_e670];
                                                                    local_53 = _e672;
                                                                    let _e673 = local_44;
                                                                    let _e674 = local_50;
                                                                    if (_e673 > _e674) {
                                                                        phi_383_ = true;
                                                                    } else {
                                                                        let _e676 = local_44;
                                                                        let _e677 = local_50;
                                                                        if (_e676 == _e677) {
                                                                            let _e679 = local_47;
                                                                            let _e680 = local_53;
                                                                            phi_382_ = (_e679 > _e680);
                                                                        } else {
                                                                            phi_382_ = false;
                                                                        }
                                                                        let _e683 = phi_382_;
                                                                        phi_383_ = _e683;
                                                                    }
                                                                    let _e685 = phi_383_;
                                                                    if _e685 {
                                                                        let _e686 = local_43;
                                                                        if _e686 {
                                                                        } else {
                                                                            phi_976_ = true;
                                                                            break;
                                                                        }
                                                                        let _e687 = local_50;
                                                                        global_8[_e651] = _e687;
                                                                        let _e688 = local_46;
                                                                        if _e688 {
                                                                        } else {
                                                                            phi_976_ = true;
                                                                            break;
                                                                        }
                                                                        let _e689 = local_53;
                                                                        global_8[_e657] = _e689;
                                                                        let _e690 = local_49;
                                                                        if _e690 {
                                                                        } else {
                                                                            phi_976_ = true;
                                                                            break;
                                                                        }
                                                                        let _e691 = local_44;
                                                                        global_8[_e664] = _e691;
                                                                        let _e692 = local_52;
                                                                        if _e692 {
                                                                        } else {
                                                                            phi_976_ = true;
                                                                            break;
                                                                        }
                                                                        let _e693 = local_47;
                                                                        global_8[_e670] = _e693;
                                                                    }
                                                                }
                                                                let _e694 = local_35;
                                                                phi_295_ = (_e694 + 256u);
                                                            } else {
                                                                phi_295_ = u32();
                                                            }
                                                            let _e697 = phi_295_;
                                                            continue;
                                                            continuing {
                                                                let _e698 = local_36;
                                                                phi_294_ = _e697;
                                                                phi_976_ = _e597;
                                                                break if !(_e698);
                                                            }
                                                        }
                                                        let _e701 = phi_976_;
                                                        phi_986_ = _e701;
                                                        phi_940_ = bool();
                                                        if _e701 {
                                                            break;
                                                        }
                                                        storageBarrier();
                                                        workgroupBarrier();
                                                        let _e702 = local_33;
                                                        phi_988_ = _e701;
                                                        phi_417_ = (_e702 / 2u);
                                                    }
                                                    let _e705 = phi_988_;
                                                    let _e707 = phi_417_;
                                                    let _e708 = local_34;
                                                    phi_987_ = _e705;
                                                    phi_280_ = _e707;
                                                    phi_419_ = select(true, false, _e708);
                                                    phi_420_ = _e604;
                                                } else {
                                                    phi_987_ = _e597;
                                                    phi_280_ = u32();
                                                    phi_419_ = false;
                                                    phi_420_ = false;
                                                }
                                                let _e711 = phi_987_;
                                                let _e713 = phi_280_;
                                                let _e715 = phi_419_;
                                                let _e717 = phi_420_;
                                                local_54 = _e715;
                                                continue;
                                                continuing {
                                                    let _e718 = local_54;
                                                    phi_983_ = _e711;
                                                    phi_279_ = _e713;
                                                    phi_986_ = _e711;
                                                    phi_940_ = _e717;
                                                    break if !(_e718);
                                                }
                                            }
                                            let _e721 = phi_986_;
                                            let _e723 = phi_940_;
                                            local_129 = _e723;
                                            phi_1000_ = _e721;
                                            if _e721 {
                                                break;
                                            }
                                            let _e724 = local_129;
                                            if _e724 {
                                                let _e725 = local;
                                                let _e727 = local_19;
                                                local_55 = (_e727 + (_e725 * 8u));
                                                phi_996_ = _e721;
                                                let _e999 = local_131;
                                                phi_427_ = _e999;
                                                loop {
                                                    let _e730 = phi_996_;
                                                    let _e732 = phi_427_;
                                                    local_56 = _e732;
                                                    let _e733 = local_56;
                                                    let _e734 = (_e733 > 0u);
                                                    local_57 = _e734;
                                                    if _e734 {
                                                        phi_437_ = 0u;
                                                        loop {
                                                            let _e736 = phi_437_;
                                                            local_58 = _e736;
                                                            let _e737 = local_58;
                                                            let _e738 = (_e737 < 4u);
                                                            local_59 = _e738;
                                                            if _e738 {
                                                                let _e739 = local_56;
                                                                let _e740 = (_e739 - 1u);
                                                                let _e742 = local_58;
                                                                let _e745 = ((_e742 & ~(_e740)) << bitcast<u32>(1i));
                                                                local_60 = _e745;
                                                                let _e746 = local_58;
                                                                let _e747 = (_e746 & _e740);
                                                                local_61 = _e747;
                                                                local_62 = (_e745 + _e747);
                                                                let _e749 = local_31;
                                                                let _e752 = local_56;
                                                                if (_e752 == (_e749 >> bitcast<u32>(1i))) {
                                                                    let _e759 = local_60;
                                                                    let _e760 = local_31;
                                                                    let _e763 = local_61;
                                                                    let _e765 = local_62;
                                                                    phi_471_ = type_12(_e765, (((_e759 + _e760) - 1u) - _e763));
                                                                } else {
                                                                    let _e754 = local_62;
                                                                    let _e755 = local_56;
                                                                    let _e757 = local_62;
                                                                    phi_471_ = type_12(_e757, (_e754 + _e755));
                                                                }
                                                                let _e768 = phi_471_;
                                                                local_63 = _e768.member;
                                                                let _e771 = local_55;
                                                                let _e772 = (_e771 + _e768.member_1);
                                                                local_64 = _e772;
                                                                let _e773 = local_15;
                                                                if (_e772 < _e773) {
                                                                    let _e775 = local_55;
                                                                    let _e776 = local_63;
                                                                    let _e778 = local_19;
                                                                    let _e779 = ((_e775 + _e776) - _e778);
                                                                    local_65 = _e779;
                                                                    let _e780 = (_e779 < 4096u);
                                                                    local_66 = _e780;
                                                                    if _e780 {
                                                                    } else {
                                                                        phi_989_ = true;
                                                                        break;
                                                                    }
                                                                    let _e781 = local_65;
                                                                    let _e783 = global_8[_e781];
                                                                    local_67 = _e783;
                                                                    let _e784 = local_65;
                                                                    let _e785 = (2048u + _e784);
                                                                    local_68 = _e785;
                                                                    let _e786 = (_e785 < 4096u);
                                                                    local_69 = _e786;
                                                                    if _e786 {
                                                                    } else {
                                                                        phi_989_ = true;
                                                                        break;
                                                                    }
                                                                    let _e787 = local_68;
                                                                    let _e789 = global_8[_e787];
                                                                    local_70 = _e789;
                                                                    let _e790 = local_64;
                                                                    let _e791 = local_19;
                                                                    let _e792 = (_e790 - _e791);
                                                                    local_71 = _e792;
                                                                    let _e793 = (_e792 < 4096u);
                                                                    local_72 = _e793;
                                                                    if _e793 {
                                                                    } else {
                                                                        phi_989_ = true;
                                                                        break;
                                                                    }
                                                                    let _e794 = local_71;
                                                                    let _e796 = global_8[_e794];
                                                                    local_73 = _e796;
                                                                    let _e797 = local_71;
                                                                    let _e798 = (2048u + _e797);
                                                                    local_74 = _e798;
                                                                    let _e799 = (_e798 < 4096u);
                                                                    local_75 = _e799;
                                                                    if _e799 {
                                                                    } else {
                                                                        phi_989_ = true;
                                                                        break;
                                                                    }
                                                                    let _e800 = local_74;
                                                                    let _e802 = global_8[_e800];
                                                                    local_76 = _e802;
                                                                    let _e803 = local_67;
                                                                    let _e804 = local_73;
                                                                    if (_e803 > _e804) {
                                                                        phi_526_ = true;
                                                                    } else {
                                                                        let _e806 = local_67;
                                                                        let _e807 = local_73;
                                                                        if (_e806 == _e807) {
                                                                            let _e809 = local_70;
                                                                            let _e810 = local_76;
                                                                            phi_525_ = (_e809 > _e810);
                                                                        } else {
                                                                            phi_525_ = false;
                                                                        }
                                                                        let _e813 = phi_525_;
                                                                        phi_526_ = _e813;
                                                                    }
                                                                    let _e815 = phi_526_;
                                                                    if _e815 {
                                                                        let _e816 = local_66;
                                                                        if _e816 {
                                                                        } else {
                                                                            phi_989_ = true;
                                                                            break;
                                                                        }
                                                                        let _e817 = local_73;
                                                                        global_8[_e781] = _e817;
                                                                        let _e818 = local_69;
                                                                        if _e818 {
                                                                        } else {
                                                                            phi_989_ = true;
                                                                            break;
                                                                        }
                                                                        let _e819 = local_76;
                                                                        global_8[_e787] = _e819;
                                                                        let _e820 = local_72;
                                                                        if _e820 {
                                                                        } else {
                                                                            phi_989_ = true;
                                                                            break;
                                                                        }
                                                                        let _e821 = local_67;
                                                                        global_8[_e794] = _e821;
                                                                        let _e822 = local_75;
                                                                        if _e822 {
                                                                        } else {
                                                                            phi_989_ = true;
                                                                            break;
                                                                        }
                                                                        let _e823 = local_70;
                                                                        global_8[_e800] = _e823;
                                                                    }
                                                                }
                                                                let _e824 = local_58;
                                                                phi_438_ = (_e824 + 1u);
                                                            } else {
                                                                phi_438_ = u32();
                                                            }
                                                            let _e827 = phi_438_;
                                                            continue;
                                                            continuing {
                                                                let _e828 = local_59;
                                                                phi_437_ = _e827;
                                                                phi_989_ = _e730;
                                                                break if !(_e828);
                                                            }
                                                        }
                                                        let _e831 = phi_989_;
                                                        phi_998_ = _e831;
                                                        if _e831 {
                                                            break;
                                                        }
                                                        let _e832 = local_56;
                                                        phi_999_ = _e831;
                                                        phi_428_ = (_e832 / 2u);
                                                    } else {
                                                        phi_999_ = _e730;
                                                        phi_428_ = u32();
                                                    }
                                                    let _e835 = phi_999_;
                                                    let _e837 = phi_428_;
                                                    continue;
                                                    continuing {
                                                        let _e838 = local_57;
                                                        phi_996_ = _e835;
                                                        phi_427_ = _e837;
                                                        phi_998_ = _e835;
                                                        break if !(_e838);
                                                    }
                                                }
                                                let _e841 = phi_998_;
                                                phi_1000_ = _e841;
                                                if _e841 {
                                                    break;
                                                }
                                                storageBarrier();
                                                workgroupBarrier();
                                                phi_1002_ = _e841;
                                            } else {
                                                phi_1002_ = _e721;
                                            }
                                            let _e843 = phi_1002_;
                                            let _e844 = local_31;
                                            phi_1001_ = _e843;
                                            phi_264_ = (_e844 * 2u);
                                        } else {
                                            phi_1001_ = _e589;
                                            phi_264_ = u32();
                                        }
                                        let _e847 = phi_1001_;
                                        let _e849 = phi_264_;
                                        continue;
                                        continuing {
                                            let _e850 = local_32;
                                            phi_984_ = _e847;
                                            phi_263_ = _e849;
                                            phi_1000_ = _e847;
                                            break if !(_e850);
                                        }
                                    }
                                    let _e853 = phi_1000_;
                                    phi_1009_ = _e853;
                                    if _e853 {
                                        break;
                                    }
                                    phi_1007_ = _e853;
                                } else {
                                    phi_960_ = _e337;
                                    phi_569_ = 1024u;
                                    loop {
                                        let _e341 = phi_960_;
                                        let _e343 = phi_569_;
                                        local_77 = _e343;
                                        local_130 = _e343;
                                        let _e344 = local_77;
                                        if (_e344 > 0u) {
                                            let _e346 = local_77;
                                            let _e348 = ((2u * _e346) <= 8u);
                                            local_78 = _e348;
                                            if _e348 {
                                                phi_964_ = _e341;
                                                phi_707_ = u32();
                                            } else {
                                                phi_584_ = _e165;
                                                loop {
                                                    let _e350 = phi_584_;
                                                    local_79 = _e350;
                                                    let _e351 = local_79;
                                                    let _e352 = (_e351 < 1024u);
                                                    local_80 = _e352;
                                                    if _e352 {
                                                        let _e353 = local_77;
                                                        let _e354 = (_e353 - 1u);
                                                        let _e356 = local_79;
                                                        let _e359 = ((_e356 & ~(_e354)) << bitcast<u32>(1i));
                                                        local_81 = _e359;
                                                        let _e360 = local_79;
                                                        let _e361 = (_e360 & _e354);
                                                        local_82 = _e361;
                                                        local_83 = (_e359 + _e361);
                                                        let _e363 = local_16;
                                                        let _e366 = local_77;
                                                        if (_e366 == (_e363 >> bitcast<u32>(1i))) {
                                                            let _e373 = local_81;
                                                            let _e374 = local_16;
                                                            let _e377 = local_82;
                                                            let _e379 = local_83;
                                                            phi_618_ = type_12(_e379, (((_e373 + _e374) - 1u) - _e377));
                                                        } else {
                                                            let _e368 = local_83;
                                                            let _e369 = local_77;
                                                            let _e371 = local_83;
                                                            phi_618_ = type_12(_e371, (_e368 + _e369));
                                                        }
                                                        let _e382 = phi_618_;
                                                        local_84 = _e382.member;
                                                        let _e385 = local_19;
                                                        let _e386 = (_e385 + _e382.member_1);
                                                        local_85 = _e386;
                                                        let _e387 = local_15;
                                                        if (_e386 < _e387) {
                                                            let _e389 = local_19;
                                                            let _e390 = local_84;
                                                            let _e392 = local_19;
                                                            let _e393 = ((_e389 + _e390) - _e392);
                                                            local_86 = _e393;
                                                            let _e394 = (_e393 < 4096u);
                                                            local_87 = _e394;
                                                            if _e394 {
                                                            } else {
                                                                phi_953_ = true;
                                                                break;
                                                            }
                                                            let _e395 = local_86;
                                                            let _e397 = global_8[_e395];
                                                            local_88 = _e397;
                                                            let _e398 = local_86;
                                                            let _e399 = (2048u + _e398);
                                                            local_89 = _e399;
                                                            let _e400 = (_e399 < 4096u);
                                                            local_90 = _e400;
                                                            if _e400 {
                                                            } else {
                                                                phi_953_ = true;
                                                                break;
                                                            }
                                                            let _e401 = local_89;
                                                            let _e403 = global_8[_e401];
                                                            local_91 = _e403;
                                                            let _e404 = local_85;
                                                            let _e405 = local_19;
                                                            let _e406 = (_e404 - _e405);
                                                            local_92 = _e406;
                                                            let _e407 = (_e406 < 4096u);
                                                            local_93 = _e407;
                                                            if _e407 {
                                                            } else {
                                                                phi_953_ = true;
                                                                break;
                                                            }
                                                            let _e408 = local_92;
                                                            let _e410 = global_8[_e408];
                                                            local_94 = _e410;
                                                            let _e411 = local_92;
                                                            let _e412 = (2048u + _e411);
                                                            local_95 = _e412;
                                                            let _e413 = (_e412 < 4096u);
                                                            local_96 = _e413;
                                                            if _e413 {
                                                            } else {
                                                                phi_953_ = true;
                                                                break;
                                                            }
                                                            let _e414 = local_95;
                                                            let _e416 = global_8[_e414];
                                                            local_97 = _e416;
                                                            let _e417 = local_88;
                                                            let _e418 = local_94;
                                                            if (_e417 > _e418) {
                                                                phi_673_ = true;
                                                            } else {
                                                                let _e420 = local_88;
                                                                let _e421 = local_94;
                                                                if (_e420 == _e421) {
                                                                    let _e423 = local_91;
                                                                    let _e424 = local_97;
                                                                    phi_672_ = (_e423 > _e424);
                                                                } else {
                                                                    phi_672_ = false;
                                                                }
                                                                let _e427 = phi_672_;
                                                                phi_673_ = _e427;
                                                            }
                                                            let _e429 = phi_673_;
                                                            if _e429 {
                                                                let _e430 = local_87;
                                                                if _e430 {
                                                                } else {
                                                                    phi_953_ = true;
                                                                    break;
                                                                }
                                                                let _e431 = local_94;
                                                                global_8[_e395] = _e431;
                                                                let _e432 = local_90;
                                                                if _e432 {
                                                                } else {
                                                                    phi_953_ = true;
                                                                    break;
                                                                }
                                                                let _e433 = local_97;
                                                                global_8[_e401] = _e433;
                                                                let _e434 = local_93;
                                                                if _e434 {
                                                                } else {
                                                                    phi_953_ = true;
                                                                    break;
                                                                }
                                                                let _e435 = local_88;
                                                                global_8[_e408] = _e435;
                                                                let _e436 = local_96;
                                                                if _e436 {
                                                                } else {
                                                                    phi_953_ = true;
                                                                    break;
                                                                }
                                                                let _e437 = local_91;
                                                                global_8[_e414] = _e437;
                                                            }
                                                        }
                                                        let _e438 = local_79;
                                                        phi_585_ = (_e438 + 256u);
                                                    } else {
                                                        phi_585_ = u32();
                                                    }
                                                    let _e441 = phi_585_;
                                                    continue;
                                                    continuing {
                                                        let _e442 = local_80;
                                                        phi_584_ = _e441;
                                                        phi_953_ = _e341;
                                                        break if !(_e442);
                                                    }
                                                }
                                                let _e445 = phi_953_;
                                                phi_962_ = _e445;
                                                phi_939_ = bool();
                                                if _e445 {
                                                    break;
                                                }
                                                storageBarrier();
                                                workgroupBarrier();
                                                let _e446 = local_77;
                                                phi_964_ = _e445;
                                                phi_707_ = (_e446 / 2u);
                                            }
                                            let _e449 = phi_964_;
                                            let _e451 = phi_707_;
                                            let _e452 = local_78;
                                            phi_963_ = _e449;
                                            phi_570_ = _e451;
                                            phi_709_ = select(true, false, _e452);
                                            phi_710_ = _e348;
                                        } else {
                                            phi_963_ = _e341;
                                            phi_570_ = u32();
                                            phi_709_ = false;
                                            phi_710_ = false;
                                        }
                                        let _e455 = phi_963_;
                                        let _e457 = phi_570_;
                                        let _e459 = phi_709_;
                                        let _e461 = phi_710_;
                                        local_98 = _e459;
                                        continue;
                                        continuing {
                                            let _e462 = local_98;
                                            phi_960_ = _e455;
                                            phi_569_ = _e457;
                                            phi_962_ = _e455;
                                            phi_939_ = _e461;
                                            break if !(_e462);
                                        }
                                    }
                                    let _e465 = phi_962_;
                                    let _e467 = phi_939_;
                                    local_128 = _e467;
                                    phi_1009_ = _e465;
                                    if _e465 {
                                        break;
                                    }
                                    let _e468 = local_128;
                                    if _e468 {
                                        let _e469 = local;
                                        let _e471 = local_19;
                                        local_99 = (_e471 + (_e469 * 8u));
                                        phi_972_ = _e465;
                                        let _e967 = local_130;
                                        phi_717_ = _e967;
                                        loop {
                                            let _e474 = phi_972_;
                                            let _e476 = phi_717_;
                                            local_100 = _e476;
                                            let _e477 = local_100;
                                            let _e478 = (_e477 > 0u);
                                            local_101 = _e478;
                                            if _e478 {
                                                phi_727_ = 0u;
                                                loop {
                                                    let _e480 = phi_727_;
                                                    local_102 = _e480;
                                                    let _e481 = local_102;
                                                    let _e482 = (_e481 < 4u);
                                                    local_103 = _e482;
                                                    if _e482 {
                                                        let _e483 = local_100;
                                                        let _e484 = (_e483 - 1u);
                                                        let _e486 = local_102;
                                                        let _e489 = ((_e486 & ~(_e484)) << bitcast<u32>(1i));
                                                        local_104 = _e489;
                                                        let _e490 = local_102;
                                                        let _e491 = (_e490 & _e484);
                                                        local_105 = _e491;
                                                        local_106 = (_e489 + _e491);
                                                        let _e493 = local_16;
                                                        let _e496 = local_100;
                                                        if (_e496 == (_e493 >> bitcast<u32>(1i))) {
                                                            let _e503 = local_104;
                                                            let _e504 = local_16;
                                                            let _e507 = local_105;
                                                            let _e509 = local_106;
                                                            phi_761_ = type_12(_e509, (((_e503 + _e504) - 1u) - _e507));
                                                        } else {
                                                            let _e498 = local_106;
                                                            let _e499 = local_100;
                                                            let _e501 = local_106;
                                                            phi_761_ = type_12(_e501, (_e498 + _e499));
                                                        }
                                                        let _e512 = phi_761_;
                                                        local_107 = _e512.member;
                                                        let _e515 = local_99;
                                                        let _e516 = (_e515 + _e512.member_1);
                                                        local_108 = _e516;
                                                        let _e517 = local_15;
                                                        if (_e516 < _e517) {
                                                            let _e519 = local_99;
                                                            let _e520 = local_107;
                                                            let _e522 = local_19;
                                                            let _e523 = ((_e519 + _e520) - _e522);
                                                            local_109 = _e523;
                                                            let _e524 = (_e523 < 4096u);
                                                            local_110 = _e524;
                                                            if _e524 {
                                                            } else {
                                                                phi_965_ = true;
                                                                break;
                                                            }
                                                            let _e525 = local_109;
                                                            let _e527 = global_8[_e525];
                                                            local_111 = _e527;
                                                            let _e528 = local_109;
                                                            let _e529 = (2048u + _e528);
                                                            local_112 = _e529;
                                                            let _e530 = (_e529 < 4096u);
                                                            local_113 = _e530;
                                                            if _e530 {
                                                            } else {
                                                                phi_965_ = true;
                                                                break;
                                                            }
                                                            let _e531 = local_112;
                                                            let _e533 = global_8[_e531];
                                                            local_114 = _e533;
                                                            let _e534 = local_108;
                                                            let _e535 = local_19;
                                                            let _e536 = (_e534 - _e535);
                                                            local_115 = _e536;
                                                            let _e537 = (_e536 < 4096u);
                                                            local_116 = _e537;
                                                            if _e537 {
                                                            } else {
                                                                phi_965_ = true;
                                                                break;
                                                            }
                                                            let _e538 = local_115;
                                                            let _e540 = global_8[_e538];
                                                            local_117 = _e540;
                                                            let _e541 = local_115;
                                                            let _e542 = (2048u + _e541);
                                                            local_118 = _e542;
                                                            let _e543 = (_e542 < 4096u);
                                                            local_119 = _e543;
                                                            if _e543 {
                                                            } else {
                                                                phi_965_ = true;
                                                                break;
                                                            }
                                                            let _e544 = local_118;
                                                            let _e546 = global_8[_e544];
                                                            local_120 = _e546;
                                                            let _e547 = local_111;
                                                            let _e548 = local_117;
                                                            if (_e547 > _e548) {
                                                                phi_816_ = true;
                                                            } else {
                                                                let _e550 = local_111;
                                                                let _e551 = local_117;
                                                                if (_e550 == _e551) {
                                                                    let _e553 = local_114;
                                                                    let _e554 = local_120;
                                                                    phi_815_ = (_e553 > _e554);
                                                                } else {
                                                                    phi_815_ = false;
                                                                }
                                                                let _e557 = phi_815_;
                                                                phi_816_ = _e557;
                                                            }
                                                            let _e559 = phi_816_;
                                                            if _e559 {
                                                                let _e560 = local_110;
                                                                if _e560 {
                                                                } else {
                                                                    phi_965_ = true;
                                                                    break;
                                                                }
                                                                let _e561 = local_117;
                                                                global_8[_e525] = _e561;
                                                                let _e562 = local_113;
                                                                if _e562 {
                                                                } else {
                                                                    phi_965_ = true;
                                                                    break;
                                                                }
                                                                let _e563 = local_120;
                                                                global_8[_e531] = _e563;
                                                                let _e564 = local_116;
                                                                if _e564 {
                                                                } else {
                                                                    phi_965_ = true;
                                                                    break;
                                                                }
                                                                let _e565 = local_111;
                                                                global_8[_e538] = _e565;
                                                                let _e566 = local_119;
                                                                if _e566 {
                                                                } else {
                                                                    phi_965_ = true;
                                                                    break;
                                                                }
                                                                let _e567 = local_114;
                                                                global_8[_e544] = _e567;
                                                            }
                                                        }
                                                        let _e568 = local_102;
                                                        phi_728_ = (_e568 + 1u);
                                                    } else {
                                                        phi_728_ = u32();
                                                    }
                                                    let _e571 = phi_728_;
                                                    continue;
                                                    continuing {
                                                        let _e572 = local_103;
                                                        phi_727_ = _e571;
                                                        phi_965_ = _e474;
                                                        break if !(_e572);
                                                    }
                                                }
                                                let _e575 = phi_965_;
                                                phi_974_ = _e575;
                                                if _e575 {
                                                    break;
                                                }
                                                let _e576 = local_100;
                                                phi_975_ = _e575;
                                                phi_718_ = (_e576 / 2u);
                                            } else {
                                                phi_975_ = _e474;
                                                phi_718_ = u32();
                                            }
                                            let _e579 = phi_975_;
                                            let _e581 = phi_718_;
                                            continue;
                                            continuing {
                                                let _e582 = local_101;
                                                phi_972_ = _e579;
                                                phi_717_ = _e581;
                                                phi_974_ = _e579;
                                                break if !(_e582);
                                            }
                                        }
                                        let _e585 = phi_974_;
                                        phi_1009_ = _e585;
                                        if _e585 {
                                            break;
                                        }
                                        storageBarrier();
                                        workgroupBarrier();
                                        phi_1008_ = _e585;
                                    } else {
                                        phi_1008_ = _e465;
                                    }
                                    let _e587 = phi_1008_;
                                    phi_1007_ = _e587;
                                }
                                let _e855 = phi_1007_;
                                phi_851_ = _e165;
                                loop {
                                    let _e857 = phi_851_;
                                    local_121 = _e857;
                                    let _e858 = local_121;
                                    if (_e858 < 2048u) {
                                        let _e860 = local_19;
                                        let _e861 = local_121;
                                        let _e863 = local_15;
                                        let _e864 = ((_e860 + _e861) < _e863);
                                        if _e864 {
                                            let _e865 = local_13;
                                            let _e866 = local_19;
                                            let _e868 = local_121;
                                            local_122 = ((_e865 + _e866) + _e868);
                                            let _e870 = local_121;
                                            if (_e870 < 4096u) {
                                            } else {
                                                phi_1003_ = true;
                                                break;
                                            }
                                            let _e872 = local_121;
                                            let _e874 = global_8[_e872];
                                            local_123 = _e874;
                                            let _e875 = local_122;
                                            let _e876 = local_4;
                                            if (_e875 < _e876) {
                                            } else {
                                                phi_1003_ = true;
                                                break;
                                            }
                                            let _e878 = local_122;
                                            let _e881 = local_123;
                                            global_9.member[_e878] = _e881;
                                            let _e882 = local_121;
                                            let _e883 = (2048u + _e882);
                                            local_124 = _e883;
                                            if (_e883 < 4096u) {
                                            } else {
                                                phi_1003_ = true;
                                                break;
                                            }
                                            let _e885 = local_124;
                                            let _e887 = global_8[_e885];
                                            local_125 = _e887;
                                            let _e888 = local_122;
                                            let _e889 = local_5;
                                            if (_e888 < _e889) {
                                            } else {
                                                phi_1003_ = true;
                                                break;
                                            }
                                            let _e891 = local_122;
                                            let _e894 = local_125;
                                            global_10.member[_e891] = _e894;
                                            let _e895 = local_121;
                                            phi_897_ = (_e895 + 256u);
                                        } else {
                                            phi_897_ = u32();
                                        }
                                        let _e898 = phi_897_;
                                        phi_852_ = _e898;
                                        phi_898_ = _e864;
                                    } else {
                                        phi_852_ = u32();
                                        phi_898_ = false;
                                    }
                                    let _e900 = phi_852_;
                                    let _e902 = phi_898_;
                                    local_126 = _e902;
                                    continue;
                                    continuing {
                                        let _e903 = local_126;
                                        phi_851_ = _e900;
                                        phi_1003_ = _e855;
                                        break if !(_e903);
                                    }
                                }
                                let _e906 = phi_1003_;
                                phi_1009_ = _e906;
                                if _e906 {
                                    break;
                                }
                                storageBarrier();
                                workgroupBarrier();
                                let _e907 = local_18;
                                let _e908 = local_6;
                                phi_1011_ = _e906;
                                phi_904_ = (_e907 + _e908);
                            } else {
                                phi_1011_ = _e242;
                                phi_904_ = u32();
                            }
                            let _e911 = phi_1011_;
                            let _e913 = phi_904_;
                            phi_1010_ = _e911;
                            phi_146_ = _e913;
                            phi_905_ = _e249;
                        } else {
                            phi_1010_ = _e242;
                            phi_146_ = u32();
                            phi_905_ = false;
                        }
                        let _e915 = phi_1010_;
                        let _e917 = phi_146_;
                        let _e919 = phi_905_;
                        local_127 = _e919;
                        continue;
                        continuing {
                            let _e920 = local_127;
                            phi_948_ = _e915;
                            phi_145_ = _e917;
                            phi_1009_ = _e915;
                            break if !(_e920);
                        }
                    }
                    let _e923 = phi_1009_;
                    phi_1012_ = _e923;
                    if _e923 {
                        break;
                    }
                    let _e924 = local_9;
                    let _e925 = local_7;
                    phi_1013_ = _e923;
                    phi_92_ = (_e924 + _e925);
                } else {
                    phi_1013_ = _e189;
                    phi_92_ = u32();
                }
                let _e928 = phi_1013_;
                let _e930 = phi_92_;
                continue;
                continuing {
                    let _e931 = local_10;
                    phi_950_ = _e928;
                    phi_91_ = _e930;
                    phi_1012_ = _e928;
                    break if !(_e931);
                }
            }
            let _e934 = phi_1012_;
            if _e934 {
                break;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(256, 1, 1) 
fn sort_global_local(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>, @builtin(num_workgroups) param_2: vec3<u32>) {
    global = param;
    global_1 = param_1;
    global_2 = param_2;
    function_();
}
