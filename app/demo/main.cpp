// frustum-demo: the only place that prints. Results (paths written) go to
// stdout; progress, notes and errors to stderr.
#include "demo/command_line.hpp"
#include "demo/curved_report.hpp"
#include "demo/run_render.hpp"
#include "demo/warp_reports.hpp"
#include "demo/window_main.hpp"

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>
#include <unistd.h>

namespace {

// A usage or runtime failure on stderr; its exit status.
int print_failure(const demo::Failure& failure) {
    std::cerr << "frustum-demo: error: " << failure.message << '\n';
    return static_cast<int>(failure.status);
}

// Progress lines as they are, notes with the program's name, both on stderr.
demo::Reporter stderr_reporter() {
    const auto print_line = [](std::string_view line) { std::cerr << line << '\n'; };
    return demo::Reporter{print_line, [](std::string_view line) { std::cerr << "frustum-demo: " << line << '\n'; }};
}

// A report command: its parsed command line (`Request`, --help or a usage
// failure) -> the report `run` makes, its Markdown on stdout.
template <class Request, class Parsed, class Run>
int report_main(const Parsed& parsed, const std::string& help, const Run& run) {
    if (const auto* failure = std::get_if<demo::Failure>(&parsed)) {
        return print_failure(*failure);
    }
    if (std::holds_alternative<demo::HelpRequest>(parsed)) {
        std::cout << help;
        return 0;
    }
    const auto outcome = run(std::get<Request>(parsed), stderr_reporter());
    if (const auto* failure = std::get_if<demo::Failure>(&outcome)) {
        return print_failure(*failure);
    }
    std::cout << std::get<0>(outcome).markdown;
    return 0;
}

// frustum-demo curved-report: the Markdown report on stdout, progress on stderr.
int curved_report_main(const std::vector<std::string>& args) {
    return report_main<demo::CurvedReportRequest>(demo::parse_curved_report(args), demo::curved_report_help(),
                                                  demo::run_curved_report);
}

// frustum-demo lens-report | nonaffine-report: as curved-report.
int warp_report_main(const std::vector<std::string>& args) {
    return report_main<demo::WarpReportRequest>(demo::parse_warp_report(args), demo::warp_report_help(args[0]),
                                                demo::run_warp_report);
}

int render_main(const std::vector<std::string>& args) {
    const auto parsed = demo::parse_command_line(args);
    if (const auto* failure = std::get_if<demo::Failure>(&parsed)) {
        return print_failure(*failure);
    }
    if (std::holds_alternative<demo::HelpRequest>(parsed)) {
        std::cout << demo::help_text();
        return 0;
    }
    demo::Reporter reporter = stderr_reporter();
    const auto& request = std::get<demo::RenderRequest>(parsed);
    // A long render's progress: in place on a terminal, one line each with --verbose, else quiet.
    if (isatty(STDERR_FILENO)) {
        reporter.status = [](std::string_view line) { std::cerr << "\r" << line << "\033[K" << std::flush; };
    } else if (request.verbose) {
        reporter.status = [](std::string_view line) {
            if (!line.empty()) {
                std::cerr << "frustum-demo: " << line << '\n';
            }
        };
    }
    const auto outcome = demo::run_render(request, reporter);
    if (const auto* failure = std::get_if<demo::Failure>(&outcome)) {
        return print_failure(*failure);
    }
    const auto& run = std::get<demo::RenderRun>(outcome);
    for (const std::string& path : run.written_paths) {
        std::cout << path << '\n';
    }
    for (const std::string& failure : run.failed_effects) {
        std::cerr << "frustum-demo: error: effect " << failure << '\n';
    }
    return run.failed_effects.empty() ? 0 : static_cast<int>(demo::ExitStatus::RuntimeFailure);
}

// The commands: name -> parse, run, print (args[0] is the name).
struct CommandEntry {
    const char* name;
    int (*main)(const std::vector<std::string>& args);
};
constexpr CommandEntry kCommandTable[] = {
    {"render", render_main},
    {"window", demo::window_main}, // prints its own results and errors ("frustum-demo window: ...")
    {"curved-report", curved_report_main},
    {"lens-report", warp_report_main},
    {"nonaffine-report", warp_report_main},
};

int run_main(const std::vector<std::string>& args) {
    if (args.empty()) {
        std::cerr << "frustum-demo: error: expected a command: render" << demo::help_hint(demo::kRender) << '\n';
        return static_cast<int>(demo::ExitStatus::UsageError);
    }
    if (args[0] == "--help" || args[0] == "-h") {
        std::cout << demo::help_text();
        return 0;
    }
    for (const CommandEntry& command : kCommandTable) {
        if (args[0] == command.name) {
            return command.main(args);
        }
    }
    std::cerr << "frustum-demo: error: unknown command '" << args[0] << "'" << demo::help_hint(demo::kRender) << '\n';
    return static_cast<int>(demo::ExitStatus::UsageError);
}

} // namespace

// No exception leaves main: running out of memory (a budget raised past
// what the machine has) is an error line and exit 1, not an abort.
int main(int argc, char** argv) {
    try {
        const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
        return run_main(args);
    } catch (const std::bad_alloc&) {
        std::cerr << "frustum-demo: error: out of memory while " << demo::g_activity
                  << " (lower --size or the --max-* budget options)\n";
    } catch (const std::exception& error) {
        std::cerr << "frustum-demo: error: internal error while " << demo::g_activity << ": " << error.what()
                  << '\n';
    }
    return 1;
}
