// Rendering into an OffscreenTarget through both backends and reading it back.
#include "gl_test_support.hpp"

#include <gl/clip_control.hpp>
#include <gl/errors.hpp>
#include <gl/objects.hpp>
#include <gl/offscreen_target.hpp>
#include <image/compare.hpp>
#include <image/contact_sheet.hpp>
#include <image/png.hpp>

#include <cstdio>
#include <optional>
#include <string>
#include <utility>

namespace {

constexpr int kSize = 64;
// glClearColor(0.1, 0.2, 0.6, 1) and the triangle's (1, 0.5, 0, 1) as RGBA8;
// drivers may round x.5 either way, hence the tolerance of 1.
constexpr image::Rgba kClearRgba{26, 51, 153, 255};
constexpr image::Rgba kTriangleRgba{255, 128, 0, 255};
constexpr int kRoundingTolerance = 1;

// A triangle in the top half of clip space: its centroid (0, 0.5) lands on
// image row 16 of 64 when rows run top to bottom.
constexpr std::array<gl_test::Vertex, 3> kTopTriangle = {{
    {-0.5f, 0.2f, 0.0f, 1.0f},
    {0.5f, 0.2f, 0.0f, 1.0f},
    {0.0f, 0.9f, 0.0f, 1.0f},
}};

// Into the bound target: cleared to kClearRgba, one triangle in kTriangleRgba.
void draw_cleared_triangle(const gl::Functions& fn, const std::array<gl_test::Vertex, 3>& vertices) {
    auto program = gl::Program::build(fn, gl_test::kVertexShader, gl_test::kFragmentShader);
    REQUIRE_MESSAGE(program.ok(), program.error());
    fn.ClearColor(0.1f, 0.2f, 0.6f, 1.0f);
    fn.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl_test::draw_triangle(fn, *program, vertices, {1.0f, 0.5f, 0.0f, 1.0f});
    REQUIRE(gl::check_error(fn, "draw_cleared_triangle()").ok());
}

// A fresh kSize x kSize target with draw_cleared_triangle(), read back.
image::Image render_triangle(const gl::Functions& fn,
                                            const std::array<gl_test::Vertex, 3>& vertices,
                                            gl::ColorStorage color = gl::ColorStorage::Renderbuffer,
                                            gl::DepthFormat depth = gl::DepthFormat::Depth24) {
    auto target = gl::OffscreenTarget::create(fn, {kSize, kSize, color, depth});
    REQUIRE_MESSAGE(target.ok(), target.error());
    draw_cleared_triangle(fn, vertices);
    auto pixels = target->read_rgba8();
    REQUIRE_MESSAGE(pixels.ok(), pixels.error());
    return std::move(*pixels);
}

void check_top_triangle(const image::Image& picture) {
    REQUIRE(picture.width == kSize);
    REQUIRE(picture.height == kSize);
    CHECK(gl_test::near(image::pixel_at(picture, 32, 16), kTriangleRgba, kRoundingTolerance));
    CHECK(gl_test::near(image::pixel_at(picture, 32, 48), kClearRgba, kRoundingTolerance));
    for (int corner_x : {0, kSize - 1}) {
        for (int corner_y : {0, kSize - 1}) {
            CHECK(gl_test::near(image::pixel_at(picture, corner_x, corner_y), kClearRgba,
                                kRoundingTolerance));
        }
    }
}

// On a failed comparison, saves a, b, their diff and a contact sheet.
void save_for_inspection(const std::string& stem, const image::Image& a, const image::Image& b) {
    const auto diff = image::diff_image(a, b);
    REQUIRE(diff.ok());
    const auto sheet = image::contact_sheet({{"a", &a}, {"b", &b}, {"diff", &*diff}}, 3);
    REQUIRE(sheet.ok());
    const std::string path = stem + "-a-b-diff.png";
    const auto written = image::write_png(*sheet, path);
    MESSAGE((written ? "wrote " + path : written.error()));
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("a triangle in the top half comes back in the top rows") {
    for (gl::Backend backend : gl_test::kBackends) {
        INFO("backend: " << gl::to_string(backend));
        auto env = gl_test::make_environment(backend);
        if (!env) {
            continue;
        }
        check_top_triangle(render_triangle(env->fn, kTopTriangle));
    }
    CHECK(gl::live_object_count() == 0);
}

TEST_CASE("texture colour and 32-bit float depth targets render the same") {
    auto env = gl_test::make_environment(gl::Backend::Egl);
    if (!env) {
        return;
    }
    check_top_triangle(render_triangle(env->fn, kTopTriangle, gl::ColorStorage::Texture,
                                       gl::DepthFormat::Depth32F));
}

TEST_CASE("read_rgba8_into() puts the target's rows, top to bottom, in its columns of a wider image") {
    auto env = gl_test::make_any_environment();
    if (!env) {
        return;
    }
    const gl::Functions& fn = env->fn;
    auto target = gl::OffscreenTarget::create(fn, {kSize, kSize});
    REQUIRE_MESSAGE(target.ok(), target.error());
    draw_cleared_triangle(fn, kTopTriangle);
    auto alone = target->read_rgba8();
    REQUIRE_MESSAGE(alone.ok(), alone.error());

    constexpr image::Rgba kUntouched{7, 8, 9, 10};
    constexpr int kColumn = 24;
    image::Image rows = image::make_image(kSize * 2 + 5, kSize, kUntouched);
    auto read = target->read_rgba8_into(rows, kColumn);
    REQUIRE_MESSAGE(read.ok(), read.error());
    int differing = 0, touched_outside = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < rows.width; ++x) {
            const image::Rgba got = image::pixel_at(rows, x, y);
            if (x >= kColumn && x < kColumn + kSize) {
                differing += !(got == image::pixel_at(*alone, x - kColumn, y));
            } else {
                touched_outside += !(got == kUntouched);
            }
        }
    }
    CHECK(differing == 0);
    CHECK(touched_outside == 0);
    // Pack state is left as read_rgba8() expects it.
    auto again = target->read_rgba8();
    REQUIRE(again.ok());
    CHECK(again->rgba == alone->rgba);

    image::Image narrow = image::make_image(kSize + 3, kSize, kUntouched);
    auto off = target->read_rgba8_into(narrow, 4);
    REQUIRE_FALSE(off.ok());
    CHECK(off.error() ==
          "gl::OffscreenTarget::read_rgba8_into(): a 64x64 target at column 4 does not fit a 67x64 image");
    image::Image low = image::make_image(kSize * 2, kSize - 1, kUntouched);
    CHECK_FALSE(target->read_rgba8_into(low, 0).ok());
}

TEST_CASE("blit_color_to() moves a multisampled target's bottom-left part to any place in a larger texture") {
    auto env = gl_test::make_any_environment();
    if (!env) {
        return;
    }
    const gl::Functions& fn = env->fn;
    for (int samples : {1, 4}) {
        if (samples > gl::max_samples(fn)) {
            continue;
        }
        INFO("samples: " << samples);
        auto drawn = gl::OffscreenTarget::create(fn, {kSize, kSize, gl::ColorStorage::Renderbuffer,
                                                      gl::DepthFormat::Depth24, samples});
        REQUIRE_MESSAGE(drawn.ok(), drawn.error());
        draw_cleared_triangle(fn, kTopTriangle);
        auto alone = drawn->read_rgba8();
        REQUIRE_MESSAGE(alone.ok(), alone.error());

        // Two parts of kSize x kSize / 2 (the drawn image's bottom half), one
        // at the origin and one at (kSize + 3, kSize / 2 + 1), into a texture
        // cleared to kUntouched.
        constexpr int kTo = 2 * kSize + 8;
        auto texture = gl::OffscreenTarget::create(fn, {kTo, kTo, gl::ColorStorage::Texture, gl::DepthFormat::None, 1});
        REQUIRE_MESSAGE(texture.ok(), texture.error());
        fn.ClearColor(7 / 255.0f, 8 / 255.0f, 9 / 255.0f, 10 / 255.0f);
        fn.Clear(GL_COLOR_BUFFER_BIT);
        constexpr int kPartX = kSize + 3, kPartY = kSize / 2 + 1;
        for (const auto& [x, y] : {std::pair{0, 0}, std::pair{kPartX, kPartY}}) {
            auto blit = drawn->blit_color_to(*texture, kSize, kSize / 2, x, y);
            REQUIRE_MESSAGE(blit.ok(), blit.error());
        }
        auto got = texture->read_rgba8();
        REQUIRE_MESSAGE(got.ok(), got.error());
        constexpr image::Rgba kUntouched{7, 8, 9, 10};
        int differing = 0, touched_outside = 0;
        for (int y = 0; y < kTo; ++y) { // image rows, top to bottom
            for (int x = 0; x < kTo; ++x) {
                const int from_bottom = kTo - 1 - y;
                const image::Rgba pixel = image::pixel_at(*got, x, y);
                std::optional<image::Rgba> expected;
                for (const auto& [px, py] : {std::pair{0, 0}, std::pair{kPartX, kPartY}}) {
                    if (x >= px && x < px + kSize && from_bottom >= py && from_bottom < py + kSize / 2) {
                        expected = image::pixel_at(*alone, x - px, kSize - 1 - (from_bottom - py));
                    }
                }
                if (expected) {
                    differing += !(pixel == *expected);
                } else {
                    touched_outside += !gl_test::near(pixel, kUntouched, kRoundingTolerance);
                }
            }
        }
        CHECK(differing == 0);
        CHECK(touched_outside == 0);

        auto outside = drawn->blit_color_to(*texture, kSize, kSize / 2, kTo - kSize + 1, 0);
        REQUIRE_FALSE(outside.ok());
        CHECK(outside.error() == "gl::OffscreenTarget::blit_color_to(): 64x32 pixels at (73, 0) must fit both the "
                                 "64x64 target and the 136x136 one");
        CHECK_FALSE(drawn->blit_color_to(*texture, kSize, kSize, 0, -1).ok());
        if (samples > 1) { // into a multisampled target
            CHECK_FALSE(texture->blit_color_to(*drawn, 8, 8).ok());
        }
    }
}

TEST_CASE("EGL and OSMesa images agree") {
    std::optional<image::Image> pictures[2];
    for (std::size_t i = 0; i < 2; ++i) {
        auto env = gl_test::make_environment(gl_test::kBackends[i]);
        if (!env) {
            return;
        }
        pictures[i] = render_triangle(env->fn, kTopTriangle);
    }
    // Both are llvmpipe, so edges should match too; allow one level of
    // rounding per channel and no pixel beyond it.
    const auto diff = image::compare(*pictures[0], *pictures[1], kRoundingTolerance);
    REQUIRE(diff.ok());
    MESSAGE("egl vs osmesa: mean " << diff->mean_abs << ", max " << diff->max_abs << ", "
                                   << diff->pixels_over << " pixels over " << diff->tolerance);
    CHECK(diff->pixels_over == 0);
    if (diff->pixels_over != 0) {
        save_for_inspection("egl-vs-osmesa", *pictures[0], *pictures[1]);
    }
}

TEST_CASE("zero-to-one clip control clips what [-1, 1] keeps") {
    // Clip z = -0.5 w: inside [-1, 1] depth, behind the near plane in [0, 1].
    constexpr std::array<gl_test::Vertex, 3> kNegativeZ = {{
        {-0.5f, 0.2f, -0.5f, 1.0f},
        {0.5f, 0.2f, -0.5f, 1.0f},
        {0.0f, 0.9f, -0.5f, 1.0f},
    }};
    for (gl::Backend backend : gl_test::kBackends) {
        INFO("backend: " << gl::to_string(backend));
        auto env = gl_test::make_environment(backend);
        if (!env) {
            continue;
        }
        if (!gl::supports_zero_to_one_depth(env->fn, *env->context)) {
            if (!gl_test::clip_control_removed_on_purpose()) {
                test_skips::skip(std::string(gl::to_string(backend)) + ": no clip control");
            }
            const auto status = gl::set_depth_zero_to_one(env->fn, true);
            CHECK_FALSE(status.ok());
            continue;
        }
        REQUIRE(gl::set_depth_zero_to_one(env->fn, true).ok());
        const auto clipped = render_triangle(env->fn, kNegativeZ);
        CHECK(gl_test::near(image::pixel_at(clipped, 32, 16), kClearRgba, kRoundingTolerance));
        REQUIRE(gl::set_depth_zero_to_one(env->fn, false).ok());
        const auto kept = render_triangle(env->fn, kNegativeZ);
        CHECK(gl_test::near(image::pixel_at(kept, 32, 16), kTriangleRgba, kRoundingTolerance));
    }
}

TEST_CASE("an occlusion query sees the triangle") {
    auto env = gl_test::make_environment(gl::Backend::Egl);
    if (!env) {
        return;
    }
    const gl::Functions& fn = env->fn;
    auto query = gl::Query::create(fn);
    REQUIRE(query.ok());
    fn.BeginQuery(GL_ANY_SAMPLES_PASSED, query->id());
    render_triangle(fn, kTopTriangle);
    fn.EndQuery(GL_ANY_SAMPLES_PASSED);
    GLuint any_passed = 0;
    fn.GetQueryObjectuiv(query->id(), GL_QUERY_RESULT, &any_passed);
    CHECK(any_passed == GL_TRUE);
    CHECK(gl::check_error(fn, "query").ok());
}

TEST_CASE("shader errors carry the stage and the info log") {
    auto env = gl_test::make_environment(gl::Backend::Egl);
    if (!env) {
        return;
    }
    const gl::Functions& fn = env->fn;
    const auto broken = gl::Program::build(fn, gl_test::kVertexShader,
                                           "#version 300 es\nvoid main() { undefined_call(); }\n");
    REQUIRE_FALSE(broken.ok());
    const std::string prefix = "gl::Program::build(): fragment shader failed to compile:\n";
    CHECK(broken.error().rfind(prefix, 0) == 0);
    CHECK(broken.error().size() > prefix.size() + 10);
    MESSAGE(broken.error());

    const auto unlinked = gl::Program::build(
        fn, gl_test::kVertexShader,
        "#version 300 es\nprecision mediump float;\nin vec4 v_never_written;\nout vec4 o;\n"
        "void main() { o = v_never_written; }\n");
    REQUIRE_FALSE(unlinked.ok());
    CHECK(unlinked.error().rfind("gl::Program::build(): link failed:\n", 0) == 0);
    MESSAGE(unlinked.error());

    const auto bad_stage = gl::Shader::compile(fn, GL_TEXTURE_2D, "");
    REQUIRE_FALSE(bad_stage.ok());
    CHECK(bad_stage.error() ==
          "gl::Shader::compile(): glCreateShader failed for shader stage 0x0DE1: GL error GL_INVALID_ENUM");
    CHECK(gl::live_object_count(gl::ObjectKind::Shader) == 0);
    CHECK(gl::live_object_count(gl::ObjectKind::Program) == 0);
}

TEST_CASE("bad target sizes and incomplete framebuffers give clear errors") {
    auto env = gl_test::make_environment(gl::Backend::Egl);
    if (!env) {
        return;
    }
    const gl::Functions& fn = env->fn;
    const auto empty = gl::OffscreenTarget::create(fn, {0, 64});
    REQUIRE_FALSE(empty.ok());
    CHECK(empty.error() == "gl::OffscreenTarget::create(): width and height must be >= 1, got 0x64");

    GLint max_renderbuffer = 0;
    fn.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
    const int too_wide = max_renderbuffer + 1;
    const auto oversized = gl::OffscreenTarget::create(fn, {too_wide, 64});
    REQUIRE_FALSE(oversized.ok());
    CHECK(oversized.error() ==
          "gl::OffscreenTarget::create(): width and height must be <= GL_MAX_RENDERBUFFER_SIZE=" +
              std::to_string(max_renderbuffer) + ", got " + std::to_string(too_wide) + "x64");

    auto framebuffer = gl::Framebuffer::create(fn);
    REQUIRE(framebuffer.ok());
    fn.BindFramebuffer(GL_FRAMEBUFFER, framebuffer->id());
    const auto incomplete = gl::check_framebuffer_complete(fn, GL_FRAMEBUFFER, "gl_test::bare()");
    REQUIRE_FALSE(incomplete.ok());
    CHECK(incomplete.error() ==
          "gl_test::bare(): framebuffer incomplete: GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT");
    fn.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("handles move, reset and count live objects") {
    auto env = gl_test::make_environment(gl::Backend::OsMesa);
    if (!env) {
        return;
    }
    const int before = gl::live_object_count();
    auto created = gl::Buffer::create(env->fn);
    REQUIRE(created.ok());
    gl::Buffer moved = std::move(*created);
    CHECK_FALSE(*created);
    CHECK(moved);
    CHECK(gl::live_object_count(gl::ObjectKind::Buffer) == 1);
    gl::Buffer assigned;
    assigned = std::move(moved);
    CHECK(assigned.kind() == gl::ObjectKind::Buffer);
    CHECK(gl::live_object_count() == before + 1);
    assigned.reset();
    CHECK_FALSE(assigned);
    CHECK(gl::live_object_count() == before);
}

TEST_CASE("no GL object outlives the tests") {
    for (int kind = 0; kind < gl::kObjectKindCount; ++kind) {
        INFO(gl::to_string(static_cast<gl::ObjectKind>(kind)));
        CHECK(gl::live_object_count(static_cast<gl::ObjectKind>(kind)) == 0);
    }
}

} // TEST_SUITE
