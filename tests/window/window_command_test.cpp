// `frustum-demo window` as a built binary. Under xvfb-run (an X server in
// memory; skipped with a message when xvfb-run is not installed) its
// --screenshot must match `frustum-demo render` of the same view: the
// window draws with the same renderer into an offscreen target and blits it
// 1:1, and with no input its camera is the scene's main camera exactly.
// Tolerances: shots.hpp.
#include "process.hpp"
#include "shots.hpp"

#include <doctest/doctest.h>

#include <image/compare.hpp>
#include <image/image.hpp>
#include <image/png.hpp>
#include <plan/effect.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace {

using window_test::Child;
using window_test::check_similar;
using window_test::crop;
using window_test::kDemo;
using window_test::kTolerance;
using window_test::read;
using window_test::render_offscreen;
using window_test::run_window_under_xvfb;
using support::TempDir;

} // namespace

TEST_SUITE("window") {

TEST_CASE("the window's screenshot matches the offscreen renderer for every effect") {
    for (plan::Effect effect : plan::kAllEffects) {
        const std::string name(plan::to_string(effect));
        CAPTURE(name);
        TempDir dir;
        const std::string shot = (dir / "window.png").string();
        const auto child =
            run_window_under_xvfb({"--size", "256x144", "--effect", name, "--frames", "3", "--screenshot", shot});
        if (!child) {
            return;
        }
        REQUIRE_MESSAGE(child->exit_status == 0, child->err);
        CHECK(child->out == shot + "\n");
        const image::Image window = read(shot);
        CHECK(window.width == 256);
        CHECK(window.height == 144);
        check_similar(window, render_offscreen(dir, name, "256x144"), name);
    }
}

// --context gl: a desktop OpenGL core context (through EGL, as the ES one)
// draws the same frames, the panel shown and hidden again (P twice) as in
// panel_test.cpp; the mirror effect (clip control, the reflection pass) and
// the recursion effect (its levels marked as passes).
TEST_CASE("--context gl: the window with the panel hidden equals render") {
    for (const std::string effect : {"mirror", "recursion"}) {
        CAPTURE(effect);
        TempDir dir;
        const std::string shot = (dir / "window.png").string();
        const auto child = run_window_under_xvfb({"--context", "gl", "--size", "256x144", "--effect", effect, "--panel",
                                                  "--keys", "P,P,P", "--frames", "4", "--screenshot", shot, "--verbose"});
        if (!child) {
            return;
        }
        REQUIRE_MESSAGE(child->exit_status == 0, child->err);
        // --verbose names the context by its GL_VERSION, which starts with "OpenGL ES" only on ES.
        CHECK_MESSAGE(child->err.find("window: context: ") != std::string::npos, child->err);
        CHECK_MESSAGE(child->err.find("window: context: OpenGL ES") == std::string::npos, child->err);
        check_similar(read(shot), render_offscreen(dir, effect, "256x144"), effect);
    }
}

// The effect options set where the window starts: --lens-power and --tiles
// (the viewer's state, which the keys then change) as much as the others;
// --depth minus_one_to_one the [-1, 1] conversion (the default takes clip
// control where the context has it, so this is the other path).
TEST_CASE("the window starts from --lens-power, --tiles and --depth as render draws them") {
    for (const std::vector<std::string>& options :
         {std::vector<std::string>{"--effect", "lens", "--lens-power", "1.5"},
          std::vector<std::string>{"--effect", "tiles", "--tiles", "20x2", "--tile-borders"},
          std::vector<std::string>{"--effect", "mirror", "--depth", "minus_one_to_one", "--verbose"}}) {
        CAPTURE(options[1]);
        TempDir dir;
        const std::string shot = (dir / "window.png").string();
        std::vector<std::string> window_options{"--size", "128x72", "--frames", "2", "--screenshot", shot};
        window_options.insert(window_options.end(), options.begin(), options.end());
        const auto child = run_window_under_xvfb(window_options);
        if (!child) {
            return;
        }
        REQUIRE_MESSAGE(child->exit_status == 0, child->err);
        if (options[2] == "--depth") {
            CHECK_MESSAGE(child->err.find("depth: matrices converted to the [-1, 1] clip range\n") !=
                              std::string::npos,
                          child->err);
        }
        std::vector<std::string> render_args{"render", "--size", "128x72", "--out", (dir / "render").string()};
        render_args.insert(render_args.end(), options.begin(), options.end());
        const Child rendered = window_test::run(kDemo, render_args);
        REQUIRE_MESSAGE(rendered.exit_status == 0, rendered.err);
        check_similar(read(shot), read(dir / "render" / (options[1] + ".png")), options[1]);
    }
}

TEST_CASE("--stereo: the window's two eyes match render --stereo") {
    // Each eye its own camera and mirror, side by side; a wide base so the
    // two halves differ visibly.
    TempDir dir;
    const std::string shot = (dir / "window.png").string();
    const std::vector<std::string> stereo{"--stereo", "--ipd-m", "0.5"};
    std::vector<std::string> options{"--size", "256x72", "--effect", "mirror", "--frames", "3", "--screenshot", shot};
    options.insert(options.end(), stereo.begin(), stereo.end());
    const auto child = run_window_under_xvfb(options);
    if (!child) {
        return;
    }
    REQUIRE_MESSAGE(child->exit_status == 0, child->err);
    const image::Image window = read(shot);
    REQUIRE(window.width == 256);
    check_similar(window, render_offscreen(dir, "mirror", "256x72", stereo), "stereo mirror");
    // The halves are two different eyes, not one picture twice.
    const auto halves = image::compare(crop(window, 0, 0, 128, 72), crop(window, 128, 0, 256, 72), kTolerance);
    REQUIRE_MESSAGE(halves.ok(), halves.error());
    CHECK(halves->fraction_over() > 0.05);
}

TEST_CASE("the help overlay and the inset cover only their corners") {
    TempDir dir;
    const auto shot = [&](const std::string& file, std::vector<std::string> extra) {
        std::vector<std::string> options{"--size", "640x360", "--frames", "2", "--screenshot", (dir / file).string()};
        options.insert(options.end(), extra.begin(), extra.end());
        return run_window_under_xvfb(options);
    };
    const auto plain = shot("plain.png", {});
    if (!plain) {
        return;
    }
    REQUIRE_MESSAGE(plain->exit_status == 0, plain->err);
    const auto help = shot("help.png", {"--help-overlay"});
    const auto inset = shot("inset.png", {"--inset"});
    REQUIRE_MESSAGE(help->exit_status == 0, help->err);
    REQUIRE_MESSAGE(inset->exit_status == 0, inset->err);
    const image::Image base = read(dir / "plain.png");
    const image::Image with_help = read(dir / "help.png");
    const image::Image with_inset = read(dir / "inset.png");
    // The help panel sits top-left and the inset (a third of the width) top-right.
    check_similar(crop(with_help, 480, 250, 640, 360), crop(base, 480, 250, 640, 360), "outside the help panel");
    CHECK(image::compare(crop(with_help, 0, 0, 200, 100), crop(base, 0, 0, 200, 100), kTolerance)->pixels_over > 1000);
    check_similar(crop(with_inset, 0, 150, 640, 360), crop(base, 0, 150, 640, 360), "below the inset");
    CHECK(image::compare(crop(with_inset, 430, 10, 630, 110), crop(base, 430, 10, 630, 110), kTolerance)->pixels_over >
          1000);
}

TEST_CASE("without a display the window command says so and exits 1") {
    TempDir dir;
    const std::string shot = (dir / "never.png").string();
    const Child child = window_test::run(kDemo, {"window", "--frames", "1", "--screenshot", shot},
                                         {{"DISPLAY", std::nullopt}, {"WAYLAND_DISPLAY", std::nullopt}});
    CHECK(child.exit_status == 1);
    CHECK(child.out.empty());
    CHECK(child.err.find("frustum-demo window: error: cannot open a window: ") == 0);
    CHECK(child.err.find("no display (DISPLAY is not set") != std::string::npos);
    CHECK(child.err.find("use `frustum-demo render` for offscreen images\n") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(shot));
}

TEST_CASE("window usage errors exit 2 before opening anything") {
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"--frames", "0"}, "--frames must be 1..1000000, got '0'"},
        {{"--frames", "x"}, "--frames must be 1..1000000, got 'x'"},
        {{"--screenshot", "a.png"}, "--screenshot needs --frames N"},
        {{"--size", "0x10"}, "--size must be WxH with 1..8192 each, got '0x10'"},
        {{"--tiles", "0x1"}, "--tiles must be NxM (columns x rows, each >= 1), got '0x1'"},
        {{"--slit", "-1"}, "--slit must be a depth in (0, 1000] metres, got '-1'"},
        {{"--lens-center", "2,0"}, "--lens-center must be x,y with each in [-1, 1]"},
        {{"--mirror-plane", "0,0,0,1"}, "--mirror-plane must be a,b,c,d"},
        {{"--keys", "Ctrl+X"}, "--keys must be a comma-separated list of keys"},
        {{"--effect", "sepia"}, "unknown effect 'sepia' (expected plain, mirror, tiles, frustum"},
        {{"--mirror", "flat"}, "unknown mirror method 'flat'"},
        {{"--msaa", "0"}, "--msaa must be a sample count in 1..64 (1 = off), got '0'"},
        {{"--colour"}, "unknown option '--colour' of window"},
        {{"--size"}, "--size needs a value"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"window"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        CAPTURE(c.message);
        const Child child = window_test::run(kDemo, args, {{"DISPLAY", std::nullopt}});
        CHECK(child.exit_status == 2);
        CHECK(child.err.find("frustum-demo window: error: " + c.message) == 0);
    }
}

TEST_CASE("window --help lists the options") {
    const Child child = window_test::run(kDemo, {"window", "--help"});
    CHECK(child.exit_status == 0);
    for (const char* option : {"--scene", "--size", "--effect", "--frames", "--screenshot", "--help-overlay", "--inset", "--msaa"}) {
        CHECK(child.out.find(option) != std::string::npos);
    }
}

} // TEST_SUITE

TEST_SUITE("window") {

// The effect options come from one table: both commands list the same
// ones in --help and refuse the same bad value with the same message.
TEST_CASE("render and window share every effect option, with the same messages") {
    const Child render_help = window_test::run(kDemo, {"--help"});
    const Child window_help = window_test::run(kDemo, {"window", "--help"});
    REQUIRE(render_help.exit_status == 0);
    REQUIRE(window_help.exit_status == 0);
    const auto section = [](const std::string& help) {
        const std::size_t start = help.find("effect options");
        REQUIRE(start != std::string::npos);
        return help.substr(start, help.find("\nUnset", start) - start);
    };
    const std::string render_options = section(render_help.out);
    CHECK(render_options.substr(render_options.find('\n')) ==
          section(window_help.out).substr(section(window_help.out).find('\n')));
    std::vector<std::string> names;
    for (std::size_t at = render_options.find("\n  --"); at != std::string::npos;
         at = render_options.find("\n  --", at + 1)) {
        const std::size_t end = render_options.find(' ', at + 3);
        names.push_back(render_options.substr(at + 3, end - at - 3));
    }
    CHECK(names.size() >= 14);
    for (const std::string& name : names) {
        CAPTURE(name);
        if (name == "--tile-borders" || name == "--fog" || name == "--stereo") {
            continue; // flags: no value to refuse
        }
        const Child r = window_test::run(kDemo, {"render", name, "bogus!"});
        const Child w = window_test::run(kDemo, {"window", name, "bogus!"}, {{"DISPLAY", std::nullopt}});
        CHECK(r.exit_status == 2);
        CHECK(w.exit_status == 2);
        const std::string r_prefix = "frustum-demo: error: ", w_prefix = "frustum-demo window: error: ";
        REQUIRE(r.err.rfind(r_prefix, 0) == 0);
        REQUIRE(w.err.rfind(w_prefix, 0) == 0);
        CHECK(r.err.substr(r_prefix.size()) == w.err.substr(w_prefix.size()));
        CHECK(r.err.find("bogus!") != std::string::npos);
    }
}

} // TEST_SUITE
