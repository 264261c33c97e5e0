// Context creation, entry-point loading, clip control detection and debug output.
#include "gl_test_support.hpp"

#include <gl/clip_control.hpp>
#include <gl/errors.hpp>

#include <optional>
#include <string>
#include <vector>

namespace {

// Forwards to a real context but hides one entry point, to test what
// Functions::load() says when the driver lacks it.
class ContextHidingEntryPoint final : public gl::Context {
public:
    ContextHidingEntryPoint(gl::Context& inner, std::string hidden)
        : gl::Context(inner.options()), inner_(inner), hidden_(std::move(hidden)) {
        REQUIRE(initialize(inner.api(), "ContextHidingEntryPoint").ok());
    }
    frustum::Status make_current() override { return inner_.make_current(); }
    Proc get_proc_address(const char* name) const override {
        return hidden_ == name ? nullptr : inner_.get_proc_address(name);
    }
    gl::Backend backend() const override { return inner_.backend(); }

private:
    gl::Context& inner_;
    std::string hidden_;
};

} // namespace

TEST_SUITE("gl") {

TEST_CASE("backend names parse and print") {
    CHECK(gl::to_string(gl::Backend::Egl) == "egl");
    CHECK(gl::to_string(gl::Backend::OsMesa) == "osmesa");
    CHECK(*gl::parse_backend("egl") == gl::Backend::Egl);
    CHECK(*gl::parse_backend("osmesa") == gl::Backend::OsMesa);
    const auto bad = gl::parse_backend("vulkan");
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error() == "gl::parse_backend(): backend must be 'egl' or 'osmesa', got 'vulkan'");
}

TEST_CASE("each backend makes a context with the expected API, version and clip control") {
    for (gl::Backend backend : gl_test::kBackends) {
        INFO("backend: " << gl::to_string(backend));
        auto env = gl_test::make_environment(backend);
        if (!env) {
            continue;
        }
        const gl::Context& context = *env->context;
        const gl::ContextInfo& info = context.describe();
        const bool zero_to_one = gl::supports_zero_to_one_depth(env->fn, context);
        MESSAGE(gl::to_string(backend) << ": " << gl::summary(info)
                                       << " | zero-to-one depth: " << std::string(zero_to_one ? "yes" : "no"));
        CHECK(context.backend() == backend);
        CHECK_FALSE(info.vendor.empty());
        CHECK_FALSE(info.renderer.empty());
        if (backend == gl::Backend::Egl) {
            CHECK(context.api() == gl::Api::Gles);
            CHECK(info.version.major == 3);
            CHECK(info.version_text.rfind("OpenGL ES 3.", 0) == 0);
        } else {
            CHECK(context.api() == gl::Api::GlCore);
            CHECK(context.version_at_least(4, 3));
            CHECK(context.has_extension("GL_ARB_ES3_compatibility"));
        }
        CHECK(zero_to_one == (gl::clip_control_entry_point(context) != nullptr));
        CHECK(zero_to_one == (env->fn.ClipControl != nullptr));
        CHECK_FALSE(context.has_extension("GL_EXT"));
        CHECK_FALSE(context.has_extension(""));
        CHECK(env->context->make_current().ok());
    }
}

TEST_CASE("the fallback factory makes an EGL context when it can, else OSMesa, else names both errors") {
    std::string egl_error, osmesa_error;
    const bool egl = gl_test::try_environment(gl::Backend::Egl, egl_error) != nullptr;
    const bool osmesa = gl_test::try_environment(gl::Backend::OsMesa, osmesa_error) != nullptr;
    std::optional<std::string> fallback_error;
    auto context = gl::create_offscreen_context_with_fallback(
        {}, [&](const std::string& error) { fallback_error = error; });
    CHECK(context.ok() == (egl || osmesa));
    CHECK(fallback_error.has_value() == !egl); // told why EGL was passed over exactly when it was
    if (egl) {
        REQUIRE(context.ok());
        CHECK((*context)->backend() == gl::Backend::Egl);
    } else if (osmesa) {
        REQUIRE(context.ok());
        CHECK((*context)->backend() == gl::Backend::OsMesa);
    } else {
        REQUIRE_FALSE(context.ok());
        CHECK(context.error().find("egl: ") != std::string::npos);
        CHECK(context.error().find("osmesa: ") != std::string::npos);
    }
}

TEST_CASE("an unsupported requested version is an error naming it") {
    gl::ContextOptions options;
    options.gles_version = gl::Version{2, 0};
    options.gl_version = gl::Version{3, 1};
    const auto egl = gl::create_offscreen_context(gl::Backend::Egl, options);
    REQUIRE_FALSE(egl.ok());
    CHECK(egl.error() == "gl::EglSurfacelessContext::create(): gles_version must be >= 3.0, got 2.0");
    const auto osmesa = gl::create_offscreen_context(gl::Backend::OsMesa, options);
    REQUIRE_FALSE(osmesa.ok());
    CHECK(osmesa.error() ==
          "gl::OsMesaContext::create(): gl_version must be >= 3.2 (core profile), got 3.1");
}

TEST_CASE("an exact requested version is honoured") {
    gl::ContextOptions options;
    options.gles_version = gl::Version{3, 0};
    options.gl_version = gl::Version{3, 3};
    for (gl::Backend backend : gl_test::kBackends) {
        INFO("backend: " << gl::to_string(backend));
        auto env = gl_test::make_environment(backend, options);
        if (env) {
            // Drivers may return any compatible version at least as high.
            CHECK(env->context->version_at_least(3, backend == gl::Backend::Egl ? 0 : 3));
        }
    }
}

TEST_CASE("a missing required entry point is named") {
    auto env = gl_test::make_environment(gl::Backend::Egl);
    if (!env) {
        return;
    }
    ContextHidingEntryPoint hiding(*env->context, "glBlitFramebuffer");
    const auto fn = gl::Functions::load(hiding);
    REQUIRE_FALSE(fn.ok());
    CHECK(fn.error() == "gl::Functions::load(): missing required entry points glBlitFramebuffer (" +
                            env->context->describe().version_text + ")");
}

TEST_CASE("two EGL contexts live side by side; destroying one keeps the other") {
    auto first = gl_test::make_environment(gl::Backend::Egl);
    if (!first) {
        return;
    }
    {
        auto second = gl_test::make_environment(gl::Backend::Egl);
        REQUIRE(second);
    }
    REQUIRE(first->context->make_current().ok());
    auto buffer = gl::Buffer::create(first->fn);
    REQUIRE(buffer.ok());
    CHECK(gl::check_error(first->fn, "second context gone").ok());
}

TEST_CASE("debug output reaches the sink") {
    for (gl::Backend backend : gl_test::kBackends) {
        INFO("backend: " << gl::to_string(backend));
        std::vector<std::string> messages;
        gl::ContextOptions options;
        options.debug = true;
        options.debug_sink = [&messages](std::string_view line) { messages.emplace_back(line); };
        auto env = gl_test::make_environment(backend, options);
        if (!env) {
            continue;
        }
        env->fn.Enable(0xFFFF);
        CHECK_FALSE(gl::check_error(env->fn, "after glEnable(0xFFFF)").ok());
        REQUIRE_FALSE(messages.empty());
        MESSAGE(gl::to_string(backend) << " said: " << messages.front());
        CHECK(messages.front().rfind("GL debug: error, high, api #", 0) == 0);
        CHECK(messages.front().find("GL_INVALID_ENUM") != std::string::npos);
    }
}

TEST_CASE("debug output without a sink is an error") {
    gl::ContextOptions options;
    options.debug = true;
    for (gl::Backend backend : gl_test::kBackends) {
        INFO("backend: " << gl::to_string(backend));
        if (!gl_test::make_environment(backend)) {
            continue;
        }
        const auto context = gl::create_offscreen_context(backend, options);
        REQUIRE_FALSE(context.ok());
        CHECK(context.error().find("options.debug needs a debug_sink") != std::string::npos);
    }
}

TEST_CASE("check_error names every flag") {
    auto env = gl_test::make_environment(gl::Backend::Egl);
    if (!env) {
        return;
    }
    CHECK(gl::check_error(env->fn, "clean").ok());
    env->fn.Enable(0xFFFF);
    const auto status = gl::check_error(env->fn, "gl_test::enable()");
    REQUIRE_FALSE(status.ok());
    CHECK(status.error() == "gl_test::enable(): GL error GL_INVALID_ENUM");
    CHECK(gl::check_error(env->fn, "drained").ok());
    CHECK(gl::error_name(0x1234) == "0x1234");
}

} // TEST_SUITE
