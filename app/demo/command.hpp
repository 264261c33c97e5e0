// The commands of frustum-demo, as bits: an option row (demo/options.hpp)
// names the commands that accept it.
#pragma once

#include <string>

namespace demo {

enum Command : unsigned {
    kRender = 1u << 0,
    kWindow = 1u << 1,
    kCurvedReport = 1u << 2,
    kLensReport = 1u << 3,
    kNonAffineReport = 1u << 4,
};

inline constexpr unsigned kReports = kCurvedReport | kLensReport | kNonAffineReport;
inline constexpr unsigned kEveryCommand = kRender | kWindow | kReports;
inline constexpr Command kCommands[] = {kRender, kWindow, kCurvedReport, kLensReport, kNonAffineReport};

// "render", "window", "curved-report", "lens-report", "nonaffine-report".
inline const char* command_name(Command command) {
    switch (command) {
    case kRender: return "render";
    case kWindow: return "window";
    case kCurvedReport: return "curved-report";
    case kLensReport: return "lens-report";
    case kNonAffineReport: return "nonaffine-report";
    }
    return "?";
}

// What a usage error ends with: " (see frustum-demo --help)" for render,
// " (see frustum-demo window --help)" for the others.
inline std::string help_hint(Command command) {
    return command == kRender ? std::string(" (see frustum-demo --help)")
                              : " (see frustum-demo " + std::string(command_name(command)) + " --help)";
}

} // namespace demo
