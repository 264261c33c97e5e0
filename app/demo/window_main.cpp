#include "demo/window_main.hpp"

#include "demo/window_command_line.hpp"
#include "demo/window_run.hpp"

#include <iostream>

namespace demo {

int window_main(const std::vector<std::string>& args) {
    const auto parsed = parse_window_command_line(args);
    if (const auto* failure = std::get_if<Failure>(&parsed)) {
        std::cerr << "frustum-demo window: error: " << failure->message << '\n';
        return static_cast<int>(failure->status);
    }
    if (std::holds_alternative<HelpRequest>(parsed)) {
        std::cout << window_help_text();
        return 0;
    }
    const auto note = [](std::string_view line) { std::cerr << "frustum-demo window: " << line << '\n'; };
    const auto outcome = run_window(std::get<WindowRequest>(parsed), args, note);
    if (const auto* failure = std::get_if<Failure>(&outcome)) {
        std::cerr << "frustum-demo window: error: " << failure->message << '\n';
        return static_cast<int>(failure->status);
    }
    for (const std::string& path : std::get<WindowRun>(outcome).written_paths) {
        std::cout << path << '\n';
    }
    return 0;
}

} // namespace demo
