// frustum-demo render's command line: the rows of the option table
// (demo/options.hpp) that render declares, plus the checks that need several
// of them (tiles and lens grid within the image, the output images within
// --max-memory-mb).
//   frustum-demo render [options]          (frustum-demo --help lists them)
//   frustum-demo window [options]          (demo/window_command_line.hpp)
//   frustum-demo curved-report [options]   (demo/curved_report.hpp)
//   frustum-demo lens-report, nonaffine-report [options] (demo/warp_reports.hpp)
//   frustum-demo --help
#pragma once

#include "demo/failure.hpp"
#include "demo/options.hpp"

#include <string>
#include <variant>
#include <vector>

namespace demo {

// render's settings: --effect all (the default) is every effect, in
// plan::kAllEffects order.
using RenderRequest = Settings;

// args[0] is "render". Every usage error is ExitStatus::UsageError with a
// one-line message that names the value, e.g. "--size must be WxH with
// 1..8192 each, got '0x10'".
std::variant<HelpRequest, RenderRequest, Failure> parse_command_line(const std::vector<std::string>& args);

std::string help_text();

// The bytes a render run holds at once: one RGBA8 image per effect plus
// the contact sheet when there are several (2 columns, 4 px borders).
unsigned long long output_image_bytes(int width_px, int height_px, std::size_t effects);
} // namespace demo
