#include "image/png.hpp"

// Declarations only: the code is Debian's libstb.so (image/CMakeLists.txt).
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace image {
namespace {

std::string errno_text() { return std::strerror(errno); }

// Writes every byte or fails; remembers the first errno.
struct FdWriter {
    int fd;
    int error = 0;
};

void write_all(void* context, void* data, int size) {
    auto* writer = static_cast<FdWriter*>(context);
    const auto* bytes = static_cast<const char*>(data);
    while (writer->error == 0 && size > 0) {
        const ssize_t written = ::write(writer->fd, bytes, static_cast<std::size_t>(size));
        if (written < 0 && errno == EINTR) {
            continue;
        }
        if (written <= 0) {
            writer->error = written < 0 ? errno : EIO;
            return;
        }
        bytes += written;
        size -= static_cast<int>(written);
    }
}

// Creates a fresh file "<path>.tmp-<pid>-<n>" (O_EXCL, so never someone
// else's file); on success `temp_path` holds its name.
frustum::Result<int> create_temporary(const std::string& path, std::string& temp_path) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        temp_path = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
        const int fd = ::open(temp_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            return fd;
        }
        if (errno != EEXIST) {
            break;
        }
    }
    return frustum::Error{"image::write_png(): cannot create '" + temp_path + "': " + errno_text()};
}

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
frustum::Status check_replaceable(const std::string& path) {
    struct stat status{};
    if (::lstat(path.c_str(), &status) != 0) {
        if (errno == ENOENT) {
            return {};
        }
        return frustum::Error{"image::write_png(): cannot inspect '" + path + "': " + errno_text()};
    }
    if (!S_ISREG(status.st_mode)) {
        return frustum::Error{"image::write_png(): '" + path + "' is " + kind_of(status.st_mode) +
                              ", not a regular file; refusing to replace it"};
    }
    return {};
}

// stb_image_write computes row and image sizes in int: (width*4+1)*height
// must fit, or its arithmetic overflows.
frustum::Status check_encodable(const Image& image) {
    const long long filtered_bytes = (static_cast<long long>(image.width) * 4 + 1) * image.height;
    if (filtered_bytes > INT_MAX / 2) {
        return frustum::Error{"image::write_png(): " + std::to_string(image.width) + "x" +
                              std::to_string(image.height) +
                              " px is too large to encode (the PNG encoder holds at most " +
                              std::to_string(INT_MAX / 2) + " bytes)"};
    }
    return {};
}

} // namespace

frustum::Status write_png(const Image& image, const std::string& path) {
    if (auto valid = validate(image, "image::write_png()"); !valid) {
        return valid;
    }
    if (auto encodable = check_encodable(image); !encodable) {
        return encodable;
    }
    if (auto replaceable = check_replaceable(path); !replaceable) {
        return replaceable;
    }
    std::string temp_path;
    auto fd = create_temporary(path, temp_path);
    if (!fd) {
        return fd.take_error();
    }
    FdWriter writer{*fd};
    const int encoded = stbi_write_png_to_func(write_all, &writer, image.width, image.height, 4,
                                               image.rgba.data(), image.width * 4);
    std::string failure;
    if (!encoded) {
        failure = "PNG encoding failed";
    } else if (writer.error != 0) {
        failure = std::strerror(writer.error);
    } else if (::fsync(*fd) != 0) {
        failure = "fsync: " + errno_text();
    }
    if (::close(*fd) != 0 && failure.empty()) {
        failure = "close: " + errno_text();
    }
    if (failure.empty() && std::rename(temp_path.c_str(), path.c_str()) != 0) {
        failure = "rename to '" + path + "': " + errno_text();
    }
    if (failure.empty()) {
        return {};
    }
    ::unlink(temp_path.c_str());
    return frustum::Error{"image::write_png(): cannot write '" + path + "': " + failure};
}

frustum::Result<Image> read_png(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        return frustum::Error{"image::read_png(): cannot open '" + path + "': " + errno_text()};
    }
    std::vector<unsigned char> bytes;
    unsigned char chunk[65536];
    std::size_t got = 0;
    while ((got = std::fread(chunk, 1, sizeof chunk, file)) > 0) {
        bytes.insert(bytes.end(), chunk, chunk + got);
    }
    const bool read_failed = std::ferror(file) != 0;
    std::fclose(file);
    if (read_failed || bytes.size() > static_cast<std::size_t>(INT_MAX)) {
        return frustum::Error{"image::read_png(): cannot read '" + path + "': " +
                              (read_failed ? "read error" : "file larger than 2 GiB")};
    }
    int width = 0;
    int height = 0;
    int channels = 0;
    unsigned char* pixels = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()),
                                                  &width, &height, &channels, 4);
    if (pixels == nullptr) {
        return frustum::Error{"image::read_png(): cannot decode '" + path +
                              "': " + stbi_failure_reason()};
    }
    Image result{width, height, {}};
    result.rgba.assign(pixels, pixels + static_cast<std::size_t>(width) * height * 4);
    stbi_image_free(pixels);
    return result;
}

} // namespace image
