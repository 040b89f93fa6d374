struct type_2 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_4 {
    member: array<u32>,
}

struct type_12 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_13 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: type_2,
    member_9: type_12,
}

struct type_14 {
    member: type_13,
}

struct VertexOutput {
    @builtin(position) member: vec4<f32>,
    @location(0) member_1: vec2<f32>,
    @location(1) @interpolate(flat) member_2: vec4<f32>,
    @location(2) @interpolate(flat) member_3: vec2<f32>,
}

@group(0) @binding(0) 
var<storage> global: type_4;
var<immediate> global_1: type_14;
var<private> global_2: i32;
var<private> global_3: i32;
var<private> global_4: vec4<f32> = vec4<f32>(0f, 0f, 0f, 1f);
var<private> global_5: vec2<f32>;
var<private> global_6: vec4<f32>;
var<private> global_7: vec2<f32>;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: i32;
    var local_3: u32;
    var local_4: bool;
    var local_5: f32;
    var local_6: f32;
    var local_7: f32;
    var local_8: f32;
    var local_9: u32;
    var local_10: u32;
    var local_11: f32;
    var local_12: u32;
    var local_13: f32;
    var local_14: u32;
    var local_15: u32;
    var local_16: f32;
    var local_17: f32;
    var phi_87_: bool;
    var phi_88_: bool;
    var phi_105_: bool;
    var phi_106_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e47 = global_2;
            let _e48 = global_3;
            local = arrayLength((&global.member));
            local_1 = (bitcast<u32>(_e48) * 8u);
            let _e53 = (_e47 % 6i);
            local_2 = _e53;
            if (_e53 == 1i) {
                phi_88_ = true;
            } else {
                let _e55 = local_2;
                if (_e55 == 3i) {
                    phi_87_ = true;
                } else {
                    let _e57 = local_2;
                    phi_87_ = (_e57 == 4i);
                }
                let _e60 = phi_87_;
                phi_88_ = _e60;
            }
            let _e62 = phi_88_;
            local_16 = select(-1f, 1f, _e62);
            let _e64 = local_2;
            if (_e64 == 2i) {
                phi_106_ = true;
            } else {
                let _e66 = local_2;
                if (_e66 == 4i) {
                    phi_105_ = true;
                } else {
                    let _e68 = local_2;
                    phi_105_ = (_e68 == 5i);
                }
                let _e71 = phi_105_;
                phi_106_ = _e71;
            }
            let _e73 = phi_106_;
            local_17 = select(-1f, 1f, _e73);
            let _e75 = local_1;
            let _e76 = (_e75 + 2u);
            local_3 = _e76;
            let _e77 = local;
            let _e78 = (_e76 < _e77);
            local_4 = _e78;
            if _e78 {
            } else {
                break;
            }
            let _e79 = local_3;
            let _e82 = global.member[_e79];
            let _e83 = bitcast<f32>(_e82);
            local_5 = _e83;
            let _e84 = (_e83 + 0.5f);
            let _e85 = local_16;
            local_6 = (_e85 * _e84);
            let _e87 = local_17;
            local_7 = (_e87 * _e84);
            let _e89 = local_1;
            let _e90 = local;
            if (_e89 < _e90) {
            } else {
                break;
            }
            let _e92 = local_1;
            let _e95 = global.member[_e92];
            let _e97 = local_6;
            local_8 = (bitcast<f32>(_e95) + _e97);
            let _e99 = local_1;
            let _e100 = (_e99 + 1u);
            local_9 = _e100;
            let _e101 = local;
            if (_e100 < _e101) {
            } else {
                break;
            }
            let _e103 = local_9;
            let _e106 = global.member[_e103];
            let _e108 = local_7;
            let _e110 = local_8;
            let _e114 = global_1.member.member;
            let _e121 = global_1.member.member_1;
            global_4 = vec4<f32>((((2f * _e110) / f32(_e114)) - 1f), (((2f * (bitcast<f32>(_e106) + _e108)) / f32(_e121)) - 1f), 0f, 1f);
            let _e127 = local_6;
            global_5[0u] = _e127;
            let _e129 = local_7;
            global_5[1u] = _e129;
            let _e130 = local_1;
            let _e131 = (_e130 + 4u);
            local_10 = _e131;
            let _e132 = local;
            if (_e131 < _e132) {
            } else {
                break;
            }
            let _e134 = local_10;
            let _e137 = global.member[_e134];
            local_11 = bitcast<f32>(_e137);
            let _e139 = local_1;
            let _e140 = (_e139 + 5u);
            local_12 = _e140;
            let _e141 = local;
            if (_e140 < _e141) {
            } else {
                break;
            }
            let _e143 = local_12;
            let _e146 = global.member[_e143];
            local_13 = bitcast<f32>(_e146);
            let _e148 = local_1;
            let _e149 = (_e148 + 6u);
            local_14 = _e149;
            let _e150 = local;
            if (_e149 < _e150) {
            } else {
                break;
            }
            let _e152 = local_14;
            let _e155 = global.member[_e152];
            let _e157 = local_11;
            let _e158 = local_13;
            global_6 = vec4<f32>(_e157, _e158, bitcast<f32>(_e155), 0f);
            let _e160 = local_4;
            if _e160 {
            } else {
                break;
            }
            let _e161 = local_1;
            let _e162 = (_e161 + 3u);
            local_15 = _e162;
            let _e163 = local;
            if (_e162 < _e163) {
            } else {
                break;
            }
            let _e165 = local_15;
            let _e168 = global.member[_e165];
            let _e171 = local_5;
            global_7[0u] = _e171;
            global_7[1u] = bitcast<f32>(_e168);
            break;
        }
    }
    return;
}

@vertex 
fn bokeh_vs(@builtin(vertex_index) param: u32, @builtin(instance_index) param_1: u32) -> VertexOutput {
    global_2 = i32(param);
    global_3 = i32(param_1);
    function_();
    let _e10 = global_4;
    let _e11 = global_5;
    let _e12 = global_6;
    let _e13 = global_7;
    return VertexOutput(_e10, _e11, _e12, _e13);
}
