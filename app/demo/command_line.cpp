#include "demo/command_line.hpp"

#include <charconv>
#include <string_view>
#include <tuple>
#include <utility>

namespace demo {
namespace {

constexpr int kMaxSidePx = 8192;
constexpr const char* kHelpHint = " (see frustum-demo --help)";

std::string default_scene() { return std::string(FRUSTUM_ASSETS_DIR) + "/showcase.gltf"; }

Failure usage(std::string message) { return {ExitStatus::UsageError, std::move(message)}; }

// "640x360" -> (640, 360): two decimal numbers in [1, max] joined by 'x'.
std::optional<std::pair<int, int>> parse_pair(std::string_view text, int max) {
    const std::size_t x = text.find('x');
    if (x == std::string_view::npos) {
        return std::nullopt;
    }
    const auto number = [max](std::string_view part) -> std::optional<int> {
        int value = 0;
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (part.empty() || error != std::errc() || end != part.data() + part.size() || value < 1 || value > max) {
            return std::nullopt;
        }
        return value;
    };
    const auto first = number(text.substr(0, x));
    const auto second = number(text.substr(x + 1));
    if (!first || !second) {
        return std::nullopt;
    }
    return std::pair<int, int>(*first, *second);
}

// Applies one "--name value" option; empty on success.
std::optional<Failure> apply(RenderRequest& r, std::string_view name, const std::string& value) {
    const std::string quoted = "'" + value + "'";
    if (name == "--scene") {
        r.scene_path = value;
    } else if (name == "--camera") {
        r.camera = value;
    } else if (name == "--out") {
        if (value.empty()) {
            return usage("--out needs a folder, got ''");
        }
        r.out_dir = value;
    } else if (name == "--effect") {
        if (value == "all") {
            r.effects.assign(std::begin(render::kAllEffects), std::end(render::kAllEffects));
        } else if (const auto effect = render::parse_effect(value)) {
            r.effects = {*effect};
        } else {
            return usage("unknown effect " + quoted + " (expected mirror, tiles, frustum, plain or all)");
        }
    } else if (name == "--size") {
        const auto size = parse_pair(value, kMaxSidePx);
        if (!size) {
            return usage("--size must be WxH with 1..8192 each, got " + quoted);
        }
        std::tie(r.width_px, r.height_px) = *size;
    } else if (name == "--tiles") {
        const auto tiles = parse_pair(value, kMaxSidePx);
        if (!tiles) {
            return usage("--tiles must be NxM (columns x rows, each >= 1), got " + quoted);
        }
        std::tie(r.tile_columns, r.tile_rows) = *tiles;
    } else if (name == "--backend") {
        const auto backend = gl::parse_backend(value);
        if (!backend) {
            return usage("unknown backend " + quoted + " (expected egl or osmesa)");
        }
        r.backend = *backend;
    } else if (name == "--depth") {
        if (value == "zero_to_one") {
            r.depth = render::DepthPath::ClipControlWhenAvailable;
        } else if (value == "minus_one_to_one") {
            r.depth = render::DepthPath::MinusOneToOne;
        } else {
            return usage("unknown depth range " + quoted + " (expected zero_to_one or minus_one_to_one)");
        }
    } else if (name == "--mirror") {
        const auto method = render::parse_mirror_method(value);
        if (!method) {
            return usage("unknown mirror method " + quoted + " (expected oblique, rectangle or reflect_only)");
        }
        r.mirror = *method;
    } else {
        return usage("unknown option '" + std::string(name) + "'" + kHelpHint);
    }
    return std::nullopt;
}

bool takes_value(std::string_view name) {
    for (std::string_view known : {"--scene", "--camera", "--effect", "--tiles", "--size", "--backend", "--depth",
                                   "--mirror", "--out"}) {
        if (name == known) {
            return true;
        }
    }
    return false;
}

} // namespace

std::variant<HelpRequest, RenderRequest, Failure> parse_command_line(const std::vector<std::string>& args) {
    if (args.empty()) {
        return usage(std::string("expected a command: render") + kHelpHint);
    }
    if (args[0] == "--help" || args[0] == "-h") {
        return HelpRequest{};
    }
    if (args[0] != "render") {
        return usage("unknown command '" + args[0] + "'" + kHelpHint);
    }
    RenderRequest request;
    request.scene_path = default_scene();
    request.effects.assign(std::begin(render::kAllEffects), std::end(render::kAllEffects));
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& name = args[i];
        if (name == "--help" || name == "-h") {
            return HelpRequest{};
        }
        if (name == "--verbose") {
            request.verbose = true;
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
    if (request.tile_columns > request.width_px || request.tile_rows > request.height_px) {
        return usage("--tiles " + std::to_string(request.tile_columns) + "x" + std::to_string(request.tile_rows) +
                     " needs at least one pixel per tile, but the image is " + std::to_string(request.width_px) +
                     "x" + std::to_string(request.height_px));
    }
    return request;
}

std::string help_text() {
    return "frustum-demo: renders a glTF scene with the frustum library's effects into PNG files.\n"
           "\n"
           "usage:\n"
           "  frustum-demo render [options]\n"
           "  frustum-demo --help\n"
           "\n"
           "options of render:\n"
           "  --scene FILE        glTF 2.0 file (.gltf or .glb); default: the showcase,\n"
           "                      " + default_scene() + "\n"
           "                      (found through FRUSTUM_ASSETS_DIR, compiled in at build time)\n"
           "  --camera NAME|INDEX camera by name (glTF camera, else its node) or index;\n"
           "                      default \"main\", else camera 0, else one framing the scene\n"
           "  --effect E          plain | mirror | tiles | frustum | all (default all)\n"
           "  --tiles NxM         columns x rows of the tiles effect (default 3x2)\n"
           "  --size WxH          image size in pixels, 1..8192 each (default 640x360)\n"
           "  --backend B         egl | osmesa (default: egl, falling back to osmesa with a note)\n"
           "  --depth D           zero_to_one: [0, 1] clip depth via clip control when the\n"
           "                      context has it, else matrices converted to [-1, 1] (default);\n"
           "                      minus_one_to_one: always the conversion\n"
           "  --mirror M          reflection camera: oblique (reflect + oblique near plane,\n"
           "                      default) | rectangle (reflected eye through the mirror) |\n"
           "                      reflect_only (no near plane: shows what is behind the mirror)\n"
           "  --out DIR           output folder, created if missing (default out)\n"
           "  --verbose           print the GL context and its KHR_debug messages\n"
           "\n"
           "Writes DIR/<effect>.png per effect and, for several, DIR/contact_sheet.png;\n"
           "prints each path written. Progress goes to stderr.\n"
           "Exit status: 0 success, 1 runtime failure (scene, GL, output), 2 usage error.\n";
}

} // namespace demo
