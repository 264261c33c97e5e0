#include "support.hpp"

#include "../skips.hpp"

#include <doctest/doctest.h>

#include <gl/context.hpp>

#include <algorithm>
#include <cerrno>

#include <sys/wait.h>
#include <unistd.h>

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
    int fds[2];
    REQUIRE(::pipe(fds) == 0);
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        ::close(fds[0]);
        ::alarm(timeout_s);
        const std::string value = work();
        for (std::size_t done = 0; done < value.size();) {
            const ssize_t n = ::write(fds[1], value.data() + done, value.size() - done);
            if (n <= 0) ::_exit(125);
            done += std::size_t(n);
        }
        ::_exit(0); // no atexit handlers, no doctest report from the child
    }
    ::close(fds[1]);
    Isolated result;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) != 0;) {
        if (n < 0 && errno == EINTR) continue;
        REQUIRE(n > 0);
        result.value.append(buffer, std::size_t(n));
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
        REQUIRE(errno == EINTR);
    }
    result.finished = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (WIFSIGNALED(status)) result.how = "killed by signal " + std::to_string(WTERMSIG(status));
    if (WIFEXITED(status) && !result.finished) result.how = "exit status " + std::to_string(WEXITSTATUS(status));
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
