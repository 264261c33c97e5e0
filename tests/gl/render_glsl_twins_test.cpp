// shaders/frustum.glsl, the GPU twins of the library's per-frame math, run
// on the GPU (a vertex shader captured with transform feedback) for random
// pairs and compared with the C++ library in float.
#include "gl_test_support.hpp"

#include <frustum/frustum.hpp>
#include <gl/offscreen_target.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

// One vec4 per vertex: what gl_VertexID asks for.
constexpr int kOutputs = 27;
constexpr const char* kTwinsVertex = R"glsl(
uniform mat4 u_m;
uniform mat4 u_inverse;
uniform float u_z_near;
uniform float u_z_far;
uniform vec4 u_rect;       // crop rectangle (x, y, width, height)
uniform vec2 u_full;       // full image size
uniform vec4 u_outward[6]; // non-affine planes, unit, outward
uniform vec3 u_point;      // a point for eq. 36
uniform vec3 u_ndc_depth;  // u_point through u_m: x, y / w and its window depth in [0, 1]

out vec4 v_out;

void main() {
    int i = gl_VertexID;
    vec4 planes[6];
    frustum_planes(u_m, u_z_near, u_z_far, planes);
    if (i < 6) {
        v_out = planes[i];                                            // 0..5: L R B T N F
    } else if (i < 14) {
        v_out = frustum_corner(u_inverse, i - 6, u_z_near, u_z_far);  // 6..13: C1..C8
    } else if (i == 14) {
        v_out = frustum_center(u_inverse, u_z_near, u_z_far);
    } else if (i == 15) {
        v_out = frustum_eye(u_m, u_inverse, u_z_near, u_z_far);
    } else if (i < 20) {
        v_out = frustum_row(frustum_crop_matrix(u_m, u_rect, u_full), i - 16); // 16..19: rows of the crop
    } else if (i < 24) {
        v_out = frustum_crop_inverse(u_inverse, u_rect, u_full)[i - 20];       // 20..23: its inverse's columns
    } else if (i == 24) {
        v_out = frustum_non_affine_clip(u_outward, u_point, u_z_near, u_z_far);
    } else if (i == 25) {
        v_out = vec4(frustum_non_affine_denominators(u_outward, u_point), 0.0);
    } else {
        v_out = vec4(frustum_world_from_depth(u_inverse, u_ndc_depth.xy, u_ndc_depth.z, u_z_near, u_z_far), 1.0);
    }
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
)glsl";

constexpr const char* kTwinsFragment = R"glsl(#version 300 es
precision mediump float;
out vec4 o_color;
void main() { o_color = vec4(0.0); }
)glsl";

std::string read_snippet() {
    std::ifstream in(std::string(FRUSTUM_SOURCE_DIR) + "/shaders/frustum.glsl");
    REQUIRE_MESSAGE(in.good(), "cannot read shaders/frustum.glsl");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Transform feedback entry points, which gl::Functions does not load.
struct Feedback {
    PFNGLTRANSFORMFEEDBACKVARYINGSPROC varyings = nullptr;
    PFNGLBEGINTRANSFORMFEEDBACKPROC begin = nullptr;
    PFNGLENDTRANSFORMFEEDBACKPROC end = nullptr;
    PFNGLMAPBUFFERRANGEPROC map = nullptr;
    PFNGLUNMAPBUFFERPROC unmap = nullptr;

    explicit Feedback(const gl::Context& context) {
        varyings = reinterpret_cast<PFNGLTRANSFORMFEEDBACKVARYINGSPROC>(
            context.get_proc_address("glTransformFeedbackVaryings"));
        begin = reinterpret_cast<PFNGLBEGINTRANSFORMFEEDBACKPROC>(context.get_proc_address("glBeginTransformFeedback"));
        end = reinterpret_cast<PFNGLENDTRANSFORMFEEDBACKPROC>(context.get_proc_address("glEndTransformFeedback"));
        map = reinterpret_cast<PFNGLMAPBUFFERRANGEPROC>(context.get_proc_address("glMapBufferRange"));
        unmap = reinterpret_cast<PFNGLUNMAPBUFFERPROC>(context.get_proc_address("glUnmapBuffer"));
    }
    bool ok() const { return varyings && begin && end && map && unmap; }
};

// A linked program capturing v_out; deleted with the object.
class FeedbackProgram {
public:
    FeedbackProgram(const gl::Functions& fn, const Feedback& feedback) : fn_(fn) {
        auto vertex = gl::Shader::compile(fn, GL_VERTEX_SHADER, "#version 300 es\n" + read_snippet() + kTwinsVertex);
        REQUIRE_MESSAGE(vertex.ok(), vertex.error());
        auto fragment = gl::Shader::compile(fn, GL_FRAGMENT_SHADER, kTwinsFragment);
        REQUIRE_MESSAGE(fragment.ok(), fragment.error());
        id_ = fn.CreateProgram();
        fn.AttachShader(id_, vertex->id());
        fn.AttachShader(id_, fragment->id());
        const char* captured[] = {"v_out"};
        feedback.varyings(id_, 1, captured, GL_INTERLEAVED_ATTRIBS);
        fn.LinkProgram(id_);
        GLint linked = GL_FALSE;
        fn.GetProgramiv(id_, GL_LINK_STATUS, &linked);
        REQUIRE(linked == GL_TRUE);
    }
    ~FeedbackProgram() { fn_.DeleteProgram(id_); }
    FeedbackProgram(const FeedbackProgram&) = delete;
    FeedbackProgram& operator=(const FeedbackProgram&) = delete;
    GLuint id() const { return id_; }
    GLint uniform(const char* name) const { return fn_.GetUniformLocation(id_, name); }

private:
    const gl::Functions& fn_;
    GLuint id_ = 0;
};

struct Case {
    frustum::MatrixPair<float> pair;
    frustum::CropRect<float> rect;
    frustum::NonAffineFrustum<float> outward;
    glm::vec3 point;
};

// A random camera (perspective, off-axis or orthographic) looking from a
// random eye, in a random depth range, with a random crop rectangle, a
// non-affine frustum from its planes each turned a little, and a point
// inside that frustum.
Case random_case(std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const auto between = [&](float a, float b) { return a + (b - a) * unit(rng); };
    const frustum::DepthRange depths[] = {frustum::DepthRange::ZeroToOne, frustum::DepthRange::MinusOneToOne,
                                          frustum::DepthRange::ReversedZeroToOne};
    const frustum::DepthRange depth = depths[rng() % 3];
    const float near_m = between(0.05f, 1.0f), far_m = near_m * between(10.0f, 1000.0f);
    // One draw per statement (argument order is unspecified), last argument
    // first: the order these cases were always drawn in.
    const auto draw_zyx = [&](float half_x, float half_y, float half_z) {
        const float z = between(-half_z, half_z), y = between(-half_y, half_y), x = between(-half_x, half_x);
        return glm::vec3(x, y, z);
    };
    const int kind = static_cast<int>(rng() % 3);
    const auto make_projection = [&]() {
        if (kind == 0) {
            const float aspect = between(0.5f, 2.5f), fovy_rad = between(0.3f, 2.0f);
            return frustum::perspective<float>(fovy_rad, aspect, near_m, far_m, depth);
        }
        if (kind == 1) {
            const float top = between(0.01f, 1.0f), bottom = -between(0.01f, 1.0f);
            const float right = between(0.01f, 1.0f), left = -between(0.01f, 1.0f);
            return frustum::off_axis<float>(left, right, bottom, top, near_m, far_m, depth);
        }
        const float far_ortho = between(5.0f, 50.0f), near_ortho = -between(0.0f, 2.0f);
        const float top = between(1.0f, 5.0f), bottom = -between(1.0f, 5.0f);
        const float right = between(1.0f, 5.0f), left = -between(1.0f, 5.0f);
        return frustum::orthographic<float>(left, right, bottom, top, near_ortho, far_ortho, depth);
    };
    auto projection = make_projection();
    REQUIRE_MESSAGE(projection.ok(), projection.error());
    const glm::vec3 eye = draw_zyx(10.0f, 10.0f, 10.0f);
    const glm::vec3 target = eye + draw_zyx(1.0f, 0.5f, 1.0f);
    auto view = frustum::look_at<float>(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    REQUIRE_MESSAGE(view.ok(), view.error());
    const frustum::MatrixPair<float> pair = frustum::compose(*projection, *view);

    const float full_w = between(100.0f, 1000.0f), full_h = between(100.0f, 1000.0f);
    const float w = between(1.0f, full_w), h = between(1.0f, full_h);
    const frustum::CropRect<float> rect{between(0.0f, full_w - w), between(0.0f, full_h - h), w, h, full_w, full_h};

    // Inside: the centre D, a finite point for every kind.
    const glm::vec3 centre(frustum::to_point(frustum::key_points(pair).center, 1e-6f));
    const auto p = frustum::planes(pair);
    REQUIRE(p.far.has_value());
    const auto turned = [&](const frustum::Plane<float>& inward) {
        const glm::vec3 n = glm::normalize(-inward.normal() + 0.1f * draw_zyx(1.0f, 1.0f, 1.0f));
        const float distance_inside = inward.distance(centre); // keep D as far inside as it was
        return frustum::Plane<float>(glm::vec4(n, -glm::dot(n, centre) - distance_inside));
    };
    const auto far = turned(*p.far), near = turned(p.near), top = turned(p.top); // far first, as always
    const auto bottom = turned(p.bottom), right = turned(p.right), left = turned(p.left);
    auto outward = frustum::NonAffineFrustum<float>::from_planes(left, right, bottom, top, near, far, centre, depth);
    REQUIRE_MESSAGE(outward.ok(), outward.error());
    // A point between D and a near corner: inside the (turned) frustum near D.
    const glm::vec3 corner(frustum::to_point(frustum::key_points(pair).corners[rng() % 4], 1e-6f));
    const glm::vec3 point = centre + between(0.0f, 0.5f) * (corner - centre);
    return {pair, rect, *outward, point};
}

// |gpu - cpu| relative to the larger of 1 and cpu's largest component.
float relative_error(const glm::vec4& gpu, const glm::vec4& cpu) {
    const glm::vec4 d = glm::abs(gpu - cpu);
    const float scale = std::max({1.0f, std::abs(cpu.x), std::abs(cpu.y), std::abs(cpu.z), std::abs(cpu.w)});
    return std::max({d.x, d.y, d.z, d.w}) / scale;
}

// What frustum.glsl should give for output i, from the C++ library.
std::vector<glm::vec4> expected(const Case& c) {
    std::vector<glm::vec4> out;
    const auto p = frustum::planes(c.pair);
    for (const auto& plane : {p.left, p.right, p.bottom, p.top, p.near, *p.far}) {
        out.push_back(plane.abcd);
    }
    const auto k = frustum::key_points(c.pair);
    out.insert(out.end(), k.corners.begin(), k.corners.end());
    out.push_back(k.center);
    out.push_back(k.eye);
    const auto cropped = frustum::crop(c.pair, c.rect);
    REQUIRE_MESSAGE(cropped.ok(), cropped.error());
    for (int r = 0; r < 4; ++r) {
        out.push_back(frustum::row(cropped->matrix(), r));
    }
    for (int col = 0; col < 4; ++col) {
        out.push_back(cropped->inverse()[col]);
    }
    const auto clip = c.outward.to_clip(c.point, 0.0f);
    REQUIRE(clip.has_value());
    out.push_back(*clip);
    out.push_back(glm::vec4(c.outward.denominators(c.point), 0.0f));
    out.push_back(glm::vec4(c.point, 1.0f)); // frustum_world_from_depth() takes it back from its depth
    return out;
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("frustum.glsl matches the C++ library on the GPU (transform feedback, 200 random pairs)") {
    std::unique_ptr<gl_test::Environment> env;
    for (gl::Backend backend : gl_test::kBackends) {
        if ((env = gl_test::make_environment(backend))) {
            break;
        }
    }
    if (!env) {
        return;
    }
    const gl::Functions& fn = env->fn;
    const Feedback feedback(*env->context);
    REQUIRE(feedback.ok());
    const FeedbackProgram program(fn, feedback);
    // The contexts are surfaceless: even with rasterization off, a draw needs a complete framebuffer.
    auto target = gl::OffscreenTarget::create(fn, {1, 1});
    REQUIRE_MESSAGE(target.ok(), target.error());
    auto buffer = gl::Buffer::create(fn);
    auto vertex_array = gl::VertexArray::create(fn);
    REQUIRE(buffer.ok());
    REQUIRE(vertex_array.ok());
    fn.BindVertexArray(vertex_array->id());
    fn.BindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffer->id());
    fn.BufferData(GL_TRANSFORM_FEEDBACK_BUFFER, kOutputs * sizeof(glm::vec4), nullptr, GL_DYNAMIC_READ);
    fn.BindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer->id());
    fn.UseProgram(program.id());
    fn.Enable(GL_RASTERIZER_DISCARD);
    const auto setup = gl::check_error(fn, "transform feedback setup");
    REQUIRE_MESSAGE(setup.ok(), setup.error());

    // Tolerance: 2e-5 of the larger of 1 and the value's largest component
    // (about 170 float ulps), per output vector, GPU (llvmpipe, IEEE float,
    // its own normalize and division) against the C++ library in float.
    // Measured over 200 cases (see the MESSAGE): corners, centre and eye
    // bit-identical, planes and crop <= 1e-6, the eq. 36 clip 6.4e-6 (the
    // GPU divides by the denominators with its own reciprocal), world from
    // depth 4e-7.
    constexpr float kTolerance = 2e-5f;
    const char* names[kOutputs] = {"L", "R", "B", "T", "N", "F", "C1", "C2", "C3", "C4", "C5", "C6", "C7",
                                   "C8", "D", "O", "crop m0", "crop m1", "crop m2", "crop m3", "crop inv0",
                                   "crop inv1", "crop inv2", "crop inv3", "eq. 36 clip", "eq. 36 denominators",
                                   "world from depth"};
    std::vector<float> worst(kOutputs, 0.0f);
    std::mt19937 rng(20240601u);
    for (int n = 0; n < 200; ++n) {
        const Case c = random_case(rng);
        fn.UniformMatrix4fv(program.uniform("u_m"), 1, GL_FALSE, glm::value_ptr(c.pair.matrix()));
        fn.UniformMatrix4fv(program.uniform("u_inverse"), 1, GL_FALSE, glm::value_ptr(c.pair.inverse()));
        fn.Uniform1f(program.uniform("u_z_near"), frustum::clip_z_near<float>(c.pair.depth()));
        fn.Uniform1f(program.uniform("u_z_far"), frustum::clip_z_far<float>(c.pair.depth()));
        fn.Uniform4f(program.uniform("u_rect"), c.rect.x, c.rect.y, c.rect.width, c.rect.height);
        fn.Uniform2f(program.uniform("u_full"), c.rect.full_width, c.rect.full_height);
        glm::vec4 outward[6];
        for (int i = 0; i < 6; ++i) {
            outward[i] = c.outward.plane(i).abcd;
        }
        fn.Uniform4fv(program.uniform("u_outward"), 6, glm::value_ptr(outward[0]));
        fn.Uniform3f(program.uniform("u_point"), c.point.x, c.point.y, c.point.z);
        const glm::vec4 clip = c.pair.matrix() * glm::vec4(c.point, 1.0f);
        const float z_lo = std::min(frustum::clip_z_near<float>(c.pair.depth()), frustum::clip_z_far<float>(c.pair.depth()));
        const float window = (clip.z / clip.w - z_lo) / std::abs(frustum::clip_z_span<float>(c.pair.depth()));
        fn.Uniform3f(program.uniform("u_ndc_depth"), clip.x / clip.w, clip.y / clip.w, window);
        feedback.begin(GL_POINTS);
        fn.DrawArrays(GL_POINTS, 0, kOutputs);
        feedback.end();
        const auto drawn = gl::check_error(fn, "transform feedback draw");
        REQUIRE_MESSAGE(drawn.ok(), drawn.error());
        const auto* gpu = static_cast<const glm::vec4*>(
            feedback.map(GL_TRANSFORM_FEEDBACK_BUFFER, 0, kOutputs * sizeof(glm::vec4), GL_MAP_READ_BIT));
        REQUIRE(gpu != nullptr);
        const std::vector<glm::vec4> cpu = expected(c);
        for (int i = 0; i < kOutputs; ++i) {
            const float e = relative_error(gpu[i], cpu[static_cast<std::size_t>(i)]);
            worst[static_cast<std::size_t>(i)] = std::max(worst[static_cast<std::size_t>(i)], e);
            INFO("case " << n << ", " << std::string(names[i]) << ": gpu " << gpu[i].x << " " << gpu[i].y << " "
                          << gpu[i].z << " " << gpu[i].w);
            CHECK(e <= kTolerance);
        }
        feedback.unmap(GL_TRANSFORM_FEEDBACK_BUFFER);
    }
    fn.Disable(GL_RASTERIZER_DISCARD);
    fn.BindVertexArray(0);
    REQUIRE(gl::check_error(fn, "twins").ok());
    std::ostringstream summary;
    for (int i = 0; i < kOutputs; ++i) {
        summary << names[i] << " " << worst[static_cast<std::size_t>(i)] << (i + 1 < kOutputs ? ", " : "");
    }
    MESSAGE("worst relative error per output: " << summary.str());
}

} // TEST_SUITE
