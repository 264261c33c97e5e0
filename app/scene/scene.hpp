// A validated, GPU-free scene: what the glTF loader produces and the renderer
// consumes. Everything here has been range-checked; indices are in bounds.
#pragma once

#include "image/image.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace scene {

// glTF alphaMode: OPAQUE ignores alpha, MASK discards below alpha_cutoff,
// BLEND is alpha-blended (drawn after the opaque geometry).
enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 base_color_factor{1.0f};
    int base_color_texture = -1; // index into Scene::images, -1 = none
    bool double_sided = false;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = 0.5f; // MASK only
    bool unlit = false;        // KHR_materials_unlit: base colour only, no lighting
};

// glTF primitive modes, numbered as in the glTF spec (and GL).
enum class PrimitiveMode : std::uint32_t {
    Points = 0,
    Lines = 1,
    LineLoop = 2,
    LineStrip = 3,
    Triangles = 4,
    TriangleStrip = 5,
    TriangleFan = 6,
};

struct Primitive {
    PrimitiveMode mode = PrimitiveMode::Triangles;
    // POSITION and NORMAL have the morph targets' default weights applied
    // (node.weights, else mesh.weights).
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;   // empty: flat-shade in the renderer
    std::vector<glm::vec4> colors;    // COLOR_0 as RGBA float, empty: white
    // The TEXCOORD_<n> set the material's base colour texture reads
    // (textureInfo.texCoord, overridden by KHR_texture_transform's texCoord),
    // with KHR_texture_transform's offset, rotation and scale applied;
    // TEXCOORD_0 for an untextured material; empty (also when the primitive
    // lacks the set): the renderer reads the texture at uv (0, 0).
    std::vector<glm::vec2> texcoords;
    std::vector<std::uint32_t> indices; // always filled (0..n-1 when the file had none)
    int material = -1; // index into Scene::materials, -1 = default material
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
};

// One drawn mesh: the node graph flattened to world transforms. A node with
// EXT_mesh_gpu_instancing gives one Instance per GPU instance (its world
// transform times the instance's TRS), in order. `mesh` may be a copy of a
// file mesh built with the node's own morph weights.
struct Instance {
    int mesh = 0;
    glm::mat4 world{1.0f};
    std::string node_name;
};

// A camera placed by a node of the chosen scene (cameras no node uses are
// dropped). name: the glTF camera's name, else its node's, else "camera <i>".
struct Camera {
    enum class Kind { Perspective, Orthographic };
    std::string name;
    std::string node_name;           // the node that places the camera
    Kind kind = Kind::Perspective;
    glm::mat4 camera_to_world{1.0f}; // rigid: rotation + translation only; the
                                     // node's scale/shear is removed (columns
                                     // orthonormalized, z = x cross y)
    float yfov_rad = 0.0f;              // perspective
    std::optional<float> aspect;        // perspective; absent: use the viewport's
    float xmag = 0.0f, ymag = 0.0f;     // orthographic half sizes
    float znear_m = 0.0f;
    std::optional<float> zfar_m;        // absent: infinite (perspective only)
};

// The demo's special objects, found by node name (the first such node in
// depth-first order; see assets/README.md):
// a node named "mirror" is a rectangle: the quad [-0.5,0.5]^2 in its local
// XY plane, reflecting toward local +Z.
struct MirrorRect {
    glm::vec3 corner; // P1 in world space
    glm::vec3 a1;     // first side (world)
    glm::vec3 a2;     // second side (world); normalize(cross(a1, a2)) is the reflecting side
    int instance = -1; // the Instance that draws the mirror surface, -1 = none
};

// A node named "lens": centre and radius (world units) of a magnifier spot,
// from the node's translation and uniform scale (radius = scale.x * 0.5).
struct LensSpot {
    glm::vec3 center;
    float radius_m = 0.0f;
    int instance = -1;
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

// The bounds' eight corners, corner i taking max along x, y, z where bits 0, 1, 2 of i are set.
inline std::array<glm::vec3, 8> corners(const Bounds& b) {
    std::array<glm::vec3, 8> out{};
    for (int i = 0; i < 8; ++i) {
        out[static_cast<std::size_t>(i)] = glm::vec3((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                                                     (i & 4) ? b.max.z : b.min.z);
    }
    return out;
}

struct Scene {
    // Decoded RGBA8, rows top to bottom as in the file; empty (0 x 0) where
    // no texture draws the image (it is not decoded).
    std::vector<image::Image> images;
    std::vector<Material> materials;
    std::vector<Mesh> meshes;
    std::vector<Instance> instances;
    std::vector<Camera> cameras; // each with its world transform
    std::optional<MirrorRect> mirror;
    std::optional<LensSpot> lens;
    Bounds world_bounds; // of all instances' positions
    // Where the file's world origin is not, the scene's is: every world
    // position above (instances, cameras, mirror, lens, bounds) is relative
    // to this point of the file's world, in metres. Chosen at load (relative
    // to centre, as Cesium's CESIUM_RTC does): the centre of the meshes'
    // bounds rounded to whole metres when it is more than 1024 m from the
    // file's origin (UTM, ECEF and other georeferenced exports), else 0.
    // Transforms are composed in double and moved by -origin_m before they
    // are rounded to float, so the GPU never sees a large coordinate.
    glm::dvec3 origin_m{0.0};
};

} // namespace scene
