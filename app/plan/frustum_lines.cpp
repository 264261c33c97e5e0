#include "plan/frustum_lines.hpp"

#include <frustum/queries.hpp>

#include <array>

namespace plan {
namespace {

glm::vec4 canonical(const glm::vec4& homogeneous) {
    return frustum::to_point(homogeneous, frustum::infinity_tolerance<float>());
}

bool is_finite_point(const glm::vec4& canonical_point) { return canonical_point.w == 1.0f; }

// The far end of side edge near -> far (homogeneous, near.w > 0: the pair's
// sign convention). Along the edge w(t) = near.w + t (far.w - near.w); when
// the far corner is not a finite point in front (w > 0), the edge reaches
// infinity at t0 = near.w / (near.w - far.w), in direction (near + t0 (far -
// near)).xyz, and is drawn as a ray that long.
glm::vec3 side_edge_end(const glm::vec4& near, const glm::vec4& far, float infinite_length_m) {
    const glm::vec4 far_point = canonical(far);
    if (is_finite_point(far_point) && far.w > 0.0f) {
        return glm::vec3(far_point);
    }
    const float t0 = near.w / (near.w - far.w);
    const glm::vec3 direction = glm::normalize(glm::vec3(near + t0 * (far - near)));
    return glm::vec3(canonical(near)) + direction * infinite_length_m;
}

void add_cross(std::vector<glm::vec3>& lines, const glm::vec3& center, float size_m) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 half(0.0f);
        half[axis] = size_m * 0.5f;
        lines.push_back(center - half);
        lines.push_back(center + half);
    }
}

} // namespace

std::vector<glm::vec3> frustum_lines(const frustum::MatrixPair<float>& pair, const FrustumLineStyle& style) {
    const frustum::KeyPoints<float> keys = frustum::key_points(pair);
    std::array<glm::vec3, 8> corner{};
    for (std::size_t i = 0; i < 4; ++i) {
        corner[i] = glm::vec3(canonical(keys.corners[i]));
        corner[i + 4] = side_edge_end(keys.corners[i], keys.corners[i + 4], style.infinite_length_m);
    }
    std::vector<glm::vec3> lines;
    for (std::size_t i = 0; i < 4; ++i) {
        const std::size_t next = (i + 1) % 4;
        lines.insert(lines.end(), {corner[i], corner[next]});         // near face
        lines.insert(lines.end(), {corner[i + 4], corner[next + 4]}); // far face
        lines.insert(lines.end(), {corner[i], corner[i + 4]});         // side edge
    }
    const glm::vec4 eye = canonical(keys.eye);
    if (is_finite_point(eye)) {
        for (std::size_t i = 0; i < 4; ++i) {
            lines.insert(lines.end(), {glm::vec3(eye), corner[i]});
        }
        add_cross(lines, glm::vec3(eye), style.marker_size_m);
    }
    for (const glm::vec4& key : {keys.center, keys.vanishing_y, keys.vanishing_x}) {
        const glm::vec4 point = canonical(key);
        if (is_finite_point(point)) {
            add_cross(lines, glm::vec3(point), style.marker_size_m);
        }
    }
    return lines;
}

} // namespace plan
