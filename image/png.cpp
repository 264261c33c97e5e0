#include "image/png.hpp"

#include "image/atomic_file.hpp"

// Declarations only: the code is Debian's libstb.so (image/CMakeLists.txt).
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>

namespace image {
namespace {

std::string errno_text() { return std::strerror(errno); }

// stb_image_write hands the encoded bytes to this callback.
void write_to(void* context, void* data, int size) {
    static_cast<AtomicFile*>(context)->write(data, static_cast<std::size_t>(size));
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
    auto file = AtomicFile::create(path, "image::write_png()");
    if (!file) {
        return file.take_error();
    }
    const int encoded = stbi_write_png_to_func(write_to, &*file, image.width, image.height, 4,
                                               image.rgba.data(), image.width * 4);
    return file->commit(encoded ? std::string() : std::string("PNG encoding failed"));
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
