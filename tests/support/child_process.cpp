#include "child_process.hpp"

#include "temp_dir.hpp"

#include <doctest/doctest.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace support {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// NAME=value strings: the inherited environment with `changes` applied.
std::vector<std::string> environment_with(const std::map<std::string, std::optional<std::string>>& changes) {
    std::vector<std::string> result;
    for (char** entry = environ; *entry != nullptr; ++entry) {
        const std::string text(*entry);
        if (changes.count(text.substr(0, text.find('='))) == 0) {
            result.push_back(text);
        }
    }
    for (const auto& [name, value] : changes) {
        if (value) {
            result.push_back(name + "=" + *value);
        }
    }
    return result;
}

// Null-terminated pointers into `strings` (which must outlive them).
std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> result;
    for (std::string& text : strings) {
        result.push_back(text.data());
    }
    result.push_back(nullptr);
    return result;
}

// In the child after fork(): `path` opened as file descriptor `target`, else exit 126.
void redirect(const std::string& path, int flags, int target) {
    const int fd = ::open(path.c_str(), flags, 0600);
    if (fd < 0 || ::dup2(fd, target) < 0) ::_exit(126);
    ::close(fd);
}

// In the child after fork(): only async-signal-safe calls, then exec.
[[noreturn]] void exec_child(const std::string& program, const Launch& launch, char* const* argv, char* const* envp,
                             const std::string& in_path, const std::string& out_path, const std::string& err_path) {
    ::setpgid(0, 0); // its own process group, so that a timeout kills what it started too
    redirect(in_path, O_RDONLY, 0);
    redirect(out_path, O_WRONLY | O_CREAT | O_TRUNC, 1);
    redirect(err_path, O_WRONLY | O_CREAT | O_TRUNC, 2);
    if (!launch.cwd.empty() && ::chdir(launch.cwd.c_str()) != 0) ::_exit(126);
    if (launch.file_size_limit_bytes >= 0) {
        const rlimit limit{rlim_t(launch.file_size_limit_bytes), rlim_t(launch.file_size_limit_bytes)};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(126);
    }
    // An AddressSanitizer build reserves terabytes of shadow memory at start,
    // which no address-space cap admits: there the cap is left out and the
    // peak-RSS bound of each case still holds (make test-asan).
    if (launch.address_space_limit_bytes >= 0 && !kSanitized) {
        const rlimit limit{rlim_t(launch.address_space_limit_bytes), rlim_t(launch.address_space_limit_bytes)};
        if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(126);
    }
    ::signal(SIGXFSZ, launch.ignore_sigxfsz ? SIG_IGN : SIG_DFL);
    ::execve(program.c_str(), argv, envp);
    ::_exit(127);
}

struct Waited {
    int status = 0;
    rusage usage{};
    bool timed_out = false;
};

// Waits for `pid` (the leader of its own process group) at most timeout_s;
// past it kills the group and the child, reaps it and says so.
Waited wait_bounded(pid_t pid, int timeout_s) {
    Waited waited;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
    for (;;) {
        const pid_t done = ::wait4(pid, &waited.status, WNOHANG, &waited.usage);
        REQUIRE((done >= 0 || errno == EINTR));
        if (done == pid) return waited;
        if (std::chrono::steady_clock::now() > deadline) {
            ::kill(-pid, SIGKILL);
            ::kill(pid, SIGKILL);
            while (::wait4(pid, &waited.status, 0, &waited.usage) < 0) REQUIRE(errno == EINTR);
            waited.timed_out = true;
            return waited;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

void fill_status(Outcome& outcome, const Waited& waited) {
    outcome.peak_rss_kb = waited.usage.ru_maxrss;
    if (WIFEXITED(waited.status)) outcome.exit_status = WEXITSTATUS(waited.status);
    if (WIFSIGNALED(waited.status)) outcome.signal = WTERMSIG(waited.status);
}

} // namespace

Outcome run(const std::string& program, const Launch& launch) {
    TempDir io;
    const std::string in_path = launch.stdin_file.empty() ? (io / "stdin").string() : launch.stdin_file;
    if (launch.stdin_file.empty()) write_file(in_path, launch.stdin_text);
    const std::string out_path = launch.stdout_file.empty() ? (io / "stdout").string() : launch.stdout_file;
    const std::string err_path = (io / "stderr").string();
    std::vector<std::string> argv_text{program};
    argv_text.insert(argv_text.end(), launch.args.begin(), launch.args.end());
    std::vector<std::string> env_text = environment_with(launch.environment);
    const std::vector<char*> argv = pointers(argv_text), envp = pointers(env_text);
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) exec_child(program, launch, argv.data(), envp.data(), in_path, out_path, err_path);
    std::string command = program;
    for (const std::string& arg : launch.args) command += " " + arg;
    const Waited waited = wait_bounded(pid, launch.timeout_s);
    if (waited.timed_out) {
        FAIL("killed after the timeout of " << launch.timeout_s << " s: " << command << "\nstderr: " << slurp(err_path));
    }
    Outcome outcome;
    fill_status(outcome, waited);
    REQUIRE_MESSAGE(outcome.exit_status != 127, "cannot execute ", program);
    if (launch.stdout_file.empty()) outcome.out = slurp(out_path);
    outcome.err = slurp(err_path);
    return outcome;
}

Outcome run_function(const std::string& what, const std::function<std::string()>& body, int timeout_s) {
    TempDir io;
    const std::string in_path = (io / "stdin").string(), out_path = (io / "stdout").string(),
                      err_path = (io / "stderr").string(), value_path = (io / "value").string();
    write_file(in_path, "");
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        ::setpgid(0, 0);
        for (const int sig : {SIGABRT, SIGSEGV, SIGFPE, SIGILL, SIGBUS}) ::signal(sig, SIG_DFL);
        redirect(in_path, O_RDONLY, 0);
        redirect(out_path, O_WRONLY | O_CREAT | O_TRUNC, 1);
        redirect(err_path, O_WRONLY | O_CREAT | O_TRUNC, 2);
        const std::string value = body();
        const int fd = ::open(value_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (fd < 0) ::_exit(125);
        for (std::size_t done = 0; done < value.size();) {
            const ssize_t n = ::write(fd, value.data() + done, value.size() - done);
            if (n <= 0) ::_exit(125);
            done += std::size_t(n);
        }
        ::close(fd);
        ::_exit(0); // no atexit handlers, no doctest report from the child
    }
    const Waited waited = wait_bounded(pid, timeout_s);
    Outcome outcome;
    fill_status(outcome, waited);
    outcome.out = slurp(out_path);
    outcome.err = slurp(err_path);
    outcome.value = slurp(value_path);
    outcome.timed_out = waited.timed_out;
    if (waited.timed_out) {
        FAIL_CHECK("killed after the timeout of " << timeout_s << " s: " << what << " (run in a child process)"
                                                  << "\nstderr: " << outcome.err);
    }
    return outcome;
}

std::string find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::istringstream folders(path != nullptr ? path : "");
    for (std::string folder; std::getline(folders, folder, ':');) {
        const fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
        if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) {
            return candidate.string();
        }
    }
    return {};
}

} // namespace support
