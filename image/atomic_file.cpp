#include "image/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace image {
namespace {

std::string errno_text() { return std::strerror(errno); }

// What lstat() found at `path`, for the refusal message.
const char* kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISLNK(mode)) return "a symbolic link";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// The rename at the end replaces whatever is at `path`: only a regular file
// (or nothing) may be there, never a device node, FIFO, link or directory.
frustum::Status check_replaceable(const std::string& path, const char* who) {
    struct stat status{};
    if (::lstat(path.c_str(), &status) != 0) {
        if (errno == ENOENT) {
            return {};
        }
        return frustum::Error{std::string(who) + ": cannot inspect '" + path + "': " + errno_text()};
    }
    if (!S_ISREG(status.st_mode)) {
        return frustum::Error{std::string(who) + ": '" + path + "' is " + kind_of(status.st_mode) +
                              ", not a regular file; refusing to replace it"};
    }
    return {};
}

} // namespace

frustum::Result<AtomicFile> AtomicFile::create(const std::string& path, const char* who) {
    if (auto replaceable = check_replaceable(path, who); !replaceable) {
        return replaceable.take_error();
    }
    // "<path>.tmp-<pid>-<n>", O_EXCL: never someone else's file.
    static std::atomic<unsigned> counter{0};
    std::string temp_path;
    for (int attempt = 0; attempt < 100; ++attempt) {
        temp_path = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
        const int fd = ::open(temp_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            return AtomicFile(path, std::move(temp_path), fd, who);
        }
        if (errno != EEXIST) {
            break;
        }
    }
    return frustum::Error{std::string(who) + ": cannot create '" + temp_path + "': " + errno_text()};
}

AtomicFile::AtomicFile(std::string path, std::string temp_path, int fd, const char* who)
    : path_(std::move(path)), temp_path_(std::move(temp_path)), fd_(fd), who_(who) {}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : path_(std::move(other.path_)), temp_path_(std::move(other.temp_path_)), fd_(other.fd_),
      error_(other.error_), who_(other.who_), done_(other.done_) {
    other.fd_ = -1;
    other.done_ = true;
}

AtomicFile::~AtomicFile() {
    if (done_) {
        return;
    }
    if (fd_ >= 0) {
        ::close(fd_);
    }
    ::unlink(temp_path_.c_str());
}

void AtomicFile::write(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const char*>(data);
    while (error_ == 0 && size > 0) {
        const ssize_t written = ::write(fd_, bytes, size);
        if (written < 0 && errno == EINTR) {
            continue;
        }
        if (written <= 0) {
            error_ = written < 0 ? errno : EIO;
            return;
        }
        bytes += written;
        size -= static_cast<std::size_t>(written);
    }
}

frustum::Status AtomicFile::commit(const std::string& failure_in) {
    std::string failure = failure_in;
    if (failure.empty() && error_ != 0) {
        failure = std::strerror(error_);
    }
    if (failure.empty() && ::fsync(fd_) != 0) {
        failure = "fsync: " + errno_text();
    }
    if (::close(fd_) != 0 && failure.empty()) {
        failure = "close: " + errno_text();
    }
    fd_ = -1;
    if (failure.empty() && std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
        failure = "rename to '" + path_ + "': " + errno_text();
    }
    if (failure.empty()) {
        done_ = true;
        return {};
    }
    ::unlink(temp_path_.c_str());
    done_ = true;
    return frustum::Error{std::string(who_) + ": cannot write '" + path_ + "': " + failure};
}

} // namespace image
