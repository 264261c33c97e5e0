// The window's user camera: an orbit (yaw, pitch, distance) around a target
// point, built as a matrix pair with frustum::look_at and frustum::compose.
// Pure math: no GL, no GLFW.
//
// The orbit starts from the scene's main camera (orbit_from_pair); until the
// user moves, the window draws with that camera's own pair, not this one
// (see controls.hpp), so an untouched window matches `frustum-demo render`.
#pragma once

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>

namespace window {

// Pitch stays within +-85 degrees, so the view never looks straight up or
// down, where look_at's up vector (+Y) would be parallel to it.
inline constexpr float kMaxPitchRad = 1.48352986f; // 85 degrees

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float distance_m = 1.0f; // eye to target
    float yaw_rad = 0.0f;    // about +Y; 0 puts the eye on the +Z side of the target
    float pitch_rad = 0.0f;  // eye elevation seen from the target, in [-kMaxPitchRad, kMaxPitchRad]

    // target + distance (cos p sin y, sin p, cos p cos y)
    glm::vec3 eye() const;
    // Unit vector from the eye to the target.
    glm::vec3 forward() const;
};

// The projection the orbit draws with (vertical fov; the aspect comes from
// the framebuffer each frame).
struct OrbitProjection {
    float yfov_rad = 0.785398163f; // 45 degrees, as plan::framing_camera
    // The scene camera's near and far (far unset: infinite). near unset:
    // fitted to the scene's bounding sphere from the current distance, as
    // plan::framing_camera does: near (d - r) / 2 (at least r / 1000),
    // far d + 2 r.
    std::optional<float> near_m;
    std::optional<float> far_m;
};

// The orbit that looks the way `camera` does: eye from its key points (for
// an orthographic camera, a point on its axis), direction from its near
// plane; the target on that axis at the depth of the centre of `bounds`
// (at least a tenth of the bounds' radius ahead). Roll is dropped and the
// pitch clamped to kMaxPitchRad.
OrbitCamera orbit_from_pair(const frustum::MatrixPair<float>& camera, const scene::Bounds& bounds);

// The main camera's fov, near and far when it is a perspective glTF camera
// (index into scene.cameras), else the default (45 degrees, depth fitted).
OrbitProjection orbit_projection(const scene::Scene& scene, int main_camera);

// Radius of the sphere around `bounds` (half its diagonal; 1 m for a point).
float bounds_radius(const scene::Bounds& bounds);

// Turns the eye around the target; the pitch is clamped.
void orbit(OrbitCamera& camera, float yaw_delta_rad, float pitch_delta_rad);
// Moves eye and target together along the view's right and up directions.
void pan(OrbitCamera& camera, float right_m, float up_m);
// distance *= factor (> 0), kept within [min_m, max_m].
void zoom(OrbitCamera& camera, float factor, float min_m, float max_m);

// perspective(yfov, aspect, near, far, ZeroToOne) composed with
// look_at(eye, target, +Y). Errors come from the frustum library, prefixed
// "window::orbit_pair(): ".
frustum::Result<frustum::MatrixPair<float>> orbit_pair(const OrbitCamera& camera, const OrbitProjection& projection,
                                                       float aspect, const scene::Bounds& bounds);

} // namespace window
