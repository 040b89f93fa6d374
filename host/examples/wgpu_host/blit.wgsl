// The example's own pass that shows the depth of field's output in a window: a full-screen
// triangle loading the RGBA32F texels, through a plain x / (1 + x) curve (the surface's sRGB
// encoding, where it has one, is the hardware's).
@group(0) @binding(0) var image: texture_2d<f32>;

@vertex
fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
}

@fragment
fn fs(@builtin(position) at: vec4<f32>) -> @location(0) vec4<f32> {
    let c = max(textureLoad(image, vec2<i32>(at.xy), 0).rgb, vec3<f32>(0.0));
    return vec4<f32>(c / (1.0 + c), 1.0);
}
