// README: BLEND primitives are drawn after the opaque ones, from back to
// front. Three overlapping half-transparent quads, listed front, back,
// middle (so that drawing them in file order, or front to back, gives
// another picture): where all three overlap, each channel is the weight of
// its quad, front 1/2, middle 1/4, back 1/8 (plus 1/8 of the sky), so the
// front quad's channel is the largest and the back one's the smallest,
// whatever the framebuffer's encoding.
#include "render_test_support.hpp"

#include <frustum/projection.hpp>
#include <frustum/rigid.hpp>

#include <cmath>

namespace {

constexpr int kSidePx = 64;

// An unlit square of half size `half_m` facing +z at depth z, colour `rgb` with alpha 1/2.
void add_glass_quad(scene::Scene& s, float z, float half_m, const glm::vec3& rgb) {
    scene::Material material;
    material.base_color_factor = glm::vec4(rgb, 0.5f);
    material.alpha_mode = scene::AlphaMode::Blend;
    material.unlit = true;
    s.materials.push_back(material);
    scene::Primitive quad;
    quad.positions = {{-half_m, -half_m, z}, {half_m, -half_m, z}, {half_m, half_m, z}, {-half_m, half_m, z}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.material = static_cast<int>(s.materials.size()) - 1;
    s.meshes.push_back(scene::Mesh{"glass", {quad}});
    scene::Instance instance;
    instance.mesh = static_cast<int>(s.meshes.size()) - 1;
    s.instances.push_back(instance);
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("BLEND primitives are drawn from back to front: three glass quads, the front one's colour dominates") {
    scene::Scene s;
    add_glass_quad(s, 0.5f, 0.4f, {0.0f, 1.0f, 0.0f});  // front: green
    add_glass_quad(s, -0.5f, 0.8f, {1.0f, 0.0f, 0.0f}); // back: red
    add_glass_quad(s, 0.0f, 0.6f, {0.0f, 0.0f, 1.0f});  // middle: blue
    s.world_bounds = {{-0.8f, -0.8f, -0.5f}, {0.8f, 0.8f, 0.5f}};
    auto r = render_test::make_any_renderer(s);
    if (!r) {
        return;
    }
    auto cameras = plan::make_cameras(s, -1, kSidePx, kSidePx);
    REQUIRE_MESSAGE(cameras.ok(), cameras.error());
    // From (0, 0, 3) down -z, 45 degrees: the quads fill the middle of the frame.
    auto projection = frustum::perspective<float>(glm::radians(45.0f), 1.0f, 0.1f, 20.0f, frustum::DepthRange::ZeroToOne);
    REQUIRE(projection.ok());
    cameras->main.pair = frustum::compose(
        *projection, frustum::RigidTransform<float>::from_rotation_translation(glm::mat3(1.0f), glm::vec3(0, 0, -3)));
    const image::Image picture = r->render(plan::Effect::Plain, *cameras, render_test::options(kSidePx, kSidePx));
    // The centre (all three quads), and a pixel on the back quad alone: the
    // quads' right edges are 12.4 (front), 15.5 (middle) and 17.7 px (back)
    // right of the centre (half size / depth / tan 22.5 deg x 32 px).
    const image::Rgba centre = image::pixel_at(picture, kSidePx / 2, kSidePx / 2);
    const image::Rgba back_only = image::pixel_at(picture, kSidePx / 2 + 16, kSidePx / 2);
    CAPTURE(int{centre[0]});
    CAPTURE(int{centre[1]});
    CAPTURE(int{centre[2]});
    CAPTURE(int{back_only[0]});
    // Each quad shows (drawn front to back with depth writes, the ones behind would vanish).
    CHECK(int{centre[1]} > int{centre[2]} + 20); // front (green) over middle (blue)
    CHECK(int{centre[2]} > int{centre[0]} + 10); // middle (blue) over back (red)
    // As numbers (the blend unit works on the stored 8-bit values): front
    // 1/2, middle 1/4, back 1/8 of their channel plus 1/8 of the sky's.
    // Measured (51, 151, 91); 2 LSB for the blend unit's rounding.
    const glm::vec3 weights(1.0f / 8, 1.0f / 2, 1.0f / 4); // r: back, g: front, b: middle
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        const float expected = 255.0f * (weights[c] + render::kClearColor[c] / 8.0f);
        CHECK(std::abs(float(centre[static_cast<std::size_t>(c)]) - expected) <= 2.0f);
    }
    // The back quad alone is red over the sky: red dominates there.
    CHECK(int{back_only[0]} > int{back_only[1]});
    CHECK(int{back_only[0]} > int{back_only[2]});
    if (!(centre[1] > centre[2] + 20 && centre[2] > centre[0] + 10)) {
        render_test::save_failure("blend-order", picture, picture);
    }
}

} // TEST_SUITE
