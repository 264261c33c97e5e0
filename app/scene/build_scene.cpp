#include "build_scene.hpp"

#include "accessor_reader.hpp"
#include "extensions.hpp"
#include "node_graph.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <utility>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Result;
using frustum::Status;

constexpr double kDegenerateLength = 1e-12;
// Scenes whose centre lies further than this from the file's origin are
// kept relative to their centre (Scene::origin_m): float steps there are
// 2^-14 m = 61 um at 1024 m, 0.5 m at 6.4e6 m (ECEF), 0.06 m at 5e5 m (UTM).
constexpr double kRebaseBeyondM = 1024.0;

Result<std::vector<glm::vec4>> read_colors(const tinygltf::Model& model, int accessor) {
    Result<std::vector<float>> values = read_floats(model, accessor);
    if (!values) {
        return values.take_error();
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
        return values.take_error();
    }
    out.resize(values->size() / N);
    for (std::size_t i = 0; i < out.size(); ++i) {
        for (int c = 0; c < N; ++c) {
            out[i][c] = (*values)[i * N + c];
        }
    }
    return {};
}

// How a material's base colour texture is read: from which TEXCOORD_<set>
// (textureInfo.texCoord, or KHR_texture_transform's texCoord), through which
// KHR_texture_transform matrix (identity without one).
struct TexcoordUse {
    bool textured = false;
    int set = 0;
    glm::mat3 transform{1.0f};
};

Result<glm::vec2> read_vec2(const tinygltf::Value& object, const char* key, glm::vec2 fallback,
                            const std::string& where) {
    if (!object.Has(key)) {
        return fallback;
    }
    const tinygltf::Value& value = object.Get(key);
    if (!value.IsArray() || value.ArrayLen() != 2 || !value.Get(0).IsNumber() || !value.Get(1).IsNumber()) {
        return Error{where + " " + key + " must be an array of 2 numbers"};
    }
    const glm::vec2 out(static_cast<float>(value.Get(0).GetNumberAsDouble()),
                        static_cast<float>(value.Get(1).GetNumberAsDouble()));
    if (!std::isfinite(out.x) || !std::isfinite(out.y)) {
        return Error{where + " " + key + " must be finite"};
    }
    return out;
}

// KHR_texture_transform: uv' = T R S uv, written as in the extension's
// specification (column-major, as GLSL's and GLM's mat3 constructors).
Result<TexcoordUse> texcoord_use(const tinygltf::Material& material, int index) {
    const tinygltf::TextureInfo& texture = material.pbrMetallicRoughness.baseColorTexture;
    TexcoordUse use;
    use.textured = texture.index >= 0;
    use.set = texture.texCoord;
    auto found = texture.extensions.find(kTextureTransform);
    if (!use.textured || found == texture.extensions.end()) {
        return use;
    }
    const std::string where = "material " + std::to_string(index) + " baseColorTexture " + kTextureTransform;
    const tinygltf::Value& ext = found->second;
    if (!ext.IsObject()) {
        return Error{where + " is not an object"};
    }
    Result<glm::vec2> offset = read_vec2(ext, "offset", glm::vec2(0.0f), where);
    Result<glm::vec2> scale = read_vec2(ext, "scale", glm::vec2(1.0f), where);
    if (!offset || !scale) {
        return Error{!offset ? offset.error() : scale.error()};
    }
    float rotation = 0.0f;
    if (ext.Has("rotation")) {
        const tinygltf::Value& value = ext.Get("rotation");
        rotation = value.IsNumber() ? static_cast<float>(value.GetNumberAsDouble()) : NAN;
        if (!std::isfinite(rotation)) {
            return Error{where + " rotation must be a finite number"};
        }
    }
    if (ext.Has("texCoord")) {
        const tinygltf::Value& value = ext.Get("texCoord");
        if (!value.IsInt() || value.GetNumberAsInt() < 0) {
            return Error{where + " texCoord must be a whole number >= 0"};
        }
        use.set = value.GetNumberAsInt();
    }
    const float c = std::cos(rotation);
    const float s = std::sin(rotation);
    const glm::mat3 translation(1, 0, 0, 0, 1, 0, offset->x, offset->y, 1);
    const glm::mat3 rotate(c, s, 0, -s, c, 0, 0, 0, 1);
    const glm::mat3 scaling(scale->x, 0, 0, 0, scale->y, 0, 0, 0, 1);
    use.transform = translation * rotate * scaling;
    return use;
}

// Morph targets with the given default weights, added on the CPU
// (glTF 2.0 "Morph Targets": p = p0 + sum w_i t_i, for POSITION and NORMAL).
Status apply_morph(const tinygltf::Model& model, const tinygltf::Primitive& source, const std::vector<double>& weights,
                   Primitive& primitive) {
    for (std::size_t t = 0; t < source.targets.size() && t < weights.size(); ++t) {
        const float weight = static_cast<float>(weights[t]);
        if (weight == 0.0f) {
            continue;
        }
        for (auto [semantic, out] : {std::pair<const char*, std::vector<glm::vec3>*>{"POSITION", &primitive.positions},
                                     {"NORMAL", &primitive.normals}}) {
            auto found = source.targets[t].find(semantic);
            if (found == source.targets[t].end() || out->empty()) {
                continue;
            }
            Result<std::vector<float>> delta = read_floats(model, found->second);
            if (!delta) {
                return delta.take_error();
            }
            for (std::size_t v = 0; v < out->size(); ++v) { // counts: validate_morphs
                (*out)[v] += weight * glm::vec3((*delta)[3 * v], (*delta)[3 * v + 1], (*delta)[3 * v + 2]);
            }
        }
    }
    return {};
}

Result<Primitive> build_primitive(const tinygltf::Model& model, const tinygltf::Primitive& source,
                                  const std::string& where, const std::vector<TexcoordUse>& uses,
                                  const std::vector<double>& weights) {
    Primitive primitive;
    primitive.mode = static_cast<PrimitiveMode>(source.mode);
    primitive.material = source.material;
    const TexcoordUse use = source.material >= 0 ? uses[static_cast<std::size_t>(source.material)] : TexcoordUse{};
    // A set the primitive lacks leaves texcoords empty: the renderer then
    // reads the texture at (0, 0), as it always did for a missing TEXCOORD_0.
    const std::string texcoord = "TEXCOORD_" + std::to_string(use.set);
    Status reads[] = {
        read_vectors<3>(model, source, "POSITION", primitive.positions),
        read_vectors<3>(model, source, "NORMAL", primitive.normals),
        read_vectors<2>(model, source, texcoord.c_str(), primitive.texcoords),
        apply_morph(model, source, weights, primitive),
    };
    for (Status& status : reads) {
        if (!status) {
            return status.take_error();
        }
    }
    for (glm::vec2& uv : primitive.texcoords) {
        uv = glm::vec2(use.transform * glm::vec3(uv, 1.0f));
    }
    if (auto color = source.attributes.find("COLOR_0"); color != source.attributes.end()) {
        Result<std::vector<glm::vec4>> colors = read_colors(model, color->second);
        if (!colors) {
            return colors.take_error();
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
        return indices.take_error();
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

Result<Mesh> build_mesh(const tinygltf::Model& model, int index, const std::vector<TexcoordUse>& uses,
                        const std::vector<double>& weights) {
    const tinygltf::Mesh& source = model.meshes[index];
    Mesh mesh;
    mesh.name = source.name;
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
        if (source.primitives[p].attributes.count("POSITION") == 0) {
            continue; // nothing to draw (validate_primitive())
        }
        const std::string where = "mesh " + std::to_string(index) + " primitive " + std::to_string(p);
        Result<Primitive> primitive = build_primitive(model, source.primitives[p], where, uses, weights);
        if (!primitive) {
            return primitive.take_error();
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
    // Each primitive loads the TEXCOORD set its material's texture reads (texcoord_use()).
    const tinygltf::TextureInfo& texture = source.pbrMetallicRoughness.baseColorTexture;
    if (texture.index >= 0) {
        material.base_color_texture = model.textures[texture.index].source;
    }
    material.unlit = source.extensions.count(kUnlit) > 0;
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
        return rigid.take_error();
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

// EXT_mesh_gpu_instancing: the node's world transform times each instance's
// T R S (the attributes it lacks are identity), one Instance each.
Result<std::vector<glm::dmat4>> instance_transforms(const tinygltf::Model& model, const tinygltf::Node& node,
                                                    const glm::dmat4& world) {
    auto found = node.extensions.find(kGpuInstancing);
    if (found == node.extensions.end()) {
        return std::vector<glm::dmat4>{world};
    }
    const tinygltf::Value& attributes = found->second.Get("attributes"); // validate_instancing
    std::vector<float> columns[3];
    const char* names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
    std::size_t count = 0;
    for (int a = 0; a < 3; ++a) {
        if (attributes.Has(names[a])) {
            Result<std::vector<float>> values = read_floats(model, attributes.Get(names[a]).GetNumberAsInt());
            if (!values) {
                return values.take_error();
            }
            columns[a] = std::move(values).value();
            count = columns[a].size() / (a == 1 ? 4 : 3);
        }
    }
    std::vector<glm::dmat4> out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        glm::dvec3 t(0.0), s(1.0);
        glm::dquat r(1.0, 0.0, 0.0, 0.0);
        if (!columns[0].empty()) t = glm::dvec3(columns[0][3 * i], columns[0][3 * i + 1], columns[0][3 * i + 2]);
        if (!columns[2].empty()) s = glm::dvec3(columns[2][3 * i], columns[2][3 * i + 1], columns[2][3 * i + 2]);
        if (!columns[1].empty()) {
            r = glm::dquat(columns[1][4 * i + 3], columns[1][4 * i], columns[1][4 * i + 1], columns[1][4 * i + 2]);
            const double length = glm::length(r);
            r = length > kDegenerateLength ? r / length : glm::dquat(1.0, 0.0, 0.0, 0.0);
        }
        glm::dmat4 trs = glm::mat4_cast(r);
        trs[0] *= s.x;
        trs[1] *= s.y;
        trs[2] *= s.z;
        trs[3] = glm::dvec4(t, 1.0);
        out.push_back(world * trs);
    }
    return out;
}

bool finite_single(const glm::dmat4& world) {
    const glm::mat4 world_f(world);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(world_f[c][r])) {
                return false;
            }
        }
    }
    return true;
}

// Meshes as drawn: model mesh m with its own weights is scene mesh m; a node
// with other morph weights (node.weights) gets a copy built with them.
class MeshVariants {
public:
    MeshVariants(const tinygltf::Model& model, const std::vector<TexcoordUse>& uses) : model_(model), uses_(uses) {}

    Result<int> index(int mesh, const std::vector<double>& node_weights, Scene& scene) {
        if (node_weights.empty() || node_weights == model_.meshes[mesh].weights) {
            return mesh;
        }
        const auto key = std::make_pair(mesh, node_weights);
        if (auto found = variants_.find(key); found != variants_.end()) {
            return found->second;
        }
        Result<Mesh> built = build_mesh(model_, mesh, uses_, node_weights);
        if (!built) {
            return built.take_error();
        }
        const int index = static_cast<int>(scene.meshes.size());
        scene.meshes.push_back(std::move(built).value());
        variants_.emplace(key, index);
        return index;
    }

private:
    const tinygltf::Model& model_;
    const std::vector<TexcoordUse>& uses_;
    std::map<std::pair<int, std::vector<double>>, int> variants_;
};

// Scene::origin_m for the flattened forest: the centre of the meshes'
// world bounds (each mesh's object-space box, its eight corners through the
// node's double world transform), rounded to whole metres, or 0 when that
// centre is within kRebaseBeyondM of the file's origin (or nothing is drawn,
// or the centre is not finite: place_nodes() refuses those transforms).
glm::dvec3 scene_origin(const tinygltf::Model& model, const std::vector<WorldNode>& nodes, const Scene& scene) {
    glm::dvec3 low(std::numeric_limits<double>::max());
    glm::dvec3 high(std::numeric_limits<double>::lowest());
    for (const WorldNode& flat : nodes) {
        const int mesh = model.nodes[flat.node].mesh;
        if (mesh < 0) {
            continue;
        }
        for (const Primitive& primitive : scene.meshes[static_cast<std::size_t>(mesh)].primitives) {
            if (primitive.positions.empty()) {
                continue;
            }
            glm::vec3 box_low = primitive.positions.front();
            glm::vec3 box_high = box_low;
            for (const glm::vec3& p : primitive.positions) {
                box_low = glm::min(box_low, p);
                box_high = glm::max(box_high, p);
            }
            for (const glm::vec3& corner : corners(Bounds{box_low, box_high})) {
                const glm::dvec3 world(flat.world * glm::dvec4(glm::dvec3(corner), 1.0));
                low = glm::min(low, world);
                high = glm::max(high, world);
            }
        }
    }
    if (!(low.x <= high.x)) {
        return glm::dvec3(0.0);
    }
    const glm::dvec3 centre = 0.5 * low + 0.5 * high;
    const double reach_m = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
    if (!std::isfinite(reach_m) || reach_m <= kRebaseBeyondM) {
        return glm::dvec3(0.0);
    }
    return glm::round(centre);
}

// Instances, cameras, mirror and lens from the flattened node forest, with
// every world transform moved by -scene.origin_m in double before it is
// rounded to float.
Status place_nodes(const tinygltf::Model& model, const std::vector<WorldNode>& nodes, MeshVariants& meshes,
                   Scene& scene) {
    for (const WorldNode& unmoved : nodes) {
        const tinygltf::Node& node = model.nodes[unmoved.node];
        // Finite inputs can still overflow single precision when composed
        // down the hierarchy (or exceed it alone: a translation of 1e39).
        const std::string too_large = "node " + std::to_string(unmoved.node) +
                                      (node.name.empty() ? "" : " (\"" + node.name + "\")") +
                                      " has a world transform too large for single precision";
        if (!finite_single(unmoved.world)) {
            return Error{too_large};
        }
        WorldNode flat = unmoved;
        flat.world[3] -= glm::dvec4(scene.origin_m, 0.0);
        int instance = -1; // the first Instance of the node (EXT_mesh_gpu_instancing: of several)
        if (node.mesh >= 0) {
            Result<int> mesh = meshes.index(node.mesh, node.weights, scene);
            Result<std::vector<glm::dmat4>> worlds = instance_transforms(model, node, flat.world);
            if (!mesh || !worlds) {
                return Error{!mesh ? mesh.error() : worlds.error()};
            }
            instance = static_cast<int>(scene.instances.size());
            for (const glm::dmat4& world : *worlds) {
                if (!finite_single(world)) {
                    return Error{too_large + " (with its " + kGpuInstancing + " instances)"};
                }
                scene.instances.push_back({*mesh, glm::mat4(world), node.name});
            }
        }
        if (node.camera >= 0) {
            Result<Camera> camera = build_camera(model, flat.node, flat.world);
            if (!camera) {
                return camera.take_error();
            }
            scene.cameras.push_back(std::move(camera).value());
        }
        if (node.name == "mirror" && !scene.mirror) {
            Result<MirrorRect> mirror = build_mirror(flat.world, instance);
            if (!mirror) {
                return mirror.take_error();
            }
            scene.mirror = *mirror;
        }
        if (node.name == "lens" && !scene.lens) {
            Result<LensSpot> lens = build_lens(flat.world, instance);
            if (!lens) {
                return lens.take_error();
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
        return roots.take_error();
    }
    Scene scene;
    for (tinygltf::Image& source : model.images) {
        if (source.image.empty()) {
            scene.images.emplace_back(); // not decoded: no texture draws it (parse_model())
            continue;
        }
        scene.images.push_back({source.width, source.height, std::move(source.image)});
    }
    std::vector<TexcoordUse> uses;
    for (std::size_t m = 0; m < model.materials.size(); ++m) {
        scene.materials.push_back(build_material(model, model.materials[m]));
        Result<TexcoordUse> use = texcoord_use(model.materials[m], static_cast<int>(m));
        if (!use) {
            return use.take_error();
        }
        uses.push_back(*use);
    }
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        Result<Mesh> mesh = build_mesh(model, static_cast<int>(m), uses, model.meshes[m].weights);
        if (!mesh) {
            return mesh.take_error();
        }
        scene.meshes.push_back(std::move(mesh).value());
    }
    MeshVariants variants(model, uses);
    const std::vector<WorldNode> nodes = flatten(model, *roots);
    scene.origin_m = scene_origin(model, nodes, scene);
    if (Status placed = place_nodes(model, nodes, variants, scene); !placed) {
        return placed.take_error();
    }
    scene.world_bounds = bounds_of(scene);
    return scene;
}

} // namespace scene::detail
