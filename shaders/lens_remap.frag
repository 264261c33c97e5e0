#version 300 es
// The per-pixel lens reference (paper section 5.4): every ray passes through
// the eye, so the lens image is a 2D remap of the unwarped one. The pixel
// whose centre is the near-plane point X shows the unwarped view at
// X' = lens_warp(X) (eq. 34), looked up in a texture rendered through the
// near-plane rectangle u_source_rect_m. Nested rectangles are drawn from the
// widest to the narrowest (reference::draw_lens_reference()); a pixel whose X'
// falls outside this one keeps what a wider one wrote. This is a second
// implementation of eq. 34, independent of frustum::lens_warp() and of the
// tile frustums.
precision highp float;

uniform sampler2D u_source;    // the unwarped view, sRGB-encoded RGBA8, bilinear
uniform vec4 u_source_rect_m;  // (x0, y0, x1, y1): the texture's rectangle, metres on the near plane
uniform vec2 u_frame_px;       // target width and height
uniform vec2 u_half_size_m;    // near-plane half width and half height
uniform vec4 u_lens;           // centre C (x, y) in metres, radius R in metres, power p

out vec4 o_color;

// eq. 34: v = X - C, r = |v| / R, X' = C + R r^p v / |v| (X' = C at C).
vec2 lens_warp(vec2 point_m, vec4 lens) {
    vec2 v = point_m - lens.xy;
    float length_m = length(v);
    if (length_m == 0.0) {
        return lens.xy;
    }
    float r = length_m / lens.z;
    return lens.xy + (lens.z * pow(r, lens.w) / length_m) * v;
}

bool inside(vec2 p, vec4 rect) {
    return all(greaterThanEqual(p, rect.xy)) && all(lessThanEqual(p, rect.zw));
}

void main() {
    // Pixel centre -> near-plane metres (origin at the centre, y up), as
    // frustum::lens_tiles() places pixel corners.
    vec2 point_m = (gl_FragCoord.xy / u_frame_px * 2.0 - 1.0) * u_half_size_m;
    vec2 warped_m = lens_warp(point_m, u_lens);
    // Bilinear taps stay on real texels at least half a texel inside the edge.
    vec2 half_texel_m = 0.5 * (u_source_rect_m.zw - u_source_rect_m.xy) / vec2(textureSize(u_source, 0));
    vec4 valid_m = vec4(u_source_rect_m.xy + half_texel_m, u_source_rect_m.zw - half_texel_m);
    if (!inside(warped_m, valid_m)) {
        discard;
    }
    vec2 uv = (warped_m - u_source_rect_m.xy) / (u_source_rect_m.zw - u_source_rect_m.xy);
    o_color = vec4(texture(u_source, uv).rgb, 1.0);
}
