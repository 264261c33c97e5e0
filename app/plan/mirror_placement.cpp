#include "plan/mirror_placement.hpp"

#include "plan/number_text.hpp"

#include <algorithm>
#include <cmath>

namespace render {
namespace {

constexpr float kFloorGapFraction = 0.01f; // the floor lies 1% of the model's diagonal below it
constexpr float kMinSizeM = 1e-3f;         // for a model of no extent (a point)
constexpr glm::vec4 kMirrorColor{0.8f, 0.8f, 0.82f, 1.0f};

std::string vec_text(const glm::vec3& v) {
    return "(" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + ")";
}

// The placed mirror: a quad spanning `mirror` (a1, a2 its edges).
void add_mirror_instance(scene::Scene& scene, scene::MirrorRect mirror) {
    const glm::vec3 normal = glm::normalize(glm::cross(mirror.a1, mirror.a2));
    const glm::vec3 center = mirror.corner + 0.5f * (mirror.a1 + mirror.a2);
    const glm::mat4 world(glm::vec4(mirror.a1, 0.0f), glm::vec4(mirror.a2, 0.0f), glm::vec4(normal, 0.0f),
                          glm::vec4(center, 1.0f));
    mirror.instance = add_quad_instance(scene, world, kMirrorColor, "placed mirror");
    scene.instances.back().node_name = "mirror (placed)";
    scene.mirror = mirror;
}

scene::MirrorRect centered(const glm::vec3& center, const glm::vec3& a1, const glm::vec3& a2) {
    scene::MirrorRect mirror;
    mirror.corner = center - 0.5f * (a1 + a2);
    mirror.a1 = a1;
    mirror.a2 = a2;
    return mirror;
}

} // namespace

std::optional<std::string> place_mirror(scene::Scene& scene, const MirrorRequest& request) {
    const scene::Bounds& b = scene.world_bounds;
    const glm::vec3 middle = 0.5f * (b.min + b.max);
    const glm::vec3 extent = b.max - b.min;
    const float diagonal_m = std::max(glm::length(extent), kMinSizeM);
    const std::string replaced = scene.mirror ? " (instead of the scene's node mirror)" : "";
    if (request.rect) {
        const auto& r = *request.rect;
        const glm::vec3 center(r[0], r[1], r[2]), a1(r[3], r[4], r[5]), a2(r[6], r[7], r[8]);
        add_mirror_instance(scene, centered(center, a1, a2));
        return "mirror: rectangle at " + vec_text(center) + ", sides " + vec_text(a1) + " and " + vec_text(a2) +
               replaced;
    }
    if (request.plane) {
        const glm::vec3 normal = glm::normalize(glm::vec3(*request.plane));
        const float d = request.plane->w / glm::length(glm::vec3(*request.plane));
        // The square of the model's diagonal on the plane, centred at the foot of the model's centre.
        const glm::vec3 foot = middle - (glm::dot(normal, middle) + d) * normal;
        const glm::vec3 helper = std::abs(normal.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 u = glm::normalize(glm::cross(helper, normal));
        const glm::vec3 v = glm::cross(normal, u); // u x v = normal
        add_mirror_instance(scene, centered(foot, diagonal_m * u, diagonal_m * v));
        return "mirror: on the plane " + number_text(request.plane->x) + " x + " + number_text(request.plane->y) +
               " y + " + number_text(request.plane->z) + " z + " + number_text(request.plane->w) + " = 0, " +
               number_text(diagonal_m) + " x " + number_text(diagonal_m) + " centred at " + vec_text(foot) + replaced;
    }
    if (scene.mirror) {
        return std::nullopt;
    }
    // Floor: y up (glTF), a square one diagonal wider than the model's footprint.
    const float side_m = std::max(extent.x, extent.z) + diagonal_m;
    const float floor_y = b.min.y - kFloorGapFraction * diagonal_m;
    // a1 = +x, a2 = -z: a1 x a2 = +y, so it reflects upwards.
    add_mirror_instance(scene, centered(glm::vec3(middle.x, floor_y, middle.z), glm::vec3(side_m, 0, 0),
                                        glm::vec3(0, 0, -side_m)));
    return "mirror: floor under the model, y = " + number_text(floor_y) + ", " + number_text(side_m) + " x " +
           number_text(side_m) + " centred at x = " + number_text(middle.x) + ", z = " + number_text(middle.z) +
           " (the scene has no node named mirror; --mirror-plane or --mirror-rect place one by hand)";
}

int add_quad_instance(scene::Scene& scene, const glm::mat4& world, const glm::vec4& color, const std::string& name) {
    scene::Material material;
    material.name = name;
    material.base_color_factor = color;
    material.double_sided = true;
    scene.materials.push_back(material);
    scene::Primitive quad;
    quad.positions = {{-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}, {-0.5f, 0.5f, 0.0f}};
    quad.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.material = static_cast<int>(scene.materials.size()) - 1;
    scene.meshes.push_back(scene::Mesh{name, {quad}});
    scene::Instance instance;
    instance.mesh = static_cast<int>(scene.meshes.size()) - 1;
    instance.world = world;
    instance.node_name = name;
    scene.instances.push_back(instance);
    return static_cast<int>(scene.instances.size()) - 1;
}

} // namespace render
