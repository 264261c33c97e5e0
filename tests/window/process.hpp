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

// Runs `program` with `args` (no shell) and waits for it. `environment`:
// a value sets the variable, nullopt removes it; the rest is inherited.
Child run(const std::string& program, const std::vector<std::string>& args,
          const std::map<std::string, std::optional<std::string>>& environment = {});

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
