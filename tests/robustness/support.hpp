// Helpers of the robustness suite: phrase matching, private temp folders and
// running a built tool as a child process (stdin from text or a file,
// stdout/stderr captured, optional file-size limit).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rob {

// Built with -DFRUSTUM_SANITIZE=ON (CMake defines FRUSTUM_SANITIZED): the
// AddressSanitizer's shadow memory cannot be mapped under an address-space
// cap, so run() leaves the cap out there, and heaps are about twice as big.
#if defined(FRUSTUM_SANITIZED)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// Every phrase occurs in text; the first missing one otherwise.
std::optional<std::string> missing_phrase(const std::string& text, const std::vector<std::string>& phrases);

// A fresh folder below the system temp folder, removed (recursively, after
// restoring write permission) when the object dies.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

void write_file(const std::filesystem::path& path, const std::string& bytes);

// Names of the entries of a folder (empty when it does not exist).
std::vector<std::string> list_dir(const std::filesystem::path& dir);

struct Launch {
    std::vector<std::string> args;   // without the program
    std::string stdin_text;          // ignored when stdin_file is set
    std::string stdin_file;          // path to read stdin from
    std::string stdout_file;         // e.g. /dev/full; empty: captured
    long file_size_limit_bytes = -1; // RLIMIT_FSIZE for the child, -1: none
    bool ignore_sigxfsz = true;      // a write past the limit fails (EFBIG) instead of killing
    std::string cwd;                 // empty: the test's
    long address_space_limit_bytes = -1; // RLIMIT_AS for the child (as prlimit --as), -1: none
    // Then the child is killed (SIGKILL) and the case fails. The longest
    // measured is a 640x360 render of every effect, under 10 s on llvmpipe
    // with 2 cores: 12 times that for a loaded machine or a sanitizer build.
    int timeout_s = 120;
};

struct Outcome {
    int exit_status = -1; // -1 when killed by a signal
    int signal = 0;
    std::string out, err; // out is empty when stdout_file was given
    long peak_rss_kb = 0; // the child's maximum resident set (wait4 rusage)
};

// Runs `program` and waits for it (no shell), at most launch.timeout_s.
Outcome run(const std::string& program, const Launch& launch);

// `work` run in a forked child, so that a crash, a sanitizer abort or a hang
// (killed after timeout_s) fails one case instead of the whole suite. The
// child must not use doctest: it only computes the text it returns.
struct Isolated {
    bool finished = false; // the child returned normally
    std::string how;       // otherwise "killed by signal N" / "exit status N"
    std::string value;     // what work() returned
};
Isolated isolated(const std::function<std::string()>& work, unsigned timeout_s = 60);

} // namespace rob
