// frustum-demo's command line:
//   frustum-demo render [--scene FILE] [--camera NAME|INDEX] [--effect E]
//                       [--size WxH] [--backend egl|osmesa]
//                       [--depth zero_to_one|minus_one_to_one] [--out DIR] [--verbose]
//                       [--max-memory-mb N] [--max-nodes N] [--max-depth N] [--max-drawn-vertices N]
//                       [the effect options of demo/effect_options.hpp]
//   frustum-demo window [options]          (demo/window_command_line.hpp)
//   frustum-demo curved-report [options]   (demo/curved_report.hpp)
//   frustum-demo lens-report, nonaffine-report [options] (demo/warp_reports.hpp)
//   frustum-demo --help
#pragma once

#include "demo/effect_options.hpp"
#include "demo/failure.hpp"

#include <gl/context.hpp>
#include <gl/offscreen_target.hpp>
#include <render/curved_mirror.hpp>
#include <render/depth_policy.hpp>
#include <render/effect.hpp>
#include <scene/load_gltf.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace demo {

// The effect options (tiles, mirror, curved, lens, nonaffine) come from
// EffectSettings, shared with the window.
struct RenderRequest : EffectSettings {
    std::string scene_path;            // default: FRUSTUM_ASSETS_DIR/showcase.gltf
    std::optional<std::string> camera; // name or index; default "main", else camera 0
    std::vector<render::Effect> effects; // --effect all: every effect, in kAllEffects order
    int width_px = 640, height_px = 360;
    std::optional<gl::Backend> backend; // unset: EGL, falling back to OSMesa with a note
    render::DepthPath depth = render::DepthPath::ClipControlWhenAvailable;
    std::string out_dir = "out";
    bool verbose = false;
    // --max-memory-mb (also bounds the run's output images), --max-nodes,
    // --max-depth, --max-drawn-vertices.
    scene::Budget budget;
    int msaa_samples = gl::kAutomaticSamples; // --msaa N; default 4 or the context's maximum
};

struct HelpRequest {};

// Every usage error is ExitStatus::UsageError with a one-line message that
// names the value, e.g. "--size must be WxH with 1..8192 each, got '0x10'".
std::variant<HelpRequest, RenderRequest, Failure> parse_command_line(const std::vector<std::string>& args);

std::string help_text();

// Most tiles of the tiles effect (columns x rows): 128 x 128.
inline constexpr long long kMaxTiles = 16384;

// Applies --max-memory-mb, --max-nodes, --max-depth or --max-drawn-vertices
// (whole numbers >= 1) to `budget`; shared with the window command.
std::optional<Failure> apply_budget_option(scene::Budget& budget, std::string_view name,
                                           const std::string& value);

// The bytes a render run holds at once: one RGBA8 image per effect plus
// the contact sheet when there are several (2 columns, 4 px borders).
unsigned long long output_image_bytes(int width_px, int height_px, std::size_t effects);
} // namespace demo
