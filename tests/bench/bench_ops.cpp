// Speed of the analytic matrix-pair updates (paper §5.1-5.4) against two
// baselines, side by side in one run: "build the new matrix + glm::inverse"
// and "build the new matrix + Eigen's Matrix4 inverse", in float and in
// double. Each iteration walks a ring of 1024 random cases (camera, mirror
// plane, rectangle, crop rectangle) so that branch predictor and cache see
// realistic variety and nothing folds to a constant; the ring index wraps
// with a power-of-two mask (a `%` costs a 64-bit division per call).
//
//   bench_ops --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// Batched benchmarks (crop_tiles, lens_tiles) report `per_tile`: seconds per
// tile (Google Benchmark prints it in ns when it is small enough).
#include "eigen_inverse.hpp"
#include "random_cases.hpp"
#include "reinvert.hpp"

#include <frustum/detail/from_planes_points.hpp>
#include <frustum/detail/lens_matrices.hpp>
#include <frustum/detail/plane_intersection.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <iterator>

namespace {

using frustum::CropRect;
using frustum::DepthRange;
using frustum::MatrixPair;
using frustum::Plane;

constexpr std::size_t ring_size = 1024; // a power of two: see `ring_mask`
constexpr std::size_t ring_mask = ring_size - 1;
static_assert((ring_size & ring_mask) == 0, "ring_size must be a power of two");

template <class T>
struct Case {
    MatrixPair<T> camera;
    bench::RawPair<T> raw_camera;
    Plane<T> plane;      // unit; the eye is on its positive side
    Plane<T> clip_plane; // the same plane flipped: the eye on its negative side (flipped once, not per call)
    frustum::Rectangle<T> rectangle;
    frustum::Vec3<T> eye;
    CropRect<T> crop;       // a random sub-rectangle of a 1280 x 720 image
    CropRect<T> chain_crop; // the same in a unit image (repeated crops stay sane)
};

// A random rectangle inside a 1280 x 720 image, whole pixels.
CropRect<double> random_rect(std::uint32_t& state) {
    const auto next = [&state](int range) {
        state = state * 1664525u + 1013904223u;
        return static_cast<int>((state >> 8) % static_cast<std::uint32_t>(range));
    };
    const double width = 160 + next(800), height = 90 + next(500);
    const double x = next(static_cast<int>(1280 - width)), y = next(static_cast<int>(720 - height));
    return {x, y, width, height, 1280, 720};
}

// The depth ranges a benchmark's second argument names (LensTiles_Grid).
constexpr DepthRange depth_ranges[] = {DepthRange::ZeroToOne, DepthRange::MinusOneToOne,
                                       DepthRange::ReversedZeroToOne};

template <class T>
std::vector<Case<T>> make_ring(DepthRange depth) {
    std::vector<Case<T>> out;
    std::uint32_t state = 7u;
    for (const auto& c : bench::make_mirror_cases(static_cast<int>(ring_size), depth, 99u)) {
        const auto camera = c.camera.template cast<T>();
        const CropRect<double> r = random_rect(state);
        const CropRect<T> crop{T(r.x), T(r.y), T(r.width), T(r.height), T(r.full_width), T(r.full_height)};
        // A milder crop for the chain: the middle 80-95% of the image.
        const CropRect<T> chain{T(r.x / 1280 * 0.1), T(r.y / 720 * 0.1), T(0.8 + r.width / 1280 * 0.1),
                                T(0.8 + r.height / 720 * 0.1), T(1), T(1)};
        const Plane<T> plane(frustum::Vec4<T>(c.mirror_plane.normalized().abcd));
        out.push_back(Case<T>{camera, bench::raw(camera), plane, plane.flipped(),
                              {frustum::Vec3<T>(c.rectangle.corner), frustum::Vec3<T>(c.rectangle.a1),
                               frustum::Vec3<T>(c.rectangle.a2)},
                              frustum::Vec3<T>(c.eye), crop, chain});
    }
    return out;
}

// The cameras of `depth` (zero_to_one unless a benchmark names another),
// each ring made when a benchmark first asks for it.
template <class T>
const std::vector<Case<T>>& cases(DepthRange depth = DepthRange::ZeroToOne) {
    static std::vector<Case<T>> rings[std::size(depth_ranges)];
    std::vector<Case<T>>& ring = rings[std::find(std::begin(depth_ranges), std::end(depth_ranges), depth) -
                                       std::begin(depth_ranges)];
    if (ring.empty()) {
        ring = make_ring<T>(depth);
    }
    return ring;
}

template <class T, class F>
void run(benchmark::State& state, F&& op, DepthRange depth = DepthRange::ZeroToOne) {
    const auto& ring = cases<T>(depth);
    std::size_t i = 0;
    for (auto _ : state) {
        auto result = op(ring[i]);
        benchmark::DoNotOptimize(result);
        i = (i + 1) & ring_mask;
    }
}

// ---- single operations: analytic, + glm::inverse, + Eigen inverse ----

template <class T, class Inverse>
void crop_reinvert(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) { return bench::crop_reinvert(c.raw_camera, c.crop, Inverse{}); });
}
template <class T, class Inverse>
void reflect_reinvert(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) { return bench::reflect_reinvert(c.raw_camera, c.plane, Inverse{}); });
}
template <class T, class Inverse>
void clip_reinvert(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) {
        return bench::clip_reinvert(c.raw_camera, c.clip_plane, DepthRange::ZeroToOne, Inverse{});
    });
}
template <class T, class Inverse>
void mirror_reinvert(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) {
        return bench::mirror_reinvert(c.raw_camera, c.plane, DepthRange::ZeroToOne, Inverse{});
    });
}

template <class T>
void Crop_Analytic(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) { return frustum::crop(c.camera, c.crop); });
}
template <class T>
void Reflect_Analytic(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) { return frustum::reflect(c.camera, c.plane); });
}
template <class T>
void Clip_Analytic(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) { return frustum::clip_oblique(c.camera, c.clip_plane); });
}
template <class T>
void Mirror_Analytic(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) { return frustum::mirror(c.camera, c.plane); });
}
template <class T>
void MirrorRectangle_Analytic(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) {
        return frustum::mirror_rectangle(c.rectangle, c.eye, T(100), frustum::MirrorFit::Exact, DepthRange::ZeroToOne);
    });
}
// The same construction, then the baseline's inverse of its matrix (this
// also pays for the closed-form inverse it discards, a few multiplies: the
// ratio is a slight overestimate of the saving).
template <class T, class Inverse>
void mirror_rectangle_reinvert(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) {
        const auto pair = frustum::mirror_rectangle(c.rectangle, c.eye, T(100), frustum::MirrorFit::Exact,
                                                    DepthRange::ZeroToOne);
        return Inverse{}(pair->matrix());
    });
}

const Plane<double> tilt_a(0.6, 0.8, 0.0, -1.0);
const Plane<double> tilt_b(0.0, 0.28, 0.96, 2.0);

// mirror, then crop and reflect alternating: 16 operations, both matrices
// kept current after every step.
template <class T>
void Chain16_Analytic(benchmark::State& s) {
    const Plane<T> a(frustum::Vec4<T>(tilt_a.abcd)), b(frustum::Vec4<T>(tilt_b.abcd));
    run<T>(s, [&](const Case<T>& c) {
        MatrixPair<T> p = *frustum::mirror(c.camera, c.plane);
        for (int i = 0; i < 15; ++i) {
            p = (i % 2 == 0) ? *frustum::crop(p, c.chain_crop) : *frustum::reflect(p, i % 4 == 1 ? a : b);
        }
        return p;
    });
}
template <class T, class Inverse>
void chain16_reinvert(benchmark::State& s) {
    const Plane<T> a(frustum::Vec4<T>(tilt_a.abcd)), b(frustum::Vec4<T>(tilt_b.abcd));
    run<T>(s, [&](const Case<T>& c) {
        bench::RawPair<T> p = bench::mirror_reinvert(c.raw_camera, c.plane, DepthRange::ZeroToOne, Inverse{});
        for (int i = 0; i < 15; ++i) {
            p = (i % 2 == 0) ? bench::crop_reinvert(p, c.chain_crop, Inverse{})
                             : bench::reflect_reinvert(p, i % 4 == 1 ? a : b, Inverse{});
        }
        return p;
    });
}

// ---- reference points ----

// The harness and the Result wrapper alone: copy a pair into a Result.
template <class T>
void CopyPair_Only(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) { return frustum::Result<MatrixPair<T>>(c.camera); });
}
template <class T, class Inverse>
void inverse_only(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) { return Inverse{}(c.raw_camera.matrix); });
}

// ---- batched: crop_tiles and lens_tiles, per tile ----

void per_tile(benchmark::State& s, int tiles) {
    s.counters["per_tile"] =
        benchmark::Counter(static_cast<double>(tiles), benchmark::Counter::kIsIterationInvariantRate |
                                                           benchmark::Counter::kInvert);
}

// All G x G tiles of a 1280 x 720 image.
template <class T>
void CropTiles_Analytic(benchmark::State& s) {
    const int g = static_cast<int>(s.range(0));
    run<T>(s, [g](const Case<T>& c) { return frustum::crop_tiles(c.camera, 1280, 720, g, g); });
    per_tile(s, g * g);
}
// The grid form: the same tiles written into one TileGrid kept across
// iterations (as a renderer keeps it from frame to frame: no allocation).
template <class T>
void CropTiles_Grid(benchmark::State& s) {
    const int g = static_cast<int>(s.range(0));
    frustum::TileGrid<T> grid;
    run<T>(s, [g, &grid](const Case<T>& c) {
        frustum::Status status = frustum::crop_tiles(c.camera, 1280, 720, g, g, grid);
        benchmark::ClobberMemory();
        return status.ok();
    });
    per_tile(s, g * g);
}
// Per tile: its crop rectangle, the new matrix (eq. 14), glm::inverse; the
// tiles go into a vector allocated once, like the grid's storage.
template <class T, class Inverse>
void crop_tiles_reinvert(benchmark::State& s) {
    const int g = static_cast<int>(s.range(0));
    std::vector<bench::RawPair<T>> out(static_cast<std::size_t>(g * g));
    run<T>(s, [g, &out](const Case<T>& c) {
        const auto edge = [](int i, int size, int count) { return (i * size) / count; };
        std::size_t t = 0;
        for (int r = 0; r < g; ++r) {
            const int y0 = edge(r, 720, g), y1 = edge(r + 1, 720, g);
            for (int col = 0; col < g; ++col) {
                const int x0 = edge(col, 1280, g), x1 = edge(col + 1, 1280, g);
                const CropRect<T> rect{T(x0), T(y0), T(x1 - x0), T(y1 - y0), T(1280), T(720)};
                out[t++] = bench::crop_reinvert(c.raw_camera, rect, Inverse{});
            }
        }
        benchmark::ClobberMemory();
        return out.data();
    });
    per_tile(s, g * g);
}

template <class T>
frustum::Lens<T> bench_lens() {
    frustum::Lens<T> lens;
    lens.center_m = frustum::Vec2<T>(T(0.01), T(-0.005));
    lens.radius_m = T(0.03);
    lens.power = T(1.5);
    return lens;
}
// The lens camera of the ring: the case camera (perspective, finite far).
template <class T>
void LensTiles_Analytic(benchmark::State& s) {
    const int g = static_cast<int>(s.range(0));
    const auto lens = bench_lens<T>();
    run<T>(s, [g, &lens](const Case<T>& c) { return frustum::lens_tiles(c.camera, lens, 1280, 720, g, g); });
    per_tile(s, g * g);
}
template <class T>
void LensTiles_Grid(benchmark::State& s) {
    const int g = static_cast<int>(s.range(0));
    const auto lens = bench_lens<T>();
    frustum::TileGrid<T> grid;
    run<T>(
        s,
        [g, &lens, &grid](const Case<T>& c) {
            frustum::Status status = frustum::lens_tiles(c.camera, lens, 1280, 720, g, g, grid);
            benchmark::ClobberMemory();
            return status.ok();
        },
        depth_ranges[s.range(1)]);
    per_tile(s, g * g);
}
// Per tile: its matrix built as lens_tiles builds it (the same shared
// corners, planes and far plane: detail::lens_tile_matrices), then inverted.
template <class T, class Inverse>
void lens_tiles_reinvert(benchmark::State& s) {
    const int g = static_cast<int>(s.range(0));
    const auto lens = bench_lens<T>();
    frustum::TileGrid<T> layout;
    std::vector<frustum::Mat4<T>> matrices;
    std::vector<frustum::Mat4<T>> inverses(static_cast<std::size_t>(g * g));
    run<T>(s, [g, &lens, &layout, &matrices, &inverses](const Case<T>& c) {
        const frustum::Status status =
            frustum::detail::lens_tile_matrices(c.camera, lens, 1280, 720, g, g, layout, matrices);
        for (std::size_t t = 0; t < matrices.size(); ++t) {
            inverses[t] = Inverse{}(matrices[t]);
        }
        benchmark::ClobberMemory();
        return status.ok();
    });
    per_tile(s, g * g);
}
// What a tile's analytic inverse costs inside lens_tiles (§4: rows to
// inverse by plane intersections) against inverting the same matrix: the
// baseline per tile is LensTiles_Analytic - InverseFromRows + GlmInverse.
template <class T>
void InverseFromRows_Only(benchmark::State& s) {
    run<T>(s, [](const Case<T>& c) { return frustum::detail::inverse_from_rows(c.raw_camera.matrix); });
}

} // namespace

// The baseline the lens tile had when issue 34 was filed (0.8x then): per
// tile, §4's construction of its matrix (detail::from_planes_matrix: the four
// side planes through the eye and two warped corners, normalized; Cramer's
// rule for the corners; the far plane through the far points), then
// glm::inverse. The grid's warped corners are shared (eq. 34 once per
// corner), as lens_tiles shares them.
template <class T>
void LensTiles_FromPlanesReinvert(benchmark::State& s) {
    const int g = static_cast<int>(s.range(0));
    const auto lens = bench_lens<T>();
    const std::size_t n = static_cast<std::size_t>(g) + 1;
    std::vector<frustum::Vec3<T>> corners(n * n);
    std::vector<frustum::Mat4<T>> inverses(static_cast<std::size_t>(g * g));
    run<T>(s, [&](const Case<T>& c) {
        const auto frame = frustum::near_plane_frame(c.camera);
        const auto near = frustum::raw_planes(c.camera).near;
        const auto far = frustum::far_distance(c.camera);
        const auto near_m = frustum::near_distance(c.camera);
        if (!frame || !far || !near_m) {
            return false;
        }
        const T ratio = *far / *near_m;
        for (std::size_t r = 0; r < n; ++r) {
            for (std::size_t col = 0; col < n; ++col) {
                const frustum::Vec2<T> at((T(-1) + T(2 * col) / T(g)) * frame->half_width_m,
                                          (T(-1) + T(2 * r) / T(g)) * frame->half_height_m);
                corners[r * n + col] = frame->point(frustum::lens_warp(at, lens));
            }
        }
        const frustum::Vec3<T> eye = frame->eye;
        for (std::size_t r = 0; r < static_cast<std::size_t>(g); ++r) {
            for (std::size_t col = 0; col < static_cast<std::size_t>(g); ++col) {
                const frustum::Vec3<T> x[4] = {corners[r * n + col], corners[r * n + col + 1],
                                               corners[(r + 1) * n + col + 1], corners[(r + 1) * n + col]};
                const frustum::Vec3<T> inside = (x[0] + x[1] + x[2] + x[3]) / T(4);
                const auto side = [&](const frustum::Vec3<T>& a, const frustum::Vec3<T>& b) {
                    return Plane<T>::through(eye, a, b).facing(inside);
                };
                const frustum::SidePlanes<T> planes{side(x[3], x[0]), side(x[1], x[2]), side(x[0], x[1]),
                                                    side(x[2], x[3]), near};
                frustum::Vec3<T> far_points[4];
                for (int i = 0; i < 4; ++i) {
                    far_points[i] = eye + (x[i] - eye) * ratio;
                }
                const auto m = frustum::detail::from_planes_matrix(planes, far_points, 4, c.camera.depth());
                if (!m) {
                    return false;
                }
                inverses[r * static_cast<std::size_t>(g) + col] = glm::inverse(*m);
            }
        }
        benchmark::ClobberMemory();
        return true;
    });
    per_tile(s, g * g);
}

#define FRUSTUM_BENCH_OPS(T)                                                                         \
    BENCHMARK_TEMPLATE(Crop_Analytic, T);                                                            \
    BENCHMARK_TEMPLATE(crop_reinvert, T, bench::GlmInverse)->Name("Crop_Reinvert<" #T ">");          \
    BENCHMARK_TEMPLATE(crop_reinvert, T, bench::EigenInverse)->Name("Crop_Eigen<" #T ">");           \
    BENCHMARK_TEMPLATE(Reflect_Analytic, T);                                                         \
    BENCHMARK_TEMPLATE(reflect_reinvert, T, bench::GlmInverse)->Name("Reflect_Reinvert<" #T ">");    \
    BENCHMARK_TEMPLATE(reflect_reinvert, T, bench::EigenInverse)->Name("Reflect_Eigen<" #T ">");     \
    BENCHMARK_TEMPLATE(Clip_Analytic, T);                                                            \
    BENCHMARK_TEMPLATE(clip_reinvert, T, bench::GlmInverse)->Name("Clip_Reinvert<" #T ">");          \
    BENCHMARK_TEMPLATE(clip_reinvert, T, bench::EigenInverse)->Name("Clip_Eigen<" #T ">");           \
    BENCHMARK_TEMPLATE(Mirror_Analytic, T);                                                          \
    BENCHMARK_TEMPLATE(mirror_reinvert, T, bench::GlmInverse)->Name("Mirror_Reinvert<" #T ">");      \
    BENCHMARK_TEMPLATE(mirror_reinvert, T, bench::EigenInverse)->Name("Mirror_Eigen<" #T ">");       \
    BENCHMARK_TEMPLATE(MirrorRectangle_Analytic, T);                                                 \
    BENCHMARK_TEMPLATE(mirror_rectangle_reinvert, T, bench::GlmInverse)                              \
        ->Name("MirrorRectangle_Reinvert<" #T ">");                                                  \
    BENCHMARK_TEMPLATE(mirror_rectangle_reinvert, T, bench::EigenInverse)                            \
        ->Name("MirrorRectangle_Eigen<" #T ">");                                                     \
    BENCHMARK_TEMPLATE(Chain16_Analytic, T);                                                         \
    BENCHMARK_TEMPLATE(chain16_reinvert, T, bench::GlmInverse)->Name("Chain16_Reinvert<" #T ">");    \
    BENCHMARK_TEMPLATE(chain16_reinvert, T, bench::EigenInverse)->Name("Chain16_Eigen<" #T ">");     \
    BENCHMARK_TEMPLATE(inverse_only, T, bench::GlmInverse)->Name("GlmInverse_Only<" #T ">");         \
    BENCHMARK_TEMPLATE(inverse_only, T, bench::EigenInverse)->Name("EigenInverse_Only<" #T ">");     \
    BENCHMARK_TEMPLATE(InverseFromRows_Only, T);                                                     \
    BENCHMARK_TEMPLATE(CopyPair_Only, T);                                                            \
    BENCHMARK_TEMPLATE(CropTiles_Analytic, T)->Arg(8)->Arg(16)->Arg(32);                             \
    BENCHMARK_TEMPLATE(CropTiles_Grid, T)->Arg(8)->Arg(16)->Arg(32);                                 \
    BENCHMARK_TEMPLATE(crop_tiles_reinvert, T, bench::GlmInverse)                                    \
        ->Name("CropTiles_Reinvert<" #T ">")->Arg(8)->Arg(16)->Arg(32);                              \
    BENCHMARK_TEMPLATE(crop_tiles_reinvert, T, bench::EigenInverse)                                  \
        ->Name("CropTiles_Eigen<" #T ">")->Arg(8)->Arg(16)->Arg(32);                                 \
    BENCHMARK_TEMPLATE(LensTiles_Analytic, T)->Arg(4)->Arg(8)->Arg(16)->Arg(32);                     \
    BENCHMARK_TEMPLATE(LensTiles_Grid, T)->ArgsProduct({{4, 8, 16, 32}, {0, 1, 2}})->ArgNames({"", "depth"}); \
    BENCHMARK_TEMPLATE(LensTiles_FromPlanesReinvert, T)->Arg(4)->Arg(8)->Arg(16)->Arg(32);           \
    BENCHMARK_TEMPLATE(lens_tiles_reinvert, T, bench::GlmInverse)                                    \
        ->Name("LensTiles_Reinvert<" #T ">")->Arg(4)->Arg(8)->Arg(16)->Arg(32);                      \
    BENCHMARK_TEMPLATE(lens_tiles_reinvert, T, bench::EigenInverse)                                  \
        ->Name("LensTiles_Eigen<" #T ">")->Arg(4)->Arg(8)->Arg(16)->Arg(32);

FRUSTUM_BENCH_OPS(float)
FRUSTUM_BENCH_OPS(double)
BENCHMARK_MAIN();
