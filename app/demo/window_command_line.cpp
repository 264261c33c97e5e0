#include "demo/window_command_line.hpp"

#include "demo/option_values.hpp"

#include <cctype>
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

// "1,Shift+Left,+,h": one key press per item (letters in either case).
std::optional<std::vector<gl::KeyPressed>> parse_keys(std::string_view text) {
    std::vector<gl::KeyPressed> keys;
    while (!text.empty()) {
        // "," alone is the comma key only as the last item; items are split at the first comma after their first character.
        const std::size_t comma = text.find(',', 1);
        std::string_view item = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
        gl::KeyPressed key;
        if (item.size() > 6 && item.substr(0, 6) == "Shift+") {
            key.mods.shift = true;
            item.remove_prefix(6);
        }
        if (item == "Left" || item == "Right" || item == "Up" || item == "Down" || item == "Esc") {
            key.key = item == "Left" ? gl::Key::Left : item == "Right" ? gl::Key::Right : item == "Up" ? gl::Key::Up
                      : item == "Down" ? gl::Key::Down : gl::Key::Escape;
        } else if (item.size() == 1 && item[0] > ' ' && item[0] < 127) {
            key.key = gl::Key::Character;
            key.character = static_cast<char>(std::toupper(static_cast<unsigned char>(item[0])));
        } else {
            return std::nullopt;
        }
        keys.push_back(key);
    }
    if (keys.empty()) {
        return std::nullopt;
    }
    return keys;
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
    } else if (name == "--keys") {
        auto keys = parse_keys(value);
        if (!keys) {
            return usage("--keys must be a comma-separated list of keys (a character, Left, Right, Up, Down, "
                         "Esc, Shift+KEY), got " + quoted);
        }
        r.keys = std::move(*keys);
    } else if (const EffectOption* option = find_effect_option(name)) {
        return option->apply(r, value);
    } else {
        return usage("unknown option '" + std::string(name) + "' of window" + kHelpHint);
    }
    return std::nullopt;
}

bool takes_value(std::string_view name) {
    for (std::string_view known :
         {"--scene", "--camera", "--effect", "--size", "--frames", "--screenshot", "--keys", "--msaa"}) {
        if (name == known) {
            return true;
        }
    }
    const EffectOption* option = find_effect_option(name);
    return option && option->value;
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
    if (auto failure = check_effect_settings(request)) {
        return *failure;
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
           "  --inset             start with the frustum view inset shown (key F)\n"
           "  --help-overlay      start with the key help shown (key H)\n"
           "  --msaa N            multisampled anti-aliasing, N samples per pixel, 1 = off\n"
           "                      (default 4, or the most the context offers when fewer)\n"
           "  --frames N          draw N frames, then exit (for scripts and tests)\n"
           "  --screenshot FILE   with --frames: save frame N as PNG (what the window shows)\n"
           "  --keys LIST         press these keys, one per frame from the first (for tests):\n"
           "                      e.g. 1,7,Shift+Left,+,H (a character, Left, Right, Up, Down, Esc)\n"
           "effect options (the same as in render):\n" +
           effect_options_help() +
           "Unset effect parameters are derived from the scene and the camera of each\n"
           "frame (docs/any-scene.md). An effect that cannot be drawn from the current\n"
           "camera keeps the previous one on screen and says why in the overlay.\n"
           "\n"
           "Keys: H in the window lists them; see also docs/window.md.\n"
           "Needs a display (DISPLAY); without one use `frustum-demo render`, or run under\n"
           "xvfb-run. Exit status: 0 closed or done, 1 runtime failure, 2 usage error.\n";
}

} // namespace demo
