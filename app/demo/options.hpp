// frustum-demo's one option table: every option of every command
// (render, window, curved-report, lens-report, nonaffine-report) is one row
// here, or one row of the effect section (demo/effect_options.hpp). The rows
// give the parser, the usage errors and the --help lines of each command,
// so an option shared by several commands is declared once and means the
// same in all of them, and a command refuses every option it does not
// declare. Adding an option is adding a row (and its field in Settings or
// plan::EffectParams).
#pragma once

#include "demo/command.hpp"
#include "demo/effect_options.hpp"
#include "demo/failure.hpp"

#include <gl/context.hpp>
#include <gl/offscreen_target.hpp>
#include <gl/window_input.hpp>
#include <render/depth_policy.hpp>
#include <render/session.hpp>
#include <plan/effect.hpp>
#include <scene/load_gltf.hpp>

#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace demo {

// What the options set, for every command (each reads the fields of the
// options it declares). The defaults are those of render; defaults(command)
// gives each command's own.
// The session's values (every command: --scene, --camera, --size,
// --verbose, the --max-* budget) are render::SessionSettings'.
struct Settings : plan::EffectParams, render::SessionSettings {
    // Offscreen commands (render and the reports).
    std::optional<gl::Backend> backend; // --backend; unset: EGL, falling back to OSMesa with a note
    render::DepthPath depth = render::DepthPath::ClipControlWhenAvailable; // --depth
    std::string out_dir = "out";        // --out
    // render and window.
    std::vector<plan::Effect> effects; // --effect (window: one, the first shown)
    int msaa_samples = gl::kAutomaticSamples; // --msaa N; default 4 or the context's maximum
    // render.
    // --poster-tile WxH | auto: a poster in tiles of this size, or of the
    // automatic layout's (render::poster_layout()) even when one target holds the frame.
    bool poster = false;
    std::optional<std::pair<int, int>> poster_tile_px; // WxH; empty for auto
    // window.
    gl::Api context_api = gl::Api::Gles;   // --context es|gl: the window's OpenGL ES or desktop core context
    bool inset = false;                    // --inset: start with the frustum view inset shown
    bool help_overlay = false;             // --help-overlay: start with the key help shown
    bool panel = false;                    // --panel: start with the control panel shown
    std::optional<int> frames;             // --frames: draw this many frames, then exit
    std::optional<std::string> screenshot; // --screenshot: with frames, the last frame as PNG
    std::vector<gl::KeyPressed> keys;      // --keys: pressed one per frame, from the first frame on
    // The reports.
    std::vector<int> patch_counts = {1, 2, 4, 8, 16};              // curved-report --patches LIST
    std::vector<int> grids = {4, 8, 16, 32};                       // lens-report --grids
    int supersampling = 4;                                         // lens-report --supersampling
    std::vector<float> max_edges_m = {0.0f, 1.0f, 0.5f, 0.25f, 0.1f}; // nonaffine-report --edges
    int runs = 5;                                                  // lens-, nonaffine-report --runs
};

// Each command's defaults: render every effect at 640x360, the window the
// plain effect at 960x540.
Settings defaults(Command command);

struct Option {
    std::string name;                 // "--size"
    const char* value;                // "WxH" for the help line; nullptr: a flag without a value
    std::string help;                 // what follows the name in --help ('\n' starts an indented line)
    // Applies the value (a flag gets ""); a usage Failure naming the value when it is wrong.
    std::function<std::optional<Failure>(Settings&, const std::string&)> apply;
    unsigned commands;                // the Command bits that accept the option
    const char* example;              // a value the row accepts; nullptr for a flag
    bool effect_row;                  // from effect_options(): listed under "effect options"
    PanelControl control = {};        // the window panel's widget (demo/effect_options.hpp)
};

// Every row, the effect section last. A name appears in several rows only
// for disjoint commands (e.g. --size of render and of window: one value
// parser, two help lines).
const std::vector<Option>& options();

// The row named `name` that `command` accepts; nullptr for any other.
const Option* find_option(Command command, const std::string& name);

struct HelpRequest {};

// args[0] is the command's name. Usage errors are ExitStatus::UsageError
// with one line naming the value; an option of another command "does not
// apply to" this one; checks that need several options are the caller's.
std::variant<HelpRequest, Settings, Failure> parse_options(Command command, const std::vector<std::string>& args);

// parse_options()'s usage failure or --help as a command's own parse result
// (`Parsed`, a variant holding both); empty when it gave settings.
template <class Parsed>
std::optional<Parsed> failure_or_help(const std::variant<HelpRequest, Settings, Failure>& parsed) {
    if (const auto* failure = std::get_if<Failure>(&parsed)) {
        return Parsed{*failure};
    }
    if (std::holds_alternative<HelpRequest>(parsed)) {
        return Parsed{HelpRequest{}};
    }
    return std::nullopt;
}

// The --help lines of `command`'s rows, "  --slit M            ...": the
// effect rows when `effect_rows`, the others otherwise.
std::string options_help(Command command, bool effect_rows);

// "plain, mirror, tiles, ..." (plan::kAllEffects, in order).
std::string effect_names();

} // namespace demo
