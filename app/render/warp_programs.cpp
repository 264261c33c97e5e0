#include "render/warp_programs.hpp"

#include "render/embedded_shaders.hpp"
#include "render/program_support.hpp"

#include <string>
#include <string_view>
#include <utility>

namespace render {
namespace {

using detail::link;
using Uniforms = detail::UniformFinder;

} // namespace

frustum::Result<LensRemapProgram> build_lens_remap_program(const gl::Functions& fn) {
    auto program = link(fn, shaders::lens_remap_vert, shaders::lens_remap_frag, "lens remap");
    if (!program) {
        return program.take_error();
    }
    LensRemapProgram p;
    p.program = std::move(*program);
    Uniforms u(fn, p.program, "lens remap");
    u.find(p.source, "u_source");
    u.find(p.source_rect_m, "u_source_rect_m");
    u.find(p.frame_px, "u_frame_px");
    u.find(p.half_size_m, "u_half_size_m");
    u.find(p.lens, "u_lens");
    if (auto status = u.status(); !status) {
        return status.take_error();
    }
    return p;
}

frustum::Result<NonAffineProgram> build_non_affine_program(const gl::Functions& fn, bool alpha_mask) {
    const std::string vertex = detail::insert_after_version(shaders::non_affine_vert, shaders::frustum_glsl);
    const std::string fragment = detail::insert_after_version(shaders::scene_frag, alpha_mask ? "#define ALPHA_MASK 1\n" : "");
    const char* name = alpha_mask ? "masked non-affine" : "non-affine";
    auto program = link(fn, vertex, fragment, name);
    if (!program) {
        return program.take_error();
    }
    NonAffineProgram p;
    p.program = std::move(*program);
    Uniforms u(fn, p.program, name);
    u.find(p.planes, "u_planes");
    u.find(p.z_near, "u_z_near");
    u.find(p.z_far, "u_z_far");
    u.find(p.base_color, "u_base_color");
    u.find(p.has_texture, "u_has_texture");
    u.find(p.base_color_texture, "u_base_color_texture");
    u.find(p.shading, "u_shading");
    u.find(p.double_sided, "u_double_sided");
    u.find(p.flat_normal_sign, "u_flat_normal_sign");
    u.find(p.to_light, "u_to_light");
    u.find(p.ambient, "u_ambient");
    u.find(p.diffuse, "u_diffuse");
    u.find(p.blend, "u_blend");
    if (alpha_mask) {
        u.find(p.alpha_cutoff, "u_alpha_cutoff");
    }
    if (auto status = u.status(); !status) {
        return status.take_error();
    }
    return p;
}

} // namespace render
