#include "render/programs.hpp"

#include "render/embedded_shaders.hpp"
#include "render/program_support.hpp"

#include <string>
#include <string_view>
#include <utility>

namespace render {
namespace {

using detail::link;
using detail::UniformFinder;

frustum::Result<SceneProgram> build_scene(const gl::Functions& fn, bool clip_plane, bool alpha_mask) {
    const char* names[2][2] = {{"scene", "masked scene"}, {"clipped scene", "clipped masked scene"}};
    const char* name = names[clip_plane ? 1 : 0][alpha_mask ? 1 : 0];
    const std::string defines = std::string(clip_plane ? "#define CLIP_PLANE 1\n" : "") +
                                (alpha_mask ? "#define ALPHA_MASK 1\n" : "");
    const std::string fragment = detail::insert_after_version(shaders::scene_frag, defines);
    auto program = link(fn, shaders::scene_vert, fragment, name);
    if (!program) {
        return program.take_error();
    }
    SceneProgram p;
    p.program = std::move(*program);
    UniformFinder u(fn, p.program, name);
    u.find(p.view_projection, "u_view_projection");
    u.find(p.model, "u_model");
    u.find(p.normal_matrix, "u_normal_matrix");
    u.find(p.point_size_px, "u_point_size_px");
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
    if (clip_plane) {
        u.find(p.clip_plane, "u_clip_plane");
    }
    if (alpha_mask) {
        u.find(p.alpha_cutoff, "u_alpha_cutoff");
    }
    if (auto status = u.status(); !status) {
        return status.take_error();
    }
    return p;
}

frustum::Result<MirrorCompositeProgram> build_mirror_composite(const gl::Functions& fn) {
    auto program = link(fn, shaders::mirror_composite_vert, shaders::mirror_composite_frag, "mirror composite");
    if (!program) {
        return program.take_error();
    }
    MirrorCompositeProgram p;
    p.program = std::move(*program);
    UniformFinder u(fn, p.program, "mirror composite");
    u.find(p.view_projection, "u_view_projection");
    u.find(p.model, "u_model");
    u.find(p.reflection_matrix, "u_reflection_matrix");
    u.find(p.reflection, "u_reflection");
    u.find(p.tint, "u_tint");
    if (auto status = u.status(); !status) {
        return status.take_error();
    }
    return p;
}

frustum::Result<LineProgram> build_line(const gl::Functions& fn) {
    auto program = link(fn, shaders::line_vert, shaders::line_frag, "line");
    if (!program) {
        return program.take_error();
    }
    LineProgram p;
    p.program = std::move(*program);
    UniformFinder u(fn, p.program, "line");
    u.find(p.view_projection, "u_view_projection");
    u.find(p.color, "u_color");
    if (auto status = u.status(); !status) {
        return status.take_error();
    }
    return p;
}

frustum::Result<CurvedMirrorProgram> build_curved_mirror(const gl::Functions& fn) {
    auto program = link(fn, shaders::curved_mirror_vert, shaders::curved_mirror_frag, "curved mirror");
    if (!program) {
        return program.take_error();
    }
    CurvedMirrorProgram p;
    p.program = std::move(*program);
    UniformFinder u(fn, p.program, "curved mirror");
    u.find(p.view_projection, "u_view_projection");
    u.find(p.patch_matrix, "u_patch_matrix");
    u.find(p.atlas, "u_atlas");
    u.find(p.tile, "u_tile");
    u.find(p.half_texel, "u_half_texel");
    u.find(p.tint, "u_tint");
    if (auto status = u.status(); !status) {
        return status.take_error();
    }
    return p;
}

} // namespace

const SceneProgram& Programs::scene_program(bool clip_plane, bool alpha_mask) const {
    return scene[clip_plane ? 1 : 0][alpha_mask ? 1 : 0];
}

const NonAffineProgram& Programs::non_affine_program(bool alpha_mask) const {
    return non_affine[alpha_mask ? 1 : 0];
}

frustum::Result<Programs> Programs::build(const gl::Functions& fn) {
    Programs programs;
    for (const bool clip : {false, true}) {
        for (const bool mask : {false, true}) {
            auto scene = build_scene(fn, clip, mask);
            if (!scene) {
                return scene.take_error();
            }
            programs.scene[clip ? 1 : 0][mask ? 1 : 0] = std::move(*scene);
        }
    }
    for (const bool mask : {false, true}) {
        auto non_affine = build_non_affine_program(fn, mask);
        if (!non_affine) {
            return non_affine.take_error();
        }
        programs.non_affine[mask ? 1 : 0] = std::move(*non_affine);
    }
    auto mirror_composite = build_mirror_composite(fn);
    if (!mirror_composite) {
        return mirror_composite.take_error();
    }
    programs.mirror_composite = std::move(*mirror_composite);
    auto line = build_line(fn);
    if (!line) {
        return line.take_error();
    }
    programs.line = std::move(*line);
    auto curved_mirror = build_curved_mirror(fn);
    if (!curved_mirror) {
        return curved_mirror.take_error();
    }
    programs.curved_mirror = std::move(*curved_mirror);
    auto lens_remap = build_lens_remap_program(fn);
    if (!lens_remap) {
        return lens_remap.take_error();
    }
    programs.lens_remap = std::move(*lens_remap);
    return programs;
}

} // namespace render
