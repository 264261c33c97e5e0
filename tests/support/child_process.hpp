// Running a built program as a child process (no shell), the one runner of
// the suites: stdin from text or a file, stdout and stderr captured,
// environment variables set or removed, resource limits, and a timeout
// after which its whole process group is killed and the test fails.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace support {

// Built with -DFRUSTUM_SANITIZE=ON (CMake defines FRUSTUM_SANITIZED): the
// AddressSanitizer's shadow memory cannot be mapped under an address-space
// cap, so run() leaves the cap out there, and heaps are about twice as big.
#if defined(FRUSTUM_SANITIZED)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

struct Launch {
    std::vector<std::string> args;   // without the program
    std::string stdin_text;          // ignored when stdin_file is set
    std::string stdin_file;          // path to read stdin from
    std::string stdout_file;         // e.g. /dev/full; empty: captured
    long file_size_limit_bytes = -1; // RLIMIT_FSIZE for the child, -1: none
    bool ignore_sigxfsz = true;      // a write past the limit fails (EFBIG) instead of killing
    std::string cwd;                 // empty: the test's
    long address_space_limit_bytes = -1; // RLIMIT_AS for the child (as prlimit --as), -1: none
    // A value sets the variable, nullopt removes it; the rest is inherited.
    std::map<std::string, std::optional<std::string>> environment;
    // Then the child's process group is killed (SIGKILL) and the test fails
    // with the command and its stderr. The longest measured is a 640x360
    // render of every effect, under 10 s on llvmpipe with 2 cores: 12 times
    // that for a loaded machine or a sanitizer build.
    int timeout_s = 120;
};

struct Outcome {
    int exit_status = -1; // -1 when killed by a signal
    int signal = 0;
    std::string out, err; // out is empty when stdout_file was given
    long peak_rss_kb = 0; // the child's maximum resident set (wait4 rusage)
    std::string value;    // run_function(): what the body returned
    bool timed_out = false; // run_function(): killed at the timeout (the test already failed)
};

// Runs `program` and waits for it, at most launch.timeout_s; past it, FAIL
// (the test case ends) naming the command and the limit.
Outcome run(const std::string& program, const Launch& launch);

// Runs `body` in a forked child (no exec: the test's own code, e.g. a call
// that must abort, or one that may crash or hang), in its own process group,
// stdout and stderr captured, SIGABRT, SIGSEGV, SIGFPE, SIGILL and SIGBUS at
// their default actions (so that the child dies of its signal without
// doctest's report of the parent's run). The body must not use doctest; what
// it returns comes back as Outcome::value (exit status 0). Waits at most
// `timeout_s`; past it the child's group is killed and the check fails
// (FAIL_CHECK, so that a table of cases goes on) naming `what` and the
// limit, with timed_out set. Needs fork(): not under emscripten.
Outcome run_function(const std::string& what, const std::function<std::string()>& body, int timeout_s = 120);

// `name` found in a folder of PATH (an executable file), else empty.
std::string find_on_path(const std::string& name);

} // namespace support
