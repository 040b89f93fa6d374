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

struct type_16 {
    member: array<f32, 3>,
    member_1: f32,
    member_2: f32,
}

struct type_17 {
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
    member_1: type_16,
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
    var local_128: type_17;
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
    var phi_1335_: type_17;
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
    var phi_1611_: type_17;
    var phi_1612_: type_17;
    var phi_1613_: type_17;
    var phi_1336_: type_17;
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
                                let _e415 = (_e409 != _e409);
                                local_178 = _e415;
                                if _e415 {
                                    phi_1855_ = true;
                                } else {
                                    let _e416 = local_33;
                                    let _e417 = local_32;
                                    phi_1855_ = (_e416 <= _e417);
                                }
                                let _e420 = phi_1855_;
                                let _e421 = local_33;
                                let _e422 = local_32;
                                local_181 = select(_e422, _e421, _e420);
                                let _e424 = local_178;
                                if _e424 {
                                    phi_1870_ = true;
                                } else {
                                    let _e425 = local_33;
                                    let _e426 = local_32;
                                    phi_1870_ = (_e425 >= _e426);
                                }
                                let _e429 = phi_1870_;
                                let _e430 = local_33;
                                let _e431 = local_32;
                                let _e433 = local_181;
                                phi_270_ = type_19(_e433, select(_e431, _e430, _e429));
                            }
                            let _e436 = phi_270_;
                            local_34 = _e436.member;
                            local_35 = _e436.member_1;
                            let _e439 = local_26;
                            if (_e439 == 0f) {
                                phi_285_ = _e289;
                            } else {
                                let _e441 = local_15;
                                let _e443 = local_26;
                                let _e444 = ((-0.5f - _e441) / _e443);
                                local_36 = _e444;
                                let _e445 = local_31;
                                let _e446 = local_16;
                                let _e448 = local_26;
                                local_37 = ((_e445 - _e446) / _e448);
                                let _e450 = (_e444 != _e444);
                                local_179 = _e450;
                                if _e450 {
                                    phi_1885_ = true;
                                } else {
                                    let _e451 = local_37;
                                    let _e452 = local_36;
                                    phi_1885_ = (_e451 <= _e452);
                                }
                                let _e455 = phi_1885_;
                                let _e456 = local_37;
                                let _e457 = local_36;
                                local_182 = select(_e457, _e456, _e455);
                                let _e459 = local_179;
                                if _e459 {
                                    phi_1900_ = true;
                                } else {
                                    let _e460 = local_37;
                                    let _e461 = local_36;
                                    phi_1900_ = (_e460 >= _e461);
                                }
                                let _e464 = phi_1900_;
                                let _e465 = local_37;
                                let _e466 = local_36;
                                let _e468 = local_182;
                                phi_285_ = type_19(_e468, select(_e466, _e465, _e464));
                            }
                            let _e471 = phi_285_;
                            local_38 = _e471.member;
                            local_39 = _e471.member_1;
                            let _e474 = local_29;
                            let _e475 = (2u * _e474);
                            local_40 = _e475;
                            let _e476 = local_2;
                            if (_e475 < _e476) {
                            } else {
                                phi_2166_ = true;
                                break;
                            }
                            let _e478 = local_40;
                            let _e481 = global_6.member[_e478];
                            let _e482 = bitcast<f32>(_e481);
                            local_41 = _e482;
                            if (_e482 != _e482) {
                                phi_1915_ = true;
                            } else {
                                let _e484 = local_34;
                                let _e485 = local_41;
                                phi_1915_ = (_e484 >= _e485);
                            }
                            let _e488 = phi_1915_;
                            let _e489 = local_34;
                            let _e490 = local_41;
                            let _e491 = select(_e490, _e489, _e488);
                            local_183 = _e491;
                            if (_e491 != _e491) {
                                phi_1930_ = true;
                            } else {
                                let _e493 = local_38;
                                let _e494 = local_183;
                                phi_1930_ = (_e493 >= _e494);
                            }
                            let _e497 = phi_1930_;
                            let _e498 = local_38;
                            let _e499 = local_183;
                            let _e504 = global_5.member.member_8.member_1;
                            let _e509 = global_5.member.member_8.member;
                            let _e514 = global_5.member.member_8.member_2;
                            local_42 = _e514;
                            let _e520 = global_5.member.member_8.member_3;
                            let _e521 = ((((2f * _e504) * _e509) / (_e514 - _e509)) * _e520);
                            local_43 = _e521;
                            let _e522 = (0.5f * _e521);
                            local_44 = _e522;
                            if (_e522 != _e522) {
                                phi_1945_ = true;
                            } else {
                                let _e524 = local_35;
                                let _e525 = local_44;
                                phi_1945_ = (_e524 <= _e525);
                            }
                            let _e528 = phi_1945_;
                            let _e529 = local_35;
                            let _e530 = local_44;
                            let _e531 = select(_e530, _e529, _e528);
                            local_184 = _e531;
                            if (_e531 != _e531) {
                                phi_1960_ = true;
                            } else {
                                let _e533 = local_39;
                                let _e534 = local_184;
                                phi_1960_ = (_e533 <= _e534);
                            }
                            let _e537 = phi_1960_;
                            let _e538 = local_39;
                            let _e539 = local_184;
                            local_185 = select(_e539, _e538, _e537);
                            let _e541 = local_24;
                            let _e542 = abs(_e541);
                            local_45 = _e542;
                            let _e543 = local_26;
                            local_46 = abs(_e543);
                            if (_e542 != _e542) {
                                phi_1975_ = true;
                            } else {
                                let _e546 = local_46;
                                let _e547 = local_45;
                                phi_1975_ = (_e546 >= _e547);
                            }
                            let _e550 = phi_1975_;
                            let _e551 = local_46;
                            let _e552 = local_45;
                            let _e553 = select(_e552, _e551, _e550);
                            local_186 = _e553;
                            if (_e553 > 0f) {
                                let _e555 = local_186;
                                phi_326_ = (0.01f / _e555);
                            } else {
                                phi_326_ = _e288;
                            }
                            let _e558 = phi_326_;
                            local_47 = _e558;
                            let _e559 = local_8;
                            let _e560 = local_9;
                            let _e563 = local_27;
                            local_48 = ((4u * (_e559 + _e560)) + (8u * _e563));
                            let _e566 = local_16;
                            let _e568 = local_16;
                            let _e570 = local_16;
                            let _e574 = local_8;
                            let _e576 = local_14;
                            let _e578 = local_14;
                            let _e580 = local_14;
                            phi_2071_ = _e354;
                            phi_356_ = type_14(array<f32, 3>(0f, 0f, 0f), 1f);
                            phi_359_ = 0u;
                            phi_361_ = 4294967295u;
                            phi_363_ = _e286;
                            phi_365_ = ((select(select(u32(_e566), 0u, (_e568 < 0f)), 4294967295u, (_e570 > 4294967000f)) * _e574) + select(select(u32(_e576), 0u, (_e578 < 0f)), 4294967295u, (_e580 > 4294967000f)));
                            phi_367_ = 0u;
                            phi_369_ = 0u;
                            phi_371_ = select(_e499, _e498, _e497);
                            loop {
                                let _e586 = phi_2071_;
                                let _e588 = phi_356_;
                                let _e590 = phi_359_;
                                let _e592 = phi_361_;
                                let _e594 = phi_363_;
                                let _e596 = phi_365_;
                                let _e598 = phi_367_;
                                let _e600 = phi_369_;
                                let _e602 = phi_371_;
                                local_49 = _e588;
                                local_50 = _e590;
                                local_51 = _e592;
                                local_52 = _e594;
                                local_53 = _e596;
                                local_54 = _e598;
                                local_55 = _e600;
                                local_56 = _e602;
                                local_227 = _e588;
                                let _e603 = local_56;
                                let _e604 = local_185;
                                let _e605 = (_e603 <= _e604);
                                local_57 = _e605;
                                if _e605 {
                                    let _e606 = local_54;
                                    let _e607 = local_48;
                                    let _e608 = (_e606 < _e607);
                                    local_58 = _e608;
                                    if _e608 {
                                        let _e609 = local_54;
                                        let _e611 = local_24;
                                        let _e612 = local_56;
                                        let _e614 = local_14;
                                        let _e615 = (_e614 + (_e611 * _e612));
                                        local_59 = _e615;
                                        let _e616 = local_26;
                                        let _e617 = local_56;
                                        let _e619 = local_16;
                                        local_60 = (_e619 + (_e616 * _e617));
                                        let _e621 = (_e615 >= 0f);
                                        local_61 = _e621;
                                        if _e621 {
                                            let _e622 = local_60;
                                            let _e623 = (_e622 >= 0f);
                                            local_62 = _e623;
                                            if _e623 {
                                                let _e624 = local_59;
                                                let _e625 = local_30;
                                                let _e626 = (_e624 < _e625);
                                                local_63 = _e626;
                                                if _e626 {
                                                    let _e627 = local_60;
                                                    let _e628 = local_31;
                                                    let _e629 = (_e627 < _e628);
                                                    local_64 = _e629;
                                                    if _e629 {
                                                        let _e630 = local_59;
                                                        let _e631 = floor(_e630);
                                                        let _e636 = select(select(u32(_e631), 0u, (_e631 < 0f)), 4294967295u, (_e631 > 4294967000f));
                                                        let _e637 = local_60;
                                                        let _e638 = floor(_e637);
                                                        let _e643 = select(select(u32(_e638), 0u, (_e638 < 0f)), 4294967295u, (_e638 > 4294967000f));
                                                        let _e644 = local_8;
                                                        let _e646 = ((_e643 * _e644) + _e636);
                                                        local_65 = _e646;
                                                        let _e647 = local_55;
                                                        let _e648 = (_e647 & 31u);
                                                        local_66 = (_e636 >> bitcast<u32>(_e648));
                                                        local_67 = (_e643 >> bitcast<u32>(_e648));
                                                        local_68 = (1u << bitcast<u32>(_e648));
                                                        let _e655 = local_24;
                                                        if (_e655 > 0f) {
                                                            let _e657 = local_66;
                                                            let _e660 = local_68;
                                                            let _e663 = local_14;
                                                            let _e665 = local_24;
                                                            phi_450_ = (((f32((_e657 + 1u)) * f32(_e660)) - _e663) / _e665);
                                                        } else {
                                                            let _e667 = local_24;
                                                            if (_e667 < 0f) {
                                                                let _e669 = local_66;
                                                                let _e671 = local_68;
                                                                let _e674 = local_14;
                                                                let _e676 = local_24;
                                                                phi_449_ = (((f32(_e669) * f32(_e671)) - _e674) / _e676);
                                                            } else {
                                                                phi_449_ = _e288;
                                                            }
                                                            let _e679 = phi_449_;
                                                            phi_450_ = _e679;
                                                        }
                                                        let _e681 = phi_450_;
                                                        local_69 = _e681;
                                                        let _e682 = local_26;
                                                        if (_e682 > 0f) {
                                                            let _e684 = local_67;
                                                            let _e687 = local_68;
                                                            let _e690 = local_16;
                                                            let _e692 = local_26;
                                                            phi_471_ = (((f32((_e684 + 1u)) * f32(_e687)) - _e690) / _e692);
                                                        } else {
                                                            let _e694 = local_26;
                                                            if (_e694 < 0f) {
                                                                let _e696 = local_67;
                                                                let _e698 = local_68;
                                                                let _e701 = local_16;
                                                                let _e703 = local_26;
                                                                phi_470_ = (((f32(_e696) * f32(_e698)) - _e701) / _e703);
                                                            } else {
                                                                phi_470_ = _e288;
                                                            }
                                                            let _e706 = phi_470_;
                                                            phi_471_ = _e706;
                                                        }
                                                        let _e708 = phi_471_;
                                                        local_70 = _e708;
                                                        let _e709 = local_69;
                                                        let _e710 = local_69;
                                                        if (_e709 != _e710) {
                                                            phi_1990_ = true;
                                                        } else {
                                                            let _e712 = local_70;
                                                            let _e713 = local_69;
                                                            phi_1990_ = (_e712 <= _e713);
                                                        }
                                                        let _e716 = phi_1990_;
                                                        let _e717 = local_70;
                                                        let _e718 = local_69;
                                                        let _e719 = select(_e718, _e717, _e716);
                                                        local_187 = _e719;
                                                        if (_e719 != _e719) {
                                                            phi_2005_ = true;
                                                        } else {
                                                            let _e721 = local_185;
                                                            let _e722 = local_187;
                                                            phi_2005_ = (_e721 <= _e722);
                                                        }
                                                        let _e725 = phi_2005_;
                                                        let _e726 = local_185;
                                                        let _e727 = local_187;
                                                        local_188 = select(_e727, _e726, _e725);
                                                        let _e729 = local_68;
                                                        let _e730 = (_e729 == 0u);
                                                        local_71 = _e730;
                                                        if _e730 {
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
                                                        let _e731 = local_8;
                                                        let _e732 = local_68;
                                                        let _e733 = (_e731 / _e732);
                                                        local_72 = _e733;
                                                        let _e734 = local_71;
                                                        if _e734 {
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
                                                        let _e735 = local_8;
                                                        let _e736 = local_68;
                                                        if ((_e735 % _e736) > 0u) {
                                                            let _e739 = local_72;
                                                            phi_493_ = (_e739 + 1u);
                                                        } else {
                                                            phi_493_ = _e733;
                                                        }
                                                        let _e742 = phi_493_;
                                                        local_73 = _e742;
                                                        let _e743 = local_71;
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
                                                        let _e744 = local_71;
                                                        if _e744 {
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
                                                        let _e745 = local_55;
                                                        if (_e745 < 14u) {
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
                                                        let _e747 = local_55;
                                                        let _e751 = global_5.member.member_9[_e747];
                                                        let _e752 = local_67;
                                                        let _e753 = local_73;
                                                        let _e756 = local_66;
                                                        let _e758 = (2u * ((_e751 + (_e752 * _e753)) + _e756));
                                                        local_74 = _e758;
                                                        let _e759 = local_2;
                                                        if (_e758 < _e759) {
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
                                                        let _e761 = local_74;
                                                        let _e764 = global_6.member[_e761];
                                                        local_75 = bitcast<f32>(_e764);
                                                        let _e766 = local_74;
                                                        let _e767 = (_e766 + 1u);
                                                        local_76 = _e767;
                                                        let _e768 = local_2;
                                                        if (_e767 < _e768) {
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
                                                        let _e770 = local_76;
                                                        let _e773 = global_6.member[_e770];
                                                        let _e775 = local_56;
                                                        let _e777 = local_188;
                                                        let _e781 = (0.00001f * ((abs(_e775) + abs(_e777)) + 1f));
                                                        local_77 = _e781;
                                                        let _e782 = local_56;
                                                        let _e783 = (_e782 - _e781);
                                                        local_78 = _e783;
                                                        if (bitcast<f32>(_e773) < _e783) {
                                                            phi_2109_ = _e586;
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
                                                            let _e785 = local_188;
                                                            let _e786 = local_77;
                                                            let _e787 = (_e785 + _e786);
                                                            local_79 = _e787;
                                                            let _e788 = local_75;
                                                            let _e789 = (_e788 > _e787);
                                                            if _e789 {
                                                                phi_2110_ = _e586;
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
                                                                let _e790 = local_55;
                                                                if (_e790 > 0u) {
                                                                    let _e792 = local_55;
                                                                    phi_2112_ = _e586;
                                                                    phi_1041_ = _e588;
                                                                    phi_1042_ = _e590;
                                                                    phi_1043_ = _e592;
                                                                    phi_1044_ = _e594;
                                                                    phi_1045_ = (_e792 - 1u);
                                                                    phi_1046_ = _e602;
                                                                    phi_1047_ = type_14();
                                                                    phi_1048_ = array<f32, 3>();
                                                                    phi_1049_ = true;
                                                                    phi_1050_ = false;
                                                                    phi_1051_ = false;
                                                                    phi_1052_ = false;
                                                                } else {
                                                                    let _e794 = local_65;
                                                                    let _e795 = local_1;
                                                                    if (_e794 < _e795) {
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
                                                                    let _e797 = local_65;
                                                                    let _e800 = global_3.member[_e797];
                                                                    let _e803 = global_5.member.member_2;
                                                                    local_80 = _e803;
                                                                    let _e805 = select(_e800, _e803, (_e803 < _e800));
                                                                    local_189 = _e805;
                                                                    let _e806 = (_e805 == 0u);
                                                                    if _e806 {
                                                                        phi_2113_ = _e586;
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
                                                                        phi_578_ = _e588;
                                                                        phi_581_ = _e590;
                                                                        phi_583_ = _e592;
                                                                        phi_585_ = 0u;
                                                                        phi_587_ = _e594;
                                                                        loop {
                                                                            let _e808 = phi_578_;
                                                                            let _e810 = phi_581_;
                                                                            let _e812 = phi_583_;
                                                                            let _e814 = phi_585_;
                                                                            let _e816 = phi_587_;
                                                                            local_81 = _e808;
                                                                            local_82 = _e810;
                                                                            local_83 = _e812;
                                                                            local_84 = _e814;
                                                                            local_85 = _e816;
                                                                            local_223 = _e808;
                                                                            local_224 = _e810;
                                                                            local_225 = _e812;
                                                                            local_226 = _e816;
                                                                            let _e817 = local_84;
                                                                            let _e818 = local_189;
                                                                            let _e819 = (_e817 < _e818);
                                                                            local_86 = _e819;
                                                                            if _e819 {
                                                                                let _e820 = local_65;
                                                                                let _e821 = local_80;
                                                                                let _e823 = local_84;
                                                                                let _e825 = (5u * ((_e820 * _e821) + _e823));
                                                                                local_87 = _e825;
                                                                                let _e826 = local;
                                                                                if (_e825 < _e826) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e828 = local_87;
                                                                                let _e831 = global_4.member[_e828];
                                                                                local_88 = bitcast<f32>(_e831);
                                                                                let _e833 = local_87;
                                                                                let _e834 = (_e833 + 1u);
                                                                                local_89 = _e834;
                                                                                let _e835 = local;
                                                                                if (_e834 < _e835) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e837 = local_89;
                                                                                let _e840 = global_4.member[_e837];
                                                                                local_90 = bitcast<f32>(_e840);
                                                                                let _e842 = local_87;
                                                                                let _e843 = (_e842 + 2u);
                                                                                local_91 = _e843;
                                                                                let _e844 = local;
                                                                                if (_e843 < _e844) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e846 = local_91;
                                                                                let _e849 = global_4.member[_e846];
                                                                                local_92 = bitcast<f32>(_e849);
                                                                                let _e851 = local_87;
                                                                                let _e852 = (_e851 + 3u);
                                                                                local_93 = _e852;
                                                                                let _e853 = local;
                                                                                if (_e852 < _e853) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e855 = local_93;
                                                                                let _e858 = global_4.member[_e855];
                                                                                local_94 = bitcast<f32>(_e858);
                                                                                let _e860 = local_87;
                                                                                let _e861 = (_e860 + 4u);
                                                                                local_95 = _e861;
                                                                                let _e862 = local;
                                                                                if (_e861 < _e862) {
                                                                                } else {
                                                                                    phi_2010_ = true;
                                                                                    phi_1832_ = bool();
                                                                                    phi_1831_ = bool();
                                                                                    phi_1830_ = bool();
                                                                                    phi_1828_ = array<f32, 3>();
                                                                                    phi_1826_ = type_14();
                                                                                    break;
                                                                                }
                                                                                let _e864 = local_95;
                                                                                let _e867 = global_4.member[_e864];
                                                                                local_96 = bitcast<f32>(_e867);
                                                                                let _e869 = local_88;
                                                                                if ((bitcast<u32>(_e869) & 2139095040u) != 2139095040u) {
                                                                                    let _e873 = local_90;
                                                                                    if ((bitcast<u32>(_e873) & 2139095040u) != 2139095040u) {
                                                                                        let _e877 = local_92;
                                                                                        let _e880 = ((bitcast<u32>(_e877) & 2139095040u) != 2139095040u);
                                                                                        local_97 = _e880;
                                                                                        if _e880 {
                                                                                            let _e881 = local_94;
                                                                                            let _e882 = bitcast<u32>(_e881);
                                                                                            local_98 = _e882;
                                                                                            if (_e882 == 0u) {
                                                                                                phi_668_ = false;
                                                                                            } else {
                                                                                                let _e884 = local_98;
                                                                                                phi_668_ = (_e884 <= 2139095040u);
                                                                                            }
                                                                                            let _e887 = phi_668_;
                                                                                            phi_669_ = _e887;
                                                                                        } else {
                                                                                            phi_669_ = bool();
                                                                                        }
                                                                                        let _e889 = phi_669_;
                                                                                        let _e890 = local_97;
                                                                                        phi_671_ = _e889;
                                                                                        phi_672_ = select(true, false, _e890);
                                                                                    } else {
                                                                                        phi_671_ = bool();
                                                                                        phi_672_ = true;
                                                                                    }
                                                                                    let _e893 = phi_671_;
                                                                                    let _e895 = phi_672_;
                                                                                    phi_673_ = _e893;
                                                                                    phi_674_ = _e895;
                                                                                } else {
                                                                                    phi_673_ = bool();
                                                                                    phi_674_ = true;
                                                                                }
                                                                                let _e897 = phi_673_;
                                                                                let _e899 = phi_674_;
                                                                                if select(_e897, false, _e899) {
                                                                                    let _e901 = local_94;
                                                                                    let _e902 = bitcast<u32>(_e901);
                                                                                    local_99 = _e902;
                                                                                    if (_e902 == 0u) {
                                                                                        phi_689_ = false;
                                                                                    } else {
                                                                                        let _e904 = local_99;
                                                                                        phi_689_ = (_e904 <= 2139095040u);
                                                                                    }
                                                                                    let _e907 = phi_689_;
                                                                                    if _e907 {
                                                                                        let _e908 = local_43;
                                                                                        if (_e908 == 0f) {
                                                                                            phi_717_ = 0f;
                                                                                        } else {
                                                                                            let _e910 = local_42;
                                                                                            let _e911 = local_94;
                                                                                            let _e914 = local_43;
                                                                                            phi_717_ = (_e914 * (1f - (_e910 / _e911)));
                                                                                        }
                                                                                        let _e917 = phi_717_;
                                                                                        phi_718_ = _e917;
                                                                                    } else {
                                                                                        phi_718_ = _e284;
                                                                                    }
                                                                                    let _e919 = phi_718_;
                                                                                    let _e920 = (0.5f * _e919);
                                                                                    local_100 = _e920;
                                                                                    let _e923 = ((bitcast<u32>(_e920) & 2139095040u) != 2139095040u);
                                                                                    local_101 = _e923;
                                                                                    if _e923 {
                                                                                        let _e924 = local_88;
                                                                                        if (_e924 > 1267650600000000000000000000000f) {
                                                                                            let _e926 = local_88;
                                                                                            phi_735_ = select(true, false, (_e926 <= 340282350000000000000000000000000000000f));
                                                                                        } else {
                                                                                            phi_735_ = true;
                                                                                        }
                                                                                        let _e930 = phi_735_;
                                                                                        if _e930 {
                                                                                            let _e931 = local_88;
                                                                                            if (_e931 < 0.000000000000000000000000000000000000011754944f) {
                                                                                                let _e933 = local_88;
                                                                                                phi_749_ = select(true, false, (_e933 >= -340282350000000000000000000000000000000f));
                                                                                            } else {
                                                                                                phi_749_ = true;
                                                                                            }
                                                                                            let _e937 = phi_749_;
                                                                                            let _e938 = local_88;
                                                                                            phi_754_ = select(0f, _e938, _e937);
                                                                                        } else {
                                                                                            phi_754_ = 1267650600000000000000000000000f;
                                                                                        }
                                                                                        let _e941 = phi_754_;
                                                                                        local_102 = _e941;
                                                                                        let _e942 = local_90;
                                                                                        if (_e942 > 1267650600000000000000000000000f) {
                                                                                            let _e944 = local_90;
                                                                                            phi_764_ = select(true, false, (_e944 <= 340282350000000000000000000000000000000f));
                                                                                        } else {
                                                                                            phi_764_ = true;
                                                                                        }
                                                                                        let _e948 = phi_764_;
                                                                                        if _e948 {
                                                                                            let _e949 = local_90;
                                                                                            if (_e949 < 0.000000000000000000000000000000000000011754944f) {
                                                                                                let _e951 = local_90;
                                                                                                phi_778_ = select(true, false, (_e951 >= -340282350000000000000000000000000000000f));
                                                                                            } else {
                                                                                                phi_778_ = true;
                                                                                            }
                                                                                            let _e955 = phi_778_;
                                                                                            let _e956 = local_90;
                                                                                            phi_783_ = select(0f, _e956, _e955);
                                                                                        } else {
                                                                                            phi_783_ = 1267650600000000000000000000000f;
                                                                                        }
                                                                                        let _e959 = phi_783_;
                                                                                        local_103 = _e959;
                                                                                        let _e960 = local_92;
                                                                                        if (_e960 > 1267650600000000000000000000000f) {
                                                                                            let _e962 = local_92;
                                                                                            phi_793_ = select(true, false, (_e962 <= 340282350000000000000000000000000000000f));
                                                                                        } else {
                                                                                            phi_793_ = true;
                                                                                        }
                                                                                        let _e966 = phi_793_;
                                                                                        if _e966 {
                                                                                            let _e967 = local_92;
                                                                                            if (_e967 < 0.000000000000000000000000000000000000011754944f) {
                                                                                                let _e969 = local_92;
                                                                                                phi_807_ = select(true, false, (_e969 >= -340282350000000000000000000000000000000f));
                                                                                            } else {
                                                                                                phi_807_ = true;
                                                                                            }
                                                                                            let _e973 = phi_807_;
                                                                                            let _e974 = local_92;
                                                                                            phi_812_ = select(0f, _e974, _e973);
                                                                                        } else {
                                                                                            phi_812_ = 1267650600000000000000000000000f;
                                                                                        }
                                                                                        let _e977 = phi_812_;
                                                                                        let _e978 = local_102;
                                                                                        let _e979 = local_103;
                                                                                        local_104 = array<f32, 3>(_e978, _e979, _e977);
                                                                                        let _e981 = local_96;
                                                                                        if (_e981 > 1f) {
                                                                                            phi_823_ = 1f;
                                                                                        } else {
                                                                                            let _e983 = local_96;
                                                                                            let _e985 = local_96;
                                                                                            phi_823_ = select(0f, _e985, (_e983 >= 0f));
                                                                                        }
                                                                                        let _e988 = phi_823_;
                                                                                        let _e989 = local_104;
                                                                                        let _e990 = local_100;
                                                                                        phi_826_ = type_24(1u, type_16(_e989, _e990, _e988));
                                                                                    } else {
                                                                                        phi_826_ = type_24();
                                                                                    }
                                                                                    let _e994 = phi_826_;
                                                                                    let _e995 = local_101;
                                                                                    phi_828_ = _e994;
                                                                                    phi_829_ = select(true, false, _e995);
                                                                                } else {
                                                                                    phi_828_ = type_24();
                                                                                    phi_829_ = true;
                                                                                }
                                                                                let _e998 = phi_828_;
                                                                                let _e1000 = phi_829_;
                                                                                if _e1000 {
                                                                                    phi_834_ = type_24(0u, type_24().member_1);
                                                                                } else {
                                                                                    phi_834_ = _e998;
                                                                                }
                                                                                let _e1005 = phi_834_;
                                                                                local_105 = _e1005;
                                                                                if (bitcast<i32>(_e1005.member) != 0i) {
                                                                                    let _e1009 = local_105;
                                                                                    local_106 = _e1009.member_1.member;
                                                                                    let _e1012 = local_105;
                                                                                    local_107 = _e1012.member_1.member_1;
                                                                                    let _e1015 = local_105;
                                                                                    local_108 = _e1015.member_1.member_2;
                                                                                    let _e1018 = local_65;
                                                                                    let _e1019 = local_83;
                                                                                    if (_e1018 != _e1019) {
                                                                                        phi_852_ = true;
                                                                                    } else {
                                                                                        let _e1021 = local_84;
                                                                                        let _e1022 = local_82;
                                                                                        phi_852_ = (_e1021 > _e1022);
                                                                                    }
                                                                                    let _e1025 = phi_852_;
                                                                                    if _e1025 {
                                                                                        let _e1026 = local_107;
                                                                                        let _e1027 = local_78;
                                                                                        if (_e1026 >= _e1027) {
                                                                                            let _e1029 = local_107;
                                                                                            let _e1030 = local_79;
                                                                                            let _e1031 = (_e1029 <= _e1030);
                                                                                            local_109 = _e1031;
                                                                                            if _e1031 {
                                                                                                let _e1032 = local_108;
                                                                                                if (_e1032 >= 1f) {
                                                                                                    let _e1034 = local_81;
                                                                                                    if (_e1034.member_1 >= 1f) {
                                                                                                        let _e1037 = local_81;
                                                                                                        if (_e1037.member[0] == 0f) {
                                                                                                            let _e1041 = local_81;
                                                                                                            let _e1044 = (_e1041.member[1] == 0f);
                                                                                                            local_110 = _e1044;
                                                                                                            if _e1044 {
                                                                                                                let _e1045 = local_81;
                                                                                                                phi_887_ = (_e1045.member[2] == 0f);
                                                                                                            } else {
                                                                                                                phi_887_ = bool();
                                                                                                            }
                                                                                                            let _e1050 = phi_887_;
                                                                                                            let _e1051 = local_110;
                                                                                                            phi_889_ = _e1050;
                                                                                                            phi_890_ = select(true, false, _e1051);
                                                                                                        } else {
                                                                                                            phi_889_ = bool();
                                                                                                            phi_890_ = true;
                                                                                                        }
                                                                                                        let _e1054 = phi_889_;
                                                                                                        let _e1056 = phi_890_;
                                                                                                        phi_891_ = _e1054;
                                                                                                        phi_892_ = _e1056;
                                                                                                    } else {
                                                                                                        phi_891_ = bool();
                                                                                                        phi_892_ = true;
                                                                                                    }
                                                                                                    let _e1058 = phi_891_;
                                                                                                    let _e1060 = phi_892_;
                                                                                                    phi_901_ = select(true, false, select(_e1058, false, _e1060));
                                                                                                } else {
                                                                                                    phi_901_ = true;
                                                                                                }
                                                                                                let _e1064 = phi_901_;
                                                                                                local_111 = _e1064;
                                                                                                if _e1064 {
                                                                                                    let _e1065 = local_81;
                                                                                                    local_112 = _e1065.member_1;
                                                                                                    if (_e1065.member_1 >= 1f) {
                                                                                                        let _e1068 = local_81;
                                                                                                        if (_e1068.member[0] == 0f) {
                                                                                                            let _e1072 = local_81;
                                                                                                            let _e1075 = (_e1072.member[1] == 0f);
                                                                                                            local_113 = _e1075;
                                                                                                            if _e1075 {
                                                                                                                let _e1076 = local_81;
                                                                                                                phi_923_ = (_e1076.member[2] == 0f);
                                                                                                            } else {
                                                                                                                phi_923_ = bool();
                                                                                                            }
                                                                                                            let _e1081 = phi_923_;
                                                                                                            let _e1082 = local_113;
                                                                                                            phi_925_ = _e1081;
                                                                                                            phi_926_ = select(true, false, _e1082);
                                                                                                        } else {
                                                                                                            phi_925_ = bool();
                                                                                                            phi_926_ = true;
                                                                                                        }
                                                                                                        let _e1085 = phi_925_;
                                                                                                        let _e1087 = phi_926_;
                                                                                                        phi_927_ = _e1085;
                                                                                                        phi_928_ = _e1087;
                                                                                                    } else {
                                                                                                        phi_927_ = bool();
                                                                                                        phi_928_ = true;
                                                                                                    }
                                                                                                    let _e1089 = phi_927_;
                                                                                                    let _e1091 = phi_928_;
                                                                                                    if select(_e1089, false, _e1091) {
                                                                                                        let _e1093 = local_108;
                                                                                                        let _e1095 = local_106;
                                                                                                        phi_961_ = type_14(_e1095, (1f - _e1093));
                                                                                                    } else {
                                                                                                        let _e1097 = local_112;
                                                                                                        if (_e1097 > 0f) {
                                                                                                            let _e1099 = local_81;
                                                                                                            let _e1102 = local_106;
                                                                                                            let _e1104 = local_112;
                                                                                                            let _e1107 = local_81;
                                                                                                            let _e1110 = local_106;
                                                                                                            let _e1112 = local_112;
                                                                                                            let _e1115 = local_81;
                                                                                                            let _e1118 = local_106;
                                                                                                            let _e1120 = local_112;
                                                                                                            let _e1124 = local_108;
                                                                                                            let _e1126 = local_112;
                                                                                                            phi_960_ = type_14(array<f32, 3>((_e1099.member[0] + (_e1104 * _e1102[0])), (_e1107.member[1] + (_e1112 * _e1110[1])), (_e1115.member[2] + (_e1120 * _e1118[2]))), (_e1126 * (1f - _e1124)));
                                                                                                        } else {
                                                                                                            phi_960_ = _e808;
                                                                                                        }
                                                                                                        let _e1130 = phi_960_;
                                                                                                        phi_961_ = _e1130;
                                                                                                    }
                                                                                                    let _e1132 = phi_961_;
                                                                                                    let _e1134 = (_e1132.member_1 <= 0f);
                                                                                                    phi_968_ = _e1132;
                                                                                                    phi_970_ = select(true, false, _e1134);
                                                                                                    phi_971_ = _e1134;
                                                                                                } else {
                                                                                                    phi_968_ = type_14();
                                                                                                    phi_970_ = false;
                                                                                                    phi_971_ = false;
                                                                                                }
                                                                                                let _e1137 = phi_968_;
                                                                                                let _e1139 = phi_970_;
                                                                                                let _e1141 = phi_971_;
                                                                                                let _e1142 = local_111;
                                                                                                phi_973_ = _e1137;
                                                                                                phi_974_ = _e1137;
                                                                                                phi_978_ = _e1139;
                                                                                                phi_979_ = _e1141;
                                                                                                phi_980_ = select(true, false, _e1142);
                                                                                            } else {
                                                                                                phi_973_ = type_14();
                                                                                                phi_974_ = _e808;
                                                                                                phi_978_ = true;
                                                                                                phi_979_ = false;
                                                                                                phi_980_ = false;
                                                                                            }
                                                                                            let _e1145 = phi_973_;
                                                                                            let _e1147 = phi_974_;
                                                                                            let _e1149 = phi_978_;
                                                                                            let _e1151 = phi_979_;
                                                                                            let _e1153 = phi_980_;
                                                                                            let _e1154 = local_109;
                                                                                            let _e1155 = local_84;
                                                                                            let _e1156 = local_82;
                                                                                            let _e1158 = local_109;
                                                                                            let _e1159 = local_65;
                                                                                            let _e1160 = local_83;
                                                                                            let _e1162 = local_109;
                                                                                            let _e1163 = local_107;
                                                                                            let _e1164 = local_85;
                                                                                            phi_981_ = _e1145;
                                                                                            phi_982_ = _e1147;
                                                                                            phi_983_ = select(_e1156, _e1155, _e1154);
                                                                                            phi_984_ = select(_e1160, _e1159, _e1158);
                                                                                            phi_985_ = select(_e1164, _e1163, _e1162);
                                                                                            phi_986_ = _e1149;
                                                                                            phi_987_ = _e1151;
                                                                                            phi_988_ = _e1153;
                                                                                        } else {
                                                                                            phi_981_ = type_14();
                                                                                            phi_982_ = _e808;
                                                                                            phi_983_ = _e810;
                                                                                            phi_984_ = _e812;
                                                                                            phi_985_ = _e816;
                                                                                            phi_986_ = true;
                                                                                            phi_987_ = false;
                                                                                            phi_988_ = false;
                                                                                        }
                                                                                        let _e1167 = phi_981_;
                                                                                        let _e1169 = phi_982_;
                                                                                        let _e1171 = phi_983_;
                                                                                        let _e1173 = phi_984_;
                                                                                        let _e1175 = phi_985_;
                                                                                        let _e1177 = phi_986_;
                                                                                        let _e1179 = phi_987_;
                                                                                        let _e1181 = phi_988_;
                                                                                        phi_989_ = _e1167;
                                                                                        phi_990_ = _e1169;
                                                                                        phi_991_ = _e1171;
                                                                                        phi_992_ = _e1173;
                                                                                        phi_993_ = _e1175;
                                                                                        phi_994_ = _e1177;
                                                                                        phi_995_ = _e1179;
                                                                                        phi_996_ = _e1181;
                                                                                    } else {
                                                                                        phi_989_ = type_14();
                                                                                        phi_990_ = _e808;
                                                                                        phi_991_ = _e810;
                                                                                        phi_992_ = _e812;
                                                                                        phi_993_ = _e816;
                                                                                        phi_994_ = true;
                                                                                        phi_995_ = false;
                                                                                        phi_996_ = false;
                                                                                    }
                                                                                    let _e1183 = phi_989_;
                                                                                    let _e1185 = phi_990_;
                                                                                    let _e1187 = phi_991_;
                                                                                    let _e1189 = phi_992_;
                                                                                    let _e1191 = phi_993_;
                                                                                    let _e1193 = phi_994_;
                                                                                    let _e1195 = phi_995_;
                                                                                    let _e1197 = phi_996_;
                                                                                    phi_1002_ = _e1185;
                                                                                    phi_1003_ = _e1187;
                                                                                    phi_1004_ = _e1189;
                                                                                    phi_1005_ = _e1191;
                                                                                    phi_1006_ = _e1183;
                                                                                    phi_1007_ = _e1009.member_1.member;
                                                                                    phi_1008_ = _e1193;
                                                                                    phi_1009_ = select(_e1195, false, _e1193);
                                                                                    phi_1010_ = select(_e1197, false, _e1193);
                                                                                } else {
                                                                                    phi_1002_ = _e808;
                                                                                    phi_1003_ = _e810;
                                                                                    phi_1004_ = _e812;
                                                                                    phi_1005_ = _e816;
                                                                                    phi_1006_ = type_14();
                                                                                    phi_1007_ = array<f32, 3>();
                                                                                    phi_1008_ = true;
                                                                                    phi_1009_ = false;
                                                                                    phi_1010_ = false;
                                                                                }
                                                                                let _e1201 = phi_1002_;
                                                                                let _e1203 = phi_1003_;
                                                                                let _e1205 = phi_1004_;
                                                                                let _e1207 = phi_1005_;
                                                                                let _e1209 = phi_1006_;
                                                                                let _e1211 = phi_1007_;
                                                                                let _e1213 = phi_1008_;
                                                                                let _e1215 = phi_1009_;
                                                                                let _e1217 = phi_1010_;
                                                                                local_114 = _e1213;
                                                                                local_115 = _e1215;
                                                                                local_116 = _e1217;
                                                                                if _e1213 {
                                                                                    let _e1218 = local_84;
                                                                                    phi_1015_ = (_e1218 + 1u);
                                                                                } else {
                                                                                    phi_1015_ = u32();
                                                                                }
                                                                                let _e1221 = phi_1015_;
                                                                                let _e1222 = local_114;
                                                                                let _e1223 = local_115;
                                                                                let _e1225 = local_114;
                                                                                let _e1226 = local_116;
                                                                                phi_579_ = _e1201;
                                                                                phi_582_ = _e1203;
                                                                                phi_584_ = _e1205;
                                                                                phi_586_ = _e1221;
                                                                                phi_588_ = _e1207;
                                                                                phi_1018_ = _e1209;
                                                                                phi_1019_ = _e1211;
                                                                                phi_1020_ = _e1213;
                                                                                phi_1022_ = select(_e1223, false, _e1222);
                                                                                phi_1023_ = select(_e1226, false, _e1225);
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
                                                                            let _e1229 = phi_579_;
                                                                            let _e1231 = phi_582_;
                                                                            let _e1233 = phi_584_;
                                                                            let _e1235 = phi_586_;
                                                                            let _e1237 = phi_588_;
                                                                            let _e1239 = phi_1018_;
                                                                            let _e1241 = phi_1019_;
                                                                            let _e1243 = phi_1020_;
                                                                            let _e1245 = phi_1022_;
                                                                            let _e1247 = phi_1023_;
                                                                            local_117 = _e1243;
                                                                            let _e1248 = local_86;
                                                                            continue;
                                                                            continuing {
                                                                                let _e1250 = local_117;
                                                                                phi_578_ = _e1229;
                                                                                phi_581_ = _e1231;
                                                                                phi_583_ = _e1233;
                                                                                phi_585_ = _e1235;
                                                                                phi_587_ = _e1237;
                                                                                phi_2010_ = _e586;
                                                                                phi_1832_ = _e1247;
                                                                                phi_1831_ = _e1245;
                                                                                phi_1830_ = select(true, false, _e1248);
                                                                                phi_1828_ = _e1241;
                                                                                phi_1826_ = _e1239;
                                                                                break if !(_e1250);
                                                                            }
                                                                        }
                                                                        let _e1253 = phi_2010_;
                                                                        let _e1255 = phi_1832_;
                                                                        let _e1257 = phi_1831_;
                                                                        let _e1259 = phi_1830_;
                                                                        let _e1261 = phi_1828_;
                                                                        let _e1263 = phi_1826_;
                                                                        local_166 = _e1255;
                                                                        local_165 = _e1257;
                                                                        local_164 = _e1259;
                                                                        phi_2099_ = _e1253;
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
                                                                        if _e1253 {
                                                                            break;
                                                                        }
                                                                        let _e1264 = local_164;
                                                                        if _e1264 {
                                                                            let _e1265 = local_188;
                                                                            let _e1266 = local_47;
                                                                            phi_1028_ = (_e1265 + _e1266);
                                                                        } else {
                                                                            phi_1028_ = f32();
                                                                        }
                                                                        let _e1269 = phi_1028_;
                                                                        let _e1270 = local_164;
                                                                        let _e1271 = local_165;
                                                                        let _e1273 = local_164;
                                                                        let _e1274 = local_166;
                                                                        phi_2113_ = _e1253;
                                                                        let _e2423 = local_223;
                                                                        phi_1031_ = _e2423;
                                                                        let _e2426 = local_224;
                                                                        phi_1032_ = _e2426;
                                                                        let _e2429 = local_225;
                                                                        phi_1033_ = _e2429;
                                                                        let _e2432 = local_226;
                                                                        phi_1034_ = _e2432;
                                                                        phi_1035_ = _e1269;
                                                                        phi_1036_ = _e1263;
                                                                        phi_1037_ = _e1261;
                                                                        phi_1038_ = _e1259;
                                                                        phi_1039_ = select(_e1271, false, _e1270);
                                                                        phi_1040_ = select(_e1274, false, _e1273);
                                                                    }
                                                                    let _e1277 = phi_2113_;
                                                                    let _e1279 = phi_1031_;
                                                                    let _e1281 = phi_1032_;
                                                                    let _e1283 = phi_1033_;
                                                                    let _e1285 = phi_1034_;
                                                                    let _e1287 = phi_1035_;
                                                                    let _e1289 = phi_1036_;
                                                                    let _e1291 = phi_1037_;
                                                                    let _e1293 = phi_1038_;
                                                                    let _e1295 = phi_1039_;
                                                                    let _e1297 = phi_1040_;
                                                                    phi_2112_ = _e1277;
                                                                    phi_1041_ = _e1279;
                                                                    phi_1042_ = _e1281;
                                                                    phi_1043_ = _e1283;
                                                                    phi_1044_ = _e1285;
                                                                    phi_1045_ = _e600;
                                                                    phi_1046_ = _e1287;
                                                                    phi_1047_ = _e1289;
                                                                    phi_1048_ = _e1291;
                                                                    phi_1049_ = _e1293;
                                                                    phi_1050_ = _e806;
                                                                    phi_1051_ = _e1295;
                                                                    phi_1052_ = _e1297;
                                                                }
                                                                let _e1299 = phi_2112_;
                                                                let _e1301 = phi_1041_;
                                                                let _e1303 = phi_1042_;
                                                                let _e1305 = phi_1043_;
                                                                let _e1307 = phi_1044_;
                                                                let _e1309 = phi_1045_;
                                                                let _e1311 = phi_1046_;
                                                                let _e1313 = phi_1047_;
                                                                let _e1315 = phi_1048_;
                                                                let _e1317 = phi_1049_;
                                                                let _e1319 = phi_1050_;
                                                                let _e1321 = phi_1051_;
                                                                let _e1323 = phi_1052_;
                                                                phi_2110_ = _e1299;
                                                                phi_1059_ = _e1301;
                                                                phi_1060_ = _e1303;
                                                                phi_1061_ = _e1305;
                                                                phi_1062_ = _e1307;
                                                                phi_1063_ = _e1309;
                                                                phi_1064_ = _e1311;
                                                                phi_1065_ = _e1313;
                                                                phi_1066_ = _e1315;
                                                                phi_1067_ = _e1317;
                                                                phi_1068_ = select(_e1319, false, _e1317);
                                                                phi_1069_ = select(_e1321, false, _e1317);
                                                                phi_1070_ = select(_e1323, false, _e1317);
                                                            }
                                                            let _e1328 = phi_2110_;
                                                            let _e1330 = phi_1059_;
                                                            let _e1332 = phi_1060_;
                                                            let _e1334 = phi_1061_;
                                                            let _e1336 = phi_1062_;
                                                            let _e1338 = phi_1063_;
                                                            let _e1340 = phi_1064_;
                                                            let _e1342 = phi_1065_;
                                                            let _e1344 = phi_1066_;
                                                            let _e1346 = phi_1067_;
                                                            let _e1348 = phi_1068_;
                                                            let _e1350 = phi_1069_;
                                                            let _e1352 = phi_1070_;
                                                            phi_2109_ = _e1328;
                                                            phi_1071_ = _e1330;
                                                            phi_1072_ = _e1332;
                                                            phi_1073_ = _e1334;
                                                            phi_1074_ = _e1336;
                                                            phi_1075_ = _e1338;
                                                            phi_1076_ = _e1340;
                                                            phi_1077_ = _e1342;
                                                            phi_1078_ = _e1344;
                                                            phi_1079_ = _e789;
                                                            phi_1080_ = _e1346;
                                                            phi_1081_ = _e1348;
                                                            phi_1082_ = _e1350;
                                                            phi_1083_ = _e1352;
                                                        }
                                                        let _e1354 = phi_2109_;
                                                        let _e1356 = phi_1071_;
                                                        let _e1358 = phi_1072_;
                                                        let _e1360 = phi_1073_;
                                                        let _e1362 = phi_1074_;
                                                        let _e1364 = phi_1075_;
                                                        let _e1366 = phi_1076_;
                                                        let _e1368 = phi_1077_;
                                                        let _e1370 = phi_1078_;
                                                        let _e1372 = phi_1079_;
                                                        let _e1374 = phi_1080_;
                                                        let _e1376 = phi_1081_;
                                                        let _e1378 = phi_1082_;
                                                        let _e1380 = phi_1083_;
                                                        local_118 = _e1358;
                                                        local_119 = _e1360;
                                                        local_120 = _e1362;
                                                        local_121 = _e1372;
                                                        local_122 = _e1374;
                                                        local_123 = _e1376;
                                                        local_124 = _e1378;
                                                        local_125 = _e1380;
                                                        if _e1372 {
                                                            let _e1381 = local_188;
                                                            let _e1382 = local_47;
                                                            let _e1384 = local_55;
                                                            let _e1385 = (_e1384 + 1u);
                                                            let _e1386 = local_27;
                                                            let _e1388 = local_55;
                                                            phi_1097_ = _e588;
                                                            phi_1101_ = select(_e1388, _e1385, (_e1385 < _e1386));
                                                            phi_1102_ = (_e1381 + _e1382);
                                                        } else {
                                                            phi_1097_ = _e1356;
                                                            phi_1101_ = _e1364;
                                                            phi_1102_ = _e1366;
                                                        }
                                                        let _e1391 = phi_1097_;
                                                        let _e1393 = phi_1101_;
                                                        let _e1395 = phi_1102_;
                                                        let _e1396 = local_121;
                                                        let _e1397 = local_50;
                                                        let _e1398 = local_118;
                                                        let _e1400 = local_121;
                                                        let _e1401 = local_51;
                                                        let _e1402 = local_119;
                                                        let _e1404 = local_121;
                                                        let _e1405 = local_52;
                                                        let _e1406 = local_120;
                                                        let _e1408 = local_121;
                                                        let _e1409 = local_122;
                                                        let _e1410 = select(_e1409, true, _e1408);
                                                        let _e1411 = local_121;
                                                        let _e1412 = local_123;
                                                        let _e1414 = local_121;
                                                        let _e1415 = local_124;
                                                        let _e1417 = local_121;
                                                        let _e1418 = local_125;
                                                        phi_2105_ = _e1354;
                                                        phi_1113_ = _e1391;
                                                        phi_1114_ = select(_e1398, _e1397, _e1396);
                                                        phi_1115_ = select(_e1402, _e1401, _e1400);
                                                        phi_1116_ = select(_e1406, _e1405, _e1404);
                                                        phi_1117_ = _e646;
                                                        phi_1118_ = _e1393;
                                                        phi_1119_ = _e1395;
                                                        phi_1120_ = _e1368;
                                                        phi_1121_ = _e1370;
                                                        phi_1122_ = _e1410;
                                                        phi_1123_ = select(select(_e1412, false, _e1411), false, _e1410);
                                                        phi_1124_ = select(select(_e1415, false, _e1414), false, _e1410);
                                                        phi_1125_ = select(select(_e1418, false, _e1417), false, _e1410);
                                                    } else {
                                                        phi_2105_ = _e586;
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
                                                    let _e1424 = phi_2105_;
                                                    let _e1426 = phi_1113_;
                                                    let _e1428 = phi_1114_;
                                                    let _e1430 = phi_1115_;
                                                    let _e1432 = phi_1116_;
                                                    let _e1434 = phi_1117_;
                                                    let _e1436 = phi_1118_;
                                                    let _e1438 = phi_1119_;
                                                    let _e1440 = phi_1120_;
                                                    let _e1442 = phi_1121_;
                                                    let _e1444 = phi_1122_;
                                                    let _e1446 = phi_1123_;
                                                    let _e1448 = phi_1124_;
                                                    let _e1450 = phi_1125_;
                                                    let _e1451 = local_64;
                                                    phi_2104_ = _e1424;
                                                    phi_1127_ = _e1426;
                                                    phi_1128_ = _e1428;
                                                    phi_1129_ = _e1430;
                                                    phi_1130_ = _e1432;
                                                    phi_1131_ = _e1434;
                                                    phi_1132_ = _e1436;
                                                    phi_1133_ = _e1438;
                                                    phi_1134_ = _e1440;
                                                    phi_1135_ = _e1442;
                                                    phi_1136_ = _e1444;
                                                    phi_1137_ = _e1446;
                                                    phi_1138_ = _e1448;
                                                    phi_1139_ = _e1450;
                                                    phi_1140_ = select(true, false, _e1451);
                                                } else {
                                                    phi_2104_ = _e586;
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
                                                let _e1454 = phi_2104_;
                                                let _e1456 = phi_1127_;
                                                let _e1458 = phi_1128_;
                                                let _e1460 = phi_1129_;
                                                let _e1462 = phi_1130_;
                                                let _e1464 = phi_1131_;
                                                let _e1466 = phi_1132_;
                                                let _e1468 = phi_1133_;
                                                let _e1470 = phi_1134_;
                                                let _e1472 = phi_1135_;
                                                let _e1474 = phi_1136_;
                                                let _e1476 = phi_1137_;
                                                let _e1478 = phi_1138_;
                                                let _e1480 = phi_1139_;
                                                let _e1482 = phi_1140_;
                                                let _e1483 = local_63;
                                                phi_2103_ = _e1454;
                                                phi_1142_ = _e1456;
                                                phi_1143_ = _e1458;
                                                phi_1144_ = _e1460;
                                                phi_1145_ = _e1462;
                                                phi_1146_ = _e1464;
                                                phi_1147_ = _e1466;
                                                phi_1148_ = _e1468;
                                                phi_1149_ = _e1470;
                                                phi_1150_ = _e1472;
                                                phi_1151_ = _e1474;
                                                phi_1152_ = _e1476;
                                                phi_1153_ = _e1478;
                                                phi_1154_ = _e1480;
                                                phi_1155_ = _e1482;
                                                phi_1156_ = select(true, false, _e1483);
                                            } else {
                                                phi_2103_ = _e586;
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
                                            let _e1486 = phi_2103_;
                                            let _e1488 = phi_1142_;
                                            let _e1490 = phi_1143_;
                                            let _e1492 = phi_1144_;
                                            let _e1494 = phi_1145_;
                                            let _e1496 = phi_1146_;
                                            let _e1498 = phi_1147_;
                                            let _e1500 = phi_1148_;
                                            let _e1502 = phi_1149_;
                                            let _e1504 = phi_1150_;
                                            let _e1506 = phi_1151_;
                                            let _e1508 = phi_1152_;
                                            let _e1510 = phi_1153_;
                                            let _e1512 = phi_1154_;
                                            let _e1514 = phi_1155_;
                                            let _e1516 = phi_1156_;
                                            let _e1517 = local_62;
                                            phi_2102_ = _e1486;
                                            phi_1158_ = _e1488;
                                            phi_1159_ = _e1490;
                                            phi_1160_ = _e1492;
                                            phi_1161_ = _e1494;
                                            phi_1162_ = _e1496;
                                            phi_1163_ = _e1498;
                                            phi_1164_ = _e1500;
                                            phi_1165_ = _e1502;
                                            phi_1166_ = _e1504;
                                            phi_1167_ = _e1506;
                                            phi_1168_ = _e1508;
                                            phi_1169_ = _e1510;
                                            phi_1170_ = _e1512;
                                            phi_1171_ = _e1514;
                                            phi_1172_ = _e1516;
                                            phi_1173_ = select(true, false, _e1517);
                                        } else {
                                            phi_2102_ = _e586;
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
                                        let _e1520 = phi_2102_;
                                        let _e1522 = phi_1158_;
                                        let _e1524 = phi_1159_;
                                        let _e1526 = phi_1160_;
                                        let _e1528 = phi_1161_;
                                        let _e1530 = phi_1162_;
                                        let _e1532 = phi_1163_;
                                        let _e1534 = phi_1164_;
                                        let _e1536 = phi_1165_;
                                        let _e1538 = phi_1166_;
                                        let _e1540 = phi_1167_;
                                        let _e1542 = phi_1168_;
                                        let _e1544 = phi_1169_;
                                        let _e1546 = phi_1170_;
                                        let _e1548 = phi_1171_;
                                        let _e1550 = phi_1172_;
                                        let _e1552 = phi_1173_;
                                        let _e1553 = local_61;
                                        phi_2101_ = _e1520;
                                        phi_1175_ = _e1522;
                                        phi_1176_ = _e1524;
                                        phi_1177_ = _e1526;
                                        phi_1178_ = _e1528;
                                        phi_1179_ = _e1530;
                                        phi_1180_ = (_e609 + 1u);
                                        phi_1181_ = _e1532;
                                        phi_1182_ = _e1534;
                                        phi_1183_ = _e1536;
                                        phi_1184_ = _e1538;
                                        phi_1185_ = _e1540;
                                        phi_1186_ = _e1542;
                                        phi_1187_ = _e1544;
                                        phi_1188_ = _e1546;
                                        phi_1189_ = _e1548;
                                        phi_1190_ = _e1550;
                                        phi_1191_ = _e1552;
                                        phi_1192_ = select(true, false, _e1553);
                                    } else {
                                        phi_2101_ = _e586;
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
                                    let _e1556 = phi_2101_;
                                    let _e1558 = phi_1175_;
                                    let _e1560 = phi_1176_;
                                    let _e1562 = phi_1177_;
                                    let _e1564 = phi_1178_;
                                    let _e1566 = phi_1179_;
                                    let _e1568 = phi_1180_;
                                    let _e1570 = phi_1181_;
                                    let _e1572 = phi_1182_;
                                    let _e1574 = phi_1183_;
                                    let _e1576 = phi_1184_;
                                    let _e1578 = phi_1185_;
                                    let _e1580 = phi_1186_;
                                    let _e1582 = phi_1187_;
                                    let _e1584 = phi_1188_;
                                    let _e1586 = phi_1189_;
                                    let _e1588 = phi_1190_;
                                    let _e1590 = phi_1191_;
                                    let _e1592 = phi_1192_;
                                    let _e1593 = local_58;
                                    phi_2100_ = _e1556;
                                    phi_357_ = _e1558;
                                    phi_360_ = _e1560;
                                    phi_362_ = _e1562;
                                    phi_364_ = _e1564;
                                    phi_366_ = _e1566;
                                    phi_368_ = _e1568;
                                    phi_370_ = _e1570;
                                    phi_372_ = _e1572;
                                    phi_1194_ = _e1574;
                                    phi_1195_ = _e1576;
                                    phi_1196_ = _e1578;
                                    phi_1198_ = _e1580;
                                    phi_1199_ = _e1582;
                                    phi_1200_ = _e1584;
                                    phi_1201_ = _e1586;
                                    phi_1202_ = _e1588;
                                    phi_1203_ = _e1590;
                                    phi_1204_ = _e1592;
                                    phi_1205_ = select(true, false, _e1593);
                                } else {
                                    phi_2100_ = _e586;
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
                                let _e1596 = phi_2100_;
                                let _e1598 = phi_357_;
                                let _e1600 = phi_360_;
                                let _e1602 = phi_362_;
                                let _e1604 = phi_364_;
                                let _e1606 = phi_366_;
                                let _e1608 = phi_368_;
                                let _e1610 = phi_370_;
                                let _e1612 = phi_372_;
                                let _e1614 = phi_1194_;
                                let _e1616 = phi_1195_;
                                let _e1618 = phi_1196_;
                                let _e1620 = phi_1198_;
                                let _e1622 = phi_1199_;
                                let _e1624 = phi_1200_;
                                let _e1626 = phi_1201_;
                                let _e1628 = phi_1202_;
                                let _e1630 = phi_1203_;
                                let _e1632 = phi_1204_;
                                let _e1634 = phi_1205_;
                                local_126 = _e1618;
                                let _e1635 = local_57;
                                continue;
                                continuing {
                                    let _e1637 = local_126;
                                    phi_2071_ = _e1596;
                                    phi_356_ = _e1598;
                                    phi_359_ = _e1600;
                                    phi_361_ = _e1602;
                                    phi_363_ = _e1604;
                                    phi_365_ = _e1606;
                                    phi_367_ = _e1608;
                                    phi_369_ = _e1610;
                                    phi_371_ = _e1612;
                                    phi_2099_ = _e1596;
                                    phi_1843_ = _e1634;
                                    phi_1842_ = _e1632;
                                    phi_1841_ = _e1630;
                                    phi_1840_ = _e1628;
                                    phi_1839_ = _e1626;
                                    phi_1838_ = _e1624;
                                    phi_1837_ = _e1622;
                                    phi_1836_ = _e1620;
                                    phi_1835_ = select(true, false, _e1635);
                                    phi_1834_ = _e1616;
                                    phi_1833_ = _e1614;
                                    break if !(_e1637);
                                }
                            }
                            let _e1640 = phi_2099_;
                            let _e1642 = phi_1843_;
                            let _e1644 = phi_1842_;
                            let _e1646 = phi_1841_;
                            let _e1648 = phi_1840_;
                            let _e1650 = phi_1839_;
                            let _e1652 = phi_1838_;
                            let _e1654 = phi_1837_;
                            let _e1656 = phi_1836_;
                            let _e1658 = phi_1835_;
                            let _e1660 = phi_1834_;
                            let _e1662 = phi_1833_;
                            local_177 = _e1642;
                            local_176 = _e1644;
                            local_175 = _e1646;
                            local_174 = _e1648;
                            local_173 = _e1650;
                            local_172 = _e1652;
                            local_171 = _e1654;
                            local_170 = _e1656;
                            local_169 = _e1658;
                            local_168 = _e1660;
                            local_167 = _e1662;
                            phi_2166_ = _e1640;
                            if _e1640 {
                                break;
                            }
                            let _e1663 = local_169;
                            let _e1664 = local_170;
                            let _e1665 = select(_e1664, false, _e1663);
                            local_190 = _e1665;
                            let _e1666 = local_169;
                            let _e1667 = local_171;
                            local_191 = select(_e1667, false, _e1666);
                            let _e1669 = local_169;
                            let _e1670 = local_172;
                            local_192 = select(_e1670, false, _e1669);
                            let _e1672 = local_169;
                            let _e1673 = local_173;
                            local_193 = select(_e1673, false, _e1672);
                            let _e1675 = local_169;
                            let _e1676 = local_174;
                            local_194 = select(_e1676, false, _e1675);
                            let _e1678 = local_169;
                            let _e1679 = local_175;
                            local_195 = select(_e1679, false, _e1678);
                            let _e1681 = local_169;
                            let _e1682 = local_176;
                            local_196 = select(_e1682, false, _e1681);
                            let _e1684 = local_169;
                            let _e1685 = local_177;
                            local_197 = select(_e1685, false, _e1684);
                            if _e1665 {
                                let _e1687 = local_49;
                                phi_1222_ = type_25(_e1687.member, true);
                            } else {
                                phi_1222_ = type_25();
                            }
                            let _e1691 = phi_1222_;
                            let _e1692 = local_190;
                            let _e1693 = local_191;
                            let _e1694 = select(_e1693, false, _e1692);
                            local_198 = _e1694;
                            let _e1695 = local_190;
                            let _e1696 = local_192;
                            local_199 = select(_e1696, false, _e1695);
                            let _e1698 = local_190;
                            let _e1699 = local_193;
                            local_200 = select(_e1699, false, _e1698);
                            let _e1701 = local_190;
                            let _e1702 = local_194;
                            local_201 = select(_e1702, false, _e1701);
                            let _e1704 = local_190;
                            let _e1705 = local_195;
                            local_202 = select(_e1705, false, _e1704);
                            let _e1707 = local_190;
                            let _e1708 = local_196;
                            local_203 = select(_e1708, false, _e1707);
                            let _e1710 = local_190;
                            let _e1711 = local_197;
                            local_204 = select(_e1711, false, _e1710);
                            let _e1713 = local_190;
                            let _e1714 = local_169;
                            local_205 = select(_e1714, false, _e1713);
                            if _e1694 {
                                let _e1716 = local_167;
                                phi_1236_ = type_25(_e1716.member, true);
                            } else {
                                phi_1236_ = type_25();
                            }
                            let _e1720 = phi_1236_;
                            let _e1721 = local_198;
                            let _e1722 = local_199;
                            let _e1723 = select(_e1722, false, _e1721);
                            local_206 = _e1723;
                            let _e1724 = local_198;
                            let _e1725 = local_190;
                            local_207 = select(_e1725, false, _e1724);
                            let _e1727 = local_198;
                            let _e1728 = local_200;
                            local_208 = select(_e1728, false, _e1727);
                            let _e1730 = local_198;
                            let _e1731 = local_201;
                            local_209 = select(_e1731, false, _e1730);
                            let _e1733 = local_198;
                            let _e1734 = local_202;
                            local_210 = select(_e1734, false, _e1733);
                            let _e1736 = local_198;
                            let _e1737 = local_203;
                            local_211 = select(_e1737, false, _e1736);
                            let _e1739 = local_198;
                            let _e1740 = local_204;
                            local_212 = select(_e1740, false, _e1739);
                            let _e1742 = local_198;
                            let _e1743 = local_205;
                            local_213 = select(_e1743, false, _e1742);
                            if _e1723 {
                                let _e1745 = local_168;
                                phi_1249_ = type_25(_e1745, true);
                            } else {
                                phi_1249_ = _e1720;
                            }
                            let _e1748 = phi_1249_;
                            let _e1749 = local_206;
                            let _e1750 = local_198;
                            let _e1751 = select(_e1750, true, _e1749);
                            local_214 = _e1751;
                            let _e1752 = local_206;
                            let _e1753 = local_207;
                            local_215 = select(_e1753, false, _e1752);
                            let _e1755 = local_206;
                            let _e1756 = local_208;
                            local_216 = select(_e1756, false, _e1755);
                            let _e1758 = local_206;
                            let _e1759 = local_209;
                            local_217 = select(_e1759, false, _e1758);
                            let _e1761 = local_206;
                            let _e1762 = local_210;
                            local_218 = select(_e1762, false, _e1761);
                            let _e1764 = local_206;
                            let _e1765 = local_211;
                            local_219 = select(_e1765, false, _e1764);
                            let _e1767 = local_206;
                            let _e1768 = local_212;
                            local_220 = select(_e1768, false, _e1767);
                            let _e1770 = local_206;
                            let _e1771 = local_213;
                            local_221 = select(_e1771, false, _e1770);
                            if _e1751 {
                                phi_1261_ = _e1748;
                            } else {
                                phi_1261_ = _e1691;
                            }
                            let _e1774 = phi_1261_;
                            let _e1775 = local_214;
                            let _e1776 = local_215;
                            let _e1777 = select(_e1776, true, _e1775);
                            let _e1778 = local_214;
                            let _e1779 = local_216;
                            let _e1781 = local_214;
                            let _e1782 = local_217;
                            let _e1784 = local_214;
                            let _e1785 = local_218;
                            let _e1787 = local_214;
                            let _e1788 = local_219;
                            let _e1790 = local_214;
                            let _e1791 = local_220;
                            let _e1793 = local_214;
                            let _e1794 = local_221;
                            let _e1796 = select(select(_e1779, false, _e1778), false, _e1777);
                            let _e1802 = select(select(select(_e1782, false, _e1781), false, _e1777), false, _e1796);
                            let _e1807 = select(select(select(select(_e1785, false, _e1784), false, _e1777), false, _e1796), false, _e1802);
                            let _e1812 = select(select(select(select(select(_e1788, false, _e1787), false, _e1777), false, _e1796), false, _e1802), false, _e1807);
                            let _e1816 = select(select(select(_e1796, true, _e1802), true, _e1807), true, _e1812);
                            if select(select(select(select(select(select(select(select(_e1794, false, _e1793), false, _e1777), false, _e1796), false, _e1802), false, _e1807), false, _e1812), true, _e1816), true, select(select(select(select(select(select(select(_e1791, false, _e1790), false, _e1777), false, _e1796), false, _e1802), false, _e1807), false, _e1812), false, _e1816)) {
                                let _e1825 = local_53;
                                let _e1826 = local_1;
                                if (_e1825 < _e1826) {
                                } else {
                                    phi_2166_ = true;
                                    break;
                                }
                                let _e1828 = local_53;
                                let _e1831 = global_3.member[_e1828];
                                let _e1834 = global_5.member.member_2;
                                local_127 = _e1834;
                                local_222 = select(_e1831, _e1834, (_e1834 < _e1831));
                                phi_1335_ = type_17(0u, type_17().member_1);
                                phi_1338_ = 0u;
                                loop {
                                    let _e1838 = phi_1335_;
                                    let _e1840 = phi_1338_;
                                    local_128 = _e1838;
                                    local_129 = _e1840;
                                    let _e1841 = local_129;
                                    let _e1842 = local_222;
                                    let _e1843 = (_e1841 < _e1842);
                                    local_130 = _e1843;
                                    if _e1843 {
                                        let _e1844 = local_53;
                                        let _e1845 = local_127;
                                        let _e1847 = local_129;
                                        let _e1849 = (5u * ((_e1844 * _e1845) + _e1847));
                                        local_131 = _e1849;
                                        let _e1850 = local;
                                        if (_e1849 < _e1850) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1852 = local_131;
                                        let _e1855 = global_4.member[_e1852];
                                        local_132 = bitcast<f32>(_e1855);
                                        let _e1857 = local_131;
                                        let _e1858 = (_e1857 + 1u);
                                        local_133 = _e1858;
                                        let _e1859 = local;
                                        if (_e1858 < _e1859) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1861 = local_133;
                                        let _e1864 = global_4.member[_e1861];
                                        local_134 = bitcast<f32>(_e1864);
                                        let _e1866 = local_131;
                                        let _e1867 = (_e1866 + 2u);
                                        local_135 = _e1867;
                                        let _e1868 = local;
                                        if (_e1867 < _e1868) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1870 = local_135;
                                        let _e1873 = global_4.member[_e1870];
                                        local_136 = bitcast<f32>(_e1873);
                                        let _e1875 = local_131;
                                        let _e1876 = (_e1875 + 3u);
                                        local_137 = _e1876;
                                        let _e1877 = local;
                                        if (_e1876 < _e1877) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1879 = local_137;
                                        let _e1882 = global_4.member[_e1879];
                                        local_138 = bitcast<f32>(_e1882);
                                        let _e1884 = local_131;
                                        let _e1885 = (_e1884 + 4u);
                                        local_139 = _e1885;
                                        let _e1886 = local;
                                        if (_e1885 < _e1886) {
                                        } else {
                                            phi_2115_ = true;
                                            break;
                                        }
                                        let _e1888 = local_139;
                                        let _e1891 = global_4.member[_e1888];
                                        local_140 = bitcast<f32>(_e1891);
                                        let _e1893 = local_132;
                                        if ((bitcast<u32>(_e1893) & 2139095040u) != 2139095040u) {
                                            let _e1897 = local_134;
                                            if ((bitcast<u32>(_e1897) & 2139095040u) != 2139095040u) {
                                                let _e1901 = local_136;
                                                let _e1904 = ((bitcast<u32>(_e1901) & 2139095040u) != 2139095040u);
                                                local_141 = _e1904;
                                                if _e1904 {
                                                    let _e1905 = local_138;
                                                    let _e1906 = bitcast<u32>(_e1905);
                                                    local_142 = _e1906;
                                                    if (_e1906 == 0u) {
                                                        phi_1419_ = false;
                                                    } else {
                                                        let _e1908 = local_142;
                                                        phi_1419_ = (_e1908 <= 2139095040u);
                                                    }
                                                    let _e1911 = phi_1419_;
                                                    phi_1420_ = _e1911;
                                                } else {
                                                    phi_1420_ = bool();
                                                }
                                                let _e1913 = phi_1420_;
                                                let _e1914 = local_141;
                                                phi_1422_ = _e1913;
                                                phi_1423_ = select(true, false, _e1914);
                                            } else {
                                                phi_1422_ = bool();
                                                phi_1423_ = true;
                                            }
                                            let _e1917 = phi_1422_;
                                            let _e1919 = phi_1423_;
                                            phi_1424_ = _e1917;
                                            phi_1425_ = _e1919;
                                        } else {
                                            phi_1424_ = bool();
                                            phi_1425_ = true;
                                        }
                                        let _e1921 = phi_1424_;
                                        let _e1923 = phi_1425_;
                                        if select(_e1921, false, _e1923) {
                                            let _e1925 = local_138;
                                            let _e1926 = bitcast<u32>(_e1925);
                                            local_143 = _e1926;
                                            if (_e1926 == 0u) {
                                                phi_1440_ = false;
                                            } else {
                                                let _e1928 = local_143;
                                                phi_1440_ = (_e1928 <= 2139095040u);
                                            }
                                            let _e1931 = phi_1440_;
                                            if _e1931 {
                                                let _e1932 = local_43;
                                                if (_e1932 == 0f) {
                                                    phi_1468_ = 0f;
                                                } else {
                                                    let _e1934 = local_42;
                                                    let _e1935 = local_138;
                                                    let _e1938 = local_43;
                                                    phi_1468_ = (_e1938 * (1f - (_e1934 / _e1935)));
                                                }
                                                let _e1941 = phi_1468_;
                                                phi_1469_ = _e1941;
                                            } else {
                                                phi_1469_ = _e284;
                                            }
                                            let _e1943 = phi_1469_;
                                            let _e1944 = (0.5f * _e1943);
                                            local_144 = _e1944;
                                            let _e1947 = ((bitcast<u32>(_e1944) & 2139095040u) != 2139095040u);
                                            local_145 = _e1947;
                                            if _e1947 {
                                                let _e1948 = local_132;
                                                if (_e1948 > 1267650600000000000000000000000f) {
                                                    let _e1950 = local_132;
                                                    phi_1486_ = select(true, false, (_e1950 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1486_ = true;
                                                }
                                                let _e1954 = phi_1486_;
                                                if _e1954 {
                                                    let _e1955 = local_132;
                                                    if (_e1955 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e1957 = local_132;
                                                        phi_1500_ = select(true, false, (_e1957 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_1500_ = true;
                                                    }
                                                    let _e1961 = phi_1500_;
                                                    let _e1962 = local_132;
                                                    phi_1505_ = select(0f, _e1962, _e1961);
                                                } else {
                                                    phi_1505_ = 1267650600000000000000000000000f;
                                                }
                                                let _e1965 = phi_1505_;
                                                local_146 = _e1965;
                                                let _e1966 = local_134;
                                                if (_e1966 > 1267650600000000000000000000000f) {
                                                    let _e1968 = local_134;
                                                    phi_1515_ = select(true, false, (_e1968 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1515_ = true;
                                                }
                                                let _e1972 = phi_1515_;
                                                if _e1972 {
                                                    let _e1973 = local_134;
                                                    if (_e1973 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e1975 = local_134;
                                                        phi_1529_ = select(true, false, (_e1975 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_1529_ = true;
                                                    }
                                                    let _e1979 = phi_1529_;
                                                    let _e1980 = local_134;
                                                    phi_1534_ = select(0f, _e1980, _e1979);
                                                } else {
                                                    phi_1534_ = 1267650600000000000000000000000f;
                                                }
                                                let _e1983 = phi_1534_;
                                                local_147 = _e1983;
                                                let _e1984 = local_136;
                                                if (_e1984 > 1267650600000000000000000000000f) {
                                                    let _e1986 = local_136;
                                                    phi_1544_ = select(true, false, (_e1986 <= 340282350000000000000000000000000000000f));
                                                } else {
                                                    phi_1544_ = true;
                                                }
                                                let _e1990 = phi_1544_;
                                                if _e1990 {
                                                    let _e1991 = local_136;
                                                    if (_e1991 < 0.000000000000000000000000000000000000011754944f) {
                                                        let _e1993 = local_136;
                                                        phi_1558_ = select(true, false, (_e1993 >= -340282350000000000000000000000000000000f));
                                                    } else {
                                                        phi_1558_ = true;
                                                    }
                                                    let _e1997 = phi_1558_;
                                                    let _e1998 = local_136;
                                                    phi_1563_ = select(0f, _e1998, _e1997);
                                                } else {
                                                    phi_1563_ = 1267650600000000000000000000000f;
                                                }
                                                let _e2001 = phi_1563_;
                                                let _e2002 = local_146;
                                                let _e2003 = local_147;
                                                local_148 = array<f32, 3>(_e2002, _e2003, _e2001);
                                                let _e2005 = local_140;
                                                if (_e2005 > 1f) {
                                                    phi_1574_ = 1f;
                                                } else {
                                                    let _e2007 = local_140;
                                                    let _e2009 = local_140;
                                                    phi_1574_ = select(0f, _e2009, (_e2007 >= 0f));
                                                }
                                                let _e2012 = phi_1574_;
                                                let _e2013 = local_148;
                                                let _e2014 = local_144;
                                                phi_1577_ = type_24(1u, type_16(_e2013, _e2014, _e2012));
                                            } else {
                                                phi_1577_ = type_24();
                                            }
                                            let _e2018 = phi_1577_;
                                            let _e2019 = local_145;
                                            phi_1579_ = _e2018;
                                            phi_1580_ = select(true, false, _e2019);
                                        } else {
                                            phi_1579_ = type_24();
                                            phi_1580_ = true;
                                        }
                                        let _e2022 = phi_1579_;
                                        let _e2024 = phi_1580_;
                                        if _e2024 {
                                            phi_1585_ = type_24(0u, type_24().member_1);
                                        } else {
                                            phi_1585_ = _e2022;
                                        }
                                        let _e2029 = phi_1585_;
                                        local_149 = _e2029;
                                        if (bitcast<i32>(_e2029.member) != 0i) {
                                            let _e2033 = local_149;
                                            local_150 = _e2033.member_1.member;
                                            let _e2036 = local_149;
                                            let _e2039 = local_52;
                                            if (_e2036.member_1.member_1 > _e2039) {
                                                let _e2041 = local_53;
                                                let _e2042 = local_51;
                                                if (_e2041 != _e2042) {
                                                    phi_1606_ = true;
                                                } else {
                                                    let _e2044 = local_129;
                                                    let _e2045 = local_50;
                                                    phi_1606_ = (_e2044 > _e2045);
                                                }
                                                let _e2048 = phi_1606_;
                                                if _e2048 {
                                                    let _e2049 = local_150;
                                                    phi_1611_ = type_17(1u, _e2049);
                                                } else {
                                                    phi_1611_ = _e1838;
                                                }
                                                let _e2052 = phi_1611_;
                                                phi_1612_ = _e2052;
                                            } else {
                                                phi_1612_ = _e1838;
                                            }
                                            let _e2054 = phi_1612_;
                                            phi_1613_ = _e2054;
                                        } else {
                                            phi_1613_ = _e1838;
                                        }
                                        let _e2056 = phi_1613_;
                                        let _e2057 = local_129;
                                        phi_1336_ = _e2056;
                                        phi_1339_ = (_e2057 + 1u);
                                    } else {
                                        phi_1336_ = type_17();
                                        phi_1339_ = u32();
                                    }
                                    let _e2060 = phi_1336_;
                                    let _e2062 = phi_1339_;
                                    continue;
                                    continuing {
                                        let _e2063 = local_130;
                                        phi_1335_ = _e2060;
                                        phi_1338_ = _e2062;
                                        phi_2115_ = _e1640;
                                        break if !(_e2063);
                                    }
                                }
                                let _e2066 = phi_2115_;
                                phi_2166_ = _e2066;
                                if _e2066 {
                                    break;
                                }
                                let _e2067 = local_128;
                                if (bitcast<i32>(_e2067.member) != 0i) {
                                    let _e2071 = local_49;
                                    local_151 = _e2071.member_1;
                                    let _e2073 = (_e2071.member_1 >= 1f);
                                    local_152 = _e2073;
                                    if _e2073 {
                                        let _e2074 = local_49;
                                        if (_e2074.member[0] == 0f) {
                                            let _e2078 = local_49;
                                            let _e2081 = (_e2078.member[1] == 0f);
                                            local_153 = _e2081;
                                            if _e2081 {
                                                let _e2082 = local_49;
                                                phi_1638_ = (_e2082.member[2] == 0f);
                                            } else {
                                                phi_1638_ = bool();
                                            }
                                            let _e2087 = phi_1638_;
                                            let _e2088 = local_153;
                                            phi_1640_ = _e2087;
                                            phi_1641_ = select(true, false, _e2088);
                                        } else {
                                            phi_1640_ = bool();
                                            phi_1641_ = true;
                                        }
                                        let _e2091 = phi_1640_;
                                        let _e2093 = phi_1641_;
                                        phi_1642_ = _e2091;
                                        phi_1643_ = _e2093;
                                    } else {
                                        phi_1642_ = bool();
                                        phi_1643_ = true;
                                    }
                                    let _e2095 = phi_1642_;
                                    let _e2097 = phi_1643_;
                                    if select(_e2095, false, _e2097) {
                                        let _e2099 = local_128;
                                        phi_1713_ = type_25(_e2099.member_1, false);
                                    } else {
                                        let _e2102 = local_128;
                                        local_154 = _e2102.member_1;
                                        let _e2104 = local_152;
                                        if _e2104 {
                                            let _e2105 = local_49;
                                            if (_e2105.member[0] == 0f) {
                                                let _e2109 = local_49;
                                                let _e2112 = (_e2109.member[1] == 0f);
                                                local_155 = _e2112;
                                                if _e2112 {
                                                    let _e2113 = local_49;
                                                    phi_1672_ = (_e2113.member[2] == 0f);
                                                } else {
                                                    phi_1672_ = bool();
                                                }
                                                let _e2118 = phi_1672_;
                                                let _e2119 = local_155;
                                                phi_1674_ = _e2118;
                                                phi_1675_ = select(true, false, _e2119);
                                            } else {
                                                phi_1674_ = bool();
                                                phi_1675_ = true;
                                            }
                                            let _e2122 = phi_1674_;
                                            let _e2124 = phi_1675_;
                                            phi_1676_ = _e2122;
                                            phi_1677_ = _e2124;
                                        } else {
                                            phi_1676_ = bool();
                                            phi_1677_ = true;
                                        }
                                        let _e2126 = phi_1676_;
                                        let _e2128 = phi_1677_;
                                        if select(_e2126, false, _e2128) {
                                            let _e2130 = local_154;
                                            phi_1710_ = type_14(_e2130, 0f);
                                        } else {
                                            let _e2132 = local_151;
                                            if (_e2132 > 0f) {
                                                let _e2134 = local_49;
                                                let _e2137 = local_154;
                                                let _e2139 = local_151;
                                                let _e2142 = local_49;
                                                let _e2145 = local_154;
                                                let _e2147 = local_151;
                                                let _e2150 = local_49;
                                                let _e2153 = local_154;
                                                let _e2155 = local_151;
                                                phi_1709_ = type_14(array<f32, 3>((_e2134.member[0] + (_e2139 * _e2137[0])), (_e2142.member[1] + (_e2147 * _e2145[1])), (_e2150.member[2] + (_e2155 * _e2153[2]))), 0f);
                                            } else {
                                                let _e2643 = local_227;
                                                phi_1709_ = _e2643;
                                            }
                                            let _e2161 = phi_1709_;
                                            phi_1710_ = _e2161;
                                        }
                                        let _e2163 = phi_1710_;
                                        phi_1713_ = type_25(_e2163.member, false);
                                    }
                                    let _e2167 = phi_1713_;
                                    phi_1718_ = _e2167;
                                } else {
                                    let _e2168 = local_49;
                                    let _e2170 = local_49;
                                    phi_1718_ = type_25(_e2168.member, (_e2170.member_1 < 1f));
                                }
                                let _e2175 = phi_1718_;
                                phi_2170_ = _e2066;
                                phi_1719_ = _e2175;
                            } else {
                                phi_2170_ = _e1640;
                                phi_1719_ = _e1774;
                            }
                            let _e2177 = phi_2170_;
                            let _e2179 = phi_1719_;
                            local_156 = _e2179;
                            let _e2180 = local_18;
                            if (_e2180 == 0u) {
                                let _e2182 = local_156;
                                phi_1725_ = _e2182.member;
                            } else {
                                phi_1725_ = _e356;
                            }
                            let _e2185 = phi_1725_;
                            let _e2186 = local_156;
                            let _e2191 = local_20;
                            let _e2194 = local_156;
                            let _e2199 = local_20;
                            let _e2202 = local_156;
                            let _e2207 = local_20;
                            let _e2211 = local_156;
                            if _e2211.member_1 {
                                phi_1749_ = _e360;
                            } else {
                                let _e2213 = local_19;
                                phi_1749_ = (_e2213 + 1u);
                            }
                            let _e2216 = phi_1749_;
                            let _e2217 = local_18;
                            phi_2167_ = _e2177;
                            phi_203_ = _e2185;
                            phi_206_ = (_e2217 + 1u);
                            phi_208_ = _e2216;
                            phi_210_ = array<f32, 3>((_e2191[0] + (_e2186.member[0] - _e2185[0])), (_e2199[1] + (_e2194.member[1] - _e2185[1])), (_e2207[2] + (_e2202.member[2] - _e2185[2])));
                        } else {
                            phi_2167_ = _e354;
                            phi_203_ = array<f32, 3>();
                            phi_206_ = u32();
                            phi_208_ = u32();
                            phi_210_ = array<f32, 3>();
                        }
                        let _e2220 = phi_2167_;
                        let _e2222 = phi_203_;
                        let _e2224 = phi_206_;
                        let _e2226 = phi_208_;
                        let _e2228 = phi_210_;
                        continue;
                        continuing {
                            let _e2229 = local_22;
                            phi_2085_ = _e2220;
                            phi_202_ = _e2222;
                            phi_205_ = _e2224;
                            phi_207_ = _e2226;
                            phi_209_ = _e2228;
                            phi_2166_ = _e2220;
                            break if !(_e2229);
                        }
                    }
                    let _e2232 = phi_2166_;
                    if _e2232 {
                        break;
                    }
                    let _e2233 = local_21;
                    let _e2235 = local_21;
                    let _e2238 = (1f / f32(select(1u, _e2235, (1u < _e2233))));
                    local_157 = _e2238;
                    let _e2239 = local_10;
                    let _e2240 = (3u * _e2239);
                    local_158 = _e2240;
                    let _e2241 = local_17;
                    let _e2243 = local_20;
                    local_159 = bitcast<u32>((_e2241[0] + (_e2243[0] * _e2238)));
                    let _e2248 = local_4;
                    if (_e2240 < _e2248) {
                    } else {
                        break;
                    }
                    let _e2250 = local_158;
                    let _e2253 = local_159;
                    global_2.member[_e2250] = _e2253;
                    let _e2254 = local_158;
                    let _e2255 = (_e2254 + 1u);
                    local_160 = _e2255;
                    let _e2256 = local_17;
                    let _e2258 = local_20;
                    let _e2260 = local_157;
                    local_161 = bitcast<u32>((_e2256[1] + (_e2258[1] * _e2260)));
                    let _e2264 = local_4;
                    if (_e2255 < _e2264) {
                    } else {
                        break;
                    }
                    let _e2266 = local_160;
                    let _e2269 = local_161;
                    global_2.member[_e2266] = _e2269;
                    let _e2270 = local_158;
                    let _e2271 = (_e2270 + 2u);
                    local_162 = _e2271;
                    let _e2272 = local_17;
                    let _e2274 = local_20;
                    let _e2276 = local_157;
                    local_163 = bitcast<u32>((_e2272[2] + (_e2274[2] * _e2276)));
                    let _e2280 = local_4;
                    if (_e2271 < _e2280) {
                    } else {
                        break;
                    }
                    let _e2282 = local_162;
                    let _e2285 = local_163;
                    global_2.member[_e2282] = _e2285;
                    let _e2286 = local_19;
                    if (_e2286 > 0u) {
                        let _e2288 = local_5;
                        if (0u < _e2288) {
                        } else {
                            break;
                        }
                        let _e2292 = local_19;
                        let _e2293 = atomicAdd((&global_8.member[0u]), _e2292);
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
