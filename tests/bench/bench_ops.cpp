// Speed of the analytic matrix-pair updates (paper §5.1-5.3) against the
// baseline "build the new matrix + glm::inverse", side by side in one run,
// in float. Each iteration walks a ring of 1024 random cases so the branch
// predictor and cache see realistic variety.
//
//   bench_ops --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "random_cases.hpp"
#include "reinvert.hpp"

#include <benchmark/benchmark.h>

namespace {

using frustum::DepthRange;
using frustum::MatrixPair;
using frustum::Plane;

constexpr int ring_size = 1024;

struct FloatCase {
    MatrixPair<float> camera;
    bench::RawPair<float> raw_camera;
    Plane<float> plane; // unit; the eye is on its positive side
    frustum::Rectangle<float> rectangle;
    glm::vec3 eye;
};

const std::vector<FloatCase>& cases() {
    static const std::vector<FloatCase> ring = [] {
        std::vector<FloatCase> out;
        for (const auto& c : bench::make_mirror_cases(ring_size, DepthRange::ZeroToOne, 99u)) {
            const auto camera = c.camera.cast<float>();
            out.push_back(FloatCase{camera, bench::raw(camera),
                                    Plane<float>(glm::vec4(c.mirror_plane.normalized().abcd)),
                                    {glm::vec3(c.rectangle.corner), glm::vec3(c.rectangle.a1), glm::vec3(c.rectangle.a2)},
                                    glm::vec3(c.eye)});
        }
        return out;
    }();
    return ring;
}

const frustum::CropRect<float> crop_rect{100, 50, 320, 180, 1280, 720};

template <class F>
void run(benchmark::State& state, F&& op) {
    const auto& ring = cases();
    std::size_t i = 0;
    for (auto _ : state) {
        auto result = op(ring[i]);
        benchmark::DoNotOptimize(result);
        i = (i + 1) % ring.size();
    }
}

void Crop_Analytic(benchmark::State& s) { run(s, [](const FloatCase& c) { return frustum::crop(c.camera, crop_rect); }); }
void Crop_Reinvert(benchmark::State& s) { run(s, [](const FloatCase& c) { return bench::crop_reinvert(c.raw_camera, crop_rect); }); }
void Reflect_Analytic(benchmark::State& s) { run(s, [](const FloatCase& c) { return frustum::reflect(c.camera, c.plane); }); }
void Reflect_Reinvert(benchmark::State& s) { run(s, [](const FloatCase& c) { return bench::reflect_reinvert(c.raw_camera, c.plane); }); }
void Clip_Analytic(benchmark::State& s) {
    run(s, [](const FloatCase& c) { return frustum::clip_oblique(c.camera, c.plane.flipped()); });
}
void Clip_Reinvert(benchmark::State& s) {
    run(s, [](const FloatCase& c) { return bench::clip_reinvert(c.raw_camera, c.plane.flipped(), DepthRange::ZeroToOne); });
}
void Mirror_Analytic(benchmark::State& s) { run(s, [](const FloatCase& c) { return frustum::mirror(c.camera, c.plane); }); }
void Mirror_Reinvert(benchmark::State& s) {
    run(s, [](const FloatCase& c) { return bench::mirror_reinvert(c.raw_camera, c.plane, DepthRange::ZeroToOne); });
}
void MirrorRectangle_Analytic(benchmark::State& s) {
    run(s, [](const FloatCase& c) {
        return frustum::mirror_rectangle(c.rectangle, c.eye, 100.0f, frustum::MirrorFit::Exact, DepthRange::ZeroToOne);
    });
}
// The same construction, then glm::inverse of its matrix (this also pays for
// the closed-form inverse it discards, a few multiplies: the ratio is a
// slight overestimate of the saving).
void MirrorRectangle_Reinvert(benchmark::State& s) {
    run(s, [](const FloatCase& c) {
        const auto pair = frustum::mirror_rectangle(c.rectangle, c.eye, 100.0f, frustum::MirrorFit::Exact,
                                                    DepthRange::ZeroToOne);
        return glm::inverse(pair->matrix());
    });
}

const Plane<float> tilt_a = Plane<float>(0.6f, 0.8f, 0.0f, -1.0f);
const Plane<float> tilt_b = Plane<float>(0.0f, 0.28f, 0.96f, 2.0f);
const frustum::CropRect<float> chain_rect{0.1f, 0.2f, 0.8f, 0.7f, 1.0f, 1.0f};

// mirror, then crop and reflect alternating: 16 operations, both matrices
// kept current after every step.
void Chain16_Analytic(benchmark::State& s) {
    run(s, [](const FloatCase& c) {
        MatrixPair<float> p = *frustum::mirror(c.camera, c.plane);
        for (int i = 0; i < 15; ++i) {
            p = (i % 2 == 0) ? *frustum::crop(p, chain_rect) : *frustum::reflect(p, i % 4 == 1 ? tilt_a : tilt_b);
        }
        return p;
    });
}
void Chain16_Reinvert(benchmark::State& s) {
    run(s, [](const FloatCase& c) {
        bench::RawPair<float> p = bench::mirror_reinvert(c.raw_camera, c.plane, DepthRange::ZeroToOne);
        for (int i = 0; i < 15; ++i) {
            p = (i % 2 == 0) ? bench::crop_reinvert(p, chain_rect) : bench::reflect_reinvert(p, i % 4 == 1 ? tilt_a : tilt_b);
        }
        return p;
    });
}
// Diagnostic: the analytic clip formulas alone, no checks, no Result.
void Clip_RawMath(benchmark::State& s) {
    run(s, [](const FloatCase& c) {
        const auto& inv = c.raw_camera.inverse;
        const glm::vec4 p = -c.plane.abcd;
        const glm::vec4 cc(glm::dot(p, inv[0]), glm::dot(p, inv[1]), glm::dot(p, inv[2]), glm::dot(p, inv[3]));
        const glm::vec4 q(cc.x >= 0 ? 1.f : -1.f, cc.y >= 0 ? 1.f : -1.f, 1.f, 1.f);
        const float k = 1.0f / glm::dot(cc, q);
        bench::RawPair<float> out = c.raw_camera;
        for (int j = 0; j < 4; ++j) out.matrix[j].z = k * p[j];
        const float inv_x2 = 1.0f / (k * cc.z);
        out.inverse[0] = inv[0] - (k * cc.x * inv_x2) * inv[2];
        out.inverse[1] = inv[1] - (k * cc.y * inv_x2) * inv[2];
        out.inverse[3] = inv[3] - (k * cc.w * inv_x2) * inv[2];
        out.inverse[2] = inv[2] * inv_x2;
        return out;
    });
}
// The harness and the Result wrapper alone: copy a pair into a Result.
void CopyPair_Only(benchmark::State& s) {
    run(s, [](const FloatCase& c) { return frustum::Result<MatrixPair<float>>(c.camera); });
}
// Baseline of the baseline: glm::inverse alone.
void GlmInverse_Only(benchmark::State& s) { run(s, [](const FloatCase& c) { return glm::inverse(c.raw_camera.matrix); }); }

} // namespace

BENCHMARK(Crop_Analytic);
BENCHMARK(Crop_Reinvert);
BENCHMARK(Reflect_Analytic);
BENCHMARK(Reflect_Reinvert);
BENCHMARK(Clip_Analytic);
BENCHMARK(Clip_Reinvert);
BENCHMARK(Mirror_Analytic);
BENCHMARK(Mirror_Reinvert);
BENCHMARK(MirrorRectangle_Analytic);
BENCHMARK(MirrorRectangle_Reinvert);
BENCHMARK(Chain16_Analytic);
BENCHMARK(Chain16_Reinvert);
BENCHMARK(GlmInverse_Only);
BENCHMARK(CopyPair_Only);
BENCHMARK(Clip_RawMath);
BENCHMARK_MAIN();
