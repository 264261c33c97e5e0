#include "shots.hpp"

#include "../skips.hpp"

#include <doctest/doctest.h>

#include <image/compare.hpp>
#include <image/png.hpp>

namespace window_test {
namespace {

image::Image opaque(image::Image picture) {
    for (std::size_t alpha = 3; alpha < picture.rgba.size(); alpha += 4) {
        picture.rgba[alpha] = 255;
    }
    return picture;
}

} // namespace

std::optional<Child> run_window_under_xvfb(const std::vector<std::string>& options) {
    static const std::string xvfb_run = find_on_path("xvfb-run");
    if (xvfb_run.empty()) {
        test_skips::skip("xvfb-run is not installed (scripts/install-deps.sh --window installs xvfb)");
        return std::nullopt;
    }
    std::vector<std::string> args{"-a", "-s", "-screen 0 1024x768x24", kDemo, "window"};
    args.insert(args.end(), options.begin(), options.end());
    return run(xvfb_run, args);
}

image::Image read(const std::filesystem::path& path) {
    auto picture = image::read_png(path.string());
    REQUIRE_MESSAGE(picture.ok(), picture.error());
    return std::move(*picture);
}

image::Image render_offscreen(const support::TempDir& dir, const std::string& effect, const std::string& size,
                              const std::vector<std::string>& more) {
    std::vector<std::string> args{"render", "--size", size, "--effect", effect, "--out", (dir / "render").string()};
    args.insert(args.end(), more.begin(), more.end());
    const Child child = run(kDemo, args);
    REQUIRE_MESSAGE(child.exit_status == 0, child.err);
    return read(dir / "render" / (effect + ".png"));
}

image::Image crop(const image::Image& picture, int x0, int y0, int x1, int y1) {
    image::Image part = image::make_image(x1 - x0, y1 - y0, {0, 0, 0, 0});
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            image::set_pixel(part, x - x0, y - y0, image::pixel_at(picture, x, y));
        }
    }
    return part;
}

void check_similar(const image::Image& window, const image::Image& offscreen, const std::string& what) {
    const auto diff = image::compare(opaque(window), opaque(offscreen), kTolerance);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    INFO(what << ": " << diff->pixels_over << " of " << diff->pixel_count << " pixels differ by more than "
              << kTolerance << ", max " << diff->max_abs);
    CHECK(diff->fraction_over() <= kMaxFractionOver);
}

int pixels_differing(const image::Image& a, const image::Image& b) {
    const auto diff = image::compare(opaque(a), opaque(b), kTolerance);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    return diff->pixels_over;
}

} // namespace window_test
