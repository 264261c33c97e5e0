// The entry-point table (gl/functions.hpp) asks only for OpenGL ES 3.0
// functions: every required name is declared in the Khronos <GLES3/gl3.h>,
// which holds ES 3.0 alone (gl31.h and gl32.h add the later versions). The
// two optional entries are loaded only after their extension or version check
// (clip_control_entry_point(), debug_callback_entry_point()). No context needed.
#include <gl/functions.hpp>

#include <doctest/doctest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

std::string gles30_header() {
    std::ifstream in(FRUSTUM_GLES3_HEADER, std::ios::binary);
    REQUIRE_MESSAGE(in.good(), "cannot open " FRUSTUM_GLES3_HEADER);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// "GL_APICALL void GL_APIENTRY glActiveTexture (GLenum texture);"
bool declares(const std::string& header, const std::string& name) {
    return header.find("GL_APIENTRY " + name + " (") != std::string::npos;
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("gl entry points: every required function of gl::Functions is an OpenGL ES 3.0 function") {
    const std::string header = gles30_header();
    std::vector<std::string> names;
#define FRUSTUM_GL_NAME(type, name) names.push_back("gl" #name);
    FRUSTUM_GL_REQUIRED_FUNCTIONS(FRUSTUM_GL_NAME)
#undef FRUSTUM_GL_NAME
    MESSAGE(names.size() << " required entry points checked against " FRUSTUM_GLES3_HEADER);
    CHECK(names.size() >= 50);
    for (const std::string& name : names) {
        INFO(name << " is not declared in <GLES3/gl3.h> (OpenGL ES 3.0)");
        CHECK(declares(header, name));
    }
    // The check can fail: ES 3.1 and 3.2 functions are not in the ES 3.0 header.
    CHECK(declares(header, "glDrawArrays"));
    CHECK_FALSE(declares(header, "glDispatchCompute"));
    CHECK_FALSE(declares(header, "glDebugMessageCallback"));
}

} // TEST_SUITE
