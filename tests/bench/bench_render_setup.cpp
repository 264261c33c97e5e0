#include "bench_render_setup.hpp"

#include <frustum/projection.hpp>
#include <scene/load_gltf.hpp>

#include <cmath>
#include <stdexcept>

namespace bench_render {
namespace {

constexpr GLenum kSamplesPassed = 0x8914;              // GL_SAMPLES_PASSED (desktop GL)
constexpr GLenum kFragmentShaderInvocations = 0x82F4; // GL_FRAGMENT_SHADER_INVOCATIONS_ARB

template <class T>
T value_or_throw(frustum::Result<T> result, const char* what) {
    if (!result) {
        throw std::runtime_error(std::string(what) + ": " + result.error());
    }
    return std::move(*result);
}

const scene::Camera& main_scene_camera() {
    const scene::Scene& s = showcase();
    const int index = value_or_throw(plan::find_camera(s, std::nullopt), "main camera");
    if (index < 0) {
        throw std::runtime_error("the showcase has no camera");
    }
    return s.cameras[static_cast<std::size_t>(index)];
}

const scene::MirrorRect& mirror() {
    if (!showcase().mirror) {
        throw std::runtime_error("the showcase has no mirror");
    }
    return *showcase().mirror;
}

glm::vec3 mirror_centre() { return mirror().corner + 0.5f * (mirror().a1 + mirror().a2); }

double coverage_at(float distance_m, plan::PixelRect* rect_out) {
    const auto rect = plan::mirror_screen_rect(mirror(), camera_at_distance(distance_m), kWidthPx, kHeightPx);
    if (!rect) {
        return 0.0;
    }
    if (rect_out) {
        *rect_out = *rect;
    }
    return double(rect->width) * rect->height / (double(kWidthPx) * kHeightPx);
}

} // namespace

const scene::Scene& showcase() {
    static const scene::Scene loaded =
        value_or_throw(scene::load_gltf(std::string(FRUSTUM_SOURCE_DIR) + "/assets/showcase.gltf"), "showcase");
    return loaded;
}

frustum::MatrixPair<float> main_camera() {
    const auto cameras = value_or_throw(
        plan::make_cameras(showcase(), value_or_throw(plan::find_camera(showcase(), std::nullopt), "camera"),
                           kWidthPx, kHeightPx),
        "cameras");
    return cameras.main.pair;
}

frustum::MatrixPair<float> camera_at_distance(float distance_m) {
    const scene::Camera& c = main_scene_camera();
    const glm::vec3 eye0(c.camera_to_world[3]);
    const glm::vec3 centre = mirror_centre();
    const glm::vec3 eye = centre + distance_m * glm::normalize(eye0 - centre);
    const auto projection = value_or_throw(
        frustum::perspective<float>(c.yfov_rad, float(kWidthPx) / kHeightPx, c.znear_m, c.zfar_m,
                                    frustum::DepthRange::ZeroToOne),
        "perspective");
    const auto view = value_or_throw(frustum::look_at<float>(eye, centre, glm::vec3(0, 1, 0)), "look_at");
    return frustum::compose(projection, view);
}

MirrorCase make_mirror_case(const std::string& label, double fraction) {
    // Coverage falls with distance: bisect in log distance.
    float near_m = 0.3f, far_m = 90.0f;
    if (!(coverage_at(near_m, nullptr) >= 1.0) || !(coverage_at(far_m, nullptr) < fraction)) {
        throw std::runtime_error("mirror coverage is not bracketed");
    }
    for (int i = 0; i < 60; ++i) {
        const float mid = std::sqrt(near_m * far_m);
        // For fraction 1 find where the rectangle stops filling the frame.
        const bool too_close = fraction >= 1.0 ? coverage_at(mid, nullptr) >= 1.0 : coverage_at(mid, nullptr) > fraction;
        (too_close ? near_m : far_m) = mid;
    }
    // 1/1: 10% closer than the last distance at which it fills the frame.
    const float distance_m = fraction >= 1.0 ? 0.9f * near_m : near_m;
    MirrorCase out{label, fraction, distance_m, camera_at_distance(distance_m), {}, 0.0, plan::mirror_plane(mirror())};
    out.coverage = coverage_at(distance_m, &out.rect);
    return out;
}

render::LensDraw lens_draw(int grid) {
    const auto camera = main_camera();
    const auto lens = value_or_throw(render::lens_on_near_plane(camera, showcase().lens, 2.0f), "lens");
    return render::LensDraw{camera, lens, grid, showcase().lens ? showcase().lens->instance : -1};
}

std::unique_ptr<Gpu> make_gpu(gl::Backend backend, std::string& why) {
    auto context = gl::create_offscreen_context(backend, {});
    if (!context) {
        why = context.error();
        return nullptr;
    }
    auto gpu = std::make_unique<Gpu>();
    gpu->context = std::move(*context);
    gpu->fn = std::make_unique<gl::Functions>(value_or_throw(gl::Functions::load(*gpu->context), "gl::Functions"));
    gpu->renderer.emplace(
        value_or_throw(render::Renderer::create(*gpu->context, *gpu->fn, showcase()), "render::Renderer"));
    gpu->depth.emplace(value_or_throw(
        render::DepthPolicy::apply(*gpu->fn, *gpu->context, render::DepthPath::ClipControlWhenAvailable),
        "render::DepthPolicy"));
    return gpu;
}

FragmentCounts count_fragments(const Gpu& gpu, const std::function<void(bool count_all)>& draw) {
    FragmentCounts counts;
    if (gpu.context->api() != gl::Api::GlCore) {
        return counts; // GLES has only the boolean GL_ANY_SAMPLES_PASSED
    }
    const gl::Functions& fn = *gpu.fn;
    const bool statistics = gpu.context->has_extension("GL_ARB_pipeline_statistics_query");
    auto samples = value_or_throw(gl::Query::create(fn), "gl::Query");
    auto invocations = value_or_throw(gl::Query::create(fn), "gl::Query");
    const auto result = [&](const gl::Query& q) {
        GLuint value = 0;
        fn.GetQueryObjectuiv(q.id(), GL_QUERY_RESULT, &value);
        return static_cast<std::int64_t>(value);
    };
    // The real pass.
    fn.BeginQuery(kSamplesPassed, samples.id());
    if (statistics) {
        fn.BeginQuery(kFragmentShaderInvocations, invocations.id());
    }
    draw(false);
    fn.EndQuery(kSamplesPassed);
    if (statistics) {
        fn.EndQuery(kFragmentShaderInvocations);
        counts.fs_invocations = result(invocations);
    }
    counts.written = result(samples);
    // Every rasterized fragment.
    fn.BeginQuery(kSamplesPassed, samples.id());
    draw(true);
    fn.EndQuery(kSamplesPassed);
    counts.rasterized = result(samples);
    fn.DepthFunc(GL_LESS);
    fn.DepthMask(GL_TRUE);
    return counts;
}

} // namespace bench_render
