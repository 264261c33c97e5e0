#version 300 es
// uv = (M_reflection * world).xy / w * 0.5 + 0.5, slightly tinted.
precision highp float;

in vec4 v_reflection_clip;

uniform sampler2D u_reflection; // sRGB-encoded RGBA8, as the scene shader wrote it
uniform vec3 u_tint;            // multiplies the encoded colour; (1, 1, 1) = a perfect mirror

out vec4 o_color;

void main() {
    vec2 uv = v_reflection_clip.xy / v_reflection_clip.w * 0.5 + 0.5;
    o_color = vec4(texture(u_reflection, uv).rgb * u_tint, 1.0);
}
