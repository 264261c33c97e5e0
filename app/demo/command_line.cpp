#include "demo/command_line.hpp"

#include "demo/option_values.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <tuple>
#include <utility>

namespace demo {
namespace {

constexpr int kMaxSidePx = 8192;
constexpr const char* kHelpHint = " (see frustum-demo --help)";

Failure usage(std::string message) { return {ExitStatus::UsageError, std::move(message)}; }

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
            return usage("unknown effect " + quoted +
                         " (expected mirror, tiles, frustum, curved, lens, nonaffine, plain or all)");
        }
    } else if (name == "--size") {
        const auto size = parse_pair(value, kMaxSidePx);
        if (!size) {
            return usage("--size must be WxH with 1..8192 each, got " + quoted);
        }
        std::tie(r.width_px, r.height_px) = *size;
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
    } else if (const EffectOption* option = find_effect_option(name)) {
        return option->apply(r, value);
    } else {
        return usage("unknown option '" + std::string(name) + "'" + kHelpHint);
    }
    return std::nullopt;
}

bool takes_value(std::string_view name) {
    for (std::string_view known : {"--scene", "--camera", "--effect", "--size", "--backend", "--depth", "--out"}) {
        if (name == known) {
            return true;
        }
    }
    const EffectOption* option = find_effect_option(name);
    return option && option->value;
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
    if (auto failure = check_effect_settings(request)) {
        return *failure;
    }
    if (request.tile_columns > request.width_px || request.tile_rows > request.height_px) {
        return usage("--tiles " + std::to_string(request.tile_columns) + "x" + std::to_string(request.tile_rows) +
                     " needs at least one pixel per tile, but the image is " + std::to_string(request.width_px) +
                     "x" + std::to_string(request.height_px));
    }
    const bool lens = std::find(request.effects.begin(), request.effects.end(), render::Effect::Lens) !=
                      request.effects.end();
    if (lens && request.lens_grid > std::min(request.width_px, request.height_px)) {
        return usage("--lens-grid " + std::to_string(request.lens_grid) +
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
           "  frustum-demo window [options]  (the effects in an interactive window; --help there)\n"
           "  frustum-demo curved-report [options]  (curved mirror vs ray tracing; --help there)\n"
           "  frustum-demo lens-report [options]  (tiled lens vs per-pixel reference; --help there)\n"
           "  frustum-demo nonaffine-report [options]  (eq. 36 remedies vs ray casting; --help there)\n"
           "  frustum-demo --help\n"
           "\n"
           "options of render:\n"
           "  --scene FILE        glTF 2.0 file (.gltf or .glb); default: the showcase,\n"
           "                      " + default_scene() + "\n"
           "                      (found through FRUSTUM_ASSETS_DIR, compiled in at build time)\n"
           "  --camera NAME|INDEX camera by name (glTF camera, else its node) or index;\n"
           "                      default \"main\", else camera 0, else one framing the scene\n"
           "  --effect E          plain | mirror | tiles | frustum | curved | lens | nonaffine |\n"
           "                      all (default all)\n"
           "  --size WxH          image size in pixels, 1..8192 each (default 640x360)\n"
           "  --backend B         egl | osmesa (default: egl, falling back to osmesa with a note)\n"
           "  --depth D           zero_to_one: [0, 1] clip depth via clip control when the\n"
           "                      context has it, else matrices converted to [-1, 1] (default);\n"
           "                      minus_one_to_one: always the conversion\n"
           "  --out DIR           output folder, created if missing (default out)\n"
           "  --verbose           print the GL context and its KHR_debug messages\n"
           "effect options (the same in window):\n" +
           effect_options_help() +
           "Unset effect parameters are derived from the scene's bounds and the camera\n"
           "(docs/any-scene.md), so the defaults work on any scene.\n"
           "\n"
           "Writes DIR/<effect>.png per effect and, for several, DIR/contact_sheet.png;\n"
           "prints each path written. Progress goes to stderr. When an effect of\n"
           "several fails, the others and the sheet are still written, and the exit\n"
           "status is 1 with a message naming the effect.\n"
           "Exit status: 0 success, 1 runtime failure (scene, GL, output), 2 usage error.\n";
}

} // namespace demo
