#version 300 es
// uv = tile origin + ((M_patch * world).xy / w * 0.5 + 0.5) * tile size,
// kept half a texel inside the patch's tile so that bilinear filtering
// never reads a neighbouring patch.
precision highp float;

in vec4 v_patch_clip;

uniform sampler2D u_atlas;  // G x G tiles, sRGB-encoded RGBA8 as the scene shader wrote them
uniform vec4 u_tile;        // the patch's tile in atlas uv: origin (x, y), size (z, w)
uniform vec2 u_half_texel;  // 0.5 / atlas size in texels
uniform vec3 u_tint;        // multiplies the encoded colour; (1, 1, 1) = a perfect mirror

out vec4 o_color;

void main() {
    vec2 local = v_patch_clip.xy / v_patch_clip.w * 0.5 + 0.5;
    vec2 uv = clamp(u_tile.xy + local * u_tile.zw, u_tile.xy + u_half_texel, u_tile.xy + u_tile.zw - u_half_texel);
    o_color = vec4(texture(u_atlas, uv).rgb * u_tint, 1.0);
}
