#include "support.hpp"

#include "../skips.hpp"

#include <doctest/doctest.h>

#include <gl/context.hpp>

#include <algorithm>

namespace rob {

namespace fs = std::filesystem;

std::vector<std::string> list_dir(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(dir, error)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

Isolated isolated(const std::function<std::string()>& work, unsigned timeout_s) {
    const support::Outcome child = support::run_function("work isolated in a child", work, int(timeout_s));
    Isolated result;
    result.value = child.value;
    result.finished = child.exit_status == 0 && !child.timed_out;
    if (child.timed_out) {
        result.how = "killed after the timeout of " + std::to_string(timeout_s) + " s";
    } else if (child.signal != 0) {
        result.how = "killed by signal " + std::to_string(child.signal);
    } else if (!result.finished) {
        result.how = "exit status " + std::to_string(child.exit_status);
    }
    if (!result.finished && !child.err.empty()) result.how += "; stderr: " + child.err.substr(0, 2000);
    return result;
}

bool no_gl() {
    static const std::string why_not = [] {
        const auto context = gl::create_offscreen_context_with_fallback({});
        return context.ok() ? std::string() : context.error();
    }();
    if (!why_not.empty()) {
        test_skips::skip(why_not);
    }
    return !why_not.empty();
}

support::Outcome run_checked(const std::string& program, const support::Launch& launch, int exit_status,
                             bool no_stdout) {
    support::Outcome r = support::run(program, launch);
    CAPTURE(r.err);
    CHECK(r.signal == 0);
    CHECK(r.exit_status == exit_status);
    if (no_stdout) CHECK_MESSAGE(r.out.empty(), "stdout must be empty, got: ", r.out.substr(0, 200));
    return r;
}

support::Outcome run_checked(const std::string& program, const std::vector<std::string>& args, int exit_status,
                             bool no_stdout, const std::string& stdin_text) {
    support::Launch launch;
    launch.args = args;
    launch.stdin_text = stdin_text;
    return run_checked(program, launch, exit_status, no_stdout);
}

} // namespace rob
