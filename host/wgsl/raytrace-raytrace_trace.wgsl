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
    member: array<f32, 3>,
    member_1: f32,
}

struct type_17 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: f32,
}

struct type_18 {
    member: u32,
    member_1: array<f32, 3>,
}

struct type_19 {
    member: f32,
    member_1: f32,
}

struct type_21 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: u32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: type_5,
    member_9: array<u32, 14>,
    member_10: array<u32, 2>,
}

struct type_22 {
    member: type_21,
}

struct type_24 {
    member: u32,
    member_1: type_17,
}

struct type_25 {
    member: array<f32, 3>,
    member_1: bool,
}

struct type_36 {
    member: array<atomic<u32>>,
}

var<private> global: u32;
var<private> global_1: vec3<u32>;
@group(0) @binding(4) 
var<storage, read_write> global_2: type_7;
@group(0) @binding(1) 
var<storage> global_3: type_7;
@group(0) @binding(0) 
var<storage> global_4: type_7;
var<immediate> global_5: type_22;
@group(0) @binding(2) 
var<storage> global_6: type_7;
@group(0) @binding(3) 
var<storage> global_7: type_7;
@group(0) @binding(5) 
var<storage, read_write> global_8: type_36;
var<private> global_9: u32 = 2143289344u;
var<private> global_10: u32 = 4286578688u;
var<private> global_11: u32 = 2139095040u;

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
    var local_13: f32;
    var local_14: f32;
    var local_15: f32;
    var local_16: f32;
    var local_17: array<f32, 3>;
    var local_18: u32;
    var local_19: u32;
    var local_20: array<f32, 3>;
    var local_21: u32;
    var local_22: bool;
    var local_23: u32;
    var local_24: f32;
    var local_25: u32;
    var local_26: f32;
    var local_27: u32;
    var local_28: u32;
    var local_29: u32;
    var local_30: f32;
    var local_31: f32;
    var local_32: f32;
    var local_33: f32;
    var local_34: f32;
    var local_35: f32;
    var local_36: f32;
    var local_37: f32;
    var local_38: f32;
    var local_39: f32;
    var local_40: u32;
    var local_41: f32;
    var local_42: f32;
    var local_43: f32;
    var local_44: f32;
    var local_45: f32;
    var local_46: f32;
    var local_47: f32;
    var local_48: u32;
    var local_49: type_14;
    var local_50: u32;
    var local_51: u32;
    var local_52: f32;
    var local_53: u32;
    var local_54: u32;
    var local_55: u32;
    var local_56: f32;
    var local_57: bool;
    var local_58: bool;
    var local_59: f32;
    var local_60: f32;
    var local_61: bool;
    var local_62: bool;
    var local_63: bool;
    var local_64: bool;
    var local_65: u32;
    var local_66: u32;
    var local_67: u32;
    var local_68: u32;
    var local_69: f32;
    var local_70: f32;
    var local_71: bool;
    var local_72: u32;
    var local_73: u32;
    var local_74: u32;
    var local_75: f32;
    var local_76: u32;
    var local_77: f32;
    var local_78: f32;
    var local_79: f32;
    var local_80: u32;
    var local_81: type_14;
    var local_82: u32;
    var local_83: u32;
    var local_84: u32;
    var local_85: f32;
    var local_86: bool;
    var local_87: u32;
    var local_88: f32;
    var local_89: u32;
    var local_90: f32;
    var local_91: u32;
    var local_92: f32;
    var local_93: u32;
    var local_94: f32;
    var local_95: u32;
    var local_96: f32;
    var local_97: bool;
    var local_98: u32;
    var local_99: u32;
    var local_100: f32;
    var local_101: bool;
    var local_102: f32;
    var local_103: f32;
    var local_104: array<f32, 3>;
    var local_105: type_24;
    var local_106: array<f32, 3>;
    var local_107: f32;
    var local_108: f32;
    var local_109: bool;
    var local_110: bool;
    var local_111: bool;
    var local_112: f32;
    var local_113: bool;
    var local_114: bool;
    var local_115: bool;
    var local_116: bool;
    var local_117: bool;
    var local_118: u32;
    var local_119: u32;
    var local_120: f32;
    var local_121: bool;
    var local_122: bool;
    var local_123: bool;
    var local_124: bool;
    var local_125: bool;
    var local_126: bool;
    var local_127: u32;
    var local_128: type_18;
    var local_129: u32;
    var local_130: bool;
    var local_131: u32;
    var local_132: f32;
    var local_133: u32;
    var local_134: f32;
    var local_135: u32;
    var local_136: f32;
    var local_137: u32;
    var local_138: f32;
    var local_139: u32;
    var local_140: f32;
    var local_141: bool;
    var local_142: u32;
    var local_143: u32;
    var local_144: f32;
    var local_145: bool;
    var local_146: f32;
    var local_147: f32;
    var local_148: array<f32, 3>;
    var local_149: type_24;
    var local_150: array<f32, 3>;
    var local_151: f32;
    var local_152: bool;
    var local_153: bool;
    var local_154: array<f32, 3>;
    var local_155: bool;
    var local_156: type_25;
    var local_157: f32;
    var local_158: u32;
    var local_159: u32;
    var local_160: u32;
    var local_161: u32;
    var local_162: u32;
    var local_163: u32;
    var local_164: bool;
    var local_165: bool;
    var local_166: bool;
    var local_167: type_14;
    var local_168: array<f32, 3>;
    var local_169: bool;
    var local_170: bool;
    var local_171: bool;
    var local_172: bool;
    var local_173: bool;
    var local_174: bool;
    var local_175: bool;
    var local_176: bool;
    var local_177: bool;
    var local_178: bool;
    var local_179: bool;
    var local_180: u32;
    var local_181: f32;
    var local_182: f32;
    var local_183: f32;
    var local_184: f32;
    var local_185: f32;
    var local_186: f32;
    var local_187: f32;
    var local_188: f32;
    var local_189: u32;
    var local_190: bool;
    var local_191: bool;
    var local_192: bool;
    var local_193: bool;
    var local_194: bool;
    var local_195: bool;
    var local_196: bool;
    var local_197: bool;
    var local_198: bool;
    var local_199: bool;
    var local_200: bool;
    var local_201: bool;
    var local_202: bool;
    var local_203: bool;
    var local_204: bool;
    var local_205: bool;
    var local_206: bool;
    var local_207: bool;
    var local_208: bool;
    var local_209: bool;
    var local_210: bool;
    var local_211: bool;
    var local_212: bool;
    var local_213: bool;
    var local_214: bool;
    var local_215: bool;
    var local_216: bool;
    var local_217: bool;
    var local_218: bool;
    var local_219: bool;
    var local_220: bool;
    var local_221: bool;
    var local_222: u32;
    var phi_2085_: bool;
    var phi_202_: array<f32, 3>;
    var phi_205_: u32;
    var phi_207_: u32;
    var phi_209_: array<f32, 3>;
    var phi_1855_: bool;
    var phi_1870_: bool;
    var phi_270_: type_19;
    var phi_1885_: bool;
    var phi_1900_: bool;
    var phi_285_: type_19;
    var phi_1915_: bool;
    var phi_1930_: bool;
    var phi_1945_: bool;
    var phi_1960_: bool;
    var phi_1975_: bool;
    var phi_326_: f32;
    var phi_2071_: bool;
    var phi_356_: type_14;
    var phi_359_: u32;
    var phi_361_: u32;
    var phi_363_: f32;
    var phi_365_: u32;
    var phi_367_: u32;
    var phi_369_: u32;
    var phi_371_: f32;
    var phi_449_: f32;
    var phi_450_: f32;
    var phi_470_: f32;
    var phi_471_: f32;
    var phi_1990_: bool;
    var phi_2005_: bool;
    var phi_493_: u32;
    var phi_578_: type_14;
    var phi_581_: u32;
    var phi_583_: u32;
    var phi_585_: u32;
    var phi_587_: f32;
    var phi_668_: bool;
    var phi_669_: bool;
    var phi_671_: bool;
    var phi_672_: bool;
    var phi_673_: bool;
    var phi_674_: bool;
    var phi_689_: bool;
    var phi_717_: f32;
    var phi_718_: f32;
    var phi_735_: bool;
    var phi_749_: bool;
    var phi_754_: f32;
    var phi_764_: bool;
    var phi_778_: bool;
    var phi_783_: f32;
    var phi_793_: bool;
    var phi_807_: bool;
    var phi_812_: f32;
    var phi_823_: f32;
    var phi_826_: type_24;
    var phi_828_: type_24;
    var phi_829_: bool;
    var phi_834_: type_24;
    var phi_852_: bool;
    var phi_887_: bool;
    var phi_889_: bool;
    var phi_890_: bool;
    var phi_891_: bool;
    var phi_892_: bool;
    var phi_901_: bool;
    var phi_923_: bool;
    var phi_925_: bool;
    var phi_926_: bool;
    var phi_927_: bool;
    var phi_928_: bool;
    var phi_960_: type_14;
    var phi_961_: type_14;
    var phi_968_: type_14;
    var phi_970_: bool;
    var phi_971_: bool;
    var phi_973_: type_14;
    var phi_974_: type_14;
    var phi_978_: bool;
    var phi_979_: bool;
    var phi_980_: bool;
    var phi_981_: type_14;
    var phi_982_: type_14;
    var phi_983_: u32;
    var phi_984_: u32;
    var phi_985_: f32;
    var phi_986_: bool;
    var phi_987_: bool;
    var phi_988_: bool;
    var phi_989_: type_14;
    var phi_990_: type_14;
    var phi_991_: u32;
    var phi_992_: u32;
    var phi_993_: f32;
    var phi_994_: bool;
    var phi_995_: bool;
    var phi_996_: bool;
    var phi_1002_: type_14;
    var phi_1003_: u32;
    var phi_1004_: u32;
    var phi_1005_: f32;
    var phi_1006_: type_14;
    var phi_1007_: array<f32, 3>;
    var phi_1008_: bool;
    var phi_1009_: bool;
    var phi_1010_: bool;
    var phi_1015_: u32;
    var phi_579_: type_14;
    var phi_582_: u32;
    var phi_584_: u32;
    var phi_586_: u32;
    var phi_588_: f32;
    var phi_1018_: type_14;
    var phi_1019_: array<f32, 3>;
    var phi_1020_: bool;
    var phi_1022_: bool;
    var phi_1023_: bool;
    var phi_2010_: bool;
    var phi_1832_: bool;
    var phi_1831_: bool;
    var phi_1830_: bool;
    var phi_1828_: array<f32, 3>;
    var phi_1826_: type_14;
    var phi_1028_: f32;
    var phi_2113_: bool;
    var phi_1031_: type_14;
    var phi_1032_: u32;
    var phi_1033_: u32;
    var phi_1034_: f32;
    var phi_1035_: f32;
    var phi_1036_: type_14;
    var phi_1037_: array<f32, 3>;
    var phi_1038_: bool;
    var phi_1039_: bool;
    var phi_1040_: bool;
    var phi_2112_: bool;
    var phi_1041_: type_14;
    var phi_1042_: u32;
    var phi_1043_: u32;
    var phi_1044_: f32;
    var phi_1045_: u32;
    var phi_1046_: f32;
    var phi_1047_: type_14;
    var phi_1048_: array<f32, 3>;
    var phi_1049_: bool;
    var phi_1050_: bool;
    var phi_1051_: bool;
    var phi_1052_: bool;
    var phi_2110_: bool;
    var phi_1059_: type_14;
    var phi_1060_: u32;
    var phi_1061_: u32;
    var phi_1062_: f32;
    var phi_1063_: u32;
    var phi_1064_: f32;
    var phi_1065_: type_14;
    var phi_1066_: array<f32, 3>;
    var phi_1067_: bool;
    var phi_1068_: bool;
    var phi_1069_: bool;
    var phi_1070_: bool;
    var phi_2109_: bool;
    var phi_1071_: type_14;
    var phi_1072_: u32;
    var phi_1073_: u32;
    var phi_1074_: f32;
    var phi_1075_: u32;
    var phi_1076_: f32;
    var phi_1077_: type_14;
    var phi_1078_: array<f32, 3>;
    var phi_1079_: bool;
    var phi_1080_: bool;
    var phi_1081_: bool;
    var phi_1082_: bool;
    var phi_1083_: bool;
    var phi_1097_: type_14;
    var phi_1101_: u32;
    var phi_1102_: f32;
    var phi_2105_: bool;
    var phi_1113_: type_14;
    var phi_1114_: u32;
    var phi_1115_: u32;
    var phi_1116_: f32;
    var phi_1117_: u32;
    var phi_1118_: u32;
    var phi_1119_: f32;
    var phi_1120_: type_14;
    var phi_1121_: array<f32, 3>;
    var phi_1122_: bool;
    var phi_1123_: bool;
    var phi_1124_: bool;
    var phi_1125_: bool;
    var phi_2104_: bool;
    var phi_1127_: type_14;
    var phi_1128_: u32;
    var phi_1129_: u32;
    var phi_1130_: f32;
    var phi_1131_: u32;
    var phi_1132_: u32;
    var phi_1133_: f32;
    var phi_1134_: type_14;
    var phi_1135_: array<f32, 3>;
    var phi_1136_: bool;
    var phi_1137_: bool;
    var phi_1138_: bool;
    var phi_1139_: bool;
    var phi_1140_: bool;
    var phi_2103_: bool;
    var phi_1142_: type_14;
    var phi_1143_: u32;
    var phi_1144_: u32;
    var phi_1145_: f32;
    var phi_1146_: u32;
    var phi_1147_: u32;
    var phi_1148_: f32;
    var phi_1149_: type_14;
    var phi_1150_: array<f32, 3>;
    var phi_1151_: bool;
    var phi_1152_: bool;
    var phi_1153_: bool;
    var phi_1154_: bool;
    var phi_1155_: bool;
    var phi_1156_: bool;
    var phi_2102_: bool;
    var phi_1158_: type_14;
    var phi_1159_: u32;
    var phi_1160_: u32;
    var phi_1161_: f32;
    var phi_1162_: u32;
    var phi_1163_: u32;
    var phi_1164_: f32;
    var phi_1165_: type_14;
    var phi_1166_: array<f32, 3>;
    var phi_1167_: bool;
    var phi_1168_: bool;
    var phi_1169_: bool;
    var phi_1170_: bool;
    var phi_1171_: bool;
    var phi_1172_: bool;
    var phi_1173_: bool;
    var phi_2101_: bool;
    var phi_1175_: type_14;
    var phi_1176_: u32;
    var phi_1177_: u32;
    var phi_1178_: f32;
    var phi_1179_: u32;
    var phi_1180_: u32;
    var phi_1181_: u32;
    var phi_1182_: f32;
    var phi_1183_: type_14;
    var phi_1184_: array<f32, 3>;
    var phi_1185_: bool;
    var phi_1186_: bool;
    var phi_1187_: bool;
    var phi_1188_: bool;
    var phi_1189_: bool;
    var phi_1190_: bool;
    var phi_1191_: bool;
    var phi_1192_: bool;
    var phi_2100_: bool;
    var phi_357_: type_14;
    var phi_360_: u32;
    var phi_362_: u32;
    var phi_364_: f32;
    var phi_366_: u32;
    var phi_368_: u32;
    var phi_370_: u32;
    var phi_372_: f32;
    var phi_1194_: type_14;
    var phi_1195_: array<f32, 3>;
    var phi_1196_: bool;
    var phi_1198_: bool;
    var phi_1199_: bool;
    var phi_1200_: bool;
    var phi_1201_: bool;
    var phi_1202_: bool;
    var phi_1203_: bool;
    var phi_1204_: bool;
    var phi_1205_: bool;
    var phi_2099_: bool;
    var phi_1843_: bool;
    var phi_1842_: bool;
    var phi_1841_: bool;
    var phi_1840_: bool;
    var phi_1839_: bool;
    var phi_1838_: bool;
    var phi_1837_: bool;
    var phi_1836_: bool;
    var phi_1835_: bool;
    var phi_1834_: array<f32, 3>;
    var phi_1833_: type_14;
    var phi_1222_: type_25;
    var phi_1236_: type_25;
    var phi_1249_: type_25;
    var phi_1261_: type_25;
    var phi_1335_: type_18;
    var phi_1338_: u32;
    var phi_1419_: bool;
    var phi_1420_: bool;
    var phi_1422_: bool;
    var phi_1423_: bool;
    var phi_1424_: bool;
    var phi_1425_: bool;
    var phi_1440_: bool;
    var phi_1468_: f32;
    var phi_1469_: f32;
    var phi_1486_: bool;
    var phi_1500_: bool;
    var phi_1505_: f32;
    var phi_1515_: bool;
    var phi_1529_: bool;
    var phi_1534_: f32;
    var phi_1544_: bool;
    var phi_1558_: bool;
    var phi_1563_: f32;
    var phi_1574_: f32;
    var phi_1577_: type_24;
    var phi_1579_: type_24;
    var phi_1580_: bool;
    var phi_1585_: type_24;
    var phi_1606_: bool;
    var phi_1611_: type_18;
    var phi_1612_: type_18;
    var phi_1613_: type_18;
    var phi_1336_: type_18;
    var phi_1339_: u32;
    var phi_2115_: bool;
    var phi_1638_: bool;
    var phi_1640_: bool;
    var phi_1641_: bool;
    var phi_1642_: bool;
    var phi_1643_: bool;
    var phi_1672_: bool;
    var phi_1674_: bool;
    var phi_1675_: bool;
    var phi_1676_: bool;
    var phi_1677_: bool;
    var phi_1709_: type_14;
    var phi_1710_: type_14;
    var phi_1713_: type_25;
    var phi_1718_: type_25;
    var phi_2170_: bool;
    var phi_1719_: type_25;
    var phi_1725_: array<f32, 3>;
    var phi_1749_: u32;
    var phi_2167_: bool;
    var phi_203_: array<f32, 3>;
    var phi_206_: u32;
    var phi_208_: u32;
    var phi_210_: array<f32, 3>;
    var phi_2166_: bool;
    var local_223: type_14;
    var local_224: u32;
    var local_225: u32;
    var local_226: f32;
    var local_227: type_14;

    let _e283 = global_9;
    let _e284 = bitcast<f32>(_e283);
    let _e285 = global_10;
    let _e286 = bitcast<f32>(_e285);
    let _e287 = global_11;
    let _e288 = bitcast<f32>(_e287);
    let _e289 = type_19(_e286, _e288);
    switch bitcast<i32>(0u) {
        default: {
            let _e291 = global;
            let _e292 = global_1;
            local = arrayLength((&global_4.member));
            local_1 = arrayLength((&global_3.member));
            local_2 = arrayLength((&global_6.member));
            local_3 = arrayLength((&global_7.member));
            local_4 = arrayLength((&global_2.member));
            local_5 = arrayLength((&global_8.member));
            let _e309 = ((_e292.x * 8u) + (_e291 % 8u));
            local_6 = _e309;
            local_7 = ((_e292.y * 8u) + (_e291 / 8u));
            let _e315 = global_5.member.member;
            local_8 = _e315;
            if (_e309 >= _e315) {
            } else {
                let _e319 = global_5.member.member_1;
                local_9 = _e319;
                let _e320 = local_7;
                if (_e320 >= _e319) {
                } else {
                    let _e322 = local_7;
                    let _e323 = local_8;
                    let _e325 = local_6;
                    let _e326 = ((_e322 * _e323) + _e325);
                    local_10 = _e326;
                    let _e330 = ((_e326 ^ (_e326 >> bitcast<u32>(16i))) * 2146121005u);
                    let _e334 = ((_e330 ^ (_e330 >> bitcast<u32>(15i))) * 2221713035u);
                    local_11 = (_e334 ^ (_e334 >> bitcast<u32>(16i)));
                    let _e340 = global_5.member.member_5;
                    let _e342 = select(1u, _e340, (1u < _e340));
                    local_180 = _e342;
                    if (_e342 == 0u) {
                        break;
                    }
                    let _e344 = local_11;
                    let _e345 = local_180;
                    local_12 = (_e344 % _e345);
                    let _e347 = local_6;
                    let _e348 = f32(_e347);
                    local_13 = _e348;
                    local_14 = (_e348 + 0.5f);
                    let _e350 = local_7;
                    let _e351 = f32(_e350);
                    local_15 = _e351;
                    local_16 = (_e351 + 0.5f);
                    phi_2085_ = false;
                    phi_202_ = array<f32, 3>(0f, 0f, 0f);
                    phi_205_ = 0u;
                    phi_207_ = 0u;
                    phi_209_ = array<f32, 3>(0f, 0f, 0f);
                    loop {
                        let _e354 = phi_2085_;
                        let _e356 = phi_202_;
                        let _e358 = phi_205_;
                        let _e360 = phi_207_;
                        let _e362 = phi_209_;
                        local_17 = _e356;
                        local_18 = _e358;
                        local_19 = _e360;
                        local_20 = _e362;
                        let _e365 = global_5.member.member_4;
                        local_21 = _e365;
                        let _e366 = local_18;
                        let _e367 = (_e366 < _e365);
                        local_22 = _e367;
                        if _e367 {
                            let _e368 = local_12;
                            let _e369 = local_21;
                            let _e371 = local_18;
                            let _e373 = (2u * ((_e368 * _e369) + _e371));
                            local_23 = _e373;
                            let _e374 = local_3;
                            if (_e373 < _e374) {
                            } else {
                                phi_2166_ = true;
                                break;
                            }
                            let _e376 = local_23;
                            let _e379 = global_7.member[_e376];
                            local_24 = bitcast<f32>(_e379);
                            let _e381 = local_23;
                            let _e382 = (_e381 + 1u);
                            local_25 = _e382;
                            let _e383 = local_3;
                            if (_e382 < _e383) {
                            } else {
                                phi_2166_ = true;
                                break;
                            }
                            let _e385 = local_25;
                            let _e388 = global_7.member[_e385];
                            local_26 = bitcast<f32>(_e388);
                            let _e392 = global_5.member.member_3;
                            local_27 = _e392;
                            let _e393 = (_e392 - 1u);
                            local_28 = _e393;
                            if (_e393 < 14u) {
                            } else {
                                phi_2166_ = true;
                                break;
                            }
                            let _e395 = local_28;
                            let _e399 = global_5.member.member_9[_e395];
                            local_29 = _e399;
                            let _e400 = local_8;
                            local_30 = f32(_e400);
                            let _e402 = local_9;
                            local_31 = f32(_e402);
                            let _e404 = local_24;
                            if (_e404 == 0f) {
                                phi_270_ = _e289;
                            } else {
                                let _e406 = local_13;
                                let _e408 = local_24;
                                let _e409 = ((-0.5f - _e406) / _e408);
                                local_32 = _e409;
                                let _e410 = local_30;
                                let _e411 = local_14;
                                let _e413 = local_24;
                                local_33 = ((_e410 - _e411) / _e413);
                                let _e416 = !((_e409 == _e409));
                                local_178 = _e416;
                                if _e416 {
                                    phi_1855_ = true;
                                } else {
                                    let _e417 = local_33;
                                    let _e418 = local_32;
                                    phi_1855_ = (_e417 <= _e418);
                                }
                                let _e421 = phi_1855_;
                                let _e422 = local_33;
                                let _e423 = local_32;
                                local_181 = select(_e423, _e422, _e421);
                                let _e425 = local_178;
                                if _e425 {
                                    phi_1870_ = true;
                                } else {
                                    let _e426 = local_33;
                                    let _e427 = local_32;
                                    phi_1870_ = (_e426 >= _e427);
                                }
                                let _e430 = phi_1870_;
                                let _e431 = local_33;
                                let _e432 = local_32;
                                let _e434 = local_181;
                                phi_270_ = type_19(_e434, select(_e432, _e431, _e430));
                            }
                            let _e437 = phi_270_;
                            local_34 = _e437.member;
                            local_35 = _e437.member_1;
                            let _e440 = local_26;
                            if (_e440 == 0f) {
                                phi_285_ = _e289;
                            } else {
                                let _e442 = local_15;
                                let _e444 = local_26;
                                let _e445 = ((-0.5f - _e442) / _e444);
                                local_36 = _e445;
                                let _e446 = local_31;
                                let _e447 = local_16;
                                let _e449 = local_26;
                                local_37 = ((_e446 - _e447) / _e449);
                                let _e452 = !((_e445 == _e445));
                                local_179 = _e452;
                                if _e452 {
                                    phi_1885_ = true;
                                } else {
                                    let _e453 = local_37;
                                    let _e454 = local_36;
                                    phi_1885_ = (_e453 <= _e454);
                                }
                                let _e457 = phi_1885_;
                                let _e458 = local_37;
                                let _e459 = local_36;
                                local_182 = select(_e459, _e458, _e457);
                                let _e461 = local_179;
                                if _e461 {
                                    phi_1900_ = true;
                                } else {
                                    let _e462 = local_37;
                                    let _e463 = local_36;
                                    phi_1900_ = (_e462 >= _e463);
                                }
                                let _e466 = phi_1900_;
                                let _e467 = local_37;
                                let _e468 = local_36;
                                let _e470 = local_182;
                                phi_285_ = type_19(_e470, select(_e468, _e467, _e466));
                            }
                            let _e473 = phi_285_;
                            local_38 = _e473.member;
                            local_39 = _e473.member_1;
                            let _e476 = local_29;
                            let _e477 = (2u * _e476);
                            local_40 = _e477;
                            let _e478 = local_2;
                            if (_e477 < _e478) {
                            } else {
                                phi_2166_ = true;
                                break;
                            }
                            let _e480 = local_40;
                            let _e483 = global_6.member[_e480];
                            let _e484 = bitcast<f32>(_e483);
                            local_41 = _e484;
                            if !((_e484 == _e484)) {
                                phi_1915_ = true;
                            } else {
                                let _e487 = local_34;
                                let _e488 = local_41;
                                phi_1915_ = (_e487 >= _e488);
                            }
                            let _e491 = phi_1915_;
                            let _e492 = local_34;
                            let _e493 = local_41;
                            let _e494 = select(_e493, _e492, _e491);
                            local_183 = _e494;
                            if !((_e494 == _e494)) {
                                phi_1930_ = true;
                            } else {
                                let _e497 = local_38;
                                let _e498 = local_183;
                                phi_1930_ = (_e497 >= _e498);
                            }
                            let _e501 = phi_1930_;
                            let _e502 = local_38;
                            let _e503 = local_183;
                            let _e508 = global_5.member.member_8.member_1;
                            let _e513 = global_5.member.member_8.member;
                            let _e518 = global_5.member.member_8.member_2;
                            local_42 = _e518;
                            let _e524 = global_5.member.member_8.member_3;
                            let _e525 = ((((2f * _e508) * _e513) / (_e518 - _e513)) * _e524);
                            local_43 = _e525;
                            let _e526 = (0.5f * _e525);
                            local_44 = _e526;
                            if !((_e526 == _e526)) {
                                phi_1945_ = true;
                            } else {
                                let _e529 = local_35;
                                let _e530 = local_44;
                                phi_1945_ = (_e529 <= _e530);
                            }
                            let _e533 = phi_1945_;
                            let _e534 = local_35;
                            let _e535 = local_44;
                            let _e536 = select(_e535, _e534, _e533);
                            local_184 = _e536;
                            if !((_e536 == _e536)) {
                                phi_1960_ = true;
                            } else {
                                let _e539 = local_39;
                                let _e540 = local_184;
                                phi_1960_ = (_e539 <= _e540);
                            }
                            let _e543 = phi_1960_;
                            let _e544 = local_39;
                            let _e545 = local_184;
                            local_185 = select(_e545, _e544, _e543);
                            let _e547 = local_24;
                            let _e548 = abs(_e547);
                            local_45 = _e548;
                            let _e549 = local_26;
                            local_46 = abs(_e549);
                            if !((_e548 == _e548)) {
                                phi_1975_ = true;
                            } else {
                                let _e553 = local_46;
                                let _e554 = local_45;
                                phi_1975_ = (_e553 >= _e554);
                            }
                            let _e557 = phi_1975_;
                            let _e558 = local_46;
                            let _e559 = local_45;
                            let _e560 = select(_e559, _e558, _e557);
                            local_186 = _e560;
                            if (_e560 > 0f) {
                                let _e562 = local_186;
                                phi_326_ = (0.01f / _e562);
                            } else {
                                phi_326_ = _e288;
                            }
                            let _e565 = phi_326_;
                            local_47 = _e565;
                            let _e566 = local_8;
                            let _e567 = local_9;
                            let _e570 = local_27;
                            local_48 = ((4u * (_e566 + _e567)) + (8u * _e570));
                            let _e573 = local_16;
                            let _e575 = local_16;
                            let _e578 = local_16;
                            let _e582 = local_8;
                            let _e584 = local_14;
                            let _e586 = local_14;
                            let _e589 = local_14;
                            phi_2071_ = _e354;
                            phi_356_ = type_14(array<f32, 3>(0f, 0f, 0f), 1f);
                            phi_359_ = 0u;
                            phi_361_ = 4294967295u;
                            phi_363_ = _e286;
                            phi_365_ = ((select(select(u32(_e573), 0u, !((_e575 >= 0f))), 4294967295u, (_e578 > 4294967000f)) * _e582) + select(select(u32(_e584), 0u, !((_e586 >= 0f))), 4294967295u, (_e589 > 4294967000f)));
                            phi_367_ = 0u;
                            phi_369_ = 0u;
                            phi_371_ = select(_e503, _e502, _e501);
                            loop {
                                let _e595 = phi_2071_;
                                let _e597 = phi_356_;
                                let _e599 = phi_359_;
                                let _e601 = phi_361_;
                                let _e603 = phi_363_;
                                let _e605 = phi_365_;
                                let _e607 = phi_367_;
                                let _e609 = phi_369_;
                                let _e611 = phi_371_;
                                local_49 = _e597;
                                local_50 = _e599;
                                local_51 = _e601;
                                local_52 = _e603;
                                local_53 = _e605;
                                local_54 = _e607;
                                local_55 = _e609;
                                local_56 = _e611;
                                local_227 = _e597;
                                let _e612 = local_56;
                                let _e613 = local_185;
                                let _e614 = (_e612 <= _e613);
                                local_57 = _e614;
                                if _e614 {
                                    let _e615 = local_54;
                                    let _e616 = local_48;
                                    let _e617 = (_e615 < _e616);
                                    local_58 = _e617;
                                    if _e617 {
                                        let _e618 = local_54;
                                        let _e620 = local_24;
                                        let _e621 = local_56;
                                        let _e623 = local_14;
                                        let _e624 = (_e623 + (_e620 * _e621));
                                        local_59 = _e624;
                                        let _e625 = local_26;
                                        let _e626 = local_56;
                                        let _e628 = local_16;
                                        local_60 = (_e628 + (_e625 * _e626));
                                        let _e630 = (_e624 >= 0f);
                                        local_61 = _e630;
                                        if _e630 {
                                            let _e631 = local_60;
                                            let _e632 = (_e631 >= 0f);
                                            local_62 = _e632;
                                            if _e632 {
                                                let _e633 = local_59;
                                                let _e634 = local_30;
                                                let _e635 = (_e633 < _e634);
                                                local_63 = _e635;
                                                if _e635 {
                                                    let _e636 = local_60;
                                                    let _e637 = local_31;
                                                    let _e638 = (_e636 < _e637);
                                                    local_64 = _e638;
                                                    if _e638 {
                                                        let _e639 = local_59;
                                                        let _e640 = floor(_e639);
                                                        let _e646 = select(select(u32(_e640), 0u, !((_e640 >= 0f))), 4294967295u, (_e640 > 4294967000f));
                                                        let _e647 = local_60;
                                                        let _e648 = floor(_e647);
                                                        let _e654 = select(select(u32(_e648), 0u, !((_e648 >= 0f))), 4294967295u, (_e648 > 4294967000f));
                                                        let _e655 = local_8;
                                                        let _e657 = ((_e654 * _e655) + _e646);
                                                        local_65 = _e657;
                                                        let _e658 = local_55;
                                                        let _e659 = (_e658 & 31u);
                                                        local_66 = (_e646 >> bitcast<u32>(_e659));
                                                        local_67 = (_e654 >> bitcast<u32>(_e659));
                                                        local_68 = (1u << bitcast<u32>(_e659));
                                                        let _e666 = local_24;
                                                        if (_e666 > 0f) {
                                                            let _e668 = local_66;
                                                            let _e671 = local_68;
                                                            let _e674 = local_14;
                                                            let _e676 = local_24;
                                                            phi_450_ = (((f32((_e668 + 1u)) * f32(_e671)) - _e674) / _e676);
                                                        } else {
                                                            let _e678 = local_24;
                                                            if (_e678 < 0f) {
                                                                let _e680 = local_66;
                                                                let _e682 = local_68;
                                                                let _e685 = local_14;
                                                                let _e687 = local_24;
                                                                phi_449_ = (((f32(_e680) * f32(_e682)) - _e685) / _e687);
                                                            } else {
                                                                phi_449_ = _e288;
                                                            }
                                                            let _e690 = phi_449_;
                                                            phi_450_ = _e690;
                                                        }
                                                        let _e692 = phi_450_;
                                                        local_69 = _e692;
                                                        let _e693 = local_26;
                                                        if (_e693 > 0f) {
                                                            let _e695 = local_67;
                                                            let _e698 = local_68;
                                                            let _e701 = local_16;
                                                            let _e703 = local_26;
                                                            phi_471_ = (((f32((_e695 + 1u)) * f32(_e698)) - _e701) / _e703);
                                                        } else {
                                                            let _e705 = local_26;
                                                            if (_e705 < 0f) {
                                                                let _e707 = local_67;
                                                                let _e709 = local_68;
                                                                let _e712 = local_16;
                                                                let _e714 = local_26;
                                                                phi_470_ = (((f32(_e707) * f32(_e709)) - _e712) / _e714);
                                                            } else {
                                                                phi_470_ = _e288;
                                                            }
                                                            let _e717 = phi_470_;
                                                            phi_471_ = _e717;
                                                        }
                                                        let _e719 = phi_471_;
                                                        local_70 = _e719;
                                                        let _e720 = local_69;
                                                        let _e721 = local_69;
                                                        if !((_e720 == _e721)) {
                                                            phi_1990_ = true;
                                                        } else {
                                                            let _e724 = local_70;
                                                            let _e725 = local_69;
                                                            phi_1990_ = (_e724 <= _e725);
                                                        }
                                                        let _e728 = phi_1990_;
                                                        let _e729 = local_70;
                                                        let _e730 = local_69;
                                                        let _e731 = select(_e730, _e729, _e728);
                                                        local_187 = _e731;
                                                        if !((_e731 == _e731)) {
                                                            phi_2005_ = true;
                                                        } else {
                                                            let _e734 = local_185;
                                                            let _e735 = local_187;
                                                            phi_2005_ = (_e734 <= _e735);
                                                        }
                                                        let _e738 = phi_2005_;
                                                        let _e739 = local_185;
                                                        let _e740 = local_187;
                                                        local_188 = select(_e740, _e739, _e738);
                                                        let _e742 = local_68;
                                                        let _e743 = (_e742 == 0u);
                                                        local_71 = _e743;
                                                        if _e743 {
                                                            phi_2099_ = true;
                                                            phi_1843_ = bool();
                                                            phi_1842_ = bool();
                                                            phi_1841_ = bool();
                                                            phi_1840_ = bool();
                                                            phi_1839_ = bool();
                                                            phi_1838_ = bool();
                                                            phi_1837_ = bool();
                                                            phi_1836_ = bool();
                                                            phi_1835_ = bool();
                                                            phi_1834_ = array<f32, 3>();
                                                            phi_1833_ = type_14();
                                                            break;
                                                        }
                                                        let _e744 = local_8;
                                                        let _e745 = local_68;
                                                        let _e746 = (_e744 / _e745);
                                                        local_72 = _e746;
                                                        let _e747 = local_71;
                                                        if _e747 {
                                                            phi_2099_ = true;
                                                            phi_1843_ = bool();
                                                            phi_1842_ = bool();
                                                            phi_1841_ = bool();
                                                            phi_1840_ = bool();
                                                            phi_1839_ = bool();
                                                            phi_1838_ = bool();
                                                            phi_1837_ = bool();
                                                            phi_1836_ = bool();
                                                            phi_1835_ = bool();
                                                            phi_1834_ = array<f32, 3>();
                                                            phi_1833_ = type_14();
                                                            break;
                                                        }
                                                        let _e748 = local_8;
                                                        let _e749 = local_68;
                                                        if ((_e748 % _e749) > 0u) {
                                                            let _e752 = local_72;
                                                            phi_493_ = (_e752 + 1u);
                                                        } else {
                                                            phi_493_ = _e746;
                                                        }
                                                        let _e755 = phi_493_;
                                                        local_73 = _e755;
                                                        let _e756 = local_71;
                                                        if _e756 {
                                                            phi_2099_ = true;
                                                            phi_1843_ = bool();
                                                            phi_1842_ = bool();
                                                            phi_1841_ = bool();
                                                            phi_1840_ = bool();
                                                            phi_1839_ = bool();
                                                            phi_1838_ = bool();
                                                            phi_1837_ = bool();
                                                            phi_1836_ = bool();
                                                            phi_1835_ = bool();
                                                            phi_1834_ = array<f32, 3>();
                                                            phi_1833_ = type_14();
                                                            break;
                                                        }
                                                        let _e757 = local_71;
                                                        if _e757 {
                                                            phi_2099_ = true;
                                                            phi_1843_ = bool();
                                                            phi_1842_ = bool();
                                                            phi_1841_ = bool();
                                                            phi_1840_ = bool();
                                                            phi_1839_ = bool();
                                                            phi_1838_ = bool();
                                                            phi_1837_ = bool();
                                                            phi_1836_ = bool();
                                                            phi_1835_ = bool();
                                                            phi_1834_ = array<f32, 3>();
                                                            phi_1833_ = type_14();
                                                            break;
                                                        }
                                                        let _e758 = local_55;
                                                        if (_e758 < 14u) {
                                                        } else {
                                                            phi_2099_ = true;
                                                            phi_1843_ = bool();
                                                            phi_1842_ = bool();
                                                            phi_1841_ = bool();
                                                            phi_1840_ = bool();
                                                            phi_1839_ = bool();
                                                            phi_1838_ = bool();
                                                            phi_1837_ = bool();
                                                            phi_1836_ = bool();
                                                            phi_1835_ = bool();
                                                            phi_1834_ = array<f32, 3>();
                                                            phi_1833_ = type_14();
                                                            break;
                                                        }
                                                        let _e760 = local_55;
                                                        let _e764 = global_5.member.member_9[_e760];
                                                        let _e765 = local_67;
                                                        let _e766 = local_73;
                                                        let _e769 = local_66;
                                                        let _e771 = (2u * ((_e764 + (_e765 * _e766)) + _e769));
                                                        local_74 = _e771;
                                                        let _e772 = local_2;
                                                        if (_e771 < _e772) {
                                                        } else {
                                                            phi_2099_ = true;
                                                            phi_1843_ = bool();
                                                            phi_1842_ = bool();
                                                            phi_1841_ = bool();
                                                            phi_1840_ = bool();
                                                            phi_1839_ = bool();
                                                            phi_1838_ = bool();
                                                            phi_1837_ = bool();
                                                            phi_1836_ = bool();
                                                            phi_1835_ = bool();
                                                            phi_1834_ = array<f32, 3>();
                                                            phi_1833_ = type_14();
                                                            break;
                                                        }
                                                        let _e774 = local_74;
                                                        let _e777 = global_6.member[_e774];
                                                        local_75 = bitcast<f32>(_e777);
                                                        let _e779 = local_74;
                                                        let _e780 = (_e779 + 1u);
                                                        local_76 = _e780;
                                                        let _e781 = local_2;
                                                        if (_e780 < _e781) {
                                                        } else {
                                                            phi_2099_ = true;
                                                            phi_1843_ = bool();
                                                            phi_1842_ = bool();
                                                            phi_1841_ = bool();
                                                            phi_1840_ = bool();
                                                            phi_1839_ = bool();
                                                            phi_1838_ = bool();
                                                            phi_1837_ = bool();
                                                            phi_1836_ = bool();
                                                            phi_1835_ = bool();
                                                            phi_1834_ = array<f32, 3>();
                                                            phi_1833_ = type_14();
                                                            break;
                                                        }
                                                        let _e783 = local_76;
                                                        let _e786 = global_6.member[_e783];
                                                        let _e788 = local_56;
                                                        let _e790 = local_188;
                                                        let _e794 = (0.00001f * ((abs(_e788) + abs(_e790)) + 1f));
                                                        local_77 = _e794;
                                                        let _e795 = local_56;
                                                        let _e796 = (_e795 - _e794);
                                                        local_78 = _e796;
                                                        if (bitcast<f32>(_e786) < _e796) {
                                                            phi_2109_ = _e595;
                                                            phi_1071_ = type_14();
                                                            phi_1072_ = u32();
                                                            phi_1073_ = u32();
                                                            phi_1074_ = f32();
                                                            phi_1075_ = u32();
                                                            phi_1076_ = f32();
                                                            phi_1077_ = type_14();
                                                            phi_1078_ = array<f32, 3>();
                                                            phi_1079_ = true;
                                                            phi_1080_ = false;
                                                            phi_1081_ = false;
                                                            phi_1082_ = false;
                                                            phi_1083_ = false;
                                                        } else {
                                                            let _e798 = local_188;
                                                            let _e799 = local_77;
                                                            let _e800 = (_e798 + _e799);
                                                            local_79 = _e800;
                                                            let _e801 = local_75;
                                                            let _e802 = (_e801 > _e800);
                                                            if _e802 {
                                                                phi_2110_ = _e595;
                                                                phi_1059_ = type_14();
                                                                phi_1060_ = u32();
                                                                phi_1061_ = u32();
                                                                phi_1062_ = f32();
                                                                phi_1063_ = u32();
                                                                phi_1064_ = f32();
                                                                phi_1065_ = type_14();
                                                                phi_1066_ = array<f32, 3>();
                                                                phi_1067_ = false;
                                                                phi_1068_ = false;
                                                                phi_1069_ = false;
                                                                phi_1070_ = false;
                                                            } else {
                                                                let _e803 = local_55;
                                                                if (_e803 > 0u) {
                                                                    let _e805 = local_55;
                                                                    phi_2112_ = _e595;
                                                                    phi_1041_ = _e597;
                                                                    phi_1042_ = _e599;
                                                                    phi_1043_ = _e601;
                                                                    phi_1044_ = _e603;
                                                                    phi_1045_ = (_e805 - 1u);
                                                                    phi_1046_ = _e611;
                                                                    phi_1047_ = type_14();
                                                                    phi_1048_ = array<f32, 3>();
                                                                    phi_1049_ = true;
                                                                    phi_1050_ = false;
                                                                    phi_1051_ = false;
                                                                    phi_1052_ = false;
                                                                } else {
                                                                    let _e807 = local_65;
                                                                    let _e808 = local_1;
                                                                    if (_e807 < _e808) {
                                                                    } else {
                                                                        phi_2099_ = true;
                                                                        phi_1843_ = bool();
                                                                        phi_1842_ = bool();
                                                                        phi_1841_ = bool();
                                                                        phi_1840_ = bool();
                                                                        phi_1839_ = bool();
                                                                        phi_1838_ = bool();
                                                                        phi_1837_ = bool();
                                                                        phi_1836_ = bool();
                                                                        phi_1835_ = bool();
                                                                        phi_1834_ = array<f32, 3>();
                                                                        phi_1833_ = type_14();
                                                                        break;
                                                                    }
                                                                    let _e810 = local_65;
                                                                    let _e813 = global_3.member[_e810];
                                                                    let _e816 = global_5.member.member_2;
                                                                    local_80 = _e816;
                                                                    let _e818 = select(_e813, _e816, (_e816 < _e813));
                                                                    local_189 = _e818;
                                                                    let _e819 = (_e818 == 0u);
                                                                    if _e819 {
                                                                        phi_2113_ = _e595;
                                                                        phi_1031_ = type_14();
                                                                        phi_1032_ = u32();
                                                                        phi_1033_ = u32();
                                                                        phi_1034_ = f32();
                                                                        phi_1035_ = f32();
                                                                        phi_1036_ = type_14();
                                                                        phi_1037_ = array<f32, 3>();
                                                                        phi_1038_ = false;
                                                                        phi_1039_ = false;
                                                                        phi_1040_ = false;
                                                                    } else {
                                                                        phi_578_ = _e597;
                                                                        phi_581_ = _e599;
                                                                        phi_583_ = _e601;
                                                                        phi_585_ = 0u;
                                                                        phi_587_ = _e603;
                                                                        loop {
                                                                            let _e821 = phi_578_;
                                                                            let _e823 = phi_581_;
                                                                            let _e825 = phi_583_;
                                                                            let _e827 = phi_585_;
                                                                            let _e829 = phi_587_;
                                                                            local_81 = _e821;
                                                                            local_82 = _e823;
                                                                            local_83 = _e825;
                                                                            local_84 = _e827;
                                                                            local_85 = _e829;
                                                                            local_223 = _e821;
                                                                            local_224 = _e823;
                                                                            local_225 = _e825;
                                                                            local_226 = _e829;
                                                                            let _e830 = local_84;
                                                                            let _e831 = local_189;
                                                                            let _e832 = (_e830 < _e831);
                                                                            local_86 = _e832;
                                                                            if _e832 {
                                                                                let _e833 = local_65;
                                                                                let _e834 = local_80;
                                                                                let _e836 = local_84;
                                                                                let _e838 = (5u * ((_e833 * _e834) + _e836));
                                                                                local_87 = _e838;
                                                                                let _e839 = local;
                                                                                if (_e838 < _e839) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e841 = local_87;
                                                                                let _e844 = global_4.member[_e841];
                                                                                local_88 = bitcast<f32>(_e844);
                                                                                let _e846 = local_87;
                                                                                let _e847 = (_e846 + 1u);
                                                                                local_89 = _e847;
                                                                                let _e848 = local;
                                                                                if (_e847 < _e848) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e850 = local_89;
                                                                                let _e853 = global_4.member[_e850];
                                                                                local_90 = bitcast<f32>(_e853);
                                                                                let _e855 = local_87;
                                                                                let _e856 = (_e855 + 2u);
                                                                                local_91 = _e856;
                                                                                let _e857 = local;
                                                                                if (_e856 < _e857) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e859 = local_91;
                                                                                let _e862 = global_4.member[_e859];
                                                                                local_92 = bitcast<f32>(_e862);
                                                                                let _e864 = local_87;
                                                                                let _e865 = (_e864 + 3u);
                                                                                local_93 = _e865;
                                                                                let _e866 = local;
                                                                                if (_e865 < _e866) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e868 = local_93;
                                                                                let _e871 = global_4.member[_e868];
                                                                                local_94 = bitcast<f32>(_e871);
                                                                                let _e873 = local_87;
                                                                                let _e874 = (_e873 + 4u);
                                                                                local_95 = _e874;
                                                                                let _e875 = local;
                                                                                if (_e874 < _e875) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e877 = local_95;
                                                                                let _e880 = global_4.member[_e877];
                                                                                local_96 = bitcast<f32>(_e880);
                                                                                let _e882 = local_88;
                                                                                if ((bitcast<u32>(_e882) & 2139095040u) != 2139095040u) {
                                                                                    let _e886 = local_90;
                                                                                    if ((bitcast<u32>(_e886) & 2139095040u) != 2139095040u) {
                                                                                        let _e890 = local_92;
                                                                                        let _e893 = ((bitcast<u32>(_e890) & 2139095040u) != 2139095040u);
                                                                                        local_97 = _e893;
                                                                                        if _e893 {
                                                                                            let _e894 = local_94;
                                                                                            let _e895 = bitcast<u32>(_e894);
                                                                                            local_98 = _e895;
                                                                                            if (_e895 == 0u) {
                                                                                                phi_668_ = false;
                                                                                            } else {
                                                                                                let _e897 = local_98;
                                                                                                phi_668_ = (_e897 <= 2139095040u);
                                                                                            }
                                                                                            let _e900 = phi_668_;
                                                                                            phi_669_ = _e900;
                                                                                        } else {
                                                                                            phi_669_ = bool();
                                                                                        }
                                                                                        let _e902 = phi_669_;
                                                                                        let _e903 = local_97;
                                                                                        phi_671_ = _e902;
                                                                                        phi_672_ = select(true, false, _e903);
                                                                                    } else {
                                                                                        phi_671_ = bool();
                                                                                        phi_672_ = true;
                                                                                    }
                                                                                    let _e906 = phi_671_;
                                                                                    let _e908 = phi_672_;
                                                                                    phi_673_ = _e906;
                                                                                    phi_674_ = _e908;
                                                                                } else {
                                                                                    phi_673_ = bool();
                                                                                    phi_674_ = true;
                                                                                }
                                                                                let _e910 = phi_673_;
                                                                                let _e912 = phi_674_;
                                                                                if select(_e910, false, _e912) {
                                                                                    let _e914 = local_94;
                                                                                    let _e915 = bitcast<u32>(_e914);
                                                                                    local_99 = _e915;
                                                                                    if (_e915 == 0u) {
                                                                                        phi_689_ = false;
                                                                                    } else {
                                                                                        let _e917 = local_99;
                                                                                        phi_689_ = (_e917 <= 2139095040u);
                                                                                    }
                                                                                    let _e920 = phi_689_;
                                                                                    if _e920 {
                                                                                        let _e921 = local_43;
                                                                                        if (_e921 == 0f) {
                                                                                            phi_717_ = 0f;
                                                                                        } else {
                                                                                            let _e923 = local_42;
                                                                                            let _e924 = local_94;
                                                                                            let _e927 = local_43;
                                                                                            phi_717_ = (_e927 * (1f - (_e923 / _e924)));
                                                                                        }
                                                                                        let _e930 = phi_717_;
                                                                                        phi_718_ = _e930;
                                                                                    } else {
                                                                                        phi_718_ = _e284;
                                                                                    }
                                                                                    let _e932 = phi_718_;
                                                                                    let _e933 = (0.5f * _e932);
                                                                                    local_100 = _e933;
                                                                                    let _e936 = ((bitcast<u32>(_e933) & 2139095040u) != 2139095040u);
                                                                                    local_101 = _e936;
                                                                                    if _e936 {
                                                                                        let _e937 = local_88;
                                                                                        if (_e937 > 1267650600000000000000000000000f) {
                                                                                            let _e939 = local_88;
                                                                                            phi_735_ = select(true, false, (_e939 <= 340282350000000000000000000000000000000f));
                                                                                        } else {
                                                                                            phi_735_ = true;
                                                                                        }
                                                                                        let _e943 = phi_735_;
                                                                                        if _e943 {
                                                                                            let _e944 = local_88;
                                                                                            if (_e944 < 0.000000000000000000000000000000000000011754944f) {
                                                                                                let _e946 = local_88;
                                                                                                phi_749_ = select(true, false, (_e946 >= -340282350000000000000000000000000000000f));
                                                                                            } else {
                                                                                                phi_749_ = true;
                                                                                            }
                                                                                            let _e950 = phi_749_;
                                                                                            let _e951 = local_88;
                                                                                            phi_754_ = select(0f, _e951, _e950);
                                                                                        } else {
                                                                                            phi_754_ = 1267650600000000000000000000000f;
                                                                                        }
                                                                                        let _e954 = phi_754_;
                                                                                        local_102 = _e954;
                                                                                        let _e955 = local_90;
                                                                                        if (_e955 > 1267650600000000000000000000000f) {
                                                                                            let _e957 = local_90;
                                                                                            phi_764_ = select(true, false, (_e957 <= 340282350000000000000000000000000000000f));
                                                                                        } else {
                                                                                            phi_764_ = true;
                                                                                        }
                                                                                        let _e961 = phi_764_;
                                                                                        if _e961 {
                                                                                            let _e962 = local_90;
                                                                                            if (_e962 < 0.000000000000000000000000000000000000011754944f) {
                                                                                                let _e964 = local_90;
                                                                                                phi_778_ = select(true, false, (_e964 >= -340282350000000000000000000000000000000f));
                                                                                            } else {
                                                                                                phi_778_ = true;
                                                                                            }
                                                                                            let _e968 = phi_778_;
                                                                                            let _e969 = local_90;
                                                                                            phi_783_ = select(0f, _e969, _e968);
                                                                                        } else {
                                                                                            phi_783_ = 1267650600000000000000000000000f;
                                                                                        }
                                                                                        let _e972 = phi_783_;
                                                                                        local_103 = _e972;
                                                                                        let _e973 = local_92;
                                                                                        if (_e973 > 1267650600000000000000000000000f) {
                                                                                            let _e975 = local_92;
                                                                                            phi_793_ = select(true, false, (_e975 <= 340282350000000000000000000000000000000f));
                                                                                        } else {
                                                                                            phi_793_ = true;
                                                                                        }
                                                                                        let _e979 = phi_793_;
                                                                                        if _e979 {
                                                                                            let _e980 = local_92;
                                                                                            if (_e980 < 0.000000000000000000000000000000000000011754944f) {
                                                                                                let _e982 = local_92;
                                                                                                phi_807_ = select(true, false, (_e982 >= -340282350000000000000000000000000000000f));
                                                                                            } else {
                                                                                                phi_807_ = true;
                                                                                            }
                                                                                            let _e986 = phi_807_;
                                                                                            let _e987 = local_92;
                                                                                            phi_812_ = select(0f, _e987, _e986);
                                                                                        } else {
                                                                                            phi_812_ = 1267650600000000000000000000000f;
                                                                                        }
                                                                                        let _e990 = phi_812_;
                                                                                        let _e991 = local_102;
                                                                                        let _e992 = local_103;
                                                                                        local_104 = array<f32, 3>(_e991, _e992, _e990);
                                                                                        let _e994 = local_96;
                                                                                        if (_e994 > 1f) {
                                                                                            phi_823_ = 1f;
                                                                                        } else {
                                                                                            let _e996 = local_96;
                                                                                            let _e998 = local_96;
                                                                                            phi_823_ = select(0f, _e998, (_e996 >= 0f));
                                                                                        }
                                                                                        let _e1001 = phi_823_;
                                                                                        let _e1002 = local_104;
                                                                                        let _e1003 = local_100;
                                                                                        phi_826_ = type_24(1u, type_17(_e1002, _e1003, _e1001));
                                                                                    } else {
                                                                                        phi_826_ = type_24();
                                                                                    }
                                                                                    let _e1007 = phi_826_;
                                                                                    let _e1008 = local_101;
                                                                                    phi_828_ = _e1007;
                                                                                    phi_829_ = select(true, false, _e1008);
                                                                                } else {
                                                                                    phi_828_ = type_24();
                                                                                    phi_829_ = true;
                                                                                }
                                                                                let _e1011 = phi_828_;
                                                                                let _e1013 = phi_829_;
                                                                                if _e1013 {
                                                                                    phi_834_ = type_24(0u, type_24().member_1);
                                                                                } else {
                                                                                    phi_834_ = _e1011;
                                                                                }
                                                                                let _e1018 = phi_834_;
                                                                                local_105 = _e1018;
                                                                                if (bitcast<i32>(_e1018.member) != 0i) {
                                                                                    let _e1022 = local_105;
                                                                                    local_106 = _e1022.member_1.member;
                                                                                    let _e1025 = local_105;
                                                                                    local_107 = _e1025.member_1.member_1;
                                                                                    let _e1028 = local_105;
                                                                                    local_108 = _e1028.member_1.member_2;
                                                                                    let _e1031 = local_65;
                                                                                    let _e1032 = local_83;
                                                                                    if (_e1031 != _e1032) {
                                                                                        phi_852_ = true;
                                                                                    } else {
                                                                                        let _e1034 = local_84;
                                                                                        let _e1035 = local_82;
                                                                                        phi_852_ = (_e1034 > _e1035);
                                                                                    }
                                                                                    let _e1038 = phi_852_;
                                                                                    if _e1038 {
                                                                                        let _e1039 = local_107;
                                                                                        let _e1040 = local_78;
                                                                                        if (_e1039 >= _e1040) {
                                                                                            let _e1042 = local_107;
                                                                                            let _e1043 = local_79;
                                                                                            let _e1044 = (_e1042 <= _e1043);
                                                                                            local_109 = _e1044;
                                                                                            if _e1044 {
                                                                                                let _e1045 = local_108;
                                                                                                if (_e1045 >= 1f) {
                                                                                                    let _e1047 = local_81;
                                                                                                    if (_e1047.member_1 >= 1f) {
                                                                                                        let _e1050 = local_81;
                                                                                                        if (_e1050.member[0] == 0f) {
                                                                                                            let _e1054 = local_81;
                                                                                                            let _e1057 = (_e1054.member[1] == 0f);
                                                                                                            local_110 = _e1057;
                                                                                                            if _e1057 {
                                                                                                                let _e1058 = local_81;
                                                                                                                phi_887_ = (_e1058.member[2] == 0f);
                                                                                                            } else {
                                                                                                                phi_887_ = bool();
                                                                                                            }
                                                                                                            let _e1063 = phi_887_;
                                                                                                            let _e1064 = local_110;
                                                                                                            phi_889_ = _e1063;
                                                                                                            phi_890_ = select(true, false, _e1064);
                                                                                                        } else {
                                                                                                            phi_889_ = bool();
                                                                                                            phi_890_ = true;
                                                                                                        }
                                                                                                        let _e1067 = phi_889_;
                                                                                                        let _e1069 = phi_890_;
                                                                                                        phi_891_ = _e1067;
                                                                                                        phi_892_ = _e1069;
                                                                                                    } else {
                                                                                                        phi_891_ = bool();
                                                                                                        phi_892_ = true;
                                                                                                    }
                                                                                                    let _e1071 = phi_891_;
                                                                                                    let _e1073 = phi_892_;
                                                                                                    phi_901_ = select(true, false, select(_e1071, false, _e1073));
                                                                                                } else {
                                                                                                    phi_901_ = true;
                                                                                                }
                                                                                                let _e1077 = phi_901_;
                                                                                                local_111 = _e1077;
                                                                                                if _e1077 {
                                                                                                    let _e1078 = local_81;
                                                                                                    local_112 = _e1078.member_1;
                                                                                                    if (_e1078.member_1 >= 1f) {
                                                                                                        let _e1081 = local_81;
                                                                                                        if (_e1081.member[0] == 0f) {
                                                                                                            let _e1085 = local_81;
                                                                                                            let _e1088 = (_e1085.member[1] == 0f);
                                                                                                            local_113 = _e1088;
                                                                                                            if _e1088 {
                                                                                                                let _e1089 = local_81;
                                                                                                                phi_923_ = (_e1089.member[2] == 0f);
                                                                                                            } else {
                                                                                                                phi_923_ = bool();
                                                                                                            }
                                                                                                            let _e1094 = phi_923_;
                                                                                                            let _e1095 = local_113;
                                                                                                            phi_925_ = _e1094;
                                                                                                            phi_926_ = select(true, false, _e1095);
                                                                                                        } else {
                                                                                                            phi_925_ = bool();
                                                                                                            phi_926_ = true;
                                                                                                        }
                                                                                                        let _e1098 = phi_925_;
                                                                                                        let _e1100 = phi_926_;
                                                                                                        phi_927_ = _e1098;
                                                                                                        phi_928_ = _e1100;
                                                                                                    } else {
                                                                                                        phi_927_ = bool();
                                                                                                        phi_928_ = true;
                                                                                                    }
                                                                                                    let _e1102 = phi_927_;
                                                                                                    let _e1104 = phi_928_;
                                                                                                    if select(_e1102, false, _e1104) {
                                                                                                        let _e1106 = local_108;
                                                                                                        let _e1108 = local_106;
                                                                                                        phi_961_ = type_14(_e1108, (1f - _e1106));
                                                                                                    } else {
                                                                                                        let _e1110 = local_112;
                                                                                                        if (_e1110 > 0f) {
                                                                                                            let _e1112 = local_81;
                                                                                                            let _e1115 = local_106;
                                                                                                            let _e1117 = local_112;
                                                                                                            let _e1120 = local_81;
                                                                                                            let _e1123 = local_106;
                                                                                                            let _e1125 = local_112;
                                                                                                            let _e1128 = local_81;
                                                                                                            let _e1131 = local_106;
                                                                                                            let _e1133 = local_112;
                                                                                                            let _e1137 = local_108;
                                                                                                            let _e1139 = local_112;
                                                                                                            phi_960_ = type_14(array<f32, 3>((_e1112.member[0] + (_e1117 * _e1115[0])), (_e1120.member[1] + (_e1125 * _e1123[1])), (_e1128.member[2] + (_e1133 * _e1131[2]))), (_e1139 * (1f - _e1137)));
                                                                                                        } else {
                                                                                                            phi_960_ = _e821;
                                                                                                        }
                                                                                                        let _e1143 = phi_960_;
                                                                                                        phi_961_ = _e1143;
                                                                                                    }
                                                                                                    let _e1145 = phi_961_;
                                                                                                    let _e1147 = (_e1145.member_1 <= 0f);
                                                                                                    phi_968_ = _e1145;
                                                                                                    phi_970_ = select(true, false, _e1147);
                                                                                                    phi_971_ = _e1147;
                                                                                                } else {
                                                                                                    phi_968_ = type_14();
                                                                                                    phi_970_ = false;
                                                                                                    phi_971_ = false;
                                                                                                }
                                                                                                let _e1150 = phi_968_;
                                                                                                let _e1152 = phi_970_;
                                                                                                let _e1154 = phi_971_;
                                                                                                let _e1155 = local_111;
                                                                                                phi_973_ = _e1150;
                                                                                                phi_974_ = _e1150;
                                                                                                phi_978_ = _e1152;
                                                                                                phi_979_ = _e1154;
                                                                                                phi_980_ = select(true, false, _e1155);
                                                                                            } else {
                                                                                                phi_973_ = type_14();
                                                                                                phi_974_ = _e821;
                                                                                                phi_978_ = true;
                                                                                                phi_979_ = false;
                                                                                                phi_980_ = false;
                                                                                            }
                                                                                            let _e1158 = phi_973_;
                                                                                            let _e1160 = phi_974_;
                                                                                            let _e1162 = phi_978_;
                                                                                            let _e1164 = phi_979_;
                                                                                            let _e1166 = phi_980_;
                                                                                            let _e1167 = local_109;
                                                                                            let _e1168 = local_84;
                                                                                            let _e1169 = local_82;
                                                                                            let _e1171 = local_109;
                                                                                            let _e1172 = local_65;
                                                                                            let _e1173 = local_83;
                                                                                            let _e1175 = local_109;
                                                                                            let _e1176 = local_107;
                                                                                            let _e1177 = local_85;
                                                                                            phi_981_ = _e1158;
                                                                                            phi_982_ = _e1160;
                                                                                            phi_983_ = select(_e1169, _e1168, _e1167);
                                                                                            phi_984_ = select(_e1173, _e1172, _e1171);
                                                                                            phi_985_ = select(_e1177, _e1176, _e1175);
                                                                                            phi_986_ = _e1162;
                                                                                            phi_987_ = _e1164;
                                                                                            phi_988_ = _e1166;
                                                                                        } else {
                                                                                            phi_981_ = type_14();
                                                                                            phi_982_ = _e821;
                                                                                            phi_983_ = _e823;
                                                                                            phi_984_ = _e825;
                                                                                            phi_985_ = _e829;
                                                                                            phi_986_ = true;
                                                                                            phi_987_ = false;
                                                                                            phi_988_ = false;
                                                                                        }
                                                                                        let _e1180 = phi_981_;
                                                                                        let _e1182 = phi_982_;
                                                                                        let _e1184 = phi_983_;
                                                                                        let _e1186 = phi_984_;
                                                                                        let _e1188 = phi_985_;
                                                                                        let _e1190 = phi_986_;
                                                                                        let _e1192 = phi_987_;
                                                                                        let _e1194 = phi_988_;
                                                                                        phi_989_ = _e1180;
                                                                                        phi_990_ = _e1182;
                                                                                        phi_991_ = _e1184;
                                                                                        phi_992_ = _e1186;
                                                                                        phi_993_ = _e1188;
                                                                                        phi_994_ = _e1190;
                                                                                        phi_995_ = _e1192;
                                                                                        phi_996_ = _e1194;
                                                                                    } else {
                                                                                        phi_989_ = type_14();
                                                                                        phi_990_ = _e821;
                                                                                        phi_991_ = _e823;
                                                                                        phi_992_ = _e825;
                                                                                        phi_993_ = _e829;
                                                                                        phi_994_ = true;
                                                                                        phi_995_ = false;
                                                                                        phi_996_ = false;
                                                                                    }
                                                                                    let _e1196 = phi_989_;
                                                                                    let _e1198 = phi_990_;
                                                                                    let _e1200 = phi_991_;
                                                                                    let _e1202 = phi_992_;
                                                                                    let _e1204 = phi_993_;
                                                                                    let _e1206 = phi_994_;
                                                                                    let _e1208 = phi_995_;
                                                                                    let _e1210 = phi_996_;
                                                                                    phi_1002_ = _e1198;
                                                                                    phi_1003_ = _e1200;
                                                                                    phi_1004_ = _e1202;
                                                                                    phi_1005_ = _e1204;
                                                                                    phi_1006_ = _e1196;
                                                                                    phi_1007_ = _e1022.member_1.member;
                                                                                    phi_1008_ = _e1206;
                                                                                    phi_1009_ = select(_e1208, false, _e1206);
                                                                                    phi_1010_ = select(_e1210, false, _e1206);
                                                                                } else {
                                                                                    phi_1002_ = _e821;
                                                                                    phi_1003_ = _e823;
                                                                                    phi_1004_ = _e825;
                                                                                    phi_1005_ = _e829;
                                                                                    phi_1006_ = type_14();
                                                                                    phi_1007_ = array<f32, 3>();
                                                                                    phi_1008_ = true;
                                                                                    phi_1009_ = false;
                                                                                    phi_1010_ = false;
                                                                                }
                                                                                let _e1214 = phi_1002_;
                                                                                let _e1216 = phi_1003_;
                                                                                let _e1218 = phi_1004_;
                                                                                let _e1220 = phi_1005_;
                                                                                let _e1222 = phi_1006_;
                                                                                let _e1224 = phi_1007_;
                                                                                let _e1226 = phi_1008_;
                                                                                let _e1228 = phi_1009_;
                                                                                let _e1230 = phi_1010_;
                                                                                local_114 = _e1226;
                                                                                local_115 = _e1228;
                                                                                local_116 = _e1230;
                                                                                if _e1226 {
                                                                                    let _e1231 = local_84;
                                                                                    phi_1015_ = (_e1231 + 1u);
                                                                                } else {
                                                                                    phi_1015_ = u32();
                                                                                }
                                                                                let _e1234 = phi_1015_;
                                                                                let _e1235 = local_114;
                                                                                let _e1236 = local_115;
                                                                                let _e1238 = local_114;
                                                                                let _e1239 = local_116;
                                                                                phi_579_ = _e1214;
                                                                                phi_582_ = _e1216;
                                                                                phi_584_ = _e1218;
                                                                                phi_586_ = _e1234;
                                                                                phi_588_ = _e1220;
                                                                                phi_1018_ = _e1222;
                                                                                phi_1019_ = _e1224;
                                                                                phi_1020_ = _e1226;
                                                                                phi_1022_ = select(_e1236, false, _e1235);
                                                                                phi_1023_ = select(_e1239, false, _e1238);
                                                                            } else {
                                                                                phi_579_ = type_14();
                                                                                phi_582_ = u32();
                                                                                phi_584_ = u32();
                                                                                phi_586_ = u32();
                                                                                phi_588_ = f32();
                                                                                phi_1018_ = type_14();
                                                                                phi_1019_ = array<f32, 3>();
                                                                                phi_1020_ = false;
                                                                                phi_1022_ = false;
                                                                                phi_1023_ = false;
                                                                            }
                                                                            let _e1242 = phi_579_;
                                                                            let _e1244 = phi_582_;
                                                                            let _e1246 = phi_584_;
                                                                            let _e1248 = phi_586_;
                                                                            let _e1250 = phi_588_;
                                                                            let _e1252 = phi_1018_;
                                                                            let _e1254 = phi_1019_;
                                                                            let _e1256 = phi_1020_;
                                                                            let _e1258 = phi_1022_;
                                                                            let _e1260 = phi_1023_;
                                                                            local_117 = _e1256;
                                                                            let _e1261 = local_86;
                                                                            continue;
                                                                            continuing {
                                                                                let _e1263 = local_117;
                                                                                phi_578_ = _e1242;
                                                                                phi_581_ = _e1244;
                                                                                phi_583_ = _e1246;
                                                                                phi_585_ = _e1248;
                                                                                phi_587_ = _e1250;
                                                                                phi_2010_ = _e595;
                                                                                phi_1832_ = _e1260;
                                                                                phi_1831_ = _e1258;
                                                                                phi_1830_ = select(true, false, _e1261);
                                                                                phi_1828_ = _e1254;
                                                                                phi_1826_ = _e1252;
                                                                                break if !(_e1263);
                                                                            }
                                                                        }
                                                                        let _e1266 = phi_2010_;
                                                                        let _e1268 = phi_1832_;
                                                                        let _e1270 = phi_1831_;
                                                                        let _e1272 = phi_1830_;
                                                                        let _e1274 = phi_1828_;
                                                                        let _e1276 = phi_1826_;
                                                                        local_166 = _e1268;
                                                                        local_165 = _e1270;
                                                                        local_164 = _e1272;
                                                                        phi_2099_ = _e1266;
                                                                        phi_1843_ = bool();
                                                                        phi_1842_ = bool();
                                                                        phi_1841_ = bool();
                                                                        phi_1840_ = bool();
                                                                        phi_1839_ = bool();
                                                                        phi_1838_ = bool();
                                                                        phi_1837_ = bool();
                                                                        phi_1836_ = bool();
                                                                        phi_1835_ = bool();
                                                                        phi_1834_ = array<f32, 3>();
                                                                        phi_1833_ = type_14();
                                                                        if _e1266 {
                                                                            break;
                                                                        }
                                                                        let _e1277 = local_164;
                                                                        if _e1277 {
                                                                            let _e1278 = local_188;
                                                                            let _e1279 = local_47;
                                                                            phi_1028_ = (_e1278 + _e1279);
                                                                        } else {
                                                                            phi_1028_ = f32();
                                                                        }
                                                                        let _e1282 = phi_1028_;
                                                                        let _e1283 = local_164;
                                                                        let _e1284 = local_165;
                                                                        let _e1286 = local_164;
                                                                        let _e1287 = local_166;
                                                                        phi_2113_ = _e1266;
                                                                        let _e2436 = local_223;
                                                                        phi_1031_ = _e2436;
                                                                        let _e2439 = local_224;
                                                                        phi_1032_ = _e2439;
                                                                        let _e2442 = local_225;
                                                                        phi_1033_ = _e2442;
                                                                        let _e2445 = local_226;
                                                                        phi_1034_ = _e2445;
                                                                        phi_1035_ = _e1282;
                                                                        phi_1036_ = _e1276;
                                                                        phi_1037_ = _e1274;
                                                                        phi_1038_ = _e1272;
                                                                        phi_1039_ = select(_e1284, false, _e1283);
                                                                        phi_1040_ = select(_e1287, false, _e1286);
                                                                    }
                                                                    let _e1290 = phi_2113_;
                                                                    let _e1292 = phi_1031_;
                                                                    let _e1294 = phi_1032_;
                                                                    let _e1296 = phi_1033_;
                                                                    let _e1298 = phi_1034_;
                                                                    let _e1300 = phi_1035_;
                                                                    let _e1302 = phi_1036_;
                                                                    let _e1304 = phi_1037_;
                                                                    let _e1306 = phi_1038_;
                                                                    let _e1308 = phi_1039_;
                                                                    let _e1310 = phi_1040_;
                                                                    phi_2112_ = _e1290;
                                                                    phi_1041_ = _e1292;
                                                                    phi_1042_ = _e1294;
                                                                    phi_1043_ = _e1296;
                                                                    phi_1044_ = _e1298;
                                                                    phi_1045_ = _e609;
                                                                    phi_1046_ = _e1300;
                                                                    phi_1047_ = _e1302;
                                                                    phi_1048_ = _e1304;
                                                                    phi_1049_ = _e1306;
                                                                    phi_1050_ = _e819;
                                                                    phi_1051_ = _e1308;
                                                                    phi_1052_ = _e1310;
                                                                }
                                                                let _e1312 = phi_2112_;
                                                                let _e1314 = phi_1041_;
                                                                let _e1316 = phi_1042_;
                                                                let _e1318 = phi_1043_;
                                                                let _e1320 = phi_1044_;
                                                                let _e1322 = phi_1045_;
                                                                let _e1324 = phi_1046_;
                                                                let _e1326 = phi_1047_;
                                                                let _e1328 = phi_1048_;
                                                                let _e1330 = phi_1049_;
                                                                let _e1332 = phi_1050_;
                                                                let _e1334 = phi_1051_;
                                                                let _e1336 = phi_1052_;
                                                                phi_2110_ = _e1312;
                                                                phi_1059_ = _e1314;
                                                                phi_1060_ = _e1316;
                                                                phi_1061_ = _e1318;
                                                                phi_1062_ = _e1320;
                                                                phi_1063_ = _e1322;
                                                                phi_1064_ = _e1324;
                                                                phi_1065_ = _e1326;
                                                                phi_1066_ = _e1328;
                                                                phi_1067_ = _e1330;
                                                                phi_1068_ = select(_e1332, false, _e1330);
                                                                phi_1069_ = select(_e1334, false, _e1330);
                                                                phi_1070_ = select(_e1336, false, _e1330);
                                                            }
                                                            let _e1341 = phi_2110_;
                                                            let _e1343 = phi_1059_;
                                                            let _e1345 = phi_1060_;
                                                            let _e1347 = phi_1061_;
                                                            let _e1349 = phi_1062_;
                                                            let _e1351 = phi_1063_;
                                                            let _e1353 = phi_1064_;
                                                            let _e1355 = phi_1065_;
                                                            let _e1357 = phi_1066_;
                                                            let _e1359 = phi_1067_;
                                                            let _e1361 = phi_1068_;
                                                            let _e1363 = phi_1069_;
                                                            let _e1365 = phi_1070_;
                                                            phi_2109_ = _e1341;
                                                            phi_1071_ = _e1343;
                                                            phi_1072_ = _e1345;
                                                            phi_1073_ = _e1347;
                                                            phi_1074_ = _e1349;
                                                            phi_1075_ = _e1351;
                                                            phi_1076_ = _e1353;
                                                            phi_1077_ = _e1355;
                                                            phi_1078_ = _e1357;
                                                            phi_1079_ = _e802;
                                                            phi_1080_ = _e1359;
                                                            phi_1081_ = _e1361;
                                                            phi_1082_ = _e1363;
                                                            phi_1083_ = _e1365;
                                                        }
                                                        let _e1367 = phi_2109_;
                                                        let _e1369 = phi_1071_;
                                                        let _e1371 = phi_1072_;
                                                        let _e1373 = phi_1073_;
                                                        let _e1375 = phi_1074_;
                                                        let _e1377 = phi_1075_;
                                                        let _e1379 = phi_1076_;
                                                        let _e1381 = phi_1077_;
                                                        let _e1383 = phi_1078_;
                                                        let _e1385 = phi_1079_;
                                                        let _e1387 = phi_1080_;
                                                        let _e1389 = phi_1081_;
                                                        let _e1391 = phi_1082_;
                                                        let _e1393 = phi_1083_;
                                                        local_118 = _e1371;
                                                        local_119 = _e1373;
                                                        local_120 = _e1375;
                                                        local_121 = _e1385;
                                                        local_122 = _e1387;
                                                        local_123 = _e1389;
                                                        local_124 = _e1391;
                                                        local_125 = _e1393;
                                                        if _e1385 {
                                                            let _e1394 = local_188;
                                                            let _e1395 = local_47;
                                                            let _e1397 = local_55;
                                                            let _e1398 = (_e1397 + 1u);
                                                            let _e1399 = local_27;
                                                            let _e1401 = local_55;
                                                            phi_1097_ = _e597;
                                                            phi_1101_ = select(_e1401, _e1398, (_e1398 < _e1399));
                                                            phi_1102_ = (_e1394 + _e1395);
                                                        } else {
                                                            phi_1097_ = _e1369;
                                                            phi_1101_ = _e1377;
                                                            phi_1102_ = _e1379;
                                                        }
                                                        let _e1404 = phi_1097_;
                                                        let _e1406 = phi_1101_;
                                                        let _e1408 = phi_1102_;
                                                        let _e1409 = local_121;
                                                        let _e1410 = local_50;
                                                        let _e1411 = local_118;
                                                        let _e1413 = local_121;
                                                        let _e1414 = local_51;
                                                        let _e1415 = local_119;
                                                        let _e1417 = local_121;
                                                        let _e1418 = local_52;
                                                        let _e1419 = local_120;
                                                        let _e1421 = local_121;
                                                        let _e1422 = local_122;
                                                        let _e1423 = select(_e1422, true, _e1421);
                                                        let _e1424 = local_121;
                                                        let _e1425 = local_123;
                                                        let _e1427 = local_121;
                                                        let _e1428 = local_124;
                                                        let _e1430 = local_121;
                                                        let _e1431 = local_125;
                                                        phi_2105_ = _e1367;
                                                        phi_1113_ = _e1404;
                                                        phi_1114_ = select(_e1411, _e1410, _e1409);
                                                        phi_1115_ = select(_e1415, _e1414, _e1413);
                                                        phi_1116_ = select(_e1419, _e1418, _e1417);
                                                        phi_1117_ = _e657;
                                                        phi_1118_ = _e1406;
                                                        phi_1119_ = _e1408;
                                                        phi_1120_ = _e1381;
                                                        phi_1121_ = _e1383;
                                                        phi_1122_ = _e1423;
                                                        phi_1123_ = select(select(_e1425, false, _e1424), false, _e1423);
                                                        phi_1124_ = select(select(_e1428, false, _e1427), false, _e1423);
                                                        phi_1125_ = select(select(_e1431, false, _e1430), false, _e1423);
                                                    } else {
                                                        phi_2105_ = _e595;
                                                        phi_1113_ = type_14();
                                                        phi_1114_ = u32();
                                                        phi_1115_ = u32();
                                                        phi_1116_ = f32();
                                                        phi_1117_ = u32();
                                                        phi_1118_ = u32();
                                                        phi_1119_ = f32();
                                                        phi_1120_ = type_14();
                                                        phi_1121_ = array<f32, 3>();
                                                        phi_1122_ = false;
                                                        phi_1123_ = false;
                                                        phi_1124_ = false;
                                                        phi_1125_ = false;
                                                    }
                                                    let _e1437 = phi_2105_;
                                                    let _e1439 = phi_1113_;
                                                    let _e1441 = phi_1114_;
                                                    let _e1443 = phi_1115_;
                                                    let _e1445 = phi_1116_;
                                                    let _e1447 = phi_1117_;
                                                    let _e1449 = phi_1118_;
                                                    let _e1451 = phi_1119_;
                                                    let _e1453 = phi_1120_;
                                                    let _e1455 = phi_1121_;
                                                    let _e1457 = phi_1122_;
                                                    let _e1459 = phi_1123_;
                                                    let _e1461 = phi_1124_;
                                                    let _e1463 = phi_1125_;
                                                    let _e1464 = local_64;
                                                    phi_2104_ = _e1437;
                                                    phi_1127_ = _e1439;
                                                    phi_1128_ = _e1441;
                                                    phi_1129_ = _e1443;
                                                    phi_1130_ = _e1445;
                                                    phi_1131_ = _e1447;
                                                    phi_1132_ = _e1449;
                                                    phi_1133_ = _e1451;
                                                    phi_1134_ = _e1453;
                                                    phi_1135_ = _e1455;
                                                    phi_1136_ = _e1457;
                                                    phi_1137_ = _e1459;
                                                    phi_1138_ = _e1461;
                                                    phi_1139_ = _e1463;
                                                    phi_1140_ = select(true, false, _e1464);
                                                } else {
                                                    phi_2104_ = _e595;
                                                    phi_1127_ = type_14();
                                                    phi_1128_ = u32();
                                                    phi_1129_ = u32();
                                                    phi_1130_ = f32();
                                                    phi_1131_ = u32();
                                                    phi_1132_ = u32();
                                                    phi_1133_ = f32();
                                                    phi_1134_ = type_14();
                                                    phi_1135_ = array<f32, 3>();
                                                    phi_1136_ = false;
                                                    phi_1137_ = false;
                                                    phi_1138_ = false;
                                                    phi_1139_ = false;
                                                    phi_1140_ = false;
                                                }
                                                let _e1467 = phi_2104_;
                                                let _e1469 = phi_1127_;
                                                let _e1471 = phi_1128_;
                                                let _e1473 = phi_1129_;
                                                let _e1475 = phi_1130_;
                                                let _e1477 = phi_1131_;
                                                let _e1479 = phi_1132_;
                                                let _e1481 = phi_1133_;
                                                let _e1483 = phi_1134_;
                                                let _e1485 = phi_1135_;
                                                let _e1487 = phi_1136_;
                                                let _e1489 = phi_1137_;
                                                let _e1491 = phi_1138_;
                                                let _e1493 = phi_1139_;
                                                let _e1495 = phi_1140_;
                                                let _e1496 = local_63;
                                                phi_2103_ = _e1467;
                                                phi_1142_ = _e1469;
                                                phi_1143_ = _e1471;
                                                phi_1144_ = _e1473;
                                                phi_1145_ = _e1475;
                                                phi_1146_ = _e1477;
                                                phi_1147_ = _e1479;
                                                phi_1148_ = _e1481;
                                                phi_1149_ = _e1483;
                                                phi_1150_ = _e1485;
                                                phi_1151_ = _e1487;
                                                phi_1152_ = _e1489;
                                                phi_1153_ = _e1491;
                                                phi_1154_ = _e1493;
                                                phi_1155_ = _e1495;
                                                phi_1156_ = select(true, false, _e1496);
                                            } else {
                                                phi_2103_ = _e595;
                                                phi_1142_ = type_14();
                                                phi_1143_ = u32();
                                                phi_1144_ = u32();
                                                phi_1145_ = f32();
                                                phi_1146_ = u32();
                                                phi_1147_ = u32();
                                                phi_1148_ = f32();
                                                phi_1149_ = type_14();
                                                phi_1150_ = array<f32, 3>();
                                                phi_1151_ = false;
                                                phi_1152_ = false;
                                                phi_1153_ = false;
                                                phi_1154_ = false;
                                                phi_1155_ = false;
                                                phi_1156_ = false;
                                            }
                                            let _e1499 = phi_2103_;
                                            let _e1501 = phi_1142_;
                                            let _e1503 = phi_1143_;
                                            let _e1505 = phi_1144_;
                                            let _e1507 = phi_1145_;
                                            let _e1509 = phi_1146_;
                                            let _e1511 = phi_1147_;
                                            let _e1513 = phi_1148_;
                                            let _e1515 = phi_1149_;
                                            let _e1517 = phi_1150_;
                                            let _e1519 = phi_1151_;
                                            let _e1521 = phi_1152_;
                                            let _e1523 = phi_1153_;
                                            let _e1525 = phi_1154_;
                                            let _e1527 = phi_1155_;
                                            let _e1529 = phi_1156_;
                                            let _e1530 = local_62;
                                            phi_2102_ = _e1499;
                                            phi_1158_ = _e1501;
                                            phi_1159_ = _e1503;
                                            phi_1160_ = _e1505;
                                            phi_1161_ = _e1507;
                                            phi_1162_ = _e1509;
                                            phi_1163_ = _e1511;
                                            phi_1164_ = _e1513;
                                            phi_1165_ = _e1515;
                                            phi_1166_ = _e1517;
                                            phi_1167_ = _e1519;
                                            phi_1168_ = _e1521;
                                            phi_1169_ = _e1523;
                                            phi_1170_ = _e1525;
                                            phi_1171_ = _e1527;
                                            phi_1172_ = _e1529;
                                            phi_1173_ = select(true, false, _e1530);
                                        } else {
                                            phi_2102_ = _e595;
                                            phi_1158_ = type_14();
                                            phi_1159_ = u32();
                                            phi_1160_ = u32();
                                            phi_1161_ = f32();
                                            phi_1162_ = u32();
                                            phi_1163_ = u32();
                                            phi_1164_ = f32();
                                            phi_1165_ = type_14();
                                            phi_1166_ = array<f32, 3>();
                                            phi_1167_ = false;
                                            phi_1168_ = false;
                                            phi_1169_ = false;
                                            phi_1170_ = false;
                                            phi_1171_ = false;
                                            phi_1172_ = false;
                                            phi_1173_ = false;
                                        }
                                        let _e1533 = phi_2102_;
                                        let _e1535 = phi_1158_;
                                        let _e1537 = phi_1159_;
                                        let _e1539 = phi_1160_;
                                        let _e1541 = phi_1161_;
                                        let _e1543 = phi_1162_;
                                        let _e1545 = phi_1163_;
                                        let _e1547 = phi_1164_;
                                        let _e1549 = phi_1165_;
                                        let _e1551 = phi_1166_;
                                        let _e1553 = phi_1167_;
                                        let _e1555 = phi_1168_;
                                        let _e1557 = phi_1169_;
                                        let _e1559 = phi_1170_;
                                        let _e1561 = phi_1171_;
                                        let _e1563 = phi_1172_;
                                        let _e1565 = phi_1173_;
                                        let _e1566 = local_61;
                                        phi_2101_ = _e1533;
                                        phi_1175_ = _e1535;
                                        phi_1176_ = _e1537;
                                        phi_1177_ = _e1539;
                                        phi_1178_ = _e1541;
                                        phi_1179_ = _e1543;
                                        phi_1180_ = (_e618 + 1u);
                                        phi_1181_ = _e1545;
                                        phi_1182_ = _e1547;
                                        phi_1183_ = _e1549;
                                        phi_1184_ = _e1551;
                                        phi_1185_ = _e1553;
                                        phi_1186_ = _e1555;
                                        phi_1187_ = _e1557;
                                        phi_1188_ = _e1559;
                                        phi_1189_ = _e1561;
                                        phi_1190_ = _e1563;
                                        phi_1191_ = _e1565;
                                        phi_1192_ = select(true, false, _e1566);
                                    } else {
                                        phi_2101_ = _e595;
                                        phi_1175_ = type_14();
                                        phi_1176_ = u32();
                                        phi_1177_ = u32();
                                        phi_1178_ = f32();
                                        phi_1179_ = u32();
                                        phi_1180_ = u32();
                                        phi_1181_ = u32();
                                        phi_1182_ = f32();
                                        phi_1183_ = type_14();
                                        phi_1184_ = array<f32, 3>();
                                        phi_1185_ = false;
                                        phi_1186_ = false;
                                        phi_1187_ = false;
                                        phi_1188_ = false;
                                        phi_1189_ = false;
                                        phi_1190_ = false;
                                        phi_1191_ = false;
                                        phi_1192_ = false;
                                    }
                                    let _e1569 = phi_2101_;
                                    let _e1571 = phi_1175_;
                                    let _e1573 = phi_1176_;
                                    let _e1575 = phi_1177_;
                                    let _e1577 = phi_1178_;
                                    let _e1579 = phi_1179_;
                                    let _e1581 = phi_1180_;
                                    let _e1583 = phi_1181_;
                                    let _e1585 = phi_1182_;
                                    let _e1587 = phi_1183_;
                                    let _e1589 = phi_1184_;
                                    let _e1591 = phi_1185_;
                                    let _e1593 = phi_1186_;
                                    let _e1595 = phi_1187_;
                                    let _e1597 = phi_1188_;
                                    let _e1599 = phi_1189_;
                                    let _e1601 = phi_1190_;
                                    let _e1603 = phi_1191_;
                                    let _e1605 = phi_1192_;
                                    let _e1606 = local_58;
                                    phi_2100_ = _e1569;
                                    phi_357_ = _e1571;
                                    phi_360_ = _e1573;
                                    phi_362_ = _e1575;
                                    phi_364_ = _e1577;
                                    phi_366_ = _e1579;
                                    phi_368_ = _e1581;
                                    phi_370_ = _e1583;
                                    phi_372_ = _e1585;
                                    phi_1194_ = _e1587;
                                    phi_1195_ = _e1589;
                                    phi_1196_ = _e1591;
                                    phi_1198_ = _e1593;
                                    phi_1199_ = _e1595;
                                    phi_1200_ = _e1597;
                                    phi_1201_ = _e1599;
                                    phi_1202_ = _e1601;
                                    phi_1203_ = _e1603;
                                    phi_1204_ = _e1605;
                                    phi_1205_ = select(true, false, _e1606);
                                } else {
                                    phi_2100_ = _e595;
                                    phi_357_ = type_14();
                                    phi_360_ = u32();
                                    phi_362_ = u32();
                                    phi_364_ = f32();
                                    phi_366_ = u32();
                                    phi_368_ = u32();
                                    phi_370_ = u32();
                                    phi_372_ = f32();
                                    phi_1194_ = type_14();
                                    phi_1195_ = array<f32, 3>();
                                    phi_1196_ = false;
                                    phi_1198_ = false;
                                    phi_1199_ = false;
                                    phi_1200_ = false;
                                    phi_1201_ = false;
                                    phi_1202_ = false;
                                    phi_1203_ = false;
                                    phi_1204_ = false;
                                    phi_1205_ = false;
                                }
                                let _e1609 = phi_2100_;
                                let _e1611 = phi_357_;
                                let _e1613 = phi_360_;
                                let _e1615 = phi_362_;
                                let _e1617 = phi_364_;
                                let _e1619 = phi_366_;
                                let _e1621 = phi_368_;
                                let _e1623 = phi_370_;
                                let _e1625 = phi_372_;
                                let _e1627 = phi_1194_;
                                let _e1629 = phi_1195_;
                                let _e1631 = phi_1196_;
                                let _e1633 = phi_1198_;
                                let _e1635 = phi_1199_;
                                let _e1637 = phi_1200_;
                                let _e1639 = phi_1201_;
                                let _e1641 = phi_1202_;
                                let _e1643 = phi_1203_;
                                let _e1645 = phi_1204_;
                                let _e1647 = phi_1205_;
                                local_126 = _e1631;
                                let _e1648 = local_57;
                                continue;
                                continuing {
                                    let _e1650 = local_126;
                                    phi_2071_ = _e1609;
                                    phi_356_ = _e1611;
                                    phi_359_ = _e1613;
                                    phi_361_ = _e1615;
                                    phi_363_ = _e1617;
                                    phi_365_ = _e1619;
                                    phi_367_ = _e1621;
                                    phi_369_ = _e1623;
                                    phi_371_ = _e1625;
                                    phi_2099_ = _e1609;
                                    phi_1843_ = _e1647;
                                    phi_1842_ = _e1645;
                                    phi_1841_ = _e1643;
                                    phi_1840_ = _e1641;
                                    phi_1839_ = _e1639;
                                    phi_1838_ = _e1637;
                                    phi_1837_ = _e1635;
                                    phi_1836_ = _e1633;
                                    phi_1835_ = select(true, false, _e1648);
                                    phi_1834_ = _e1629;
                                    phi_1833_ = _e1627;
                                    break if !(_e1650);
                                }
                            }
                            let _e1653 = phi_2099_;
                            let _e1655 = phi_1843_;
                            let _e1657 = phi_1842_;
                            let _e1659 = phi_1841_;
                            let _e1661 = phi_1840_;
                            let _e1663 = phi_1839_;
                            let _e1665 = phi_1838_;
                            let _e1667 = phi_1837_;
                            let _e1669 = phi_1836_;
                            let _e1671 = phi_1835_;
                            let _e1673 = phi_1834_;
                            let _e1675 = phi_1833_;
                            local_177 = _e1655;
                            local_176 = _e1657;
                            local_175 = _e1659;
                            local_174 = _e1661;
                            local_173 = _e1663;
                            local_172 = _e1665;
                            local_171 = _e1667;
                            local_170 = _e1669;
                            local_169 = _e1671;
                            local_168 = _e1673;
                            local_167 = _e1675;
                            phi_2166_ = _e1653;
                            if _e1653 {
                                break;
                            }
                            let _e1676 = local_169;
                            let _e1677 = local_170;
                            let _e1678 = select(_e1677, false, _e1676);
                            local_190 = _e1678;
                            let _e1679 = local_169;
                            let _e1680 = local_171;
                            local_191 = select(_e1680, false, _e1679);
                            let _e1682 = local_169;
                            let _e1683 = local_172;
                            local_192 = select(_e1683, false, _e1682);
                            let _e1685 = local_169;
                            let _e1686 = local_173;
                            local_193 = select(_e1686, false, _e1685);
                            let _e1688 = local_169;
                            let _e1689 = local_174;
                            local_194 = select(_e1689, false, _e1688);
                            let _e1691 = local_169;
                            let _e1692 = local_175;
                            local_195 = select(_e1692, false, _e1691);
                            let _e1694 = local_169;
                            let _e1695 = local_176;
                            local_196 = select(_e1695, false, _e1694);
                            let _e1697 = local_169;
                            let _e1698 = local_177;
                            local_197 = select(_e1698, false, _e1697);
                            if _e1678 {
                                let _e1700 = local_49;
                                phi_1222_ = type_25(_e1700.member, true);
                            } else {
                                phi_1222_ = type_25();
                            }
                            let _e1704 = phi_1222_;
                            let _e1705 = local_190;
                            let _e1706 = local_191;
                            let _e1707 = select(_e1706, false, _e1705);
                            local_198 = _e1707;
                            let _e1708 = local_190;
                            let _e1709 = local_192;
                            local_199 = select(_e1709, false, _e1708);
                            let _e1711 = local_190;
                            let _e1712 = local_193;
                            local_200 = select(_e1712, false, _e1711);
                            let _e1714 = local_190;
                            let _e1715 = local_194;
                            local_201 = select(_e1715, false, _e1714);
                            let _e1717 = local_190;
                            let _e1718 = local_195;
                            local_202 = select(_e1718, false, _e1717);
                            let _e1720 = local_190;
                            let _e1721 = local_196;
                            local_203 = select(_e1721, false, _e1720);
                            let _e1723 = local_190;
                            let _e1724 = local_197;
                            local_204 = select(_e1724, false, _e1723);
                            let _e1726 = local_190;
                            let _e1727 = local_169;
                            local_205 = select(_e1727, false, _e1726);
                            if _e1707 {
                                let _e1729 = local_167;
                                phi_1236_ = type_25(_e1729.member, true);
                            } else {
                                phi_1236_ = type_25();
                            }
                            let _e1733 = phi_1236_;
                            let _e1734 = local_198;
                            let _e1735 = local_199;
                            let _e1736 = select(_e1735, false, _e1734);
                            local_206 = _e1736;
                            let _e1737 = local_198;
                            let _e1738 = local_190;
                            local_207 = select(_e1738, false, _e1737);
                            let _e1740 = local_198;
                            let _e1741 = local_200;
                            local_208 = select(_e1741, false, _e1740);
                            let _e1743 = local_198;
                            let _e1744 = local_201;
                            local_209 = select(_e1744, false, _e1743);
                            let _e1746 = local_198;
                            let _e1747 = local_202;
                            local_210 = select(_e1747, false, _e1746);
                            let _e1749 = local_198;
                            let _e1750 = local_203;
                            local_211 = select(_e1750, false, _e1749);
                            let _e1752 = local_198;
                            let _e1753 = local_204;
                            local_212 = select(_e1753, false, _e1752);
                            let _e1755 = local_198;
                            let _e1756 = local_205;
                            local_213 = select(_e1756, false, _e1755);
                            if _e1736 {
                                let _e1758 = local_168;
                                phi_1249_ = type_25(_e1758, true);
                            } else {
                                phi_1249_ = _e1733;
                            }
                            let _e1761 = phi_1249_;
                            let _e1762 = local_206;
                            let _e1763 = local_198;
                            let _e1764 = select(_e1763, true, _e1762);
                            local_214 = _e1764;
                            let _e1765 = local_206;
                            let _e1766 = local_207;
                            local_215 = select(_e1766, false, _e1765);
                            let _e1768 = local_206;
                            let _e1769 = local_208;
                            local_216 = select(_e1769, false, _e1768);
                            let _e1771 = local_206;
                            let _e1772 = local_209;
                            local_217 = select(_e1772, false, _e1771);
                            let _e1774 = local_206;
                            let _e1775 = local_210;
                            local_218 = select(_e1775, false, _e1774);
                            let _e1777 = local_206;
                            let _e1778 = local_211;
                            local_219 = select(_e1778, false, _e1777);
                            let _e1780 = local_206;
                            let _e1781 = local_212;
                            local_220 = select(_e1781, false, _e1780);
                            let _e1783 = local_206;
                            let _e1784 = local_213;
                            local_221 = select(_e1784, false, _e1783);
                            if _e1764 {
                                phi_1261_ = _e1761;
                            } else {
                                phi_1261_ = _e1704;
                            }
                            let _e1787 = phi_1261_;
                            let _e1788 = local_214;
                            let _e1789 = local_215;
                            let _e1790 = select(_e1789, true, _e1788);
                            let _e1791 = local_214;
                            let _e1792 = local_216;
                            let _e1794 = local_214;
                            let _e1795 = local_217;
                            let _e1797 = local_214;
                            let _e1798 = local_218;
                            let _e1800 = local_214;
                            let _e1801 = local_219;
                            let _e1803 = local_214;
                            let _e1804 = local_220;
                            let _e1806 = local_214;
                            let _e1807 = local_221;
                            let _e1809 = select(select(_e1792, false, _e1791), false, _e1790);
                            let _e1815 = select(select(select(_e1795, false, _e1794), false, _e1790), false, _e1809);
                            let _e1820 = select(select(select(select(_e1798, false, _e1797), false, _e1790), false, _e1809), false, _e1815);
                            let _e1825 = select(select(select(select(select(_e1801, false, _e1800), false, _e1790), false, _e1809), false, _e1815), false, _e1820);
                            let _e1829 = select(select(select(_e1809, true, _e1815), true, _e1820), true, _e1825);
                            if select(select(select(select(select(select(select(select(_e1807, false, _e1806), false, _e1790), false, _e1809), false, _e1815), false, _e1820), false, _e1825), true, _e1829), true, select(select(select(select(select(select(select(_e1804, false, _e1803), false, _e1790), false, _e1809), false, _e1815), false, _e1820), false, _e1825), false, _e1829)) {
                                let _e1838 = local_53;
                                let _e1839 = local_1;
                                if (_e1838 < _e1839) {
                                } else {
                                    phi_2166_ = true;
                                    break;
                                }
                                let _e1841 = local_53;
                                let _e1844 = global_3.member[_e1841];
                                let _e1847 = global_5.member.member_2;
                                local_127 = _e1847;
                                local_222 = select(_e1844, _e1847, (_e1847 < _e1844));
                                phi_1335_ = type_18(0u, type_18().member_1);
                                phi_1338_ = 0u;
                                loop {
                                    let _e1851 = phi_1335_;
                                    let _e1853 = phi_1338_;
                                    local_128 = _e1851;
                                    local_129 = _e1853;
                                    let _e1854 = local_129;
                                    let _e1855 = local_222;
                                    let _e1856 = (_e1854 < _e1855);
                                    local_130 = _e1856;
                                    if _e1856 {
                                        let _e1857 = local_53;
                                        let _e1858 = local_127;
                                        let _e1860 = local_129;
                                        let _e1862 = (5u * ((_e1857 * _e1858) + _e1860));
                                        local_131 = _e1862;
                                        let _e1863 = local;
                                        if (_e1862 < _e1863) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1865 = local_131;
                                        let _e1868 = global_4.member[_e1865];
                                        local_132 = bitcast<f32>(_e1868);
                                        let _e1870 = local_131;
                                        let _e1871 = (_e1870 + 1u);
                                        local_133 = _e1871;
                                        let _e1872 = local;
                                        if (_e1871 < _e1872) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1874 = local_133;
                                        let _e1877 = global_4.member[_e1874];
                                        local_134 = bitcast<f32>(_e1877);
                                        let _e1879 = local_131;
                                        let _e1880 = (_e1879 + 2u);
                                        local_135 = _e1880;
                                        let _e1881 = local;
                                        if (_e1880 < _e1881) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1883 = local_135;
                                        let _e1886 = global_4.member[_e1883];
                                        local_136 = bitcast<f32>(_e1886);
                                        let _e1888 = local_131;
                                        let _e1889 = (_e1888 + 3u);
                                        local_137 = _e1889;
                                        let _e1890 = local;
                                        if (_e1889 < _e1890) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1892 = local_137;
                                        let _e1895 = global_4.member[_e1892];
                                        local_138 = bitcast<f32>(_e1895);
                                        let _e1897 = local_131;
                                        let _e1898 = (_e1897 + 4u);
                                        local_139 = _e1898;
                                        let _e1899 = local;
                                        if (_e1898 < _e1899) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1901 = local_139;
                                        let _e1904 = global_4.member[_e1901];
                                        local_140 = bitcast<f32>(_e1904);
                                        let _e1906 = local_132;
                                        if ((bitcast<u32>(_e1906) & 2139095040u) != 2139095040u) {
                                            let _e1910 = local_134;
                                            if ((bitcast<u32>(_e1910) & 2139095040u) != 2139095040u) {
                                                let _e1914 = local_136;
                                                let _e1917 = ((bitcast<u32>(_e1914) & 2139095040u) != 2139095040u);
                                                local_141 = _e1917;
                                                if _e1917 {
                                                    let _e1918 = local_138;
                                                    let _e1919 = bitcast<u32>(_e1918);
                                                    local_142 = _e1919;
                                                    if (_e1919 == 0u) {
                                                        phi_1419_ = false;
                                                    } else {
                                                        let _e1921 = local_142;
                                                        phi_1419_ = (_e1921 <= 2139095040u);
                                                    }
                                                    let _e1924 = phi_1419_;
                                                    phi_1420_ = _e1924;
                                                } else {
                                                    phi_1420_ = bool();
                                                }
                                                let _e1926 = phi_1420_;
                                                let _e1927 = local_141;
                                                phi_1422_ = _e1926;
                                                phi_1423_ = select(true, false, _e1927);
                                            } else {
                                                phi_1422_ = bool();
                                                phi_1423_ = true;
                                            }
                                            let _e1930 = phi_1422_;
                                            let _e1932 = phi_1423_;
                                            phi_1424_ = _e1930;
                                            phi_1425_ = _e1932;
                                        } else {
                                            phi_1424_ = bool();
                                            phi_1425_ = true;
                                        }
                                        let _e1934 = phi_1424_;
                                        let _e1936 = phi_1425_;
                                        if select(_e1934, false, _e1936) {
                                            let _e1938 = local_138;
                                            let _e1939 = bitcast<u32>(_e1938);
                                            local_143 = _e1939;
                                            if (_e1939 == 0u) {
                                                phi_1440_ = false;
                                            } else {
                                                let _e1941 = local_143;
                                                phi_1440_ = (_e1941 <= 2139095040u);
                                            }
                                            let _e1944 = phi_1440_;
                                            if _e1944 {
                                                let _e1945 = local_43;
                                                if (_e1945 == 0f) {
                                                    phi_1468_ = 0f;
                                                } else {
                                                    let _e1947 = local_42;
                                                    let _e1948 = local_138;
                                                    let _e1951 = local_43;
                                                    phi_1468_ = (_e1951 * (1f - (_e1947 / _e1948)));
                                                }
                                                let _e1954 = phi_1468_;
                                                phi_1469_ = _e1954;
                                            } else {
                                                phi_1469_ = _e284;
                                            }
                                            let _e1956 = phi_1469_;
                                            let _e1957 = (0.5f * _e1956);
                                            local_144 = _e1957;
                                            let _e1960 = ((bitcast<u32>(_e1957) & 2139095040u) != 2139095040u);
                                            local_145 = _e1960;
                                            if _e1960 {
                                                let _e1961 = local_132;
                                                if (_e1961 > 1267650600000000000000000000000f) {
                                                    let _e1963 = local_132;
                                                    phi_1486_ = select(true, false, (_e1963 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1486_ = true;
                                                }
                                                let _e1967 = phi_1486_;
                                                if _e1967 {
                                                    let _e1968 = local_132;
                                                    if (_e1968 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e1970 = local_132;
                                                        phi_1500_ = select(true, false, (_e1970 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_1500_ = true;
                                                    }
                                                    let _e1974 = phi_1500_;
                                                    let _e1975 = local_132;
                                                    phi_1505_ = select(0f, _e1975, _e1974);
                                                } else {
                                                    phi_1505_ = 1267650600000000000000000000000f;
                                                }
                                                let _e1978 = phi_1505_;
                                                local_146 = _e1978;
                                                let _e1979 = local_134;
                                                if (_e1979 > 1267650600000000000000000000000f) {
                                                    let _e1981 = local_134;
                                                    phi_1515_ = select(true, false, (_e1981 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1515_ = true;
                                                }
                                                let _e1985 = phi_1515_;
                                                if _e1985 {
                                                    let _e1986 = local_134;
                                                    if (_e1986 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e1988 = local_134;
                                                        phi_1529_ = select(true, false, (_e1988 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_1529_ = true;
                                                    }
                                                    let _e1992 = phi_1529_;
                                                    let _e1993 = local_134;
                                                    phi_1534_ = select(0f, _e1993, _e1992);
                                                } else {
                                                    phi_1534_ = 1267650600000000000000000000000f;
                                                }
                                                let _e1996 = phi_1534_;
                                                local_147 = _e1996;
                                                let _e1997 = local_136;
                                                if (_e1997 > 1267650600000000000000000000000f) {
                                                    let _e1999 = local_136;
                                                    phi_1544_ = select(true, false, (_e1999 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1544_ = true;
                                                }
                                                let _e2003 = phi_1544_;
                                                if _e2003 {
                                                    let _e2004 = local_136;
                                                    if (_e2004 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e2006 = local_136;
                                                        phi_1558_ = select(true, false, (_e2006 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_1558_ = true;
                                                    }
                                                    let _e2010 = phi_1558_;
                                                    let _e2011 = local_136;
                                                    phi_1563_ = select(0f, _e2011, _e2010);
                                                } else {
                                                    phi_1563_ = 1267650600000000000000000000000f;
                                                }
                                                let _e2014 = phi_1563_;
                                                let _e2015 = local_146;
                                                let _e2016 = local_147;
                                                local_148 = array<f32, 3>(_e2015, _e2016, _e2014);
                                                let _e2018 = local_140;
                                                if (_e2018 > 1f) {
                                                    phi_1574_ = 1f;
                                                } else {
                                                    let _e2020 = local_140;
                                                    let _e2022 = local_140;
                                                    phi_1574_ = select(0f, _e2022, (_e2020 >= 0f));
                                                }
                                                let _e2025 = phi_1574_;
                                                let _e2026 = local_148;
                                                let _e2027 = local_144;
                                                phi_1577_ = type_24(1u, type_17(_e2026, _e2027, _e2025));
                                            } else {
                                                phi_1577_ = type_24();
                                            }
                                            let _e2031 = phi_1577_;
                                            let _e2032 = local_145;
                                            phi_1579_ = _e2031;
                                            phi_1580_ = select(true, false, _e2032);
                                        } else {
                                            phi_1579_ = type_24();
                                            phi_1580_ = true;
                                        }
                                        let _e2035 = phi_1579_;
                                        let _e2037 = phi_1580_;
                                        if _e2037 {
                                            phi_1585_ = type_24(0u, type_24().member_1);
                                        } else {
                                            phi_1585_ = _e2035;
                                        }
                                        let _e2042 = phi_1585_;
                                        local_149 = _e2042;
                                        if (bitcast<i32>(_e2042.member) != 0i) {
                                            let _e2046 = local_149;
                                            local_150 = _e2046.member_1.member;
                                            let _e2049 = local_149;
                                            let _e2052 = local_52;
                                            if (_e2049.member_1.member_1 > _e2052) {
                                                let _e2054 = local_53;
                                                let _e2055 = local_51;
                                                if (_e2054 != _e2055) {
                                                    phi_1606_ = true;
                                                } else {
                                                    let _e2057 = local_129;
                                                    let _e2058 = local_50;
                                                    phi_1606_ = (_e2057 > _e2058);
                                                }
                                                let _e2061 = phi_1606_;
                                                if _e2061 {
                                                    let _e2062 = local_150;
                                                    phi_1611_ = type_18(1u, _e2062);
                                                } else {
                                                    phi_1611_ = _e1851;
                                                }
                                                let _e2065 = phi_1611_;
                                                phi_1612_ = _e2065;
                                            } else {
                                                phi_1612_ = _e1851;
                                            }
                                            let _e2067 = phi_1612_;
                                            phi_1613_ = _e2067;
                                        } else {
                                            phi_1613_ = _e1851;
                                        }
                                        let _e2069 = phi_1613_;
                                        let _e2070 = local_129;
                                        phi_1336_ = _e2069;
                                        phi_1339_ = (_e2070 + 1u);
                                    } else {
                                        phi_1336_ = type_18();
                                        phi_1339_ = u32();
                                    }
                                    let _e2073 = phi_1336_;
                                    let _e2075 = phi_1339_;
                                    continue;
                                    continuing {
                                        let _e2076 = local_130;
                                        phi_1335_ = _e2073;
                                        phi_1338_ = _e2075;
                                        phi_2115_ = _e1653;
                                        break if !(_e2076);
                                    }
                                }
                                let _e2079 = phi_2115_;
                                phi_2166_ = _e2079;
                                if _e2079 {
                                    break;
                                }
                                let _e2080 = local_128;
                                if (bitcast<i32>(_e2080.member) != 0i) {
                                    let _e2084 = local_49;
                                    local_151 = _e2084.member_1;
                                    let _e2086 = (_e2084.member_1 >= 1f);
                                    local_152 = _e2086;
                                    if _e2086 {
                                        let _e2087 = local_49;
                                        if (_e2087.member[0] == 0f) {
                                            let _e2091 = local_49;
                                            let _e2094 = (_e2091.member[1] == 0f);
                                            local_153 = _e2094;
                                            if _e2094 {
                                                let _e2095 = local_49;
                                                phi_1638_ = (_e2095.member[2] == 0f);
                                            } else {
                                                phi_1638_ = bool();
                                            }
                                            let _e2100 = phi_1638_;
                                            let _e2101 = local_153;
                                            phi_1640_ = _e2100;
                                            phi_1641_ = select(true, false, _e2101);
                                        } else {
                                            phi_1640_ = bool();
                                            phi_1641_ = true;
                                        }
                                        let _e2104 = phi_1640_;
                                        let _e2106 = phi_1641_;
                                        phi_1642_ = _e2104;
                                        phi_1643_ = _e2106;
                                    } else {
                                        phi_1642_ = bool();
                                        phi_1643_ = true;
                                    }
                                    let _e2108 = phi_1642_;
                                    let _e2110 = phi_1643_;
                                    if select(_e2108, false, _e2110) {
                                        let _e2112 = local_128;
                                        phi_1713_ = type_25(_e2112.member_1, false);
                                    } else {
                                        let _e2115 = local_128;
                                        local_154 = _e2115.member_1;
                                        let _e2117 = local_152;
                                        if _e2117 {
                                            let _e2118 = local_49;
                                            if (_e2118.member[0] == 0f) {
                                                let _e2122 = local_49;
                                                let _e2125 = (_e2122.member[1] == 0f);
                                                local_155 = _e2125;
                                                if _e2125 {
                                                    let _e2126 = local_49;
                                                    phi_1672_ = (_e2126.member[2] == 0f);
                                                } else {
                                                    phi_1672_ = bool();
                                                }
                                                let _e2131 = phi_1672_;
                                                let _e2132 = local_155;
                                                phi_1674_ = _e2131;
                                                phi_1675_ = select(true, false, _e2132);
                                            } else {
                                                phi_1674_ = bool();
                                                phi_1675_ = true;
                                            }
                                            let _e2135 = phi_1674_;
                                            let _e2137 = phi_1675_;
                                            phi_1676_ = _e2135;
                                            phi_1677_ = _e2137;
                                        } else {
                                            phi_1676_ = bool();
                                            phi_1677_ = true;
                                        }
                                        let _e2139 = phi_1676_;
                                        let _e2141 = phi_1677_;
                                        if select(_e2139, false, _e2141) {
                                            let _e2143 = local_154;
                                            phi_1710_ = type_14(_e2143, 0f);
                                        } else {
                                            let _e2145 = local_151;
                                            if (_e2145 > 0f) {
                                                let _e2147 = local_49;
                                                let _e2150 = local_154;
                                                let _e2152 = local_151;
                                                let _e2155 = local_49;
                                                let _e2158 = local_154;
                                                let _e2160 = local_151;
                                                let _e2163 = local_49;
                                                let _e2166 = local_154;
                                                let _e2168 = local_151;
                                                phi_1709_ = type_14(array<f32, 3>((_e2147.member[0] + (_e2152 * _e2150[0])), (_e2155.member[1] + (_e2160 * _e2158[1])), (_e2163.member[2] + (_e2168 * _e2166[2]))), 0f);
                                            } else {
                                                let _e2656 = local_227;
                                                phi_1709_ = _e2656;
                                            }
                                            let _e2174 = phi_1709_;
                                            phi_1710_ = _e2174;
                                        }
                                        let _e2176 = phi_1710_;
                                        phi_1713_ = type_25(_e2176.member, false);
                                    }
                                    let _e2180 = phi_1713_;
                                    phi_1718_ = _e2180;
                                } else {
                                    let _e2181 = local_49;
                                    let _e2183 = local_49;
                                    phi_1718_ = type_25(_e2181.member, (_e2183.member_1 < 1f));
                                }
                                let _e2188 = phi_1718_;
                                phi_2170_ = _e2079;
                                phi_1719_ = _e2188;
                            } else {
                                phi_2170_ = _e1653;
                                phi_1719_ = _e1787;
                            }
                            let _e2190 = phi_2170_;
                            let _e2192 = phi_1719_;
                            local_156 = _e2192;
                            let _e2193 = local_18;
                            if (_e2193 == 0u) {
                                let _e2195 = local_156;
                                phi_1725_ = _e2195.member;
                            } else {
                                phi_1725_ = _e356;
                            }
                            let _e2198 = phi_1725_;
                            let _e2199 = local_156;
                            let _e2204 = local_20;
                            let _e2207 = local_156;
                            let _e2212 = local_20;
                            let _e2215 = local_156;
                            let _e2220 = local_20;
                            let _e2224 = local_156;
                            if _e2224.member_1 {
                                phi_1749_ = _e360;
                            } else {
                                let _e2226 = local_19;
                                phi_1749_ = (_e2226 + 1u);
                            }
                            let _e2229 = phi_1749_;
                            let _e2230 = local_18;
                            phi_2167_ = _e2190;
                            phi_203_ = _e2198;
                            phi_206_ = (_e2230 + 1u);
                            phi_208_ = _e2229;
                            phi_210_ = array<f32, 3>((_e2204[0] + (_e2199.member[0] - _e2198[0])), (_e2212[1] + (_e2207.member[1] - _e2198[1])), (_e2220[2] + (_e2215.member[2] - _e2198[2])));
                        } else {
                            phi_2167_ = _e354;
                            phi_203_ = array<f32, 3>();
                            phi_206_ = u32();
                            phi_208_ = u32();
                            phi_210_ = array<f32, 3>();
                        }
                        let _e2233 = phi_2167_;
                        let _e2235 = phi_203_;
                        let _e2237 = phi_206_;
                        let _e2239 = phi_208_;
                        let _e2241 = phi_210_;
                        continue;
                        continuing {
                            let _e2242 = local_22;
                            phi_2085_ = _e2233;
                            phi_202_ = _e2235;
                            phi_205_ = _e2237;
                            phi_207_ = _e2239;
                            phi_209_ = _e2241;
                            phi_2166_ = _e2233;
                            break if !(_e2242);
                        }
                    }
                    let _e2245 = phi_2166_;
                    if _e2245 {
                        break;
                    }
                    let _e2246 = local_21;
                    let _e2248 = local_21;
                    let _e2251 = (1f / f32(select(1u, _e2248, (1u < _e2246))));
                    local_157 = _e2251;
                    let _e2252 = local_10;
                    let _e2253 = (3u * _e2252);
                    local_158 = _e2253;
                    let _e2254 = local_17;
                    let _e2256 = local_20;
                    local_159 = bitcast<u32>((_e2254[0] + (_e2256[0] * _e2251)));
                    let _e2261 = local_4;
                    if (_e2253 < _e2261) {
                    } else {
                        break;
                    }
                    let _e2263 = local_158;
                    let _e2266 = local_159;
                    global_2.member[_e2263] = _e2266;
                    let _e2267 = local_158;
                    let _e2268 = (_e2267 + 1u);
                    local_160 = _e2268;
                    let _e2269 = local_17;
                    let _e2271 = local_20;
                    let _e2273 = local_157;
                    local_161 = bitcast<u32>((_e2269[1] + (_e2271[1] * _e2273)));
                    let _e2277 = local_4;
                    if (_e2268 < _e2277) {
                    } else {
                        break;
                    }
                    let _e2279 = local_160;
                    let _e2282 = local_161;
                    global_2.member[_e2279] = _e2282;
                    let _e2283 = local_158;
                    let _e2284 = (_e2283 + 2u);
                    local_162 = _e2284;
                    let _e2285 = local_17;
                    let _e2287 = local_20;
                    let _e2289 = local_157;
                    local_163 = bitcast<u32>((_e2285[2] + (_e2287[2] * _e2289)));
                    let _e2293 = local_4;
                    if (_e2284 < _e2293) {
                    } else {
                        break;
                    }
                    let _e2295 = local_162;
                    let _e2298 = local_163;
                    global_2.member[_e2295] = _e2298;
                    let _e2299 = local_19;
                    if (_e2299 > 0u) {
                        let _e2301 = local_5;
                        if (0u < _e2301) {
                        } else {
                            break;
                        }
                        let _e2305 = local_19;
                        let _e2306 = atomicAdd((&global_8.member[0u]), _e2305);
                    }
                }
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn raytrace_trace(@builtin(local_invocation_index) param: u32, @builtin(workgroup_id) param_1: vec3<u32>) {
    global = param;
    global_1 = param_1;
    function_();
}
