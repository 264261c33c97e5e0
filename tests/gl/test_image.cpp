// The image library: pixels, PNG round trip, atomic writes, comparison.
#include "image_printer.hpp"

#include <image/compare.hpp>
#include <image/contact_sheet.hpp>
#include <image/image.hpp>
#include <image/png.hpp>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// A fresh empty directory, removed with everything in it at scope exit.
struct TempDir {
    fs::path path;
    TempDir() {
        std::string pattern = (fs::temp_directory_path() / "frustum-image-XXXXXX").string();
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        path = pattern;
    }
    ~TempDir() { fs::remove_all(path); }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(path)) {
            names.push_back(entry.path().filename().string());
        }
        return names;
    }
};

image::Image two_pixels(image::Rgba left, image::Rgba right) {
    image::Image picture = image::make_image(2, 1, left);
    image::set_pixel(picture, 1, 0, right);
    return picture;
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("pixels are addressed from the top-left") {
    image::Image picture = image::make_image(3, 2, {1, 2, 3, 4});
    CHECK(picture.rgba.size() == 24);
    image::set_pixel(picture, 2, 1, {9, 8, 7, 6});
    CHECK(image::pixel_at(picture, 2, 1) == image::Rgba{9, 8, 7, 6});
    CHECK(picture.rgba[(1 * 3 + 2) * 4] == 9);
    CHECK(image::pixel_at(picture, 0, 0) == image::Rgba{1, 2, 3, 4});
    CHECK(image::validate(picture, "here").ok());
    picture.rgba.pop_back();
    const auto invalid = image::validate(picture, "here");
    REQUIRE_FALSE(invalid.ok());
    CHECK(invalid.error() == "here: image must be non-empty with width*height*4 bytes, got 3x2 with 23 bytes");
}

TEST_CASE("PNG write and read round trip, leaving no temporary file") {
    TempDir dir;
    image::Image picture = image::make_image(3, 2, {10, 20, 30, 255});
    image::set_pixel(picture, 0, 0, {255, 0, 0, 255});
    image::set_pixel(picture, 2, 1, {0, 0, 255, 128});
    const std::string path = (dir.path / "round.png").string();
    const auto written = image::write_png(picture, path);
    REQUIRE_MESSAGE(written.ok(), written.error());
    CHECK(dir.entries() == std::vector<std::string>{"round.png"});
    const auto read = image::read_png(path);
    REQUIRE_MESSAGE(read.ok(), read.error());
    CHECK(read->width == 3);
    CHECK(read->height == 2);
    CHECK(read->rgba == picture.rgba);

    // Overwriting replaces the file in one step.
    REQUIRE(image::write_png(image::make_image(1, 1, {1, 1, 1, 1}), path).ok());
    CHECK(image::read_png(path)->width == 1);
    CHECK(dir.entries() == std::vector<std::string>{"round.png"});
}

TEST_CASE("writing into a missing directory fails and leaves nothing") {
    TempDir dir;
    const std::string missing = (dir.path / "missing").string();
    const auto written = image::write_png(image::make_image(1, 1, {0, 0, 0, 255}), missing + "/a.png");
    REQUIRE_FALSE(written.ok());
    CHECK(written.error().rfind("image::write_png(): cannot create '" + missing + "/a.png.tmp-", 0) == 0);
    CHECK(written.error().find("': No such file or directory") != std::string::npos);
    CHECK(dir.entries().empty());
}

TEST_CASE("an invalid image is not written") {
    TempDir dir;
    const auto written = image::write_png(image::Image{2, 2, {}}, (dir.path / "x.png").string());
    REQUIRE_FALSE(written.ok());
    CHECK(written.error() ==
          "image::write_png(): image must be non-empty with width*height*4 bytes, got 2x2 with 0 bytes");
    CHECK(dir.entries().empty());
}

TEST_CASE("reading a missing or non-PNG file names the path and reason") {
    TempDir dir;
    const std::string missing = (dir.path / "none.png").string();
    const auto absent = image::read_png(missing);
    REQUIRE_FALSE(absent.ok());
    CHECK(absent.error() == "image::read_png(): cannot open '" + missing + "': No such file or directory");
    const std::string text = (dir.path / "text.png").string();
    std::ofstream(text) << "not a png";
    const auto garbage = image::read_png(text);
    REQUIRE_FALSE(garbage.ok());
    CHECK(garbage.error().rfind("image::read_png(): cannot decode '" + text + "': ", 0) == 0);
}

TEST_CASE("compare reports mean, max and pixels over the tolerance") {
    const image::Image a = two_pixels({0, 0, 0, 255}, {10, 20, 30, 255});
    const image::Image b = two_pixels({0, 0, 0, 255}, {10, 25, 27, 255});
    // Differences per channel: 0 0 0 0 | 0 5 3 0 -> sum 8 over 8 channels.
    const auto loose = image::compare(a, b, 5);
    REQUIRE(loose.ok());
    CHECK(loose->pixel_count == 2);
    CHECK(loose->mean_abs == 1.0); // 8 / 8, exact in double
    CHECK(loose->max_abs == 5);
    CHECK(loose->pixels_over == 0);
    CHECK(loose->fraction_over() == 0.0);
    const auto strict = image::compare(a, b, 4);
    REQUIRE(strict.ok());
    CHECK(strict->tolerance == 4);
    CHECK(strict->pixels_over == 1);
    CHECK(strict->fraction_over() == 0.5); // 1 of 2 pixels, exact
    CHECK(image::compare(a, a, 0)->max_abs == 0);

    const auto mismatch = image::compare(a, image::make_image(1, 2, {0, 0, 0, 0}), 0);
    REQUIRE_FALSE(mismatch.ok());
    CHECK(mismatch.error() == "image::compare(): sizes must match, got 2x1 and 1x2");
    const auto negative = image::compare(a, b, -1);
    REQUIRE_FALSE(negative.ok());
    CHECK(negative.error() == "image::compare(): tolerance must be >= 0, got -1");
}

TEST_CASE("compare sees every channel alone, in either direction, in any pixel") {
    // One channel of one pixel of a 3x2 image differs by 7: the others are
    // equal, so max 7, 1 pixel over tolerance 6, none over 7, mean 7 / 24.
    const image::Image base = image::make_image(3, 2, {100, 110, 120, 130});
    for (int pixel = 0; pixel < 6; ++pixel) {
        for (int channel = 0; channel < 4; ++channel) {
            for (int sign : {-1, 1}) {
                CAPTURE(pixel);
                CAPTURE(channel);
                CAPTURE(sign);
                image::Image other = base;
                other.rgba[static_cast<std::size_t>(pixel * 4 + channel)] =
                    static_cast<std::uint8_t>(base.rgba[static_cast<std::size_t>(pixel * 4 + channel)] + sign * 7);
                const auto over = image::compare(base, other, 6);
                REQUIRE(over.ok());
                CHECK(over->max_abs == 7);
                CHECK(over->pixels_over == 1);
                CHECK(over->mean_abs == doctest::Approx(7.0 / 24.0).epsilon(1e-15));
                CHECK(image::compare(other, base, 7)->pixels_over == 0);
            }
        }
    }
}

TEST_CASE("diff_image amplifies and clamps the difference, alpha opaque") {
    const image::Image a = two_pixels({0, 0, 0, 0}, {100, 20, 30, 255});
    const image::Image b = two_pixels({0, 0, 0, 9}, {90, 25, 30, 0});
    const auto diff = image::diff_image(a, b, 16);
    REQUIRE(diff.ok());
    CHECK(image::pixel_at(*diff, 0, 0) == image::Rgba{0, 0, 0, 255});
    CHECK(image::pixel_at(*diff, 1, 0) == image::Rgba{160, 80, 0, 255});
    CHECK(image::diff_image(a, b, 200)->rgba[4] == 255);
    CHECK_FALSE(image::diff_image(a, b, 0).ok());
}

TEST_CASE("contact_sheet lays images on a grid") {
    const image::Image red = image::make_image(2, 2, {255, 0, 0, 255});
    const image::Image green = image::make_image(3, 1, {0, 255, 0, 255});
    const auto row = image::contact_sheet({{"red", &red}, {"green", &green}}, 2);
    REQUIRE(row.ok());
    // Cells of 3x2 with 4-pixel borders: 4 + 3 + 4 + 3 + 4 by 4 + 2 + 4.
    CHECK(row->width == 18);
    CHECK(row->height == 10);
    CHECK(image::pixel_at(*row, 4, 4) == image::Rgba{255, 0, 0, 255});
    CHECK(image::pixel_at(*row, 11, 4) == image::Rgba{0, 255, 0, 255});
    CHECK(image::pixel_at(*row, 11, 5) == image::Rgba{64, 64, 64, 255});
    CHECK(image::pixel_at(*row, 0, 0) == image::Rgba{64, 64, 64, 255});

    const auto column = image::contact_sheet({{"red", &red}, {"green", &green}}, 1);
    REQUIRE(column.ok());
    CHECK(column->width == 11);
    CHECK(column->height == 16);
    CHECK(image::pixel_at(*column, 4, 10) == image::Rgba{0, 255, 0, 255});

    const auto null = image::contact_sheet({{"red", &red}, {"egl", nullptr}}, 2);
    REQUIRE_FALSE(null.ok());
    CHECK(null.error() == "image::contact_sheet(): image 'egl' is null");
    CHECK_FALSE(image::contact_sheet({}, 2).ok());
}

} // TEST_SUITE
