struct type_3 {
    member: f32,
    member_1: f32,
    member_2: f32,
    member_3: f32,
}

struct type_5 {
    member: array<u32>,
}

struct type_11 {
    member: u32,
    member_1: f32,
    member_2: array<f32, 2>,
    member_3: array<f32, 2>,
    member_4: f32,
    member_5: f32,
    member_6: u32,
}

struct type_12 {
    member: u32,
    member_1: u32,
    member_2: u32,
    member_3: u32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: type_3,
    member_9: type_11,
}

struct type_13 {
    member: type_12,
}

var<private> global: u32;
var<immediate> global_1: type_13;
@group(0) @binding(0) 
var<storage, read_write> global_2: type_5;

fn function_() {
    var local: u32;
    var local_1: u32;
    var local_2: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e14 = global;
            local = arrayLength((&global_2.member));
            if (_e14 == 0u) {
                let _e18 = local;
                if (4u < _e18) {
                } else {
                    break;
                }
                let _e22 = global_2.member[4u];
                local_1 = _e22;
                let _e23 = local;
                if (0u < _e23) {
                } else {
                    break;
                }
                global_2.member[0u] = 6u;
                let _e29 = global_1.member.member_2;
                let _e30 = local_1;
                let _e32 = local_1;
                local_2 = select(_e29, _e32, (_e30 < _e29));
                let _e34 = local;
                if (1u < _e34) {
                } else {
                    break;
                }
                let _e38 = local_2;
                global_2.member[1u] = _e38;
                let _e39 = local;
                if (2u < _e39) {
                } else {
                    break;
                }
                global_2.member[2u] = 0u;
                let _e43 = local;
                if (3u < _e43) {
                } else {
                    break;
                }
                global_2.member[3u] = 0u;
            }
            storageBarrier();
            workgroupBarrier();
            break;
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn bokeh_args(@builtin(local_invocation_index) param: u32) {
    global = param;
    function_();
}
