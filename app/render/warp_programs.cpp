#include "render/warp_programs.hpp"

#include "render/embedded_shaders.hpp"

#include <string>
#include <string_view>
#include <utility>

namespace render {
namespace {

constexpr const char* kBuild = "render::Programs::build()";

// `snippet` inserted after the "#version" line, which must stay first.
std::string with_snippet(std::string_view source, std::string_view snippet) {
    const std::size_t line_end = source.find('\n') + 1;
    return std::string(source.substr(0, line_end)) + std::string(snippet) + std::string(source.substr(line_end));
}

frustum::Result<gl::Program> link(const gl::Functions& fn, std::string_view vertex, std::string_view fragment,
                                  const char* name) {
    auto program = gl::Program::build(fn, vertex, fragment);
    if (!program) {
        return frustum::Error{std::string(kBuild) + ": " + name + " program: " + program.error()};
    }
    return program;
}

// Looks up uniforms; status() names the first that is missing.
class Uniforms {
public:
    Uniforms(const gl::Functions& fn, const gl::Program& program, const char* name)
        : fn_(fn), program_(program), name_(name) {}
    void find(GLint& location, const char* uniform) {
        location = fn_.GetUniformLocation(program_.id(), uniform);
        if (location < 0 && missing_.empty()) {
            missing_ = uniform;
        }
    }
    frustum::Status status() const {
        if (missing_.empty()) {
            return {};
        }
        return frustum::Error{std::string(kBuild) + ": " + name_ + " program has no active uniform " + missing_};
    }

private:
    const gl::Functions& fn_;
    const gl::Program& program_;
    const char* name_;
    std::string missing_;
};

} // namespace

frustum::Result<LensRemapProgram> build_lens_remap_program(const gl::Functions& fn) {
    auto program = link(fn, shaders::lens_remap_vert, shaders::lens_remap_frag, "lens remap");
    if (!program) {
        return frustum::Error{program.error()};
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
        return frustum::Error{status.error()};
    }
    return p;
}

frustum::Result<NonAffineProgram> build_non_affine_program(const gl::Functions& fn) {
    const std::string vertex = with_snippet(shaders::non_affine_vert, shaders::frustum_glsl);
    auto program = link(fn, vertex, shaders::scene_frag, "non-affine");
    if (!program) {
        return frustum::Error{program.error()};
    }
    NonAffineProgram p;
    p.program = std::move(*program);
    Uniforms u(fn, p.program, "non-affine");
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
    if (auto status = u.status(); !status) {
        return frustum::Error{status.error()};
    }
    return p;
}

} // namespace render
