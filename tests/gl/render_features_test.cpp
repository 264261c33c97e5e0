// Pictures of the glTF features (tests/data/gltf-features, made by
// scripts/make_feature_gltf.py; the loading side is tests/scene/features_test.cpp):
// unlit ignores the lighting, texCoord 1 and KHR_texture_transform pick and
// move the texture, instancing draws N copies, morph weights move vertices,
// BLEND shows what lies behind, MASK cuts, an orthographic camera keeps its
// aspect, and the showcase's lens disc is glass in every effect.
// Every file has a square orthographic camera seeing world x, y in [-1, 1].
#include "render_test_support.hpp"

#include <frustum/frustum.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

constexpr int kSidePx = 64;

scene::Scene load_feature(const std::string& name) {
    auto loaded = scene::load_gltf(std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-features/" + name);
    REQUIRE_MESSAGE(loaded.ok(), loaded.error());
    return std::move(*loaded);
}

plan::Cameras cameras_of(const scene::Scene& s, int width_px, int height_px) {
    const auto index = plan::find_camera(s, std::nullopt);
    REQUIRE_MESSAGE(index.ok(), index.error());
    auto cameras = plan::make_cameras(s, *index, width_px, height_px);
    REQUIRE_MESSAGE(cameras.ok(), cameras.error());
    return std::move(*cameras);
}

struct Picture {
    image::Image image;
    // The pixel showing world (x, y) of the square view.
    image::Rgba at(float x, float y) const {
        const int px = static_cast<int>((x + 1.0f) * 0.5f * static_cast<float>(image.width));
        const int py = static_cast<int>((1.0f - y) * 0.5f * static_cast<float>(image.height));
        return image::pixel_at(image, px, py);
    }
};

Picture render_feature(const std::string& name, render::RenderOptions o = render_test::options(kSidePx, kSidePx)) {
    const scene::Scene s = load_feature(name);
    auto r = render_test::make_any_renderer(s);
    REQUIRE(r);
    return {r->render(plan::Effect::Plain, cameras_of(s, o.width_px, o.height_px), o)};
}

std::uint8_t srgb_byte(float linear) {
    const float c = linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(c * 255.0f));
}

image::Rgba sky() {
    return {static_cast<std::uint8_t>(std::lround(render::kClearColor.r * 255.0f)),
            static_cast<std::uint8_t>(std::lround(render::kClearColor.g * 255.0f)),
            static_cast<std::uint8_t>(std::lround(render::kClearColor.b * 255.0f)), 255};
}

// a over b with alpha (8-bit, as the blend unit on RGBA8 values).
image::Rgba over(const image::Rgba& a, float alpha, const image::Rgba& b) {
    image::Rgba out{0, 0, 0, 255};
    for (std::size_t c = 0; c < 3; ++c) {
        out[c] = static_cast<std::uint8_t>(std::lround(alpha * a[c] + (1.0f - alpha) * b[c]));
    }
    return out;
}

#define CHECK_NEAR_RGBA(actual, expected, tolerance)                                                              \
    do {                                                                                                          \
        const image::Rgba a_ = (actual), e_ = (expected);                                                         \
        CAPTURE(int{a_[0]}); CAPTURE(int{a_[1]}); CAPTURE(int{a_[2]});                                          \
        CAPTURE(int{e_[0]}); CAPTURE(int{e_[1]}); CAPTURE(int{e_[2]});                                          \
        CHECK(gl_test::near(a_, e_, tolerance));                                                                  \
    } while (false)

} // namespace

TEST_SUITE("gl") {

TEST_CASE("KHR_materials_unlit: the base colour as is, whatever the light") {
    const image::Rgba expected{srgb_byte(0.8f), srgb_byte(0.2f), srgb_byte(0.2f), 255};
    const Picture lit = render_feature("unlit.gltf");
    CHECK_NEAR_RGBA(lit.at(0.5f, 0.0f), expected, 1);
    CHECK(int{lit.at(-0.5f, 0.0f)[0]} < int{expected[0]} - 20); // the lit twin: shaded darker
    auto o = render_test::options(kSidePx, kSidePx);
    o.lighting.ambient = 0.0f;
    o.lighting.diffuse = 0.0f;
    const Picture dark = render_feature("unlit.gltf", o);
    CHECK_NEAR_RGBA(dark.at(0.5f, 0.0f), expected, 1);
    CHECK_NEAR_RGBA(dark.at(-0.5f, 0.0f), (image::Rgba{0, 0, 0, 255}), 1);
}

TEST_CASE("texCoord 1 selects TEXCOORD_1; KHR_texture_transform's offset moves the texture") {
    // The texture: red texel left (u = 0.25), green right (u = 0.75); the quad spans x in [-0.8, 0.8].
    const auto is_red = [](const image::Rgba& p) { return p[0] > 200 && p[1] < 60 && p[2] < 60; };
    const auto is_green = [](const image::Rgba& p) { return p[1] > 200 && p[0] < 60 && p[2] < 60; };
    const Picture plain = render_feature("texcoord1.gltf");
    CHECK(is_red(plain.at(-0.4f, 0.0f)));
    CHECK(is_green(plain.at(0.4f, 0.0f)));
    const Picture moved = render_feature("texture_transform.gltf"); // offset (0.5, 0): swapped
    CHECK(is_green(moved.at(-0.4f, 0.0f)));
    CHECK(is_red(moved.at(0.4f, 0.0f)));
}

TEST_CASE("EXT_mesh_gpu_instancing draws one copy per instance") {
    const Picture p = render_feature("instancing.gltf");
    const image::Rgba background = sky();
    int runs = 0;
    bool inside = false;
    const int row = kSidePx / 2;
    for (int x = 0; x < kSidePx; ++x) {
        const bool drawn = !gl_test::near(image::pixel_at(p.image, x, row), background, 2);
        runs += drawn && !inside ? 1 : 0;
        inside = drawn;
    }
    CHECK(runs == 3);
    // The middle copy is scaled 2x in y: it reaches y = 0.25, the others do not.
    CHECK_FALSE(gl_test::near(p.at(0.0f, 0.25f), background, 2));
    CHECK(gl_test::near(p.at(-0.6f, 0.25f), background, 2));
    CHECK(gl_test::near(p.at(0.6f, 0.25f), background, 2));
}

TEST_CASE("morph target weights move the vertices (mesh.weights, node.weights)") {
    const Picture p = render_feature("morph.gltf");
    const image::Rgba orange{srgb_byte(0.9f), srgb_byte(0.6f), srgb_byte(0.1f), 255};
    CHECK_NEAR_RGBA(p.at(0.5f, 0.5f), orange, 1); // weight 1: moved +0.5 m
    CHECK_NEAR_RGBA(p.at(0.0f, 0.5f), sky(), 1);
    CHECK_NEAR_RGBA(p.at(0.0f, -0.5f), orange, 1); // node weight 0: where the mesh put it
    CHECK_NEAR_RGBA(p.at(0.5f, -0.5f), sky(), 1);
}

TEST_CASE("alphaMode BLEND shows what lies behind (drawn after the opaque), MASK cuts below alphaCutoff") {
    const Picture p = render_feature("alpha.gltf");
    const image::Rgba white{255, 255, 255, 255};
    const image::Rgba red{srgb_byte(0.5f), 0, 0, 255};
    CHECK_NEAR_RGBA(p.at(-0.7f, 0.5f), over(white, 0.5f, sky()), 2); // glass over the sky
    CHECK_NEAR_RGBA(p.at(-0.25f, 0.5f), over(white, 0.5f, red), 2); // glass over the red drawn after it
    CHECK_NEAR_RGBA(p.at(0.5f, 0.5f), red, 1);
    CHECK_NEAR_RGBA(p.at(-0.5f, -0.5f), sky(), 1); // alpha < 0.5: cut away
    CHECK_NEAR_RGBA(p.at(0.5f, -0.5f), (image::Rgba{0, srgb_byte(0.5f), 0, 255}), 1);
    CHECK(p.image.rgba[3] == 255); // the image stays opaque

    // The tiles effect draws the same groups in the same order.
    const scene::Scene s = load_feature("alpha.gltf");
    auto r = render_test::make_any_renderer(s);
    REQUIRE(r);
    const auto o = render_test::options(kSidePx, kSidePx);
    const auto cameras = cameras_of(s, kSidePx, kSidePx);
    const auto diff = image::compare(r->render(plan::Effect::Plain, cameras, o),
                                     r->render(plan::Effect::Tiles, cameras, o), 2);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    CHECK(diff->pixels_over == 0);
}

TEST_CASE("an orthographic glTF camera keeps its aspect in a 16:9 image") {
    // ymag 1 fills the 90 px height with 2 m; the 1 m square is 45 px each way (not 80 wide).
    const Picture p = render_feature("orthographic.gltf", render_test::options(160, 90));
    int width_px = 0, height_px = 0;
    for (int x = 0; x < 160; ++x) {
        width_px += !gl_test::near(image::pixel_at(p.image, x, 45), sky(), 2);
    }
    for (int y = 0; y < 90; ++y) {
        height_px += !gl_test::near(image::pixel_at(p.image, 80, y), sky(), 2);
    }
    CHECK(height_px == doctest::Approx(45).epsilon(0.05));
    CHECK(width_px == height_px);
}

TEST_CASE("an orthographic camera: the effects built from an eye draw with its perspective twin") {
    const scene::Scene s = load_feature("orthographic.gltf");
    const auto cameras = cameras_of(s, 160, 90);
    REQUIRE(cameras.perspective_twin);
    REQUIRE(cameras.twin_note);
    CHECK_FALSE(frustum::eye_point(cameras.main.pair)); // the file's camera stays main
    CHECK(frustum::eye_point(cameras.perspective_twin->pair));
    for (plan::Effect effect : plan::kAllEffects) {
        INFO(plan::to_string(effect));
        const plan::Cameras used = plan::cameras_for(effect, cameras);
        CHECK(frustum::eye_point(used.main.pair).has_value() == plan::effect_needs_finite_eye(effect));
    }
    auto r = render_test::make_any_renderer(s);
    REQUIRE(r);
    const auto o = render_test::options(160, 90);
    // Rows of the square above the middle row, in column 80 (22.5 when 2 ymag fill 90 rows).
    const auto upper_half_px = [](const image::Image& image) {
        int rows = 0;
        for (int y = 44; y >= 0 && !gl_test::near(image::pixel_at(image, 80, y), sky(), 2); --y) {
            ++rows;
        }
        return rows;
    };
    CHECK(upper_half_px(r->render(plan::Effect::Plain, cameras, o)) == doctest::Approx(22.5).epsilon(0.1));
    for (plan::Effect effect : plan::kAllEffects) {
        if (!plan::effect_needs_finite_eye(effect)) {
            continue;
        }
        INFO(plan::to_string(effect));
        const image::Image picture = r->render(effect, cameras, o); // refused before the twin
        CHECK(picture.width == 160);
        if (effect == plan::Effect::NonAffine || effect == plan::Effect::Portal || effect == plan::Effect::Recursion) {
            // The twin shows the plane of the scene's centre, the square's, as the orthographic camera does.
            CHECK(upper_half_px(picture) == doctest::Approx(22.5).epsilon(0.15));
        }
    }
}

TEST_CASE("the showcase's lens disc is glass in every effect that draws it") {
    // Three versions of the showcase: the disc as it is (BLEND), made opaque,
    // and shrunk to nothing. Where the opaque disc shows, the glass one lies
    // between the opaque colour and what is behind the disc.
    const scene::Scene& glass = render_test::showcase();
    REQUIRE(glass.lens);
    const int disc = glass.lens->instance;
    REQUIRE(disc >= 0);
    scene::Scene opaque = glass;
    const int material = opaque.meshes[opaque.instances[disc].mesh].primitives.front().material;
    REQUIRE(material >= 0);
    REQUIRE(opaque.materials[material].alpha_mode == scene::AlphaMode::Blend);
    opaque.materials[material].alpha_mode = scene::AlphaMode::Opaque;
    scene::Scene hidden = glass;
    hidden.instances[disc].world = glm::scale(hidden.instances[disc].world, glm::vec3(0.0f));

    auto r_glass = render_test::make_any_renderer(glass);
    auto r_opaque = render_test::make_any_renderer(opaque);
    auto r_hidden = render_test::make_any_renderer(hidden);
    REQUIRE((r_glass && r_opaque && r_hidden));
    const auto cameras = render_test::showcase_cameras();
    const auto o = render_test::options();
    for (plan::Effect effect : {plan::Effect::Plain, plan::Effect::Mirror, plan::Effect::Tiles,
                                plan::Effect::Curved, plan::Effect::NonAffine}) {
        CAPTURE(plan::to_string(effect));
        const image::Image g = r_glass->render(effect, cameras, o);
        const image::Image a = r_opaque->render(effect, cameras, o);
        const image::Image b = r_hidden->render(effect, cameras, o);
        int disc_pixels = 0, between = 0;
        for (int y = 0; y < g.height; ++y) {
            for (int x = 0; x < g.width; ++x) {
                const image::Rgba pg = image::pixel_at(g, x, y), pa = image::pixel_at(a, x, y),
                                  pb = image::pixel_at(b, x, y);
                if (gl_test::near(pa, pb, 24)) {
                    continue; // the opaque disc hardly differs from behind: nothing to see
                }
                ++disc_pixels;
                bool inside = !gl_test::near(pg, pa, 8) && !gl_test::near(pg, pb, 8);
                for (std::size_t c = 0; c < 3; ++c) {
                    inside = inside && pg[c] + 2 >= std::min(pa[c], pb[c]) && pg[c] <= std::max(pa[c], pb[c]) + 2;
                }
                between += inside ? 1 : 0;
            }
        }
        MESSAGE(plan::to_string(effect) << ": " << between << " of " << disc_pixels << " disc pixels are glass");
        CHECK(disc_pixels > 50); // measured: 1368 plain, 78 nonaffine (the slits squeeze it)
        CHECK(between >= disc_pixels * 9 / 10);
    }
}

} // TEST_SUITE
