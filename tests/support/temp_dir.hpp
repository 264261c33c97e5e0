// A private folder for one test, the one every suite uses, and files in it.
#pragma once

#include <filesystem>
#include <string>

namespace support {

// A fresh folder below the system temp folder ("frustum-test-XXXXXX"),
// removed (recursively, after restoring write permission to its folders)
// when the object dies.
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

// Writes `bytes` to `path` (replacing it); REQUIREs success.
void write_file(const std::filesystem::path& path, const std::string& bytes);

} // namespace support
