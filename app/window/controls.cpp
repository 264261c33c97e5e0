#include "window/controls.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <tuple>
#include <type_traits>
#include <variant>

namespace window {
namespace {

constexpr float kKeyTurnRad = 0.0872664626f;  // 5 degrees per key press
constexpr float kDragTurnRad = 0.00523598776f; // 0.3 degrees per cursor pixel
constexpr float kKeyPanFraction = 0.05f;       // of the orbit distance, per key press
constexpr float kDragPanFraction = 0.0015f;    // of the orbit distance, per cursor pixel
constexpr float kZoomStep = 0.9f;              // distance factor per key press or wheel notch
constexpr float kMirrorStepFraction = 0.05f;   // of the mirror's longer edge, per key press
constexpr float kLensPowerStep = 1.25f;        // factor per key press
constexpr float kLinkStepFraction = 0.02f;     // recursion mirrors: of the scene's radius, per key press
constexpr float kMinDistanceFraction = 0.02f;  // orbit distance limits, of the scene radius
constexpr float kMaxDistanceFraction = 10.0f;

constexpr std::size_t effect_count() { return std::size(plan::kAllEffects); }

plan::MirrorMethod next_method(plan::MirrorMethod method) {
    switch (method) {
    case plan::MirrorMethod::Oblique: return plan::MirrorMethod::Rectangle;
    case plan::MirrorMethod::Rectangle: return plan::MirrorMethod::ReflectOnly;
    case plan::MirrorMethod::ReflectOnly: return plan::MirrorMethod::Oblique;
    }
    return plan::MirrorMethod::Oblique;
}

} // namespace

ControlScene control_scene(const scene::Scene& scene) {
    ControlScene result;
    result.bounds = scene.world_bounds;
    if (scene.mirror) {
        result.mirror_size_m = std::max(glm::length(scene.mirror->a1), glm::length(scene.mirror->a2));
    }
    return result;
}

void Controls::apply(const gl::InputEvent& event, const frustum::MatrixPair<float>& main_camera, ViewerState& state) {
    std::visit(
        [&](const auto& e) {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, gl::KeyPressed>) {
                key(e, main_camera, state);
            } else if constexpr (std::is_same_v<E, gl::MouseButtonChanged>) {
                if (e.button == gl::MouseButton::Left) {
                    left_down_ = e.pressed && !e.mods.shift;
                    pan_down_ = e.pressed && e.mods.shift;
                } else {
                    pan_down_ = e.pressed;
                }
            } else if constexpr (std::is_same_v<E, gl::CursorMoved>) {
                const glm::dvec2 position(e.x, e.y);
                if (cursor_ && (left_down_ || pan_down_)) {
                    drag(position - *cursor_, main_camera, state);
                }
                cursor_ = position;
            } else if constexpr (std::is_same_v<E, gl::Scrolled>) {
                if (e.dy != 0.0) {
                    const float radius_m = bounds_radius(scene_.bounds);
                    zoom(start_orbit(main_camera, state), std::pow(kZoomStep, static_cast<float>(e.dy)),
                         kMinDistanceFraction * radius_m, kMaxDistanceFraction * radius_m);
                }
            }
            // FramebufferResized: the window loop's business.
        },
        event);
}

void Controls::drag(const glm::dvec2& delta, const frustum::MatrixPair<float>& main_camera, ViewerState& state) {
    OrbitCamera& camera = start_orbit(main_camera, state);
    const auto dx = static_cast<float>(delta.x);
    const auto dy = static_cast<float>(delta.y);
    if (pan_down_) {
        // The scene follows the cursor: drag right moves the camera left.
        const float step_m = kDragPanFraction * camera.distance_m;
        pan(camera, -dx * step_m, dy * step_m);
    } else {
        orbit(camera, -dx * kDragTurnRad, dy * kDragTurnRad);
    }
}

OrbitCamera& Controls::start_orbit(const frustum::MatrixPair<float>& main_camera, ViewerState& state) const {
    if (!state.orbit) {
        state.orbit = orbit_from_pair(main_camera, scene_.bounds);
    }
    return *state.orbit;
}

void Controls::key(const gl::KeyPressed& press, const frustum::MatrixPair<float>& main_camera, ViewerState& state) {
    if (press.key == gl::Key::Escape) {
        state.quit = true;
        return;
    }
    if (mirror_key(press, state.mirror)) {
        return;
    }
    if (press.key != gl::Key::Character) {
        return;
    }
    if (link_key(press, state.link_moves)) {
        return;
    }
    const char c = press.character;
    if (c >= '1' && c <= '9' && static_cast<std::size_t>(c - '1') < effect_count()) {
        state.effect = plan::kAllEffects[c - '1'];
    } else if (c == 'H' && !press.repeat) {
        state.show_help = !state.show_help;
    } else if (c == 'P' && !press.repeat) {
        state.show_panel = !state.show_panel;
    } else if (c == 'F' && !press.repeat) {
        state.show_inset = !state.show_inset;
    } else if (c == 'R') {
        state.orbit.reset();
    } else if (c == 'M') {
        state.mirror = MirrorPose{};
    } else if (c == 'O' && !press.repeat) {
        state.mirror_method = next_method(state.mirror_method);
    } else if (c == ',' || c == '.') {
        state.recursion_depth = std::clamp(state.recursion_depth + (c == ',' ? -1 : 1), 0, plan::kMaxRecursionDepth);
    } else if (c == '[' || c == ']') {
        state.lens_power = next_lens_power(state.lens_power, c == '[' ? -1 : 1);
    } else if (c == '=' || c == '+' || c == '-') {
        std::tie(state.tile_columns, state.tile_rows) = next_tiles(state.tile_columns, state.tile_rows, c == '-' ? -1 : 1);
    } else if (c == 'W' || c == 'A' || c == 'S' || c == 'D' || c == 'Q' || c == 'E') {
        camera_key(press, start_orbit(main_camera, state));
    }
}

// Z X: the left facing mirror out / in, C V: the right one; with Shift
// they turn instead (5 degrees per press). A push step is 2% of the scene's
// bounding radius.
bool Controls::link_key(const gl::KeyPressed& press, std::vector<plan::LinkMove>& moves) const {
    const char c = press.character;
    if ((c != 'Z' && c != 'X' && c != 'C' && c != 'V') || moves.size() < 2) {
        return false;
    }
    plan::LinkMove& move = moves[c == 'Z' || c == 'X' ? 0 : 1];
    const float sign = c == 'X' || c == 'V' ? 1.0f : -1.0f;
    if (press.mods.shift) {
        move.turn_rad += sign * kKeyTurnRad;
    } else {
        move.push_m += sign * kLinkStepFraction * bounds_radius(scene_.bounds);
    }
    return true;
}

bool Controls::camera_key(const gl::KeyPressed& press, OrbitCamera& camera) const {
    const char c = press.character;
    const float radius_m = bounds_radius(scene_.bounds);
    if (c == 'Q' || c == 'E') {
        zoom(camera, c == 'Q' ? kZoomStep : 1.0f / kZoomStep, kMinDistanceFraction * radius_m,
             kMaxDistanceFraction * radius_m);
        return true;
    }
    // W / S: up / down, A / D: left / right; with Shift the camera slides instead of turning.
    const float horizontal = c == 'A' ? -1.0f : c == 'D' ? 1.0f : 0.0f;
    const float vertical = c == 'W' ? 1.0f : c == 'S' ? -1.0f : 0.0f;
    if (press.mods.shift) {
        const float step_m = kKeyPanFraction * camera.distance_m;
        pan(camera, horizontal * step_m, vertical * step_m);
    } else {
        orbit(camera, horizontal * kKeyTurnRad, vertical * kKeyTurnRad);
    }
    return true;
}

bool Controls::mirror_key(const gl::KeyPressed& press, MirrorPose& pose) const {
    const bool arrow = press.key == gl::Key::Left || press.key == gl::Key::Right || press.key == gl::Key::Up ||
                       press.key == gl::Key::Down;
    if (!arrow || scene_.mirror_size_m <= 0.0f) {
        return arrow;
    }
    const float sign = press.key == gl::Key::Left || press.key == gl::Key::Down ? -1.0f : 1.0f;
    const bool sideways = press.key == gl::Key::Left || press.key == gl::Key::Right;
    const float step_m = kMirrorStepFraction * scene_.mirror_size_m;
    if (press.mods.shift) {
        (sideways ? pose.slide_m : pose.push_m) += sign * step_m;
    } else if (sideways) {
        pose.turn_rad -= sign * kKeyTurnRad; // Right turns clockwise seen from above
    } else {
        pose.tilt_rad -= sign * kKeyTurnRad; // Up tips the top edge away
    }
    return true;
}

std::pair<int, int> next_tiles(int columns, int rows, int step) {
    if (step > 0) {
        if (columns <= rows) {
            columns = std::max(columns, std::min(columns + 1, kMaxTiles));
        } else {
            rows = std::max(rows, std::min(rows + 1, kMaxTiles));
        }
    } else if (step < 0) {
        if (columns > rows) {
            columns = std::max(columns - 1, 1);
        } else {
            rows = std::max(rows - 1, 1);
        }
    }
    return {columns, rows};
}

float next_lens_power(float power, int step) {
    const float next = step > 0 ? power * kLensPowerStep : step < 0 ? power / kLensPowerStep : power;
    return std::clamp(next, kMinLensPower, kMaxLensPower);
}

} // namespace window
