#include "demo/command_line.hpp"

#include "demo/option_values.hpp"
#include "demo/poster_file.hpp"

#include <algorithm>
#include <utility>

namespace demo {
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
    auto parsed = parse_options(kRender, args);
    if (auto early = failure_or_help<std::variant<HelpRequest, RenderRequest, Failure>>(parsed)) {
        return *early;
    }
    RenderRequest& request = std::get<Settings>(parsed);
    if (request.tile_columns > request.width_px || request.tile_rows > request.height_px) {
        return usage("--tiles " + std::to_string(request.tile_columns) + "x" + std::to_string(request.tile_rows) +
                     " needs at least one pixel per tile, but the image is " + std::to_string(request.width_px) +
                     "x" + std::to_string(request.height_px));
    }
    // A poster (above one target, or --poster-tile) is streamed to its file:
    // only its contact-sheet thumbnail is held.
    const bool poster = request.poster || request.width_px > kMaxDirectSidePx ||
                        request.height_px > kMaxDirectSidePx;
    const int held_factor = poster ? (std::max(request.width_px, request.height_px) + kPosterThumbnailSidePx - 1) /
                                         kPosterThumbnailSidePx
                                   : 1;
    const unsigned long long image_bytes =
        output_image_bytes((request.width_px + held_factor - 1) / held_factor,
                           (request.height_px + held_factor - 1) / held_factor, request.effects.size());
    if (image_bytes > request.budget.max_decoded_bytes) {
        return usage("--size " + std::to_string(request.width_px) + "x" + std::to_string(request.height_px) +
                     " with " + std::to_string(request.effects.size()) + " effect(s) holds " +
                     std::to_string(image_bytes >> 20) + " MiB of images (with the contact sheet), over the budget of " +
                     std::to_string(request.budget.max_decoded_bytes >> 20) +
                     " MiB (raise it with --max-memory-mb, or render fewer effects)");
    }
    const bool lens = std::find(request.effects.begin(), request.effects.end(), plan::Effect::Lens) !=
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
           "options of render:\n" +
           options_help(kRender, false) + "effect options (the same in window):\n" + options_help(kRender, true) +
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
