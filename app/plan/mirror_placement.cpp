#include "plan/mirror_placement.hpp"

#include "plan/number_text.hpp"
#include "plan/view_links.hpp"

#include <frustum/queries.hpp>

#include <algorithm>
#include <cmath>

namespace plan {
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

constexpr int kRaysX = 16, kRaysY = 9; // fraction_in_view()'s grid

// The floor mirror place_mirror() derives without a camera.
scene::MirrorRect floor_mirror(const scene::Bounds& b, float& side_m, float& floor_y) {
    const glm::vec3 middle = 0.5f * (b.min + b.max);
    const glm::vec3 extent = b.max - b.min;
    const float diagonal_m = std::max(glm::length(extent), kMinSizeM);
    // Floor: y up (glTF), a square one diagonal wider than the model's footprint.
    side_m = std::max(extent.x, extent.z) + diagonal_m;
    floor_y = b.min.y - kFloorGapFraction * diagonal_m;
    // a1 = +x, a2 = -z: a1 x a2 = +y, so it reflects upwards.
    return centered(glm::vec3(middle.x, floor_y, middle.z), glm::vec3(side_m, 0, 0), glm::vec3(0, 0, -side_m));
}

} // namespace

float fraction_in_view(const frustum::MatrixPair<float>& camera, const scene::MirrorRect& mirror) {
    auto near = frustum::near_plane_frame(camera);
    if (!near) {
        return 0.0f;
    }
    const glm::vec3 n = glm::cross(mirror.a1, mirror.a2);
    const float a1_len2 = glm::dot(mirror.a1, mirror.a1), a2_len2 = glm::dot(mirror.a2, mirror.a2);
    int hits = 0;
    for (int j = 0; j < kRaysY; ++j) {
        for (int i = 0; i < kRaysX; ++i) {
            const float u = (2.0f * (static_cast<float>(i) + 0.5f) / kRaysX) - 1.0f;
            const float v = (2.0f * (static_cast<float>(j) + 0.5f) / kRaysY) - 1.0f;
            const glm::vec3 through = near->center + u * near->half_width_m * near->x_axis +
                                      v * near->half_height_m * near->y_axis;
            const glm::vec3 d = through - near->eye;
            const float along = glm::dot(d, n);
            if (along == 0.0f) {
                continue;
            }
            const float t = glm::dot(mirror.corner - near->eye, n) / along;
            if (!(t > 1.0f)) { // behind the near plane
                continue;
            }
            const glm::vec3 local = near->eye + t * d - mirror.corner;
            const float s1 = glm::dot(local, mirror.a1) / a1_len2, s2 = glm::dot(local, mirror.a2) / a2_len2;
            hits += (s1 >= 0.0f && s1 <= 1.0f && s2 >= 0.0f && s2 <= 1.0f) ? 1 : 0;
        }
    }
    return static_cast<float>(hits) / static_cast<float>(kRaysX * kRaysY);
}

std::optional<std::string> place_mirror(scene::Scene& scene, const MirrorRequest& request,
                                        const frustum::MatrixPair<float>* camera) {
    const scene::Bounds& b = scene.world_bounds;
    const glm::vec3 middle = 0.5f * (b.min + b.max);
    const glm::vec3 extent = b.max - b.min;
    const float diagonal_m = std::max(glm::length(extent), kMinSizeM);
    const std::string replaced = scene.mirror ? " (instead of the scene's node mirror)" : "";
    if (request.rect) {
        const auto& r = *request.rect;
        const glm::vec3 center(r[0], r[1], r[2]), a1(r[3], r[4], r[5]), a2(r[6], r[7], r[8]);
        // The request is in the file's world; the scene is relative to its origin_m.
        add_mirror_instance(scene, centered(glm::vec3(glm::dvec3(center) - scene.origin_m), a1, a2));
        return "mirror: rectangle at " + vec_text(center) + ", sides " + vec_text(a1) + " and " + vec_text(a2) +
               replaced;
    }
    if (request.plane) {
        const glm::vec3 normal = glm::normalize(glm::vec3(*request.plane));
        // a x + b y + c z + d = 0 in the file's world; relative to the
        // scene's origin_m o the offset is d + n . o (in double).
        const double file_d = request.plane->w / glm::length(glm::vec3(*request.plane));
        const float d = static_cast<float>(file_d + glm::dot(glm::dvec3(normal), scene.origin_m));
        // The square of the model's diagonal on the plane, centred at the foot of the model's centre.
        const glm::vec3 foot = middle - (glm::dot(normal, middle) + d) * normal;
        const glm::vec3 helper = std::abs(normal.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 u = glm::normalize(glm::cross(helper, normal));
        const glm::vec3 v = glm::cross(normal, u); // u x v = normal
        add_mirror_instance(scene, centered(foot, diagonal_m * u, diagonal_m * v));
        return "mirror: on the plane " + number_text(request.plane->x) + " x + " + number_text(request.plane->y) +
               " y + " + number_text(request.plane->z) + " z + " + number_text(request.plane->w) + " = 0, " +
               number_text(diagonal_m) + " x " + number_text(diagonal_m) + " centred at " + vec_text(glm::vec3(glm::dvec3(foot) + scene.origin_m)) + replaced;
    }
    if (scene.mirror) {
        return std::nullopt;
    }
    float side_m = 0.0f, floor_y = 0.0f;
    const scene::MirrorRect floor = floor_mirror(b, side_m, floor_y);
    if (camera && frustum::eye_point(*camera)) {
        auto a = view_anchor(*camera, b, instance_boxes(scene), "plan::place_mirror()");
        if (a && (a->inside || fraction_in_view(*camera, floor) < kMinFloorInView)) {
            // a1 x a2 = R x (R x f) = -f: it faces the eye.
            add_mirror_instance(scene, centered(a->point, a->half_width_m * a->right, a->half_height_m * a->view_up));
            return "mirror: in front of the camera (" +
                   std::string(a->inside ? "the eye is inside the model's bounds" : "a floor under the model would be out of view") +
                   "), " + number_text(a->depth_m) + " m ahead at " + vec_text(a->point) + ", " +
                   number_text(a->half_width_m) + " x " + number_text(a->half_height_m) +
                   ", facing the eye (the scene has no node named mirror; --mirror-plane or --mirror-rect place one by hand)";
        }
    }
    add_mirror_instance(scene, floor);
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

} // namespace plan
