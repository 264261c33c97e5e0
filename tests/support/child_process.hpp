// Running a built program as a child process (no shell), the one runner of
// the suites: stdin from text or a file, stdout and stderr captured,
// environment variables set or removed, resource limits, and a timeout
// after which its whole process group is killed and the test fails.
#pragma once

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
};

// Runs `program` and waits for it, at most launch.timeout_s.
Outcome run(const std::string& program, const Launch& launch);

} // namespace support
