#include "render/programs.hpp"

#include "render/embedded_shaders.hpp"

#include <string>
#include <utility>

namespace render {
namespace {

// Links `program` from `source` with its uniform table, or the error.
template <class P, class Link>
frustum::Result<P> built(P program, Link&& link) {
    if (auto status = link(program); !status) {
        return frustum::Error{status.error()};
    }
    return program;
}

std::string with_defines(std::string_view source, bool clip_plane, bool alpha_mask) {
    return detail::insert_after_version(source, std::string(clip_plane ? "#define CLIP_PLANE 1\n" : "") +
                                                    (alpha_mask ? "#define ALPHA_MASK 1\n" : ""));
}

} // namespace

// LitProgram: shaders/scene.frag.

frustum::Status LitProgram::link_lit(const gl::Functions& fn, const Source& source, std::vector<Uniform> uniforms,
                                     bool alpha_mask) {
    uniforms.insert(uniforms.end(), {{"u_base_color", &base_color_},
                                     {"u_has_texture", &has_texture_},
                                     {"u_base_color_texture", &base_color_texture_},
                                     {"u_shading", &shading_},
                                     {"u_double_sided", &double_sided_},
                                     {"u_flat_normal_sign", &flat_normal_sign_},
                                     {"u_to_light", &to_light_},
                                     {"u_ambient", &ambient_},
                                     {"u_diffuse", &diffuse_},
                                     {"u_blend", &blend_}});
    if (alpha_mask) {
        uniforms.push_back({"u_alpha_cutoff", &alpha_cutoff_});
    }
    return link(fn, source, uniforms);
}

void LitProgram::set_material(const GpuMaterial& material, const std::vector<gl::Texture>& textures) const {
    set(base_color_, material.base_color_factor);
    const bool textured = material.texture >= 0 && static_cast<std::size_t>(material.texture) < textures.size();
    set(has_texture_, textured ? 1 : 0);
    // set_base_color_texture_unit() chose the unit; the pass made it active.
    fn().BindTexture(GL_TEXTURE_2D, textured ? textures[static_cast<std::size_t>(material.texture)].id() : 0);
    set(double_sided_, material.double_sided ? 1 : 0);
    set(blend_, material.alpha_mode == scene::AlphaMode::Blend ? 1 : 0);
    if (alpha_cutoff_ >= 0) {
        set(alpha_cutoff_, material.alpha_cutoff);
    }
}

void LitProgram::set_shading(Shading shading) const { set(shading_, static_cast<GLint>(shading)); }

void LitProgram::set_light(const glm::vec3& to_light, float ambient, float diffuse) const {
    set(to_light_, glm::normalize(to_light));
    set(ambient_, ambient);
    set(diffuse_, diffuse);
}

void LitProgram::set_flat_normal_sign(float sign) const { set(flat_normal_sign_, sign); }
void LitProgram::set_base_color_texture_unit(int unit) const { set(base_color_texture_, unit); }

// SceneProgram: shaders/scene.vert + scene.frag.

frustum::Result<SceneProgram> SceneProgram::build(const gl::Functions& fn, bool clip_plane, bool alpha_mask) {
    const char* names[2][2] = {{"scene", "masked scene"}, {"clipped scene", "clipped masked scene"}};
    return built(SceneProgram{}, [&](SceneProgram& p) {
        std::vector<Uniform> uniforms = {{"u_view_projection", &p.view_projection_},
                                         {"u_model", &p.model_},
                                         {"u_normal_matrix", &p.normal_matrix_},
                                         {"u_point_size_px", &p.point_size_px_}};
        if (clip_plane) {
            uniforms.push_back({"u_clip_plane", &p.clip_plane_});
        }
        const Source source{names[clip_plane ? 1 : 0][alpha_mask ? 1 : 0], std::string(shaders::scene_vert),
                            with_defines(shaders::scene_frag, clip_plane, alpha_mask)};
        return p.link_lit(fn, source, std::move(uniforms), alpha_mask);
    });
}

void SceneProgram::set_view_projection(const glm::mat4& matrix) const { set(view_projection_, matrix); }
void SceneProgram::set_model(const glm::mat4& matrix) const { set(model_, matrix); }
void SceneProgram::set_normal_matrix(const glm::mat3& matrix) const { set(normal_matrix_, matrix); }
void SceneProgram::set_point_size_px(float size_px) const { set(point_size_px_, size_px); }
void SceneProgram::set_clip_plane(const glm::vec4& abcd) const { set(clip_plane_, abcd); }

// NonAffineProgram: shaders/non_affine.vert with frustum.glsl + scene.frag.

frustum::Result<NonAffineProgram> NonAffineProgram::build(const gl::Functions& fn, bool alpha_mask) {
    return built(NonAffineProgram{}, [&](NonAffineProgram& p) {
        const Source source{alpha_mask ? "masked non-affine" : "non-affine",
                            detail::insert_after_version(shaders::non_affine_vert, shaders::frustum_glsl),
                            with_defines(shaders::scene_frag, false, alpha_mask)};
        return p.link_lit(fn, source,
                          {{"u_planes", &p.planes_}, {"u_z_near", &p.z_near_}, {"u_z_far", &p.z_far_},
                           {"u_crop", &p.crop_}},
                          alpha_mask);
    });
}

void NonAffineProgram::set_planes(const glm::vec4 (&abcd)[6]) const { set(planes_, abcd, 6); }
void NonAffineProgram::set_crop(const glm::vec4& scale_offset) const { set(crop_, scale_offset); }
void NonAffineProgram::set_clip_z(float z_near, float z_far) const {
    set(z_near_, z_near);
    set(z_far_, z_far);
}

// MirrorCompositeProgram: shaders/mirror_composite.*.

frustum::Result<MirrorCompositeProgram> MirrorCompositeProgram::build(const gl::Functions& fn) {
    return built(MirrorCompositeProgram{}, [&](MirrorCompositeProgram& p) {
        return p.link(fn, {"mirror composite", std::string(shaders::mirror_composite_vert),
                           std::string(shaders::mirror_composite_frag)},
                      {{"u_view_projection", &p.view_projection_},
                       {"u_model", &p.model_},
                       {"u_reflection_matrix", &p.reflection_matrix_},
                       {"u_reflection", &p.reflection_},
                       {"u_tint", &p.tint_}});
    });
}

void MirrorCompositeProgram::set_view_projection(const glm::mat4& matrix) const { set(view_projection_, matrix); }
void MirrorCompositeProgram::set_model(const glm::mat4& matrix) const { set(model_, matrix); }
void MirrorCompositeProgram::set_reflection_matrix(const glm::mat4& matrix) const { set(reflection_matrix_, matrix); }
void MirrorCompositeProgram::set_reflection_texture_unit(int unit) const { set(reflection_, unit); }
void MirrorCompositeProgram::set_tint(const glm::vec3& rgb) const { set(tint_, rgb); }

// CurvedMirrorProgram: shaders/curved_mirror.*.

frustum::Result<CurvedMirrorProgram> CurvedMirrorProgram::build(const gl::Functions& fn) {
    return built(CurvedMirrorProgram{}, [&](CurvedMirrorProgram& p) {
        return p.link(fn, {"curved mirror", std::string(shaders::curved_mirror_vert),
                           std::string(shaders::curved_mirror_frag)},
                      {{"u_view_projection", &p.view_projection_},
                       {"u_patch_matrix", &p.patch_matrix_},
                       {"u_view", &p.view_},
                       {"u_view_rows", &p.view_rows_},
                       {"u_strip", &p.strip_},
                       {"u_half_texel", &p.half_texel_},
                       {"u_tint", &p.tint_}});
    });
}

void CurvedMirrorProgram::set_view_projection(const glm::mat4& matrix) const { set(view_projection_, matrix); }
void CurvedMirrorProgram::set_patch_matrix(const glm::mat4& matrix) const { set(patch_matrix_, matrix); }
void CurvedMirrorProgram::set_view_texture_unit(int unit) const { set(view_, unit); }
void CurvedMirrorProgram::set_view_rows(float rows) const { set(view_rows_, rows); }
void CurvedMirrorProgram::set_strip(const glm::vec4& rows) const { set(strip_, rows); }
void CurvedMirrorProgram::set_half_texel(const glm::vec2& uv) const { set(half_texel_, uv); }
void CurvedMirrorProgram::set_tint(const glm::vec3& rgb) const { set(tint_, rgb); }

// LineProgram: shaders/line.*.

frustum::Result<LineProgram> LineProgram::build(const gl::Functions& fn) {
    return built(LineProgram{}, [&](LineProgram& p) {
        return p.link(fn, {"line", std::string(shaders::line_vert), std::string(shaders::line_frag)},
                      {{"u_view_projection", &p.view_projection_}, {"u_color", &p.color_}});
    });
}

void LineProgram::set_view_projection(const glm::mat4& matrix) const { set(view_projection_, matrix); }
void LineProgram::set_color(const glm::vec4& rgba) const { set(color_, rgba); }

// Programs.

const SceneProgram& Programs::scene_program(bool clip_plane, bool alpha_mask) const {
    return scene[clip_plane ? 1 : 0][alpha_mask ? 1 : 0];
}

const NonAffineProgram& Programs::non_affine_program(bool alpha_mask) const {
    return non_affine[alpha_mask ? 1 : 0];
}

frustum::Result<Programs> Programs::build(const gl::Functions& fn) {
    Programs programs;
    frustum::Status status;
    // Each row builds one program into its slot; after the first error
    // nothing more is built.
    const auto step = [&status](auto& slot, const auto& build) {
        if (!status) {
            return;
        }
        auto program = build();
        if (!program) {
            status = frustum::Error{program.error()};
            return;
        }
        slot = std::move(*program);
    };
    for (const bool clip : {false, true}) {
        for (const bool mask : {false, true}) {
            step(programs.scene[clip ? 1 : 0][mask ? 1 : 0], [&] { return SceneProgram::build(fn, clip, mask); });
        }
    }
    for (const bool mask : {false, true}) {
        step(programs.non_affine[mask ? 1 : 0], [&] { return NonAffineProgram::build(fn, mask); });
    }
    step(programs.mirror_composite, [&] { return MirrorCompositeProgram::build(fn); });
    step(programs.line, [&] { return LineProgram::build(fn); });
    step(programs.curved_mirror, [&] { return CurvedMirrorProgram::build(fn); });
    if (!status) {
        return frustum::Error{status.error()};
    }
    return programs;
}

} // namespace render
