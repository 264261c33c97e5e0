#include "bench_recursion_room.hpp"

#include <frustum/projection.hpp>
#include <plan/mirror_placement.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace bench_recursion {
namespace {

constexpr float kHalfWidthM = 3.0f, kHalfDepthM = 10.0f, kHeightM = 4.0f;
constexpr float kTileM = 0.5f;

// A quad of size (sx, sy) centred at c in the plane spanned by unit u, v.
glm::mat4 quad_world(const glm::vec3& c, const glm::vec3& u, const glm::vec3& v, float sx, float sy) {
    return glm::mat4(glm::vec4(sx * u, 0.0f), glm::vec4(sy * v, 0.0f), glm::vec4(glm::cross(u, v), 0.0f),
                     glm::vec4(c, 1.0f));
}

// A box as six quads (one draw and one culling test each).
void add_box(scene::Scene& s, const glm::vec3& c, const glm::vec3& half, const glm::vec4& color) {
    const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    plan::add_quad_instance(s, quad_world(c + half.x * X, Y, Z, 2 * half.y, 2 * half.z), color, "box");
    plan::add_quad_instance(s, quad_world(c - half.x * X, Z, Y, 2 * half.z, 2 * half.y), color, "box");
    plan::add_quad_instance(s, quad_world(c + half.y * Y, Z, X, 2 * half.z, 2 * half.x), color, "box");
    plan::add_quad_instance(s, quad_world(c - half.y * Y, X, Z, 2 * half.x, 2 * half.z), color, "box");
    plan::add_quad_instance(s, quad_world(c + half.z * Z, X, Y, 2 * half.x, 2 * half.y), color, "box");
    plan::add_quad_instance(s, quad_world(c - half.z * Z, Y, X, 2 * half.y, 2 * half.x), color, "box");
}

frustum::Frame<float> frame(const glm::vec3& origin, const glm::vec3& x) {
    frustum::Frame<float> f;
    f.origin = origin;
    f.x = x;
    f.y = glm::vec3(0.0f, 1.0f, 0.0f);
    return f;
}

} // namespace

Room make_room(int width_px, int height_px) {
    scene::Scene s;
    const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    // Floor: 0.5 m tiles in two greys.
    for (float x = -kHalfWidthM; x < kHalfWidthM - 1e-3f; x += kTileM) {
        for (float z = -kHalfDepthM; z < kHalfDepthM - 1e-3f; z += kTileM) {
            const bool dark = (static_cast<int>((x + kHalfWidthM) / kTileM) + static_cast<int>((z + kHalfDepthM) / kTileM)) % 2;
            plan::add_quad_instance(s, quad_world({x + 0.5f * kTileM, 0.0f, z + 0.5f * kTileM}, Z, X, kTileM, kTileM),
                                    dark ? glm::vec4(0.35f, 0.35f, 0.38f, 1) : glm::vec4(0.85f, 0.85f, 0.8f, 1),
                                    "floor tile");
        }
    }
    // Ceiling, the end walls, the side walls (behind the mirrors).
    const glm::vec4 wall(0.75f, 0.68f, 0.55f, 1), end(0.55f, 0.65f, 0.75f, 1);
    plan::add_quad_instance(s, quad_world({0, kHeightM, 0}, X, Z, 2 * kHalfWidthM, 2 * kHalfDepthM),
                            glm::vec4(0.9f, 0.9f, 0.9f, 1), "ceiling");
    plan::add_quad_instance(s, quad_world({0, 0.5f * kHeightM, -kHalfDepthM}, X, Y, 2 * kHalfWidthM, kHeightM), end,
                            "far wall");
    plan::add_quad_instance(s, quad_world({0, 0.5f * kHeightM, kHalfDepthM}, -X, Y, 2 * kHalfWidthM, kHeightM), end,
                            "near wall");
    plan::add_quad_instance(s, quad_world({-kHalfWidthM, 0.5f * kHeightM, 0}, -Z, Y, 2 * kHalfDepthM, kHeightM), wall,
                            "left wall");
    plan::add_quad_instance(s, quad_world({kHalfWidthM, 0.5f * kHeightM, 0}, Z, Y, 2 * kHalfDepthM, kHeightM), wall,
                            "right wall");
    // Furniture: a grid of boxes of three sizes and colours (4 x 6).
    const glm::vec4 colors[3] = {{0.2f, 0.45f, 0.85f, 1}, {0.9f, 0.6f, 0.15f, 1}, {0.25f, 0.7f, 0.35f, 1}};
    int i = 0;
    for (float x = -2.0f; x <= 2.01f; x += 4.0f / 3.0f) {
        for (float z = -8.0f; z <= 8.01f; z += 1.6f, ++i) {
            const float h = 0.25f + 0.2f * static_cast<float>(i % 3);
            add_box(s, {x, h, z}, {0.25f, h, 0.25f}, colors[i % 3]);
        }
    }
    s.world_bounds = {{-kHalfWidthM, 0.0f, -kHalfDepthM}, {kHalfWidthM, kHeightM, kHalfDepthM}};

    // The mirrors, 1 cm in front of their walls.
    plan::ViewLink left, right;
    left.entry = frame({-kHalfWidthM + 0.01f, 1.5f, 0.0f}, -Z);  // normal (-z) x y = +x
    right.entry = frame({kHalfWidthM - 0.01f, 1.5f, 0.0f}, Z);   // normal z x y = -x
    left.half_width_m = right.half_width_m = 1.5f;
    left.half_height_m = right.half_height_m = 0.9f;

    // 0.8 m from the right mirror, looking into the left one, 15 degrees off its normal.
    const glm::vec3 eye(2.2f, 1.6f, -1.0f);
    const glm::vec3 target = eye + glm::vec3(-std::cos(glm::radians(15.0f)), 0.0f, std::sin(glm::radians(15.0f)));
    auto projection = frustum::perspective<float>(glm::radians(50.0f), float(width_px) / float(height_px), 0.1f, 100.0f,
                                                  frustum::DepthRange::ZeroToOne);
    auto view = frustum::look_at<float>(eye, target, Y);
    if (!projection || !view) {
        throw std::runtime_error("room camera: " + (!projection ? projection.error() : view.error()));
    }
    return Room{std::move(s), {left, right}, frustum::compose(*projection, *view)};
}

} // namespace bench_recursion
