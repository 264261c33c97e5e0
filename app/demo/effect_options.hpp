// The effect options, the effect section of frustum-demo's one option table
// (demo/options.hpp): each row is a name, its value's shape, its help line,
// the function that applies it, the commands that accept it (render and
// window unless the row says otherwise) and a value it accepts (for the test
// that walks the table). Every command parses and lists them through the
// same table, so they have the same bounds and messages everywhere.
#pragma once

#include "demo/command.hpp"
#include "demo/failure.hpp"

#include <plan/effect_params.hpp>
#include <plan/view_tree.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace demo {

// --lens-grid N (1..kMaxLensGrid) and --lens-power P (0 < P <= kMaxLensPower):
// the bounds where every tile of eq. 34 stays a valid frustum in single
// precision (measured on the showcase at 64x64 .. 2048x512: power 3 breaks
// at grid 128, power 2 at grid 256, power 5 already at grid 16).
inline constexpr int kMaxLensGrid = 128;
inline constexpr float kMaxLensPower = 2.0f;
// --tiles NxM: each count 1..kMaxTileSide, at most kMaxTiles tiles (128 x
// 128) in all, the same in render and window (the window's + and - keys
// step within 1..16 per direction, but a larger start stays as given).
inline constexpr int kMaxTileSide = 8192;
inline constexpr long long kMaxTiles = 16384;

// What the effect options set is plan::EffectParams (plan/effect_params.hpp:
// every effect value and its default, once); demo::Settings, what every
// command's options set, is those plus the others. Unset parameters are
// derived from the scene by plan::resolve_effects() (docs/any-scene.md).

// How the window's panel (demo/window_panel.hpp) edits a row with a value:
// a slider per component over [low, high] (the row's own bounds; a value
// the row refuses, e.g. an open end, shows the row's message in the
// panel), or one of `choices`. Rows without a control (Kind::None) are not
// in the panel; flags (value nullptr) are checkboxes.
struct PanelControl {
    enum class Kind { None, Slider, Choice, SceneCamera } kind = Kind::None; // SceneCamera: the scene's cameras
    float low = 0.0f, high = 0.0f;
    bool whole = false;        // whole numbers
    bool logarithmic = false;  // a slider whose range spans decades
    int components = 1;        // "NxM": 2 with separator 'x'; "x,y": 2 with ','
    char separator = ',';
    const char* choices = nullptr; // Kind::Choice: "oblique|rectangle|reflect_only"
};

// A slider over [low, high]; a choice among "a|b|c"; one of the scene's cameras.
constexpr PanelControl slider(float low, float high, bool whole = false, bool logarithmic = false,
                              int components = 1, char separator = ',') {
    return {PanelControl::Kind::Slider, low, high, whole, logarithmic, components, separator, nullptr};
}
constexpr PanelControl choice(const char* choices) {
    return {PanelControl::Kind::Choice, 0.0f, 0.0f, false, false, 1, ',', choices};
}
constexpr PanelControl scene_camera() {
    return {PanelControl::Kind::SceneCamera, 0.0f, 0.0f, false, false, 1, ',', nullptr};
}

struct EffectOption {
    const char* name;  // "--slit"
    const char* value; // "M" for the help line; nullptr: a flag without a value
    const char* help;  // what follows the name in --help (may hold '\n' + indent for more lines)
    // Applies the value; a usage Failure naming the value when it is out of range.
    std::optional<Failure> (*apply)(plan::EffectParams& settings, const std::string& value);
    unsigned commands = kRender | kWindow; // Command bits
    const char* example = nullptr;         // a value the row accepts (tests/cli/demo_options_test.cpp)
    PanelControl control = {};             // the window panel's widget
};

const std::vector<EffectOption>& effect_options();

// The row named `name`; nullptr for any other name.
const EffectOption* find_effect_option(std::string_view name);

// Checks that need several options together (--mirror-plane and
// --mirror-rect are exclusive; --tiles within kMaxTiles in all).
std::optional<Failure> check_effect_settings(const plan::EffectParams& settings);

} // namespace demo
