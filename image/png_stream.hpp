// A PNG written row by row, for images no one holds whole (posters,
// render::render_poster()): open -> write_rows() top to bottom -> finish().
// libpng encodes each row as it comes (png_write_row), so memory stays one
// row plus zlib's window whatever the height. The file appears atomically as
// image::write_png()'s do (image/atomic_file.hpp): finish() renames it into
// place; a stream destroyed before finish() leaves no file behind.
#pragma once

#include "image/atomic_file.hpp"
#include "image/image.hpp"

#include <frustum/result.hpp>

#include <memory>
#include <string>

namespace image {

// zlib level 3, every row with the PNG "sub" filter (no per-row trial of
// the five filters): chosen for speed. On a 4096 x 4096 showcase render
// levels 1 and 3 encode equally fast (about 120 Mpx per CPU second here),
// level 3's file is 22 % smaller, level 6 is half as fast (docs/performance.md,
// "Posters"; tests/bench/poster_zlib.cpp).
inline constexpr int kStreamZlibLevel = 3;

class PngStream {
public:
    // width_px, height_px >= 1, zlib_level 0..9; errors name the
    // path, e.g. "image::PngStream: cannot create '/no/dir/a.png.tmp-42-0': No such file or directory".
    static frustum::Result<std::unique_ptr<PngStream>> open(const std::string& path, int width_px, int height_px,
                                                            int zlib_level = kStreamZlibLevel);
    ~PngStream(); // without finish(): the temporary file is removed

    PngStream(const PngStream&) = delete;
    PngStream& operator=(const PngStream&) = delete;

    // The next rows.height rows (rows.width == width_px); no more than
    // height_px in all.
    frustum::Status write_rows(const Image& rows);
    // After exactly height_px rows: the PNG's end, then the rename.
    frustum::Status finish();

    int rows_written() const { return rows_written_; }

    struct Encoder; // libpng's structs (png_stream.cpp)

private:
    PngStream(AtomicFile file, int width_px, int height_px);
    AtomicFile file_;
    int width_px_;
    int height_px_;
    int rows_written_ = 0;
    bool failed_ = false;
    std::unique_ptr<Encoder> encoder_;
};

} // namespace image
