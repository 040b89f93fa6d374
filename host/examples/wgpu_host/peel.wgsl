// dof: depth peeling with your own passes (dof_core::frame::RendererPeel), in WGSL.
// The bound of every pixel, written by the library before each pass (one f32 a pixel, row-major
// over the attachments' width).
@group(0) @binding(0) var<storage, read> dof_peel_bound: array<f32>;

// Whether a fragment of depth-buffer value `frag_depth` (@builtin(position).z) belongs to this
// pass: beyond `bound` (standard planes: bound >= 0, keep frag_depth > bound; reversed planes:
// bound < 0, keep frag_depth < -bound; -inf keeps all, +inf and NaN keep none).
fn dof_peel_keep(frag_depth: f32, bound: f32) -> bool {
    return select(frag_depth > bound, frag_depth < -bound, bound < 0.0);
}

// At the top of the fragment shader (`position`: @builtin(position); `width`: the attachments' width):
//   let pixel = u32(position.y) * width + u32(position.x);
//   if !dof_peel_keep(position.z, dof_peel_bound[pixel]) { discard; }

// The example's own peel pass: coloured triangles (rgb, coverage) through a view-projection matrix.
struct Push {
    view_proj: mat4x4<f32>,
    width: u32,
}
var<immediate> push: Push;

struct Varyings {
    @builtin(position) position: vec4<f32>,
    @location(0) colour: vec4<f32>,
}

@vertex
fn vs(@location(0) position: vec3<f32>, @location(1) colour: vec4<f32>) -> Varyings {
    return Varyings(push.view_proj * vec4<f32>(position, 1.0), colour);
}

@fragment
fn fs(v: Varyings) -> @location(0) vec4<f32> {
    let pixel = u32(v.position.y) * push.width + u32(v.position.x);
    if !dof_peel_keep(v.position.z, dof_peel_bound[pixel]) {
        discard;
    }
    return v.colour;
}
