// A file that appears whole or not at all: the bytes go to a fresh
// temporary file next to the target ("<path>.tmp-<pid>-<n>"), which commit()
// renames over it once complete. Destroyed without commit() (an error, an
// interrupted run), the temporary file is removed. Shared by image::write_png
// (image/png.hpp) and image::PngStream (image/png_stream.hpp).
#pragma once

#include <frustum/result.hpp>

#include <cstddef>
#include <string>

namespace image {

class AtomicFile {
public:
    // Refuses a `path` that is anything but a regular file or nothing
    // (never replaces a device, FIFO, link or directory). `who` starts every
    // error, e.g. "image::write_png(): cannot create '/no/dir/a.png.tmp-42-0': No such file or directory".
    static frustum::Result<AtomicFile> create(const std::string& path, const char* who);

    AtomicFile(AtomicFile&& other) noexcept;
    AtomicFile& operator=(AtomicFile&&) = delete;
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    ~AtomicFile(); // removes the temporary file unless committed

    // Writes every byte or remembers the first errno (later writes do nothing).
    void write(const void* data, std::size_t size);
    bool failed() const { return error_ != 0; }

    // fsync, close and rename into place; `failure` (e.g. "PNG encoding
    // failed"), a write error or a failed step removes the temporary file and
    // returns "<who>: cannot write '<path>': <why>".
    frustum::Status commit(const std::string& failure = {});

    const std::string& path() const { return path_; }

private:
    AtomicFile(std::string path, std::string temp_path, int fd, const char* who);
    std::string path_;
    std::string temp_path_;
    int fd_ = -1;
    int error_ = 0;
    const char* who_;
    bool done_ = false;
};

} // namespace image
