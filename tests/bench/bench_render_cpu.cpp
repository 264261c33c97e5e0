// CPU side of a frame: every matrix-pair update the renderer makes per frame
// (camera, mirror, crop to the mirror's rectangle, 4x4 tiles), analytic
// versus the same matrices inverted with glm::inverse; and frustum::lens_tiles.
#include "bench_render_cpu.hpp"

#include "bench_render_setup.hpp"
#include "reinvert.hpp"

#include <frustum/crop.hpp>
#include <frustum/lens.hpp>
#include <frustum/mirror.hpp>
#include <frustum/projection.hpp>

#include <benchmark/benchmark.h>
#include <glm/gtc/matrix_transform.hpp>

#include <random>
#include <vector>

namespace bench_render {
namespace {

constexpr int kRing = 256;
constexpr int kTiles = 4; // 4 x 4 tiles per frame

struct FrameInput {
    glm::vec3 eye, target;
    frustum::CropRect<float> mirror_rect;
};

struct Lens {
    float fovy_rad, aspect, near_m, far_m;
};

struct CpuCases {
    Lens lens;
    frustum::Plane<float> plane;
    std::vector<FrameInput> frames;
};

// Eyes jittered by up to 0.5 m around the main camera's, looking at the
// mirror's centre, so each frame updates every pair from new inputs.
const CpuCases& cases() {
    static const CpuCases c = [] {
        const scene::Scene& s = showcase();
        const auto index = render::find_camera(s, std::nullopt);
        const scene::Camera& cam = s.cameras[static_cast<std::size_t>(*index)];
        const scene::MirrorRect& m = *s.mirror;
        CpuCases out{{cam.yfov_rad, float(kWidthPx) / kHeightPx, cam.znear_m, cam.zfar_m.value_or(100.0f)},
                     render::mirror_plane(m).normalized(),
                     {}};
        std::mt19937 rng(7u);
        std::uniform_real_distribution<float> jitter(-0.5f, 0.5f);
        const glm::vec3 eye0(cam.camera_to_world[3]);
        const glm::vec3 target = m.corner + 0.5f * (m.a1 + m.a2);
        for (int i = 0; i < kRing; ++i) {
            const float dz = jitter(rng), dy = jitter(rng), dx = jitter(rng); // one draw each, z first (as always)
            const glm::vec3 eye = eye0 + glm::vec3(dx, dy, dz);
            const auto projection = frustum::perspective<float>(out.lens.fovy_rad, out.lens.aspect, out.lens.near_m,
                                                                out.lens.far_m, frustum::DepthRange::ZeroToOne);
            const auto camera = frustum::compose(*projection, *frustum::look_at<float>(eye, target, {0, 1, 0}));
            const auto rect = render::mirror_screen_rect(m, camera, kWidthPx, kHeightPx);
            out.frames.push_back({eye, target,
                                  {float(rect->x), float(rect->y), float(rect->width), float(rect->height),
                                   float(kWidthPx), float(kHeightPx)}});
        }
        return out;
    }();
    return c;
}

struct AnalyticFrame {
    frustum::MatrixPair<float> camera, mirror, tight;
    std::vector<frustum::Tile<float>> tiles;
};

AnalyticFrame analytic_frame(const CpuCases& c, const FrameInput& in) {
    const auto projection =
        frustum::perspective<float>(c.lens.fovy_rad, c.lens.aspect, c.lens.near_m, c.lens.far_m,
                                    frustum::DepthRange::ZeroToOne);
    const auto camera = frustum::compose(*projection, *frustum::look_at<float>(in.eye, in.target, {0, 1, 0}));
    const auto mirror = frustum::mirror(camera, c.plane);
    const auto tight = frustum::crop(*mirror, in.mirror_rect);
    auto tiles = frustum::crop_tiles(camera, kWidthPx, kHeightPx, kTiles, kTiles);
    return {camera, *mirror, *tight, std::move(*tiles)};
}

struct ReinvertFrame {
    bench::RawPair<float> camera, mirror, tight;
    std::vector<bench::RawPair<float>> tiles;
};

// The same matrices built forward with GLM and each inverted with glm::inverse.
ReinvertFrame reinvert_frame(const CpuCases& c, const FrameInput& in) {
    const glm::mat4 m = glm::perspectiveRH_ZO(c.lens.fovy_rad, c.lens.aspect, c.lens.near_m, c.lens.far_m) *
                        glm::lookAtRH(in.eye, in.target, glm::vec3(0, 1, 0));
    ReinvertFrame out;
    out.camera = {m, glm::inverse(m)};
    out.mirror = bench::mirror_reinvert(out.camera, c.plane, frustum::DepthRange::ZeroToOne);
    out.tight = bench::crop_reinvert(out.mirror, in.mirror_rect);
    out.tiles.reserve(kTiles * kTiles);
    for (int row = 0; row < kTiles; ++row) {
        for (int column = 0; column < kTiles; ++column) {
            const int x0 = column * kWidthPx / kTiles, x1 = (column + 1) * kWidthPx / kTiles;
            const int y0 = row * kHeightPx / kTiles, y1 = (row + 1) * kHeightPx / kTiles;
            out.tiles.push_back(bench::crop_reinvert(
                out.camera, frustum::CropRect<float>{float(x0), float(y0), float(x1 - x0), float(y1 - y0),
                                                     float(kWidthPx), float(kHeightPx)}));
        }
    }
    return out;
}

template <class F>
void run_ring(benchmark::State& state, F&& frame) {
    const CpuCases& c = cases();
    std::size_t i = 0;
    for (auto _ : state) {
        auto result = frame(c, c.frames[i]);
        benchmark::DoNotOptimize(result);
        i = (i + 1) % c.frames.size();
    }
}

} // namespace

void register_cpu_benchmarks() {
    benchmark::RegisterBenchmark("cpu/frame_updates/analytic",
                                 [](benchmark::State& s) { run_ring(s, analytic_frame); })
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("cpu/frame_updates/glm_inverse",
                                 [](benchmark::State& s) { run_ring(s, reinvert_frame); })
        ->Unit(benchmark::kMicrosecond);
    for (int n : kLensTileCounts) {
        const std::string nn = std::to_string(n) + "x" + std::to_string(n);
        benchmark::RegisterBenchmark(("cpu/lens_tiles/" + nn).c_str(),
                                     [n](benchmark::State& s) {
                                         const render::LensDraw draw = lens_draw(n);
                                         for (auto _ : s) {
                                             auto tiles = frustum::lens_tiles(draw.camera, draw.lens, kWidthPx,
                                                                              kHeightPx, n, n);
                                             benchmark::DoNotOptimize(tiles);
                                         }
                                     })
            ->Unit(benchmark::kMicrosecond);
    }
}

} // namespace bench_render
