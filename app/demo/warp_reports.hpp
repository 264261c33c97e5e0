// Two report commands that measure the warped-frustum effects against
// per-pixel references and print Markdown tables (docs/lens.md,
// docs/non-affine.md):
//
// Each takes its rows of the option table (demo/options.hpp): its own,
// the scene, size, context and budget options of render and --verbose; any
// other is refused.
//
//   frustum-demo lens-report [--grids 4,8,16,32] [--supersampling K] [--runs N]
//       [--lens-power P] [the shared options]
//     The tiled lens (paper §5.4) for each grid vs the texture-remap
//     reference (eq. 34 per pixel): error and median frame time. Writes
//     DIR/lens-<grid>.png, lens-diff-<grid>.png and lens-reference.png.
//
//   frustum-demo nonaffine-report [--edges 0,1,0.5,0.25,0.1] [--runs N] [--slit M] [--pivot M]
//       [the shared options]
//     eq. 36 naive, culled, and culled + subdivided to each edge length
//     (metres; 0 = no subdivision) vs the CPU ray cast. Writes
//     DIR/nonaffine-naive.png, nonaffine-cull.png, nonaffine-<edge>m.png,
//     nonaffine-reference.png, nonaffine-diff-cull.png and nonaffine-diff.png
//     (culled without / the last edge with subdivision, vs the reference).
#pragma once

#include "demo/command_line.hpp"
#include "demo/failure.hpp"
#include "demo/run_render.hpp"

#include <string>
#include <variant>
#include <vector>

namespace demo {

struct WarpReportRequest {
    enum class Kind { Lens, NonAffine };
    Kind kind = Kind::Lens;
    RenderRequest render;             // scene, camera, size, backend, depth, lens power, out
    std::vector<int> grids;           // lens: grid sizes, each 1..kMaxLensGrid
    std::vector<float> max_edges_m;   // nonaffine: subdivision edge lengths, 0 = none
    float slit_depth_m = 0.0f;        // nonaffine: 0 = plan::NonAffineOptions' default
    float pivot_depth_m = 0.0f;
    int supersampling = 4;            // lens reference: texture resolution / frame resolution
    int runs = 5;                     // timed repetitions (median reported)
};

// args[0] is "lens-report" or "nonaffine-report". Usage errors as
// parse_command_line()'s.
std::variant<HelpRequest, WarpReportRequest, Failure> parse_warp_report(const std::vector<std::string>& args);

std::string warp_report_help(const std::string& command);

struct WarpReport {
    std::string markdown;
    std::vector<std::string> written_paths;
};

std::variant<WarpReport, Failure> run_warp_report(const WarpReportRequest& request, const Reporter& reporter);

} // namespace demo
