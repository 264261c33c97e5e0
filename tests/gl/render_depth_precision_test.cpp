// docs/depth-precision.md's numbers against the GPU: the metres one depth
// step spans, predicted from the pair by precision::metres_per_step(), and
// measured as the width of the bins the depth buffer stores (the depth
// test with GL_LEQUAL passes a second, farther quad only while its stored
// depth equals the first's).
#include "render_test_support.hpp"

#include <precision/depth_precision.hpp>

#include <frustum/oblique_clip.hpp>
#include <frustum/projection.hpp>
#include <render/gpu_scene.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace {

constexpr int kSidePx = 9; // the axis hits the centre of pixel (4, 4)
constexpr double kPi = 3.14159265358979323846;

struct DepthProbe {
    const gl::Functions& fn;
    const render::LineProgram& program;
    const gl::OffscreenTarget& target;
    glm::mat4 matrix; // as the GPU gets it
    bool reversed;    // GL_GREATER / GL_GEQUAL against a clear value of 0
    gl::Buffer buffer;
    gl::VertexArray vertex_array;

    // A small square across the axis at distance_m, in a flat colour (small:
    // the oblique row 2 weighs x, and large x would add float rounding).
    void draw_square(double distance_m, const glm::vec4& color) const {
        const float z = static_cast<float>(-distance_m), h = static_cast<float>(0.001 * distance_m);
        const glm::vec3 v[6] = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, -h, z}, {h, h, z}, {-h, h, z}};
        fn.BindBuffer(GL_ARRAY_BUFFER, buffer.id());
        fn.BufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STREAM_DRAW);
        program.set_color(color);
        fn.DrawArrays(GL_TRIANGLES, 0, 6);
    }

    // Whether a square at b_m lands in the same stored depth as one at a_m.
    bool same_bin(double a_m, double b_m) const {
        target.bind();
        fn.Enable(GL_DEPTH_TEST);
        fn.DepthMask(GL_TRUE);
        fn.Disable(GL_CULL_FACE);
        fn.ClearDepthf(reversed ? 0.0f : 1.0f);
        fn.ClearColor(0, 0, 0, 1);
        fn.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        program.use();
        program.set_view_projection(matrix);
        fn.BindVertexArray(vertex_array.id());
        fn.BindBuffer(GL_ARRAY_BUFFER, buffer.id());
        fn.EnableVertexAttribArray(render::kPositionLocation);
        fn.VertexAttribPointer(render::kPositionLocation, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        fn.DepthFunc(reversed ? GL_GREATER : GL_LESS);
        draw_square(a_m, {1, 0, 0, 1});
        fn.DepthFunc(reversed ? GL_GEQUAL : GL_LEQUAL);
        draw_square(b_m, {0, 1, 0, 1});
        fn.BindVertexArray(0);
        fn.DepthFunc(GL_LESS);
        fn.ClearDepthf(1.0f);
        auto picture = target.read_rgba8();
        REQUIRE_MESSAGE(picture.ok(), picture.error());
        return image::pixel_at(*picture, kSidePx / 2, kSidePx / 2)[1] > 128;
    }

    // The far edge of the bin holding `from_m`, by bisection (the bin's
    // far edge is at most `reach_m` away).
    double bin_edge(double from_m, double reach_m) const {
        double inside = 0.0, outside = reach_m;
        REQUIRE(!same_bin(from_m, from_m + outside));
        for (int i = 0; i < 30; ++i) {
            const double mid = 0.5 * (inside + outside);
            (same_bin(from_m, from_m + mid) ? inside : outside) = mid;
        }
        return from_m + outside;
    }

    // Mean width of `bins` consecutive bins from distance_m on.
    double measured_step_m(double distance_m, double predicted_m, int bins) const {
        const double first = bin_edge(distance_m, 4.0 * predicted_m);
        double edge = first;
        for (int i = 0; i < bins; ++i) {
            edge = bin_edge(edge + 0.02 * predicted_m, 4.0 * predicted_m);
        }
        return (edge - first) / bins;
    }
};

} // namespace

TEST_SUITE("gl") {

TEST_CASE("metres per depth step: the pair's prediction is what the GPU stores") {
    RENDER_TEST_ANY_RENDERER(r);
    const render::DepthPolicy depth = render_test::apply_depth_policy(*r);
    const bool clip_control = depth.gpu_range() == frustum::DepthRange::ZeroToOne;
    const gl::Functions& fn = r->env->fn;
    const auto camera = frustum::perspective<double>(kPi / 3.0, 1.0, 0.1, 100.0, frustum::DepthRange::ZeroToOne);
    REQUIRE(camera.ok());
    // A plane 1 m down the axis, tilted 60 degrees (as in the doc's table).
    const double t = 60.0 * kPi / 180.0;
    const glm::dvec3 n(std::sin(t), 0.0, -std::cos(t));
    const auto oblique = frustum::clip_oblique(*camera, frustum::Plane<double>(n.x, n.y, n.z, -n.z * -1.0));
    REQUIRE_MESSAGE(oblique.ok(), oblique.error());
    constexpr double kDistanceM = 50.0; // steps of many float ulps of the vertex positions there

    struct Case {
        const char* name;
        const frustum::MatrixPair<double>* pair;
        gl::DepthFormat format;
        precision::Storage storage;
        frustum::DepthRange range; // the pair's range on the GPU
    };
    const frustum::DepthRange gpu = depth.gpu_range();
    std::vector<Case> cases = {
        {"oblique, 24-bit fixed", &*oblique, gl::DepthFormat::Depth24, precision::Storage::Fixed24, gpu},
        {"un-clipped, 24-bit fixed", &*camera, gl::DepthFormat::Depth24, precision::Storage::Fixed24, gpu},
        {"oblique, 32-bit float", &*oblique, gl::DepthFormat::Depth32F, precision::Storage::Float32, gpu},
    };
    if (clip_control) { // reversed-Z needs GL_ZERO_TO_ONE
        cases.push_back({"oblique, reversed-Z 32-bit float", &*oblique, gl::DepthFormat::Depth32F,
                         precision::Storage::Float32, frustum::DepthRange::ReversedZeroToOne});
    }
    for (const Case& c : cases) {
        INFO(std::string(c.name) << ", GPU range " << frustum::to_string(c.range));
        const frustum::MatrixPair<double> pair = c.pair->with_depth_range(c.range);
        const auto predicted = precision::metres_per_step(pair, c.storage, glm::dvec3(0.0),
                                                          glm::dvec3(0.0, 0.0, -kDistanceM));
        REQUIRE(predicted.has_value());
        auto target = gl::OffscreenTarget::create(fn, {kSidePx, kSidePx, gl::ColorStorage::Renderbuffer, c.format, 1});
        REQUIRE_MESSAGE(target.ok(), target.error());
        auto buffer = gl::Buffer::create(fn);
        auto vertex_array = gl::VertexArray::create(fn);
        REQUIRE(buffer.ok());
        REQUIRE(vertex_array.ok());
        const DepthProbe probe{fn,
                               r->renderer->programs().line,
                               *target,
                               glm::mat4(pair.matrix()),
                               c.range == frustum::DepthRange::ReversedZeroToOne,
                               std::move(*buffer),
                               std::move(*vertex_array)};
        const double measured = probe.measured_step_m(kDistanceM, *predicted, 16);
        MESSAGE(std::string(c.name) << " at " << kDistanceM << " m: predicted " << *predicted * 1000.0 << " mm, measured "
                       << measured * 1000.0 << " mm per step");
        // The GPU computes clip z in float: where its rounding (about 2^-24
        // of w) is as large as the stored step (z / w near 1 in 24 bits;
        // reversed-Z, whose z is a difference of terms of size w) it blurs
        // the bin edges and the bisection reads them wide. Tolerance 25% on the mean of 16 bins. Measured
        // (llvmpipe): oblique 24-bit +0.02%, oblique float -1.4%, un-clipped
        // 24-bit +12.8%, oblique reversed-Z float +12.9% (docs/depth-precision.md).
        CHECK(measured > 0.75 * *predicted);
        CHECK(measured < 1.25 * *predicted);
    }
    render::set_frame_state(r->renderer->pass_context(depth, render::Lighting{}));
}

} // TEST_SUITE
