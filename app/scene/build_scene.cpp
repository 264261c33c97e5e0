#include "build_scene.hpp"

#include "accessor_reader.hpp"
#include "node_graph.hpp"

#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Result;
using frustum::Status;

constexpr double kDegenerateLength = 1e-12;

Result<std::vector<glm::vec4>> read_colors(const tinygltf::Model& model, int accessor) {
    Result<std::vector<float>> values = read_floats(model, accessor);
    if (!values) {
        return Error{values.error()};
    }
    const std::size_t components = model.accessors[accessor].type == TINYGLTF_TYPE_VEC4 ? 4 : 3;
    std::vector<glm::vec4> colors(values->size() / components, glm::vec4(1.0f));
    for (std::size_t i = 0; i < colors.size(); ++i) {
        for (std::size_t c = 0; c < components; ++c) {
            colors[i][int(c)] = (*values)[i * components + c];
        }
    }
    return colors;
}

// Reads attribute `semantic` (if present) as vectors of N floats.
template <int N>
Status read_vectors(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                    const char* semantic, std::vector<glm::vec<N, float>>& out) {
    auto attribute = primitive.attributes.find(semantic);
    if (attribute == primitive.attributes.end()) {
        return {};
    }
    Result<std::vector<float>> values = read_floats(model, attribute->second);
    if (!values) {
        return Error{values.error()};
    }
    out.resize(values->size() / N);
    for (std::size_t i = 0; i < out.size(); ++i) {
        for (int c = 0; c < N; ++c) {
            out[i][c] = (*values)[i * N + c];
        }
    }
    return {};
}

Result<Primitive> build_primitive(const tinygltf::Model& model, const tinygltf::Primitive& source,
                                  const std::string& where) {
    Primitive primitive;
    primitive.mode = static_cast<PrimitiveMode>(source.mode);
    primitive.material = source.material;
    Status reads[] = {
        read_vectors<3>(model, source, "POSITION", primitive.positions),
        read_vectors<3>(model, source, "NORMAL", primitive.normals),
        read_vectors<2>(model, source, "TEXCOORD_0", primitive.texcoords),
    };
    for (Status& status : reads) {
        if (!status) {
            return Error{status.error()};
        }
    }
    if (auto color = source.attributes.find("COLOR_0"); color != source.attributes.end()) {
        Result<std::vector<glm::vec4>> colors = read_colors(model, color->second);
        if (!colors) {
            return Error{colors.error()};
        }
        primitive.colors = std::move(colors).value();
    }
    for (std::size_t v = 0; v < primitive.positions.size(); ++v) {
        const glm::vec3& p = primitive.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            return Error{"POSITION of " + where + " is not finite at vertex " + std::to_string(v)};
        }
    }
    const std::size_t vertex_count = primitive.positions.size();
    if (source.indices < 0) {
        primitive.indices.resize(vertex_count);
        std::iota(primitive.indices.begin(), primitive.indices.end(), 0u);
        return primitive;
    }
    Result<std::vector<std::uint32_t>> indices = read_uints(model, source.indices);
    if (!indices) {
        return Error{indices.error()};
    }
    for (std::size_t i = 0; i < indices->size(); ++i) {
        if ((*indices)[i] >= vertex_count) {
            return Error{"indices of " + where + " (accessor " + std::to_string(source.indices) +
                         ") has value " + std::to_string((*indices)[i]) + " at position " +
                         std::to_string(i) + " but the primitive has " +
                         std::to_string(vertex_count) + " vertices"};
        }
    }
    primitive.indices = std::move(indices).value();
    return primitive;
}

Result<Mesh> build_mesh(const tinygltf::Model& model, int index) {
    const tinygltf::Mesh& source = model.meshes[index];
    Mesh mesh;
    mesh.name = source.name;
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
        const std::string where = "mesh " + std::to_string(index) + " primitive " + std::to_string(p);
        Result<Primitive> primitive = build_primitive(model, source.primitives[p], where);
        if (!primitive) {
            return Error{primitive.error()};
        }
        mesh.primitives.push_back(std::move(primitive).value());
    }
    return mesh;
}

Material build_material(const tinygltf::Model& model, const tinygltf::Material& source) {
    Material material;
    material.name = source.name;
    const auto& factor = source.pbrMetallicRoughness.baseColorFactor;
    material.base_color_factor = glm::vec4(factor[0], factor[1], factor[2], factor[3]);
    // Only TEXCOORD_0 is loaded, so a texture read through another set is dropped.
    const tinygltf::TextureInfo& texture = source.pbrMetallicRoughness.baseColorTexture;
    if (texture.index >= 0 && texture.texCoord == 0) {
        material.base_color_texture = model.textures[texture.index].source;
    }
    material.double_sided = source.doubleSided;
    material.alpha_mode = source.alphaMode == "BLEND"  ? AlphaMode::Blend
                          : source.alphaMode == "MASK" ? AlphaMode::Mask
                                                       : AlphaMode::Opaque;
    material.alpha_cutoff = static_cast<float>(source.alphaCutoff);
    return material;
}

// Removes scale and shear from a world transform: columns x, y orthonormalized
// by Gram-Schmidt, z = x cross y, translation kept. A mirroring transform thus
// keeps the camera's x and y axes and the view direction follows from them.
Result<glm::mat4> rigid_part(const glm::dmat4& world, const std::string& what) {
    glm::dvec3 x(world[0]);
    glm::dvec3 y(world[1]);
    if (glm::length(x) < kDegenerateLength) {
        return Error{what + " has a degenerate world transform (zero x axis)"};
    }
    x = glm::normalize(x);
    y -= glm::dot(y, x) * x;
    if (glm::length(y) < kDegenerateLength) {
        return Error{what + " has a degenerate world transform (y axis parallel to x or zero)"};
    }
    y = glm::normalize(y);
    const glm::dvec3 z = glm::cross(x, y);
    return glm::mat4(glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(y, 0.0), glm::dvec4(z, 0.0),
                                world[3]));
}

Result<Camera> build_camera(const tinygltf::Model& model, int node_index, const glm::dmat4& world) {
    const tinygltf::Node& node = model.nodes[node_index];
    const tinygltf::Camera& source = model.cameras[node.camera];
    Camera camera;
    camera.name = !source.name.empty() ? source.name
                  : !node.name.empty() ? node.name
                                       : "camera " + std::to_string(node.camera);
    camera.node_name = node.name;
    Result<glm::mat4> rigid = rigid_part(world, "camera node " + std::to_string(node_index));
    if (!rigid) {
        return Error{rigid.error()};
    }
    camera.camera_to_world = *rigid;
    if (source.type == "perspective") {
        camera.kind = Camera::Kind::Perspective;
        camera.yfov_rad = static_cast<float>(source.perspective.yfov);
        camera.znear_m = static_cast<float>(source.perspective.znear);
        if (source.perspective.aspectRatio > 0.0) {
            camera.aspect = static_cast<float>(source.perspective.aspectRatio);
        }
        if (source.perspective.zfar > 0.0) {
            camera.zfar_m = static_cast<float>(source.perspective.zfar);
        }
    } else {
        camera.kind = Camera::Kind::Orthographic;
        camera.xmag = static_cast<float>(source.orthographic.xmag);
        camera.ymag = static_cast<float>(source.orthographic.ymag);
        camera.znear_m = static_cast<float>(source.orthographic.znear);
        camera.zfar_m = static_cast<float>(source.orthographic.zfar);
    }
    return camera;
}

Result<MirrorRect> build_mirror(const glm::dmat4& world, int instance) {
    MirrorRect mirror;
    mirror.corner = glm::vec3(world * glm::dvec4(-0.5, -0.5, 0.0, 1.0));
    mirror.a1 = glm::vec3(world * glm::dvec4(1.0, 0.0, 0.0, 0.0));
    mirror.a2 = glm::vec3(world * glm::dvec4(0.0, 1.0, 0.0, 0.0));
    mirror.instance = instance;
    if (glm::length(glm::cross(glm::dvec3(mirror.a1), glm::dvec3(mirror.a2))) < kDegenerateLength) {
        return Error{"node \"mirror\" has a degenerate world transform (its quad has no area)"};
    }
    return mirror;
}

Result<LensSpot> build_lens(const glm::dmat4& world, int instance) {
    LensSpot lens;
    lens.center = glm::vec3(world[3]);
    lens.radius_m = static_cast<float>(glm::length(glm::dvec3(world[0])) * 0.5);
    lens.instance = instance;
    if (!(lens.radius_m > 0.0f)) {
        return Error{"node \"lens\" has zero scale, so its radius is 0"};
    }
    return lens;
}

Result<std::vector<int>> scene_roots(const tinygltf::Model& model, const LoadOptions& options) {
    const int scene_count = static_cast<int>(model.scenes.size());
    int chosen = model.defaultScene >= 0 ? model.defaultScene : (scene_count > 0 ? 0 : -1);
    if (options.scene_index) {
        chosen = *options.scene_index;
        if (chosen < 0 || chosen >= scene_count) {
            return Error{"scene " + std::to_string(chosen) + " was requested but the file has " +
                         std::to_string(scene_count) + " scenes"};
        }
    }
    return chosen >= 0 ? model.scenes[chosen].nodes : root_nodes(model);
}

Bounds bounds_of(const Scene& scene) {
    glm::vec3 low(std::numeric_limits<float>::max());
    glm::vec3 high(std::numeric_limits<float>::lowest());
    for (const Instance& instance : scene.instances) {
        for (const Primitive& primitive : scene.meshes[instance.mesh].primitives) {
            for (const glm::vec3& position : primitive.positions) {
                const glm::vec3 world = glm::vec3(instance.world * glm::vec4(position, 1.0f));
                low = glm::min(low, world);
                high = glm::max(high, world);
            }
        }
    }
    return low.x <= high.x ? Bounds{low, high} : Bounds{};
}

// Instances, cameras, mirror and lens from the flattened node forest.
Status place_nodes(const tinygltf::Model& model, const std::vector<WorldNode>& nodes, Scene& scene) {
    for (const WorldNode& flat : nodes) {
        const tinygltf::Node& node = model.nodes[flat.node];
        // Finite inputs can still overflow single precision when composed
        // down the hierarchy (or exceed it alone: a translation of 1e39).
        const glm::mat4 world_f(flat.world);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) {
                if (!std::isfinite(world_f[c][r])) {
                    return Error{"node " + std::to_string(flat.node) +
                                 (node.name.empty() ? "" : " (\"" + node.name + "\")") +
                                 " has a world transform too large for single precision"};
                }
            }
        }
        int instance = -1;
        if (node.mesh >= 0) {
            instance = static_cast<int>(scene.instances.size());
            scene.instances.push_back({node.mesh, glm::mat4(flat.world), node.name});
        }
        if (node.camera >= 0) {
            Result<Camera> camera = build_camera(model, flat.node, flat.world);
            if (!camera) {
                return Error{camera.error()};
            }
            scene.cameras.push_back(std::move(camera).value());
        }
        if (node.name == "mirror" && !scene.mirror) {
            Result<MirrorRect> mirror = build_mirror(flat.world, instance);
            if (!mirror) {
                return Error{mirror.error()};
            }
            scene.mirror = *mirror;
        }
        if (node.name == "lens" && !scene.lens) {
            Result<LensSpot> lens = build_lens(flat.world, instance);
            if (!lens) {
                return Error{lens.error()};
            }
            scene.lens = *lens;
        }
    }
    return {};
}

} // namespace

Result<Scene> build_scene(tinygltf::Model&& model, const LoadOptions& options) {
    Result<std::vector<int>> roots = scene_roots(model, options);
    if (!roots) {
        return Error{roots.error()};
    }
    Scene scene;
    for (tinygltf::Image& source : model.images) {
        scene.images.push_back({source.width, source.height, std::move(source.image)});
    }
    for (const tinygltf::Material& source : model.materials) {
        scene.materials.push_back(build_material(model, source));
    }
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        Result<Mesh> mesh = build_mesh(model, static_cast<int>(m));
        if (!mesh) {
            return Error{mesh.error()};
        }
        scene.meshes.push_back(std::move(mesh).value());
    }
    if (Status placed = place_nodes(model, flatten(model, *roots), scene); !placed) {
        return Error{placed.error()};
    }
    scene.world_bounds = bounds_of(scene);
    return scene;
}

} // namespace scene::detail
