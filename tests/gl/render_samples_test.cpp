// The external samples corpus (FRUSTUM_TEST_DATA/gltf-samples, not part of
// the repository; CTest corpus-samples-render, a skip when it is not set):
// every sample x every effect x EGL and OSMesa, as the generated models are
// checked (any_scene_check.hpp), and every effect visible on each
// (every_effect_check.hpp, as render_every_effect_visible_test.cpp).
#include "../sample_files.hpp"
#include "any_scene_check.hpp"
#include "every_effect_check.hpp"

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

TEST_CASE("every effect visible on every glTF sample: mirror, curved, portal, recursion change 1% of the frame") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) {
        return;
    }
    const auto files = test_samples::gltf_files_under(*samples);
    REQUIRE(files.size() == 18);
    const auto short_of = every_effect::check_files(files, true); // every_effect_check.hpp
    for (const every_effect::Outcome& o : short_of) {
        MESSAGE(o.file << " " << o.effect << ": " << o.changed_fraction * 100.0 << "% of the frame changed");
    }
    CHECK(short_of.empty());
}

} // TEST_SUITE
