// Every GL object the renderer makes is deleted with it.
#include "render_test_support.hpp"

TEST_SUITE("gl") {

TEST_CASE("no GL object outlives a renderer") {
    const int before = gl::live_object_count();
    {
        RENDER_TEST_ANY_RENDERER(r);
        CHECK(gl::live_object_count() > before);
        const auto cameras = render_test::showcase_cameras();
        for (plan::Effect effect : plan::kAllEffects) {
            r->render(effect, cameras, render_test::options());
        }
    }
    for (int kind = 0; kind < gl::kObjectKindCount; ++kind) {
        INFO(gl::to_string(static_cast<gl::ObjectKind>(kind)));
        CHECK(gl::live_object_count(static_cast<gl::ObjectKind>(kind)) == 0);
    }
}

} // TEST_SUITE
