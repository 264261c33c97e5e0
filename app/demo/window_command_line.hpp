// frustum-demo window's command line: the rows of the option table
// (demo/options.hpp) that window declares (frustum-demo window --help
// lists them), plus --screenshot needing --frames.
#pragma once

#include "demo/failure.hpp"
#include "demo/options.hpp"

#include <string>
#include <variant>
#include <vector>

namespace demo {

// window's settings: effects holds the first effect shown; width_px and
// height_px are the window's size in screen coordinates.
using WindowRequest = Settings;

// args[0] is "window". Usage errors are ExitStatus::UsageError with a
// one-line message naming the value, e.g. "--frames must be 1..1000000, got '0'".
std::variant<HelpRequest, WindowRequest, Failure> parse_window_command_line(const std::vector<std::string>& args);

std::string window_help_text();

} // namespace demo
