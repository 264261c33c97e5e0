#include "plan/mirror_motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace plan {
namespace {

constexpr float kRigidTolerance = 1e-4f;

std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(value));
    return text;
}

} // namespace

frustum::Status check_rigid_motion(const glm::mat4& motion, const char* where) {
    const glm::mat3 rotation(motion);
    const glm::mat3 gram = glm::transpose(rotation) * rotation;
    float worst = 0.0f; // largest deviation of R^T R from the identity
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            worst = std::max(worst, std::abs(gram[c][r] - (c == r ? 1.0f : 0.0f)));
        }
    }
    const float det = glm::determinant(rotation);
    const glm::vec4 last_row(motion[0][3], motion[1][3], motion[2][3], motion[3][3]);
    const bool last_row_ok = std::abs(last_row.x) <= kRigidTolerance && std::abs(last_row.y) <= kRigidTolerance &&
                             std::abs(last_row.z) <= kRigidTolerance &&
                             std::abs(last_row.w - 1.0f) <= kRigidTolerance;
    if (worst <= kRigidTolerance && std::abs(det - 1.0f) <= kRigidTolerance && last_row_ok) {
        return {};
    }
    return frustum::Error{std::string(where) +
                          ": motion must be rigid (det 1, orthonormal columns, last row 0 0 0 1), got det=" +
                          number(det) + " |R^T R - I|max=" + number(worst) + " last row " + number(last_row.x) +
                          " " + number(last_row.y) + " " + number(last_row.z) + " " + number(last_row.w)};
}

scene::MirrorRect moved_mirror(const scene::MirrorRect& mirror, const glm::mat4& motion) {
    scene::MirrorRect moved = mirror;
    moved.corner = glm::vec3(motion * glm::vec4(mirror.corner, 1.0f));
    moved.a1 = glm::vec3(motion * glm::vec4(mirror.a1, 0.0f));
    moved.a2 = glm::vec3(motion * glm::vec4(mirror.a2, 0.0f));
    return moved;
}

} // namespace plan
