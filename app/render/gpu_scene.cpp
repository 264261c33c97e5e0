#include "render/gpu_scene.hpp"

#include <gl/errors.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

namespace render {
namespace {

constexpr const char* kUpload = "render::GpuScene::upload()";

GLenum gl_mode(scene::PrimitiveMode mode) {
    switch (mode) {
    case scene::PrimitiveMode::Points: return GL_POINTS;
    case scene::PrimitiveMode::Lines: return GL_LINES;
    case scene::PrimitiveMode::LineLoop: return GL_LINE_LOOP;
    case scene::PrimitiveMode::LineStrip: return GL_LINE_STRIP;
    case scene::PrimitiveMode::Triangles: return GL_TRIANGLES;
    case scene::PrimitiveMode::TriangleStrip: return GL_TRIANGLE_STRIP;
    case scene::PrimitiveMode::TriangleFan: return GL_TRIANGLE_FAN;
    }
    return GL_TRIANGLES;
}

// Interleaved floats: position, then normal, colour and texcoord when present.
struct VertexLayout {
    bool normals, colors, texcoords;
    int floats_per_vertex() const { return 3 + (normals ? 3 : 0) + (colors ? 4 : 0) + (texcoords ? 2 : 0); }
};

std::vector<float> interleave(const scene::Primitive& p, const VertexLayout& layout) {
    std::vector<float> data;
    data.reserve(p.positions.size() * static_cast<std::size_t>(layout.floats_per_vertex()));
    for (std::size_t i = 0; i < p.positions.size(); ++i) {
        data.insert(data.end(), {p.positions[i].x, p.positions[i].y, p.positions[i].z});
        if (layout.normals) {
            data.insert(data.end(), {p.normals[i].x, p.normals[i].y, p.normals[i].z});
        }
        if (layout.colors) {
            data.insert(data.end(), {p.colors[i].r, p.colors[i].g, p.colors[i].b, p.colors[i].a});
        }
        if (layout.texcoords) {
            data.insert(data.end(), {p.texcoords[i].x, p.texcoords[i].y});
        }
    }
    return data;
}

void set_attribute_pointers(const gl::Functions& fn, const VertexLayout& layout) {
    const GLsizei stride = layout.floats_per_vertex() * static_cast<GLsizei>(sizeof(float));
    std::size_t offset = 0;
    const auto attribute = [&](GLuint location, int size) {
        fn.EnableVertexAttribArray(location);
        fn.VertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride,
                               reinterpret_cast<const void*>(offset * sizeof(float)));
        offset += static_cast<std::size_t>(size);
    };
    attribute(kPositionLocation, 3);
    if (layout.normals) {
        attribute(kNormalLocation, 3);
    }
    if (layout.colors) {
        attribute(kColorLocation, 4);
    }
    if (layout.texcoords) {
        attribute(kTexcoordLocation, 2);
    }
}

// 16-bit indices when they fit: half the index bandwidth on a mobile GPU.
void upload_indices(const gl::Functions& fn, const std::vector<std::uint32_t>& indices, GpuPrimitive& out) {
    const std::uint32_t largest = indices.empty() ? 0 : *std::max_element(indices.begin(), indices.end());
    out.index_count = static_cast<GLsizei>(indices.size());
    if (largest <= std::numeric_limits<std::uint16_t>::max()) {
        const std::vector<std::uint16_t> narrow(indices.begin(), indices.end());
        fn.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(narrow.size() * sizeof(std::uint16_t)),
                      narrow.data(), GL_STATIC_DRAW);
        out.index_type = GL_UNSIGNED_SHORT;
    } else {
        fn.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                      indices.data(), GL_STATIC_DRAW);
        out.index_type = GL_UNSIGNED_INT;
    }
}

frustum::Result<GpuPrimitive> upload_primitive(const gl::Functions& fn, const scene::Primitive& p) {
    GpuPrimitive out;
    auto vertex_array = gl::VertexArray::create(fn);
    auto vertex_buffer = gl::Buffer::create(fn);
    auto index_buffer = gl::Buffer::create(fn);
    if (!vertex_array || !vertex_buffer || !index_buffer) {
        return frustum::Error{!vertex_array ? vertex_array.error()
                              : !vertex_buffer ? vertex_buffer.error()
                                               : index_buffer.error()};
    }
    out.vertex_array = std::move(*vertex_array);
    out.vertex_buffer = std::move(*vertex_buffer);
    out.index_buffer = std::move(*index_buffer);
    out.mode = gl_mode(p.mode);
    out.material = p.material;
    const VertexLayout layout{!p.normals.empty(), !p.colors.empty(), !p.texcoords.empty()};
    out.has_normals = layout.normals;
    out.has_colors = layout.colors;
    out.has_texcoords = layout.texcoords;
    if (!p.positions.empty()) {
        glm::vec3 low = p.positions.front(), high = p.positions.front();
        for (const glm::vec3& position : p.positions) {
            low = glm::min(low, position);
            high = glm::max(high, position);
        }
        out.center = 0.5f * (low + high);
        out.low = low;
        out.high = high;
    }

    fn.BindVertexArray(out.vertex_array.id());
    const std::vector<float> vertices = interleave(p, layout);
    fn.BindBuffer(GL_ARRAY_BUFFER, out.vertex_buffer.id());
    fn.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(),
                  GL_STATIC_DRAW);
    set_attribute_pointers(fn, layout);
    // The element buffer binding is vertex-array state: bind it while ours is bound.
    fn.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, out.index_buffer.id());
    upload_indices(fn, p.indices, out);
    fn.BindVertexArray(0);
    fn.BindBuffer(GL_ARRAY_BUFFER, 0);
    return out;
}

int mip_levels(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2) {
        ++levels;
    }
    return levels;
}

// Base-colour textures hold sRGB colour (glTF 2.0): GL_SRGB8_ALPHA8 makes
// the sampler return linear values. Rows go up in file order, so GL's
// t = 0 is the image's top row, which is where glTF puts uv (0, 0).
frustum::Result<gl::Texture> upload_texture(const gl::Functions& fn, const image::Image& image, std::size_t index) {
    GLint max_size = 0;
    fn.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (image.width > max_size || image.height > max_size) {
        return frustum::Error{std::string(kUpload) + ": image " + std::to_string(index) + " is " +
                              std::to_string(image.width) + "x" + std::to_string(image.height) +
                              ", larger than GL_MAX_TEXTURE_SIZE=" + std::to_string(max_size)};
    }
    auto texture = gl::Texture::create(fn);
    if (!texture) {
        return texture.take_error();
    }
    fn.BindTexture(GL_TEXTURE_2D, texture->id());
    fn.TexStorage2D(GL_TEXTURE_2D, mip_levels(image.width, image.height), GL_SRGB8_ALPHA8, image.width,
                    image.height);
    fn.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    fn.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    fn.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    fn.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                     image.rgba.data());
    fn.GenerateMipmap(GL_TEXTURE_2D);
    // glTF's default sampler: repeat, trilinear. (The loader drops samplers.)
    fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

} // namespace

frustum::Result<PositionBuffer> create_position_buffer(const gl::Functions& fn, const std::string& caller) {
    auto buffer = gl::Buffer::create(fn);
    auto vertex_array = gl::VertexArray::create(fn);
    if (!buffer || !vertex_array) {
        return frustum::Error{caller + ": " + (!buffer ? buffer.error() : vertex_array.error())};
    }
    fn.BindVertexArray(vertex_array->id());
    fn.BindBuffer(GL_ARRAY_BUFFER, buffer->id());
    fn.EnableVertexAttribArray(kPositionLocation);
    fn.VertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    return PositionBuffer{std::move(*buffer), std::move(*vertex_array)};
}

frustum::Result<GpuScene> GpuScene::upload(const gl::Functions& fn, const scene::Scene& scene) {
    GpuScene gpu;
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        if (scene.images[i].rgba.empty()) {
            gpu.textures_.emplace_back(); // no texture draws it (scene::Scene::images)
            continue;
        }
        auto texture = upload_texture(fn, scene.images[i], i);
        if (!texture) {
            return texture.take_error();
        }
        gpu.textures_.push_back(std::move(*texture));
    }
    for (const scene::Material& m : scene.materials) {
        gpu.materials_.push_back(
            GpuMaterial{m.base_color_factor, m.base_color_texture, m.double_sided, m.alpha_mode, m.alpha_cutoff, m.unlit});
    }
    for (const scene::Mesh& mesh : scene.meshes) {
        GpuMesh& gpu_mesh = gpu.meshes_.emplace_back();
        for (const scene::Primitive& primitive : mesh.primitives) {
            auto uploaded = upload_primitive(fn, primitive);
            if (!uploaded) {
                return uploaded.take_error();
            }
            gpu_mesh.push_back(std::move(*uploaded));
        }
    }
    gpu.instances_ = scene.instances;
    if (auto status = gl::check_error(fn, kUpload); !status) {
        return status.take_error();
    }
    return gpu;
}

const GpuMaterial& GpuScene::material(int index) const {
    return index >= 0 && static_cast<std::size_t>(index) < materials_.size()
               ? materials_[static_cast<std::size_t>(index)]
               : default_material_;
}

void draw_primitive(const gl::Functions& fn, const GpuPrimitive& primitive) {
    if (!primitive.has_normals) {
        fn.VertexAttrib4f(kNormalLocation, 0.0f, 0.0f, 1.0f, 0.0f);
    }
    if (!primitive.has_colors) {
        fn.VertexAttrib4f(kColorLocation, 1.0f, 1.0f, 1.0f, 1.0f);
    }
    if (!primitive.has_texcoords) {
        fn.VertexAttrib4f(kTexcoordLocation, 0.0f, 0.0f, 0.0f, 1.0f);
    }
    fn.BindVertexArray(primitive.vertex_array.id());
    fn.DrawElements(primitive.mode, primitive.index_count, primitive.index_type, nullptr);
}

} // namespace render
