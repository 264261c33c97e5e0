// frustum-demo's command line:
//   frustum-demo render [--scene FILE] [--camera NAME|INDEX] [--effect E]
//                       [--tiles NxM] [--size WxH] [--backend egl|osmesa]
//                       [--depth zero_to_one|minus_one_to_one]
//                       [--mirror oblique|rectangle|reflect_only] [--out DIR] [--verbose]
//                       [--patches N] [--sagitta M] [--cap sphere|cylinder]
//                       [--lens-grid N] [--lens-power P] [--msaa N]
//   frustum-demo curved-report [options]   (demo/curved_report.hpp)
//   frustum-demo lens-report [options]     (demo/lens_report.hpp)
//   frustum-demo nonaffine-report [options] (demo/nonaffine_report.hpp)
//   frustum-demo --help
#pragma once

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

struct RenderRequest {
    std::string scene_path;            // default: FRUSTUM_ASSETS_DIR/showcase.gltf
    std::optional<std::string> camera; // name or index; default "main", else camera 0
    std::vector<render::Effect> effects; // --effect all: every effect, in kAllEffects order
    int tile_columns = 3, tile_rows = 2;
    int width_px = 640, height_px = 360;
    std::optional<gl::Backend> backend; // unset: EGL, falling back to OSMesa with a note
    render::DepthPath depth = render::DepthPath::ClipControlWhenAvailable;
    render::MirrorMethod mirror = render::MirrorMethod::Oblique;
    render::CurvedMirrorOptions curved; // --patches, --sagitta, --cap
    int lens_grid = 16;                 // --lens-grid: tiles per side of the lens effect
    float lens_power = 2.0f;            // --lens-power: p of eq. 34
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

// Applies --patches N (1..64), --sagitta M (metres, >= 0) or --cap
// sphere|cylinder; a usage Failure names the value. Shared with curved-report.
std::optional<Failure> apply_curved_option(render::CurvedMirrorOptions& curved, std::string_view name,
                                           const std::string& value);

// Applies --lens-grid N (1..kMaxLensGrid) or --lens-power P (0 < P <=
// kMaxLensPower); a usage Failure names the value. Shared with lens-report.
// The bounds are where every tile of eq. 34 stays a valid frustum in single
// precision (measured on the showcase at 64x64 .. 2048x512: power 3 breaks
// at grid 128, power 2 at grid 256, power 5 already at grid 16).
inline constexpr int kMaxLensGrid = 128;
inline constexpr float kMaxLensPower = 2.0f;
// Most tiles of the tiles effect (columns x rows): 128 x 128.
inline constexpr long long kMaxTiles = 16384;

// Applies --max-memory-mb, --max-nodes, --max-depth or --max-drawn-vertices
// (whole numbers >= 1) to `budget`; shared with the window command.
std::optional<Failure> apply_budget_option(scene::Budget& budget, std::string_view name,
                                           const std::string& value);

// The bytes a render run holds at once: one RGBA8 image per effect plus
// the contact sheet when there are several (2 columns, 4 px borders).
unsigned long long output_image_bytes(int width_px, int height_px, std::size_t effects);
std::optional<Failure> apply_lens_option(RenderRequest& request, std::string_view name, const std::string& value);

} // namespace demo
