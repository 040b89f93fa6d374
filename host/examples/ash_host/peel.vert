#version 450
// The example host's own peel pass: coloured triangles through a view-projection matrix.
layout(push_constant) uniform Push { mat4 view_proj; uint width; } push;
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour; // rgb, coverage
layout(location = 0) out vec4 v_colour;

void main() {
    v_colour = colour;
    gl_Position = push.view_proj * vec4(position, 1.0);
}
