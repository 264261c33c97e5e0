#version 300 es
// uv = (M_patch * world).xy / w * 0.5 + 0.5 in the patch's view, kept half
// a texel inside it, then read from the strip of the view that holds its
// row (curved_pass.hpp): the patch is drawn once per strip, and each
// fragment is kept by one strip only.
precision highp float;

in vec4 v_patch_clip;

uniform sampler2D u_view;   // the strip, sRGB-encoded RGBA8 as the scene shader wrote it
uniform vec2 u_half_texel;  // 0.5 / view size in texels
uniform float u_view_rows;  // the view's height in texels
uniform vec4 u_strip;       // view rows [x, y) are this strip's; its texture holds rows z .. z + w
uniform vec3 u_tint;        // multiplies the encoded colour; (1, 1, 1) = a perfect mirror

out vec4 o_color;

void main() {
    vec2 local = v_patch_clip.xy / v_patch_clip.w * 0.5 + 0.5;
    vec2 uv = clamp(local, u_half_texel, vec2(1.0) - u_half_texel);
    float row = uv.y * u_view_rows;
    if (row < u_strip.x || row >= u_strip.y) {
        discard;
    }
    o_color = vec4(texture(u_view, vec2(uv.x, (row - u_strip.z) / u_strip.w)).rgb * u_tint, 1.0);
}
