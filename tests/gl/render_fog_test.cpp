// Depth that decodes (fog_pass.hpp): the main view fogged from its depth
// buffer against distances computed on the CPU; the mirror's reflection,
// fogged in its own pass from its own depth buffer, against a direct fogged
// render of the mirrored scene; and the same pass decoding the reflection's
// depth with the reflected pair before its oblique near plane (what engines do).
#include "render_test_support.hpp"

#include <frustum/projection.hpp>
#include <frustum/queries.hpp>
#include <frustum/rigid.hpp>
#include <image/contact_sheet.hpp>
#include <render/fog_pass.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

// The reference: the mirrored geometry from the real camera, fogged by the
// distance of each virtual point from the real eye (= the length of the
// reflected ray), decoded with the camera's own pair.
image::Image fogged_mirrored_geometry(const render_test::RenderEnvironment& r, const plan::Cameras& cameras,
                                      render::DepthPath path, const render::FogParams& fog) {
    const render::DepthPolicy depth = render_test::apply_depth_policy(r, path);
    const gl::OffscreenTarget target = render_test::draw_mirrored_geometry(r, cameras, depth);
    auto pass = render::FogPass::build(r.env->fn);
    REQUIRE_MESSAGE(pass.ok(), pass.error());
    const render::PassContext ctx = r.renderer->pass_context(depth, render::Lighting{});
    const auto status = pass->apply(ctx, target, cameras.main.pair, fog);
    REQUIRE_MESSAGE(status.ok(), status.error());
    auto picture = target.read_rgba8();
    REQUIRE_MESSAGE(picture.ok(), picture.error());
    return std::move(*picture);
}

// The main view's reference: a floor quad (y = 0, 400 m wide, unlit dark
// red) seen from 2 m above it, looking 30 degrees down, so that every pixel
// is floor and its distance is known on the CPU without reading depth back.
constexpr int kFloorW = 96, kFloorH = 64;
constexpr float kFloorDensityPerM = 0.12f;

scene::Scene floor_scene() {
    scene::Scene s;
    scene::Material material;
    material.base_color_factor = {0.5f, 0.08f, 0.05f, 1.0f};
    material.unlit = true;
    material.double_sided = true;
    s.materials.push_back(material);
    scene::Primitive quad;
    quad.positions = {{-200.0f, 0.0f, -200.0f}, {200.0f, 0.0f, -200.0f}, {-200.0f, 0.0f, 200.0f},
                      {200.0f, 0.0f, 200.0f}};
    quad.indices = {0, 2, 1, 1, 2, 3};
    quad.material = 0;
    s.meshes.push_back(scene::Mesh{"floor", {quad}});
    s.instances.push_back(scene::Instance{});
    s.world_bounds = {{-200.0f, 0.0f, -200.0f}, {200.0f, 0.0f, 200.0f}};
    return s;
}

frustum::MatrixPair<float> floor_camera() {
    auto projection = frustum::perspective<float>(glm::radians(45.0f), float(kFloorW) / float(kFloorH), 0.1f, 100.0f,
                                                  frustum::DepthRange::ZeroToOne);
    REQUIRE(projection.ok());
    const glm::vec3 eye_m{0.3f, 2.0f, 1.0f};
    const glm::mat3 camera_to_world = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(-30.0f), {1.0f, 0.0f, 0.0f}));
    const glm::mat3 world_to_camera = glm::transpose(camera_to_world);
    const auto view =
        frustum::RigidTransform<float>::from_rotation_translation(world_to_camera, -(world_to_camera * eye_m));
    return frustum::compose(*projection, view);
}

// Distance from the eye to the floor along pixel (i, j)'s centre ray (row j
// from the top), from the pair's inverse on the CPU (double).
double floor_distance_m(const frustum::MatrixPair<float>& pair, const glm::vec3& eye_m, int i, int j) {
    const glm::dvec4 ndc{(i + 0.5) / kFloorW * 2.0 - 1.0, (kFloorH - j - 0.5) / kFloorH * 2.0 - 1.0, 0.5, 1.0};
    const glm::dvec4 q = glm::dmat4(pair.inverse()) * ndc;
    const glm::dvec3 through = glm::dvec3(q) / q.w;
    const glm::dvec3 eye{eye_m};
    const glm::dvec3 direction = glm::normalize(through - eye);
    REQUIRE(direction.y < 0.0);
    return -eye.y / direction.y;
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("the main view's fog is the fog of the CPU's distance along each pixel's ray") {
    const scene::Scene s = floor_scene();
    auto r = render_test::make_any_renderer(s);
    if (!r) {
        return;
    }
    auto cameras = plan::make_cameras(s, -1, kFloorW, kFloorH);
    REQUIRE_MESSAGE(cameras.ok(), cameras.error());
    cameras->main.pair = floor_camera();
    const auto eye = frustum::eye_point(cameras->main.pair);
    REQUIRE(eye.has_value());
    for (auto path : {render::DepthPath::ClipControlWhenAvailable, render::DepthPath::MinusOneToOne}) {
        INFO("GPU depth range " << frustum::to_string(r->renderer->gpu_depth_range(path)));
        auto o = render_test::options(kFloorW, kFloorH);
        o.depth = path;
        const image::Image plain = r->render(plan::Effect::Plain, *cameras, o);
        plan::FogOptions fog_options;
        fog_options.density_per_m = kFloorDensityPerM;
        fog_options.start_m = 0.5f;
        o.fog = fog_options;
        const image::Image fogged = r->render(plan::Effect::Plain, *cameras, o);
        const render::FogParams fog = render::fit_fog(fog_options, s.world_bounds, render::kClearColor);

        // Expected: the plain pixel blended towards the fog colour by
        // f = 1 - exp(-density max(d - start, 0)) (shaders/fog.frag), d from
        // the CPU. The GPU decodes d from 24-bit depth: at 15 m (the top
        // rows) one depth step is ~1 cm, f moves by < 0.1%; blending rounds
        // to 8 bits. Tolerance 1 LSB. Measured (llvmpipe, both ranges): max 1,
        // mean 0.37 LSB.
        int over = 0, max_abs = 0;
        double sum_abs = 0.0, f_min = 1.0, f_max = 0.0;
        for (int j = 0; j < kFloorH; ++j) {
            for (int i = 0; i < kFloorW; ++i) {
                const double d = floor_distance_m(cameras->main.pair, *eye, i, j);
                const double f = 1.0 - std::exp(-double(fog.density_per_m) * std::max(d - double(fog.start_m), 0.0));
                f_min = std::min(f_min, f);
                f_max = std::max(f_max, f);
                const image::Rgba p = image::pixel_at(plain, i, j), q = image::pixel_at(fogged, i, j);
                for (int c = 0; c < 3; ++c) {
                    const double expected = p[c] * (1.0 - f) + 255.0 * double(fog.color[c]) * f;
                    const int diff = int(std::lround(std::abs(expected - q[c])));
                    max_abs = std::max(max_abs, diff);
                    sum_abs += std::abs(expected - q[c]);
                    over += diff > 1 ? 1 : 0;
                }
            }
        }
        const double mean = sum_abs / (3.0 * kFloorW * kFloorH);
        MESSAGE("main-view fog vs CPU distances: f in [" << f_min << ", " << f_max << "], max " << max_abs << " LSB, mean "
                                                         << mean << ", " << over << " channels over 1 LSB");
        CHECK(f_max - f_min > 0.5); // the fog varies across the frame: a constant would not pass
        CHECK(over == 0);
        CHECK(mean < 0.6);
        if (over > 0) {
            render_test::save_failure("fog-main-view", fogged, plain);
        }
    }
}


TEST_CASE("the fogged reflection is the fogged mirrored scene; decoded without the oblique plane it is not") {
    RENDER_TEST_ANY_RENDERER(r);
    const auto cameras = render_test::showcase_cameras();
    const auto mask = render_test::mirror_mask(*r, cameras, render_test::options());
    REQUIRE(render_test::count(mask) > 500);
    const render::FogParams fog =
        render::fit_fog(plan::FogOptions{}, render_test::showcase().world_bounds, render::kClearColor);
    for (auto path : {render::DepthPath::ClipControlWhenAvailable, render::DepthPath::MinusOneToOne}) {
        const auto range = r->renderer->gpu_depth_range(path);
        INFO("GPU depth range " << frustum::to_string(range));
        auto o = render_test::options();
        o.depth = path;
        const image::Image plain_mirror = r->render(plan::Effect::Mirror, cameras, o);
        o.fog = plan::FogOptions{};
        const image::Image fogged = r->render(plan::Effect::Mirror, cameras, o);
        o.fog->decode_reflection_unclipped = true;
        const image::Image unclipped = r->render(plan::Effect::Mirror, cameras, o);
        const image::Image reference = fogged_mirrored_geometry(*r, cameras, path, fog);

        // The fog is there: the fogged mirror is far from the unfogged one
        // (measured: mean 11.9 LSB).
        const auto visible = render_test::compare_masked(fogged, plain_mirror, mask, 2);
        MESSAGE("fog vs no fog in the mirror: mean " << visible.mean_abs << " LSB");
        CHECK(visible.mean_abs > 8.0);

        // Same pixel centres (texel (i, j) is screen pixel (x + i, y + j)),
        // depth decoded from the same 24 bits along different depth axes:
        // the fog differs by the decoded distance's rounding. Measured: 0
        // over 2 LSB, max 1, mean 0.0006 LSB in both ranges. Tolerance 2 LSB,
        // at most 2 pixels beyond it (as in render_mirror_test.cpp).
        const auto good = render_test::compare_masked(fogged, reference, mask, 2);
        MESSAGE("fogged reflection vs fogged mirrored scene: " << good.compared << " pixels, " << good.pixels_over
                                                               << " over 2 LSB, max " << good.max_abs << ", mean "
                                                               << good.mean_abs);
        CHECK(good.pixels_over <= 2);
        CHECK(good.mean_abs < 0.5);

        // Decoded with the un-clipped reflected pair, the depth means other
        // points. Measured (llvmpipe, both ranges): 643 of 1645 mirror pixels
        // over 2 LSB, max 75, mean 11.7 LSB; pinned to mean 8..16 and 25..60%
        // of the pixels over 2 LSB.
        const auto bad = render_test::compare_masked(unclipped, reference, mask, 2);
        MESSAGE("decoded with the un-clipped pair vs fogged mirrored scene: " << bad.pixels_over << " of "
                                                                              << bad.compared << " over 2 LSB, max "
                                                                              << bad.max_abs << ", mean "
                                                                              << bad.mean_abs);
        CHECK(bad.mean_abs > 8.0);
        CHECK(bad.mean_abs < 16.0);
        CHECK(bad.pixels_over > bad.compared / 4);
        CHECK(bad.pixels_over < bad.compared * 6 / 10);

        if (path == render::DepthPath::ClipControlWhenAvailable) {
            auto sheet = image::contact_sheet({{"oblique", &fogged}, {"unclipped", &unclipped}}, 2);
            REQUIRE_MESSAGE(sheet.ok(), sheet.error());
            const auto written = image::write_png(*sheet, (render_test::output_dir() / "fog-reflection.png").string());
            CHECK_MESSAGE(written.ok(), written.error());
        }
        if (good.pixels_over > 2) {
            render_test::save_failure("fog-vs-fogged-mirrored-geometry", fogged, reference);
        }
    }
}

} // TEST_SUITE
