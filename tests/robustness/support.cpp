#include "support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <thread>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace rob {

namespace fs = std::filesystem;

std::optional<std::string> missing_phrase(const std::string& text, const std::vector<std::string>& phrases) {
    for (const std::string& phrase : phrases) {
        if (text.find(phrase) == std::string::npos) {
            return phrase;
        }
    }
    return std::nullopt;
}

TempDir::TempDir() {
    std::string pattern = (fs::temp_directory_path() / "frustum-robustness-XXXXXX").string();
    REQUIRE(::mkdtemp(pattern.data()) != nullptr);
    path_ = pattern;
}

TempDir::~TempDir() {
    std::error_code ignored;
    for (const auto& entry : fs::recursive_directory_iterator(path_, ignored)) {
        if (entry.is_directory(ignored) && !entry.is_symlink(ignored)) {
            fs::permissions(entry.path(), fs::perms::owner_all, fs::perm_options::add, ignored);
        }
    }
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(path_, ignored);
}

void write_file(const fs::path& path, const std::string& bytes) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file << bytes;
    REQUIRE_MESSAGE(file.good(), "cannot write ", path.string());
}

std::vector<std::string> list_dir(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(dir, error)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

namespace {

std::string slurp(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// In the child after fork(): only async-signal-safe calls, then exec.
[[noreturn]] void exec_child(const std::string& program, const Launch& launch, const std::string& in_path,
                             const std::string& out_path, const std::string& err_path) {
    const auto redirect = [](const std::string& path, int flags, int target) {
        const int fd = ::open(path.c_str(), flags, 0600);
        if (fd < 0 || ::dup2(fd, target) < 0) ::_exit(126);
        ::close(fd);
    };
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
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& arg : launch.args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
}

} // namespace

Outcome run(const std::string& program, const Launch& launch) {
    TempDir io;
    const std::string in_path = launch.stdin_file.empty() ? (io / "stdin").string() : launch.stdin_file;
    if (launch.stdin_file.empty()) write_file(in_path, launch.stdin_text);
    const std::string out_path = launch.stdout_file.empty() ? (io / "stdout").string() : launch.stdout_file;
    const std::string err_path = (io / "stderr").string();
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) exec_child(program, launch, in_path, out_path, err_path);
    int status = 0;
    rusage usage{};
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(launch.timeout_s);
    for (;;) {
        const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
        REQUIRE((done >= 0 || errno == EINTR));
        if (done == pid) break;
        if (std::chrono::steady_clock::now() > deadline) {
            ::kill(pid, SIGKILL);
            while (::wait4(pid, &status, 0, &usage) < 0) REQUIRE(errno == EINTR);
            std::string command = program;
            for (const std::string& arg : launch.args) command += " " + arg;
            FAIL("killed after the timeout of " << launch.timeout_s << " s: " << command);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    Outcome outcome;
    outcome.peak_rss_kb = usage.ru_maxrss;
    if (WIFEXITED(status)) outcome.exit_status = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
    REQUIRE_MESSAGE(outcome.exit_status != 127, "cannot execute ", program);
    if (launch.stdout_file.empty()) outcome.out = slurp(out_path);
    outcome.err = slurp(err_path);
    return outcome;
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

} // namespace rob
