// frustum-demo curved-report: the curved mirror (paper §4.3) rendered with
// G x G patches for several G and compared against a per-pixel ray-traced
// reference, with the fit's iterations and objective per patch.
//   frustum-demo curved-report [--patches 1,2,4,8,16] [--sagitta M] [--cap C]
//       [the scene, size, context and budget options of render, --verbose]
// (its rows of the option table, demo/options.hpp; any other is refused).
// Writes DIR/curved-<G>.png, curved-diff-<G>.png and curved-reference.png
// (cropped to the mirror) and prints a Markdown report on stdout.
#pragma once

#include "demo/command_line.hpp"
#include "demo/failure.hpp"
#include "demo/run_render.hpp"

#include <string>
#include <variant>
#include <vector>

namespace demo {

struct CurvedReportRequest {
    RenderRequest render;          // scene, camera, size, backend, depth, curved options, out
    std::vector<int> patch_counts; // G values, each 1..64
};

// args[0] is "curved-report". Usage errors as parse_command_line()'s.
std::variant<HelpRequest, CurvedReportRequest, Failure> parse_curved_report(const std::vector<std::string>& args);

std::string curved_report_help();

struct CurvedReport {
    std::string markdown;                   // the tables
    std::vector<std::string> written_paths; // PNG files, in the order written
};

std::variant<CurvedReport, Failure> run_curved_report(const CurvedReportRequest& request, const Reporter& reporter);

} // namespace demo
