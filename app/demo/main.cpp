// frustum-demo: the only place that prints. Results (paths written) go to
// stdout; progress, notes and errors to stderr.
#include "demo/command_line.hpp"
#include "demo/run_render.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
    const auto parsed = demo::parse_command_line(args);
    if (const auto* failure = std::get_if<demo::Failure>(&parsed)) {
        std::cerr << "frustum-demo: error: " << failure->message << '\n';
        return static_cast<int>(failure->status);
    }
    if (std::holds_alternative<demo::HelpRequest>(parsed)) {
        std::cout << demo::help_text();
        return 0;
    }
    const auto print_line = [](std::string_view line) { std::cerr << line << '\n'; };
    const demo::Reporter reporter{print_line, [](std::string_view line) { std::cerr << "frustum-demo: " << line << '\n'; }};
    const auto outcome = demo::run_render(std::get<demo::RenderRequest>(parsed), reporter);
    if (const auto* failure = std::get_if<demo::Failure>(&outcome)) {
        std::cerr << "frustum-demo: error: " << failure->message << '\n';
        return static_cast<int>(failure->status);
    }
    for (const std::string& path : std::get<demo::RenderRun>(outcome).written_paths) {
        std::cout << path << '\n';
    }
    return 0;
}
