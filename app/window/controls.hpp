// Keyboard and mouse -> what the window shows. Pure: events come in as
// gl::InputEvent values, so tests drive it without a window.
#pragma once

#include "window/mirror_pose.hpp"
#include "window/orbit_camera.hpp"

#include <frustum/matrix_pair.hpp>
#include <gl/window_input.hpp>
#include <plan/effect.hpp>
#include <plan/effect_params.hpp>
#include <plan/link_moves.hpp>
#include <plan/view_tree.hpp>
#include <render/depth_policy.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace window {

inline constexpr int kMaxTiles = 16; // per direction
// Lens power (paper eq. 34's p) stays within [kMinLensPower, kMaxLensPower]:
// the upper end is --lens-power's bound (demo::kMaxLensPower, asserted
// equal where both are seen, app/demo/window_run.cpp).
inline constexpr float kMinLensPower = 0.25f;
inline constexpr float kMaxLensPower = 2.0f;

// What the window shows; Controls::apply() changes it.
// The effect values (plan/effect_params.hpp: their defaults stated there
// once; the keys change tiles, mirror method, lens power and recursion
// depth) and what only the window has.
struct ViewerState : plan::EffectParams {
    plan::Effect effect = plan::Effect::Plain;
    // Unset: the scene's main camera pair exactly (no camera input yet, or
    // after R). Set on the first camera input, starting where that camera is.
    std::optional<OrbitCamera> orbit;
    MirrorPose mirror;
    // Recursion effect: the left [0] and right [1] facing mirror, each moved
    // on its own (keys Z X, C V; with Shift turned) after the frame places them.
    std::vector<plan::LinkMove> link_moves = std::vector<plan::LinkMove>(2);
    bool show_help = false;
    bool show_panel = false; // the control panel (key P; --panel starts with it)
    bool show_inset = false; // the frustum view in a corner
    int msaa_samples = 0;    // gl::choose_samples(): 0 = 4 or the context's maximum, 1 = off
    render::DepthPath depth = render::DepthPath::ClipControlWhenAvailable; // --depth
    bool quit = false;
};

// What the controls need to know about the scene.
struct ControlScene {
    scene::Bounds bounds;
    // Longer edge of the mirror; 0 = no mirror (the mirror keys do nothing).
    float mirror_size_m = 0.0f;
};

ControlScene control_scene(const scene::Scene& scene);

class Controls {
public:
    explicit Controls(const ControlScene& scene) : scene_(scene) {}

    // `main_camera`: the scene's camera this frame, where orbiting starts.
    void apply(const gl::InputEvent& event, const frustum::MatrixPair<float>& main_camera, ViewerState& state);

private:
    void key(const gl::KeyPressed& press, const frustum::MatrixPair<float>& main_camera, ViewerState& state);
    bool camera_key(const gl::KeyPressed& press, OrbitCamera& orbit) const;
    bool mirror_key(const gl::KeyPressed& press, MirrorPose& pose) const;
    bool link_key(const gl::KeyPressed& press, std::vector<plan::LinkMove>& moves) const;
    OrbitCamera& start_orbit(const frustum::MatrixPair<float>& main_camera, ViewerState& state) const;
    void drag(const glm::dvec2& delta, const frustum::MatrixPair<float>& main_camera, ViewerState& state);

    ControlScene scene_;
    bool left_down_ = false;
    bool pan_down_ = false; // right or middle button, or Shift + left
    std::optional<glm::dvec2> cursor_;
};

// The tile grid after '+' (step 1) or '-' (step -1): a column is added
// when there are no more columns than rows, else a row (3x2 -> 3x3 -> 4x3),
// and '-' undoes it; '+' adds up to kMaxTiles per direction and never
// lowers a larger grid given with --tiles (at most demo::kMaxTileSide).
std::pair<int, int> next_tiles(int columns, int rows, int step);

// The lens power after ']' (step 1: times 1.25) or '[' (step -1: divided by
// 1.25), kept within [kMinLensPower, kMaxLensPower].
float next_lens_power(float power, int step);

} // namespace window
