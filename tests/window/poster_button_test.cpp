// The panel's screenshot control at a multiple of the window (issue 36),
// driven like a user would under xvfb-run with xdotool: the "screenshot
// size" list set to 4x, then the "screenshot" button. The file it saves,
// frustum-window-4x.png, must be 4 x the window's size, and box-filtered 4x
// it must be the window's own frame beside the panel (the poster draws the
// same view as crop tiles, without the panel).
//
// The script (tests/window/poster_clicks.sh) clicks the widgets by name
// where the window says it drew them, so it does not depend on how many
// rows the panel has above them; every wait is for a state (a frame drawn,
// a widget drawn, the list closed, the file there: it is written whole)
// with a timeout, never a fixed sleep.
#include "process.hpp"
#include "shots.hpp"

#include "../skips.hpp"

#include <doctest/doctest.h>

#include <demo/window_panel.hpp>
#include <image/compare.hpp>
#include <image/thumbnail.hpp>

#include <string>
#include <vector>

namespace {

using support::TempDir;

constexpr int kWindowWidthPx = 640;
constexpr int kWindowHeightPx = 400;
constexpr int kScale = 4;
constexpr int kPanelPx = static_cast<int>(demo::kPanelWidthPx) + 1; // with its border


} // namespace

TEST_SUITE("window") {

TEST_CASE("the panel's screenshot at 4x saves a poster 4x the window that, downsampled, is the window's frame") {
    const std::string xvfb_run = window_test::find_on_path("xvfb-run");
    if (xvfb_run.empty() || window_test::find_on_path("xdotool").empty() ||
        window_test::find_on_path("import").empty()) {
        test_skips::skip("needs xvfb-run, xdotool and ImageMagick's import (scripts/install-deps.sh --window)");
        return;
    }
    TempDir dir;
    const std::string script = std::string(FRUSTUM_SOURCE_DIR) + "/tests/window/poster_clicks.sh";
    const window_test::Child child = window_test::run(
        xvfb_run, {"-a", "-s", "-screen 0 1024x768x24", "bash", script, window_test::kDemo, (dir / "").string()});
    REQUIRE_MESSAGE(child.exit_status == 0, child.err);

    const image::Image window = window_test::read(dir / "window.png");
    REQUIRE(window.width == kWindowWidthPx);
    REQUIRE(window.height == kWindowHeightPx);
    const image::Image poster = window_test::read(dir / "frustum-window-4x.png");
    // The chosen multiple of the window.
    CHECK(poster.width == kScale * kWindowWidthPx);
    CHECK(poster.height == kScale * kWindowHeightPx);
    REQUIRE(poster.width == kScale * window.width);
    REQUIRE(poster.height == kScale * window.height);

    // Box-filtered 4x (each pixel the mean of its 4 x 4 block), as a poster's thumbnail.
    image::Thumbnail small(poster.width, poster.height, kWindowWidthPx);
    small.add_rows(poster);
    REQUIRE(small.factor() == kScale);
    // Beside the panel (the poster has none) the window's frame. Tolerance
    // as test_poster_slow's 16384^2-downsampled-4x check (not equal: 16
    // pixels x 4 samples against the window's 4 samples, so edges differ by
    // some LSB): RGB means at most 1 LSB, at most 1% of the pixels more than
    // 24 LSB off. A poster of another view, size or crop differs in most
    // pixels.
    std::vector<bool> beside(static_cast<std::size_t>(window.width) * window.height, false);
    for (int y = 0; y < window.height; ++y) {
        for (int x = kPanelPx; x < window.width; ++x) {
            beside[static_cast<std::size_t>(y) * window.width + x] = true;
        }
    }
    const auto diff = image::compare_masked(window, small.image(), beside, image::Channels::Rgb, 24);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    MESSAGE("4x poster downsampled vs the window beside the panel: mean " << diff->mean_abs << " LSB, "
                                                                           << 100.0 * diff->fraction_over()
                                                                           << "% pixels over 24 LSB");
    CHECK(diff->mean_abs <= 1.0);
    CHECK(diff->fraction_over() <= 0.01);
}

} // TEST_SUITE
