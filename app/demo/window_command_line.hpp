// frustum-demo's window command line:
//   frustum-demo window [--scene FILE] [--camera NAME|INDEX] [--size WxH]
//                       [--effect E] [--inset] [--help-overlay]
//                       [--frames N [--screenshot FILE]] [--keys LIST]
//                       [the effect options of demo/effect_options.hpp]
#pragma once

#include "demo/command_line.hpp"
#include "demo/failure.hpp"

#include <gl/window_input.hpp>
#include <render/effect.hpp>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace demo {

// The effect options come from EffectSettings, shared with render.
struct WindowRequest : EffectSettings {
    std::string scene_path;            // default: FRUSTUM_ASSETS_DIR/showcase.gltf
    std::optional<std::string> camera; // name or index; default "main", else camera 0
    render::Effect effect = render::Effect::Plain;
    int width_px = 960, height_px = 540; // window size in screen coordinates
    bool inset = false;        // start with the frustum view inset shown
    bool help_overlay = false; // start with the key help shown
    std::optional<int> frames;             // draw this many frames, then exit
    std::optional<std::string> screenshot; // with frames: the last frame as PNG
    int msaa_samples = 0; // --msaa N; 0 = gl::kAutomaticSamples: 4 or the context's maximum
    std::vector<gl::KeyPressed> keys;      // --keys: pressed one per frame, from the first frame on
};

// args[0] is "window". Usage errors are ExitStatus::UsageError with a
// one-line message naming the value, e.g. "--frames must be 1..1000000, got '0'".
std::variant<HelpRequest, WindowRequest, Failure> parse_window_command_line(const std::vector<std::string>& args);

std::string window_help_text();

} // namespace demo
