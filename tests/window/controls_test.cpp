// Input events -> ViewerState, driven without a window.
#include "../plan/showcase.hpp"

#include <doctest/doctest.h>
// Approx epsilon of these float results: 2 float ulps relative (2 x 1.19e-7), doctest's
// default (1.19e-5) being 100; each passes at 2 ulps (measured: tightened until one failed).
static constexpr double kFloatTwoUlps = 2.4e-7;

#include <demo/effect_options.hpp>
#include <plan/link_moves.hpp>
#include <window/controls.hpp>
#include <window/frame.hpp>
#include <window/key_help.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

namespace {

gl::KeyPressed character(char c, bool shift = false) {
    gl::KeyPressed press;
    press.key = gl::Key::Character;
    press.character = c;
    press.mods.shift = shift;
    return press;
}

gl::KeyPressed key(gl::Key k, bool shift = false) {
    gl::KeyPressed press;
    press.key = k;
    press.mods.shift = shift;
    return press;
}

struct Rig {
    plan::Cameras cameras = render_test::showcase_cameras();
    window::Controls controls{window::control_scene(render_test::showcase())};
    window::ViewerState state;

    void send(const gl::InputEvent& event) { controls.apply(event, cameras.main.pair, state); }
};

} // namespace

TEST_SUITE("window") {

TEST_CASE("number keys pick the effects of plan::kAllEffects in order") {
    Rig rig;
    for (std::size_t i = 0; i < std::size(plan::kAllEffects) && i < 9; ++i) {
        rig.send(character(static_cast<char>('1' + i)));
        CHECK(rig.state.effect == plan::kAllEffects[i]);
    }
    rig.send(character('1'));
    rig.send(character(static_cast<char>('1' + std::size(plan::kAllEffects)))); // one past: ignored
    CHECK(rig.state.effect == plan::Effect::Plain);
}

TEST_CASE("toggles and Escape") {
    Rig rig;
    rig.send(character('H'));
    CHECK(rig.state.show_help);
    gl::KeyPressed held = character('H');
    held.repeat = true;
    rig.send(held); // a held key does not flicker
    CHECK(rig.state.show_help);
    rig.send(character('H'));
    CHECK_FALSE(rig.state.show_help);
    rig.send(character('F'));
    CHECK(rig.state.show_inset);
    rig.send(character('O'));
    CHECK(rig.state.mirror_method == plan::MirrorMethod::Rectangle);
    rig.send(character('O'));
    rig.send(character('O'));
    CHECK(rig.state.mirror_method == plan::MirrorMethod::Oblique);
    CHECK_FALSE(rig.state.quit);
    rig.send(key(gl::Key::Escape));
    CHECK(rig.state.quit);
}

TEST_CASE("the camera stays the scene's until the first camera input, and R brings it back") {
    Rig rig;
    rig.send(gl::CursorMoved{100.0, 100.0});
    rig.send(gl::CursorMoved{150.0, 100.0}); // moving without a button: no orbit
    rig.send(character('H'));
    CHECK_FALSE(rig.state.orbit);

    rig.send(character('D'));
    REQUIRE(rig.state.orbit);
    const window::OrbitCamera start = window::orbit_from_pair(rig.cameras.main.pair, render_test::showcase().world_bounds);
    CHECK(rig.state.orbit->yaw_rad == doctest::Approx(start.yaw_rad + 0.0872664626f).epsilon(kFloatTwoUlps));
    rig.send(character('R'));
    CHECK_FALSE(rig.state.orbit);
}

TEST_CASE("left drag orbits, right drag and Shift + left drag pan, the wheel zooms") {
    Rig rig;
    const window::OrbitCamera start = window::orbit_from_pair(rig.cameras.main.pair, render_test::showcase().world_bounds);
    rig.send(gl::CursorMoved{10.0, 10.0});
    rig.send(gl::MouseButtonChanged{gl::MouseButton::Left, true, {}});
    rig.send(gl::CursorMoved{20.0, 10.0});
    REQUIRE(rig.state.orbit);
    CHECK(rig.state.orbit->yaw_rad < start.yaw_rad); // drag right: the eye goes left
    CHECK(rig.state.orbit->target == start.target);
    rig.send(gl::MouseButtonChanged{gl::MouseButton::Left, false, {}});

    const window::OrbitCamera before_pan = *rig.state.orbit;
    rig.send(gl::MouseButtonChanged{gl::MouseButton::Right, true, {}});
    rig.send(gl::CursorMoved{30.0, 10.0});
    rig.send(gl::MouseButtonChanged{gl::MouseButton::Right, false, {}});
    CHECK(rig.state.orbit->yaw_rad == before_pan.yaw_rad);
    CHECK(rig.state.orbit->target != before_pan.target);

    const glm::vec3 target = rig.state.orbit->target;
    gl::Modifiers shift;
    shift.shift = true;
    rig.send(gl::MouseButtonChanged{gl::MouseButton::Left, true, shift});
    rig.send(gl::CursorMoved{30.0, 40.0});
    CHECK(rig.state.orbit->target.y > target.y); // drag down: the scene follows the cursor, the camera goes up
    rig.send(gl::MouseButtonChanged{gl::MouseButton::Left, false, shift});

    const float distance = rig.state.orbit->distance_m;
    rig.send(gl::Scrolled{0.0, 2.0});
    CHECK(rig.state.orbit->distance_m == doctest::Approx(distance * 0.81f).epsilon(kFloatTwoUlps));
}

TEST_CASE("arrows turn, tilt, slide and push the mirror; M puts it back") {
    Rig rig;
    rig.send(key(gl::Key::Left));
    rig.send(key(gl::Key::Up));
    CHECK(rig.state.mirror.turn_rad == doctest::Approx(0.0872664626f).epsilon(kFloatTwoUlps));
    CHECK(rig.state.mirror.tilt_rad == doctest::Approx(-0.0872664626f).epsilon(kFloatTwoUlps));
    rig.send(key(gl::Key::Right, true));
    rig.send(key(gl::Key::Down, true));
    // 5% of the showcase mirror's longer edge (3 m).
    CHECK(rig.state.mirror.slide_m == doctest::Approx(0.15f).epsilon(kFloatTwoUlps));
    CHECK(rig.state.mirror.push_m == doctest::Approx(-0.15f).epsilon(kFloatTwoUlps));
    CHECK_FALSE(rig.state.orbit); // the camera did not move
    rig.send(character('M'));
    CHECK(rig.state.mirror == window::MirrorPose{});
}

TEST_CASE("without a mirror the arrows do nothing") {
    window::Controls controls{window::ControlScene{}};
    window::ViewerState state;
    controls.apply(key(gl::Key::Left), render_test::showcase_cameras().main.pair, state);
    CHECK(state.mirror == window::MirrorPose{});
}

TEST_CASE("+ and - grow and shrink the tile grid within 1..16") {
    CHECK(window::next_tiles(3, 2, 1) == std::pair<int, int>(3, 3));
    CHECK(window::next_tiles(3, 3, 1) == std::pair<int, int>(4, 3));
    CHECK(window::next_tiles(4, 3, -1) == std::pair<int, int>(3, 3));
    CHECK(window::next_tiles(3, 3, -1) == std::pair<int, int>(3, 2));
    CHECK(window::next_tiles(1, 1, -1) == std::pair<int, int>(1, 1));
    // --tiles 20x2 (accepted by window as by render): '+' keeps the 20 columns, '-' removes one.
    CHECK(window::next_tiles(20, 2, 1) == std::pair<int, int>(20, 3));
    CHECK(window::next_tiles(20, 16, 1) == std::pair<int, int>(20, 16));
    CHECK(window::next_tiles(20, 2, -1) == std::pair<int, int>(19, 2));
    CHECK(window::next_tiles(16, 16, 1) == std::pair<int, int>(16, 16));
    Rig rig;
    rig.send(character('=', true)); // '+' on a US keyboard
    CHECK(rig.state.tile_rows == 3);
    rig.send(character('+')); // keypad
    CHECK(rig.state.tile_columns == 4);
    rig.send(character('-'));
    rig.send(character('-'));
    CHECK(rig.state.tile_columns == 3);
    CHECK(rig.state.tile_rows == 2);
}

TEST_CASE("[ and ] change the lens power by 1.25 within [0.25, 2], --lens-power's bound") {
    Rig rig;
    rig.send(character(']'));
    CHECK(rig.state.lens_power == doctest::Approx(2.0f).epsilon(kFloatTwoUlps)); // starts at 2, the bound
    rig.send(character('['));
    rig.send(character('['));
    CHECK(rig.state.lens_power == doctest::Approx(1.28f).epsilon(kFloatTwoUlps));
    CHECK(window::next_lens_power(1.9f, 1) == doctest::Approx(window::kMaxLensPower).epsilon(kFloatTwoUlps));
    CHECK(window::kMaxLensPower == demo::kMaxLensPower);
    CHECK(window::next_lens_power(0.3f, -1) == doctest::Approx(window::kMinLensPower).epsilon(kFloatTwoUlps));
    const auto frame = window::make_frame(rig.state, rig.cameras, {}, scene::Bounds{}, 256, 144);
    REQUIRE_MESSAGE(frame.ok(), frame.error());
    CHECK(frame->options.lens_power == doctest::Approx(1.28f).epsilon(kFloatTwoUlps));
}

TEST_CASE(", and . change the recursion depth within 0..8") {
    Rig rig;
    rig.send(character('.'));
    CHECK(rig.state.recursion_depth == 5);
    for (int i = 0; i < 10; ++i) {
        rig.send(character(','));
    }
    CHECK(rig.state.recursion_depth == 0);
    for (int i = 0; i < 12; ++i) {
        rig.send(character('.'));
    }
    CHECK(rig.state.recursion_depth == 8);
    const auto frame = window::make_frame(rig.state, rig.cameras, {}, scene::Bounds{}, 256, 144);
    REQUIRE_MESSAGE(frame.ok(), frame.error());
    CHECK(frame->options.recursion_depth == 8);
}

TEST_CASE("the help lists every effect, and docs/window.md lists every key") {
    const std::vector<std::string> lines = window::help_lines(window::ViewerState{});
    std::string all;
    for (const std::string& line : lines) {
        all += line + "\n";
    }
    for (plan::Effect effect : plan::kAllEffects) {
        CHECK(all.find(std::string(plan::to_string(effect))) != std::string::npos);
    }
    std::ifstream file(std::string(FRUSTUM_SOURCE_DIR) + "/docs/window.md");
    REQUIRE(file.good());
    std::stringstream docs;
    docs << file.rdbuf();
    for (const window::KeyHelp& entry : window::key_help()) {
        if (entry.keys.rfind("1..", 0) == 0) {
            continue; // the effect count changes as effects are added
        }
        CAPTURE(entry.keys);
        CHECK(docs.str().find("| " + entry.keys + " | " + entry.action + " |") != std::string::npos);
    }
}

} // TEST_SUITE

TEST_SUITE("window") {

TEST_CASE("Z X and C V move the recursion's two facing mirrors, each on its own; with Shift they turn") {
    Rig rig;
    const float step_m = 0.02f * window::bounds_radius(render_test::showcase().world_bounds);
    rig.send(character('Z'));
    rig.send(character('Z'));
    rig.send(character('V', true));
    CHECK(rig.state.link_moves[0].push_m == doctest::Approx(-2.0f * step_m).epsilon(kFloatTwoUlps));
    CHECK(rig.state.link_moves[0].turn_rad == 0.0f);
    CHECK(rig.state.link_moves[1].push_m == 0.0f);
    CHECK(rig.state.link_moves[1].turn_rad == doctest::Approx(0.0872664626f).epsilon(kFloatTwoUlps));
    rig.send(character('X'));
    rig.send(character('C'));
    CHECK(rig.state.link_moves[0].push_m == doctest::Approx(-step_m).epsilon(kFloatTwoUlps));
    CHECK(rig.state.link_moves[1].push_m == doctest::Approx(-step_m).epsilon(kFloatTwoUlps));
    CHECK_FALSE(rig.state.orbit); // not camera keys
    const auto frame = window::make_frame(rig.state, rig.cameras, {}, scene::Bounds{}, 256, 144);
    REQUIRE_MESSAGE(frame.ok(), frame.error());
    REQUIRE(frame->options.link_moves.size() == 2);
    CHECK(frame->options.link_moves[0] == rig.state.link_moves[0]);
    CHECK(frame->options.link_moves[1] == rig.state.link_moves[1]);
}

TEST_CASE("move_links: a push slides the mirror along its normal, a turn keeps its frame orthonormal") {
    const auto placed = plan::place_facing_links(render_test::showcase_cameras().main.pair,
                                                 render_test::showcase().world_bounds, plan::LinkSet::Mirrors);
    REQUIRE_MESSAGE(placed.ok(), placed.error());
    std::vector<plan::ViewLink> links = *placed;
    plan::move_links(links, {{0.5f, 0.0f}, {0.0f, 0.3f}});
    const glm::vec3 moved = links[0].entry.origin - (*placed)[0].entry.origin;
    CHECK(glm::length(moved - 0.5f * (*placed)[0].entry.normal()) < 1e-5f);
    const plan::ViewLink& turned = links[1];
    CHECK(glm::length(turned.entry.origin - (*placed)[1].entry.origin) < 1e-5f); // about its centre
    CHECK(std::abs(glm::length(turned.entry.x) - 1.0f) < 1e-6f);
    CHECK(std::abs(glm::dot(turned.entry.x, turned.entry.y)) < 1e-6f);
    // A normal turned by float trig and compared with cos(0.3f): over 2 ulps off (fails at 2), passes at 4: allowed 4.
    CHECK(glm::dot(turned.entry.normal(), (*placed)[1].entry.normal()) == doctest::Approx(std::cos(0.3f)).epsilon(4.8e-7));
}

} // TEST_SUITE
