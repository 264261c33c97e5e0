#include "image/png_stream.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstdint>
#include <utility>

namespace image {

// libpng reports errors by longjmp to the png_jmpbuf of the call that
// failed: every call into it goes through one of the small functions below,
// which set that jump point and hold no C++ object with a destructor.
struct PngStream::Encoder {
    png_structp png = nullptr;
    png_infop info = nullptr;
    char message[256] = {}; // libpng's last error or warning text
    ~Encoder() { png_destroy_write_struct(&png, &info); }
};

namespace {

constexpr const char* kWho = "image::PngStream";

void on_error(png_structp png, png_const_charp text) {
    auto* encoder = static_cast<PngStream::Encoder*>(png_get_error_ptr(png));
    std::snprintf(encoder->message, sizeof encoder->message, "%s", text);
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void on_write(png_structp png, png_bytep data, png_size_t size) {
    static_cast<AtomicFile*>(png_get_io_ptr(png))->write(data, size);
}

void on_flush(png_structp) {}

// false: libpng failed (encoder.message says why).
bool start(PngStream::Encoder& encoder, AtomicFile& file, int width_px, int height_px, int zlib_level) {
    if (setjmp(png_jmpbuf(encoder.png))) {
        return false;
    }
    png_set_write_fn(encoder.png, &file, on_write, on_flush);
    png_set_IHDR(encoder.png, encoder.info, static_cast<png_uint_32>(width_px), static_cast<png_uint_32>(height_px),
                 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(encoder.png, zlib_level);
    png_set_filter(encoder.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB); // one cheap filter: no per-row trial of all five
    png_write_info(encoder.png, encoder.info);
    return true;
}

bool write_row_range(PngStream::Encoder& encoder, const std::uint8_t* first, int rows, int stride) {
    if (setjmp(png_jmpbuf(encoder.png))) {
        return false;
    }
    for (int y = 0; y < rows; ++y) {
        png_write_row(encoder.png, first + static_cast<std::size_t>(y) * static_cast<std::size_t>(stride));
    }
    return true;
}

bool end(PngStream::Encoder& encoder) {
    if (setjmp(png_jmpbuf(encoder.png))) {
        return false;
    }
    png_write_end(encoder.png, nullptr);
    return true;
}

std::string size_text(int width_px, int height_px) {
    return std::to_string(width_px) + "x" + std::to_string(height_px);
}

} // namespace

PngStream::PngStream(AtomicFile file, int width_px, int height_px)
    : file_(std::move(file)), width_px_(width_px), height_px_(height_px), encoder_(std::make_unique<Encoder>()) {}

PngStream::~PngStream() = default; // file_ removes its temporary file unless finished

frustum::Result<std::unique_ptr<PngStream>> PngStream::open(const std::string& path, int width_px, int height_px,
                                                            int zlib_level) {
    if (width_px < 1 || height_px < 1 || zlib_level < 0 || zlib_level > 9) {
        return frustum::Error{std::string(kWho) + ": '" + path + "': size must be at least 1x1 px and zlib level 0..9, got " +
                              size_text(width_px, height_px) + " at level " + std::to_string(zlib_level)};
    }
    auto file = AtomicFile::create(path, kWho);
    if (!file) {
        return file.take_error();
    }
    std::unique_ptr<PngStream> stream(new PngStream(std::move(*file), width_px, height_px));
    Encoder& encoder = *stream->encoder_;
    encoder.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &encoder, on_error, on_warning);
    encoder.info = encoder.png ? png_create_info_struct(encoder.png) : nullptr;
    if (!encoder.info) {
        return frustum::Error{std::string(kWho) + ": '" + path + "': libpng could not start (out of memory)"};
    }
    // libpng allows at most 1,000,000 px per side unless told otherwise.
    png_set_user_limits(encoder.png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    if (!start(encoder, stream->file_, width_px, height_px, zlib_level)) {
        return frustum::Error{std::string(kWho) + ": cannot write '" + path + "': " + encoder.message};
    }
    return stream;
}

frustum::Status PngStream::write_rows(const Image& rows) {
    const std::string where = std::string(kWho) + ": '" + file_.path() + "'";
    if (failed_) {
        return frustum::Error{where + ": an earlier write failed"};
    }
    if (auto valid = validate(rows, kWho); !valid) {
        return valid;
    }
    if (rows.width != width_px_ || rows.height > height_px_ - rows_written_) {
        return frustum::Error{where + ": rows " + size_text(rows.width, rows.height) + " do not fit the " +
                              size_text(width_px_, height_px_) + " image after " + std::to_string(rows_written_) +
                              " rows"};
    }
    if (!write_row_range(*encoder_, rows.rgba.data(), rows.height, rows.width * 4)) {
        failed_ = true;
        return frustum::Error{where + ": " + encoder_->message};
    }
    rows_written_ += rows.height;
    if (file_.failed()) {
        failed_ = true;
        return file_.commit(); // removes the temporary file; the error names the path and why
    }
    return {};
}

frustum::Status PngStream::finish() {
    if (failed_ || rows_written_ != height_px_) {
        failed_ = true;
        return frustum::Error{std::string(kWho) + ": '" + file_.path() + "': finished after " +
                              std::to_string(rows_written_) + " of " + std::to_string(height_px_) + " rows"};
    }
    failed_ = true; // finish once
    const bool ended = end(*encoder_);
    return file_.commit(ended ? std::string() : std::string("PNG encoding failed: ") + encoder_->message);
}

} // namespace image
