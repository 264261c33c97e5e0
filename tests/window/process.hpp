// Running a built program as a child process for the window suite: with
// environment variables removed or set, stdout and stderr captured.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace window_test {

struct Child {
    int exit_status = -1; // -1 when killed by a signal
    std::string out, err;
};

// The longest a child may run: the longest measured, the key sweep under
// xvfb-run (about 40 s alone on llvmpipe, 2 cores), times 7 for a loaded
// machine. A hung child (an X server that never comes up, a window that
// never closes) then fails its test instead of stalling the suite.
inline constexpr int kChildTimeoutS = 300;

// Runs `program` with `args` (no shell) and waits for it, at most
// `timeout_s`: then its whole process group is killed (SIGKILL) and the
// test fails with the command. `environment`: a value sets the variable,
// nullopt removes it; the rest is inherited.
Child run(const std::string& program, const std::vector<std::string>& args,
          const std::map<std::string, std::optional<std::string>>& environment = {},
          int timeout_s = kChildTimeoutS);

// `name` found on PATH, else empty.
std::string find_on_path(const std::string& name);

// A fresh folder below the system temp folder, removed when the object dies.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

} // namespace window_test
