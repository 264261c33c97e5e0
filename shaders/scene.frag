#version 300 es
// Base colour (factor x vertex colour x texture) lit by one directional
// light plus ambient, in linear space, written sRGB-encoded to an RGBA8
// target. The program is also built with "#define CLIP_PLANE 1": a world-space
// clip plane by fragment discard, and with "#define ALPHA_MASK 1": glTF
// alphaMode MASK, discarding where alpha < alphaCutoff. They are separate
// programs because a shader that may discard loses early depth testing on
// tile-based mobile GPUs. alphaMode BLEND writes alpha for the blend unit.
precision highp float;

in vec3 v_world;
in vec3 v_normal;
in vec4 v_color;
in vec2 v_texcoord;

uniform vec4 u_base_color;               // material baseColorFactor (linear)
uniform bool u_has_texture;
uniform sampler2D u_base_color_texture;  // GL_SRGB8_ALPHA8: the sampler decodes to linear
uniform int u_shading;                   // 0: vertex normals, 1: flat (screen derivatives), 2: unlit
uniform bool u_double_sided;             // light back faces with the flipped normal
uniform float u_flat_normal_sign;        // -1 when the view is mirrored (pair flips winding)
uniform vec3 u_to_light;                 // unit vector towards the light, world space
uniform float u_ambient;
uniform float u_diffuse;
uniform bool u_blend;                    // alphaMode BLEND: output alpha = base alpha, else 1
#ifdef ALPHA_MASK
uniform float u_alpha_cutoff;            // alphaMode MASK: fragments with alpha below it are cut
#endif
#ifdef CLIP_PLANE
uniform vec4 u_clip_plane;               // world (a, b, c, d): keeps a x + b y + c z + d >= 0
#endif

out vec4 o_color;

vec3 linear_to_srgb(vec3 c) {
    vec3 low = c * 12.92;
    vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, vec3(lessThanEqual(c, vec3(0.0031308))));
}

void main() {
    // Derivatives first, in uniform control flow (before any discard).
    // cross(dFdx, dFdy) faces the viewer for an unmirrored view.
    vec3 flat_normal = u_flat_normal_sign * cross(dFdx(v_world), dFdy(v_world));
#ifdef CLIP_PLANE
    if (dot(u_clip_plane, vec4(v_world, 1.0)) < 0.0) {
        discard;
    }
#endif
    vec4 base = u_base_color * v_color;
    if (u_has_texture) {
        base *= texture(u_base_color_texture, v_texcoord);
    }
#ifdef ALPHA_MASK
    if (base.a < u_alpha_cutoff) {
        discard;
    }
#endif
    vec3 color = base.rgb;
    if (u_shading != 2) {
        vec3 n;
        if (u_shading == 0) {
            n = normalize(v_normal);
            if (u_double_sided && !gl_FrontFacing) {
                n = -n;
            }
        } else {
            n = normalize(flat_normal);
        }
        color *= u_ambient + u_diffuse * max(dot(n, u_to_light), 0.0);
    }
    // Blending happens on the sRGB-encoded values (the target is RGBA8).
    o_color = vec4(linear_to_srgb(clamp(color, 0.0, 1.0)), u_blend ? clamp(base.a, 0.0, 1.0) : 1.0);
}
