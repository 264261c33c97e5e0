// The programs of the lens reference and the non-affine effect (shaders
// lens_remap.*, non_affine.vert + scene.frag, with shaders/frustum.glsl
// inserted after the #version line), built with the others in
// render::Programs::build().
#pragma once

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

namespace render {

// shaders/lens_remap.*: the per-pixel lens reference (eq. 34 in GLSL).
struct LensRemapProgram {
    gl::Program program;
    GLint source = -1, source_rect_m = -1, frame_px = -1, half_size_m = -1, lens = -1;
};

// shaders/non_affine.vert + scene.frag: eq. 36 per vertex, lit as the scene.
struct NonAffineProgram {
    gl::Program program;
    GLint planes = -1, z_near = -1, z_far = -1;
    GLint base_color = -1, has_texture = -1, base_color_texture = -1, shading = -1, double_sided = -1;
    GLint flat_normal_sign = -1, to_light = -1, ambient = -1, diffuse = -1, blend = -1;
    GLint alpha_cutoff = -1; // only with alpha_mask
};

// Errors as render::Programs::build()'s: the stage and info log, or the
// first uniform the program lacks.
frustum::Result<LensRemapProgram> build_lens_remap_program(const gl::Functions& fn);
// alpha_mask: scene.frag with ALPHA_MASK (glTF alphaMode MASK).
frustum::Result<NonAffineProgram> build_non_affine_program(const gl::Functions& fn, bool alpha_mask);

} // namespace render
