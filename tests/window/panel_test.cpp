// The window's control panel (key P, --panel) under xvfb-run: it covers
// only its own region (the left demo::kPanelWidthPx screen units), hiding
// it again gives `frustum-demo render`'s image, and clicks on it (xdotool,
// panel_clicks.sh) change the effect and an option while a refused value
// shows its error in the panel and leaves the view alone; the scene file
// control (scene_clicks.sh) loads another sample, as `render` draws it, and
// a missing file leaves it on screen with the error in the panel. Tolerances:
// shots.hpp; "differs" means more than 200 pixels differ by more than it.
#include "process.hpp"
#include "shots.hpp"

#include "../skips.hpp"

#include <doctest/doctest.h>

#include <demo/scene_files.hpp>
#include <demo/window_panel.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include <string>
#include <vector>

namespace {

using window_test::check_similar;
using window_test::crop;
using window_test::pixels_differing;
using window_test::read;
using window_test::render_offscreen;
using support::TempDir;

constexpr int kPanelPx = static_cast<int>(demo::kPanelWidthPx) + 1; // with its border
constexpr int kDiffers = 200;

// The part of a screenshot right of the panel.
image::Image beside_panel(const image::Image& shot) { return crop(shot, kPanelPx, 0, shot.width, shot.height); }
image::Image panel_part(const image::Image& shot) { return crop(shot, 0, 0, kPanelPx, shot.height); }

struct ScriptShots {
    window_test::Child child;
    image::Image a, b, c, d; // the script's a.png .. d.png
    std::string a_state, b_state, c_state, d_state; // the window's state line at each (FRUSTUM_WINDOW_STATE)
};

std::string slurp(const std::filesystem::path& path) {
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// The value of `name=` in a state line (window::state_line()); empty when absent.
std::string state_field(const std::string& line, const std::string& name) {
    std::istringstream words(line);
    for (std::string word; words >> word;) {
        if (word.rfind(name + "=", 0) == 0) {
            return word.substr(name.size() + 1);
        }
    }
    return {};
}

// tests/window/<script> FRUSTUM_DEMO OUT_DIR args... under xvfb-run, which
// must end with 0, and its four screenshots; empty (after recording a skip) when
// xvfb-run, xdotool or ImageMagick's import is missing.
std::optional<ScriptShots> run_panel_script(const std::string& script, const TempDir& dir,
                                            const std::vector<std::string>& args = {}) {
    const std::string xvfb_run = window_test::find_on_path("xvfb-run");
    if (xvfb_run.empty() || window_test::find_on_path("xdotool").empty() ||
        window_test::find_on_path("import").empty()) {
        test_skips::skip("needs xvfb-run, xdotool and ImageMagick's import (scripts/install-deps.sh --window)");
        return std::nullopt;
    }
    std::vector<std::string> all{"-a", "-s", "-screen 0 1024x768x24", "bash",
                                 std::string(FRUSTUM_SOURCE_DIR) + "/tests/window/" + script, window_test::kDemo,
                                 (dir / "").string()};
    all.insert(all.end(), args.begin(), args.end());
    ScriptShots shots;
    shots.child = window_test::run(xvfb_run, all);
    REQUIRE_MESSAGE(shots.child.exit_status == 0, shots.child.err);
    shots.a = read(dir / "a.png");
    shots.b = read(dir / "b.png");
    shots.c = read(dir / "c.png");
    shots.d = read(dir / "d.png");
    shots.a_state = slurp(dir / "a.state");
    shots.b_state = slurp(dir / "b.state");
    shots.c_state = slurp(dir / "c.state");
    shots.d_state = slurp(dir / "d.state");
    REQUIRE(shots.a.width == 480);
    return shots;
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("the panel covers only its region; hidden again the window equals render") {
    TempDir dir;
    const auto shot = [&](const std::string& file, std::vector<std::string> extra) {
        std::vector<std::string> options{"--size", "480x270", "--frames", "4", "--screenshot", (dir / file).string()};
        options.insert(options.end(), extra.begin(), extra.end());
        return window_test::run_window_under_xvfb(options);
    };
    const auto shown = shot("panel.png", {"--panel"});
    if (!shown) {
        return;
    }
    REQUIRE_MESSAGE(shown->exit_status == 0, shown->err);
    // P three times: hidden, shown (one ImGui frame drawn), hidden, then the screenshot.
    const auto hidden = shot("hidden.png", {"--panel", "--keys", "P,P,P"});
    REQUIRE_MESSAGE(hidden->exit_status == 0, hidden->err);
    const image::Image rendered = render_offscreen(dir, "plain", "480x270");
    const image::Image with_panel = read(dir / "panel.png");
    check_similar(beside_panel(with_panel), beside_panel(rendered), "beside the panel");
    CHECK(pixels_differing(panel_part(with_panel), panel_part(rendered)) > 20000);
    check_similar(read(dir / "hidden.png"), rendered, "panel hidden again");
}

TEST_CASE("clicks on the panel change the effect and the lens power; a refused value changes nothing") {
    TempDir dir;
    const auto child = run_panel_script("panel_clicks.sh", dir);
    if (!child) {
        return;
    }
    const image::Image &a = child->a, &b = child->b, &c = child->c, &d = child->d;
    // The effect list's "lens": the view is render's lens effect.
    check_similar(beside_panel(b), beside_panel(render_offscreen(dir, "lens", "480x360")), "lens chosen");
    CHECK(pixels_differing(beside_panel(a), beside_panel(b)) > kDiffers);
    CHECK(state_field(child->a_state, "effect") == "plain");
    CHECK(state_field(child->b_state, "effect") == "lens");
    CHECK(state_field(child->b_state, "lens-power") == "2");
    // The --lens-power slider, (0, 2] along its grab's span, clicked a
    // quarter along: the window took 0.5 to within 0.02 (measured 0.507: the
    // click lands on a whole pixel, 0.012 of power at this width; 0.02 is
    // under two pixels), and
    // drew another magnification.
    const std::string power = state_field(child->c_state, "lens-power");
    REQUIRE(!power.empty());
    INFO("lens power after the click: " << power);
    CHECK(std::abs(std::stod(power) - 0.5) <= 0.02);
    CHECK(state_field(child->c_state, "effect") == "lens");
    CHECK(pixels_differing(beside_panel(b), beside_panel(c)) > kDiffers);
    // Its left end, 0, is refused by the row ("--lens-power must be a number
    // in (0, 2]"): the panel shows the message, the view stays.
    check_similar(beside_panel(d), beside_panel(c), "refused value");
    CHECK(state_field(child->d_state, "lens-power") == power);
    CHECK(pixels_differing(crop(c, 0, 20, kPanelPx, 45), crop(d, 0, 20, kPanelPx, 45)) > kDiffers); // the message on top
}

TEST_CASE("the scene file control loads another scene, and a missing file leaves the old one on screen") {
    TempDir dir;
    const std::string box = std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-models/box.gltf";
    // The other scene: the textured square of the feature files (tests/data/gltf-features, the folder next to box's).
    const std::string other = std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-features/orientation.gltf";
    // In the "beside it" list, as the panel derives it, among the eight rows the open list shows.
    const std::vector<std::string> beside = demo::scene_files_beside(box);
    const auto at = std::find(beside.begin(), beside.end(), other);
    REQUIRE(at != beside.end());
    REQUIRE(at - beside.begin() < 8);
    const auto child = run_panel_script("scene_clicks.sh", dir, {box, "orientation.gltf", "/nonexistent/missing.gltf"});
    if (!child) {
        return;
    }
    const image::Image &a = child->a, &b = child->b, &c = child->c, &d = child->d;
    // The square chosen: the view changes, and with the panel hidden it is what render draws of it.
    CHECK(pixels_differing(beside_panel(a), beside_panel(b)) > kDiffers);
    const image::Image rendered = render_offscreen(dir, "plain", "480x480", {"--scene", other});
    check_similar(beside_panel(b), beside_panel(rendered), "the square loaded");
    check_similar(d, rendered, "the square loaded, panel hidden");
    // The missing file: its error on top of the panel, the square still on screen.
    check_similar(beside_panel(c), beside_panel(b), "missing file");
    CHECK(pixels_differing(crop(b, 0, 20, kPanelPx, 45), crop(c, 0, 20, kPanelPx, 45)) > kDiffers);
    CHECK(child->child.err.find("does not exist") == std::string::npos); // shown in the panel, not printed
}

} // TEST_SUITE
