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
    } else if (name == "--max-memory-mb" || name == "--max-nodes" || name == "--max-depth" ||
               name == "--max-drawn-vertices") {
        return apply_budget_option(r.budget, name, value);
    } else if (name == "--msaa") {
        const auto samples = parse_count(value, kMaxMsaaOption);
        if (!samples) {
            return usage(kMsaaExpected + quoted);
        }
        r.msaa_samples = *samples;
    } else {
        return usage("unknown option '" + std::string(name) + "'" + kHelpHint);
    }
    return std::nullopt;
}

bool takes_value(std::string_view name) {
    for (std::string_view known : {"--scene", "--camera", "--effect", "--size", "--backend", "--depth", "--out", "--msaa",
                                   "--max-memory-mb", "--max-nodes", "--max-depth", "--max-drawn-vertices"}) {
        if (name == known) {
            return true;
        }
    }
    const EffectOption* option = find_effect_option(name);
    return option && option->value;
}

} // namespace

std::optional<Failure> apply_budget_option(scene::Budget& budget, std::string_view name,
                                           const std::string& value) {
    unsigned long long number = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
    // 2^40 MiB and 2^60 counts: far above any machine, below uint64 overflow.
    const unsigned long long most = name == "--max-memory-mb" ? (1ull << 40) : (1ull << 60);
    if (value.empty() || error != std::errc() || end != value.data() + value.size() || number < 1 ||
        number > most) {
        return usage(std::string(name) + " must be a whole number in 1.." + std::to_string(most) + ", got '" +
                     value + "'");
    }
    if (name == "--max-memory-mb") {
        budget.max_decoded_bytes = number << 20;
    } else if (name == "--max-nodes") {
        budget.max_nodes = number;
    } else if (name == "--max-depth") {
        budget.max_depth = number;
    } else {
        budget.max_drawn_vertices = number;
    }
    return std::nullopt;
}

unsigned long long output_image_bytes(int width_px, int height_px, std::size_t effects) {
    const unsigned long long w = static_cast<unsigned long long>(width_px);
    const unsigned long long h = static_cast<unsigned long long>(height_px);
    unsigned long long bytes = effects * w * h * 4;
    if (effects > 1) { // image::contact_sheet(): 2 columns, 4 px borders
        const unsigned long long rows = (effects + 1) / 2;
        bytes += (2 * (w + 4) + 4) * (rows * (h + 4) + 4) * 4;
    }
    return bytes;
}

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
    const long long tiles = static_cast<long long>(request.tile_columns) * request.tile_rows;
    if (tiles > kMaxTiles) {
        return usage("--tiles " + std::to_string(request.tile_columns) + "x" + std::to_string(request.tile_rows) +
                     " is " + std::to_string(tiles) + " tiles, over the limit of " + std::to_string(kMaxTiles));
    }
    const unsigned long long image_bytes =
        output_image_bytes(request.width_px, request.height_px, request.effects.size());
    if (image_bytes > request.budget.max_decoded_bytes) {
        return usage("--size " + std::to_string(request.width_px) + "x" + std::to_string(request.height_px) +
                     " with " + std::to_string(request.effects.size()) + " effect(s) holds " +
                     std::to_string(image_bytes >> 20) + " MiB of images (with the contact sheet), over the budget of " +
                     std::to_string(request.budget.max_decoded_bytes >> 20) +
                     " MiB (raise it with --max-memory-mb, or render fewer effects)");
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
           "                      portal | recursion | all (default all)\n"
           "  --size WxH          image size in pixels, 1..8192 each (default 640x360)\n"
           "  --backend B         egl | osmesa (default: egl, falling back to osmesa with a note)\n"
           "  --depth D           zero_to_one: [0, 1] clip depth via clip control when the\n"
           "                      context has it, else matrices converted to [-1, 1] (default);\n"
           "                      minus_one_to_one: always the conversion\n"
           "  --msaa N            multisampled anti-aliasing with N samples per pixel, 1 = off\n"
           "                      (default 4, or the most the context offers when fewer)\n"
           "  --out DIR           output folder, created if missing (default out)\n"
           "  --verbose           print the GL context and its KHR_debug messages\n"
           "  --max-memory-mb N   budget for the decoded scene (vertices, indices, images,\n"
           "                      parsed JSON) and, separately, for the output images of\n"
           "                      the run (default 256; a render peaks at about 5x the scene's)\n"
           "  --max-nodes N       most nodes, and most mesh primitives, in the file (default 100000)\n"
           "  --max-depth N       longest parent-to-child node chain (default 10000)\n"
           "  --max-drawn-vertices N  most vertices drawn per frame, over all nodes (default 33554432)\n"
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
