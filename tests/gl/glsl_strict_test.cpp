// GLES 3.0 strictness of the shaders as the renderer composes them (defines
// and the frustum.glsl snippet inserted after "#version 300 es"): every
// source a Renderer hands to glShaderSource while it builds its programs and
// draws every effect is captured through its function table and checked by
// glslangValidator (Debian glslang-tools) as ES 300 (the #version line),
// strictly, outside Mesa, which also accepts 310/320 features. The raw
// shaders/ files are checked too (lens_remap.frag is linked only by the lens
// reference).
#include "render_test_support.hpp"

#include <support/child_process.hpp>

#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Captured {
    GLenum stage;
    std::string text;
};

// glCreateShader / glShaderSource with a record of every source (the test
// is single-threaded; the originals are the context's).
PFNGLCREATESHADERPROC g_create_shader = nullptr;
PFNGLSHADERSOURCEPROC g_shader_source = nullptr;
std::map<GLuint, GLenum> g_stages;
std::vector<Captured> g_sources;

GLuint GL_APIENTRY record_create_shader(GLenum stage) {
    const GLuint id = g_create_shader(stage);
    g_stages[id] = stage;
    return id;
}

void GL_APIENTRY record_shader_source(GLuint id, GLsizei count, const GLchar* const* strings, const GLint* lengths) {
    std::string text;
    for (GLsizei i = 0; i < count; ++i) {
        text += lengths && lengths[i] >= 0 ? std::string(strings[i], static_cast<std::size_t>(lengths[i]))
                                           : std::string(strings[i]);
    }
    g_sources.push_back({g_stages[id], text});
    g_shader_source(id, count, strings, lengths);
}

// glslangValidator's verdict on `text` as a `stage` shader: empty when valid.
// (tests/support's runner: no shell, at most its 120 s, then a failure naming the command.)
std::string validate(const std::string& validator, const fs::path& folder, const std::string& name, GLenum stage,
                     const std::string& text) {
    const fs::path path = folder / (name + (stage == GL_VERTEX_SHADER ? ".vert" : ".frag"));
    std::ofstream(path) << text;
    support::Launch launch;
    launch.args = {path.string()};
    const support::Outcome verdict = support::run(validator, launch);
    return verdict.exit_status == 0 && verdict.signal == 0 ? std::string() : verdict.out + verdict.err;
}

} // namespace

TEST_CASE("every shader the renderer composes is valid GLSL ES 3.00 for glslangValidator") {
    const std::string validator = support::find_on_path("glslangValidator");
    REQUIRE_MESSAGE(!validator.empty(), "glslangValidator not found (glslang-tools, scripts/install-deps.sh)");
    auto env = gl_test::make_environment(gl::Backend::Egl);
    if (!env) {
        return;
    }
    g_create_shader = env->fn.CreateShader;
    g_shader_source = env->fn.ShaderSource;
    gl::Functions recording = env->fn;
    recording.CreateShader = &record_create_shader;
    recording.ShaderSource = &record_shader_source;
    g_sources.clear();
    {
        auto renderer = render::Renderer::create(*env->context, recording, render_test::showcase());
        REQUIRE_MESSAGE(renderer.ok(), renderer.error());
        const plan::Cameras cameras = render_test::showcase_cameras(64, 36);
        render::RenderOptions options;
        options.width_px = 64;
        options.height_px = 36;
        options.fog = plan::FogOptions{};
        for (plan::Effect effect : plan::kAllEffects) {
            CAPTURE(plan::to_string(effect));
            auto picture = renderer->render(effect, cameras, options);
            REQUIRE_MESSAGE(picture.ok(), picture.error());
        }
    }
    // scene (4 variants) + non-affine (2) + composite + line + curved + fog, each two stages.
    CHECK(g_sources.size() >= 20);
    const fs::path folder = render_test::output_dir() / "glsl_strict";
    fs::create_directories(folder);
    std::set<std::string> distinct;
    for (std::size_t i = 0; i < g_sources.size(); ++i) {
        const Captured& source = g_sources[i];
        REQUIRE((source.stage == GL_VERTEX_SHADER || source.stage == GL_FRAGMENT_SHADER));
        CHECK(source.text.rfind("#version 300 es\n", 0) == 0);
        if (!distinct.insert(source.text).second) {
            continue;
        }
        const std::string verdict = validate(validator, folder, "composed-" + std::to_string(i), source.stage, source.text);
        CHECK_MESSAGE(verdict.empty(), "composed shader " << i << ":\n" << source.text << "\n" << verdict);
    }
    MESSAGE(distinct.size() << " distinct composed shaders checked");
}

TEST_CASE("every GLSL file in shaders/ with a #version line is valid GLSL ES 3.00") {
    const std::string validator = support::find_on_path("glslangValidator");
    REQUIRE_MESSAGE(!validator.empty(), "glslangValidator not found (glslang-tools, scripts/install-deps.sh)");
    const fs::path folder = render_test::output_dir() / "glsl_strict";
    fs::create_directories(folder);
    int checked = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(FRUSTUM_SOURCE_DIR) / "shaders")) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".vert" && extension != ".frag") {
            continue; // frustum.glsl: a snippet without #version, checked inside the composed shaders
        }
        std::ifstream in(entry.path());
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        CAPTURE(entry.path().filename().string());
        CHECK(text.rfind("#version 300 es\n", 0) == 0);
        if (text.find("frustum_") != std::string::npos) {
            continue; // calls frustum.glsl: valid only composed (the case above)
        }
        const std::string verdict = validate(validator, folder, "file-" + entry.path().stem().string(),
                                             extension == ".vert" ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER, text);
        CHECK_MESSAGE(verdict.empty(), verdict);
        ++checked;
    }
    CHECK(checked >= 8);
}
