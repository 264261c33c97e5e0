// The shader programs (GLSL ES 3.00 from shaders/, embedded at build time)
// as small classes, after Magnum's Shaders::*GL: each links its shaders,
// finds its uniforms from one table (programs.cpp), keeps their locations
// private and offers typed setters. Call use() before the setters.
//
// A new program is one class here with its table in programs.cpp, plus one
// member of Programs when every Renderer needs it; a program only a
// reference uses is built by that reference (lens_reference.cpp).
#pragma once

#include "render/gpu_scene.hpp"
#include "render/program_support.hpp"

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

#include <glm/glm.hpp>

#include <vector>

namespace render {

// u_shading values of scene.frag.
enum class Shading : GLint {
    VertexNormals = 0,
    FlatNormals = 1, // from screen-space derivatives: triangles without normals
    Unlit = 2,       // points and lines without normals, KHR_materials_unlit
};

// The uniforms of shaders/scene.frag, shared by every program that shades
// with it (the scene and the non-affine programs): material, shading mode
// and the one directional light plus ambient.
class LitProgram : public ShaderProgram {
public:
    // Base colour, texture (bound to unit 0; none when the index is out of
    // `textures`), double-sidedness, blending and, in the ALPHA_MASK
    // variants, the alpha cutoff.
    void set_material(const GpuMaterial& material, const std::vector<gl::Texture>& textures) const;
    void set_shading(Shading shading) const;
    // `to_light` is normalized here.
    void set_light(const glm::vec3& to_light, float ambient, float diffuse) const;
    // -1 where a mirrored view turns cross(dFdx, dFdy) away from the viewer.
    void set_flat_normal_sign(float sign) const;
    void set_base_color_texture_unit(int unit) const;

protected:
    // link() with the scene.frag uniforms added to `uniforms`;
    // alpha_mask: the fragment shader was built with ALPHA_MASK.
    frustum::Status link_lit(const gl::Functions& fn, const Source& source, std::vector<Uniform> uniforms,
                             bool alpha_mask);

private:
    GLint base_color_ = -1, has_texture_ = -1, base_color_texture_ = -1, shading_ = -1, double_sided_ = -1;
    GLint flat_normal_sign_ = -1, to_light_ = -1, ambient_ = -1, diffuse_ = -1, blend_ = -1;
    GLint alpha_cutoff_ = -1; // only in the ALPHA_MASK variants
};

// shaders/scene.vert + scene.frag: lit geometry, optionally clipped by a
// world plane (CLIP_PLANE) and alpha-tested (ALPHA_MASK).
class SceneProgram : public LitProgram {
public:
    static frustum::Result<SceneProgram> build(const gl::Functions& fn, bool clip_plane, bool alpha_mask);

    void set_view_projection(const glm::mat4& matrix) const;
    void set_model(const glm::mat4& matrix) const;
    void set_normal_matrix(const glm::mat3& matrix) const;
    void set_point_size_px(float size_px) const;
    // CLIP_PLANE variants only: fragments with dot(abcd, world) < 0 are discarded.
    void set_clip_plane(const glm::vec4& abcd) const;

private:
    GLint view_projection_ = -1, model_ = -1, normal_matrix_ = -1, point_size_px_ = -1;
    GLint clip_plane_ = -1; // only in the CLIP_PLANE variants
};

// shaders/non_affine.vert (with shaders/frustum.glsl) + scene.frag: eq. 36
// per vertex, lit as the scene.
class NonAffineProgram : public LitProgram {
public:
    // alpha_mask: scene.frag with ALPHA_MASK (glTF alphaMode MASK).
    static frustum::Result<NonAffineProgram> build(const gl::Functions& fn, bool alpha_mask);

    // The crossed-slits frustum's six planes (frustum::NonAffineFrustum::plane()).
    void set_planes(const glm::vec4 (&abcd)[6]) const;
    // Clip z of the near and far planes in the GPU's depth range.
    void set_clip_z(float z_near, float z_far) const;
    // NDC xy -> xy * scale_offset.xy + scale_offset.zw: the crop to a poster
    // tile (window_ndc_scale_offset()); (1, 1, 0, 0) for the whole frame.
    void set_crop(const glm::vec4& scale_offset) const;

private:
    GLint planes_ = -1, z_near_ = -1, z_far_ = -1, crop_ = -1;
};

// shaders/mirror_composite.*: the mirror surface with a projective lookup.
class MirrorCompositeProgram : public ShaderProgram {
public:
    static frustum::Result<MirrorCompositeProgram> build(const gl::Functions& fn);

    void set_view_projection(const glm::mat4& matrix) const;
    void set_model(const glm::mat4& matrix) const;
    void set_reflection_matrix(const glm::mat4& matrix) const;
    void set_reflection_texture_unit(int unit) const;
    void set_tint(const glm::vec3& rgb) const;

private:
    GLint view_projection_ = -1, model_ = -1, reflection_matrix_ = -1, reflection_ = -1, tint_ = -1;
};

// shaders/curved_mirror.*: a curved mirror's patch with a lookup in its view (one texture per patch).
class CurvedMirrorProgram : public ShaderProgram {
public:
    static frustum::Result<CurvedMirrorProgram> build(const gl::Functions& fn);

    void set_view_projection(const glm::mat4& matrix) const;
    void set_patch_matrix(const glm::mat4& matrix) const;
    void set_view_texture_unit(int unit) const;
    // The view's height in texel rows, and the strip bound: its rows
    // [x, y) of the view, held by texture rows from z on, w of them.
    void set_view_rows(float rows) const;
    void set_strip(const glm::vec4& rows) const;
    void set_half_texel(const glm::vec2& uv) const;
    void set_tint(const glm::vec3& rgb) const;

private:
    GLint view_projection_ = -1, patch_matrix_ = -1, view_ = -1, view_rows_ = -1, strip_ = -1, half_texel_ = -1, tint_ = -1;
};

// shaders/line.*: flat-colour lines and points.
class LineProgram : public ShaderProgram {
public:
    static frustum::Result<LineProgram> build(const gl::Functions& fn);

    void set_view_projection(const glm::mat4& matrix) const;
    void set_color(const glm::vec4& rgba) const;

private:
    GLint view_projection_ = -1, color_ = -1;
};

// The programs every Renderer draws with.
struct Programs {
    // scene.frag as [CLIP_PLANE][ALPHA_MASK]: [1][*] discard behind a world
    // plane, [*][1] discard below the material's alphaCutoff.
    SceneProgram scene[2][2];
    NonAffineProgram non_affine[2]; // [ALPHA_MASK]
    MirrorCompositeProgram mirror_composite;
    LineProgram line;
    CurvedMirrorProgram curved_mirror;

    const SceneProgram& scene_program(bool clip_plane, bool alpha_mask) const;
    const NonAffineProgram& non_affine_program(bool alpha_mask) const;

    // Every program above, or the first error of ShaderProgram::link().
    static frustum::Result<Programs> build(const gl::Functions& fn);
};

} // namespace render
