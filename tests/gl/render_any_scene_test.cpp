// Every effect on every generated model and the showcase, both backends
// (any_scene_check.hpp; the external samples corpus: render_samples_test.cpp).
#include "../sample_files.hpp"
#include "any_scene_check.hpp"

TEST_SUITE("gl") {

TEST_CASE("every effect on every generated model and the showcase, both backends: non-flat, the mirror only where it is") {
    any_scene::check_every_effect(test_samples::scene_files());
}

} // TEST_SUITE
