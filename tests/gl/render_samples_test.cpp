// The external samples corpus (FRUSTUM_TEST_DATA/gltf-samples, not part of
// the repository; CTest corpus-samples-render, a skip when it is not set):
// every sample x every effect x EGL and OSMesa, as the generated models are
// checked (any_scene_check.hpp).
#include "../sample_files.hpp"
#include "any_scene_check.hpp"

TEST_SUITE("corpus-samples") {

TEST_CASE("every effect on every glTF sample, both backends: non-flat, the mirror only where it is") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) {
        return;
    }
    const auto files = test_samples::gltf_files_under(*samples);
    REQUIRE(files.size() == 18);
    any_scene::check_every_effect(files);
}

} // TEST_SUITE
