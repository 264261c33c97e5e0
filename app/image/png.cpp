#include "image/png.hpp"

// stb's implementation lives here, with internal linkage (see CMakeLists.txt).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#include <stb/stb_image.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
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

} // namespace

frustum::Status write_png(const Image& image, const std::string& path) {
    if (auto valid = validate(image, "image::write_png()"); !valid) {
        return valid;
    }
    std::string temp_path;
    auto fd = create_temporary(path, temp_path);
    if (!fd) {
        return frustum::Error{fd.error()};
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
