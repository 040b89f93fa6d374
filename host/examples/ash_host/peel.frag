#version 450
// dof: depth peeling with your own passes (dof_core::frame::RendererPeel).
// The bound of every pixel, written by the library before each pass (one float a pixel, row-major
// over the attachments' width).
layout(std430, set = 0, binding = 0) readonly buffer DofPeelBound { float dof_peel_bound[]; };

// Whether a fragment of depth-buffer value `frag_depth` (gl_FragCoord.z) belongs to this pass:
// beyond `bound` (standard planes: bound >= 0, keep frag_depth > bound; reversed planes: bound < 0,
// keep frag_depth < -bound; -inf keeps all, +inf and NaN keep none).
bool dof_peel_keep(float frag_depth, float bound) {
    return bound < 0.0 ? frag_depth < -bound : frag_depth > bound;
}

// At the top of the fragment shader (`width`: the attachments' width):
//   uint pixel = uint(gl_FragCoord.y) * width + uint(gl_FragCoord.x);
//   if (!dof_peel_keep(gl_FragCoord.z, dof_peel_bound[pixel])) discard;

// The example host's own peel pass: its colour (rgb, coverage) for the fragments beyond the bound.
layout(push_constant) uniform Push { mat4 view_proj; uint width; } push;
layout(location = 0) in vec4 v_colour;
layout(location = 0) out vec4 colour;

void main() {
    uint pixel = uint(gl_FragCoord.y) * push.width + uint(gl_FragCoord.x);
    if (!dof_peel_keep(gl_FragCoord.z, dof_peel_bound[pixel])) discard;
    colour = v_colour;
}
