// README: morph targets apply to NORMAL too, so the lighting follows the
// weight. tests/data/gltf-models/morph.gltf (scripts/gltf_models.py): a
// square facing +z (normals (0, 0, 1)) with a NORMAL target of (1, 0, 0);
// with the light along +x the base normal gets no diffuse light and the
// morphed normal (w, 0, 1) / |(w, 0, 1)| gets n . l = w / sqrt(1 + w^2).
// Rendered at weights 0, 0.5 and 1 (the file's mesh.weights rewritten in a
// temporary copy), the square's colour is the Lambert formula of that normal.
#include "render_test_support.hpp"

#include "support/temp_dir.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iterator>

namespace {

constexpr int kSidePx = 64;
const glm::vec3 kBaseColor(0.9f, 0.5f, 0.3f); // the file's baseColorFactor (linear)

std::uint8_t srgb_byte(float linear) {
    const float c = linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(std::min(c, 1.0f) * 255.0f));
}

// morph.gltf with the NORMAL target's weight set to `normal_weight`, written into `dir`.
std::string with_normal_weight(const support::TempDir& dir, double normal_weight) {
    std::ifstream in(std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-models/morph.gltf");
    REQUIRE(in.good());
    nlohmann::json gltf = nlohmann::json::parse(std::string(std::istreambuf_iterator<char>(in), {}));
    REQUIRE(gltf["meshes"][0]["weights"].size() == 2); // POSITION target, NORMAL target
    gltf["meshes"][0]["weights"][1] = normal_weight;
    const std::string path = (dir.path() / ("morph-" + std::to_string(normal_weight) + ".gltf")).string();
    std::ofstream(path) << gltf.dump();
    return path;
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("morph targets on NORMAL: the lighting follows the weight (Lambert of the morphed normal)") {
    support::TempDir dir;
    auto o = render_test::options(kSidePx, kSidePx);
    o.lighting.to_light = glm::vec3(1.0f, 0.0f, 0.0f);
    o.lighting.ambient = 0.2f;
    o.lighting.diffuse = 0.8f;
    int previous_red = -1;
    for (const double w : {0.0, 0.5, 1.0}) {
        CAPTURE(w);
        auto loaded = scene::load_gltf(with_normal_weight(dir, w));
        REQUIRE_MESSAGE(loaded.ok(), loaded.error());
        auto r = render_test::make_any_renderer(*loaded);
        if (!r) {
            return;
        }
        const auto index = plan::find_camera(*loaded, std::nullopt);
        REQUIRE_MESSAGE(index.ok(), index.error());
        auto cameras = plan::make_cameras(*loaded, *index, kSidePx, kSidePx);
        REQUIRE_MESSAGE(cameras.ok(), cameras.error());
        const image::Image picture = r->render(plan::Effect::Plain, *cameras, o);
        const image::Rgba centre = image::pixel_at(picture, kSidePx / 2, kSidePx / 2);
        const float n_dot_l = static_cast<float>(w / std::sqrt(1.0 + w * w));
        const float factor = o.lighting.ambient + o.lighting.diffuse * n_dot_l;
        for (int c = 0; c < 3; ++c) {
            CAPTURE(c);
            CAPTURE(int{centre[static_cast<std::size_t>(c)]});
            // 2 LSB: the shader's float normalize and sRGB encoding against these.
            CHECK(std::abs(int{centre[static_cast<std::size_t>(c)]} - int{srgb_byte(kBaseColor[c] * factor)}) <= 2);
        }
        CHECK(int{centre[0]} > previous_red + 20); // brighter with each step of the weight
        previous_red = centre[0];
    }
}

} // TEST_SUITE
