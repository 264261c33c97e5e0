#version 300 es
// Distance fog as a post pass: each pixel's world point decoded from the
// depth buffer with the inverse of the pair that wrote it
// (frustum_world_from_depth() of shaders/frustum.glsl, inserted after this
// line by render::FogPass), fogged by its distance from that pair's eye:
//   f = 1 - exp(-density max(distance - start, 0)),
// blended over the frame as (fog colour, alpha f). Pixels where the depth
// buffer still holds its clear value 1 (the sky) are left alone. Drawn with
// lens_remap.vert's full-screen triangle.
precision highp float;

uniform highp sampler2D u_depth; // the frame's depth, resolved to one sample, read with texelFetch
uniform mat4 u_inverse;          // inverse of the matrix that wrote the depth, in the GPU's range
uniform vec2 u_z_range;          // that pair's clip z of the near and far planes
uniform vec2 u_frame_px;         // the target's size
uniform vec3 u_eye;              // that pair's eye, world
uniform vec3 u_fog_color;        // sRGB-encoded, like the frame
uniform float u_density_per_m;
uniform float u_start_m;

out vec4 o_color;

void main() {
    float depth = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
    if (depth >= 1.0) {
        discard;
    }
    vec2 ndc_xy = gl_FragCoord.xy / u_frame_px * 2.0 - 1.0;
    vec3 world = frustum_world_from_depth(u_inverse, ndc_xy, depth, u_z_range.x, u_z_range.y);
    float distance_m = length(world - u_eye);
    float fog = 1.0 - exp(-u_density_per_m * max(distance_m - u_start_m, 0.0));
    o_color = vec4(u_fog_color, fog);
}
