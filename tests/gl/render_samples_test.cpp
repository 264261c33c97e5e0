// Every glTF sample loads and renders something with its default camera.
#include "render_test_support.hpp"

#include <filesystem>

TEST_SUITE("gl") {

TEST_CASE("every glTF sample renders a non-empty image") {
    const std::filesystem::path root(FRUSTUM_SAMPLES_DIR);
    if (!std::filesystem::is_directory(root)) {
        MESSAGE("skipping: no samples folder " << root.string());
        return;
    }
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        const auto extension = entry.path().extension();
        if (entry.is_regular_file() && (extension == ".gltf" || extension == ".glb")) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    REQUIRE(!files.empty());

    auto env = gl_test::make_environment(gl::Backend::Egl);
    if (!env) {
        env = gl_test::make_environment(gl::Backend::OsMesa);
    }
    if (!env) {
        return;
    }
    constexpr int kSizePx = 128;
    for (const auto& file : files) {
        INFO(file.string());
        const auto scene = scene::load_gltf(file.string());
        REQUIRE_MESSAGE(scene.ok(), scene.error());
        const auto index = render::find_camera(*scene, std::nullopt);
        REQUIRE_MESSAGE(index.ok(), index.error());
        const auto cameras = render::make_cameras(*scene, *index, kSizePx, kSizePx);
        REQUIRE_MESSAGE(cameras.ok(), cameras.error());
        auto renderer = render::Renderer::create(*env->context, env->fn, *scene);
        REQUIRE_MESSAGE(renderer.ok(), renderer.error());
        const auto picture = renderer->render(render::Effect::Plain, *cameras, render_test::options(kSizePx, kSizePx));
        REQUIRE_MESSAGE(picture.ok(), picture.error());
        // Pixels more than 2 LSB away from the clear colour (the sky).
        const glm::vec4 clear = render::kClearColor;
        const image::Image sky = image::make_image(
            kSizePx, kSizePx,
            {static_cast<std::uint8_t>(clear.r * 255.0f + 0.5f), static_cast<std::uint8_t>(clear.g * 255.0f + 0.5f),
             static_cast<std::uint8_t>(clear.b * 255.0f + 0.5f), 255});
        const auto diff = image::compare(*picture, sky, 2);
        REQUIRE(diff.ok());
        MESSAGE(file.filename().string() << ": " << diff->pixels_over << " of " << kSizePx * kSizePx
                                         << " pixels are not sky");
        CHECK(diff->pixels_over > 0);
        if (diff->pixels_over == 0) {
            render_test::save_failure("sample-" + file.stem().string(), *picture, sky);
        }
    }
}

} // TEST_SUITE
