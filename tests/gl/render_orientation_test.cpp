// The texture's orientation through the whole path (decode, upload, uv,
// sampling): the feature file orientation.gltf (scripts/make_feature_gltf.py)
// shows its 4 x 4 quadrant texture on a square facing its orthographic
// camera, and the generated textured cube (tests/data/gltf-models) shows it
// on the face turned to a camera in front of it. Red must be top left,
// green top right, blue bottom left, white bottom right: a flip of v puts
// blue on top, a flip of u green on the left, and both fail here.
#include "../sample_files.hpp"
#include "render_test_support.hpp"

#include <frustum/frustum.hpp>

#include <cmath>
#include <optional>

namespace {

constexpr int kSidePx = 64;

enum class Colour { Red, Green, Blue, White, Other };

// Which of the four texel colours a pixel shows (lit or not: by its channels' order).
Colour colour_of(const image::Rgba& p) {
    const int r = p[0], g = p[1], b = p[2];
    if (r > 150 && g > 150 && b > 150) return Colour::White;
    if (r > 2 * g + 40 && r > 2 * b + 40) return Colour::Red;
    if (g > 2 * r + 40 && g > 2 * b + 40) return Colour::Green;
    if (b > 2 * r + 40 && b > 2 * g + 40) return Colour::Blue;
    return Colour::Other;
}

const char* name(Colour c) {
    switch (c) {
    case Colour::Red: return "red";
    case Colour::Green: return "green";
    case Colour::Blue: return "blue";
    case Colour::White: return "white";
    case Colour::Other: return "other";
    }
    return "?";
}

// The colours at the four quarter points of the picture (x, y from the top left).
void check_quadrants(const image::Image& picture, int x0, int y0, int x1, int y1) {
    const struct {
        int x, y;
        Colour expected;
    } points[] = {{x0, y0, Colour::Red}, {x1, y0, Colour::Green}, {x0, y1, Colour::Blue}, {x1, y1, Colour::White}};
    for (const auto& p : points) {
        const image::Rgba px = image::pixel_at(picture, p.x, p.y);
        INFO("pixel (" << p.x << ", " << p.y << ") = " << int(px[0]) << " " << int(px[1]) << " " << int(px[2]));
        CHECK(std::string(name(colour_of(px))) == std::string(name(p.expected)));
    }
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("texture orientation: red top left on the feature square and on the cube's front face") {
    auto env = gl_test::make_any_environment();
    if (!env) {
        return;
    }
    {
        auto s = scene::load_gltf(std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-features/orientation.gltf");
        REQUIRE_MESSAGE(s.ok(), s.error());
        const auto index = plan::find_camera(*s, std::nullopt);
        REQUIRE(index.ok());
        const auto cameras = plan::make_cameras(*s, *index, kSidePx, kSidePx);
        REQUIRE(cameras.ok());
        auto renderer = render::Renderer::create(*env->context, env->fn, *s);
        REQUIRE_MESSAGE(renderer.ok(), renderer.error());
        const auto picture = renderer->render(plan::Effect::Plain, *cameras, render_test::options(kSidePx, kSidePx));
        REQUIRE_MESSAGE(picture.ok(), picture.error());
        // The square spans world [-0.8, 0.8]: its quadrants' centres at +-0.4 (pixels 19 and 44).
        check_quadrants(*picture, 19, 19, 44, 44);
        if (colour_of(image::pixel_at(*picture, 19, 19)) != Colour::Red) {
            render_test::save_failure("orientation-square", *picture, *picture);
        }
    }
    {
        auto s = scene::load_gltf(test_samples::model_path("box_textured.gltf"));
        REQUIRE_MESSAGE(s.ok(), s.error());
        // A camera 3 m in front of the +Z face, looking at its centre; the
        // face (1 m) fills the middle of a 30 degree view.
        const float fovy_rad = glm::radians(30.0f);
        const auto projection =
            frustum::perspective<float>(fovy_rad, 1.0f, 0.1f, std::optional<float>(10.0f), frustum::DepthRange::ZeroToOne);
        REQUIRE_MESSAGE(projection.ok(), projection.error());
        const auto view = frustum::look_at<float>(glm::vec3(0, 0, 3.5f), glm::vec3(0), glm::vec3(0, 1, 0));
        REQUIRE_MESSAGE(view.ok(), view.error());
        const frustum::MatrixPair<float> pair = frustum::compose(*projection, *view);
        plan::Cameras cameras{{"front", pair}, {"overview", pair}, std::nullopt, std::nullopt, std::nullopt};
        auto renderer = render::Renderer::create(*env->context, env->fn, *s);
        REQUIRE_MESSAGE(renderer.ok(), renderer.error());
        const auto picture = renderer->render(plan::Effect::Plain, cameras, render_test::options(kSidePx, kSidePx));
        REQUIRE_MESSAGE(picture.ok(), picture.error());
        // The face at z = 0.5 spans +-0.5 m at 3 m: tan(15 deg) * 3 = 0.80 m of
        // half view, so +-0.25 m (its quadrants' centres) is +-0.31 of the half image.
        const int lo = int(kSidePx * (0.5f - 0.5f * 0.25f / (3.0f * std::tan(fovy_rad / 2))));
        const int hi = kSidePx - 1 - lo;
        check_quadrants(*picture, lo, lo, hi, hi);
        if (colour_of(image::pixel_at(*picture, lo, lo)) != Colour::Red) {
            render_test::save_failure("orientation-cube", *picture, *picture);
        }
    }
}

} // TEST_SUITE
