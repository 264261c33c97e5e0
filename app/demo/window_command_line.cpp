#include "demo/window_command_line.hpp"

#include "demo/option_values.hpp"

#include <charconv>
#include <iterator>
#include <string_view>
#include <tuple>
#include <utility>

namespace demo {
namespace {

constexpr int kMaxSidePx = 8192;
constexpr int kMaxFrames = 1000000;
constexpr const char* kHelpHint = " (see frustum-demo window --help)";

Failure usage(std::string message) { return {ExitStatus::UsageError, std::move(message)}; }

std::string effect_names() {
    std::string names;
    for (std::size_t i = 0; i < std::size(render::kAllEffects); ++i) {
        names += (i ? ", " : "") + std::string(render::to_string(render::kAllEffects[i]));
    }
    return names;
}

// Applies one "--name value" option; empty on success.
std::optional<Failure> apply(WindowRequest& r, std::string_view name, const std::string& value) {
    const std::string quoted = "'" + value + "'";
    if (name == "--scene") {
        r.scene_path = value;
    } else if (name == "--camera") {
        r.camera = value;
    } else if (name == "--effect") {
        const auto effect = render::parse_effect(value);
        if (!effect) {
            return usage("unknown effect " + quoted + " (expected " + effect_names() + ")");
        }
        r.effect = *effect;
    } else if (name == "--size") {
        const auto size = parse_pair(value, kMaxSidePx);
        if (!size) {
            return usage("--size must be WxH with 1..8192 each, got " + quoted);
        }
        std::tie(r.width_px, r.height_px) = *size;
    } else if (name == "--tiles") {
        const auto tiles = parse_pair(value, 16);
        if (!tiles) {
            return usage("--tiles must be NxM (columns x rows, 1..16 each), got " + quoted);
        }
        std::tie(r.tile_columns, r.tile_rows) = *tiles;
    } else if (name == "--mirror") {
        const auto method = render::parse_mirror_method(value);
        if (!method) {
            return usage("unknown mirror method " + quoted + " (expected oblique, rectangle or reflect_only)");
        }
        r.mirror = *method;
    } else if (name == "--frames") {
        r.frames = parse_count(value, kMaxFrames);
        if (!r.frames) {
            return usage("--frames must be 1.." + std::to_string(kMaxFrames) + ", got " + quoted);
        }
    } else if (name == "--msaa") {
        const auto samples = parse_count(value, kMaxMsaaOption);
        if (!samples) {
            return usage(kMsaaExpected + quoted);
        }
        r.msaa_samples = *samples;
    } else if (name == "--screenshot") {
        if (value.empty()) {
            return usage("--screenshot needs a file, got ''");
        }
        r.screenshot = value;
    } else {
        return usage("unknown option '" + std::string(name) + "' of window" + kHelpHint);
    }
    return std::nullopt;
}

bool takes_value(std::string_view name) {
    for (std::string_view known :
         {"--scene", "--camera", "--effect", "--size", "--tiles", "--mirror", "--frames", "--screenshot", "--msaa"}) {
        if (name == known) {
            return true;
        }
    }
    return false;
}

} // namespace

std::variant<HelpRequest, WindowRequest, Failure> parse_window_command_line(const std::vector<std::string>& args) {
    WindowRequest request;
    request.scene_path = default_scene();
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& name = args[i];
        if (name == "--help" || name == "-h") {
            return HelpRequest{};
        }
        if (name == "--inset" || name == "--help-overlay") {
            (name == "--inset" ? request.inset : request.help_overlay) = true;
            continue;
        }
        if (takes_value(name) && i + 1 >= args.size()) {
            return usage(name + " needs a value" + kHelpHint);
        }
        const std::string value = takes_value(name) ? args[++i] : std::string();
        if (auto failure = apply(request, name, value)) {
            return *failure;
        }
    }
    if (request.screenshot && !request.frames) {
        return usage("--screenshot needs --frames N (the screenshot is frame N)");
    }
    return request;
}

std::string window_help_text() {
    return "frustum-demo window: the effects live in a window (GLFW, OpenGL ES 3 through EGL),\n"
           "drawn by the same renderer as `frustum-demo render`.\n"
           "\n"
           "usage:\n"
           "  frustum-demo window [options]\n"
           "\n"
           "options:\n"
           "  --scene FILE        glTF 2.0 file; default: the showcase,\n"
           "                      " + default_scene() + "\n"
           "  --camera NAME|INDEX the camera to start from (default \"main\", else camera 0)\n"
           "  --size WxH          window size, 1..8192 each (default 960x540)\n"
           "  --effect E          first effect: " + effect_names() + " (default plain)\n"
           "  --tiles NxM         tiles of the tiles effect, 1..16 each (default 3x2)\n"
           "  --mirror M          oblique | rectangle | reflect_only (default oblique)\n"
           "  --inset             start with the frustum view inset shown (key F)\n"
           "  --help-overlay      start with the key help shown (key H)\n"
           "  --msaa N            multisampled anti-aliasing, N samples per pixel, 1 = off\n"
           "                      (default 4, or the most the context offers when fewer)\n"
           "  --frames N          draw N frames, then exit (for scripts and tests)\n"
           "  --screenshot FILE   with --frames: save frame N as PNG (what the window shows)\n"
           "\n"
           "Keys: H in the window lists them; see also docs/window.md.\n"
           "Needs a display (DISPLAY); without one use `frustum-demo render`, or run under\n"
           "xvfb-run. Exit status: 0 closed or done, 1 runtime failure, 2 usage error.\n";
}

} // namespace demo
