// CPU side of a frame: every matrix-pair update the renderer makes per frame
// (camera, mirror, crop to the mirror's rectangle, 4x4 tiles), analytic
// versus the same matrices inverted with glm::inverse; and frustum::lens_tiles.
#include "bench_render_cpu.hpp"

#include "bench_render_setup.hpp"
#include "reinvert.hpp"

#include <frustum/crop.hpp>
#include <frustum/detail/tolerances.hpp>
#include <frustum/lens.hpp>
#include <frustum/queries.hpp>
#include <frustum/volume_approximation.hpp>
#include <plan/curved_mirror.hpp>
#include <frustum/mirror.hpp>
#include <frustum/projection.hpp>

#include <benchmark/benchmark.h>
#include <glm/gtc/matrix_transform.hpp>

#include <map>
#include <optional>
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
        const auto index = plan::find_camera(s, std::nullopt);
        const scene::Camera& cam = s.cameras[static_cast<std::size_t>(*index)];
        const scene::MirrorRect& m = *s.mirror;
        CpuCases out{{cam.yfov_rad, float(kWidthPx) / kHeightPx, cam.znear_m, cam.zfar_m.value_or(100.0f)},
                     plan::mirror_plane(m).normalized(),
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
            const auto rect = plan::mirror_screen_rect(m, camera, kWidthPx, kHeightPx);
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

// The curved mirror's fits (docs/curved-mirror.md): the showcase's sphere
// cap, sagitta 0.3 m, seen from the main camera; every patch's target built
// once, outside the timed loop.
struct CurvedCase {
    std::vector<frustum::VolumeTarget<double>> targets; // index j * G + i
    double far_m = 1.0;
};
const CurvedCase& curved_case(int grid) {
    static std::map<int, CurvedCase> cases;
    auto found = cases.find(grid);
    if (found != cases.end()) {
        return found->second;
    }
    const auto mirror = plan::CurvedMirror::create(*showcase().mirror, plan::CapShape::Sphere, 0.3);
    const auto eye = frustum::eye_point(main_camera());
    CurvedCase c;
    c.far_m = std::max(glm::length(glm::dvec3(showcase().world_bounds.max - showcase().world_bounds.min)), 1.0);
    for (int j = 0; j < grid; ++j) {
        for (int i = 0; i < grid; ++i) {
            c.targets.push_back(plan::patch_target(*mirror, glm::dvec3(*eye), grid, i, j));
        }
    }
    return cases.emplace(grid, std::move(c)).first->second;
}

// fit_volume() before issue 34, kept here as the baseline: gradient ascent
// with backtracking (Armijo) from the paper's start, the step doubled after
// each gain, at most 200 steps (its default), then the same frustum.
frustum::Result<frustum::VolumeFit<double>> former_fit(const frustum::VolumeTarget<double>& target, double far_m) {
    const auto start = frustum::fit_volume(target, far_m, frustum::DepthRange::ZeroToOne, 0); // the paper's start
    if (!start) {
        return start;
    }
    const frustum::Plane<double> near = target.near.normalized();
    glm::dvec3 origin = start->origin, gradient;
    double value = frustum::volume_objective(target, origin, &gradient), step = 1.0;
    int iterations = 0;
    for (; iterations < 200; ++iterations) {
        const double g2 = glm::dot(gradient, gradient);
        if (!(g2 > 0.0)) break;
        bool improved = false;
        for (int halvings = 0; halvings < 60; ++halvings) {
            const glm::dvec3 candidate = origin + step * gradient;
            glm::dvec3 g;
            const double v = frustum::volume_objective(target, candidate, &g);
            if (near.distance(candidate) < 0.0 &&
                v >= value + frustum::detail::sufficient_increase<double>() * step * g2) {
                improved = v - value > 1e-10;
                origin = candidate, value = v, gradient = g, step *= 2.0;
                break;
            }
            step /= 2.0;
        }
        if (!improved) break;
    }
    // The frustum through the ascent's origin: fit_volume() from there, 0 solves.
    auto fit = frustum::fit_volume(target, far_m, frustum::DepthRange::ZeroToOne, 0, 1e-10,
                                   std::optional<glm::dvec3>(origin));
    if (fit) {
        fit->iterations = iterations;
    }
    return fit;
}

// Every patch of a G x G cap: Newton (warm-started from the left or lower
// neighbour, as plan::plan_curved_mirror does) or the former ascent.
void curved_fits(benchmark::State& state, int grid, bool newton) {
    const CurvedCase& c = curved_case(grid);
    std::vector<std::optional<glm::dvec3>> origins(c.targets.size());
    double steps = 0.0, objective = 0.0;
    std::int64_t fits = 0;
    for (auto _ : state) {
        for (int j = 0; j < grid; ++j) {
            for (int i = 0; i < grid; ++i) {
                const std::size_t k = static_cast<std::size_t>(j * grid + i);
                std::optional<glm::dvec3> warm;
                if (i > 0) warm = origins[k - 1];
                else if (j > 0) warm = origins[k - static_cast<std::size_t>(grid)];
                auto fit = newton ? frustum::fit_volume(c.targets[k], c.far_m, frustum::DepthRange::ZeroToOne, 50,
                                                        1e-10, warm)
                                  : former_fit(c.targets[k], c.far_m);
                origins[k] = fit ? std::optional<glm::dvec3>(fit->origin) : std::nullopt;
                if (fit) {
                    steps += fit->iterations;
                    objective += fit->objective;
                    ++fits;
                }
                benchmark::DoNotOptimize(fit);
            }
        }
    }
    state.counters["steps"] = steps / static_cast<double>(std::max<std::int64_t>(fits, 1));
    state.counters["F_mean"] = objective / static_cast<double>(std::max<std::int64_t>(fits, 1));
    state.counters["per_patch_us"] = benchmark::Counter(static_cast<double>(state.iterations()) * grid * grid,
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
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
        // The renderer's lens frame (render::draw_lens_frame's CPU part: the
        // vector of tiles it draws from; no per-tile refit since the library
        // hands each tile its far plane) next to the grid form alone.
        benchmark::RegisterBenchmark(("cpu/lens_tiles_grid/" + nn).c_str(),
                                     [n](benchmark::State& s) {
                                         const render::LensDraw draw = lens_draw(n);
                                         frustum::TileGrid<float> grid;
                                         for (auto _ : s) {
                                             auto status = frustum::lens_tiles(draw.camera, draw.lens, kWidthPx,
                                                                               kHeightPx, n, n, grid);
                                             benchmark::DoNotOptimize(status);
                                             benchmark::ClobberMemory();
                                         }
                                     })
            ->Unit(benchmark::kMicrosecond);
    }
    for (int g : {4, 16}) {
        const std::string gg = std::to_string(g) + "x" + std::to_string(g);
        benchmark::RegisterBenchmark(("cpu/curved_fits/newton/" + gg).c_str(),
                                     [g](benchmark::State& s) { curved_fits(s, g, true); })
            ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark(("cpu/curved_fits/former_ascent/" + gg).c_str(),
                                     [g](benchmark::State& s) { curved_fits(s, g, false); })
            ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark(("cpu/curved_plan/" + gg).c_str(),
                                     [g](benchmark::State& s) {
                                         const auto mirror = plan::CurvedMirror::create(
                                             *showcase().mirror, plan::CapShape::Sphere, 0.3);
                                         const auto eye = frustum::eye_point(main_camera());
                                         for (auto _ : s) {
                                             auto plan = plan::plan_curved_mirror(*mirror, glm::dvec3(*eye),
                                                                                  showcase().world_bounds, g);
                                             benchmark::DoNotOptimize(plan);
                                         }
                                     })
            ->Unit(benchmark::kMicrosecond);
    }
}

} // namespace bench_render
