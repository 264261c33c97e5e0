// image::PngStream: rows written top to bottom read back equal through
// image::read_png (stb, an independent decoder); a stream given up before
// finish() leaves no file; bad paths and misuse are one-line errors.
#include <image/png.hpp>
#include <image/png_stream.hpp>

#include <support/temp_dir.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using support::TempDir;

// A w x h image whose every channel of every pixel differs from its
// neighbours' (so a row out of place or a channel swapped shows).
image::Image pattern(int w, int h, int first_row) {
    image::Image picture = image::make_image(w, h, {0, 0, 0, 0});
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int row = first_row + y;
            image::set_pixel(picture, x, y,
                             {static_cast<std::uint8_t>(x * 7 + row), static_cast<std::uint8_t>(row * 13 + x),
                              static_cast<std::uint8_t>(x ^ row), static_cast<std::uint8_t>(255 - (x + row) % 97)});
        }
    }
    return picture;
}

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) {
        names.push_back(entry.path().filename().string());
    }
    return names;
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("png_stream: rows in bands of any height read back as the whole image") {
    const int w = 301, h = 77;
    for (int level : {1, 3, 6}) {
        CAPTURE(level);
        TempDir level_dir;
        const std::string path = (level_dir / "stream.png").string();
        auto stream = image::PngStream::open(path, w, h, level);
        REQUIRE_MESSAGE(stream.ok(), stream.error());
        int top = 0;
        for (int band : {1, 16, 40, 20}) { // 77 rows
            const auto written = (*stream)->write_rows(pattern(w, band, top));
            REQUIRE_MESSAGE(written.ok(), written.error());
            top += band;
        }
        CHECK(entries(level_dir.path()).size() == 1); // only the temporary file so far
        CHECK_FALSE(fs::exists(path));
        const auto finished = (*stream)->finish();
        REQUIRE_MESSAGE(finished.ok(), finished.error());
        CHECK(entries(level_dir.path()) == std::vector<std::string>{"stream.png"});
        const auto read = image::read_png(path);
        REQUIRE_MESSAGE(read.ok(), read.error());
        CHECK(read->width == w);
        CHECK(read->height == h);
        CHECK(read->rgba == pattern(w, h, 0).rgba);
    }
}

TEST_CASE("png_stream: a stream given up before finish() leaves no file, not even an old one replaced") {
    TempDir dir;
    const std::string path = (dir / "poster.png").string();
    {
        auto stream = image::PngStream::open(path, 16, 8);
        REQUIRE(stream.ok());
        REQUIRE((*stream)->write_rows(pattern(16, 4, 0)).ok());
    } // interrupted after half the rows
    CHECK(entries(dir.path()).empty());

    REQUIRE(image::write_png(pattern(2, 2, 0), path).ok());
    {
        auto stream = image::PngStream::open(path, 16, 8);
        REQUIRE(stream.ok());
        REQUIRE((*stream)->write_rows(pattern(16, 4, 0)).ok());
        const auto early = (*stream)->finish();
        REQUIRE_FALSE(early.ok());
        CHECK(early.error() == "image::PngStream: '" + path + "': finished after 4 of 8 rows");
    }
    CHECK(entries(dir.path()) == std::vector<std::string>{"poster.png"});
    CHECK(image::read_png(path)->width == 2); // the old file, untouched
}

TEST_CASE("png_stream: a bad path, a bad size and rows that do not fit are one-line errors") {
    TempDir dir;
    const std::string missing = (dir / "missing").string() + "/a.png";
    const auto absent = image::PngStream::open(missing, 4, 4);
    REQUIRE_FALSE(absent.ok());
    CHECK(absent.error().rfind("image::PngStream: cannot create '" + missing + ".tmp-", 0) == 0);
    CHECK(absent.error().find("': No such file or directory") != std::string::npos);
    CHECK(absent.error().find('\n') == std::string::npos);

    const auto folder = image::PngStream::open(dir.path().string(), 4, 4);
    REQUIRE_FALSE(folder.ok());
    CHECK(folder.error() == "image::PngStream: '" + dir.path().string() +
                                "' is a directory, not a regular file; refusing to replace it");

    const auto empty = image::PngStream::open((dir / "e.png").string(), 0, 4);
    REQUIRE_FALSE(empty.ok());
    CHECK(empty.error().find("got 0x4") != std::string::npos);

    const std::string path = (dir / "fit.png").string();
    auto stream = image::PngStream::open(path, 8, 4);
    REQUIRE(stream.ok());
    const auto narrow = (*stream)->write_rows(pattern(7, 2, 0));
    REQUIRE_FALSE(narrow.ok());
    CHECK(narrow.error() == "image::PngStream: '" + path + "': rows 7x2 do not fit the 8x4 image after 0 rows");
    REQUIRE((*stream)->write_rows(pattern(8, 3, 0)).ok());
    const auto tall = (*stream)->write_rows(pattern(8, 2, 3));
    REQUIRE_FALSE(tall.ok());
    CHECK(tall.error() == "image::PngStream: '" + path + "': rows 8x2 do not fit the 8x4 image after 3 rows");
    CHECK(entries(dir.path()).size() == 1); // the temporary file only
}

} // TEST_SUITE
