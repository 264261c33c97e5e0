// The shader programs (GLSL ES 3.00 from shaders/, embedded at build time)
// and their uniform locations, looked up once.
#pragma once

#include "render/warp_programs.hpp"

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

namespace render {

// shaders/scene.vert + scene.frag: lit geometry.
struct SceneProgram {
    gl::Program program;
    GLint view_projection = -1, model = -1, normal_matrix = -1, point_size_px = -1;
    GLint base_color = -1, has_texture = -1, base_color_texture = -1, shading = -1, double_sided = -1;
    GLint flat_normal_sign = -1, to_light = -1, ambient = -1, diffuse = -1, blend = -1;
    GLint clip_plane = -1;   // only in the CLIP_PLANE variants
    GLint alpha_cutoff = -1; // only in the ALPHA_MASK variants
};

// u_shading values of scene.frag.
enum class Shading : GLint {
    VertexNormals = 0,
    FlatNormals = 1, // from screen-space derivatives: triangles without normals
    Unlit = 2,       // points and lines without normals, KHR_materials_unlit
};

// shaders/mirror_composite.*: the mirror surface with a projective lookup.
struct MirrorCompositeProgram {
    gl::Program program;
    GLint view_projection = -1, model = -1, reflection_matrix = -1, reflection = -1, tint = -1;
};

// shaders/curved_mirror.*: a curved mirror's patch with a lookup in its atlas tile.
struct CurvedMirrorProgram {
    gl::Program program;
    GLint view_projection = -1, patch_matrix = -1, atlas = -1, tile = -1, half_texel = -1, tint = -1;
};

// shaders/line.*: flat-colour lines and points.
struct LineProgram {
    gl::Program program;
    GLint view_projection = -1, color = -1;
};

struct Programs {
    // scene.frag as [CLIP_PLANE][ALPHA_MASK]: [1][*] discard behind a world
    // plane, [*][1] discard below the material's alphaCutoff.
    SceneProgram scene[2][2];
    MirrorCompositeProgram mirror_composite;
    LineProgram line;
    CurvedMirrorProgram curved_mirror;
    LensRemapProgram lens_remap;    // lens reference (warp_programs.hpp)
    NonAffineProgram non_affine[2]; // non-affine effect (warp_programs.hpp), [ALPHA_MASK]

    const SceneProgram& scene_program(bool clip_plane, bool alpha_mask) const;
    const NonAffineProgram& non_affine_program(bool alpha_mask) const;

    // Compile and link errors carry the info log; a uniform the code sets
    // but the program lacks is an error too ("render::Programs::build():
    // scene program has no active uniform u_model").
    static frustum::Result<Programs> build(const gl::Functions& fn);
};

} // namespace render
