// The panel's side of the one option table, without a window: each row's
// PanelControl keeps to the row's own bounds (a slider's ends and a
// choice's entries are what the row accepts, just outside is what it
// refuses), the panel's edits of the command line re-parse with the
// command line's own messages, and the live numbers come from the frame's
// pairs.
#include "../plan/showcase.hpp"
#include "../sample_files.hpp"

#include <doctest/doctest.h>
// Approx epsilon of these float results: 2 float ulps relative (2 x 1.19e-7), doctest's
// default (1.19e-5) being 100; each passes at 2 ulps (measured: tightened until one failed).
static constexpr double kFloatTwoUlps = 2.4e-7;

#include <demo/options.hpp>
#include <demo/panel_command_line.hpp>
#include <demo/scene_files.hpp>
#include <plan/number_text.hpp>
#include <window/frame.hpp>
#include <window/live_numbers.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <string>
#include <variant>
#include <vector>

namespace {

// The row's apply() on a fresh window Settings: empty = accepted, else the message.
std::optional<std::string> refusal(const demo::Option& row, const std::string& value) {
    demo::Settings settings = demo::defaults(demo::kWindow);
    if (auto failure = row.apply(settings, value)) {
        return failure->message;
    }
    return std::nullopt;
}

// `value` written as the row's text: each component, joined by its separator.
std::string row_text(const demo::PanelControl& control, float value) {
    const std::string one = control.whole ? std::to_string(static_cast<int>(value)) : plan::number_text(value);
    std::string text = one;
    for (int i = 1; i < control.components; ++i) {
        text += control.separator + one;
    }
    return text;
}

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> parts;
    for (std::size_t start = 0;;) {
        const std::size_t bar = text.find('|', start);
        parts.push_back(text.substr(start, bar - start));
        if (bar == std::string::npos) {
            return parts;
        }
        start = bar + 1;
    }
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("every panel slider spans its row's bounds: its high end is accepted, just outside is refused") {
    int sliders = 0;
    for (const demo::Option& row : demo::options()) {
        if (!(row.commands & demo::kWindow) || row.control.kind != demo::PanelControl::Kind::Slider) {
            continue;
        }
        CAPTURE(row.name);
        ++sliders;
        const demo::PanelControl& c = row.control;
        CHECK(c.low < c.high);
        CHECK_FALSE(refusal(row, row_text(c, c.high)));
        const float below = c.whole ? c.low - 1.0f : c.low - 0.01f * (c.high - c.low);
        CHECK(refusal(row, row_text(c, below)));
        // --sagitta's upper end is the mirror's (half its centre-to-rim
        // distance, checked with the scene): the row itself has none.
        if (row.name != "--sagitta") {
            const float above = c.whole ? c.high + 1.0f : c.high + 0.01f * (c.high - c.low);
            CHECK(refusal(row, row_text(c, above)));
        }
        // The example lies on the slider.
        const std::string example = row.example;
        const float first = std::stof(example);
        CHECK(first >= c.low);
        CHECK(first <= c.high);
    }
    CHECK(sliders >= 14);
}

TEST_CASE("every panel choice is accepted by its row; the effect list is plan::kAllEffects") {
    for (const demo::Option& row : demo::options()) {
        if (!(row.commands & demo::kWindow) || row.control.kind != demo::PanelControl::Kind::Choice) {
            continue;
        }
        CAPTURE(row.name);
        for (const std::string& choice : split(row.control.choices)) {
            CAPTURE(choice);
            CHECK_FALSE(refusal(row, choice));
        }
        CHECK(refusal(row, "nonsense"));
        if (row.name == "--effect") {
            CHECK(split(row.control.choices).size() == std::size(plan::kAllEffects));
        }
    }
}

TEST_CASE("the panel's command line: set replaces, remove drops, and a refused value has the command line's message") {
    demo::PanelCommandLine line({"window", "--effect", "lens", "--tile-borders", "--lens-power", "1.5"});
    CHECK(line.value("--lens-power") == "1.5");
    CHECK(line.value("--tile-borders") == "");
    CHECK_FALSE(line.value("--fog"));
    line.set("--lens-power", "0.5");
    line.set("--fog", "");
    line.remove("--tile-borders");
    CHECK(line.args() == std::vector<std::string>{"window", "--effect", "lens", "--lens-power", "0.5", "--fog"});
    CHECK(line.text() == "frustum-demo window --effect lens --lens-power 0.5 --fog");
    const auto parsed = line.parse();
    REQUIRE(std::holds_alternative<demo::Settings>(parsed));
    CHECK(std::get<demo::Settings>(parsed).lens_power == doctest::Approx(0.5f).epsilon(kFloatTwoUlps));
    CHECK(std::get<demo::Settings>(parsed).fog.has_value());

    line.set("--lens-power", "0");
    const auto refused = line.parse();
    const auto command_line = demo::parse_window_command_line({"window", "--lens-power", "0"});
    REQUIRE(std::holds_alternative<demo::Failure>(refused));
    REQUIRE(std::holds_alternative<demo::Failure>(command_line));
    CHECK(std::get<demo::Failure>(refused).message == std::get<demo::Failure>(command_line).message);
    CHECK(std::get<demo::Failure>(refused).message == "--lens-power must be a number in (0, 2], got '0'");
}

TEST_CASE("the scene files beside one: its folder's and the folders' next to it, sorted") {
    // A generated model: every model of its folder and every feature file
    // of the folder next to it (tests/data/gltf-models, gltf-features), and nothing else.
    const std::filesystem::path data = std::filesystem::path(FRUSTUM_SOURCE_DIR) / "tests/data";
    std::vector<std::string> expected;
    for (const char* folder : {"gltf-features", "gltf-models"}) {
        for (const auto& file : test_samples::gltf_files_under(data / folder)) expected.push_back(file.string());
    }
    std::sort(expected.begin(), expected.end());
    REQUIRE(expected.size() == 9 + 19);
    CHECK(demo::scene_files_beside(test_samples::model_path("box.gltf")) == expected);
    // The showcase: itself among them (its folder's only scene file).
    const std::string showcase = std::string(FRUSTUM_SOURCE_DIR) + "/assets/showcase.gltf";
    const std::vector<std::string> near_showcase = demo::scene_files_beside(showcase);
    CHECK(std::find(near_showcase.begin(), near_showcase.end(), showcase) != near_showcase.end());
    for (const std::string& file : near_showcase) {
        const std::string extension = std::filesystem::path(file).extension().string();
        CHECK((extension == ".gltf" || extension == ".glb"));
    }
    // A folder that does not exist: nothing, no error.
    CHECK(demo::scene_files_beside("/nonexistent/folder/x.gltf").empty());
}

TEST_CASE("live numbers: the camera pair's residual, the mirror's rectangle, a timed pass per planned pair") {
    const scene::Scene& scene = render_test::showcase();
    window::ViewerState state;
    state.effect = plan::Effect::Mirror;
    const plan::Cameras cameras = render_test::showcase_cameras();
    const auto mirror = window::make_frame(state, cameras, {}, scene.world_bounds, 256, 144);
    REQUIRE_MESSAGE(mirror.ok(), mirror.error());
    const window::LiveNumbers numbers = window::live_numbers(*mirror, scene);
    CHECK(numbers.pair.matrix() == cameras.main.pair.matrix());
    CHECK(numbers.residual == doctest::Approx(window::inverse_residual(cameras.main.pair)).epsilon(kFloatTwoUlps));
    CHECK(numbers.residual < 1e-4); // single precision: a few ulps of entries up to ~10 (measured 1.0e-5)
    CHECK(numbers.residual > 0.0);  // ... which is not exact
    const auto rect = plan::mirror_screen_rect(*scene.mirror, cameras.main.pair, 256, 144);
    REQUIRE(rect);
    REQUIRE(numbers.mirror_rect);
    CHECK(numbers.mirror_rect->width == rect->width);
    CHECK(numbers.mirror_rect->y == rect->y);
    REQUIRE(numbers.passes.size() == 1);
    CHECK(numbers.passes[0].result.find("px texture") != std::string::npos);
    CHECK(numbers.passes[0].cpu_us >= 0.0);
    // Planes and key points of the pair, in the forms the panel prints:
    // the side planes pass through the eye, the near corners lie on the near
    // plane and the far ones on the far plane, every corner inside or on the
    // other planes, all finite points with w = 1.
    REQUIRE(numbers.planes.far);
    const auto distance = [](const frustum::Plane<float>& plane, const glm::vec4& point) {
        return glm::dot(plane.abcd, point);
    };
    REQUIRE(numbers.points.eye.w == 1.0f);
    const float scale = glm::length(glm::vec3(numbers.points.corners[7])); // far corner distance: error scale
    for (const frustum::Plane<float>& side :
         {numbers.planes.left, numbers.planes.right, numbers.planes.bottom, numbers.planes.top}) {
        CHECK(std::abs(distance(side, numbers.points.eye)) < 1e-4f * scale);
    }
    for (std::size_t i = 0; i < 8; ++i) {
        const glm::vec4& corner = numbers.points.corners[i];
        REQUIRE(corner.w == 1.0f);
        const frustum::Plane<float>& own = i < 4 ? numbers.planes.near : *numbers.planes.far;
        CHECK(std::abs(distance(own, corner)) < 1e-4f * scale);
        for (const auto& plane : numbers.planes.as_array()) {
            CHECK(distance(*plane, corner) > -1e-4f * scale);
        }
    }

    state.effect = plan::Effect::Recursion;
    const auto recursion = window::make_frame(state, cameras, {}, scene.world_bounds, 256, 144);
    REQUIRE_MESSAGE(recursion.ok(), recursion.error());
    const window::LiveNumbers deeper = window::live_numbers(*recursion, scene);
    REQUIRE(deeper.passes.size() == 1); // the scene's mirror is not drawn by the recursion effect
    CHECK(deeper.passes[0].pass == "recursion views (depth 4)");
    CHECK(deeper.passes[0].result.find(" views") != std::string::npos);
}

} // TEST_SUITE
