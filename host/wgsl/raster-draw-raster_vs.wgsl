struct type_3 {
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

struct VertexOutput {
    @builtin(position) member: vec4<f32>,
    @location(0) member_1: vec2<f32>,
    @location(1) member_2: f32,
    @location(2) @interpolate(flat) member_3: u32,
}

@group(0) @binding(0) 
var<storage> global: type_3;
@group(0) @binding(1) 
var<storage> global_1: type_3;
var<private> global_2: i32;
var<private> global_3: vec4<f32> = vec4<f32>(0f, 0f, 0f, 1f);
@group(0) @binding(2) 
var<storage> global_4: type_3;
var<immediate> global_5: type_22;
var<private> global_6: vec2<f32>;
var<private> global_7: f32;
var<private> global_8: u32;

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
    var local_14: f32;
    var local_15: u32;
    var local_16: f32;
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
    var local_27: u32;
    var local_28: f32;
    var local_29: u32;
    var local_30: f32;
    var local_31: f32;
    var local_32: f32;
    var local_33: f32;
    var local_34: u32;
    var local_35: bool;
    var local_36: f32;
    var local_37: f32;
    var local_38: f32;
    var local_39: array<array<f32, 3>, 3>;
    var phi_245_: bool;
    var phi_246_: bool;
    var phi_326_: vec4<f32>;

    switch bitcast<i32>(0u) {
        default: {
            let _e64 = global_2;
            local = arrayLength((&global.member));
            let _e68 = arrayLength((&global_1.member));
            local_1 = _e68;
            local_2 = arrayLength((&global_4.member));
            let _e71 = bitcast<u32>(_e64);
            let _e72 = (_e71 / 3u);
            local_3 = _e72;
            local_4 = (_e71 % 3u);
            let _e74 = (_e72 * 4u);
            local_5 = _e74;
            if (_e74 < _e68) {
            } else {
                break;
            }
            let _e76 = local_5;
            let _e79 = global_1.member[_e76];
            local_6 = _e79;
            let _e80 = local_5;
            let _e81 = (_e80 + 1u);
            local_7 = _e81;
            let _e82 = local_1;
            if (_e81 < _e82) {
            } else {
                break;
            }
            let _e84 = local_7;
            let _e87 = global_1.member[_e84];
            local_8 = _e87;
            let _e88 = local_5;
            let _e89 = (_e88 + 2u);
            local_9 = _e89;
            let _e90 = local_1;
            if (_e89 < _e90) {
            } else {
                break;
            }
            let _e92 = local_9;
            let _e95 = global_1.member[_e92];
            local_10 = _e95;
            let _e96 = local_5;
            let _e97 = (_e96 + 3u);
            local_11 = _e97;
            let _e98 = local_1;
            if (_e97 < _e98) {
            } else {
                break;
            }
            let _e100 = local_11;
            let _e103 = global_1.member[_e100];
            local_12 = _e103;
            let _e104 = local_6;
            let _e105 = (_e104 * 10u);
            local_13 = _e105;
            let _e106 = local;
            if (_e105 < _e106) {
            } else {
                break;
            }
            let _e108 = local_13;
            let _e111 = global.member[_e108];
            local_14 = bitcast<f32>(_e111);
            let _e113 = local_13;
            let _e114 = (_e113 + 1u);
            local_15 = _e114;
            let _e115 = local;
            if (_e114 < _e115) {
            } else {
                break;
            }
            let _e117 = local_15;
            let _e120 = global.member[_e117];
            local_16 = bitcast<f32>(_e120);
            let _e122 = local_13;
            let _e123 = (_e122 + 2u);
            local_17 = _e123;
            let _e124 = local;
            if (_e123 < _e124) {
            } else {
                break;
            }
            let _e126 = local_17;
            let _e129 = global.member[_e126];
            local_18 = bitcast<f32>(_e129);
            let _e131 = local_8;
            let _e132 = (_e131 * 10u);
            local_19 = _e132;
            let _e133 = local;
            if (_e132 < _e133) {
            } else {
                break;
            }
            let _e135 = local_19;
            let _e138 = global.member[_e135];
            local_20 = bitcast<f32>(_e138);
            let _e140 = local_19;
            let _e141 = (_e140 + 1u);
            local_21 = _e141;
            let _e142 = local;
            if (_e141 < _e142) {
            } else {
                break;
            }
            let _e144 = local_21;
            let _e147 = global.member[_e144];
            local_22 = bitcast<f32>(_e147);
            let _e149 = local_19;
            let _e150 = (_e149 + 2u);
            local_23 = _e150;
            let _e151 = local;
            if (_e150 < _e151) {
            } else {
                break;
            }
            let _e153 = local_23;
            let _e156 = global.member[_e153];
            local_24 = bitcast<f32>(_e156);
            let _e158 = local_10;
            let _e159 = (_e158 * 10u);
            local_25 = _e159;
            let _e160 = local;
            if (_e159 < _e160) {
            } else {
                break;
            }
            let _e162 = local_25;
            let _e165 = global.member[_e162];
            local_26 = bitcast<f32>(_e165);
            let _e167 = local_25;
            let _e168 = (_e167 + 1u);
            local_27 = _e168;
            let _e169 = local;
            if (_e168 < _e169) {
            } else {
                break;
            }
            let _e171 = local_27;
            let _e174 = global.member[_e171];
            local_28 = bitcast<f32>(_e174);
            let _e176 = local_25;
            let _e177 = (_e176 + 2u);
            local_29 = _e177;
            let _e178 = local;
            if (_e177 < _e178) {
            } else {
                break;
            }
            let _e180 = local_29;
            let _e183 = global.member[_e180];
            let _e184 = bitcast<f32>(_e183);
            local_30 = _e184;
            let _e185 = local_20;
            let _e186 = local_14;
            let _e187 = (_e185 - _e186);
            let _e188 = local_22;
            let _e189 = local_16;
            let _e190 = (_e188 - _e189);
            let _e191 = local_24;
            let _e192 = local_18;
            let _e193 = (_e191 - _e192);
            let _e194 = local_26;
            let _e195 = local_14;
            let _e196 = (_e194 - _e195);
            let _e197 = local_28;
            let _e198 = local_16;
            let _e199 = (_e197 - _e198);
            let _e200 = local_18;
            let _e201 = (_e184 - _e200);
            let _e204 = ((_e190 * _e201) - (_e193 * _e199));
            local_31 = _e204;
            let _e207 = ((_e193 * _e196) - (_e187 * _e201));
            local_32 = _e207;
            let _e210 = ((_e187 * _e199) - (_e190 * _e196));
            local_33 = _e210;
            if ((((_e204 * _e204) + (_e207 * _e207)) + (_e210 * _e210)) == 0f) {
                phi_246_ = false;
            } else {
                let _e217 = local_12;
                let _e219 = ((_e217 * 16u) + 10u);
                local_34 = _e219;
                let _e220 = local_2;
                if (_e219 < _e220) {
                } else {
                    break;
                }
                let _e222 = local_34;
                let _e225 = global_4.member[_e222];
                if ((_e225 & 2u) == 0u) {
                    let _e230 = global_5.member.member_3;
                    let _e232 = local_14;
                    let _e235 = local_16;
                    let _e238 = local_18;
                    let _e240 = local_31;
                    let _e242 = local_32;
                    let _e245 = local_33;
                    phi_245_ = ((((_e240 * (_e232 - _e230[0])) + (_e242 * (_e235 - _e230[1]))) + (_e245 * (_e238 - _e230[2]))) < 0f);
                } else {
                    phi_245_ = true;
                }
                let _e250 = phi_245_;
                phi_246_ = _e250;
            }
            let _e252 = phi_246_;
            local_35 = _e252;
            let _e253 = local_14;
            let _e254 = local_16;
            let _e255 = local_18;
            let _e257 = local_20;
            let _e258 = local_22;
            let _e259 = local_24;
            let _e261 = local_26;
            let _e262 = local_28;
            let _e263 = local_30;
            local_39 = array<array<f32, 3>, 3>(array<f32, 3>(_e253, _e254, _e255), array<f32, 3>(_e257, _e258, _e259), array<f32, 3>(_e261, _e262, _e263));
            let _e266 = local_4;
            if (_e266 < 3u) {
            } else {
                break;
            }
            let _e268 = local_4;
            let _e270 = local_39[_e268];
            let _e276 = global_5.member.member;
            local_36 = ((((_e276[0] * _e270[0]) + (_e276[1] * _e270[1])) + (_e276[2] * _e270[2])) + _e276[3]);
            let _e289 = global_5.member.member_1;
            local_37 = ((((_e289[0] * _e270[0]) + (_e289[1] * _e270[1])) + (_e289[2] * _e270[2])) + _e289[3]);
            let _e302 = global_5.member.member_2;
            local_38 = ((((_e302[0] * _e270[0]) + (_e302[1] * _e270[1])) + (_e302[2] * _e270[2])) + _e302[3]);
            let _e313 = local_35;
            if _e313 {
                let _e316 = global_5.member.member_4;
                let _e317 = local_36;
                let _e318 = local_37;
                let _e319 = local_38;
                phi_326_ = vec4<f32>(_e317, _e318, _e316, _e319);
            } else {
                phi_326_ = vec4<f32>(2f, 2f, 0.5f, 1f);
            }
            let _e322 = phi_326_;
            global_3 = _e322;
            let _e323 = local_4;
            let _e326 = local_4;
            global_6[0u] = select(0f, 1f, (_e323 == 0u));
            global_6[1u] = select(0f, 1f, (_e326 == 1u));
            let _e331 = local_38;
            global_7 = _e331;
            let _e332 = local_3;
            global_8 = _e332;
            break;
        }
    }
    return;
}

@vertex 
fn raster_vs(@builtin(vertex_index) param: u32) -> VertexOutput {
    global_2 = i32(param);
    function_();
    let _e7 = global_3;
    let _e8 = global_6;
    let _e9 = global_7;
    let _e10 = global_8;
    return VertexOutput(_e7, _e8, _e9, _e10);
}
