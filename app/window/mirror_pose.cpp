#include "window/mirror_pose.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace window {
namespace {

constexpr float kAttachMargin = 0.05f; // of the mirror's longer edge

glm::vec3 mirror_center(const scene::MirrorRect& mirror) { return mirror.corner + 0.5f * (mirror.a1 + mirror.a2); }

// Every vertex of `mesh` placed by `world` lies within `margin_m` of the
// mirror's plane and inside its rectangle grown by margin_m.
bool lies_on_mirror(const scene::Mesh& mesh, const glm::mat4& world, const scene::MirrorRect& mirror, float margin_m) {
    const glm::vec3 normal = glm::normalize(glm::cross(mirror.a1, mirror.a2));
    const float length1 = glm::length(mirror.a1);
    const float length2 = glm::length(mirror.a2);
    const glm::vec3 u1 = mirror.a1 / length1;
    const glm::vec3 u2 = mirror.a2 / length2;
    bool any = false;
    for (const scene::Primitive& primitive : mesh.primitives) {
        for (const glm::vec3& position : primitive.positions) {
            const glm::vec3 offset = glm::vec3(world * glm::vec4(position, 1.0f)) - mirror.corner;
            const float along1 = glm::dot(offset, u1);
            const float along2 = glm::dot(offset, u2);
            if (std::abs(glm::dot(offset, normal)) > margin_m || along1 < -margin_m || along1 > length1 + margin_m ||
                along2 < -margin_m || along2 > length2 + margin_m) {
                return false;
            }
            any = true;
        }
    }
    return any;
}

} // namespace

bool MirrorPose::operator==(const MirrorPose& other) const {
    return turn_rad == other.turn_rad && tilt_rad == other.tilt_rad && slide_m == other.slide_m &&
           push_m == other.push_m;
}

glm::mat4 mirror_motion(const scene::MirrorRect& mirror, const MirrorPose& pose) {
    const glm::vec3 center = mirror_center(mirror);
    const glm::vec3 edge = glm::normalize(mirror.a1);
    const glm::vec3 normal = glm::normalize(glm::cross(mirror.a1, mirror.a2));
    const glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), pose.turn_rad, glm::vec3(0.0f, 1.0f, 0.0f)) *
                               glm::rotate(glm::mat4(1.0f), pose.tilt_rad, edge);
    const glm::vec3 shift = pose.slide_m * glm::vec3(rotation * glm::vec4(edge, 0.0f)) +
                            pose.push_m * glm::vec3(rotation * glm::vec4(normal, 0.0f));
    return glm::translate(glm::mat4(1.0f), center + shift) * rotation * glm::translate(glm::mat4(1.0f), -center);
}

std::vector<int> mirror_attachments(const scene::Scene& scene) {
    std::vector<int> attached;
    if (!scene.mirror) {
        return attached;
    }
    const scene::MirrorRect& mirror = *scene.mirror;
    const float margin_m = kAttachMargin * std::max(glm::length(mirror.a1), glm::length(mirror.a2));
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        if (static_cast<int>(i) != mirror.instance &&
            lies_on_mirror(scene.meshes[static_cast<std::size_t>(instance.mesh)], instance.world, mirror, margin_m)) {
            attached.push_back(static_cast<int>(i));
        }
    }
    return attached;
}

} // namespace window
