// A scene::Scene uploaded to GL: per primitive one vertex buffer
// (interleaved), one index buffer and one vertex array; per image one
// mipmapped sRGB texture. Every object is an RAII gl:: handle, so destroying
// the GpuScene (with its context current) deletes all of them.
#pragma once

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace render {

// Vertex attribute locations, as every shader declares them (layout(location = N)).
enum AttributeLocation : GLuint {
    kPositionLocation = 0,
    kNormalLocation = 1,
    kColorLocation = 2,
    kTexcoordLocation = 3,
};

// A vertex array whose one attribute, kPositionLocation, is a buffer of
// glm::vec3 (lines, overlay triangles), both bound on return. Errors are
// gl::Buffer's or gl::VertexArray's after "<caller>: ".
struct PositionBuffer {
    gl::Buffer buffer;
    gl::VertexArray vertex_array;
};
frustum::Result<PositionBuffer> create_position_buffer(const gl::Functions& fn, const std::string& caller);

struct GpuPrimitive {
    gl::VertexArray vertex_array;
    gl::Buffer vertex_buffer;
    gl::Buffer index_buffer;
    GLenum mode = GL_TRIANGLES;         // the glTF mode as a GL primitive type
    GLsizei index_count = 0;
    GLenum index_type = GL_UNSIGNED_INT; // GL_UNSIGNED_SHORT when every index fits
    int material = -1;                  // into GpuScene::material(); -1 = default material
    bool has_normals = false;
    bool has_colors = false;
    bool has_texcoords = false;
    glm::vec3 center{0.0f}; // of the positions' bounding box, object space: sorts blended primitives
    glm::vec3 low{0.0f}, high{0.0f}; // that bounding box (object space): frustum culling
};

using GpuMesh = std::vector<GpuPrimitive>;

struct GpuMaterial {
    glm::vec4 base_color_factor{1.0f};
    int texture = -1; // into GpuScene::textures(), -1 = none
    bool double_sided = false;
    scene::AlphaMode alpha_mode = scene::AlphaMode::Opaque;
    float alpha_cutoff = 0.5f; // MASK
    bool unlit = false;        // KHR_materials_unlit
};

class GpuScene {
public:
    // Errors name the object, e.g.
    // "render::GpuScene::upload(): image 2 is 9000x9000, larger than GL_MAX_TEXTURE_SIZE=8192".
    static frustum::Result<GpuScene> upload(const gl::Functions& fn, const scene::Scene& scene);

    const std::vector<GpuMesh>& meshes() const { return meshes_; }
    const std::vector<scene::Instance>& instances() const { return instances_; }
    // Places instance `index` (< instances().size()) anew, e.g. a mirror the
    // user moves (Renderer::move_mirror()).
    void set_instance_world(std::size_t index, const glm::mat4& world) { instances_.at(index).world = world; }
    const std::vector<gl::Texture>& textures() const { return textures_; }
    // index -1 (or none given by the file): glTF's default material, white and single-sided.
    const GpuMaterial& material(int index) const;

private:
    GpuScene() = default;

    std::vector<GpuMesh> meshes_;
    std::vector<scene::Instance> instances_;
    std::vector<gl::Texture> textures_;
    std::vector<GpuMaterial> materials_;
    GpuMaterial default_material_;
};

// Binds the primitive's vertex array, sets the constant values of the
// attributes it lacks (normal (0, 0, 1), colour white, texcoord (0, 0):
// these are context state, not vertex-array state) and draws it.
void draw_primitive(const gl::Functions& fn, const GpuPrimitive& primitive);

} // namespace render
