// The suite's OpenGL ES 3.0 reruns (ctest -L gl: gl-es30 and
// gl-es30-no-clip-control, tests/app_tests.cmake) run this whole suite with
// MESA_GLES_VERSION_OVERRIDE=3.0, the second also with
// MESA_EXTENSION_OVERRIDE=-GL_EXT_clip_control. FRUSTUM_EXPECT_GLES names
// what the rerun asked for; this case proves Mesa gave it, so the rerun
// cannot pass on an ES 3.2 context by accident.
#include <gl/clip_control.hpp>
#include <gl/context.hpp>

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

TEST_CASE("an ES 3.0 rerun runs on an OpenGL ES 3.0 context, without clip control when asked") {
    const char* expect = std::getenv("FRUSTUM_EXPECT_GLES");
    if (!expect) {
        MESSAGE("not an ES 3.0 rerun (FRUSTUM_EXPECT_GLES unset)");
        return;
    }
    const std::string expected = expect;
    REQUIRE_MESSAGE((expected == "3.0" || expected == "3.0-no-clip-control"),
                    "FRUSTUM_EXPECT_GLES must be 3.0 or 3.0-no-clip-control, got " << expected);
    auto context = gl::create_offscreen_context(gl::Backend::Egl, {});
    REQUIRE_MESSAGE(context.ok(), context.error());
    const gl::ContextInfo& info = (*context)->describe();
    INFO(info.version_text);
    CHECK(info.version.major == 3);
    CHECK(info.version.minor == 0);
    CHECK(info.version_text.rfind("OpenGL ES 3.0", 0) == 0);
    const bool clip_control = (*context)->has_extension("GL_EXT_clip_control");
    CHECK(clip_control == (expected == "3.0"));
    CHECK(clip_control == (gl::clip_control_entry_point(**context) != nullptr));
}
